"""Sphinx configuration of the bearinglab documentation (``pip install -e ".[docs]"``, then
``sphinx-build -b html docs docs/_build``)."""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "src"))

import bearinglab

project = "bearinglab"
author = "bearinglab developers"
release = version = bearinglab.__version__

extensions = ["sphinx.ext.autodoc", "sphinx.ext.mathjax", "sphinx.ext.viewcode", "numpydoc"]
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
autodoc_member_order = "bysource"
exclude_patterns = ["_build"]
html_theme = "alabaster"
