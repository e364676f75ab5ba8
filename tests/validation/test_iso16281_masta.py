"""ISO/TS 16281 reference rating life against MASTA (cases of github.com/minzhun/ISO16281).

The per-ball loads come from a small rigid-ring solver written here, independently of the library:
Hertz point contact with the exact ellipticity (scipy's elliptic integrals, a root find of its own),
pure radial load (load line through the first ball, rings axially centred) or pure axial load, one
degree of freedom each, solved with scipy's brentq. The stiffness is evaluated at the nominal contact
angle, as MASTA's results imply (its deflections are matched to 0.05 % this way). The solver is checked
against MASTA's deflections (0.2 %) before its ball loads enter ``ratings.reference_rating_life``.
"""

import csv
import math
from pathlib import Path

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk

from bearinglab import ratings
from bearinglab.life import rating_life

DATA = Path(__file__).resolve().parent.parent / "data" / "masta_iso16281.csv"
CASES = list(csv.DictReader(line for line in DATA.read_text(encoding="utf-8").splitlines()
                            if not line.startswith("#")))

Z, DW, DPW, FI, FE = 7, 11.5, 43.5, 0.52, 0.53  # mm
E, NU, C = 210000.0, 0.3, 23400.0  # N/mm^2, -, N


def _contact_compliance(sum_rho, f_rho):
    """delta = c Q^(2/3) [mm, N] of one Hertz point contact (Harris & Kotzalas, ch. 6)."""
    def residual(k):
        m = 1.0 - 1.0 / k**2
        return 1.0 - 2.0 / (k**2 - 1.0) * (ellipk(m) / ellipe(m) - 1.0) - f_rho

    k = brentq(residual, 1.0 + 1e-9, 50.0, xtol=1e-15)
    m = 1.0 - 1.0 / k**2
    delta_star = 2.0 * ellipk(m) / math.pi * (math.pi / (2.0 * k**2 * ellipe(m))) ** (1 / 3)
    e_red = E / (1.0 - NU**2)
    return delta_star * (3.0 / (sum_rho * e_red)) ** (2 / 3) * sum_rho / 2.0


def _ball_stiffness():
    """K of Q = K delta^1.5 for the ball between both raceways, at alpha = 0. [N/mm^1.5]"""
    g = DW / DPW
    compliance = 0.0
    for f, term in ((FI, 2 * g / (1 - g)), (FE, -2 * g / (1 + g))):
        total = 4.0 - 1.0 / f + term
        compliance += _contact_compliance(total / DW, (1.0 / f + term) / total)
    return compliance**-1.5


def _ball_loads(direction, load, clearance_mm):
    """Ball loads [N] and the deflection [mm] of the rigid rings under pure Fx or pure Fz."""
    k = _ball_stiffness()
    a = (FI + FE - 1.0) * DW
    phi = 2 * np.pi * np.arange(Z) / Z
    if direction == "x":
        def loads(d):
            return k * np.maximum(d * np.cos(phi) - clearance_mm / 2, 0.0) ** 1.5

        d = brentq(lambda d: np.sum(loads(d) * np.cos(phi)) - load, clearance_mm / 2, 1.0, xtol=1e-14)
        return loads(d), d
    a0 = a - clearance_mm / 2  # groove-centre distance at the centred position

    def axial(d):
        approach = math.hypot(a0, d) - a
        return Z * k * max(approach, 0.0) ** 1.5 * d / math.hypot(a0, d)

    lo = math.sqrt(max(a**2 - a0**2, 0.0))
    d = brentq(lambda d: axial(d) - load, lo, 2.0, xtol=1e-14)
    return np.full(Z, k * (math.hypot(a0, d) - a) ** 1.5), d


@pytest.mark.parametrize("row", CASES, ids=[f"case{r['case']}" for r in CASES])
def test_reference_life_matches_masta(row):
    q, deflection = _ball_loads(row["direction"], float(row["load"]), float(row["radial_clearance"]) * 1e-3)
    # the test solver first: MASTA's deflection, printed to 5-6 digits (21.223 um: 2.4e-5); the issue
    # asks for 0.2 %, the solver agrees to 1e-5
    assert deflection * 1e3 == pytest.approx(float(row["deflection"]), rel=1e-4)
    life = ratings.reference_rating_life(q, C, DW * 1e-3, DPW * 1e-3, FI, FE, 0.0)
    # the acceptance band is 1 %; the lives agree to 7e-5 (case 3), above the 8 printed digits
    # because the test solver's loads differ from MASTA's by its 1e-5 in deflection, so 1e-4 here
    assert life / 1e6 == pytest.approx(float(row["l10r"]), rel=1e-4)


def test_batch_of_cases_in_one_call():
    rows = [_ball_loads(r["direction"], float(r["load"]), float(r["radial_clearance"]) * 1e-3)[0] for r in CASES]
    batch = ratings.reference_rating_life(np.array(rows), C, DW * 1e-3, DPW * 1e-3, FI, FE)
    one_by_one = [ratings.reference_rating_life(r, C, DW * 1e-3, DPW * 1e-3, FI, FE) for r in rows]
    assert_allclose(batch, one_by_one, rtol=1e-15)


def test_reference_life_through_the_library_combined_model():
    """The same cases through the library: ``bearinglab.life.rating_life`` takes the ball loads from the combined
    model (:mod:`bearinglab.quasistatic.combined`) by default."""
    import warnings

    from bearinglab.bearing import BallBearing, Material

    steel = Material("MASTA steel", E * 1e6, NU, 7850.0)
    for row in CASES:
        e = float(row["radial_clearance"]) * 1e-6
        b = BallBearing(Z, DW * 1e-3, DPW * 1e-3, FI, FE, contact_angle=None if e else 0.0, radial_clearance=e or None,
                        type="radial", dynamic_load_rating=C, ball_material=steel, ring_material=steel)
        load = [float(row["load"]), 0, 0, 0, 0] if row["direction"] == "x" else [0, 0, float(row["load"]), 0, 0]
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ratings.RatingWarning)
            r = rating_life(b, load, 100.0, kinematic_viscosity=20e-6)
        # the acceptance band is 1 %; the combined model agrees to 6e-5
        assert r.reference_rating_life / 1e6 == pytest.approx(float(row["l10r"]), rel=0.01), row["case"]
