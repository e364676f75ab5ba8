"""The ``frequencies`` calculation: characteristic frequencies (FTF, BPFO, BPFI, BSF) and the spectral
mask, at the nominal contact angle or at the operating one under an axial stand load.

:func:`document` gives what ``bearinglab frequencies ... --json`` prints (the command prints it), for
the command line and the web alike.

Functions
---------
document   Parsed -> the JSON document
"""

from __future__ import annotations

import math
import re

from ..errors import InputError
from . import _reading as inp
from ._failures import failures
from ._finite import finite

__all__ = ["document"]

_HZ = 2.0 * math.pi  # rad/s per Hz (rev/s)
_PERCENT = re.compile(r"^\s*([-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?)\s*(%|percent)?\s*$")


def _band(text):
    """'2 %', '2%' or '2' (percent) -> the relative full width 0.02."""
    m = _PERCENT.match(str(text))
    if not m:
        raise InputError(f"band: cannot read {text!r} as a percentage (e.g. '2 %', '0.5%', '2')")
    value = float(m.group(1))
    if not 0.0 < value < 200.0:
        raise InputError(f"band must be in (0, 200) [%], got {value:g} %")
    return value / 100.0


@finite('frequencies')
def document(parsed, *, bearing_file=None, catalog=None):
    """The document of ``bearinglab frequencies ... --json`` for a request.

    Parameters
    ----------
    parsed : bearinglab.calculations.Parsed
        The request (fields of ``CALCULATIONS["frequencies"]``).
    bearing_file, catalog : path, optional
        A bearing file or a user catalog (the command line's files; the web has none).

    Returns
    -------
    dict
        The frequencies (``*_hz``, ``*_order``), the nominal ones and the shift, the inputs echoed,
        ``mask`` with the ``mask`` flag, and ``warnings`` (the bearing's provenance notes).
    """
    with failures(parsed, options=False):  # messages in the command line's words (_failures)
        b = inp.bearing_of(parsed, bearing_file=bearing_file, catalog=catalog)
        hertz = inp.value(parsed, "hertz", "exact")
        harmonics, sidebands = inp.value(parsed, "harmonics", 3), inp.value(parsed, "sidebands", 1)
        w_in, w_out, fa, band_fraction = _read(b, inp.text(parsed, "speed"), inp.text(parsed, "outer_speed", "0 rpm"),
                                               inp.text(parsed, "axial_load"), hertz, harmonics, sidebands,
                                               inp.text(parsed, "band", "2 %"))
        elastic_constant = inp.choice("elastic-constant", inp.value(parsed, "elastic_constant", "materials"),
                                      ("materials", "paper"))
        out, angle = _frequencies(b, w_in, w_out, fa, hertz, elastic_constant)
        if inp.value(parsed, "mask", False):
            out["mask"] = {"harmonics": harmonics, "sidebands": sidebands, "band_percent": band_fraction * 100.0,
                           "lines": _mask(b, w_in, w_out, angle, harmonics, sidebands, band_fraction)}
    return inp.notes_in(out, b)


def _read(b, speed, outer_speed, axial_load, hertz, harmonics, sidebands, band):
    """The options in SI, checked: ring speeds, axial load (or None), band as a fraction."""
    from .. import limits
    from .._bounds import MAX_HARMONICS, MAX_SIDEBANDS, check_count
    from ..units import parse_quantity
    inp.choice("hertz", hertz, ("exact", "table"))
    if speed is None:
        raise InputError("speed: missing; give the inner-ring (shaft) speed, e.g. '3000 rpm'")
    # one convention in every command: --speed is the inner ring's, >= 0, within the d_m n guard
    w_in = inp.parse_speed(speed, bearing=b, what="the inner-ring speed, a magnitude; give --outer-speed a "
                                                  "negative value for rings turning against each other")
    w_out = parse_quantity(outer_speed, "speed", "outer-speed")  # signed: the sense relative to --speed
    if inp.speed_size(b) is not None:
        limits.check_speed(w_out, inp.speed_size(b), "outer-speed")
    if w_in == w_out:
        raise InputError(
            f"speed: the rings must turn relative to each other, got speed = outer-speed = "
            f"{w_in / _HZ * 60:g} rpm"
        )
    band_fraction = _band(band)
    check_count("harmonics", harmonics, MAX_HARMONICS)
    check_count("sidebands", sidebands, MAX_SIDEBANDS, minimum=0)
    fa = None
    if axial_load is not None:
        fa = parse_quantity(axial_load, "force", "axial-load")
    return w_in, w_out, fa, band_fraction


def _frequencies(b, w_in, w_out, fa, hertz, elastic_constant):
    """Frequencies at the nominal angle, or at the operating angle under ``fa`` with the shift; and
    the angle [rad] they are at."""
    from .. import kinematics, stand, tables
    from ..units import KGF, format_dms
    z, d, dm, a0 = b.require("n_balls", "ball_diameter", "pitch_diameter", "contact_angle")
    out = inp.inputs_echo(b, speed_rpm=w_in / _HZ * 60.0, outer_speed_rpm=w_out / _HZ * 60.0,
                          elastic_constant=elastic_constant)
    shaft_hz = w_in / _HZ
    if fa is not None:
        if not fa > 0:
            raise InputError(f"axial-load must be > 0 [N], got {fa:g} N ({fa / KGF:g} kgf)")
        angle = float(stand.stand_analysis(b, fa, hertz=hertz, elastic_constant=elastic_constant).contact_angle)
        out.update(axial_load_N=fa, axial_load_kgf=fa / KGF, hertz=hertz)
    else:
        angle = a0
    shift = kinematics.frequency_shift(w_in, d, dm, z, a0, angle, outer_speed=w_out)
    out.update(
        contact_angle_deg=math.degrees(angle),
        contact_angle_dms=format_dms(angle),
        nominal_contact_angle_deg=math.degrees(a0),
        shaft_hz=shaft_hz,
        outer_hz=w_out / _HZ,
    )
    out.update(tables.frequencies(shift.operating, w_in))
    out["nominal"] = dict(
        contact_angle_deg=math.degrees(a0), shaft_hz=shaft_hz, **tables.frequencies(shift.nominal, w_in)
    )
    out["shift_hz"] = {n: float(getattr(shift.shift, n)) / _HZ for n in kinematics.FAMILIES[1:]}
    out["shift_percent"] = {
        n: float(getattr(shift.shift_percent, n)) for n in kinematics.FAMILIES[1:]
    }
    return out, angle


def _mask(b, w_in, w_out, angle, harmonics, sidebands, band_fraction):
    """The lines of the spectral mask at the angle of the frequencies (Hz and orders)."""
    from .. import kinematics, tables
    z, d, dm = b.require("n_balls", "ball_diameter", "pitch_diameter")
    m = kinematics.spectral_mask(w_in, d, dm, z, angle, outer_speed=w_out, harmonics=harmonics,
                                 sidebands=sidebands, band=band_fraction)
    return tables.rows(tables.spectral_mask(m, w_in))
