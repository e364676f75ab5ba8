"""Test configuration.

Hypothesis explores new random examples on every local run (and remembers failures in .hypothesis/).
Under CI (the environment variable CI is set, as the CI runner does) it runs derandomized: the same
examples every time, so a CI result depends on the code only. Failures that random exploration finds
locally are added to the tests as explicit @example cases.
"""

import importlib.util
import os
from pathlib import Path

import pytest
from hypothesis import settings

settings.register_profile("ci", derandomize=True, database=None)
if os.environ.get("CI"):
    settings.load_profile("ci")


@pytest.fixture
def load_bench(monkeypatch):
    """Import a benchmark script ``bench/NAME.py`` as a module, for smoke tests of its functions.

    The scripts run as ``python bench/NAME.py``, which puts bench/ on sys.path for their shared helpers
    (bench/_timing.py); the fixture does the same for the duration of the test.
    """
    bench_dir = Path(__file__).resolve().parent.parent / "bench"
    monkeypatch.syspath_prepend(str(bench_dir))

    def load(name):
        spec = importlib.util.spec_from_file_location(f"bench_{name}", bench_dir / f"{name}.py")
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        return module

    return load
