"""Scaling benchmark (issues 6 and 31): a 10^5-bearing runout Monte Carlo on a local dask cluster, 1 and 2
workers, 360 positions (180 steps x 2 revolutions) per bearing.

Reports the samples/s on 2 workers (issue 31's goal: >= 2000), the parallel efficiency T1 / (2 T2) (issue
6's goal: >= 0.8 on the 2-core machine), the time of one chunk and the scheduler's overhead per task, and
from them an estimate of the wall time of 10^7 bearings on a 64-worker cluster. The clusters are started
before the clock runs (a running cluster is what a user with a scheduler has), and the kernels are loaded in
every worker by a warm-up study first (a user's workers load them once); the samples are identical on
every run (per-sample seeds), which is checked. The machine is shared: the 1-minute load average is taken
at the start and at the end of each study, and the run writes the goal's row of BENCHMARKS.md ("Where the
goals stand") with it (written whole: a temporary file, then a rename).

Usage: python bench/scaling.py [N_SAMPLES]
"""

from __future__ import annotations

import datetime as _dt
import logging
import math
import os
import sys
import time
from pathlib import Path

# the workers are processes started by this one: keep their shutdown chatter (heartbeats to a closed
# scheduler) off the report
os.environ.setdefault("DASK_LOGGING__DISTRIBUTED", "critical")

import numpy as np

from bearinglab import runout

N_SAMPLES = int(sys.argv[1]) if len(sys.argv) > 1 else 100_000
CHUNK = 1000  # samples per task
SEED = 2026
TARGET_SAMPLES, TARGET_WORKERS = 10_000_000, 64
GOAL = 2000.0  # samples/s on 2 workers (issue 31)
GOAL_ROW = "| runout Monte Carlo >= 2000 samples/s on 2 workers, 360 positions each (31) |"
BENCH_MD = Path(__file__).resolve().parent.parent / "BENCHMARKS.md"


def _noop(x):
    return x


def study(geometry, executor, n=N_SAMPLES):
    t = time.perf_counter()
    r = runout.monte_carlo(geometry, "G5", "P4", n, SEED, chunk_size=CHUNK, executor=executor)
    return time.perf_counter() - t, r


def goal_row(rate, rate_1, efficiency, loads, n, stamp):
    """The goal's row of the table "Where the goals stand"."""
    met = "yes" if rate >= GOAL else "no"
    return (f"{GOAL_ROW} {rate:.4g} samples/s on 2 workers (1 worker: {rate_1:.4g}; efficiency "
            f"{efficiency:.2f}), {n} samples, `bench/scaling.py` of {stamp}; load average (1 min) "
            f"{loads[0]:.2f} at the start and {loads[1]:.2f} at the end of the 2-worker study on the shared "
            f"2 cores | {met} |")


def write_goal_row(row, path=BENCH_MD):
    """Replace the goal's row in BENCHMARKS.md, or add it at the end of the goals table."""
    lines = path.read_text().splitlines()
    at = next((i for i, x in enumerate(lines) if x.startswith(GOAL_ROW)), None)
    if at is None:
        head = next(i for i, x in enumerate(lines) if x.startswith("## Where the goals stand"))
        table = next(i for i in range(head, len(lines)) if lines[i].startswith("| goal"))
        at = next((i for i in range(table, len(lines)) if not lines[i].startswith("|")), len(lines))
        lines.insert(at, row)
    else:
        lines[at] = row
    tmp = path.with_suffix(".md.tmp")
    tmp.write_text("\n".join(lines) + "\n")
    os.replace(tmp, path)


def main():
    from distributed import Client, LocalCluster

    g = runout.geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(15))
    runout.monte_carlo_chunk(g, "G5", "P4", np.arange(4), SEED)  # loads the kernels in this process
    t = time.perf_counter()  # one chunk, in this process: the unit of work of a task
    runout.monte_carlo_chunk(g, "G5", "P4", np.arange(CHUNK), SEED)
    t_chunk = time.perf_counter() - t

    times, results, loads, overhead = {}, {}, {}, None
    for workers in (1, 2):
        with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None,
                          silence_logs=logging.ERROR) as cluster, Client(cluster) as client:
            client.submit(_noop, 0).result()  # workers up and warm
            study(g, cluster.scheduler_address, n=2 * CHUNK * workers)  # every worker loads the kernels
            start_load = os.getloadavg()[0]
            times[workers], results[workers] = study(g, cluster.scheduler_address)
            loads[workers] = (start_load, os.getloadavg()[0])
            if workers == 2:  # scheduler overhead: many trivial tasks through the same path
                n_tasks = 4000
                t = time.perf_counter()
                client.gather(client.map(_noop, range(n_tasks), pure=False))
                overhead = (time.perf_counter() - t) / n_tasks
        print(f"{workers} worker(s): {N_SAMPLES} bearings in {times[workers]:8.2f} s = "
              f"{N_SAMPLES / times[workers]:9.1f} bearings/s (load average {loads[workers][0]:.2f} at the start, "
              f"{loads[workers][1]:.2f} at the end)", flush=True)
    same = all(np.array_equal(getattr(results[1].samples, k), getattr(results[2].samples, k))
               for k in results[1].samples._fields)
    speedup = times[1] / times[2]
    efficiency = speedup / 2
    rate, rate_1 = N_SAMPLES / times[2], N_SAMPLES / times[1]
    n_tasks = math.ceil(TARGET_SAMPLES / CHUNK)
    compute = n_tasks * t_chunk / TARGET_WORKERS
    scheduling = n_tasks * overhead  # the scheduler hands out tasks one after another
    estimate = max(compute, scheduling) + min(compute, scheduling) / TARGET_WORKERS
    print(f"speed-up 1 -> 2 workers: {speedup:.3f}, parallel efficiency {efficiency:.3f} (goal >= 0.8)")
    print(f"2 workers: {rate:.4g} samples/s (goal >= {GOAL:g}: {'met' if rate >= GOAL else 'not met'})")
    print(f"identical samples on 1 and 2 workers: {same}")
    print(f"one chunk of {CHUNK} bearings (360 positions each): {t_chunk:.3f} s; scheduler overhead per task: "
          f"{overhead * 1e3:.3f} ms")
    print(f"estimate for {TARGET_SAMPLES:.0e} bearings on {TARGET_WORKERS} workers (chunks of {CHUNK}, {n_tasks} tasks): "
          f"compute {compute:.0f} s per worker, scheduling {scheduling:.1f} s -> about {estimate / 60:.1f} min "
          f"(workers as fast as one core here)")
    print(f"RESULT runout_mc_scaling cases_per_s={rate:.4g} baseline_cases_per_s={rate_1:.4g} "
          f"ratio={speedup:.4g} efficiency={efficiency:.3f} chunk_s={t_chunk:.3g} task_overhead_ms={overhead * 1e3:.3g} "
          f"estimate_1e7_64w_min={estimate / 60:.3g} load_avg_1min_start={loads[2][0]:.2f} "
          f"load_avg_1min_end={loads[2][1]:.2f} goal_samples_per_s={GOAL:g} "
          f"goal_met={'yes' if rate >= GOAL else 'no'} batched_label=2_workers baseline_label=1_worker")
    if same:
        stamp = _dt.datetime.now(_dt.UTC).strftime("%Y-%m-%d %H:%M UTC")
        write_goal_row(goal_row(rate, rate_1, efficiency, loads[2], N_SAMPLES, stamp))
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
