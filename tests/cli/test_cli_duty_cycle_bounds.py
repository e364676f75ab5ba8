"""Issue 29, item 3: a duty cycle has a step limit (a 200 000-step duty cycle took 76 s and 1.8 GB), checked
from the parsed size before any step is read, on the command line, the web (tests/web) and the Python API
alike; its documents are read strictly (a repeated JSON key, nesting too deep: one line, exit 2).
"""

import json

import numpy as np
import pytest

from bearinglab import _bounds, catalog
from bearinglab.calculations import _inputs
from bearinglab.cli import main
from bearinglab.errors import InputError
from bearinglab.life import analysis, duty_cycle_life

STEP = '[[step]]\nfx = "1 kN"\nspeed = "1000 rpm"\ntime = {share!r}\n'


def run(capsys, *args):
    code = main([str(a) for a in args])
    out, err = capsys.readouterr()
    return code, out, err


def one_line_error(code, err):
    assert code == 2, err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("bearinglab: error: "), err
    return lines[0]


@pytest.fixture
def counted(monkeypatch):
    """How many steps' loads were read (none may be, for a duty cycle over the limit)."""
    calls = []
    original = _inputs.five_loads

    def five_loads(*args, **kwargs):
        calls.append(args)
        return original(*args, **kwargs)

    from bearinglab.calculations import life

    monkeypatch.setattr(life, "five_loads", five_loads)
    return calls


def test_the_200000_step_duty_cycle_is_refused_before_any_step_is_read(tmp_path, capsys, counted):
    path = tmp_path / "cycle.toml"
    path.write_text(STEP.format(share=1 / 200_000) * 200_000, encoding="utf-8")
    line = one_line_error(*run(capsys, "life", "-b", "6208", "--duty-cycle", path, "--viscosity", "20 cSt")[::2])
    assert line == (f"bearinglab: error: duty-cycle: {path}: 200000 steps, more than the limit of "
                    f"{_bounds.MAX_DUTY_CYCLE_STEPS} steps of a duty cycle; bin the load spectrum into fewer "
                    f"steps (the life of a step depends on its load and speed only)")
    assert counted == []


@pytest.mark.parametrize("form", ["json", "inline-toml"])
def test_a_duty_cycle_over_the_limit_in_any_syntax_is_refused(tmp_path, capsys, counted, form):
    steps = _bounds.MAX_DUTY_CYCLE_STEPS + 1
    path = tmp_path / "cycle.txt"
    if form == "json":  # no [[step]] headers: the parsed count refuses it
        path.write_text(json.dumps({"step": [{"fx": "1 kN", "speed": "1000 rpm", "time": 0}] * steps}),
                        encoding="utf-8")
    else:
        path.write_text("step = [" + ", ".join(['{speed = "1000 rpm", time = 0}'] * steps) + "]\n",
                        encoding="utf-8")
    line = one_line_error(*run(capsys, "life", "-b", "6208", "--duty-cycle", path)[::2])
    assert f"{steps} steps, more than the limit of {_bounds.MAX_DUTY_CYCLE_STEPS} steps" in line
    assert counted == []


def test_the_limit_itself_is_accepted(tmp_path, capsys, monkeypatch):
    monkeypatch.setattr(_bounds, "MAX_DUTY_CYCLE_STEPS", 3)  # the boundary, on a small cycle
    path = tmp_path / "cycle.toml"
    path.write_text(STEP.format(share=0.25) * 3 + STEP.format(share=0.25), encoding="utf-8")
    line = one_line_error(*run(capsys, "life", "-b", "6208", "--duty-cycle", path)[::2])
    assert "4 steps, more than the limit of 3 steps" in line
    path.write_text(STEP.format(share=0.5) * 2 + STEP.format(share=0.0), encoding="utf-8")
    code, out, err = run(capsys, "life", "-b", "6208", "--duty-cycle", path, "--json")
    assert code == 0, err
    assert len(json.loads(out)["steps"]) == 3


@pytest.mark.parametrize("text, words", [
    ("a = " + "[" * 1000 + "]" * 1000, "nested more than 32 levels deep"),
    ('{"step": [{"speed": "1000 rpm", "time": 1}], "step": []}', "key 'step' given more than once"),
])
def test_a_hostile_duty_cycle_file_is_one_line(tmp_path, capsys, text, words):
    path = tmp_path / "cycle.toml"
    path.write_text(text, encoding="utf-8")
    line = one_line_error(*run(capsys, "life", "-b", "6208", "--duty-cycle", path)[::2])
    assert line.startswith("bearinglab: error: duty-cycle: ") and words in line


def test_the_python_api_bounds_the_steps_before_any_work(monkeypatch):
    def never(*args, **kwargs):
        raise AssertionError("a step was computed")

    monkeypatch.setattr(analysis, "rating_life", never)
    k = _bounds.MAX_DUTY_CYCLE_STEPS + 1
    with pytest.raises(InputError, match=rf"^shaft_speeds: {k} steps, more than the limit of 10000 steps"):
        duty_cycle_life(catalog.get("6208"), np.zeros((k, 5)), np.ones(k), np.full(k, 1 / k))
