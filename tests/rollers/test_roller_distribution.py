"""The 5-DOF load distribution of the slice model (bearinglab.rollers.distribution).

The reference reaction of these tests is computed independently of the batched kernel: each lamina as a point
on the cup raceway with its normal, moved by the rigid-ring displacement delta + theta x p, its load by the
power law typed out again, and the ring's load as the sum of the lamina forces and of their moments p x F.
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearinglab.errors import InputError
from bearinglab.rollers import distribution as dist
from bearinglab.rollers import geometry

CYL = dist.roller_set(14, 11e-3, 9.6e-3, 60.5e-3, normal_gap=5e-6,
                      drop=geometry.logarithmic_drop(geometry.slice_positions(9.6e-3, 30), 9.6e-3, 11e-3))
TAP = dist.roller_set(17, 10e-3, 14e-3, 60e-3, contact_angle=math.radians(14.0),
                      drop=geometry.logarithmic_drop(geometry.slice_positions(14e-3, 30), 14e-3, 10e-3, tapered=True))


def reference_reaction(rs, u):
    """The load on the inner ring at displacement u, lamina by lamina (independent of the kernel)."""
    dx, dy, dz, tx, ty = u
    a = rs.contact_angle
    c = 35948.0 * (rs.roller_length * 1e3) ** (8 / 9) / len(rs.slice_position)  # N / mm^(10/9)
    force = np.zeros(3)
    moment = np.zeros(3)
    for psi in rs.azimuth:
        n = np.array([math.cos(a) * math.cos(psi), math.cos(a) * math.sin(psi), math.sin(a)])
        for s, p_drop in zip(rs.slice_position, rs.drop, strict=True):
            r, z = 0.5 * rs.pitch_diameter - s * math.sin(a), s * math.cos(a)
            p = np.array([r * math.cos(psi), r * math.sin(psi), z])
            move = np.array([dx, dy, dz]) + np.cross([tx, ty, 0.0], p)
            approach = n @ move - rs.normal_gap - 2 * p_drop
            if approach > 0:
                q = c * (approach * 1e3) ** (10 / 9)
                force += q * n
                moment += np.cross(p, q * n)
    return np.array([*force, moment[0], moment[1]])


@pytest.mark.parametrize("rs", [CYL, TAP], ids=["cylindrical", "tapered"])
def test_the_kernels_reaction_is_the_sum_of_the_laminae(rs):
    u = np.array([18e-6, -7e-6, 30e-6 if rs is TAP else 0.0, 2e-4, -1.5e-4])
    e = dist.equilibrium(u, np.zeros(5), rs)
    assert e.reaction == pytest.approx(reference_reaction(rs, u), rel=1e-11, abs=1e-9)


@pytest.mark.parametrize("rs", [CYL, TAP], ids=["cylindrical", "tapered"])
def test_the_stiffness_is_the_derivative_of_the_reaction(rs):
    u = np.array([18e-6, -7e-6, 30e-6 if rs is TAP else 0.0, 2e-4, -1.5e-4])
    k = dist.equilibrium(u, np.zeros(5), rs).stiffness
    steps = np.array([1e-9, 1e-9, 1e-9, 1e-8, 1e-8])
    for j in range(5):
        du = np.zeros(5)
        du[j] = steps[j]
        up = dist.equilibrium(u + du, np.zeros(5), rs).reaction
        dn = dist.equilibrium(u - du, np.zeros(5), rs).reaction
        num = (up - dn) / (2 * steps[j])
        assert k[:, j] == pytest.approx(num, rel=2e-5, abs=1e-6 * np.abs(k).max()), f"column {j}"
    assert k == pytest.approx(k.T, rel=1e-12, abs=1e-9 * np.abs(k).max())  # at rest: symmetric


def test_pure_radial_load_at_zero_clearance_gives_stribecks_line_contact_factor():
    # flat rollers, no gap: delta_j = delta_r cos(psi_j) on every lamina, Q_j ~ cos^(10/9), so
    # Z Q_max / F_r = Z / sum cos^(19/9)(psi_j) over the loaded rollers exactly, -> 4.08 as Z grows
    # (Stribeck's classical line-contact value, printed 4.08: NSK CAT. No. E1102e eq. (5); Harris ch. 7)
    for z in (14, 24):
        rs = dist.roller_set(z, 10e-3, 10e-3, 80e-3)
        r = dist.load_distribution([12e3, 0, 0, 0, 0], rs)
        psi = rs.azimuth
        want = z / np.sum(np.clip(np.cos(psi), 0, None) ** (19 / 9))
        assert r.max_roller_load * z / 12e3 == pytest.approx(want, rel=1e-9)
    big = dist.roller_set(400, 1e-3, 1e-3, 200e-3)
    r = dist.load_distribution([1e4, 0, 0, 0, 0], big)
    assert r.max_roller_load * 400 / 1e4 == pytest.approx(4.08, abs=0.005)  # 3 printed digits


def load(top):
    """0, or a load of an engineering size (from 0.1 N / 0.01 N m, 1e-6 C of this bearing). Far below, where a
    lamina's approach is a few picometres, the ring Newton may stall; it then says so (ConvergenceError)."""
    low = 0.1 if top > 100 else 0.01
    return st.one_of(st.just(0.0), st.floats(low, top), st.floats(-top, -low))


@settings(max_examples=25, deadline=None)
@given(fx=load(3e4), fy=load(3e4), mx=load(60.0), my=load(60.0), gap=st.floats(-5e-6, 20e-6))
def test_every_case_is_in_equilibrium_to_1e_9(fx, fy, mx, my, gap):
    rs = CYL._replace(normal_gap=gap)
    loads = np.array([fx, fy, 0.0, mx, my])
    r = dist.load_distribution(loads, rs)
    back = reference_reaction(rs, r.displacement)
    scale = max(np.linalg.norm(loads * [1, 1, 1, 2 / rs.pitch_diameter, 2 / rs.pitch_diameter]), r.roller_load.sum())
    free = np.array([1, 1, 0, 1, 1.0])  # the cylindrical bearing's delta_z is held
    residual = (loads - back) * free * [1, 1, 1, 2 / rs.pitch_diameter, 2 / rs.pitch_diameter]
    assert np.linalg.norm(residual) <= 1e-9 * scale


@settings(max_examples=20, deadline=None)
@given(fr=st.floats(0.0, 2e4), fz=st.floats(1e3, 3e4), tilt=st.floats(-0.3, 0.3), phi=st.floats(0, 2 * math.pi))
def test_load_displacement_load_round_trip_of_a_tapered_bearing(fr, fz, tilt, phi):
    fz = max(fz, 1.3 * fr * math.tan(TAP.contact_angle) + 1.0)
    my = tilt * fz * 0.5 * TAP.pitch_diameter * math.sin(TAP.contact_angle)  # a moment the thrust can hold
    loads = np.array([fr * math.cos(phi), fr * math.sin(phi), fz, 0.0, my])
    r = dist.load_distribution(loads, TAP)
    e = dist.equilibrium(r.displacement, loads, TAP)
    assert e.reaction == pytest.approx(loads, rel=1e-9, abs=1e-9 * fz)


def test_rotating_the_load_by_one_roller_pitch_rotates_the_roller_loads():
    step = 2 * math.pi / CYL.rollers
    a = dist.load_distribution([1e4, 0, 0, 0, 20.0], CYL)
    b = dist.load_distribution([1e4 * math.cos(step), 1e4 * math.sin(step), 0, -20.0 * math.sin(step),
                                20.0 * math.cos(step)], CYL)
    assert np.roll(a.roller_load, 1) == pytest.approx(b.roller_load, rel=1e-9, abs=1e-6)


def test_a_tilt_loads_the_edge_of_the_roller():
    flat = CYL._replace(drop=np.zeros(30), normal_gap=0.0)
    r = dist.load_distribution([1e4, 0, 0, 0, 0], flat, prescribed_displacement=[np.nan, np.nan, np.nan, 0, 1e-3])
    top = int(np.argmax(r.roller_load))
    q = r.slice_load[top]
    assert q[-1] > 1.5 * q[0] and np.all(np.diff(q[q > 0]) > 0)  # the +s end carries the most
    assert r.slice_pressure[top, -1] == pytest.approx(r.max_pressure[top])
    assert r.reactions[4] != 0 and np.isnan(r.reactions[0])


def test_zero_and_negative_clearance():
    zero = dist.load_distribution([0, 0, 0, 0, 0], CYL._replace(normal_gap=0.0))
    assert np.all(zero.roller_load == 0) and np.all(zero.displacement == 0)
    pre = dist.load_distribution([0, 0, 0, 0, 0], CYL._replace(normal_gap=-3e-6))
    assert np.all(pre.roller_load > 0) and pre.displacement == pytest.approx(np.zeros(5), abs=1e-15)
    loaded = dist.load_distribution([1e3, 0, 0, 0, 0], CYL._replace(normal_gap=-3e-6))
    assert np.all(loaded.roller_load > 0)  # a preloaded bearing keeps every roller in contact


def test_a_tapered_bearing_couples_radial_and_axial():
    r = dist.load_distribution([0, 0, 8e3, 0, 0], TAP)
    assert r.roller_load == pytest.approx(np.full(17, 8e3 / (17 * math.sin(TAP.contact_angle))), rel=1e-9)
    k = r.stiffness
    assert k[2, 2] > 0 and abs(k[0, 2]) < 1e-6 * k[2, 2]  # uniform: no coupling by symmetry
    shifted = dist.equilibrium(r.displacement + [5e-6, 0, 0, 0, 0], np.zeros(5), TAP)
    assert shifted.reaction[2] > 8e3  # a radial displacement raises the thrust the bearing carries


def test_axial_loads_of_cylindrical_designs():
    nu = CYL
    with pytest.raises(InputError, match="^loads: F_z = 100 N on a cylindrical roller bearing"):
        dist.load_distribution([1e3, 0, 100, 0, 0], nu)
    nj = CYL._replace(axial_support="ribs-positive")
    with pytest.raises(InputError, match="^loads: F_z = -100 N on an NJ"):
        dist.load_distribution([1e3, 0, -100, 0, 0], nj)
    nup = dist.load_distribution([1e3, 0, -100, 0, 0], CYL._replace(axial_support="ribs"))
    assert nup.rib_load == -100 and nup.loads[2] == -100 and nup.stiffness[2, 2] == 0


def test_a_single_tapered_bearing_needs_its_thrust():
    with pytest.raises(InputError, match=r"^loads: F_z = 1000 N cannot hold F_r = 10000 N"):
        dist.load_distribution([1e4, 0, 1e3, 0, 0], TAP)


def test_a_case_gives_the_same_bits_alone_and_in_a_batch():
    # 1100 cases: more than one chunk of the solve, and a batch that runs on one BLAS thread (single cases do not)
    n = 1100
    rng = np.random.default_rng(7)
    loads = np.column_stack([rng.uniform(-2e4, 2e4, n), rng.uniform(-2e4, 2e4, n), np.zeros(n),
                             rng.uniform(-30, 30, n), rng.uniform(-30, 30, n)])
    assert n > dist._CHUNK and n > dist._ONE_BLAS_THREAD
    batch = dist.load_distribution(loads, CYL)
    for k in (0, 17, 39, 1050):
        one = dist.load_distribution(loads[k], CYL)
        assert np.array_equal(one.displacement, batch.displacement[k])
        assert np.array_equal(one.slice_load, batch.slice_load[k])
