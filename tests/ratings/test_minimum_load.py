"""The minimum load of a running ball bearing (issue 20 item 12): SKF's rules against hand calculations, and
the high-speed warning that replaces the test-stand criterion for a running bearing."""

import json
import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from bearinglab import catalog, ratings
from bearinglab.cli import main
from bearinglab.ratings import minimum_load as ml

RPM = math.pi / 30


def test_every_rule_has_its_source():
    rules = ml.minimum_load_rules()
    assert set(rules) == {"general", "deep_groove", "angular_contact"}
    for name, rule in rules.items():
        assert "SKF, Rolling bearings, PUB BU/P1 17000 EN (2018)" in rule["source"], name
    assert rules["general"]["factor"] == 0.01  # "minimum loads of 0,01 C should be imposed on ball bearings"


def test_general_rule_by_hand():
    assert ml.general_minimum_load(14800.0) == pytest.approx(148.0, rel=1e-15)


def test_deep_groove_rule_by_hand():
    # F_rm = k_r (nu n / 1000)^(2/3) (d_m / 100)^2 kN: k_r = 0.025, nu = 20 mm^2/s, n = 3000 r/min, d_m = 38.5 mm
    by_hand = 0.025 * (20 * 3000 / 1000) ** (2 / 3) * (38.5 / 100) ** 2 * 1000  # N
    assert by_hand == pytest.approx(56.79, abs=0.01)
    assert ml.minimum_radial_load(3000 * RPM, 38.5e-3, 20e-6, 0.025) == pytest.approx(by_hand, rel=1e-13)


def test_angular_contact_rule_by_hand():
    # F_am = A (n / 1000)^2 kN: A = 0.00377, n = 10 000 r/min -> 0.377 kN
    assert ml.minimum_axial_load(10000 * RPM, 0.00377) == pytest.approx(377.0, rel=1e-13)
    assert ml.minimum_axial_load(0.0, 0.00377) == 0.0


@given(n=st.floats(10.0, 3e4), nu=st.floats(2.0, 500.0), dm=st.floats(5.0, 500.0), kr=st.floats(0.01, 0.2))
def test_deep_groove_rule_scales_as_published(n, nu, dm, kr):
    f = ml.minimum_radial_load(n * RPM, dm * 1e-3, nu * 1e-6, kr)
    assert ml.minimum_radial_load(2 * n * RPM, dm * 1e-3, nu * 1e-6, kr) == pytest.approx(f * 2 ** (2 / 3), rel=1e-12)
    assert ml.minimum_radial_load(n * RPM, 2 * dm * 1e-3, nu * 1e-6, kr) == pytest.approx(4 * f, rel=1e-12)
    assert ml.minimum_radial_load(n * RPM, dm * 1e-3, 2 * nu * 1e-6, kr) == pytest.approx(f * 2 ** (2 / 3), rel=1e-12)


def test_warning_counts_cases_at_speed_only():
    msgs = ml.minimum_load_warnings([50.0, 50.0, 5e3], [0.0, 100.0, 100.0], 1e5, case_index=[7, 8, 9])
    assert len(msgs) == 1
    assert msgs[0].startswith("minimum load: 1 of 3 case(s) at speed below 0.01 C = 1 kN")
    assert "e.g. case 8: P = 0.05 kN" in msgs[0]
    assert ml.minimum_load_warnings([5e3], [100.0], 1e5) == []


def _high_speed(capsys, *args):
    code = main(["high-speed", "-b", "B218", *args, "--json"])
    out, err = capsys.readouterr()
    assert code == 0, err
    return json.loads(out)


def test_issue_case_no_longer_warns(capsys):
    # issue 20: B218 at 20 kN and 15 000 rpm was told "2e+04 N < 1.132e+05 N" (the test-stand criterion at
    # mu = 0.02, more than C); with SKF's rule 0.01 C it is well loaded
    doc = _high_speed(capsys, "-F", "20 kN", "-n", "15000 rpm")
    assert not any("minimum" in w for w in doc["warnings"]), doc["warnings"]
    c = ratings.bearing_ratings(catalog.get("B218")).dynamic_load_rating
    assert 1.132e5 > c  # what the old warning asked for exceeded the rating itself


def test_light_thrust_warns_in_kn(capsys):
    doc = _high_speed(capsys, "-F", "0.5 kN", "-n", "15000 rpm")
    text = [w for w in doc["warnings"] if w.startswith("minimum load")]
    assert len(text) == 1
    c = ratings.bearing_ratings(catalog.get("B218")).dynamic_load_rating
    assert f"below 0.01 C = {0.01 * c / 1e3:.4g} kN" in text[0]
    # ISO 281 table 3, single-row 40 deg, Fa/Fr > e: X = 0.35, Y = 0.57, so P = 0.57 x 0.5 kN (pure thrust)
    assert "P = X F_r + Y F_a (ISO 281) = 0.285 kN" in text[0]
    assert "stand-load" in text[0] and not any(" N < " in w for w in doc["warnings"])


def test_below_the_limit_only_at_speed(capsys):
    assert not any("minimum load" in w for w in _high_speed(capsys, "-F", "0.5 kN", "-n", "0 rpm")["warnings"])
    low = np.array([0.5e3])
    assert ml.minimum_load_warnings(low, [0.0], 1e5) == []


def test_load_distribution_at_speed_judges_the_reactions_of_the_balls():
    # B218 under F_r = F_a = 1 kN at 6000 rpm: the balls' reactions give back F_r and F_a, and with
    # F_a/F_r = 1 <= e = 1.14 (ISO 281 table 3, 40 deg) P = F_r = 1 kN, below 0.01 C of the geometry
    from bearinglab.quasistatic import combined

    b = catalog.get("B218")
    r = combined.combined_analysis(b, [1e3, 0, 1e3, 0, 0], 6000 * RPM)
    text = [w for w in r.warnings if w.startswith("minimum load")]
    c = ratings.dynamic_load_rating(b.n_balls, b.ball_diameter, b.pitch_diameter, b.contact_angle)
    assert len(text) == 1 and f"0.01 C (ISO 281, from the geometry) = {0.01 * c / 1e3:.4g} kN" in text[0]
    assert "P = X F_r + Y F_a (ISO 281) = 1 kN" in text[0]
    heavy = combined.combined_analysis(b, [5e3, 0, 10e3, 0, 0], 6000 * RPM)
    assert not any(w.startswith("minimum load") for w in heavy.warnings)
