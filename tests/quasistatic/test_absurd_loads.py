"""Issue 29: solves of absurd loads stop at the solver's bound, quickly, with a ConvergenceError that says
why (exit 3 on the command line); loads within the bound are still solved, and a flagged batch keeps
its other cases."""

import time

import numpy as np
import pytest

from bearinglab import catalog, quasistatic
from bearinglab.cli import main
from bearinglab.errors import ConvergenceError, InputError
from bearinglab.quasistatic import combined, sets
from bearinglab.units import RPM

B218 = catalog.get("B218")


def _bound(bearing):
    geo = combined._geometry(*combined._bearing_args(bearing), 0.0, "operating", "outer", bearing.type)
    return combined._load_bound(geo)


def test_the_bound_is_a_ball_compressed_by_its_diameter():
    """Z max K D^1.5 with K the stiffer contact at any angle: at least the load of every ball compressed by D
    at the free angle, and far above anything a bearing carries (B218: C0 = 86 kN, the bound 2.3e9 N)."""
    from bearinglab.quasistatic.contact import contact_stiffness

    k = contact_stiffness(B218.contact_angle, B218.contact_angle, B218.ball_diameter, B218.pitch_diameter,
                          B218.inner_conformity, B218.outer_conformity, B218.reduced_modulus)
    bound = _bound(B218)
    assert bound >= B218.n_balls * max(k.inner, k.outer) * B218.ball_diameter**1.5 * (1 - 1e-12)
    assert bound > 1e9


@pytest.mark.parametrize("loads", [[0, 1e33, 0, 0, 0], [0, 0, -1e30, 0, 0], [0, 0, 5e3, 1e30, 0]])
def test_load_distribution_stops_at_the_bound(loads):
    start = time.perf_counter()
    with pytest.raises(ConvergenceError, match="beyond what the bearing can carry") as err:
        combined.combined_analysis(B218, loads)
    assert err.value.iterations == 0 and not err.value.physical and time.perf_counter() - start < 1.0
    r = combined.combined_analysis(B218, [loads, [0, 1e3, 5e3, 0, 0]], on_failure="flag")
    assert r.converged.tolist() == [False, True] and np.isnan(r.displacement[0]).all()
    assert any("the solver's bound" in w for w in r.warnings)


def test_a_load_just_within_the_bound_is_still_solved():
    f = 0.5 * _bound(B218)
    r = combined.combined_analysis(B218, [0, 0, f, 0, 0], on_failure="flag")
    assert r.converged  # absurd but within the model: solved, its plausibility warnings say the rest


def test_bearing_set_and_high_speed_stop_at_the_bound():
    start = time.perf_counter()
    with pytest.raises(ConvergenceError, match="beyond what the set can carry"):
        sets.set_analysis(B218, [0, 1e33, 0, 0, 0], arrangement_kind="DB", spacing=0.1, preload=1e3)
    with pytest.raises(ConvergenceError, match="beyond what the bearing can carry"):
        quasistatic.high_speed_analysis(B218, 1e33, 3000 * RPM)
    assert time.perf_counter() - start < 2.0
    s = sets.set_analysis(B218, [[0, 1e33, 0, 0, 0], [0, 1e3, 0, 0, 0]], arrangement_kind="DB", spacing=0.1,
                          preload=1e3, on_failure="flag")
    assert s.converged.tolist() == [False, True]
    h = quasistatic.high_speed_analysis(B218, [1e33, 5e3], 3000 * RPM, on_failure="flag")
    assert h.status.tolist() == ["no_convergence", "ok"] and h.axial_load[0] == 1e33


def test_a_thrust_too_light_to_resolve_is_an_input_error():
    with pytest.raises(InputError, match="axial_load must be >= .* to be resolved"):
        quasistatic.high_speed_analysis(B218, 1e-30, 3000 * RPM)
    assert quasistatic.high_speed_analysis(B218, 1e-3, 0.0).converged


@pytest.mark.parametrize("args", [["load-distribution", "-b", "B218", "--fy", "1e30 kN"],
                                  ["bearing-set", "-b", "B218", "--preload", "1 kN", "--fy", "1e30 kN"],
                                  ["high-speed", "-b", "B218", "-F", "1e30 kN", "-n", "3000 rpm"]])
def test_the_command_line_exits_3_with_the_reason(capsys, args):
    start = time.perf_counter()
    assert main(args) == 3
    err = capsys.readouterr().err
    assert "can carry" in err and "solver's bound" in err and len(err.strip().splitlines()) == 1
    assert time.perf_counter() - start < 5.0
