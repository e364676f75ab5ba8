r"""Monte Carlo runout over tolerance classes (spec 003 section 11).

Tolerance classes
-----------------
BallGrade, RingClass    ISO 3290 ball grades and ring-class presets (``data/tolerance_classes.toml``)
tolerance_classes       all grades and classes, with their sources
ball_grade, ring_class  one of them by name

Monte Carlo
-----------
monte_carlo_chunk       per-sample metrics of a chunk of samples (seeded per sample)
monte_carlo             a whole study, serial or on dask (``execution=parallel.Execution(...)``)
summarize               mean, std, median, p95 and max of per-sample metrics

Reproducing samples
-------------------
SampleErrors            one sample as drawn: index, geometry (with its theta^1), ManufacturingErrors
monte_carlo_errors      the geometry and errors of chosen samples, exactly as the study drew them
worst_samples           indices of the samples with the largest value of a metric

Units: SI (m, rad); the tolerance-class file gives micrometres.
"""

from __future__ import annotations

import math
import tomllib
from importlib import resources
from typing import NamedTuple

import numpy as np

from .. import _bounds, parallel
from .._validate import check_finite, check_integer
from ..errors import InputError
from . import _solver
from . import contact as _contact
from .contact import _UM, _generalized_error, ball_angles, pose_from_sinusoid, tie_break_centre
from .deviations import FourierSeries, ManufacturingErrors, RacewayErrors, _combined
from .geometry import SpindleGeometry
from .rotation import METRICS, runout_metrics

__all__ = [
    "BallGrade",
    "MonteCarloResult",
    "MonteCarloSamples",
    "RingClass",
    "SampleErrors",
    "Summary",
    "ball_grade",
    "monte_carlo",
    "monte_carlo_chunk",
    "monte_carlo_errors",
    "ring_class",
    "summarize",
    "tolerance_classes",
    "worst_samples",
]


class BallGrade(NamedTuple):
    """An ISO 3290-1 steel-ball grade. [m]"""

    name: str
    single_diameter_variation: float  # V_DWS
    lot_diameter_variation: float  # V_DWL
    source: str


class RingClass(NamedTuple):
    """A ring tolerance-class preset of spec 003 section 11. [m]"""

    name: str
    radial_runout: float  # K_ia, inner ring of the assembled bearing
    axial_runout: float  # S_ia
    waviness_rms: float  # w_rms of orders 2..K_max (an assumption, not a standard value)
    source: str


def tolerance_classes():
    """Ball grades and ring classes of ``data/tolerance_classes.toml``, each with its source.

    Returns
    -------
    tuple of dict
        ``({name: BallGrade}, {name: RingClass})``.

    Examples
    --------
    >>> grades, classes = tolerance_classes()
    >>> print(sorted(classes), f"{grades['G5'].lot_diameter_variation * 1e6:.2f}")
    ['P2', 'P4', 'P5'] 0.25
    """
    ref = resources.files("bearinglab") / "data" / "tolerance_classes.toml"
    doc = tomllib.loads(ref.read_text(encoding="utf-8"))
    unit = _UM
    grades = {
        k: BallGrade(
            k,
            v["single_diameter_variation"] * unit,
            v["lot_diameter_variation"] * unit,
            v["source"],
        )
        for k, v in doc["ball_grades"].items()
    }
    classes = {
        k: RingClass(
            k,
            v["radial_runout"] * unit,
            v["axial_runout"] * unit,
            v["waviness_rms"] * unit,
            v["source"],
        )
        for k, v in doc["ring_classes"].items()
    }
    return grades, classes


def ball_grade(name):
    """An ISO 3290-1 ball grade by name (``"G5"``); the message lists the known ones.

    Parameters
    ----------
    name : str or BallGrade
        Grade name, case-insensitive.

    Returns
    -------
    BallGrade

    Examples
    --------
    >>> print(f"{ball_grade('g10').single_diameter_variation * 1e6:.2f}")
    0.25
    """
    return _tolerance_lookup("ball_grade", name, BallGrade, 0)


def ring_class(name):
    """A ring-class preset by name (``"P4"``); the message lists the known ones.

    Parameters
    ----------
    name : str or RingClass
        Class name, case-insensitive.

    Returns
    -------
    RingClass

    Examples
    --------
    >>> print(f"{ring_class('P4').radial_runout * 1e6:.1f}")
    4.0
    """
    return _tolerance_lookup("ring_class", name, RingClass, 1)


def _tolerance_lookup(param, name, cls, which):
    """``name`` itself if already a ``cls``, else the preset of that name (case-insensitive) in
    ``tolerance_classes()[which]``; the data file is read only when a name is given."""
    if isinstance(name, cls):
        return name
    presets = tolerance_classes()[which]
    key = str(name).upper()
    if key not in presets:
        raise InputError(f"{param} must be one of {list(presets)}, got {name!r}")
    return presets[key]


class MonteCarloSamples(NamedTuple):
    """Per-sample results of a Monte Carlo chunk (arrays over samples)."""

    sample_index: np.ndarray  # global index of each sample [-]
    first_ball_angle: np.ndarray  # theta^1 drawn [rad]
    radial_ptp_x: np.ndarray  # [m]
    radial_ptp_y: np.ndarray  # [m]
    radial_ptp_max: np.ndarray  # [m]
    axial_ptp: np.ndarray  # [m]
    dz_mean: np.ndarray  # [m]
    degenerate_fraction: np.ndarray  # share of degenerate positions [-]


class Summary(NamedTuple):
    """Summary statistics of one per-sample metric. [m]"""

    mean: float
    std: float  # sample standard deviation (ddof = 1)
    median: float
    p95: float  # 95th percentile (linear interpolation)
    max: float


class MonteCarloResult(NamedTuple):
    """A Monte Carlo study: the per-sample metrics and their summary statistics."""

    samples: MonteCarloSamples
    summary: dict  # metric name -> Summary
    ball_grade: BallGrade
    ring_class: RingClass
    seed: int
    steps_per_revolution: int
    revolutions: int
    max_order: int


def _seed(seed):
    """(entropy, spawn-key prefix) of a root seed: a whole number >= 0 or a SeedSequence."""
    if isinstance(seed, np.random.SeedSequence):
        return seed.entropy, tuple(seed.spawn_key)
    if isinstance(seed, (bool, np.bool_)) or not isinstance(seed, (int, np.integer)) or seed < 0:
        raise InputError(
            f"seed must be a whole number >= 0 or a numpy.random.SeedSequence, got {seed!r}"
        )
    return int(seed), ()


def _uniforms(seed, index, count):
    """``count`` uniforms per sample from the sample's own generator.

    Sample i uses ``SeedSequence(entropy, spawn_key=prefix + (i,))``, i.e. the i-th child that
    ``SeedSequence(seed).spawn`` would give, so a sample's numbers do not depend on how the samples are
    split into chunks.
    """
    entropy, prefix = _seed(seed)
    # a loop over samples for the draws only (one generator call each); the physics below is batched
    return np.stack(
        [
            np.random.default_rng(
                np.random.SeedSequence(entropy, spawn_key=prefix + (int(i),))
            ).random(count)
            for i in index
        ]
    ).reshape(len(index), count)


def _sampled_errors(u, n, grade, rings, k_max):
    """Map per-sample uniforms (S, M) to raceway series and ball deficits (section 11)."""
    S = u.shape[0]
    pos = 0

    def take(m):
        nonlocal pos
        out = u[:, pos : pos + m]
        pos += m
        return out

    theta1 = 2 * np.pi * take(1)[:, 0]
    dd = (take(n) - 0.5) * grade.lot_diameter_variation + (
        take(n) - 0.5
    ) * grade.single_diameter_variation
    orders = np.arange(2, k_max + 1)
    c = rings.waviness_rms / math.sqrt(float(np.sum(orders**-2.0))) if k_max >= 2 else 0.0
    sigma = c / orders

    def waviness():
        amp = sigma * np.sqrt(-2.0 * np.log1p(-take(k_max - 1)))  # Rayleigh(sigma_k) by inversion
        ph = 2 * np.pi * take(k_max - 1)
        return amp, ph

    inner = np.zeros((S, k_max + 1), complex)  # a_k - i b_k of A cos(k theta + phi)
    a1 = take(1)[:, 0] * rings.radial_runout / 2
    inner[:, 1] = a1 * np.exp(1j * 2 * np.pi * take(1)[:, 0])
    if k_max >= 2:
        amp, ph = waviness()
        inner[:, 2:] = amp * np.exp(1j * ph)
    wob = np.zeros((S, 2), complex)
    s1 = take(1)[:, 0] * rings.axial_runout / 2
    wob[:, 1] = s1 * np.exp(1j * 2 * np.pi * take(1)[:, 0])
    outer = np.zeros((S, k_max + 1), complex)
    if k_max >= 2:
        amp, ph = waviness()
        outer[:, 2:] = amp * np.exp(1j * ph)
    assert pos == u.shape[1]
    # A cos(k t + phi) = A cos(phi) cos(k t) - A sin(phi) sin(k t): cos = Re, sin = -Im
    series = {
        name: FourierSeries(v.real, -v.imag)
        for name, v in (("inner", inner), ("wobble", wob), ("outer", outer))
    }
    return theta1, dd, series


def _draw_count(n, k_max):
    return 1 + 2 * n + 2 + 2 * max(k_max - 1, 0) + 2 + 2 * max(k_max - 1, 0)


def _draw(n, grade, rings, idx, seed, k_max):
    """theta^1 (S,), ball deficits Delta r31 = Delta r32 (S, n) and raceway series of the samples ``idx``."""
    u = _uniforms(seed, idx, _draw_count(n, k_max))
    theta1, dd, series = _sampled_errors(u, n, grade, rings, k_max)
    return theta1, -0.5 * dd, series  # Delta r31 = Delta r32 = -delta D / 2 (section 11)


def _errors(deficit, series, sample=None):
    """The ManufacturingErrors of one sample (an index), or of all with leading axes (S, 1, ...) for
    ball azimuths (S, P, n) when ``sample`` is None."""
    at, ball_at = (np.s_[:, None, None], np.s_[:, None]) if sample is None else (sample, sample)

    def one(name):
        return FourierSeries(series[name].cos[at], series[name].sin[at])

    inner = RacewayErrors(radial=one("inner"), axial=one("wobble"))  # delta H2 and delta S2
    return ManufacturingErrors(
        RacewayErrors(radial=one("outer")), inner, deficit[ball_at], deficit[ball_at]
    )


class SampleErrors(NamedTuple):
    """One Monte Carlo sample as it was drawn: the bearing that :func:`monte_carlo` solved."""

    sample_index: int  # global index of the sample [-]
    geometry: SpindleGeometry  # the nominal geometry with the drawn theta^1 as first_ball_angle
    errors: ManufacturingErrors  # raceway waviness, ball deficits; no tilt


def monte_carlo_errors(geometry, grade, rings, sample_index, seed, *, max_order=15):
    r"""The geometry and errors of chosen Monte Carlo samples, exactly as :func:`monte_carlo` drew them.

    Parameters
    ----------
    geometry : SpindleGeometry
        Nominal geometry of the study.
    grade : str or BallGrade
        Ball grade of the study.
    rings : str or RingClass
        Ring class of the study.
    sample_index : array_like of int
        Global indices of the samples (``MonteCarloSamples.sample_index``). [-]
    seed : int or numpy.random.SeedSequence
        Root seed of the study.
    max_order : int
        K_max of the study. [-]

    Returns
    -------
    tuple of SampleErrors
        One per index, in the order given.

    Notes
    -----
    Sample i draws from its own seed sequence (see :func:`monte_carlo_chunk`), so the errors depend on
    the seed, the index, the grade, the class and K_max only, not on the chunk size or executor.
    :func:`rotation_sequence` of a sample's geometry and errors, with the study's steps and revolutions,
    gives that sample's metrics bit for bit (the Monte Carlo kernel evaluates the same functions).

    Examples
    --------
    >>> from bearinglab.runout import geometry_from_catalog, rotation_sequence
    >>> g = geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(15))
    >>> mc = monte_carlo_chunk(g, "G5", "P4", [0, 1, 2], 7, steps_per_revolution=36)
    >>> (s,) = monte_carlo_errors(g, "G5", "P4", [2], 7)
    >>> t = rotation_sequence(s.geometry, s.errors, revolutions=2, steps_per_revolution=36)
    >>> bool(t.metrics.axial_ptp == mc.axial_ptp[2])
    True
    """
    grade = ball_grade(grade)
    rings = ring_class(rings)
    idx = np.atleast_1d(check_integer("sample_index", sample_index, 0))
    k_max = int(check_integer("max_order", max_order, 1))
    _seed(seed)
    theta1, deficit, series = _draw(geometry.n_balls, grade, rings, idx, seed, k_max)
    # one object per chosen sample (a handful, for files): the draws above are batched
    return tuple(
        SampleErrors(
            int(i), geometry._replace(first_ball_angle=float(t1)), _errors(deficit, series, s)
        )
        for s, (i, t1) in enumerate(zip(idx, theta1))
    )


def monte_carlo_chunk(
    geometry,
    grade,
    rings,
    sample_index,
    seed,
    *,
    steps_per_revolution=180,
    revolutions=2,
    max_order=15,
    cage_ratio=None,
    engine="auto",
):
    r"""Per-sample runout metrics of a chunk of random bearings (spec 003 section 11).

    Parameters
    ----------
    geometry : SpindleGeometry
        Nominal geometry (its first-ball angle is replaced by the random one).
    grade : str or BallGrade
        Ball grade, e.g. ``"G5"``.
    rings : str or RingClass
        Ring-class preset, e.g. ``"P4"``.
    sample_index : array_like of int
        Global indices of the samples of this chunk.
    seed : int or numpy.random.SeedSequence
        Root seed; sample i draws from its own child sequence, so results do not depend on chunking.
    steps_per_revolution, revolutions : int
        Rotation sequence of each sample. [-]
    max_order : int
        K_max, highest waviness order. [-]
    cage_ratio : float, optional
        kappa override. [-]
    engine : {"auto", "numpy", "compiled"}
        ``"compiled"``: each sample's generalized errors and contact solves in one numba kernel
        (:func:`bearinglab.runout._compiled.sequences`), samples in parallel; ``"numpy"``: the same model
        vectorized over the samples' positions; ``"auto"`` (default): compiled when numba is installed.
        The engines agree to rounding; each gives the same bits on every executor and chunk size.

    Returns
    -------
    MonteCarloSamples

    Notes
    -----
    Per sample (first approximation): theta^1 ~ U(0, 2 pi); ball i: delta D = U(-V_DWL/2, V_DWL/2) +
    U(-V_DWS/2, V_DWS/2), Delta r31 = Delta r32 = -delta D/2; inner delta H2 order 1 with amplitude
    U(0, K_ia/2), orders 2..K_max with Rayleigh(c/k) amplitudes, c = w_rms / sqrt(sum k^-2); inner delta
    S2 order 1 with amplitude U(0, S_ia/2); outer delta H1 orders 2..K_max as for the inner ring; all
    phases uniform. All positions of all samples of the chunk are solved in one batch (numpy: in blocks
    of samples, or of one sample's positions, of at most 2^20 ball-positions, so that memory stays
    linear in the balls and positions and bounded per chunk).

    Every operation is element by element, per position or per sample, in a fixed order (no BLAS
    product, whose rounding depends on the number of BLAS threads; BLAS is held to one thread here all
    the same, as on a dask worker), so a sample gives the same bits in any chunk, on any executor, and,
    with the same engine, equal to :func:`rotation_sequence` of its :func:`monte_carlo_errors`.

    Examples
    --------
    >>> from bearinglab.runout import geometry_from_catalog
    >>> g = geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(15))
    >>> a = monte_carlo_chunk(g, "G5", "P4", [0, 1, 2, 3], 7, steps_per_revolution=36)
    >>> b = monte_carlo_chunk(g, "G5", "P4", [2, 3], 7, steps_per_revolution=36)
    >>> bool(np.array_equal(a.axial_ptp[2:], b.axial_ptp))  # bit for bit
    True
    """
    from threadpoolctl import threadpool_limits

    grade = ball_grade(grade)
    rings = ring_class(rings)
    idx = np.atleast_1d(check_integer("sample_index", sample_index, 0))
    steps = int(check_integer("steps_per_revolution", steps_per_revolution, 1, _bounds.MAX_STEPS_PER_REV))
    revs = int(check_integer("revolutions", revolutions, 1, _bounds.MAX_REVOLUTIONS))
    k_max = int(check_integer("max_order", max_order, 1, _bounds.MAX_ORDER))
    kappa = (
        geometry.cage_ratio
        if cage_ratio is None
        else float(check_finite("cage_ratio", cage_ratio, "-"))
    )
    n = geometry.n_balls
    if idx.size == 0:
        empty = np.zeros(0)
        return MonteCarloSamples(idx, *(empty,) * 7)
    engine = _contact._engine(engine, "dual")
    theta1, deficit, series = _draw(n, grade, rings, idx, seed, k_max)
    S = idx.size
    psi = 2.0 * np.pi * np.arange(steps * revs) / steps
    P = psi.size
    if engine == "compiled":
        a0, b, d, degenerate = _compiled_chunk(geometry, kappa, psi, theta1, deficit, series)
    else:
        a0, b, d, degenerate = (np.empty((S, P)) for _ in range(4))
        # blocks of samples, or of one sample's positions, of at most _NUMPY_BLOCK ball-positions
        step = max(1, _NUMPY_BLOCK // (P * n))
        p_step = P if P * n <= _NUMPY_BLOCK else max(1, _NUMPY_BLOCK // n)
        with threadpool_limits(limits=1, user_api="blas"):
            for q in range(0, S, step):
                sl = slice(q, q + step)
                blk = (deficit[sl], {k: FourierSeries(v.cos[sl], v.sin[sl]) for k, v in series.items()})
                for p0 in range(0, P, p_step):
                    ps = slice(p0, p0 + p_step)
                    out = _numpy_chunk(geometry, kappa, psi[ps], theta1[sl], *blk)
                    for o, v in zip((a0, b, d, degenerate), out):
                        o[sl, ps] = v
    pose = pose_from_sinusoid(a0 * _UM, b * _UM, d * _UM, geometry)
    m = runout_metrics(*pose, engine=engine)
    return MonteCarloSamples(idx, theta1, *(np.atleast_1d(v) for v in m), degenerate.mean(axis=1))


_NUMPY_BLOCK = 1 << 20  # ball-positions per block of samples of the numpy engine (~8 MB per array)


def _numpy_chunk(geometry, kappa, psi, theta1, deficit, series):
    """a0, B, D [um] and the degenerate flags, (S, P), by the functions of rotation_sequence with a leading
    axis of samples: (S, P, n)."""
    S, P, n = theta1.size, psi.size, geometry.n_balls
    theta = ball_angles(psi, geometry, cage_ratio=kappa, first_ball_angle=theta1[:, None])
    dk = _generalized_error(psi, theta, geometry, _errors(deficit, series))
    a0, b, d, _lam, degenerate, _diam = _solver.solve_dual(
        dk.reshape(S * P, n) / _UM, theta.reshape(S * P, n), 0.0, 0.0
    )
    return (v.reshape(S, P) for v in (a0, b, d, degenerate))


def _compiled_chunk(geometry, kappa, psi, theta1, deficit, series):
    """The same by the compiled kernel, with the inputs :func:`initial_displacement` gives it for one
    sample's errors (the same series, deficits and tie-break centre, bit for bit)."""
    from . import _compiled  # imports numba: only when the compiled path runs

    tau0 = geometry.contact_angle
    outer = _combined(RacewayErrors(radial=series["outer"]), tau0, 1.0)
    inner = _combined(RacewayErrors(radial=series["inner"], axial=series["wobble"]), tau0, -1.0)
    cb, cd = (np.asarray(v, float) / _UM for v in tie_break_centre(geometry))
    a0, b, d, degenerate, _diam, status, _dk, _lam = _compiled.sequences(
        theta1, kappa, psi, (outer.cos / _UM, outer.sin / _UM), (inner.cos / _UM, inner.sin / _UM),
        (deficit + deficit) / _UM, cb, cd,
    )
    _solver.check_status(status, a0, geometry.n_balls)
    return a0, b, d, degenerate


def worst_samples(samples, metric="radial_ptp_max", count=1):
    """Global indices of the samples with the largest magnitude of a metric, largest first.

    Parameters
    ----------
    samples : MonteCarloSamples or MonteCarloResult
        Per-sample metrics of a study.
    metric : str
        One of :data:`METRICS`; ranked by absolute value (``dz_mean`` is negative).
    count : int
        How many, >= 1 (fewer if the study has fewer samples). [-]

    Returns
    -------
    ndarray of int
        Sample indices; equal values keep the lower index first.

    Examples
    --------
    >>> s = MonteCarloSamples(np.arange(4), *np.zeros((6, 4)), np.zeros(4))
    >>> s = s._replace(axial_ptp=np.array([1.0, 3.0, 2.0, 3.0]))
    >>> worst_samples(s, "axial_ptp", 3)
    array([1, 3, 2])
    """
    if isinstance(samples, MonteCarloResult):
        samples = samples.samples
    if metric not in METRICS:
        raise InputError(f"metric must be one of {list(METRICS)}, got {metric!r}")
    count = int(check_integer("count", count, 1))
    value = np.abs(np.asarray(getattr(samples, metric), float))
    index = np.asarray(samples.sample_index)
    order = np.lexsort((index, -value))  # largest first, then by index
    return index[order[:count]]


def summarize(values):
    """Mean, standard deviation (ddof = 1), median, 95th percentile and maximum.

    Parameters
    ----------
    values : array_like
        Per-sample values of one metric.

    Returns
    -------
    Summary

    Examples
    --------
    >>> print(" ".join(f"{v:.4f}" for v in summarize([1.0, 2.0, 3.0, 4.0])))
    2.5000 1.2910 2.5000 3.8500 4.0000
    """
    v = np.ravel(check_finite("values", values, "-"))
    if v.size < 2:
        raise InputError(
            f"values must hold at least 2 samples for a standard deviation, got {v.size}"
        )
    return Summary(
        float(v.mean()),
        float(v.std(ddof=1)),
        float(np.median(v)),
        float(np.percentile(v, 95)),
        float(v.max()),
    )


def _monte_carlo_task(sample_index, geometry, grade, rings, seed, **options):
    """:func:`monte_carlo_chunk` as a mapping of per-sample arrays (the chunk function of the execution layer)."""
    return monte_carlo_chunk(geometry, grade, rings, sample_index, seed, **options)._asdict()


_DEFAULT_CHUNK_SIZE = 100  # samples per task: about 3 kB per sample and position


def monte_carlo(
    geometry,
    grade,
    rings,
    n_samples,
    seed,
    *,
    steps_per_revolution=180,
    revolutions=2,
    max_order=15,
    cage_ratio=None,
    execution=None,
    chunk_size=None,
    progress=None,
    executor=None,
    workers=None,
    memory_limit=None,
    processes=None,
    engine="auto",
):
    """Monte Carlo runout study over a ball grade and a ring class (spec 003 section 11).

    Parameters
    ----------
    geometry : SpindleGeometry
        Nominal geometry.
    grade : str or BallGrade
        Ball grade (``"G3"`` ... ``"G40"``).
    rings : str or RingClass
        Ring class (``"P5"``, ``"P4"``, ``"P2"``).
    n_samples : int
        Number of random bearings, >= 2. [-]
    seed : int or numpy.random.SeedSequence
        Root seed; the result is reproducible and independent of the chunk size and executor.
    steps_per_revolution, revolutions : int
        Rotation sequence of each sample (spec: 180 and 2). [-]
    max_order : int
        K_max (spec: 15). [-]
    cage_ratio : float, optional
        kappa override. [-]
    execution : parallel.Execution, optional
        Executor (``"serial"``, ``"local"`` or a scheduler address), workers, chunk size (default 100
        samples per task; memory about 3 kB per sample and position), progress and timeout as one value
        (:mod:`bearinglab.parallel`). The keyword arguments below are the older spelling of the same
        fields; give one or the other.
    chunk_size : int, optional
        Samples per task. [-]
    progress : callable or "dask", optional
        Called as ``progress(done, total)`` after each chunk, or ``"dask"`` for dask's progress bar.
    executor : str, optional
        ``"serial"`` (default), ``"local"`` (a dask LocalCluster for this study) or a scheduler address
        ``"tcp://host:8786"``.
    workers : int, optional
        Workers of the local cluster. [-]
    memory_limit : str, optional
        Memory limit per local worker, e.g. ``"4GiB"``.
    processes : bool, optional
        Local workers as processes (default) or threads.
    engine : {"auto", "numpy", "compiled"}
        As for :func:`monte_carlo_chunk` (compiled when numba is installed).

    Returns
    -------
    MonteCarloResult

    Notes
    -----
    Each sample has its own seed and every sample is computed independently of its chunk and of the
    number of BLAS threads, so the per-sample metrics and the statistics are bit-identical on every
    executor and for every chunk size.

    Examples
    --------
    >>> from bearinglab.runout import geometry_from_catalog
    >>> g = geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(15))
    >>> r = monte_carlo(g, "G5", "P4", 8, 1, steps_per_revolution=36,
    ...                 execution=parallel.Execution(chunk_size=4))
    >>> sorted(r.summary)
    ['axial_ptp', 'dz_mean', 'radial_ptp_max', 'radial_ptp_x', 'radial_ptp_y']
    """
    total = int(check_integer("n_samples", n_samples, 2, _bounds.MAX_SAMPLES))
    _seed(seed)
    _contact._engine(engine, "dual")  # an unknown engine is refused before any work
    ex = parallel._execution(
        execution,
        chunk_size=chunk_size,
        executor=executor,
        workers=workers,
        memory_limit=memory_limit,
        processes=processes,
        progress=progress,
    ).with_default_chunk_size(_DEFAULT_CHUNK_SIZE)
    grade = ball_grade(grade)
    rings = ring_class(rings)
    # chunks of samples, each one batch, run by the execution layer (serial or on dask)
    fields = parallel.run_cases(
        _monte_carlo_task,
        {"sample_index": np.arange(total)},
        constants={
            "geometry": geometry,
            "grade": grade,
            "rings": rings,
            "seed": seed,
            "steps_per_revolution": steps_per_revolution,
            "revolutions": revolutions,
            "max_order": max_order,
            "cage_ratio": cage_ratio,
            "engine": engine,
        },
        execution=ex,
    )
    samples = MonteCarloSamples(**fields)
    summary = {name: summarize(getattr(samples, name)) for name in METRICS}
    return MonteCarloResult(
        samples,
        summary,
        grade,
        rings,
        _seed(seed)[0],
        int(steps_per_revolution),
        int(revolutions),
        int(max_order),
    )
