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
