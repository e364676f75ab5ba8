"""The calculator page: the form (from the calculations' fields), the sections, the report, the CSV.

Every section is one calculation of :mod:`bearinglab.calculations`, computed with the form's values
that are fields of that calculation, so the page shows the command line's numbers. A section that does
not apply to the input (no thrust for the high-speed model, no load for a life) is left out with one
line saying why; an input error is shown next to the field it names, in the field's label.

Form and sections
-----------------
FIELDS          the form fields, by name, grouped (loads, lubricant, model, set, geometry, mounting,
                film, heat, runout)
Section         one section of results: title, calculation, the rule that says when it applies
SECTIONS        the sections, in the order shown
NOT_ON_PAGE     registered calculations without a section of their own, and why
sections        SECTIONS, then a left-out line for any registered calculation the page lacks
value_rows      a document's table of values: label, text, unit (scalars, ranges, nested numbers)
case_rows       a document that is a list of cases as a table of rows (the inputs that differ first)
chain_rows      the mounted-clearance chain: stages x least / probable / largest (CHAIN, CHAIN_COLUMNS)
percentile_rows the Monte Carlo study of a clearance: percentiles, mean, std, P(clearance < 0)
render_context  form values -> what the template shows (async: the sections run in the workers)
PAGE_ROWS       the most rows of a table of cases the page shows (the JSON and CSV hold them all)
lists_note      the report's line on lists and ranges of the loads and speed: a table of the cases in
                the sections that take them; the sections that take one value are left out, saying so
to_csv          a document as CSV text (quantity, value, unit; a table of cases as rows)
quantity        a result key with its unit suffix -> a readable label and unit
number          a value as the page shows it: 6 significant digits, float noise as 0
scales          the largest value of each unit in a document (what counts as noise next to it)
column_scales   the same per column of a table of rows

Deprecated (removed in the next release): Result, compute, figure_svg.
"""

from __future__ import annotations

import asyncio
import csv
import datetime
import io
import math
import urllib.parse
from typing import NamedTuple

from ..calculations import CALCULATIONS
from ..calculations.registry import GEOMETRY, MOUNTING
from . import shaft as _shaft  # the shaft-system section: its editor, request and tables (issue 33)

__all__ = [
    "CHAIN",
    "CHAIN_COLUMNS",
    "DIGITS",
    "FIELDS",
    "NOISE",
    "NOT_ON_PAGE",
    "PAGE_ROWS",
    "SECTIONS",
    "Result",
    "Section",
    "case_rows",
    "chain_rows",
    "column_scales",
    "compute",
    "figure_svg",
    "lists_note",
    "number",
    "percentile_rows",
    "quantity",
    "render_context",
    "scales",
    "sections",
    "to_csv",
    "value_rows",
]


def _pick(calc, name, **change):
    import dataclasses

    return dataclasses.replace(CALCULATIONS[calc].field(name), **change)


#: The form fields, by name: each is a field of one or more calculations (same name, same unit).
FIELDS = {
    f.name: f
    for f in (
        _pick("life", "radial_load", group="loads", label="Radial load F_r"),
        _pick("life", "fx", group="loads"),
        _pick("life", "fy", group="loads"),
        _pick("life", "axial_load", group="loads", label="Axial load F_a"),
        _pick("life", "mx", group="loads"),
        _pick("life", "my", group="loads"),
        _pick("high-speed", "speed", group="loads", many=False, required=False),
        _pick("life", "viscosity", group="lubricant"),
        _pick("life", "oil", group="lubricant"),
        _pick("life", "temperature", group="lubricant"),
        _pick("life", "viscosity_index", group="lubricant"),
        _pick("life", "contamination", group="lubricant"),
        _pick("life", "contamination_factor", group="lubricant"),
        _pick("life", "reliability", group="lubricant", default=None),
        _pick("friction", "lubrication", group="lubricant"),
        _pick("friction", "oil_level", group="lubricant"),  # an oil bath: H and SKF's V_M read at H/d_m
        _pick("friction", "drag_loss_factor", group="lubricant"),
        _pick("friction", "model", group="model"),
        _pick("high-speed", "constants", group="model"),
        _pick("bearing-set", "arrangement", group="set", default="",
              choices=("", "DB", "DF", "DT"), label="Arrangement (a set of two)"),
        _pick("bearing-set", "preload", group="set"),
        _pick("bearing-set", "spacing", group="set", default=None),
        _pick("bearing-set", "preload_offset", group="set"),
        *GEOMETRY,
        *(_pick("clearance", f.name, group="mounting") for f in MOUNTING),
        _pick("clearance", "shaft_roughness", group="mounting"),
        _pick("clearance", "housing_roughness", group="mounting"),
        _pick("clearance", "monte_carlo", group="mounting"),
        _pick("clearance", "seed", group="mounting", default=None),
        _pick("clearance", "distribution", group="mounting", default=None),
        _pick("film", "roughness", group="film"),
        _pick("film", "roughness_ball", group="film"),
        _pick("film", "roughness_race", group="film"),
        _pick("film", "density", group="film"),
        _pick("film", "pressure_viscosity_coefficient", group="film"),
        _pick("film", "loads_at", group="film", default=None),
        _pick("temperature", "ambient", group="heat", default=None),
        _pick("temperature", "thermal_resistance", group="heat"),
        _pick("temperature", "oil_flow", group="heat"),
        _pick("temperature", "oil_inlet_temperature", group="heat"),
        _pick("temperature", "max_temperature", group="heat", default=None),
        _pick("temperature", "skf_constants", group="heat"),
        _pick("runout", "errors", group="runout", required=False),
        _pick("runout", "angle", group="runout"),
    )
}
_GROUPS = (("loads", "Loads and speed"), ("lubricant", "Lubricant, cleanliness, reliability"),
           ("model", "Models"), ("set", "Bearing set (leave the arrangement empty for one bearing)"),
           ("geometry", "Inline geometry (overrides the catalog bearing's)"),
           ("mounting", "Mounting: fits, ring temperatures, Monte Carlo of the tolerances"),
           ("film", "Lubricant film: roughness, oil density and pressure-viscosity coefficient"),
           ("heat", "Heat balance: ambient, dissipation, oil flow"),
           ("runout", "Runout: paste an error set (TOML or JSON, as examples/runout/README.md)"))
_EXAMPLES = {"radial_load": "10 kN", "fx": "1 kN", "fy": "0 N", "axial_load": "5 kN",
             "mx": "0 N*mm", "my": "0 N*mm", "speed": "6000 rpm", "viscosity": "20 cSt",
             "oil": "VG68", "temperature": "70 degC", "contamination_factor": "0.5",
             "reliability": "90", "preload": "500 N", "spacing": "0 mm", "preload_offset": "5 um",
             "oil_level": "5 mm", "drag_loss_factor": "0.0002", "balls": "16",
             "ball_diameter": "22.225 mm", "pitch_diameter": "125.26 mm", "inner_groove_radius": "",
             "outer_groove_radius": "", "inner_conformity": "0.52", "outer_conformity": "0.52",
             "contact_angle": "40 deg", "radial_clearance": "", "mean_diameter": "",
             "viscosity_index": "95", "shaft_fit": "k5", "housing_fit": "H7",
             "shaft_interference": "5 um, 20 um", "housing_interference": "-10 um, 5 um",
             "shaft_bore": "20 mm", "housing_outside_diameter": "120 mm", "tolerance_class": "P6",
             "clearance_class": "C3", "inner_ring_temperature": "60 degC",
             "outer_ring_temperature": "50 degC", "ball_temperature": "55 degC",
             "shaft_temperature": "60 degC", "housing_temperature": "45 degC",
             "shaft_roughness": "4 um", "housing_roughness": "4 um", "monte_carlo": "10000",
             "seed": "0", "roughness": "0.1 um", "roughness_ball": "0.05 um",
             "roughness_race": "0.15 um", "density": "870 kg/m^3",
             "pressure_viscosity_coefficient": "23 1/GPa", "ambient": "20 degC",
             "thermal_resistance": "0.5 K/W", "oil_flow": "0.5 l/min",
             "oil_inlet_temperature": "40 degC", "max_temperature": "150 degC",
             "skf_constants": "R1,R2,R3,S1,S2,S3"}


class Section(NamedTuple):
    """One section of results."""

    key: str
    title: str
    calculation: str
    note: str


SECTIONS = (
    Section("catalog", "Catalog bearing", "catalog", "Catalog data, derived geometry and ratings."),
    Section("high-speed", "Contact angles at speed", "high-speed",
            "Quasi-static model under thrust (Jones/Harris); radial loads and moments do not enter."),
    Section("axial-angle", "Contact angle at rest", "axial-angle",
            "Operating contact angle under the axial load, at rest (test-stand method)."),
    Section("frequencies", "Defect frequencies", "frequencies",
            "At the operating contact angle under the axial load, if one is given."),
    Section("load-distribution", "Load distribution and stiffness", "load-distribution", ""),
    Section("bearing-set", "Bearing set", "bearing-set", "Two bearings of the catalog bearing."),
    Section("life", "Rating life", "life", ""),
    Section("stand-load", "Test-stand load", "stand-load",
            "Minimum axial load on a test stand at this speed (the stand's test method)."),
    Section("runout", "Runout", "runout", "Inner-ring displacement from the error set."),
    Section("friction", "Friction torque", "friction",
            "F_r = |(F_x, F_y)| where F_x, F_y are given; the moments do not enter these models."),
    Section("clearance", "Mounted clearance", "clearance",
            "Diametral clearance from the unmounted class range through the fits, the ring "
            "temperatures and the speed; least / probable / largest."),
    Section("film", "Lubricant film", "film",
            "EHL film per contact (Hamrock-Dowson), at the ball loads of the load distribution."),
    Section("temperature", "Operating temperature", "temperature",
            "Thermal balance: SKF friction power = heat dissipated. F_r = |(F_x, F_y)| where F_x, "
            "F_y are given; the moments do not enter."),
    Section("shaft", "Shaft system", "shaft",
            "Several bearings on one elastic shaft (Timoshenko elements), from the Shaft system tables: the "
            "load on each support, its displacement and tilt, the bearings' lives and the system's (ISO 281)."),
)
#: Calculations of :data:`~bearinglab.calculations.CALCULATIONS` with no section of their own, and why
#: (one line on the page). A calculation that is in neither SECTIONS nor here (a newly registered one)
#: gets a left-out line pointing to its API endpoint, so the page never misses one silently.
NOT_ON_PAGE = {
    "catalog-search": "the bearing picker of the form",
}

_LOADS = ("radial_load", "fx", "fy", "axial_load", "mx", "my")
#: the form's fields that make a mounted clearance differ from the unmounted one (or ask for its study)
_MOUNTED = (*(f.name for f in MOUNTING if f.name not in ("tolerance_class", "clearance_class")),
            "monte_carlo")


def sections():
    """:data:`SECTIONS`, then a left-out section for every registered calculation the page does not
    show (not in :data:`NOT_ON_PAGE`): its line names the API endpoint that computes it.

    Returns
    -------
    tuple of Section
    """
    from .api import ENDPOINTS

    shown = {s.calculation for s in SECTIONS} | set(NOT_ON_PAGE)
    paths = {name: path for path, name in ENDPOINTS.items()}
    extra = tuple(
        Section(name, calc.title, name, f"{calc.title} is not on this page yet; the JSON API computes "
                f"it at /api/{paths.get(name, name)} (see /docs).")
        for name, calc in CALCULATIONS.items() if name not in shown)
    return SECTIONS + extra


def _given(values, name):
    return bool(str(values.get(name) or "").strip())


#: The most rows of a table of cases the page shows (a range may hold 10^5 cases: its JSON and CSV links
#: hold every row, the page the first ones, and says so)
PAGE_ROWS = 500

#: The form's fields that some section takes as a list or range of cases (the loads and the speed)
_LISTABLE = tuple(name for name in FIELDS
                  if any(f.name == name and f.many and f.kind != "text"
                         for calc in CALCULATIONS.values() for f in calc.fields))


def _lists(values):
    """The form's fields given as a list or a range of more than one value: name -> its count (a value
    that does not read is no list: the sections name its error)."""
    import dataclasses

    from ..calculations import CASE_LIMIT, count_values

    out = {}
    for name in _LISTABLE:
        if not _given(values, name):
            continue
        try:
            count = count_values(dataclasses.replace(FIELDS[name], many=True), str(values[name]))
        except Exception:  # noqa: BLE001 -- a value that does not read: the sections name its error
            count = 1
        if count > 1:
            out[name] = min(count, CASE_LIMIT + 1)
    return out


def _single_only(section, lists):
    """The fields given as a list that the section's calculation takes one value of (its names)."""
    calc = CALCULATIONS[section.calculation]
    return [f.name for f in calc.fields if f.name in lists and not f.many]


def lists_note(lists):
    """The report's line on lists and ranges: how many cases each holds, and how the sections show them.

    Parameters
    ----------
    lists : dict of str to int
        The form's fields given as a list or range -> their number of values.

    Returns
    -------
    str
        One line; '' without a list.
    """
    if not lists:
        return ""
    held = ", ".join(f"{FIELDS[name].title} holds {count} values" for name, count in lists.items())
    return (f"Lists and ranges: {held}. The sections that take a list show a table of the cases, one row "
            f"per case; the sections that take one value at a time are left out and say so (give one "
            f"value to see them).")


def _left_out(section, values, lists=None):
    """Why a section does not apply to the input (one line), or '' when it does."""
    if section.key == "shaft":  # its own fields, none of the form's (web/shaft.py)
        return _shaft.left_out(values)
    has = {k: _given(values, k) for k in values}
    single = _single_only(section, lists or {})
    if single:
        named = " and ".join(FIELDS[name].title for name in single)
        return (f"Left out: {section.title.lower()} takes one value of {named}, not a list or range; the "
                f"sections with a table of cases take the list.")
    any_load = any(has.get(k) for k in _LOADS)
    if section.key == "high-speed" and not (has.get("axial_load") and has.get("speed")):
        return "Left out: the high-speed model solves a thrust at speed; give an axial load and a speed."
    if section.key == "axial-angle" and not has.get("axial_load"):
        return "Left out: the contact angle at rest needs an axial load."
    if section.key == "frequencies" and not has.get("speed"):
        return "Left out: the frequencies need a shaft speed."
    if section.key in ("load-distribution", "life") and not any_load:
        return "Left out: no load given."
    if section.key == "life" and not has.get("speed"):
        return "Left out: a life in hours needs a shaft speed."
    if section.key == "catalog" and not has.get("bearing"):
        return "Left out: no catalog bearing picked (inline geometry)."
    if section.key == "stand-load" and not has.get("speed"):
        return "Left out: the test-stand load needs a shaft speed."
    if section.key == "runout" and not has.get("errors"):
        return "Left out: no error set pasted."
    if section.key == "bearing-set":
        if not values.get("arrangement"):
            return "Left out: no set arrangement chosen (one bearing)."
        if not has.get("bearing"):
            return "Left out: a set is built from a catalog bearing; pick one."
    if section.key == "clearance":
        if not has.get("bearing"):
            return ("Left out: the mounted clearance needs a catalog bearing (its bore, outside "
                    "diameter and clearance class); pick one.")
        if not any(has.get(f) for f in _MOUNTED):
            return ("Left out: no fit, interference, ring temperature or Monte Carlo given "
                    "(Mounting); the clearance is the unmounted one.")
    if section.key == "film":
        if not any_load:
            return "Left out: no load given (the film is computed at each ball's load)."
        if not has.get("speed"):
            return "Left out: no film forms at rest; give a shaft speed."
        if not (has.get("viscosity") or has.get("oil")):
            return "Left out: the film needs the lubricant: a viscosity, or an oil grade and temperature."
    if section.key == "temperature":
        if not has.get("speed"):
            return "Left out: the thermal balance needs a shaft speed."
        if not has.get("oil"):
            return ("Left out: the thermal balance needs an oil grade (its viscosity follows the "
                    "temperature); a fixed viscosity is not enough.")
        if not has.get("bearing"):
            return "Left out: the thermal balance needs a catalog bearing (its SKF friction data)."
        if values.get("lubrication") == "oil-bath" and not has.get("oil_level"):
            return "Left out: an oil bath needs its oil level H (its drag loss follows from SKF's V_M diagram)."
    if section not in SECTIONS:
        return f"Left out: {section.note}"
    if section.key == "friction":
        if not (has.get("bearing") or has.get("speed") or any_load or any(has.get(f.name) for f in GEOMETRY)):
            return "Left out: no bearing, load or speed given (a shaft system or an error set alone)."
        model = values.get("model") or "one-term"
        oil = has.get("oil") and has.get("temperature") and model == "skf"  # SKF's takes a grade too
        if model in ("palmgren", "skf") and not (has.get("viscosity") or oil):
            return f"Left out: the {model} model needs the lubricant viscosity."
        if model == "two-term":
            return "Left out: the two-term model needs its measured f0 (bearinglab friction lab)."
    return ""


def _query(section, values):
    """The form values that are fields of the section's calculation (empty ones left out)."""
    if section.key == "shaft":  # the page's shaft, shaft_stiffness_at ... as the calculation's fields
        return _shaft.query(values)
    calc = CALCULATIONS[section.calculation]
    names = {f.name for f in calc.fields}
    out = {k: v for k, v in values.items() if k in names and _given(values, k)}
    if section.key == "catalog":
        return {"name": values["bearing"]}
    if section.key == "bearing-set" and "bearing" in out:
        out["bearing"] = f"{out['bearing']}, {out['bearing']}"
    if section.key == "friction" and (values.get("model") or "one-term") != "skf":
        for name in ("oil", "temperature", "viscosity_index", "viscosity_100", "lubrication",
                     "oil_level", "drag_loss_factor"):
            out.pop(name, None)  # the lubricant of SKF's model; the others refuse it
    if section.key in ("film", "life") and str(values.get("temperature") or "").strip() != "auto":
        for name in ("ambient", "thermal_resistance", "skf_constants") + (("lubrication",) if section.key
                                                                            == "life" else ()):
            out.pop(name, None)  # the heat balance's, which film and life take with temperature auto only
    if section.key in ("friction", "temperature") and "radial_load" not in out and (
            _given(values, "fx") or _given(values, "fy")):
        out["radial_load"] = _resultant(values)  # the friction models take F_r = |(F_x, F_y)|
    return out


_DATA_SECTIONS = ("clearance", "film", "temperature")


def _worded(detail):
    """A web error line with its leading parameter name as the page labels the field."""
    name, sep, rest = detail.partition(": ")
    if sep and name in FIELDS:
        return f"{FIELDS[name].title}: {rest}"
    return detail


def _resultant(values):
    """F_r = |(F_x, F_y)| as text in N (the form's F_x and F_y; a bad one is reported by its section)."""
    from ..units import parse_quantity

    try:
        fx, fy = (parse_quantity(values.get(k) or "0 N", "force", k) for k in ("fx", "fy"))
    except Exception:  # noqa: BLE001 -- the load sections name the bad field
        return values.get("fx") or values.get("fy")
    return f"{math.hypot(fx, fy)!r} N"


def _label(name):
    field = FIELDS.get(name)
    return field.title if field else ("Bearing" if name == "bearing" else name.replace("_", " "))


async def _section(section, values, server, lists=None):
    reason = _left_out(section, values, lists)
    if reason:
        return {"section": section, "document": None, "message": "", "left_out": reason, "figure": "",
                "query": {}}
    query = _query(section, values)
    status, doc = await server.compute(section.calculation, query)
    if (status == 422 and doc.get("parameter") == "temperature" and "'auto'" in doc.get("detail", "")
            and str(values.get("temperature")).strip() == "auto"):
        # 'auto' (the thermal balance's temperature) is the film's; a calculation that does not take
        # it yet is left out rather than marking the field the film section reads
        return {"section": section, "document": None, "message": "", "figure": "", "query": {},
                "left_out": f"Left out: {section.title.lower()} takes no oil temperature 'auto' yet; "
                            "give the temperature (the operating temperature section computes one)."}
    name = doc.get("parameter") if status == 422 and doc.get("error") == "input" else ""
    if name != "" and name not in query and name not in values and (
            name is not None or section.key in _DATA_SECTIONS):
        # what is missing or out of range is nothing the user gave (the film's groove conformities,
        # SKF's constants of an angular-contact bearing, a clearance the fits turned into a
        # preload): the section does not apply as it stands; an error of a field the user filled
        # is shown at that field
        return {"section": section, "document": None, "message": "", "figure": "", "query": {},
                "left_out": f"Left out: {_worded(doc['detail'])}"}
    if status == 422 and section.key == "friction" and doc.get("parameter") == "model":
        # the model has no constants for this bearing (SKF's are for deep-groove bearings): the
        # section does not apply; it is no error of the form
        return {"section": section, "document": None, "message": "", "figure": "", "query": {},
                "left_out": f"Left out: {doc['detail'].removeprefix('model: ')}."}
    result = {"section": section, "document": doc if status == 200 else None, "left_out": "",
              "message": "" if status == 200 else doc["detail"], "figure": "", "query": query,
              "parameter": None if status == 200 else doc.get("parameter"), "error": doc}
    if section.key == "shaft" and status != 200:  # its fields by the page's names, not the form's model
        result["parameter"] = {v: k for k, v in _shaft.FORM.items()}.get(result["parameter"], result["parameter"])
        result["message"] = result["message"].replace("model: ", "Shaft system: ", 1)
    if status == 200 and section.key in ("high-speed", "load-distribution", "shaft"):
        result["figure"] = await _figure(section, query, server, lists or {})
    return result


async def _figure(section, query, server, lists=None):
    fig_query = dict(query)
    if section.key == "high-speed" and not {"axial_load", "speed"} & set(lists or {}):
        # one case: the map around it, a tenth to twice the thrust (lists: the map of the cases given)
        try:
            from ..units import parse_quantity

            fa = parse_quantity(query["axial_load"], "force", "axial_load")
            n = parse_quantity(query["speed"], "speed", "speed")
        except Exception:  # noqa: BLE001 -- no figure; the numbers stand
            return ""
        step = fa / 10.0
        fig_query["axial_load"] = f"{step:.6g}N:{20 * step:.6g}N:{step:.6g}N"
        fig_query["speed"] = f"0 rpm; {query['speed']}" if n > 0 else query["speed"]
    status, svg = await server.compute(section.calculation, fig_query, what="figure")
    return svg if status == 200 and isinstance(svg, str) else ""


def _inputs(values):
    """The inputs as the report lists them: (label, value as given)."""
    out = [("Bearing", values.get("bearing") or "inline")]
    for k, field in FIELDS.items():
        if _given(values, k):
            text = str(values[k])
            if field.kind == "document":  # the pasted document is summarised, not printed whole
                text = f"pasted, {len(text.strip().splitlines())} lines"
            out.append((field.title, text))
    return out + _shaft.inputs(values)


async def render_context(values, server):
    """What the page template shows for the form ``values``.

    Parameters
    ----------
    values : dict of str to str
        The query of the page.
    server : object
        Has ``async compute(name, given, request=None, what=...)`` -> (status, document).

    Returns
    -------
    dict
        ``fields``, ``groups``, ``values``, ``submitted``, ``results`` (one dict per section),
        ``errors`` (field -> message in the page's words), ``inputs``, ``date``, ``links``,
        ``lists_note`` (the cases of a list or range, and how the sections show them; '' without one).
    """
    values = {k: v for k, v in values.items() if k in FIELDS or k == "bearing" or k in _shaft.FORM}
    submitted = any(_given(values, k) for k in values)
    lists = _lists(values) if submitted else {}
    results = []
    if submitted:
        results = list(await asyncio.gather(*(_section(s, values, server, lists) for s in sections())))
    errors = {}
    for r in results:
        name = r.get("parameter")
        if r["message"] and name and (name in FIELDS or name == "bearing"):
            detail = r["message"]
            if detail.startswith(name):  # the field named as the page names it
                detail = _label(name) + detail[len(name):]
            errors.setdefault(name, detail)
            r["message"] = detail
    for r in results:
        if r["document"] is not None:
            q = urllib.parse.urlencode(r["query"])
            path = r["section"].calculation
            r["links"] = {"json": f"/api/{path}?{q}", "csv": f"/csv/{path}?{q}"}
    return {
        "fields": FIELDS, "groups": _GROUPS, "examples": _EXAMPLES, "values": values,
        "submitted": submitted, "results": results, "errors": errors, "inputs": _inputs(values),
        "lists_note": lists_note(lists),
        "shaft_editor": _shaft.editor(values.get("shaft") or ""),
        "date": datetime.datetime.now(datetime.UTC).strftime("%Y-%m-%d %H:%M UTC"),
        "geometry_open": not values.get("bearing") or any(
            _given(values, f.name) for f in GEOMETRY),
        # the groups folded in <details>, and whether each is open (no bearing, or a value given)
        "folded": {g: (g == "geometry" and not values.get("bearing")) or any(
            _given(values, f.name) for f in FIELDS.values()
            if f.group == g and f.name not in ("seed", "distribution", "loads_at"))
            for g in ("geometry", "mounting", "film", "heat")},
    }


def to_csv(document):
    """A document as CSV text: ``quantity,value,unit`` rows, then each table of cases as rows.

    Parameters
    ----------
    document : dict or list
        A calculation's JSON document.

    Returns
    -------
    str
    """
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    rows = document if isinstance(document, list) else None
    if isinstance(document, dict):
        writer.writerow(["quantity", "value", "unit"])
        for key, value in document.items():
            if isinstance(value, list) and value and all(_is_number(v) for v in value):
                value = ", ".join(repr(v) for v in value)  # a range such as a probable interference
            elif isinstance(value, (dict, list)):
                continue
            _label_text, unit = quantity(key)
            writer.writerow([key, value, unit])
        for key, value in _nested(document):
            writer.writerow([key, value, quantity(key)[1]])
        for label, unit, cells in chain_rows(document):
            for column, value in zip(CHAIN_COLUMNS, cells):
                writer.writerow([f"chain {column} {label}", value, unit])
        for label, value, unit in percentile_rows(document):
            writer.writerow([f"monte carlo {label}", value, unit])
        for note in document.get("warnings") or []:
            writer.writerow(["warning", note, ""])
        for key, value in document.items():
            if isinstance(value, list) and value and isinstance(value[0], dict):
                rows = value
                writer.writerow([])
                writer.writerow([key])
                break
    if rows and isinstance(rows[0], dict):
        keys = list(rows[0])
        writer.writerow(keys)
        for row in rows:
            writer.writerow([row.get(k) if not isinstance(row.get(k), (dict, list)) else "" for k in keys])
    return out.getvalue()


def _is_number(value):
    return isinstance(value, (int, float)) and not isinstance(value, bool)


#: Keys of a document that are not result rows: the echo of the bearing and the inputs, and the
#: nested tables shown by :func:`chain_rows` and :func:`percentile_rows`.
_NOT_ROWS = ("warnings", "geometry", "bearing", "inputs", "chain", "monte_carlo")


def _nested(document):
    """(key, value) of the numbers one level down in a document's mappings (``ring_diameters_mm``
    -> ``ring_diameters_inner_raceway_mm``), and the lubricant a film or thermal balance used."""
    out = []
    for key, value in document.items():
        if key in _NOT_ROWS or not isinstance(value, dict):
            continue
        label, unit = quantity(key)
        suffix = key[len(label):] if unit else ""
        for sub, v in value.items():
            if _is_number(v):
                out.append((f"{key[:len(key) - len(suffix)]}_{sub}{suffix}", v))
    inputs = document.get("inputs")
    if isinstance(inputs, dict):
        for sub in ("lubricant", "dynamic_viscosity_mPas"):
            if inputs.get(sub) is not None:
                out.append((sub, inputs[sub]))
    return out


def value_rows(document):
    """The rows of a section's table of values: (label, text, unit, css class ``num``, ``txt`` or
    ``list``).

    Every scalar of the document, ranges of numbers (``4.77, 18.2``), the numbers of nested
    mappings and the lubricant used; the bearing's echo, the warnings and the tables shown apart
    (cases, the clearance chain, the Monte Carlo) are left out.

    Parameters
    ----------
    document : mapping
        A calculation's JSON document.

    Returns
    -------
    list of tuple
    """
    sc = scales(document)
    rows = []
    chained = isinstance(document.get("chain"), dict)
    for key, value in document.items():
        if key in _NOT_ROWS or isinstance(value, dict) or chained and key in _IN_CHAIN:
            continue
        label, unit = quantity(key)
        if isinstance(value, list):
            if not value or not all(_is_number(v) for v in value):
                continue  # a table of cases, shown as rows
            scale = max(_magnitude(v) for v in value)
            # a line may break between the values, never inside one (no-break spaces in '1 × 10⁻⁵')
            text = ", ".join(number(v, scale).replace(" ", "\u00a0") for v in value)
            rows.append((label, text, unit, "list"))
            continue
        css = "num" if _is_number(value) else "txt"
        rows.append((label, number(value, sc.get(key, 0.0)), unit, css))
    nested = dict(_nested(document))
    nsc = scales(nested)
    for key, value in nested.items():
        label, unit = quantity(key)
        rows.append((label, number(value, nsc[key]), unit, "num" if _is_number(value) else "txt"))
    return rows


def case_rows(document):
    """A document that is a list of cases (film, temperature at a list of speeds) as a table: one row per
    case, the inputs that differ between the cases first (the speed), then the case's scalars.

    Parameters
    ----------
    document : list of mapping
        The cases.

    Returns
    -------
    tuple
        ``(rows, warnings)``: the rows (mappings of key -> value) and the cases' warnings, each once.
    """
    cases = [c for c in document if isinstance(c, dict)] if isinstance(document, list) else []
    echoes = [c.get("inputs") if isinstance(c.get("inputs"), dict) else {} for c in cases]
    varying = [k for k, v in (echoes[0] if echoes else {}).items()
               if _is_number(v) and any(e.get(k) != v for e in echoes)]
    rows = [{**{k: e.get(k) for k in varying},
             **{k: v for k, v in c.items() if k != "warnings" and not isinstance(v, (dict, list))}}
            for c, e in zip(cases, echoes)]
    warnings = list(dict.fromkeys(w for c in cases for w in c.get("warnings") or ()))
    return rows, warnings


#: The clearance chain: its stages in order, as (key, label, unit); then its columns.
#: the scalars of a ``clearance`` document that its chain table shows (as least / probable / largest):
#: not repeated as rows, so the printed report stays on two pages
_IN_CHAIN = frozenset(f"{k}_um" for k in (
    "interference_inner_min", "interference_inner_max", "interference_outer_min", "interference_outer_max",
    "fit_reduction_min", "fit_reduction_max", "thermal_reduction", "centrifugal_reduction",
    "unmounted_clearance_min", "unmounted_clearance_max", "operating_clearance_min",
    "operating_clearance_max", "operating_clearance_probable")) | {"fit_pressure_inner_MPa",
                                                                   "fit_pressure_outer_MPa"}
CHAIN = (
    ("unmounted_clearance", "unmounted clearance", "µm"),
    ("inner_interference", "inner interference", "µm"),
    ("outer_interference", "outer interference", "µm"),
    ("fit_reduction", "− fit reduction", "µm"),
    ("thermal_reduction", "− thermal reduction", "µm"),
    ("centrifugal_reduction", "− centrifugal reduction", "µm"),
    ("operating_clearance", "= operating clearance", "µm"),
    ("inner_operating_interference", "inner interference at speed", "µm"),
    ("outer_operating_interference", "outer interference at temperature", "µm"),
    ("inner_pressure", "inner fit pressure", "MPa"),
    ("outer_pressure", "outer fit pressure", "MPa"),
    ("inner_loosened_by_speed", "inner fit loosened by speed", ""),
)
CHAIN_COLUMNS = ("least", "probable", "largest")


def chain_rows(document):
    """The mounted-clearance chain of a ``clearance`` document as rows of least / probable / largest.

    Parameters
    ----------
    document : mapping
        A ``clearance`` document (any other gives no rows).

    Returns
    -------
    list of (label, unit, [least, probable, largest])
        Raw values (the page formats them with :func:`number`); a stage the document does not
        hold is left out.
    """
    chain = document.get("chain") if isinstance(document, dict) else None
    if not isinstance(chain, dict) or not all(isinstance(chain.get(c), dict) for c in CHAIN_COLUMNS):
        return []
    return [(label, unit, [chain[c].get(key) for c in CHAIN_COLUMNS]) for key, label, unit in CHAIN
            if any(key in chain[c] for c in CHAIN_COLUMNS)]


def percentile_rows(document):
    """The Monte Carlo study of a ``clearance`` document: (label, value, unit) rows.

    Parameters
    ----------
    document : mapping
        A ``clearance`` document; without ``monte_carlo`` there are no rows.

    Returns
    -------
    list of tuple
        The operating clearance's percentiles, mean and standard deviation [µm], the probability of
        a negative clearance, the samples, the seed and the distribution.
    """
    mc = document.get("monte_carlo") if isinstance(document, dict) else None
    if not isinstance(mc, dict):
        return []
    rows = [(f"operating clearance {p}", v, "µm") for p, v in (mc.get("percentiles_um") or {}).items()]
    for key in ("mean_um", "std_um"):
        if key in mc:
            rows.append((f"operating clearance {quantity(key)[0]}", mc[key], "µm"))
    if "probability_negative_clearance" in mc:
        rows.append(("P(clearance < 0)", mc["probability_negative_clearance"], ""))
    rows += [(k, mc[k], "") for k in ("samples", "seed", "distribution") if k in mc]
    return rows


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
    from ..tables import quantity as label_and_unit  # the one table of unit suffixes

    return label_and_unit(key)


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


# ----------------------------------------------------------------------------- deprecated (0.2)
class Result(NamedTuple):
    """A section's outcome (deprecated: :func:`render_context` gives dicts)."""

    section: Section
    document: object
    message: str
    figure: str


class _InProcess:
    """Runs calculations in this process (for the deprecated synchronous functions)."""

    async def compute(self, name, given, request=None, *, what="document"):
        from .. import calculations
        from .api import web_error

        try:
            parsed = calculations.parse(name, given)
            value = calculations.figure_svg(parsed) if what == "figure" else calculations.run(parsed)
        except calculations.RequestError as exc:
            return web_error(exc)
        return 200, value


def _warn(name):
    import warnings

    warnings.warn(f"bearinglab.web.page.{name} is deprecated; use render_context", DeprecationWarning,
                  stacklevel=3)


def compute(values):
    """Deprecated: every section for the form ``values``, computed in this process.

    Parameters
    ----------
    values : dict of str to str
        The form.

    Returns
    -------
    results : list of Result
    field_errors : dict of str to str
    """
    _warn("compute")
    context = asyncio.run(render_context(values, _InProcess()))
    results = [Result(r["section"], r["document"], r["message"] or r["left_out"], r["figure"])
               for r in context["results"]]
    return results, context["errors"]


def figure_svg(endpoint, query):
    """Deprecated: the calculation's figure as SVG text, or ''.

    Parameters
    ----------
    endpoint : str
        A calculation name.
    query : dict
        Its parameters.

    Returns
    -------
    str
    """
    _warn("figure_svg")
    from .. import calculations

    try:
        return calculations.figure_svg(calculations.parse(endpoint, query))
    except calculations.RequestError:
        return ""
