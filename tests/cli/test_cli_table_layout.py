"""Issue 15 item 8: the command line never shortens a number cell (no '14°28'03.3…'), at any width,
on a terminal or in a pipe; issue 20 item 13: nor is a table wider than the console, on a pipe either."""

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


@pytest.mark.parametrize("terminal", [False, True])
def test_narrow_console_stacks_the_rows(monkeypatch, terminal):
    out = _render(monkeypatch, 30, terminal)
    assert "(1 of 2)" in out and "(2 of 2)" in out
    assert max(len(line) for line in out.splitlines()) <= 30


@pytest.mark.parametrize("terminal", [False, True])
def test_a_table_that_fits_is_one_table(monkeypatch, terminal):
    out = _render(monkeypatch, 80, terminal)
    assert "(1 of 2)" not in out and any(re.search(r"0\.0434034.*4\.02e-09", line) for line in out.splitlines())
    assert max(len(line) for line in out.splitlines()) <= 80


def test_commands_print_whole_numbers_at_80_columns(capsys, monkeypatch):
    monkeypatch.setenv("COLUMNS", "80")
    assert main(["axial-angle", "-b", "4-1006095", "-F", "2 kgf"]) == 0
    out = capsys.readouterr().out
    assert "…" not in out and "14°28'03.97\"" in out


# ----------------------------------------------------------------------------- no negative zero (review)
@pytest.mark.parametrize("text, shown", [
    ("-0", "0"), ("z = -0 mm", "z = 0 mm"), ("0.0000, -0.0000, 668.7709", "0.0000, 0.0000, 668.7709"),
    ("-0e+00", "0e+00"), ("(-0.000 %)", "(0.000 %)"), ("\u22120.00", "0.00"),
    # not a zero, or not a whole number: the sign stays
    ("-0.5", "-0.5"), ("-0.00001", "-0.00001"), ("-10", "-10"), ("-0°30'00.00\"", "-0°30'00.00\""),
    ("x-0", "x-0"), ("1e-0", "1e-0"), ("+0.0", "+0.0"),
])
def test_plain_zero(text, shown):
    assert _common.plain_zero(text) == shown


def test_tables_print_no_negative_zero(monkeypatch):
    buf = io.StringIO()
    monkeypatch.setattr(_common, "console", Console(file=buf, width=120, color_system=None))
    _common.table("Bearing 0 (z = -0 mm)", ["quantity", "value"], [["δ_x, δ_y [µm]", "-0.0000, 3.5"], ["m", "-0"]],
                  caption="at -0 rpm")
    out = buf.getvalue()
    assert "z = 0 mm" in out and "0.0000, 3.5" in out and "at 0 rpm" in out
    assert not re.search(r"-0(?:\.0*)?(?:\s|,|$)", out), out


def test_no_python_list_or_dict_in_a_table(capsys):
    # issue 30: the mounted clearance's range and the mounting echo printed as words, never as Python repr
    from bearinglab.cli import _common, main

    assert _common.cell_text([6.0, 20.000000000000004]) == "6, 20"
    assert _common.cell_text({"shaft_fit": "j5", "tolerance_class": "Normal"}) == "shaft fit: j5; tolerance class: Normal"
    assert main(["life", "-b", "6208", "-R", "2 kN", "-n", "3000 rpm", "--viscosity", "20 cSt",
                 "--shaft-fit", "j5", "--housing-fit", "H7"]) == 0
    out = capsys.readouterr().out
    assert "unmounted clearance" in out and "shaft fit: j5" in out
    assert not any(c in out for c in ("['", "{'", "[6.0", "']"))
