"""Monte Carlo over tolerance classes, spec 003 section 11 (``runout.tolerances``): reproducibility, the
draws, the statistics, and bit-identical results on every executor."""

import importlib.util
import math
import time

import numpy as np
import pytest
from threadpoolctl import threadpool_limits

from bearinglab import parallel
from bearinglab import runout as R
from bearinglab.errors import InputError

# both engines of the Monte Carlo (the compiled one where numba is installed): each gives the same bits on
# every chunk size and executor, and equal to the rotation sequence of a sample's errors
ENGINES = ["numpy", pytest.param("compiled", marks=pytest.mark.skipif(
    importlib.util.find_spec("numba") is None, reason="numba is not installed"))]


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


@pytest.mark.parametrize("engine", ENGINES)
def test_monte_carlo_is_reproducible_and_independent_of_chunking(g, engine):
    a = R.monte_carlo(g, "G5", "P4", 12, 99, steps_per_revolution=36, chunk_size=5, engine=engine)
    b = R.monte_carlo(g, "G5", "P4", 12, 99, steps_per_revolution=36, chunk_size=12, engine=engine)
    c = R.monte_carlo(
        g, "G5", "P4", 12, np.random.SeedSequence(99), steps_per_revolution=36, chunk_size=7,
        engine=engine,
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


@pytest.mark.parametrize("engine", ENGINES)
def test_monte_carlo_sample_equals_the_public_path(g, engine):
    """A sample's metrics equal a rotation_sequence of the same errors built with the public API, to the
    last bit (with the same engine)."""
    from bearinglab.runout.tolerances import _draw_count, _sampled_errors, _uniforms

    res = R.monte_carlo_chunk(g, "G10", "P5", [3], 5, steps_per_revolution=60, revolutions=2, engine=engine)
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
        g._replace(first_ball_angle=theta1[0]), e, revolutions=2, steps_per_revolution=60, engine=engine
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


# ------------------------------------------------------------------------------ the same bits everywhere
def _assert_same_study(a, b):
    """Per-sample metrics and statistics equal to the last bit (==, not allclose)."""
    for name in a.samples._fields:
        assert np.array_equal(getattr(a.samples, name), getattr(b.samples, name)), name
    assert a.summary == b.summary


def test_monte_carlo_chunk_does_not_depend_on_the_blas_threads(g):
    """Defect 4: a complex matrix product (OpenBLAS zgemm) in the kernel rounded differently with one and
    with two BLAS threads; the kernel now has no BLAS product and holds BLAS to one thread."""
    runs = []
    for threads in (1, 2):
        with threadpool_limits(limits=threads, user_api="blas"):
            # the spec's 180 steps x 2 revolutions: OpenBLAS threads products of this size, not smaller
            runs.append(R.monte_carlo_chunk(g, "G5", "P4", np.arange(20), 7))
    for name in runs[0]._fields:
        assert np.array_equal(getattr(runs[0], name), getattr(runs[1], name)), name


def test_monte_carlo_on_a_local_cluster_equals_serial(g):
    """Defect 4: serial (here with 2 BLAS threads, as a 2-core machine has by default) and a real dask
    LocalCluster of 2 worker processes (1 BLAS thread each), chunks of 37: the same bits."""
    options = {"steps_per_revolution": 180, "revolutions": 2}  # smaller products ran on one thread
    start = time.perf_counter()
    with threadpool_limits(limits=2, user_api="blas"):
        serial = R.monte_carlo(g, "G5", "P4", 90, 7, **options)
    local = R.monte_carlo(
        g,
        "G5",
        "P4",
        90,
        7,
        execution=parallel.Execution("local", workers=2, chunk_size=37, processes=True),
        **options,
    )
    _assert_same_study(serial, local)
    assert time.perf_counter() - start < 60.0  # about 6 s, most of it starting the cluster


def test_execution_value_and_the_older_keywords_agree(g):
    options = {"steps_per_revolution": 12, "revolutions": 1}
    calls = []
    a = R.monte_carlo(
        g,
        "G5",
        "P4",
        10,
        3,
        execution=parallel.Execution(chunk_size=4, progress=lambda k, n: calls.append((k, n))),
        **options,
    )
    assert calls == [(4, 10), (8, 10), (10, 10)]
    b = R.monte_carlo(g, "G5", "P4", 10, 3, chunk_size=4, executor="serial", **options)
    c = R.monte_carlo(g, "G5", "P4", 10, 3, **options)  # default chunks of 100
    _assert_same_study(a, b)
    _assert_same_study(a, c)
    with pytest.raises(InputError, match="not both"):
        R.monte_carlo(g, "G5", "P4", 10, 3, execution=parallel.Execution(), chunk_size=4)
    with pytest.raises(InputError, match="chunk-size must be an integer >= 1"):
        R.monte_carlo(g, "G5", "P4", 10, 3, chunk_size=0)


# ------------------------------------------------------------------------------ reproducing samples
@pytest.mark.parametrize("engine", ENGINES)
def test_chosen_samples_are_reproduced_bit_for_bit(g, engine):
    """Defect 6: the errors of any sample regenerate from the seed; a rotation sequence of them gives the
    sample's metrics exactly, whichever chunk the sample was computed in (with the same engine)."""
    r = R.monte_carlo(g, "G10", "P5", 30, 11, steps_per_revolution=45, chunk_size=7, engine=engine)
    worst = R.worst_samples(r, "axial_ptp", 3)
    drawn = R.monte_carlo_errors(g, "G10", "P5", worst, 11)
    assert [s.sample_index for s in drawn] == list(worst)
    for s in drawn:
        assert s.geometry == g._replace(first_ball_angle=r.samples.first_ball_angle[s.sample_index])
        assert s.errors.tilt_x == 0.0 and s.errors.inner.axial.cos.size == 2  # order-1 wobble only
        t = R.rotation_sequence(s.geometry, s.errors, revolutions=2, steps_per_revolution=45, engine=engine)
        for name in R.METRICS:
            assert getattr(t.metrics, name) == getattr(r.samples, name)[s.sample_index], name


def test_worst_samples_ranks_by_magnitude():
    zeros = np.zeros(5)
    s = R.MonteCarloSamples(np.arange(10, 15), *(zeros,) * 7)
    s = s._replace(dz_mean=np.array([-1.0, -4.0, 2.0, 4.0, 0.5]))
    assert list(R.worst_samples(s, "dz_mean", 3)) == [11, 13, 12]  # |-4| = |4|: lower index first
    assert list(R.worst_samples(s, "dz_mean", 99)) == [11, 13, 12, 10, 14]
    with pytest.raises(InputError, match=r"metric must be one of \['radial_ptp_x'"):
        R.worst_samples(s, "runout", 1)
    with pytest.raises(InputError, match="count must be an integer >= 1"):
        R.worst_samples(s, "axial_ptp", 0)
