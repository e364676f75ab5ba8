"""The command line's options and the calculations' fields name the same inputs, so the two cannot drift.

Each option of a command (its long name, dashes as underscores) is a field of its calculation and each
field is an option, except the differences listed here with their reason.
"""

import pytest
import typer

from bearinglab import cli
from bearinglab.calculations import CALCULATIONS

# options the web never takes: files read or written, clusters, output format
_FILES_AND_OUTPUT = {"json", "help", "csv", "plot", "out", "catalog", "bearing_file", "executor",
                     "workers", "chunk_size", "ross"}
#: calculation -> {option or field: reason}, the known differences
KNOWN = {
    "catalog": {"name": "the command's argument NAME is the field 'name'"},
    "runout": {"geometry": "a file: the posted error set carries its [geometry] table, or a bearing",
               "errors": "a file on the command line; a posted document on the web"},
    "runout-monte-carlo": {
        "geometry": "a file: the web takes a catalog bearing",
        "samples_csv": "a file written", "write_worst": "error files written into worst_dir",
        "worst_by": "ranks the samples of write_worst", "worst_dir": "a directory written",
        "progress": "a progress bar on the terminal"},
}


#: calculations registered before their command: the command line generated from the registry adds them
#: (issue 33 item 5); remove a name here when its command exists
NOT_YET_COMMANDS = {"shaft"}
_WITH_COMMAND = [n for n in CALCULATIONS if CALCULATIONS[n].command and n not in NOT_YET_COMMANDS]


def _command(words):
    command = typer.main.get_command(cli.app)
    for word in words:
        command = command.commands[word]
    return command


def _options(words):
    out = {}
    for param in _command(words).params:
        longs = [o for o in param.opts if o.startswith("--")]
        if longs:
            out[longs[0][2:].replace("-", "_")] = param
    return out


@pytest.mark.parametrize("name", _WITH_COMMAND)
def test_every_option_is_a_field_and_every_field_an_option(name):
    calc = CALCULATIONS[name]
    options = set(_options(calc.command)) - _FILES_AND_OUTPUT
    fields = {f.name for f in calc.fields}
    known = set(KNOWN.get(name, {}))
    assert options - fields - known == set(), "options without a field"
    assert fields - options - known == set(), "fields without an option"


@pytest.mark.parametrize("name", _WITH_COMMAND)
def test_the_fields_spell_the_options_and_defaults_as_the_command_line(name):
    calc = CALCULATIONS[name]
    options = _options(calc.command)
    for f in calc.fields:
        if f.name not in options or f.name in KNOWN.get(name, {}):
            continue
        param = options[f.name]
        assert f.cli_option in param.opts, f.name
        assert f.required == param.required, f.name
        assert (f.kind == "flag") == bool(getattr(param, "is_flag", False)), f.name
        if f.default is not None and f.kind != "flag":
            assert str(param.default) == str(f.default) or float(param.default) == float(f.default), f.name
        if f.choices and f.default is not None:
            assert f.default in f.choices, f.name


def test_catalog_search_takes_the_options_of_catalog_search_and_the_pickers_own():
    # the web's search answers the page's picker (query, limit: part of a designation, within 0.5 mm)
    # and, in "bearings", what `catalog search` prints for the same options
    # (tests/calculations/test_documents.py), so it is no command of its own
    calc = CALCULATIONS["catalog-search"]
    assert calc.command == ()
    options = set(_options(("catalog", "search"))) - _FILES_AND_OUTPUT
    assert options | {"query", "limit"} == {f.name for f in calc.fields}
