r"""The balls of the five-degree-of-freedom model of :mod:`bearinglab.quasistatic.combined` (private).

Split from that module (issue 20: no module over 1000 lines); every name here is private to the
combined-load model and re-imported there.

Geometry
--------
_arms            rows d(axial, radial groove offset)/d(displacement) of every ball
_geometry        one bearing's checked data and what every evaluation needs (:class:`_Geometry`)

Hertz interpolants
------------------
_tables, _hertz_k  Chebyshev series of ln K and ln(a* b*) in cos(alpha), per bearing
_series, _log_k    ln K of both contacts and its derivative, as the solvers evaluate them

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
from . import _ring
from .ball import RACEWAY_CONTROLS, _dynamics
from .contact import contact_stiffness

# the constants of the ball-level iteration (combined.py re-exports them for its solver and the benches)
_N_CHEB = 16  # Chebyshev nodes in cos(alpha) of the Hertz interpolants (analytic on [0, 1]; ~1e-13)
_BALL_TOL = 1e-14  # ball Newton: |step| / D
_BALL_MAX_ITER = 40
_EPS = np.finfo(float).eps
#: Bearing types (see :data:`bearinglab.quasistatic.combined.BEARING_TYPES`): the single rows built here, and
#: the other types, whose elements :mod:`bearinglab.quasistatic._types` builds on them.
BEARING_TYPES = ("radial", "angular", "four-point", "double-row-angular", "double-row-radial", "self-aligning",
                 "thrust")
#: Where the Hertz constants are evaluated (see :data:`bearinglab.quasistatic.combined.STIFFNESS_AT`).
STIFFNESS_AT = ("operating", "free")


# --------------------------------------------------------------------------- geometry
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


def _series(tables):
    """(4, N) Chebyshev series in x = 2 cos(alpha) - 1 of ln K_i, d ln K_i / d cos(alpha), ln K_o and
    d ln K_o / d cos(alpha) (the derivative series padded with a zero to the same length; a constant
    series has a zero derivative), without the trailing coefficients at rounding level."""
    ki, ko = (np.asarray(t, dtype=float) for t in tables[:2])
    # the coefficients fall geometrically (ln K is analytic in cos alpha) to rounding by the 11th or 12th;
    # the ones below 8 eps of the largest are rounding of the fit and are left out (a quicker sum)
    size = 1 + max(int(np.flatnonzero(np.abs(t) > 8.0 * _EPS * np.max(np.abs(t)))[-1]) for t in (ki, ko))
    ki, ko = ki[:size], ko[:size]
    out = np.zeros((4, ki.size))
    out[0], out[2] = ki, ko
    if ki.size > 1:
        out[1, :-1], out[3, :-1] = 2.0 * _cheb.chebder(ki), 2.0 * _cheb.chebder(ko)
    return _read_only(out)


def _log_k(geo, c, race):
    """ln K and d ln K / d cos(alpha) of the inner (race 0) or outer (race 1) contact at cos(alpha) = c."""
    x = 2.0 * c - 1.0
    return _cheb.chebval(x, geo.series[2 * race]), _cheb.chebval(x, geo.series[2 * race + 1])


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
    a0: float  # free contact angle alpha0 (0 for a bearing without clearance or with a negative one)
    ep: float
    mass: float  # ball mass [kg]
    inertia: float  # J = m D^2 / 10 [kg m^2]
    big_a: float  # A = B D
    gr0: float  # A - e/2 (= A cos alpha0 for e > 0), radial offset of the groove centres in the concentric position
    ri: float  # (f_i - 0.5) D
    ro: float  # (f_o - 0.5) D
    psi: np.ndarray
    ja: np.ndarray  # (Z, 5) d axial offset / d u
    jr: np.ndarray  # (Z, 5) d radial offset / d u
    cos_psi: np.ndarray  # (Z,)
    sin_psi: np.ndarray  # (Z,)
    weights: tuple  # trigonometric weights of the sums over the balls (_ring.weights)
    tables: list | None  # ln K_i, ln K_o, ln(a*b*)_i, ln(a*b*)_o
    lam: tuple  # (lambda_i, lambda_o)
    control: str
    kind: str
    stiffness_at: str
    series: np.ndarray | None = None  # (4, N) ln K and its derivative of both contacts (_series)
    clearance: float = math.nan  # e, the diametral operating clearance [m] (negative: a preload)
    elements: object = None  # the other types' elements (bearinglab.quasistatic._types.Elements); None: one row

    @property
    def trust(self):
        """The ring Newton's step bound: no groove centre moves by more than half of it in a step. [m]"""
        return self.big_a if self.elements is None else self.elements.trust

    @property
    def interference(self):
        """-e/2 for e < 0: the radial compression of every ball in the concentric position (0 otherwise). [m]"""
        return max(-0.5 * self.clearance, 0.0)


#: A preload beyond this many ball diameters of radial interference per ball (-e/2 > D) is a unit mistake:
#: the rings would pass through the balls (as for a prescribed displacement, combined._check_held).
_MAX_INTERFERENCE = 1.0


def _free_angle_and_offset(big_a, d, a0, clearance):
    """alpha0, the radial groove-centre offset g0 and e from the free angle or the diametral clearance.

    With a clearance e: g0 = A - e/2, alpha0 = arccos(1 - e / (2 A)) for e > 0 and 0 for e <= 0 (every
    ball touches both raceways at alpha = 0, compressed by -e/2). Without it: g0 = A cos alpha0 (the
    definition of alpha0, Harris and Kotzalas ch. 2), e = 2 A (1 - cos alpha0).
    """
    if clearance is None:
        a0 = float(as_float("free_angle", a0))
        if not 0.0 <= a0 < math.pi / 2:
            raise InputError(f"free_angle must be in [0, 90) [deg], got {math.degrees(a0):g}")
        return a0, big_a * math.cos(a0), 2.0 * big_a * (1.0 - math.cos(a0))
    e = float(as_float("radial_clearance", clearance))
    if not (math.isfinite(e) and -2.0 * _MAX_INTERFERENCE * d <= e < 2.0 * big_a):
        raise InputError(f"radial_clearance must be in [{-2.0 * _MAX_INTERFERENCE * d * 1e3:.6g}, "
                         f"{2.0 * big_a * 1e3:.6g}) [mm] (from an interference of one ball diameter per ball to "
                         f"a free contact angle of 90 deg), got {e * 1e3:.6g} mm")
    angle = math.acos(1.0 - e / (2.0 * big_a)) if e > 0 else 0.0
    if a0 is not None:
        given = float(as_float("free_angle", a0))
        if abs(given - angle) > 1e-9:
            raise InputError(f"free_angle ({math.degrees(given):.6g} deg) and radial_clearance ({e * 1e6:.6g} um) "
                             f"disagree: the clearance gives {math.degrees(angle):.6g} deg; give one of them")
    return angle, big_a - 0.5 * e, e


def _geometry(n_balls, d, dm, fi, fo, a0, ep, density, phi0, stiffness_at, control, kind, *, tables=True,
              clearance=None):
    """Check one bearing's data and precompute what every evaluation needs.

    ``clearance``: the diametral operating clearance e [m] instead of the free angle ``a0`` (which may then be
    None); e <= 0 is a preloaded bearing.
    """
    z = int(check_integer("n_balls", n_balls, 1, _bounds.MAX_BALLS))
    d = float(check_positive_finite("ball_diameter", d, "m"))
    dm = float(geometry.pitch_ratio(d, dm, 0.0) and dm)  # checks d_m > D
    big_a = float(geometry.total_curvature(fi, fo)) * d
    if not big_a < dm:  # the groove centres are a ring's width apart, not a bearing's size (f = 1e300)
        raise InputError(f"inner_conformity + outer_conformity - 1 must be < pitch_diameter / ball_diameter = "
                         f"{dm / d:g} [-] (the groove-centre distance A below d_m), got {big_a / d:g}")
    a0, gr0, e = _free_angle_and_offset(big_a, d, a0, clearance)
    if stiffness_at not in STIFFNESS_AT:
        raise InputError(f"stiffness_at must be one of {list(STIFFNESS_AT)}, got {stiffness_at!r}")
    if control not in RACEWAY_CONTROLS:
        raise InputError(f"raceway_control must be one of {list(RACEWAY_CONTROLS)}, got {control!r}")
    if kind not in BEARING_TYPES:
        raise InputError(f"bearing_type must be one of {list(BEARING_TYPES)}, got {kind!r}")
    psi = _ring.azimuths(z, float(as_float("first_ball_angle", phi0)))
    ja, jr = _arms(psi, dm / 2.0)
    mass = inertia = ep_f = np.nan
    tab = None
    if tables:
        ep_f = float(check_positive_finite("reduced_modulus", ep, "Pa"))
        rho = float(check_positive_finite("density", density, "kg/m^3"))
        mass = rho * math.pi * d**3 / 6.0
        inertia = mass * d**2 / 10.0
        tab = _tables(d, dm, float(fi), float(fo), ep_f, a0, stiffness_at)
    return _Geometry(z, d, dm, float(fi), float(fo), a0, ep_f, mass, inertia, big_a, gr0,
                     (fi - 0.5) * d, (fo - 0.5) * d, psi, ja, jr, np.cos(psi), np.sin(psi), _ring.weights(psi), tab,
                     RACEWAY_CONTROLS[control], control, kind, stiffness_at, None if tab is None else _series(tab), e)


# --------------------------------------------------------------------------- balls at rest
def _rest_balls(geo, ga, gr):
    """Ball reaction on the inner ring and its 2 x 2 stiffness per ball, at rest (no ball unknowns).

    Each ball is a spring between the groove-curvature centres: Q = K_n (rho - A)^1.5 along the line
    between them, K_n = (K_i^-2/3 + K_o^-2/3)^-3/2 at that line's angle (spec 004 section 5.3). ``h`` holds
    the entries (h00, h01, h10, h11) of H = dP/dg in (axial, radial), each shaped like ``ga``.
    """
    rho = np.hypot(ga, gr)
    s, c = ga / rho, gr / rho
    lki, dli = _log_k(geo, c, 0)
    lko, dlo = _log_k(geo, c, 1)
    wi, wo = np.exp(lki * (-2.0 / 3.0)), np.exp(lko * (-2.0 / 3.0))  # K^(-2/3)
    sw = wi + wo
    kn = 1.0 / (sw * np.sqrt(sw))
    dlkn = (wi * dli + wo * dlo) / sw  # d ln K_n / d cos(alpha)
    defl = np.maximum(rho - geo.big_a, 0.0)
    root = np.sqrt(defl)
    q = kn * defl * root
    dq = 1.5 * kn * root
    q_a = -q * s * dlkn  # dQ/d alpha
    # H = dQ n n^T + (Q_alpha / rho) n t^T + (Q / rho) t t^T, n = (s, c), t = (c, -s) in (axial, radial)
    qa_r, q_r = q_a / rho, q / rho
    h = (dq * s * s + qa_r * s * c + q_r * c * c, dq * s * c - qa_r * s * s - q_r * c * s,
         dq * c * s + qa_r * c * c - q_r * s * c, dq * c * c - qa_r * c * s + q_r * s * s)
    alpha = np.arctan2(ga, gr)
    return {"pa": q * s, "pr": q * c, "h": h, "qi": q, "qo": q, "ai": alpha, "ao": alpha,
            "mg": np.zeros_like(q), "fc": np.zeros_like(q), "noise": dq * _EPS * rho}


# --------------------------------------------------------------------------- balls at speed
def _ball_state(geo, xa, xr, ga, gr, w2, deriv=True):
    """Ball residual (eqs. 5-6), ring reaction and their partials for ball centres x = (xa, xr).

    x is measured from the outer groove-curvature centre, (ga, gr) is the inner one, all in the plane of
    the ball (axial, radial) and of one shape. Returns a dict with the residual (``b0``, ``b1``) [N], the
    reaction on the inner ring (``pa``, ``pr``), the loads, angles and dynamics, the rounding floors of
    the ring reaction (``noise``) and of the ball residual (``noise_b``) and, with ``deriv``, the partials
    ``bx``, ``bg``, ``px``, ``pg``, each a 4-tuple of the entries (00, 01, 10, 11) of a 2 x 2 matrix
    (``deriv="x"``: ``bx`` only, what the ball Newton needs). Written elementwise: no matrix product, so a
    ball rounds alike in any batch (see :mod:`bearinglab.quasistatic._ring`).
    """
    ia, ir = ga - xa, gr - xr
    rho_o, rho_i = np.hypot(xa, xr), np.hypot(ia, ir)
    so, co = xa / rho_o, xr / rho_o
    si, ci = ia / rho_i, ir / rho_i
    di, do = rho_i - geo.ri, rho_o - geo.ro
    lki, dli = _log_k(geo, ci, 0)
    lko, dlo = _log_k(geo, co, 1)
    ki, ko = np.exp(lki), np.exp(lko)
    dip, dop = np.maximum(di, 0.0), np.maximum(do, 0.0)
    rti, rto = np.sqrt(dip), np.sqrt(dop)
    qi, qo = ki * dip * rti, ko * dop * rto
    lam_i, lam_o = geo.lam
    lam_i = lam_i * (di > 0)  # friction at the inner contact needs contact
    fc, fc_i, fc_o, mg, mg_i, mg_o = (w2 * v for v in _dynamics(si, ci, so, co, geo.d / geo.dm, geo.control,
                                                                 geo.inertia, geo.mass, geo.dm))
    m = mg / geo.d
    v0, v1 = lam_i * ci - lam_o * co, -lam_i * si + lam_o * so  # lambda_i t_i - lambda_o t_o
    out = {"b0": qi * si - qo * so + m * v0, "b1": qi * ci - qo * co + m * v1 + fc,
           "pa": qi * si + m * lam_i * ci, "pr": qi * ci - m * lam_i * si,  # the ball's reaction is -(pa, pr)
           "qi": qi, "qo": qo, "si": si, "ci": ci, "so": so, "co": co, "mg": mg, "fc": fc, "di": di, "do": do,
           "noise": 1.5 * ki * rti * _EPS * rho_i, "noise_b": 1.5 * (ki * rti * rho_i + ko * rto * rho_o) * _EPS}
    if not deriv:
        return out
    qi_a, qo_a = -qi * si * dli, -qo * so * dlo
    qi_d, qo_d = 1.5 * ki * rti, 1.5 * ko * rto
    mi, mo = mg_i / geo.d, mg_o / geo.d
    # partials of the ball residual in (alpha_i, alpha_o, delta_i, delta_o), axial (0) and radial (1) rows
    ba_i = qi_a * si + qi * ci + mi * v0 - m * lam_i * si
    ba_o = -qo_a * so - qo * co + mo * v0 + m * lam_o * so
    br_i = qi_a * ci - qi * si + mi * v1 - m * lam_i * ci + fc_i
    br_o = -qo_a * co + qo * so + mo * v1 + m * lam_o * co + fc_o
    # d(alpha_i, alpha_o, delta_i, delta_o) / d(xa, xr): alpha_i (-ci, si) / rho_i, alpha_o (co, -so) / rho_o,
    # delta_i -(si, ci), delta_o (so, co)
    ai_a, ai_r, ao_a, ao_r = -ci / rho_i, si / rho_i, co / rho_o, -so / rho_o
    out["bx"] = (ba_i * ai_a + ba_o * ao_a - qi_d * si * si + (-qo_d) * so * so,
                 ba_i * ai_r + ba_o * ao_r - qi_d * si * ci + (-qo_d) * so * co,
                 br_i * ai_a + br_o * ao_a - qi_d * ci * si + (-qo_d) * co * so,
                 br_i * ai_r + br_o * ao_r - qi_d * ci * ci + (-qo_d) * co * co)
    if deriv == "x":
        return out
    pa_i = qi_a * si + qi * ci + lam_i * (mi * ci - m * si)
    pr_i = qi_a * ci - qi * si + lam_i * (-mi * si - m * ci)
    pa_o, pr_o = lam_i * mo * ci, -lam_i * mo * si
    # d(alpha_i, delta_i) / d(ga, gr): alpha_i (ci, -si) / rho_i, delta_i (si, ci); alpha_o and delta_o do not move
    gi_a, gi_r = ci / rho_i, -si / rho_i
    out["bg"] = (ba_i * gi_a + qi_d * si * si, ba_i * gi_r + qi_d * si * ci,
                 br_i * gi_a + qi_d * ci * si, br_i * gi_r + qi_d * ci * ci)
    out["px"] = (pa_i * ai_a + pa_o * ao_a - qi_d * si * si, pa_i * ai_r + pa_o * ao_r - qi_d * si * ci,
                 pr_i * ai_a + pr_o * ao_a - qi_d * ci * si, pr_i * ai_r + pr_o * ao_r - qi_d * ci * ci)
    out["pg"] = (pa_i * gi_a + qi_d * si * si, pa_i * gi_r + qi_d * si * ci,
                 pr_i * gi_a + qi_d * ci * si, pr_i * gi_r + qi_d * ci * ci)
    return out


def _inverse2(a):
    """The entries of the inverse of the 2 x 2 matrices with entries ``a`` = (a00, a01, a10, a11)."""
    det = a[0] * a[3] - a[1] * a[2]
    return a[3] / det, -a[1] / det, -a[2] / det, a[0] / det


def _mul2(a, b):
    """Entries of the 2 x 2 products a b (each a 4-tuple of entries)."""
    return (a[0] * b[0] + a[1] * b[2], a[0] * b[1] + a[1] * b[3], a[2] * b[0] + a[3] * b[2], a[2] * b[1] + a[3] * b[3])


def _schur(st):
    """Each ball's relaxation and ring stiffness at a state of :func:`_ball_state` (``deriv=True``).

    With M = b_x^-1: the ball's Newton step at fixed rings dx_b = -M b, its response to the rings
    dx/dg = -M b_g, its ring stiffness H = p_g + p_x dx/dg (the Schur complement of the ball equations,
    implicit function theorem) and the ring reaction once the balls have taken dx_b, to first order,
    (pa, pr) + p_x dx_b. Returns (dx_b (2-tuple), dx/dg (4-tuple), H (4-tuple), relaxed (pa, pr)).
    """
    inv = _inverse2(st["bx"])
    dxb = (-(inv[0] * st["b0"] + inv[1] * st["b1"]), -(inv[2] * st["b0"] + inv[3] * st["b1"]))
    dxdg = tuple(-v for v in _mul2(inv, st["bg"]))
    px, pg = st["px"], st["pg"]
    h = tuple(g + v for g, v in zip(pg, _mul2(px, dxdg), strict=True))
    relaxed = (st["pa"] + (px[0] * dxb[0] + px[1] * dxb[1]), st["pr"] + (px[2] * dxb[0] + px[3] * dxb[1]))
    return dxb, dxdg, h, relaxed


def _ball_start(geo, ga, gr, w2):
    """A ball position to start from: on the line between the groove centres, pressed out by F_c.

    Where the ball is loaded at rest its outer deflection is its share of rho - A (the rest position);
    F_c = m (d_m/2) omega_m^2 with the cage at about half the shaft speed is a lower bound.
    """
    rho = np.hypot(ga, gr)
    na, nr = ga / rho, gr / rho
    lki = _log_k(geo, nr, 0)[0]
    lko = _log_k(geo, nr, 1)[0]
    wi, wo = np.exp(lki * (-2.0 / 3.0)), np.exp(lko * (-2.0 / 3.0))
    total = rho - geo.big_a
    fc = w2 * geo.mass * geo.dm / 2.0 * 0.25  # cage at about half the shaft speed
    do = geo.ro + np.maximum(total * wo / (wi + wo), np.cbrt(fc) ** 2 * wo)  # (F_c / K_o)^(2/3)
    if geo.kind == "self-aligning":
        return _sphere_start(geo, ga, gr, rho, na * do, nr * do, np.cbrt(fc) ** 2, wi, wo)
    return na * do, nr * do


def _sphere_start(geo, ga, gr, rho, xa, xr, fc23, wi, wo):
    """A self-aligning bearing's unloaded ball (rho < A) at speed: F_c presses it on the outer sphere, and it
    slides on it towards the centre plane until the flank of its inner groove holds it, so it starts where
    it touches both, each contact compressed as by F_c: on the circle of radius r_o + (F_c/K_o)^(2/3) about
    the sphere's centre and that of radius r_i + (F_c/K_i)^(2/3) about the inner groove centre, at their
    intersection nearer the centre plane. On the line between the groove centres it would lie on the sphere
    alone, whose large radius leaves it almost no stiffness across that line."""
    r1 = geo.ro + fc23 * wo  # |x|, the sphere's centre the origin
    r2 = geo.ri + fc23 * wi  # |g - x|
    along = (rho * rho + r1 * r1 - r2 * r2) / (2.0 * rho)
    with np.errstate(invalid="ignore"):
        across = np.sqrt(r1 * r1 - along * along)
    ua, ur = ga / rho, gr / rho
    # the two intersections along +-(ur, -ua); the one whose axial coordinate is nearer zero
    pa, pr = along * ua + across * ur, along * ur - across * ua
    qa, qr = along * ua - across * ur, along * ur + across * ua
    near = np.abs(pa) <= np.abs(qa)
    sa, sr = np.where(near, pa, qa), np.where(near, pr, qr)
    use = (rho < geo.big_a) & np.isfinite(across) & (fc23 > 0)
    return np.where(use, sa, xa), np.where(use, sr, xr)


def _speed_balls(geo, ga, gr, w2, x0=None):
    """Solve every ball's equilibrium (eqs. 5-6) at fixed rings for its centre, then the ring reaction and
    its stiffness.

    Batched Newton on the 2 x 2 ball systems with step halving that keeps delta_o > 0; the ring stiffness
    per ball is the Schur complement (:func:`_schur`). ``x0`` = (xa, xr) or None for :func:`_ball_start`.
    Returns the ball dict (with ``x``, ``h``, ``dxdg`` and ``ok``). A position where a ball's kinematics
    are singular (inf or NaN) leaves the ball not ``ok``.
    """
    w2 = np.broadcast_to(w2, ga.shape)
    if x0 is None:
        x0 = _ball_start(geo, ga, gr, w2)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        return _speed_balls_newton(geo, ga, gr, w2, x0)


def _speed_balls_newton(geo, ga, gr, w2, x0):
    # the balls still iterating, flattened: converged balls drop out of the work (each ball is independent)
    shape = ga.shape
    xa, xr = (np.array(v, dtype=float).ravel() for v in x0)
    gaf, grf, w2f = ga.ravel(), gr.ravel(), np.ascontiguousarray(w2).ravel()
    act = np.arange(gaf.size)
    for _ in range(_BALL_MAX_ITER):
        ea, er = xa[act], xr[act]
        st = _ball_state(geo, ea, er, gaf[act], grf[act], w2f[act], deriv="x")
        inv = _inverse2(st["bx"])
        s0, s1 = -(inv[0] * st["b0"] + inv[1] * st["b1"]), -(inv[2] * st["b0"] + inv[3] * st["b1"])
        bad = ~(np.isfinite(s0) & np.isfinite(s1))
        s0[bad], s1[bad] = 0.0, 0.0
        t = np.ones(act.size)
        for _h in range(20):  # keep the ball on the outer raceway
            lost = np.hypot(ea + t * s0, er + t * s1) <= geo.ro
            if not lost.any():
                break
            t = np.where(lost, 0.5 * t, t)
        xa[act], xr[act] = ea + t * s0, er + t * s1
        act = act[np.maximum(np.abs(s0), np.abs(s1)) > _BALL_TOL * geo.d]
        if act.size == 0:
            break
    active = np.zeros(gaf.size, dtype=bool)
    active[act] = True
    xa, xr = xa.reshape(shape), xr.reshape(shape)
    st = _ball_state(geo, xa, xr, ga, gr, w2)
    _dxb, dxdg, h, _relaxed = _schur(st)
    fs = np.maximum(np.maximum(st["qo"], st["qi"]), 1e-300)
    ok = ~active.reshape(shape) & (np.abs(st["b0"]) <= 1e-9 * fs) & (np.abs(st["b1"]) <= 1e-9 * fs)
    st.update(x=(xa, xr), h=h, dxdg=dxdg, ok=ok, ai=np.arctan2(ga - xa, gr - xr), ao=np.arctan2(xa, xr))
    return st
