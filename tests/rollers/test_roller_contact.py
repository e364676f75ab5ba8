"""The ISO/TS 16281 lamina law and the Hertz line contact (bearinglab.rollers.contact)."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearinglab.rollers import contact


@settings(deadline=None)
@given(length=st.floats(2e-3, 80e-3), n=st.integers(1, 80), delta=st.floats(1e-8, 1e-4))
def test_a_uniformly_loaded_roller_carries_the_same_load_for_any_number_of_slices(length, n, delta):
    # ISO/TS 16281: Q = 35948 L^(8/9) delta^(10/9) (N, mm) for the whole roller
    q, _ = contact.slice_loads(np.full(n, delta), contact.slice_stiffness(length, n))
    want = 35948.0 * (length * 1e3) ** (8 / 9) * (delta * 1e3) ** (10 / 9)
    assert q.sum() == pytest.approx(want, rel=1e-12)


def test_the_lamina_law_has_a_continuous_derivative():
    d = np.array([-1e-9, 0.0, 1e-9, 1e-6])
    q, k = contact.slice_loads(d, 1.0)
    assert q[0] == 0 and q[1] == 0 and k[0] == 0
    h = 1e-12
    num = (contact.slice_loads(1e-6 + h, 1.0)[0] - contact.slice_loads(1e-6 - h, 1.0)[0]) / (2 * h)
    assert k[3] == pytest.approx(num, rel=1e-6)


def test_line_contact_pressure_is_twice_the_mean_of_the_strip():
    w, r, ep = 8e5, 4.6e-3, 2.28e11
    c = contact.line_contact(w, r, ep)
    assert c.max_pressure == pytest.approx(2 * w / (math.pi * c.half_width), rel=1e-12)  # elliptical distribution
    # Johnson (4.43) with E* = E'/2: b^2 = 4 w R / (pi E*)
    assert c.half_width**2 == pytest.approx(4 * w * r / (math.pi * ep / 2), rel=1e-12)


def test_contact_radii_of_the_raceways():
    ri, ro = contact.contact_radii(10e-3, 60e-3, math.radians(15.0))
    g = 10e-3 * math.cos(math.radians(15.0)) / 60e-3
    assert ri == pytest.approx(5e-3 * (1 - g)) and ro == pytest.approx(5e-3 * (1 + g))
