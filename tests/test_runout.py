"""Properties of the spindle-bearing runout model (spec 003): the contact problem and its solvers, the
sign conventions, the refinement, rotation metrics, spectrum, Monte Carlo, error files and input checks.

Published cases are in ``tests/validation/test_runout_examples.py``.
"""

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose
from scipy.optimize import linprog

from bearinglab import runout as R
from bearinglab._solve import RUNOUT_CONTACT_TOL_UM
from bearinglab.errors import CatalogError, ConvergenceError, InputError

UM = 1e-6
FAST = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@pytest.fixture(scope="module")
def g():
    return R.geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(15))


def um(x):
    return np.asarray(x) / UM


def regular(n, first=0.0):
    return first + 2 * np.pi * np.arange(n) / n


def contact_tol_um(dk_um):
    """Spec 003 section 7.6: the slack below which a ball touches, scaled by max(1, max |dk| / 1 um)."""
    return RUNOUT_CONTACT_TOL_UM * max(1.0, float(np.max(np.abs(dk_um))))


# ------------------------------------------------------------------------------ contact problem
cases = st.integers(3, 20).flatmap(
    lambda n: st.tuples(
        st.just(n),
        st.floats(0.0, 2 * np.pi),
        st.lists(st.floats(-2.0, 2.0), min_size=n, max_size=n),
        st.booleans(),
    )
)


@FAST
@given(case=cases)
# a face 0.002 um long seen from a tie-break centre 1 um away: the LP's tolerance once came out x1e6
@example(case=(4, 0.0, [-1.056640625, 0.0, 1.0546875, 0.0], False))
# a face 1e-231 um long: its squared length underflowed to 0 in the LP's tie-break projection (nan)
@example(case=(3, 0.0, [0.0, 0.0, 3.5751661739973926e-231], False))
def test_solvers_agree_on_random_cases(case):
    """Section 16.2: LP, triple enumeration and the dual agree within 1e-6 um (some inputs rounded to
    0.1 um to create ties)."""
    n, first, dk, rounded = case
    dk = np.round(dk, 1) if rounded else np.asarray(dk)
    th = regular(n, first)
    sols = [R.solve_contact(dk * UM, th, method=m) for m in ("dual", "triples", "lp")]
    for s in sols[1:]:
        for name in ("constant", "sine", "cosine", "face_diameter"):
            assert um(getattr(s, name)) == pytest.approx(um(getattr(sols[0], name)), abs=1e-6), name
        assert np.array_equal(s.degenerate, sols[0].degenerate)


def test_triples_face_of_a_near_tie_is_a_point():
    # four balls tied, the fifth 6e-8 um higher (hypothesis found it): the face is one point for the
    # dual and the LP; the triple enumeration once counted vertices within the face tolerance of it
    dk = np.array([0.0, 0.0, 0.0, 0.0, 5.960464477539063e-08]) * UM
    sols = [R.solve_contact(dk, regular(5), method=m) for m in ("dual", "triples", "lp")]
    assert [bool(s.degenerate) for s in sols] == [False, False, False]


@FAST
@given(n=st.integers(3, 12), data=st.data())
def test_solvers_agree_on_irregular_azimuths(n, data):
    """Azimuths that are not equally spaced (and differ between positions) use the per-position path."""
    gaps = np.array(data.draw(st.lists(st.floats(0.2, 1.0), min_size=n, max_size=n)))
    th = np.cumsum(gaps / gaps.sum() * 2 * np.pi)
    if np.max(gaps / gaps.sum() * 2 * np.pi) >= np.pi - 1e-6:
        return  # a half-circle gap: rejected, tested separately
    dk = np.array(
        data.draw(st.lists(st.floats(-1.0, 1.0), min_size=2 * n, max_size=2 * n))
    ).reshape(2, n)
    angles = np.stack([th, th * 1.0001 + 0.3])  # two positions, different patterns
    if np.max(np.diff(np.sort(np.mod(angles[1], 2 * np.pi)))) >= np.pi - 1e-6:
        return
    a = R.solve_contact(dk * UM, angles)
    b = R.solve_contact(dk * UM, angles, method="triples")
    c = R.solve_contact(dk * UM, angles, method="lp")
    for name in ("constant", "sine", "cosine"):
        assert_allclose(um(getattr(a, name)), um(getattr(b, name)), atol=1e-6, err_msg=name)
    # the LP's eps-relaxed face (eps = 1e-9 um) is stretched by 1/sin of the angle between nearly
    # parallel constraints (here balls nearly opposite), so only a0 is compared with it
    assert_allclose(um(a.constant), um(c.constant), atol=1e-6)


def test_nearly_opposite_balls_are_solved_exactly():
    """Four balls, one pair 0.018 deg off diametral: the optimum is a vertex of nearly parallel lines. The
    dual and the triple enumeration find the same exact point; so does the LP once its face end points
    are polished onto their defining constraints (before, its relaxed face was 6e-6 um long)."""
    th = np.cumsum(np.full(4, np.pi / 2)) * 1.0001 + 0.3
    dk = np.array([0.0, 0.0, 0.0, -1.0])
    a = R.solve_contact(dk * UM, th)
    b = R.solve_contact(dk * UM, th, method="triples")
    c = R.solve_contact(dk * UM, th, method="lp")
    assert_allclose(
        um([a.constant, a.sine, a.cosine]), um([b.constant, b.sine, b.cosine]), atol=1e-12
    )
    assert np.all(um(a.slack[a.contact]) == pytest.approx(0.0, abs=1e-12)) and a.contact.sum() == 3
    assert not a.degenerate
    assert um(c.constant) == pytest.approx(um(a.constant), abs=1e-9)
    assert um(abs(c.sine - a.sine)) < 1e-9 and um(abs(c.cosine - a.cosine)) < 1e-9


@FAST
@given(case=cases)
@example(case=(6, 0.0, [0.0, 0.0, 0.0, 0.0, 2.0, 1.192092896e-07], False))
def test_solution_is_feasible_and_the_dual_certifies_it(case):
    """Slack >= 0, contacts at zero slack, and the load shares lambda are a dual certificate:
    lambda >= 0, sum 1, sum lambda (sin, cos) = 0, lambda > 0 only at contacts, sum lambda dk = a0."""
    n, first, dk, rounded = case
    dk = np.round(dk, 1) if rounded else np.asarray(dk)
    th = regular(n, first)
    s = R.solve_contact(dk * UM, th)
    assert np.all(um(s.slack) >= -1e-7)
    # a ball touches within the scaled contact tolerance (1.19e-7 um was seen at max |dk| = 2 um)
    assert np.all(np.abs(um(s.slack[s.contact])) <= contact_tol_um(dk))
    lam = s.load_share
    assert np.all(lam >= -1e-12)
    assert lam.sum() == pytest.approx(1.0, abs=1e-12)
    assert abs(np.dot(lam, np.sin(th))) < 1e-9 and abs(np.dot(lam, np.cos(th))) < 1e-9
    assert np.all(s.contact[lam > 1e-9])
    assert np.dot(lam, dk) == pytest.approx(um(s.constant), abs=1e-9)  # strong duality


@FAST
@given(case=cases, shift=st.floats(-5, 5), factor=st.floats(0.01, 100), turn=st.integers(0, 20))
# a face of optima 1e-8 um across: shorter than the contact tolerance, so it is reported as one point
@example(case=(6, 0.0, [0.0, 1e-08, 1.0, 1e-08, 0.0, 0.0], False), shift=0.0, factor=0.5, turn=0)
def test_invariances(case, shift, factor, turn):
    """Adding a constant to every dk shifts a0 only; scaling scales a0, B, D; relabelling the balls
    (starting the count at another ball) changes nothing.

    a0 is unique and compared to 1e-9 um. B and D are unique only up to the contact tolerance: a face of
    optima shorter than it counts as a single point (spec 003 section 7.6), and which of its points is
    reported may move by up to its length when the tolerance does not scale with the data (max |dk| < 1 um).
    """
    n, first, dk, _ = case
    dk = np.asarray(dk)
    th = regular(n, first)
    base = R.solve_contact(dk * UM, th)
    moved = R.solve_contact((dk + shift) * UM, th)
    assert um(moved.constant) == pytest.approx(um(base.constant) + shift, abs=1e-9)
    face_tol = max(contact_tol_um(dk), contact_tol_um(dk + shift))
    assert_allclose(um([moved.sine, moved.cosine]), um([base.sine, base.cosine]), atol=face_tol)
    scaled = R.solve_contact(dk * factor * UM, th)
    assert um(scaled.constant) == pytest.approx(factor * um(base.constant), abs=1e-9 * max(1.0, factor))
    assert_allclose(
        um([scaled.sine, scaled.cosine]),
        factor * um([base.sine, base.cosine]),
        atol=max(factor * contact_tol_um(dk), contact_tol_um(dk * factor)),
    )
    k = turn % n
    rolled = R.solve_contact(np.roll(dk, k) * UM, np.roll(th, k))
    assert_allclose(
        um([rolled.constant, rolled.sine, rolled.cosine]),
        um([base.constant, base.sine, base.cosine]),
        atol=1e-9,
    )
    assert np.array_equal(np.roll(base.contact, k), rolled.contact)


@FAST
@given(case=cases, delta=st.floats(0, 2 * np.pi))
def test_rotating_the_ball_set_rotates_the_sinusoid(case, delta):
    n, first, dk, _ = case
    th = regular(n, first)
    a = R.solve_contact(np.asarray(dk) * UM, th)
    b = R.solve_contact(np.asarray(dk) * UM, th + delta)
    # s(theta) = a0 + A sin(theta + phi): the same curve at theta + delta means phi -> phi - delta
    assert um(b.constant) == pytest.approx(um(a.constant), abs=1e-9)
    assert um(b.amplitude) == pytest.approx(um(a.amplitude), abs=1e-7)
    if not a.degenerate and a.amplitude > 1e-8 * UM:
        assert math.remainder(float(b.phase - (a.phase - delta)), 2 * math.pi) == pytest.approx(
            0.0, abs=1e-6
        )


def test_equal_errors_every_ball_touches():
    """Section 16.3."""
    for n in (3, 4, 7, 16):
        s = R.solve_contact(np.full(n, 0.37) * UM, regular(n, 0.1))
        assert um(s.constant) == pytest.approx(0.37, abs=1e-12)
        assert um(s.sine) == pytest.approx(0, abs=1e-12) and um(s.cosine) == pytest.approx(
            0, abs=1e-12
        )
        assert np.all(s.contact)
        assert not s.degenerate


def test_four_balls_always_rest_on_a_pair():
    """With n = 4 no triangle strictly contains the centre: the optimum is a diametral pair and, unless
    both pairs tie, the face is a segment."""
    s = R.solve_contact(np.array([0.0, 1.0, 0.5, 2.0]) * UM, regular(4))
    assert list(np.flatnonzero(s.contact)) == [0, 2]
    assert s.degenerate
    tie = R.solve_contact(np.array([0.0, 1.0, 2.0, 1.0]) * UM, regular(4))
    assert not tie.degenerate and np.all(tie.contact)


@pytest.mark.parametrize(
    "angles, match",
    [
        (np.array([0.0]), "n_balls must be >= 3"),
        (np.array([0.0, np.pi]), "n_balls must be >= 3"),
        (np.radians([0, 30, 60, 90, 120]), "half-circle"),  # five balls within 120 deg
        (np.radians([0, 90, 180]), "half-circle"),  # a closed half-circle is unbounded too
        (np.radians([0, 0, 120, 240]), "same azimuth"),
    ],
)
def test_unbounded_configurations_are_rejected(angles, match):
    """Section 16.4."""
    with pytest.raises(InputError, match=match):
        R.solve_contact(np.zeros(angles.size), angles)


def test_bad_inputs_of_the_contact_solver():
    th = regular(5)
    with pytest.raises(InputError, match="method must be one of"):
        R.solve_contact(np.zeros(5), th, method="simplex")
    with pytest.raises(InputError, match="tie_break must be one of"):
        R.solve_contact(np.zeros(5), th, tie_break="left")
    with pytest.raises(InputError, match="generalized_error must be finite"):
        R.solve_contact(np.r_[np.nan, np.zeros(4)], th)
    with pytest.raises(InputError, match="only available with method='dual'"):
        R.solve_contact(np.zeros(5), th, method="lp", tie_break="midpoint")


def test_sign_of_the_envelope():
    """Section 16.7: the source's literal rule, "minimise a0 with the sinusoid above the points", applied
    to the clearance-signed dk of example 1, leaves the ring in place and the 2 um oversize ball
    penetrates by 2 um. The library's rule keeps every ball out of the rings and moves the ring."""
    th = regular(16)
    dk = np.r_[-2.0, np.zeros(15)]
    rows = np.column_stack([np.ones(16), np.sin(th), np.cos(th)])
    literal = linprog(
        [1.0, 0.0, 0.0], A_ub=-rows, b_ub=-dk, bounds=[(None, None)] * 3, method="highs"
    )
    s_literal = rows @ literal.x
    assert literal.x[0] == pytest.approx(0.0, abs=1e-9)
    assert np.min(dk - s_literal) == pytest.approx(-2.0, abs=1e-9)  # penetration 2 um
    s = R.solve_contact(dk * UM, th)
    assert um(s.constant) == pytest.approx(-1.0, abs=1e-12)
    assert np.min(um(s.slack)) >= -1e-12
    # and with the interference-signed form of section 6 (E = -dk, minimise u0 above E) both agree
    upper = linprog([1.0, 0.0, 0.0], A_ub=-rows, b_ub=dk, bounds=[(None, None)] * 3, method="highs")
    assert -upper.x[0] == pytest.approx(um(s.constant), abs=1e-9)


def test_a_position_gives_the_same_bits_alone_or_in_a_batch(g):
    e = R.manufacturing_errors(
        16,
        ball_diameter_deviation=np.linspace(-0.2, 0.2, 16) * UM,
        inner=R.RacewayErrors(radial=R.fourier_series({1: 0.4, 3: 0.1}, scale=UM)),
    )
    psi = np.linspace(0, 4 * np.pi, 500)
    batch = R.initial_displacement(psi, g, e)
    one = R.initial_displacement(psi[123], g, e)
    for name in ("x", "y", "z"):
        assert getattr(one, name) == getattr(batch, name)[123]


# ------------------------------------------------------------------------------ reduced bearing (5.1), (5.2)
poses = st.tuples(*(st.floats(-5, 5) for _ in range(3)))


@FAST
@given(pose=poses, tilt=st.tuples(st.floats(-50, 50), st.floats(-50, 50)), with_tilt=st.booleans())
def test_pose_round_trip(g, pose, tilt, with_tilt):
    """Section 16.5: pose -> sinusoid -> pose, with and without tilt."""
    a, b = (np.array(tilt) * UM) if with_tilt else (0.0, 0.0)
    p = np.array(pose) * UM
    s = R.sinusoid_from_pose(*p, g, tilt_x=a, tilt_y=b)
    back = R.pose_from_sinusoid(*s, g, tilt_x=a, tilt_y=b)
    assert_allclose(um(back), um(p), atol=1e-12)


@FAST
@given(pose=poses, tilt=st.tuples(st.floats(-50, 50), st.floats(-50, 50)))
def test_tie_break_centre_minimises_the_lateral_displacement(g, pose, tilt):
    """(B, D) = c gives dx = dy = 0: c is the point of the (B, D) plane with no lateral displacement."""
    a, b = np.array(tilt) * UM
    cb, cd = R.tie_break_centre(g, tilt_x=a, tilt_y=b)
    p = R.pose_from_sinusoid(pose[2] * UM, cb, cd, g, tilt_x=a, tilt_y=b)
    assert abs(um(p.x)) < 1e-12 and abs(um(p.y)) < 1e-12


@FAST
@given(
    pose=poses,
    tilt=st.tuples(st.floats(-50, 50), st.floats(-50, 50)),
    theta=st.lists(st.floats(0, 2 * np.pi), min_size=1, max_size=8),
)
def test_refinement_angle_equals_source_eq30(g, pose, tilt, theta):
    """Section 16.6: (9.1) equals the source's eq. 30 with 2 Delta r33 = s(theta), to 1e-15 rad."""
    x, y, z = np.array(pose) * UM
    a, b = np.array(tilt) * UM
    th = np.array(theta)
    shifts = R.contact_point_shifts(x, y, z, th, g, tilt_x=a, tilt_y=b)
    s = R.sinusoid_from_pose(x, y, z, g, tilt_x=a, tilt_y=b)
    s_theta = s.constant + s.sine * np.sin(th) + s.cosine * np.cos(th)
    m = a * np.sin(th) - b * np.cos(th)
    tau0, rc = g.contact_angle, g.inner_centre_radius
    eq30 = (z - s_theta * math.sin(tau0) + rc * m) / (
        (g.outer_groove_radius + g.inner_groove_radius - 2 * g.ball_radius) * math.cos(tau0)
    )
    assert_allclose(shifts.outer_angle_shift, eq30, rtol=0, atol=1e-15)
    assert_allclose(shifts.inner_angle_shift, eq30 - m, rtol=0, atol=1e-15)  # eq. 29


# ------------------------------------------------------------------------------ errors and their signs
def test_sign_conventions_of_the_generalized_error(g):
    """Clearance-positive: material missing (a bigger outer raceway, a smaller inner raceway, a bigger
    groove radius, an undersize ball) makes dk positive."""
    one = R.fourier_series({0: 1.0}, scale=UM)
    cases = {
        "outer radial +": (R.manufacturing_errors(16, outer=R.RacewayErrors(radial=one)), +1),
        "inner radial +": (R.manufacturing_errors(16, inner=R.RacewayErrors(radial=one)), -1),
        "outer groove +": (R.manufacturing_errors(16, outer=R.RacewayErrors(groove=one)), +1),
        "inner groove +": (R.manufacturing_errors(16, inner=R.RacewayErrors(groove=one)), +1),
        "outer axial +": (R.manufacturing_errors(16, outer=R.RacewayErrors(axial=one)), +1),
        "inner axial +": (R.manufacturing_errors(16, inner=R.RacewayErrors(axial=one)), -1),
        "ball oversize": (R.manufacturing_errors(16, ball_diameter_deviation=np.full(16, UM)), -1),
    }
    for name, (e, sign) in cases.items():
        dk = R.generalized_error(0.3, g, e)
        assert np.all(np.sign(dk) == sign), name
    # a uniformly undersize set of balls (2 um) lets the ring advance by 2 um / sin(tau0) along +Z1
    e = R.manufacturing_errors(16, ball_diameter_deviation=np.full(16, -2 * UM))
    d = R.initial_displacement(0.0, g, e)
    assert um(d.z) == pytest.approx(2 / math.sin(g.contact_angle), rel=1e-12)


def test_first_approximation_equals_the_refined_formula_with_zero_shifts(g):
    e = R.manufacturing_errors(
        16,
        outer=R.RacewayErrors(
            radial=R.fourier_series({2: 0.3}, {3: 0.1}, scale=UM),
            axial=R.fourier_series({1: 0.2}, scale=UM),
            groove=R.fourier_series({0: 0.05}, scale=UM),
        ),
        inner=R.RacewayErrors(
            radial=R.fourier_series({1: 0.4}, scale=UM),
            axial=R.fourier_series({}, {1: 0.3}, scale=UM),
            normal=R.fourier_series({4: 0.02}, scale=UM),
        ),
    )
    zero = np.zeros((5, 16))
    psi = np.linspace(0, 2, 5)
    a = R.generalized_error(psi, g, e)
    b = R.generalized_error(psi, g, e, shifts=R.Shifts(zero, zero, zero))
    assert_allclose(a, b, atol=1e-20)


def test_inner_ring_errors_turn_with_the_ring(g):
    """After one inner-ring revolution the inner error pattern returns, the balls have moved on by kappa."""
    e = R.manufacturing_errors(
        16, inner=R.RacewayErrors(radial=R.fourier_series({3: 1.0}, scale=UM))
    )
    th = R.ball_angles(2 * np.pi, g)
    dk = R.generalized_error(2 * np.pi, g, e)
    assert_allclose(um(dk), -math.cos(g.contact_angle) * np.cos(3 * (th - 2 * np.pi)), atol=1e-12)


def test_roundness_profile_fit(g):
    rng = np.random.default_rng(3)
    th = np.sort(rng.uniform(0, 2 * np.pi, 50))  # uneven spacing
    true = R.fourier_series({0: 0.1, 1: 0.5, 4: -0.2}, {2: 0.3, 4: 0.05})
    dev = R.evaluate_series(true, th)
    fit = R.roundness_coefficients(th, dev, 6)
    assert_allclose(fit.cos, np.r_[true.cos, 0, 0], atol=1e-12)
    assert_allclose(fit.sin, np.r_[true.sin, 0, 0], atol=1e-12)
    with pytest.raises(InputError, match="max_order must be <="):
        R.roundness_coefficients(th[:7], dev[:7], 4)
    with pytest.raises(InputError, match="one value per angle"):
        R.roundness_coefficients(th, dev[:-1], 3)


def test_fourier_series_input_checks():
    assert_allclose(R.fourier_series({"2": 1.0}).cos, [0, 0, 1])
    with pytest.raises(InputError, match="whole number >= 0"):
        R.fourier_series({-1: 1.0})
    with pytest.raises(InputError, match="whole number >= 0"):
        R.fourier_series({"1.5": 1.0})
    with pytest.raises(InputError, match="must be finite"):
        R.fourier_series({1: float("inf")})


def test_manufacturing_errors_checks():
    with pytest.raises(InputError, match="one value per ball"):
        R.manufacturing_errors(16, ball_diameter_deviation=np.zeros(15))
    with pytest.raises(InputError, match="not both"):
        R.manufacturing_errors(
            3, ball_diameter_deviation=np.zeros(3), ball_outer_deficit=np.zeros(3)
        )
    with pytest.raises(InputError, match="tilt_x must be finite"):
        R.manufacturing_errors(3, tilt_x=float("nan"))
    with pytest.raises(InputError, match="RacewayErrors"):
        R.manufacturing_errors(3, inner={"radial": 1})


def test_tilt_as_a_function_of_rotation(g):
    """A tilt given as a Fourier series in psi, or as a callable, enters the pose through (5.2)."""
    series = R.fourier_series({0: 5.0, 1: 10.0}, scale=UM)
    e1 = R.manufacturing_errors(16, tilt_x=series)
    e2 = R.manufacturing_errors(16, tilt_x=lambda psi: (5.0 + 10.0 * np.cos(psi)) * UM)
    psi = np.linspace(0, 2 * np.pi, 9)
    a = R.initial_displacement(psi, g, e1)
    b = R.initial_displacement(psi, g, e2)
    k = g.inner_centre_radius * math.tan(g.contact_angle)
    assert_allclose(a.y, -(5.0 + 10.0 * np.cos(psi)) * UM * k, rtol=1e-12)
    assert_allclose(a.y, b.y, rtol=1e-14)
    assert_allclose(a.tilt_x, (5.0 + 10.0 * np.cos(psi)) * UM, rtol=1e-14)


# ------------------------------------------------------------------------------ geometry
def test_geometry_forms_and_checks(g):
    h = R.geometry_from_catalog(
        16, 7.144e-3, 54e-3, 0.53, 0.52, outer_bottom_radius=g.outer_bottom_radius
    )
    assert h.contact_angle == pytest.approx(g.contact_angle, abs=1e-12)
    with pytest.raises(InputError, match="inconsistent with contact_angle"):
        R.geometry_from_radii(
            16,
            g.ball_radius,
            g.outer_groove_radius,
            g.inner_groove_radius,
            g.inner_bottom_radius,
            g.contact_angle,
            outer_bottom_radius=g.outer_bottom_radius + 1e-6,
        )
    with pytest.raises(InputError, match="n_balls must be an integer >= 3"):
        R.geometry_from_catalog(2, 7.144e-3, 54e-3, 0.53, 0.52, 0.26)
    with pytest.raises(InputError, match="outer_conformity must be > 0.5"):
        R.geometry_from_catalog(16, 7.144e-3, 54e-3, 0.5, 0.52, 0.26)
    with pytest.raises(InputError, match="inner_groove_radius must be > ball_radius"):
        R.geometry_from_radii(16, 3.572e-3, 3.8e-3, 3.5e-3, 23.4e-3, 0.26)
    with pytest.raises(InputError, match=r"contact_angle must be in \(0, 90\)"):
        R.geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, 0.0)
    with pytest.raises(InputError, match=r"contact_angle must be in \(0, 90\)"):
        R.geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(95))
    with pytest.raises(InputError, match="pitch_diameter must be > ball_diameter"):
        R.geometry_from_catalog(16, 7.144e-3, 5e-3, 0.53, 0.52, 0.26)
    with pytest.raises(InputError, match="give contact_angle"):
        R.geometry_from_radii(
            16, g.ball_radius, g.outer_groove_radius, g.inner_groove_radius, g.inner_bottom_radius
        )


def test_geometry_from_a_catalog_bearing():
    from bearinglab import catalog

    b = catalog.get("B218")
    h = R.geometry_from_bearing(b, first_ball_angle=0.1)
    assert h.n_balls == 16 and h.first_ball_angle == 0.1
    assert 2 * h.ball_centre_radius == pytest.approx(b.pitch_diameter, rel=1e-14)
    with pytest.raises(InputError, match="n_balls of '1000095' is not known"):
        R.geometry_from_bearing(catalog.get("1000095"))


# ------------------------------------------------------------------------------ refinement
def test_refinement_converges_and_reports(g):
    e = R.manufacturing_errors(
        16,
        inner=R.RacewayErrors(
            radial=R.fourier_series({2: 1.0}, scale=UM), groove=R.fourier_series({3: 0.5}, scale=UM)
        ),
    )
    d = R.initial_displacement(np.linspace(0, 1, 7), g, e, refine=True)
    assert np.all(d.converged) and np.all(d.passes >= 2)
    with pytest.raises(
        ConvergenceError, match=r"no convergence after 1 iterations \(\|residual\| = 9.91e-09\)"
    ):
        R.initial_displacement(0.0, g, e, refine=True, max_iter=1)
    flagged = R.initial_displacement(0.0, g, e, refine=True, max_iter=1, raise_on_failure=False)
    assert not flagged.converged and flagged.passes == 1
    assert flagged.last_change == pytest.approx(
        abs(flagged.z - flagged.first_approximation.z), rel=1e-9, abs=0
    )


def test_refinement_is_a_second_order_correction(g):
    """The refined pose differs from the first approximation by O(error^2): halving all errors quarters
    the correction."""

    def correction(scale):
        e = R.manufacturing_errors(
            16, inner=R.RacewayErrors(radial=R.fourier_series({2: scale}, scale=UM))
        )
        d = R.initial_displacement(0.0, g, e, refine=True)
        return d.z - d.first_approximation.z

    assert correction(0.5) / correction(1.0) == pytest.approx(0.25, rel=0.01)


# ------------------------------------------------------------------------------ rotation and metrics
def test_metrics_against_brute_force():
    rng = np.random.default_rng(7)
    x, y, z = rng.normal(size=(3, 3, 200))
    m = R.runout_metrics(x, y, z)
    for k in range(3):
        d = np.hypot(x[k][:, None] - x[k][None, :], y[k][:, None] - y[k][None, :]).max()
        assert m.radial_ptp_max[k] == pytest.approx(d, rel=1e-14)
        assert m.radial_ptp_max[k] >= max(m.radial_ptp_x[k], m.radial_ptp_y[k])
        # the largest peak-to-peak over directions equals the diameter: check against 3600 directions
        phi = np.linspace(0, np.pi, 3600, endpoint=False)
        proj = np.outer(np.cos(phi), x[k]) + np.outer(np.sin(phi), y[k])
        assert np.ptp(proj, axis=1).max() == pytest.approx(d, rel=1e-6)


def test_synchronous_and_asynchronous_parts(g):
    e = R.manufacturing_errors(
        16,
        ball_diameter_deviation=np.r_[1.0, np.zeros(15)] * UM,
        inner=R.RacewayErrors(radial=R.fourier_series({1: 0.5}, scale=UM)),
    )
    t = R.rotation_sequence(g, e, revolutions=4, steps_per_revolution=90)
    x = t.displacement.x
    sync = R.synchronous_part(x, 90)
    assert_allclose(sync[:90], sync[90:180])
    assert_allclose((x - sync).reshape(4, 90).mean(axis=0), 0.0, atol=1e-20)
    assert t.asynchronous.dz_mean == pytest.approx(0.0, abs=1e-20)
    with pytest.raises(InputError, match="whole revolutions"):
        R.synchronous_part(x[:-1], 90)


def test_spectrum_of_known_motion():
    psi = 2 * np.pi * np.arange(20 * 64) / 64  # 20 revolutions: resolution 1/20 order
    x = 0.5 * np.cos(psi) + 0.2 * np.cos(2 * psi)
    y = 0.5 * np.sin(psi) - 0.2 * np.sin(2 * psi)  # forward at 1x, backward at 2x
    z = 0.1 * np.cos(psi * 0.45)  # 0.45 = 9/20, on the grid
    sp = R.runout_spectrum(x, y, z, 64)
    assert sp.order[20] == 1.0
    assert sp.radial_forward[20] == pytest.approx(0.5, abs=1e-12)
    assert sp.radial_backward[40] == pytest.approx(0.2, abs=1e-12)
    assert sp.radial_x[40] == pytest.approx(0.2, abs=1e-12)
    assert sp.axial[9] == pytest.approx(0.1, abs=1e-12)
    lines = R.spectrum_lines(sp, 0.45)
    got = {(ln.component, ln.label, ln.source) for ln in lines}
    assert got == {
        ("radial forward", "1×", "ring"),
        ("radial backward", "2×", "ring"),
        ("axial", "κ", "cage"),
    }


def test_cage_override_changes_the_ball_motion(g):
    e = R.manufacturing_errors(16, ball_diameter_deviation=np.r_[2.0, np.zeros(15)] * UM)
    t = R.rotation_sequence(g, e, revolutions=1, steps_per_revolution=8, cage_ratio=0.5)
    assert_allclose(t.displacement.ball_angle[:, 0], 0.5 * t.rotation_angle)
    # ball 1 drives the ring away from itself: the centre sits opposite ball 1
    ang = np.arctan2(t.displacement.y, t.displacement.x)
    assert_allclose(np.cos(ang - (t.displacement.ball_angle[:, 0] + np.pi)), 1.0, atol=1e-9)


# ------------------------------------------------------------------------------ exact geometry
def test_exact_reduction_properties(g):
    th = R.ball_angles(0.0, g)
    assert np.max(np.abs(um(R.exact_reduction(th, 0.0, 0.0, 0.0, g)))) < 1e-9
    # a lateral shift is seen as a cos(theta) pattern of period 2 pi: balls opposite see opposite signs
    s = R.exact_reduction(np.array([0.0, np.pi]), 0.3 * UM, 0.0, 0.0, g)
    assert s[0] > 0 > s[1]
    with pytest.raises(ConvergenceError):
        R.exact_reduction(th, 0.8 * UM, -0.5 * UM, 2 * UM, g, max_iter=1)


# ------------------------------------------------------------------------------ Monte Carlo
def test_tolerance_classes_have_sources():
    grades, classes = R.tolerance_classes()
    assert list(grades) == ["G3", "G5", "G10", "G16", "G20", "G24", "G28", "G40"]
    assert all("ISO 3290" in v.source for v in grades.values())
    assert all("ISO 492" in v.source and "assumed" in v.source for v in classes.values())
    # V_DWS < V_DWL and both grow with the grade number
    s = [v.single_diameter_variation for v in grades.values()]
    lot = [v.lot_diameter_variation for v in grades.values()]
    assert (
        np.all(np.diff(s) > 0) and np.all(np.diff(lot) > 0) and all(a < b for a, b in zip(s, lot))
    )
    with pytest.raises(InputError, match=r"ball_grade must be one of \['G3'"):
        R.ball_grade("G7")
    with pytest.raises(InputError, match=r"ring_class must be one of \['P5'"):
        R.ring_class("P0")


def test_monte_carlo_is_reproducible_and_independent_of_chunking(g):
    a = R.monte_carlo(g, "G5", "P4", 12, 99, steps_per_revolution=36, chunk_size=5)
    b = R.monte_carlo(g, "G5", "P4", 12, 99, steps_per_revolution=36, chunk_size=12)
    c = R.monte_carlo(
        g, "G5", "P4", 12, np.random.SeedSequence(99), steps_per_revolution=36, chunk_size=7
    )
    for name in R.METRICS:
        assert np.array_equal(getattr(a.samples, name), getattr(b.samples, name)), name
        assert np.array_equal(getattr(a.samples, name), getattr(c.samples, name)), name
    d = R.monte_carlo(g, "G5", "P4", 12, 100, steps_per_revolution=36)
    assert not np.array_equal(a.samples.axial_ptp, d.samples.axial_ptp)
    calls = []
    R.monte_carlo(
        g,
        "G5",
        "P4",
        10,
        1,
        steps_per_revolution=12,
        chunk_size=4,
        progress=lambda k, n: calls.append((k, n)),
    )
    assert calls == [(4, 10), (8, 10), (10, 10)]


def test_monte_carlo_sample_equals_the_public_path(g):
    """A sample's metrics equal a rotation_sequence of the same errors built with the public API."""
    from bearinglab.runout import _draw_count, _sampled_errors, _uniforms

    res = R.monte_carlo_chunk(g, "G10", "P5", [3], 5, steps_per_revolution=60, revolutions=2)
    u = _uniforms(5, [3], _draw_count(16, 15))
    theta1, dd, ser = _sampled_errors(u, 16, R.ball_grade("G10"), R.ring_class("P5"), 15)
    one = {k: R.FourierSeries(v.cos[0], v.sin[0]) for k, v in ser.items()}
    e = R.manufacturing_errors(
        16,
        ball_diameter_deviation=dd[0],
        inner=R.RacewayErrors(radial=one["inner"], axial=one["wobble"]),
        outer=R.RacewayErrors(radial=one["outer"]),
    )
    t = R.rotation_sequence(
        g._replace(first_ball_angle=theta1[0]), e, revolutions=2, steps_per_revolution=60
    )
    for name in R.METRICS:
        assert getattr(res, name)[0] == pytest.approx(
            getattr(t.metrics, name), rel=1e-12, abs=1e-20
        ), name


def test_monte_carlo_draws_follow_the_tolerance_classes():
    """Ball deviations within (V_DWL + V_DWS)/2, order-1 amplitudes within K_ia/2 and S_ia/2, and the
    waviness RMS close to w_rms on average."""
    from bearinglab.runout import _draw_count, _sampled_errors, _uniforms

    grade, rings = R.ball_grade("G10"), R.ring_class("P5")
    u = _uniforms(11, np.arange(400), _draw_count(16, 15))
    theta1, dd, ser = _sampled_errors(u, 16, grade, rings, 15)
    assert np.all(
        np.abs(dd) <= (grade.lot_diameter_variation + grade.single_diameter_variation) / 2
    )
    assert np.all((theta1 >= 0) & (theta1 < 2 * np.pi))
    a1 = np.hypot(ser["inner"].cos[:, 1], ser["inner"].sin[:, 1])
    assert np.all(a1 <= rings.radial_runout / 2) and a1.mean() == pytest.approx(
        rings.radial_runout / 4, rel=0.1
    )
    s1 = np.hypot(ser["wobble"].cos[:, 1], ser["wobble"].sin[:, 1])
    assert np.all(s1 <= rings.axial_runout / 2)
    for key in ("inner", "outer"):
        ms = 0.5 * (ser[key].cos[:, 2:] ** 2 + ser[key].sin[:, 2:] ** 2).sum(
            axis=1
        )  # mean square of orders 2..15
        assert math.sqrt(ms.mean()) == pytest.approx(rings.waviness_rms, rel=0.05)
    assert np.all(ser["outer"].cos[:, :2] == 0)  # outer order 1 only shifts the centre: not drawn


def test_summarize_checks():
    s = R.summarize(np.arange(101.0))
    assert s.median == 50 and s.p95 == 95 and s.max == 100
    with pytest.raises(InputError, match="at least 2 samples"):
        R.summarize([1.0])


# ------------------------------------------------------------------------------ error files
def _write(tmp_path, text, name="e.toml"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


GEOM = """
[geometry]
balls = 16
ball_diameter = "7.144 mm"
pitch_diameter = "54 mm"
outer_conformity = 0.53
inner_conformity = 0.52
contact_angle = "15 deg"
"""


def test_error_file_all_features(tmp_path, g):
    (tmp_path / "prof.csv").write_text(
        "# angle deg, deviation um\n"
        + "\n".join(f"{a}, {0.2 * math.cos(math.radians(2 * a))}" for a in range(0, 360, 15)),
        encoding="utf-8",
    )
    p = _write(
        tmp_path,
        GEOM
        + """
first_ball_angle = "10 deg"
[errors.inner.radial]
profile = "prof.csv"
max_order = 4
[errors.inner.axial]
sin = { 1 = "0.3 um" }
[errors.outer.groove]
cos = { 0 = 50 }
unit = "nm"
[errors.outer.normal]
angle = [0, 90, 180, 270]
deviation = [0.1, 0, -0.1, 0]
max_order = 1
[errors.balls]
outer_deficit = [0.1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0]
inner_deficit = [0, 0.2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0]
[tilt]
alpha = 5
beta = "-0.01 mrad"
""",
    )
    geom, e = R.load_error_file(p)
    assert geom.first_ball_angle == pytest.approx(math.radians(10))
    assert_allclose(e.inner.radial.cos, [0, 0, 0.2e-6, 0, 0], atol=1e-18)
    assert e.inner.axial.sin[1] == pytest.approx(0.3e-6)
    assert e.outer.groove.cos[0] == pytest.approx(50e-9)
    assert_allclose(e.outer.normal.cos, [0, 0.1e-6], atol=1e-18)
    assert e.ball_outer_deficit[0] == pytest.approx(0.1e-6) and e.ball_inner_deficit[
        1
    ] == pytest.approx(0.2e-6)
    assert e.tilt_x == pytest.approx(5e-6) and e.tilt_y == pytest.approx(-10e-6)
    # a given geometry overrides the file's
    g2, _ = R.load_error_file(p, g)
    assert g2 is g


@pytest.mark.parametrize(
    "text, match",
    [
        ("[geometry]\nballs = 16\n", "ball_diameter"),
        (
            GEOM + "[errors.inner.radial]\ncos = { 1 = 0.5 }\nfoo = 1\n",
            r"\[errors.inner.radial\], key 'foo': unknown key",
        ),
        (GEOM + "[errors.balls]\ndiameter = [0.1, 0.2]\n", "16 balls, got 2 values"),
        (
            GEOM + "[errors.inner.radial]\ncos = { 1 = 0.5 }\nprofile = 'x.csv'\nmax_order = 2\n",
            "not both",
        ),
        (GEOM + "[errors.inner.radial]\nprofile = 'missing.csv'\nmax_order = 2\n", "no such file"),
        (GEOM + "[errors.inner.radial]\nprofile = 'missing.csv'\n", "max_order"),
        (GEOM + "[errors.inner.radial]\ncos = { 1 = '2 kg' }\n", "is a mass, expected a length"),
        (GEOM + "[errors.inner.radial]\nsin = { 0 = 1 }\n", "sin has no order 0"),
        (GEOM + "[errors.inner.wobble]\ncos = { 1 = 1 }\n", "unknown key"),
        (GEOM + "[tilt]\nalpha = '3 mm'\n", "expected an angle"),
        (GEOM + "[errors.balls]\ndiameter = [0.1]\nouter_deficit = [0.1]\n", "not both"),
        (
            GEOM.replace(
                'pitch_diameter = "54 mm"',
                'inner_bottom_radius = "23.4 mm"\npitch_diameter = "54 mm"',
            ),
            "exactly one",
        ),
        (GEOM.replace("0.53", "0.49"), "outer_conformity must be > 0.5"),
        ("title = 'x'\n", "no \\[geometry\\] table"),
        ("[geometry\n", "not valid TOML"),
    ],
)
def test_error_file_problems_name_the_place(tmp_path, text, match):
    p = _write(tmp_path, text)
    with pytest.raises(CatalogError, match=match):
        R.load_error_file(p)


def test_error_file_is_not_modified(tmp_path):
    p = _write(
        tmp_path,
        GEOM + "[errors.balls]\ndiameter = [2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0]\n",
    )
    before = p.read_bytes(), p.stat().st_mtime_ns
    R.load_error_file(p)
    assert (p.read_bytes(), p.stat().st_mtime_ns) == before


def test_missing_error_file():
    with pytest.raises(CatalogError, match="no such file"):
        R.load_error_file("/nonexistent/errors.toml")


def test_benchmark_functions_agree_on_a_small_input(load_bench):
    """Smoke test of bench/runout.py (the benchmark itself is not run in the tests)."""
    bench = load_bench("runout")
    dk, theta = bench.cases(40)
    sol = bench.solve_batch(dk, theta)
    a0 = bench.solve_one_by_one(dk[:8], theta[:8])
    assert_allclose(um(sol.constant[:8]), um(a0), atol=1e-6)


def test_monte_carlo_seed_checks(g):
    for bad in (-1, 1.5, "7", True):
        with pytest.raises(InputError, match="seed must be a whole number >= 0"):
            R.monte_carlo(g, "G5", "P4", 4, bad, steps_per_revolution=12)
    r = R.monte_carlo(g, "G5", "P4", 4, np.int64(5), steps_per_revolution=12)
    assert r.seed == 5


def test_shipped_measured_profile_example():
    """The profile example: catalog geometry, a CSV roundness profile, inline samples, contact deficits and a
    tilt varying with rotation."""
    from pathlib import Path

    path = Path(__file__).parent.parent / "examples" / "runout" / "measured_profile.toml"
    geom, e = R.load_error_file(path)
    assert geom.n_balls == 16 and geom.contact_angle == pytest.approx(math.radians(40))
    assert geom.first_ball_angle == pytest.approx(math.radians(5))
    assert e.inner.radial.cos.size == 9 and e.outer.radial.cos.size == 4
    assert isinstance(e.tilt_x, R.FourierSeries) and isinstance(e.tilt_y, R.FourierSeries)
    t = R.rotation_sequence(geom, e, revolutions=2, steps_per_revolution=90, refine=True)
    assert np.all(t.displacement.converged)
    assert 0 < t.metrics.radial_ptp_max < 5 * UM
