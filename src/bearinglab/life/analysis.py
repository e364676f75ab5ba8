r"""Rating life of a ball bearing: the ISO 281 and ISO/TS 16281 analysis of a BallBearing, and duty cycles.

Ratings of a bearing
--------------------
reference_load_distribution   the ball loads of the ISO/TS 16281 reference life (combined-load model at rest)

Analysis
--------
rating_life            every life quantity for loads (Fx, Fy, Fz, Mx, My), speed, lubricant, cleanliness
                       and reliability, batched over load cases (a RollerBearing: :mod:`bearinglab.life.roller`)
duty_cycle_life        the combined life of a duty cycle (Palmgren-Miner)
miner_life             Palmgren-Miner combination of lives at given revolution shares

The analysis composes the functions of :mod:`~bearinglab.ratings.static`,
:mod:`~bearinglab.ratings.dynamic`, :mod:`~bearinglab.ratings.lubrication` and
:mod:`~bearinglab.ratings.reference`, so each number it reports can be had from them. SI throughout:
N, N m, rad/s, m^2/s, K; lives in revolutions and their durations in seconds.
"""

from __future__ import annotations

import warnings
from typing import NamedTuple

import numpy as np

from .._bounds import check_steps
from .._validate import as_float, check_nonnegative, check_positive
from ..bearing import covers
from ..errors import InputError
from ..ratings import dynamic, lubrication, reference, static
from ..ratings.bearing import _conformities, bearing_ratings
from ..ratings.static import RatingWarning
from ._common import RatingLife, _contamination, _result, _untilted, _viscosity

RatingLife.__module__ = __name__  # documented and reached here, as before the roller analysis shared it

__all__ = [
    "DutyCycleLife",
    "RatingLife",
    "duty_cycle_life",
    "miner_life",
    "rating_life",
    "reference_load_distribution",
]


def _split_loads(loads):
    f = np.asarray(loads, dtype=float)
    if f.ndim == 0 or f.shape[-1] != 5:
        raise InputError(f"loads must have the five components (Fx, Fy, Fz, Mx, My) on their last axis "
                         f"[N, N, N, N m, N m], got shape {np.shape(loads)}")
    bad = ~np.isfinite(f)
    if bad.any():
        raise InputError(f"loads must be finite [N, N m], got {float(f[bad].flat[0])!r}")
    return np.hypot(f[..., 0], f[..., 1]), np.abs(f[..., 2]), np.hypot(f[..., 3], f[..., 4])


_GEOMETRY_FIELDS = ("n_balls", "ball_diameter", "pitch_diameter", "inner_conformity", "outer_conformity")


def reference_load_distribution(bearing, loads, *, on_failure="raise"):
    """The load distribution of the ISO/TS 16281 reference life, as :func:`rating_life` uses by default.

    Parameters
    ----------
    bearing : BallBearing
        Needs its ball set and both conformities.
    loads : array_like
        (..., 5): Fx, Fy, Fz, Mx, My on the rotating ring. [N, N, N, N m, N m]
    on_failure : {"raise", "flag"}, optional
        A case without equilibrium raises :class:`~bearinglab.errors.ConvergenceError`, or is flagged
        (NaN ball loads, ``converged`` False, the reason in ``warnings``); :func:`rating_life` then gives
        NaN reference lives for it.

    Returns
    -------
    LoadDistribution or None
        :func:`bearinglab.quasistatic.combined.combined_analysis` at rest, with the Hertz constants at
        the free contact angle (ISO/TS 16281:2008); None when the bearing's ball set or
        conformities are not known, or the load distribution does not cover its type
        (:data:`bearinglab.bearing.MODEL_TYPES`), or a field its type's model needs is missing (a
        four-point bearing's clearance, a double-row bearing's row distance: :func:`_missing`).
    """
    from ..quasistatic import combined  # the life does not need the quasi-static package to import

    if _missing(bearing) is not None:
        return None
    return combined.combined_analysis(bearing, loads, 0.0, stiffness_at="free", on_failure=on_failure)


def _missing(bearing):
    """Why the combined-load model cannot solve ``bearing`` (a missing field, one line), or None."""
    if any(getattr(bearing, k) is None for k in _GEOMETRY_FIELDS):
        return "the bearing's ball set and conformities are not known"
    if not covers(bearing, "load-distribution"):
        return f"the combined-load model does not cover a {bearing.type} bearing yet"
    if bearing.type not in ("radial", "angular"):
        from ..quasistatic import _types

        try:
            _types.bearing_options(bearing)
        except InputError as exc:
            return str(exc).split(";")[0]
    return None


def _combined_at_rest(bearing, loads, shaft_speed):
    """The default ``load_distribution`` callable of :func:`rating_life` (the speed is not used)."""
    return reference_load_distribution(bearing, loads)


def _nominal_angle(bearing):
    """alpha0 of ISO/TS 16281's contact ratings: 0 for a deep-groove bearing (its angle from the clearance is
    not a nominal angle; MASTA's reference lives with clearance imply 0), else the bearing's angle."""
    return 0.0 if bearing.type in ("radial", "double-row-radial") else (bearing.contact_angle or 0.0)


def _reference_life(bearing, r, qi, qo, rows, rotating):
    """L10r of the ball loads (..., Z) of one row, or of the rows of the other types (``rows``: the row of
    each entry, :class:`~bearinglab.quasistatic.combined.LoadDistribution`'s ``row``): each row (a
    four-point bearing's diagonal: its two raceways with the bearing's C, i = 1) by ISO/TS 16281 with the
    bearing's i in Q_c, the rows in series (:func:`bearinglab.ratings.reference.rows_rating_life`)."""
    fi, fo = _conformities(bearing)
    d, dm = bearing.require("ball_diameter"), bearing.require("pitch_diameter")
    kw = {"rotating": rotating, "thrust": bearing.type == "thrust",
          "n_rows": 1 if bearing.type == "four-point" else bearing.rows}
    with np.errstate(divide="ignore"):
        if rows is None or np.max(rows) == 0:
            return reference.reference_rating_life(qi, r.dynamic_load_rating, d, dm, fi, fo, _nominal_angle(bearing),
                                                   outer_contact_loads=qo, **kw)
        lives = [reference.reference_rating_life(qi[..., rows == k], r.dynamic_load_rating, d, dm, fi, fo,
                                                 _nominal_angle(bearing), outer_contact_loads=qo[..., rows == k], **kw)
                 for k in range(int(np.max(rows)) + 1)]
    return reference.rows_rating_life(np.stack(lives, axis=-1))


def _contact_loads(load_distribution, bearing, loads, shaft_speed):
    """(inner, outer) ball loads from a load-distribution callable, result or array; None if not given.

    ``None`` means the combined-load model when the bearing has the geometry it needs; ``False`` none.
    """
    if load_distribution is None and _missing(bearing) is None:
        load_distribution = _combined_at_rest
    if load_distribution is None or load_distribution is False:
        return None
    result = load_distribution(bearing, loads, shaft_speed) if callable(load_distribution) else load_distribution
    rows = getattr(result, "row", None)  # the rows of the other types' entries (None: one row)
    for inner, outer in (("ball_load_inner", "ball_load_outer"), ("contact_loads", "contact_loads")):
        if hasattr(result, inner):
            return (np.asarray(getattr(result, inner), dtype=float), np.asarray(getattr(result, outer), dtype=float),
                    rows)
    q = np.asarray(result, dtype=float)
    return q, q, None


def _iso281(bearing, ratings, fr, fa, moment):
    """P and P0 of ISO 281 / ISO 76, NaN where a moment acts (not defined there)."""
    kind, alpha = bearing.type, bearing.contact_angle if bearing.contact_angle is not None else 0.0
    deep_groove = kind in ("radial", "double-row-radial")
    if (fa > 0).any() and deep_groove and not np.isfinite(ratings.static_load_factor):
        raise InputError(f"the axial factor Y of a deep-groove bearing needs f0 Fa / C0 (ISO 281 table 3), "
                         f"and f0 needs the ball set of {bearing.designation or 'this bearing'!r} (or the "
                         f"maker's f0 in its catalog entry)")
    f0 = ratings.static_load_factor if deep_groove else None
    p = dynamic.equivalent_dynamic_load(fr, fa, ratings.static_load_rating, alpha, bearing_type=kind,
                                        static_load_factor=f0 if f0 is None or np.isfinite(f0) else 1.0)
    p0 = static.static_equivalent_load(fr, fa, alpha, bearing_type=kind)
    return _untilted(p, p0, moment)


def rating_life(bearing, loads, shaft_speed, *, kinematic_viscosity=None, contamination=1.0, reliability=0.9,
                ep_additives=False, load_distribution=None, rotating="inner", fatigue_method="precise",
                **lubricant):
    r"""ISO 281 and ISO/TS 16281 life of a ball bearing for a batch of load cases.

    Parameters
    ----------
    bearing : BallBearing or RollerBearing
        The bearing; catalog ratings take precedence over the geometry (see :func:`bearing_ratings`). A
        :class:`~bearinglab.rollers.bearing.RollerBearing` goes to :func:`bearinglab.life.roller.roller_rating_life`
        (the roller formulas, the slice model's reference life).
    loads : array_like
        (..., 5): Fx, Fy, Fz (axial), Mx, My on the rotating ring. [N, N, N, N m, N m]
    shaft_speed : array_like
        Speed of the rotating ring, > 0, broadcast against the load cases. [rad/s]
    kinematic_viscosity : array_like, optional
        nu at the operating temperature (or give the oil through ``lubricant``). Without either, the
        lubrication-dependent results (kappa, a_ISO, L_nm and its duration, L_nmr) are None, not NaN:
        they are not computed, while P, L10, L10r and s0 are. [m^2/s]
    contamination : float or str
        e_C in [0, 1], or a cleanliness class of ISO 281 table 13 (mid-range value). [-]
    reliability : float
        0.90 to 0.9995 (a fraction). [-]
    ep_additives : bool
        Apply the EP-additive rule of ISO 281 clause 9.3.3.
    load_distribution : callable, result, array_like or False, optional
        Per-ball loads for ISO/TS 16281: a callable ``f(bearing, loads, shaft_speed)`` or its result,
        with ``ball_load_inner`` / ``ball_load_outer`` or ``contact_loads`` (..., Z) attributes, or the
        array of ball loads itself. [N] By default (None) the combined-load model at rest,
        :func:`bearinglab.quasistatic.combined.combined_analysis` with the Hertz constants at the free
        contact angle (ISO/TS 16281), when the bearing has its ball set and both conformities; ``False``
        (or a bearing without them) leaves the reference lives NaN; the warning says so.
    rotating : {"inner", "outer"}
        Ring rotating relative to the load (ISO/TS 16281 equivalent loads).
    fatigue_method : {"precise", "simplified"}
        Cu from the geometry or C0/22 (when the catalog has no Cu).
    **lubricant : optional
        ``temperature`` [K] with ``iso_vg`` or ``viscosity_40`` [m^2/s], and ``viscosity_100`` [m^2/s] or
        ``viscosity_index`` [-] (:func:`.lubrication.kinematic_viscosity`; neither: VI 95).

    Returns
    -------
    RatingLife

    Notes
    -----
    ISO 281:2007: :math:`L_{10} = (C/P)^3` (eq. (15)), :math:`L_{nm} = a_1 a_{ISO} L_{10}` (eq. (16));
    kappa with nu1 of eqs. (14)-(15) at the bearing's mean diameter d_m = (d + D)/2 (ISO 281 fig. 7, and
    SKF's d_m), or at the pitch diameter where bore and outside diameter are not known.
    ISO/TS 16281:2008: L10r from the ball loads (the contact ratings at the nominal angle, 0 for a
    deep-groove bearing whatever its clearance), and the modified reference life with a_ISO evaluated
    at the equivalent reference load :math:`P_{ref} = C L_{10r}^{-1/3}` (L10r in 10^6 revolutions).
    The warnings are both raised (:class:`RatingWarning`) and returned.

    Examples
    --------
    >>> from bearinglab.bearing import BallBearing
    >>> b = BallBearing(9, 7.94e-3, 39.04e-3, 0.52, 0.53, contact_angle=0.0, type="radial")
    >>> r = rating_life(b, [1000.0, 0, 0, 0, 0], 3000 * np.pi / 30, kinematic_viscosity=20e-6)
    >>> print(f"L10 = {r.basic_rating_life / 1e6:.0f} Mrev = {r.basic_rating_life_duration / 3600:.0f} h")
    L10 = 2758 Mrev = 15320 h
    """
    if hasattr(bearing, "roller_diameter"):  # a RollerBearing: the roller formulas (issue 32)
        from .roller import roller_rating_life

        return roller_rating_life(bearing, loads, shaft_speed, kinematic_viscosity=kinematic_viscosity,
                                  contamination=contamination, reliability=reliability, ep_additives=ep_additives,
                                  load_distribution=load_distribution, rotating=rotating, **lubricant)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        out = _rating_life(bearing, loads, shaft_speed, kinematic_viscosity, contamination, reliability,
                           ep_additives, load_distribution, rotating, fatigue_method, lubricant)
    messages = tuple(dict.fromkeys(str(w.message) for w in caught))
    for w in caught:
        warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
    return out._replace(warnings=messages)


def _rating_life(bearing, loads, shaft_speed, nu, contamination, reliability, ep_additives, load_distribution,
                 rotating, fatigue_method, lubricant):
    r = bearing_ratings(bearing, fatigue_method=fatigue_method)
    fr, fa, moment = _split_loads(loads)
    n = check_positive("shaft_speed", shaft_speed, "rad/s")
    nu = _viscosity(nu, dict(lubricant))
    pitch = bearing.pitch_diameter if bearing.pitch_diameter is not None else bearing.mean_diameter
    if bearing.bore is not None and bearing.outside_diameter is not None:
        dm, dm_source = bearing.mean_diameter, "mean diameter (d + D)/2"  # ISO 281 fig. 7, SKF's d_m
    else:
        dm, dm_source = bearing.require("pitch_diameter"), "pitch diameter"
    a1 = float(dynamic.reliability_factor(reliability))
    ec = _contamination(contamination, pitch)
    nu1 = lubrication.rated_viscosity(n, dm)
    kappa = None if nu is None else lubrication.viscosity_ratio(nu, n, dm)
    p, p0 = _iso281(bearing, r, fr, fa, moment)
    p_safe = np.where(np.isfinite(p) & (p > 0), p, 1.0)
    l10 = np.where(np.isfinite(p), dynamic.basic_rating_life(r.dynamic_load_rating, np.where(np.isfinite(p), p, 0.0)),
                   np.nan)
    a_iso = None if nu is None else np.where(np.isfinite(p), lubrication.life_modification_factor(
        kappa, ec, r.fatigue_load_limit, p_safe, ep_additives=ep_additives), np.nan)
    if a_iso is not None and bearing.type == "thrust":
        # ISO 281 gives a_ISO of thrust ball bearings by an equation of their own, which is not in bearinglab
        warnings.warn("a_ISO of a thrust ball bearing: ISO 281 has an equation of its own for thrust ball bearings, "
                      "which bearinglab does not implement; a_ISO and the modified lives are not given",
                      RatingWarning, stacklevel=3)
        a_iso = np.full(np.shape(a_iso), np.nan)
    s0 = np.where(np.isfinite(p0), static.static_safety_factor(r.static_load_rating, np.where(np.isfinite(p0), p0, 0.0)),
                  np.nan)
    l10r = np.full(np.shape(fr), np.nan)
    a_ref = np.full(np.shape(fr), np.nan)
    balls = _contact_loads(load_distribution, bearing, loads, shaft_speed)
    missing = _missing(bearing) if load_distribution is None else None
    if balls is None and missing is not None and (bearing.type not in ("radial", "angular")
                                                   or not covers(bearing, "load-distribution")):
        warnings.warn(f"no load distribution: {missing}, so the ISO/TS 16281 reference lives are not defined (the "
                      "ISO 281 lives are)", RatingWarning, stacklevel=3)
    elif balls is None:
        warnings.warn("no load distribution (the bearing's ball set and conformities are not known, or "
                      "load_distribution=False): the ISO/TS 16281 reference lives are not defined", RatingWarning,
                      stacklevel=3)
    else:
        failed = ~np.asarray(np.all(np.isfinite(balls[0]), axis=-1) & np.all(np.isfinite(balls[1]), axis=-1))
        if failed.any():  # a flagged case of the load distribution (NaN ball loads): no reference life
            warnings.warn(f"{int(failed.sum())} of {failed.size} load cases have no ball loads (the load "
                          "distribution found no equilibrium; its warnings say why): their ISO/TS 16281 "
                          "reference lives are not defined", RatingWarning, stacklevel=3)
        qi, qo = (np.where(failed[..., None], 0.0, q) for q in balls[:2])
        l10r = np.where(failed, np.nan, _reference_life(bearing, r, qi, qo, balls[2], rotating))
        with np.errstate(divide="ignore"):
            p_ref = r.dynamic_load_rating * (l10r / 1e6) ** (-1.0 / 3.0)
        if nu is not None and bearing.type != "thrust":  # a_ISO of thrust bearings: not implemented (above)
            a_ref = np.where(p_ref > 0, lubrication.life_modification_factor(
                kappa, ec, r.fatigue_load_limit, np.where(p_ref > 0, p_ref, 1.0), ep_additives=ep_additives),
                np.inf)
    return _result(r, n, fr, p, l10, l10r, s0, a1, nu, nu1, kappa, ec, a_iso, a_ref, dm, dm_source, ())


def miner_life(lives, revolution_shares, *, axis=-1):
    r"""Palmgren-Miner combination of lives: :math:`L = 1 / \sum_k (u_k / L_k)`.

    Parameters
    ----------
    lives : array_like
        Life at each duty-cycle step (inf allowed; NaN gives NaN). [revolutions]
    revolution_shares : array_like
        Share u_k of the revolutions run at each step, >= 0, summing to 1 along ``axis``. [-]
    axis : int
        The step axis.

    Returns
    -------
    ndarray or float
        Combined life. [revolutions]

    Examples
    --------
    >>> print(miner_life([1e9, 1e8], [0.5, 0.5]) / 1e6)
    181.8181818181818
    """
    lives = as_float("lives", lives)
    bad = lives <= 0  # NaN (a life not defined) passes and gives NaN
    if bad.any():
        raise InputError(f"lives must be > 0 [rev], got {float(lives[bad].flat[0])!r}")
    u = check_nonnegative("revolution_shares", revolution_shares, "-")
    total = np.sum(u, axis=axis)
    if not np.allclose(total, 1.0, rtol=0, atol=1e-9):
        raise InputError(f"revolution_shares must sum to 1 [-], got {float(np.ravel(total)[0])!r}")
    return (1.0 / np.sum(u / lives, axis=axis))[()]


class DutyCycleLife(NamedTuple):
    """Combined lives of a duty cycle (Palmgren-Miner) and the analysis of each step."""

    basic_rating_life: float
    """Combined L10. [revolutions]"""
    modified_rating_life: float | None
    """Combined L_nm (None without a lubricant). [revolutions]"""
    reference_rating_life: float
    """Combined L10r (NaN without a load distribution). [revolutions]"""
    modified_reference_rating_life: float | None
    """Combined L_nmr (None without a lubricant). [revolutions]"""
    mean_speed: float
    """Time-weighted mean speed, to turn the lives into durations. [rad/s]"""
    steps: RatingLife
    """The analysis of each step (arrays along the steps)."""


def duty_cycle_life(bearing, loads, shaft_speeds, time_shares, **options):
    r"""Combined life of a duty cycle: steps of load and speed, each run for a share of the time.

    Parameters
    ----------
    bearing : BallBearing
        The bearing.
    loads : array_like
        (k, 5) loads of the k steps (see :func:`rating_life`). [N, N m]
    shaft_speeds : array_like
        (k,) speeds, > 0. [rad/s]
    time_shares : array_like
        (k,) shares of the time, >= 0, summing to 1. [-] At most
        :data:`bearinglab._bounds.MAX_DUTY_CYCLE_STEPS` (10 000) steps.
    **options : optional
        Passed to :func:`rating_life` (lubricant, contamination, reliability, load distribution ...);
        array options broadcast along the steps.

    Returns
    -------
    DutyCycleLife

    Notes
    -----
    Palmgren-Miner: the revolution share of step k is :math:`u_k = t_k n_k / \sum_j t_j n_j`, and
    :math:`L = 1/\sum_k u_k/L_k` for each life; a duration is :math:`L / \bar n` with
    :math:`\bar n = \sum_k t_k n_k`.

    Examples
    --------
    >>> from bearinglab.bearing import BallBearing
    >>> b = BallBearing(9, 7.94e-3, 39.04e-3, 0.52, 0.53, contact_angle=0.0, type="radial")
    >>> d = duty_cycle_life(b, [[1000.0, 0, 0, 0, 0], [2000.0, 0, 0, 0, 0]], [300.0, 300.0], [0.5, 0.5],
    ...                     kinematic_viscosity=20e-6)
    >>> print(f"{d.basic_rating_life / 1e6:.1f} Mrev")
    612.8 Mrev
    """
    shape = np.shape(shaft_speeds)
    check_steps(shape[0] if shape else 1, "shaft_speeds")  # the steps are bounded before any step's work
    n = check_positive("shaft_speeds", shaft_speeds, "rad/s")
    t = check_nonnegative("time_shares", time_shares, "-")
    if n.ndim != 1 or t.shape != n.shape or np.shape(loads)[:-1] != n.shape:
        raise InputError(f"loads (k, 5), shaft_speeds (k,) and time_shares (k,) must agree, got shapes "
                         f"{np.shape(loads)}, {n.shape} and {t.shape}")
    if not np.isclose(t.sum(), 1.0, rtol=0, atol=1e-9):
        raise InputError(f"time_shares must sum to 1 [-], got {float(t.sum())!r}")
    steps = rating_life(bearing, loads, n, **options)
    u = t * n / np.sum(t * n)
    combine = {name: None if getattr(steps, name) is None  # no lubricant: no modified lives
               else float(miner_life(np.asarray(getattr(steps, name), dtype=float), u))
               for name in ("basic_rating_life", "modified_rating_life", "reference_rating_life",
                            "modified_reference_rating_life")}
    return DutyCycleLife(**combine, mean_speed=float(np.sum(t * n)), steps=steps)
