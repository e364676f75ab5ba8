"""The command line is generated from the calculations' fields (``bearinglab.cli._options``).

Every field of every calculation with a command is an option of that command, with its spelling, short
aliases, default, requiredness, type, help panel and help; the only other options are the command
line's own (files, ``--json``, the executor), declared by hand in the command's ``run``. A calculation
added to the registry gets a working command, API document and printed table without a command module.
"""

import inspect
import json
import sys
import types
from pathlib import Path

import pytest
import typer

from bearinglab import cli
from bearinglab.calculations import CALCULATIONS, Calculation, Field, parse, run
from bearinglab.calculations.registry import GROUPS
from bearinglab.cli import _options

CLI = Path(cli.__file__).parent
COMMANDED = [n for n in CALCULATIONS if CALCULATIONS[n].command]


#: calculations registered before their command: the command line generated from the registry adds them
#: (issue 33 item 5); remove a name here when its command exists
NOT_YET_COMMANDS: set = set()
_WITH_COMMAND = [n for n in CALCULATIONS if CALCULATIONS[n].command and n not in NOT_YET_COMMANDS]


def _command(words):
    command = cli._click_command()
    for word in words:
        command = command.commands[word]
    return command


def _params(words):
    """The command's parameters by name (a field's name is its parameter's)."""
    return {p.name: p for p in _command(words).params}


@pytest.mark.parametrize("name", COMMANDED)
def test_every_field_is_an_option_of_its_command_as_declared(name):
    calc = CALCULATIONS[name]
    params = _params(calc.command)
    group_callback = name == "runout"  # its options come before a subcommand: none is required
    for f in calc.fields:
        if not f.cli:
            assert f.name not in params, f.name
            continue
        p = params[f.name]
        assert [f.cli_option, *f.aliases] == (list(p.opts) if f.cli_option.startswith("-") else [f.cli_option]), f.name
        assert p.required == (f.required and not group_callback), f.name
        if f.kind == "flag":
            assert p.is_flag and p.default is bool(f.default), f.name
        elif not p.required:
            assert p.default == f.default, f.name
        kind = {"int": "int", "number": "float", "document": "path"}.get(f.kind, "str")
        assert p.type.name == kind or f.kind == "flag", (f.name, p.type.name)
        assert bool(getattr(p, "multiple", False)) == (f.many and f.kind == "text"), f.name
        if f.cli_option.startswith("-"):
            assert p.rich_help_panel == GROUPS.get(f.group, f.group.capitalize() or None), f.name


@pytest.mark.parametrize("name", COMMANDED)
def test_the_other_options_are_the_command_lines_own(name):
    """An option that is no field is a keyword parameter of the command's ``run``: written by hand."""
    calc = CALCULATIONS[name]
    others = {p.name for p in _command(calc.command).params} - {f.name for f in calc.fields} - {"help"}
    generated = _generated(calc.command)
    assert generated.calculation == name
    assert others == set(inspect.signature(generated.run).parameters) - {"given", "ctx"}


def _generated(words):
    """The function typer registered for a command (the one :func:`_options.command` built)."""
    apps = [cli.app]
    for word in words[:-1]:
        apps.append(next(g.typer_instance for g in apps[-1].registered_groups if g.name == word))
    last = apps[-1]
    for c in last.registered_commands:
        if c.name == words[-1]:
            return c.callback
    group = next(g for g in last.registered_groups if g.name == words[-1])  # a group's callback (runout)
    return group.typer_instance.registered_callback.callback


def test_help_names_the_other_fields_as_options_and_lists_the_choices():
    life = CALCULATIONS["life"]
    assert "`temperature`" in life.field("oil").help  # the page and the API show the name
    assert "(with --temperature)" in _options.help_of(life.field("oil"), life)
    lubrication = _options.help_of(life.field("ball_material"), life)
    assert lubrication.endswith("steel | silicon_nitride.")
    x0 = CALCULATIONS["axial-angle"].field("x0")
    assert "\\[rad]" in _options.help_of(x0, CALCULATIONS["axial-angle"])  # rich would drop '[rad]'
    for name in COMMANDED:
        calc = CALCULATIONS[name]
        for f in calc.fields:
            text = _options.help_of(f, calc)
            assert not any(f"`{g.name}`" in text for g in calc.fields if g.cli), (name, f.name, text)


def test_the_command_line_declares_by_hand_only_its_own_options():
    # issue 28: the options of the calculations are generated; what is typed by hand is the command
    # line's own (files, --json, the executor, serve, sweep, the lab): about 25 declarations at most
    written = sum(path.read_text(encoding="utf-8").count("typer.Option(") for path in CLI.glob("*.py"))
    assert written <= 25, written


# ----------------------------------------------------------------------------- a calculation added
def _document(parsed):
    """ISO 281:2007 basic rating life of a ball bearing, eq. (1) and (3): L10 = (C/P)^3 10^6 rev,
    L10h = 10^6 L10 / (60 n); one document per equivalent load."""
    import numpy as np

    c, n = parsed.values["dynamic_load_rating"], parsed.values["speed"]
    rpm = n * 60.0 / (2.0 * np.pi)
    cases = [{"equivalent_load_N": float(p), "basic_rating_life_Mrev": float((c / p) ** 3),
              "basic_rating_life_h": float((c / p) ** 3 * 1e6 / (60.0 * rpm))}
             for p in np.atleast_1d(parsed.values["equivalent_load"])]
    doc = {"dynamic_load_rating_N": c, "speed_rpm": rpm, "warnings": []}
    return dict(doc, **cases[0]) if len(cases) == 1 else dict(doc, cases=cases)


DEMO = Calculation(
    "demo-life", ("demo-life",), "Basic rating life (demo)", "L10 of a ball bearing from C and P.",
    (Field("dynamic_load_rating", "force", "C, e.g. '32.5 kN'.", unit="N", required=True, minimum=0,
           exclusive=True, group="bearing data"),
     Field("equivalent_load", "force", "P, e.g. '5 kN', or a list (same unit as `dynamic_load_rating`).",
           unit="N", required=True, minimum=0, exclusive=True, many=True, group="loads", aliases=("-P",)),
     Field("speed", "speed", "Inner-ring speed.", unit="rpm", default="1000 rpm", minimum=0, exclusive=True,
           group="loads", aliases=("-n",))),
    combine="grid", module="demo_calculations.demo_life")


@pytest.fixture
def demo(monkeypatch):
    """DEMO in the registry, its document module importable, and the application with its command."""
    module = types.ModuleType("demo_calculations.demo_life")
    module.document = _document
    monkeypatch.setitem(sys.modules, "demo_calculations", types.ModuleType("demo_calculations"))
    monkeypatch.setitem(sys.modules, "demo_calculations.demo_life", module)
    monkeypatch.setitem(CALCULATIONS, DEMO.name, DEMO)
    monkeypatch.setattr(_options, "_BUILT", set(_options._BUILT))
    monkeypatch.setattr(cli.app, "registered_commands", list(cli.app.registered_commands))
    monkeypatch.setattr(cli, "_CLICK", {})
    _options.register(cli.app)
    return DEMO


def test_a_calculation_added_to_the_registry_gets_a_command(demo, capsys):
    code = cli.main(["demo-life", "--help"])
    out = capsys.readouterr().out
    assert code == 0
    assert "--dynamic-load-rating" in out and "--equivalent-load" in out and "-P" in out
    assert "Bearing data (override the catalog)" in out  # the help panel of its group
    assert "[default: 1000 rpm]" in out and "--dynamic-load-rating)." in out  # the help names the option

    argv = ["demo-life", "--dynamic-load-rating", "32.5 kN", "-P", "5 kN, 6.5 kN", "-n", "3000 rpm"]
    assert cli.main([*argv, "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    lives = [case["basic_rating_life_Mrev"] for case in doc["cases"]]
    assert lives == pytest.approx([6.5 ** 3, 5.0 ** 3], rel=1e-12)  # (C/P)^3: 274.625, 125
    assert doc["cases"][0]["basic_rating_life_h"] == pytest.approx(274.625e6 / (60 * 3000), rel=1e-12)
    # the same document through the request layer (the web's API)
    given = {"dynamic_load_rating": "32.5 kN", "equivalent_load": "5 kN, 6.5 kN", "speed": "3000 rpm"}
    assert json.loads(json.dumps(run(parse(DEMO.name, given)))) == doc

    assert cli.main(argv) == 0  # no command module: the generic table, units from the keys
    out = capsys.readouterr().out
    assert "Basic rating life (demo)" in out and "basic rating life [h]" in out and "1525.69" in out


def test_a_calculation_added_to_the_registry_names_its_options_in_errors(demo, capsys):
    code = cli.main(["demo-life", "--dynamic-load-rating", "32.5 kN", "--equivalent-load=-5 kN"])
    err = capsys.readouterr().err.strip()
    assert code == 2 and err.startswith("bearinglab: error: equivalent-load must be > 0")
    code = cli.main(["demo-life", "-P", "5 kN"])
    err = capsys.readouterr().err.strip()
    assert code == 2 and "Missing option '--dynamic-load-rating'" in err


def test_a_field_of_the_page_alone_is_no_option():
    search = CALCULATIONS["catalog-search"]
    params = _params(search.command)
    assert {f.name for f in search.fields if not f.cli} == {"query", "limit"}
    assert not {"query", "limit"} & set(params) and {"bore", "series"} <= set(params)


def test_the_words_of_a_request_leave_out_the_fields_of_the_page_alone(capsys):
    from bearinglab.calculations import argv

    words = argv(parse("catalog-search", {"query": "62", "bore": "40 mm", "limit": 5}))
    assert words == ["catalog", "search", "--bore=40 mm"]
    assert cli.main([*words, "--json"]) == 0
    assert "6208" in [b["name"] for b in json.loads(capsys.readouterr().out)["bearings"]]


def test_a_clash_between_a_field_and_an_own_option_is_refused():
    def run_(given, *, speed: typer.Option = None):  # 'speed' is a field of life
        return given

    with pytest.raises(ValueError, match="speed"):
        _options.command("life", run_)


# ----------------------------------------------------------------------------- a document given as a file
def _sum_document(parsed):
    """The sum of the numbers of the document's ``values`` (the text the field holds, never a path)."""
    import tomllib

    text = parsed.values.get("numbers", parsed.given.get("numbers"))
    assert isinstance(text, str)
    return {"sum": float(sum(tomllib.loads(text)["values"])), "warnings": []}


DOCUMENT_DEMO = Calculation(
    "demo-sum", ("demo-sum",), "Sum (demo)", "The sum of a document's numbers.",
    (Field("numbers", "document", "the numbers, as `values = [...]`.", required=True, option="FILE",
           group="demo"),),
    module="demo_calculations.demo_sum")


@pytest.fixture
def document_demo(monkeypatch):
    module = types.ModuleType("demo_calculations.demo_sum")
    module.document = _sum_document
    monkeypatch.setitem(sys.modules, "demo_calculations", types.ModuleType("demo_calculations"))
    monkeypatch.setitem(sys.modules, "demo_calculations.demo_sum", module)
    monkeypatch.setitem(CALCULATIONS, DOCUMENT_DEMO.name, DOCUMENT_DEMO)
    monkeypatch.setattr(_options, "_BUILT", set(_options._BUILT))
    monkeypatch.setattr(cli.app, "registered_commands", list(cli.app.registered_commands))
    monkeypatch.setattr(cli, "_CLICK", {})
    _options.register(cli.app)
    return DOCUMENT_DEMO


def test_a_document_field_is_a_file_whose_text_the_command_reads(document_demo, capsys, tmp_path):
    # issue 33 item 5: any document field given as a positional FILE, not a case of one command
    path = tmp_path / "n.toml"
    path.write_text("values = [1.5, 2.25, 3]\n", encoding="utf-8")
    assert cli.main(["demo-sum", str(path), "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["sum"] == 6.75
    # the web posts the text: the same document
    assert run(parse("demo-sum", {"numbers": path.read_text(encoding="utf-8")}))["sum"] == 6.75
    assert cli.main(["demo-sum", "--help"]) == 0
    out = " ".join(capsys.readouterr().out.split())
    assert "demo-sum [OPTIONS] {FILE}" in out and "TOML file of the numbers" in out
    for argv, message in (([str(tmp_path / "none.toml")], f"numbers: {tmp_path / 'none.toml'}: no such file"),
                          ([str(tmp_path)], f"numbers: {str(tmp_path)!r} is a directory; give a file name"),
                          (["/dev/zero"], "numbers: '/dev/zero' is not a regular file")):
        assert cli.main(["demo-sum", *argv]) == 2
        err = capsys.readouterr().err.strip()
        assert err.startswith(f"bearinglab: error: {message}") and len(err.splitlines()) == 1, err


def test_a_document_file_is_an_input_of_the_run(document_demo, tmp_path):
    # the file the command read is one of the run's inputs: no output of the same run may replace it
    from bearinglab import _io
    from bearinglab.cli._common import read_document
    from bearinglab.errors import InputError

    path = tmp_path / "n.toml"
    path.write_text("values = [1]\n", encoding="utf-8")
    with _io.run_files():
        assert read_document(path, "numbers") == "values = [1]\n"
        with pytest.raises(InputError, match="input"):
            _io.write_text(path, "replaced")
    assert path.read_text(encoding="utf-8") == "values = [1]\n"
