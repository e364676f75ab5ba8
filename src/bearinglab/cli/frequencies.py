"""Command line of the characteristic frequencies: ``frequencies`` (with the spectral mask).

Commands
--------
COMMANDS   the ``frequencies`` command, by name (the application adds it)
"""

import math

from ._common import (
    BearingFile,
    CatalogFile,
    FileOption,
    JsonFlag,
    check_output,
    console,
    emit_csv,
    emit_json,
    print_warnings,
    table,
)
from ._options import command

__all__ = ["COMMANDS"]

_HZ = 2.0 * math.pi  # rad/s per Hz (rev/s)
_LABELS = {
    "shaft": "shaft",
    "ftf": "FTF",
    "bpfo": "BPFO",
    "bpfi": "BPFI",
    "bsf": "BSF",
    "two_bsf": "2·BSF",
}


def frequencies(
    given, *, bearing_file: BearingFile = None, catalog: CatalogFile = None,
    csv_file: FileOption("--csv", "Write the spectral mask to this CSV file.") = None,
    json_out: JsonFlag = False,
):
    """Characteristic frequencies (FTF, BPFO, BPFI, BSF, 2·BSF) and the spectral mask.

    With --axial-load the frequencies are at the operating contact angle under that load, and the
    nominal ones and the shift are shown too.
    """
    from ..calculations import _reading as _inputs
    from ..calculations import frequencies as calculation

    if csv_file is not None:  # before anything is computed
        check_output(csv_file, "csv", (".csv",), inputs=(bearing_file, catalog))
    mask = given["mask"]
    given = dict(given, mask=mask or csv_file is not None)  # the fields as typed (the mask for the CSV)
    out = calculation.document(_inputs.request("frequencies", given), bearing_file=bearing_file,
                               catalog=catalog)
    mask_rows = out["mask"]["lines"] if "mask" in out else []
    if csv_file is not None:  # None (no order at zero shaft speed) is written as an empty cell
        emit_csv(csv_file, {c: [r[c] for r in mask_rows] for c in mask_rows[0]})
    if not mask:
        out.pop("mask", None)
    if json_out:
        emit_json(out)
        return
    _print(out, mask_rows if mask else None)
    if csv_file is not None:
        console.print(
            f"spectral mask ({len(mask_rows)} lines) written to {csv_file}", highlight=False
        )
    print_warnings(out.get("warnings", []))


def _print(out, mask_rows):
    """The frequencies (and the shift under load) as tables; the mask too if ``mask_rows`` is given."""
    from .. import kinematics
    loaded = "axial_load_N" in out
    shaft_hz, outer_hz = out["shaft_hz"], out["outer_hz"]
    speeds = f"shaft {out['speed_rpm']:g} rpm = {shaft_hz:.6g} Hz"
    if outer_hz:
        speeds += f", outer ring {out['outer_speed_rpm']:g} rpm = {outer_hz:.6g} Hz"
    console.print(
        f"Bearing {out['bearing']}: {speeds}; nominal contact angle {out['nominal_contact_angle_deg']:.4f}°",
        highlight=False,
    )
    if loaded:
        console.print(
            f"operating contact angle at {out['axial_load_kgf']:.4g} kgf ({out['axial_load_N']:.4g} N): "
            f"{out['contact_angle_deg']:.4f}° = {out['contact_angle_dms']} ({out['hertz']} Hertz)",
            highlight=False,
        )
    columns = ["frequency", "nominal [Hz]" if loaded else "f [Hz]", "order"]
    if loaded:
        columns += ["operating [Hz]", "order", "shift [Hz]", "shift [%]"]
    rows = []
    for n in kinematics.FAMILIES[1:]:
        nom = out["nominal"]
        row = [_LABELS[n], f"{nom[n + '_hz']:.4f}", _order(nom[n + "_order"])]
        if loaded:
            row += [
                f"{out[n + '_hz']:.4f}",
                _order(out[n + "_order"]),
                f"{out['shift_hz'][n]:+.4f}",
                f"{out['shift_percent'][n]:+.3f}",
            ]
        rows.append(row)
    table("Characteristic frequencies", columns, rows)
    if mask_rows is not None:
        m = out["mask"]
        table(
            f"Spectral mask: harmonics 1..{m['harmonics']}, sidebands ±1..{m['sidebands']}, band {m['band_percent']:g} %",
            ["line", "h", "sideband", "f [Hz]", "low [Hz]", "high [Hz]", "order"],
            [
                [
                    _LABELS[r["name"]],
                    r["harmonic"],
                    _sideband(r),
                    f"{r['frequency_hz']:.3f}",
                    f"{r['low_hz']:.3f}",
                    f"{r['high_hz']:.3f}",
                    _order(r["order"]),
                ]
                for r in mask_rows
            ],
        )


def _order(x):
    return "" if x is None else f"{x:.5f}"


def _sideband(row):
    if not row["modulation"]:
        return ""
    return f"{row['sideband']:+d}×{_LABELS[row['modulation']].split(' ')[0]}"


#: The ``frequencies`` command, as the application adds it.
COMMANDS = {"frequencies": command("frequencies", frequencies)}
