"""Figures of the combined-load model (issue 11); every function returns a matplotlib Figure.

ball_loads   polar plot of the ball loads of one case (inner and outer contact) at their azimuths

Matplotlib is loaded on first use (:func:`bearinglab.plots.figure`), so importing this module is light.
"""

from __future__ import annotations

import numpy as np

from . import figure

__all__ = ["ball_loads"]


def ball_loads(result, *, title=None):
    """Polar plot of the ball loads of one case of a combined-load distribution.

    Parameters
    ----------
    result : LoadDistribution
        One case of :func:`bearinglab.quasistatic.combined.load_distribution` (``azimuth``,
        ``ball_load_inner`` and ``ball_load_outer`` of shape (Z,)).
    title : str, optional
        Figure title.

    Returns
    -------
    matplotlib.figure.Figure
        Azimuth from +x counter-clockwise, radius the ball load in N; a stem per ball for the inner
        contact, markers for the outer one (they differ at speed).

    Examples
    --------
    >>> from collections import namedtuple
    >>> r = namedtuple("R", "azimuth ball_load_inner ball_load_outer")(
    ...     np.linspace(0, 2 * np.pi, 4, endpoint=False), np.array([10.0, 2, 0, 2]), np.array([10.0, 2, 0, 2]))
    >>> len(ball_loads(r).axes)
    1
    """
    psi = np.asarray(result.azimuth, dtype=float)
    qi = np.nan_to_num(np.asarray(result.ball_load_inner, dtype=float))
    qo = np.nan_to_num(np.asarray(result.ball_load_outer, dtype=float))
    fig = figure(figsize=(5.2, 5.8))
    ax = fig.add_subplot(projection="polar")
    for k, (a, q) in enumerate(zip(psi, qi, strict=True)):
        ax.plot([a, a], [0.0, q], color="#1f5fa8", lw=2.5, label="inner contact" if k == 0 else None)
    ax.plot(psi, qo, "o", color="#c0392b", ms=5, fillstyle="none", label="outer contact")
    loop = np.append(psi, psi[0] + 2 * np.pi)
    ax.plot(loop, np.append(qi, qi[0]), color="#1f5fa8", lw=0.8, alpha=0.5)
    ax.set_rlabel_position(112.5)
    ax.set_ylim(0.0, max(float(np.max(qi, initial=0.0)), float(np.max(qo, initial=0.0)), 1e-9) * 1.1)
    # below the polar axes, outside them (constrained layout makes room): never over the plot
    fig.legend(loc="outside lower center", ncols=2, fontsize="small", frameon=False,
               title="ball load [N], azimuth from +x", title_fontsize="small")
    if title:
        ax.set_title(title, fontsize="medium")
    return fig
