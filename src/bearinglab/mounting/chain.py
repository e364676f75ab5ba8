"""The clearance chain: unmounted -> fit -> temperature -> speed -> operating clearance.

Mounting            the geometry and materials of a mounted bearing: bore, outside diameter, the raceway
                    diameters that model the rings, ball, shaft bore, housing wall, four materials
mounting_of         a Mounting from a :class:`~bearinglab.bearing.BallBearing` and the seat options
Conditions          temperatures of the five parts and the inner ring's speed
ChainResult         the stage reductions, the fit pressures and the operating clearance
operating_clearance the chain for arrays of unmounted clearances and interferences (vectorized)
ChainRange          least, probable and largest operating clearance, with warnings
operating_range     the chain at the three corners of the tolerance fields

Sign convention: a reduction is positive when the clearance gets smaller; a negative operating clearance
is a preload. The inner ring rotates (``speed``), the outer ring stands.

Which diameters model the rings. The raceways carry the balls, so the clearance lives there: with the
ball contact at 0 deg, d_i = d_m - D and d_o = d_m + D (groove bottoms). Each ring is a thick cylinder
from its seat to its groove bottom (inner: d -> d_i; outer: d_o -> D), the thinnest wall of the ring,
as in the fit formulas of NSK and JTEKT [1]_ [2]_ that use the raceway (groove) diameter; the shoulders,
left out, make a real ring a little stiffer, so the reduction computed here is an upper bound of the
elastic one. When the ball set is not known, the groove diameters are estimated as JTEKT does for deep
groove ball bearings: D_i = (4 d + D)/5, D_o = (d + 4 D)/5 [2]_, and D = (D_o - D_i)/2 (labelled as
an estimate in the warnings).

References
----------
.. [1] NSK, Rolling Bearings, cat. no. E1102m, section 15.2, table 15.1: expansion of the inner raceway :math:`\\Delta D_i = \\Delta d_{eff}
   (d/D_i)(1 - k_0^2)/(1 - k^2 k_0^2)`.
.. [2] JTEKT (Koyo), Ball and Roller Bearings catalogue, "Fitting surface pressure" (web copy:
   hchbearing.com): D_i, D_o the average groove diameters; deep groove ball bearings
   D_i = (4 d + D)/5, D_o = (d + 4 D)/5.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from ..errors import InputError
from . import centrifugal, lame, thermal
from .materials import MountingMaterial, material, of_bearing

__all__ = ["ChainRange", "ChainResult", "Conditions", "Mounting", "mounting_of", "operating_clearance",
           "operating_range"]

_MM = 1e-3
T_REF = thermal.REFERENCE_TEMPERATURE


@dataclass(frozen=True)
class Mounting:
    """Geometry and materials of a bearing in its seats (SI units).

    Parameters
    ----------
    bore, outside_diameter : float
        d and D. [m]
    inner_raceway, outer_raceway : float
        d_i and d_o: the raceway diameters of the clearance and the diameters that model the rings. [m]
    ball_diameter : float
        D_w. [m]
    shaft_bore : float
        Bore d_0 of a hollow shaft, 0 for a solid shaft. [m]
    housing_outside_diameter : float
        Outside diameter of the housing, ``inf`` for a housing of unbounded wall. [m]
    ring, ball, shaft, housing : MountingMaterial
        The four materials.
    estimated : bool
        True when the raceways (and ball) were estimated from the envelope, not the ball set.
    """

    bore: float
    outside_diameter: float
    inner_raceway: float
    outer_raceway: float
    ball_diameter: float
    shaft_bore: float = 0.0
    housing_outside_diameter: float = math.inf
    ring: MountingMaterial = None
    ball: MountingMaterial = None
    shaft: MountingMaterial = None
    housing: MountingMaterial = None
    estimated: bool = False

    def __post_init__(self):
        for name in ("ring", "ball", "shaft", "housing"):
            if getattr(self, name) is None:
                object.__setattr__(self, name, material("steel"))
        d, big = self.bore, self.outside_diameter
        if not (0 < d < self.inner_raceway < self.outer_raceway < big):
            raise InputError(f"raceways must satisfy 0 < d < d_i < d_o < D [mm], got d = {d / _MM:g}, "
                             f"d_i = {self.inner_raceway / _MM:g}, d_o = {self.outer_raceway / _MM:g}, "
                             f"D = {big / _MM:g} mm")
        if not 0 <= self.shaft_bore < d:
            raise InputError(f"shaft-bore must be >= 0 and < the bearing bore d = {d / _MM:g} [mm], got "
                             f"{self.shaft_bore / _MM:g} mm")
        if not self.housing_outside_diameter > big:
            raise InputError(f"housing-outside-diameter must be > the bearing outside diameter "
                             f"D = {big / _MM:g} [mm], got {self.housing_outside_diameter / _MM:g} mm")
        if not self.ball_diameter > 0:
            raise InputError(f"ball_diameter must be > 0 [mm], got {self.ball_diameter / _MM:g} mm")


def mounting_of(bearing, *, shaft_bore=0.0, housing_outside_diameter=math.inf, shaft_material="steel",
                housing_material="steel"):
    """The :class:`Mounting` of a catalog bearing with its seat options.

    Parameters
    ----------
    bearing : bearinglab.bearing.BallBearing
        Needs ``bore`` and ``outside_diameter``; ``pitch_diameter`` and ``ball_diameter`` give the
        raceways (else they are estimated, see the module notes).
    shaft_bore : float, optional
        Bore of a hollow shaft, 0 for solid. [m]
    housing_outside_diameter : float, optional
        Outside diameter of the housing (``inf``: unbounded wall). [m]
    shaft_material, housing_material : str or MountingMaterial, optional
        By name from :data:`bearinglab.mounting.materials.MATERIAL_NAMES`; steel by default.

    Returns
    -------
    Mounting

    Examples
    --------
    >>> from bearinglab import catalog
    >>> m = mounting_of(catalog.get("6205-2RS"))
    >>> print(f"{m.inner_raceway * 1e3:.3f} {m.outer_raceway * 1e3:.3f} mm")
    31.100 46.980 mm
    """
    d, big = bearing.require("bore", "outside_diameter")
    if bearing.pitch_diameter is not None and bearing.ball_diameter is not None:
        dm, dw = bearing.pitch_diameter, bearing.ball_diameter
        di, do, estimated = dm - dw, dm + dw, False
    else:  # JTEKT's average groove diameters of deep groove ball bearings (module notes, [2])
        di, do, estimated = (4 * d + big) / 5, (d + 4 * big) / 5, True
        dw = (do - di) / 2
    pick = lambda m: m if isinstance(m, MountingMaterial) else material(m)
    return Mounting(d, big, di, do, dw, shaft_bore=float(shaft_bore),
                    housing_outside_diameter=float(housing_outside_diameter),
                    ring=of_bearing(bearing.ring_material), ball=of_bearing(bearing.ball_material),
                    shaft=pick(shaft_material), housing=pick(housing_material), estimated=estimated)


class Conditions(NamedTuple):
    """Operating temperatures [K] and the inner ring's speed [rad/s]; None takes the default."""

    inner_temperature: float = T_REF
    outer_temperature: float = T_REF
    ball_temperature: float | None = None
    """Default: the mean of the two rings."""
    shaft_temperature: float | None = None
    """Default: the inner ring's."""
    housing_temperature: float | None = None
    """Default: the outer ring's."""
    speed: float = 0.0


class ChainResult(NamedTuple):
    """The clearance chain of one case (or of arrays of cases); reductions > 0 take clearance away."""

    unmounted_clearance: np.ndarray
    """Diametral clearance of the bearing before mounting, at 20 degC. [m]"""
    inner_interference: np.ndarray
    """Interference of the inner fit at mounting (20 degC, standstill), after smoothing. [m]"""
    outer_interference: np.ndarray
    """Interference of the outer fit at mounting. [m]"""
    fit_reduction: np.ndarray
    """Clearance taken by the two fits at 20 degC. [m]"""
    thermal_reduction: np.ndarray
    """Clearance taken by the temperatures: free expansion of rings and balls, and the fits' change. [m]"""
    centrifugal_reduction: np.ndarray
    """Clearance taken by the speed: the inner raceway's centrifugal growth and the fit's loss. [m]"""
    operating_clearance: np.ndarray
    """Unmounted minus the three reductions; negative is a preload. [m]"""
    inner_pressure: np.ndarray
    """Fit pressure of the inner ring in operation (temperature and speed). [Pa]"""
    outer_pressure: np.ndarray
    """Fit pressure of the outer ring in operation. [Pa]"""
    inner_operating_interference: np.ndarray
    """Interference of the inner fit in operation (<= 0: the ring is loose on its shaft). [m]"""
    outer_operating_interference: np.ndarray
    """Interference of the outer fit in operation. [m]"""
    inner_loosened_by_speed: np.ndarray
    """True where the inner fit holds at temperature but comes loose at speed."""


def _inner_growth(interference, m):
    p = lame.fit_pressure_inner(interference, m.bore, m.inner_raceway, m.shaft_bore, m.ring.elastic_modulus,
                                m.ring.poisson_ratio, m.shaft.elastic_modulus, m.shaft.poisson_ratio)
    return lame.inner_raceway_growth(p, m.bore, m.inner_raceway, m.ring.elastic_modulus), p


def _outer_shrink(interference, m):
    p = lame.fit_pressure_outer(interference, m.outside_diameter, m.outer_raceway, m.housing_outside_diameter,
                                m.ring.elastic_modulus, m.ring.poisson_ratio, m.housing.elastic_modulus,
                                m.housing.poisson_ratio)
    return lame.outer_raceway_shrink(p, m.outside_diameter, m.outer_raceway, m.ring.elastic_modulus), p


def operating_clearance(unmounted_clearance, inner_interference, outer_interference, mounting,
                        conditions=None):
    r"""The operating clearance of a mounted bearing, stage by stage (vectorized over the cases).

    Parameters
    ----------
    unmounted_clearance : array_like
        Diametral (radial) clearance before mounting, at 20 degC. [m]
    inner_interference, outer_interference : array_like
        Diametral interferences of the two fits at 20 degC (negative: clearance fits), after any
        smoothing. [m]
    mounting : Mounting
        Geometry and materials.
    conditions : Conditions, optional
        Temperatures and speed; 20 degC and standstill by default.

    Returns
    -------
    ChainResult

    Notes
    -----
    1. Fit (20 degC): each ring is a Lamé thick cylinder (:mod:`bearinglab.mounting.lame`); the inner
       raceway grows by :math:`2 p_i d^2 d_i / (E (d_i^2 - d^2))`, the outer shrinks likewise.
    2. Temperature: rings and balls expand freely (:func:`bearinglab.mounting.thermal.clearance_loss`)
       and the interferences change with the seat and ring temperatures; the fits are solved again.
    3. Speed: the inner ring's raceway grows as a free rotating disc and the fit loses the difference
       of the ring's and the shaft's centrifugal growth at the bore
       (:mod:`bearinglab.mounting.centrifugal`); superposed on the Lamé solution while the fit holds.

    Each stage's reduction is the change it makes; a fit that becomes a clearance fit carries no
    pressure, so the chain is not linear in the tolerances. For a solid shaft of the ring's steel the
    inner raceway grows by :math:`\delta\,d/d_i` (the tests check this limit).

    Examples
    --------
    >>> m = Mounting(0.025, 0.052, 0.03110, 0.04698, 0.00794)
    >>> r = operating_clearance(20e-6, 15e-6, 0.0, m)
    >>> print(f"{r.fit_reduction * 1e6:.2f} um, {r.operating_clearance * 1e6:.2f} um")
    12.06 um, 7.94 um
    """
    m = mounting
    c = Conditions() if conditions is None else conditions
    e0 = np.asarray(unmounted_clearance, dtype=float)
    i0 = np.asarray(inner_interference, dtype=float)
    o0 = np.asarray(outer_interference, dtype=float)
    t_i = np.asarray(c.inner_temperature, dtype=float)
    t_o = np.asarray(c.outer_temperature, dtype=float)
    t_b = 0.5 * (t_i + t_o) if c.ball_temperature is None else np.asarray(c.ball_temperature, dtype=float)
    t_s = t_i if c.shaft_temperature is None else np.asarray(c.shaft_temperature, dtype=float)
    t_h = t_o if c.housing_temperature is None else np.asarray(c.housing_temperature, dtype=float)
    # 1. the fits at 20 degC
    grow0, _ = _inner_growth(i0, m)
    shrink0, _ = _outer_shrink(o0, m)
    fit = grow0 + shrink0
    # 2. temperatures: free expansion, then the fits at their new interferences
    i_t = i0 + thermal.inner_interference_change(m.bore, t_s, m.shaft.thermal_expansion, t_i,
                                                 m.ring.thermal_expansion)
    o_t = o0 + thermal.outer_interference_change(m.outside_diameter, t_o, m.ring.thermal_expansion, t_h,
                                                 m.housing.thermal_expansion)
    free = thermal.clearance_loss(m.inner_raceway, m.outer_raceway, m.ball_diameter, t_i, t_o, t_b,
                                  m.ring.thermal_expansion, m.ball.thermal_expansion)
    grow_t, _ = _inner_growth(i_t, m)
    shrink_t, p_o = _outer_shrink(o_t, m)
    therm = free + grow_t + shrink_t - fit
    # 3. speed: the inner raceway's free growth, and the fit at its interference less the centrifugal loss
    w = np.asarray(c.speed, dtype=float)
    i_w = i_t - centrifugal.inner_fit_loss(w, m.bore, m.inner_raceway, m.shaft_bore, m.ring, m.shaft)
    raceway = centrifugal.disc_growth(w, m.bore, m.inner_raceway, m.inner_raceway, m.ring.density,
                                      m.ring.elastic_modulus, m.ring.poisson_ratio)
    grow_w, p_i = _inner_growth(i_w, m)
    cent = raceway + grow_w - grow_t
    op = e0 - fit - therm - cent
    loose = (i_t > 0) & (i_w <= 0)
    return ChainResult(*(np.asarray(x)[()] for x in (
        e0 + 0 * op, i0 + 0 * op, o0 + 0 * op, fit + 0 * op, therm + 0 * op, cent + 0 * op, op, p_i + 0 * op,
        p_o + 0 * op, i_w + 0 * op, o_t + 0 * op, loose | (0 * op > 0))))


class ChainRange(NamedTuple):
    """The chain at the corners of the tolerances: least, probable (mid-fields) and largest clearance."""

    least: ChainResult
    """Smallest unmounted clearance with the largest interferences."""
    probable: ChainResult
    """Middle of every tolerance field."""
    largest: ChainResult
    """Largest unmounted clearance with the least interferences."""
    warnings: list
    """Doubtful or notable results, as sentences."""


def operating_range(unmounted_clearance, inner_interference, outer_interference, mounting,
                    conditions=None):
    """The least, probable and largest operating clearance from the tolerance ranges.

    Parameters
    ----------
    unmounted_clearance : tuple of float
        (minimum, maximum) diametral clearance before mounting (e.g. an ISO 5753-1 class). [m]
    inner_interference, outer_interference : tuple of float
        (least, largest) interference of each fit (:mod:`bearinglab.mounting.fits`), after smoothing. [m]
    mounting : Mounting
    conditions : Conditions, optional

    Returns
    -------
    ChainRange

    Notes
    -----
    Every reduction grows with the interferences, so the least operating clearance is the smallest
    unmounted one with the tightest fits, and the largest the other way round: these are the worst
    cases of the tolerance stack, through the nonlinear chain. "Probable" is the chain at the middle
    of each field (MESYS and SKF call the mean value so); the Monte Carlo
    (:mod:`bearinglab.mounting.monte_carlo`) gives the distribution.

    Examples
    --------
    >>> m = Mounting(0.025, 0.052, 0.03110, 0.04698, 0.00794)
    >>> r = operating_range((5e-6, 20e-6), (2e-6, 21e-6), (-41e-6, -0e-6), m)
    >>> print(f"{r.least.operating_clearance * 1e6:.2f} to {r.largest.operating_clearance * 1e6:.2f} um")
    -11.88 to 18.39 um
    >>> r.warnings[0][:46]
    'the least operating clearance is negative (-11'
    """
    e = np.array([unmounted_clearance[0], 0.5 * (unmounted_clearance[0] + unmounted_clearance[1]),
                  unmounted_clearance[1]])
    ii = np.array([inner_interference[1], 0.5 * (inner_interference[0] + inner_interference[1]),
                   inner_interference[0]])
    oo = np.array([outer_interference[1], 0.5 * (outer_interference[0] + outer_interference[1]),
                   outer_interference[0]])
    r = operating_clearance(e, ii, oo, mounting, conditions)
    rows = [ChainResult(*(np.asarray(f)[k] for f in r)) for k in range(3)]
    notes = []
    if r.operating_clearance[0] < 0:
        notes.append(f"the least operating clearance is negative ({r.operating_clearance[0] * 1e6:.1f} um): "
                     "the bearing runs preloaded there")
    if r.operating_clearance[2] < 0:
        notes.append("even the largest operating clearance is negative: the bearing is always preloaded")
    labels = ("at the largest interference", "at the probable interference", "at the least interference")
    for k in range(3):
        if r.inner_loosened_by_speed[k]:
            notes.append(f"the inner fit comes loose at speed {labels[k]}: the ring's bore grows past the "
                         "shaft seat (creep)")
            break
    for k in range(3):
        if r.inner_interference[k] > 0 and r.inner_operating_interference[k] <= 0 and not r.inner_loosened_by_speed[k]:
            notes.append(f"the inner fit comes loose at the operating temperatures {labels[k]}")
            break
    for k in range(3):
        if r.outer_interference[k] > 0 and r.outer_operating_interference[k] <= 0:
            notes.append(f"the outer fit comes loose at the operating temperatures {labels[k]} (a housing "
                         "that expands more than the ring)")
            break
    if mounting.estimated:
        notes.append("the raceway diameters and the ball are estimates from the bore and outside diameter "
                     "(JTEKT: (4d + D)/5, (d + 4D)/5); give the ball set for the bearing's own")
    return ChainRange(rows[0], rows[1], rows[2], notes)
