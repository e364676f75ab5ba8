"""Command line of the bearing temperature (issue 24): ``temperature``.

The steady temperature of a bearing where the SKF friction power at the viscosity of that temperature
equals the heat carried away (:func:`bearinglab.thermal.thermal_balance`): to the ambient through a
thermal resistance (or ISO 15312's reference heat flow), and by an oil flow. The oil is an ISO VG grade
with its viscosity index or its viscosity at 100 degC (the shared oil options of ``life``). Where no
steady state exists below the safe limit, a thermal-runaway warning and no number.

Commands
--------
COMMANDS   the ``temperature`` command, by name (the application adds it)
"""

from ._common import (
    BearingFile,
    CatalogFile,
    JsonFlag,
    console,
    emit_json,
    print_warnings,
    table,
)
from ._options import command

__all__ = ["COMMANDS"]


def temperature(given, *, bearing_file: BearingFile = None, catalog: CatalogFile = None,
                json_out: JsonFlag = False):
    """Steady bearing temperature: SKF friction power at nu(T) = heat carried away; nu, kappa, runaway."""
    from ..calculations import parse
    from ..calculations import temperature as calculation

    # typer has read the options; the calculation checks each value by the command line's own rules
    # (its messages), not by the fields' ranges the web checks first
    result = calculation.document(parse("temperature", given, check=False),
                                  bearing_file=bearing_file, catalog=catalog)
    if json_out:
        emit_json(result)
        return
    docs = result if isinstance(result, list) else [result]
    table(f"Steady temperature of {docs[0]['inputs']['bearing']}, {docs[0]['inputs']['lubricant']}",
          ["n [rpm]", "T [°C]", "ν [mm²/s]", "κ", "M [N·mm]", "P [W]", "iter."],
          [[f"{d['inputs']['speed_rpm']:g}", _f(d["bearing_temperature_degC"], ".2f"),
            _f(d["viscosity_mm2_s"], ".3g"), _f(d["kappa"], ".3g"), _f(d["friction_moment_Nmm"], ".4g"),
            _f(d["friction_power_W"], ".4g"), str(d["iterations"])] for d in docs],
          caption="P: friction power = heat carried away; — where no steady state exists (runaway)")
    if "reference_heat_flow_W" in docs[0]:  # --reference-speed: one value per bearing
        n_r = docs[0]["thermal_reference_speed_rpm"]
        console.print(f"Thermal reference speed (ISO 15312, SKF model): "
                      f"{'none found' if n_r is None else format(n_r, '.0f') + ' rpm'} at "
                      f"{docs[0]['reference_heat_flow_W']:.4g} W", highlight=False)
    print_warnings(docs[0]["warnings"])


def _f(x, spec):
    return "—" if x is None else format(x, spec)


#: The ``temperature`` command, as the application adds it.
COMMANDS = {"temperature": command("temperature", temperature)}
