"""The HTML page of a friction-lab report: self-contained, readable offline, printable (spec 001 section 7).

render_html       the HTML text of the report (figures embedded as SVG data URIs)

The page holds, in order: the rig and the test conditions with the bearing data and the handbook
constants; Tables 4 and 5 and every measurement row; the fitted coefficients with their standard
errors and handbook comparisons; the plots (points and fitted lines from abscissa 0, section 7.4);
and the generated conclusions (section 7.5). It needs no external resource: styles are inline and
images embedded. Its numbers come from :mod:`bearinglab.lab.presentation`; this module only marks
them up.
"""

from __future__ import annotations

import base64
import datetime as _dt
import html
import math

from ..lab import presentation

__all__ = ["render_html"]

_RIG_TEXT = (
    "DP11A-type friction rig. The test-bearing unit is screwed into the rotating "
    "spindle; the load mass Q is fixed on the unit, whose driver pin bears on the saddle of a flat measuring "
    "spring that takes up the friction torque. The plate carrying the spindle tilts from vertical (β = 0°, "
    "pure axial load) to horizontal (β = 90°, pure radial load) in 15° steps; masses of 0.5, 1.0 and 2.0 kg. "
    "A tachogenerator drives the microammeter in speed mode; in torque mode a shutter on the spring, a light "
    "source and a photodiode drive it, with a sensitivity switch (position 1 is the more sensitive). "
    "Readings are converted with the calibration tables of the session (piecewise linear, no extrapolation). "
    "Loads: F_a = g·Q·cos β, F_r = g·Q·sin β; P0 = max(x0·F_r + y0·F_a, F_r)."
)

_CSS = """
:root { --ink: #1b1b1b; --muted: #5a5a5a; --rule: #c8c8c8; --head: #eef2f7; }
body { font-family: "DejaVu Sans", "Helvetica Neue", Arial, sans-serif; color: var(--ink); margin: 2rem auto;
       max-width: 60rem; padding: 0 1rem; line-height: 1.45; font-size: 15px; }
h1 { font-size: 1.6rem; margin-bottom: 0.2rem; } h2 { font-size: 1.25rem; border-bottom: 2px solid var(--rule);
padding-bottom: 0.2rem; margin-top: 2rem; } h3 { font-size: 1.05rem; margin-top: 1.4rem; }
p.meta { color: var(--muted); margin-top: 0; }
table { border-collapse: collapse; margin: 0.6rem 0 1rem; font-size: 0.85rem; }
caption { text-align: left; font-weight: bold; padding-bottom: 0.3rem; }
th, td { border: 1px solid var(--rule); padding: 0.2rem 0.45rem; text-align: right; vertical-align: top; }
th { background: var(--head); } td.text, th.text { text-align: left; }
figure { margin: 1rem 0; } figure img { max-width: 100%; height: auto; border: 1px solid var(--rule); }
figcaption { color: var(--muted); font-size: 0.85rem; }
ol.conclusions li { margin-bottom: 0.5rem; } .warn { color: #a04000; }
.wide { overflow-x: auto; }
@media print {
  body { margin: 0; max-width: none; font-size: 10.5pt; }
  table { font-size: 8pt; } th, td { padding: 0.1rem 0.3rem; }
  h2 { break-after: avoid; page-break-after: avoid; }
  table, figure, li { break-inside: avoid; page-break-inside: avoid; }
  .wide { overflow: visible; } figure img { max-width: 17cm; border: none; }
  @page { size: A4; margin: 1.6cm; }
}
"""


# ----------------------------------------------------------------------------- the page
def render_html(result, figures, *, generated=None):
    """The HTML text of the report.

    Parameters
    ----------
    result : bearinglab.lab.analysis.LabResult
        The analysed session.
    figures : list of (PlotData, str)
        Each plot with its SVG text, embedded as a data URI.
    generated : str, optional
        Time stamp shown in the header (default: now, UTC).

    Returns
    -------
    str
        A complete, self-contained HTML document.
    """
    d = presentation.to_dict(result)
    generated = generated or _dt.datetime.now(_dt.UTC).strftime("%Y-%m-%d %H:%M UTC")
    title = d["session"].get("title") or f"Friction torque of bearing {d['bearing']['designation']}"
    out = _head(result.session, title, generated)
    out.append("<h2>1. Rig and test conditions</h2>")
    out += _conditions(d)
    out.append("<h2>2. Measurements</h2>")
    for t in (
        presentation.table4(result)
        + presentation.table5(result)
        + [presentation.rows_table(result)]
    ):
        out.append(_html_table(t.title, t.columns, t.rows, t.formats))
    out.append("<h2>3. Fitted coefficients and handbook comparison</h2>")
    out.append(_coefficient_tables(d))
    if d["mean_f0"] is not None:
        out.append(f"<p>Mean f0 of task 2: {d['mean_f0']:.6e} N·mm⁻²·min^(2/3).</p>")
    out.append("<h2>4. Plots</h2>")
    out += _figures(figures)
    out.append('<h2>5. Conclusions</h2><ol class="conclusions">')
    for text in d["conclusions"]:
        cls = ' class="warn"' if text.startswith("Warning") else ""
        out.append(f"<li{cls}>{html.escape(text)}</li>")
    out.append("</ol>")
    out.append(
        '<p class="meta">Every number of this report is in results.json; tables are also CSV files and '
        "plots PNG and SVG files in the same directory.</p></body></html>"
    )
    return "\n".join(out)


def _head(session, title, generated):
    """The document head and the title block."""
    from .. import __version__

    return [
        "<!DOCTYPE html>",
        '<html lang="en"><head><meta charset="utf-8">',
        '<meta name="viewport" content="width=device-width, initial-scale=1">',
        f"<title>{html.escape(title)}</title><style>{_CSS}</style></head><body>",
        f"<h1>{html.escape(title)}</h1>",
        (
            f'<p class="meta">Friction torque of ball bearings under combined loading (the friction-rig lab). Session file '
            f"{html.escape(str(session.source))}; rows from {html.escape(str(session.rows_source))}. "
            f"Generated {generated} by bearinglab {__version__}.</p>"
        ),
    ]


def _conditions(d):
    """Section 1: the rig, the session, the test conditions, the bearing and the handbook constants."""
    out = [f"<p>{html.escape(_RIG_TEXT)}</p>"]
    meta = [[k.capitalize(), v] for k, v in d["session"].items() if v]
    if meta:
        out.append(_html_table("Session", ["item", "value"], meta, ["", ""]))
    rows, rig = d["rows"], d["rig"]
    tilts = sorted({r["tilt_deg"] for r in rows})
    masses = sorted({r["mass_kg"] for r in rows})
    speeds = sorted({round(r["speed_rpm"], 6) for r in rows})
    n4, n5 = (sum(r["series"] == series for r in rows) for series in ("T4", "T5"))
    conditions = [
        ["tilts β [deg]", ", ".join(f"{t:g}" for t in tilts)],
        ["masses Q [kg]", ", ".join(f"{q:g}" for q in masses)],
        ["tare mass [kg]", f"{rig['tare_mass_kg']:g}"],
        ["g [m/s²]", f"{rig['gravity_m_per_s2']:g}"],
        ["spindle speeds n [rpm]", ", ".join(f"{n:.6g}" for n in speeds)],
        ["rows (T4 / T5)", f"{n4} / {n5}"],
    ]
    if rig["branch_switch_tilt_deg"] is not None:
        conditions.append(
            [
                "P0 branch switch β* = arctan(y0/(1 − x0)) [deg]",
                f"{rig['branch_switch_tilt_deg']:.4f}",
            ]
        )
    out.append(_html_table("Test conditions", ["quantity", "value"], conditions, ["", ""]))
    out.append(
        _html_table("Test bearing", ["quantity", "value"], _bearing_rows(d["bearing"]), ["", ""])
    )
    hb = d["handbook"]
    over = set(hb["overridden"])
    hb_rows = [
        [f"{name}{' (given in the session file)' if key in over else ''}", hb[key]]
        for key, name in (
            ("x0", "x0 (Table 1)"),
            ("y0", "y0 (Table 1)"),
            ("mu", "μ_hb"),
            ("f", "f_hb (Table 2)"),
            ("c", "c = e (Table 2)"),
        )
    ]
    out.append(_html_table("Handbook constants", ["constant", "value"], hb_rows, ["", "g"]))
    return out


def _bearing_rows(b):
    rows = [
        ["designation", b["designation"]],
        ["type", b["type"]],
        ["bore d [mm]", f"{b['bore_mm']:g}"],
        ["outside diameter D [mm]", f"{b['outside_diameter_mm']:g}"],
        ["mean diameter d_m [mm]", f"{b['mean_diameter_mm']:g}"],
        ["static load rating C0 [N]", f"{b['static_load_rating_N']:g}"],
    ]
    if b["type"] == "angular" and b["contact_angle_deg"] is not None:
        rows.insert(2, ["contact angle α [deg]", f"{b['contact_angle_deg']:g}"])
    if b["source"]:
        rows.append(["source", b["source"]])
    return rows


def _figures(figures):
    """Section 4: every plot as an embedded SVG with its caption."""
    out = []
    for k, (plot, svg) in enumerate(figures, start=1):
        uri = "data:image/svg+xml;base64," + base64.b64encode(svg.encode("utf-8")).decode("ascii")
        out.append(
            f'<figure><img alt="{html.escape(plot.title)}" src="{uri}">'
            f"<figcaption>Figure {k}. {html.escape(plot.title)}: experimental points and the fitted lines, "
            f"drawn from abscissa 0 to 1.1 × the largest experimental abscissa (files {plot.name}.png, "
            f"{plot.name}.svg).</figcaption></figure>"
        )
    return out


# ----------------------------------------------------------------------------- tables
def _cell(value, fmt):
    if value is None:
        return ""
    if isinstance(value, float) and math.isnan(value):
        return "n/a"
    if fmt and isinstance(value, (int, float)):
        try:
            return format(value, fmt)
        except (ValueError, TypeError):
            return str(value)
    return str(value)


def _html_table(title, columns, rows, formats):
    """A table; headers ``"group: name"`` become a two-row header (the group spanning its columns)."""
    out = ['<div class="wide"><table>', f"<caption>{html.escape(title)}</caption>", "<thead>"]
    split = [c.split(": ", 1) if ": " in c else [None, c] for c in columns]
    if any(g is not None for g, _ in split):
        out.append("<tr>")
        k = 0
        while k < len(split):
            group = split[k][0]
            span = 1
            while k + span < len(split) and group is not None and split[k + span][0] == group:
                span += 1
            if group is None:
                out.append(f'<th rowspan="2">{html.escape(split[k][1])}</th>')
            else:
                out.append(f'<th colspan="{span}">{html.escape(group)}</th>')
            k += span
        out.append("</tr>")
        header = [(name, f) for (g, name), f in zip(split, formats) if g is not None]
    else:
        header = [(name, f) for (_g, name), f in zip(split, formats)]
    out.append("<tr>")
    for name, f in header:
        cls = ' class="text"' if f == "" else ""
        out.append(f"<th{cls}>{html.escape(name)}</th>")
    out.append("</tr></thead><tbody>")
    for row in rows:
        out.append("<tr>")
        for v, f in zip(row, formats):
            cls = ' class="text"' if f == "" else ""
            out.append(f"<td{cls}>{html.escape(_cell(v, f))}</td>")
        out.append("</tr>")
    out.append("</tbody></table></div>")
    return "".join(out)


def _pm(value, error, fmt):
    if value is None:
        return ""
    if error is None:
        return f"{format(value, fmt)}"
    return f"{format(value, fmt)} ± {format(error, '.2g')}"


def _coefficient_tables(d):
    """Section 3: one table per task (only for tasks that were run) and a note on the statistics."""
    parts = [
        _records_table(_TASK1_TITLE, d["task1"], _TASK1_COLUMNS),
        _records_table(_TASK2_TITLE, d["task2"], _TASK2_COLUMNS),
        _records_table(_TASK3_TITLE, d["task3"], _TASK3_COLUMNS),
        _records_table(_TASK4_TITLE, d["task4"], _TASK4_COLUMNS),
    ]
    parts.append(
        "<p>Standard errors from the least-squares covariance with m − p degrees of freedom (p = 1 for "
        "task 1, 2 for tasks 2 and 3, the number of fitted parameters for task 4); “n/a” where m = p. The intercepts T_F (n → 0) and T0 (P0 → 0) are "
        "extrapolations.</p>"
    )
    return "".join(parts)


def _records_table(title, records, columns):
    """A table of result records (dicts of :func:`~bearinglab.lab.presentation.to_dict`), one row each;
    ``columns`` are (header, display format, cell of a record); no records, no table."""
    if not records:
        return ""
    rows = [[cell(r) for _h, _f, cell in columns] for r in records]
    return _html_table(title, [h for h, _f, _c in columns], rows, [f for _h, f, _c in columns])


def _field(key, scale=None):
    return (lambda r: r[key]) if scale is None else (lambda r: r[key] * scale)


def _with_error(key, error_key):
    return lambda r: _pm(r[key], r[error_key], ".6e")


_TASK1_TITLE = "Task 1: reduced friction coefficient μ (least squares through the origin, eq. 6.1)"
_TASK1_COLUMNS = (
    ("β [deg]", "g", _field("tilt_deg")),
    ("column", "", _field("column")),
    ("n [rpm]", ".6g", _field("speed_rpm")),
    ("μ ± s.e.", "", _with_error("mu", "mu_standard_error")),
    ("m", "d", _field("n_points")),
    ("residual RMS [N·mm]", ".4e", _field("residual_rms_Nmm")),
    ("mean T [N·mm]", ".6f", _field("mean_torque_Nmm")),
    ("μ_hb", "g", _field("mu_handbook")),
    ("μ/μ_hb − 1 [%] (I2)", "+.2f", _field("mu_relative_to_handbook", 100)),
    ("RMS/mean T [%] (I3)", ".2f", _field("residual_rms_relative_to_mean_torque", 100)),
)
_TASK2_TITLE = (
    "Task 2: speed dependence T = f0·d_m³·n^(2/3) + T_F (eq. 6.2); f0 in N·mm⁻²·min^(2/3)"
)
_TASK2_COLUMNS = (
    ("β [deg]", "g", _field("tilt_deg")),
    ("Q [kg]", "g", _field("mass_kg")),
    ("P0 [N]", ".6f", _field("equivalent_static_load_N")),
    ("f0 ± s.e.", "", _with_error("f0", "f0_standard_error")),
    (
        "T_F ± s.e. [N·mm]",
        "",
        _with_error("torque_load_term_Nmm", "torque_load_term_standard_error_Nmm"),
    ),
    ("m", "d", _field("n_points")),
    ("residual RMS [N·mm]", ".4e", _field("residual_rms_Nmm")),
    ("handbook T_F [N·mm]", ".6e", _field("handbook_torque_load_term_Nmm")),
    ("T_F with f of task 3 [N·mm]", ".6e", _field("torque_load_term_with_task3_f_Nmm")),
)
_TASK3_TITLE = "Task 3: load dependence T = T0 + f·P0·(P0/C0)^e·d_m (eqs. 6.2-6.3)"
_TASK3_COLUMNS = (
    ("β [deg]", "g", _field("tilt_deg")),
    ("column", "", _field("column")),
    ("n [rpm]", ".6g", _field("speed_rpm")),
    ("f ± s.e.", "", _with_error("f", "f_standard_error")),
    (
        "T0 ± s.e. [N·mm]",
        "",
        _with_error("torque_speed_term_Nmm", "torque_speed_term_standard_error_Nmm"),
    ),
    ("m", "d", _field("n_points")),
    ("residual RMS [N·mm]", ".4e", _field("residual_rms_Nmm")),
    ("f_hb", "g", _field("f_handbook")),
    ("f/f_hb − 1 [%]", "+.2f", _field("f_relative_to_handbook", 100)),
    (
        "f0·d_m³·n^(2/3), mean f0 of task 2 [N·mm]",
        ".6e",
        _field("torque_speed_term_with_task2_f0_Nmm"),
    ),
)
_TASK4_TITLE = (
    "Task 4: SKF four-term model T = k·M_rr + μ_sl·G_sl + M_seal (least squares, all rows of a tilt)"
)
_TASK4_COLUMNS = (
    ("β [deg]", "g", _field("tilt_deg")),
    ("fitted", "", _field("fitted")),
    ("μ_sl ± s.e.", "", lambda r: _pm(r["mu_sl"], r["mu_sl_standard_error"], ".4f")),
    ("k on M_rr ± s.e.", "", lambda r: _pm(r["rolling_scale"], r["rolling_scale_standard_error"], ".4f")),
    ("μ_sl of the model", ".4f", _field("mu_sl_model")),
    ("m", "d", _field("n_points")),
    ("residual RMS [N·mm]", ".4e", _field("residual_rms_Nmm")),
    ("RMS of the unfitted model [N·mm]", ".4e", _field("model_residual_rms_Nmm")),
    ("mean T [N·mm]", ".6f", _field("mean_torque_Nmm")),
)
