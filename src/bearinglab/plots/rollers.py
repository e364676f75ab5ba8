"""Figures of the roller-bearing slice model (issue 32); every function returns a matplotlib Figure.

slice_pressures   the lamina pressures along the loaded rollers of one case (edge loading of a tilted ring),
                  beside a map of the pressure over roller azimuth and position
overview          the roller loads over azimuth (polar) beside the two panels of ``slice_pressures``
                  (``load-distribution --plot`` of a roller bearing)

Matplotlib is loaded on first use (:func:`bearinglab.plots.figure`), so importing this module is light.
"""

from __future__ import annotations

import numpy as np

from . import figure

__all__ = ["overview", "slice_pressures"]


def slice_pressures(result, *, rollers=3, title=None):
    """Lamina pressures of one case of a roller load distribution: along the most loaded rollers, and as a map.

    Parameters
    ----------
    result : RollerLoadDistribution
        One case of :func:`bearinglab.rollers.distribution.load_distribution` (``slice_pressure`` of shape
        (Z, n_s), ``slice_position`` (n_s,), ``azimuth`` (Z,), ``roller_load`` (Z,)).
    rollers : int, optional
        How many of the most loaded rollers to draw on the left.
    title : str, optional
        Figure title.

    Returns
    -------
    matplotlib.figure.Figure
        Left: pressure [MPa] against the position along the roller [mm] of the ``rollers`` most loaded
        rollers (their azimuths in the legend); right: the pressure of every lamina over roller azimuth [deg]
        and position [mm].

    Examples
    --------
    >>> from collections import namedtuple
    >>> r = namedtuple("R", "slice_pressure slice_position azimuth roller_load")(
    ...     np.array([[1.0e9, 1.2e9], [0.0, 0.0]]), np.array([-2e-3, 2e-3]), np.array([0.0, np.pi]),
    ...     np.array([10.0, 0.0]))
    >>> len(slice_pressures(r).axes)
    3
    """
    fig = figure(figsize=(10.0, 4.2))
    left, right = fig.subplots(1, 2, width_ratios=[1.0, 1.1])
    _slices(fig, left, right, result, rollers)
    if title:
        fig.suptitle(title, fontsize="medium")
    return fig


def _columns(result):
    p = np.nan_to_num(np.asarray(result.slice_pressure, dtype=float)) / 1e6
    s = np.asarray(result.slice_position, dtype=float) * 1e3
    psi = np.degrees(np.asarray(result.azimuth, dtype=float))
    q = np.nan_to_num(np.asarray(result.roller_load, dtype=float))
    if p.ndim != 2:
        raise ValueError(f"slice_pressures takes one case: slice_pressure of shape (Z, n_s), got {p.shape}")
    return p, s, psi, q


def _slices(fig, left, right, result, rollers):
    """The two panels of :func:`slice_pressures` on the axes ``left`` and ``right``."""
    p, s, psi, q = _columns(result)
    for j in np.argsort(-q, kind="stable")[: max(1, int(rollers))]:
        if q[j] <= 0:
            continue
        left.plot(s, p[j], marker=".", ms=3, lw=1.2, label=f"roller at {psi[j] % 360:.0f} deg ({q[j] / 1e3:.2f} kN)")
    left.set_xlabel("position along the roller [mm]")
    left.set_ylabel("lamina pressure, inner raceway [MPa]")
    left.set_ylim(bottom=0.0)
    left.grid(alpha=0.3)
    left.legend(fontsize="small", frameon=False)
    order = np.argsort(psi % 360)
    a = psi[order] % 360
    step = 360.0 / max(len(a), 1)
    ds = (s[1] - s[0]) if len(s) > 1 else 1.0
    mesh = right.pcolormesh(np.append(a - step / 2, a[-1] + step / 2), np.append(s - ds / 2, s[-1] + ds / 2),
                            p[order].T, shading="flat", cmap="viridis")
    right.set_xlabel("roller azimuth from +x [deg]")
    right.set_ylabel("position along the roller [mm]")
    fig.colorbar(mesh, ax=right, label="lamina pressure [MPa]")


def overview(result, *, rollers=3, title=None):
    """Roller loads over azimuth and the lamina pressures of one case of a roller load distribution.

    Parameters
    ----------
    result : RollerLoadDistribution
        One case, as for :func:`slice_pressures` (``roller_load`` (Z,), ``azimuth`` (Z,), ``slice_pressure``
        (Z, n_s), ``slice_position`` (n_s,)).
    rollers : int, optional
        How many of the most loaded rollers the middle panel draws.
    title : str, optional
        Figure title.

    Returns
    -------
    matplotlib.figure.Figure
        Left: the roller loads [kN] at their azimuths (polar; the load of each roller along its raceway
        normal, an unloaded roller at 0); middle and right: the panels of :func:`slice_pressures`.

    Examples
    --------
    >>> from collections import namedtuple
    >>> r = namedtuple("R", "slice_pressure slice_position azimuth roller_load")(
    ...     np.array([[1.0e9, 1.2e9], [0.0, 0.0]]), np.array([-2e-3, 2e-3]), np.array([0.0, np.pi]),
    ...     np.array([10.0, 0.0]))
    >>> len(overview(r).axes)
    4
    """
    _, _, psi, q = _columns(result)
    fig = figure(figsize=(14.0, 4.4))
    grid = fig.add_gridspec(1, 3, width_ratios=[0.8, 1.0, 1.1])
    polar = fig.add_subplot(grid[0], projection="polar")
    order = np.argsort(psi % 360)
    angles = np.radians(np.append(psi[order], psi[order][0] + 360.0))
    loads = np.append(q[order], q[order][0]) / 1e3
    polar.plot(angles, loads, lw=1.2)
    polar.plot(np.radians(psi), q / 1e3, "o", ms=4)
    polar.set_rlabel_position(112.5)
    polar.set_title("roller loads [kN]", fontsize="medium")
    _slices(fig, fig.add_subplot(grid[1]), fig.add_subplot(grid[2]), result, rollers)
    if title:
        fig.suptitle(title, fontsize="medium")
    return fig
