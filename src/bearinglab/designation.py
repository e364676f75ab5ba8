"""Bearing designations as engineers write them: the base size and its suffixes.

Functions
---------
parse          a designation -> Designation (base size, seals, clearance class, angle, tolerance class)

Constants
---------
SEALS          seal and shield suffixes -> (seal type of the friction model, sealed sides)
CLEARANCES     radial internal clearance suffixes (ISO 5753-1 groups)
TOLERANCES     tolerance-class suffixes (ISO 492 classes; ABEC-style P4A)
ANGLES         contact-angle codes of angular-contact bearings -> nominal contact angle [deg]
CAGES          cage suffixes, accepted and kept (they change no number bearinglab uses)

Examples of what is read: ``6208-2RS1/C3``, ``6208 2RS C3``, ``6208ZZC3``, ``6205 DDU``, ``62/22-2Z``,
``7205 BECBP``, ``7205-B-TVP``, ``7014 CD/P4A``, ``71914 ACD``. Suffixes may be written with or
without separators (``-``, ``/``, space); an unknown one is refused, naming the valid ones.

Maker spellings of the angle codes (the nominal contact angle they stand for): SKF ``B``/``BE`` (and
``BECBP``, ``BECBM``, ``BECBY``, ``BEP``, ``BEY``, ``BEM``, ``BW``) 40 deg, ``AC`` 25 deg, ``CD`` 15 deg,
``ACD`` 25 deg; NSK ``A5`` 25 deg, ``A`` 30 deg, ``B`` 40 deg, ``C`` 15 deg; Schaeffler ``-B-TVP``
40 deg (``TVP`` is its cage). Sources: SKF General Catalogue 6000/I (2006), designation systems of
deep-groove and angular-contact ball bearings; NSK CAT. No. E1102e, note (2) of the angular-contact
tables ("A, A5, B and C represent contact angles of 30, 25, 40 and 15 deg").
"""

from __future__ import annotations

import re
from typing import NamedTuple

from .errors import InputError

__all__ = ["ANGLES", "CAGES", "CLEARANCES", "SEALS", "TOLERANCES", "Designation", "parse"]

#: Seal and shield suffixes -> (seal type as the SKF friction model names it, number of sealed sides).
SEALS = {
    "2RS1": ("RS1", 2), "RS1": ("RS1", 1), "2RSH": ("RSH", 2), "RSH": ("RSH", 1), "2RSL": ("RSL", 2),
    "RSL": ("RSL", 1), "2RS": ("RS", 2), "RS": ("RS", 1), "2RZ": ("RZ", 2), "RZ": ("RZ", 1),
    "2Z": ("Z", 2), "ZZ": ("Z", 2), "Z": ("Z", 1), "DDU": ("DDU", 2), "DU": ("DDU", 1),
    "VV": ("VV", 2), "V": ("VV", 1), "LLU": ("LLU", 2), "LU": ("LLU", 1), "LLB": ("LLB", 2),
    "LB": ("LLB", 1), "2LS": ("LS", 2), "LS": ("LS", 1),
}
CLEARANCES = ("C2", "CN", "C3", "C4", "C5")
TOLERANCES = ("P0", "P6", "P5", "P4", "P4A", "P2", "PA9A")
ANGLES = {
    "B": 40.0, "BE": 40.0, "BECBP": 40.0, "BECBM": 40.0, "BECBY": 40.0, "BEP": 40.0, "BEY": 40.0,
    "BEM": 40.0, "BW": 40.0, "AC": 25.0, "ACD": 25.0, "A5": 25.0, "A": 30.0, "C": 15.0, "CD": 15.0,
}
CAGES = ("TVP", "TN9", "TNH", "TN", "MA", "MB", "M", "Y", "J")

_VOCABULARY = sorted({*SEALS, *CLEARANCES, *TOLERANCES, *ANGLES, *CAGES}, key=len, reverse=True)
_BASE = re.compile(r"^\s*(?P<base>[0-9]{2,3}/[0-9]+|[0-9]{3,6})")
_NSK_THIN = re.compile(r"^(6[89])([0-9][0-9])$")      # NSK/NTN 6805, 6905 -> ISO 61805, 61905
_NSK_SPINDLE = re.compile(r"^719([0-9][0-9])$")      # SKF 71914 -> NSK 7914


class Designation(NamedTuple):
    """A designation taken apart."""

    text: str
    """The designation as given."""
    base: str
    """The base size in ISO spelling: ``6208``, ``61805``, ``7205``, ``62/22``."""
    angle_code: str | None
    """The angle code as written (``BECBP``, ``CD``, ``B``), or None."""
    contact_angle: float | None
    """The nominal contact angle the code stands for. [deg]"""
    seal: str | None
    """Seal type (``RS1``, ``Z``, ...), or None."""
    seals: int | None
    """Number of sealed sides (1 or 2), or None."""
    clearance_class: str | None
    """``C2``, ``CN``, ``C3``, ``C4``, ``C5`` or None (none written: Normal)."""
    tolerance_class: str | None
    """``P6``, ``P5``, ``P4``, ``P4A``, ... or None (none written: Normal, P0)."""
    cage: str | None
    """Cage suffix, or None."""
    alternatives: tuple
    """Other spellings of the base in the makers' catalogues (``6805`` for ``61805``)."""


def _valid():
    return (f"seals/shields {', '.join(SEALS)}; clearance {', '.join(CLEARANCES)}; tolerance "
            f"{', '.join(TOLERANCES)}; angle {', '.join(ANGLES)}; cage {', '.join(CAGES)}")


# the suffix part: chunks of letters and digits, each after at most one separator ('-', '/' or spaces)
_PART = re.compile(r"\s*[-/]\s*|\s+|[A-Z0-9]+|.", re.ASCII | re.IGNORECASE)


def _check_separators(rest, text):
    """Refuse a suffix part that is not chunks after single separators: ``6208-`` (a separator with no
    suffix), ``6208////``, ``6208.2RS`` (a dot is no separator): the message names the part."""
    parts = [m.group() for m in _PART.finditer(rest.rstrip())]
    for k, part in enumerate(parts):
        if part[0].isalnum() and part.isascii():
            continue
        if part.strip() in ("-", "/", "") and k + 1 < len(parts) and parts[k + 1][0].isalnum():
            continue
        shown = part if part.strip() else "a space"
        where = "at the end" if k + 1 == len(parts) else f"before {parts[k + 1]!r}"
        raise InputError(f"bearing: cannot read {text!r} as a designation: {shown.strip() or shown!r} {where} is "
                         "not understood (suffixes follow the size, each after at most one '-', '/' or space)")


def _tokens(rest, text):
    """Split the suffix part into known tokens, longest match first; refuse an unknown one."""
    out = []
    for chunk in filter(None, re.split(r"[-/\s]+", rest)):
        while chunk:
            token = next((t for t in _VOCABULARY if chunk.startswith(t)), None)
            if token is None:
                raise InputError(f"bearing: unknown suffix {chunk!r} in {text!r}; valid suffixes: {_valid()}")
            out.append(token)
            chunk = chunk[len(token):]
    return out


def parse(text):
    """Take a designation apart.

    Parameters
    ----------
    text : str
        A designation such as ``"6208-2RS1/C3"`` or ``"7205 BECBP"``.

    Returns
    -------
    Designation

    Raises
    ------
    InputError
        No base size, an unknown suffix (the message names the valid ones), two suffixes of one kind,
        or an angle code on a bearing that is not angular-contact (a base starting with 7).

    Examples
    --------
    >>> d = parse("6208-2RS1/C3")
    >>> d.base, d.seal, d.seals, d.clearance_class
    ('6208', 'RS1', 2, 'C3')
    >>> d = parse("7205 BECBP")
    >>> d.base, d.angle_code, d.contact_angle
    ('7205', 'BECBP', 40.0)
    """
    raw = str(text)
    upper = raw.upper()
    m = _BASE.match(upper)
    if not m:
        raise InputError(f"bearing: {raw!r} is not a designation (it starts with no size such as 6208 or "
                         "7205)")
    base, rest = m.group("base"), upper[m.end():]
    _check_separators(raw[m.end():] if len(raw) == len(upper) else rest, raw)
    alternatives = ()
    if _NSK_THIN.match(base):
        alternatives, base = (base,), "61" + base[1:]
    elif _NSK_SPINDLE.match(base):
        alternatives = ("79" + base[3:],)
    kinds = {"angle": None, "seal": None, "clearance": None, "tolerance": None, "cage": None}
    for token in _tokens(rest, raw):
        if token in SEALS:
            kind = "seal"
        elif token in CLEARANCES:
            kind = "clearance"
        elif token in TOLERANCES:
            kind = "tolerance"
        elif token in ANGLES:
            kind = "angle"
        else:
            kind = "cage"
        if kinds[kind] is not None:
            raise InputError(f"bearing: two {kind} suffixes in {raw!r} ({kinds[kind]} and {token})")
        kinds[kind] = token
    if kinds["angle"] is not None and not base.startswith("7"):
        raise InputError(f"bearing: the angle code {kinds['angle']!r} in {raw!r} is for angular-contact "
                         "bearings (designations 7...)")
    seal, sides = SEALS.get(kinds["seal"], (None, None))
    return Designation(raw, base, kinds["angle"], ANGLES.get(kinds["angle"]), seal, sides, kinds["clearance"],
                       kinds["tolerance"], kinds["cage"], alternatives)
