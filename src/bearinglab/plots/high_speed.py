"""Figures of the high-speed model under thrust (spec 004).

Functions
---------
plot_map   the map of a thrust x speed sweep: outer and inner contact angle (the paper's figures 2
           and 3), their increments from the static angle (figure 4) and the axial displacement
           with its sign change
"""

from __future__ import annotations

import math

import numpy as np

from ..units import RPM
from . import figure

__all__ = ["plot_map"]


def _sign_changes(fa, da, j, n, sign_change):
    """Thrusts [kN] at which delta_a changes sign for speed column ``j``."""
    if sign_change is not None:
        f0 = float(sign_change[j]) * 1e-3
        return [f0] if fa[0] <= f0 <= fa[-1] and n > 0 else []
    # linear interpolation of the sign change between grid loads
    return [fa[k] - da[k, j] * (fa[k + 1] - fa[k]) / (da[k + 1, j] - da[k, j])
            for k in np.flatnonzero(np.diff(np.sign(da[:, j])) > 0)]


def plot_map(state, *, title="", sign_change=None):
    """The map of a :func:`bearinglab.quasistatic.sweep` result (loads x speeds) in four panels.

    The outer and the inner contact angle against thrust, one curve per speed (the paper's figures 2
    and 3); their increments from the static angle, inner solid and outer dashed (figure 4); and the
    axial displacement against thrust with its sign change marked.

    Parameters
    ----------
    state : HighSpeedState
        A grid of thrusts (rows) x speeds (columns), as :func:`bearinglab.quasistatic.sweep` returns.
    title : str, optional
        Title over the four panels.
    sign_change : array_like, optional
        Thrust at which delta_a changes sign, one per speed (e.g. from
        :func:`bearinglab.quasistatic.sign_change_thrust`); if not given, interpolated between grid
        loads. [N]

    Returns
    -------
    matplotlib.figure.Figure
        Write it with :func:`bearinglab.plots.save`.
    """
    fa = np.asarray(state.axial_load)[:, 0] * 1e-3
    speeds = np.asarray(state.shaft_speed)[0] / RPM
    deg = 180.0 / math.pi
    ai = np.asarray(state.contact_angle_inner) * deg
    ae = np.asarray(state.contact_angle_outer) * deg
    a_s = np.asarray(state.static_contact_angle) * deg
    da = np.asarray(state.axial_displacement) * 1e6
    fig = figure(figsize=(11, 8.5))
    axes = fig.subplots(2, 2)
    from matplotlib import colormaps

    colors = colormaps["viridis"](np.linspace(0.0, 0.9, len(speeds)))
    many = len(speeds) > 8
    for j, (n, c) in enumerate(zip(speeds, colors)):
        label = None if many and j not in (0, len(speeds) - 1) else f"{n:g} rpm"
        axes[0, 0].plot(fa, ae[:, j], color=c, label=label)
        axes[0, 1].plot(fa, ai[:, j], color=c, label=label)
        if n > 0:
            axes[1, 0].plot(fa, ai[:, j] - a_s[:, j], color=c, label=label)
            axes[1, 0].plot(fa, a_s[:, j] - ae[:, j], color=c, ls="--")
        axes[1, 1].plot(fa, da[:, j], color=c, label=label)
        for f0 in _sign_changes(fa, da, j, n, sign_change):
            axes[1, 1].plot([f0], [0.0], "o", color=c, mfc="white")
            if not many:
                axes[1, 1].annotate(f"{f0:.2f} kN", (f0, 0.0), textcoords="offset points", xytext=(4, -12),
                                    fontsize=8, color=c)
    axes[0, 0].set(title="outer contact angle α_e", ylabel="α_e [deg]")
    axes[0, 1].set(title="inner contact angle α_i", ylabel="α_i [deg]")
    axes[1, 0].set(title="increments from α_s: Δα_i solid, Δα_e dashed", ylabel="Δα [deg]")
    axes[1, 1].axhline(0.0, color="0.5", lw=0.8)
    axes[1, 1].set(title="axial displacement (○ sign change)", ylabel="δ_a [µm]")
    for ax in axes.flat:
        ax.set_xlabel("thrust F_a [kN]")
        ax.grid(alpha=0.3)
    axes[0, 0].legend(fontsize=8)
    if title:
        fig.suptitle(title)
    return fig
