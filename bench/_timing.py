"""Shared by the benchmark scripts (run as ``python bench/NAME.py``, so this directory is on sys.path)."""

import time


def best_of(fn, repeat):
    """(shortest wall time of ``repeat`` calls of fn [s], the result of the last call)."""
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - start)
    return min(times), out


def best_of_wall_and_cpu(fn, repeat):
    """(shortest wall time [s], the CPU time of the process in that call [s], the last result).

    The CPU time sums all threads: on a machine shared with other work it shows what the code costs when
    the wall time shows what it got.
    """
    best = (float("inf"), float("inf"))
    out = None
    for _ in range(repeat):
        wall, cpu = time.perf_counter(), time.process_time()
        out = fn()
        wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
        best = min(best, (wall, cpu))
    return best[0], best[1], out
