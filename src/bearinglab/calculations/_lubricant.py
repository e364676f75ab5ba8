"""The lubricant inputs shared by every calculation that needs the operating viscosity (life, film,
friction, temperature): a viscosity alone, or an ISO VG grade with its temperature (and its viscosity
index or viscosity at 100 degC). Moved from the command line's ``cli._common``, which re-exports them.

parse_viscosity      a kinematic viscosity > 0 [m^2/s] (the message in cSt)
parse_temperature    '70 degC', '343 K' or '158 degF' [K]
lubricant_viscosity  the oil inputs -> LubricantViscosity (nu, how it was obtained, the inputs as used)
"""

from __future__ import annotations

import math
import re
import typing

from ..errors import InputError

__all__: list[str] = []  # private to the calculations and the command line


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



_ZERO_C = 273.15  # K at 0 degC
_TEMPERATURE = re.compile(r"^\s*([-+]?\d+(?:\.\d*)?(?:[eE][-+]?\d+)?)\s*(°C|degC|C|K|°F|degF|F)\s*$")


def parse_temperature(text, name="temperature"):
    """A temperature '70 degC', '343 K' or '158 degF' [K], above absolute zero."""
    m = _TEMPERATURE.match(text or "")
    if not m:
        raise InputError(f"{name} must be a number with degC, K or degF (e.g. '70 degC'), got {text!r}")
    v, unit = float(m.group(1)), m.group(2).lstrip("°").removeprefix("deg")
    t = {"C": v + _ZERO_C, "K": v, "F": (v - 32.0) / 1.8 + _ZERO_C}[unit]
    if not (t > 0 and math.isfinite(t)):
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
    m = re.fullmatch(r"(?:ISO\s*)?VG\s*(\d+)", oil.strip(), flags=re.IGNORECASE)
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
