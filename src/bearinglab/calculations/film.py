"""The ``film`` document: the lubricant film at every ball's contacts (issue 24).

The EHL film (Hamrock and Dowson) at every ball's inner and outer contact of a bearing under
(F_x, F_y, F_z, M_x, M_y) at a speed (:func:`bearinglab.film.film_analysis`): the ball loads and angles
of the load distribution (quasi-static at the speed, or at rest), the lubricant's viscosity (given, or
of an ISO VG oil at a temperature; temperature ``auto`` takes the steady bearing temperature of
:mod:`bearinglab.thermal`), its pressure-viscosity coefficient and the surface roughness. The columns
are :func:`bearinglab.tables.film`. The command line (``bearinglab film``) and the web compute it here.

Functions
---------
document   Parsed request -> the JSON document ``bearinglab film --json`` prints
"""

from __future__ import annotations

from .. import catalog as _catalog
from .._io import json_value
from ..errors import InputError
from . import _rollers
from ._failures import failures
from ._finite import finite
from ._inputs import (
    choice,
    default_lubrication,
    five_loads,
    inputs_echo,
    lubricant_viscosity,
    parse_length,
    parse_speeds,
    resolve_bearing,
)

__all__ = ["document"]

_GEOMETRY = ("balls", "ball_diameter", "pitch_diameter", "inner_groove_radius", "outer_groove_radius",
             "inner_conformity", "outer_conformity", "contact_angle", "radial_clearance", "ball_material")

#: Default density of a mineral oil [kg/m^3] when none is given: a typical value (0.86-0.89 g/cm^3 at
#: 15 degC for ISO VG 10-460 mineral oils), an estimate labelled as one in the output.
DEFAULT_DENSITY = 870.0
_DEFAULT_ROUGHNESS = 0.1e-6
_UM = 1e-6
# absurd-value guards: beyond these no lubricating oil exists (water 1 mPa s, bitumen 1e5 Pa s)
_ETA_RANGE = (1e-4, 1e4)  # Pa s
_RHO_RANGE = (500.0, 2500.0)  # kg/m^3
_ALPHA_RANGE = (1e-9, 1e-7)  # 1/Pa: 1 to 100 1/GPa
_RQ_MAX = 10e-6  # m


def _in_range(name, value, bounds, unit, scale=1.0):
    if not (bounds[0] <= value <= bounds[1]):
        raise InputError(f"{name} must be in [{bounds[0] * scale:g}, {bounds[1] * scale:g}] [{unit}], got "
                         f"{value * scale:g} {unit}")
    return value


def density(text):
    """The oil density [kg/m^3] and whether it was assumed."""
    from ..units import parse_quantity

    if text is None:
        return DEFAULT_DENSITY, True
    return _in_range("density", parse_quantity(text, "density", "density"), _RHO_RANGE, "kg/m^3"), False


def lubricant(viscosity, dynamic_viscosity, oil, temperature, viscosity_index, viscosity_100, density_text):
    """(eta [Pa s], nu [m^2/s] or None, description, inputs, notes) from the lubricant options."""
    from ..units import parse_quantity

    rho, assumed = density(density_text)
    notes = []
    if dynamic_viscosity is not None:
        if any(x is not None for x in (viscosity, oil, temperature, viscosity_index, viscosity_100)):
            raise InputError("dynamic-viscosity: give --dynamic-viscosity, or --viscosity, or --oil with "
                             "--temperature, not more than one")
        eta = _in_range("dynamic-viscosity", parse_quantity(dynamic_viscosity, "dynamic_viscosity",
                                                              "dynamic-viscosity"), _ETA_RANGE, "mPa s", 1e3)
        return eta, None, f"eta = {eta * 1e3:.4g} mPa s (given)", {"dynamic_viscosity_mPas": eta * 1e3}, notes
    lv = lubricant_viscosity(viscosity, oil, temperature, viscosity_index, viscosity_100, required=True)
    eta = lv.viscosity * rho
    _in_range("viscosity", eta, _ETA_RANGE, "mPa s (dynamic, nu rho)", 1e3)
    if assumed:
        notes.append(f"density: not given, so {DEFAULT_DENSITY:g} kg/m^3 (a typical mineral oil, an estimate) "
                     "turns the kinematic viscosity into the dynamic one; give --density")
    inputs = {**lv.inputs, "density_kg_m3": rho, "density_assumed": assumed, "dynamic_viscosity_mPas": eta * 1e3}
    return eta, lv.viscosity, f"{lv.description}; eta = {eta * 1e3:.4g} mPa s", inputs, notes


def roughness(both, ball, race):
    """(Rq_ball, Rq_race) [m] from --roughness or --roughness-ball/--roughness-race."""
    if both is not None and (ball is not None or race is not None):
        raise InputError("roughness: give --roughness, or --roughness-ball and --roughness-race, not both")
    if both is not None:
        ball = race = both
    out = []
    for name, text in (("roughness-ball" if both is None else "roughness", ball),
                       ("roughness-race" if both is None else "roughness", race)):
        rq = _DEFAULT_ROUGHNESS if text is None else parse_length(text, name, "um", zero=True)
        out.append(_in_range(name, rq, (0.0, _RQ_MAX), "um", 1e6))
    if out[0] == 0 and out[1] == 0:
        raise InputError("roughness must not be 0 for both surfaces [um] (Lambda would be infinite)")
    return tuple(out)


def pressure_viscosity(text):
    from ..units import parse_quantity

    if text is None:
        return None
    return _in_range("pressure-viscosity-coefficient", parse_quantity(text, "inverse_pressure",
                     "pressure-viscosity-coefficient"), _ALPHA_RANGE, "1/GPa", 1e9)


@finite('film')
def document(parsed, *, bearing_file=None, catalog=None):
    """The document of ``bearinglab film ... --json`` for a checked request.

    Parameters
    ----------
    parsed : Parsed
        A request of the calculation ``film``.
    bearing_file, catalog : Path, optional
        The command line's bearing file and user catalog (the web gives neither).

    Returns
    -------
    dict or list of dict
        One document per speed (a list for several): the film at every ball (``balls``), the smallest
        film, Lambda and the regime, ``inputs`` and ``warnings`` (with the bearing's provenance notes).

    Raises
    ------
    RunFailure
        An input the model refuses, naming its field.
    """
    with failures(parsed.calculation):
        return json_value(_document(parsed, bearing_file, catalog))


def _document(parsed, bearing_file, catalog):
    import numpy as np

    from .. import film as film_model
    from .. import tables
    from ..film.analysis import LOADS_AT
    from ..units import RPM
    from . import _mounting, _preload
    from .load_distribution import clearance_source

    def text(name):
        return str(parsed.given[name]).strip() if name in parsed.given else None

    roller = _rollers.bearing_of(parsed, bearing_file=bearing_file, catalog=catalog)
    if roller is not None:  # the line-contact film of every roller (issue 32)
        return _roller_film(parsed, roller)
    v = parsed.values
    geometry = {k: (v[k] if k in ("balls", "inner_conformity", "outer_conformity") else text(k))
                for k in _GEOMETRY if k in parsed.given}
    b = resolve_bearing(text("bearing"), bearing_file, catalog, **geometry)
    from ..bearing import check_model

    check_model(b, "film")
    loads = five_loads(*(text(k) for k in ("fx", "fy", "fz", "mx", "my", "radial_load", "axial_load")))
    speed = text("speed")
    if speed is None:
        raise InputError("speed: give the inner-ring speed, e.g. --speed '6000 rpm' (no film forms at rest)")
    w = parse_speeds(speed, pitch_diameter=b.require("pitch_diameter"), zero=False)
    # the fits, temperatures and speed set the clearance the ball loads run with, as in the load distribution
    b, mounted = _mounting.operating_bearing(b, float(np.max(w)), {k: text(k) for k in _mounting.NAMES})
    loads_at = v.get("loads_at", "speed")
    choice("loads-at", loads_at, LOADS_AT)
    rq_ball, rq_race = roughness(text("roughness"), text("roughness_ball"), text("roughness_race"))
    alpha = pressure_viscosity(text("pressure_viscosity_coefficient"))
    temperature, lubrication = text("temperature"), v.get("lubrication")
    oil = {k: (v.get(k) if k == "viscosity_index" else text(k))
           for k in ("viscosity", "dynamic_viscosity", "oil", "viscosity_index", "viscosity_100")}
    auto = temperature is not None and temperature.lower() == "auto"
    if auto:
        eta, how, lub_inputs, notes = _auto_temperature(
            b, loads, w, oil["oil"], oil["viscosity"], oil["dynamic_viscosity"], oil["viscosity_index"],
            oil["viscosity_100"], text("density"), text("ambient"), text("thermal_resistance"),
            default_lubrication(lubrication, text("oil")), text("skf_constants"))
        nu = eta / lub_inputs["density_kg_m3"]
    else:
        if any(text(k) is not None for k in ("ambient", "thermal_resistance", "skf_constants")):
            raise InputError("temperature: --ambient, --thermal-resistance and --skf-constants go with "
                             "--temperature auto (the thermal balance)")
        eta, nu, how, lub_inputs, notes = lubricant(oil["viscosity"], oil["dynamic_viscosity"], oil["oil"],
                                                   temperature, oil["viscosity_index"],
                                                   oil["viscosity_100"], text("density"))
    cases = np.broadcast_to(np.asarray(loads, dtype=float), w.shape + (5,))
    starve = {}
    if lubrication is not None:
        from ..friction.skf import LUBRICATION_METHODS

        choice("lubrication", lubrication, list(LUBRICATION_METHODS))
        if nu is None:
            nu = eta / density(text("density"))[0]
        starve = {"lubrication": lubrication, "kinematic_viscosity": nu}
    r = _solve(film_model.film_analysis, b, cases, w, eta, alpha, roughness_ball=rq_ball,
               roughness_race=rq_race, loads_at=loads_at, **starve)
    notes = list(dict.fromkeys([*notes, *r.warnings]))
    preloaded, note = _preload.report(b, source=clearance_source(mounted, text("radial_clearance")))
    if note:  # issue 30: the film at the ball loads of the preloaded bearing
        notes.insert(0, note)
    notes += [n for n in dict.fromkeys(_catalog.provenance_notes(b)) if n not in notes]
    docs = []
    for k in range(w.size):
        doc = tables.film(r, (k,))
        doc["inputs"] = inputs_echo(b, fx_N=loads[0], fy_N=loads[1], fz_N=loads[2], mx_Nmm=loads[3] * 1e3,
                                    my_Nmm=loads[4] * 1e3, speed_rpm=float(w[k]) / RPM,
                                    loads_at=loads_at, **lub_inputs, lubricant=how,
                                    pressure_viscosity_coefficient_per_GPa=None if alpha is None
                                    else alpha * 1e9,
                                    roughness_ball_um=rq_ball * 1e6, roughness_race_um=rq_race * 1e6)
        temps = lub_inputs.get("bearing_temperature_degC")
        if isinstance(temps, list):  # temperature auto over several speeds: this case's temperature
            doc["inputs"]["bearing_temperature_degC"] = temps[k]
        doc.update(mounted)
        doc.update(preloaded)
        doc["warnings"] = notes
        docs.append(doc)
    return docs[0] if w.size == 1 else docs


def _auto_temperature(b, loads, w, oil, viscosity, dynamic_viscosity, viscosity_index, viscosity_100, density_text,
                      ambient, thermal_resistance, lubrication, skf_constants):
    """Temperature auto: the steady temperature of each case
    (:func:`bearinglab.calculations.temperature.steady_temperature`, as ``life`` takes it) and the oil's
    dynamic viscosity there; (eta per case, description, inputs, notes)."""
    import numpy as np

    from .temperature import steady_temperature

    r, how, inputs, notes = steady_temperature(b, loads, w, oil, viscosity, viscosity_index, viscosity_100, ambient,
                                               thermal_resistance, lubrication, skf_constants,
                                               dynamic_viscosity=dynamic_viscosity)
    rho, assumed = density(density_text)
    if assumed:
        notes.append(f"density: not given, so {DEFAULT_DENSITY:g} kg/m^3 (a typical mineral oil, an estimate) "
                     "turns the kinematic viscosity into the dynamic one; give --density")
    inputs = {**inputs, "density_kg_m3": rho, "density_assumed": assumed}
    t = np.atleast_1d(r.temperature)
    nu = np.atleast_1d(r.kinematic_viscosity)
    text = (f"{how} at the steady temperature {', '.join(f'{x - 273.15:.1f}' for x in t)} degC (thermal balance): "
            f"nu = {', '.join(f'{x * 1e6:.4g}' for x in nu)} cSt")
    return nu * rho, text, inputs, [*notes, *r.warnings]


def _roller_film(parsed, bearing):
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
    import warnings

    import numpy as np

    from .. import film as film_model
    from ..film import ehl
    from ..rollers import analysis
    from ..units import RPM
    from ._mounting import NAMES as MOUNTING
    from ._reading import text as _text
    from ._rollers import geometry_of, notes_of, operating, slices_of, spherical

    spherical(bearing, "the film")
    b = geometry_of(bearing)
    loads = five_loads(*(_text(parsed, k) for k in ("fx", "fy", "fz", "mx", "my", "radial_load", "axial_load")))
    speed = _text(parsed, "speed")
    if speed is None:
        raise InputError("speed: give the inner-ring speed, e.g. --speed '6000 rpm' (no film forms at rest)")
    w = parse_speeds(speed, pitch_diameter=b.pitch_diameter, zero=False)
    rq_roller, rq_race = roughness(_text(parsed, "roughness"), _text(parsed, "roughness_ball"),
                                             _text(parsed, "roughness_race"))
    alpha = pressure_viscosity(_text(parsed, "pressure_viscosity_coefficient"))
    oil = {k: (parsed.values.get(k) if k == "viscosity_index" else _text(parsed, k))
           for k in ("viscosity", "dynamic_viscosity", "oil", "viscosity_index", "viscosity_100")}
    temperature = _text(parsed, "temperature")
    notes = []
    if temperature is not None and temperature.lower() == "auto":
        eta, how, lub_inputs, notes = _auto_temperature(
            b, loads, w, oil["oil"], oil["viscosity"], oil["dynamic_viscosity"], oil["viscosity_index"],
            oil["viscosity_100"], _text(parsed, "density"), _text(parsed, "ambient"),
            _text(parsed, "thermal_resistance"), _text(parsed, "lubrication") or "oil-jet",
            _text(parsed, "skf_constants"))
    else:
        if any(_text(parsed, k) is not None for k in ("ambient", "thermal_resistance", "skf_constants")):
            raise InputError("temperature: --ambient, --thermal-resistance and --skf-constants go with "
                             "--temperature auto (the thermal balance)")
        eta, _, how, lub_inputs, notes = lubricant(oil["viscosity"], oil["dynamic_viscosity"], oil["oil"],
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
        doc = _roller_film_doc(r, f)
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


def _roller_film_doc(r, f):
    """One speed's film of the rollers, JSON-ready (null where a roller carries no load)."""
    import math

    import numpy as np

    from .._io import json_value

    hmin = np.fmin(f.minimum_inner, f.minimum_outer)
    loaded = np.isfinite(hmin)
    k = int(np.nanargmin(np.where(loaded, hmin, np.nan))) if loaded.any() else None
    rollers = [{"azimuth_deg": math.degrees(float(r.azimuth[j])), "load_N": float(r.roller_load[j]),
                "entrainment_velocity_m_s": float(f.entrainment_velocity),
                "film_central_inner_um": float(f.central_inner[j]) * 1e6,
                "film_min_inner_um": float(f.minimum_inner[j]) * 1e6,
                "film_central_outer_um": float(f.central_outer[j]) * 1e6,
                "film_min_outer_um": float(f.minimum_outer[j]) * 1e6,
                "lambda": float(f.film_parameter[j])} for j in range(len(r.roller_load))]
    return json_value({"film_min_um": None if k is None else float(hmin[k]) * 1e6,  # as a whole: nulls known by key
                       "lambda_min": None if k is None else float(f.film_parameter[k]),
                       "regime": None if k is None else str(f.regime[k]), "converged": bool(r.converged),
                       "rollers": rollers})


def _solve(model, *args, **kwargs):
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the result carries its warnings
        return model(*args, **kwargs)
