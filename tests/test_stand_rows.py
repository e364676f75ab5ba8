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
