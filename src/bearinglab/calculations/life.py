"""The rating life (issue 12) as a calculation: the document of ``bearinglab life --json``.

ISO 281 and ISO/TS 16281 lives of a bearing under (F_x, F_y, F_z, M_x, M_y) at a speed
(:func:`bearinglab.life.rating_life`; the ball loads of the reference life from the combined-load
model), or of a duty cycle (:func:`bearinglab.life.duty_cycle_life`). The columns are
:func:`bearinglab.tables.rating_life`. Where ISO 281's P is not defined (under a moment) its fields
are null and a warning says why; the ISO/TS 16281 fields are still given. The command line
(:mod:`bearinglab.cli.life`) and the web compute the same document with :func:`document`.

Duty cycle (the field ``duty_cycle``: TOML, or the same tables as JSON; the time shares sum to 1; at most
:data:`bearinglab._bounds.MAX_DUTY_CYCLE_STEPS` steps, 10 000, on the command line and the web alike)::

    [[step]]
    fx = "2 kN"          # any of fx, fy, fz, mx, my (radial_load = fx, axial_load = fz)
    fz = "500 N"
    speed = "3000 rpm"
    time = 0.6

Functions
---------
document   Parsed -> the document (one case, or the duty cycle's combined life and its steps)
"""

from __future__ import annotations

import json
import warnings

from ..errors import InputError
from ._failures import failures
from ._finite import finite
from ._inputs import (
    default_lubrication,
    five_loads,
    inputs_echo,
    lubricant_viscosity,
    parse_speed,
    parse_speeds,
    resolve_bearing,
    speed_size,
)
from ._request import given_text, with_notes

__all__ = ["document"]

# the keys of bearinglab.ratings.CONTAMINATION_CLASSES, spelled out for the help text (the help is built
# without importing the model; tests/cli/test_cli_startup.py checks that the two agree)
_CONTAMINATION_CLASSES = ("extreme_cleanliness", "high_cleanliness", "normal_cleanliness", "slight_contamination",
                          "typical_contamination", "severe_contamination", "very_severe_contamination")
_CONTAMINATION = {k.split("_")[0] if k != "very_severe_contamination" else "very-severe": k
                  for k in _CONTAMINATION_CLASSES}

# Said whenever the user gave no cleanliness: e_C = 1 is the laboratory's extreme cleanliness of ISO 281
# table 13, and with a good lubricant it drives a_ISO to its limit of 50; service conditions are dirtier.
_CLEANLINESS_ASSUMED = ("contamination: none given, so e_C = 1 (extreme cleanliness, ISO 281 table 13) is used "
                        "for a_ISO and L_nm; give --contamination (e.g. normal) or --contamination-factor for "
                        "the bearing's service")
_GEOMETRY = ("ball_diameter", "pitch_diameter", "inner_groove_radius", "outer_groove_radius")
_LOADS = ("fx", "fy", "fz", "mx", "my", "radial_load", "axial_load")
_MOUNTING = ("shaft_fit", "housing_fit", "shaft_interference", "housing_interference", "shaft_bore",
             "housing_outside_diameter", "shaft_material", "housing_material", "tolerance_class",
             "clearance_class", "inner_ring_temperature", "outer_ring_temperature", "ball_temperature",
             "shaft_temperature", "housing_temperature")
#: where a posted duty cycle is named in messages (the command line names its file instead)
POSTED = "the posted document"


@finite('life')
def document(parsed, *, catalog=None, bearing_file=None, duty_cycle_source=POSTED):
    """The document of ``bearinglab life ... --json`` for a checked request.

    Parameters
    ----------
    parsed : Parsed
        A request of the calculation ``life`` (:func:`bearinglab.calculations.parse`).
    catalog, bearing_file : str or Path, optional
        The command line's user catalog and bearing file (the web takes neither).
    duty_cycle_source : str
        How messages name the duty cycle's text: its file on the command line.

    Returns
    -------
    dict
        The JSON document: the ratings, lives, factors, ``inputs`` and ``warnings`` (the bearing's
        provenance notes last).

    Raises
    ------
    RunFailure
        An input the calculation refuses, naming its field.
    """
    from .. import catalog as _catalog
    from .. import tables
    from . import _rollers

    v = parsed.values

    def text(name):
        return given_text(parsed, name)

    with failures(parsed):
        b = _rollers.bearing_of(parsed, bearing_file=bearing_file, catalog=catalog, only=("tilt_x", "tilt_y")) or \
            resolve_bearing(text("bearing"), bearing_file, catalog, v.get("balls"), *map(text, _GEOMETRY),
                            v.get("inner_conformity"), v.get("outer_conformity"),
                            text("contact_angle"), text("radial_clearance"), text("ball_material"))
        notes = [] if _rollers.is_roller(b) else _catalog.provenance_notes(b)
        auto = (text("temperature") or "").lower() == "auto"
        thermal = {k: text(k) for k in _THERMAL}
        if auto:  # the viscosity of the steady temperature, once the loads and speed are known
            lube = None  # known after the thermal balance
            if "duty_cycle" in parsed.given:
                raise InputError("temperature: 'auto' takes the loads and speed of one case, not a duty cycle; "
                                 "give the temperature")
        elif any(thermal.values()):
            raise InputError("temperature: --ambient, --thermal-resistance, --lubrication and --skf-constants "
                             "go with --temperature auto (the thermal balance)")
        else:
            lube = lubricant_viscosity(text("viscosity"), text("oil"), text("temperature"),
                                       v.get("viscosity_index"), text("viscosity_100"))
        options = {"kinematic_viscosity": None if lube is None else lube.viscosity,
                   "contamination": _cleanliness(v.get("contamination_factor"), text("contamination")),
                   "reliability": _reliability(float(v.get("reliability", 90.0)))}
        no_cleanliness = v.get("contamination_factor") is None and "contamination" not in parsed.given
        assumed = [] if auto else _assumed(lube, no_cleanliness)
        mounting = {k: text(k) for k in _MOUNTING}
        if "duty_cycle" in parsed.given:
            if any(k in parsed.given for k in (*_LOADS, "speed")):
                raise InputError("duty-cycle: the loads and speeds are in the duty cycle; give no --fx ... "
                                 "--speed")
            b, _ = _rollers.operating(b, 0.0, mounting)  # no single speed for the centrifugal
            steps = _duty_cycle(str(parsed.given["duty_cycle"]), duty_cycle_source, b)
        elif "speed" not in parsed.given:
            raise InputError("speed: missing; give the inner-ring speed, e.g. '3000 rpm' (or --duty-cycle)")
        else:  # one speed, or a list like film's: one document per speed (issue 30)
            speeds = parse_speeds(text("speed"), pitch_diameter=speed_size(b), zero=False)
            loads = five_loads(*map(text, _LOADS))
            runs = []
            for n in map(float, speeds):
                b_n, mounted = _rollers.operating(b, n, mounting)  # issue 23: the operating clearance
                run = {"bearing": b_n, "speed": n, "mounted": mounted, "lube": lube, "assumed": assumed,
                       "options": dict(options)}
                if auto:
                    run["lube"], run["temperature"], notes_auto = _auto_viscosity(b_n, loads, n, text, v, thermal)
                    run["options"]["kinematic_viscosity"] = run["lube"].viscosity
                    run["assumed"] = [*_assumed(run["lube"], no_cleanliness), *notes_auto]
                runs.append(run)
    if _rollers.is_roller(b):  # ISO 281 of roller bearings, ISO/TS 16281 over the laminae (issue 32)
        with failures(parsed):
            if "duty_cycle" in parsed.given:
                return json.loads(tables.json_text(_roller_life(parsed, b, options, lube, assumed, steps=steps)))
            docs = [json.loads(tables.json_text(_roller_life(
                parsed, run["bearing"], run["options"], run["lube"], run["assumed"], loads=loads, speed=run["speed"],
                mounted=run["mounted"], temperature=run.get("temperature")))) for run in runs]
        return docs[0] if len(docs) == 1 else docs
    if "duty_cycle" in parsed.given:
        return json.loads(tables.json_text(with_notes(_life_of_duty_cycle(b, *steps, options, lube, assumed), notes)))
    docs = []
    for run in runs:
        doc = _life(run["bearing"], loads, run["speed"], run["options"], run["lube"], run["assumed"], run["mounted"],
                    text("radial_clearance"))
        if auto:  # the steady temperature, after the viscosity it gives
            items = list(doc.items())
            at = list(doc).index("viscosity_mm2_s") + 1
            doc = dict([*items[:at], ("bearing_temperature_degC", run["temperature"]), *items[at:]])
        docs.append(json.loads(tables.json_text(with_notes(doc, notes))))
    return docs[0] if len(docs) == 1 else docs


_THERMAL = ("ambient", "thermal_resistance", "lubrication", "skf_constants")


def _auto_viscosity(b, loads, n, text, values, thermal):
    """Temperature ``auto``: the thermal balance of the case
    (:func:`bearinglab.calculations.temperature.steady_temperature`, the path of ``film``'s ``auto``) and
    the oil's viscosity at its temperature, as the lubricant; (lubricant, temperature [degC], notes)."""
    from ._inputs import LubricantViscosity
    from .temperature import steady_temperature

    r, how, inputs, notes = steady_temperature(b, loads, n, text("oil"), text("viscosity"),
                                               values.get("viscosity_index"), text("viscosity_100"),
                                               thermal["ambient"], thermal["thermal_resistance"],
                                               default_lubrication(thermal["lubrication"], text("oil")),
                                               thermal["skf_constants"])
    t, nu = float(r.temperature) - 273.15, float(r.kinematic_viscosity)
    inputs = {k: x for k, x in inputs.items() if k not in ("bearing_temperature_degC", "max_temperature_degC")}
    description = f"{how} at the steady temperature {t:.1f} degC (thermal balance): nu = {nu * 1e6:.4g} cSt"
    return LubricantViscosity(nu, description, {**inputs, "bearing_temperature_degC": t}), t, [
        *notes, *(f"thermal balance: {w}" for w in r.warnings)]


def _life(b, loads, n, options, lube, assumed, mounted, clearance_text=None):
    import numpy as np

    from .. import tables
    from ..life import rating_life
    from ..units import RPM
    from . import _preload
    from .load_distribution import clearance_source

    dist = _distribution(b, loads)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the analysis returns its warnings
        r = rating_life(b, loads, n, **options, load_distribution=dist)
    doc = {**tables.rows(tables.rating_life(r))[0], "contamination_factor": r.contamination_factor,
           "rating_source": r.rating_source,
           "inputs": _echo(b, options, lube, fx_N=loads[0], fy_N=loads[1], fz_N=loads[2], mx_Nmm=loads[3] * 1e3,
                           my_Nmm=loads[4] * 1e3, speed_rpm=n / RPM),
           "warnings": assumed + _diameter_note(r) + _notes(b, loads, r.warnings, dist) + _unbounded(r)}
    preloaded, note = _preload.report(b, loads if dist is not None and bool(np.all(dist.converged)) else None,
                                      n, source=clearance_source(mounted, clearance_text))
    if note:  # the preload's ball loads are in L10r (the load distribution); ISO 281's L10 takes F_r, F_a only
        doc["warnings"] = [note + "; L10r counts the preload's ball loads, L10 of ISO 281 does not", *doc["warnings"]]
    return {**{k: doc[k] for k in _KEYS}, **mounted, **preloaded}  # e_C null without a_ISO (no lubricant)


def _cleanliness(factor, name):
    if factor is not None and name is not None:
        raise InputError("contamination: give --contamination-factor or --contamination, not both")
    if name is not None:
        key = name.strip().lower().replace("_", "-")
        if key not in _CONTAMINATION:
            raise InputError(f"contamination must be one of {list(_CONTAMINATION)}, got {name!r}")
        return _CONTAMINATION[key]
    if factor is not None and not 0.0 <= factor <= 1.0:
        raise InputError(f"contamination-factor must be in [0, 1] [-] (e_C of ISO 281 table 13), got {factor:g}")
    return 1.0 if factor is None else factor


def _reliability(percent):
    if not 90.0 <= percent <= 99.95:
        raise InputError(f"reliability must be in [90, 99.95] [%], got {percent:g}")
    return percent / 100.0


# the roller bearings (issue 32): ISO 281 of roller bearings, ISO/TS 16281 over the laminae of the slice model
def _misalignment(parsed, loads):
    """(theta_x, theta_y) [rad] of the request (None where not given); a moment and a tilt about one axis
    refused together."""
    import numpy as np

    from ..units import parse_quantity

    out = []
    for axis, moment in (("x", 3), ("y", 4)):
        text = given_text(parsed, f"tilt_{axis}")
        if text is None:
            out.append(None)
            continue
        if np.any(np.asarray(loads, dtype=float)[..., moment] != 0):
            raise InputError(f"tilt-{axis}: give --m{axis} or --tilt-{axis}, not both (the ring takes a moment or a "
                             "tilt about one axis)")
        tilt = parse_quantity(text, "angle", f"tilt-{axis}")
        if not abs(tilt) < 0.05:
            raise InputError(f"tilt-{axis} must be in (-50, 50) [mrad] (a misalignment), got {tilt * 1e3:g} mrad")
        out.append(tilt)
    return tuple(out)


def _lamina_loads(bearing, loads, n_slices, tilt=(None, None)):
    """The lamina loads of the ISO/TS 16281 reference life for a batch of load cases, the results' warnings and
    the largest lamina pressure of each case; (None, notes, None) where there is no slice model (a spherical
    bearing, a bearing without the data to estimate its roller set: the life analysis then says why).

    The ring is held square where a case has no moment (ISO 281's load case: the other bearing holds the
    shaft), free to tilt under a moment, held at ``tilt`` about an axis where given (a misalignment); a single
    tapered bearing needs a thrust F_z > F_r tan(alpha) (its cases without one have no reference life).
    """
    import math

    import numpy as np

    from ..life.roller import reference_slice_loads
    from ._rollers import geometry_of

    if bearing.type == "spherical":
        return None, [], None
    try:
        geo = geometry_of(bearing)
    except InputError:
        return None, [], None
    flat = np.asarray(loads, dtype=float).reshape(-1, 5)
    moment = np.hypot(flat[:, 3], flat[:, 4]) > 0
    held = np.where(moment[:, None], np.nan, np.array([np.nan, np.nan, np.nan, 0.0, 0.0]))
    for k, t in enumerate(tilt):
        if t is not None:
            held[:, 3 + k] = t
    ok = np.ones(len(flat), dtype=bool)
    notes = []
    if geo.type == "tapered":
        ok = flat[:, 2] > np.hypot(flat[:, 0], flat[:, 1]) * math.tan(geo.contact_angle)
        if not ok.all():
            notes.append(f"{int((~ok).sum())} of {ok.size} load cases give a single tapered bearing less thrust than "
                         "F_r tan(alpha), which no equilibrium of the bearing alone holds: their ISO/TS 16281 "
                         "reference lives are not defined (give the thrust of the mounting, or solve the pair with "
                         "bearing-set)")
    if not ok.any():  # the life analysis says why there is no reference life
        return None, [], None
    q = np.full((len(flat), geo.rollers, n_slices), np.nan)
    pressure = np.full(len(flat), np.nan)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        r = reference_slice_loads(geo, flat[ok], n_slices=n_slices, prescribed_displacement=held[ok])
    q[ok] = r.slice_load
    pressure[ok] = np.max(np.reshape(r.max_pressure, (-1, geo.rollers)), axis=-1)
    notes += [*r.warnings, *(str(c.message) for c in caught)]
    shape = np.shape(loads)[:-1]
    return q.reshape(shape + q.shape[1:]), list(dict.fromkeys(notes)), pressure.reshape(shape)


def _roller_life(parsed, bearing, options, lube, assumed, *, loads=None, speed=None, mounted=None, steps=None,
         temperature=None):
    """The document of ``life`` for a roller bearing: one case, or a duty cycle (``steps``).

    Parameters
    ----------
    parsed : Parsed
        The request (its ``tilt_x``, ``tilt_y`` and ``slices``).
    bearing : RollerBearing
        At its operating clearance.
    options : dict
        ``kinematic_viscosity``, ``contamination``, ``reliability`` of :func:`bearinglab.life.rating_life`.
    lube : LubricantViscosity
        The lubricant as read.
    assumed : list of str
        The notes on what was assumed (no lubricant, the cleanliness).
    loads, speed : optional
        One case: (F_x, F_y, F_z, M_x, M_y) [N, N m] and the speed [rad/s].
    mounted : dict, optional
        The mounting entries of the case.
    steps : tuple, optional
        A duty cycle: loads (k, 5), speeds (k,), time shares (k,).
    temperature : float, optional
        The steady temperature of temperature ``auto`` [degC], shown after the viscosity.

    Returns
    -------
    dict
        The keys of the ball bearing's document (:mod:`.life`), with ``slices``, the misalignment in ``inputs``
        and ``max_pressure_MPa`` (the slice model's largest lamina pressure).
    """
    import numpy as np

    from .. import tables
    from ..life import duty_cycle_life, rating_life
    from ..units import RPM
    from ._rollers import geometry_of, notes_of, pressure_warnings, slices_of

    n_slices = slices_of(parsed)
    if bearing.type != "spherical":  # the roller set of the reference life, estimated (labelled) where missing
        try:
            bearing = geometry_of(bearing)
        except InputError:  # the ISO 281 lives need none; the analysis says why there is no reference life
            pass
    f = np.asarray(loads if steps is None else steps[0], dtype=float)
    tilt = _misalignment(parsed, f)
    q, model_notes, pressure = _lamina_loads(bearing, f, n_slices, tilt)
    extra = {"slices": n_slices}
    for axis, t in zip("xy", tilt, strict=True):
        if t is not None:
            extra[f"tilt_{axis}_mrad"] = t * 1e3
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the analysis returns its warnings
        if steps is None:
            r = rating_life(bearing, f, speed, **options, load_distribution=q)
        else:
            d = duty_cycle_life(bearing, *steps, **options, load_distribution=q)
            r = d.steps
    notes = [*assumed, *_diameter_note(r), *r.warnings, *model_notes]
    if any("less thrust than F_r tan(alpha)" in n for n in notes):  # why, not its consequence once more
        notes = [n for n in notes if "have no lamina loads (the slice model found no equilibrium)" not in n]
    if any(t is not None for t in tilt) and bearing.type == "spherical":
        notes.append("tilt: a spherical roller bearing aligns itself; ISO 281's lives do not depend on a tilt")
    if pressure is not None:
        notes += pressure_warnings(pressure)
    top = None if pressure is None or not np.any(np.isfinite(pressure)) else float(np.nanmax(pressure)) / 1e6
    if steps is None:
        doc = {**tables.rows(tables.rating_life(r))[0], "contamination_factor": r.contamination_factor,
               "rating_source": r.rating_source,
               "inputs": _echo(bearing, options, lube, fx_N=f[0], fy_N=f[1], fz_N=f[2], mx_Nmm=f[3] * 1e3,
                               my_Nmm=f[4] * 1e3, speed_rpm=speed / RPM, **extra),
               "warnings": [*notes, *_unbounded(r)]}
        doc = {**{k: doc[k] for k in _KEYS if k not in ("inputs", "warnings")}, "max_pressure_MPa": top,
               **(mounted or {}), "inputs": doc["inputs"], "warnings": doc["warnings"]}
        if temperature is not None:
            items = list(doc.items())
            at = list(doc).index("viscosity_mm2_s") + 1
            doc = dict([*items[:at], ("bearing_temperature_degC", temperature), *items[at:]])
    else:
        loads_k, speeds, times = steps
        hours = 2 * np.pi / d.mean_speed / 3600.0

        def scaled(x, factor):
            return None if x is None else x * factor

        doc = {**tables.ratings(d.steps), "reliability_factor": d.steps.reliability_factor,
               **({} if d.steps.contamination_factor is None else
                  {"contamination_factor": d.steps.contamination_factor}),
               "basic_rating_life_Mrev": d.basic_rating_life * 1e-6, "basic_rating_life_h": d.basic_rating_life * hours,
               "modified_rating_life_Mrev": scaled(d.modified_rating_life, 1e-6),
               "modified_rating_life_h": scaled(d.modified_rating_life, hours),
               "reference_rating_life_Mrev": d.reference_rating_life * 1e-6,
               "modified_reference_rating_life_Mrev": scaled(d.modified_reference_rating_life, 1e-6),
               "mean_speed_rpm": d.mean_speed / RPM, "max_pressure_MPa": top,
               "steps": tables.rows(tables.rating_life(d.steps)),
               "inputs": _echo(bearing, options, lube, **extra,
                               steps=[{"fx_N": x[0], "fy_N": x[1], "fz_N": x[2], "mx_Nmm": x[3] * 1e3,
                                       "my_Nmm": x[4] * 1e3, "speed_rpm": w / RPM, "time": t}
                                      for x, w, t in zip(loads_k.tolist(), speeds.tolist(), times.tolist())]),
               "warnings": [*notes, *_unbounded(d)]}
    doc["warnings"] = list(dict.fromkeys([*doc["warnings"], *notes_of(bearing)]))
    return tables.json_value(doc)


def _steps_of(text, source):
    """The ``[[step]]`` tables of a duty cycle given as TOML or JSON text; their number is checked
    (:data:`bearinglab._bounds.MAX_DUTY_CYCLE_STEPS`) before any step is read."""
    import re
    import tomllib

    from .._bounds import check_steps, parse_document

    # each [[step]] header is one step: a file with too many is refused before it is parsed (a 16 MB file
    # takes seconds to parse); the parsed count is checked below, whatever the syntax
    check_steps(len(re.findall(r"(?m)^[ \t]*\[\[[ \t]*step[ \t]*\]\]", text)), f"duty-cycle: {source}")
    try:  # a repeated JSON key and a document nested too deeply are refused too
        doc = parse_document(text, source)
    except InputError as exc:
        raise InputError(f"duty-cycle: {exc}") from None
    except (ValueError, tomllib.TOMLDecodeError) as exc:
        raise InputError(f"duty-cycle: {source}: {exc}") from None
    steps = doc.get("step") if isinstance(doc, dict) else None
    if not isinstance(steps, list) or not steps or not all(isinstance(s, dict) for s in steps):
        raise InputError(f"duty-cycle: {source}: needs [[step]] tables with loads, speed and time")
    check_steps(len(steps), f"duty-cycle: {source}")
    return steps


def _duty_cycle(text, source, bearing):
    """Loads (k, 5), speeds (k,) and time shares (k,) of a duty cycle; each speed by the rule of every
    speed option (:func:`parse_speed`: > 0, one value, within the d_m n guard of ``bearing``)."""
    import numpy as np

    loads, speeds, times = [], [], []
    for k, s in enumerate(_steps_of(text, source), 1):
        unknown = set(s) - {"fx", "fy", "fz", "mx", "my", "radial_load", "axial_load", "speed", "time"}
        if unknown or "speed" not in s or "time" not in s:
            raise InputError(f"duty-cycle: step {k} needs speed and time and takes fx, fy, fz, mx, my; got "
                             f"{sorted(s)}")
        loads.append(five_loads(*(s.get(n) for n in _LOADS)))
        speeds.append(parse_speed(s["speed"], f"duty-cycle step {k} speed", bearing=bearing, zero=False))
        t = s["time"]
        if isinstance(t, bool) or not isinstance(t, (int, float)) or not 0.0 <= t <= 1.0:
            raise InputError(f"duty-cycle step {k} time must be a share in [0, 1] [-] (the shares sum to 1), "
                             f"got {t!r}")
        times.append(float(t))
    return np.array(loads), np.array(speeds), np.array(times)


def _distribution(b, loads):
    """The load distribution of the ISO/TS 16281 reference life
    (:func:`bearinglab.life.reference_load_distribution`), computed here so that the plausibility limits
    see the ball loads. A case without equilibrium is flagged, not raised: the ISO 281 lives do not need
    the distribution. None without the ball set (the reference lives are then NaN, and say why)."""
    from ..life import reference_load_distribution

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the life analysis reports what matters to it
        return reference_load_distribution(b, loads, on_failure="flag")


def _notes(b, loads, rating_notes, dist):
    """The warnings of a life: the analysis's, why the reference lives are missing where the load
    distribution failed, and the plausibility limits of the ball loads (bearinglab.limits; s0 < 1 is
    the analysis's own warning, so the limits do not repeat it)."""

    import numpy as np

    from .. import limits

    notes = list(rating_notes)
    if dist is not None:
        # the model's own warnings (e.g. a thrust the angular-contact bearing cannot carry) qualify the
        # reference lives; its failure notes are replaced by the reason _unavailable gives
        steps = "" if np.reshape(loads, (-1, 5)).shape[0] == 1 else " (case k is duty-cycle step k + 1)"
        notes += [f"load distribution of the reference lives{steps}: {w}" for w in dist.warnings
                  if "not converged" not in w]
        notes += _unavailable(b, loads, dist)
        notes += limits.combined_warnings(b, loads, dist.ball_load_inner, dist.ball_load_outer,
                                          dist.contact_angle_inner, dist.contact_angle_outer, static=False)
    return list(dict.fromkeys(notes))


# the lives and s0 that are infinite without load, by their symbols
_UNBOUNDED = {"basic_rating_life": "L10", "modified_rating_life": "L_nm", "reference_rating_life": "L10r",
              "modified_reference_rating_life": "L_nmr", "static_safety_factor": "s0"}


def _unbounded(result):
    """Why a life or s0 is shown as '—' where it is infinite: no load (P = 0, P0 = 0); a RatingLife or a
    DutyCycleLife (whose combined lives are infinite only when every step is unloaded)."""
    import numpy as np

    names = [symbol for field, symbol in _UNBOUNDED.items()  # None: not computed (no lubricant)
             if getattr(result, field, None) is not None and np.any(np.isposinf(getattr(result, field)))]
    if not names:
        return []
    where = " at every step" if hasattr(result, "steps") else ""
    listed = ", ".join(names[:-1]) + " and " + names[-1] if len(names) > 1 else names[0]
    verb = "are" if len(names) > 1 else "is"
    return [f"P = 0{where}: no equivalent load, so {listed} {verb} unbounded (shown as —, null in --json)"]


def _unavailable(b, loads, dist):
    """Why the reference lives are missing where the load distribution found no equilibrium: the reason of
    the first such case, from its :class:`~bearinglab.errors.ConvergenceError` (that case solved again alone:
    a flagged result keeps no reason per case)."""
    import numpy as np

    from ..errors import ConvergenceError
    from ..life import reference_load_distribution

    failed = np.flatnonzero(~np.ravel(dist.converged))
    if not failed.size:
        return []
    f = np.reshape(loads, (-1, 5))
    where = "" if len(f) == 1 else f" at {failed.size} of {len(f)} steps (first: step {failed[0] + 1})"
    try:
        reference_load_distribution(b, f[failed[0]], on_failure="raise")
        why = "the combined-load model found no equilibrium"
    except ConvergenceError as exc:
        why = exc.summary
    return [f"ISO/TS 16281 reference lives not available{where}: {why}"]


def _echo(b, options, lube, **quantities):
    """The inputs as used (:func:`inputs_echo`): the bearing, the loads and speed, lubricant and cleanliness."""
    c = options["contamination"]
    return inputs_echo(b, **quantities, **lube.inputs, contamination=c,
                       reliability_percent=options["reliability"] * 100)


def _diameter_note(result):
    """Say so where nu1 is not at ISO 281's d_m = (d + D)/2 (bore or outside diameter unknown)."""
    if result.rated_viscosity_diameter_source == "pitch diameter":
        return [("rated viscosity nu1: bore and outside diameter not known, so nu1 is taken at the pitch "
                 "diameter instead of ISO 281's mean diameter d_m = (d + D)/2")]
    return []


def _assumed(lube, no_cleanliness):
    """What was assumed for want of an input: no lubricant (the modified lives are not computed), the oil's
    viscosity index, the cleanliness (only where a lubricant makes it matter)."""
    if lube.viscosity is None:
        return [("lubricant: none given, so a_ISO, L_nm and L_nmr are not computed (null in --json); give "
                 "--viscosity, or --oil (e.g. VG68) with --temperature")]
    notes = [f"viscosity: {lube.description}"] if lube.inputs.get("viscosity_index_assumed") else []
    return notes + ([_CLEANLINESS_ASSUMED] if no_cleanliness else [])


_KEYS = ("dynamic_load_rating_N", "static_load_rating_N", "fatigue_load_limit_N", "rating_source",
         "equivalent_dynamic_load_N", "basic_rating_life_Mrev", "basic_rating_life_h", "reliability_factor",
         "viscosity_mm2_s", "rated_viscosity_mm2_s", "rated_viscosity_diameter_mm", "viscosity_ratio",
         "contamination_factor", "life_modification_factor", "modified_rating_life_Mrev", "modified_rating_life_h",
         "reference_rating_life_Mrev", "modified_reference_rating_life_Mrev", "static_safety_factor", "inputs",
         "warnings")


def _life_of_duty_cycle(b, loads, speeds, times, options, lube, assumed=()):
    import numpy as np

    from .. import tables
    from ..life import duty_cycle_life
    from ..units import RPM

    dist = _distribution(b, loads)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        d = duty_cycle_life(b, loads, speeds, times, **options, load_distribution=dist)
    steps = tables.rows(tables.rating_life(d.steps))
    hours = 2 * np.pi / d.mean_speed / 3600.0

    def scaled(life, factor):  # None: not computed (no lubricant)
        return None if life is None else life * factor

    doc = {**tables.ratings(d.steps), "reliability_factor": d.steps.reliability_factor,
           **({} if d.steps.contamination_factor is None else {"contamination_factor": d.steps.contamination_factor}),
           "basic_rating_life_Mrev": d.basic_rating_life * 1e-6, "basic_rating_life_h": d.basic_rating_life * hours,
           "modified_rating_life_Mrev": scaled(d.modified_rating_life, 1e-6),
           "modified_rating_life_h": scaled(d.modified_rating_life, hours),
           "reference_rating_life_Mrev": d.reference_rating_life * 1e-6,
           "modified_reference_rating_life_Mrev": scaled(d.modified_reference_rating_life, 1e-6),
           "mean_speed_rpm": d.mean_speed / RPM, "steps": steps,
           "inputs": _echo(b, options, lube, steps=[{"fx_N": f[0], "fy_N": f[1], "fz_N": f[2], "mx_Nmm": f[3] * 1e3,
                                                "my_Nmm": f[4] * 1e3, "speed_rpm": w / RPM, "time": t}
                                               for f, w, t in zip(loads.tolist(), speeds.tolist(), times.tolist())]),
           "warnings": [*assumed, *_diameter_note(d.steps), *_notes(b, loads, d.steps.warnings, dist),
                        *_unbounded(d)]}
    from . import _preload

    preloaded, note = _preload.report(b)
    if note:
        doc["warnings"] = [note + "; L10r counts the preload's ball loads, L10 of ISO 281 does not", *doc["warnings"]]
    return tables.json_value({**doc, **preloaded})

