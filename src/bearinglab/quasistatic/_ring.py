r"""Numerical kernels of the ring Newton of :mod:`bearinglab.quasistatic.combined` (private).

Linear algebra
--------------
rowwise           a @ b with every row rounded as in any other batch (BLAS takes another path for one row)
solve5            batched 5 x 5 linear systems by Gaussian elimination on contiguous columns
lm_step           the Levenberg-Marquardt step of the ring Newton in scaled variables
hold              its stiffness with prescribed freedoms held (no equation, no step)

Start
-----
thrust_offset     axial groove-centre offset at which Z balls at one angle carry a given axial load

The ring Newton solves thousands of 5 x 5 systems per iteration. :func:`numpy.linalg.solve` calls LAPACK
once per system, which costs more than the elimination itself at this size; :func:`solve5` eliminates
all systems together, one column at a time, and hands the rare system whose pivot is tiny (a ring held
by fewer than three balls, kept regular only by the damping floor) to LAPACK with partial pivoting.
Every system is solved from its own row alone, so results do not depend on the batch.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["hold", "lm_step", "rowwise", "solve5", "thrust_offset"]

_PIVOT = 1e-10  # a pivot below this fraction of the largest diagonal entry goes to LAPACK (partial pivoting)
_START_ITER = 5  # Newton steps of the thrust offset (a start only; see thrust_offset)


def rowwise(a, b):
    """a (n, k) @ b (k, m), each row's result independent of the other rows.

    BLAS computes a single row as a matrix-vector product, which rounds differently from the same row in
    a matrix-matrix product; a single row is therefore doubled. Batches of two rows or more round every
    row alike, so a case's result does not depend on how many cases share its iteration.
    """
    if a.shape[0] == 1:
        return (np.concatenate([a, a]) @ b)[:1]
    return a @ b


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

    All balls at one angle: rho = hypot(z, A cos alpha0), P = K_n (rho - A)^1.5 z / rho. Newton on
    P^(2/3) = K_n^(2/3) (rho - A) (z / rho)^(2/3), which is close to linear in z. The root lies between
    the zero-clearance estimate (rho - A = z^2 / 2A) and the small-deflection one (rho - A = s0 (z - z0),
    z / rho = s0, s0 = sin alpha0); the Newton starts from the smaller of the latter and twice the former,
    kept to the right of first contact z0 = A sin alpha0. A start only:
    ``_START_ITER`` steps reach 1e-8 relative (as the bisection they replaced).
    """
    g = radial_offset
    z0 = big_a * math.sin(free_angle)
    k23 = kn0 ** (2.0 / 3.0)
    target = np.cbrt(per_ball) ** 2
    s0 = math.sin(free_angle)
    z_zero = np.sqrt(np.sqrt(per_ball / kn0 * (2.0 * big_a) ** 1.5 * big_a))  # alpha0 = 0: rho - A = z^2 / 2A
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
