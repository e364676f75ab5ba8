"""Load ratings and rating life of ball bearings: ISO 76, ISO 281 and ISO/TS 16281.

Modules
-------
static         C0 and f0 (ISO 76), Cu (ISO 281 annex B), P0 and the static safety factor s0
dynamic        C and f_c, X / Y / e and P, L10 and the reliability factor a1 (ISO 281)
lubrication    oil viscosity (ISO VG, ASTM D2270 viscosity index, ASTM D341), nu1 and kappa, e_C classes, a_ISO (ISO 281)
reference      ISO/TS 16281 reference rating life from the ball loads
life           the analysis of a BallBearing (every life quantity at once) and duty cycles

Every public function of these modules is also reachable here, e.g. ``ratings.rating_life`` and
``ratings.static_load_rating``. SI throughout; lives in revolutions and durations in seconds.
"""

from . import dynamic, life, lubrication, reference, static
from .dynamic import (
    MATERIAL_FACTOR,
    DynamicLoadFactors,
    basic_rating_life,
    dynamic_load_factors,
    dynamic_load_rating,
    equivalent_dynamic_load,
    load_rating_factor,
    reliability_factor,
)
from .life import (
    BearingRatings,
    DutyCycleLife,
    RatingLife,
    bearing_ratings,
    duty_cycle_life,
    miner_life,
    rating_life,
    reference_load_distribution,
)
from .lubrication import (
    CONTAMINATION_CLASSES,
    DEFAULT_VISCOSITY_INDEX,
    ISO_VG_GRADES,
    contamination_factor,
    iso_vg_viscosity,
    kinematic_viscosity,
    life_modification_factor,
    rated_viscosity,
    viscosity_100_from_index,
    viscosity_index,
    viscosity_ratio,
    walther_constants,
    walther_viscosity,
)
from .reference import (
    ContactDynamicLoads,
    EquivalentContactLoads,
    contact_dynamic_loads,
    equivalent_contact_loads,
    reference_rating_life,
)
from .static import (
    FATIGUE_CONTACT_STRESS,
    MINIMUM_STATIC_SAFETY,
    STATIC_CONTACT_STRESS,
    RatingWarning,
    StaticLoadFactors,
    fatigue_load_limit,
    fatigue_load_limit_simplified,
    static_equivalent_load,
    static_load_factor,
    static_load_factors,
    static_load_rating,
    static_safety_factor,
)

__all__ = [
    "CONTAMINATION_CLASSES",
    "DEFAULT_VISCOSITY_INDEX",
    "FATIGUE_CONTACT_STRESS",
    "ISO_VG_GRADES",
    "MATERIAL_FACTOR",
    "MINIMUM_STATIC_SAFETY",
    "STATIC_CONTACT_STRESS",
    "BearingRatings",
    "ContactDynamicLoads",
    "DutyCycleLife",
    "DynamicLoadFactors",
    "EquivalentContactLoads",
    "RatingLife",
    "RatingWarning",
    "StaticLoadFactors",
    "basic_rating_life",
    "bearing_ratings",
    "contact_dynamic_loads",
    "contamination_factor",
    "duty_cycle_life",
    "dynamic",
    "dynamic_load_factors",
    "dynamic_load_rating",
    "equivalent_contact_loads",
    "equivalent_dynamic_load",
    "fatigue_load_limit",
    "fatigue_load_limit_simplified",
    "iso_vg_viscosity",
    "kinematic_viscosity",
    "life",
    "life_modification_factor",
    "load_rating_factor",
    "lubrication",
    "miner_life",
    "rated_viscosity",
    "rating_life",
    "reference",
    "reference_load_distribution",
    "reference_rating_life",
    "reliability_factor",
    "static",
    "static_equivalent_load",
    "static_load_factor",
    "static_load_factors",
    "static_load_rating",
    "static_safety_factor",
    "viscosity_100_from_index",
    "viscosity_index",
    "viscosity_ratio",
    "walther_constants",
    "walther_viscosity",
]
