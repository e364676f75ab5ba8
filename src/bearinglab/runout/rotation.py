r"""Rotation of the inner ring (spec 003 section 10): the centre trajectory, its runout and spectrum.

Trajectory and runout
---------------------
rotation_sequence       the centre trajectory over revolutions, all positions in one batch
runout_metrics          radial peak-to-peak in x, y and over all directions, axial peak-to-peak, mean dz
synchronous_part        average at equal rotation angle over the revolutions
METRICS                 the names of the runout metrics (fields of RunoutMetrics)

Spectrum
--------
runout_spectrum         spectrum of the radial (forward/backward whirl) and axial motion, in orders
spectrum_lines          the spectral lines, labelled as cage, ring or combination lines

Units: SI (m, rad).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from .._solve import RUNOUT_REFINE_MAX_ITER, RUNOUT_REFINE_TOL, use_compiled
from .._validate import check_finite, check_integer, check_open_interval
from ..errors import InputError
from .contact import Displacement, initial_displacement

__all__ = [
    "METRICS",
    "RunoutMetrics",
    "Spectrum",
    "SpectrumLine",
    "Trajectory",
    "rotation_sequence",
    "runout_metrics",
    "runout_spectrum",
    "spectrum_lines",
    "synchronous_part",
]

METRICS = ("radial_ptp_x", "radial_ptp_y", "radial_ptp_max", "axial_ptp", "dz_mean")


class RunoutMetrics(NamedTuple):
    """Runout metrics of a trajectory (section 10) [m]; arrays when computed per sample."""

    radial_ptp_x: np.ndarray  # max dx - min dx
    radial_ptp_y: np.ndarray  # max dy - min dy
    radial_ptp_max: np.ndarray  # largest peak-to-peak over all radial directions (set diameter)
    axial_ptp: np.ndarray  # max dz - min dz
    dz_mean: np.ndarray  # mean dz


def _farthest_pair(px, py, idx):
    """Largest distance between the points ``idx`` (pairs of index arrays ``(a, b)``) of one set."""
    a, b = idx
    return math.sqrt(float(np.max((px[a] - px[b]) ** 2 + (py[a] - py[b]) ** 2)))


def _antipodal_pairs(vx, vy):
    """Candidate farthest pairs of a convex polygon with vertices in counterclockwise order.

    Rotating calipers [1]_: a farthest pair is antipodal, and each antipodal pair is an end of an edge
    together with the vertex farthest from that edge's line. Round a convex polygon the edge
    directions turn monotonically, so that vertex is where the direction has turned by pi (a sorted
    search for all edges at once); its two neighbours are kept too, against rounding and parallel
    edges. O(h) pairs for h vertices.

    .. [1] M. I. Shamos, "Computational geometry," PhD thesis, Yale University, 1978, ch. 4.
    """
    h = vx.size
    i = np.arange(h)
    turn = np.arctan2(np.roll(vy, -1) - vy, np.roll(vx, -1) - vx)
    turn = np.maximum.accumulate(np.mod(turn - turn[0], 2 * np.pi))  # rounding must not un-sort it
    j = np.searchsorted(
        turn, np.mod(turn + np.pi, 2 * np.pi)
    )  # the edge turned by pi, round the end
    ends = np.concatenate([i, (i + 1) % h] * 3)
    far = np.concatenate([(j + k) % h for k in (-1, 0, 1) for _ in range(2)])
    return ends, far


def _diameter_of_points(px, py):
    """Largest distance between two of the points (px, py) (1-D): the diameter of their convex hull."""
    from scipy.spatial import ConvexHull, QhullError

    n = px.size
    if n <= 8:  # few points: all pairs
        return _farthest_pair(px, py, np.triu_indices(n, 1)) if n > 1 else 0.0
    span = max(float(np.ptp(px)), float(np.ptp(py)))
    if span == 0.0:
        return 0.0
    # the hull is found on scaled copies (qhull's tolerances are relative); distances use the inputs
    pts = np.column_stack([(px - px.min()) / span, (py - py.min()) / span])
    try:
        v = ConvexHull(pts).vertices  # counterclockwise in 2-D
    except QhullError:  # (nearly) collinear: the farthest pair are extremes along some direction
        ext = np.unique([f(w) for w in (px, py, px + py, px - py) for f in (np.argmin, np.argmax)])
        return _farthest_pair(px[ext], py[ext], np.triu_indices(ext.size, 1))
    return _farthest_pair(px[v], py[v], _antipodal_pairs(px[v], py[v]))


def _diameter(x, y, engine="numpy"):
    """Largest distance between two points of each trajectory (its radial peak-to-peak over all
    directions), by the convex hull: memory O(N), time O(N log N). x, y: (S, N) -> (S,)."""
    if engine == "compiled":
        from . import _compiled  # imports numba: only when the compiled path runs

        return _compiled.diameters(x, y)
    # one hull per trajectory: a loop over trajectories (each one vectorized), as qhull takes one set
    return np.array([_diameter_of_points(px, py) for px, py in zip(x, y)], dtype=float)


def runout_metrics(x, y, z, *, engine="auto"):
    """Runout metrics of centre trajectories (spec 003 section 10).

    Parameters
    ----------
    x, y, z : array_like
        dx, dy, dz along the last axis (positions); leading axes are independent trajectories. [m]
    engine : {"auto", "numpy", "compiled"}
        Who finds the largest distance: qhull's hull and numpy's rotating calipers, or a compiled monotone
        chain and rotating calipers (``"auto"``: compiled when numba is installed). Both take the square
        root of the largest dx^2 + dy^2 of an antipodal pair, so they agree to the bit unless rounding
        decides which of two nearly collinear hull points is kept.

    Returns
    -------
    RunoutMetrics
        radial_ptp_x, radial_ptp_y, radial_ptp_max (the largest distance between two trajectory
        points), axial_ptp, dz_mean. [m]

    Examples
    --------
    >>> t = np.linspace(0, 2 * np.pi, 6, endpoint=False)
    >>> m = runout_metrics(np.cos(t), np.sin(t), 0 * t)
    >>> print(f"{m.radial_ptp_x:.6f} {m.radial_ptp_y:.6f} {m.radial_ptp_max:.6f}")
    2.000000 1.732051 2.000000
    """
    x = np.atleast_1d(check_finite("x", x, "m"))
    y = np.atleast_1d(check_finite("y", y, "m"))
    z = np.atleast_1d(check_finite("z", z, "m"))
    engine = "compiled" if use_compiled(engine, auto=True) else "numpy"
    x, y, z = np.broadcast_arrays(x, y, z)
    lead = x.shape[:-1]
    n = x.shape[-1]
    diam = _diameter(x.reshape(-1, n), y.reshape(-1, n), engine).reshape(lead)
    return RunoutMetrics(
        np.ptp(x, axis=-1)[()],
        np.ptp(y, axis=-1)[()],
        diam[()],
        np.ptp(z, axis=-1)[()],
        z.mean(axis=-1)[()],
    )


def synchronous_part(values, steps_per_revolution):
    """Synchronous part of a signal sampled at equal steps over whole revolutions.

    Parameters
    ----------
    values : array_like
        Samples along the last axis, a whole number of revolutions long.
    steps_per_revolution : int
        Samples per revolution. [-]

    Returns
    -------
    ndarray
        The average at equal psi mod 2 pi over the revolutions, repeated to the input length; the
        asynchronous part is ``values - synchronous_part(values, ...)``.

    Examples
    --------
    >>> synchronous_part([1.0, 2.0, 3.0, 6.0], 2)
    array([2., 4., 2., 4.])
    """
    v = np.atleast_1d(check_finite("values", values, "-"))
    m = int(check_integer("steps_per_revolution", steps_per_revolution, 1))
    if v.shape[-1] % m:
        raise InputError(
            f"values must hold whole revolutions: {v.shape[-1]} samples is not a multiple of "
            f"steps_per_revolution = {m}"
        )
    revs = v.shape[-1] // m
    mean = v.reshape(v.shape[:-1] + (revs, m)).mean(axis=-2)
    return np.tile(mean, (1,) * (v.ndim - 1) + (revs,))


class Trajectory(NamedTuple):
    """Centre trajectory over a rotation sequence and its runout (spec 003 section 10)."""

    rotation_angle: np.ndarray  # psi_k [rad]
    displacement: Displacement  # all positions
    metrics: RunoutMetrics  # of the whole motion [m]
    synchronous: RunoutMetrics  # of the synchronous part [m]
    asynchronous: RunoutMetrics  # of the asynchronous part [m]
    steps_per_revolution: int
    revolutions: int
    cage_ratio: float  # kappa used [-]
    degenerate_fraction: float  # share of positions with a degenerate face [-]


def rotation_sequence(
    geometry,
    errors,
    *,
    revolutions=3,
    steps_per_revolution=360,
    start_angle=0.0,
    cage_ratio=None,
    refine=False,
    method="dual",
    tie_break="centre",
    tol=RUNOUT_REFINE_TOL,
    max_iter=RUNOUT_REFINE_MAX_ITER,
    raise_on_failure=False,
    engine="auto",
):
    r"""Centre trajectory over inner-ring revolutions with cage kinematics, and its runout (section 10).

    Parameters
    ----------
    geometry : SpindleGeometry
        Nominal geometry.
    errors : ManufacturingErrors
        Raceway, ball and tilt errors.
    revolutions : int
        Number of inner-ring revolutions N_revs. [-]
    steps_per_revolution : int
        N_steps. [-]
    start_angle : float
        psi_start. [rad]
    cage_ratio : float, optional
        kappa override. [-]
    refine : bool
        Refine every position (section 9).
    method, tie_break : str
        As for :func:`solve_contact`.
    tol, max_iter : float, int
        Refinement tolerance [m] and passes [-].
    raise_on_failure : bool
        Raise when a refined position does not converge (default: flag it in ``displacement.converged``).
    engine : {"auto", "numpy", "compiled"}
        As for :func:`~bearinglab.runout.initial_displacement` (compiled when numba is installed).

    Returns
    -------
    Trajectory

    Notes
    -----
    psi_k = psi_start + 2 pi k / N_steps, k = 0 .. N_steps N_revs - 1; all positions are solved as one
    batch. Ball features repeat with the cage (period 2 pi / kappa in psi), inner-ring features every
    2 pi; the synchronous part is the average at equal psi mod 2 pi.

    Examples
    --------
    Spec 003 example 1 (ball 1 oversize by 2 um): the centre runs on a circle of radius 1/cos tau0 um.

    >>> import math
    >>> from bearinglab.runout import geometry_from_catalog, manufacturing_errors
    >>> g = geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(15))
    >>> e = manufacturing_errors(16, ball_diameter_deviation=np.r_[2e-6, np.zeros(15)])
    >>> t = rotation_sequence(g, e)
    >>> print(f"{t.metrics.radial_ptp_x * 1e6:.6f} {t.metrics.dz_mean * 1e6:.6f}")
    2.070550 -3.863703
    """
    revs = int(check_integer("revolutions", revolutions, 1))
    steps = int(check_integer("steps_per_revolution", steps_per_revolution, 1))
    start = float(check_finite("start_angle", start_angle, "rad"))
    psi = start + 2.0 * np.pi * np.arange(steps * revs) / steps
    kappa = (
        geometry.cage_ratio
        if cage_ratio is None
        else float(check_open_interval("cage_ratio", cage_ratio, 0.0, 1.0, "-"))  # the cage turns slower
    )
    disp = initial_displacement(
        psi,
        geometry,
        errors,
        refine=refine,
        method=method,
        tie_break=tie_break,
        cage_ratio=kappa,
        tol=tol,
        max_iter=max_iter,
        raise_on_failure=raise_on_failure,
        engine=engine,
    )
    x, y, z = disp.x, disp.y, disp.z
    metrics = runout_metrics(x, y, z, engine=engine)
    sx, sy, sz = (synchronous_part(v, steps) for v in (x, y, z))
    return Trajectory(
        psi,
        disp,
        metrics,
        runout_metrics(sx[:steps], sy[:steps], sz[:steps], engine=engine),
        runout_metrics(x - sx, y - sy, z - sz, engine=engine),
        steps,
        revs,
        kappa,
        float(np.mean(disp.contact.degenerate)),
    )


class Spectrum(NamedTuple):
    """Amplitude spectrum of the centre motion in orders of shaft speed (cycles per revolution)."""

    order: np.ndarray  # 0, 1/N_revs, 2/N_revs, ... up to the Nyquist order [-]
    radial_forward: np.ndarray  # radius of the forward (with the shaft) whirl component [m]
    radial_backward: np.ndarray  # radius of the backward whirl component [m]
    radial_x: np.ndarray  # amplitude of dx [m]
    radial_y: np.ndarray  # amplitude of dy [m]
    axial: np.ndarray  # amplitude of dz [m]


def runout_spectrum(x, y, z, steps_per_revolution):
    r"""Spectrum of the radial and axial motion of a trajectory sampled over whole revolutions.

    Parameters
    ----------
    x, y, z : array_like
        dx, dy, dz at psi_k = psi_0 + 2 pi k / N_steps. [m]
    steps_per_revolution : int
        N_steps. [-]

    Returns
    -------
    Spectrum
        One-sided amplitudes (the DC line is the mean); the radial motion is also split into forward
        and backward whirl: dx + i dy = sum r_f e^{i f psi} + r_b e^{-i f psi}.

    Examples
    --------
    >>> psi = 2 * np.pi * np.arange(64) / 32
    >>> sp = runout_spectrum(np.cos(3 * psi), np.sin(3 * psi), 0.2 * np.cos(psi), 32)
    >>> print(sp.order[6], sp.radial_forward[6].round(12), sp.radial_backward[6].round(12), sp.axial[2].round(12))
    3.0 1.0 0.0 0.2
    """
    x = np.atleast_1d(check_finite("x", x, "m"))
    y = np.atleast_1d(check_finite("y", y, "m"))
    z = np.atleast_1d(check_finite("z", z, "m"))
    m = int(check_integer("steps_per_revolution", steps_per_revolution, 2))
    npts = x.shape[-1]
    if npts % m:
        raise InputError(
            f"x must hold whole revolutions: {npts} samples is not a multiple of "
            f"steps_per_revolution = {m}"
        )
    revs = npts // m
    half = npts // 2 + 1
    order = np.arange(half) / revs

    def one_sided(v):
        a = np.abs(np.fft.rfft(v, axis=-1)) / npts
        a[..., 1:] *= 2.0
        if npts % 2 == 0:
            a[..., -1] /= 2.0  # the Nyquist line is not doubled
        return a

    w = np.fft.fft(x + 1j * y, axis=-1) / npts
    fwd = np.abs(w[..., :half])
    bwd = np.abs(w[..., (-np.arange(half)) % npts])
    bwd[..., 0] = 0.0  # the mean is counted once, as forward
    if npts % 2 == 0:
        bwd[..., -1] = 0.0  # so is the Nyquist line
    return Spectrum(order, fwd, bwd, one_sided(x), one_sided(y), one_sided(z))


class SpectrumLine(NamedTuple):
    """A line of the runout spectrum and the kinematic combination it belongs to."""

    component: str  # "radial forward", "radial backward" or "axial"
    order: float  # cycles per shaft revolution [-]
    amplitude: float  # [m]
    cage_harmonic: int  # p in p kappa + q
    shaft_harmonic: int  # q in p kappa + q
    source: str  # "cage" (q = 0), "ring" (p = 0, synchronous), "cage+ring" or "unassigned"
    label: str  # e.g. "16κ", "1×", "16κ−1×"
    bin_order: float = float("nan")  # the order of the spectrum bin the line was found in [-]
    resolution: float = float("nan")  # bin spacing 1/N_revs: the bin order is within half of it [-]


def _label(p, q):
    def term(k, sym):
        if k == 0:
            return ""
        return ("−" if k < 0 else "+") + (f"{abs(k)}" if abs(k) != 1 or sym == "×" else "") + sym

    text = (term(p, "κ") + term(q, "×")).lstrip("+")
    return text or "0"


def spectrum_lines(
    spectrum,
    cage_ratio,
    *,
    threshold=0.02,
    max_cage_harmonic=64,
    max_shaft_harmonic=64,
    max_lines=12,
):
    r"""The main lines of a runout spectrum, each labelled with the combination p kappa + q it sits on.

    Parameters
    ----------
    spectrum : Spectrum
        From :func:`runout_spectrum`.
    cage_ratio : float
        kappa. [-]
    threshold : float
        Lines below this fraction of the largest non-DC amplitude of all components are dropped. [-]
    max_cage_harmonic, max_shaft_harmonic : int
        Largest absolute values of p and q tried. [-]
    max_lines : int
        Most lines per component, largest first. [-]

    Returns
    -------
    tuple of SpectrumLine

    Notes
    -----
    The motion is a function of the cage angle kappa psi and of psi, so its lines lie at p kappa + q.
    Cage lines (q = 0) come from the balls and from the fixed outer ring; ring lines (p = 0) are
    synchronous (inner-ring errors carried round with the shaft); the others mix both. A line is
    assigned to the simplest combination within half the resolution 1/N_revs; with few revolutions
    several combinations can fit and the simplest is taken, so use many revolutions for spectra. The
    line's ``order`` is the true order p kappa + q of its combination (``bin_order`` is the bin it was
    found in, within ``resolution``/2 of it); an unassigned line keeps its bin order.

    Examples
    --------
    >>> psi = 2 * np.pi * np.arange(40 * 64) / 64
    >>> sp = runout_spectrum(np.cos(psi), np.sin(psi), 0.1 * np.cos(0.25 * psi), 64)
    >>> [(l.component, l.label, l.source) for l in spectrum_lines(sp, 0.25)]
    [('radial forward', '1×', 'ring'), ('axial', 'κ', 'cage')]
    """
    kappa = float(check_finite("cage_ratio", cage_ratio, "-"))
    order = np.asarray(spectrum.order)
    if order.size < 3:
        return ()
    res = order[1] - order[0]
    p = np.arange(-max_cage_harmonic, max_cage_harmonic + 1)[:, None]
    q = np.arange(-max_shaft_harmonic, max_shaft_harmonic + 1)[None, :]
    comb = p * kappa + q
    cost = np.abs(p) + np.abs(q)
    out = []
    comps = (
        ("radial forward", spectrum.radial_forward),
        ("radial backward", spectrum.radial_backward),
        ("axial", spectrum.axial),
    )
    ref = max(float(np.max(np.asarray(a)[1:], initial=0.0)) for _, a in comps)
    if not ref > 0:
        return ()
    for name, amp in comps:
        a = np.asarray(amp)
        peak = np.zeros(a.size, bool)
        peak[1:-1] = (a[1:-1] >= a[:-2]) & (a[1:-1] >= a[2:])
        peak[-1] = a[-1] >= a[-2]
        peak &= a >= threshold * ref
        peak[0] = False
        idx = np.flatnonzero(peak)
        idx = idx[np.argsort(-a[idx])][:max_lines]
        for i in idx:
            f = order[i]
            ok = (np.abs(comb - f) <= res / 2 + 1e-12) & (comb >= 0)
            if ok.any():
                c = np.where(ok, cost + np.abs(comb - f) / max(res, 1e-12) * 1e-3, np.inf)
                pi, qi = np.unravel_index(c.argmin(), c.shape)
                pp, qq = int(p[pi, 0]), int(q[0, qi])
                src = "cage" if qq == 0 else ("ring" if pp == 0 else "cage+ring")
                out.append(SpectrumLine(name, float(pp * kappa + qq), float(a[i]), pp, qq, src, _label(pp, qq),
                                        float(f), float(res)))
            else:
                out.append(
                    SpectrumLine(name, float(f), float(a[i]), 0, 0, "unassigned", f"{f:.4g}×", float(f), float(res))
                )
    return tuple(out)
