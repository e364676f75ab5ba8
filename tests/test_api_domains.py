"""Issue 29 item 2: the public Python functions raise InputError for values outside their domain.

A probe generated from the public API (tests/data/public_api.json) and the functions' own docstring
examples: each example that calls the function is run again with one of its numeric arguments replaced by
a hostile value (0, -0.0, -1, 1e-30, 1e30, 1e300, -1e300, inf, -inf, NaN, the smallest subnormal, a Python
int of 31 digits, 2^63). A function must answer with a result, an InputError (or a ConvergenceError, a
solve that says it failed), and within seconds: never a ZeroDivisionError, OverflowError, TypeError,
ValueError, LinAlgError or SystemError from inside, and never a loop that does not end. A new public
function with an example is probed without a line here.

``make test`` draws a sample (hypothesis, derandomized under CI); ``make fuzz`` runs every (example, argument,
value) (``BEARINGLAB_FUZZ=full``). Known and documented: a finite result of an absurd finite input (1e300
N) may still be inf or NaN in the Python API; the command line and the web refuse those documents
(bearinglab.calculations._finite).
"""

from __future__ import annotations

import ast
import contextlib
import copy
import doctest
import importlib
import io
import json
import math
import os
import signal
import warnings
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from bearinglab.errors import ConvergenceError, InputError

ROOT = Path(__file__).resolve().parents[1]
FULL = os.environ.get("BEARINGLAB_FUZZ") == "full"
SECONDS = 20.0  # a call that takes longer has a loop that does not end (the slowest example takes ~1 s)
# the boundaries (their inputs are text, fuzzed elsewhere) and the drawing code are not probed here
SKIP = ("bearinglab.cli", "bearinglab.web", "bearinglab.calculations", "bearinglab.plots", "bearinglab.report")
HOSTILE = [0, -0.0, -1.0, 1e-30, 1e30, 1e300, -1e300, math.inf, -math.inf, math.nan, 5e-324, 10**30, 2**63]


def _functions():
    """(module name, function name) of every public function whose docstring example calls it."""
    api = json.loads((ROOT / "tests" / "data" / "public_api.json").read_text(encoding="utf-8"))
    out = []
    for modname, names in sorted(api.items()):
        if modname == "bearinglab" or modname.startswith(SKIP):
            continue
        try:
            mod = importlib.import_module(modname)
        except ImportError:
            continue
        for name in names:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", DeprecationWarning)  # old names moved elsewhere
                fn = getattr(mod, name, None)
            if (callable(fn) and not isinstance(fn, type) and getattr(fn, "__module__", "") == modname
                    and f"{name}(" in (fn.__doc__ or "")):
                out.append((modname, name))
    return out


FUNCTIONS = _functions()


class _Timeout(Exception):
    pass


def _alarm(*_args):
    raise _Timeout


@contextlib.contextmanager
def _limited(seconds):
    previous = signal.signal(signal.SIGALRM, _alarm)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        with warnings.catch_warnings(), contextlib.redirect_stdout(io.StringIO()):
            warnings.simplefilter("ignore")
            yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


_SLOTS = {}


def slots(modname, name):
    """The probe points of one function: (namespace, call expression with ``__v`` for the argument, slot
    name), one per numeric argument of each example call, the examples before it run for their setup."""
    key = (modname, name)
    if key in _SLOTS:
        return _SLOTS[key]
    mod = importlib.import_module(modname)
    ns = dict(vars(mod), np=np, math=math)
    out = []
    for example in doctest.DocTestParser().get_examples(getattr(mod, name).__doc__ or ""):
        try:
            tree = ast.parse(example.source)
        except SyntaxError:
            continue
        for call in ast.walk(tree):
            if not (isinstance(call, ast.Call) and name in (getattr(call.func, "id", None),
                                                            getattr(call.func, "attr", None))):
                continue
            places = [("arg", i, a) for i, a in enumerate(call.args)] + [
                ("kw", k.arg, k.value) for k in call.keywords if k.arg]
            for where, index, node in places:
                try:
                    with _limited(SECONDS):
                        value = eval(ast.unparse(node), dict(ns))
                except BaseException:  # noqa: BLE001, S112 -- an argument that is no number: not a probe point
                    continue
                if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, float, np.integer, np.floating)):
                    continue
                probe = copy.deepcopy(call)
                if where == "arg":
                    probe.args[index] = ast.Name("__v", ast.Load())
                else:
                    next(k for k in probe.keywords if k.arg == index).value = ast.Name("__v", ast.Load())
                out.append((ns, ast.unparse(probe), f"{where} {index}"))
        try:  # the example itself: the setup of the next ones
            with _limited(SECONDS):
                exec(compile(example.source, "<example>", "exec"), ns)  # noqa: S102
        except BaseException:  # noqa: BLE001, S110 -- an example that prints or fails: its setup is kept as far as it got
            pass
    _SLOTS[key] = out
    return out


def probe(modname, name, index, value):
    """Run one probe point with ``value``; a description of the failure, or None."""
    points = slots(modname, name)
    if not points:
        return None
    ns, expression, where = points[index % len(points)]
    ns = dict(ns, __v=value)
    try:
        with _limited(SECONDS):
            result = eval(expression, ns)
            if hasattr(result, "__next__"):
                list(result)
    except (InputError, ConvergenceError):
        return None
    except _Timeout:
        return f"{modname}.{name} ({where} = {value!r}) did not return within {SECONDS:g} s: {expression}"
    except Exception as exc:  # noqa: BLE001 -- what the test is about
        return f"{modname}.{name} ({where} = {value!r}) raised {type(exc).__name__}: {exc}: {expression}"
    return None


def test_the_probe_finds_the_public_functions_and_their_examples():
    names = {f"{m}.{n}" for m, n in FUNCTIONS}
    for expected in ("bearinglab.bearing.max_balls", "bearinglab.limits.check_speed", "bearinglab.units.to_dms",
                     "bearinglab.film.ehl.hamrock_dowson", "bearinglab.quasistatic.thrust.high_speed_analysis"):
        assert expected in names
    assert len(FUNCTIONS) > 150
    assert slots("bearinglab.bearing", "max_balls")


@settings(max_examples=60, deadline=None, database=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(function=st.sampled_from(FUNCTIONS), index=st.integers(0, 50), value=st.sampled_from(HOSTILE))
def test_public_functions_answer_hostile_numbers_with_input_errors(function, index, value):
    failure = probe(*function, index, value)
    assert failure is None, failure


@pytest.mark.skipif(not FULL, reason="every example, argument and value: make fuzz (BEARINGLAB_FUZZ=full)")
@pytest.mark.parametrize("function", FUNCTIONS, ids=lambda f: f"{f[0]}.{f[1]}")
def test_public_functions_full_probe(function):
    failures = []
    for index in range(len(slots(*function))):
        for value in HOSTILE:
            failure = probe(*function, index, value)
            if failure:
                failures.append(failure)
    if os.environ.get("BEARINGLAB_FUZZ_REPORT"):
        with open(os.environ["BEARINGLAB_FUZZ_REPORT"], "a", encoding="utf-8") as fh:
            fh.write(f"api {function[0]}.{function[1]}: {len(slots(*function)) * len(HOSTILE)} calls, "
                     f"{len(failures)} failures\n" + "".join(f"    {f[:300]}\n" for f in failures))
    assert not failures, "\n".join(failures)
