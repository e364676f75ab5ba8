r"""The 5-DOF model at speed: ring and balls solved together by one block Newton (private).

Split from :mod:`bearinglab.quasistatic.combined` (issue 31): at speed every ball has two unknowns, its
centre x_j = (axial, radial) in its own plane, besides the five of the ring. The former solver nested a
Newton on every ball inside each evaluation of the ring Newton (15 ring iterations and some 60 ball
evaluations a case on the 218 map). Here one Newton iteration updates the ring and the balls together:

- the ball equations b_j(x_j, g_j) = 0 (spec 004 eqs. 5-6) and the ring equation F - sum_j J_j^T p_j = 0
  are linearised at once; eliminating each ball by its 2 x 2 block (the Schur complement per ball, M_j =
  (db_j/dx_j)^-1) leaves the 5 x 5 ring system K du = F - R*, K = sum_j J_j^T (p_g - p_x M b_g)_j J_j the
  tangent stiffness and R* the reaction once every ball has taken its own Newton step
  (:func:`~bearinglab.quasistatic._combined_balls._schur`); then dx_j = -M_j (b_j + b_g J_j du);
- the same Levenberg-Marquardt damping, trust region (no groove centre and no ball centre moves by more
  than A/2 in a step), line search (8 cuts by 4, Armijo on the residual of ring and balls) and iteration
  limits as the ring Newton at rest;
- converged when the ring residual meets the tolerance of the rest solve (1e-12 relative, or the
  rounding floor) and every ball's residual is below the same tolerance relative to its contact load (or
  its own rounding floor): the stopping rule of the nested solver, which solved each ball to 1e-14 D;
- started from the rest solution with every ball in its equilibrium at speed there (the balls alone,
  by their 2 x 2 Newton at fixed rings: a ball's position across its contact line is soft, and a joint
  step from balls far from equilibrium moves them by a good part of A); the first step is then the
  predictor in omega^2 from the rest solution, the ring's Newton step on the change of the ball
  reactions that the speed brings; a case that does not converge at once is solved again by
  continuation in omega^2 (4, then 16 equal steps), as before.

Functions
---------
solve_speed     every moving case from its rest solution: u, converged, iterations, last evaluation

References: those of :mod:`bearinglab.quasistatic.combined`; the elimination is the Schur complement
of a block-arrow Jacobian (J. Nocedal and S. J. Wright, *Numerical Optimization*, 2nd ed., Springer,
2006, section 16.2, doi:10.1007/978-0-387-40065-5).
"""

from __future__ import annotations

import numpy as np

from . import _ring, _types
from ._combined_balls import _ball_state, _schur, _speed_balls

__all__ = ["solve_speed"]

_LINE_SEARCH = 8  # step cuts (by 4), as the ring Newton at rest
_CONTINUATION = (1, 4, 16)  # equal steps in omega^2 tried for a case that fails at the full speed


def _measure(geo, loads, w2, u, xa, xr, free, tol, noise_factor, resolvable):
    """Ring and balls at (u, x): the Schur parts, the stiffness, the ball outputs and the measures of
    convergence (``merit`` the norm of the ring residual and every ball residual, ``rel`` the relative
    ring residual, ``floor`` its rounding floor, ``conv`` converged, ``valid`` every ball on its outer
    raceway and finite)."""
    ga, gr = _types.offsets(geo, u)
    st = _ball_state(geo, xa, xr, ga, gr, w2[:, None])
    dxb, dxdg, h, relaxed = _schur(st)
    force = _types.reaction(geo, st["pa"], st["pr"])
    scale_v = np.array([1.0, 1.0, 1.0, 2.0 / geo.dm, 2.0 / geo.dm])
    diff = loads - force if free is None else (loads - force) * free
    ring = np.sqrt(np.add.reduce((diff * scale_v) ** 2, axis=-1))
    bsq = st["b0"] ** 2 + st["b1"] ** 2
    merit = np.sqrt(ring * ring + _ring.ballsum(bsq))
    total = _ring.ballsum(np.hypot(st["pa"], st["pr"]))
    scale = np.maximum(np.sqrt(np.add.reduce((loads * scale_v) ** 2, axis=-1)), total)
    with np.errstate(invalid="ignore", divide="ignore"):
        rel = np.where(scale > 0, ring / scale, ring)
        floor = np.minimum(np.where(scale > 0, noise_factor * _ring.ballsum(st["noise"]) / scale, 0.0), resolvable)
    fs = np.maximum(st["qi"], st["qo"])
    balls_ok = np.all(np.sqrt(bsq) <= np.maximum(tol * fs, noise_factor * st["noise_b"]), axis=-1)
    valid = np.all(st["do"] > 0, axis=-1) & np.isfinite(merit)
    return {"dxb0": dxb[0], "dxb1": dxb[1], "dxdg0": dxdg[0], "dxdg1": dxdg[1], "dxdg2": dxdg[2],
            "dxdg3": dxdg[3], "stiffness": _types.assemble(geo, *h), "relaxed": _types.reaction(geo, *relaxed),
            "force": force, "merit": merit, "rel": rel, "floor": floor,
            "conv": (rel <= np.maximum(tol, floor)) & balls_ok & valid, "valid": valid, "xa": xa, "xr": xr,
            "ga": ga, "gr": gr, "qi": st["qi"], "qo": st["qo"], "mg": st["mg"], "fc": st["fc"]}


def _newton(geo, loads, w2, u0, x0, tol, max_iter, free, lam_max, noise_factor, resolvable):
    """Block Newton on ring and balls, all cases together, each with its own damping and line search.

    Returns u, converged, iterations and the last accepted evaluation of every case (the dict of
    :func:`_measure`), which is the evaluation at the returned u.
    """
    n = len(loads)
    u = u0.copy()
    it = np.zeros(n, dtype=int)
    lam = np.zeros(n)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        cur = _measure(geo, loads, w2, u, np.array(x0[0], dtype=float), np.array(x0[1], dtype=float), free, tol,
                       noise_factor, resolvable)
        for _ in range(max_iter):
            act = np.flatnonzero(~cur["conv"] & (it < max_iter) & (lam <= lam_max) & cur["valid"])
            if act.size == 0:
                break
            it[act] += 1
            du, dxa, dxr, t = _step(geo, loads[act], {k: cur[k][act] for k in _STEP}, lam[act],
                                    None if free is None else free[act])
            full = t == 1.0
            pending = np.arange(act.size)
            for _ls in range(_LINE_SEARCH):
                sel = act[pending]
                tt = t[pending]
                trial_u = u[sel] + tt[:, None] * du[pending]
                trial = _measure(geo, loads[sel], w2[sel], trial_u, cur["xa"][sel] + tt[:, None] * dxa[pending],
                                 cur["xr"][sel] + tt[:, None] * dxr[pending], None if free is None else free[sel],
                                 tol, noise_factor, resolvable)
                good = trial["valid"] & ((trial["merit"] < cur["merit"][sel] * (1.0 - 1e-4 * tt)) | trial["conv"])
                g = sel[good]
                u[g] = trial_u[good]
                for key, val in cur.items():
                    val[g] = trial[key][good]
                pending = pending[~good]
                if pending.size == 0:
                    break
                t[pending] *= 0.25
                full[pending] = False
            _ring.damp(lam, act, full, pending)
    return u, cur["conv"].copy(), it, cur


_STEP = ("stiffness", "relaxed", "dxb0", "dxb1", "dxdg0", "dxdg1", "dxdg2", "dxdg3")


def _step(geo, loads, cur, lam, free):
    """The damped block-Newton step of the cases of ``cur``: du, dx (axial, radial) and the trust-region
    fraction t (no groove centre and no ball centre moves by more than A/2)."""
    rhs = loads - cur["relaxed"]
    if free is None:
        du = _ring.lm_step(cur["stiffness"], rhs, lam, geo.dm)
    else:
        du = _ring.lm_step(_ring.hold(cur["stiffness"], free), rhs * free, lam, geo.dm)
    c, s, arm = geo.cos_psi, geo.sin_psi, geo.dm / 2.0
    if geo.elements is None:
        dga = du[:, 2:3] + arm * (du[:, 3:4] * s - du[:, 4:5] * c)
        dgr = du[:, 0:1] * c + du[:, 1:2] * s
    else:  # the other types' elements (rows at their axial positions)
        dga, dgr = _types.steps(geo, du)
    dxa = cur["dxb0"] + (cur["dxdg0"] * dga + cur["dxdg1"] * dgr)
    dxr = cur["dxb1"] + (cur["dxdg2"] * dga + cur["dxdg3"] * dgr)
    move = np.maximum(np.abs(du[:, 2]) + arm * np.hypot(du[:, 3], du[:, 4]), np.hypot(du[:, 0], du[:, 1]))
    move = np.maximum(move, np.max(np.hypot(dxa, dxr), axis=-1))
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.minimum(1.0, 0.5 * geo.trust / move)
    t = np.where(np.isfinite(t), t, 0.0)
    return du, dxa, dxr, t


def solve_speed(geo, loads, w2, u_rest, tol, max_iter, free, lam_max, noise_factor, resolvable):
    """Every case at its speed from its rest solution ``u_rest``: direct, then by continuation in omega^2.

    Returns u (n, 5), converged (n,), iterations (n,) and the last evaluation of each converged case (the
    outputs: ``qi``, ``qo``, ``ai``, ``ao``, ``mg``, ``fc`` (n, Z), ``residual``, ``floor`` (n,),
    ``stiffness`` (n, 5, 5), ``force`` (n, 5)).
    """
    n, z = len(loads), geo.z
    u = np.full((n, 5), np.nan)
    ok = np.zeros(n, dtype=bool)
    it = np.zeros(n, dtype=int)
    final = {k: np.full((n, z), np.nan) for k in ("qi", "qo", "ai", "ao", "mg", "fc")}
    final.update(residual=np.full(n, np.nan), floor=np.zeros(n), stiffness=np.full((n, 5, 5), np.nan),
                 force=np.full((n, 5), np.nan))
    pending = np.arange(n)
    for steps in _CONTINUATION:
        sel = pending
        us = u_rest[sel].copy()
        x, good, last = None, np.ones(sel.size, dtype=bool), None
        for k in range(1, steps + 1):
            wk = w2[sel] * k / steps
            if x is None:  # the balls in equilibrium at the rest position of the rings
                ga, gr = _types.offsets(geo, us)
                x = _speed_balls(geo, ga, gr, wk[:, None])["x"]
            us, conv, itk, last = _newton(geo, loads[sel], wk, us, x, tol, max_iter,
                                          None if free is None else free[sel], lam_max, noise_factor, resolvable)
            x = (last["xa"], last["xr"])
            it[sel] += itk
            good &= conv
        done = sel[good]
        u[done], ok[done] = us[good], True
        for key in ("qi", "qo", "mg", "fc", "stiffness", "force"):
            final[key][done] = last[key][good]
        xa, xr, ga, gr = (last[k][good] for k in ("xa", "xr", "ga", "gr"))
        final["ai"][done], final["ao"][done] = np.arctan2(ga - xa, gr - xr), np.arctan2(xa, xr)
        final["residual"][done], final["floor"][done] = last["rel"][good], last["floor"][good]
        pending = sel[~good]
        if pending.size == 0:
            break
    return u, ok, it, final
