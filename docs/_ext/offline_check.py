"""Sphinx extension: the built site works offline; no page loads a script or a style sheet from the network.

Math is rendered by MathJax 3 from a copy in ``_static/mathjax`` (the ``sphinx-mathjax-offline`` package of
the ``docs`` extra ships it and sets ``mathjax_path``), not from a CDN. After a build, every HTML page is
read and the build fails (an extension error, so even without ``-W``) if a ``<script src=...>`` or a
``<link rel="stylesheet" href=...>`` points to ``http://``, ``https://`` or a protocol-relative ``//``
address, or if the MathJax script a page loads is missing. ``tests/test_docs.py`` checks the scanner.
"""

from __future__ import annotations

import re
from html.parser import HTMLParser
from pathlib import Path

from sphinx.errors import ExtensionError

_REMOTE = re.compile(r"^\s*(https?:)?//", re.IGNORECASE)
_INLINE = re.compile(r"^\s*(data|blob):", re.IGNORECASE)  # in the page itself: nothing to fetch


class _Resources(HTMLParser):
    """The addresses of a page's scripts and style sheets."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.found = []

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "script" and a.get("src"):
            self.found.append(("script", a["src"]))
        elif tag == "link" and "stylesheet" in (a.get("rel") or "").lower().split() and a.get("href"):
            self.found.append(("stylesheet", a["href"]))


def remote_resources(html):
    """The (kind, address) of every script and style sheet of ``html`` loaded from the network."""
    parser = _Resources()
    parser.feed(html)
    return [(kind, src) for kind, src in parser.found if _REMOTE.match(src)]


def local_resources(html):
    """The (kind, address) of every script and style sheet of ``html`` loaded from the site itself."""
    parser = _Resources()
    parser.feed(html)
    return [(kind, src) for kind, src in parser.found if not _REMOTE.match(src) and not _INLINE.match(src)]


def check_site(outdir):
    """Problems of a built HTML site: remote scripts or style sheets, local ones that are missing."""
    outdir = Path(outdir)
    problems = []
    for page in sorted(outdir.rglob("*.html")):
        if page.relative_to(outdir).parts[0] in ("_static", "_sources", "_downloads"):
            continue  # copies of theme templates and sources, not pages
        text = page.read_text(encoding="utf-8", errors="replace")
        rel = page.relative_to(outdir)
        problems += [f"{rel}: {kind} from the network: {src}" for kind, src in remote_resources(text)]
        for kind, src in local_resources(text):
            path = src.split("?", 1)[0].split("#", 1)[0]
            if path and not (page.parent / path).is_file():
                problems.append(f"{rel}: {kind} not in the built site: {src}")
    return problems


def _check(app, exc):
    if exc is not None or app.builder.format != "html":
        return
    problems = check_site(app.outdir)
    if problems:
        shown = "\n  ".join(problems[:20])
        more = f"\n  ... and {len(problems) - 20} more" if len(problems) > 20 else ""
        raise ExtensionError(f"the site would need the network or misses files:\n  {shown}{more}")


def setup(app):
    # after sphinx-mathjax-offline has copied MathJax into _static (it also listens to build-finished)
    app.connect("build-finished", _check, priority=900)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
