"""The film of every ball (bearinglab.film.analysis): reproduced from the load distribution and the
contact formulas called directly, pure-rolling limit, symmetry and batching."""

import math
import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearinglab import catalog
from bearinglab.errors import InputError, ValidityWarning
from bearinglab.film import analysis, ehl
from bearinglab.quasistatic.combined import combined_analysis
from bearinglab.units import RPM

B218 = catalog.get("B218")


def test_every_ball_is_reproduced_from_the_load_distribution_and_the_contact_formulas():
    loads, w = [3000.0, 0.0, 8000.0, 0.0, 0.0], 8000 * RPM
    r = analysis.film_analysis(B218, loads, w, 0.012, 2.1e-8, roughness_ball=0.05e-6, roughness_race=0.15e-6)
    ld = combined_analysis(B218, loads, w)
    np.testing.assert_array_equal(r.load_inner, ld.ball_load_inner)
    d, dm = B218.ball_diameter, B218.pitch_diameter
    for j in range(B218.n_balls):
        for race, q, a, conf, u, hm in (
                ("inner", ld.ball_load_inner[j], ld.contact_angle_inner[j], B218.inner_conformity,
                 r.entrainment_velocity_inner[j], r.minimum_film_inner[j]),
                ("outer", ld.ball_load_outer[j], ld.contact_angle_outer[j], B218.outer_conformity,
                 r.entrainment_velocity_outer[j], r.minimum_film_outer[j])):
            if q == 0:
                assert math.isnan(hm)
                continue
            radii = ehl.contact_radii(d, dm, conf, a, race=race)
            k = ehl.ellipticity(radii.rx, radii.ry)
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", ValidityWarning)  # k slightly above 8 at the inner contacts
                ref = ehl.hamrock_dowson(q, u, radii.rx, k, 0.012, 2.1e-8, B218.reduced_modulus).minimum
            assert hm == pytest.approx(ref, rel=1e-12)
    lam = np.concatenate([r.film_parameter_inner, r.film_parameter_outer])
    assert r.minimum_film_parameter == pytest.approx(np.nanmin(lam), rel=1e-15)
    assert r.minimum_film_parameter == pytest.approx(r.minimum_film / math.hypot(0.05e-6, 0.15e-6), rel=1e-12)
    assert r.regime == ehl.lubrication_regime(r.minimum_film_parameter)


def test_entrainment_velocity_reduces_to_pure_rolling_at_equal_angles():
    a = np.radians([0.0, 15.0, 40.0])
    ui, uo = analysis.entrainment_velocities(1000.0, a, a, 12e-3, 60e-3)
    ref = 1000.0 * (60e-3**2 - (12e-3 * np.cos(a)) ** 2) / (4 * 60e-3)
    np.testing.assert_allclose(ui, ref, rtol=1e-14)
    np.testing.assert_allclose(uo, ref, rtol=1e-14)


def test_the_rolling_velocities_match_the_quasistatic_ball_speeds():
    from bearinglab.quasistatic import attitude_angle, ball_speeds

    w, ai, ao, d, dm = 10000 * RPM, math.radians(49.3), math.radians(32.5), 22.23e-3, 125.3e-3
    ui, uo = analysis.entrainment_velocities(w, ai, ao, d, dm)
    beta = attitude_angle(ai, ao, d, dm)
    s = ball_speeds(w, ai, ao, beta, d, dm)
    # raceway speed in the cage frame, and the ball surface speed, at each contact
    assert ui == pytest.approx((w - s.cage_speed) * (dm - d * math.cos(ai)) / 2, rel=1e-12)
    assert ui == pytest.approx(s.ball_spin_speed * d / 2 * math.cos(ai - beta), rel=1e-12)
    assert uo == pytest.approx(s.cage_speed * (dm + d * math.cos(ao)) / 2, rel=1e-12)


def test_pure_thrust_gives_the_same_film_on_every_ball_and_batches_agree():
    loads = np.array([[0, 0, 5e3, 0, 0], [0, 0, 20e3, 0, 0]], dtype=float)
    r = analysis.film_analysis(B218, loads, 6000 * RPM, 0.01, 2e-8)
    assert r.minimum_film.shape == (2,)
    np.testing.assert_allclose(r.minimum_film_inner, np.broadcast_to(r.minimum_film_inner[:, :1], (2, 16)), rtol=1e-9)
    one = analysis.film_analysis(B218, loads[1], 6000 * RPM, 0.01, 2e-8)
    assert one.minimum_film == pytest.approx(r.minimum_film[1], rel=1e-12)
    assert r.minimum_film[1] < r.minimum_film[0]  # a heavier load thins the film (W^-0.073)


def test_loads_at_rest_and_low_lambda_warning():
    r = analysis.film_analysis(B218, [0, 0, 5e3, 0, 0], 100 * RPM, 0.002, 1.5e-8, loads_at="rest",
                               roughness_ball=0.2e-6, roughness_race=0.3e-6)
    assert r.regime == "boundary"
    assert any("Lambda" in n and "< 1" in n for n in r.warnings)
    ai = r.contact_angle_inner
    np.testing.assert_array_equal(ai, r.contact_angle_outer)  # at rest both angles are one


def test_estimated_pressure_viscosity_is_said_and_bad_options_raise():
    r = analysis.film_analysis(B218, [0, 0, 5e3, 0, 0], 3000 * RPM, 0.02)
    assert any("Wooster" in n for n in r.warnings)
    with pytest.raises(InputError, match="loads_at must be one of"):
        analysis.film_analysis(B218, [0, 0, 5e3, 0, 0], 3000 * RPM, 0.02, loads_at="now")
    with pytest.raises(InputError, match="shaft_speed must be > 0"):
        analysis.film_analysis(B218, [0, 0, 5e3, 0, 0], 0.0, 0.02, 2e-8)


def test_inlet_heating_reduces_every_film():
    cold = analysis.film_analysis(B218, [0, 0, 5e3, 0, 0], 12000 * RPM, 0.02, 2e-8)
    hot = analysis.film_analysis(B218, [0, 0, 5e3, 0, 0], 12000 * RPM, 0.02, 2e-8, inlet_heating=(0.03, 0.14))
    assert np.all(hot.minimum_film_inner < cold.minimum_film_inner)


def test_starvation_risk_from_skfs_replenishment_factor():
    from bearinglab import friction

    b = catalog.get("6205-2RS").replace(inner_conformity=0.52, outer_conformity=0.53)
    w = 15000 * RPM
    phi = friction.replenishment_factor(68e-6, w, b.bore, b.outside_diameter, lubrication="grease")
    # by hand: K_rs = 6e-8 (grease), K_Z = 3.1, rpm, mm^2/s, mm
    assert phi == pytest.approx(math.exp(-6e-8 * 68 * 15000 * 77 * math.sqrt(3.1 / 54)), rel=1e-13)
    assert phi < analysis.STARVATION_LIMIT
    starved = analysis.film_analysis(b, [1e3, 0, 0, 0, 0], w, 0.059, 2e-8, lubrication="grease",
                                     kinematic_viscosity=68e-6)
    assert any(n.startswith("starvation risk (grease)") for n in starved.warnings)
    slow = analysis.film_analysis(b, [1e3, 0, 0, 0, 0], 1000 * RPM, 0.059, 2e-8, lubrication="oil-jet",
                                  kinematic_viscosity=68e-6)
    assert not any("starvation" in n for n in slow.warnings)
    with pytest.raises(InputError, match="kinematic_viscosity is needed"):
        analysis.film_analysis(b, [1e3, 0, 0, 0, 0], w, 0.059, 2e-8, lubrication="grease")


@settings(max_examples=15, deadline=None)
@given(s=st.floats(1.1, 20.0), thrust=st.floats(2e3, 30e3))
def test_every_film_scales_with_viscosity_to_the_power_of_its_fit(s, thrust):
    """The loads and angles do not depend on the oil: each film scales as eta^0.68 (h_min), eta^0.67 (h_c)."""
    base = analysis.film_analysis(B218, [0.1 * thrust, 0, thrust, 0, 0], 8000 * RPM, 0.01, 2e-8)
    thick = analysis.film_analysis(B218, [0.1 * thrust, 0, thrust, 0, 0], 8000 * RPM, 0.01 * s, 2e-8)
    np.testing.assert_allclose(thick.minimum_film_inner / base.minimum_film_inner, s**0.68, rtol=1e-11)
    np.testing.assert_allclose(thick.central_film_outer / base.central_film_outer, s**0.67, rtol=1e-11)
