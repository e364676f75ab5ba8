"""The execution layer: chunking, executors, seeds, failures, scheduler errors."""

import time

import numpy as np
import pytest

from bearinglab import parallel
from bearinglab.errors import InputError


def square_or_flag(x):
    # a per-case failure is a flag, not an exception: the other cases complete
    ok = x != 3.0
    return {"y": np.where(ok, x**2, np.nan), "ok": ok}


def draw(n, rng, scale=1.0):
    return {"u": scale * rng.normal(size=n), "v": rng.integers(0, 1000, size=n)}


def test_chunk_bounds_cover_all_cases_once():
    for n in (0, 1, 7, 100):
        for size in (1, 3, 100, 1000):
            b = parallel.chunk_bounds(n, size)
            covered = np.concatenate([np.arange(a, z) for a, z in b]) if b else np.array([], int)
            assert np.array_equal(covered, np.arange(n))
            assert all(z - a <= size for a, z in b)


@pytest.mark.parametrize("size", [0, -1, 2.5, True])
def test_bad_chunk_size(size):
    with pytest.raises(InputError, match="chunk_size must be an integer >= 1"):
        parallel.chunk_bounds(10, size)


def test_run_cases_concatenates_in_order_and_flags_failures():
    x = np.arange(10.0)
    out = parallel.run_cases(square_or_flag, {"x": x}, chunk_size=3)
    assert np.array_equal(out["ok"], x != 3.0)
    assert np.array_equal(out["y"][out["ok"]], x[x != 3.0] ** 2)
    assert np.isnan(out["y"][3])


def test_run_cases_progress_callback_reaches_total():
    seen = []
    parallel.run_cases(square_or_flag, {"x": np.arange(10.0)}, chunk_size=4, progress=lambda d, t: seen.append((d, t)))
    assert seen == [(4, 10), (8, 10), (10, 10)]


def test_run_cases_rejects_ragged_inputs_and_bad_executor():
    with pytest.raises(InputError, match="same length"):
        parallel.run_cases(square_or_flag, {"x": np.arange(3.0), "z": np.arange(4.0)})
    with pytest.raises(InputError, match="executor must be 'serial', 'local' or a scheduler address"):
        parallel.run_cases(square_or_flag, {"x": np.arange(3.0)}, executor="cloud")


@pytest.mark.parametrize("chunk", [1, 100, 256, 1000, 5000])
def test_seeded_result_does_not_depend_on_chunking(chunk):
    ref = parallel.run_seeded(draw, 3000, 42, chunk_size=3000, constants={"scale": 2.0})
    got = parallel.run_seeded(draw, 3000, 42, chunk_size=chunk, constants={"scale": 2.0})
    assert np.array_equal(ref["u"], got["u"]) and np.array_equal(ref["v"], got["v"])
    other = parallel.run_seeded(draw, 3000, 43, chunk_size=chunk, constants={"scale": 2.0})
    assert not np.array_equal(ref["u"], other["u"])


def test_local_cluster_threads_is_bit_identical_to_serial():
    x = np.linspace(0.0, 9.0, 1001)
    serial = parallel.run_cases(square_or_flag, {"x": x}, chunk_size=50)
    local = parallel.run_cases(square_or_flag, {"x": x}, chunk_size=50, executor="local", workers=2, processes=False)
    for k in serial:
        assert np.array_equal(serial[k], local[k], equal_nan=True)
    a = parallel.run_seeded(draw, 2000, 5, chunk_size=512)
    b = parallel.run_seeded(draw, 2000, 5, chunk_size=300, executor="local", workers=2, processes=False)
    assert np.array_equal(a["u"], b["u"])


def test_dask_progress_bar_keeps_stdout_clean(capsys):
    # stdout of a command is one table or one JSON document; dask's text bar goes to stderr
    out = parallel.run_cases(square_or_flag, {"x": np.arange(10.0)}, chunk_size=4, executor="local", workers=1,
                             processes=False, progress="dask")
    assert out["ok"].sum() == 9
    assert capsys.readouterr().out == ""


def test_bad_scheduler_address_fails_fast_with_clear_error():
    t = time.perf_counter()
    with pytest.raises(InputError, match=r"cannot reach a dask scheduler at 'tcp://127.0.0.1:9' within 1 s"):
        parallel.run_cases(square_or_flag, {"x": np.arange(3.0)}, executor="tcp://127.0.0.1:9", timeout=1.0)
    assert time.perf_counter() - t < 10.0


def die_once(x, marker):
    """Kill the worker process the first time the chunk holding case 5 runs (a crash, not an exception)."""
    import os
    from pathlib import Path

    if 5.0 in x and not Path(marker).exists():
        Path(marker).write_text("died")
        os._exit(1)
    return {"y": x * 10.0, "pid": np.full(x.shape, os.getpid())}


def test_a_worker_that_dies_is_replaced_and_no_case_is_lost_or_duplicated(tmp_path):
    x = np.arange(12.0)
    out = parallel.run_cases(die_once, {"x": x}, constants={"marker": str(tmp_path / "died")}, chunk_size=3,
                             executor="local", workers=2, processes=True)
    assert (tmp_path / "died").exists()  # the crash happened
    assert np.array_equal(out["y"], x * 10.0)  # every case once, in order
