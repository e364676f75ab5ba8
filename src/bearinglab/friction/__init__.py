r"""Friction torque of ball bearings: one function per published model, and a dispatcher.

Classic models (:mod:`.classic`, spec 001 section 3)
----------------------------------------------------
static_load_factors, equivalent_static_load, combined_branch_governs   P0 = max(x0 Fr + y0 Fa, Fr)
handbook_friction_coefficient, one_term                T = mu P0 d / 2 (mu: reduced friction coefficient)
load_term_constants, load_term, speed_term, two_term   T = T0 + T_F
palmgren, speed_term_factor_from_palmgren              Palmgren's M0 from the viscosity

SKF four-term model (:mod:`.skf`)
---------------------------------
skf, skf_for_bearing                   M = M_rr + M_sl + M_seal + M_drag
series_constants, bearing_series, seal_constants, sliding_friction_coefficient   its parts and tables
angular_contact_constants              SKF's constants of an angular-contact type (single row 40 deg, ...)
self_aligning_constants                SKF's constants of a self-aligning series (12, 13, 22, 23, ...)
inlet_shear_heating_factor, replenishment_factor   Phi_ish and Phi_rs
drag_moment                            M_drag of an oil bath
drag_loss_factor (:mod:`.drag`)        V_M of SKF's diagram at H/d_m, for ball and roller bearings

SKF model of roller bearings (:mod:`.skf_roller`, issue 32)
-----------------------------------------------------------
skf_roller, skf_roller_for_bearing     the same four terms for cylindrical, tapered and spherical roller bearings
roller_series_constants, roller_drag_moment   SKF's constants by series; M_drag = 10 V_M K_roll B d_m^4 n^2

Dispatcher
----------
torque                                 call a model by name (``MODELS``)

Every name of the former module ``bearinglab.friction`` is re-exported here.
"""

from ..errors import InputError
from . import classic
from . import skf as skf_model
from . import skf_roller as skf_roller_model
from .classic import (
    ANGULAR_LOAD_TERM_BELOW_30,
    ANGULAR_LOAD_TERM_FROM_30,
    ANGULAR_STATIC_FACTORS,
    BEARING_TYPES,
    HANDBOOK_FRICTION_COEFFICIENTS,
    RADIAL_LOAD_TERM,
    RADIAL_STATIC_FACTORS,
    LoadTermConstants,
    StaticLoadFactors,
    TwoTermTorque,
    combined_branch_governs,
    equivalent_static_load,
    handbook_friction_coefficient,
    load_term,
    load_term_constants,
    one_term,
    palmgren,
    speed_term,
    speed_term_factor_from_palmgren,
    static_load_factors,
    two_term,
)
from .drag import MAX_LEVEL_RATIO, drag_loss_factor, drag_loss_table
from .skf import (
    ANGULAR_CONTACT_CONSTANTS,
    ANGULAR_SEAL_CONSTANTS,
    DEEP_GROOVE_CONSTANTS,
    LUBRICATION_METHODS,
    SEAL_CONSTANTS,
    SELF_ALIGNING_CONSTANTS,
    SKF_BEARING_TYPES,
    THRUST_BALL_CONSTANTS,
    SealConstants,
    SKFConstants,
    SKFTorque,
    angular_contact_constants,
    bearing_series,
    drag_moment,
    inlet_shear_heating_factor,
    replenishment_factor,
    seal_constants,
    self_aligning_constants,
    series_constants,
    skf,
    skf_for_bearing,
    sliding_friction_coefficient,
)
from .skf_roller import (
    CYLINDRICAL_CONSTANTS,
    ROLLER_EHL_COEFFICIENTS,
    ROLLER_SEAL_CONSTANTS,
    ROLLER_TYPE_CONSTANTS,
    SPHERICAL_CONSTANTS,
    TAPERED_CONSTANTS,
    RollerConstants,
    roller_drag_moment,
    roller_series_constants,
    skf_roller,
    skf_roller_for_bearing,
)

__all__ = [
    "ANGULAR_CONTACT_CONSTANTS",
    "ANGULAR_LOAD_TERM_BELOW_30",
    "ANGULAR_LOAD_TERM_FROM_30",
    "ANGULAR_SEAL_CONSTANTS",
    "ANGULAR_STATIC_FACTORS",
    "BEARING_TYPES",
    "CYLINDRICAL_CONSTANTS",
    "DEEP_GROOVE_CONSTANTS",
    "HANDBOOK_FRICTION_COEFFICIENTS",
    "LUBRICATION_METHODS",
    "MAX_LEVEL_RATIO",
    "MODELS",
    "RADIAL_LOAD_TERM",
    "RADIAL_STATIC_FACTORS",
    "ROLLER_EHL_COEFFICIENTS",
    "ROLLER_SEAL_CONSTANTS",
    "ROLLER_TYPE_CONSTANTS",
    "SEAL_CONSTANTS",
    "SELF_ALIGNING_CONSTANTS",
    "SKF_BEARING_TYPES",
    "SPHERICAL_CONSTANTS",
    "TAPERED_CONSTANTS",
    "THRUST_BALL_CONSTANTS",
    "LoadTermConstants",
    "RollerConstants",
    "SKFConstants",
    "SKFTorque",
    "SealConstants",
    "StaticLoadFactors",
    "TwoTermTorque",
    "angular_contact_constants",
    "bearing_series",
    "classic",
    "combined_branch_governs",
    "drag_loss_factor",
    "drag_loss_table",
    "drag_moment",
    "equivalent_static_load",
    "handbook_friction_coefficient",
    "inlet_shear_heating_factor",
    "load_term",
    "load_term_constants",
    "one_term",
    "palmgren",
    "replenishment_factor",
    "roller_drag_moment",
    "roller_series_constants",
    "seal_constants",
    "self_aligning_constants",
    "series_constants",
    "skf",
    "skf_for_bearing",
    "skf_model",
    "skf_roller",
    "skf_roller_for_bearing",
    "skf_roller_model",
    "sliding_friction_coefficient",
    "speed_term",
    "speed_term_factor_from_palmgren",
    "static_load_factors",
    "torque",
    "two_term",
]

#: Model name -> function, for :func:`torque` and the command line.
MODELS = {"one-term": one_term, "two-term": two_term, "palmgren": palmgren, "skf": skf}


def torque(model, *args, **kwargs):
    """Friction torque by the named model.

    Parameters
    ----------
    model : str
        One of :data:`MODELS`: ``"one-term"``, ``"two-term"``, ``"palmgren"``, ``"skf"``.
    *args, **kwargs : optional
        The arguments of that model's function.

    Returns
    -------
    float, ndarray or NamedTuple
        What the model's function returns (N m, or its NamedTuple of moments).

    Examples
    --------
    >>> print(f"{torque('one-term', 19.62, 5e-3) * 1e3:.6f} N*mm")
    0.073575 N*mm
    """
    if model not in MODELS:
        raise InputError(f"model must be one of {list(MODELS)}, got {model!r}")
    return MODELS[model](*args, **kwargs)
