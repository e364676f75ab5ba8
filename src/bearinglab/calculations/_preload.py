"""The preload of a bearing with zero or negative operating clearance, as every document reports it (issue 30).

A bearing reaches a calculation at its operating clearance: from ``--radial-clearance`` or from the fits
and temperatures (:func:`bearinglab.calculations._mounting.operating_bearing`). Where that clearance is zero
or negative the models solve it as preloaded (:mod:`bearinglab.quasistatic.preload`); the documents say
so with one JSON entry and one warning.

Functions
---------
report    the ``preload`` entry of a document and its warning ({} and None for a positive clearance)
"""

from __future__ import annotations

import math

__all__ = ["report"]


def report(bearing, loads=None, speed=0.0, *, source=None, model=None):
    """The ``preload`` entry and the warning of a bearing with zero or negative clearance.

    Parameters
    ----------
    bearing : BallBearing
        At its operating clearance.
    loads : array_like, optional
        One case's five loads (F_x, F_y, F_z [N], M_x, M_y [N m]): with them the entry has the stiffness
        at those loads against the same bearing at zero clearance (``stiffness_gain_at_load``).
    speed : float, optional
        The speed of those loads. [rad/s]
    source : str, optional
        How the clearance was given, for the warning (default: "the operating clearance").
    model : str, optional
        A model that does not take the preload (a friction model of the external loads): the warning says
        that its result leaves the preload out.

    Returns
    -------
    entry : dict
        ``{"preload": {...}}`` in engineering units (um, N, N/um, N m/mrad), or {}.
    note : str or None
        The warning.
    """
    e = bearing.radial_clearance
    if e is None or e > 0:
        return {}, None
    from ..quasistatic import preload

    p = preload.preload(bearing)
    k = p.stiffness
    entry = {"operating_clearance_um": e * 1e6, "interference_per_ball_um": p.interference * 1e6,
             "ball_load_N": p.ball_load, "ball_load_sum_N": p.ball_load_sum,
             "stiffness_at_zero_load": {"k_xx_N_per_um": k[0, 0] / 1e6, "k_yy_N_per_um": k[1, 1] / 1e6,
                                        "k_zz_N_per_um": k[2, 2] / 1e6, "k_tilt_x_Nm_per_mrad": k[3, 3] / 1e3,
                                        "k_tilt_y_Nm_per_mrad": k[4, 4] / 1e3}}
    note = preload.preload_note(bearing, source or "the operating clearance")
    if loads is not None:
        with_preload, zero = preload.stiffness_gain(bearing, loads, speed)
        names = ("k_xx", "k_yy", "k_zz", "k_tilt_x", "k_tilt_y")
        # a ratio only where the bearing at zero clearance has that stiffness (none at zero load)
        gain = {n: float(a / b) for n, a, b in zip(names, with_preload, zero, strict=True)
                if b > 0 and math.isfinite(a / b)}
        entry["stiffness_gain_at_load"] = gain
        shown = [f"{n} x{g:.3g}" for n, g in gain.items() if n in ("k_xx", "k_yy", "k_zz")]
        if shown and e < 0:
            note += f"; at these loads the stiffness against zero clearance: {', '.join(shown)}"
    if model:
        note += f"; the {model} takes the external loads only and leaves the preload's ball loads out"
    return {"preload": entry}, note
