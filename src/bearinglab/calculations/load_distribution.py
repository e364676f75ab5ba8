"""The combined-load model (issue 11) as a calculation: the document of ``bearinglab load-distribution
--json``, and its figure.

One bearing under (F_x, F_y, F_z, M_x, M_y), or with some freedoms held at a displacement, at rest or at
speed (:func:`bearinglab.quasistatic.combined.combined_analysis`): the ball loads, the displacement and
the 5 x 5 stiffness (:func:`bearinglab.tables.load_distribution`). The command line
(:mod:`bearinglab.cli.load`) and the web compute the same document with :func:`document`; the polar plot
of the ball loads is drawn from the document (:func:`figure`). The helpers shared with the bearing set
(:mod:`.bearing_set`) are here.

Functions
---------
document   Parsed -> the document (a list of documents over a list of speeds, for the ROSS file)
figure     a document -> the polar plot of its ball loads (:func:`bearinglab.plots.load_distribution.ball_loads`)
"""

from __future__ import annotations

import json
import math
import types
import warnings

from ..errors import InputError
from ._failures import failures
from ._finite import finite
from ._inputs import (
    FREEDOMS,
    choice,
    five_loads,
    inputs_echo,
    parse_speeds,
    resolve_bearing,
)
from ._inputs import held_reactions as _reactions
from ._inputs import prescribed_displacements as _held
from ._inputs import prescribed_echo as _prescribed_echo
from ._request import given_text, with_notes

__all__ = ["document", "figure"]

#: The freedoms, their load fields, the JSON keys of their reactions and their displacement inputs
#: (:data:`._inputs.FREEDOMS`, which the roller bearings' document reads too)
_FREEDOMS = FREEDOMS
_LOADS = ("fx", "fy", "fz", "mx", "my", "radial_load", "axial_load")
_GEOMETRY = ("ball_diameter", "pitch_diameter", "inner_groove_radius", "outer_groove_radius")
MOUNTING = ("shaft_fit", "housing_fit", "shaft_interference", "housing_interference", "shaft_bore",
            "housing_outside_diameter", "shaft_material", "housing_material", "tolerance_class",
            "clearance_class", "inner_ring_temperature", "outer_ring_temperature", "ball_temperature",
            "shaft_temperature", "housing_temperature")


@finite('load-distribution')
def document(parsed, *, catalog=None, bearing_file=None, speeds=False):
    """The document of ``bearinglab load-distribution ... --json`` for a checked request.

    Parameters
    ----------
    parsed : Parsed
        A request of the calculation ``load-distribution`` (:func:`bearinglab.calculations.parse`).
    catalog, bearing_file : str or Path, optional
        The command line's user catalog and bearing file (the web takes neither).
    speeds : bool
        Whether ``speed`` may be a list (the command line's ``--ross``): one document per speed.

    Returns
    -------
    dict or list of dict
        The document (the bearing's provenance notes last in its ``warnings``); a list over a list of
        speeds.

    Raises
    ------
    RunFailure
        An input the calculation refuses, naming its field.
    """
    import numpy as np

    from .. import catalog as _catalog
    from .. import tables
    from ..quasistatic import combined
    from ..units import parse_quantity
    from . import _mounting, _preload, _rollers

    v, given = parsed.values, parsed.given

    def text(name):
        return given_text(parsed, name)

    with failures(parsed):
        roller = _rollers.bearing_of(parsed, bearing_file=bearing_file, catalog=catalog)
        if roller is not None:  # the slice model of a roller bearing (issue 32)
            return json.loads(tables.json_text(_rollers.load_document(parsed, roller, speeds=speeds)))
        b = resolve_bearing(text("bearing"), bearing_file, catalog, v.get("balls"), *map(text, _GEOMETRY),
                            v.get("inner_conformity"), v.get("outer_conformity"), text("contact_angle"),
                            text("radial_clearance"), text("ball_material"))
        from ..bearing import check_model

        check_model(b, "load-distribution")  # the types the model covers (issue 30): a refusal in one line
        notes = _catalog.provenance_notes(b)
        loads = five_loads(*map(text, _LOADS))
        held = _held([text(n.replace("-", "_")) for _, _, n, _ in _FREEDOMS],
                     ("fx" in given or "radial_load" in given, "fy" in given, "fz" in given or "axial_load" in given,
                      "mx" in given, "my" in given))
        w = _speeds(text("speed") or "0 rpm", speeds, b.require("pitch_diameter"))
        b, mounted = _mounting.operating_bearing(b, w.max(), {k: text(k) for k in MOUNTING})  # issue 23
        phi0 = parse_quantity(text("first_ball_angle") or "0 deg", "angle", "first-ball-angle")
        stiffness_at = choice("stiffness-at", text("stiffness_at") or "operating", combined.STIFFNESS_AT)
    cases = np.broadcast_to(loads, w.shape + (5,))
    r, caught = solve(combined.combined_analysis, b, cases, w, first_ball_angle=phi0, stiffness_at=stiffness_at,
                      prescribed_displacement=held)
    caught = plausibility(b, np.reshape(r.loads, (-1, 5)), r, [*r.warnings, *caught])
    flat = np.reshape(r.loads, (-1, 5))
    preloaded, note = _preload.report(b, flat[0] if bool(np.all(r.converged)) else None, float(w[0]),
                                      source=clearance_source(mounted, text("radial_clearance")))
    if note:
        caught = [note, *caught]
    docs = []
    for k in range(w.size):
        case = resolved(_case(r, k), b.require("pitch_diameter"))
        docs.append({**with_takeup(tables.load_distribution(case), takeup_um(b),
                                   _reactions(np.reshape(r.reactions, (-1, 5))[k], held)), **mounted, **preloaded,
                     "inputs": inputs(b, loads, w[k], phi0, stiffness_at=stiffness_at, **_prescribed_echo(held)),
                     "warnings": caught})
    return json.loads(tables.json_text(with_notes(docs[0] if w.size == 1 else docs, notes)))


def figure(doc, title=None):
    """The polar plot of the ball loads of one document (a load distribution, or a bearing of a set).

    Parameters
    ----------
    doc : dict
        A document of :func:`document` (its ``balls``).
    title : str, optional
        The figure's title; default: the bearing and the speed, as ``load-distribution --plot`` draws it.

    Returns
    -------
    matplotlib.figure.Figure
    """
    import numpy as np

    from ..plots import load_distribution as load_plots

    if "rollers" in doc:  # a roller bearing: its roller loads and lamina pressures (issue 32)
        from . import _rollers

        return _rollers.figure(doc, title)

    def column(key, scale=1.0):
        return np.array([np.nan if ball[key] is None else ball[key] * scale for ball in doc["balls"]])

    if title is None:
        title = f"Bearing {doc['inputs']['bearing']}: ball loads at {doc['inputs']['speed_rpm']:g} rpm"
    result = types.SimpleNamespace(azimuth=column("azimuth_deg", math.pi / 180.0),
                                   ball_load_inner=column("load_inner_N"), ball_load_outer=column("load_outer_N"))
    return load_plots.ball_loads(result, title=title)


def _speeds(text, allow_list, pitch_diameter):
    w = parse_speeds(text, pitch_diameter=pitch_diameter)
    if w.size > 1 and not allow_list:
        raise InputError("speed: a list of speeds needs --ross FILE (one speed otherwise)")
    return w


def solve(what, *args, **kwargs):
    """Run a model; return its result and every warning raised on the way (as messages)."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = what(*args, **kwargs)
    return result, [str(c.message) for c in caught]


def inputs(b, loads, speed, phi0, **options):
    """The inputs as used, in engineering units (echoed in the JSON; :func:`inputs_echo`)."""
    from ..units import RPM

    fx, fy, fz, mx, my = loads
    return inputs_echo(b, fx_N=fx, fy_N=fy, fz_N=fz, mx_Nmm=mx * 1e3, my_Nmm=my * 1e3, speed_rpm=float(speed) / RPM,
                       first_ball_angle_deg=math.degrees(phi0), **options,
                       radial_clearance_um=None if b.radial_clearance is None else b.radial_clearance * 1e6,
                       reduced_modulus_GPa=b.reduced_modulus / 1e9)


def plausibility(b, loads, r, notes):
    """The analysis's warnings, those raised on the way and the plausibility limits (bearinglab.limits)."""
    import numpy as np

    from .. import limits

    z = np.shape(r.ball_load_inner)[-1]
    ok = np.ravel(np.asarray(getattr(r, "converged", True), dtype=bool)) & np.ones(np.size(loads) // 5, bool)
    if ok.any():
        def pick(name):
            return np.reshape(getattr(r, name), (-1, z))[ok]

        notes = [*notes, *limits.combined_warnings(b, np.reshape(loads, (-1, 5))[ok], pick("ball_load_inner"),
                                                   pick("ball_load_outer"), pick("contact_angle_inner"),
                                                   pick("contact_angle_outer"))]
    return list(dict.fromkeys(notes))


def takeup_um(b):
    """Half the axial play, A sin(alpha0) [um]: the part of delta_z a thrust spends before any ball carries
    (displacements are counted from the concentric position, MASTA's convention; issue 20 item 11); the
    other ball types' own (issue 30: ``combined._takeup``)."""
    from ..quasistatic import combined

    return combined._takeup(b) * 1e6


def with_takeup(doc, takeup, reactions=None):
    """``doc`` with ``axial_play_takeup_um`` after the tilts (so the elastic part is one subtraction) and,
    with ``reactions``, the reactions of the held freedoms after it."""
    out = {}
    for key, value in doc.items():
        out[key] = value
        if key == "tilt_y_mrad":
            out["axial_play_takeup_um"] = takeup
            if reactions is not None:
                out["reactions"] = reactions
    return out


def clearance_source(mounted, radial_clearance):
    """How a bearing's operating clearance was given, for the preload warning."""
    if mounted:
        return "the operating clearance from the fits and temperatures"
    return "the given radial clearance" if radial_clearance is not None else "the bearing's clearance"


#: Below these fractions a displacement component (tilts at the pitch radius) or a stiffness coupling
#: (against sqrt(k_ii k_jj)) is rounding where symmetry makes it zero: far below the solver's resolution
#: (relative residual 1e-12, so 1e-12 of the displacement times the condition) and far below any
#: coupling the geometry makes (1e-6 and up), printed as 0 so that a document reads the same on any CPU.
_ZERO_DISPLACEMENT, _ZERO_COUPLING, _ZERO_ANGLE = 1e-9, 1e-10, 1e-12


def resolved(case, pitch_diameter):
    """One case with the values below the solver's resolution (symmetry's zeros) set to 0.0."""
    import numpy as np

    u = np.asarray(case.displacement, dtype=float)
    if np.all(np.isfinite(u)):
        arm = np.array([1.0, 1.0, 1.0, pitch_diameter / 2.0, pitch_diameter / 2.0])
        size = np.max(np.abs(u * arm))
        u = np.where(np.abs(u * arm) <= _ZERO_DISPLACEMENT * size, 0.0, u)
    k = np.asarray(case.stiffness, dtype=float)
    if np.all(np.isfinite(k)):
        d = np.sqrt(np.abs(np.diagonal(k)))
        k = np.where(np.abs(k) <= _ZERO_COUPLING * d[:, None] * d[None, :], 0.0, k)
    out = dict(vars(case), displacement=u, stiffness=k)
    for name in ("contact_angle_inner", "contact_angle_outer"):
        a = np.asarray(out[name], dtype=float)
        out[name] = np.where(np.abs(a) <= _ZERO_ANGLE, 0.0, a)
    return types.SimpleNamespace(**out)


def _case(r, k):
    """Case k of a batched LoadDistribution (cases on the first axis), as an object with one case's fields."""
    import numpy as np

    fields = {f: np.asarray(getattr(r, f))[k] for f in r._fields if f not in ("warnings", "azimuth", "row")}
    return types.SimpleNamespace(**fields, azimuth=r.azimuth, warnings=r.warnings, row=getattr(r, "row", None))
