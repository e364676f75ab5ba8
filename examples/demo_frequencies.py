"""Characteristic frequencies and spectral masks.

1. The Case Western Reserve University drive-end bearing (6205-2RS): orders against the published
   multipliers.
2. Bearing 4-1006095 on the test stand at 3000 rpm under 2 kgf (spec 000): frequencies at the nominal and
   at the operating contact angle, and the spectral mask at the operating angle.

Writes under OUT/frequencies/: cwru_orders.csv, stand_frequencies.csv, stand_mask.csv and
frequencies.png. Usage: python examples/demo_frequencies.py OUT
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np

from bearinglab import catalog, kinematics, plots, static, tables
from bearinglab.plots import frequencies as frequency_plots
from bearinglab.units import KGF, RPM, format_dms

HZ = 2 * math.pi  # rad/s per Hz
# Case Western Reserve University Bearing Data Center, drive-end bearing: multiples of the shaft speed
CWRU_PUBLISHED = {"bpfi": 5.4152, "bpfo": 3.5848, "ftf": 0.39828, "two_bsf": 4.7135}


def write_csv(path, header, rows):
    """Write a CSV whole or not at all (rows -> columns for :func:`bearinglab.tables.write_table`)."""
    tables.write_table(dict(zip(header, zip(*rows))), path)


def main(out):
    out = Path(out) / "frequencies"
    out.mkdir(parents=True, exist_ok=True)

    cwru = catalog.get("6205-2RS")
    orders = kinematics.characteristic_orders(
        cwru.ball_diameter, cwru.pitch_diameter, cwru.n_balls, cwru.contact_angle
    )
    write_csv(
        out / "cwru_orders.csv",
        ["name", "order", "published", "difference"],
        [[n, getattr(orders, n), p, getattr(orders, n) - p] for n, p in CWRU_PUBLISHED.items()],
    )

    b = catalog.get("4-1006095")
    speed, load = 3000 * RPM, 2 * KGF
    alpha = float(static.stand_analysis(b, load).contact_angle)
    shift = kinematics.frequency_shift(
        speed, b.ball_diameter, b.pitch_diameter, b.n_balls, b.contact_angle, alpha
    )
    names = kinematics.FAMILIES[1:]
    write_csv(
        out / "stand_frequencies.csv",
        ["name", "nominal_hz", "operating_hz", "shift_hz", "shift_percent"],
        [
            [
                n,
                getattr(shift.nominal, n) / HZ,
                getattr(shift.operating, n) / HZ,
                getattr(shift.shift, n) / HZ,
                getattr(shift.shift_percent, n),
            ]
            for n in names
        ],
    )
    masks = {
        label: kinematics.spectral_mask(
            speed,
            b.ball_diameter,
            b.pitch_diameter,
            b.n_balls,
            a,
            harmonics=3,
            sidebands=1,
            band=0.02,
        )
        for label, a in (("nominal", b.contact_angle), ("operating", alpha))
    }
    m = masks["operating"]
    write_csv(
        out / "stand_mask.csv",
        ["name", "harmonic", "modulation", "sideband", "frequency_hz", "low_hz", "high_hz"],
        [
            [n, h, mod, k, f / HZ, lo / HZ, hi / HZ]
            for n, h, mod, k, f, lo, hi in zip(
                m.name, m.harmonic, m.modulation, m.sideband, m.frequency, m.low, m.high
            )
        ],
    )
    # lines of the operating mask that fall outside their band of the nominal-angle mask
    nominal = masks["nominal"]
    outside = int(np.sum((m.frequency < nominal.low) | (m.frequency > nominal.high)))

    fig = plots.figure(figsize=(12, 7))
    top, bottom = fig.subplots(2, 1)
    frequency_plots.spectral_mask(
        m,
        xlim=(0, 700),
        title=f"Spectral mask of 4-1006095 at 3000 rpm, 2 kgf (operating angle {format_dms(alpha)}): "
        "carriers dark, sidebands light, 2 % bands",
        ax=top,
    )
    frequency_plots.orders(
        b.ball_diameter,
        b.pitch_diameter,
        b.n_balls,
        np.radians(np.linspace(0.0, 45.0, 181)),
        marks=[(b.contact_angle, "nominal 12°"), (alpha, "operating at 2 kgf")],
        title="Orders of 4-1006095 against the contact angle",
        ax=bottom,
    )
    plots.save(fig, out / "frequencies.png")

    print(
        "CWRU 6205-2RS orders: "
        + ", ".join(
            f"{n} {getattr(orders, n):.5f} (published {p})" for n, p in CWRU_PUBLISHED.items()
        )
    )
    print(
        f"4-1006095 at 3000 rpm, 2 kgf: contact angle {format_dms(b.contact_angle)} -> {format_dms(alpha)}; "
        f"BPFI {shift.nominal.bpfi / HZ:.3f} -> {shift.operating.bpfi / HZ:.3f} Hz "
        f"({shift.shift_percent.bpfi:+.3f} %), BPFO {shift.shift_percent.bpfo:+.3f} %"
    )
    print(
        f"spectral mask: {len(m.name)} lines; {outside} of them leave the 2 % band of the nominal-angle mask"
    )
    print(f"wrote {', '.join(sorted(p.name for p in out.iterdir()))} in {out}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "out")
