"""The standard series of the built-in catalog: data files, designation resolution and search.

The rows live in ``data/catalog_series.csv`` (boundary dimensions, ratings and limits, each with its
source), the published ball sets in ``data/ball_sets.csv``; what no source gives is estimated
(:mod:`bearinglab.estimation`) and listed in ``BallBearing.estimated_fields``. The files are parsed once,
with the csv module and plain floats (no units library on this path), and bearings are built on demand.
"""

from __future__ import annotations

import csv
import difflib
import functools
import math
import re
from importlib import resources

from ..errors import CatalogError, InputError

__all__: list[str] = []

_MM, _KN = 1e-3, 1e3
_RPM = 2.0 * math.pi / 60.0
GEOMETRY_FIELDS = ("n_balls", "ball_diameter", "pitch_diameter", "inner_conformity", "outer_conformity")
_ESTIMATED = ("estimated by the rule of bearinglab.estimation from d, D and B (see the user guide, "
              "'Estimated internal geometry')")
# angle code written -> the codes of the catalog rows that stand for it, best first
_ROW_CODES = {"BE": ("BE", "B"), "BECBP": ("BE", "B"), "BECBM": ("BE", "B"), "BECBY": ("BE", "B"),
              "BEP": ("BE", "B"), "BEY": ("BE", "B"), "BEM": ("BE", "B"), "B": ("B", "BE"), "BW": ("B", "BE"),
              "A5": ("A5", "ACD"), "AC": ("A5", "ACD"), "ACD": ("A5", "ACD"), "A": ("A",), "C": ("C", "CD"),
              "CD": ("C", "CD")}


def _csv_rows(name):
    text = (resources.files("bearinglab") / "data" / name).read_text(encoding="utf-8")
    return list(csv.DictReader(line for line in text.splitlines() if not line.startswith("#")))


def _num(text):
    return float(text) if text not in ("", None) else None


@functools.cache
def records():
    """``{name: row}`` of the standard series, numbers as floats (mm, kN, rpm, kg)."""
    out = {}
    for r in _csv_rows("catalog_series.csv"):
        row = dict(r)
        for key in ("bore_mm", "outside_diameter_mm", "width_mm", "chamfer_mm", "contact_angle_deg",
                    "dynamic_load_rating_kN", "static_load_rating_kN", "fatigue_load_limit_kN",
                    "reference_speed_rpm", "limiting_speed_rpm", "mass_kg"):
            row[key] = _num(r[key])
        out[r["designation"]] = row
    return out


@functools.cache
def by_base():
    """``{base size: [names]}``: ``"7205"`` -> ``["7205 BE", "7205 A", ...]``, ``"6208"`` -> ``["6208"]``."""
    out = {}
    for name in records():
        out.setdefault(name.split()[0], []).append(name)
    return out


@functools.cache
def ball_sets():
    """``{catalog name: row}`` of the published ball sets that belong to a catalog size."""
    return {r["catalog"]: r for r in _csv_rows("ball_sets.csv") if r["catalog"]}


def _geometry(name, row):
    """Ball set and conformities of a row: published where a source gives them, else estimated."""
    from .. import estimation

    published = ball_sets().get(name)
    sources, estimated = {}, []
    if published:
        kw = {"n_balls": int(published["n_balls"]), "ball_diameter": float(published["ball_diameter_mm"]) / 1e3,
              "pitch_diameter": float(published["pitch_diameter_mm"]) / 1e3}
        for key in ("n_balls", "ball_diameter", "pitch_diameter"):
            sources[key] = f"published: {published['source']} ({published['bearing']})"
    else:
        family = "deep-groove" if row["type"] == "radial" else "angular"
        est = estimation.estimate_ball_set(row["bore_mm"] / 1e3, row["outside_diameter_mm"] / 1e3,
                                           row["width_mm"] / 1e3, family=family)
        kw = {"n_balls": int(est.n_balls), "ball_diameter": float(est.ball_diameter),
              "pitch_diameter": float(est.pitch_diameter)}
        for key in ("n_balls", "ball_diameter", "pitch_diameter"):
            sources[key] = _ESTIMATED
            estimated.append(key)
    for race in ("inner", "outer"):
        key = f"{race}_conformity"
        value = published.get(key) if published else ""
        if value:
            kw[key] = float(value)
            sources[key] = f"published: {published['source']}"
        else:
            kw[key] = estimation.GROOVE_CONFORMITY[race]
            sources[key] = ("estimated: the conformity ISO 76 and ISO 281 assume (0.52 inner, 0.53 outer; "
                            "bearinglab.estimation)")
            estimated.append(key)
    return kw, sources, estimated


def _pick_row(d):
    """The catalog row of a parsed designation, or CatalogError with suggestions."""
    names = list(by_base().get(d.base, []))
    for alt in d.alternatives:
        names += by_base().get(alt, [])
    if not names:
        raise CatalogError(f"bearing: unknown name {d.text!r}; {suggest(d)}")
    if d.base.startswith("7"):
        if d.angle_code is None:
            raise CatalogError(f"bearing: {d.text!r} needs its contact-angle code; {suggest(d)}")
        for code in _ROW_CODES[d.angle_code]:
            hit = [n for n in names if n.split()[1] == code]
            if hit:
                return hit[0]
        raise CatalogError(f"bearing: no {d.base} with the angle code {d.angle_code} "
                           f"({d.contact_angle:g} deg) in the catalog; {suggest(d)}")
    return names[0]


def suggest(d):
    """'did you mean ...' for a parsed designation: the same size with other codes, else the nearest sizes
    of the same series, else the closest spellings."""
    known = by_base()
    same = list(known.get(d.base, []))
    for alt in d.alternatives:
        same += known.get(alt, [])
    if same:
        return f"did you mean {' or '.join(same[:6])}?"
    m = re.match(r"^(\d{2,3}?)(\d\d)$", d.base)
    if m:
        series, code = m.groups()
        near = sorted((abs(int(b[len(series):]) - int(code)), b) for b in known
                      if b.startswith(series) and len(b) == len(d.base) and b[len(series):].isdigit())
        names = [n for _, b in near[:3] for n in known[b][:2]]
        if names:
            return f"did you mean {' or '.join(names)} (series {series})?"
    close = difflib.get_close_matches(d.base, list(known), n=3, cutoff=0.6)
    if close:
        return f"did you mean {' or '.join(close)}?"
    return "`bearinglab catalog search --bore ...` finds a bearing by its dimensions"


def resolve(text, *, clearance="mean"):
    """A BallBearing for a designation of the standard series, or CatalogError.

    ``clearance``: ``"mean"``, ``"min"`` or ``"max"`` of the ISO 5753-1 range that the models use.
    """
    from .. import designation

    if clearance not in ("mean", "min", "max"):
        raise InputError(f"clearance must be one of ['mean', 'min', 'max'], got {clearance!r}")
    d = designation.parse(text)
    name = _pick_row(d)
    return build(name, d, clearance=clearance)


def build(name, d=None, *, clearance="mean"):
    """The BallBearing of a catalog row, with the seals, clearance and tolerance class of ``d``."""
    from .. import internal_clearance
    from ..bearing import BallBearing

    row = records()[name]
    kw, sources, estimated = _geometry(name, row)
    dims = row["source_dimensions"]
    ratings = row["source_ratings"]
    sources.update(bore=dims, outside_diameter=dims, width=dims, chamfer=dims)
    for key, col in (("dynamic_load_rating", "dynamic_load_rating_kN"), ("static_load_rating", "static_load_rating_kN"),
                     ("fatigue_load_limit", "fatigue_load_limit_kN")):
        if row[col] is not None:
            kw[key] = row[col] * 1e3
            sources[key] = ratings
        elif ratings.startswith("computed"):
            sources[key] = ratings
        else:
            sources[key] = ("computed by ISO 281 annex B from the internal geometry (the maker gives no "
                            "fatigue load limit)")
    for key in ("reference_speed", "limiting_speed", "mass"):
        if row[f"{key}_rpm" if key != "mass" else "mass_kg"] is not None:
            sources[key] = row["source_limits"]
    label = d.text.strip() if d is not None else name
    kw.update(designation=label, bore=row["bore_mm"] / 1e3, outside_diameter=row["outside_diameter_mm"] / 1e3,
              width=row["width_mm"] / 1e3, type=row["type"], series=row["series"],
              source=f"{row['maker_designation'] or name}: {ratings}")
    if row["type"] == "angular":
        kw["contact_angle"] = math.radians(row["contact_angle_deg"])
        code = name.split()[1]
        sources["contact_angle"] = f"nominal contact angle of the code {code} ({row['maker_designation'] or name})"
        if "inner_conformity" in estimated:  # the clearance follows from the angle and the conformities
            estimated.append("radial_clearance")
        if d is not None and d.angle_code and d.angle_code != code:
            sources["contact_angle"] += (f"; the code {d.angle_code} written stands for the same "
                                         f"{row['contact_angle_deg']:g} deg; ratings and dimensions are "
                                         f"{row['maker_designation'] or name}'s")
    clearance_class = d.clearance_class if d is not None else None
    if d is not None and clearance_class and row["type"] != "radial":
        raise InputError(f"bearing: the clearance class {clearance_class} of {d.text!r} is a deep-groove "
                         "ball bearing class (ISO 5753-1); angular-contact bearings are set by their "
                         "arrangement (give --contact-angle or --radial-clearance)")
    if row["type"] == "radial":
        cls = clearance_class or "CN"
        try:
            rng = internal_clearance.radial_clearance_range(kw["bore"], cls)
        except InputError:
            rng = None
        if rng is not None:
            value = {"mean": (rng.minimum + rng.maximum) / 2, "min": rng.minimum, "max": rng.maximum}[clearance]
            kw["radial_clearance"] = float(value)
            written = f"class {cls}" if clearance_class else "no clearance suffix: Normal (CN)"
            sources["radial_clearance"] = (f"ISO 5753-1 {written}, {rng.minimum * 1e6:g}-{rng.maximum * 1e6:g} "
                                           f"um for d = {row['bore_mm']:g} mm; the models use the {clearance}")
            sources["contact_angle"] = ("free contact angle from the radial clearance and the groove "
                                        "conformities")
            if "inner_conformity" in estimated:
                estimated.append("contact_angle")
        else:
            kw["contact_angle"] = 0.0
            sources["contact_angle"] = "nominal contact angle of a deep-groove ball bearing"
    if d is not None and d.seal:
        kw["seal"], kw["seals"] = d.seal, d.seals
        sources["seal"] = f"designation suffix of {d.text!r}: {d.seal} seals/shields on {d.seals} side(s)"
    if clearance_class:
        kw["clearance_class"] = clearance_class
    if d is not None and d.tolerance_class:
        kw["tolerance_class"] = d.tolerance_class
        sources["tolerance_class"] = f"designation suffix of {d.text!r}"
    return BallBearing(estimated_fields=tuple(estimated), sources=sources, **kw)


def details(name_or_bearing):
    """Catalog data that is not a BallBearing field: chamfer, speeds, mass, maker designation."""
    row = records()[name_or_bearing]
    return {"chamfer_mm": row["chamfer_mm"], "reference_speed_rpm": row["reference_speed_rpm"],
            "limiting_speed_rpm": row["limiting_speed_rpm"], "mass_kg": row["mass_kg"],
            "maker_designation": row["maker_designation"]}


def row_name(text):
    """The catalog row a designation resolves to (None if it is not one)."""
    from .. import designation

    try:
        return _pick_row(designation.parse(text))
    except InputError:
        return None


def _within(value, target, tolerance):
    return target is None or abs(value - target) <= tolerance


def search(*, bore=None, outside_diameter=None, width=None, type=None, series=None, tolerance=1e-6):
    """Rows of the standard series matching the dimensions [m], type and series."""
    types = {None: None, "deep-groove": "radial", "radial": "radial", "angular": "angular"}
    if type not in types:
        raise InputError(f"type must be one of ['deep-groove', 'angular'], got {type!r}")
    out = []
    for name, r in records().items():
        if not (_within(r["bore_mm"] / 1e3, bore, tolerance)
                and _within(r["outside_diameter_mm"] / 1e3, outside_diameter, tolerance)
                and _within(r["width_mm"] / 1e3, width, tolerance)):
            continue
        if types[type] is not None and r["type"] != types[type]:
            continue
        if series is not None and not (r["series"] == series or r["series"].startswith(series)
                                       and not r["series"][len(series):].isdigit()):
            continue
        out.append(name)
    return out


@functools.cache
def listing():
    """``{name: (n_balls, ball_diameter_mm, pitch_diameter_mm, estimated)}`` of every row, the estimates
    computed for all rows at once (a listing needs no BallBearing)."""
    import numpy as np

    from .. import estimation

    names = list(records())
    rows = [records()[n] for n in names]
    out = {}
    for family, kind in (("deep-groove", "radial"), ("angular", "angular")):
        pick = [i for i, r in enumerate(rows) if r["type"] == kind]
        if not pick:
            continue
        arr = np.array([[rows[i]["bore_mm"], rows[i]["outside_diameter_mm"], rows[i]["width_mm"]] for i in pick]) / 1e3
        est = estimation.estimate_ball_set(arr[:, 0], arr[:, 1], arr[:, 2], family=family)
        for j, i in enumerate(pick):
            out[names[i]] = (int(est.n_balls[j]), float(est.ball_diameter[j]) / _MM,
                             float(est.pitch_diameter[j]) / _MM, True)
    for name, s in ball_sets().items():
        if name in out:
            out[name] = (int(s["n_balls"]), float(s["ball_diameter_mm"]), float(s["pitch_diameter_mm"]), False)
    return out
