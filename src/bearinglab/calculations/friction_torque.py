"""The ``friction`` calculation (``bearinglab friction torque``): the friction torque of a bearing under
combined load by the handbook models of the friction-rig lab (one-term, two-term, Palmgren: P0, T, T0
and T_F) or SKF's four-term model (rolling, sliding, seal and drag moments; oil bath included).

:func:`document` gives what ``bearinglab friction torque ... --json`` prints (the command prints it),
for the command line and the web alike. The physics is :mod:`bearinglab.friction`.

Functions
---------
compute    Parsed -> FrictionResult (the document, the bearing, SKF's result where that model ran)
document   Parsed -> the JSON document
"""

from __future__ import annotations

import dataclasses
import warnings
from typing import NamedTuple

from ..errors import InputError
from . import _reading as inp
from ._failures import failures
from ._finite import finite
from ._inputs import default_lubrication, lubricant_viscosity, parse_viscosity

__all__ = ["MODELS", "FrictionResult", "compute", "document"]

#: The friction models, by the name the request gives.
MODELS = ("one-term", "two-term", "palmgren", "skf")
_MODELS = MODELS


class FrictionResult(NamedTuple):
    """A computed friction request."""

    document: dict
    """The JSON document (``bearinglab friction torque --json``)."""
    skf: object
    """The :class:`bearinglab.friction.SKFFriction`-like result of the skf model, None for the others."""


@finite('friction')
def compute(parsed, *, bearing_file=None, catalog=None):
    """Compute a friction request.

    Parameters
    ----------
    parsed : bearinglab.calculations.Parsed
        The request (fields of ``CALCULATIONS["friction"]``).
    bearing_file, catalog : path, optional
        A bearing file or a user catalog (the command line's files; the web has none).

    Returns
    -------
    FrictionResult
    """
    t, v = inp.text, inp.value
    resolved = []
    with failures(parsed, options=False):  # messages in the command line's words (_failures)
        doc, m, b, n = _torque(
            t(parsed, "radial_load", "0 N"), t(parsed, "axial_load", "0 N"), t(parsed, "speed", "0 rpm"),
            v(parsed, "model", "one-term"), t(parsed, "bearing"), bearing_file, catalog, v(parsed, "type"),
            t(parsed, "contact_angle"), t(parsed, "bore"), t(parsed, "outside_diameter"),
            t(parsed, "mean_diameter"), t(parsed, "static_load_rating"), v(parsed, "mu"), v(parsed, "x0"),
            v(parsed, "y0"), v(parsed, "f"), v(parsed, "c"), v(parsed, "f0"), t(parsed, "viscosity"),
            v(parsed, "palmgren_f0"), default_lubrication(v(parsed, "lubrication"), t(parsed, "oil")), t(parsed, "oil"),
            t(parsed, "temperature"), v(parsed, "viscosity_index"), t(parsed, "viscosity_100"),
            t(parsed, "oil_level"), v(parsed, "drag_loss_factor"), parsed.given.get("series"), resolved)  # series as typed: "  " is no series
        doc = _with_operating_clearance(doc, parsed, b, n)
    for b in resolved:  # the provenance notes of a catalog bearing, as the command line adds them
        doc = inp.notes_in(doc, b)
    return FrictionResult(doc, m)


@finite('friction')
def document(parsed, *, bearing_file=None, catalog=None):
    """The document of ``bearinglab friction torque ... --json`` for a request.

    Parameters
    ----------
    parsed : bearinglab.calculations.Parsed
        The request.
    bearing_file, catalog : path, optional
        A bearing file or a user catalog (the command line's files; the web has none).

    Returns
    -------
    dict
        The model's torques (one case as one object, lists as ``cases``), the constants used,
        ``inputs`` and ``warnings``.
    """
    return compute(parsed, bearing_file=bearing_file, catalog=catalog).document


def _torque(radial_load, axial_load, speed, model, bearing, bearing_file, catalog, bearing_type, contact_angle,
            bore, outside_diameter, mean_diameter, static_load_rating, mu, x0, y0, f, c, f0, viscosity,
            palmgren_f0, lubrication, oil, temperature, viscosity_index, viscosity_100, oil_level,
            drag_loss_factor, series, resolved):
    """The document of one request, SKF's result (None for the handbook models), the bearing and the
    speeds; the bearing resolved from the catalog or a file is appended to ``resolved``."""
    import numpy as np

    from .. import friction, tables
    from ..units import RPM
    if model not in _MODELS:
        raise InputError(f"model must be one of {list(_MODELS)}, got {model!r}")
    _check_constants(mu=mu, x0=x0, y0=y0, f=f, c=c, f0=f0, palmgren_f0=palmgren_f0)
    if model == "skf":
        b = inp.resolve_bearing(bearing, bearing_file, catalog, contact_angle=contact_angle) if (
            bearing or bearing_file) else None
        if b is None:
            raise InputError("bearing: the skf model needs --bearing NAME or --bearing-file FILE (series, seals)")
        resolved.append(b)
        b = _skf_bearing(b, series)
        fr, fa, n = _cases(radial_load, axial_load, speed)
        _check_speed(b, n)
        doc, m = _skf_torque(b, fr, fa, n, viscosity, lubrication,
                             oil=(oil, temperature, viscosity_index, viscosity_100), bath=(oil_level, drag_loss_factor))
        return doc, m, b, n
    if any(x is not None for x in (oil, temperature, viscosity_index, viscosity_100, oil_level, drag_loss_factor)):
        raise InputError("oil: --oil, --temperature, --viscosity-index, --viscosity-100, --oil-level and "
                         "--drag-loss-factor go with --model skf")
    if series is not None:
        raise InputError("series: only the skf model takes --series (SKF's geometry constants)")
    b = _friction_bearing(
        resolved,
        bearing,
        bearing_file,
        catalog,
        bearing_type,
        contact_angle,
        bore,
        outside_diameter,
        mean_diameter,
        static_load_rating,
    )
    if b.type not in ("radial", "angular"):  # the handbook constants are for these two types only
        raise InputError(f"model: the {model} model's handbook constants are for deep-groove and angular-contact "
                         f"bearings; {b.designation!r} is a {b.type} bearing: give --model skf")
    fr, fa, n = _cases(radial_load, axial_load, speed)
    _check_speed(b, n)
    angle = b.contact_angle if b.type == "angular" else None
    if b.type == "angular" and angle is None and (x0 is None or y0 is None):
        raise InputError(
            "contact-angle: an angular-contact bearing needs --contact-angle (or --x0 and --y0)"
        )
    kw = {"bearing_type": b.type, "contact_angle": angle, "radial_factor": x0, "axial_factor": y0}
    p0 = np.atleast_1d(friction.equivalent_static_load(fr, fa, **kw))
    combined = np.atleast_1d(friction.combined_branch_governs(fr, fa, **kw))
    x0_used, y0_used = x0, y0
    if x0 is None or y0 is None:
        x_tab, y_tab = friction.static_load_factors(b.type, angle)
        x0_used = float(x_tab) if x0 is None else x0
        y0_used = float(y_tab) if y0 is None else y0
    info = {"bearing": b.designation, "type": b.type, "model": model, "x0": x0_used, "y0": y0_used}
    notes = _static_warnings(b, p0)
    if model == "one-term":
        speed_term, load_term = _one_term(b, p0, mu, info)
    else:
        speed_term, load_term = _two_term(b, model, angle, p0, n, f, c, f0, viscosity, palmgren_f0, info)
    total = speed_term + load_term
    rpm = tables.significant(n / RPM)  # a converted input shown without round-trip noise
    cases = [
        {
            "radial_load_N": float(fr[i]),
            "axial_load_N": float(fa[i]),
            "speed_rpm": float(rpm[i]),
            "equivalent_static_load_N": float(p0[i]),
            "branch": "x0*Fr+y0*Fa" if combined[i] else "Fr",
            "torque_Nmm": float(total[i] * 1e3),
            "torque_speed_term_Nmm": float(speed_term[i] * 1e3),
            "torque_load_term_Nmm": float(load_term[i] * 1e3),
        }
        for i in range(p0.size)
    ]
    echo = {"inputs": _echo(b, fr, fa, n, model=model, mu=mu, x0=x0, y0=y0, f=f, c=c, f0=f0,
                            viscosity_cSt=None if viscosity is None else _viscosity_cst(viscosity),
                            palmgren_f0=palmgren_f0), "warnings": notes}
    doc = {**info, **cases[0], **echo} if len(cases) == 1 else {**info, "cases": cases, **echo}
    return doc, None, b, n


def _friction_bearing(
    resolved,
    bearing,
    bearing_file,
    catalog,
    bearing_type,
    contact_angle,
    bore,
    outside_diameter,
    mean_diameter,
    static_load_rating,
):
    from .. import friction
    from ..bearing import BallBearing
    from ..units import parse_quantity
    if bearing or bearing_file:
        base = inp.resolve_bearing(bearing, bearing_file, catalog, contact_angle=contact_angle)
        resolved.append(base)  # its provenance notes go with the document
    else:
        if bearing_type is None and bore is None:
            raise InputError(
                "bearing: give --bearing NAME (e.g. 101), --bearing-file FILE, or --type, --bore, "
                "--mean-diameter/--outside-diameter and --static-load-rating"
            )
        base = BallBearing(
            designation="inline",
            type=bearing_type or "radial",
            contact_angle=None
            if contact_angle is None
            else parse_quantity(contact_angle, "angle", "contact-angle"),
        )
    changes = {}
    if bearing_type is not None:
        if bearing_type not in friction.BEARING_TYPES:
            raise InputError(
                f"type must be one of {list(friction.BEARING_TYPES)}, got {bearing_type!r}"
            )
        changes["type"] = bearing_type
    if bore is not None:
        changes["bore"] = inp.parse_length(bore, "bore")
    if static_load_rating is not None:
        c0 = parse_quantity(static_load_rating, "force", "static-load-rating")
        if not c0 > 0:
            raise InputError(f"static-load-rating must be > 0 [N] (C0), got {c0:g} N")
        changes["static_load_rating"] = c0
    if mean_diameter is not None and outside_diameter is not None:
        raise InputError("mean-diameter: give --mean-diameter or --outside-diameter, not both")
    if outside_diameter is not None:
        changes["outside_diameter"] = inp.parse_length(outside_diameter, "outside-diameter")
    if mean_diameter is not None:
        dm = inp.parse_length(mean_diameter, "mean-diameter")
        d = changes.get("bore", base.bore)
        if d is None:
            raise InputError("mean-diameter: needs the bore (--bore) to give the outside diameter")
        if not dm > d:
            raise InputError(
                f"mean-diameter must be > bore [mm], got {dm * 1e3:g} mm with bore {d * 1e3:g} mm"
            )
        changes["outside_diameter"] = 2.0 * dm - d
    return dataclasses.replace(base, **changes) if changes else base


def _case_values(text, kind, name):
    import numpy as np

    from .._bounds import MAX_CASES
    from ..units import parse_values
    values = parse_values(text, kind, name, limit=MAX_CASES)
    if np.any(~(values >= 0)):  # a force: its magnitude (P0 takes |F_r| and |F_a|)
        raise InputError(f"{name} must be >= 0 [N], got {float(values[~(values >= 0)][0]):g} N")
    return values


_CONSTANT_UNITS = {"mu": "-", "x0": "-", "y0": "-", "f": "-", "c": "-", "f0": "N·mm⁻²·min^(2/3)", "palmgren_f0": "-"}


def _check_constants(**constants):
    """The handbook constants given: finite, and >= 0 but for the exponent c (the message names the option,
    not the library's parameter)."""
    import math

    for name, value in constants.items():
        if value is None:
            continue
        if not math.isfinite(value) or (name != "c" and value < 0):
            rule = "a finite number" if name == "c" else "a finite number >= 0"
            raise InputError(f"{name.replace('_', '-')} must be {rule} [{_CONSTANT_UNITS[name]}], got {value!r}")


def _check_speed(b, n):
    """The speed guard (d_m n), with the pitch diameter or the handbook's mean diameter, where known."""
    from .. import limits

    if inp.speed_size(b) is not None:
        limits.check_speed(n, inp.speed_size(b))


def _static_warnings(b, p0):
    """P0 of ISO 76 against C0 (bearinglab.limits), where the bearing has a static rating."""
    from .. import limits

    c0 = b.static_load_rating
    if c0 is None:
        try:
            from .. import ratings

            c0 = ratings.bearing_ratings(b).static_load_rating
        except (ValueError, ArithmeticError):  # no ball set to compute C0 from
            return []
    return limits.static_load_warnings(p0, c0)


def _viscosity_cst(text):
    return parse_viscosity(text) * 1e6


def _echo(b, fr, fa, n, **options):
    """The inputs as used (:func:`inputs_echo`): the bearing, the loads and speeds, the model's options."""
    from ..units import RPM

    one = fr.size == 1
    def value(x, scale=1.0):
        return float(x[0]) * scale if one else [v * scale for v in x.tolist()]

    return inp.inputs_echo(b, radial_load_N=value(fr), axial_load_N=value(fa), speed_rpm=value(n, 1.0 / RPM),
                       **{k: v for k, v in options.items() if v is not None})


def _skf_bearing(b, series):
    """The bearing with its SKF series checked: the --series given, else the bearing's own, else the one
    its designation spells (:func:`bearinglab.friction.bearing_series`). An empty series is an error,
    never taken as 'not given'."""
    from .. import friction

    if b.type == "self-aligning":  # SKF's constants by self-aligning series (table 3b)
        value = series if series is not None else b.series
        known = list(friction.SELF_ALIGNING_CONSTANTS)
        if value is None or value.strip() not in known:
            raise InputError(f"series must be one of {known} (SKF's self-aligning series) for {b.designation!r}, "
                             f"got {value!r}")
        return dataclasses.replace(b, series=value.strip())
    if b.type not in ("radial", "double-row-radial"):  # SKF's constants of the type (single row: 40 deg)
        if series is not None:
            raise InputError(f"series: --series names SKF's deep-groove series; {b.designation!r} is {b.type}, "
                             f"whose constants are SKF's for its type")
        design = friction.SKF_BEARING_TYPES[b.type][0]
        if design not in ("thrust",):
            try:  # the model, not a field, is what does not apply (the web page leaves the section out)
                friction.angular_contact_constants(b.contact_angle, design=design)
            except InputError as exc:
                raise InputError(f"model: {exc}") from None
        return b
    known = list(friction.DEEP_GROOVE_CONSTANTS)
    for name, value in (("series", series), (f"series of {b.designation!r}", b.series)):
        if value is not None:
            if value.strip().upper() not in known:
                raise InputError(f"{name} must be one of {known} (SKF's deep-groove series), got {value!r}")
            return dataclasses.replace(b, series=value.strip().upper())
    try:
        friction.bearing_series(b.designation)
    except InputError as exc:
        raise InputError(f"series: {exc} (--series, e.g. --series 62)") from None
    return b


def _skf_torque(b, fr, fa, n, viscosity, lubrication, oil=(None,) * 4, bath=(None, None)):
    """The SKF four-term model (:func:`bearinglab.friction.skf_for_bearing`): the document and the result
    (moments, power loss, mu_sl)."""
    from .. import friction, tables
    from ..units import RPM
    if viscosity is None and oil[0] is None:
        raise InputError("viscosity: the skf model needs --viscosity (e.g. '30 cSt'; of the base oil for grease), "
                         "or --oil VG68 with --temperature")
    nu = lubricant_viscosity(viscosity, *oil, required=True).viscosity
    kw = {}
    if lubrication == "oil-bath":
        if bath[0] is None:
            raise InputError("oil-level: --lubrication oil-bath needs --oil-level (e.g. '5 mm'); V_M follows from "
                             "SKF's diagram at H/d_m (--drag-loss-factor overrides it)")
        h = inp.parse_length(bath[0], "oil-level", zero=True)
        dm = b.mean_diameter
        if h > dm / 2:
            raise InputError(f"oil-level must be <= d_m/2 = {dm / 2 * 1e3:g} mm [mm] (at most up to the bearing's "
                             f"centre), got {h * 1e3:g} mm")
        if bath[1] is not None and not 0.0 <= bath[1] <= 1.0:
            raise InputError(f"drag-loss-factor must be in [0, 1] [-] (V_M of SKF's diagram), got {bath[1]:g}")
        kw = {"oil_level": h, "drag_loss_factor": bath[1]}
    elif bath[0] is not None or bath[1] is not None:
        raise InputError("oil-level: --oil-level and --drag-loss-factor go with --lubrication oil-bath")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the result returns its warnings (a seal moment left out)
        m = friction.skf_for_bearing(b, fr, fa, n, nu, lubrication=lubrication, **kw)  # checks the lubrication
    notes = [*m.warnings, *_skf_warnings(b, fr, fa)]
    moments = tables.rows(tables.skf_torque(m))
    rpm = tables.significant(n / RPM)
    cases = [{"radial_load_N": float(fr[i]), "axial_load_N": float(fa[i]), "speed_rpm": float(rpm[i]), **moments[i]}
             for i in range(len(moments))]
    info = {"bearing": b.designation, "type": b.type, "model": "skf", "lubrication": lubrication,
            "viscosity_cSt": float(tables.significant(nu * 1e6)[0])}
    if m.drag_loss_factor is not None:  # the oil bath's V_M: given, or SKF's diagram at H/d_m
        info.update(oil_level_mm=kw["oil_level"] * 1e3, drag_loss_factor=float(m.drag_loss_factor),
                    drag_loss_factor_source="given" if bath[1] is not None else
                    "SKF's diagram at H/d_m (ball bearings; bearinglab.friction.drag)")
    echo = {"inputs": _echo(b, fr, fa, n, model="skf", lubrication=lubrication, viscosity_cSt=nu * 1e6),
            "warnings": notes}
    doc = {**info, **cases[0], **echo} if len(cases) == 1 else {**info, "cases": cases, **echo}
    return doc, m


def _skf_warnings(b, fr, fa):
    """P0 of ISO 76 (from F_r, F_a) against C0, where the bearing has its ratings."""
    from .. import ratings

    try:
        angle = b.contact_angle or 0.0
        p0 = ratings.static_equivalent_load(fr, fa, angle, bearing_type=b.type)
    except (ValueError, ArithmeticError):  # an angle outside ISO 76's table: no P0
        return []
    return _static_warnings(b, p0)


def _cases(radial_load, axial_load, speed):
    """The radial loads, axial loads and speeds (SI), broadcast to one length."""
    import numpy as np
    fr = _case_values(radial_load, "force", "radial-load")
    fa = _case_values(axial_load, "force", "axial-load")
    n = inp.parse_speeds(speed)
    sizes = {v.size for v in (fr, fa, n) if v.size > 1}
    if len(sizes) > 1:
        from .fields import RunFailure

        raise RunFailure("radial_load", None, "{name}, axial-load, speed: lists are paired "
                         "element by element (rows of a log) and must have the same length, or one value")
    return np.broadcast_arrays(fr, fa, n)


def _one_term(b, p0, mu, info):
    """Speed and load terms of the one-term model (the whole torque is the load term)."""
    import numpy as np

    from .. import friction
    d = b.require("bore")
    mu_used = friction.handbook_friction_coefficient(b.type) if mu is None else mu
    total = np.atleast_1d(friction.one_term(p0, d, bearing_type=b.type, reduced_friction_coefficient=mu))
    info.update({"mu": mu_used, "bore_mm": d * 1e3})
    return np.zeros_like(total), total  # one term, proportional to the load


def _two_term(b, model, angle, p0, n, f, c, f0, viscosity, palmgren_f0, info):
    """Speed and load terms of the two-term and the Palmgren model; the constants used go to ``info``."""
    import numpy as np

    from .. import friction
    dm = b.mean_diameter
    c0 = b.require("static_load_rating")
    f_used, c_used = f, c
    if f is None or c is None:
        f_tab, c_tab = friction.load_term_constants(b.type, angle)
        f_used = float(f_tab) if f is None else f
        c_used = float(c_tab) if c is None else c
    load_term = np.atleast_1d(
        friction.load_term(
            p0,
            dm,
            c0,
            bearing_type=b.type,
            contact_angle=angle,
            load_term_factor=f_used,
            load_term_exponent=c_used,
        )
    )
    if model == "two-term":
        if f0 is None:
            raise InputError(
                "f0: the two-term model needs --f0 [N·mm⁻²·min^(2/3)], e.g. 2e-7; it has no handbook "
                "value (measure it with `bearinglab friction lab`, task 2)"
            )
        speed_term = np.atleast_1d(friction.speed_term(n, dm, f0))
        info["f0"] = f0
    else:
        if viscosity is None or palmgren_f0 is None:
            raise InputError(
                "viscosity: the palmgren model needs --viscosity (e.g. '20 cSt') and --palmgren-f0 "
                "(e.g. 2)"
            )
        nu = parse_viscosity(viscosity)
        speed_term = np.atleast_1d(friction.palmgren(nu, n, dm, palmgren_f0))
        info.update(
            {
                "viscosity_cSt": nu * 1e6,
                "palmgren_f0": palmgren_f0,
                "equivalent_f0": float(
                    friction.speed_term_factor_from_palmgren(palmgren_f0, nu)
                ),
            }
        )
    info.update(
        {"f": f_used, "c": c_used, "mean_diameter_mm": dm * 1e3, "static_load_rating_N": c0}
    )
    return speed_term, load_term




def _with_operating_clearance(doc, parsed, bearing, speeds):
    """The document with the operating clearance of the mounting inputs (issue 23), where given: the
    entries of :func:`bearinglab.calculations._mounting.operating_clearance` (at the highest speed) before
    ``inputs``, and a warning that the friction model does not depend on it. None of the four takes the
    clearance: the handbook models take P0 of ISO 76 from the loads (and the tabulated x0, y0 of the
    nominal angle), SKF's the loads, d_m and its series constants."""
    from . import _mounting

    given = {k: parsed.given.get(k) for k in _mounting.NAMES}
    if not any(v is not None for v in given.values()):
        return doc
    mounted = _mounting.operating_clearance(bearing, given, float(max(speeds)))
    note = (f"operating clearance: the {doc['model']} friction model does not depend on the clearance; "
            f"operating_clearance_um is reported, the torque is the same without the mounting inputs")
    head = {k: v for k, v in doc.items() if k not in ("inputs", "warnings")}
    preloaded, pre_note = _preloaded(bearing, mounted["operating_clearance_um"] * 1e-6, doc["model"])
    notes = [*doc.get("warnings", []), *([pre_note] if pre_note else []), note]
    return {**head, **mounted, **preloaded, "inputs": doc["inputs"], "warnings": notes}


def _preloaded(bearing, clearance, model):
    """Issue 30: the preload of a negative operating clearance (:mod:`._preload`), which the friction
    models leave out; without the bearing's ball set, the warning without its numbers."""
    from ..errors import InputError as _InputError
    from . import _preload

    if not clearance <= 0:
        return {}, None
    what = f"{model} friction model"
    try:
        return _preload.report(bearing.replace(radial_clearance=clearance),
                               source="the operating clearance from the fits and temperatures", model=what)
    except _InputError:  # no ball set (a handbook bearing given by its envelope)
        return {}, (f"the operating clearance from the fits and temperatures is {clearance * 1e6:.3g} um: the "
                    f"bearing runs preloaded (its ball loads need the ball set, which is not known here); the "
                    f"{what} takes the external loads only and leaves the preload's ball loads out")
