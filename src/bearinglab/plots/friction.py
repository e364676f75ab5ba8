"""Figures of the friction-rig lab (spec 001 section 7.4); every function returns a matplotlib Figure.

fitted_lines    one plot of :func:`bearinglab.lab.presentation.plots`: the experimental points and
                the fitted lines, drawn from abscissa 0

Matplotlib is imported on first use, with the Agg canvas attached explicitly (no pyplot, no global
backend state), so importing this module stays light and figures work on headless machines. The
figures are laid out once when drawn here; :mod:`bearinglab.report` writes them as PNG and SVG.
"""

from __future__ import annotations

__all__ = ["fitted_lines"]

_COLOURS = ("#1f5fa8", "#c0392b", "#2e8b57", "#8e44ad", "#d35400", "#16a085", "#7f8c8d", "#b7950b")
_MARKERS = ("o", "s", "^", "D", "v", "P", "X", "*")


def fitted_lines(plot):
    """Draw one plot of the lab: experimental points and fitted lines from abscissa 0.

    Parameters
    ----------
    plot : bearinglab.lab.presentation.PlotData
        Points and lines in engineering units.

    Returns
    -------
    matplotlib.figure.Figure
        6.4 x 4.2 in at 150 dpi, with an Agg canvas, laid out (constrained) and then fixed, so that
        every format it is saved in has the same layout.

    Examples
    --------
    >>> import numpy as np
    >>> from bearinglab.lab.presentation import PlotData, PlotSeries
    >>> line = PlotSeries("mu = 1.5e-3", np.array([5.0, 10.0]), np.array([0.04, 0.08]),
    ...                   np.array([0.0, 11.0]), np.array([0.0, 0.088]))
    >>> fig = fitted_lines(PlotData("task1", "Task 1", "P0 [N]", "T [N·mm]", [line]))
    >>> ax = fig.axes[0]
    >>> float(ax.get_xlim()[0]), ax.get_ylabel(), len(ax.lines)  # the axis starts at 0; line, points, T = 0
    (0.0, 'T [N·mm]', 3)
    """
    import matplotlib
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    with matplotlib.rc_context({"font.size": 9.5}):
        fig = Figure(figsize=(6.4, 4.2), dpi=150)
        FigureCanvasAgg(fig)
        ax = fig.add_subplot()
        ymin = 0.0
        for k, s in enumerate(plot.series):
            colour, marker = _COLOURS[k % len(_COLOURS)], _MARKERS[k % len(_MARKERS)]
            ax.plot(s.line_x, s.line_y, "-", color=colour, lw=1.4, label=s.label)
            ax.plot(s.x, s.y, marker, color=colour, ms=5.5, mfc="white", mew=1.4, ls="none")
            ymin = min(ymin, float(min(s.line_y.min(), s.y.min())))
        ax.set_xlim(left=0.0)
        ax.set_ylim(bottom=ymin * 1.1 if ymin < 0 else 0.0)
        ax.axhline(0.0, color="0.6", lw=0.6)
        ax.set_xlabel(plot.xlabel)
        ax.set_ylabel(plot.ylabel)
        ax.set_title(plot.title, fontsize=10.5)
        ax.grid(True, color="0.88", lw=0.6)
        ax.legend(fontsize=8, loc="upper left", frameon=False)
        fig.set_layout_engine("constrained")  # lay out once, then keep that layout for every format
        fig.draw_without_rendering()
        fig.set_layout_engine("none")
    return fig
