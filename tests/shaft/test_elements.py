"""The Timoshenko shaft element: its matrices from the shape functions, and against ROSS's element."""

import math
import warnings

import numpy as np
import pytest

from bearinglab.shaft import elements


def _shape(xi, length, phi):
    """Interdependent interpolation (Friedman and Kosmatka 1993, eqs. (17)-(18)), written here apart from
    the library: w and psi of the four end freedoms (w1, psi1, w2, psi2) at xi = z / L."""
    L, c = length, 1.0 / (1.0 + phi)
    nw = c * np.array([2 * xi**3 - 3 * xi**2 - phi * xi + 1 + phi,
                       L * (xi**3 - (2 + phi / 2) * xi**2 + (1 + phi / 2) * xi),
                       -2 * xi**3 + 3 * xi**2 + phi * xi,
                       L * (xi**3 - (1 - phi / 2) * xi**2 - phi / 2 * xi)])
    npsi = c * np.array([6 / L * (xi**2 - xi), 3 * xi**2 - (4 + phi) * xi + 1 + phi,
                         -6 / L * (xi**2 - xi), 3 * xi**2 - (2 - phi) * xi])
    dnw = c * np.array([(6 * xi**2 - 6 * xi - phi) / L, 3 * xi**2 - (4 + phi) * xi + 1 + phi / 2,
                        (-6 * xi**2 + 6 * xi + phi) / L, 3 * xi**2 - (2 - phi) * xi - phi / 2])
    dnpsi = c * np.array([6 / L**2 * (2 * xi - 1), (6 * xi - 4 - phi) / L, -6 / L**2 * (2 * xi - 1),
                          (6 * xi - 2 + phi) / L])
    return nw, npsi, dnw, dnpsi


def _integrated(length, ei, ks, rho_a, rho_i):
    """K = int EI psi'^2 + ks (w' - psi)^2, M_T = int rho A w^2, M_R = int rho I psi^2 by 6-point Gauss."""
    phi = 12 * ei / (ks * length**2)
    x, wts = np.polynomial.legendre.leggauss(6)
    k, mt, mr = np.zeros((4, 4)), np.zeros((4, 4)), np.zeros((4, 4))
    for xg, wg in zip(0.5 * (x + 1), 0.5 * wts * length, strict=True):
        nw, npsi, dnw, dnpsi = _shape(xg, length, phi)
        gamma = dnw - npsi
        k += wg * (ei * np.outer(dnpsi, dnpsi) + ks * np.outer(gamma, gamma))
        mt += wg * rho_a * np.outer(nw, nw)
        mr += wg * rho_i * np.outer(npsi, npsi)
    return k, mt, mr, phi


@pytest.mark.parametrize("length,diameter,bore", [(0.1, 0.04, 0.0), (0.02, 0.06, 0.03), (0.5, 0.02, 0.015)])
def test_the_element_matrices_are_the_integrals_of_the_shape_functions(length, diameter, bore):
    e, nu, rho = 2.1e11, 0.3, 7850.0
    p = elements.section_properties(diameter, bore)
    ks = elements.shear_coefficient(nu, diameter, bore) * e / (2 * (1 + nu)) * p.area
    k, mt, mr, phi = _integrated(length, e * p.second_moment, ks, rho * p.area, rho * p.second_moment)
    np.testing.assert_allclose(elements.beam_stiffness(length, e * p.second_moment, ks), k, rtol=1e-11,
                               atol=1e-12 * np.abs(k).max())
    got_t, got_r = elements.beam_mass(length, rho * p.area, rho * p.second_moment, phi)
    np.testing.assert_allclose(got_t, mt, rtol=1e-11, atol=1e-13 * np.abs(mt).max())
    np.testing.assert_allclose(got_r, mr, rtol=1e-11, atol=1e-13 * np.abs(mr).max())


def test_the_shear_coefficient_of_a_solid_circle_is_cowpers():
    nu = 0.3
    assert elements.shear_coefficient(nu, 0.05) == pytest.approx(6 * (1 + nu) / (7 + 6 * nu), rel=1e-15)
    # a thin tube tends to Cowper's 2(1 + nu)/(4 + 3 nu)
    assert elements.shear_coefficient(nu, 1.0, 0.9999) == pytest.approx(2 * (1 + nu) / (4 + 3 * nu), rel=1e-6)


def test_a_rigid_motion_of_the_element_stores_no_energy_and_the_gyroscopic_matrix_is_skew():
    m = elements.shaft_element(0.12, 0.05, 0.02, 2.1e11, 0.3, 7850.0)
    L = 0.12
    for q in ([1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0], [0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0],
              [0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 1], [0, 0, 0, 0, 1e-3, 0, 1e-3 * L, 0, 0, 0, 1e-3, 0],
              [0, 0, 0, 1e-3, 0, 0, 0, -1e-3 * L, 0, 1e-3, 0, 0]):
        assert np.abs(m.stiffness @ np.array(q, float)).max() < 1e-6 * np.abs(m.stiffness).max() * 1e-3
    np.testing.assert_allclose(m.gyroscopic, -m.gyroscopic.T, atol=0)
    # a uniform bar: the translational mass adds up to the element's mass in every direction
    mass = 7850.0 * elements.section_properties(0.05, 0.02).area * L
    for i in (0, 1, 2):
        assert m.mass[np.ix_((i, i + 6), (i, i + 6))].sum() == pytest.approx(mass, rel=1e-12)


def test_the_element_is_rosss_element():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ross = pytest.importorskip("ross")
        material = ross.Material(name="steel_test", rho=7810.0, E=211e9, Poisson=0.3)
        for bore in (0.0, 0.02):
            e = ross.ShaftElement(L=0.25, idl=bore, odl=0.05, material=material, rotary_inertia=True,
                                  shear_effects=True, gyroscopic=True)
            mine = elements.shaft_element(0.25, 0.05, bore, 211e9, 0.3, 7810.0)
            for theirs, ours in ((e.K(), mine.stiffness), (e.M(), mine.mass), (e.G(), mine.gyroscopic)):
                np.testing.assert_allclose(ours, theirs, rtol=1e-12, atol=1e-12 * np.abs(theirs).max())


def test_a_thin_disk_has_half_its_polar_inertia_about_a_diameter():
    d = elements.disk_element(3.0, 0.02)
    assert d.mass[3, 3] == d.mass[4, 4] == 0.01 and d.gyroscopic[3, 4] == 0.02 == -d.gyroscopic[4, 3]
    assert math.isclose(elements.disk_element(3.0, 0.02, 0.5).mass[3, 3], 0.5)


def test_a_rigid_disk_adds_no_stiffness_on_its_six_freedoms():
    # a gear or a pulley adds mass and gyroscopic inertia, never stiffness (found by mutation testing: no test
    # looked at the disk's stiffness block)
    d = elements.disk_element(3.0, 0.02)
    assert d.stiffness.shape == (6, 6) and not np.any(d.stiffness)
    assert d.mass.shape == d.gyroscopic.shape == (6, 6)


def test_a_disk_without_a_polar_inertia_is_a_point_mass():
    d = elements.disk_element(3.0)
    assert np.array_equal(np.diag(d.mass), [3.0, 3.0, 3.0, 0.0, 0.0, 0.0]) and not np.any(d.gyroscopic)


def test_a_solid_section_by_default():
    # the bore defaults to 0: A = pi d^2/4, I = pi d^4/64, J = 2 I (found by mutation testing)
    p = elements.section_properties(0.05)
    assert p.area == pytest.approx(math.pi * 0.05**2 / 4, rel=1e-15)
    assert p.second_moment == pytest.approx(math.pi * 0.05**4 / 64, rel=1e-15)
    assert p.polar_moment == pytest.approx(math.pi * 0.05**4 / 32, rel=1e-15)


def test_without_shear_the_element_is_euler_bernoullis():
    # shear=False: the classical cubic beam, E I / L^3 [[12, 6L, -12, 6L], [6L, 4L^2, -6L, 2L^2], ...] in the
    # x-z plane (u_x, theta_y at both nodes), written from the textbook matrix
    L, d, e = 0.12, 0.04, 2.1e11
    ei = e * math.pi * d**4 / 64
    want = ei / L**3 * np.array([[12, 6 * L, -12, 6 * L], [6 * L, 4 * L * L, -6 * L, 2 * L * L],
                                 [-12, -6 * L, 12, -6 * L], [6 * L, 2 * L * L, -6 * L, 4 * L * L]])
    got = elements.shaft_element(L, d, 0.0, e, 0.3, 7850.0, shear=False).stiffness
    xz = np.ix_((0, 4, 6, 10), (0, 4, 6, 10))
    assert got[xz] == pytest.approx(want, rel=1e-13)
    # with shear the same short shaft is softer in bending
    sheared = elements.shaft_element(L, d, 0.0, e, 0.3, 7850.0).stiffness
    assert sheared[0, 0] < got[0, 0]


def test_without_rotary_inertia_there_is_no_gyroscopic_coupling():
    full = elements.shaft_element(0.1, 0.04, 0.0, 2.1e11, 0.3, 7850.0)
    bare = elements.shaft_element(0.1, 0.04, 0.0, 2.1e11, 0.3, 7850.0, rotary_inertia=False)
    assert not np.any(bare.gyroscopic) and np.any(full.gyroscopic)
    # the translational mass is the same, the rotary one gone: the slope terms are smaller
    assert bare.mass[0, 0] < full.mass[0, 0] or bare.mass[4, 4] < full.mass[4, 4]
    assert bare.mass[2, 2] == full.mass[2, 2]  # the axial bar's mass does not depend on it
