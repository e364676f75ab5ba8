"""Roller bearings in the calculations (issue 32): the bearing of a request, its mounting, the load
distribution document, and the one line of a model that is ball bearings' only.

A request names a roller bearing as it names a ball bearing: by a catalog designation (``NU 208 ECP``), a
user catalog or bearing file whose table says ``type = "cylindrical" | "tapered" | "spherical"``, or inline by
its roller set (``rollers``, ``roller_diameter``, ``roller_length``, ``pitch_diameter``; a cylindrical NU
without a contact angle, a tapered bearing with one). The roller fields of :mod:`.registry` (``ROLLERS``) and
the shared geometry fields ``pitch_diameter``, ``contact_angle`` (a tapered bearing's cup angle) and
``radial_clearance`` (any sign: zero is line to line, negative a preload) override the named bearing's. Each
calculation's ``document`` asks :func:`bearing_of` first and takes its roller path where it gets a bearing.

Bearing
-------
is_roller        whether a bearing is a RollerBearing
bearing_of       the RollerBearing of a request, or None for a ball bearing (roller inputs then refused)
refuse           the one line of a calculation that does not take roller bearings (or not this type)
operating        the bearing at its operating clearance under the mounting inputs (ball or roller)
slices_of        the slices per roller of a request (30 by default)
notes_of         the provenance note of a user catalog entry overriding a built-in roller bearing
provenance_of    every provenance note of a roller bearing (its estimated roller set, notes_of)

Load distribution
-----------------
load_document    the document of ``load-distribution`` for a roller bearing (rollers, laminae, stiffness)
roller_case      one case of a RollerLoadDistribution as JSON entries (displacement, stiffness, rollers)
ring_entries     a ring's or a shaft's displacement and stiffness as JSON entries (symmetry's zeros as 0)
figure           a roller document -> the roller loads and the lamina pressures (plots.rollers.overview)

The physics is :mod:`bearinglab.rollers` (the ISO/TS 16281 slice model at rest); the other calculations'
roller paths are in their own modules (``_roller_life`` of :mod:`.life`, ``_roller_film`` of :mod:`.film` ...) and in
:mod:`._roller_pairs` (``bearing-set``). This module imports no calculation's module.
"""

from __future__ import annotations

import math
import warnings

from ..errors import InputError
from ._inputs import five_loads, inputs_echo, parse_length, parse_speeds
from ._reading import text as _text

__all__ = ["bearing_of", "figure", "is_roller", "load_document", "notes_of", "operating", "provenance_of", "refuse", "ring_entries",
           "roller_case", "slices_of"]

#: The roller inputs of a request: they describe a roller bearing, and a ball bearing refuses them.
ROLLER_INPUTS = ("rollers", "roller_diameter", "roller_length", "profile", "crown_drop", "slices")
#: The inputs of a ball bearing's geometry, which a roller bearing refuses.
_BALL_INPUTS = ("balls", "ball_diameter", "inner_groove_radius", "outer_groove_radius", "inner_conformity",
                "outer_conformity", "ball_material")
_SHARED = ("pitch_diameter", "contact_angle", "radial_clearance")
_MAX_SLICES = 1000  # slices per roller on the command line (the web's field: 200); ISO/TS 16281 asks >= 30
_LOADS = ("fx", "fy", "fz", "mx", "my", "radial_load", "axial_load")
_UM = 1e-6


def is_roller(bearing):
    """Whether ``bearing`` is a :class:`~bearinglab.rollers.bearing.RollerBearing`."""
    return hasattr(bearing, "roller_diameter")


def _option(name):
    return "--" + name.replace("_", "-")


def _base(parsed, bearing_file, catalog):
    """The named bearing (catalog or file), or None where none is named, both are, or it is not found (the
    ball path then says why, in its words)."""
    from .. import catalog as _catalog

    name = _text(parsed, "bearing")
    if bool(name) == bool(bearing_file):
        return None
    try:
        return _catalog.get(name, catalog=catalog) if name else _catalog.load_bearing_file(bearing_file)
    except InputError:
        return None


def bearing_of(parsed, *, bearing_file=None, catalog=None, only=()):
    """The roller bearing of a request, with its overrides; None for a ball bearing.

    Parameters
    ----------
    parsed : Parsed
        The request (its ``bearing`` field, the geometry and roller fields it has).
    bearing_file, catalog : str or Path, optional
        The command line's bearing file and user catalog.
    only : tuple of str
        More fields of this calculation that only a roller bearing takes (``life``'s misalignment).

    Returns
    -------
    RollerBearing or None

    Raises
    ------
    InputError
        A roller input given for a ball bearing, a ball input for a roller bearing, a field the bearing
        refuses (a roller longer than the ring is wide, a negative crown drop, a cup angle over 45 deg),
        naming the field.
    """
    from ..rollers.bearing import RollerBearing

    given = parsed.given
    roller_given = [k for k in (*ROLLER_INPUTS, *only) if k in given]
    base = _base(parsed, bearing_file, catalog)
    named = bool(_text(parsed, "bearing") or bearing_file)
    inline = not named and any(k in given for k in ("rollers", "roller_diameter", "roller_length"))
    if not (is_roller(base) or inline):
        if roller_given and (base is not None or not named):
            what = f"{base.designation!r} is a ball bearing" if base is not None else "the inline bearing is a ball bearing"
            raise InputError(f"{roller_given[0].replace('_', '-')}: {what}; {_option(roller_given[0])} is an input of "
                             "roller bearings (give a roller bearing, e.g. --bearing 'NU 208 ECP')")
        return None
    ball = [k for k in _BALL_INPUTS if k in given]
    if ball:
        label = f"{base.designation!r} is a {base.type} roller bearing" if base is not None else \
            "a roller bearing (--rollers ...)"
        raise InputError(f"{ball[0].replace('_', '-')}: {label}, which has no {ball[0].replace('_', ' ')}; its roller "
                         "set is --rollers, --roller-diameter, --roller-length, --pitch-diameter")
    if base is None:  # inline: a cylindrical NU, or a tapered bearing with a cup angle
        angle = _angle(parsed)
        base = RollerBearing("tapered" if angle else "cylindrical", contact_angle=angle or None,
                             designation="inline")
    return _overridden(parsed, base)


def _angle(parsed):
    from ..units import parse_quantity

    text = _text(parsed, "contact_angle")
    return None if text is None else parse_quantity(text, "angle", "contact-angle")


def _overridden(parsed, base):
    """``base`` with the request's roller set, profile, angle and clearance (checked by RollerBearing: its
    message opens with the field's name)."""
    from ..units import parse_quantity
    from . import _inputs

    given = parsed.given
    changes, overrides = {}, {}
    if "rollers" in given:
        changes["rollers"] = _whole(parsed.values["rollers"], "rollers")
    for name in ("roller_diameter", "roller_length", "pitch_diameter"):
        if name in given:
            changes[name] = parse_length(_text(parsed, name), name.replace("_", "-"))
    if "contact_angle" in given and base.designation != "inline":
        changes["contact_angle"] = _angle(parsed)
    if "radial_clearance" in given and parsed.calculation.field("radial_clearance").kind == "length":
        # zero: line to line; negative: a preload (issue 32); `clearance`'s is the unmounted range, not this
        changes["radial_clearance"] = parse_quantity(_text(parsed, "radial_clearance"), "length", "radial-clearance")
    profile = _text(parsed, "profile")
    if "crown_drop" in given:
        if profile not in (None, "crowned"):
            raise InputError(f"crown-drop: goes with --profile crowned, not --profile {profile}")
        profile = "crowned"
        drop = parse_quantity(_text(parsed, "crown_drop"), "length", "crown-drop")
        if not drop >= 0:
            raise InputError(f"crown-drop must be >= 0 [um] (the roller profile drops towards the ends), got "
                             f"{drop * 1e6:g} um")
        changes["crown_drop"] = drop
    if profile is not None:
        if profile == "crowned" and "crown_drop" not in changes and base.crown_drop is None:
            raise InputError("profile: 'crowned' needs --crown-drop (the drop at the roller ends, e.g. '5 um')")
        changes["profile"] = profile
    for name in (*ROLLER_INPUTS, *_SHARED):
        if name in given and name != "slices" and name.replace("_", "-") not in overrides and (
                name != "radial_clearance" or "radial_clearance" in changes):
            overrides[name.replace("_", "-")] = _text(parsed, name)
    if not changes:
        return base
    if base.designation != "inline":
        label = ", ".join(f"{k} {v}" for k, v in overrides.items())
        changes["designation"] = f"{base.designation} ({label})"
    if base.estimated_fields:  # a value given is no longer an estimate
        changes["estimated_fields"] = tuple(f for f in base.estimated_fields if f not in changes)
    b = base.replace(**changes)
    if base.designation != "inline":
        _inputs._OVERRIDES[b] = {"catalog_bearing": base.designation, "overrides": overrides}
    return b


def _whole(value, name):
    if isinstance(value, bool) or not isinstance(value, int):
        try:
            value = int(str(value).strip())
        except ValueError:
            raise InputError(f"{name}: expected a whole number, got {value!r}") from None
    return value


def slices_of(parsed):
    """The slices per roller of a request: ``slices`` (1 ... 1000 on the command line) or 30."""
    from .._bounds import check_count
    from ..rollers.analysis import N_SLICES

    if "slices" not in parsed.given:
        return N_SLICES
    return check_count("slices", _whole(parsed.values["slices"], "slices"), _MAX_SLICES)


def provenance_of(bearing):
    """Every provenance note of a roller bearing: its estimated fields (the rules of
    :mod:`bearinglab.rollers.estimation`) and :func:`notes_of`."""
    from ..rollers.analysis import provenance

    return [*provenance(bearing), *notes_of(bearing)]


def notes_of(bearing):
    """The provenance notes a result of this bearing carries beyond the model's own (which name an estimated
    roller set): a user catalog entry overriding a built-in bearing."""
    note = (bearing.sources or {}).get("catalog")
    return [f"{bearing.designation}: {note}"] if note else []


#: The calculations that do not take roller bearings, and why (their models are of ball bearings).
BALL_MODELS = {
    "high-speed": "the high-speed model solves the contact angles of balls at speed (spec 004)",
    "axial-angle": "the test-stand method solves the contact angle of balls under thrust (spec 000)",
    "stand-load": "the test-stand load keeps balls from gyroscopic slip (spec 000)",
    "runout": "the runout model rolls balls over the errors of ball grooves (spec 003)",
    "runout-monte-carlo": "the runout model rolls balls over the errors of ball grooves (spec 003)",
}


def refuse(bearing, what, reason=None):
    """The InputError of a calculation that does not take this roller bearing: ``bearing: 'NU 208 ECP' is a
    cylindrical roller bearing: <reason>``.

    Parameters
    ----------
    bearing : RollerBearing
        The bearing.
    what : str
        The calculation's name (a key of :data:`BALL_MODELS`) or its words.
    reason : str, optional
        Why; by default that of :data:`BALL_MODELS`, a model of ball bearings.

    Returns
    -------
    InputError
    """
    if reason is None:
        reason = f"{BALL_MODELS.get(what, what)}: a ball-bearing model, for ball bearings only"
    return InputError(f"bearing: {bearing.designation!r} is a {bearing.type} roller bearing: {reason}")


def check_model(parsed, *, bearing_file=None, catalog=None):
    """Refuse a roller bearing in a calculation of ball bearings only (:data:`BALL_MODELS`), in one line.
    A name that is not found is left to the calculation's own message."""
    base = _base(parsed, bearing_file, catalog)
    if is_roller(base):
        raise refuse(base, parsed.calculation.name)


def spherical(bearing, what):
    """Refuse a spherical roller bearing in a model of its load distribution, in one line."""
    if bearing.type == "spherical":
        raise refuse(bearing, what, f"{what} needs its load distribution, which is not modelled (two rows of barrel "
                                    "rollers on a spherical raceway); spherical roller bearings have ratings, life "
                                    "(ISO 281) and friction only")


# ----------------------------------------------------------------------------------------------- mounting
class _Mounted:
    """A roller bearing as :mod:`bearinglab.mounting` reads a bearing: raceways at the roller middles
    (D_pw -+ D_we), the rollers' material as the balls'."""

    type = "roller"
    clearance_class = None
    tolerance_class = None

    def __init__(self, b):
        self._b = b
        self.bore, self.outside_diameter = b.bore, b.outside_diameter
        self.pitch_diameter, self.ball_diameter = b.pitch_diameter, b.roller_diameter
        self.ring_material, self.ball_material = b.ring_material, b.roller_material
        self.radial_clearance, self.designation = b.radial_clearance, b.designation

    def require(self, *names):
        return self._b.require(*names)


def operating(bearing, speed=0.0, options=None):
    """The bearing at its probable operating clearance under the mounting inputs, and the JSON entries.

    A ball bearing goes to :func:`bearinglab.calculations._mounting.operating_bearing`. A roller bearing takes
    the chain of :mod:`bearinglab.mounting` with its raceways at the roller middles; its unmounted clearance is
    its ``radial_clearance`` (``--radial-clearance`` or its catalog entry): ISO 5753-1's clearance classes of
    roller bearings are not in bearinglab (only those of deep-groove ball bearings,
    ``data/iso5753_radial_clearance.csv``), and a clearance class is refused naming what is missing. A zero or
    negative operating clearance is solved (a preloaded bearing).

    Parameters
    ----------
    bearing : BallBearing or RollerBearing
        The bearing.
    speed : float
        Inner-ring speed, for the centrifugal growth. [rad/s]
    options : dict
        The mounting fields (name -> text as given, None: not given).

    Returns
    -------
    tuple
        ``(bearing, entries)``; ``(bearing, {})`` without mounting inputs.
    """
    from . import _mounting

    if not is_roller(bearing):
        return _mounting.operating_bearing(bearing, speed, options)
    given = {k: v for k, v in (options or {}).items() if v is not None}
    if not given:
        return bearing, {}
    inputs = mounted_inputs(bearing, given, speed)
    from ..mounting import chain

    r = chain.operating_range(inputs.unmounted, inputs.inner, inputs.outer, inputs.mounting, inputs.conditions)
    e = float(r.probable.operating_clearance)
    doc = {"operating_clearance_um": e / _UM,
           "operating_clearance_min_um": float(r.least.operating_clearance) / _UM,
           "operating_clearance_max_um": float(r.largest.operating_clearance) / _UM,
           "unmounted_clearance_um": [inputs.unmounted[0] / _UM, inputs.unmounted[1] / _UM],
           "mounting": inputs.echo, "mounting_warnings": list(r.warnings)}
    return bearing.replace(radial_clearance=e), doc


def mounted_inputs(bearing, given, speed=0.0, *, radial_clearance=None):
    """The mounting inputs of a roller bearing (:func:`bearinglab.calculations._mounting.mounted_inputs` on its
    raceways), its unmounted clearance from ``radial_clearance`` (text: one value or 'min, max') or the
    bearing's own."""
    from . import _mounting

    if bearing.type == "spherical":
        raise refuse(bearing, "mounting", "its mounted clearance is not modelled (ratings, life and friction only)")
    if given.get("clearance_class") is not None:
        raise InputError(f"clearance-class: ISO 5753-1's clearance classes of {bearing.type} roller bearings are not "
                         "in bearinglab (only those of deep-groove ball bearings, data/iso5753_radial_clearance.csv); "
                         "give the unmounted clearance (--radial-clearance) from the maker's table")
    if radial_clearance is None:
        if bearing.radial_clearance is None:
            raise InputError("radial-clearance: the mounting chain of a roller bearing starts from its unmounted "
                             "clearance: give --radial-clearance (ISO 5753-1's clearance classes of roller bearings "
                             "are not in bearinglab)")
        radial_clearance = f"{bearing.radial_clearance!r} m"
    options = {k: v for k, v in given.items() if k != "clearance_class"}
    return _mounting.mounted_inputs(_Mounted(bearing), **options, radial_clearance=radial_clearance,
                                    speed=float(speed), require=True)


# ------------------------------------------------------------------------------------- load distribution
def _held(parsed):
    from ._inputs import FREEDOMS, prescribed_displacements

    given = parsed.given
    return prescribed_displacements([_text(parsed, n.replace("-", "_")) for _, _, n, _ in FREEDOMS],
                 ("fx" in given or "radial_load" in given, "fy" in given, "fz" in given or "axial_load" in given,
                  "mx" in given, "my" in given))


def geometry_of(bearing):
    """The bearing with its roller set, estimated (and labelled) where its catalog entry gives none."""
    from ..rollers.estimation import with_estimated_geometry

    return bearing if bearing.has_internal_geometry and bearing.contact_angle is not None else \
        with_estimated_geometry(bearing)


def load_document(parsed, bearing, *, speeds=False):
    """The document of ``load-distribution`` for a roller bearing: the slice model at rest.

    Parameters
    ----------
    parsed : Parsed
        A request of ``load-distribution``.
    bearing : RollerBearing
        From :func:`bearing_of`.
    speeds : bool
        Whether a list of speeds was asked for (``--ross``): refused, the slice model is at rest.

    Returns
    -------
    dict
        The ring's displacement and the 5 x 5 ``stiffness_matrix`` (SI), ``max_roller_load_N``,
        ``max_pressure_MPa``, ``rib_load_N``, ``slice_positions_mm`` and ``rollers`` (per roller
        ``azimuth_deg``, ``load_N``, ``max_pressure_MPa``, ``slice_loads_N``, ``slice_pressures_MPa``), the
        mounting entries, ``inputs`` and ``warnings``.
    """
    from .. import tables
    from ..rollers import analysis
    from ..units import RPM, parse_quantity
    from ._inputs import held_reactions, prescribed_echo
    from ._mounting import NAMES as MOUNTING

    b = bearing
    spherical(b, "the load distribution")
    loads = five_loads(*(_text(parsed, k) for k in _LOADS))
    held = _held(parsed)
    b = geometry_of(b)
    w = parse_speeds(_text(parsed, "speed") or "0 rpm", pitch_diameter=b.pitch_diameter)
    if w.size > 1 or speeds:
        raise InputError("speed: a roller bearing's slice model is at rest (ISO/TS 16281): one speed, no --ross (the "
                         "ROSS coefficients over speed are of the ball bearings' quasi-static model)")
    if (_text(parsed, "stiffness_at") or "operating") != "operating":
        raise InputError("stiffness-at: chooses the contact angles of a ball bearing's Hertz constants; a roller "
                         "bearing's laminae have ISO/TS 16281's stiffness")
    speed = float(w[0])
    b, mounted = operating(b, speed, {k: _text(parsed, k) for k in MOUNTING})
    phi0 = parse_quantity(_text(parsed, "first_ball_angle") or "0 deg", "angle", "first-ball-angle")
    n_slices = slices_of(parsed)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        r = analysis.roller_analysis(b, loads, n_slices=n_slices, first_roller_angle=phi0, prescribed_displacement=held)
    notes = [*r.warnings, *(str(c.message) for c in caught)]
    if b.radial_clearance is None:
        notes.append("radial clearance: not given, so 0 (line to line); give --radial-clearance or the mounting "
                     "(fits, temperatures) for the operating clearance")
    elif b.radial_clearance <= 0:
        notes.append(f"operating clearance {b.radial_clearance / _UM:.4g} um: the bearing runs "
                     f"{'line to line' if b.radial_clearance == 0 else 'preloaded'}; the slice model solves it so")
    if speed > 0:
        notes.append("speed: the slice model is at rest (ISO/TS 16281, no centrifugal roller loads); the speed "
                     "enters the mounting only")
    notes += pressure_warnings(r.max_pressure)
    doc = {**roller_case(r, b.pitch_diameter, reactions=held_reactions(r.reactions, held)), **mounted,
           "inputs": inputs_echo(b, fx_N=loads[0], fy_N=loads[1], fz_N=loads[2], mx_Nmm=loads[3] * 1e3,
                                 my_Nmm=loads[4] * 1e3, speed_rpm=speed / RPM, first_roller_angle_deg=math.degrees(phi0),
                                 slices=n_slices, **prescribed_echo(held),
                                 radial_clearance_um=None if b.radial_clearance is None else b.radial_clearance / _UM,
                                 reduced_modulus_GPa=b.reduced_modulus / 1e9),
           "warnings": list(dict.fromkeys([*notes, *notes_of(b)]))}
    return tables.json_value(doc)


#: ISO 76:2006's contact stress of C0 for roller bearings [Pa]: 4000 MPa at the most loaded line contact.
ISO76_ROLLER_STRESS = 4000e6


def pressure_warnings(max_pressure):
    """The warning where a lamina pressure exceeds ISO 76's 4000 MPa of roller bearings (permanent
    deformation of the raceways: the static load rating's reference stress)."""
    import numpy as np

    p = np.nan_to_num(np.asarray(max_pressure, dtype=float))
    top = float(np.max(p)) if p.size else 0.0
    if top <= ISO76_ROLLER_STRESS:
        return []
    over = int(np.sum(p > ISO76_ROLLER_STRESS))
    return [(f"inner raceway: lamina pressure {top / 1e6:.0f} MPa exceeds ISO 76's 4000 MPa of roller bearings "
             f"({over} of {p.size} rollers): permanent deformation of the raceways")]


def roller_case(r, pitch_diameter, *, reactions=None):
    """One case of a :class:`~bearinglab.rollers.distribution.RollerLoadDistribution` as JSON entries.

    Parameters
    ----------
    r : RollerLoadDistribution
        One case (roller fields of shape (Z,), lamina fields (Z, n_s)).
    pitch_diameter : float
        D_pw, the arm of the tilts in what counts as a zero. [m]
    reactions : dict, optional
        The reactions of the held freedoms (N, N mm), after the tilts.

    Returns
    -------
    dict
        ``displacement_x_um`` ... ``tilt_y_mrad``, ``reactions``, ``stiffness_matrix`` (SI),
        ``max_roller_load_N``, ``max_pressure_MPa``, ``rib_load_N``, ``converged``, ``residual``,
        ``iterations``, ``slices``, ``slice_positions_mm`` and ``rollers``.
    """
    import numpy as np

    from .._io import json_value

    out = ring_entries(r.displacement, r.stiffness, pitch_diameter)
    if reactions:
        stiffness = out.pop("stiffness_matrix")
        out.update(reactions=reactions, stiffness_matrix=stiffness)
    q = np.asarray(r.slice_load, dtype=float)
    p = np.asarray(r.slice_pressure, dtype=float)
    out.update(max_roller_load_N=json_value(float(np.max(r.roller_load))),
               max_pressure_MPa=json_value(float(np.max(r.max_pressure)) / 1e6),
               rib_load_N=json_value(float(r.rib_load)),
               converged=bool(r.converged), residual=json_value(float(r.residual)), iterations=int(r.iterations),
               slices=int(q.shape[-1]), slice_positions_mm=json_value(np.asarray(r.slice_position) * 1e3))
    out["rollers"] = [{"azimuth_deg": json_value(math.degrees(float(r.azimuth[j]))),
                       "load_N": json_value(float(r.roller_load[j])),
                       "max_pressure_MPa": json_value(float(r.max_pressure[j]) / 1e6),
                       "slice_loads_N": json_value(q[j]), "slice_pressures_MPa": json_value(p[j] / 1e6)}
                      for j in range(q.shape[0])]
    return out


#: Below these fractions a displacement component (tilts at the pitch radius) or a stiffness coupling (against
#: sqrt(k_ii k_jj)) is the rounding of a zero that symmetry makes (the ring Newton stops at a relative residual
#: of 1e-12): shown as 0, so that a document reads the same on any CPU.
_ZERO_DISPLACEMENT, _ZERO_COUPLING = 1e-9, 1e-10


def ring_entries(displacement, stiffness, pitch_diameter):
    """A ring's (or a shaft's) displacement [um, mrad] and 5 x 5 stiffness (SI) as JSON entries, with the zeros
    that symmetry makes shown as 0.

    Parameters
    ----------
    displacement : array_like
        (5,) delta_x, delta_y, delta_z [m], theta_x, theta_y [rad].
    stiffness : array_like
        (5, 5). [N/m, N/rad, N m/m, N m/rad]
    pitch_diameter : float
        The arm of the tilts in what counts as a zero. [m]

    Returns
    -------
    dict
        ``displacement_x_um``, ``displacement_y_um``, ``displacement_z_um``, ``tilt_x_mrad``, ``tilt_y_mrad``,
        ``stiffness_matrix``.
    """
    from .._io import json_value

    u, k = _resolved(displacement, stiffness, pitch_diameter)
    out = {f"displacement_{a}_um": json_value(u[i] * 1e6) for i, a in enumerate("xyz")}
    out.update(tilt_x_mrad=json_value(u[3] * 1e3), tilt_y_mrad=json_value(u[4] * 1e3),
               stiffness_matrix=json_value(k))
    return out


def _resolved(displacement, stiffness, pitch_diameter):
    """The displacement and the stiffness of one case with symmetry's zeros set to 0.0."""
    import numpy as np

    u = np.asarray(displacement, dtype=float)
    k = np.asarray(stiffness, dtype=float)
    if np.all(np.isfinite(u)):
        arm = np.array([1.0, 1.0, 1.0, 0.5 * pitch_diameter, 0.5 * pitch_diameter])
        size = np.max(np.abs(u * arm))
        u = np.where(np.abs(u * arm) <= _ZERO_DISPLACEMENT * size, 0.0, u)
    if np.all(np.isfinite(k)):
        d = np.sqrt(np.abs(np.diagonal(k)))
        k = np.where(np.abs(k) <= _ZERO_COUPLING * d[:, None] * d[None, :], 0.0, k)
    return u, k


def figure(doc, title=None):
    """The roller loads and the lamina pressures of a roller document (``load-distribution --plot``).

    Parameters
    ----------
    doc : dict
        A document of :func:`load_document` (or one bearing of a tapered pair): its ``rollers`` and
        ``slice_positions_mm``.
    title : str, optional
        Default: the bearing and its largest roller load.

    Returns
    -------
    matplotlib.figure.Figure
    """
    import types

    import numpy as np

    from ..plots import rollers as roller_plots

    rows = doc["rollers"]

    def column(key, scale=1.0):
        return np.array([np.nan if row[key] is None else row[key] * scale for row in rows])

    result = types.SimpleNamespace(
        azimuth=column("azimuth_deg", math.pi / 180.0), roller_load=column("load_N"),
        slice_pressure=np.array([[np.nan if x is None else x * 1e6 for x in row["slice_pressures_MPa"]]
                                 for row in rows]),
        slice_position=np.asarray(doc["slice_positions_mm"], dtype=float) * 1e-3)
    if title is None:
        bearing = doc.get("inputs", {}).get("bearing", doc.get("bearing", ""))
        title = f"Bearing {bearing}: roller loads and lamina pressures"
    return roller_plots.overview(result, title=title)
