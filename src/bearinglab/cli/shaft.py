"""Command line of shaft systems (issue 33): ``shaft FILE``.

Several bearings on an elastic shaft, read from a TOML file (the format of
docs/user_guide/shaft_systems.md): the load on each support and its displacement and tilt, each
bearing's lives, static safety and largest contact pressure, the system life, the stiffness at a point
(``--stiffness-at``), the natural frequencies (``--modes``), the Campbell diagram (``--campbell``) and
the load spectrum of the file's ``[[cases]]``. ``--csv`` writes the rows along the shaft (deflection,
slope, shear force, bending moment), ``--plot`` draws the shaft to scale above its deflection, slope and
bending-moment lines (:func:`bearinglab.calculations.shaft.figure`). The document is
:func:`bearinglab.calculations.shaft.document`, the web's too; this module prints it.

Commands
--------
COMMANDS   the ``shaft`` command, by name (the application adds it)
"""

import math

from ._common import (
    FIGURE_SUFFIXES,
    CatalogFile,
    FileOption,
    JsonFlag,
    check_output,
    console,
    emit_csv,
    emit_json,
    print_warnings,
    run_calculation,
    table,
)
from ._options import command

__all__ = ["COMMANDS"]


def shaft(
    given, *, catalog: CatalogFile = None,
    csv_file: FileOption("--csv", "Write the rows along the shaft (z, deflection, slope, shear force, bending "
                         "moment) to this CSV file.") = None,
    plot: FileOption("--plot", "Draw the shaft to scale above its deflection, slope and bending-moment lines "
                     "into this PNG/PDF/SVG file.") = None,
    json_out: JsonFlag = False,
):
    """Shaft system: several bearings on an elastic shaft with loads, gears and pulleys. Support loads, displacements and tilts, bearing lives, system life, stiffness at a point, natural frequencies."""
    from .. import plots
    from ..calculations import shaft as calculation

    if csv_file is not None:  # the output files, checked before anything is solved
        check_output(csv_file, "csv", (".csv",), inputs=(catalog,))
    if plot is not None:
        check_output(plot, "plot", FIGURE_SUFFIXES, inputs=(catalog,))
    doc = run_calculation("shaft", given, calculation.document, catalog=catalog)
    if csv_file is not None:
        emit_csv(csv_file, deflection_columns(doc))
    if plot is not None:
        plots.save(calculation.figure(doc), plot)
    if json_out:
        emit_json(doc)
        return
    print_shaft(doc)
    for path in (csv_file, plot):
        if path is not None:
            console.print(f"wrote {path}", highlight=False)


def deflection_columns(doc):
    """The document's rows along the shaft as columns (name -> list), the keys of its ``deflection``."""
    rows = doc["deflection"]
    return {key: [r[key] for r in rows] for key in rows[0]} if rows else {}


def _f(x, spec):
    return "—" if x is None else format(x, spec)


def _sig(x, digits=4):
    """``x`` to ``digits`` significant digits, without an exponent below 10^7 (lives in hours)."""
    if x is None:
        return "—"
    if x == 0 or not math.isfinite(x):
        return format(x, "g")
    if abs(x) >= 1e7:
        return format(x, f".{digits - 1}e")
    decimals = max(0, digits - 1 - math.floor(math.log10(abs(x))))
    return format(x, f".{decimals}f")


def _kN(x):
    """A force in kN to the newton (3 decimals): a support's load next to the others'."""
    return "—" if x is None else format(x / 1e3, ".3f")


def print_shaft(doc):
    """The document as tables: the system, the supports' loads and displacements, the bearings, the
    spectrum and the Campbell diagram where asked for, then the warnings."""
    s = doc["shaft"]
    title = (f"Shaft system: {s['length_mm']:g} mm, {len(s['sections'])} sections, {s['mass_kg']:.3g} kg, "
             f"at {doc['speed_rpm']:g} rpm")
    rows = []
    lives = doc["system_lives_h"]
    for key, label in (("basic_rating_life_h", "system life L10h [h]"),
                       ("modified_rating_life_h", "system life L_nmh [h]"),
                       ("reference_rating_life_h", "system life L10rh (ISO/TS 16281) [h]"),
                       ("modified_reference_rating_life_h", "system life L_nmrh [h]")):
        if lives.get(key) is not None or key == "basic_rating_life_h":
            rows.append([label, _sig(lives.get(key))])
    k = doc.get("stiffness_at")
    if k:
        at = f"z = {k['position_mm']:g} mm"
        rows += [[f"stiffness at {at}: k_x, k_y [N/µm]",
                  f"{_sig(k['stiffness_x_N_per_um'])}, {_sig(k['stiffness_y_N_per_um'])}"],
                 [f"stiffness at {at}: k_z [N/µm]", _sig(k["stiffness_z_N_per_um"])]]
    if doc.get("natural_frequencies_Hz") is not None:
        modes = doc.get("modes") or []
        text = ", ".join(_sig(f) + (f" ({m['whirl']})" if m.get("whirl") else "")
                         for f, m in zip(doc["natural_frequencies_Hz"], modes + [{}] * len(doc["natural_frequencies_Hz"])))
        rows.append(["natural frequencies [Hz]", text or "—"])
    eq, conv = doc["equilibrium"], doc["convergence"]
    rows.append(["equilibrium (relative error)", _f(eq["relative_error"], ".1e")])
    rows.append(["converged (iterations, residual)",
                 f"{str(conv['converged']).lower()} ({conv['iterations']}, {_f(conv['residual'], '.1e')})"])
    table(title, ["quantity", "value"], rows)
    supports = doc["supports"]
    table("Support loads (the load the shaft puts on each support)",
          ["support", "z [mm]", "F_x [kN]", "F_y [kN]", "F_z [kN]", "M_x [N·m]", "M_y [N·m]"],
          [[p["name"], f"{p['position_mm']:g}", _kN(p["force_x_N"]), _kN(p["force_y_N"]), _kN(p["force_z_N"]),
            _f(p["moment_x_Nm"], ".3f"), _f(p["moment_y_Nm"], ".3f")] for p in supports])
    table("Support displacements and tilts (the misalignment each bearing sees)",
          ["support", "δ_x [µm]", "δ_y [µm]", "δ_z [µm]", "θ_x [mrad]", "θ_y [mrad]"],
          [[p["name"], _f(p["displacement_x_um"], ".3f"), _f(p["displacement_y_um"], ".3f"),
            _f(p["displacement_z_um"], ".3f"), _f(p["tilt_x_mrad"], ".4f"), _f(p["tilt_y_mrad"], ".4f")]
           for p in supports])
    bearings = [(p, j, b) for p in supports for j, b in enumerate(p.get("bearings") or [])]
    if bearings:
        table("Bearings (ISO 281, ISO/TS 16281)",
              ["support", "bearing", "P [kN]", "L10h [h]", "L_nmh [h]", "L10rh [h]", "s0", "p_max [MPa]"],
              [[p["name"] + (f" {j + 1}" if len(p["bearings"]) > 1 else ""), b["bearing"],
                _kN(b["equivalent_dynamic_load_N"]), _sig(b["basic_rating_life_h"]),
                _sig(b["modified_rating_life_h"]), _sig(b["reference_rating_life_h"]),
                _f(b["static_safety_factor"], ".2f"), _f(b["max_contact_pressure_MPa"], ".0f")]
               for p, j, b in bearings],
              caption="--json for every key; --csv for the rows along the shaft")
    _print_spectrum(doc.get("spectrum"))
    _print_campbell(doc.get("campbell"))
    print_warnings(doc.get("warnings", []))


def _print_spectrum(sp):
    if not sp:
        return
    table(f"Load spectrum: {len(sp['cases'])} cases, mean speed {sp['mean_speed_rpm']:g} rpm",
          ["case", "time share", "speed [rpm]", "factor", "revolution share"],
          [[c["name"], f"{c['time_share']:.6g}", f"{c['speed_rpm']:g}", f"{c['factor']:.6g}",
            f"{c['revolution_share']:.6g}"]
           for c in sp["cases"]])
    table("Lives over the spectrum (Palmgren-Miner)", ["bearing", "L10h [h]", "L_nmh [h]", "L10rh [h]"],
          [[b["name"], _sig(b["basic_rating_life_h"]), _sig(b["modified_rating_life_h"]),
            _sig(b["reference_rating_life_h"])] for b in sp["bearings"]]
          + [["system", _sig(sp["system_lives_h"]["basic_rating_life_h"]),
              _sig(sp["system_lives_h"]["modified_rating_life_h"]),
              _sig(sp["system_lives_h"]["reference_rating_life_h"])]])


def _print_campbell(c):
    if not c:
        return
    count = max((len(row) for row in c["frequency_Hz"]), default=0)
    table("Campbell diagram: natural frequencies [Hz] over the speed",
          ["speed [rpm]", *[f"mode {i + 1}" for i in range(count)]],
          [[f"{n:g}", *[_sig(f) for f in row], *["—"] * (count - len(row))]
           for n, row in zip(c["speed_rpm"], c["frequency_Hz"])])


#: The ``shaft`` command, as the application adds it.
COMMANDS = {"shaft": command("shaft", shaft)}
