"""The test-stand method's printed columns, checked row by row and field by field (spec 000 sections 6-8).

Mutation testing (TESTING.md, issue 14) found that only the first two rows of the iteration table (the
paper's print) were compared by value, and that the echo fields of ``StandAnalysis`` were not compared
at all: a mutant that set ``axial_load`` of the result to None survived. Here every row of a converged
table is checked against spec 000's formulas, written again in the test with ``math``:

* eq. (1): F_a,k = C* (cos a0 / cos a_k - 1)^(3/2) sin a_k, and Delta_k = (F_a,k - F_a) / F_a 100 %;
* section 6.1: tan a = tan a0 + xi_a / cos a0, so xi_a = (tan a_k - tan a0) cos a0;
* section 6.3: x_(k+1) = x_k + [(F_a / F_a,k)^(2/3) - 1] / [tan a_k + (2/3) cot a_k + sin a_k / (cos a0 - cos a_k)].
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearinglab import catalog, stand
from bearinglab.units import KGF

B = catalog.get("4-1006095")  # the paper's bearing


def _thrust(alpha, cs, a0):
    return cs * (math.cos(a0) / math.cos(alpha) - 1.0) ** 1.5 * math.sin(alpha)


def _increment(fa, fk, alpha, a0):
    ratio = (fa / fk) ** (2.0 / 3.0) - 1.0
    return ratio / (math.tan(alpha) + (2.0 / 3.0) / math.tan(alpha) + math.sin(alpha) / (math.cos(a0) - math.cos(alpha)))


@settings(max_examples=60, deadline=None)
@given(load=st.floats(0.01, 500.0), cs_kgf=st.floats(1e3, 1e5), a0_deg=st.floats(5.0, 45.0))
def test_every_row_of_the_iteration_table_follows_spec_000(load, cs_kgf, a0_deg):
    fa, cs, a0 = load * KGF, cs_kgf * KGF, math.radians(a0_deg)
    rows = stand.iteration_table(fa, cs, a0)
    assert [r.k for r in rows] == list(range(len(rows)))
    for row, following in zip(rows, rows[1:] + [None]):
        assert row.contact_angle == a0 + row.x
        assert row.axial_load == pytest.approx(_thrust(row.contact_angle, cs, a0), rel=1e-13)
        assert row.error_percent == pytest.approx((row.axial_load - fa) / fa * 100.0, rel=1e-12, abs=1e-13)
        xi_a = (math.tan(row.contact_angle) - math.tan(a0)) * math.cos(a0)
        assert row.axial_displacement_ratio == pytest.approx(xi_a, rel=1e-12, abs=1e-16)
        if following is not None:
            step = _increment(fa, row.axial_load, row.contact_angle, a0)
            if a0 < row.contact_angle + step < math.pi / 2:  # otherwise the step was halved into the domain
                # the increment is a difference of nearly equal terms near convergence: absolute tolerance
                assert following.x - row.x == pytest.approx(step, rel=1e-9, abs=1e-15)
    last = rows[-1]
    assert abs(last.error_percent) < 1e-8
    assert last.contact_angle == pytest.approx(stand.operating_contact_angle(fa, cs, a0), abs=1e-12)


def test_the_table_starts_from_a_given_x0_and_stops_after_max_rows():
    rows = stand.iteration_table(2 * KGF, 7792.357 * KGF, math.radians(12.0), x0=0.05, max_rows=3)
    assert len(rows) == 3
    assert rows[0].x == 0.05


@pytest.mark.parametrize("loads", [2 * KGF, np.array([0.5, 2.0, 20.0]) * KGF])
@pytest.mark.parametrize("hertz", ["exact", "table"])
def test_stand_analysis_echoes_its_inputs_and_derives_every_field(loads, hertz):
    r = stand.stand_analysis(B, loads, hertz=hertz)
    np.testing.assert_array_equal(r.axial_load, loads)
    assert r.free_angle == B.contact_angle
    assert r.hertz == hertz
    alpha = np.atleast_1d(r.contact_angle)
    fa = np.atleast_1d(loads)
    cs = np.broadcast_to(r.constants.force_characteristic, alpha.shape)
    a0 = B.contact_angle
    z = B.n_balls
    for k in range(alpha.size):
        # eq. (1) at the converged angle, with the constants the analysis reports
        assert _thrust(alpha[k], cs[k], a0) == pytest.approx(fa[k], rel=1e-11)
        xi_a = (math.tan(alpha[k]) - math.tan(a0)) * math.cos(a0)
        assert np.atleast_1d(r.axial_displacement_ratio)[k] == pytest.approx(xi_a, rel=1e-12)
        groove = (B.inner_conformity + B.outer_conformity - 1.0) * B.ball_diameter  # xi d, section 3
        assert np.atleast_1d(r.axial_displacement)[k] == pytest.approx(xi_a * groove, rel=1e-12)
        assert np.atleast_1d(r.ball_load)[k] == pytest.approx(fa[k] / (z * math.sin(alpha[k])), rel=1e-14)
    assert np.shape(r.series) == (5,) + np.shape(loads)
    assert np.shape(r.first_approximation) == np.shape(loads)
    if np.ndim(loads) == 0:
        assert r.iterations and r.iterations[-1].contact_angle == pytest.approx(float(r.contact_angle), abs=1e-12)
    else:
        assert r.iterations == []


def _independent_section_newton(fa, cs, a0, alpha, xtol, ftol_percent, max_iter):
    """Spec 000 section 6.3 written again: (alpha, converged, F_a,k/F_a - 1 of the last step or 0).

    A step that leaves (alpha0, 90 deg) is halved toward the boundary it crossed (the library's documented
    guard, ``stand.operating_contact_angle``)."""
    residual = math.nan
    for _ in range(max_iter):
        fk = _thrust(alpha, cs, a0)
        dx = _increment(fa, fk, alpha, a0)
        new = alpha + dx
        if new <= a0:
            new = 0.5 * (alpha + a0)
        if new >= math.pi / 2:
            new = 0.5 * (alpha + math.pi / 2)
        alpha = new
        residual = fk / fa - 1.0
        if abs(dx) < xtol or abs(fa / fk - 1.0) * 100.0 < ftol_percent:
            return alpha, True, 0.0
    return alpha, False, residual


@settings(max_examples=80, deadline=None)
@given(load=st.floats(0.01, 500.0), a0_deg=st.floats(5.0, 45.0), where=st.floats(0.0005, 0.999),
       max_iter=st.integers(0, 6), ftol_percent=st.sampled_from([0.0, 1e-10, 0.5]))
def test_the_newton_of_section_6_3_from_any_start(load, a0_deg, where, max_iter, ftol_percent):
    # The solve's own start passes the load test for every load tried, so the Newton it falls back on is
    # checked here on its own, from starts anywhere in (alpha0, 90 deg): far starts overshoot 90 deg and
    # are halved, few iterations leave cases unconverged with the residual of their last step.
    fa, cs, a0 = load * KGF, 7792.357 * KGF, math.radians(a0_deg)
    start = a0 + where * (math.pi / 2 - a0)
    want = _independent_section_newton(fa, cs, a0, start, 1e-12, ftol_percent, max_iter)
    alpha, ok, residual = stand.method._section_newton(np.array([fa]), cs, a0, math.cos(a0), np.array([start]), 1e-12,
                                                ftol_percent, max_iter)
    assert bool(ok[0]) == want[1]
    # the same iterates up to rounding (pow against cbrt, tan against sin/cos); an iterate still far from the
    # root (not converged) carries that rounding amplified by the steps from near alpha0 (~1e-12 rad seen)
    assert alpha[0] == pytest.approx(want[0], abs=1e-12 if want[1] else 1e-9)
    if want[1]:
        assert residual[0] == 0.0
    elif max_iter == 0:
        assert math.isnan(residual[0])
    else:
        # F_a,k / F_a - 1 amplifies the rounding of the angle by about 1.5 / (alpha - alpha0) near the free
        # angle (a 1e-16 rad difference becomes ~1e-11 at alpha - alpha0 = 1e-5 rad) and by 1.5 tan(alpha)
        # near 90 deg, where a far start is halved to (3e-9 relative seen): hence rel=1e-6, abs=1e-9
        assert residual[0] == pytest.approx(want[2], rel=1e-6, abs=1e-9)


def test_the_newton_of_section_6_3_converges_from_far_starts_to_the_root():
    fa, cs, a0 = 2 * KGF, 7792.357 * KGF, math.radians(12.0)
    starts = a0 + np.array([1e-6, 0.01, 0.3, 0.9, 0.999]) * (math.pi / 2 - a0)
    alpha, ok, residual = stand.method._section_newton(np.full(5, fa), cs, a0, math.cos(a0), starts, 1e-12, 1e-10, 50)
    assert ok.all() and (residual == 0.0).all()
    for a in alpha:
        assert _thrust(a, cs, a0) == pytest.approx(fa, rel=1e-10)


def test_a_converged_case_has_no_residual_next_to_one_that_did_not_converge():
    fa, cs, a0 = 2 * KGF, 7792.357 * KGF, math.radians(12.0)
    root = stand.operating_contact_angle(fa, cs, a0)
    starts = np.array([root, a0 + 0.999 * (math.pi / 2 - a0)])  # at the root; far above it
    _, ok, residual = stand.method._section_newton(np.full(2, fa), cs, a0, math.cos(a0), starts, 1e-12, 1e-10, 2)
    assert ok.tolist() == [True, False]
    assert residual[0] == 0.0
    want = _independent_section_newton(fa, cs, a0, starts[1], 1e-12, 1e-10, 2)
    assert residual[1] == pytest.approx(want[2], rel=1e-9)


def test_the_load_test_of_section_6_3_uses_the_error_in_percent():
    # a start whose load error is just inside ftol_percent converges on that test, one just outside does not
    fa, cs, a0 = 2 * KGF, 7792.357 * KGF, math.radians(12.0)
    start = stand.operating_contact_angle(fa, cs, a0) + 1e-4
    error = abs(fa / _thrust(start, cs, a0) - 1.0) * 100.0
    for ftol, converged in ((error * 1.005, True), (error / 1.005, False)):
        _, ok, _ = stand.method._section_newton(np.array([fa]), cs, a0, math.cos(a0), np.array([start]), 1e-30, ftol, 1)
        assert bool(ok[0]) is converged


@settings(max_examples=200, deadline=None)
@given(load=st.floats(0.01, 500.0), a0_deg=st.floats(1.0, 60.0), where=st.floats(1e-6, 1.0 - 1e-6))
def test_a_newton_step_of_section_6_3_never_falls_below_the_free_angle(load, a0_deg, where):
    # Why the guard against a step below alpha0 never acts (TESTING.md: its mutants are equivalent): a step
    # down has |numerator| = 1 - (F_a/F_a,k)^(2/3) < 1, and the denominator exceeds sin a / (cos a0 - cos a)
    # >= 1 / (a - a0) (sin increases on the interval), so the step is shorter than a - a0.
    fa, cs, a0 = load * KGF, 7792.357 * KGF, math.radians(a0_deg)
    alpha = a0 + where * (math.pi / 2 - a0)
    assert alpha + _increment(fa, _thrust(alpha, cs, a0), alpha, a0) > a0
