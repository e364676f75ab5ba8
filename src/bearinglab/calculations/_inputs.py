"""The inputs every calculation shares: the bearing (named, from a file, inline), the speeds and
lengths as typed, and the echo of the inputs in a document.

Used by the calculations' documents (:mod:`bearinglab.calculations`) and by the command line (which
imports them through ``bearinglab.cli._common``); nothing here prints or knows a boundary.

Functions
---------
resolve_bearing   the bearing named, read from a file, or given inline; inline options override
inputs_echo       the inputs a result was computed from, for its JSON
parse_length      a length > 0 (the message in mm or um)
speed_size        d_m of the speed guard
parse_speeds      the speeds of a speed option (one rule for every command); parse_speed: one speed
choice            a value among choices
field             context: an InputError of the command's wording about a field -> RunFailure
"""

from __future__ import annotations

import contextlib
import dataclasses
import math
import weakref
from typing import TYPE_CHECKING

from ..errors import InputError

if TYPE_CHECKING:
    from ..bearing import BallBearing

__all__: list[str] = []  # private to the calculations and the command line


def resolve_bearing(bearing=None, bearing_file=None, catalog=None, balls=None, ball_diameter=None,
                    pitch_diameter=None, inner_groove_radius=None, outer_groove_radius=None,
                    inner_conformity=None, outer_conformity=None, contact_angle=None,
                    radial_clearance=None, ball_material=None) -> BallBearing:
    """The bearing named, read from a file, or given inline; inline options override named fields."""
    from .. import catalog as _catalog
    from ..bearing import MATERIALS, BallBearing
    from ..units import parse_quantity

    if bearing and bearing_file:
        raise InputError("bearing: give --bearing or --bearing-file, not both")
    if bearing:
        base = _catalog.get(bearing, catalog=catalog)
    elif bearing_file:
        base = _catalog.load_bearing_file(bearing_file)
    else:
        base = BallBearing(designation="inline")
    changes = {}
    if balls is not None:
        from .._bounds import MAX_BALLS, check_count

        changes["n_balls"] = check_count("balls", balls, MAX_BALLS)
    for key, text in (("ball_diameter", ball_diameter), ("pitch_diameter", pitch_diameter)):
        if text is not None:
            changes[key] = parse_length(text, key.replace("_", "-"))
    d = changes.get("ball_diameter", base.ball_diameter)
    for race, radius, conf in (("inner", inner_groove_radius, inner_conformity), ("outer", outer_groove_radius, outer_conformity)):
        if radius is not None and conf is not None:
            raise InputError(f"{race}-groove-radius: give the radius or the conformity, not both")
        if radius is not None:
            if d is None:
                raise InputError(f"{race}-groove-radius: needs --ball-diameter")
            r = parse_quantity(radius, "length", f"{race}-groove-radius")
            if not r > d / 2:  # the groove must hold the ball (conformity f = r / D > 0.5)
                raise InputError(f"{race}-groove-radius must be > D/2 = {d / 2 / _MM:g} [mm] (the ball radius), "
                                 f"got {r / _MM:g} mm")
            changes[f"{race}_conformity"] = r / d
        elif conf is not None:
            changes[f"{race}_conformity"] = conf
    if contact_angle is not None and radial_clearance is not None:
        raise InputError("contact-angle: give --contact-angle or --radial-clearance, not both")
    if contact_angle is not None:
        changes["contact_angle"] = parse_quantity(contact_angle, "angle", "contact-angle")
        changes["radial_clearance"] = None
    elif radial_clearance is not None:
        changes["radial_clearance"] = parse_length(radial_clearance, "radial-clearance", "um")
        changes["contact_angle"] = None
    elif {"inner_conformity", "outer_conformity", "ball_diameter"} & set(changes):
        # a new ball or new grooves keep the angle and re-derive the clearance
        changes["radial_clearance"] = None
    if ball_material is not None:
        key = ball_material.lower().replace("-", "_")
        if key not in MATERIALS:
            raise InputError(f"ball-material must be one of {sorted(MATERIALS)}, got {ball_material!r}")
        changes["ball_material"] = MATERIALS[key]
    if not changes and not (bearing or bearing_file):
        raise InputError("bearing: give --bearing NAME, --bearing-file FILE or the inline geometry (--balls, --ball-diameter, ...)")
    if not changes:
        return base
    given = {"balls": balls, "ball-diameter": ball_diameter, "pitch-diameter": pitch_diameter,
             "inner-groove-radius": inner_groove_radius, "outer-groove-radius": outer_groove_radius,
             "inner-conformity": inner_conformity, "outer-conformity": outer_conformity,
             "contact-angle": contact_angle, "radial-clearance": radial_clearance, "ball-material": ball_material}
    overrides = {k: v for k, v in given.items() if v is not None}
    label = ", ".join(f"{k} {v}" for k, v in overrides.items())
    if base.designation != "inline":  # the title and the JSON say that the named bearing was changed
        changes["designation"] = f"{base.designation} ({label})"
    given_fields = {"n_balls", "ball_diameter", "pitch_diameter", "inner_conformity", "outer_conformity",
                    "contact_angle", "radial_clearance"} & set(changes)
    if base.estimated_fields and given_fields:  # a value given inline is no longer an estimate
        changes["estimated_fields"] = tuple(f for f in base.estimated_fields if f not in given_fields)
    b = dataclasses.replace(base, **changes)
    _OVERRIDES[b] = {"catalog_bearing": base.designation, "overrides": overrides}
    return b


_OVERRIDES = weakref.WeakKeyDictionary()  # bearing -> the catalog bearing and the options that changed it



def _clean(value):
    """A float without the noise of unit conversions (3000.0000000000005 -> 3000.0): 15 digits."""
    if isinstance(value, float) and math.isfinite(value):
        return float(f"{value:.15g}")
    if isinstance(value, dict):
        return {k: _clean(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_clean(v) for v in value]
    return value


def inputs_echo(bearing, **quantities):
    """The inputs a result was computed from, for its JSON: the bearing as used and what was given.

    Parameters
    ----------
    bearing : BallBearing
        The bearing actually used (after the inline options, from :func:`resolve_bearing`).
    **quantities
        The loads, speeds and options given, already in engineering units with the unit in the name
        (``axial_load_N=...``, ``speed_rpm=...``).

    Returns
    -------
    dict
        ``bearing`` (the designation; a changed catalog bearing says what changed), ``geometry``
        (every known field and derived quantity, :func:`bearinglab.tables.bearing_summary`),
        ``overrides`` (option -> text as given, and ``catalog_bearing``) where options changed a named
        bearing, then the quantities. Floats carry 15 significant digits, so that a unit conversion
        does not show as noise (``3000.0000000000005`` rpm); results are never rounded.
    """
    from .. import tables

    geometry = {k: v for k, v in tables.bearing_summary(bearing).items()
                if v is not None and k not in ("designation", "source")}
    out = {"bearing": bearing.designation, "geometry": geometry}
    try:
        extra = _OVERRIDES.get(bearing)
    except TypeError:  # an unhashable bearing cannot have been resolved here
        extra = None
    if extra and extra["overrides"]:
        out["catalog_bearing"] = extra["catalog_bearing"]
        out["overrides"] = dict(extra["overrides"])
    out.update(quantities)
    return _clean(out)


_MM, _UM = 1e-3, 1e-6  # m per mm, per um
_LENGTH_UNITS = {"mm": _MM, "um": _UM}


def parse_length(text, name, unit="mm", *, zero=False):
    """A length option [m], > 0 (>= 0 with ``zero``): the message gives the value in ``unit`` ("mm" or
    "um"), the unit in which such a length is typed, never in metres."""
    from ..units import parse_quantity

    x = parse_quantity(text, "length", name)
    if not (x >= 0 if zero else x > 0):
        raise InputError(f"{name} must be {'>=' if zero else '>'} 0 [{unit}], got {x / _LENGTH_UNITS[unit]:g} {unit}")
    return x


def speed_size(bearing):
    """d_m of the speed guard (:func:`bearinglab.limits.check_speed`) [m]: the pitch diameter, else the
    mean of bore and outside diameter (the handbook's d_m); None when neither is known."""
    if bearing.pitch_diameter is not None:
        return bearing.pitch_diameter
    if bearing.bore is not None and bearing.outside_diameter is not None:
        return bearing.mean_diameter
    return None


def parse_speed(text, name="speed", *, bearing=None, zero=True, what="the inner-ring speed, a magnitude"):
    """One speed [rad/s] by the rule of :func:`parse_speeds` (the d_m n guard with ``bearing``'s
    :func:`speed_size`); a list is refused, never cut to its first value."""
    w = parse_speeds(text, name, pitch_diameter=None if bearing is None else speed_size(bearing), zero=zero,
                     what=what)
    if w.size != 1:
        raise InputError(f"{name}: give one speed, got {w.size} values in {text!r}")
    return float(w[0])


def parse_speeds(text, name="speed", *, pitch_diameter=None, zero=True, what="the inner-ring speed, a magnitude"):
    """The speeds of a speed option [rad/s]: one convention for every command. A speed is a magnitude,
    >= 0 (> 0 with ``zero=False``, where a zero speed has no meaning, e.g. a life in hours), and below
    the d_m n that no ball bearing of the size runs (:func:`bearinglab.limits.check_speed`) when the
    pitch diameter is given. The message gives the offending value in rpm."""
    from .. import _bounds, limits
    from ..units import RPM, parse_values

    w = parse_values(text, "speed", name, limit=_bounds.MAX_CASES)
    bad = ~(w >= 0) if zero else ~(w > 0)
    if bad.any():
        raise InputError(f"{name} must be {'>=' if zero else '>'} 0 [rpm] ({what}), got "
                         f"{float(w[bad][0]) / RPM:g} rpm")
    if pitch_diameter is not None:
        limits.check_speed(w, pitch_diameter, name)
    return w


def choice(name, value, choices):
    """``value`` if it is one of ``choices``; otherwise an InputError listing them."""
    if value not in choices:
        raise InputError(f"{name} must be one of {list(choices)}, got {value!r}")
    return value




# ----------------------------------------------------------------------------- requests and their failures
def request(name, given):
    """The command line's request for calculation ``name``: the options as typed (``given``, field name
    -> value; None for an option not given) as a :class:`bearinglab.calculations.Parsed`.

    The command line does not run the fields' range checks of :func:`bearinglab.calculations.parse`:
    those hold the web's smaller limits (``balls <= 200``, ``harmonics <= 100``), while the command
    line keeps its own (:mod:`bearinglab._bounds`). The document checks every input itself, with the
    same messages for both boundaries, so ``values`` holds the typed values (whole numbers, numbers,
    flags, choices, text) and the quantities as the text given.
    """
    from . import CALCULATIONS, Parsed

    calc = CALCULATIONS[name]
    names = {f.name for f in calc.fields}
    given = {k: v for k, v in given.items() if v is not None and k in names}
    return Parsed(calc, given, dict(given), 1)


def text(parsed, name, default=None):
    """The value of field ``name`` as the user wrote it (a number from a JSON body with the field's
    unit), or ``default`` when it was not given."""
    if name not in parsed.given:
        return default
    value = parsed.given[name]
    if isinstance(value, str):
        return value.strip()
    unit = parsed.calculation.field(name).unit
    return f"{value} {unit}" if unit and unit != "-" else str(value)


def value(parsed, name, default=None):
    """The checked value of a whole-number, number, flag or choice field, or ``default``."""
    return parsed.values.get(name, default)


def failure(exc, names=()):
    """An InputError as a RunFailure: it names the field of ``names`` (field names) whose option its
    message opens with (``axial-load must be ...``, ``speed: ...``); otherwise it names no field."""
    from .documents import RunFailure

    message = str(exc)
    for name in sorted(names, key=len, reverse=True):  # 'outer-speed' before 'speed'
        spelled = name.replace("_", "-")
        rest = message[len(spelled):]
        if message.startswith(spelled) and (rest[:1] in (":", " ", "")):
            return RunFailure(name, None, "{name}" + rest)
    return RunFailure(None, None, message)


@contextlib.contextmanager
def fields(parsed):
    """Run a document's computation: an InputError that opens with one of the calculation's options
    becomes a RunFailure naming that field (the command line words it back as the option)."""
    from .fields import RequestError

    try:
        yield
    except RequestError:
        raise
    except InputError as exc:
        raise failure(exc, [f.name for f in parsed.calculation.fields]) from None


def notes_in(doc, bearing):
    """The document with the bearing's provenance notes after its own warnings, as the command line's
    ``emit_json`` adds them."""
    from .. import catalog

    notes = list(dict.fromkeys(catalog.provenance_notes(bearing)))
    if not notes:  # emit_json adds no key of its own then
        return doc
    own = list(doc.get("warnings") or [])
    doc["warnings"] = own + [n for n in notes if n not in own]
    return doc


def bearing_of(parsed, *, bearing_file=None, catalog=None):
    """The bearing of a request: the ``bearing`` field, a bearing file or catalog file (command line
    only), and the inline geometry fields, by :func:`resolve_bearing`."""
    return resolve_bearing(
        text(parsed, "bearing"), bearing_file, catalog, value(parsed, "balls"),
        text(parsed, "ball_diameter"), text(parsed, "pitch_diameter"), text(parsed, "inner_groove_radius"),
        text(parsed, "outer_groove_radius"), value(parsed, "inner_conformity"),
        value(parsed, "outer_conformity"), text(parsed, "contact_angle"), text(parsed, "radial_clearance"),
        text(parsed, "ball_material"))
