r"""Plausibility of manufacturing errors for the first-order runout model (issue 20 item 8).

The runout method of spec 003 is first order in the errors: it is built for errors of micrometres on
balls and grooves of millimetres. This module refuses errors that cannot be manufacturing errors of
the bearing at all, and names those that leave the range where the first-order model holds.

Limits
------
ERROR_LIMIT             fraction of the ball diameter D_w at which an error is refused (5 %)
TILT_LIMIT              largest ring tilt accepted, 2 pi [rad]
LINEAR_LIMIT            fraction of the groove distance A0 beyond which a displacement is doubtful (5 %)

Checks
------
error_bounds            the largest magnitude each error can reach (ball deficits, each ring's normal
                        deviation at tau0, each tilt) [m, rad]
check_errors            refuse the absurd (InputError), list the doubtful (messages); for the errors
displacement_warnings   the doubtful displacements of a solution: the linearisation's neglected term

Why these limits
----------------
* **Refused: an error of 5 % of D_w or more** (360 um on a 7.144 mm ball). Ball grades (ISO 3290) and
  ring tolerance classes (ISO 492, ``data/tolerance_classes.toml``) allow 0.1 to some tens of
  micrometres; 5 % of D_w is also about the whole groove distance A0 = (f_i + f_o - 1) D_w of usual
  conformities (0.04 to 0.06 D_w), so an error of that size takes the ball out of its groove geometry
  and no first-order result means anything. Today such an input (1 m on a 7 mm ball) gave a displacement
  of -1.93 m with no word.
* **Refused: a tilt beyond 2 pi.** An angle past one turn is a unit mistake (degrees typed as radians),
  not a tilt.
* **Warned: a displacement abs(u) of 5 % of A0 or more, or a tilt that moves the raceway by as much.** The
  first-order reduction s(theta) of eq. (5.1) drops a term of about abs(delta_perp)^2 / (2 A0) (spec 003
  sections 9 and 15, example 4; :func:`~bearinglab.runout.exact_reduction` computes it exactly), with
  delta_perp the displacement across the contact normal, at most abs(u). At abs(u) = 0.05 A0 that term is
  2.5 % of the displacement itself, and because the displacement is several times the errors (1 / sin
  tau0, 3.9 at 15 deg), around 10 % of the errors; beyond it the result is an extrapolation: check it
  with :func:`~bearinglab.runout.exact_reduction`.

Units: SI (m, rad).
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError
from .deviations import FourierSeries, _combined

__all__ = ["ERROR_LIMIT", "LINEAR_LIMIT", "TILT_LIMIT", "check_errors", "displacement_warnings", "error_bounds"]

#: An error of this fraction of the ball diameter or more is refused (see the module notes). [-]
ERROR_LIMIT = 0.05
#: A ring tilt beyond this is refused (one turn: a unit mistake). [rad]
TILT_LIMIT = 2.0 * math.pi
#: A displacement (or a tilt's raceway shift) of this fraction of the groove distance A0 or more is
#: beyond the first-order model's range, and warned about (see the module notes). [-]
LINEAR_LIMIT = 0.05


def _amplitude(series):
    """Largest |sum_k c_k cos(k t) + s_k sin(k t)| over t is at most sum_k hypot(c_k, s_k) (s_0 ignored);
    the largest over any leading axes (Monte Carlo samples)."""
    c = np.asarray(series.cos, dtype=float)
    s = np.array(series.sin, dtype=float, copy=True)
    s[..., 0] = 0.0
    return float(np.max(np.sum(np.hypot(c, s), axis=-1))) if c.size else 0.0


def _tilt_bound(value, psi):
    """Largest |tilt| [rad]: a number, the amplitude sum of a series, or a callable's values at psi."""
    if isinstance(value, FourierSeries):
        return _amplitude(value)
    if callable(value):
        return float(np.max(np.abs(value(np.asarray(psi, dtype=float))), initial=0.0))
    return float(np.max(np.abs(np.asarray(value, dtype=float)), initial=0.0))


def error_bounds(geometry, errors, rotation_angle=0.0):
    """The largest magnitude each error can reach.

    Parameters
    ----------
    geometry : SpindleGeometry
        Nominal geometry (its contact angle tau0 combines each ring's errors).
    errors : ManufacturingErrors
        The errors.
    rotation_angle : array_like, optional
        psi at which a tilt given as a callable is evaluated. [rad]

    Returns
    -------
    dict
        ``ball_outer_deficit``, ``ball_inner_deficit`` (largest abs(value) over the balls), ``outer``,
        ``inner`` (bound of the ring's normal deviation at tau0: the sum of the amplitudes of its
        combined Fourier series) [m]; ``tilt_x``, ``tilt_y`` [rad].

    Examples
    --------
    >>> from bearinglab.runout import RacewayErrors, fourier_series, geometry_from_catalog, manufacturing_errors
    >>> g = geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(15))
    >>> e = manufacturing_errors(16, inner=RacewayErrors(radial=fourier_series({2: 1e-6})))
    >>> print(f"{error_bounds(g, e)['inner'] * 1e6:.6f}")  # cos(15 deg) x 1 um
    0.965926
    """
    tau0 = geometry.contact_angle
    out = {name: float(np.max(np.abs(getattr(errors, name)), initial=0.0))
           for name in ("ball_outer_deficit", "ball_inner_deficit")}
    for ring, sign in (("outer", 1.0), ("inner", -1.0)):
        series = _combined(getattr(errors, ring), tau0, sign)
        out[ring] = 0.0 if series is None else _amplitude(series)
    for name in ("tilt_x", "tilt_y"):
        out[name] = _tilt_bound(getattr(errors, name), rotation_angle)
    return out


def check_errors(geometry, errors, rotation_angle=0.0):
    """Refuse errors no bearing can have; list those beyond the first-order model's range.

    Parameters
    ----------
    geometry : SpindleGeometry
        Nominal geometry.
    errors : ManufacturingErrors
        The errors.
    rotation_angle : array_like, optional
        The positions psi (a tilt given as a callable is evaluated there). [rad]

    Returns
    -------
    list of str
        Warnings: a tilt that moves the raceway at the ball circle by ``LINEAR_LIMIT`` A0 or more.

    Raises
    ------
    InputError
        An error of ``ERROR_LIMIT`` D_w or more (naming it, its size and the limit), or a tilt beyond
        ``TILT_LIMIT``.
    """
    bounds = error_bounds(geometry, errors, rotation_angle)
    d_w = 2.0 * geometry.ball_radius
    limit = ERROR_LIMIT * d_w
    for name in ("ball_outer_deficit", "ball_inner_deficit", "outer", "inner"):
        if not bounds[name] < limit:
            what = name if name.startswith("ball") else f"{name} raceway errors (normal deviation at tau0)"
            raise InputError(f"{what}: up to {bounds[name] * 1e6:.6g} um, which is not a manufacturing error "
                             f"of a bearing with {d_w * 1e3:.6g} mm balls: errors must stay below "
                             f"{ERROR_LIMIT:g} D_w = {limit * 1e6:.6g} um (the first-order runout model is "
                             "built for micrometres)")
    msgs = []
    for name in ("tilt_x", "tilt_y"):
        if not bounds[name] <= TILT_LIMIT:
            raise InputError(f"{name} must be within 2 pi [rad] (one turn), got up to {bounds[name]:.6g} rad "
                             "(a tilt in degrees given as radians?)")
        shift = bounds[name] * geometry.ball_centre_radius
        if shift >= LINEAR_LIMIT * geometry.groove_distance:
            msgs.append(f"{name} of up to {bounds[name] * 1e3:.6g} mrad moves the raceway at the ball circle by "
                        f"{shift * 1e6:.6g} um >= {LINEAR_LIMIT:g} A0 = "
                        f"{LINEAR_LIMIT * geometry.groove_distance * 1e6:.6g} um: beyond the range of the "
                        "first-order runout model (check with runout.exact_reduction)")
    return msgs


def displacement_warnings(geometry, x, y, z):
    """The doubtful displacements of a solution: abs(u) >= ``LINEAR_LIMIT`` A0.

    Parameters
    ----------
    geometry : SpindleGeometry
        Nominal geometry.
    x, y, z : array_like
        Displacement of the inner-ring centre. [m]

    Returns
    -------
    list of str
        One message if any position is beyond the limit (its count and the largest abs(u)), else empty.

    Notes
    -----
    The neglected term of the reduction (5.1) is about abs(delta_perp)^2 / (2 A0) <= abs(u)^2 / (2 A0), i.e.
    abs(u) / (2 A0) of the displacement: 2.5 % at the limit (module notes).
    """
    u = np.sqrt(np.square(x) + np.square(y) + np.square(z))
    limit = LINEAR_LIMIT * geometry.groove_distance
    bad = u >= limit
    if not np.any(bad):
        return []
    worst = float(np.max(u))
    return [(f"{int(np.sum(bad))} position(s) displaced by up to {worst * 1e6:.6g} um >= {LINEAR_LIMIT:g} A0 = "
            f"{limit * 1e6:.6g} um: the first-order runout model neglects about |u|^2 / (2 A0) = "
            f"{worst**2 / (2.0 * geometry.groove_distance) * 1e6:.3g} um there; the errors are beyond its "
            "range (check with runout.exact_reduction)")]
