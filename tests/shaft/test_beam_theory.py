"""Closed forms of beam theory, each written here from the textbook, against the shaft solve.

Deflections with the shear term of Timoshenko's beam (the unit-load method: the bending integral plus
the shear integral V v / (kappa G A)), reactions of a continuous shaft by compatibility, and the natural
frequencies of a simply supported uniform shaft from Timoshenko's frequency equation, at rest and
spinning. The finite elements are exact at the nodes for point loads and for the consistent load of a
uniform weight, so the statics agree to rounding; the frequencies converge with the mesh, and their
tolerances say how far.
"""

import math

import numpy as np
import pytest

from bearinglab import shaft
from bearinglab.bearing import Material
from bearinglab.shaft import elements

E, NU, RHO = 2.1e11, 0.3, 7850.0
STEEL = Material("steel", E, NU, RHO)
G = E / (2 * (1 + NU))


def _props(d, bore=0.0):
    p = elements.section_properties(d, bore)
    kga = elements.shear_coefficient(NU, d, bore) * G * p.area
    return E * p.second_moment, kga, p


def _system(length, d, supports, **kw):
    return shaft.ShaftSystem(shaft.Shaft((shaft.Section(length, d),), STEEL), supports, **kw)


def _uy(state, z):
    i = int(np.argmin(np.abs(state.assembly.mesh.z - z)))
    assert abs(state.assembly.mesh.z[i] - z) < 1e-12
    return state.displacement[0, i, 1]


@pytest.mark.parametrize("a_frac", [0.5, 0.3])
@pytest.mark.parametrize("d", [0.02, 0.2])  # slender (L/d = 50) and short (L/d = 5): the shear term
def test_simply_supported_shaft_under_a_point_load(a_frac, d):
    L, P = 1.0, -2000.0
    a, b = a_frac * L, (1 - a_frac) * L
    ei, kga, _ = _props(d)
    s = _system(L, d, (shaft.RigidSupport("A", 0.0, axial=True), shaft.RigidSupport("B", L)),
                loads=(shaft.PointLoad(a, fy=P),), elements=7)
    r = shaft.solve(s)
    # Timoshenko: P a^2 b^2 / (3 EI L) bending + P a b / (kappa G A L) shear, at the load
    expected = P * a * a * b * b / (3 * ei * L) + P * a * b / (kga * L)
    assert _uy(r, a) == pytest.approx(expected, rel=1e-10)
    np.testing.assert_allclose(r.support_loads[0, :, 1], [P * b / L, P * a / L], rtol=1e-12)


def test_the_shear_term_of_a_short_shaft_is_there():
    # L/d = 2: the shear deflection is 35 % of the whole; Euler-Bernoulli's alone would be that far off
    L, d, P = 0.1, 0.05, 1e4
    ei, kga, _ = _props(d)
    s = _system(L, d, (shaft.RigidSupport("A", 0.0, axial=True), shaft.RigidSupport("B", L)),
                loads=(shaft.PointLoad(L / 2, fy=P),))
    got = _uy(shaft.solve(s), L / 2)
    bending, shearing = P * L**3 / (48 * ei), P * L / (4 * kga)
    assert got == pytest.approx(bending + shearing, rel=1e-10)
    assert 0.34 < shearing / (bending + shearing) < 0.36


def test_overhung_shaft_tip_deflection():
    # supports at 0 and a, a load P at the free end a + b
    a, b, d, P = 0.4, 0.15, 0.03, 500.0
    ei, kga, _ = _props(d)
    s = _system(a + b, d, (shaft.RigidSupport("A", 0.0, axial=True), shaft.RigidSupport("B", a)),
                loads=(shaft.PointLoad(a + b, fx=P),), elements=5)
    r = shaft.solve(s)
    expected = P * b * b * (a + b) / (3 * ei) + P * b * (a + b) / (a * kga)
    assert r.displacement[0, -1, 0] == pytest.approx(expected, rel=1e-10)
    np.testing.assert_allclose(r.support_loads[0, :, 0], [-P * b / a, P * (a + b) / a], rtol=1e-12)


def test_simply_supported_shaft_on_springs():
    L, d, P, k1, k2 = 0.8, 0.04, 3000.0, 5e7, 2e7
    c = 0.3
    ei, kga, _ = _props(d)
    s = _system(L, d, (shaft.LinearSupport("A", 0.0, k1, axial_stiffness=1e9), shaft.LinearSupport("B", L, k2)),
                loads=(shaft.PointLoad(c, fy=P),), elements=3)
    r1, r2 = P * (L - c) / L, P * c / L
    rigid = r1 / k1 * (1 - c / L) + r2 / k2 * (c / L)
    beam = P * c * c * (L - c) ** 2 / (3 * ei * L) + P * c * (L - c) / (kga * L)
    got = shaft.solve(s)
    assert _uy(got, c) == pytest.approx(rigid + beam, rel=1e-10)
    np.testing.assert_allclose(got.support_loads[0, :, 1], [r1, r2], rtol=1e-12)


def test_continuous_shaft_on_three_supports_under_its_weight():
    # two equal spans l, uniform weight q: the middle reaction R from w_q(mid) = w_R(mid) on the span 2 l,
    # with the shear terms: 5 q (2l)^4/(384 EI) + q (2l)^2/(8 kGA) = R ((2l)^3/(48 EI) + 2l/(4 kGA))
    l, d = 0.5, 0.03
    ei, kga, p = _props(d)
    q = RHO * p.area * 9.80665
    s = _system(2 * l, d, (shaft.RigidSupport("A", 0.0, axial=True), shaft.RigidSupport("B", l),
                           shaft.RigidSupport("C", 2 * l)), gravity=(0.0, -9.80665, 0.0), elements=20)
    r = shaft.solve(s)
    big = 2 * l
    mid = (5 * q * big**4 / (384 * ei) + q * big**2 / (8 * kga)) / (big**3 / (48 * ei) + big / (4 * kga))
    end = (q * big - mid) / 2
    np.testing.assert_allclose(-r.support_loads[0, :, 1], [end, mid, end], rtol=1e-10)
    # without the shear terms, the textbook's 5/4 q l (Euler-Bernoulli): 0.06 % away for this slender shaft
    assert mid == pytest.approx(1.25 * q * l, rel=1e-3)


def test_continuous_shaft_with_a_point_load_in_one_span():
    # three supports at 0, l, 2 l; P in the middle of the first span; the middle reaction by compatibility
    # of the simply supported 2 l beam: deflection at x = l from P at a = l/2 and from R at l
    l, d, P = 0.4, 0.025, -1000.0
    ei, kga, _ = _props(d)
    big = 2 * l
    a = l / 2

    def w(load_at, x):  # deflection at x of a simply supported span `big` under a unit load at load_at
        aa, bb = load_at, big - load_at
        if x <= aa:
            bend = bb * x * (big**2 - bb**2 - x**2) / (6 * ei * big)
            shear = bb * x / (kga * big)
        else:
            bend = aa * (big - x) * (big**2 - aa**2 - (big - x) ** 2) / (6 * ei * big)
            shear = aa * (big - x) / (kga * big)
        return bend + shear

    r_mid = -P * w(a, l) / w(l, l)  # the support's reaction on the shaft
    s = _system(big, d, (shaft.RigidSupport("A", 0.0, axial=True), shaft.RigidSupport("B", l),
                         shaft.RigidSupport("C", big)), loads=(shaft.PointLoad(a, fy=P),))
    got = shaft.solve(s)
    assert -got.support_loads[0, 1, 1] == pytest.approx(r_mid, rel=1e-10)


def _timoshenko_frequencies(n, L, d, spin=0.0):
    """Simply supported uniform Timoshenko shaft, mode n: the roots omega of
    (rho A w^2 - kGA k^2)(rho I (w^2 - 2 Omega w) - EI k^2 - kGA) - (kGA k)^2 = 0 with k = n pi / L
    (the gyroscopic moment turns rho I w^2 into rho I (w^2 - 2 Omega w) for a circular whirl w; w > 0
    whirls forward, w < 0 backward). Returns the positive (forward) and negative (backward) roots of
    the lower branch, in Hz."""
    ei, kga, p = _props(d)
    ra, ri = RHO * p.area, RHO * p.second_moment
    k = n * math.pi / L
    # expand in w: (ra w^2 - a)(ri w^2 - 2 ri W w - b) - c = 0
    a, b, c = kga * k * k, ei * k * k + kga, (kga * k) ** 2
    coeffs = [ra * ri, -2 * ra * ri * spin, -(ra * b + a * ri), 2 * a * ri * spin, a * b - c]
    roots = np.roots(coeffs)
    roots = roots[np.abs(roots.imag) < 1e-6 * np.abs(roots).max()].real
    fwd = min(r for r in roots if r > 0)
    bwd = max(r for r in roots if r < 0)
    return fwd / (2 * math.pi), -bwd / (2 * math.pi)


def _frequencies(L, d, elements, spin=0.0, count=6):
    s = _system(L, d, (shaft.RigidSupport("A", 0.0, axial=True), shaft.RigidSupport("B", L)), elements=elements,
                speed=spin)
    return shaft.natural_modes(shaft.solve(s), count)


def test_bending_frequencies_of_a_simply_supported_uniform_shaft():
    # The elements converge on Timoshenko's frequencies from above, the error falling fourfold as the
    # elements halve (4.3 and 4.1 for mode 1 from 20 to 40 to 80): Richardson's extrapolation of 40 and 80
    # elements, (4 f_80 - f_40) / 3, is the exact value to within 5e-7 for the first three modes.
    L, d = 1.0, 0.05
    m40, m80 = _frequencies(L, d, 40), _frequencies(L, d, 80)
    for n in (1, 2, 3):
        exact = _timoshenko_frequencies(n, L, d)[0]
        f40, f80 = m40.frequency[2 * n - 2:2 * n], m80.frequency[2 * n - 2:2 * n]  # each mode twice: x, y
        assert np.all(f40 > f80) and np.all(f80 > exact)
        assert 3.5 < (f40[0] - exact) / (f80[0] - exact) < 4.5
        np.testing.assert_allclose((4 * f80 - f40) / 3, exact, rtol=5e-7)  # the h^4 term left: 1e-7 at n = 2
    # Euler-Bernoulli's (n pi / L)^2 sqrt(EI / rho A) is above Timoshenko's by the shear and rotary inertia
    ei, _, p = _props(d)
    bernoulli = (math.pi / L) ** 2 * math.sqrt(ei / (RHO * p.area)) / (2 * math.pi)
    assert bernoulli > m80.frequency[0] > 0.995 * bernoulli


def test_a_spinning_shaft_whirls_forward_faster_and_backward_slower():
    L, d, spin = 0.6, 0.12, 3000.0  # a stubby shaft spinning fast: a gyroscopic split of 3 %
    fwd, bwd = _timoshenko_frequencies(1, L, d, spin)
    ext = {}
    for el in (40, 80):
        m = _frequencies(L, d, el, spin, 2)
        assert set(m.whirl) == {"forward", "backward"}
        ext[el] = dict(zip(m.whirl, m.frequency, strict=True))
    for whirl, exact in (("forward", fwd), ("backward", bwd)):
        assert (4 * ext[80][whirl] - ext[40][whirl]) / 3 == pytest.approx(exact, rel=1e-7)
    assert fwd > 1.03 * bwd
    # turning the other way changes the sense only: the same frequencies
    m2 = _frequencies(L, d, 40, -spin, 2)
    np.testing.assert_allclose(np.sort(m2.frequency), sorted(ext[40].values()), rtol=1e-9)
