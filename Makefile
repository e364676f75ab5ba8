# bearinglab: set-up, demo, tests and benchmarks. Everything runs inside .venv.
PYTHON ?= python3.11
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed
TSTAMP := $(VENV)/.installed-test
DSTAMP := $(VENV)/.installed-docs

.PHONY: demo test lint docs bench mutants fuzz clean

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

BSTAMP := $(VENV)/.installed-bench
$(BSTAMP): $(PY) pyproject.toml
	$(PY) -m pip install --quiet -e ".[bench]"
	@touch $@ $(STAMP)

# every bench/*.py against its fair baseline and the compiled limit; rewrites BENCHMARKS.md's table
bench: $(BSTAMP)
	$(PY) bench/run_all.py

# the whole pool of the fuzz generated from the registry (every field of every calculation, through the
# command line and the web API) and the probe of the public functions' numbers (issue 29); `make test`
# runs a sample of both. The counts go to fuzz-report.txt (TESTING.md keeps them).
fuzz: $(TSTAMP)
	rm -f fuzz-report.txt
	BEARINGLAB_FUZZ=full BEARINGLAB_FUZZ_REPORT=$(CURDIR)/fuzz-report.txt $(PY) -m pytest -q -n 2 \
		tests/calculations/test_fuzz_registry.py tests/test_api_domains.py -k full
	@grep "^fuzz " fuzz-report.txt
	@awk '/^api /{n++; c+=$$3; f+=$$5} END {print "api probe: " n " functions, " c " calls, " f " failures"}' fuzz-report.txt

MSTAMP := $(VENV)/.installed-mutation
$(MSTAMP): $(TSTAMP)
	$(PY) -m pip install --quiet -e ".[test,mutation]"
	@touch $@

# mutation testing of the physics modules ([tool.mutmut] in pyproject.toml), at most MUTANTS_BUDGET
# seconds; not part of CI: run it before resolving an issue that touches physics (TESTING.md)
MUTANTS_BUDGET ?= 1200
mutants: $(MSTAMP)
	-CI=1 timeout $(MUTANTS_BUDGET) $(VENV)/bin/mutmut run --max-children 2  # CI=1: derandomized hypothesis
	$(VENV)/bin/mutmut results --all true > mutants-results.txt || $(VENV)/bin/mutmut results > mutants-results.txt
	@grep -c "killed" mutants-results.txt || true
	@echo "surviving mutants: $(VENV)/bin/mutmut results; one of them: $(VENV)/bin/mutmut show NAME"

clean:
	rm -rf $(VENV) mutants mutants-results.txt fuzz-report.txt out build *.egg-info src/*.egg-info docs/_build docs/auto_examples docs/sg_execution_times.rst
