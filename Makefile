# bearinglab: set-up, demo, tests and benchmarks. Everything runs inside .venv.
PYTHON ?= python3.11
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed
TSTAMP := $(VENV)/.installed-test
DSTAMP := $(VENV)/.installed-docs

.PHONY: demo test lint docs bench clean

$(PY):
	@command -v $(PYTHON) >/dev/null 2>&1 || { echo "$(PYTHON) not found; set PYTHON=python3" >&2; exit 1; }
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip

$(STAMP): $(PY) pyproject.toml
	$(PY) -m pip install --quiet -e .
	@touch $@

$(TSTAMP): $(PY) pyproject.toml
	$(PY) -m pip install --quiet -e ".[test,ross,webtest]"
	@touch $@ $(STAMP)

# every examples/demo_*.py runs a published worked example and writes under out/
demo: $(STAMP)
	@mkdir -p out
	@set -e; for f in examples/demo_*.py; do echo "== $$f"; MPLBACKEND=Agg $(PY) $$f out; done
	@echo "tables and figures are in out/"

test: $(TSTAMP)
	$(PY) -m pytest -q -n 2

lint: $(TSTAMP)
	$(VENV)/bin/ruff check .

$(DSTAMP): $(PY) pyproject.toml
	$(PY) -m pip install --quiet -e ".[docs]"
	@touch $@ $(STAMP)

# the documentation site (runs the worked examples of docs/examples/); open docs/_build/html/index.html
docs: $(DSTAMP)
	MPLBACKEND=Agg $(VENV)/bin/sphinx-build -W --keep-going -b html docs docs/_build/html

bench: $(STAMP)
	$(PY) bench/run_all.py

clean:
	rm -rf $(VENV) out build *.egg-info src/*.egg-info docs/_build docs/auto_examples docs/sg_execution_times.rst
