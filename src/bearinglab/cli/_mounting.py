"""The mounting options every command shares: fits, seats, materials, temperatures (issue 23).

Options       ShaftFitOpt, HousingFitOpt, ShaftInterferenceOpt, HousingInterferenceOpt, ShaftBoreOpt,
              HousingOutsideDiameterOpt, ShaftMaterialOpt, HousingMaterialOpt, the five temperatures,
              ToleranceClassOpt, ClearanceClassOpt, ShaftRoughnessOpt, HousingRoughnessOpt
parse_temperature   a temperature option [K] ('60 degC', '333 K'; a bare number is degC)
mounting_options    decorator: adds the options to a command (load-distribution, life, high-speed, ...)
operating_bearing   inside such a command: the bearing at its probable operating clearance, and the JSON
mounted_set         the options of bearing-set applied to its bearings (MountedSet)
MountedInputs       the parsed options: tolerance limits, Mounting, Conditions, unmounted clearance range
mounted_inputs      the options of a command -> MountedInputs (None when no mounting option was given)

``bearinglab clearance`` takes all of them; a command that uses the operating clearance takes the same
options through this module, so that they mean the same everywhere. The physics is
:mod:`bearinglab.mounting`; nothing here computes beyond parsing and choosing the tables.
"""

from __future__ import annotations

import contextvars
import functools
import inspect
from typing import Annotated, NamedTuple

import typer

from ..calculations._mounting import (  # noqa: F401 -- shared with the calculations
    MountedInputs,
    mounted_inputs,
    parse_temperature,
)
from ..errors import InputError

__all__: list[str] = []  # private to the command line

_FIT = "Mounting: fits and seats"
_TEMP = "Mounting: temperatures (default 20 degC)"
ShaftFitOpt = Annotated[str | None, typer.Option("--shaft-fit", help="ISO 286 field of the shaft seat: g6 h5 h6 j5 j6 js5 js6 k5 k6 m5 m6 n6 p6.", rich_help_panel=_FIT)]
HousingFitOpt = Annotated[str | None, typer.Option("--housing-fit", help="ISO 286 field of the housing bore: F7 G6 G7 H6 H7 H8 J6 J7 JS6 JS7 K6 K7 M6 M7 N6 N7 P6 P7.", rich_help_panel=_FIT)]
ShaftInterferenceOpt = Annotated[str | None, typer.Option("--shaft-interference", help="Inner-ring interference instead of --shaft-fit: one value or 'least, largest', e.g. '5 um, 20 um' (negative: loose).", rich_help_panel=_FIT)]
HousingInterferenceOpt = Annotated[str | None, typer.Option("--housing-interference", help="Outer-ring interference instead of --housing-fit, as --shaft-interference.", rich_help_panel=_FIT)]
ShaftBoreOpt = Annotated[str | None, typer.Option("--shaft-bore", help="Bore of a hollow shaft, e.g. '20 mm' (default solid).", rich_help_panel=_FIT)]
HousingOutsideDiameterOpt = Annotated[str | None, typer.Option("--housing-outside-diameter", help="Outside diameter of the housing, e.g. '120 mm' (default: a thick housing).", rich_help_panel=_FIT)]
ShaftMaterialOpt = Annotated[str | None, typer.Option("--shaft-material", help="steel | structural_steel | aluminium (default steel).", rich_help_panel=_FIT)]
HousingMaterialOpt = Annotated[str | None, typer.Option("--housing-material", help="steel | structural_steel | aluminium (default steel).", rich_help_panel=_FIT)]
ShaftRoughnessOpt = Annotated[str | None, typer.Option("--shaft-roughness", help="Rz of shaft seat and ring bore for the smoothing of DIN 7190-1 (off by default), e.g. '4 um' or '4 um, 1.6 um'.", rich_help_panel=_FIT)]
HousingRoughnessOpt = Annotated[str | None, typer.Option("--housing-roughness", help="Rz of housing bore and ring outside, as --shaft-roughness.", rich_help_panel=_FIT)]
ToleranceClassOpt = Annotated[str | None, typer.Option("--tolerance-class", help="ISO 492 class of the bearing: Normal, P6, P5, P4 (default: the designation's, else Normal).", rich_help_panel=_FIT)]
ClearanceClassOpt = Annotated[str | None, typer.Option("--clearance-class", help="ISO 5753-1 class: C2, CN, C3, C4, C5 (default: the designation's, else CN).", rich_help_panel=_FIT)]
InnerTempOpt = Annotated[str | None, typer.Option("--inner-ring-temperature", help="e.g. '60 degC'.", rich_help_panel=_TEMP)]
OuterTempOpt = Annotated[str | None, typer.Option("--outer-ring-temperature", help="e.g. '50 degC'.", rich_help_panel=_TEMP)]
BallTempOpt = Annotated[str | None, typer.Option("--ball-temperature", help="Default: the mean of the rings.", rich_help_panel=_TEMP)]
ShaftTempOpt = Annotated[str | None, typer.Option("--shaft-temperature", help="Default: the inner ring's.", rich_help_panel=_TEMP)]
HousingTempOpt = Annotated[str | None, typer.Option("--housing-temperature", help="Default: the outer ring's.", rich_help_panel=_TEMP)]

_UM, _MM = 1e-6, 1e-3


class MountedSet(NamedTuple):
    """A bearing set with its mounting: the bearings at their operating clearance and the interference."""

    bearings: list
    interference: float
    """The set's axial interference in operation. [m]"""
    clearance: float
    """The probable operating diametral clearance of each bearing. [m]"""
    echo: dict
    warnings: list


def mounted_set(bearings, assembled_interference, arrangement, spacing, speed, options):
    """The mounting options of ``bearing-set`` applied to its (like) bearings; None without options."""
    if all(v is None for v in options.values()):
        return None
    if len({b.designation for b in bearings}) > 1:
        raise InputError("bearing: the mounting options need one bearing type for the whole set")
    from ..mounting import chain, preload

    b = bearings[0]
    inp = mounted_inputs(b, **options, speed=speed, require=True)
    r = chain.operating_range(inp.unmounted, inp.inner, inp.outer, inp.mounting, inp.conditions)
    p = r.probable
    reduction = float(p.fit_reduction + p.thermal_reduction + p.centrifugal_reduction)
    c = inp.conditions
    t_s = c.inner_temperature if c.shaft_temperature is None else c.shaft_temperature
    t_h = c.outer_temperature if c.housing_temperature is None else c.housing_temperature
    interference, clearance = preload.operating_interference(
        b, assembled_interference, reduction, arrangement_kind=arrangement, spacing=spacing,
        shaft_temperature=t_s, housing_temperature=t_h, shaft_expansion=inp.mounting.shaft.thermal_expansion,
        housing_expansion=inp.mounting.housing.thermal_expansion)
    new = [x.replace(radial_clearance=clearance) for x in bearings]
    echo = dict(inp.echo, unmounted_clearance_um=inp.unmounted[0] / _UM,
                clearance_reduction_um=reduction / _UM, fit_reduction_um=float(p.fit_reduction) / _UM,
                thermal_reduction_um=float(p.thermal_reduction) / _UM,
                centrifugal_reduction_um=float(p.centrifugal_reduction) / _UM,
                assembled_interference_um=assembled_interference / _UM, operating_interference_um=interference / _UM)
    notes = [n for n in r.warnings if "negative" not in n]  # an angular set runs preloaded by design
    return MountedSet(new, interference, clearance, echo, notes)


# ----------------------------------------------------------------------------- the options on any command
# name -> option type: every command that takes a bearing takes these through ``mounting_options``
_COMMAND_OPTIONS = {
    "shaft_fit": ShaftFitOpt, "housing_fit": HousingFitOpt, "shaft_interference": ShaftInterferenceOpt,
    "housing_interference": HousingInterferenceOpt, "shaft_bore": ShaftBoreOpt,
    "housing_outside_diameter": HousingOutsideDiameterOpt, "shaft_material": ShaftMaterialOpt,
    "housing_material": HousingMaterialOpt, "tolerance_class": ToleranceClassOpt,
    "clearance_class": ClearanceClassOpt, "inner_ring_temperature": InnerTempOpt,
    "outer_ring_temperature": OuterTempOpt, "ball_temperature": BallTempOpt, "shaft_temperature": ShaftTempOpt,
    "housing_temperature": HousingTempOpt,
}
_GIVEN = contextvars.ContextVar("bearinglab_mounting_options", default=None)


def mounting_options(command):
    """Add the mounting options to a command (keyword options after its own); inside the command,
    :func:`operating_bearing` reads them. The command's own code is unchanged otherwise."""
    sig = inspect.signature(command)
    extra = [inspect.Parameter(name, inspect.Parameter.KEYWORD_ONLY, default=None, annotation=kind)
             for name, kind in _COMMAND_OPTIONS.items() if name not in sig.parameters]
    params = [p.replace(kind=inspect.Parameter.KEYWORD_ONLY) if p.kind is inspect.Parameter.POSITIONAL_OR_KEYWORD
              else p for p in sig.parameters.values()]

    @functools.wraps(command)
    def wrapper(*args, **kwargs):
        given = {k: kwargs.pop(k) for k in list(kwargs) if k in _COMMAND_OPTIONS and k not in sig.parameters}
        token = _GIVEN.set(given)
        try:
            return command(*args, **kwargs)
        finally:
            _GIVEN.reset(token)

    wrapper.__signature__ = sig.replace(parameters=[*params, *extra])
    return wrapper


def operating_bearing(bearing, speed=0.0):
    """The bearing at its probable operating clearance under the command's mounting options, and the
    JSON entries to add (``operating_clearance_um`` and the range); ``(bearing, {})`` without options."""
    given = {k: v for k, v in (_GIVEN.get() or {}).items() if v is not None}
    if not given:
        return bearing, {}
    from ..mounting import chain

    inp = mounted_inputs(bearing, **given, speed=float(speed), require=True)
    r = chain.operating_range(inp.unmounted, inp.inner, inp.outer, inp.mounting, inp.conditions)
    e = float(r.probable.operating_clearance)
    if not e > 0:
        raise InputError(f"operating clearance must be > 0 [um] for this model, got {e / _UM:.3g} um (the fits and "
                         "temperatures preload the bearing); give a larger --clearance-class, or model a "
                         "preloaded pair with bearing-set")
    doc = {"operating_clearance_um": e / _UM,
           "operating_clearance_min_um": float(r.least.operating_clearance) / _UM,
           "operating_clearance_max_um": float(r.largest.operating_clearance) / _UM,
           "unmounted_clearance_um": [inp.unmounted[0] / _UM, inp.unmounted[1] / _UM],
           "mounting": inp.echo, "mounting_warnings": list(r.warnings)}
    return bearing.replace(radial_clearance=e), doc
