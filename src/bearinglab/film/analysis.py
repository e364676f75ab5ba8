r"""The EHL film of every ball of a bearing under combined load, at rest or at speed.

entrainment_velocities   mean rolling velocity at the inner and outer contact of a ball, from its angles
film_analysis            ball loads and angles of the load distribution -> film and Lambda per contact
distribution_films       the film stage alone, for a load distribution already solved
FilmAnalysis             its result

The ball loads and contact angles come from :func:`bearinglab.quasistatic.combined.combined_analysis`
(at rest, or quasi-static at the operating speed with centrifugal force and gyroscopic moment); each
contact's radii, ellipticity (exact Hertz) and film follow from :mod:`bearinglab.film.ehl`. Everything
is batched over load cases and balls.

References
----------
.. [1] B. J. Hamrock, S. R. Schmid and B. O. Jacobson, *Fundamentals of Fluid Film Lubrication*,
   2nd ed., Marcel Dekker, 2004, ch. 24 (the film of a ball bearing, contact by contact).
.. [2] T. A. Harris and M. N. Kotzalas, *Advanced Concepts of Bearing Technology*, 5th ed., CRC Press,
   2006, ch. 3 (ball speeds at high speed) and ch. 4 (lubricant films in rolling bearings).
"""

from __future__ import annotations

import warnings
from typing import NamedTuple

import numpy as np

from .._validate import check_nonnegative, check_positive
from ..errors import InputError
from . import ehl

__all__ = ["LOADS_AT", "STARVATION_LIMIT", "FilmAnalysis", "distribution_films", "entrainment_velocities", "film_analysis"]

#: Where the ball loads are solved: at the operating speed (quasi-static, spec 004) or at rest (the
#: static distribution a handbook uses; the speeds then follow pure rolling at those angles).
LOADS_AT = ("speed", "rest")
#: Below this SKF replenishment factor Phi_rs a starvation risk is reported (a judgement of this library:
#: the SKF model then removes more than a third of the rolling moment for an inlet that does not refill).
STARVATION_LIMIT = 2.0 / 3.0


class FilmAnalysis(NamedTuple):
    """Films of every ball (SI). ``(...)`` is the shape of the load cases, Z the number of balls; an
    unloaded contact carries NaN films."""

    load_inner: np.ndarray  # (..., Z) Q_i [N]
    load_outer: np.ndarray  # (..., Z) Q_o [N]
    contact_angle_inner: np.ndarray  # (..., Z) [rad]
    contact_angle_outer: np.ndarray  # (..., Z) [rad]
    entrainment_velocity_inner: np.ndarray  # (..., Z) u_i [m/s]
    entrainment_velocity_outer: np.ndarray  # (..., Z) u_o [m/s]
    ellipticity_inner: np.ndarray  # (..., Z) k_i [-]
    ellipticity_outer: np.ndarray  # (..., Z) k_o [-]
    central_film_inner: np.ndarray  # (..., Z) h_c [m]
    minimum_film_inner: np.ndarray  # (..., Z) h_min [m]
    central_film_outer: np.ndarray  # (..., Z) [m]
    minimum_film_outer: np.ndarray  # (..., Z) [m]
    film_parameter_inner: np.ndarray  # (..., Z) Lambda_i [-]
    film_parameter_outer: np.ndarray  # (..., Z) Lambda_o [-]
    minimum_film: np.ndarray  # (...) smallest h_min over the loaded contacts [m]
    minimum_film_parameter: np.ndarray  # (...) smallest Lambda [-]
    regime: np.ndarray  # (...) "boundary", "mixed" or "full film" at the smallest Lambda
    converged: np.ndarray  # (...) the load distribution converged
    warnings: tuple  # messages


def entrainment_velocities(shaft_speed, contact_angle_inner, contact_angle_outer, ball_diameter, pitch_diameter, *,
                           raceway_control="outer"):
    r"""Mean rolling (entrainment) velocity at the inner and the outer contact of a ball, outer ring fixed.

    Parameters
    ----------
    shaft_speed : array_like
        Inner-ring speed omega >= 0. [rad/s]
    contact_angle_inner, contact_angle_outer : array_like
        alpha_i, alpha_o of the ball. [rad]
    ball_diameter : array_like
        D. [m]
    pitch_diameter : array_like
        d_m. [m]
    raceway_control : {"outer", "inner"}, optional
        The ball's attitude (:func:`bearinglab.quasistatic.attitude_angle`).

    Returns
    -------
    tuple of ndarray
        u_i, u_o. [m/s]

    Notes
    -----
    In the frame of the cage a ball rolls without slip along the rolling direction at both contacts
    (the kinematics of :func:`bearinglab.quasistatic.ball_speeds`): the raceway surface and the ball
    surface move at the same speed u there, so the mean velocity entraining the oil is u itself. With
    :math:`\gamma_j = D\cos\alpha_j/d_m` and :math:`\Delta = (1+\gamma_o)\cos(\alpha_i-\beta) +
    (1-\gamma_i)\cos(\alpha_o-\beta)`,

    .. math::
        u_j = \omega \frac{d_m}{2}\,\frac{(1-\gamma_i)(1+\gamma_o)\cos(\alpha_j-\beta)}{\Delta}.

    At equal angles this is :math:`u = \omega (d_m^2 - D^2\cos^2\alpha)/(4 d_m)` at both contacts,
    whatever beta, Hamrock's pure-rolling value ([1] ch. 24).

    Examples
    --------
    >>> ui, uo = entrainment_velocities(400.0, 0.0, 0.0, 12.7e-3, 65e-3)
    >>> print(f"{ui:.4f} {uo:.4f} m/s")
    6.2519 6.2519 m/s
    """
    from ..quasistatic import attitude_angle

    w = check_nonnegative("shaft_speed", shaft_speed, "rad/s")
    ai = np.asarray(contact_angle_inner, dtype=float)
    ao = np.asarray(contact_angle_outer, dtype=float)
    d = check_positive("ball_diameter", ball_diameter, "m")
    dm = check_positive("pitch_diameter", pitch_diameter, "m")
    beta = attitude_angle(np.abs(ai), np.abs(ao), d, dm, raceway_control=raceway_control)
    ai, ao = np.abs(ai), np.abs(ao)  # a ball on the other shoulder is the mirror image
    gi, go = d * np.cos(ai) / dm, d * np.cos(ao) / dm
    ci, co = np.cos(ai - beta), np.cos(ao - beta)
    common = w * 0.5 * dm * (1.0 - gi) * (1.0 + go) / ((1.0 + go) * ci + (1.0 - gi) * co)
    ui, uo = np.broadcast_arrays(common * ci, common * co)
    return ui[()], uo[()]


def _contact(q, u, angle, d, dm, conformity, race, eta, alpha, ep, thermal, lubricant):
    """Ellipticity and films of one raceway's contacts (NaN where unloaded)."""
    radii = ehl.contact_radii(d, dm, conformity, angle, race=race)
    k = ehl.ellipticity(radii.rx, radii.ry)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # k > 8: noted once by film_analysis
        loaded = q > 0
        h = ehl.hamrock_dowson(np.where(loaded, q, 1.0), u, radii.rx, k, eta, alpha, ep)
    hc = np.where(loaded, h.central, np.nan)
    hm = np.where(loaded, h.minimum, np.nan)
    if thermal is not None:
        from .. import hertz

        f = (1.0 / radii.rx - 1.0 / radii.ry) / (1.0 / radii.rx + 1.0 / radii.ry)
        p = hertz.point_contact(np.where(loaded, q, 0.0), 1.0 / radii.rx + 1.0 / radii.ry, f, ep).p_max
        phi = ehl.thermal_reduction_factor(u, eta, thermal[0], thermal[1], p, ep)
        hc, hm = hc * phi, hm * phi
    return k, hc, hm


def film_analysis(bearing, loads, shaft_speed, dynamic_viscosity, pressure_viscosity_coefficient=None, *,
                  roughness_ball=0.1e-6, roughness_race=0.1e-6, loads_at="speed", raceway_control="outer",
                  inlet_heating=None, reduced_modulus=None, lubrication=None, kinematic_viscosity=None,
                  **options):
    r"""Film thickness and film parameter at every ball's inner and outer contact.

    Parameters
    ----------
    bearing : BallBearing
        Needs the ball set (Z, D, d_m, f_i, f_o) and the free contact angle or clearance.
    loads : array_like
        (..., 5): F_x, F_y, F_z [N], M_x, M_y [N m] on the inner ring.
    shaft_speed : array_like
        Inner-ring speed > 0, broadcast against the cases. [rad/s]
    dynamic_viscosity : array_like
        eta0 of the oil at the inlet (bearing) temperature, per case. [Pa s]
    pressure_viscosity_coefficient : array_like, optional
        alpha; default the estimate :func:`bearinglab.film.ehl.pressure_viscosity_coefficient` (a warning
        says so). [1/Pa]
    roughness_ball, roughness_race : float, optional
        RMS roughness R_q of the balls and of the raceways (0.1 um each by default). [m]
    loads_at : {"speed", "rest"}, optional
        Solve the ball loads at the operating speed (quasi-static; default) or at rest. Four-point and
        thrust ball bearings, whose model has no speed terms, are solved at rest (a note says so).
    raceway_control : {"outer", "inner"}, optional
        Ball attitude for the entrainment velocities and the quasi-static solve.
    inlet_heating : tuple of float, optional
        (temperature_viscosity_coefficient [1/K], thermal_conductivity [W/(m K)]): reduce the films by
        the inlet shear heating factor (:func:`bearinglab.film.ehl.thermal_reduction_factor`); off by
        default, as in Hamrock and Dowson's isothermal formulas.
    reduced_modulus : float, optional
        E' instead of the one of the bearing's materials. [Pa]
    lubrication : str, optional
        The lubrication method ("grease", "oil-air", "oil-jet", "oil-bath"): with it, a starvation-risk
        warning where SKF's replenishment factor falls below :data:`STARVATION_LIMIT`.
    kinematic_viscosity : array_like, optional
        nu per case, for that check. [m^2/s]

    Other Parameters
    ----------------
    **options
        Passed to :func:`bearinglab.quasistatic.combined.combined_analysis` (``on_failure``, ...).

    Returns
    -------
    FilmAnalysis

    Notes
    -----
    Each contact keeps its own load, angle, radii R_x, R_y at that angle and ellipticity; the film
    is Hamrock and Dowson's for a fully flooded contact (no starvation). Lambda uses the minimum film.

    Examples
    --------
    >>> from bearinglab import catalog
    >>> from bearinglab.units import RPM
    >>> r = film_analysis(catalog.get("B218"), [0, 0, 20e3, 0, 0], 10000 * RPM, 0.01, 2e-8)
    >>> print(f"h_min = {r.minimum_film * 1e6:.3f} um, Lambda = {r.minimum_film_parameter:.2f}, {r.regime}")
    h_min = 0.887 um, Lambda = 6.27, full film
    """
    from ..bearing import check_model

    check_model(bearing, "film")
    from ..quasistatic.combined import combined_analysis

    if loads_at not in LOADS_AT:
        raise InputError(f"loads_at must be one of {list(LOADS_AT)}, got {loads_at!r}")
    notes = []
    if loads_at == "speed" and bearing.type in ("four-point", "thrust"):  # their model has no speed terms
        loads_at = "rest"
        notes.append(f"ball loads at rest: the {bearing.type} model has no speed terms (centrifugal force, gyroscopic "
                     "moment); the films are those of the rest loads at the operating speed")
    w = check_positive("shaft_speed", shaft_speed, "rad/s")
    eta = check_positive("dynamic_viscosity", dynamic_viscosity, "Pa s")
    if pressure_viscosity_coefficient is None:
        alpha = ehl.pressure_viscosity_coefficient(eta)
        notes.append("pressure-viscosity coefficient: not given, so Wooster's estimate for mineral oils is used "
                     f"({float(np.min(alpha)) * 1e9:.3g} 1/GPa); give the oil's own value")
    else:
        alpha = check_positive("pressure_viscosity_coefficient", pressure_viscosity_coefficient, "1/Pa")
    rb = check_nonnegative("roughness_ball", roughness_ball, "m")
    rr = check_nonnegative("roughness_race", roughness_race, "m")
    if inlet_heating is not None:
        inlet_heating = (check_positive("temperature_viscosity_coefficient", inlet_heating[0], "1/K"),
                         check_positive("thermal_conductivity", inlet_heating[1], "W/(m K)"))
    f = np.asarray(loads, dtype=float)
    shape = np.broadcast_shapes(f.shape[:-1], w.shape, eta.shape, np.shape(alpha))
    f = np.broadcast_to(f, shape + (5,))
    w_b = np.broadcast_to(w, shape)
    options.setdefault("raceway_control", raceway_control)
    ld = combined_analysis(bearing, f, w_b if loads_at == "speed" else np.zeros(shape), reduced_modulus=reduced_modulus,
                           **options)
    return distribution_films(ld, bearing, w_b, eta, alpha, roughness_ball=rb, roughness_race=rr,
                              raceway_control=raceway_control, inlet_heating=inlet_heating,
                              reduced_modulus=reduced_modulus, notes=notes, lubrication=lubrication,
                              kinematic_viscosity=kinematic_viscosity)


def distribution_films(distribution, bearing, shaft_speed, dynamic_viscosity, pressure_viscosity_coefficient, *,
                       roughness_ball=0.1e-6, roughness_race=0.1e-6, raceway_control="outer", inlet_heating=None,
                       reduced_modulus=None, notes=(), lubrication=None, kinematic_viscosity=None):
    r"""The films of a solved load distribution: the film stage of :func:`film_analysis`.

    Parameters
    ----------
    distribution : LoadDistribution
        Of the bearing (:func:`bearinglab.quasistatic.combined.combined_analysis`), cases of shape (...).
    bearing : BallBearing
        The bearing it was solved for.
    shaft_speed : array_like
        Inner-ring speed of each case (the film's speed, whatever speed the loads were solved at). [rad/s]
    dynamic_viscosity : array_like
        eta0 per case. [Pa s]
    pressure_viscosity_coefficient : array_like
        alpha per case. [1/Pa]
    roughness_ball, roughness_race : float, optional
        R_q of balls and raceways. [m]
    raceway_control : {"outer", "inner"}, optional
        Ball attitude for the entrainment velocities.
    inlet_heating : tuple of float, optional
        See :func:`film_analysis`.
    reduced_modulus : float, optional
        E' instead of the bearing's. [Pa]
    notes : sequence of str, optional
        Warnings to carry into the result.
    lubrication : str, optional
        See :func:`film_analysis` (the starvation check).
    kinematic_viscosity : array_like, optional
        nu per case, for the starvation check. [m^2/s]

    Returns
    -------
    FilmAnalysis

    Examples
    --------
    >>> from bearinglab import catalog
    >>> from bearinglab.quasistatic.combined import combined_analysis
    >>> from bearinglab.units import RPM
    >>> b = catalog.get("B218")
    >>> ld = combined_analysis(b, [0, 0, 20e3, 0, 0], 10000 * RPM)
    >>> r = distribution_films(ld, b, 10000 * RPM, 0.01, 2e-8)
    >>> print(f"{r.minimum_film * 1e6:.3f} um")
    0.887 um
    """
    ld = distribution
    shape = np.shape(ld.converged)
    w_b = np.broadcast_to(check_nonnegative("shaft_speed", shaft_speed, "rad/s"), shape)
    eta = check_positive("dynamic_viscosity", dynamic_viscosity, "Pa s")
    alpha = check_positive("pressure_viscosity_coefficient", pressure_viscosity_coefficient, "1/Pa")
    rb = check_nonnegative("roughness_ball", roughness_ball, "m")
    rr = check_nonnegative("roughness_race", roughness_race, "m")
    notes = list(notes)
    ep = bearing.reduced_modulus if reduced_modulus is None else reduced_modulus
    d, dm = bearing.ball_diameter, bearing.pitch_diameter
    ai, ao = ld.contact_angle_inner, ld.contact_angle_outer
    qi, qo = ld.ball_load_inner, ld.ball_load_outer
    ex = (...,) + (None,)  # per case -> per ball
    ui, uo = entrainment_velocities(w_b[ex], ai, ao, d, dm, raceway_control=raceway_control)
    eta_b, alpha_b = np.broadcast_to(eta, shape)[ex], np.broadcast_to(alpha, shape)[ex]
    good = np.isfinite(qi)
    qi0, qo0 = np.where(good, qi, 0.0), np.where(good, qo, 0.0)
    ai0, ao0 = np.where(good, ai, 0.0), np.where(good, ao, 0.0)
    ui0, uo0 = np.where(good, ui, 0.0), np.where(good, uo, 0.0)
    ki, hci, hmi = _contact(qi0, ui0, ai0, d, dm, bearing.inner_conformity, "inner", eta_b, alpha_b, ep,
                            inlet_heating, None)
    sphere = bearing.type == "self-aligning"  # the outer raceway is a sphere: 1/R_o at any contact angle
    ko, hco, hmo = _contact(qo0, uo0, np.full_like(ao0, bearing.contact_angle) if sphere else ao0, d, dm,
                            bearing.outer_conformity, "outer", eta_b, alpha_b, ep, inlet_heating, None)
    lam_i = ehl.film_parameter(hmi, rb, rr)
    lam_o = ehl.film_parameter(hmo, rb, rr)
    both = np.concatenate([hmi, hmo], axis=-1)
    lam = np.concatenate([np.broadcast_to(lam_i, hmi.shape), np.broadcast_to(lam_o, hmo.shape)], axis=-1)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # all-NaN cases: no loaded contact
        h_min = np.nanmin(np.where(np.isnan(both), np.inf, both), axis=-1)
        lam_min = np.nanmin(np.where(np.isnan(lam), np.inf, lam), axis=-1)
    h_min, lam_min = np.where(np.isinf(h_min), np.nan, h_min), np.where(np.isinf(lam_min), np.nan, lam_min)
    regime = ehl.lubrication_regime(lam_min)
    notes += list(ld.warnings)
    notes += _notes(ki, ko, qi0, qo0, lam_min)
    if lubrication is not None:
        notes += _starvation(bearing, lubrication, kinematic_viscosity, w_b)
    return FilmAnalysis(qi, qo, ai, ao, ui, uo, ki, ko, hci, hmi, hco, hmo, np.asarray(lam_i), np.asarray(lam_o),
                        h_min[()], lam_min[()], regime, ld.converged, tuple(dict.fromkeys(notes)))


def _starvation(bearing, lubrication, nu, w):
    """The starvation-risk warning from SKF's kinematic replenishment factor (a judgement: below
    STARVATION_LIMIT the SKF model takes off more than a third of the rolling moment for a starved
    inlet, and the fully flooded film of Hamrock and Dowson is then optimistic)."""
    from ..friction.skf import replenishment_factor

    if nu is None:
        raise InputError("kinematic_viscosity is needed with lubrication= (the starvation check) [m^2/s]")
    if bearing.bore is None or bearing.outside_diameter is None:
        return [("starvation: not checked (the bearing has no bore and outside diameter for SKF's replenishment "
                "factor)")]
    phi = np.atleast_1d(replenishment_factor(nu, w, bearing.bore, bearing.outside_diameter, lubrication=lubrication,
                                             bearing_type=bearing.type))
    low = phi < STARVATION_LIMIT
    if not low.any():
        return []
    return [(f"starvation risk ({lubrication}): SKF's kinematic replenishment factor Phi_rs = {float(phi.min()):.3g} "
            f"< {STARVATION_LIMIT:.2f} in {int(low.sum())} of {phi.size} case(s): the oil may not flow back into the "
            "track between balls, and the real film is thinner than the fully flooded one shown")]


def _notes(ki, ko, qi, qo, lam_min):
    """Warnings: an ellipticity beyond the fitted range, films too thin for the roughness."""
    notes = []
    k = np.concatenate([np.where(qi > 0, ki, 0.0), np.where(qo > 0, ko, 0.0)], axis=-1)
    if np.any(k > 8.0):
        notes.append(f"ellipticity up to k = {float(np.max(k)):.3g}: beyond the k <= 8 of Hamrock and Dowson's fit "
                     "(the formulas are smooth there and commonly used; read the film as an estimate)")
    lam = np.atleast_1d(lam_min)
    low = lam < ehl.REGIME_THRESHOLDS[0]
    if np.any(low):
        notes.append(f"film parameter Lambda = {float(np.nanmin(lam)):.3g} < 1 in {int(low.sum())} of {lam.size} "
                     "case(s): boundary lubrication, the asperities of balls and raceways touch (surface "
                     "distress and wear; an additive oil or a higher viscosity is needed)")
    return notes
