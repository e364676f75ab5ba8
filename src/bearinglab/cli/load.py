"""Command line of the combined-load model (issue 11): ``load-distribution`` and ``bearing-set``.

``load-distribution`` solves one bearing under (F_x, F_y, F_z, M_x, M_y) at rest or at speed
(:func:`bearinglab.quasistatic.combined.combined_analysis`): a table per ball, the displacement and the
5 x 5 stiffness, a polar plot of the ball loads (``--plot``), and the ROSS coefficient file over a list of
speeds (``--ross``, :mod:`bearinglab.quasistatic.rotordynamics`). ``bearing-set`` does the same for a
preloaded DB / DF / DT set (:func:`bearinglab.quasistatic.sets.set_analysis`). The columns are
:func:`bearinglab.tables.load_distribution`; the figure is :func:`bearinglab.plots.load_distribution.ball_loads`.

Commands
--------
COMMANDS   the ``load-distribution`` and ``bearing-set`` commands, by name (the application adds them)
"""

import math
import types
import warnings
from pathlib import Path
from typing import Annotated

import typer

from ..errors import InputError
from . import _mounting as mo
from ._common import (
    FIGURE_SUFFIXES,
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
    OuterConformity,
    OuterRadius,
    PitchDiameter,
    RadialLoadOpt,
    add_notes,
    check_output,
    choice,
    console,
    emit_json,
    five_loads,
    inputs_echo,
    parse_length,
    parse_speeds,
    print_warnings,
    resolve_bearing,
    table,
)

__all__ = ["COMMANDS"]

SpeedOpt = Annotated[str, typer.Option("--speed", "-n", help="Inner-ring speed, e.g. '6000 rpm' (a list '0, 6000, 12000 rpm' with --ross).")]
FirstBallOpt = Annotated[str, typer.Option("--first-ball-angle", help="Azimuth of ball 0 from +x, e.g. '0 deg'.")]
StiffnessAtOpt = Annotated[str, typer.Option("--stiffness-at", help="operating (Hertz constants at each contact's angle; default) | free (at α0, ISO/TS 16281).")]
PlotOpt = Annotated[Path | None, typer.Option("--plot", help="Polar plot of the ball loads into this PNG/PDF/SVG file.")]
_HELD = "Prescribed displacements (instead of the load on that freedom)"
DxOpt = Annotated[str | None, typer.Option("--dx", help="Hold delta_x at this value, e.g. '10 um' (instead of --fx).", rich_help_panel=_HELD)]
DyOpt = Annotated[str | None, typer.Option("--dy", help="Hold delta_y, e.g. '0 um' (instead of --fy).", rich_help_panel=_HELD)]
DzOpt = Annotated[str | None, typer.Option("--dz", help="Hold delta_z, from the concentric position (half the axial play included), e.g. '700 um' (instead of --fz).", rich_help_panel=_HELD)]
TiltXOpt = Annotated[str | None, typer.Option("--tilt-x", help="Hold theta_x, e.g. '0 mrad' (instead of --mx).", rich_help_panel=_HELD)]
TiltYOpt = Annotated[str | None, typer.Option("--tilt-y", help="Hold theta_y, e.g. '0 mrad' (instead of --my); --tilt-x/--tilt-y '0 mrad' hold the ring square.", rich_help_panel=_HELD)]
#: The freedoms, their load options, the JSON keys of their reactions and their displacement options.
_FREEDOMS = (("fx", "fx_N", "dx", "length"), ("fy", "fy_N", "dy", "length"), ("fz", "fz_N", "dz", "length"),
             ("mx", "mx_Nmm", "tilt-x", "angle"), ("my", "my_Nmm", "tilt-y", "angle"))


def _speeds(text, allow_list, pitch_diameter):
    w = parse_speeds(text, pitch_diameter=pitch_diameter)
    if w.size > 1 and not allow_list:
        raise InputError("speed: a list of speeds needs --ross FILE (one speed otherwise)")
    return w


def _solve(what, *args, **kwargs):
    """Run a model; return its result and every warning raised on the way (as messages)."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = what(*args, **kwargs)
    return result, [str(c.message) for c in caught]


def _inputs(b, loads, speed, phi0, **options):
    """The inputs as used, in engineering units (echoed in the JSON; :func:`inputs_echo`)."""
    from ..units import RPM

    fx, fy, fz, mx, my = loads
    return inputs_echo(b, fx_N=fx, fy_N=fy, fz_N=fz, mx_Nmm=mx * 1e3, my_Nmm=my * 1e3, speed_rpm=float(speed) / RPM,
                       first_ball_angle_deg=math.degrees(phi0), **options,
                       radial_clearance_um=None if b.radial_clearance is None else b.radial_clearance * 1e6,
                       reduced_modulus_GPa=b.reduced_modulus / 1e9)


def _warnings(b, loads, r, notes):
    """The analysis's warnings, those raised on the way and the plausibility limits (bearinglab.limits)."""
    import numpy as np

    from .. import limits

    z = np.shape(r.ball_load_inner)[-1]
    ok = np.ravel(np.asarray(getattr(r, "converged", True), dtype=bool)) & np.ones(np.size(loads) // 5, bool)
    if ok.any():
        def pick(name):
            return np.reshape(getattr(r, name), (-1, z))[ok]

        notes = [*notes, *limits.combined_warnings(b, np.reshape(loads, (-1, 5))[ok], pick("ball_load_inner"),
                                                   pick("ball_load_outer"), pick("contact_angle_inner"),
                                                   pick("contact_angle_outer"))]
    return list(dict.fromkeys(notes))


def _held(texts, given):
    """The prescribed displacements [m, rad] (NaN: free) from the five options, or None; ``given`` tells
    which load options were typed (a freedom takes a load or a displacement, not both)."""
    import numpy as np

    from ..units import parse_quantity

    if all(t is None for t in texts):
        return None
    held = np.full(5, np.nan)
    for k, ((load, _, name, kind), text) in enumerate(zip(_FREEDOMS, texts, strict=True)):
        if text is None:
            continue
        if given[k]:
            raise InputError(f"{name}: give --{load} or --{name}, not both (a freedom takes a load or a "
                             "displacement)")
        held[k] = parse_quantity(text, kind, name)
        if not np.isfinite(held[k]):
            raise InputError(f"{name} must be finite, got {text!r}")
    return held


def _reactions(reactions, held):
    """The reactions on the held freedoms, by JSON key (N, N mm); empty without held freedoms."""
    if held is None:
        return {}
    import numpy as np

    out = {}
    for k, (_, key, _, _) in enumerate(_FREEDOMS):
        if not np.isnan(held[k]):
            out[key] = float(reactions[k]) * (1e3 if key.endswith("Nmm") else 1.0)
    return out


def _prescribed_echo(held):
    """The prescribed displacements as typed, in engineering units (um, mrad), for the inputs echo."""
    if held is None:
        return {}
    import numpy as np

    keys = ("dx_um", "dy_um", "dz_um", "tilt_x_mrad", "tilt_y_mrad")
    scale = (1e6, 1e6, 1e6, 1e3, 1e3)
    return {"prescribed": {k: float(v * f) for k, v, f in zip(keys, held, scale, strict=True) if not np.isnan(v)}}


def _takeup_um(b):
    """Half the axial play, A sin(alpha0) [um]: the part of delta_z a thrust spends before any ball carries
    (displacements are counted from the concentric position, MASTA's convention; issue 20 item 11)."""
    from ..quasistatic import combined

    _, d, _, fi, fo, a0, _, _ = combined._bearing_args(b)
    return combined.axial_play_takeup(d, fi, fo, a0) * 1e6


def _set_takeup_um(bearings, orient):
    """The axial play inside the shaft's delta_z [um]: none for opposed bearings (the shaft is counted from
    the assembled set, play taken up or preloaded), else that of the bearing whose balls touch first."""
    import numpy as np

    if not np.all(orient == orient[0]):
        return 0.0
    return min(_takeup_um(b) for b in bearings)


def _with_takeup(doc, takeup_um, reactions=None):
    """``doc`` with ``axial_play_takeup_um`` after the tilts (so the elastic part is one subtraction) and,
    with ``reactions``, the reactions of the held freedoms after it."""
    out = {}
    for key, value in doc.items():
        out[key] = value
        if key == "tilt_y_mrad":
            out["axial_play_takeup_um"] = takeup_um
            if reactions is not None:
                out["reactions"] = reactions
    return out


def _case(r, k):
    """Case k of a batched LoadDistribution (cases on the first axis), as an object with one case's fields."""
    import numpy as np
    fields = {f: np.asarray(getattr(r, f))[k] for f in r._fields if f not in ("warnings", "azimuth")}
    return types.SimpleNamespace(**fields, azimuth=r.azimuth, warnings=r.warnings)


@mo.mounting_options
def load_distribution(
    fx: FxOpt = None, fy: FyOpt = None, fz: FzOpt = None, mx: MxOpt = None, my: MyOpt = None,
    radial_load: RadialLoadOpt = None, axial_load: AxialLoadOpt = None,
    dx: DxOpt = None, dy: DyOpt = None, dz: DzOpt = None, tilt_x: TiltXOpt = None, tilt_y: TiltYOpt = None,
    speed: SpeedOpt = "0 rpm", first_ball_angle: FirstBallOpt = "0 deg", stiffness_at: StiffnessAtOpt = "operating",
    bearing: BearingName = None, bearing_file: BearingFile = None, catalog: CatalogFile = None,
    balls: Balls = None, ball_diameter: BallDiameter = None, pitch_diameter: PitchDiameter = None,
    inner_groove_radius: InnerRadius = None, outer_groove_radius: OuterRadius = None,
    inner_conformity: InnerConformity = None, outer_conformity: OuterConformity = None,
    contact_angle: ContactAngle = None, radial_clearance: Clearance = None, ball_material: BallMaterial = None,
    plot: PlotOpt = None,
    ross: Annotated[Path | None, typer.Option("--ross", help="Write the ROSS BearingElement coefficients (JSON, SI) over the --speed list to this .json file.")] = None,
    json_out: JsonFlag = False,
):
    """Ball bearing under combined load (5-DOF): displacement, ball loads, contact angles, pressures, stiffness."""
    import numpy as np

    from .. import plots, tables
    from ..plots import load_distribution as load_plots
    from ..quasistatic import combined, rotordynamics
    from ..units import parse_quantity
    b = resolve_bearing(bearing, bearing_file, catalog, balls, ball_diameter, pitch_diameter, inner_groove_radius,
                        outer_groove_radius, inner_conformity, outer_conformity, contact_angle, radial_clearance,
                        ball_material)
    loads = five_loads(fx, fy, fz, mx, my, radial_load, axial_load)
    held = _held((dx, dy, dz, tilt_x, tilt_y), (fx is not None or radial_load is not None, fy is not None,
                                                fz is not None or axial_load is not None, mx is not None,
                                                my is not None))
    w = _speeds(speed, ross is not None, b.require("pitch_diameter"))
    b, mounted = mo.operating_bearing(b, w.max())  # issue 23: the operating clearance (at the highest speed)
    phi0 = parse_quantity(first_ball_angle, "angle", "first-ball-angle")
    choice("stiffness-at", stiffness_at, combined.STIFFNESS_AT)
    if plot is not None:
        check_output(plot, "plot", FIGURE_SUFFIXES, inputs=(bearing_file, catalog))
    if ross is not None:
        check_output(ross, "ross", (".json",), inputs=(bearing_file, catalog))
    cases = np.broadcast_to(loads, w.shape + (5,))
    r, notes = _solve(combined.combined_analysis, b, cases, w, first_ball_angle=phi0, stiffness_at=stiffness_at,
                      prescribed_displacement=held)
    notes = _warnings(b, np.reshape(r.loads, (-1, 5)), r, [*r.warnings, *notes])
    docs = []
    for k in range(w.size):
        case = _case(r, k)
        docs.append({**_with_takeup(tables.load_distribution(case), _takeup_um(b),
                                    _reactions(np.reshape(r.reactions, (-1, 5))[k], held)), **mounted,
                     "inputs": _inputs(b, loads, w[k], phi0, stiffness_at=stiffness_at, **_prescribed_echo(held)),
                     "warnings": notes})
    if ross is not None:
        rotordynamics.write_coefficients(rotordynamics.from_stiffness(np.reshape(r.stiffness, (-1, 5, 5)), w), ross)
    if plot is not None:
        title = f"Bearing {b.designation}: ball loads at {docs[0]['inputs']['speed_rpm']:g} rpm"
        plots.save(load_plots.ball_loads(_case(r, 0), title=title), plot)
    if json_out:
        emit_json(docs[0] if w.size == 1 else docs)
        return
    for doc in docs:
        _print_case(f"Bearing {b.designation} at {doc['inputs']['speed_rpm']:g} rpm", doc)
    print_warnings(notes)
    _print_written(plot, ross)


def _f(x, spec):
    return "—" if x is None else format(x, spec)


def _sig(x, decimals=2):
    """``x`` with ``decimals`` decimals, or more where that would leave fewer than four significant digits
    (a light load, a soft direction): a load or a stiffness is never printed as 0.00 or 0.07."""
    if x is None:
        return "—"
    if x == 0 or not math.isfinite(x):
        return format(x, f".{decimals}f")
    return format(x, f".{min(max(decimals, 3 - math.floor(math.log10(abs(x)))), 12)}f")


def _print_case(title, doc, *, balls=True, body="ring", origin="concentric", extra=()):
    if balls:
        _print_balls(title, doc)
    _print_ring(title, doc, body, origin, extra)


def _print_balls(title, doc):
    table(f"{title}: ball loads", ["ball", "ψ [deg]", "Q_i [N]", "Q_o [N]", "α_i [deg]", "α_o [deg]",
                                   "p_i [MPa]", "p_o [MPa]"],
          [[str(j), _f(r["azimuth_deg"], ".2f"), _sig(r["load_inner_N"]), _sig(r["load_outer_N"]),
            _f(r["contact_angle_inner_deg"], ".3f"), _f(r["contact_angle_outer_deg"], ".3f"),
            _f(r["max_pressure_inner_MPa"], ".0f"), _f(r["max_pressure_outer_MPa"], ".0f")]
           for j, r in enumerate(doc["balls"])])


def _print_ring(title, doc, body="ring", origin="concentric", extra=()):
    """The ring (or shaft) table; ``origin`` names where the displacements are counted from."""
    rows = [*extra,
            [f"δ_x, δ_y, δ_z [µm] (from {origin})", ", ".join(_f(doc[f"displacement_{a}_um"], ".4f") for a in "xyz")],
            ["θ_x, θ_y [mrad]", f"{_f(doc['tilt_x_mrad'], '.5f')}, {_f(doc['tilt_y_mrad'], '.5f')}"]]
    if doc.get("axial_play_takeup_um") is not None:
        rows.append(["half axial play in δ_z [µm]", _f(doc["axial_play_takeup_um"], ".4f")])
    if doc.get("reactions"):
        names = {"fx_N": "F_x [N]", "fy_N": "F_y [N]", "fz_N": "F_z [N]", "mx_Nmm": "M_x [N·mm]",
                 "my_Nmm": "M_y [N·mm]"}
        for key, value in doc["reactions"].items():
            shown = 0.0 if abs(value) < 1e-6 else value  # below a micronewton: rounding of a symmetric case
            rows.append([f"reaction {names[key]} (held)", _sig(shown)])
    rows.append(["max ball load [N]", _sig(doc["max_ball_load_N"])])
    k = doc["stiffness_matrix"]
    if k is not None and k[0][0] is not None:
        rows += [["k_xx, k_yy, k_zz [N/µm]", ", ".join(_sig(k[i][i] * 1e-6) for i in range(3))],
                 ["k_θx, k_θy [N·m/mrad]", ", ".join(_sig(k[i][i] * 1e-3) for i in (3, 4))]]
    if "converged" in doc:
        rows.append(["converged (iterations, residual)",
                     f"{str(doc['converged']).lower()} ({doc['iterations']}, {_f(doc['residual'], '.1e')})"])
    table(f"{title}: {body}", ["quantity", "value"], rows, caption="--json for the full 5 × 5 stiffness matrix (SI)")


def _print_written(*paths):
    for path in paths:
        if path is not None:
            console.print(f"wrote {path}", highlight=False)


def bearing_set(
    bearing: Annotated[list[str], typer.Option("--bearing", "-b", help="Catalog name; once for every position, or once per bearing from -z to +z.", rich_help_panel="Bearing")],
    catalog: CatalogFile = None,
    arrangement: Annotated[str, typer.Option("--arrangement", help="DB (back-to-back) | DF (face-to-face) | DT (tandem).")] = "DB",
    spacing: Annotated[str | None, typer.Option("--spacing", help="Distance between bearing centres, e.g. '100 mm'; default: side by side, one ring width B (needs the bearings' width).")] = None,
    preload: Annotated[str | None, typer.Option("--preload", help="Axial preload force at rest, e.g. '500 N'.")] = None,
    preload_offset: Annotated[str | None, typer.Option("--preload-offset", help="Axial interference from first contact (zero preload) instead, e.g. '5 um'; negative is axial play.")] = None,
    fx: FxOpt = None, fy: FyOpt = None, fz: FzOpt = None, mx: MxOpt = None, my: MyOpt = None,
    radial_load: RadialLoadOpt = None, axial_load: AxialLoadOpt = None,
    speed: SpeedOpt = "0 rpm", first_ball_angle: FirstBallOpt = "0 deg", stiffness_at: StiffnessAtOpt = "operating",
    plot: PlotOpt = None,
    json_out: JsonFlag = False,
    shaft_fit: mo.ShaftFitOpt = None, housing_fit: mo.HousingFitOpt = None,
    shaft_interference: mo.ShaftInterferenceOpt = None, housing_interference: mo.HousingInterferenceOpt = None,
    shaft_bore: mo.ShaftBoreOpt = None, housing_outside_diameter: mo.HousingOutsideDiameterOpt = None,
    shaft_material: mo.ShaftMaterialOpt = None, housing_material: mo.HousingMaterialOpt = None,
    tolerance_class: mo.ToleranceClassOpt = None,
    inner_ring_temperature: mo.InnerTempOpt = None, outer_ring_temperature: mo.OuterTempOpt = None,
    ball_temperature: mo.BallTempOpt = None, shaft_temperature: mo.ShaftTempOpt = None,
    housing_temperature: mo.HousingTempOpt = None,
):
    """Preloaded bearing set (DB/DF/DT) on a rigid shaft: shaft displacement, each bearing's ball loads, set stiffness."""
    import numpy as np

    from .. import catalog as _catalog
    from .. import plots, tables
    from ..plots import load_distribution as load_plots
    from ..quasistatic import combined, sets
    from ..units import parse_quantity
    bl = [_catalog.get(name, catalog=catalog) for name in bearing]
    for b in bl:  # each estimated bearing says so in the result (cli._common.add_notes)
        add_notes(_catalog.provenance_notes(b))
    choice("arrangement", arrangement, tuple(sets.ARRANGEMENTS))
    s = None if spacing is None else parse_length(spacing, "spacing", zero=True)
    if preload is not None and preload_offset is not None:
        raise InputError("preload: give --preload or --preload-offset, not both")
    fp = 0.0 if preload is None else parse_quantity(preload, "force", "preload")
    if not fp >= 0:
        raise InputError(f"preload must be >= 0 [N] (an axial force at rest), got {fp:g} N")
    e = None if preload_offset is None else parse_quantity(preload_offset, "length", "preload-offset")
    loads = five_loads(fx, fy, fz, mx, my, radial_load, axial_load)
    # the speed guard of the largest bearing of the set (the highest d_m n)
    w = float(_speeds(speed, False, max(b.require("pitch_diameter") for b in bl))[0])
    phi0 = parse_quantity(first_ball_angle, "angle", "first-ball-angle")
    choice("stiffness-at", stiffness_at, combined.STIFFNESS_AT)
    if plot is not None:
        check_output(plot, "plot", FIGURE_SUFFIXES, inputs=(catalog,))
    st, notes = _solve(sets.set_analysis, bl if len(bl) > 1 else bl[0], loads, w, arrangement_kind=arrangement,
                       spacing=s, preload=fp, preload_displacement=e, first_ball_angle=phi0, stiffness_at=stiffness_at)
    # issue 23: fits, temperatures and speed change each bearing's clearance, and so the set's interference
    # the thermal expansion over the spacing needs its value: the solver's own when it is the default
    gap = s if s is not None else (float(np.diff(st.positions)[0]) if len(st.positions) > 1 else 0.0)
    mounted = mo.mounted_set(bl, st.preload_displacement, arrangement, gap, w, {
        "shaft_fit": shaft_fit, "housing_fit": housing_fit, "shaft_interference": shaft_interference,
        "housing_interference": housing_interference, "shaft_bore": shaft_bore,
        "housing_outside_diameter": housing_outside_diameter, "shaft_material": shaft_material,
        "housing_material": housing_material, "tolerance_class": tolerance_class,
        "inner_ring_temperature": inner_ring_temperature, "outer_ring_temperature": outer_ring_temperature,
        "ball_temperature": ball_temperature, "shaft_temperature": shaft_temperature,
        "housing_temperature": housing_temperature})
    if mounted is not None:
        bl = mounted.bearings
        st, notes = _solve(sets.set_analysis, bl if len(bl) > 1 else bl[0], loads, w, arrangement_kind=arrangement,
                           spacing=s, preload_displacement=mounted.interference, first_ball_angle=phi0,
                           stiffness_at=stiffness_at)
        notes = [*mounted.warnings, *notes]
    idle, _ = _solve(sets.set_analysis, bl if len(bl) > 1 else bl[0], [0.0] * 5, w, arrangement_kind=arrangement,
                     spacing=s, preload_displacement=st.preload_displacement, first_ball_angle=phi0,
                     stiffness_at=stiffness_at)
    operating_preload = float(abs(np.asarray(idle.bearing_loads)[0][2]))
    notes = list(dict.fromkeys([*st.warnings, *notes]))
    orient, pos = sets.arrangement(arrangement, np.diff(st.positions), len(st.bearings))
    gaps_mm = [float(g) * 1e3 for g in np.diff(st.positions)]
    spacing_mm = gaps_mm[0] if len(set(gaps_mm)) == 1 else gaps_mm  # one value, or one per gap
    names = [b.designation for b in bl] * (len(st.bearings) if len(bl) == 1 else 1)
    members = []
    for k, part in enumerate(st.bearings):
        bk = bl[k % len(bl)]
        ns = types.SimpleNamespace(**part, azimuth=combined.ball_azimuths(bk.n_balls, phi0))
        carried = st.bearing_loads[k]
        if bool(np.all(st.converged)):
            notes += [f"bearing {k}: {m}" for m in _warnings(bk, carried, ns, [])]
        members.append({"bearing": names[k], "orientation": int(orient[k]), "position_mm": float(pos[k] * 1e3) + 0.0,  # + 0.0: no -0
                        "loads": {"fx_N": carried[0], "fy_N": carried[1], "fz_N": carried[2],
                                  "mx_Nmm": carried[3] * 1e3, "my_Nmm": carried[4] * 1e3},
                        **_with_takeup(tables.load_distribution(ns), _takeup_um(bk))})
    doc = {**_with_takeup(tables.load_distribution(_shaft(st)), _set_takeup_um(bl, orient)),
           "preload_offset_um": st.preload_displacement * 1e6,
           "operating_preload_N": operating_preload,
           **({} if mounted is None else {"operating_clearance_um": mounted.clearance * 1e6,
                                          "mounting": mounted.echo}),
           "bearings": members,
           "inputs": {**_inputs(bl[0], loads, w, phi0, stiffness_at=stiffness_at), "bearings": names,
                      "arrangement": arrangement, "spacing_mm": spacing_mm, "spacing_default": st.default_spacing,
                      "preload_N": fp,
                      "preload_offset_um": None if e is None else e * 1e6},
           "warnings": notes}
    del doc["balls"], doc["max_ball_load_N"]
    if plot is not None:
        plots.save(load_plots.ball_loads(types.SimpleNamespace(**st.bearings[0], azimuth=combined.ball_azimuths(
            bl[0].n_balls, phi0)), title=f"Set {arrangement}: ball loads of bearing 0 ({names[0]})"), plot)
    if json_out:
        emit_json(tables.json_value(doc))
        return
    for k, m in enumerate(members):
        _print_case(f"Bearing {k} ({m['bearing']}, orientation {m['orientation']:+d}, z = {m['position_mm']:g} mm)", m)
    loads = [m["max_ball_load_N"] for m in members if m["max_ball_load_N"] is not None]
    gaps = ", ".join(f"{g:g}" for g in np.atleast_1d(spacing_mm))
    spacing_row = ["spacing [mm]", f"{gaps} ({'default: side by side, one width' if st.default_spacing else 'given'})"]
    origin = "concentric" if np.all(orient == orient[0]) else "assembled"
    _print_case(f"Set {arrangement} of {len(members)}", {**doc, "max_ball_load_N": max(loads, default=None)},
                balls=False, body="shaft", origin=origin, extra=[spacing_row])  # the balls: each bearing's table
    print_warnings(notes)
    _print_written(plot)


def _shaft(st):
    """The shaft of a set as the fields :func:`bearinglab.tables.load_distribution` reads."""
    import numpy as np
    return types.SimpleNamespace(displacement=st.displacement, stiffness=st.stiffness, converged=st.converged,
                                 residual=st.residual, iterations=st.iterations, ball_load_inner=np.zeros(1),
                                 azimuth=np.zeros(0), ball_load_outer=np.zeros(0),
                                 contact_angle_inner=np.zeros(0), contact_angle_outer=np.zeros(0),
                                 max_pressure_inner=np.zeros(0), max_pressure_outer=np.zeros(0))


#: The commands of this module, as the application adds them.
COMMANDS = {"load-distribution": load_distribution, "bearing-set": bearing_set}
