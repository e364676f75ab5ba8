r"""One measurement session -> every number the friction lab reports (spec 001 sections 6 and 7.5).

Analysis
--------
analyse          Session -> LabResult: per-row speed, torque, loads and P0; the three tasks; the
                 cross-checks of section 6.5; the indicators I1-I7 of section 7.5
LabResult        the results (SI), with the session they came from
RowValues        the converted values of every row
Task1, Task2, Task3, Task4, Indicators
                 the fits of each task with their cross-checks (task 4: the SKF four-term model,
                 sessions with an [skf] table), and I1-I7

Grouping. T4 rows are grouped by (tilt, speed-column label): one task-1 and one task-3 fit per
group, at the column speed = the mean n of its rows (section 6.1). T5 rows are grouped by (mass,
tilt): one task-2 fit per group. Task 4 (the SKF model, when the session has an [skf] table) fits
all rows, T4 and T5, grouped by tilt. All groups of a task are fitted at once (:mod:`bearinglab.lab.fits`).

Every number here can be had from :mod:`bearinglab.friction`, :mod:`.rig`, :mod:`.calibration` and
:mod:`bearinglab.lab.fits` directly; this module only composes them. The tables, plot data, conclusions and the
results dict (engineering units) are made by :mod:`bearinglab.lab.presentation`; its names
(``table4``, ``table5``, ``rows_table``, ``plots``, ``conclusions``, ``to_dict``, ``TableData``,
``PlotData``, ``PlotSeries``, ``RESULTS_FORMAT``, ``WORDING_THRESHOLD``) stay reachable here too.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from .. import friction
from ..errors import InputError
from . import fits
from ._compat import renamed_field
from ._rows import _by_tilt
from .calibration import convert, convert_torque
from .rig import rig_equivalent_load

__all__ = [
    "Indicators",
    "LabResult",
    "RowValues",
    "Task1",
    "Task2",
    "Task3",
    "Task4",
    "analyse",
]

_RPM = 2.0 * math.pi / 60.0  # rad/s per rpm


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
    reduced_friction_coefficient: np.ndarray
    """mu of (6.1), referred to the bore. [-]"""
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

    friction_coefficient = renamed_field(
        "Task1", "friction_coefficient", "reduced_friction_coefficient"
    )


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


class Task4(NamedTuple):
    """Task 4 per tilt: the SKF four-term model fitted to all rows (mu_sl and/or a scale on M_rr)."""

    tilt: np.ndarray
    """[rad]"""
    fit: str
    """What was fitted: ``"sliding"``, ``"rolling"`` or ``"both"``."""
    sliding_friction_coefficient: np.ndarray
    """mu_sl fitted (NaN with fit = "rolling"). [-]"""
    sliding_friction_coefficient_standard_error: np.ndarray
    """[-]"""
    rolling_scale: np.ndarray
    """k on the model's rolling moment (1 with fit = "sliding"). [-]"""
    rolling_scale_standard_error: np.ndarray
    """[-]"""
    model_sliding_friction_coefficient: np.ndarray
    """Mean over the group of the model's own mu_sl. [-]"""
    residual_rms: np.ndarray
    """[N*m]"""
    count: np.ndarray
    """Number of rows. [-]"""
    mean_torque: np.ndarray
    """Mean measured T of the group. [N*m]"""
    model_residual_rms: np.ndarray
    """RMS of measured minus the unfitted model's torque (mu_sl of the model, k = 1). [N*m]"""
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
    task4: Task4 | None = None
    """Task 4 (None without an [skf] table in the session)."""


# ----------------------------------------------------------------------------- analysis
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
    >>> t1, t3 = result.task1, result.task3
    >>> print(f"{t1.reduced_friction_coefficient[0]:.6e} {t3.load_term_factor[0]:.6e}")
    1.470209e-03 1.500000e-03
    """
    rows = _row_values(session)
    g4 = _table4_groups(session, rows)
    g5 = _table5_groups(session, rows)
    f1, f3 = _fit_table4(session, rows, g4)
    f2 = _fit_table5(session, rows, g5)
    mean_f0 = float(np.mean(f2.speed_term_factor)) if g5.members else math.nan
    task1 = _task1(session, rows, g4, f1)
    task2 = _task2(session, rows, g5, f2, g4.tilt, f3.load_term_factor)
    task3 = _task3(session, g4, f3, mean_f0)
    c = session.handbook.load_term_exponent
    task4 = _task4(session, rows) if session.skf is not None else None
    return LabResult(
        session, rows, task1, task2, task3, _indicators(task1, task2, task3, c, mean_f0), task4
    )


class _Groups(NamedTuple):
    """Groups of rows fitted together, in the order of the task's results."""

    members: list  # row indices of each group
    tilt: np.ndarray  # [rad]
    key: np.ndarray  # T4: speed-column label; T5: mass Q [kg]
    speed: np.ndarray  # T4: column speed, the mean n of its rows [rad/s]; T5: unused

    def ids(self, size):
        """Group number of every row, -1 for rows in no group."""
        gid = np.full(size, -1)
        for k, m in enumerate(self.members):
            gid[m] = k
        return gid


def _groups(keys, mask):
    """Group ids 0..G-1 of the masked rows, ordered by the keys (first key first); -1 elsewhere."""
    idx = np.flatnonzero(mask)
    gid = np.full(mask.size, -1)
    if idx.size == 0:
        return gid, []
    inverse = []
    for key in keys:
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


def _row_values(session):
    """Speed and torque of every row (read through the calibration or given), loads and P0 (6.1)."""
    s, r, b, hb = session, session.rows, session.bearing, session.handbook
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
    return RowValues(speed, torque, *(np.atleast_1d(np.asarray(v)) for v in loads))


def _table4_groups(session, rows):
    """T4 rows by (tilt, column), ordered by tilt then column speed; checks tasks 1 and 3 can run."""
    r, speed, p0 = session.rows, rows.shaft_speed, rows.equivalent_load
    _gid, members = _groups([r.column.astype(str), r.tilt], r.series == "T4")
    col_speed = np.array([speed[m].mean() for m in members]) if members else np.zeros(0)
    tilt = np.array([r.tilt[m[0]] for m in members]) if members else np.zeros(0)
    order = np.lexsort((col_speed, tilt))
    members = [members[k] for k in order]
    col_speed, tilt = col_speed[order], tilt[order]
    label = np.array([r.column[m[0]] for m in members], dtype=object)
    for k, m in enumerate(members):
        what = f"Table 4 column {label[k]!r} at tilt {math.degrees(tilt[k]):g} deg"
        if not np.any(p0[m] > 0):
            raise _fail_group(
                session,
                m,
                what,
                "mass",
                "task 1: all P0 are zero; a line through the origin needs a load",
            )
        if not np.ptp(p0[m]) > 0:
            raise _fail_group(
                session,
                m,
                what,
                "mass",
                f"task 3 needs at least two distinct loads P0, got {m.size} "
                f"row(s) all at P0 = {p0[m][0]:.6g} N",
            )
    return _Groups(members, tilt, label, col_speed)


def _table5_groups(session, rows):
    """T5 rows by (tilt, mass), ordered by tilt then mass; checks task 2 can run."""
    r, speed = session.rows, rows.shaft_speed
    _gid, members = _groups([r.tilt, r.mass], r.series == "T5")
    mass = np.array([r.mass[m[0]] for m in members]) if members else np.zeros(0)
    tilt = np.array([r.tilt[m[0]] for m in members]) if members else np.zeros(0)
    read_speed = np.isnan(r.speed)
    for k, m in enumerate(members):
        what = f"Table 5 column tilt {math.degrees(tilt[k]):g} deg, Q = {mass[k]:g} kg"
        if not np.ptp(speed[m]) > 0:
            field = "speed_reading" if read_speed[m].all() else "speed"
            raise _fail_group(
                session,
                m,
                what,
                field,
                f"task 2 needs at least two distinct speeds, got {m.size} row(s) "
                f"all at {speed[m][0] / _RPM:.6g} rpm",
            )
    return _Groups(members, tilt, mass, np.zeros(0))


def _fit_table4(session, rows, groups):
    """Tasks 1 and 3 of every T4 group (empty fits without T4 rows)."""
    if not groups.members:
        return (
            fits.ReducedFrictionCoefficientFit(*(np.zeros(0),) * 5),
            fits.LoadDependenceFit(*(np.zeros(0),) * 7),
        )
    b, hb = session.bearing, session.handbook
    gid = groups.ids(rows.torque.size)
    sel = np.flatnonzero(session.rows.series == "T4")
    torque, p0, gid = rows.torque[sel], rows.equivalent_load[sel], gid[sel]
    f1 = fits.reduced_friction_coefficient(torque, p0, b.bore, groups=gid)
    f3 = fits.load_dependence(
        torque,
        p0,
        b.mean_diameter,
        b.static_load_rating,
        load_term_exponent=hb.load_term_exponent,
        groups=gid,
    )
    return f1, f3


def _fit_table5(session, rows, groups):
    """Task 2 of every T5 group (an empty fit without T5 rows)."""
    if not groups.members:
        return fits.SpeedDependenceFit(*(np.zeros(0),) * 7)
    gid = groups.ids(rows.torque.size)
    sel = np.flatnonzero(session.rows.series == "T5")
    return fits.speed_dependence(
        rows.torque[sel], rows.shaft_speed[sel], session.bearing.mean_diameter, groups=gid[sel]
    )


# fitted with groups=, every fit field is already a 1-d array (one value per group)
def _task1(session, rows, groups, f1):
    mean_t = (
        np.array([rows.torque[m].mean() for m in groups.members]) if groups.members else np.zeros(0)
    )
    return Task1(
        groups.tilt,
        groups.key,
        groups.speed,
        f1.reduced_friction_coefficient,
        f1.standard_error,
        f1.residual_rms,
        f1.count,
        mean_t,
        f1.reduced_friction_coefficient / session.handbook.reduced_friction_coefficient - 1.0,
        f1.residual_rms / mean_t if groups.members else np.zeros(0),
        tuple(groups.members),
    )


def _task2(session, rows, groups, f2, task3_tilt, task3_factor):
    """Task 2 with T_F of the handbook and with the mean f of task 3 at the same tilt (6.5)."""
    b, hb, n = session.bearing, session.handbook, len(groups.members)
    p0 = np.array([rows.equivalent_load[m].mean() for m in groups.members]) if n else np.zeros(0)
    unit_tf = (  # the load term is linear in f
        friction.load_term(
            p0,
            b.mean_diameter,
            b.static_load_rating,
            load_term_factor=1.0,
            load_term_exponent=hb.load_term_exponent,
        )
        if n
        else np.zeros(0)
    )
    f3_at = np.full(n, np.nan)
    for k in range(n):
        same = np.isclose(task3_tilt, groups.tilt[k], rtol=0, atol=1e-12)
        if same.any():
            f3_at[k] = np.mean(task3_factor[same])
    return Task2(
        groups.key,
        groups.tilt,
        p0,
        f2.speed_term_factor,
        f2.speed_term_factor_standard_error,
        f2.load_term,
        f2.load_term_standard_error,
        f2.residual_rms,
        f2.count,
        hb.load_term_factor * unit_tf,
        f3_at * unit_tf,
        tuple(groups.members),
    )


def _task3(session, groups, f3, mean_f0):
    """Task 3 with T0 from the mean f0 of task 2 (6.5)."""
    unit_t0 = (  # the speed term is linear in f0
        friction.speed_term(groups.speed, session.bearing.mean_diameter, 1.0)
        if groups.members
        else np.zeros(0)
    )
    return Task3(
        groups.tilt,
        groups.key,
        groups.speed,
        f3.load_term_factor,
        f3.load_term_factor_standard_error,
        f3.speed_term,
        f3.speed_term_standard_error,
        f3.residual_rms,
        f3.count,
        f3.load_term_factor / session.handbook.load_term_factor - 1.0,
        mean_f0 * unit_t0,
        tuple(groups.members),
    )


def _task4(session, rows):
    """Task 4: the SKF model fitted to every row, one group per tilt (fits.skf_friction)."""
    b, settings, r = session.bearing, session.skf, session.rows
    gid, members = _groups([r.tilt], np.ones(r.tilt.size, dtype=bool))
    loads = (rows.radial_load, rows.axial_load, rows.shaft_speed, settings.kinematic_viscosity,
             b.bore, b.outside_diameter)
    options = settings.model_options(b)
    try:
        f4 = fits.skf_friction(rows.torque, *loads, fit=settings.fit, groups=gid, **options)
    except InputError as exc:
        where = _where_rows(session, members[exc.group]) if hasattr(exc, "group") else session.source
        raise InputError(f"{where} (task 4, the SKF model): {exc}") from None
    m = np.bincount(gid, minlength=len(members))
    return Task4(
        np.array([r.tilt[k[0]] for k in members]),
        settings.fit,
        f4.sliding_friction_coefficient,
        f4.sliding_friction_coefficient_standard_error,
        f4.rolling_scale,
        f4.rolling_scale_standard_error,
        f4.model_sliding_friction_coefficient,
        f4.residual_rms,
        f4.count,
        np.bincount(gid, weights=rows.torque, minlength=len(members)) / m,
        np.sqrt(np.bincount(gid, weights=f4.model_residuals**2, minlength=len(members)) / m),
        tuple(members),
    )


def _indicators(task1, task2, task3, c, mean_f0):
    i1 = []
    for tilt, ks in _by_tilt(task1.tilt).items():
        if len(ks) >= 2:
            lo = min(ks, key=lambda k: task1.shaft_speed[k])
            hi = max(ks, key=lambda k: task1.shaft_speed[k])
            if task1.shaft_speed[hi] > task1.shaft_speed[lo]:
                mu = task1.reduced_friction_coefficient
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


# ----------------------------------------------------------------------------- moved names
def __getattr__(name):
    # The names of .presentation lived here before issue 10 and stay reachable (the same objects, no
    # warning). Imported on first use: .presentation imports this module.
    from . import presentation

    if name in presentation.__all__:
        return getattr(presentation, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__():
    from . import presentation

    return sorted(set(globals()) | set(presentation.__all__))
