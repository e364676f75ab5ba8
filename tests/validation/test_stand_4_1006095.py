"""Spec 000 section 8: every printed number of the worked example (bearing 4-1006095, F_a = 2 kgf).

Printed values and tolerances are read from tests/data/stand_4_1006095.csv (spec 000 section 8); the
tolerances are those of the spec: the printed digits, or the pi = 3.14 artefacts of section 9.9.
"""

import csv
import math
from pathlib import Path

import pytest
from numpy.testing import assert_allclose

from bearinglab import catalog, stand
from bearinglab.units import KGF, to_dms

DATA = Path(__file__).parents[1] / "data" / "stand_4_1006095.csv"
ROWS = {r["quantity"]: r for r in csv.DictReader(line for line in DATA.open() if not line.startswith("#"))}
FA = 2.0 * KGF
A0 = math.radians(12.0)


@pytest.fixture(scope="module")
def table_run():
    return stand.stand_analysis(catalog.get("4-1006095"), FA, hertz="table", elastic_constant="paper")


def _check(name, got, column="printed"):
    row = ROWS[name]
    want, tol = float(row[column]), float(row["tol"])
    if row["kind"] == "rel":
        assert_allclose(got, want, rtol=tol, err_msg=name)
    else:
        assert_allclose(got, want, rtol=0, atol=tol, err_msg=name)


def _seconds(angle):
    d, m, s = to_dms(angle)
    return d * 3600 + m * 60 + s


def test_contact_constants_match_print(table_run):
    c = table_run.constants
    _check("cos_tau_inner", c.curvature_difference_inner)
    _check("cos_tau_outer", c.curvature_difference_outer)
    _check("sum_rho_inner", c.curvature_sum_inner * 1e-3)
    _check("sum_rho_outer", c.curvature_sum_outer * 1e-3)
    _check("c_inner", c.approach_inner_paper)
    _check("c_outer", c.approach_outer_paper)
    _check("force_characteristic", c.force_characteristic_kgf)


def test_contact_constants_match_exact_column(table_run):
    # the spec's independent implementation, to its printed digits (last digit +-1)
    c = table_run.constants
    assert_allclose(c.curvature_difference_inner, 0.928724244, atol=1e-9)
    assert_allclose(c.curvature_difference_outer, 0.711126915, atol=1e-9)
    assert_allclose(c.curvature_sum_inner * 1e-3, 1.336192009, atol=1e-9)
    assert_allclose(c.curvature_sum_outer * 1e-3, 0.954959404, atol=1e-9)
    assert_allclose(c.approach_outer_paper, 0.625796e-4, rtol=2e-6)
    assert_allclose(c.approach_inner_paper, 0.517561e-4, rtol=2e-6)
    assert_allclose(c.force_characteristic_kgf, 7792.357, atol=1e-3)
    # C* in SI with d in mm: 76 417 N (spec 000 section 5.3)
    assert_allclose(c.force_characteristic, 76417, atol=0.5)


def test_series_coefficients_reference(table_run):
    want = [-4.038692e-3, 0.07459799, 0.4253049, 0.4573164, 0.1471544]
    assert_allclose(table_run.series, want, rtol=1e-6)  # the spec prints 7 significant digits


def test_iteration_table_matches_print(table_run):
    rows = table_run.iterations
    _check("x0", rows[0].x)
    _check("xi_a_0", rows[0].axial_displacement_ratio)
    _check("F_1", rows[0].axial_load / KGF)
    _check("delta_0", rows[0].error_percent)
    _check("x1", rows[1].x)
    _check("xi_a_1", rows[1].axial_displacement_ratio)
    _check("F_2", rows[1].axial_load / KGF)
    _check("delta_1", rows[1].error_percent)
    # printed angles 14°29'16" and 14°28'5" use pi = 3.14 (spec 000 section 9.9): tolerance 5"
    assert abs(_seconds(rows[0].contact_angle) - (14 * 3600 + 29 * 60 + 16)) < 5
    assert abs(_seconds(rows[1].contact_angle) - (14 * 3600 + 28 * 60 + 5)) < 5


def test_iteration_table_matches_exact_column(table_run):
    rows = table_run.iterations
    for name, got in (("x0", rows[0].x), ("xi_a_0", rows[0].axial_displacement_ratio), ("F_1", rows[0].axial_load / KGF),
                      ("x1", rows[1].x), ("xi_a_1", rows[1].axial_displacement_ratio), ("F_2", rows[1].axial_load / KGF)):
        want = float(ROWS[name]["exact"])
        assert_allclose(got, want, rtol=1e-6, atol=1e-7, err_msg=name)  # 6-7 digits printed in the spec
    assert abs(_seconds(rows[0].contact_angle) - (14 * 3600 + 29 * 60 + 11.99)) < 0.01
    assert abs(_seconds(rows[1].contact_angle) - (14 * 3600 + 28 * 60 + 3.48)) < 0.01


def test_converged_angle(table_run):
    assert_allclose(table_run.contact_angle - A0, 0.0430678, atol=1e-7)
    assert abs(_seconds(table_run.contact_angle) - (14 * 3600 + 28 * 60 + 3.38)) < 0.01
    assert_allclose(math.degrees(table_run.contact_angle - A0), 2.468, atol=5e-4)  # "about 2.5 deg above nominal"
    last = table_run.iterations[-1]
    assert abs(last.axial_load - FA) / FA < 1e-12


def test_exact_hertz_column():
    # spec 000's exact column holds the exact coefficients at alpha0, like the table ones
    r = stand.stand_analysis(catalog.get("4-1006095"), FA, hertz="exact", elastic_constant="paper", stiffness_at="free")
    c = r.constants
    assert_allclose(c.approach_outer_paper, 0.626130e-4, rtol=2e-6)
    assert_allclose(c.approach_inner_paper, 0.516201e-4, rtol=2e-6)
    assert_allclose(c.force_characteristic_kgf, 7802.86, atol=0.01)
    assert_allclose(r.first_approximation, 0.0433680, atol=1e-7)
    assert_allclose(r.iterations[1].x, 0.0430364, atol=1e-7)
    assert abs(_seconds(r.contact_angle) - (14 * 3600 + 27 * 60 + 56.81)) < 0.01
    # 6.6 arc seconds below the value obtained with the table coefficients
    t = stand.stand_analysis(catalog.get("4-1006095"), FA, hertz="table", elastic_constant="paper")
    assert_allclose(_seconds(t.contact_angle) - _seconds(r.contact_angle), 6.6, atol=0.05)


def test_legacy_mode_reproduces_printed_rounding():
    cs = stand.stand_constants(7, 2e-3, 8.7355e-3, 0.525, 0.58, A0, delta_star_inner=0.63,
                                delta_star_outer=0.852, elastic_constant="paper").force_characteristic
    rows = stand.iteration_table(FA, cs, A0, x0=0.0433985, reproduce_print=True, max_rows=2)
    assert_allclose(rows[1].x, 0.0430573, atol=1e-7)
    assert to_dms(rows[0].contact_angle, truncate=True) == (14, 29, 16.0)
    assert to_dms(rows[1].contact_angle, truncate=True) == (14, 28, 5.0)
    assert_allclose(rows[0].axial_displacement_ratio, 0.0448325, atol=2e-7)
    assert_allclose(rows[1].axial_displacement_ratio, 0.0444763, atol=2e-7)
    # F at the pi = 3.14 angles: 2.02994 (printed truncated "2.029") and 2.00095 (printed rounded "2.001")
    assert math.floor(rows[0].axial_load / KGF * 1000) == 2029
    assert round(rows[1].axial_load / KGF, 3) == 2.001
    assert_allclose(rows[0].error_percent, 1.45, atol=1e-9)  # from the three-decimal 2.029


def test_clearance_of_the_example_and_the_052_shortcut():
    b = catalog.get("4-1006095")
    assert_allclose(b.radial_clearance * 1e6, 9.178, atol=5e-4)
    assert_allclose(math.degrees(b.free_contact_angle_052()), 19.50, atol=5e-3)


def test_minimum_stand_load_of_the_example():
    b = catalog.get("4-1006095")
    n = [3000 * math.pi / 30, 10000 * math.pi / 30]
    got = stand.min_axial_load(n, b.n_balls, b.ball_diameter, b.pitch_diameter, b.contact_angle)
    # F_min = 1.1549e-10 n^2 kgf: 1.04e-3 kgf at 3000 rpm, 1.15e-2 kgf at 10 000 rpm
    assert_allclose(got.minimum / KGF, [1.1549e-10 * 3000**2, 1.1549e-10 * 10000**2], rtol=1e-4)
    assert_allclose(got.maximum, 1.2 * got.minimum, rtol=1e-15)
