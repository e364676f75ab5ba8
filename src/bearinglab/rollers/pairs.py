r"""Two tapered roller bearings on one rigid shaft: back to back or face to face, with end play or preload.

Pair
----
ARRANGEMENTS          ``"back-to-back"`` (O: the load lines open outwards, the wide effective spread) and
                      ``"face-to-face"`` (X)
pair_analysis         the shaft's displacement, each bearing's loads, rollers and laminae, and the pair's 5 x 5
                      stiffness under loads on the shaft, batched over cases
preload_gap           the axial interference that gives a preload (identical bearings)
PairAnalysis          its result

The shaft's reference point is midway between the two bearings' roller middles, which lie ``distance``
apart on the axis. Bearing A sits at +distance/2, bearing B at -distance/2. Each bearing is the slice model
of :mod:`bearinglab.rollers.distribution` in its own frame; a bearing whose cup narrows towards -z is the
mirror image (z, theta_x and theta_y change sign). In the O arrangement A's cup narrows towards -z and B's
towards +z (each pressure centre lies outside its bearing, at (d_m/2) tan(alpha) from the roller middle);
in the X arrangement the other way round. The end play s (the axial play of the shaft, both directions
together) gives each bearing the gap (s/2) sin(alpha) along its cup normal at the centred position; a
negative s is an interference: preload.

The shaft carries the loads (F_x, F_y, F_z, M_x, M_y) at the reference point; the reactions of the two
bearings, moved to that point, balance them:
:math:`F = \sum_i T_i^T S_i F_i(S_i T_i u)` with the shift :math:`T_i` of the bearing's position
(:math:`\delta_x + \theta_y z_i`, :math:`\delta_y - \theta_x z_i`) and the mirror :math:`S_i`.

References
----------
.. [1] T. A. Harris and M. N. Kotzalas, *Advanced Concepts of Bearing Technology*, 5th ed., CRC Press,
   2006, ch. 1 (bearings of a rigid shaft, preloaded pairs).
.. [2] SKF, *General Catalogue* 6000/I RU, 2006, p. 613 (tapered bearings in O and X arrangements; the
   pressure centre a of the bearing tables).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from .._validate import as_float, check_integer, check_positive
from ..errors import ConvergenceError, InputError
from . import contact, distribution
from .analysis import N_SLICES, bearing_roller_set, provenance
from .estimation import with_estimated_geometry

__all__ = ["ARRANGEMENTS", "PairAnalysis", "pair_analysis", "preload_gap"]

#: Arrangements of a tapered pair.
ARRANGEMENTS = ("back-to-back", "face-to-face")
_TOL = distribution.TOL


class PairAnalysis(NamedTuple):
    """A tapered pair under load (SI; at rest)."""

    loads: np.ndarray
    """(..., 5) the loads on the shaft at its reference point. [N, N m]"""
    displacement: np.ndarray
    """(..., 5) of the shaft at its reference point. [m, rad]"""
    stiffness: np.ndarray
    """(..., 5, 5) of the pair at the reference point."""
    bearing_a: distribution.RollerLoadDistribution
    """Bearing A (at +distance/2) in its own frame: its loads, displacement, rollers and laminae."""
    bearing_b: distribution.RollerLoadDistribution
    """Bearing B (at -distance/2) in its own frame."""
    axial_loads: np.ndarray
    """(..., 2) the axial load F_a of A and B (>= 0, along each bearing's own thrust direction). [N]"""
    radial_loads: np.ndarray
    """(..., 2) F_r of A and B. [N]"""
    axial_play: float
    """s: the end play (> 0) or the interference (< 0) the pair was solved with. [m]"""
    effective_spread: float
    """The distance between the pressure centres of the two bearings. [m]"""
    converged: np.ndarray
    """(...) bool."""
    residual: np.ndarray
    """(...) relative equilibrium residual of the shaft. [-]"""
    iterations: np.ndarray
    """(...) Newton iterations."""
    warnings: tuple
    """Messages (estimated roller sets, failures)."""


def _orientations(arrangement):
    if arrangement not in ARRANGEMENTS:
        raise InputError(f"arrangement must be one of {list(ARRANGEMENTS)}, got {arrangement!r}")
    return (-1.0, 1.0) if arrangement == "back-to-back" else (1.0, -1.0)


def _transform(z_pos, orient):
    """(5, 5) matrix of local displacement = M u (shift to z_pos, then mirror if orient < 0)."""
    shift = np.eye(5)
    shift[0, 4] = z_pos  # delta_x + theta_y z
    shift[1, 3] = -z_pos  # delta_y - theta_x z
    return np.diag([1.0, 1.0, orient, orient, orient]) @ shift


def _bearing(b):
    if b.type != "tapered":
        raise InputError(f"pair_analysis takes tapered roller bearings, got a {b.type} one "
                         f"({b.designation or 'bearing'!r}); solve cylindrical bearings in a shaft model "
                         "(bearinglab.reactions)")
    return with_estimated_geometry(b) if not b.has_internal_geometry else b


def _pair_sets(a, b, play, n_slices):
    out = []
    for brg in (a, b):
        gap = 0.5 * play * math.sin(brg.contact_angle)
        out.append(bearing_roller_set(brg, n_slices=n_slices, normal_gap=gap))
    return out


def preload_gap(bearing, preload, *, n_slices=N_SLICES):
    r"""The end play s < 0 (an interference) that gives a pair of identical tapered bearings an axial preload.

    Parameters
    ----------
    bearing : RollerBearing
        One of the two identical bearings (tapered).
    preload : float
        The axial force each bearing carries at zero external load, > 0. [N]
    n_slices : int, optional
        Slices per roller. [-]

    Returns
    -------
    float
        s [m]: with it both bearings carry ``preload`` axially at the centred position.

    Notes
    -----
    Centred, every lamina of a bearing approaches by :math:`-g_0 - 2P(s_k)` with :math:`g_0 = (s/2)\sin\alpha`,
    and the bearing carries :math:`F_a = Z\sin\alpha\sum_k c_s\langle -g_0 - 2P(s_k)\rangle^{10/9}`,
    monotone in s: solved by bisection to 1e-12 of the bracket.

    Examples
    --------
    >>> from bearinglab.rollers.bearing import RollerBearing
    >>> b = RollerBearing("tapered", 17, 10e-3, 14e-3, 60e-3, math.radians(14.0))
    >>> print(f"{preload_gap(b, 2000.0) * 1e6:.3f} um")
    -42.521 um
    """
    p = float(check_positive("preload", preload, "N"))
    b = _bearing(bearing)
    rs = bearing_roller_set(b, n_slices=n_slices, normal_gap=0.0)
    sa = math.sin(rs.contact_angle)

    def axial(gap):
        q, _ = contact.slice_loads(-gap - 2.0 * rs.drop, rs.slice_constant)
        return rs.rollers * sa * float(np.sum(q))

    lo, hi = -0.25 * rs.roller_diameter, 0.0  # gaps: interference ... none
    if axial(lo) < p:
        raise InputError(f"preload {p:g} N needs an interference beyond a quarter roller diameter [N]")
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if axial(mid) > p:
            lo = mid
        else:
            hi = mid
        if hi - lo < 1e-12 * rs.roller_diameter:
            break
    return 2.0 * (0.5 * (lo + hi)) / sa


def pair_analysis(bearing_a, bearing_b, loads, *, distance, arrangement="back-to-back", axial_play=0.0, preload=None,
                  n_slices=N_SLICES, on_failure="raise", tol=_TOL, max_iter=distribution.MAX_ITER):
    r"""A pair of tapered roller bearings on one rigid shaft under loads, batched over cases.

    Parameters
    ----------
    bearing_a, bearing_b : RollerBearing
        Tapered; A at +distance/2, B at -distance/2 (a missing roller set is estimated, with a warning).
    loads : array_like
        (..., 5) F_x, F_y, F_z [N], M_x, M_y [N m] on the shaft at the reference point.
    distance : float
        The axial distance between the roller middles of the two bearings, > 0. [m]
    arrangement : {"back-to-back", "face-to-face"}
        O or X.
    axial_play : float, optional
        The end play s of the adjusted pair, negative for an interference (preload). [m]
    preload : float, optional
        An axial preload force instead of ``axial_play`` (identical bearings only; :func:`preload_gap`). [N]
    n_slices : int, optional
        Slices per roller. [-]
    on_failure : {"raise", "flag"}, optional
        Raise :class:`~bearinglab.errors.ConvergenceError` for a case without equilibrium, or flag it.
    tol : float, optional
        Relative equilibrium residual. [-]
    max_iter : int, optional
        Newton iterations per case.

    Returns
    -------
    PairAnalysis

    Notes
    -----
    Each bearing carries its laminae's loads (module docstring of :mod:`bearinglab.rollers.distribution`);
    the shaft's equilibrium and stiffness are the sum of the two, moved to the reference point (module
    docstring). A pair with end play holds a thrust on one bearing and a radial load on both.

    Examples
    --------
    >>> from bearinglab.rollers.bearing import RollerBearing
    >>> b = RollerBearing("tapered", 17, 10e-3, 14e-3, 60e-3, math.radians(14.0))
    >>> r = pair_analysis(b, b, [5e3, 0, 2e3, 0, 0], distance=0.1)
    >>> print(np.round(r.axial_loads), f"{r.effective_spread * 1e3:.1f} mm")
    [ 681. 2681.] 115.0 mm
    """
    sign_a, sign_b = _orientations(arrangement)
    dist = float(check_positive("distance", distance, "m"))
    a, b = _bearing(bearing_a), _bearing(bearing_b)
    if preload is not None:
        if axial_play != 0.0:
            raise InputError("preload: give axial_play or preload, not both")
        if a != b:
            raise InputError("preload: a preload force needs two identical bearings; give axial_play (negative: "
                             "an interference) for different ones")
        play = preload_gap(a, preload, n_slices=n_slices)
    else:
        play = float(as_float("axial_play", axial_play))
    n_slices = int(check_integer("n_slices", n_slices, 1))
    sets = _pair_sets(a, b, play, n_slices)
    kernels = [distribution._kernel(rs) for rs in sets]
    mats = [_transform(0.5 * dist, sign_a), _transform(-0.5 * dist, sign_b)]
    f = as_float("loads", loads)
    if f.shape[-1:] != (5,) or not np.all(np.isfinite(f)):
        raise InputError(f"loads must be finite with a last axis of length 5 (F_x, F_y, F_z, M_x, M_y), got shape {f.shape}")
    shape = f.shape[:-1]
    flat = np.ascontiguousarray(f.reshape(-1, 5))

    def evaluate(u):
        force = np.zeros_like(u)
        stiff = np.zeros((len(u), 5, 5))
        total = np.zeros(len(u))
        noise = np.zeros(len(u))
        for kn, m in zip(kernels, mats, strict=True):
            fl, kl, _, roller, nz = distribution._evaluate(kn, u @ m.T)
            force += fl @ m
            stiff += np.einsum("ji,njk,kl->nil", m, kl, m)
            total += np.sum(roller, axis=-1)
            noise += nz
        return force, stiff, total, noise

    dm = max(rs.pitch_diameter for rs in sets)
    arm = np.array([1.0, 1.0, 1.0, 2.0 / dm, 2.0 / dm])
    limit = 0.1 * min(rs.roller_diameter for rs in sets)
    span = 0.5 * dist + dm
    u0 = np.zeros_like(flat)
    u0[:, 2] = 0.0
    free = np.ones_like(flat)
    u = np.empty_like(flat)
    ok = np.empty(len(flat), dtype=bool)
    it = np.empty(len(flat), dtype=int)
    rel = np.empty(len(flat))
    chunk = distribution._CHUNK
    with distribution._one_blas_thread(len(flat)):
        for lo in range(0, len(flat), chunk):
            sl = slice(lo, min(len(flat), lo + chunk))
            u[sl], ok[sl], it[sl], rel[sl] = distribution._newton(evaluate, arm, flat[sl], u0[sl], free[sl], tol,
                                                                  max_iter, limit, span,
                                                                  sum(kn.resolution for kn in kernels))
    warns = [*provenance(a), *(provenance(b) if b != a else [])]
    if not ok.all():
        k = int(np.flatnonzero(~ok)[0])
        if on_failure == "raise":
            raise ConvergenceError("rollers.pair_analysis", iterations=int(it[k]), residual=rel[k], estimate=u[k],
                                   reason=f"loads {flat[k].tolist()}: the shaft's Newton iteration stalled "
                                          f"({int((~ok).sum())} of {ok.size} cases failed)")
        warns.append(f"{int((~ok).sum())} case(s) not converged (NaN, converged False; first: case {k})")
    _, stiff, _, _ = evaluate(u)
    results, axial, radial = [], [], []
    for rs, kn, m in zip(sets, kernels, mats, strict=True):
        ul = u @ m.T
        fl, kl, q, roller, _ = distribution._evaluate(kn, np.nan_to_num(ul), slices=True)
        none = np.full_like(fl, np.nan)
        results.append(distribution._result(rs, fl, ul, q, roller, kl, np.zeros(len(fl)), ok, it, rel, shape, (),
                                            none))
        axial.append(fl[:, 2])
        radial.append(np.hypot(fl[:, 0], fl[:, 1]))

    def out(x, tail):
        x = np.array(x, dtype=float, copy=True)
        x[~ok] = np.nan
        return x.reshape(shape + tail)[()]

    centres = [0.5 * dist - sign_a * 0.5 * sets[0].pitch_diameter * math.tan(sets[0].contact_angle),
               -0.5 * dist - sign_b * 0.5 * sets[1].pitch_diameter * math.tan(sets[1].contact_angle)]
    return PairAnalysis(out(flat, (5,)), out(u, (5,)), out(stiff, (5, 5)), results[0], results[1],
                        out(np.stack(axial, axis=-1), (2,)), out(np.stack(radial, axis=-1), (2,)), play,
                        abs(centres[0] - centres[1]), ok.reshape(shape)[()], out(rel, ()), it.reshape(shape)[()],
                        tuple(dict.fromkeys(warns)))
