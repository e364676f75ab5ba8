"""The Python session of docs/user_guide/roller_bearings.md runs, and prints what the page shows.

Every ```python block of the page runs in one namespace, in order; where the next block is ```text, the
lines the python block prints must be those lines (trailing spaces ignored).
"""

from __future__ import annotations

import contextlib
import io
import re
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

PAGE = Path(__file__).resolve().parents[2] / "docs" / "user_guide" / "roller_bearings.md"
FENCE = re.compile(r"^```(\w*)\n(.*?)^```", re.DOTALL | re.MULTILINE)


def _blocks():
    return [(m.group(1), m.group(2)) for m in FENCE.finditer(PAGE.read_text(encoding="utf-8"))]


def test_the_page_has_python_and_its_output():
    kinds = [k for k, _ in _blocks()]
    assert kinds.count("python") >= 8 and kinds.count("text") >= 8


def test_every_python_block_prints_what_the_page_shows():
    blocks = _blocks()
    scope = {"__name__": "user_guide"}
    for k, (kind, code) in enumerate(blocks):
        if kind != "python":
            continue
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            exec(compile(code, f"{PAGE.name} block {k}", "exec"), scope)  # noqa: S102 - the page's own example
        if k + 1 < len(blocks) and blocks[k + 1][0] == "text":
            got = [x.rstrip() for x in out.getvalue().splitlines()]
            want = [x.rstrip() for x in blocks[k + 1][1].splitlines()]
            assert got == want, f"block {k}:\n" + "\n".join(got)
