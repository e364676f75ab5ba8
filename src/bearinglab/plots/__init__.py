"""All figures of bearinglab (matplotlib): each function takes results and returns a Figure.

Modules
-------
high_speed   the high-speed map under thrust (spec 004, the paper's figures 2-4 and delta_a)
frequencies  characteristic frequencies and the spectral mask on a frequency axis
friction     the friction-rig lab: measured torques and fitted lines (spec 001 section 7.4)
load_distribution  ball loads of the combined-load model (polar)
rollers      the lamina pressures of the roller slice model (issue 32)
runout       spec 003: contact, trajectory, axial motion, spectrum, Monte Carlo histograms

A module per model family; import the one you need (``from bearinglab.plots import high_speed``).
Nothing heavy is imported here: matplotlib is loaded by the plotting functions on first use, so
``import bearinglab.plots`` costs nothing and a new module needs no line in this file.

Functions
---------
figure   a new matplotlib Figure, not managed by pyplot (no backend, no global state)
save     write a Figure to a file (format from the suffix), whole or not at all
"""

from __future__ import annotations

from pathlib import Path

from .._io import atomic_output

__all__ = ["figure", "save"]


def figure(**kwargs):
    """A new :class:`matplotlib.figure.Figure` (``constrained`` layout unless told otherwise).

    The figure is not registered with pyplot: it needs no interactive backend and no ``plt.close``,
    and a notebook shows it as a cell's value.

    Parameters
    ----------
    **kwargs
        Passed to :class:`matplotlib.figure.Figure` (``figsize``, ``dpi``, ``layout``, ...).

    Returns
    -------
    matplotlib.figure.Figure
    """
    from matplotlib.figure import Figure

    kwargs.setdefault("layout", "constrained")
    return Figure(**kwargs)


def save(fig, path, *, dpi=120):
    """Write ``fig`` to ``path`` (PNG, PDF, SVG, ... from the suffix; PNG without one), whole or not at all.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure.
    path : str or Path
        Target file; its directory must exist.
    dpi : float, optional
        Resolution of raster formats. [1/inch]

    Returns
    -------
    Path
    """
    path = Path(path)
    fmt = path.suffix.lower().lstrip(".") or "png"
    with atomic_output(path, suffix=f".{fmt}") as tmp:
        fig.savefig(tmp, format=fmt, dpi=dpi)
    return path
