"""Published worked examples of clearance reduction, reproduced (issue 23, item 7).

Source: SKF, *Rolling bearings*, PUB BU/P1 17000/1 EN, October 2018.

- Method, section "Selecting internal clearance or preload", p. 184: the clearance reduction of the
  fits is dr_fit = D1 f1 + D2 f2, with D1, D2 the *maximum probable* interferences of the fit tables
  and f1, f2 reduction factors read from diagram 2 against d/D (solid steel shaft, thick-walled steel
  or cast-iron housing); the thermal reduction is dr_temp = 0.012 dT d_m [um], d_m = (d + D)/2 [mm].
- Example C.2 "Rope sheave", step "Bearing execution / Initial internal clearance": 6207-2RSH, outer
  ring rotating, housing N6, no interference at the inner ring. Printed: initial clearance
  Normal 6/13/20 um and C3 15/24/33 um (min/avg/max); D2 = -29/-17/-5 um (SKF writes interference
  negative); dr_fit = -25/-15/-4 um; clearance after mounting Normal -19/-2/6 um, C3 -10/9/29 um.
  (The value f2 read from the diagram is not legible in the copy we read; the three printed pairs fix it
  to a narrow interval, computed below.)
- Example C.3 "Centrifugal pump", step "Bearing execution / Checking the initial internal clearance":
  a pair of 7312 BECBP on a k5 shaft in a K7 housing, inner ring 10 degC warmer than the outer.
  Printed: D1 = -26/-16/-6 um, D2 = -21/1/23 um, dr_fit = -38/-12/-5 um, d_m = 95 mm,
  dr_temp = -11 um. (The pair's initial and operating clearances are not legible in our copy, so they
  are not used.)

Every number printed to 1 um: the tolerances below are the half-unit of that rounding, plus the stated
model difference where bearinglab's Lamé chain is compared (docs/theory/clearance.md, "Published
worked examples").
"""

import math

import numpy as np
import pytest

from bearinglab import catalog, internal_clearance
from bearinglab.mounting import chain, fits, tables, thermal

UM = 1e-6
HALF = 0.5  # half the printed unit (1 um)


def _factor_interval(interferences, reductions):
    """The factors f that reproduce every printed reduction round(f * interference) (one ring)."""
    lo = max((r - HALF) / i for i, r in zip(interferences, reductions))
    hi = min((r + HALF) / i for i, r in zip(interferences, reductions))
    return lo, hi


# --- C.2 Rope sheave: 6207-2RSH in an N6 housing, outer ring rotating ------------------------------

ROPE_D2 = (29.0, 17.0, 5.0)  # probable interference max/avg/min [um] (printed -29/-17/-5)
ROPE_FIT = (25.0, 15.0, 4.0)  # printed dr_fit [um] (-25/-15/-4)
ROPE_C3 = (15.0, 24.0, 33.0)  # printed initial clearance min/avg/max [um]
ROPE_C3_MOUNTED = (-10.0, 9.0, 29.0)  # printed clearance after mounting [um]


def test_rope_sheave_probable_interference_is_skfs():
    """The printed D2 = -29/-5 um is the probable interference of N6 at D = 72 mm (rounded outward)."""
    p = fits.probable_interference(tables.outside_diameter_limits(0.072), tables.field_limits("N6", 0.072))
    assert (math.floor(p.least / UM + 1e-9), math.ceil(p.largest / UM - 1e-9)) == (5, 29)
    assert 0.5 * (p.least + p.largest) / UM == pytest.approx(17.0, abs=HALF)


def test_rope_sheave_published_method_is_consistent():
    """One factor f2 reproduces the three printed reductions, and the mounted C3 clearances follow."""
    lo, hi = _factor_interval(ROPE_D2, ROPE_FIT)
    assert 0.85 < lo < hi < 0.88  # the diagram's f2 at d/D = 0.486 lies in [0.853, 0.879]
    f2 = 0.5 * (lo + hi)
    assert [round(f2 * i) for i in ROPE_D2] == list(ROPE_FIT)
    # clearance after mounting = initial - dr_fit, least with the largest interference
    mounted = [c - r for c, r in zip(ROPE_C3, ROPE_FIT)]
    assert mounted == list(ROPE_C3_MOUNTED)


def test_rope_sheave_c3_is_iso5753():
    c = internal_clearance.radial_clearance_range(0.035, "C3")
    assert (c.minimum / UM, c.maximum / UM) == pytest.approx((ROPE_C3[0], ROPE_C3[2]), abs=1e-9)


def test_rope_sheave_bearinglab_factor_exceeds_skfs_by_under_5_percent():
    """bearinglab's ring is the groove bottom (thinnest wall): f2 = d_o / D, a little above SKF's."""
    m = chain.mounting_of(catalog.get("6207"))
    f2 = float(chain.operating_clearance(0.0, 0.0, 10 * UM, m).fit_reduction) / (10 * UM)
    assert f2 == pytest.approx(m.outer_raceway / m.outside_diameter, rel=1e-12)
    _, hi = _factor_interval(ROPE_D2, ROPE_FIT)
    assert hi < f2 < 1.05 * hi


def test_rope_sheave_bearinglab_chain_against_printed_mounted_clearance():
    """bearinglab's chain with SKF's printed interferences: within 1/2 um + 5 % of the interference."""
    m = chain.mounting_of(catalog.get("6207"))
    c3 = np.array(ROPE_C3) * UM
    d2 = np.array(ROPE_D2) * UM
    r = chain.operating_clearance(c3, 0.0, d2, m)  # SKF: no interference at the inner ring (g6)
    got = np.asarray(r.operating_clearance) / UM
    for g, printed, i in zip(got, ROPE_C3_MOUNTED, ROPE_D2):
        assert g <= printed + HALF  # the groove-bottom ring takes a little more clearance
        assert g == pytest.approx(printed, abs=HALF + 0.05 * i)
    assert np.asarray(r.thermal_reduction) == pytest.approx(0.0, abs=1e-15)


def test_rope_sheave_bearinglab_from_its_own_tables():
    """The whole chain from bearinglab's tables (N6, ISO 492 Normal, ISO 5753 C3): SKF's C3 range.

    SKF rounds the probable interference outward to 1 um (5.49 -> 5, 28.51 -> 29), hence one more
    half unit than above."""
    b = catalog.get("6207")
    m = chain.mounting_of(b)
    p = fits.probable_interference(tables.outside_diameter_limits(0.072), tables.field_limits("N6", 0.072))
    c = internal_clearance.radial_clearance_range(0.035, "C3")
    r = chain.operating_range((c.minimum, c.maximum), (0.0, 0.0), (p.least, p.largest), m)
    least, largest = r.least.operating_clearance / UM, r.largest.operating_clearance / UM
    assert least == pytest.approx(ROPE_C3_MOUNTED[0], abs=2 * HALF + 0.05 * ROPE_D2[0])
    assert largest == pytest.approx(ROPE_C3_MOUNTED[2], abs=2 * HALF + 0.05 * ROPE_D2[2])
    assert any("negative" in w for w in r.warnings)  # SKF: "a small negative clearance is not critical"


# --- C.3 Centrifugal pump: a pair of 7312 BECBP, k5 shaft, K7 housing, dT = 10 degC -------------------

PUMP_D1 = (26.0, 16.0, 6.0)  # inner probable interference max/avg/min [um] (printed -26/-16/-6)
PUMP_D2 = (21.0, -1.0, -23.0)  # outer (printed -21/1/23: negative there is interference)
PUMP_FIT = (38.0, 12.0, 5.0)  # printed dr_fit [um] (-38/-12/-5)
PUMP_DM, PUMP_DT, PUMP_TEMP = 95.0, 10.0, 11.0  # printed d_m [mm], dT [K], dr_temp [um]


def test_pump_probable_interferences_are_skfs():
    k5 = fits.probable_interference(tables.field_limits("k5", 0.060), tables.bore_limits(0.060))
    k7 = fits.probable_interference(tables.outside_diameter_limits(0.130), tables.field_limits("K7", 0.130))
    assert (math.floor(k5.least / UM), math.ceil(k5.largest / UM)) == (6, 26)
    assert (math.floor(k7.least / UM), math.ceil(k7.largest / UM)) == (-23, 21)


def _pump_factor_intervals():
    # avg and min rows have no outer interference: they fix f1; the max row then fixes f2
    f1_lo, f1_hi = _factor_interval(PUMP_D1[1:], PUMP_FIT[1:])
    f2_lo = (PUMP_FIT[0] - HALF - PUMP_D1[0] * f1_hi) / PUMP_D2[0]
    f2_hi = (PUMP_FIT[0] + HALF - PUMP_D1[0] * f1_lo) / PUMP_D2[0]
    return (f1_lo, f1_hi), (f2_lo, f2_hi)


def test_pump_published_method_is_consistent():
    (f1_lo, f1_hi), (f2_lo, f2_hi) = _pump_factor_intervals()
    assert 0.74 < f1_lo < f1_hi < 0.79 and 0.81 < f2_lo < f2_hi < 0.91
    f1, f2 = 0.5 * (f1_lo + f1_hi), 0.5 * (f2_lo + f2_hi)
    fit = [f1 * max(i, 0) + f2 * max(o, 0) for i, o in zip(PUMP_D1, PUMP_D2)]
    assert [round(x) for x in fit] == list(PUMP_FIT)
    # dr_temp = 0.012 dT d_m, d_m = (d + D)/2 = (60 + 130)/2
    assert (60 + 130) / 2 == PUMP_DM
    assert round(0.012 * PUMP_DT * PUMP_DM) == PUMP_TEMP


def test_pump_bearinglab_factors_against_skfs():
    """f1 = d/d_i is 4-8 % above SKF's diagram value; f2 = d_o/D falls inside SKF's interval."""
    m = chain.mounting_of(catalog.get("7312 BE"))
    f1 = float(chain.operating_clearance(0.0, 10 * UM, 0.0, m).fit_reduction) / (10 * UM)
    f2 = float(chain.operating_clearance(0.0, 0.0, 10 * UM, m).fit_reduction) / (10 * UM)
    (f1_lo, f1_hi), (f2_lo, f2_hi) = _pump_factor_intervals()
    assert f1 == pytest.approx(m.bore / m.inner_raceway, rel=1e-12)
    assert f1_hi < f1 < 1.09 * f1_lo
    assert f2_lo < f2 < f2_hi


def test_pump_bearinglab_chain_against_printed_reductions():
    """Fit: within 1/2 um + 5 % of the interference; thermal: SKF's 0.012 becomes bearinglab's alpha."""
    m = chain.mounting_of(catalog.get("7312 BE"))
    t_o = thermal.REFERENCE_TEMPERATURE + 30.0
    cond = chain.Conditions(inner_temperature=t_o + PUMP_DT, outer_temperature=t_o)
    r = chain.operating_clearance(0.0, np.array(PUMP_D1) * UM, np.array(PUMP_D2) * UM, m, cond)
    for got, printed, i, o in zip(np.asarray(r.fit_reduction) / UM, PUMP_FIT, PUMP_D1, PUMP_D2):
        assert got == pytest.approx(printed, abs=HALF + 0.05 * (i + max(o, 0)))
    # one steel, shaft at the inner ring's and housing at the outer ring's temperature: the fits keep
    # their interference, and the loss is alpha dT d_m with d_m the pitch diameter (95 mm here too)
    assert (m.inner_raceway + m.outer_raceway) / 2 == pytest.approx(PUMP_DM * 1e-3, rel=1e-12)
    therm = np.asarray(r.thermal_reduction) / UM
    assert therm == pytest.approx(12.5e-6 * PUMP_DT * PUMP_DM * 1e3, rel=1e-9)
    assert therm == pytest.approx(PUMP_TEMP * 12.5 / 12.0, abs=HALF * 12.5 / 12.0)  # SKF's alpha 12e-6
