"""The shaft-system section of the calculator page: its editor's tables, its request and its results.

The page edits a shaft system (issue 33) as tables of sections, supports, loads and gears, drawn to scale
as the user types (``static/shaft.js``), and posts the file those tables make, as TOML text, in the form
field ``shaft``: the document field ``model`` of the calculation ``shaft``, computed as every section of
the page is. A file uploaded into the editor is the same text: the page reads it back into the tables
here (:func:`editor`), so the browser needs no TOML reader. What the tables do not show (the speed, the
material, the lubricant, masses, pulleys, load cases, user bearings, a support's housing ...) stays in
the file's other lines, which the editor shows as TOML and composes with the tables unchanged; a key of
a table row that has no column of its own (a support's ``orientation``, a gear's ``rotation``) stays in
that row's *more* cell.

Form and request
----------------
FORM        the page's fields of this section -> the calculation's field each gives
FIELDS      the calculation's fields, by name (their help on the page)
TABLES      the editor's tables: key -> (title, columns); a column is (key, label, placeholder)
KINDS       the kinds of support of the editor -> the key of the file that gives each
editor      the shaft file's text -> the tables' rows and the other lines (for the template)
query       the page's values -> the request of the calculation ``shaft``
left_out    why the section does not apply (no shaft given), or ''
inputs      the report's lines of inputs of this section

Results (the command line's tables, :mod:`bearinglab.cli.shaft`)
-----------------------------------------------------------------
summary_rows   the system: lives, stiffness at a point, natural frequencies, convergence
support_rows   each support's load, displacement and tilt
bearing_rows   each bearing's load, lives, static safety factor and largest contact pressure
"""

from __future__ import annotations

import json
import math
import re

from ..calculations import CALCULATIONS

__all__ = ["FIELDS", "FORM", "KINDS", "TABLES", "bearing_rows", "editor", "inputs", "left_out", "query", "summary_rows",
           "support_rows"]

#: The page's fields of the shaft section -> the field of the calculation ``shaft`` (the page's own names:
#: ``model`` and ``speed`` are other fields of the form).
FORM = {"shaft": "model", "shaft_stiffness_at": "stiffness_at", "shaft_modes": "modes"}
#: The fields of the calculation ``shaft``, by name.
FIELDS = {f.name: f for f in CALCULATIONS["shaft"].fields}

#: The editor's tables: the file's array of tables -> (title, columns); each column (key, label, placeholder).
#: A support's ``kind`` picks its key: ``bearing``, ``bearing_set`` (``value`` the bearing, with
#: ``arrangement`` and ``preload``), ``radial_stiffness`` (``value`` the stiffness) or ``rigid``.
TABLES = {
    "sections": ("Sections, from z = 0", (("length", "Length", "60 mm"), ("diameter", "Diameter", "40 mm"),
                                          ("bore", "Bore", "0 mm"))),
    "supports": ("Supports", (("name", "Name", "A"), ("position", "Position", "20 mm"),
                              ("kind", "Kind", ""), ("value", "Bearing or stiffness", "6206"),
                              ("arrangement", "Set", "DB"), ("preload", "Preload", "500 N"),
                              ("axial", "Locates axially", ""))),
    "loads": ("Loads", (("name", "Name", "F"), ("position", "Position", "150 mm"), ("fx", "F_x", "1 kN"),
                        ("fy", "F_y", "0 N"), ("fz", "F_z", "0 N"), ("mx", "M_x", "0 N*m"),
                        ("my", "M_y", "0 N*m"))),
    "gears": ("Gears", (("name", "Name", "G"), ("position", "Position", "80 mm"),
                        ("pitch_diameter", "Pitch diameter", "120 mm"), ("pressure_angle", "Pressure angle", "20 deg"),
                        ("helix_angle", "Helix angle", "0 deg"), ("torque", "Torque", "100 N*m"),
                        ("power", "Power", "5 kW"), ("mesh_angle", "Mesh angle", "0 deg"))),
}
#: the kinds of support (the editor's choice) -> the key of the file that gives it
KINDS = {"bearing": "bearing", "set": "bearing_set", "linear": "radial_stiffness", "rigid": "rigid"}
_BARE = re.compile(r"^[A-Za-z0-9_-]+$")


def _key(name):
    return name if _BARE.match(name) else json.dumps(name)


def _value(v):
    """A value as TOML writes it: a string, number, flag, array or inline table."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, float) and not math.isfinite(v):  # TOML's spelling, not JSON's NaN
        return "nan" if math.isnan(v) else ("inf" if v > 0 else "-inf")
    if isinstance(v, (int, float)):
        return repr(v)
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{_key(k)} = {_value(x)}" for k, x in v.items()) + " }"
    if isinstance(v, list):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    return json.dumps(str(v), ensure_ascii=False)  # a JSON string is a TOML basic string


def _lines(table, prefix=""):
    """The keys of a table as TOML lines, a sub-table as dotted keys (``housing.radial_stiffness = ...``)."""
    out = []
    for k, v in table.items():
        if isinstance(v, dict) and v:
            out += _lines(v, f"{prefix}{_key(k)}.")
        else:
            out.append(f"{prefix}{_key(k)} = {_value(v)}")
    return out


def _is_rows(v):
    return isinstance(v, list) and bool(v) and all(isinstance(x, dict) for x in v)


def _other_lines(doc):
    """The file without the editor's tables, as TOML: top-level keys, tables, then arrays of tables."""
    rest = {k: v for k, v in doc.items() if k not in TABLES}
    lines = [f"{_key(k)} = {_value(v)}" for k, v in rest.items() if not isinstance(v, dict) and not _is_rows(v)]
    for k, v in rest.items():
        if isinstance(v, dict):
            if v and all(isinstance(x, dict) for x in v.values()):  # [bearings."NAME"]
                for name, sub in v.items():
                    lines += ["", f"[{_key(k)}.{_key(name)}]", *_lines(sub)]
            else:
                lines += ["", f"[{_key(k)}]", *_lines(v)]
    for k, v in rest.items():
        if _is_rows(v):
            for row in v:
                lines += ["", f"[[{_key(k)}]]", *_lines(row)]
    return "\n".join(lines).strip() + ("\n" if lines else "")


def _text(v):
    return "" if v is None else (v if isinstance(v, str) else _value(v))


def _support_row(t):
    t = dict(t)
    row = {"name": _text(t.pop("name", "")), "position": _text(t.pop("position", ""))}
    kind = next((k for k, key in KINDS.items() if key in t), "bearing")
    row["kind"] = kind
    row["axial"] = t.pop("axial", kind == "set") is True  # the editor writes it, true or false
    row["value"] = row["arrangement"] = row["preload"] = ""
    if kind == "bearing" and isinstance(t.get("bearing"), str):
        row["value"] = t.pop("bearing")
    elif kind == "set" and isinstance(t.get("bearing_set"), dict):
        s = dict(t.pop("bearing_set"))
        if isinstance(s.get("bearing"), str):
            row["value"] = s.pop("bearing")
        row["arrangement"] = _text(s.pop("arrangement", ""))
        row["preload"] = _text(s.pop("preload", ""))
        if s:
            t["bearing_set"] = s
    elif kind == "linear":
        row["value"] = _text(t.pop("radial_stiffness"))
    elif kind == "rigid":
        t.pop("rigid")  # the editor writes rigid = true
    row["more"] = "\n".join(_lines(t))
    return row


def _row(name, t):
    if name == "supports":
        return _support_row(t)
    t, row = dict(t), {}
    for key, _label, _example in TABLES[name][1]:
        held = key in t and not isinstance(t[key], (dict, list))  # a list or table stays in the row's lines
        row[key] = _text(t.pop(key)) if held else ""
    row["more"] = "\n".join(_lines(t))
    return row


def editor(text):
    """The shaft file's text as the editor shows it.

    Parameters
    ----------
    text : str
        The file (TOML or JSON), as posted by the page or uploaded; '' for none.

    Returns
    -------
    dict
        ``tables`` (key of :data:`TABLES` -> list of rows, each a dict of the columns' texts, ``axial`` a
        flag, and ``more``: the row's other keys as TOML lines), ``other`` (the file's other lines as
        TOML), ``error`` ('' or why the text is no shaft file the tables can show: then ``other`` is the
        text as given, so that nothing typed is lost).

    Examples
    --------
    >>> e = editor('speed = "3000 rpm"\\n[[supports]]\\nname = "A"\\nposition = "20 mm"\\nbearing = "6206"\\n'
    ...            'orientation = "-z"\\n')
    >>> e["tables"]["supports"][0]["value"], e["tables"]["supports"][0]["more"], e["other"]
    ('6206', 'orientation = "-z"', 'speed = "3000 rpm"\\n')
    """
    from .._bounds import parse_document

    empty = {name: [] for name in TABLES}
    if not isinstance(text, str) or not text.strip():
        return {"tables": empty, "other": "", "error": ""}
    try:
        doc = parse_document(text, "shaft")
    except Exception as exc:  # noqa: BLE001 -- any reader's error: the text stays as typed, the section says why
        return {"tables": empty, "other": text, "error": f"not a TOML or JSON document ({exc})"}
    if not isinstance(doc, dict) or not all(isinstance(doc.get(k, []), list) and all(
            isinstance(t, dict) for t in doc.get(k, [])) for k in TABLES):
        return {"tables": empty, "other": text, "error": "the tables are not arrays of tables ([[sections]] ...)"}
    tables = {name: [_row(name, t) for t in doc.get(name, [])] for name in TABLES}
    return {"tables": tables, "other": _other_lines(doc), "error": ""}


def query(values):
    """The request of the calculation ``shaft`` from the page's values (:data:`FORM`; empty ones left out).

    Parameters
    ----------
    values : dict of str to str

    Returns
    -------
    dict
    """
    return {field: values[name] for name, field in FORM.items() if str(values.get(name) or "").strip()}


def left_out(values):
    """Why the shaft section does not apply ('' where it does).

    Parameters
    ----------
    values : dict of str to str

    Returns
    -------
    str
    """
    if not str(values.get("shaft") or "").strip():
        return ("Left out: no shaft system given; edit one in the form's Shaft system tables, or upload its "
                "TOML file.")
    return ""


def inputs(values):
    """The report's inputs of this section: (label, value) pairs, the file summarised.

    Parameters
    ----------
    values : dict of str to str

    Returns
    -------
    list of tuple
    """
    text = str(values.get("shaft") or "").strip()
    if not text:
        return []
    out = [("Shaft system", f"{len(text.splitlines())} lines of TOML")]
    for name, label in (("shaft_stiffness_at", "Stiffness at"), ("shaft_modes", "Natural modes")):
        if str(values.get(name) or "").strip():
            out.append((label, str(values[name]).strip()))
    return out


# ----------------------------------------------------------------------------- results
def summary_rows(doc):
    """The system's rows: (label, value, unit), the values as the document holds them.

    Parameters
    ----------
    doc : dict
        A document of :func:`bearinglab.calculations.shaft.document`.

    Returns
    -------
    list of tuple
    """
    s = doc["shaft"]
    rows = [("shaft length", s["length_mm"], "mm"), ("shaft mass", s["mass_kg"], "kg"),
            ("speed", doc["speed_rpm"], "rpm")]
    lives = doc.get("system_lives_h") or {}
    for key, label in (("basic_rating_life_h", "system life L10h"), ("modified_rating_life_h", "system life L_nmh"),
                       ("reference_rating_life_h", "system life L10rh (ISO/TS 16281)"),
                       ("modified_reference_rating_life_h", "system life L_nmrh")):
        if lives.get(key) is not None or key == "basic_rating_life_h":
            rows.append((label, lives.get(key), "h"))
    k = doc.get("stiffness_at")
    if k:
        at = f"z = {k['position_mm']:g} mm"
        rows += [(f"stiffness at {at}: k_x", k["stiffness_x_N_per_um"], "N/µm"),
                 (f"stiffness at {at}: k_y", k["stiffness_y_N_per_um"], "N/µm"),
                 (f"stiffness at {at}: k_z", k["stiffness_z_N_per_um"], "N/µm")]
    for i, f in enumerate(doc.get("natural_frequencies_Hz") or []):
        whirl = ((doc.get("modes") or [{}] * (i + 1))[i] or {}).get("whirl")
        rows.append((f"natural frequency {i + 1}" + (f" ({whirl})" if whirl else ""), f, "Hz"))
    conv = doc["convergence"]
    rows += [("equilibrium, relative error", doc["equilibrium"]["relative_error"], ""),
             ("converged", conv["converged"], ""), ("iterations", conv["iterations"], "")]
    return rows


def support_rows(doc):
    """Each support: name, z [mm], F_x, F_y, F_z [kN], M_x, M_y [N·m], δ_x, δ_y [µm], θ_x, θ_y [mrad], and
    the scale of each column (the largest value of its unit in the table: float noise below it shows as
    0, :func:`bearinglab.web.page.number`).

    Parameters
    ----------
    doc : dict

    Returns
    -------
    tuple of (list of list, list of float)
        The rows (the name, then the numbers in the units of the header) and the scale of each column.
    """
    rows = []
    for p in doc["supports"]:
        rows.append([p["name"], p["position_mm"], *(None if p[k] is None else p[k] / 1e3
                                                    for k in ("force_x_N", "force_y_N", "force_z_N")),
                     p["moment_x_Nm"], p["moment_y_Nm"], p["displacement_x_um"], p["displacement_y_um"],
                     p["tilt_x_mrad"], p["tilt_y_mrad"]])

    def largest(columns):
        return max((abs(r[c]) for r in rows for c in columns if isinstance(r[c], float)), default=0.0)

    units = [(), (1,), (2, 3, 4), (2, 3, 4), (2, 3, 4), (5, 6), (5, 6), (7, 8), (7, 8), (9, 10), (9, 10)]
    return rows, [largest(c) for c in units]


def bearing_rows(doc):
    """Each bearing: support, designation, P [kN], L10h, L_nmh, L10rh [h], s0, p_max [MPa].

    Parameters
    ----------
    doc : dict

    Returns
    -------
    list of list
    """
    out = []
    for p in doc["supports"]:
        bearings = p.get("bearings") or []
        for j, b in enumerate(bearings):
            load = b["equivalent_dynamic_load_N"]
            out.append([p["name"] + (f" {j + 1}" if len(bearings) > 1 else ""), b["bearing"],
                        None if load is None else load / 1e3, b["basic_rating_life_h"], b["modified_rating_life_h"],
                        b["reference_rating_life_h"], b["static_safety_factor"], b["max_contact_pressure_MPa"]])
    return out
