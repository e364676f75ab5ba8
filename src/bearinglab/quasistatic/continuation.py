r"""Batched Newton-Raphson with per-case continuation in speed: the solver of spec 004 section 5.1.

All cases of a batch are updated together; each case has its own current speed, continuation step and
line-search fraction. The state of the iteration is one ``_Continuation`` value (one row per case).
Started from the static solution at the same thrust (section 5.3), so the result at zero speed is the
static one.

Nothing here is public: :func:`bearinglab.quasistatic.contact_angles` calls ``_newton``.
``_static_start`` and ``_unknowns_from`` (the start point) are also used by bench/high_speed.py.

References
----------
.. [1] Zhao Chunjiang, Cui Guohua, Wang Guoqiang, Huang Qingxue and Zhang Fangping, "Precise definition
   of the contact-angle field of a high-speed angular-contact ball bearing under axial load,"
   Transactions of the CSAM, vol. 39, no. 12, pp. 154-156, 209, 2008 (spec 004 of this project).
.. [2] E. L. Allgower and K. Georg, *Introduction to Numerical Continuation Methods*, SIAM, 2003,
   ch. 2 (predictor-corrector continuation), doi:10.1137/1.9780898719154.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from .. import _solve
from ..stand import static
from .equations import _NOCONV, _OK, _equations

__all__: list[str] = []


def _static_start(model, idx):
    """Static solution (spec 004 section 5.3) at the loads of ``idx``, computed once per distinct case."""
    keys = np.stack([model.fa[idx], model.z[idx], model.d[idx], model.dm[idx], model.fi[idx], model.fo[idx],
                     model.a0[idx], model.ep[idx]], axis=1)
    if keys.size and np.all(keys[:, 1:] == keys[:1, 1:]):  # one bearing: distinct loads only
        loads, inv = np.unique(keys[:, 0], return_inverse=True)
        uniq = np.column_stack([loads, np.broadcast_to(keys[:1, 1:], (len(loads), 7))])
    else:
        uniq, inv = np.unique(keys, axis=0, return_inverse=True)
    s = static.contact_angle_under_thrust(uniq[:, 0], uniq[:, 1], uniq[:, 2], uniq[:, 3], uniq[:, 4], uniq[:, 5],
                                          uniq[:, 6], uniq[:, 7], stiffness_at="operating")
    inv = inv.ravel()
    return (np.atleast_1d(s.contact_angle)[inv], np.atleast_1d(s.deflection_inner)[inv],
            np.atleast_1d(s.deflection_outer)[inv], np.atleast_1d(s.axial_displacement)[inv])


def _unknowns_from(model, idx, ae, di, de, da):
    """The unknowns (X1, X2, delta_i, delta_e, delta_a) / D from the outer angle and the displacements."""
    d = model.d[idx]
    le_len = (model.fo[idx] - 0.5) * d + de
    return np.stack([le_len * np.sin(ae), le_len * np.cos(ae), di, de, da], axis=1) / d[:, None]


@dataclasses.dataclass
class _Continuation:
    """State of the batched continuation, one row per case (arrays are updated in place)."""

    v: np.ndarray  # current iterate (n, 5)
    v_ok: np.ndarray  # last converged point of the continuation
    w_ok: np.ndarray  # its speed [rad/s]
    w_cur: np.ndarray  # speed of the current continuation step [rad/s]
    w_target: np.ndarray  # target speed [rad/s]
    h: np.ndarray  # current continuation step in speed [rad/s]
    h_max: float  # largest step (``speed_step``, inf if None) [rad/s]
    h_min: np.ndarray  # step below which a case gives up [rad/s]
    tangent: np.ndarray  # dv/d(omega^2) at the last converged point (n, 5)
    v_base: np.ndarray  # iterate before the current Newton step (line search)
    step: np.ndarray  # the current Newton step (n, 5)
    t: np.ndarray  # line-search fraction of the step
    norm_prev: np.ndarray  # residual norm at v_base
    k_stage: np.ndarray  # Newton iterations in the current continuation step
    iters: np.ndarray  # Newton iterations over all steps
    max_iter: int  # limit of ``iters``
    status: np.ndarray  # -1 running, else a status code
    last_bad: np.ndarray  # code of the last invalid state met
    norm_out: np.ndarray  # residual norm at convergence

    @classmethod
    def start(cls, v0, w_target, speed_step, max_iter):
        """All cases at the static start (speed 0), first step to the target speed or ``speed_step``."""
        n = len(v0)
        h_max = np.inf if speed_step is None else speed_step
        return cls(v=v0.copy(), v_ok=v0.copy(), w_ok=np.zeros(n), w_cur=np.zeros(n), w_target=w_target,
                   h=np.minimum(w_target, h_max), h_max=h_max, h_min=np.maximum(w_target * 1e-6, 1e-3),
                   tangent=np.zeros((n, 5)), v_base=v0.copy(), step=np.zeros((n, 5)), t=np.ones(n),
                   norm_prev=np.full(n, np.inf), k_stage=np.zeros(n, dtype=int), iters=np.zeros(n, dtype=int),
                   max_iter=max_iter, status=np.full(n, -1), last_bad=np.full(n, _NOCONV),
                   norm_out=np.full(n, np.nan))

    def advance(self, a):
        """Start the next continuation step of cases ``a`` from their last converged point (tangent predictor).

        The predictor is linear in omega^2, except for X1 = L_e sin(alpha_e) > 0, which is extrapolated
        multiplicatively (the same to first order): at low thrust and high speed alpha_e falls like
        1/omega^2 and a linear predictor would overshoot to alpha_e < 0 and force tiny steps.
        """
        w_new = np.minimum(self.w_ok[a] + self.h[a], self.w_target[a])
        self.w_cur[a] = w_new
        inc = (w_new**2 - self.w_ok[a] ** 2)[:, None] * self.tangent[a]
        pred = self.v_ok[a] + inc
        x1 = self.v_ok[a, 0]
        with np.errstate(over="ignore", divide="ignore", invalid="ignore"):
            pred[:, 0] = np.where(x1 > 0, x1 * np.exp(np.minimum(inc[:, 0] / x1, 50.0)), pred[:, 0])
        self.v[a] = pred
        self.k_stage[a] = 0
        self.norm_prev[a] = np.inf
        self.t[a] = 1.0

    def cut(self, a):
        """A continuation step failed: retry with a quarter of the speed step, or give up.

        Out of iterations the reason is "no_convergence"; out of speed step it is the last invalid state
        met (the ball leaving a raceway, an angle leaving (0, 90 deg)) if any.
        """
        if a.size == 0:
            return
        self.h[a] = 0.25 * (self.w_cur[a] - self.w_ok[a])
        exhausted = self.iters[a] >= self.max_iter
        stalled = ~exhausted & (self.h[a] < self.h_min[a])
        self.status[a[exhausted]] = _NOCONV
        self.status[a[stalled]] = self.last_bad[a[stalled]]
        go = a[~(exhausted | stalled)]
        if go.size:
            self.advance(go)

    def converged(self, act, conv, norm, jac, r_w2):
        """Cases ``act[conv]`` converged at their current speed: finish them, or take the next step."""
        a = act[conv]
        self.norm_out[a] = norm[conv]
        final = self.w_cur[a] >= self.w_target[a]
        self.status[a[final]] = _OK
        go = a[~final]
        if go.size:
            sel = conv.copy()
            sel[conv] = ~final
            self.tangent[go] = np.linalg.solve(jac[sel], -r_w2[sel][:, :, None])[:, :, 0]  # dv/d(omega^2)
            self.v_ok[go] = self.v[go]
            self.w_ok[go] = self.w_cur[go]
            easy = (self.k_stage[go] <= 4) & (self.w_cur[go] > 0)
            self.h[go] = np.minimum(np.where(easy, 2.0 * self.h[go], self.h[go]), self.h_max)  # grow after an easy step
            self.advance(go)

    def newton_step(self, act, accept, norm, r, jac):
        """Cases ``act[accept]`` have an accepted iterate: take the next Newton step (or cut the speed step)."""
        a = act[accept]
        too_many = (self.k_stage[a] >= _solve.QUASISTATIC_STAGE_MAX_ITER) | (self.iters[a] >= self.max_iter)
        ok = a[~too_many]
        if ok.size:
            sel = accept.copy()
            sel[accept] = ~too_many
            try:
                dv = np.linalg.solve(jac[sel], -r[sel][:, :, None])[:, :, 0]
            except np.linalg.LinAlgError:  # a singular Jacobian in the batch: solve one by one
                dv = _robust_solve(jac[sel], -r[sel])
            bad_step = ~np.all(np.isfinite(dv), axis=1)
            good = ok[~bad_step]
            self.v_base[good] = self.v[good]
            self.step[good] = dv[~bad_step]
            self.norm_prev[good] = norm[sel][~bad_step]
            self.t[good] = 1.0
            self.v[good] = self.v[good] + dv[~bad_step]
            self.k_stage[good] += 1
            self.iters[good] += 1
            self.cut(ok[bad_step])
        self.cut(a[too_many])

    def halve(self, a):
        """The iterate of cases ``a`` was rejected: halve their Newton step, or cut the speed step."""
        self.t[a] *= 0.5
        small = self.t[a] < 1.0 / 1024.0
        ls = a[~small]
        self.v[ls] = self.v_base[ls] + self.t[ls, None] * self.step[ls]
        self.cut(a[small])


def _robust_solve(a, b):
    out = np.full(b.shape, np.nan)
    for k in range(len(a)):  # only reached when a batch contains a singular Jacobian
        try:
            out[k] = np.linalg.solve(a[k], b[k])
        except np.linalg.LinAlgError:
            pass
    return out


def _newton(model, idx, w_target, v0, *, tol, max_iter, speed_step):
    """Batched Newton-Raphson with per-case continuation in speed and step control (spec 004 section 5.1).

    Returns the unknowns, the status codes, the Newton iterations, the residual norm at convergence and
    the last converged speed of each case.
    """
    s = _Continuation.start(v0, w_target, speed_step, max_iter)
    for _ in range(_solve.QUASISTATIC_MAX_LOOPS):
        act = np.flatnonzero(s.status < 0)
        if act.size == 0:
            break
        r, jac, code, ex = _equations(model, idx[act], s.v[act], s.w_cur[act] ** 2, True)
        norm = np.sqrt(np.einsum("ij,ij->i", r, r))
        valid = (code == _OK) & np.isfinite(norm)
        s.last_bad[act[~valid]] = code[~valid]
        conv = valid & (norm < tol)
        # an iterate is accepted when it is valid and decreases the residual (Armijo on the norm)
        accept = valid & ~conv & (norm <= s.norm_prev[act] * (1.0 - 1e-4 * s.t[act]))
        retry = ~conv & ~accept & (s.k_stage[act] > 0)  # step halving from the previous iterate
        fresh_bad = ~conv & ~accept & (s.k_stage[act] == 0)  # a predictor that is not usable
        if conv.any():
            s.converged(act, conv, norm, jac, ex["r_w2"])
        if accept.any():
            s.newton_step(act, accept, norm, r, jac)
        if retry.any():
            s.halve(act[retry])
        if fresh_bad.any():
            s.cut(act[fresh_bad])
    else:
        s.status[s.status < 0] = _NOCONV
    return s.v, s.status, s.iters, s.norm_out, s.w_ok
