"""Command line of the bearing temperature (issue 24): ``temperature``.

The steady temperature of a bearing where the SKF friction power at the viscosity of that temperature
equals the heat carried away (:func:`bearinglab.thermal.thermal_balance`): to the ambient through a
thermal resistance (or ISO 15312's reference heat flow), and by an oil flow. The oil is an ISO VG grade
with its viscosity index or its viscosity at 100 degC (the shared oil options of ``life``). Where no
steady state exists below the safe limit, a thermal-runaway warning and no number.

Commands
--------
COMMANDS   the ``temperature`` command, by name (the application adds it)
"""

from typing import Annotated

import typer

from ..errors import InputError
from ._common import (
    AxialLoadOpt,
    BearingFile,
    BearingName,
    CatalogFile,
    JsonFlag,
    OilOpt,
    RadialLoadOpt,
    Viscosity100Opt,
    ViscosityIndexOpt,
    console,
    emit_json,
    inputs_echo,
    parse_speeds,
    print_warnings,
    resolve_bearing,
    table,
)

__all__ = ["COMMANDS"]

_HEAT = "Heat balance"
AmbientOpt = Annotated[str, typer.Option("--ambient", help="Ambient temperature, e.g. '20 degC'.", rich_help_panel=_HEAT)]
ResistanceOpt = Annotated[str | None, typer.Option("--thermal-resistance", help="Bearing to ambient, e.g. '0.5 K/W' (default: ISO 15312's reference heat flow of the bearing).", rich_help_panel=_HEAT)]
OilFlowOpt = Annotated[str | None, typer.Option("--oil-flow", help="Oil jet or circulation flow through the bearing, e.g. '0.5 l/min'.", rich_help_panel=_HEAT)]
OilInletOpt = Annotated[str | None, typer.Option("--oil-inlet-temperature", help="Of the oil flow (default: the ambient), e.g. '40 degC'.", rich_help_panel=_HEAT)]
HeatCapacityOpt = Annotated[str | None, typer.Option("--oil-heat-capacity", help="c_p of the oil (default 1950 J/(kg*K), a mineral oil: an estimate).", rich_help_panel=_HEAT)]
OilDensityOpt = Annotated[str | None, typer.Option("--density", help="Oil density (default 870 kg/m^3, a mineral oil: an estimate).", rich_help_panel=_HEAT)]
MaxTemperatureOpt = Annotated[str, typer.Option("--max-temperature", help="Safe limit: no steady state below it is thermal runaway, e.g. '150 degC'.", rich_help_panel=_HEAT)]
LubricationOpt = Annotated[str, typer.Option("--lubrication", help="SKF model: oil-jet (default) | oil-air | grease (oil bath: refused, its drag loss needs SKF's V_M chart).", rich_help_panel=_HEAT)]
ReferenceSpeedOpt = Annotated[bool, typer.Option("--reference-speed", help="Also ISO 15312's thermal reference speed of the bearing by the SKF model (JSON: thermal_reference_speed_rpm).", rich_help_panel=_HEAT)]
ConstantsOpt = Annotated[str | None, typer.Option("--skf-constants", help="SKF geometry constants R1,R2,R3,S1,S2,S3 in place of SKF's tables (angular contact other than 40 deg needs them), e.g. '5e-7,1.9,1.9e-12,0.013,0.7,1.9e-12'.", rich_help_panel=_HEAT)]

from ..calculations.temperature import (  # noqa: F401 -- shared with film and life (temperature auto)
    _ZERO_C,
    DEFAULT_DENSITY,
    DEFAULT_HEAT_CAPACITY,
    heat_options,
    oil_reference_viscosities,
    skf_options,
)


def radial_axial(radial_load, axial_load):
    from ..units import parse_quantity

    fr = 0.0 if radial_load is None else parse_quantity(radial_load, "force", "radial-load")
    fa = 0.0 if axial_load is None else parse_quantity(axial_load, "force", "axial-load")
    for name, v in (("radial-load", fr), ("axial-load", fa)):
        if not v >= 0:
            raise InputError(f"{name} must be >= 0 [N], got {v:g} N")
    return fr, fa


def temperature(
    radial_load: RadialLoadOpt = None, axial_load: AxialLoadOpt = None,
    speed: Annotated[str | None, typer.Option("--speed", "-n", help="Inner-ring speed, e.g. '6000 rpm' (a list for several cases).")] = None,
    oil: OilOpt = None, viscosity_index: ViscosityIndexOpt = None, viscosity_100: Viscosity100Opt = None,
    lubrication: LubricationOpt = "oil-jet", skf_constants: ConstantsOpt = None,
    ambient: AmbientOpt = "20 degC", thermal_resistance: ResistanceOpt = None, oil_flow: OilFlowOpt = None,
    oil_inlet_temperature: OilInletOpt = None, oil_heat_capacity: HeatCapacityOpt = None,
    density_text: OilDensityOpt = None, max_temperature: MaxTemperatureOpt = "150 degC",
    reference_speed: ReferenceSpeedOpt = False,
    bearing: BearingName = None, bearing_file: BearingFile = None, catalog: CatalogFile = None,
    json_out: JsonFlag = False,
):
    """Steady bearing temperature: SKF friction power at nu(T) = heat carried away; nu, kappa, runaway."""
    from .. import thermal
    from ..units import RPM

    b = resolve_bearing(bearing, bearing_file, catalog)
    if speed is None:
        raise InputError("speed: give the inner-ring speed, e.g. --speed '6000 rpm'")
    fr, fa = radial_axial(radial_load, axial_load)
    w = parse_speeds(speed, zero=False, pitch_diameter=b.pitch_diameter or b.mean_diameter)
    nu40, nu100, how, oil_inputs = oil_reference_viscosities(oil, viscosity_index, viscosity_100)
    heat, notes, heat_inputs = heat_options(b, ambient, thermal_resistance, oil_flow, oil_inlet_temperature,
                                            oil_heat_capacity, density_text, max_temperature)
    r = thermal.thermal_balance(b, fr, fa, w, heat.pop("ambient"), nu40, nu100, **heat,
                                **skf_options(b, lubrication, skf_constants))
    notes = list(dict.fromkeys([*notes, *r.warnings]))
    extra = {}
    if reference_speed:  # ISO 15312 (bearinglab.thermal.thermal_reference_speed); one value per bearing
        ref = thermal.thermal_reference_speed(b, **{k: v for k, v in skf_options(b, lubrication, skf_constants).items()
                                                  if k == "constants"})
        extra = {"thermal_reference_speed_rpm": _json(ref.speed / RPM),
                 "reference_heat_flow_W": _json(ref.reference_heat_flow)}
        notes = list(dict.fromkeys([*notes, *ref.warnings]))
    docs = [_doc(r, k, w.size) | extra | {"inputs": inputs_echo(b, radial_load_N=fr, axial_load_N=fa,
                                                         speed_rpm=float(w[k]) / RPM, lubrication=lubrication,
                                                         **oil_inputs, lubricant=how, **heat_inputs),
                                 "warnings": notes} for k in range(w.size)]
    if json_out:
        emit_json(docs[0] if w.size == 1 else docs)
        return
    table(f"Steady temperature of {b.designation}, {how}",
          ["n [rpm]", "T [°C]", "ν [mm²/s]", "κ", "M [N·mm]", "P [W]", "iter."],
          [[f"{d['inputs']['speed_rpm']:g}", _f(d["bearing_temperature_degC"], ".2f"),
            _f(d["viscosity_mm2_s"], ".3g"), _f(d["kappa"], ".3g"), _f(d["friction_moment_Nmm"], ".4g"),
            _f(d["friction_power_W"], ".4g"), str(d["iterations"])] for d in docs],
          caption="P: friction power = heat carried away; — where no steady state exists (runaway)")
    if extra:
        n_r = extra["thermal_reference_speed_rpm"]
        console.print(f"Thermal reference speed (ISO 15312, SKF model): "
                      f"{'none found' if n_r is None else format(n_r, '.0f') + ' rpm'} at "
                      f"{extra['reference_heat_flow_W']:.4g} W", highlight=False)
    print_warnings(notes)


def _json(x):
    from ..tables import json_value

    return json_value(float(x))


def _f(x, spec):
    return "—" if x is None else format(x, spec)


def _doc(r, k, n):
    import numpy as np

    from ..tables import json_value

    def pick(name, scale=1.0, shift=0.0):
        return json_value(float(np.atleast_1d(getattr(r, name))[k]) * scale + shift)

    return {"bearing_temperature_degC": pick("temperature", shift=-_ZERO_C),
            "viscosity_mm2_s": pick("kinematic_viscosity", 1e6), "friction_power_W": pick("friction_power"),
            "heat_dissipated_W": pick("heat_dissipated"), "friction_moment_Nmm": pick("friction_moment", 1e3),
            "kappa": pick("viscosity_ratio"), "iterations": int(np.atleast_1d(r.iterations)[k]),
            "steady": bool(np.atleast_1d(r.steady)[k])}


#: The ``temperature`` command, as the application adds it.
COMMANDS = {"temperature": temperature}
