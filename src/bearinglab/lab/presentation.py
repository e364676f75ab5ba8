r"""A friction-lab session in engineering units: tables, plot data, conclusions, results (spec 001 section 7).

Tables (N*mm, rpm, deg, N, kg)
------------------------------
table4, table5      the layouts of Tables 4 and 5 (section 7.1-7.2), one table per tilt / per mass
rows_table          every row with its converted values
TableData           a table: file-name stem, caption, column headers, raw cells, display formats

Plots
-----
plots               points and fitted lines of the three plots, lines from abscissa 0 (section 7.4)
PlotData            one plot: name, title, axis labels and its series
PlotSeries          the points and fitted line of one fit

Conclusions and the results file
--------------------------------
conclusions         the generated conclusions with their numbers (section 7.5)
to_dict             every number of the analysis as a JSON-ready dict (``results.json``)
RESULTS_FORMAT      the format identifier of that dict
WORDING_THRESHOLD   the relative effect above which a conclusion calls an effect marked

This module only formats: every number comes from the
:class:`~bearinglab.lab.analysis.LabResult` of :func:`bearinglab.lab.analysis.analyse`. The plots are
drawn by :mod:`bearinglab.plots.friction` and written by :mod:`bearinglab.report`.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from ._rows import _by_tilt
from .rig import branch_switch_tilt

__all__ = [
    "RESULTS_FORMAT",
    "WORDING_THRESHOLD",
    "PlotData",
    "PlotSeries",
    "TableData",
    "conclusions",
    "plots",
    "rows_table",
    "table4",
    "table5",
    "to_dict",
]

RESULTS_FORMAT = "bearinglab-friction-results/1"
# Wording of the generated conclusions only (not from the source): a relative effect larger than this
# is called marked / not admissible / inadequate, a smaller one small / admissible / adequate.
WORDING_THRESHOLD = 0.10
_MM, _RPM = 1e-3, 2.0 * math.pi / 60.0  # m per mm, rad/s per rpm


def _f(x):
    """A float, or None for NaN (an empty cell, JSON null)."""
    x = float(x)
    return None if math.isnan(x) else x


def _sig(x):
    """A converted input without round-trip noise: 1500.0000000000002 rpm -> 1500.0, 59.99999999999999 deg -> 60.0."""
    return float(f"{float(x):.12g}")


def _deg(x):
    return f"{math.degrees(x):g}"


def _pct(x):
    v = x * 100
    return f"{0.0 if abs(v) < 0.05 else v:+.1f} %"


def _share(x, digits=1):
    return f"{x * 100:.{digits}f} %"


def _rpm(w):
    return f"{w / _RPM:.6g} rpm"


# ----------------------------------------------------------------------------- tables
class TableData(NamedTuple):
    """A table to print, write as CSV or render as HTML."""

    name: str
    """File-name stem, e.g. ``table4_tilt45``."""
    title: str
    """Caption."""
    columns: list
    """Column headers with units."""
    rows: list
    """Rows of raw cells (float, int, str or None for an empty cell)."""
    formats: list
    """Display format of each column (``format`` spec; ``""`` for text)."""


def table4(result):
    """Table 4 of spec 001 section 7.1, one table per tilt: Q, P0, and per speed column the readings,
    switch positions and converted values.

    Parameters
    ----------
    result : LabResult
        The analysed session.

    Returns
    -------
    list of TableData
    """
    s, rv, t1 = result.session, result.rows, result.task1
    out = []
    for tilt, ks in _by_tilt(t1.tilt).items():
        columns, formats = ["Q [kg]", "P0 [N]"], [".3g", ".6f"]
        for k in ks:
            lab = f"{t1.column[k]} (n = {t1.shaft_speed[k] / _RPM:.6g} rpm)"
            columns += [
                f"{lab}: speed reading",
                f"{lab}: n [rpm]",
                f"{lab}: torque reading",
                f"{lab}: switch",
                f"{lab}: T [N·mm]",
            ]
            formats += ["g", ".6g", "g", "d", ".9g"]
        cells = {}  # (mass, occurrence) -> {k: row index}
        for k in ks:
            seen = {}
            for i in sorted(t1.rows[k], key=lambda i: (s.rows.mass[i], i)):
                q = float(s.rows.mass[i])
                occ = seen.get(q, 0)
                seen[q] = occ + 1
                cells.setdefault((q, occ), {})[k] = i
        rows = []
        for (q, _occ), by_col in sorted(cells.items()):
            any_i = next(iter(by_col.values()))
            row = [q, float(rv.equivalent_load[any_i])]
            for k in ks:
                i = by_col.get(k)
                if i is None:
                    row += [None] * 5
                else:
                    row += [
                        _f(s.rows.speed_reading[i]),
                        _sig(rv.shaft_speed[i] / _RPM),
                        _f(s.rows.torque_reading[i]),
                        int(s.rows.switch[i]) or None,
                        _sig(rv.torque[i] / _MM),
                    ]
            rows.append(row)
        out.append(
            TableData(
                f"table4_tilt{_deg(tilt)}",
                f"Table 4. Friction torque at tilt β = {_deg(tilt)}°",
                columns,
                rows,
                formats,
            )
        )
    return out


def table5(result):
    """Table 5 of spec 001 section 7.2, one table per mass: speed settings (reading, n) and per tilt the
    torque reading, switch position and T; the P0 of each tilt in its column header.

    Parameters
    ----------
    result : LabResult
        The analysed session.

    Returns
    -------
    list of TableData
    """
    s, rv, t2 = result.session, result.rows, result.task2
    out = []
    masses = {}
    for k, q in enumerate(t2.mass):
        masses.setdefault(float(q), []).append(k)
    for q, ks in masses.items():
        columns, formats = ["speed reading", "n [rpm]"], ["g", ".6g"]
        for k in ks:
            lab = f"β = {_deg(t2.tilt[k])}° (P0 = {t2.equivalent_load[k]:.6g} N)"
            columns += [f"{lab}: torque reading", f"{lab}: switch", f"{lab}: T [N·mm]"]
            formats += ["g", "d", ".9g"]
        cells = {}
        for k in ks:
            seen = {}
            for i in t2.rows[k]:
                reading = s.rows.speed_reading[i]
                key = (
                    ("r", float(reading))
                    if not np.isnan(reading)
                    else ("n", float(rv.shaft_speed[i]))
                )
                occ = seen.get(key, 0)
                seen[key] = occ + 1
                cells.setdefault((key, occ), {})[k] = i
        rows = []
        for (key, _occ), by_col in sorted(
            cells.items(), key=lambda kv: (rv.shaft_speed[next(iter(kv[1].values()))], kv[0])
        ):
            any_i = next(iter(by_col.values()))
            row = [_f(s.rows.speed_reading[any_i]), _sig(rv.shaft_speed[any_i] / _RPM)]
            for k in ks:
                i = by_col.get(k)
                row += (
                    [None] * 3
                    if i is None
                    else [
                        _f(s.rows.torque_reading[i]),
                        int(s.rows.switch[i]) or None,
                        _sig(rv.torque[i] / _MM),
                    ]
                )
            rows.append(row)
        out.append(
            TableData(
                f"table5_Q{q:g}kg",
                f"Table 5. Friction torque at Q = {q:g} kg",
                columns,
                rows,
                formats,
            )
        )
    return out


def rows_table(result):
    """Every measurement row with its converted speed, torque, loads and P0.

    Parameters
    ----------
    result : LabResult
        The analysed session.

    Returns
    -------
    TableData
    """
    s, rv = result.session, result.rows
    columns = [
        "line",
        "series",
        "β [deg]",
        "Q [kg]",
        "column",
        "speed reading",
        "n [rpm]",
        "torque reading",
        "switch",
        "T [N·mm]",
        "F_a [N]",
        "F_r [N]",
        "P0 [N]",
        "P0 branch",
    ]
    formats = ["d", "", "g", "g", "", "g", ".6g", "g", "d", ".9g", ".6f", ".6f", ".6f", ""]
    rows = []
    for i in range(s.rows.line.size):
        rows.append(
            [
                int(s.rows.line[i]),
                s.rows.series[i],
                _sig(math.degrees(s.rows.tilt[i])),
                float(s.rows.mass[i]),
                s.rows.column[i],
                _f(s.rows.speed_reading[i]),
                _sig(rv.shaft_speed[i] / _RPM),
                _f(s.rows.torque_reading[i]),
                int(s.rows.switch[i]) or None,
                _sig(rv.torque[i] / _MM),
                float(rv.axial_load[i]),
                float(rv.radial_load[i]),
                float(rv.equivalent_load[i]),
                "x0·Fr + y0·Fa" if rv.combined[i] else "Fr",
            ]
        )
    return TableData("rows", "Measurement rows and converted values", columns, rows, formats)


class PlotSeries(NamedTuple):
    """Experimental points and fitted line of one fit (engineering units)."""

    label: str
    """Legend text."""
    x: np.ndarray
    """Abscissae of the points."""
    y: np.ndarray
    """Torque of the points. [N*mm]"""
    line_x: np.ndarray
    """Abscissae of the fitted line, from 0 to 1.1 times the largest abscissa of the plot."""
    line_y: np.ndarray
    """Torque on the fitted line. [N*mm]"""


class PlotData(NamedTuple):
    """One plot of section 7.4."""

    name: str
    """File-name stem."""
    title: str
    """Title."""
    xlabel: str
    """Abscissa label with unit."""
    ylabel: str
    """Ordinate label with unit."""
    series: list
    """The PlotSeries."""


# ----------------------------------------------------------------------------- plots
def plots(result):
    """Data of the three plots of spec 001 section 7.4 (task 1 and task 3 one plot per tilt).

    Parameters
    ----------
    result : LabResult
        The analysed session.

    Returns
    -------
    list of PlotData
        Lines are drawn from abscissa 0 to 1.1 times the largest experimental abscissa of the plot.
    """
    return _task1_plots(result) + _task2_plots(result) + _task3_plots(result)


def _task1_plots(result):
    """T against P0, one plot per tilt, one line per speed column: T = mu P0 d/2."""
    rv, t1 = result.rows, result.task1
    d_mm = result.session.bearing.bore / _MM
    t_nmm = rv.torque / _MM
    out = []
    for tilt, ks in _by_tilt(t1.tilt).items():
        xmax = 1.1 * max(rv.equivalent_load[t1.rows[k]].max() for k in ks)
        series = []
        for k in ks:
            idx, mu = t1.rows[k], t1.reduced_friction_coefficient[k]
            lx = np.array([0.0, xmax])
            series.append(
                PlotSeries(
                    f"n = {t1.shaft_speed[k] / _RPM:.6g} rpm: μ = {mu:.4e}",
                    rv.equivalent_load[idx],
                    t_nmm[idx],
                    lx,
                    mu * lx * d_mm / 2,
                )
            )
        out.append(
            PlotData(
                f"task1_tilt{_deg(tilt)}",
                f"Task 1: T = μ·P0·d/2 at β = {_deg(tilt)}°",
                "P0 [N]",
                "T [N·mm]",
                series,
            )
        )
    return out


def _task2_plots(result):
    """T against N = n^(2/3), one plot (none without task 2), one line per Table 5 column."""
    rv, t2 = result.rows, result.task2
    if not t2.tilt.size:
        return []
    dm_mm = result.session.bearing.mean_diameter / _MM
    t_nmm = rv.torque / _MM
    n23 = (rv.shaft_speed / _RPM) ** (2.0 / 3.0)
    xmax = 1.1 * max(n23[t2.rows[k]].max() for k in range(t2.tilt.size))
    series = []
    for k in range(t2.tilt.size):
        idx = t2.rows[k]
        lx = np.array([0.0, xmax])
        series.append(
            PlotSeries(
                f"β = {_deg(t2.tilt[k])}°, Q = {t2.mass[k]:g} kg: f0 = {t2.speed_term_factor[k]:.4e}, "
                f"T_F = {t2.load_term[k] / _MM:.4g} N·mm",
                n23[idx],
                t_nmm[idx],
                lx,
                t2.speed_term_factor[k] * dm_mm**3 * lx + t2.load_term[k] / _MM,
            )
        )
    return [
        PlotData(
            "task2",
            "Task 2: T = f0·d_m³·N + T_F, N = n^(2/3)",
            "N = n^(2/3) [min^(-2/3)]",
            "T [N·mm]",
            series,
        )
    ]


def _task3_plots(result):
    """T against N = P0^(1+e), one plot per tilt, one line per speed column."""
    rv, t3 = result.rows, result.task3
    b, e = result.session.bearing, result.session.handbook.load_term_exponent
    dm_mm, c0 = b.mean_diameter / _MM, b.static_load_rating
    t_nmm = rv.torque / _MM
    out = []
    for tilt, ks in _by_tilt(t3.tilt).items():
        big_n = rv.equivalent_load ** (1.0 + e)
        xmax = 1.1 * max(big_n[t3.rows[k]].max() for k in ks)
        series = []
        for k in ks:
            idx = t3.rows[k]
            lx = np.array([0.0, xmax])
            series.append(
                PlotSeries(
                    f"n = {t3.shaft_speed[k] / _RPM:.6g} rpm: f = {t3.load_term_factor[k]:.4e}, "
                    f"T0 = {t3.speed_term[k] / _MM:.4g} N·mm",
                    big_n[idx],
                    t_nmm[idx],
                    lx,
                    t3.speed_term[k] / _MM + t3.load_term_factor[k] * dm_mm / c0**e * lx,
                )
            )
        out.append(
            PlotData(
                f"task3_tilt{_deg(tilt)}",
                f"Task 3: T = T0 + f·d_m·N/C0^e at β = {_deg(tilt)}°",
                f"N = P0^(1+e) [N^{1 + e:g}]",
                "T [N·mm]",
                series,
            )
        )
    return out


# ----------------------------------------------------------------------------- conclusions
def conclusions(result):
    """The generated conclusions of spec 001 section 7.5, with their numbers.

    Parameters
    ----------
    result : LabResult
        The analysed session.

    Returns
    -------
    list of str
        One paragraph per indicator that the data allow; the wording uses :data:`WORDING_THRESHOLD`.
    """
    return (
        _task1_conclusions(result)
        + _task2_conclusions(result)
        + _task3_conclusions(result)
        + _task4_conclusions(result)
    )


def _task1_conclusions(result):
    """I1 (speed effect on mu), I2 (mu against the handbook), I3 (adequacy of the one-term model)."""
    ind, hb, t1 = result.indicators, result.session.handbook, result.task1
    th = WORDING_THRESHOLD
    out = []
    if t1.tilt.size == 0:
        out.append("No T4 rows: tasks 1 and 3 were not run.")
    for tilt, lo, hi, i1 in ind.speed_effect_on_mu:
        judged = (
            "depends markedly on speed" if abs(i1) > th else "is practically independent of speed"
        )
        out.append(
            f"I1, effect of speed on μ (β = {_deg(tilt)}°): μ(n_max)/μ(n_min) − 1 = {_pct(i1)} between {_rpm(lo)} "
            f"and {_rpm(hi)}; the reduced friction coefficient {judged}."
        )
    if t1.tilt.size == 0:
        return out
    parts = ", ".join(
        f"{_pct(v)} at {_rpm(n)} (β = {_deg(t)}°)"
        for v, n, t in zip(ind.mu_vs_handbook, t1.shaft_speed, t1.tilt)
    )
    ok = np.all(np.abs(ind.mu_vs_handbook) <= th)
    verdict = (
        f"admissible within ±{_share(th, 0)} at every speed"
        if ok
        else f"not admissible within ±{_share(th, 0)} everywhere"
    )
    out.append(
        f"I2, admissibility of the one-term formula: μ/μ_hb − 1 = {parts} "
        f"(μ_hb = {hb.reduced_friction_coefficient:g}); the handbook value is {verdict}."
    )
    parts = ", ".join(
        f"{_share(v)} at {_rpm(n)}" for v, n in zip(ind.one_term_adequacy, t1.shaft_speed)
    )
    bad = np.any(ind.one_term_adequacy > th)
    verdict = (
        "the line through the origin misses a load-independent part of the torque (T0): the two-term "
        "model is needed"
        if bad
        else "the one-term model describes the data adequately"
    )
    out.append(f"I3, adequacy of the one-term model: residual RMS / mean T = {parts}; {verdict}.")
    return out


def _task2_conclusions(result):
    """I4 (f0 against tilt and mass), I5 (load term against (3.4)), T_F against the handbook."""
    ind, hb, t2 = result.indicators, result.session.handbook, result.task2
    th = WORDING_THRESHOLD
    if t2.tilt.size == 0:
        return ["No T5 rows: task 2 was not run."]
    out = []
    parts = ", ".join(
        f"{f:.4e} (β = {_deg(t)}°, Q = {q:g} kg)"
        for f, t, q in zip(t2.speed_term_factor, t2.tilt, t2.mass)
    )
    if math.isnan(ind.f0_spread):
        out.append(
            f"f0 = {parts} N·mm⁻²·min^(2/3); one Table 5 column only, so I4 is not available."
        )
    else:
        what = "β" if np.unique(t2.mass).size == 1 else "β and Q"  # the columns differ in these
        verdict = (
            f"f0 does not depend on {what}, as the model assumes"
            if ind.f0_spread <= th
            else f"f0 varies with {what}, contrary to the model"
        )
        out.append(
            f"I4, dependence of f0 on {what}: f0 = {parts} N·mm⁻²·min^(2/3), mean {ind.mean_speed_term_factor:.6e}; "
            f"(max − min)/mean = {_share(ind.f0_spread, 2)}: {verdict}."
        )
    for a, bb, measured, predicted in ind.load_term_ratio:
        out.append(
            f"I5, load term against (3.4): T_F = {t2.load_term[a] / _MM:.6g} N·mm at β = {_deg(t2.tilt[a])}° "
            f"{'' if t2.mass[a] == t2.mass[bb] else f'(Q = {t2.mass[a]:g} kg) '}"
            f"and {t2.load_term[bb] / _MM:.6g} N·mm at β = {_deg(t2.tilt[bb])}° (Q = {t2.mass[bb]:g} kg): "
            f"measured ratio {measured:.6f}, predicted (P0 ratio)^(1+c) = {predicted:.6f} "
            f"({_pct(measured / predicted - 1)})."
        )
    parts = ", ".join(
        f"{tf / _MM:.6g} vs {h / _MM:.6g} N·mm (β = {_deg(t)}°)"
        for tf, h, t in zip(t2.load_term, t2.handbook_load_term, t2.tilt)
    )
    out.append(
        f"T_F of task 2 vs the handbook f_hb·P0·(P0/C0)^c·d_m with f_hb = {hb.load_term_factor:g}: {parts}."
    )
    for k in np.flatnonzero(~np.isnan(t2.load_term_with_task3_factor)):
        out.append(
            f"T_F of task 2 at β = {_deg(t2.tilt[k])}° vs the value with f of task 3 at the same β: "
            f"{t2.load_term[k] / _MM:.6g} vs {t2.load_term_with_task3_factor[k] / _MM:.6g} N·mm."
        )
    for k in np.flatnonzero(t2.load_term < 0):
        out.append(
            f"Warning: T_F at β = {_deg(t2.tilt[k])}° is negative ({t2.load_term[k] / _MM:.4g} N·mm); it is an "
            f"extrapolation to n → 0 that the data do not support."
        )
    return out


def _task4_conclusions(result):
    """Task 4: the fitted mu_sl / scale on M_rr against the SKF model's own values."""
    t4 = result.task4
    if t4 is None:
        return []
    out = []
    for k in range(t4.tilt.size):
        parts = []
        if t4.fit in ("sliding", "both"):
            mu, se = t4.sliding_friction_coefficient[k], t4.sliding_friction_coefficient_standard_error[k]
            model = t4.model_sliding_friction_coefficient[k]
            parts.append(f"μ_sl = {mu:.4g} ± {se:.2g} (the model's μ_sl: {model:.4g}, {_pct(mu / model - 1)})")
        if t4.fit in ("rolling", "both"):
            parts.append(
                f"scale on M_rr k = {t4.rolling_scale[k]:.4g} ± {t4.rolling_scale_standard_error[k]:.2g}"
            )
        share = t4.residual_rms[k] / t4.mean_torque[k]
        out.append(
            f"Task 4, SKF four-term model (β = {_deg(t4.tilt[k])}°, {int(t4.count[k])} rows): "
            f"{'; '.join(parts)}. Residual RMS {t4.residual_rms[k] / _MM:.4g} N·mm = {_share(share)} of the "
            f"mean torque; the unfitted model misses by {t4.model_residual_rms[k] / _MM:.4g} N·mm RMS."
        )
    return out


def _task3_conclusions(result):
    """I6 (f against speed and the handbook), I7 (speed term against (3.5)), T0 against task 2."""
    ind, hb, t3 = result.indicators, result.session.handbook, result.task3
    th = WORDING_THRESHOLD
    if not t3.tilt.size:
        return []
    out = []
    for tilt, i6 in ind.f_spread:
        ks = np.flatnonzero(np.isclose(t3.tilt, tilt, rtol=0, atol=1e-12))
        parts = ", ".join(f"{t3.load_term_factor[k]:.4e} at {_rpm(t3.shaft_speed[k])}" for k in ks)
        verdict = "f is practically independent of speed" if i6 <= th else "f depends on speed"
        rel = ", ".join(_pct(ind.f_vs_handbook[k]) for k in ks)
        out.append(
            f"I6, dependence of f on speed (β = {_deg(tilt)}°): f = {parts}; (max − min)/mean = {_share(i6, 2)}: "
            f"{verdict}. Against f_hb = {hb.load_term_factor:g}: f/f_hb − 1 = {rel}."
        )
    if not ind.f_spread:
        rel = ", ".join(
            f"{_pct(v)} at {_rpm(n)}" for v, n in zip(ind.f_vs_handbook, t3.shaft_speed)
        )
        out.append(
            f"f/f_hb − 1 = {rel} (f_hb = {hb.load_term_factor:g}); one speed per tilt, so I6 is not available."
        )
    for tilt, na, nb, measured, predicted in ind.speed_term_ratio:
        out.append(
            f"I7, speed term against (3.5) (β = {_deg(tilt)}°): T0({_rpm(nb)})/T0({_rpm(na)}) = {measured:.6f}, "
            f"predicted (n_b/n_a)^(2/3) = {predicted:.6f} ({_pct(measured / predicted - 1)})."
        )
    if not math.isnan(ind.mean_speed_term_factor):
        several = np.unique(t3.tilt).size > 1
        parts = ", ".join(
            f"{a / _MM:.6f} vs {p / _MM:.6f} N·mm at {_rpm(n)}"
            + (f" (β = {_deg(t)}°)" if several else "")
            for a, p, n, t in zip(
                t3.speed_term, t3.speed_term_with_task2_factor, t3.shaft_speed, t3.tilt
            )
        )
        out.append(
            f"T0 of task 3 vs f0·d_m³·n^(2/3) with the mean f0 of task 2 ({ind.mean_speed_term_factor:.6e}): "
            f"{parts}."
        )
    for k in np.flatnonzero(t3.speed_term < 0):
        out.append(
            f"Warning: T0 at {_rpm(t3.shaft_speed[k])} (β = {_deg(t3.tilt[k])}°) is negative "
            f"({t3.speed_term[k] / _MM:.4g} N·mm); it is an extrapolation to P0 → 0 that the data do not "
            f"support."
        )
    return out


# ----------------------------------------------------------------------------- results file
def to_dict(result):
    """Every number of the analysis as a JSON-ready dict (N*mm, rpm, deg, N, kg; NaN -> None).

    Parameters
    ----------
    result : LabResult
        The analysed session.

    Returns
    -------
    dict
        Keys ``format``, ``source``, ``session``, ``bearing``, ``handbook``, ``rig``, ``rows``, ``task1``,
        ``task2``, ``task3``, ``task4`` (the SKF model fit; empty without an ``[skf]`` table), ``mean_f0``,
        ``indicators``, ``tables``, ``plots`` and ``conclusions``.
    """
    s = result.session
    task1, task2, task3 = _task1_dicts(result), _task2_dicts(result), _task3_dicts(result)
    tables = [rows_table(result)] + table4(result) + table5(result)
    return {
        "format": RESULTS_FORMAT,
        "source": s.source,
        "rows_source": s.rows_source,
        "session": dict(s.info),
        "bearing": _bearing_dict(s.bearing),
        "handbook": _handbook_dict(s.handbook),
        "rig": _rig_dict(s),
        "rows": _row_dicts(result),
        "task1": task1,
        "task2": task2,
        "task3": task3,
        "task4": _task4_dicts(result),
        "mean_f0": _f(result.indicators.mean_speed_term_factor),
        "indicators": _indicator_dicts(result, task1, task3),
        "tables": [
            {"name": t.name, "title": t.title, "columns": t.columns, "rows": t.rows} for t in tables
        ],
        "plots": [_plot_dict(p) for p in plots(result)],
        "conclusions": conclusions(result),
    }


def _bearing_dict(b):
    return {
        "designation": b.designation,
        "type": b.type,
        "contact_angle_deg": None if b.contact_angle is None else math.degrees(b.contact_angle),
        "bore_mm": b.bore / _MM,
        "outside_diameter_mm": b.outside_diameter / _MM,
        "mean_diameter_mm": b.mean_diameter / _MM,
        "static_load_rating_N": b.static_load_rating,
        "source": b.source or None,
    }


def _handbook_dict(hb):
    return {
        "x0": hb.radial_factor,
        "y0": hb.axial_factor,
        "mu": hb.reduced_friction_coefficient,
        "f": hb.load_term_factor,
        "c": hb.load_term_exponent,
        "overridden": list(hb.overridden),
    }


def _rig_dict(s):
    hb = s.handbook
    return {
        "tare_mass_kg": s.tare_mass,
        "gravity_m_per_s2": s.gravity,
        "branch_switch_tilt_deg": math.degrees(
            branch_switch_tilt(hb.radial_factor, hb.axial_factor)
        )
        if hb.radial_factor < 1
        else None,
    }


def _row_dicts(result):
    r, rv = result.session.rows, result.rows
    return [
        {
            "line": int(r.line[i]),
            "series": r.series[i],
            "tilt_deg": _sig(math.degrees(r.tilt[i])),
            "mass_kg": float(r.mass[i]),
            "column": r.column[i] or None,
            "speed_reading": _f(r.speed_reading[i]),
            "speed_rpm": _sig(rv.shaft_speed[i] / _RPM),
            "torque_reading": _f(r.torque_reading[i]),
            "switch": int(r.switch[i]) or None,
            "torque_Nmm": _sig(rv.torque[i] / _MM),
            "axial_load_N": float(rv.axial_load[i]),
            "radial_load_N": float(rv.radial_load[i]),
            "equivalent_static_load_N": float(rv.equivalent_load[i]),
            "branch": "x0*Fr+y0*Fa" if rv.combined[i] else "Fr",
            "note": r.note[i] or None,
        }
        for i in range(r.line.size)
    ]


def _lines(result, rows_idx):
    return [int(x) for x in result.session.rows.line[rows_idx]]


def _task1_dicts(result):
    t1, hb = result.task1, result.session.handbook
    return [
        {
            "tilt_deg": _sig(math.degrees(t1.tilt[k])),
            "column": t1.column[k],
            "speed_rpm": _sig(t1.shaft_speed[k] / _RPM),
            "mu": float(t1.reduced_friction_coefficient[k]),
            "mu_standard_error": _f(t1.standard_error[k]),
            "residual_rms_Nmm": float(t1.residual_rms[k] / _MM),
            "n_points": int(t1.count[k]),
            "mean_torque_Nmm": float(t1.mean_torque[k] / _MM),
            "mu_handbook": hb.reduced_friction_coefficient,
            "mu_relative_to_handbook": float(t1.relative_to_handbook[k]),
            "residual_rms_relative_to_mean_torque": float(t1.relative_rms[k]),
            "lines": _lines(result, t1.rows[k]),
        }
        for k in range(t1.tilt.size)
    ]


def _task2_dicts(result):
    t2 = result.task2
    return [
        {
            "tilt_deg": _sig(math.degrees(t2.tilt[k])),
            "mass_kg": float(t2.mass[k]),
            "equivalent_static_load_N": float(t2.equivalent_load[k]),
            "f0": float(t2.speed_term_factor[k]),
            "f0_standard_error": _f(t2.speed_term_factor_standard_error[k]),
            "torque_load_term_Nmm": float(t2.load_term[k] / _MM),
            "torque_load_term_standard_error_Nmm": _f(t2.load_term_standard_error[k] / _MM),
            "residual_rms_Nmm": float(t2.residual_rms[k] / _MM),
            "n_points": int(t2.count[k]),
            "handbook_torque_load_term_Nmm": float(t2.handbook_load_term[k] / _MM),
            "torque_load_term_with_task3_f_Nmm": _f(t2.load_term_with_task3_factor[k] / _MM),
            "negative_intercept": bool(t2.load_term[k] < 0),
            "lines": _lines(result, t2.rows[k]),
        }
        for k in range(t2.tilt.size)
    ]


def _task3_dicts(result):
    t3, hb = result.task3, result.session.handbook
    return [
        {
            "tilt_deg": _sig(math.degrees(t3.tilt[k])),
            "column": t3.column[k],
            "speed_rpm": _sig(t3.shaft_speed[k] / _RPM),
            "f": float(t3.load_term_factor[k]),
            "f_standard_error": _f(t3.load_term_factor_standard_error[k]),
            "torque_speed_term_Nmm": float(t3.speed_term[k] / _MM),
            "torque_speed_term_standard_error_Nmm": _f(t3.speed_term_standard_error[k] / _MM),
            "residual_rms_Nmm": float(t3.residual_rms[k] / _MM),
            "n_points": int(t3.count[k]),
            "f_handbook": hb.load_term_factor,
            "f_relative_to_handbook": float(t3.relative_to_handbook[k]),
            "torque_speed_term_with_task2_f0_Nmm": _f(t3.speed_term_with_task2_factor[k] / _MM),
            "negative_intercept": bool(t3.speed_term[k] < 0),
            "lines": _lines(result, t3.rows[k]),
        }
        for k in range(t3.tilt.size)
    ]


def _task4_dicts(result):
    t4 = result.task4
    if t4 is None:
        return []
    return [
        {
            "tilt_deg": _sig(math.degrees(t4.tilt[k])),
            "fitted": t4.fit,
            "mu_sl": _f(t4.sliding_friction_coefficient[k]),
            "mu_sl_standard_error": _f(t4.sliding_friction_coefficient_standard_error[k]),
            "rolling_scale": float(t4.rolling_scale[k]),
            "rolling_scale_standard_error": _f(t4.rolling_scale_standard_error[k]),
            "mu_sl_model": float(t4.model_sliding_friction_coefficient[k]),
            "residual_rms_Nmm": float(t4.residual_rms[k] / _MM),
            "model_residual_rms_Nmm": float(t4.model_residual_rms[k] / _MM),
            "mean_torque_Nmm": float(t4.mean_torque[k] / _MM),
            "n_points": int(t4.count[k]),
            "lines": _lines(result, t4.rows[k]),
        }
        for k in range(t4.tilt.size)
    ]


def _indicator_dicts(result, task1, task3):
    """I1-I7; those per task-1 or task-3 group are taken from the task dicts."""
    ind, t2 = result.indicators, result.task2
    return {
        "I1": [
            {
                "tilt_deg": _sig(math.degrees(t)),
                "speed_min_rpm": _sig(lo / _RPM),
                "speed_max_rpm": _sig(hi / _RPM),
                "value": v,
            }
            for t, lo, hi, v in ind.speed_effect_on_mu
        ],
        "I2": _per_group(task1, value="mu_relative_to_handbook"),
        "I3": _per_group(task1, value="residual_rms_relative_to_mean_torque"),
        "I4": {"value": _f(ind.f0_spread), "mean_f0": _f(ind.mean_speed_term_factor)},
        "I5": [
            {
                "tilt_a_deg": _sig(math.degrees(t2.tilt[a])),
                "mass_a_kg": float(t2.mass[a]),
                "tilt_b_deg": _sig(math.degrees(t2.tilt[bb])),
                "mass_b_kg": float(t2.mass[bb]),
                "measured": m,
                "predicted": p,
            }
            for a, bb, m, p in ind.load_term_ratio
        ],
        "I6": [{"tilt_deg": _sig(math.degrees(t)), "value": v} for t, v in ind.f_spread],
        "I6_f_relative_to_handbook": _per_group(task3, value="f_relative_to_handbook"),
        "I7": [
            {
                "tilt_deg": _sig(math.degrees(t)),
                "speed_a_rpm": _sig(na / _RPM),
                "speed_b_rpm": _sig(nb / _RPM),
                "measured": m,
                "predicted": p,
            }
            for t, na, nb, m, p in ind.speed_term_ratio
        ],
        "I7_torque_speed_term_vs_task2": _per_group(
            task3,
            task3_Nmm="torque_speed_term_Nmm",
            from_task2_f0_Nmm="torque_speed_term_with_task2_f0_Nmm",
        ),
    }


def _per_group(records, **fields):
    """Tilt, speed and ``key: record[field]`` for every task-1 or task-3 record."""
    return [
        {"tilt_deg": r["tilt_deg"], "speed_rpm": r["speed_rpm"]}
        | {key: r[field] for key, field in fields.items()}
        for r in records
    ]


def _plot_dict(p):
    return {
        "name": p.name,
        "title": p.title,
        "xlabel": p.xlabel,
        "ylabel": p.ylabel,
        "series": [
            {
                "label": ps.label,
                "x": ps.x.tolist(),
                "y": ps.y.tolist(),
                "line_x": ps.line_x.tolist(),
                "line_y": ps.line_y.tolist(),
            }
            for ps in p.series
        ],
    }
