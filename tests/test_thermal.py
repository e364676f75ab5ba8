"""The steady bearing temperature (bearinglab.thermal): the balance closes, it is the SKF moment at the
viscosity of that temperature, ISO 15312's reference surface and heat flow by hand, trends, runaway."""

import math

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from bearinglab import catalog, friction, thermal
from bearinglab.errors import InputError
from bearinglab.ratings import lubrication
from bearinglab.units import RPM

B = catalog.get("6205-2RS")
NU40, NU100 = 32e-6, 5.4e-6


def _solve(speed_rpm, **kw):
    kw.setdefault("conductance", 1.0)
    return thermal.thermal_balance(B, 1000.0, 200.0, np.asarray(speed_rpm) * RPM, 293.15, NU40, NU100, **kw)


def test_balance_closes_at_the_skf_moment_of_the_viscosity_of_that_temperature():
    r = _solve(6000.0, oil_flow_conductance=3.0, oil_inlet_temperature=303.15)
    assert r.steady
    a, b = lubrication.walther_constants((313.15, 373.15), (NU40, NU100))
    nu = lubrication.walther_viscosity(r.temperature, a, b)
    assert r.kinematic_viscosity == pytest.approx(nu, rel=1e-14)
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        m = friction.skf_for_bearing(B, 1000.0, 200.0, 6000 * RPM, nu, lubrication="oil-jet").total_moment
    p_f = m * 6000 * RPM
    p_d = 1.0 * (r.temperature - 293.15) + 3.0 * (r.temperature - 303.15)
    assert r.friction_power == pytest.approx(p_f, rel=1e-13)
    assert r.heat_dissipated == pytest.approx(p_d, rel=1e-13)
    assert r.friction_power == pytest.approx(r.heat_dissipated, rel=1e-10)  # the solver's tolerance
    assert r.viscosity_ratio == pytest.approx(float(lubrication.viscosity_ratio(nu, 6000 * RPM, B.mean_diameter)))


@settings(max_examples=20, deadline=None)
@given(n=st.floats(100.0, 20000.0), g=st.floats(0.2, 20.0))
@example(n=19080.0, g=0.203125)  # a runaway (found by hypothesis)
@example(n=19000.0, g=0.203125)  # steady at 598.7 K, just below the limit
def test_the_balance_closes_for_any_speed_and_conductance(n, g):
    r = _solve(n, conductance=g, maximum_temperature=600.0)
    if r.steady:
        assert r.friction_power == pytest.approx(r.heat_dissipated, rel=1e-9)
        assert 293.15 < r.temperature < 600.0
        return
    # no steady state below 600 K (e.g. 19 080 rpm at 0.203 W/K): then the friction power at the safe
    # limit, at the viscosity of that temperature, still exceeds what the conductance carries away
    assert any("thermal runaway" in w for w in r.warnings)
    assert np.isnan(r.temperature)
    a, b = lubrication.walther_constants((313.15, 373.15), (NU40, NU100))
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        m = friction.skf_for_bearing(B, 1000.0, 200.0, n * RPM, lubrication.walther_viscosity(600.0, a, b),
                                     lubrication="oil-jet").total_moment
    assert m * n * RPM > g * (600.0 - 293.15)


def test_hotter_with_speed_and_cooler_with_better_cooling():
    r = _solve([1000.0, 4000.0, 12000.0])
    assert np.all(np.diff(r.temperature) > 0) and np.all(np.diff(r.friction_power) > 0)
    cool = _solve(12000.0, conductance=5.0)
    assert cool.temperature < r.temperature[2]
    # batched and one by one agree
    one = _solve(4000.0)
    assert one.temperature == pytest.approx(r.temperature[1], abs=1e-8)


def test_runaway_gives_no_number_and_a_warning():
    r = _solve([3000.0, 30000.0], conductance=0.2, maximum_temperature=373.15)
    assert r.steady.tolist() == [True, False]
    assert math.isnan(r.temperature[1]) and math.isnan(r.friction_power[1])
    assert any(w.startswith("thermal runaway") for w in r.warnings)


def test_iso_15312_reference_surface_heat_flow_and_conductance_by_hand():
    ar = math.pi * 0.015 * (0.052 + 0.025)
    assert thermal.reference_surface(0.025, 0.052, 0.015) == pytest.approx(ar, rel=1e-15)
    assert thermal.reference_heat_flow_density(ar) == 16e3
    assert thermal.reference_heat_flow_density(0.1) == pytest.approx(16e3 * 2.0**-0.34, rel=1e-14)
    assert thermal.reference_heat_flow_density(0.05) == 16e3  # the limit belongs to the constant part
    assert thermal.reference_conductance(0.025, 0.052, 0.015) == pytest.approx(16e3 * ar / 50.0, rel=1e-14)
    r = thermal.thermal_balance(B, 1000.0, 0.0, 6000 * RPM, 293.15, NU40, NU100)
    assert any("ISO 15312" in w for w in r.warnings)


def test_oil_flow_and_heat_dissipated():
    assert thermal.oil_flow_conductance(1e-3 / 60, 870.0, 1950.0) == pytest.approx(870 * 1e-3 / 60 * 1950)
    assert thermal.heat_dissipated(350.0, 300.0, 2.0, oil_flow_conductance=1.0, oil_inlet_temperature=320.0) == \
        pytest.approx(2.0 * 50 + 30.0)


@pytest.mark.parametrize("kw, match", [
    ({"conductance": 0.0}, "no heat leaves"),
    ({"conductance": -1.0}, "conductance must be >= 0"),
    ({"oil_flow_conductance": -1.0}, "oil_flow_conductance must be >= 0"),
    ({"maximum_temperature": 280.0}, "ambient must be < maximum_temperature"),
])
def test_bad_inputs(kw, match):
    kw.setdefault("conductance", 1.0)
    with pytest.raises(InputError, match=match):
        thermal.thermal_balance(B, 1000.0, 0.0, 6000 * RPM, 293.15, NU40, NU100, **kw)
