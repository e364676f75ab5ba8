"""Issue 20, items 5-7 and 9: malformed quantities, size limits, inputs never touched, a wrong executor.

Each test drives the command line in-process (``bearinglab.cli.main``) and checks the exit code and the one
line on stderr, or calls the library function that the command line relies on.
"""

import errno
import os
import signal
import socket
import subprocess
import sys
import textwrap
import threading
from pathlib import Path

import numpy as np
import pytest

from bearinglab import _bounds, _io, parallel
from bearinglab import sweep as sweep_module
from bearinglab.cli import main
from bearinglab.errors import InputError

ROOT = Path(__file__).resolve().parents[2]
ERRORS_EXAMPLE = ROOT / "examples" / "runout" / "example1_oversize_ball.toml"
SWEEP_EXAMPLE = ROOT / "examples" / "sweep" / "stand_geometry_variants.toml"


def run(capsys, *args):
    code = main([str(a) for a in args])
    out, err = capsys.readouterr()
    return code, out, err


def one_line_error(code, err):
    assert code == 2, err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("bearinglab: error: "), err
    return lines[0]


# ----------------------------------------------------------------------------- item 5: quantities
@pytest.mark.parametrize(
    "value, match",
    [
        ("1.2.3 N", r"axial-load: cannot read '1.2.3 N' as a quantity: write one number and one unit"),
        ("--5 N", r"axial-load: cannot read '--5 N' as a quantity"),
        ("N", r"axial-load: cannot read 'N' as a quantity: it has no number"),
        ("kN*kN/kN", r"axial-load: cannot read 'kN\*kN/kN' as a quantity: it has no number"),
        ("pi kN", r"axial-load: cannot read 'pi kN' as a quantity: it has no number"),
        ("2 pi kN", r"'pi' is a constant, not a unit"),
        ("10**308*10 N", r"axial-load: cannot read '10\*\*308\*10 N' as a quantity"),
        ("1kN:1e308kN:1kN", r"axial-load: '1e308kN' is not a finite quantity \(it overflows in SI units\)"),
        ("nan N", r"not a finite quantity"),
    ],
)
def test_malformed_quantity_is_one_line_naming_the_option(capsys, value, match):
    import re

    line = one_line_error(*run(capsys, "axial-angle", "-b", "4-1006095", "-F", value)[::2])
    assert re.search(match, line), line


@pytest.mark.parametrize("value", ["2 kgf", "19.6 N", "0.02 kN", "5kN,20kN", "2.5kN:45kN:2.5kN"])
def test_good_quantities_still_compute(capsys, value):
    code, _out, err = run(capsys, "axial-angle", "-b", "4-1006095", "-F", value, "--json")
    assert code == 0, err


# ----------------------------------------------------------------------------- item 6: sizes
def _never(*_args, **_kwargs):
    raise AssertionError("computed before the size was checked")


def test_product_of_ranges_is_refused_before_the_grid(capsys, monkeypatch):
    from bearinglab import quasistatic

    monkeypatch.setattr(quasistatic, "sweep", _never)
    # each range alone is within the per-list limit; their product (10^9 cases) is not
    line = one_line_error(*run(capsys, "high-speed", "-b", "B218", "-F", "1N:1e5N:1N", "-n",
                               "0rpm:9999rpm:1rpm")[::2])
    assert "cases: 100000 thrusts x 10000 speeds make 1e+09 cases, more than the limit of 1e+05" in line
    assert "bearinglab sweep` on dask, in chunks" in line


def test_the_issue_example_is_refused_naming_the_limit(capsys):
    line = one_line_error(*run(capsys, "high-speed", "-b", "B218", "-F", "1N:1e6N:1N", "-n",
                               "0rpm:9999rpm:1rpm")[::2])
    assert "more than the limit of 1e+05" in line and "sweep" in line


def test_range_is_counted_before_it_is_built(monkeypatch):
    from bearinglab import units

    def no_arange(*a, **k):
        raise AssertionError("the range was built")

    monkeypatch.setattr(units.np, "arange", no_arange)
    with pytest.raises(InputError, match=r"x: range '1N:1e12N:1N' has 1e\+12 values, more than the limit"):
        units.parse_values("1N:1e12N:1N", "force", "x")


@pytest.mark.parametrize(
    "args, match",
    [
        (["axial-angle", "-b", "4-1006095", "-F", "2 kgf", "--rows", "1000000000"],
         r"rows must be <= 1000 \[-\] \(bearinglab's size limit\), got 1000000000"),
        (["frequencies", "-b", "B218", "-n", "3000 rpm", "--mask", "--harmonics", "1000000000"],
         r"harmonics must be <= 1000 \[-\]"),
        (["frequencies", "-b", "B218", "-n", "3000 rpm", "--mask", "--sidebands", "1000000000"],
         r"sidebands must be <= 100 \[-\]"),
        (["frequencies", "-b", "B218", "-n", "3000 rpm", "--sidebands", "-1"], r"sidebands must be an integer >= 0"),
        (["runout", "--errors", ERRORS_EXAMPLE, "--revolutions", "1000000000"],
         r"revolutions must be <= 10000 \[-\]"),
        (["runout", "--errors", ERRORS_EXAMPLE, "--revolutions", "2", "--steps-per-rev", "1000000000"],
         r"steps-per-rev must be <= 100000 \[-\]"),
        (["runout", "--errors", ERRORS_EXAMPLE, "--revolutions", "100", "--steps-per-rev", "36000"],
         r"revolutions x steps-per-rev must be <= 1000000 positions \(bearinglab's size limit\), got 100 x 36000"),
        (["runout", "monte-carlo", "-b", "B218", "--samples", "2", "--revolutions", "10", "--steps-per-rev", "3600"],
         r"revolutions x steps-per-rev must be <= 10000 positions"),
        (["runout", "monte-carlo", "-b", "B218", "--samples", "2", "--max-order", "1000000000"],
         r"max-order must be <= 10000 \[-\]"),
        (["runout", "monte-carlo", "-b", "B218", "--samples", "1000000000000"], r"samples must be <= 10000000"),
        (["runout", "monte-carlo", "-b", "B218", "--samples", "2", "--revolutions", "1000000000"],
         r"revolutions must be <= 10000"),
        (["axial-angle", "-b", "4-1006095", "--balls", "1000000000", "-F", "2 kgf"], r"balls must be <= 1000 \[-\]"),
        (["high-speed", "-b", "B218", "-F", "1 kN", "-n", "3000 rpm", "--executor", "local", "--workers",
          "1000000"], r"workers must be <= 256 \[-\]"),
        (["stand-load", "-b", "B218", "-n", "0rpm:1e6rpm:1rpm"], r"more than the limit of 1e\+05"),
        (["friction", "torque", "-b", "6205-2RS", "-A", "0N:1e6N:1N", "-n", "3000 rpm", "--viscosity", "20 cSt"],
         r"axial-load: range .* more than the limit of 1e\+05"),
    ],
)
def test_count_options_are_bounded(capsys, monkeypatch, args, match):
    import re

    from bearinglab import runout, stand

    # nothing may be computed before the check (the sizes would allocate first)
    monkeypatch.setattr(stand, "stand_analysis", _never)
    monkeypatch.setattr(runout, "rotation_sequence", _never)
    monkeypatch.setattr(runout, "monte_carlo", _never)
    line = one_line_error(*run(capsys, *args)[::2])
    assert re.search(match, line), line


def _runout_file(tmp_path, text):
    path = tmp_path / "errors.toml"
    path.write_text(ERRORS_EXAMPLE.read_text(encoding="utf-8") + text, encoding="utf-8")
    return path


def test_fourier_order_in_a_runout_file_is_bounded(tmp_path, capsys):
    doc = ERRORS_EXAMPLE.read_text(encoding="utf-8")
    assert "[errors.outer" not in doc  # the example has no ring series: add one
    path = _runout_file(tmp_path, '\n[errors.outer.radial]\ncos = { 1000000000 = 0.5 }\n')
    line = one_line_error(*run(capsys, "runout", "--errors", path)[::2])
    assert "Fourier order must be <= 10000 (bearinglab's size limit), got 1000000000" in line
    assert str(path) in line


def test_ball_count_in_a_runout_file_is_bounded(tmp_path, capsys):
    text = ERRORS_EXAMPLE.read_text(encoding="utf-8")
    import re

    path = tmp_path / "errors.toml"
    path.write_text(re.sub(r"(?m)^balls = \d+", "balls = 1000000000", text), encoding="utf-8")
    line = one_line_error(*run(capsys, "runout", "--errors", path)[::2])
    assert "'balls'" in line and "must be <= 1000 (bearinglab's size limit), got 1000000000" in line


def test_sweep_grid_is_bounded_before_it_is_built(tmp_path, capsys, monkeypatch):
    monkeypatch.setattr(sweep_module.np, "meshgrid", _never)
    path = tmp_path / "big.toml"
    path.write_text('model = "axial-angle"\nbearing = "4-1006095"\n[parameters]\n'
                    'axial_load = "1N:1e6N:1N"\ncontact_angle = "1deg:45deg:0.001deg"\n', encoding="utf-8")
    line = one_line_error(*run(capsys, "sweep", path)[::2])
    assert "more than the limit of 1e+07" in line and "split the study into several sweeps" in line
    with pytest.raises(InputError, match="more than the limit of 1e\\+07"):
        sweep_module.case_grid({"a": np.zeros(10_000), "b": np.zeros(10_000)})


@pytest.mark.parametrize("device", ["/dev/zero", "/dev/urandom"])
@pytest.mark.parametrize("option", ["catalog", "bearing-file", "errors", "sweep"])
def test_devices_are_not_read(capsys, device, option):
    if not os.path.exists(device):
        pytest.skip(f"no {device}")
    args = {"catalog": ["catalog", "list", "--catalog", device],
            "bearing-file": ["axial-angle", "--bearing-file", device, "-F", "1 kN"],
            "errors": ["runout", "--errors", device],
            "sweep": ["sweep", device]}[option]
    line = one_line_error(*run(capsys, *args)[::2])
    assert "not a regular file" in line and device in line


def test_fifo_is_not_read_and_does_not_hang(tmp_path, capsys):
    fifo = tmp_path / "pipe.toml"
    os.mkfifo(fifo)
    line = one_line_error(*run(capsys, "axial-angle", "--bearing-file", fifo, "-F", "1 kN")[::2])
    assert "not a regular file" in line


def test_input_file_size_is_bounded(tmp_path, capsys, monkeypatch):
    monkeypatch.setattr(_bounds, "MAX_INPUT_BYTES", 1000)
    path = tmp_path / "cat.toml"
    path.write_text("# padding\n" * 200, encoding="utf-8")
    with pytest.raises(InputError, match=r"cat.toml: 2000 bytes, more than the limit of 1000 bytes"):
        _bounds.read_input_bytes(path, limit=1000)
    line = one_line_error(*run(capsys, "catalog", "list", "--catalog", path)[::2])
    assert "more than the limit of 1000 bytes" in line


@pytest.mark.parametrize("error, words", [(MemoryError, "out of memory"), (OverflowError, "overflow"),
                                          (RecursionError, "nested too deeply")])
def test_memory_overflow_recursion_are_one_line(capsys, monkeypatch, error, words):
    from bearinglab import stand

    def boom(*a, **k):
        raise error()

    monkeypatch.setattr(stand, "stand_analysis", boom)
    line = one_line_error(*run(capsys, "axial-angle", "-b", "4-1006095", "-F", "2 kgf")[::2])
    assert words in line and "Traceback" not in line


# ----------------------------------------------------------------------------- item 7: inputs untouched
def test_runout_csv_onto_its_error_file_is_refused(tmp_path, capsys):
    errors = tmp_path / "ex1.csv"  # an error file may have any name; --csv needs .csv
    errors.write_bytes(ERRORS_EXAMPLE.read_bytes())
    before = errors.read_bytes()
    line = one_line_error(*run(capsys, "runout", "--errors", errors, "--revolutions", "1", "--csv", errors)[::2])
    assert "is an input file of this command" in line
    assert errors.read_bytes() == before
    # the same file under another name: a symbolic link, and a path with '..'
    link = tmp_path / "link.csv"
    link.symlink_to(errors)
    for other in (link, tmp_path / "sub" / ".." / "ex1.csv"):
        (tmp_path / "sub").mkdir(exist_ok=True)
        line = one_line_error(*run(capsys, "runout", "--errors", errors, "--revolutions", "1", "--csv", other)[::2])
        assert "is an input file of this command" in line
    assert errors.read_bytes() == before


def test_the_issue_example_keeps_the_error_file(tmp_path, capsys):
    errors = tmp_path / "ex1.toml"
    errors.write_bytes(ERRORS_EXAMPLE.read_bytes())
    line = one_line_error(*run(capsys, "runout", "--errors", errors, "--revolutions", "1", "--csv", errors)[::2])
    assert "must end in .csv" in line
    assert errors.read_bytes() == ERRORS_EXAMPLE.read_bytes()


@pytest.mark.parametrize("option", ["--csv", "--plot"])
def test_high_speed_output_onto_its_bearing_file(tmp_path, capsys, option):
    bearing = tmp_path / ("b.csv" if option == "--csv" else "b.png")
    bearing.write_text('[bearings."X"]\nballs = 9\nball_diameter = "7.938 mm"\npitch_diameter = "38.5 mm"\n'
                       'inner_conformity = 0.52\nouter_conformity = 0.53\ncontact_angle = "15 deg"\n',
                       encoding="utf-8")
    before = bearing.read_bytes()
    line = one_line_error(*run(capsys, "high-speed", "--bearing-file", bearing, "-F", "1kN,2kN", "-n", "3000 rpm",
                               option, bearing)[::2])
    assert "is an input file of this command" in line and bearing.read_bytes() == before


def test_catalog_of_the_environment_is_an_input(tmp_path, capsys, monkeypatch):
    catalog = tmp_path / "cat.csv"
    catalog.write_text('[bearings."X"]\nballs = 9\nball_diameter = "7.938 mm"\npitch_diameter = "38.5 mm"\n'
                       'inner_conformity = 0.52\nouter_conformity = 0.53\ncontact_angle = "15 deg"\n',
                       encoding="utf-8")
    monkeypatch.setenv("BEARINGLAB_CATALOG", str(catalog))
    line = one_line_error(*run(capsys, "frequencies", "-b", "X", "-n", "3000 rpm", "--csv", catalog)[::2])
    assert "is an input file of this command" in line


def test_sweep_output_onto_its_own_file(tmp_path, capsys):
    path = tmp_path / "s.csv"
    path.write_text('model = "axial-angle"\nbearing = "4-1006095"\n[parameters]\naxial_load = "1 kgf"\n',
                    encoding="utf-8")
    line = one_line_error(*run(capsys, "sweep", path, "--out", path)[::2])
    assert "is an input file of this command" in line


@pytest.mark.parametrize(
    "args",
    [["high-speed", "-b", "B218", "-F", "1 kN", "-n", "3000 rpm", "--csv"],
     ["frequencies", "-b", "B218", "-n", "3000 rpm", "--csv"],
     ["runout", "--errors", ERRORS_EXAMPLE, "--revolutions", "1", "--csv"],
     ["runout", "monte-carlo", "-b", "B218", "--samples", "2", "--samples-csv"]],
)
@pytest.mark.parametrize("name", ["out.txt", "out", "out.toml"])
def test_csv_options_need_the_csv_suffix(tmp_path, capsys, args, name):
    line = one_line_error(*run(capsys, *args, tmp_path / name)[::2])
    assert "must end in .csv" in line
    assert not (tmp_path / name).exists()


def test_worst_dir_must_exist_and_is_not_created(tmp_path, capsys):
    target = tmp_path / "worst"
    line = one_line_error(*run(capsys, "runout", "monte-carlo", "-b", "B218", "--samples", "2",
                               "--write-worst", "1", "--worst-dir", target)[::2])
    assert f"worst-dir: directory '{target}' does not exist (it is never created" in line
    assert not target.exists()
    target.write_text("x", encoding="utf-8")
    line = one_line_error(*run(capsys, "runout", "monte-carlo", "-b", "B218", "--samples", "2",
                               "--write-worst", "1", "--worst-dir", target)[::2])
    assert "worst-dir" in line and "is a file; give a directory" in line
    target.unlink()
    target.mkdir()
    code, _out, err = run(capsys, "runout", "monte-carlo", "-b", "B218", "--samples", "2", "--steps-per-rev", "8",
                         "--revolutions", "1", "--max-order", "2", "--write-worst", "1", "--worst-dir", target,
                         "--json")
    assert code == 0, err
    assert len(list(target.glob("sample_*.toml"))) == 1


def test_disk_full_names_the_file(tmp_path, monkeypatch):
    target = tmp_path / "out.csv"

    def full(self, *a, **k):
        raise OSError(errno.ENOSPC, "No space left on device")  # as write() raises it: no file name

    monkeypatch.setattr(Path, "write_text", full)
    with pytest.raises(OSError) as info:
        _io.write_text(target, "a,b\n")
    assert info.value.errno == errno.ENOSPC and info.value.filename == str(target)
    assert list(tmp_path.iterdir()) == []  # no temporary file left


def test_disk_full_on_the_command_line_names_the_file(tmp_path, capsys, monkeypatch):
    def full(self, *a, **k):
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(Path, "write_text", full)
    target = tmp_path / "map.csv"
    line = one_line_error(*run(capsys, "high-speed", "-b", "B218", "-F", "1 kN", "-n", "3000 rpm",
                               "--csv", target)[::2])
    assert line == f"bearinglab: error: {target}: No space left on device"
    assert list(tmp_path.iterdir()) == []


@pytest.mark.skipif(not hasattr(signal, "SIGHUP"), reason="POSIX signals")
@pytest.mark.parametrize("name", ["SIGTERM", "SIGHUP"])
def test_signal_removes_the_temporary_file(tmp_path, name):
    # a child process starts an atomic write, writes half of it and is killed by the signal
    script = textwrap.dedent(f"""
        import os, signal, sys
        from bearinglab import _io
        with _io.atomic_output(sys.argv[1]) as tmp:
            tmp.write_text("half of it", encoding="utf-8")
            print(tmp, flush=True)
            os.kill(os.getpid(), signal.{name})
            raise SystemExit("not killed")
    """)
    env = dict(os.environ, PYTHONPATH=str(ROOT / "src"))
    p = subprocess.run([sys.executable, "-c", script, str(tmp_path / "out.csv")], check=False, capture_output=True,
                       text=True, env=env, timeout=60)
    assert p.returncode == -getattr(signal, name), p.stderr
    assert Path(p.stdout.strip()).parent == tmp_path  # it did write a temporary file there
    assert list(tmp_path.iterdir()) == []  # and the signal removed it


# ----------------------------------------------------------------------------- item 9: executor
class _Garbage:
    """A TCP server on 127.0.0.1 that answers every connection with ``reply`` and closes; bounded in time."""

    def __init__(self, reply):
        self.reply = reply
        self.sock = socket.create_server(("127.0.0.1", 0))
        self.sock.settimeout(20)
        self.address = f"tcp://127.0.0.1:{self.sock.getsockname()[1]}"
        self.thread = threading.Thread(target=self._serve, daemon=True)
        self.thread.start()

    def _serve(self):
        try:
            while True:
                conn, _ = self.sock.accept()
                with conn:
                    if self.reply is not None:
                        conn.sendall(self.reply)
                        conn.settimeout(2)
                        try:
                            conn.recv(1024)
                        except OSError:
                            pass
                    else:
                        conn.settimeout(3)  # says nothing
                        try:
                            conn.recv(1024)
                        except OSError:
                            pass
        except OSError:
            return

    def close(self):
        self.sock.close()


GARBAGE = {
    "http": b"HTTP/1.0 400 Bad Request\r\nContent-Length: 0\r\n\r\n",  # reads as a length of ~3 EiB
    "huge-length": (2**62).to_bytes(8, "little") + b"\x00" * 8,
    "short": b"\x01\x02",
    "frames": (64).to_bytes(8, "little") + (10**6).to_bytes(8, "little") + b"\x00" * 56,
}


@pytest.mark.parametrize("kind", sorted(GARBAGE))
def test_garbage_server_is_not_a_dask_scheduler(capsys, kind):
    server = _Garbage(GARBAGE[kind])
    try:
        with pytest.raises(InputError, match=r"answers but is not a dask scheduler"):
            parallel.probe_scheduler(server.address, timeout=5)
        line = one_line_error(*run(capsys, "high-speed", "-b", "B218", "-F", "5kN,20kN", "-n", "0, 10000rpm",
                                   "--executor", server.address)[::2])
        assert f"executor: '{server.address}' answers but is not a dask scheduler" in line
    finally:
        server.close()


def test_silent_server_times_out_as_not_a_scheduler():
    server = _Garbage(None)
    try:
        with pytest.raises(InputError, match=r"is not a dask scheduler \(no handshake within 1 s\)"):
            parallel.probe_scheduler(server.address, timeout=1)
    finally:
        server.close()


def test_nothing_listening_is_cannot_reach():
    s = socket.create_server(("127.0.0.1", 0))
    port = s.getsockname()[1]
    s.close()
    with pytest.raises(InputError, match=r"cannot reach a dask scheduler at 'tcp://127.0.0.1:\d+' within 2 s"):
        parallel.probe_scheduler(f"tcp://127.0.0.1:{port}", timeout=2)


def test_a_dask_handshake_passes_the_probe():
    # the first message of a dask scheduler (distributed 2026.8, read off a running one): length, one
    # frame of 42 bytes, the msgpack map {compression: None, python: (3, 11, 7), pickle-protocol: 5}
    frame = b"\x83\xabcompression\xc0\xa6python\x93\x03\x0b\x07\xafpickle-protocol\x05"
    body = (1).to_bytes(8, "little") + len(frame).to_bytes(8, "little") + frame
    server = _Garbage(len(body).to_bytes(8, "little") + body)
    try:
        parallel.probe_scheduler(server.address, timeout=5)
    finally:
        server.close()


def test_a_running_scheduler_passes_the_probe():
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=0, processes=False, protocol="tcp", host="127.0.0.1",
                                  dashboard_address=None) as cluster:
        assert cluster.scheduler_address.startswith("tcp://127.0.0.1:")
        parallel.probe_scheduler(cluster.scheduler_address, timeout=10)


@pytest.mark.parametrize("address, local", [("serial", True), ("local", True), ("tcp://127.0.0.1:8786", True),
                                            ("tcp://localhost:8786", True), ("tcp://[::1]:8786", True),
                                            ("tcp://10.0.0.5:8786", False), ("tcp://lab-cluster:8786", False),
                                            ("tls://scheduler.example.org:8786", False)])
def test_local_addresses(address, local):
    assert parallel.is_local_address(address) is local


def _remote_sweep(tmp_path):
    text = SWEEP_EXAMPLE.read_text(encoding="utf-8").replace('file = "stand_geometry_variants.csv"',
                                                             'file = "out.csv"')
    path = tmp_path / "remote.toml"
    path.write_text(text + '\n[execution]\nexecutor = "tcp://192.0.2.1:8786"\n', encoding="utf-8")
    return path


def test_sweep_file_with_a_remote_scheduler_needs_confirmation(tmp_path, capsys, monkeypatch):
    monkeypatch.setattr(parallel, "probe_scheduler", _never)  # refused before any connection
    path = _remote_sweep(tmp_path)
    line = one_line_error(*run(capsys, "sweep", path)[::2])
    assert "the sweep file names the scheduler 'tcp://192.0.2.1:8786', not on this machine" in line
    assert "--allow-remote-executor" in line
    spec = sweep_module.load_sweep(path)
    with pytest.raises(InputError, match="allow_remote_executor=True"):
        sweep_module.run_sweep(spec)
    # the command line's own --executor needs no confirmation: it is the user's
    code, _out, err = run(capsys, "sweep", path, "--executor", "serial", "--json")
    assert code == 0, err


def test_confirmed_remote_scheduler_is_probed(tmp_path, capsys, monkeypatch):
    probed = []

    def probe(address, timeout=10.0):
        probed.append(address)
        raise InputError(f"executor: {address!r} answers but is not a dask scheduler (test)")

    monkeypatch.setattr(parallel, "probe_scheduler", probe)
    line = one_line_error(*run(capsys, "sweep", _remote_sweep(tmp_path), "--allow-remote-executor")[::2])
    assert probed == ["tcp://192.0.2.1:8786"] and "is not a dask scheduler" in line


def test_runout_csv_onto_a_measured_profile_the_error_file_names(tmp_path, capsys):
    source = ROOT / "examples" / "runout"
    for name in ("measured_profile.toml", "inner_roundness.csv"):
        (tmp_path / name).write_bytes((source / name).read_bytes())
    profile = tmp_path / "inner_roundness.csv"
    before = profile.read_bytes()
    line = one_line_error(*run(capsys, "runout", "--errors", tmp_path / "measured_profile.toml", "--revolutions", "1",
                               "--steps-per-rev", "8", "--csv", profile)[::2])
    assert "is an input file of this command" in line and profile.read_bytes() == before
    from bearinglab.runout import files

    assert files.profile_files(tmp_path / "measured_profile.toml") == [profile]
    assert files.profile_files(ERRORS_EXAMPLE) == []


def test_friction_template_does_not_replace_the_user_catalog(tmp_path, capsys, monkeypatch):
    catalog = tmp_path / "cat.toml"
    catalog.write_text('[bearings."X"]\nballs = 9\n', encoding="utf-8")
    monkeypatch.setenv("BEARINGLAB_CATALOG", str(catalog))
    line = one_line_error(*run(capsys, "friction", "template", catalog, "--force")[::2])
    assert "is an input file of this command" in line
    assert catalog.read_text(encoding="utf-8") == '[bearings."X"]\nballs = 9\n'


def test_ball_count_of_a_catalog_file_is_bounded(tmp_path, capsys):
    path = tmp_path / "cat.toml"
    path.write_text('[bearings."X"]\nballs = 1000000000\n', encoding="utf-8")
    line = one_line_error(*run(capsys, "catalog", "list", "--catalog", path)[::2])
    assert "field 'balls': must be <= 1000 (bearinglab's size limit), got 1000000000" in line


def test_an_output_that_is_a_device_or_pipe_is_refused(tmp_path, capsys):
    # /dev/null as --csv would be replaced by the atomic rename when run as root: a FIFO stands in for it
    fifo = tmp_path / "null.csv"
    os.mkfifo(fifo)
    line = one_line_error(*run(capsys, "high-speed", "-b", "B218", "-F", "1 kN", "-n", "3000 rpm", "--csv", fifo)[::2])
    assert "is not a regular file" in line
    with pytest.raises(InputError, match=r"null.csv: not a regular file"):
        _io.write_text(fifo, "a\n")
    assert fifo.is_fifo() and sorted(p.name for p in tmp_path.iterdir()) == ["null.csv"]
