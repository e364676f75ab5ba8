r"""Inputs and bounds of the 5-DOF model of :mod:`bearinglab.quasistatic.combined` (private).

Split from that module (no module over 1000 lines); every name here is private to the combined-load
model and re-imported there.

Inputs
------
_flat_inputs    loads and speeds checked and broadcast to one flat batch
_held           the prescribed displacements broadcast with them (None if none)
_check_held     a prescribed displacement moves a groove centre by at most a ball diameter

The solver's bound (issue 29)
-----------------------------
_load_bound, _beyond_bound, _bound_reason   the largest load the balls carry with none compressed by more
                                            than a ball diameter, the cases beyond it, and why

References: those of :mod:`bearinglab.quasistatic.combined`.
"""

from __future__ import annotations

import numpy as np

from .._validate import as_float, check_nonnegative
from ..errors import InputError
from . import _combined_balls

__all__: list[str] = []


def _flat_inputs(loads, shaft_speed):
    f = as_float("loads", loads)
    if f.shape[-1:] != (5,):
        raise InputError(f"loads must have a last axis of length 5 (F_x, F_y, F_z, M_x, M_y), got shape {f.shape}")
    if not np.all(np.isfinite(f)):
        raise InputError("loads must be finite [N, N m]")
    w = check_nonnegative("shaft_speed", shaft_speed, "rad/s")
    if not np.all(np.isfinite(w)):
        raise InputError("shaft_speed must be finite [rad/s]")
    shape = np.broadcast_shapes(f.shape[:-1], w.shape)
    return (np.ascontiguousarray(np.broadcast_to(f, shape + (5,)).reshape(-1, 5)),
            np.broadcast_to(w, shape).ravel().astype(float), shape)


#: The solver's bound (issue 29): no ball is compressed by more than this many ball diameters.
_MAX_DEFLECTION = 1.0


def _load_bound(geo):
    """The largest force (and moment over d_m/2) the balls can carry with no contact compressed by more
    than a ball diameter: Z max_alpha max(K_i, K_o) D^1.5 [N]. Beyond it the rings would pass through the
    balls (as a prescribed displacement beyond a ball diameter, :func:`_check_held`): a unit mistake or an
    absurd load, never an answer."""
    c = np.linspace(0.0, 1.0, 65)  # cos(alpha): every contact angle
    k = max(np.max(np.exp(_combined_balls._log_k(geo, c, race)[0])) for race in (0, 1))
    return geo.z * k * (_MAX_DEFLECTION * geo.d) ** 1.5


def _beyond_bound(geo, loads):
    """Cases whose force or moment (over d_m/2) exceeds :func:`_load_bound`, and the bound [N]."""
    bound = _load_bound(geo)
    force = np.linalg.norm(loads[:, :3], axis=-1)
    moment = np.linalg.norm(loads[:, 3:], axis=-1) / (geo.dm / 2.0)
    return (force > bound) | (moment > bound), bound


def _bound_reason(bound):
    return (f"loads beyond what the bearing can carry: a force above {bound:.4g} N (or a moment above that "
            "times d_m/2) would compress a ball by more than its diameter, the solver's bound (a unit mistake?)")


def _held(f, w, shape, prescribed):
    """Loads, speeds and prescribed displacements broadcast to one flat batch (held None if none)."""
    if prescribed is None:
        return f, w, None, shape
    p = np.asarray(as_float("prescribed_displacement", prescribed), dtype=float)
    if p.shape[-1:] != (5,):
        raise InputError("prescribed_displacement must have a last axis of length 5 (delta_x, delta_y, delta_z, "
                         f"theta_x, theta_y; NaN for a freedom under load), got shape {p.shape}")
    if np.any(np.isinf(p)):
        raise InputError("prescribed_displacement must be finite or NaN (a freedom under load) [m, rad]")
    full = np.broadcast_shapes(shape, p.shape[:-1])
    f = np.broadcast_to(f.reshape(shape + (5,)), full + (5,)).reshape(-1, 5)
    w = np.broadcast_to(w.reshape(shape), full).ravel()
    held = np.ascontiguousarray(np.broadcast_to(p, full + (5,)).reshape(-1, 5))
    both = ~np.isnan(held) & (f != 0)
    if both.any():
        k, j = np.argwhere(both)[0]
        name = ("F_x", "F_y", "F_z", "M_x", "M_y")[j]
        raise InputError(f"loads: {name} = {f[k, j]:g} [N, N m] is given on a freedom whose displacement is "
                         "prescribed; give each freedom either a load or a displacement (its reaction is "
                         "computed)")
    if np.all(np.isnan(held)):
        return np.ascontiguousarray(f), np.ascontiguousarray(w), None, full
    return np.ascontiguousarray(f), np.ascontiguousarray(w), held, full


def _check_held(geo, held):
    """A prescribed displacement may move a groove-curvature centre by at most one ball diameter (tilts
    at the pitch radius d_m/2): beyond that the rings would pass through the balls, which no load can
    do; such an input is a unit mistake (InputError naming the freedom and the limit)."""
    names = ("delta_x", "delta_y", "delta_z", "theta_x", "theta_y")
    arm = np.array([1.0, 1.0, 1.0, geo.dm / 2.0, geo.dm / 2.0])
    with np.errstate(invalid="ignore"):
        bad = np.abs(held) * arm > geo.d
    if bad.any():
        k, j = np.argwhere(bad)[0]
        unit, scale = ("mm", 1e3) if j < 3 else ("mrad", 1e3)
        raise InputError(f"prescribed_displacement: {names[j]} = {held[k, j] * scale:.6g} {unit} moves the rings by "
                         f"more than one ball diameter (D = {geo.d * 1e3:.6g} mm"
                         + (f"; a tilt at most {geo.d / arm[j] * 1e3:.6g} mrad at the pitch radius)" if j >= 3
                            else ")"))
