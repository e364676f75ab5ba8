"""Issue 29, items 1 and 2: one grammar for every quantity, every result finite or an error.

Each finding of the issue is a test here, with variants: numbers silently read as other numbers (a unit
with a plain factor, a decimal comma, digit grouping, non-ASCII digits, an expression, an underflow), the
mounting temperatures that went through pint's evaluator, designations with a dangling separator, the
CLI's integer and float options, range counts that overflowed, non-finite results that crashed a table or
printed null, and an int that overflowed numpy. The web's side of the same inputs is in
tests/web/test_strict_input_web.py; the fuzz generated from the registry in
tests/calculations/test_fuzz_registry.py.
"""

import json
import math
import re
import time

import numpy as np
import pytest

from bearinglab import calculations, catalog, designation, units
from bearinglab.calculations import CALCULATIONS, RequestError, count_values, parse, parse_field
from bearinglab.cli import main
from bearinglab.errors import ConvergenceError, InputError


def run(capsys, *args):
    code = main([str(a) for a in args])
    out, err = capsys.readouterr()
    return code, out, err


def one_line(code, err, expected=2):
    assert code == expected, err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("bearinglab: error: "), err
    return lines[0]


# ----------------------------------------------------------------------------- no plain factor in a unit
@pytest.mark.parametrize("text, kind, factor", [
    ("2 turn kgf", "force", "turn"),            # the issue: read as 123 N
    ("2 kgf %", "force", "percent"),            # 0.196 N
    ("10000 % rpm", "speed", "percent"),        # 100 rpm
    ("2 kgf h/s", "force", "hour/second"),      # 70 608 N
    ("2 rad kgf", "force", "radian"),
    ("2 kgf ppm", "force", "ppm"),
    ("2 kgf permille", "force", "permille"),
    ("3000 rpm %", "speed", "percent"),
    ("2 kgf min/s", "force", "minute/second"),
    ("2 km/m N", "force", "kilometer/meter"),
    ("2 deg N*m", "torque", "degree"),
    ("1 kN*deg/rad", "force", "degree"),
    ("3000 rad*rpm", "speed", "turn"),          # two angles: one is the speed's, the other a factor
    ("12 deg %", "angle", "percent"),
    ("20 cSt %", "kinematic_viscosity", "percent"),
    ("5 mm/m", "dimensionless", "millimeter/meter"),
])
def test_a_unit_with_a_plain_factor_is_refused(text, kind, factor):
    with pytest.raises(InputError, match=rf"x: cannot read '{re.escape(text)}' as a quantity: '{factor}' is a plain "
                                         "factor"):
        units.parse_quantity(text, kind, "x")


def test_an_angle_is_no_plain_number():
    with pytest.raises(InputError, match=r"x: '2 deg' is an angle, expected a plain number"):
        units.parse_quantity("2 deg", "dimensionless", "x")


@pytest.mark.parametrize("text, kind, want", [
    ("2 kgf", "force", 19.6133), ("3000 rpm", "speed", 100 * math.pi), ("12 deg", "angle", math.radians(12)),
    ("68 mm^2/s", "kinematic_viscosity", 68e-6), ("68 mm²/s", "kinematic_viscosity", 68e-6),
    ("20 cSt", "kinematic_viscosity", 20e-6), ("1 kN", "force", 1e3), ("10 N*m", "torque", 10.0),
    ("9 um", "length", 9e-6), ("9 µm", "length", 9e-6), ("0.5 K/W", "thermal_resistance", 0.5),
    ("5 l/min", "volume_flow", 5e-3 / 60), ("2 %", "dimensionless", 0.02), ("50 Hz", "speed", 100 * math.pi),
    ("3000 1/min", "speed", 100 * math.pi), ("1 s⁻¹", "speed", 2 * math.pi), ("7850 kg/m³", "density", 7850.0),
    ("1900 J/(kg*K)", "specific_heat", 1900.0), ("16 kW/m^2", "heat_flux", 16e3),  # dimensions that cancel
    ("40 cP", "dynamic_viscosity", 0.04), ("23 1/GPa", "inverse_pressure", 23e-9),  # are one unit, no factor
    ("2.3e-8 m^2/N", "inverse_pressure", 2.3e-8), ("40 mPa*s", "dynamic_viscosity", 0.04),
    ("6000 deg/s", "speed", math.radians(6000)), ("20 urad", "angle", 20e-6), ("10 krpm", "speed", 10000 * 2 * math.pi / 60),
])
def test_units_users_write_keep_working(text, kind, want):
    assert units.parse_quantity(text, kind, "x") == pytest.approx(want, rel=1e-12)


# ----------------------------------------------------------------------------- one number, ASCII digits
@pytest.mark.parametrize("text, match", [
    ("٥ kN", r"'٥' is not an ASCII digit"),             # the issue: read as 5 kN
    ("١٠ N", r"is not an ASCII digit"),
    ("१० N", r"is not an ASCII digit"),                 # Devanagari
    ("１０ N", r"is not an ASCII digit"),                # fullwidth
    ("1e٥ N", r"is not an ASCII digit"),
    ("½ N", r"is not an ASCII digit"),
    ("1_000 N", r"digits are not grouped"),
    ("1_0.5 N", r"digits are not grouped"),
    ("1 000 N", r"holds more than one number"),         # pint: 1 * 0 N
    ("5,5 N", r"is ambiguous: write '5.5 N' for one value"),
    ("1.2.3 N", r"cannot read '1.2.3 N' as a quantity"),
    ("9**9**9 K", r"cannot read"),
    ("10**308*10 N", r"cannot read"),
    ("2 m^10", r"cannot read"),                         # an exponent is one digit
    ("1e-400 N", r"'1e-400 N' underflows"),             # the issue: read as 0
    ("-1e-400 N", r"underflows"),
    ("1e-320 um", r"underflows in SI units"),           # 1e-326 m: read as 0
    ("1 m^-2 N", r"is a pressure, expected a length"),  # the sign of an exponent is no second number
    ("1e308 kN", r"not a finite quantity \(it overflows in SI units\)"),
    ("x" * 101, r"is too long for a quantity"),
    ("2 é", r"cannot read"),
])
def test_one_ascii_number_and_no_underflow(text, match):
    with pytest.raises(InputError, match=match):
        units.parse_quantity(text, "force" if "um" not in text and "m^" not in text else "length", "x")


def test_an_expression_is_refused_before_pint_sees_it(monkeypatch):
    import pint

    def never(*args, **kwargs):
        raise AssertionError("pint was asked to read an expression")

    units._ureg()
    monkeypatch.setattr(pint.UnitRegistry, "parse_expression", never)
    start = time.perf_counter()
    for text in ("9**9**9 K", "9**9**9 degC", "10**308*10 N", "2**2**2**2**2 kN"):
        with pytest.raises(InputError):
            units.parse_quantity(text, "force", "x")
        with pytest.raises(InputError):
            units.parse_temperature(text, "x")
    assert time.perf_counter() - start < 1.0


def test_a_subnormal_number_is_kept_an_underflow_to_zero_is_not():
    # a file the package writes reads back bit for bit, subnormals too (tests/runout/test_runout_files.py);
    # what is refused is a number read as 0 though it is not
    assert units.parse_quantity("1e-320 N", "force", "x") == 1e-320
    assert units.parse_quantity(5e-324, "force", "x", default_unit="N") == 5e-324
    for text in ("1e-324 N", "2e-324 N", "1e-5000 N", "0.1e-323 N"):
        with pytest.raises(InputError, match="underflows"):
            units.parse_quantity(text, "force", "x")
    assert units.parse_quantity("0e-400 N", "force", "x") == 0.0 and units.parse_quantity("-0.0 N", "force", "x") == 0.0


def test_lists_and_ranges_hold_items_of_the_same_grammar():
    np.testing.assert_array_equal(units.parse_values("1 kN, 2 kN", "force", "x"), [1e3, 2e3])
    for text, match in [("1 N, ٥ N", "ASCII digit"), ("1 N, 1_000 N", "not grouped"), ("1 N:2 N %:1 N", "plain factor"),
                        ("1, 1e-400 N", "underflows"), ("1:2:1e-400 N", "underflows"),
                        ("1 N, 2 turn kgf", "plain factor")]:
        with pytest.raises(InputError, match=match):
            units.parse_values(text, "force", "x")


@pytest.mark.parametrize("line, match", [
    ('axial_load = "2 turn kgf"', "plain factor"), ('axial_load = "٥ kN"', "ASCII digit"),
    ('axial_load = "1_000 N"', "not grouped"), ('axial_load = "1e-400 N"', "underflows"),
    ('axial_load = "9**9**9 N"', "cannot read"), ('axial_load = "1 kN"\ninner_conformity = nan', "not a finite"),
    ('axial_load = "1 kN"\ninner_conformity = inf', "not a finite"),
])
def test_files_take_the_same_grammar(tmp_path, line, match):
    from bearinglab import sweep
    from bearinglab.errors import CatalogError

    path = tmp_path / "bad.toml"
    path.write_text(f'model = "axial-angle"\nbearing = "B218"\n[parameters]\n{line}\n', encoding="utf-8")
    with pytest.raises(CatalogError, match=match):
        sweep.load_sweep(path)


# ----------------------------------------------------------------------------- temperatures
@pytest.mark.parametrize("text, kelvin", [("70 degC", 343.15), ("70 °C", 343.15), ("70°C", 343.15),
                                          ("343.15 K", 343.15), ("158 degF", 343.15), ("-40 degF", 233.15),
                                          ("60degC", 333.15), ("20 C", 293.15)])
def test_temperatures_read(text, kelvin):
    assert units.parse_temperature(text, "x") == pytest.approx(kelvin, abs=1e-12)


@pytest.mark.parametrize("text, match", [
    ("5,5 degC", r"has a comma: write one temperature with a decimal point, e.g. '5.5 degC'"),  # pint: 55 degC
    ("1 000 K", r"cannot read '1 000 K' as a temperature"),  # pint: 0 K
    ("1.2.3 degC", r"cannot read"),                          # pint: 0.36 degC
    ("9**9**9 K", r"cannot read"),                           # pint: minutes of big integers
    ("٥ degC", r"is not an ASCII digit"), ("1_000 K", r"not grouped"), ("1e-400 K", r"underflows"),
    ("1e400 K", r"not a finite"), ("nan degC", r"cannot read"), ("60 degC degC", r"cannot read"),
    ("60 kelvin*2", r"cannot read"), ("auto", r"cannot read"), ("60", r"has no unit"), ("60 deg", r"cannot read"),
])
def test_temperatures_refused(text, match):
    with pytest.raises(InputError, match=match):
        units.parse_temperature(text, "x")


MOUNTING_TEMPERATURES = ("--inner-ring-temperature", "--outer-ring-temperature", "--ball-temperature",
                         "--shaft-temperature", "--housing-temperature")


@pytest.mark.parametrize("option", MOUNTING_TEMPERATURES)
@pytest.mark.parametrize("value", ["5,5 degC", "1 000 K", "1.2.3 degC", "9**9**9 K", "٥ degC", "1_0 degC"])
def test_the_five_mounting_temperatures_take_the_grammar(capsys, option, value):
    line = one_line(*run(capsys, "clearance", "-b", "6205-2RS", "--shaft-fit", "k5", option, value)[::2])
    assert line.startswith(f"bearinglab: error: {option[2:]}: ") and repr(value) in line, line


def test_a_decimal_comma_temperature_is_no_longer_read_as_ten_times_more(capsys):
    # the issue: '5,5 degC' was read as 55 degC (operating clearance -13.8 um instead of +10.3 um)
    def probable(value):
        code, out, err = run(capsys, "clearance", "-b", "6205-2RS", "--shaft-fit", "k5",
                             "--inner-ring-temperature", value, "--json")
        assert code == 0, err
        return json.loads(out)["chain"]["probable"]["operating_clearance"]

    assert probable("5.5 degC") == pytest.approx(10.33, abs=0.01)
    assert probable("55 degC") == pytest.approx(-13.82, abs=0.01)
    assert probable("5.5") == probable("5.5 degC")  # a bare number is degC, as before
    one_line(*run(capsys, "clearance", "-b", "6205-2RS", "--shaft-fit", "k5", "--inner-ring-temperature",
                  "5,5 degC")[::2])


@pytest.mark.parametrize("option", ["--temperature", "--ambient"])
def test_the_oil_and_ambient_temperatures_take_the_grammar(capsys, option):
    args = ["life", "-b", "6205-2RS", "-R", "1 kN", "-n", "3000 rpm", "--oil", "VG68", "--temperature", "70 degC"]
    if option == "--ambient":
        args[-1] = "auto"
    for value in ("5,5 degC", "٥ degC", "9**9**9 K"):
        line = one_line(*run(capsys, *args, option, value)[::2])
        assert option[2:] in line


# ----------------------------------------------------------------------------- fields and CLI numbers
@pytest.mark.parametrize("field, value, match", [
    ("harmonics", "٥", "expected a whole number"), ("harmonics", "1_0", "expected a whole number"),
    ("harmonics", "1e1", "expected a whole number"), ("harmonics", "9" * 50, "expected a whole number"),
    ("harmonics", "nan", "expected a whole number"),
])
def test_integer_fields_are_plain_ascii_digits(field, value, match):
    with pytest.raises(RequestError, match=match):
        parse("frequencies", {"bearing": "B218", "speed": "1 rpm", field: value})


def test_integer_fields_still_read_plain_digits():
    assert parse("frequencies", {"bearing": "B218", "speed": "1 rpm", "harmonics": " 7 "}).values["harmonics"] == 7
    assert parse("frequencies", {"bearing": "B218", "speed": "1 rpm", "harmonics": 7}).values["harmonics"] == 7


@pytest.mark.parametrize("value, match", [("nan", "expected a plain number"), ("inf", "expected a plain number"),
                                          ("٥", "expected a plain number"), ("1_0", "expected a plain number"),
                                          ("1e-400", "underflows"), (float("nan"), "not a finite number"),
                                          (float("inf"), "not a finite number"), (True, "expected a number")])
def test_number_fields_are_one_finite_ascii_number(value, match):
    field = CALCULATIONS["life"].field("viscosity_index")
    with pytest.raises(RequestError, match=match):
        parse_field(field, value)


@pytest.mark.parametrize("argv, option", [
    (["frequencies", "-b", "B218", "-n", "3000 rpm", "--harmonics", "٥"], "--harmonics"),
    (["frequencies", "-b", "B218", "-n", "3000 rpm", "--harmonics", "1_000"], "--harmonics"),
    (["frequencies", "-b", "B218", "-n", "3000 rpm", "--harmonics", "1e3"], "--harmonics"),
    (["life", "-b", "6205-2RS", "-n", "3000 rpm", "--oil", "VG68", "--temperature", "70 degC",
      "--viscosity-index", "nan"], "--viscosity-index"),
    (["life", "-b", "6205-2RS", "-n", "3000 rpm", "--oil", "VG68", "--temperature", "70 degC",
      "--viscosity-index", "1e-400"], "--viscosity-index"),
    (["life", "-b", "6205-2RS", "-n", "3000 rpm", "--oil", "VG68", "--temperature", "70 degC",
      "--viscosity-index", "٩٥"], "--viscosity-index"),
    (["axial-angle", "-b", "4-1006095", "-F", "2 kgf", "--x0", "inf"], "--x0"),
    (["life", "-b", "6205-2RS", "-n", "3000 rpm", "--oil", "VG٦٨", "--temperature", "70 degC"], "oil"),
])
def test_cli_numbers_are_plain_ascii(capsys, argv, option):
    line = one_line(*run(capsys, *argv)[::2])
    assert option in line


def test_cli_integers_with_plain_digits_still_work(capsys):
    code, _out, err = run(capsys, "frequencies", "-b", "B218", "-n", "3000 rpm", "--harmonics", "5", "--json")
    assert code == 0, err


# ----------------------------------------------------------------------------- range counts
def test_a_range_count_that_overflows_is_refused_on_both_boundaries(capsys):
    text = "0 kN:1e300 kN:1e-300 kN"
    field = CALCULATIONS["high-speed"].field("axial_load")
    with pytest.raises(RequestError, match=r"axial_load: range '0 kN:1e300 kN:1e-300 kN' holds too many values to "
                                           r"count") as err:
        count_values(field, text)
    assert err.value.parameter == "axial_load"
    with pytest.raises(RequestError, match="too many values"):
        parse("high-speed", {"bearing": "B218", "axial_load": text, "speed": "1000 rpm"})
    line = one_line(*run(capsys, "high-speed", "-b", "B218", "-F", text, "-n", "1000 rpm")[::2])
    assert "too many values" in line and "axial-load" in line


@pytest.mark.parametrize("text", ["0 N:1e308 N:1e-308 N", "-1e308 N:1e308 N:1e-10 N", "0 rpm:1e300 rpm:1e-300 rpm"])
def test_range_count_variants_never_overflow(text):
    kind = "speed" if "rpm" in text else "force"
    calc = "friction"
    field = CALCULATIONS[calc].field("speed" if kind == "speed" else "radial_load")
    with pytest.raises(RequestError):
        parse_field(field, text, limit=1000)


# ----------------------------------------------------------------------------- designations
@pytest.mark.parametrize("text, part", [("6208-", "'-' at the end"), ("6208////", "'/' before '/'"),
                                        ("6208.2RS", "'.' before '2RS'"), ("6208--2RS", "'-' before '-'"),
                                        ("6208/", "'/' at the end"), ("6208-2RS-", "'-' at the end"),
                                        ("6208 2RS.", "'.' at the end"), ("6208_2RS", "'_' before '2RS'")])
def test_a_designation_with_a_part_not_understood_is_refused(capsys, text, part):
    message = rf"bearing: cannot read '{text}' as a designation: {part} is not understood"
    with pytest.raises(InputError, match=message.replace(".", r"\.").replace("/", "/")):
        designation.parse(text)
    with pytest.raises(InputError, match="is not understood"):
        catalog.get(text)
    line = one_line(*run(capsys, "catalog", "show", text)[::2])
    assert "is not understood" in line


@pytest.mark.parametrize("text", ["6208-2RS1/C3", "6208 2RS C3", "6208ZZC3", "62/22-2Z", "7205-B-TVP", "7014 CD/P4A",
                                  "6208 - 2RS", " 6208 ", "6208-2rs"])
def test_designations_users_write_still_read(text):
    assert designation.parse(text).base in ("6208", "62/22", "7205", "7014")


# ----------------------------------------------------------------------------- every result finite
def test_a_non_finite_result_is_an_error_naming_it(capsys):
    # the issue: the table crashed (a traceback), and --json exited 0 with nulls
    args = ("clearance", "-b", "6205-2RS", "--housing-outside-diameter", "1e308 mm")
    for extra in ((), ("--json",)):
        code, out, err = run(capsys, *args, *extra)
        line = one_line(code, err, expected=3)
        assert "clearance: the result " in line and "is NaN (not a number): the computation overflowed" in line
        assert out == ""


def test_the_check_skips_only_documented_nulls():
    from bearinglab.calculations import _finite

    with pytest.raises(_finite.NonFiniteResult, match=r"x: the result chain\.least\.a is infinite"):
        _finite.check({"chain": {"least": {"a": math.inf}}}, "x")
    with pytest.raises(_finite.NonFiniteResult, match=r"the result cases\[1\]\.y is NaN"):
        _finite.check({"cases": [{"y": 1.0}, {"y": np.float64("nan")}]}, "x")
    with pytest.raises(_finite.NonFiniteResult, match=r"the result v\[2\] is NaN"):
        _finite.check({"v": np.array([1.0, 2.0, np.nan])}, "x")
    assert _finite.check({"life": math.inf}, "x", nullable=("life",))
    assert _finite.check({"cases": [{"converged": False, "y": math.nan}]}, "x")
    assert _finite.check({"steady": np.bool_(False), "kappa": math.nan}, "x")
    with pytest.raises(_finite.NonFiniteResult, match=r"the result y is NaN"):
        _finite.check({}, "x", nulled=[("y", math.nan, {"converged": True})])


def test_a_documented_null_is_kept(capsys):
    # an unbounded life at P = 0 is documented as null: still exit 0
    code, out, err = run(capsys, "life", "-b", "6205-2RS", "-n", "3000 rpm", "--json")
    assert code == 0, err
    assert json.loads(out)["basic_rating_life_Mrev"] is None


def test_the_non_finite_error_is_a_convergence_failure_of_the_calculation():
    parsed = parse("clearance", {"bearing": "6205-2RS", "housing_outside_diameter": "1e308 mm"})
    with pytest.raises(calculations.RunFailure) as err:
        calculations.run(parsed)
    assert err.value.kind == "convergence" and "overflowed" in str(err.value)


def test_write_worst_beyond_the_samples_is_one_line(capsys):
    line = one_line(*run(capsys, "runout", "monte-carlo", "-b", "B218", "--samples", "2", "--steps-per-rev", "36",
                         "--revolutions", "1", "--write-worst", "9223372036854775808")[::2])
    assert "write-worst must be <=" in line


# ----------------------------------------------------------------------------- the Python API's domains
def test_the_python_functions_of_the_issue_raise_input_errors():
    from bearinglab import bearing, film, limits, quasistatic, stand

    b218 = catalog.get("B218")
    with pytest.raises(InputError, match=r"axial_load / \(n_balls E'"):  # was ZeroDivisionError
        quasistatic.high_speed_analysis(b218, 1e-30, 15000 * units.RPM)
    with pytest.raises(InputError, match=r"ball_diameter must be > 0"):  # was ZeroDivisionError
        bearing.max_balls(0, 0.0385)
    with pytest.raises(InputError, match=r"pitch_diameter must be > 0"):
        bearing.max_balls(0.007938, 0)
    with pytest.raises(InputError, match=r"pitch_diameter must be > 0"):  # was ZeroDivisionError
        limits.check_speed([1000.0], 0)
    with pytest.raises(InputError, match=r"angle must be finite"):  # was OverflowError
        units.to_dms(math.inf)
    with pytest.raises(InputError, match=r"angle must be finite"):  # was ValueError
        units.format_dms(math.nan)
    start = time.perf_counter()
    with pytest.raises(InputError, match=r"axial_load must be finite"):  # never returned
        stand.iteration_table(math.inf, 1000.0, math.radians(12))
    assert time.perf_counter() - start < 1.0
    with pytest.raises(InputError, match=r"load must be > 0 \[N\], got 0.0"):  # returned NaN
        film.hamrock_dowson(0.0, 10.0, 5e-3, 6.0, 0.04, 2.3e-8, 2.2e11)


@pytest.mark.parametrize("call, match", [
    (lambda: __import__("bearinglab.bearing").bearing.max_balls(-1.0, 0.0385), "ball_diameter must be > 0"),
    (lambda: __import__("bearinglab.bearing").bearing.max_balls(5e-324, 0.0385), "ball_diameter must be >= 1e-6"),
    (lambda: __import__("bearinglab.limits").limits.truncation_warnings(1.0, 3e-3, 0.0, 1e-3), "groove_radius"),
    (lambda: __import__("bearinglab.kinematics").kinematics.spectral_mask(
        1.0, 0.00794, 0.03904, 9, 0.0, harmonics=1e30), r"harmonics must be an integer in \[1, 1000\]"),
    (lambda: __import__("bearinglab.parallel").parallel.chunk_bounds(1e30, 4), "n_cases must be <="),
    (lambda: __import__("bearinglab.parallel").parallel.chunk_bounds(math.inf, 4), "n_cases must be an integer"),
    (lambda: __import__("bearinglab.parallel").parallel.chunk_bounds(10, math.nan), "chunk_size must be an integer"),
    (lambda: __import__("bearinglab.parallel").parallel.run_seeded(lambda n, rng: {"u": rng.random(n)}, 2**63, 7),
     "n_samples must be <="),
    (lambda: __import__("bearinglab.parallel").parallel.run_seeded(lambda n, rng: {"u": rng.random(n)}, 10, -1),
     "seed must be an integer >= 0"),
    (lambda: __import__("bearinglab.stand.method").stand.method.engine_for(math.inf), "n_cases must be"),
    (lambda: __import__("bearinglab.units").units.format_dms(0.1, digits=1e30), "digits must be an integer"),
    (lambda: __import__("bearinglab.runout.tolerances").runout.tolerances.monte_carlo_chunk(
        None, "G5", "P4", [0], 7, steps_per_revolution=1e30), r"steps_per_revolution must be an integer in"),
])
def test_variants_found_by_the_probe_raise_input_errors(call, match):
    with pytest.raises(InputError, match=match):
        call()


def test_the_papers_rounding_of_a_tiny_thrust_is_no_division_by_zero(capsys):
    # found by tests/cli/test_fuzz.py: '-F 1e-30 N --legacy' cut F to 0 kgf and divided by it
    from bearinglab import stand

    with pytest.raises(InputError, match=r"axial_load must be >= 0.001 kgf"):
        stand.iteration_table(1e-30, 1000.0, math.radians(12), reproduce_print=True)
    line = one_line(*run(capsys, "axial-angle", "-b", "4-1006095", "-F", "1e-30 N", "--legacy")[::2])
    assert "axial-load must be >= 0.001 kgf" in line
    with pytest.raises(ConvergenceError):  # without the rounding: a solve that says it failed
        stand.iteration_table(1e-30, 1000.0, math.radians(12))


def test_a_python_int_too_big_for_numpy_is_a_float_not_a_type_error():
    from bearinglab.mounting import thermal

    assert thermal.expansion(10**30, 303.15, 1e-5) == pytest.approx(1e-5 * 10 * 1e30)  # was TypeError


def test_check_integer_refuses_counts_numpy_cannot_hold():
    from bearinglab._validate import check_integer

    with pytest.raises(InputError, match=r"count must be an integer below 2\^63"):
        check_integer("count", 9223372036854775808, 1)
    with pytest.raises(InputError, match=r"count must be an integer in \[1, 10\]"):
        check_integer("count", 11, 1, 10)
    assert check_integer("count", 2**62, 1) == 2**62


def test_runout_exact_reduction_far_outside_the_rings_is_no_linalg_error():
    from bearinglab.runout import exact_reduction, geometry_from_catalog

    g = geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(15))
    with pytest.raises(ConvergenceError, match="no ball fits between the rings"):
        exact_reduction(0.0, -1.0, 0.0, 1e-6, g)
