r"""The finite-element mesh of a shaft: nodes, assembled matrices and load vectors.

Mesh
----
Mesh            node positions, element sections and the assembled K, M, G of the free shaft
build_mesh      nodes at every section change, support, load and extra point, refined to a length
node_of         the node at a position

Loads
-----
load_vectors    the nodal loads of load cases: point loads, gears, pulleys and the weight, (n, 6 n_nodes)
element_weight  the consistent nodal loads of each element's own weight

A node has six degrees of freedom (:mod:`bearinglab.shaft.elements`): u_x, u_y, u_z, theta_x,
theta_y, theta_z; node i holds rows 6 i ... 6 i + 5 of the matrices. The interval between two
neighbouring stations (section ends, supports, bearing rows of a set, loads, gears, pulleys, masses and
the extra points asked for) is split into equal elements no longer than the shaft's length divided by
``ShaftSystem.elements``. An element lies within one section, so its matrices are those of a cylinder.
"""

from __future__ import annotations

import itertools
import math
from typing import NamedTuple

import numpy as np

from ..errors import InputError
from . import elements
from .model import MAX_ELEMENTS, BearingSetSupport, gear_loads, pulley_loads

__all__ = ["Mesh", "build_mesh", "element_weight", "load_vectors", "node_of"]

_MERGE = 1e-9  # stations closer than this are one node [m]


class Mesh(NamedTuple):
    """The free shaft as finite elements (no supports)."""

    z: np.ndarray
    """(n_nodes,) node positions. [m]"""
    diameter: np.ndarray
    """(n_elements,) outside diameter of each element. [m]"""
    bore: np.ndarray
    """(n_elements,) bore of each element. [m]"""
    stiffness: np.ndarray
    """(6 n_nodes, 6 n_nodes) K of the shaft, with the masses' nothing. [N/m, N/rad, N m/rad]"""
    mass: np.ndarray
    """(6 n_nodes, 6 n_nodes) M of the shaft and its rigid masses (gears, pulleys, masses). [kg, kg m^2]"""
    gyroscopic: np.ndarray
    """(6 n_nodes, 6 n_nodes) G of the shaft and its masses, skew-symmetric (times the spin speed). [kg m^2]"""


def _stations(system, extra):
    zs = [0.0, *system.shaft.ends]
    for s in system.supports:
        zs += [z for _, z, _ in s.rows()] if isinstance(s, BearingSetSupport) else [s.position]
    for name in ("loads", "gears", "pulleys", "masses"):
        zs += [item.position for item in getattr(system, name)]
    length = system.shaft.length
    for z in extra:
        if not -_MERGE <= z <= length + _MERGE:
            raise InputError(f"position {z / 1e-3:g} mm lies outside the shaft (0 ... {length / 1e-3:g} mm)")
        zs.append(float(z))
    zs = np.clip(np.sort(np.asarray(zs, dtype=float)), 0.0, length)
    keep = np.concatenate([[True], np.diff(zs) > _MERGE])
    out = zs[keep]
    out[-1] = length
    return out


def build_mesh(system, extra=()):
    """The mesh of a shaft system: nodes, elements and the assembled matrices of the free shaft.

    Parameters
    ----------
    system : ShaftSystem
    extra : sequence of float, optional
        More positions that must be nodes (a point whose stiffness is asked for). [m]

    Returns
    -------
    Mesh

    Raises
    ------
    InputError
        An extra position outside the shaft, or a mesh of more than 400 elements.

    Examples
    --------
    >>> from bearinglab.shaft.model import RigidSupport, Section, Shaft, ShaftSystem
    >>> s = ShaftSystem(Shaft((Section(0.2, 0.03),)), (RigidSupport("A", 0.0, axial=True),
    ...                 RigidSupport("B", 0.2)), elements=4)
    >>> print(build_mesh(s).z * 1e3)
    [  0.  50. 100. 150. 200.]
    """
    st = _stations(system, extra)
    h = system.shaft.length / system.elements
    z = [st[0]]
    for a, b in itertools.pairwise(st):
        n = max(1, math.ceil((b - a) / h - 1e-9))
        z += list(a + (b - a) * np.arange(1, n + 1) / n)
    z = np.asarray(z)
    z[-1] = system.shaft.length
    n_el = len(z) - 1
    if n_el > MAX_ELEMENTS:
        raise InputError(f"elements: the mesh needs {n_el} elements (at every station, and at least "
                         f"{system.elements} over the shaft), more than the limit of {MAX_ELEMENTS}")
    secs = system.shaft.sections
    mid = 0.5 * (z[:-1] + z[1:])
    idx = [system.shaft.section_at(m) for m in mid]
    dia = np.array([secs[i].diameter for i in idx])
    bore = np.array([secs[i].bore for i in idx])
    mat = system.shaft.material
    n = 6 * len(z)
    k, m, g = np.zeros((n, n)), np.zeros((n, n)), np.zeros((n, n))
    for e in range(n_el):
        em = elements.shaft_element(z[e + 1] - z[e], dia[e], bore[e], mat.elastic_modulus, mat.poisson_ratio,
                                    mat.density)
        sl = slice(6 * e, 6 * e + 12)
        k[sl, sl] += em.stiffness
        m[sl, sl] += em.mass
        g[sl, sl] += em.gyroscopic
    for item in _rigid_masses(system):
        i = node_of(z, item.position)
        d = elements.disk_element(item.mass, item.polar_inertia, item.diametral_inertia)
        sl = slice(6 * i, 6 * i + 6)
        m[sl, sl] += d.mass
        g[sl, sl] += d.gyroscopic
    return Mesh(z, dia, bore, k, m, g)


def _rigid_masses(system):
    return [x for x in (*system.gears, *system.pulleys, *system.masses) if x.mass > 0 or x.polar_inertia > 0
            or (x.diametral_inertia or 0) > 0]


def node_of(z, position):
    """The index of the node at ``position`` (within 1e-9 m).

    Parameters
    ----------
    z : array_like
        Node positions (``Mesh.z``). [m]
    position : float
        [m]

    Returns
    -------
    int
    """
    z = np.asarray(z)
    i = int(np.argmin(np.abs(z - position)))
    if abs(z[i] - position) > 1e-6 * max(1.0, abs(position)):
        raise InputError(f"position {position / 1e-3:g} mm is no node of the mesh")
    return i


def load_vectors(system, mesh, speed, factor=1.0, point_loads=None):
    r"""The nodal loads of load cases.

    Parameters
    ----------
    system : ShaftSystem
    mesh : Mesh
    speed : array_like
        (n,) signed shaft speed of each case (for gears given by their power). [rad/s]
    factor : array_like, optional
        (n,) factor on every load, gear, pulley (not on the weight). [-]
    point_loads : array_like, optional
        (n, n_loads, 6) the system's point loads case by case (fx, fy, fz [N], mx, my, mz [N m]),
        instead of the ones in ``system.loads`` (their positions are kept). [N, N m]

    Returns
    -------
    ndarray
        (n, 6 n_nodes). [N, N m]

    Notes
    -----
    The weight: rho A g per unit length of each element as consistent nodal loads, q L / 2 at each end
    and the moments q L^2 / 12 (of either sign) of the bending planes (exact for the interdependent
    interpolation of :func:`bearinglab.shaft.elements.beam_mass`, whose integrals of N_w are 1/2 and
    L / 12), and m g of each rigid mass at its node.
    """
    w = np.atleast_1d(np.asarray(speed, dtype=float))
    n_cases = w.size
    fac = np.broadcast_to(np.asarray(factor, dtype=float), (n_cases,))
    z = mesh.z
    out = np.zeros((n_cases, 6 * len(z)))

    def add(position, vec):
        i = node_of(z, position)
        out[:, 6 * i:6 * i + 6] += vec

    if point_loads is None:
        for ld in system.loads:
            add(ld.position, fac[:, None] * ld.vector)
    else:
        p = np.asarray(point_loads, dtype=float)
        if p.shape != (n_cases, len(system.loads), 6):
            raise InputError(f"point_loads must have the shape (cases, loads, 6) = ({n_cases}, {len(system.loads)}, "
                             f"6), got {p.shape}")
        for j, ld in enumerate(system.loads):
            add(ld.position, fac[:, None] * p[:, j])
    for g in system.gears:
        add(g.position, fac[:, None] * gear_loads(g, w))
    for p in system.pulleys:
        add(p.position, fac[:, None] * pulley_loads(p))
    if system.gravity is not None:
        out += _weight(system, mesh)[None, :]
    return out


def element_weight(system, mesh):
    """The consistent nodal loads of each element's own weight.

    Parameters
    ----------
    system : ShaftSystem
    mesh : Mesh

    Returns
    -------
    ndarray
        (n_elements, 12) for the two nodes of each element (zeros without gravity). [N, N m]
    """
    z = mesh.z
    out = np.zeros((len(z) - 1, 12))
    if system.gravity is None:
        return out
    gx, gy, gz = system.gravity
    rho = system.shaft.material.density
    for e in range(len(z) - 1):
        L = z[e + 1] - z[e]
        q = rho * elements.section_properties(mesh.diameter[e], mesh.bore[e]).area  # kg/m
        for k, gk in ((0, gx), (1, gy), (2, gz)):
            out[e, k] += q * gk * L / 2
            out[e, 6 + k] += q * gk * L / 2
        # x-z plane: theta_y carries +qL^2/12 at the left end; y-z plane: theta_x = -psi
        out[e, 4] += q * gx * L * L / 12
        out[e, 10] -= q * gx * L * L / 12
        out[e, 3] -= q * gy * L * L / 12
        out[e, 9] += q * gy * L * L / 12
    return out


def _weight(system, mesh):
    z = mesh.z
    vec = np.zeros(6 * len(z))
    per = element_weight(system, mesh)
    for e in range(len(z) - 1):
        vec[6 * e:6 * e + 12] += per[e]
    for item in _rigid_masses(system):
        i = node_of(z, item.position)
        vec[6 * i:6 * i + 3] += item.mass * np.asarray(system.gravity)
    return vec
