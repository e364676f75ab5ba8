"""The roller bearing as an input of the models: a frozen dataclass checked on creation.

Bearing
-------
RollerBearing     cylindrical (N, NU, NJ, NUP), tapered (single row) and spherical roller bearings: internal
                  geometry, roller profile, envelope, catalogue ratings and factors, materials
ROLLER_TYPES      the types; DESIGNS their designs

What each type is modelled for: cylindrical and tapered roller bearings in every model (the slice model of
load distribution and stiffness, ISO 281 / ISO/TS 16281 lives, SKF friction, the line-contact film);
spherical roller bearings for ratings, life (ISO 281) and friction only: their load distribution (two
rows of barrel rollers on a spherical outer raceway) is not modelled, and the models that need it say so.

The physics is in :mod:`bearinglab.rollers.geometry`, :mod:`~bearinglab.rollers.contact` and
:mod:`~bearinglab.rollers.distribution`; the class only checks and passes its fields on. It shares
:class:`bearinglab.bearing.Material` with the ball bearing.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field

import numpy as np

from .. import hertz
from ..bearing import STEEL, Material
from ..errors import InputError
from . import geometry

__all__ = ["DESIGNS", "ROLLER_TYPES", "RollerBearing"]

#: Roller bearing types.
ROLLER_TYPES = ("cylindrical", "tapered", "spherical")
#: Designs of each type: ribs of a cylindrical roller bearing (N: ribs on the inner ring; NU: on the outer
#: ring; NJ: NU with one inner rib, locating in +z; NUP: NU with a loose rib, locating both ways); a single
#: row tapered roller bearing; a double-row spherical roller bearing.
DESIGNS = {"cylindrical": ("NU", "N", "NJ", "NUP"), "tapered": ("single",), "spherical": ("double",)}
_PROFILE_FIELDS = ("crown_drop", "edge_radius", "edge_length")


def _positive(name, value, unit, optional=True):
    if value is None and optional:
        return
    ok = isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(value, bool) and math.isfinite(value)
    if not ok or not value > 0:
        raise InputError(f"{name} must be > 0 [{unit}], got {value!r}")


@dataclass(frozen=True)
class RollerBearing:
    """Geometry, profile, envelope, ratings and materials of a roller bearing, checked on creation.

    Parameters
    ----------
    type : {"cylindrical", "tapered", "spherical"}
        The bearing type.
    rollers : int
        Z, rollers per row. [-]
    roller_diameter : float
        D_we (of a tapered roller: in the middle of its length). [m]
    roller_length : float
        L_we, the effective roller length (the straight contact length, without the end chamfers). [m]
    pitch_diameter : float
        D_pw, the circle through the middles of the rollers. [m]
    contact_angle : float
        alpha: 0 for a cylindrical roller bearing; the cup angle of a tapered one (outer raceway to the
        bearing axis, in (0, 45 deg]; the cone and roller angles follow, :attr:`tapered_angles`); the
        nominal angle of the rows of a spherical one. [rad]
    radial_clearance : float
        The operating diametral clearance e (the radial play of one ring against the other); 0 or
        negative (preload) allowed. None: 0 in the models. [m]
    design : str
        ``"NU"`` (default), ``"N"``, ``"NJ"``, ``"NUP"`` for a cylindrical roller bearing (:data:`DESIGNS`).
    rows : int
        1, or 2 for a spherical roller bearing (the default there). [-]
    profile : str or sequence of (position, drop)
        ``"logarithmic"`` (ISO/TS 16281's, the default), ``"crowned"`` (a circular crown with ``crown_drop``
        at the ends of L_we), ``"flat"`` (straight, with ``edge_radius`` over ``edge_length`` at each end if
        given), or a table of (position [m] from the roller's middle, drop [m]) pairs.
    crown_drop : float
        The drop of the ``"crowned"`` profile at the ends of L_we, >= 0. [m]
    edge_radius, edge_length : float
        The edge zones of the ``"flat"`` profile. [m]
    designation : str
        E.g. ``"NU 208 ECP"``.
    bore, outside_diameter, width : float
        d, D and the width (B of a cylindrical or spherical bearing, the overall width T of a tapered one). [m]
    inner_ring_width : float
        B of a tapered bearing's cone (the drag moment's B); the width otherwise. [m]
    dynamic_load_rating, static_load_rating, fatigue_load_limit : float
        The catalogue's C, C0 and Cu; they take precedence over ISO 281 / ISO 76 from the geometry. [N]
    ratio_limit : float
        The catalogue's e (the limit of F_a / F_r). [-]
    axial_factor : float
        The catalogue's Y of a single-row bearing (P = 0.4 F_r + Y F_a beyond e); of a spherical bearing its
        Y2 (P = 0.67 F_r + Y2 F_a beyond e). [-]
    axial_factor_below : float
        Y1 of a spherical (double-row) bearing: P = F_r + Y1 F_a up to e. [-]
    static_axial_factor : float
        The catalogue's Y0: P0 = 0.5 F_r + Y0 F_a (single row; F_r + Y0 F_a double row). [-]
    pressure_centre : float
        a of a tapered bearing: the distance of its pressure centre from the back face of the cone
        (catalogue). [m]
    series : str
        The SKF series for the friction constants (``"2"``, ``"22"``, ``"302"``, ``"222 E"``), read from the
        designation when not given.
    full_complement : bool
        A cylindrical roller bearing without cage (SKF's friction and drag constants differ).
    roller_material, ring_material : Material
        Steel by default.
    estimated_fields : tuple of str
        Fields whose values are estimates (:mod:`bearinglab.rollers.estimation`); a result built on them
        carries a warning.
    sources : dict
        Field -> where its value comes from (catalog entries).
    source : str
        A note on the bearing's origin.

    Examples
    --------
    >>> import math
    >>> b = RollerBearing("tapered", 17, 10e-3, 14e-3, 60e-3, math.radians(14.0))
    >>> print(f"cone {math.degrees(b.tapered_angles.cone_angle):.2f} deg")
    cone 10.03 deg
    """

    type: str = "cylindrical"
    rollers: int | None = None
    roller_diameter: float | None = None
    roller_length: float | None = None
    pitch_diameter: float | None = None
    contact_angle: float | None = None
    radial_clearance: float | None = None
    design: str | None = None
    rows: int | None = None
    profile: object = "logarithmic"
    crown_drop: float | None = None
    edge_radius: float | None = None
    edge_length: float | None = None
    designation: str = ""
    bore: float | None = None
    outside_diameter: float | None = None
    width: float | None = None
    inner_ring_width: float | None = None
    dynamic_load_rating: float | None = None
    static_load_rating: float | None = None
    fatigue_load_limit: float | None = None
    ratio_limit: float | None = None
    axial_factor: float | None = None
    axial_factor_below: float | None = None
    static_axial_factor: float | None = None
    pressure_centre: float | None = None
    series: str | None = None
    full_complement: bool = False
    roller_material: Material = STEEL
    ring_material: Material = STEEL
    estimated_fields: tuple = field(default=(), compare=False)
    sources: dict = field(default_factory=dict, compare=False)
    source: str = ""

    def __post_init__(self):
        if self.type not in ROLLER_TYPES:
            raise InputError(f"type must be one of {list(ROLLER_TYPES)}, got {self.type!r}")
        designs = DESIGNS[self.type]
        if self.design is None:
            object.__setattr__(self, "design", designs[0])
        elif self.design not in designs:
            raise InputError(f"design must be one of {list(designs)} for a {self.type} roller bearing, got {self.design!r}")
        if self.rows is None:
            object.__setattr__(self, "rows", 2 if self.type == "spherical" else 1)
        if isinstance(self.rows, bool) or self.rows not in (1, 2):
            raise InputError(f"rows must be 1 or 2 [-], got {self.rows!r}")
        if self.rollers is not None and (isinstance(self.rollers, bool) or not isinstance(self.rollers, (int, np.integer))
                                         or self.rollers < 3):
            raise InputError(f"rollers must be an integer >= 3 [-], got {self.rollers!r}")
        for name, unit in (("roller_diameter", "m"), ("roller_length", "m"), ("pitch_diameter", "m"), ("bore", "m"),
                           ("outside_diameter", "m"), ("width", "m"), ("inner_ring_width", "m"),
                           ("dynamic_load_rating", "N"), ("static_load_rating", "N"), ("fatigue_load_limit", "N"),
                           ("ratio_limit", "-"), ("axial_factor", "-"), ("axial_factor_below", "-"),
                           ("static_axial_factor", "-"), ("pressure_centre", "m")):
            _positive(name, getattr(self, name), unit)
        self._check_angle()
        self._check_fit()
        self._check_profile()
        if self.radial_clearance is not None:
            e = self.radial_clearance
            if not (isinstance(e, (int, float, np.floating)) and math.isfinite(e)):
                raise InputError(f"radial_clearance must be a finite number [um], got {e!r}")
            if self.roller_diameter is not None and abs(e) >= self.roller_diameter:
                raise InputError(f"radial_clearance must be in (-{self.roller_diameter * 1e3:g}, "
                                 f"{self.roller_diameter * 1e3:g}) [mm] (less than a roller diameter), got {e * 1e3:g} mm")
        if self.series is not None and not isinstance(self.series, str):
            raise InputError(f"series must be a string, got {self.series!r}")

    def _check_angle(self):
        a = self.contact_angle
        if a is None:
            if self.type == "cylindrical":
                object.__setattr__(self, "contact_angle", 0.0)
            return
        if not (isinstance(a, (int, float, np.floating)) and math.isfinite(a)):
            raise InputError(f"contact_angle must be a number [deg], got {a!r}")
        deg = math.degrees(a)
        if self.type == "cylindrical" and a != 0.0:
            raise InputError(f"contact_angle must be 0 [deg] for a cylindrical roller bearing, got {deg:g} deg")
        if self.type == "tapered" and not 0.0 < a <= math.radians(45.0) + 1e-12:
            raise InputError(f"contact_angle must be in (0, 45] [deg] for a tapered roller bearing (the cup angle), "
                             f"got {deg:g} deg")
        if self.type == "spherical" and not 0.0 <= a < math.radians(45.0):
            raise InputError(f"contact_angle must be in [0, 45) [deg] for a spherical roller bearing, got {deg:g} deg")

    def _check_fit(self):
        z, d, dpw, length = self.rollers, self.roller_diameter, self.pitch_diameter, self.roller_length
        if d is not None and dpw is not None and not dpw > d:
            raise InputError(f"pitch_diameter must be > roller_diameter [mm], got {dpw * 1e3:g} mm with roller_diameter "
                             f"= {d * 1e3:g} mm")
        if z is not None and d is not None and dpw is not None:
            z_max = math.floor(math.pi / math.asin(min(1.0, d / dpw)))
            if z > z_max:
                raise InputError(f"rollers must be <= {z_max} [-] for rollers of {d * 1e3:g} mm on a {dpw * 1e3:g} mm "
                                 f"pitch diameter (neighbouring rollers would overlap), got {z}")
        if dpw is not None and self.bore is not None and not dpw - (d or 0.0) > self.bore:
            raise InputError(f"pitch_diameter - roller_diameter must be > bore [mm] (the rollers run outside the bore), "
                             f"got {(dpw - (d or 0.0)) * 1e3:g} mm with bore = {self.bore * 1e3:g} mm")
        if dpw is not None and self.outside_diameter is not None and not dpw + (d or 0.0) < self.outside_diameter:
            raise InputError(f"pitch_diameter + roller_diameter must be < outside_diameter [mm], got "
                             f"{(dpw + (d or 0.0)) * 1e3:g} mm with outside_diameter = {self.outside_diameter * 1e3:g} mm")
        if self.bore is not None and self.outside_diameter is not None and not self.outside_diameter > self.bore:
            raise InputError(f"outside_diameter must be > bore [mm], got {self.outside_diameter * 1e3:g} mm with bore = "
                             f"{self.bore * 1e3:g} mm")
        if length is not None and self.width is not None:
            axial = length * math.cos(self.contact_angle or 0.0)  # a tapered roller lies at about alpha to the axis
            if not axial <= self.width * (1 + 1e-12):
                raise InputError(f"roller_length must be <= the ring width {self.width * 1e3:g} mm [mm] (a roller longer "
                                 f"than the ring is wide), got {length * 1e3:g} mm"
                                 + (f" ({axial * 1e3:g} mm along the axis)" if self.type == "tapered" else ""))

    def _check_profile(self):
        p = self.profile
        for name in _PROFILE_FIELDS:
            v = getattr(self, name)
            if v is not None and not (isinstance(v, (int, float, np.floating)) and math.isfinite(v) and v >= 0):
                raise InputError(f"{name} must be >= 0 [um], got {v * 1e6 if isinstance(v, (int, float)) else v!r}"
                                 + (" um" if isinstance(v, (int, float)) else ""))
        if isinstance(p, str):
            if p not in geometry.PROFILES:
                raise InputError(f"profile must be one of {list(geometry.PROFILES)} or a table of (position, drop) "
                                 f"pairs, got {p!r}")
            if p == "crowned" and self.crown_drop is None:
                raise InputError("crown_drop is needed with profile 'crowned' (the drop at the ends of L_we) [um]")
            if p == "flat" and (self.edge_length or 0.0) > 0 and self.edge_radius is None:
                raise InputError("edge_radius is needed with an edge_length > 0 [mm]")
            return
        table = np.asarray(p, dtype=float) if not isinstance(p, np.ndarray) else p
        if table.ndim != 2 or table.shape[1] != 2 or len(table) < 2:
            raise InputError(f"profile must be a name or a table of (position, drop) pairs, got shape {table.shape}")
        if np.any(table[:, 1] < 0):
            raise InputError(f"profile drop must be >= 0 [um], got {float(table[table[:, 1] < 0, 1][0]) * 1e6:g} um")
        object.__setattr__(self, "profile", tuple(tuple(float(v) for v in row) for row in table))

    # ------------------------------------------------------------------ helpers
    def replace(self, **changes):
        """A copy with some fields changed (checked again)."""
        return dataclasses.replace(self, **changes)

    def require(self, *names):
        """The named fields, raising InputError naming the first one that is not known."""
        out = []
        for name in names:
            value = getattr(self, name)
            if value is None:
                label = self.designation or f"this {self.type} roller bearing"
                raise InputError(f"{name} of {label!r} is not known; give it (catalog entry, file or option), or "
                                 "estimate the internal geometry from the boundary dimensions "
                                 "(bearinglab.rollers.estimation.with_estimated_geometry)")
            out.append(value)
        return out[0] if len(out) == 1 else tuple(out)

    @property
    def tapered_angles(self):
        """Cup, cone, roller and roller-axis angles of a tapered bearing (:func:`geometry.tapered_angles`)."""
        if self.type != "tapered":
            raise InputError(f"tapered_angles: {self.designation or 'this bearing'!r} is a {self.type} roller bearing")
        return geometry.tapered_angles(*self.require("contact_angle", "roller_diameter", "pitch_diameter"))

    @property
    def mean_diameter(self):
        """(bore + outside diameter) / 2, the d_m of SKF's friction model. [m]"""
        d, big = self.require("bore", "outside_diameter")
        return 0.5 * (d + big)

    @property
    def reduced_modulus(self):
        """E' of the roller-ring pair. [Pa]"""
        r, g = self.roller_material, self.ring_material
        return float(hertz.reduced_modulus(r.elastic_modulus, r.poisson_ratio, g.elastic_modulus, g.poisson_ratio))

    @property
    def has_internal_geometry(self):
        """Whether rollers, roller diameter and length and pitch diameter are all known."""
        return None not in (self.rollers, self.roller_diameter, self.roller_length, self.pitch_diameter)

    def profile_drop(self, position):
        """The roller profile drop at positions along the roller (:mod:`bearinglab.rollers.geometry`). [m]

        Parameters
        ----------
        position : array_like
            From the middle of the effective length, abs(x) < L_we / 2. [m]

        Returns
        -------
        ndarray
            The drop. [m]
        """
        length = self.require("roller_length")
        p = self.profile
        if p == "logarithmic":
            return geometry.logarithmic_drop(position, length, self.require("roller_diameter"),
                                             tapered=self.type == "tapered")
        if p == "crowned":
            return geometry.crowned_drop(position, length, self.crown_drop)
        if p == "flat":
            return geometry.flat_drop(position, length, edge_radius=self.edge_radius, edge_length=self.edge_length or 0.0)
        return geometry.table_drop(position, p)
