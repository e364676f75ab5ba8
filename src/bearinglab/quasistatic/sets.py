r"""Bearing sets: two or more ball bearings on one rigid shaft in a rigid housing, preloaded.

Arrangements
------------
ARRANGEMENTS       "DB" back-to-back, "DF" face-to-face, "DT" tandem: the orientation of each bearing
arrangement        orientations (+1 / -1) and axial positions of a set from its arrangement and spacing
default_spacing    bearings side by side: centres one ring width apart, (B_k + B_k+1) / 2

Solution
--------
set_analysis       shaft displacement, each bearing's load distribution and the set's 5 x 5 stiffness
SetState           the result

Conventions: the shaft carries (F_x, F_y, F_z, M_x, M_y) at the origin of z (the middle of the set) and
moves by (delta_x, delta_y, delta_z, theta_x, theta_y) there. Bearing k sits at z_k; a bearing of
orientation +1 takes thrust F_z > 0 on its inner ring (its contact line meets the axis at
z_k - (d_m/2) tan(alpha), on the -z side); orientation -1 is its mirror image z -> -z. Back-to-back (DB):
the contact lines diverge outwards (the bearing at +z has orientation -1); face-to-face (DF): they
converge. Each bearing is solved by :mod:`bearinglab.quasistatic.combined` in its own frame.

The preload is an axial interference between the two groups of opposed bearings, measured from the
zero-preload position where the balls of every bearing first touch (zero-clearance contact), as a spacer
offset or preload displacement is given in MESYS and MASTA: a ground spacer offset
``preload_displacement`` (half of it in each group, in the bearings' own frames), or the interference
that gives each group of like-oriented bearings the axial force ``preload`` at rest with no external load
(the set is then assembled at rest; at speed the preload force changes, as in a real spindle with a
rigid spacer). A bearing with diametral clearance first touches at the axial offset A sin(alpha0) of its
groove-curvature centres, A = (f_i + f_o - 1) D; zero preload is that position, and a negative
``preload_displacement`` is axial play. The shaft displacement is measured from the assembled position
(a set without opposed bearings, such as a tandem set or a single bearing, cannot be preloaded and is
measured from the concentric position, as a single bearing is). A bearing that carries no load at all
in a case is named in the warnings.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from .._validate import as_float, check_nonnegative, check_positive
from ..errors import ConvergenceError, InputError
from . import _types, combined

__all__ = ["ARRANGEMENTS", "SetState", "arrangement", "default_spacing", "set_analysis"]

#: Orientation of each bearing, listed from -z to +z, per arrangement of a pair.
ARRANGEMENTS = {"DB": (1, -1), "DF": (-1, 1), "DT": (1, 1)}
_MIRROR = np.array([1.0, 1.0, -1.0, -1.0, -1.0])  # z -> -z: displacements and loads of a mirrored bearing


def arrangement(kind, spacing, n_bearings=2):
    """Orientations and axial positions of a set of ``n_bearings``.

    Parameters
    ----------
    kind : {"DB", "DF", "DT"} or sequence of +1/-1
        Arrangement of a pair (for more bearings the first half takes the first orientation), or the
        orientations themselves.
    spacing : float or sequence of float
        Axial distance between neighbouring bearing centres: one value for every gap, or one per gap
        (n - 1 values, from -z to +z). [m]
    n_bearings : int, optional
        Number of bearings (with a named arrangement). [-]

    Returns
    -------
    orientations, positions : ndarray
        +1 / -1 per bearing and z_k [m], centred on z = 0 (the middle between the outer two).

    Examples
    --------
    >>> o, z = arrangement("DB", 0.1)
    >>> print(o, z)
    [ 1 -1] [-0.05  0.05]
    """
    if isinstance(kind, str):
        if kind not in ARRANGEMENTS:
            raise InputError(f"arrangement must be one of {list(ARRANGEMENTS)} or a list of +1/-1, got {kind!r}")
        first, second = ARRANGEMENTS[kind]
        n = int(n_bearings)
        orient = np.array([first] * ((n + 1) // 2) + [second] * (n // 2))
    else:
        orient = np.asarray(kind, dtype=int)
        if not np.all(np.isin(orient, (-1, 1))):
            raise InputError(f"orientations must be +1 or -1, got {list(kind)!r}")
    gaps = check_nonnegative("spacing", spacing, "m")
    if gaps.ndim == 0:
        gaps = np.full(max(orient.size - 1, 0), float(gaps))
    elif gaps.shape != (orient.size - 1,):
        raise InputError(f"spacing: one value or one per gap ({orient.size - 1}), got {gaps.size} values")
    if not np.all(np.isfinite(gaps)):
        raise InputError("spacing must be finite [m]")
    pos = np.concatenate([[0.0], np.cumsum(gaps)])
    return orient, pos - 0.5 * (pos[0] + pos[-1])


def default_spacing(bearings):
    """Distance between neighbouring bearing centres of a set mounted side by side: (B_k + B_k+1) / 2.

    The bearings of a duplex set touch at their ring faces (no spacer), so their centres are one ring
    width B apart for a matched pair; this is the default of :func:`set_analysis` (issue 20: a default
    of zero gave a DB and a DF pair the same tilt stiffness).

    Parameters
    ----------
    bearings : sequence of BallBearing
        The bearings from -z to +z; each needs its ``width``.

    Returns
    -------
    ndarray
        n - 1 gaps. [m]

    Raises
    ------
    InputError
        Naming ``spacing`` and the first bearing without a width.

    Examples
    --------
    >>> from bearinglab import catalog
    >>> b = catalog.get("B218")
    >>> print(default_spacing([b, b]) * 1e3)
    [30.]
    """
    if len(bearings) < 2:
        return np.zeros(0)  # one bearing: no gap, no width needed
    widths = []
    for k, b in enumerate(bearings):
        if b.width is None:
            raise InputError(f"spacing: bearing {k} ({b.designation}) has no width, so the distance between "
                             "the bearing centres cannot default to one ring width; give spacing")
        widths.append(b.width)
    w = np.asarray(widths, dtype=float)
    return 0.5 * (w[:-1] + w[1:])


def _transform(orientation, position):
    """T with u_bearing = T u_shaft (own frame of the bearing)."""
    t = np.eye(5)
    t[0, 4] = position  # delta_x = delta_x + theta_y z
    t[1, 3] = -position  # delta_y = delta_y - theta_x z
    return (_MIRROR if orientation < 0 else np.ones(5))[:, None] * t


class SetState(NamedTuple):
    """A preloaded bearing set under shaft loads (SI)."""

    loads: np.ndarray  # (..., 5) on the shaft at z = 0 [N, N m]
    displacement: np.ndarray  # (..., 5) of the shaft at z = 0 [m, rad]
    bearings: tuple  # one LoadDistribution-like dict per bearing, in its own frame
    bearing_loads: np.ndarray  # (..., n, 5) load each bearing carries, shaft frame, reduced to z = 0 [N, N m]
    stiffness: np.ndarray  # (..., 5, 5) of the set at z = 0
    preload_displacement: float  # axial interference of the set from first contact (zero preload) [m]
    converged: np.ndarray
    residual: np.ndarray  # relative residual of the shaft equilibrium [-]
    iterations: np.ndarray
    warnings: tuple
    positions: np.ndarray = None  # (n,) z_k of the bearing centres [m]
    default_spacing: bool = False  # True when the spacing was not given (bearings side by side, B apart)


def _first_contact_offsets(geos):
    """Axial offset A sin(alpha0) of the groove-curvature centres at which each bearing's balls first touch
    (0 for a bearing with zero or negative clearance, alpha0 = 0: its balls touch in the concentric position)."""
    return np.array([g.big_a * math.sin(g.a0) if g.elements is None else _types.first_contact(g) for g in geos])


def _preload_offsets(geos, orient, preload, preload_displacement):
    """Axial offset of each bearing in its own frame (from the concentric position) and the interference.

    The interference e is measured from first contact (zero preload): each bearing's offset is its
    first-contact offset plus e / 2, so the two opposed groups overlap by e. A force preload solves each
    bearing alone under its group's share of the force; its interference is the sum over the two groups of
    the mean offset beyond first contact (exact for groups of like bearings, the usual matched sets).
    """
    opposed = not np.all(orient == orient[0])
    touch = _first_contact_offsets(geos) if opposed else np.zeros(len(geos))
    if preload_displacement is not None:
        e = float(as_float("preload_displacement", preload_displacement))
        if not np.isfinite(e):
            raise InputError(f"preload_displacement must be finite [m], got {e!r}")
        if e != 0.0 and not opposed:
            raise InputError("preload_displacement: a set without opposed bearings (tandem) has nothing to "
                             f"preload against, got {e!r} m")
        return touch + 0.5 * e, e
    fp = float(check_nonnegative("preload", preload, "N"))
    if fp == 0.0:
        return touch, 0.0
    if not opposed:
        raise InputError("preload: a tandem set has no opposed bearing to preload against")
    offsets = np.zeros(len(geos))
    for k, geo in enumerate(geos):
        share = fp / np.sum(orient == orient[k])
        u, ok, _ = combined._solve(geo, np.array([[0.0, 0.0, share, 0.0, 0.0]]), np.zeros(1), combined.TOL,
                                   combined.MAX_ITER)
        if not ok[0]:
            raise ConvergenceError("sets.set_analysis", iterations=combined.MAX_ITER, residual=np.nan,
                                   estimate=u[0], reason=f"preload of bearing {k}")
        offsets[k] = u[0, 2]
    beyond = offsets - touch
    return offsets, float(np.mean(beyond[orient > 0]) + np.mean(beyond[orient < 0]))


def _unloaded_notes(per, ok):
    """A warning per bearing that carries no load at all (every ball unloaded) in some converged case."""
    notes = []
    for j, out in enumerate(per):
        idle = ok & ~np.any(out["ball_load_inner"].reshape(len(ok), -1) > 0, axis=1)
        if idle.any():
            notes.append(f"bearing {j} carries no load at all in {int(idle.sum())} case(s) (first: case "
                         f"{int(np.flatnonzero(idle)[0])}): none of its balls touch (axial play, a preload "
                         "too small for the loads, or loads that lift it off)")
    return notes


def _set_evaluate(geos, trans, offsets, u, w2):
    """Reaction of the set on the shaft, its stiffness and each bearing's reaction (shaft frame)."""
    force = np.zeros_like(u)
    stiff = np.zeros(u.shape + (5,))
    parts = []
    scale = np.zeros(len(u))
    for geo, t, off in zip(geos, trans, offsets, strict=True):
        ub = u @ t.T
        ub[:, 2] += off
        f, k, balls = combined._evaluate(geo, ub, w2)
        part = f @ t
        parts.append(part)
        force += part
        stiff += t.T @ k @ t
        scale += np.sum(np.hypot(balls["pa"], balls["pr"]), axis=-1)
    return force, stiff, parts, scale


_STALL = 10  # line searches in a row without a decrease after which a case of the set Newton stops


def _set_newton(geos, trans, offsets, loads, w2, tol, max_iter):
    """Damped Newton on the shaft equilibrium (all cases together)."""
    arm = max(g.dm for g in geos) / 2.0
    sc = np.array([1.0, 1.0, 1.0, 1.0 / arm, 1.0 / arm])
    u = np.zeros_like(loads)
    it = np.zeros(len(loads), dtype=int)

    def measure(f, s):
        res = np.linalg.norm((loads - f) * sc, axis=-1)
        return res, res / np.maximum(np.maximum(np.linalg.norm(loads * sc, axis=-1), s), 1e-300)

    force, stiff, _, tot = _set_evaluate(geos, trans, offsets, u, w2)
    norm, rel = measure(force, tot)
    stalled = np.zeros(len(loads), dtype=bool)
    misses = np.zeros(len(loads), dtype=int)  # line searches in a row without a decrease
    for _ in range(max_iter):
        act = (rel > tol) & ~stalled
        if not act.any():
            break
        ks = stiff * sc[None, :, None] * sc[None, None, :]
        diag = np.max(np.abs(np.diagonal(ks, axis1=1, axis2=2)), axis=1)
        ks = ks + (1e-12 * np.where(diag > 0, diag, 1.0))[:, None, None] * np.eye(5)
        du = np.linalg.solve(ks, ((loads - force) * sc)[:, :, None])[:, :, 0] * sc
        du[~act] = 0.0
        t = np.ones(len(u))
        for _ls in range(30):
            f_t, _, _, s_t = _set_evaluate(geos, trans, offsets, u + t[:, None] * du, w2)
            n_t, r_t = measure(f_t, s_t)
            good = (n_t < norm) | (r_t <= tol) | ~act
            if good.all():
                break
            t = np.where(good, t, 0.25 * t)
        # a line search that finds no decrease still moves by its last (tiny) step, which can bring a ball
        # into contact from the concentric start; ten of them in a row end the case (not converged)
        misses = np.where(good, 0, misses + 1)
        stalled |= misses >= _STALL
        u = u + t[:, None] * du
        force, stiff, _, tot = _set_evaluate(geos, trans, offsets, u, w2)
        norm, rel = measure(force, tot)
        it += act
    return u, rel <= tol, it, rel


def _check_bound(geos, positions, loads, on_failure):
    """Issue 29: a load beyond what the set's balls can carry with none compressed by more than a ball
    diameter (each bearing's :func:`~bearinglab.quasistatic.combined._load_bound`; moments at the set's
    centre over the bearings' arms |z_k| + d_m/2) stops before any work, as the solver's bound."""
    bounds = np.array([combined._load_bound(g) for g in geos])
    force_bound = float(np.sum(bounds))
    moment_bound = float(np.sum(bounds * (np.abs(positions) + np.array([g.dm for g in geos]) / 2.0)))
    over = ((np.linalg.norm(loads[:, :3], axis=-1) > force_bound)
            | (np.linalg.norm(loads[:, 3:], axis=-1) > moment_bound))
    if over.any() and on_failure == "raise":
        k = int(np.flatnonzero(over)[0])
        raise ConvergenceError("sets.set_analysis", iterations=0, residual=np.inf, estimate=np.nan,
                               reason=f"loads {loads[k].tolist()}: beyond what the set can carry, a force above "
                                      f"{force_bound:.4g} N or a moment above {moment_bound:.4g} N m would compress a "
                                      "ball by more than its diameter, the solver's bound (a unit mistake?)")
    return over


def set_analysis(bearings, loads, shaft_speed=0.0, *, arrangement_kind="DB", spacing=None, preload=0.0,
                 preload_displacement=None, on_failure="raise", tol=combined.TOL, max_iter=combined.MAX_ITER,
                 **options):
    """Solve a preloaded set of ball bearings on a rigid shaft under the shaft's five loads.

    Parameters
    ----------
    bearings : BallBearing or sequence of BallBearing
        The bearings from -z to +z (one bearing is used twice for a pair).
    loads : array_like
        (..., 5): F_x, F_y, F_z [N], M_x, M_y [N m] on the shaft at the middle of the set.
    shaft_speed : float, optional
        Speed of the shaft (inner rings); one value for all cases. [rad/s]
    arrangement_kind : {"DB", "DF", "DT"} or sequence of +1/-1, optional
        See :func:`arrangement`.
    spacing : float or sequence of float, optional
        Distance between neighbouring bearing centres (one value, or one per gap). Default: the bearings
        side by side, face against face with no spacer, centres one ring width apart
        (:func:`default_spacing`; a bearing without a width then raises :class:`InputError`). It sets the
        lever of the tilt stiffness: with the pressure centres a = (d_m/2) tan(alpha) beyond (DB) or
        short of (DF) the bearing centres, the effective spread is spacing + 2a for DB and
        abs(spacing - 2a) for DF, so a DB pair is stiffer in tilt than a DF pair except at spacing 0. [m]
    preload : float, optional
        Axial preload force of each group of like-oriented bearings at rest, no external load; 0 assembles
        the set at first contact (zero preload, no axial play). [N]
    preload_displacement : float, optional
        Axial interference of the set instead (e.g. a ground spacer offset), measured from the position
        where every bearing's balls first touch (zero preload), as MESYS and MASTA give it; negative is
        axial play. [m]
    on_failure : {"raise", "flag"}, optional
        As in :func:`bearinglab.quasistatic.combined.load_distribution`.
    tol : float, optional
        Relative residual of the shaft equilibrium. [-]
    max_iter : int, optional
        Newton iterations.

    Other Parameters
    ----------------
    **options
        ``first_ball_angle``, ``stiffness_at``, ``raceway_control`` as in
        :func:`~bearinglab.quasistatic.combined.load_distribution`.

    Returns
    -------
    SetState

    Notes
    -----
    Bearing k sees the shaft displacement at its position, u_k = T_k u (tilts move the inner ring
    radially by theta z_k; a mirrored bearing sees z -> -z), plus its preload offset along its own axis:
    its first-contact offset A sin(alpha0) (half the end play 2 A sin(alpha0) of a bearing with diametral
    clearance, [1]_) plus half the interference. ``preload_displacement`` in the result is that
    interference, also for a force preload, so feeding it back reproduces the force.
    The shaft is in equilibrium when F = sum_k T_k^T F_k(u_k); the set stiffness is
    sum_k T_k^T K_k T_k with each bearing's analytic tangent stiffness K_k.

    References
    ----------
    .. [1] T. A. Harris and M. N. Kotzalas, *Essential Concepts of Bearing Technology*, 5th ed., CRC
       Press, 2006, ch. 2 (end play of a ball bearing with diametral clearance).

    Examples
    --------
    >>> from bearinglab import catalog
    >>> b = catalog.get("B218")
    >>> s = set_analysis(b, [0, 0, 0, 0, 0], arrangement_kind="DB", spacing=0.1, preload=2000.0)
    >>> print(f"{s.bearing_loads[0, 2]:.1f} N, {s.bearing_loads[1, 2]:.1f} N")
    2000.0 N, -2000.0 N
    """
    from ..bearing import check_model

    for b in (bearings if isinstance(bearings, (list, tuple)) else [bearings]):
        check_model(b, "bearing-set")
    bl = [bearings] if not isinstance(bearings, (list, tuple)) else list(bearings)
    orient, _ = arrangement(arrangement_kind, 0.0, 2 if len(bl) == 1 else len(bl))
    bl = bl * len(orient) if len(bl) == 1 else bl
    if len(bl) != len(orient):
        raise InputError(f"bearings: {len(bl)} bearings for {len(orient)} orientations")
    is_default = spacing is None
    orient, pos = arrangement(arrangement_kind, default_spacing(bl) if is_default else spacing, len(orient))
    f = as_float("loads", loads)
    if f.shape[-1:] != (5,):
        raise InputError(f"loads must have a last axis of length 5, got shape {f.shape}")
    shape = f.shape[:-1]
    flat = f.reshape(-1, 5)
    w = float(check_nonnegative("shaft_speed", shaft_speed, "rad/s"))
    check_positive("tol", tol, "-")
    geos = [combined._bearing_geometry(b, options.get("first_ball_angle", 0.0), options.get("stiffness_at", "operating"),
                                       options.get("raceway_control", "outer")) for b in bl]
    for b, g in zip(bl, geos, strict=True):  # the loads a type cannot carry alone are its mates' in a set
        if g.elements is not None and g.kind not in _types.AT_SPEED and w > 0:
            _types.check_loads(g, np.zeros((1, 5)), np.array([w]), None)
    trans = [_transform(o, z) for o, z in zip(orient, pos, strict=True)]
    over = _check_bound(geos, pos, flat, on_failure)
    offsets, interference = _preload_offsets(geos, orient, preload, preload_displacement)
    w2 = np.full(len(flat), w * w)
    u, ok, it, rel = _set_newton(geos, trans, offsets, np.where(over[:, None], 0.0, flat), w2, tol, int(max_iter))
    ok &= ~over  # beyond the solver's bound: flagged, not solved
    if on_failure == "raise" and not ok.all():
        k = int(np.flatnonzero(~ok)[0])
        raise ConvergenceError("sets.set_analysis", iterations=int(it[k]), residual=rel[k], estimate=u[k],
                               reason=f"{int((~ok).sum())} of {ok.size} cases failed")
    _, stiff, parts, _ = _set_evaluate(geos, trans, offsets, u, w2)
    per = []
    notes = []
    for j, (geo, t, off) in enumerate(zip(geos, trans, offsets, strict=True)):
        ub = u @ t.T
        ub[:, 2] += off
        out = combined._outputs(geo, (ub * 0.0), np.full(len(flat), w), ub, ok, it)
        out["displacement"] = np.where(ok[:, None], ub, np.nan)
        notes += [f"bearing {j}: {m}" for m in combined._notes(geo, None, np.full(len(flat), w), out, ok)]
        per.append({k: v.reshape(shape + v.shape[1:]) for k, v in out.items() if k not in ("residual", "floor")})
        if geo.elements is not None:  # the other types: a ball per row, each entry's azimuth and row
            per[-1].update(azimuth=geo.psi, row=geo.elements.row)
    notes += _unloaded_notes(per, ok)
    if over.any():
        notes.append(f"{int(over.sum())} case(s) not converged (NaN, converged False; first: case "
                     f"{int(np.flatnonzero(over)[0])}): loads beyond what the set can carry (a ball compressed by "
                     "more than its diameter), the solver's bound")
    bad = ~ok
    u[bad], stiff[bad] = np.nan, np.nan
    bearing_loads = np.stack(parts, axis=1)
    bearing_loads[bad] = np.nan
    return SetState(f, u.reshape(shape + (5,)), tuple(per), bearing_loads.reshape(shape + (len(bl), 5)),
                    stiff.reshape(shape + (5, 5)), interference, ok.reshape(shape), rel.reshape(shape),
                    it.reshape(shape), tuple(dict.fromkeys(notes)), pos, is_default)
