"""Reports of the friction-rig lab: a self-contained HTML report, PNG and SVG plots, CSV tables, JSON.

Report
------
write_report      analysed session -> a report directory, written atomically (whole or not at all)
render_html       the HTML text of the report (figures embedded as SVG data URIs)
render_figure     one plot of :func:`bearinglab.lab.analysis.plots` -> (PNG bytes, SVG text)
ReportFiles       what :func:`write_report` wrote

The HTML report opens offline (no external resource: styles inline, images embedded), prints well
(print style sheet, no page breaks inside tables and figures) and holds the test conditions and
bearing data, Tables 4 and 5, the fitted coefficients with their standard errors and handbook
comparisons, the plots (points and fitted lines from abscissa 0, spec 001 section 7.4) and the
generated conclusions (section 7.5). Next to it: every plot as PNG and SVG, every table as CSV and
every number in ``results.json``.

Matplotlib is imported on first use, with the Agg canvas set explicitly (no pyplot, no global
backend state), so ``import bearinglab`` stays light and reports work on headless machines.
"""

from __future__ import annotations

import base64
import csv
import datetime as _dt
import html
import io
import json
import math
import os
import shutil
import tempfile
from pathlib import Path
from typing import NamedTuple

from .errors import InputError

__all__ = ["MARKER", "ReportFiles", "render_figure", "render_html", "write_report"]

MARKER = ".bearinglab-report"  # marks a directory written by write_report (it may be replaced)
_COLOURS = ("#1f5fa8", "#c0392b", "#2e8b57", "#8e44ad", "#d35400", "#16a085", "#7f8c8d", "#b7950b")
_MARKERS = ("o", "s", "^", "D", "v", "P", "X", "*")

_RIG_TEXT = (
    "DP11A-type friction rig (spec 001 section 4). The test-bearing unit is screwed into the rotating "
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


class ReportFiles(NamedTuple):
    """Files written by :func:`write_report` (all inside ``directory``)."""

    directory: Path
    """The report directory."""
    html: Path
    """``report.html``."""
    json: Path
    """``results.json``."""
    figures: list
    """PNG and SVG files of the plots."""
    tables: list
    """CSV files of the tables."""


# ----------------------------------------------------------------------------- figures
def render_figure(plot):
    """Draw one plot: experimental points and fitted lines from abscissa 0.

    Parameters
    ----------
    plot : bearinglab.lab.analysis.PlotData
        Points and lines in engineering units.

    Returns
    -------
    tuple of (bytes, str)
        The PNG image and the SVG text.
    """
    import matplotlib
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    with matplotlib.rc_context(
        {"svg.fonttype": "path", "svg.hashsalt": plot.name, "font.size": 9.5}
    ):
        fig = Figure(figsize=(6.4, 4.2), dpi=150)
        FigureCanvasAgg(fig)
        ax = fig.add_subplot()
        ymin = 0.0
        for k, s in enumerate(plot.series):
            colour, marker = _COLOURS[k % len(_COLOURS)], _MARKERS[k % len(_MARKERS)]
            ax.plot(s.line_x, s.line_y, "-", color=colour, lw=1.4, label=s.label)
            ax.plot(s.x, s.y, marker, color=colour, ms=5.5, mfc="white", mew=1.4, ls="none")
            ymin = min(ymin, float(min(s.line_y.min(), s.y.min())))
        ax.set_xlim(left=0.0)
        ax.set_ylim(bottom=ymin * 1.1 if ymin < 0 else 0.0)
        ax.axhline(0.0, color="0.6", lw=0.6)
        ax.set_xlabel(plot.xlabel)
        ax.set_ylabel(plot.ylabel)
        ax.set_title(plot.title, fontsize=10.5)
        ax.grid(True, color="0.88", lw=0.6)
        ax.legend(fontsize=8, loc="upper left", frameon=False)
        fig.set_layout_engine("constrained")  # lay out once, then keep that layout for both formats
        fig.draw_without_rendering()
        fig.set_layout_engine("none")
        png = io.BytesIO()
        fig.savefig(png, format="png", metadata={"Software": None})
        svg = io.StringIO()
        fig.savefig(
            svg,
            format="svg",
            metadata={"Date": None, "Creator": None, "Format": None, "Type": None},
        )
    text = svg.getvalue()
    start = text.find("<metadata>")  # drop the RDF block: it only names external vocabularies
    if start >= 0:
        end = text.find("</metadata>", start)
        text = text[:start] + text[end + len("</metadata>") :]
    return png.getvalue(), text


# ----------------------------------------------------------------------------- HTML
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
    parts = []
    rows = [
        [
            r["tilt_deg"],
            r["column"],
            r["speed_rpm"],
            _pm(r["mu"], r["mu_standard_error"], ".6e"),
            r["n_points"],
            r["residual_rms_Nmm"],
            r["mean_torque_Nmm"],
            r["mu_handbook"],
            r["mu_relative_to_handbook"] * 100,
            r["residual_rms_relative_to_mean_torque"] * 100,
        ]
        for r in d["task1"]
    ]
    if rows:
        parts.append(
            _html_table(
                "Task 1: reduced friction coefficient μ (least squares through the origin, eq. 6.1)",
                [
                    "β [deg]",
                    "column",
                    "n [rpm]",
                    "μ ± s.e.",
                    "m",
                    "residual RMS [N·mm]",
                    "mean T [N·mm]",
                    "μ_hb",
                    "μ/μ_hb − 1 [%] (I2)",
                    "RMS/mean T [%] (I3)",
                ],
                rows,
                ["g", "", ".6g", "", "d", ".4e", ".6f", "g", "+.2f", ".2f"],
            )
        )
    rows = [
        [
            r["tilt_deg"],
            r["mass_kg"],
            r["equivalent_static_load_N"],
            _pm(r["f0"], r["f0_standard_error"], ".6e"),
            _pm(r["torque_load_term_Nmm"], r["torque_load_term_standard_error_Nmm"], ".6e"),
            r["n_points"],
            r["residual_rms_Nmm"],
            r["handbook_torque_load_term_Nmm"],
            r["torque_load_term_with_task3_f_Nmm"],
        ]
        for r in d["task2"]
    ]
    if rows:
        parts.append(
            _html_table(
                "Task 2: speed dependence T = f0·d_m³·n^(2/3) + T_F (eq. 6.2); f0 in N·mm⁻²·min^(2/3)",
                [
                    "β [deg]",
                    "Q [kg]",
                    "P0 [N]",
                    "f0 ± s.e.",
                    "T_F ± s.e. [N·mm]",
                    "m",
                    "residual RMS [N·mm]",
                    "handbook T_F [N·mm]",
                    "T_F with f of task 3 [N·mm]",
                ],
                rows,
                ["g", "g", ".6f", "", "", "d", ".4e", ".6e", ".6e"],
            )
        )
    rows = [
        [
            r["tilt_deg"],
            r["column"],
            r["speed_rpm"],
            _pm(r["f"], r["f_standard_error"], ".6e"),
            _pm(r["torque_speed_term_Nmm"], r["torque_speed_term_standard_error_Nmm"], ".6e"),
            r["n_points"],
            r["residual_rms_Nmm"],
            r["f_handbook"],
            r["f_relative_to_handbook"] * 100,
            r["torque_speed_term_with_task2_f0_Nmm"],
        ]
        for r in d["task3"]
    ]
    if rows:
        parts.append(
            _html_table(
                "Task 3: load dependence T = T0 + f·P0·(P0/C0)^e·d_m (eqs. 6.2-6.3)",
                [
                    "β [deg]",
                    "column",
                    "n [rpm]",
                    "f ± s.e.",
                    "T0 ± s.e. [N·mm]",
                    "m",
                    "residual RMS [N·mm]",
                    "f_hb",
                    "f/f_hb − 1 [%]",
                    "f0·d_m³·n^(2/3), mean f0 of task 2 [N·mm]",
                ],
                rows,
                ["g", "", ".6g", "", "", "d", ".4e", "g", "+.2f", ".6e"],
            )
        )
    parts.append(
        "<p>Standard errors from the least-squares covariance with m − p degrees of freedom (p = 1 for "
        "task 1, 2 for tasks 2 and 3); “n/a” where m = p. The intercepts T_F (n → 0) and T0 (P0 → 0) are "
        "extrapolations (spec 001 section 8.14).</p>"
    )
    return "".join(parts)


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
    from . import __version__
    from .lab import analysis

    d = analysis.to_dict(result)
    s = result.session
    b = d["bearing"]
    hb = d["handbook"]
    info = d["session"]
    generated = generated or _dt.datetime.now(_dt.UTC).strftime("%Y-%m-%d %H:%M UTC")
    title = info.get("title") or f"Friction torque of bearing {b['designation']}"
    out = [
        "<!DOCTYPE html>",
        '<html lang="en"><head><meta charset="utf-8">',
        '<meta name="viewport" content="width=device-width, initial-scale=1">',
        f"<title>{html.escape(title)}</title><style>{_CSS}</style></head><body>",
        f"<h1>{html.escape(title)}</h1>",
        (
            f'<p class="meta">Friction torque of ball bearings under combined loading (spec 001). Session file '
            f"{html.escape(str(s.source))}; rows from {html.escape(str(s.rows_source))}. Generated {generated} by "
            f"bearinglab {__version__}.</p>"
        ),
    ]
    # 1. rig and test conditions
    out.append("<h2>1. Rig and test conditions</h2>")
    out.append(f"<p>{html.escape(_RIG_TEXT)}</p>")
    meta = [[k.capitalize(), v] for k, v in info.items() if v]
    if meta:
        out.append(_html_table("Session", ["item", "value"], meta, ["", ""]))
    tilts = sorted({r["tilt_deg"] for r in d["rows"]})
    masses = sorted({r["mass_kg"] for r in d["rows"]})
    speeds = sorted({round(r["speed_rpm"], 6) for r in d["rows"]})
    conditions = [
        ["tilts β [deg]", ", ".join(f"{t:g}" for t in tilts)],
        ["masses Q [kg]", ", ".join(f"{q:g}" for q in masses)],
        ["tare mass [kg]", f"{d['rig']['tare_mass_kg']:g}"],
        ["g [m/s²]", f"{d['rig']['gravity_m_per_s2']:g}"],
        ["spindle speeds n [rpm]", ", ".join(f"{n:.6g}" for n in speeds)],
        [
            "rows (T4 / T5)",
            f"{sum(r['series'] == 'T4' for r in d['rows'])} / {sum(r['series'] == 'T5' for r in d['rows'])}",
        ],
    ]
    if d["rig"]["branch_switch_tilt_deg"] is not None:
        conditions.append(
            [
                "P0 branch switch β* = arctan(y0/(1 − x0)) [deg]",
                f"{d['rig']['branch_switch_tilt_deg']:.4f}",
            ]
        )
    out.append(_html_table("Test conditions", ["quantity", "value"], conditions, ["", ""]))
    bearing_rows = [
        ["designation", b["designation"]],
        ["type", b["type"]],
        ["bore d [mm]", f"{b['bore_mm']:g}"],
        ["outside diameter D [mm]", f"{b['outside_diameter_mm']:g}"],
        ["mean diameter d_m [mm]", f"{b['mean_diameter_mm']:g}"],
        ["static load rating C0 [N]", f"{b['static_load_rating_N']:g}"],
    ]
    if b["type"] == "angular" and b["contact_angle_deg"] is not None:
        bearing_rows.insert(2, ["contact angle α [deg]", f"{b['contact_angle_deg']:g}"])
    if b["source"]:
        bearing_rows.append(["source", b["source"]])
    out.append(_html_table("Test bearing", ["quantity", "value"], bearing_rows, ["", ""]))
    over = set(hb["overridden"])
    hb_rows = [
        [f"{name}{' (given in the session file)' if key in over else ''}", hb[key]]
        for key, name in (
            ("x0", "x0 (Table 1)"),
            ("y0", "y0 (Table 1)"),
            ("mu", "μ_hb (section 3.2)"),
            ("f", "f_hb (Table 2)"),
            ("c", "c = e (Table 2)"),
        )
    ]
    out.append(_html_table("Handbook constants", ["constant", "value"], hb_rows, ["", "g"]))
    # 2. measurements
    out.append("<h2>2. Measurements</h2>")
    for t in analysis.table4(result) + analysis.table5(result):
        out.append(_html_table(t.title, t.columns, t.rows, t.formats))
    rt = analysis.rows_table(result)
    out.append(_html_table(rt.title, rt.columns, rt.rows, rt.formats))
    # 3. coefficients
    out.append("<h2>3. Fitted coefficients and handbook comparison</h2>")
    out.append(_coefficient_tables(d))
    if d["mean_f0"] is not None:
        out.append(f"<p>Mean f0 of task 2: {d['mean_f0']:.6e} N·mm⁻²·min^(2/3).</p>")
    # 4. plots
    out.append("<h2>4. Plots</h2>")
    for k, (plot, svg) in enumerate(figures, start=1):
        uri = "data:image/svg+xml;base64," + base64.b64encode(svg.encode("utf-8")).decode("ascii")
        out.append(
            f'<figure><img alt="{html.escape(plot.title)}" src="{uri}">'
            f"<figcaption>Figure {k}. {html.escape(plot.title)}: experimental points and the fitted lines, "
            f"drawn from abscissa 0 to 1.1 × the largest experimental abscissa (files {plot.name}.png, "
            f"{plot.name}.svg).</figcaption></figure>"
        )
    # 5. conclusions
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


# ----------------------------------------------------------------------------- writing
def _write_csv(path, columns, rows):
    with open(path, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(columns)
        for row in rows:
            w.writerow(["" if v is None else (repr(v) if isinstance(v, float) else v) for v in row])


def _coefficient_csvs(d):
    out = []
    for name in ("task1", "task2", "task3"):
        rows = d[name]
        if not rows:
            continue
        columns = [k for k in rows[0] if k != "lines"] + ["lines"]
        out.append(
            (
                name,
                columns,
                [
                    [r[k] if k != "lines" else " ".join(map(str, r[k])) for k in columns]
                    for r in rows
                ],
            )
        )
    return out


def _is_replaceable(target):
    if not target.exists():
        return True
    if not target.is_dir():
        return False
    return not any(target.iterdir()) or (target / MARKER).is_file()


def write_report(result, out_dir, *, generated=None):
    """Write the report of an analysed session into a directory, atomically.

    Parameters
    ----------
    result : bearinglab.lab.analysis.LabResult
        The analysed session.
    out_dir : str or Path
        The report directory. It is created (with its parents); an existing directory is replaced
        only if it is empty or a previous report (it holds the marker file ``.bearinglab-report``).
    generated : str, optional
        Time stamp shown in the report (default: now, UTC).

    Returns
    -------
    ReportFiles

    Raises
    ------
    InputError
        ``out_dir`` exists and is a file or a directory that is not a previous report.

    Notes
    -----
    Everything is built in a temporary directory next to the target and renamed into place at the
    end; a failure at any point removes the temporary directory and leaves the target untouched.
    """
    from .lab import analysis

    target = Path(out_dir)
    if not _is_replaceable(target):
        raise InputError(
            f"out: {target} exists and is not a bearinglab report directory; give a new or empty "
            f"directory (a previous report is replaced)"
        )
    parent = target.parent if str(target.parent) else Path(".")
    parent.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(prefix=f".{target.name}.tmp-", dir=parent))
    try:
        umask = os.umask(0o022)
        os.umask(umask)
        os.chmod(
            tmp, 0o777 & ~umask
        )  # mkdtemp makes it private; a report directory is an ordinary one
        d = analysis.to_dict(result)
        figures, figure_files, table_files = [], [], []
        for plot in analysis.plots(result):
            png, svg = render_figure(plot)
            (tmp / f"{plot.name}.png").write_bytes(png)
            (tmp / f"{plot.name}.svg").write_text(svg, encoding="utf-8")
            figures.append((plot, svg))
            figure_files += [f"{plot.name}.png", f"{plot.name}.svg"]
        for t in [analysis.rows_table(result)] + analysis.table4(result) + analysis.table5(result):
            _write_csv(tmp / f"{t.name}.csv", t.columns, t.rows)
            table_files.append(f"{t.name}.csv")
        for name, columns, rows in _coefficient_csvs(d):
            _write_csv(tmp / f"{name}.csv", columns, rows)
            table_files.append(f"{name}.csv")
        d["files"] = {
            "html": "report.html",
            "json": "results.json",
            "figures": figure_files,
            "tables": table_files,
        }
        with open(tmp / "results.json", "w", encoding="utf-8") as fh:
            json.dump(d, fh, indent=2, ensure_ascii=False, allow_nan=False)
            fh.write("\n")
        (tmp / "report.html").write_text(
            render_html(result, figures, generated=generated), encoding="utf-8"
        )
        (tmp / MARKER).write_text(
            "bearinglab friction-lab report; this directory is replaced on the next run\n",
            encoding="utf-8",
        )
        _swap_into_place(tmp, target)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    return ReportFiles(
        target,
        target / "report.html",
        target / "results.json",
        [target / f for f in figure_files],
        [target / f for f in table_files],
    )


def _swap_into_place(tmp, target):
    if not _is_replaceable(target):  # checked again: something may have appeared meanwhile
        raise InputError(f"out: {target} exists and is not a bearinglab report directory")
    if not target.exists():
        os.rename(tmp, target)
        return
    if not any(target.iterdir()):
        target.rmdir()
        os.rename(tmp, target)
        return
    old = Path(tempfile.mkdtemp(prefix=f".{target.name}.old-", dir=tmp.parent))
    old.rmdir()
    os.rename(target, old)
    try:
        os.rename(tmp, target)
    except BaseException:
        os.rename(old, target)  # put the previous report back
        raise
    shutil.rmtree(old, ignore_errors=True)
