r"""What a solved shaft system gives: loads along the shaft, stiffness at a point, each bearing's state.

Along the shaft
---------------
InternalLoads     shear forces, axial force, bending moments and torque at every node
internal_loads    from the element end forces of the solution

Stiffness
---------
StiffnessAt       the direct stiffness of the system at a point, linearised at the operating point
stiffness_at      for every load case
system_stiffness  the full tangent stiffness matrix of shaft, supports and bearings (housings condensed)

Bearings
--------
BearingState      each bearing's load distribution (ball loads, contact pressures) and lives
bearing_states    every bearing of a solution, batched over the load cases

Internal loads follow one rule: at a cut just to the right of a node (at the last node, just to its
left) they are the resultant of every load on the shaft between z = 0 and the cut, reduced to the cut:
the force and moment the left part passes to the right. Shear forces and bending moments are its
x and y components (moments as vectors: ``bending_moment_x`` turns about x); the axial force is
positive in tension. They come from the element end forces K_e u_e - f_e (f_e the element's own
weight), which the interdependent-interpolation element gives exactly at the nodes.
"""

from __future__ import annotations

import warnings
from typing import NamedTuple

import numpy as np

from ..errors import InputError
from . import elements
from .mesh import element_weight, node_of
from .statics import _mv, assemble, tangent

__all__ = ["BearingState", "InternalLoads", "StiffnessAt", "bearing_states", "internal_loads", "stiffness_at",
           "system_stiffness"]


class InternalLoads(NamedTuple):
    """Loads inside the shaft at every node, for every case (n cases, n_nodes nodes)."""

    z: np.ndarray
    """(n_nodes,) [m]"""
    shear_force: np.ndarray
    """(n, n_nodes, 2) V_x, V_y. [N]"""
    axial_force: np.ndarray
    """(n, n_nodes) N, tension positive. [N]"""
    bending_moment: np.ndarray
    """(n, n_nodes, 2) M_x, M_y (moment vectors). [N m]"""
    torque: np.ndarray
    """(n, n_nodes) M_z passed from the left part to the right. [N m]"""


def _element_matrices(system, mesh):
    mat = system.shaft.material
    return np.array([elements.shaft_element(mesh.z[e + 1] - mesh.z[e], mesh.diameter[e], mesh.bore[e],
                                            mat.elastic_modulus, mat.poisson_ratio, mat.density).stiffness
                     for e in range(len(mesh.z) - 1)])


def internal_loads(state):
    """Shear forces, axial force, bending moments and torque at every node of a solution.

    Parameters
    ----------
    state : SystemState
        From :func:`bearinglab.shaft.solve`.

    Returns
    -------
    InternalLoads
        See the module notes for the signs.

    Examples
    --------
    >>> from bearinglab.shaft.model import PointLoad, RigidSupport, Section, Shaft, ShaftSystem
    >>> from bearinglab.shaft.statics import solve
    >>> s = ShaftSystem(Shaft((Section(1.0, 0.05),)), (RigidSupport("A", 0.0, axial=True),
    ...                 RigidSupport("B", 1.0)), loads=(PointLoad(0.5, fy=-1000.0),), elements=2)
    >>> q = internal_loads(solve(s))
    >>> print(np.round(q.bending_moment[0, :, 0], 6) + 0.0, np.round(q.shear_force[0, :, 1], 6))
    [  0. 250.   0.] [ 500. -500. -500.]
    """
    asm = state.assembly
    mesh = asm.mesh
    ke = _element_matrices(asm.system, mesh)
    fe = element_weight(asm.system, mesh)
    n, nn = state.displacement.shape[:2]
    u = state.displacement.reshape(n, -1)
    ue = np.stack([u[:, 6 * e:6 * e + 12] for e in range(nn - 1)], axis=1)  # (n, n_el, 12)
    p = np.matmul(ke[None], ue[..., None])[..., 0] - fe[None]
    left = np.concatenate([p[:, :, :6], -p[:, -1:, 6:]], axis=1)  # (n, n_nodes, 6)
    return InternalLoads(mesh.z.copy(), left[:, :, 0:2] + 0.0, -left[:, :, 2] + 0.0, left[:, :, 3:5] + 0.0,
                         left[:, :, 5] + 0.0)


def system_stiffness(state, case=0, *, mesh=None):
    """The tangent stiffness matrix of the whole system at a solution, its housings condensed.

    Parameters
    ----------
    state : SystemState
    case : int, optional
        The load case.
    mesh : Mesh, optional
        Another mesh of the same system (with more nodes); default the solution's.

    Returns
    -------
    stiffness : ndarray
        (6 n_nodes, 6 n_nodes): the shaft, the linear supports' springs and each bearing's tangent
        stiffness (own frame turned into the shaft's, in series with its housing springs). [N/m, N/rad,
        N m/rad]
    held : ndarray
        The degrees of freedom held at zero (rigid supports, the torsion reference).
    """
    from .supports import constrained_dofs, linear_springs

    asm = state.assembly
    system = asm.system
    if mesh is None:
        mesh, k, held = asm.mesh, asm.stiffness.copy(), asm.constrained
    else:
        k = mesh.stiffness.copy()
        for dof, kk in linear_springs(system, mesh):
            k[dof, dof] += kk
        held = np.array(constrained_dofs(system, mesh), dtype=int)
    for j, r in enumerate(asm.rows):
        t = r.transform
        ks = state.row_stiffness[case, j] * (t[:, None] * t[None, :])
        keff = _series(ks, r.housing)
        i = node_of(mesh.z, r.position)
        k[6 * i:6 * i + 5, 6 * i:6 * i + 5] += keff
    return k, held


def _series(ks, housing):
    """A bearing's stiffness ks (5, 5, shaft frame) in series with its housing springs (inf: rigid)."""
    free = np.flatnonzero(np.isfinite(housing))
    if not free.size:
        return ks
    kuh = -ks[:, free]
    khh = ks[np.ix_(free, free)] + np.diag(housing[free])
    return ks - kuh @ np.linalg.pinv(khh, rcond=1e-13) @ kuh.T


class StiffnessAt(NamedTuple):
    """The direct stiffness of the system at one point, per load case."""

    position: float
    """z. [m]"""
    stiffness: np.ndarray
    """(n, 5) along x, y, z [N/m] and about x, y [N m/rad]: the load over the displacement it causes
    there, in its own direction, all else free (inf where the point is held)."""
    compliance: np.ndarray
    """(n, 5, 5) displacement at the point per unit load at the point. [m/N, rad/(N m), ...]"""


def stiffness_at(state, position):
    r"""The direct stiffness of a solved system at a point: a spindle's stiffness at its tool.

    Parameters
    ----------
    state : SystemState
    position : float
        z of the point. [m]

    Returns
    -------
    StiffnessAt

    Notes
    -----
    The system is linearised at its operating point: the shaft, the springs and each bearing's tangent
    stiffness at the solution (its preload and load). A unit load at the point's node gives, through the
    condensed tangent A of :func:`bearinglab.shaft.statics.tangent`, the displacement
    u_p = (K_II^-1 e_p)_p - (K_II^-1 K_IB A^-1 f_c)_p with f_c = -K_BI K_II^-1 e_p (or u_B = A^-1 e_p at a
    bearing node); the direct stiffness is 1/u_p. Where the point is no node of the solution's mesh, the
    same bearings' stiffness acts on a mesh with the point added (exact: the solution is not needed
    between the nodes).
    """
    asm = state.assembly
    system = asm.system
    z = asm.mesh.z
    p = float(position)
    if not -1e-9 <= p <= system.length + 1e-9:
        raise InputError(f"stiffness_at: {p / 1e-3:g} mm lies outside the shaft (0 ... {system.length / 1e-3:g} mm)")
    if np.min(np.abs(z - p)) > 1e-9:
        asm = assemble(system, extra=[p])
        if len(asm.rows) != len(state.assembly.rows):  # pragma: no cover - the rows do not depend on the mesh
            raise InputError("stiffness_at: the bearings moved with the mesh")
    i = node_of(asm.mesh.z, p)
    n = state.row_stiffness.shape[0]
    out = np.full((n, 5, 5), 0.0)
    a = tangent(asm, state.row_stiffness) if asm.rows else np.zeros((n, 0, 0))
    nb = len(asm.coupled)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        for c in range(5):
            dof = 6 * i + c
            if dof in set(asm.constrained.tolist()):
                continue
            if dof in set(asm.coupled.tolist()):
                k = int(np.flatnonzero(asm.coupled == dof)[0])
                rhs = np.zeros((n, a.shape[1]))
                rhs[:, k] = 1.0
                x = np.linalg.solve(a, rhs[:, :, None])[:, :, 0]
                disp = _full(asm, x[:, :nb], np.zeros((n, len(asm.internal))))
            else:
                k = int(np.flatnonzero(asm.internal == dof)[0])
                e = np.zeros((1, len(asm.internal)))
                e[0, k] = 1.0
                u0 = np.broadcast_to(asm.flexibility[:, k], (n, len(asm.internal)))
                if nb:
                    rhs = np.zeros((n, a.shape[1]))
                    rhs[:, :nb] = -asm.transfer[k][None]
                    x = np.linalg.solve(a, rhs[:, :, None])[:, :, 0]
                else:
                    x = np.zeros((n, 0))
                disp = _full(asm, x[:, :nb], u0)
            out[:, :, c] = disp[:, 6 * i:6 * i + 5]
        diag = np.diagonal(out, axis1=1, axis2=2)
        stiff = np.where(diag > 0, 1.0 / np.where(diag > 0, diag, 1.0), np.inf)
    held = [c for c in range(5) if 6 * i + c in set(asm.constrained.tolist())]
    stiff[:, held] = np.inf
    return StiffnessAt(p, stiff, out)


def _full(asm, ub, u0):
    """Every dof's displacement from u_B (n, nb) and K_II^-1 f_I (n, n_I)."""
    n = len(ub)
    u = np.zeros((n, 6 * len(asm.mesh.z)))
    if len(asm.coupled):
        u[:, asm.coupled] = ub
        u[:, asm.internal] = u0 - _mv(asm.transfer, ub)
    else:
        u[:, asm.internal] = u0
    return u


class BearingState(NamedTuple):
    """One bearing of a solution, over the load cases (own frame of the bearing)."""

    name: str
    bearing: object
    loads: np.ndarray
    """(n, 5) F_x, F_y, F_z [N], M_x, M_y [N m] it carries."""
    displacement: np.ndarray
    """(n, 5) its ring displacement. [m, rad]"""
    load_distribution: object
    """:class:`~bearinglab.quasistatic.combined.LoadDistribution` at that displacement and speed
    (ball loads, contact angles and pressures), or None for a bearing without that model."""
    life: object
    """:class:`~bearinglab.life.RatingLife`: ISO 281 from F_r and F_a (moments left out, as ISO 281 has
    none), ISO/TS 16281 from the ball loads of the solution (tilt included); None at standstill."""


def bearing_states(state, *, life=True, **life_options):
    r"""The load distribution and the lives of every bearing of a solution.

    Parameters
    ----------
    state : SystemState
    life : bool, optional
        Compute the lives (:func:`bearinglab.life.rating_life`).
    **life_options
        ``kinematic_viscosity``, ``contamination``, ``reliability``, the oil (``temperature``,
        ``iso_vg``, ...) as :func:`bearinglab.life.rating_life` takes them.

    Returns
    -------
    list of BearingState

    Notes
    -----
    The ball loads are those of the system's solution: the combined-load model at the bearing's ring
    displacement d_j, all five freedoms held (:func:`bearinglab.quasistatic.combined.combined_analysis`
    with ``prescribed_displacement``), at the case's speed; its reaction equals the load the system
    solve found. ISO 281's equivalent load takes the radial and axial load only (P and P0 have no
    moment, as MESYS's ISO 281 life); the reference life L10r of ISO/TS 16281 takes the ball loads,
    tilt and all. A bearing at standstill has no life in hours: its lives are None.
    """
    from ..bearing import BallBearing
    from ..life import rating_life
    from ..quasistatic import combined

    out = []
    speed = np.abs(state.cases.speed)
    for j, r in enumerate(state.assembly.rows):
        d = state.row_displacement[:, j]
        f = state.row_force[:, j]
        ok = np.all(np.isfinite(d), axis=-1)
        ld = None
        if isinstance(r.bearing, BallBearing):
            held = np.where(ok[:, None], d, 0.0)
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                ld = combined.combined_analysis(r.bearing, np.zeros_like(held), speed, prescribed_displacement=held,
                                                on_failure="flag")
        lf = None
        if life and np.all(speed > 0):
            iso = np.where(ok[:, None], f, 0.0).copy()
            iso[:, 3:] = 0.0
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                lf = rating_life(r.bearing, iso, speed, load_distribution=ld if ld is not None else False,
                                 **life_options)
        out.append(BearingState(r.name, r.bearing, f, d, ld, lf))
    return out
