"""Command line of the lubricant film (issue 24): ``film``.

The EHL film (Hamrock and Dowson) at every ball's inner and outer contact of a bearing under
(F_x, F_y, F_z, M_x, M_y) at a speed (:func:`bearinglab.film.film_analysis`): the ball loads and angles
of the load distribution (quasi-static at the speed, or at rest), the lubricant's viscosity (given, or of
an ISO VG oil at a temperature; ``--temperature auto`` takes the steady bearing temperature of
:mod:`bearinglab.thermal`), its pressure-viscosity coefficient and the surface roughness. The columns are
:func:`bearinglab.tables.film`.

Commands
--------
COMMANDS   the ``film`` command, by name (the application adds it)
"""

from typing import Annotated

import typer

from ..errors import InputError
from ._common import (
    AxialLoadOpt,
    BallDiameter,
    BallMaterial,
    Balls,
    BearingFile,
    BearingName,
    CatalogFile,
    Clearance,
    ContactAngle,
    FxOpt,
    FyOpt,
    FzOpt,
    InnerConformity,
    InnerRadius,
    JsonFlag,
    MxOpt,
    MyOpt,
    OilOpt,
    OuterConformity,
    OuterRadius,
    PitchDiameter,
    RadialLoadOpt,
    TemperatureOpt,
    Viscosity100Opt,
    ViscosityIndexOpt,
    ViscosityOpt,
    choice,
    emit_json,
    five_loads,
    inputs_echo,
    lubricant_viscosity,
    parse_speeds,
    print_warnings,
    resolve_bearing,
    table,
)

__all__ = ["COMMANDS"]

_FILM = "Lubricant film"
DensityOpt = Annotated[str | None, typer.Option("--density", help="Oil density, e.g. '870 kg/m^3' (default 870 kg/m^3, a typical mineral oil: an estimate).", rich_help_panel=_FILM)]
DynamicViscosityOpt = Annotated[str | None, typer.Option("--dynamic-viscosity", help="Dynamic viscosity at the bearing temperature, e.g. '0.04 Pa*s' or '40 cP' (instead of --viscosity).", rich_help_panel=_FILM)]
AlphaOpt = Annotated[str | None, typer.Option("--pressure-viscosity-coefficient", help="alpha, e.g. '2.3e-8 m^2/N' or '23 1/GPa' (default: Wooster's estimate for mineral oils).", rich_help_panel=_FILM)]
RoughnessOpt = Annotated[str | None, typer.Option("--roughness", help="RMS roughness R_q of balls and raceways alike, e.g. '0.1 um' (default 0.1 um each).", rich_help_panel=_FILM)]
RoughnessBallOpt = Annotated[str | None, typer.Option("--roughness-ball", help="R_q of the balls, e.g. '0.05 um'.", rich_help_panel=_FILM)]
RoughnessRaceOpt = Annotated[str | None, typer.Option("--roughness-race", help="R_q of the raceways, e.g. '0.15 um'.", rich_help_panel=_FILM)]
LoadsAtOpt = Annotated[str, typer.Option("--loads-at", help="speed (quasi-static ball loads at the speed; default) | rest (loads at rest, pure rolling).", rich_help_panel=_FILM)]

_AUTO = "Temperature auto (thermal balance)"
#: Default density of a mineral oil [kg/m^3] when none is given: a typical value (0.86-0.89 g/cm^3 at
#: 15 degC for ISO VG 10-460 mineral oils), an estimate labelled as one in the output.
DEFAULT_DENSITY = 870.0
_DEFAULT_ROUGHNESS = 0.1e-6
_UM = 1e-6
# absurd-value guards: beyond these no lubricating oil exists (water 1 mPa s, bitumen 1e5 Pa s)
_ETA_RANGE = (1e-4, 1e4)  # Pa s
_RHO_RANGE = (500.0, 2500.0)  # kg/m^3
_ALPHA_RANGE = (1e-9, 1e-7)  # 1/Pa: 1 to 100 1/GPa
_RQ_MAX = 10e-6  # m


def _in_range(name, value, bounds, unit, scale=1.0):
    if not (bounds[0] <= value <= bounds[1]):
        raise InputError(f"{name} must be in [{bounds[0] * scale:g}, {bounds[1] * scale:g}] [{unit}], got "
                         f"{value * scale:g} {unit}")
    return value


def density(text):
    """The oil density [kg/m^3] and whether it was assumed."""
    from ..units import parse_quantity

    if text is None:
        return DEFAULT_DENSITY, True
    return _in_range("density", parse_quantity(text, "density", "density"), _RHO_RANGE, "kg/m^3"), False


def lubricant(viscosity, dynamic_viscosity, oil, temperature, viscosity_index, viscosity_100, density_text):
    """(eta [Pa s], nu [m^2/s] or None, description, inputs, notes) from the lubricant options."""
    from ..units import parse_quantity

    rho, assumed = density(density_text)
    notes = []
    if dynamic_viscosity is not None:
        if any(x is not None for x in (viscosity, oil, temperature, viscosity_index, viscosity_100)):
            raise InputError("dynamic-viscosity: give --dynamic-viscosity, or --viscosity, or --oil with "
                             "--temperature, not more than one")
        eta = _in_range("dynamic-viscosity", parse_quantity(dynamic_viscosity, "dynamic_viscosity",
                                                              "dynamic-viscosity"), _ETA_RANGE, "mPa s", 1e3)
        return eta, None, f"eta = {eta * 1e3:.4g} mPa s (given)", {"dynamic_viscosity_mPas": eta * 1e3}, notes
    lv = lubricant_viscosity(viscosity, oil, temperature, viscosity_index, viscosity_100, required=True)
    eta = lv.viscosity * rho
    _in_range("viscosity", eta, _ETA_RANGE, "mPa s (dynamic, nu rho)", 1e3)
    if assumed:
        notes.append(f"density: not given, so {DEFAULT_DENSITY:g} kg/m^3 (a typical mineral oil, an estimate) "
                     "turns the kinematic viscosity into the dynamic one; give --density")
    inputs = {**lv.inputs, "density_kg_m3": rho, "density_assumed": assumed, "dynamic_viscosity_mPas": eta * 1e3}
    return eta, lv.viscosity, f"{lv.description}; eta = {eta * 1e3:.4g} mPa s", inputs, notes


def roughness(both, ball, race):
    """(Rq_ball, Rq_race) [m] from --roughness or --roughness-ball/--roughness-race."""
    from ._common import parse_length

    if both is not None and (ball is not None or race is not None):
        raise InputError("roughness: give --roughness, or --roughness-ball and --roughness-race, not both")
    if both is not None:
        ball = race = both
    out = []
    for name, text in (("roughness-ball" if both is None else "roughness", ball),
                       ("roughness-race" if both is None else "roughness", race)):
        rq = _DEFAULT_ROUGHNESS if text is None else parse_length(text, name, "um", zero=True)
        out.append(_in_range(name, rq, (0.0, _RQ_MAX), "um", 1e6))
    if out[0] == 0 and out[1] == 0:
        raise InputError("roughness must not be 0 for both surfaces [um] (Lambda would be infinite)")
    return tuple(out)


def pressure_viscosity(text):
    from ..units import parse_quantity

    if text is None:
        return None
    return _in_range("pressure-viscosity-coefficient", parse_quantity(text, "inverse_pressure",
                     "pressure-viscosity-coefficient"), _ALPHA_RANGE, "1/GPa", 1e9)


def film(
    fx: FxOpt = None, fy: FyOpt = None, fz: FzOpt = None, mx: MxOpt = None, my: MyOpt = None,
    radial_load: RadialLoadOpt = None, axial_load: AxialLoadOpt = None,
    speed: Annotated[str | None, typer.Option("--speed", "-n", help="Inner-ring speed, e.g. '6000 rpm' (a list '3000, 6000 rpm' for several cases).")] = None,
    viscosity: ViscosityOpt = None, oil: OilOpt = None, temperature: TemperatureOpt = None,
    viscosity_index: ViscosityIndexOpt = None, viscosity_100: Viscosity100Opt = None,
    dynamic_viscosity: DynamicViscosityOpt = None, density_text: DensityOpt = None,
    pressure_viscosity_coefficient: AlphaOpt = None,
    roughness_both: RoughnessOpt = None, roughness_ball: RoughnessBallOpt = None, roughness_race: RoughnessRaceOpt = None,
    loads_at: LoadsAtOpt = "speed",
    ambient: Annotated[str | None, typer.Option("--ambient", help="With --temperature auto: the ambient (default 20 degC).", rich_help_panel=_AUTO)] = None,
    thermal_resistance: Annotated[str | None, typer.Option("--thermal-resistance", help="With --temperature auto: bearing to ambient, e.g. '0.5 K/W' (default: ISO 15312's reference heat flow).", rich_help_panel=_AUTO)] = None,
    lubrication: Annotated[str | None, typer.Option("--lubrication", help="grease | oil-air | oil-jet | oil-bath: a starvation-risk check (SKF's replenishment factor); with --temperature auto also the SKF model's (default oil-jet).", rich_help_panel=_FILM)] = None,
    skf_constants: Annotated[str | None, typer.Option("--skf-constants", help="With --temperature auto: SKF constants R1,R2,R3,S1,S2,S3 (angular contact).", rich_help_panel=_AUTO)] = None,
    bearing: BearingName = None, bearing_file: BearingFile = None, catalog: CatalogFile = None,
    balls: Balls = None, ball_diameter: BallDiameter = None, pitch_diameter: PitchDiameter = None,
    inner_groove_radius: InnerRadius = None, outer_groove_radius: OuterRadius = None,
    inner_conformity: InnerConformity = None, outer_conformity: OuterConformity = None,
    contact_angle: ContactAngle = None, radial_clearance: Clearance = None, ball_material: BallMaterial = None,
    json_out: JsonFlag = False,
):
    """EHL film (Hamrock-Dowson) at every ball's contacts: h_c, h_min, film parameter Lambda and regime."""
    import numpy as np

    from .. import film as film_model
    from .. import tables
    from ..film.analysis import LOADS_AT
    from ..units import RPM

    b = resolve_bearing(bearing, bearing_file, catalog, balls, ball_diameter, pitch_diameter, inner_groove_radius,
                        outer_groove_radius, inner_conformity, outer_conformity, contact_angle, radial_clearance,
                        ball_material)
    loads = five_loads(fx, fy, fz, mx, my, radial_load, axial_load)
    if speed is None:
        raise InputError("speed: give the inner-ring speed, e.g. --speed '6000 rpm' (no film forms at rest)")
    w = parse_speeds(speed, pitch_diameter=b.require("pitch_diameter"), zero=False)
    choice("loads-at", loads_at, LOADS_AT)
    rq_ball, rq_race = roughness(roughness_both, roughness_ball, roughness_race)
    alpha = pressure_viscosity(pressure_viscosity_coefficient)
    auto = temperature is not None and temperature.strip().lower() == "auto"
    if auto:
        eta, how, lub_inputs, notes = _auto_temperature(b, loads, w, oil, viscosity, dynamic_viscosity,
                                                        viscosity_index, viscosity_100, density_text, ambient,
                                                        thermal_resistance, lubrication or "oil-jet",
                                                        skf_constants)
        nu = eta / lub_inputs["density_kg_m3"]
    else:
        if any(x is not None for x in (ambient, thermal_resistance, skf_constants)):
            raise InputError("temperature: --ambient, --thermal-resistance and --skf-constants go with "
                             "--temperature auto (the thermal balance)")
        eta, nu, how, lub_inputs, notes = lubricant(viscosity, dynamic_viscosity, oil, temperature,
                                                   viscosity_index, viscosity_100, density_text)
    cases = np.broadcast_to(np.asarray(loads, dtype=float), w.shape + (5,))
    starve = {}
    if lubrication is not None:
        from ..friction.skf import LUBRICATION_METHODS

        choice("lubrication", lubrication, list(LUBRICATION_METHODS))
        if nu is None:
            nu = eta / density(density_text)[0]
        starve = {"lubrication": lubrication, "kinematic_viscosity": nu}
    r = _solve(film_model.film_analysis, b, cases, w, eta, alpha, roughness_ball=rq_ball, roughness_race=rq_race,
               loads_at=loads_at, **starve)
    notes = list(dict.fromkeys([*notes, *r.warnings]))
    docs = []
    for k in range(w.size):
        doc = tables.film(r, (k,))
        doc["inputs"] = inputs_echo(b, fx_N=loads[0], fy_N=loads[1], fz_N=loads[2], mx_Nmm=loads[3] * 1e3,
                                    my_Nmm=loads[4] * 1e3, speed_rpm=float(w[k]) / RPM, loads_at=loads_at,
                                    **lub_inputs, lubricant=how,
                                    pressure_viscosity_coefficient_per_GPa=None if alpha is None else alpha * 1e9,
                                    roughness_ball_um=rq_ball * 1e6, roughness_race_um=rq_race * 1e6)
        temps = lub_inputs.get("bearing_temperature_degC")
        if isinstance(temps, list):  # --temperature auto over several speeds: this case's temperature
            doc["inputs"]["bearing_temperature_degC"] = temps[k]
        doc["warnings"] = notes
        docs.append(doc)
    if json_out:
        emit_json(docs[0] if w.size == 1 else docs)
        return
    for doc in docs:
        _print(b, doc, how)
    print_warnings(notes)


def _auto_temperature(b, loads, w, oil, viscosity, dynamic_viscosity, viscosity_index, viscosity_100, density_text,
                      ambient, thermal_resistance, lubrication, skf_constants):
    """--temperature auto: the steady temperature of each case
    (:func:`bearinglab.calculations.temperature.steady_temperature`, as ``life`` takes it) and the oil's
    dynamic viscosity there; (eta per case, description, inputs, notes)."""
    import numpy as np

    from ..calculations.temperature import steady_temperature

    r, how, inputs, notes = steady_temperature(b, loads, w, oil, viscosity, viscosity_index, viscosity_100, ambient,
                                               thermal_resistance, lubrication, skf_constants,
                                               dynamic_viscosity=dynamic_viscosity)
    rho, assumed = density(density_text)
    if assumed:
        notes.append(f"density: not given, so {DEFAULT_DENSITY:g} kg/m^3 (a typical mineral oil, an estimate) "
                     "turns the kinematic viscosity into the dynamic one; give --density")
    inputs = {**inputs, "density_kg_m3": rho, "density_assumed": assumed}
    t = np.atleast_1d(r.temperature)
    nu = np.atleast_1d(r.kinematic_viscosity)
    text = (f"{how} at the steady temperature {', '.join(f'{x - 273.15:.1f}' for x in t)} degC (thermal balance): "
            f"nu = {', '.join(f'{x * 1e6:.4g}' for x in nu)} cSt")
    return nu * rho, text, inputs, [*notes, *r.warnings]


def _solve(model, *args, **kwargs):
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the result carries its warnings
        return model(*args, **kwargs)


def _f(x, spec):
    return "—" if x is None else format(x, spec)


def _print(b, doc, how):
    rpm = doc["inputs"]["speed_rpm"]
    table(f"Film of {b.designation} at {rpm:g} rpm",
          ["ball", "Q_i [N]", "Q_o [N]", "h_min,i [µm]", "h_min,o [µm]", "Λ_i", "Λ_o"],
          [[str(j), _f(r["load_inner_N"], ".1f"), _f(r["load_outer_N"], ".1f"), _f(r["film_min_inner_um"], ".4f"),
            _f(r["film_min_outer_um"], ".4f"), _f(r["lambda_inner"], ".2f"), _f(r["lambda_outer"], ".2f")]
           for j, r in enumerate(doc["balls"])],
          caption=f"{how}; --json for h_c, angles and velocities")
    table("Smallest film", ["quantity", "value"],
          [["h_min [µm]", _f(doc["film_min_um"], ".4f")], ["Λ_min", _f(doc["lambda_min"], ".3f")],
           ["regime", doc["regime"] or "—"]])


#: The ``film`` command, as the application adds it.
COMMANDS = {"film": film}
