"""Command line of the combined-load model (issue 11): ``load-distribution`` and ``bearing-set``.

``load-distribution`` solves one bearing under (F_x, F_y, F_z, M_x, M_y) at rest or at speed
(:func:`bearinglab.quasistatic.combined.combined_analysis`): a table per ball, the displacement and the
5 x 5 stiffness, a polar plot of the ball loads (``--plot``), and the ROSS coefficient file over a list of
speeds (``--ross``, :mod:`bearinglab.quasistatic.rotordynamics`). ``bearing-set`` does the same for a
preloaded DB / DF / DT set (:func:`bearinglab.quasistatic.sets.set_analysis`). The columns are
:func:`bearinglab.tables.load_distribution`; the figure is :func:`bearinglab.plots.load_distribution.ball_loads`.
The documents (and the figures, drawn from them) are :mod:`bearinglab.calculations.load_distribution` and
:mod:`bearinglab.calculations.bearing_set`, the web's too; this module reads the options and prints.

Commands
--------
COMMANDS   the ``load-distribution`` and ``bearing-set`` commands, by name (the application adds them)
"""

import math

from ._common import (
    FIGURE_SUFFIXES,
    BearingFile,
    CatalogFile,
    FileOption,
    JsonFlag,
    check_output,
    console,
    emit_json,
    parse_speeds,
    print_warnings,
    run_calculation,
    table,
)
from ._options import command

__all__ = ["COMMANDS"]

PlotFile = FileOption("--plot", "Polar plot of the ball loads (a roller bearing: the roller loads and the lamina "
                                "pressures) into this PNG/PDF/SVG file.")


def load_distribution(
    given, *, bearing_file: BearingFile = None, catalog: CatalogFile = None, plot: PlotFile = None,
    ross: FileOption("--ross", "Write the ROSS BearingElement coefficients (JSON, SI) over the --speed list "
                     "(e.g. '0, 6000, 12000 rpm') to this .json file.") = None,
    json_out: JsonFlag = False,
):
    """Ball bearing under combined load (5-DOF): displacement, ball loads, contact angles, pressures, stiffness."""
    import numpy as np

    from .. import plots
    from ..calculations import load_distribution as calculation
    from ..quasistatic import rotordynamics

    if plot is not None:
        check_output(plot, "plot", FIGURE_SUFFIXES, inputs=(bearing_file, catalog))
    if ross is not None:
        check_output(ross, "ross", (".json",), inputs=(bearing_file, catalog))
    doc = run_calculation("load-distribution", given, calculation.document, catalog=catalog,
                          bearing_file=bearing_file, speeds=ross is not None)
    docs = doc if isinstance(doc, list) else [doc]
    if ross is not None:  # the speeds the document was computed at (checked there)
        stiffness = np.array([d["stiffness_matrix"] for d in docs], dtype=float)
        speeds = parse_speeds(given["speed"])  # the list the documents were computed at
        rotordynamics.write_coefficients(rotordynamics.from_stiffness(stiffness, speeds), ross)
    if plot is not None:
        plots.save(calculation.figure(docs[0]), plot)
    if json_out:
        emit_json(doc)
        return
    for d in docs:
        _print_case(f"Bearing {d['inputs']['bearing']} at {d['inputs']['speed_rpm']:g} rpm", d)
    print_warnings(docs[0]["warnings"])
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
    if "rollers" in doc:  # a roller bearing (issue 32)
        _print_rollers(title, doc)
        if doc.get("operating_clearance_um") is not None:
            extra = [*extra, ["operating clearance (probable) [µm]", _f(doc["operating_clearance_um"], ".4f")]]
        _print_ring(title, doc, body, origin, extra)
        return
    if balls:
        _print_balls(title, doc)
    _print_ring(title, doc, body, origin, extra)


def _print_rollers(title, doc):
    """The table per roller of a roller bearing: azimuth, roller load, the highest lamina pressure and where
    along the roller it is (from the roller's middle, towards +z)."""
    positions = doc["slice_positions_mm"]

    def peak(r):
        p = [x if x is not None else -1.0 for x in r["slice_pressures_MPa"]]
        top = max(range(len(p)), key=p.__getitem__)
        return "—" if not r["load_N"] else _f(positions[top], ".2f")

    table(f"{title}: roller loads ({doc['slices']} slices per roller)",
          ["roller", "ψ [deg]", "Q [N]", "p_max [MPa]", "at s [mm]"],
          [[str(j), _f(r["azimuth_deg"], ".2f"), _sig(r["load_N"]), _f(r["max_pressure_MPa"], ".0f"), peak(r)]
           for j, r in enumerate(doc["rollers"])])


def _print_balls(title, doc):
    balls = doc["balls"]
    rows = bool(balls) and "row" in balls[0]  # the other ball types: a ball per row (a four-point bearing's diagonal)
    per_row = len(balls) // len({r["row"] for r in balls}) if rows else len(balls)
    table(f"{title}: ball loads", [*(["row"] if rows else []), "ball", "ψ [deg]", "Q_i [N]", "Q_o [N]", "α_i [deg]",
                                   "α_o [deg]", "p_i [MPa]", "p_o [MPa]"],
          [[*([str(r["row"])] if rows else []), str(j % per_row),
            _f(r["azimuth_deg"], ".2f"), _sig(r["load_inner_N"]), _sig(r["load_outer_N"]),
            _f(r["contact_angle_inner_deg"], ".3f"), _f(r["contact_angle_outer_deg"], ".3f"),
            _f(r["max_pressure_inner_MPa"], ".0f"), _f(r["max_pressure_outer_MPa"], ".0f")]
           for j, r in enumerate(balls)])


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
    if "max_roller_load_N" in doc:  # a roller bearing
        rows += [["max roller load [N]", _sig(doc["max_roller_load_N"])],
                 ["max lamina pressure [MPa]", _f(doc["max_pressure_MPa"], ".0f")]]
        if doc.get("rib_load_N"):
            rows.append(["axial load on the ribs [N]", _sig(doc["rib_load_N"])])
    else:
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


def bearing_set(given, *, catalog: CatalogFile = None, plot: PlotFile = None, json_out: JsonFlag = False):
    """Preloaded bearing set (DB/DF/DT) on a rigid shaft: shaft displacement, each bearing's ball loads, set stiffness."""
    import numpy as np

    from .. import plots
    from ..calculations import bearing_set as calculation

    if plot is not None:
        check_output(plot, "plot", FIGURE_SUFFIXES, inputs=(catalog,))
    doc = run_calculation("bearing-set", given, calculation.document, catalog=catalog)
    if plot is not None:
        plots.save(calculation.figure(doc), plot)
    if json_out:
        emit_json(doc)
        return
    if "iso281" in doc:  # a pair of tapered roller bearings (issue 32)
        _print_pair(doc)
        _print_written(plot)
        return
    members = doc["bearings"]
    for k, m in enumerate(members):
        _print_case(f"Bearing {k} ({m['bearing']}, orientation {m['orientation']:+d}, z = {m['position_mm']:g} mm)", m)
    loads = [m["max_ball_load_N"] for m in members if m["max_ball_load_N"] is not None]
    spacing_mm = doc["inputs"]["spacing_mm"]
    gaps = ", ".join(f"{g:g}" for g in np.atleast_1d(spacing_mm))
    default = doc["inputs"]["spacing_default"]
    spacing_row = ["spacing [mm]", f"{gaps} ({'default: side by side, one width' if default else 'given'})"]
    orient = [m["orientation"] for m in members]
    origin = "concentric" if all(o == orient[0] for o in orient) else "assembled"
    _print_case(f"Set {doc['inputs']['arrangement']} of {len(members)}", {**doc, "max_ball_load_N": max(loads, default=None)},
                balls=False, body="shaft", origin=origin, extra=[spacing_row])  # the balls: each bearing's table
    print_warnings(doc["warnings"])
    _print_written(plot)


def _print_pair(doc):
    """A pair of tapered roller bearings: each bearing's rollers, the shaft, and ISO 281's method."""
    inputs = doc["inputs"]
    kind = {"DB": "back to back", "DF": "face to face"}[inputs["arrangement"]]
    for k, m in enumerate(doc["bearings"]):
        if "rollers" in m:
            title = (f"Bearing {'AB'[k]} ({m['bearing']}, pressure centre z = {m['pressure_centre_mm']:g} mm, "
                     f"F_r = {m['radial_load_N']:.1f} N, F_a = {m['axial_load_N']:.1f} N)")
            _print_rollers(title, m)
    if doc["stiffness_matrix"] is not None:
        play = doc["axial_play_um"]
        extra = [["effective spread (pressure centres) [mm]", f"{doc['effective_spread_mm']:g}"],
                 ["roller middles apart [mm]", _f(doc["roller_distance_mm"], ".4f")],
                 ["end play (< 0: interference) [µm]", _f(play, ".4f")],
                 ["operating preload [N]", _sig(doc["operating_preload_N"])]]
        ring = {**doc, "max_roller_load_N": max(m["max_roller_load_N"] for m in doc["bearings"]),
                "max_pressure_MPa": max(m["max_pressure_MPa"] for m in doc["bearings"])}
        _print_ring(f"Pair {inputs['arrangement']} ({kind})", ring, "shaft", "the middle of the pressure centres",
                    extra)
    iso = doc["iso281"]
    rows = []
    for k, m in enumerate(iso["bearings"]):
        rows.append([f"{'AB'[k]} {m['bearing']}", _sig(m["radial_load_N"]), _sig(m["induced_axial_load_N"]),
                     _sig(m["axial_load_N"]), _sig(m["equivalent_dynamic_load_N"]), _f(m["basic_rating_life_Mrev"], ".6g"),
                     _f(m["basic_rating_life_h"], ".6g")])
    table(f"ISO 281's method (induced axial load {iso['induced_axial_factor']:g} F_r/Y)",
          ["bearing", "F_r [N]", "f F_r/Y [N]", "F_a [N]", "P [N]", "L10 [10^6 rev]", "L10h [h]"], rows,
          caption=iso["source"])
    print_warnings(doc["warnings"])


#: The commands of this module, as the application adds them.
COMMANDS = {"load-distribution": command("load-distribution", load_distribution),
            "bearing-set": command("bearing-set", bearing_set)}
