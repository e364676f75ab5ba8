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
                ball triangles that contain the origin and the diametral pairs, so a0 is the smallest
                barycentric interpolation of dk at the origin over those (one matrix product for a batch
                of positions when the balls keep their relative azimuths, as in spec 003 section 10)
solve_triples   the independent enumeration of spec 003 section 8.2 (primal triples, then the face
                candidates of step 4)
solve_lp        the general LP solver (scipy.optimize.linprog, HiGHS dual simplex), one position at a
                time: stage 1, then the face vertices from four small LPs (section 8.1)

Each returns ``(a0, b, d, lam, degenerate, diameter)`` with ``lam`` the dual weights (load shares)
per ball; the callers compute slacks and contact flags.
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
from ..errors import ConvergenceError

__all__: list[str] = []

_SAME_PATTERN_ATOL = 1e-12  # rad, relative azimuths equal in all positions -> one candidate matrix
_CHUNK = 4096  # positions per block in the paths that need per-position candidate weights
_BLOCK = 4096  # positions per block of the shared-candidate path (values stay in cache)


def scale(dk):
    """Per-position tolerance multiplier: max(1, max |dk|) in um (spec 003 section 7.6)."""
    return np.maximum(1.0, np.max(np.abs(dk), axis=-1))


def _unit(angles):
    # constraint normals in the (B, D) plane: u_i = (sin theta_i, cos theta_i)
    return np.sin(angles), np.cos(angles)


def _cross(ax, ay, bx, by):
    return ax * by - ay * bx


def _triples(n):
    return np.array(list(itertools.combinations(range(n), 3)), dtype=np.intp).reshape(-1, 3)


def _barycentric(angles, idx):
    """Barycentric coordinates of the origin in the triangles ``idx`` of the unit points at ``angles``.

    angles (m, n) -> lam (m, T, 3). Three distinct points of a circle are never collinear, so the
    triangle area in the denominator does not vanish for distinct azimuths.
    """
    ux, uy = _unit(angles)
    x = ux[:, idx]
    y = uy[:, idx]
    w0 = _cross(x[..., 1], y[..., 1], x[..., 2], y[..., 2])
    w1 = _cross(x[..., 2], y[..., 2], x[..., 0], y[..., 0])
    w2 = _cross(x[..., 0], y[..., 0], x[..., 1], y[..., 1])
    w = np.stack([w0, w1, w2], axis=-1)
    return w / w.sum(axis=-1, keepdims=True)


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


def _shared_candidates(pattern):
    """Dual vertices for one azimuth pattern (n,): strict triangles and diametral pairs.

    Returns idx (T, 3), lam (T, 3), strict (T,). A pair is stored as a triangle whose third weight is 0;
    each diametral pair appears once.
    """
    n = pattern.size
    idx = _triples(n)
    lam = _barycentric(pattern[None, :], idx)[0]
    lo = lam.min(axis=1)
    strict = lo > RUNOUT_STRICT_WEIGHT
    keep = strict.copy()
    pairs = []
    seen = set()
    for t in np.flatnonzero((lo >= -RUNOUT_STRICT_WEIGHT) & ~strict):
        order = np.argsort(lam[t])[::-1]
        i, j = sorted(idx[t, order[:2]])
        if (i, j) in seen:
            continue
        seen.add((i, j))
        if abs(np.sin(pattern[j] - pattern[i])) < 1e-12 and np.cos(pattern[j] - pattern[i]) < 0:
            pairs.append((i, j))
        else:  # a near-degenerate triangle of an irregular set: keep it as it is
            keep[t] = True
    order = np.argsort(~strict[keep], kind="stable")  # strict triangles first
    idx_s, lam_s, strict_s = idx[keep][order], lam[keep][order], strict[keep][order]
    if pairs:
        pi = np.array([(i, j, j) for i, j in pairs], dtype=np.intp)
        pl = np.tile([0.5, 0.5, 0.0], (len(pairs), 1))
        idx_s = np.concatenate([idx_s, pi])
        lam_s = np.concatenate([lam_s, pl])
        strict_s = np.concatenate([strict_s, np.zeros(len(pairs), bool)])
    return idx_s, lam_s, strict_s


def _point_from_triangle(dk, angles, a0, tri):
    """(B, D) through the three balls of ``tri`` at height a0: least squares on the 3 equations."""
    rows = np.arange(dk.shape[0])[:, None]
    th = angles[rows, tri]
    r = dk[rows, tri] - a0[:, None]
    sx, cx = np.sin(th), np.cos(th)
    # normal equations of u_i . v = r_i, i in tri
    m11 = (sx * sx).sum(1)
    m12 = (sx * cx).sum(1)
    m22 = (cx * cx).sum(1)
    y1 = (sx * r).sum(1)
    y2 = (cx * r).sum(1)
    det = m11 * m22 - m12 * m12
    b = (m22 * y1 - m12 * y2) / det
    d = (m11 * y2 - m12 * y1) / det
    return b, d


def _segment(dk, angles, a0, i, centre_b, centre_d, tie_break):
    """Face of a diametral pair (i, i'): the segment u_i . v = r_i cut by the other balls.

    Returns b, d, length.
    """
    rows = np.arange(dk.shape[0])
    th_i = angles[rows, i]
    r_i = dk[rows, i] - a0
    ux, uy = np.sin(th_i), np.cos(th_i)
    ex, ey = uy, -ux  # along the face, perpendicular to u_i
    p0x, p0y = r_i * ux, r_i * uy
    rel = angles - th_i[:, None]
    a = np.sin(rel)  # u_k . e
    bnd = (dk - a0[:, None]) - r_i[:, None] * np.cos(rel)  # r_k - u_k . p0
    with np.errstate(divide="ignore", invalid="ignore"):
        lim = bnd / a
    up = a > 1e-12
    dn = a < -1e-12
    t_hi = np.where(up, lim, np.inf).min(axis=1)
    t_lo = np.where(dn, lim, -np.inf).max(axis=1)
    # rounding can cross the two ends of a zero-length face
    mid = 0.5 * (t_lo + t_hi)
    crossed = t_lo > t_hi
    t_lo = np.where(crossed, mid, t_lo)
    t_hi = np.where(crossed, mid, t_hi)
    if tie_break == "midpoint":
        t = mid
    else:
        t_c = (centre_b - p0x) * ex + (centre_d - p0y) * ey
        t = np.clip(t_c, t_lo, t_hi)
    return p0x + t * ex, p0y + t * ey, t_hi - t_lo


def _finish(dk, angles, values, idx, lam, strict, centre_b, centre_d, tie_break):
    """From candidate values to the solution (shared by the shared and per-position paths).

    values: (P, T) for per-position candidates, or the pair (strict block, other block) of column
    blocks for shared candidates (``strict`` 1-D, strict candidates first).
    """
    P, n = dk.shape
    rows = np.arange(P)
    tol = RUNOUT_TIE_TOL_UM * scale(dk)
    if strict.ndim == 1:  # shared candidates, strict ones first
        ns = int(strict.sum())
        # values = (strict block, rest block), each C-contiguous (argmin on a column slice is slow)
        v_s, v_r = values
        t_s = v_s.argmin(axis=1) if ns else np.zeros(P, np.intp)
        s_min = v_s[rows, t_s] if ns else np.full(P, np.inf)
        if v_r.shape[1]:
            t_r = v_r.argmin(axis=1) + ns
            r_min = v_r[rows, t_r - ns]
        else:
            t_r, r_min = t_s, s_min
        a0 = np.minimum(s_min, r_min)
        t_all = np.where(s_min <= r_min, t_s, t_r)
    else:
        t_all = values.argmin(axis=1)
        a0 = values[rows, t_all]
        vs = np.where(strict, values, np.inf)
        t_s = vs.argmin(axis=1)
        s_min = vs[rows, t_s]
    point = s_min <= a0 + tol
    # the winning candidate: a strict triangle if one is optimal, otherwise a diametral pair
    t_win = np.where(point, t_s, t_all)
    idx_w = idx[t_win] if idx.ndim == 2 else idx[rows, t_win]
    lam_w = lam[t_win] if lam.ndim == 2 else lam[rows, t_win]
    b = np.empty(P)
    d = np.empty(P)
    length = np.zeros(P)
    if point.any():
        b[point], d[point] = _point_from_triangle(dk[point], angles[point], a0[point], idx_w[point])
    seg = ~point
    if seg.any():
        order = np.argsort(-lam_w[seg], axis=1)
        first = np.take_along_axis(idx_w[seg], order[:, :1], axis=1)[:, 0]
        b[seg], d[seg], length[seg] = _segment(
            dk[seg],
            angles[seg],
            a0[seg],
            first,
            np.broadcast_to(centre_b, (P,))[seg],
            np.broadcast_to(centre_d, (P,))[seg],
            tie_break,
        )
    weights = np.zeros((P, n))
    for j in (2, 1, 0):  # one index per row in each assignment; a pair's third weight is 0
        weights[rows, idx_w[:, j]] += lam_w[:, j]
    degenerate = length > RUNOUT_CONTACT_TOL_UM * scale(dk)
    return a0, b, d, weights, degenerate, np.where(degenerate, length, 0.0)


def _weighted(dk, idx, lam):
    """(P, T) array of lam[t, 0] dk[:, idx[t, 0]] + lam[t, 1] dk[:, idx[t, 1]] + lam[t, 2] dk[:, idx[t, 2]].

    Summed in a fixed order per row (not a BLAS product, whose rounding can depend on the number of
    rows): a position gives the same bits alone or in any batch.
    """
    out = np.take(dk, idx[:, 0], axis=1)
    out *= lam[:, 0]
    for j in (1, 2):
        tmp = np.take(dk, idx[:, j], axis=1)
        tmp *= lam[:, j]
        out += tmp
    return out


def _pattern(angles):
    """Azimuths relative to ball 1 shared by all positions; the exact regular pattern when equally spaced.

    Snapping to 2 pi k / n makes the candidate weights independent of which position they are taken
    from, so results do not depend on how positions are batched.
    """
    n = angles.shape[-1]
    rel = np.remainder(angles[0] - angles[0, 0], 2 * np.pi)
    regular = 2 * np.pi * np.arange(n) / n
    if np.all(np.abs(rel - regular) < 1e-9):
        return regular
    return rel


def solve_dual(dk, angles, centre_b, centre_d, tie_break="centre"):
    """Exact solve of (6.1) by the dual (convex-hull) vertices, vectorized over positions.

    dk, angles: (P, n) in um and rad; centre_b, centre_d: (P,) tie-break centre in um.
    """
    P, n = dk.shape
    centre_b = np.broadcast_to(np.asarray(centre_b, float), (P,))
    centre_d = np.broadcast_to(np.asarray(centre_d, float), (P,))
    out = [np.empty(P), np.empty(P), np.empty(P), np.empty((P, n)), np.empty(P, bool), np.empty(P)]
    if same_pattern(angles):
        idx, lam, strict = _shared_candidates(_pattern(angles))
        ns = int(strict.sum())
        for s in range(0, P, _BLOCK):  # blocks of positions that stay in cache
            sl = slice(s, s + _BLOCK)
            values = tuple(
                _weighted(dk[sl], idx[c], lam[c]) for c in (slice(0, ns), slice(ns, None))
            )
            res = _finish(
                dk[sl], angles[sl], values, idx, lam, strict, centre_b[sl], centre_d[sl], tie_break
            )
            for o, r in zip(out, res):
                o[sl] = r
        return tuple(out)
    # irregular azimuths that change from position to position: candidate weights per position
    idx = _triples(n)
    for s in range(0, P, _CHUNK):
        sl = slice(s, s + _CHUNK)
        lam = _barycentric(angles[sl], idx)
        lo = lam.min(axis=2)
        valid = lo >= -RUNOUT_STRICT_WEIGHT
        strict = lo > RUNOUT_STRICT_WEIGHT
        values = np.where(valid, np.einsum("ptk,ptk->pt", lam, dk[sl][:, idx]), np.inf)
        m = values.shape[0]
        res = _finish(
            dk[sl],
            angles[sl],
            values,
            np.broadcast_to(idx, (m,) + idx.shape),
            lam,
            strict,
            centre_b[sl],
            centre_d[sl],
            tie_break,
        )
        for o, r in zip(out, res):
            o[sl] = r
    return tuple(out)


def solve_triples(dk, angles, centre_b, centre_d, chunk=256):
    """Enumeration of spec 003 section 8.2: all triples, feasibility, max a0, then the face candidates.

    Independent of :func:`solve_dual` (it never uses the dual); O(n^3) per position.
    """
    P, n = dk.shape
    idx = _triples(n)
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
