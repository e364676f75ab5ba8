"""The roller-bearing paths of the calculations other than the load distribution and the tapered pair (issue 32).

Each function computes the document of one calculation for a :class:`~bearinglab.rollers.bearing.RollerBearing`,
with the keys of its ball-bearing document where the quantity is the same, and the rollers in place of the
balls. The calculation's ``document`` resolves the bearing (:func:`._rollers.bearing_of`) and calls its
function here.

life          ISO 281 roller ratings and lives (a_ISO, L_nm) and ISO/TS 16281's L10r over the laminae of the
              slice model, with a misalignment (``tilt_x``, ``tilt_y``) or the tilt a moment gives; duty cycles
film          the line-contact film (Pan and Hamrock) and Lambda of every roller at its load of the slice model
friction      SKF's four-term model of roller bearings (its constants and the drag moment of an oil bath)
frequencies   the defect frequencies of the rollers (pure rolling: rollers, roller diameter, pitch diameter,
              contact angle) and the spectral mask
clearance     the mounted clearance of a cylindrical or tapered roller bearing through the fits, temperatures
              and speed (its unmounted clearance given)

Spherical roller bearings have ratings, life (ISO 281) and friction only: the others say so in one line.
"""

from __future__ import annotations

import math
import warnings

import numpy as np

from ..errors import InputError
from ._inputs import inputs_echo
from ._reading import text as _text
from ._rollers import geometry_of, notes_of, pressure_warnings, slices_of, spherical

__all__ = ["clearance", "film", "frequencies", "friction", "life"]

_UM = 1e-6


# ---------------------------------------------------------------------------------------------------- life
def misalignment(parsed, loads):
    """(theta_x, theta_y) [rad] of the request (None where not given); a moment and a tilt about one axis
    refused together."""
    from ..units import parse_quantity

    out = []
    for axis, moment in (("x", 3), ("y", 4)):
        text = _text(parsed, f"tilt_{axis}")
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


def lamina_loads(bearing, loads, n_slices, tilt=(None, None)):
    """The lamina loads of the ISO/TS 16281 reference life for a batch of load cases, the results' warnings and
    the largest lamina pressure of each case; (None, notes, None) where there is no slice model (a spherical
    bearing, a bearing without the data to estimate its roller set: the life analysis then says why).

    The ring is held square where a case has no moment (ISO 281's load case: the other bearing holds the
    shaft), free to tilt under a moment, held at ``tilt`` about an axis where given (a misalignment); a single
    tapered bearing needs a thrust F_z > F_r tan(alpha) (its cases without one have no reference life).
    """
    from ..life.roller import reference_slice_loads

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


def life(parsed, bearing, options, lube, assumed, *, loads=None, speed=None, mounted=None, steps=None,
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
    from .. import tables
    from ..life import duty_cycle_life, rating_life
    from ..units import RPM
    from .life import _KEYS, _diameter_note, _echo, _unbounded

    n_slices = slices_of(parsed)
    if bearing.type != "spherical":  # the roller set of the reference life, estimated (labelled) where missing
        try:
            bearing = geometry_of(bearing)
        except InputError:  # the ISO 281 lives need none; the analysis says why there is no reference life
            pass
    f = np.asarray(loads if steps is None else steps[0], dtype=float)
    tilt = misalignment(parsed, f)
    q, model_notes, pressure = lamina_loads(bearing, f, n_slices, tilt)
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
        doc = {**tables.rows(tables.rating_life(r))[0], "rating_source": r.rating_source,
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


# ---------------------------------------------------------------------------------------------------- film
def film(parsed, bearing):
    """The document of ``film`` for a roller bearing: the line-contact film of every roller.

    The roller loads are the slice model's at rest (ISO/TS 16281: no centrifugal roller loads), the film of
    each roller that of a line contact of its mean load per length at both raceways (Pan and Hamrock's
    formula, :func:`bearinglab.film.roller_films`), Lambda with the roughness of the rollers (``roughness_ball``)
    and the raceways.

    Parameters
    ----------
    parsed : Parsed
        A request of ``film``.
    bearing : RollerBearing
        From :func:`._rollers.bearing_of`.

    Returns
    -------
    dict or list of dict
        One document per speed: ``film_min_um``, ``lambda_min``, ``regime``, ``converged`` and ``rollers`` (per
        roller ``azimuth_deg``, ``load_N``, ``entrainment_velocity_m_s``, ``film_central_inner_um``,
        ``film_min_inner_um``, ``film_central_outer_um``, ``film_min_outer_um``, ``lambda``), ``inputs`` and
        ``warnings``.
    """
    from .. import film as film_model
    from ..film import ehl
    from ..rollers import analysis
    from ..units import RPM
    from . import film as ball_film
    from ._inputs import five_loads, parse_speeds
    from ._rollers import operating
    from .load_distribution import MOUNTING

    spherical(bearing, "the film")
    b = geometry_of(bearing)
    loads = five_loads(*(_text(parsed, k) for k in ("fx", "fy", "fz", "mx", "my", "radial_load", "axial_load")))
    speed = _text(parsed, "speed")
    if speed is None:
        raise InputError("speed: give the inner-ring speed, e.g. --speed '6000 rpm' (no film forms at rest)")
    w = parse_speeds(speed, pitch_diameter=b.pitch_diameter, zero=False)
    rq_roller, rq_race = ball_film.roughness(_text(parsed, "roughness"), _text(parsed, "roughness_ball"),
                                             _text(parsed, "roughness_race"))
    alpha = ball_film.pressure_viscosity(_text(parsed, "pressure_viscosity_coefficient"))
    oil = {k: (parsed.values.get(k) if k == "viscosity_index" else _text(parsed, k))
           for k in ("viscosity", "dynamic_viscosity", "oil", "viscosity_index", "viscosity_100")}
    temperature = _text(parsed, "temperature")
    notes = []
    if temperature is not None and temperature.lower() == "auto":
        eta, how, lub_inputs, notes = ball_film._auto_temperature(
            b, loads, w, oil["oil"], oil["viscosity"], oil["dynamic_viscosity"], oil["viscosity_index"],
            oil["viscosity_100"], _text(parsed, "density"), _text(parsed, "ambient"),
            _text(parsed, "thermal_resistance"), _text(parsed, "lubrication") or "oil-jet",
            _text(parsed, "skf_constants"))
    else:
        if any(_text(parsed, k) is not None for k in ("ambient", "thermal_resistance", "skf_constants")):
            raise InputError("temperature: --ambient, --thermal-resistance and --skf-constants go with "
                             "--temperature auto (the thermal balance)")
        eta, _, how, lub_inputs, notes = ball_film.lubricant(oil["viscosity"], oil["dynamic_viscosity"], oil["oil"],
                                                             temperature, oil["viscosity_index"],
                                                             oil["viscosity_100"], _text(parsed, "density"))
        if _text(parsed, "lubrication") is not None:
            notes.append("lubrication: the starvation check (SKF's replenishment factor) is made for ball bearings; "
                         "the rollers' films are those of a fully flooded contact")
    if alpha is None:
        alpha = ehl.pressure_viscosity_coefficient(eta)
        notes.append("pressure-viscosity coefficient: not given, so Wooster's estimate for mineral oils is used "
                     f"({float(np.min(alpha)) * 1e9:.3g} 1/GPa); give the oil's own value")
    b, mounted = operating(b, float(np.max(w)), {k: _text(parsed, k) for k in MOUNTING if k in parsed.given})
    n_slices = slices_of(parsed)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        r = analysis.roller_analysis(b, loads, n_slices=n_slices)
    notes += [*r.warnings, *(str(c.message) for c in caught)]
    notes.append("roller loads: those of the slice model at rest (ISO/TS 16281: no centrifugal roller loads); each "
                 "roller's film is that of its mean load per length (a tilted roller's loaded end runs thinner)")
    eta_k = np.broadcast_to(np.asarray(eta, dtype=float), w.shape)
    alpha_k = np.broadcast_to(np.asarray(alpha, dtype=float), w.shape)
    docs = []
    for k in range(w.size):
        f = film_model.roller_films(r.roller_load, float(w[k]), b.roller_diameter, b.roller_length, b.pitch_diameter,
                                    float(eta_k[k]), float(alpha_k[k]), b.reduced_modulus, contact_angle=b.contact_angle,
                                    roughness_roller=rq_roller, roughness_race=rq_race)
        doc = _film_doc(r, f)
        doc["inputs"] = inputs_echo(b, fx_N=loads[0], fy_N=loads[1], fz_N=loads[2], mx_Nmm=loads[3] * 1e3,
                                    my_Nmm=loads[4] * 1e3, speed_rpm=float(w[k]) / RPM, loads_at="rest",
                                    **lub_inputs, lubricant=how, pressure_viscosity_coefficient_per_GPa=
                                    float(alpha_k[k]) * 1e9, roughness_ball_um=rq_roller * 1e6,
                                    roughness_race_um=rq_race * 1e6, slices=n_slices)
        temps = lub_inputs.get("bearing_temperature_degC")
        if isinstance(temps, list):
            doc["inputs"]["bearing_temperature_degC"] = temps[k]
        doc.update(mounted)
        doc["warnings"] = list(dict.fromkeys([*notes, *notes_of(b)]))
        docs.append(doc)
    return docs[0] if w.size == 1 else docs


def _film_doc(r, f):
    """One speed's film of the rollers, JSON-ready (null where a roller carries no load)."""
    from .._io import json_value

    hmin = np.fmin(f.minimum_inner, f.minimum_outer)
    loaded = np.isfinite(hmin)
    k = int(np.nanargmin(np.where(loaded, hmin, np.nan))) if loaded.any() else None
    rollers = [{"azimuth_deg": math.degrees(float(r.azimuth[j])), "load_N": float(r.roller_load[j]),
                "entrainment_velocity_m_s": float(f.entrainment_velocity),
                "film_central_inner_um": json_value(float(f.central_inner[j]) * 1e6),
                "film_min_inner_um": json_value(float(f.minimum_inner[j]) * 1e6),
                "film_central_outer_um": json_value(float(f.central_outer[j]) * 1e6),
                "film_min_outer_um": json_value(float(f.minimum_outer[j]) * 1e6),
                "lambda": json_value(float(f.film_parameter[j]))} for j in range(len(r.roller_load))]
    return {"film_min_um": None if k is None else float(hmin[k]) * 1e6,
            "lambda_min": None if k is None else float(f.film_parameter[k]),
            "regime": None if k is None else str(f.regime[k]), "converged": bool(r.converged),
            "rollers": rollers}


# ------------------------------------------------------------------------------------------------ friction
_HANDBOOK = ("type", "bore", "outside_diameter", "mean_diameter", "static_load_rating", "mu", "x0", "y0", "f", "c",
             "f0", "palmgren_f0")


def friction(parsed, bearing):
    """The document of ``friction torque`` for a roller bearing: SKF's four-term model of its type.

    SKF General Catalogue 6000 (module :mod:`bearinglab.friction.skf_roller`): the rolling and sliding moments with
    the constants of the bearing's series, the inlet shear heating and replenishment factors, and the drag moment
    of an oil bath (``lubrication`` oil-bath with ``oil_level`` and ``drag_loss_factor``, V_M of SKF's diagram).
    The handbook models of the friction-rig lab (one-term, two-term, Palmgren) are ball bearings': refused.

    Parameters
    ----------
    parsed : Parsed
        A request of ``friction``.
    bearing : RollerBearing
        From :func:`._rollers.bearing_of`.

    Returns
    -------
    tuple
        ``(document, SKFTorque)``: the keys of the ball bearing's ``skf`` document.
    """
    from .. import friction as friction_model
    from .. import tables
    from ..units import RPM
    from . import _reading as inp
    from ._inputs import lubricant_viscosity
    from ._rollers import operating
    from .friction_torque import _cases, _check_speed, _echo
    from .load_distribution import MOUNTING

    model = inp.value(parsed, "model", "one-term")
    if model != "skf":
        raise InputError(f"model: the {model} model is of ball bearings (the friction-rig lab's handbook constants); "
                         f"{bearing.designation!r} is a {bearing.type} roller bearing: give --model skf (SKF's "
                         "constants of roller bearings)")
    given = [k for k in _HANDBOOK if k in parsed.given]
    if given:
        raise InputError(f"{given[0].replace('_', '-')}: an input of the handbook models of ball bearings; the skf "
                         "model reads a roller bearing's envelope and series from the bearing")
    series = parsed.given.get("series")
    if series is not None:
        try:
            friction_model.roller_series_constants(bearing.type, str(series).strip())
        except InputError as exc:
            raise InputError(f"series: {exc}".replace("series: series", "series")) from None
        bearing = bearing.replace(series=str(series).strip())
    fr, fa, n = _cases(inp.text(parsed, "radial_load", "0 N"), inp.text(parsed, "axial_load", "0 N"),
                       inp.text(parsed, "speed", "0 rpm"))
    _check_speed(bearing, n)
    lubrication = inp.value(parsed, "lubrication", "grease")
    oil = (inp.text(parsed, "oil"), inp.text(parsed, "temperature"), inp.value(parsed, "viscosity_index"),
           inp.text(parsed, "viscosity_100"))
    if inp.text(parsed, "viscosity") is None and oil[0] is None:
        raise InputError("viscosity: the skf model needs --viscosity (e.g. '30 cSt'; of the base oil for grease), "
                         "or --oil VG68 with --temperature")
    nu = lubricant_viscosity(inp.text(parsed, "viscosity"), *oil, required=True).viscosity
    kw = {}
    level, vm = inp.text(parsed, "oil_level"), inp.value(parsed, "drag_loss_factor")
    if lubrication == "oil-bath":
        if level is None or vm is None:
            raise InputError("oil-level: --lubrication oil-bath needs --oil-level (e.g. '5 mm') and "
                             "--drag-loss-factor (V_M of SKF's diagram at H/d_m, the roller-bearing curve)")
        h = inp.parse_length(level, "oil-level", zero=True)
        dm = bearing.mean_diameter
        if h > dm / 2:
            raise InputError(f"oil-level must be <= d_m/2 = {dm / 2 * 1e3:g} mm [mm] (at most up to the bearing's "
                             f"centre), got {h * 1e3:g} mm")
        if not 0.0 <= vm <= 1.0:
            raise InputError(f"drag-loss-factor must be in [0, 1] [-] (V_M of SKF's diagram), got {vm:g}")
        kw["drag_loss_factor"] = vm
    elif level is not None or vm is not None:
        raise InputError("oil-level: --oil-level and --drag-loss-factor go with --lubrication oil-bath")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        m = friction_model.skf_roller_for_bearing(bearing, fr, fa, n, nu, lubrication=lubrication, **kw)
    notes = list(dict.fromkeys([*m.warnings, *(str(c.message) for c in caught)]))
    if bearing.type == "cylindrical" and bearing.design in ("N", "NU") and np.any(fa > 0):
        notes.append(f"axial load: an {bearing.design} carries none (no ribs on both rings); SKF's sliding moment "
                     "takes it as if on the flanges")
    moments = tables.rows(tables.skf_torque(m))
    rpm = tables.significant(n / RPM)
    cases = [{"radial_load_N": float(fr[i]), "axial_load_N": float(fa[i]), "speed_rpm": float(rpm[i]), **moments[i]}
             for i in range(len(moments))]
    info = {"bearing": bearing.designation, "type": bearing.type, "model": "skf", "lubrication": lubrication,
            "viscosity_cSt": float(tables.significant(nu * 1e6)[0]), "series": bearing.series}
    mounting = {k: inp.text(parsed, k) for k in MOUNTING if k in parsed.given}
    mounted = {}
    if mounting:
        _, mounted = operating(bearing, float(np.max(n)), mounting)
        notes.append("operating clearance: the skf friction model does not depend on the clearance; "
                     "operating_clearance_um is reported, the torque is the same without the mounting inputs")
    echo = {"inputs": _echo(bearing, fr, fa, n, model="skf", lubrication=lubrication, viscosity_cSt=nu * 1e6,
                            **({"drag_loss_factor": vm, "oil_level_mm": float(h) * 1e3} if kw else {})),
            "warnings": list(dict.fromkeys([*notes, *notes_of(bearing)]))}
    doc = {**info, **cases[0], **mounted, **echo} if len(cases) == 1 else {**info, "cases": cases, **mounted, **echo}
    return doc, m


# --------------------------------------------------------------------------------------------- frequencies
def frequencies(parsed, bearing):
    """The document of ``frequencies`` for a roller bearing: the defect frequencies of its rollers.

    Pure rolling at the roller middles (:mod:`bearinglab.kinematics`, the formulas of ball bearings with the
    roller diameter D_we, the pitch diameter D_pw, the rollers Z and the contact angle; of a tapered bearing its
    cup angle, the usual approximation: the cone's raceway runs at alpha - 2 phi). The keys of the ball
    bearing's document; the operating angle under an axial stand load is the test-stand method of ball
    bearings, refused.

    Parameters
    ----------
    parsed : Parsed
        A request of ``frequencies``.
    bearing : RollerBearing
        From :func:`._rollers.bearing_of`.

    Returns
    -------
    dict
    """
    from .. import kinematics, tables
    from ..units import format_dms
    from . import _reading as inp
    from .frequencies import _HZ, _mask, _read

    spherical(bearing, "its defect frequencies")
    if inp.text(parsed, "axial_load") is not None:
        raise InputError("axial-load: the operating contact angle under a stand load is the test-stand method of ball "
                         f"bearings; {bearing.designation!r} is a {bearing.type} roller bearing, whose frequencies are "
                         "at its nominal angle")
    b = geometry_of(bearing)
    harmonics, sidebands = inp.value(parsed, "harmonics", 3), inp.value(parsed, "sidebands", 1)
    w_in, w_out, _, band = _read(b, inp.text(parsed, "speed"), inp.text(parsed, "outer_speed", "0 rpm"), None,
                                 "exact", harmonics, sidebands, inp.text(parsed, "band", "2 %"))
    z, d, dm, a0 = b.rollers, b.roller_diameter, b.pitch_diameter, b.contact_angle
    out = inputs_echo(b, speed_rpm=w_in / _HZ * 60.0, outer_speed_rpm=w_out / _HZ * 60.0)
    shift = kinematics.frequency_shift(w_in, d, dm, z, a0, a0, outer_speed=w_out)
    out.update(contact_angle_deg=math.degrees(a0), contact_angle_dms=format_dms(a0),
               nominal_contact_angle_deg=math.degrees(a0), shaft_hz=w_in / _HZ, outer_hz=w_out / _HZ)
    out.update(tables.frequencies(shift.operating, w_in))
    out["nominal"] = dict(contact_angle_deg=math.degrees(a0), shaft_hz=w_in / _HZ,
                          **tables.frequencies(shift.nominal, w_in))
    out["shift_hz"] = {n: float(getattr(shift.shift, n)) / _HZ for n in kinematics.FAMILIES[1:]}
    out["shift_percent"] = {n: float(getattr(shift.shift_percent, n)) for n in kinematics.FAMILIES[1:]}
    if inp.value(parsed, "mask", False):
        view = _BallView(b)
        out["mask"] = {"harmonics": harmonics, "sidebands": sidebands, "band_percent": band * 100.0,
                       "lines": _mask(view, w_in, w_out, a0, harmonics, sidebands, band)}
    notes = []
    if b.estimated_fields:
        from ..rollers.analysis import provenance

        notes += provenance(b)
    if b.type == "tapered":
        notes.append("tapered roller bearing: the frequencies of pure rolling at the roller middles with the cup angle "
                     "(the usual approximation; the cone's raceway runs at alpha - 2 phi)")
    out["warnings"] = list(dict.fromkeys([*notes, *notes_of(b)]))
    return out


class _BallView:
    """A roller bearing as the spectral mask reads a ball bearing (Z, D, d_m)."""

    def __init__(self, b):
        self._values = {"n_balls": b.rollers, "ball_diameter": b.roller_diameter, "pitch_diameter": b.pitch_diameter}

    def require(self, *names):
        return tuple(self._values[n] for n in names)


# ----------------------------------------------------------------------------------------------- clearance
def clearance(parsed, bearing, mounting, speed, speed_text):
    """The mounted-clearance chain of a cylindrical roller bearing (its raceways at the roller middles).

    Parameters
    ----------
    parsed : Parsed
        A request of ``clearance``.
    bearing : RollerBearing
        From :func:`._rollers.bearing_of`.
    mounting : dict
        The mounting fields (name -> text as given).
    speed : float
        Inner-ring speed. [rad/s]
    speed_text : str or None
        As typed, for the echo.

    Returns
    -------
    tuple
        ``(bearing, inputs, range)``: the bearing with its roller set (estimated where missing), the
        :class:`~bearinglab.calculations._mounting.MountedInputs` and the chain's range.
    """
    from ..mounting import chain
    from ._rollers import mounted_inputs

    if bearing.type == "tapered":
        raise InputError(f"bearing: {bearing.designation!r} is a tapered roller bearing, whose play is set by "
                         "adjusting it against the other bearing of its pair (bearing-set, --preload-offset): its "
                         "mounted radial clearance is not modelled")
    spherical(bearing, "the mounted clearance")
    b = geometry_of(bearing)
    given = {k: v for k, v in mounting.items() if v is not None and k != "radial_clearance"}
    inp = mounted_inputs(b, given, speed, radial_clearance=mounting.get("radial_clearance"))
    r = chain.operating_range(inp.unmounted, inp.inner, inp.outer, inp.mounting, inp.conditions)
    return b, inp, r
