"""Tests of bearinglab.geometry: spec 000 sections 4 and 5.1 (printed values), an independent curvature
computation from the principal radii, the paper's m-form of cos tau, round trips, properties, bad input."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose

from bearinglab import geometry
from bearinglab.errors import InputError

# bearing 4-1006095 (spec 000 section 7)
D, DM, FI, FO, A0 = 2e-3, 8.7355e-3, 0.525, 0.58, math.radians(12.0)
SETTINGS = settings(max_examples=40, deadline=None)


# ------------------------------------------------------------------------------- spec 000 section 4
def test_clearance_of_the_example_is_9_178_um():
    e = geometry.radial_clearance(A0, D, FI, FO)
    assert (
        f"{e * 1e6:.3f}" == "9.178"
    )  # printed to the micrometre's thousandth (spec 000 section 4)
    # and back: 9.178 um gives 12 deg to the precision of the printed clearance; de/dalpha = 2 B D sin(alpha0)
    # = 87.3 um/rad, so +-0.5 nm is +-5.7e-6 rad = +-3.3e-4 deg
    assert math.degrees(geometry.free_contact_angle(9.178e-6, D, FI, FO)) == pytest.approx(
        12.0, abs=3.3e-4
    )


def test_052_shortcut_gives_19_50_deg():
    # spec 000 section 4: with the e that gives 12 deg exactly, arccos(1 - 12.5 e / d) = 19.50 deg
    e = geometry.radial_clearance(A0, D, FI, FO)
    assert f"{math.degrees(geometry.free_contact_angle_052(e, D)):.2f}" == "19.50"
    # the shortcut is the exact formula with both radii 0.52 D
    assert geometry.free_contact_angle_052(e, D) == pytest.approx(
        geometry.free_contact_angle(e, D, 0.52, 0.52), rel=1e-14
    )


@SETTINGS
@given(
    a0=st.floats(1e-3, 1.55),
    fi=st.floats(0.501, 0.6),
    fo=st.floats(0.501, 0.6),
    d=st.floats(1e-4, 0.1),
)
def test_clearance_angle_round_trip(a0, fi, fo, d):
    e = geometry.radial_clearance(a0, d, fi, fo)
    assert geometry.free_contact_angle(e, d, fi, fo) == pytest.approx(a0, rel=1e-9)
    # axial play, Harris eq. 2.13 written with the clearance: P_e = (4 A P_d - P_d^2)^(1/2), A = B D
    a = (fi + fo - 1.0) * d
    assert geometry.axial_play(a0, d, fi, fo) == pytest.approx(
        math.sqrt(4 * a * e - e * e), rel=1e-9
    )


def test_total_curvature_and_pitch_ratio():
    assert geometry.total_curvature(FI, FO) == pytest.approx(0.105, rel=1e-14)
    assert geometry.pitch_ratio(D, DM, A0) == pytest.approx(2.0 * math.cos(A0) / 8.7355, rel=1e-15)
    assert_allclose(geometry.total_curvature([0.52, 0.53], 0.52), [0.04, 0.05], rtol=1e-13)


# ----------------------------------------------------------------------------- spec 000 section 5.1
@pytest.mark.parametrize(
    "race, cos_tau, sum_rho",
    [
        ("inner", 0.9287242, 1.3361919),  # printed; Sigma rho in 1/mm
        ("outer", 0.7111268, 0.9549594),
    ],
)
def test_curvature_of_the_example_matches_print(race, cos_tau, sum_rho):
    c = geometry.raceway_curvature(D, DM, FI if race == "inner" else FO, A0, race=race)
    # tolerance 2e-7 abs: spec 000 section 8 (the print is off by one unit in the 7th decimal twice, 9.11)
    assert c.curvature_difference == pytest.approx(cos_tau, abs=2e-7)
    assert c.curvature_sum * 1e-3 == pytest.approx(sum_rho, abs=2e-7)


def _principal(d, dm, f, alpha, race):
    """Curvature sum and F(rho) from the four principal curvatures (Harris ch. 2), independently."""
    rho_ball = 2.0 / d  # both planes
    if race == "inner":  # convex raceway in the rolling plane, radius (dm - D cos a) / (2 cos a)
        rho_race = 2.0 * math.cos(alpha) / (dm - d * math.cos(alpha))
    else:  # concave outer raceway
        rho_race = -2.0 * math.cos(alpha) / (dm + d * math.cos(alpha))
    rho_groove = -1.0 / (f * d)  # concave groove
    total = 2 * rho_ball + rho_race + rho_groove
    return total, abs((rho_ball - rho_ball) + (rho_race - rho_groove)) / total


@SETTINGS
@given(
    d=st.floats(1e-3, 0.05),
    ratio=st.floats(1.2, 15),
    f=st.floats(0.505, 0.6),
    alpha=st.floats(0, 1.5),
    race=st.sampled_from(["inner", "outer"]),
)
def test_curvature_from_principal_radii(d, ratio, f, alpha, race):
    c = geometry.raceway_curvature(d, d * ratio, f, alpha, race=race)
    total, diff = _principal(d, d * ratio, f, alpha, race)
    assert c.curvature_sum == pytest.approx(total, rel=1e-12)
    assert c.curvature_difference == pytest.approx(diff, rel=1e-12, abs=1e-14)
    assert 0 <= c.curvature_difference < 1


def _paper_m_form(m, xi, race):
    """The paper's formulas with the corrected sign pattern (spec 000 section 5.1, 9.1)."""
    s = 1.0 if race == "outer" else -1.0  # upper sign: outer ring (n)
    bracket = m + s * 2.0 * xi - s * 1.0
    cos_tau = m / (4.0 * xi * bracket - m)
    sum_rho_d = 2.0 * (4.0 * xi * bracket - m) / (2.0 * xi * (m + s * 2.0 * xi))
    return cos_tau, sum_rho_d


def test_paper_m_form_equals_harris_form():
    gc = geometry.groove_centre_diameters(D, DM, FI, FO, A0)
    for race, m, xi in (("inner", gc.m_inner, FI), ("outer", gc.m_outer, FO)):
        cos_tau, sum_rho_d = _paper_m_form(float(m), xi, race)
        c = geometry.raceway_curvature(D, DM, xi, A0, race=race)
        assert c.curvature_difference == pytest.approx(cos_tau, rel=1e-13)
        assert c.curvature_sum * D == pytest.approx(sum_rho_d, rel=1e-13)


def test_groove_centre_circles_and_the_catalogue_m():
    # spec 000 section 5.1 / section 8: the catalogue prints T_v = 8.831, T_n = 8.42 mm and
    # m_v = 4.514, m_n = 4.304 (tol 5e-4); those correspond to d_m ~ 8.733 mm, not to 8.7355
    gc = geometry.groove_centre_diameters(D, 8.733e-3, FI, FO, A0)
    assert gc.inner_diameter * 1e3 == pytest.approx(8.831, abs=5e-4)
    assert gc.outer_diameter * 1e3 == pytest.approx(8.42, abs=5e-3)  # printed to 2 decimals
    assert gc.m_inner == pytest.approx(4.514, abs=5e-4)
    assert gc.m_outer == pytest.approx(4.304, abs=5e-4)
    # m from the catalogue T as the paper computes it, m = T / (d cos alpha0): 4.5141, 4.3041
    assert 8.831 / (2.0 * math.cos(A0)) == pytest.approx(4.514, abs=5e-4)
    # with the true d_m the m differ from the print by more than its digits (the print used d_m ~ 8.733)
    gc = geometry.groove_centre_diameters(D, DM, FI, FO, A0)
    assert abs(gc.m_inner - 4.514) > 1e-3 and abs(gc.m_outer - 4.304) > 1e-3
    # T = d_m +- (2r - d) cos alpha0
    assert gc.inner_diameter == pytest.approx(DM + (2 * 1.05e-3 - D) * math.cos(A0), rel=1e-15)
    assert gc.outer_diameter == pytest.approx(DM - (2 * 1.16e-3 - D) * math.cos(A0), rel=1e-15)


def test_catalogue_m_give_the_unprinted_curvatures():
    # spec 000 section 5.1: with the catalogue m the paper's formulas give these (not the print)
    for race, m, xi, want_cos, want_sum in (
        ("inner", 8.831 / (2 * math.cos(A0)), FI, 0.9287295, 1.3362906),
        ("outer", 8.42 / (2 * math.cos(A0)), FO, 0.7111140, 0.9549167),
    ):
        cos_tau, sum_rho_d = _paper_m_form(m, xi, race)
        assert cos_tau == pytest.approx(want_cos, abs=1e-7)
        assert sum_rho_d / 2.0 == pytest.approx(want_sum, abs=1e-7)  # d = 2 mm


def test_vectorized_curvature():
    angles = np.radians([0.0, 12.0, 40.0])
    c = geometry.raceway_curvature(D, DM, FI, angles, race="inner")
    for i, a in enumerate(angles):
        one = geometry.raceway_curvature(D, DM, FI, a, race="inner")
        assert (
            c.curvature_sum[i] == one.curvature_sum
            and c.curvature_difference[i] == one.curvature_difference
        )


# ------------------------------------------------------------------------------------------ bad input
@pytest.mark.parametrize(
    "call, match",
    [
        (
            lambda: geometry.total_curvature(0.5, 0.52),
            r"inner_conformity must be in \(0.5, inf\) \[-\], got 0.5",
        ),
        (
            lambda: geometry.total_curvature(0.52, 0.3),
            r"outer_conformity must be in \(0.5, inf\) \[-\], got 0.3",
        ),
        (
            lambda: geometry.raceway_curvature(D, D, FI, A0, race="inner"),
            r"pitch_diameter must be > ball_diameter \[m\], got 0.002 with ball_diameter = 0.002",
        ),
        (lambda: geometry.pitch_ratio(D, 1e-3, A0), r"pitch_diameter must be > ball_diameter"),
        (
            lambda: geometry.raceway_curvature(D, DM, 0.49, A0, race="outer"),
            r"conformity must be in \(0.5, inf\)",
        ),
        (
            lambda: geometry.raceway_curvature(D, DM, FI, A0, race="middle"),
            r"race must be one of \['inner', 'outer'\], got 'middle'",
        ),
        (
            lambda: geometry.raceway_curvature(-D, DM, FI, A0, race="inner"),
            r"ball_diameter must be > 0 \[m\], got -0.002",
        ),
        # clearance with no real contact angle: e must be < 4 B D = 0.84 mm (spec 000 section 4)
        (
            lambda: geometry.free_contact_angle(0.9e-3, D, FI, FO),
            r"radial_clearance must be in \(0, 0.84\) \[mm\] to give a real contact angle, got 0.9 mm",
        ),
        (
            lambda: geometry.free_contact_angle(0.0, D, FI, FO),
            r"radial_clearance must be > 0 \[m\], got 0.0",
        ),
        (
            lambda: geometry.free_contact_angle_052(0.33e-3, D),
            r"radial_clearance must be in \(0, 0.32\) \[mm\] to give a real contact angle, got 0.33 mm",
        ),
        (
            lambda: geometry.radial_clearance(math.radians(90), D, FI, FO),
            r"free_angle must be in \[0, 90\) \[deg\], got 90.0",
        ),
        (
            lambda: geometry.axial_play(-0.01, D, FI, FO),
            r"free_angle must be in \[0, 90\) \[deg\], got -0.57",
        ),
        (
            lambda: geometry.groove_centre_diameters(D, DM, 0.5, FO, A0),
            r"inner_conformity must be in \(0.5, inf\)",
        ),
    ],
)
def test_bad_input(call, match):
    with pytest.raises(InputError, match=match):
        call()


def test_bad_clearance_in_an_array_names_the_first_offender():
    with pytest.raises(InputError, match=r"got 1 mm"):
        geometry.free_contact_angle(np.array([5e-6, 1e-3, 2e-3]), D, FI, FO)
