"""Issue 28 item 6: the help loads typer's rich help without the markdown parser it does not use.

``cli._rich_help_without_markdown`` loads ``typer.rich_utils`` with a stand-in for ``rich.markdown``
(markdown-it is about a fifth of ``bearinglab --help``'s start); the real module stays importable.
"""

import subprocess
import sys

CODE = """
import contextlib, io, sys
from bearinglab.cli import main
with contextlib.redirect_stdout(io.StringIO()) as out:
    assert main(["high-speed", "--help"]) == 0
assert "--axial-load" in out.getvalue() and "Mounting: fits and seats" in out.getvalue()
print(sorted(m for m in ("markdown_it", "rich.markdown") if m in sys.modules))
import rich.markdown
print(rich.markdown.Markdown.__module__, "markdown_it" in sys.modules)
"""


def test_the_help_loads_no_markdown_parser_and_rich_markdown_stays_real():
    r = subprocess.run([sys.executable, "-c", CODE], capture_output=True, text=True, timeout=120, check=True)
    assert r.stdout.splitlines() == ["[]", "rich.markdown True"]


def test_a_markdown_stand_in_makes_the_real_class(monkeypatch):
    import typer

    from bearinglab import cli

    monkeypatch.delitem(sys.modules, "typer.rich_utils", raising=False)
    monkeypatch.delitem(sys.modules, "rich.markdown", raising=False)
    monkeypatch.setattr(typer, "rich_utils", None, raising=False)
    cli._rich_help_without_markdown()
    rich_utils = sys.modules["typer.rich_utils"]
    assert "rich.markdown" not in sys.modules  # the stand-in is gone once typer's help is loaded
    made = rich_utils.Markdown("*a*")  # typer's markdown mode, were it used, gets the real class
    assert type(made) is sys.modules["rich.markdown"].Markdown
