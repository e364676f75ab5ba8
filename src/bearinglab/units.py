"""Units at the boundary: SI conversion constants, converters, and parsing of quantities with units.

The physics modules work in coherent SI (m, N, Pa, rad, rad/s). Only this module (and the command
line, input files and reports that call it) knows about other units.

Constants
---------
MM, CM, UM              metres per millimetre, centimetre, micrometre
KGF                     newtons per kilogram-force (standard gravity)
RPM                     rad/s per rev/min
DEG                     radians per degree

Converters
----------
from_rpm, to_rpm        shaft speed rev/min <-> rad/s
from_kgf, to_kgf        force kgf <-> N
to_dms                  angle in radians -> (degrees, minutes, seconds)
format_dms              angle in radians -> ``14°28'03.38"``

Parsing (pint is imported on first use, so ``import bearinglab`` stays light)
-----------------------------------------------------------------------------
parse_quantity          ``"2 kgf"`` -> 19.6133 (N), checking the dimension
parse_values            ``"2.5kN:45kN:2.5kN"`` or ``"0,3000,6000rpm"`` -> array in SI
parse_temperature       ``"70 degC"``, ``"343.15 K"``, ``"158 degF"`` -> 343.15 (K)
MAX_QUANTITY_TEXT       the longest text of one quantity [characters]

One grammar at every boundary (issue 29): one number of ASCII digits (an optional sign, a decimal point,
an exponent; no digit grouping), then one unit of the expected kind, with no plain factor (an angle, a
percentage or a ratio that cancels, multiplying another kind). Nothing is evaluated: pint reads the unit
only. Underflow and overflow are errors.
"""

from __future__ import annotations

import math
import re

import numpy as np

from . import _bounds
from .errors import InputError

__all__ = [
    "CM",
    "DEG",
    "KGF",
    "KINDS",
    "MAX_QUANTITY_TEXT",
    "MM",
    "RPM",
    "STANDARD_GRAVITY",
    "UM",
    "format_dms",
    "from_kgf",
    "from_rpm",
    "parse_quantity",
    "parse_temperature",
    "parse_values",
    "to_dms",
    "to_kgf",
    "to_rpm",
]

MM = 1e-3
CM = 1e-2
UM = 1e-6
STANDARD_GRAVITY = 9.80665  # m/s^2, CGPM 1901; defines the kilogram-force
KGF = STANDARD_GRAVITY
RPM = 2.0 * math.pi / 60.0
DEG = math.pi / 180.0


def from_rpm(speed_rpm):
    """Shaft speed in rev/min -> rad/s.

    Parameters
    ----------
    speed_rpm : array_like
        Speed. [rev/min]

    Returns
    -------
    ndarray
        Speed. [rad/s]

    Examples
    --------
    >>> round(float(from_rpm(3000.0)), 4)
    314.1593
    """
    return np.asarray(speed_rpm, dtype=float) * RPM


def to_rpm(speed):
    """Shaft speed in rad/s -> rev/min.

    Parameters
    ----------
    speed : array_like
        Speed. [rad/s]

    Returns
    -------
    ndarray
        Speed. [rev/min]
    """
    return np.asarray(speed, dtype=float) / RPM


def from_kgf(force_kgf):
    """Force in kilogram-force -> N.

    Parameters
    ----------
    force_kgf : array_like
        Force. [kgf]

    Returns
    -------
    ndarray
        Force. [N]
    """
    return np.asarray(force_kgf, dtype=float) * KGF


def to_kgf(force):
    """Force in N -> kilogram-force.

    Parameters
    ----------
    force : array_like
        Force. [N]

    Returns
    -------
    ndarray
        Force. [kgf]
    """
    return np.asarray(force, dtype=float) / KGF


def to_dms(angle, *, pi=math.pi, truncate=False):
    """Angle in radians -> (degrees, minutes, seconds).

    Parameters
    ----------
    angle : float
        Angle. [rad]
    pi : float, optional
        Value of pi used to convert to degrees. [-]
    truncate : bool, optional
        Truncate the seconds to whole seconds instead of keeping the fraction.

    Returns
    -------
    tuple
        Degrees (int), minutes (int), seconds (float).

    Notes
    -----
    ``pi`` and ``truncate`` exist for the legacy reproduction of printed tables (spec 000 section 8,
    which converts with pi = 3.14 and truncates the seconds). A negative angle gives three
    non-positive parts, so that degrees + minutes / 60 + seconds / 3600 is the angle.

    Examples
    --------
    >>> to_dms(math.radians(14.5))
    (14, 30, 0.0)
    >>> to_dms(math.radians(-0.5))
    (0, -30, -0.0)
    """
    angle, pi = _finite_number("angle", angle, "rad"), _finite_number("pi", pi, "-")
    if not pi > 0:
        raise InputError(f"pi must be > 0 [-], got {pi!r}")
    deg = angle * 180.0 / pi
    if not math.isfinite(deg):
        raise InputError(f"angle must be finite in degrees [rad], got {angle!r}")
    sign = -1 if deg < 0 else 1
    deg = abs(deg)
    d = int(deg)
    m = int((deg - d) * 60.0)
    s = (deg - d - m / 60.0) * 3600.0
    if truncate:
        s = float(math.floor(s + 1e-9))
    elif s >= 59.995:  # keep "60.00" out of a rounded display
        s, m = 0.0, m + 1
        if m == 60:
            m, d = 0, d + 1
    return sign * d, sign * m, sign * s


def _finite_number(name, value, unit):
    """``value`` as a finite float, or an InputError naming ``name``."""
    try:
        x = float(value)
    except (TypeError, ValueError, OverflowError):
        raise InputError(f"{name} must be a finite number [{unit}], got {value!r}") from None
    if not math.isfinite(x):
        raise InputError(f"{name} must be finite [{unit}], got {value!r}")
    return x


def format_dms(angle, *, digits=2):
    """Angle in radians -> ``14°28'03.38"``, the seconds rounded to ``digits`` decimals.

    Parameters
    ----------
    angle : float
        Angle. [rad]
    digits : int, optional
        Decimals of the seconds.

    Returns
    -------
    str
        The angle as degrees, minutes and seconds; :func:`parse_quantity` reads it back.

    Examples
    --------
    >>> format_dms(math.radians(12.0))
    '12°00\\'00.00"'
    >>> format_dms(math.radians(-0.5)), format_dms(math.radians(14.99999), digits=0)
    ('-0°30\\'00.00"', '15°00\\'00"')
    """
    angle = _finite_number("angle", angle, "rad")
    if isinstance(digits, bool) or not isinstance(digits, (int, np.integer)) or not 0 <= digits <= 15:
        raise InputError(f"digits must be an integer in [0, 15] [-] (the decimals of the seconds), got {digits!r}")
    sign = "-" if angle < 0 else ""
    d, m, s = to_dms(abs(angle))
    s = round(s, digits)
    if s >= 60.0:  # rounding to fewer digits can reach 60: carry
        s, m = s - 60.0, m + 1
    if m >= 60:
        m, d = m - 60, d + 1
    width = 3 + digits if digits else 2
    return f"{sign}{d}°{m:02d}'{s:0{width}.{digits}f}\""


# --------------------------------------------------------------------------- parsing with pint

# kind -> (pint dimensionality, SI unit to convert to, examples for messages)
KINDS = {
    "length": ("[length]", "m", "'2 mm', '0.2 cm'"),
    "force": ("[force]", "N", "'19.6 N', '2 kgf', '20 kN'"),
    "mass": ("[mass]", "kg", "'2 kg', '500 g'"),
    "angle": ("", "rad", "'12 deg', '0.21 rad', '20 urad'"),
    "speed": ("1/[time]", "rad/s", "'3000 rpm', '50 Hz', '314 rad/s'"),
    "pressure": ("[pressure]", "Pa", "'208 GPa', '2.1e5 MPa'"),
    "density": ("[mass]/[length]**3", "kg/m**3", "'7850 kg/m^3', '3.2 g/cm^3'"),
    "torque": ("[force]*[length]", "N*m", "'0.07 N*mm'"),
    "kinematic_viscosity": ("[length]**2/[time]", "m**2/s", "'20 cSt', '2e-5 m^2/s'"),
    "dynamic_viscosity": ("[pressure]*[time]", "Pa*s", "'0.04 Pa*s', '40 mPa*s', '40 cP'"),
    "inverse_pressure": ("1/[pressure]", "1/Pa", "'2.3e-8 m^2/N', '23 1/GPa'"),
    "thermal_resistance": ("[temperature]/[power]", "K/W", "'0.5 K/W'"),
    "volume_flow": ("[length]**3/[time]", "m**3/s", "'0.5 l/min', '1e-5 m^3/s'"),
    "specific_heat": ("[energy]/[mass]/[temperature]", "J/(kg*K)", "'1900 J/(kg*K)'"),
    "heat_flux": ("[power]/[length]**2", "W/m**2", "'16 kW/m^2'"),
    "dimensionless": ("", "", "'0.52'"),
    # the shaft-system file (issue 33): supports, gears, temperatures, masses
    "stiffness": ("[force]/[length]", "N/m", "'200 N/um', '2e8 N/m'"),
    "rotational_stiffness": ("[force]*[length]", "N*m", "'1e5 N*m/rad', '100 N*m/mrad'"),
    "power": ("[power]", "W", "'5 kW', '7.5 hp'"),
    "temperature": ("[temperature]", "K", "'60 degC', '333 K'"),
    "thermal_expansion": ("1/[temperature]", "1/K", "'12e-6 1/K', '12 um/(m*K)'"),
    "moment_of_inertia": ("[mass]*[length]**2", "kg*m**2", "'0.02 kg*m^2'"),
}

_ANGLE_UNITS = ("radian", "degree", "arcminute", "arcsecond", "revolution", "turn")
# the dimensionless units a ratio may be written in (a field of kind "dimensionless": '2 %')
_RATIO_UNITS = ("percent", "permille", "ppm")
#: The longest text of one quantity [characters]: '228.0419 GPa' has 12, 'J/(kg*K)' units 8. A longer text
#: is no quantity a user typed, and is refused before any pattern or pint looks at it.
MAX_QUANTITY_TEXT = 100
_SMALLEST = 5e-324  # the smallest positive float: a number below it is read as 0 (an underflow)
# an angle written in degrees, minutes and seconds: 14°28'03.38", 14° 28′ 3.38″, 12 deg 30 arcmin
_DMS = re.compile(r"^\s*([-+]?)\s*([0-9]+(?:\.[0-9]*)?)\s*(?:°|deg\b)\s*(?:([0-9]+(?:\.[0-9]*)?)\s*(?:′|'|arcmin\b)\s*)?"
                  r"(?:([0-9]+(?:\.[0-9]*)?)\s*(?:″|\"|''|arcsec\b)\s*)?$", re.ASCII)
# a number that is not an exponent (m^3, m**3) nor part of a name
_STANDALONE_NUMBER = re.compile(r"(?<![\w.^*])(?<![\^*][-+])(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?",
                                re.ASCII)
_registry = None


def _ureg():
    global _registry
    if _registry is None:
        import pint

        _registry = pint.UnitRegistry(autoconvert_offset_to_baseunit=True)
        _registry.formatter.default_format = "~P"
    return _registry


# spellings engineers write that pint does not know (or reads otherwise), and what they mean
_SPELLINGS = (
    (re.compile(r"(?<![\w/])(?:rpm|r/min|rev/min|U/min|1/min|min\^-1|min-1)(?![\w/^*])", re.IGNORECASE),
     " revolution/minute"),
    (re.compile(r"(?<![\w/])(?:rps|r/s|rev/s)(?![\w/^*])", re.IGNORECASE), " revolution/s"),
    (re.compile(r"(?<![\w/])kgf(?!\w)", re.IGNORECASE), "kgf"),
    (re.compile(r"(?<![\w/])kp(?!\w)"), "kilopond"),
    (re.compile(r"(?<![\w/])cSt(?!\w)"), "centistokes"),
    # torques as engineers write them: Nm, Nmm, kNm, mNm (capital N: "nm" stays the nanometre)
    (re.compile(r"(?<![\w/])([kmM]?)N(mm|m)(?![\w/^*])"), r"\1N*\2"),
    (re.compile(r"(?<![\w/.^*])1\s*/\s*(?=[A-Za-z])"), " /"),  # "50 1/s" is 50 per second, one number
)
# exponents as superscripts: mm²/s, kg/m³, s⁻¹
_SUPERSCRIPT = re.compile("(⁻?)([¹²³⁴⁵⁶⁷⁸⁹])")
_SUPERSCRIPT_DIGITS = "¹²³⁴⁵⁶⁷⁸⁹"


def _normalise(text: str) -> str:
    t = text.strip().replace("µ", "u").replace("μ", "u").replace("·", "*").replace("π", " pi ")
    t = _SUPERSCRIPT.sub(lambda m: "^" + "-" * bool(m.group(1)) + str(_SUPERSCRIPT_DIGITS.index(m.group(2)) + 1), t)
    t = re.sub(r"°\s*([CF])\b", r" deg\1", t).replace("°", " deg ")  # 70 °C is degC, not deg * coulomb
    t = t.replace("′", " arcmin ").replace("″", " arcsec ").replace("−", "-")
    # a rotation frequency in Hz means revolutions per second, not radians per second
    t = re.sub(r"(?<![A-Za-z])(k?)Hz\b", lambda m: " revolution/s" if not m.group(1) else " kilorevolution/s", t)
    for pattern, replacement in _SPELLINGS:
        t = pattern.sub(replacement, t)
    return t


# "2,5 kN": one comma between two digits, no unit before it -- a decimal comma or a list of two?
_AMBIGUOUS_COMMA = re.compile(r"^\s*([-+]?[0-9]+),([0-9]+)\s*([^,;:]*)$", re.ASCII)


def _reject_decimal_comma(text, name):
    m = _AMBIGUOUS_COMMA.match(text)
    if m:
        whole, frac, unit = m.group(1), m.group(2), m.group(3).strip()
        u = f" {unit}" if unit else ""
        raise InputError(
            f"{name}: {text!r} is ambiguous: write '{whole}.{frac}{u}' for one value (a decimal point, "
            f"not a comma) or '{whole}{u}, {frac}{u}' for a list of two values"
        )


def _shown(text):
    """``text`` for a message: its repr, cut after 40 characters."""
    return repr(text) if len(text) <= 40 else repr(text[:40]) + f"... ({len(text)} characters)"


def _check_text(text, name, what="a quantity"):
    """The checks of a quantity's text before any pattern reads it: its length, its digits (ASCII only:
    ``'٥ kN'`` is no number here, though Python's ``float`` reads it) and no digit grouping."""
    if len(text) > MAX_QUANTITY_TEXT:
        raise InputError(f"{name}: {_shown(text)} is too long for {what} (at most {MAX_QUANTITY_TEXT} "
                         "characters: one number and one unit)")
    foreign = next((c for c in text if c.isnumeric() and not c.isascii() and c not in _SUPERSCRIPT_DIGITS), None)
    if foreign is not None:
        raise InputError(f"{name}: cannot read {text!r} as {what}: {foreign!r} is not an ASCII digit; write "
                         "the number with the digits 0-9")
    grouped = re.search(r"[0-9]_[0-9]", text)
    if grouped:
        raise InputError(f"{name}: cannot read {text!r} as {what}: digits are not grouped; write the number "
                         f"without '_' (e.g. 1000, 1e6)")


def _literal(number, text, name):
    """The float of a number literal of the grammar; an overflow or an underflow is an error."""
    magnitude = float(number)
    if not math.isfinite(magnitude):  # 1e309
        raise InputError(f"{name}: {text!r} is not a finite quantity")
    mantissa = re.split(r"[eE]", number)[0]
    if magnitude == 0.0 and re.search(r"[1-9]", mantissa):  # 1e-400: not 0, but read as 0
        raise InputError(f"{name}: {text!r} underflows: {number} is below the smallest number computed with "
                         f"({_SMALLEST:.3g}); write 0 or a larger value")
    return magnitude


def parse_quantity(value, kind, name, *, default_unit=None):
    """Parse a quantity written by a user and return it in coherent SI.

    Parameters
    ----------
    value : str or float
        ``"2 kgf"``, ``"3000 rpm"``, ``"12 deg"``; a bare number only when ``default_unit`` is given
        (or for ``kind="dimensionless"``).
    kind : str
        One of :data:`KINDS`.
    name : str
        The parameter's name, used in error messages.
    default_unit : str, optional
        Unit of a bare number.

    Returns
    -------
    float
        The value in SI (m, N, kg, rad, rad/s, Pa, kg/m³, N·m, m²/s).

    Raises
    ------
    InputError
        The text does not parse, has no unit where one is needed, has the wrong dimension, or is not
        finite in SI units, or underflows.

    Notes
    -----
    The text is ONE number (``-5``, ``2.5``, ``.5``, ``1e-3``; ASCII digits, one sign at most, no digit
    grouping) followed by ONE unit of the expected kind: unit names joined by ``*``, ``/`` or a space,
    each with an optional one-digit exponent (``mm^2/s``, ``kg/m**3``, ``N*m``, ``N·m``, ``1/min``,
    ``mm²/s``). pint converts the unit only; the text is never evaluated as an expression, so
    ``1.2.3 N``, ``--5 N``, a bare ``N``, ``kN*kN/kN``, ``2 pi kN`` (a constant), ``9**9**9 K`` and
    ``10**308*10 N`` are refused, as are non-ASCII digits (``٥ kN``), ``1_000 N``, a value that overflows
    (``1e308 kN``) or underflows, a number that is not 0 read as 0 (``1e-400 N``), in SI. A unit holds no
    plain factor: an angle, a percentage or a ratio of two units of one dimension multiplies no other
    kind (``2 turn kgf``, ``2 kgf %``, ``10000 % rpm``, ``2 kgf h/s`` are refused); an angle is the
    unit of an angle and the numerator of a speed, a percentage (``%``, ``permille``, ``ppm``) the unit
    of a plain number. Angles may also be written in degrees, minutes and seconds (``14°28'03.38"``).

    Examples
    --------
    >>> round(parse_quantity("2 kgf", "force", "axial-load"), 5)
    19.6133
    >>> round(parse_quantity("3000 rpm", "speed", "speed"), 4)
    314.1593
    >>> parse_quantity("2 m", "force", "axial-load")
    Traceback (most recent call last):
    ...
    bearinglab.errors.InputError: axial-load: '2 m' is a length, expected a force (e.g. '19.6 N', '2 kgf', '20 kN')
    """
    if kind not in KINDS:
        raise InputError(f"kind must be one of {sorted(KINDS)}, got {kind!r}")
    dim, si, examples = KINDS[kind]
    ureg = _ureg()
    if isinstance(value, bool):
        raise InputError(f"{name}: expected a quantity, got {value!r}")
    if isinstance(value, (int, float, np.integer, np.floating)):
        if isinstance(value, (int, np.integer)) and not isinstance(value, bool) and abs(int(value)) > 2**1023:
            raise InputError(f"{name}: {value!r} is not a finite quantity")
        if not np.isfinite(value):
            raise InputError(f"{name}: {value!r} is not a finite quantity")
        if kind == "dimensionless":
            return float(value)
        if default_unit is None:
            raise InputError(f"{name}: {value!r} has no unit; write it with one, e.g. {examples}")
        text = f"{value} {default_unit}"
    elif isinstance(value, str):
        text = value
    else:
        raise InputError(f"{name}: expected a quantity such as {examples}, got {value!r}")
    _check_text(text, name)
    _reject_decimal_comma(text, name)
    dms = _DMS.match(text) if kind == "angle" else None
    if dms and (dms.group(3) or dms.group(4)):  # 14°28'03.38": pint would multiply the three parts
        deg = float(dms.group(2)) + float(dms.group(3) or 0.0) / 60.0 + float(dms.group(4) or 0.0) / 3600.0
        return _finite(math.radians(-deg if dms.group(1) == "-" else deg), text, name, deg)
    if len(_STANDALONE_NUMBER.findall(_normalise(text))) > 1:  # pint reads "1 000 N" as 1 * 0 N and "2 3 kgf" as 6 kgf
        raise InputError(f"{name}: {text!r} holds more than one number; write one number and its unit, e.g. {examples}")
    q = _quantity(text, name, examples, kind)
    if q.dimensionless and not q.unit_items() and kind != "dimensionless":
        if default_unit is None:
            raise InputError(f"{name}: {text!r} has no unit; write it with one, e.g. {examples}")
        q = _quantity(f"{q.magnitude!r} {default_unit}", name, examples, kind)
    magnitude = q.magnitude
    if kind in ("angle", "dimensionless"):
        is_angle = any(_root(u) in _ANGLE_UNITS for u, _exp in q.unit_items())
        if not q.dimensionless:
            raise InputError(
                f"{name}: {text!r} is a {_describe(q)}, expected {'an angle' if kind == 'angle' else 'a plain number'} (e.g. {examples})"
            )
        if kind == "angle" and not is_angle:
            raise InputError(f"{name}: {text!r} is not an angle; write e.g. {examples}")
        return _finite(q.to("radian" if kind == "angle" else "").magnitude, text, name, magnitude)
    if not q.check(dim):
        raise InputError(f"{name}: {text!r} is a {_describe(q)}, expected a {kind.replace('_', ' ')} (e.g. {examples})")
    if kind == "speed" and not any(a in u for u, _exp in q.unit_items() for a in _ANGLE_UNITS):
        # a rotational speed written as a plain reciprocal time ("50 1/s", "50 /s") counts revolutions,
        # as n in DIN/ISO drawings and as Hz does here; reading it as rad/s would slip a factor of 2 pi
        q = q * ureg.revolution
    return _finite(q.to(si).magnitude, text, name, magnitude)


def _finite(x, text, name, magnitude=None):
    """``x`` as a float, refused when the conversion to SI overflowed (``1e308 kN``) or underflowed to 0
    (``1e-320 um``: a number that is not 0 read as 0)."""
    x = float(x)
    if not math.isfinite(x):
        raise InputError(f"{name}: {text!r} is not a finite quantity (it overflows in SI units)")
    if magnitude and x == 0.0:
        raise InputError(f"{name}: {text!r} underflows in SI units (below {_SMALLEST:.3g}); write 0 or a "
                         "larger value")
    return x


# The grammar of a quantity (issue 20, issue 29): ONE numeric literal of ASCII digits, then a unit
# expression of unit names joined by '*', '/' or spaces, each with an optional one-digit exponent ('^2',
# '**-1'). pint converts only the unit; it never evaluates the text, which it would read as an expression:
# '1.2.3 N' as 1.2 * 0.3 N, '--5 N' as +5 N, 'N' as 1 N, '10**308*10 N' as an overflow, 'pi kN' as
# 3141.6 N, '9**9**9 K' as minutes of big-integer arithmetic.
_NUMBER_TEXT = r"[-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?"
_UNIT_NAME = r"(?:[A-Za-z]\w*|%)"
_UNIT_TERM = rf"{_UNIT_NAME}(?:\s*(?:\^|\*\*)\s*[-+]?[1-9](?![0-9]))?"
_UNIT_PRODUCT = rf"{_UNIT_TERM}(?:(?:\s*[*/]\s*|\s+){_UNIT_TERM})*"
# one level of brackets, as engineers write a denominator: J/(kg*K), W/(m^2*K)
_UNIT_FACTOR = rf"(?:{_UNIT_TERM}|\(\s*{_UNIT_PRODUCT}\s*\)(?:\s*(?:\^|\*\*)\s*[-+]?[1-9](?![0-9]))?)"
_UNIT_EXPR = rf"(?:/\s*)?{_UNIT_FACTOR}(?:(?:\s*[*/]\s*|\s+){_UNIT_FACTOR})*"
_QUANTITY = re.compile(rf"^\s*({_NUMBER_TEXT})\s*({_UNIT_EXPR})?\s*$", re.ASCII)
_NOT_FINITE = re.compile(r"^\s*[-+]?(?:nan|inf|infinity)(?![\w.])", re.IGNORECASE | re.ASCII)
_UNIT_ONLY = re.compile(rf"^\s*{_UNIT_EXPR}\s*$", re.ASCII)
# dimensionless names that are units, not numbers in disguise (the constants pi, ln10, ... are refused)
_DIMENSIONLESS_UNITS = (*_ANGLE_UNITS, *_RATIO_UNITS, "dimensionless")
_MAX_UNIT_NAMES = 8  # 'J/(kg*K)' has 3, 'W/(m^2*K)' 3: more is no unit a user typed
_constants = None


def _constant_names():
    """The canonical names of pint's physical and mathematical constants (its ``constants_en.txt``),
    but the standard atmosphere, which is a unit of pressure as well."""
    global _constants
    if _constants is None:
        from importlib import resources

        names = {"pi", "eulers_number"}
        try:
            text = (resources.files("pint") / "constants_en.txt").read_text(encoding="utf-8")
        except (OSError, ModuleNotFoundError):  # another pint layout: the mathematical ones still refused
            text = ""
        for line in text.splitlines():
            m = re.match(r"^([^\W\d]\w*)\s*=", line)
            if m:
                names.add(m.group(1))
        _constants = frozenset(names - {"standard_atmosphere"})
    return _constants


def _root(unit_name):
    """The unit's name without its prefix: 'kilorevolution' -> 'revolution', 'microradian' -> 'radian'."""
    parsed = _ureg().parse_unit_name(unit_name)
    return parsed[0][1] if parsed else unit_name


def _quantity(text, name, examples, kind=None):
    """``text`` -> a pint Quantity by the grammar above, or an InputError naming ``name``. With ``kind``,
    the unit may hold no plain factor (:func:`_plain_factor`)."""
    ureg = _ureg()
    t = _normalise(text)
    m = _QUANTITY.match(t)
    if not m and _NOT_FINITE.match(t):
        raise InputError(f"{name}: {text!r} is not a finite quantity")
    if not m:
        why = ("it has no number" if _UNIT_ONLY.match(t)
               else "write one number and one unit, without operators or constants")
        raise InputError(f"{name}: cannot read {text!r} as a quantity: {why} (e.g. {examples})")
    number, unit = m.group(1), (m.group(2) or "").strip()
    magnitude = _literal(number, text, name)
    if not unit:
        return ureg.Quantity(magnitude)
    words = re.findall(_UNIT_NAME, unit, re.ASCII)
    repeated = next((w for w in words if words.count(w) > 1), None)
    if repeated:  # 'kN*kN/kN': an expression, not a unit
        raise InputError(f"{name}: cannot read {text!r} as a quantity: {repeated!r} appears twice in the unit")
    if len(words) > _MAX_UNIT_NAMES:
        raise InputError(f"{name}: cannot read {text!r} as a quantity: more than {_MAX_UNIT_NAMES} unit names")
    try:
        q = ureg.Quantity(magnitude, "1" + unit if unit.startswith("/") else unit)
        items = list(q.unit_items())
    except Exception as exc:  # pint raises several unrelated exception types
        raise InputError(f"{name}: cannot read {text!r} as a quantity (e.g. {examples})") from exc
    for unit_name, _exp in items:
        root = _root(unit_name)
        constant = root in _constant_names()
        if not constant and ureg.get_dimensionality(unit_name) == ureg.get_dimensionality(""):
            constant = not any(a in unit_name for a in _DIMENSIONLESS_UNITS)
        if constant:  # '2 pi kN' is a product with a number in disguise
            raise InputError(f"{name}: cannot read {text!r} as a quantity: {unit_name!r} is a constant, not a "
                             f"unit; write one number and its unit (e.g. {examples})")
    if kind is not None:
        _plain_factor(items, kind, text, name, examples)
    return q


def _plain_factor(items, kind, text, name, examples):
    """Refuse a unit that holds a plain factor: a dimensionless unit (an angle, a percentage) or units
    whose dimensions cancel (``h/s``, ``km/m``) multiplying a unit of the kind. ``2 kgf %`` would be
    0.196 N, ``2 turn kgf`` 123 N and ``2 kgf h/s`` 70 608 N: numbers silently read as other numbers.
    The one dimensionless unit a kind is written in is allowed: the angle of an angle or of a speed
    (``rad/s``, ``rpm``), the percentage of a plain number."""
    import itertools

    ureg = _ureg()
    dims = {u: dict(ureg.get_dimensionality(u)) for u, _exp in items}
    rest = list(items)
    allowed = _ANGLE_UNITS if kind in ("angle", "speed") else _RATIO_UNITS if kind == "dimensionless" else ()
    own = next((i for i, (u, exp) in enumerate(rest) if not dims[u] and exp == 1 and _root(u) in allowed), None)
    if own is not None:
        del rest[own]
    if kind == "dimensionless" and any(not dims[u] and _root(u) in _ANGLE_UNITS for u, _exp in rest):
        raise InputError(f"{name}: {text!r} is an angle, expected a plain number (e.g. {examples})")
    # the whole unit dimensionless ('2 %' for a force) is the dimension check's to word, unless a
    # dimensionless unit is what the kind takes
    whole = own is not None or kind == "dimensionless"
    for size in range(1, len(rest) + whole):
        for subset in itertools.combinations(rest, size):
            total = {}
            for u, exp in subset:
                for d, e in dims[u].items():
                    total[d] = total.get(d, 0) + e * exp
            if not any(total.values()):
                shown = _unit_text(subset)
                raise InputError(f"{name}: cannot read {text!r} as a quantity: {shown!r} is a plain factor (an "
                                 f"angle, a ratio or a percentage), not part of a {kind.replace('_', ' ')} unit; "
                                 f"write one number and one unit (e.g. {examples})")


def _unit_text(items):
    """Unit items as a unit expression: (('hour', 1), ('second', -1)) -> 'hour/second'."""
    def term(u, exp):
        return u if abs(exp) == 1 else f"{u}^{abs(exp):g}"

    top = "*".join(term(u, e) for u, e in items if e > 0) or "1"
    bottom = [term(u, e) for u, e in items if e < 0]
    return top + "".join("/" + b for b in bottom)


def _describe(q):
    for kind, (dim, _si, _ex) in KINDS.items():
        if dim and q.check(dim):
            return kind.replace("_", " ")
    return f"quantity in {q.units:~P}"  # the unit it was read in, not pint's dimension symbols


_NUMBER_UNIT = re.compile(rf"^\s*({_NUMBER_TEXT})\s*(.*)$", re.ASCII | re.DOTALL)


def _split_unit(item: str):
    m = _NUMBER_UNIT.match(item)
    if not m:
        return None, None
    return m.group(1), m.group(2).strip()


# ----------------------------------------------------------------------------- temperatures
_ZERO_CELSIUS = 273.15  # K at 0 degC
_TEMPERATURE_UNITS = {"degC": "C", "°C": "C", "C": "C", "K": "K", "degF": "F", "°F": "F", "F": "F"}
_TEMPERATURE = re.compile(rf"^\s*({_NUMBER_TEXT})\s*(degC|°C|° C|C|K|degF|°F|° F|F)?\s*$", re.ASCII)


def parse_temperature(value, name, *, default_unit=None):
    """Parse a temperature written by a user: one number and ``degC``, ``°C``, ``degF``, ``°F`` or ``K``.

    Parameters
    ----------
    value : str or float
        ``"70 degC"``, ``"343.15 K"``, ``"158 degF"``; a bare number only with ``default_unit``.
    name : str
        The parameter's name, used in error messages.
    default_unit : {"degC", "degF", "K"}, optional
        The unit of a bare number.

    Returns
    -------
    float
        The absolute temperature. [K] (Not checked against absolute zero: the caller's range says.)

    Raises
    ------
    InputError
        Not one number with one of those units (by the grammar of :func:`parse_quantity`: ASCII
        digits, no expression, no digit grouping, nothing evaluated), or not finite.

    Notes
    -----
    pint reads ``'5,5 degC'`` as 55 degC, ``'1 000 K'`` as 0 K and ``'1.2.3 degC'`` as 0.36 degC, and
    evaluates ``'9**9**9 K'`` for minutes: none of them reaches pint here. The word ``auto`` (a
    temperature from the thermal balance) is the caller's to read, where it is offered.

    Examples
    --------
    >>> parse_temperature("70 degC", "temperature")
    343.15
    >>> round(parse_temperature("158 degF", "temperature"), 2)
    343.15
    >>> parse_temperature("60", "inner-ring-temperature", default_unit="degC")
    333.15
    """
    examples = "'70 degC', '343.15 K', '158 degF'"
    if isinstance(value, bool) or not isinstance(value, (str, int, float, np.integer, np.floating)):
        raise InputError(f"{name}: expected a temperature such as {examples}, got {value!r}")
    if not isinstance(value, str):
        if not np.isfinite(value) or abs(float(value)) > 1e300:
            raise InputError(f"{name}: {value!r} is not a finite temperature")
        value = f"{float(value)!r}"
    text = value
    _check_text(text, name, "a temperature")
    comma = _AMBIGUOUS_COMMA.match(text)
    if comma:  # '5,5 degC': pint reads 55 degC; one temperature has a decimal point
        unit = f" {comma.group(3).strip()}" if comma.group(3).strip() else ""
        raise InputError(f"{name}: {text!r} has a comma: write one temperature with a decimal point, e.g. "
                         f"'{comma.group(1)}.{comma.group(2)}{unit}'")
    m = _TEMPERATURE.match(text)
    if not m:
        raise InputError(f"{name}: cannot read {text!r} as a temperature: write one number and degC, degF or "
                         f"K (e.g. {examples})")
    number, unit = m.group(1), m.group(2)
    v = _literal(number, text, name)
    if unit is None:
        if default_unit is None:
            raise InputError(f"{name}: {text!r} has no unit; write it with degC, degF or K (e.g. {examples})")
        unit = default_unit
    scale = _TEMPERATURE_UNITS[unit.replace(" ", "")]
    kelvin = {"C": v + _ZERO_CELSIUS, "K": v, "F": (v - 32.0) / 1.8 + _ZERO_CELSIUS}[scale]
    if not math.isfinite(kelvin):
        raise InputError(f"{name}: {text!r} is not a finite temperature")
    return kelvin


def parse_values(text, kind, name, *, limit=None):
    """Parse one value, a list ``a,b,cUNIT`` or a range ``start:stop:step`` into an SI array.

    Parameters
    ----------
    text : str
        ``"2 kgf"``, ``"1 kN, 500 N"``, ``"0,3000,6000rpm"``, ``"1 kN; 2 kN"`` or ``"2.5kN:45kN:2.5kN"``.
    kind : str
        One of :data:`KINDS`.
    name : str
        The parameter's name, used in error messages.
    limit : int, optional
        The most values accepted (a command's :data:`bearinglab._bounds.MAX_CASES`); by default
        :data:`bearinglab._bounds.MAX_RANGE_VALUES`. A range is counted before it is built.

    Returns
    -------
    ndarray
        The values in SI (see :func:`parse_quantity`).

    Notes
    -----
    Each item is one quantity by the grammar of :func:`parse_quantity`. A unit written only on the last
    item applies to all items without one. A range includes its end point when the steps land on it; it
    may hold at most :data:`bearinglab._bounds.MAX_RANGE_VALUES` values (counted before it is built,
    without overflow: ``0 kN:1e300 kN:1e-300 kN`` is refused). Items are separated by commas or
    semicolons. One comma between two digits (``"2,5 kN"``) could be a decimal comma or a list of two
    values; it is rejected with both spellings in the message, never guessed.

    Examples
    --------
    >>> parse_values("2.5kN:10kN:2.5kN", "force", "axial-load")
    array([ 2500.,  5000.,  7500., 10000.])
    >>> parse_values("0,3000,6000rpm", "speed", "speed").round(3)
    array([  0.   , 314.159, 628.319])
    """
    text = str(text).strip()
    limit = _bounds.MAX_RANGE_VALUES if limit is None else limit
    _reject_decimal_comma(text, name)
    sep = ":" if ":" in text else (";" if ";" in text else ",")
    items = [s.strip() for s in text.split(sep) if s.strip()]
    if not items:
        raise InputError(f"{name}: no values in {text!r}")
    if len(items) > limit:  # counted before each item is parsed
        raise InputError(f"{name}: {len(items)} values, more than the limit of {limit}")
    if sep == ":" and len(items) != 3:
        raise InputError(f"{name}: a range is start:stop:step, got {text!r}")
    parsed = [_split_unit(s) for s in items]
    last_unit = parsed[-1][1] or None
    values = []
    for item, (num, unit) in zip(items, parsed):
        if num is not None and not unit and last_unit:
            item = f"{_literal(num, item, name)} {last_unit}"
        values.append(parse_quantity(item, kind, name))
    if sep == ":":
        start, stop, step = values
        if not step > 0 or stop < start:
            raise InputError(f"{name}: range {text!r} needs step > 0 and stop >= start")
        count = _bounds.range_count(start, stop, step, name, text, limit=limit)  # before np.arange allocates
        return start + step * np.arange(count)
    return np.array(values, dtype=float)
