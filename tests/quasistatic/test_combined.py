"""Issue 11: the combined-load (5-DOF) model, quasistatic.combined.

Special cases (pure thrust at speed = high-speed model ball by ball; pure thrust at rest = the axial-angle
method and the static thrust solution; zero speed = rest), equilibrium, symmetries, the analytic tangent
stiffness against finite differences of the solver, light-load warnings, failure handling.
"""

import dataclasses
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose

from bearinglab import catalog, geometry, hertz, quasistatic, stand, static
from bearinglab.bearing import BallBearing, Material
from bearinglab.errors import ConvergenceError, InputError
from bearinglab.quasistatic import combined
from bearinglab.units import RPM

B218 = catalog.get("B218")
STAND = catalog.get("4-1006095")
STEEL_210 = Material("steel", 210e9, 0.3, 7850.0)
DEEP = BallBearing(n_balls=7, ball_diameter=11.5e-3, pitch_diameter=43.5e-3, inner_conformity=0.52,
                   outer_conformity=0.53, radial_clearance=10e-6, type="radial", ball_material=STEEL_210,
                   ring_material=STEEL_210)
ANGULAR = BallBearing(n_balls=9, ball_diameter=7.144e-3, pitch_diameter=33.5e-3, inner_conformity=0.52,
                      outer_conformity=0.53, contact_angle=math.radians(25), type="angular")
SLOW = settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
CWRU = dataclasses.replace(catalog.get("6205-2RS"), inner_conformity=0.52, outer_conformity=0.53)  # not in the data
UM_MRAD = np.array([1e-6, 1e-6, 1e-6, 1e-3, 1e-3])  # displacements compared in um and mrad

loads_strategy = st.tuples(st.floats(-3e3, 3e3), st.floats(-3e3, 3e3), st.floats(-3e3, 3e3),
                           st.floats(-30.0, 30.0), st.floats(-30.0, 30.0)).filter(
    lambda f: math.hypot(f[0], f[1]) + abs(f[2]) + math.hypot(f[3], f[4]) / 0.02 > 50.0)


def _thrust(fa):
    fa = np.asarray(fa, dtype=float)
    out = np.zeros(fa.shape + (5,))
    out[..., 2] = fa
    return out


# ---------------------------------------------------------------- special cases
def test_pure_thrust_at_speed_equals_high_speed_ball_by_ball():
    fa = np.array([2.5e3, 10e3, 45e3])[:, None]
    w = np.array([0.0, 3000.0, 6000.0, 15000.0])[None, :] * RPM
    ref = quasistatic.high_speed_analysis(B218, fa, w)
    got = combined.combined_analysis(B218, _thrust(fa + 0 * w), w)
    assert got.converged.all()
    deg = 180.0 / math.pi
    assert_allclose(got.contact_angle_inner * deg, np.repeat(ref.contact_angle_inner[..., None] * deg, 16, -1),
                    rtol=0, atol=1e-6)  # issue 11: 1e-6 deg
    assert_allclose(got.contact_angle_outer * deg, np.repeat(ref.contact_angle_outer[..., None] * deg, 16, -1),
                    rtol=0, atol=1e-6)
    for mine, theirs in ((got.ball_load_inner, ref.ball_load_inner), (got.ball_load_outer, ref.ball_load_outer)):
        assert_allclose(mine, np.repeat(theirs[..., None], 16, -1), rtol=1e-7)  # issue 11: 1e-7 relative
    # delta_z is measured from the concentric position: high-speed's delta_a plus half the axial play
    half_play = B218.groove_distance * math.sin(B218.contact_angle)
    assert_allclose(got.displacement[..., 2], ref.axial_displacement + half_play, rtol=0, atol=1e-11)
    assert_allclose(got.centrifugal_force[..., 0], ref.centrifugal_force, rtol=1e-7)
    assert_allclose(np.abs(got.gyroscopic_moment[..., 0]), ref.gyroscopic_moment, rtol=1e-7)
    assert_allclose(got.displacement[..., [0, 1, 3, 4]], 0.0, atol=1e-15)


@pytest.mark.parametrize("stiffness_at", ["operating", "free"])
def test_pure_thrust_at_rest_equals_axial_angle_with_exact_hertz(stiffness_at):
    """stand_analysis (the ``axial-angle`` command, exact Hertz, the bearing's materials) evaluates the Hertz
    constants at the loaded angle by default and at alpha0 with stiffness_at="free" (spec 000); the combined
    model under pure thrust gives the same angles and loads either way."""
    loads = np.array([0.5, 2.0, 20.0]) * 9.80665
    ref = stand.stand_analysis(STAND, loads, hertz="exact", stiffness_at=stiffness_at)
    got = combined.combined_analysis(STAND, _thrust(loads), stiffness_at=stiffness_at)
    assert_allclose(got.contact_angle_inner, np.repeat(ref.contact_angle[:, None], 7, 1), rtol=0, atol=1e-12)
    assert_allclose(got.ball_load_inner, np.repeat(ref.ball_load[:, None], 7, 1), rtol=1e-11)
    half_play = STAND.groove_distance * math.sin(STAND.contact_angle)
    assert_allclose(got.displacement[:, 2], ref.axial_displacement + half_play, rtol=1e-10)


def test_pure_thrust_at_rest_equals_the_static_thrust_solution():
    fa = np.array([100.0, 5e3, 40e3])
    ref = static.contact_angle_under_thrust(fa, *combined._bearing_args(B218)[:7])
    got = combined.combined_analysis(B218, _thrust(fa))
    assert_allclose(got.contact_angle_inner[:, 3], ref.contact_angle, rtol=0, atol=1e-12)
    assert_allclose(got.ball_load_inner[:, 5], ref.ball_load, rtol=1e-10)
    half_play = B218.groove_distance * math.sin(B218.contact_angle)
    assert_allclose(got.displacement[:, 2] - half_play, ref.axial_displacement, rtol=1e-9)


@pytest.mark.parametrize("loads", [[0, 0, 900.0, 0, 0], [300.0, -200.0, 900.0, 2.0, -1.0]])
def test_zero_speed_limit_is_the_static_solution(loads):
    """At rest the balls are springs between the groove centres; the ball equilibrium at speed (eqs. 5-6)
    tends to it as the speed goes to zero (1 rpm: F_c ~ 1e-7 of the ball loads here)."""
    rest = combined.combined_analysis(ANGULAR, loads)
    slow = combined.combined_analysis(ANGULAR, loads, 1.0 * RPM)
    assert_allclose(slow.displacement / UM_MRAD, rest.displacement / UM_MRAD, rtol=1e-5, atol=1e-6)
    assert_allclose(slow.ball_load_inner, rest.ball_load_inner, rtol=1e-5, atol=1e-5 * rest.max_ball_load)


# ---------------------------------------------------------------- equilibrium and symmetries
def _sums(r, arm):
    """The five equilibrium sums from the returned ball loads and angles (recomputed here)."""
    q, a, psi = r.ball_load_inner, r.contact_angle_inner, r.azimuth
    return np.stack([np.sum(q * np.cos(a) * np.cos(psi), -1), np.sum(q * np.cos(a) * np.sin(psi), -1),
                     np.sum(q * np.sin(a), -1), arm * np.sum(q * np.sin(a) * np.sin(psi), -1),
                     -arm * np.sum(q * np.sin(a) * np.cos(psi), -1)], -1)


# bearing, load scale [N], speed [rad/s] for the property test below; moments scale with d_m / 2
PROPERTY_BEARINGS = [(DEEP, 2e3, 0.0), (ANGULAR, 1e3, 0.0), (ANGULAR, 1e3, 20000 * RPM), (B218, 2e4, 0.0),
                     (B218, 2e4, 10000 * RPM), (CWRU, 3e3, 0.0), (STAND, 60.0, 0.0)]


@st.composite
def awkward_loads(draw, scale, arm):
    """Load vectors an engineer may well type: zero and near-zero components, pure moments, pure radial loads,
    loads that unload most balls, thrust of either sign."""
    def component(s):
        return draw(st.one_of(st.just(0.0), st.sampled_from([1.0 / 64, -1.0 / 64, 1e-6]),
                              st.floats(-s, s, allow_subnormal=False)))
    kind = draw(st.sampled_from(["any", "radial", "moment", "one ball"]))
    f = [component(scale) for _ in range(3)] + [component(0.3 * scale * arm) for _ in range(2)]
    if kind == "radial":
        f[2:] = [component(1e-3), 0.0, 0.0]
    elif kind == "moment":
        f[:3] = [0.0, 0.0, component(1e-3)]
    elif kind == "one ball":  # a radial load much larger than everything else
        f[0] = math.copysign(scale, f[0] or 1.0)
        f[2:] = [component(1e-2 * scale), component(1e-3 * scale * arm), 0.0]
    return f


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data(), case=st.sampled_from(PROPERTY_BEARINGS))
def test_every_case_is_in_equilibrium_or_flagged_with_a_reason(data, case):
    """Issue 11: every returned case has a relative residual <= 1e-9 and no negative ball load; any other case is
    flagged (converged False, NaN) with a reason among the warnings. A thrust F_z <= 0 on a single
    angular-contact bearing is warned about. Six cases per call, so the batched path is exercised too."""
    bearing, scale, w = case
    arm = bearing.pitch_diameter / 2
    loads = np.array(data.draw(st.lists(awkward_loads(scale, arm), min_size=6, max_size=6)))
    r = combined.combined_analysis(bearing, loads, w, on_failure="flag")
    ok = r.converged
    assert np.all(r.residual[ok] <= 1e-9) and np.all(r.ball_load_inner[ok] >= 0.0)
    assert np.all(r.ball_load_outer[ok] >= 0.0)
    arms = np.array([1.0, 1.0, 1.0, 1 / arm, 1 / arm])
    miss = np.linalg.norm((_sums(r, arm) - loads) * arms, axis=-1)[ok]
    size = np.maximum(np.linalg.norm(loads * arms, axis=-1), np.sum(r.ball_load_inner, axis=-1))[ok]
    assert np.all(miss <= 1.01e-9 * size)  # recomputed from the returned loads and angles (rounding: 1 %)
    if bearing.type == "angular" and np.any(ok & (loads[:, 2] <= 0) & np.any(loads != 0, axis=1)):
        assert any("thrust F_z <= 0" in m for m in r.warnings)
    assert np.all(np.isnan(r.displacement[~ok])) and np.all(np.isnan(r.ball_load_inner[~ok]))
    flagged = [m for m in r.warnings if "not converged" in m]
    assert sum(int(m.split()[0]) for m in flagged) == int((~ok).sum())  # every failure counted once ...
    assert all(len(m.split("): ", 1)[1]) > 20 for m in flagged)  # ... with a reason


def test_batched_call_equals_case_by_case():
    rng = np.random.default_rng(7)
    loads = np.abs(rng.normal(size=(6, 5))) * [800, 800, 800, 10, 10] * [1, -1, 1, 1, -1]  # F_z >= 0: angular
    batch = combined.combined_analysis(ANGULAR, loads)
    for k in range(6):
        one = combined.combined_analysis(ANGULAR, loads[k])
        assert_allclose(one.displacement, batch.displacement[k], rtol=1e-10, atol=1e-16)
        assert_allclose(one.ball_load_inner, batch.ball_load_inner[k], rtol=1e-9, atol=1e-9)


@pytest.mark.parametrize("shift", [1, 4])
@pytest.mark.parametrize("loads", [[700.0, 300.0, 500.0, 3.0, -2.0], [-900.0, 100.0, 200.0, 0.0, 5.0]])
def test_rotating_the_load_by_a_ball_pitch_rotates_the_distribution(loads, shift):
    z = ANGULAR.n_balls
    phi = 2 * math.pi * shift / z
    rot = np.array([[math.cos(phi), -math.sin(phi)], [math.sin(phi), math.cos(phi)]])
    f = np.asarray(loads)
    turned = np.concatenate([rot @ f[:2], f[2:3], rot @ f[3:5]])
    a = combined.combined_analysis(ANGULAR, f)
    b = combined.combined_analysis(ANGULAR, turned)
    scale = a.max_ball_load
    assert_allclose(b.ball_load_inner, np.roll(a.ball_load_inner, shift), rtol=1e-8, atol=1e-9 * scale)
    assert_allclose(b.displacement[2], a.displacement[2], rtol=1e-8, atol=1e-15)


@SLOW
@given(loads=loads_strategy)
def test_mirror_image_in_the_xz_plane(loads):
    """y -> -y: (F_x, -F_y, F_z, -M_x, M_y) loads ball -j as (F) loads ball j; the displacement mirrors too."""
    f = np.asarray(loads)
    mirrored = f * [1, -1, 1, -1, 1]
    a = combined.combined_analysis(DEEP, f)
    b = combined.combined_analysis(DEEP, mirrored)
    back = np.roll(a.ball_load_inner[::-1], 1)  # ball j at psi_j goes to -psi_j = psi_{Z-j}
    assert_allclose(b.ball_load_inner, back, rtol=1e-8, atol=1e-9 * a.max_ball_load)
    assert_allclose(b.displacement / UM_MRAD, a.displacement * [1, -1, 1, -1, 1] / UM_MRAD, rtol=1e-7, atol=1e-9)


def test_reversing_the_radial_load_with_the_ball_set_turned_by_half_a_turn():
    loads = np.array([1200.0, 0.0, 300.0, 0.0, 0.0])
    a = combined.combined_analysis(DEEP, loads)
    b = combined.combined_analysis(DEEP, loads * [-1, 1, 1, 1, 1], first_ball_angle=math.pi)
    assert_allclose(b.ball_load_inner, a.ball_load_inner, rtol=1e-9)
    assert_allclose(b.displacement[:3], a.displacement[:3] * [-1, 1, 1], rtol=1e-9, atol=1e-16)


def test_unloaded_balls_carry_zero_load():
    r = combined.combined_analysis(DEEP, [1000.0, 0, 0, 0, 0])
    assert np.sum(r.ball_load_inner == 0.0) >= 2  # the clearance leaves the far balls free
    assert np.all(r.ball_load_inner >= 0.0)
    assert np.all(r.max_pressure_inner[r.ball_load_inner == 0.0] == 0.0)


def test_zero_load_gives_the_concentric_position():
    r = combined.combined_analysis(DEEP, np.zeros(5))
    assert r.converged and np.all(r.displacement == 0.0) and np.all(r.ball_load_inner == 0.0)


def test_max_pressure_is_the_exact_hertz_pressure():
    r = combined.combined_analysis(ANGULAR, [900.0, 200.0, 500.0, 2.0, 0.0])
    loaded = r.ball_load_inner > 0
    d, dm = ANGULAR.ball_diameter, ANGULAR.pitch_diameter
    curv = geometry.raceway_curvature(d, dm, ANGULAR.inner_conformity, r.contact_angle_inner[loaded], race="inner")
    ref = hertz.point_contact(r.ball_load_inner[loaded], curv.curvature_sum, curv.curvature_difference,
                              ANGULAR.reduced_modulus)
    assert_allclose(r.max_pressure_inner[loaded], ref.p_max, rtol=1e-11)


# ---------------------------------------------------------------- at speed
def test_ball_equilibrium_at_speed_with_combined_load():
    """Every ball satisfies spec 004 eqs. (5)-(6) with F_c and M_g from the public high-speed pieces."""
    w = 12000 * RPM
    r = combined.combined_analysis(B218, [6e3, -2e3, 15e3, 80.0, 40.0], w)
    assert r.converged and r.residual <= 1e-9
    ai, ao, qi, qo = r.contact_angle_inner, r.contact_angle_outer, r.ball_load_inner, r.ball_load_outer
    d, dm = B218.ball_diameter, B218.pitch_diameter
    beta = quasistatic.attitude_angle(ai, ao, d, dm)
    speeds = quasistatic.ball_speeds(w, ai, ao, beta, d, dm)
    fc = quasistatic.centrifugal_force(speeds.cage_speed, B218.ball_mass, dm)
    mg = quasistatic.gyroscopic_moment(speeds.ball_spin_speed, speeds.cage_speed, beta, B218.ball_mass, d)
    assert_allclose(r.centrifugal_force, fc, rtol=1e-12)
    assert_allclose(r.gyroscopic_moment, mg, rtol=1e-12)
    axial = qi * np.sin(ai) - qo * np.sin(ao) - 2 * mg / d * np.cos(ao)  # outer-raceway control
    radial = qi * np.cos(ai) - qo * np.cos(ao) + 2 * mg / d * np.sin(ao) + fc
    assert_allclose(axial, 0.0, atol=1e-9 * qo.max())
    assert_allclose(radial, 0.0, atol=1e-9 * qo.max())
    assert_allclose(_sums(r, dm / 2), [6e3, -2e3, 15e3, 80.0, 40.0], atol=1e-8 * 15e3)


def test_light_thrust_at_high_speed_is_warned_about():
    """Issue 11: B218 at 0.05 kN and 15 000 rpm drives alpha_o to about zero; it must say so."""
    r = combined.combined_analysis(B218, [0, 0, 50.0, 0, 0], 15000 * RPM)
    assert r.converged
    assert math.degrees(r.contact_angle_outer[0]) < 1.0
    text = " ".join(r.warnings)
    assert "minimum load: 1 of 1 case(s)" in text and "outer contact angle" in text
    ok = combined.combined_analysis(B218, [0, 0, 20e3, 0, 0], 3000 * RPM)
    assert ok.warnings == ()
    assert combined.combined_analysis(B218, [0, 0, 50.0, 0, 0]).warnings == ()  # at rest nothing to warn


def test_light_load_warnings_for_the_high_speed_model():
    s = quasistatic.high_speed_analysis(B218, [50.0, 20e3], 15000 * RPM)
    msgs = combined.light_load_warnings(s.axial_load, s.contact_angle_inner, s.contact_angle_outer, s.shaft_speed,
                                       *combined._bearing_args(B218)[:3], B218.contact_angle)
    assert len(msgs) == 2 and "case 0" in msgs[1]
    flags = combined.light_load(s.axial_load, s.contact_angle_inner, s.contact_angle_outer, s.shaft_speed,
                                *combined._bearing_args(B218)[:3], B218.contact_angle)
    assert flags.outer_angle_lost.tolist() == [True, False]
    assert_allclose(flags.minimum_axial_load, static.min_axial_load_gyroscopic(
        15000 * RPM, 16, B218.ball_diameter, B218.pitch_diameter, B218.contact_angle), rtol=1e-12)


def test_angular_contact_ball_on_the_low_shoulder_is_warned_about():
    """A light thrust under a large radial load leaves the balls opposite the load at a negative angle."""
    r = combined.combined_analysis(ANGULAR, [1500.0, 0, 50.0, 0, 0])
    assert r.converged and np.any((r.ball_load_inner > 0) & (r.contact_angle_inner < 0))
    assert any("low shoulder" in m for m in r.warnings)
    assert not combined.combined_analysis(DEEP, [1500.0, 0, -200.0, 0, 0]).warnings


@pytest.mark.parametrize("fz", [-1.0, 0.0, 1.0])
@pytest.mark.parametrize("other", [[1000.0, 0.0, 0.0, 0.0], [0.0, 0.0, 3.0, 0.0]], ids=["radial", "moment"])
def test_angular_contact_thrust_rule_has_no_jump_at_zero(fz, other):
    """A radial load or a moment on a single angular-contact bearing needs F_z > 0 to be carried as one.
    Every side of F_z = 0 is solved with the full groove, in equilibrium, and the answer is continuous
    through F_z = 0; F_z <= 0 is warned about (F_z = 0 used to return every ball at alpha = 0 silently),
    and so is any ball loaded at a negative contact angle."""
    loads = np.array([other[0], other[1], fz, other[2], other[3]])
    r = combined.combined_analysis(ANGULAR, loads)
    assert r.converged and r.residual <= 1e-9 and np.all(r.ball_load_inner >= 0.0)
    assert_allclose(_sums(r, ANGULAR.pitch_diameter / 2), loads, rtol=0, atol=1e-9 * 1000.0)
    unheld = [m for m in r.warnings if "thrust F_z <= 0" in m]
    assert len(unheld) == (fz <= 0)
    assert all("cannot carry them as an angular-contact bearing" in m for m in unheld)
    low = np.any((r.ball_load_inner > 0) & (r.contact_angle_inner < 0))
    assert low == any("negative contact angle" in m for m in r.warnings)
    if fz < 0:
        assert low  # the balls are pushed onto the low shoulder
    # continuity: a thousandth of the thrust changes the displacement by little (no jump at F_z = 0)
    near = combined.combined_analysis(ANGULAR, loads * [1, 1, 1e-3, 1, 1] + [0, 0, 1e-3 * (fz == 0), 0, 0])
    zero = combined.combined_analysis(ANGULAR, loads * [1, 1, 0, 1, 1])
    assert_allclose(near.displacement[:2], zero.displacement[:2], rtol=0, atol=2e-3 * np.abs(zero.displacement).max())


def test_negative_thrust_on_a_single_angular_contact_bearing_is_warned_about():
    """F_z < 0 pushes the balls of an angular-contact bearing onto its low shoulder: solved with the full
    groove, flagged in the warnings; a deep-groove bearing takes it without a word."""
    r = combined.combined_analysis(ANGULAR, [[1500.0, 0, -200.0, 0, 0], [1500.0, 0, 200.0, 0, 0]])
    assert r.converged.all() and np.all(r.contact_angle_inner[0][r.ball_load_inner[0] > 0] < 0)
    assert any("1 case(s) load a single angular-contact bearing with a thrust F_z <= 0 (first: case 0, "
               "F_z = -200 N)" in m for m in r.warnings)
    assert not combined.combined_analysis(DEEP, [1500.0, 0, -200.0, 0, 0]).warnings


def test_angular_contact_without_any_load_is_concentric():
    r = combined.combined_analysis(ANGULAR, np.zeros(5))
    assert r.converged and np.all(r.displacement == 0.0) and np.all(r.ball_load_inner == 0.0)


def test_nearly_pure_radial_load_on_angular_contact_converges():
    """Regression (issue 11): (-230, 83, 1/64) N on ANGULAR failed after 60 iterations. The clearance lets the
    ring tilt almost freely; the tiny thrust is carried by the neighbours of the loaded ball at a large tilt,
    which the Newton used to crawl towards because each shortened step raised its damping."""
    loads = [-230.0, 83.0, 0.015625, 0.0, 0.0]
    r = combined.combined_analysis(ANGULAR, loads)
    assert r.converged and r.residual <= 1e-12 and np.all(r.ball_load_inner >= 0.0)
    assert_allclose(_sums(r, ANGULAR.pitch_diameter / 2), loads, rtol=0, atol=1e-10 * 250.0)
    assert r.iterations < combined.MAX_ITER / 2


# ---------------------------------------------------------------- stiffness
def _fd_solver(bearing, loads, w, **kw):
    """d displacement / d load by central differences of the solver, column by column."""
    out = np.zeros((5, 5))
    for k in range(5):
        h = np.zeros(5)
        h[k] = 1e-4 * (abs(loads[k]) + (100.0 if k < 3 else 2.0))
        up = combined.combined_analysis(bearing, loads + h, w, tol=1e-14, **kw).displacement
        down = combined.combined_analysis(bearing, loads - h, w, tol=1e-14, **kw).displacement
        out[:, k] = (up - down) / (2 * h[k])
    return out


@pytest.mark.parametrize(("bearing", "loads", "w"), [
    (DEEP, np.array([900.0, 300.0, 400.0, 3.0, -2.0]), 0.0),
    (ANGULAR, np.array([500.0, -400.0, 900.0, 2.0, 4.0]), 0.0),
    (B218, np.array([5e3, 2e3, 20e3, 100.0, -50.0]), 10000 * RPM),
])
def test_stiffness_equals_finite_differences_of_the_solver(bearing, loads, w):
    r = combined.combined_analysis(bearing, loads, w)
    compliance = np.linalg.inv(r.stiffness)
    fd = _fd_solver(bearing, loads, w)
    assert_allclose(fd, compliance, rtol=1e-5, atol=1e-6 * np.abs(compliance).max())


def test_stiffness_is_symmetric_at_rest():
    """Exactly (to rounding) with the Hertz constants at the free angle, where the ball forces derive from
    a potential; with the constants at the operating angle, to the small angle dependence of K."""
    loads = [800.0, -300.0, 600.0, 4.0, 1.0]
    for bearing in (DEEP, ANGULAR):
        k = combined.combined_analysis(bearing, loads, stiffness_at="free").stiffness
        assert_allclose(k, k.T, rtol=0, atol=1e-12 * np.abs(k).max())
        k = combined.combined_analysis(bearing, loads).stiffness
        assert_allclose(k, k.T, rtol=0, atol=2e-3 * np.abs(k).max())  # d ln K / d alpha is small


def test_stiffness_units_and_order():
    """Pure thrust on a symmetric set: k_xx = k_yy, k_zz > 0, no coupling into z; tilt terms in N m/rad."""
    k = combined.combined_analysis(ANGULAR, [0, 0, 1000.0, 0, 0]).stiffness
    assert k[0, 0] == pytest.approx(k[1, 1], rel=1e-9) and k[2, 2] > 0
    assert_allclose(k[2, [0, 1, 3, 4]], 0.0, atol=1e-9 * k[2, 2])
    # small tilt of the ring from the axial stiffness of the balls at the pitch radius: k_tt ~ k_zz (d_m/2)^2 / 2
    assert k[3, 3] == pytest.approx(k[2, 2] * (ANGULAR.pitch_diameter / 2) ** 2 / 2, rel=0.05)


# ---------------------------------------------------------------- failures and inputs
def test_non_convergence_raises_or_is_flagged():
    loads = np.array([[800.0, 0, 500.0, 0, 0], [0, 0, 1000.0, 0, 0]])
    with pytest.raises(ConvergenceError, match="combined.load_distribution"):
        combined.combined_analysis(ANGULAR, loads, max_iter=1)
    r = combined.combined_analysis(ANGULAR, loads, max_iter=1, on_failure="flag")
    assert not r.converged.all()
    bad = ~r.converged
    assert np.all(np.isnan(r.displacement[bad])) and np.all(np.isnan(r.ball_load_inner[bad]))
    assert any("not converged" in m for m in r.warnings)


@pytest.mark.parametrize(("kwargs", "match"), [
    ({"loads": [1.0, 2.0, 3.0]}, "loads must have a last axis of length 5"),
    ({"shaft_speed": -1.0}, "shaft_speed must be >= 0"),
    ({"stiffness_at": "nominal"}, "stiffness_at must be one of"),
    ({"raceway_control": "cage"}, "raceway_control must be one of"),
    ({"on_failure": "ignore"}, "on_failure must be one of"),
    ({"bearing_type": "tapered"}, "bearing_type must be one of"),
    ({"loads": [np.nan, 0, 0, 0, 0]}, "loads must be finite"),
])
def test_invalid_inputs_name_the_parameter(kwargs, match):
    kwargs = dict(kwargs)  # a copy: the parameters are shared between runs in one process (mutmut)
    args = {"loads": [100.0, 0, 0, 0, 0], "shaft_speed": 0.0}
    args.update({k: kwargs.pop(k) for k in list(kwargs) if k in args})
    with pytest.raises(InputError, match=match):
        combined.load_distribution(args["loads"], args["shaft_speed"], 7, 11.5e-3, 43.5e-3, 0.52, 0.53, 0.0,
                                   2.3e11, 7850.0, **kwargs)


def test_geometry_helpers():
    assert_allclose(combined.ball_azimuths(4, math.pi / 4), np.radians([45, 135, 225, 315]))
    axial, radial = combined.groove_offsets([1e-6, 0, 2e-6, 0, 1e-4], 4, 11.5e-3, 43.5e-3, 0.52, 0.53, 0.0)
    big_a = 0.05 * 11.5e-3
    assert_allclose(radial, big_a + 1e-6 * np.array([1, 0, -1, 0]), rtol=1e-14)
    assert_allclose(axial, 2e-6 - 43.5e-3 / 2 * 1e-4 * np.array([1, 0, -1, 0]), rtol=1e-12, atol=1e-20)


def test_bench_paths_agree_on_a_small_input(load_bench):
    bench = load_bench("combined")
    loads = bench.cases(12, [1500, 1500, 1500, 15.0, 15.0], seed=3)
    state = bench.batched(bench.DEEP, loads)
    ref = bench.baseline(bench.DEEP, loads)()
    assert state.converged.all()
    assert_allclose(ref / UM_MRAD, state.displacement / UM_MRAD, rtol=0, atol=1e-8)
