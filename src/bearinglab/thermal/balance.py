r"""The steady bearing temperature: the SKF friction power at the oil's viscosity of T against the heat shed.

Balance
-------
thermal_balance                T where M(nu(T)) omega = P_d(T), batched; runaway when there is none
ThermalBalance                 its result

The friction moment is :func:`bearinglab.friction.skf_for_bearing` at the viscosity nu(T) of the oil
(ASTM D341 through nu40 and nu100, :mod:`bearinglab.ratings.lubrication`); M rises as the oil cools,
P_d as the bearing heats, so the balance has one root between the ambient and a safe maximum when it
has any. References are those of :mod:`bearinglab.thermal`.
"""

from __future__ import annotations

import warnings
from typing import NamedTuple

import numpy as np

from .. import _solve
from .._validate import check_nonnegative, check_positive
from ..errors import ConvergenceError, InputError
from .heat import reference_conductance

__all__ = ["ThermalBalance", "thermal_balance"]

_T40, _T100 = 313.15, 373.15


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
    bearing : BallBearing or RollerBearing
        For the SKF model (a roller bearing: :func:`bearinglab.friction.skf_roller_for_bearing`) (bore, outside diameter, series or constants; seals) and, without
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
    from ..friction import skf_for_bearing, skf_roller_for_bearing
    from ..ratings import lubrication as lub

    # a roller bearing: SKF's model of its type and series (issue 32)
    model = skf_roller_for_bearing if hasattr(bearing, "roller_diameter") else skf_for_bearing

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
                     f"({float(conductance):.4g} W/K, its reference housing) is used; give the housing's own thermal resistance")
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
            m = model(bearing, fr[sel], fa[sel], w[sel], nu_of(t), lubrication=lubrication, **friction_options)
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
