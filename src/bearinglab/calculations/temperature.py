"""The ``temperature`` document: the steady temperature of a bearing (issue 24), and the thermal-balance
inputs ``film`` and ``life`` read alike with their temperature ``auto``.

The temperature where the SKF friction power at the viscosity of that temperature equals the heat
carried away (:func:`bearinglab.thermal.thermal_balance`): to the ambient through a thermal resistance
(or ISO 15312's reference heat flow), and by an oil flow. The oil is an ISO VG grade with its viscosity
index or its viscosity at 100 degC. Where no steady state exists below the safe limit, a
thermal-runaway warning and no number. With ``reference_speed``, also ISO 15312's thermal reference
speed of the bearing (:func:`bearinglab.thermal.thermal_reference_speed`). The command line
(``bearinglab temperature``) and the web compute it here alike.

Functions
---------
document                   Parsed request -> the JSON document ``bearinglab temperature --json`` prints
oil_reference_viscosities  an ISO VG oil's nu40 and nu100, from its grade and VI or nu100
heat_options               the heat-balance inputs in SI, the notes on assumed values, their echo
skf_options                the SKF model's lubrication method and constants for a bearing
steady_temperature         temperature ``auto``: the thermal balance of each case, its temperature and
                           the oil's viscosity there (thermal runaway refused in one line)
"""

from __future__ import annotations

from .. import catalog as _catalog
from .._io import json_value
from ..errors import InputError
from ._failures import failures
from ._finite import finite
from ._inputs import (
    HOTTEST_OIL_DEGC,
    default_lubrication,
    inputs_echo,
    lubricant_viscosity,
    parse_speeds,
    parse_temperature,
    resolve_bearing,
)

__all__ = ["document", "heat_options", "oil_reference_viscosities", "skf_options", "steady_temperature"]

#: Defaults of the oil's properties when not given: typical mineral-oil values, estimates labelled as such
#: in the output (density 0.86-0.89 g/cm^3, specific heat 1.8-2.1 kJ/(kg K) between 20 and 100 degC).
DEFAULT_DENSITY = 870.0
DEFAULT_HEAT_CAPACITY = 1950.0
_ZERO_C = 273.15
_LUBRICATIONS = ("oil-jet", "oil-air", "grease", "oil-bath")
_HOTTEST = HOTTEST_OIL_DEGC  # the sanity bound on the balance's temperatures (issue 24)


def oil_reference_viscosities(oil, viscosity_index, viscosity_100):
    """(nu40, nu100 [m^2/s], description, inputs) of an ISO VG oil, by the shared oil options.

    Parameters
    ----------
    oil : str
        The ISO VG grade as typed ('VG32').
    viscosity_index : float or None
        The oil's viscosity index (default 95, assumed).
    viscosity_100 : str or None
        Its viscosity at 100 degC as typed, instead of the index.

    Returns
    -------
    tuple
        ``(nu40, nu100, description, inputs)``.
    """
    from ..ratings import lubrication

    if oil is None:
        raise InputError("oil: give --oil, an ISO VG grade (e.g. VG32), with --viscosity-index or --viscosity-100 "
                         "if known (its viscosity follows the temperature)")
    at100 = lubricant_viscosity(None, oil, "100 degC", viscosity_index, viscosity_100)
    nu100 = at100.viscosity
    grade = int(at100.inputs["oil"][2:])
    nu40 = lubrication.iso_vg_viscosity(grade)
    inputs = {k: v for k, v in at100.inputs.items() if k != "temperature_degC"}
    if "viscosity_index" in inputs:
        how = f"VG{grade}, VI {inputs['viscosity_index']:g}{' (assumed)' if inputs['viscosity_index_assumed'] else ''}"
    else:
        how = f"VG{grade}, nu100 {nu100 * 1e6:.4g} cSt"
    return nu40, nu100, how, inputs


def heat_options(b, ambient, thermal_resistance, oil_flow, oil_inlet_temperature, heat_capacity, density_text,
                 max_temperature):
    """The heat-balance options in SI, the notes on assumed values and the inputs echoed.

    Parameters
    ----------
    b : BallBearing
        The bearing.
    ambient, thermal_resistance, oil_flow, oil_inlet_temperature, heat_capacity, density_text, \
max_temperature : str or None
        The inputs as typed ('20 degC', '0.5 K/W', '0.5 l/min', ...).

    Returns
    -------
    tuple
        ``(options, notes, inputs)``: the keyword options of :func:`bearinglab.thermal.thermal_balance`
        (with ``ambient``), the notes on assumed values, the inputs echoed.
    """
    from .. import thermal
    from ..units import parse_quantity

    ta = parse_temperature(ambient, "ambient")
    t_max = parse_temperature(max_temperature, "max-temperature")
    if not t_max > ta:
        raise InputError(f"max-temperature must be above the ambient [degC], got {t_max - _ZERO_C:g} degC")
    if not t_max <= _ZERO_C + _HOTTEST:
        raise InputError(f"max-temperature must be <= {_HOTTEST:g} [degC], got {t_max - _ZERO_C:g} degC")
    notes, inputs = [], {"ambient_degC": ta - _ZERO_C, "max_temperature_degC": t_max - _ZERO_C}
    conductance = None
    if thermal_resistance is not None:
        r = parse_quantity(thermal_resistance, "thermal_resistance", "thermal-resistance")
        if not 1e-4 <= r <= 1e4:
            raise InputError(f"thermal-resistance must be in [0.0001, 10000] [K/W], got {r:g} K/W")
        conductance, inputs["thermal_resistance_K_W"] = 1.0 / r, r
    g_oil, t_in = 0.0, None
    if oil_flow is not None:
        q = parse_quantity(oil_flow, "volume_flow", "oil-flow")
        if not 0.0 <= q <= 1e-2:
            raise InputError(f"oil-flow must be in [0, 600] [l/min], got {q * 6e4:g} l/min")
        rho = DEFAULT_DENSITY if density_text is None else parse_quantity(density_text, "density", "density")
        if not 500.0 <= rho <= 2500.0:
            raise InputError(f"density must be in [500, 2500] [kg/m^3], got {rho:g} kg/m^3")
        cp = DEFAULT_HEAT_CAPACITY if heat_capacity is None else parse_quantity(heat_capacity, "specific_heat",
                                                                              "oil-heat-capacity")
        if not 500.0 <= cp <= 5000.0:
            raise InputError(f"oil-heat-capacity must be in [500, 5000] [J/(kg K)], got {cp:g} J/(kg K)")
        for name, text, value in (("density", density_text, DEFAULT_DENSITY),
                                  ("oil-heat-capacity", heat_capacity, DEFAULT_HEAT_CAPACITY)):
            if text is None:
                notes.append(f"{name}: not given, so {value:g} (a typical mineral oil, an estimate) is used for "
                             "the heat the oil flow carries; give --" + name)
        g_oil = thermal.oil_flow_conductance(q, rho, cp)
        inputs.update(oil_flow_l_min=q * 6e4, density_kg_m3=rho, oil_heat_capacity_J_kgK=cp)
        if oil_inlet_temperature is not None:
            t_in = parse_temperature(oil_inlet_temperature, "oil-inlet-temperature")
            if not t_in <= _ZERO_C + _HOTTEST:
                raise InputError(f"oil-inlet-temperature must be <= {_HOTTEST:g} [degC], got {t_in - _ZERO_C:g} degC")
            inputs["oil_inlet_temperature_degC"] = t_in - _ZERO_C
    elif oil_inlet_temperature is not None or heat_capacity is not None or density_text is not None:
        raise InputError("oil-flow: --oil-inlet-temperature, --oil-heat-capacity and --density describe an oil "
                         "flow; give --oil-flow")
    return {"ambient": ta, "conductance": conductance, "oil_flow_conductance": g_oil,
            "oil_inlet_temperature": t_in, "maximum_temperature": t_max}, notes, inputs


def skf_options(b, lubrication, constants, oil_level=None):
    """The SKF model's options for the bearing: its lubrication method (an oil bath with its oil level)
    and, for angular contact, the constants given (else SKF's single-row ones, for 40 deg bearings only:
    others refused in one line).

    Parameters
    ----------
    b : BallBearing
        The bearing.
    lubrication : str
        oil-jet, oil-air, grease or oil-bath.
    constants : str or None
        R1,R2,R3,S1,S2,S3 as typed.
    oil_level : str or None
        The oil bath's level H as typed ('5 mm'); needed with oil-bath, refused otherwise. Its drag loss
        factor V_M is SKF's diagram at H/d_m (:func:`bearinglab.friction.drag.drag_loss_factor`).

    Returns
    -------
    dict
        ``lubrication``, ``oil_level`` [m] of an oil bath and, where given, ``constants``
        (:class:`bearinglab.friction.SKFConstants`).
    """
    from .. import friction

    if lubrication not in _LUBRICATIONS:
        raise InputError(f"lubrication must be one of {list(_LUBRICATIONS)}, got {lubrication!r}")
    out = {"lubrication": lubrication}
    if lubrication == "oil-bath":
        if oil_level is None:
            raise InputError("oil-level: --lubrication oil-bath needs the oil level, e.g. --oil-level '5 mm' (H from "
                             "the lowest point of the outer raceway; V_M follows from SKF's diagram at H/d_m)")
        from . import _reading

        h = _reading.parse_length(oil_level, "oil-level", zero=True)
        dm = b.mean_diameter
        if h > dm / 2:
            raise InputError(f"oil-level must be <= d_m/2 = {dm / 2 * 1e3:g} mm [mm] (at most up to the bearing's "
                             f"centre), got {h * 1e3:g} mm")
        out["oil_level"] = h
    elif oil_level is not None:
        raise InputError("oil-level: --oil-level goes with --lubrication oil-bath")
    if constants is not None:
        try:
            values = [float(x) for x in constants.split(",")]
        except ValueError:
            values = []
        if len(values) != 6 or not all(v >= 0 and v < 1e6 for v in values):
            raise InputError(f"skf-constants must be six numbers >= 0, R1,R2,R3,S1,S2,S3, got {constants!r}")
        r1, r2, r3, s1, s2, s3 = values
        out["constants"] = friction.SKFConstants(r1, r2, s1, s2, r3, s3)
    elif b.type != "radial":  # SKF's table covers single-row 40 deg bearings; others are refused in one line
        friction.angular_contact_constants(b.contact_angle)
    return out


def steady_temperature(b, loads, w, oil, viscosity, viscosity_index, viscosity_100, ambient, thermal_resistance,
                       lubrication, skf_constants, dynamic_viscosity=None):
    """Temperature ``auto``: the steady temperature of each case (:func:`bearinglab.thermal.thermal_balance`).

    Parameters
    ----------
    b : BallBearing
        The bearing.
    loads : sequence of float
        (F_x, F_y, F_z, M_x, M_y) [N, N m]; the SKF model takes no tilting moment.
    w : float or array_like
        Inner-ring speed(s). [rad/s]
    oil, viscosity_index, viscosity_100 : str, float, str or None
        The oil by grade (its viscosity follows the temperature).
    viscosity, dynamic_viscosity : str or None
        Refused when given: a fixed viscosity does not follow the temperature.
    ambient, thermal_resistance, lubrication, skf_constants : str or None
        The heat-balance inputs as typed (ambient default 20 degC).

    Returns
    -------
    tuple
        ``(result, how, inputs, notes)``: the :class:`~bearinglab.thermal.ThermalBalance` (its
        ``temperature`` [K] and ``kinematic_viscosity`` [m^2/s] per case, its own ``warnings``), the
        oil in words, the inputs echoed (``temperature: "auto"`` and ``bearing_temperature_degC``) and
        the notes on assumed values.
    """
    import math

    import numpy as np

    from .. import thermal

    if viscosity is not None or dynamic_viscosity is not None:
        raise InputError("temperature: 'auto' needs the oil by grade (--oil VG32, with --viscosity-index or "
                         "--viscosity-100), whose viscosity follows the temperature; not --viscosity")
    if loads[3] or loads[4]:
        raise InputError("temperature: 'auto' takes the SKF friction model, which has no tilting moment; give "
                         "no --mx/--my")
    if lubrication == "oil-bath":
        raise InputError("lubrication: temperature 'auto' with an oil bath needs the bath's oil level, which this "
                         "command does not take; compute it with `bearinglab temperature --lubrication oil-bath "
                         "--oil-level ...` and give that temperature")
    nu40, nu100, how, oil_inputs = oil_reference_viscosities(oil, viscosity_index, viscosity_100)
    heat, notes, heat_inputs = heat_options(b, ambient or "20 degC", thermal_resistance, None, None, None,
                                            None, "150 degC")
    r = thermal.thermal_balance(b, math.hypot(loads[0], loads[1]), abs(loads[2]), w, heat.pop("ambient"), nu40,
                                nu100, **heat, **skf_options(b, lubrication, skf_constants))
    if not np.all(r.steady):
        from ..units import RPM

        bad = float(np.atleast_1d(w)[~np.atleast_1d(r.steady)][0]) / RPM
        raise InputError(f"temperature: no steady temperature below 150 degC at {bad:g} rpm (thermal runaway); "
                         "give the temperature, or more cooling (--thermal-resistance)")
    t = np.atleast_1d(r.temperature)
    inputs = {**oil_inputs, **heat_inputs, "temperature": "auto",
              "bearing_temperature_degC": (t - 273.15).tolist() if t.size > 1 else float(t[0] - 273.15)}
    return r, how, inputs, notes


def radial_axial(radial_load, axial_load):
    from ..units import parse_quantity

    fr = 0.0 if radial_load is None else parse_quantity(radial_load, "force", "radial-load")
    fa = 0.0 if axial_load is None else parse_quantity(axial_load, "force", "axial-load")
    for name, v in (("radial-load", fr), ("axial-load", fa)):
        if not v >= 0:
            raise InputError(f"{name} must be >= 0 [N], got {v:g} N")
    return fr, fa


@finite('temperature')
def document(parsed, *, bearing_file=None, catalog=None):
    """The document of ``bearinglab temperature ... --json`` for a checked request.

    Parameters
    ----------
    parsed : Parsed
        A request of the calculation ``temperature``.
    bearing_file, catalog : Path, optional
        The command line's bearing file and user catalog (the web gives neither).

    Returns
    -------
    dict or list of dict
        One document per speed (a list for several): temperature, viscosity, kappa, friction moment and
        power, heat dissipated, ``inputs`` and ``warnings`` (with the bearing's provenance notes).

    Raises
    ------
    RunFailure
        An input the balance refuses, naming its field.
    """
    with failures(parsed.calculation):
        return json_value(_document(parsed, bearing_file, catalog))


def _document(parsed, bearing_file, catalog):
    from .. import thermal
    from ..units import RPM

    def text(name, default=None):
        return str(parsed.given[name]).strip() if name in parsed.given else default

    v = parsed.values
    b = resolve_bearing(text("bearing"), bearing_file, catalog)
    speed = text("speed")
    if speed is None:
        raise InputError("speed: give the inner-ring speed, e.g. --speed '6000 rpm'")
    fr, fa = radial_axial(text("radial_load"), text("axial_load"))
    w = parse_speeds(speed, zero=False, pitch_diameter=b.pitch_diameter or b.mean_diameter)
    nu40, nu100, how, oil_inputs = oil_reference_viscosities(text("oil"), v.get("viscosity_index"),
                                                             text("viscosity_100"))
    heat, notes, heat_inputs = heat_options(b, text("ambient", "20 degC"), text("thermal_resistance"),
                                            text("oil_flow"), text("oil_inlet_temperature"),
                                            text("oil_heat_capacity"), text("density"),
                                            text("max_temperature", "150 degC"))
    lubrication = default_lubrication(v.get("lubrication"), text("oil"))  # the oil is required: oil-jet
    skf = skf_options(b, lubrication, text("skf_constants"), text("oil_level"))
    r = thermal.thermal_balance(b, fr, fa, w, heat.pop("ambient"), nu40, nu100, **heat, **skf)
    notes = list(dict.fromkeys([*notes, *r.warnings]))
    extra = {}
    if v.get("reference_speed"):  # ISO 15312 (bearinglab.thermal.thermal_reference_speed); one per bearing
        ref = thermal.thermal_reference_speed(b, **{k: x for k, x in skf.items() if k == "constants"})
        extra = json_value({"thermal_reference_speed_rpm": float(ref.speed / RPM),
                            "reference_heat_flow_W": float(ref.reference_heat_flow)})
        notes = list(dict.fromkeys([*notes, *ref.warnings]))
    from . import _preload

    preloaded, note = _preload.report(b, source="the bearing's clearance", model="SKF friction model of the balance")
    if note:  # issue 30: a bearing file with a zero or negative clearance
        notes.insert(0, note)
    notes += [n for n in dict.fromkeys(_catalog.provenance_notes(b)) if n not in notes]
    bath = {}
    if "oil_level" in skf:  # the oil bath: its level and SKF's V_M at H/d_m (ball-bearing curve)
        from ..friction.drag import drag_loss_factor

        bath = {"oil_level_mm": skf["oil_level"] * 1e3,
                "drag_loss_factor": float(drag_loss_factor(skf["oil_level"], b.mean_diameter, "ball"))}
    docs = [_doc(r, k, w.size) | extra | preloaded | {"inputs": inputs_echo(b, radial_load_N=fr, axial_load_N=fa,
                                                         speed_rpm=float(w[k]) / RPM,
                                                         lubrication=lubrication, **bath, **oil_inputs,
                                                         lubricant=how, **heat_inputs),
                                 "warnings": notes} for k in range(w.size)]
    return docs[0] if w.size == 1 else docs


def _doc(r, k, n):
    import numpy as np

    from ..tables import json_value

    def pick(name, scale=1.0, shift=0.0):
        return float(np.atleast_1d(getattr(r, name))[k]) * scale + shift

    return json_value({"bearing_temperature_degC": pick("temperature", shift=-_ZERO_C),  # nulls known by key
                       "viscosity_mm2_s": pick("kinematic_viscosity", 1e6), "friction_power_W": pick("friction_power"),
                       "heat_dissipated_W": pick("heat_dissipated"), "friction_moment_Nmm": pick("friction_moment", 1e3),
                       "kappa": pick("viscosity_ratio"), "iterations": int(np.atleast_1d(r.iterations)[k]),
                       "steady": bool(np.atleast_1d(r.steady)[k])})
