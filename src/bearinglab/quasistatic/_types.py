r"""The ball-bearing types beyond the single row in the 5-DOF model of :mod:`bearinglab.quasistatic.combined` (private).

Four-point contact (QJ), double-row angular contact (32 A, 33 A), double-row deep groove (42, 43),
self-aligning (12, 13, 22, 23) and single-direction thrust ball bearings (511-514) are sets of
*elements*: an element is one pair of contacts, an inner one and an outer one, of one ball. A
double-row bearing has one element per ball and row (2 Z), a four-point bearing one per ball and
diagonal (2 Z: the contacts on the two halves of its split inner ring, each with the opposite arc of the
outer ring), a thrust bearing one per ball (Z). Every element has its own offset of the inner
groove-curvature centre from the outer one in the concentric position and its own Jacobian rows, and
the ring equilibrium, the stiffness, the solvers and the outputs of the single-row model then hold as
they are, element by element (docs/theory/load_distribution.md, "The other ball-bearing types").

Geometry
--------
MODELLED        the types of this module
AT_SPEED        those with the speed terms (centrifugal force, gyroscopic moment): two contacts a ball
Elements        the elements of one bearing (offsets, rows, Jacobian rows, weights of the sums)
geometry        one bearing's checked data, any type (a single row: :func:`._combined_balls._geometry`)
elements        the elements from the bearing's data
offsets         groove-centre offsets of every element (or ball) for ring displacements
steps           the change of those offsets for a change of the displacements
reaction        the ring load of the element reactions
assemble        the ring stiffness of the elements' 2 x 2 stiffnesses

Balls
-----
rest_balls      every element at rest: the closed form of two contacts, the thrust closed form, or the
                four-contact ball of a four-point bearing solved for its centre

Solver support
--------------
start           a start of the ring Newton
held            the freedoms the type does not resist (a self-aligning ring's tilt, a thrust bearing's
                radial freedoms), held with their loads checked zero
check_loads     the loads the type cannot carry (refused in one line)
first_contact   delta_z at which the bearing first carries a thrust F_z > 0 (half its axial play)
bearing_options the model's options from a BallBearing (clearance, row distance), missing fields named
misalignment_limit, misalignment_note   a self-aligning ring's tilt at which a contact reaches the outer
                ring's side, and the warning beyond it

References
----------
.. [1] T. A. Harris and M. N. Kotzalas, *Essential Concepts of Bearing Technology*, 5th ed., CRC Press,
   2006, ch. 2 (ball-bearing macrogeometry: groove-curvature centres, clearance, contact angle and end
   play) and *Advanced Concepts of Bearing Technology*, ch. 1 (the five-degree-of-freedom distribution of
   internal loading).
.. [2] A. B. Jones, "A general theory for elastically constrained ball and radial roller bearings under
   arbitrary load and speed conditions," J. Basic Eng., vol. 82, no. 2, pp. 309-320, 1960,
   doi:10.1115/1.3662587 (each ball's equilibrium between its contacts).
.. [3] ISO/TS 16281:2008 (the pitch radius as the arm of tilts and moments; the sphere r_e = D_w (1 +
   1/gamma) / 2 of a self-aligning bearing's outer raceway).
.. [4] J. I. Amasorrain, X. Sagartzazu and J. Damian, "Load distribution in a four contact-point slewing
   bearing," Mechanism and Machine Theory, vol. 38, pp. 479-496, 2003
   (the four contacts of a ball between two pairs of groove-curvature centres offset by the angle).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from .._validate import as_float, check_positive
from ..errors import InputError
from . import _combined_balls, _ring
from ._combined_balls import _hertz_k, _log_k, _rest_balls

__all__ = ["AT_SPEED", "MODELLED", "Elements", "assemble", "bearing_options", "check_loads", "elements",
           "first_contact", "geometry", "held", "misalignment_limit", "misalignment_note", "offsets", "reaction",
           "rest_balls", "start", "steps"]

#: The types of this module (``BallBearing.type`` words).
MODELLED = ("four-point", "double-row-angular", "double-row-radial", "self-aligning", "thrust")
#: The types solved at speed too (two contacts a ball, the single-row model's ball equilibrium).
AT_SPEED = ("double-row-angular", "double-row-radial", "self-aligning")
#: Types whose angle is that of the rings' design (the rest: a deep-groove row, angle from the clearance).
_BUILT_IN = ("four-point", "double-row-angular", "self-aligning")
_EPS = np.finfo(float).eps
_BALL_TOL = 1e-14  # the four-contact ball's Newton: |step| / D, as the single-row model's ball at speed
_BALL_MAX_ITER = 60
_HALVINGS = 30
_SPHERE_TOLERANCE = math.radians(0.05)  # a self-aligning bearing's angle and sphere agree to the printed digits


class Elements(NamedTuple):
    """The elements of one bearing (each array over the elements, rows one after the other)."""

    psi: np.ndarray  # azimuth of the element's ball [rad]
    ga0: np.ndarray  # axial offset of the inner groove-curvature centre from the outer one, concentric [m]
    gr0: np.ndarray  # radial offset, concentric [m]
    row: np.ndarray  # row (a four-point bearing: diagonal) of each element, 0 or 1
    sign: np.ndarray  # +1 where the element carries a thrust F_z > 0 on the inner ring, -1 where F_z < 0
    ja: np.ndarray  # (n_el, 5) d(axial offset)/du
    jr: np.ndarray  # (n_el, 5) d(radial offset)/du
    wa: np.ndarray  # (5, n_el) ja transposed (the weights of the reaction's sums)
    wr: np.ndarray  # (5, n_el)
    wk: tuple  # four (25, n_el) weights of the stiffness sums: ja ja, ja jr, jr ja, jr jr
    n_balls: int  # balls per row
    n_rows: int
    row_z: tuple  # axial position of each row's ball centres [m]
    trust: float  # the ring Newton's step bound (no groove centre moves by more than half of it) [m]
    axial_offset: float  # A sin(alpha0) of the built-in angle (thrust: A); 0 for deep-groove rows [m]
    radial_offset: float  # A cos(alpha0) - e/2 (deep-groove rows: A - e/2; thrust: 0) [m]


def geometry(n_balls, d, dm, fi, fo, a0, ep, density, phi0, stiffness_at, control, kind, *, tables=True,
             clearance=None, row_distance=None):
    """One bearing's checked data and what every evaluation needs (``_combined_balls._Geometry``), any type.

    A single row (``radial``, ``angular``) is :func:`bearinglab.quasistatic._combined_balls._geometry` as it
    is; the types of :data:`MODELLED` take ``a0`` as their nominal angle (built into the rings; a double-row
    deep-groove bearing: its free angle, or None with ``clearance``), ``clearance`` as their diametral
    clearance e (None: 0) and, double-row, their ``row_distance`` [m]; ``z`` and the azimuths are then
    those of the elements.
    """
    if kind not in MODELLED:
        return _combined_balls._geometry(n_balls, d, dm, fi, fo, a0, ep, density, phi0, stiffness_at, control, kind,
                                         tables=tables, clearance=clearance)
    base = _combined_balls._geometry(n_balls, d, dm, fi, fo, 0.0, ep, density, phi0, stiffness_at, control, "radial",
                                     tables=False)
    if row_distance is not None:
        row_distance = float(check_positive("row_distance", row_distance, "m"))
    elif kind in ("double-row-angular", "double-row-radial"):
        raise InputError(f"row_distance is needed for a {kind} bearing (the axial distance between the ball centres "
                         "of its two rows) [m]")
    a0, e, el = elements(kind, base.z, base.d, base.dm, base.fi, base.fo, a0, clearance, base.psi, row_distance)
    tab = series = None
    ep_f = mass = inertia = np.nan
    if tables:
        ep_f = float(check_positive("reduced_modulus", ep, "Pa"))
        mass = float(check_positive("density", density, "kg/m^3")) * math.pi * base.d ** 3 / 6.0
        inertia = mass * base.d ** 2 / 10.0
        tab = _tables(kind, base.d, base.dm, base.fi, base.fo, ep_f, a0, stiffness_at)
        series = _combined_balls._series(tab)
    return base._replace(z=el.psi.size, a0=a0, ep=ep_f, mass=mass, inertia=inertia, gr0=el.radial_offset,
                         psi=el.psi, ja=el.ja, jr=el.jr, cos_psi=np.cos(el.psi), sin_psi=np.sin(el.psi),
                         weights=_ring.weights(el.psi), tables=tab, kind=kind, series=series, clearance=e, elements=el)


def _tables(kind, d, dm, fi, fo, ep, a0, stiffness_at):
    """The Hertz series of :func:`._combined_balls._tables`; a self-aligning bearing's outer contact is on a
    sphere, whose curvature is 1/R_o in every direction at any contact angle, so its constants are those
    at alpha0 (where the raceway formulas give that sphere) for every angle, a constant series."""
    if kind != "self-aligning":
        return _combined_balls._tables(d, dm, fi, fo, ep, a0, stiffness_at)
    sphere = _combined_balls._tables(d, dm, fi, fo, ep, a0, "free")
    if stiffness_at == "free":
        return sphere
    groove = _combined_balls._tables(d, dm, fi, 0.53, ep, a0, stiffness_at)  # the inner contacts (f_o unused)
    n = groove[0].size

    def constant(c):
        out = np.zeros(n)
        out[0] = c[0]
        out.setflags(write=False)
        return out

    return groove[0], constant(sphere[1]), groove[2], constant(sphere[3])


def _rows(kind, dm, a0, row_distance):
    """(axial position, sign) of each row: a double-row angular bearing back to back (O, the row at -z
    carries F_z > 0: its contact line meets the axis outside the bearing), a self-aligning bearing's rows
    on lines through the sphere's centre (X, meeting at the bearing centre), the two diagonals of a
    four-point bearing in one plane, one row of a thrust bearing."""
    if kind == "thrust":
        return ((0.0, 1),)
    if kind == "four-point":
        return ((0.0, 1), (0.0, -1))
    if kind == "self-aligning":
        zr = 0.5 * dm * math.tan(a0)
        return ((-zr, -1), (zr, 1))
    half = 0.5 * row_distance
    return ((-half, 1), (half, -1))


def elements(kind, z, d, dm, fi, fo, a0, clearance, psi1, row_distance):
    """The elements of a bearing of ``kind`` and its free angle alpha0 and clearance e.

    Parameters: Z (balls per row), D, d_m, f_i, f_o, the nominal angle alpha0 (built into the rings; for a
    double-row deep-groove bearing None or the free angle of its clearance), the diametral clearance e
    (None: 0 for a deep-groove row given by its angle, see below), the azimuths psi (Z,) of one row and
    the row distance L (double-row types).

    Concentric offsets: A (s sin alpha0, cos alpha0) - (0, e/2) with s the element's sign (the
    groove-curvature centres offset by the built-in angle, the clearance taking the inner ones down by
    e/2: Harris and Kotzalas [1] ch. 2), (0, A - e/2) for a deep-groove row, (A, 0) for a thrust
    bearing (its contact at 90 deg; the displacement delta_z counts from first contact).
    """
    big_a = (fi + fo - 1.0) * d
    if kind == "double-row-radial":
        if clearance is None:
            a = 0.0 if a0 is None else float(as_float("free_angle", a0))
            e = 2.0 * big_a * (1.0 - math.cos(a))
        else:
            e = _clearance(clearance, d, 2.0 * big_a, "2 A (a free contact angle of 90 deg)")
            a = math.acos(1.0 - e / (2.0 * big_a)) if e > 0 else 0.0
            if a0 is not None and abs(float(a0) - a) > 1e-9:
                raise InputError(f"free_angle ({math.degrees(float(a0)):.6g} deg) and radial_clearance "
                                 f"({e * 1e6:.6g} um) disagree: the clearance gives {math.degrees(a):.6g} deg; give one "
                                 "of them")
        axial, radial = 0.0, big_a - 0.5 * e
    elif kind == "thrust":
        a = float(as_float("free_angle", a0))
        if abs(a - math.pi / 2) > 1e-9:
            raise InputError(f"free_angle of a thrust ball bearing must be 90 deg (the model covers single-direction "
                             f"thrust ball bearings of 90 deg, 511-514), got {math.degrees(a):.6g} deg")
        e, axial, radial = 0.0, big_a, 0.0
    else:
        a = float(as_float("free_angle", a0))
        if not 0.0 < a < math.pi / 2:
            raise InputError(f"free_angle of a {kind} bearing (its nominal angle) must be in (0, 90) [deg], got "
                             f"{math.degrees(a):.6g}")
        if kind == "self-aligning":  # the outer raceway is a sphere about the bearing centre: r_o = d_m/(2 cos a)
            c = dm / (2.0 * (fo - 0.5) * d)
            sphere = math.acos(c) if c < 1.0 else math.nan
            if not abs(sphere - a) <= _SPHERE_TOLERANCE:
                raise InputError(f"outer_conformity ({fo:.6g}) and free_angle ({math.degrees(a):.6g} deg) of a "
                                 "self-aligning bearing disagree: its outer raceway is a sphere about the bearing "
                                 f"centre, so f_o = 0.5 + d_m / (2 D cos alpha0) = {0.5 + dm / (2.0 * d * math.cos(a)):.6g}")
            a = sphere
        e = 0.0 if clearance is None else _clearance(clearance, d, 2.0 * big_a * math.cos(a),
                                                      "2 A cos(alpha0) (the inner groove centres on the axis' side)")
        axial, radial = big_a * math.sin(a), big_a * math.cos(a) - 0.5 * e
    rows = _rows(kind, dm, a, row_distance)
    n = len(rows)
    psi = np.tile(psi1, n)
    c, s = np.cos(psi), np.sin(psi)
    arm = 0.5 * dm
    zeros = np.zeros_like(psi)
    ja = np.stack([zeros, zeros, np.ones_like(psi), arm * s, -arm * c], axis=1)
    rz = np.repeat([r[0] for r in rows], len(psi1))
    sign = np.repeat([float(r[1]) for r in rows], len(psi1))
    jr = np.stack([c, s, zeros, -rz * s, rz * c], axis=1)
    if kind == "self-aligning":  # a tilt about the sphere's centre changes no contact: no tilt columns
        ja[:, 3:] = 0.0
        jr[:, 3:] = 0.0
    if kind == "thrust":  # the housing washer is free radially: no radial row
        jr[:] = 0.0
    ja, jr = np.ascontiguousarray(ja), np.ascontiguousarray(jr)
    wk = tuple(np.ascontiguousarray((p[:, :, None] * q[:, None, :]).reshape(len(psi), 25).T)
               for p, q in ((ja, ja), (ja, jr), (jr, ja), (jr, jr)))
    # the step bound of the ring Newton: half a groove distance of an ordinary groove (a self-aligning
    # bearing's A spans the sphere's radius, which would bound nothing)
    trust = (fi + min(fo, 0.53) - 1.0) * d if kind == "self-aligning" else big_a
    el = Elements(psi, sign * axial, np.full(psi.shape, radial), np.repeat(np.arange(n), len(psi1)), sign, ja, jr,
                  np.ascontiguousarray(ja.T), np.ascontiguousarray(jr.T), wk, len(psi1), n,
                  tuple(r[0] for r in rows), trust, axial, radial)
    return a, e, el


def _clearance(e, d, top, what):
    e = float(as_float("radial_clearance", e))
    if not (math.isfinite(e) and -2.0 * d <= e < top):
        raise InputError(f"radial_clearance must be in [{-2.0 * d * 1e3:.6g}, {top * 1e3:.6g}) [mm] (from an "
                         f"interference of one ball diameter per ball to {what}), got {e * 1e3:.6g} mm")
    return e


# --------------------------------------------------------------------------- the ring
def offsets(geo, u):
    """(axial, radial) offsets (n, n_el) of every element for displacements u (n, 5): g0 + J u (a single row:
    :func:`bearinglab.quasistatic._ring.offsets`)."""
    el = geo.elements
    if el is None:
        return _ring.offsets(geo, u)
    ga = np.broadcast_to(el.ga0, (len(u), el.ga0.size)).copy()
    gr = np.broadcast_to(el.gr0, ga.shape).copy()
    for i in range(5):
        ga += u[:, i:i + 1] * el.ja[:, i]
        gr += u[:, i:i + 1] * el.jr[:, i]
    return ga, gr


def steps(geo, du):
    """The change (n, n_el) of the axial and radial offsets for a change du (n, 5) of the displacements (the
    types of this module only)."""
    ga, gr = offsets(geo, du)
    return ga - geo.elements.ga0, gr - geo.elements.gr0


def reaction(geo, pa, pr):
    """Ring load (n, 5) of the element reactions (n, n_el): sum_e J_e^T (pa_e, pr_e), the elements added
    one after the other (the same bits in any batch; a single row: :func:`._ring.reaction`)."""
    el = geo.elements
    if el is None:
        return _ring.reaction(geo, pa, pr)
    return _ring._sum(pa, el.wa) + _ring._sum(pr, el.wr)


def assemble(geo, h00, h01, h10, h11):
    """Ring stiffness (n, 5, 5) sum_e J_e^T H_e J_e from the elements' 2 x 2 stiffnesses (a single row:
    :func:`._ring.assemble`)."""
    if geo.elements is None:
        return _ring.assemble(geo, h00, h01, h10, h11)
    wk = geo.elements.wk
    k = _ring._sum(h00, wk[0]) + _ring._sum(h01, wk[1]) + _ring._sum(h10, wk[2]) + _ring._sum(h11, wk[3])
    return k.reshape(len(h00), 5, 5)


# --------------------------------------------------------------------------- balls at rest
def rest_balls(geo, ga, gr):
    """Every element's (or ball's) reaction, 2 x 2 stiffness and outputs at rest (the keys of
    :func:`bearinglab.quasistatic._combined_balls._rest_balls`; a four-point ball's residual ``b_res``)."""
    if geo.kind == "thrust":
        return _thrust_balls(geo, ga)
    if geo.kind == "four-point":
        return _four_point_balls(geo, ga, gr)
    return _rest_balls(geo, ga, gr)


def _thrust_balls(geo, ga):
    """A thrust ball between flat-bottomed grooves at 90 deg: Q = K_n(90 deg) (A_z - A)^1.5, axial only."""
    c = np.zeros_like(ga)
    wi, wo = np.exp(_log_k(geo, c, 0)[0] * (-2.0 / 3.0)), np.exp(_log_k(geo, c, 1)[0] * (-2.0 / 3.0))
    sw = wi + wo
    kn = 1.0 / (sw * np.sqrt(sw))
    defl = np.maximum(ga - geo.big_a, 0.0)
    root = np.sqrt(defl)
    q = kn * defl * root
    dq = 1.5 * kn * root
    zero = np.zeros_like(q)
    right = np.full_like(q, 0.5 * math.pi)
    return {"pa": q, "pr": zero, "h": (dq, zero, zero.copy(), zero.copy()), "qi": q, "qo": q, "ai": right,
            "ao": right, "mg": zero, "fc": zero, "noise": dq * _EPS * np.abs(ga)}


def _contact(geo, va, vr, race):
    """One contact of a four-point ball: the centre-to-ball vector (va, vr) (outer: ball centre minus the
    outer groove centre; inner: inner groove centre minus the ball centre) -> its load, direction, angle
    and the 2 x 2 matrix C = n (Q' n^T + Q_alpha t^T / rho) + Q t t^T / rho (the derivative of the force
    along n by the vector)."""
    rho = np.hypot(va, vr)
    na, nr = va / rho, vr / rho
    lk, dlk = _log_k(geo, nr, race)
    k = np.exp(lk)
    defl = np.maximum(rho - (geo.ri if race == 0 else geo.ro), 0.0)
    root = np.sqrt(defl)
    q = k * defl * root
    dq = 1.5 * k * root
    qa_r = -q * na * dlk / rho  # dQ/dalpha / rho
    q_r = q / rho
    # n = (na, nr), t = (nr, -na)
    cm = (dq * na * na + qa_r * na * nr + q_r * nr * nr, dq * na * nr - qa_r * na * na - q_r * nr * na,
          dq * nr * na + qa_r * nr * nr - q_r * na * nr, dq * nr * nr - qa_r * nr * na + q_r * na * na)
    return {"q": q, "na": na, "nr": nr, "c": cm, "noise": dq * rho * _EPS}


def _four_point_state(geo, xa, xr, ia, ir, oa, orr):
    """The four contacts of the balls at centres (xa, xr) (n, Z), the inner groove centres (ia, ir) and the
    outer ones (oa, orr) of both diagonals (each a pair): the ball residual, its Jacobian and the contacts."""
    inner = [_contact(geo, ia[k] - xa, ir[k] - xr, 0) for k in range(2)]
    outer = [_contact(geo, xa - oa[k], xr - orr[k], 1) for k in range(2)]
    # force on the ball: + Q m from an inner contact (towards its groove centre), - Q n from an outer one
    b0 = inner[0]["q"] * inner[0]["na"] + inner[1]["q"] * inner[1]["na"] - outer[0]["q"] * outer[0]["na"] \
        - outer[1]["q"] * outer[1]["na"]
    b1 = inner[0]["q"] * inner[0]["nr"] + inner[1]["q"] * inner[1]["nr"] - outer[0]["q"] * outer[0]["nr"] \
        - outer[1]["q"] * outer[1]["nr"]
    # d b / d x = - sum over the four contacts of C
    bx = tuple(-(inner[0]["c"][i] + inner[1]["c"][i] + outer[0]["c"][i] + outer[1]["c"][i]) for i in range(4))
    return b0, b1, bx, inner, outer


def _four_point_balls(geo, ga, gr):
    """The balls of a four-point bearing at rest: each ball's centre solved between its four contacts.

    Element k of ball j (k = 0: the diagonal carrying F_z > 0) holds the contact of inner half-ring k with
    the outer arc of the same diagonal. The outer groove-curvature centres are O_k = -r_o (s_k sin alpha0,
    cos alpha0) from the ball centre of the concentric, zero-clearance position, the inner ones
    I_k = O_k + g_k (the element offsets). The ball is in equilibrium under the four contact forces,
    sum_k (Q_ik m_k - Q_ok n_k) = 0 (m_k towards I_k, n_k from O_k): Newton in its centre from the
    closed-form position of its more compressed diagonal (or the mean of both, both compressed) with
    step halving on the residual; a ball that touches on one diagonal only ends on that diagonal's line
    (the single-row closed form), one that touches nowhere carries nothing. The ring reaction of element
    k is Q_ik m_k and its stiffness H_k = C_ik (I - dx/dg), dx/dg = -(db/dx)^-1 sum_k C_ik (implicit
    function theorem; the two elements share the ball's ring offset).
    """
    z = geo.elements.n_balls
    s0, c0 = math.sin(geo.a0), math.cos(geo.a0)
    oa = (-geo.ro * s0, geo.ro * s0)
    orr = (-geo.ro * c0, -geo.ro * c0)
    ia = (oa[0] + ga[:, :z], oa[1] + ga[:, z:])
    ir = (orr[0] + gr[:, :z], orr[1] + gr[:, z:])
    xa, xr = _four_point_start(geo, ga, gr, oa, orr)
    with np.errstate(divide="ignore", invalid="ignore"):
        xa, xr = _four_point_newton(geo, xa, xr, ia, ir, oa, orr)
        b0, b1, bx, inner, outer = _four_point_state(geo, xa, xr, ia, ir, oa, orr)
        # dx/dg = -bx^-1 sum_k C_ik (an unloaded ball: no stiffness, dx/dg = 0)
        ci = tuple(inner[0]["c"][i] + inner[1]["c"][i] for i in range(4))
        det = bx[0] * bx[3] - bx[1] * bx[2]
        free = ~(np.abs(det) > 0)
        det = np.where(free, 1.0, det)
        inv = (bx[3] / det, -bx[1] / det, -bx[2] / det, bx[0] / det)
        dxdg = tuple(np.where(free, 0.0, -v) for v in (inv[0] * ci[0] + inv[1] * ci[2], inv[0] * ci[1] + inv[1] * ci[3],
                                                        inv[2] * ci[0] + inv[3] * ci[2], inv[2] * ci[1] + inv[3] * ci[3]))
    one_minus = (1.0 - dxdg[0], -dxdg[1], -dxdg[2], 1.0 - dxdg[3])
    h = []
    for c in (inner[0]["c"], inner[1]["c"]):
        h.append((c[0] * one_minus[0] + c[1] * one_minus[2], c[0] * one_minus[1] + c[1] * one_minus[3],
                  c[2] * one_minus[0] + c[3] * one_minus[2], c[2] * one_minus[1] + c[3] * one_minus[3]))

    def both(key_or_fn):
        return np.concatenate([key_or_fn(0), key_or_fn(1)], axis=1)

    qi = both(lambda k: inner[k]["q"])
    qo = both(lambda k: outer[k]["q"])
    return {"pa": both(lambda k: inner[k]["q"] * inner[k]["na"]), "pr": both(lambda k: inner[k]["q"] * inner[k]["nr"]),
            "h": tuple(np.concatenate([h[0][i], h[1][i]], axis=1) for i in range(4)), "qi": qi, "qo": qo,
            "ai": both(lambda k: np.arctan2(inner[k]["na"], inner[k]["nr"])),
            "ao": both(lambda k: np.arctan2(outer[k]["na"], outer[k]["nr"])),
            "mg": np.zeros_like(qi), "fc": np.zeros_like(qi),
            "noise": both(lambda k: inner[k]["noise"] + outer[k]["noise"]),
            "b_res": np.concatenate([np.hypot(b0, b1), np.zeros_like(b0)], axis=1),
            "ok": np.tile(np.hypot(b0, b1) <= np.maximum(1e-9 * np.maximum(np.max(qi, axis=1, keepdims=True), 0.0),
                                                          1e3 * (inner[0]["noise"] + inner[1]["noise"])), (1, 2))}


def _four_point_start(geo, ga, gr, oa, orr):
    """Each ball on the line of its more compressed diagonal, its deflection shared between the two
    contacts as the closed form shares it (or between both lines' positions where both are compressed)."""
    z = geo.elements.n_balls
    pos = []
    defl = []
    for k, sl in enumerate((slice(0, z), slice(z, 2 * z))):
        a, r = ga[:, sl], gr[:, sl]
        rho = np.hypot(a, r)
        na, nr = a / rho, r / rho
        wi, wo = np.exp(_log_k(geo, nr, 0)[0] * (-2.0 / 3.0)), np.exp(_log_k(geo, nr, 1)[0] * (-2.0 / 3.0))
        d_o = geo.ro + (rho - geo.big_a) * wo / (wi + wo)
        pos.append((oa[k] + na * d_o, orr[k] + nr * d_o))
        defl.append(rho - geo.big_a)
    both = (defl[0] > 0) & (defl[1] > 0)
    first = defl[0] >= defl[1]
    xa = np.where(both, 0.5 * (pos[0][0] + pos[1][0]), np.where(first, pos[0][0], pos[1][0]))
    xr = np.where(both, 0.5 * (pos[0][1] + pos[1][1]), np.where(first, pos[0][1], pos[1][1]))
    none = (defl[0] <= 0) & (defl[1] <= 0)
    return np.where(none, 0.5 * (pos[0][0] + pos[1][0]), xa), np.where(none, 0.5 * (pos[0][1] + pos[1][1]), xr)


def _four_point_newton(geo, xa, xr, ia, ir, oa, orr):
    """Newton on the ball centres with step halving on |b|, each ball until its residual is below 1e-14 of its
    largest contact load or four times its rounding floor (converged balls drop out of the work; the state
    of an accepted trial is the next iteration's)."""
    shape = xa.shape
    xa, xr = xa.ravel().copy(), xr.ravel().copy()
    iaf, irf = [v.ravel() for v in ia], [v.ravel() for v in ir]

    def state(sel, ea, er):
        b0, b1, bx, inner, outer = _four_point_state(geo, ea, er, [v[sel] for v in iaf], [v[sel] for v in irf], oa, orr)
        qmax = np.maximum(np.maximum(inner[0]["q"], inner[1]["q"]), np.maximum(outer[0]["q"], outer[1]["q"]))
        floor = 4.0 * (inner[0]["noise"] + inner[1]["noise"] + outer[0]["noise"] + outer[1]["noise"])
        norm = np.hypot(b0, b1)
        return {"b0": b0, "b1": b1, "bx": bx, "norm": norm, "done": norm <= np.maximum(1e-14 * qmax, floor)}

    act = np.arange(xa.size)
    cur = state(act, xa, xr)
    for _ in range(_BALL_MAX_ITER):
        keep = ~cur["done"]
        act = act[keep]
        if act.size == 0:
            break
        cur = {k: (v[keep] if not isinstance(v, tuple) else tuple(x[keep] for x in v)) for k, v in cur.items()}
        b0, b1, bx = cur["b0"], cur["b1"], cur["bx"]
        det = bx[0] * bx[3] - bx[1] * bx[2]
        s0 = -(bx[3] * b0 - bx[1] * b1) / det
        s1 = -(-bx[2] * b0 + bx[0] * b1) / det
        bad = ~(np.isfinite(s0) & np.isfinite(s1))
        s0[bad], s1[bad] = 0.0, 0.0
        # a ball far from its contacts (a start that penetrates one contact only) is moved by at most D/4
        big = np.hypot(s0, s1) / (0.25 * geo.d)
        t = np.where(big > 1.0, 1.0 / np.where(big > 1.0, big, 1.0), 1.0)
        pending = np.arange(act.size)
        stalled = np.zeros(act.size, dtype=bool)
        for h in range(_HALVINGS + 1):
            if pending.size == 0:
                break
            sel = act[pending]
            ea, er = xa[sel] + t[pending] * s0[pending], xr[sel] + t[pending] * s1[pending]
            trial = state(sel, ea, er)
            good = (trial["norm"] < cur["norm"][pending]) | trial["done"]
            g = pending[good]
            xa[act[g]], xr[act[g]] = ea[good], er[good]
            for k, v in trial.items():
                if isinstance(v, tuple):
                    for a, b in zip(cur[k], v, strict=True):
                        a[g] = b[good]
                else:
                    cur[k][g] = v[good]
            pending = pending[~good]
            t[pending] *= 0.5
            if h == _HALVINGS:
                stalled[pending] = True  # no decrease: at its rounding floor (or the ring's residual shows it)
        cur["done"] = cur["done"] | stalled | bad
    return xa.reshape(shape), xr.reshape(shape)


# --------------------------------------------------------------------------- solver support
def start(geo, loads):
    """A start of the ring Newton: the thrust on the elements of its direction (each row alone, the
    single-row model's closed form), the radial load on half the balls of every row (Stribeck's 5/Z) past
    the radial play, the moment as the single-row start takes it; a thrust bearing from the thrust's
    closed form (every ball the same, Q = F_z/Z)."""
    el = geo.elements
    c0 = np.array([math.cos(geo.a0)])
    ki, ko = (_hertz_k(t, c0)[0][0] for t in geo.tables[:2])
    kn0 = (ki ** (-2.0 / 3.0) + ko ** (-2.0 / 3.0)) ** -1.5
    u = np.zeros_like(loads)
    fz = loads[:, 2]
    big_a = geo.big_a
    if geo.kind == "thrust":
        u[:, 2] = np.cbrt(np.maximum(fz, 0.0) / (el.n_balls * kn0)) ** 2
        return u
    axial, radial = el.axial_offset, el.radial_offset
    # the free angle of one row alone (its first contact under thrust), for the thrust closed form
    free = math.acos(min(radial / big_a, 1.0)) if radial < big_a else 0.0
    per_row = 1 if geo.kind != "double-row-radial" else 2  # deep-groove rows share a thrust
    zt = _ring.thrust_offset(np.abs(fz) / (el.n_balls * per_row), big_a, free, radial, kn0)
    u[:, 2] = np.sign(fz) * np.maximum(zt - axial, 0.0)
    fr = np.hypot(loads[:, 0], loads[:, 1])
    play = max(math.sqrt(max(big_a * big_a - axial * axial, 0.0)) - radial, 0.0)
    hertz = (5.0 * fr / (el.n_balls * el.n_rows) / kn0) ** (2.0 / 3.0) / max(math.cos(geo.a0), 0.2)
    mm = np.hypot(loads[:, 3], loads[:, 4])
    arm = 0.5 * geo.dm
    tilt = np.zeros_like(mm) if geo.kind == "self-aligning" else \
        _ring.thrust_offset(2.0 * mm / arm / el.n_balls, big_a, free, radial, kn0) / arm
    with np.errstate(invalid="ignore", divide="ignore"):
        u[:, 0:2] = np.where(fr[:, None] > 0, loads[:, 0:2] / fr[:, None] * (play + hertz)[:, None], 0.0)
        u[:, 3:5] = np.where(mm[:, None] > 0, loads[:, 3:5] / mm[:, None] * tilt[:, None], 0.0)
    return u


#: The freedoms each type does not resist: held at their prescribed value (default 0), their load zero.
_HELD = {"self-aligning": (3, 4), "thrust": (0, 1)}
_WHY = {
    "self-aligning": ("M_x and M_y must be 0 [N m] for a self-aligning ball bearing, got {}: its outer raceway is a "
                      "sphere about the bearing centre, so it carries no moment (zero tilt stiffness) and the inner "
                      "ring tilts freely (give the tilts, e.g. --tilt-x, for a misalignment)"),
    "thrust": ("F_x and F_y must be 0 [N] for a thrust ball bearing, got {}: a single-direction thrust ball bearing "
               "carries no radial load (its housing washer is free radially: zero radial stiffness; carry the "
               "radial load with another bearing)"),
}


def held(geo, loads, prescribed):
    """The prescribed displacements (n, 5) with the freedoms the type does not resist held (at the given
    value, else 0), or ``prescribed`` itself (None: nothing held) for the other types. Their loads must be
    zero: InputError naming them otherwise."""
    idx = _HELD.get(geo.kind)
    if idx is None:
        return prescribed
    bad = np.any(loads[:, list(idx)] != 0.0, axis=1)
    if prescribed is not None:
        bad &= np.any(np.isnan(prescribed[:, list(idx)]), axis=1)
    if bad.any():
        k = int(np.flatnonzero(bad)[0])
        raise InputError(_WHY[geo.kind].format(", ".join(f"{v:g}" for v in loads[k, list(idx)])))
    out = np.full(loads.shape, np.nan) if prescribed is None else np.array(prescribed, dtype=float, copy=True)
    for i in idx:
        out[:, i] = np.where(np.isnan(out[:, i]), 0.0, out[:, i])
    return np.ascontiguousarray(out)


def check_loads(geo, loads, w, held_u):
    """Refuse what the type cannot carry: a thrust bearing's F_z < 0 (its washers part) and a line of
    action outside its balls' pitch polygon (the washer lifts off), and any speed for the types without
    the speed terms (InputError, one line)."""
    if geo.kind not in AT_SPEED and np.any(w > 0):
        raise InputError(f"shaft_speed: the {geo.kind} model is at rest only (its balls' centrifugal forces and "
                         "gyroscopic moments are not modelled), got a speed > 0; solve it at rest (speed 0)")
    if geo.kind != "thrust":
        return
    free_z = np.ones(len(loads), dtype=bool) if held_u is None else np.isnan(held_u[:, 2])
    neg = free_z & (loads[:, 2] < 0)
    if neg.any():
        k = int(np.flatnonzero(neg)[0])
        raise InputError(f"F_z must be >= 0 [N] for a single-direction thrust ball bearing (the shaft washer pressed "
                         f"against the balls), got {loads[k, 2]:g} N")
    moment = np.ones(len(loads), dtype=bool) if held_u is None else np.all(np.isnan(held_u[:, 2:]), axis=1)
    m = loads[:, 3:5]
    fz = loads[:, 2]
    # the resultant's point (x, y) = (-M_y, M_x) / F_z must lie inside the polygon of the ball centres
    z = geo.elements.n_balls
    edge = geo.psi[:z] + math.pi / z
    with np.errstate(invalid="ignore", divide="ignore"):
        reach = (np.outer(-m[:, 1], np.cos(edge)) + np.outer(m[:, 0], np.sin(edge))).max(axis=1)
    inner = 0.5 * geo.dm * math.cos(math.pi / z) if z >= 3 else 0.0
    out = moment & np.any(m != 0, axis=1) & ~(reach < inner * fz)
    if out.any():
        k = int(np.flatnonzero(out)[0])
        raise InputError(f"loads: the moment ({loads[k, 3]:g}, {loads[k, 4]:g}) N m with F_z = {fz[k]:g} N puts the "
                         f"thrust's line of action outside the balls' pitch polygon ({inner * 1e3:.6g} mm from the "
                         "axis at most): the shaft washer would lift off; a thrust ball bearing needs |M| < F_z times "
                         "that distance")


def first_contact(geo):
    """delta_z at which the first element carries a thrust F_z > 0 (half the axial play, s_a/2): 0 for a
    bearing whose balls touch in the concentric position and for a thrust bearing (counted from first
    contact). [m]"""
    el = geo.elements
    if geo.kind == "thrust":
        return 0.0
    return max(math.sqrt(max(geo.big_a ** 2 - el.radial_offset ** 2, 0.0)) - el.axial_offset, 0.0)


def misalignment_limit(bearing):
    """The tilt of a self-aligning bearing's inner ring at which a ball's contact reaches the side of the
    outer ring: its row's contact on the sphere (radius R_o = f_o D, at alpha0 from the centre plane) moves
    to alpha0 + theta, so theta_max = arcsin(B / (2 R_o)) - alpha0 (B the outer ring's width, chamfers
    left out: an upper bound of what the maker permits); None without the width. [rad]"""
    if bearing.type != "self-aligning" or bearing.width is None or bearing.outer_conformity is None:
        return None
    big_r = bearing.outer_conformity * bearing.require("ball_diameter")
    return math.asin(min(0.5 * bearing.width / big_r, 1.0)) - bearing.require("contact_angle")


def misalignment_note(bearing, tilt):
    """The warning of a self-aligning bearing tilted beyond :func:`misalignment_limit` (``tilt`` (..., 2):
    theta_x, theta_y [rad]), or None."""
    limit = misalignment_limit(bearing)
    if limit is None:
        return None
    angle = np.hypot(np.asarray(tilt)[..., 0], np.asarray(tilt)[..., 1])
    over = angle > limit
    if not np.any(over):
        return None
    return (f"misalignment: the inner ring is tilted by up to {math.degrees(float(np.nanmax(angle))):.3g} deg, beyond "
            f"the {math.degrees(limit):.3g} deg at which a ball's contact reaches the side of the outer ring (its "
            "sphere ends at the ring's width); the balls would run off the raceway")


def bearing_options(bearing):
    """``radial_clearance`` and ``row_distance`` of :func:`bearinglab.quasistatic.combined.load_distribution`
    for a BallBearing of these types; a field the model needs and the bearing lacks raises InputError
    naming it (one line)."""
    kind = bearing.type
    out = {}
    label = bearing.designation or "this bearing"
    if kind in _BUILT_IN:
        bearing.require("contact_angle")
        if bearing.radial_clearance is None:
            raise InputError(f"radial_clearance of {label!r} is not known; give its diametral clearance (catalog "
                             "entry, file or --radial-clearance; 0 for none, negative for a preload): the model of a "
                             f"{kind} bearing needs it apart from its nominal angle")
        out["radial_clearance"] = float(bearing.radial_clearance)
    elif kind == "double-row-radial":  # a deep-groove row: its free angle says it all, but for a preload
        e = bearing.radial_clearance
        out["radial_clearance"] = float(e) if e is not None and e <= 0 else None
    elif kind == "thrust":
        bearing.require("contact_angle")
    if kind in ("double-row-angular", "double-row-radial"):
        if bearing.row_distance is None:
            raise InputError(f"row_distance of {label!r} is not known; give the axial distance between the ball "
                             "centres of its two rows (catalog entry or bearing file: row_distance = '...mm')")
        out["row_distance"] = float(bearing.row_distance)
    return out
