r"""A shaft system as Python objects: the shaft, its supports and its loads, checked on creation (SI units).

The shaft
---------
Section            one cylindrical section: length, diameter, optional bore
Shaft              the sections in order from z = 0, the material and its thermal expansion

Supports
--------
Housing            linear springs of a bearing seat, in series with the bearing
BearingSupport     one bearing (any catalog or user bearing) at a position, located axially or floating
BearingSetSupport  a preloaded set (DB, DF, DT) centred at a position, as in ``bearing-set``
LinearSupport      linear springs to the ground: radial, optional axial and tilt
RigidSupport       the radial displacement held, free to tilt (a simple support)

Loads
-----
PointLoad          forces and moments at a position
Gear               a spur or helical gear mesh: its forces from the torque or power
Pulley             a belt pull in a direction, and its torque
Mass               a rigid mass on the shaft (a tool, a rotor): weight and inertia
gear_loads         the forces and moments a gear mesh puts on the shaft axis
pulley_loads       the belt pull and torque of a pulley on the shaft axis

The system
----------
ShaftSystem        shaft, supports, loads, gears, pulleys, masses, gravity, speed and temperatures

Positions z run along the shaft axis from its left end; x and y are radial, as in
:mod:`bearinglab.quasistatic.combined`. Every check raises :class:`~bearinglab.errors.InputError` with
one line that names the field (``supports[1].position``), the rule and the value; the file reader
(:mod:`bearinglab.shaft.reading`) words the same checks for the file.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..bearing import STEEL, BallBearing, Material
from ..errors import InputError

__all__ = ["BearingSetSupport", "BearingSupport", "Gear", "Housing", "LinearSupport", "Mass", "PointLoad",
           "Pulley", "RigidSupport", "Section", "Shaft", "ShaftSystem", "gear_loads", "pulley_loads"]

_MM = 1e-3
#: the most elements a shaft mesh may hold (dense matrices of 6 (n + 1) rows; 400 elements: 2406 rows)
MAX_ELEMENTS = 400
#: the most supports, loads, gears, pulleys or masses of one system
MAX_ITEMS = 100
#: thermal expansion of the default shaft steel: mounting_materials.toml [steel] [1/K]
_STEEL_EXPANSION = 12.5e-6


def _mm(x):
    return f"{x / _MM:g} mm"


def _finite(name, value, unit="m"):
    if isinstance(value, bool) or not isinstance(value, (int, float, np.floating, np.integer)):
        raise InputError(f"{name} must be a number [{unit}], got {value!r}")
    if not math.isfinite(value):
        raise InputError(f"{name} must be finite [{unit}], got {value!r}")
    return float(value)


def _positive(name, value, unit="m"):
    v = _finite(name, value, unit)
    if not v > 0:
        raise InputError(f"{name} must be > 0 [{unit}], got {v!r}")
    return v


def _nonnegative(name, value, unit, *, allow_inf=False):
    if allow_inf and isinstance(value, (int, float)) and value == math.inf:
        return math.inf
    v = _finite(name, value, unit)
    if not v >= 0:
        raise InputError(f"{name} must be >= 0 [{unit}], got {v!r}")
    return v


# --------------------------------------------------------------------------- the shaft
@dataclass(frozen=True)
class Section:
    """One cylindrical section of the shaft.

    Parameters
    ----------
    length : float
        Length along z. [m]
    diameter : float
        Outside diameter. [m]
    bore : float, optional
        Bore of a hollow section, < diameter (0: solid). [m]
    start : float, optional
        Where the section begins; when given it must be the end of the section before it (a check of
        the drawing: an earlier start overlaps, a later one leaves a gap). [m]
    """

    length: float
    diameter: float
    bore: float = 0.0
    start: float | None = None

    def __post_init__(self):
        _positive("length", self.length)
        _positive("diameter", self.diameter)
        b = _nonnegative("bore", self.bore, "m")
        if not b < self.diameter:
            raise InputError(f"bore must be < the diameter {_mm(self.diameter)}, got {_mm(b)}")
        if self.start is not None:
            _nonnegative("start", self.start, "m")


@dataclass(frozen=True)
class Shaft:
    """The shaft: its sections from z = 0, its material and thermal expansion.

    Parameters
    ----------
    sections : tuple of Section
        In order from the left end.
    material : Material, optional
        E, nu and density (default: steel of :mod:`bearinglab.mounting.materials`, the rings' steel).
    thermal_expansion : float, optional
        Linear expansion coefficient, for the axial growth between the bearings. [1/K]

    Examples
    --------
    >>> s = Shaft((Section(0.1, 0.04), Section(0.2, 0.05, 0.02)))
    >>> print(f"{s.length * 1e3:g} mm, ends {[round(x * 1e3, 6) for x in s.ends]}")
    300 mm, ends [0.0, 100.0, 300.0]
    """

    sections: tuple
    material: Material = STEEL
    thermal_expansion: float = _STEEL_EXPANSION

    def __post_init__(self):
        secs = tuple(self.sections)
        object.__setattr__(self, "sections", secs)
        if not secs:
            raise InputError("sections: a shaft needs at least one section")
        if len(secs) > MAX_ELEMENTS:
            raise InputError(f"sections: at most {MAX_ELEMENTS}, got {len(secs)}")
        end = 0.0
        for k, s in enumerate(secs):
            if not isinstance(s, Section):
                raise InputError(f"sections[{k}] must be a Section, got {type(s).__name__}")
            if s.start is not None and not math.isclose(s.start, end, rel_tol=0.0, abs_tol=1e-9):
                what = "overlaps the section before it" if s.start < end else "leaves a gap after the section before it"
                raise InputError(f"sections[{k}].start: the section {what}: it starts at {_mm(s.start)}, "
                                 f"the sections before it end at {_mm(end)} (sections run in order from z = 0)")
            end += s.length
        if not isinstance(self.material, Material):
            raise InputError(f"material must be a bearinglab.bearing.Material, got {type(self.material).__name__}")
        _nonnegative("thermal_expansion", self.thermal_expansion, "1/K")

    @property
    def length(self):
        """Total length. [m]"""
        return float(sum(s.length for s in self.sections))

    @property
    def ends(self):
        """z of the section boundaries, from 0 to the length. [m]"""
        return [0.0, *np.cumsum([s.length for s in self.sections]).tolist()]

    def section_at(self, z):
        """The index of the section that holds z (at a boundary, the one to its right)."""
        ends = self.ends
        for k in range(len(self.sections)):
            if z < ends[k + 1] or k == len(self.sections) - 1:
                return k
        return len(self.sections) - 1


# --------------------------------------------------------------------------- supports
@dataclass(frozen=True)
class Housing:
    """Linear springs between a bearing's outer ring and the ground, in series with the bearing.

    Parameters
    ----------
    radial_stiffness : float, optional
        Along x and along y (inf: rigid). [N/m]
    axial_stiffness : float, optional
        Along z (inf: rigid). [N/m]
    tilt_stiffness : float, optional
        About x and about y (inf: rigid). [N m/rad]
    """

    radial_stiffness: float = math.inf
    axial_stiffness: float = math.inf
    tilt_stiffness: float = math.inf

    def __post_init__(self):
        for name, unit in (("radial_stiffness", "N/m"), ("axial_stiffness", "N/m"), ("tilt_stiffness", "N m/rad")):
            v = _nonnegative(name, getattr(self, name), unit, allow_inf=True)
            if not v > 0:
                raise InputError(f"{name} must be > 0 [{unit}] (a housing spring in series with the bearing), "
                                 f"got {v!r}")

    @property
    def diagonal(self):
        """(k_x, k_y, k_z, k_theta_x, k_theta_y); inf where rigid."""
        return np.array([self.radial_stiffness, self.radial_stiffness, self.axial_stiffness,
                         self.tilt_stiffness, self.tilt_stiffness], dtype=float)


def _orientation(value):
    if value in (1, -1) and not isinstance(value, bool):
        return int(value)
    raise InputError(f"orientation must be +1 (the bearing takes the shaft's thrust towards +z) or -1, got {value!r}")


@dataclass(frozen=True)
class BearingSupport:
    """One rolling bearing between the shaft and the housing.

    Parameters
    ----------
    name : str
        Shown in the results.
    position : float
        z of the bearing centre. [m]
    bearing : BallBearing
        Any catalog or user bearing (:func:`bearinglab.catalog.get`).
    orientation : {+1, -1}, optional
        +1: the bearing carries the shaft's thrust towards +z (its contact lines meet the axis on the -z
        side, as orientation +1 in :mod:`bearinglab.quasistatic.sets`); -1 the mirror image.
    axial : bool, optional
        The outer ring is held axially (a locating bearing); False: it slides in the housing and
        carries no thrust (a floating bearing).
    housing : Housing, optional
        Springs of the seat in series (default rigid).
    axial_offset : float, optional
        Axial position of the outer ring along the bearing's own axis beyond the position where its
        balls first touch with the shaft at z-displacement 0 (a shim or an adjusting nut, as
        ``preload_offset`` of a set): > 0 preloads it against an opposed bearing, < 0 leaves axial play.
        Default 0: the bearing touches at the shaft's zero position. [m]
    """

    name: str
    position: float
    bearing: BallBearing
    orientation: int = 1
    axial: bool = False
    housing: Housing | None = None
    axial_offset: float = 0.0

    def __post_init__(self):
        _finite("position", self.position)
        if not isinstance(self.bearing, BallBearing):
            raise InputError(f"bearing must be a bearing (bearinglab.catalog.get), got {type(self.bearing).__name__}")
        object.__setattr__(self, "orientation", _orientation(self.orientation))
        _finite("axial_offset", self.axial_offset)
        if self.housing is not None and not isinstance(self.housing, Housing):
            raise InputError(f"housing must be a Housing, got {type(self.housing).__name__}")


@dataclass(frozen=True)
class BearingSetSupport:
    """A preloaded set of bearings centred at a position, as ``bearing-set`` solves it on a rigid shaft.

    Parameters
    ----------
    name : str
    position : float
        z of the middle of the set (between its outer two bearing centres). [m]
    bearings : tuple of BallBearing
        From -z to +z; one bearing stands for a pair.
    arrangement : {"DB", "DF", "DT"}, optional
        As :func:`bearinglab.quasistatic.sets.arrangement`.
    spacing : float, optional
        Between neighbouring bearing centres (default: side by side, one ring width apart). [m]
    preload : float, optional
        Axial force of each group of like-oriented bearings at rest, with no external load. [N]
    preload_offset : float, optional
        The axial interference from first contact instead (a ground spacer). [m]
    axial : bool, optional
        The set locates the shaft axially (default True: the usual fixed bearing of a spindle).
    housing : Housing, optional
        Springs of the seat in series, for each bearing of the set.
    """

    name: str
    position: float
    bearings: tuple
    arrangement: str = "DB"
    spacing: float | None = None
    preload: float = 0.0
    preload_offset: float | None = None
    axial: bool = True
    housing: Housing | None = None

    def __post_init__(self):
        from ..quasistatic import sets

        _finite("position", self.position)
        bl = (self.bearings,) if isinstance(self.bearings, BallBearing) else tuple(self.bearings)
        if not bl or not all(isinstance(b, BallBearing) for b in bl):
            raise InputError("bearings must be one or more bearings (bearinglab.catalog.get)")
        if len(bl) > 8:
            raise InputError(f"bearings: at most 8 in a set, got {len(bl)}")
        object.__setattr__(self, "bearings", bl)
        if self.arrangement not in sets.ARRANGEMENTS:
            raise InputError(f"arrangement must be one of {list(sets.ARRANGEMENTS)}, got {self.arrangement!r}")
        if self.spacing is not None:
            _nonnegative("spacing", self.spacing, "m")
        _nonnegative("preload", self.preload, "N")
        if self.preload_offset is not None:
            _finite("preload_offset", self.preload_offset)
            if self.preload:
                raise InputError("preload_offset: give preload or preload_offset, not both")
        if self.housing is not None and not isinstance(self.housing, Housing):
            raise InputError(f"housing must be a Housing, got {type(self.housing).__name__}")

    def rows(self):
        """The bearings one by one: (bearing, z, orientation) from -z to +z."""
        from ..quasistatic import sets

        bl = list(self.bearings)
        n = 2 if len(bl) == 1 else len(bl)
        bl = bl * n if len(bl) == 1 else bl
        gaps = sets.default_spacing(bl) if self.spacing is None else self.spacing
        orient, pos = sets.arrangement(self.arrangement, gaps, n)
        return [(b, self.position + float(z), int(o)) for b, z, o in zip(bl, pos, orient, strict=True)]


@dataclass(frozen=True)
class LinearSupport:
    """Linear springs between the shaft and the ground (a hydrodynamic or magnetic bearing, a test fixture).

    Parameters
    ----------
    name : str
    position : float
        [m]
    radial_stiffness : float
        Along x and along y, > 0. [N/m]
    axial_stiffness : float, optional
        Along z; given, the support locates the shaft axially. [N/m]
    tilt_stiffness : float, optional
        About x and about y (0: free to tilt). [N m/rad]
    axial : bool, optional
        Locates the shaft axially; without ``axial_stiffness``, rigidly.
    """

    name: str
    position: float
    radial_stiffness: float
    axial_stiffness: float | None = None
    tilt_stiffness: float = 0.0
    axial: bool = False

    def __post_init__(self):
        _finite("position", self.position)
        _positive("radial_stiffness", self.radial_stiffness, "N/m")
        if self.axial_stiffness is not None:
            _positive("axial_stiffness", self.axial_stiffness, "N/m")
            object.__setattr__(self, "axial", True)
        _nonnegative("tilt_stiffness", self.tilt_stiffness, "N m/rad")


@dataclass(frozen=True)
class RigidSupport:
    """The radial displacement held at a position, the shaft free to tilt there (a simple support).

    Parameters
    ----------
    name : str
    position : float
        [m]
    axial : bool, optional
        Also hold the axial displacement.
    """

    name: str
    position: float
    axial: bool = False

    def __post_init__(self):
        _finite("position", self.position)


# --------------------------------------------------------------------------- loads
@dataclass(frozen=True)
class PointLoad:
    """Forces and moments on the shaft axis at a position.

    Parameters
    ----------
    position : float
        [m]
    fx, fy, fz : float, optional
        [N]
    mx, my, mz : float, optional
        Moments about x, y and the shaft axis (a torque). [N m]
    name : str, optional
    """

    position: float
    fx: float = 0.0
    fy: float = 0.0
    fz: float = 0.0
    mx: float = 0.0
    my: float = 0.0
    mz: float = 0.0
    name: str = ""

    def __post_init__(self):
        _finite("position", self.position)
        for k in ("fx", "fy", "fz"):
            _finite(k, getattr(self, k), "N")
        for k in ("mx", "my", "mz"):
            _finite(k, getattr(self, k), "N m")

    @property
    def vector(self):
        """(fx, fy, fz, mx, my, mz)."""
        return np.array([self.fx, self.fy, self.fz, self.mx, self.my, self.mz], dtype=float)


@dataclass(frozen=True)
class Gear:
    r"""A gear on the shaft: the mesh force from its torque or power.

    Parameters
    ----------
    position : float
        z of the middle of the face width. [m]
    pitch_diameter : float
        Operating pitch diameter d_w. [m]
    pressure_angle : float
        Normal pressure angle alpha_n, in [0, 45 deg). [rad]
    helix_angle : float, optional
        beta, > 0 for a right-hand helix, < 0 left-hand, in (-45, 45) deg. [rad]
    torque : float, optional
        Torque the mesh puts on the shaft about +z. [N m]
    power : float, optional
        Power through the mesh instead: > 0 flows into the shaft (the gear drives it), < 0 out. [W]
    mesh_angle : float, optional
        Azimuth of the contact with the mating gear, from +x towards +y. [rad]
    rotation : {+1, -1}, optional
        Sense of rotation about +z, for ``power``; default the sign of the speed.
    mass, polar_inertia, diametral_inertia : float, optional
        The gear body as a rigid mass (weight, natural frequencies). [kg, kg m^2]
    name : str, optional
    """

    position: float
    pitch_diameter: float
    pressure_angle: float
    helix_angle: float = 0.0
    torque: float | None = None
    power: float | None = None
    mesh_angle: float = 0.0
    rotation: int | None = None
    mass: float = 0.0
    polar_inertia: float = 0.0
    diametral_inertia: float | None = None
    name: str = ""

    def __post_init__(self):
        _finite("position", self.position)
        _positive("pitch_diameter", self.pitch_diameter)
        a = _finite("pressure_angle", self.pressure_angle, "rad")
        if not 0 <= a < math.radians(45):
            raise InputError(f"pressure_angle must be in [0, 45) [deg], got {math.degrees(a):g} deg")
        b = _finite("helix_angle", self.helix_angle, "rad")
        if not abs(b) < math.radians(45):
            raise InputError(f"helix_angle must be in (-45, 45) [deg], got {math.degrees(b):g} deg")
        if (self.torque is None) == (self.power is None):
            raise InputError("torque: give the gear's torque or its power, one of the two")
        if self.torque is not None:
            _finite("torque", self.torque, "N m")
        if self.power is not None:
            _finite("power", self.power, "W")
        _finite("mesh_angle", self.mesh_angle, "rad")
        if self.rotation is not None and self.rotation not in (1, -1):
            raise InputError(f"rotation must be +1 or -1 (the sense about +z), got {self.rotation!r}")
        _mass_checks(self)


def _mass_checks(obj):
    _nonnegative("mass", obj.mass, "kg")
    _nonnegative("polar_inertia", obj.polar_inertia, "kg m^2")
    if obj.diametral_inertia is not None:
        _nonnegative("diametral_inertia", obj.diametral_inertia, "kg m^2")


@dataclass(frozen=True)
class Pulley:
    """A belt or chain pulley: the belt pull on the shaft in a direction, and the torque it passes.

    Parameters
    ----------
    position : float
        [m]
    force : float
        The pull of both strands together on the shaft, >= 0. [N]
    direction : float, optional
        Its direction in the x-y plane, from +x towards +y. [rad]
    torque : float, optional
        Torque on the shaft about +z. [N m]
    mass, polar_inertia, diametral_inertia : float, optional
        [kg, kg m^2]
    name : str, optional
    """

    position: float
    force: float
    direction: float = 0.0
    torque: float = 0.0
    mass: float = 0.0
    polar_inertia: float = 0.0
    diametral_inertia: float | None = None
    name: str = ""

    def __post_init__(self):
        _finite("position", self.position)
        _nonnegative("force", self.force, "N")
        _finite("direction", self.direction, "rad")
        _finite("torque", self.torque, "N m")
        _mass_checks(self)


@dataclass(frozen=True)
class Mass:
    """A rigid mass on the shaft: its weight under gravity and its inertia in the natural frequencies.

    Parameters
    ----------
    position : float
        [m]
    mass : float
        [kg]
    polar_inertia : float, optional
        About the shaft axis. [kg m^2]
    diametral_inertia : float, optional
        About a diameter (default half the polar inertia, a thin disk). [kg m^2]
    name : str, optional
    """

    position: float
    mass: float
    polar_inertia: float = 0.0
    diametral_inertia: float | None = None
    name: str = ""

    def __post_init__(self):
        _finite("position", self.position)
        _mass_checks(self)


def gear_loads(gear, shaft_speed):
    r"""The forces and moments a gear mesh puts on the shaft axis at the gear's position.

    Parameters
    ----------
    gear : Gear
    shaft_speed : array_like
        Signed speed about +z (its sign is the default sense of rotation; needed with ``power``). [rad/s]

    Returns
    -------
    ndarray
        (..., 6) F_x, F_y, F_z [N], M_x, M_y, M_z [N m].

    Notes
    -----
    With r = d_w/2, the contact at P = r (cos phi, sin phi) and the torque T on the shaft (given, or
    P_power s / abs(Omega) with s the sense of rotation): the tangential force F_t = T / r along
    (-sin phi, cos phi); the radial (separating) force abs(F_t) tan(alpha_n) / cos(beta) towards the
    axis; the axial force -F_t tan(beta) (the tooth normal lies in the pitch plane across the helix
    (sin beta, cos beta) of a right-hand tooth); the moments r x F of these forces about the axis
    point, which give M_z = T. ISO 6336-1:2019 section 5 (F_t = 2000 T / d, F_r = F_t tan(alpha_wt),
    F_x = F_t tan(beta_w)).

    Examples
    --------
    >>> g = Gear(0.1, 0.2, math.radians(20.0), torque=100.0)
    >>> print(np.round(gear_loads(g, 100.0), 3))
    [-363.97 1000.      0.      0.      0.    100.  ]
    """
    w = np.asarray(shaft_speed, dtype=float)
    r = 0.5 * gear.pitch_diameter
    if gear.torque is not None:
        t = np.full(w.shape, float(gear.torque))
    else:
        if np.any(w == 0):
            raise InputError("power: a gear given by its power needs a speed (the torque is P / speed); give "
                             "its torque, or a speed")
        sense = np.sign(w) if gear.rotation is None else gear.rotation
        t = gear.power * sense / np.abs(w)
    ft = t / r
    phi, alpha, beta = gear.mesh_angle, gear.pressure_angle, gear.helix_angle
    fr = np.abs(ft) * math.tan(alpha) / math.cos(beta)
    fx = -ft * math.sin(phi) - fr * math.cos(phi)
    fy = ft * math.cos(phi) - fr * math.sin(phi)
    fz = -ft * math.tan(beta)
    px, py = r * math.cos(phi), r * math.sin(phi)
    out = np.stack([fx, fy, fz, py * fz, -px * fz, px * fy - py * fx], axis=-1)
    return out + 0.0  # no -0


def pulley_loads(pulley):
    """The forces and moments a pulley puts on the shaft axis at its position.

    Parameters
    ----------
    pulley : Pulley

    Returns
    -------
    ndarray
        (6,) F_x, F_y, F_z [N], M_x, M_y, M_z [N m]: the belt pull in its direction and the torque.

    Examples
    --------
    >>> print(pulley_loads(Pulley(0.1, 500.0, math.pi / 2, torque=20.0)).round(9))
    [  0. 500.   0.   0.   0.  20.]
    """
    return np.array([pulley.force * math.cos(pulley.direction), pulley.force * math.sin(pulley.direction),
                     0.0, 0.0, 0.0, pulley.torque]) + 0.0


# --------------------------------------------------------------------------- the system
_SUPPORT_TYPES = (BearingSupport, BearingSetSupport, LinearSupport, RigidSupport)


@dataclass(frozen=True)
class ShaftSystem:
    """A shaft on its supports under loads: what :func:`bearinglab.shaft.solve` solves.

    Parameters
    ----------
    shaft : Shaft
    supports : tuple
        BearingSupport, BearingSetSupport, LinearSupport or RigidSupport, at distinct positions.
    loads, gears, pulleys, masses : tuple, optional
        PointLoad, Gear, Pulley and Mass items.
    gravity : tuple of float, optional
        The acceleration of gravity (g_x, g_y, g_z) for the weight of the shaft and its masses; None
        leaves the weight out. [m/s^2]
    speed : float, optional
        Shaft (inner-ring) speed about +z; its sign is the sense of rotation. [rad/s]
    shaft_temperature, housing_temperature : float, optional
        Operating temperatures; given, the shaft's and housing's axial growth between the bearings
        (from 20 degC) shifts each bearing's rings, and the bearings' clearances follow the mounting
        chain (:mod:`bearinglab.mounting.chain`). [K]
    housing_material : str, optional
        The housing's material by name (:data:`bearinglab.mounting.materials.MATERIAL_NAMES`): its thermal
        expansion and, for the mounting chain, its elastic constants.
    elements : int, optional
        The mesh: at least this many elements over the shaft's length, refined at every section
        change, support and load (each interval between two such points split evenly). [-]

    Raises
    ------
    InputError
        A support outside the shaft, two supports at one position, a bearing wider than its seat, no
        axial location, a mechanism (too few supports), a load outside the shaft, torques that do not
        balance, a mesh of more than 400 elements.
    """

    shaft: Shaft
    supports: tuple
    loads: tuple = ()
    gears: tuple = ()
    pulleys: tuple = ()
    masses: tuple = ()
    gravity: tuple | None = None
    speed: float = 0.0
    shaft_temperature: float | None = None
    housing_temperature: float | None = None
    housing_material: str = "steel"
    elements: int = 30

    def __post_init__(self):
        if not isinstance(self.shaft, Shaft):
            raise InputError(f"shaft must be a Shaft, got {type(self.shaft).__name__}")
        for name, kind in (("supports", _SUPPORT_TYPES), ("loads", (PointLoad,)), ("gears", (Gear,)),
                           ("pulleys", (Pulley,)), ("masses", (Mass,))):
            items = tuple(getattr(self, name))
            object.__setattr__(self, name, items)
            if len(items) > MAX_ITEMS:
                raise InputError(f"{name}: at most {MAX_ITEMS}, got {len(items)}")
            for k, item in enumerate(items):
                if not isinstance(item, kind):
                    raise InputError(f"{name}[{k}] must be one of {[t.__name__ for t in kind]}, got "
                                     f"{type(item).__name__}")
        _finite("speed", self.speed, "rad/s")
        if self.gravity is not None:
            g = np.asarray(self.gravity, dtype=float)
            if g.shape != (3,) or not np.all(np.isfinite(g)):
                raise InputError(f"gravity must be three finite components (g_x, g_y, g_z) [m/s^2], got {self.gravity!r}")
            object.__setattr__(self, "gravity", tuple(float(x) for x in g))
        for name in ("shaft_temperature", "housing_temperature"):
            t = getattr(self, name)
            if t is not None and not (_finite(name, t, "K") > 0):
                raise InputError(f"{name} must be > 0 [K] (above absolute zero), got {t!r}")
        from ..mounting.materials import material

        try:
            material(self.housing_material)
        except InputError as exc:
            raise InputError(f"housing_{exc}") from None
        if isinstance(self.elements, bool) or int(self.elements) != self.elements or not 1 <= self.elements <= MAX_ELEMENTS:
            raise InputError(f"elements must be a whole number in 1 ... {MAX_ELEMENTS}, got {self.elements!r}")
        self._check_positions()
        self._check_seats()
        self._check_location()
        self._check_torques()

    # ----------------------------------------------------------------- checks
    def _check_positions(self):
        length = self.shaft.length
        tol = 1e-9
        seen = {}
        for k, s in enumerate(self.supports):
            zs = [z for _, z, _ in s.rows()] if isinstance(s, BearingSetSupport) else [s.position]
            for z in zs:
                if not -tol <= z <= length + tol:
                    raise InputError(f"supports[{k}].position: {s.name or 'the support'} at {_mm(z)} lies outside the "
                                     f"shaft (0 ... {_mm(length)})")
                key = round(z / tol)
                if key in seen:
                    raise InputError(f"supports[{k}].position: {s.name or 'the support'} at {_mm(z)} is where "
                                     f"supports[{seen[key]}] is; give each support its own position")
                seen[key] = k
        for name in ("loads", "gears", "pulleys", "masses"):
            for k, item in enumerate(getattr(self, name)):
                if not -tol <= item.position <= length + tol:
                    raise InputError(f"{name}[{k}].position: {_mm(item.position)} lies outside the shaft "
                                     f"(0 ... {_mm(length)})")

    def _check_seats(self):
        """Each bearing sits on one seat: its width B within one stretch of constant diameter."""
        ends = self.shaft.ends
        secs = self.shaft.sections
        for k, s in enumerate(self.supports):
            if isinstance(s, BearingSupport):
                rows = [(s.bearing, s.position, s.orientation)]
            elif isinstance(s, BearingSetSupport):
                rows = s.rows()
            else:
                continue
            for b, z, _ in rows:
                if b.width is None:
                    continue
                i = self.shaft.section_at(z)
                lo, hi = i, i  # the seat: neighbouring sections of the same diameter and bore
                while lo > 0 and (secs[lo - 1].diameter, secs[lo - 1].bore) == (secs[i].diameter, secs[i].bore):
                    lo -= 1
                while hi < len(secs) - 1 and (secs[hi + 1].diameter, secs[hi + 1].bore) == (secs[i].diameter, secs[i].bore):
                    hi += 1
                a, c = ends[lo], ends[hi + 1]
                if z - 0.5 * b.width < a - 1e-9 or z + 0.5 * b.width > c + 1e-9:
                    raise InputError(f"supports[{k}].position: bearing {b.designation or ''} (width {_mm(b.width)}) "
                                     f"at {_mm(z)} is wider than its seat, the {_mm(secs[i].diameter)} section "
                                     f"from {_mm(a)} to {_mm(c)}; move it or lengthen the seat")

    def _check_location(self):
        axial = [s for s in self.supports if getattr(s, "axial", False)]
        if not axial:
            raise InputError("supports: no support locates the shaft axially; mark the fixed bearing(s) with "
                             "axial = true")
        radial = len(self.supports) + sum(len(s.rows()) - 1 for s in self.supports if isinstance(s, BearingSetSupport))
        tilt = any(isinstance(s, BearingSetSupport) or (isinstance(s, LinearSupport) and s.tilt_stiffness > 0)
                   for s in self.supports)
        if radial < 2 and not tilt:
            raise InputError(f"supports: a mechanism: {len(self.supports)} support holds the shaft at one point, "
                             "free to tilt; give two supports, or one that holds the tilt (a bearing set, a "
                             "linear support with tilt_stiffness)")

    def _check_torques(self):
        if self.speed == 0 and any(g.power is not None for g in self.gears):
            raise InputError("power: a gear given by its power needs a speed (the torque is P / speed); give its "
                             "torque, or the speed")
        total = self.torque_sum(self.speed)
        scale = max([abs(float(x)) for x in self._torques(self.speed)] + [1e-300])
        if abs(total) > 1e-9 * scale:
            raise InputError(f"loads: the torques on the shaft do not balance (their sum is {total:.6g} N m, nothing "
                             "holds the shaft in torsion): give the torque out as well (a gear, a pulley's torque "
                             "or a load's mz)")

    def _torques(self, speed):
        out = [ld.mz for ld in self.loads] + [p.torque for p in self.pulleys]
        out += [float(gear_loads(g, speed if speed else 1.0)[5]) for g in self.gears if g.power is None or speed]
        return out

    def torque_sum(self, speed):
        """The sum of the torques about the axis at a speed (0 when they balance). [N m]"""
        return float(sum(self._torques(speed)))

    # ----------------------------------------------------------------- views
    @property
    def length(self):
        """The shaft's length. [m]"""
        return self.shaft.length

    def replace(self, **changes):
        """A copy with fields changed (checked again)."""
        import dataclasses

        return dataclasses.replace(self, **changes)
