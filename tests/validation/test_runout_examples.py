"""Spec 003 worked examples (section 15), the reference geometry (section 2), the tilt example (section 5),
the refinement remarks (section 9) and the Monte Carlo acceptance test (section 11).

Expected values are in ``tests/data/runout_worked_examples.toml`` and
``tests/data/runout_monte_carlo_reference.csv``. Tolerances follow section 15: 1e-6 um for a0, B, D,
dx, dy, dz and the runout metrics, 1e-5 um for refined values, contact sets exact, 1e-6 relative for
kappa-dependent angles; other printed values to half a unit of their last printed digit.
"""

import csv
import math
import tomllib
from pathlib import Path

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.optimize import linprog

from bearinglab import runout as R

DATA = Path(__file__).parent.parent / "data"
EXAMPLES = Path(__file__).parent.parent.parent / "examples" / "runout"
REF = tomllib.loads((DATA / "runout_worked_examples.toml").read_text(encoding="utf-8"))
UM = 1e-6
TOL = 1e-6  # um, spec 003 section 15
TOL_REFINED = 1e-5  # um
METHODS = ("dual", "triples", "lp")


def um(x):
    return np.asarray(x) / UM


def half_unit(value):
    """Half a unit of the last printed digit of a value as written in the data file (6 decimals)."""
    return 0.5e-6


@pytest.fixture(scope="module")
def g():
    r = REF["geometry"]
    return R.geometry_from_catalog(
        r["balls"],
        r["ball_diameter"] * 1e-3,
        r["pitch_diameter"] * 1e-3,
        r["outer_conformity"],
        r["inner_conformity"],
        math.radians(r["contact_angle"]),
    )


def example1():
    return R.manufacturing_errors(16, ball_diameter_deviation=np.r_[2.0, np.zeros(15)] * UM)


def example2():
    return R.manufacturing_errors(
        16, inner=R.RacewayErrors(radial=R.fourier_series({2: 1.0}, scale=UM))
    )


def example3():
    r = REF["example3"]
    inner = R.RacewayErrors(radial=R.fourier_series(r["inner_cos"], r["inner_sin"], scale=UM))
    outer = R.RacewayErrors(radial=R.fourier_series(r["outer_cos"], r["outer_sin"], scale=UM))
    return R.manufacturing_errors(
        16,
        inner=inner,
        outer=outer,
        ball_diameter_deviation=np.array(r["ball_diameter_deviation"]) * UM,
    )


def contacts(d):
    return list(np.flatnonzero(d.contact.contact) + 1)


# ------------------------------------------------------------------------------------------- section 2
def test_reference_geometry(g):
    r = REF["geometry"]
    got = {
        "r30": g.ball_radius,
        "rho10": g.outer_groove_radius,
        "rho20": g.inner_groove_radius,
        "A0": g.groove_distance,
        "R_b": g.ball_centre_radius,
        "H20": g.inner_bottom_radius,
        "H10": g.outer_bottom_radius,
        "S": g.axial_offset,
        "R_c2": g.inner_centre_radius,
    }
    for key, value in got.items():  # printed to 6 decimals in mm (A0 to 5)
        assert value * 1e3 == pytest.approx(r[key], abs=0.5e-6 if key != "A0" else 0.5e-5), key
    assert g.pitch_ratio == pytest.approx(r["gamma"], abs=0.5e-6)
    assert g.cage_ratio == pytest.approx(r["kappa"], abs=0.5e-6)
    assert 1 / math.sin(g.contact_angle) == pytest.approx(r["inv_sin_tau0"], abs=0.5e-6)
    assert 1 / math.cos(g.contact_angle) == pytest.approx(r["inv_cos_tau0"], abs=0.5e-6)


def test_radii_form_gives_the_same_geometry(g):
    h = R.geometry_from_radii(
        16,
        g.ball_radius,
        g.outer_groove_radius,
        g.inner_groove_radius,
        g.inner_bottom_radius,
        g.contact_angle,
        outer_bottom_radius=g.outer_bottom_radius,
    )
    for a, b in zip(g, h):
        assert a == pytest.approx(b, rel=1e-14, abs=1e-18)


# ------------------------------------------------------------------------------------------- section 5
def test_tilt_only_example(g):
    r = REF["tilt_only"]
    e = R.manufacturing_errors(16, tilt_x=r["alpha_urad"] * UM, tilt_y=r["beta_urad"] * UM)
    d = R.initial_displacement(0.0, g, e)
    assert um([d.contact.constant, d.contact.sine, d.contact.cosine]) == pytest.approx(
        [0, 0, 0], abs=TOL
    )
    assert_allclose(um([d.x, d.y, d.z]), [r["dx"], r["dy"], r["dz"]], atol=half_unit(r["dx"]))
    # dx = beta R_c2 tan(tau0), dy = -alpha R_c2 tan(tau0) exactly
    k = g.inner_centre_radius * math.tan(g.contact_angle)
    assert d.x == pytest.approx(r["beta_urad"] * UM * k, rel=1e-12)
    assert d.y == pytest.approx(-r["alpha_urad"] * UM * k, rel=1e-12)


# ------------------------------------------------------------------------------------------- example 1
@pytest.mark.parametrize("method", METHODS)
def test_example1_single_position(g, method):
    r = REF["example1"]
    d = R.initial_displacement(0.0, g, example1(), method=method)
    c = d.contact
    assert_allclose(
        um([c.constant, c.sine, c.cosine, c.amplitude]), [r["a0"], r["B"], r["D"], r["A"]], atol=TOL
    )
    assert math.degrees(c.phase) == pytest.approx(r["phi"], abs=1e-6)
    assert contacts(d) == r["contacts"]
    assert bool(c.degenerate) is r["degenerate"]
    assert um(c.face_diameter) == pytest.approx(r["face_diameter"], abs=0.5e-6)
    assert um(d.free_play) / 2 == pytest.approx(r["play_half"], abs=0.5e-6)
    assert_allclose(um([d.x, d.y, d.z]), [r["dx"], r["dy"], r["dz"]], atol=TOL)
    lam = c.load_share
    assert_allclose(lam[[0, 8]], [r["load_share"]] * 2, atol=1e-12)
    assert lam.sum() == pytest.approx(1.0, abs=1e-12)


def test_example1_face_ends(g):
    """The optimal face is B in [-0.198912, +0.198912] at D = -1: the ends are where balls 8, 10 (B > 0) or
    balls 8, 10 mirrored (B < 0) start to touch; the tie-break picks B = 0."""
    r = REF["example1"]
    th = R.ball_angles(0.0, g)
    dk = um(R.generalized_error(0.0, g, example1()))
    b_hi = min((1 - r["D"] * np.cos(t)) / np.sin(t) for t in th[1:] if np.sin(t) > 1e-9)
    assert b_hi == pytest.approx(r["face_B_half"], abs=0.5e-6)
    # an LP over the face confirms both ends
    face = np.column_stack([np.sin(th), np.cos(th)])
    rhs = dk - r["a0"] + 1e-12
    ends = [
        linprog(c, A_ub=face, b_ub=rhs, bounds=[(None, None)] * 2, method="highs").x[0]
        for c in ([1, 0], [-1, 0])
    ]
    assert_allclose(ends, [-r["face_B_half"], r["face_B_half"]], atol=0.5e-6)


def test_example1_literal_eq27_has_the_wrong_sign(g):
    """Source eq. 27: dx = (beta R_c2 sin tau0 + A / sqrt(1 + ctg^2 phi)) / cos tau0 = A |sin phi| / cos tau0."""
    r = REF["example1"]
    d = R.initial_displacement(0.0, g, example1())
    a, phi = float(d.contact.amplitude), float(d.contact.phase)
    literal = a / math.sqrt(1 + 1 / math.tan(phi) ** 2) / math.cos(g.contact_angle)
    assert um(literal) == pytest.approx(r["literal_eq27_dx"], abs=TOL)
    assert um(d.x) == pytest.approx(-r["literal_eq27_dx"], abs=TOL)


def test_example1_trajectory(g):
    r = REF["example1"]
    t = R.rotation_sequence(g, example1(), revolutions=3, steps_per_revolution=360)
    for name in R.METRICS:
        assert um(getattr(t.metrics, name)) == pytest.approx(r[name], abs=TOL), name
    # the centre runs on a circle of radius 1/cos(tau0) um
    radius = np.hypot(t.displacement.x, t.displacement.y)
    assert_allclose(um(radius), REF["geometry"]["inv_cos_tau0"], atol=TOL)


# ------------------------------------------------------------------------------------------- example 2
@pytest.mark.parametrize("method", METHODS)
def test_example2_psi0(g, method):
    r = REF["example2"]
    d = R.initial_displacement(0.0, g, example2(), method=method)
    assert um(d.contact.constant) == pytest.approx(r["psi0_a0"], abs=TOL)
    assert contacts(d) == r["psi0_contacts"]
    assert bool(d.contact.degenerate)
    assert um(d.contact.face_diameter) == pytest.approx(r["psi0_face_diameter"], abs=0.5e-6)
    assert um(d.free_play) / 2 == pytest.approx(r["psi0_play_half"], abs=0.5e-6)
    assert_allclose(um([d.x, d.y, d.z]), [0.0, 0.0, r["psi0_dz"]], atol=TOL)


def test_example2_psi0_refined(g):
    r = REF["example2"]
    d = R.initial_displacement(0.0, g, example2(), refine=True)
    assert um(d.z) == pytest.approx(r["psi0_refined_dz"], abs=TOL_REFINED)
    assert um(d.x) == pytest.approx(0.0, abs=TOL_REFINED) and um(d.y) == pytest.approx(
        0.0, abs=TOL_REFINED
    )
    assert bool(d.converged)
    shifts = d.shifts
    for i in (
        np.array(r["psi0_contacts"]) - 1
    ):  # d tau1 = d tau2 = -0.010119 rad at the contacts (no tilt)
        assert shifts.outer_angle_shift[i] == pytest.approx(r["psi0_refined_dtau_rad"], abs=0.5e-6)
        assert shifts.inner_angle_shift[i] == pytest.approx(r["psi0_refined_dtau_rad"], abs=0.5e-6)
    # section 9: dz = -3.7 um changes the contact angle by -0.58 deg
    assert math.degrees(shifts.inner_angle_shift[0]) == pytest.approx(
        r["contact_angle_change"], abs=0.005
    )


@pytest.mark.parametrize(
    "example, psi, key",
    [
        ("example2", 0.0, "psi0_refined_passes"),
        ("example3", 0.0, "psi0_refined_passes"),
        ("example3", 90.0, "psi90_refined_passes"),
    ],
)
def test_refinement_pass_counts(g, example, psi, key):
    """The printed pass counts (6, 5, 4) do not follow from the stated tolerance of 1e-9 um, which stops
    after 4, 3 and 3 passes here (the pose changes by 1.7e-10, 3.9e-10 and 1.5e-11 um at those passes).
    They are reproduced with a tolerance of 1e-13 um (any value in (2.3e-15, 2.4e-13] um gives them), i.e.
    iterating until the pose stops changing in double precision. Both are pinned here; see the report."""
    e = example2() if example == "example2" else example3()
    strict = R.initial_displacement(math.radians(psi), g, e, refine=True, tol=1e-13 * UM)
    assert int(strict.passes) == REF[example][key]
    default = R.initial_displacement(math.radians(psi), g, e, refine=True)  # regression: 1e-9 um
    assert int(default.passes) == {"example2": 4, "example3": 3}[example]


def test_example2_psi10(g):
    r = REF["example2"]
    d = R.initial_displacement(math.radians(10.0), g, example2())
    assert math.degrees(d.ball_angle[0]) == pytest.approx(r["psi10_ball1"], rel=1e-6)
    assert um(d.contact.constant) == pytest.approx(r["psi10_a0"], abs=TOL)
    assert contacts(d) == r["psi10_contacts"]
    assert um(d.z) == pytest.approx(r["psi10_dz"], abs=TOL)
    refined = R.initial_displacement(math.radians(10.0), g, example2(), refine=True)
    assert um(refined.z) == pytest.approx(r["psi10_refined_dz"], abs=TOL_REFINED)


def test_example2_trajectory(g):
    r = REF["example2"]
    t = R.rotation_sequence(g, example2(), revolutions=3, steps_per_revolution=360)
    d = t.displacement
    assert np.max(np.abs(um(d.x))) < TOL and np.max(np.abs(um(d.y))) < TOL  # dx = dy = 0 throughout
    assert um(t.metrics.axial_ptp) == pytest.approx(r["axial_ptp"], abs=TOL)
    assert um(t.metrics.dz_mean) == pytest.approx(r["dz_mean"], abs=TOL)
    assert t.degenerate_fraction > 0.9  # "almost every position is degenerate"


def test_example2_axial_ptp_tends_to_the_analytic_value(g):
    """Over a full cycle the axial peak-to-peak is cos(tau0)(1 - cos(pi/8))/sin(tau0) = 0.284085 um; the
    1080-step trajectory misses the exact extreme by 0.0008 um, a fine one does not."""
    r = REF["example2"]
    analytic = (
        math.cos(g.contact_angle) * (1 - math.cos(math.pi / 8)) / math.sin(g.contact_angle)
    )  # um per um
    assert analytic == pytest.approx(r["axial_ptp_analytic"], abs=0.5e-6)
    # dz is lowest when a ball sits at the ovality's minor axis (psi = 0) and highest when two balls sit
    # symmetrically about it, the ball set turned by pi/16 relative to the inner ring: (kappa - 1) psi = -pi/16
    psi_top = -math.pi / 16 / (g.cage_ratio - 1.0)
    d = R.initial_displacement(np.array([0.0, psi_top]), g, example2())
    assert um(d.z[1] - d.z[0]) == pytest.approx(analytic, abs=1e-9)
    # sampled trajectories stay below it and approach it
    fine = R.rotation_sequence(g, example2(), revolutions=1, steps_per_revolution=4000)
    assert um(fine.metrics.axial_ptp) <= analytic + 1e-9
    assert um(fine.metrics.axial_ptp) == pytest.approx(analytic, abs=1e-4)


# ------------------------------------------------------------------------------------------- example 3
@pytest.mark.parametrize("method", METHODS)
def test_example3_psi0(g, method):
    r = REF["example3"]
    d = R.initial_displacement(0.0, g, example3(), method=method)
    assert_allclose(um(d.generalized_error), r["psi0_dk"], atol=0.5e-6)  # printed to 6 decimals
    c = d.contact
    assert_allclose(
        um([c.constant, c.sine, c.cosine]), [r["psi0_a0"], r["psi0_B"], r["psi0_D"]], atol=TOL
    )
    assert contacts(d) == r["psi0_contacts"]
    assert bool(c.degenerate)
    assert um(c.face_diameter) == pytest.approx(r["psi0_face_diameter"], abs=0.5e-6)
    assert_allclose(um([d.x, d.y, d.z]), r["psi0_pose"], atol=TOL)


@pytest.mark.parametrize("method", METHODS)
def test_example3_psi90(g, method):
    r = REF["example3"]
    d = R.initial_displacement(math.radians(90.0), g, example3(), method=method)
    assert math.degrees(d.ball_angle[0]) == pytest.approx(r["psi90_ball1"], rel=1e-6)
    c = d.contact
    assert_allclose(
        um([c.constant, c.sine, c.cosine]), [r["psi90_a0"], r["psi90_B"], r["psi90_D"]], atol=TOL
    )
    assert contacts(d) == r["psi90_contacts"]
    assert not bool(c.degenerate)
    assert_allclose(
        c.load_share[np.array(r["psi90_contacts"]) - 1], r["psi90_load_share"], atol=0.5e-6
    )
    assert_allclose(um([d.x, d.y, d.z]), r["psi90_pose"], atol=TOL)


@pytest.mark.parametrize("psi, key", [(0.0, "psi0_refined_pose"), (90.0, "psi90_refined_pose")])
def test_example3_refined(g, psi, key):
    d = R.initial_displacement(math.radians(psi), g, example3(), refine=True)
    assert_allclose(um([d.x, d.y, d.z]), REF["example3"][key], atol=TOL_REFINED)
    assert bool(d.converged)


def test_example3_pose_table(g):
    p = REF["example3"]["poses"]
    d = R.initial_displacement(np.radians(p["psi"]), g, example3())
    for name in ("dx", "dy", "dz"):  # rounded to 1e-4 um in the spec
        assert_allclose(um(getattr(d, name[1])), p[name], atol=0.5e-4, err_msg=name)
    for k, expected in enumerate(p["contacts"]):
        assert list(np.flatnonzero(d.contact.contact[k]) + 1) == expected, p["psi"][k]


def test_example3_trajectory(g):
    r = REF["example3"]
    t = R.rotation_sequence(g, example3(), revolutions=3, steps_per_revolution=360)
    for name in R.METRICS:
        assert um(getattr(t.metrics, name)) == pytest.approx(r[name], abs=TOL), name
    assert round(100 * t.degenerate_fraction) == r["degenerate_percent"]  # "about 23 %"


def test_example3_refined_trajectory(g):
    r = REF["example3"]
    t = R.rotation_sequence(g, example3(), revolutions=3, steps_per_revolution=36, refine=True)
    assert np.all(t.displacement.converged)
    for name in R.METRICS:
        assert um(getattr(t.metrics, name)) == pytest.approx(
            r[f"refined_{name}"], abs=TOL_REFINED
        ), name


def test_example3_with_15_balls_has_no_degenerate_position(g):
    g15 = R.geometry_from_catalog(15, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(15))
    e = example3()
    e15 = e._replace(
        ball_outer_deficit=e.ball_outer_deficit[:15], ball_inner_deficit=e.ball_inner_deficit[:15]
    )
    t = R.rotation_sequence(g15, e15, revolutions=3, steps_per_revolution=360)
    assert t.degenerate_fraction == 0.0


def test_example3_midpoint_tie_break_moves_points_but_not_metrics(g):
    r = REF["example3"]
    a = R.rotation_sequence(g, example3(), revolutions=3, steps_per_revolution=360)
    b = R.rotation_sequence(
        g, example3(), revolutions=3, steps_per_revolution=360, tie_break="midpoint"
    )
    move = np.hypot(a.displacement.x - b.displacement.x, a.displacement.y - b.displacement.y)
    face_move = np.hypot(
        a.displacement.contact.sine - b.displacement.contact.sine,
        a.displacement.contact.cosine - b.displacement.contact.cosine,
    )
    # The spec's "up to 0.265 um" is the move in the (B, D) plane (0.26557 um, i.e. truncated, not rounded);
    # the ring centre itself moves 1/cos(tau0) times as far, 0.27494 um. Tolerance 1e-3 um covers the
    # truncation; see the report.
    assert um(face_move.max()) == pytest.approx(r["midpoint_max_move"], abs=1e-3)
    assert move.max() == pytest.approx(face_move.max() / math.cos(g.contact_angle), rel=1e-9)
    for name in R.METRICS:
        assert um(getattr(b.metrics, name)) == pytest.approx(
            um(getattr(a.metrics, name)), abs=1e-9
        ), name


# ------------------------------------------------------------------------------------------- example 4
def test_example4_sinusoid_and_round_trip(g):
    r = REF["example4"]
    alpha, beta = r["alpha_urad"] * UM, r["beta_urad"] * UM
    s = R.sinusoid_from_pose(*(np.array(r["pose"]) * UM), g, tilt_x=alpha, tilt_y=beta)
    assert_allclose(um(s), [r["a0"], r["B"], r["D"]], atol=0.5e-6)
    th = R.ball_angles(0.0, g)
    dk = s.constant + s.sine * np.sin(th) + s.cosine * np.cos(th)
    e = R.manufacturing_errors(16, ball_outer_deficit=dk, tilt_x=alpha, tilt_y=beta)
    for method in METHODS:
        d = R.initial_displacement(0.0, g, e, method=method)
        assert np.all(d.contact.contact), method  # every ball touches
        assert_allclose(um([d.x, d.y, d.z]), r["pose"], atol=r["round_trip_tol"], err_msg=method)


def test_example4_exact_geometry(g):
    r = REF["example4"]
    th = R.ball_angles(0.0, g)
    for scale, key in ((1.0, "exact_minus_linear_max"), (0.1, "exact_minus_linear_max_tenth")):
        pose = np.array(r["pose"]) * UM * scale
        alpha, beta = r["alpha_urad"] * UM * scale, r["beta_urad"] * UM * scale
        s = R.sinusoid_from_pose(*pose, g, tilt_x=alpha, tilt_y=beta)
        linear = s.constant + s.sine * np.sin(th) + s.cosine * np.cos(th)
        exact = R.exact_reduction(th, *pose, g, tilt_x=alpha, tilt_y=beta)
        worst = um(np.abs(exact - linear).max())
        assert worst == pytest.approx(r[key], rel=0.05 / 9.3), key  # 2 significant digits printed
    assert um(R.exact_reduction(0.0, 0.0, 0.0, 1.0 * UM, g)) == pytest.approx(
        r["dz1_exact"], abs=0.5e-6
    )
    assert um(R.sinusoid_from_pose(0.0, 0.0, 1.0 * UM, g).constant) == pytest.approx(
        r["dz1_linear"], abs=0.5e-6
    )


def test_example4_exact_minus_linear_is_about_the_quadratic_term(g):
    """Section 9: |exact - linear| ~ |delta_perp|^2 / (2 A0) in s; a pure dz = 1 um has delta_perp = dz cos tau0."""
    d_perp = 1.0 * UM * math.cos(g.contact_angle)
    quad = d_perp**2 / (2 * g.groove_distance)
    diff = (
        R.exact_reduction(0.0, 0.0, 0.0, 1.0 * UM, g)
        - R.sinusoid_from_pose(0.0, 0.0, 1.0 * UM, g).constant
    )
    assert diff == pytest.approx(quad, rel=0.01)


# ------------------------------------------------------------------------------------------- shipped files
@pytest.mark.parametrize(
    "name, key",
    [
        ("example1_oversize_ball.toml", "example1"),
        ("example2_inner_ovality.toml", "example2"),
        ("example3_mixed.toml", "example3"),
    ],
)
def test_shipped_example_files_reproduce_the_spec(name, key):
    geom, e = R.load_error_file(EXAMPLES / name)
    t = R.rotation_sequence(geom, e, revolutions=3, steps_per_revolution=360)
    for metric in ("axial_ptp", "dz_mean"):
        assert um(getattr(t.metrics, metric)) == pytest.approx(REF[key][metric], abs=TOL), metric
    if key != "example2":
        assert um(t.metrics.radial_ptp_x) == pytest.approx(REF[key]["radial_ptp_x"], abs=TOL)


def test_shipped_example4_file_recovers_the_pose_at_every_angle():
    geom, e = R.load_error_file(EXAMPLES / "example4_tilt.toml")
    t = R.rotation_sequence(geom, e, revolutions=1, steps_per_revolution=36)
    d = t.displacement
    for v, expected in zip((d.x, d.y, d.z), REF["example4"]["pose"]):
        assert_allclose(um(v), expected, atol=1e-8)
    assert np.all(d.contact.contact)


# ------------------------------------------------------------------------------------------- section 11
def _mc_reference():
    lines = [
        ln
        for ln in (DATA / "runout_monte_carlo_reference.csv").read_text().splitlines()
        if ln and not ln.startswith("#")
    ]
    return list(csv.DictReader(lines))


@pytest.mark.parametrize("case, n", [("G5/P4", 200), ("G10/P5", 100)])
def test_monte_carlo_statistical_acceptance(g, case, n):
    """Section 11: with N samples the sample means lie within mean +- 3 std / sqrt(N) of the table."""
    grade, rings = case.split("/")
    res = R.monte_carlo(
        g, grade, rings, n, 20260, steps_per_revolution=180, revolutions=2, max_order=15
    )
    rows = [row for row in _mc_reference() if row["case"] == case]
    assert len(rows) == 3
    for row in rows:
        mean, std = float(row["mean"]), float(row["std"])
        got = um(res.summary[row["metric"]].mean)
        assert abs(got - mean) <= 3 * std / math.sqrt(n), (row["metric"], got, mean)
