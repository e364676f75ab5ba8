"""The contact tolerance of spec 003 section 7.6 pinned by constructed near-ties, and the solver's choice
of the diametral pair that carries the ring, checked on every pair of a 16-ball bearing.

Constructed cases: Delta k is a sinusoid s(theta) = a0 + B sin theta + D cos theta plus chosen slacks,
so the answer (a0, which balls touch) is known without solving anything.
"""

import numpy as np
import pytest

from bearinglab import runout

UM = 1e-6
N = 16
THETA = 2 * np.pi * np.arange(N) / N


def _sinusoid(a0, b, d):
    return a0 + b * np.sin(THETA) + d * np.cos(THETA)


# the dual method on both engines ("auto" is the compiled one where numba is installed)
ENGINES = ["numpy", "auto"]


@pytest.mark.parametrize(("method", "engine"), [("dual", "numpy"), ("dual", "auto"), ("triples", "numpy"),
                                                ("lp", "numpy")])
def test_contact_tolerance_is_one_tenth_of_a_nanometre_scaled(method, engine):
    """Spec 003 section 7.6: a ball touches when its slack is <= 1e-7 um x max(1, max|Delta k| / 1 um).

    Balls 1 and 9 (a diametral pair) carry the ring at a0 = -1 um, D = -1 um; max|Delta k| = 2 um,
    so the tolerance is 2e-7 um. Ball 2 sits 1.5e-7 um above the sinusoid (a contact only because the
    tolerance scales) and ball 3 3e-7 um above it (no contact): the tolerance is pinned to within a
    factor of 2 either way.
    """
    slack = 1.0 + np.cos(THETA)  # zero at ball 9 (theta = pi)
    slack[0], slack[1], slack[2] = 0.0, 1.5e-7, 3e-7
    dk = _sinusoid(-1.0, 0.0, -1.0) + slack  # dk[0] = -2 um
    s = runout.solve_contact(dk * UM, THETA, method=method, engine=engine)
    assert s.constant == pytest.approx(-1.0 * UM, abs=1e-15 * UM)
    assert np.flatnonzero(s.contact).tolist() == [0, 1, 8]
    assert s.slack[1] == pytest.approx(1.5e-7 * UM, rel=1e-6)
    assert s.slack[2] == pytest.approx(3e-7 * UM, rel=1e-6)


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("pair", range(N // 2))
def test_the_binding_diametral_pair_is_found(pair, engine):
    """Zero slack on balls ``pair`` and ``pair + 8`` only: the ring rests on that pair, whichever it is."""
    rng = np.random.default_rng(pair)
    base = (0.3, -0.2, 0.4)  # a0, B, D [um]
    slack = rng.uniform(0.2, 1.0, N)
    slack[[pair, pair + N // 2]] = 0.0
    s = runout.solve_contact((_sinusoid(*base) + slack) * UM, THETA, engine=engine)
    assert s.constant == pytest.approx(base[0] * UM, abs=1e-12 * UM)
    assert s.contact[pair] and s.contact[pair + N // 2]
    assert s.degenerate  # a pair leaves the ring free to slide along the pair's normal
    others = np.delete(np.arange(N), [pair, pair + N // 2])
    # the tie-break point lies on the face: every other ball keeps a slack of at least 0 and the sinusoid
    # found satisfies the pair's two constraints with equality
    assert np.all(s.slack[others] >= -1e-12 * UM)
    fitted = s.constant + s.sine * np.sin(THETA) + s.cosine * np.cos(THETA)
    assert fitted[[pair, pair + N // 2]] == pytest.approx(_sinusoid(*base)[[pair, pair + N // 2]] * UM,
                                                          abs=1e-12 * UM)


@pytest.mark.parametrize("engine", ENGINES)
def test_a_triangle_beats_a_pair_when_it_is_lower(engine):
    """Balls 1, 6, 11 (a triangle around the centre) at zero slack and no pair at zero slack: three
    contacts and no sliding."""
    slack = np.full(N, 0.5)
    slack[[0, 5, 10]] = 0.0
    s = runout.solve_contact((_sinusoid(0.1, 0.2, -0.3) + slack) * UM, THETA, engine=engine)
    assert np.flatnonzero(s.contact).tolist() == [0, 5, 10]
    assert not s.degenerate
    assert s.sine == pytest.approx(0.2 * UM, abs=1e-12 * UM)
    assert s.cosine == pytest.approx(-0.3 * UM, abs=1e-12 * UM)
