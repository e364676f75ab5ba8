r"""Numerical kernels of the ring Newton of :mod:`bearinglab.quasistatic.combined` (private).

Ball set
--------
azimuths          psi_j = phi0 + 2 pi j / Z of the balls or rollers (checked Z and phi0)
offsets           groove-centre offsets (axial, radial) of every ball for ring displacements
ballsum           a sum over the balls, case by case
reaction          the ring load of the ball reactions, sum_j J_j^T p_j
assemble          the ring stiffness of the balls' 2 x 2 stiffnesses, sum_j J_j^T H_j J_j

Linear algebra
--------------
solve5            batched 5 x 5 linear systems by Gaussian elimination on contiguous columns
lm_step           the Levenberg-Marquardt step of the ring Newton in scaled variables
damp              its damping after a line search: lower after a full step, higher after none
hold              its stiffness with prescribed freedoms held (no equation, no step)

Start
-----
thrust_offset     axial groove-centre offset at which Z balls at one angle carry a given axial load

The ring Newton solves thousands of 5 x 5 systems per iteration. :func:`numpy.linalg.solve` calls LAPACK
once per system, which costs more than the elimination itself at this size; :func:`solve5` eliminates
all systems together, one column at a time, and hands the rare system whose pivot is tiny (a ring held
by fewer than three balls, kept regular only by the damping floor) to LAPACK with partial pivoting.
Every system is solved from its own row alone, so results do not depend on the batch.

Bit-identity for any batch: BLAS rounds a row of a matrix product differently with the number of rows
(its kernels treat the last rows of an odd block apart: the same row in batches of 2 and 3 differs in
the last bit on an AVX-512 host), and ``einsum`` fuses multiply-adds in its vector body but not in its
tail. So the sums over the balls are written as elementwise products added ball after ball (each case's
sum in one order whatever the batch), never as a matrix product.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["assemble", "ballsum", "hold", "lm_step", "offsets", "reaction", "solve5", "thrust_offset"]

_PIVOT = 1e-10  # a pivot below this fraction of the largest diagonal entry goes to LAPACK (partial pivoting)
_START_ITER = 5  # Newton steps of the thrust offset (a start only; see thrust_offset)


def azimuths(z, phi0):
    """psi_j = phi0 + 2 pi j / Z for checked Z and phi0: the balls' and the rollers' alike [rad]."""
    return phi0 + 2.0 * np.pi * np.arange(z) / z


def offsets(geo, u):
    """Axial and radial groove-centre offsets (n, Z) of every ball for displacements u (n, 5) (Harris and
    Kotzalas ch. 1, the pitch radius as arm; see :func:`bearinglab.quasistatic.combined.groove_offsets`):
    A_z = delta_z + (d_m/2)(theta_x sin psi - theta_y cos psi), A_r = g_0 + delta_x cos psi + delta_y sin psi."""
    c, s, arm = geo.cos_psi, geo.sin_psi, geo.dm / 2.0
    ga = u[:, 2:3] + arm * (u[:, 3:4] * s - u[:, 4:5] * c)
    gr = geo.gr0 + (u[:, 0:1] * c + u[:, 1:2] * s)
    return ga, gr


def _sum(h, weights):
    """sum_j h[n, j] w[k, j] -> (n, k), the balls added one after the other (elementwise over the cases, so
    in one order whatever the batch; numpy's reduction along a short axis costs a call per row).

    The sums run along (k, n) rows, the cases contiguous: a (n, 1) x (k,) product with k of 3 to 28 strides
    through memory and cost 1.3-4 times more (the same products added in the same order: the same bits)."""
    z = h.shape[-1]
    ht = np.ascontiguousarray(np.transpose(h))  # (Z, n)
    cols = weights.T[:, :, None]  # (Z, k, 1)
    acc = cols[0] * ht[0]
    tmp = np.empty_like(acc)
    for j in range(1, z):
        np.multiply(cols[j], ht[j], out=tmp)
        acc += tmp
    return np.transpose(acc)


def rowwise(a, b):
    """a (n, k) @ b (k, m), each row's result independent of the other rows: the k terms added one after the
    other, elementwise over the rows (BLAS rounds a row of a 3-row product differently from the same row
    alone), so a case gives the same bits in any batch. For the roller slice model's narrow products."""
    return _sum(a, np.ascontiguousarray(np.transpose(b)))


def ballsum(a):
    """sum_j a[n, j] -> (n,), the balls added one after the other (as :func:`_sum`)."""
    acc = a[:, 0].copy()
    for j in range(1, a.shape[-1]):
        acc += a[:, j]
    return acc


def reaction(geo, pa, pr):
    """Ring load (n, 5) in equilibrium with ball reactions (axial ``pa``, radial ``pr``, each (n, Z)):
    F = sum_j J_j^T (pa_j, pr_j)."""
    arm = geo.dm / 2.0
    r = _sum(pr, geo.weights[0])  # sum pr c, sum pr s
    a = _sum(pa, geo.weights[1])  # sum pa, sum pa s, sum pa c
    return np.stack([r[:, 0], r[:, 1], a[:, 0], arm * a[:, 1], -arm * a[:, 2]], axis=1)


def assemble(geo, h00, h01, h10, h11):
    """Ring stiffness (n, 5, 5) sum_j J_j^T H_j J_j from the 2 x 2 ball stiffnesses H_j (axial, radial)
    given by their entries, each (n, Z); J_j has the rows (0, 0, 1, a s, -a c) and (c, s, 0, 0, 0)."""
    arm = geo.dm / 2.0
    aa = _sum(h00, geo.weights[2])  # 1, s, c, ss, sc, cc
    ar = _sum(h01, geo.weights[3])  # c, s, sc, ss, cc
    ra = _sum(h10, geo.weights[3])
    rr = _sum(h11, geo.weights[4])  # cc, cs, ss
    k = np.empty((len(aa), 5, 5))
    k[:, 0, 0], k[:, 0, 1], k[:, 1, 0], k[:, 1, 1] = rr[:, 0], rr[:, 1], rr[:, 1], rr[:, 2]
    k[:, 2, 2], k[:, 2, 3], k[:, 2, 4] = aa[:, 0], arm * aa[:, 1], -arm * aa[:, 2]
    k[:, 3, 2], k[:, 4, 2] = k[:, 2, 3], k[:, 2, 4]
    a2 = arm * arm
    k[:, 3, 3], k[:, 3, 4], k[:, 4, 3], k[:, 4, 4] = a2 * aa[:, 3], -a2 * aa[:, 4], -a2 * aa[:, 4], a2 * aa[:, 5]
    k[:, 2, 0], k[:, 2, 1] = ar[:, 0], ar[:, 1]
    k[:, 3, 0], k[:, 3, 1], k[:, 4, 0], k[:, 4, 1] = arm * ar[:, 2], arm * ar[:, 3], -arm * ar[:, 4], -arm * ar[:, 2]
    k[:, 0, 2], k[:, 1, 2] = ra[:, 0], ra[:, 1]
    k[:, 0, 3], k[:, 1, 3], k[:, 0, 4], k[:, 1, 4] = arm * ra[:, 2], arm * ra[:, 3], -arm * ra[:, 4], -arm * ra[:, 2]
    return k


def weights(psi):
    """The trigonometric weights of :func:`reaction` and :func:`assemble` for the azimuths psi (Z,)."""
    c, s = np.cos(psi), np.sin(psi)
    one = np.ones_like(psi)

    def rows(*w):
        return np.ascontiguousarray(np.stack(w))

    return (rows(c, s), rows(one, s, c), rows(one, s, c, s * s, s * c, c * c), rows(c, s, s * c, s * s, c * c),
            rows(c * c, c * s, s * s))


def solve5(a, b, shift=None):
    """Solve (a + shift I) x = b for stacks of 5 x 5 systems, a (n, 5, 5), b (n, 5), shift (n,); x (n, 5).

    Gaussian elimination without pivoting, vectorised over the systems; a system with a pivot below
    ``_PIVOT`` times its largest diagonal entry, or a non-finite result, is solved again by
    :func:`numpy.linalg.solve` (LU with partial pivoting).
    """
    return _eliminate([[a[:, i, j].copy() for j in range(5)] for i in range(5)], b, shift, a.__getitem__)


def _eliminate(m, b, shift, matrices):
    """:func:`solve5` on the columns ``m[i][j]`` (contiguous copies of a[:, i, j], overwritten);
    ``matrices(rows)`` gives the (k, 5, 5) matrices of the rows that go to LAPACK."""
    if shift is not None:
        for i in range(5):
            m[i][i] += shift
    r = [b[:, i].copy() for i in range(5)]
    scale = np.abs(m[0][0])
    for i in range(1, 5):
        scale = np.maximum(scale, np.abs(m[i][i]))
    weak = np.zeros(len(b), dtype=bool)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):  # such systems go to LAPACK below
        for k in range(5):
            weak |= ~(np.abs(m[k][k]) > _PIVOT * scale)
            inv = 1.0 / m[k][k]
            for i in range(k + 1, 5):
                f = m[i][k] * inv
                for j in range(k + 1, 5):
                    m[i][j] -= f * m[k][j]
                r[i] -= f * r[k]
        x = [None] * 5
        for k in range(4, -1, -1):
            s = r[k]
            for j in range(k + 1, 5):
                s = s - m[k][j] * x[j]
            x[k] = s / m[k][k]
    out = np.stack(x, axis=1)
    weak |= ~np.all(np.isfinite(out), axis=1)
    if weak.any():
        aw = matrices(weak) + (0.0 if shift is None else shift[weak][:, None, None] * np.eye(5))
        out[weak] = np.linalg.solve(aw, b[weak][:, :, None])[:, :, 0]
    return out


def lm_step(stiff, residual, lam, dm):
    """Levenberg-Marquardt step (K + lam max|diag K| I) du = r in scaled variables (lam = 0: Newton).

    Moments and tilts are scaled by the pitch radius d_m/2. A K that is singular (fewer than three
    balls loaded, or none) gets a floor of 1e-14 max|diag K|.
    """
    sc = [1.0, 1.0, 1.0, 2.0 / dm, 2.0 / dm]
    m = [[stiff[:, i, j] * (sc[i] * sc[j]) for j in range(5)] for i in range(5)]  # scaled columns
    diag = np.abs(m[0][0])
    for i in range(1, 5):
        diag = np.maximum(diag, np.abs(m[i][i]))
    diag = np.where(diag > 0, diag, 1.0)
    sv = np.array(sc)
    return _eliminate(m, residual * sv, np.maximum(lam, 1e-14) * diag,
                      lambda rows: stiff[rows] * (sv[:, None] * sv[None, :])) * sv


def thrust_offset(per_ball, big_a, free_angle, radial_offset, kn0):
    """Axial offset z of the groove-curvature centres at which each ball carries ``per_ball`` axially.

    All balls at one angle: rho = hypot(z, g), P = K_n (rho - A)^1.5 z / rho. Newton on
    P^(2/3) = K_n^(2/3) (rho - A) (z / rho)^(2/3), which is close to linear in z. With clearance (g < A)
    the root lies between the zero-clearance estimate (rho - A = z^2 / 2A) and the small-deflection one
    (rho - A = s0 (z - z0), z / rho = s0, s0 = sin alpha0); the Newton starts from the smaller of the
    latter and twice the former, kept to the right of first contact z0 = A sin alpha0. Preloaded (g > A,
    every ball compressed by g - A at z = 0): from the smaller of twice the zero-clearance estimate and
    the linear one, P = Q_0 z / g with Q_0 = K_n (g - A)^1.5. A start only: ``_START_ITER`` steps reach
    1e-8 relative (as the bisection they replaced).
    """
    g = radial_offset
    pre = g > big_a
    z0 = 0.0 if pre else big_a * math.sin(free_angle)
    k23 = kn0 ** (2.0 / 3.0)
    target = np.cbrt(per_ball) ** 2
    s0 = math.sin(free_angle)
    z_zero = np.sqrt(np.sqrt(per_ball / kn0 * (2.0 * big_a) ** 1.5 * big_a))  # alpha0 = 0: rho - A = z^2 / 2A
    if pre:  # P = Q_0 z / g for small z
        z_lin = per_ball * g / (kn0 * (g - big_a) ** 1.5)
    else:
        with np.errstate(divide="ignore"):  # rho - A >= s0 (z - z0) and z / rho >= s0: the root is below z_lin
            z_lin = z0 + target / (k23 * s0 ** (5.0 / 3.0)) if s0 > 0 else np.full_like(z_zero, np.inf)
    z = np.maximum(np.minimum(z_lin, 2.0 * z_zero), z0 + 1e-9 * big_a)
    for _ in range(_START_ITER):
        rho = np.hypot(z, g)
        s = z / rho
        c13 = np.cbrt(s)
        h = k23 * (rho - big_a) * c13 * c13 - target
        dh = k23 * (s * c13 * c13 + (rho - big_a) * (2.0 / 3.0) * g * g / rho**3 / c13)
        z = np.maximum(z - h / dh, 0.5 * (z + z0))  # never back past first contact
    return np.where(per_ball > 0, z, 0.0)


def damp(lam, act, full, pending):
    """Update in place the damping ``lam`` of the active cases ``act`` after their line search: a full step
    lowers it tenfold, a shortened one keeps it, none at all raises it a hundredfold (at least to 1e-3); below
    1e-12 it is 0 (the undamped Newton step). ``full`` is per active case, ``pending`` indexes ``act``."""
    lam[act] = np.where(full, 0.1 * lam[act], lam[act])
    lam[act[pending]] = np.maximum(100.0 * lam[act[pending]], 1e-3)  # no decrease at all
    lam[lam < 1e-12] = 0.0


def hold(stiff, free):
    """The stiffness of the ring Newton with prescribed (held) freedoms: their rows and columns zeroed
    and their diagonal kept (or the largest diagonal entry where it is zero), so that with a zero
    right-hand side on those rows the step leaves them exactly where they are (issue 20 item 18).

    ``stiff`` (n, 5, 5), ``free`` (n, 5) of 1.0 (free) or 0.0 (held).
    """
    k = stiff * free[:, :, None] * free[:, None, :]
    diag = np.abs(np.diagonal(stiff, axis1=1, axis2=2))
    big = np.max(diag, axis=1, keepdims=True)
    fill = np.where(diag > 0, diag, np.where(big > 0, big, 1.0))
    idx = np.arange(5)
    k[:, idx, idx] = np.where(free > 0, k[:, idx, idx], fill)
    return k
