"""Figures of the characteristic frequencies and the spectral mask.

Functions
---------
spectral_mask   the bands of a spectral mask on a frequency axis (carriers dark, sidebands light)
orders          characteristic orders against the contact angle, with marked angles
"""

from __future__ import annotations

import itertools
import math

import numpy as np

from .. import kinematics
from . import figure

__all__ = ["orders", "spectral_mask"]

_HZ = 2.0 * math.pi  # rad/s per Hz
#: one colour per family of lines
COLOURS = {"bpfo": "C0", "bpfi": "C3", "bsf": "C2", "two_bsf": "C4", "ftf": "C1", "shaft": "0.4"}


def _axes(ax, figsize):
    if ax is not None:
        return ax.figure, ax
    fig = figure(figsize=figsize)
    return fig, fig.add_subplot()


def spectral_mask(mask, *, title="", xlim=None, ax=None):
    """The bands of a spectral mask: carriers dark, sidebands light, one colour per family.

    Parameters
    ----------
    mask : SpectralMask
        A result of :func:`bearinglab.kinematics.spectral_mask`.
    title : str, optional
        Title of the axes.
    xlim : tuple of float, optional
        Frequency range shown. [Hz]
    ax : matplotlib.axes.Axes, optional
        Draw into these axes instead of a new figure.

    Returns
    -------
    matplotlib.figure.Figure
    """
    fig, ax = _axes(ax, (12, 3.5))
    for name, colour in COLOURS.items():
        sel = mask.name == name
        for lo, hi, mod in zip(mask.low[sel] / _HZ, mask.high[sel] / _HZ, mask.modulation[sel]):
            ax.axvspan(lo, hi, color=colour, alpha=0.25 if mod else 0.6, lw=0)
        ax.plot([], [], color=colour, lw=6, label=name)
    ax.set(yticks=[], xlabel="frequency [Hz]", title=title)
    if xlim is not None:
        ax.set_xlim(*xlim)
    ax.legend(ncol=6, loc="upper right", fontsize=8)
    return fig


def orders(ball_diameter, pitch_diameter, n_balls, contact_angle, *, marks=(), title="", ax=None):
    """Characteristic orders (multiples of the shaft speed) against the contact angle.

    Parameters
    ----------
    ball_diameter : float
        Ball diameter. [m]
    pitch_diameter : float
        Pitch diameter. [m]
    n_balls : int
        Number of balls. [-]
    contact_angle : array_like
        Contact angles of the curves. [rad]
    marks : sequence of (float, str), optional
        Angles [rad] to mark with a vertical line, each with its label.
    title : str, optional
        Title of the axes.
    ax : matplotlib.axes.Axes, optional
        Draw into these axes instead of a new figure.

    Returns
    -------
    matplotlib.figure.Figure
    """
    fig, ax = _axes(ax, (12, 3.5))
    angles = np.asarray(contact_angle, dtype=float)
    curves = kinematics.characteristic_orders(ball_diameter, pitch_diameter, n_balls, angles)
    for name in ("bpfi", "bpfo", "two_bsf", "bsf"):
        ax.plot(np.degrees(angles), getattr(curves, name), color=COLOURS[name], label=name)
    for (angle, label), (colour, ls) in zip(marks, itertools.cycle([("0.5", "--"), ("k", ":"), ("C7", "-.")])):
        ax.axvline(math.degrees(angle), color=colour, ls=ls, lw=1, label=label)
    ax.set(xlabel="contact angle [deg]", ylabel="order (multiple of shaft speed)", title=title)
    ax.legend(ncol=3, fontsize=8)
    return fig
