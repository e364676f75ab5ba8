"""Issue 20, items 2 and 13: every command, and its help, on any output encoding and in 80 columns.

Every command of the application (listed from the application itself, so that a new command without a
representative invocation here fails ``test_every_command_has_an_invocation``) runs with its ``--help``:

* under ``PYTHONIOENCODING=cp1252`` (a redirection on Windows) and ``ascii``: the documented exit code,
  no traceback, no UnicodeEncodeError, and the Greek letters, degree signs and box lines spelled the
  ASCII way (``alpha``, ``deg``, ``+--+``) where the encoding cannot hold them;
* under UTF-8 too, and in each run with ``COLUMNS=80`` on a pipe: no line wider than 80 columns.

The runs are batched, one interpreter per encoding (the three run at once), each calling ``cli.main``
for every invocation in turn, as the console script does; ``test_console_script_*`` run the real entry
point (``python -m bearinglab``). Output files go to a temporary directory.
"""

import json
import os
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from bearinglab.cli import _click_command
from bearinglab.cli._console import ERRORS, ascii_spelling, needs_spelling

ROOT = Path(__file__).resolve().parents[2]
RUNOUT = "examples/runout/example3_mixed.toml"

# command path -> (arguments after it, the exit code they document); {tmp} is a temporary directory
INVOCATIONS = {
    "axial-angle": ("-b 4-1006095 -F 2kgf", 0),
    "stand-load": ("-b 4-1006095 -n 3000rpm,10000rpm", 0),
    "frequencies": ("-b 4-1006095 -n 3000rpm -F 2kgf --mask --harmonics 2", 0),
    "sweep": ("examples/sweep/stand_geometry_variants.toml --out {tmp}/sweep.csv", 0),
    "high-speed": ("-b B218 -A 5kN,20kN -n 0rpm,15000rpm", 0),
    "load-distribution": ("-b B218 --fx 5kN --fz 10kN --my 50N*m", 0),
    "bearing-set": ("-b B218 --arrangement DB --spacing 100mm --preload 2kN --fx 3kN", 0),
    "life": ("-b 6205-2RS --fx 2kN --speed 3000rpm --viscosity 20cSt", 0),
    "clearance": ("-b 6208-2RS1/C3 --shaft-fit k5 --housing-fit H7 --inner-ring-temperature 60degC", 0),
    "film": ("-b B218 --fx 5kN --fz 10kN --speed 6000rpm --oil VG68 --temperature 70degC --roughness 0.1um", 0),
    "temperature": ("-b 6208 -R 2kN --speed 3000rpm --oil VG68", 0),
    "serve": ("--port 99999", 2),  # refused before anything starts: the one-line error, no traceback
    "catalog list": ("", 0),
    "catalog show": ("B218", 0),
    "catalog search": ("--bore 40mm --type deep-groove", 0),
    "friction torque": ("--model skf -b 6205-2RS --radial-load 0N:2000N:1000N -n 2000rpm --viscosity 30cSt", 0),
    "friction lab": ("examples/friction/s1_readings.toml --out {tmp}/lab", 0),
    "friction template": ("-b 18", 0),
    "runout": (f"--errors {RUNOUT} --angle 90", 0),
    "runout monte-carlo": ("--geometry examples/runout/monte_carlo_reference.toml --samples 50 --seed 1", 0),
    "shaft": ("examples/shaft/spindle.toml --stiffness-at 0mm --modes 2", 0),
}
# more of what the commands print: the one-term friction table, the iteration table of axial-angle,
# a single case of high-speed and of the SKF model, a rotation sequence of runout
EXTRA = [
    ("axial-angle", "-b B218 -F 5kN,10kN,20kN", 0),
    ("high-speed", "-b B218 -F 20kN -n 15000rpm", 0),
    ("friction torque", "-b 101 --radial-load 0N:40N:20N --axial-load 5N -n 3000rpm --model two-term --f0 1.5e-7", 0),
    ("friction torque", "--model skf -b 61811-2RS1 --radial-load 6.51N -n 2000rpm --viscosity 30cSt", 0),
    ("runout", f"--errors {RUNOUT} --revolutions 1 --steps-per-rev 36", 0),
    ("axial-angle", "-b 4-1006095 -F 2kgf --json", 0),  # a JSON document with a degree sign in it
]


def _commands(command=None, path=()):
    """Every command path of the application, groups that run on their own (``runout``) included."""
    command = command or _click_command()
    out = []
    subs = getattr(command, "commands", None)
    if path and (not subs or getattr(command, "invoke_without_command", False)):
        out.append(" ".join(path))
    for name, sub in (subs or {}).items():
        out.extend(_commands(sub, (*path, name)))
    return out


def test_every_command_has_an_invocation():
    assert sorted(_commands()) == sorted(INVOCATIONS)


def _runs(tmp):
    runs = [(path, f"{path} {args}", code) for path, (args, code) in INVOCATIONS.items()]
    runs += [(path, f"{path} {args}", code) for path, args, code in EXTRA]
    runs += [(path, f"{path} --help", 0) for path in ["", *INVOCATIONS]]
    return [(path, line.format(tmp=tmp).split(), code) for path, line, code in runs]


_DRIVER = textwrap.dedent("""
    import json, sys, traceback
    from bearinglab.cli import main
    for k, argv in enumerate(json.loads(sys.argv[1])):
        try:
            code = main(argv)
        except BaseException:  # what would reach the user as a traceback
            traceback.print_exc()
            code = "traceback"
        sys.stdout.flush()
        sys.stderr.flush()
        sys.stdout.write(f"\\x1e{k}\\n")
        sys.stderr.write(f"\\x1e{k} {code}\\n")
        sys.stdout.flush()
        sys.stderr.flush()
""")


ENCODINGS = ("cp1252", "ascii", "utf-8")


@pytest.fixture(scope="module")
def batches(tmp_path_factory):
    """Every run under each encoding: {encoding: [(path, argv, expected code, code, stdout, stderr)]}."""
    procs, every = {}, {}
    for encoding in ENCODINGS:  # the three at once, each writing its files in a directory of its own
        runs = every[encoding] = _runs(tmp_path_factory.mktemp(encoding))
        env = dict(os.environ, PYTHONIOENCODING=encoding, COLUMNS="80", PYTHONPATH=str(ROOT / "src"))
        env.pop("FORCE_COLOR", None)
        procs[encoding] = subprocess.Popen([sys.executable, "-c", _DRIVER, json.dumps([a for _, a, _ in runs])],
                                           cwd=ROOT, env=env, stdin=subprocess.DEVNULL,
                                           stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    out = {}
    for encoding, proc in procs.items():
        runs = every[encoding]
        stdout, stderr = proc.communicate(timeout=600)
        outs = stdout.decode(encoding).split("\x1e")
        errs = stderr.decode(encoding).split("\x1e")
        assert len(outs) == len(runs) + 1, stderr.decode(encoding)[-3000:]
        rows = []
        for k, (path, argv, expected) in enumerate(runs):
            head = errs[k + 1].partition("\n")[0]
            assert head.split()[0] == str(k)
            code = head.split()[1]
            # the k-th output is before the k-th separator; drop the separator's index line
            text = outs[k].split("\n", 1)[1] if k else outs[k]
            err = errs[k].split("\n", 1)[1] if k else errs[k]
            rows.append((path, argv, expected, code, text, err))
        out[encoding] = rows
    return out


@pytest.mark.parametrize("encoding", ["cp1252", "ascii"])
def test_every_command_runs_on_a_narrow_encoding(batches, encoding):
    bad = [(" ".join(argv), code, err[-500:]) for _, argv, expected, code, _, err in batches[encoding]
           if code != str(expected) or "Traceback" in err or "UnicodeEncodeError" in err]
    assert not bad, bad


@pytest.mark.parametrize("encoding", ["cp1252", "ascii"])
def test_characters_are_spelled_not_lost(batches, encoding):
    """A table on an ASCII stream has ASCII boxes and Greek names; cp1252 keeps the µ and ° it holds."""
    text = "".join(out for *_, out, _ in batches[encoding])
    assert "alpha" in text and "+-" in text and "┃" not in text
    assert ("µm" in text and "°" in text) if encoding == "cp1252" else text.isascii()
    # every character the project writes is in the spelling table: a '?' is never a lost character
    assert "?" not in text  # no "?" of an unknown character in any output


# what a command writes on stdout as a file, not as a console text: the session template (a TOML file
# whose rows header is CSV data) is as wide as its format needs, as a --json document is
FILE_FORMATS = {"friction template -b 18"}


@pytest.mark.parametrize("encoding", ["utf-8", "cp1252", "ascii"])
def test_every_output_fits_80_columns(batches, encoding):
    wide = [(" ".join(argv), max(map(len, out.splitlines()), default=0))
            for _, argv, *_, out, _ in batches[encoding] if " ".join(argv) not in FILE_FORMATS]
    assert all(width <= 80 for _, width in wide), [w for w in wide if w[1] > 80]


def test_no_table_is_stacked_at_80_columns(batches):
    """The default output of every command is designed for 80 columns: no table falls back to one small
    table per row ('(1 of 16)')."""
    stacked = [" ".join(argv) for _, argv, *_, out, _ in batches["utf-8"] if " of " in out and "(1 of" in out]
    assert not stacked, stacked


def test_no_cyrillic_and_no_spec_numbers_in_output(batches):
    for _, argv, *_, out, _ in batches["utf-8"]:
        assert not any("\u0400" <= c <= "\u04ff" for c in out), argv
        assert "spec 00" not in out and "paper fig" not in out, argv


def test_json_is_the_same_document_on_every_encoding(batches):
    """A JSON document's strings are exact on any stream: JSON escapes, not an ASCII spelling."""
    docs = {e: [json.loads(out) for _, argv, *_, out, _ in batches[e] if "--json" in argv] for e in ENCODINGS}
    assert docs["utf-8"] and any("°" in json.dumps(d, ensure_ascii=False) for d in docs["utf-8"])
    assert docs["ascii"] == docs["utf-8"] and docs["cp1252"] == docs["utf-8"]


def test_files_are_utf8_whatever_the_console(batches):
    """The report the friction-rig lab writes under an ASCII console is UTF-8, its Greek letters kept."""
    lab = next(argv for path, argv, *_ in batches["ascii"] if path == "friction lab" and "--out" in argv)
    html = (Path(lab[lab.index("--out") + 1]) / "report.html").read_text(encoding="utf-8")
    assert "μ" in html and "β" in html


# ----------------------------------------------------------------------------- the console script itself
def _script(args, encoding, stdin=subprocess.DEVNULL):
    """``python -m bearinglab ARGS`` with stdout on a pipe and no $COLUMNS."""
    env = dict(os.environ, PYTHONIOENCODING=encoding, PYTHONPATH=str(ROOT / "src"))
    env.pop("COLUMNS", None)
    return subprocess.run([sys.executable, "-m", "bearinglab", *args], cwd=ROOT, env=env, stdin=stdin,
                          capture_output=True, timeout=120, check=False)


@pytest.mark.parametrize("encoding", ["cp1252", "ascii"])
def test_console_script_help_on_a_narrow_encoding(encoding):
    p = _script(["high-speed", "--help"], encoding)
    err = p.stderr.decode(encoding)
    assert p.returncode == 0 and "Traceback" not in err, err
    assert "-A" in p.stdout.decode(encoding) and "alpha_i" in p.stdout.decode(encoding)


@pytest.mark.skipif(not hasattr(os, "openpty"), reason="needs a pseudo-terminal")
def test_console_script_on_a_pipe_is_80_wide_whatever_the_terminal():
    """stdout to a pipe, stdin on a 200-column terminal, no $COLUMNS: 80 columns, the help included."""
    import fcntl
    import struct
    import termios

    master, slave = os.openpty()
    try:
        fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", 50, 200, 0, 0))
        # the help fills the console's width; the catalog's table is 87 columns wide where it may be
        for args, width in ((["high-speed", "--help"], 80), (["catalog", "list"], None)):
            p = _script(args, "utf-8", stdin=slave)
            out = p.stdout.decode()
            assert p.returncode == 0, p.stderr.decode()
            assert max(map(len, out.splitlines())) == width if width else max(map(len, out.splitlines())) <= 80, out
    finally:
        os.close(master)
        os.close(slave)


# ----------------------------------------------------------------------------- the spelling itself
@pytest.mark.parametrize("text, spelled", [
    ("α_i [deg]", "alpha_i [deg]"), ("κ = 1.52", "kappa = 1.52"), ("δ_a [µm]", "delta_a [um]"),
    ("14°28′03.97″", "14d28'03.97\""), ("12°", "12deg"), ("ψ, θ, Δ", "psi, theta, Delta"),
    ("M [N·mm]", "M [N*mm]"), ("5 × 5", "5 x 5"), ("−0.5", "-0.5"), ("a ≤ b ≥ c", "a <= b >= c"),
    ("m² m³", "m^2 m^3"), ("10⁻⁶", "10^-6"), ("inner (в)", "inner (v)"), ("┏━┳┓│", "+-++|"),
    ("Sjoväll", "Sjovall"), ("μ_sl", "mu_sl"), ("\u2603", "?"),
])
def test_ascii_spelling(text, spelled):
    assert ascii_spelling(text) == spelled
    assert ascii_spelling(text).isascii()


def test_the_error_handler_spells_what_the_encoding_cannot_hold():
    assert "α ≤ 2 µm, 20 °C".encode("cp1252", errors=ERRORS) == "alpha <= 2 µm, 20 °C".encode("cp1252")
    assert "α ≤ 2 µm".encode("ascii", errors=ERRORS) == b"alpha <= 2 um"
    with pytest.raises(UnicodeDecodeError):
        b"\xff".decode("ascii", errors=ERRORS)


@pytest.mark.parametrize("encoding, needed", [("utf-8", False), ("UTF-8", False), ("cp1252", True),
                                              ("ascii", True), ("latin-1", True), ("gb18030", False),
                                              (None, True), ("no-such-codec", True)])
def test_needs_spelling(encoding, needed):
    assert needs_spelling(encoding) is needed
