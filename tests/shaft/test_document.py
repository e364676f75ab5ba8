"""The calculation ``shaft`` through the typed-request layer: its JSON document and its figure."""

import math

import numpy as np
import pytest

from bearinglab import calculations, shaft
from bearinglab.calculations import RequestError, RunFailure, parse, run

SPINDLE = '''
[[sections]]
length = "60 mm"
diameter = "70 mm"
bore = "30 mm"
[[sections]]
length = "90 mm"
diameter = "70 mm"
bore = "30 mm"
[[sections]]
length = "200 mm"
diameter = "65 mm"
bore = "30 mm"
[[sections]]
length = "50 mm"
diameter = "60 mm"
bore = "30 mm"
[[supports]]
name = "front"
position = "100 mm"
bearing_set = { bearing = "7014 C", arrangement = "DB", preload = "500 N" }
[[supports]]
name = "rear"
position = "375 mm"
bearing = "6012"
[[loads]]
name = "tool"
position = "0 mm"
fx = "1 kN"
fz = "300 N"
[lubricant]
viscosity = "20 cSt"
contamination = "normal"
'''

GEARS = '''
speed = "1500 rpm"
[[sections]]
length = "300 mm"
diameter = "35 mm"
[[supports]]
name = "A"
position = "20 mm"
bearing = "6207"
axial = true
[[supports]]
name = "B"
position = "280 mm"
bearing = "6207"
[[gears]]
name = "pinion"
position = "100 mm"
pitch_diameter = "80 mm"
helix_angle = "15 deg"
power = "7.5 kW"
[[gears]]
name = "wheel"
position = "220 mm"
pitch_diameter = "160 mm"
power = "-7.5 kW"
mesh_angle = "180 deg"
[[cases]]
time_share = 0.3
factor = 1.4
[[cases]]
time_share = 0.7
factor = 0.8
speed = "1200 rpm"
'''


def test_the_document_holds_the_issues_keys_and_its_supports_carry_the_applied_loads():
    doc = run(parse("shaft", {"model": SPINDLE, "speed": "6000 rpm", "stiffness_at": "0 mm", "modes": "4"}))
    assert doc["speed_rpm"] == pytest.approx(6000.0)
    for key in ("force_x_N", "force_y_N", "force_z_N", "moment_x_Nm", "moment_y_Nm", "displacement_x_um",
                "displacement_y_um", "displacement_z_um", "tilt_x_mrad", "tilt_y_mrad"):
        assert all(key in s for s in doc["supports"])
    total = np.sum([[s["force_x_N"], s["force_y_N"], s["force_z_N"]] for s in doc["supports"]], axis=0)
    np.testing.assert_allclose(total, [1000.0, 0.0, 300.0], atol=1e-9 * 1000)
    assert doc["equilibrium"]["relative_error"] < 1e-9 and doc["convergence"]["converged"]
    rear = doc["supports"][1]
    for key in ("basic_rating_life_h", "modified_rating_life_h", "reference_rating_life_h", "static_safety_factor",
                "max_contact_pressure_MPa"):
        assert rear[key] is not None and rear[key] > 0
    front = doc["supports"][0]["bearings"]
    assert len(front) == 2 and front[1]["orientation"] == -1
    # the system life from the three bearings' L10 by the Weibull rule (slope 10/9)
    lives = [b["basic_rating_life_h"] for s in doc["supports"] for b in s["bearings"]]
    assert doc["system_life_h"] == pytest.approx(sum(x ** (-10 / 9) for x in lives) ** (-0.9), rel=1e-12)
    assert doc["system_life_h"] < min(lives)
    rows = doc["deflection"]
    assert rows[0]["z_mm"] == 0.0 and rows[0]["at"] == "tool"
    for z in (90.0, 110.0, 375.0):  # every bearing is a row
        assert any(abs(r["z_mm"] - z) < 1e-9 for r in rows)
    for key in ("displacement_x_um", "displacement_y_um", "slope_x_mrad", "slope_y_mrad", "bending_moment_x_Nm",
                "bending_moment_y_Nm", "shear_force_x_N", "shear_force_y_N"):
        assert key in rows[0]
    assert rows[1]["bending_moment_y_Nm"] == pytest.approx(-rows[1]["z_mm"] * 1e-3 * 1000.0, rel=1e-9)
    k = doc["stiffness_at"]
    assert k["position_mm"] == 0.0 and 10 < k["stiffness_x_N_per_um"] < 1000 and k["stiffness_y_N_per_um"] > 0
    assert len(doc["natural_frequencies_Hz"]) == 4 and doc["modes"][0]["whirl"] in ("forward", "backward")
    assert len(doc["modes"][0]["shape"]) == len(rows)


def test_a_duty_cycle_gives_miner_lives_and_the_system_life():
    doc = run(parse("shaft", {"model": GEARS}))
    sp = doc["spectrum"]
    assert [c["time_share"] for c in sp["cases"]] == [0.3, 0.7]
    u = np.array([0.3 * 1500, 0.7 * 1200]) / (0.3 * 1500 + 0.7 * 1200)
    np.testing.assert_allclose([c["revolution_share"] for c in sp["cases"]], u, rtol=1e-12)
    # each bearing's Miner life from the lives of its cases (solved here case by case), in hours at the mean speed
    d = shaft.from_text(GEARS)
    lives = []
    for k, (w, f) in enumerate(zip(d.case_speed, d.case_factor, strict=True)):
        st = shaft.bearing_states(shaft.solve(d.system, shaft.load_cases(d.system, speed=[w], factor=[f])))
        lives.append([b.life.basic_rating_life[0] for b in st])
    lives = np.array(lives)
    mean = (0.3 * 1500 + 0.7 * 1200) / 60.0  # rev/s
    miner = 1.0 / np.sum(u[:, None] / lives, axis=0) / mean / 3600.0
    np.testing.assert_allclose([b["basic_rating_life_h"] for b in sp["bearings"]], miner, rtol=1e-9)
    assert sp["system_life_h"] == pytest.approx(np.sum(miner ** (-10 / 9)) ** (-0.9), rel=1e-9)


def test_the_figure_is_drawn_from_the_document():
    svg = calculations.figure_svg(parse("shaft", {"model": GEARS}))
    assert svg.startswith("<svg") and "</svg>" in svg


def test_requests_that_cannot_run_name_their_field():
    with pytest.raises(RequestError) as err:
        parse("shaft", {"speed": "3000 rpm"})
    assert err.value.parameter == "model"
    with pytest.raises(RunFailure) as err:
        run(parse("shaft", {"model": SPINDLE.replace('position = "375 mm"', 'position = "500 mm"')}))
    assert err.value.parameter == "model" and "supports[1].position" in str(err.value)
    with pytest.raises(RunFailure) as err:
        run(parse("shaft", {"model": SPINDLE, "stiffness_at": "900 mm"}))
    assert err.value.parameter == "stiffness_at"
    with pytest.raises(RequestError) as err:
        parse("shaft", {"model": SPINDLE, "modes": "51"})
    assert err.value.parameter == "modes"


def test_a_campbell_diagram_over_speeds():
    doc = run(parse("shaft", {"model": SPINDLE, "campbell": "0, 10000, 20000 rpm", "modes": "2"}))
    c = doc["campbell"]
    assert c["speed_rpm"] == pytest.approx([0.0, 10000.0, 20000.0])
    f = np.array(c["frequency_Hz"], dtype=float)
    assert f.shape == (3, 4) and np.all(f > 0)
    assert all(set(w) <= {"forward", "backward", ""} for w in c["whirl"])


def test_the_unchecked_request_of_the_command_line_gives_the_same_document():
    given = {"model": SPINDLE, "speed": "3000 rpm", "stiffness_at": "0 mm"}
    a = run(parse("shaft", given))
    b = run(parse("shaft", given, check=False))
    assert a["supports"] == b["supports"] and a["stiffness_at"] == b["stiffness_at"]
    assert math.isclose(a["speed_rpm"], 3000.0)
