"""Properties of the one-position runout model (spec 003 sections 4-9, ``runout.contact``): the contact
problem and its solvers, the reduced bearing, the generalized error and its signs, the refinement.

Published cases are in ``tests/validation/test_runout_examples.py``.
"""

import importlib.util
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose
from scipy.optimize import linprog

from bearinglab import runout as R
from bearinglab._solve import RUNOUT_CONTACT_TOL_UM
from bearinglab.errors import ConvergenceError, InputError

UM = 1e-6
# the dual method on both engines (the compiled one where numba is installed)
ENGINES = ["numpy", pytest.param("compiled", marks=pytest.mark.skipif(
    importlib.util.find_spec("numba") is None, reason="numba is not installed"))]
FAST = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])


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


@pytest.mark.parametrize("engine", ENGINES)
@FAST
@given(case=cases)
# a face 0.002 um long seen from a tie-break centre 1 um away: the LP's tolerance once came out x1e6
@example(case=(4, 0.0, [-1.056640625, 0.0, 1.0546875, 0.0], False))
# a face 1e-231 um long: its squared length underflowed to 0 in the LP's tie-break projection (nan)
@example(case=(3, 0.0, [0.0, 0.0, 3.5751661739973926e-231], False))
def test_solvers_agree_on_random_cases(case, engine):
    """Section 16.2: LP, triple enumeration and the dual agree within 1e-6 um (some inputs rounded to
    0.1 um to create ties)."""
    n, first, dk, rounded = case
    dk = np.round(dk, 1) if rounded else np.asarray(dk)
    th = regular(n, first)
    sols = [R.solve_contact(dk * UM, th, engine=engine)]
    sols += [R.solve_contact(dk * UM, th, method=m) for m in ("triples", "lp")]
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


@pytest.mark.parametrize("engine", ENGINES)
@FAST
@given(n=st.integers(3, 12), data=st.data())
def test_solvers_agree_on_irregular_azimuths(n, data, engine):
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
    a = R.solve_contact(dk * UM, angles, engine=engine)
    b = R.solve_contact(dk * UM, angles, method="triples")
    c = R.solve_contact(dk * UM, angles, method="lp")
    for name in ("constant", "sine", "cosine"):
        assert_allclose(um(getattr(a, name)), um(getattr(b, name)), atol=1e-6, err_msg=name)
    # the LP's eps-relaxed face (eps = 1e-9 um) is stretched by 1/sin of the angle between nearly
    # parallel constraints (here balls nearly opposite), so only a0 is compared with it
    assert_allclose(um(a.constant), um(c.constant), atol=1e-6)


@pytest.mark.parametrize("engine", ENGINES)
def test_nearly_opposite_balls_are_solved_exactly(engine):
    """Four balls, one pair 0.018 deg off diametral: the optimum is a vertex of nearly parallel lines. The
    dual and the triple enumeration find the same exact point; so does the LP once its face end points
    are polished onto their defining constraints (before, its relaxed face was 6e-6 um long)."""
    th = np.cumsum(np.full(4, np.pi / 2)) * 1.0001 + 0.3
    dk = np.array([0.0, 0.0, 0.0, -1.0])
    a = R.solve_contact(dk * UM, th, engine=engine)
    b = R.solve_contact(dk * UM, th, method="triples")
    c = R.solve_contact(dk * UM, th, method="lp")
    assert_allclose(
        um([a.constant, a.sine, a.cosine]), um([b.constant, b.sine, b.cosine]), atol=1e-12
    )
    assert np.all(um(a.slack[a.contact]) == pytest.approx(0.0, abs=1e-12)) and a.contact.sum() == 3
    assert not a.degenerate
    assert um(c.constant) == pytest.approx(um(a.constant), abs=1e-9)
    assert um(abs(c.sine - a.sine)) < 1e-9 and um(abs(c.cosine - a.cosine)) < 1e-9


@pytest.mark.parametrize("engine", ENGINES)
@FAST
@given(case=cases)
@example(case=(6, 0.0, [0.0, 0.0, 0.0, 0.0, 2.0, 1.192092896e-07], False))
def test_solution_is_feasible_and_the_dual_certifies_it(case, engine):
    """Slack >= 0, contacts at zero slack, and the load shares lambda are a dual certificate:
    lambda >= 0, sum 1, sum lambda (sin, cos) = 0, lambda > 0 only at contacts, sum lambda dk = a0."""
    n, first, dk, rounded = case
    dk = np.round(dk, 1) if rounded else np.asarray(dk)
    th = regular(n, first)
    s = R.solve_contact(dk * UM, th, engine=engine)
    assert np.all(um(s.slack) >= -1e-7)
    # a ball touches within the scaled contact tolerance (1.19e-7 um was seen at max |dk| = 2 um)
    assert np.all(np.abs(um(s.slack[s.contact])) <= contact_tol_um(dk))
    lam = s.load_share
    assert np.all(lam >= -1e-12)
    assert lam.sum() == pytest.approx(1.0, abs=1e-12)
    assert abs(np.dot(lam, np.sin(th))) < 1e-9 and abs(np.dot(lam, np.cos(th))) < 1e-9
    assert np.all(s.contact[lam > 1e-9])
    assert np.dot(lam, dk) == pytest.approx(um(s.constant), abs=1e-9)  # strong duality


@pytest.mark.parametrize("engine", ENGINES)
@FAST
@given(case=cases, shift=st.floats(-5, 5), factor=st.floats(0.01, 100), turn=st.integers(0, 20))
# a face of optima 1e-8 um across: shorter than the contact tolerance, so it is reported as one point
@example(case=(6, 0.0, [0.0, 1e-08, 1.0, 1e-08, 0.0, 0.0], False), shift=0.0, factor=0.5, turn=0)
def test_invariances(case, shift, factor, turn, engine):
    """Adding a constant to every dk shifts a0 only; scaling scales a0, B, D; relabelling the balls
    (starting the count at another ball) changes nothing.

    a0 is unique and compared to 1e-9 um. B and D are unique only up to the contact tolerance: a face of
    optima shorter than it counts as a single point (spec 003 section 7.6), and which of its points is
    reported may move by up to its length when the tolerance does not scale with the data (max |dk| < 1 um).
    """
    n, first, dk, _ = case
    dk = np.asarray(dk)
    th = regular(n, first)
    base = R.solve_contact(dk * UM, th, engine=engine)
    moved = R.solve_contact((dk + shift) * UM, th, engine=engine)
    assert um(moved.constant) == pytest.approx(um(base.constant) + shift, abs=1e-9)
    face_tol = max(contact_tol_um(dk), contact_tol_um(dk + shift))
    assert_allclose(um([moved.sine, moved.cosine]), um([base.sine, base.cosine]), atol=face_tol)
    scaled = R.solve_contact(dk * factor * UM, th, engine=engine)
    assert um(scaled.constant) == pytest.approx(
        factor * um(base.constant), abs=1e-9 * max(1.0, factor)
    )
    assert_allclose(
        um([scaled.sine, scaled.cosine]),
        factor * um([base.sine, base.cosine]),
        atol=max(factor * contact_tol_um(dk), contact_tol_um(dk * factor)),
    )
    k = turn % n
    rolled = R.solve_contact(np.roll(dk, k) * UM, np.roll(th, k), engine=engine)
    assert_allclose(
        um([rolled.constant, rolled.sine, rolled.cosine]),
        um([base.constant, base.sine, base.cosine]),
        atol=1e-9,
    )
    assert np.array_equal(np.roll(base.contact, k), rolled.contact)


@pytest.mark.parametrize("engine", ENGINES)
@FAST
@given(case=cases, delta=st.floats(0, 2 * np.pi))
def test_rotating_the_ball_set_rotates_the_sinusoid(case, delta, engine):
    n, first, dk, _ = case
    th = regular(n, first)
    a = R.solve_contact(np.asarray(dk) * UM, th, engine=engine)
    b = R.solve_contact(np.asarray(dk) * UM, th + delta, engine=engine)
    # s(theta) = a0 + A sin(theta + phi): the same curve at theta + delta means phi -> phi - delta
    assert um(b.constant) == pytest.approx(um(a.constant), abs=1e-9)
    assert um(b.amplitude) == pytest.approx(um(a.amplitude), abs=1e-7)
    if not a.degenerate and a.amplitude > 1e-8 * UM:
        assert math.remainder(float(b.phase - (a.phase - delta)), 2 * math.pi) == pytest.approx(
            0.0, abs=1e-6
        )


@pytest.mark.parametrize("engine", ENGINES)
def test_equal_errors_every_ball_touches(engine):
    """Section 16.3."""
    for n in (3, 4, 7, 16):
        s = R.solve_contact(np.full(n, 0.37) * UM, regular(n, 0.1), engine=engine)
        assert um(s.constant) == pytest.approx(0.37, abs=1e-12)
        assert um(s.sine) == pytest.approx(0, abs=1e-12) and um(s.cosine) == pytest.approx(
            0, abs=1e-12
        )
        assert np.all(s.contact)
        assert not s.degenerate


@pytest.mark.parametrize("engine", ENGINES)
def test_four_balls_always_rest_on_a_pair(engine):
    """With n = 4 no triangle strictly contains the centre: the optimum is a diametral pair and, unless
    both pairs tie, the face is a segment."""
    s = R.solve_contact(np.array([0.0, 1.0, 0.5, 2.0]) * UM, regular(4), engine=engine)
    assert list(np.flatnonzero(s.contact)) == [0, 2]
    assert s.degenerate
    tie = R.solve_contact(np.array([0.0, 1.0, 2.0, 1.0]) * UM, regular(4), engine=engine)
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


@pytest.mark.parametrize("engine", ENGINES)
def test_a_position_gives_the_same_bits_alone_or_in_a_batch(g, engine):
    e = R.manufacturing_errors(
        16,
        ball_diameter_deviation=np.linspace(-0.2, 0.2, 16) * UM,
        inner=R.RacewayErrors(radial=R.fourier_series({1: 0.4, 3: 0.1}, scale=UM)),
    )
    psi = np.linspace(0, 4 * np.pi, 500)
    batch = R.initial_displacement(psi, g, e, engine=engine)
    one = R.initial_displacement(psi[123], g, e, engine=engine)
    for name in ("x", "y", "z"):
        assert getattr(one, name) == getattr(batch, name)[123]
    for name in ("generalized_error", "ball_angle"):
        assert np.array_equal(getattr(one, name), getattr(batch, name)[123])
    for name in ("constant", "sine", "cosine", "load_share", "slack", "contact"):
        assert np.array_equal(getattr(one.contact, name), getattr(batch.contact, name)[123])


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


# ------------------------------------------------------------------------------ generalized error and its signs
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


def test_benchmark_functions_agree_on_a_small_input(load_bench):
    """Smoke test of bench/runout.py (the benchmark itself is not run in the tests)."""
    bench = load_bench("runout")
    dk, theta = bench.cases(40)
    sol = bench.solve_batch(dk, theta)
    a0 = bench.solve_one_by_one(dk[:8], theta[:8])
    assert_allclose(um(sol.constant[:8]), um(a0), atol=1e-6)
