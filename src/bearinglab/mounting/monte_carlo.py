"""The clearance chain over random tolerances: the distribution of the operating clearance.

FIELDS          the five random inputs: unmounted clearance, shaft seat, bore, outside diameter, housing bore
draw_field      samples of a tolerance field, uniform or truncated normal (+-3 sigma at the limits)
sample_chain    one block of samples through :func:`bearinglab.mounting.chain.operating_clearance`
MonteCarlo      the samples, their percentiles and the probability of a preload
monte_carlo     a seeded study on :func:`bearinglab.parallel.run_seeded` (serial or dask)

MESYS takes the tolerances as normal, independent and linear and adds them as a root sum of squares; it
notes that this fails where a fit turns from interference to clearance. Here every sample goes through the
nonlinear chain, so a fit that comes loose in some samples is counted as it is.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from scipy import special

from .. import parallel
from ..errors import InputError
from .chain import Conditions, operating_clearance

__all__ = ["BLOCK_SIZE", "DISTRIBUTIONS", "FIELDS", "PERCENTILES", "MonteCarlo", "draw_field", "monte_carlo",
           "sample_chain"]

FIELDS = ("unmounted_clearance", "shaft", "bore", "outside_diameter", "housing")
DISTRIBUTIONS = ("uniform", "normal")
PERCENTILES = (0.1, 1.0, 5.0, 50.0, 95.0, 99.0, 99.9)
_SIGMAS = 3.0  # a normal field has its limits at +-3 sigma (99.73 %), and is cut there


def draw_field(rng, n, lower, upper, distribution="uniform"):
    """Samples of a tolerance field between two limits.

    Parameters
    ----------
    rng : numpy.random.Generator
    n : int
        Number of samples. [-]
    lower, upper : float
        The limits. [m]
    distribution : {"uniform", "normal"}
        Uniform between the limits, or normal with its mean in the middle and the limits at +-3 sigma,
        cut at the limits (drawn by the inverse CDF, so every sample lies within them).

    Returns
    -------
    ndarray
        ``n`` values in [lower, upper]. [m]

    Examples
    --------
    >>> x = draw_field(np.random.default_rng(1), 1000, -1.0, 1.0, "normal")
    >>> bool(x.min() >= -1.0 and x.max() <= 1.0), round(float(x.std()), 1)
    (True, 0.3)
    """
    if distribution not in DISTRIBUTIONS:
        raise InputError(f"distribution must be one of {list(DISTRIBUTIONS)}, got {distribution!r}")
    from .. import _bounds
    from .._validate import check_finite, check_integer

    n = int(check_integer("n", n, 0, _bounds.MAX_SAMPLES))
    lower, upper = check_finite("lower", lower, "m"), check_finite("upper", upper, "m")
    u = rng.random(n)
    if distribution == "normal":
        lo = special.ndtr(-_SIGMAS)
        u = 0.5 + special.ndtri(lo + u * (1 - 2 * lo)) / (2 * _SIGMAS)
    return lower + (upper - lower) * u


def sample_chain(n, rng, *, limits, mounting, conditions, distribution="uniform"):
    """``n`` random bearings through the clearance chain (the block function of :func:`monte_carlo`).

    Parameters
    ----------
    n : int
        Samples in this block. [-]
    rng : numpy.random.Generator
        The block's generator.
    limits : dict
        (lower, upper) of each of :data:`FIELDS` [m]: the unmounted clearance, the shaft seat's and the
        bore's deviations (inner interference = shaft - bore), the outside diameter's and the housing
        bore's deviations (outer interference = outside diameter - housing). An interference given
        directly is the shaft (or outside-diameter) field with a zero bore (housing) field.
    mounting : Mounting
    conditions : Conditions
    distribution : {"uniform", "normal"}

    Returns
    -------
    dict of str to ndarray
        ``operating_clearance``, ``fit_reduction``, ``thermal_reduction``, ``centrifugal_reduction``,
        ``inner_interference``, ``outer_interference``, ``unmounted_clearance``. [m]
    """
    x = {f: draw_field(rng, n, *limits[f], distribution) for f in FIELDS}
    r = operating_clearance(x["unmounted_clearance"], x["shaft"] - x["bore"],
                            x["outside_diameter"] - x["housing"], mounting, conditions)
    return {"operating_clearance": np.atleast_1d(r.operating_clearance),
            "fit_reduction": np.atleast_1d(r.fit_reduction),
            "thermal_reduction": np.atleast_1d(r.thermal_reduction),
            "centrifugal_reduction": np.atleast_1d(r.centrifugal_reduction),
            "inner_interference": np.atleast_1d(r.inner_interference),
            "outer_interference": np.atleast_1d(r.outer_interference),
            "unmounted_clearance": np.atleast_1d(r.unmounted_clearance)}


class MonteCarlo(NamedTuple):
    """A Monte Carlo study of the operating clearance."""

    samples: dict
    """Per-sample arrays of :func:`sample_chain`. [m]"""
    percentiles: dict
    """Percentile (of :data:`PERCENTILES`) -> operating clearance. [m]"""
    probability_preload: float
    """Fraction of samples with a negative operating clearance. [-]"""
    mean: float
    """Mean operating clearance. [m]"""
    std: float
    """Standard deviation of the operating clearance. [m]"""


#: Samples per seeded block: the chain costs ~40 numpy calls per block, so blocks of 2^14 samples keep that
#: overhead below the arithmetic; the result depends on the seed and this size only.
BLOCK_SIZE = 16384


def monte_carlo(n_samples, seed, limits, mounting, conditions=None, *, distribution="uniform",
                execution=None, block_size=BLOCK_SIZE):
    """The distribution of the operating clearance over random bearings and seats.

    Parameters
    ----------
    n_samples : int
        Number of samples, >= 1. [-]
    seed : int
        Root seed; the result depends on it only (not on the chunking or executor).
    limits : dict
        (lower, upper) of each of :data:`FIELDS`, as in :func:`sample_chain`. [m]
    mounting : Mounting
    conditions : Conditions, optional
    distribution : {"uniform", "normal"}, optional
    execution : bearinglab.parallel.Execution, optional
        Serial by default, or a dask cluster.
    block_size : int, optional
        Samples per seeded block (:func:`bearinglab.parallel.run_seeded`). [-]

    Returns
    -------
    MonteCarlo

    Examples
    --------
    >>> from bearinglab.mounting.chain import Mounting
    >>> m = Mounting(0.025, 0.052, 0.03110, 0.04698, 0.00794)
    >>> lim = {"unmounted_clearance": (5e-6, 20e-6), "shaft": (2e-6, 11e-6), "bore": (-10e-6, 0.0),
    ...        "outside_diameter": (-13e-6, 0.0), "housing": (0.0, 30e-6)}
    >>> mc = monte_carlo(10_000, 1, lim, m)
    >>> bool(0.0 < mc.probability_preload < 0.5)
    True
    """
    if distribution not in DISTRIBUTIONS:
        raise InputError(f"distribution must be one of {list(DISTRIBUTIONS)}, got {distribution!r}")
    missing = [f for f in FIELDS if f not in limits]
    if missing:
        raise InputError(f"limits: missing {missing}; give (lower, upper) of each of {list(FIELDS)}")
    out = parallel.run_seeded(sample_chain, n_samples, seed, execution=execution, block_size=block_size,
                              constants={"limits": {f: tuple(map(float, limits[f])) for f in FIELDS},
                                         "mounting": mounting,
                                         "conditions": Conditions() if conditions is None else conditions,
                                         "distribution": distribution})
    op = out["operating_clearance"]
    pct = dict(zip(PERCENTILES, np.percentile(op, PERCENTILES)))
    return MonteCarlo(out, {k: float(v) for k, v in pct.items()}, float(np.mean(op < 0)), float(op.mean()),
                      float(op.std()))
