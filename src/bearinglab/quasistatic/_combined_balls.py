r"""The balls of the five-degree-of-freedom model of :mod:`bearinglab.quasistatic.combined` (private).

Split from that module (issue 20: no module over 1000 lines); every name here is private to the
combined-load model and re-imported there.

Geometry
--------
_azimuths        psi_j = phi0 + 2 pi j / Z (unchecked; :func:`~bearinglab.quasistatic.combined.ball_azimuths`)
_arms            rows d(axial, radial groove offset)/d(displacement) of every ball
_geometry        one bearing's checked data and what every evaluation needs (:class:`_Geometry`)

Hertz interpolants
------------------
_tables, _hertz_k  Chebyshev series of ln K and ln(a* b*) in cos(alpha), per bearing

Balls
-----
_rest_balls      ball reaction and 2 x 2 stiffness at rest (closed form)
_speed_balls     each ball's equilibrium at speed (spec 004 eqs. 5-6) and its Schur-complement stiffness
_ball_state, _ball_start, _solve2   their parts

References: those of :mod:`bearinglab.quasistatic.combined`.
"""

from __future__ import annotations

import functools
import math
from typing import NamedTuple

import numpy as np
from numpy.polynomial import chebyshev as _cheb

from .. import _bounds, geometry, hertz
from .._validate import as_float, check_integer, check_positive_finite
from ..errors import InputError
from .ball import RACEWAY_CONTROLS, _dynamics
from .contact import contact_stiffness

# the constants of the ball-level iteration (combined.py re-exports them for its solver and the benches)
_N_CHEB = 16  # Chebyshev nodes in cos(alpha) of the Hertz interpolants (analytic on [0, 1]; ~1e-13)
_BALL_TOL = 1e-14  # ball Newton: |step| / D
_BALL_MAX_ITER = 40
_EPS = np.finfo(float).eps
#: Bearing types (see :data:`bearinglab.quasistatic.combined.BEARING_TYPES`).
BEARING_TYPES = ("radial", "angular")
#: Where the Hertz constants are evaluated (see :data:`bearinglab.quasistatic.combined.STIFFNESS_AT`).
STIFFNESS_AT = ("operating", "free")


# --------------------------------------------------------------------------- geometry
def _azimuths(z, phi0):
    """psi_j = phi0 + 2 pi j / Z for checked Z and phi0."""
    return phi0 + 2.0 * np.pi * np.arange(z) / z


def _arms(psi, arm):
    """Rows d(axial, radial offset)/d(displacement) of every ball, each (Z, 5)."""
    c, s = np.cos(psi), np.sin(psi)
    zero = np.zeros_like(psi)
    axial = np.stack([zero, zero, np.ones_like(psi), arm * s, -arm * c], axis=1)
    radial = np.stack([c, s, zero, zero, zero], axis=1)
    return axial, radial



# --------------------------------------------------------------------------- Hertz interpolants
@functools.lru_cache(maxsize=64)
def _tables(d, dm, fi, fo, ep, a0, stiffness_at):
    """Chebyshev coefficients in x = 2 cos(alpha) - 1 of ln K and ln(a* b*) of each race (read-only).

    The exact Hertz solution is iterative; it is evaluated once per bearing on _N_CHEB nodes, and kept for
    the next call with the same bearing. With ``stiffness_at="free"`` the series are constants (the values
    at alpha0).
    """
    return tuple(_read_only(c) for c in _chebyshev_tables(d, dm, fi, fo, ep, a0, stiffness_at))


def _read_only(a):
    a.setflags(write=False)
    return a


def _chebyshev_tables(d, dm, fi, fo, ep, a0, stiffness_at):
    def exact(c):
        alpha = np.arccos(np.clip(c, 0.0, 1.0))
        k = contact_stiffness(alpha, alpha, d, dm, fi, fo, ep)
        ab = []
        for race, f in (("inner", fi), ("outer", fo)):
            curv = geometry.raceway_curvature(d, dm, f, alpha, race=race)
            co = hertz.coefficients(curv.curvature_difference)
            ab.append(np.log(co.a_star * co.b_star))
        return np.log(k.inner), np.log(k.outer), ab[0], ab[1]

    if stiffness_at == "free":
        return [np.atleast_1d(np.asarray(v, dtype=float)) for v in exact(np.array([math.cos(a0)]))]
    x = np.cos(np.pi * (np.arange(_N_CHEB) + 0.5) / _N_CHEB)
    return [_cheb.chebfit(x, v, _N_CHEB - 1) for v in exact((x + 1.0) / 2.0)]


def _hertz_k(coef, c, slope=None):
    """K and d ln K / d cos(alpha) from a series (a constant series has zero slope); ``slope`` is the
    derivative series (:func:`numpy.polynomial.chebyshev.chebder`), precomputed per bearing."""
    x = 2.0 * c - 1.0
    if coef.size == 1:
        return np.full_like(c, math.exp(coef[0])), np.zeros_like(c)
    slope = _cheb.chebder(coef) if slope is None else slope
    return np.exp(_cheb.chebval(x, coef)), 2.0 * _cheb.chebval(x, slope)


# --------------------------------------------------------------------------- the bearing
class _Geometry(NamedTuple):
    z: int
    d: float
    dm: float
    fi: float
    fo: float
    a0: float
    ep: float
    mass: float  # ball mass [kg]
    inertia: float  # J = m D^2 / 10 [kg m^2]
    big_a: float  # A = B D
    gr0: float  # A cos(alpha0), radial offset of the groove centres in the concentric position
    ri: float  # (f_i - 0.5) D
    ro: float  # (f_o - 0.5) D
    psi: np.ndarray
    ja: np.ndarray  # (Z, 5) d axial offset / d u
    jr: np.ndarray  # (Z, 5) d radial offset / d u
    jj: np.ndarray  # (2, 2, Z, 25) outer products J_p J_q^T per ball
    tables: list | None  # ln K_i, ln K_o, ln(a*b*)_i, ln(a*b*)_o
    lam: tuple  # (lambda_i, lambda_o)
    control: str
    kind: str
    stiffness_at: str
    slopes: tuple = (None, None)  # chebder of tables[0], tables[1] (the ball Newton evaluates them often)


def _geometry(n_balls, d, dm, fi, fo, a0, ep, density, phi0, stiffness_at, control, kind, *, tables=True):
    """Check one bearing's data and precompute what every evaluation needs."""
    z = int(check_integer("n_balls", n_balls, 1, _bounds.MAX_BALLS))
    d = float(check_positive_finite("ball_diameter", d, "m"))
    dm = float(geometry.pitch_ratio(d, dm, 0.0) and dm)  # checks d_m > D
    big_a = float(geometry.total_curvature(fi, fo)) * d
    if not big_a < dm:  # the groove centres are a ring's width apart, not a bearing's size (f = 1e300)
        raise InputError(f"inner_conformity + outer_conformity - 1 must be < pitch_diameter / ball_diameter = "
                         f"{dm / d:g} [-] (the groove-centre distance A below d_m), got {big_a / d:g}")
    a0 = float(as_float("free_angle", a0))
    if not 0.0 <= a0 < math.pi / 2:
        raise InputError(f"free_angle must be in [0, 90) [deg], got {math.degrees(a0):g}")
    if stiffness_at not in STIFFNESS_AT:
        raise InputError(f"stiffness_at must be one of {list(STIFFNESS_AT)}, got {stiffness_at!r}")
    if control not in RACEWAY_CONTROLS:
        raise InputError(f"raceway_control must be one of {list(RACEWAY_CONTROLS)}, got {control!r}")
    if kind not in BEARING_TYPES:
        raise InputError(f"bearing_type must be one of {list(BEARING_TYPES)}, got {kind!r}")
    psi = _azimuths(z, float(as_float("first_ball_angle", phi0)))
    ja, jr = _arms(psi, dm / 2.0)
    rows = (ja, jr)
    jj = np.array([[np.einsum("zk,zl->zkl", p, q).reshape(z, 25) for q in rows] for p in rows])
    mass = inertia = ep_f = np.nan
    tab = None
    if tables:
        ep_f = float(check_positive_finite("reduced_modulus", ep, "Pa"))
        rho = float(check_positive_finite("density", density, "kg/m^3"))
        mass = rho * math.pi * d**3 / 6.0
        inertia = mass * d**2 / 10.0
        tab = _tables(d, dm, float(fi), float(fo), ep_f, a0, stiffness_at)
    return _Geometry(z, d, dm, float(fi), float(fo), a0, ep_f, mass, inertia, big_a, big_a * math.cos(a0),
                     (fi - 0.5) * d, (fo - 0.5) * d, psi, ja, jr, jj, tab, RACEWAY_CONTROLS[control], control,
                     kind, stiffness_at, tuple(_cheb.chebder(t) if t.size > 1 else None for t in tab[:2])
                     if tab is not None else (None, None))


# --------------------------------------------------------------------------- balls at rest
def _rest_balls(geo, ga, gr):
    """Ball reaction on the inner ring and its 2 x 2 stiffness per ball, at rest (no ball unknowns).

    Each ball is a spring between the groove-curvature centres: Q = K_n (rho - A)^1.5 along the line
    between them, K_n = (K_i^-2/3 + K_o^-2/3)^-3/2 at that line's angle (spec 004 section 5.3).
    """
    rho = np.hypot(ga, gr)
    s, c = ga / rho, gr / rho
    ki, dli = _hertz_k(geo.tables[0], c, geo.slopes[0])
    ko, dlo = _hertz_k(geo.tables[1], c, geo.slopes[1])
    wi, wo = ki ** (-2.0 / 3.0), ko ** (-2.0 / 3.0)
    kn = (wi + wo) ** -1.5
    dlkn = (wi * dli + wo * dlo) / (wi + wo)  # d ln K_n / d cos(alpha)
    defl = np.maximum(rho - geo.big_a, 0.0)
    q = kn * defl**1.5
    dq = 1.5 * kn * np.sqrt(defl)
    q_a = -q * s * dlkn  # dQ/d alpha
    # H = dQ n n^T + (Q_alpha / rho) n t^T + (Q / rho) t t^T, n = (s, c), t = (c, -s) in (axial, radial)
    h = np.empty(ga.shape + (2, 2))
    h[..., 0, 0] = dq * s * s + q_a / rho * s * c + q / rho * c * c
    h[..., 0, 1] = dq * s * c - q_a / rho * s * s - q / rho * c * s
    h[..., 1, 0] = dq * c * s + q_a / rho * c * c - q / rho * s * c
    h[..., 1, 1] = dq * c * c - q_a / rho * c * s + q / rho * s * s
    alpha = np.arctan2(ga, gr)
    return {"pa": q * s, "pr": q * c, "h": h, "qi": q, "qo": q, "ai": alpha, "ao": alpha,
            "ci": c, "co": c, "mg": np.zeros_like(q), "fc": np.zeros_like(q), "noise": dq * _EPS * rho}


# --------------------------------------------------------------------------- balls at speed
def _ball_state(geo, x, ga, gr, w2, deriv=True):
    """Ball residual (eqs. 5-6), ring reaction and their partials for ball centres x = (axial, radial).

    x is measured from the outer groove-curvature centre, (ga, gr) is the inner one. Returns a dict with
    the residual ``b`` (..., 2) [N], the reaction on the inner ring (``pa``, ``pr``) and, if ``deriv``,
    the partials ``b_x``, ``b_g``, ``p_x``, ``p_g`` (..., 2, 2).
    """
    ea, er = x[..., 0], x[..., 1]
    ia, ir = ga - ea, gr - er
    rho_o, rho_i = np.hypot(ea, er), np.hypot(ia, ir)
    so, co = ea / rho_o, er / rho_o
    si, ci = ia / rho_i, ir / rho_i
    di, do = rho_i - geo.ri, rho_o - geo.ro
    ki, dli = _hertz_k(geo.tables[0], ci, geo.slopes[0])
    ko, dlo = _hertz_k(geo.tables[1], co, geo.slopes[1])
    dip, dop = np.maximum(di, 0.0), np.maximum(do, 0.0)
    qi, qo = ki * dip**1.5, ko * dop**1.5
    lam_i, lam_o = geo.lam
    lam_i = lam_i * (di > 0)  # friction at the inner contact needs contact
    dyn = _dynamics(si, ci, so, co, geo.d / geo.dm, geo.control, geo.inertia, geo.mass, geo.dm)
    fc, fc_i, fc_o, mg, mg_i, mg_o = (w2 * v for v in dyn)
    m = mg / geo.d
    ni, no, ti, to = (si, ci), (so, co), (ci, -si), (co, -so)
    v = [lam_i * ti[k] - lam_o * to[k] for k in range(2)]
    b = np.stack([qi * ni[k] - qo * no[k] + m * v[k] + (fc if k else 0.0) for k in range(2)], axis=-1)
    pa = qi * si + m * lam_i * ci  # reaction of the ball on the inner ring is -(pa, pr)
    pr = qi * ci - m * lam_i * si
    out = {"b": b, "pa": pa, "pr": pr, "qi": qi, "qo": qo, "ai": np.arctan2(ia, ir), "ao": np.arctan2(ea, er),
           "ci": ci, "co": co, "mg": mg, "fc": fc, "di": di, "do": do,
           "noise": 1.5 * ki * np.sqrt(dip) * _EPS * rho_i}
    if not deriv:
        return out
    qi_a, qo_a = -qi * si * dli, -qo * so * dlo
    qi_d, qo_d = 1.5 * ki * np.sqrt(dip), 1.5 * ko * np.sqrt(dop)
    mi, mo = mg_i / geo.d, mg_o / geo.d
    # partials in (alpha_i, alpha_o, delta_i, delta_o), component k = axial, radial
    b_p = [[qi_a * ni[k] + qi * ti[k] + mi * v[k] - m * lam_i * ni[k] + (fc_i if k else 0.0),
            -qo_a * no[k] - qo * to[k] + mo * v[k] + m * lam_o * no[k] + (fc_o if k else 0.0),
            qi_d * ni[k], -qo_d * no[k]] for k in range(2)]
    # chain rule: d(alpha_i, alpha_o, delta_i, delta_o) / d x and / d g
    dx = [[-ti[j] / rho_i for j in range(2)], [to[j] / rho_o for j in range(2)], [-ni[j] for j in range(2)],
          [no[j] for j in range(2)]]

    def chain(parts, dvar):
        return np.stack([np.stack([sum(parts[k][v] * dvar[v][j] for v in range(4)) for j in range(2)], axis=-1)
                         for k in range(2)], axis=-2)

    out["b_x"] = chain(b_p, dx)
    if deriv == "x":  # the ball Newton needs no more
        return out
    p_p = [[qi_a * ni[k] + qi * ti[k] + lam_i * (mi * ti[k] - m * ni[k]), lam_i * mo * ti[k], qi_d * ni[k], 0.0]
           for k in range(2)]
    dg = [[ti[j] / rho_i for j in range(2)], [0.0, 0.0], [ni[j] for j in range(2)], [0.0, 0.0]]
    out.update(b_g=chain(b_p, dg), p_x=chain(p_p, dx), p_g=chain(p_p, dg))
    return out


def _solve2(a, b):
    """Solve the 2 x 2 systems a x = b, stacked over the leading axes (b (..., 2) or (..., 2, k))."""
    det = a[..., 0, 0] * a[..., 1, 1] - a[..., 0, 1] * a[..., 1, 0]
    inv = np.stack([np.stack([a[..., 1, 1], -a[..., 0, 1]], -1), np.stack([-a[..., 1, 0], a[..., 0, 0]], -1)], -2)
    inv = inv / det[..., None, None]
    if b.ndim == a.ndim - 1:
        return np.einsum("...ij,...j->...i", inv, b)
    return inv @ b


def _ball_start(geo, ga, gr, w2):
    """A ball position to start from: on the line between the groove centres, pressed out by F_c."""
    rho = np.hypot(ga, gr)
    n = np.stack([ga / rho, gr / rho], axis=-1)
    ki = _hertz_k(geo.tables[0], n[..., 1])[0]
    ko = _hertz_k(geo.tables[1], n[..., 1])[0]
    wi, wo = ki ** (-2.0 / 3.0), ko ** (-2.0 / 3.0)
    total = rho - geo.big_a
    fc = w2 * geo.mass * geo.dm / 2.0 * 0.25  # cage at about half the shaft speed
    do = np.maximum(total * wo / (wi + wo), (fc / ko) ** (2.0 / 3.0))
    return n * (geo.ro + do)[..., None]


def _speed_balls(geo, ga, gr, w2, x0):
    """Solve every ball's equilibrium (eqs. 5-6) for its centre, then the ring reaction and its stiffness.

    Batched Newton on the 2 x 2 ball systems with step halving that keeps delta_o > 0; the ring stiffness
    per ball is the Schur complement H = p_g - p_x b_x^-1 b_g (implicit function theorem).
    Returns the ball dict (with ``x``, ``h`` and ``ok``). A trial ring position can put a ball where its
    kinematics are singular (inf or NaN): such a ball is not ``ok``, and the ring line search rejects it.
    """
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        return _speed_balls_newton(geo, ga, gr, w2, x0)


def _speed_balls_newton(geo, ga, gr, w2, x0):
    # the balls still iterating, flattened: converged balls drop out of the work (each ball is independent)
    x = x0.reshape(-1, 2).copy()
    gaf, grf, w2f = ga.ravel(), gr.ravel(), np.broadcast_to(w2, ga.shape).ravel()
    act = np.arange(gaf.size)
    for _ in range(_BALL_MAX_ITER):
        xa = x[act]
        st = _ball_state(geo, xa, gaf[act], grf[act], w2f[act], deriv="x")
        step = -_solve2(st["b_x"], st["b"])
        step[~np.all(np.isfinite(step), axis=-1)] = 0.0
        t = np.ones(act.size)
        for _h in range(20):  # keep the ball on the outer raceway
            trial = xa + t[:, None] * step
            lost = np.hypot(trial[:, 0], trial[:, 1]) <= geo.ro
            if not lost.any():
                break
            t = np.where(lost, 0.5 * t, t)
        x[act] = xa + t[:, None] * step
        act = act[np.max(np.abs(step), axis=-1) > _BALL_TOL * geo.d]
        if act.size == 0:
            break
    active = np.zeros(gaf.size, dtype=bool)
    active[act] = True
    active, x = active.reshape(ga.shape), x.reshape(ga.shape + (2,))
    st = _ball_state(geo, x, ga, gr, w2)
    dxdg = -_solve2(st["b_x"], st["b_g"])  # d x / d g of every ball (implicit function theorem)
    h = st["p_g"] + st["p_x"] @ dxdg
    fs = np.maximum(np.maximum(st["qo"], st["qi"]), 1e-300)
    st.update(x=x, h=h, dxdg=dxdg, ok=~active & np.all(np.abs(st["b"]) <= 1e-9 * fs[..., None], axis=-1))
    return st


