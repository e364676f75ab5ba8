"""Issue 15 item 8: the command line never shortens a number cell (no '14°28'03.3…'), at any width,
on a terminal or in a pipe."""

import io
import re

import pytest
from rich.console import Console

from bearinglab.cli import _common, main

CELLS = [["0", "0.0434034", "14°28'03.97\"", "4.02e-09", "inner_contact_lost"],
         ["12", "-1234.56789", "-0°30'00.00\"", "6.34e-13", "ok"]]
COLUMNS = ["k", "x_k [rad]", "α [D°M′S″]", "Δ [%]", "status of the case"]


def _render(monkeypatch, width, terminal):
    buf = io.StringIO()
    monkeypatch.setattr(_common, "console", Console(file=buf, width=width, force_terminal=terminal,
                                                    color_system=None))
    _common.table("A table with a rather long title", COLUMNS, CELLS, caption="a caption")
    return buf.getvalue()


@pytest.mark.parametrize("terminal", [False, True])
@pytest.mark.parametrize("width", [30, 50, 80, 200])
def test_number_cells_are_never_shortened(monkeypatch, width, terminal):
    out = _render(monkeypatch, width, terminal)
    assert "…" not in out
    for row in CELLS:
        for cell in row[:4]:
            assert cell in out, (cell, out)


def test_narrow_terminal_stacks_the_rows(monkeypatch):
    out = _render(monkeypatch, 30, True)
    assert "(1 of 2)" in out and "(2 of 2)" in out
    assert max(len(line) for line in out.splitlines()) <= 30


def test_narrow_pipe_prints_wide(monkeypatch):
    out = _render(monkeypatch, 30, False)
    assert "(1 of 2)" not in out and any(re.search(r"0\.0434034.*4\.02e-09", line) for line in out.splitlines())


def test_commands_print_whole_numbers_at_80_columns(capsys, monkeypatch):
    monkeypatch.setenv("COLUMNS", "80")
    assert main(["axial-angle", "-b", "4-1006095", "-F", "2 kgf"]) == 0
    out = capsys.readouterr().out
    assert "…" not in out and "14°28'03.97\"" in out
