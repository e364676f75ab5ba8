"""Reading and checking a request's values: errors name the field, sizes are bounded before any work."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearinglab.calculations import CALCULATIONS, CASE_LIMIT, RequestError, count_values, parse
from bearinglab.units import RPM


def test_a_request_reads_quantities_into_si():
    p = parse("high-speed", {"bearing": "B218", "axial_load": "20 kN", "speed": "10000 rpm"})
    assert p.values["axial_load"].tolist() == [20000.0]
    assert p.values["speed"][0] == pytest.approx(10000 * RPM, rel=1e-15)
    assert p.cases == 1 and not p.heavy


def test_a_grid_multiplies_its_lists():
    p = parse("high-speed", {"bearing": "B218", "axial_load": "1kN:10kN:1kN", "speed": "0, 5000 rpm"})
    assert p.cases == 20 and p.heavy


def test_a_range_is_counted_before_it_is_built():
    field = CALCULATIONS["high-speed"].field("axial_load")
    assert count_values(field, "1N:1e9N:1N") == 10**9  # no array of 10^9 values is made
    with pytest.raises(RequestError, match=r"axial_load: '1N:1e9N:1N' holds 1000000000 values") as err:
        parse("high-speed", {"bearing": "B218", "axial_load": "1N:1e9N:1N", "speed": "1 rpm"})
    assert err.value.parameter == "axial_load" and err.value.valid == f"at most {CASE_LIMIT} values"


def test_a_grid_over_the_case_limit_is_refused():
    with pytest.raises(RequestError, match="more than the limit of 100"):
        parse("high-speed", {"bearing": "B218", "axial_load": "1kN:20kN:1kN", "speed": "0rpm:9000rpm:1000rpm"},
              limit=100)


def test_a_full_design_map_of_ten_to_the_five_cases_is_valid():
    p = parse("high-speed", {"bearing": "B218", "axial_load": "1N:1000N:1N", "speed": "1rpm:100rpm:1rpm"})
    assert p.cases == 100_000


@pytest.mark.parametrize("name, given, parameter, words", [
    ("high-speed", {"axial_load": "1.2.3 kN", "speed": "1 rpm"}, "axial_load", "malformed number"),
    ("high-speed", {"axial_load": "2 m", "speed": "1 rpm"}, "axial_load", "is a length, expected a force"),
    ("high-speed", {"axial_load": "-2 kN", "speed": "1 rpm"}, "axial_load", "must be > 0 N, got -2000 N"),
    ("high-speed", {"speed": "1 rpm"}, "axial_load", "missing"),
    ("high-speed", {"axial_load": "1 kN", "speed": "1 rpm", "solver": "magic"}, "solver",
     "must be one of newton, angle-iteration"),
    ("frequencies", {"speed": "1 rpm", "harmonics": "100000000"}, "harmonics", "must be 1 ... 100"),
    ("frequencies", {"speed": "1 rpm", "harmonics": "2.5"}, "harmonics", "expected a whole number"),
    ("axial-angle", {"axial_load": "2 kgf", "rows": "1000000000"}, "rows", "must be 1 ... 1000"),
    ("frequencies", {"speed": "1 rpm", "mask": "maybe"}, "mask", "expected true or false"),
    ("life", {"reliability": "80"}, "reliability", "must be 90 ... 99.95 %, got 80 %"),
    ("life", {"wheels": "4"}, "wheels", "not an input of life"),
])
def test_an_error_names_the_field_value_and_valid_range(name, given, parameter, words):
    with pytest.raises(RequestError) as err:
        parse(name, dict({"bearing": "B218"}, **given))
    assert err.value.parameter == parameter
    assert words in str(err.value)
    assert str(err.value).startswith(parameter)


def test_each_boundary_words_the_error_its_own_way():
    with pytest.raises(RequestError) as err:
        parse("high-speed", {"bearing": "B218", "axial_load": "2 m", "speed": "1 rpm"})
    e = err.value
    field = CALCULATIONS["high-speed"].field(e.parameter)
    assert e.worded(lambda n: CALCULATIONS["high-speed"].field(n).cli_option).startswith("--axial-load: '2 m'")
    assert e.worded(lambda n: field.title).startswith("Axial load F_a: '2 m'")
    assert e.worded(lambda n: n).startswith("axial_load: '2 m'")


def test_an_empty_value_is_not_given():
    p = parse("frequencies", {"bearing": "B218", "speed": "1 rpm", "axial_load": " "})
    assert "axial_load" not in p.values


@settings(max_examples=300, deadline=None)
@given(name=st.sampled_from(sorted(CALCULATIONS)), data=st.data())
def test_any_text_is_read_or_refused_with_a_request_error(name, data):
    """Fuzz: no value of any field makes the reader fail otherwise (no crash, no huge allocation)."""
    calc = CALCULATIONS[name]
    field = data.draw(st.sampled_from(calc.fields))
    text = data.draw(st.one_of(
        st.text(max_size=30),
        st.from_regex(r"-?[0-9.eE+]{1,12} ?(kN|N|rpm|mm|um|deg|cSt|GPa|m|%)?(:[0-9.e]{1,8}){0,2}", fullmatch=True),
        st.integers(-10**12, 10**12).map(str),
        st.floats(allow_nan=True, allow_infinity=True).map(str)))
    try:
        p = parse(name, {field.name: text}, limit=1000)
    except RequestError as exc:
        assert exc.parameter in (None, *(f.name for f in calc.fields))
        return
    value = p.values.get(field.name)
    if isinstance(value, np.ndarray):
        assert value.size <= 1000 and np.all(np.isfinite(value))
    elif isinstance(value, float):
        assert math.isfinite(value)


def test_the_web_limits_are_the_command_lines_or_lower():
    from bearinglab import _bounds
    from bearinglab.calculations import registry

    assert CASE_LIMIT <= _bounds.MAX_CASES
    assert registry.DOCUMENT_LIMIT <= registry.BODY_LIMIT <= _bounds.MAX_INPUT_BYTES
    pairs = {"balls": _bounds.MAX_BALLS, "harmonics": _bounds.MAX_HARMONICS,
             "sidebands": _bounds.MAX_SIDEBANDS, "rows": _bounds.MAX_ROWS,
             "revolutions": _bounds.MAX_REVOLUTIONS, "steps_per_rev": _bounds.MAX_STEPS_PER_REV,
             "monte_carlo": _bounds.MAX_SAMPLES}
    seen = set()
    for calc in CALCULATIONS.values():
        for f in calc.fields:
            if f.name in pairs:
                assert f.maximum is not None and f.maximum <= pairs[f.name], (calc.name, f.name)
                seen.add(f.name)
    assert seen == set(pairs)


def test_monte_carlo_samples_are_cases_of_the_clearance_request():
    assert parse("clearance", {"bearing": "6205-2RS", "monte_carlo": "1000"}).cases == 1000
    with pytest.raises(RequestError, match="more than the limit") as err:
        parse("clearance", {"bearing": "6205-2RS", "monte_carlo": str(CASE_LIMIT + 1)})
    assert err.value.parameter == "monte_carlo"
