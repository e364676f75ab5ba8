"""The Monte Carlo sampler of spec 003 section 11, distribution by distribution.

The draws alone are cheap (no contact solves), so each distribution is checked on 16 000 samples
against the section-11 rules with the tolerance-class values typed in from the spec's tables
(independently of ``data/tolerance_classes.toml``): a Kolmogorov-Smirnov test against the exact
distribution, and the first two moments. With a fixed seed the tests are deterministic; the
thresholds (p > 1e-3, moments within 4 standard errors) leave a correct sampler far inside them,
while halving the order-1 wobble amplitude or dropping the single-ball diameter variation moves the
statistics by dozens of standard errors.
"""

import math

import numpy as np
import pytest
from scipy import stats

from bearinglab import runout as R

UM = 1e-6
N_SAMPLES = 16_000
K_MAX = 15
# spec 003 section 11 tables (um): G5 balls, P4 rings
V_DWS, V_DWL = 0.13, 0.25
K_IA, S_IA, W_RMS = 4.0, 4.0, 0.15


@pytest.fixture(scope="module")
def drawn(g):
    samples = R.monte_carlo_errors(g, "G5", "P4", np.arange(N_SAMPLES), 20261123, max_order=K_MAX)
    e = [s.errors for s in samples]
    return {
        "theta1": np.array([s.geometry.first_ball_angle for s in samples]),
        "outer_deficit": np.array([x.ball_outer_deficit for x in e]) / UM,
        "inner_deficit": np.array([x.ball_inner_deficit for x in e]) / UM,
        "inner": np.array([x.inner.radial.cos - 1j * x.inner.radial.sin for x in e]) / UM,
        "wobble": np.array([x.inner.axial.cos - 1j * x.inner.axial.sin for x in e]) / UM,
        "outer": np.array([x.outer.radial.cos - 1j * x.outer.radial.sin for x in e]) / UM,
    }


def _within_standard_errors(values, expected_mean, expected_var, k=4.0):
    n = values.size
    assert abs(values.mean() - expected_mean) < k * math.sqrt(expected_var / n)
    # the variance estimate's standard error, bounded with a fourth moment <= 3 var^2 (normal-like)
    assert abs(values.var() - expected_var) < k * expected_var * math.sqrt(2.0 / n) * 1.5


def test_first_ball_angle_is_uniform_on_the_circle(drawn):
    assert stats.kstest(drawn["theta1"] / (2 * np.pi), "uniform").pvalue > 1e-3


def test_ball_diameter_deviation_is_lot_plus_single_ball_spread(drawn):
    # delta D = U(-V_DWL/2, V_DWL/2) + U(-V_DWS/2, V_DWS/2), Delta r31 = Delta r32 = -delta D / 2
    assert np.array_equal(drawn["outer_deficit"], drawn["inner_deficit"])
    dd = (-2.0 * drawn["outer_deficit"]).ravel()
    assert np.abs(dd).max() <= (V_DWL + V_DWS) / 2 + 1e-12
    _within_standard_errors(dd, 0.0, (V_DWL**2 + V_DWS**2) / 12.0)
    lo, hi = sorted((V_DWL, V_DWS))

    def cdf(x):  # sum of U(-hi/2, hi/2) and U(-lo/2, lo/2): trapezoidal density, integrated
        x = np.asarray(x)
        a, b = (hi - lo) / 2, (hi + lo) / 2
        ramp_left = (x + b) ** 2 / (2 * hi * lo)
        middle = (x + b - lo / 2) / hi
        ramp_right = 1.0 - (b - x) ** 2 / (2 * hi * lo)
        out = np.where(x < -a, ramp_left, np.where(x <= a, middle, ramp_right))
        return np.clip(np.where(x < -b, 0.0, np.where(x > b, 1.0, out)), 0.0, 1.0)

    assert stats.kstest(dd[:20_000], cdf).pvalue > 1e-3


@pytest.mark.parametrize(("series", "tolerance"), [("inner", K_IA), ("wobble", S_IA)])
def test_order_one_amplitude_and_phase_are_uniform(drawn, series, tolerance):
    """Inner-ring radial runout (K_ia) and wobble (S_ia): amplitude U(0, tol/2), phase U(0, 2 pi)."""
    a1 = np.abs(drawn[series][:, 1])
    assert a1.max() <= tolerance / 2
    assert stats.kstest(a1 / (tolerance / 2), "uniform").pvalue > 1e-3
    _within_standard_errors(a1, tolerance / 4, (tolerance / 2) ** 2 / 12)
    phase = np.angle(drawn[series][:, 1]) % (2 * np.pi)
    assert stats.kstest(phase / (2 * np.pi), "uniform").pvalue > 1e-3


def test_the_outer_ring_has_no_order_zero_or_one(drawn):
    assert np.all(drawn["outer"][:, :2] == 0)  # its order 1 only shifts the centre (section 11)


@pytest.mark.parametrize("ring", ["inner", "outer"])
def test_waviness_orders_are_rayleigh_with_the_class_rms(drawn, ring):
    k = np.arange(2, K_MAX + 1)
    sigma = W_RMS / math.sqrt(sum(1.0 / j**2 for j in k)) / k  # sigma_k = c / k
    amp = np.abs(drawn[ring][:, 2:])
    for j in range(k.size):
        assert stats.kstest(amp[:, j], "rayleigh", args=(0, sigma[j])).pvalue > 1e-3, f"order {k[j]}"
        phase = np.angle(drawn[ring][:, 2 + j]) % (2 * np.pi)
        assert stats.kstest(phase / (2 * np.pi), "uniform").pvalue > 1e-3, f"order {k[j]}"
    mean_square = np.sum(amp**2, axis=1) / 2  # RMS^2 of sum A_k cos(k t + phi_k) over a revolution
    assert mean_square.mean() == pytest.approx(W_RMS**2, rel=0.03)  # ~8 standard errors (0.4 %) at 16 000
