r"""One measurement session -> everything the friction lab reports (spec 001 sections 6 and 7).

Analysis
--------
analyse          Session -> LabResult: per-row speed, torque, loads and P0; the three tasks; the
                 cross-checks of section 6.5; the indicators I1-I7 of section 7.5
LabResult        the results (SI), with the session they came from

Presentation (engineering units: N*mm, rpm, deg, N, kg)
-------------------------------------------------------
table4, table5   the layouts of Tables 4 and 5 (section 7.1-7.2), one table per tilt / per mass
rows_table       every row with its converted values
plots            points and fitted lines of the three plots, lines from abscissa 0 (section 7.4)
conclusions      the generated conclusions with their numbers (section 7.5)
to_dict          every number of the analysis as a JSON-ready dict

Grouping. T4 rows are grouped by (tilt, speed-column label): one task-1 and one task-3 fit per
group, at the column speed = the mean n of its rows (section 6.1). T5 rows are grouped by (mass,
tilt): one task-2 fit per group. All groups of a task are fitted at once (:mod:`.fits`).

Every number here can be had from :mod:`bearinglab.friction`, :mod:`.rig`, :mod:`.calibration` and
:mod:`.fits` directly; this module only composes them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from .. import friction
from ..errors import InputError
from . import fits
from .calibration import convert, convert_torque
from .rig import branch_switch_tilt, rig_equivalent_load

__all__ = [
    "RESULTS_FORMAT",
    "WORDING_THRESHOLD",
    "Indicators",
    "LabResult",
    "PlotData",
    "PlotSeries",
    "RowValues",
    "TableData",
    "Task1",
    "Task2",
    "Task3",
    "analyse",
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
_MM, _RPM, _DEG = 1e-3, 2.0 * math.pi / 60.0, math.pi / 180.0


class RowValues(NamedTuple):
    """Converted values of every measurement row (SI)."""

    shaft_speed: np.ndarray
    """n. [rad/s]"""
    torque: np.ndarray
    """T. [N*m]"""
    axial_load: np.ndarray
    """F_a. [N]"""
    radial_load: np.ndarray
    """F_r. [N]"""
    equivalent_load: np.ndarray
    """P0. [N]"""
    combined: np.ndarray
    """True where x0 F_r + y0 F_a governs (3.1)."""


class Task1(NamedTuple):
    """Task 1 per (tilt, speed column), with the cross-check against mu_hb."""

    tilt: np.ndarray
    """[rad]"""
    column: np.ndarray
    """Speed-column label."""
    shaft_speed: np.ndarray
    """Column speed, the mean n of its rows. [rad/s]"""
    friction_coefficient: np.ndarray
    """mu of (6.1). [-]"""
    standard_error: np.ndarray
    """Standard error of mu (NaN for one point). [-]"""
    residual_rms: np.ndarray
    """[N*m]"""
    count: np.ndarray
    """Number of rows. [-]"""
    mean_torque: np.ndarray
    """Mean T of the column. [N*m]"""
    relative_to_handbook: np.ndarray
    """mu/mu_hb - 1 (indicator I2). [-]"""
    relative_rms: np.ndarray
    """residual RMS / mean T (indicator I3). [-]"""
    rows: tuple
    """Row indices of each group."""


class Task2(NamedTuple):
    """Task 2 per (mass, tilt) of Table 5, with the cross-checks of section 6.5."""

    mass: np.ndarray
    """Q (without tare). [kg]"""
    tilt: np.ndarray
    """[rad]"""
    equivalent_load: np.ndarray
    """P0 of the group. [N]"""
    speed_term_factor: np.ndarray
    """f0. [N*mm^-2*min^(2/3)]"""
    speed_term_factor_standard_error: np.ndarray
    """[N*mm^-2*min^(2/3)]"""
    load_term: np.ndarray
    """T_F, the intercept at n -> 0. [N*m]"""
    load_term_standard_error: np.ndarray
    """[N*m]"""
    residual_rms: np.ndarray
    """[N*m]"""
    count: np.ndarray
    """Number of rows. [-]"""
    handbook_load_term: np.ndarray
    """f_hb P0 (P0/C0)^c d_m at the group's P0. [N*m]"""
    load_term_with_task3_factor: np.ndarray
    """The same with the mean f of task 3 at this tilt (NaN if task 3 has no group at it). [N*m]"""
    rows: tuple
    """Row indices of each group."""


class Task3(NamedTuple):
    """Task 3 per (tilt, speed column), with the cross-checks of section 6.5."""

    tilt: np.ndarray
    """[rad]"""
    column: np.ndarray
    """Speed-column label."""
    shaft_speed: np.ndarray
    """Column speed. [rad/s]"""
    load_term_factor: np.ndarray
    """f of (6.3). [-]"""
    load_term_factor_standard_error: np.ndarray
    """[-]"""
    speed_term: np.ndarray
    """T0, the intercept at P0 -> 0. [N*m]"""
    speed_term_standard_error: np.ndarray
    """[N*m]"""
    residual_rms: np.ndarray
    """[N*m]"""
    count: np.ndarray
    """Number of rows. [-]"""
    relative_to_handbook: np.ndarray
    """f/f_hb - 1. [-]"""
    speed_term_with_task2_factor: np.ndarray
    """f0 d_m^3 n^(2/3) with the mean f0 of task 2 (NaN without task 2). [N*m]"""
    rows: tuple
    """Row indices of each group."""


class Indicators(NamedTuple):
    """The conclusion indicators of spec 001 section 7.5 (SI; ratios dimensionless)."""

    speed_effect_on_mu: tuple
    """I1 per tilt: ``(tilt, n_min, n_max, mu(n_max)/mu(n_min) - 1)``."""
    mu_vs_handbook: np.ndarray
    """I2 per task-1 group: mu/mu_hb - 1."""
    one_term_adequacy: np.ndarray
    """I3 per task-1 group: residual RMS / mean T."""
    f0_spread: float
    """I4: (max f0 - min f0)/mean f0 over the task-2 groups (NaN with fewer than two)."""
    mean_speed_term_factor: float
    """Mean f0 of task 2 (NaN without task 2). [N*mm^-2*min^(2/3)]"""
    load_term_ratio: tuple
    """I5: ``(group_a, group_b, measured T_F(b)/T_F(a), predicted (P0_b/P0_a)^(1+c))`` against the first
    task-2 group."""
    f_spread: tuple
    """I6 per tilt with two or more task-3 groups: ``(tilt, (max f - min f)/mean f)``."""
    f_vs_handbook: np.ndarray
    """I6, second part, per task-3 group: f/f_hb - 1."""
    speed_term_ratio: tuple
    """I7 per tilt: ``(tilt, n_a, n_b, measured T0(n_b)/T0(n_a), predicted (n_b/n_a)^(2/3))``."""


@dataclass(frozen=True)
class LabResult:
    """Everything computed from one session (SI)."""

    session: object
    """The :class:`~bearinglab.lab.measurement.Session` analysed."""
    rows: RowValues
    """Per-row converted values."""
    task1: Task1
    """Task 1 (empty arrays without T4 rows)."""
    task2: Task2
    """Task 2 (empty arrays without T5 rows)."""
    task3: Task3
    """Task 3 (empty arrays without T4 rows)."""
    indicators: Indicators
    """I1-I7."""


# ----------------------------------------------------------------------------- analysis
def _groups(keys_sorted, mask):
    """Group ids 0..G-1 of the masked rows from sort keys (primary key last); -1 elsewhere."""
    idx = np.flatnonzero(mask)
    gid = np.full(mask.size, -1)
    if idx.size == 0:
        return gid, []
    inverse = []
    for key in keys_sorted:
        _u, inv = np.unique(np.asarray(key)[idx], return_inverse=True)
        inverse.append(inv.ravel())
    combined = np.zeros(idx.size, dtype=np.int64)
    for inv in inverse:
        combined = combined * (int(inv.max()) + 1) + inv
    _u, g = np.unique(combined, return_inverse=True)
    gid[idx] = g.ravel()
    members = [idx[g.ravel() == k] for k in range(_u.size)]
    return gid, members


def _where_rows(session, rows_idx):
    lines = ", ".join(str(int(x)) for x in session.rows.line[rows_idx])
    return f"{session.rows_source}, line{'s' if len(rows_idx) > 1 else ''} {lines}"


def _fail_group(session, rows_idx, what, field, message):
    return InputError(f"{_where_rows(session, rows_idx)} ({what}), field {field!r}: {message}")


def analyse(session):
    r"""Analyse a measurement session: convert, fit the three tasks, cross-check, compute I1-I7.

    Parameters
    ----------
    session : Session
        From :func:`bearinglab.lab.measurement.read_session` (or built in Python).

    Returns
    -------
    LabResult

    Raises
    ------
    InputError
        A reading outside its calibration, a task-1 group whose P0 are all zero, a task-2 group with
        fewer than two distinct speeds or a task-3 group with fewer than two distinct P0; the message
        names the file, the lines of the group and the field (spec 001 section 9).

    Examples
    --------
    Task 1 of spec 001 data set S0 at 1500 rpm (a session with its rows inline):

    >>> from bearinglab.lab import measurement
    >>> text = "\n".join(['[bearing]', 'catalog = "1000095"', '[measurements]', "csv = '''",
    ...                   "series, tilt [deg], mass [kg], column, speed [rpm], torque [N*mm]",
    ...                   "T4, 90, 0.5, A, 1500, 0.025055204", "T4, 90, 1.0, A, 1500, 0.036527822",
    ...                   "T4, 90, 2.0, A, 1500, 0.070121614", "'''"])
    >>> result = analyse(measurement.parse_session(text))
    >>> print(f"{result.task1.friction_coefficient[0]:.6e} {result.task3.load_term_factor[0]:.6e}")
    1.470209e-03 1.500000e-03
    """
    s = session
    r = s.rows
    b = s.bearing
    hb = s.handbook
    bore, dm, c0 = b.bore, b.mean_diameter, b.static_load_rating
    # ---- per row (6.1)
    speed = r.speed.astype(float).copy()
    read_speed = np.isnan(speed)
    if read_speed.any():
        speed[read_speed] = convert(r.speed_reading[read_speed], s.calibration.speed)
    torque = r.torque.astype(float).copy()
    read_torque = np.isnan(torque)
    if read_torque.any():
        torque[read_torque] = convert_torque(
            r.torque_reading[read_torque], r.switch[read_torque], s.calibration
        )
    loads = rig_equivalent_load(
        r.mass,
        r.tilt,
        tare_mass=s.tare_mass,
        gravity=s.gravity,
        bearing_type=b.type,
        contact_angle=b.contact_angle if b.type == "angular" else None,
        radial_factor=hb.radial_factor,
        axial_factor=hb.axial_factor,
    )
    rows = RowValues(speed, torque, *(np.atleast_1d(np.asarray(v)) for v in loads))
    p0 = rows.equivalent_load
    # ---- T4 groups: (tilt, column), ordered by tilt then column speed
    t4 = r.series == "T4"
    gid4, members4 = _groups([r.column.astype(str), r.tilt], t4)
    n4 = len(members4)
    col_speed = np.array([speed[m].mean() for m in members4]) if n4 else np.zeros(0)
    tilt4 = np.array([r.tilt[m[0]] for m in members4]) if n4 else np.zeros(0)
    order = np.lexsort((col_speed, tilt4))
    members4 = [members4[k] for k in order]
    col_speed, tilt4 = col_speed[order], tilt4[order]
    label4 = np.array([r.column[m[0]] for m in members4], dtype=object)
    gid4 = np.full(r.line.size, -1)
    for k, m in enumerate(members4):
        gid4[m] = k
    sel4 = np.flatnonzero(t4)
    for k, m in enumerate(members4):
        what = f"Table 4 column {label4[k]!r} at tilt {math.degrees(tilt4[k]):g} deg"
        if not np.any(p0[m] > 0):
            raise _fail_group(
                s,
                m,
                what,
                "mass",
                "task 1: all P0 are zero; a line through the origin needs a load",
            )
        if not np.ptp(p0[m]) > 0:
            raise _fail_group(
                s,
                m,
                what,
                "mass",
                f"task 3 needs at least two distinct loads P0, got {m.size} "
                f"row(s) all at P0 = {p0[m][0]:.6g} N",
            )
    if n4:
        f1 = fits.friction_coefficient(torque[sel4], p0[sel4], bore, groups=gid4[sel4])
        f3 = fits.load_dependence(
            torque[sel4],
            p0[sel4],
            dm,
            c0,
            load_term_exponent=hb.load_term_exponent,
            groups=gid4[sel4],
        )
        mean_t = np.array([torque[m].mean() for m in members4])
    else:
        f1 = fits.FrictionCoefficientFit(*(np.zeros(0),) * 5)
        f3 = fits.LoadDependenceFit(*(np.zeros(0),) * 7)
        mean_t = np.zeros(0)
    # ---- T5 groups: (mass, tilt), ordered by mass then tilt
    t5 = r.series == "T5"
    gid5, members5 = _groups([r.tilt, r.mass], t5)
    n5 = len(members5)
    sel5 = np.flatnonzero(t5)
    mass5 = np.array([r.mass[m[0]] for m in members5]) if n5 else np.zeros(0)
    tilt5 = np.array([r.tilt[m[0]] for m in members5]) if n5 else np.zeros(0)
    for k, m in enumerate(members5):
        what = f"Table 5 column tilt {math.degrees(tilt5[k]):g} deg, Q = {mass5[k]:g} kg"
        if not np.ptp(speed[m]) > 0:
            field = "speed_reading" if read_speed[m].all() else "speed"
            raise _fail_group(
                s,
                m,
                what,
                field,
                f"task 2 needs at least two distinct speeds, got {m.size} row(s) "
                f"all at {speed[m][0] / _RPM:.6g} rpm",
            )
    if n5:
        f2 = fits.speed_dependence(torque[sel5], speed[sel5], dm, groups=gid5[sel5])
        p0_5 = np.array([p0[m].mean() for m in members5])
    else:
        f2 = fits.SpeedDependenceFit(*(np.zeros(0),) * 7)
        p0_5 = np.zeros(0)
    # ---- cross-checks (6.5); the load and speed terms are linear in f and f0
    c = hb.load_term_exponent
    unit_tf5 = (
        friction.load_term(p0_5, dm, c0, load_term_factor=1.0, load_term_exponent=c)
        if n5
        else np.zeros(0)
    )
    hb_tf = hb.load_term_factor * unit_tf5
    f3_at = np.full(n5, np.nan)
    for k in range(n5):
        same = np.isclose(tilt4, tilt5[k], rtol=0, atol=1e-12)
        if same.any():
            f3_at[k] = np.mean(f3.load_term_factor[same])
    tf_task3 = f3_at * unit_tf5
    mean_f0 = float(np.mean(f2.speed_term_factor)) if n5 else math.nan
    unit_t0 = friction.speed_term(col_speed, dm, 1.0) if n4 else np.zeros(0)
    t0_task2 = mean_f0 * unit_t0
    # fitted with groups=, every fit field is already a 1-d array (one value per group)
    task1 = Task1(
        tilt4,
        label4,
        col_speed,
        f1.friction_coefficient,
        f1.standard_error,
        f1.residual_rms,
        f1.count,
        mean_t,
        f1.friction_coefficient / hb.friction_coefficient - 1.0,
        f1.residual_rms / mean_t if n4 else np.zeros(0),
        tuple(members4),
    )
    task2 = Task2(
        mass5,
        tilt5,
        p0_5,
        f2.speed_term_factor,
        f2.speed_term_factor_standard_error,
        f2.load_term,
        f2.load_term_standard_error,
        f2.residual_rms,
        f2.count,
        hb_tf,
        tf_task3,
        tuple(members5),
    )
    task3 = Task3(
        tilt4,
        label4,
        col_speed,
        f3.load_term_factor,
        f3.load_term_factor_standard_error,
        f3.speed_term,
        f3.speed_term_standard_error,
        f3.residual_rms,
        f3.count,
        f3.load_term_factor / hb.load_term_factor - 1.0,
        t0_task2,
        tuple(members4),
    )
    return LabResult(s, rows, task1, task2, task3, _indicators(task1, task2, task3, c, mean_f0))


def _by_tilt(tilt):
    out = {}
    for k, t in enumerate(tilt):
        out.setdefault(float(t), []).append(k)
    return out


def _indicators(task1, task2, task3, c, mean_f0):
    i1 = []
    for tilt, ks in _by_tilt(task1.tilt).items():
        if len(ks) >= 2:
            lo = min(ks, key=lambda k: task1.shaft_speed[k])
            hi = max(ks, key=lambda k: task1.shaft_speed[k])
            if task1.shaft_speed[hi] > task1.shaft_speed[lo]:
                mu = task1.friction_coefficient
                i1.append(
                    (
                        tilt,
                        float(task1.shaft_speed[lo]),
                        float(task1.shaft_speed[hi]),
                        float(mu[hi] / mu[lo] - 1.0),
                    )
                )
    f0 = task2.speed_term_factor
    i4 = float((f0.max() - f0.min()) / f0.mean()) if f0.size >= 2 else math.nan
    i5 = []
    for k in range(1, task2.tilt.size):
        measured = float(task2.load_term[k] / task2.load_term[0])
        predicted = float((task2.equivalent_load[k] / task2.equivalent_load[0]) ** (1.0 + c))
        i5.append((0, k, measured, predicted))
    i6, i7 = [], []
    for tilt, ks in _by_tilt(task3.tilt).items():
        if len(ks) >= 2:
            f = task3.load_term_factor[ks]
            i6.append((tilt, float((f.max() - f.min()) / f.mean())))
            ks = sorted(ks, key=lambda k: task3.shaft_speed[k])
            a = ks[0]
            for b in ks[1:]:
                if task3.shaft_speed[b] > task3.shaft_speed[a]:
                    i7.append(
                        (
                            tilt,
                            float(task3.shaft_speed[a]),
                            float(task3.shaft_speed[b]),
                            float(task3.speed_term[b] / task3.speed_term[a]),
                            float((task3.shaft_speed[b] / task3.shaft_speed[a]) ** (2.0 / 3.0)),
                        )
                    )
    return Indicators(
        tuple(i1),
        task1.relative_to_handbook,
        task1.relative_rms,
        i4,
        mean_f0,
        tuple(i5),
        tuple(i6),
        task3.relative_to_handbook,
        tuple(i7),
    )


# ----------------------------------------------------------------------------- presentation
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


def _deg(x):
    return f"{math.degrees(x):g}"


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
                        _nan_none(s.rows.speed_reading[i]),
                        _sig(rv.shaft_speed[i] / _RPM),
                        _nan_none(s.rows.torque_reading[i]),
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
            row = [_nan_none(s.rows.speed_reading[any_i]), _sig(rv.shaft_speed[any_i] / _RPM)]
            for k in ks:
                i = by_col.get(k)
                row += (
                    [None] * 3
                    if i is None
                    else [
                        _nan_none(s.rows.torque_reading[i]),
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


def _nan_none(x):
    x = float(x)
    return None if math.isnan(x) else x


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
                _nan_none(s.rows.speed_reading[i]),
                _sig(rv.shaft_speed[i] / _RPM),
                _nan_none(s.rows.torque_reading[i]),
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
    s, rv = result.session, result.rows
    b, hb = s.bearing, s.handbook
    d_mm, dm_mm, c0, e = (
        b.bore / _MM,
        b.mean_diameter / _MM,
        b.static_load_rating,
        hb.load_term_exponent,
    )
    t_nmm = rv.torque / _MM
    out = []
    t1, t3, t2 = result.task1, result.task3, result.task2
    for tilt, ks in _by_tilt(t1.tilt).items():
        xmax = 1.1 * max(rv.equivalent_load[t1.rows[k]].max() for k in ks)
        series = []
        for k in ks:
            idx = t1.rows[k]
            lx = np.array([0.0, xmax])
            series.append(
                PlotSeries(
                    f"n = {t1.shaft_speed[k] / _RPM:.6g} rpm: μ = {t1.friction_coefficient[k]:.4e}",
                    rv.equivalent_load[idx],
                    t_nmm[idx],
                    lx,
                    t1.friction_coefficient[k] * lx * d_mm / 2,
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
    if t2.tilt.size:
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
        out.append(
            PlotData(
                "task2",
                "Task 2: T = f0·d_m³·N + T_F, N = n^(2/3)",
                "N = n^(2/3) [min^(-2/3)]",
                "T [N·mm]",
                series,
            )
        )
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


def _pct(x):
    v = x * 100
    return f"{0.0 if abs(v) < 0.05 else v:+.1f} %"


def _share(x, digits=1):
    return f"{x * 100:.{digits}f} %"


def _rpm(w):
    return f"{w / _RPM:.6g} rpm"


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
    s, ind = result.session, result.indicators
    hb = s.handbook
    t1, t2, t3 = result.task1, result.task2, result.task3
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
    if t1.tilt.size:
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
            f"I2, admissibility of the one-term formula: μ/μ_hb − 1 = {parts} (μ_hb = {hb.friction_coefficient:g}); "
            f"the handbook value is {verdict}."
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
        out.append(
            f"I3, adequacy of the one-term model: residual RMS / mean T = {parts}; {verdict}."
        )
    if t2.tilt.size == 0:
        out.append("No T5 rows: task 2 was not run.")
    else:
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
                f"extrapolation to n → 0 that the data do not support (spec 001 section 8.14)."
            )
    if t3.tilt.size:
        for tilt, i6 in ind.f_spread:
            ks = np.flatnonzero(np.isclose(t3.tilt, tilt, rtol=0, atol=1e-12))
            parts = ", ".join(
                f"{t3.load_term_factor[k]:.4e} at {_rpm(t3.shaft_speed[k])}" for k in ks
            )
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
                f"support (spec 001 section 8.14)."
            )
    return out


def _f(x):
    x = float(x)
    return None if math.isnan(x) else x


def _sig(x):
    """A converted input without round-trip noise: 1500.0000000000002 rpm -> 1500.0, 59.99999999999999 deg -> 60.0."""
    return float(f"{float(x):.12g}")


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
        ``task2``, ``task3``, ``mean_f0``, ``indicators``, ``tables``, ``plots`` and ``conclusions``.
    """
    s, rv, hb, b = result.session, result.rows, result.session.handbook, result.session.bearing
    t1, t2, t3, ind = result.task1, result.task2, result.task3, result.indicators
    rows = []
    for i in range(s.rows.line.size):
        rows.append(
            {
                "line": int(s.rows.line[i]),
                "series": s.rows.series[i],
                "tilt_deg": _sig(math.degrees(s.rows.tilt[i])),
                "mass_kg": float(s.rows.mass[i]),
                "column": s.rows.column[i] or None,
                "speed_reading": _f(s.rows.speed_reading[i]),
                "speed_rpm": _sig(rv.shaft_speed[i] / _RPM),
                "torque_reading": _f(s.rows.torque_reading[i]),
                "switch": int(s.rows.switch[i]) or None,
                "torque_Nmm": _sig(rv.torque[i] / _MM),
                "axial_load_N": float(rv.axial_load[i]),
                "radial_load_N": float(rv.radial_load[i]),
                "equivalent_static_load_N": float(rv.equivalent_load[i]),
                "branch": "x0*Fr+y0*Fa" if rv.combined[i] else "Fr",
                "note": s.rows.note[i] or None,
            }
        )
    task1 = [
        {
            "tilt_deg": _sig(math.degrees(t1.tilt[k])),
            "column": t1.column[k],
            "speed_rpm": _sig(t1.shaft_speed[k] / _RPM),
            "mu": float(t1.friction_coefficient[k]),
            "mu_standard_error": _f(t1.standard_error[k]),
            "residual_rms_Nmm": float(t1.residual_rms[k] / _MM),
            "n_points": int(t1.count[k]),
            "mean_torque_Nmm": float(t1.mean_torque[k] / _MM),
            "mu_handbook": hb.friction_coefficient,
            "mu_relative_to_handbook": float(t1.relative_to_handbook[k]),
            "residual_rms_relative_to_mean_torque": float(t1.relative_rms[k]),
            "lines": [int(x) for x in s.rows.line[t1.rows[k]]],
        }
        for k in range(t1.tilt.size)
    ]
    task2 = [
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
            "lines": [int(x) for x in s.rows.line[t2.rows[k]]],
        }
        for k in range(t2.tilt.size)
    ]
    task3 = [
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
            "lines": [int(x) for x in s.rows.line[t3.rows[k]]],
        }
        for k in range(t3.tilt.size)
    ]
    indicators = {
        "I1": [
            {
                "tilt_deg": _sig(math.degrees(t)),
                "speed_min_rpm": _sig(lo / _RPM),
                "speed_max_rpm": _sig(hi / _RPM),
                "value": v,
            }
            for t, lo, hi, v in ind.speed_effect_on_mu
        ],
        "I2": [
            {
                "tilt_deg": r["tilt_deg"],
                "speed_rpm": r["speed_rpm"],
                "value": r["mu_relative_to_handbook"],
            }
            for r in task1
        ],
        "I3": [
            {
                "tilt_deg": r["tilt_deg"],
                "speed_rpm": r["speed_rpm"],
                "value": r["residual_rms_relative_to_mean_torque"],
            }
            for r in task1
        ],
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
        "I6_f_relative_to_handbook": [
            {
                "tilt_deg": r["tilt_deg"],
                "speed_rpm": r["speed_rpm"],
                "value": r["f_relative_to_handbook"],
            }
            for r in task3
        ],
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
        "I7_torque_speed_term_vs_task2": [
            {
                "tilt_deg": r["tilt_deg"],
                "speed_rpm": r["speed_rpm"],
                "task3_Nmm": r["torque_speed_term_Nmm"],
                "from_task2_f0_Nmm": r["torque_speed_term_with_task2_f0_Nmm"],
            }
            for r in task3
        ],
    }
    tables = [rows_table(result)] + table4(result) + table5(result)
    return {
        "format": RESULTS_FORMAT,
        "source": s.source,
        "rows_source": s.rows_source,
        "session": dict(s.info),
        "bearing": {
            "designation": b.designation,
            "type": b.type,
            "contact_angle_deg": None if b.contact_angle is None else math.degrees(b.contact_angle),
            "bore_mm": b.bore / _MM,
            "outside_diameter_mm": b.outside_diameter / _MM,
            "mean_diameter_mm": b.mean_diameter / _MM,
            "static_load_rating_N": b.static_load_rating,
            "source": b.source or None,
        },
        "handbook": {
            "x0": hb.radial_factor,
            "y0": hb.axial_factor,
            "mu": hb.friction_coefficient,
            "f": hb.load_term_factor,
            "c": hb.load_term_exponent,
            "overridden": list(hb.overridden),
        },
        "rig": {
            "tare_mass_kg": s.tare_mass,
            "gravity_m_per_s2": s.gravity,
            "branch_switch_tilt_deg": math.degrees(
                branch_switch_tilt(hb.radial_factor, hb.axial_factor)
            )
            if hb.radial_factor < 1
            else None,
        },
        "rows": rows,
        "task1": task1,
        "task2": task2,
        "task3": task3,
        "mean_f0": _f(ind.mean_speed_term_factor),
        "indicators": indicators,
        "tables": [
            {"name": t.name, "title": t.title, "columns": t.columns, "rows": t.rows} for t in tables
        ],
        "plots": [
            {
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
            for p in plots(result)
        ],
        "conclusions": conclusions(result),
    }
