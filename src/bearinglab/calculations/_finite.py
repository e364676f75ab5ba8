"""Every result finite or an error: the check of a calculation's document before any boundary shows it.

A number that overflowed (``clearance --housing-outside-diameter "1e308 mm"``: the Lamé factors of a
housing 10^305 m wide) is no result. Printed, it crashed a table; as JSON it became ``null`` with exit 0,
where the document promises a number. Each calculation's document function (and the ``compute`` whose
result the command line prints) is wrapped by :func:`finite`, so that the command line, the web and the
Python API see the same error whichever boundary asks.

A few values are not numbers by design, and are documented so (``null`` in the JSON): an unbounded life
at zero load, a film at an unloaded contact, the temperature of a thermal runaway, the fields of a case
that did not converge (with its status), a frequency at rest. Those keys are named per calculation in
:data:`NULLABLE`; any other non-finite number raises :class:`NonFiniteResult`, naming the key.

finite            decorator: the wrapped function's document (or result's ``.document``) checked finite
check             a document -> itself, or NonFiniteResult naming the first key that is not finite
NonFiniteResult   the error (a ConvergenceError: exit 3 on the command line, 422 on the web)
NULLABLE          calculation -> the keys whose null is documented
"""

from __future__ import annotations

import contextvars
import functools
import math
import re

from ..errors import ConvergenceError

__all__: list[str] = []  # private to the calculations

#: calculation -> key names (the last key of a path; ``[]`` stands for a list index) whose value may be
#: NaN or infinite by design, as the user guide documents them (null in the JSON)
NULLABLE = {
    # ISO 281 defines no P under a moment, no life at P = 0, no a_ISO without a lubricant; no reference life
    # where the load distribution found no equilibrium (docs/user_guide/life.md)
    "life": ("equivalent_dynamic_load_N", "basic_rating_life_Mrev", "basic_rating_life_h",
             "life_modification_factor", "modified_rating_life_Mrev", "modified_rating_life_h",
             "reference_rating_life_Mrev", "modified_reference_rating_life_Mrev", "static_safety_factor",
             "viscosity_mm2_s", "viscosity_ratio"),
    # an unloaded ball has no film (docs/user_guide/film.md)
    "film": ("film_central_inner_um", "film_min_inner_um", "film_central_outer_um", "film_min_outer_um",
             "lambda_inner", "lambda_outer"),
}


class NonFiniteResult(ConvergenceError):
    """A result that is not a finite number where the document promises one.

    A :class:`~bearinglab.errors.ConvergenceError` that is not ``physical``: the command line exits
    with 3 and the web answers 422 (``"error": "convergence"``), as for a solve that failed.
    """

    def __init__(self, calculation, path, value):
        self.calculation, self.path, self.value = calculation, path, value
        message = (f"{calculation}: the result {path} is {_word(value)}: the computation overflowed (an input "
                   "far outside the model's range?); check the values and units given")
        RuntimeError.__init__(self, message)
        self.where, self.iterations, self.residual, self.estimate = calculation, 0, value, None
        self.reason, self.physical, self.summary = message, False, message


def _word(value):
    return "NaN (not a number)" if math.isnan(value) else "infinite"


def check(doc, calculation, nullable=(), nulled=()):
    """``doc``, when every number in it is finite (but at the keys ``nullable``); else NonFiniteResult.

    Parameters
    ----------
    doc : dict or list
        A calculation's document (numpy arrays and scalars are looked into).
    calculation : str
        Its name, for the message.
    nullable : iterable of str
        Key names whose value may be NaN or infinite by design (documented as null).
    nulled : iterable of (str, float)
        The paths and values of the numbers already written as null on the way
        (:data:`bearinglab._io.NULLED`).

    Returns
    -------
    dict or list
        ``doc``.
    """
    nullable = set(nullable)
    for path, value, parent in [*nulled, *_nonfinite_all(doc)]:
        if _key(path) in nullable or _failed_case(parent):
            continue
        raise NonFiniteResult(calculation, path or "(the document)", value)
    return doc


def _failed_case(parent):
    """Whether the dict holding a value is a case that says it has no solution (``converged: false``,
    ``steady: false`` of a thermal runaway): its nulls are documented by its status."""
    if not isinstance(parent, dict):
        return False
    return any(key in parent and parent[key] is not None and not bool(parent[key])
               for key in ("converged", "steady"))


def _key(path):
    """The last key of a path: 'cases[3].film_um[0]' -> 'film_um'; '' for none."""
    keys = re.findall(r"([^.\[\]]+)(?:\[\d+\])*$", path)
    return keys[0] if keys else ""


def _nonfinite_all(doc):
    """Every (path, value, the dict holding it) of ``doc`` that is a float (or numpy float) not finite."""
    out, stack = [], [("", doc, None)]
    while stack:
        where, node, parent = stack.pop()
        if isinstance(node, dict):
            stack.extend((f"{where}.{k}" if where else str(k), v, node) for k, v in node.items())
        elif isinstance(node, (list, tuple)):
            stack.extend((f"{where}[{i}]", v, parent) for i, v in enumerate(node))
        elif hasattr(node, "dtype") and hasattr(node, "shape"):  # a numpy array or scalar
            import numpy as np

            if node.dtype.kind in "fc":
                for i in np.flatnonzero(~np.isfinite(np.ravel(node))):
                    out.append((f"{where}[{int(i)}]" if np.ndim(node) else where, float(np.ravel(node)[i].real),
                                parent))
            elif node.dtype.kind == "O":
                stack.extend((f"{where}[{i}]", v, parent) for i, v in enumerate(np.ravel(node)))
        elif isinstance(node, float) and not math.isfinite(node):
            out.append((where, node, parent))
    return sorted(out, key=lambda found: _order(found[0]))


def _order(path):
    """A path's sort key: the document's order (indices as numbers)."""
    return [int(p) if p.isdigit() else p for p in re.findall(r"[^.\[\]]+", path)]


_DEPTH = contextvars.ContextVar("bearinglab_finite_depth", default=0)


def finite(calculation=None):
    """Decorator: the document the function returns (a dict or list; or the ``.document`` of a result
    tuple; or the first item of a tuple) is checked by :func:`check` with :data:`NULLABLE` of
    ``calculation`` (None: the calculation of the function's first argument, a Parsed request), and so
    are the numbers the function wrote as null on the way (:data:`bearinglab._io.NULLED`). Nested
    wrapped calls (``document`` calling ``compute``) are checked once, by the outermost."""

    def wrap(function):
        @functools.wraps(function)
        def checked(*args, **kwargs):
            from .._io import NULLED

            outermost = _DEPTH.get() == 0
            token = _DEPTH.set(_DEPTH.get() + 1)
            nulled = [] if outermost else None
            recording = NULLED.set(nulled) if outermost else None
            try:
                result = function(*args, **kwargs)
            finally:
                _DEPTH.reset(token)
                if recording is not None:
                    NULLED.reset(recording)
            if outermost:
                doc = getattr(result, "document", None)
                if doc is None:
                    doc = result[0] if isinstance(result, tuple) else result
                name = calculation
                if name is None:  # one function for several calculations (axial-angle, stand-load)
                    name = args[0].calculation.name
                check(doc, name, NULLABLE.get(name, ()), nulled)
            return result

        return checked

    return wrap
