"""Tapered roller bearings in pairs as the ``bearing-set`` calculation (issue 32): the slice model of both on a rigid
shaft, and ISO 281's method of the catalogues.

A pair is two tapered roller bearings (one designation for both, or one each: A then B), back to back (``DB``,
O) or face to face (``DF``, X), adjusted to an end play (``preload_offset`` < 0) or a preload (``preload``, a
force, or ``preload_offset`` > 0, an axial interference). ``spacing`` is the distance between the two pressure
centres, the effective spread of the catalogues: bearing A's pressure centre lies at +spacing/2, B's at
-spacing/2, and the shaft's loads act at the middle between them.

Two answers, side by side:

- the slice model (:func:`bearinglab.rollers.pairs.pair_analysis`): the shaft's displacement and 5 x 5
  stiffness at that middle, each bearing's radial and axial load, rollers and laminae, with the end play or the
  preload as given;
- ISO 281's method, as the makers print it for a pair adjusted to zero clearance without preload: the radial
  loads at the pressure centres from the shaft's statics, the induced axial loads f F_r / Y (SKF's f = 0.5,
  General Catalogue 6000 p. 208, the default; NSK's f = 0.6, CAT. No. E1102e eq. (5.27)), the axial loads of
  :func:`bearinglab.ratings.paired_axial_loads`, P and L10 (p = 10/3) of each bearing.

A bearing given by its catalogue values alone (C, e, Y) has ISO 281's answer; its slice model needs the roller
set or the data to estimate it (d, D, width, C0), and says what is missing otherwise.

Functions
---------
document   the bearing-set document of a tapered pair
"""

from __future__ import annotations

import math
import warnings

import numpy as np

from ..errors import InputError
from ._inputs import five_loads, inputs_echo, parse_length, parse_speeds, speed_size
from ._reading import text as _text
from ._rollers import (
    geometry_of,
    is_roller,
    notes_of,
    pressure_warnings,
    ring_entries,
    roller_case,
    slices_of,
)

__all__ = ["document"]

_ARRANGEMENTS = {"DB": "back-to-back", "DF": "face-to-face"}
_LOADS = ("fx", "fy", "fz", "mx", "my", "radial_load", "axial_load")
_MOUNTING = ("shaft_fit", "housing_fit", "shaft_interference", "housing_interference", "shaft_bore",
             "housing_outside_diameter", "shaft_material", "housing_material", "tolerance_class",
             "inner_ring_temperature", "outer_ring_temperature", "ball_temperature", "shaft_temperature",
             "housing_temperature")
_SOURCES = {"SKF": "SKF General Catalogue 6000/I RU (2006), p. 208: F_a = 0.5 F_r / Y",
            "NSK": "NSK Rolling Bearings CAT. No. E1102e, eq. (5.27): F_a = 0.6 F_r / Y"}


def _bearings(bearings):
    """The two bearings (A, B) of a pair, checked: tapered roller bearings only."""
    if not all(is_roller(b) for b in bearings):
        raise InputError("bearing: a set mixes ball and roller bearings; bearing-set takes a set of ball bearings "
                         "or a pair of tapered roller bearings")
    other = next((b for b in bearings if b.type != "tapered"), None)
    if other is not None:
        raise InputError(f"bearing: {other.designation!r} is a {other.type} roller bearing: bearing-set takes tapered "
                         "roller bearings in pairs (back to back, face to face); a cylindrical bearing locates "
                         "nothing axially (its load distribution is load-distribution's)")
    if len(bearings) > 2:
        raise InputError(f"bearing: a tapered pair is two bearings, got {len(bearings)}")
    return (bearings[0], bearings[-1])


def _centre_offset(bearing):
    """(D_pw/2) tan(alpha): the pressure centre's distance from the roller middle along the axis. [m]"""
    return 0.5 * bearing.pitch_diameter * math.tan(bearing.contact_angle)


def _shift(z):
    """(5, 5) T with u at z = T u at the reference (delta_x + theta_y z, delta_y - theta_x z)."""
    t = np.eye(5)
    t[0, 4], t[1, 3] = z, -z
    return t


def document(parsed, bearings):
    """The document of ``bearing-set`` for a pair of tapered roller bearings.

    Parameters
    ----------
    parsed : Parsed
        A request of ``bearing-set``.
    bearings : list of RollerBearing
        The bearings named (one for both, or A and B).

    Returns
    -------
    dict
        The shaft's ``displacement_*``, ``tilt_*`` and ``stiffness_matrix`` at the middle between the pressure
        centres (the slice model; null without it), ``effective_spread_mm``, ``roller_distance_mm``,
        ``axial_play_um`` (negative: an interference), ``operating_preload_N``, ``bearings`` (each one's
        position, loads, rollers and laminae), ``iso281`` (the catalogues' method: ``induced_axial_factor``,
        its ``source``, and per bearing ``radial_load_N``, ``induced_axial_load_N``, ``axial_load_N``,
        ``equivalent_dynamic_load_N``, ``basic_rating_life_Mrev``, ``basic_rating_life_h``), ``inputs`` and
        ``warnings``.
    """
    from ..units import RPM, parse_quantity

    a, b = _bearings(bearings)
    arrangement = _text(parsed, "arrangement") or "DB"
    if arrangement not in _ARRANGEMENTS:
        raise InputError(f"arrangement: a tapered pair is DB (back to back, O) or DF (face to face, X), got "
                         f"{arrangement!r} (a tandem needs a third bearing to locate the shaft the other way)")
    mounting = [k for k in _MOUNTING if _text(parsed, k) is not None]
    if mounting:
        raise InputError(f"{mounting[0].replace('_', '-')}: a tapered pair's play is set by its adjustment, not by "
                         "its fits: give its end play or interference (--preload-offset) or its preload (--preload)")
    if _text(parsed, "spacing") is None:
        raise InputError("spacing: a tapered pair needs the distance between its pressure centres (the effective "
                         "spread), e.g. '100 mm'")
    spread = parse_length(_text(parsed, "spacing"), "spacing")
    if _text(parsed, "preload") is not None and _text(parsed, "preload_offset") is not None:
        raise InputError("preload: give --preload or --preload-offset, not both")
    force = None if _text(parsed, "preload") is None else parse_quantity(_text(parsed, "preload"), "force", "preload")
    if force is not None and not force >= 0:
        raise InputError(f"preload must be >= 0 [N] (an axial force at rest), got {force:g} N")
    offset = None if _text(parsed, "preload_offset") is None else parse_quantity(
        _text(parsed, "preload_offset"), "length", "preload-offset")
    if (_text(parsed, "stiffness_at") or "operating") != "operating":
        raise InputError("stiffness-at: chooses the contact angles of a ball bearing's Hertz constants; the laminae "
                         "of a roller bearing have ISO/TS 16281's stiffness")
    loads = np.array(five_loads(*(_text(parsed, k) for k in _LOADS)))
    sizes = [speed_size(x) for x in (a, b) if speed_size(x) is not None]
    w = parse_speeds(_text(parsed, "speed") or "0 rpm", pitch_diameter=max(sizes, default=None))
    if w.size != 1:
        raise InputError(f"speed: give one speed, got {w.size} values")
    speed = float(w[0])
    factor_name = _text(parsed, "induced_axial_factor") or "SKF"
    if factor_name not in _SOURCES:
        raise InputError(f"induced-axial-factor must be one of {list(_SOURCES)}, got {factor_name!r}")
    n_slices = slices_of(parsed)
    notes = []
    model, entries = _slice_model(a, b, arrangement, spread, loads, force, offset, n_slices, notes)
    iso = _iso281(a, b, arrangement, spread, loads, speed, factor_name)
    notes.append("ISO 281's method (iso281) takes the pair adjusted to zero clearance without preload, as the "
                 "catalogues do; the slice model takes the end play or preload given")
    names = [a.designation, b.designation]
    doc = {**model, "bearings": entries, "iso281": iso,
           "inputs": {**inputs_echo(a, fx_N=loads[0], fy_N=loads[1], fz_N=loads[2], mx_Nmm=loads[3] * 1e3,
                                    my_Nmm=loads[4] * 1e3, speed_rpm=speed / RPM, slices=n_slices),
                      "bearings": names, "arrangement": arrangement, "spacing_mm": spread * 1e3,
                      "preload_N": force, "preload_offset_um": None if offset is None else offset * 1e6,
                      "induced_axial_factor": factor_name},
           "warnings": list(dict.fromkeys([*notes, *notes_of(a), *notes_of(b)]))}
    return doc


def _slice_model(a, b, arrangement, spread, loads, force, offset, n_slices, notes):
    """The slice model of the pair: the shaft's entries and each bearing's; without the roller sets (and the
    data to estimate them), null entries and a note saying what is missing."""
    from ..rollers import pairs

    kind = _ARRANGEMENTS[arrangement]
    empty = {"displacement_x_um": None, "displacement_y_um": None, "displacement_z_um": None, "tilt_x_mrad": None,
             "tilt_y_mrad": None, "stiffness_matrix": None, "effective_spread_mm": spread * 1e3,
             "roller_distance_mm": None, "axial_play_um": None, "operating_preload_N": None}
    try:
        ga, gb = geometry_of(a), geometry_of(b)
    except InputError as exc:
        notes.append(f"slice model: not computed ({exc}); ISO 281's method needs C, e and Y only")
        return empty, [{"bearing": x.designation} for x in (a, b)]
    sign_a, sign_b = pairs._orientations(kind)
    ca, cb = _centre_offset(ga), _centre_offset(gb)
    distance = spread - ca - cb if kind == "back-to-back" else spread + ca + cb
    if not distance > 0:
        raise InputError(f"spacing must be > {(ca + cb) * 1e3:.4g} [mm] for this pair back to back (the pressure "
                         f"centres lie that far outside the roller middles), got {spread * 1e3:g} mm")
    centre_a = 0.5 * distance - sign_a * ca
    centre_b = -0.5 * distance - sign_b * cb
    mid = 0.5 * (centre_a + centre_b)  # the loads' point, in the frame of the roller middles
    t = _shift(mid)
    at_rollers = t.T @ loads  # the same loads at the middle between the roller middles
    play = 0.0 if offset is None else -offset
    kw = {"preload": force} if force else {"axial_play": play}
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        r = pairs.pair_analysis(ga, gb, at_rollers, distance=distance, arrangement=kind, n_slices=n_slices, **kw)
        idle = pairs.pair_analysis(ga, gb, np.zeros(5), distance=distance, arrangement=kind, n_slices=n_slices,
                                   axial_play=r.axial_play)
    notes += [*r.warnings, *(str(c.message) for c in caught)]
    inv = np.linalg.inv(t)
    shaft = ring_entries(t @ np.asarray(r.displacement, dtype=float),  # at the loads' point (module docstring)
                         inv.T @ np.asarray(r.stiffness, dtype=float) @ inv, ga.pitch_diameter)
    shaft.update(effective_spread_mm=spread * 1e3, roller_distance_mm=distance * 1e3, axial_play_um=r.axial_play * 1e6,
                 operating_preload_N=float(max(idle.axial_loads[0], 0.0)) if r.axial_play < 0 else 0.0,
                 converged=bool(r.converged), residual=float(r.residual), iterations=int(r.iterations))
    entries = []
    for k_, (x, res, sign, centre) in enumerate(((ga, r.bearing_a, sign_a, centre_a),
                                                 (gb, r.bearing_b, sign_b, centre_b))):
        notes += [f"bearing {'AB'[k_]}: {w}" for w in pressure_warnings(res.max_pressure)]
        entries.append({"bearing": x.designation, "orientation": int(sign),
                        "pressure_centre_mm": (centre - mid) * 1e3, "roller_middle_mm": ((0.5 if k_ == 0 else -0.5)
                                                                                         * distance - mid) * 1e3,
                        "radial_load_N": float(r.radial_loads[k_]), "axial_load_N": float(r.axial_loads[k_]),
                        **roller_case(res, x.pitch_diameter)})
    return shaft, entries


def _iso281(a, b, arrangement, spread, loads, speed, factor_name):
    """ISO 281's method of the catalogues for the pair: radial loads at the pressure centres, induced and
    resulting axial loads, P and L10 of each bearing."""
    from ..ratings import INDUCED_AXIAL_FACTORS, bearing_ratings, paired_axial_loads, roller
    from ..units import RPM

    fx, fy, fz, mx, my = loads
    # statics of a shaft on two supports at +-spread/2 (A at +): R_A + R_B = F, R_A z_A + R_B z_B = M_y (x) and
    # -(R_A z_A + R_B z_B) = M_x (y), the moments of the loads about the middle
    rx = (0.5 * fx + my / spread, 0.5 * fx - my / spread)
    ry = (0.5 * fy - mx / spread, 0.5 * fy + mx / spread)
    fr = [math.hypot(x, y) for x, y in zip(rx, ry, strict=True)]
    ya, yb = a.require("axial_factor"), b.require("axial_factor")
    factor = INDUCED_AXIAL_FACTORS[factor_name]
    # the thrust F_z > 0 on the shaft loads B back to back (A's cup narrows towards -z), A face to face
    pushed = 1 if (fz >= 0) == (arrangement == "DB") else 0
    other = 1 - pushed
    pair = paired_axial_loads(fr[other], fr[pushed], (ya, yb)[other], (ya, yb)[pushed], abs(fz), factor=factor)
    fa = [0.0, 0.0]
    fa[other], fa[pushed] = float(pair.axial_load_a), float(pair.axial_load_b)
    out = []
    for k, x in enumerate((a, b)):
        induced = factor * fr[k] / (ya, yb)[k]
        p = float(roller.roller_equivalent_load(fr[k], fa[k], x.contact_angle or 0.0, ratio_limit=x.ratio_limit,
                                                axial_factor=x.axial_factor))
        c = x.dynamic_load_rating if x.dynamic_load_rating is not None else \
            bearing_ratings(geometry_of(x)).dynamic_load_rating  # ISO 281 from the roller set
        l10 = float(roller.roller_rating_life(c, p)) if p > 0 else math.inf
        out.append({"bearing": x.designation, "radial_load_N": fr[k], "induced_axial_load_N": induced,
                    "axial_load_N": fa[k], "e": x.ratio_limit, "Y": (ya, yb)[k], "equivalent_dynamic_load_N": p,
                    "dynamic_load_rating_N": c, "basic_rating_life_Mrev": l10 * 1e-6 if math.isfinite(l10) else None,
                    "basic_rating_life_h": l10 / (speed / RPM) / 60.0 if speed > 0 and math.isfinite(l10) else None})
    return {"induced_axial_factor": factor, "source": _SOURCES[factor_name], "bearings": out}
