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
    from . import _mounting

    v = parsed.values

    def text(name):
        return given_text(parsed, name)

    with failures(parsed):
        b = resolve_bearing(text("bearing"), bearing_file, catalog, v.get("balls"), *map(text, _GEOMETRY),
                            v.get("inner_conformity"), v.get("outer_conformity"),
                            text("contact_angle"), text("radial_clearance"), text("ball_material"))
        notes = _catalog.provenance_notes(b)
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
            b, _ = _mounting.operating_bearing(b, 0.0, mounting)  # no single speed for the centrifugal
            steps = _duty_cycle(str(parsed.given["duty_cycle"]), duty_cycle_source, b)
        elif "speed" not in parsed.given:
            raise InputError("speed: missing; give the inner-ring speed, e.g. '3000 rpm' (or --duty-cycle)")
        else:  # one speed, or a list like film's: one document per speed (issue 30)
            speeds = parse_speeds(text("speed"), pitch_diameter=speed_size(b), zero=False)
            loads = five_loads(*map(text, _LOADS))
            runs = []
            for n in map(float, speeds):
                b_n, mounted = _mounting.operating_bearing(b, n, mounting)  # issue 23: the operating clearance
                run = {"bearing": b_n, "speed": n, "mounted": mounted, "lube": lube, "assumed": assumed,
                       "options": dict(options)}
                if auto:
                    run["lube"], run["temperature"], notes_auto = _auto_viscosity(b_n, loads, n, text, v, thermal)
                    run["options"]["kinematic_viscosity"] = run["lube"].viscosity
                    run["assumed"] = [*_assumed(run["lube"], no_cleanliness), *notes_auto]
                runs.append(run)
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

