r"""Steady bearing temperature: the friction power of the SKF model against the heat carried away.

Heat carried away
-----------------
reference_surface              A_r = pi B (D + d), the reference heat-emitting surface of a radial bearing
reference_heat_flow_density    q_r of ISO 15312 from A_r
reference_conductance          q_r A_r / (70 - 20) K: the housing's heat conductance of ISO 15312's
                               reference conditions, taken as linear in the temperature rise
oil_flow_conductance           rho Q c_p of an oil jet or circulation
heat_dissipated                P_d = G (T - T_ambient) + G_oil (T - T_oil,in)

Balance
-------
thermal_balance                T where M(nu(T)) omega = P_d(T), batched; runaway when there is none
ThermalBalance                 its result

Thermal reference speed (ISO 15312)
-----------------------------------
reference_heat_flow            q_r A_r: the heat a bearing sheds at ISO 15312's reference conditions
thermal_reference_speed        n_theta_r where the SKF friction power at the reference load and viscosity
                               equals that heat flow
ThermalReferenceSpeed          its result

Ring temperatures (coupling to the mounted clearance)
-----------------------------------------------------
ring_temperatures              inner and outer ring from the lumped bearing temperature and a split
clearance_conditions           the same as :class:`bearinglab.mounting.chain.Conditions`
RingTemperatures               their result

The friction moment is :func:`bearinglab.friction.skf_for_bearing` at the viscosity nu(T) of the oil
(ASTM D341 through nu40 and nu100, :mod:`bearinglab.ratings.lubrication`); M rises as the oil cools,
P_d as the bearing heats, so the balance has one root between the ambient and a safe maximum when it
has any.

References
----------
.. [1] ISO 15312:2003, *Rolling bearings - Thermal speed rating - Calculation and coefficients*:
   the reference conditions (bearing 70 degC, ambient 20 degC), the reference heat-emitting surface
   A_r = pi B (D + d) of radial bearings and the reference heat flow density q_r = 16 kW/m^2 for
   A_r <= 50 000 mm^2, q_r = 16 (A_r / 50 000 mm^2)^-0.34 kW/m^2 above.
.. [2] SKF, *Rolling bearings*, catalogue PUB BU/P1 17000 EN, 2018, "Friction" (the frictional moment)
   and "Speeds" (the thermal reference speed and its heat balance).
.. [3] T. A. Harris and M. N. Kotzalas, *Advanced Concepts of Bearing Technology*, 5th ed., CRC Press,
   2006, ch. 6 (friction heat generation and the thermal balance of a bearing).
.. [4] Schaeffler, *Rolling bearings*, catalogue HR 1, 2006, pp. 62-65, "Speeds": ISO 15312's reference
   conditions (ambient 20 degC, outer ring 70 degC, P_1r = 0.05 C_0r, 12 mm^2/s (ISO VG 32) for radial
   bearings), q_r = 0.016 W/mm^2 for A_r <= 50 000 mm^2 and 0.016 (A_r/50 000)^-0.34 W/mm^2 above
   (radial bearings), A_r = pi B (D + d); DIN 732's heat flow through the seats Q_S = k_q A_r dT
   (linear in the temperature rise; k_q 0.2-1.0e-6 kW/(mm^2 K) for A_r up to 25 000 mm^2).
.. [5] SKF, "Reference speeds" (skf.com, rolling bearings, principles, speeds): ISO 15312:2003's reference
   conditions, the bearing temperature "measured on the bearing stationary outer ring", oil bath up to
   the middle of the lowest rolling element; bearings with contact seals are not rated.
.. [6] KRW, *Rolling bearings* catalogue, "Bearing clearance", p. 95: the radial clearance is reduced "when
   the inner ring becomes warmer than the outer ring, which is usually the case"; a temperature
   difference above 10 K calls for a larger clearance group than Normal.
"""

from __future__ import annotations

import math
import warnings
from typing import NamedTuple

import numpy as np

from . import _solve
from ._validate import check_nonnegative, check_positive
from .errors import ConvergenceError, InputError

__all__ = [
    "REFERENCE_CONDITIONS",
    "RING_TEMPERATURE_DIFFERENCE",
    "RingTemperatures",
    "ThermalBalance",
    "ThermalReferenceSpeed",
    "clearance_conditions",
    "heat_dissipated",
    "oil_flow_conductance",
    "reference_conductance",
    "reference_heat_flow",
    "reference_heat_flow_density",
    "reference_surface",
    "ring_temperatures",
    "thermal_balance",
    "thermal_reference_speed",
]

#: ISO 15312 [1]: reference bearing temperature and ambient [K], the limit of A_r of the constant heat
#: flow density [m^2], that density [W/m^2] and the exponent of its decrease above the limit (radial
#: bearings); the reference load of a radial bearing as a fraction of C_0r [-] and the oil's kinematic
#: viscosity at the reference temperature [m^2/s]. All checked against Schaeffler HR 1 (2006), p. 62 [4]
#: (q_r = 0.016 W/mm^2, 0.016 (A_r/50 000)^-0.34 W/mm^2, P_1r = 0.05 C_0r, 12 mm^2/s, ISO VG 32) and
#: SKF's "Reference speeds" [5] (70 degC bearing, 20 degC ambient, 0.05 C0, 12 mm^2/s at 70 degC).
REFERENCE_CONDITIONS = {"bearing_temperature": 343.15, "ambient": 293.15, "surface_limit": 50_000e-6,
                        "heat_flow_density": 16e3, "exponent": -0.34, "load_ratio": 0.05,
                        "viscosity": 12e-6}
#: Inner ring warmer than the outer by this much by default [K]: the upper end of the ring temperature
#: difference that Normal clearance is made for (KRW catalogue, p. 95 [6]: more than 10 K calls for a
#: larger clearance group). A design value, not a prediction; give the machine's own where known.
RING_TEMPERATURE_DIFFERENCE = 10.0
_T40, _T100 = 313.15, 373.15


def reference_surface(bore, outside_diameter, width):
    r"""Reference heat-emitting surface A_r = pi B (D + d) of a radial bearing (ISO 15312 [1]).

    Parameters
    ----------
    bore, outside_diameter, width : array_like
        d, D and B. [m]

    Returns
    -------
    ndarray
        A_r. [m^2]

    Examples
    --------
    >>> print(f"{reference_surface(0.025, 0.052, 0.015) * 1e6:.1f} mm^2")
    3628.5 mm^2
    """
    d = check_positive("bore", bore, "m")
    big = check_positive("outside_diameter", outside_diameter, "m")
    b = check_positive("width", width, "m")
    return (np.pi * b * (big + d))[()]


def reference_heat_flow_density(reference_surface):
    r"""Reference heat flow density q_r of ISO 15312 [1] for a reference surface A_r.

    Parameters
    ----------
    reference_surface : array_like
        A_r. [m^2]

    Returns
    -------
    ndarray
        q_r: 16 kW/m^2 up to A_r = 50 000 mm^2, then 16 (A_r / 50 000 mm^2)^-0.34 kW/m^2. [W/m^2]

    Examples
    --------
    >>> print(reference_heat_flow_density([0.01, 0.2]).round(1).tolist())
    [16000.0, 9986.6]
    """
    a = check_positive("reference_surface", reference_surface, "m^2")
    c = REFERENCE_CONDITIONS
    return np.where(a <= c["surface_limit"], c["heat_flow_density"],
                    c["heat_flow_density"] * (a / c["surface_limit"]) ** c["exponent"])[()]


def reference_conductance(bore, outside_diameter, width):
    r"""Heat conductance from the bearing to the ambient of ISO 15312's reference conditions.

    Parameters
    ----------
    bore, outside_diameter, width : array_like
        d, D and B. [m]

    Returns
    -------
    ndarray
        G = q_r A_r / (70 degC - 20 degC). [W/K]

    Notes
    -----
    ISO 15312 [1] fixes the heat flow q_r A_r that a bearing in a reference housing carries away at
    70 degC with a 20 degC ambient. Dividing by those 50 K makes it a conductance, which assumes the
    heat flow proportional to the temperature rise (conduction through the housing and shaft;
    convection and radiation are not quite linear). This is the model's assumption, not the
    standard's: a measured conductance or thermal resistance of the real housing is better.

    Examples
    --------
    >>> print(f"{reference_conductance(0.025, 0.052, 0.015):.4f} W/K")
    1.1611 W/K
    """
    a = reference_surface(bore, outside_diameter, width)
    c = REFERENCE_CONDITIONS
    return (reference_heat_flow_density(a) * a / (c["bearing_temperature"] - c["ambient"]))[()]


def oil_flow_conductance(volume_flow, density, specific_heat):
    r"""Heat carried by an oil flow per kelvin of its temperature rise, rho Q c_p.

    Parameters
    ----------
    volume_flow : array_like
        Q >= 0. [m^3/s]
    density : array_like
        rho. [kg/m^3]
    specific_heat : array_like
        c_p of the oil, about 1.9-2.1 kJ/(kg K) for mineral oils. [J/(kg K)]

    Returns
    -------
    ndarray
        G_oil. [W/K]

    Examples
    --------
    >>> print(f"{oil_flow_conductance(1e-3 / 60, 870.0, 1950.0):.3f} W/K")
    28.275 W/K
    """
    q = check_nonnegative("volume_flow", volume_flow, "m^3/s")
    rho = check_positive("density", density, "kg/m^3")
    cp = check_positive("specific_heat", specific_heat, "J/(kg K)")
    return (rho * q * cp)[()]


def heat_dissipated(temperature, ambient, conductance, *, oil_flow_conductance=0.0, oil_inlet_temperature=None):
    r"""Heat carried away from a bearing at a temperature.

    Parameters
    ----------
    temperature : array_like
        Bearing temperature T. [K]
    ambient : array_like
        T_ambient. [K]
    conductance : array_like
        G to the ambient (1 / thermal resistance). [W/K]
    oil_flow_conductance : array_like, optional
        G_oil = rho Q c_p of an oil flow through the bearing. [W/K]
    oil_inlet_temperature : array_like, optional
        T_oil,in; the ambient when not given. [K]

    Returns
    -------
    ndarray
        P_d = G (T - T_ambient) + G_oil (T - T_oil,in): the oil leaves at the bearing's temperature. [W]

    Examples
    --------
    >>> print(f"{heat_dissipated(343.15, 293.15, 1.2, oil_flow_conductance=10.0):.1f} W")
    560.0 W
    """
    t = check_positive("temperature", temperature, "K")
    ta = check_positive("ambient", ambient, "K")
    g = check_nonnegative("conductance", conductance, "W/K")
    go = check_nonnegative("oil_flow_conductance", oil_flow_conductance, "W/K")
    tin = ta if oil_inlet_temperature is None else check_positive("oil_inlet_temperature", oil_inlet_temperature, "K")
    return (g * (t - ta) + go * (t - tin))[()]


class ThermalBalance(NamedTuple):
    """Steady bearing temperature and its heat balance (SI); NaN where no steady state exists."""

    temperature: np.ndarray  # T [K]
    kinematic_viscosity: np.ndarray  # nu(T) [m^2/s]
    friction_moment: np.ndarray  # M(T) [N m]
    friction_power: np.ndarray  # M omega [W]
    heat_dissipated: np.ndarray  # P_d(T) [W]
    viscosity_ratio: np.ndarray  # kappa = nu / nu1 (ISO 281) [-]
    iterations: np.ndarray  # of the root solve
    steady: np.ndarray  # a steady state exists below the maximum temperature
    warnings: tuple  # messages


def _bracketed_root(f, lo, hi, f_lo, f_hi, scale, xtol, rtol, max_iter):
    """Illinois regula falsi on [lo, hi] for all cases at once (f(lo) > 0 > f(hi)); a bisection step
    where the secant would leave the bracket or stalls. Returns the root, f there and the iterations."""
    x = 0.5 * (lo + hi)
    fx = np.full_like(x, np.inf)
    it = np.zeros(x.shape, dtype=int)
    active = np.ones(x.shape, dtype=bool)
    side = np.zeros(x.shape, dtype=int)  # which end was kept twice (Illinois halves its f)
    for k in range(1, max_iter + 1):
        with np.errstate(invalid="ignore", divide="ignore"):
            sec = hi - f_hi * (hi - lo) / (f_hi - f_lo)
        bad = ~np.isfinite(sec) | (sec <= lo) | (sec >= hi)
        x_new = np.where(bad | (k % 8 == 0), 0.5 * (lo + hi), sec)  # every 8th step bisects: no stall
        x = np.where(active, x_new, x)
        fx_new = f(x, active)
        fx = np.where(active, fx_new, fx)
        it = np.where(active, k, it)
        pos = fx > 0
        keep_hi = active & pos  # root above x: x is the new lower end
        keep_lo = active & ~pos
        lo, f_lo = np.where(keep_hi, x, lo), np.where(keep_hi, fx, f_lo)
        hi, f_hi = np.where(keep_lo, x, hi), np.where(keep_lo, fx, f_hi)
        f_hi = np.where(keep_hi & (side == 1), 0.5 * f_hi, f_hi)
        f_lo = np.where(keep_lo & (side == -1), 0.5 * f_lo, f_lo)
        side = np.where(keep_hi, 1, np.where(keep_lo, -1, side))
        done = (np.abs(fx) <= rtol * scale(x)) | (hi - lo <= xtol)
        active &= ~done
        if not active.any():
            return x, fx, it
    raise ConvergenceError("thermal.thermal_balance", iterations=max_iter, residual=float(np.max(np.abs(fx))),
                           estimate=x)


def thermal_balance(bearing, radial_load, axial_load, shaft_speed, ambient, viscosity_40, viscosity_100, *,
                    conductance=None, oil_flow_conductance=0.0, oil_inlet_temperature=None, lubrication="oil-jet",
                    maximum_temperature=423.15, xtol=_solve.THERMAL_XTOL, rtol=_solve.THERMAL_RTOL,
                    max_iter=_solve.THERMAL_MAX_ITER, **friction_options):
    r"""Steady bearing temperature where the SKF friction power equals the heat carried away.

    Parameters
    ----------
    bearing : BallBearing
        For the SKF model (bore, outside diameter, series or constants; seals) and, without
        ``conductance``, its width for ISO 15312's reference surface.
    radial_load, axial_load : array_like
        F_r, F_a >= 0. [N]
    shaft_speed : array_like
        omega > 0. [rad/s]
    ambient : array_like
        T_ambient. [K]
    viscosity_40, viscosity_100 : float
        The oil's nu at 40 and 100 degC (its nu(T) by ASTM D341). [m^2/s]
    conductance : array_like, optional
        Heat conductance to the ambient, 1 / thermal resistance; default :func:`reference_conductance`
        of the bearing (a warning says so). [W/K]
    oil_flow_conductance : array_like, optional
        rho Q c_p of an oil jet (:func:`oil_flow_conductance`). [W/K]
    oil_inlet_temperature : array_like, optional
        Of the oil jet; the ambient by default. [K]
    lubrication : str, optional
        The SKF model's lubrication method (K_rs). [-]
    maximum_temperature : float, optional
        The safe limit: above it there is no steady state worth the name (thermal runaway). [K]
    xtol, rtol : float, optional
        Bracket width [K] and relative balance residual at which a case is converged.
    max_iter : int, optional
        Iterations of the root solve.

    Other Parameters
    ----------------
    **friction_options
        Passed to :func:`bearinglab.friction.skf_for_bearing` (``constants`` of an angular-contact
        series, ``sliding_friction_coefficient``, ...).

    Returns
    -------
    ThermalBalance

    Notes
    -----
    Solves :math:`P_f(T) = M(\nu(T))\,\omega = G (T - T_a) + G_{oil}(T - T_{in}) = P_d(T)` on
    [min(T_a, T_in), T_max] for all cases together (Illinois regula falsi, bracketed). The SKF moment
    depends on the temperature only through nu; the bearing is one lumped temperature (rings, balls and
    oil alike), as in ISO 15312 and SKF's thermal reference speed [2]. Where :math:`P_f > P_d` at T_max
    the case has no steady state below the limit: its fields are NaN, ``steady`` is False and a
    thermal-runaway warning says so.

    Examples
    --------
    >>> from bearinglab import catalog
    >>> from bearinglab.units import RPM
    >>> r = thermal_balance(catalog.get("6205-2RS"), 1000.0, 0.0, 6000 * RPM, 293.15, 32e-6, 5.4e-6,
    ...                     conductance=1.0)
    >>> print(f"{r.temperature - 273.15:.2f} degC, {r.friction_power:.3f} W = {r.heat_dissipated:.3f} W")
    39.54 degC, 19.538 W = 19.538 W
    """
    from .friction import skf_for_bearing
    from .ratings import lubrication as lub

    fr = check_nonnegative("radial_load", radial_load, "N")
    fa = check_nonnegative("axial_load", axial_load, "N")
    w = check_positive("shaft_speed", shaft_speed, "rad/s")
    ta = check_positive("ambient", ambient, "K")
    t_max = float(check_positive("maximum_temperature", maximum_temperature, "K"))
    a, b = lub.walther_constants((_T40, _T100), (viscosity_40, viscosity_100))
    notes = []
    if conductance is None:
        d, big, width = bearing.require("bore", "outside_diameter", "width")
        conductance = reference_conductance(d, big, width)
        notes.append(f"heat dissipation: no thermal resistance given, so ISO 15312's reference heat flow "
                     f"({float(conductance):.4g} W/K, its reference housing) is used; give the housing's own")
    g = check_nonnegative("conductance", conductance, "W/K")
    go = check_nonnegative("oil_flow_conductance", oil_flow_conductance, "W/K")
    tin = ta if oil_inlet_temperature is None else check_positive("oil_inlet_temperature", oil_inlet_temperature, "K")
    if np.any(g + go <= 0):
        raise InputError("conductance: no heat leaves the bearing (conductance and oil flow both 0) [W/K]")
    shape = np.broadcast_shapes(fr.shape, fa.shape, w.shape, ta.shape, g.shape, go.shape, np.shape(tin))
    fr, fa, w, ta, g, go, tin = (np.broadcast_to(x, shape).astype(float).ravel()
                                 for x in (fr, fa, w, ta, g, go, tin))
    if np.any(ta >= t_max):
        raise InputError(f"ambient must be < maximum_temperature [K] ({t_max:g} K), got {float(np.max(ta))!r}")
    caught = []

    def nu_of(t):
        return lub.walther_viscosity(t, a, b)

    def moment(t, sel):
        with warnings.catch_warnings(record=True) as rec:
            warnings.simplefilter("always")
            m = skf_for_bearing(bearing, fr[sel], fa[sel], w[sel], nu_of(t), lubrication=lubrication,
                                **friction_options)
        caught.extend(str(c.message) for c in rec)
        return m

    def balance(t, sel=None):
        sel = np.ones(t.shape, dtype=bool) if sel is None else sel
        out = np.zeros(t.shape)
        ts = t[sel]
        out[sel] = moment(ts, sel).power_loss - (g[sel] * (ts - ta[sel]) + go[sel] * (ts - tin[sel]))
        return out

    lo = np.minimum(ta, tin)
    hi = np.full(lo.shape, t_max)
    f_lo, f_hi = balance(lo), balance(hi)
    steady = f_hi < 0  # f_lo > 0: the friction power is positive at any speed
    temp = np.full(lo.shape, np.nan)
    its = np.zeros(lo.shape, dtype=int)
    if steady.any():
        s = steady

        def f(t, active):
            sel = np.flatnonzero(s)[active]
            full = np.zeros(s.size, dtype=bool)
            full[sel] = True
            return balance_on(t, active, full)

        def balance_on(t, active, full):
            out = np.zeros(t.shape)
            ts = t[active]
            out[active] = moment(ts, full).power_loss - (g[full] * (ts - ta[full]) + go[full] * (ts - tin[full]))
            return out

        def scale(t):
            return np.abs(g[s] * (t - ta[s]) + go[s] * (t - tin[s])) + 1e-300

        root, _, it = _bracketed_root(f, lo[s], hi[s], f_lo[s], f_hi[s], scale, xtol, rtol, max_iter)
        temp[s], its[s] = root, it
    if (~steady).any():
        notes.append(f"thermal runaway: in {int((~steady).sum())} of {steady.size} case(s) the friction power "
                     f"exceeds the heat carried away up to the safe limit {t_max - 273.15:g} degC: no steady "
                     "temperature below it (more cooling, a lower speed or a thinner oil is needed)")
    ok = np.isfinite(temp)
    m = np.full(temp.shape, np.nan)
    if ok.any():
        m[ok] = moment(temp[ok], ok).total_moment
    nu = np.where(ok, nu_of(np.where(ok, temp, 343.15)), np.nan)
    p_f = m * w
    p_d = np.where(ok, g * (temp - ta) + go * (temp - tin), np.nan)
    kappa = np.where(ok, lub.viscosity_ratio(np.where(ok, nu, 1e-5), w, bearing.mean_diameter), np.nan)
    notes += list(dict.fromkeys(caught))

    def shaped(x):
        return np.reshape(x, shape)[()]

    return ThermalBalance(shaped(temp), shaped(nu), shaped(m), shaped(p_f), shaped(p_d), shaped(kappa),
                          shaped(its), shaped(steady), tuple(dict.fromkeys(notes)))


def reference_heat_flow(bore, outside_diameter, width):
    r"""Heat flow a radial bearing sheds at ISO 15312's reference conditions, q_r A_r.

    Parameters
    ----------
    bore, outside_diameter, width : array_like
        d, D and B. [m]

    Returns
    -------
    ndarray
        :math:`\Phi_r = q_r A_r` (:func:`reference_heat_flow_density`, :func:`reference_surface`) at
        70 degC on the outer ring with a 20 degC ambient [1] [4]. [W]

    Examples
    --------
    >>> print(f"{reference_heat_flow(0.025, 0.052, 0.015):.2f} W")
    58.06 W
    """
    a = reference_surface(bore, outside_diameter, width)
    return (reference_heat_flow_density(a) * a)[()]


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
    from .friction import skf_for_bearing

    c = REFERENCE_CONDITIONS
    d, big, width = bearing.require("bore", "outside_diameter", "width")
    if static_load_rating is None:
        static_load_rating = bearing.static_load_rating
        if static_load_rating is None:
            from .ratings import bearing_ratings

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

    from .units import RPM

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


class RingTemperatures(NamedTuple):
    """Inner and outer ring temperatures from a lumped bearing temperature [K]."""

    inner: np.ndarray
    outer: np.ndarray


def ring_temperatures(bearing_temperature, *, difference=RING_TEMPERATURE_DIFFERENCE):
    r"""Inner and outer ring temperatures from the lumped temperature of the thermal balance.

    Parameters
    ----------
    bearing_temperature : array_like
        T of :func:`thermal_balance` (or any lumped bearing temperature). [K]
    difference : array_like, optional
        T_inner - T_outer; by default :data:`RING_TEMPERATURE_DIFFERENCE` (10 K). [K]

    Returns
    -------
    RingTemperatures
        T_outer = T and T_inner = T + difference. [K]

    Notes
    -----
    The balance has one temperature; the clearance needs two. The lumped temperature is read as the
    outer ring's, because that is where ISO 15312 and SKF measure the bearing temperature ("on the
    bearing stationary outer ring" [5]), and the inner ring, which sheds its heat only through the
    balls and the shaft, is warmer - "which is usually the case" [6]. The default split of 10 K is the
    upper end of what Normal clearance is made for [6]: a design value, not a prediction. A measured
    or estimated difference of the machine should be given; 0 gives one temperature throughout.

    Examples
    --------
    >>> r = ring_temperatures(343.15)
    >>> print(f"inner {r.inner - 273.15:.1f} degC, outer {r.outer - 273.15:.1f} degC")
    inner 80.0 degC, outer 70.0 degC
    """
    t = check_positive("bearing_temperature", bearing_temperature, "K")
    dt = np.asarray(difference, dtype=float)
    if not np.all(np.isfinite(dt)) or np.any(np.abs(dt) > 100.0):
        raise InputError(f"difference must be in [-100, 100] [K] (inner minus outer ring), got "
                         f"{float(np.max(np.abs(dt)))!r}")
    return RingTemperatures((t + dt)[()], (t + 0 * dt)[()])


def clearance_conditions(bearing_temperature, *, difference=RING_TEMPERATURE_DIFFERENCE, speed=0.0):
    r"""The mounted-clearance chain's operating conditions from a bearing temperature.

    Parameters
    ----------
    bearing_temperature : float
        Lumped T of :func:`thermal_balance`. [K]
    difference : float, optional
        T_inner - T_outer (:func:`ring_temperatures`). [K]
    speed : float, optional
        Inner-ring speed for the chain's centrifugal stage. [rad/s]

    Returns
    -------
    bearinglab.mounting.chain.Conditions
        Inner and outer ring temperatures of :func:`ring_temperatures`; the balls at their mean, the
        shaft at the inner ring's and the housing at the outer ring's (the chain's defaults).

    Examples
    --------
    >>> from bearinglab.mounting.chain import Mounting, operating_clearance
    >>> m = Mounting(0.025, 0.052, 0.03110, 0.04698, 0.00794)
    >>> r = operating_clearance(20e-6, 0.0, 0.0, m, clearance_conditions(343.15, difference=10.0))
    >>> print(f"{r.thermal_reduction * 1e6:.2f} um")
    4.88 um
    """
    from .mounting.chain import Conditions

    r = ring_temperatures(bearing_temperature, difference=difference)
    w = check_nonnegative("speed", speed, "rad/s")
    return Conditions(inner_temperature=float(r.inner), outer_temperature=float(r.outer), speed=float(w))
