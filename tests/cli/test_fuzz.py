"""Issue 15: a fuzz test of the whole command line.

Every command of the application (found by walking the typer app, so a new command is fuzzed without
a line here) is run in-process with random options: values with and without units, lists, ranges,
garbage, and files of random bytes. Only three outcomes are allowed:

* exit 0, and no ``nan`` or ``inf`` in what was printed;
* exit 2 with one line ``bearinglab: error: ...`` on stderr (invalid or impossible input);
* exit 3 with one line (a genuine non-convergence).

No traceback, no numpy warning, nothing else. And (issue 20, items 5-9) whatever the outcome, no file
that existed before the run was changed (an output option given an input file's name is refused), no
missing directory was created, and no run allocates beyond the size limits: the pools hold malformed
quantities, huge counts and ranges, /dev/zero as an input file, and executors that are no scheduler.
The value pools keep every run small (a few cases per
command), and the slow commands get fewer examples, so that the CI run (derandomized, see
tests/conftest.py) of over 2000 examples stays near a minute and a half on two workers.
``BEARINGLAB_FUZZ_EXAMPLES`` sets the examples per command (default 220) for a longer local hunt.
"""

import os
import re
import shutil
from pathlib import Path

import pytest
import typer.main
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from bearinglab.cli import app, main

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"
EXAMPLES_PER_COMMAND = int(os.environ.get("BEARINGLAB_FUZZ_EXAMPLES", "220"))
# commands whose runs take 10 to 50 times longer (plots, reports, sweeps, sequences): fewer examples
SLOW = {("sweep",): 4, ("friction", "lab"): 8, ("runout",): 3, ("runout", "monte-carlo"): 2, ("bearing-set",): 6,
        # lists and prints all 646 catalog bearings each run (0.6-1.1 s): 220 runs took 250 s of the suite
        ("catalog", "list"): 10}


def _commands():
    """(path of names, click command) for every leaf command and every group that runs on its own."""
    out = []

    def walk(cmd, path):
        subs = getattr(cmd, "commands", None)
        if (subs is None or getattr(cmd, "invoke_without_command", False)) and path:
            out.append((tuple(path), cmd))
        for name, sub in (subs or {}).items():
            walk(sub, [*path, name])

    walk(typer.main.get_command(app), [])
    return out


# commands that do not return (a server): not fuzzed in-process
NOT_FUZZED = {("serve",)}
COMMANDS = {p: c for p, c in _commands() if p not in NOT_FUZZED}

QUANTITIES = [
    "2 kgf", "19.6 N", "20 kN", "0.05 kN", "1e9 N", "-5 N", "0 N", "1e-30 N", "2,5 kN", "1 kN, 5 kN",
    "1kN:3kN:1kN", "3000 rpm", "0 rpm", "-3000 rpm", "10000 1/min", "50 Hz", "1e12 rpm", "15000 RPM",
    "12 deg", "40 deg", "95 deg", "-1 deg", "14°28'03\"", "0.21 rad", "2 mm", "7.938 mm", "38.5 mm", "0 mm",
    "-2 mm", "1e300 mm", "9 um", "100 um", "2 m", "208 GPa", "0.07 N*mm", "20 cSt", "2 %", "0.52", "0.5",
    "nan", "inf", "-inf", "1e309", "", " ", "abc", "2 3 kgf", "1 000 N", "kgf", "2 kgf kgf", ";", ":", ",",
    "1:2", "1kN:0kN:1kN", "0,3000,6000rpm", "é", "\x00", "--json",
    # issue 20 item 5: one number and a unit, nothing else; item 6: ranges too big to build
    "1.2.3 N", "--5 N", "N", "kN*kN/kN", "pi kN", "2 pi kN", "10**308*10 N", "1kN:1e308kN:1kN", "1e308 kN",
    "1N:1e6N:1N", "0rpm:9999rpm:1rpm", "1e-300 N:1e300 N:1e-300 N", "70 degC", "68 mm^2/s", "50 N*m",
]
NUMBERS = ["-1", "0", "1", "2", "3", "7", "9", "16", "0.5", "0.52", "1.5", "-0.5", "1e9", "nan", "inf", "x",
           "1000000000", "99999999999999999999"]  # counts far beyond the size limits (issue 20 item 6)
NAMES = ["B218", "7218B", "4-1006095", "6205-2RS", "18", "61811-2RS1", "b218", "no-such-bearing", "", "G5",
         "P4", "newton", "outer", "mass", "harris", "exact", "table", "paper", "materials", "serial", "bogus",
         "steel", "silicon_nitride", "radial_ptp_max", "palmgren", "one-term", "skf", "grease", "oil-bath", "DB",
         "XX", "free", "VG68", "VG7000", "dirty", "normal"]
RUNOUT_FILES = [EXAMPLES / "runout" / "example1_oversize_ball.toml", EXAMPLES / "runout" / "example4_tilt.toml"]
BEARING_FILE = ('[bearings."X"]\nballs = 9\nball_diameter = "7.938 mm"\npitch_diameter = "38.5 mm"\n'
                'inner_conformity = 0.52\nouter_conformity = 0.53\ncontact_angle = "15 deg"\n')
# the valid files of an input option, by the command's first word and the parameter's name
VALID_FILES = {
    ("runout", "errors"): RUNOUT_FILES, ("runout", "geometry"): RUNOUT_FILES,
    ("sweep", "file"): [EXAMPLES / "sweep" / "stand_geometry_variants.toml"],
    ("friction", "file"): [EXAMPLES / "friction" / "s0_direct.toml", EXAMPLES / "friction" / "s1_readings.toml"],
}
OUTPUT_NAMES = ["out.csv", "out.png", "out.txt", "out.parquet", "missing/out.csv", "out", "out.json", "."]
# an output option given the name of an input file of the run (issue 20 item 7): must be refused
INPUT_AS_OUTPUT = "<an input>"
# the words of an option's name that make it a file or directory the command reads or writes
INPUT_WORDS = ("file", "catalog", "errors", "geometry")
OUTPUT_WORDS = ("csv", "plot", "out", "dir")
NOT_FINITE = re.compile(r"(?<![\w.'\"])(nan|inf|-inf|infinity)(?![\w])", re.IGNORECASE)  # not an echoed word ("series": "nan")


def _kind(param):
    name = (param.name or "").lower()
    if getattr(param, "is_flag", False):
        return "flag"
    if "csv" in name or "plot" in name or name in ("out", "output") or name.endswith("_dir"):
        return "output"
    if any(w in name for w in INPUT_WORDS) or (param.param_type_name == "argument" and name == "file"):
        return "input"
    return "value"


@st.composite
def _input_file(draw, workdir, good, command, name):
    choice = "valid" if good else draw(st.sampled_from(["bytes", "text", "missing", "directory", "device"]))
    if choice == "valid":  # a copy: a command may write where an input was expected (friction template)
        if (command, name) in VALID_FILES:
            source = draw(st.sampled_from(VALID_FILES[(command, name)]))
            for sibling in source.parent.iterdir():  # with the files it names (measurement CSVs)
                shutil.copy(sibling, workdir / sibling.name)
            return str(workdir / source.name)
        path = workdir / "bearing.toml"  # a catalog or a bearing file
        path.write_text(BEARING_FILE, encoding="utf-8")
        return str(path)
    if choice == "missing":
        return str(workdir / "no-such-file.toml")
    if choice == "directory":
        return str(workdir)
    if choice == "device" and os.path.exists("/dev/zero"):  # endless: refused before it is read
        # through a link in the work directory: a command that writes where an input was expected replaces
        # the link, never the device itself (the test may run as root)
        link = workdir / "zero.toml"
        if not link.is_symlink():
            link.symlink_to("/dev/zero")
        return str(link)
    path = workdir / f"in{draw(st.integers(0, 3))}.toml"
    if choice == "bytes":
        path.write_bytes(draw(st.binary(max_size=200)))
    else:
        lines = draw(st.lists(st.sampled_from([
            '[bearings."X"]', "balls = 40", 'ball_diameter = "7.938 mm"', 'pitch_diameter = "38.5 mm"',
            'contact_angle = "40 deg"', 'radial_clearance = "100 um"', "inner_conformity = 0.52",
            "outer_conformity = 0.53", 'model = "high-speed"', 'bearing = "B218"', "[parameters]",
            'axial_load = "1kN:3kN:1kN"', 'speed = "3000 rpm"', "[geometry]", "balls = 16", "[errors.balls]",
            "diameter = [2, 0]", "x = ", "[[", 'title = "t"', "[output]", 'file = "o.csv"', "output = 3",
            "[execution]", 'chunk_size = "x"', "chunk_size = 0", 'executor = "bogus"', "model = 3",
            'executor = "tcp://192.0.2.1:8786"', "[errors.outer.radial]", "cos = { 1000000000 = 0.5 }",
            "balls = 1000000000", "max_order = 99999999", 'chunk_size = 1',
        ]), max_size=12))
        path.write_text("\n".join(lines), encoding="utf-8")
    return str(path)


# values that make sense for an option (by its parameter name): most draws take one of these, so that
# the commands get past their input checks and compute; the rest come from the whole random pool
GOOD = {
    "axial_load": ["2 kgf", "1 kN", "20 kN", "5kN,20kN", "1kN:3kN:1kN", "0.05 kN"],
    "radial_load": ["1 kN", "0 N", "500 N"],
    "speed": ["3000 rpm", "0 rpm", "15000 rpm", "50 Hz", "10000 1/min", "0,3000rpm"],
    "outer_speed": ["0 rpm", "100 rpm"],
    "bearing": ["B218", "4-1006095", "7218B"],
    "name": ["B218", "7218B", "4-1006095", "18"],
    "hertz": ["exact", "table"], "elastic_constant": ["materials", "paper"],
    "solver": ["newton", "angle-iteration"], "raceway_control": ["outer", "inner"],
    "constants": ["mass", "harris", "paper"], "gyroscopic_sign": ["physical", "reversed"],
    "executor": ["serial", "serial", "serial", "tcp://127.0.0.1:1", "<garbage server>"], "workers": ["1"],
    "chunk_size": ["1", "50"],
    "revolutions": ["1", "2"], "steps_per_rev": ["36", "90"], "samples": ["2", "5"], "seed": ["0", "7"],
    "max_order": ["3", "15"], "angle": ["0", "10 deg"], "start_angle": ["0 deg", "5 deg"],
    "first_ball_angle": ["0 deg", "3 deg"], "cage_ratio": ["0.4", "0.45"], "ball_grade": ["G5", "G10"],
    "ring_class": ["P4", "P5"], "write_worst": ["1"], "worst_by": ["radial_ptp_max"],
    "harmonics": ["1", "3"], "sidebands": ["0", "1"], "band": ["2 %", "1%"], "x0": ["0.04"], "rows": ["1", "2"],
    "balls": ["7", "9", "16"], "ball_diameter": ["2 mm", "7.938 mm"], "pitch_diameter": ["8.7355 mm", "38.5 mm"],
    "inner_conformity": ["0.52"], "outer_conformity": ["0.53"], "contact_angle": ["12 deg", "40 deg"],
    "radial_clearance": ["9 um", "20 um"], "ball_material": ["steel", "silicon_nitride"],
    "reduced_modulus": ["228 GPa"], "memory_limit": ["1GiB"],
    # load-distribution, bearing-set, life, friction torque (all its models), catalog show
    "fx": ["1 kN", "0 N", "-500 N", "5 kN"], "fy": ["0 N", "300 N"], "fz": ["1 kN", "0 N", "-2 kN", "10 kN"],
    "mx": ["0 N*m", "50 N*m"], "my": ["0 N*m", "-20 N*m"], "stiffness_at": ["operating", "free"],
    "arrangement": ["DB", "DF", "DT"], "spacing": ["0 mm", "100 mm"], "preload": ["500 N", "2 kN"],
    "preload_offset": ["5 um", "0 um"], "model": ["one-term", "two-term", "palmgren", "skf", "skf"],
    "viscosity": ["20 cSt", "2 cSt", "100 cSt"], "lubrication": ["grease", "oil-air", "oil-jet"],
    "oil": ["VG68", "VG32"], "viscosity_100": ["8.7 cSt"], "temperature": ["70 degC", "40 degC"],
    "contamination_factor": ["0.5", "1"], "contamination": ["normal", "severe"], "reliability": ["90", "99"],
    "f0": ["2e-7"], "palmgren_f0": ["1.5"], "mu": ["0.0015"],
}
# the commands that need a bearing with catalog ratings or an SKF series draw these too
GOOD_BEARINGS = {"friction": ["6205-2RS", "61811-2RS1", "101", "18"], "life": ["6205-2RS", "B218", "7218B"],
                 "catalog": ["6205-2RS", "61811-2RS1", "101"]}
# options whose default makes a run long (200 Monte Carlo samples, 3 x 360 positions): always given,
# mostly with a small value, so that the examples stay fast
SMALL = ("samples", "steps_per_rev", "revolutions")
# an option of a new command not in GOOD: one of these may fit (a number, or a quantity of some kind)
ANY_GOOD = ["1", "0.5", "2", "2 kN", "3000 rpm", "20 cSt", "0.07 N*mm", "12 deg", "8 mm", "B218"]
# options that make a command run at all: drawn more often than the others
LIKELY = ("bearing", "errors", "file", "name", "viscosity")
LIKELY_FOR = {"life": ("speed",)}  # an optional option that a command needs to compute
# the inline geometry: any one of them changes the bearing, so they are drawn rarely
INLINE = ("balls", "ball_diameter", "pitch_diameter", "inner_groove_radius", "outer_groove_radius",
          "inner_conformity", "outer_conformity", "contact_angle", "radial_clearance", "ball_material")


@st.composite
def _argv(draw, path, command, workdir):
    args = list(path)
    inputs = []
    for param in command.params:
        if param.name in ("help",):
            continue
        kind = _kind(param)
        chance = 80 if param.name in LIKELY or param.name in LIKELY_FOR.get(path[0], ()) else (6 if kind == "input" or param.name in INLINE else 25)
        if param.name in SMALL:
            chance = 100
        if not param.required and draw(st.integers(0, 99)) >= chance:
            continue
        good = draw(st.integers(0, 99)) < 90
        if kind == "flag":
            value = None
        elif kind == "input":
            value = draw(_input_file(workdir, good, path[0], param.name))
            inputs.append(value)
        elif kind == "output":
            name = draw(st.sampled_from([*OUTPUT_NAMES, INPUT_AS_OUTPUT] if inputs else OUTPUT_NAMES))
            value = draw(st.sampled_from(inputs)) if name == INPUT_AS_OUTPUT else str(workdir / name)
        elif good:
            pool = GOOD.get(param.name, ANY_GOOD)
            if param.name in ("bearing", "name"):
                pool = pool + GOOD_BEARINGS.get(path[0], [])
            value = draw(st.sampled_from(pool))
        else:
            value = draw(st.sampled_from(QUANTITIES + NUMBERS + NAMES))
        if value == "<garbage server>":
            value = _garbage_server()
        if param.param_type_name == "argument":
            args.append(value)
            continue
        if kind == "flag":  # --json, or one of --progress/--no-progress
            args.append(draw(st.sampled_from(list(param.opts) + list(param.secondary_opts or []))))
            continue
        args.append(param.opts[0])
        if value is not None:
            args.append(value)
    return args


_GARBAGE = []


def _garbage_server():
    """The address of a TCP server on 127.0.0.1 that answers like a web server, not a dask scheduler
    (issue 20 item 9); one per test session, a daemon thread."""
    import socket
    import threading

    if not _GARBAGE:
        sock = socket.create_server(("127.0.0.1", 0))

        def serve():
            while True:
                try:
                    conn, _ = sock.accept()
                except OSError:
                    return
                with conn:
                    conn.sendall(b"HTTP/1.0 400 Bad Request\r\n\r\n")

        threading.Thread(target=serve, daemon=True).start()
        _GARBAGE.append(f"tcp://127.0.0.1:{sock.getsockname()[1]}")
    return _GARBAGE[0]


def _snapshot(workdir):
    """Every file under ``workdir`` -> its bytes (the inputs of a run, before it)."""
    return {p: p.read_bytes() for p in workdir.rglob("*") if p.is_file() and not p.is_symlink()}


# commands whose file argument is what they write (with --force they replace it on purpose)
WRITES_ITS_ARGUMENT = {("friction", "template")}


def _check_files(path, argv, workdir, before):
    where = f"bearinglab {' '.join(map(repr, argv))}"
    assert not (workdir / "missing").exists(), f"{where}: created a missing directory"
    if path in WRITES_ITS_ARGUMENT:
        return
    for file, data in before.items():
        assert file.exists() and file.read_bytes() == data, f"{where}: changed the input {file}"


def _check_outcome(argv, code, out, err):
    where = f"bearinglab {' '.join(map(repr, argv))}"
    assert "Traceback" not in err and "Warning:" not in err, f"{where}\n{err}"
    if code == 0:
        assert not NOT_FINITE.search(out), f"{where}: a non-finite number in the output\n{out}"
        return
    assert code in (2, 3), f"{where}: exit {code}\n{err}"
    lines = [ln for ln in err.splitlines() if ln.strip() and not ln.startswith("bearinglab: warning:")]
    assert len(lines) == 1 and lines[0].startswith("bearinglab: error: "), f"{where}: exit {code}\n{err}"


@pytest.mark.parametrize("path", sorted(COMMANDS), ids=lambda p: "-".join(p))
def test_fuzz_command(path, tmp_path_factory, capsys, monkeypatch):
    workdir = tmp_path_factory.mktemp("fuzz")
    monkeypatch.chdir(workdir)  # commands that write next to the working directory write here
    monkeypatch.delenv("BEARINGLAB_CATALOG", raising=False)
    monkeypatch.setenv("COLUMNS", "80")
    from bearinglab import parallel

    monkeypatch.setattr(parallel, "_CONNECT_TIMEOUT_S", 0.5)  # an unreachable scheduler costs 0.5 s, not 10
    command = COMMANDS[path]

    @settings(max_examples=EXAMPLES_PER_COMMAND // SLOW.get(path, 1), deadline=None, database=None,
              suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                     HealthCheck.function_scoped_fixture])
    @given(argv=_argv(path, command, workdir))
    def run(argv):
        before = _snapshot(workdir)
        try:
            code = main(argv)
            _check_files(path, argv, workdir, before)
        finally:
            out, err = capsys.readouterr()
            for child in workdir.iterdir():  # a clean directory for the next example
                shutil.rmtree(child) if child.is_dir() else child.unlink()
        _check_outcome(argv, code, out, err)

    run()


def test_every_command_is_fuzzed():
    names = {" ".join(p) for p in COMMANDS}
    for expected in ("axial-angle", "high-speed", "runout", "runout monte-carlo", "catalog list", "sweep",
                     "load-distribution", "bearing-set", "life", "friction torque", "catalog show"):
        assert expected in names
    assert sum(EXAMPLES_PER_COMMAND // SLOW.get(p, 1) for p in COMMANDS) >= 2000
