"""The mounting options every command shares: fits, seats, materials, temperatures (issue 23).

Options       ShaftFitOpt, HousingFitOpt, ShaftInterferenceOpt, HousingInterferenceOpt, ShaftBoreOpt,
              HousingOutsideDiameterOpt, ShaftMaterialOpt, HousingMaterialOpt, the five temperatures,
              ToleranceClassOpt, ClearanceClassOpt, ShaftRoughnessOpt, HousingRoughnessOpt
parse_temperature   a temperature option [K] ('60 degC', '333 K'; a bare number is degC)
mounting_options    decorator: adds the options to a command (load-distribution, life, high-speed, ...)
given_options       inside such a command: its mounting options as typed (for a calculation's fields)
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
from typing import Annotated

import typer

from ..calculations import _mounting as _calc_mounting
from ..calculations._mounting import (  # noqa: F401 -- the commands import them from here
    MountedInputs,
    MountedSet,
    mounted_inputs,
    mounted_set,
    parse_temperature,
)

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


def given_options():
    """The mounting options of the running command as typed (name -> text; None: not given)."""
    return dict(_GIVEN.get() or {})


def operating_bearing(bearing, speed=0.0):
    """The bearing at its probable operating clearance under the command's mounting options, and the
    JSON entries to add (``operating_clearance_um`` and the range); ``(bearing, {})`` without options
    (:func:`bearinglab.calculations._mounting.operating_bearing`)."""
    return _calc_mounting.operating_bearing(bearing, speed, _GIVEN.get())
