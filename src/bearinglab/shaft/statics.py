r"""The shaft system solved: the elastic shaft condensed to its bearing nodes, the bearings by Newton.

Assembly
--------
Assembly     the mesh, the bearing rows, springs and constraints, and the condensed shaft
assemble     a ShaftSystem -> Assembly (the shaft's stiffness condensed to the bearing nodes once)

Load cases
----------
Cases        speeds, load factors and point loads of a batch of load cases
load_cases   the cases of a system: its own speed and loads, or lists of them

Solution
--------
solve        every load case of a system at once: displacements, bearing loads, support loads
SystemState  its result
tangent      the tangent stiffness of the condensed system for given bearing stiffnesses

The shaft is linear: with its degrees of freedom split into those of the bearing nodes (B, five per
node: u_x, u_y, u_z, theta_x, theta_y), those held (rigid supports, the torsion reference) and the rest
(I), the free part is condensed once,

.. math::

   K_c = K_{BB} - K_{BI} K_{II}^{-1} K_{IB}, \qquad f_c = f_B - K_{BI} K_{II}^{-1} f_I,

(static condensation [1]_ section 6.3, Guyan's reduction without inertia: exact for the statics), so the
nonlinear system has only the bearing nodes' displacements u_B and the free freedoms u_H of the housing
springs as unknowns, whatever the number of elements:

.. math::

   K_c u_B + \sum_j P_j^T T_j F_j(d_j) = f_c, \qquad K_h u_H - \sum_j Q_j^T T_j F_j(d_j) = 0,
   \qquad d_j = T_j (P_j u_B - Q_j u_H) + o_j e_z,

with F_j the load bearing j carries at its ring displacement d_j and its tangent stiffness K_j from
:func:`bearinglab.reactions.bearing_reactions` (all bearings and all cases in one call per iteration).
Newton's method solves it for all cases at once, with the analytic tangent
[[K_c + sum P^T T K T P, -sum P^T T K T Q], [-sum Q^T T K T P, K_h + sum Q^T T K T Q]], Levenberg-Marquardt
damping where a step does not lower the residual (a bearing inside its clearance has no stiffness), a
trust region of half the groove-centre distance A per step for each bearing, and a line search. The rest
of the shaft follows, u_I = K_II^{-1} (f_I - K_IB u_B). A case is converged when the residual, moments
divided by the largest pitch radius, is below ``tol`` relative to the loads on the bearing nodes and the
bearings' loads together.

References
----------
.. [1] K.-J. Bathe, *Finite Element Procedures*, 2nd ed., 2014, section 8.2.4 (static condensation);
   R. J. Guyan, "Reduction of stiffness and mass matrices," AIAA J., vol. 3, no. 2, p. 380, 1965,
   doi:10.2514/3.2874.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import scipy.linalg

from .._validate import check_integer, check_positive
from ..errors import ConvergenceError, InputError
from .mesh import build_mesh, load_vectors, node_of
from .model import BearingSetSupport, BearingSupport, LinearSupport, RigidSupport
from .supports import bearing_rows, constrained_dofs, linear_springs

__all__ = ["Assembly", "Cases", "SystemState", "assemble", "load_cases", "solve", "tangent"]

#: relative residual of the system's equilibrium below which a case is converged
TOL = 1e-12
#: Newton iterations per case
MAX_ITER = 100
_LINE_SEARCH = 8  # step cuts (by 4)
_LAM_MIN, _LAM_MAX = 1e-14, 1e8  # Levenberg-Marquardt damping: start, and beyond which a case has failed
_NOISE = 64.0  # roundings of the elastic terms K_c u_B that a residual may hold and count as converged
_MOST_CASES = 1_000_000


class Assembly(NamedTuple):
    """A shaft system ready to solve: its mesh and the shaft condensed to the bearing nodes."""

    system: object
    """The ShaftSystem."""
    mesh: object
    """Its :class:`~bearinglab.shaft.mesh.Mesh`."""
    rows: tuple
    """The :class:`~bearinglab.shaft.supports.BearingRow` of every bearing."""
    stiffness: np.ndarray
    """The shaft's K with the linear supports' springs. [N/m, N/rad, N m/rad]"""
    constrained: np.ndarray
    """Global dofs held at zero."""
    coupled: np.ndarray
    """Global dofs of the bearing nodes (B), five per node."""
    internal: np.ndarray
    """The other free dofs (I)."""
    slot: np.ndarray
    """(n_rows,) each bearing's node among the bearing nodes."""
    housing_index: np.ndarray
    """(n_rows, 5) each bearing's housing freedoms in the unknowns (after u_B), -1 where held."""
    housing_stiffness: np.ndarray
    """(n_h,) the springs of the free housing freedoms (0 for a floating bearing's axial freedom)."""
    condensed: np.ndarray
    """K_c. [N/m, N/rad, N m/rad]"""
    transfer: np.ndarray
    """K_II^-1 K_IB. [-]"""
    flexibility: np.ndarray
    """K_II^-1."""
    length_scale: float
    """The largest pitch radius of the bearings (or the shaft's largest radius): moments over it. [m]"""
    trust: np.ndarray
    """(n_rows,) the largest change of a bearing's displacement in one Newton step. [m]"""
    notes: tuple
    """Warnings of the assembly."""

    @property
    def n_unknowns(self):
        """Unknowns of the nonlinear system: u_B and u_H."""
        return len(self.coupled) + len(self.housing_stiffness)


def _trust(bearing):
    """Half the groove-centre distance A = (f_i + f_o - 1) D: the step limit of the ring Newton of
    :mod:`bearinglab.quasistatic.combined`; 0.1 mm where the ball set is not known."""
    d, fi, fo = bearing.ball_diameter, bearing.inner_conformity, bearing.outer_conformity
    if None in (d, fi, fo):
        return 1e-4
    return 0.5 * (fi + fo - 1.0) * d


def assemble(system, extra=()):
    """Mesh a shaft system and condense its shaft to the bearing nodes.

    Parameters
    ----------
    system : ShaftSystem
    extra : sequence of float, optional
        Positions that must be nodes (for :func:`bearinglab.shaft.stiffness_at`). [m]

    Returns
    -------
    Assembly

    Raises
    ------
    InputError
        A mechanism: the supports leave the shaft free to move (their springs and constraints do not
        hold it, with every bearing node held).
    """
    extra = list(extra) + [s.position for s in system.supports if isinstance(s, BearingSetSupport)]
    mesh = build_mesh(system, extra)
    rows, notes = bearing_rows(system, mesh)
    n = 6 * len(mesh.z)
    k = mesh.stiffness.copy()
    for dof, kk in linear_springs(system, mesh):
        k[dof, dof] += kk
    held = np.array(constrained_dofs(system, mesh), dtype=int)
    nodes = sorted({r.node for r in rows})
    slot = np.array([nodes.index(r.node) for r in rows], dtype=int)
    coupled = np.array([6 * i + c for i in nodes for c in range(5)], dtype=int)
    free = np.setdiff1d(np.arange(n), np.concatenate([held, coupled]))
    h_index = np.full((len(rows), 5), -1, dtype=int)
    h_stiff = []
    m = len(coupled)
    for j, r in enumerate(rows):
        for c in range(5):
            if np.isfinite(r.housing[c]):
                h_index[j, c] = m + len(h_stiff)
                h_stiff.append(float(r.housing[c]))
    kii = k[np.ix_(free, free)]
    try:
        factor = scipy.linalg.cho_factor(kii, lower=True, check_finite=False)
        flex = scipy.linalg.cho_solve(factor, np.eye(len(free)), check_finite=False)
    except (np.linalg.LinAlgError, ValueError):
        raise InputError("supports: a mechanism: the supports do not hold the shaft (it can move as a rigid "
                         "body); add a support, or axial or tilt stiffness") from None
    flex = 0.5 * (flex + flex.T)
    kib = k[np.ix_(free, coupled)]
    transfer = flex @ kib
    kc = k[np.ix_(coupled, coupled)] - kib.T @ transfer
    kc = 0.5 * (kc + kc.T)
    pitch = [0.5 * r.bearing.pitch_diameter for r in rows if r.bearing.pitch_diameter]
    ell = max(pitch) if pitch else 0.5 * float(np.max(mesh.diameter))
    trust = np.array([_trust(r.bearing) for r in rows])
    return Assembly(system, mesh, tuple(rows), k, held, coupled, free, slot, h_index, np.array(h_stiff), kc,
                    transfer, flex, float(ell), trust, tuple(notes))


class Cases(NamedTuple):
    """A batch of load cases of one system."""

    speed: np.ndarray
    """(n,) signed shaft speed. [rad/s]"""
    factor: np.ndarray
    """(n,) factor on the loads, gears and pulleys (not on the weight). [-]"""
    point_loads: np.ndarray | None = None
    """(n, n_loads, 6) the point loads case by case, or None (the system's). [N, N m]"""


def load_cases(system, *, speed=None, factor=1.0, point_loads=None):
    """The load cases of a system: its own speed and loads, or lists of speeds, factors and point loads.

    Parameters
    ----------
    system : ShaftSystem
    speed : array_like, optional
        Signed speeds (default: the system's). [rad/s]
    factor : array_like, optional
        Factors on the loads, gears and pulleys (not the weight). [-]
    point_loads : array_like, optional
        (n, n_loads, 6) the point loads of ``system.loads`` case by case. [N, N m]

    Returns
    -------
    Cases
        Broadcast to one length.
    """
    w = np.atleast_1d(np.asarray(system.speed if speed is None else speed, dtype=float))
    f = np.atleast_1d(np.asarray(factor, dtype=float))
    lead = [w.shape[0], f.shape[0]]
    p = None
    if point_loads is not None:
        p = np.asarray(point_loads, dtype=float)
        if p.ndim != 3 or p.shape[1:] != (len(system.loads), 6):
            raise InputError(f"point_loads must have the shape (cases, {len(system.loads)}, 6), got {p.shape}")
        lead.append(p.shape[0])
    n = max(lead)
    if any(x not in (1, n) for x in lead) or w.ndim != 1 or f.ndim != 1:
        raise InputError(f"speed, factor and point_loads must be lists of one length (or one value), got {lead}")
    if n > _MOST_CASES:
        raise InputError(f"cases: at most {_MOST_CASES} in one batch, got {n}")
    for name, v in (("speed", w), ("factor", f)):
        if not np.all(np.isfinite(v)):
            raise InputError(f"{name} must be finite")
    if p is not None and not np.all(np.isfinite(p)):
        raise InputError("point_loads must be finite [N, N m]")
    if p is not None and p.shape[0] != n:
        p = np.broadcast_to(p, (n,) + p.shape[1:])
    return Cases(np.broadcast_to(w, (n,)).copy(), np.broadcast_to(f, (n,)).copy(), p)


class SystemState(NamedTuple):
    """The shaft system in equilibrium, for a batch of load cases (SI units; n cases)."""

    assembly: Assembly
    """What was solved."""
    cases: Cases
    """The load cases."""
    applied: np.ndarray
    """(n, 6 n_nodes) the nodal loads. [N, N m]"""
    displacement: np.ndarray
    """(n, n_nodes, 6) u_x, u_y, u_z [m], theta_x, theta_y, theta_z [rad] of every node."""
    housing: np.ndarray
    """(n, n_rows, 5) the displacement of each bearing's outer ring (its housing). [m, rad]"""
    row_displacement: np.ndarray
    """(n, n_rows, 5) each bearing's ring displacement in its own frame, d_j. [m, rad]"""
    row_force: np.ndarray
    """(n, n_rows, 5) the load each bearing carries, in its own frame. [N, N m]"""
    row_stiffness: np.ndarray
    """(n, n_rows, 5, 5) its tangent stiffness, own frame. [N/m, N/rad, N m/rad]"""
    support_loads: np.ndarray
    """(n, n_supports, 6) the load the shaft puts on each support, at its position (a set: its
    centre), shaft frame: F_x, F_y, F_z [N], M_x, M_y, M_z [N m]."""
    support_displacement: np.ndarray
    """(n, n_supports, 5) the shaft's displacement at each support relative to its housing (a bearing:
    the misalignment it sees), shaft frame. [m, rad]"""
    torsion_reaction: np.ndarray
    """(n,) the torque that holds the torsion reference (0 when the torques balance). [N m]"""
    converged: np.ndarray
    """(n,) bool."""
    residual: np.ndarray
    """(n,) relative residual of the equilibrium (moments over :attr:`Assembly.length_scale`). [-]"""
    iterations: np.ndarray
    """(n,) Newton iterations."""
    warnings: tuple
    """Messages."""


def _mv(a, x):
    """(n, q) rows times the matrix a (p, q) transposed, case by case (the same bits in any batch)."""
    return np.matmul(a[None, :, :], x[:, :, None])[:, :, 0]


def _scale(asm, size):
    """(size,) 1 for forces and translations, 1/l for the moments and rotations of the unknowns."""
    s = np.ones(size)
    nb = len(asm.coupled)
    s[:nb][np.arange(nb) % 5 >= 3] = 1.0 / asm.length_scale
    for j in range(len(asm.rows)):
        for c in (3, 4):
            if asm.housing_index[j, c] >= 0:
                s[asm.housing_index[j, c]] = 1.0 / asm.length_scale
    return s


def _relative(asm, x):
    """(n, n_rows, 5) each bearing's ring displacement d_j from the unknowns x (n, m)."""
    n = len(x)
    nb = len(asm.coupled)
    rows = asm.rows
    u = x[:, :nb].reshape(n, -1, 5)[:, asm.slot, :]
    h = np.zeros((n, len(rows), 5))
    mask = asm.housing_index >= 0
    h[:, mask] = x[:, asm.housing_index[mask]]
    t = np.array([r.transform for r in rows])
    d = t[None] * (u - h)
    d[:, :, 2] += np.array([r.offset for r in rows])[None]
    return d, u, h


def _evaluate(asm, x, fc, speed, deriv=True):
    """Residual (n, m) of the unknowns x, the bearings' reactions and (deriv) the tangent A (n, m, m)."""
    from ..reactions import bearing_reactions

    n, m = x.shape
    nb = len(asm.coupled)
    rows = asm.rows
    d, _, _ = _relative(asm, x)
    re = bearing_reactions([r.bearing for r in rows], d, np.abs(speed))
    t = np.array([r.transform for r in rows])
    tf = t[None] * re.force  # shaft frame
    res = np.zeros((n, m))
    res[:, :nb] = fc - _mv(asm.condensed, x[:, :nb])
    nh = len(asm.housing_stiffness)
    if nh:
        res[:, nb:] = -asm.housing_stiffness[None] * x[:, nb:]
    for j in range(len(rows)):
        b = 5 * asm.slot[j] + np.arange(5)
        res[:, b] -= tf[:, j]
        hj = asm.housing_index[j]
        ok = hj >= 0
        res[:, hj[ok]] += tf[:, j, ok]
    if not deriv:
        return res, re, None
    return res, re, tangent(asm, re.stiffness)


def tangent(asm, row_stiffness):
    """The tangent A (n, m, m) of the condensed system for the bearings' stiffness (n, n_rows, 5, 5).

    Parameters
    ----------
    asm : Assembly
    row_stiffness : ndarray
        (n, n_rows, 5, 5) each bearing's tangent stiffness in its own frame.

    Returns
    -------
    ndarray
        d(loads on the unknowns) / d(unknowns): [[K_c + sum P^T T K T P, -sum P^T T K T Q],
        [-sum Q^T T K T P, K_h + sum Q^T T K T Q]].
    """
    n = len(row_stiffness)
    nb, m = len(asm.coupled), asm.n_unknowns
    t = np.array([r.transform for r in asm.rows]).reshape(-1, 5)
    a = np.zeros((n, m, m))
    a[:, :nb, :nb] = asm.condensed
    if m > nb:
        a[:, np.arange(nb, m), np.arange(nb, m)] = asm.housing_stiffness
    for j in range(len(asm.rows)):
        kt = row_stiffness[:, j] * (t[j][:, None] * t[j][None, :])  # T K T
        b = 5 * asm.slot[j] + np.arange(5)
        hj = asm.housing_index[j]
        ok = np.flatnonzero(hj >= 0)
        a[:, b[:, None], b[None, :]] += kt
        if ok.size:
            h = hj[ok]
            a[:, b[:, None], h[None, :]] -= kt[:, :, ok]
            a[:, h[:, None], b[None, :]] -= kt[:, ok, :]
            a[:, h[:, None], h[None, :]] += kt[:, ok[:, None], ok[None, :]]
    return a


def _measure(asm, res, fc, re, x, sc):
    """Norm of the scaled residual, its relative value and the relative rounding floor of the residual."""
    t = np.array([r.transform for r in asm.rows])
    sb = sc[:5]
    nb = fc.shape[1]
    norm = np.linalg.norm(res * sc, axis=-1)
    loads = np.linalg.norm(fc * sc[:nb], axis=-1) + np.sum(np.linalg.norm(t[None] * re.force * sb, axis=-1), axis=-1)
    loads = np.maximum(loads, 1e-300)
    # the rounding floor of K_c u_B: the sizes of its terms, not of their sum (a stiff shaft moving as a rigid
    # body sums large terms to almost nothing); _NOISE roundings of them
    terms = np.linalg.norm(_mv(np.abs(asm.condensed), np.abs(x[:, :nb])) * sc[:nb], axis=-1)
    return norm, norm / loads, _NOISE * np.finfo(float).eps * terms / loads


def _step_limit(asm, dx):
    """The fraction of the step dx (n, m) that keeps every bearing's change within its trust length."""
    n = len(dx)
    nb = len(asm.coupled)
    du = dx[:, :nb].reshape(n, -1, 5)[:, asm.slot, :]
    dh = np.zeros_like(du)
    mask = asm.housing_index >= 0
    dh[:, mask] = dx[:, asm.housing_index[mask]]
    dd = du - dh  # T only flips signs
    move = np.maximum(np.max(np.abs(dd[:, :, :3]), axis=-1),
                      asm.length_scale * np.max(np.abs(dd[:, :, 3:]), axis=-1))
    return np.minimum(1.0, np.min(asm.trust[None] / np.maximum(move, 1e-300), axis=-1))


def _newton(asm, fc, speed, tol, max_iter):
    """Damped Newton on the bearing nodes, every case at once; (x, converged, iterations, residual)."""
    n = len(fc)
    m = asm.n_unknowns
    sc = _scale(asm, m)
    x = np.zeros((n, m))
    # the offsets alone: a case with preloaded bearings starts in its preload
    res, re, a = _evaluate(asm, x, fc, speed)
    norm, rel, floor = _measure(asm, res, fc, re, x, sc)
    lam = np.full(n, _LAM_MIN)
    it = np.zeros(n, dtype=int)
    failed = np.zeros(n, dtype=bool)
    eye = np.eye(m)
    for _ in range(max_iter):
        act = np.flatnonzero((rel > np.maximum(tol, floor)) & ~failed)
        if not act.size:
            break
        it[act] += 1
        As = a[act] * sc[None, :, None] * sc[None, None, :]
        diag = np.max(np.abs(np.diagonal(As, axis1=1, axis2=2)), axis=1)
        diag = np.where(diag > 0, diag, 1.0)
        rhs = (res[act] * sc)[:, :, None]
        dx = np.linalg.solve(As + (lam[act] * diag)[:, None, None] * eye, rhs)[:, :, 0] * sc
        frac = _step_limit(asm, dx)
        dx *= frac[:, None]
        trial = np.ones(act.size)
        todo = np.arange(act.size)
        done = np.zeros(act.size, dtype=bool)
        for _cut in range(_LINE_SEARCH):
            cand = act[todo]
            xt = x[cand] + trial[todo, None] * dx[todo]
            r_t, re_t, a_t = _evaluate(asm, xt, fc[cand], speed[cand])
            n_t, rel_t, fl_t = _measure(asm, r_t, fc[cand], re_t, xt, sc)
            good = ((n_t < norm[cand]) | (rel_t <= np.maximum(tol, fl_t))) & np.all(np.isfinite(r_t), axis=-1)
            if good.any():
                g = cand[good]
                x[g], res[g], a[g], norm[g], rel[g] = xt[good], r_t[good], a_t[good], n_t[good], rel_t[good]
                floor[g] = fl_t[good]
                done[todo[good]] = True
            todo = todo[~good]
            if not todo.size:
                break
            trial[todo] *= 0.25
        lam[act[done]] = np.maximum(lam[act[done]] * 0.25, _LAM_MIN)
        stuck = act[~done]
        lam[stuck] *= 16.0
        failed |= lam > _LAM_MAX
    return x, rel <= np.maximum(tol, floor), it, rel, res


def solve(system, cases=None, *, on_failure="raise", tol=TOL, max_iter=MAX_ITER, extra=(), assembly=None):
    """Solve a shaft system for a batch of load cases: bearings, shaft and supports in equilibrium.

    Parameters
    ----------
    system : ShaftSystem
    cases : Cases, optional
        Speeds, load factors and point loads (:func:`load_cases`); default the system's own case.
    on_failure : {"raise", "flag"}, optional
        A case that does not converge raises :class:`~bearinglab.errors.ConvergenceError`, or gets NaN
        and ``converged`` False.
    tol : float, optional
        Relative residual of the equilibrium. [-]
    max_iter : int, optional
        Newton iterations.
    extra : sequence of float, optional
        Positions that must be nodes. [m]
    assembly : Assembly, optional
        The system already assembled (:func:`assemble`), to solve more cases.

    Returns
    -------
    SystemState

    Examples
    --------
    >>> from bearinglab import catalog
    >>> from bearinglab.shaft.model import BearingSupport, PointLoad, Section, Shaft, ShaftSystem
    >>> b = catalog.get("6206")
    >>> s = ShaftSystem(Shaft((Section(0.3, 0.03),)),
    ...                 (BearingSupport("A", 0.02, b, axial=True), BearingSupport("B", 0.28, b)),
    ...                 loads=(PointLoad(0.15, fy=-2000.0),))
    >>> r = solve(s)
    >>> print(np.round(r.support_loads[0, :, 1], 3))
    [-1000. -1000.]
    """
    if on_failure not in ("raise", "flag"):
        raise InputError(f"on_failure must be one of ['raise', 'flag'], got {on_failure!r}")
    check_positive("tol", tol, "-")
    max_iter = int(check_integer("max_iter", max_iter, 1))
    asm = assemble(system, extra) if assembly is None else assembly
    if cases is None:
        cases = load_cases(system)
    n = len(cases.speed)
    f = load_vectors(system, asm.mesh, cases.speed, cases.factor, cases.point_loads)
    torque = f[:, 5::6].sum(axis=1)
    f_i = f[:, asm.internal]
    u0 = _mv(asm.flexibility, f_i)
    nb = len(asm.coupled)
    rows = asm.rows
    notes = list(asm.notes)
    if rows:
        fc = f[:, asm.coupled] - _mv(asm.transfer.T, f_i)
        x, ok, it, rel, _ = _newton(asm, fc, cases.speed, tol, max_iter)
        _, re, _ = _evaluate(asm, x, fc, cases.speed, deriv=False)
        if not np.all(re.converged):
            notes.append("a bearing's internal solve (its balls at speed) did not converge in "
                         f"{int(np.sum(~re.converged))} bearing case(s)")
        d, _, h = _relative(asm, x)
        force, stiff = re.force, re.stiffness
    else:
        x = np.zeros((n, 0))
        ok, it, rel = np.ones(n, dtype=bool), np.zeros(n, dtype=int), np.zeros(n)
        d = h = force = np.zeros((n, 0, 5))
        stiff = np.zeros((n, 0, 5, 5))
    if on_failure == "raise" and not ok.all():
        k = int(np.flatnonzero(~ok)[0])
        raise ConvergenceError("shaft.solve", iterations=int(it[k]), residual=float(rel[k]), estimate=x[k],
                               reason=f"{int((~ok).sum())} of {n} load cases did not converge (first: case {k}, "
                                      f"speed {cases.speed[k]:g} rad/s, factor {cases.factor[k]:g}); a bearing "
                                      "that carries no load inside its clearance leaves the shaft free")
    u = np.zeros((n, 6 * len(asm.mesh.z)))
    if rows:
        u[:, asm.coupled] = x[:, :nb]
        u[:, asm.internal] = u0 - _mv(asm.transfer, x[:, :nb])
    else:
        u[:, asm.internal] = u0
    reaction = np.zeros_like(u)  # the reaction each held dof needs, on the shaft (K u - f; held rows only)
    reaction[:, asm.constrained] = _mv(asm.stiffness[asm.constrained], u) - f[:, asm.constrained]
    sup_loads, sup_disp = _support_results(asm, u, reaction, force, h)
    torsion = reaction[:, 5]
    bad = ~ok
    for arr in (u, d, h, force, stiff, sup_loads, sup_disp):
        arr[bad] = np.nan
    return SystemState(asm, cases, f, u.reshape(n, -1, 6), h, d, force, stiff, sup_loads, sup_disp, torsion + 0 * torque,
                       ok, rel, it, tuple(dict.fromkeys(notes)))


def _support_results(asm, u, reaction, force, housing):
    """Per support: the load the shaft puts on it and its displacement relative to its housing."""
    system, z = asm.system, asm.mesh.z
    n = len(u)
    loads = np.zeros((n, len(system.supports), 6))
    disp = np.zeros((n, len(system.supports), 5))
    t = np.array([r.transform for r in asm.rows]) if asm.rows else np.zeros((0, 5))
    for k, s in enumerate(system.supports):
        i = node_of(z, s.position)
        un = u[:, 6 * i:6 * i + 5]
        if isinstance(s, (BearingSupport, BearingSetSupport)):
            js = [j for j, r in enumerate(asm.rows) if r.support == k]
            for j in js:
                fj = t[j] * force[:, j]
                dz = asm.rows[j].position - s.position
                loads[:, k, :5] += fj
                loads[:, k, 3] += -dz * fj[:, 1]
                loads[:, k, 4] += dz * fj[:, 0]
            disp[:, k] = un - np.mean(housing[:, js], axis=1)
        elif isinstance(s, LinearSupport):
            kk = np.array([s.radial_stiffness, s.radial_stiffness, s.axial_stiffness or 0.0, s.tilt_stiffness,
                           s.tilt_stiffness])
            loads[:, k, :5] = kk * un
            if s.axial and s.axial_stiffness is None:
                loads[:, k, 2] = -reaction[:, 6 * i + 2]
            disp[:, k] = un
        elif isinstance(s, RigidSupport):
            loads[:, k, 0:2] = -reaction[:, 6 * i:6 * i + 2]
            if s.axial:
                loads[:, k, 2] = -reaction[:, 6 * i + 2]
            disp[:, k] = un
    return loads + 0.0, disp
