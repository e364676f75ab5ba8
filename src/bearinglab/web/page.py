"""The calculator page: form fields, the sections computed from them, and the figures.

Every section runs one endpoint of the JSON API (:mod:`bearinglab.web.api`) with the fields its
command takes, so the page shows the command line's numbers. A section whose command fails shows the
command's one-line message; a message that names a form field is shown next to that field.

Form
----
FIELDS       the form fields: query name, label, placeholder (an example with its unit)
Section      one section of results: title, endpoint, extra parameters
SECTIONS     the sections, in the order shown
compute      form values -> the sections' results and the field messages
figure_svg   a command's own figure (its ``--plot`` option) as inline SVG
quantity     a result key with its unit suffix -> a readable label and unit
number       a value as the page shows it: 6 significant digits, float noise as 0
scales       the largest value of each unit in a document (what counts as noise next to it)
column_scales  the same per column of a table of rows
"""

from __future__ import annotations

import math
import tempfile
from pathlib import Path
from typing import NamedTuple

from .. import cli
from ..errors import InputError
from ..units import parse_quantity
from . import api

__all__ = [
    "DIGITS",
    "FIELDS",
    "NOISE",
    "SECTIONS",
    "Result",
    "Section",
    "column_scales",
    "compute",
    "figure_svg",
    "number",
    "quantity",
    "scales",
]


class Field(NamedTuple):
    """One form field."""

    name: str
    label: str
    placeholder: str
    group: str
    choices: tuple = ()  # a select; the first is the default


#: The form fields, by query name; the geometry fields override the catalog bearing's.
FIELDS = {
    f.name: f
    for f in (
        Field("axial_load", "Axial load", "20 kN", "loads"),
        Field("radial_load", "Radial load", "0 kN", "loads"),
        Field("speed", "Shaft speed", "10000 rpm", "loads"),
        Field("viscosity", "Lubricant viscosity", "20 cSt", "loads"),
        # the command line's default first (one answer per question); the published B218 results of
        # spec 004 section 7 use Harris's constants, one choice away
        Field("constants", "High-speed constants", "", "loads", ("mass", "harris", "paper")),
        Field("balls", "Balls", "16", "geometry"),
        Field("ball_diameter", "Ball diameter", "22.225 mm", "geometry"),
        Field("pitch_diameter", "Pitch diameter", "125.26 mm", "geometry"),
        Field("inner_conformity", "Inner conformity r/D", "0.52", "geometry"),
        Field("outer_conformity", "Outer conformity r/D", "0.52", "geometry"),
        Field("contact_angle", "Free contact angle", "40 deg", "geometry"),
        Field("ball_material", "Ball material", "steel", "geometry"),
    )
}


class Section(NamedTuple):
    """One section of results."""

    key: str
    title: str
    endpoint: str
    extra: dict
    note: str


SECTIONS = (
    Section(
        "high-speed",
        "Contact angles at speed",
        "high-speed",
        {},
        "Quasi-static model under thrust (Jones/Harris); the radial load does not enter.",
    ),
    Section(
        "axial-angle",
        "Contact angle at rest",
        "axial-angle",
        {},
        "Operating contact angle under the axial load, at rest (test-stand method).",
    ),
    Section(
        "frequencies",
        "Defect frequencies",
        "frequencies",
        {},
        "Characteristic frequencies at the operating contact angle under the axial load.",
    ),
    Section("load-distribution", "Load distribution and stiffness", "load-distribution", {}, ""),
    Section("life", "Rating life", "life", {}, ""),
    Section("friction", "Friction torque", "friction", {"model": "skf"}, "SKF model."),
)


class Result(NamedTuple):
    """A section's outcome."""

    section: Section
    document: object  # the command's JSON document, or None
    message: str  # the command's message when it failed ('' otherwise)
    figure: str  # inline SVG, or ''


def _argv_values(endpoint, values, extra):
    """The form values the endpoint's command takes (empty fields left out), and the extra options."""
    known = api.options(endpoint)
    query = {k: v for k, v in values.items() if k in known and v.strip()}
    query.update({k: v for k, v in extra.items() if k in known})
    return query


def figure_svg(endpoint, query):
    """The command's own figure for ``query`` (its ``--plot`` option, written as SVG) or ''.

    Parameters
    ----------
    endpoint : str
        A key of :data:`bearinglab.web.api.ENDPOINTS`.
    query : dict
        Query parameters of the command (a sweep where the figure needs one).

    Returns
    -------
    str
        The ``<svg>`` element, or '' when the command has no figure or failed.
    """
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "figure.svg"
        argv = list(api.ENDPOINTS[endpoint])
        argv += [f"--{k.replace('_', '-')}={v}" for k, v in query.items()] + [f"--plot={path}"]
        try:
            drawn = cli.run_json(argv).exit_code == 0 and path.exists()
        except Exception:  # noqa: BLE001 -- a figure that fails is left out; the numbers stand
            drawn = False
        if not drawn:
            return ""
        svg = path.read_text(encoding="utf-8")
    start = svg.find("<svg")
    return svg[start:] if start >= 0 else ""


def _high_speed_map(query):
    """The high-speed map around the case: thrust from a tenth to twice the load, at rest and at speed."""
    try:
        fa = parse_quantity(query["axial_load"], "force", "axial-load")
        n = parse_quantity(query["speed"], "speed", "speed")
    except (InputError, KeyError):
        return ""
    step = fa / 10.0
    sweep = dict(
        query,
        axial_load=f"{step:.6g}N:{20 * step:.6g}N:{step:.6g}N",
        speed=f"0 rpm; {query['speed']}" if n > 0 else query["speed"],
    )
    return figure_svg("high-speed", sweep)


def compute(values):
    """Run every section with the form ``values``.

    Parameters
    ----------
    values : dict of str to str
        The form: ``bearing`` and the :data:`FIELDS` (empty strings for empty fields).

    Returns
    -------
    results : list of Result
        One per section of :data:`SECTIONS`.
    field_errors : dict of str to str
        Field name -> the first message that names it.
    """
    results, field_errors = [], {}
    for section in SECTIONS:
        if not api.options(section.endpoint):
            results.append(
                Result(section, None, "Not available in this version of bearinglab.", "")
            )
            continue
        if section.endpoint in ("life", "friction") and not values.get("viscosity", "").strip():
            # no lubricant given: not an error of the form, just nothing to compute yet
            results.append(Result(section, None, "Enter the lubricant viscosity to see this section.", ""))
            continue
        query = _argv_values(section.endpoint, values, section.extra)
        status, doc = api.call(section.endpoint, query)  # never raises: errors come as a body
        if status != 200:
            name = doc.get("parameter")
            if name in FIELDS or name == "bearing":
                field_errors.setdefault(name, doc["detail"])
            results.append(Result(section, None, doc["detail"], ""))
            continue
        svg = _high_speed_map(query) if section.endpoint == "high-speed" else ""
        if not svg and "plot" in _plot_options(section.endpoint):
            svg = figure_svg(section.endpoint, query)
        results.append(Result(section, doc, "", svg))
    return results, field_errors


def _plot_options(endpoint):
    """The file options of the command (the web API hides them; the page uses ``--plot`` for figures)."""
    command = api._command(api.ENDPOINTS[endpoint])
    return {
        o[2:]
        for p in getattr(command, "params", ())
        for o in getattr(p, "opts", ())
        if o.startswith("--")
    }


_UNITS = (
    ("_cm2_per_kgf_2_3", "cm²/kgf^⅔"),
    ("_N_per_um", "N/µm"),
    ("_per_mm", "1/mm"),
    ("_Nmm", "N·mm"),
    ("_Nm", "N·m"),
    ("_kN", "kN"),
    ("_N", "N"),
    ("_deg", "°"),
    ("_dms", "° ′ ″"),
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
    """A result key -> (label, unit): ``contact_angle_inner_deg`` -> ``("contact angle inner", "°")``.

    Parameters
    ----------
    key : str
        A key of a command's JSON document; its suffix is the unit.

    Returns
    -------
    tuple of str
    """
    for suffix, unit in _UNITS:
        if key.endswith(suffix) and len(key) > len(suffix):
            return key[: -len(suffix)].replace("_", " "), unit
    return key.replace("_", " "), ""


#: Significant digits the page shows (the JSON API keeps every digit).
DIGITS = 6
#: A value below this fraction of the largest value of its unit in the same table is float noise
#: (3.5e-14 µm next to 696 µm, the off-axis displacement of a symmetric load) and is shown as 0.
NOISE = 1e-9
_SUPERSCRIPT = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")


def number(value, scale=0.0):
    """A value as the page shows it: floats to :data:`DIGITS` significant digits, noise as 0.

    Parameters
    ----------
    value : object
        A value of a command's JSON document.
    scale : float, optional
        The largest magnitude of the values of the same unit in the same table
        (:func:`scales`); a float below :data:`NOISE` times it is shown as ``0``.

    Returns
    -------
    str
        ``3000`` for 3000.0000000000005, ``1.06553 × 10⁶`` for 1065532.66, ``yes``/``no`` for flags,
        ``—`` for a missing value.

    Examples
    --------
    >>> number(3000.0000000000005), number(12449.999999999998), number(3.45e-14, 696.3)
    ('3000', '12450', '0')
    >>> number(31344565.19), number(-2.5e-7), number(True), number(None)
    ('3.13446 × 10⁷', '-2.5 × 10⁻⁷', 'yes', '—')
    """
    if isinstance(value, bool) or value is None:
        return {True: "yes", False: "no", None: "—"}[value]
    if not isinstance(value, float) or not math.isfinite(value):
        return str(value)
    if abs(value) <= NOISE * scale or value == 0.0:
        return "0"  # also -0.0
    text = f"{value:.{DIGITS}g}"
    if "e" not in text:
        return text
    mantissa, exponent = text.split("e")
    return f"{mantissa} × 10{str(int(exponent)).translate(_SUPERSCRIPT)}"


def _magnitude(value):
    return abs(value) if isinstance(value, float) and math.isfinite(value) else 0.0


def scales(document):
    """The :func:`number` scale of each value of a document: the largest magnitude of its unit there.

    Parameters
    ----------
    document : mapping
        A command's JSON document (its scalar values; nested values are left out).

    Returns
    -------
    dict
        Key -> scale; 0 for dimensionless values (a residual of 1e-15 is not noise) and non-numbers.

    Examples
    --------
    >>> scales({"displacement_x_um": 83.6, "displacement_y_um": 3e-14, "residual": 1e-15})
    {'displacement_x_um': 83.6, 'displacement_y_um': 83.6, 'residual': 0.0}
    """
    largest = {}
    for key, value in document.items():
        unit = quantity(key)[1]
        if unit:
            largest[unit] = max(largest.get(unit, 0.0), _magnitude(value))
    return {key: largest.get(quantity(key)[1], 0.0) for key in document}


def column_scales(rows):
    """The :func:`number` scale of each column of a table of rows: its largest magnitude.

    Parameters
    ----------
    rows : list of mapping
        One dict per row, all with the same keys.

    Returns
    -------
    dict
        Column key -> scale.
    """
    return {key: max((_magnitude(row.get(key)) for row in rows), default=0.0) for key in rows[0]} if rows else {}
