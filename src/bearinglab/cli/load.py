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


def _case(r, k):
    """Case k of a batched LoadDistribution (cases on the first axis), as an object with one case's fields."""
    import numpy as np
    fields = {f: np.asarray(getattr(r, f))[k] for f in r._fields if f not in ("warnings", "azimuth")}
    return types.SimpleNamespace(**fields, azimuth=r.azimuth, warnings=r.warnings)


def load_distribution(
    fx: FxOpt = None, fy: FyOpt = None, fz: FzOpt = None, mx: MxOpt = None, my: MyOpt = None,
    radial_load: RadialLoadOpt = None, axial_load: AxialLoadOpt = None,
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
    w = _speeds(speed, ross is not None, b.require("pitch_diameter"))
    phi0 = parse_quantity(first_ball_angle, "angle", "first-ball-angle")
    choice("stiffness-at", stiffness_at, combined.STIFFNESS_AT)
    if plot is not None:
        check_output(plot, "plot", FIGURE_SUFFIXES, inputs=(bearing_file, catalog))
    if ross is not None:
        check_output(ross, "ross", (".json",), inputs=(bearing_file, catalog))
    cases = np.broadcast_to(loads, w.shape + (5,))
    r, notes = _solve(combined.combined_analysis, b, cases, w, first_ball_angle=phi0, stiffness_at=stiffness_at)
    notes = _warnings(b, cases, r, [*r.warnings, *notes])
    docs = []
    for k in range(w.size):
        case = _case(r, k)
        docs.append({**tables.load_distribution(case),
                     "inputs": _inputs(b, loads, w[k], phi0, stiffness_at=stiffness_at), "warnings": notes})
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


def _print_case(title, doc, *, balls=True, body="ring"):
    if balls:
        _print_balls(title, doc)
    _print_ring(title, doc, body)


def _print_balls(title, doc):
    table(f"{title}: ball loads", ["ball", "ψ [deg]", "Q_i [N]", "Q_o [N]", "α_i [deg]", "α_o [deg]",
                                   "p_i [MPa]", "p_o [MPa]"],
          [[str(j), _f(r["azimuth_deg"], ".2f"), _sig(r["load_inner_N"]), _sig(r["load_outer_N"]),
            _f(r["contact_angle_inner_deg"], ".3f"), _f(r["contact_angle_outer_deg"], ".3f"),
            _f(r["max_pressure_inner_MPa"], ".0f"), _f(r["max_pressure_outer_MPa"], ".0f")]
           for j, r in enumerate(doc["balls"])])


def _print_ring(title, doc, body="ring"):
    rows = [["δ_x, δ_y, δ_z [µm]", ", ".join(_f(doc[f"displacement_{a}_um"], ".4f") for a in "xyz")],
            ["θ_x, θ_y [mrad]", f"{_f(doc['tilt_x_mrad'], '.5f')}, {_f(doc['tilt_y_mrad'], '.5f')}"],
            ["max ball load [N]", _sig(doc["max_ball_load_N"])]]
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
    spacing: Annotated[str, typer.Option("--spacing", help="Distance between bearing centres, e.g. '100 mm'.")] = "0 mm",
    preload: Annotated[str | None, typer.Option("--preload", help="Axial preload force at rest, e.g. '500 N'.")] = None,
    preload_offset: Annotated[str | None, typer.Option("--preload-offset", help="Axial interference from first contact (zero preload) instead, e.g. '5 um'; negative is axial play.")] = None,
    fx: FxOpt = None, fy: FyOpt = None, fz: FzOpt = None, mx: MxOpt = None, my: MyOpt = None,
    radial_load: RadialLoadOpt = None, axial_load: AxialLoadOpt = None,
    speed: SpeedOpt = "0 rpm", first_ball_angle: FirstBallOpt = "0 deg", stiffness_at: StiffnessAtOpt = "operating",
    plot: PlotOpt = None,
    json_out: JsonFlag = False,
):
    """Preloaded bearing set (DB/DF/DT) on a rigid shaft: shaft displacement, each bearing's ball loads, set stiffness."""
    import numpy as np

    from .. import catalog as _catalog
    from .. import plots, tables
    from ..plots import load_distribution as load_plots
    from ..quasistatic import combined, sets
    from ..units import parse_quantity
    bl = [_catalog.get(name, catalog=catalog) for name in bearing]
    choice("arrangement", arrangement, tuple(sets.ARRANGEMENTS))
    s = parse_length(spacing, "spacing", zero=True)
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
    notes = list(dict.fromkeys([*st.warnings, *notes]))
    orient, pos = sets.arrangement(arrangement, s, len(st.bearings))
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
                        **tables.load_distribution(ns)})
    doc = {**tables.load_distribution(_shaft(st)), "preload_offset_um": st.preload_displacement * 1e6,
           "bearings": members,
           "inputs": {**_inputs(bl[0], loads, w, phi0, stiffness_at=stiffness_at), "bearings": names,
                      "arrangement": arrangement, "spacing_mm": s * 1e3, "preload_N": fp,
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
    _print_case(f"Set {arrangement} of {len(members)}", {**doc, "max_ball_load_N": max(loads, default=None)},
                balls=False, body="shaft")  # the balls are in each bearing's table
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
