"""The polar ball-load figure of the combined-load model (bearinglab.plots.load_distribution)."""

from collections import namedtuple

import numpy as np

from bearinglab.plots import load_distribution

Case = namedtuple("Case", "azimuth ball_load_inner ball_load_outer")


def _case(z=16):
    psi = np.linspace(0.0, 2.0 * np.pi, z, endpoint=False)
    q = 1500.0 + 1000.0 * np.cos(psi)  # a radial load on top of a thrust: every ball loaded
    return Case(psi, q, q + 40.0)


def test_legend_lies_outside_the_polar_axes():
    fig = load_distribution.ball_loads(_case(), title="B218")
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    canvas = FigureCanvasAgg(fig)  # the figure is not managed by pyplot: give it a canvas to draw on
    canvas.draw()  # the constrained layout places the legend on drawing
    renderer = canvas.get_renderer()
    (ax,) = fig.axes
    legend = fig.legends[0] if fig.legends else ax.get_legend()
    box, plot = legend.get_window_extent(renderer), ax.get_window_extent(renderer)
    assert not box.overlaps(plot), (box, plot)
    assert box.y1 <= plot.y0  # below the plot
    assert fig.bbox.contains(box.x0, box.y0) and fig.bbox.contains(box.x1, box.y1)  # and not cut off


def test_one_stem_per_ball_and_the_outer_markers():
    case = _case(9)
    (ax,) = load_distribution.ball_loads(case).axes
    stems = [line for line in ax.lines if len(line.get_xdata()) == 2]
    assert len(stems) == 9
    np.testing.assert_allclose([s.get_ydata()[1] for s in stems], case.ball_load_inner)
    assert ax.get_ylim()[1] >= np.max(case.ball_load_outer)
