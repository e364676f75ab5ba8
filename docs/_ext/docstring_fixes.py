"""Sphinx extension: render the topic lists of module docstrings as literal blocks.

The docstrings are written to be read in a terminal (``help()``) as much as on this site. Every module
docstring opens with a list of its public names by topic (``name    description``, continued on
indented lines; STYLE.md section 1), which is not reStructuredText: read as is, it would make
``sphinx-build -W`` fail. These lists are turned into literal blocks, which keep their columns.

The docstrings themselves are not changed; only what Sphinx reads. Connected before numpydoc.
"""

from __future__ import annotations

import re

_ENTRY = re.compile(r"^[A-Za-z_][\w.]*(?:[ ,|]{1,3}[A-Za-z_][\w.()]*)*\s{2,}\S")
_UNDERLINE = re.compile(r"^(-{3,}|={3,}|~{3,})\s*$")


def _literal_topic_lists(lines):
    out, i = [], 0
    while i < len(lines):
        line = lines[i]
        if _ENTRY.match(line) and (i == 0 or not lines[i - 1].strip() or _UNDERLINE.match(lines[i - 1])):
            j = i + 1
            while j < len(lines) and (_ENTRY.match(lines[j]) or lines[j].startswith("    ")):
                j += 1
            if j - i > 1 or (j < len(lines) and not lines[j].strip()):
                out += ["::", ""] + ["    " + x for x in lines[i:j]] + [""]
                i = j
                continue
        out.append(line)
        i += 1
    return out


def _fix(app, what, name, obj, options, lines):
    if what == "module":
        lines[:] = _literal_topic_lists(lines)


def setup(app):
    app.connect("autodoc-process-docstring", _fix, priority=100)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
