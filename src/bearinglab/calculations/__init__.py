"""Typed requests: every calculation's inputs declared once, parsed and checked once, and run.

The command line, the JSON API and the page share this layer. A calculation is declared in
:mod:`.registry` as a list of :class:`~.fields.Field` (name, quantity kind and unit, range, default,
help, list or not); :func:`parse` reads the values a user gave (text, numbers, flags) and checks them
and the size of the request; :func:`run` computes the JSON document ``bearinglab <command> --json``
prints. A bad input raises :class:`~.fields.RequestError`, which each boundary words its own way.

Functions
---------
parse        calculation name and values as given -> Parsed (checked values, cases, weight, heavy)
run          Parsed -> the calculation's JSON document (the command line's ``--json`` document)
figure_svg   Parsed -> the calculation's figure as SVG text ('' where it has none)
argv         Parsed -> the command line's words and options for the same request

Classes and constants
---------------------
Parsed, Calculation, Field, RequestError, RunFailure
CALCULATIONS, CASE_LIMIT, TIME_BUDGET, BODY_LIMIT, DOCUMENT_LIMIT (from :mod:`.registry`)
LIGHT_WEIGHT (the most estimated work a request may have in the web's light pool)
"""

from __future__ import annotations

import math
from typing import NamedTuple

from .documents import RunFailure, argv, figure_svg, run
from .fields import Field, RequestError, count_values, parse_field
from .registry import BODY_LIMIT, CALCULATIONS, CASE_LIMIT, DOCUMENT_LIMIT, TIME_BUDGET, Calculation

__all__ = [
    "BODY_LIMIT",
    "CALCULATIONS",
    "CASE_LIMIT",
    "DOCUMENT_LIMIT",
    "LIGHT_WEIGHT",
    "TIME_BUDGET",
    "Calculation",
    "Field",
    "Parsed",
    "RequestError",
    "RunFailure",
    "argv",
    "count_values",
    "figure_svg",
    "parse",
    "parse_field",
    "run",
]


#: The most work (:attr:`Parsed.weight`, in single cases) a request may have and still run in the light pool
#: of the web: a duty cycle of 50 steps takes ~30 ms (0.5 ms a step, 6208), like one light case with its
#: overhead; a heavier one goes to the heavy pool.
LIGHT_WEIGHT = 50


class Parsed(NamedTuple):
    """A checked request."""

    calculation: Calculation
    """What is computed."""
    given: dict
    """Field name -> the value as given (text, number or flag), only the fields given."""
    values: dict
    """Field name -> the checked value (SI floats or arrays, ints, choices, flags, text)."""
    cases: int
    """How many cases the request holds (the product of a grid, the longest list, mask lines ...)."""

    @property
    def weight(self):
        """The request's work estimated from its parsed size, in single cases: its cases (the product of
        its lists and ranges, a runout's positions, a Monte Carlo study's samples, a mask's lines) times
        the steps of a duty cycle (counted by their ``speed`` keys, one per step, without reading the
        document)."""
        weight = max(1, self.cases)
        cycle = self.values.get("duty_cycle")
        if isinstance(cycle, str):
            weight *= max(1, cycle.count("speed"))
        return weight

    @property
    def heavy(self):
        """Whether the request may take long: a list or range of more than one value, a heavy
        calculation (runout), or a :attr:`weight` over :data:`LIGHT_WEIGHT` (a duty cycle of many
        steps): the web runs it in the heavy pool, so that it never holds a light worker."""
        lists = [v for f in self.calculation.fields if f.many and f.kind != "text"
                 for v in [self.values.get(f.name)] if v is not None]
        return self.calculation.heavy or any(len(v) > 1 for v in lists) or self.weight > LIGHT_WEIGHT


def _cases(calc, values, given, limit):
    """The cases of a request by the calculation's rule; too many raises RequestError."""
    counts = {f.name: len(values[f.name]) for f in calc.fields if f.many and f.name in values
              and f.kind != "text"}
    if calc.combine == "grid":
        cases = math.prod(counts.values()) if counts else 1
    elif calc.combine == "broadcast":
        cases = max(counts.values(), default=1)
    else:
        cases = 1
    if calc.name == "runout" and ("revolutions" in values or "steps_per_rev" in values):
        cases = values.get("revolutions", 3) * values.get("steps_per_rev", 360)  # the positions
    if calc.name == "runout-monte-carlo":  # the random bearings are the cases
        cases = values.get("samples", 200)
    if calc.name == "axial-angle":
        cases *= values.get("rows", 1)
    if calc.name == "clearance":  # the Monte Carlo samples are the cases
        cases = values.get("monte_carlo", 1)
    if calc.name == "frequencies":
        cases = values.get("harmonics", 3) * (2 * values.get("sidebands", 1) + 1)
    if cases > limit:
        if not counts:  # a size field makes the cases: name it
            counts = {k: 1 for k in ("monte_carlo", "revolutions", "steps_per_rev", "rows", "harmonics")
                      if k in values}
            if calc.name == "runout-monte-carlo":
                counts = {"samples": 1}
        names = ", ".join(sorted(counts)) or "request"
        raise RequestError(next(iter(sorted(counts)), None), cases, f"at most {limit} cases",
                           f"{{name}}: the request holds {cases} cases ({names}), more than the "
                           f"limit of {limit}")
    return cases


def parse(name, given, *, limit=CASE_LIMIT, check=True):
    """Read and check the values of a request for calculation ``name``.

    Parameters
    ----------
    name : str
        A key of :data:`CALCULATIONS` (``high-speed``).
    given : mapping of str to str, int, float or bool
        Field name -> value as the user wrote it (``{"axial_load": "20 kN"}``). A value of None, or
        an empty string, counts as not given.
    limit : int
        The most cases the request may hold.
    check : bool
        Read and check each value against its field (the web). False keeps the values as given: the
        command line, whose options typer has read, and whose calculation checks each value by the
        command line's own rules and bounds (:mod:`bearinglab._bounds`, not the web's lower ones).

    Returns
    -------
    Parsed

    Raises
    ------
    RequestError
        An unknown field, a missing required field, a value that does not parse or lies outside its
        range, or more cases than ``limit``.
    """
    calc = CALCULATIONS[name]
    fields = {f.name: f for f in calc.fields}
    given = {k: v for k, v in given.items() if v is not None and not (isinstance(v, str) and not v.strip())}
    for key in given:
        if key not in fields:
            raise RequestError(key, given[key], ", ".join(fields),
                               f"{{name}}: not an input of {name}; valid: {', '.join(fields)}")
    values = {}
    for f in calc.fields:
        if f.name in given:
            if not check:
                values[f.name] = given[f.name]
                continue
            if f.kind == "document" and len(str(given[f.name])) > DOCUMENT_LIMIT:
                raise RequestError(f.name, "...", f"at most {DOCUMENT_LIMIT} characters",
                                   f"{{name}}: the document is longer than {DOCUMENT_LIMIT} characters")
            if f.many and f.kind == "text":
                items = [s.strip() for s in str(given[f.name]).split(",") if s.strip()]
                if not 1 <= len(items) <= 8:
                    raise RequestError(f.name, given[f.name], "1 ... 8 names",
                                       f"{{name}}: give 1 to 8 names, got {len(items)}")
                values[f.name] = items
            else:
                values[f.name] = parse_field(f, given[f.name], limit=limit)
        elif f.required:
            raise RequestError(f.name, None, f.valid(), f"{{name}}: missing; {f.help}")
    return Parsed(calc, given, values, _cases(calc, values, given, limit) if check else 1)
