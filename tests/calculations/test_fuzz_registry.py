"""Issue 29 item 6: a fuzz test generated from the registry of calculations.

Every field of every calculation (:data:`bearinglab.calculations.CALCULATIONS`) gets a pool of hostile
values for its kind: the malformed quantities of the issue (``1.2.3 N``, ``9**9**9 K``, ``٥ kN``, ``1_000
N``, ``5,5 degC``, ``2 kgf h/s`` ...), extremes, NaN and infinity, lists and ranges (one with an
uncountable number of values), the wrong kind, empty, huge and non-ASCII text, and JSON numbers on the
web. Each (field, value) runs on top of a valid request of its calculation, found from the registry alone
(the fields' defaults and the examples of their help), through

* the command line's entry point, ``bearinglab.cli.main(argv)`` with ``--json``, in-process;
* the web API, ``GET`` and ``POST /api/<endpoint>`` of ``bearinglab.web.create_app()`` (a TestClient).

The only outcomes allowed: exit 2 (or 3, a stated non-convergence) with one line ``bearinglab: error: ...``
on stderr, or 422 with a one-line ``detail``; or exit 0 / 200 with one JSON document whose numbers are all
finite. Never a traceback, never a 500 (a body over the limit is 413, a run over its time budget 503).

A new calculation, or a new field, is fuzzed without a line here. ``make test`` runs a quick sample (a few
cases per calculation, derandomized); ``make fuzz`` runs the whole pool (``BEARINGLAB_FUZZ=full``) and
prints its counts (TESTING.md keeps them).
"""

from __future__ import annotations

import contextlib
import io
import json
import math
import os
import random
import re
from pathlib import Path

import pytest

from bearinglab import calculations, units
from bearinglab.calculations import CALCULATIONS

ROOT = Path(__file__).resolve().parents[2]
FULL = os.environ.get("BEARINGLAB_FUZZ") == "full"
QUICK_CASES = 2  # (field, value) pairs per calculation in the quick sample of `make test`

# ----------------------------------------------------------------------------- valid values, by field
# text fields whose valid values the help does not quote (names, grades, classes): by field name, so that
# any calculation with such a field finds them
TEXT_EXAMPLES = {
    "bearing": ["6205-2RS", "B218", "7205 BECBP"], "name": ["6205-2RS", "B218"], "query": ["62"],
    "oil": ["VG68"], "temperature": ["70 degC", "auto"], "series": ["62"], "ball_grade": ["G5"],
    "ring_class": ["P4"], "shaft_fit": ["k5"], "housing_fit": ["H7"], "tolerance_class": ["P6"],
    "clearance_class": ["C3"], "band": ["2 %"], "skf_constants": ["1.6,2.1,1.1,4.0,0.0052,0.008"],
}
DOCUMENTS = {
    "errors": (ROOT / "examples" / "runout" / "example1_oversize_ball.toml").read_text(encoding="utf-8"),
    "duty_cycle": '[[step]]\nfx = "1 kN"\nspeed = "1000 rpm"\ntime = 0.7\n\n[[step]]\nfx = "2 kN"\n'
                  'speed = "3000 rpm"\ntime = 0.3\n',
}
# a size a valid request keeps small, so that a run takes a fraction of a second
SMALL = {"samples": "4", "steps_per_rev": "36", "revolutions": "1", "monte_carlo": "100", "rows": "3",
         "harmonics": "2", "limit": "5"}


def _quoted(text):
    return re.findall(r"'([^']+)'", text or "")


def valid_values(field):
    """Values a user would give ``field``: its default, the examples of its help, by kind otherwise."""
    out = []
    if field.name in SMALL:
        out.append(SMALL[field.name])
    if field.kind == "document":  # the registry's own example, else a shipped example file
        return [field.example or DOCUMENTS.get(field.name, "{}")]
    if field.choices:
        return list(field.choices)
    if field.kind == "flag":
        return ["true", "false"]
    out += TEXT_EXAMPLES.get(field.name, [])
    out += [q for q in _quoted(field.help) if q not in out]
    if field.default not in (None, "") and str(field.default) not in out:
        out.append(str(field.default))
    if field.kind in units.KINDS:
        out += [q for q in _quoted(units.KINDS[field.kind][2]) if q not in out]
    if field.kind == "int":
        low = 1 if field.minimum is None else int(field.minimum)
        out.append(str(max(low, 1)))
    if field.kind == "number":
        low, high = field.minimum, field.maximum
        mid = 0.5 if low is None and high is None else (
            (low + high) / 2 if low is not None and high is not None else (low or 0) + 0.5)
        out.append(f"{mid:g}")
    return out


# ----------------------------------------------------------------------------- hostile values, by kind
# the strings of the issue, whatever the field
STRINGS = ["1.2.3 N", "--5 N", "N", "kN*kN/kN", "2 pi kN", "9**9**9 K", "10**308*10 N", "1e308 kN", "1e-400 N",
           "1e309", "nan", "inf", "-inf", "", " ", "٥ kN", "٥", "1_000 N", "1 000 K", "5,5 degC", "1.2.3 degC",
           "2 turn kgf", "2 kgf %", "10000 % rpm", "2 kgf h/s", "0 kN:1e300 kN:1e-300 kN", "6208-", "6208////",
           "6208.2RS", "é", "\x00", "<script>", "../../etc/passwd", "9" * 400, "x" * 20000, "1 N," * 5000,
           "true", "-1", "0"]


def hostile_values(field):
    """The pool of ``field``: the strings of the issue, and values made for its kind."""
    unit = field.unit if field.unit not in ("", "-") else ""
    u = f" {unit}" if unit else ""
    pool = list(STRINGS)
    if field.kind in units.KINDS or field.unit:  # a quantity (or a text that holds one, a temperature)
        pool += [f"0{u}", f"-1{u}", f"1e300{u}", f"1e-300{u}", f"-1e300{u}", f"1{u}, 2{u}", f"1{u}:3{u}:1{u}",
                 f"0{u}:1e300{u}:1e-300{u}", f"1{u}:1e9{u}:1{u}", f"3{u}:1{u}:1{u}", f"1{u}:2{u}",
                 f"nan{u}", f"inf{u}", f"1e-320{u}", f"5{u} {u}", f"2{u}%", "2 m", "2 kgf", "3000 rpm", "12 deg",
                 "20 cSt", "70 degC", "0.5 K/W", f"+1{u}", f"١{u}"]
    if field.kind == "int":
        top = 10**6 if field.maximum is None else int(field.maximum) + 1
        pool += [str(top), "2.5", "1e3", " 7 ", "9223372036854775808", "9" * 50, "0x10", "+3", "-0", "٣",
                 "1_0", 3, 3.0, -1, 10**30, True, 2.5]
    if field.kind == "number":
        pool += ["0.5", "1e308", "-1e308", "1e-400", "1,5", "0x10", ".5", "5.", 0.5, 1e308, -1.0, 10**30, True]
    if field.kind == "flag":
        pool += ["maybe", "1", "yes", "no", True, False, 1]
    if field.choices:
        pool += [field.choices[0].upper(), f" {field.choices[0]} ", field.choices[0] + "x"]
    if field.kind == "document":
        pool += ["{", "[]", "{}", "a = ", 'x = "1 N"', "[[step]]\ntime = 1e309", '{"profile": "/etc/passwd"}',
                 "[geometry]\nballs = 1000000000"]
    pool += [v for v in valid_values(field)]
    return pool


# ----------------------------------------------------------------------------- running one request
def _argv(calc, given, workdir):
    """The command line of ``given`` (field -> value), as a user would type it; None when the
    calculation has no command."""
    if not calc.command:
        return None
    fields = {f.name: f for f in calc.fields}
    words = list(calc.command)
    for name, value in given.items():
        f = fields[name]
        text = value if isinstance(value, str) else json.dumps(value)
        if f.kind == "flag":
            if text.strip().lower() in ("true", "1", "yes", "on"):
                words.append(f.cli_option)
            elif text.strip().lower() not in ("false", "0", "no", "off", ""):
                words.append(f"{f.cli_option}={text}")  # a value for a flag: a usage error
        elif f.kind == "document":
            path = workdir / f"{name}.toml"
            path.write_text(text, encoding="utf-8")
            words.append(f"{f.cli_option}={path}")
        elif f.cli_option == "NAME":
            words.append(text)
        elif f.many and f.kind == "text":
            words += [f"{f.cli_option}={item.strip()}" for item in text.split(",") or [""]]
        else:
            words.append(f"{f.cli_option}={text}")
    return [*words, "--json"]


def _strict_json(text):
    """The document, refusing NaN and Infinity (which json.loads would read)."""
    def refuse(token):
        raise ValueError(f"a non-finite number in the JSON: {token}")

    return json.loads(text, parse_constant=refuse)


def run_cli(calc, given, workdir):
    """(exit code, stdout, stderr) of the command line; None without a command."""
    from bearinglab.cli import main

    argv = _argv(calc, given, workdir)
    if argv is None:
        return None
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(argv)
    return code, out.getvalue(), err.getvalue()


def check_cli(calc, given, result):
    code, out, err = result
    where = f"bearinglab {calc.name} {given!r:.300}"
    assert "Traceback" not in err and "Traceback" not in out, f"{where}\n{err[-3000:]}"
    if code == 0:
        _strict_json(out)
        return "ok"
    assert code in (2, 3), f"{where}: exit {code}\n{err[-2000:]}"
    lines = [ln for ln in err.splitlines() if ln.strip() and not ln.startswith("bearinglab: warning:")]
    assert len(lines) == 1 and lines[0].startswith("bearinglab: error: "), f"{where}: exit {code}\n{err[-2000:]}"
    return "refused"


def check_web(calc, given, response, method):
    where = f"{method} /api/{calc.name} {given!r:.300}"
    assert response.status_code != 500, f"{where}: 500\n{response.text[:2000]}"
    assert response.status_code in (200, 413, 422, 503), f"{where}: {response.status_code}\n{response.text[:2000]}"
    body = _strict_json(response.text)
    if response.status_code == 200:
        return "ok"
    detail = body["detail"]
    assert isinstance(detail, str) and "\n" not in detail and "Traceback" not in detail, f"{where}: {detail!r}"
    return "refused"


def _endpoint(calc):
    from bearinglab.web import api

    return next(path for path, name in api.ENDPOINTS.items() if name == calc.name)


def run_web(client, calc, given, method):
    path = f"/api/{_endpoint(calc)}"
    if method == "GET":
        params = [(k, v if isinstance(v, str) else json.dumps(v)) for k, v in given.items()]
        return client.get(path, params=params)
    return client.post(path, content=json.dumps(given).encode(), headers={"content-type": "application/json"})


# ----------------------------------------------------------------------------- a valid request, found
_BASES = {}


def _runs(calc, given):
    try:
        calculations.run(calculations.parse(calc.name, given))
    except Exception:  # noqa: BLE001 -- any failure: not a base
        return False
    return True


def base(calc):
    """A valid request of ``calc``: its required fields (and small sizes) from their first valid values; where
    that does not run, one optional field more, the first that makes it run (a bearing first, then in the
    registry's order)."""
    if calc.name in _BASES:
        return _BASES[calc.name]
    given = {f.name: valid_values(f)[0] for f in calc.fields if f.required or f.name in SMALL}
    names = {f.name for f in calc.fields}
    if not _runs(calc, given) and "bearing" in names:  # most calculations need a bearing
        bearing = calc.field("bearing")
        given = next(({**given, "bearing": b} for b in valid_values(bearing)[:3]
                      if _runs(calc, {**given, "bearing": b})), {**given, "bearing": valid_values(bearing)[0]})
    for _round in range(2):  # then up to two optional fields, each the first that makes it run
        if _runs(calc, given):
            break
        given = _with_one_more(calc, given, lambda trial: _runs(calc, trial)) or _with_one_more(
            calc, given, lambda trial: _runs(calc, _with_one_more(calc, trial, lambda t: _runs(calc, t)) or trial))
    _BASES[calc.name] = given
    return given


def _with_one_more(calc, given, good):
    """``given`` with one more optional field (its first valid values tried) for which ``good`` holds."""
    for f in calc.fields:
        if f.name in given or f.kind in ("flag", "choice"):
            continue
        for value in valid_values(f)[:2]:
            trial = {**given, f.name: value}
            if good(trial):
                return trial
    return None


def cases(calc):
    """Every (field, value) of the calculation's pool."""
    for f in calc.fields:
        for value in hostile_values(f):
            yield f, value


def sample(calc, n):
    """``n`` cases of the pool, the same on every run (seeded by the calculation's name)."""
    every = list(cases(calc))
    return random.Random(calc.name).sample(every, min(n, len(every)))


# ----------------------------------------------------------------------------- the tests
@pytest.fixture(scope="module")
def client():
    from fastapi.testclient import TestClient

    from bearinglab.web import create_app

    with TestClient(create_app(light_workers=1, heavy_workers=1, time_budget=60.0)) as c:
        yield c


def _fuzz(calc, chosen, client, tmp_path, counts):
    """Run each (field, value) on both boundaries; the failures as a list of messages (every case runs)."""
    failures = []
    for k, (f, value) in enumerate(chosen):
        given = {**base(calc), f.name: value}
        methods = [("GET", "POST")[k % 2]] if FULL else ["GET", "POST"]  # the whole pool: one of them each
        try:
            result = run_cli(calc, given, tmp_path)
            if result is not None:
                counts[check_cli(calc, given, result)] += 1
            for m in methods:
                m = m if isinstance(value, str) else "POST"  # a JSON number travels in a body
                counts[check_web(calc, given, run_web(client, calc, given, m), m)] += 1
        except Exception as exc:  # noqa: BLE001 -- an assertion or a crash: a failure, and the next case
            failures.append(f"{f.name} = {value!r:.80}: {type(exc).__name__}: {str(exc)[:1500]}")
    return failures


@pytest.mark.parametrize("name", sorted(CALCULATIONS))
def test_registry_fuzz_quick_sample(name, client, tmp_path):
    calc = CALCULATIONS[name]
    counts = {"ok": 0, "refused": 0}
    failures = _fuzz(calc, sample(calc, QUICK_CASES), client, tmp_path, counts)
    assert not failures, "\n".join(failures)
    assert sum(counts.values()) >= QUICK_CASES


@pytest.mark.skipif(not FULL, reason="the whole pool: make fuzz (BEARINGLAB_FUZZ=full)")
@pytest.mark.parametrize("name", sorted(CALCULATIONS))
def test_registry_fuzz_full_pool(name, client, tmp_path):
    calc = CALCULATIONS[name]
    counts = {"ok": 0, "refused": 0}
    chosen = list(cases(calc))
    failures = _fuzz(calc, chosen, client, tmp_path, counts)
    line = (f"fuzz {name}: {len(chosen)} cases, {sum(counts.values())} runs ({counts['ok']} ok, "
            f"{counts['refused']} refused), {len(failures)} failures")
    print("\n" + line)
    if os.environ.get("BEARINGLAB_FUZZ_REPORT"):  # make fuzz sums the lines of the workers
        with open(os.environ["BEARINGLAB_FUZZ_REPORT"], "a", encoding="utf-8") as fh:
            fh.write(line + "\n" + "".join(f"    {x[:300]}\n" for x in failures))
    assert not failures, f"{len(failures)} failures:\n" + "\n".join(failures)


def test_every_calculation_has_a_base_that_runs():
    """The valid request found from the registry runs for every calculation (else the fuzz would only
    reach the first check of each field)."""
    failing = [name for name, calc in CALCULATIONS.items() if not _runs(calc, base(calc))]
    assert not failing, {name: base(CALCULATIONS[name]) for name in failing}


def test_every_field_has_a_pool():
    for calc in CALCULATIONS.values():
        for f in calc.fields:
            pool = hostile_values(f)
            assert len(pool) >= len(STRINGS) and all(isinstance(v, (str, int, float, bool)) for v in pool)
            assert not any(isinstance(v, float) and not math.isfinite(v) for v in pool)  # JSON cannot hold them
