r"""Ball bearing under combined load: the five-degree-of-freedom load distribution, at rest and at speed.

The inner ring carries the loads (F_x, F_y, F_z, M_x, M_y) and moves by (delta_x, delta_y, delta_z,
theta_x, theta_y) relative to the fixed outer ring. Every ball has its own contact angles and loads;
the ring is in equilibrium with all of them. At rest each ball is a Hertz spring between the two
groove-curvature centres (the static contact of spec 000 / spec 004 section 5.3, ball by ball); at speed
each ball has its own Jones-Harris equilibrium with centrifugal force and gyroscopic moment (spec 004
eqs. 5-6 and 8-13), solved inside the ring iteration. Pure thrust reproduces
:func:`bearinglab.quasistatic.contact_angles` and :func:`bearinglab.static.contact_angle_under_thrust`.

Geometry
--------
ball_azimuths          psi_j = phi0 + 2 pi j / Z, from +x
groove_offsets         inner groove-curvature centre relative to the outer one, per ball, for a displacement
axial_play_takeup      A sin(alpha0), the part of delta_z a thrust takes up before any ball carries load

Load distribution
-----------------
load_distribution      displacement, ball loads, contact angles, pressures and 5 x 5 stiffness, batched
combined_analysis      the same for a :class:`~bearinglab.bearing.BallBearing`
equilibrium            ring residual and tangent stiffness at a given displacement (no solve)

Warnings
--------
light_load, light_load_warnings   re-exported from :mod:`bearinglab.quasistatic.light_load`

Conventions (see docs/theory/load_distribution.md): z is the bearing axis; ball j sits at
psi_j = phi0 + 2 pi j/Z from +x. Displacements are those of the inner ring relative to the outer ring,
measured from the concentric position: with a diametral clearance, a pure thrust first takes up half the
axial play, A sin(alpha0), and that part is included in delta_z (MASTA's convention). The tilt arm and
the moment arm are the pitch radius d_m/2 (ISO/TS 16281). Loads and displacements are ordered
(x, y, z, theta_x, theta_y); the stiffness matrix is d(load)/d(displacement) in N/m, N/rad, N m/m and
N m/rad. Unloaded balls carry zero load. Four-point, double-row, self-aligning and thrust ball bearings are
sets of elements, one inner and one outer contact of a ball each, with their own groove-centre offsets and
Jacobian rows (:mod:`bearinglab.quasistatic._types`; docs/theory/load_distribution.md, "The other
ball-bearing types").

References
----------
.. [1] A. B. Jones, "A general theory for elastically constrained ball and radial roller bearings under
   arbitrary load and speed conditions," J. Basic Eng., vol. 82, no. 2, pp. 309-320, 1960,
   doi:10.1115/1.3662587.
.. [2] T. A. Harris and M. N. Kotzalas, *Advanced Concepts of Bearing Technology*, 5th ed., CRC Press,
   2006, ch. 1 (distribution of internal loading) and ch. 3 (high-speed ball bearings),
   doi:10.1201/9781420006582.
.. [3] ISO/TS 16281:2008, Rolling bearings - Methods for calculating the modified reference rating life
   for universally loaded bearings (displacement and load-distribution equations, pitch-radius arms).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from .. import _solve as _solve_mod
from .. import geometry
from .._validate import as_float, check_integer, check_positive
from ..errors import ConvergenceError, InputError
from ..units import RPM
from . import _combined_balls, _combined_speed, _ring, _types
from ._combined_balls import (  # the balls and the bearing data, split off (issue 20); private names
    _BALL_MAX_ITER,
    _BALL_TOL,
    _hertz_k,
    _rest_balls,
    _speed_balls,
)
from ._combined_inputs import (  # split off (no module over 1000 lines); private names
    _MAX_DEFLECTION,  # noqa: F401
    _beyond_bound,
    _bound_reason,
    _check_held,
    _flat_inputs,
    _held,
    _load_bound,  # noqa: F401  (sets, tests)
)
from ._combined_notes import notes as _notes
from ._types import geometry as _geometry
from .light_load import LightLoad, light_load, light_load_warnings

__all__ = [
    "BEARING_TYPES",
    "STIFFNESS_AT",
    "Equilibrium",
    "LightLoad",
    "LoadDistribution",
    "axial_play_takeup",
    "ball_azimuths",
    "combined_analysis",
    "equilibrium",
    "groove_offsets",
    "light_load",
    "light_load_warnings",
    "load_distribution",
]

#: Bearing types: a deep-groove ("radial") bearing is loaded on both groove shoulders; an angular-contact
#: bearing too, but a ball loaded at a negative contact angle (against its low shoulder) gives a warning.
BEARING_TYPES = _combined_balls.BEARING_TYPES
#: Where the Hertz constants are evaluated: at each contact's operating angle (spec 004) or at the free
#: contact angle alpha0 (ISO/TS 16281, spec 000's force characteristic).
STIFFNESS_AT = _combined_balls.STIFFNESS_AT

# Defaults of the ring Newton (belong in bearinglab._solve, which this module does not own yet)
TOL = 1e-12  # relative residual |F - F(u)| / max(|F|, sum of ball loads), moments divided by d_m/2
MAX_ITER = 100  # ring Newton iterations per case (per continuation step at speed)
_LINE_SEARCH = 8  # step cuts (by 4) of the ring Newton line search
_LAM_MAX = 1e4  # Levenberg-Marquardt damping beyond which a case has failed
_CONTINUATION = _combined_speed._CONTINUATION  # equal steps in omega^2 tried for a case that fails at full speed
_RESOLVABLE = 1e-9  # issue 11: every returned case in equilibrium to 1e-9 relative, rounding or not
_NOISE = 4.0  # a residual within this many rounding floors (see _measure) is converged
_CHUNK = 2048  # cases per pass of the rest Newton (see _rest_newton)
_BALL_OUT = ("qi", "qo", "ai", "ao", "mg", "fc")  # ball loads, angles, gyroscopic moments, F_c, per case
_AT_REST = {"qi": "qi", "qo": "qi", "ai": "ai", "ao": "ai"}  # at rest both contacts share load and angle


# --------------------------------------------------------------------------- geometry
def ball_azimuths(n_balls, first_ball_angle=0.0):
    """Azimuths of the balls, psi_j = phi0 + 2 pi j / Z, measured from +x towards +y.

    Parameters
    ----------
    n_balls : int
        Z. [-]
    first_ball_angle : float, optional
        phi0; 0 puts ball 0 on the +x load line. [rad]

    Returns
    -------
    ndarray
        psi, shape (Z,). [rad]

    Examples
    --------
    >>> print(np.degrees(ball_azimuths(4)))
    [  0.  90. 180. 270.]
    """
    z = int(check_integer("n_balls", n_balls, 1))
    phi0 = float(as_float("first_ball_angle", first_ball_angle))
    return _ring.azimuths(z, phi0)


def groove_offsets(displacement, n_balls, ball_diameter, pitch_diameter, inner_conformity, outer_conformity,
                   free_angle, *, first_ball_angle=0.0, radial_clearance=None):
    r"""Inner groove-curvature centre relative to the outer one, per ball, for a ring displacement.

    Parameters
    ----------
    displacement : array_like
        (..., 5): delta_x, delta_y, delta_z [m], theta_x, theta_y [rad] of the inner ring from the
        concentric position.
    n_balls : int
        Z. [-]
    ball_diameter : float
        D. [m]
    pitch_diameter : float
        d_m. [m]
    inner_conformity, outer_conformity : float
        f_i, f_o. [-]
    free_angle : float
        alpha0 (from the clearance: cos alpha0 = 1 - e / (2 A)). [rad]
    first_ball_angle : float, optional
        phi0. [rad]
    radial_clearance : float, optional
        The diametral clearance e instead of ``free_angle`` (e <= 0: a preload). [m]

    Returns
    -------
    axial, radial : ndarray
        (..., Z) components in the plane of each ball. [m]

    Notes
    -----
    Harris and Kotzalas (module reference [2]) ch. 1 with the pitch radius as arm (ISO/TS 16281, [3]):

    .. math::
        A_{z,j} = \delta_z + \tfrac{d_m}{2}(\theta_x\sin\psi_j - \theta_y\cos\psi_j),\qquad
        A_{r,j} = A\cos\alpha_0 + \delta_x\cos\psi_j + \delta_y\sin\psi_j

    with A = (f_i + f_o - 1) D; A cos(alpha0) is A - e/2 in general, also for e <= 0. A ball is loaded
    where sqrt(A_z^2 + A_r^2) > A; its contact angle is atan2(A_z, A_r).
    """
    u = as_float("displacement", displacement)
    if u.shape[-1:] != (5,):
        raise InputError(f"displacement must have a last axis of length 5, got shape {u.shape}")
    geo = _geometry(n_balls, ball_diameter, pitch_diameter, inner_conformity, outer_conformity, free_angle,
                    None, None, first_ball_angle, "free", "outer", "radial", tables=False, clearance=radial_clearance)
    flat = u.reshape(-1, 5)
    ga, gr = _ring.offsets(geo, flat)
    return ga.reshape(u.shape[:-1] + (geo.z,))[()], gr.reshape(u.shape[:-1] + (geo.z,))[()]


def axial_play_takeup(ball_diameter, inner_conformity, outer_conformity, free_angle):
    r"""Half the axial play, s_a/2 = A sin(alpha0): the part of delta_z spent before any ball carries load.

    Displacements are counted from the concentric position (MASTA's convention), so under a thrust
    delta_z contains this take-up; delta_z - s_a/2 (for F_z > 0) is the elastic approach of the rings.

    Parameters
    ----------
    ball_diameter : array_like
        D. [m]
    inner_conformity, outer_conformity : array_like
        f_i, f_o. [-]
    free_angle : array_like
        alpha0, from the diametral clearance e by cos alpha0 = 1 - e / (2 A). [rad]

    Returns
    -------
    ndarray
        s_a / 2. [m]

    Notes
    -----
    A ball touches both raceways when its groove-curvature centres are A = (f_i + f_o - 1) D apart. In the
    concentric position they are A cos(alpha0) apart radially (the definition of alpha0 by the
    clearance, e = 2 A (1 - cos alpha0)); an axial shift z brings them to sqrt(z^2 + A^2 cos^2 alpha0),
    which equals A at z = A sin(alpha0). Both directions together give the axial play
    s_a = 2 (f_i + f_o - 1) D sin(alpha0), Harris, *Rolling Bearing Analysis* (eq. 2.13 of the
    edition cited by :func:`bearinglab.geometry.axial_play`, which computes s_a).

    Examples
    --------
    >>> print(f"{axial_play_takeup(22.23e-3, 0.5232, 0.5232, math.radians(40)) * 1e3:.4f} mm")  # B218
    0.6630 mm
    """
    return (geometry.axial_play(free_angle, ball_diameter, inner_conformity, outer_conformity) / 2.0)[()]


# --------------------------------------------------------------------------- the ring
def _evaluate(geo, u, w2, x=None, deriv=True):
    """Bearing reaction F(u) (the load in equilibrium with u), tangent stiffness dF/du and ball states.

    ``w2`` (n,) is omega^2; cases with w2 = 0 use the closed-form balls at rest, the others solve their
    balls at fixed rings starting from ``x`` ((xa, xr), each (n, Z)) or from :func:`_ball_start`.
    """
    ga, gr = _types.offsets(geo, u)
    moving = w2 > 0
    if not moving.any():
        balls = _types.rest_balls(geo, ga, gr)
        balls.setdefault("ok", np.ones(ga.shape, dtype=bool))
    else:
        balls = _merge(geo, ga, gr, w2, moving, x)
    force = _types.reaction(geo, balls["pa"], balls["pr"])
    stiff = _types.assemble(geo, *balls["h"]) if deriv else None
    return force, stiff, balls


_MERGED = ("pa", "pr", "qi", "qo", "ai", "ao", "mg", "fc", "noise", "ok")


def _merge(geo, ga, gr, w2, moving, x):
    """Ball states of a batch with some cases at rest and some at speed (the fields of :data:`_MERGED`
    and ``h``)."""
    mv = np.flatnonzero(moving)
    spd = _speed_balls(geo, ga[mv], gr[mv], w2[mv, None], None if x is None else (x[0][mv], x[1][mv]))
    if mv.size == len(ga):
        return spd
    rest = _rest_balls(geo, ga, gr)
    rest["ok"] = np.ones(ga.shape, dtype=bool)
    out = {}
    for key in _MERGED:
        merged = np.array(rest[key], dtype=float if key != "ok" else bool, copy=True)
        merged[mv] = spd[key]
        out[key] = merged
    out["h"] = tuple(np.array(a, copy=True) for a in rest["h"])
    for a, b in zip(out["h"], spd["h"], strict=True):
        a[mv] = b
    return out


def _scaled(geo, vec):
    """Loads or displacements with the moment (tilt) components divided (multiplied) by the arm."""
    return vec * np.array([1.0, 1.0, 1.0, 2.0 / geo.dm, 2.0 / geo.dm])


def _measure(geo, loads, force, balls, free=None):
    """Residual norm |F - F(u)| (moments divided by d_m/2) [N], the same relative to
    max(|F|, sum of the ball reactions) [-], and the relative residual rounding alone leaves [-].

    ``free`` (n, 5) of 1.0 / 0.0, or None for all free: a held (prescribed) freedom has no equation, its
    load is the reaction, so its component of F - F(u) does not count.

    The floor: a ball's deflection rho - A is a difference of two lengths of order A, so Q carries a
    rounding error of about dQ/d(delta) eps rho; under very light loads (deflections of a few nm) this
    exceeds the default tolerance, and no iteration can do better.
    """
    diff = loads - force if free is None else (loads - force) * free
    res = np.linalg.norm(_scaled(geo, diff), axis=-1)
    if "b_res" in balls:  # a four-point ball's own residual counts: a ball not in equilibrium is no answer
        res = np.hypot(res, _ring.ballsum(balls["b_res"]))
    total = _ring.ballsum(np.hypot(balls["pa"], balls["pr"]))
    scale = np.maximum(np.linalg.norm(_scaled(geo, loads), axis=-1), total)
    noise = _NOISE * _ring.ballsum(balls["noise"])
    with np.errstate(invalid="ignore", divide="ignore"):
        return res, np.where(scale > 0, res / scale, res), np.minimum(np.where(scale > 0, noise / scale, 0.0), _RESOLVABLE)


def _start(geo, loads):
    """Start of the ring Newton: thrust, radial load and moment each taken alone (Stribeck's 5/Z).

    A preloaded bearing (e < 0, every ball compressed by delta_0 = -e/2 in the concentric position)
    starts at the smaller of its linear response at zero load (radial stiffness 0.75 Z K_n delta_0^0.5
    for Z >= 3) and the zero-clearance estimate, and at least at the latter less delta_0.
    """
    if geo.elements is not None:
        return _types.start(geo, loads)
    c0 = np.array([math.cos(geo.a0)])
    ki, ko = (_hertz_k(t, c0)[0][0] for t in geo.tables[:2])
    kn0 = (ki ** (-2.0 / 3.0) + ko ** (-2.0 / 3.0)) ** -1.5
    fr = np.hypot(loads[:, 0], loads[:, 1])
    mm = np.hypot(loads[:, 3], loads[:, 4])
    dz = _ring.thrust_offset(np.abs(loads[:, 2]) / geo.z, geo.big_a, geo.a0, geo.gr0, kn0)
    hertz = (5.0 * fr / geo.z / kn0) ** (2.0 / 3.0)
    pre = geo.interference
    if pre > 0:
        linear = fr / (0.75 * geo.z * kn0 * math.sqrt(pre))
        dr = np.where(fr > 0, np.maximum(hertz - pre, np.minimum(linear, hertz)), 0.0)
    else:
        dr = np.where(fr > 0, geo.big_a - geo.gr0 + hertz, 0.0)
    tilt = _ring.thrust_offset(2.0 * mm / (geo.dm / 2.0) / geo.z, geo.big_a, geo.a0, geo.gr0, kn0) / (geo.dm / 2.0)
    u = np.zeros_like(loads)
    with np.errstate(invalid="ignore", divide="ignore"):
        u[:, 0:2] = np.where(fr[:, None] > 0, loads[:, 0:2] / fr[:, None] * dr[:, None], 0.0)
        u[:, 3:5] = np.where(mm[:, None] > 0, loads[:, 3:5] / mm[:, None] * tilt[:, None], 0.0)
    u[:, 2] = np.sign(loads[:, 2]) * dz
    return u


def _newton(geo, loads, u0, tol, max_iter, keep=(), free=None):
    """Damped Newton (Levenberg-Marquardt) on the ring equilibrium at rest, all cases together.

    Each case has its own damping: it falls tenfold after a full step and rises when the line search
    on |F - F(u)| has to cut the step. Returns u, converged, iterations and the last accepted evaluation
    of every case, which is the evaluation at the returned u: relative residual, rounding floor,
    stiffness, reaction and the ball fields named in ``keep``. ``free`` (n, 5), 1.0 for a freedom under a
    given load and 0.0 for a held one (its displacement stays at u0), or None.
    """
    n = len(loads)
    u = u0.copy()
    it = np.zeros(n, dtype=int)
    lam = np.zeros(n)
    rest = np.zeros(n)
    force, stiff, balls = _evaluate(geo, u, rest)
    norm, rel, floor = _measure(geo, loads, force, balls, free)
    done = rel <= np.maximum(tol, floor)
    final = {k: np.array(balls[k], dtype=float) for k in keep}
    for _ in range(max_iter):
        act = np.flatnonzero(~done & (it < max_iter) & (lam <= _LAM_MAX))
        if act.size == 0:
            break
        it[act] += 1
        if free is None:
            du = _ring.lm_step(stiff[act], loads[act] - force[act], lam[act], geo.dm)
        else:  # held freedoms: no equation, no step (issue 20 item 18)
            du = _ring.lm_step(_ring.hold(stiff[act], free[act]), (loads[act] - force[act]) * free[act], lam[act],
                               geo.dm)
        # trust region: no groove centre moves by more than A / 2 in one step (bounded over the balls:
        # axial |dz| + d_m/2 |tilt|, radial |(dx, dy)|)
        move = np.maximum(np.abs(du[:, 2]) + geo.dm / 2.0 * np.hypot(du[:, 3], du[:, 4]), np.hypot(du[:, 0], du[:, 1]))
        with np.errstate(divide="ignore"):
            t = np.minimum(1.0, 0.5 * geo.trust / move)
        full = t == 1.0
        pending = np.arange(act.size)
        for _ls in range(_LINE_SEARCH):
            sel = act[pending]
            trial = u[sel] + t[pending, None] * du[pending]
            f_t, k_t, b_t = _evaluate(geo, trial, rest[sel])
            n_t, r_t, fl_t = _measure(geo, loads[sel], f_t, b_t, None if free is None else free[sel])
            conv_t = r_t <= np.maximum(tol, fl_t)
            good = (n_t < norm[sel] * (1.0 - 1e-4 * t[pending])) | conv_t
            g, kk = sel[good], (slice(None) if good.all() else good)  # a view, not a copy, when all are good
            u[g], force[g], stiff[g], norm[g], rel[g] = trial[kk], f_t[kk], k_t[kk], n_t[kk], r_t[kk]
            floor[g] = fl_t[kk]
            for key in keep:
                final[key][g] = b_t[key][kk]
            pending = pending[~good]
            if pending.size == 0:
                break
            t[pending] *= 0.25
            full[pending] = False
        # a step the line search had to shorten keeps its damping: raising it there starves the soft
        # directions of a ring near a mechanism and the Newton crawls (issue 11, ANGULAR under -230, 83, 1/64 N)
        _ring.damp(lam, act, full, pending)
        done = rel <= np.maximum(tol, floor)
    final.update(residual=rel, floor=floor, stiffness=stiff, force=force)
    return u, done, it, final


def _rest_newton(geo, loads, tol, max_iter, held=None):
    """The rest Newton of every case, ``_CHUNK`` cases at a time (the same per case: bit-identical for any
    batch); each pass's arrays stay in the processor's cache and off the operating system's page faults.
    ``held`` (n, 5): the prescribed displacements, NaN on the freedoms under a given load (or None)."""
    n = len(loads)
    if n <= _CHUNK:
        u0, free = _start(geo, loads), None
        if held is not None:
            free = np.isnan(held).astype(float)
            u0 = np.where(free > 0, u0, held)
        keep = ("qi", "ai") if geo.kind != "four-point" else ("qi", "ai", "qo", "ao")  # four contacts a ball
        u, ok, it, last = _newton(geo, loads, u0, tol, max_iter, keep=keep, free=free)
        return u, ok, it, last
    parts = [_rest_newton(geo, loads[lo:lo + _CHUNK], tol, max_iter, None if held is None else held[lo:lo + _CHUNK])
             for lo in range(0, n, _CHUNK)]
    last = {k: np.concatenate([p[3][k] for p in parts]) for k in parts[0][3]}
    return (*(np.concatenate([p[j] for p in parts]) for j in range(3)), last)


def _solve(geo, loads, w2, tol, max_iter, *, final=False, held=None, compiled=False):
    """Rest solution of every case, then the cases at speed from it (:mod:`._combined_speed`), by numpy or,
    with ``compiled``, by the kernel (:mod:`._combined_kernel`, the same algorithm case by case).

    Returns u, converged, iterations and, with ``final``, (have, the last evaluation): ``have`` marks the
    cases whose outputs the last evaluation holds (all converged ones), so they need no evaluation of
    their own.
    """
    if compiled and geo.elements is None:  # the kernel solves a single row; the other types are numpy's
        u, ok, it, last = _solve_compiled(geo, loads, w2, tol, max_iter, held)
        return (u, ok, it, (ok.copy(), last)) if final else (u, ok, it)
    u, ok, it, last = _rest_newton(geo, loads, tol, max_iter, held)
    free = None if held is None else np.isnan(held).astype(float)
    have = w2 == 0
    moving = np.flatnonzero((w2 > 0) & ok)
    if moving.size:
        us, oks, its, fin = _combined_speed.solve_speed(geo, loads[moving], w2[moving], u[moving], tol, max_iter,
                                                        None if free is None else free[moving], _LAM_MAX, _NOISE,
                                                        _RESOLVABLE)
        u[moving], ok[moving] = us, oks
        it[moving] += its
        if final:
            last = dict(last)
            for key, val in fin.items():
                src = last.get(_AT_REST.get(key, key))
                merged = np.zeros((len(loads),) + val.shape[1:]) if src is None else np.array(src, copy=True)
                merged[moving] = val
                last[key] = merged
            have = have.copy()
            have[moving] = oks
    extra = (have, last) if final else None
    return (u, ok, it, extra) if final else (u, ok, it)


def _reactions(geo, u, w2, compiled):
    """Ring load (n, 5), stiffness (n, 5, 5) and every ball converged (n,) at the displacements u (n, 5):
    the kernel's evaluation (:func:`._combined_kernel.reactions`) or :func:`_evaluate`'s. The types without
    the speed terms (four-point, thrust: :data:`._types.AT_SPEED`) are evaluated at rest at any speed."""
    if geo.elements is not None and geo.kind not in _types.AT_SPEED:
        w2 = np.zeros_like(w2)
    if compiled and geo.elements is None:
        from . import _combined_kernel

        par, ser = _kernel_parameters(geo, TOL, MAX_ITER)
        return _combined_kernel.reactions(geo, u, w2, par, ser)
    force, stiff, balls = _evaluate(geo, u, w2)
    return force, stiff, np.all(balls["ok"], axis=-1)


def _kernel_parameters(geo, tol, max_iter):
    from . import _combined_kernel

    return _combined_kernel.parameters(geo, tol, max_iter, _LAM_MAX, _NOISE, _RESOLVABLE, _BALL_TOL, _BALL_MAX_ITER)


def _solve_compiled(geo, loads, w2, tol, max_iter, held):
    """:func:`_solve` by the compiled kernel: the same starts (numpy, case by case), then each case's rest
    and speed solves in one kernel call, parallel over the cases."""
    from . import _combined_kernel  # imports numba: only when the compiled path runs

    u0, free = _start(geo, loads), None
    if held is not None:
        free = np.isnan(held).astype(float)
        u0 = np.where(free > 0, u0, held)
    par, ser = _kernel_parameters(geo, tol, max_iter)
    return _combined_kernel.solve(geo, loads, u0, free, w2, par, ser)


# --------------------------------------------------------------------------- results
class LoadDistribution(NamedTuple):
    """Load distribution of a ball bearing under combined load (SI units).

    Shapes: ``(...)`` is the broadcast shape of the load cases, Z the number of balls. Failed cases
    (``converged`` False) carry NaN in every physical field.
    """

    loads: np.ndarray  # (..., 5) F_x, F_y, F_z [N], M_x, M_y [N m]
    shaft_speed: np.ndarray  # (...) inner-ring speed [rad/s]
    displacement: np.ndarray  # (..., 5) delta_x, delta_y, delta_z [m], theta_x, theta_y [rad]
    azimuth: np.ndarray  # (Z,) psi_j [rad]
    ball_load_inner: np.ndarray  # (..., Z) Q_i, 0 for an unloaded ball [N]
    ball_load_outer: np.ndarray  # (..., Z) Q_o (at speed includes the centrifugal force) [N]
    contact_angle_inner: np.ndarray  # (..., Z) alpha_i [rad]
    contact_angle_outer: np.ndarray  # (..., Z) alpha_o [rad]
    max_pressure_inner: np.ndarray  # (..., Z) p_max [Pa]
    max_pressure_outer: np.ndarray  # (..., Z) [Pa]
    centrifugal_force: np.ndarray  # (..., Z) F_c [N]
    gyroscopic_moment: np.ndarray  # (..., Z) M_g, signed with the attitude angle [N m]
    max_ball_load: np.ndarray  # (...) max over the balls of Q_i [N]
    stiffness: np.ndarray  # (..., 5, 5) d load / d displacement [N/m, N/rad, N m/m, N m/rad]
    converged: np.ndarray  # (...) bool
    residual: np.ndarray  # (...) relative equilibrium residual [-]
    iterations: np.ndarray  # (...) ring Newton iterations
    warnings: tuple  # messages (light load, low-shoulder contact, friction), one per kind
    #: (..., 5) load needed to hold each prescribed freedom at its displacement [N, N m]; NaN on a freedom
    #: under a given load (all NaN without ``prescribed_displacement``)
    reactions: np.ndarray = None
    #: (Z',) the row of each ball-axis entry of the other types (:mod:`._types`: a double-row bearing's row, a
    #: four-point bearing's diagonal; the ball fields then hold Z' = 2 Z entries, row after row); None for a
    #: single row
    row: np.ndarray = None


def _pressure(geo, q, alpha, race):
    """p_max = 3 Q / (2 pi a b) with a b = (a* b*) (3 Q / (E' Sigma rho))^(2/3)."""
    sphere = race == "outer" and geo.kind == "self-aligning"  # curvature 1/R_o at any angle (_types._tables)
    angle = np.full_like(alpha, geo.a0) if geo.stiffness_at == "free" or sphere else alpha
    conf = geo.fi if race == "inner" else geo.fo
    curv = geometry.raceway_curvature(geo.d, geo.dm, conf, angle, race=race)
    coef = geo.tables[2 if race == "inner" else 3]
    ab = _hertz_k(coef, np.cos(angle))[0] * np.cbrt(3.0 * q / (geo.ep * curv.curvature_sum)) ** 2
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(q > 0, 3.0 * q / (2.0 * np.pi * ab), 0.0)


def _at_solution(geo, loads, w, u, sel, final, free=None):
    """Relative residual, rounding floor, stiffness, reaction and ball outputs (``_BALL_OUT``) of the cases
    ``sel``: from the solver's last evaluation (``final`` of :func:`_solve`) where it has one, else evaluated."""
    have = np.zeros(sel.size, dtype=bool) if final is None else final[0][sel]
    if have.all() and sel.size == len(loads):  # every case (the usual batch): the last evaluation as it is
        last = final[1]
        res = {k: (last[k] if k in last else last[_AT_REST[k]] if k in _AT_REST else np.zeros((sel.size, geo.z)))
               for k in _BALL_OUT}
        res.update({k: last[k] for k in ("residual", "floor", "stiffness", "force", "pi", "po") if k in last})
        return res
    res = {k: np.empty((sel.size, geo.z)) for k in _BALL_OUT}
    res.update(residual=np.empty(sel.size), floor=np.empty(sel.size), stiffness=np.empty((sel.size, 5, 5)),
               force=np.empty((sel.size, 5)))
    if have.any():
        last, rows = final[1], sel[have]
        for k, v in res.items():
            src = k if k in last else _AT_REST.get(k)
            v[have] = last[src][rows] if src is not None else 0.0  # at rest F_c = M_g = 0
    if not have.all():
        fresh = sel[~have]
        force, stiff, balls = _evaluate(geo, u[fresh], w[fresh] ** 2)
        res["residual"][~have], res["floor"][~have] = _measure(geo, loads[fresh], force, balls,
                                                               None if free is None else free[fresh])[1:]
        res["stiffness"][~have], res["force"][~have] = stiff, force
        for k in _BALL_OUT:
            res[k][~have] = balls[k]
    return res


def _outputs(geo, loads, w, u, ok, it, final=None, held=None):
    """Every field of :class:`LoadDistribution` (flat cases) from the converged displacements; ``final``
    (from :func:`_solve`) spares the evaluation at the solution of the cases it covers; ``held`` (n, 5)
    the prescribed displacements (NaN: free), whose reactions go to ``reactions`` (NaN on free ones; the
    key only with ``held``)."""
    free = None if held is None else np.isnan(held).astype(float)
    n, z = len(loads), geo.z
    nan = np.full((n, z), np.nan)
    out = {k: nan.copy() for k in ("ball_load_inner", "ball_load_outer", "contact_angle_inner",
                                   "contact_angle_outer", "max_pressure_inner", "max_pressure_outer",
                                   "centrifugal_force", "gyroscopic_moment")}
    out.update(displacement=np.where(ok[:, None], u, np.nan), stiffness=np.full((n, 5, 5), np.nan),
               residual=np.full(n, np.nan), floor=np.zeros(n), max_ball_load=np.full(n, np.nan))
    if free is not None:
        out["reactions"] = np.full((n, 5), np.nan)
    sel = np.flatnonzero(ok)
    if sel.size:
        balls = _at_solution(geo, loads, w, u, sel, final, free)
        if free is not None:
            out["reactions"][sel] = np.where(free[sel] > 0, np.nan, balls["force"])
        for k in ("residual", "floor", "stiffness"):
            out[k][sel] = balls[k]
        qi, qo = balls["qi"], balls["qo"]
        vals = {"ball_load_inner": qi, "ball_load_outer": qo, "contact_angle_inner": balls["ai"],
                "contact_angle_outer": balls["ao"], "centrifugal_force": balls["fc"],
                "gyroscopic_moment": balls["mg"],  # the kernel computes the pressures with the rest
                "max_pressure_inner": balls["pi"] if "pi" in balls else _pressure(geo, qi, balls["ai"], "inner"),
                "max_pressure_outer": balls["po"] if "po" in balls else _pressure(geo, qo, balls["ao"], "outer")}
        for k, v in vals.items():
            out[k][sel] = v
        out["max_ball_load"][sel] = np.max(qi, axis=1)
    return out


# --------------------------------------------------------------------------- public solvers
def load_distribution(loads, shaft_speed, n_balls, ball_diameter, pitch_diameter, inner_conformity, outer_conformity,
                      free_angle, reduced_modulus, density, *, first_ball_angle=0.0, stiffness_at="operating",
                      raceway_control="outer", bearing_type="radial", on_failure="raise",
                      tol=TOL, max_iter=MAX_ITER, prescribed_displacement=None, radial_clearance=None,
                      engine="auto", row_distance=None):
    r"""Load distribution, displacement and stiffness of a ball bearing under combined load, at rest or at speed.

    Parameters
    ----------
    loads : array_like
        (..., 5): F_x, F_y, F_z [N], M_x, M_y [N m] on the inner ring.
    shaft_speed : array_like
        Inner-ring speed >= 0, outer ring fixed; broadcast against the cases of ``loads``. [rad/s]
    n_balls : int
        Z. [-]
    ball_diameter : float
        D. [m]
    pitch_diameter : float
        d_m > D. [m]
    inner_conformity, outer_conformity : float
        f_i, f_o. [-]
    free_angle : float or None
        alpha0 in [0, 90 deg), from the diametral clearance e by cos alpha0 = 1 - e / (2 A); None when
        ``radial_clearance`` is given. [rad]
    reduced_modulus : float
        E' of the ball-ring pair. [Pa]
    density : float
        Ball density. [kg/m^3]
    first_ball_angle : float, optional
        phi0, azimuth of ball 0 from +x. [rad]
    stiffness_at : {"operating", "free"}, optional
        Hertz constants at each contact's operating angle (default, as spec 004) or at alpha0 (ISO/TS 16281;
        then the stiffness matrix at rest is exactly symmetric).
    raceway_control : {"outer", "inner"}, optional
        Which raceway resists the gyroscopic moment (spec 004, lambda_i, lambda_o).
    bearing_type : {"radial", "angular"}, optional
        An angular-contact bearing warns when a ball is loaded at a negative contact angle (against its
        low shoulder), and when it carries any load with a thrust F_z <= 0: a single angular-contact
        bearing carries a radial load or a moment as one only together with a thrust F_z > 0 that holds its
        balls on the high shoulder. Such loads are solved with the full groove (the solution is continuous
        through F_z = 0: a radial load alone puts every ball at alpha = 0, a negative thrust puts them on
        the low shoulder) and the warning says the real bearing cannot be trusted to carry them, which is
        what MESYS and MASTA show (a full-groove solution with a shoulder warning; their contact-ellipse
        check against the shoulder height needs shoulder data this model does not have). The other types,
        "four-point", "double-row-angular", "double-row-radial", "self-aligning" and "thrust"
        (:mod:`bearinglab.quasistatic._types`), take ``free_angle`` as their nominal angle built into the
        rings (a double-row deep-groove bearing: its free angle) and ``radial_clearance`` apart (None: 0);
        their ball fields hold a ball per row (``row``). A self-aligning bearing carries no moment and a
        thrust bearing no radial load (those freedoms are held, their loads must be 0); four-point and
        thrust bearings are solved at rest only.
    on_failure : {"raise", "flag"}, optional
        Raise :class:`~bearinglab.errors.ConvergenceError` if any case fails (default), or return NaN
        and ``converged`` False for it.
    tol : float, optional
        Relative equilibrium residual below which a case is converged; under loads so light that rounding
        of the ball deflections (rho - A, with rho ~ A) leaves more, four times that rounding floor, up
        to 1e-9 (issue 11). [-]
    max_iter : int, optional
        Ring Newton iterations per case (and per continuation step).
    prescribed_displacement : array_like, optional
        (..., 5): delta_x, delta_y, delta_z [m], theta_x, theta_y [rad] held at these values, NaN for a
        freedom under its given load; broadcast against the cases. Each freedom is given either as a load
        or as a displacement, so the load of a held freedom must be 0 in ``loads``; its reaction, the load
        that holds it, is in ``reactions`` and in ``loads`` of the result. Example: ``[nan, nan, nan, 0, 0]``
        holds the ring square (no tilt) under F_r + F_a, as the textbook combined-load cases (Sjovall,
        Harris) assume; without it the ring tilts freely (MASTA's single-bearing convention).
        delta_z counts from the concentric position, like the result (:func:`axial_play_takeup`).
    radial_clearance : float, optional
        The diametral operating clearance e instead of ``free_angle``, in [-2 D, 2 A). e <= 0 is a
        preloaded bearing: in the concentric position every ball touches both raceways at alpha = 0,
        compressed by -e/2, and carries Q_0 = K_n (-e/2)^1.5 with no external load (see Notes). [m]
    engine : {"auto", "numpy", "compiled"}, optional
        Who solves: "compiled" the numba kernel (:mod:`bearinglab.quasistatic._combined_kernel`, the same
        algorithm case by case, parallel over the cases), "numpy" the batched numpy path, "auto" (default)
        the kernel when numba is installed. The two agree to rounding (1e-12 relative); each gives a case
        the same bits in any batch. The other types are solved by the numpy path whatever the engine.
    row_distance : float, optional
        Axial distance between the ball centres of the two rows of a double-row bearing (needed there). [m]

    Returns
    -------
    LoadDistribution
        ``loads`` holds the loads in equilibrium with ``displacement``: the given ones, and the reactions
        on the held freedoms.

    Raises
    ------
    ConvergenceError
        With ``on_failure="raise"``, when a case does not converge; its reason says why (loads too light
        to resolve, a ring that moves through its clearance almost as a mechanism, or a stalled
        iteration). With ``on_failure="flag"``
        the same reasons are in ``warnings``.

    Notes
    -----
    Geometry: :func:`groove_offsets`. At rest a ball with groove-centre distance rho carries
    Q = K_n (rho - A)^1.5 along that line (K_n from the exact Hertz constants of both contacts,
    :mod:`bearinglab.hertz`). At speed each ball solves eqs. (5)-(6) of spec 004 for its centre, with F_c,
    M_g and the kinematics (8)-(13) at its own angles (Jones [1], Harris and Kotzalas [2] ch. 3, module references); the
    inner ring carries sum_j [Q_i n_i + (M_g/D) lambda_i t_i]. An unloaded ball keeps its kinematics.

    The ring equilibrium F = F_bearing(u) is solved by damped Newton for all cases at once; its Jacobian
    is the tangent stiffness, analytic: at rest sum_j J_j^T H_j J_j with H the 2 x 2 stiffness of ball j
    in its plane, at speed the Schur complement of the ball equations (implicit function theorem). The
    rest solution starts the speed solve, which updates ring and balls together (one block Newton,
    :mod:`bearinglab.quasistatic._combined_speed`), with continuation in omega^2 where the direct solve fails.
    Zero load gives the concentric position. The returned stiffness is d(load)/d(displacement) at the
    solution.

    Clearance: in the concentric position the groove-curvature centres of a ball are g_0 = A - e/2 apart
    radially (A cos alpha0 for e > 0, the definition of alpha0). With e <= 0 (zero or negative operating
    clearance, e.g. from an interference fit and a warm inner ring) g_0 >= A: every ball is loaded at
    alpha = 0 with the deflection delta_0 = -e/2 before any load, the ring is held radially from all
    sides and a zero load still gives the concentric position, now with the stiffness of the preload
    (radial 0.75 Z K_n delta_0^0.5 for Z >= 3, axial Z Q_0 / g_0). An angular-contact bearing is the same
    groove: its free contact angle comes from its (large, geometric) clearance, fits and temperatures
    take the clearance down and the angle with it, and at e <= 0 its balls sit radially preloaded at
    alpha = 0 like a deep-groove bearing's, turning to a contact angle only under thrust (with the
    single-bearing thrust warning of ``bearing_type="angular"``).

    Examples
    --------
    >>> from bearinglab import hertz
    >>> ep = hertz.reduced_modulus(210e9, 0.3, 210e9, 0.3)
    >>> r = load_distribution([1000.0, 0, 0, 0, 0], 0.0, 7, 11.5e-3, 43.5e-3, 0.52, 0.53, 0.0, ep, 7850.0)
    >>> print(f"{r.displacement[0] * 1e6:.4f} um, Q_max = {r.max_ball_load:.1f} N")
    15.1102 um, Q_max = 619.6 N
    """
    f, w, shape = _flat_inputs(loads, shaft_speed)
    f, w, held, shape = _held(f, w, shape, prescribed_displacement)
    if on_failure not in ("raise", "flag"):
        raise InputError(f"on_failure must be one of ['raise', 'flag'], got {on_failure!r}")
    check_positive("tol", tol, "-")
    max_iter = int(check_integer("max_iter", max_iter, 1))
    geo = _geometry(n_balls, ball_diameter, pitch_diameter, inner_conformity, outer_conformity, free_angle,
                    reduced_modulus, density, first_ball_angle, stiffness_at, raceway_control, bearing_type,
                    clearance=radial_clearance, row_distance=row_distance)
    if geo.elements is not None:  # what the type cannot carry, and the freedoms it does not resist (held)
        _types.check_loads(geo, f, w, held)
        held = _types.held(geo, f, held)
    if held is not None:
        _check_held(geo, held)
    over, bound = _beyond_bound(geo, f)
    if over.any() and on_failure == "raise":  # issue 29: stop at the solver's bound, before any work
        k = int(np.flatnonzero(over)[0])
        raise ConvergenceError("combined.load_distribution", iterations=0, residual=np.inf, estimate=np.nan,
                               reason=f"loads {f[k].tolist()} at {w[k] / RPM:g} rpm: {_bound_reason(bound)} "
                                      f"({int(over.sum())} of {over.size} cases)")
    compiled = _solve_mod.use_compiled(engine, auto=True)
    solved = np.where(over[:, None], 0.0, f) if over.any() else f  # such a case is not solved, only flagged
    u, ok, it, final = _solve(geo, solved, w**2, tol, max_iter, final=True, held=held, compiled=compiled)
    ok &= ~over
    out = _outputs(geo, f, w, u, ok, it, final, held)
    out.setdefault("reactions", np.full((len(f), 5), np.nan))
    ok &= out["residual"] <= np.maximum(tol, out.pop("floor"))
    if not ok.all():
        failures = _failures(geo, f, w, u, ok, None if held is None else np.isnan(held).astype(float))
        failures.update({int(k): _bound_reason(bound) for k in np.flatnonzero(over)})
        failures = dict(sorted(failures.items()))
        if on_failure == "raise":
            k, reason = next(iter(failures.items()))
            force, _, balls = _evaluate(geo, np.nan_to_num(u[k:k + 1]), w[k:k + 1] ** 2, deriv=False)
            raise ConvergenceError("combined.load_distribution", iterations=int(it[k]),
                                   residual=_measure(geo, f[k:k + 1], force, balls, None if held is None else
                                                     np.isnan(held[k:k + 1]).astype(float))[1][0], estimate=u[k],
                                   reason=f"loads {f[k].tolist()} at {w[k] / RPM:g} rpm: {reason} "
                                          f"({int((~ok).sum())} of {ok.size} cases failed)")
    for key in out:
        out[key][~ok] = np.nan
    if held is not None:  # the loads in equilibrium: the reactions on the held freedoms
        f = np.where(np.isnan(held), f, out["reactions"])
    notes = _notes(geo, f, w, out, ok)
    if not ok.all():
        notes += _failure_notes(failures)
    z = geo.z
    shaped = {k: v.reshape(shape + v.shape[1:])[()] for k, v in out.items()}
    return LoadDistribution(loads=f.reshape(shape + (5,)), shaft_speed=w.reshape(shape)[()],
                            azimuth=geo.psi, converged=ok.reshape(shape)[()], iterations=it.reshape(shape)[()],
                            warnings=notes, row=None if geo.elements is None else geo.elements.row,
                            **{k: shaped[k] for k in shaped if k in LoadDistribution._fields and (k != "azimuth" or z)})


def _failures(geo, loads, w, u, ok, free=None):
    """{case: reason} for every failed case, in case order, judged at the last rest iterate (every one a
    solver's failure: the model has a solution for any load since F_z <= 0 is solved with the full groove)."""
    bad = np.flatnonzero(~ok)
    solved = bad[np.all(np.isfinite(u[bad]), axis=1)]
    loaded, inv_cond, floor = (np.zeros(len(loads)) for _ in range(3))
    if solved.size:
        force, stiff, balls = _evaluate(geo, u[solved], np.zeros(solved.size))
        loaded[solved] = np.sum(balls["qi"] > 0, axis=1)
        sc = np.array([1.0, 1.0, 1.0, 2.0 / geo.dm, 2.0 / geo.dm])
        finite = np.all(np.isfinite(stiff), axis=(1, 2))  # an overflowing iterate has no condition number
        sv = np.linalg.svd(np.where(finite[:, None, None], stiff, 0.0) * sc[:, None] * sc[None, :], compute_uv=False)
        inv_cond[solved] = np.where(finite, sv[:, -1] / np.maximum(sv[:, 0], 1e-300), 0.0)
        floor[solved] = _measure(geo, loads[solved], force, balls, None if free is None else free[solved])[2]
    out = {}
    for k in bad:
        if floor[k] >= _RESOLVABLE:
            out[k] = ("loads too light to resolve: ball deflections are so small against the groove distance "
                      f"that rounding alone leaves a relative residual above {_RESOLVABLE:g}")
        elif k in solved and (loaded[k] <= 3 or inv_cond[k] < 1e-4):
            out[k] = (f"{int(loaded[k])} of {geo.z} balls in contact and a nearly singular stiffness: these "
                      "loads move the inner ring through its clearance almost as a mechanism, which the "
                      "bearing alone hardly resists (add thrust or preload, or solve the bearing in a set)")
        else:
            out[k] = "the ring Newton iteration stalled"
    return out


def _failure_notes(failures):
    """One warning per kind of failure, with its count and first case."""
    kinds = {}
    for k, reason in failures.items():
        kinds.setdefault(reason, []).append(k)
    return tuple(f"{len(ks)} case(s) not converged (NaN, converged False; first: case {ks[0]}): {reason}"
                 for reason, ks in kinds.items())


def _bearing_args(bearing, reduced_modulus=None):
    z, d, dm, fi, fo = bearing.require("n_balls", "ball_diameter", "pitch_diameter", "inner_conformity",
                                       "outer_conformity")
    a0 = bearing.contact_angle if bearing.contact_angle is not None else 0.0
    ep = bearing.reduced_modulus if reduced_modulus is None else reduced_modulus
    return z, d, dm, fi, fo, a0, ep, bearing.ball_material.density


def combined_analysis(bearing, loads, shaft_speed=0.0, *, reduced_modulus=None, **options):
    """Load distribution of a :class:`~bearinglab.bearing.BallBearing` under combined load.

    Parameters
    ----------
    bearing : BallBearing
        Needs n_balls, ball_diameter, pitch_diameter and both conformities; the free contact angle (or the
        clearance that gives it; none means zero clearance, alpha0 = 0; a zero or negative
        ``radial_clearance`` is a preload, see :func:`load_distribution`); materials give E' and the ball
        density; ``type`` the bearing type.
    loads : array_like
        (..., 5): F_x, F_y, F_z [N], M_x, M_y [N m].
    shaft_speed : array_like, optional
        Inner-ring speed. [rad/s]
    reduced_modulus : float, optional
        E' instead of the one of the bearing's materials. [Pa]

    Other Parameters
    ----------------
    **options
        Passed to :func:`load_distribution` (``first_ball_angle``, ``stiffness_at``, ``on_failure``, ...).

    Returns
    -------
    LoadDistribution

    Examples
    --------
    >>> from bearinglab import catalog
    >>> from bearinglab.units import RPM
    >>> r = combined_analysis(catalog.get("B218"), [0, 0, 20e3, 0, 0], 10000 * RPM)
    >>> print(f"{math.degrees(r.contact_angle_inner[0]):.3f} / {math.degrees(r.contact_angle_outer[0]):.3f} deg")
    49.310 / 32.510 deg
    """
    from ..bearing import check_model

    check_model(bearing, "load-distribution")
    options.setdefault("bearing_type", bearing.type)
    if bearing.type not in _types.MODELLED:
        options.setdefault("radial_clearance", _preload_clearance(bearing))
        return load_distribution(loads, shaft_speed, *_bearing_args(bearing, reduced_modulus), **options)
    for key, value in _types.bearing_options(bearing).items():  # their clearance and row distance
        options.setdefault(key, value)
    r = load_distribution(loads, shaft_speed, *_bearing_args(bearing, reduced_modulus), **options)
    note = _types.misalignment_note(bearing, np.asarray(r.displacement)[..., 3:])
    return r if note is None else r._replace(warnings=(*r.warnings, note))


def _bearing_geometry(bearing, first_ball_angle=0.0, stiffness_at="operating", raceway_control="outer", *,
                      reduced_modulus=None, tables=True):
    """The checked geometry of a :class:`~bearinglab.bearing.BallBearing` of any type, as
    :func:`combined_analysis` solves it (its operating clearance included)."""
    z, d, dm, fi, fo, a0, ep, rho = _bearing_args(bearing, reduced_modulus)
    if bearing.type in _types.MODELLED:
        opts = _types.bearing_options(bearing)
        e = opts.get("radial_clearance")
        return _geometry(z, d, dm, fi, fo, None if bearing.type == "double-row-radial" and e is not None else a0, ep,
                         rho, first_ball_angle, stiffness_at, raceway_control, bearing.type, tables=tables, clearance=e,
                         row_distance=opts.get("row_distance"))
    e = _preload_clearance(bearing)
    return _geometry(z, d, dm, fi, fo, None if e is not None else a0, ep, rho, first_ball_angle, stiffness_at,
                     raceway_control, bearing.type, tables=tables, clearance=e)


def _takeup(bearing):
    """Half the axial play of a BallBearing of any type, the part of delta_z a thrust F_z > 0 spends before
    a ball carries: A sin(alpha0) (:func:`axial_play_takeup`) of a single row, the first contact of the
    other types' elements (:func:`._types.first_contact`; 0 for a thrust bearing). [m]"""
    if bearing.type in _types.MODELLED:
        return _types.first_contact(_bearing_geometry(bearing, tables=False))
    _, d, _, fi, fo, a0, _, _ = _bearing_args(bearing)
    return float(axial_play_takeup(d, fi, fo, a0))


def _preload_clearance(bearing):
    """The bearing's diametral clearance where it is zero or negative (a preload), else None (its free
    contact angle says it all)."""
    e = bearing.radial_clearance
    return float(e) if e is not None and e <= 0 else None


class Equilibrium(NamedTuple):
    """Ring equilibrium at a given displacement."""

    residual: np.ndarray  # (..., 5) load minus bearing reaction [N, N m]
    stiffness: np.ndarray  # (..., 5, 5) tangent stiffness d reaction / d displacement
    reaction: np.ndarray  # (..., 5) the load the bearing carries at this displacement [N, N m]


def equilibrium(displacement, loads, shaft_speed, n_balls, ball_diameter, pitch_diameter, inner_conformity,
                outer_conformity, free_angle, reduced_modulus, density, *, first_ball_angle=0.0,
                stiffness_at="operating", raceway_control="outer", radial_clearance=None, engine="auto"):
    """Residual of the ring equilibrium and tangent stiffness at a given displacement (the balls solved).

    Parameters
    ----------
    displacement : array_like
        (..., 5) delta_x, delta_y, delta_z [m], theta_x, theta_y [rad].
    loads : array_like
        (..., 5) applied loads. [N, N m]
    shaft_speed : array_like
        Inner-ring speed. [rad/s]
    n_balls : int
        Z. [-]
    ball_diameter : float
        D. [m]
    pitch_diameter : float
        d_m. [m]
    inner_conformity, outer_conformity : float
        f_i, f_o. [-]
    free_angle : float
        alpha0. [rad]
    reduced_modulus : float
        E'. [Pa]
    density : float
        Ball density. [kg/m^3]
    first_ball_angle : float, optional
        phi0. [rad]
    stiffness_at : {"operating", "free"}, optional
        See :func:`load_distribution`.
    raceway_control : {"outer", "inner"}, optional
        See :func:`load_distribution`.
    radial_clearance : float, optional
        See :func:`load_distribution`. [m]
    engine : {"auto", "numpy", "compiled"}, optional
        See :func:`load_distribution`.

    Returns
    -------
    Equilibrium
        ``residual`` = loads - reaction, ``stiffness`` and ``reaction``.
    """
    u = as_float("displacement", displacement)
    if u.shape[-1:] != (5,):
        raise InputError(f"displacement must have a last axis of length 5, got shape {u.shape}")
    f, w, shape = _flat_inputs(np.broadcast_to(loads, np.broadcast_shapes(np.shape(loads), u.shape)), shaft_speed)
    uu = np.broadcast_to(u, shape + (5,)).reshape(-1, 5)
    geo = _geometry(n_balls, ball_diameter, pitch_diameter, inner_conformity, outer_conformity, free_angle,
                    reduced_modulus, density, first_ball_angle, stiffness_at, raceway_control, "radial",
                    clearance=radial_clearance)
    force, stiff, _ = _reactions(geo, np.ascontiguousarray(uu), w**2, _solve_mod.use_compiled(engine, auto=True))
    return Equilibrium((f - force).reshape(shape + (5,)), stiff.reshape(shape + (5, 5)), force.reshape(shape + (5,)))
