"""Bearing designations as engineers write them: the base size and its suffixes.

Functions
---------
parse          a designation -> Designation (base size, seals, clearance class, angle, tolerance class, ...)
makers_of      the makers whose own suffixes a designation uses (to say when another maker's data answers it)
parse_roller   a roller-bearing designation -> RollerDesignation (NU 208 ECP/C3, 30208 J2/Q, 22208 EK), or None

Constants
---------
SEALS          seal and shield suffixes -> (seal type of the friction model, sealed sides)
CLEARANCES     radial internal clearance suffixes (ISO 5753-1 groups)
TOLERANCES     tolerance-class suffixes (ISO 492 classes; ABEC-style P4A)
ANGLES         contact-angle codes of angular-contact bearings -> nominal contact angle [deg]
CAGES          cage suffixes, accepted and kept (they change no number bearinglab uses)
DESIGNS        internal-design and snap-ring suffixes (E, XL, A, N, NR, N2), accepted and kept
BALLS          ball-material suffixes (HC5, HC: silicon nitride balls)
PRELOADS       preload classes of universally matchable bearings (GA, GB, GC) and their axial clearance
               classes (CA, CB, CC)
ARRANGEMENTS   matched-set arrangements (DB, DF, DT), with a super-precision preload class (DBA ... DFC)
MAKER_SUFFIXES suffixes used by one maker only -> that maker
ROLLER_SUFFIXES  SKF's suffixes of cylindrical, tapered and spherical roller bearings, by type and kind

Examples of what is read: ``6208-2RS1/C3``, ``6208 2RS C3``, ``6208ZZC3``, ``6205 DDU``, ``62/22-2Z``,
``7205 BECBP``, ``7205-B-TVP``, ``7014 CD/P4A``, ``71914 ACD``, and (issue 30) Schaeffler's
``6208-2RSR``, ``6208-2Z``, ``6208-C3``, ``6208-2RSR-C3``, ``7208-B-XL-JP``, ``QJ208-TVP``; SKF's
``6208 NR``, ``6208-2ZNR``, ``1208 ETN9``, ``2306 M``, ``QJ 208 N2MA``, ``4208 ATN9``, ``3208 A``,
``6208-2Z/HC5C3``, ``7208 BEGAPH``, ``7014 CD/P4ADBB``, ``7014 CD/P2``; GMN's spindle bearings
``S 6208 C TA P4 UL``, ``S 61910 E TA``. Suffixes may be written with or
without separators (``-``, ``/``, space); an unknown one is refused, naming the valid ones.

Maker spellings of the angle codes (the nominal contact angle they stand for): SKF ``B``/``BE`` (and
``BECBP``, ``BECBM``, ``BECBY``, ``BEP``, ``BEY``, ``BEM``, ``BW``) 40 deg, ``AC`` 25 deg, ``CD`` 15 deg,
``ACD`` 25 deg; NSK ``A5`` 25 deg, ``A`` 30 deg, ``B`` 40 deg, ``C`` 15 deg; Schaeffler ``-B-TVP``
40 deg (``TVP`` is its cage); SKF's double-row angular contact bearings 32 A, 33 A: ``A`` 30 deg.
Sources: SKF General Catalogue 6000/I RU (2006), designation systems of deep-groove, angular-contact,
double-row, four-point and self-aligning ball bearings (supplementary designations: N, NR, E, TN9, M,
MA, N2 pp. 440, 455; GA, GB, GC, CA, CB, CC p. 412-413); NSK CAT. No. E1102e, note (2) of the
angular-contact tables ("A, A5, B and C represent contact angles of 30, 25, 40 and 15 deg");
Schaeffler, Rolling bearings (catalogue HR 1, 2006): the suffixes 2RSR (lip seals), XL (X-life), JP
(sheet-steel cage), TVP, TVH (polyamide cages), MPA (brass cage). HC5 (SKF): rolling elements of
silicon nitride. GMN, High precision ball bearings (catalogue 4000 0813 EN), bearing designation p. 21:
S (standard spindle series), C 15 deg, E 25 deg, TA and TXM cages, UL, UM, US universal matching with
light, medium, heavy preload.
"""

from __future__ import annotations

import re
from typing import NamedTuple

from .errors import InputError

__all__ = ["ANGLES", "ARRANGEMENTS", "BALLS", "CAGES", "CLEARANCES", "DESIGNS", "MAKER_SUFFIXES", "PRELOADS",
           "ROLLER_SUFFIXES", "SEALS", "TOLERANCES", "Designation", "RollerDesignation", "makers_of", "parse",
           "parse_roller"]

#: Seal and shield suffixes -> (seal type as the SKF friction model names it, number of sealed sides).
SEALS = {
    "2RS1": ("RS1", 2), "RS1": ("RS1", 1), "2RSH": ("RSH", 2), "RSH": ("RSH", 1), "2RSL": ("RSL", 2),
    "RSL": ("RSL", 1), "2RS": ("RS", 2), "RS": ("RS", 1), "2RZ": ("RZ", 2), "RZ": ("RZ", 1),
    "2Z": ("Z", 2), "ZZ": ("Z", 2), "Z": ("Z", 1), "DDU": ("DDU", 2), "DU": ("DDU", 1),
    "VV": ("VV", 2), "V": ("VV", 1), "LLU": ("LLU", 2), "LU": ("LLU", 1), "LLB": ("LLB", 2),
    "LB": ("LLB", 1), "2LS": ("LS", 2), "LS": ("LS", 1), "2RSR": ("RSR", 2), "RSR": ("RSR", 1),
}
CLEARANCES = ("C2", "CN", "C3", "C4", "C5")
TOLERANCES = ("P0", "P6", "P5", "P4", "P4A", "P2", "PA9A")
ANGLES = {
    "B": 40.0, "BE": 40.0, "BECBP": 40.0, "BECBM": 40.0, "BECBY": 40.0, "BEP": 40.0, "BEY": 40.0,
    "BEM": 40.0, "BW": 40.0, "AC": 25.0, "ACD": 25.0, "A5": 25.0, "A": 30.0, "C": 15.0, "CD": 15.0,
}
CAGES = ("TVP", "TVH", "TN9", "TNH", "TN", "MA", "MB", "MPA", "M", "Y", "J", "JP", "PHAS", "PH", "P", "TXM", "TA")
#: Internal-design and snap-ring suffixes: SKF E (reinforced internal design), Schaeffler XL (X-life),
#: SKF N (snap-ring groove), NR (groove and snap ring), N2 (two locating slots, four-point bearings); and
#: A of SKF's double-row deep groove bearings (42 A, 43 A: no filling slots). No number changes.
DESIGNS = ("E", "XL", "NR", "N2", "N")
#: Ball-material suffixes -> the material (SKF: HC5 silicon nitride rolling elements; HC hybrid
#: super-precision bearings).
BALLS = {"HC5": "silicon_nitride", "HC": "silicon_nitride"}
#: Preload classes of SKF's universally matchable single-row angular contact bearings (GA light, GB
#: moderate, GC heavy) and their axial internal clearance classes (CA, CB, CC); GMN's universal matching
#: with light, medium and heavy preload (UL, UM, US).
PRELOADS = ("GA", "GB", "GC", "UL", "UM", "US")
AXIAL_CLEARANCES = ("CA", "CB", "CC")
#: Matched sets: back-to-back, face-to-face, tandem; SKF super-precision sets add the preload class
#: A (light), B (moderate) or C (heavy): DBA, DBB, DBC, DFA, DFB, DFC.
ARRANGEMENTS = ("DBA", "DBB", "DBC", "DFA", "DFB", "DFC", "DB", "DF", "DT")
#: Suffixes only one maker uses -> that maker (to say when a designation is answered with another
#: maker's data).
MAKER_SUFFIXES = {
    **dict.fromkeys(("2RS1", "RS1", "2RSH", "RSH", "2RSL", "RSL", "2RZ", "RZ", "BE", "BECBP", "BECBM",
                     "BECBY", "BEP", "BEY", "BEM", "AC", "ACD", "CD", "E", "TN9", "HC5", "HC", "GA", "GB",
                     "GC", "CA", "CB", "CC", "N2", "PHAS", "PH", "DBA", "DBB", "DBC", "DFA", "DFB", "DFC"), "SKF"),
    **dict.fromkeys(("2RSR", "RSR", "XL", "JP", "TVP", "TVH", "MPA"), "Schaeffler"),
    **dict.fromkeys(("TA", "TXM", "UL", "UM", "US"), "GMN"),
    **dict.fromkeys(("A5", "DDU", "DU", "VV", "V"), "NSK"),
    **dict.fromkeys(("LLU", "LU", "LLB", "LB"), "NTN"),
}

_KINDS = [(SEALS, "seal"), (CLEARANCES, "clearance"), (TOLERANCES, "tolerance"), (ANGLES, "angle"),
          (CAGES, "cage"), (DESIGNS, "design"), (BALLS, "balls"), (PRELOADS, "preload"),
          (AXIAL_CLEARANCES, "axial clearance"), (ARRANGEMENTS, "arrangement")]
_KIND = {t: kind for table, kind in reversed(_KINDS) for t in table}
_VOCABULARY = sorted(_KIND, key=len, reverse=True)
_BASE = re.compile(r"^\s*(?P<base>QJ\s?[0-9]{3}|S\s?(?:[0-9]{3}/[0-9]+|[0-9]{3,6})|[0-9]{2,3}/[0-9]+|[0-9]{3,6})")
#: GMN's spindle bearings (series S): the codes C (15 deg) and E (25 deg) after the size
_GMN_ANGLES = {"C": 15.0, "E": 25.0}
_NSK_THIN = re.compile(r"^(6[89])([0-9][0-9])$")      # NSK/NTN 6805, 6905 -> ISO 61805, 61905
_NSK_SPINDLE = re.compile(r"^719([0-9][0-9])$")      # SKF 71914 -> NSK 7914
_DOUBLE_ROW_ANGULAR = re.compile(r"^3[23][0-9][0-9]$")  # 32 A, 33 A: the code A is the contact angle (30 deg)
_DOUBLE_ROW_RADIAL = re.compile(r"^4[23][0-9][0-9]$")   # 42 A, 43 A: the code A is a design (no filling slots)


class Designation(NamedTuple):
    """A designation taken apart."""

    text: str
    """The designation as given."""
    base: str
    """The base size in ISO spelling: ``6208``, ``61805``, ``7205``, ``62/22``, ``QJ208``."""
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
    designs: tuple = ()
    """Internal-design and snap-ring suffixes (``E``, ``XL``, ``N``, ``NR``, ``N2``; ``A`` of 42 A / 43 A)."""
    ball_material: str | None = None
    """``silicon_nitride`` for HC5 / HC, or None (steel)."""
    preload_class: str | None = None
    """``GA``, ``GB``, ``GC`` (SKF), ``UL``, ``UM``, ``US`` (GMN), or ``A``, ``B``, ``C`` of a DBA ... DFC set;
    or None."""
    axial_clearance_class: str | None = None
    """``CA``, ``CB`` or ``CC`` of a universally matchable bearing, or None."""
    arrangement: str | None = None
    """``DB``, ``DF`` or ``DT`` of a matched set, or None."""
    tokens: tuple = ()
    """Every suffix as read, in order."""


def _valid():
    return (f"seals/shields {', '.join(SEALS)}; clearance {', '.join(CLEARANCES)}; tolerance "
            f"{', '.join(TOLERANCES)}; angle {', '.join(ANGLES)}; cage {', '.join(CAGES)}; design "
            f"{', '.join(DESIGNS)}; balls {', '.join(BALLS)}; preload {', '.join(PRELOADS)}, "
            f"{', '.join(AXIAL_CLEARANCES)}; sets {', '.join(ARRANGEMENTS)}")


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


def makers_of(d):
    """The makers whose own suffixes a designation uses.

    Parameters
    ----------
    d : Designation
        A parsed designation.

    Returns
    -------
    tuple of str
        ``("SKF",)``, ``("Schaeffler",)``, ``("NSK",)``, ``("NTN",)``, several, or ``()`` where every
        suffix is common to the makers (``6208-2Z/C3``).

    Examples
    --------
    >>> makers_of(parse("7008 CD/P4A")), makers_of(parse("6208-2RSR")), makers_of(parse("6208-2Z"))
    (('SKF',), ('Schaeffler',), ())
    """
    gmn = d.base.startswith("S")  # GMN's own codes C and E after the size of an S bearing
    return tuple(dict.fromkeys(("GMN",) if gmn else ()) | dict.fromkeys(
        MAKER_SUFFIXES[t] for t in d.tokens if t in MAKER_SUFFIXES and not (gmn and t in _GMN_ANGLES)))


def parse(text):
    """Take a designation apart.

    Parameters
    ----------
    text : str
        A designation such as ``"6208-2RS1/C3"``, ``"7205 BECBP"``, ``"QJ 208 N2MA"``.

    Returns
    -------
    Designation

    Raises
    ------
    InputError
        No base size, an unknown suffix (the message names the valid ones), two suffixes of one kind,
        or an angle code on a bearing that is not angular-contact (a base starting with 7, or SKF's
        double-row 32 A, 33 A).

    Examples
    --------
    >>> d = parse("6208-2RS1/C3")
    >>> d.base, d.seal, d.seals, d.clearance_class
    ('6208', 'RS1', 2, 'C3')
    >>> d = parse("7205 BECBP")
    >>> d.base, d.angle_code, d.contact_angle
    ('7205', 'BECBP', 40.0)
    >>> d = parse("7208-B-XL-JP")
    >>> d.angle_code, d.designs, d.cage
    ('B', ('XL',), 'JP')
    >>> parse("6208-2Z/HC5C3").ball_material, parse("7208 BEGAPH").preload_class
    ('silicon_nitride', 'GA')
    """
    raw = str(text)
    upper = raw.upper()
    m = _BASE.match(upper)
    if not m:
        raise InputError(f"bearing: {raw!r} is not a designation (it starts with no size such as 6208 or "
                         "7205)")
    base, rest = m.group("base").replace(" ", ""), upper[m.end():]
    _check_separators(raw[m.end():] if len(raw) == len(upper) else rest, raw)
    alternatives = ()
    if _NSK_THIN.match(base):
        alternatives, base = (base,), "61" + base[1:]
    elif _NSK_SPINDLE.match(base):
        alternatives = ("79" + base[3:],)
    kinds = {kind: None for _, kind in _KINDS}
    designs = []
    tokens = _tokens(rest, raw)
    for token in tokens:
        kind = _KIND[token]
        if kind == "angle" and token == "A" and _DOUBLE_ROW_RADIAL.match(base):
            kind = "design"  # SKF 4208 A(TN9): no filling slots, not an angle
        if base.startswith("S") and token == "E":
            kind = "angle"  # GMN S 6208 E: 25 deg
        if kind == "design":
            if token in designs:
                raise InputError(f"bearing: two {token} suffixes in {raw!r}")
            designs.append(token)
            continue
        if kinds[kind] is not None:
            raise InputError(f"bearing: two {kind} suffixes in {raw!r} ({kinds[kind]} and {token})")
        kinds[kind] = token
    angle = ANGLES.get(kinds["angle"])
    if base.startswith("S"):
        if kinds["angle"] is not None and kinds["angle"] not in _GMN_ANGLES:
            raise InputError(f"bearing: the angle code {kinds['angle']!r} in {raw!r} is not GMN's (C 15 deg, "
                             "E 25 deg)")
        angle = _GMN_ANGLES.get(kinds["angle"])
    elif kinds["angle"] is not None and not (base.startswith("7") or _DOUBLE_ROW_ANGULAR.match(base)):
        raise InputError(f"bearing: the angle code {kinds['angle']!r} in {raw!r} is for angular-contact "
                         "bearings (designations 7..., and 32.., 33.. A, GMN S ...)")
    snap = [t for t in designs if t in ("N", "NR")]
    if len(snap) > 1:
        raise InputError(f"bearing: two snap-ring suffixes in {raw!r} ({snap[0]} and {snap[1]})")
    seal, sides = SEALS.get(kinds["seal"], (None, None))
    arrangement, preload = kinds["arrangement"], kinds["preload"]
    if arrangement is not None and len(arrangement) == 3:
        if preload is not None:
            raise InputError(f"bearing: two preload classes in {raw!r} ({preload} and {arrangement[2]} of "
                             f"{arrangement})")
        arrangement, preload = arrangement[:2], arrangement[2]
    return Designation(raw, base, kinds["angle"], angle, seal, sides, kinds["clearance"],
                       kinds["tolerance"], kinds["cage"], alternatives, tuple(designs), BALLS.get(kinds["balls"]),
                       preload, kinds["axial clearance"], arrangement, tuple(tokens))



# ------------------------------------------------------------------ roller bearings (issue 32)
# SKF's suffixes of its single row cylindrical, tapered and spherical roller bearings (General Catalogue 6000/I RU,
# 2006: pp. 520-521, 614, 696 and 709, and VG900 of 32915 TN9/QVG900 on p. 628), by kind; a kind holds one suffix. ``other`` suffixes (steels, heat
# treatments, lubrication features, tolerances of width, ...) are kept and change no number bearinglab uses.
ROLLER_SUFFIXES = {
    "cylindrical": {
        "design": ("EC",),
        "cage": ("PHA", "PH", "P", "J", "ML", "MA", "MB", "MP", "MR", "M"),
        "bore": ("K",),
        "other": ("HA3", "HB1", "HN1", "NR", "N1", "N2", "N", "S1", "S2", "VA3091", "VA301", "VA305", "VA350",
                  "VA380", "VC025", "VL0241", "VL2071", "VQ015"),
    },
    "tapered": {
        "design": ("B", "X"),
        "cage": ("J1", "J2", "J3", "TN9"),
        "bore": (),
        "other": ("Q601", "Q", "CL7C", "CL7A", "CL00", "CL0", "CLN", "C02", "HA1", "HA3", "HN1", "HN3", "R", "U2",
                  "U4", "VA321", "VA606", "VA607", "VB022", "VB026", "VB061", "VB134", "VB406", "VB481", "VC027",
                  "VC068", "VE174", "VG900", "VQ051", "VQ267", "VQ495", "VQ506", "VQ507", "VQ523", "W"),
    },
    "spherical": {
        "design": ("ECAC", "ECA", "CAC", "CAF", "CA", "CC", "EJA", "E"),
        "cage": ("JA", "MA", "MB", "M"),
        "bore": ("K30", "K"),
        "other": ("2CS2", "2CS5", "2CS", "C083", "C084", "C08", "HA3", "P62", "VA405", "VA406", "VE552E", "VE552",
                  "VE553E", "VE553", "VG114", "VQ424", "VT143", "W513", "W20", "W26", "W33", "W64", "W77", "W"),
    },
}
_ROLLER_CLEARANCES = ("C2", "C3", "C4", "C5", "CN")
_ROLLER_TOLERANCES = ("P6", "P5")
_ROLLER_BASES = (
    ("cylindrical", re.compile(r"^\s*(?P<prefix>NUP|NU|NJ|N)[\s-]*(?P<base>[0-9]{1,2}/[0-9]{3,4}|[0-9]{3,4})(?![0-9])(?!/[0-9])")),
    ("tapered", re.compile(r"^\s*(?P<base>3[0-3][0-9]/[0-9]{2,3}|3[0-3][0-9]{3})(?![0-9])(?!/[0-9])")),
    ("spherical", re.compile(r"^\s*(?P<base>2[1-4][0-9]/[0-9]{3,4}|2[1-4][0-9]{3})(?![0-9])(?!/[0-9])")),
)


class RollerDesignation(NamedTuple):
    """A roller-bearing designation taken apart (:func:`parse_roller`)."""

    text: str
    """The designation as given."""
    type: str
    """``"cylindrical"``, ``"tapered"`` or ``"spherical"``."""
    prefix: str | None
    """The design of a cylindrical bearing (``NU``, ``NJ``, ``NUP``, ``N``), else None."""
    base: str
    """The basic number: ``208``, ``2208``, ``30208``, ``302/28``, ``22208``."""
    series: str
    """The dimension series (cylindrical ``2``, ``22``; tapered ``302``; spherical ``222``)."""
    bore: float
    """d from the bore code. [mm]"""
    design: str | None
    """Internal design: ``EC``; tapered ``B`` (steeper), ``X`` (ISO dimensions); spherical ``E``, ``CC``, ``CA``."""
    cage: str | None
    """Cage suffix (``P``, ``J``, ``M``, ``ML``, ``MA``; tapered ``J2``, ``TN9``), or None."""
    tapered_bore: str | None
    """``K`` (taper 1:12) or ``K30`` (1:30), or None."""
    clearance_class: str | None
    """``C2`` ... ``C5``, ``CN`` (with SKF's reduced-range letter ``H`` or ``L`` if written), or None."""
    tolerance_class: str | None
    """``P6``, ``P5``, or None."""
    other: tuple
    """The other suffixes written, in order."""


def _roller_bore(base):
    if "/" in base:
        return float(base.split("/")[1])
    code = int(base[-2:])
    return {0: 10.0, 1: 12.0, 2: 15.0, 3: 17.0}.get(code, 5.0 * code)


def _roller_valid(kind):
    v = ROLLER_SUFFIXES[kind]
    bore = f"; tapered bore {', '.join(v['bore'])}" if v["bore"] else ""
    clearance = "" if kind == "tapered" else f"; clearance {', '.join(_ROLLER_CLEARANCES)}"
    return (f"design {', '.join(v['design'])}; cage {', '.join(v['cage'])}{bore}{clearance}; tolerance "
            f"{', '.join(_ROLLER_TOLERANCES)}; other {', '.join(v['other'])}")


def parse_roller(text):
    """Take a roller-bearing designation apart, or None if it is no roller-bearing designation.

    Parameters
    ----------
    text : str
        E.g. ``"NU 208 ECP/C3"``, ``"NJ2208ECJ"``, ``"30208 J2/Q"``, ``"32310 BJ2/QCL7C"``, ``"22208 EK/C3"``,
        ``"22324 CCK/W33"``. Suffixes may be written with or without separators (``/``, space, ``-``).

    Returns
    -------
    RollerDesignation or None
        None when the text does not start with a roller-bearing base (``NU 208``, a five-digit ``3xxxx``
        tapered or ``2xxxx`` spherical number): a ball-bearing designation.

    Raises
    ------
    InputError
        An unknown suffix (the message names the valid ones of the type) or two suffixes of one kind.

    Notes
    -----
    SKF's designation system of roller bearings, General Catalogue 6000/I RU (2006): cylindrical pp. 520-521
    (EC optimized internal design; cages J, M, MA, MB, ML, MP, MR, P, PH, PHA; K tapered bore), tapered
    p. 614 (B steeper contact angle, X ISO boundary dimensions, J cage, TN9, Q, CL7C ...), spherical pp. 696
    and 709 (E, CC, CA designs; K, K30 tapered bore; W33 lubrication groove and holes ...).

    Examples
    --------
    >>> d = parse_roller("NU 208 ECJ/C3")
    >>> d.type, d.prefix, d.base, d.design, d.cage, d.clearance_class
    ('cylindrical', 'NU', '208', 'EC', 'J', 'C3')
    >>> d = parse_roller("22208 EK")
    >>> d.series, d.design, d.tapered_bore
    ('222', 'E', 'K')
    >>> parse_roller("6208-2RS1") is None
    True
    """
    raw = str(text)
    upper = raw.upper()
    for kind, pattern in _ROLLER_BASES:
        m = pattern.match(upper)
        if m:
            break
    else:
        return None
    base, rest = m.group("base"), upper[m.end():]
    prefix = m.groupdict().get("prefix")
    series = base.split("/")[0] if "/" in base else base[:-2]
    vocab = ROLLER_SUFFIXES[kind]
    kinds = {"design": vocab["design"], "cage": vocab["cage"], "bore": vocab["bore"],
             "tolerance": _ROLLER_TOLERANCES, "other": vocab["other"]}
    # clearance: C2-C5 or CN, with SKF's H or L of a reduced range (C3L, CNH); tried before the other suffixes
    clearance_re = re.compile(r"(C[2-5]|CN)(?:[HL](?![0-9]))?")
    words = sorted({(t, k) for k, ts in kinds.items() for t in ts}, key=lambda tk: len(tk[0]), reverse=True)
    found = {"design": None, "cage": None, "bore": None, "clearance": None, "tolerance": None}
    other = []
    for chunk in filter(None, re.split(r"[-/\s.]+", rest)):
        while chunk:
            cm = clearance_re.match(chunk) if kind != "tapered" else None  # set by mounting, no class
            hit = next(((t, k) for t, k in words if chunk.startswith(t)), None)
            if cm and (hit is None or len(cm.group(0)) >= len(hit[0])):
                token, k = cm.group(0), "clearance"
            elif hit is not None:
                token, k = hit
            else:
                raise InputError(f"bearing: unknown suffix {chunk!r} in {raw!r} for a {kind} roller bearing; "
                                 f"valid suffixes: {_roller_valid(kind)}")
            if k == "other":
                other.append(token)
            elif found[k] is not None:
                raise InputError(f"bearing: two {k} suffixes in {raw!r} ({found[k]} and {token})")
            else:
                found[k] = token
            chunk = chunk[len(token):]
    return RollerDesignation(raw, kind, prefix, base, series, _roller_bore(base), found["design"], found["cage"],
                             found["bore"], found["clearance"], found["tolerance"], tuple(other))
