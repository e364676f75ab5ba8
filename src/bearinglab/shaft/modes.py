r"""Natural frequencies of a shaft system: bending modes at the operating point, gyroscopic at speed.

Modes
-----
Modes           frequencies, whirl, kind and shapes of the lowest bending modes
natural_modes   the modes of a solved system, each bearing linearised at its operating point
campbell        the bending frequencies over a list of speeds (each speed solved for its own operating point)

The system is linearised at the solution of :func:`bearinglab.shaft.solve`: the shaft's Timoshenko
elements with their consistent mass, rotary inertia and gyroscopic matrices
(:mod:`bearinglab.shaft.elements`), the rigid masses of gears, pulleys and masses, the linear supports,
and each bearing's 5 x 5 tangent stiffness at its operating point, in series with its housing springs
(:func:`bearinglab.shaft.outputs.system_stiffness`). The rigid supports' freedoms are held. Torsion has
no coupling to bending here (the bearings carry no torque) and is left out, with it the rigid rotation;
axial modes couple to bending through the angular-contact bearings and are computed with them, then
told apart by where their kinetic energy lies (``kind``), as are rigid-body modes (a frequency below
1e-6 of the highest) of a shaft that some freedom does not hold.

At rest the modes solve K phi = omega^2 M phi. At speed Omega the equations M q'' + Omega G q' + K q = 0
(G skew-symmetric, K of the bearings possibly unsymmetric at speed) are solved in first-order form,
[[0, I], [-M^-1 K, -Omega M^-1 G]] v = lambda v, lambda = i omega; a mode whirls forward when its
orbits turn with the shaft, backward otherwise. The housings are massless. No damping: the bearings'
quasi-static model has none.

References
----------
.. [1] M. I. Friswell, J. E. T. Penny, S. D. Garvey and A. W. Lees, *Dynamics of Rotating Machines*,
   Cambridge University Press, 2010, sections 3.6 (forward and backward whirl), 6.2 (the first-order
   form) and 6.6 (the Campbell diagram).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import scipy.linalg

from .._validate import check_integer
from ..errors import InputError
from .outputs import system_stiffness
from .statics import load_cases, solve

__all__ = ["Campbell", "Modes", "campbell", "natural_modes"]

_RIGID = 1e-6  # a frequency below this fraction of the highest is a rigid-body mode
_MAX_MODES = 50


class Modes(NamedTuple):
    """The lowest bending modes of one operating point."""

    speed: float
    """Shaft speed. [rad/s]"""
    frequency: np.ndarray
    """(k,) natural frequencies, lowest first. [Hz]"""
    whirl: tuple
    """(k,) "forward", "backward" or "" (at rest: a planar mode)."""
    z: np.ndarray
    """(n_nodes,) node positions. [m]"""
    shape: np.ndarray
    """(k, n_nodes, 2) displacements u_x, u_y of each mode (the orbit's major axis at the phase of the
    largest amplitude), scaled to a largest amplitude of 1. [-]"""
    axial: tuple
    """Frequencies of the axial modes below the highest bending mode reported, left out of
    ``frequency``. [Hz]"""
    rigid: int
    """How many rigid-body modes were found and left out."""


def _reduced(state, case):
    """K, M, G of the lateral and axial freedoms (torsion and held freedoms out), and the kept dofs."""
    asm = state.assembly
    k, held = system_stiffness(state, case)
    n = k.shape[0]
    keep = np.setdiff1d(np.arange(n), np.concatenate([held, np.arange(5, n, 6)]))
    ix = np.ix_(keep, keep)
    return k[ix], asm.mesh.mass[ix], asm.mesh.gyroscopic[ix], keep


def natural_modes(state, count=6, *, case=0):
    r"""The lowest bending natural frequencies and mode shapes of a solved system.

    Parameters
    ----------
    state : SystemState
        The operating point (:func:`bearinglab.shaft.solve`); its case's speed sets the gyroscopic terms.
    count : int, optional
        How many bending modes, 1 ... 50.
    case : int, optional
        The load case.

    Returns
    -------
    Modes

    Examples
    --------
    >>> from bearinglab.shaft.model import RigidSupport, Section, Shaft, ShaftSystem
    >>> s = ShaftSystem(Shaft((Section(1.0, 0.02),)), (RigidSupport("A", 0.0, axial=True),
    ...                 RigidSupport("B", 1.0)), elements=20)
    >>> m = natural_modes(solve(s), 2)
    >>> print(np.round(m.frequency, 2))
    [40.36 40.36]
    """
    count = int(check_integer("count", count, 1))
    if count > _MAX_MODES:
        raise InputError(f"modes must be <= {_MAX_MODES}, got {count}")
    if not 0 <= case < len(state.cases.speed):
        raise InputError(f"case must be in 0 ... {len(state.cases.speed) - 1}, got {case}")
    if not np.all(np.isfinite(state.row_stiffness[case])):
        raise InputError(f"case {case} did not converge: it has no operating point to linearise")
    omega = float(state.cases.speed[case])
    k, m, g, keep = _reduced(state, case)
    size = len(keep)
    if omega == 0.0 and np.allclose(k, k.T, rtol=0, atol=1e-9 * np.max(np.abs(k))):
        lam, vec = scipy.linalg.eigh(0.5 * (k + k.T), m)
        w = np.sqrt(np.abs(lam)) * np.sign(lam)
        vecs = vec.T.astype(complex)
    else:
        chol = scipy.linalg.cho_factor(m, lower=True, check_finite=False)
        a = np.block([[np.zeros((size, size)), np.eye(size)],
                      [-scipy.linalg.cho_solve(chol, k, check_finite=False),
                       -omega * scipy.linalg.cho_solve(chol, g, check_finite=False)]])
        from threadpoolctl import threadpool_limits

        with threadpool_limits(limits=1, user_api="blas"):  # a few hundred rows: threads only contend
            lam, vec = scipy.linalg.eig(a, check_finite=False)
        pos = np.isfinite(lam) & (lam.imag > -1e-9 * np.max(np.abs(lam[np.isfinite(lam)])))
        lam, vec = lam[pos], vec[:size, pos]
        order = np.argsort(np.abs(lam.imag))
        lam, vec = lam[order], vec[:, order]
        w = lam.imag
        vecs = vec.T
    top = np.max(np.abs(w)) if w.size else 1.0
    nodes = len(state.assembly.mesh.z)
    full = np.zeros((len(w), 6 * nodes), dtype=complex)
    full[:, keep] = vecs
    u = full.reshape(len(w), nodes, 6)
    freqs, whirl, shapes, axial, rigid = [], [], [], [], 0
    diag_m = np.diag(m)
    for i in range(len(w)):
        if abs(w[i]) < _RIGID * top:
            rigid += 1
            continue
        v = vecs[i]
        energy = diag_m * np.abs(v) ** 2
        kind_axial = keep % 6 == 2
        if len(freqs) == count:
            break
        if energy[kind_axial].sum() > 0.5 * energy.sum():
            axial.append(float(w[i]) / (2 * np.pi))
            continue
        ux, uy = u[i, :, 0], u[i, :, 1]
        if omega == 0.0:
            spin = ""
        else:  # the orbit's sense: x y' - y x' = -omega Im(conj(x) y) summed over the nodes
            h = -np.sum(np.imag(np.conj(ux) * uy))
            spin = "forward" if h * np.sign(omega) > 0 else "backward"
        big = np.argmax(np.abs(np.concatenate([ux, uy])))
        ref = np.concatenate([ux, uy])[big]
        phase = np.exp(-1j * np.angle(ref)) if abs(ref) > 0 else 1.0
        shp = np.stack([np.real(ux * phase), np.real(uy * phase)], axis=-1)
        peak = np.max(np.abs(shp))
        shapes.append(shp / peak if peak > 0 else shp)
        freqs.append(float(w[i]) / (2 * np.pi))
        whirl.append(spin)
    return Modes(omega, np.array(freqs), tuple(whirl), state.assembly.mesh.z.copy(),
                 np.array(shapes).reshape(len(freqs), nodes, 2), tuple(axial), rigid)


class Campbell(NamedTuple):
    """Bending frequencies over speeds."""

    speed: np.ndarray
    """(s,) [rad/s]"""
    frequency: np.ndarray
    """(s, k) the k lowest bending frequencies at each speed (NaN where fewer were found). [Hz]"""
    whirl: tuple
    """(s,) tuples of "forward" / "backward" / ""."""


def campbell(system, speeds, count=6, **options):
    """The lowest bending frequencies of a system over a list of speeds: a Campbell diagram.

    Parameters
    ----------
    system : ShaftSystem
    speeds : array_like
        (s,) signed shaft speeds. [rad/s]
    count : int, optional
        Modes per speed.
    **options
        Passed to :func:`bearinglab.shaft.solve` (``tol``, ``max_iter``).

    Returns
    -------
    Campbell

    Notes
    -----
    Every speed is its own operating point, solved in one batch: the bearings' stiffness changes with
    speed (centrifugal forces and gyroscopic moments of the balls, :mod:`bearinglab.reactions`) and the
    shaft's gyroscopic terms with it. Power-given gears take their torque at each speed. The bearings'
    clearances follow the mounting chain at the system's own speed only.
    """
    w = np.atleast_1d(np.asarray(speeds, dtype=float))
    if w.ndim != 1 or not w.size or not np.all(np.isfinite(w)):
        raise InputError("speeds must be a list of finite speeds [rad/s]")
    if w.size > 200:
        raise InputError(f"speeds: at most 200 in a Campbell diagram, got {w.size}")
    state = solve(system, load_cases(system, speed=w), **options)
    freq = np.full((w.size, count), np.nan)
    whirl = []
    for c in range(w.size):
        m = natural_modes(state, count, case=c)
        freq[c, :m.frequency.size] = m.frequency
        whirl.append(m.whirl)
    return Campbell(w, freq, tuple(whirl))
