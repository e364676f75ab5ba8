r"""Roller bearing under combined load: the five-degree-of-freedom load distribution of the slice model, batched.

The inner ring carries the loads (F_x, F_y, F_z, M_x, M_y) and moves by (delta_x, delta_y, delta_z,
theta_x, theta_y) relative to the fixed outer ring, as in the ball-bearing model
(:mod:`bearinglab.quasistatic.combined`, the same conventions and the same batched 5 x 5 kernels of
:mod:`bearinglab.quasistatic._ring`). Each roller is cut into n_s laminae (ISO/TS 16281); a lamina's
approach follows from the ring displacement at its position along the roller, less the gap and the profile
drop, and its load from the line-contact law of :mod:`bearinglab.rollers.contact`. Ring tilt and
misalignment load the laminae of a roller unevenly: edge loading.

Geometry
--------
RollerSet           the checked geometry of the slice model of one bearing
roller_set          build it (rollers, diameters, length, cup angle, gap, profile drops, slices, E')
roller_azimuths     psi_j = phi0 + 2 pi j / Z

Load distribution
-----------------
load_distribution   displacement, roller and lamina loads, pressures and 5 x 5 stiffness, batched over cases
equilibrium         load, residual and tangent stiffness at given displacements (no solve)
RollerLoadDistribution, Equilibrium   their results

Conventions (docs/theory/roller_bearings.md): z is the bearing axis; roller j sits at psi_j from +x. A
lamina at position s along its roller (from the roller's middle; s > 0 towards +z) approaches by

.. math::
    \delta_{jk} = \cos\alpha\,(\delta_x\cos\psi_j + \delta_y\sin\psi_j) + \sin\alpha\,\delta_z
                  + \left(\tfrac{d_m}{2}\sin\alpha - s_k\right)(\theta_x\sin\psi_j - \theta_y\cos\psi_j)
                  - g_0 - 2\,P(s_k)

along the cup-raceway normal n = (cos alpha e_r, sin alpha e_z); alpha = 0 for a cylindrical roller
bearing (then the tilt term is s_k times the misalignment of the raceways at that roller, ISO/TS 16281's
x_k tan psi_j), g_0 is the gap at the concentric position ((e/2) cos alpha for a diametral clearance e;
negative: preload) and P the roller profile drop. A tapered bearing so described is loaded by a thrust
F_z > 0 on the inner ring (its cup narrows towards +z). The inner ring carries sum_jk q_jk n at the
laminae: by the roller's own equilibrium at rest, the cone and rib contacts pass on the cup's load and
moment, so this is the load of the ring whatever the cone angle (:func:`bearinglab.rollers.geometry.
tapered_angles`). The stiffness matrix is d(load)/d(displacement) in N/m, N/rad, N m/m and N m/rad.

A cylindrical roller bearing carries no axial load on its raceways: its delta_z is held (at 0, or where
``prescribed_displacement`` puts it). An NJ carries a thrust F_z >= 0 on its ribs and an NUP one of
either sign; that rib load is reported (``rib_load``) and not part of the slice model or its stiffness
(MESYS models the roller-end/rib contact; here the ribs are rigid). N and NU carry none.

References
----------
.. [1] ISO/TS 16281:2008, *Rolling bearings -- Methods for calculating the modified reference rating life
   for universally loaded bearings*, clause 8 (the laminae, their deflection with tilt and clearance, the
   equilibrium of the ring, eqs. (38)-(46), as transcribed in github.com/minzhun/ISO16281).
.. [2] T. A. Harris and M. N. Kotzalas, *Advanced Concepts of Bearing Technology*, 5th ed., CRC Press,
   2006, ch. 1 (rigid rings in five degrees of freedom, roller bearings with tilt and slices).
"""

from __future__ import annotations

import contextlib
import math
from typing import NamedTuple

import numpy as np

from .._validate import as_float, check_finite, check_integer, check_positive
from ..errors import ConvergenceError, InputError
from ..quasistatic import _ring
from . import contact, geometry

__all__ = [
    "AXIAL_SUPPORTS",
    "Equilibrium",
    "RollerLoadDistribution",
    "RollerSet",
    "equilibrium",
    "load_distribution",
    "roller_azimuths",
    "roller_set",
]

#: How the bearing carries axial load: ``"raceways"`` (tapered: the laminae, along the cup normal),
#: ``"none"`` (N, NU: free axially), ``"ribs-positive"`` (NJ: F_z >= 0 on rigid ribs), ``"ribs"`` (NUP:
#: either sign on rigid ribs).
AXIAL_SUPPORTS = ("raceways", "none", "ribs-positive", "ribs")

TOL = 1e-12  # relative residual |F - F(u)| / max(|F|, sum of roller loads), moments divided by d_m/2
MAX_ITER = 200  # ring Newton iterations per case (4-8 typical; the tail: light loads with clearance)
_RESOLVABLE = 1e-9  # every returned case in equilibrium to 1e-9 relative (issue 32), rounding or not
_NOISE = 4.0  # a residual within this many rounding floors is converged
_LINE_SEARCH = 10  # step cuts (by 4) of the line search
_LAM_MAX = 1e6  # Levenberg-Marquardt damping beyond which a case has failed
_CHUNK = 1024  # cases per pass (the (cases, rollers, slices) arrays stay in cache)
_EPS = np.finfo(float).eps
_ONE_BLAS_THREAD = 256  # cases from which the solve runs its small matrix products on one BLAS thread


class RollerSet(NamedTuple):
    """The checked geometry of the slice model of one roller bearing (SI)."""

    rollers: int
    """Z. [-]"""
    roller_diameter: float
    """D_we. [m]"""
    roller_length: float
    """L_we, the effective length. [m]"""
    pitch_diameter: float
    """D_pw = d_m. [m]"""
    contact_angle: float
    """alpha (the cup angle of a tapered bearing, 0 for a cylindrical one). [rad]"""
    normal_gap: float
    """g_0, the gap along the cup normal at the concentric position (negative: interference). [m]"""
    slice_position: np.ndarray
    """(n_s,) s_k from the roller's middle, positive towards +z. [m]"""
    drop: np.ndarray
    """(n_s,) the roller profile drop P(s_k) (the approach loses 2 P). [m]"""
    slice_constant: float
    """c_s of :func:`bearinglab.rollers.contact.slice_stiffness`. [N/m^(10/9)]"""
    reduced_modulus: float
    """E' of the roller-ring pair, for the pressures. [Pa]"""
    azimuth: np.ndarray
    """(Z,) psi_j. [rad]"""
    axial_support: str
    """One of :data:`AXIAL_SUPPORTS`."""


def roller_azimuths(rollers, first_roller_angle=0.0):
    """Azimuths of the rollers, psi_j = phi0 + 2 pi j / Z, from +x towards +y.

    Parameters
    ----------
    rollers : int
        Z. [-]
    first_roller_angle : float, optional
        phi0. [rad]

    Returns
    -------
    ndarray
        (Z,) psi. [rad]

    Examples
    --------
    >>> print(np.degrees(roller_azimuths(4)))
    [  0.  90. 180. 270.]
    """
    z = int(check_integer("rollers", rollers, 1))
    return _ring.azimuths(z, float(as_float("first_roller_angle", first_roller_angle)))


def roller_set(rollers, roller_diameter, roller_length, pitch_diameter, *, contact_angle=0.0, normal_gap=0.0,
               drop=None, n_slices=30, reduced_modulus=2.28e11, first_roller_angle=0.0, axial_support=None,
               slice_constant=None):
    r"""The checked geometry of the slice model of one bearing.

    Parameters
    ----------
    rollers : int
        Z (per row), >= 3. [-]
    roller_diameter : float
        D_we (the middle of a tapered roller). [m]
    roller_length : float
        L_we, the effective length. [m]
    pitch_diameter : float
        D_pw > D_we. [m]
    contact_angle : float, optional
        alpha: 0 for a cylindrical roller bearing, the cup angle in (0, 45 deg] for a tapered one. [rad]
    normal_gap : float, optional
        g_0 along the cup normal at the concentric position; (e/2) cos alpha for a diametral clearance e;
        negative for an interference (preload). [m]
    drop : array_like, optional
        (n_s,) the profile drop at the slice centres (:mod:`bearinglab.rollers.geometry`); 0 (a straight
        roller) by default. [m]
    n_slices : int, optional
        n_s, at least 30 recommended (ISO/TS 16281). [-]
    reduced_modulus : float, optional
        E' of roller and ring, for the pressures (the stiffness is ISO/TS 16281's constant of steel). [Pa]
    first_roller_angle : float, optional
        phi0. [rad]
    axial_support : str, optional
        One of :data:`AXIAL_SUPPORTS`; by default ``"raceways"`` for alpha > 0 and ``"none"`` for alpha = 0.
    slice_constant : float, optional
        c_s in place of :func:`bearinglab.rollers.contact.slice_stiffness` (another material). [N/m^(10/9)]

    Returns
    -------
    RollerSet

    Examples
    --------
    >>> rs = roller_set(14, 11e-3, 9.6e-3, 60.5e-3)
    >>> print(rs.rollers, len(rs.slice_position), rs.axial_support)
    14 30 none
    """
    z = int(check_integer("rollers", rollers, 3))
    d = float(check_positive("roller_diameter", roller_diameter, "m"))
    length = float(check_positive("roller_length", roller_length, "m"))
    dpw = float(check_positive("pitch_diameter", pitch_diameter, "m"))
    alpha = float(as_float("contact_angle", contact_angle))
    if not 0.0 <= alpha <= math.radians(45.0) + 1e-12:
        raise InputError(f"contact_angle must be in [0, 45] [deg] for a roller bearing, got {math.degrees(alpha):g} deg")
    if not dpw > d:
        raise InputError(f"pitch_diameter must be > roller_diameter [mm], got {dpw * 1e3:g} mm with "
                         f"roller_diameter = {d * 1e3:g} mm")
    gap = float(check_finite("normal_gap", normal_gap, "m"))
    if abs(gap) > 0.5 * d:
        raise InputError(f"normal_gap must be in (-{0.5 * d * 1e3:g}, {0.5 * d * 1e3:g}) [mm] (half a roller "
                         f"diameter), got {gap * 1e3:g} mm")
    n = int(check_integer("n_slices", n_slices, 1))
    s = geometry.slice_positions(length, n)
    p = np.zeros(n) if drop is None else np.array(as_float("drop", drop), dtype=float).reshape(-1)
    if p.shape != (n,):
        raise InputError(f"drop must hold one value per slice ({n}), got {p.size}")
    if not np.all(np.isfinite(p)) or np.any(p < 0):
        raise InputError(f"drop must be finite and >= 0 [um], got {float(p[~(np.isfinite(p) & (p >= 0))][0]) * 1e6:g} um")
    if axial_support is None:
        axial_support = "raceways" if alpha > 0 else "none"
    if axial_support not in AXIAL_SUPPORTS:
        raise InputError(f"axial_support must be one of {list(AXIAL_SUPPORTS)}, got {axial_support!r}")
    if (axial_support == "raceways") != (alpha > 0):
        raise InputError("axial_support: only a bearing with contact_angle > 0 carries axial load on its raceways")
    c = contact.slice_stiffness(length, n) if slice_constant is None else float(
        check_positive("slice_constant", slice_constant, "N/m^(10/9)"))
    ep = float(check_positive("reduced_modulus", reduced_modulus, "Pa"))
    return RollerSet(z, d, length, dpw, alpha, gap, s, p, float(c), ep, roller_azimuths(z, first_roller_angle),
                     axial_support)


class _Kernel(NamedTuple):
    """The arrays of the batched evaluation (private)."""

    g: np.ndarray  # (Z, 5) d(roller approach) / du at the roller's middle
    t: np.ndarray  # (Z, 5) d(approach) / du per metre along the roller
    gg: np.ndarray  # (Z, 25) outer products for the stiffness
    gt: np.ndarray
    tt: np.ndarray
    s: np.ndarray  # (n_s,)
    s2: np.ndarray
    base: np.ndarray  # (n_s,) -g0 - 2 P(s_k)
    c: float
    dm: float
    arm: np.ndarray  # (5,) moment arms of the scaled residual
    resolution: float  # [N] the load of an approach of one rounding of the gap or drop on every lamina
    s_max: float  # max |s_k|
    base_max: float  # max_k (-g0 - 2 P(s_k))
    base_abs: float  # max_k |-g0 - 2 P(s_k)|
    gt_cols: np.ndarray  # (5, 2Z) [g.T, t.T]: the approaches at the middles and their slopes in one product
    force_rows: np.ndarray  # (2Z, 5) [g; t]: the reaction from the roller loads and moments in one product
    stiff_blocks: tuple  # per K_0, K_1, K_2: (columns of the m entries it reaches, its (Z, those) weights)
    stiff_upper: np.ndarray  # (m,) the flat 5 x 5 index of the stiffness's distinct non-zero entries
    stiff_lower: np.ndarray  # (m,) the flat index of each one's mirror image below the diagonal


def _one_blas_thread(n):
    """One BLAS thread for the products of a batch of n cases (from :data:`_ONE_BLAS_THREAD`; as
    :func:`bearinglab.runout.tolerances.monte_carlo_chunk` does): the (n, Z) x (Z, 25) products are too narrow to
    share, and on a busy machine OpenBLAS's threads made the solve 1.5-3 times slower (bench/rollers.py). The
    results are the same bits either way."""
    if n < _ONE_BLAS_THREAD:
        return contextlib.nullcontext()
    from threadpoolctl import threadpool_limits

    return threadpool_limits(limits=1, user_api="blas")


def _kernel(rs):
    psi, a = rs.azimuth, rs.contact_angle
    cp, sp, ca, sa = np.cos(psi), np.sin(psi), math.cos(a), math.sin(a)
    half = 0.5 * rs.pitch_diameter
    zero = np.zeros_like(psi)
    g = np.stack([ca * cp, ca * sp, np.full_like(psi, sa), half * sa * sp, -half * sa * cp], axis=1)
    t = np.stack([zero, zero, zero, -sp, cp], axis=1)
    gg = (g[:, :, None] * g[:, None, :]).reshape(-1, 25)
    gt = (g[:, :, None] * t[:, None, :] + t[:, :, None] * g[:, None, :]).reshape(-1, 25)
    tt = (t[:, :, None] * t[:, None, :]).reshape(-1, 25)
    s = np.ascontiguousarray(rs.slice_position)
    # the rounding of an approach near contact is eps times the gap or the drop it is measured against
    size = max(abs(rs.normal_gap), 2.0 * float(np.max(rs.drop)), np.finfo(float).tiny)
    resolution = _NOISE * rs.rollers * len(s) * rs.slice_constant * (_EPS * size) ** (10.0 / 9.0)
    base = -rs.normal_gap - 2.0 * rs.drop
    # gg, gt and tt are symmetric to the bit (g_i g_j = g_j g_i; g_i t_j + t_i g_j is the same sum both ways), so
    # the products compute the entries on and above the diagonal that are not zero for every roller and mirror
    # them, each of K_0, K_1, K_2 only into the entries it reaches (a cylindrical bearing: 3, 4 and 3 of 25):
    # a third of the work of the full (n, 3Z) x (3Z, 25) product, the solve's costliest step
    rows = np.concatenate([gg, gt, tt])
    upper = np.array([5 * i + j for i in range(5) for j in range(i, 5) if np.any(rows[:, 5 * i + j] != 0.0)])
    lower = (upper % 5) * 5 + upper // 5
    blocks = []
    for block in (gg, gt, tt):
        reach = np.flatnonzero(np.any(block[:, upper] != 0.0, axis=0))
        blocks.append((reach, np.ascontiguousarray(block[:, upper[reach]])))
    return _Kernel(g, t, gg, gt, tt, s, s * s, base, rs.slice_constant,
                   rs.pitch_diameter, np.array([1.0, 1.0, 1.0, 2.0 / rs.pitch_diameter, 2.0 / rs.pitch_diameter]),
                   resolution, float(np.max(np.abs(s))), float(np.max(base)), float(np.max(np.abs(base))),
                   np.ascontiguousarray(np.concatenate([g.T, t.T], axis=1)), np.concatenate([g, t]),
                   tuple(blocks), upper, lower)


def _evaluate(kn, u, deriv=True, slices=False):
    """Reaction F(u) (n, 5), tangent stiffness (n, 5, 5), lamina loads (n, Z, n_s) (with ``slices``, else None),
    roller loads (n, Z) and a rounding scale of the reaction (n,), for (n, 5) displacements u.

    Only the rollers that can touch are sliced: a roller whose largest possible approach
    g.u + |t.u| max|s| + max(-g0 - 2P) is <= 0 carries nothing (about half of them under a radial load).
    Every row is computed from its own numbers alone (gathered, summed along its laminae, scattered back), so a
    case gives the same bits in any batch.
    """
    n, z = len(u), kn.g.shape[0]
    gtu = _ring.rowwise(u, kn.gt_cols)  # (n, 2Z)
    gu, tu = gtu[:, :z], gtu[:, z:]
    reach = gu + np.abs(tu) * kn.s_max + kn.base_max
    live = np.flatnonzero(reach > 0)
    roller, moment = np.zeros(n * z), np.zeros(n * z)
    k0, k1, k2 = np.zeros(n * z), np.zeros(n * z), np.zeros(n * z)
    q_all = np.zeros((n * z, len(kn.s))) if slices else None
    if live.size:
        gl, tl = gu.ravel()[live], tu.ravel()[live]
        delta = np.multiply.outer(tl, kn.s)  # (m, n_s): g.u + (t.u) s_k - g0 - 2 P(s_k)
        delta += gl[:, None]
        delta += kn.base
        q, k = contact._slice_loads_into(delta, kn.c)
        # sums along each row's laminae (einsum: one loop per row, the same for any number of rows; BLAS is
        # slower on these tall, narrow arrays and rounds a single row differently)
        roller[live] = np.einsum("ij->i", q)
        moment[live] = np.einsum("ij,j->i", q, kn.s)
        k0[live] = np.einsum("ij->i", k)
        if deriv:
            k1[live] = np.einsum("ij,j->i", k, kn.s)
            k2[live] = np.einsum("ij,j->i", k, kn.s2)
        if slices:
            q_all[live] = q
    roller, moment, k0 = roller.reshape(n, z), moment.reshape(n, z), k0.reshape(n, z)
    force = _ring.rowwise(np.concatenate([roller, moment], axis=1), kn.force_rows)
    stiff = None
    if deriv:
        entries = np.zeros((n, len(kn.stiff_upper)))
        for (reach, weights), kk in zip(kn.stiff_blocks, (k0, k1.reshape(n, z), k2.reshape(n, z)), strict=True):
            if reach.size:  # K_0's, then K_1's, then K_2's share of each entry: one order for every case
                entries[:, reach] += _ring.rowwise(kk, weights)
        stiff = np.zeros((n, 25))
        stiff[:, kn.stiff_upper] = entries
        stiff[:, kn.stiff_lower] = entries
        stiff = stiff.reshape(-1, 5, 5)
    # the rounding of an approach is eps times the size of the terms it is the difference of (bounded per roller)
    noise = np.sum(k0 * (np.abs(gu) + np.abs(tu) * kn.s_max + kn.base_abs), axis=1) * _EPS
    return force, stiff, None if q_all is None else q_all.reshape(n, z, -1), roller, noise


def _measure(arm, loads, force, total, noise, free, resolution=0.0):
    """Residual norm [N], relative residual and relative rounding floor (capped at 1e-9); ``total`` is the sum
    of the roller loads of each case, ``noise`` the rounding of its reaction. A residual below ``resolution``
    [N] (what all laminae carry at an approach of one rounding of the gap or of the profile drop, about
    1e-13 N) is no residual: such loads are below what the geometry resolves, and the relative residual is
    set to 0."""
    diff = (loads - force) if free is None else (loads - force) * free
    res = np.linalg.norm(diff * arm, axis=-1)
    scale = np.maximum(np.linalg.norm(loads * arm, axis=-1), total)
    with np.errstate(invalid="ignore", divide="ignore"):
        rel = np.where(res <= resolution, 0.0, np.where(scale > 0, res / scale, res))
        floor = np.where(scale > 0, _NOISE * noise / scale, 0.0)
    return res, rel, np.minimum(floor, _RESOLVABLE)


def _start(rs, kn, loads):
    """Start of the ring Newton: each load component alone on uniformly loaded rollers (Stribeck's 4.08/Z
    for a radial load on line contacts, all rollers for a thrust)."""
    big_k = rs.slice_constant * len(rs.slice_position)  # Q = K delta^(10/9) of a uniformly loaded roller
    a = rs.contact_angle
    z = rs.rollers
    fr = np.hypot(loads[:, 0], loads[:, 1])
    mm = np.hypot(loads[:, 3], loads[:, 4])
    gap = rs.normal_gap + 2.0 * float(np.min(rs.drop))  # the least approach at which a lamina touches
    u = np.zeros_like(loads)
    # the roller nearest the load direction lies within pi/Z of it: reach it
    dr = np.where(fr > 0, (max(gap, 0.0) + (4.08 * fr / (z * math.cos(a) * big_k)) ** 0.9)
                  / (math.cos(a) * math.cos(math.pi / z)), 0.0)
    with np.errstate(invalid="ignore", divide="ignore"):
        u[:, 0:2] = np.where(fr[:, None] > 0, loads[:, 0:2] / fr[:, None] * dr[:, None], 0.0)
    if a > 0:
        fz = np.maximum(loads[:, 2], 0.0)
        u[:, 2] = np.where(fz > 0, (gap + (fz / (z * math.sin(a) * big_k)) ** 0.9) / math.sin(a), gap / math.sin(a))
    # tilt: a linear spring at the approach the other loads give (or 1 um), every lamina in contact
    ref = np.maximum(np.max(np.abs(u[:, :3]), axis=1), 1e-6)
    k_lin = (10.0 / 9.0) * big_k * ref ** (1.0 / 9.0)
    arm2 = (0.5 * rs.pitch_diameter * math.sin(a)) ** 2 + rs.roller_length**2 / 12.0
    k_tilt = 0.5 * z * k_lin * arm2
    # a moment that outweighs the radial load (as a force at the roller ends) must first close the gap and the
    # profile drop at the roller ends by the tilt: the rollers it loads are not the ones the radial load reaches
    lever = 0.5 * rs.pitch_diameter * math.sin(a) + 0.5 * rs.roller_length
    closing = (max(rs.normal_gap, 0.0) + 2.0 * float(max(rs.drop[0], rs.drop[-1]))) / lever
    closing = np.where(mm > fr * lever, closing, 0.0)
    with np.errstate(invalid="ignore", divide="ignore"):
        tilt = np.where(mm[:, None] > 0, loads[:, 3:5] / mm[:, None] * (mm / k_tilt + closing)[:, None], 0.0)
    u[:, 3:5] = np.clip(tilt, -0.05 * rs.roller_diameter / rs.roller_length, 0.05 * rs.roller_diameter / rs.roller_length)
    return u


def _newton(evaluate, arm, loads, u0, free, tol, max_iter, limit, span, resolution=0.0):
    """Damped Newton (Levenberg-Marquardt, the kernels of :mod:`bearinglab.quasistatic._ring`) with a line
    search on |F - F(u)|, all cases together, each with its own damping.

    ``evaluate(u)`` gives the reaction (n, 5), the stiffness (n, 5, 5), the sum of the roller loads (n,) and the
    rounding of the reaction (n,); ``arm`` the residual's scale (moments / (d_m/2)); ``free`` (n, 5) 1.0 for a
    freedom under a given load, 0.0 for one held at u0; a step moves no lamina by more than ``limit`` [m]
    (``span`` the lever of a tilt); ``resolution`` of :func:`_measure`. Returns u, converged, iterations and the
    relative residual.
    """
    n = len(loads)
    u = u0.copy()
    it = np.zeros(n, dtype=int)
    lam = np.zeros(n)
    force, stiff, total, noise = evaluate(u)
    norm, rel, floor = _measure(arm, loads, force, total, noise, free, resolution)
    done = rel <= np.maximum(tol, floor)
    loaded = np.any(loads * free != 0, axis=1)
    dm = 2.0 / arm[3]
    for _ in range(max_iter):
        act = np.flatnonzero(~done & (lam <= _LAM_MAX))
        if act.size == 0:
            break
        it[act] += 1
        du = _ring.lm_step(_ring.hold(stiff[act], free[act]), (loads[act] - force[act]) * free[act], lam[act], dm)
        move = np.hypot(du[:, 0], du[:, 1]) + np.abs(du[:, 2]) + span * np.hypot(du[:, 3], du[:, 4])
        with np.errstate(divide="ignore", invalid="ignore"):
            t = np.where(move > 0, np.minimum(1.0, limit / move), 1.0)
        full = t == 1.0
        pending = np.arange(act.size)
        for _ls in range(_LINE_SEARCH):
            sel = act[pending]
            trial = u[sel] + t[pending, None] * du[pending]
            f_t, k_t, tot_t, n_t = evaluate(trial)
            nm_t, rel_t, fl_t = _measure(arm, loads[sel], f_t, tot_t, n_t, free[sel], resolution)
            good = (nm_t < norm[sel] * (1.0 - 1e-4 * t[pending])) | (rel_t <= np.maximum(tol, fl_t))
            # a loaded ring that loses every contact has no stiffness to come back with: not a step to take
            good &= (tot_t > 0) | ~loaded[sel]
            g = sel[good]
            u[g], force[g], stiff[g], norm[g], rel[g], floor[g] = (trial[good], f_t[good], k_t[good], nm_t[good],
                                                                   rel_t[good], fl_t[good])
            pending = pending[~good]
            if pending.size == 0:
                break
            t[pending] *= 0.25
            full[pending] = False
        _ring.damp(lam, act, full, pending)
        done = rel <= np.maximum(tol, floor)
    return u, done, it, rel


class RollerLoadDistribution(NamedTuple):
    """Load distribution of a roller bearing under combined load (SI; at rest).

    Shapes: ``(...)`` the load cases, Z the rollers, n_s the slices. Failed cases (``converged`` False)
    carry NaN in every physical field.
    """

    loads: np.ndarray
    """(..., 5) F_x, F_y, F_z [N], M_x, M_y [N m] in equilibrium with ``displacement`` (with the reactions
    of the held freedoms)."""
    displacement: np.ndarray
    """(..., 5) delta_x, delta_y, delta_z [m], theta_x, theta_y [rad]."""
    azimuth: np.ndarray
    """(Z,) psi_j. [rad]"""
    slice_position: np.ndarray
    """(n_s,) s_k along the roller. [m]"""
    roller_load: np.ndarray
    """(..., Z) Q_j = sum_k q_jk, along the cup normal; 0 for an unloaded roller. [N]"""
    slice_load: np.ndarray
    """(..., Z, n_s) q_jk. [N]"""
    slice_pressure: np.ndarray
    """(..., Z, n_s) Hertz line-contact pressure of each lamina at the inner raceway (the higher). [Pa]"""
    max_pressure: np.ndarray
    """(..., Z) the highest lamina pressure of each roller (inner raceway). [Pa]"""
    max_roller_load: np.ndarray
    """(...) max_j Q_j. [N]"""
    stiffness: np.ndarray
    """(..., 5, 5) d load / d displacement (the held axial freedom of a cylindrical bearing: 0). """
    rib_load: np.ndarray
    """(...) axial load carried by the ribs of an NJ or NUP (rigid), 0 otherwise. [N]"""
    converged: np.ndarray
    """(...) bool."""
    residual: np.ndarray
    """(...) relative equilibrium residual. [-]"""
    iterations: np.ndarray
    """(...) ring Newton iterations."""
    warnings: tuple
    """Messages, one per kind."""
    reactions: np.ndarray
    """(..., 5) load that holds each prescribed freedom (NaN on a freedom under a given load)."""


def _flat(loads, prescribed, rs):
    f = as_float("loads", loads)
    if f.shape[-1:] != (5,):
        raise InputError(f"loads must have a last axis of length 5 (F_x, F_y, F_z, M_x, M_y), got shape {f.shape}")
    if not np.all(np.isfinite(f)):
        raise InputError("loads must be finite [N, N m]")
    shape = f.shape[:-1]
    held = None
    if prescribed is not None:
        p = as_float("prescribed_displacement", prescribed)
        if p.shape[-1:] != (5,):
            raise InputError("prescribed_displacement must have a last axis of length 5 (delta_x, delta_y, delta_z, "
                             f"theta_x, theta_y; NaN for a freedom under load), got shape {p.shape}")
        if np.any(np.isinf(p)):
            raise InputError("prescribed_displacement must be finite or NaN (a freedom under load) [m, rad]")
        shape = np.broadcast_shapes(shape, p.shape[:-1])
        held = np.ascontiguousarray(np.broadcast_to(p, shape + (5,)).reshape(-1, 5))
    f = np.ascontiguousarray(np.broadcast_to(f, shape + (5,)).reshape(-1, 5))
    if held is None:
        held = np.full_like(f, np.nan)
    given = held.copy()
    held = held.copy()
    fz = f[:, 2]
    if rs.axial_support != "raceways":  # cylindrical: delta_z held (0 unless prescribed); F_z on the ribs
        if rs.axial_support == "none" and np.any(fz != 0):
            raise InputError(f"loads: F_z = {float(fz[fz != 0][0]):g} N on a cylindrical roller bearing without "
                             "ribs on both rings (N, NU), which carries no axial load; use an NJ (F_z >= 0) or NUP")
        if rs.axial_support == "ribs-positive" and np.any(fz < 0):
            raise InputError(f"loads: F_z = {float(fz[fz < 0][0]):g} N on an NJ, which carries axial load in +z only "
                             "(on its ribs); use an NUP for both directions")
        held[:, 2] = np.where(np.isnan(held[:, 2]), 0.0, held[:, 2])
    both = ~np.isnan(held) & (f != 0)
    if rs.axial_support != "raceways":
        both[:, 2] = False
    if both.any():
        k, j = np.argwhere(both)[0]
        name = ("F_x", "F_y", "F_z", "M_x", "M_y")[j]
        raise InputError(f"loads: {name} = {f[k, j]:g} [N, N m] is given on a freedom whose displacement is "
                         "prescribed; give each freedom either a load or a displacement (its reaction is computed)")
    arm = np.array([1.0, 1.0, 1.0, 0.5 * rs.pitch_diameter, 0.5 * rs.pitch_diameter])
    with np.errstate(invalid="ignore"):
        far = np.abs(held) * arm > rs.roller_diameter
    if far.any():
        k, j = np.argwhere(far)[0]
        raise InputError(f"prescribed_displacement: {('delta_x', 'delta_y', 'delta_z', 'theta_x', 'theta_y')[j]} "
                         f"= {held[k, j] * 1e3:.6g} {'mm' if j < 3 else 'mrad'} moves the rings by more than one roller "
                         f"diameter (D_we = {rs.roller_diameter * 1e3:.6g} mm)")
    return f, held, given, shape


def _check_single_tapered(rs, f, held):
    """A single tapered bearing with its axial freedom under load holds a radial load only with a thrust
    F_z > F_r tan(alpha) (one roller carrying all; Harris ch. 1): below that no equilibrium exists."""
    if rs.axial_support != "raceways":
        return
    free_z = np.isnan(held[:, 2]) & np.isnan(held[:, 0]) & np.isnan(held[:, 1])
    fr = np.hypot(f[:, 0], f[:, 1])
    need = fr * math.tan(rs.contact_angle)
    bad = free_z & (fr > 0) & ~(f[:, 2] > need)
    if bad.any():
        k = int(np.flatnonzero(bad)[0])
        raise InputError(f"loads: F_z = {f[k, 2]:g} N cannot hold F_r = {fr[k]:g} N on a single tapered roller "
                         f"bearing: it needs F_z > F_r tan(alpha) = {need[k]:g} N (the induced axial load of the "
                         "radial load); give the thrust of the mounting, prescribe delta_z, or solve the bearing in "
                         "a pair (bearinglab.rollers.pairs)")


def _solve(rs, kn, f, held, tol, max_iter):
    n = len(f)
    free = np.isnan(held).astype(float)
    u = np.empty_like(f)
    ok = np.empty(n, dtype=bool)
    it = np.empty(n, dtype=int)
    rel = np.empty(n)
    def evaluate(uu):
        force, stiff, _, roller, noise = _evaluate(kn, uu)
        return force, stiff, np.sum(roller, axis=-1), noise

    span = 0.5 * rs.pitch_diameter + 0.5 * rs.roller_length
    for lo in range(0, n, _CHUNK):
        sl = slice(lo, min(n, lo + _CHUNK))
        u0 = np.where(free[sl] > 0, _start(rs, kn, f[sl]), held[sl])
        u[sl], ok[sl], it[sl], rel[sl] = _newton(evaluate, kn.arm, f[sl], u0, free[sl], tol, max_iter,
                                                 0.1 * rs.roller_diameter, span, kn.resolution)
    return u, ok, it, rel, free


def load_distribution(loads, roller_set, *, prescribed_displacement=None, on_failure="raise", tol=TOL,
                      max_iter=MAX_ITER):
    r"""Load distribution, displacement and stiffness of a roller bearing under combined load, batched.

    Parameters
    ----------
    loads : array_like
        (..., 5): F_x, F_y, F_z [N], M_x, M_y [N m] on the inner ring.
    roller_set : RollerSet
        The bearing (:func:`roller_set`, or :func:`bearinglab.rollers.analysis.bearing_roller_set`).
    prescribed_displacement : array_like, optional
        (..., 5) held displacements, NaN on a freedom under its given load (as in
        :func:`bearinglab.quasistatic.combined.load_distribution`); broadcast against ``loads``. A freedom
        takes a load or a displacement, not both; the reaction of a held one is in ``reactions``.
    on_failure : {"raise", "flag"}, optional
        Raise :class:`~bearinglab.errors.ConvergenceError` for a case without equilibrium, or return it
        with NaN and ``converged`` False.
    tol : float, optional
        Relative equilibrium residual of convergence (a rounding floor, at most 1e-9, under loads too light
        to resolve). [-]
    max_iter : int, optional
        Ring Newton iterations per case.

    Returns
    -------
    RollerLoadDistribution

    Notes
    -----
    The lamina approaches are linear in the ring displacement u (module docstring); with
    :math:`q_{jk} = c_s\langle\delta_{jk}\rangle^{10/9}` the ring carries
    :math:`F(u) = \sum_j Q_j G_j + M_j T_j` with :math:`Q_j = \sum_k q_{jk}`, :math:`M_j = \sum_k q_{jk} s_k`
    and :math:`G_j`, :math:`T_j` the derivatives of a lamina approach with respect to u at the middle of
    roller j and per metre along it. The tangent stiffness is analytic,
    :math:`K = \sum_j K_{0j} G_j G_j^T + K_{1j}(G_j T_j^T + T_j G_j^T) + K_{2j} T_j T_j^T` with the moments
    :math:`K_{mj} = \sum_k k_{jk} s_k^m` of the lamina stiffnesses :math:`k = (10/9) c_s \delta^{1/9}`. The
    equilibrium F(u) = F is solved by a damped Newton with a line search for all cases at once, started
    from each load component alone (Stribeck's :math:`Q_{max} = 4.08 F_r / (Z\cos\alpha)` of line contact
    for a radial load); every returned case is in equilibrium to ``tol`` (moments divided by d_m/2).
    The rollers carry no centrifugal force (ISO/TS 16281 is a model at rest).

    Examples
    --------
    >>> rs = roller_set(14, 11e-3, 9.6e-3, 60.5e-3)
    >>> r = load_distribution([10e3, 0, 0, 0, 0], rs)
    >>> print(f"delta_r = {r.displacement[0] * 1e6:.3f} um, Q_max = {r.max_roller_load:.0f} N")
    delta_r = 17.090 um, Q_max = 2919 N
    """
    if not isinstance(roller_set, RollerSet):
        raise InputError(f"roller_set must be a RollerSet (bearinglab.rollers.roller_set), got {type(roller_set).__name__}")
    if on_failure not in ("raise", "flag"):
        raise InputError(f"on_failure must be one of ['raise', 'flag'], got {on_failure!r}")
    check_positive("tol", tol, "-")
    max_iter = int(check_integer("max_iter", max_iter, 1))
    rs = roller_set
    f, held, given, shape = _flat(loads, prescribed_displacement, rs)
    _check_single_tapered(rs, f, held)
    kn = _kernel(rs)
    with _one_blas_thread(len(f)):
        u, ok, it, rel, free = _solve(rs, kn, f, held, tol, max_iter)
        force, stiff, q, roller, _ = _evaluate(kn, np.nan_to_num(u), slices=True)
    cylindrical = rs.axial_support != "raceways"
    rib = f[:, 2].copy() if cylindrical else np.zeros(len(f))  # F_z of an NJ / NUP: on its (rigid) ribs
    reactions = np.where(np.isnan(given), np.nan, force)  # the prescribed freedoms only
    loads_out = np.where(free > 0, f, force)
    if cylindrical:
        loads_out[:, 2] = f[:, 2]
    warnings = []
    if not ok.all():
        k = int(np.flatnonzero(~ok)[0])
        reason = (f"loads {f[k].tolist()}: the ring Newton iteration stalled at a relative residual of "
                  f"{rel[k]:.3g} ({int((~ok).sum())} of {ok.size} cases failed)")
        if on_failure == "raise":
            raise ConvergenceError("rollers.load_distribution", iterations=int(it[k]), residual=rel[k],
                                   estimate=u[k], reason=reason)
        warnings.append(f"{int((~ok).sum())} case(s) not converged (NaN, converged False; first: case {k}): "
                        "the ring Newton iteration stalled")
    return _result(rs, loads_out, u, q, roller, stiff, rib, ok, it, rel, shape, tuple(warnings), reactions)


def _result(rs, loads, u, q, roller, stiff, rib, ok, it, rel, shape, warnings, reactions):
    """The RollerLoadDistribution of flat cases (pressures from the lamina loads; NaN where not converged)."""
    ri, _ = contact.contact_radii(rs.roller_diameter, rs.pitch_diameter, rs.contact_angle)
    width = rs.roller_length / len(rs.slice_position)
    # contact.line_contact's p_max = sqrt(w E' / (2 pi R)) with w = q / width, in one pass over the laminae
    pressure = np.multiply(q, rs.reduced_modulus / (2.0 * np.pi * ri * width))
    np.sqrt(pressure, out=pressure)
    nan = ~ok
    failed = bool(nan.any())
    z, ns = rs.rollers, len(rs.slice_position)

    def out(a, tail):
        # every array here was made for this result (none is the caller's): NaN goes in in place, no copy
        if failed:
            a[nan] = np.nan
        return a.reshape(shape + tail)[()]

    return RollerLoadDistribution(
        loads=out(loads, (5,)), displacement=out(u, (5,)), azimuth=rs.azimuth, slice_position=rs.slice_position,
        roller_load=out(roller, (z,)), slice_load=out(q, (z, ns)), slice_pressure=out(pressure, (z, ns)),
        max_pressure=out(np.max(pressure, axis=-1), (z,)), max_roller_load=out(np.max(roller, axis=-1), ()),
        stiffness=out(stiff, (5, 5)), rib_load=out(rib, ()), converged=ok.reshape(shape)[()],
        residual=out(rel, ()), iterations=it.reshape(shape)[()], warnings=warnings,
        reactions=out(reactions, (5,)))


class Equilibrium(NamedTuple):
    """Ring equilibrium of a roller bearing at a given displacement."""

    residual: np.ndarray
    """(..., 5) load minus bearing reaction. [N, N m]"""
    stiffness: np.ndarray
    """(..., 5, 5) tangent stiffness d reaction / d displacement."""
    reaction: np.ndarray
    """(..., 5) the load the bearing carries at this displacement. [N, N m]"""


def equilibrium(displacement, loads, roller_set):
    """Reaction, residual and tangent stiffness of a roller bearing at given displacements (no solve).

    Parameters
    ----------
    displacement : array_like
        (..., 5) delta_x, delta_y, delta_z [m], theta_x, theta_y [rad].
    loads : array_like
        (..., 5) applied loads, broadcast against ``displacement``. [N, N m]
    roller_set : RollerSet
        The bearing.

    Returns
    -------
    Equilibrium
        ``reaction`` F(u) (the axial component of a cylindrical bearing is 0: its ribs are not modelled),
        ``residual`` = loads - F(u) and ``stiffness``.

    Examples
    --------
    >>> rs = roller_set(14, 11e-3, 9.6e-3, 60.5e-3)
    >>> e = equilibrium([10e-6, 0, 0, 0, 0], [0, 0, 0, 0, 0], rs)
    >>> print(f"{e.reaction[0]:.0f} N")
    5513 N
    """
    u = as_float("displacement", displacement)
    if u.shape[-1:] != (5,):
        raise InputError(f"displacement must have a last axis of length 5, got shape {u.shape}")
    f = as_float("loads", loads)
    shape = np.broadcast_shapes(u.shape, f.shape)[:-1]
    uu = np.ascontiguousarray(np.broadcast_to(u, shape + (5,)).reshape(-1, 5))
    ff = np.broadcast_to(f, shape + (5,)).reshape(-1, 5)
    force, stiff, _, _, _ = _evaluate(_kernel(roller_set), uu)
    return Equilibrium((ff - force).reshape(shape + (5,))[()], stiff.reshape(shape + (5, 5))[()],
                       force.reshape(shape + (5,))[()])
