r"""Rating life of a roller bearing: the ISO 281 and ISO/TS 16281 analysis of a RollerBearing.

Analysis
--------
roller_rating_life          every life quantity for loads, speed, lubricant, cleanliness and reliability, batched
                            over load cases; :func:`bearinglab.life.rating_life` calls it for a RollerBearing
reference_slice_loads       the lamina loads of the ISO/TS 16281 reference life (the slice model at rest)

It returns the :class:`~bearinglab.life.analysis.RatingLife` of the ball-bearing analysis, with the roller
formulas: P of ISO 281 (the catalogue's e, Y, Y1, Y2 where given), L10 = (C/P)^(10/3), a_ISO of roller
bearings, P0 and s0 of ISO 76, and L10r of ISO/TS 16281 summed over the laminae of the slice model
(:mod:`bearinglab.rollers`), with the profile and the tilt. The modified reference life uses
:math:`P_{ref} = C L_{10r}^{-3/10}` (L10r in 10^6 revolutions). A spherical roller bearing has every ISO 281
quantity and no reference life (no load-distribution model; the warning says so).
"""

from __future__ import annotations

import warnings

import numpy as np

from .._validate import check_positive
from ..errors import InputError
from ..ratings import dynamic, lubrication, roller, roller_reference, static
from ..ratings.bearing import bearing_ratings
from ..ratings.static import RatingWarning
from ._common import _contamination, _result, _untilted, _viscosity

__all__ = ["reference_slice_loads", "roller_rating_life"]


def reference_slice_loads(bearing, loads, *, n_slices=None, radial_clearance=None, on_failure="flag",
                          prescribed_displacement=None):
    """The slice model of the ISO/TS 16281 reference life of a roller bearing (at rest).

    Parameters
    ----------
    bearing : RollerBearing
        Cylindrical or tapered (a missing roller set is estimated, with a warning).
    loads : array_like
        (..., 5) F_x, F_y, F_z, M_x, M_y on the rotating ring. [N, N m]
    n_slices : int, optional
        Slices per roller (30 by default). [-]
    radial_clearance : float, optional
        The operating clearance in place of the bearing's. [m]
    on_failure : {"raise", "flag"}, optional
        As in :func:`bearinglab.rollers.distribution.load_distribution`.
    prescribed_displacement : array_like, optional
        Held freedoms (NaN: free), as there; :func:`roller_rating_life` holds the ring square (no tilt) where
        a case has no moment.

    Returns
    -------
    RollerLoadDistribution
    """
    from ..rollers import analysis  # the life does not need the slice model to import

    kw = {} if n_slices is None else {"n_slices": n_slices}
    return analysis.roller_analysis(bearing, loads, radial_clearance=radial_clearance, on_failure=on_failure,
                                    prescribed_displacement=prescribed_displacement, **kw)


def _split(loads):
    f = np.asarray(loads, dtype=float)
    if f.ndim == 0 or f.shape[-1] != 5:
        raise InputError(f"loads must have the five components (Fx, Fy, Fz, Mx, My) on their last axis "
                         f"[N, N, N, N m, N m], got shape {np.shape(loads)}")
    if not np.all(np.isfinite(f)):
        raise InputError("loads must be finite [N, N m]")
    return np.hypot(f[..., 0], f[..., 1]), np.abs(f[..., 2]), np.hypot(f[..., 3], f[..., 4])


def _equivalent_loads(bearing, fr, fa, moment):
    alpha = bearing.contact_angle or 0.0
    kw = {"rows": bearing.rows, "ratio_limit": bearing.ratio_limit, "axial_factor": bearing.axial_factor,
          "axial_factor_below": bearing.axial_factor_below}
    if bearing.type == "cylindrical" and (fa > 0).any():
        warnings.warn("a cylindrical roller bearing carries no axial load on its raceways: ISO 281 takes P = F_r and "
                      "ISO 76 P0 = F_r (the axial load on the ribs of an NJ / NUP is not in them)", RatingWarning,
                      stacklevel=3)
        fa = np.zeros_like(fa)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RatingWarning)  # the alpha = 0 note is given above, once
        p = roller.roller_equivalent_load(fr, fa, alpha, **kw)
    p0 = roller.roller_static_equivalent_load(fr, fa, alpha, rows=bearing.rows,
                                              static_axial_factor=bearing.static_axial_factor)
    return _untilted(p, p0, moment)


def roller_rating_life(bearing, loads, shaft_speed, *, kinematic_viscosity=None, contamination=1.0, reliability=0.9,
                       ep_additives=False, load_distribution=None, rotating="inner", n_slices=None,
                       radial_clearance=None, **lubricant):
    r"""ISO 281 and ISO/TS 16281 life of a roller bearing for a batch of load cases.

    Parameters
    ----------
    bearing : RollerBearing
        The bearing; the catalogue's C, C0, Cu take precedence over the geometry.
    loads : array_like
        (..., 5): Fx, Fy, Fz (axial), Mx, My on the rotating ring. [N, N, N, N m, N m]
    shaft_speed : array_like
        Speed of the rotating ring, > 0. [rad/s]
    kinematic_viscosity : array_like, optional
        nu at the operating temperature (or the oil through ``lubricant``); without either the
        lubrication-dependent results are None. [m^2/s]
    contamination : float or str
        e_C or a cleanliness class of ISO 281 table 13. [-]
    reliability : float
        0.90 to 0.9995. [-]
    ep_additives : bool
        The EP-additive rule of ISO 281 clause 9.3.3.
    load_distribution : RollerLoadDistribution, array_like or False, optional
        Lamina loads (..., Z, n_s) for ISO/TS 16281, or a result with ``slice_load``; by default the slice
        model at rest (:func:`reference_slice_loads`) with the ring square (its tilt held at 0, as ISO 281's
        load case) where a case has no moment, free to tilt where it has one; False: none (L10r NaN, with a
        warning).
    rotating : {"inner", "outer"}
        The ring rotating relative to the load.
    n_slices : int, optional
        Slices per roller of the default slice model. [-]
    radial_clearance : float, optional
        The operating clearance of the slice model. [m]
    **lubricant : optional
        ``temperature`` with ``iso_vg`` or ``viscosity_40`` (and ``viscosity_100`` or ``viscosity_index``).

    Returns
    -------
    RatingLife

    Notes
    -----
    ISO 281:2007 eq. (15) with p = 10/3, :math:`L_{nm} = a_1 a_{ISO} L_{10}` with a_ISO of radial roller
    bearings at d_m = (d + D)/2; ISO/TS 16281 :math:`L_{10r}` of
    :func:`bearinglab.ratings.roller_reference.roller_reference_rating_life` and
    :math:`L_{nmr} = a_1 a_{ISO}(P_{ref}) L_{10r}`, :math:`P_{ref} = C L_{10r}^{-3/10}`.

    Examples
    --------
    >>> from bearinglab import catalog
    >>> r = roller_rating_life(catalog.get("NU 208 ECP"), [10e3, 0, 0, 0, 0], 1500 * np.pi / 30,
    ...                        kinematic_viscosity=20e-6)
    >>> print(f"L10 = {r.basic_rating_life / 1e6:.0f} Mrev, L10r = {r.reference_rating_life / 1e6:.0f} Mrev")
    L10 = 438 Mrev, L10r = 1695 Mrev
    """
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        r = bearing_ratings(bearing)
        fr, fa, moment = _split(loads)
        n = check_positive("shaft_speed", shaft_speed, "rad/s")
        nu = _viscosity(kinematic_viscosity, dict(lubricant))
        dm = bearing.mean_diameter if bearing.bore is not None and bearing.outside_diameter is not None else \
            bearing.require("pitch_diameter")
        dm_source = "mean diameter (d + D)/2" if bearing.bore is not None and bearing.outside_diameter is not None \
            else "pitch diameter"
        pitch = bearing.pitch_diameter if bearing.pitch_diameter is not None else dm
        a1 = float(dynamic.reliability_factor(reliability))
        ec = _contamination(contamination, pitch)
        nu1 = lubrication.rated_viscosity(n, dm)
        kappa = None if nu is None else lubrication.viscosity_ratio(nu, n, dm)
        p, p0 = _equivalent_loads(bearing, fr, fa, moment)
        finite = np.isfinite(p)
        l10 = np.where(finite, roller.roller_rating_life(r.dynamic_load_rating, np.where(finite, p, 0.0)), np.nan)
        a_iso = None if nu is None else np.where(finite, roller.roller_life_modification_factor(
            kappa, ec, r.fatigue_load_limit, np.where(finite & (p > 0), p, 1.0), ep_additives=ep_additives), np.nan)
        s0 = np.where(np.isfinite(p0), static.static_safety_factor(r.static_load_rating,
                                                                     np.where(np.isfinite(p0), p0, 0.0)), np.nan)
        l10r = np.full(np.shape(fr), np.nan)
        a_ref = np.full(np.shape(fr), np.nan)
        q, geo = _slices(bearing, loads, load_distribution, n_slices, radial_clearance)
        if q is not None:
            failed = ~np.all(np.isfinite(q), axis=(-2, -1))
            if failed.any():
                warnings.warn(f"{int(failed.sum())} of {failed.size} load cases have no lamina loads (the slice model "
                              "found no equilibrium): their ISO/TS 16281 reference lives are not defined", RatingWarning,
                              stacklevel=2)
            with np.errstate(divide="ignore"):
                l10r = roller_reference.roller_reference_rating_life(
                    np.where(failed[..., None, None], 0.0, q), r.dynamic_load_rating, geo.require("roller_diameter"),
                    geo.require("pitch_diameter"), geo.contact_angle or 0.0, rows=geo.rows, rotating=rotating)
            l10r = np.where(failed, np.nan, l10r)
            with np.errstate(divide="ignore"):
                p_ref = r.dynamic_load_rating * (l10r / 1e6) ** (-0.3)
            if nu is not None:
                a_ref = np.where(p_ref > 0, roller.roller_life_modification_factor(
                    kappa, ec, r.fatigue_load_limit, np.where(p_ref > 0, p_ref, 1.0), ep_additives=ep_additives), np.inf)
    messages = tuple(dict.fromkeys(str(w.message) for w in caught))
    for w in caught:
        warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
    return _result(r, n, fr, p, l10, l10r, s0, a1, nu, nu1, kappa, ec, a_iso, a_ref, dm, dm_source, messages)


def _slices(bearing, loads, given, n_slices, radial_clearance):
    """(..., Z, n_s) lamina loads for the reference life and the bearing with its roller set (estimated where
    missing), or (None, bearing) with the warning why."""
    from ..rollers.estimation import with_estimated_geometry

    if given is False:
        warnings.warn("no load distribution (load_distribution=False): the ISO/TS 16281 reference lives are not "
                      "defined", RatingWarning, stacklevel=3)
        return None, bearing
    if bearing.type == "spherical":
        warnings.warn(f"{bearing.designation or 'this bearing'}: a spherical roller bearing has no load-distribution "
                      "model, so no ISO/TS 16281 reference life (the ISO 281 lives are given)", RatingWarning,
                      stacklevel=3)
        return None, bearing
    if not bearing.has_internal_geometry:
        if None in (bearing.bore, bearing.outside_diameter, bearing.static_load_rating):
            warnings.warn("no roller set (and no envelope and C0 to estimate one): the ISO/TS 16281 reference lives "
                          "are not defined", RatingWarning, stacklevel=3)
            return None, bearing
        bearing = with_estimated_geometry(bearing)
    if given is not None:
        return np.asarray(getattr(given, "slice_load", given), dtype=float), bearing
    f = np.asarray(loads, dtype=float)
    shape = f.shape[:-1]
    flat = f.reshape(-1, 5)
    moment = np.hypot(flat[:, 3], flat[:, 4]) > 0
    # a ring square to its housing where no moment is given (ISO 281's load case: the other bearing of the
    # arrangement holds the shaft), free to tilt under a moment
    held = np.where(moment[:, None], np.nan, np.array([np.nan, np.nan, np.nan, 0.0, 0.0]))
    ok = np.ones(len(flat), dtype=bool)
    if bearing.type == "tapered":
        ok = flat[:, 2] > np.hypot(flat[:, 0], flat[:, 1]) * np.tan(bearing.contact_angle)
        if not ok.all():
            warnings.warn(f"{int((~ok).sum())} of {ok.size} load cases give a single tapered bearing less thrust than "
                          "F_r tan(alpha), which no equilibrium of the bearing alone holds: their ISO/TS 16281 "
                          "reference lives are not defined (solve the pair: bearing-set with DB or DF, "
                          "bearinglab.rollers.pairs)", RatingWarning, stacklevel=3)
    q = np.full((len(flat), bearing.rollers, n_slices or _default_slices()), np.nan)
    if ok.any():
        r = reference_slice_loads(bearing, flat[ok], n_slices=n_slices, radial_clearance=radial_clearance,
                                  prescribed_displacement=held[ok])
        q[ok] = r.slice_load
    return q.reshape(shape + q.shape[1:]), bearing


def _default_slices():
    from ..rollers.analysis import N_SLICES

    return N_SLICES
