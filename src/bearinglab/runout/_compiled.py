r"""The compiled path of the runout model (spec 003 sections 4-8, 10, 11): the contact problem of one
position at a time, and the generalized errors and contact solves of whole rotation sequences.

The same method as the numpy path of :mod:`bearinglab.runout._solver`, written in scalar form so that numba
can compile it, and run in parallel over positions or Monte Carlo samples:

- the contact problem (6.1) by its dual: a walk over the triangles of balls that contain the centre
  (the simplex method on the dual, from a start triangle of the lowest ball and the balls nearest to
  +-120 deg from it), then the point of the optimal face (the tie-break of section 7.5), the load shares
  and the face diameter. Memory O(n) per position, time O(n) per pivot;
- the generalized errors (4.1) of a rotation sequence, first approximation: the Fourier series of the
  outer ring at theta^i = alpha^i + kappa psi and of the inner ring at theta^i - psi. Each sample
  tabulates c_k exp(i k alpha^i) once, and each position adds Re sum_k of it times exp(i k beta) (the
  powers by recurrence; beta = kappa psi, or kappa psi - psi for the inner ring); a series too long for the
  table (n (K + 1) > ``TABLE_LIMIT``) is summed by Horner's rule in z = exp(i alpha^i) exp(i beta)
  instead. Either way no sine or cosine per ball and position, and the loops run over the balls
  (vectorized);
- the runout metric radial_ptp_max of a trajectory: the diameter of its points.

A position's or a sample's result depends on its own data only (not on the batch, the chunk or the thread
that computes it). A call runs on all of numba's threads, or on the calling thread alone (without the GIL)
for a small call, a single sample and inside a task of a dask worker (whose executor already gives each
chunk its core). Nothing here is public:
:mod:`bearinglab.runout.contact`, :mod:`~bearinglab.runout.rotation` and
:mod:`~bearinglab.runout.tolerances` import this module (and numba, which only this module imports) when
their ``engine`` is the compiled one; without numba the functions run as plain Python.

Functions
---------
available        True if numba imports (the compiled path can run)
walk             the contact problem of one position (scalar; the numpy path does the same on arrays)
solve            the contact problem of many positions, given Delta k and the ball directions
sequences        Delta k and the contact problem of whole rotation sequences (one per sample), first
                 approximation
diameter         largest distance between two points of a trajectory (monotone chain, rotating calipers)
diameters        the same for many trajectories

References
----------
.. [1] G. B. Dantzig, *Linear Programming and Extensions*, Princeton University Press, 1963, ch. 7 (the
   simplex method, here on the dual of (6.1) with three equality rows).
.. [2] W. H. Press, S. A. Teukolsky, W. T. Vetterling and B. P. Flannery, *Numerical Recipes*, 3rd ed.,
   Cambridge University Press, 2007, section 5.1 (Horner's rule for polynomials).
"""

from __future__ import annotations

import math
import sys

import numpy as np

from .. import _numba
from .._solve import RUNOUT_CONTACT_TOL_UM, RUNOUT_STRICT_WEIGHT
from . import _solver
from ._solver import _NOCONV, _OK, _SIN120, PIVOTS_EXTRA, PIVOTS_PER_BALL, WALK_TOL_UM

#: Largest n (K + 1) of a ring whose series is tabulated per sample (two tables of that many doubles, 1 MB at
#: the limit, per ring and thread); a bigger one is summed by Horner's rule at every ball and position
#: (twice the arithmetic, no table). Each gives the same bits for a sample in any batch.
TABLE_LIMIT = 1 << 16

try:
    import numba
except ImportError:  # the numpy path is used instead (engine="auto")
    numba = None

__all__ = ["available", "diameter", "diameters", "sequences", "solve", "walk"]


def _jit(func):
    return func if numba is None else numba.njit(cache=True)(func)


def available():
    """True if numba imports, so that the compiled kernels can run."""
    return numba is not None


# the solver's own arithmetic (written for arrays, it does the same on scalars): the same operations in the
# same order on both engines
_bary = _jit(_solver._bary)
_plane = _jit(_solver._plane)


@_jit
def _start(dk, s, c, i0):
    """A triangle of balls that contains the centre, with the lowest ball i0: the balls round(n/3) and
    round(2n/3) places on (the balls nearest to +-120 deg in an equally spaced set numbered round the
    circle), else the balls nearest to +-120 deg, else (irregular sets) the ball most nearly opposite i0 and
    the ball farthest from their chord on the centre's side (which always holds the centre when no
    half-circle holds every ball)."""
    n = dk.size
    x0, y0 = s[i0], c[i0]
    a, b = (i0 + (n + 1) // 3) % n, (i0 + (2 * n + 1) // 3) % n
    if a != i0 and b != i0 and a != b:
        li, la, lb = _bary(x0, y0, s[a], c[a], s[b], c[b], 0.0, 0.0)
        if min(li, min(la, lb)) >= -RUNOUT_STRICT_WEIGHT:
            return a, b
    w1x, w1y = -0.5 * x0 - _SIN120 * y0, _SIN120 * x0 - 0.5 * y0
    w2x, w2y = -0.5 * x0 + _SIN120 * y0, -_SIN120 * x0 - 0.5 * y0
    a, b = 0, 0
    best1, best2 = -np.inf, -np.inf
    for m in range(n):
        p1 = s[m] * w1x + c[m] * w1y
        p2 = s[m] * w2x + c[m] * w2y
        if p1 > best1:
            best1, a = p1, m
        if p2 > best2:
            best2, b = p2, m
    if a != i0 and b != i0 and a != b:
        li, la, lb = _bary(x0, y0, s[a], c[a], s[b], c[b], 0.0, 0.0)
        if min(li, min(la, lb)) >= -RUNOUT_STRICT_WEIGHT:
            return a, b
    a = 0
    best = np.inf
    for m in range(n):
        p = s[m] * x0 + c[m] * y0
        if p < best:
            best, a = p, m
    ex, ey = s[a] - x0, c[a] - y0
    sigma = 1.0 if ex * (-y0) - ey * (-x0) >= 0.0 else -1.0
    b = 0
    best = -np.inf
    for m in range(n):
        p = sigma * (ex * (c[m] - y0) - ey * (s[m] - x0))
        if p > best:
            best, b = p, m
    return a, b


@_jit
def _sort3(i, j, k):
    if i > j:
        i, j = j, i
    if j > k:
        j, k = k, j
    if i > j:
        i, j = j, i
    return i, j, k


@_jit
def walk(dk, s, c, cb, cd, midpoint, lam):
    """The contact problem (6.1) of one position, in um: ``(a0, B, D, degenerate, diameter, status)``.

    dk, s, c: (n,) Delta k [um] and sin, cos of the ball azimuths; (cb, cd) the tie-break centre [um];
    ``midpoint`` takes the middle of a degenerate face instead. ``lam`` (n,) receives the load shares.
    status 0: solved; 1: the walk did not end within ``_solver.max_pivots(n)`` pivots.
    """
    n = dk.size
    scale, i = 1.0, 0
    for m in range(n):
        scale = max(scale, abs(dk[m]))
        if dk[m] < dk[i]:  # the lowest ball (the first of equals)
            i = m
    thr = WALK_TOL_UM * scale
    j, k = _start(dk, s, c, i)
    # the vertices are kept sorted, so that the final triangle's values (those of its last pass) do not
    # depend on the path that led to it, and the ratio test breaks ties alike on both engines
    i, j, k = _sort3(i, j, k)
    status = _NOCONV
    for _ in range(PIVOTS_PER_BALL * n + PIVOTS_EXTRA + 1):
        li, lj, lk = _bary(s[i], c[i], s[j], c[j], s[k], c[k], 0.0, 0.0)
        a0 = li * dk[i] + lj * dk[j] + lk * dk[k]
        b, d = _plane(s[i], c[i], dk[i] - a0, s[j], c[j], dk[j] - a0, s[k], c[k], dk[k] - a0)
        e = 0
        low = np.inf
        for m in range(n):
            r = dk[m] - a0 - b * s[m] - d * c[m]
            if r < low:
                low, e = r, m
        if low >= -thr:
            status = _OK
            break
        # the entering ball replaces the vertex whose weight reaches 0 first (the ratio test)
        mi, mj, mk = _bary(s[i], c[i], s[j], c[j], s[k], c[k], s[e], c[e])
        out, best = 0, np.inf
        for slot, lm, mu in ((0, li, mi), (1, lj, mj), (2, lk, mk)):
            if mu > 0.0:
                ratio = max(lm, 0.0) / mu
                if ratio < best:
                    best, out = ratio, slot
        if out == 0:
            i = e
        elif out == 1:
            j = e
        else:
            k = e
        i, j, k = _sort3(i, j, k)
    if status != _OK:  # the caller raises
        return np.nan, np.nan, np.nan, False, 0.0, status
    for m in range(n):
        lam[m] = 0.0
    lam[i], lam[j], lam[k] = li, lj, lk
    if min(li, min(lj, lk)) > RUNOUT_STRICT_WEIGHT:  # the centre inside: one optimal point
        return a0, b, d, False, 0.0, status
    # the centre on an edge: a diametral pair, whose line u_f . v = dk_f - a0 the other balls cut
    f = i
    if lj > lam[f]:
        f = j
    if lk > lam[f]:
        f = k
    sf, cf = s[f], c[f]
    rf = dk[f] - a0
    px, py = rf * sf, rf * cf
    t_lo, t_hi = -np.inf, np.inf
    for m in range(n):
        a = s[m] * cf - c[m] * sf  # u_m . e, e = (cf, -sf) along the face
        bnd = (dk[m] - a0) - rf * (c[m] * cf + s[m] * sf)
        if a > 1e-12:
            t_hi = min(t_hi, bnd / a)
        elif a < -1e-12:
            t_lo = max(t_lo, bnd / a)
    mid = 0.5 * (t_lo + t_hi)
    if t_lo > t_hi:  # rounding crossed the two ends of a face of zero length
        t_lo, t_hi = mid, mid
    if midpoint:
        t = mid
    else:
        t = min(max((cb - px) * cf + (cd - py) * (-sf), t_lo), t_hi)
    length = t_hi - t_lo
    degenerate = length > RUNOUT_CONTACT_TOL_UM * scale
    return a0, px + t * cf, py - t * sf, degenerate, length if degenerate else 0.0, status


def _solve(dk, s, c, cb, cd, midpoint, a0, b, d, lam, deg, diam, status):
    for p in _prange(dk.shape[0]):  # parallel over the positions (each is independent of the others)
        a0[p], b[p], d[p], deg[p], diam[p], status[p] = walk(dk[p], s[p], c[p], cb[p], cd[p], midpoint, lam[p])


@_jit
def _horner_re(cr, ci, zr, zi, out, ar, ai):
    """out += Re sum_k (cr_k + i ci_k) z^k for every ball (z per ball), by Horner's rule; ar, ai scratch.

    The loop over the balls is innermost, with the coefficients held in scalars, so that it is vectorized.
    """
    n = zr.size
    top = cr.size - 1
    c_r, c_i = cr[top], ci[top]
    for m in range(n):
        ar[m] = c_r
        ai[m] = c_i
    for q in range(top - 1, -1, -1):
        c_r, c_i = cr[q], ci[q]
        for m in range(n):
            xr = ar[m] * zr[m] - ai[m] * zi[m] + c_r
            ai[m] = ar[m] * zi[m] + ai[m] * zr[m] + c_i
            ar[m] = xr
    for m in range(n):
        out[m] = out[m] + ar[m]


@_jit
def _ring_table(cr, ci, za_r, za_i, tr, ti, pw_r, pw_i):
    """tr + i ti [k, m] = (cr_k + i ci_k) exp(i k alpha_m), k = 0..K (the powers by recurrence); pw scratch."""
    n = za_r.size
    for m in range(n):
        pw_r[m] = 1.0
        pw_i[m] = 0.0
    for k in range(cr.size):
        c_r, c_i = cr[k], ci[k]
        for m in range(n):  # over the balls: vectorized
            tr[k, m] = c_r * pw_r[m] - c_i * pw_i[m]
            ti[k, m] = c_r * pw_i[m] + c_i * pw_r[m]
            x = pw_r[m] * za_r[m] - pw_i[m] * za_i[m]
            pw_i[m] = pw_r[m] * za_i[m] + pw_i[m] * za_r[m]
            pw_r[m] = x


@_jit
def _ring_add(tr, ti, w_r, w_i, out, acc):
    """out += Re sum_k (tr + i ti)[k] exp(i k beta) for every ball, exp(i beta) = w_r + i w_i (the powers by
    recurrence): 4 operations a ball and order where Horner's rule takes 8; acc scratch."""
    n = out.size
    for m in range(n):
        acc[m] = 0.0
    er, ei = 1.0, 0.0
    for k in range(tr.shape[0]):
        for m in range(n):  # over the balls: vectorized
            acc[m] += tr[k, m] * er - ti[k, m] * ei
        er, ei = er * w_r - ei * w_i, er * w_i + ei * w_r
    for m in range(n):
        out[m] = out[m] + acc[m]


def _sequences(t1, kappa, psi, oc, oi, ic, ii, deficit, cb, cd, midpoint, store, table_limit, dk_out, lam_out, a0,
               b, d, deg, diam, status):
    n = deficit.shape[1]
    P = psi.size
    # each ring's series is tabulated per sample against the balls' exp(i k alpha) when the table is small
    # (n (K + 1) <= table_limit), else summed by Horner's rule at every ball and position
    table_o = oc.shape[1] * n <= table_limit
    table_i = ic.shape[1] * n <= table_limit
    # the positions' factors of z, shared by every sample: exp(i kappa psi), exp(i (kappa psi - psi))
    wo_r, wo_i = np.empty(P), np.empty(P)
    wi_r, wi_i = np.empty(P), np.empty(P)
    for p in range(P):
        bo = kappa * psi[p]
        bi = bo - psi[p]
        wo_r[p], wo_i[p] = math.cos(bo), math.sin(bo)
        wi_r[p], wi_i[p] = math.cos(bi), math.sin(bi)
    for q in _prange(t1.size):  # parallel over the samples
        # a series or a deficit row per sample, or one for all (the prange index may be unsigned: no min)
        qi = np.int64(q)
        so = qi if oc.shape[0] > 1 else 0
        si = qi if ic.shape[0] > 1 else 0
        sd = qi if deficit.shape[0] > 1 else 0
        za_r, za_i = np.empty(n), np.empty(n)
        for m in range(n):
            alpha = t1[q] + 2.0 * np.pi * m / n
            za_r[m], za_i[m] = math.cos(alpha), math.sin(alpha)
        zo_r, zo_i, zi_r, zi_i = np.empty(n), np.empty(n), np.empty(n), np.empty(n)
        ar, ai, row, lam = np.empty(n), np.empty(n), np.empty(n), np.empty(n)
        ko, ki = oc.shape[1] if table_o else 0, ic.shape[1] if table_i else 0
        to_r, to_i, ti_r, ti_i = np.empty((ko, n)), np.empty((ko, n)), np.empty((ki, n)), np.empty((ki, n))
        if ko:
            _ring_table(oc[so], oi[so], za_r, za_i, to_r, to_i, ar, ai)
        if ki:
            _ring_table(ic[si], ii[si], za_r, za_i, ti_r, ti_i, ar, ai)
        status[q] = _OK
        for p in range(P):
            o_r, o_i, i_r, i_i = wo_r[p], wo_i[p], wi_r[p], wi_i[p]
            for m in range(n):
                zo_r[m] = za_r[m] * o_r - za_i[m] * o_i
                zo_i[m] = za_r[m] * o_i + za_i[m] * o_r
                row[m] = deficit[sd, m]
            if ko:
                _ring_add(to_r, to_i, o_r, o_i, row, ar)
            elif oc.shape[1]:
                _horner_re(oc[so], oi[so], zo_r, zo_i, row, ar, ai)
            if ki:
                _ring_add(ti_r, ti_i, i_r, i_i, row, ar)
            elif ic.shape[1]:
                for m in range(n):
                    zi_r[m] = za_r[m] * i_r - za_i[m] * i_i
                    zi_i[m] = za_r[m] * i_i + za_i[m] * i_r
                _horner_re(ic[si], ii[si], zi_r, zi_i, row, ar, ai)
            # zo = exp(i theta): sin theta = Im, cos theta = Re
            x = walk(row, zo_i, zo_r, cb[p], cd[p], midpoint, lam)
            a0[q, p], b[q, p], d[q, p], deg[q, p], diam[q, p] = x[0], x[1], x[2], x[3], x[4]
            if x[5] != _OK:
                status[q] = x[5]
            if store:
                for m in range(n):
                    dk_out[q * P + p, m] = row[m]
                    lam_out[q * P + p, m] = lam[m]


@_jit
def _d2(px, py, a, b):
    dx = px[a] - px[b]
    dy = py[a] - py[b]
    return dx * dx + dy * dy


@_jit
def diameter(px, py):
    """Largest distance between two of the points (px, py) (1-D): the diameter of their convex hull.

    Andrew's monotone chain [3]_ gives the hull (counterclockwise, collinear points dropped), rotating
    calipers [4]_ its antipodal pairs: each edge's ends with the vertex farthest from its line, and that
    vertex's two neighbours (against rounding and parallel edges). O(N log N) time, O(N) memory. The
    result is the square root of the largest dx^2 + dy^2 among them, as the numpy path takes it.

    .. [3] A. M. Andrew, "Another efficient algorithm for convex hulls in two dimensions," Information
       Processing Letters 9(5), 216-219, 1979.
    .. [4] M. I. Shamos, "Computational geometry," PhD thesis, Yale University, 1978, ch. 4.
    """
    n = px.size
    best = 0.0
    if n <= 8:  # few points: all pairs
        for a in range(n):
            for b in range(a + 1, n):
                best = max(best, _d2(px, py, a, b))
        return math.sqrt(best)
    order = np.argsort(px)  # by x, then (below) by y within runs of equal x
    start = 0
    for q in range(1, n + 1):
        if q == n or px[order[q]] != px[order[start]]:
            for r in range(start + 1, q):  # insertion sort of the run (runs are short, mostly of one)
                v = order[r]
                t = r
                while t > start and py[order[t - 1]] > py[v]:
                    order[t] = order[t - 1]
                    t -= 1
                order[t] = v
            start = q
    hull = np.empty(2 * n, dtype=np.int64)
    h = 0
    floor = 2
    for q in range(2 * n - 1):  # the lower chain left to right, then the upper one back
        v = order[q] if q < n else order[2 * n - 2 - q]
        if q == n:
            floor = h + 1  # the upper chain keeps the lower one's last point
        while h >= (2 if q < n else floor):
            o, a = hull[h - 2], hull[h - 1]
            if (px[a] - px[o]) * (py[v] - py[o]) - (py[a] - py[o]) * (px[v] - px[o]) > 0.0:
                break
            h -= 1
        hull[h] = v
        h += 1
    h -= 1  # the last point is the first
    if h <= 3:
        for a in range(h):
            for b in range(a + 1, h):
                best = max(best, _d2(px, py, hull[a], hull[b]))
        return math.sqrt(max(best, _extreme_pairs(px, py)))
    j = 1
    for i in range(h):
        i2 = i + 1 if i + 1 < h else 0
        a, b = hull[i], hull[i2]
        ex, ey = px[b] - px[a], py[b] - py[a]
        for _ in range(h):  # advance to the vertex farthest from the edge's line
            jn = j + 1 if j + 1 < h else 0
            c, cn = hull[j], hull[jn]
            if ex * (py[cn] - py[a]) - ey * (px[cn] - px[a]) > ex * (py[c] - py[a]) - ey * (px[c] - px[a]):
                j = jn
            else:
                break
        for k in (j - 1, j, j + 1):
            c = hull[k % h]
            best = max(best, max(_d2(px, py, a, c), _d2(px, py, b, c)))
    return math.sqrt(max(best, _extreme_pairs(px, py)))


@_jit
def _extreme_pairs(px, py):
    """The largest dx^2 + dy^2 among the points extreme along x, y, x + y and x - y: the diameter of a
    (nearly) collinear set, whose hull the rounding of the orientation test may leave with points out of
    order (the numpy path falls back to the same extremes where qhull finds the set flat)."""
    ext = np.zeros(8, dtype=np.int64)
    for q in range(1, px.size):
        if px[q] < px[ext[0]]:
            ext[0] = q
        if px[q] > px[ext[1]]:
            ext[1] = q
        if py[q] < py[ext[2]]:
            ext[2] = q
        if py[q] > py[ext[3]]:
            ext[3] = q
        if px[q] + py[q] < px[ext[4]] + py[ext[4]]:
            ext[4] = q
        if px[q] + py[q] > px[ext[5]] + py[ext[5]]:
            ext[5] = q
        if px[q] - py[q] < px[ext[6]] - py[ext[6]]:
            ext[6] = q
        if px[q] - py[q] > px[ext[7]] - py[ext[7]]:
            ext[7] = q
    best = 0.0
    for a in range(8):
        for b in range(a + 1, 8):
            best = max(best, _d2(px, py, ext[a], ext[b]))
    return best


def _diameters(x, y, out):
    for q in _prange(x.shape[0]):  # parallel over the trajectories
        out[q] = diameter(x[q], y[q])


_prange = range if numba is None else numba.prange
# each loop twice: over numba's threads (under the shared lock), and on the calling thread alone without the
# GIL (prange runs as range; threads of a dask worker run these side by side). The same scalar code, so the
# same bits
_KERNELS = {name: (func, func) for name, func in (("solve", _solve), ("sequences", _sequences),
                                                  ("diameters", _diameters))}
if numba is not None:
    _KERNELS = {name: (numba.njit(cache=True, nogil=True)(func), numba.njit(parallel=True, cache=True)(func))
                for name, (func, _) in _KERNELS.items()}


def _in_dask_worker():
    """True inside a task of a dask worker, whose executor already runs one chunk per thread it was given."""
    distributed = sys.modules.get("distributed")  # not imported: not a worker
    if distributed is None:
        return False
    try:
        distributed.get_worker()
    except ValueError:
        return False
    return True


def _threads_to_use(work, items):
    """Threads for a call of ``items`` parallel iterations: one for a small call or a single item (waking
    the others costs more than it saves, most on a loaded machine) and on a dask worker (more would compete
    with the other workers for the cores), else all of numba's."""
    if numba is None or work < 4096 or items < 2 or _in_dask_worker():
        return 1
    return numba.config.NUMBA_NUM_THREADS


def _run(name, work, items, *args):
    """Run kernel ``name`` on one thread, or on numba's threads under the shared lock (numba's workqueue
    layer forbids concurrent launches of parallel kernels)."""
    serial, parallel = _KERNELS[name]
    threads = _threads_to_use(work, items)
    if threads == 1:
        return serial(*args)
    with _numba.LOCK:
        before = numba.get_num_threads()
        numba.set_num_threads(threads)
        try:
            return parallel(*args)
        finally:
            numba.set_num_threads(before)


def diameters(x, y):
    """:func:`diameter` of every trajectory (rows of x, y (S, N)): (S,)."""
    x, y = (np.ascontiguousarray(v, dtype=float) for v in (x, y))
    out = np.empty(x.shape[0])
    _run("diameters", x.size, x.shape[0], x, y, out)
    return out


def solve(dk, s, c, cb, cd, midpoint):
    """The contact problem of P positions: dk, s, c (P, n) [um], cb, cd (P,) [um].

    Returns ``(a0, b, d, lam, degenerate, diameter, status)``, the first three and the last three (P,), lam
    (P, n); status 1 marks a position whose walk did not end (the caller raises).
    """
    dk, s, c = (np.ascontiguousarray(v, dtype=float) for v in (dk, s, c))
    P, n = dk.shape
    cb = np.ascontiguousarray(np.broadcast_to(np.asarray(cb, float), (P,)))
    cd = np.ascontiguousarray(np.broadcast_to(np.asarray(cd, float), (P,)))
    a0, b, d, diam = np.empty(P), np.empty(P), np.empty(P), np.empty(P)
    lam, deg, status = np.empty((P, n)), np.empty(P, dtype=np.bool_), np.empty(P, dtype=np.int64)
    _run("solve", P * n, P, dk, s, c, cb, cd, bool(midpoint), a0, b, d, lam, deg, diam, status)
    return a0, b, d, lam, deg, diam, status


def sequences(first_ball_angle, cage_ratio, psi, outer, inner, deficit, cb, cd, midpoint=False, store=False):
    """Delta k (first approximation) and the contact problem at every position of S rotation sequences.

    Parameters
    ----------
    first_ball_angle : ndarray
        theta^1 per sample, (S,). [rad]
    cage_ratio : float
        kappa. [-]
    psi : ndarray
        Rotation angles, (P,), the same for every sample. [rad]
    outer, inner : tuple of ndarray or None
        ``(cos, sin)`` coefficients [um] of the normal deviation of each ring at tau0 (one series each,
        :func:`bearinglab.runout.deviations._combined`), (S or 1, K + 1); None for no error.
    deficit : ndarray
        Delta r31 + Delta r32 per ball, (S or 1, n). [um]
    cb, cd : ndarray
        Tie-break centre per position, (P,). [um]
    midpoint, store : bool
        Middle of a degenerate face; keep Delta k and the load shares (else only the sinusoid).

    Returns
    -------
    tuple
        a0, B, D [um], degenerate, face diameter [um], each (S, P); status (S,); and with ``store`` Delta k
        and the load shares, (S P, n) (else None).
    """
    t1 = np.ascontiguousarray(np.atleast_1d(first_ball_angle), dtype=float)
    psi = np.ascontiguousarray(psi, dtype=float)
    deficit = np.ascontiguousarray(np.atleast_2d(deficit), dtype=float)
    S, P, n = t1.size, psi.size, deficit.shape[1]

    def series(v):
        if v is None:
            return np.zeros((1, 0)), np.zeros((1, 0))
        cos, sin = (np.atleast_2d(np.asarray(x, float)) for x in v)
        # c_k = cos_k - i sin_k, as deviations._horner takes them
        return np.ascontiguousarray(cos), np.ascontiguousarray(-sin)

    oc, oi = series(outer)
    ic, ii = series(inner)
    cb = np.ascontiguousarray(np.broadcast_to(np.asarray(cb, float), (P,)))
    cd = np.ascontiguousarray(np.broadcast_to(np.asarray(cd, float), (P,)))
    out = [np.empty((S, P)) for _ in range(3)]
    deg, diam, status = np.empty((S, P), dtype=np.bool_), np.empty((S, P)), np.empty(S, dtype=np.int64)
    dk_out = np.empty((S * P, n)) if store else np.empty((1, n))
    lam_out = np.empty((S * P, n)) if store else np.empty((1, n))
    _run("sequences", S * P * n, S, t1, float(cage_ratio), psi, oc, oi, ic, ii, deficit, cb, cd, bool(midpoint),
         bool(store), TABLE_LIMIT, dk_out, lam_out, *out, deg, diam, status)
    return (*out, deg, diam, status, dk_out if store else None, lam_out if store else None)
