"""Scaling benchmark (issue 6): a 10^5-bearing runout Monte Carlo on a local dask cluster, 1 and 2 workers.

Reports the parallel efficiency T1 / (2 T2) (goal >= 0.8 on the 2-core machine), the time of one chunk
and the scheduler's overhead per task, and from them an estimate of the wall time of 10^7 bearings on a
64-worker cluster. The clusters are started before the clock runs (a running cluster is what a user with
a scheduler has); the samples are identical on every run (per-sample seeds), which is checked.

Usage: python bench/scaling.py [N_SAMPLES]
"""

from __future__ import annotations

import logging
import math
import os
import sys
import time

# the workers are processes started by this one: keep their shutdown chatter (heartbeats to a closed
# scheduler) off the report
os.environ.setdefault("DASK_LOGGING__DISTRIBUTED", "critical")

import numpy as np

from bearinglab import runout

N_SAMPLES = int(sys.argv[1]) if len(sys.argv) > 1 else 100_000
CHUNK = 1000  # samples per task
SEED = 2026
TARGET_SAMPLES, TARGET_WORKERS = 10_000_000, 64


def _noop(x):
    return x


def study(geometry, executor):
    t = time.perf_counter()
    r = runout.monte_carlo(geometry, "G5", "P4", N_SAMPLES, SEED, chunk_size=CHUNK, executor=executor)
    return time.perf_counter() - t, r


def main():
    from distributed import Client, LocalCluster

    g = runout.geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(15))
    t = time.perf_counter()  # one chunk, in this process: the unit of work of a task
    runout.monte_carlo_chunk(g, "G5", "P4", np.arange(CHUNK), SEED)
    t_chunk = time.perf_counter() - t

    times, results, overhead = {}, {}, None
    for workers in (1, 2):
        with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None,
                          silence_logs=logging.ERROR) as cluster, Client(cluster) as client:
            client.submit(_noop, 0).result()  # workers up and warm
            times[workers], results[workers] = study(g, cluster.scheduler_address)
            if workers == 2:  # scheduler overhead: many trivial tasks through the same path
                n_tasks = 4000
                t = time.perf_counter()
                client.gather(client.map(_noop, range(n_tasks), pure=False))
                overhead = (time.perf_counter() - t) / n_tasks
        print(f"{workers} worker(s): {N_SAMPLES} bearings in {times[workers]:8.2f} s = "
              f"{N_SAMPLES / times[workers]:9.1f} bearings/s", flush=True)
    same = all(np.array_equal(getattr(results[1].samples, k), getattr(results[2].samples, k))
               for k in results[1].samples._fields)
    speedup = times[1] / times[2]
    efficiency = speedup / 2
    n_tasks = math.ceil(TARGET_SAMPLES / CHUNK)
    compute = n_tasks * t_chunk / TARGET_WORKERS
    scheduling = n_tasks * overhead  # the scheduler hands out tasks one after another
    estimate = max(compute, scheduling) + min(compute, scheduling) / TARGET_WORKERS
    print(f"speed-up 1 -> 2 workers: {speedup:.3f}, parallel efficiency {efficiency:.3f} (goal >= 0.8)")
    print(f"identical samples on 1 and 2 workers: {same}")
    print(f"one chunk of {CHUNK} bearings (360 positions each): {t_chunk:.3f} s; scheduler overhead per task: "
          f"{overhead * 1e3:.3f} ms")
    print(f"estimate for {TARGET_SAMPLES:.0e} bearings on {TARGET_WORKERS} workers (chunks of {CHUNK}, {n_tasks} tasks): "
          f"compute {compute:.0f} s per worker, scheduling {scheduling:.1f} s -> about {estimate / 60:.1f} min "
          f"(workers as fast as one core here)")
    print(f"RESULT runout_mc_scaling cases_per_s={N_SAMPLES / times[2]:.4g} baseline_cases_per_s={N_SAMPLES / times[1]:.4g} "
          f"ratio={speedup:.4g} efficiency={efficiency:.3f} chunk_s={t_chunk:.3g} task_overhead_ms={overhead * 1e3:.3g} "
          f"estimate_1e7_64w_min={estimate / 60:.3g} batched_label=2_workers baseline_label=1_worker")
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
