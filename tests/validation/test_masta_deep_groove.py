"""Issue 11 section 7: the combined-load model against MASTA for a deep-groove ball bearing.

The MASTA results (tests/data/masta_deep_groove.csv) are quoted by the public ISO/TS 16281 code
minzhun/ISO16281 for Z = 7, D_w = 11.5 mm, D_pw = 43.5 mm, f_i = 0.52, f_e = 0.53, alpha = 0, steel with
E = 210 GPa, nu = 0.3. Cases 1-4 (radial or axial load, with and without clearance) are the issue's; cases
5-7 add thrust with radial load and a moment perpendicular to it. Tolerance 0.2 % (the issue's); the model
agrees to better than 0.01 % with either Hertz convention (constants at the operating or the free angle).
"""

import csv
import math
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import root

from bearinglab import geometry, hertz
from bearinglab.bearing import BallBearing, Material
from bearinglab.quasistatic import combined

DATA = Path(__file__).parents[1] / "data" / "masta_deep_groove.csv"
STEEL_210 = Material("steel (E = 210 GPa)", 210e9, 0.3, 7850.0)


def _rows():
    with DATA.open() as fh:
        return list(csv.DictReader(line for line in fh if not line.startswith("#")))


ROWS = _rows()


def masta_bearing(clearance):
    """The MASTA example bearing with a diametral clearance [m] (0: alpha0 = 0)."""
    extra = {"radial_clearance": clearance} if clearance > 0 else {"contact_angle": 0.0}
    return BallBearing(n_balls=7, ball_diameter=11.5e-3, pitch_diameter=43.5e-3, inner_conformity=0.52,
                       outer_conformity=0.53, type="radial", ball_material=STEEL_210, ring_material=STEEL_210,
                       **extra)


@pytest.mark.parametrize("stiffness_at", ["operating", "free"])
@pytest.mark.parametrize("row", ROWS, ids=[f"case{r['case']}" for r in ROWS])
def test_masta_deep_groove(row, stiffness_at):
    b = masta_bearing(float(row["clearance_um"]) * 1e-6)
    loads = [float(row[k]) for k in ("Fx", "Fy", "Fz", "Mx", "My")]
    r = combined.combined_analysis(b, loads, stiffness_at=stiffness_at)
    u = r.displacement
    got = {"radial_um": math.hypot(u[0], u[1]) * 1e6, "axial_um": abs(u[2]) * 1e6,
           "tilt_mrad": math.hypot(u[3], u[4]) * 1e3, "max_ball_load_N": r.max_ball_load}
    checked = 0
    for key, value in got.items():
        if row[key]:
            assert value == pytest.approx(float(row[key]), rel=2e-3), (key, value, row[key])  # issue 11: 0.2 %
            checked += 1
    assert checked >= 1
    assert r.converged and r.residual <= 1e-9


def test_masta_cases_agree_to_a_hundredth_of_a_percent():
    """Tighter than the issue asks: with the Hertz constants at the free angle (ISO/TS 16281), every quoted
    displacement agrees to 1e-4 relative (the quoted digits are 5-6 significant)."""
    for row in ROWS:
        b = masta_bearing(float(row["clearance_um"]) * 1e-6)
        u = combined.combined_analysis(b, [float(row[k]) for k in ("Fx", "Fy", "Fz", "Mx", "My")],
                                       stiffness_at="free").displacement
        for key, value in (("radial_um", math.hypot(u[0], u[1]) * 1e6), ("axial_um", u[2] * 1e6),
                           ("tilt_mrad", math.hypot(u[3], u[4]) * 1e3)):
            if row[key]:
                assert value == pytest.approx(float(row[key]), rel=1e-4), (row["case"], key)


# ---------------------------------------------------------------- own combined cases, independent check
def _independent(bearing, loads, start):
    """The same equations written out separately: per-ball Hertz springs between the groove-curvature
    centres, exact Hertz constants at each ball's angle, five equilibrium sums; scipy root per case."""
    z, d, dm = bearing.n_balls, bearing.ball_diameter, bearing.pitch_diameter
    big_a = (bearing.inner_conformity + bearing.outer_conformity - 1.0) * d
    a0 = bearing.contact_angle
    ep = hertz.reduced_modulus(210e9, 0.3, 210e9, 0.3)
    psi = 2.0 * np.pi * np.arange(z) / z

    def ball_loads(u):
        dx, dy, dz, tx, ty = u
        radial = big_a * math.cos(a0) + dx * np.cos(psi) + dy * np.sin(psi)
        axial = dz + dm / 2.0 * (tx * np.sin(psi) - ty * np.cos(psi))
        alpha = np.arctan2(axial, radial)
        ks = []
        for race, f in (("inner", bearing.inner_conformity), ("outer", bearing.outer_conformity)):
            c = geometry.raceway_curvature(d, dm, f, alpha, race=race)
            ks.append(hertz.load_deflection_constant(c.curvature_sum, c.curvature_difference, ep))
        kn = (ks[0] ** (-2 / 3) + ks[1] ** (-2 / 3)) ** -1.5
        return kn * np.maximum(np.hypot(radial, axial) - big_a, 0.0) ** 1.5, alpha

    def equations(v):
        u = v * np.array([1e-6, 1e-6, 1e-6, 1e-3, 1e-3])  # um and mrad
        q, alpha = ball_loads(u)
        sums = np.array([np.sum(q * np.cos(alpha) * np.cos(psi)), np.sum(q * np.cos(alpha) * np.sin(psi)),
                         np.sum(q * np.sin(alpha)), dm / 2 * np.sum(q * np.sin(alpha) * np.sin(psi)),
                         -dm / 2 * np.sum(q * np.sin(alpha) * np.cos(psi))])
        return (sums - np.asarray(loads)) / 1000.0

    sol = root(equations, start / np.array([1e-6, 1e-6, 1e-6, 1e-3, 1e-3]), method="hybr", tol=1e-14)
    for _ in range(3):  # hybr can stop at machine precision on "xtol too small" (it depends on the last bit
        if sol.success:  # of the start): restarting from its last point lets it confirm the root
            break
        sol = root(equations, sol.x, method="hybr", tol=1e-14)
    assert sol.success, sol.message
    u = sol.x * np.array([1e-6, 1e-6, 1e-6, 1e-3, 1e-3])
    return u, ball_loads(u)[0]


OWN_CASES = [  # clearance [m], loads (F_x, F_y, F_z [N], M_x, M_y [N m])
    (0.0, (1500.0, 0.0, 800.0, 0.0, 4.0)),  # moment in the plane of the radial load
    (0.0, (1500.0, 0.0, 800.0, 4.0, 0.0)),  # moment perpendicular to it
    (10e-6, (-700.0, 1200.0, -500.0, -3.0, 2.0)),  # everything at once, negative thrust (other shoulder)
    (20e-6, (2000.0, 500.0, 300.0, 0.0, -6.0)),
]


@pytest.mark.parametrize(("clearance", "loads"), OWN_CASES)
def test_combined_force_and_moment_against_an_independent_root(clearance, loads):
    b = masta_bearing(clearance)
    r = combined.combined_analysis(b, loads)
    u_ref, q_ref = _independent(b, loads, 1.1 * r.displacement)
    scale = np.array([1e-6, 1e-6, 1e-6, 1e-3, 1e-3])  # compare in um and mrad
    assert np.allclose(r.displacement / scale, u_ref / scale, rtol=1e-8, atol=1e-8)
    assert np.allclose(r.ball_load_inner, q_ref, rtol=1e-8, atol=1e-6)
