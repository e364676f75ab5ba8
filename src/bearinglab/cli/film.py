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
    emit_json,
    fields_given,
    print_warnings,
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
    lubrication: Annotated[str | None, typer.Option("--lubrication", help="grease | oil-air | oil-jet | oil-bath: a starvation-risk check (SKF's replenishment factor); with --temperature auto also the SKF model's (default oil-jet: the oil is a grade; the rule of every command: grease, oil-jet when an oil grade is given).", rich_help_panel=_FILM)] = None,
    skf_constants: Annotated[str | None, typer.Option("--skf-constants", help="With --temperature auto: SKF constants R1,R2,R3,S1,S2,S3 (angular contact).", rich_help_panel=_AUTO)] = None,
    bearing: BearingName = None, bearing_file: BearingFile = None, catalog: CatalogFile = None,
    balls: Balls = None, ball_diameter: BallDiameter = None, pitch_diameter: PitchDiameter = None,
    inner_groove_radius: InnerRadius = None, outer_groove_radius: OuterRadius = None,
    inner_conformity: InnerConformity = None, outer_conformity: OuterConformity = None,
    contact_angle: ContactAngle = None, radial_clearance: Clearance = None, ball_material: BallMaterial = None,
    json_out: JsonFlag = False,
):
    """EHL film (Hamrock-Dowson) at every ball's contacts: h_c, h_min, film parameter Lambda and regime."""
    from ..calculations import film as calculation
    from ..calculations import parse

    # typer has read the options; the calculation checks each value by the command line's own rules
    # (its messages), not by the fields' ranges the web checks first
    given = fields_given("film", locals(), density="density_text", roughness="roughness_both")
    result = calculation.document(parse("film", given, check=False),
                                  bearing_file=bearing_file, catalog=catalog)
    if json_out:
        emit_json(result)
        return
    docs = result if isinstance(result, list) else [result]
    for doc in docs:
        _print(doc)
    print_warnings(docs[0]["warnings"])


def _f(x, spec):
    return "—" if x is None else format(x, spec)


def _print(doc):
    rpm = doc["inputs"]["speed_rpm"]
    table(f"Film of {doc['inputs']['bearing']} at {rpm:g} rpm",
          ["ball", "Q_i [N]", "Q_o [N]", "h_min,i [µm]", "h_min,o [µm]", "Λ_i", "Λ_o"],
          [[str(j), _f(r["load_inner_N"], ".1f"), _f(r["load_outer_N"], ".1f"), _f(r["film_min_inner_um"], ".4f"),
            _f(r["film_min_outer_um"], ".4f"), _f(r["lambda_inner"], ".2f"), _f(r["lambda_outer"], ".2f")]
           for j, r in enumerate(doc["balls"])],
          caption=f"{doc['inputs']['lubricant']}; --json for h_c, angles and velocities")
    table("Smallest film", ["quantity", "value"],
          [["h_min [µm]", _f(doc["film_min_um"], ".4f")], ["Λ_min", _f(doc["lambda_min"], ".3f")],
           ["regime", doc["regime"] or "—"]])


#: The ``film`` command, as the application adds it.
COMMANDS = {"film": film}
