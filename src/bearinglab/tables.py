"""Results as columns in engineering units: one convention for the command line, the reports and the web page.

The library computes in SI (STYLE.md section 3); engineers read mm, µm, N, kN, deg and rpm. Every table
a user sees is built here, from column specifications: the column name (which carries the unit, as in
``contact_angle_inner_deg``), the field of the result it comes from, the unit label, and the conversion
from SI. The same result gives the same columns wherever it is shown.

Column specifications
---------------------
Column          one column: name, field of the result, unit label, conversion factor and divisor
HIGH_SPEED      the columns of a :class:`bearinglab.quasistatic.HighSpeedState`
AXIAL_ANGLE     the per-case columns of :func:`bearinglab.stand.stand_analysis`
RUNOUT_GEOMETRY the fields of a runout geometry (:func:`bearinglab.runout.geometry_from_bearing`)
BALLS           the per-ball columns of a combined-load distribution
RATINGS, RATING_LIFE   the ratings and the lives of :func:`bearinglab.life.rating_life`
SKF_TORQUE      the moments of :func:`bearinglab.friction.skf`
KIND_UNITS      quantity kind -> (column suffix, factor from SI), for inputs given by kind
UNIT_SUFFIXES   a key's unit suffix -> the unit as it is shown (``_um`` -> ``µm``)

Results -> columns
------------------
columns         a result NamedTuple -> ordered dict of 1-D columns, by specifications
record          one case of a result -> ordered dict of Python scalars, by specifications
rows            columns -> list of per-case dicts (JSON-ready scalars)
high_speed      a high-speed state -> its columns (kN, rpm, deg, mm, µm, N, N·mm, Hz, MPa, N/µm)
input_columns   sweep inputs (SI, by kind) -> columns with the unit in the name
stand_load      speeds and a minimum-load result -> columns (rpm, N, kgf)
frequencies     characteristic frequencies -> ``{name}_hz`` and ``{name}_order`` values
spectral_mask   the lines of a spectral mask -> columns (Hz and orders)
bearing_summary every known field of a bearing and its derived quantities
roller_summary  the same of a roller bearing (bearing_summary gives it for a RollerBearing)
catalog_entry   the catalog-list row of a bearing
runout_metrics  runout metrics -> ``{metric}_um`` values
load_distribution   one case of a combined-load distribution -> displacements, stiffness, per-ball rows
ball_columns    the per-ball columns of one case (deg, N, MPa)
rating_life     a rating-life analysis -> its columns (N, Mrev, h, factors)
ratings         a bearing's C, C0, Cu (N) and where each comes from
skf_torque      the SKF model's moments -> N·mm, W and mu_sl
significant     input values without the last-bit noise of a unit round trip
quantity        a document's key -> its label and unit (``contact_angle_inner_deg``: contact angle inner, °)

Writers
-------
write_table     columns -> .csv or .parquet, whole or not at all
json_value      values -> JSON-ready values (NaN and inf -> None, numpy -> Python)
json_text       one JSON document, as the command line prints it
csv_text        CSV text with ``#`` comment lines (cells as :func:`write_table` writes them)
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from ._io import csv_text, json_text, json_value, write_columns
from .units import KGF, RPM

__all__ = [
    "AXIAL_ANGLE",
    "BALLS",
    "HIGH_SPEED",
    "KIND_UNITS",
    "RATINGS",
    "RATING_LIFE",
    "RUNOUT_GEOMETRY",
    "SKF_TORQUE",
    "UNIT_SUFFIXES",
    "Column",
    "ball_columns",
    "bearing_summary",
    "catalog_entry",
    "columns",
    "csv_text",
    "film",
    "frequencies",
    "high_speed",
    "input_columns",
    "json_text",
    "json_value",
    "load_distribution",
    "quantity",
    "rating_life",
    "ratings",
    "record",
    "roller_summary",
    "rows",
    "runout_metrics",
    "significant",
    "skf_torque",
    "spectral_mask",
    "stand_load",
    "write_table",
]

_DEG = 180.0 / math.pi  # deg per rad
_HZ = 1.0 / (2.0 * math.pi)  # Hz per rad/s


class Column(NamedTuple):
    """One column of a table: ``value [unit] = SI value * factor / divisor``.

    Factor and divisor are kept apart so that each conversion is the same floating-point operation
    as everywhere else in the package (a multiplication by 1e3 for mm, a division by the kilogram-force
    for kgf), and a printed number does not change in its last digit between two outputs.

    Parameters
    ----------
    name : str
        Column name; it ends in the unit (``axial_load_kN``), unless dimensionless or not a number.
    field : str
        Attribute of the result the column is taken from.
    unit : str
        Unit label for headers (``"kN"``; ``"-"`` dimensionless; ``""`` not a number).
    factor : float or None, optional
        Multiplier from SI; ``None`` passes the values unchanged (flags, counts, text).
    divisor : float, optional
        Divisor from SI, applied after ``factor``.
    """

    name: str
    field: str
    unit: str
    factor: float | None = 1.0
    divisor: float = 1.0

    def convert(self, value):
        """``value`` (SI) in the column's unit; unchanged if the column has no factor."""
        if self.factor is None:
            return value
        return np.asarray(value, dtype=float) * self.factor / self.divisor


#: Columns of a :class:`bearinglab.quasistatic.HighSpeedState` (spec 004), in the order printed.
HIGH_SPEED = (
    Column("axial_load_N", "axial_load", "N"),
    Column("speed_rpm", "shaft_speed", "rpm", 1.0 / RPM),
    Column("contact_angle_inner_deg", "contact_angle_inner", "deg", _DEG),
    Column("contact_angle_outer_deg", "contact_angle_outer", "deg", _DEG),
    Column("static_contact_angle_deg", "static_contact_angle", "deg", _DEG),
    Column("axial_displacement_um", "axial_displacement", "µm", 1e6),
    Column("ball_load_inner_N", "ball_load_inner", "N"),
    Column("ball_load_outer_N", "ball_load_outer", "N"),
    Column("deflection_inner_um", "deflection_inner", "µm", 1e6),
    Column("deflection_outer_um", "deflection_outer", "µm", 1e6),
    Column("centrifugal_force_N", "centrifugal_force", "N"),
    Column("gyroscopic_moment_Nmm", "gyroscopic_moment", "N·mm", 1e3),
    Column("attitude_angle_deg", "attitude_angle", "deg", _DEG),
    Column("cage_speed_rpm", "cage_speed", "rpm", 1.0 / RPM),
    Column("ball_spin_speed_rpm", "ball_spin_speed", "rpm", 1.0 / RPM),
    Column("bpfo_hz", "bpfo", "Hz", _HZ),
    Column("bpfi_hz", "bpfi", "Hz", _HZ),
    Column("max_pressure_inner_MPa", "max_pressure_inner", "MPa", 1e-6),
    Column("max_pressure_outer_MPa", "max_pressure_outer", "MPa", 1e-6),
    Column("axial_stiffness_N_per_um", "axial_stiffness", "N/µm", 1e-6),
    Column("friction_coefficient", "friction_coefficient", "-"),
    Column("converged", "converged", "", None),
    Column("residual", "residual", "-"),
    Column("iterations", "iterations", "", None),
    Column("status", "status", "", None),
    Column("method", "method", "", None),
)

#: Per-case columns of :func:`bearinglab.stand.stand_analysis` over several loads (spec 000).
AXIAL_ANGLE = (
    Column("axial_load_N", "axial_load", "N"),
    Column("axial_load_kgf", "axial_load", "kgf", 1.0, KGF),
    Column("operating_contact_angle_deg", "contact_angle", "deg", _DEG),
    Column("axial_displacement_ratio", "axial_displacement_ratio", "-"),
    Column("axial_displacement_um", "axial_displacement", "µm", 1e6),
    Column("ball_load_N", "ball_load", "N"),
)

#: Fields of a runout geometry (spec 003), as printed with a runout result.
RUNOUT_GEOMETRY = (
    Column("balls", "n_balls", "", None),
    Column("ball_diameter_mm", "ball_radius", "mm", 2e3),
    Column("pitch_diameter_mm", "ball_centre_radius", "mm", 2e3),
    Column("outer_groove_radius_mm", "outer_groove_radius", "mm", 1e3),
    Column("inner_groove_radius_mm", "inner_groove_radius", "mm", 1e3),
    Column("outer_bottom_radius_mm", "outer_bottom_radius", "mm", 1e3),
    Column("inner_bottom_radius_mm", "inner_bottom_radius", "mm", 1e3),
    Column("contact_angle_deg", "contact_angle", "deg", _DEG),
    Column("first_ball_angle_deg", "first_ball_angle", "deg", _DEG),
    Column("groove_distance_mm", "groove_distance", "mm", 1e3),
    Column("axial_offset_mm", "axial_offset", "mm", 1e3),
    Column("inner_centre_radius_mm", "inner_centre_radius", "mm", 1e3),
    Column("gamma", "pitch_ratio", "-"),
    Column("cage_ratio", "cage_ratio", "-"),
)

#: Quantity kind -> (column-name suffix, factor from SI), for inputs known by their kind (sweep files).
KIND_UNITS = {
    "force": ("_N", 1.0),
    "angle": ("_deg", _DEG),
    "speed": ("_rpm", 30.0 / math.pi),
    "length": ("_mm", 1e3),
    "dimensionless": ("", 1.0),
    "mass": ("_kg", 1.0),
}


def columns(result, specs):
    """The columns ``specs`` of ``result``, each flattened to 1-D and converted from SI.

    Parameters
    ----------
    result : NamedTuple
        A result of the library (any object with the fields the specifications name).
    specs : sequence of Column
        The columns wanted, in order.

    Returns
    -------
    dict
        Column name -> 1-D ndarray (floats in the column's unit; unconverted columns as they are).

    Examples
    --------
    >>> from collections import namedtuple
    >>> r = namedtuple("R", "axial_load")(2500.0)
    >>> columns(r, [Column("axial_load_kN", "axial_load", "kN", 1e-3)])["axial_load_kN"].tolist()
    [2.5]
    """
    out = {}
    for spec in specs:
        value = np.ravel(np.asarray(getattr(result, spec.field)))
        out[spec.name] = spec.convert(value) if spec.factor is not None else value
    return out


def record(result, specs):
    """One case of ``result`` as Python scalars in engineering units, by specifications.

    Parameters
    ----------
    result : NamedTuple
        A result whose fields are scalars.
    specs : sequence of Column
        The fields wanted, in order.

    Returns
    -------
    dict
        Column name -> Python float (or the value unchanged for columns without a factor).
    """
    out = {}
    for spec in specs:
        value = getattr(result, spec.field)
        out[spec.name] = value if spec.factor is None else float(value) * spec.factor / spec.divisor
    return out


def rows(table):
    """Columns -> one dict per case, with JSON-ready scalars (NaN and inf as ``None``).

    Parameters
    ----------
    table : dict
        Column name -> 1-D array, all of one length.

    Returns
    -------
    list of dict
    """
    names = list(table)
    if not names:
        return []
    n = len(table[names[0]])
    # converted as a whole, so that a null is known by its key (bearinglab._io.NULLED)
    return json_value([{k: np.asarray(table[k])[i] for k in names} for i in range(n)])


#: A document's key ends with its unit (``contact_angle_inner_deg``, ``film_min_um``): suffix -> the
#: unit as it is shown, the longer suffix of two first (``_N_per_um`` before ``_um``, ``_Nmm`` before ``_N``).
UNIT_SUFFIXES = (
    ("_cm2_per_kgf_2_3", "cm²/kgf^⅔"),
    ("_per_GPa", "1/GPa"),
    ("_mm2_s", "mm²/s"),
    ("_m_s", "m/s"),
    ("_mPas", "mPa·s"),
    ("_kg_m3", "kg/m³"),
    ("_degC", "°C"),
    ("_N_per_um", "N/µm"),
    ("_per_mm", "1/mm"),
    ("_Nmm", "N·mm"),
    ("_Nm", "N·m"),
    ("_kN", "kN"),
    ("_N", "N"),
    ("_deg", "°"),
    ("_dms", ""),  # the value is a text that carries its own degrees, minutes and seconds
    ("_mrad", "mrad"),
    ("_rad", "rad"),
    ("_rpm", "rpm"),
    ("_hz", "Hz"),
    ("_mm", "mm"),
    ("_um", "µm"),
    ("_MPa", "MPa"),
    ("_GPa", "GPa"),
    ("_Mrev", "10⁶ rev"),
    ("_h", "h"),
    ("_s", "s"),
    ("_W", "W"),
    ("_kgf", "kgf"),
    ("_cSt", "cSt"),
    ("_percent", "%"),
    ("_order", "× shaft"),
)


def quantity(key):
    """A document's key -> (label, unit), by its unit suffix (:data:`UNIT_SUFFIXES`).

    Parameters
    ----------
    key : str
        A key of a calculation's JSON document.

    Returns
    -------
    tuple of str
        The key without its suffix, in words, and the unit ('' where the key has none).

    Examples
    --------
    >>> quantity("contact_angle_inner_deg")
    ('contact angle inner', '°')
    >>> quantity("basic_rating_life_h")
    ('basic rating life', 'h')
    >>> quantity("regime")
    ('regime', '')
    """
    for suffix, unit in UNIT_SUFFIXES:
        if key.endswith(suffix) and len(key) > len(suffix):
            return key[: -len(suffix)].replace("_", " "), unit
    return key.replace("_", " "), ""


def significant(values, digits=12):
    """Values rounded to ``digits`` significant digits: an input without the last-bit noise of a
    unit round trip (3000 rpm -> rad/s -> 3000.0000000000005 rpm -> 3000.0).

    Parameters
    ----------
    values : array_like
        Values, any unit.
    digits : int, optional
        Significant digits kept. [-]

    Returns
    -------
    ndarray
        1-D array of floats.

    Examples
    --------
    >>> significant([3000.0000000000005]).tolist()
    [3000.0]
    """
    return np.array([float(f"{x:.{digits}g}") for x in np.ravel(np.asarray(values, dtype=float))])


def high_speed(state):
    """A high-speed state as flat columns in engineering units (kN, rpm, deg, mm, µm, N, N·mm, Hz, MPa, N/µm).

    Parameters
    ----------
    state : HighSpeedState
        A result of :func:`bearinglab.quasistatic.contact_angles`,
        :func:`~bearinglab.quasistatic.high_speed_analysis` or :func:`~bearinglab.quasistatic.sweep`.

    Returns
    -------
    dict
        Column name -> 1-D ndarray, the names and order of :data:`HIGH_SPEED` (``contact_angle_inner_deg``,
        ``axial_displacement_um``, ``gyroscopic_moment_Nmm``, ...). The inputs (thrust and speed) are
        rounded to 12 significant digits.
    """
    cols = columns(state, HIGH_SPEED)
    for name in ("axial_load_N", "speed_rpm"):  # inputs: drop the last-bit noise of the unit round trip
        cols[name] = significant(cols[name])
    return cols


def input_columns(cases, kinds):
    """Input values (SI) as columns in the units engineers read, the unit in the column name.

    Parameters
    ----------
    cases : dict
        Parameter name -> 1-D array of SI values.
    kinds : dict
        Parameter name -> quantity kind (a key of :data:`KIND_UNITS`).

    Returns
    -------
    dict
        ``name + suffix`` -> converted array (``axial_load_N``, ``contact_angle_deg``, ``speed_rpm``),
        rounded to 12 significant digits where a unit was converted.
    """
    out = {}
    for k, v in cases.items():
        suffix, scale = KIND_UNITS[kinds[k]]
        # an input read in the user's unit, taken to SI and back, drops the last-bit noise of the round trip
        # (3000 rpm is written 3000, not 3000.0000000000005); 12 digits are more than any input carries
        out[f"{k}{suffix}"] = significant(v * scale).reshape(np.shape(v)) if scale != 1 else v
    return out


def stand_load(shaft_speed, result):
    """The minimum and maximum axial load on a test stand, per speed (spec 000 section 3).

    Parameters
    ----------
    shaft_speed : array_like
        Inner-ring speeds. [rad/s]
    result : StandLoad
        A result of :func:`bearinglab.stand.min_axial_load` at those speeds.

    Returns
    -------
    dict
        ``speed_rpm``, ``min_axial_load_kgf``, ``min_axial_load_N``, ``max_axial_load_kgf``,
        ``max_axial_load_N``: 1-D arrays.
    """
    lo, hi = np.atleast_1d(result.minimum), np.atleast_1d(result.maximum)
    return {"speed_rpm": significant(np.ravel(shaft_speed) / RPM), "min_axial_load_kgf": lo / KGF, "min_axial_load_N": lo,
            "max_axial_load_kgf": hi / KGF, "max_axial_load_N": hi}


def _order(hz, shaft_hz):
    """Multiple of the shaft frequency; NaN (shown empty, or null in JSON) when the shaft stands still."""
    return hz / abs(shaft_hz) if shaft_hz else math.nan


def frequencies(freqs, shaft_speed, names=("ftf", "bpfo", "bpfi", "bsf", "two_bsf")):
    """Characteristic frequencies in Hz and as orders (multiples of the shaft frequency).

    Parameters
    ----------
    freqs : CharacteristicFrequencies
        A result of :mod:`bearinglab.kinematics` for one speed. [rad/s]
    shaft_speed : float
        Inner-ring (shaft) speed the orders refer to. [rad/s]
    names : sequence of str, optional
        The families wanted, in order (default: every defect family of ``kinematics.FAMILIES``).

    Returns
    -------
    dict
        ``{name}_hz`` and ``{name}_order`` -> float, per family (``None`` for the orders at zero
        shaft speed).
    """
    shaft_hz = shaft_speed / (2.0 * math.pi)
    out = {}
    for name in names:
        hz = float(getattr(freqs, name)) / (2.0 * math.pi)
        out[f"{name}_hz"] = hz
        out[f"{name}_order"] = hz / abs(shaft_hz) if shaft_hz else None
    return out


def spectral_mask(mask, shaft_speed):
    """The lines of a spectral mask as columns, the frequencies in Hz and as orders.

    Parameters
    ----------
    mask : SpectralMask
        A result of :func:`bearinglab.kinematics.spectral_mask` for one speed.
    shaft_speed : float
        Inner-ring (shaft) speed the orders refer to. [rad/s]

    Returns
    -------
    dict
        ``name``, ``harmonic``, ``modulation``, ``sideband``, ``frequency_hz``, ``low_hz``, ``high_hz``
        and ``order`` (NaN at zero shaft speed): 1-D arrays, one entry per line.
    """
    hz = 2.0 * math.pi  # rad/s per Hz
    cols = {"name": np.asarray(mask.name).astype(str), "harmonic": np.asarray(mask.harmonic).astype(int),
            "modulation": np.asarray(mask.modulation).astype(str), "sideband": np.asarray(mask.sideband).astype(int)}
    for key, field in (("frequency_hz", "frequency"), ("low_hz", "low"), ("high_hz", "high")):
        cols[key] = np.ravel(getattr(mask, field)) / hz
    cols["order"] = np.array([_order(f, shaft_speed / hz) for f in cols["frequency_hz"]])
    return cols


def _optional(value, factor):
    return None if value is None else value * factor


def bearing_summary(bearing):
    """Every known field of a bearing and its derived quantities, in engineering units.

    Parameters
    ----------
    bearing : BallBearing
        The bearing.

    Returns
    -------
    dict
        Field name (with its unit) -> value; ``None`` for a field the bearing does not give.
    """
    if hasattr(bearing, "roller_diameter"):  # a RollerBearing (issue 32)
        return roller_summary(bearing)
    b = bearing
    out = {"designation": b.designation, "type": b.type, "balls": b.n_balls,
           "ball_diameter_mm": b.ball_diameter and b.ball_diameter * 1e3,
           "pitch_diameter_mm": b.pitch_diameter and b.pitch_diameter * 1e3,
           "inner_conformity": b.inner_conformity, "outer_conformity": b.outer_conformity,
           "contact_angle_deg": None if b.contact_angle is None else math.degrees(b.contact_angle),
           "radial_clearance_um": b.radial_clearance and b.radial_clearance * 1e6,
           "bore_mm": b.bore and b.bore * 1e3, "outside_diameter_mm": b.outside_diameter and b.outside_diameter * 1e3,
           "width_mm": b.width and b.width * 1e3, "static_load_rating_N": b.static_load_rating,
           "ball_material": b.ball_material.name, "ring_material": b.ring_material.name, "source": b.source}
    if b.inner_conformity is not None and b.outer_conformity is not None and b.ball_diameter is not None:
        out["inner_groove_radius_mm"] = b.inner_groove_radius * 1e3
        out["outer_groove_radius_mm"] = b.outer_groove_radius * 1e3
        out["total_curvature_B"] = b.total_curvature
        out["groove_distance_A_mm"] = b.groove_distance * 1e3
        if b.contact_angle is not None and b.pitch_diameter is not None:
            out["gamma"] = b.gamma
            if b.contact_angle > 0 and b.type != "thrust" and (b.radial_clearance is not None or b.type in (
                    "radial", "angular", "double-row-radial")):  # the others need their clearance
                out["axial_play_mm"] = b.axial_play() * 1e3
    if b.hertz_table:
        out["hertz_table"] = dict(b.hertz_table)
    return out


def catalog_entry(name, bearing):
    """The row of a bearing in a catalog listing.

    Parameters
    ----------
    name : str
        The name the catalog lists it under.
    bearing : BallBearing
        The bearing.

    Returns
    -------
    dict
        ``name``, ``type``, ``balls`` and the main dimensions in mm and deg (``None`` where not given).
    """
    b = bearing
    return {
        "name": name, "type": b.type, "balls": b.n_balls,
        "ball_diameter_mm": _optional(b.ball_diameter, 1e3),
        "pitch_diameter_mm": _optional(b.pitch_diameter, 1e3),
        "contact_angle_deg": None if b.contact_angle is None else math.degrees(b.contact_angle),
        "bore_mm": _optional(b.bore, 1e3),
        "outside_diameter_mm": _optional(b.outside_diameter, 1e3),
    }


def runout_metrics(metrics, names):
    """Runout metrics (SI) as ``{name}_um`` values in micrometres.

    Parameters
    ----------
    metrics : NamedTuple
        A metrics result of :mod:`bearinglab.runout` (fields in m).
    names : sequence of str
        The metrics wanted, in order (e.g. ``runout.METRICS``).

    Returns
    -------
    dict
        ``{name}_um`` -> float.
    """
    return {f"{name}_um": float(getattr(metrics, name)) / 1e-6 for name in names}


def write_table(table, path, *, comments=()):
    """Write columns to a .csv or .parquet file, whole or not at all (temporary file, then rename).

    CSV cells: floats in full precision, NaN and missing values empty, booleans ``true``/``false``;
    ``comments`` become ``#`` lines before the header. The directory must exist.

    Parameters
    ----------
    table : dict
        Column name -> 1-D array, all of one length.
    path : str or Path
        Target file; its suffix (.csv or .parquet) chooses the format.
    comments : sequence of str, optional
        Lines written as ``# line`` before the header (CSV only).

    Returns
    -------
    Path
    """
    return write_columns(path, table, comments=comments)


# ----------------------------------------------------------------------------- issues 11 and 12
#: Per-ball columns of one case of :func:`bearinglab.quasistatic.combined.load_distribution`.
BALLS = (
    Column("azimuth_deg", "azimuth", "deg", _DEG),
    Column("load_inner_N", "ball_load_inner", "N"),
    Column("load_outer_N", "ball_load_outer", "N"),
    Column("contact_angle_inner_deg", "contact_angle_inner", "deg", _DEG),
    Column("contact_angle_outer_deg", "contact_angle_outer", "deg", _DEG),
    Column("max_pressure_inner_MPa", "max_pressure_inner", "MPa", 1e-6),
    Column("max_pressure_outer_MPa", "max_pressure_outer", "MPa", 1e-6),
)

#: Load ratings of a bearing (:class:`bearinglab.ratings.BearingRatings` or a rating-life result).
RATINGS = (
    Column("dynamic_load_rating_N", "dynamic_load_rating", "N"),
    Column("static_load_rating_N", "static_load_rating", "N"),
    Column("fatigue_load_limit_N", "fatigue_load_limit", "N"),
)

#: Per-case columns of :func:`bearinglab.life.rating_life` (Mrev: 10^6 revolutions).
RATING_LIFE = (
    Column("equivalent_dynamic_load_N", "equivalent_dynamic_load", "N"),
    Column("basic_rating_life_Mrev", "basic_rating_life", "Mrev", 1e-6),
    Column("basic_rating_life_h", "basic_rating_life_duration", "h", 1.0, 3600.0),
    Column("reliability_factor", "reliability_factor", "-"),
    Column("viscosity_mm2_s", "kinematic_viscosity", "mm^2/s", 1e6),
    Column("rated_viscosity_mm2_s", "rated_viscosity", "mm^2/s", 1e6),
    Column("rated_viscosity_diameter_mm", "rated_viscosity_diameter", "mm", 1e3),
    Column("viscosity_ratio", "viscosity_ratio", "-"),
    Column("life_modification_factor", "life_modification_factor", "-"),
    Column("modified_rating_life_Mrev", "modified_rating_life", "Mrev", 1e-6),
    Column("modified_rating_life_h", "modified_rating_life_duration", "h", 1.0, 3600.0),
    Column("reference_rating_life_Mrev", "reference_rating_life", "Mrev", 1e-6),
    Column("modified_reference_rating_life_Mrev", "modified_reference_rating_life", "Mrev", 1e-6),
    Column("static_safety_factor", "static_safety_factor", "-"),
)

#: The moments of :func:`bearinglab.friction.skf` (an :class:`~bearinglab.friction.skf.SKFTorque`).
SKF_TORQUE = (
    Column("rolling_moment_Nmm", "rolling_moment", "N·mm", 1e3),
    Column("sliding_moment_Nmm", "sliding_moment", "N·mm", 1e3),
    Column("seal_moment_Nmm", "seal_moment", "N·mm", 1e3),
    Column("drag_moment_Nmm", "drag_moment", "N·mm", 1e3),
    Column("total_moment_Nmm", "total_moment", "N·mm", 1e3),
    Column("power_loss_W", "power_loss", "W"),
    Column("sliding_friction_coefficient", "sliding_friction_coefficient", "-"),
)


def _broadcast(cols):
    """Columns of one length (scalars such as a rating repeated over the cases)."""
    n = max(len(v) for v in cols.values())
    return {k: np.broadcast_to(v, (n,)) for k, v in cols.items()}


def ball_columns(result):
    """The per-ball columns of one case of a combined-load distribution (:data:`BALLS`).

    Parameters
    ----------
    result : LoadDistribution
        One case (ball fields of shape (Z,)).

    Returns
    -------
    dict
        ``azimuth_deg``, ``load_inner_N``, ``load_outer_N``, ``contact_angle_inner_deg``,
        ``contact_angle_outer_deg``, ``max_pressure_inner_MPa``, ``max_pressure_outer_MPa`` -> (Z,) arrays.
    """
    return columns(result, BALLS)


def load_distribution(result):
    """One case of a combined-load distribution in engineering units, JSON-ready.

    Parameters
    ----------
    result : LoadDistribution
        One case of :func:`bearinglab.quasistatic.combined.load_distribution` (or one bearing of a set,
        any object with ``displacement`` (5,), ``stiffness`` (5, 5), the per-ball fields and
        ``max_ball_load``).

    Returns
    -------
    dict
        ``displacement_x_um``, ``displacement_y_um``, ``displacement_z_um``, ``tilt_x_mrad``,
        ``tilt_y_mrad``, ``stiffness_matrix`` (5 x 5 in SI: N/m, N/rad, N m/m, N m/rad), ``max_ball_load_N``,
        ``converged``, ``residual``, ``iterations`` (those the result has) and ``balls`` (one dict per ball,
        :func:`ball_columns`; the other ball types one per ball and row, its ``row`` first: a double-row
        bearing's row, a four-point bearing's diagonal, 0 carrying F_z > 0).
    """
    u = np.asarray(result.displacement, dtype=float)
    out = {f"displacement_{a}_um": u[i] * 1e6 for i, a in enumerate("xyz")}
    out.update(tilt_x_mrad=u[3] * 1e3, tilt_y_mrad=u[4] * 1e3,
               stiffness_matrix=np.asarray(result.stiffness, dtype=float),
               max_ball_load_N=np.max(np.asarray(result.ball_load_inner, dtype=float)))
    for name in ("converged", "residual", "iterations"):
        if hasattr(result, name):
            out[name] = getattr(result, name)
    out = json_value(out)  # as a whole: a null is known by its key (bearinglab._io.NULLED)
    out["balls"] = rows(ball_columns(result))
    row = getattr(result, "row", None)  # the other ball types: each entry's row (a four-point bearing's diagonal)
    if row is not None:
        out["balls"] = [{"row": int(k), **ball} for k, ball in zip(np.ravel(row), out["balls"], strict=True)]
    return out


def rating_life(result):
    """A rating-life analysis as columns: the ratings (:data:`RATINGS`) and the lives (:data:`RATING_LIFE`).

    Parameters
    ----------
    result : RatingLife
        A result of :func:`bearinglab.life.rating_life` (one or more load cases).

    Returns
    -------
    dict
        Column name -> 1-D array, one row per load case (the ratings repeated): ``dynamic_load_rating_N``,
        ..., ``basic_rating_life_Mrev``, ``basic_rating_life_h``, ..., ``static_safety_factor``. A life that
        ISO 281 does not define (under a moment) is NaN, and so are the lubrication-dependent columns
        (viscosity, kappa, a_ISO, L_nm, L_nmr) of an analysis without a lubricant (None there).
    """
    return _broadcast({**columns(result, RATINGS), **columns(result, RATING_LIFE)})


def ratings(result):
    """The load ratings of a bearing and their sources, JSON-ready.

    Parameters
    ----------
    result : BearingRatings
        From :func:`bearinglab.ratings.bearing_ratings` (or a rating-life result).

    Returns
    -------
    dict
        ``dynamic_load_rating_N``, ``static_load_rating_N``, ``fatigue_load_limit_N`` and
        ``rating_source`` (quantity -> ``"catalog"``, ``"ISO 281"``, ``"ISO 76"``, ...).
    """
    return {**record(result, RATINGS), "rating_source": dict(result.rating_source)}


def skf_torque(result):
    """The moments of the SKF model in N·mm, the power loss in W and mu_sl (:data:`SKF_TORQUE`).

    Parameters
    ----------
    result : SKFTorque
        From :func:`bearinglab.friction.skf` or :func:`~bearinglab.friction.skf.skf_for_bearing`.

    Returns
    -------
    dict
        Column name -> 1-D array, one row per case.
    """
    return _broadcast(columns(result, SKF_TORQUE))


def film(result, case=()):
    """One case of a film analysis in engineering units, JSON-ready.

    Parameters
    ----------
    result : FilmAnalysis
        A result of :func:`bearinglab.film.film_analysis`.
    case : tuple of int, optional
        Index of the case in a batched result (``()`` for a single case).

    Returns
    -------
    dict
        ``film_min_um``, ``lambda_min``, ``regime``, ``converged`` and ``balls``: one dict per ball with
        ``load_inner_N``, ``load_outer_N``, ``contact_angle_inner_deg``, ``contact_angle_outer_deg``,
        ``entrainment_velocity_inner_m_s``, ``entrainment_velocity_outer_m_s``, ``ellipticity_inner``,
        ``ellipticity_outer``, ``film_central_inner_um``, ``film_min_inner_um``, ``film_central_outer_um``,
        ``film_min_outer_um``, ``lambda_inner``, ``lambda_outer`` (null where a ball carries no load).
    """
    def pick(name):
        return np.asarray(getattr(result, name), dtype=float)[case]

    per_ball = {"load_inner_N": (pick("load_inner"), 1.0), "load_outer_N": (pick("load_outer"), 1.0),
                "contact_angle_inner_deg": (pick("contact_angle_inner"), 180.0 / np.pi),
                "contact_angle_outer_deg": (pick("contact_angle_outer"), 180.0 / np.pi),
                "entrainment_velocity_inner_m_s": (pick("entrainment_velocity_inner"), 1.0),
                "entrainment_velocity_outer_m_s": (pick("entrainment_velocity_outer"), 1.0),
                "ellipticity_inner": (pick("ellipticity_inner"), 1.0),
                "ellipticity_outer": (pick("ellipticity_outer"), 1.0),
                "film_central_inner_um": (pick("central_film_inner"), 1e6),
                "film_min_inner_um": (pick("minimum_film_inner"), 1e6),
                "film_central_outer_um": (pick("central_film_outer"), 1e6),
                "film_min_outer_um": (pick("minimum_film_outer"), 1e6),
                "lambda_inner": (pick("film_parameter_inner"), 1.0),
                "lambda_outer": (pick("film_parameter_outer"), 1.0)}
    z = per_ball["load_inner_N"][0].shape[-1]
    balls = [{k: float(np.broadcast_to(v, (z,))[j]) * f for k, (v, f) in per_ball.items()} for j in range(z)]
    return json_value({"film_min_um": float(pick("minimum_film")) * 1e6,  # as a whole: nulls known by key
                       "lambda_min": float(pick("minimum_film_parameter")),
                       "regime": str(np.asarray(result.regime)[case]) or None,
                       "converged": bool(np.asarray(result.converged)[case]), "balls": balls})


def roller_summary(bearing):
    """Every known field of a roller bearing and its derived quantities, in engineering units.

    Parameters
    ----------
    bearing : RollerBearing
        The bearing.

    Returns
    -------
    dict
        Field name (with its unit) -> value, ``None`` for a field the bearing does not give: the type and
        design, the roller set (``rollers``, ``roller_diameter_mm``, ``roller_length_mm``,
        ``pitch_diameter_mm``, ``contact_angle_deg``, ``radial_clearance_um``), the profile (a name, or
        [position mm, drop um] pairs), the envelope, the catalogue's ratings and factors (``e``, ``Y``, ``Y1``,
        ``Y0``), the materials; ``gamma`` = D_we cos(alpha) / D_pw and a tapered bearing's cone and roller
        angles where the roller set is known.
    """
    b = bearing

    def mm(x, f=1e3):
        return None if x is None else x * f

    profile = b.profile if isinstance(b.profile, str) else [[x * 1e3, h * 1e6] for x, h in b.profile]
    out = {"designation": b.designation, "type": b.type, "design": b.design, "rows": b.rows, "rollers": b.rollers,
           "roller_diameter_mm": mm(b.roller_diameter), "roller_length_mm": mm(b.roller_length),
           "pitch_diameter_mm": mm(b.pitch_diameter),
           "contact_angle_deg": None if b.contact_angle is None else math.degrees(b.contact_angle),
           "radial_clearance_um": mm(b.radial_clearance, 1e6), "profile": profile,
           "crown_drop_um": mm(b.crown_drop, 1e6), "edge_radius_mm": mm(b.edge_radius),
           "edge_length_mm": mm(b.edge_length), "bore_mm": mm(b.bore), "outside_diameter_mm": mm(b.outside_diameter),
           "width_mm": mm(b.width), "inner_ring_width_mm": mm(b.inner_ring_width),
           "dynamic_load_rating_N": b.dynamic_load_rating, "static_load_rating_N": b.static_load_rating,
           "fatigue_load_limit_N": b.fatigue_load_limit, "e": b.ratio_limit, "Y": b.axial_factor,
           "Y1": b.axial_factor_below, "Y0": b.static_axial_factor, "pressure_centre_mm": mm(b.pressure_centre),
           "series": b.series, "full_complement": b.full_complement, "roller_material": b.roller_material.name,
           "ring_material": b.ring_material.name, "source": b.source}
    if None not in (b.roller_diameter, b.pitch_diameter, b.contact_angle):
        out["gamma"] = b.roller_diameter * math.cos(b.contact_angle) / b.pitch_diameter
        if b.type == "tapered":
            a = b.tapered_angles
            out["cone_angle_deg"] = math.degrees(a.cone_angle)
            out["roller_angle_deg"] = math.degrees(a.roller_angle)
    return out
