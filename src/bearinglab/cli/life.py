"""Command line of the rating life (issue 12): ``life``.

ISO 281 and ISO/TS 16281 lives of a bearing under (F_x, F_y, F_z, M_x, M_y) at a speed
(:func:`bearinglab.ratings.rating_life`; the ball loads of the reference life from the combined-load
model), or of a duty cycle (``--duty-cycle FILE``, :func:`bearinglab.ratings.duty_cycle_life`). The columns
are :func:`bearinglab.tables.rating_life`. Where ISO 281's P is not defined (under a moment) its fields
are null and a warning says why; the ISO/TS 16281 fields are still given.

Duty-cycle file (TOML; the time shares sum to 1)::

    [[step]]
    fx = "2 kN"          # any of fx, fy, fz, mx, my (radial_load = fx, axial_load = fz)
    fz = "500 N"
    speed = "3000 rpm"
    time = 0.6

Commands
--------
COMMANDS   the ``life`` command, by name (the application adds it)
"""

import re
import tomllib
import warnings
from pathlib import Path
from typing import Annotated

import typer

from ..errors import InputError
from ._common import (
    AxialLoadOpt,
    BallDiameter,
    BallMaterial,
    Balls,
    BearingFile,
    BearingName,
    CatalogFile,
    Clearance,
    ContactAngle,
    FxOpt,
    FyOpt,
    FzOpt,
    InnerConformity,
    InnerRadius,
    JsonFlag,
    MxOpt,
    MyOpt,
    OuterConformity,
    OuterRadius,
    PitchDiameter,
    RadialLoadOpt,
    check_input,
    emit_json,
    five_loads,
    inputs_echo,
    parse_speed,
    parse_viscosity,
    print_warnings,
    resolve_bearing,
    table,
)

__all__ = ["COMMANDS"]

# the keys of bearinglab.ratings.CONTAMINATION_CLASSES, spelled out for the help text (the help is built
# without importing the model; tests/cli/test_cli_startup.py checks that the two agree)
_CONTAMINATION_CLASSES = ("extreme_cleanliness", "high_cleanliness", "normal_cleanliness", "slight_contamination",
                          "typical_contamination", "severe_contamination", "very_severe_contamination")
_CONTAMINATION = {k.split("_")[0] if k != "very_severe_contamination" else "very-severe": k
                  for k in _CONTAMINATION_CLASSES}
_LUBRICANT = "Lubricant and cleanliness"
_ZERO_C = 273.15  # K at 0 degC
_TEMPERATURE = re.compile(r"^\s*([-+]?\d+(?:\.\d*)?(?:[eE][-+]?\d+)?)\s*(°C|degC|C|K|°F|degF|F)\s*$")


def _temperature(text):
    """A temperature '70 degC', '343 K' or '158 degF' in K, above absolute zero."""
    m = _TEMPERATURE.match(text or "")
    if not m:
        raise InputError(f"temperature must be a number with degC, K or degF (e.g. '70 degC'), got {text!r}")
    v, unit = float(m.group(1)), m.group(2).lstrip("°").removeprefix("deg")
    t = {"C": v + _ZERO_C, "K": v, "F": (v - 32.0) / 1.8 + _ZERO_C}[unit]
    if not t > 0:
        raise InputError(f"temperature must be above absolute zero (0 K = -273.15 degC), got {text!r}")
    return t


def _viscosity(viscosity, oil, viscosity_100, temperature):
    """kinematic_viscosity or the oil options of :func:`bearinglab.ratings.rating_life`."""
    from .. import ratings
    if viscosity is not None:
        if oil is not None or temperature is not None or viscosity_100 is not None:  # none is ignored
            raise InputError("viscosity: give --viscosity, or --oil with --viscosity-100 and --temperature, not both")
        return {"kinematic_viscosity": parse_viscosity(viscosity, "viscosity")}
    if oil is None or temperature is None:
        raise InputError("viscosity: give --viscosity (e.g. '20 cSt'), or --oil VG68 with --viscosity-100 and "
                         "--temperature")
    m = re.fullmatch(r"(?:ISO\s*)?VG\s*(\d+)", oil.strip(), flags=re.IGNORECASE)
    if not m or int(m.group(1)) not in ratings.ISO_VG_GRADES:
        raise InputError(f"oil must be an ISO VG grade (VG{ratings.ISO_VG_GRADES[0]} ... "
                         f"VG{ratings.ISO_VG_GRADES[-1]}), got {oil!r}")
    if viscosity_100 is None:
        raise InputError("viscosity-100: the oil's viscosity at 100 degC (data sheet) is needed with --oil, "
                         "e.g. '8.7 cSt'")
    return {"iso_vg": int(m.group(1)), "temperature": _temperature(temperature),
            "viscosity_100": parse_viscosity(viscosity_100, "viscosity-100")}


# Said whenever the user gave no cleanliness: e_C = 1 is the laboratory's extreme cleanliness of ISO 281
# table 13, and with a good lubricant it drives a_ISO to its limit of 50; service conditions are dirtier.
_CLEANLINESS_ASSUMED = ("contamination: none given, so e_C = 1 (extreme cleanliness, ISO 281 table 13) is used "
                        "for a_ISO and L_nm; give --contamination (e.g. normal) or --contamination-factor for "
                        "the bearing's service")


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


def _duty_cycle(path, bearing):
    """Loads (k, 5), speeds (k,) and time shares (k,) of a duty-cycle file; each speed by the rule of every
    speed option (:func:`parse_speed`: > 0, one value, within the d_m n guard of ``bearing``)."""
    import numpy as np

    from .._bounds import read_input_bytes

    try:
        doc = tomllib.loads(read_input_bytes(path).decode("utf-8"))  # a regular file of bounded size
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"duty-cycle: {path}: {exc}") from None
    except UnicodeDecodeError:
        raise InputError(f"duty-cycle: {path}: not a UTF-8 text file") from None
    steps = doc.get("step")
    if not isinstance(steps, list) or not steps or not all(isinstance(s, dict) for s in steps):
        raise InputError(f"duty-cycle: {path}: needs [[step]] tables with loads, speed and time")
    loads, speeds, times = [], [], []
    for k, s in enumerate(steps, 1):
        unknown = set(s) - {"fx", "fy", "fz", "mx", "my", "radial_load", "axial_load", "speed", "time"}
        if unknown or "speed" not in s or "time" not in s:
            raise InputError(f"duty-cycle: step {k} needs speed and time and takes fx, fy, fz, mx, my; got "
                             f"{sorted(s)}")
        loads.append(five_loads(*(s.get(n) for n in ("fx", "fy", "fz", "mx", "my", "radial_load", "axial_load"))))
        speeds.append(parse_speed(s["speed"], f"duty-cycle step {k} speed", bearing=bearing, zero=False))
        t = s["time"]
        if isinstance(t, bool) or not isinstance(t, (int, float)) or not 0.0 <= t <= 1.0:
            raise InputError(f"duty-cycle step {k} time must be a share in [0, 1] [-] (the shares sum to 1), "
                             f"got {t!r}")
        times.append(float(t))
    return np.array(loads), np.array(speeds), np.array(times)


def life(
    fx: FxOpt = None, fy: FyOpt = None, fz: FzOpt = None, mx: MxOpt = None, my: MyOpt = None,
    radial_load: RadialLoadOpt = None, axial_load: AxialLoadOpt = None,
    speed: Annotated[str | None, typer.Option("--speed", "-n", help="Inner-ring speed, e.g. '3000 rpm'.")] = None,
    viscosity: Annotated[str | None, typer.Option("--viscosity", help="Operating viscosity, e.g. '20 cSt'.", rich_help_panel=_LUBRICANT)] = None,
    oil: Annotated[str | None, typer.Option("--oil", help="ISO VG grade, e.g. VG68 (with --viscosity-100 and --temperature).", rich_help_panel=_LUBRICANT)] = None,
    viscosity_100: Annotated[str | None, typer.Option("--viscosity-100", help="The oil's viscosity at 100 degC, e.g. '8.7 cSt'.", rich_help_panel=_LUBRICANT)] = None,
    temperature: Annotated[str | None, typer.Option("--temperature", help="Operating temperature, e.g. '70 degC'.", rich_help_panel=_LUBRICANT)] = None,
    contamination_factor: Annotated[float | None, typer.Option("--contamination-factor", help="e_C in [0, 1] (default 1).", rich_help_panel=_LUBRICANT)] = None,
    contamination: Annotated[str | None, typer.Option("--contamination", help="Cleanliness of ISO 281 table 13: " + " | ".join(_CONTAMINATION) + ".", rich_help_panel=_LUBRICANT)] = None,
    reliability: Annotated[float, typer.Option("--reliability", help="Reliability in percent, 90 to 99.95.")] = 90.0,
    duty_cycle: Annotated[Path | None, typer.Option("--duty-cycle", help="TOML file of \\[\\[step]] loads, speed and time share: the combined life.")] = None,
    bearing: BearingName = None, bearing_file: BearingFile = None, catalog: CatalogFile = None,
    balls: Balls = None, ball_diameter: BallDiameter = None, pitch_diameter: PitchDiameter = None,
    inner_groove_radius: InnerRadius = None, outer_groove_radius: OuterRadius = None,
    inner_conformity: InnerConformity = None, outer_conformity: OuterConformity = None,
    contact_angle: ContactAngle = None, radial_clearance: Clearance = None, ball_material: BallMaterial = None,
    json_out: JsonFlag = False,
):
    """Rating life (ISO 281, ISO/TS 16281): C, C0, Cu, P, L10, a_ISO, L_nm, L10r, L_nmr, s0; duty cycles."""
    from .. import ratings, tables
    from ..units import RPM
    b = resolve_bearing(bearing, bearing_file, catalog, balls, ball_diameter, pitch_diameter, inner_groove_radius,
                        outer_groove_radius, inner_conformity, outer_conformity, contact_angle, radial_clearance,
                        ball_material)
    options = {**_viscosity(viscosity, oil, viscosity_100, temperature),
               "contamination": _cleanliness(contamination_factor, contamination),
               "reliability": _reliability(reliability)}
    assumed = [_CLEANLINESS_ASSUMED] if contamination_factor is None and contamination is None else []
    if duty_cycle is not None:
        if any(x is not None for x in (fx, fy, fz, mx, my, radial_load, axial_load, speed)):
            raise InputError("duty-cycle: the loads and speeds are in the file; give no --fx ... --speed")
        _life_of_duty_cycle(b, *_duty_cycle(check_input(duty_cycle, "duty-cycle"), b), options, json_out, assumed)
        return
    if speed is None:
        raise InputError("speed: give the inner-ring speed, e.g. --speed '3000 rpm'")
    n = parse_speed(speed, bearing=b, zero=False)
    loads = five_loads(fx, fy, fz, mx, my, radial_load, axial_load)
    dist = _distribution(b, loads)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the analysis returns its warnings
        r = ratings.rating_life(b, loads, n, **options, load_distribution=dist)
    doc = {**tables.rows(tables.rating_life(r))[0], "rating_source": r.rating_source,
           "inputs": _echo(b, options, fx_N=loads[0], fy_N=loads[1], fz_N=loads[2], mx_Nmm=loads[3] * 1e3,
                           my_Nmm=loads[4] * 1e3, speed_rpm=n / RPM),
           "warnings": assumed + _notes(b, loads, r.warnings, dist) + _unbounded(r)}
    doc = {k: doc[k] for k in _KEYS}
    if json_out:
        emit_json(doc)
        return
    _print(f"Rating life of {b.designation} at {doc['inputs']['speed_rpm']:g} rpm", doc)


def _distribution(b, loads):
    """The load distribution of the ISO/TS 16281 reference life
    (:func:`bearinglab.ratings.reference_load_distribution`), computed here so that the plausibility limits
    see the ball loads. A case without equilibrium is flagged, not raised: the ISO 281 lives do not need
    the distribution. None without the ball set (the reference lives are then NaN, and say why)."""
    from .. import ratings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the life analysis reports what matters to it
        return ratings.reference_load_distribution(b, loads, on_failure="flag")


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

    names = [symbol for field, symbol in _UNBOUNDED.items()
             if np.any(np.isposinf(getattr(result, field, np.nan)))]
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

    from .. import ratings
    from ..errors import ConvergenceError

    failed = np.flatnonzero(~np.ravel(dist.converged))
    if not failed.size:
        return []
    f = np.reshape(loads, (-1, 5))
    where = "" if len(f) == 1 else f" at {failed.size} of {len(f)} steps (first: step {failed[0] + 1})"
    try:
        ratings.reference_load_distribution(b, f[failed[0]], on_failure="raise")
        why = "the combined-load model found no equilibrium"
    except ConvergenceError as exc:
        why = exc.summary
    return [f"ISO/TS 16281 reference lives not available{where}: {why}"]


def _echo(b, options, **quantities):
    """The inputs as used (:func:`inputs_echo`): the bearing, the loads and speed, lubricant and cleanliness."""
    lube = {k: v for k, v in options.items() if k not in ("contamination", "reliability")}
    if "kinematic_viscosity" in lube:
        lube = {"viscosity_cSt": lube["kinematic_viscosity"] * 1e6}
    else:
        lube = {"oil": f"VG{lube['iso_vg']}", "temperature_degC": lube["temperature"] - _ZERO_C,
                "viscosity_100_cSt": lube["viscosity_100"] * 1e6}
    c = options["contamination"]
    return inputs_echo(b, **quantities, **lube, contamination=c, reliability_percent=options["reliability"] * 100)


_KEYS = ("dynamic_load_rating_N", "static_load_rating_N", "fatigue_load_limit_N", "rating_source",
         "equivalent_dynamic_load_N", "basic_rating_life_Mrev", "basic_rating_life_h", "reliability_factor",
         "viscosity_ratio", "life_modification_factor", "modified_rating_life_Mrev", "modified_rating_life_h",
         "reference_rating_life_Mrev", "modified_reference_rating_life_Mrev", "static_safety_factor", "inputs",
         "warnings")


def _life_of_duty_cycle(b, loads, speeds, times, options, json_out, assumed=()):
    import numpy as np

    from .. import ratings, tables
    from ..units import RPM
    dist = _distribution(b, loads)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        d = ratings.duty_cycle_life(b, loads, speeds, times, **options, load_distribution=dist)
    steps = tables.rows(tables.rating_life(d.steps))
    hours = 2 * np.pi / d.mean_speed / 3600.0
    doc = {**tables.ratings(d.steps), "reliability_factor": d.steps.reliability_factor,
           "basic_rating_life_Mrev": d.basic_rating_life * 1e-6, "basic_rating_life_h": d.basic_rating_life * hours,
           "modified_rating_life_Mrev": d.modified_rating_life * 1e-6,
           "modified_rating_life_h": d.modified_rating_life * hours,
           "reference_rating_life_Mrev": d.reference_rating_life * 1e-6,
           "modified_reference_rating_life_Mrev": d.modified_reference_rating_life * 1e-6,
           "mean_speed_rpm": d.mean_speed / RPM, "steps": steps,
           "inputs": _echo(b, options, steps=[{"fx_N": f[0], "fy_N": f[1], "fz_N": f[2], "mx_Nmm": f[3] * 1e3,
                                                "my_Nmm": f[4] * 1e3, "speed_rpm": w / RPM, "time": t}
                                               for f, w, t in zip(loads.tolist(), speeds.tolist(), times.tolist())]),
           "warnings": [*assumed, *_notes(b, loads, d.steps.warnings, dist), *_unbounded(d)]}
    doc = tables.json_value(doc)
    if json_out:
        emit_json(doc)
        return
    _print(f"Duty cycle of {b.designation}: {len(steps)} steps, mean speed {doc['mean_speed_rpm']:g} rpm",
           {k: v for k, v in doc.items() if k not in ("steps", "inputs")})


# The printed names of the JSON keys: the symbols of ISO 281 and ISO/TS 16281, with the unit.
_LABELS = {
    "dynamic_load_rating_N": "basic dynamic load rating C [N]",
    "static_load_rating_N": "basic static load rating C0 [N]",
    "fatigue_load_limit_N": "fatigue load limit Cu [N]",
    "equivalent_dynamic_load_N": "equivalent dynamic load P [N]",
    "basic_rating_life_Mrev": "basic rating life L10 [10^6 rev]",
    "basic_rating_life_h": "basic rating life L10h [h]",
    "reliability_factor": "reliability factor a1 [-]",
    "viscosity_ratio": "viscosity ratio κ [-]",
    "life_modification_factor": "life modification factor a_ISO [-]",
    "modified_rating_life_Mrev": "modified rating life L_nm [10^6 rev]",
    "modified_rating_life_h": "modified rating life L_nmh [h]",
    "reference_rating_life_Mrev": "reference rating life L10r [10^6 rev]",
    "modified_reference_rating_life_Mrev": "modified ref. life L_nmr [10^6 rev]",
    "static_safety_factor": "static safety factor s0 [-]",
    "mean_speed_rpm": "mean speed [rpm]",
}


def _print(title, doc):
    def fmt(v):
        return "— (see the warnings)" if v is None else (f"{v:.6g}" if isinstance(v, float) else str(v))

    src = doc["rating_source"]
    rows = [[_LABELS.get(k, k), fmt(v) + (f"  ({src[k[:-2]]})" if k[:-2] in src else "")]
            for k, v in doc.items() if k not in ("rating_source", "warnings", "inputs", "steps")]
    table(title, ["quantity", "value"], rows, caption="--json for one JSON document (keys in the units shown)")
    print_warnings(doc["warnings"])


#: The ``life`` command, as the application adds it.
COMMANDS = {"life": life}
