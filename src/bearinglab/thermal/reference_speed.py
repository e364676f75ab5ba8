r"""The thermal reference speed of ISO 15312: where the SKF friction power at the reference conditions equals
the heat the bearing sheds there.

Thermal reference speed
-----------------------
thermal_reference_speed        n_theta_r where the SKF friction power at the reference load and viscosity
                               equals the reference heat flow
ThermalReferenceSpeed          its result

References are those of :mod:`bearinglab.thermal`.
"""

from __future__ import annotations

import math
import warnings
from typing import NamedTuple

import numpy as np

from .. import _solve
from .._validate import check_positive
from .balance import _bracketed_root
from .heat import REFERENCE_CONDITIONS, reference_heat_flow

__all__ = ["ThermalReferenceSpeed", "thermal_reference_speed"]


class ThermalReferenceSpeed(NamedTuple):
    """ISO 15312's thermal reference speed by the SKF friction model (SI); NaN where none was found."""

    speed: float  # n_theta_r [rad/s]
    reference_heat_flow: float  # q_r A_r [W]
    radial_load: float  # P_1r = 0.05 C_0r [N]
    kinematic_viscosity: float  # nu_r [m^2/s]
    friction_moment: float  # M at n_theta_r [N m]; M n_theta_r = q_r A_r
    iterations: int  # of the root solve
    warnings: tuple  # messages


#: Speeds scanned for the first crossing of P_f(n) = q_r A_r [rpm]: the SKF model's friction power is not
#: monotonic in the speed at 12 mm^2/s (its starvation factor Phi_rs lowers M faster than n rises above a
#: peak), so the *lowest* speed of the balance is sought by scanning before the bracketed solve.
_SCAN_RPM = np.geomspace(10.0, 1e7, 421)


def thermal_reference_speed(bearing, *, static_load_rating=None, drag_loss_factor=None,
                            rtol=_solve.THERMAL_RTOL, max_iter=_solve.THERMAL_MAX_ITER, **friction_options):
    r"""Thermal reference speed of ISO 15312 from the SKF friction model at the reference conditions.

    Parameters
    ----------
    bearing : BallBearing
        A radial ball bearing (deep groove; angular contact with ``constants=``): bore, outside
        diameter, width and C_0 (else ISO 76 from the ball set).
    static_load_rating : float, optional
        C_0r in place of the bearing's. [N]
    drag_loss_factor : float, optional
        V_M of SKF's drag-loss diagram at H/d_m with H = D_w/2 (ISO 15312's oil bath reaches the middle
        of the lowest ball); without it the bath's drag moment is left out (a warning says so). [-]
    rtol : float, optional
        Relative balance residual abs(P_f - q_r A_r) / (q_r A_r) at which the solve stops.
    max_iter : int, optional
        Iterations of the bracketed solve.

    Other Parameters
    ----------------
    **friction_options
        Passed to :func:`bearinglab.friction.skf_for_bearing` (``constants`` of an angular-contact
        series, ``ehl_coefficient`` ...).

    Returns
    -------
    ThermalReferenceSpeed

    Notes
    -----
    ISO 15312 [1] defines the thermal reference speed :math:`n_{\theta r}` as the inner-ring speed at
    which the friction power of an open bearing at the reference conditions equals the reference heat
    flow: :math:`M(n)\,n = q_r A_r` with the radial load :math:`P_{1r} = 0.05\,C_{0r}`, a mineral oil
    of 12 mm^2/s at the reference temperature of 70 degC and an oil bath up to the middle of the lowest
    rolling element [4] [5]. The standard computes M with its own coefficients f_0r, f_1r; here M is
    the SKF four-term model [2] (as bearinglab's thermal balance uses), with K_rs = 3e-8 of an oil bath
    (the value of SKF's low-level oil bath and oil jet alike). Seals are left out (ISO 15312 rates open
    bearings). The lowest root is taken: the model's power is scanned on a log grid of speeds from 10
    to 10^7 rpm, then the bracket of its first crossing is solved (Illinois regula falsi). Against
    SKF's catalogue reference speeds of the deep-groove series the result is within a factor 0.6 to 2
    (see the theory page's table): an estimate, not the maker's rating.

    Examples
    --------
    >>> from bearinglab import catalog
    >>> from bearinglab.units import RPM
    >>> r = thermal_reference_speed(catalog.get("6205"))
    >>> print(f"{r.speed / RPM:.0f} rpm at {r.reference_heat_flow:.2f} W")
    35400 rpm at 58.06 W
    """
    from ..friction import skf_for_bearing

    c = REFERENCE_CONDITIONS
    d, big, width = bearing.require("bore", "outside_diameter", "width")
    if static_load_rating is None:
        static_load_rating = bearing.static_load_rating
        if static_load_rating is None:
            from ..ratings import bearing_ratings

            static_load_rating = bearing_ratings(bearing).static_load_rating
    c0 = float(check_positive("static_load_rating", static_load_rating, "N"))
    q = float(reference_heat_flow(d, big, width))
    load = c["load_ratio"] * c0
    nu = c["viscosity"]
    options = dict(friction_options, seals=0)
    notes = []
    if drag_loss_factor is None:
        lubrication = "oil-jet"  # the oil bath's K_rs (3e-8) without its drag moment
        notes.append("thermal reference speed: the oil bath's drag moment is left out (no drag loss factor "
                     "V_M given), so the speed is on the high side")
    else:
        lubrication = "oil-bath"
        dw = bearing.require("ball_diameter")
        options.update(oil_level=0.5 * dw, drag_loss_factor=drag_loss_factor)
    caught = []

    def power(n):
        with warnings.catch_warnings(record=True) as rec:
            warnings.simplefilter("always")
            m = skf_for_bearing(bearing, load, 0.0, n, nu, lubrication=lubrication, **options)
        caught.extend(str(w.message) for w in rec)
        return m.power_loss

    from ..units import RPM

    scan = _SCAN_RPM * RPM
    excess = power(scan) - q
    above = np.flatnonzero(excess >= 0)
    if above.size == 0 or above[0] == 0:
        notes.append(f"thermal reference speed: the friction power does not cross the reference heat flow "
                     f"{q:.4g} W between {_SCAN_RPM[0]:g} and {_SCAN_RPM[-1]:g} rpm")
        return ThermalReferenceSpeed(math.nan, q, load, nu, math.nan, 0, tuple(dict.fromkeys(notes)))
    k = above[0]
    lo, hi = scan[k - 1:k], scan[k:k + 1]

    def f(n, active):
        return q - power(n)

    root, _, it = _bracketed_root(f, lo, hi, -excess[k - 1:k], -excess[k:k + 1], lambda n: np.full(n.shape, q),
                                  1e-12 * hi, rtol, max_iter)
    n_r = float(root[0])
    moment = q / n_r
    if getattr(bearing, "seal", None) is not None or any("sealed" in m or "shields" in m for m in caught):
        notes.append("thermal reference speed: ISO 15312 rates open bearings; the seals are left out")
    return ThermalReferenceSpeed(n_r, q, load, nu, moment, int(it[0]), tuple(dict.fromkeys(notes)))
