"""Line-contact EHL film and the film of every roller (bearinglab.film.line_contact)."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearinglab import film
from bearinglab.errors import InputError
from bearinglab.rollers import RollerBearing, roller_analysis


def test_pan_hamrock_by_hand():
    w, u, r, eta, alpha, ep = 8e5, 4.0, 4.5e-3, 0.03, 2.2e-8, 2.28e11
    big_u, big_g, big_w = eta * u / (ep * r), alpha * ep, w / (ep * r)
    f = film.line_film(w, u, r, eta, alpha, ep)
    assert f.minimum == pytest.approx(r * 1.714 * big_w**-0.128 * big_u**0.694 * big_g**0.568, rel=1e-12)
    assert f.central == pytest.approx(r * 2.922 * big_w**-0.166 * big_u**0.692 * big_g**0.470, rel=1e-12)
    dh = film.line_film(w, u, r, eta, alpha, ep, model="dowson-higginson")
    assert dh.minimum == pytest.approx(r * 2.65 * big_u**0.7 * big_g**0.54 * big_w**-0.13, rel=1e-12)
    assert np.isnan(dh.central)
    with pytest.raises(InputError, match="^model must be one of"):
        film.line_film(w, u, r, eta, alpha, ep, model="ertel")


@settings(deadline=None)
@given(w=st.floats(1e5, 3e6), u=st.floats(0.5, 30.0), eta=st.floats(0.005, 0.2))
def test_the_two_published_formulas_agree_within_a_fifth(w, u, eta):
    a = film.line_film(w, u, 5e-3, eta, 2e-8, 2.28e11)
    b = film.line_film(w, u, 5e-3, eta, 2e-8, 2.28e11, model="dowson-higginson")
    assert b.minimum / a.minimum == pytest.approx(1.0, abs=0.2)
    # the speed exponent of the minimum film
    c = film.line_film(w, 2 * u, 5e-3, eta, 2e-8, 2.28e11)
    assert c.minimum / a.minimum == pytest.approx(2**0.694, rel=1e-12)


def test_the_entrainment_velocity_is_the_rolling_speed_relative_to_the_cage():
    w, d, dm, a = 300.0, 11e-3, 60.5e-3, math.radians(12.0)
    g = d * math.cos(a) / dm
    cage = 0.5 * w * (1 - g)  # outer ring fixed
    inner_surface = (w - cage) * 0.5 * dm * (1 - g)
    assert film.roller_entrainment_velocity(w, d, dm, a) == pytest.approx(inner_surface, rel=1e-12)


def test_the_films_of_every_roller():
    b = RollerBearing("cylindrical", 14, 11e-3, 9.6e-3, 60.5e-3)
    r = roller_analysis(b, [8e3, 0, 0, 0, 0])
    f = film.roller_films(r.roller_load, 300.0, 11e-3, 9.6e-3, 60.5e-3, 0.02, 2e-8, b.reduced_modulus)
    loaded = r.roller_load > 0
    assert np.all(np.isnan(f.minimum_inner[~loaded])) and np.all(f.minimum_inner[loaded] < f.minimum_outer[loaded])
    top = int(np.argmax(r.roller_load))
    assert np.nanmin(f.minimum_inner) == f.minimum_inner[top]  # the most loaded roller has the thinnest film
    assert f.film_parameter[top] == pytest.approx(f.minimum_inner[top] / math.hypot(0.1e-6, 0.2e-6))
    assert set(f.regime[~loaded]) == {""}
