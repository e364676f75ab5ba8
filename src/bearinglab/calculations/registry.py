"""Every calculation's inputs, declared: the fields, how they combine into cases, the size bounds.

One :class:`Calculation` per capability of the command line (``life``, ``load-distribution``,
``bearing-set``, ``friction``, ``high-speed``, ``frequencies``, ``axial-angle``, ``stand-load``,
``catalog``, ``catalog-search``, ``clearance``, ``film``, ``temperature``, ``runout``,
``runout-monte-carlo``, ``shaft``). Every boundary is built from these declarations: the command line's
options (:mod:`bearinglab.cli._options`), the web's models and form, the documents (the module of
each calculation, :attr:`Calculation.module`).

Bounds (the command line's limits are :mod:`bearinglab._bounds`; the web's own are named here)
----------------------------------------------------------------------------------------------
CASE_LIMIT       the most cases one request may hold (a list or range, or their grid)
TIME_BUDGET      seconds one web request may run before it is stopped
BODY_LIMIT       the largest request body the web accepts [bytes]
DOCUMENT_LIMIT   the largest posted document (a runout error set) [characters]

Calculations
------------
Calculation      one calculation: name, command words, title, fields, combination of cases
CALCULATIONS     name -> Calculation
GROUPS           a field's group -> its heading (the command line's help panel)
"""

from __future__ import annotations

from dataclasses import dataclass

from .. import _bounds
from .fields import Field

__all__ = ["BODY_LIMIT", "CALCULATIONS", "CASE_LIMIT", "DOCUMENT_LIMIT", "GROUPS", "TIME_BUDGET",
           "Calculation"]

#: The most cases one request may hold: the command line's own limit (a full design map of 10^5 cases);
#: a larger study runs through ``bearinglab sweep``, which the web does not offer.
CASE_LIMIT = _bounds.MAX_CASES
#: Seconds one web request may compute before its worker is stopped (>= 30 s by the issue; a map of
#: 10^5 high-speed cases took 50 s with its 112 MB of JSON on the shared 2-core machine).
TIME_BUDGET = 120.0
#: The largest request body the web reads [bytes] (below the command line's input files,
#: :data:`bearinglab._bounds.MAX_INPUT_BYTES`: a request is typed or posted, not a data file).
BODY_LIMIT = 1 << 20
#: The largest posted document, e.g. a runout error set [characters]; it travels in the body.
DOCUMENT_LIMIT = 500_000

#: A small valid shaft system (two simple supports, one load): the ``example`` of the shaft's document field
_SHAFT_EXAMPLE = ('[material]\nmaterial = "steel"\n\n[[sections]]\nlength = "200 mm"\ndiameter = "30 mm"\n\n'
                  '[[supports]]\nname = "A"\nposition = "20 mm"\nrigid = true\naxial = true\n\n'
                  '[[supports]]\nname = "B"\nposition = "180 mm"\nrigid = true\n\n'
                  '[[loads]]\nposition = "100 mm"\nfy = "1 kN"\n')

# The web's own size limits: lower than the command line's (bearinglab._bounds), because one request
# shares a small server with others and answers within TIME_BUDGET; each is <= its _bounds limit
# (tests/calculations/test_fields.py checks it).
WEB_MAX_BALLS = 200  # <= _bounds.MAX_BALLS; the catalog's largest bearing has under 40 balls
WEB_MAX_HARMONICS = 100  # <= _bounds.MAX_HARMONICS; vibration analysis looks at the first 10 to 20
WEB_MAX_SIDEBANDS = 50  # <= _bounds.MAX_SIDEBANDS
# a runout sequence is bounded by its positions (revolutions x steps per revolution), which are its
# cases, and a runout Monte Carlo study by its samples: at most CASE_LIMIT on the web


@dataclass(frozen=True)
class Calculation:
    """One calculation as every boundary sees it.

    ``combine`` says how list fields make cases: ``grid`` (every combination), ``broadcast`` (lists
    of one length, or one value, taken element by element), ``single`` (no lists). ``heavy`` marks a
    calculation whose single case may take seconds (it runs in the heavy pool of the web).
    ``command`` are the words of its command (``("friction", "torque")``; ``()``: none), ``module`` the
    module whose ``document(parsed)`` computes it: one of :mod:`bearinglab.calculations` (default: the
    name with underscores, ``load_distribution``) or a full dotted name.
    """

    name: str
    command: tuple
    title: str
    summary: str
    fields: tuple
    combine: str = "single"
    heavy: bool = False
    module: str = ""

    @property
    def document_module(self):
        """The module of this package that computes the document: ``module`` or the name."""
        return self.module or self.name.replace("-", "_")

    def field(self, name):
        """The field called ``name`` (KeyError when there is none)."""
        return {f.name: f for f in self.fields}[name]


def _f(name, kind, help, **kw):
    return Field(name, kind, help, **kw)


#: A field's group -> its heading: the help panel of the command line (None: the command's own
#: options, listed first). A group not listed here is a panel of its own name.
GROUPS = {
    "": None, "loads": None, "model": None, "set": None, "mask": None, "runout": None,
    "inner-ring loads": "Loads on the inner ring",
    "displacements": "Prescribed displacements (instead of the load on that freedom)",
    "bearing": "Bearing", "geometry": "Inline geometry", "bearing data": "Bearing data (override the catalog)",
    "lubricant": "Lubricant", "temperature auto": "Temperature auto (thermal balance)",
    "friction": "Handbook constants", "film": "Lubricant film", "heat": "Heat balance",
    "mounting": "Mounting: fits and seats", "mounting temperatures": "Mounting: temperatures (default 20 degC)",
    "monte carlo": "Monte Carlo", "rotation": "Rotation",
    "rollers": "Roller bearings: roller set, profile, slices (override the catalog's)",
}
#: The bearing types a catalog search takes (the ``type`` words of the rows, deep-groove for ``radial``).
CATALOG_TYPES = ("deep-groove", "angular", "four-point", "double-row-angular", "double-row-radial", "self-aligning",
                 "thrust", "cylindrical", "tapered", "spherical")


_GEO = "geometry"
BEARING = _f("bearing", "text", "Catalog name, e.g. B218, 4-1006095, 6205-2RS.", label="Bearing",
             group="bearing", aliases=("-b",))
GEOMETRY = (
    _f("balls", "int", "Number of balls.", label="Balls", minimum=3, maximum=WEB_MAX_BALLS,
       group=_GEO),
    _f("ball_diameter", "length", "Ball diameter D, e.g. '2 mm'.", label="Ball diameter", unit="mm",
       minimum=0, exclusive=True, maximum=1000, group=_GEO),
    _f("pitch_diameter", "length", "Pitch diameter d_m, e.g. '8.7355 mm'.", label="Pitch diameter",
       unit="mm", minimum=0, exclusive=True, maximum=10000, group=_GEO),
    _f("inner_groove_radius", "length", "Inner groove radius r_i, e.g. '1.05 mm'.",
       label="Inner groove radius", unit="mm", minimum=0, exclusive=True, group=_GEO),
    _f("outer_groove_radius", "length", "Outer groove radius r_o, e.g. '1.16 mm'.",
       label="Outer groove radius", unit="mm", minimum=0, exclusive=True, group=_GEO),
    _f("inner_conformity", "number", "f_i = r_i / D.", label="Inner conformity r/D", unit="-",
       minimum=0.5, exclusive=True, maximum=1.0, group=_GEO),
    _f("outer_conformity", "number", "f_o = r_o / D.", label="Outer conformity r/D", unit="-",
       minimum=0.5, exclusive=True, maximum=1.0, group=_GEO),
    _f("contact_angle", "angle", "Nominal (free) angle, e.g. '12 deg' (a tapered roller bearing: its cup "
       "angle, at most 45 deg).", label="Free contact angle", unit="deg", minimum=0, maximum=90, group=_GEO),
    _f("radial_clearance", "length", "Diametral clearance, e.g. '9 um'; zero or negative is a preload.",
       label="Radial clearance", unit="um", group=_GEO),
    _f("ball_material", "choice", "Ball material.", label="Ball material",
       choices=("steel", "silicon_nitride"), group=_GEO),
)
_L, _RL = "loads", "inner-ring loads"
LOADS = (
    _f("fx", "force", "Radial force along x, e.g. '1 kN'.", label="F_x", unit="N", group=_RL),
    _f("fy", "force", "Radial force along y, e.g. '200 N'.", label="F_y", unit="N", group=_RL),
    _f("fz", "force", "Axial force (along the bearing axis), e.g. '500 N'.", label="F_z", unit="N",
       group=_RL),
    _f("mx", "torque", "Tilting moment about x, e.g. '1000 N*mm'.", label="M_x", unit="N*mm", group=_RL),
    _f("my", "torque", "Tilting moment about y, e.g. '2 N*m'.", label="M_y", unit="N*mm", group=_RL),
    _f("radial_load", "force", "Radial load F_r (same as `fx`).", label="Radial load F_r", unit="N",
       group=_RL, aliases=("-R",)),
    _f("axial_load", "force", "Axial load F_a (same as `fz`).", label="Axial load F_a", unit="N",
       group=_RL, aliases=("-A",)),
)
_SOLVE = (
    _f("speed", "speed", "Inner-ring speed, e.g. '6000 rpm'.", label="Shaft speed", unit="rpm",
       default="0 rpm", group=_L, aliases=("-n",)),
    _f("first_ball_angle", "angle", "Azimuth of ball 0 from +x, e.g. '0 deg'.", label="First ball azimuth",
       unit="deg", default="0 deg", group="model"),
    _f("stiffness_at", "choice", "operating (Hertz constants at each contact's angle) | free (at the free "
       "angle, ISO/TS 16281).", label="Stiffness at", default="operating",
       choices=("operating", "free"), group="model"),
)
_O = "lubricant"
OIL = (
    _f("viscosity", "kinematic_viscosity", "Operating kinematic viscosity, e.g. '20 cSt'.",
       label="Viscosity", unit="cSt", minimum=0, exclusive=True, group=_O),
    _f("oil", "text", "ISO VG grade, e.g. VG68 (with `temperature`).", label="Oil grade", group=_O),
    _f("temperature", "text", "Operating temperature of the oil, e.g. '70 degC'.",
       label="Oil temperature", unit="degC", group=_O),
    _f("viscosity_index", "number", "The oil's viscosity index (default 95, a mineral oil).",
       label="Viscosity index", unit="-", minimum=-100, maximum=400, group=_O),
    _f("viscosity_100", "kinematic_viscosity", "The oil's viscosity at 100 degC, e.g. '8.7 cSt' "
       "(instead of `viscosity_index`).",
       label="Viscosity at 100 degC", unit="cSt", minimum=0, exclusive=True, group=_O),
)
_M, _T = "mounting", "mounting temperatures"
_MATERIALS = ("steel", "structural_steel", "aluminium")
#: the mounting options of every command that takes a bearing (issue 23); the fits,
#: classes and interference pairs are checked by the command (its tables), so they are text here
MOUNTING = (
    _f("shaft_fit", "text", "ISO 286 field of the shaft seat: g6 h5 h6 j5 j6 js5 js6 k5 k6 m5 m6 n6 p6.",
       label="Shaft fit", group=_M),
    _f("housing_fit", "text", "ISO 286 field of the housing bore: F7 G6 G7 H6 H7 H8 J6 J7 JS6 JS7 K6 "
       "K7 M6 M7 N6 N7 P6 P7.", label="Housing fit", group=_M),
    _f("shaft_interference", "text", "Inner-ring interference instead of `shaft_fit`: one value or "
       "'least, largest', e.g. '5 um, 20 um' (negative: loose).", label="Shaft interference",
       unit="um", group=_M),
    _f("housing_interference", "text", "Outer-ring interference instead of `housing_fit`, as "
       "`shaft_interference`.", label="Housing interference", unit="um", group=_M),
    _f("shaft_bore", "length", "Bore of a hollow shaft, e.g. '20 mm' (default solid).",
       label="Shaft bore", unit="mm", minimum=0, group=_M),
    _f("housing_outside_diameter", "length", "Outside diameter of the housing, e.g. '120 mm' "
       "(default: a thick housing).", label="Housing outside diameter", unit="mm", minimum=0,
       exclusive=True, group=_M),
    _f("shaft_material", "choice", "Shaft material: steel | structural_steel | aluminium (default steel).", label="Shaft material",
       choices=_MATERIALS, group=_M),
    _f("housing_material", "choice", "Housing material: steel | structural_steel | aluminium (default "
       "steel).", label="Housing material",
       choices=_MATERIALS, group=_M),
    _f("tolerance_class", "text", "ISO 492 class of the bearing: Normal, P6, P5, P4 (default: the "
       "designation's, else Normal).", label="Tolerance class", group=_M),
    _f("clearance_class", "text", "ISO 5753-1 class: C2, CN, C3, C4, C5 (default: the designation's, "
       "else CN).", label="Clearance class", group=_M),
    _f("inner_ring_temperature", "text", "e.g. '60 degC' (default 20 degC).",
       label="Inner-ring temperature", unit="degC", group=_T),
    _f("outer_ring_temperature", "text", "e.g. '50 degC' (default 20 degC).",
       label="Outer-ring temperature", unit="degC", group=_T),
    _f("ball_temperature", "text", "Default: the mean of the rings.", label="Ball temperature",
       unit="degC", group=_T),
    _f("shaft_temperature", "text", "Default: the inner ring's.", label="Shaft temperature",
       unit="degC", group=_T),
    _f("housing_temperature", "text", "Default: the outer ring's.", label="Housing temperature",
       unit="degC", group=_T),
)
#: bearing-set takes its clearance from the preload, not from a clearance class
_SET_MOUNTING = tuple(f for f in MOUNTING if f.name != "clearance_class")
_ROUGHNESS = (
    _f("shaft_roughness", "text", "Rz of shaft seat and ring bore for the smoothing of DIN 7190-1 "
       "(off by default), e.g. '4 um' or '4 um, 1.6 um'.", label="Shaft seat roughness Rz",
       unit="um", group=_M),
    _f("housing_roughness", "text", "Rz of housing bore and ring outside, as `shaft_roughness`.",
       label="Housing seat roughness Rz", unit="um", group=_M),
)
_D = "displacements"
_DISPLACEMENTS = (
    _f("dx", "length", "Hold delta_x at this value, e.g. '10 um' (instead of `fx`).", label="delta_x",
       unit="um", group=_D),
    _f("dy", "length", "Hold delta_y, e.g. '0 um' (instead of `fy`).", label="delta_y", unit="um",
       group=_D),
    _f("dz", "length", "Hold delta_z, from the concentric position (half the axial play included), "
       "e.g. '700 um' (instead of `fz`).", label="delta_z", unit="um", group=_D),
    _f("tilt_x", "angle", "Hold theta_x, e.g. '0 mrad' (instead of `mx`).", label="theta_x",
       unit="mrad", group=_D),
    _f("tilt_y", "angle", "Hold theta_y, e.g. '0 mrad' (instead of `my`); `tilt_x`/`tilt_y` '0 mrad' "
       "hold the ring square.", label="theta_y", unit="mrad", group=_D),
)
_R = "rollers"
#: the roller set and profile of a roller bearing (issue 32): they override the catalog's or the bearing file's
#: (pitch diameter, contact angle and clearance are the `GEOMETRY` fields, shared with ball bearings)
ROLLER_SET = (
    _f("rollers", "int", "Rollers per row Z of a roller bearing.", label="Rollers", minimum=3,
       maximum=WEB_MAX_BALLS, group=_R),
    _f("roller_diameter", "length", "Roller diameter D_we (of a tapered roller: at its middle), e.g. '11 mm'.",
       label="Roller diameter", unit="mm", minimum=0, exclusive=True, maximum=1000, group=_R),
    _f("roller_length", "length", "Effective roller length L_we, e.g. '9.6 mm' (at most the ring width).",
       label="Roller length", unit="mm", minimum=0, exclusive=True, maximum=1000, group=_R),
)
ROLLER_PROFILE = (
    _f("profile", "choice", "Roller profile: logarithmic (ISO/TS 16281's, the default) | crowned (with "
       "`crown_drop`) | flat.", label="Roller profile", choices=("logarithmic", "crowned", "flat"), group=_R),
    _f("crown_drop", "length", "Drop of the crowned profile at the roller ends, e.g. '5 um'.",
       label="Crown drop", unit="um", minimum=0, maximum=1000, group=_R),
)
SLICES = _f("slices", "int", "Slices per roller of the ISO/TS 16281 model (default 30).", label="Slices",
            minimum=1, maximum=200, group=_R)
#: every roller input of a calculation with the slice model
ROLLERS = (*ROLLER_SET, *ROLLER_PROFILE, SLICES)
_MISALIGNMENT = (
    _f("tilt_x", "angle", "Roller bearings: hold the inner ring tilted by theta_x against the outer ring "
       "(misalignment) in the ISO/TS 16281 life, e.g. '1 mrad' (instead of `mx`).", label="theta_x",
       unit="mrad", group=_R),
    _f("tilt_y", "angle", "As `tilt_x`, about y.", label="theta_y", unit="mrad", group=_R),
)
_CONTAMINATION = ("extreme", "high", "normal", "slight", "typical", "severe", "very-severe")
_HERTZ = _f("hertz", "choice", "Hertz coefficients: exact | table (the bearing's tabulated 2K/(pi mu)).",
            label="Hertz coefficients", default="exact", choices=("exact", "table"), group="model")
_ELASTIC = _f("elastic_constant", "choice", "materials (from E, nu) | paper (0.592e-4 (cm^2/kgf)^(2/3)).",
              label="Elastic constant", default="materials", choices=("materials", "paper"),
              group="model")

_CALCS = (
    Calculation(
        "life", ("life",), "Rating life",
        "ISO 281 basic and modified rating lives, ISO/TS 16281 reference life.",
        (*LOADS, _f("speed", "speed", "Inner-ring speed, e.g. '3000 rpm' (a list '1000, 3000 rpm' for "
                    "several cases).", label="Shaft speed", unit="rpm", minimum=0, many=True, group=_L,
                    aliases=("-n",)),
         *OIL,
         _f("contamination_factor", "number", "e_C of ISO 281 table 13, in [0, 1] (default 1).",
            label="Contamination factor e_C", unit="-", minimum=0, maximum=1, group=_O),
         _f("contamination", "choice", "Cleanliness of ISO 281 table 13.", label="Contamination",
            choices=_CONTAMINATION, group=_O),
         _f("reliability", "number", "Reliability in percent, 90 to 99.95.", label="Reliability",
            unit="%", default=90.0, minimum=90, maximum=99.95),
         # a document: the page and the API take its text; the command line a file holding it
         _f("duty_cycle", "document", "[[step]] loads, speed and time share: the combined life, instead "
            "of the loads and speed (the tables hold fx, fy, fz, mx, my, speed and time; the shares sum "
            "to 1).", label="Duty cycle", group=_L,
            example='[[step]]\nfx = "1 kN"\nspeed = "1000 rpm"\ntime = 0.7\n\n[[step]]\nfx = "2 kN"\n'
                    'speed = "3000 rpm"\ntime = 0.3\n'),
         _f("ambient", "text", "With `temperature` auto: the ambient (default 20 degC).",
            label="Ambient temperature", unit="degC", group="temperature auto"),
         _f("thermal_resistance", "thermal_resistance", "With `temperature` auto: bearing to ambient, "
            "e.g. '0.5 K/W' (default: ISO 15312's reference heat flow).", label="Thermal resistance",
            unit="K/W", minimum=0, exclusive=True, group="temperature auto"),
         _f("lubrication", "choice", "With `temperature` auto: the SKF model's lubrication method "
            "(default grease; oil-jet when an oil grade is given, as temperature auto needs).",
            label="Lubrication method", choices=("oil-jet", "oil-air", "grease"),
            group="temperature auto"),
         _f("skf_constants", "text", "With `temperature` auto: SKF constants R1,R2,R3,S1,S2,S3 "
            "(angular contact).", label="SKF constants", group="temperature auto"),
         BEARING, *GEOMETRY, *ROLLERS, *_MISALIGNMENT, *MOUNTING),
        combine="broadcast"),
    Calculation(
        "load-distribution", ("load-distribution",), "Load distribution and stiffness",
        "5-DOF load distribution of one bearing under F_x, F_y, F_z, M_x, M_y; stiffness matrix.",
        (*LOADS, *_DISPLACEMENTS, *_SOLVE, BEARING, *GEOMETRY, *ROLLERS, *MOUNTING)),
    Calculation(
        "bearing-set", ("bearing-set",), "Bearing set",
        "Preloaded DB/DF/DT sets on one shaft under F_x, F_y, F_z, M_x, M_y.",
        (_f("bearing", "text", "Catalog name; once for every position, or one per bearing from -z to "
            "+z (the page: a comma-separated list).", label="Bearings", required=True, many=True,
            group="bearing", aliases=("-b",)),
         _f("arrangement", "choice", "DB (back-to-back) | DF (face-to-face) | DT (tandem).",
            label="Arrangement", default="DB", choices=("DB", "DF", "DT"), group="set"),
         _f("spacing", "length", "Distance between bearing centres, e.g. '100 mm'; default: side by "
            "side, one ring width B (needs the bearings' width); a tapered pair: the distance between its pressure "
            "centres (the effective spread), needed.", label="Spacing", unit="mm", minimum=0, group="set"),
         _f("preload", "force", "Axial preload force at rest, e.g. '500 N'.", label="Preload",
            unit="N", minimum=0, group="set"),
         _f("preload_offset", "length", "Axial interference from first contact (zero preload) instead, "
            "e.g. '5 um'; negative is axial play.",
            label="Preload offset", unit="um", group="set"),
         _f("induced_axial_factor", "choice", "Tapered pairs, ISO 281's method: the induced axial load f F_r / Y "
            "with SKF's f = 0.5 (General Catalogue 6000, p. 208; the default) | NSK's f = 0.6 (CAT. No. E1102e "
            "eq. (5.27)).", label="Induced axial load factor", default="SKF", choices=("SKF", "NSK"), group="set"),
         *LOADS, *_SOLVE, *_SET_MOUNTING, SLICES)),
    Calculation(
        "friction", ("friction", "torque"), "Friction torque",
        "Friction torque: one-term, two-term (handbook), Palmgren, SKF.",
        (_f("radial_load", "force", "F_r, e.g. '10 N', '1 kgf', or a list/range '0N:50N:10N'.",
            label="Radial load F_r", unit="N", default="0 N", minimum=0, many=True, group=_L,
            aliases=("-R",)),
         _f("axial_load", "force", "F_a, e.g. '5 N' (list/range allowed).", label="Axial load F_a",
            unit="N", default="0 N", minimum=0, many=True, group=_L, aliases=("-A",)),
         _f("speed", "speed", "Inner-ring speed, e.g. '3000 rpm' (list/range allowed).",
            label="Shaft speed", unit="rpm", default="0 rpm", many=True, group=_L, aliases=("-n",)),
         _f("model", "choice", "one-term | two-term (needs `f0`) | palmgren (needs `viscosity`, "
            "`palmgren_f0`) | skf (needs `viscosity`; `lubrication`).", label="Friction model",
            default="one-term", choices=("one-term", "two-term", "palmgren", "skf"), group="model",
            aliases=("-m",)),
         BEARING,
         _f("type", "choice", "Bearing type: radial | angular.", label="Bearing type",
            choices=("radial", "angular"), group="bearing data"),
         _f("contact_angle", "angle", "Nominal (free) angle, e.g. '12 deg'.",
            label="Free contact angle", unit="deg", minimum=0, maximum=90, group=_GEO),
         _f("bore", "length", "Bore d, e.g. '12 mm'.", label="Bore d", unit="mm", minimum=0,
            exclusive=True, group="bearing data"),
         _f("outside_diameter", "length", "Outside diameter D, e.g. '28 mm'.",
            label="Outside diameter", unit="mm", minimum=0, exclusive=True, group="bearing data"),
         _f("mean_diameter", "length", "d_m = (d + D)/2, e.g. '20 mm'.", label="Mean diameter",
            unit="mm", minimum=0, exclusive=True, group="bearing data"),
         _f("static_load_rating", "force", "C0, e.g. '2227 N'.", label="Static load rating C0",
            unit="N", minimum=0, exclusive=True, group="bearing data"),
         _f("mu", "number", "Override of the handbook μ (0.0015 radial, 0.0020 angular).", label="mu",
            unit="-", minimum=0, group="friction"),
         _f("x0", "number", "Override of x0 (Table 1).", label="x0", unit="-", group="friction"),
         _f("y0", "number", "Override of y0 (Table 1).", label="y0", unit="-", group="friction"),
         _f("f", "number", "Override of f (Table 2).", label="f", unit="-", group="friction"),
         _f("c", "number", "Override of c (Table 2).", label="c", unit="-", group="friction"),
         _f("f0", "number", "Speed-term factor of T0 = f0·d_m³·n^(2/3) in N·mm⁻²·min^(2/3) (e.g. 2e-7; "
            "from `friction lab`, task 2).", label="f0 (two-term)", unit="-", minimum=0,
            group="friction"),
         _f("viscosity", "kinematic_viscosity", "Lubricant kinematic viscosity for `model` palmgren, "
            "e.g. '20 cSt'.", label="Viscosity", unit="cSt", minimum=0, exclusive=True,
            group="friction"),
         _f("palmgren_f0", "number", "Palmgren's f0 (about 0.7-2 for deep-groove bearings) for `model` "
            "palmgren.", label="Palmgren f0", unit="-", minimum=0, group="friction"),
         _f("lubrication", "choice", "For `model` skf: grease | oil-air | oil-jet | oil-bath (with "
            "`oil_level`). Default grease; oil-jet when an oil grade (`oil`) is given.",
            label="Lubrication method", choices=("grease", "oil-air", "oil-jet", "oil-bath"), group="friction"),
         *(f for f in OIL if f.name != "viscosity"),
         _f("oil_level", "length", "For `model` skf, `lubrication` oil-bath: H from the lowest point of "
            "the outer raceway, e.g. '5 mm' (at most to the bearing's centre).", label="Oil level H",
            unit="mm", minimum=0, group="friction"),
         _f("drag_loss_factor", "number", "For `lubrication` oil-bath: V_M in place of SKF's drag "
            "loss diagram at H/d_m (default: the diagram, digitised).", label="Drag loss factor V_M", unit="-", minimum=0, group="friction"),
         _f("series", "text", "For `model` skf: the deep-groove series of SKF's constants, e.g. 62 "
            "(default: the bearing's series, else read from its designation).",
            label="SKF series", group="friction"),
         *MOUNTING),  # issue 23: reported as operating_clearance_um; no friction model depends on it
        combine="broadcast", module="friction_torque"),
    Calculation(
        "high-speed", ("high-speed",), "Contact angles at speed",
        "High-speed quasi-static model under thrust (Jones/Harris).",
        (_f("axial_load", "force", "Thrust: '20 kN', or a list/range '2.5kN:45kN:2.5kN'.",
            label="Axial load F_a", unit="N", required=True, minimum=0, exclusive=True, many=True,
            group=_L, aliases=("-A", "-F")),
         _f("speed", "speed", "Inner-ring speed: '10000 rpm', or a list/range '0,3000,6000rpm'.",
            label="Shaft speed", unit="rpm", required=True, minimum=0, many=True, group=_L,
            aliases=("-n",)),
         BEARING, *GEOMETRY,
         _f("solver", "choice", "newton (batched Newton-Raphson) | angle-iteration (the paper's "
            "search).", label="Solver", default="newton", choices=("newton", "angle-iteration"),
            group="model"),
         _f("raceway_control", "choice", "outer (the paper's) | inner.", label="Raceway control",
            default="outer", choices=("outer", "inner"), group="model"),
         _f("constants", "choice", "mass (F_c, M_g from the ball mass) | harris (2.26e-11, 4.47e-12: "
            "Harris's printed constants) | paper (2.26e-11, 4.5e-12).",
            label="High-speed constants", default="mass", choices=("mass", "harris", "paper"),
            group="model"),
         _f("gyroscopic_sign", "choice", "physical | reversed (for comparison only).",
            label="Gyroscopic sign", default="physical", choices=("physical", "reversed"),
            group="model"),
         _f("reduced_modulus", "pressure", "E' of the contact pair, e.g. '228.04 GPa' (default: from the "
            "materials).",
            label="Reduced modulus E'", unit="GPa", minimum=0, exclusive=True, group="model"),
         *MOUNTING),
        combine="grid"),
    Calculation(
        "frequencies", ("frequencies",), "Defect frequencies",
        "Characteristic frequencies (FTF, BPFO, BPFI, BSF) and the spectral mask.",
        (_f("speed", "speed", "Inner-ring (shaft) speed: '3000 rpm', '50 Hz'.", label="Shaft speed",
            unit="rpm", required=True, group=_L, aliases=("-n",)),
         _f("outer_speed", "speed", "Outer-ring speed, same sense as `speed`.", label="Outer-ring speed",
            unit="rpm", default="0 rpm", group=_L),
         _f("axial_load", "force", "Axial stand load, e.g. '2 kgf': the frequencies at the operating "
            "contact angle (the test-stand method).", label="Axial load F_a", unit="N", minimum=0,
            exclusive=True, group=_L, aliases=("-F",)),
         _HERTZ, _ELASTIC, BEARING, *GEOMETRY, *ROLLER_SET,
         _f("harmonics", "int", "Harmonics 1..N in the spectral mask.", label="Harmonics",
            default=3, minimum=1, maximum=WEB_MAX_HARMONICS, group="mask"),
         _f("sidebands", "int", "Sideband orders ±1..S around BPFI and BSF.", label="Sidebands",
            default=1, minimum=0, maximum=WEB_MAX_SIDEBANDS, group="mask"),
         _f("band", "text", "Full width of each mask line, in % of its frequency: '2 %'.",
            label="Band", default="2 %", group="mask"),
         _f("mask", "flag", "Add the spectral-mask table (to the tables printed and to the JSON).",
            label="Spectral mask", default=False,
            group="mask"))),
    Calculation(
        "axial-angle", ("axial-angle",), "Contact angle at rest",
        "Operating contact angle under axial load (test-stand method).",
        (_f("axial_load", "force", "Axial load: '2 kgf', '19.6 N', or a list/range '1kgf:5kgf:1kgf'.",
            label="Axial load F_a", unit="N", required=True, minimum=0, exclusive=True, many=True,
            group=_L, aliases=("-F",)),
         BEARING, *GEOMETRY, _HERTZ, _ELASTIC,
         _f("legacy", "flag", "Reproduce the paper's printed rounding (π = 3.14, F cut to 3 decimals).",
            label="Legacy rounding",
            default=False, group="model"),
         _f("x0", "number", "Start of the iteration table [rad] (the paper printed 0.0433985).",
            label="x0 [rad]", unit="-",
            group="model"),
         _f("rows", "int", "Rows of the iteration table (default: to convergence).",
            label="Iteration rows", minimum=1, maximum=_bounds.MAX_ROWS, group="model")),
        combine="grid", module="stand"),
    Calculation(
        "stand-load", ("stand-load",), "Test-stand load",
        "Minimum axial load on a test stand.",
        (_f("speed", "speed", "Inner-ring speed: '3000 rpm', or a list '1000,3000,10000rpm'.",
            label="Shaft speed", unit="rpm", required=True, many=True, group=_L, aliases=("-n",)),
         BEARING, *GEOMETRY),
        combine="grid", module="stand"),
    Calculation(
        "catalog", ("catalog", "show"), "Catalog bearing",
        "One bearing with its derived geometry and its ratings C, C0, Cu.",
        (_f("name", "text", "Bearing name, alias or designation (6208-2RS1/C3).", label="Bearing",
            required=True, option="NAME", group="bearing"),
         _f("clearance", "choice", "Value of the ISO 5753-1 clearance range the models use: mean "
            "(default), min or max.", label="Clearance value", choices=("mean", "min", "max")),
         _f("radial_clearance", "length", "Diametral clearance, e.g. '9 um'; zero or negative is a preload.",
            label="Radial clearance", unit="um", group=_GEO)),),
    Calculation(
        "catalog-search", ("catalog", "search"), "Catalog search",
        "Catalog bearings by designation, bore, outside diameter, width, type and series; "
        "``bearings`` is ``bearinglab catalog search --json``, ``matches`` the page's picker (its "
        "sizes within 0.5 mm; ``query`` and ``limit`` are the picker's alone).",
        (_f("query", "text", "Part of a designation or alias, e.g. 62.", label="Designation",
            default="", cli=False),
         _f("bore", "length", "Bore d, e.g. '25 mm' (matches within 0.5 mm).", label="Bore d",
            unit="mm", minimum=0, exclusive=True),
         _f("outside_diameter", "length", "Outside diameter D (matches within 0.5 mm).",
            label="Outside diameter", unit="mm", minimum=0, exclusive=True),
         _f("width", "length", "Width B (matches within 0.5 mm).", label="Width B", unit="mm",
            minimum=0, exclusive=True),
         _f("type", "choice", "deep-groove, angular, four-point, double-row-angular, double-row-radial, "
            "self-aligning, thrust, cylindrical, tapered or spherical.", label="Type", choices=CATALOG_TYPES),
         _f("series", "text", "Series, e.g. 62, 618, 72, 72B, 79C; 22, 302, 222.", label="Series"),
         _f("limit", "int", "The most matches returned.", label="Matches", default=50, minimum=1,
            maximum=500, cli=False)),),
    Calculation(
        "clearance", ("clearance",), "Mounted clearance",
        "Operating clearance after fits, temperatures and speed (least, probable, largest); "
        "optionally a Monte Carlo study of the tolerances.",
        (BEARING, *MOUNTING, *_ROUGHNESS,
         _f("radial_clearance", "text", "Unmounted diametral clearance instead of the class: one "
            "value or 'min, max', e.g. '6 um, 20 um'.", label="Unmounted clearance", unit="um"),
         _f("speed", "speed", "Inner-ring (shaft) speed, e.g. '6000 rpm'.", label="Shaft speed",
            unit="rpm", group=_L, aliases=("-n",)),
         _f("monte_carlo", "int", "Samples of random tolerances through the chain.",
            label="Monte Carlo samples", minimum=2, maximum=_bounds.MAX_SAMPLES, group="monte carlo"),
         _f("seed", "int", "Root seed (results do not depend on chunking).", label="Seed", default=0,
            minimum=0, group="monte carlo"),
         _f("distribution", "choice", "uniform | normal (limits at +-3 sigma).",
            label="Distribution", default="uniform", choices=("uniform", "normal"),
            group="monte carlo"))),
    Calculation(
        "film", ("film",), "Lubricant film",
        "EHL film thickness and lambda ratio at each contact (Hamrock-Dowson), the regime.",
        (*LOADS,
         _f("speed", "speed", "Inner-ring speed, e.g. '6000 rpm' (a list '3000, 6000 rpm' for several "
            "cases).", label="Shaft speed", unit="rpm", many=True, group=_L, aliases=("-n",)),
         *OIL,
         _f("dynamic_viscosity", "dynamic_viscosity", "Dynamic viscosity at the bearing temperature, "
            "e.g. '0.04 Pa*s' or '40 cP' (instead of `viscosity`).", label="Dynamic viscosity",
            unit="Pa*s", minimum=1e-4, maximum=1e4, group="film"),
         _f("density", "density", "Oil density, e.g. '870 kg/m^3' (default 870 kg/m^3, a typical "
            "mineral oil: an estimate).", label="Oil density", unit="kg/m^3", minimum=500, maximum=2500,
            group="film"),
         _f("pressure_viscosity_coefficient", "inverse_pressure", "alpha, e.g. '2.3e-8 m^2/N' or "
            "'23 1/GPa' (default: Wooster's estimate for mineral oils).",
            label="Pressure-viscosity coefficient", unit="m^2/N", minimum=1e-9, maximum=1e-7,
            group="film"),
         _f("roughness", "length", "RMS roughness R_q of balls and raceways alike, e.g. '0.1 um' "
            "(default 0.1 um each).", label="Roughness R_q", unit="um", minimum=0, maximum=10, group="film"),
         _f("roughness_ball", "length", "R_q of the balls, e.g. '0.05 um'.",
            label="Ball roughness R_q", unit="um", minimum=0, maximum=10, group="film"),
         _f("roughness_race", "length", "R_q of the raceways, e.g. '0.15 um'.",
            label="Raceway roughness R_q", unit="um", minimum=0, maximum=10, group="film"),
         _f("loads_at", "choice", "speed (quasi-static ball loads at the speed) | rest (loads at "
            "rest, pure rolling).", label="Ball loads at", default="speed",
            choices=("speed", "rest"), group="film"),
         _f("ambient", "text", "With `temperature` auto: the ambient (default 20 degC).",
            label="Ambient temperature", unit="degC", group="temperature auto"),
         _f("thermal_resistance", "thermal_resistance", "With `temperature` auto: bearing to ambient, "
            "e.g. '0.5 K/W' (default: ISO 15312's reference heat flow).",
            label="Thermal resistance", unit="K/W", minimum=1e-4, maximum=1e4, group="temperature auto"),
         _f("lubrication", "choice", "grease | oil-air | oil-jet | oil-bath: a starvation-risk check "
            "(SKF's replenishment factor); with `temperature` auto also the SKF model's (default grease; "
            "oil-jet when an oil grade is given).", label="Lubrication method",
            choices=("grease", "oil-air", "oil-jet", "oil-bath"), group="film"),
         _f("skf_constants", "text", "With `temperature` auto: SKF constants R1,R2,R3,S1,S2,S3 "
            "(angular contact).", label="SKF constants", group="temperature auto"),
         BEARING, *GEOMETRY, *ROLLERS, *MOUNTING),  # the film at the ball loads of the mounted bearing
        combine="broadcast"),
    Calculation(
        "temperature", ("temperature",), "Operating temperature",
        "Thermal balance: the bearing temperature where the friction power equals the heat "
        "dissipated; thermal runaway below the limit.",
        (_f("radial_load", "force", "Radial load F_r, e.g. '1 kN'.", label="Radial load F_r", unit="N",
            group=_RL, aliases=("-R",)),
         _f("axial_load", "force", "Axial load F_a, e.g. '500 N'.", label="Axial load F_a", unit="N",
            group=_RL, aliases=("-A",)),
         _f("speed", "speed", "Inner-ring speed, e.g. '6000 rpm' (a list for several cases).",
            label="Shaft speed", unit="rpm", many=True, group=_L, aliases=("-n",)),
         *(f for f in OIL if f.name in ("oil", "viscosity_index", "viscosity_100")),
         _f("lubrication", "choice", "SKF model: oil-jet | oil-air | grease | oil-bath (with "
            "`oil_level`; its drag loss from SKF's V_M diagram). Default grease, oil-jet when an oil "
            "grade is given (this command's oil is a grade: oil-jet).", label="Lubrication method",
            choices=("oil-jet", "oil-air", "grease", "oil-bath"), group="heat"),
         _f("oil_level", "length", "For `lubrication` oil-bath: H from the lowest point of the outer "
            "raceway, e.g. '5 mm' (at most to the bearing's centre).", label="Oil level H", unit="mm",
            minimum=0, group="heat"),
         _f("skf_constants", "text", "SKF geometry constants R1,R2,R3,S1,S2,S3 in place of SKF's tables "
            "(angular contact other than 40 deg needs them), e.g. '5e-7,1.9,1.9e-12,0.013,0.7,1.9e-12'.",
            label="SKF constants", group="heat"),
         _f("ambient", "text", "Ambient temperature, e.g. '20 degC'.", label="Ambient temperature",
            unit="degC", default="20 degC", group="heat"),
         _f("thermal_resistance", "thermal_resistance", "Bearing to ambient, e.g. '0.5 K/W' "
            "(default: ISO 15312's reference heat flow of the bearing).",
            label="Thermal resistance", unit="K/W", minimum=1e-4, maximum=1e4, group="heat"),
         _f("oil_flow", "volume_flow", "Oil jet or circulation flow through the bearing, e.g. "
            "'0.5 l/min'.", label="Oil flow", unit="l/min", minimum=0, maximum=600, group="heat"),
         _f("oil_inlet_temperature", "text", "Of the oil flow (default: the ambient), e.g. '40 degC'.",
            label="Oil inlet temperature", unit="degC", group="heat"),
         _f("oil_heat_capacity", "specific_heat", "c_p of the oil (default 1950 J/(kg*K), a mineral "
            "oil: an estimate).", label="Oil heat capacity", unit="J/(kg*K)", minimum=500,
            maximum=5000, group="heat"),
         _f("density", "density", "Oil density (default 870 kg/m^3, a mineral oil: an estimate).",
            label="Oil density", unit="kg/m^3", minimum=500, maximum=2500, group="heat"),
         _f("max_temperature", "text", "Safe limit: no steady state below it is thermal runaway, "
            "e.g. '150 degC'.", label="Temperature limit", unit="degC", default="150 degC",
            group="heat"),
         _f("reference_speed", "flag", "Also ISO 15312's thermal reference speed of the bearing by the "
            "SKF model (JSON: thermal_reference_speed_rpm).", label="Thermal reference speed",
            default=False, group="heat"),
         BEARING),
        combine="broadcast"),
    Calculation(
        "runout", ("runout",), "Runout",
        "Inner-ring displacement at one angle, or the trajectory and runout over revolutions.",
        # a document: the page and the API take its text; the command line a file holding it
        (_f("errors", "document", "the manufacturing errors (the format of examples/runout/README.md).",
            label="Error set", required=True, group="runout", aliases=("-e",)),
         BEARING,
         _f("first_ball_angle", "angle", "Azimuth of ball 1 at psi = 0, e.g. '0 deg' (overrides the "
            "geometry).", label="First ball azimuth", unit="deg", group="bearing"),
         _f("angle", "angle", "One rotation angle psi, e.g. '90 deg' (default 0).",
            label="Rotation angle", unit="deg", group="rotation"),
         _f("revolutions", "int", "Rotation sequence over N inner-ring revolutions.",
            label="Revolutions", minimum=1, maximum=_bounds.MAX_REVOLUTIONS, group="rotation"),
         _f("steps_per_rev", "int", "Positions per revolution of the sequence (default 360).",
            label="Steps per revolution", minimum=4, maximum=_bounds.MAX_STEPS_PER_REV,
            group="rotation"),
         _f("start_angle", "angle", "psi of the first position of the sequence.",
            label="Start angle", unit="deg", default="0 deg", group="rotation"),
         _f("cage_ratio", "number", "Cage speed / inner-ring speed kappa (default (1 - gamma)/2).",
            label="Cage ratio", unit="-", minimum=0, exclusive=True, maximum=1, group="rotation"),
         _f("refine", "flag", "Refine the contact points (a second pass at the contact points found).",
            label="Refine contacts", default=False, group="runout")),
        heavy=True),
    Calculation(
        "runout-monte-carlo", ("runout", "monte-carlo"), "Runout Monte Carlo",
        "Runout statistics over random bearings of an ISO 3290 ball grade and a ring class; the "
        "samples are the request's cases.",
        (BEARING,
         _f("ball_grade", "text", "ISO 3290 grade: G3, G5, G10, G16, G20, G24, G28, G40.",
            label="Ball grade", default="G5", group="runout"),
         _f("ring_class", "text", "Ring-class preset: P5, P4, P2.", label="Ring class", default="P4",
            group="runout"),
         _f("samples", "int", "Number of random bearings (the request's cases).",
            label="Samples", default=200, minimum=2, maximum=_bounds.MAX_SAMPLES, group="runout"),
         _f("seed", "int", "Root seed (results do not depend on chunking).", label="Seed",
            default=0, minimum=0, group="runout"),
         _f("steps_per_rev", "int", "Positions per revolution.", label="Steps per revolution",
            default=180, minimum=4, maximum=_bounds.MAX_STEPS_PER_REV, group="runout"),
         _f("revolutions", "int", "Revolutions per sample.", label="Revolutions", default=2,
            minimum=1, maximum=_bounds.MAX_REVOLUTIONS, group="runout"),
         _f("max_order", "int", "Highest waviness order K_max.", label="Highest waviness order",
            default=15, minimum=0, maximum=_bounds.MAX_ORDER, group="runout"),
         _f("cage_ratio", "number", "Cage speed / inner-ring speed kappa (default (1 - gamma)/2).",
            label="Cage ratio", unit="-", minimum=0, exclusive=True, maximum=1, group="rotation")),
        heavy=True),
    Calculation(
        "shaft", ("shaft",), "Shaft system",
        "Several bearings on an elastic shaft (Timoshenko elements) with gears, pulleys, housings and speed: "
        "support loads, bearing lives and the system life, deflection, stiffness at a point, natural "
        "frequencies.",
        # a document: the page and the API take its text, the command line the file (FILE) holding it
        (_f("model", "document", "the shaft system: its sections, supports, loads, gears, pulleys and load "
            "cases, as tables (JSON takes the same tables; the format of the user guide's shaft-systems page).",
            label="Shaft system", required=True, option="FILE", group="shaft", example=_SHAFT_EXAMPLE),
         _f("speed", "speed", "Shaft speed instead of the file's, e.g. '3000 rpm' (its sign: the sense of "
            "rotation).", label="Shaft speed", unit="rpm", group=_L),
         _f("stiffness_at", "length", "The direct stiffness at this position, e.g. '0 mm' (a spindle's nose).",
            label="Stiffness at", unit="mm", minimum=0, group="shaft"),
         _f("modes", "int", "The N lowest bending natural frequencies and their mode shapes.",
            label="Natural modes", minimum=0, maximum=50, group="shaft"),
         _f("campbell", "speed", "Speeds of a Campbell diagram, e.g. '0, 6000, 12000 rpm' or "
            "'0rpm:12000rpm:2000rpm' (at most 200).", label="Campbell speeds", unit="rpm", many=True,
            group="shaft"),
         _f("elements", "int", "At least this many elements over the shaft (instead of the file's).",
            label="Elements", minimum=1, maximum=400, group="shaft")),
        heavy=True),
)

#: Every calculation, by the name the API and the page use.
CALCULATIONS = {c.name: c for c in _CALCS}
