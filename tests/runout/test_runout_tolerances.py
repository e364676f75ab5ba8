"""Monte Carlo over tolerance classes, spec 003 section 11 (``runout.tolerances``): reproducibility, the
draws, the statistics, and bit-identical results on every executor."""

import math

import numpy as np
import pytest

from bearinglab import runout as R
from bearinglab.errors import InputError


# ------------------------------------------------------------------------------ Monte Carlo
def test_tolerance_classes_have_sources():
    grades, classes = R.tolerance_classes()
    assert list(grades) == ["G3", "G5", "G10", "G16", "G20", "G24", "G28", "G40"]
    assert all("ISO 3290" in v.source for v in grades.values())
    assert all("ISO 492" in v.source and "assumed" in v.source for v in classes.values())
    # V_DWS < V_DWL and both grow with the grade number
    s = [v.single_diameter_variation for v in grades.values()]
    lot = [v.lot_diameter_variation for v in grades.values()]
    assert (
        np.all(np.diff(s) > 0) and np.all(np.diff(lot) > 0) and all(a < b for a, b in zip(s, lot))
    )
    with pytest.raises(InputError, match=r"ball_grade must be one of \['G3'"):
        R.ball_grade("G7")
    with pytest.raises(InputError, match=r"ring_class must be one of \['P5'"):
        R.ring_class("P0")


def test_monte_carlo_is_reproducible_and_independent_of_chunking(g):
    a = R.monte_carlo(g, "G5", "P4", 12, 99, steps_per_revolution=36, chunk_size=5)
    b = R.monte_carlo(g, "G5", "P4", 12, 99, steps_per_revolution=36, chunk_size=12)
    c = R.monte_carlo(
        g, "G5", "P4", 12, np.random.SeedSequence(99), steps_per_revolution=36, chunk_size=7
    )
    for name in R.METRICS:
        assert np.array_equal(getattr(a.samples, name), getattr(b.samples, name)), name
        assert np.array_equal(getattr(a.samples, name), getattr(c.samples, name)), name
    d = R.monte_carlo(g, "G5", "P4", 12, 100, steps_per_revolution=36)
    assert not np.array_equal(a.samples.axial_ptp, d.samples.axial_ptp)
    calls = []
    R.monte_carlo(
        g,
        "G5",
        "P4",
        10,
        1,
        steps_per_revolution=12,
        chunk_size=4,
        progress=lambda k, n: calls.append((k, n)),
    )
    assert calls == [(4, 10), (8, 10), (10, 10)]


def test_monte_carlo_sample_equals_the_public_path(g):
    """A sample's metrics equal a rotation_sequence of the same errors built with the public API, to the
    last bit."""
    from bearinglab.runout.tolerances import _draw_count, _sampled_errors, _uniforms

    res = R.monte_carlo_chunk(g, "G10", "P5", [3], 5, steps_per_revolution=60, revolutions=2)
    u = _uniforms(5, [3], _draw_count(16, 15))
    theta1, dd, ser = _sampled_errors(u, 16, R.ball_grade("G10"), R.ring_class("P5"), 15)
    one = {k: R.FourierSeries(v.cos[0], v.sin[0]) for k, v in ser.items()}
    e = R.manufacturing_errors(
        16,
        ball_diameter_deviation=dd[0],
        inner=R.RacewayErrors(radial=one["inner"], axial=one["wobble"]),
        outer=R.RacewayErrors(radial=one["outer"]),
    )
    t = R.rotation_sequence(
        g._replace(first_ball_angle=theta1[0]), e, revolutions=2, steps_per_revolution=60
    )
    for name in R.METRICS:  # the Monte Carlo kernel evaluates the same functions: bit for bit
        assert getattr(res, name)[0] == getattr(t.metrics, name), name


def test_monte_carlo_draws_follow_the_tolerance_classes():
    """Ball deviations within (V_DWL + V_DWS)/2, order-1 amplitudes within K_ia/2 and S_ia/2, and the
    waviness RMS close to w_rms on average."""
    from bearinglab.runout.tolerances import _draw_count, _sampled_errors, _uniforms

    grade, rings = R.ball_grade("G10"), R.ring_class("P5")
    u = _uniforms(11, np.arange(400), _draw_count(16, 15))
    theta1, dd, ser = _sampled_errors(u, 16, grade, rings, 15)
    assert np.all(
        np.abs(dd) <= (grade.lot_diameter_variation + grade.single_diameter_variation) / 2
    )
    assert np.all((theta1 >= 0) & (theta1 < 2 * np.pi))
    a1 = np.hypot(ser["inner"].cos[:, 1], ser["inner"].sin[:, 1])
    assert np.all(a1 <= rings.radial_runout / 2) and a1.mean() == pytest.approx(
        rings.radial_runout / 4, rel=0.1
    )
    s1 = np.hypot(ser["wobble"].cos[:, 1], ser["wobble"].sin[:, 1])
    assert np.all(s1 <= rings.axial_runout / 2)
    for key in ("inner", "outer"):
        ms = 0.5 * (ser[key].cos[:, 2:] ** 2 + ser[key].sin[:, 2:] ** 2).sum(
            axis=1
        )  # mean square of orders 2..15
        assert math.sqrt(ms.mean()) == pytest.approx(rings.waviness_rms, rel=0.05)
    assert np.all(ser["outer"].cos[:, :2] == 0)  # outer order 1 only shifts the centre: not drawn


def test_summarize_checks():
    s = R.summarize(np.arange(101.0))
    assert s.median == 50 and s.p95 == 95 and s.max == 100
    with pytest.raises(InputError, match="at least 2 samples"):
        R.summarize([1.0])


def test_monte_carlo_seed_checks(g):
    for bad in (-1, 1.5, "7", True):
        with pytest.raises(InputError, match="seed must be a whole number >= 0"):
            R.monte_carlo(g, "G5", "P4", 4, bad, steps_per_revolution=12)
    r = R.monte_carlo(g, "G5", "P4", 4, np.int64(5), steps_per_revolution=12)
    assert r.seed == 5
