r"""Finite elements of a rotating shaft: Timoshenko beams in two planes, bars, torsion, rigid disks.

Cross-sections
--------------
section_properties   area, second moment of area and polar moment of a solid or hollow circle
shear_coefficient    Cowper's shear coefficient of a solid or hollow circle

One bending plane
-----------------
beam_stiffness       4 x 4 stiffness of a Timoshenko beam (w, psi at both ends)
beam_mass            4 x 4 translational and rotary mass of the same beam (consistent)

The shaft element
-----------------
shaft_element        12 x 12 stiffness, mass and gyroscopic matrices of a cylindrical element
disk_element         6 x 6 mass and gyroscopic matrices of a rigid disk on a node

Degrees of freedom of a node, in this order: u_x, u_y, u_z [m], theta_x, theta_y, theta_z [rad]. In the
x-z plane theta_y is the rotation of the cross-section, dw/dz without shear (a rotation about y turns
z into x); in the y-z plane theta_x = -dv/dz likewise (a rotation about x turns y into z), so that a
bearing at z sees delta_x = u_x + theta_y z and delta_y = u_y - theta_x z as in
:mod:`bearinglab.quasistatic.sets`, and ROSS's ShaftElement has the same order and signs. The equations
of motion are M q'' + Omega G q' + K q = f with G skew-symmetric: a disk spinning at Omega about +z
obeys M_x = I_d theta_x'' + I_p Omega theta_y' and M_y = I_d theta_y'' - I_p Omega theta_x' (the change of
its angular momentum I_p Omega (theta_y, -theta_x, 1)).

References
----------
.. [1] J. S. Przemieniecki, *Theory of Matrix Structural Analysis*, McGraw-Hill, 1968, sections 5.6 and
   11.4 (the beam with shear deformation: stiffness and consistent mass).
.. [2] Z. Friedman and J. B. Kosmatka, "An improved two-node Timoshenko beam finite element," Computers
   & Structures, vol. 47, no. 3, pp. 473-481, 1993, doi:10.1016/0045-7949(93)90243-7 (the interdependent
   interpolation: the shape functions whose products give these matrices exactly).
.. [3] H. D. Nelson, "A finite rotating shaft element using Timoshenko beam theory," J. Mech. Des.,
   vol. 102, no. 4, pp. 793-803, 1980, doi:10.1115/1.3254824 (rotary inertia and gyroscopic matrices).
.. [4] G. R. Cowper, "The shear coefficient in Timoshenko's beam theory," J. Appl. Mech., vol. 33,
   no. 2, pp. 335-340, 1966, doi:10.1115/1.3625046.
.. [5] M. I. Friswell, J. E. T. Penny, S. D. Garvey and A. W. Lees, *Dynamics of Rotating Machines*,
   Cambridge University Press, 2010, ch. 5 (shaft elements, the same conventions as ROSS).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

__all__ = ["ElementMatrices", "SectionProperties", "beam_mass", "beam_stiffness", "disk_element",
           "section_properties", "shaft_element", "shear_coefficient"]

#: the x-z plane's degrees of freedom in a 12-vector of two nodes: (u_x, theta_y) at both ends
_XZ = (0, 4, 6, 10)
#: the y-z plane's: (u_y, theta_x) at both ends; psi = -theta_x there, hence _FLIP
_YZ = (1, 3, 7, 9)
_FLIP = np.array([1.0, -1.0, 1.0, -1.0])


class SectionProperties(NamedTuple):
    """Properties of a circular cross-section."""

    area: np.ndarray
    """A. [m^2]"""
    second_moment: np.ndarray
    """I about a diameter. [m^4]"""
    polar_moment: np.ndarray
    """J = 2 I, the torsion constant of a circle. [m^4]"""


def section_properties(diameter, bore=0.0):
    """Area, second moment of area and polar moment of a solid or hollow circle.

    Parameters
    ----------
    diameter : array_like
        Outside diameter d. [m]
    bore : array_like, optional
        Bore d_i < d (0 for a solid shaft). [m]

    Returns
    -------
    SectionProperties
        A = pi (d^2 - d_i^2)/4, I = pi (d^4 - d_i^4)/64, J = 2 I.

    Examples
    --------
    >>> p = section_properties(0.05, 0.03)
    >>> print(f"{p.area * 1e6:.1f} mm^2, {p.second_moment * 1e12:.0f} mm^4")
    1256.6 mm^2, 267035 mm^4
    """
    d = np.asarray(diameter, dtype=float)
    b = np.asarray(bore, dtype=float)
    area = np.pi * (d * d - b * b) / 4.0
    second = np.pi * (d**4 - b**4) / 64.0
    return SectionProperties(area[()], second[()], (2.0 * second)[()])


def shear_coefficient(poisson_ratio, diameter, bore=0.0):
    r"""Cowper's shear coefficient kappa of a solid or hollow circular section.

    Parameters
    ----------
    poisson_ratio : array_like
        nu. [-]
    diameter : array_like
        Outside diameter d. [m]
    bore : array_like, optional
        Bore d_i (0 for solid). [m]

    Returns
    -------
    ndarray
        kappa. [-]

    Notes
    -----
    Cowper [4] table 1, hollow circle with m = d_i/d:
    :math:`\kappa = 6(1+\nu)(1+m^2)^2 / ((7+6\nu)(1+m^2)^2 + (20+12\nu) m^2)`; a solid circle
    (m = 0) gives 6(1 + nu)/(7 + 6 nu), 0.886 for steel. ROSS uses the same formula (its default
    ``shear_method_calc="cowper"``).

    Examples
    --------
    >>> print(f"{shear_coefficient(0.3, 0.05):.4f}")
    0.8864
    """
    nu = np.asarray(poisson_ratio, dtype=float)
    m2 = (np.asarray(bore, dtype=float) / np.asarray(diameter, dtype=float)) ** 2
    r = (1.0 + m2) ** 2
    return (6.0 * (1.0 + nu) * r / ((7.0 + 6.0 * nu) * r + (20.0 + 12.0 * nu) * m2))[()]


def beam_stiffness(length, bending_stiffness, shear_stiffness):
    r"""Stiffness matrix of a Timoshenko beam in one plane.

    Parameters
    ----------
    length : array_like
        L. [m]
    bending_stiffness : array_like
        E I. [N m^2]
    shear_stiffness : array_like
        kappa G A (infinite: no shear deformation, the Euler-Bernoulli beam). [N]

    Returns
    -------
    ndarray
        (..., 4, 4) for the end displacements and rotations (w_1, psi_1, w_2, psi_2), psi = dw/dz
        without shear. [N/m, N, N m]

    Notes
    -----
    :math:`\Phi = 12 EI / (\kappa G A L^2)` and

    .. math::

       K = \frac{EI}{(1+\Phi)L^3}\begin{bmatrix}12 & 6L & -12 & 6L\\ 6L & (4+\Phi)L^2 & -6L & (2-\Phi)L^2\\
       -12 & -6L & 12 & -6L\\ 6L & (2-\Phi)L^2 & -6L & (4+\Phi)L^2\end{bmatrix}

    ([1] section 5.6, [2] eq. (21)): exact for end loads on a uniform beam, with the shear
    deflection P L / (kappa G A) of a cantilever included.

    Examples
    --------
    >>> k = beam_stiffness(1.0, 1.0, np.inf)
    >>> print(k[0])
    [ 12.   6. -12.   6.]
    """
    ell = np.asarray(length, dtype=float)
    ei = np.asarray(bending_stiffness, dtype=float)
    phi = 12.0 * ei / (np.asarray(shear_stiffness, dtype=float) * ell * ell)
    c = ei / ((1.0 + phi) * ell**3)
    L, L2 = ell, ell * ell
    a, b = (4.0 + phi) * L2, (2.0 - phi) * L2
    rows = [[12.0 + 0 * L, 6 * L, -12.0 + 0 * L, 6 * L], [6 * L, a, -6 * L, b],
            [-12.0 + 0 * L, -6 * L, 12.0 + 0 * L, -6 * L], [6 * L, b, -6 * L, a]]
    k = np.stack([np.stack(r, axis=-1) for r in rows], axis=-2)
    return c[..., None, None] * k


def _phi(length, bending_stiffness, shear_stiffness):
    return 12.0 * np.asarray(bending_stiffness, dtype=float) / (
        np.asarray(shear_stiffness, dtype=float) * np.asarray(length, dtype=float) ** 2)


def beam_mass(length, mass_per_length, rotary_inertia_per_length, phi):
    r"""Consistent translational and rotary mass matrices of a Timoshenko beam in one plane.

    Parameters
    ----------
    length : float
        L. [m]
    mass_per_length : float
        rho A. [kg/m]
    rotary_inertia_per_length : float
        rho I, the diametral mass moment of inertia per unit length. [kg m]
    phi : float
        Phi = 12 E I / (kappa G A L^2) (0: Euler-Bernoulli). [-]

    Returns
    -------
    translational, rotary : ndarray
        (4, 4) each, for (w_1, psi_1, w_2, psi_2). [kg, kg m, kg m^2]

    Notes
    -----
    The integrals of rho A N_w^T N_w and rho I N_psi^T N_psi over the element with the interdependent
    shape functions of [2] (the same as [1] section 11.4 and Nelson [3]; ROSS's ShaftElement with
    a uniform section gives the same numbers).

    Examples
    --------
    >>> mt, mr = beam_mass(1.0, 420.0, 0.0, 0.0)
    >>> print(mt[0])
    [156.  22.  54. -13.]
    """
    L, f = float(length), float(phi)
    t = float(mass_per_length) * L / (1.0 + f) ** 2
    m1 = 13 / 35 + 7 * f / 10 + f * f / 3
    m2 = (11 / 210 + 11 * f / 120 + f * f / 24) * L
    m3 = 9 / 70 + 3 * f / 10 + f * f / 6
    m4 = (13 / 420 + 3 * f / 40 + f * f / 24) * L
    m5 = (1 / 105 + f / 60 + f * f / 120) * L * L
    m6 = (1 / 140 + f / 60 + f * f / 120) * L * L
    mt = t * np.array([[m1, m2, m3, -m4], [m2, m5, m4, -m6], [m3, m4, m1, -m2], [-m4, -m6, -m2, m5]])
    r = float(rotary_inertia_per_length) / (L * (1.0 + f) ** 2)
    r1 = 6 / 5
    r2 = (1 / 10 - f / 2) * L
    r3 = (2 / 15 + f / 6 + f * f / 3) * L * L
    r4 = (-1 / 30 - f / 6 + f * f / 6) * L * L
    mr = r * np.array([[r1, r2, -r1, r2], [r2, r3, -r2, r4], [-r1, -r2, r1, -r2], [r2, r4, -r2, r3]])
    return mt, mr


class ElementMatrices(NamedTuple):
    """The matrices of one element (12 x 12 for a shaft element, 6 x 6 for a disk)."""

    stiffness: np.ndarray
    """K. [N/m, N/rad, N m/rad]"""
    mass: np.ndarray
    """M. [kg, kg m, kg m^2]"""
    gyroscopic: np.ndarray
    """G, skew-symmetric, to be multiplied by the spin speed Omega. [kg m^2]"""


def shaft_element(length, diameter, bore, elastic_modulus, poisson_ratio, density, *, shear=True,
                  rotary_inertia=True):
    r"""Stiffness, mass and gyroscopic matrices of a cylindrical shaft element with two 6-DOF nodes.

    Parameters
    ----------
    length : float
        L > 0. [m]
    diameter : float
        Outside diameter d. [m]
    bore : float
        Bore d_i (0: solid). [m]
    elastic_modulus : float
        E. [Pa]
    poisson_ratio : float
        nu (G = E / (2 (1 + nu))). [-]
    density : float
        rho. [kg/m^3]
    shear : bool, optional
        Timoshenko (True) or Euler-Bernoulli (False) bending.
    rotary_inertia : bool, optional
        Include the rotary inertia rho I of the cross-sections (and so the gyroscopic matrix).

    Returns
    -------
    ElementMatrices
        12 x 12 matrices for (u_x, u_y, u_z, theta_x, theta_y, theta_z) of node 1 then node 2.

    Notes
    -----
    Bending in each plane by :func:`beam_stiffness` and :func:`beam_mass` (the y-z plane with
    psi = -theta_x); axial: a bar, E A / L and rho A L / 6 [[2, 1], [1, 2]]; torsion likewise with G J
    and rho J. The gyroscopic matrix is the rotary mass with the polar inertia rho J = 2 rho I
    coupling the two planes ([3], [5] section 5.4): G[x-plane, y-plane] = 2 M_R S and
    G[y-plane, x-plane] = -2 S M_R, S = diag(1, -1, 1, -1).

    Examples
    --------
    >>> e = shaft_element(0.1, 0.04, 0.0, 2.1e11, 0.3, 7850.0)
    >>> print(f"{e.mass[2, 2] + e.mass[2, 8] + e.mass[8, 2] + e.mass[8, 8]:.4f} kg")
    0.9865 kg
    """
    L = float(length)
    p = section_properties(diameter, bore)
    g = float(elastic_modulus) / (2.0 * (1.0 + float(poisson_ratio)))
    ei = float(elastic_modulus) * p.second_moment
    ks = shear_coefficient(poisson_ratio, diameter, bore) * g * p.area if shear else np.inf
    kb = beam_stiffness(L, ei, ks)
    phi = float(_phi(L, ei, ks))
    mt, mr = beam_mass(L, density * p.area, density * p.second_moment if rotary_inertia else 0.0, phi)
    mb = mt + mr
    k = np.zeros((12, 12))
    m = np.zeros((12, 12))
    gy = np.zeros((12, 12))
    xz, yz = np.ix_(_XZ, _XZ), np.ix_(_YZ, _YZ)
    k[xz], m[xz] = kb, mb
    flip = _FLIP[:, None] * _FLIP[None, :]
    k[yz], m[yz] = kb * flip, mb * flip
    gy[np.ix_(_XZ, _YZ)] = 2.0 * mr * _FLIP[None, :]
    gy[np.ix_(_YZ, _XZ)] = -2.0 * _FLIP[:, None] * mr
    bar = np.array([[1.0, -1.0], [-1.0, 1.0]])
    lumped = np.array([[2.0, 1.0], [1.0, 2.0]]) / 6.0
    ax, tw = np.ix_((2, 8), (2, 8)), np.ix_((5, 11), (5, 11))
    k[ax] = float(elastic_modulus) * p.area / L * bar
    m[ax] = density * p.area * L * lumped
    k[tw] = g * p.polar_moment / L * bar
    m[tw] = density * p.polar_moment * L * lumped
    return ElementMatrices(k, m, gy)


def disk_element(mass, polar_inertia=0.0, diametral_inertia=None):
    r"""Mass and gyroscopic matrices of a rigid disk (a gear, a pulley, a tool) on one node.

    Parameters
    ----------
    mass : float
        m. [kg]
    polar_inertia : float, optional
        I_p about the shaft axis. [kg m^2]
    diametral_inertia : float, optional
        I_d about a diameter (default I_p / 2, a thin disk). [kg m^2]

    Returns
    -------
    ElementMatrices
        6 x 6 matrices (the stiffness zero): M = diag(m, m, m, I_d, I_d, I_p), G[theta_x, theta_y] =
        I_p = -G[theta_y, theta_x].

    Examples
    --------
    >>> d = disk_element(10.0, 0.05)
    >>> print(np.diag(d.mass), d.gyroscopic[3, 4])
    [10.    10.    10.     0.025  0.025  0.05 ] 0.05
    """
    ip = float(polar_inertia)
    idd = 0.5 * ip if diametral_inertia is None else float(diametral_inertia)
    m = np.diag([float(mass)] * 3 + [idd, idd, ip])
    g = np.zeros((6, 6))
    g[3, 4], g[4, 3] = ip, -ip
    return ElementMatrices(np.zeros((6, 6)), m, g)
