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
