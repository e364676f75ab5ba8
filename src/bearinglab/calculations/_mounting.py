"""The mounting inputs of every calculation that takes a bearing: fits, seats, materials, temperatures
(issue 23), read the same way by the command line and the calculations.

parse_temperature   a temperature [K] ('60 degC', '333 K'; a bare number is degC)
MountedInputs       the parsed inputs: tolerance limits, Mounting, Conditions, unmounted clearance range
mounted_inputs      the inputs -> MountedInputs (None when none was given)
operating_bearing   the bearing at its probable operating clearance, and the JSON entries to add
MountedSet, mounted_set   the inputs of a bearing set applied to its bearings

The options are the fields ``MOUNTING`` of :mod:`.registry`; the physics is :mod:`bearinglab.mounting`. Messages
name the inputs as the command line spells them without their dashes (``shaft-fit must be ...``).
"""

from __future__ import annotations

import math
from typing import NamedTuple

from ..errors import InputError
from ._inputs import parse_length

__all__ = ["MountedInputs", "MountedSet", "mounted_inputs", "mounted_set", "operating_bearing",
           "parse_temperature"]

_ABSOLUTE_ZERO_C = -273.15
_UM, _MM = 1e-6, 1e-3


def parse_temperature(text, name):
    """A temperature option [K]: '60 degC', '60 °C', '333 K', '140 degF'; a bare number is in degC. One
    number and one unit by the grammar of every quantity (:func:`bearinglab.units.parse_temperature`):
    pint never evaluates it ('5,5 degC', '1 000 K', '9**9**9 K' are refused)."""
    from ..units import parse_temperature as read

    kelvin = read(str(text).strip(), name, default_unit="degC")
    if kelvin < 0:
        raise InputError(f"{name} must be >= -273.15 [degC] (absolute zero), got {kelvin - 273.15:g} degC")
    return kelvin


class MountedInputs(NamedTuple):
    """What the mounting options of one command give, ready for :mod:`bearinglab.mounting`."""

    mounting: object
    conditions: object
    unmounted: tuple
    """(minimum, maximum) unmounted diametral clearance. [m]"""
    unmounted_source: str
    limits: dict
    """(lower, upper) of the five random fields (:data:`bearinglab.mounting.monte_carlo.FIELDS`). [m]"""
    inner: tuple
    """(least, largest) interference of the inner fit after smoothing. [m]"""
    outer: tuple
    """(least, largest) interference of the outer fit after smoothing. [m]"""
    echo: dict
    """The options as given, for the JSON."""
    probable: tuple
    """SKF's probable interference range of the inner and the outer fit (fits.probable_interference)."""


def _pair(text, name):
    from ..units import parse_values

    v = parse_values(text, "length", name)
    if v.size not in (1, 2):
        raise InputError(f"{name}: give one value or 'least, largest', got {v.size} values in {text!r}")
    lo, hi = float(v.min()), float(v.max())
    return lo, hi


def _roughness(text, name):
    if text is None:
        return 0.0
    from ..mounting import fits

    a, b = _pair(text, name)
    if a < 0:
        raise InputError(f"{name} must be >= 0 [um], got {a / _UM:g} um")
    return float(fits.smoothing(a, b))  # one value: both surfaces have that R_z


def mounted_inputs(bearing, *, shaft_fit=None, housing_fit=None, shaft_interference=None,
                   housing_interference=None, shaft_bore=None, housing_outside_diameter=None,
                   shaft_material=None, housing_material=None, shaft_roughness=None, housing_roughness=None,
                   tolerance_class=None, clearance_class=None, radial_clearance=None,
                   inner_ring_temperature=None, outer_ring_temperature=None, ball_temperature=None,
                   shaft_temperature=None, housing_temperature=None, speed=0.0, require=False):
    """Parse the mounting options of a command; None when none was given and ``require`` is False."""
    given = {k: v for k, v in {
        "shaft_fit": shaft_fit, "housing_fit": housing_fit, "shaft_interference": shaft_interference,
        "housing_interference": housing_interference, "shaft_bore": shaft_bore,
        "housing_outside_diameter": housing_outside_diameter, "shaft_material": shaft_material,
        "housing_material": housing_material, "shaft_roughness": shaft_roughness, "housing_roughness": housing_roughness,
        "tolerance_class": tolerance_class, "clearance_class": clearance_class,
        "inner_ring_temperature": inner_ring_temperature, "outer_ring_temperature": outer_ring_temperature,
        "ball_temperature": ball_temperature, "shaft_temperature": shaft_temperature,
        "housing_temperature": housing_temperature}.items() if v is not None}
    if not given and not require:
        return None
    from ..mounting import chain, tables
    from ..mounting.materials import material

    if shaft_fit is not None and shaft_interference is not None:
        raise InputError("shaft-interference: give --shaft-fit or --shaft-interference, not both")
    if housing_fit is not None and housing_interference is not None:
        raise InputError("housing-interference: give --housing-fit or --housing-interference, not both")
    if shaft_fit is not None and shaft_fit not in tables.SHAFT_FIELDS:
        raise InputError(f"shaft-fit must be one of {list(tables.SHAFT_FIELDS)}, got {shaft_fit!r}")
    if housing_fit is not None and housing_fit not in tables.HOUSING_FIELDS:
        raise InputError(f"housing-fit must be one of {list(tables.HOUSING_FIELDS)}, got {housing_fit!r}")
    temps = {}
    for key, text in (("inner_temperature", inner_ring_temperature), ("outer_temperature", outer_ring_temperature),
                      ("ball_temperature", ball_temperature), ("shaft_temperature", shaft_temperature),
                      ("housing_temperature", housing_temperature)):
        if text is not None:
            option = {"inner_temperature": "inner-ring-temperature",
                      "outer_temperature": "outer-ring-temperature"}.get(key, key.replace("_", "-"))
            temps[key] = parse_temperature(text, option)
    for key, option, mat in (("shaft", "shaft-material", shaft_material), ("housing", "housing-material",
                                                                           housing_material)):
        if mat is not None:
            try:
                material(mat)
            except InputError as exc:
                raise InputError(f"{option}{str(exc).removeprefix('material')}") from None
    d0 = 0.0 if shaft_bore is None else parse_length(shaft_bore, "shaft-bore", zero=True)
    dh = math.inf if housing_outside_diameter is None else parse_length(housing_outside_diameter,
                                                                        "housing-outside-diameter")
    d, big = bearing.require("bore", "outside_diameter")
    if not d0 < d:
        raise InputError(f"shaft-bore must be < the bearing bore d = {d / _MM:g} [mm], got {d0 / _MM:g} mm")
    if not dh > big:
        raise InputError(f"housing-outside-diameter must be > the bearing outside diameter D = {big / _MM:g} "
                         f"[mm], got {dh / _MM:g} mm")
    m = chain.mounting_of(bearing, shaft_bore=d0, housing_outside_diameter=dh,
                          shaft_material=shaft_material or "steel", housing_material=housing_material or "steel")
    designated = getattr(bearing, "tolerance_class", None)  # from the designation suffix (P6, P5, ...)
    klass = tolerance_class or designated or "Normal"
    try:
        klass = tables.tolerance_class(klass)
    except InputError:
        if tolerance_class is not None:
            raise
        raise InputError(f"tolerance-class: the designation's class {designated!r} has no ISO 492 table here "
                         f"(valid: {list(tables.TOLERANCE_CLASSES)}); give --tolerance-class") from None
    s_in, s_out = _roughness(shaft_roughness, "shaft-roughness"), _roughness(housing_roughness,
                                                                             "housing-roughness")
    if shaft_interference is not None:
        lo, hi = _pair(shaft_interference, "shaft-interference")
        shaft, bore = (lo - s_in, hi - s_in), (0.0, 0.0)
    else:
        field = tables.field_limits(shaft_fit or "h6", d) if shaft_fit else tables.Limits(0.0, 0.0)
        b = tables.bore_limits(d, klass) if shaft_fit else tables.Limits(0.0, 0.0)
        shaft, bore = (float(field.lower) - s_in, float(field.upper) - s_in), (float(b.lower), float(b.upper))
    if housing_interference is not None:
        lo, hi = _pair(housing_interference, "housing-interference")
        od, housing = (lo - s_out, hi - s_out), (0.0, 0.0)
    else:
        field = tables.field_limits(housing_fit, big) if housing_fit else tables.Limits(0.0, 0.0)
        o = tables.outside_diameter_limits(big, klass) if housing_fit else tables.Limits(0.0, 0.0)
        od, housing = (float(o.lower) - s_out, float(o.upper) - s_out), (float(field.lower), float(field.upper))
    unmounted, source = _unmounted(bearing, radial_clearance, clearance_class)
    limits = {"unmounted_clearance": unmounted, "shaft": shaft, "bore": bore, "outside_diameter": od,
              "housing": housing}
    inner = (shaft[0] - bore[1], shaft[1] - bore[0])
    outer = (od[0] - housing[1], od[1] - housing[0])
    from ..mounting import fits

    probable = (fits.probable_interference(tables.Limits(*shaft), tables.Limits(*bore)),
                fits.probable_interference(tables.Limits(*od), tables.Limits(*housing)))
    conditions = chain.Conditions(**temps, speed=float(speed))
    echo = dict(given, tolerance_class=klass)
    return MountedInputs(m, conditions, unmounted, source, limits, inner, outer, echo, probable)


def _unmounted(bearing, radial_clearance, clearance_class):
    """The unmounted clearance range and where it comes from."""
    if radial_clearance is not None:
        if clearance_class is not None:
            raise InputError("clearance-class: give --clearance-class or --radial-clearance, not both")
        lo, hi = _pair(radial_clearance, "radial-clearance")
        if lo < 0:
            raise InputError(f"radial-clearance must be >= 0 [um], got {lo / _UM:g} um")
        return (lo, hi), "--radial-clearance"
    klass = clearance_class or getattr(bearing, "clearance_class", None)
    if klass is None and bearing.type == "angular" and bearing.radial_clearance is not None:
        e = float(bearing.radial_clearance)
        return (e, e), "the bearing's free contact angle (geometric clearance of an angular-contact bearing)"
    from .. import internal_clearance

    klass = klass or "CN"
    try:
        r = internal_clearance.radial_clearance_range(bearing.require("bore"), klass)
    except InputError as exc:
        raise InputError(f"clearance-class: {exc}; give --radial-clearance for this bearing") from None
    lo, hi = (float(r[0]), float(r[1]))
    return (lo, hi), f"ISO 5753-1 class {str(klass).upper()}"


class MountedSet(NamedTuple):
    """A bearing set with its mounting: the bearings at their operating clearance and the interference."""

    bearings: list
    interference: float
    """The set's axial interference in operation. [m]"""
    clearance: float
    """The probable operating diametral clearance of each bearing. [m]"""
    echo: dict
    warnings: list


def mounted_set(bearings, assembled_interference, arrangement, spacing, speed, options):
    """The mounting options of ``bearing-set`` applied to its (like) bearings; None without options."""
    if all(v is None for v in options.values()):
        return None
    if len({b.designation for b in bearings}) > 1:
        raise InputError("bearing: the mounting options need one bearing type for the whole set")
    from ..mounting import chain, preload

    b = bearings[0]
    inp = mounted_inputs(b, **options, speed=speed, require=True)
    r = chain.operating_range(inp.unmounted, inp.inner, inp.outer, inp.mounting, inp.conditions)
    p = r.probable
    reduction = float(p.fit_reduction + p.thermal_reduction + p.centrifugal_reduction)
    c = inp.conditions
    t_s = c.inner_temperature if c.shaft_temperature is None else c.shaft_temperature
    t_h = c.outer_temperature if c.housing_temperature is None else c.housing_temperature
    interference, clearance = preload.operating_interference(
        b, assembled_interference, reduction, arrangement_kind=arrangement, spacing=spacing,
        shaft_temperature=t_s, housing_temperature=t_h, shaft_expansion=inp.mounting.shaft.thermal_expansion,
        housing_expansion=inp.mounting.housing.thermal_expansion)
    new = [x.replace(radial_clearance=clearance) for x in bearings]
    echo = dict(inp.echo, unmounted_clearance_um=inp.unmounted[0] / _UM,
                clearance_reduction_um=reduction / _UM, fit_reduction_um=float(p.fit_reduction) / _UM,
                thermal_reduction_um=float(p.thermal_reduction) / _UM,
                centrifugal_reduction_um=float(p.centrifugal_reduction) / _UM,
                assembled_interference_um=assembled_interference / _UM, operating_interference_um=interference / _UM)
    notes = [n for n in r.warnings if "negative" not in n]  # an angular set runs preloaded by design
    return MountedSet(new, interference, clearance, echo, notes)


def operating_bearing(bearing, speed=0.0, options=None):
    """The bearing at its probable operating clearance under the mounting ``options`` (name -> text as
    given, None for not given), and the JSON entries to add (``operating_clearance_um`` and the range);
    ``(bearing, {})`` without options."""
    given = {k: v for k, v in (options or {}).items() if v is not None}
    if not given:
        return bearing, {}
    from ..mounting import chain

    inp = mounted_inputs(bearing, **given, speed=float(speed), require=True)
    r = chain.operating_range(inp.unmounted, inp.inner, inp.outer, inp.mounting, inp.conditions)
    e = float(r.probable.operating_clearance)  # zero or negative: a preloaded bearing, solved as one (issue 30)
    doc = {"operating_clearance_um": e / _UM,
           "operating_clearance_min_um": float(r.least.operating_clearance) / _UM,
           "operating_clearance_max_um": float(r.largest.operating_clearance) / _UM,
           "unmounted_clearance_um": [inp.unmounted[0] / _UM, inp.unmounted[1] / _UM],
           "mounting": inp.echo, "mounting_warnings": list(r.warnings)}
    return bearing.replace(radial_clearance=e), doc


#: the mounting fields (``registry.MOUNTING``) by name
NAMES = ("shaft_fit", "housing_fit", "shaft_interference", "housing_interference", "shaft_bore",
         "housing_outside_diameter", "shaft_material", "housing_material", "tolerance_class", "clearance_class",
         "inner_ring_temperature", "outer_ring_temperature", "ball_temperature", "shaft_temperature",
         "housing_temperature")


def operating_clearance(bearing, given, speed=0.0):
    """The operating clearance of ``bearing`` under the mounting inputs ``given`` (field name -> text as
    typed; other names are left out) as the JSON entries of :func:`operating_bearing`
    (``operating_clearance_um`` probable, ``_min_um``, ``_max_um``, ``unmounted_clearance_um``,
    ``mounting``, ``mounting_warnings``); ``{}`` without mounting inputs. A negative clearance (a
    preload) is reported, not refused: for a model that does not take the clearance (friction)."""
    given = {k: v for k, v in given.items() if v is not None and k in NAMES}
    if not given:
        return {}
    from ..mounting import chain

    inp = mounted_inputs(bearing, **given, speed=float(speed), require=True)
    r = chain.operating_range(inp.unmounted, inp.inner, inp.outer, inp.mounting, inp.conditions)
    return {"operating_clearance_um": float(r.probable.operating_clearance) / _UM,
            "operating_clearance_min_um": float(r.least.operating_clearance) / _UM,
            "operating_clearance_max_um": float(r.largest.operating_clearance) / _UM,
            "unmounted_clearance_um": [inp.unmounted[0] / _UM, inp.unmounted[1] / _UM],
            "mounting": inp.echo, "mounting_warnings": list(r.warnings)}
