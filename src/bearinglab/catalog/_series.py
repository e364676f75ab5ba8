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

#: The types of the catalog rows whose ball set :mod:`bearinglab.estimation` estimates (its rules are
#: calibrated on published deep-groove and angular-contact ball sets only): type -> estimation family.
ESTIMATED_FAMILIES = {"radial": "deep-groove", "angular": "angular"}
#: The word of each row type in listings and search results (``radial`` is shown as deep-groove).
DISPLAY_TYPES = {"radial": "deep-groove"}

_MM, _KN = 1e-3, 1e3
_RPM = 2.0 * math.pi / 60.0
GEOMETRY_FIELDS = ("n_balls", "ball_diameter", "pitch_diameter", "inner_conformity", "outer_conformity")
_ESTIMATED = ("estimated by the rule of bearinglab.estimation from d, D and B (see the user guide, "
              "'Estimated internal geometry')")
# angle code written -> the codes of the catalog rows that stand for it, best first
_ROW_CODES = {"BE": ("BE", "B"), "BECBP": ("BE", "B"), "BECBM": ("BE", "B"), "BECBY": ("BE", "B"),
              "BEP": ("BE", "B"), "BEY": ("BE", "B"), "BEM": ("BE", "B"), "B": ("B", "BE"), "BW": ("B", "BE"),
              "A5": ("A5", "ACD", "AC"), "AC": ("A5", "ACD", "AC"), "ACD": ("A5", "ACD", "AC"), "A": ("A",),
              "C": ("C", "CD"),
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
                    "reference_speed_rpm", "limiting_speed_rpm", "mass_kg", "calculation_factor_f0", "preload_light_N", "preload_medium_N",
                    "preload_heavy_N"):
            row[key] = _num(r.get(key))
        out[r["designation"]] = row
    return out


_PREFIXES = ("QJ", "S")  # series prefixes written apart from the size: SKF QJ 208, GMN S 6208 C


def base_of(name):
    """The base size of a row name: ``"7205 BE"`` -> ``"7205"``, ``"QJ 208"`` -> ``"QJ208"``,
    ``"S 6208 C"`` -> ``"S6208"``."""
    parts = name.split()
    return parts[0] + parts[1] if parts[0] in _PREFIXES else parts[0]


def code_of(name):
    """The variant code of a row name: ``"7205 BE"`` -> ``"BE"``, ``"6208 ETN9"`` -> ``"ETN9"``, else ``""``."""
    parts = name.split()
    return " ".join(parts[2 if parts[0] in _PREFIXES else 1:])


def display_type(row_type):
    """The type word of a row type in listings: ``radial`` -> ``deep-groove``, the others as they are."""
    return DISPLAY_TYPES.get(row_type, row_type)


@functools.cache
def by_base():
    """``{base size: [names]}``: ``"7205"`` -> ``["7205 BE", "7205 A", ...]``, ``"6208"`` -> ``["6208", "6208 ETN9"]``."""
    out = {}
    for name in records():
        out.setdefault(base_of(name), []).append(name)
    return out


@functools.cache
def ball_sets():
    """``{catalog name: row}`` of the published ball sets that belong to a catalog size (a row's ``catalog``
    may name several, separated by ``;``: GMN's C and E bearings of a size have one ball set)."""
    return {name: r for r in _csv_rows("ball_sets.csv") for name in filter(None, r["catalog"].split(";"))}


def _geometry(name, row):
    """Ball set and conformities of a row: published where a source gives them, else estimated where
    :mod:`bearinglab.estimation` has a rule for the row's type, else unknown (None, and not estimated)."""
    from .. import estimation

    published = ball_sets().get(name)
    sources, estimated = {}, []
    family = ESTIMATED_FAMILIES.get(row["type"])
    if published:
        kw = {"n_balls": int(published["n_balls"]), "ball_diameter": float(published["ball_diameter_mm"]) / 1e3,
              "pitch_diameter": float(published["pitch_diameter_mm"]) / 1e3}
        for key in ("n_balls", "ball_diameter", "pitch_diameter"):
            sources[key] = f"published: {published['source']} ({published['bearing']})"
    elif family is not None:
        est = estimation.estimate_ball_set(row["bore_mm"] / 1e3, row["outside_diameter_mm"] / 1e3,
                                           row["width_mm"] / 1e3, family=family)
        kw = {"n_balls": int(est.n_balls), "ball_diameter": float(est.ball_diameter),
              "pitch_diameter": float(est.pitch_diameter)}
        for key in ("n_balls", "ball_diameter", "pitch_diameter"):
            sources[key] = _ESTIMATED
            estimated.append(key)
    else:
        # no published ball set of these types was found to calibrate a rule on: left unknown, and the
        # commands that need it ask for it (docs/user_guide/catalog.md, "Estimated internal geometry")
        for key in GEOMETRY_FIELDS:
            sources[key] = (f"not published for this {row['type']} bearing, and not estimated: no public ball set "
                            "of its type was found to calibrate a rule on; give it in a user catalog")
        return {}, sources, estimated
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


_DOUBLE_ROW_ANGULAR = re.compile(r"^3[23]\d\d$")


def _pick_row(d):
    """The catalog row of a parsed designation, or CatalogError with suggestions."""
    names = list(by_base().get(d.base, []))
    for alt in d.alternatives:
        names += by_base().get(alt, [])
    if not names:
        raise CatalogError(f"bearing: unknown name {d.text!r}; {suggest(d)}")
    if d.base.startswith(("7", "S")):
        if d.base.startswith("S"):  # GMN's spindle bearings: the codes C and E are the rows' own
            if d.angle_code is None:
                raise CatalogError(f"bearing: {d.text!r} needs its contact-angle code; {suggest(d)}")
            hit = [n for n in names if code_of(n) == d.angle_code]
            if not hit:
                raise CatalogError(f"bearing: no {d.base} with the angle code {d.angle_code} "
                                   f"({d.contact_angle:g} deg) in the catalog; {suggest(d)}")
            return hit[0]
        if d.angle_code is None:
            raise CatalogError(f"bearing: {d.text!r} needs its contact-angle code; {suggest(d)}")
        codes = _ROW_CODES[d.angle_code]
        if d.preload_class in ("GA", "GB", "GC") and "BE" in codes:
            codes = ("BE",)  # SKF's preload classes belong to its universally matchable BE bearings
        for code in codes:
            hit = [n for n in names if code_of(n) == code]
            if hit:
                return hit[0]
        raise CatalogError(f"bearing: no {d.base} with the angle code {d.angle_code} "
                           f"({d.contact_angle:g} deg) in the catalog; {suggest(d)}")
    if _DOUBLE_ROW_ANGULAR.match(d.base):  # SKF 32 A, 33 A: the code A (30 deg) is the only one
        hit = [n for n in names if code_of(n) == (d.angle_code or "A")]
        if not hit:
            raise CatalogError(f"bearing: no {d.base} with the angle code {d.angle_code} "
                               f"({d.contact_angle:g} deg) in the catalog; {suggest(d)}")
        return hit[0]
    if "E" in d.designs:  # SKF's E design: its own row (6208 ETN9), or the size SKF makes only so (1208 ETN9)
        hit = [n for n in names if code_of(n).startswith("E") or (not code_of(n) and _is_e_design(n))]
        if not hit:
            maker = records()[names[0]]["maker_designation"] or names[0]
            raise CatalogError(f"bearing: {d.text!r} asks for the E design, and the catalog has {maker} only "
                               f"(not its E design); write {names[0]}")
        return hit[0]
    plain = [n for n in names if not code_of(n)]
    return plain[0] if plain else names[0]


def _is_e_design(name):
    """Whether a row's maker designation is an E design (SKF 1208 ETN9, 2205 E-2RS1TN9)."""
    maker = records()[name]["maker_designation"] or ""
    return bool(re.search(r"\s\d+(/\d+)?\s?E", maker))


def suggest(d):
    """'did you mean ...' for a parsed designation: the same size with other codes, else the nearest sizes
    of the same series, else the closest spellings."""
    known = by_base()
    same = list(known.get(d.base, []))
    for alt in d.alternatives:
        same += known.get(alt, [])
    if same:
        return f"did you mean {' or '.join(same[:6])}?"
    m = re.match(r"^(QJ\d|\d{2,3}?)(\d\d)$", d.base)
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


# SKF General Catalogue 6000/I RU (2006), single row angular contact ball bearings, table 2, p. 412:
# preload of universally matchable bearings arranged back-to-back or face-to-face, before mounting, by
# bore d (over, up to) [mm]: (GA max, GB min, GB max, GC min, GC max) [N]; GA's minimum is none (its
# axial clearance, +4 to -4 um at d <= 50 mm, may be play).
_SKF_PRELOAD = ((10, 18, (80, 30, 330, 230, 660)), (18, 30, (120, 40, 480, 340, 970)),
                (30, 50, (160, 60, 630, 450, 1280)), (50, 80, (380, 140, 1500, 1080, 3050)),
                (80, 120, (410, 150, 1600, 1150, 3250)), (120, 180, (540, 200, 2150, 1500, 4300)),
                (180, 250, (940, 330, 3700, 2650, 7500)))
_PRELOAD_SOURCE = ("SKF General Catalogue 6000/I RU (2006), single row angular contact ball bearings, table 2, "
                   "p. 412 (universally matchable bearings, back-to-back or face-to-face, before mounting)")

# types whose sealed bearings are not the open row with seals: SKF prints the sealed self-aligning bearings
# (2200 E-2RS1TN9 ...) as other bearings with lower ratings (p. 492: 2210 E-2RS1TN9 C = 22.9 kN, the open
# 2210 ETN9 33.8 kN), and lists no sealed bearing of the other types (sealed 32 A / 33 A, p. 446, and the
# single-row deep groove bearings have the open bearing's C, C0, Pu, so they are taken)
_UNSEALED = {
    "self-aligning": "SKF's sealed self-aligning ball bearings (E-2RS1TN9, p. 492) are other bearings with "
                     "lower ratings, not in the catalog",
    "double-row-radial": "no sealed double row deep groove ball bearing is in the sources used",
    "four-point": "four-point contact ball bearings are not sealed",
    "thrust": "thrust ball bearings are not sealed",
}


def skf_preload(preload_class, bore_mm):
    """(minimum, maximum) preload [N] of SKF's class GA, GB or GC for a bore d [mm], or None outside the
    table (d <= 10 or d > 250 mm); GA's minimum is 0 (its axial clearance may be play)."""
    for lo, hi, (ga, gb_lo, gb_hi, gc_lo, gc_hi) in _SKF_PRELOAD:
        if lo < bore_mm <= hi:
            return {"GA": (0.0, ga), "GB": (gb_lo, gb_hi), "GC": (gc_lo, gc_hi)}[preload_class]
    return None


def _maker(row):
    """The maker of a row's data (the first word of its maker designation), or None (computed rows)."""
    return (row["maker_designation"] or "").split(" ")[0] or None


def build(name, d=None, *, clearance="mean"):
    """The BallBearing of a catalog row, with the seals, clearance, tolerance class, ball material and
    preload class of ``d``."""
    from .. import internal_clearance
    from ..bearing import MATERIALS, BallBearing

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
    if row["calculation_factor_f0"] is not None:
        kw["static_load_factor"] = row["calculation_factor_f0"]
        sources["static_load_factor"] = ratings
    for key in ("reference_speed", "limiting_speed", "mass"):
        if row[f"{key}_rpm" if key != "mass" else "mass_kg"] is not None:
            sources[key] = row["source_limits"]
    label = d.text.strip() if d is not None else name
    kw.update(designation=label, bore=row["bore_mm"] / 1e3, outside_diameter=row["outside_diameter_mm"] / 1e3,
              width=row["width_mm"] / 1e3, type=row["type"], series=row["series"],
              source=f"{row['maker_designation'] or name}: {ratings}")
    if row["type"] != "radial":
        kw["contact_angle"] = math.radians(row["contact_angle_deg"])
        code = code_of(name)
        sources["contact_angle"] = (row.get("source_contact_angle") or
                                    f"nominal contact angle of the code {code} ({row['maker_designation'] or name})")
        if row["type"] == "angular" and "inner_conformity" in estimated:
            estimated.append("radial_clearance")  # the clearance follows from the angle and the conformities
        if d is not None and d.angle_code and d.angle_code != code and row["type"] == "angular":
            sources["contact_angle"] += (f"; the code {d.angle_code} written stands for the same "
                                         f"{row['contact_angle_deg']:g} deg; ratings and dimensions are "
                                         f"{row['maker_designation'] or name}'s")
    clearance_class = d.clearance_class if d is not None else None
    if d is not None and clearance_class and row["type"] != "radial":
        what = ("angular-contact bearings are set by their arrangement (give --contact-angle or "
                "--radial-clearance)" if row["type"] in ("angular", "four-point", "double-row-angular") else
                f"the clearance classes of a {row['type']} bearing are not in bearinglab (give --radial-clearance)")
        raise InputError(f"bearing: the clearance class {clearance_class} of {d.text!r} is a single-row "
                         f"deep-groove ball bearing class (ISO 5753-1); {what}")
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
    maker_designation = row["maker_designation"] or ""
    if d is not None and d.seal:
        kw["seal"], kw["seals"] = d.seal, d.seals
        sources["seal"] = f"designation suffix of {d.text!r}: {d.seal} seals/shields on {d.seals} side(s)"
    elif re.search(r"-2RS1$", maker_designation):  # SKF 622, 623: made sealed only
        kw["seal"], kw["seals"] = "RS1", 2
        sources["seal"] = (f"catalog row {maker_designation}: the catalogue lists this size sealed only (RS1 on "
                           "both sides)")
    if clearance_class:
        kw["clearance_class"] = clearance_class
    if d is not None:
        _apply_suffixes(d, row, name, kw, sources)
    kw["ball_material"] = MATERIALS[kw.pop("_ball_material", "steel")]
    return BallBearing(estimated_fields=tuple(estimated), sources=sources, **kw)


def _apply_suffixes(d, row, name, kw, sources):
    """Tolerance class, ball material, preload class and snap ring of a designation; the note when another
    maker's data answers it."""
    from .. import designation

    if d.seal and row["type"] in _UNSEALED:
        raise InputError(f"bearing: the seal {d.seal} of {d.text!r}: {_UNSEALED[row['type']]}; the catalog has the "
                         f"open {row['maker_designation'] or name} only")
    if d.tolerance_class:
        kw["tolerance_class"] = d.tolerance_class
        sources["tolerance_class"] = f"designation suffix of {d.text!r}"
    if d.ball_material:
        kw["_ball_material"] = d.ball_material
        sources["ball_material"] = (f"designation suffix of {d.text!r}: balls of silicon nitride (hybrid bearing); "
                                    f"the ratings are the catalog's, of the all-steel {row['maker_designation'] or name}")
    if d.preload_class in ("UL", "UM", "US"):
        kw["preload_class"] = d.preload_class
        key = {"UL": "preload_light_N", "UM": "preload_medium_N", "US": "preload_heavy_N"}[d.preload_class]
        if _maker(row) != "GMN" or row[key] is None:
            raise InputError(f"bearing: the preload class {d.preload_class} of {d.text!r} is GMN's (universal "
                             f"matching); {row['maker_designation'] or name} has no such preload in the catalog")
        kw["preload"] = row[key] * 1.0
        sources["preload"] = (f"{row['source_ratings'].split(':')[0]}: preload Fv of {d.preload_class} "
                              f"({row[key]:g} N)")
    elif d.preload_class:
        kw["preload_class"] = d.preload_class
        bounds = skf_preload(d.preload_class, row["bore_mm"]) if d.preload_class in ("GA", "GB", "GC") else None
        if d.preload_class in ("GA", "GB", "GC") and not (row["type"] == "angular" and _maker(row) == "SKF"):
            raise InputError(f"bearing: the preload class {d.preload_class} of {d.text!r} is SKF's, for its "
                             f"universally matchable single-row angular contact bearings (72 BE, 73 BE); "
                             f"{row['maker_designation'] or name} is not one")
        if bounds is not None:
            lo, hi = bounds
            kw["preload"] = (lo + hi) / 2.0
            sources["preload"] = (f"{_PRELOAD_SOURCE}: class {d.preload_class}, d = {row['bore_mm']:g} mm: "
                                  f"{lo:g}-{hi:g} N; the models use the middle, {(lo + hi) / 2:g} N")
        else:
            sources["preload"] = (f"preload class {d.preload_class} of {d.text!r}: its preload is not in the "
                                  f"catalog (no public table of this class and size was found); give --preload")
    if d.arrangement:
        sources["arrangement"] = f"designation suffix of {d.text!r}: a matched set {d.arrangement}"
    snap = [t for t in d.designs if t in ("N", "NR", "N2")]
    if snap:
        what = {"N": "a snap-ring groove in the outer ring", "NR": "a snap-ring groove and its snap ring",
                "N2": "two locating slots in the outer ring"}[snap[0]]
        sources["snap_ring"] = f"designation suffix {snap[0]} of {d.text!r}: {what} (no number changes)"
    makers = designation.makers_of(d)
    maker = _maker(row)
    if makers and maker is not None and maker not in makers:
        sources["maker"] = (f"{' and '.join(makers)}'s designation answered with {row['maker_designation']}'s data "
                            f"({row['source_ratings'].split(':')[0]})")


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


def types():
    """The type words a search takes: those of the rows (``deep-groove`` for ``radial``, which is also
    taken), in the order of the catalog."""
    words = {}
    for r in records().values():
        words[display_type(r["type"])] = r["type"]
    return {**words, "radial": "radial"}


def search(*, bore=None, outside_diameter=None, width=None, type=None, series=None, tolerance=1e-6):
    """Rows of the standard series matching the dimensions [m], type and series."""
    known = types()
    if type is not None and type not in known:
        raise InputError(f"type must be one of {[t for t in known if t != 'radial']}, got {type!r}")
    if series is not None:
        series = "".join(str(series).split()).upper()  # "QJ 2", "32 a" as the rows write them: QJ2, 32A
    out = []
    for name, r in records().items():
        if not (_within(r["bore_mm"] / 1e3, bore, tolerance)
                and _within(r["outside_diameter_mm"] / 1e3, outside_diameter, tolerance)
                and _within(r["width_mm"] / 1e3, width, tolerance)):
            continue
        if type is not None and r["type"] != known[type]:
            continue
        if series is not None and not (r["series"] == series or r["series"].startswith(series)
                                       and not r["series"][len(series):].isdigit()):
            continue
        out.append(name)
    return out


@functools.cache
def listing():
    """``{name: (n_balls, ball_diameter_mm, pitch_diameter_mm, estimated)}`` of every row, the estimates
    computed for all rows at once (a listing needs no BallBearing); None where the ball set is neither
    published nor estimated."""
    import numpy as np

    from .. import estimation

    names = list(records())
    rows = [records()[n] for n in names]
    out = {n: (None, None, None, False) for n in names}
    for kind, family in ESTIMATED_FAMILIES.items():
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
