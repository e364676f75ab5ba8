"""Bearing sets with their mounting: the interference from the clearance lost, and bearing-set's JSON."""

import json
import math

import pytest

from bearinglab import catalog, geometry
from bearinglab.cli import main
from bearinglab.mounting import preload, thermal

B218 = catalog.get("B218")


def test_first_contact_offset_is_a_sin_alpha0():
    d, fi, fo = B218.ball_diameter, B218.inner_conformity, B218.outer_conformity
    big_a = (fi + fo - 1) * d
    # alpha0 from the clearance, written out: cos a0 = 1 - e / (2 A)
    a0 = math.acos(1 - B218.radial_clearance / (2 * big_a))
    assert preload.first_contact_offset(B218, B218.radial_clearance) == pytest.approx(big_a * math.sin(a0), rel=1e-12)
    assert a0 == pytest.approx(float(geometry.free_contact_angle(B218.radial_clearance, d, fi, fo)), rel=1e-12)


def test_small_clearance_loss_adds_interference_by_twice_the_offset_slope():
    """d(A sin a0)/de = -(1/2) cot(a0): losing de of clearance adds cot(a0) de of axial interference."""
    de = 1e-9
    e, _ = preload.operating_interference(B218, 0.0, de)
    assert e == pytest.approx(de / math.tan(B218.contact_angle), rel=1e-5)


@pytest.mark.parametrize("kind, sign", [("DB", -1), ("DF", +1), ("DT", 0)])
def test_axial_growth_of_the_shaft_between_the_bearings(kind, sign):
    t = thermal.REFERENCE_TEMPERATURE + 30
    e, _ = preload.operating_interference(B218, 0.0, 0.0, arrangement_kind=kind, spacing=0.1, shaft_temperature=t)
    assert e == pytest.approx(sign * 12.5e-6 * 30 * 0.1, abs=1e-18)


def test_all_clearance_gone_leaves_first_contact_at_the_concentric_position():
    """Issue 30 (this refused the case before): with no clearance left the balls touch in the concentric
    position (and are squeezed by -e'/2), so the spacers' interference grows by the whole 2 A sin(alpha0)."""
    e, clearance = preload.operating_interference(B218, 0.0, 2 * B218.radial_clearance)
    assert clearance == pytest.approx(-B218.radial_clearance, rel=1e-12)
    assert e == pytest.approx(2 * B218.groove_distance * math.sin(B218.contact_angle), rel=1e-12)
    assert preload.first_contact_offset(B218, [0.0, -1e-6]).tolist() == [0.0, 0.0]


def _set(capsys, *extra):
    code = main(["bearing-set", "-b", "B218", "--arrangement", "DB", "--spacing", "100 mm", "--preload", "1 kN",
                 *extra, "--json"])
    out, err = capsys.readouterr()
    assert code == 0, err
    return json.loads(out)


def test_bearing_set_reports_its_operating_preload(capsys):
    plain = _set(capsys)
    assert plain["operating_preload_N"] == pytest.approx(1000.0, rel=1e-9)  # assembled at rest, no load
    assert "operating_clearance_um" not in plain
    warm = _set(capsys, "--inner-ring-temperature", "35 degC", "--outer-ring-temperature", "25 degC")
    assert warm["operating_clearance_um"] == pytest.approx(B218.radial_clearance * 1e6 - 12.5e-6 * 10 * 125.3e3,
                                                           rel=1e-9)
    assert warm["operating_preload_N"] > plain["operating_preload_N"]  # warmer inner rings: more preload
    fitted = _set(capsys, "--shaft-fit", "k5", "--housing-fit", "H6", "--tolerance-class", "P5")
    assert fitted["operating_preload_N"] > plain["operating_preload_N"]
