"""Roller bearings: cylindrical (N, NU, NJ, NUP), tapered (single row and pairs) and spherical (issue 32).

Modules
-------
bearing        RollerBearing: geometry, profile, envelope, catalogue ratings and factors, materials
geometry       tapered-roller angles, slice positions, roller profiles (logarithmic, crowned, flat, table)
contact        the ISO/TS 16281 lamina stiffness and the Hertz line contact (half width, pressure)
distribution   the batched 5-DOF load distribution and stiffness of the slice model (RollerSet)
analysis       the slice model of a RollerBearing: roller_analysis, bearing_roller_set
pairs          two tapered bearings on a rigid shaft, back to back or face to face, end play or preload
reactions      loads and stiffness at given displacements (the roller branch of bearinglab.reactions)
estimation     the roller set of a bearing known by its boundary dimensions and C0 (labelled estimate)

A roller bearing is a bearing with line contacts (slices) where a ball bearing has point contacts: the
5-DOF ring equilibrium uses the kernels of :mod:`bearinglab.quasistatic._ring`, the ratings and lives are in
:mod:`bearinglab.ratings` (``roller``, ``roller_reference``) and :mod:`bearinglab.life`, the friction in
:mod:`bearinglab.friction.skf_roller` and the film in :mod:`bearinglab.film.line_contact`. Spherical roller
bearings are covered by ratings, life and friction only. Every public name of the modules is reachable here.
"""

from . import analysis, bearing, contact, distribution, estimation, geometry, pairs, reactions
from .analysis import N_SLICES, bearing_roller_set, provenance, roller_analysis
from .bearing import DESIGNS, ROLLER_TYPES, RollerBearing
from .contact import (
    SLICE_CONSTANT,
    LineContact,
    contact_radii,
    line_contact,
    slice_loads,
    slice_stiffness,
)
from .distribution import (
    AXIAL_SUPPORTS,
    Equilibrium,
    RollerLoadDistribution,
    RollerSet,
    equilibrium,
    load_distribution,
    roller_azimuths,
    roller_set,
)
from .estimation import RULES, EstimatedRollerSet, estimate_roller_set, with_estimated_geometry
from .geometry import (
    PROFILES,
    TaperedAngles,
    crowned_drop,
    flat_drop,
    logarithmic_drop,
    slice_positions,
    table_drop,
    tapered_angles,
)
from .pairs import ARRANGEMENTS, PairAnalysis, pair_analysis, preload_gap
from .reactions import roller_reactions

__all__ = [
    "ARRANGEMENTS",
    "AXIAL_SUPPORTS",
    "DESIGNS",
    "N_SLICES",
    "PROFILES",
    "ROLLER_TYPES",
    "RULES",
    "SLICE_CONSTANT",
    "Equilibrium",
    "EstimatedRollerSet",
    "LineContact",
    "PairAnalysis",
    "RollerBearing",
    "RollerLoadDistribution",
    "RollerSet",
    "TaperedAngles",
    "analysis",
    "bearing",
    "bearing_roller_set",
    "contact",
    "contact_radii",
    "crowned_drop",
    "distribution",
    "equilibrium",
    "estimate_roller_set",
    "estimation",
    "flat_drop",
    "geometry",
    "line_contact",
    "load_distribution",
    "logarithmic_drop",
    "pair_analysis",
    "pairs",
    "preload_gap",
    "provenance",
    "reactions",
    "roller_analysis",
    "roller_azimuths",
    "roller_reactions",
    "roller_set",
    "slice_loads",
    "slice_positions",
    "slice_stiffness",
    "table_drop",
    "tapered_angles",
    "with_estimated_geometry",
]
