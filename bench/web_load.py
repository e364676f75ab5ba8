"""Benchmark: the web calculator under load, on the loopback interface only (issue 22).

Starts ``uvicorn`` with :func:`bearinglab.web.create_app` on 127.0.0.1 and a free port in a child
process and measures, with a bounded number of requests and a bounded time:

1. light requests per second and their p50/p99 latency (``/api/frequencies`` of the 6205-2RS, one
   case) with ``CONCURRENCY`` clients;
2. the latency of light requests while 4 heavy ones run (high-speed maps of ``HEAVY_CASES`` cases;
   ``--big``: maps of 10^5 cases, as issue 29 measured them), against the same light requests sent the
   same way with no heavy one running; issue 29's goal is a p99 beside the heavy maps of at most twice
   the p99 alone (``RESULT web_light_beside_ratio``, with the machine's load during the run);
3. the server's memory (the server process with its forkserver and workers, resident set) after 1000
   mixed requests: light, lists, errors, catalog searches and a few heavy ones.

Run: ``PYTHONPATH=src python bench/web_load.py`` (``--quick`` for a short run, ``--big`` for the
10^5-case heavy maps; ``--light-only`` for
the first figure alone, e.g. against another version's server with its ``src`` on ``PYTHONPATH``;
``--smoke`` for a few requests and a small heavy map on one worker of each pool, which
``tests/web/test_web_load_smoke.py`` runs so that the script cannot rot). The machine's load is
printed with the figures: on a shared machine they are a lower bound.
"""

from __future__ import annotations

import asyncio
import os
import socket
import statistics
import subprocess
import sys
import time

import httpx

LIGHT = ("/api/frequencies", {"bearing": "6205-2RS", "speed": "1797 rpm"})
HEAVY_CASES = 20_000
HEAVY = ("/api/high-speed", {"bearing": "B218", "axial_load": "1kN:200kN:1kN", "speed": "100rpm:10000rpm:100rpm"})
#: ``--big``: the same map at 5 times the speeds, 10^5 cases (issue 29's heavy requests)
HEAVY_BIG = ("/api/high-speed", {"bearing": "B218", "axial_load": "1kN:200kN:1kN",
                                 "speed": "20rpm:10000rpm:20rpm"})
MIXED = [
    LIGHT,
    ("/api/life", {"bearing": "6205-2RS", "radial_load": "2 kN", "speed": "3000 rpm", "oil": "VG68",
                   "temperature": "70 degC"}),
    ("/api/high-speed", {"bearing": "B218", "axial_load": "20 kN", "speed": "10000 rpm"}),
    ("/api/friction", {"bearing": "101", "radial_load": "0N:50N:10N", "speed": "3000 rpm"}),
    ("/api/catalog/search", {"query": "62"}),
    ("/api/high-speed", {"bearing": "B218", "axial_load": "2,5 kN", "speed": "1 rpm"}),  # a 422
    ("/api/axial-angle", {"bearing": "4-1006095", "axial_load": "1kgf:5kgf:1kgf"}),
]
CONCURRENCY = 8
#: ``--smoke``: a heavy map of 15 cases, and (light, beside heavy, mixed, warm-up) request counts
SMOKE_HEAVY = ("/api/high-speed", {"bearing": "B218", "axial_load": "1kN:5kN:1kN",
                                   "speed": "1000rpm:3000rpm:1000rpm"})
SMOKE_COUNTS = (20, 3, 14, 5)


def _free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _start(port, workers=None):
    env = dict(os.environ)
    pools = f"light_workers={workers[0]}, heavy_workers={workers[1]}" if workers else ""
    code = ("import uvicorn\nfrom bearinglab.web import create_app\n"
            f"uvicorn.run(create_app({pools}), host='127.0.0.1', port={port}, log_level='warning')\n")
    proc = subprocess.Popen([sys.executable, "-c", code], env=env)
    url = f"http://127.0.0.1:{port}"
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline:
        try:
            if httpx.get(url + LIGHT[0], params=LIGHT[1], timeout=60).status_code == 200:
                return proc, url
        except httpx.HTTPError:
            time.sleep(0.2)
    proc.kill()
    raise RuntimeError("the server did not start")


def _rss_mb(pid):
    """Resident memory of a process and all its descendants [MB] (Linux /proc)."""
    def kids(p):
        out = []
        for task in os.listdir(f"/proc/{p}/task"):
            try:
                with open(f"/proc/{p}/task/{task}/children") as fh:
                    out += [int(c) for c in fh.read().split()]
            except OSError:
                pass
        return out

    total, stack = 0, [pid]
    while stack:
        p = stack.pop()
        try:
            with open(f"/proc/{p}/status") as fh:
                total += next(int(line.split()[1]) for line in fh if line.startswith("VmRSS:"))
            stack += kids(p)
        except (OSError, StopIteration):
            pass
    return total / 1024


async def _light_rate(url, n):
    latencies, statuses = [], []
    queue = asyncio.Queue()
    for _ in range(n):
        queue.put_nowait(LIGHT)

    async def client(c):
        while not queue.empty():
            path, params = queue.get_nowait()
            t = time.perf_counter()
            r = await c.get(url + path, params=params)
            latencies.append(time.perf_counter() - t)
            statuses.append(r.status_code)

    async with httpx.AsyncClient(timeout=60, limits=httpx.Limits(max_connections=CONCURRENCY)) as c:
        start = time.perf_counter()
        await asyncio.gather(*(client(c) for _ in range(CONCURRENCY)))
        took = time.perf_counter() - start
    return n / took, latencies, statuses


async def _light_sequence(c, url, n_light):
    """``n_light`` light requests one after the other, 50 ms apart: their latencies."""
    latencies = []
    for _ in range(n_light):
        t = time.perf_counter()
        r = await c.get(url + LIGHT[0], params=LIGHT[1])
        latencies.append(time.perf_counter() - t)
        assert r.status_code == 200
        await asyncio.sleep(0.05)
    return latencies


async def _light_alone(url, n_light):
    """The light requests of :func:`_light_beside_heavy`, sent the same way with no heavy one running."""
    async with httpx.AsyncClient(timeout=120) as c:
        return await _light_sequence(c, url, n_light)


#: the 4 heavy requests, sent by a child process: reading and decoding their large answers in the light
#: client's own event loop would delay its light requests and count the client's work as the server's
_HEAVY_CLIENT = """
import json, sys, threading, time
import httpx
url, path, params = sys.argv[1], sys.argv[2], json.loads(sys.argv[3])
def one():
    r = httpx.get(url + path, params=params, timeout=300)
    print(time.time(), r.status_code, flush=True)
threads = [threading.Thread(target=one) for _ in range(4)]
for t in threads:
    t.start()
for t in threads:
    t.join()
"""


async def _light_beside_heavy(url, n_light, heavy_request=HEAVY):
    import json

    heavy = await asyncio.create_subprocess_exec(sys.executable, "-c", _HEAVY_CLIENT, url, heavy_request[0],
                                                 json.dumps(heavy_request[1]), stdout=asyncio.subprocess.PIPE)
    try:
        async with httpx.AsyncClient(timeout=300) as c:
            await asyncio.sleep(1.0)
            latencies = await _light_sequence(c, url, n_light)
        load = os.getloadavg()  # the machine's load while the heavy maps and the light requests ran
        ended = time.time()
        out = (await asyncio.wait_for(heavy.communicate(), 600))[0].decode()
    finally:
        if heavy.returncode is None:
            heavy.kill()
    done = [line.split() for line in out.splitlines() if line.strip()]
    running = sum(float(t) > ended for t, _ in done)
    statuses = [int(s) for _, s in done]
    return latencies, running, statuses, load


async def _mixed(url, n):
    statuses = {}
    async with httpx.AsyncClient(timeout=120, limits=httpx.Limits(max_connections=CONCURRENCY)) as c:
        sem = asyncio.Semaphore(CONCURRENCY)

        async def one(i):
            path, params = MIXED[i % len(MIXED)]
            async with sem:
                r = await c.get(url + path, params=params)
            statuses[r.status_code] = statuses.get(r.status_code, 0) + 1

        await asyncio.gather(*(one(i) for i in range(n)))
    return statuses


def _pct(values, q):
    values = sorted(values)
    return values[min(len(values) - 1, round(q * (len(values) - 1)))]


def _cases(request):
    """The cases of a map request: the product of its ranges' lengths (start:stop:step, inclusive)."""
    count = 1
    for value in request[1].values():
        if value.count(":") == 2:
            start, stop, step = (float("".join(c for c in v if c in "0123456789.e-")) for v in value.split(":"))
            count *= round((stop - start) / step) + 1
    return count


def main(quick=False, light_only=False, smoke=False, big=False):
    n_light, n_beside, n_mixed, n_warm = (200, 10, 100, 100) if quick else (1500, 40, 1000, 100)
    heavy, workers = (HEAVY_BIG if big else HEAVY), None
    if smoke:  # the script's every path on a few requests (a test, not a measurement)
        (n_light, n_beside, n_mixed, n_warm), heavy, workers = SMOKE_COUNTS, SMOKE_HEAVY, (1, 1)
    port = _free_port()
    proc, url = _start(port, workers)
    try:
        load = os.getloadavg()
        print(f"machine: {os.cpu_count()} CPUs, load average {load[0]:.1f} {load[1]:.1f} {load[2]:.1f}")
        start_mb = _rss_mb(proc.pid)
        asyncio.run(_light_rate(url, n_warm))  # warm-up
        rate, lat, statuses = asyncio.run(_light_rate(url, n_light))
        assert set(statuses) == {200}, set(statuses)
        print(f"RESULT web_light rate={rate:.0f}/s n={n_light} concurrency={CONCURRENCY} "
              f"p50={_pct(lat, 0.5) * 1e3:.1f}ms p99={_pct(lat, 0.99) * 1e3:.1f}ms")
        if light_only:  # e.g. to compare with another version of the server under the same load
            return 0
        alone = asyncio.run(_light_alone(url, n_beside))
        print(f"RESULT web_light_alone n={n_beside} p50={statistics.median(alone) * 1e3:.1f}ms "
              f"p99={_pct(alone, 0.99) * 1e3:.1f}ms max={max(alone) * 1e3:.1f}ms")
        beside, running, heavy_status, load = asyncio.run(_light_beside_heavy(url, n_beside, heavy))
        print(f"RESULT web_light_beside_4_heavy n={n_beside} p50={statistics.median(beside) * 1e3:.1f}ms "
              f"p99={_pct(beside, 0.99) * 1e3:.1f}ms max={max(beside) * 1e3:.1f}ms "
              f"(heavy: {_cases(heavy)} cases each, {running} still running after the light ones, "
              f"status {heavy_status})")
        print(f"RESULT web_light_beside_ratio p99={_pct(beside, 0.99) / _pct(alone, 0.99):.2f} "
              f"p50={statistics.median(beside) / statistics.median(alone):.2f} (goal: p99 <= 2; load average "
              f"during the run {load[0]:.1f} {load[1]:.1f} {load[2]:.1f})")
        mixed = asyncio.run(_mixed(url, n_mixed))
        time.sleep(1.0)
        print(f"RESULT web_memory after={_rss_mb(proc.pid):.0f}MB start={start_mb:.0f}MB "
              f"mixed={n_mixed} statuses={dict(sorted(mixed.items()))}")
        assert 500 not in mixed
    finally:
        proc.terminate()
        proc.wait(10)
    return 0


if __name__ == "__main__":
    sys.exit(main(quick="--quick" in sys.argv, light_only="--light-only" in sys.argv,
                  smoke="--smoke" in sys.argv, big="--big" in sys.argv))
