r"""Plausibility limits: results that are computed correctly but lie where the model or the bearing is
no longer valid. Each check returns warning messages (strings, empty when all is well); the analyses
put them in their ``warnings`` and the command line prints them.

Checks
------
contact_pressure_warnings   p_max above the ISO 76 static limit (4200 MPa for ball bearings)
static_load_warnings        the static equivalent load P0 above the basic static rating C0
deflection_warnings         an elastic approach comparable to the ball (Hertz needs small strains)
truncation_warnings         a contact ellipse that runs over the raceway shoulder
viscosity_ratio_warnings    kappa = nu / nu1 below 0.1 (ISO 281: the life model is not valid)
contact_warnings            all of the above for a bearing under thrust (ball loads and angles)
combined_warnings           all of the above for a bearing under combined load (its load distribution)
high_speed_warnings         contact_warnings and the light-load criteria for a high-speed state

Guards (errors, not warnings)
-----------------------------
check_speed                 a speed no ball bearing can run (d_m n above MAX_SPEED_FACTOR)

Constants
---------
MAX_SPEED_FACTOR, ISO76_CONTACT_PRESSURE, DEFLECTION_FRACTION, SHOULDER_HEIGHT_FRACTION, MINIMUM_VISCOSITY_RATIO
"""

from __future__ import annotations

import math

import numpy as np

from ._validate import as_float, check_nonnegative, check_positive_finite

__all__ = [
    "DEFLECTION_FRACTION",
    "ISO76_CONTACT_PRESSURE",
    "MAX_SPEED_FACTOR",
    "MINIMUM_VISCOSITY_RATIO",
    "SHOULDER_HEIGHT_FRACTION",
    "check_speed",
    "combined_warnings",
    "contact_pressure_warnings",
    "contact_warnings",
    "deflection_warnings",
    "high_speed_warnings",
    "static_load_warnings",
    "truncation_warnings",
    "viscosity_ratio_warnings",
]

#: ISO 76:2006 clause 3.1: the contact stress of the basic static load rating of ball bearings. [Pa]
ISO76_CONTACT_PRESSURE = 4.2e9
#: An elastic approach above this fraction of the ball diameter is no longer a small strain. [-]
#: (Hertz theory assumes the contact small against the radii; at 4200 MPa steel balls deflect by
#: about 0.3 % of D, so 1 % is well beyond any rated load.)
DEFLECTION_FRACTION = 0.01
#: Default raceway shoulder height, as a fraction of the ball diameter, where the catalog gives none.
#: An assumption (typical of angular-contact rings), not a standard value: give the bearing's own
#: ``inner_shoulder_height`` / ``outer_shoulder_height`` for a real check. [-]
SHOULDER_HEIGHT_FRACTION = 0.35
#: The speed factor d_m n above which no ball bearing runs: ten times the about 3.5e6 mm/min of the
#: fastest hybrid spindle bearings. An input guard (an error), not a model limit. [mm/min]
MAX_SPEED_FACTOR = 3.5e7
#: ISO 281:2007 clause 9.3.3: the life modification factor is not defined below kappa = 0.1. [-]
MINIMUM_VISCOSITY_RATIO = 0.1


def check_speed(speed, pitch_diameter, name="speed"):
    """Reject a speed that no ball bearing of this size can run.

    Parameters
    ----------
    speed : array_like
        Ring speeds, magnitudes count. [rad/s]
    pitch_diameter : float
        d_m. [m]
    name : str, optional
        The parameter's name for the message.

    Returns
    -------
    ndarray
        The speeds.

    Raises
    ------
    InputError
        Where d_m abs(n) exceeds :data:`MAX_SPEED_FACTOR`.

    Examples
    --------
    >>> check_speed([1e12 * 2 * math.pi / 60], 0.1253)
    Traceback (most recent call last):
    ...
    bearinglab.errors.InputError: speed must be <= 279330 [rpm] for d_m = 125.3 mm (d_m n <= 3.5e+07 mm/min), got 1e+12 rpm
    """
    from .errors import InputError

    w = np.ravel(as_float(name, speed))
    pitch_diameter = float(check_positive_finite("pitch_diameter", pitch_diameter, "m"))
    rpm = np.abs(w) * 60.0 / (2.0 * math.pi)
    limit = MAX_SPEED_FACTOR / (pitch_diameter * 1e3)
    bad = rpm > limit
    if bad.any():
        raise InputError(f"{name} must be <= {limit:.6g} [rpm] for d_m = {pitch_diameter * 1e3:g} mm (d_m n <= "
                         f"{MAX_SPEED_FACTOR:g} mm/min), got {rpm[bad][0]:.6g} rpm")
    return w


def _count(bad, what="case(s)"):
    return f"{int(np.count_nonzero(bad))} of {bad.size} {what}"


def contact_pressure_warnings(max_pressure, *, where="contact"):
    """Warn where the maximum Hertz pressure exceeds the ISO 76 limit of 4200 MPa.

    Parameters
    ----------
    max_pressure : array_like
        p_max of the contacts, NaN for failed cases. [Pa]
    where : str, optional
        Name of the contact for the message.

    Returns
    -------
    list of str

    Examples
    --------
    >>> contact_pressure_warnings([3e9, 5e9], where="inner contact")[0][:48]
    'inner contact: maximum contact pressure 5000 MPa'
    """
    return _pressure_messages(max_pressure, where, "case(s)")


def _pressure_messages(max_pressure, where, what):
    p = np.ravel(as_float("max_pressure", max_pressure))
    bad = p > ISO76_CONTACT_PRESSURE
    if not bad.any():
        return []
    return [(f"{where}: maximum contact pressure {np.nanmax(p) / 1e6:.0f} MPa exceeds the ISO 76 limit of "
            f"{ISO76_CONTACT_PRESSURE / 1e6:.0f} MPa ({_count(bad, what)}): permanent deformation of the raceways")]


def static_load_warnings(equivalent_load, static_load_rating):
    """Warn where the static equivalent load P0 exceeds the basic static load rating C0 (s0 < 1).

    Parameters
    ----------
    equivalent_load : array_like
        P0 of ISO 76 (:func:`bearinglab.ratings.static_equivalent_load`). [N]
    static_load_rating : float
        C0. [N]

    Returns
    -------
    list of str

    Examples
    --------
    >>> static_load_warnings([1e3, 2e4], 1e4)[0][:42]
    'static load: P0 = 20 kN exceeds C0 = 10 kN'
    """
    p0 = np.ravel(as_float("equivalent_load", equivalent_load))
    bad = p0 > static_load_rating
    if not bad.any():
        return []
    return [(f"static load: P0 = {np.nanmax(p0) / 1e3:.4g} kN exceeds C0 = {static_load_rating / 1e3:.4g} kN "
            f"({_count(bad)}; static safety s0 = {static_load_rating / np.nanmax(p0):.2g} < 1)")]


def deflection_warnings(deflection, ball_diameter, *, where="contact"):
    """Warn where the elastic approach is comparable to the ball (beyond the small strains of Hertz).

    Parameters
    ----------
    deflection : array_like
        Elastic approach delta of a contact. [m]
    ball_diameter : float
        D. [m]
    where : str, optional
        Name of the contact for the message.

    Returns
    -------
    list of str

    Examples
    --------
    >>> deflection_warnings([1e-6, 0.5e-3], 10e-3)[0][:44]
    'contact: elastic approach 500 um is 5.00 % o'
    """
    return _deflection_messages(deflection, ball_diameter, where, "case(s)")


def _deflection_messages(deflection, ball_diameter, where, what):
    delta = np.ravel(as_float("deflection", deflection))
    bad = delta > DEFLECTION_FRACTION * ball_diameter
    if not bad.any():
        return []
    worst = np.nanmax(delta)
    return [(f"{where}: elastic approach {worst * 1e6:.4g} um is {100 * worst / ball_diameter:.2f} % of the ball "
            f"diameter (above {100 * DEFLECTION_FRACTION:g} %, {_count(bad, what)}): Hertz theory does not hold")]


def truncation_warnings(contact_angle, semi_major_axis, groove_radius, shoulder_height, *, where="contact",
                        assumed=False):
    r"""Warn where the contact ellipse runs over the raceway shoulder.

    Parameters
    ----------
    contact_angle : array_like
        Operating contact angle of the contact, from the groove bottom. [rad]
    semi_major_axis : array_like
        Semi-axis a of the contact ellipse across the rolling direction (along the groove). [m]
    groove_radius : float
        r = f D. [m]
    shoulder_height : float
        Height of the shoulder above the groove bottom. [m]
    where : str, optional
        Name of the contact for the message.
    assumed : bool, optional
        The shoulder height is the default :data:`SHOULDER_HEIGHT_FRACTION`, not the bearing's; the
        message says so.

    Returns
    -------
    list of str

    Notes
    -----
    The shoulder edge is seen from the groove-curvature centre at :math:`\theta_s = \arccos(1 - h/r)`
    from the groove bottom; the ellipse reaches :math:`\alpha + a/r` (the semi-axis as an arc on the
    groove). Harris and Kotzalas, *Essential Concepts of Bearing Technology*, 5th ed., 2006, sec. 6.6
    (truncation of the contact ellipse), doi:10.1201/9781420006599.

    Examples
    --------
    >>> truncation_warnings(math.radians(60), 3e-3, 11.6e-3, 0.3 * 22.2e-3)[0][:32]
    'contact: the contact ellipse (to'
    """
    return _truncation_messages(contact_angle, semi_major_axis, groove_radius, shoulder_height, where, assumed,
                                "case(s)")


def _truncation_messages(contact_angle, semi_major_axis, groove_radius, shoulder_height, where, assumed, what):
    alpha = np.ravel(as_float("contact_angle", contact_angle))
    a = np.ravel(as_float("semi_major_axis", semi_major_axis))
    groove_radius = float(check_positive_finite("groove_radius", groove_radius, "m"))
    shoulder_height = float(check_nonnegative("shoulder_height", shoulder_height, "m"))
    edge = math.acos(max(-1.0, 1.0 - shoulder_height / groove_radius))
    reach = np.abs(alpha) + a / groove_radius
    bad = reach > edge
    if not bad.any():
        return []
    far = math.degrees(min(np.nanmax(reach), math.pi / 2))
    shoulder = (f"the shoulder at {math.degrees(edge):.1f} deg"
                + (f" (assumed height {SHOULDER_HEIGHT_FRACTION:g} D; give the bearing's shoulder heights)"
                   if assumed else ""))
    return [(f"{where}: the contact ellipse (to {far:.1f} deg from the groove bottom) runs over {shoulder} "
            f"({_count(bad, what)}): the ellipse is truncated and the pressure higher than computed")]


def viscosity_ratio_warnings(viscosity_ratio):
    """Warn where kappa = nu / nu1 is below 0.1, where ISO 281 does not define the life factor.

    Parameters
    ----------
    viscosity_ratio : array_like
        kappa. [-]

    Returns
    -------
    list of str

    Examples
    --------
    >>> viscosity_ratio_warnings([0.05])[0][:36]
    'lubrication: viscosity ratio κ = 0.0'
    """
    k = np.ravel(as_float("viscosity_ratio", viscosity_ratio))
    bad = k < MINIMUM_VISCOSITY_RATIO
    if not bad.any():
        return []
    return [(f"lubrication: viscosity ratio κ = {np.nanmin(k):.3g} is below {MINIMUM_VISCOSITY_RATIO:g} "
            f"({_count(bad)}): ISO 281 does not define a_ISO there; the film is too thin")]


def _shoulder(bearing, race):
    """The shoulder height of a raceway [m] and whether it is the assumed default."""
    h = getattr(bearing, f"{race}_shoulder_height", None)
    return (SHOULDER_HEIGHT_FRACTION * bearing.ball_diameter, True) if h is None else (h, False)


def _contact_checks(bearing, ball_loads, what="case(s)"):
    """Pressure, deflection and truncation warnings of loaded balls: ``ball_loads`` is a sequence of
    (race, Q, alpha) with flat arrays (unloaded balls, Q = 0 or NaN, are skipped); ``what`` names what
    the messages count (the cases, or the loaded balls). Returns the pressure messages and the
    deflection and truncation messages (in this order in the reports)."""
    from . import geometry, hertz

    d, dm = bearing.ball_diameter, bearing.pitch_diameter
    pressure, contacts = [], {}
    for race, q, alpha in ball_loads:
        q, alpha = np.ravel(q), np.ravel(alpha)
        loaded = (q > 0) & np.isfinite(alpha)
        if not loaded.any():
            continue
        q, alpha = q[loaded], alpha[loaded]
        f = bearing.inner_conformity if race == "inner" else bearing.outer_conformity
        sphere = race == "outer" and bearing.type == "self-aligning"  # curvature 1/R_o at any angle
        curv = geometry.raceway_curvature(d, dm, f, np.full_like(alpha, bearing.contact_angle) if sphere else alpha,
                                          race=race)
        contacts[race] = (alpha, f, hertz.point_contact(q, curv.curvature_sum, curv.curvature_difference,
                                                        bearing.reduced_modulus))
        pressure += _pressure_messages(contacts[race][2].p_max, f"{race} contact", what)
    shape = []
    for race, (_alpha, _f, pc) in contacts.items():
        shape += _deflection_messages(pc.delta, d, f"{race} contact", what)
    for race, (alpha, f, pc) in contacts.items():
        if race == "outer" and bearing.type == "self-aligning":
            continue  # a sphere across the ring's width: no shoulder
        if bearing.type == "thrust":  # a thrust washer's groove bottom is at 90 deg
            alpha = 0.5 * math.pi - np.abs(alpha)
        h, assumed = _shoulder(bearing, race)
        shape += _truncation_messages(alpha, pc.a, f * d, h, f"{race} contact", assumed, what)
    return pressure, shape


def _static_checks(bearing, radial_load, axial_load):
    """P0 of ISO 76 against C0, where the bearing has a static rating (the catalog's, or ISO 76's from
    the ball set) and ISO 76 defines P0 (X0, Y0 of its table 1 for the contact angle). Where the ratings
    cannot be computed from the ball set (a geometry outside the ISO tables, e.g. a contact angle of 87 deg
    and above), the check is left out and a warning says so: the analysis itself stands."""
    from . import ratings
    from .errors import InputError

    c0 = bearing.static_load_rating
    if c0 is None:
        if any(getattr(bearing, k) is None for k in ("n_balls", "ball_diameter", "pitch_diameter")):
            return []  # no C0 to compare with
        try:
            c0 = ratings.bearing_ratings(bearing).static_load_rating
        except InputError as exc:  # an optional check: it must not refuse the computation it checks
            return [(f"static load: the check of P0 against C0 is unavailable, as the bearing has no catalog C0 "
                     f"and the ratings cannot be computed from its ball set ({exc})")]
    try:
        p0 = ratings.static_equivalent_load(np.abs(radial_load), np.abs(axial_load), bearing.contact_angle or 0.0,
                                            bearing_type=bearing.type)
    except InputError:  # an angular-contact angle outside the rows of ISO 76 table 1: P0 is not defined
        return []
    return static_load_warnings(p0, c0)


def contact_warnings(bearing, axial_load, ball_load_inner, ball_load_outer, contact_angle_inner,
                     contact_angle_outer):
    """Every plausibility warning of a bearing under thrust, from its ball loads and contact angles.

    Parameters
    ----------
    bearing : BallBearing
        The bearing (ball set, conformities, materials; C0 from the catalog or ISO 76 where known).
    axial_load : array_like
        F_a of each case. [N]
    ball_load_inner, ball_load_outer : array_like
        Q_i, Q_e of each case. [N]
    contact_angle_inner, contact_angle_outer : array_like
        alpha_i, alpha_e of each case. [rad]

    Returns
    -------
    list of str
        Contact pressure, static load (P0 of the thrust against C0), deflection and ellipse truncation
        at both raceways; cases with NaN (failed) are skipped.
    """
    fa = np.ravel(as_float("axial_load", axial_load))
    ok = np.isfinite(fa) & np.isfinite(np.ravel(ball_load_inner)) & np.isfinite(np.ravel(ball_load_outer))
    if not ok.any():
        return []
    pressure, shape = _contact_checks(bearing, [
        ("inner", np.ravel(ball_load_inner)[ok], np.ravel(contact_angle_inner)[ok]),
        ("outer", np.ravel(ball_load_outer)[ok], np.ravel(contact_angle_outer)[ok])])
    return pressure + _static_checks(bearing, 0.0, fa[ok]) + shape


def combined_warnings(bearing, loads, ball_load_inner, ball_load_outer, contact_angle_inner,
                      contact_angle_outer, *, static=True):
    """Every plausibility warning of a bearing under combined load, from its load distribution.

    Parameters
    ----------
    bearing : BallBearing
        The bearing (ball set, conformities, materials; C0 from the catalog or ISO 76 where known).
    loads : array_like
        (..., 5): F_x, F_y, F_z [N], M_x, M_y [N m] of each case.
    ball_load_inner, ball_load_outer : array_like
        (..., Z): Q_i, Q_o of every ball, 0 (or NaN) for an unloaded ball. [N]
    contact_angle_inner, contact_angle_outer : array_like
        (..., Z): alpha_i, alpha_o of every ball. [rad]
    static : bool, optional
        Include the check of P0 against C0; False where the caller reports the static safety itself
        (the life analysis warns of s0 < 1).

    Returns
    -------
    list of str
        Contact pressure above ISO 76's 4200 MPa, P0 (ISO 76, from F_r = hypot(F_x, F_y) and F_a = abs(F_z);
        a moment is not part of P0) above C0, a deflection comparable to the ball and a contact ellipse
        over the shoulder, at every loaded ball of the converged cases. The light-load criteria at speed
        are the analysis's own (:func:`bearinglab.quasistatic.combined.combined_analysis` warnings).

    Examples
    --------
    >>> from bearinglab import catalog
    >>> b = catalog.get("7218B")
    >>> combined_warnings(b, [0, 0, 1e6, 0, 0], [60e3] * 16, [60e3] * 16, [0.7] * 16, [0.7] * 16)[0]
    'inner contact: maximum contact pressure 5034 MPa exceeds the ISO 76 limit of 4200 MPa (16 of 16 loaded balls): permanent deformation of the raceways'
    """
    f = np.reshape(as_float("loads", loads), (-1, 5))
    q_i, q_o = np.reshape(ball_load_inner, (len(f), -1)), np.reshape(ball_load_outer, (len(f), -1))
    ok = np.all(np.isfinite(f), axis=1) & np.any(np.isfinite(q_i), axis=1)
    if not ok.any():
        return []
    a_i = np.reshape(contact_angle_inner, q_i.shape)
    a_o = np.reshape(contact_angle_outer, q_o.shape)
    # counted over the loaded balls, not the cases
    pressure, shape = _contact_checks(bearing, [("inner", q_i[ok], a_i[ok]), ("outer", q_o[ok], a_o[ok])],
                                      "loaded balls")
    p0 = _static_checks(bearing, np.hypot(f[ok, 0], f[ok, 1]), f[ok, 2]) if static else []
    return pressure + p0 + shape


def high_speed_warnings(bearing, state):
    """Every plausibility warning of a high-speed state under thrust (spec 004).

    Parameters
    ----------
    bearing : BallBearing
        The bearing solved.
    state : HighSpeedState
        From :func:`bearinglab.quasistatic.high_speed_analysis` or :func:`~bearinglab.quasistatic.sweep`.

    Returns
    -------
    list of str
        :func:`contact_warnings` of the converged cases, and the light-load criteria
        (:func:`bearinglab.quasistatic.light_load.light_load_warnings`: SKF's minimum load 0.01 C with the
        bearing's C, and the outer contact angle driven to zero).
    """
    from .quasistatic.light_load import light_load_warnings

    ok = np.ravel(np.asarray(state.converged, dtype=bool))
    if not ok.any():
        return []

    def pick(name):
        return np.ravel(getattr(state, name))[ok]

    msgs = contact_warnings(bearing, pick("axial_load"), pick("ball_load_inner"), pick("ball_load_outer"),
                            pick("contact_angle_inner"), pick("contact_angle_outer"))
    from .ratings import bearing_ratings

    r = bearing_ratings(bearing)  # the catalog's C and C0 first: the minimum load is 0.01 C
    msgs += light_load_warnings(pick("axial_load"), pick("contact_angle_inner"), pick("contact_angle_outer"),
                                pick("shaft_speed"), bearing.n_balls, bearing.ball_diameter, bearing.pitch_diameter,
                                bearing.contact_angle, density=bearing.ball_material.density,
                                bearing_type=bearing.type, inner_conformity=bearing.inner_conformity or 0.52,
                                outer_conformity=bearing.outer_conformity or 0.53,
                                dynamic_load_rating=r.dynamic_load_rating,
                                static_load_rating=r.static_load_rating)
    return msgs
