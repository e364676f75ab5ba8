"""Issue 24 item 8: bad lubricant inputs of `film`, `temperature` and `friction torque` (negative or absurd
viscosities, densities, roughness, pressure-viscosity coefficients and temperatures, an ISO VG grade that
does not exist, an oil level above the bearing's centre) each end with exit 2 and one line on stderr that
names the option."""

import pytest

from bearinglab.cli import main

FILM = ["film", "-b", "6208", "-R", "2 kN", "-n", "3000 rpm"]
TEMPERATURE = ["temperature", "-b", "6208", "-R", "2 kN", "--speed", "3000 rpm"]
TORQUE = ["friction", "torque", "--model", "skf", "-b", "6208", "-R", "1 kN", "-n", "3000 rpm"]
ROUGH = ["--roughness", "0.1 um"]

CASES = [
    # film: viscosity, dynamic viscosity, density, roughness, pressure-viscosity coefficient, oil grade
    (FILM + ROUGH + ["--viscosity", "-20 cSt"], "viscosity must be > 0"),
    (FILM + ROUGH + ["--viscosity", "1e9 cSt"], "viscosity must be in [0.1, 1e+07] [cSt]"),
    (FILM + ROUGH + ["--viscosity", "1e-9 cSt"], "viscosity must be in [0.1, 1e+07] [cSt]"),
    (FILM + ROUGH + ["--viscosity", "nan cSt"], "viscosity"),
    (FILM + ROUGH + ["--dynamic-viscosity", "-0.01 Pa*s"], "dynamic-viscosity must be in"),
    (FILM + ROUGH + ["--dynamic-viscosity", "1e7 Pa*s"], "dynamic-viscosity must be in"),
    (FILM + ROUGH + ["--viscosity", "20 cSt", "--density", "-870 kg/m^3"], "density must be in [500, 2500]"),
    (FILM + ROUGH + ["--viscosity", "20 cSt", "--density", "1e6 kg/m^3"], "density must be in [500, 2500]"),
    (FILM + ["--viscosity", "20 cSt", "--roughness", "-0.1 um"], "roughness must be >= 0"),
    (FILM + ["--viscosity", "20 cSt", "--roughness", "1 m"], "roughness must be in [0, 10] [um]"),
    (FILM + ["--viscosity", "20 cSt", "--roughness", "0 um"], "roughness must not be 0"),
    (FILM + ["--viscosity", "20 cSt", "--roughness-ball", "-0.1 um", "--roughness-race", "0.1 um"],
     "roughness-ball must be >= 0"),
    (FILM + ["--viscosity", "20 cSt", "--roughness-ball", "0.1 um", "--roughness-race", "-1 um"],
     "roughness-race must be >= 0"),
    (FILM + ROUGH + ["--viscosity", "20 cSt", "--pressure-viscosity-coefficient", "-2e-8 m^2/N"],
     "pressure-viscosity-coefficient must be in [1, 100] [1/GPa]"),
    (FILM + ROUGH + ["--viscosity", "20 cSt", "--pressure-viscosity-coefficient", "1 m^2/N"],
     "pressure-viscosity-coefficient must be in [1, 100] [1/GPa]"),
    (FILM + ROUGH + ["--oil", "VG33", "--temperature", "40 degC"], "oil must be an ISO VG grade"),
    (FILM + ROUGH + ["--oil", "VG0", "--temperature", "40 degC"], "oil must be an ISO VG grade"),
    (FILM + ROUGH + ["--oil", "VG32", "--temperature", "5000 degC"], "temperature must be <= 400 [degC]"),
    (FILM + ROUGH + ["--oil", "VG32", "--temperature", "-300 degC"], "temperature must be above absolute zero"),
    (FILM + ROUGH + ["--oil", "VG32", "--temperature", "40 degC", "--viscosity-index", "-500"],
     "viscosity-index must be in [-100, 400]"),
    # temperature: oil grade, viscosity index and at 100 degC, oil-flow density, temperatures, oil bath
    (TEMPERATURE + ["--oil", "VG33"], "oil must be an ISO VG grade"),
    (TEMPERATURE + ["--oil", "XX"], "oil must be an ISO VG grade"),
    (TEMPERATURE + ["--oil", "VG32", "--viscosity-index", "1e6"], "viscosity-index must be in [-100, 400]"),
    (TEMPERATURE + ["--oil", "VG32", "--viscosity-100", "-5 cSt"], "viscosity-100 must be > 0"),
    (TEMPERATURE + ["--oil", "VG32", "--viscosity-100", "50 cSt"], "viscosity-100 must be below"),
    (TEMPERATURE + ["--oil", "VG32", "--oil-flow", "1 l/min", "--density", "-870 kg/m^3"],
     "density must be in [500, 2500]"),
    (TEMPERATURE + ["--oil", "VG32", "--oil-flow", "1 l/min", "--density", "1e6 kg/m^3"],
     "density must be in [500, 2500]"),
    (TEMPERATURE + ["--oil", "VG32", "--density", "-870 kg/m^3"], "--density describe an oil flow"),
    (TEMPERATURE + ["--oil", "VG32", "--oil-flow", "1 l/min", "--oil-heat-capacity", "-1 J/(kg*K)"],
     "oil-heat-capacity must be in"),
    (TEMPERATURE + ["--oil", "VG32", "--oil-flow", "-1 l/min"], "oil-flow must be in"),
    (TEMPERATURE + ["--oil", "VG32", "--max-temperature", "5000 degC"], "max-temperature must be <= 400"),
    (TEMPERATURE + ["--oil", "VG32", "--oil-flow", "1 l/min", "--oil-inlet-temperature", "3000 degC"],
     "oil-inlet-temperature must be <= 400"),
    (TEMPERATURE + ["--oil", "VG32", "--thermal-resistance", "-1 K/W"], "thermal-resistance must be in"),
    (TEMPERATURE + ["--oil", "VG32", "--lubrication", "oil-bath"], "oil-level: --lubrication oil-bath needs the oil level"),
    # friction torque: viscosity, oil grade and temperature, the oil bath's level
    (TORQUE + ["--viscosity", "-2 cSt"], "viscosity must be > 0"),
    (TORQUE + ["--viscosity", "1e9 cSt"], "viscosity must be in [0.1, 1e+07] [cSt]"),
    (TORQUE + ["--viscosity", "1e-9 cSt"], "viscosity must be in [0.1, 1e+07] [cSt]"),
    (TORQUE + ["--oil", "VG33", "--temperature", "40 degC"], "oil must be an ISO VG grade"),
    (TORQUE + ["--oil", "VG32", "--temperature", "5000 degC"], "temperature must be <= 400 [degC]"),
    (TORQUE + ["--viscosity", "30 cSt", "--lubrication", "oil-bath", "--oil-level", "100 mm",
               "--drag-loss-factor", "0.0003"], "oil-level must be <= d_m/2 = 30 mm"),
    (TORQUE + ["--viscosity", "30 cSt", "--lubrication", "oil-bath", "--oil-level", "-5 mm",
               "--drag-loss-factor", "0.0003"], "oil-level must be >= 0"),
    (TORQUE + ["--viscosity", "30 cSt", "--lubrication", "oil-bath", "--oil-level", "5 mm",
               "--drag-loss-factor", "-1"], "drag-loss-factor must be in [0, 1]"),
    (["friction", "torque", "--model", "palmgren", "-b", "6208", "-R", "1 kN", "-n", "3000 rpm", "--viscosity",
      "1e9 cSt", "--palmgren-f0", "2"], "viscosity must be in [0.1, 1e+07] [cSt]"),
]


@pytest.mark.parametrize("args, words", CASES, ids=[f"{a[0]}-{i}" for i, (a, _) in enumerate(CASES)])
def test_bad_lubricant_input_is_exit_2_with_one_line(capsys, args, words):
    code = main(args)
    out, err = capsys.readouterr()
    assert code == 2, (out, err)
    assert "Traceback" not in err and err.count("\n") == 1 and err.startswith("bearinglab: error: "), err
    assert words in err, err


@pytest.mark.parametrize("args", [
    FILM + ROUGH + ["--viscosity", "0.5 cSt", "--pressure-viscosity-coefficient", "2e-8 m^2/N"],
    FILM + ROUGH + ["--oil", "VG32", "--temperature", "120 degC"],
    TORQUE + ["--viscosity", "1e5 cSt"],
    TORQUE + ["--oil", "VG32", "--temperature", "400 degC"],
    TEMPERATURE + ["--oil", "VG32", "--max-temperature", "400 degC"],
])
def test_the_bounds_keep_real_oils(capsys, args):
    assert main(args) == 0, capsys.readouterr().err
