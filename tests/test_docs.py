"""The documentation cannot fall behind the package: every module is in the architecture page's module
table, and every public module has its API reference page.

``docs/architecture.md`` holds the module table as it is (STYLE.md section 1): one row per module,
private ones too, whose first cell names it (``errors``, ``quasistatic.ball``, ``cli._common``; a
package by its name, for its ``__init__.py``). ``docs/api/`` has one page per public module or package
(``docs/api/quasistatic/ball.rst``, ``docs/api/quasistatic.rst``) with its ``automodule`` directive.
"""

import pkgutil
import re
from pathlib import Path

import pytest

import bearinglab

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"


def _modules():
    """Every module and package of bearinglab, by dotted name without the ``bearinglab.`` prefix."""
    names = ["bearinglab"]
    for info in pkgutil.walk_packages(bearinglab.__path__, "bearinglab."):
        names.append(info.name.removeprefix("bearinglab."))
    return names


def _table_modules():
    """The module names of the architecture page's table: the first backticked name of each row."""
    text = (DOCS / "architecture.md").read_text(encoding="utf-8")
    start = text.index("| module |")
    rows = [line for line in text[start:].splitlines() if line.startswith("|")]
    names = set()
    for row in rows[2:]:
        first = row.split("|")[1].strip()
        match = re.match(r"`([\w.]+)`", first)  # a bold cell (**`runout/`**) heads a group
        if match:
            names.add(match.group(1))
    return names


MODULES = _modules()
PUBLIC = [m for m in MODULES if m != "bearinglab" and not any(p.startswith("_") for p in m.split("."))]


def test_modules_found():
    assert {"limits", "quasistatic.ball", "web.page", "cli._common"} <= set(MODULES)


@pytest.mark.parametrize("module", MODULES)
def test_module_is_in_the_architecture_table(module):
    assert module in _table_modules(), f"docs/architecture.md: no row for `{module}` in the module table"


def test_architecture_table_lists_no_module_that_does_not_exist():
    gone = _table_modules() - set(MODULES)
    assert not gone, f"docs/architecture.md lists modules that do not exist: {sorted(gone)}"


@pytest.mark.parametrize("module", PUBLIC)
def test_public_module_has_an_api_page(module):
    page = DOCS / "api" / (module.replace(".", "/") + ".rst")
    assert page.is_file(), f"no API page {page.relative_to(DOCS.parent)} for bearinglab.{module}"
    text = page.read_text(encoding="utf-8")
    assert re.search(rf"^\.\. automodule:: bearinglab\.{re.escape(module)}$", text, re.MULTILINE), (
        f"{page.relative_to(DOCS.parent)} has no automodule directive for bearinglab.{module}")


@pytest.mark.parametrize("module", [m for m in PUBLIC if "." in m])
def test_api_page_is_in_its_package_toctree(module):
    package, _, name = module.rpartition(".")
    parent = DOCS / "api" / (package.replace(".", "/") + ".rst")
    assert re.search(rf"^\s+{re.escape(package.rpartition('.')[2])}/{name}$", parent.read_text(encoding="utf-8"),
                     re.MULTILINE), f"{parent.relative_to(DOCS.parent)}: {name} is not in its toctree"


def test_no_api_page_for_a_module_that_does_not_exist():
    pages = {str(p.relative_to(DOCS / "api").with_suffix("")).replace("/", ".") for p in (DOCS / "api").rglob("*.rst")}
    gone = pages - set(PUBLIC) - {"index"}
    assert not gone, f"docs/api has pages for modules that do not exist: {sorted(gone)}"


def _automodules():
    """(page, module, listed members or None for all) of every automodule directive under docs/api."""
    out = []
    for page in sorted((DOCS / "api").rglob("*.rst")):
        text = page.read_text(encoding="utf-8")
        for match in re.finditer(r"^\.\. automodule:: (\S+)\n((?:   :.*\n)*)", text, re.MULTILINE):
            members = re.search(r":members:(.*)", match.group(2))
            listed = None if members is None else {m.strip() for m in members.group(1).split(",") if m.strip()}
            out.append((page.relative_to(DOCS.parent).as_posix(), match.group(1), listed))
    return out


@pytest.mark.parametrize("page, module, listed", _automodules(), ids=lambda v: v if isinstance(v, str) else "")
def test_api_page_lists_every_function_and_class_its_module_defines(page, module, listed):
    """A page that lists its members explicitly names every public function and class defined in its
    module (one defined elsewhere and re-exported is documented on its own module's page). A page
    without ``:members:`` shows the module's docstring only; it is meant for modules that define no
    function or class (packages that re-export, the command modules)."""
    import importlib

    mod = importlib.import_module(module)
    own = {n for n in mod.__all__ if getattr(getattr(mod, n), "__module__", None) == module}
    if listed is None:
        assert not own, f"{page} documents none of {sorted(own)}: add them to a :members: list"
    elif listed:  # ':members:' with no list documents everything
        assert own <= listed, f"{page} does not list {sorted(own - listed)}"


_LINK = re.compile(r"\]\((?!https?:|mailto:|#)([^)\s#]+)(?:#[^)]*)?\)")


@pytest.mark.parametrize("page", ["README.md", *sorted(str(p.relative_to(ROOT)) for p in (ROOT / "docs").rglob("*.md")
                                                 if "_build" not in p.parts and "auto_examples" not in p.parts)])
def test_relative_links_resolve(page):
    # a link to a page that was renamed (.md -> .rst) or moved must fail here, not on a reader
    text = (ROOT / page).read_text(encoding="utf-8")
    broken = [t for t in _LINK.findall(text) if not ((ROOT / page).parent / t).exists()]
    assert not broken, f"{page} links to missing files: {broken}"


def _offline_check():
    import importlib.util

    spec = importlib.util.spec_from_file_location("offline_check", DOCS / "_ext" / "offline_check.py")
    module = importlib.util.module_from_spec(spec)
    pytest.importorskip("sphinx")  # the extension raises Sphinx's error type
    spec.loader.exec_module(module)
    return module


def test_the_docs_load_mathjax_from_the_site_and_check_every_page():
    # issue 20 item 15: `make docs` on a fresh clone, offline; the build runs offline_check (docs/_ext)
    conf = (DOCS / "conf.py").read_text(encoding="utf-8")
    assert '"sphinx-mathjax-offline"' in conf and '"offline_check"' in conf
    assert '"write_computation_times": False' in conf  # sphinx-gallery's timing page loads DataTables from CDNs
    assert "mathjax_path" not in conf or "cdn" not in conf.lower()
    import tomllib

    extras = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]["optional-dependencies"]
    docs = " ".join(extras["docs"])
    assert "sphinx-mathjax-offline" in docs
    # what autodoc imports beyond the core dependencies: the web calculator's (fastapi, jinja2, uvicorn)
    assert "bearinglab[web]" in docs and {"fastapi", "jinja2", "uvicorn"} <= {
        re.split(r"[<>=\[ ]", r)[0].lower() for r in extras["web"]}


def test_the_offline_check_finds_remote_scripts_and_missing_files(tmp_path):
    check = _offline_check()
    page = ('<html><head><script src="_static/a.js"></script>'
            '<script defer src="https://cdn.jsdelivr.net/npm/mathjax@3/es5/tex-chtml.js"></script>'
            '<link rel="stylesheet" href="//fonts.example.org/x.css"><link rel="icon" href="https://x/y.ico">'
            '<script src="data:text/javascript,1"></script><script>var inline = "https://x";</script>'
            '<script src="_static/missing.js?v=1"></script></head></html>')
    assert check.remote_resources(page) == [("script", "https://cdn.jsdelivr.net/npm/mathjax@3/es5/tex-chtml.js"),
                                            ("stylesheet", "//fonts.example.org/x.css")]
    (tmp_path / "_static").mkdir()
    (tmp_path / "_static" / "a.js").write_text("")
    (tmp_path / "sub").mkdir()
    (tmp_path / "index.html").write_text(page)
    (tmp_path / "sub" / "p.html").write_text('<script src="../_static/a.js"></script>')
    (tmp_path / "_static" / "macros.html").write_text('<script src="{{ pathto(x) }}"></script>')  # a template
    problems = check.check_site(tmp_path)
    assert problems == ["index.html: script from the network: https://cdn.jsdelivr.net/npm/mathjax@3/es5/tex-chtml.js",
                        "index.html: stylesheet from the network: //fonts.example.org/x.css",
                        "index.html: script not in the built site: _static/missing.js?v=1"]
