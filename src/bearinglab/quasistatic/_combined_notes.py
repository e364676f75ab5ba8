"""Warnings of a solved combined-load batch (private; :mod:`bearinglab.quasistatic.combined` and
:mod:`bearinglab.quasistatic.sets` call them).

Warnings
--------
notes           light load at speed, friction beyond the raceway-control limit, angular-contact rules
"""

from __future__ import annotations

import math

import numpy as np

from .ball import FRICTION_WARNING_LIMIT
from .light_load import light_load_warnings

__all__ = ["notes"]


def notes(geo, loads, w, out, ok):
    """The warnings of a solved batch (light load, low-shoulder contact, friction); ``loads`` None for a
    bearing in a set (its mates hold it axially, so only its balls' angles are judged)."""
    msgs = []
    sel = np.flatnonzero(ok & (w > 0))
    if sel.size:
        qi, ai = out["ball_load_inner"][sel], out["contact_angle_inner"][sel]
        thrust = np.abs(np.sum(qi * np.sin(ai), axis=1))
        radial = np.abs(np.sum(qi * np.cos(ai) * np.exp(1j * geo.psi), axis=1))  # |sum Q cos(a) e^(i psi)|
        loaded = np.where(qi > 0, 1.0, np.nan)
        if geo.elements is None:
            msgs += light_load_warnings(thrust, ai * loaded, out["contact_angle_outer"][sel] * loaded, w[sel], geo.z,
                                        geo.d, geo.dm, geo.a0, density=geo.mass / (math.pi * geo.d**3 / 6.0),
                                        case_index=sel, radial_load=radial, bearing_type=geo.kind,
                                        inner_conformity=geo.fi, outer_conformity=geo.fo)
        else:  # the other types at speed (two rows): the outer angle of each row against its own free angle
            msgs += _rows_outer_angle(geo, ai * loaded, out["contact_angle_outer"][sel] * loaded, sel)
        mu = 2.0 * np.abs(out["gyroscopic_moment"][sel]) / (geo.d * out["ball_load_outer"][sel])
        mu = np.where(qi > 0, mu, 0.0)
        if geo.control == "outer" and np.any(mu > FRICTION_WARNING_LIMIT):
            k = int(np.argmax(np.max(mu, axis=1)))
            msgs.append(f"outer-raceway control needs a friction coefficient up to {np.max(mu):.3g} > "
                        f"{FRICTION_WARNING_LIMIT:g} (case {sel[k]}): the balls would spin or skid")
    if geo.kind == "angular":
        msgs += _angular_notes(loads, out, ok)
    return tuple(msgs)


def _rows_outer_angle(geo, ai, ao, sel):
    """The light-load criterion of a row at speed (:func:`.light_load.light_load`: the outer contact angle
    driven below a fraction of the free angle) for the rows of a double-row or self-aligning bearing, each
    row's angles taken on its own side (the minimum load 0.01 C needs the bearing's C, which the model of
    these types does not compute from the geometry: see ``bearinglab life``)."""
    from .light_load import OUTER_ANGLE_FRACTION

    # as light_load: |alpha_o| < 0.1 alpha0 while |alpha_i| > alpha0, each row on its own side (a deep-groove
    # row on either)
    sign = geo.elements.sign if geo.kind != "double-row-radial" else np.sign(ai)
    with np.errstate(invalid="ignore"):
        lost = np.any((np.abs(ao) < OUTER_ANGLE_FRACTION * geo.a0) & (sign * ai > geo.a0), axis=1) \
            if geo.a0 > 0 else np.zeros(len(ao), dtype=bool)
    if not lost.any():
        return []
    k = int(np.flatnonzero(lost)[0])
    return [(f"light load: the outer contact angle of a row is driven to zero in {int(lost.sum())} case(s) (below "
             f"{OUTER_ANGLE_FRACTION:g} x the free angle), e.g. case {sel[k]}: the load is too small for the speed")]


def _angular_notes(loads, out, ok):
    """Warnings of a single angular-contact bearing: no thrust to hold its balls on the high shoulder, and
    balls loaded at a negative contact angle (against its low shoulder)."""
    msgs = []
    unheld = np.zeros_like(ok) if loads is None else ok & (loads[:, 2] <= 0) & np.any(loads != 0, axis=1)
    if unheld.any():
        k = int(np.flatnonzero(unheld)[0])
        msgs.append(f"{int(unheld.sum())} case(s) load a single angular-contact bearing with a thrust F_z <= 0 "
                    f"(first: case {k}, F_z = {loads[k, 2] + 0.0:.6g} N): it cannot carry them as an "
                    "angular-contact bearing, which needs a thrust F_z > 0 to hold its balls on the high "
                    "shoulder; without one they run on the groove bottom (alpha = 0) or against the low "
                    "shoulder, which this full-groove solution does not check (add the thrust, turn the "
                    "bearing round, or mount it in a set)")
    low = np.any((out["ball_load_inner"] > 0) & (out["contact_angle_inner"] < 0), axis=1) & ok
    if low.any():
        msgs.append(f"{int(low.sum())} case(s) load balls at a negative contact angle, against the low "
                    f"shoulder of an angular-contact bearing (first: case {int(np.flatnonzero(low)[0])}); "
                    "the model assumes a full groove there")
    return msgs
