"""Issue 20 item 8: absurd errors are refused and doubtful ones warned about (runout.plausibility).

Spec 003 reference geometry (section 2): 16 balls of D_w = 7.144 mm, d_m = 54 mm, f_o = 0.53, f_i = 0.52,
tau0 = 15 deg, so A0 = (0.53 + 0.52 - 1) x 7.144 mm = 357.2 um and the limits are 0.05 D_w = 357.2 um
(refused) and 0.05 A0 = 17.86 um (warned), computed here by hand.
"""

import json
import math
import warnings

import numpy as np
import pytest

from bearinglab.cli import main
from bearinglab.errors import InputError, ValidityWarning
from bearinglab.runout import (
    RacewayErrors,
    exact_reduction,
    fourier_series,
    geometry_from_catalog,
    initial_displacement,
    manufacturing_errors,
    plausibility,
    rotation_sequence,
)

G = geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(15))
D_W = 7.144e-3
A0 = (0.53 + 0.52 - 1.0) * D_W


def _oversize(first_ball):
    d = np.zeros(16)
    d[0] = first_ball
    return manufacturing_errors(16, ball_diameter_deviation=d)


def _solve(errors, psi=0.0):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        r = initial_displacement(psi, G, errors)
    return r, [str(c.message) for c in caught if issubclass(c.category, ValidityWarning)]


def test_limits_by_hand():
    assert G.groove_distance == pytest.approx(A0, rel=1e-12)
    assert plausibility.ERROR_LIMIT * D_W == pytest.approx(357.2e-6, rel=1e-12)
    assert plausibility.LINEAR_LIMIT * A0 == pytest.approx(17.86e-6, rel=1e-12)


def test_a_metre_of_ball_error_is_refused():
    """The issue's case: 1 m on a 7 mm ball gave dz = -1.93 m with no warning."""
    with pytest.raises(InputError, match=r"ball_outer_deficit: up to 500000 um.*0.05 D_w = 357.2 um"):
        initial_displacement(0.0, G, _oversize(-1.0))  # undersize by 1 m in diameter: deficit 0.5 m
    with pytest.raises(InputError, match="ball_inner_deficit"):
        initial_displacement(0.0, G, manufacturing_errors(16, ball_inner_deficit=[400e-6] + [0.0] * 15))


def test_the_refusal_limit_is_five_percent_of_the_ball_diameter():
    below = manufacturing_errors(16, ball_outer_deficit=[356e-6] + [0.0] * 15)  # undersize: no contact
    initial_displacement(0.0, G, below)
    at = manufacturing_errors(16, ball_outer_deficit=[357.3e-6] + [0.0] * 15)
    with pytest.raises(InputError, match="357.3 um"):
        initial_displacement(0.0, G, at)


def test_raceway_errors_are_bounded_by_their_amplitude_sum():
    """An inner ovality of 400 um: its normal deviation reaches 400 cos(15 deg) = 386.4 um >= 357.2 um."""
    e = manufacturing_errors(16, inner=RacewayErrors(radial=fourier_series({2: 400e-6})))
    assert plausibility.error_bounds(G, e)["inner"] == pytest.approx(400e-6 * math.cos(math.radians(15)))
    with pytest.raises(InputError, match="inner raceway errors"):
        initial_displacement(0.0, G, e)
    # cos and sin terms of one order combine to their hypotenuse; orders add
    e = manufacturing_errors(16, outer=RacewayErrors(normal=fourier_series({2: 3e-6, 3: 1e-6}, {2: 4e-6})))
    assert plausibility.error_bounds(G, e)["outer"] == pytest.approx(6e-6, rel=1e-12)


@pytest.mark.parametrize("tilt", [7.0, fourier_series({0: 4.0, 1: 3.0}), lambda psi: 10.0 + 0.0 * psi])
def test_a_tilt_beyond_one_turn_is_refused(tilt):
    with pytest.raises(InputError, match=r"tilt_y must be within 2 pi"):
        initial_displacement(np.array([0.0, 1.0]), G, manufacturing_errors(16, tilt_y=tilt))


def test_spec_examples_draw_no_warning():
    """Micrometre errors (spec 003 example 1: a ball 2 um oversize) are well inside the model's range."""
    r, notes = _solve(_oversize(2e-6))
    assert notes == [] and r.z == pytest.approx(-3.863703e-6, abs=1e-12)


def test_displacements_beyond_five_percent_of_a0_are_warned_about():
    """A ball 10 um oversize pushes the ring by |u| = 20 um > 17.86 um; 8 um gives 16 um and no warning."""
    r, notes = _solve(_oversize(8e-6))
    assert notes == [] and math.hypot(r.x, r.z) < plausibility.LINEAR_LIMIT * A0
    r, notes = _solve(_oversize(10e-6))
    assert math.hypot(r.x, r.z) >= plausibility.LINEAR_LIMIT * A0
    assert len(notes) == 1 and "0.05 A0 = 17.86 um" in notes[0]
    # the warning rides along a whole sequence too, once
    with pytest.warns(ValidityWarning, match="position"):
        rotation_sequence(G, _oversize(10e-6), revolutions=1, steps_per_revolution=8)


def test_the_neglected_term_is_what_the_warning_says():
    """The rationale of LINEAR_LIMIT: first-order s(theta) against the exact reduction at the solved pose
    differs by at most |u|^2 / (2 A0) on the contact balls."""
    r, _ = _solve(_oversize(10e-6))
    c = r.contact
    contact = np.flatnonzero(c.contact)
    s1 = c.constant + c.sine * np.sin(r.ball_angle[contact]) + c.cosine * np.cos(r.ball_angle[contact])
    exact = exact_reduction(r.ball_angle[contact], r.x, r.y, r.z, G)
    u2 = r.x**2 + r.y**2 + r.z**2
    diff = np.abs(exact - s1)
    assert np.all(diff <= u2 / (2 * A0)) and np.max(diff) > 0.1 * u2 / (2 * A0)


def test_tilt_moving_the_raceway_by_five_percent_of_a0_is_warned_about():
    """A tilt of 1 mrad moves the raceway at R_b = 27 mm by 27 um >= 17.86 um."""
    notes = plausibility.check_errors(G, manufacturing_errors(16, tilt_x=1e-3))
    assert len(notes) == 1 and notes[0].startswith("tilt_x of up to 1 mrad moves the raceway")
    assert plausibility.check_errors(G, manufacturing_errors(16, tilt_x=0.5e-3)) == []


def test_cli_refuses_and_warns(capsys, tmp_path):
    bad = tmp_path / "bad.toml"
    text = ('[geometry]\nballs = 16\nball_diameter = "7.144 mm"\npitch_diameter = "54 mm"\nouter_conformity = 0.53\n'
            'inner_conformity = 0.52\ncontact_angle = "15 deg"\nfirst_ball_angle = "0 deg"\n\n[errors.balls]\n'
            "diameter = [{}, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0]\n")
    bad.write_text(text.format(-2e6), encoding="utf-8")  # um: a ball 2 m undersize
    code = main(["runout", "--errors", str(bad)])
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and len(err) == 1 and "ball_outer_deficit" in err[0] and "0.05 D_w" in err[0]
    doubtful = tmp_path / "doubtful.toml"
    doubtful.write_text(text.format(10), encoding="utf-8")
    assert main(["runout", "--errors", str(doubtful), "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert len(doc["warnings"]) == 1 and "0.05 A0" in doc["warnings"][0]
    assert main(["runout", "--errors", str(doubtful), "--revolutions", "1", "--steps-per-rev", "8"]) == 0
    assert "warning:" in capsys.readouterr().out
