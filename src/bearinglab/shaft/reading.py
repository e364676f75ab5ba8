r"""The shaft-system file: a TOML (or JSON) document -> the model, checked field by field.

Reading
-------
ShaftDocument   the system, its load cases with their time shares, the lubricant of the lives
from_text       TOML or JSON text -> ShaftDocument
from_dict       the parsed document -> ShaftDocument
load            a file (TOML, or JSON by its ``.json`` suffix) -> ShaftDocument
KEYS            the keys of each table, for the web's tables and the user guide

The format (docs/user_guide/shaft_systems.md has a whole example)::

    speed = "3000 rpm"                 # optional; its sign is the sense of rotation about +z
    gravity = "-y"                     # optional: the shaft's own weight, towards +x -x +y -y +z -z
    elements = 30                      # optional: at least this many elements over the length
    shaft_temperature = "45 degC"      # optional: with housing_temperature, the axial growth and
    housing_temperature = "30 degC"    # the bearings' clearances (the mounting chain)
    housing_material = "steel"         # for the temperatures: steel, structural_steel, aluminium

    [material]                         # material = "steel" (bearinglab.mounting.materials), or
    elastic_modulus = "210 GPa"        # elastic_modulus, poisson_ratio, density and, for the
    poisson_ratio = 0.3                # temperatures, thermal_expansion = "12e-6 1/K"
    density = "7850 kg/m^3"

    [[sections]]                       # in order from z = 0
    length = "60 mm"
    diameter = "70 mm"
    bore = "30 mm"                     # optional; start = "0 mm" optional (checked)

    [[supports]]
    name = "front"
    position = "100 mm"
    bearing_set = { bearing = "7014 C", arrangement = "DB", preload = "500 N" }  # spacing, preload_offset
    # or: bearing = "6012" with axial = true|false, orientation = "+z"|"-z", axial_offset = "5 um",
    #     housing = { radial_stiffness = "500 N/um", axial_stiffness = "...", tilt_stiffness = "..." }
    # or: radial_stiffness = "200 N/um" (axial_stiffness, tilt_stiffness = "1e5 N*m/rad", axial)
    # or: rigid = true (axial)

    [[loads]]                          # position, fx, fy, fz, mx, my, mz, name
    position = "0 mm"
    fx = "1 kN"

    [[gears]]                          # position, pitch_diameter, pressure_angle (20 deg),
    position = "200 mm"                # helix_angle (0 deg, > 0 right hand), torque or power,
    pitch_diameter = "120 mm"          # mesh_angle (0 deg), rotation ("+z" or "-z"; default the
    power = "5 kW"                     # speed's sign), mass, polar_inertia, diametral_inertia

    [[pulleys]]                        # position, force (the belt pull), direction, torque, masses
    [[masses]]                         # position, mass, polar_inertia, diametral_inertia

    [[cases]]                          # a load spectrum: time_share, factor (on the loads, gears and
    time_share = 0.25                  # pulleys), speed; the shares sum to 1
    factor = 1.5

    [lubricant]                        # for L_nm: viscosity, or oil ("VG68") with temperature;
    viscosity = "20 cSt"               # contamination (a class or e_C), reliability ("90 %")

    [bearings."MY-BEARING"]            # user bearings, in the catalog's format (bearinglab.catalog)

Units: every dimensional value is a string with its unit, read by :mod:`bearinglab.units` ("25 mm",
"3 kN", "3000 rpm", "200 N/um", "1e5 N*m/rad", "5 kW", "45 degC"); a bare number there is refused with
the field's name, because a number without a unit is the commonest error in such files. Plain numbers
are the dimensionless values: ``poisson_ratio``, ``elements``, ``factor``, ``time_share`` (or "25 %"),
``viscosity_index``, a contamination factor, ``reliability`` (or "90 %"). Every error is one line that
names the table and the field (``supports[1] (rear).bearing: ...``).
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import NamedTuple

import numpy as np

from ..errors import InputError
from ..units import KINDS, parse_quantity
from . import model

__all__ = ["KEYS", "ShaftDocument", "from_dict", "from_text", "load"]

#: the keys of each table of the file
KEYS = {
    "": ("speed", "gravity", "elements", "shaft_temperature", "housing_temperature", "housing_material",
         "material", "sections", "supports", "loads", "gears", "pulleys", "masses", "cases", "lubricant",
         "bearings", "name", "description"),
    "material": ("material", "elastic_modulus", "poisson_ratio", "density", "thermal_expansion"),
    "sections": ("length", "diameter", "bore", "start"),
    "supports": ("name", "position", "bearing", "bearing_set", "orientation", "axial", "axial_offset", "housing",
                 "radial_stiffness", "axial_stiffness", "tilt_stiffness", "rigid"),
    "bearing_set": ("bearing", "arrangement", "spacing", "preload", "preload_offset"),
    "housing": ("radial_stiffness", "axial_stiffness", "tilt_stiffness"),
    "loads": ("name", "position", "fx", "fy", "fz", "mx", "my", "mz"),
    "gears": ("name", "position", "pitch_diameter", "pressure_angle", "helix_angle", "torque", "power",
              "mesh_angle", "rotation", "mass", "polar_inertia", "diametral_inertia"),
    "pulleys": ("name", "position", "force", "direction", "torque", "mass", "polar_inertia", "diametral_inertia"),
    "masses": ("name", "position", "mass", "polar_inertia", "diametral_inertia"),
    "cases": ("name", "time_share", "factor", "speed"),
    "lubricant": ("viscosity", "oil", "temperature", "viscosity_index", "viscosity_100", "contamination",
                  "reliability"),
}
_GRAVITY = {"+x": (1, 0, 0), "-x": (-1, 0, 0), "+y": (0, 1, 0), "-y": (0, -1, 0), "+z": (0, 0, 1), "-z": (0, 0, -1)}
_STANDARD_GRAVITY = 9.80665  # m/s^2, bearinglab.units.STANDARD_GRAVITY
_MAX_CASES = 1000  # rows of a load spectrum in one file


class ShaftDocument(NamedTuple):
    """A shaft-system file, read and checked."""

    system: model.ShaftSystem
    """The model."""
    case_speed: np.ndarray | None
    """(k,) the load spectrum's speeds (signed), or None without [[cases]]. [rad/s]"""
    case_factor: np.ndarray | None
    """(k,) its factors on the loads, gears and pulleys. [-]"""
    time_share: np.ndarray | None
    """(k,) its shares of the time, summing to 1. [-]"""
    case_names: tuple
    """The cases' names."""
    lubricant: dict
    """Keyword arguments of :func:`bearinglab.life.rating_life` (kinematic_viscosity or the oil,
    contamination, reliability); empty without [lubricant]."""
    document: dict
    """The document as given."""


def _at(where, key):
    return f"{where}.{key}" if where else key


def _keys(table, kind, where):
    if not isinstance(table, dict):
        raise InputError(f"{where or 'document'}: expected a table, got {type(table).__name__}")
    unknown = [k for k in table if k not in KEYS[kind]]
    if unknown:
        raise InputError(f"{_at(where, unknown[0])}: unknown key; {where or 'the document'} takes "
                         f"{', '.join(KEYS[kind])}")


def _quantity(table, key, kind, where, default=None, required=False):
    if key not in table:
        if required:
            raise InputError(f"{_at(where, key)}: missing")
        return default
    value = table[key]
    name = _at(where, key)
    if isinstance(value, bool):
        raise InputError(f"{name}: expected a quantity with its unit, got {value!r}")
    if kind == "dimensionless":
        if isinstance(value, (int, float)):
            return float(value)
        return parse_quantity(value, "dimensionless", name)
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        example = KINDS[kind][2]
        raise InputError(f"{name}: {value!r} has no unit; write it as a string with its unit, e.g. {example}")
    if not isinstance(value, str):
        raise InputError(f"{name}: expected a quantity such as {KINDS[kind][2]}, got {value!r}")
    return parse_quantity(value, kind, name)


def _flag(table, key, where, default=False):
    v = table.get(key, default)
    if not isinstance(v, bool):
        raise InputError(f"{_at(where, key)}: expected true or false, got {v!r}")
    return v


def _text(table, key, where, default=""):
    v = table.get(key, default)
    if not isinstance(v, str):
        raise InputError(f"{_at(where, key)}: expected text, got {v!r}")
    return v


def _sense(table, key, where, default=None):
    if key not in table:
        return default
    v = table[key]
    if v in ("+z", "z", "+1", 1) and not isinstance(v, bool):
        return 1
    if v in ("-z", "-1", -1) and not isinstance(v, bool):
        return -1
    raise InputError(f"{_at(where, key)}: expected '+z' or '-z', got {v!r}")


def _array(doc, key):
    v = doc.get(key, [])
    if not isinstance(v, list):
        raise InputError(f"{key}: expected an array of tables ([[{key}]]), got {type(v).__name__}")
    if len(v) > (model.MAX_ITEMS if key != "sections" else model.MAX_ELEMENTS):
        raise InputError(f"{key}: at most {model.MAX_ITEMS if key != 'sections' else model.MAX_ELEMENTS}, got {len(v)}")
    return v


def _checked(where, build, *args, **kwargs):
    """``build(*args, **kwargs)``, naming ``where`` in the message of any InputError it raises."""
    try:
        return build(*args, **kwargs)
    except InputError as exc:
        message = str(exc)
        if message.startswith(where):
            raise
        raise InputError(f"{where}.{message}") from None


def _material(doc):
    table = doc.get("material", {"material": "steel"})
    _keys(table, "material", "material")
    from ..bearing import Material
    from ..mounting.materials import material as named

    if "material" in table:
        if len(table) > 1:
            raise InputError("material: give material = NAME or elastic_modulus, poisson_ratio and density, not both")
        try:
            m = named(_text(table, "material", "material"))
        except InputError as exc:
            raise InputError(f"material.{exc}") from None
        return Material(m.name, m.elastic_modulus, m.poisson_ratio, m.density), m.thermal_expansion
    e = _quantity(table, "elastic_modulus", "pressure", "material", required=True)
    nu = _quantity(table, "poisson_ratio", "dimensionless", "material", required=True)
    rho = _quantity(table, "density", "density", "material", required=True)
    alpha = _quantity(table, "thermal_expansion", "thermal_expansion", "material", default=model._STEEL_EXPANSION)
    try:
        return Material("shaft", e, nu, rho), alpha
    except InputError as exc:
        raise InputError(f"material.{exc}") from None


def _sections(doc):
    out = []
    for k, t in enumerate(_array(doc, "sections")):
        where = f"sections[{k}]"
        _keys(t, "sections", where)
        kw = {"length": _quantity(t, "length", "length", where, required=True),
              "diameter": _quantity(t, "diameter", "length", where, required=True),
              "bore": _quantity(t, "bore", "length", where, default=0.0)}
        if "start" in t:
            kw["start"] = _quantity(t, "start", "length", where)
        out.append(_checked(where, model.Section, **kw))
    return tuple(out)


def _bearing(value, where, user, catalog):
    from .. import catalog as _catalog

    if isinstance(value, dict):
        return _checked(where, _catalog.bearing_from_table, value, name=where)
    if not isinstance(value, str) or not value.strip():
        raise InputError(f"{where}: expected a bearing's name (e.g. '6206', '7014 C') or a table, got {value!r}")
    name = value.strip()
    if name in user:
        return user[name]
    try:
        return _catalog.get(name, catalog=catalog)
    except InputError as exc:
        raise InputError(f"{where}: {exc}") from None


def _housing(t, where):
    if "housing" not in t:
        return None
    h = t["housing"]
    w = f"{where}.housing"
    _keys(h, "housing", w)
    kw = {}
    for key, kind in (("radial_stiffness", "stiffness"), ("axial_stiffness", "stiffness"),
                      ("tilt_stiffness", "rotational_stiffness")):
        if key in h:
            kw[key] = _quantity(h, key, kind, w)
    return _checked(w, model.Housing, **kw)


def _supports(doc, user, catalog):
    out = []
    for k, t in enumerate(_array(doc, "supports")):
        where = f"supports[{k}]"
        if isinstance(t, dict) and isinstance(t.get("name"), str):
            where = f"supports[{k}] ({t['name']})"
        _keys(t, "supports", where)
        name = _text(t, "name", where, f"support {k + 1}")
        pos = _quantity(t, "position", "length", where, required=True)
        kinds = [key for key in ("bearing", "bearing_set", "radial_stiffness", "rigid") if key in t]
        if len(kinds) != 1:
            raise InputError(f"{where}: give one of bearing, bearing_set, radial_stiffness or rigid = true, got "
                             f"{', '.join(kinds) if kinds else 'none'}")
        kind = kinds[0]
        allowed = {"bearing": {"orientation", "axial", "axial_offset", "housing"},
                   "bearing_set": {"axial", "housing"},
                   "radial_stiffness": {"axial_stiffness", "tilt_stiffness", "axial"},
                   "rigid": {"axial"}}[kind] | {"name", "position", kind}
        extra = [key for key in t if key not in allowed]
        if extra:
            raise InputError(f"{_at(where, extra[0])}: does not apply to a support with {kind}")
        if kind == "bearing":
            b = _bearing(t["bearing"], f"{where}.bearing", user, catalog)
            sup = _checked(where, model.BearingSupport, name, pos, b, orientation=_sense(t, "orientation", where, 1),
                           axial=_flag(t, "axial", where), housing=_housing(t, where),
                           axial_offset=_quantity(t, "axial_offset", "length", where, default=0.0))
        elif kind == "bearing_set":
            s = t["bearing_set"]
            w = f"{where}.bearing_set"
            _keys(s, "bearing_set", w)
            names = s.get("bearing")
            names = names if isinstance(names, list) else [names]
            if not 1 <= len(names) <= 8:
                raise InputError(f"{w}.bearing: one to eight bearings, got {len(names)}")
            bl = tuple(_bearing(x, f"{w}.bearing", user, catalog) for x in names)
            kw = {"arrangement": _text(s, "arrangement", w, "DB"),
                  "spacing": _quantity(s, "spacing", "length", w),
                  "preload": _quantity(s, "preload", "force", w, default=0.0),
                  "preload_offset": _quantity(s, "preload_offset", "length", w)}
            sup = _checked(where, model.BearingSetSupport, name, pos, bl, **kw, axial=_flag(t, "axial", where, True),
                           housing=_housing(t, where))
        elif kind == "radial_stiffness":
            kw = {"radial_stiffness": _quantity(t, "radial_stiffness", "stiffness", where),
                  "axial_stiffness": _quantity(t, "axial_stiffness", "stiffness", where),
                  "tilt_stiffness": _quantity(t, "tilt_stiffness", "rotational_stiffness", where, default=0.0),
                  "axial": _flag(t, "axial", where)}
            sup = _checked(where, model.LinearSupport, name, pos, **kw)
        else:
            if t["rigid"] is not True:
                raise InputError(f"{where}.rigid: expected true (a simple support), got {t['rigid']!r}")
            sup = model.RigidSupport(name, pos, axial=_flag(t, "axial", where))
        out.append(sup)
    return tuple(out)


def _masses_of(t, where):
    kw = {"mass": _quantity(t, "mass", "mass", where, default=0.0),
          "polar_inertia": _quantity(t, "polar_inertia", "moment_of_inertia", where, default=0.0)}
    if "diametral_inertia" in t:
        kw["diametral_inertia"] = _quantity(t, "diametral_inertia", "moment_of_inertia", where)
    return kw


def _loads(doc):
    loads, gears, pulleys, masses = [], [], [], []
    for k, t in enumerate(_array(doc, "loads")):
        where = f"loads[{k}]"
        _keys(t, "loads", where)
        kw = {key: _quantity(t, key, "force" if key[0] == "f" else "torque", where, default=0.0)
              for key in ("fx", "fy", "fz", "mx", "my", "mz")}
        pos = _quantity(t, "position", "length", where, required=True)
        loads.append(_checked(where, model.PointLoad, pos, **kw, name=_text(t, "name", where)))
    for k, t in enumerate(_array(doc, "gears")):
        where = f"gears[{k}]"
        _keys(t, "gears", where)
        if ("torque" in t) == ("power" in t):
            raise InputError(f"{where}: give torque or power, one of the two")
        kw = {"pitch_diameter": _quantity(t, "pitch_diameter", "length", where, required=True),
              "pressure_angle": _quantity(t, "pressure_angle", "angle", where, default=math.radians(20.0)),
              "helix_angle": _quantity(t, "helix_angle", "angle", where, default=0.0),
              "torque": _quantity(t, "torque", "torque", where),
              "power": _quantity(t, "power", "power", where),
              "mesh_angle": _quantity(t, "mesh_angle", "angle", where, default=0.0),
              "rotation": _sense(t, "rotation", where), **_masses_of(t, where)}
        pos = _quantity(t, "position", "length", where, required=True)
        gears.append(_checked(where, model.Gear, pos, **kw, name=_text(t, "name", where)))
    for k, t in enumerate(_array(doc, "pulleys")):
        where = f"pulleys[{k}]"
        _keys(t, "pulleys", where)
        kw = {"force": _quantity(t, "force", "force", where, required=True),
              "direction": _quantity(t, "direction", "angle", where, default=0.0),
              "torque": _quantity(t, "torque", "torque", where, default=0.0), **_masses_of(t, where)}
        pos = _quantity(t, "position", "length", where, required=True)
        pulleys.append(_checked(where, model.Pulley, pos, **kw, name=_text(t, "name", where)))
    for k, t in enumerate(_array(doc, "masses")):
        where = f"masses[{k}]"
        _keys(t, "masses", where)
        kw = _masses_of(t, where)
        pos = _quantity(t, "position", "length", where, required=True)
        if "mass" not in t:
            raise InputError(f"{where}.mass: missing")
        masses.append(_checked(where, model.Mass, pos, **kw, name=_text(t, "name", where)))
    return tuple(loads), tuple(gears), tuple(pulleys), tuple(masses)


def _cases(doc, speed):
    rows = _array(doc, "cases")
    if not rows:
        return None, None, None, ()
    if len(rows) > _MAX_CASES:
        raise InputError(f"cases: at most {_MAX_CASES}, got {len(rows)}")
    w, f, t, names = [], [], [], []
    for k, row in enumerate(rows):
        where = f"cases[{k}]"
        _keys(row, "cases", where)
        share = _quantity(row, "time_share", "dimensionless", where, required=True)
        if not 0 <= share <= 1:
            raise InputError(f"{where}.time_share must be in [0, 1] (a fraction of the time, or '25 %'), got {share:g}")
        fac = _quantity(row, "factor", "dimensionless", where, default=1.0)
        if not math.isfinite(fac):
            raise InputError(f"{where}.factor must be finite, got {fac!r}")
        w.append(_quantity(row, "speed", "speed", where, default=speed))
        f.append(fac)
        t.append(share)
        names.append(_text(row, "name", where, f"case {k + 1}"))
    t = np.array(t)
    if not math.isclose(float(t.sum()), 1.0, abs_tol=1e-6):
        raise InputError(f"cases: the time shares sum to {float(t.sum()):.6g}, not 1")
    return np.array(w), np.array(f), t / t.sum(), tuple(names)


def _lubricant(doc):
    if "lubricant" not in doc:
        return {}
    t = doc["lubricant"]
    where = "lubricant"
    _keys(t, "lubricant", where)
    out = {}
    if "viscosity" in t:
        if "oil" in t:
            raise InputError("lubricant.oil: give viscosity or the oil with its temperature, not both")
        out["kinematic_viscosity"] = _quantity(t, "viscosity", "kinematic_viscosity", where)
    elif "oil" in t:
        oil = _text(t, "oil", where).strip().upper().replace(" ", "")
        if not oil.startswith("VG") or not oil[2:].isdigit():
            raise InputError(f"lubricant.oil: expected an ISO VG grade such as 'VG68', got {t['oil']!r}")
        out["iso_vg"] = int(oil[2:])
        out["temperature"] = _quantity(t, "temperature", "temperature", where, required=True)
        if "viscosity_index" in t:
            out["viscosity_index"] = _quantity(t, "viscosity_index", "dimensionless", where)
        if "viscosity_100" in t:
            out["viscosity_100"] = _quantity(t, "viscosity_100", "kinematic_viscosity", where)
    if "contamination" in t:
        c = t["contamination"]
        if isinstance(c, str):
            from ..ratings.lubrication import CONTAMINATION_CLASSES

            key = c.strip().lower().replace("-", "_").replace(" ", "_")
            full = {k.split("_")[0] if not k.startswith("very") else "very_severe": k for k in CONTAMINATION_CLASSES}
            key = full.get(key, key)
            if key not in CONTAMINATION_CLASSES:
                raise InputError(f"lubricant.contamination: expected one of {', '.join(full)} (ISO 281 table 13) or "
                                 f"a factor e_C, got {c!r}")
            out["contamination"] = key
        else:
            e = _quantity(t, "contamination", "dimensionless", where)
            if not 0 <= e <= 1:
                raise InputError(f"lubricant.contamination must be a factor e_C in [0, 1], got {e:g}")
            out["contamination"] = e
    if "reliability" in t:
        r = _quantity(t, "reliability", "dimensionless", where)
        if not 0.9 <= r <= 0.9995:
            raise InputError(f"lubricant.reliability must be 90 % ... 99.95 %, got {r * 100:g} %")
        out["reliability"] = r
    return out


def from_dict(doc, *, catalog=None):
    """A shaft-system document (the parsed TOML or JSON) -> the checked model and its load spectrum.

    Parameters
    ----------
    doc : dict
    catalog : str or Path, optional
        A user catalog file for the bearings' names (:func:`bearinglab.catalog.get`).

    Returns
    -------
    ShaftDocument

    Raises
    ------
    InputError
        One line naming the table and the field.
    """
    from .. import catalog as _catalog

    if not isinstance(doc, dict):
        raise InputError(f"document: expected a table, got {type(doc).__name__}")
    _keys(doc, "", "")
    user = {}
    tables = doc.get("bearings", {})
    if not isinstance(tables, dict):
        raise InputError("bearings: expected [bearings.\"NAME\"] tables")
    for name, table in tables.items():
        user[name] = _checked(f"bearings.{name}", _catalog.bearing_from_table, table, name=name)
    speed = _quantity(doc, "speed", "speed", "", default=0.0)
    material, alpha = _material(doc)
    shaft = _checked("sections", model.Shaft, _sections(doc), material, alpha)
    supports = _supports(doc, user, catalog)
    loads, gears, pulleys, masses = _loads(doc)
    gravity = None
    if "gravity" in doc:
        g = doc["gravity"]
        if g not in _GRAVITY:
            raise InputError(f"gravity: expected one of {', '.join(_GRAVITY)} (the direction of the weight), got {g!r}")
        gravity = tuple(_STANDARD_GRAVITY * float(c) for c in _GRAVITY[g])
    elements = doc.get("elements", 30)
    if isinstance(elements, bool) or not isinstance(elements, int):
        raise InputError(f"elements: expected a whole number, got {elements!r}")
    kw = {"shaft_temperature": _quantity(doc, "shaft_temperature", "temperature", ""),
          "housing_temperature": _quantity(doc, "housing_temperature", "temperature", ""),
          "housing_material": _text(doc, "housing_material", "", "steel")}
    system = model.ShaftSystem(shaft, supports, loads, gears, pulleys, masses, gravity, speed, elements=elements, **kw)
    w, f, t, names = _cases(doc, speed)
    if w is not None:
        for k, wk in enumerate(w):  # each case's torques balance, and a power-given gear needs its speed
            _checked(f"cases[{k}]", system.replace, speed=float(wk))
    return ShaftDocument(system, w, f, t, names, _lubricant(doc), doc)


def from_text(text, *, catalog=None):
    """A shaft-system document as TOML or JSON text (JSON when it opens with ``{``) -> ShaftDocument.

    Parameters
    ----------
    text : str
    catalog : str or Path, optional
        A user catalog file.

    Returns
    -------
    ShaftDocument

    Examples
    --------
    >>> d = from_text('''
    ... [[sections]]
    ... length = "300 mm"
    ... diameter = "30 mm"
    ... [[supports]]
    ... name = "A"
    ... position = "20 mm"
    ... bearing = "6206"
    ... axial = true
    ... [[supports]]
    ... name = "B"
    ... position = "280 mm"
    ... bearing = "6206"
    ... [[loads]]
    ... position = "150 mm"
    ... fy = "-2 kN"
    ... ''')
    >>> d.system.supports[1].position, d.system.loads[0].fy
    (0.28, -2000.0)
    """
    import tomllib

    if not isinstance(text, str):
        raise InputError(f"document: expected text, got {type(text).__name__}")
    body = text.strip()
    try:
        doc = json.loads(body) if body.startswith("{") else tomllib.loads(text)
    except (ValueError, tomllib.TOMLDecodeError) as exc:
        raise InputError(f"document: not valid {'JSON' if body.startswith('{') else 'TOML'} ({exc})") from None
    return from_dict(doc, catalog=catalog)


def load(path, *, catalog=None):
    """Read a shaft-system file: TOML, or JSON when its name ends in ``.json``.

    Parameters
    ----------
    path : str or Path
        The file; it is only read.
    catalog : str or Path, optional
        A user catalog file.

    Returns
    -------
    ShaftDocument
    """
    from .. import catalog as _catalog
    from .._bounds import read_input_bytes

    p = Path(path)
    if p.suffix.lower() == ".json":
        try:
            text = read_input_bytes(p).decode("utf-8-sig")
        except FileNotFoundError:
            raise InputError(f"{p}: no such file") from None
        except (OSError, UnicodeDecodeError) as exc:
            raise InputError(f"{p}: cannot read ({exc})") from None
        return from_text(text, catalog=catalog)
    return from_dict(_catalog.read_toml(p), catalog=catalog)
