"""The execution options checked before any cluster starts (issue 29): ``--memory-limit`` is a size with a
unit and a sane minimum, ``--workers`` is capped at the machine's cores unless the scheduler is remote.
Each finding of the issue, and variants of it, is one line on stderr and exit 2."""

import numpy as np
import pytest

from bearinglab import parallel, quasistatic, sweep
from bearinglab.cli import main
from bearinglab.errors import InputError
from bearinglab.parallel import Execution

SWEEP = 'model = "axial-angle"\nbearing = "4-1006095"\n[parameters]\naxial_load = "1 kgf, 2 kgf"\n'


@pytest.fixture
def sweep_file(tmp_path):
    path = tmp_path / "s.toml"
    path.write_text(SWEEP, encoding="utf-8")
    return path


@pytest.fixture
def no_cluster(monkeypatch):
    """Any attempt to start a local cluster fails the test: the checks come first."""
    distributed = pytest.importorskip("distributed")

    def refuse(*args, **kwargs):
        raise AssertionError("a LocalCluster was started before the options were checked")

    monkeypatch.setattr(distributed, "LocalCluster", refuse)


@pytest.fixture
def two_cores(monkeypatch):
    monkeypatch.setattr(parallel, "machine_cores", lambda: 2)


def _one_line_error(capsys, code, *words):
    err = capsys.readouterr().err
    assert code == 2, err
    assert err.count("\n") == 1 and err.startswith("bearinglab: error: "), err
    for word in words:
        assert word in err, (word, err)
    return err


# the findings (abc, -1GiB, 100MB: tracebacks; 1MB: a hang) and variants
@pytest.mark.parametrize("value", ["abc", "-1GiB", "100MB", "1MB", "0", "1e400 GB", "2 G", "4 GiBs", "1 kN",
                                   "511 MiB", "1 PB", "1.5.2 GB", "", "nan GB", "٥ GB", "1_000 MB"])
def test_bad_memory_limits_are_one_line_before_a_cluster_starts(sweep_file, capsys, no_cluster, value):
    code = main(["sweep", str(sweep_file), "--executor", "local", "--memory-limit", value])
    _one_line_error(capsys, code, "memory-limit", repr(value), "512 MiB ... ")


def test_a_memory_limit_above_the_machine_is_refused(sweep_file, capsys, no_cluster, monkeypatch):
    monkeypatch.setattr(parallel, "_machine_memory", lambda: 8 * 2**30)
    code = main(["sweep", str(sweep_file), "--executor", "local", "--memory-limit", "9 GiB"])
    _one_line_error(capsys, code, "memory-limit must be 512 MiB ... 8 GiB per worker", "'9 GiB'")


@pytest.mark.parametrize("value, size", [("512 MiB", 2**29), ("2 GB", 2 * 10**9), ("1.5GiB", 3 * 2**29),
                                         ("2gb", 2 * 10**9), ("1073741824", 2**30), (" 1 GiB ", 2**30),
                                         (2**30, 2**30), ("auto", None), (None, None)])
def test_memory_limits_with_a_unit_are_bytes(value, size):
    assert parallel.parse_memory_limit(value) == size
    assert Execution(executor="local", memory_limit=value).memory_limit == size


# the finding: --workers 256 started 127 processes on 2 cores
@pytest.mark.parametrize("workers", ["256", "3", "100"])
def test_workers_beyond_the_cores_are_refused(sweep_file, capsys, no_cluster, two_cores, workers):
    code = main(["sweep", str(sweep_file), "--executor", "local", "--workers", workers])
    _one_line_error(capsys, code, "workers must be 1 ... 2 [-]", f"got {workers}")


def test_other_batch_commands_cap_their_workers_too(capsys, no_cluster, two_cores):
    code = main(["high-speed", "-b", "B218", "-F", "1 kN,2 kN", "-n", "3000 rpm", "--executor", "local",
                 "--workers", "8"])
    _one_line_error(capsys, code, "workers must be 1 ... 2 [-]")
    code = main(["runout", "monte-carlo", "-b", "B218", "--samples", "4", "--executor", "local", "--workers", "3"])
    _one_line_error(capsys, code, "workers must be 1 ... 2 [-]")


def test_the_python_entry_points_check_before_a_cluster_starts(no_cluster, two_cores):
    from bearinglab import catalog

    b218 = catalog.get("B218")
    with pytest.raises(InputError, match="memory-limit must be 512 MiB"):
        quasistatic.sweep(b218, [5e3], [0.0], executor="local", memory_limit="1MB")
    with pytest.raises(InputError, match=r"workers must be 1 \.\.\. 2"):
        parallel.run_seeded(lambda n, rng: {"u": rng.random(n)}, 4, 0, executor="local", workers=256)
    with pytest.raises(InputError, match="memory-limit must be a size with a unit"), \
            parallel.executor_client("local", memory_limit="abc"):
        pass
    with pytest.raises(InputError, match=r"workers must be 1 \.\.\. 2"):
        Execution(executor="local", workers=5)


def test_a_file_that_asks_for_more_workers_than_cores_is_refused(tmp_path, no_cluster, two_cores):
    path = tmp_path / "s.toml"
    path.write_text(SWEEP + '[execution]\nexecutor = "local"\nworkers = 64\n', encoding="utf-8")
    with pytest.raises(InputError, match=r"workers must be 1 \.\.\. 2 \[-\].*got 64"):
        sweep.run_sweep(sweep.load_sweep(path))


def test_a_remote_scheduler_and_threads_are_not_capped(two_cores):
    # a scheduler's workers run where they were started; threads are no processes of this machine
    assert Execution(executor="tcp://10.0.0.5:8786", workers=64).workers == 64
    assert Execution(executor="local", workers=4, processes=False).workers == 4
    with pytest.raises(InputError, match=r"workers must be <= 256 \[-\]"):
        Execution(executor="tcp://10.0.0.5:8786", workers=1000)


def test_the_cores_are_those_this_process_may_use():
    import os

    n = parallel.machine_cores()
    assert 1 <= n <= (os.cpu_count() or n)
    if hasattr(os, "sched_getaffinity"):
        assert n == len(os.sched_getaffinity(0))


def test_a_checked_memory_limit_reaches_the_cluster():
    out = parallel.run_cases(lambda x: {"y": 2 * x}, {"x": np.arange(4.0)}, execution=Execution(
        executor="local", workers=1, processes=False, memory_limit="1 GiB", chunk_size=2))
    assert out["y"].tolist() == [0.0, 2.0, 4.0, 6.0]
