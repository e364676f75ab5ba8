"""Command line of the characteristic frequencies: ``frequencies`` (with the spectral mask).

Commands
--------
COMMANDS   the ``frequencies`` command, by name (the application adds it)
"""

import math
import re
from pathlib import Path
from typing import Annotated

import typer

from ..errors import InputError
from ._common import (
    BallDiameter,
    BallMaterial,
    Balls,
    BearingFile,
    BearingName,
    CatalogFile,
    Clearance,
    ContactAngle,
    InnerConformity,
    InnerRadius,
    JsonFlag,
    OuterConformity,
    OuterRadius,
    PitchDiameter,
    check_output,
    choice,
    console,
    emit_csv,
    emit_json,
    inputs_echo,
    parse_speed,
    resolve_bearing,
    speed_size,
    table,
)

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
_PERCENT = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(%|percent)?\s*$")


def _band(text):
    """'2 %', '2%' or '2' (percent) -> the relative full width 0.02."""
    m = _PERCENT.match(str(text))
    if not m:
        raise InputError(f"band: cannot read {text!r} as a percentage (e.g. '2 %', '0.5%', '2')")
    value = float(m.group(1))
    if not 0.0 < value < 200.0:
        raise InputError(f"band must be in (0, 200) [%], got {value:g} %")
    return value / 100.0


def frequencies(
    speed: Annotated[
        str, typer.Option("--speed", "-n", help="Inner-ring (shaft) speed: '3000 rpm', '50 Hz'.")
    ],
    outer_speed: Annotated[
        str, typer.Option("--outer-speed", help="Outer-ring speed, same sense as --speed.")
    ] = "0 rpm",
    axial_load: Annotated[
        str | None,
        typer.Option(
            "--axial-load",
            "-F",
            help="Axial stand load, e.g. '2 kgf': frequencies at the operating contact angle (the test-stand method).",
        ),
    ] = None,
    hertz: Annotated[
        str,
        typer.Option(
            "--hertz", help="Hertz coefficients for the operating angle: exact (default) | table."
        ),
    ] = "exact",
    elastic_constant: Annotated[
        str,
        typer.Option("--elastic-constant", help="materials (default: from E, ν) | paper (0.592e-4 (cm²/kgf)^(2/3))."),
    ] = "materials",
    bearing: BearingName = None,
    bearing_file: BearingFile = None,
    catalog: CatalogFile = None,
    balls: Balls = None,
    ball_diameter: BallDiameter = None,
    pitch_diameter: PitchDiameter = None,
    inner_groove_radius: InnerRadius = None,
    outer_groove_radius: OuterRadius = None,
    inner_conformity: InnerConformity = None,
    outer_conformity: OuterConformity = None,
    contact_angle: ContactAngle = None,
    radial_clearance: Clearance = None,
    ball_material: BallMaterial = None,
    harmonics: Annotated[
        int, typer.Option("--harmonics", help="Harmonics 1..N in the spectral mask.")
    ] = 3,
    sidebands: Annotated[
        int, typer.Option("--sidebands", help="Sideband orders ±1..S around BPFI and BSF.")
    ] = 1,
    band: Annotated[
        str,
        typer.Option("--band", help="Full width of each mask line, in % of its frequency: '2 %'."),
    ] = "2 %",
    mask: Annotated[
        bool, typer.Option("--mask", help="Print (or add to the JSON) the spectral-mask table.")
    ] = False,
    csv_file: Annotated[
        Path | None, typer.Option("--csv", help="Write the spectral mask to this CSV file.")
    ] = None,
    json_out: JsonFlag = False,
):
    """Characteristic frequencies (FTF, BPFO, BPFI, BSF, 2·BSF) and the spectral mask.

    With --axial-load the frequencies are at the operating contact angle under that load, and the
    nominal ones and the shift are shown too.
    """
    b = resolve_bearing(
        bearing,
        bearing_file,
        catalog,
        balls,
        ball_diameter,
        pitch_diameter,
        inner_groove_radius,
        outer_groove_radius,
        inner_conformity,
        outer_conformity,
        contact_angle,
        radial_clearance,
        ball_material,
    )
    w_in, w_out, fa, band_fraction = _read(b, speed, outer_speed, axial_load, hertz, harmonics, sidebands, band)
    if csv_file is not None:  # before anything is computed
        check_output(csv_file, "csv", (".csv",), inputs=(bearing_file, catalog))
    choice("elastic-constant", elastic_constant, ("materials", "paper"))
    out, angle = _frequencies(b, w_in, w_out, fa, hertz, elastic_constant)
    mask_rows = []
    if mask or csv_file is not None:
        mask_rows = _mask(b, w_in, w_out, angle, harmonics, sidebands, band_fraction)
        if csv_file is not None:  # None (no order at zero shaft speed) is written as an empty cell
            emit_csv(csv_file, {c: [r[c] for r in mask_rows] for c in mask_rows[0]})
    if mask:
        out["mask"] = {
            "harmonics": harmonics,
            "sidebands": sidebands,
            "band_percent": band_fraction * 100.0,
            "lines": mask_rows,
        }
    if json_out:
        emit_json(out)
        return
    _print(b, out, mask_rows if mask else None)
    if csv_file is not None:
        console.print(
            f"spectral mask ({len(mask_rows)} lines) written to {csv_file}", highlight=False
        )


def _read(b, speed, outer_speed, axial_load, hertz, harmonics, sidebands, band):
    """The options in SI, checked: ring speeds, axial load (or None), band as a fraction."""
    from .. import limits
    from .._bounds import MAX_HARMONICS, MAX_SIDEBANDS, check_count
    from ..units import parse_quantity
    choice("hertz", hertz, ("exact", "table"))
    # one convention in every command: --speed is the inner ring's, >= 0, within the d_m n guard
    w_in = parse_speed(speed, bearing=b, what="the inner-ring speed, a magnitude; give --outer-speed a negative "
                                               "value for rings turning against each other")
    w_out = parse_quantity(outer_speed, "speed", "outer-speed")  # signed: the sense relative to --speed
    if speed_size(b) is not None:
        limits.check_speed(w_out, speed_size(b), "outer-speed")
    if w_in == w_out:
        raise InputError(
            f"speed: the rings must turn relative to each other, got speed = outer-speed = "
            f"{w_in / _HZ * 60:g} rpm"
        )
    band_fraction = _band(band)
    check_count("harmonics", harmonics, MAX_HARMONICS)
    check_count("sidebands", sidebands, MAX_SIDEBANDS, minimum=0)
    fa = None
    if axial_load is not None:
        fa = parse_quantity(axial_load, "force", "axial-load")
    return w_in, w_out, fa, band_fraction


def _frequencies(b, w_in, w_out, fa, hertz, elastic_constant):
    """Frequencies at the nominal angle, or at the operating angle under ``fa`` with the shift; and
    the angle [rad] they are at."""
    from .. import kinematics, stand, tables
    from ..units import KGF, format_dms
    z, d, dm, a0 = b.require("n_balls", "ball_diameter", "pitch_diameter", "contact_angle")
    out = inputs_echo(b, speed_rpm=w_in / _HZ * 60.0, outer_speed_rpm=w_out / _HZ * 60.0,
                      elastic_constant=elastic_constant)
    shaft_hz = w_in / _HZ
    if fa is not None:
        if not fa > 0:
            raise InputError(f"axial-load must be > 0 [N], got {fa:g} N ({fa / KGF:g} kgf)")
        angle = float(stand.stand_analysis(b, fa, hertz=hertz, elastic_constant=elastic_constant).contact_angle)
        out.update(axial_load_N=fa, axial_load_kgf=fa / KGF, hertz=hertz)
    else:
        angle = a0
    shift = kinematics.frequency_shift(w_in, d, dm, z, a0, angle, outer_speed=w_out)
    out.update(
        contact_angle_deg=math.degrees(angle),
        contact_angle_dms=format_dms(angle),
        nominal_contact_angle_deg=math.degrees(a0),
        shaft_hz=shaft_hz,
        outer_hz=w_out / _HZ,
    )
    out.update(tables.frequencies(shift.operating, w_in))
    out["nominal"] = dict(
        contact_angle_deg=math.degrees(a0), shaft_hz=shaft_hz, **tables.frequencies(shift.nominal, w_in)
    )
    out["shift_hz"] = {n: float(getattr(shift.shift, n)) / _HZ for n in kinematics.FAMILIES[1:]}
    out["shift_percent"] = {
        n: float(getattr(shift.shift_percent, n)) for n in kinematics.FAMILIES[1:]
    }
    return out, angle


def _mask(b, w_in, w_out, angle, harmonics, sidebands, band_fraction):
    """The lines of the spectral mask at the angle of the frequencies (Hz and orders)."""
    from .. import kinematics, tables
    z, d, dm = b.require("n_balls", "ball_diameter", "pitch_diameter")
    m = kinematics.spectral_mask(
        w_in,
        d,
        dm,
        z,
        angle,
        outer_speed=w_out,
        harmonics=harmonics,
        sidebands=sidebands,
        band=band_fraction,
    )
    return tables.rows(tables.spectral_mask(m, w_in))


def _print(b, out, mask_rows):
    """The frequencies (and the shift under load) as tables; the mask too if ``mask_rows`` is given."""
    from .. import kinematics
    loaded = "axial_load_N" in out
    shaft_hz, outer_hz = out["shaft_hz"], out["outer_hz"]
    speeds = f"shaft {out['speed_rpm']:g} rpm = {shaft_hz:.6g} Hz"
    if outer_hz:
        speeds += f", outer ring {out['outer_speed_rpm']:g} rpm = {outer_hz:.6g} Hz"
    console.print(
        f"Bearing {b.designation}: {speeds}; nominal contact angle {out['nominal_contact_angle_deg']:.4f}°",
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
COMMANDS = {"frequencies": frequencies}
