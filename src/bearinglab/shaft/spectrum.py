r"""Load spectra of a shaft system: a duty cycle of load cases solved as one batch, lives by Palmgren-Miner.

Functions
---------
SpectrumLife     each bearing's and the system's lives over the spectrum, and each case's results
load_spectrum    the cases on the executor (serial, local, dask: the same bits), then the lives
case_results     one chunk of cases: the function the executor runs

A case k runs at speed n_k with its loads scaled by a factor, for a share t_k of the time. Each bearing's
life at each case (:func:`bearinglab.life.rating_life`, the ball loads of the system's solution for the
reference life) combine by Palmgren and Miner with the revolution shares u_k = t_k n_k / sum t n
(:func:`bearinglab.life.miner_life`); the system's life combines the bearings' (:mod:`bearinglab.life.
system`). Lives in hours divide by the mean speed sum t n. A case at standstill turns no revolutions
and uses no life.
"""

from __future__ import annotations

import types
import warnings
from typing import NamedTuple

import numpy as np

from .. import parallel
from ..errors import InputError

__all__ = ["SpectrumLife", "case_results", "load_spectrum"]

_LIVES = ("basic_rating_life", "modified_rating_life", "reference_rating_life", "modified_reference_rating_life")


def case_results(speed, factor, *, system, life_options, tol, max_iter):
    """Solve one chunk of load cases and the lives of every bearing in each (the executor's task).

    Parameters
    ----------
    speed, factor : ndarray
        (n,) the chunk's speeds [rad/s] and load factors [-].
    system : ShaftSystem
    life_options : dict
        For :func:`bearinglab.life.rating_life`.
    tol : float
    max_iter : int

    Returns
    -------
    dict of str to ndarray
        ``converged`` (n,), ``residual`` (n,), ``row_force`` and ``row_displacement`` (n, rows, 5),
        ``support_loads`` (n, supports, 6) and each life of :data:`_LIVES` (n, rows) in revolutions
        (inf at standstill; NaN where a life is not defined).
    """
    from ..life import rating_life
    from .outputs import bearing_states
    from .statics import Cases, solve

    state = solve(system, Cases(np.asarray(speed, dtype=float), np.asarray(factor, dtype=float), None),
                  on_failure="flag", tol=tol, max_iter=max_iter)
    n, rows = len(speed), len(state.assembly.rows)
    out = {"converged": state.converged, "residual": state.residual, "row_force": state.row_force,
           "row_displacement": state.row_displacement, "support_loads": state.support_loads}
    states = bearing_states(state, life=False)
    w = np.abs(np.asarray(speed, dtype=float))
    moving = w > 0
    for key in _LIVES:
        out[key] = np.full((n, rows), np.inf)
    for j, bs in enumerate(states):
        if not moving.any():
            continue
        ok = moving & state.converged
        iso = np.where(ok[:, None], bs.loads, 0.0).copy()
        iso[:, 3:] = 0.0
        ld = bs.load_distribution
        balls = False if ld is None else types.SimpleNamespace(
            ball_load_inner=np.where(ok[:, None], ld.ball_load_inner, 0.0),
            ball_load_outer=np.where(ok[:, None], ld.ball_load_outer, 0.0))
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            lf = rating_life(bs.bearing, iso, np.where(moving, w, 1.0), load_distribution=balls, **life_options)
        for key in _LIVES:
            v = getattr(lf, key)
            if v is None:  # not computed (no lubricant): NaN where the case turns, as in any chunk
                out[key][:, j] = np.where(moving, np.nan, np.inf)
            else:
                out[key][:, j] = np.where(ok, np.broadcast_to(v, (n,)), np.where(moving, np.nan, np.inf))
    return out


class SpectrumLife(NamedTuple):
    """Lives over a load spectrum (revolutions and hours)."""

    names: tuple
    """The bearings (a set's bearings one by one)."""
    time_share: np.ndarray
    """(k,) [-]"""
    speed: np.ndarray
    """(k,) [rad/s]"""
    factor: np.ndarray
    """(k,) [-]"""
    revolution_share: np.ndarray
    """(k,) u_k. [-]"""
    mean_speed: float
    """sum t_k abs(n_k). [rad/s]"""
    bearing_life: dict
    """Life name -> (rows,) each bearing's Palmgren-Miner life. [revolutions]"""
    system_life: dict
    """Life name -> the system's life. [revolutions]"""
    cases: dict
    """Each case's results (:func:`case_results`)."""

    def hours(self, revolutions):
        """A life in revolutions as hours at the mean speed."""
        return np.asarray(revolutions) / (self.mean_speed / (2 * np.pi)) / 3600.0


def load_spectrum(system, speeds, factors, time_shares, *, execution=None, tol=None, max_iter=None,
                  **life_options):
    r"""Solve a duty cycle of a shaft system as one batch and combine the lives by Palmgren-Miner.

    Parameters
    ----------
    system : ShaftSystem
    speeds : array_like
        (k,) signed speed of each case. [rad/s]
    factors : array_like
        (k,) factor on the loads, gears and pulleys of each case. [-]
    time_shares : array_like
        (k,) share of the time of each case, >= 0, summing to 1. [-]
    execution : bearinglab.parallel.Execution, optional
        Where and in which chunks the cases run (the results are the same bits on any executor).
    tol, max_iter : optional
        Of :func:`bearinglab.shaft.solve`.
    **life_options
        ``kinematic_viscosity`` or the oil, ``contamination``, ``reliability``
        (:func:`bearinglab.life.rating_life`).

    Returns
    -------
    SpectrumLife

    Raises
    ------
    InputError
        Inputs of different lengths, shares that do not sum to 1, a spectrum that turns no revolution.
    ConvergenceError
        A case without equilibrium.
    """
    from ..errors import ConvergenceError
    from ..life import miner_life, system_life, weibull_slope
    from .statics import MAX_ITER, TOL, assemble

    w = np.atleast_1d(np.asarray(speeds, dtype=float))
    f = np.atleast_1d(np.asarray(factors, dtype=float))
    t = np.atleast_1d(np.asarray(time_shares, dtype=float))
    if not (w.ndim == f.ndim == t.ndim == 1 and w.shape == f.shape == t.shape and w.size):
        raise InputError(f"speeds, factors and time_shares must be lists of one length, got {w.shape}, {f.shape}, "
                         f"{t.shape}")
    if np.any(~np.isfinite(w)) or np.any(~np.isfinite(f)) or np.any(~(t >= 0)):
        raise InputError("speeds and factors must be finite and time_shares >= 0")
    if not np.isclose(t.sum(), 1.0, rtol=0, atol=1e-9):
        raise InputError(f"time_shares must sum to 1 [-], got {float(t.sum())!r}")
    mean = float(np.sum(t * np.abs(w)))
    if not mean > 0:
        raise InputError("speeds: the spectrum turns no revolution (every case at standstill or of no time)")
    rows = assemble(system).rows
    out = parallel.run_cases(case_results, {"speed": w, "factor": f},
                             constants={"system": system, "life_options": dict(life_options),
                                        "tol": TOL if tol is None else tol,
                                        "max_iter": MAX_ITER if max_iter is None else max_iter},
                             execution=execution)
    if not np.all(out["converged"]):
        k = int(np.flatnonzero(~out["converged"])[0])
        raise ConvergenceError("shaft.load_spectrum", iterations=0, residual=float(out["residual"][k]),
                               estimate=None, reason=f"case {k} of the spectrum did not converge")
    u = t * np.abs(w) / np.sum(t * np.abs(w))
    slopes = np.array([weibull_slope(r.bearing) for r in rows])
    per, system_lives = {}, {}
    for key in _LIVES:
        lives = out[key]  # (k, rows)
        if np.all(np.isnan(lives[u > 0])):
            per[key], system_lives[key] = None, None
            continue
        comb = np.array([miner_life(lives[:, j], u) for j in range(len(rows))])
        per[key] = comb
        system_lives[key] = float(system_life(comb, slopes))
    return SpectrumLife(tuple(r.name for r in rows), t, w, f, u, mean, per, system_lives, out)
