"""Sphinx extension: render the library's plain-text docstring conventions as valid reStructuredText.

The docstrings are written to be read in a terminal (``help()``) as much as on this site. Three of
their conventions are not reStructuredText, and would make ``sphinx-build -W`` fail:

* the topic lists of module docstrings (``name    description``, continued on indented lines) are
  turned into literal blocks, which keep their columns;
* absolute values written with bars (``|Delta x|``) would be read as substitution references; the bars
  are escaped (not inside math, inline literals or tables);
* a function that cites a reference of its module's list (``Palmgren [2]_``) has no such target in its
  own docstring (numpydoc renames citations per docstring); the citation becomes plain text ``[2]``.

The docstrings themselves are not changed; only what Sphinx reads. Connected before numpydoc.
"""

from __future__ import annotations

import re

_ENTRY = re.compile(r"^[A-Za-z_][\w.]*(?:[ ,|]{1,3}[A-Za-z_][\w.()]*)*\s{2,}\S")
_UNDERLINE = re.compile(r"^(-{3,}|={3,}|~{3,})\s*$")
_BARS = re.compile(r"(?<![`\\|])\|([^|`\n]*?[^\s|`])\|(?![_`|])")
_CITE = re.compile(r"\[(\w+)\]_")
_TARGET = re.compile(r"^\s*\.\. \[(\w+)\]")


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


def _escape_bars(lines):
    out, in_math = [], False
    for line in lines:
        stripped = line.strip()
        if stripped.startswith(".. math::"):
            in_math = True
        elif in_math and stripped and not line.startswith((" ", "\t")):
            in_math = False
        skip = in_math or ":math:" in line or "``" in line or stripped.startswith(("|", "+"))
        out.append(line if skip else _BARS.sub(r"\\|\1\\|", line))
    return out


def _plain_foreign_citations(lines):
    targets = {m.group(1) for line in lines if (m := _TARGET.match(line))}
    return [_CITE.sub(lambda m: m.group(0) if m.group(1) in targets else f"[{m.group(1)}]", x) for x in lines]


def _fix(app, what, name, obj, options, lines):
    new = lines[:]
    if what == "module":
        new = _literal_topic_lists(new)
    new = _plain_foreign_citations(_escape_bars(new))
    lines[:] = new


def setup(app):
    app.connect("autodoc-process-docstring", _fix, priority=100)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
