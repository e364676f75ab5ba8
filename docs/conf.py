"""Sphinx configuration of the bearinglab documentation.

Build with ``make docs`` (installs the ``docs`` extra into .venv, then
``sphinx-build -W --keep-going -b html docs docs/_build/html``). Markdown pages are read by myst-parser,
the worked examples under ``docs/examples/`` are run by sphinx-gallery on every build (their figures are
made then), the CLI reference is generated from the typer app by sphinx-click, and the API reference
from the numpydoc docstrings. The site works offline: MathJax is copied into ``_static`` and no page
loads anything from the network (``docs/_ext/offline_check.py`` fails the build otherwise).
"""

import os
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "src"))
sys.path.insert(0, str(HERE / "_ext"))
os.environ.setdefault("MPLBACKEND", "Agg")

import bearinglab

project = "bearinglab"
author = "bearinglab developers"
copyright = "bearinglab developers"
release = version = bearinglab.__version__

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.mathjax",
    "sphinx-mathjax-offline",  # MathJax 3 from a local copy in _static/mathjax, not from a CDN
    "sphinx.ext.viewcode",
    "numpydoc",
    "myst_parser",
    "sphinx_gallery.gen_gallery",
    "sphinx_click",
    "sphinx_copybutton",
    "docstring_fixes",  # docs/_ext: topic lists of module docstrings -> literal blocks (see there)
    "reexports",  # docs/_ext: a reference to a re-exported name goes to the page of its definition
    "offline_check",  # docs/_ext: the build fails if a page loads a script or style sheet from the network
]
# Silenced, each for one reason:
# - ref.citation: a module docstring lists the references its functions cite; numpydoc renames the
#   citations of each docstring apart, so the module's own list looks "not referenced".
# - myst.header: BENCHMARKS.md (written by `make bench`, included as is) goes from # to ###.
suppress_warnings = ["ref.citation", "myst.header"]
source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
exclude_patterns = ["_build", "_ext", "examples/GALLERY_HEADER.rst"]

# --- autodoc / numpydoc: one page per public module or package (docs/api/). Each object is documented
# once, on the page of the module that defines it: every page lists its members explicitly (a package
# page names only what the package itself defines), so no default ``members`` option here (a default
# ``True`` would override a page's explicit member list).
autodoc_member_order = "bysource"
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_xref_param_type = False
# Validation is left to tests/test_docstrings.py; here only the checks every docstring passes.
numpydoc_validation_checks = set()

# --- MyST: $ and $$ math, anchors for in-page links, ::: fences
myst_enable_extensions = ["dollarmath", "amsmath", "colon_fence", "deflist"]
myst_heading_anchors = 3
myst_dmath_double_inline = True

# --- worked examples: run on every build, figures embedded
sphinx_gallery_conf = {
    "examples_dirs": "examples",
    "gallery_dirs": "auto_examples",
    "filename_pattern": r"/plot_",
    "within_subsection_order": "FileNameSortKey",
    "download_all_examples": False,
    "remove_config_comments": True,
    "matplotlib_animations": False,
    "image_scrapers": ("matplotlib",),
    "reference_url": {"bearinglab": None},
    "show_memory": False,
    "min_reported_time": 1,
    # the page of computation times loads jQuery and DataTables from CDNs: not written (an offline site)
    "write_computation_times": False,
}

# --- HTML
html_theme = "pydata_sphinx_theme"
html_title = f"bearinglab {release}"
html_static_path = []
html_theme_options = {
    "navigation_with_keys": False,
    "show_toc_level": 2,
    "secondary_sidebar_items": ["page-toc"],
    "footer_start": ["copyright"],
    "footer_end": [],
}
html_context = {"default_mode": "light"}
copybutton_prompt_text = r">>> |\.\.\. |\$ "
copybutton_prompt_is_regexp = True
