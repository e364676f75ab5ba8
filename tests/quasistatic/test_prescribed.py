"""Issue 20 item 18: prescribed displacements in the five-degree-of-freedom load distribution.

Each freedom is given either as a load or as a displacement; the result reports the reaction on every
held one. The textbook combined-load case (Sjovall's integrals, Harris, NSK) holds the ring square:

    delta_psi = delta_a sin(alpha) + delta_r cos(alpha) cos(psi) = delta_max (1 - (1 - cos psi) / (2 eps)),
    eps = (1 + delta_a tan(alpha) / delta_r) / 2,
    F_r = Z Q_max J_r(eps) cos(alpha),    F_a = Z Q_max J_a(eps) sin(alpha),
    J_r = 1/(2 pi) int Q/Q_max cos(psi) dpsi,    J_a = 1/(2 pi) int Q/Q_max dpsi,    Q/Q_max = (delta/delta_max)^1.5

(rigid rings, constant contact angle, point contact, balls spread evenly: the integrals are the limit of
many balls). The integrals are computed here with ``scipy.integrate.quad``, independently of the code.
Published values: at eps = 0.5 NSK (Technical report / catalogue E728g, section 5 "Bearing internal load
distribution and displacement", eqs. (4) and the text before it) gives Q_max = 4.37 F_r / (Z cos alpha)
and F_a = 1.216 F_r tan(alpha) for point contact, i.e. J_r = 1/4.37 = 0.2288 and J_a / J_r = 1.216. At
eps = 1 the integrals have a closed form (below). (Harris's table of J_r, J_a for point contact, which
also lists eps = 2.5, could not be retrieved to cite; eps = 2.5 is checked against the quadrature.)

The model is the full nonlinear one, so it matches the integrals in the limit of small deflections
(delta / A -> 0, contact angle constant) and many balls; a hypothetical bearing with Z = 360 balls of
2 mm on a 300 mm pitch circle and deflections of about 1e-4 A keeps both errors near 1e-4.
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose
from scipy.integrate import quad

from bearinglab import catalog, hertz
from bearinglab.errors import InputError
from bearinglab.quasistatic import combined
from bearinglab.units import RPM

NAN = np.nan
# hypothetical bearing (not a catalogue one): many small balls, so the ball sums approach the integrals
Z, D, DM, FI, FO, ALPHA0 = 360, 2e-3, 300e-3, 0.52, 0.52, math.radians(40.0)
EP = hertz.reduced_modulus(208e9, 0.3, 208e9, 0.3)
BIG_A = (FI + FO - 1.0) * D
ARGS = (Z, D, DM, FI, FO, ALPHA0, EP, 7850.0)


def sjovall(eps):
    """J_r(eps), J_a(eps) of point contact by quadrature of the load-distribution integrals."""
    half = math.acos(1.0 - 2.0 * eps) if eps < 1.0 else math.pi  # load zone -psi_l .. psi_l

    def ratio(psi):
        return max(1.0 - (1.0 - math.cos(psi)) / (2.0 * eps), 0.0) ** 1.5

    jr = quad(lambda p: ratio(p) * math.cos(p), -half, half, limit=200)[0] / (2.0 * math.pi)
    ja = quad(ratio, -half, half, limit=200)[0] / (2.0 * math.pi)
    return jr, ja


def test_quadrature_against_the_published_and_closed_form_values():
    jr, ja = sjovall(0.5)
    assert 1.0 / jr == pytest.approx(4.37, abs=0.005)  # NSK: Q_max = 4.37 F_r / (Z cos alpha)
    assert ja / jr == pytest.approx(1.216, abs=0.0005)  # NSK: F_a = 1.216 F_r tan(alpha)
    # eps = 1: delta/delta_max = (1 + cos psi)/2 = cos^2(psi/2) over the whole circle, so with u = psi/2
    # J_a = (1/pi) int cos^3 u du = 4/(3 pi) and J_r = (1/pi) int cos^3 u (2 cos^2 u - 1) du = 4/(5 pi)
    jr, ja = sjovall(1.0)
    assert jr == pytest.approx(4.0 / (5.0 * math.pi), rel=1e-10)
    assert ja == pytest.approx(4.0 / (3.0 * math.pi), rel=1e-10)


def _held_square(eps, delta_r=1e-9):
    """Every freedom held: delta_r along x, delta_z = A sin(alpha0) + delta_a (delta_z counts from the
    concentric position, Sjovall's delta_a from first contact), no tilt."""
    delta_a = (2.0 * eps - 1.0) * delta_r / math.tan(ALPHA0)
    u = [delta_r, 0.0, BIG_A * math.sin(ALPHA0) + delta_a, 0.0, 0.0]
    return u, combined.load_distribution(np.zeros(5), 0.0, *ARGS, stiffness_at="free", prescribed_displacement=u)


@pytest.mark.parametrize("eps", [0.5, 1.0, 2.5])
def test_reactions_at_a_held_displacement_are_sjovalls_integrals(eps):
    u, r = _held_square(eps)
    assert r.converged and r.iterations == 0  # nothing to solve: every freedom is held
    assert_allclose(r.displacement, u, rtol=0, atol=0)
    fr, fa = r.reactions[0], r.reactions[2]
    qmax = r.max_ball_load
    jr, ja = sjovall(eps)
    assert fr / (Z * qmax * math.cos(ALPHA0)) == pytest.approx(jr, rel=2e-4)  # delta/A ~ 1e-5: errors ~ 7e-5
    assert fa / (Z * qmax * math.sin(ALPHA0)) == pytest.approx(ja, rel=2e-4)
    assert r.reactions[3] == pytest.approx(0.0, abs=1e-9 * fr * DM)  # symmetric about the x axis
    assert r.reactions[4] != 0.0  # holding the ring square takes a moment (the free ring would tilt)
    assert_allclose(r.loads, r.reactions, rtol=0, atol=0)  # all held: the loads are the reactions


@pytest.mark.parametrize("eps", [0.5, 1.0, 2.5])
def test_ring_held_square_under_given_loads_reaches_sjovalls_state(eps):
    """F_r and F_a = F_r tan(alpha) J_a/J_r given, tilts held at 0: the solved displacement has the load
    zone eps and the largest ball load F_r / (Z J_r cos alpha)."""
    jr, ja = sjovall(eps)
    fr = 0.02  # deflections of about 1 nm (1e-5 A), as above
    fa = fr * math.tan(ALPHA0) * ja / jr
    r = combined.load_distribution([fr, 0.0, fa, 0.0, 0.0], 0.0, *ARGS, stiffness_at="free",
                                   prescribed_displacement=[NAN, NAN, NAN, 0.0, 0.0])
    assert r.converged
    dr, da = r.displacement[0], r.displacement[2] - BIG_A * math.sin(ALPHA0)
    assert (1.0 + da * math.tan(ALPHA0) / dr) / 2.0 == pytest.approx(eps, rel=3e-4)
    assert r.max_ball_load == pytest.approx(fr / (Z * jr * math.cos(ALPHA0)), rel=1e-4)
    assert r.displacement[3] == 0.0 and r.displacement[4] == 0.0
    assert np.isnan(r.reactions[:3]).all() and r.reactions[4] == r.loads[4]


B218 = catalog.get("B218")


def test_b218_free_ring_tilts_and_the_held_ring_takes_a_moment():
    """B218 at F_r = 5 kN, F_a = 10 kN: the free inner ring tilts by about 3 mrad (issue 20); held square it
    does not, and the reaction moment is what equilibrium() needs at that displacement."""
    free = combined.combined_analysis(B218, [5e3, 0, 10e3, 0, 0])
    assert free.displacement[4] == pytest.approx(3.0e-3, rel=0.05) and np.isnan(free.reactions).all()
    held = combined.combined_analysis(B218, [5e3, 0, 10e3, 0, 0], prescribed_displacement=[NAN, NAN, NAN, 0, 0])
    assert held.displacement[3] == 0.0 and held.displacement[4] == 0.0
    eq = combined.equilibrium(held.displacement, held.loads, 0.0, *combined._bearing_args(B218))
    scale = np.array([1, 1, 1, 2 / B218.pitch_diameter, 2 / B218.pitch_diameter])
    assert np.max(np.abs(eq.residual * scale)) <= 1e-11 * 10e3
    assert_allclose(eq.reaction[3:], held.reactions[3:], rtol=1e-9, atol=1e-9)
    assert held.loads[4] == held.reactions[4] and held.loads[0] == 5e3 and held.loads[2] == 10e3


def test_prescribed_axial_displacement_returns_the_thrust_that_gives_it():
    """Round trip: the delta_z a thrust gives, prescribed, gives the thrust back as the reaction."""
    loads = np.array([[5e3, 0, 10e3, 0, 0], [2e3, 1e3, 4e3, 30.0, -20.0]])
    ref = combined.combined_analysis(B218, loads)
    held = np.full((2, 5), NAN)
    held[:, 2] = ref.displacement[:, 2]
    given = loads.copy()
    given[:, 2] = 0.0
    r = combined.combined_analysis(B218, given, prescribed_displacement=held)
    assert_allclose(r.reactions[:, 2], loads[:, 2], rtol=1e-8)
    assert_allclose(r.displacement, ref.displacement, rtol=1e-7, atol=1e-13)


@pytest.mark.parametrize("engine", ["numpy", "auto"])
def test_batch_at_speed_and_per_case_patterns_equal_single_cases(engine):
    """The vectorized path and the compiled one: cases with different held freedoms and speeds in one batch
    equal each case solved alone, bit for bit."""
    loads = np.array([[5e3, 0, 10e3, 0, 0], [5e3, 0, 0, 0, 0], [3e3, 0, 8e3, 0, 0]])
    held = np.array([[NAN, NAN, NAN, 0, 0], [NAN, NAN, 7.0e-4, 0, 0], [NAN] * 5])
    w = np.array([0.0, 6000 * RPM, 12000 * RPM])
    batch = combined.combined_analysis(B218, loads, w, prescribed_displacement=held, engine=engine)
    assert batch.converged.all()
    for k in range(3):
        one = combined.combined_analysis(B218, loads[k], w[k], prescribed_displacement=held[k], engine=engine)
        assert np.array_equal(one.displacement, batch.displacement[k])
        assert np.array_equal(one.reactions, batch.reactions[k], equal_nan=True)
    assert batch.displacement[1, 2] == 7.0e-4 and batch.reactions[1, 2] > 0


def test_nothing_held_is_the_plain_solve_bit_for_bit():
    loads = [[5e3, 0, 10e3, 0, 0], [1e3, 2e3, 3e3, 40.0, 0.0]]
    plain = combined.combined_analysis(B218, loads)
    nan = combined.combined_analysis(B218, loads, prescribed_displacement=[NAN] * 5)
    assert np.array_equal(plain.displacement, nan.displacement)
    assert np.isnan(nan.reactions).all() and nan.reactions.shape == (2, 5)


def test_a_freedom_with_both_a_load_and_a_displacement_is_refused():
    with pytest.raises(InputError, match="F_z = 10000 .* prescribed"):
        combined.combined_analysis(B218, [5e3, 0, 10e3, 0, 0], prescribed_displacement=[NAN, NAN, 7e-4, NAN, NAN])
    with pytest.raises(InputError, match="last axis of length 5"):
        combined.combined_analysis(B218, [5e3, 0, 10e3, 0, 0], prescribed_displacement=[0.0, 0.0])
    with pytest.raises(InputError, match="finite or NaN"):
        combined.combined_analysis(B218, [5e3, 0, 10e3, 0, 0], prescribed_displacement=[NAN, NAN, NAN, np.inf, 0])


@settings(max_examples=20, deadline=None)
@given(fx=st.floats(-8e3, 8e3), fy=st.floats(-8e3, 8e3), fz=st.floats(2e3, 20e3), mx=st.floats(-200.0, 200.0),
       my=st.floats(-200.0, 200.0), mask=st.lists(st.booleans(), min_size=5, max_size=5))
def test_holding_the_free_solution_gives_its_loads_back(fx, fy, fz, mx, my, mask):
    """Invariant: solve under five loads, then hold any subset of freedoms at the displacement found; the
    solution is the same and the reactions on the held freedoms are the loads that were there."""
    loads = np.array([fx, fy, fz, mx, my])
    ref = combined.combined_analysis(B218, loads)
    held = np.where(mask, ref.displacement, NAN)
    r = combined.combined_analysis(B218, np.where(mask, 0.0, loads), prescribed_displacement=held)
    scale = np.array([1, 1, 1, 2 / B218.pitch_diameter, 2 / B218.pitch_diameter])
    total = np.sum(ref.ball_load_inner)
    assert np.all(np.abs((r.loads - loads) * scale) <= 1e-8 * total)
    assert_allclose(r.displacement[~np.array(mask)], ref.displacement[~np.array(mask)], rtol=1e-6, atol=1e-12)


@pytest.mark.parametrize(("held", "words"), [
    ([NAN, NAN, 2.0, NAN, NAN], r"delta_z = 2000 mm moves the rings by more than one ball diameter \(D = 22.23"),
    ([NAN, NAN, NAN, math.radians(95), NAN], r"theta_x = 1658.06 mrad .* at most 354.828 mrad"),
    ([NAN, NAN, 1e300, NAN, NAN], "delta_z"),
])
def test_a_displacement_beyond_one_ball_diameter_is_refused(held, words):
    """No load moves a groove centre through a ball: B218 (D = 22.23 mm, d_m/2 = 62.65 mm, so a tilt of
    at most 22.23 / 62.65 = 0.3548 rad)."""
    with pytest.raises(InputError, match=words):
        combined.combined_analysis(B218, [1e3, 0, 0, 0, 0], prescribed_displacement=held)
