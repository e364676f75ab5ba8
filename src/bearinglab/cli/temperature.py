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
    HOTTEST_OIL_DEGC,
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
    lubricant_viscosity,
    parse_speeds,
    parse_temperature,
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

#: Defaults of the oil's properties when not given: typical mineral-oil values, estimates labelled as such
#: in the output (density 0.86-0.89 g/cm^3, specific heat 1.8-2.1 kJ/(kg K) between 20 and 100 degC).
DEFAULT_DENSITY = 870.0
DEFAULT_HEAT_CAPACITY = 1950.0
_ZERO_C = 273.15
_LUBRICATIONS = ("oil-jet", "oil-air", "grease")
_HOTTEST = HOTTEST_OIL_DEGC  # the sanity bound on the balance's temperatures (issue 24)


def oil_reference_viscosities(oil, viscosity_index, viscosity_100):
    """(nu40, nu100 [m^2/s], description, inputs) of an ISO VG oil, by the shared oil options."""
    from ..ratings import lubrication

    if oil is None:
        raise InputError("oil: give --oil, an ISO VG grade (e.g. VG32), with --viscosity-index or --viscosity-100 "
                         "if known (its viscosity follows the temperature)")
    at100 = lubricant_viscosity(None, oil, "100 degC", viscosity_index, viscosity_100)
    nu100 = at100.viscosity
    grade = int(at100.inputs["oil"][2:])
    nu40 = lubrication.iso_vg_viscosity(grade)
    inputs = {k: v for k, v in at100.inputs.items() if k != "temperature_degC"}
    if "viscosity_index" in inputs:
        how = f"VG{grade}, VI {inputs['viscosity_index']:g}{' (assumed)' if inputs['viscosity_index_assumed'] else ''}"
    else:
        how = f"VG{grade}, nu100 {nu100 * 1e6:.4g} cSt"
    return nu40, nu100, how, inputs


def heat_options(b, ambient, thermal_resistance, oil_flow, oil_inlet_temperature, heat_capacity, density_text,
                 max_temperature):
    """The heat-balance options in SI, the notes on assumed values and the inputs echoed."""
    from .. import thermal
    from ..units import parse_quantity

    ta = parse_temperature(ambient, "ambient")
    t_max = parse_temperature(max_temperature, "max-temperature")
    if not t_max > ta:
        raise InputError(f"max-temperature must be above the ambient [degC], got {t_max - _ZERO_C:g} degC")
    if not t_max <= _ZERO_C + _HOTTEST:
        raise InputError(f"max-temperature must be <= {_HOTTEST:g} [degC], got {t_max - _ZERO_C:g} degC")
    notes, inputs = [], {"ambient_degC": ta - _ZERO_C, "max_temperature_degC": t_max - _ZERO_C}
    conductance = None
    if thermal_resistance is not None:
        r = parse_quantity(thermal_resistance, "thermal_resistance", "thermal-resistance")
        if not 1e-4 <= r <= 1e4:
            raise InputError(f"thermal-resistance must be in [0.0001, 10000] [K/W], got {r:g} K/W")
        conductance, inputs["thermal_resistance_K_W"] = 1.0 / r, r
    g_oil, t_in = 0.0, None
    if oil_flow is not None:
        q = parse_quantity(oil_flow, "volume_flow", "oil-flow")
        if not 0.0 <= q <= 1e-2:
            raise InputError(f"oil-flow must be in [0, 600] [l/min], got {q * 6e4:g} l/min")
        rho = DEFAULT_DENSITY if density_text is None else parse_quantity(density_text, "density", "density")
        if not 500.0 <= rho <= 2500.0:
            raise InputError(f"density must be in [500, 2500] [kg/m^3], got {rho:g} kg/m^3")
        cp = DEFAULT_HEAT_CAPACITY if heat_capacity is None else parse_quantity(heat_capacity, "specific_heat",
                                                                              "oil-heat-capacity")
        if not 500.0 <= cp <= 5000.0:
            raise InputError(f"oil-heat-capacity must be in [500, 5000] [J/(kg K)], got {cp:g} J/(kg K)")
        for name, text, value in (("density", density_text, DEFAULT_DENSITY),
                                  ("oil-heat-capacity", heat_capacity, DEFAULT_HEAT_CAPACITY)):
            if text is None:
                notes.append(f"{name}: not given, so {value:g} (a typical mineral oil, an estimate) is used for "
                             "the heat the oil flow carries; give --" + name)
        g_oil = thermal.oil_flow_conductance(q, rho, cp)
        inputs.update(oil_flow_l_min=q * 6e4, density_kg_m3=rho, oil_heat_capacity_J_kgK=cp)
        if oil_inlet_temperature is not None:
            t_in = parse_temperature(oil_inlet_temperature, "oil-inlet-temperature")
            if not t_in <= _ZERO_C + _HOTTEST:
                raise InputError(f"oil-inlet-temperature must be <= {_HOTTEST:g} [degC], got {t_in - _ZERO_C:g} degC")
            inputs["oil_inlet_temperature_degC"] = t_in - _ZERO_C
    elif oil_inlet_temperature is not None or heat_capacity is not None or density_text is not None:
        raise InputError("oil-flow: --oil-inlet-temperature, --oil-heat-capacity and --density describe an oil "
                         "flow; give --oil-flow")
    return {"ambient": ta, "conductance": conductance, "oil_flow_conductance": g_oil,
            "oil_inlet_temperature": t_in, "maximum_temperature": t_max}, notes, inputs


def skf_options(b, lubrication, constants):
    """The SKF model's options for the bearing: its lubrication method and, for angular contact, the
    constants given (else SKF's single-row ones, for 40 deg bearings only: others refused in one line)."""
    from .. import friction

    if lubrication == "oil-bath":
        raise InputError("lubrication: oil-bath is not covered by `temperature` yet (SKF's drag loss needs V_M "
                         "from the catalogue's chart); use oil-jet, oil-air or grease")
    if lubrication not in _LUBRICATIONS:
        raise InputError(f"lubrication must be one of {list(_LUBRICATIONS)}, got {lubrication!r}")
    out = {"lubrication": lubrication}
    if constants is not None:
        try:
            values = [float(x) for x in constants.split(",")]
        except ValueError:
            values = []
        if len(values) != 6 or not all(v >= 0 and v < 1e6 for v in values):
            raise InputError(f"skf-constants must be six numbers >= 0, R1,R2,R3,S1,S2,S3, got {constants!r}")
        r1, r2, r3, s1, s2, s3 = values
        out["constants"] = friction.SKFConstants(r1, r2, s1, s2, r3, s3)
    elif b.type != "radial":  # SKF's table covers single-row 40 deg bearings; others are refused in one line
        friction.angular_contact_constants(b.contact_angle)
    return out


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
