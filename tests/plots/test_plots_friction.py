"""Figures of the friction lab (bearinglab.plots.friction) and their PNG/SVG form (bearinglab.report)."""

from pathlib import Path

import numpy as np
import pytest

from bearinglab import report
from bearinglab.lab import analysis, measurement, presentation
from bearinglab.plots import friction as friction_plots

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "friction"


@pytest.fixture(scope="module")
def s1_plots():
    r = analysis.analyse(measurement.read_session(EXAMPLES / "s1_readings.toml"))
    return presentation.plots(r)


def test_figure_shows_every_series_from_abscissa_zero(s1_plots):
    from matplotlib.figure import Figure

    plot = s1_plots[0]
    fig = friction_plots.fitted_lines(plot)
    assert isinstance(fig, Figure)
    (ax,) = fig.axes
    assert ax.get_xlim()[0] == 0.0 and ax.get_ylim()[0] == 0.0
    assert ax.get_title() == plot.title and ax.get_xlabel() == "P0 [N]"
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert labels == [s.label for s in plot.series]
    lines = [ln for ln in ax.lines if ln.get_linestyle() == "-" and len(ln.get_xdata()) == 2]
    assert [list(ln.get_xdata()) for ln in lines[: len(plot.series)]] == [
        list(s.line_x) for s in plot.series
    ]


def test_negative_values_extend_the_ordinate_below_zero():
    s = presentation.PlotSeries(
        "T_F < 0",
        np.array([1.0, 2.0]),
        np.array([-0.1, 0.3]),
        np.array([0.0, 2.2]),
        np.array([-0.5, 0.38]),
    )
    fig = friction_plots.fitted_lines(presentation.PlotData("p", "t", "x", "y", [s]))
    assert fig.axes[0].get_ylim()[0] == pytest.approx(-0.55, rel=1e-12)  # 1.1 x the lowest value


def test_png_and_svg_are_reproducible_and_carry_no_metadata(s1_plots):
    png, svg = report.render_figure(s1_plots[1])
    assert png.startswith(b"\x89PNG\r\n\x1a\n") and svg.lstrip().startswith("<?xml")
    assert "<metadata>" not in svg and "Matplotlib" not in svg and b"Software" not in png
    assert report.render_figure(s1_plots[1]) == (png, svg)  # same plot, same bytes
