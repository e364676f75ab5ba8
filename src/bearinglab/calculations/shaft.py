"""Shaft systems (issue 33) as a calculation: the document of ``bearinglab shaft FILE --json``, and its figure.

The request's ``model`` is the shaft-system file as text (TOML or JSON, the format of
:mod:`bearinglab.shaft.reading`); ``speed`` replaces the file's speed, ``stiffness_at`` asks for the
direct stiffness at a position, ``modes`` for the lowest bending frequencies and mode shapes,
``campbell`` for those frequencies over a list of speeds, ``elements`` for a finer mesh. A file with
``[[cases]]`` gets its load spectrum's lives (Palmgren-Miner) too. Everything is computed by the public
functions of :mod:`bearinglab.shaft`, in SI, and shown here in engineering units.

Functions
---------
document   Parsed -> the document (supports, system life, deflection, stiffness, modes, spectrum)
figure     a document -> the shaft drawn to scale above its deflection, slope and bending-moment lines
"""

from __future__ import annotations

import math
import warnings

import numpy as np

from ..errors import InputError
from ._failures import failures

__all__ = ["document", "figure"]

_UM, _MM, _MRAD = 1e-6, 1e-3, 1e-3
_RPM = 2 * math.pi / 60
_LIVES = (("basic_rating_life", "basic_rating_life_h"), ("modified_rating_life", "modified_rating_life_h"),
          ("reference_rating_life", "reference_rating_life_h"),
          ("modified_reference_rating_life", "modified_reference_rating_life_h"))


def _value(parsed, name, kind):
    """A field's value in SI: checked by :func:`~bearinglab.calculations.parse` (the web), or the text as
    given (the command line's unchecked request), read here; None when not given."""
    from ..units import parse_quantity, parse_values

    if name not in parsed.given:
        return None
    v = parsed.values.get(name, parsed.given[name])
    if not isinstance(v, str):
        return v
    with failures(parsed, name):
        if kind == "int":
            try:
                return int(v.strip())
            except ValueError:
                raise InputError(f"{name}: expected a whole number, got {v!r}") from None
        if kind == "speeds":
            return parse_values(v, "speed", name)
        return parse_quantity(v, kind, name)


def _num(x, scale=1.0):
    x = float(x)
    return None if not math.isfinite(x) else x / scale + 0.0


def _hours(revolutions, speed):
    if revolutions is None or speed == 0:
        return None
    return _num(np.asarray(revolutions).item() / (abs(speed) / (2 * math.pi)) / 3600.0)


def document(parsed, *, catalog=None):
    """The document of ``bearinglab shaft FILE ... --json`` for a checked request.

    Parameters
    ----------
    parsed : Parsed
        A request of the calculation ``shaft`` (:func:`bearinglab.calculations.parse`): ``model`` the
        file's text.
    catalog : str or Path, optional
        The command line's user catalog (for the bearings' names; the web takes none).

    Returns
    -------
    dict
        ``shaft``, ``speed_rpm``, ``supports`` (the load each takes, F and M, its displacement and
        tilt, each bearing's loads, lives, s0, largest contact pressure and stiffness), ``system_life_h``
        and ``system_lives_h``, ``deflection`` (a row per node: every support and load position),
        ``stiffness_at``, ``natural_frequencies_Hz`` and ``modes``, ``campbell``, ``spectrum``,
        ``applied_loads``, ``gears``, ``pulleys``, ``equilibrium``, ``convergence``, ``inputs`` and
        ``warnings``.

    Raises
    ------
    RunFailure
        An input the calculation refuses, naming its field (``model`` for the file's fields, the
        message naming the table and key).
    """
    from .. import catalog as _catalog
    from .. import shaft

    text = parsed.values.get("model", parsed.given.get("model"))
    with failures(parsed, "model"):
        doc = shaft.from_text(text, catalog=catalog)
    system = doc.system
    speed = _value(parsed, "speed", "speed")
    elements = _value(parsed, "elements", "int")
    with failures(parsed, "speed" if speed is not None else "elements"):
        if speed is not None:
            system = system.replace(speed=float(speed))
        if elements is not None:
            system = system.replace(elements=int(elements))
    at = _value(parsed, "stiffness_at", "length")
    count = _value(parsed, "modes", "int") or 0
    speeds = _value(parsed, "campbell", "speeds")
    with failures(parsed, "stiffness_at" if at is not None else "model"):
        state = shaft.solve(system, extra=() if at is None else (float(at),))
    w = float(system.speed)
    with failures(parsed, "model"):
        states = shaft.bearing_states(state, life=w != 0, **doc.lubricant)
    notes = list(state.warnings)
    supports, lives, slopes = _supports(state, states, w, notes)
    out = {"shaft": _shaft(system, state), "speed_rpm": _num(w, _RPM)}
    out["supports"] = supports
    out.update(_system_lives(lives, slopes, w, notes))
    out["deflection"] = _deflection(state)
    out["stiffness_at"] = None
    if at is not None:
        with failures(parsed, "stiffness_at"):
            st = shaft.stiffness_at(state, float(at))
        k = st.stiffness[0]
        out["stiffness_at"] = {"position_mm": _num(at, _MM), "stiffness_x_N_per_um": _num(k[0] * _UM),
                               "stiffness_y_N_per_um": _num(k[1] * _UM), "stiffness_z_N_per_um": _num(k[2] * _UM),
                               "tilt_stiffness_x_Nm_per_mrad": _num(k[3] * _MRAD),
                               "tilt_stiffness_y_Nm_per_mrad": _num(k[4] * _MRAD)}
    out["natural_frequencies_Hz"], out["modes"] = None, None
    if count:
        with failures(parsed, "modes"):
            m = shaft.natural_modes(state, int(count))
        out["natural_frequencies_Hz"] = [_num(f) for f in m.frequency]
        out["modes"] = [{"frequency_Hz": _num(f), "whirl": m.whirl[i] or None,
                         "shape": [{"z_mm": _num(z, _MM), "x": _num(s[0]), "y": _num(s[1])}
                                   for z, s in zip(m.z, m.shape[i], strict=True)]}
                        for i, f in enumerate(m.frequency)]
        if m.rigid:
            notes.append(f"modes: {m.rigid} rigid-body mode(s) left out: a freedom of the shaft that no support "
                         "holds at the operating point (a bearing without load inside its clearance)")
        if len(m.frequency) < count:
            notes.append(f"modes: {len(m.frequency)} bending modes found, {count} asked for (the mesh has too few "
                         "elements; give elements)")
    out["campbell"] = None
    if speeds is not None:
        with failures(parsed, "campbell"):
            c = shaft.campbell(system, speeds, max(int(count), 4))
        out["campbell"] = {"speed_rpm": [_num(x, _RPM) for x in c.speed],
                           "frequency_Hz": [[_num(f) for f in row] for row in c.frequency],
                           "whirl": [list(x) for x in c.whirl]}
    out["spectrum"] = None
    if doc.time_share is not None:
        with failures(parsed, "model"):
            sp = shaft.load_spectrum(system, doc.case_speed if speed is None else np.full(len(doc.time_share), w),
                                     doc.case_factor, doc.time_share, **doc.lubricant)
        out["spectrum"] = _spectrum(sp, doc.case_names, slopes)
    out["applied_loads"], out["gears"], out["pulleys"] = _applied(system, state)
    out["equilibrium"] = _equilibrium(state)
    out["convergence"] = {"converged": bool(state.converged[0]), "iterations": int(state.iterations[0]),
                          "residual": _num(state.residual[0]), "tolerance": shaft.statics.TOL}
    out["inputs"] = {"speed_rpm": _num(w, _RPM), "stiffness_at_mm": None if at is None else _num(at, _MM),
                     "modes": int(count), "campbell_rpm": None if speeds is None else [_num(x, _RPM) for x in speeds],
                     "elements": int(len(state.assembly.mesh.z) - 1), "lubricant": {
                         k: (v if isinstance(v, str) else _num(v)) for k, v in doc.lubricant.items()}}
    provenance = []
    for r in state.assembly.rows:
        provenance += _catalog.provenance_notes(r.bearing)
    out["warnings"] = list(dict.fromkeys(notes + provenance))
    return out


def _shaft(system, state):
    secs, ends = system.shaft.sections, system.shaft.ends
    mat = system.shaft.material
    mass = sum(mat.density * math.pi * (s.diameter**2 - s.bore**2) / 4 * s.length for s in secs)
    return {"length_mm": _num(system.length, _MM),
            "sections": [{"start_mm": _num(a, _MM), "length_mm": _num(s.length, _MM),
                          "diameter_mm": _num(s.diameter, _MM), "bore_mm": _num(s.bore, _MM)}
                         for a, s in zip(ends, secs, strict=False)],
            "material": {"name": mat.name, "elastic_modulus_GPa": _num(mat.elastic_modulus, 1e9),
                         "poisson_ratio": mat.poisson_ratio, "density_kg_per_m3": mat.density},
            "mass_kg": _num(mass), "elements": int(len(state.assembly.mesh.z) - 1),
            "nodes": len(state.assembly.mesh.z)}


def _row(state, j, bs, w, notes):
    """One bearing's entry: loads and displacement in its own frame, lives, s0, pressure, stiffness."""
    r = state.assembly.rows[j]
    b = r.bearing
    f, d = state.row_force[0, j], state.row_displacement[0, j]
    k = state.row_stiffness[0, j]
    entry = {"bearing": b.designation, "position_mm": _num(r.position, _MM), "orientation": r.orientation,
             "width_mm": _num(b.width, _MM) if b.width else None,
             "bore_mm": _num(b.bore, _MM) if b.bore else None,
             "outside_diameter_mm": _num(b.outside_diameter, _MM) if b.outside_diameter else None,
             "loads": {"fx_N": _num(f[0]), "fy_N": _num(f[1]), "fz_N": _num(f[2]), "mx_Nm": _num(f[3]),
                       "my_Nm": _num(f[4])},
             "radial_load_N": _num(math.hypot(f[0], f[1])), "axial_load_N": _num(abs(f[2])),
             "displacement": {"dx_um": _num(d[0], _UM), "dy_um": _num(d[1], _UM), "dz_um": _num(d[2], _UM),
                              "tilt_x_mrad": _num(d[3], _MRAD), "tilt_y_mrad": _num(d[4], _MRAD)},
             "axial_offset_um": _num(r.offset, _UM),
             "stiffness_x_N_per_um": _num(k[0, 0] * _UM), "stiffness_y_N_per_um": _num(k[1, 1] * _UM),
             "stiffness_z_N_per_um": _num(k[2, 2] * _UM), "tilt_stiffness_x_Nm_per_mrad": _num(k[3, 3] * _MRAD),
             "tilt_stiffness_y_Nm_per_mrad": _num(k[4, 4] * _MRAD)}
    ld, lf = bs.load_distribution, bs.life
    if ld is not None:
        entry["max_ball_load_N"] = _num(np.nanmax(ld.ball_load_inner[0]))
        p = max(float(np.nanmax(ld.max_pressure_inner[0])), float(np.nanmax(ld.max_pressure_outer[0])))
        entry["max_contact_pressure_MPa"] = _num(p, 1e6)
        notes += [f"{r.name}: {m}" for m in ld.warnings]
    else:
        entry["max_ball_load_N"] = entry["max_contact_pressure_MPa"] = None
    if lf is not None:
        entry["equivalent_dynamic_load_N"] = _num(np.ravel(lf.equivalent_dynamic_load)[0])
        for key, name in _LIVES:
            v = getattr(lf, key)
            entry[name] = None if v is None else _hours(np.ravel(v)[0], w)
        entry["basic_rating_life_Mrev"] = _num(np.ravel(lf.basic_rating_life)[0], 1e6)
        entry["static_safety_factor"] = _num(np.ravel(lf.static_safety_factor)[0])
        notes += [f"{r.name}: {m}" for m in lf.warnings if "reference lives" not in m]
    else:
        for _, name in _LIVES:
            entry[name] = None
        entry["equivalent_dynamic_load_N"] = entry["basic_rating_life_Mrev"] = None
        entry["static_safety_factor"] = None
    return entry


def _supports(state, states, w, notes):
    from ..life import weibull_slope
    from ..shaft.model import BearingSetSupport, BearingSupport, LinearSupport

    out, lives, slopes = [], [], []
    system = state.assembly.system
    for k, s in enumerate(system.supports):
        kind = {BearingSupport: "bearing", BearingSetSupport: "bearing_set", LinearSupport: "linear"}.get(type(s), "rigid")
        ld, dp = state.support_loads[0, k], state.support_displacement[0, k]
        entry = {"name": s.name, "kind": kind, "position_mm": _num(s.position, _MM), "axial": bool(s.axial),
                 "force_x_N": _num(ld[0]), "force_y_N": _num(ld[1]), "force_z_N": _num(ld[2]),
                 "moment_x_Nm": _num(ld[3]), "moment_y_Nm": _num(ld[4]),
                 "displacement_x_um": _num(dp[0], _UM), "displacement_y_um": _num(dp[1], _UM),
                 "displacement_z_um": _num(dp[2], _UM), "tilt_x_mrad": _num(dp[3], _MRAD),
                 "tilt_y_mrad": _num(dp[4], _MRAD)}
        rows = [j for j, r in enumerate(state.assembly.rows) if r.support == k]
        if rows:
            entry["bearing"] = state.assembly.rows[rows[0]].bearing.designation
            entry["bearings"] = [_row(state, j, states[j], w, notes) for j in rows]
            for j, e in zip(rows, entry["bearings"], strict=True):
                lives.append({name: e[name] for _, name in _LIVES})
                slopes.append(weibull_slope(state.assembly.rows[j].bearing))
            if kind == "bearing":  # a single bearing: its lives at the support's level too
                first = entry["bearings"][0]
                for key in ("basic_rating_life_h", "modified_rating_life_h", "reference_rating_life_h",
                            "modified_reference_rating_life_h", "basic_rating_life_Mrev", "static_safety_factor",
                            "max_contact_pressure_MPa", "max_ball_load_N", "equivalent_dynamic_load_N"):
                    entry[key] = first[key]
        out.append(entry)
    return out, lives, slopes


def _system_lives(lives, slopes, w, notes):
    from ..life import system_life

    out = {}
    for _, name in _LIVES:
        values = [row[name] for row in lives]
        if not values or any(v is None for v in values):
            out[name] = None
            continue
        out[name] = _num(system_life(np.array(values, dtype=float), np.array(slopes)))
    if lives and w == 0:
        notes.append("speed: the shaft stands still, so no bearing has a life in hours; give speed")
    return {"system_life_h": out["basic_rating_life_h"], "system_lives_h": out}


def _deflection(state):
    from ..shaft import internal_loads

    system = state.assembly.system
    q = internal_loads(state)
    u = state.displacement[0]
    labels = {}
    for s in system.supports:
        labels.setdefault(round(s.position, 9), []).append(s.name)
    for r in state.assembly.rows:
        if round(r.position, 9) not in labels:
            labels.setdefault(round(r.position, 9), []).append(r.name)
    for kind in ("loads", "gears", "pulleys", "masses"):
        for i, item in enumerate(getattr(system, kind)):
            labels.setdefault(round(item.position, 9), []).append(item.name or f"{kind}[{i}]")
    rows = []
    for i, z in enumerate(q.z):
        m = q.bending_moment[0, i]
        v = q.shear_force[0, i]
        rows.append({"z_mm": _num(z, _MM), "at": ", ".join(labels.get(round(float(z), 9), [])),
                     "displacement_x_um": _num(u[i, 0], _UM), "displacement_y_um": _num(u[i, 1], _UM),
                     "displacement_z_um": _num(u[i, 2], _UM), "deflection_um": _num(math.hypot(u[i, 0], u[i, 1]), _UM),
                     "slope_x_mrad": _num(u[i, 4], _MRAD), "slope_y_mrad": _num(-u[i, 3], _MRAD),
                     "twist_mrad": _num(u[i, 5], _MRAD),
                     "shear_force_x_N": _num(v[0]), "shear_force_y_N": _num(v[1]),
                     "shear_force_N": _num(math.hypot(v[0], v[1])), "axial_force_N": _num(q.axial_force[0, i]),
                     "bending_moment_x_Nm": _num(m[0]), "bending_moment_y_Nm": _num(m[1]),
                     "bending_moment_Nm": _num(math.hypot(m[0], m[1])), "torque_Nm": _num(q.torque[0, i])})
    return rows


def _applied(system, state):
    from ..shaft.model import gear_loads, pulley_loads

    w = system.speed
    loads = []
    for ld in system.loads:
        loads.append({"name": ld.name, "kind": "load", "position_mm": _num(ld.position, _MM),
                      "force_N": [_num(x) for x in ld.vector[:3]], "moment_Nm": [_num(x) for x in ld.vector[3:]]})
    gears = []
    for g in system.gears:
        v = gear_loads(g, w if w else 1.0) if g.torque is not None or w else np.zeros(6)
        gears.append({"name": g.name, "position_mm": _num(g.position, _MM), "pitch_diameter_mm": _num(g.pitch_diameter, _MM),
                      "torque_Nm": _num(v[5]), "tangential_force_N": _num(2 * abs(v[5]) / g.pitch_diameter),
                      "force_N": [_num(x) for x in v[:3]], "moment_Nm": [_num(x) for x in v[3:]]})
        loads.append({"name": g.name, "kind": "gear", "position_mm": _num(g.position, _MM),
                      "force_N": [_num(x) for x in v[:3]], "moment_Nm": [_num(x) for x in v[3:]]})
    pulleys = []
    for p in system.pulleys:
        v = pulley_loads(p)
        pulleys.append({"name": p.name, "position_mm": _num(p.position, _MM), "force_N": [_num(x) for x in v[:3]],
                        "torque_Nm": _num(v[5])})
        loads.append({"name": p.name, "kind": "pulley", "position_mm": _num(p.position, _MM),
                      "force_N": [_num(x) for x in v[:3]], "moment_Nm": [_num(x) for x in v[3:]]})
    return loads, gears, pulleys


def _equilibrium(state):
    """The applied loads against the supports' loads, forces and moments about z = 0."""
    z = state.assembly.mesh.z
    f = state.applied[0].reshape(-1, 6)
    applied_f = f[:, :3].sum(axis=0)
    applied_m = f[:, 3:].sum(axis=0) + np.array([-(z * f[:, 1]).sum(), (z * f[:, 0]).sum(), 0.0])
    sl = state.support_loads[0]
    pos = np.array([s.position for s in state.assembly.system.supports])
    sup_f = sl[:, :3].sum(axis=0)
    sup_m = sl[:, 3:].sum(axis=0) + np.array([-(pos * sl[:, 1]).sum(), (pos * sl[:, 0]).sum(), 0.0])
    sup_m[2] -= state.torsion_reaction[0]
    arm = max(state.assembly.length_scale, 1e-300)
    scale = max(np.abs(applied_f).max(), np.abs(applied_m).max() / arm, np.abs(sl[:, :3]).max(), 1e-300)
    error = max(np.abs(applied_f - sup_f).max(), np.abs(applied_m - sup_m).max() / arm) / scale
    return {"applied_force_N": [_num(x) for x in applied_f], "support_force_N": [_num(x) for x in sup_f],
            "applied_moment_Nm": [_num(x) for x in applied_m], "support_moment_Nm": [_num(x) for x in sup_m],
            "relative_error": _num(error)}


def _spectrum(sp, names, slopes):
    cases = [{"name": names[k], "time_share": _num(sp.time_share[k]), "speed_rpm": _num(sp.speed[k], _RPM),
              "factor": _num(sp.factor[k]), "revolution_share": _num(sp.revolution_share[k])}
             for k in range(len(sp.time_share))]
    bearings = []
    for j, name in enumerate(sp.names):
        e = {"name": name}
        for key, col in _LIVES:
            v = sp.bearing_life[key]
            e[col] = None if v is None else _num(sp.hours(v[j]))
        bearings.append(e)
    system = {col: (None if sp.system_life[key] is None else _num(sp.hours(sp.system_life[key])))
              for key, col in _LIVES}
    return {"cases": cases, "mean_speed_rpm": _num(sp.mean_speed, _RPM), "bearings": bearings,
            "system_life_h": system["basic_rating_life_h"], "system_lives_h": system}


def figure(doc):
    """The shaft drawn to scale above its deflection, slope and bending-moment lines.

    Parameters
    ----------
    doc : dict
        A document of :func:`document`.

    Returns
    -------
    matplotlib.figure.Figure
    """
    from ..plots import shaft as shaft_plots

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return shaft_plots.overview(doc, title=f"Shaft system at {doc['speed_rpm']:g} rpm")
