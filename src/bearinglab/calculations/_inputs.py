"""The inputs every boundary reads the same way: a bearing, loads, speeds, lengths and the lubricant.

The command line's options and the calculations' fields (:mod:`bearinglab.calculations`) are read by
these functions, so that a value means the same and is refused with the same message whichever
boundary gives it. Each message opens with the input's name as the command line spells it without its
dashes (``radial-load: ...``, ``speed must be ...``); other inputs it names carry their dashes
(``give --fx or --radial-load``). Nothing here prints, and nothing imports the command line.

Bearing         resolve_bearing (a catalog name, a bearing file or the inline geometry -> BallBearing),
                inputs_echo (the bearing as used and the quantities given, for a JSON document)
Quantities      five_loads, parse_length, speed_size, parse_speed, parse_speeds, parse_viscosity,
                parse_temperature, choice
Displacements   FREEDOMS, prescribed_displacements (the held displacements and tilts -> [m, rad], NaN free),
                held_reactions (their reactions, by JSON key), prescribed_echo (as typed, for the JSON)
Lubricant       LubricantViscosity, lubricant_viscosity (the oil options -> the operating viscosity)
"""

from __future__ import annotations

import dataclasses
import math
import re
import typing
import weakref
from typing import TYPE_CHECKING

from ..errors import InputError

if TYPE_CHECKING:
    from ..bearing import BallBearing

__all__ = ["DEFAULT_LUBRICATION", "FREEDOMS", "OIL_LUBRICATION", "LubricantViscosity", "choice",
           "default_lubrication", "five_loads", "held_reactions", "inputs_echo", "lubricant_viscosity",
           "parse_length", "parse_speed", "parse_speeds", "parse_temperature", "parse_viscosity",
           "prescribed_displacements", "prescribed_echo", "resolve_bearing", "speed_size"]

def resolve_bearing(bearing=None, bearing_file=None, catalog=None, balls=None, ball_diameter=None,
                    pitch_diameter=None, inner_groove_radius=None, outer_groove_radius=None,
                    inner_conformity=None, outer_conformity=None, contact_angle=None,
                    radial_clearance=None, ball_material=None) -> BallBearing:
    """The bearing named, read from a file, or given inline; inline options override named fields.

    Its provenance notes (:func:`bearinglab.catalog.provenance_notes`) are the caller's to report."""
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
    from ..bearing import ANGLE_BUILT_IN

    built_in = base.type in ANGLE_BUILT_IN  # four-point, double-row angular, ...: angle and clearance apart
    if contact_angle is not None and radial_clearance is not None and not built_in:
        raise InputError("contact-angle: give --contact-angle or --radial-clearance, not both")
    if contact_angle is not None:
        changes["contact_angle"] = parse_quantity(contact_angle, "angle", "contact-angle")
        if not built_in:
            changes["radial_clearance"] = None
    if radial_clearance is not None and (built_in or contact_angle is None):
        # zero or negative: a preloaded bearing (issue 30), bounded by the bearing
        changes["radial_clearance"] = parse_quantity(radial_clearance, "length", "radial-clearance")
        if not built_in:
            changes["contact_angle"] = None
    elif {"inner_conformity", "outer_conformity", "ball_diameter"} & set(changes) and not built_in:
        # a new ball or new grooves keep the angle and re-derive the clearance
        changes["radial_clearance"] = None
    if base.type == "self-aligning" and "outer_conformity" not in changes and str(
            base.sources.get("outer_conformity", "")).startswith("derived") and \
            {"ball_diameter", "pitch_diameter", "contact_angle"} & set(changes):
        changes["outer_conformity"] = None  # the sphere follows the new ball set or angle (BallBearing)
    if ball_material is not None:
        key = ball_material.lower().replace("-", "_")
        if key not in MATERIALS:
            raise InputError(f"ball-material must be one of {sorted(MATERIALS)}, got {ball_material!r}")
        changes["ball_material"] = MATERIALS[key]
    if not changes:
        if not (bearing or bearing_file):
            raise InputError("bearing: give --bearing NAME, --bearing-file FILE or the inline geometry (--balls, --ball-diameter, ...)")
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


#: The lubrication method of SKF's friction model when none is given, the same for every command (issue 30):
#: grease, the common case of ball bearings (the model takes the base oil's viscosity), unless the lubricant is
#: given as an oil grade (``oil``), which says the bearing runs in oil: then an oil jet (circulating oil, SKF's
#: K_rs 3e-8). An oil bath is never assumed: its drag needs the oil level.
DEFAULT_LUBRICATION, OIL_LUBRICATION = "grease", "oil-jet"


def default_lubrication(lubrication, oil):
    """The lubrication method given, else :data:`DEFAULT_LUBRICATION` (``OIL_LUBRICATION`` with an oil grade).

    Parameters
    ----------
    lubrication : str or None
        The method given.
    oil : str or None
        The oil grade given (``"VG68"``).

    Returns
    -------
    str

    Examples
    --------
    >>> default_lubrication(None, None), default_lubrication(None, "VG68"), default_lubrication("oil-air", "VG68")
    ('grease', 'oil-jet', 'oil-air')
    """
    if lubrication is not None:
        return lubrication
    return OIL_LUBRICATION if oil is not None and str(oil).strip() else DEFAULT_LUBRICATION


#: Kinematic viscosities accepted from the command line [m^2/s]: 0.1 to 1e7 cSt, the dynamic range the film
#: command takes (0.1 to 1e7 mPa s) at about 1000 kg/m^3. A sanity bound, not a property of any oil: outside
#: it a value is taken for a typing or unit error (issue 24: absurd viscosities are refused in one line).
VISCOSITY_BOUNDS = (1e-7, 10.0)
#: The hottest oil temperature accepted from the command line [degC]. A sanity bound, not an oil's limit
#: (SKF rates its angular-contact bearings with steel or brass cages to +150 degC, General Catalogue 6000/I RU,
#: 2006, p. 413): above it a value is taken for a typing or unit error, and ASTM D341 is far outside its data.
HOTTEST_OIL_DEGC = 400.0


def parse_viscosity(text, name="viscosity"):
    """A kinematic viscosity option [m^2/s], > 0 and within :data:`VISCOSITY_BOUNDS` (the message in cSt,
    the unit of oil data sheets)."""
    from ..units import parse_quantity

    nu = parse_quantity(text, "kinematic_viscosity", name)
    if not nu > 0:
        raise InputError(f"{name} must be > 0 [cSt], got {float(nu) * 1e6:.6g} cSt")
    lo, hi = VISCOSITY_BOUNDS
    if not lo <= nu <= hi:
        raise InputError(f"{name} must be in [{lo * 1e6:g}, {hi * 1e6:g}] [cSt], got {float(nu) * 1e6:.6g} cSt")
    return nu


def choice(name, value, choices):
    """``value`` if it is one of ``choices``; otherwise an InputError listing them."""
    if value not in choices:
        raise InputError(f"{name} must be one of {list(choices)}, got {value!r}")
    return value


def five_loads(fx=None, fy=None, fz=None, mx=None, my=None, radial_load=None, axial_load=None):
    """(F_x, F_y, F_z, M_x, M_y) in N and N m from the load options (missing ones are 0)."""
    from ..units import parse_quantity

    if fx is not None and radial_load is not None:
        raise InputError("radial-load: give --fx or --radial-load, not both")
    if fz is not None and axial_load is not None:
        raise InputError("axial-load: give --fz or --axial-load, not both")
    names = (("fx" if radial_load is None else "radial-load", radial_load if fx is None else fx, "force"),
             ("fy", fy, "force"),
             ("fz" if axial_load is None else "axial-load", axial_load if fz is None else fz, "force"),
             ("mx", mx, "torque"), ("my", my, "torque"))
    return [0.0 if text is None else parse_quantity(text, kind, name) for name, text, kind in names]


_ZERO_C = 273.15  # K at 0 degC


def parse_temperature(text, name="temperature"):
    """A temperature '70 degC', '343 K' or '158 degF' [K], above absolute zero: one number and its unit by
    the grammar of every quantity (:func:`bearinglab.units.parse_temperature`)."""
    from ..units import parse_temperature as read

    t = read("" if text is None else text, name)
    if not t > 0:
        raise InputError(f"{name} must be above absolute zero (0 K = -273.15 degC), got {text!r}")
    return t


class LubricantViscosity(typing.NamedTuple):
    """The operating viscosity from the oil options (:func:`lubricant_viscosity`)."""

    viscosity: float | None
    """nu at the operating temperature [m^2/s]; None when no oil option was given."""
    description: str
    """How nu was obtained, one line for the output ("VG68 at 70 degC, VI 95 (assumed ...): 19.86 cSt")."""
    inputs: dict
    """The oil options as used, for the JSON's ``inputs`` (engineering units in the key names)."""


def lubricant_viscosity(viscosity=None, oil=None, temperature=None, viscosity_index=None, viscosity_100=None,
                        *, required=False):
    """The operating viscosity from the shared oil options: ``--viscosity``, or ``--oil`` with
    ``--temperature`` and at most one of ``--viscosity-index`` / ``--viscosity-100`` (neither: the oil's
    VI is :data:`bearinglab.ratings.DEFAULT_VISCOSITY_INDEX`, 95, and the description says it was assumed).

    Parameters
    ----------
    viscosity, oil, temperature, viscosity_100 : str or None
        The options' texts ('20 cSt', 'VG68' or 'ISO VG 68', '70 degC', '8.7 cSt').
    viscosity_index : float or None
        The option's value.
    required : bool
        Whether the command needs a viscosity (no option given is then an error; otherwise the result's
        viscosity is None).

    Returns
    -------
    LubricantViscosity
        ``(viscosity [m^2/s] or None, description, inputs)``.
    """
    from ..ratings import lubrication

    oil_opts = {"oil": oil, "temperature": temperature, "viscosity-index": viscosity_index,
                "viscosity-100": viscosity_100}
    given = [k for k, v in oil_opts.items() if v is not None]
    if viscosity is not None:
        if given:
            raise InputError(f"viscosity: give --viscosity, or --oil with --temperature, not both (also given: "
                             f"{', '.join('--' + k for k in given)})")
        nu = parse_viscosity(viscosity, "viscosity")
        return LubricantViscosity(nu, f"{nu * 1e6:.4g} cSt (given)", {"viscosity_cSt": nu * 1e6})
    if not given:
        if required:
            raise InputError("viscosity: give --viscosity (e.g. '20 cSt'), or --oil VG68 with --temperature "
                             "(and --viscosity-index or --viscosity-100 if known)")
        return LubricantViscosity(None, "no lubricant given", {})
    if oil is None or temperature is None:
        missing = "--oil (e.g. VG68)" if oil is None else "--temperature (e.g. '70 degC')"
        raise InputError(f"{'oil' if oil is None else 'temperature'}: {', '.join('--' + k for k in given)} "
                         f"also need{'s' if len(given) == 1 else ''} {missing}")
    if viscosity_index is not None and viscosity_100 is not None:
        raise InputError("viscosity-index: give --viscosity-index or --viscosity-100, not both (the index fixes "
                         "the viscosity at 100 degC)")
    m = re.fullmatch(r"(?:ISO\s*)?VG\s*([0-9]+)", oil.strip(), flags=re.IGNORECASE)
    grades = lubrication.ISO_VG_GRADES
    if not m or int(m.group(1)) not in grades:
        raise InputError(f"oil must be an ISO VG grade (VG{grades[0]} ... VG{grades[-1]}), got {oil!r}")
    grade, t = int(m.group(1)), parse_temperature(temperature)
    nu40 = lubrication.iso_vg_viscosity(grade)
    if viscosity_100 is not None:
        nu100 = parse_viscosity(viscosity_100, "viscosity-100")
        if not nu100 < nu40:
            raise InputError(f"viscosity-100 must be below the grade's {nu40 * 1e6:g} cSt at 40 degC, got "
                             f"{nu100 * 1e6:g} cSt")
        how, vi = f"nu100 {nu100 * 1e6:.4g} cSt (given)", None
    else:
        vi = lubrication.DEFAULT_VISCOSITY_INDEX if viscosity_index is None else float(viscosity_index)
        if not (math.isfinite(vi) and -100.0 <= vi <= 400.0):
            raise InputError(f"viscosity-index must be in [-100, 400] [-], got {viscosity_index!r}")
        try:
            nu100 = float(lubrication.viscosity_100_from_index(nu40, vi))
        except InputError as exc:  # the library's message names its own parameters
            raise InputError(f"viscosity-index: VG{grade} with VI {vi:g} is outside ASTM D2270 ({exc})") from None
        how = (f"VI {vi:g} ({'given' if viscosity_index is not None else 'assumed: a mineral oil, SKF'}), "
               f"nu100 {nu100 * 1e6:.4g} cSt by ASTM D2270")
    if not t <= _ZERO_C + HOTTEST_OIL_DEGC:
        raise InputError(f"temperature must be <= {HOTTEST_OIL_DEGC:g} [degC] (the oil's operating temperature), got "
                         f"{t - _ZERO_C:g} degC")
    nu = float(lubrication.kinematic_viscosity(t, viscosity_40=nu40, viscosity_100=nu100))
    lo, hi = VISCOSITY_BOUNDS
    if not lo <= nu <= hi:  # ASTM D341 extrapolated far outside the oil's liquid range
        raise InputError(f"temperature: VG{grade} at {t - _ZERO_C:g} degC would have nu = {nu * 1e6:.3g} cSt by "
                         f"ASTM D341, outside [{lo * 1e6:g}, {hi * 1e6:g}] cSt; give an operating temperature of "
                         f"the oil")
    text = f"VG{grade} at {t - _ZERO_C:.4g} degC, {how}: nu = {nu * 1e6:.4g} cSt (ASTM D341)"
    inputs = {"oil": f"VG{grade}", "temperature_degC": t - _ZERO_C, "viscosity_100_cSt": nu100 * 1e6,
              "viscosity_index": vi, "viscosity_index_assumed": viscosity_index is None and viscosity_100 is None}
    if vi is None:
        del inputs["viscosity_index"], inputs["viscosity_index_assumed"]
    return LubricantViscosity(nu, text, inputs)


#: The freedoms of a ring under load: its load input, the JSON key of its reaction, its displacement input (as
#: the command line spells it) and the input's quantity (ball and roller bearings alike).
FREEDOMS = (("fx", "fx_N", "dx", "length"), ("fy", "fy_N", "dy", "length"), ("fz", "fz_N", "dz", "length"),
            ("mx", "mx_Nmm", "tilt-x", "angle"), ("my", "my_Nmm", "tilt-y", "angle"))


def prescribed_displacements(texts, given):
    """The prescribed displacements [m, rad] (NaN: free) from the five inputs, or None; ``given`` tells
    which load inputs were given (a freedom takes a load or a displacement, not both)."""
    import numpy as np

    from ..units import parse_quantity

    if all(t is None for t in texts):
        return None
    held = np.full(5, np.nan)
    for k, ((load, _, name, kind), text) in enumerate(zip(FREEDOMS, texts, strict=True)):
        if text is None:
            continue
        if given[k]:
            raise InputError(f"{name}: give --{load} or --{name}, not both (a freedom takes a load or a "
                             "displacement)")
        held[k] = parse_quantity(text, kind, name)
        if not np.isfinite(held[k]):
            raise InputError(f"{name} must be finite, got {text!r}")
    return held


def held_reactions(reactions, held):
    """The reactions on the held freedoms, by JSON key (N, N mm); empty without held freedoms."""
    if held is None:
        return {}
    import numpy as np

    out = {}
    for k, (_, key, _, _) in enumerate(FREEDOMS):
        if not np.isnan(held[k]):
            out[key] = float(reactions[k]) * (1e3 if key.endswith("Nmm") else 1.0)
    return out


def prescribed_echo(held):
    """The prescribed displacements as typed, in engineering units (um, mrad), for the inputs echo."""
    if held is None:
        return {}
    import numpy as np

    keys = ("dx_um", "dy_um", "dz_um", "tilt_x_mrad", "tilt_y_mrad")
    scale = (1e6, 1e6, 1e6, 1e3, 1e3)
    return {"prescribed": {k: float(v * f) for k, v, f in zip(keys, held, scale, strict=True) if not np.isnan(v)}}
