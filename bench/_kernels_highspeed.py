r"""The high-speed thrust model (spec 004) for one case at a time: the fair scalar baseline.

One case is solved from rest: its static start, the Newton solve with continuation in speed, and its full
state (loads, dynamics, speeds, pressures, stiffness, friction), as the compiled path does per case.

Not part of the library. The per-case algorithm ships in the library as the compiled fast path of
:func:`bearinglab.quasistatic.contact_angles` (``engine="compiled"``, :mod:`bearinglab.quasistatic._compiled`):
the same equations and the same solver as the batched path, written in scalar form (``math``, tuples).
Run by CPython, with every helper uncompiled, it is the fair scalar baseline of bench/high_speed.py;
the compiled limit there is the library's own compiled path.

Functions
---------
bearing_parameters   the per-case constants and Hertz tables of one bearing, from the library's own set-up
solver               ``solve(fa, w) -> (alpha_s, v, status, iterations, state)`` in plain Python
"""

from __future__ import annotations

import math

from bearinglab import _solve, quasistatic
from bearinglab.quasistatic import _compiled

__all__ = ["bearing_parameters", "solver"]


def bearing_parameters(geometry_args, *, raceway_control="outer", gyroscopic_sign=1, constants="harris"):
    """(par, tables): the 14 constants of one bearing, and its 8 Chebyshev series (ln K, d ln K, ln a*, ln b*)."""
    model, _ = quasistatic._prepare(1.0, *geometry_args, raceway_control, gyroscopic_sign, constants)
    par, _gid, tables = _compiled.case_parameters(model)
    return par[0], [t[0] for t in tables]


def solver(par, tables, *, tol=_solve.QUASISTATIC_TOL, max_iter=_solve.QUASISTATIC_MAX_ITER):
    """``solve(fa, w) -> (alpha_s, v, status, iterations, state)``, one case from rest, plain Python.

    The same work as the compiled path per case: the static start (alpha_s), the Newton solve with
    continuation, and the full state of a converged case (``state``, the outputs ``_compiled.OUTPUTS``,
    NaN if the case failed).
    """
    p = [float(x) for x in par]
    t = [[float(x) for x in c] for c in tables]
    one = _compiled.plain_solver()

    def solve(fa, w):
        return one(fa, w, p, *t, tol, max_iter, math.inf, [0.0] * 35)

    return solve
