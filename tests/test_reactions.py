"""The batched entry point of system models: bearing loads and stiffness at given ring displacements."""

import numpy as np
import pytest

from bearinglab import catalog, reactions
from bearinglab.errors import InputError
from bearinglab.quasistatic import combined
from bearinglab.units import RPM

B218 = catalog.get("B218")


def _reference(bearing, u, w):
    """The reaction of the ring equilibrium at u under zero load (combined.equilibrium), case by case."""
    z, d, dm, fi, fo, a0, ep, rho = combined._bearing_args(bearing)
    eq = combined.equilibrium(u, np.zeros(5), w, z, d, dm, fi, fo, a0, ep, rho)
    return eq.reaction, eq.stiffness


@pytest.mark.parametrize("speed", [0.0, 8000 * RPM])
def test_each_case_equals_the_ring_equilibrium_alone(speed):
    rng = np.random.default_rng(7)
    u = np.column_stack([rng.uniform(-2e-5, 2e-5, 6), rng.uniform(-2e-5, 2e-5, 6),
                         rng.uniform(0.68e-3, 0.72e-3, 6), rng.uniform(-1e-4, 1e-4, 6),
                         rng.uniform(-1e-4, 1e-4, 6)])
    got = reactions.bearing_reactions(B218, u, speed)
    assert got.converged.all()
    for k in range(len(u)):
        force, stiff = _reference(B218, u[k], speed)
        assert np.array_equal(got.force[k], force) and np.array_equal(got.stiffness[k], stiff)


def test_bearings_side_by_side_equal_each_bearing_alone():
    other = catalog.get("6208")
    u = np.array([[[0.0, 0.0, 0.7e-3, 0.0, 0.0], [2e-5, 0.0, 0.0, 0.0, 0.0]]] * 3)
    both = reactions.bearing_reactions([B218, other], u, [0.0, 100.0, 300.0])
    for j, b in enumerate((B218, other)):
        alone = reactions.bearing_reactions(b, u[:, j], [0.0, 100.0, 300.0])
        assert np.array_equal(both.force[:, j], alone.force)
        assert np.array_equal(both.stiffness[:, j], alone.stiffness)


def test_stiffness_is_the_derivative_of_the_force():
    u = np.array([1e-5, -5e-6, 0.7e-3, 2e-5, 1e-5])
    r = reactions.bearing_reactions(B218, u)
    h = np.array([1e-9, 1e-9, 1e-9, 1e-8, 1e-8])
    for j in range(5):
        e = np.zeros(5)
        e[j] = h[j]
        fd = (reactions.bearing_reactions(B218, u + e).force - reactions.bearing_reactions(B218, u - e).force) / (2 * h[j])
        np.testing.assert_allclose(r.stiffness[:, j], fd, rtol=1e-5, atol=1e-6 * np.abs(r.stiffness).max())


def test_bad_shapes_and_speeds_name_the_input():
    with pytest.raises(InputError, match="displacement must have the shape"):
        reactions.bearing_reactions([B218, B218], np.zeros((4, 5)))
    with pytest.raises(InputError, match="shaft_speed"):
        reactions.bearing_reactions(B218, np.zeros(5), -1.0)


@pytest.mark.parametrize("engine", ["auto", "numpy"])
def test_a_case_gives_the_same_bits_in_any_batch_and_the_engines_agree(engine):
    """Issue 31 item 4: batched over cases and bearings through the kernels, bit-identical per case whatever
    the batch; the compiled kernel and the numpy path agree to rounding."""
    rng = np.random.default_rng(11)
    u = np.column_stack([rng.uniform(-2e-5, 2e-5, 7), rng.uniform(-2e-5, 2e-5, 7), rng.uniform(0.68e-3, 0.72e-3, 7),
                         rng.uniform(-1e-4, 1e-4, 7), rng.uniform(-1e-4, 1e-4, 7)])
    w = np.array([0.0, 0.0, 3000.0, 6000.0, 9000.0, 12000.0, 0.0]) * RPM
    whole = reactions.bearing_reactions(B218, u, w, engine=engine)
    for sel in ([6], [5], [0, 5], [5, 4, 3], [1, 2, 3, 4, 5, 6]):
        part = reactions.bearing_reactions(B218, u[sel], w[sel], engine=engine)
        assert np.array_equal(part.force, whole.force[sel]) and np.array_equal(part.stiffness, whole.stiffness[sel])
    other = reactions.bearing_reactions(B218, u, w, engine="numpy" if engine == "auto" else "auto")
    scale = np.max(np.abs(whole.force), axis=-1, keepdims=True)
    assert np.all(np.abs(other.force - whole.force) <= 1e-10 * scale)
    kscale = np.max(np.abs(whole.stiffness), axis=(-2, -1), keepdims=True)
    assert np.all(np.abs(other.stiffness - whole.stiffness) <= 1e-9 * kscale)

