"""Issue 30 item 1: a ball bearing with zero or negative operating clearance is solved as preloaded.

References computed here, independently of the model: the Hertz stiffness of both contacts from the
curvatures of Harris and Kotzalas (ch. 2) and the exact ellipticity (complete elliptic integrals of
scipy), and the ring's equilibrium summed ball by ball and solved by scipy's brentq.
"""

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk

from bearinglab import catalog
from bearinglab.bearing import BallBearing, Material
from bearinglab.errors import InputError
from bearinglab.quasistatic import combined, preload
from bearinglab.units import RPM

STEEL = Material("steel", 210e9, 0.3, 7850.0)
DEEP = BallBearing(n_balls=7, ball_diameter=11.5e-3, pitch_diameter=43.5e-3, inner_conformity=0.52,
                   outer_conformity=0.53, radial_clearance=-8e-6, type="radial", ball_material=STEEL,
                   ring_material=STEEL)
B218 = catalog.get("B218")


def _hertz_k(curvature_sum, curvature_difference, e_prime):
    """K of Q = K delta^1.5 for a point contact (Harris and Kotzalas ch. 4): the ellipticity k from
    F(rho) = ((k^2 + 1) E - 2 K) / ((k^2 - 1) E), delta* = (2 K / pi) (pi / (2 k^2 E))^(1/3) and
    delta = delta* (3 Q / (E' sum rho))^(2/3) sum rho / 2."""
    def f(k):
        m = 1.0 - 1.0 / k**2
        return ((k * k + 1.0) * ellipe(m) - 2.0 * ellipk(m)) / ((k * k - 1.0) * ellipe(m)) - curvature_difference

    k = brentq(f, 1.0 + 1e-9, 200.0, xtol=1e-15, rtol=1e-15)
    m = 1.0 - 1.0 / k**2
    delta_star = 2.0 * ellipk(m) / math.pi * (math.pi / (2.0 * k * k * ellipe(m))) ** (1.0 / 3.0)
    return e_prime * curvature_sum / 3.0 * (2.0 / (delta_star * curvature_sum)) ** 1.5


def _kn(bearing, alpha):
    """K_n = (K_i^-2/3 + K_o^-2/3)^-3/2 of a ball at the contact angle alpha (both contacts)."""
    d, dm, fi, fo = bearing.ball_diameter, bearing.pitch_diameter, bearing.inner_conformity, bearing.outer_conformity
    m = bearing.ball_material  # balls and rings of one steel: 2 / E' = 2 (1 - nu^2) / E
    assert m == bearing.ring_material
    e_prime = m.elastic_modulus / (1.0 - m.poisson_ratio**2)
    g = d * math.cos(alpha) / dm
    ks = []
    for f, race in ((fi, 1.0), (fo, -1.0)):
        extra = race * 2.0 * g / (1.0 - race * g)
        total = 4.0 - 1.0 / f + extra
        ks.append(_hertz_k(total / d, (1.0 / f + extra) / total, e_prime))
    return (ks[0] ** (-2.0 / 3.0) + ks[1] ** (-2.0 / 3.0)) ** -1.5


def _radial_equilibrium(bearing, fr):
    """u_r with F_r = sum_j K_n max(-e/2 + u_r cos psi_j, 0)^1.5 cos psi_j (all balls at alpha = 0)."""
    psi = 2 * np.pi * np.arange(bearing.n_balls) / bearing.n_balls
    kn, d0 = _kn(bearing, 0.0), -bearing.radial_clearance / 2

    def balls(u):
        return kn * np.maximum(d0 + u * np.cos(psi), 0.0) ** 1.5

    u = brentq(lambda u: np.sum(balls(u) * np.cos(psi)) - fr, 0.0, 1e-3, xtol=1e-22, rtol=1e-15)
    return u, balls(u)


@pytest.mark.parametrize("engine", ["auto", "numpy"])
@pytest.mark.parametrize("fr", [50.0, 400.0, 1500.0, 6000.0])
def test_negative_clearance_under_radial_load_against_an_independent_equilibrium(fr, engine):
    r = combined.combined_analysis(DEEP, [fr, 0.0, 0.0, 0.0, 0.0], engine=engine)
    u, q = _radial_equilibrium(DEEP, fr)
    assert r.converged
    assert_allclose(r.displacement[0], u, rtol=1e-9)
    assert np.all(np.abs(r.displacement[1:] * [1, 1, 0.02, 0.02]) <= 1e-9 * u)  # symmetric: no other motion
    assert_allclose(r.ball_load_inner, q, rtol=1e-9, atol=1e-9 * q.max())
    if fr < 100.0:  # a light load keeps every ball loaded (the preload is not used up)
        assert np.all(r.ball_load_inner > 0)


def test_zero_load_preload_is_the_closed_form():
    p = preload.preload(DEEP)
    z, d0, kn = DEEP.n_balls, 4e-6, _kn(DEEP, 0.0)
    psi = 2 * np.pi * np.arange(z) / z
    q0 = kn * d0**1.5
    g0 = DEEP.groove_distance + d0
    arm = DEEP.pitch_diameter / 2
    assert p.interference == pytest.approx(d0, rel=1e-12)
    assert p.ball_load == pytest.approx(q0, rel=1e-9) and p.ball_load_sum == pytest.approx(z * q0, rel=1e-9)
    assert_allclose(np.diag(p.stiffness), [1.5 * kn * math.sqrt(d0) * np.sum(np.cos(psi) ** 2),
                                           1.5 * kn * math.sqrt(d0) * np.sum(np.sin(psi) ** 2), z * q0 / g0,
                                           arm**2 * np.sum(np.sin(psi) ** 2) * q0 / g0,
                                           arm**2 * np.sum(np.cos(psi) ** 2) * q0 / g0], rtol=1e-9)
    assert p.stiffness[0, 0] == pytest.approx(0.75 * z * kn * math.sqrt(d0), rel=1e-9)  # Z >= 3
    r = combined.combined_analysis(DEEP, np.zeros(5))
    assert np.all(r.displacement == 0.0) and r.converged
    assert_allclose(r.ball_load_inner, q0, rtol=1e-9)


def test_zero_clearance_has_no_preload_and_solves():
    b = DEEP.replace(radial_clearance=0.0)
    p = preload.preload(b)
    assert p.ball_load == 0.0 and p.interference == 0.0 and np.all(p.stiffness == 0.0)
    u, _q = _radial_equilibrium(b, 1000.0)
    r = combined.combined_analysis(b, [1000.0, 0, 0, 0, 0])
    assert_allclose(r.displacement[0], u, rtol=1e-9)
    assert b.contact_angle == 0.0 and combined.axial_play_takeup(b.ball_diameter, 0.52, 0.53, b.contact_angle) == 0.0


def test_preloaded_angular_contact_bearing_under_thrust():
    """B218 with its clearance used up: at zero load every ball at alpha = 0; a thrust turns them all to one
    angle alpha with F_a = Z K_n(alpha) (g_0 / cos alpha - A)^1.5 sin alpha and delta_z = g_0 tan alpha."""
    b = B218.replace(radial_clearance=-6e-6)
    assert b.contact_angle == 0.0
    rest = combined.combined_analysis(b, np.zeros(5))
    assert np.all(rest.ball_load_inner > 0) and np.all(rest.contact_angle_inner == 0.0)
    fa = 20e3
    big_a = b.groove_distance
    g0 = big_a + 3e-6

    def thrust(alpha):
        return b.n_balls * _kn(b, alpha) * (g0 / math.cos(alpha) - big_a) ** 1.5 * math.sin(alpha) - fa

    alpha = brentq(thrust, 1e-6, 1.4, xtol=1e-15)
    r = combined.combined_analysis(b, [0, 0, fa, 0, 0])
    assert_allclose(r.contact_angle_inner, alpha, rtol=0, atol=1e-9)
    assert_allclose(r.displacement[2], g0 * math.tan(alpha), rtol=1e-8)


@pytest.mark.parametrize("w", [0.0, 8000 * RPM])
def test_engines_agree_on_a_preloaded_bearing(w):
    loads = np.random.default_rng(2).normal(size=(12, 5)) * [800, 800, 800, 8.0, 8.0]
    if w:
        loads[:, 2] = np.abs(loads[:, 2]) + 500
    fast = combined.combined_analysis(DEEP, loads, w, engine="compiled", on_failure="flag")
    slow = combined.combined_analysis(DEEP, loads, w, engine="numpy", on_failure="flag")
    assert fast.converged.all() and slow.converged.all()
    size = np.max(np.abs(slow.displacement[:, :3]), axis=-1, keepdims=True)
    assert np.all(np.abs(fast.displacement[:, :3] - slow.displacement[:, :3]) <= 1e-10 * size)


def test_a_preload_of_more_than_a_ball_diameter_is_refused():
    with pytest.raises(InputError, match="radial_clearance must be >= "):
        DEEP.replace(radial_clearance=-30e-3)
    with pytest.raises(InputError, match="radial_clearance must be in"):
        combined.load_distribution([0, 0, 0, 0, 0], 0.0, 7, 11.5e-3, 43.5e-3, 0.52, 0.53, None, 2.3e11, 7850.0,
                                   radial_clearance=-30e-3)
    with pytest.raises(InputError, match="disagree"):
        combined.load_distribution([0, 0, 0, 0, 0], 0.0, 7, 11.5e-3, 43.5e-3, 0.52, 0.53, 0.1, 2.3e11, 7850.0,
                                   radial_clearance=-3e-6)


def test_the_note_says_how_far_the_clearance_is_negative():
    note = preload.preload_note(DEEP)
    assert "-8 um" in note and "preloaded" in note and "N/um" in note
    assert preload.preload_note(DEEP.replace(radial_clearance=5e-6)) is None
    assert "0 um" in preload.preload_note(DEEP.replace(radial_clearance=0.0))


def test_high_speed_of_a_bearing_without_clearance_joins_spec_004_at_zero_clearance():
    """A bearing with zero clearance has no free contact angle for spec 004's model; it is solved by the
    5-DOF model with the rings held concentric. At a clearance of 1 nm spec 004's model gives the same
    state (its delta_a counts from first contact, A sin(alpha0) ~ 1 um further on)."""
    from bearinglab import quasistatic

    fa, w = np.array([5e3, 20e3]), 10000 * RPM
    zero = quasistatic.high_speed_analysis(B218.replace(radial_clearance=0.0), fa, w)
    tiny = B218.replace(radial_clearance=1e-9)
    near = quasistatic.high_speed_analysis(tiny, fa, w)
    takeup = tiny.groove_distance * math.sin(tiny.contact_angle)
    assert zero.converged.all() and list(zero.method) == ["newton", "newton"]
    assert_allclose(zero.contact_angle_inner, near.contact_angle_inner, atol=2e-4)
    assert_allclose(zero.contact_angle_outer, near.contact_angle_outer, atol=2e-4)
    assert_allclose(zero.axial_displacement, near.axial_displacement + takeup, rtol=1e-3)
    for name in ("ball_load_inner", "ball_load_outer", "centrifugal_force", "cage_speed", "deflection_inner"):
        assert_allclose(getattr(zero, name), getattr(near, name), rtol=1e-3, err_msg=name)
    assert np.all(quasistatic.sign_change_thrust(B218.replace(radial_clearance=-2e-6), [3000 * RPM]) == 0.0)
    with pytest.raises(InputError, match="5-DOF model"):
        quasistatic.high_speed_analysis(B218.replace(radial_clearance=0.0), 5e3, w, constants="harris")
