"""The application as a whole: complete on import, the entry points, the declared dependencies."""

import ast
import os
import re
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

import bearinglab
from bearinglab.cli import main

ROOT = Path(__file__).resolve().parents[2]
SRC = ROOT / "src" / "bearinglab"
GROUPS = ("catalog", "axial-angle", "stand-load", "frequencies", "sweep", "high-speed", "friction", "runout")


def _python(code_or_args, *, env=None):
    args = ["-c", code_or_args] if isinstance(code_or_args, str) else code_or_args
    env = dict(os.environ, COLUMNS="200", **(env or {}))
    return subprocess.run([sys.executable, *args], check=False, capture_output=True, text=True, env=env, timeout=120)


def _listed(help_text):
    return [g for g in GROUPS if re.search(rf"^\W*{re.escape(g)}\s", help_text, re.MULTILINE)]


def test_app_imported_alone_lists_every_command_group():
    """Defect 1 of issue 10: an embedding that imports only ``app`` must see the whole command line."""
    r = _python("from bearinglab.cli import app\napp(['--help'], prog_name='bearinglab')")
    assert r.returncode == 0, r.stderr
    assert _listed(r.stdout) == list(GROUPS), r.stdout


def test_python_dash_m_runs_the_command_line():
    r = _python(["-m", "bearinglab", "--help"])
    assert r.returncode == 0, r.stderr
    assert _listed(r.stdout) == list(GROUPS)
    bad = _python(["-m", "bearinglab", "axial-angle", "-b", "4-1006095", "-F", "2 m"])
    assert bad.returncode == 2 and bad.stderr.count("\n") == 1 and "is a length" in bad.stderr


def test_version(capsys):
    assert main(["--version"]) == 0
    assert capsys.readouterr().out == f"bearinglab {bearinglab.__version__}\n"


def test_no_arguments_prints_help_and_exits_2(capsys):
    assert main([]) == 2
    out = capsys.readouterr().out
    assert "Usage" in out and "high-speed" in out


def _third_party_imports():
    """Top-level names of every module imported anywhere in src/bearinglab that is neither the
    standard library nor bearinglab itself."""
    names = set()
    for path in SRC.rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                names.update(a.name.split(".")[0] for a in node.names)
            elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
                names.add(node.module.split(".")[0])
    return {n for n in names if n not in sys.stdlib_module_names and n not in ("bearinglab", "__future__")}


def _declared():
    project = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]
    names = set()
    # bearinglab.web and `serve` import the web extra's packages (FastAPI, uvicorn), nothing else does;
    # shaft.rotor.to_ross imports the ross extra's ROSS, inside the one function that builds its Rotor
    extras = project["optional-dependencies"]
    for req in project["dependencies"] + extras["web"] + extras["ross"]:
        # "dask[distributed]>=2024.1" declares dask and distributed
        m = re.match(r"([A-Za-z0-9_.-]+)(?:\[([^\]]*)\])?", req)
        names.add(m.group(1).lower().replace("-", "_"))
        names.update(e.strip() for e in (m.group(2) or "").split(",") if e.strip())
    if "ross_rotordynamics" in names:
        names.add("ross")  # the import name of the distribution ross-rotordynamics
    return names


def test_every_third_party_import_is_a_declared_dependency():
    """Defect 2 of issue 10: click came only through typer (and dask), and recent typer no longer brings it."""
    undeclared = sorted(_third_party_imports() - _declared())
    assert not undeclared, f"imported in src/bearinglab but not in [project] dependencies: {undeclared}"


def test_click_is_not_imported():
    hits = [str(p.relative_to(ROOT)) for p in SRC.rglob("*.py")
            if re.search(r"^\s*(import click|from click)\b", p.read_text(encoding="utf-8"), re.MULTILINE)]
    assert not hits


@pytest.mark.parametrize("module", ["bearinglab", "bearinglab.tables", "bearinglab.plots"])
def test_light_imports(module):
    """``import bearinglab`` (STYLE.md section 8), tables and the plots package load no CLI or plotting library."""
    r = _python(f"import sys, {module}\nprint(sorted({{'typer', 'rich', 'matplotlib', 'click'}} & set(sys.modules)))")
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "[]"


def _help_texts(command, path=()):
    """(command path, text) of every help string of the click command tree."""
    yield path, command.help or ""
    for param in command.params:
        yield (*path, param.name), getattr(param, "help", None) or ""
    for name, sub in getattr(command, "commands", {}).items():
        yield from _help_texts(sub, (*path, name))


def test_no_help_text_loses_a_bracket_to_rich_markup():
    # rich reads "[rad]" or "[[step]]" in a help string as a markup tag and drops it; write "\[rad]"
    from bearinglab.cli import _click_command

    tag = re.compile(r"(?<!\\)\[[A-Za-z/#][^\]\[]*\]")
    bad = [(where, text) for where, text in _help_texts(_click_command()) if tag.search(text)]
    assert not bad, bad
