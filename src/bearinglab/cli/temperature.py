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
    fields_given,
    print_warnings,
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
LubricationOpt = Annotated[str | None, typer.Option("--lubrication", help="SKF model: oil-jet | oil-air | grease | oil-bath (with --oil-level; its drag loss from SKF's V_M diagram). Default oil-jet: the oil is a grade (the rule of every command: grease, oil-jet when an oil grade is given).", rich_help_panel=_HEAT)]
OilLevelOpt = Annotated[str | None, typer.Option("--oil-level", help="For --lubrication oil-bath: H from the lowest point of the outer raceway, e.g. '5 mm' (at most to the bearing's centre).", rich_help_panel=_HEAT)]
ReferenceSpeedOpt = Annotated[bool, typer.Option("--reference-speed", help="Also ISO 15312's thermal reference speed of the bearing by the SKF model (JSON: thermal_reference_speed_rpm).", rich_help_panel=_HEAT)]
ConstantsOpt = Annotated[str | None, typer.Option("--skf-constants", help="SKF geometry constants R1,R2,R3,S1,S2,S3 in place of SKF's tables (angular contact other than 40 deg needs them), e.g. '5e-7,1.9,1.9e-12,0.013,0.7,1.9e-12'.", rich_help_panel=_HEAT)]


def temperature(
    radial_load: RadialLoadOpt = None, axial_load: AxialLoadOpt = None,
    speed: Annotated[str | None, typer.Option("--speed", "-n", help="Inner-ring speed, e.g. '6000 rpm' (a list for several cases).")] = None,
    oil: OilOpt = None, viscosity_index: ViscosityIndexOpt = None, viscosity_100: Viscosity100Opt = None,
    lubrication: LubricationOpt = None, oil_level: OilLevelOpt = None, skf_constants: ConstantsOpt = None,
    ambient: AmbientOpt = "20 degC", thermal_resistance: ResistanceOpt = None, oil_flow: OilFlowOpt = None,
    oil_inlet_temperature: OilInletOpt = None, oil_heat_capacity: HeatCapacityOpt = None,
    density_text: OilDensityOpt = None, max_temperature: MaxTemperatureOpt = "150 degC",
    reference_speed: ReferenceSpeedOpt = False,
    bearing: BearingName = None, bearing_file: BearingFile = None, catalog: CatalogFile = None,
    json_out: JsonFlag = False,
):
    """Steady bearing temperature: SKF friction power at nu(T) = heat carried away; nu, kappa, runaway."""
    from ..calculations import parse
    from ..calculations import temperature as calculation

    # typer has read the options; the calculation checks each value by the command line's own rules
    # (its messages), not by the fields' ranges the web checks first
    given = fields_given("temperature", locals(), density="density_text")
    result = calculation.document(parse("temperature", given, check=False),
                                  bearing_file=bearing_file, catalog=catalog)
    if json_out:
        emit_json(result)
        return
    docs = result if isinstance(result, list) else [result]
    table(f"Steady temperature of {docs[0]['inputs']['bearing']}, {docs[0]['inputs']['lubricant']}",
          ["n [rpm]", "T [°C]", "ν [mm²/s]", "κ", "M [N·mm]", "P [W]", "iter."],
          [[f"{d['inputs']['speed_rpm']:g}", _f(d["bearing_temperature_degC"], ".2f"),
            _f(d["viscosity_mm2_s"], ".3g"), _f(d["kappa"], ".3g"), _f(d["friction_moment_Nmm"], ".4g"),
            _f(d["friction_power_W"], ".4g"), str(d["iterations"])] for d in docs],
          caption="P: friction power = heat carried away; — where no steady state exists (runaway)")
    if "reference_heat_flow_W" in docs[0]:  # --reference-speed: one value per bearing
        n_r = docs[0]["thermal_reference_speed_rpm"]
        console.print(f"Thermal reference speed (ISO 15312, SKF model): "
                      f"{'none found' if n_r is None else format(n_r, '.0f') + ' rpm'} at "
                      f"{docs[0]['reference_heat_flow_W']:.4g} W", highlight=False)
    print_warnings(docs[0]["warnings"])


def _f(x, spec):
    return "—" if x is None else format(x, spec)


#: The ``temperature`` command, as the application adds it.
COMMANDS = {"temperature": temperature}
