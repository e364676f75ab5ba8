"""Figures of the high-speed model (bearinglab.plots.high_speed) and the plots package."""

import numpy as np
import pytest

from bearinglab import catalog, plots, quasistatic
from bearinglab.plots import high_speed
from bearinglab.units import RPM

pytest.importorskip("matplotlib")


@pytest.fixture(scope="module")
def grid():
    return quasistatic.sweep(catalog.get("B218"), np.array([2.5e3, 5e3, 10e3, 20e3]), np.array([0.0, 6000.0]) * RPM)


def test_plot_map_returns_a_figure_with_four_panels(grid):
    fig = high_speed.plot_map(grid, title="B218")
    assert len(fig.axes) == 4
    assert fig.get_suptitle() == "B218"
    # one curve per speed in the outer-angle panel, drawn from the state in degrees
    lines = fig.axes[0].get_lines()
    assert len(lines) == 2
    assert np.allclose(lines[1].get_ydata(), np.degrees(grid.contact_angle_outer[:, 1]), rtol=1e-15)


def test_sign_change_marks(grid):
    fig = high_speed.plot_map(grid, sign_change=np.array([0.0, 4.0e3]))
    markers = [ln for ln in fig.axes[3].get_lines() if ln.get_marker() == "o"]
    assert [tuple(m.get_xdata()) for m in markers] == [(4.0,)]  # kN; none at zero speed


def test_save_whole_or_not_at_all(grid, tmp_path):
    fig = high_speed.plot_map(grid)
    for name in ("m.png", "m.svg"):
        plots.save(fig, tmp_path / name)
        assert (tmp_path / name).stat().st_size > 1000
    assert sorted(p.name for p in tmp_path.iterdir()) == ["m.png", "m.svg"]
