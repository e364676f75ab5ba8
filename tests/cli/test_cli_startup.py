"""Issue 15, item 14: the command line starts at once. ``bearinglab --help`` builds every command without
importing the physics (numpy, scipy, pint, matplotlib, dask); the heavy imports happen inside the
commands. Checked by the modules loaded, in a fresh interpreter, never by a wall time (which a loaded
machine would make flaky; ``bench/cli_help.py`` measures it)."""

import json
import os
import subprocess
import sys

import pytest

from bearinglab.cli import _click_command, main

HEAVY = ("numpy", "scipy", "matplotlib", "pint", "dask", "pydantic")
COMMANDS = ("catalog", "axial-angle", "stand-load", "frequencies", "sweep", "high-speed", "load-distribution",
            "bearing-set", "life", "film", "temperature", "friction", "runout", "clearance", "shaft", "serve")
SUBCOMMANDS = {"catalog": ("list", "search", "show"), "friction": ("torque", "lab", "template"),
               "runout": ("monte-carlo",)}

_PROBE = """
import json, sys
{run}
print(json.dumps({{"heavy": sorted(m for m in {heavy!r} if m in sys.modules),
                  "commands": sorted(__import__("bearinglab.cli").cli._click_command().commands)}}))
"""

_QUIET = "import contextlib, io\nfrom bearinglab.cli import main\nwith contextlib.redirect_stdout(io.StringIO()):\n"


def _loaded_after(run):
    """The heavy modules loaded (and the commands listed) after ``run`` in a fresh interpreter."""
    code = _PROBE.format(run=run, heavy=HEAVY)
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120, check=False,
                       env=dict(os.environ, COLUMNS="100"))
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout.strip().splitlines()[-1])


@pytest.mark.parametrize("run", [
    "import bearinglab.cli",
    "from bearinglab.cli import app",
    "import bearinglab",
    _QUIET + "    assert main(['--help']) == 0",
    _QUIET + "    assert main(['high-speed', '--help']) == 0\n    assert main(['catalog', 'show', '--help']) == 0",
], ids=["import-cli", "import-app", "import-bearinglab", "help", "command-help"])
def test_the_help_imports_no_physics_and_lists_every_command(run):
    got = _loaded_after(run)
    assert got["heavy"] == [], f"{run!r} imported {got['heavy']}"
    assert got["commands"] == sorted(COMMANDS)


def test_a_command_still_imports_what_it_needs():
    got = _loaded_after(_QUIET + "    assert main(['frequencies', '-b', '6205-2RS', '-n', '1797 rpm', '--json']) == 0")
    assert "numpy" in got["heavy"]


def test_every_public_name_of_bearinglab_is_reachable_lazily():
    import bearinglab

    for name in bearinglab.__all__:
        assert getattr(bearinglab, name) is not None
        assert name in dir(bearinglab)
    with pytest.raises(AttributeError, match="no attribute 'nope'"):
        bearinglab.nope  # noqa: B018


def _all_commands():
    root = _click_command()
    for name, command in sorted(root.commands.items()):
        subs = getattr(command, "commands", None)
        if subs:
            assert sorted(subs) == sorted(SUBCOMMANDS[name])
            for sub in sorted(subs):
                yield [name, sub]
        yield [name]
    yield []


@pytest.mark.parametrize("words", list(_all_commands()), ids=lambda w: " ".join(w) or "bearinglab")
def test_help_shows_no_type_on_flags(capsys, words):
    """Item 18: ``--json``, ``--help``, ``--mask`` ... are flags: no ``<bool>`` after them."""
    assert main([*words, "--help"]) == 0
    out = capsys.readouterr().out
    assert "--help" in out and "Usage" in out
    assert "<bool>" not in out and "BOOLEAN" not in out


def test_help_texts_spell_out_the_library_names():
    """The help lists choices without importing the model: the copies must equal the library's."""
    from bearinglab import ratings, runout
    from bearinglab.cli import life as life_cli
    from bearinglab.cli import runout as runout_cli

    assert life_cli._CONTAMINATION_CLASSES == tuple(ratings.CONTAMINATION_CLASSES)
    assert runout_cli._METRICS == tuple(runout.METRICS)


def _through_the_whole_app(words):
    """What ``bearinglab WORDS`` prints (stdout, stderr and exit code) through the application built with
    every command, as the root's own help builds it."""
    import contextlib
    import io

    from bearinglab.cli import _USAGE_ERRORS

    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            code = _click_command().main(args=words, prog_name="bearinglab", standalone_mode=False)
        except _USAGE_ERRORS as exc:
            print(f"bearinglab: error: {exc.format_message()}", file=sys.stderr)
            code = 2
    return out.getvalue(), err.getvalue(), code or 0


@pytest.mark.parametrize("words", [[*w, "--help"] for w in _all_commands() if w]
                         + [["life", "--no-such-option"], ["catalog", "shw"], ["high-speed", "-F"]],
                         ids=" ".join)
def test_a_command_built_alone_reads_as_in_the_whole_app(capsys, words):
    """Issue 21, item 8: a run builds only the command it names (``_click_command(name)``); its help, usage
    lines and usage errors are those of the whole application."""
    from bearinglab.cli import _command_named

    assert _command_named(words) == words[0]
    alone = _click_command(words[0])
    assert list(alone.commands) == [words[0]]
    code = main(words)
    got = capsys.readouterr()
    assert (got.out, got.err, code) == _through_the_whole_app(words)


@pytest.mark.parametrize(("words", "named"), [
    (["--help"], None), (["--version"], None), (["-h", "life"], None), (["lif"], None), ([], None),
    (["catalog", "show", "6208"], "catalog"), (["life", "--help"], "life"),
])
def test_only_a_first_word_that_names_a_command_builds_it_alone(words, named):
    from bearinglab.cli import _command_named

    assert _command_named(words) == named
