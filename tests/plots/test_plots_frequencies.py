"""Figures of the characteristic frequencies (bearinglab.plots.frequencies)."""

import math

import numpy as np
import pytest

from bearinglab import catalog, kinematics
from bearinglab.plots import frequencies
from bearinglab.units import RPM

pytest.importorskip("matplotlib")


def test_spectral_mask_draws_one_band_per_line():
    b = catalog.get("4-1006095")
    m = kinematics.spectral_mask(3000 * RPM, b.ball_diameter, b.pitch_diameter, b.n_balls, b.contact_angle,
                                 harmonics=2, sidebands=1, band=0.02)
    fig = frequencies.spectral_mask(m, xlim=(0, 500))
    ax = fig.axes[0]
    assert len(ax.patches) == len(m.name)
    assert ax.get_xlim() == (0, 500)


def test_orders_against_the_angle_into_given_axes():
    from bearinglab import plots

    b = catalog.get("6205-2RS")
    fig = plots.figure()
    ax = fig.add_subplot()
    angles = np.radians([0.0, 10.0, 20.0])
    assert frequencies.orders(b.ball_diameter, b.pitch_diameter, b.n_balls, angles,
                              marks=[(math.radians(10), "10°")], ax=ax) is fig
    bpfi = ax.get_lines()[0]
    expected = kinematics.characteristic_orders(b.ball_diameter, b.pitch_diameter, b.n_balls, angles).bpfi
    assert np.allclose(bpfi.get_ydata(), expected, rtol=1e-15)
