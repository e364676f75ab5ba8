"""Smoke test of the web load benchmark (bench/web_load.py): it runs and prints well-formed figures.

``--smoke`` runs every path of the script (the server in its own process, light requests, light ones
alone and beside 4 heavy maps and their ratio, mixed requests and the memory) on a few requests and a 15-case map with one worker
per pool, so that the benchmark cannot rot; the figures themselves are measured by ``make bench`` and
written in BENCHMARKS.md.
"""

import os
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
NUMBER = r"(\d+(?:\.\d+)?)"


def test_the_web_load_benchmark_prints_its_figures():
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(
        [str(ROOT / "src"), *filter(None, [os.environ.get("PYTHONPATH")])]))
    run = subprocess.run([sys.executable, str(ROOT / "bench" / "web_load.py"), "--smoke"], env=env,
                         capture_output=True, text=True, timeout=600, cwd=ROOT, check=False)
    assert run.returncode == 0, run.stderr[-2000:]
    out = run.stdout
    assert re.search(r"^machine: \d+ CPUs, load average [\d.]+ [\d.]+ [\d.]+$", out, re.MULTILINE), out
    light = re.search(rf"^RESULT web_light rate={NUMBER}/s n=20 concurrency=8 p50={NUMBER}ms "
                      rf"p99={NUMBER}ms$", out, re.MULTILINE)
    assert light, out
    rate, p50, p99 = map(float, light.groups())
    assert rate > 0 and 0 < p50 <= p99
    alone = re.search(rf"^RESULT web_light_alone n=3 p50={NUMBER}ms p99={NUMBER}ms max={NUMBER}ms$", out,
                      re.MULTILINE)
    assert alone, out
    assert 0 < float(alone.group(1)) <= float(alone.group(2)) <= float(alone.group(3))
    ratio = re.search(rf"^RESULT web_light_beside_ratio p99={NUMBER} p50={NUMBER} \(goal: p99 <= 2; load "
                      rf"average during the run {NUMBER} {NUMBER} {NUMBER}\)$", out, re.MULTILINE)
    assert ratio, out
    assert float(ratio.group(1)) > 0 and float(ratio.group(2)) > 0
    beside = re.search(rf"^RESULT web_light_beside_4_heavy n=3 p50={NUMBER}ms p99={NUMBER}ms "
                       rf"max={NUMBER}ms \(heavy: 15 cases each, [0-4] still running after the light "
                       r"ones, status \[(.*)\]\)$", out, re.MULTILINE)
    assert beside, out
    p50, p99, largest = map(float, beside.groups()[:3])
    assert 0 < p50 <= p99 <= largest
    assert beside.group(4) == "200, 200, 200, 200"  # the 15-case maps are answered
    memory = re.search(rf"^RESULT web_memory after={NUMBER}MB start={NUMBER}MB mixed=14 "
                       r"statuses=\{(.*)\}$", out, re.MULTILINE)
    assert memory, out
    after, start = map(float, memory.groups()[:2])
    assert after > 0 and start > 0
    statuses = dict(map(int, pair.split(": ")) for pair in memory.group(3).split(", "))
    assert sum(statuses.values()) == 14 and 500 not in statuses
    assert statuses.get(422) == 2  # the mix holds one malformed load, sent twice in 14 requests
