r"""The paper's contact-angle search: spec 004 section 5.2, the alternative to Newton.

A 61 x 61 grid over the triangle alpha_s <= alpha_i <= alpha_s + Delta, alpha_s - Delta <= alpha_e <=
alpha_s, alpha_i + alpha_e <= 2 alpha_s (alpha_s the static angle), then a bounded damped Newton
least-squares refinement of E3, E7 (:func:`bearinglab.quasistatic.angle_residual`). A minimum with
sum E^2 >= 1e-20 is not a root, and the whole quadrant is searched instead.

Nothing here is public: :func:`bearinglab.quasistatic.contact_angles` with
``method="angle-iteration"`` calls ``_angle_iteration``.

References
----------
.. [1] Zhao Chunjiang, Cui Guohua, Wang Guoqiang, Huang Qingxue and Zhang Fangping, "Precise definition
   of the contact-angle field of a high-speed angular-contact ball bearing under axial load,"
   Transactions of the CSAM, vol. 39, no. 12, pp. 154-156, 209, 2008 (spec 004 of this project).
"""

from __future__ import annotations

import numpy as np

from .equations import _angle_sequence

__all__: list[str] = []

_ROOT_TOL = 1e-20  # scaled sum of squares below which a search minimum is a root (spec 004 section 5.2)
_GRID = 61  # search grid of section 5.2


def _refine_angles(model, idx, ai, ae, w2, lo_i, hi_i, lo_e, hi_e, line=None, max_iter=60):
    """Bounded damped Newton (least squares) on E3, E7 in (alpha_i, alpha_e), all cases at once.

    Iterates stay in the box [lo, hi] and, if ``line`` is given, below alpha_i + alpha_e = line (the
    triangle of section 5.2: a point above the line is projected onto it).
    """
    x = np.stack([ai, ae], axis=1)
    lo = np.stack([lo_i, lo_e], axis=1)
    hi = np.stack([hi_i, hi_e], axis=1)

    def project(xx, sel):
        xx = np.clip(xx, lo[sel], hi[sel])
        if line is not None:
            excess = np.maximum(xx[:, 0] + xx[:, 1] - line[sel], 0.0)
            xx = np.clip(xx - 0.5 * excess[:, None], lo[sel], hi[sel])
        return xx

    iters = np.zeros(len(idx), dtype=int)

    def obj(sel, xx):
        s = _angle_sequence(model, idx[sel], xx[:, 0], xx[:, 1], w2[sel])
        e = np.stack([s.radial, s.ring], axis=1)
        val = np.where(s.valid, np.einsum("ij,ij->i", e, e), np.inf)
        return e, val

    e, f = obj(np.arange(len(idx)), x)
    h = 1e-7
    active = np.flatnonzero(f >= 1e-28)
    for _ in range(max_iter):
        if active.size == 0:
            break
        xa = x[active]
        cols = []
        for k in range(2):  # central differences in the two angles
            dx = np.zeros(2)
            dx[k] = h
            ep_, _v1 = obj(active, xa + dx)
            em_, _v2 = obj(active, xa - dx)
            cols.append((ep_ - em_) / (2 * h))
        jac = np.stack(cols, axis=2)
        det = jac[:, 0, 0] * jac[:, 1, 1] - jac[:, 0, 1] * jac[:, 1, 0]
        ok = np.isfinite(det) & (np.abs(det) > 0)
        step = np.zeros_like(xa)
        ea = e[active]
        with np.errstate(divide="ignore", invalid="ignore"):
            step[:, 0] = -(jac[:, 1, 1] * ea[:, 0] - jac[:, 0, 1] * ea[:, 1]) / det
            step[:, 1] = -(-jac[:, 1, 0] * ea[:, 0] + jac[:, 0, 0] * ea[:, 1]) / det
        step[~ok | ~np.all(np.isfinite(step), axis=1)] = 0.0
        tt = np.ones(len(active))
        improved = np.zeros(len(active), dtype=bool)
        pending = np.arange(len(active))
        for _ls in range(30):  # step halving until the sum of squares decreases
            if pending.size == 0:
                break
            xt = project(xa[pending] + tt[pending, None] * step[pending], active[pending])
            et, ft = obj(active[pending], xt)
            better = ft < f[active[pending]]
            good = pending[better]
            x[active[good]] = xt[better]
            e[active[good]] = et[better]
            f[active[good]] = ft[better]
            improved[good] = True
            pending = pending[~better]
            tt[pending] *= 0.5
        iters[active] += 1
        active = active[improved & (f[active] >= 1e-28)]
    return x[:, 0], x[:, 1], f, iters


def _grid_search(model, idx, w2, lo_i, hi_i, lo_e, hi_e, triangle_sum):
    """Best point of a 61 x 61 grid per case (vectorized, in chunks of cases to bound memory)."""
    u = np.linspace(0.0, 1.0, _GRID)
    gi, ge = np.meshgrid(u, u, indexing="ij")
    gi, ge = gi.ravel(), ge.ravel()
    best_i = np.empty(len(idx))
    best_e = np.empty(len(idx))
    chunk = max(1, 200_000 // gi.size)
    for s in range(0, len(idx), chunk):  # chunks of cases, each solved for its whole grid at once
        sl = slice(s, s + chunk)
        ai = lo_i[sl, None] + (hi_i[sl] - lo_i[sl])[:, None] * gi[None, :]
        ae = hi_e[sl, None] - (hi_e[sl] - lo_e[sl])[:, None] * ge[None, :]
        m = ai.shape[1]
        res = _angle_sequence(model, np.repeat(idx[sl], m), ai.ravel(), ae.ravel(), np.repeat(w2[sl], m))
        f = np.where(res.valid, res.radial**2 + res.ring**2, np.inf).reshape(ai.shape)
        if triangle_sum is not None:
            f = np.where(ai + ae <= triangle_sum[sl, None] + 1e-12, f, np.inf)
        k = np.argmin(f, axis=1)
        rows = np.arange(ai.shape[0])
        best_i[sl], best_e[sl] = ai[rows, k], ae[rows, k]
    return best_i, best_e


def _angle_iteration(model, idx, w_target, alpha_s):
    """The paper's method (spec 004 section 5.2) for cases with omega > 0; returns angles, f, iters, method."""
    w2 = w_target**2
    deg = np.pi / 180.0
    span = np.minimum.reduce([np.full_like(alpha_s, 45.0 * deg), alpha_s - 0.5 * deg, 89.5 * deg - alpha_s])
    lo_i, hi_i = alpha_s, alpha_s + span
    lo_e, hi_e = alpha_s - span, alpha_s
    ai, ae = _grid_search(model, idx, w2, lo_i, hi_i, lo_e, hi_e, 2.0 * alpha_s)
    ai, ae, f, iters = _refine_angles(model, idx, ai, ae, w2, lo_i, hi_i, lo_e, hi_e, line=2.0 * alpha_s)
    method = np.full(len(idx), "search-triangle", dtype=object)
    miss = np.flatnonzero(~(f < _ROOT_TOL))
    if miss.size:  # the triangle heuristic failed: search the whole quadrant (and say so)
        q_lo, q_hi = np.full(miss.size, 0.5 * deg), np.full(miss.size, 89.5 * deg)
        qi, qe = _grid_search(model, idx[miss], w2[miss], q_lo, q_hi, q_lo, q_hi, None)
        tiny, top = np.full(miss.size, 1e-9), np.full(miss.size, np.pi / 2 - 1e-9)
        qi, qe, qf, qit = _refine_angles(model, idx[miss], qi, qe, w2[miss], tiny, top, tiny, top)
        ai[miss], ae[miss], f[miss] = qi, qe, qf
        iters[miss] += qit
        method[miss] = "search-quadrant"
    return ai, ae, f, iters, method


