"""Scale-out (issue 6): the batch entry points give the same results on every executor and chunking,
and a failed case stays flagged while the rest complete."""

import numpy as np
import pytest

from bearinglab import catalog, quasistatic
from bearinglab.cli import main
from bearinglab.units import RPM

B218 = catalog.get("B218")
LOADS = np.array([2.5e3, 10e3, 45e3])
SPEEDS = np.array([0.0, 6000.0, 15000.0]) * RPM


def _same(a, b):
    for k in a._fields:
        x, y = np.asarray(getattr(a, k)), np.asarray(getattr(b, k))
        assert np.array_equal(x, y, equal_nan=x.dtype.kind == "f"), k


def test_high_speed_sweep_serial_equals_local_cluster():
    serial = quasistatic.sweep(B218, LOADS, SPEEDS, chunk_size=4)
    local = quasistatic.sweep(B218, LOADS, SPEEDS, chunk_size=4, executor="local", workers=2, processes=False)
    _same(serial, local)


def test_high_speed_sweep_does_not_depend_on_chunk_size():
    ref = quasistatic.sweep(B218, LOADS, SPEEDS, chunk_size=9)
    for size in (1, 2, 5):
        got = quasistatic.sweep(B218, LOADS, SPEEDS, chunk_size=size)
        assert np.array_equal(got.converged, ref.converged)
        # Newton runs until every case of a batch meets the tolerance, so a case may take one more
        # (quadratically converged) step in one chunking than in another: equal to the tolerance
        np.testing.assert_allclose(got.contact_angle_inner, ref.contact_angle_inner, atol=1e-12)
        np.testing.assert_allclose(got.contact_angle_outer, ref.contact_angle_outer, atol=1e-12)


@pytest.mark.filterwarnings("ignore::bearinglab.errors.ValidityWarning")
def test_failed_case_in_the_middle_of_a_sweep_stays_flagged():
    # inner-raceway control has no solution at moderate thrust and high speed: flagged, the rest complete
    state = quasistatic.sweep(B218, LOADS, SPEEDS, chunk_size=2, raceway_control="inner", constants="harris")
    bad = ~state.converged
    assert bad.any() and (~bad).any()
    assert np.all(np.isnan(state.contact_angle_inner[bad]))
    assert set(np.asarray(state.status)[bad]) <= {"inner_contact_lost", "no_convergence", "angle_out_of_range"}
    assert np.all(np.isfinite(state.contact_angle_inner[~bad]))


def test_cli_high_speed_sweep_on_local_cluster(capsys):
    import json

    args = ["high-speed", "-b", "B218", "-F", "5kN,20kN", "-n", "0, 10000rpm", "--json", "--chunk-size", "1"]
    assert main(args) == 0
    serial = json.loads(capsys.readouterr().out)
    assert main(args + ["--executor", "local", "--workers", "2"]) == 0
    local = json.loads(capsys.readouterr().out)
    assert serial == local


def test_cli_bad_scheduler_address_is_one_line(capsys, monkeypatch):
    from bearinglab import parallel

    monkeypatch.setattr(parallel, "_CONNECT_TIMEOUT_S", 1.0)
    code = main(["high-speed", "-b", "B218", "-F", "5kN,20kN", "-n", "0, 10000rpm", "--executor", "tcp://127.0.0.1:9"])
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and "cannot reach a dask scheduler" in err
    code = main(["high-speed", "-b", "B218", "-F", "5kN,20kN", "-n", "0, 10000rpm", "--executor", "mars"])
    assert code == 2 and "executor must be 'serial', 'local' or a scheduler address" in capsys.readouterr().err


# ----------------------------------------------------------------------------- runout Monte Carlo
def _mc(**kw):
    from bearinglab import runout

    g = runout.geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, np.radians(15.0))
    return runout.monte_carlo(g, "G5", "P4", 24, 11, steps_per_revolution=24, **kw)


def test_monte_carlo_serial_equals_local_cluster_and_any_chunking():
    ref = _mc(chunk_size=24)
    for kw in ({"chunk_size": 5}, {"chunk_size": 1}, {"chunk_size": 7, "executor": "local", "workers": 2, "processes": False}):
        got = _mc(**kw)
        for k in ref.samples._fields:
            assert np.array_equal(getattr(ref.samples, k), getattr(got.samples, k)), (kw, k)
        assert ref.summary == got.summary


def test_cli_monte_carlo_on_local_cluster(capsys):
    import json

    args = ["runout", "monte-carlo", "--bearing", "B218", "--samples", "6", "--seed", "2", "--steps-per-rev", "12",
            "--json", "--chunk-size", "2"]
    assert main(args) == 0
    serial = json.loads(capsys.readouterr().out)
    assert main(args + ["--executor", "local", "--workers", "2"]) == 0
    local = json.loads(capsys.readouterr().out)
    assert serial == local


# ----------------------------------------------------------------------------- generic sweep of the high-speed model
def test_generic_sweep_of_the_high_speed_model_reproduces_spec_004(tmp_path):
    from bearinglab import sweep

    p = tmp_path / "hs.toml"
    p.write_text('model = "high-speed"\nbearing = "B218"\n[parameters]\naxial_load = ["2.5 kN", "20 kN", "-1 kN"]\n'
                 'speed = "0, 10000rpm"\n[constants]\nconstants = "harris"\n')
    cols = sweep.run_sweep(sweep.load_sweep(p), chunk_size=2)
    assert cols["axial_load_N"].tolist() == [2500.0, 2500.0, 20000.0, 20000.0, -1000.0, -1000.0]
    assert cols["converged"].tolist() == [True, True, True, True, False, False]
    assert cols["failure"][4] == "axial_load must be > 0"
    # spec 004 section 7.1: 2.5 kN static 40.421; 20 kN at 10 000 rpm 49.308 / 32.514
    np.testing.assert_allclose(cols["contact_angle_inner_deg"][[0, 3]], [40.421, 49.308], atol=1e-3)
    np.testing.assert_allclose(cols["contact_angle_outer_deg"][3], 32.514, atol=1e-3)
