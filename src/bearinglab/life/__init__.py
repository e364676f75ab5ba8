"""Rating life of a bearing: the ISO 281 and ISO/TS 16281 analysis, and duty cycles.

Modules
-------
analysis    the analysis of a BallBearing: every life quantity for loads, speed, lubricant, cleanliness and reliability,
            batched over load cases; duty cycles (Palmgren-Miner)
system      the life of a system of bearings (Lundberg-Palmgren, Weibull slopes 10/9 ball and 9/8 roller)
roller      the same analysis of a RollerBearing (ISO 281 roller formulas, ISO/TS 16281 over the laminae)

The analysis composes the ISO formulas of :mod:`bearinglab.ratings` with the load distribution of
:mod:`bearinglab.quasistatic` (the ball loads of the ISO/TS 16281 reference life), so it sits above both.
Every public name of its modules is reachable here: ``bearinglab.life.rating_life``.
"""

from ..ratings.bearing import BearingRatings, bearing_ratings  # noqa: F401 -- ratings.life.* reached them
from . import analysis, roller, system
from .analysis import (
    DutyCycleLife,
    RatingLife,
    duty_cycle_life,
    miner_life,
    rating_life,
    reference_load_distribution,
)
from .roller import reference_slice_loads, roller_rating_life
from .system import BALL_SLOPE, ROLLER_SLOPE, system_life, weibull_slope

__all__ = [
    "BALL_SLOPE",
    "ROLLER_SLOPE",
    "DutyCycleLife",
    "RatingLife",
    "analysis",
    "duty_cycle_life",
    "miner_life",
    "rating_life",
    "reference_load_distribution",
    "reference_slice_loads",
    "roller",
    "roller_rating_life",
    "system",
    "system_life",
    "weibull_slope",
]
