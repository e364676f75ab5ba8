"""Rotation of spec 003 section 10 (``runout.rotation``): metrics, synchronous part, spectrum, cage."""

import importlib.util
import time
import tracemalloc
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose

from bearinglab import runout as R
from bearinglab.errors import InputError

# who finds the largest distance: qhull and numpy's calipers, or the compiled monotone chain and calipers
ENGINES = ["numpy", pytest.param("compiled", marks=pytest.mark.skipif(
    importlib.util.find_spec("numba") is None, reason="numba is not installed"))]

UM = 1e-6
EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "runout"


# ------------------------------------------------------------------------------ rotation and metrics
@pytest.mark.parametrize("engine", ENGINES)
def test_metrics_against_brute_force(engine):
    rng = np.random.default_rng(7)
    x, y, z = rng.normal(size=(3, 3, 200))
    m = R.runout_metrics(x, y, z, engine=engine)
    for k in range(3):
        d = np.hypot(x[k][:, None] - x[k][None, :], y[k][:, None] - y[k][None, :]).max()
        assert m.radial_ptp_max[k] == pytest.approx(d, rel=1e-14)
        assert m.radial_ptp_max[k] >= max(m.radial_ptp_x[k], m.radial_ptp_y[k])
        # the largest peak-to-peak over directions equals the diameter: check against 3600 directions
        phi = np.linspace(0, np.pi, 3600, endpoint=False)
        proj = np.outer(np.cos(phi), x[k]) + np.outer(np.sin(phi), y[k])
        assert np.ptp(proj, axis=1).max() == pytest.approx(d, rel=1e-6)


def brute_force_diameter(x, y):
    """The largest distance over all pairs of points, written independently of the library."""
    dx = x[:, None] - x[None, :]
    dy = y[:, None] - y[None, :]
    return float(np.sqrt(np.max(dx * dx + dy * dy)))


coordinate = st.floats(-1e3, 1e3, allow_nan=False, allow_infinity=False)
point_sets = st.integers(1, 80).flatmap(
    lambda n: st.tuples(
        st.lists(coordinate, min_size=n, max_size=n), st.lists(coordinate, min_size=n, max_size=n)
    )
)


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(points=point_sets, scale=st.sampled_from([1.0, 1e-9]), offset=st.floats(-1e3, 1e3))
@example(points=([0.0] * 12, [0.0] * 12), scale=1.0, offset=0.0)  # one point, repeated
@example(points=(list(range(12)), [3.0] * 12), scale=1.0, offset=0.0)  # collinear, along x
@example(
    points=(list(range(12)), list(range(0, 24, 2))), scale=1e-9, offset=5.0
)  # collinear, askew
@example(points=([0.0, 1.0, 0.0, 1.0] * 3, [0.0, 0.0, 1.0, 1.0] * 3), scale=1.0, offset=0.0)  # ties
@pytest.mark.parametrize("engine", ENGINES)
def test_diameter_equals_the_largest_distance_of_all_pairs(points, scale, offset, engine):
    """The convex-hull diameter (rotating calipers) equals the brute force over all pairs. Both take the
    square root of the largest dx^2 + dy^2, so when they pick the same pair they agree to the bit;
    qhull merges points that lie within its rounding (about 1e-15 of the extent) of another point or
    of the hull, and may then report a pair shorter by that much: hence rel = 1e-13, not ==."""
    x = np.array(points[0]) * scale + offset * scale
    y = np.array(points[1]) * scale
    got = R.runout_metrics(x, y, np.zeros_like(x), engine=engine).radial_ptp_max
    assert got == pytest.approx(brute_force_diameter(x, y), rel=1e-13, abs=0.0)


@settings(max_examples=150, deadline=None)
@given(
    angles=st.lists(st.floats(0.0, 2 * np.pi), min_size=3, max_size=120),
    aspect=st.floats(0.2, 1.0),
)
# found by a random search against the first version (it looked for the antipode past the last edge)
@example(
    angles=[1.0, 5.387135627773562e-15, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 2.0], aspect=1.0
)  # merged
@example(
    angles=[1.02, 2.26, 5.31, 3.04, 3.39, 1.83, 3.46, 3.8, 2.11, 3.78, 4.74, 2.22, 2.86, 0.82],
    aspect=1.0,
)
@pytest.mark.parametrize("engine", ENGINES)
def test_diameter_of_points_on_an_ellipse_at_random_angles(angles, aspect, engine):
    """All points on the hull, none exactly antipodal: the antipode of an edge late in the hull order
    lies past the end of the list of edges (a wrap-around the first version missed)."""
    t = np.array(angles)
    x, y = np.cos(t), aspect * np.sin(t)
    got = R.runout_metrics(x, y, 0 * x, engine=engine).radial_ptp_max
    assert got == pytest.approx(brute_force_diameter(x, y), rel=1e-13, abs=0.0)  # qhull's merging


@pytest.mark.parametrize("engine", ENGINES)
def test_diameter_of_circles_and_ellipses_is_exact(engine):
    """Every point of a circle is a hull vertex and has an antipode: the worst case for a hull method."""
    t = 2 * np.pi * np.arange(3600) / 3600
    for a, b in ((1.0, 1.0), (1.0, 0.3), (2e-6, 1.9e-6)):
        x, y = a * np.cos(t + 0.1), b * np.sin(t + 0.1)
        m = R.runout_metrics(np.stack([x, y]), np.stack([y, x]), 0 * np.stack([x, y]), engine=engine)
        assert m.radial_ptp_max[0] == m.radial_ptp_max[1] == brute_force_diameter(x, y)


@pytest.mark.parametrize("engine", ENGINES)
def test_diameter_memory_is_linear_in_the_positions(engine):
    """1000 revolutions x 360 steps: all pairs would take 360 000^2 x 8 B = 1 TB; the hull a few MB."""
    psi = 2 * np.pi * np.arange(1000 * 360) / 360
    x = np.cos(psi) + 0.1 * np.cos(3 * psi)  # synchronous: every revolution the same 360 points
    y = np.sin(psi) - 0.2 * np.sin(2 * psi)
    tracemalloc.start()
    start = time.perf_counter()
    m = R.runout_metrics(x, y, np.zeros_like(x), engine=engine)
    elapsed = time.perf_counter() - start
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    assert peak < 64e6, f"peak {peak / 1e6:.0f} MB"  # inputs are 2.9 MB each
    assert elapsed < 5.0  # about 0.1 s on one core
    assert m.radial_ptp_max == brute_force_diameter(x[:360], y[:360])


def test_a_thousand_revolutions_take_seconds():
    """Issue 15: 100 revolutions of example 3 asked numpy for 9.66 GiB; 1000 now run in seconds."""
    geometry, errors = R.load_error_file(EXAMPLES / "example3_mixed.toml")
    start = time.perf_counter()
    t = R.rotation_sequence(geometry, errors, revolutions=1000, steps_per_revolution=36)
    assert time.perf_counter() - start < 20.0  # about 1 s on one core; generous for a busy machine
    assert t.metrics.radial_ptp_max >= max(t.metrics.radial_ptp_x, t.metrics.radial_ptp_y)
    few = R.rotation_sequence(geometry, errors, revolutions=10, steps_per_revolution=36)
    assert t.metrics.radial_ptp_max >= few.metrics.radial_ptp_max  # a longer record covers more


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


def test_spectrum_line_is_labelled_at_its_true_order():
    """Issue 15 item 11: kappa = 0.436 over three revolutions sits in the bin 1/3; the line is at 0.436."""
    n = 64
    psi = 2 * np.pi * np.arange(3 * n) / n
    sp = R.runout_spectrum(0 * psi, 0 * psi, np.cos(0.436 * psi), n)
    (line,) = [ln for ln in R.spectrum_lines(sp, 0.436) if ln.component == "axial"]
    assert line.label == "κ" and line.order == pytest.approx(0.436, abs=1e-15)
    assert line.bin_order == pytest.approx(1 / 3) and line.resolution == pytest.approx(1 / 3)
