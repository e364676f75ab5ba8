"""Run every benchmark under bench/ and collect their RESULT lines into BENCHMARKS.md.

Each script ends its output with ``RESULT <name> cases_per_s=<x> baseline_cases_per_s=<y> ratio=<z>``;
the table between the ``results`` markers of BENCHMARKS.md is rewritten from this run (written whole:
a temporary file, then a rename).
"""

from __future__ import annotations

import datetime as _dt
import os
import platform
import re
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
BEGIN, END = "<!-- results:begin -->", "<!-- results:end -->"
PATTERN = re.compile(r"^RESULT (\S+) (.*)$")


def run(script):
    print(f"== {script.name}", flush=True)
    proc = subprocess.run([sys.executable, str(script)], check=False, cwd=ROOT, capture_output=True, text=True)
    sys.stdout.write(proc.stdout)
    sys.stderr.write(proc.stderr)
    results = []
    for line in proc.stdout.splitlines():
        m = PATTERN.match(line.strip())
        if m:
            # key=value tokens; a free-text remark after them (web_load's heavy statuses) is not a field
            fields = dict(kv.split("=", 1) for kv in m.group(2).split() if "=" in kv)
            results.append((m.group(1), fields))
    return proc.returncode, results


def main(argv=()):
    """Run the scripts (``--skip NAME`` leaves one out, e.g. the 10-minute scaling study)."""
    skip = {argv[i + 1] for i, a in enumerate(argv[:-1]) if a == "--skip"}
    scripts = sorted(p for p in HERE.glob("*.py") if p.name != Path(__file__).name and not p.name.startswith("_")
                     and p.stem not in skip)
    rows, failed = [], []
    for script in scripts:
        code, results = run(script)
        if code != 0 or not results:
            failed.append(script.name)  # its numbers are not worth printing: left out of the table
            continue
        rows += [(script.name, name, f) for name, f in results]
    stamp = _dt.datetime.now(_dt.UTC).strftime("%Y-%m-%d %H:%M UTC")
    lines = [BEGIN, (f"Last `make bench`: {stamp}, Python {platform.python_version()}, {os.cpu_count()} cores. "
                     "Each table: the batched path and its per-case baseline, measured in the same run, "
                     "each the best of several runs."), ""]
    if skip:
        lines[-1:-1] = [f"Not run this time: {', '.join(sorted(skip))} (see its section below).", ""]
    for script, name, f in rows:  # one table per model
        # a script may name its two paths (batched_label=2_workers); underscores read as spaces
        batched = f.get("batched_label", "batched").replace("_", " ")
        baseline = f.get("baseline_label", "per-case baseline").replace("_", " ")
        lines += [f"### {name} (`bench/{script}`)", "", "| path | cases/s |", "|---|---|",
                  f"| {batched} | {f.get('cases_per_s', '')} |", f"| {baseline} | {f.get('baseline_cases_per_s', '')} |",
                  f"| **ratio** | **{f.get('ratio', '')}** |"]
        shown = ("cases_per_s", "baseline_cases_per_s", "ratio", "batched_label", "baseline_label")
        other = [(k, v) for k, v in f.items() if k not in shown]
        lines += [f"| {k} | {v} |" for k, v in other]
        lines.append("")
    if failed:
        lines.append(f"Left out (failed its own checks or printed no RESULT line): {', '.join(failed)}")
    lines.append(END)
    bench_md = ROOT / "BENCHMARKS.md"
    text = bench_md.read_text() if bench_md.exists() else "# Benchmarks\n"
    block = "\n".join(lines)
    if BEGIN in text and END in text:
        text = text[: text.index(BEGIN)] + block + text[text.index(END) + len(END):]
    else:
        text = text.rstrip("\n") + "\n\n## Latest run\n\n" + block + "\n"
    tmp = bench_md.with_suffix(".md.tmp")
    tmp.write_text(text)
    os.replace(tmp, bench_md)
    print(f"BENCHMARKS.md updated ({len(rows)} results)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
