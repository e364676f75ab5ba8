"""Every ``$ bearinglab ...`` example of the README and of docs/ is run, and the lines it shows are compared.

The convention of a ``console`` block (Markdown ```` ```console ````, or ``.. code-block:: console`` in
reStructuredText), also stated in TESTING.md:

- A line ``$ command`` starts a command; a command ending in ``\\`` continues on the next line. The lines
  that follow, up to the next command, are what the command prints (stdout and stderr together).
- A block is run when one of its commands starts with ``bearinglab``. Its commands run in order, in bash,
  with ``bearinglab`` meaning ``python -m bearinglab`` of this checkout, ``COLUMNS=80`` and a UTF-8 stdout,
  in a scratch directory holding a copy of ``examples/`` and the files the docs define (below); so example
  paths such as ``examples/runout/example3_mixed.toml`` resolve and written files go to the scratch
  directory. Shell commands of the block run too, if they are in ``SHELL`` (``printf ... > bad.toml``,
  ``head -c 120 b218.json``, ``mkdir -p out``); any other command (``pip install``, ``bearinglab serve``,
  which runs until stopped) fails the test unless the block is marked ``skip``.
- A shown line must be a line of the output (trailing spaces ignored), and the shown lines must come in
  the output's order and next to each other, except where the block has a line ``...``: there, any
  number of output lines are left out. A line that starts with ``...`` and goes on (``  ... per-ball
  table; dz = 655 um``) is a prose summary of left-out lines: it is not compared either.
- Numbers printed with 12 or more significant digits (a JSON float) compare to 1e-9 relative, so that a
  last digit that differs on another CPU (tests/test_stand_compiled.py) does not fail the example.
- A command whose shown output has no ``bearinglab: error:`` line must exit with 0; one that shows it
  must exit with 2.
- ``$ curl [-i] [-G] "http://127.0.0.1:8000/api/..." [--data-urlencode NAME=VALUE]...`` (docs/web.md) is
  sent to the web application in-process (FastAPI's TestClient, so no server is started): the body, and
  with ``-i`` the status line and headers first, are compared as above.
- ``<!-- doc-example: file NAME -->`` on the line before a code block (of any language) makes the block
  the content of file NAME in the scratch directory, for the examples of every page.
- ``<!-- doc-example: skip REASON -->`` on the line before a block leaves the block out (a server that
  runs until stopped, a port already in use, a remote cluster); the reason is required.
"""

from __future__ import annotations

import math
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path
from typing import NamedTuple

import pytest

ROOT = Path(__file__).resolve().parents[1]
PAGES = sorted([ROOT / "README.md", *(ROOT / "docs").rglob("*.md"), *(ROOT / "docs").rglob("*.rst")])
PAGES = [p for p in PAGES if "_build" not in p.parts and "auto_examples" not in p.parts]
MARK = re.compile(r"^\s*<!--\s*doc-example:\s*(\w+)\s*(.*?)\s*-->\s*$")
TIMEOUT = 300  # s for one command (the Monte Carlo of scale_out.md on a local cluster takes about 15 s)
SHELL = {"printf", "head", "cat", "echo", "grep", "ls", "mkdir", "cp"}  # shell steps an example may take


class Block(NamedTuple):
    page: Path
    line: int  # of the opening fence, 1-based
    language: str
    text: str  # the content, dedented
    mark: tuple | None  # ("skip", reason) or ("file", name) from the comment line before the fence


def _dedent(lines):
    body = [x for x in lines if x.strip()]
    cut = min((len(x) - len(x.lstrip(" ")) for x in body), default=0)
    return "\n".join(x[cut:] for x in lines)


def _blocks(page):
    """The code blocks of a page: Markdown fences, and reStructuredText code-block directives."""
    lines = page.read_text(encoding="utf-8").splitlines()
    out = []
    k = 0
    while k < len(lines):
        line = lines[k]
        fence = re.match(r"^(\s*)(```+|~~~+)\s*\{?([\w+-]*)\}?", line)
        directive = re.match(r"^(\s*)\.\. (?:code-block|code|sourcecode)::\s*(\w+)", line)
        before = next((lines[j] for j in range(k - 1, -1, -1) if lines[j].strip()), "") if k else ""
        mark = MARK.match(before)
        mark = (mark.group(1), mark.group(2)) if mark else None
        if fence and page.suffix == ".md":
            indent, ticks, language = fence.groups()
            end = k + 1
            while end < len(lines) and not lines[end].strip().startswith(ticks[:3]):
                end += 1
            body = [x[len(indent):] if x.startswith(indent) else x.lstrip() for x in lines[k + 1:end]]
            out.append(Block(page, k + 1, language.lower(), _dedent(body), mark))
            k = end + 1
        elif directive and page.suffix == ".rst":
            indent, language = directive.groups()
            end = k + 1
            while end < len(lines) and (not lines[end].strip() or lines[end].startswith(indent + " ")):
                end += 1
            body = [x for x in lines[k + 1:end] if not re.match(r"^\s+:\w+:", x)]
            out.append(Block(page, k + 1, language.lower(), _dedent(body).strip("\n"), mark))
            k = end
        else:
            k += 1
    return out


ALL_BLOCKS = [b for page in PAGES for b in _blocks(page)]


class Command(NamedTuple):
    text: str  # the command line(s), without "$ "
    shown: list  # the lines shown after it


def _commands(text):
    """The commands of a console block and the lines shown after each."""
    commands = []
    lines = text.splitlines()
    k = 0
    while k < len(lines):
        line = lines[k]
        if line.startswith("$ "):
            cmd = [line[2:]]
            while cmd[-1].rstrip().endswith("\\") and k + 1 < len(lines):
                k += 1
                cmd.append(lines[k])
            commands.append(Command("\n".join(cmd), []))
        elif commands:
            commands[-1].shown.append(line)
        k += 1
    for c in commands:  # blank lines that close a block are not output
        while c.shown and not c.shown[-1].strip():
            c.shown.pop()
    return commands


def _is_api(text):
    return text.lstrip().startswith("curl ") and "http://127.0.0.1:8000/api/" in text


def _is_run(block):
    if block.language != "console":
        return False
    return any(c.text.lstrip().startswith("bearinglab") or _is_api(c.text) for c in _commands(block.text))


RUN = [b for b in ALL_BLOCKS if _is_run(b) and (b.mark or ("",))[0] != "skip"]
SKIPPED = [b for b in ALL_BLOCKS if _is_run(b) and (b.mark or ("",))[0] == "skip"]
FILES = [b for b in ALL_BLOCKS if (b.mark or ("",))[0] == "file"]

# ---- comparison of one shown line with one output line

_NUMBER = re.compile(r"[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?")


def _digits(token):
    mantissa = re.split(r"[eE]", token.lstrip("+-"))[0].replace(".", "").lstrip("0")
    return len(mantissa)


def same_line(shown, got):
    """A shown line against an output line: equal after trailing spaces, long floats to 1e-9 relative."""
    shown, got = shown.rstrip(), got.rstrip()
    if shown == got:
        return True
    if _NUMBER.sub("#", shown) != _NUMBER.sub("#", got):
        return False
    for a, b in zip(_NUMBER.findall(shown), _NUMBER.findall(got)):
        if a == b:
            continue
        if min(_digits(a), _digits(b)) < 12:
            return False
        x, y = float(a), float(b)
        if not math.isclose(x, y, rel_tol=1e-9, abs_tol=1e-300):
            return False
    return True


def _is_gap(line):
    return line.strip().startswith("...")


def match_output(shown, output):
    """None if the shown lines are in the output by the convention of this module, else what is wrong."""
    runs, run = [], []
    for line in shown:
        if _is_gap(line):
            if run:
                runs.append(run)
            run = []
        else:
            run.append(line)
    if run:
        runs.append(run)
    pos = 0
    for run in runs:
        found = None
        for start in range(pos, len(output) - len(run) + 1):
            if all(same_line(s, output[start + j]) for j, s in enumerate(run)):
                found = start
                break
        if found is None:
            best = _closest(run, output, pos)
            return ("these shown lines are not in the output, in this order and next to each other:\n"
                    + "\n".join(f"    | {x}" for x in run) + f"\n  closest output line to the first mismatch:\n{best}")
        pos = found + len(run)
    return None


def _closest(run, output, pos):
    """Where the run goes wrong, for the failure message: the first shown line not found after pos."""
    import difflib

    for s in run:
        if not any(same_line(s, o) for o in output[pos:]):
            near = difflib.get_close_matches(s, output[pos:], n=1, cutoff=0.0)
            return f"    shown: {s!r}\n    near:  {near[0]!r}" if near else f"    shown: {s!r}\n    (no output)"
    return "    (every line is in the output, but not next to each other: add '...' where lines are left out)"


# ---- running

@pytest.fixture(scope="module")
def scratch(tmp_path_factory):
    """A scratch directory: a copy of examples/, the files the docs define, a ``bearinglab`` on the PATH."""
    return _make_scratch(tmp_path_factory.mktemp("doc-examples"))


def _make_scratch(d):
    shutil.copytree(ROOT / "examples", d / "examples", ignore=shutil.ignore_patterns("*.csv", "*.parquet", "out"))
    for csv in (ROOT / "examples").rglob("*.csv"):  # inputs are kept, outputs of earlier runs are not
        if "sweep" not in csv.relative_to(ROOT).parts:  # (not the checkout's own path)
            target = d / csv.relative_to(ROOT)
            target.parent.mkdir(parents=True, exist_ok=True)
            shutil.copy(csv, target)
    written = {}
    for b in FILES:
        name = b.mark[1]
        assert name and "/" not in name, f"{b.page.name}:{b.line}: doc-example: file needs a plain file name"
        assert written.get(name, b.text) == b.text, f"{b.page.name}:{b.line}: two different files named {name}"
        written[name] = b.text
        (d / name).write_text(b.text + "\n", encoding="utf-8")
    bin_dir = d / ".bin"
    bin_dir.mkdir()
    exe = bin_dir / "bearinglab"
    exe.write_text(f'#!/bin/sh\nexec "{sys.executable}" -m bearinglab "$@"\n')
    exe.chmod(0o755)
    return d


def _environment(scratch):
    env = dict(os.environ)
    src = str(ROOT / "src")
    env.update(COLUMNS="80", LINES="50", PYTHONIOENCODING="utf-8", MPLBACKEND="Agg", NO_COLOR="1",
               TERM="dumb", PATH=f"{scratch / '.bin'}{os.pathsep}{env.get('PATH', '')}",
               PYTHONPATH=os.pathsep.join([src, *filter(None, [env.get("PYTHONPATH")])]))
    env.pop("FORCE_COLOR", None)
    env.pop("BEARINGLAB_CATALOG", None)
    return env


def _api(text):
    """Output lines of a ``curl`` command against the web application, run in-process."""
    import shlex
    import urllib.parse

    pytest.importorskip("fastapi")
    pytest.importorskip("httpx")
    from fastapi.testclient import TestClient

    from bearinglab.web.app import create_app

    words = shlex.split(text.replace("\\\n", " "))[1:]
    head = "-i" in words
    url = next(w for w in words if w.startswith("http://"))
    params = [tuple(words[k + 1].split("=", 1)) for k, w in enumerate(words) if w == "--data-urlencode"]
    parts = urllib.parse.urlsplit(url)
    with TestClient(create_app()) as client:
        response = client.get(parts.path + ("?" + parts.query if parts.query else ""), params=params or None)
    out = []
    if head:
        out.append(f"HTTP/1.1 {response.status_code} {response.reason_phrase}")
        out += [f"{k}: {v}" for k, v in response.headers.items()]
        out.append("")
    return response.status_code, out + response.text.splitlines()


def _shell(text, scratch, env):
    """Run a command line in bash in its own process group (killed whole on a timeout); (exit code, lines)."""
    import signal

    proc = subprocess.Popen(["bash", "-c", text], cwd=scratch, env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, start_new_session=True)
    try:
        out, _ = proc.communicate(timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        return None, [f"(no answer in {TIMEOUT} s)"]
    return proc.returncode, out.decode("utf-8", errors="replace").splitlines()


def _allowed(text):
    """None if the command may run, else why not."""
    first = text.split()[0] if text.split() else ""
    if first == "bearinglab":
        return "it starts a server that runs until stopped" if text.split()[1:2] == ["serve"] else None
    if _is_api(text) or first in SHELL:
        return None
    return f"'{first}' is not a command the doc examples run ({sorted(SHELL)})"


def _run_block(block, scratch, outputs=None):
    failures = []
    env = _environment(scratch)
    for cmd in _commands(block.text):
        where = f"{block.page.relative_to(ROOT)}:{block.line}: $ {cmd.text}"
        why = _allowed(cmd.text)
        if why:
            failures.append(f"{where}\n  not run: {why}; mark the block <!-- doc-example: skip REASON -->")
            continue
        if _is_api(cmd.text):
            status, out = _api(cmd.text)
            if outputs is not None:
                outputs.append((cmd, out))
            error = any(line.startswith("HTTP/1.1 4") for line in cmd.shown)
            if (status >= 400) != error:
                failures.append(f"{where}\n  HTTP status {status}:\n" + "\n".join(out[:8]))
                continue
            wrong = match_output(cmd.shown, out)
            if wrong:
                failures.append(f"{where}\n  {wrong}")
            continue
        code, out = _shell(cmd.text, scratch, env)
        if not cmd.text.lstrip().startswith("bearinglab"):
            continue  # a shell step of the example (writing a file, showing one): run, not compared
        if outputs is not None:
            outputs.append((cmd, out))
        error = any(line.startswith("bearinglab: error:") for line in cmd.shown)
        if error and code != 2:
            failures.append(f"{where}\n  exit code {code}, the example shows an error (exit 2)")
        if not error and code != 0:
            failures.append(f"{where}\n  exit code {code}:\n" + "\n".join(out[-15:]))
            continue
        wrong = match_output(cmd.shown, out)
        if wrong:
            failures.append(f"{where}\n  {wrong}")
    return failures


@pytest.mark.parametrize("block", RUN, ids=[f"{b.page.relative_to(ROOT)}:{b.line}" for b in RUN])
def test_doc_example_prints_what_the_docs_show(block, scratch):
    failures = _run_block(block, scratch)
    assert not failures, "\n\n".join(failures)


# ---- the convention itself

def test_the_examples_are_found_and_every_skip_says_why():
    pages = {b.page.name for b in RUN}
    assert {"README.md", "test_stand.md", "life.md", "load_distribution.md", "getting_started.md"} <= pages
    assert len(RUN) >= 40
    for b in SKIPPED:
        assert b.mark[1], f"{b.page.name}:{b.line}: doc-example: skip needs a reason"
    # a mark that is neither skip nor file is a typo that would silently run or not write a file
    assert all(b.mark is None or b.mark[0] in ("skip", "file") for b in ALL_BLOCKS)


def test_match_output_follows_the_convention():
    out = ["title", "┏━━━┓", "│ a │ 1.0 │", "│ b │ 2.0 │", "└───┘", "x = 0.30000000000000004", "end"]
    assert match_output(["│ a │ 1.0 │", "│ b │ 2.0 │"], out) is None
    assert match_output(["title", "...", "end"], out) is None
    assert match_output(["title", "  ... a summary of the table", "end"], out) is None
    assert match_output(["x = 0.3000000000000001"], out) is None  # 17 digits: to 1e-9
    assert match_output(["│ a │ 1.1 │"], out) is not None  # a short number is exact
    assert match_output(["title", "end"], out) is not None  # a gap needs "..."
    assert match_output(["│ b │ 2.0 │", "...", "│ a │ 1.0 │"], out) is not None  # order
    assert match_output(["│ a │ 1.0 │   "], out) is None  # trailing spaces
    assert match_output([], out) is None


def test_commands_and_files_are_read_as_documented():
    cmds = _commands("$ bearinglab a \\\n    --b c\nline 1\n...\n$ head x\n\n")
    assert [c.text for c in cmds] == ["bearinglab a \\\n    --b c", "head x"]
    assert cmds[0].shown == ["line 1", "..."] and cmds[1].shown == []
    assert FILES, "the docs define the example files they use (doc-example: file NAME)"


# ---- re-syncing the pages with the program: python tests/test_doc_examples.py --update [PAGE ...]

def _resync(shown, output):
    """New shown lines for one command: the whole output where nothing was left out; else each run of
    shown lines replaced by the output lines from the one most like its first line to the one most like
    its last (so a run keeps its place when a table is re-laid out), the '...' lines kept."""
    import difflib

    def ratio(a, b):
        return difflib.SequenceMatcher(None, a.rstrip(), b.rstrip()).ratio()

    if not any(_is_gap(x) for x in shown):
        return [x.rstrip() for x in output]
    new, run, pos = [], [], 0

    def flush():
        nonlocal pos
        if not run:
            return
        if pos >= len(output):
            new.extend(run)
            return
        first = max(range(pos, len(output)), key=lambda i: ratio(run[0], output[i]))
        last = max(range(first, len(output)), key=lambda i: (ratio(run[-1], output[i]), -i))
        if len(run) == 1:
            last = first
        new.extend(x.rstrip() for x in output[first:last + 1])
        pos = last + 1

    for line in shown:
        if _is_gap(line):
            flush()
            run.clear()
            new.append(line)
        else:
            run.append(line)
    flush()
    return new


def _update(pages):
    """Rewrite the shown output of every failing example of ``pages`` with what the program prints now."""
    import tempfile

    with tempfile.TemporaryDirectory() as tmp:
        scratch_dir = _make_scratch(Path(tmp))
        for block in RUN:
            if pages and block.page.name not in pages and str(block.page.relative_to(ROOT)) not in pages:
                continue
            outputs = []
            if not _run_block(block, scratch_dir, outputs):
                continue
            text = block.page.read_text(encoding="utf-8")
            lines = text.split("\n")
            start = block.line  # the first content line, 0-based index
            end = start
            while not lines[end].strip().startswith(("```", "~~~")):
                end += 1
            indent = lines[start][:len(lines[start]) - len(lines[start].lstrip(" "))]
            body = []
            for cmd, out in outputs:
                body += [indent + "$ " + cmd.text.split("\n")[0]] + [indent + x for x in cmd.text.split("\n")[1:]]
                body += [indent + x if x else "" for x in _resync(cmd.shown, out)]
            # shell steps (not compared) keep their place before the command that follows them
            shell = [c for c in _commands(block.text) if not c.text.lstrip().startswith("bearinglab")
                     and not _is_api(c.text)]
            if shell:
                print(f"{block.page.name}:{block.line}: has shell steps, left for a manual update")
                continue
            lines[start:end] = body
            block.page.write_text("\n".join(lines), encoding="utf-8")
            print(f"updated {block.page.relative_to(ROOT)}:{block.line}")
            globals()["ALL_BLOCKS"] = [b for p in PAGES for b in _blocks(p)]  # line numbers moved
            RUN[:] = [b for b in ALL_BLOCKS if _is_run(b) and (b.mark or ("",))[0] != "skip"]


if __name__ == "__main__":
    if sys.argv[1:2] != ["--update"]:
        sys.exit("usage: python tests/test_doc_examples.py --update [PAGE ...]")
    _update(set(sys.argv[2:]))
