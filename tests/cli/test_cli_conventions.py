"""Issue 15, items 17 and 18: one convention per thing across every command, and errors that name the
option typed. Each convention is one parametrized test over the commands (in-process runs):

* a bad value of any option: exit 2, one line on stderr, naming the option (``axial-load: ...``,
  ``balls must be ...``: the long option without its dashes, also for names the library knows by another
  name such as ``n_balls``);
* a negative speed: refused by every command with a speed, the value in rpm;
* a missing output directory: refused by every output option before anything is computed, nothing
  written;
* JSON keys: the unit in the name, one unit per quantity: forces in N (``_N``; ``_kgf`` only beside its
  ``_N`` twin), displacements and deflections in µm (``_um``), no ``_kN``;
* CSV booleans: ``true`` / ``false``;
* echoed inputs: the bearing and its geometry, the values as given (no float noise: 3000 rpm is 3000);
* printed tables give δ in µm.
"""

import csv
import json
import re
import shlex
from pathlib import Path

import pytest

from bearinglab.cli import main

ERRORS = "examples/runout/example1_oversize_ball.toml"


def run(capsys, argv):
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def one_line(code, err):
    assert code == 2, err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("bearinglab: error: ") and "Traceback" not in err, err
    return lines[0]


# ----------------------------------------------------------------------------- bad input, every command
BAD_INPUTS = [
    ('axial-load', 'load-distribution -b 7218B --axial-load "5 N*m"'),
    ('axial-load', 'load-distribution -b 7218B --axial-load "5 m"'),
    ('fz', 'load-distribution -b 7218B --fz "5 m"'),
    ('mx', 'load-distribution -b 7218B --mx "5 N"'),
    ('speed', 'load-distribution -b 7218B --fz "1 kN" -n "-100 rpm"'),
    ('speed', 'load-distribution -b 7218B --fz "1 kN" -n "1e12 rpm"'),
    ('speed', 'load-distribution -b 7218B --fz "1 kN" -n "1000, 2000 rpm"'),
    ('first-ball-angle', 'load-distribution -b 7218B --fz "1 kN" --first-ball-angle "5 m"'),
    ('stiffness-at', 'load-distribution -b 7218B --fz "1 kN" --stiffness-at foo'),
    ('plot', 'load-distribution -b 7218B --fz "1 kN" --plot x.txt'),
    ('ross', 'load-distribution -b 7218B --fz "1 kN" --ross x.txt'),
    ('ross', 'load-distribution -b 7218B --fz "1 kN" --ross /nonexist/x.json'),
    ('arrangement', 'bearing-set -b 7218B --arrangement XX --preload "100 N"'),
    ('spacing', 'bearing-set -b 7218B --spacing "5 N" --preload "100 N"'),
    ('spacing', 'bearing-set -b 7218B --spacing "-5 mm" --preload "100 N"'),
    ('preload', 'bearing-set -b 7218B --preload "-100 N"'),
    ('preload', 'bearing-set -b 7218B --preload "100 m"'),
    ('preload-offset', 'bearing-set -b 7218B --preload-offset "5 N"'),
    ('speed', 'bearing-set -b 7218B --preload "100 N" -n "-5 rpm"'),
    ('bearing', 'bearing-set -b NOPE --preload "100 N"'),
    ('plot', 'bearing-set -b 7218B --preload "100 N" --plot /nonexist/x.png'),
    ('speed', 'life -b 6205-2RS --fx "1 kN" -n "-5 rpm" --viscosity "20 cSt"'),
    ('speed', 'life -b 6205-2RS --fx "1 kN" -n "1e12 rpm" --viscosity "20 cSt"'),
    ('viscosity', 'life -b 6205-2RS --fx "1 kN" -n "3000 rpm" --viscosity "-20 cSt"'),
    ('viscosity', 'life -b 6205-2RS --fx "1 kN" -n "3000 rpm" --viscosity "20 N"'),
    ('reliability', 'life -b 6205-2RS --fx "1 kN" -n "3000 rpm" --viscosity "20 cSt" --reliability 50'),
    ('contamination-factor', 'life -b 6205-2RS --fx "1 kN" -n "3000 rpm" --viscosity "20 cSt" --contamination-factor 2'),
    ('contamination', 'life -b 6205-2RS --fx "1 kN" -n "3000 rpm" --viscosity "20 cSt" --contamination dirty'),
    ('temperature', 'life -b 6205-2RS --fx "1 kN" -n "3000 rpm" --oil VG68 --viscosity-100 "8 cSt" --temperature "-300 degC"'),
    ('oil', 'life -b 6205-2RS --fx "1 kN" -n "3000 rpm" --oil VG8 --viscosity-100 "8 cSt" --temperature "70 degC"'),
    ('fx', 'life -b 6205-2RS --fx "1 m" -n "3000 rpm" --viscosity "20 cSt"'),
    ('duty-cycle', 'life -b 6205-2RS --duty-cycle /nonexist.toml --viscosity "20 cSt"'),
    ('radial-load', 'friction torque -b 6205-2RS --model skf --radial-load "-1 kN" --axial-load "0 N" -n "3000 rpm" --viscosity "20 cSt"'),
    ('speed', 'friction torque -b 6205-2RS --model skf --radial-load "1 kN" --axial-load "0 N" -n "-3000 rpm" --viscosity "20 cSt"'),
    ('speed', 'friction torque -b 6205-2RS --model skf --radial-load "1 kN" --axial-load "0 N" -n "1e12 rpm" --viscosity "20 cSt"'),
    ('viscosity', 'friction torque -b 6205-2RS --model skf --radial-load "1 kN" --axial-load "0 N" -n "3000 rpm" --viscosity "-2 cSt"'),
    ('lubrication', 'friction torque -b 6205-2RS --model skf --radial-load "1 kN" --axial-load "0 N" -n "3000 rpm" --viscosity "20 cSt" --lubrication foo'),
    ('speed', 'friction torque -b 6205-2RS --model two-term --radial-load "1 kN" --axial-load "0 N" -n "-3000 rpm" --viscosity "20 cSt"'),
    ('speed', 'friction torque -b 6205-2RS --model two-term --f0 2e-7 --radial-load "1 kN" --axial-load "0 N" -n "1e12 rpm" --viscosity "20 cSt"'),
    ('model', 'friction torque -b 6205-2RS --model foo --radial-load "1 kN" --axial-load "0 N" -n "3000 rpm"'),
    ('NOPE', 'catalog show NOPE'),
    ('catalog', 'catalog list --catalog /nonexist.toml'),
    ('speed', 'high-speed -b B218 -F "20 kN" -n "-5 rpm"'),
    ('speed', 'high-speed -b B218 -F "20 kN" -n "1e12 rpm"'),
    ('axial-load', 'high-speed -b B218 -F "-20 kN" -n "5 rpm"'),
    ('csv', 'high-speed -b B218 -F "20 kN" -n "5 rpm" --csv /nonexist/x.csv'),
    ('speed', 'stand-load -b 4-1006095 -n "-5 rpm"'),
    ('speed', 'stand-load -b 4-1006095 -n "1e12 rpm"'),
    ('speed', 'frequencies -b 6205-2RS -n "1e12 rpm"'),
    ('speed', 'frequencies -b 6205-2RS -n "-5 rpm"'),
    ('csv', 'frequencies -b 6205-2RS -n "5 rpm" --csv /nonexist/x.csv'),
    ('rows', 'axial-angle -b 4-1006095 -F "2 kgf" --rows 0'),
    ('axial-load', 'axial-angle -b 4-1006095 -F "-2 kgf"'),
    ('cage-ratio', 'runout -b 7218B --errors examples/runout/example1_oversize_ball.toml --cage-ratio 1.5'),
    ('steps-per-rev', 'runout -b 7218B --errors examples/runout/example1_oversize_ball.toml --revolutions 2 --steps-per-rev 2'),
    ('balls', 'high-speed --balls 40 --ball-diameter "7.938 mm" --pitch-diameter "38.5 mm" --inner-conformity 0.52 --outer-conformity 0.53 --contact-angle "15 deg" -F "1 kN" -n "1 rpm"'),
    ('ball-diameter', 'high-speed -b B218 --ball-diameter "-5 mm" -F "1 kN" -n "1 rpm"'),
    ('contact-angle', 'high-speed -b B218 --contact-angle "95 deg" -F "1 kN" -n "1 rpm"'),
    ('inner-conformity', 'high-speed -b B218 --inner-conformity 0.3 -F "1 kN" -n "1 rpm"'),
    # -5 um is a preload since issue 30; beyond -2 D (an interference of a ball diameter) is still refused
    ('radial-clearance', 'high-speed -b B218 --radial-clearance "-50 mm" -F "1 kN" -n "1 rpm"'),
    ('ball-material', 'high-speed -b B218 --ball-material gold -F "1 kN" -n "1 rpm"'),
    ('reduced-modulus', 'high-speed -b B218 --reduced-modulus "-5 GPa" -F "1 kN" -n "1 rpm"'),
    ('solver', 'high-speed -b B218 --solver foo -F "1 kN" -n "1 rpm"'),
    ('executor', 'high-speed -b B218 --executor foo -F "1 kN:2 kN:1 kN" -n "1 rpm"'),
    ('workers', 'high-speed -b B218 --workers 0 --executor local -F "1 kN:2 kN:1 kN" -n "1 rpm"'),
    ('chunk-size', 'high-speed -b B218 --chunk-size 0 -F "1 kN:2 kN:1 kN" -n "1 rpm"'),
    ('harmonics', 'frequencies -b 6205-2RS -n "5 rpm" --harmonics 0'),
    ('sidebands', 'frequencies -b 6205-2RS -n "5 rpm" --sidebands -1'),
    ('band', 'frequencies -b 6205-2RS -n "5 rpm" --band "500 %"'),
    ('outer-speed', 'frequencies -b 6205-2RS -n "5 rpm" --outer-speed "5 m"'),
    ('out', 'sweep examples/sweep/stand_geometry_variants.toml --out x.txt'),
    ('revolutions', 'runout -b 7218B --errors examples/runout/example1_oversize_ball.toml --revolutions 0'),
]


@pytest.mark.parametrize("option, command", BAD_INPUTS, ids=[f"{c.split()[0]}:{o}" for o, c in BAD_INPUTS])
def test_bad_input_exits_2_with_one_line_naming_the_option(capsys, option, command):
    line = one_line(*run(capsys, shlex.split(command))[::2])
    assert re.search(rf"(?<![\w-]){re.escape(option)}(?![\w])", line), line


def test_a_library_name_the_user_did_not_type_is_left_as_it_is(capsys):
    """A field of a catalog or input file keeps its name: only options typed are renamed."""
    line = one_line(*run(capsys, ["frequencies", "-b", "6205-2RS", "--speed", "3000 rpm", "-F", "2 kgf"])[::2])
    assert "contact_angle must be in (0, 90) [deg]" in line  # not --contact-angle: the catalog's field


# ----------------------------------------------------------------------------- negative speed, every command
SPEED_COMMANDS = {
    "high-speed": ["high-speed", "-b", "B218", "-F", "20 kN"],
    "stand-load": ["stand-load", "-b", "4-1006095"],
    "frequencies": ["frequencies", "-b", "6205-2RS"],
    "load-distribution": ["load-distribution", "-b", "B218", "--fz", "5 kN"],
    "bearing-set": ["bearing-set", "-b", "B218", "--preload", "1 kN"],
    "life": ["life", "-b", "6205-2RS", "--fx", "1 kN", "--viscosity", "20 cSt"],
    "friction-one-term": ["friction", "torque", "-b", "101", "-R", "10 N"],
    "friction-skf": ["friction", "torque", "--model", "skf", "-b", "6205-2RS", "-R", "1 kN", "--viscosity",
                     "20 cSt"],
}


@pytest.mark.parametrize("name", SPEED_COMMANDS)
def test_a_negative_speed_is_refused_alike_by_every_command(capsys, name):
    line = one_line(*run(capsys, [*SPEED_COMMANDS[name], "--speed", "-300 rpm"])[::2])
    assert re.search(r"speed must be >?=? ?0 \[rpm\].*got -300 rpm$", line), line


@pytest.mark.parametrize("name", SPEED_COMMANDS)
def test_echoed_speed_has_no_float_noise(capsys, name):
    code, out, err = run(capsys, [*SPEED_COMMANDS[name], "--speed", "3000 rpm", "--json"])
    assert code == 0, err
    assert "3000.000000" not in out and "2999.99999" not in out
    doc = json.loads(out)
    echoed = [v for k, v in _items(doc) if k == "speed_rpm"]
    assert echoed and all(v == 3000 for v in echoed), echoed


# ----------------------------------------------------------------------------- missing output directories
OUTPUTS = {
    "high-speed --csv": ["high-speed", "-b", "B218", "-F", "20 kN", "-n", "1 rpm", "--csv"],
    "high-speed --plot": ["high-speed", "-b", "B218", "-F", "10 kN:20 kN:10 kN", "-n", "1 rpm", "--plot"],
    "frequencies --csv": ["frequencies", "-b", "6205-2RS", "-n", "3000 rpm", "--mask", "--csv"],
    "load-distribution --plot": ["load-distribution", "-b", "B218", "--fz", "5 kN", "--plot"],
    "load-distribution --ross": ["load-distribution", "-b", "B218", "--fz", "5 kN", "--ross"],
    "bearing-set --plot": ["bearing-set", "-b", "B218", "--preload", "1 kN", "--plot"],
    "runout --csv": ["runout", "-b", "B218", "--errors", ERRORS, "--revolutions", "1", "--csv"],
    "runout --plot": ["runout", "-b", "B218", "--errors", ERRORS, "--revolutions", "1", "--plot"],
    "monte-carlo --samples-csv": ["runout", "monte-carlo", "-b", "B218", "--samples", "2", "--samples-csv"],
    "monte-carlo --plot": ["runout", "monte-carlo", "-b", "B218", "--samples", "2", "--plot"],
    "monte-carlo --worst-dir": ["runout", "monte-carlo", "-b", "B218", "--samples", "2", "--write-worst", "1",
                                "--worst-dir"],
    "sweep --out": ["sweep", "examples/sweep/stand_geometry_variants.toml", "--out"],
    "friction lab --out": ["friction", "lab", "examples/friction/s1_readings.toml", "--out"],
}
SUFFIX = {"--plot": ".png", "--ross": ".json", "--worst-dir": "", "--out": ".csv"}


@pytest.mark.parametrize("name", OUTPUTS)
def test_a_missing_output_directory_is_refused_alike_by_every_command(capsys, tmp_path, name):
    option = name.split()[-1]
    suffix = "" if name.startswith(("runout --plot", "monte-carlo --plot", "friction lab")) else SUFFIX.get(option, ".csv")
    target = tmp_path / "missing" / f"out{suffix}"
    line = one_line(*run(capsys, [*OUTPUTS[name], target])[::2])
    assert f"{option[2:]}: directory" in line and "does not exist" in line, line
    assert not (tmp_path / "missing").exists()


# ----------------------------------------------------------------------------- JSON keys, every command
JSON_COMMANDS = {
    "high-speed": ["high-speed", "-b", "B218", "-F", "20 kN", "-n", "10000 rpm"],
    "high-speed sweep": ["high-speed", "-b", "B218", "-F", "10 kN, 20 kN", "-n", "10000 rpm"],
    "axial-angle": ["axial-angle", "-b", "4-1006095", "-F", "2 kgf"],
    "axial-angle list": ["axial-angle", "-b", "4-1006095", "-F", "1 kgf, 2 kgf"],
    "stand-load": ["stand-load", "-b", "4-1006095", "-n", "3000 rpm"],
    "frequencies": ["frequencies", "-b", "6205-2RS", "-n", "1797 rpm", "--mask"],
    "load-distribution": ["load-distribution", "-b", "B218", "--fx", "5 kN", "--fz", "10 kN"],
    "bearing-set": ["bearing-set", "-b", "B218", "--preload", "1 kN", "--fx", "2 kN"],
    "life": ["life", "-b", "B218", "--fx", "5 kN", "-n", "3000 rpm", "--viscosity", "20 cSt"],
    "friction torque": ["friction", "torque", "-b", "101", "-R", "10 N", "-A", "5 N"],
    "friction torque skf": ["friction", "torque", "--model", "skf", "-b", "6205-2RS", "-R", "1 kN", "-n",
                            "3000 rpm", "--viscosity", "20 cSt"],
    "catalog show": ["catalog", "show", "B218"],
    "catalog list": ["catalog", "list"],
    "runout": ["runout", "-b", "B218", "--errors", ERRORS],
    "sweep": ["sweep", "examples/sweep/stand_geometry_variants.toml"],
}
# bearing commands whose JSON echoes the bearing as used (at the top or under "inputs")
ECHOING = ("high-speed", "axial-angle", "stand-load", "frequencies", "load-distribution", "bearing-set", "life",
           "friction torque", "friction torque skf", "sweep")


def _items(doc):
    """Every (key, value) of a JSON document, nested ones included."""
    if isinstance(doc, dict):
        for k, v in doc.items():
            yield k, v
            yield from _items(v)
    elif isinstance(doc, list):
        for v in doc:
            yield from _items(v)


def _dicts(doc):
    if isinstance(doc, dict):
        yield doc
        for v in doc.values():
            yield from _dicts(v)
    elif isinstance(doc, list):
        for v in doc:
            yield from _dicts(v)


@pytest.fixture(scope="module")
def documents():
    """The JSON document of every command (run once for the tests below)."""
    import contextlib
    import io

    docs = {}
    for name, argv in JSON_COMMANDS.items():
        out = io.StringIO()
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
            code = main([*argv, "--json"])
        assert code == 0, name
        docs[name] = json.loads(out.getvalue())
    return docs


@pytest.mark.parametrize("name", JSON_COMMANDS)
def test_json_keys_carry_one_unit_per_quantity(documents, name):
    keys = [k for k, _ in _items(documents[name])]
    assert not [k for k in keys if k.endswith("_kN")], "forces are in N"
    assert not [k for k in keys if k.endswith("_Hz")], "frequencies are _hz in every command"
    lengths = [k for k in keys if re.search(r"(displacement|deflection|approach|clearance|preload_offset)_[a-z]+$", k)
               and not k.endswith("_ratio")]
    assert all(k.endswith("_um") for k in lengths), lengths
    for d in _dicts(documents[name]):
        for k in d:
            if k.endswith("_kgf"):  # the paper's unit, only beside the N value
                assert k[:-4] + "_N" in d, k


@pytest.mark.parametrize("name", ECHOING)
def test_every_result_echoes_the_bearing_it_used(documents, name):
    doc = documents[name]
    doc = doc[0] if isinstance(doc, list) else doc
    echo = doc.get("inputs", doc)
    assert echo["bearing"] and isinstance(echo["geometry"], dict) and echo["geometry"], sorted(doc)


def test_overrides_are_echoed(capsys):
    code, out, err = run(capsys, ["load-distribution", "-b", "B218", "--balls", "15", "--fz", "5 kN", "--json"])
    assert code == 0, err
    echo = json.loads(out)["inputs"]
    assert echo["catalog_bearing"] == "B218" and echo["overrides"] == {"balls": 15}
    assert echo["geometry"]["balls"] == 15


# ----------------------------------------------------------------------------- CSV booleans, every writer
CSV_COMMANDS = {
    "high-speed": (["high-speed", "-b", "B218", "-F", "1 kN, 20 kN", "-n", "10000 rpm", "--csv"], "x.csv"),
    "sweep": (["sweep", "examples/sweep/stand_geometry_variants.toml", "--out"], "x.csv"),
    "monte-carlo": (["runout", "monte-carlo", "-b", "B218", "--samples", "3", "--samples-csv"], "x.csv"),
    "runout": (["runout", "-b", "B218", "--errors", ERRORS, "--revolutions", "1", "--csv"], "x.csv"),
    "frequencies": (["frequencies", "-b", "6205-2RS", "-n", "3000 rpm", "--mask", "--csv"], "x.csv"),
}


@pytest.mark.parametrize("name", CSV_COMMANDS)
def test_csv_booleans_are_spelled_true_and_false(capsys, tmp_path, name):
    argv, file = CSV_COMMANDS[name]
    code, _, err = run(capsys, [*argv, tmp_path / file])
    assert code == 0, err
    rows = [r for r in csv.reader(line for line in (tmp_path / file).read_text().splitlines()
                                  if not line.startswith("#"))]
    cells = {c for r in rows[1:] for c in r}
    assert not cells & {"True", "False", "TRUE", "FALSE"}, name
    if name in ("high-speed", "sweep"):
        assert "true" in cells  # the converged column


# ----------------------------------------------------------------------------- δ in µm in printed tables
@pytest.mark.parametrize("argv", [
    ["high-speed", "-b", "B218", "-F", "20 kN", "-n", "10000 rpm"],
    ["high-speed", "-b", "B218", "-F", "10 kN, 20 kN", "-n", "10000 rpm"],
    ["axial-angle", "-b", "4-1006095", "-F", "2 kgf"],
    ["axial-angle", "-b", "4-1006095", "-F", "1 kgf, 2 kgf"],
    ["load-distribution", "-b", "B218", "--fx", "5 kN"],
    ["bearing-set", "-b", "B218", "--preload", "1 kN"],
], ids=lambda a: " ".join(a[:1] + a[-2:]))
def test_printed_displacements_are_in_um(capsys, argv):
    code, out, err = run(capsys, argv)
    assert code == 0, err
    units = re.findall(r"(?:δ\S*|displacement)[^\n│┃]*?(?:\[|\s)(µm|um|mm)\b", out)
    assert units and set(units) == {"µm"}, units


def test_profile_csv_rows_are_counted_from_1(capsys, tmp_path):
    """Item 18: a bad row of a measured profile is named by its line in the file, counted from 1."""
    source = Path("examples/runout")
    (tmp_path / "measured_profile.toml").write_text((source / "measured_profile.toml").read_text())
    lines = (source / "inner_roundness.csv").read_text().splitlines()
    first_data = next(k for k, line in enumerate(lines) if line and not line.startswith("#"))
    lines[first_data + 1] = "10, abc"  # the second data row
    (tmp_path / "inner_roundness.csv").write_text("\n".join(lines) + "\n")
    line = one_line(*run(capsys, ["runout", "--errors", tmp_path / "measured_profile.toml"])[::2])
    assert line.endswith(f"got '10, abc' on line {first_data + 2}"), line


# ----------------------------------------------------------------------------- speed guard and one speed
@pytest.mark.parametrize("name", SPEED_COMMANDS)
def test_an_impossible_speed_is_refused_alike_by_every_command(capsys, name):
    # the d_m n guard (bearinglab.limits.check_speed) of every speed option, the message in rpm
    line = one_line(*run(capsys, [*SPEED_COMMANDS[name], "--speed", "1e9 rpm"])[::2])
    assert re.search(r"speed must be <= [\d.e+]+ \[rpm\] for d_m = [\d.]+ mm .*got 1e\+09 rpm$", line), line


@pytest.mark.parametrize("name", ["frequencies", "bearing-set"])  # life takes a speed list (issue 30)
def test_one_speed_commands_refuse_a_list(capsys, name):
    line = one_line(*run(capsys, [*SPEED_COMMANDS[name], "--speed", "3000, 6000 rpm"])[::2])
    assert "speed" in line and ("one speed" in line or "a list of speeds" in line), line
