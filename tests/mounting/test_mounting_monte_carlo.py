"""The Monte Carlo of the clearance chain: bounds, reproducibility, and RSS where the chain is linear."""

import math

import numpy as np
import pytest

from bearinglab.mounting import chain, monte_carlo

M = chain.Mounting(0.040, 0.080, 0.0479, 0.0721, 0.0121)
LIMITS = {"unmounted_clearance": (6e-6, 20e-6), "shaft": (2e-6, 13e-6), "bore": (-12e-6, 0.0),
          "outside_diameter": (-13e-6, 0.0), "housing": (-30e-6, -8e-6)}  # k5 on 40 mm, an N7-like housing


@pytest.mark.parametrize("distribution", monte_carlo.DISTRIBUTIONS)
def test_samples_lie_between_least_and_largest(distribution):
    r = chain.operating_range(LIMITS["unmounted_clearance"], (2e-6, 25e-6), (-5e-6, 30e-6), M,
                              chain.Conditions(chain.T_REF + 50, chain.T_REF + 40, speed=600.0))
    mc = monte_carlo.monte_carlo(20_000, 3, LIMITS, M, chain.Conditions(chain.T_REF + 50, chain.T_REF + 40,
                                                                        speed=600.0),
                                 distribution=distribution)
    op = mc.samples["operating_clearance"]
    assert op.min() >= r.least.operating_clearance - 1e-15
    assert op.max() <= r.largest.operating_clearance + 1e-15


def test_same_seed_same_samples_whatever_the_chunking():
    a = monte_carlo.monte_carlo(3000, 11, LIMITS, M, execution=None)
    from bearinglab import parallel

    b = monte_carlo.monte_carlo(3000, 11, LIMITS, M, execution=parallel.Execution(chunk_size=512))
    assert np.array_equal(a.samples["operating_clearance"], b.samples["operating_clearance"])


def test_rss_where_the_chain_is_linear():
    """Both fits stay tight in every sample (no sign change), one steel, solid shaft, thick housing:
    e = e0 - (d/d_i) I_i - (d_o/D) I_o exactly, so the variance is the sum of the five uniform variances
    w^2/12 weighted by the squared gains (written here from the closed forms, not from the chain)."""
    lim = dict(LIMITS, housing=(-60e-6, -40e-6))  # outer interference 27..60 um: always tight
    mc = monte_carlo.monte_carlo(200_000, 5, lim, M)
    gi, go = M.bore / M.inner_raceway, M.outer_raceway / M.outside_diameter
    gains = {"unmounted_clearance": 1.0, "shaft": gi, "bore": gi, "outside_diameter": go, "housing": go}
    var = sum(gains[f] ** 2 * (lim[f][1] - lim[f][0]) ** 2 / 12 for f in gains)
    mean = (np.mean(lim["unmounted_clearance"]) - gi * (np.mean(lim["shaft"]) - np.mean(lim["bore"]))
            - go * (np.mean(lim["outside_diameter"]) - np.mean(lim["housing"])))
    # 2e5 samples: the standard error of the std is ~ std / sqrt(2 n) = 0.16 %; of the mean std / sqrt(n)
    assert mc.std == pytest.approx(math.sqrt(var), rel=0.01)
    assert mc.mean == pytest.approx(mean, abs=4 * math.sqrt(var / 200_000))
    probable = chain.operating_range(lim["unmounted_clearance"], (2e-6, 25e-6), (27e-6, 60e-6), M).probable
    assert probable.operating_clearance == pytest.approx(mean, rel=1e-12)


def test_nonlinear_chain_departs_from_rss_when_a_fit_can_be_loose():
    """A transition fit (around zero): a sample with a loose fit carries no pressure and gives the
    clearance nothing back, where a linear (RSS) model would widen it; the nonlinear mean is smaller."""
    lim = dict(LIMITS, shaft=(-15e-6, 5e-6), bore=(0.0, 0.0), outside_diameter=(0.0, 0.0), housing=(0.0, 0.0))
    mc = monte_carlo.monte_carlo(50_000, 2, lim, M)
    gi = M.bore / M.inner_raceway
    linear_mean = np.mean(lim["unmounted_clearance"]) - gi * np.mean(lim["shaft"])
    assert mc.mean < linear_mean


def test_probability_of_preload_counts_negative_samples():
    lim = dict(LIMITS, unmounted_clearance=(0.0, 4e-6))
    mc = monte_carlo.monte_carlo(5000, 1, lim, M)
    assert mc.probability_preload == pytest.approx(np.mean(mc.samples["operating_clearance"] < 0))
    assert 0.5 < mc.probability_preload <= 1.0


def test_normal_fields_are_cut_at_the_limits_with_sigma_a_sixth():
    x = monte_carlo.draw_field(np.random.default_rng(0), 200_000, 0.0, 6.0, "normal")
    assert x.min() >= 0.0 and x.max() <= 6.0
    assert x.std() == pytest.approx(0.9865, rel=0.01)  # sigma of N(3, 1) cut at +-3: 0.98648


def test_bad_distribution():
    with pytest.raises(ValueError, match="distribution must be one of"):
        monte_carlo.monte_carlo(10, 1, LIMITS, M, distribution="beta")


def test_bench_paths_agree_sample_by_sample(load_bench):
    """bench/clearance.py: its plain-Python per-sample chain gives the batched Monte Carlo's answers."""
    r = load_bench("clearance").measure(n_batch=5000, n_baseline=500, repeat=1)
    assert r["diff"] < 1e-15


def test_normal_fields_give_skf_probable_interference():
    """Normal fields (limits at +-3 sigma): the 0.135 % / 99.865 % points of the interference are SKF's
    probable range (fits.probable_interference), to the micrometre SKF prints."""
    from bearinglab.mounting import fits, tables

    shaft, bore = tables.field_limits("m6", 0.040), tables.bore_limits(0.040)
    rng = np.random.default_rng(12)
    x = (monte_carlo.draw_field(rng, 400_000, shaft.lower, shaft.upper, "normal")
         - monte_carlo.draw_field(rng, 400_000, bore.lower, bore.upper, "normal"))
    p = fits.probable_interference(shaft, bore)
    lo, hi = np.percentile(x, [0.135, 99.865])
    assert abs(lo - p.least) < 0.5e-6 and abs(hi - p.largest) < 0.5e-6
