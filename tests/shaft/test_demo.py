"""``make demo``'s shaft-system worked examples write their tables and figures, and their documents are the
command line's."""

import json
import runpy
from pathlib import Path

from bearinglab.cli import main

ROOT = Path(__file__).resolve().parents[2]


def test_the_shaft_demo_writes_the_command_lines_documents(tmp_path, capsys, monkeypatch):
    monkeypatch.setenv("MPLBACKEND", "Agg")
    demo = runpy.run_path(str(ROOT / "examples" / "demo_shaft.py"))
    assert demo["main"](["demo_shaft.py", str(tmp_path)]) == 0
    out = tmp_path / "shaft"
    for name in ("gearbox.json", "gearbox.png", "gearbox_along_shaft.csv", "spindle.json", "spindle.png"):
        assert (out / name).stat().st_size > 0, name
    printed = capsys.readouterr().out
    assert "gearbox system life L10h" in printed and "stiffness at the nose" in printed
    assert main(["shaft", str(ROOT / "examples" / "shaft" / "gearbox.toml"), "--json"]) == 0
    cli = json.loads(capsys.readouterr().out)
    assert json.loads((out / "gearbox.json").read_text()) == cli
    rows = (out / "gearbox_along_shaft.csv").read_text().splitlines()
    assert len(rows) == len(cli["deflection"]) + 1 and rows[0].startswith("z_mm")
