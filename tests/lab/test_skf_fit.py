"""Task 4 of the friction lab (bearinglab.lab.fits.skf_friction): the SKF four-term model fitted back to
torques it made, within the noise; against an independent least-squares solve; grouped = one by one;
the [skf] session table, the analysis and the report."""

import json
import math
from pathlib import Path

import numpy as np
import pytest
from numpy.testing import assert_allclose

from bearinglab.errors import InputError
from bearinglab.friction.skf import skf
from bearinglab.lab import analysis, fits, measurement

RPM = 2 * math.pi / 60
EXAMPLE = Path(__file__).parents[2] / "examples" / "friction" / "skf_6205.toml"
GEOMETRY = (30e-6, 25e-3, 52e-3)  # nu [m^2/s], d, D [m] of a 6205 (series 62)
MODEL = {"series": "62", "static_load_rating": 7800.0}


def _grid():
    fr = np.repeat([40.0, 90.0, 180.0], 4)
    fa = np.tile([0.0, 20.0, 0.0, 60.0], 3)
    n = np.tile([600.0, 1200.0, 2400.0, 3600.0], 3) * RPM
    return fr, fa, n


def _torque(fr, fa, n, *, mu=None, scale=1.0):
    m = skf(fr, fa, n, *GEOMETRY, sliding_friction_coefficient=mu, **MODEL)
    return scale * m.rolling_moment + m.sliding_moment + m.seal_moment + m.drag_moment


def test_noiseless_torques_give_back_mu_sl_exactly():
    fr, fa, n = _grid()
    fit = fits.skf_friction(_torque(fr, fa, n, mu=0.083), fr, fa, n, *GEOMETRY, **MODEL)
    assert fit.sliding_friction_coefficient == pytest.approx(0.083, rel=1e-12)
    assert fit.rolling_scale == 1.0 and math.isnan(fit.rolling_scale_standard_error)
    assert fit.residual_rms < 1e-15
    assert fit.count == 12


def test_noiseless_torques_give_back_the_rolling_scale_and_both():
    fr, fa, n = _grid()
    t = _torque(fr, fa, n, mu=0.09, scale=1.3)
    both = fits.skf_friction(t, fr, fa, n, *GEOMETRY, fit="both", **MODEL)
    assert both.sliding_friction_coefficient == pytest.approx(0.09, rel=1e-9)
    assert both.rolling_scale == pytest.approx(1.3, rel=1e-9)
    t_model_mu = _torque(fr, fa, n, scale=0.7)  # the model's own mu_sl
    rolling = fits.skf_friction(t_model_mu, fr, fa, n, *GEOMETRY, fit="rolling", **MODEL)
    assert rolling.rolling_scale == pytest.approx(0.7, rel=1e-12)
    assert math.isnan(rolling.sliding_friction_coefficient)


def test_noisy_torques_give_mu_sl_within_the_noise():
    # normal noise of 2 % of the mean torque on 60 points (the OLS assumptions): the fitted mu_sl is
    # within 4 standard errors of the true one in each of 20 experiments, and the standard error agrees
    # with the scatter of the 20 fitted values within 30 % (the scatter of a 20-sample s.d. is ~16 %)
    fr, fa, n = (np.tile(a, 5) for a in _grid())
    exact = _torque(fr, fa, n, mu=0.11)
    sigma = 0.02 * exact.mean()
    found, errors = [], []
    for seed in range(20):
        noisy = exact + sigma * np.random.default_rng(seed).standard_normal(exact.size)
        fit = fits.skf_friction(noisy, fr, fa, n, *GEOMETRY, **MODEL)
        assert abs(fit.sliding_friction_coefficient - 0.11) < 4 * fit.sliding_friction_coefficient_standard_error
        found.append(fit.sliding_friction_coefficient)
        errors.append(fit.sliding_friction_coefficient_standard_error)
    assert np.std(found, ddof=1) == pytest.approx(np.mean(errors), rel=0.3)


def test_both_against_an_independent_lstsq_with_covariance():
    fr, fa, n = _grid()
    t = _torque(fr, fa, n, mu=0.1) * (1 + 0.03 * np.random.default_rng(5).standard_normal(fr.size))
    fit = fits.skf_friction(t, fr, fa, n, *GEOMETRY, fit="both", **MODEL)
    unit = skf(fr, fa, n, *GEOMETRY, sliding_friction_coefficient=1.0, **MODEL)
    a = np.column_stack([unit.sliding_moment, unit.rolling_moment])
    coef, ssr, *_ = np.linalg.lstsq(a, t, rcond=None)
    cov = ssr[0] / (t.size - 2) * np.linalg.inv(a.T @ a)
    assert_allclose([fit.sliding_friction_coefficient, fit.rolling_scale], coef, rtol=1e-9)
    assert_allclose(
        [fit.sliding_friction_coefficient_standard_error, fit.rolling_scale_standard_error],
        np.sqrt(np.diag(cov)),
        rtol=1e-7,
    )
    assert_allclose(fit.residuals, t - a @ coef, atol=1e-15)


@pytest.mark.parametrize("what", ["sliding", "rolling", "both"])
def test_grouped_fit_equals_one_fit_per_group(what):
    fr, fa, n = _grid()
    t = _torque(fr, fa, n, mu=0.1) * (1 + 0.03 * np.random.default_rng(9).standard_normal(fr.size))
    groups = np.array(list("ba") * 6)
    got = fits.skf_friction(t, fr, fa, n, *GEOMETRY, fit=what, groups=groups, **MODEL)
    for k, label in enumerate(["a", "b"]):
        sel = groups == label
        one = fits.skf_friction(t[sel], fr[sel], fa[sel], n[sel], *GEOMETRY, fit=what, **MODEL)
        for name in ("sliding_friction_coefficient", "rolling_scale", "residual_rms",
                     "sliding_friction_coefficient_standard_error", "rolling_scale_standard_error"):
            assert_allclose(getattr(got, name)[k], getattr(one, name), rtol=1e-12, err_msg=name)
        assert_allclose(got.residuals[sel], one.residuals, rtol=1e-12, atol=1e-18)


def test_seal_moment_is_taken_off_before_fitting():
    # the measured pair of issue 12 (61811-2RS1, grease, 30 mm^2/s): the seals dominate the torque
    kw = {"series": "618", "seal": "RS1", "seal_diameter": 59.5e-3}
    fr, n = np.array([6.51, 30.0, 60.0, 120.0]), np.array([500.0, 1000.0, 2000.0, 3000.0]) * RPM
    t = skf(fr, 0.0, n, 30e-6, 55e-3, 72e-3, sliding_friction_coefficient=0.12, **kw).total_moment
    fit = fits.skf_friction(t, fr, 0.0, n, 30e-6, 55e-3, 72e-3, **kw)
    assert fit.sliding_friction_coefficient == pytest.approx(0.12, rel=1e-10)


def test_errors():
    fr, fa, n = _grid()
    t = _torque(fr, fa, n)
    with pytest.raises(InputError, match=r"fit must be one of \['sliding', 'rolling', 'both'\]"):
        fits.skf_friction(t, fr, fa, n, *GEOMETRY, fit="mu", **MODEL)
    with pytest.raises(InputError, match="is what task 4 fits"):
        fits.skf_friction(t, fr, fa, n, *GEOMETRY, sliding_friction_coefficient=0.1, **MODEL)
    # one load and one speed: G_sl and M_rr are proportional, mu_sl and k cannot be told apart
    with pytest.raises(InputError, match="cannot separate mu_sl from the scale on M_rr") as err:
        fits.skf_friction(t[[0, 0]], fr[[0, 0]], fa[[0, 0]], n[[0, 0]], *GEOMETRY, fit="both",
                          groups=["x", "x"], **MODEL)
    assert err.value.group == "x"
    with pytest.raises(InputError, match="all load = 0"):
        fits.skf_friction([1e-3, 2e-3], 0.0, 0.0, [100.0, 200.0], *GEOMETRY, **MODEL)


def test_example_session_recovers_the_mu_sl_it_was_made_with(tmp_path):
    # examples/friction/skf_6205.toml: synthetic rows from the model with mu_sl = 0.10 and 1 % noise
    result = analysis.analyse(measurement.read_session(EXAMPLE))
    t4 = result.task4
    assert t4.fit == "sliding"
    assert_allclose(np.degrees(t4.tilt), [45.0, 90.0])
    assert np.all(np.abs(t4.sliding_friction_coefficient - 0.10) < 3 * t4.sliding_friction_coefficient_standard_error)
    assert np.all(t4.residual_rms < 0.02 * t4.mean_torque)  # the 1 % noise, not a model misfit
    assert np.all(t4.model_residual_rms > 3 * t4.residual_rms)  # the model's own mu_sl (0.06) misses

    from bearinglab.report import write_report

    files = write_report(result, tmp_path / "out", generated="test")
    d = json.loads(files.json.read_text())
    assert [r["tilt_deg"] for r in d["task4"]] == [45.0, 90.0]
    assert d["task4"][0]["mu_sl"] == pytest.approx(t4.sliding_friction_coefficient[0], rel=1e-12)
    assert (tmp_path / "out" / "task4.csv").is_file()
    html = files.html.read_text()
    assert "Task 4: SKF four-term model" in html and "μ_sl ± s.e." in html
    assert any(c.startswith("Task 4, SKF four-term model (β = 45°") for c in d["conclusions"])


def test_sessions_without_skf_table_have_no_task4():
    text = EXAMPLE.read_text().replace("[skf]", "[ignored]")
    text = "\n".join(line for line in text.splitlines()
                     if not line.startswith(("[ignored]", "viscosity", "lubrication", "series =", "fit =")))
    result = analysis.analyse(measurement.parse_session(text))
    assert result.task4 is None
    from bearinglab.lab import presentation

    assert presentation.to_dict(result)["task4"] == []


@pytest.mark.parametrize(
    ("old", "new", "message"),
    [
        ('viscosity = "30 mm^2/s"', "", "field 'skf.viscosity': is required for task 4"),
        ('viscosity = "30 mm^2/s"', 'viscosity = "30 mm"', "field 'skf.viscosity'"),
        ('lubrication = "grease"', 'lubrication = "oil-bath"', "field 'skf.lubrication': must be one of"),
        ('fit = "sliding"', 'fit = "mu"', "field 'skf.fit': must be one of"),
        ('series = "62"', 'series = "99"', r"field 'skf.series': must be one of \['2', .*\(deep groove\), got '99'; or give r1"),
        ('series = "62"', 'series = ""', r"field 'skf.series': must be one of .* got ''"),
        ('series = "62"', 'series = "62"\nr1 = 3.9e-7', "field 'skf.r1': give all of r1, r2, s1, s2"),
    ],
)
def test_skf_table_errors_name_the_field(old, new, message):
    text = EXAMPLE.read_text().replace(old, new)
    with pytest.raises(InputError, match=message):
        measurement.parse_session(text, source="s.toml")


def test_skf_series_is_read_without_its_spaces():
    session = measurement.parse_session(EXAMPLE.read_text().replace('series = "62"', 'series = " 62 "'))
    assert session.skf.series == "62"


def test_skf_constants_given_in_the_file():
    text = EXAMPLE.read_text().replace('series = "62"', "r1 = 3.9e-7\nr2 = 1.7\ns1 = 3.23e-3\ns2 = 36.5")
    session = measurement.parse_session(text)
    assert session.skf.series is None and session.skf.constants.s2 == 36.5
    by_series = analysis.analyse(measurement.read_session(EXAMPLE)).task4
    assert_allclose(analysis.analyse(session).task4.sliding_friction_coefficient,
                    by_series.sliding_friction_coefficient, rtol=1e-14)
