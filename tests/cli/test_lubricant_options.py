"""The shared oil options of the command line (cli._common.lubricant_viscosity, issue 20 item 4)."""

import pytest

from bearinglab import ratings
from bearinglab.cli._common import lubricant_viscosity, parse_temperature
from bearinglab.errors import InputError


def test_grade_and_temperature_are_enough():
    r = lubricant_viscosity(oil="VG68", temperature="70 degC")
    nu100 = ratings.viscosity_100_from_index(68e-6, 95.0)  # the default VI of a mineral oil (SKF)
    assert r.viscosity == pytest.approx(float(ratings.kinematic_viscosity(343.15, viscosity_40=68e-6,
                                                                          viscosity_100=nu100)), rel=1e-12)
    assert r.inputs["viscosity_index"] == 95.0 and r.inputs["viscosity_index_assumed"] is True
    assert "VI 95 (assumed" in r.description and "ASTM D2270" in r.description


def test_viscosity_index_and_viscosity_100_change_it():
    base = lubricant_viscosity(oil="VG68", temperature="70 degC").viscosity
    flatter = lubricant_viscosity(oil="ISO VG 68", temperature="70 degC", viscosity_index=140.0)
    assert flatter.viscosity > base and flatter.inputs["viscosity_index_assumed"] is False
    sheet = lubricant_viscosity(oil="vg68", temperature="158 degF", viscosity_100="8.7 cSt")
    assert sheet.viscosity == pytest.approx(float(ratings.kinematic_viscosity(343.15, iso_vg=68,
                                                                              viscosity_100=8.7e-6)), rel=1e-12)
    assert "viscosity_index" not in sheet.inputs


def test_viscosity_alone_and_nothing():
    assert lubricant_viscosity(viscosity="20 cSt").viscosity == pytest.approx(20e-6)
    assert lubricant_viscosity().viscosity is None
    with pytest.raises(InputError, match="^viscosity: give --viscosity"):
        lubricant_viscosity(required=True)


@pytest.mark.parametrize("kwargs, message", [
    ({"oil": "VG68", "temperature": "70 degC", "viscosity_index": 95.0, "viscosity_100": "8 cSt"},
     "^viscosity-index: give --viscosity-index or --viscosity-100, not both"),
    ({"viscosity": "20 cSt", "oil": "VG68"}, "^viscosity: give --viscosity, or --oil"),
    ({"oil": "VG68"}, "^temperature: --oil also needs --temperature"),
    ({"temperature": "70 degC", "viscosity_index": 100.0}, "^oil: --temperature, --viscosity-index also need --oil"),
    ({"oil": "VG70", "temperature": "70 degC"}, "^oil must be an ISO VG grade"),
    ({"oil": "VG68", "temperature": "70 degC", "viscosity_100": "80 cSt"}, "^viscosity-100 must be below"),
    ({"oil": "VG68", "temperature": "70 degC", "viscosity_index": float("inf")}, "^viscosity-index must be in"),
])
def test_refusals_name_the_option(kwargs, message):
    with pytest.raises(InputError, match=message):
        lubricant_viscosity(**kwargs)


def test_temperatures():
    assert parse_temperature("70 degC") == pytest.approx(343.15)
    assert parse_temperature("343.15 K") == pytest.approx(343.15)
    assert parse_temperature("158 degF") == pytest.approx(343.15)
    for bad in ("-300 degC", "70", "hot"):
        with pytest.raises(InputError, match="^temperature"):
            parse_temperature(bad)
