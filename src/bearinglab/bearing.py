"""Dataclasses bundling the inputs of the models.

Materials
---------
Material          elastic modulus, Poisson's ratio, density
STEEL             AISI 52100 bearing steel (default for balls and rings)
SILICON_NITRIDE   Si3N4 ceramic balls
MATERIALS         name -> Material, for input files and the command line

Bearings
--------
BallBearing       validated, frozen internal geometry, envelope and materials of a ball bearing
max_balls         the most balls of a diameter that fit on a pitch circle

Types and models
----------------
TYPES             the bearing types: radial (deep groove), angular, four-point, double-row-angular,
                  double-row-radial, self-aligning, thrust
ROWS              the ball rows of each type
MODEL_TYPES       the types each model that solves the contacts ball by ball takes
ANGLE_BUILT_IN    the types whose nominal angle is built into the rings (given apart from the clearance)
check_model       refuse, in one line, a bearing whose type a model does not cover yet
covers            whether a model covers a bearing's type

The dataclasses only check and pass fields on; the physics is in :mod:`bearinglab.geometry`,
:mod:`bearinglab.hertz` and the model modules.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field

import numpy as np

from . import geometry, hertz
from .errors import InputError

__all__ = [
    "ANGLE_BUILT_IN", "ANGLE_CLEARANCE_TOLERANCE", "CLEARANCE_TOLERANCE", "MATERIALS", "MODEL_TYPES", "ROWS", "SILICON_NITRIDE", "STEEL",
    "TYPES", "BallBearing", "Material", "check_model", "covers", "max_balls",
]


@dataclass(frozen=True)
class Material:
    """An isotropic elastic material.

    Parameters
    ----------
    name : str
        Display name.
    elastic_modulus : float
        Young's modulus. [Pa]
    poisson_ratio : float
        Poisson's ratio. [-]
    density : float
        Mass density. [kg/m^3]
    """

    name: str
    elastic_modulus: float
    poisson_ratio: float
    density: float

    def __post_init__(self):
        if not self.elastic_modulus > 0:
            raise InputError(f"elastic_modulus must be > 0 [Pa], got {self.elastic_modulus!r}")
        if not -1.0 < self.poisson_ratio < 0.5:
            raise InputError(f"poisson_ratio must be in (-1, 0.5) [-], got {self.poisson_ratio!r}")
        if not self.density > 0:
            raise InputError(f"density must be > 0 [kg/m^3], got {self.density!r}")


# Harris & Kotzalas, Essential Concepts of Bearing Technology, 5th ed., Table 6.? (52100: E = 2.075e5 MPa,
# nu = 0.3) and the usual density 7.85 g/cm^3 of the source papers; Si3N4: E = 3.1e5 MPa, nu = 0.26,
# 3.2 g/cm^3 (same reference, ceramic hybrid bearings).
STEEL = Material("steel", 2.075e11, 0.3, 7850.0)
SILICON_NITRIDE = Material("silicon nitride", 3.10e11, 0.26, 3200.0)
MATERIALS = {"steel": STEEL, "silicon_nitride": SILICON_NITRIDE, "si3n4": SILICON_NITRIDE}

#: The bearing types (``BallBearing.type``, the ``type`` word of files and JSON documents): deep groove
#: (``radial``), single-row angular contact, and the ball-bearing types of issue 30.
TYPES = ("radial", "angular", "four-point", "double-row-angular", "double-row-radial", "self-aligning", "thrust")
_TYPES = TYPES
#: Ball rows of each type (ISO 281's i); a self-aligning ball bearing has two rows.
ROWS = {"radial": 1, "angular": 1, "four-point": 1, "double-row-angular": 2, "double-row-radial": 2,
        "self-aligning": 2, "thrust": 1}
#: The types each model that solves the balls' contacts takes (the 5-DOF load distribution and what is
#: built on it); the others are refused by :func:`check_model` in one line, never answered wrongly.
MODEL_TYPES = {
    "load-distribution": TYPES,
    "bearing-set": TYPES,
    "high-speed": ("radial", "angular"),
    "axial-angle": ("radial", "angular"),
    "runout": ("radial", "angular"),
    "film": TYPES,
}
# what each type has that the models of MODEL_TYPES do not cover yet
_NOT_COVERED = {
    "four-point": "the four contacts of each ball (two on each ring)",
    "double-row-angular": "the second row of balls",
    "double-row-radial": "the second row of balls",
    "self-aligning": "the spherical outer raceway (no tilting stiffness) and the second row",
    "thrust": "the axial contacts of a thrust bearing (90 deg)",
}
#: The types whose contact angle is built into the rings (the nominal angle of the groove design: the
#: offset of the groove-curvature centres, or the spherical outer raceway), so that the angle and the
#: clearance are given apart and neither follows from the other (the 5-DOF model's geometry,
#: :mod:`bearinglab.quasistatic._types`); a single-row bearing's angle follows from its clearance.
ANGLE_BUILT_IN = ("four-point", "double-row-angular", "self-aligning", "thrust")
#: A contact angle given with a clearance may differ from the one the clearance implies by this much
#: (rounding of the printed values) [rad] ...
ANGLE_CLEARANCE_TOLERANCE = math.radians(0.05)
#: ... or the clearance from the one the angle implies by this fraction (the printed digits). [-]
CLEARANCE_TOLERANCE = 0.005


def max_balls(ball_diameter, pitch_diameter):
    """The most balls of diameter D that fit on a pitch circle d_m without overlapping.

    Parameters
    ----------
    ball_diameter : float
        D. [m]
    pitch_diameter : float
        d_m > D. [m]

    Returns
    -------
    int
        floor(pi / arcsin(D / d_m)): neighbouring centres are a chord d_m sin(pi / Z) apart, which must
        be at least D (a full complement with no cage). [-]

    Examples
    --------
    >>> max_balls(7.938e-3, 38.5e-3)
    15
    """
    from ._validate import check_positive_finite

    d = float(check_positive_finite("ball_diameter", ball_diameter, "m"))
    dm = float(check_positive_finite("pitch_diameter", pitch_diameter, "m"))
    ratio = min(d / dm, 1.0)
    if not ratio >= 1e-6:  # a million balls: no bearing; and D / d_m -> 0 would divide by zero
        raise InputError(f"ball_diameter must be >= 1e-6 x pitch_diameter [m], got D = {d!r} with d_m = {dm!r}")
    return math.floor(math.pi / math.asin(ratio) + 1e-9)


def covers(bearing, model):
    """Whether ``model`` (a key of :data:`MODEL_TYPES`) covers the type of ``bearing``.

    Parameters
    ----------
    bearing : BallBearing
        The bearing.
    model : str
        A key of :data:`MODEL_TYPES`.

    Returns
    -------
    bool

    Examples
    --------
    >>> covers(BallBearing(type="thrust"), "high-speed"), covers(BallBearing(type="thrust"), "load-distribution")
    (False, True)
    """
    return getattr(bearing, "type", "angular") in MODEL_TYPES[model]


def check_model(bearing, model):
    """Refuse, in one line, a bearing whose type ``model`` does not cover yet.

    Parameters
    ----------
    bearing : BallBearing
        The bearing.
    model : str
        A key of :data:`MODEL_TYPES` (``"load-distribution"``, ``"bearing-set"``, ``"high-speed"``, ...).

    Raises
    ------
    InputError
        Naming the model, the bearing, its type and what the model does not cover; the load distribution
        and the lives (``bearinglab load-distribution``, ``bearinglab life``) cover every type. For a type the model covers but whose fields it lacks
        (the catalog has no ball set of the four-point, double-row, self-aligning and thrust types), every
        missing field in one line.

    Examples
    --------
    >>> check_model(BallBearing(designation="QJ 208", type="four-point"), "high-speed")
    Traceback (most recent call last):
    ...
    bearinglab.errors.InputError: high-speed: 'QJ 208' is a four-point bearing, and the model does not cover the four contacts of each ball (two on each ring) yet; `bearinglab load-distribution` solves its balls and `bearinglab life` gives its lives
    """
    label = getattr(bearing, "designation", "") or "this bearing"
    if covers(bearing, model):
        missing = _missing_fields(bearing) if model in _BALL_BY_BALL else ()
        if missing:
            raise InputError(f"{model}: {label!r} lacks {', '.join(missing)}, which the model of a {bearing.type} "
                             "bearing needs (no public source gives the ball set of this type, so the catalog leaves "
                             "it unknown): give them in a bearing file or user catalog, or inline (--balls, "
                             "--ball-diameter, --pitch-diameter, --inner-conformity, ...)")
        return
    raise InputError(f"{model}: {label!r} is a {bearing.type} bearing, and the model does not cover "
                     f"{_NOT_COVERED.get(bearing.type, 'this type')} yet; `bearinglab load-distribution` solves its "
                     "balls and `bearinglab life` gives its lives")


# the models that solve the new types ball by ball, and the fields each type needs for it
_BALL_BY_BALL = ("load-distribution", "bearing-set", "film")
_NEEDS = ("n_balls", "ball_diameter", "pitch_diameter", "inner_conformity", "outer_conformity", "contact_angle")


def _missing_fields(bearing):
    """The fields the 5-DOF model of a four-point, double-row, self-aligning or thrust bearing needs and
    ``bearing`` lacks (a single row: none listed here; its model names a missing field itself)."""
    kind = getattr(bearing, "type", "angular")
    if kind in ("radial", "angular"):
        return ()
    out = [k for k in _NEEDS if getattr(bearing, k, None) is None
           and not (kind == "self-aligning" and k == "outer_conformity" and bearing.contact_angle is not None)]
    if kind in ("four-point", "double-row-angular", "self-aligning") and bearing.radial_clearance is None:
        out.append("radial_clearance")
    if kind in ("double-row-angular", "double-row-radial") and bearing.row_distance is None:
        out.append("row_distance")
    return tuple(out)


def _clearance_range(e, ball_diameter):
    """A diametral clearance is a finite number of metres; a negative one (a preload) at least -2 D."""
    if not (isinstance(e, (int, float, np.floating, np.integer)) and math.isfinite(e)):
        raise InputError(f"radial_clearance must be a finite length [m], got {e!r}")
    if ball_diameter is not None and e < -2.0 * ball_diameter:
        raise InputError(f"radial_clearance must be >= {-2.0 * ball_diameter * 1e3:.6g} [mm] (an interference of one "
                         f"ball diameter per ball; a negative clearance is a preload), got {e * 1e3:.6g} mm")


def _positive(name, value, unit, *, optional=True):
    if value is None and optional:
        return
    if not (isinstance(value, (int, float, np.floating, np.integer)) and value > 0 and math.isfinite(value)):
        raise InputError(f"{name} must be > 0 [{unit}], got {value!r}")


_SPHERE_SOURCE = ("derived: the spherical outer raceway about the bearing centre, R_o = d_m / (2 cos alpha0) + D/2 "
                  "(ISO/TS 16281's r_e of self-aligning ball bearings)")

# What a user who lacks a field usually needs to know (catalogs rarely print the groove radii). The range is
# the usual design range of ball-bearing conformities (Harris & Kotzalas, Rolling Bearing Analysis, ch. 2).
_MISSING_HINTS = {
    "inner_conformity": "; the inner groove radius over the ball diameter, usually 0.515 to 0.53",
    "outer_conformity": "; the outer groove radius over the ball diameter, usually 0.52 to 0.54",
}


@dataclass(frozen=True)
class BallBearing:
    """Internal geometry, envelope and materials of a single-row ball bearing (SI units).

    Give the groove conformities directly or through :meth:`from_groove_radii`, and the free contact
    angle or the diametral clearance (the other one is derived when the conformities are known).
    Fields that a catalog does not know (for the friction-rig bearings, the ball set) may be ``None``;
    a method that needs them raises :class:`~bearinglab.errors.InputError` naming the field.

    Parameters
    ----------
    n_balls : int
        Number of balls Z. [-]
    ball_diameter : float
        Ball diameter D. [m]
    pitch_diameter : float
        Pitch diameter d_m, > D. [m]
    inner_conformity, outer_conformity : float
        f_i = r_i / D and f_o = r_o / D, each > 0.5. [-]
    contact_angle : float
        Nominal (free) contact angle alpha0, in [0, 90 deg). [rad]
    radial_clearance : float
        Diametral clearance e (the operating one where the bearing is given mounted). Zero or negative
        is a preloaded bearing: its free contact angle is 0 and every ball is compressed by -e/2 in the
        concentric position (:func:`bearinglab.quasistatic.combined.load_distribution`); at least
        -2 D (an interference of one ball diameter per ball). [m]
    designation : str
        Name of the bearing.
    bore, outside_diameter, width : float
        Envelope. [m]
    type : str
        One of :data:`TYPES`: ``radial`` (deep groove), ``angular``, ``four-point``,
        ``double-row-angular``, ``double-row-radial``, ``self-aligning``, ``thrust``.
    static_load_rating : float
        Basic static load rating C0 (of a thrust bearing: C0a). [N]
    ball_material, ring_material : Material
        Steel by default.
    hertz_table : dict
        Tabulated Hertz coefficients the source used, ``{"inner": delta*, "outer": delta*}``.
    source : str
        Where the numbers come from.
    dynamic_load_rating : float
        Catalog basic dynamic load rating C; takes precedence over ISO 281 from the geometry. [N]
    fatigue_load_limit : float
        Catalog fatigue load limit Cu; takes precedence over ISO 281 annex B. [N]
    series : str
        Bearing series (``"62"``, ``"618"``, ``"72B"``) for the SKF friction constants; read from the
        designation when not given (:func:`bearinglab.friction.bearing_series`).
    seal : str
        Seal type (``"RS1"``, ``"RZ"``, ...) for the seal friction moment.
    seals : int
        Number of sealed sides, 0, 1 or 2.
    seal_diameter : float
        Seal counterface diameter d_s (SKF: the shoulder diameter the lip runs on). [m]
    inner_shoulder_height, outer_shoulder_height : float
        Height of the raceway shoulder on the loaded side above the groove bottom, for the check of a
        truncated contact ellipse (:mod:`bearinglab.limits`; a default fraction of D when not given). [m]
    clearance_class : str
        Radial internal clearance class of the designation (``"C3"``; ISO 5753-1), if any.
    tolerance_class : str
        Tolerance class of the designation (``"P5"``, ``"P4A"``; ISO 492), if any.
    static_load_factor : float
        The maker's calculation factor f0 (ISO 76), where the catalog prints it; else computed from the
        geometry. [-]
    preload_class : str
        Preload class of the designation (``"GA"``, ``"GB"``, ``"GC"``; ``"A"``, ``"B"``, ``"C"``), if any.
    preload : float
        The preload of that class from the maker's table (the middle of its range), where known. [N]
    estimated_fields : tuple of str
        Fields whose values are estimates, not published or measured (catalog entries without a
        published ball set; :mod:`bearinglab.estimation`).
    sources : dict
        Field -> where its value comes from (catalog entries).
    row_distance : float
        Axial distance between the ball centres of the two rows of a double-row bearing (32 A, 42);
        a self-aligning bearing's follows from its angle, d_m tan(alpha0). [m]

    Notes
    -----
    The types of :data:`ANGLE_BUILT_IN` (four-point, double-row angular, self-aligning, thrust) have their
    nominal contact angle built into the rings: ``contact_angle`` is that angle (the catalog's, at zero
    clearance) and ``radial_clearance`` their diametral clearance, given apart. A self-aligning bearing's
    outer raceway is a sphere about the bearing centre, radius R_o = d_m / (2 cos alpha0) + D/2 (ISO/TS
    16281's r_e of self-aligning bearings): ``outer_conformity`` R_o / D follows from the angle, or the
    angle from it; given both, they must agree.

    Examples
    --------
    >>> b = BallBearing.from_groove_radii(7, 2e-3, 8.7355e-3, 1.05e-3, 1.16e-3, contact_angle=math.radians(12))
    >>> print(round(b.total_curvature, 6), f"{b.radial_clearance * 1e6:.3f} um")
    0.105 9.178 um
    """

    n_balls: int | None = None
    ball_diameter: float | None = None
    pitch_diameter: float | None = None
    inner_conformity: float | None = None
    outer_conformity: float | None = None
    contact_angle: float | None = None
    radial_clearance: float | None = None
    designation: str = ""
    bore: float | None = None
    outside_diameter: float | None = None
    width: float | None = None
    type: str = "angular"
    static_load_rating: float | None = None
    ball_material: Material = STEEL
    ring_material: Material = STEEL
    hertz_table: dict = field(default_factory=dict, compare=False)
    source: str = ""
    dynamic_load_rating: float | None = None
    fatigue_load_limit: float | None = None
    series: str | None = None
    seal: str | None = None
    seals: int | None = None
    seal_diameter: float | None = None
    inner_shoulder_height: float | None = None
    outer_shoulder_height: float | None = None
    clearance_class: str | None = None
    tolerance_class: str | None = None
    static_load_factor: float | None = None
    preload_class: str | None = None
    preload: float | None = None
    estimated_fields: tuple = field(default=(), compare=False)
    sources: dict = field(default_factory=dict, compare=False)
    row_distance: float | None = None

    def __post_init__(self):
        if self.n_balls is not None and (
            not (isinstance(self.n_balls, (int, np.integer)) and not isinstance(self.n_balls, bool)) or self.n_balls < 1
        ):
            raise InputError(f"n_balls must be an integer >= 1 [-], got {self.n_balls!r}")
        for name, unit in (("ball_diameter", "m"), ("pitch_diameter", "m"), ("bore", "m"),
                           ("outside_diameter", "m"), ("width", "m"), ("static_load_rating", "N"),
                           ("dynamic_load_rating", "N"), ("fatigue_load_limit", "N"), ("seal_diameter", "m"),
                           ("inner_shoulder_height", "m"), ("outer_shoulder_height", "m"),
                           ("static_load_factor", "-"), ("row_distance", "m")):
            _positive(name, getattr(self, name), unit)
        for name in ("inner_conformity", "outer_conformity"):
            f = getattr(self, name)
            if f is not None and not (isinstance(f, (int, float, np.floating)) and 0.5 < f < 10.0):
                raise InputError(f"{name} must be in (0.5, 10) [-], got {f!r} (the groove radius f D must "
                                 "exceed the ball radius D/2)")
        if (
            self.ball_diameter is not None
            and self.pitch_diameter is not None
            and not self.pitch_diameter > self.ball_diameter
        ):
            raise InputError(
                f"pitch_diameter must be > ball_diameter [mm], got {self.pitch_diameter * 1e3:g} mm "
                f"with ball_diameter = {self.ball_diameter * 1e3:g} mm"
            )
        if self.bore is not None and self.outside_diameter is not None and not self.outside_diameter > self.bore:
            raise InputError(
                f"outside_diameter must be > bore [mm], got {self.outside_diameter * 1e3:g} mm "
                f"with bore = {self.bore * 1e3:g} mm"
            )
        if self.seals is not None and (isinstance(self.seals, bool) or self.seals not in (0, 1, 2)):
            raise InputError(f"seals must be 0, 1 or 2 (sealed sides) [-], got {self.seals!r}")
        for name in ("series", "seal"):
            if getattr(self, name) is not None and not isinstance(getattr(self, name), str):
                raise InputError(f"{name} must be a string, got {getattr(self, name)!r}")
        if self.type not in _TYPES:
            raise InputError(f"type must be one of {list(_TYPES)}, got {self.type!r}")
        if self.preload is not None and not (isinstance(self.preload, (int, float, np.floating)) and self.preload >= 0
                                             and math.isfinite(self.preload)):
            raise InputError(f"preload must be >= 0 [N], got {self.preload!r}")
        if self.contact_angle is not None:
            a = self.contact_angle
            thrust = self.type == "thrust"  # a thrust ball bearing's nominal angle is 90 deg
            if not (isinstance(a, (int, float, np.floating)) and 0.0 <= a < math.pi / 2 + (1e-12 if thrust else 0.0)):
                top = "90]" if thrust else "90)"
                raise InputError(f"contact_angle must be in [0, {top} [deg], got "
                                 f"{math.degrees(a) if isinstance(a, (int, float)) else a!r}")
        if self.radial_clearance is not None:
            _clearance_range(self.radial_clearance, self.ball_diameter)
        self._check_fit()
        self._check_shoulders()
        if self.type in ANGLE_BUILT_IN:  # the angle is the rings' own; the clearance is given apart
            if self.type == "self-aligning":
                self._sphere()
            return
        has_f = self.inner_conformity is not None and self.outer_conformity is not None and self.ball_diameter is not None
        if self.contact_angle is not None and self.radial_clearance is not None and has_f:
            self._check_angle_matches_clearance()
        if self.contact_angle is None and self.radial_clearance is not None:
            if not has_f:
                raise InputError("radial_clearance needs both groove conformities and the ball diameter to give a contact angle")
            angle = 0.0 if self.radial_clearance <= 0 else float(geometry.free_contact_angle(
                self.radial_clearance, self.ball_diameter, self.inner_conformity, self.outer_conformity))
            if not angle < math.pi / 2:  # arccos is real up to 4 B D, but a bearing's contact is below 90 deg
                limit = 2.0 * self.groove_distance
                raise InputError(f"radial_clearance must be in [{-2.0 * self.ball_diameter * 1e3:.6g}, {limit * 1e3:.6g}) "
                                 f"[mm] to give a contact angle below 90 deg (a negative clearance is a preload), got "
                                 f"{self.radial_clearance * 1e3:.6g} mm ({math.degrees(angle):.4g} deg)")
            object.__setattr__(self, "contact_angle", angle)
        elif self.contact_angle is not None and self.radial_clearance is None and has_f and self.contact_angle > 0:
            e = float(geometry.radial_clearance(self.contact_angle, self.ball_diameter,
                                                self.inner_conformity, self.outer_conformity))
            object.__setattr__(self, "radial_clearance", e)

    def _sphere(self):
        """A self-aligning bearing's spherical outer raceway about the bearing centre: R_o = d_m / (2 cos
        alpha0) + D/2 (the ball on the line through the sphere's centre at alpha0, zero clearance). The
        conformity follows from the angle or the angle from the conformity; both given must agree to the
        printed precision, and the row distance (if given) must be d_m tan(alpha0)."""
        d, dm, a, fo = self.ball_diameter, self.pitch_diameter, self.contact_angle, self.outer_conformity
        if d is None or dm is None:
            return
        if fo is None and a is not None:
            object.__setattr__(self, "outer_conformity", 0.5 + dm / (2.0 * d * math.cos(a)))
            object.__setattr__(self, "sources", {**self.sources, "outer_conformity": _SPHERE_SOURCE})
        elif fo is not None:
            c = dm / (2.0 * d * (fo - 0.5))
            if not c < 1.0:
                raise InputError(f"outer_conformity of a self-aligning bearing (its sphere R_o / D) must be > "
                                 f"{0.5 + dm / (2.0 * d):.6g} [-] (R_o > d_m/2 + D/2), got {fo!r}")
            implied = math.acos(c)
            if a is None:
                object.__setattr__(self, "contact_angle", implied)
            elif abs(implied - a) > ANGLE_CLEARANCE_TOLERANCE:
                raise InputError(f"contact_angle and outer_conformity of a self-aligning bearing disagree: its sphere "
                                 f"R_o = {fo * d * 1e3:.6g} mm gives {math.degrees(implied):.4g} deg with d_m = "
                                 f"{dm * 1e3:.6g} mm, not {math.degrees(a):.4g} deg; give one of them")
        a = self.contact_angle
        if self.row_distance is not None and a is not None:
            rows = dm * math.tan(a)
            if abs(self.row_distance - rows) > max(CLEARANCE_TOLERANCE * rows, 1e-5):
                raise InputError(f"row_distance of a self-aligning bearing is d_m tan(alpha0) = {rows * 1e3:.6g} mm "
                                 f"(both rows on lines through the sphere's centre), got {self.row_distance * 1e3:.6g} mm")

    def _check_fit(self):
        """The balls fit on the pitch circle, and the ball set fits between bore and outside diameter."""
        z, d, dm = self.n_balls, self.ball_diameter, self.pitch_diameter
        if z is not None and d is not None and dm is not None and z > 1:
            z_max = max_balls(d, dm)
            if z > z_max:
                raise InputError(
                    f"n_balls must be <= {z_max} [-] for balls of {d * 1e3:g} mm on a {dm * 1e3:g} mm pitch "
                    f"diameter (neighbouring balls would overlap: the pitch circle holds at most {z_max}), "
                    f"got {z}")
        if dm is not None and self.bore is not None and not dm - (d or 0.0) > self.bore:
            what = "pitch_diameter - ball_diameter" if d else "pitch_diameter"
            raise InputError(f"{what} must be > bore [mm] (the balls run outside the bore), got "
                             f"{(dm - (d or 0.0)) * 1e3:g} mm with bore = {self.bore * 1e3:g} mm")
        if dm is not None and self.outside_diameter is not None and not dm + (d or 0.0) < self.outside_diameter:
            what = "pitch_diameter + ball_diameter" if d else "pitch_diameter"
            raise InputError(f"{what} must be < outside_diameter [mm] (the balls run inside the outer ring), "
                             f"got {(dm + (d or 0.0)) * 1e3:g} mm with outside_diameter = "
                             f"{self.outside_diameter * 1e3:g} mm")

    def _check_shoulders(self):
        """A shoulder lies between the groove bottom and the ball centre: 0 < h < f D."""
        for race in ("inner", "outer"):
            h, f = getattr(self, f"{race}_shoulder_height"), getattr(self, f"{race}_conformity")
            if h is not None and f is not None and self.ball_diameter is not None and not h < f * self.ball_diameter:
                raise InputError(f"{race}_shoulder_height must be < the groove radius {f * self.ball_diameter * 1e3:.4g} "
                                 f"mm [mm] (a shoulder lower than the groove's centre), got {h * 1e3:g} mm")

    def _check_angle_matches_clearance(self):
        """A contact angle given together with a clearance must be the one the clearance implies (0 for a
        zero or negative clearance, a preload)."""
        if self.radial_clearance <= 0:
            if self.contact_angle > ANGLE_CLEARANCE_TOLERANCE:
                raise InputError(f"contact_angle and radial_clearance disagree: a clearance of "
                                 f"{self.radial_clearance * 1e6:.4g} um (a preload) gives a free contact angle of 0 "
                                 f"deg, not {math.degrees(self.contact_angle):.4g} deg; give one of them")
            return
        implied = float(geometry.free_contact_angle(
            min(self.radial_clearance, 4.0 * self.groove_distance * (1 - 1e-15)), self.ball_diameter,
            self.inner_conformity, self.outer_conformity))
        e = float(geometry.radial_clearance(self.contact_angle, self.ball_diameter, self.inner_conformity,
                                            self.outer_conformity))
        if abs(implied - self.contact_angle) > ANGLE_CLEARANCE_TOLERANCE and \
                abs(e - self.radial_clearance) > CLEARANCE_TOLERANCE * self.radial_clearance:
            raise InputError(
                f"contact_angle and radial_clearance disagree: the clearance "
                f"{self.radial_clearance * 1e6:.4g} um gives {math.degrees(implied):.4g} deg with these groove "
                f"radii, not {math.degrees(self.contact_angle):.4g} deg (which needs "
                f"{e * 1e6:.4g} um); give one of them")

    # ------------------------------------------------------------------ constructors
    @classmethod
    def from_groove_radii(cls, n_balls, ball_diameter, pitch_diameter, inner_groove_radius, outer_groove_radius, **kw):
        """Build from groove radii r_i, r_o [m] instead of conformities."""
        _positive("ball_diameter", ball_diameter, "m", optional=False)
        _positive("inner_groove_radius", inner_groove_radius, "m", optional=False)
        _positive("outer_groove_radius", outer_groove_radius, "m", optional=False)
        return cls(n_balls=n_balls, ball_diameter=ball_diameter, pitch_diameter=pitch_diameter,
                   inner_conformity=inner_groove_radius / ball_diameter,
                   outer_conformity=outer_groove_radius / ball_diameter, **kw)

    def replace(self, **changes):
        """A copy with some fields changed (validated again); a single-row bearing's angle and clearance
        follow each other (the one not given is derived again), those of :data:`ANGLE_BUILT_IN` do not."""
        if changes.get("type", self.type) not in ANGLE_BUILT_IN:
            if "contact_angle" in changes and "radial_clearance" not in changes:
                changes["radial_clearance"] = None
            if "radial_clearance" in changes and "contact_angle" not in changes:
                changes["contact_angle"] = None
        elif self.type == "self-aligning" and "outer_conformity" not in changes and \
                {"ball_diameter", "pitch_diameter", "contact_angle"} & set(changes) and \
                self.sources.get("outer_conformity") == _SPHERE_SOURCE:
            changes["outer_conformity"] = None  # the sphere follows the new ball set
        return dataclasses.replace(self, **changes)

    def require(self, *names):
        """Return the named fields, raising InputError naming the first one that is unknown."""
        out = []
        for name in names:
            value = getattr(self, name)
            if value is None:
                label = self.designation or "this bearing"
                hint = _MISSING_HINTS.get(name, "")
                raise InputError(f"{name} of {label!r} is not known; give it (catalog entry, file or option){hint}")
            out.append(value)
        return out[0] if len(out) == 1 else tuple(out)

    # ------------------------------------------------------------------ derived quantities
    @property
    def rows(self):
        """Ball rows i (ISO 281): 2 for the double-row and self-aligning types, else 1. [-]"""
        return ROWS.get(self.type, 1)

    @property
    def inner_groove_radius(self):
        """r_i = f_i D. [m]"""
        f, d = self.require("inner_conformity", "ball_diameter")
        return f * d

    @property
    def outer_groove_radius(self):
        """r_o = f_o D. [m]"""
        f, d = self.require("outer_conformity", "ball_diameter")
        return f * d

    @property
    def total_curvature(self):
        """B = f_i + f_o - 1. [-]"""
        return float(geometry.total_curvature(*self.require("inner_conformity", "outer_conformity")))

    @property
    def groove_distance(self):
        """A = B D, the distance between the groove-curvature centres. [m]"""
        return self.total_curvature * self.require("ball_diameter")

    @property
    def gamma(self):
        """gamma = D cos(alpha0) / d_m at the nominal angle. [-]"""
        d, dm, a = self.require("ball_diameter", "pitch_diameter", "contact_angle")
        return float(geometry.pitch_ratio(d, dm, a))

    @property
    def mean_diameter(self):
        """(bore + outside diameter) / 2, the d_m of the friction handbook. [m]"""
        d, big = self.require("bore", "outside_diameter")
        return 0.5 * (d + big)

    @property
    def ball_mass(self):
        """Mass of one ball. [kg]"""
        return self.ball_material.density * math.pi * self.require("ball_diameter") ** 3 / 6.0

    @property
    def reduced_modulus(self):
        """E' of the ball-ring pair. [Pa]"""
        b, r = self.ball_material, self.ring_material
        return float(hertz.reduced_modulus(b.elastic_modulus, b.poisson_ratio, r.elastic_modulus, r.poisson_ratio))

    def free_contact_angle_052(self):
        """Free angle from the clearance with both groove radii 0.52 D (spec 000 section 4). [rad]"""
        return float(geometry.free_contact_angle_052(*self.require("radial_clearance", "ball_diameter")))

    def axial_play(self):
        """Total axial play 2 B D sin(alpha0) (a double-row deep-groove bearing's too). Of the types whose angle
        is built into the rings (:data:`ANGLE_BUILT_IN`), 2 (sqrt(A^2 - g_r^2) - A sin alpha0) with
        g_r = A cos alpha0 - e/2 from their clearance e (0 when it is zero or negative: the balls touch
        concentric); a thrust ball bearing has none (InputError). [m]"""
        if self.type == "thrust":
            raise InputError("axial_play: a single-direction thrust ball bearing has no axial play (its washers are "
                             "apart until they are loaded)")
        if self.type in ANGLE_BUILT_IN:
            a, e = self.require("contact_angle", "radial_clearance")
            big_a = self.groove_distance
            g_r = big_a * math.cos(a) - 0.5 * e
            return 2.0 * max(math.sqrt(max(big_a * big_a - g_r * g_r, 0.0)) - big_a * math.sin(a), 0.0)
        return float(geometry.axial_play(self.require("contact_angle"), *self.require("ball_diameter", "inner_conformity", "outer_conformity")))

    def curvature(self, race, contact_angle=None):
        """Curvature sum and F(rho) of the ``race`` contact, at ``contact_angle`` (default nominal)."""
        conf = self.require("inner_conformity" if race == "inner" else "outer_conformity")
        angle = self.require("contact_angle") if contact_angle is None else contact_angle
        return geometry.raceway_curvature(*self.require("ball_diameter", "pitch_diameter"), conf, angle, race=race)

    def groove_centres(self):
        """Groove-centre circles T_v, T_n and the paper's m_v, m_n (spec 000 section 5.1)."""
        return geometry.groove_centre_diameters(
            *self.require("ball_diameter", "pitch_diameter", "inner_conformity", "outer_conformity", "contact_angle"))
