r"""Kinematics of a ball bearing in pure rolling: cage and ball speeds, characteristic (defect) frequencies.

All speeds are angular speeds in rad/s and every frequency comes out in the unit of the speeds that go
in (rad/s in, rad/s out; rev/s in, rev/s out). The inner ring turns at ``shaft_speed``; the general case
of both rings rotating gives the outer ring's speed as ``outer_speed`` (default 0, a fixed outer ring).

Speeds
------
cage_speed                 fundamental train frequency (FTF), the cage speed in the fixed frame (signed)
ball_pass_frequencies      BPFO and BPFI, ball-pass frequencies over the outer and inner raceway
ball_spin_frequency        BSF, the spin of a ball about its own axis relative to the cage

Sets of frequencies
-------------------
characteristic_frequencies shaft, FTF, BPFO, BPFI, BSF and 2 BSF at once
characteristic_orders      the same as multiples of the shaft speed (dimensionless)
frequency_shift            nominal vs operating contact angle: both sets, the shift and the shift in %

Spectral mask
-------------
spectral_mask              harmonics 1..N with FTF and shaft sidebands, each line with a band
FAMILIES                   the names of the frequency families, in mask order

Pure rolling at both contacts at one contact angle (Harris and Kotzalas [1]_): spec 004 eqs. (9) and
(13) with alpha_i = alpha_e = beta = alpha (no spin-axis tilt). Defect frequencies and their sidebands
in spectra: Randall and Antoni [2]_; the CWRU benchmark bearing: Smith and Randall [3]_. Speed effects on the angle are in
:mod:`bearinglab.quasistatic`; the angle under an axial stand load is in :mod:`bearinglab.static`.

References
----------
.. [1] T. A. Harris and M. N. Kotzalas, *Essential Concepts of Bearing Technology*, 5th ed., CRC Press,
   2006, doi:10.1201/9781420006599.
.. [2] R. B. Randall and J. Antoni, "Rolling element bearing diagnostics -- a tutorial," Mech. Syst.
   Signal Process., vol. 25, no. 2, pp. 485-520, 2011, doi:10.1016/j.ymssp.2010.07.017.
.. [3] W. A. Smith and R. B. Randall, "Rolling element bearing diagnostics using the Case Western
   Reserve University data: A benchmark study," Mech. Syst. Signal Process., vol. 64-65, pp. 100-131,
   2015, doi:10.1016/j.ymssp.2015.04.021.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from . import _bounds
from ._validate import as_float, check_finite, check_greater, check_integer, check_positive
from .errors import InputError

__all__ = [
    "FAMILIES",
    "BallPass",
    "CharacteristicFrequencies",
    "FrequencyShift",
    "SpectralMask",
    "ball_pass_frequencies",
    "ball_spin_frequency",
    "cage_speed",
    "characteristic_frequencies",
    "characteristic_orders",
    "frequency_shift",
    "spectral_mask",
]

#: Frequency families of :class:`CharacteristicFrequencies` (and of the spectral mask), in order.
FAMILIES = ("shaft", "ftf", "bpfo", "bpfi", "bsf", "two_bsf")


class CharacteristicFrequencies(NamedTuple):
    """Characteristic frequencies of a bearing, in the unit of the speeds given."""

    shaft: np.ndarray  # |inner-ring speed|
    ftf: np.ndarray  # |cage speed| in the fixed frame (fundamental train frequency)
    bpfo: np.ndarray  # ball pass frequency, outer race
    bpfi: np.ndarray  # ball pass frequency, inner race
    bsf: np.ndarray  # ball spin frequency
    two_bsf: np.ndarray  # 2 BSF: a ball defect strikes both raceways once per spin


class BallPass(NamedTuple):
    """Ball-pass frequencies over the two raceways."""

    bpfo: np.ndarray
    bpfi: np.ndarray


class FrequencyShift(NamedTuple):
    """Characteristic frequencies at the nominal and the operating contact angle."""

    nominal: CharacteristicFrequencies
    operating: CharacteristicFrequencies
    shift: CharacteristicFrequencies  # operating - nominal, unit of the speeds
    shift_percent: (
        CharacteristicFrequencies  # 100 (operating - nominal) / nominal [%]; NaN where nominal = 0
    )


class SpectralMask(NamedTuple):
    """Lines of a spectral mask. The first four fields describe the lines, the last three give them.

    ``name``, ``harmonic``, ``modulation`` and ``sideband`` have one entry per line; ``frequency``,
    ``low`` and ``high`` have the broadcast shape of the inputs followed by the line axis.
    """

    name: np.ndarray  # family of the carrier line, one of FAMILIES
    harmonic: np.ndarray  # h = 1..N of the carrier
    modulation: (
        np.ndarray
    )  # "" for a carrier line, else the family of the sideband spacing ("ftf", "shaft")
    sideband: np.ndarray  # k = -S..S, order of the sideband (0 for the carrier)
    frequency: np.ndarray  # |h f_carrier + k f_modulation|
    low: np.ndarray  # frequency (1 - band / 2)
    high: np.ndarray  # frequency (1 + band / 2)


def _contact_angle(value, name="contact_angle"):
    a = as_float(name, value)
    bad = ~((a >= 0.0) & (a < np.pi / 2))
    if bad.any():
        first = float(np.degrees(a[bad].flat[0] if a.ndim else a))
        raise InputError(f"{name} must be in [0, 90) [deg], got {first!r} deg")
    return a


def _gamma(ball_diameter, pitch_diameter, contact_angle):
    d = check_positive("ball_diameter", ball_diameter, "m")
    dm = check_greater("pitch_diameter", pitch_diameter, "ball_diameter", d, "m")
    return d * np.cos(_contact_angle(contact_angle)) / dm  # gamma, [1] eq. 7.1 notation


def _speeds(shaft_speed, outer_speed):
    wi = check_finite("shaft_speed", shaft_speed, "rad/s")
    wo = check_finite("outer_speed", outer_speed, "rad/s")
    return wi, wo


def cage_speed(shaft_speed, ball_diameter, pitch_diameter, contact_angle, *, outer_speed=0.0):
    r"""Speed of the cage in the fixed frame: the fundamental train frequency, signed.

    Parameters
    ----------
    shaft_speed : array_like
        Speed of the inner ring. [rad/s]
    ball_diameter : array_like
        Ball diameter D. [m]
    pitch_diameter : array_like
        Pitch diameter d_m, > D. [m]
    contact_angle : array_like
        Contact angle alpha, in [0, 90 deg). [rad]
    outer_speed : array_like, optional
        Speed of the outer ring, same sense as ``shaft_speed``; 0 for a fixed outer ring. [rad/s]

    Returns
    -------
    ndarray
        Cage speed, positive in the sense of a positive speed. [rad/s]

    Notes
    -----
    Pure rolling at both contacts, no gyroscopic or centrifugal effects; spec 004 eq. (9) with
    alpha_i = alpha_e = beta = alpha (Harris and Kotzalas 2006, see the module references):

    .. math:: \omega_c = \tfrac12\left[\omega_i (1 - \gamma) + \omega_o (1 + \gamma)\right],
              \qquad \gamma = D\cos\alpha / d_m .

    Examples
    --------
    >>> print(f"{cage_speed(1.0, 7.94e-3, 39.04e-3, 0.0):.6f}")
    0.398309
    """
    wi, wo = _speeds(shaft_speed, outer_speed)
    g = _gamma(ball_diameter, pitch_diameter, contact_angle)
    return (0.5 * (wi * (1.0 - g) + wo * (1.0 + g)))[()]


def ball_pass_frequencies(
    shaft_speed, ball_diameter, pitch_diameter, n_balls, contact_angle, *, outer_speed=0.0
):
    r"""Ball-pass frequencies over the outer (BPFO) and inner (BPFI) raceway.

    Parameters
    ----------
    shaft_speed : array_like
        Speed of the inner ring. [rad/s]
    ball_diameter : array_like
        Ball diameter D. [m]
    pitch_diameter : array_like
        Pitch diameter d_m, > D. [m]
    n_balls : array_like
        Number of balls Z, an integer >= 1. [-]
    contact_angle : array_like
        Contact angle alpha, in [0, 90 deg). [rad]
    outer_speed : array_like, optional
        Speed of the outer ring; 0 for a fixed outer ring. [rad/s]

    Returns
    -------
    BallPass
        ``bpfo`` and ``bpfi``, rates at which balls pass a point of each raceway (>= 0). [rad/s]

    Notes
    -----
    The balls pass a point of the outer ring at Z times the speed of the cage relative to that ring,
    and a point of the inner ring at Z times the speed of the inner ring relative to the cage; with
    :func:`cage_speed` and the relative speed of the rings :math:`\omega_i - \omega_o`:

    .. math:: f_{BPFO} = \tfrac{Z}{2}\,|\omega_i - \omega_o|\,(1 - \gamma), \qquad
              f_{BPFI} = \tfrac{Z}{2}\,|\omega_i - \omega_o|\,(1 + \gamma),

    so that :math:`f_{BPFO} + f_{BPFI} = Z |\omega_i - \omega_o|` for any geometry.

    Examples
    --------
    >>> bp = ball_pass_frequencies(1.0, 7.94e-3, 39.04e-3, 9, 0.0)
    >>> print(f"{bp.bpfo:.4f} {bp.bpfi:.4f}")
    3.5848 5.4152
    """
    wi, wo = _speeds(shaft_speed, outer_speed)
    z = check_integer("n_balls", n_balls, 1)
    g = _gamma(ball_diameter, pitch_diameter, contact_angle)
    rel = np.abs(wi - wo)
    return BallPass((0.5 * z * rel * (1.0 - g))[()], (0.5 * z * rel * (1.0 + g))[()])


def ball_spin_frequency(
    shaft_speed, ball_diameter, pitch_diameter, contact_angle, *, outer_speed=0.0
):
    r"""Ball spin frequency (BSF): rotation of a ball about its own axis, relative to the cage.

    Parameters
    ----------
    shaft_speed : array_like
        Speed of the inner ring. [rad/s]
    ball_diameter : array_like
        Ball diameter D. [m]
    pitch_diameter : array_like
        Pitch diameter d_m, > D. [m]
    contact_angle : array_like
        Contact angle alpha, in [0, 90 deg). [rad]
    outer_speed : array_like, optional
        Speed of the outer ring; 0 for a fixed outer ring. [rad/s]

    Returns
    -------
    ndarray
        BSF (>= 0). A ball defect strikes a raceway at 2 BSF. [rad/s]

    Notes
    -----
    Spec 004 eq. (13) with alpha_i = alpha_e = beta = alpha:
    :math:`f_{BSF} = \frac{d_m}{2D}\,|\omega_i - \omega_o|\,(1 - \gamma^2)`.

    Examples
    --------
    >>> print(f"{2 * ball_spin_frequency(1.0, 7.94e-3, 39.04e-3, 0.0):.4f}")
    4.7135
    """
    wi, wo = _speeds(shaft_speed, outer_speed)
    d = check_positive("ball_diameter", ball_diameter, "m")
    g = _gamma(d, pitch_diameter, contact_angle)
    dm = np.asarray(pitch_diameter, dtype=float)
    return (dm / (2.0 * d) * np.abs(wi - wo) * (1.0 - g * g))[()]


def characteristic_frequencies(
    shaft_speed, ball_diameter, pitch_diameter, n_balls, contact_angle, *, outer_speed=0.0
):
    r"""All characteristic frequencies at once: shaft, FTF, BPFO, BPFI, BSF and 2 BSF.

    Parameters
    ----------
    shaft_speed : array_like
        Speed of the inner ring. [rad/s]
    ball_diameter : array_like
        Ball diameter D. [m]
    pitch_diameter : array_like
        Pitch diameter d_m, > D. [m]
    n_balls : array_like
        Number of balls Z, an integer >= 1. [-]
    contact_angle : array_like
        Contact angle alpha, in [0, 90 deg). [rad]
    outer_speed : array_like, optional
        Speed of the outer ring; 0 for a fixed outer ring. [rad/s]

    Returns
    -------
    CharacteristicFrequencies
        ``shaft`` = :math:`|\omega_i|`, ``ftf`` = :math:`|\omega_c|` (:func:`cage_speed`), ``bpfo``,
        ``bpfi`` (:func:`ball_pass_frequencies`), ``bsf`` and ``two_bsf``
        (:func:`ball_spin_frequency`). [rad/s]

    Notes
    -----
    Broadcasts over all arguments, so one call gives the frequencies of many speeds, bearings or angles.
    Divide by :math:`2\pi` for Hz (rev/s), or use :func:`characteristic_orders` for multiples of the
    shaft speed.

    Examples
    --------
    >>> import math
    >>> f = characteristic_frequencies(2 * math.pi * 29.95, 7.94e-3, 39.04e-3, 9, 0.0)
    >>> print(f"BPFI = {f.bpfi / (2 * math.pi):.2f} Hz")
    BPFI = 162.19 Hz
    """
    wi, wo = _speeds(shaft_speed, outer_speed)
    z = check_integer("n_balls", n_balls, 1)
    d = check_positive("ball_diameter", ball_diameter, "m")
    g = _gamma(d, pitch_diameter, contact_angle)
    dm = np.asarray(pitch_diameter, dtype=float)
    rel = np.abs(wi - wo)
    ftf = np.abs(0.5 * (wi * (1.0 - g) + wo * (1.0 + g)))  # spec 004 eq. (9), one angle
    bpfo = 0.5 * z * rel * (1.0 - g)  # Z |w_c - w_o|
    bpfi = 0.5 * z * rel * (1.0 + g)  # Z |w_i - w_c|
    bsf = dm / (2.0 * d) * rel * (1.0 - g * g)  # spec 004 eq. (13), one angle
    shape = np.broadcast_shapes(np.shape(wi), np.shape(wo), np.shape(z), np.shape(g))
    out = [
        np.broadcast_to(x, shape).copy()[()] for x in (np.abs(wi), ftf, bpfo, bpfi, bsf, 2.0 * bsf)
    ]
    return CharacteristicFrequencies(*out)


def characteristic_orders(
    ball_diameter, pitch_diameter, n_balls, contact_angle, *, outer_speed_ratio=0.0
):
    r"""Characteristic frequencies as multiples (orders) of the shaft speed.

    Parameters
    ----------
    ball_diameter : array_like
        Ball diameter D. [m]
    pitch_diameter : array_like
        Pitch diameter d_m, > D. [m]
    n_balls : array_like
        Number of balls Z, an integer >= 1. [-]
    contact_angle : array_like
        Contact angle alpha, in [0, 90 deg). [rad]
    outer_speed_ratio : array_like, optional
        Speed of the outer ring over that of the inner ring; 0 for a fixed outer ring. [-]

    Returns
    -------
    CharacteristicFrequencies
        Orders; ``shaft`` is 1. [-]

    Notes
    -----
    The frequencies of :func:`characteristic_frequencies` at a unit shaft speed. For the CWRU
    drive-end bearing (6205-2RS, Z = 9, D = 7.94 mm, d_m = 39.04 mm, alpha = 0) they are the published
    multipliers BPFI 5.4152, BPFO 3.5848 and 2 BSF 4.7135 (Case Western Reserve University Bearing
    Data Center; Smith and Randall 2015, see the module references). The published FTF, 0.39828, is
    not consistent with the published BPFO (FTF = BPFO / Z exactly); this gives 0.39831.

    Examples
    --------
    >>> o = characteristic_orders(7.94e-3, 39.04e-3, 9, 0.0)
    >>> print(f"{o.bpfi:.4f} {o.bpfo:.4f} {o.ftf:.5f} {o.two_bsf:.4f}")
    5.4152 3.5848 0.39831 4.7135
    """
    ratio = check_finite("outer_speed_ratio", outer_speed_ratio, "-")
    return characteristic_frequencies(
        1.0, ball_diameter, pitch_diameter, n_balls, contact_angle, outer_speed=ratio
    )


def frequency_shift(
    shaft_speed,
    ball_diameter,
    pitch_diameter,
    n_balls,
    free_angle,
    contact_angle,
    *,
    outer_speed=0.0,
):
    r"""Characteristic frequencies at the nominal and at the operating contact angle, and their shift.

    Parameters
    ----------
    shaft_speed : array_like
        Speed of the inner ring. [rad/s]
    ball_diameter : array_like
        Ball diameter D. [m]
    pitch_diameter : array_like
        Pitch diameter d_m, > D. [m]
    n_balls : array_like
        Number of balls Z, an integer >= 1. [-]
    free_angle : array_like
        Nominal (free) contact angle alpha0, in [0, 90 deg). [rad]
    contact_angle : array_like
        Operating contact angle, e.g. under the stand load (:func:`bearinglab.static.stand_analysis`),
        in [0, 90 deg). [rad]
    outer_speed : array_like, optional
        Speed of the outer ring; 0 for a fixed outer ring. [rad/s]

    Returns
    -------
    FrequencyShift
        ``nominal``, ``operating`` and ``shift`` (operating - nominal) [rad/s], and ``shift_percent``
        = 100 shift / nominal [%] (NaN where the nominal frequency is 0).

    Notes
    -----
    Spec 000 section 1: spectral masks built at the nominal angle are wrong once the axial stand load
    has raised the angle. A larger angle lowers gamma, so BPFI falls while BPFO, FTF and BSF rise.

    Examples
    --------
    >>> import math
    >>> s = frequency_shift(1.0, 2e-3, 8.7355e-3, 7, math.radians(12), math.radians(14.4676))
    >>> print(f"BPFI {s.shift.bpfi:+.5f} ({s.shift_percent.bpfi:+.3f} %)")
    BPFI -0.00790 (-0.184 %)
    """
    free_angle = _contact_angle(free_angle, "free_angle")
    nominal = characteristic_frequencies(
        shaft_speed, ball_diameter, pitch_diameter, n_balls, free_angle, outer_speed=outer_speed
    )
    operating = characteristic_frequencies(
        shaft_speed, ball_diameter, pitch_diameter, n_balls, contact_angle, outer_speed=outer_speed
    )
    shift = [np.asarray(o - n) for o, n in zip(operating, nominal)]
    with np.errstate(invalid="ignore", divide="ignore"):
        percent = [
            np.where(np.asarray(n) != 0, 100.0 * s / np.where(np.asarray(n) != 0, n, 1.0), np.nan)
            for s, n in zip(shift, nominal)
        ]
    return FrequencyShift(
        nominal,
        operating,
        CharacteristicFrequencies(*[s[()] for s in shift]),
        CharacteristicFrequencies(*[p[()] for p in percent]),
    )


def spectral_mask(
    shaft_speed,
    ball_diameter,
    pitch_diameter,
    n_balls,
    contact_angle,
    *,
    outer_speed=0.0,
    harmonics=3,
    sidebands=1,
    band=0.02,
    families=FAMILIES,
):
    r"""Spectral mask: the lines where bearing defects show, each with a frequency band.

    Parameters
    ----------
    shaft_speed : array_like
        Speed of the inner ring. [rad/s]
    ball_diameter : array_like
        Ball diameter D. [m]
    pitch_diameter : array_like
        Pitch diameter d_m, > D. [m]
    n_balls : array_like
        Number of balls Z, an integer >= 1. [-]
    contact_angle : array_like
        Contact angle alpha (the operating one when the bearing is loaded), in [0, 90 deg). [rad]
    outer_speed : array_like, optional
        Speed of the outer ring; 0 for a fixed outer ring. [rad/s]
    harmonics : int, optional
        Harmonics h = 1..N of every family. [-]
    sidebands : int, optional
        Sideband orders k = 1..S on each side of the modulated carriers (0: none). [-]
    band : float, optional
        Full width of each line's band relative to its frequency, in (0, 2); 0.02 is a 2 % band,
        from 0.99 f to 1.01 f. [-]
    families : sequence of str, optional
        Carrier families to include, a subset of :data:`FAMILIES`.

    Returns
    -------
    SpectralMask
        One entry per line in ``name``, ``harmonic``, ``modulation``, ``sideband``; ``frequency``,
        ``low`` and ``high`` [rad/s] with the broadcast shape of the inputs plus a last axis of lines.

    Notes
    -----
    Carrier lines :math:`h f` for every family (h = 1..N). Sidebands, which show the modulation of a
    defect signal by the rotation of the load zone relative to the defect (Randall and Antoni 2011,
    see the module references):

    * around every BPFI harmonic, :math:`h f_{BPFI} \pm k f_{shaft}` (the inner-race defect turns with
      the shaft) and :math:`h f_{BPFI} \pm k f_{FTF}`;
    * around every BSF and 2 BSF harmonic, :math:`h f_{BSF} \pm k f_{FTF}` (the ball turns with the cage).

    A sideband that would fall below zero is folded to its absolute value. Lines are in the order of
    ``families``, then harmonic, then modulation (FTF before shaft), then k from -S to S.

    Examples
    --------
    >>> m = spectral_mask(1.0, 7.94e-3, 39.04e-3, 9, 0.0, harmonics=1, sidebands=1, families=("bpfi",))
    >>> for row in zip(m.name, m.modulation, m.sideband, m.frequency.round(4)):
    ...     print(*row)
    bpfi  0 5.4152
    bpfi ftf -1 5.0169
    bpfi ftf 1 5.8135
    bpfi shaft -1 4.4152
    bpfi shaft 1 6.4152
    """
    n_harm = int(check_integer("harmonics", harmonics, 1, _bounds.MAX_HARMONICS))
    n_side = int(check_integer("sidebands", sidebands, 0, _bounds.MAX_SIDEBANDS))
    width = np.asarray(as_float("band", band))
    if width.ndim or not 0.0 < float(width) < 2.0:
        raise InputError(f"band must be a number in (0, 2) [-] (0.02 = a 2 % band), got {band!r}")
    families = tuple(families)
    unknown = [f for f in families if f not in FAMILIES]
    if unknown or not families:
        raise InputError(
            f"families must be a non-empty subset of {list(FAMILIES)}, got {list(families)!r}"
        )
    f = characteristic_frequencies(
        shaft_speed, ball_diameter, pitch_diameter, n_balls, contact_angle, outer_speed=outer_speed
    )
    base = {name: np.asarray(getattr(f, name))[..., None] for name in FAMILIES}
    h = np.arange(1, n_harm + 1, dtype=float)
    k = np.concatenate([np.arange(-n_side, 0), np.arange(1, n_side + 1)]).astype(float)
    modulated = {"bpfi": ("ftf", "shaft"), "bsf": ("ftf",), "two_bsf": ("ftf",)}
    names, harm, mods, sides, freqs = [], [], [], [], []
    for fam in families:
        for hh in h:  # loops over the mask layout (a few lines), not over cases
            groups = [("", np.zeros(1))] + [(mod, k) for mod in modulated.get(fam, ()) if n_side]
            for mod, kk in groups:
                names += [fam] * kk.size
                harm += [hh] * kk.size
                mods += [mod] * kk.size
                sides += list(kk)
                spacing = base[mod] if mod else 0.0
                freqs.append(np.abs(hh * base[fam] + kk * spacing))
    freq = np.concatenate(freqs, axis=-1)
    return SpectralMask(
        np.array(names, dtype=str),
        np.array(harm, dtype=int),
        np.array(mods, dtype=str),
        np.array(sides, dtype=int),
        freq,
        freq * (1.0 - 0.5 * float(width)),
        freq * (1.0 + 0.5 * float(width)),
    )
