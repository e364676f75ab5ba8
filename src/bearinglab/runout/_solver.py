"""Private solvers of the rigid contact problem of spec 003 section 6 (used by :mod:`bearinglab.runout.contact`).

All functions here work in micrometres (the unit in which spec 003 states its tolerances); the public
wrapper :func:`bearinglab.runout.contact.solve_contact` converts from and to SI.

Problem (6.1), for every position p::

    maximise a0   subject to   a0 + B sin(theta_i) + D cos(theta_i) <= dk_i,   i = 1..n

followed by the normative tie-break of section 7.5 (the point of the optimal face closest to the
centre c) and the face diameter (the free play times cos tau0).

Solvers
-------
solve_dual      the fast exact method: the dual of (6.1) is the lowest point, directly above the origin,
                of the convex hull of the points (sin theta_i, cos theta_i, dk_i); its vertices are the
                ball triangles that contain the origin and the diametral pairs. A walk over them (the
                simplex method on the dual, :mod:`bearinglab.runout._compiled`) reaches the lowest in a
                few pivots of O(n) each, all positions together: memory O(P n), time O(P n) per pivot
solve_triples   the independent enumeration of spec 003 section 8.2 (primal triples, then the face
                candidates of step 4); O(n^3) per position, so refused above ``MAX_TRIPLES_BALLS`` balls
solve_lp        the general LP solver (scipy.optimize.linprog, HiGHS dual simplex), one position at a
                time: stage 1, then the face vertices from four small LPs (section 8.1)
check_status    raise ConvergenceError for a walk that did not end

Each returns ``(a0, b, d, lam, degenerate, diameter)`` (the last two solvers ``(a0, b, d, diameter)``) with
``lam`` the dual weights (load shares) per ball; the callers compute slacks and contact flags.
"""

from __future__ import annotations

import itertools

import numpy as np

from .._solve import (
    RUNOUT_CONTACT_TOL_UM,
    RUNOUT_FACE_TOL_UM,
    RUNOUT_STRICT_WEIGHT,
    RUNOUT_TIE_TOL_UM,
)
from ..errors import ConvergenceError, InputError

__all__: list[str] = []

#: A ball this far below the plane of the current triangle enters it [um, times max(1, max |dk|)]. Far
#: above the rounding of the slacks (~1e-16 x scale) and far below the tie tolerance of section 8 (1e-9):
#: the a0 found is within this of the optimum (the triangle's plane is feasible to it).
WALK_TOL_UM = 1e-12
#: Most pivots of the walk, PIVOTS_PER_BALL n + PIVOTS_EXTRA, before it is declared not converged. It takes
#: a few (1-5 for 16 balls, 2-6 for 1000; measured on random errors); cycling is impossible in exact
#: arithmetic, so this only bounds a loop that rounding could keep going.
PIVOTS_PER_BALL, PIVOTS_EXTRA = 4, 64
_SIN120 = np.sqrt(3.0) / 2.0  # sin 120 deg: the start triangle's directions
_OK, _NOCONV = 0, 1  # statuses of a position's walk

_SAME_PATTERN_ATOL = 1e-12  # rad, relative azimuths equal in all positions (a rigidly turned ball set)
_BLOCK = 1 << 16  # balls x positions per block of the walk (its arrays stay in the CPU cache)
#: most balls of the triple enumeration, O(n^3) per position: at 64 balls C(64, 3) = 41 664 triples and
#: 2016 pair vertices hold about 60 MB a position; the dual walk and the LP have no such limit
MAX_TRIPLES_BALLS = 64
_TRIPLES_BLOCK = 1 << 22  # elements of the largest (positions x triples x balls) array of a block


def scale(dk):
    """Per-position tolerance multiplier: max(1, max |dk|) in um (spec 003 section 7.6)."""
    return np.maximum(1.0, np.max(np.abs(dk), axis=-1))


def _triples(n):
    return np.array(list(itertools.combinations(range(n), 3)), dtype=np.intp).reshape(-1, 3)


def same_pattern(angles):
    """True when every position has the same azimuths relative to ball 1 (rigid rotation of the set)."""
    if angles.shape[0] <= 1:
        return True
    rel = angles - angles[:, :1]
    rel -= rel[:1]
    if np.all(np.abs(rel) < _SAME_PATTERN_ATOL):  # fast path: no wrapping between positions
        return True
    rel = np.remainder(rel + np.pi, 2 * np.pi) - np.pi
    return bool(np.all(np.abs(rel) < _SAME_PATTERN_ATOL))


def max_pivots(n):
    """Most pivots of the walk for ``n`` balls."""
    return PIVOTS_PER_BALL * n + PIVOTS_EXTRA


# ------------------------------------------------------------------------------ the walk, over positions
# Each function below does, for every row (position), the operations of its namesake in ``_compiled`` in
# the same order (``_bary`` and ``_plane`` are compiled from these very functions), so that the two engines
# differ only where their libraries round sin and cos differently.
def _bary(xi, yi, xj, yj, xk, yk, qx, qy):
    """Barycentric coordinates of (qx, qy) in the triangle of (xi, yi), (xj, yj), (xk, yk)."""
    wi = (xj - qx) * (yk - qy) - (yj - qy) * (xk - qx)
    wj = (xk - qx) * (yi - qy) - (yk - qy) * (xi - qx)
    wk = (xi - qx) * (yj - qy) - (yi - qy) * (xj - qx)
    t = wi + wj + wk
    return wi / t, wj / t, wk / t


def _plane(si, ci, ri, sj, cj, rj, sk, ck, rk):
    """(B, D) with B s + D c = r at the three balls (least squares; the equations are consistent)."""
    m11 = si * si + sj * sj + sk * sk
    m12 = si * ci + sj * cj + sk * ck
    m22 = ci * ci + cj * cj + ck * ck
    y1 = si * ri + sj * rj + sk * rk
    y2 = ci * ri + cj * rj + ck * rk
    det = m11 * m22 - m12 * m12
    return (m22 * y1 - m12 * y2) / det, (m11 * y2 - m12 * y1) / det


def _start(dk, s, c):
    """Start triangles (rows of ``_compiled._start`` with the lowest ball): (m, 3) ball indices."""
    m, n = dk.shape
    rows = np.arange(m)
    i0 = dk.argmin(axis=1)
    x0, y0 = s[rows, i0], c[rows, i0]
    a, b = (i0 + (n + 1) // 3) % n, (i0 + (2 * n + 1) // 3) % n
    ok = (a != i0) & (b != i0) & (a != b) & _contains(x0, y0, s, c, rows, a, b)
    if not ok.all():  # not equally spaced in index order: the balls nearest to +-120 deg
        bad = np.flatnonzero(~ok)
        xb, yb = x0[bad, None], y0[bad, None]
        r3 = _SIN120
        a2 = (s[bad] * (-0.5 * xb - r3 * yb) + c[bad] * (r3 * xb - 0.5 * yb)).argmax(axis=1)
        b2 = (s[bad] * (-0.5 * xb + r3 * yb) + c[bad] * (-r3 * xb - 0.5 * yb)).argmax(axis=1)
        a[bad], b[bad] = a2, b2
        ok2 = (a2 != i0[bad]) & (b2 != i0[bad]) & (a2 != b2) & _contains(x0[bad], y0[bad], s, c, bad, a2, b2)
        bad = bad[~ok2]
        if bad.size:  # irregular sets: the most opposite ball and the farthest from the chord
            xb, yb = x0[bad, None], y0[bad, None]
            opp = (s[bad] * xb + c[bad] * yb).argmin(axis=1)
            ex, ey = s[bad, opp][:, None] - xb, c[bad, opp][:, None] - yb
            sigma = np.where(ex * (-yb) - ey * (-xb) >= 0.0, 1.0, -1.0)
            far = (sigma * (ex * (c[bad] - yb) - ey * (s[bad] - xb))).argmax(axis=1)
            a[bad], b[bad] = opp, far
    return np.stack([i0, a, b], axis=1)


def _contains(x0, y0, s, c, rows, a, b):
    """The triangle of (x0, y0) and the balls a, b of the rows holds the centre (weights >= -1e-9)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        lam = _bary(x0, y0, s[rows, a], c[rows, a], s[rows, b], c[rows, b], 0.0, 0.0)
    return np.minimum(lam[0], np.minimum(lam[1], lam[2])) >= -RUNOUT_STRICT_WEIGHT


def _walk(dk, s, c, centre_b, centre_d, midpoint):
    """``_compiled.walk`` for every row of dk, s, c (m, n) at once; returns its outputs as arrays."""
    m, n = dk.shape
    scale_ = np.maximum(1.0, np.abs(dk).max(axis=1))
    thr = WALK_TOL_UM * scale_
    basis = np.sort(_start(dk, s, c), axis=1)  # kept sorted, as the compiled walk keeps it
    status = np.ones(m, np.int64)
    active = np.arange(m)
    for _ in range(max_pivots(n) + 1):
        rows = active[:, None]
        bs, bc, bk = s[rows, basis[active]], c[rows, basis[active]], dk[rows, basis[active]]
        lam = _bary(bs[:, 0], bc[:, 0], bs[:, 1], bc[:, 1], bs[:, 2], bc[:, 2], 0.0, 0.0)
        a0 = lam[0] * bk[:, 0] + lam[1] * bk[:, 1] + lam[2] * bk[:, 2]
        b, d = _plane(*(v for q in range(3) for v in (bs[:, q], bc[:, q], bk[:, q] - a0)))
        r = dk[active] - a0[:, None]
        r -= b[:, None] * s[active]
        r -= d[:, None] * c[active]
        e = r.argmin(axis=1)
        done = r[np.arange(active.size), e] >= -thr[active]
        status[active[done]] = _OK
        go = ~done
        if not go.any():
            break
        e, lam = e[go], [v[go] for v in lam]
        bs, bc = bs[go], bc[go]
        active = active[go]
        mu = _bary(bs[:, 0], bc[:, 0], bs[:, 1], bc[:, 1], bs[:, 2], bc[:, 2], s[active, e], c[active, e])
        best = np.full(active.size, np.inf)
        out = np.zeros(active.size, np.intp)
        for slot in range(3):  # the ratio test, slot by slot as the scalar loop
            with np.errstate(divide="ignore", invalid="ignore"):
                ratio = np.maximum(lam[slot], 0.0) / mu[slot]
            better = (mu[slot] > 0.0) & (ratio < best)
            best = np.where(better, ratio, best)
            out = np.where(better, slot, out)
        basis[active, out] = e
        basis[active] = np.sort(basis[active], axis=1)
    return _finish(dk, s, c, basis, centre_b, centre_d, midpoint, scale_, status)


def _finish(dk, s, c, basis, centre_b, centre_d, midpoint, scale_, status):
    """The solution from the final (sorted) triangle of every row, as ``_compiled.walk`` ends (its last
    pass computes the same values in the same order)."""
    m, n = dk.shape
    rows = np.arange(m)
    bs, bc, bk = (v[rows[:, None], basis] for v in (s, c, dk))
    li, lj, lk = _bary(bs[:, 0], bc[:, 0], bs[:, 1], bc[:, 1], bs[:, 2], bc[:, 2], 0.0, 0.0)
    a0 = li * bk[:, 0] + lj * bk[:, 1] + lk * bk[:, 2]
    lam = np.zeros((m, n))
    for q, v in enumerate((li, lj, lk)):
        lam[rows, basis[:, q]] = v
    b, d = _plane(*(v for q in range(3) for v in (bs[:, q], bc[:, q], bk[:, q] - a0)))
    length = np.zeros(m)
    seg = ~(np.minimum(li, np.minimum(lj, lk)) > RUNOUT_STRICT_WEIGHT)
    if seg.any():  # the centre on an edge: a diametral pair's line, cut by the other balls
        w = np.stack([li, lj, lk], axis=1)[seg]
        first = np.zeros(w.shape[0], np.intp)
        first = np.where(w[:, 1] > w[rows[: w.shape[0]], first], 1, first)
        first = np.where(w[:, 2] > w[rows[: w.shape[0]], first], 2, first)
        f = basis[seg][rows[: w.shape[0]], first]
        b[seg], d[seg], length[seg] = _segment(
            dk[seg], s[seg], c[seg], a0[seg], f, centre_b[seg], centre_d[seg], midpoint
        )
    degenerate = length > RUNOUT_CONTACT_TOL_UM * scale_
    return a0, b, d, lam, degenerate, np.where(degenerate, length, 0.0), status


def _segment(dk, s, c, a0, f, centre_b, centre_d, midpoint):
    """Face of the pair through ball f: the segment u_f . v = dk_f - a0 cut by the other balls; b, d, length."""
    rows = np.arange(dk.shape[0])
    sf, cf = s[rows, f][:, None], c[rows, f][:, None]
    rf = dk[rows, f] - a0
    px, py = rf * sf[:, 0], rf * cf[:, 0]
    a = s * cf - c * sf
    bnd = (dk - a0[:, None]) - rf[:, None] * (c * cf + s * sf)
    with np.errstate(divide="ignore", invalid="ignore"):
        lim = bnd / a
    t_hi = np.where(a > 1e-12, lim, np.inf).min(axis=1)
    t_lo = np.where(a < -1e-12, lim, -np.inf).max(axis=1)
    mid = 0.5 * (t_lo + t_hi)
    crossed = t_lo > t_hi  # rounding crossed the two ends of a face of zero length
    t_lo = np.where(crossed, mid, t_lo)
    t_hi = np.where(crossed, mid, t_hi)
    sf, cf = sf[:, 0], cf[:, 0]
    if midpoint:
        t = mid
    else:
        t = np.minimum(np.maximum((centre_b - px) * cf + (centre_d - py) * (-sf), t_lo), t_hi)
    return px + t * cf, py - t * sf, t_hi - t_lo


def solve_dual(dk, angles, centre_b, centre_d, tie_break="centre", kernel=None):
    """Exact solve of (6.1) through its dual, vectorized over positions; memory O(P n).

    dk, angles: (P, n) in um and rad; centre_b, centre_d: (P,) tie-break centre in um. ``kernel``, if
    given, is :func:`bearinglab.runout._compiled.solve` (the same method one position at a time, compiled),
    which the caller imports only when the compiled engine runs (it imports numba).
    Returns a0, b, d, lam, degenerate, diameter.

    Raises
    ------
    ConvergenceError
        A walk did not end within ``max_pivots(n)`` pivots (never seen; rounding could only
        make a walk go round).
    """
    P, n = dk.shape
    centre_b = np.broadcast_to(np.asarray(centre_b, float), (P,))
    centre_d = np.broadcast_to(np.asarray(centre_d, float), (P,))
    s, c = np.sin(angles), np.cos(angles)
    midpoint = tie_break == "midpoint"
    if kernel is not None:
        *res, status = kernel(dk, s, c, centre_b, centre_d, midpoint)
    else:
        res = [np.empty(P), np.empty(P), np.empty(P), np.empty((P, n)), np.empty(P, bool), np.empty(P)]
        status = np.empty(P, np.int64)
        step = max(1, _BLOCK // n)  # positions per block: the block's arrays stay in cache
        for a in range(0, P, step):
            sl = slice(a, a + step)
            *block, status[sl] = _walk(dk[sl], s[sl], c[sl], centre_b[sl], centre_d[sl], midpoint)
            for o, v in zip(res, block):
                o[sl] = v
    check_status(status, dk, n)
    return tuple(res)


def check_status(status, dk, n):
    """Raise ConvergenceError if a walk did not end (status != 0)."""
    bad = np.flatnonzero(np.ravel(status) != _OK)
    if bad.size:
        raise ConvergenceError(
            "runout.solve_contact (dual walk)",
            iterations=max_pivots(n),
            residual=np.inf,
            estimate=np.nan,
            reason=f"{bad.size} position(s) or sample(s), first {int(bad[0])}",
        )


def solve_triples(dk, angles, centre_b, centre_d):
    """Enumeration of spec 003 section 8.2: all triples, feasibility, max a0, then the face candidates.

    Independent of :func:`solve_dual` (it never uses the dual); O(n^3) per position, refused (InputError)
    above :data:`MAX_TRIPLES_BALLS` balls before anything is allocated.
    """
    P, n = dk.shape
    if n > MAX_TRIPLES_BALLS:
        raise InputError(
            f"method='triples' enumerates all C(n, 3) ball triples and is limited to n_balls <= "
            f"{MAX_TRIPLES_BALLS} [-], got {n}; use method='dual' (any number of balls)"
        )
    idx = _triples(n)
    chunk = max(1, _TRIPLES_BLOCK // (idx.shape[0] * (n + 3)))
    pairs = np.array(list(itertools.combinations(range(n), 2)), dtype=np.intp)
    centre_b = np.broadcast_to(np.asarray(centre_b, float), (P,))
    centre_d = np.broadcast_to(np.asarray(centre_d, float), (P,))
    a0 = np.empty(P)
    b = np.empty(P)
    d = np.empty(P)
    diam = np.empty(P)
    for s in range(0, P, chunk):
        sl = slice(s, s + chunk)
        th, k = angles[sl], dk[sl]
        m = th.shape[0]
        sx, cx = np.sin(th), np.cos(th)
        # step 1: sinusoid through each triple (3x3 solves)
        mat = np.stack([np.ones((m,) + idx.shape), sx[:, idx], cx[:, idx]], axis=-1)
        sol = np.linalg.solve(mat, k[:, idx][..., None])[..., 0]  # (m, T, 3)
        # step 2: keep the triples whose sinusoid lies on or below every point (eps = 1e-9 um)
        s_all = sol[..., 0:1] + sol[..., 1:2] * sx[:, None, :] + sol[..., 2:3] * cx[:, None, :]
        eps = RUNOUT_TIE_TOL_UM * scale(k)
        feas = np.all(k[:, None, :] - s_all >= -eps[:, None, None], axis=2)
        # step 3: the largest a0 among them
        a = np.where(feas, sol[..., 0], -np.inf).max(axis=1)
        # step 4: candidates on the face F = {v : u_i . v <= dk_i - a0}
        r = k - a[:, None]
        cb, cd = centre_b[sl], centre_d[sl]
        proj_b = cb[:, None] - (sx * cb[:, None] + cx * cd[:, None] - r) * sx
        proj_d = cd[:, None] - (sx * cb[:, None] + cx * cd[:, None] - r) * cx
        i, j = pairs[:, 0], pairs[:, 1]
        det = sx[:, i] * cx[:, j] - cx[:, i] * sx[:, j]
        ok = np.abs(det) > 1e-12
        with np.errstate(divide="ignore", invalid="ignore"):
            ib = (r[:, i] * cx[:, j] - cx[:, i] * r[:, j]) / det
            idd = (sx[:, i] * r[:, j] - r[:, i] * sx[:, j]) / det
        cand_b = np.concatenate([cb[:, None], proj_b, np.where(ok, ib, np.nan)], axis=1)
        cand_d = np.concatenate([cd[:, None], proj_d, np.where(ok, idd, np.nan)], axis=1)
        ftol = RUNOUT_FACE_TOL_UM * scale(k)
        viol = (cand_b[..., None] * sx[:, None, :] + cand_d[..., None] * cx[:, None, :]) - r[
            :, None, :
        ]
        good = np.all(viol <= ftol[:, None, None], axis=2) & np.isfinite(cand_b)
        dist = np.where(good, np.hypot(cand_b - cb[:, None], cand_d - cd[:, None]), np.inf)
        best = dist.argmin(axis=1)
        rows = np.arange(m)
        a0[sl], b[sl], d[sl] = a, cand_b[rows, best], cand_d[rows, best]
        # face diameter: largest distance between feasible pairwise intersections (vertices of F),
        # feasible to eps as the LP's face: ftol would admit vertices up to ~ftol / sin(angle) off F,
        # whose spread exceeds the contact tolerance on a face that is a single point
        vert = np.all(viol[:, 1 + n :] <= eps[:, None, None], axis=2) & good[:, 1 + n :]
        vb = np.where(vert, cand_b[:, 1 + n :], np.nan)
        vd = np.where(vert, cand_d[:, 1 + n :], np.nan)
        spread = np.hypot(vb[:, :, None] - vb[:, None, :], vd[:, :, None] - vd[:, None, :])
        diam[sl] = np.nan_to_num(
            np.nanmax(np.where(np.isnan(spread), -np.inf, spread), axis=(1, 2)), neginf=0.0
        )
    return a0, b, d, diam


def _polish_vertex(v, face, rhs):
    """A face end point from the LP, moved onto the exact intersection of its two tightest independent
    constraints. The simplex returns it within its feasibility tolerance (~1e-10); on a face much shorter
    than its distance to the tie-break centre, the projection onto the face magnifies that by the ratio
    (1e6 seen), so the cross-check would measure the LP's tolerance, not the solvers' disagreement."""
    order = np.argsort(np.abs(rhs - face @ v))
    i = order[0]
    for j in order[1:]:
        if abs(face[i, 0] * face[j, 1] - face[i, 1] * face[j, 0]) > 1e-8:  # not parallel
            exact = np.linalg.solve(face[[i, j]], rhs[[i, j]])
            # keep the LP's point if the pair was not the vertex's (the exact point must be feasible)
            return exact if np.all(face @ exact - rhs <= 1e-9 * max(1.0, np.abs(rhs).max())) else v
    return v


def solve_lp(dk, angles, centre_b, centre_d):
    """Reference solve with a general LP solver, one position at a time (spec 003 section 8.1).

    Stage 1 maximises a0; the face {u_i . v <= dk_i - a0 + eps} is then explored with four LPs
    (extremes of B and of D); HiGHS's dual simplex returns vertices, so the extremes are the face's end
    points. The tie-break point is the projection of c on the segment between the two farthest ones.
    """
    from scipy.optimize import linprog

    P, n = dk.shape
    centre_b = np.broadcast_to(np.asarray(centre_b, float), (P,))
    centre_d = np.broadcast_to(np.asarray(centre_d, float), (P,))
    opts = {"primal_feasibility_tolerance": 1e-10, "dual_feasibility_tolerance": 1e-10}
    a0, b, d, diam = (np.empty(P) for _ in range(4))
    for p in range(P):
        sx, cx = np.sin(angles[p]), np.cos(angles[p])
        res = linprog(
            [-1.0, 0.0, 0.0],
            A_ub=np.column_stack([np.ones(n), sx, cx]),
            b_ub=dk[p],
            bounds=[(None, None)] * 3,
            method="highs-ds",
            options=opts,
        )
        if res.status != 0:
            raise ConvergenceError(
                "runout.solve_contact (linprog)",
                iterations=res.nit,
                residual=np.inf,
                estimate=res.x,
                reason=f"position {p}: {res.message}",
            )
        a = res.x[0]
        face = np.column_stack([sx, cx])
        rhs = dk[p] - a + RUNOUT_TIE_TOL_UM * scale(dk[p])
        ends = []
        for obj in ([1.0, 0.0], [-1.0, 0.0], [0.0, 1.0], [0.0, -1.0]):
            r2 = linprog(
                obj, A_ub=face, b_ub=rhs, bounds=[(None, None)] * 2, method="highs-ds", options=opts
            )
            if r2.status != 0:
                raise ConvergenceError(
                    "runout.solve_contact (linprog, face)",
                    iterations=r2.nit,
                    residual=np.inf,
                    estimate=r2.x,
                    reason=f"position {p}: {r2.message}",
                )
            ends.append(_polish_vertex(r2.x, face, dk[p] - a))
        ends = np.array(ends)
        dist = np.hypot(ends[:, None, 0] - ends[None, :, 0], ends[:, None, 1] - ends[None, :, 1])
        i, j = np.unravel_index(dist.argmax(), dist.shape)
        p1, p2 = ends[i], ends[j]
        seg = p2 - p1
        length = float(np.hypot(*seg))
        c = np.array([centre_b[p], centre_d[p]])
        if length > 0:
            # divided in two steps: length**2 underflows to 0 on a face ~1e-160 um long (hypothesis found it)
            t = np.clip(np.dot(c - p1, seg / length) / length, 0.0, 1.0)
            v = p1 + t * seg
        else:
            v = p1
        a0[p], b[p], d[p], diam[p] = a, v[0], v[1], length
    return a0, b, d, diam
