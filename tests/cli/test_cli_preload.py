"""Issue 30 item 1 at the command line: a single bearing with zero or negative operating clearance, from
``--radial-clearance`` or from fits and temperatures, is solved as preloaded by every model that takes the
clearance; each document reports the preload and warns how far the clearance is negative."""

import json

import pytest

from bearinglab.cli import main

# issue 30's case: a 6208 on k5/H7 with its inner ring 10 K warmer than the outer one
WARM_K5 = ["--shaft-fit", "k5", "--housing-fit", "H7", "--inner-ring-temperature", "50 degC",
           "--outer-ring-temperature", "40 degC"]
COMMANDS = {
    "load-distribution": ["load-distribution", "--fx", "2 kN"],
    "life": ["life", "--fx", "2 kN", "--speed", "3000 rpm", "--viscosity", "20 cSt"],
    "high-speed": ["high-speed", "-F", "1 kN", "-n", "6000 rpm"],
    "film": ["film", "--fx", "2 kN", "--speed", "3000 rpm", "--viscosity", "20 cSt"],
}


def run(capsys, *args):
    code = main(list(args))
    captured = capsys.readouterr()
    return code, captured.out, captured.err


@pytest.mark.parametrize("command", sorted(COMMANDS))
def test_a_6208_on_k5_h7_with_a_warm_inner_ring_is_solved_preloaded(capsys, command):
    code, out, err = run(capsys, *COMMANDS[command], "-b", "6208", *WARM_K5, "--json")
    assert code == 0, err
    doc = json.loads(out)
    e = doc["operating_clearance_um"]
    assert e < 0  # the fits and the warmer inner ring took all the clearance
    p = doc["preload"]
    assert p["operating_clearance_um"] == pytest.approx(e, rel=1e-12)
    assert p["interference_per_ball_um"] == pytest.approx(-e / 2, rel=1e-12)
    assert p["ball_load_N"] > 0 and p["ball_load_sum_N"] == pytest.approx(9 * p["ball_load_N"], rel=1e-12)
    assert p["stiffness_at_zero_load"]["k_xx_N_per_um"] > 0
    assert any(f"is negative, {e:.3g} um" in w and "preloaded" in w for w in doc["warnings"])


def test_the_film_runs_at_the_ball_loads_of_the_mounted_bearing(capsys):
    """One clearance per bearing: the film's ball loads under fits and ring temperatures are those of
    the load distribution at the same speed, not those of the unmounted clearance."""
    case = ["-b", "6208", "--fx", "3 kN", "--speed", "3000 rpm", "--json"]

    def loads(*args):
        code, out, err = run(capsys, *args)
        assert code == 0, err
        doc = json.loads(out)
        return doc.get("operating_clearance_um"), sorted(b["load_inner_N"] for b in doc["balls"])

    clearance, spread = loads("load-distribution", *case, *WARM_K5)
    film_clearance, film = loads("film", *case, *WARM_K5, "--viscosity", "20 cSt")
    assert clearance < 0 and film_clearance == pytest.approx(clearance, rel=1e-12)
    assert film == pytest.approx(spread, rel=1e-9)
    _, unmounted = loads("film", *case, "--viscosity", "20 cSt")
    assert max(unmounted) > max(film) * 1.02  # with its unmounted clearance fewer balls carry the load


def test_a_c3_bearing_with_a_warm_inner_ring_fed_into_load_distribution(capsys):
    """Issue 23's case, issue 30's bar: a C3 6208 on k5/H7 with its inner ring 20 K warmer runs out of clearance;
    load-distribution solves it preloaded (every ball loaded at zero load) instead of refusing it."""
    args = ["load-distribution", "-b", "6208-C3", "--shaft-fit", "k5", "--housing-fit", "H7",
            "--inner-ring-temperature", "60 degC", "--outer-ring-temperature", "40 degC"]
    code, out, err = run(capsys, *args, "--fx", "2 kN", "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["operating_clearance_um"] < 0 and doc["converged"] and doc["preload"]["ball_load_N"] > 0
    code, out, err = run(capsys, *args, "--json")
    assert code == 0, err
    loads = [b["load_inner_N"] for b in json.loads(out)["balls"]]
    assert min(loads) > 0 and max(loads) == pytest.approx(min(loads), rel=1e-9)


@pytest.mark.parametrize("clearance", ["0 um", "-4 um"])
def test_radial_clearance_zero_or_negative_is_taken_by_every_model(capsys, clearance):
    runs = {**COMMANDS, "film": ["film", "--fx", "2 kN", "--speed", "3000 rpm", "--viscosity", "20 cSt"]}
    for name, args in runs.items():
        code, out, err = run(capsys, *args, "-b", "6208", "--radial-clearance", clearance, "--json")
        assert code == 0, (name, err)
        doc = json.loads(out)
        doc = doc[0] if isinstance(doc, list) else doc
        assert doc["preload"]["operating_clearance_um"] == pytest.approx(float(clearance.split()[0]), abs=1e-12)
        assert (doc["preload"]["ball_load_N"] > 0) == (clearance != "0 um"), name


def test_load_distribution_of_a_preloaded_bearing_loads_every_ball_at_zero_load(capsys):
    code, out, err = run(capsys, "load-distribution", "-b", "6208", "--radial-clearance", "-4 um", "--json")
    assert code == 0, err
    doc = json.loads(out)
    loads = [b["load_inner_N"] for b in doc["balls"]]
    assert min(loads) == pytest.approx(doc["preload"]["ball_load_N"], rel=1e-9)
    assert doc["displacement_x_um"] == 0.0 and doc["stiffness_matrix"][0][0] > 0


def test_bearing_set_with_all_clearance_gone_is_solved(capsys):
    code, out, err = run(capsys, "bearing-set", "-b", "6208", "--preload", "200 N", "--fx", "1 kN", "--shaft-fit",
                         "p6", "--housing-fit", "K6", "--inner-ring-temperature", "70 degC",
                         "--outer-ring-temperature", "40 degC", "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["operating_clearance_um"] < 0 and doc["preload"]["ball_load_N"] > 0
    assert doc["operating_preload_N"] > 200.0  # the fits and temperatures add to the set's preload


def test_friction_torque_reports_the_preload_it_leaves_out(capsys):
    code, out, err = run(capsys, "friction", "torque", "-b", "6208", "--radial-load", "1 kN", "--speed", "3000 rpm",
                         *WARM_K5, "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["operating_clearance_um"] < 0 and doc["preload"]["ball_load_N"] > 0
    assert any("leaves the preload's ball loads out" in w for w in doc["warnings"])
