"""Load ratings and rating life of ball bearings: ISO 76, ISO 281 and ISO/TS 16281.

Modules
-------
static         C0 and f0 (ISO 76), Cu (ISO 281 annex B), P0 and the static safety factor s0
dynamic        C and f_c, X / Y / e and P of every ball-bearing type, Ca of thrust ball bearings, L10 and the
               reliability factor a1 (ISO 281)
lubrication    oil viscosity (ISO VG, ASTM D2270 viscosity index, ASTM D341), nu1 and kappa, e_C classes, a_ISO (ISO 281)
reference      ISO/TS 16281 reference rating life from the ball loads
roller         roller bearings: ISO 281 C (10/3), ISO 76 C0, X / Y / e, Cu, a_ISO; paired tapered bearings
roller_reference  ISO/TS 16281 reference rating life of roller bearings, summed over the laminae
minimum_load   the minimum load of a running ball bearing (SKF's rules)
bearing        the ratings of one BallBearing or RollerBearing: catalog values first, else from the geometry

Every public function of these modules is also reachable here, e.g. ``ratings.static_load_rating``. SI
throughout; lives in revolutions and durations in seconds.

The analysis of a bearing (``rating_life``, ``duty_cycle_life``, ...) composes these
formulas with the load distribution of :mod:`bearinglab.quasistatic`, which builds on them, so it lives one
layer up, in :mod:`bearinglab.life`. Its names are still reachable here (and ``ratings.life``), with a
:class:`DeprecationWarning`, for one release.
"""

import importlib
import warnings

from . import (
    bearing,
    dynamic,
    lubrication,
    minimum_load,
    reference,
    roller,
    roller_reference,
    static,
)
from .bearing import BearingRatings, bearing_ratings
from .dynamic import (
    MATERIAL_FACTOR,
    DynamicLoadFactors,
    basic_rating_life,
    dynamic_axial_load_rating,
    dynamic_load_factors,
    dynamic_load_rating,
    equivalent_dynamic_load,
    load_rating_factor,
    reliability_factor,
    thrust_load_rating_factor,
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
from .minimum_load import (
    general_minimum_load,
    minimum_axial_load,
    minimum_load_rules,
    minimum_load_warnings,
    minimum_radial_load,
)
from .reference import (
    ContactDynamicLoads,
    EquivalentContactLoads,
    contact_dynamic_loads,
    equivalent_contact_loads,
    reference_rating_life,
)
from .roller import (
    INDUCED_AXIAL_FACTORS,
    ROLLER_MATERIAL_FACTOR,
    PairedAxialLoads,
    RollerLoadFactors,
    induced_axial_load,
    paired_axial_loads,
    roller_dynamic_load_rating,
    roller_equivalent_load,
    roller_fatigue_load_limit,
    roller_life_modification_factor,
    roller_load_factors,
    roller_load_rating_factor,
    roller_rating_life,
    roller_static_equivalent_load,
    roller_static_load_rating,
)
from .roller_reference import (
    LaminaEquivalentLoads,
    RollerContactDynamicLoads,
    lamina_equivalent_loads,
    roller_contact_dynamic_loads,
    roller_reference_rating_life,
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
    "INDUCED_AXIAL_FACTORS",
    "ISO_VG_GRADES",
    "MATERIAL_FACTOR",
    "MINIMUM_STATIC_SAFETY",
    "ROLLER_MATERIAL_FACTOR",
    "STATIC_CONTACT_STRESS",
    "BearingRatings",
    "ContactDynamicLoads",
    "DynamicLoadFactors",
    "EquivalentContactLoads",
    "LaminaEquivalentLoads",
    "PairedAxialLoads",
    "RatingWarning",
    "RollerContactDynamicLoads",
    "RollerLoadFactors",
    "StaticLoadFactors",
    "basic_rating_life",
    "bearing",
    "bearing_ratings",
    "contact_dynamic_loads",
    "contamination_factor",
    "dynamic",
    "dynamic_axial_load_rating",
    "dynamic_load_factors",
    "dynamic_load_rating",
    "equivalent_contact_loads",
    "equivalent_dynamic_load",
    "fatigue_load_limit",
    "fatigue_load_limit_simplified",
    "general_minimum_load",
    "induced_axial_load",
    "iso_vg_viscosity",
    "kinematic_viscosity",
    "lamina_equivalent_loads",
    "life_modification_factor",
    "load_rating_factor",
    "lubrication",
    "minimum_axial_load",
    "minimum_load",
    "minimum_load_rules",
    "minimum_load_warnings",
    "minimum_radial_load",
    "paired_axial_loads",
    "rated_viscosity",
    "reference",
    "reference_rating_life",
    "reliability_factor",
    "roller",
    "roller_contact_dynamic_loads",
    "roller_dynamic_load_rating",
    "roller_equivalent_load",
    "roller_fatigue_load_limit",
    "roller_life_modification_factor",
    "roller_load_factors",
    "roller_load_rating_factor",
    "roller_rating_life",
    "roller_reference",
    "roller_reference_rating_life",
    "roller_static_equivalent_load",
    "roller_static_load_rating",
    "static",
    "static_equivalent_load",
    "static_load_factor",
    "static_load_factors",
    "static_load_rating",
    "static_safety_factor",
    "thrust_load_rating_factor",
    "viscosity_100_from_index",
    "viscosity_index",
    "viscosity_ratio",
    "walther_constants",
    "walther_viscosity",
]

#: The names of the bearing's life analysis, moved to :mod:`bearinglab.life` (issue 28: the analysis builds
#: on the quasi-static model, which builds on these formulas; one package each way would be a cycle).
_MOVED = frozenset({"DutyCycleLife", "RatingLife", "duty_cycle_life", "miner_life", "rating_life",
                    "reference_load_distribution", "life"})


def __getattr__(name):
    """The moved names, from :mod:`bearinglab.life`, with a DeprecationWarning (removed in the next release).

    Loaded by name on first use, so that this package never imports the layer above it.
    """
    if name in _MOVED:
        warnings.warn(f"bearinglab.ratings.{name} moved to bearinglab.life"
                      f"{'' if name == 'life' else '.' + name}; the old name goes in the next release",
                      DeprecationWarning, stacklevel=2)
        moved = importlib.import_module("bearinglab.life")
        return moved if name == "life" else getattr(moved, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
