"""Demo of spec 003: initial inner-ring displacement and runout of a spindle bearing from its
manufacturing errors.

Runs worked example 3 of spec 003 (ball-size scatter plus inner- and outer-raceway waviness) at one
angle and over three revolutions, its runout spectrum over a longer record, and a small Monte Carlo
study (G5 balls, P4 rings). Usage::

    python examples/demo_runout.py out

writes tables (CSV) and figures (PNG) under ``out/runout/`` and prints a short summary.
"""

from __future__ import annotations

import csv
import io
import math
import sys
from pathlib import Path

import numpy as np

from bearinglab import runout
from bearinglab.plots import runout as plots

HERE = Path(__file__).resolve().parent
UM = 1e-6


def write_csv(path, header, rows, comments=()):
    """Write a CSV file with ``# comment`` lines first (the demo's outputs are small: one write each)."""
    buf = io.StringIO()
    buf.writelines(f"# {line}\n" for line in comments)
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(header)
    writer.writerows(rows)
    Path(path).write_text(buf.getvalue(), encoding="utf-8")
    return Path(path)


def main(argv):
    out = Path(argv[1] if len(argv) > 1 else "out") / "runout"
    out.mkdir(parents=True, exist_ok=True)
    written = []
    geometry, errors = runout.load_error_file(HERE / "runout" / "example3_mixed.toml")

    # ---- one position: the paper's figure 5 at psi = 0 and 90 deg, first approximation and refined
    rows = []
    for psi_deg in (0.0, 90.0):
        d = runout.initial_displacement(math.radians(psi_deg), geometry, errors)
        r = runout.initial_displacement(math.radians(psi_deg), geometry, errors, refine=True)
        written += plots.save_single(d, out)
        c = d.contact
        for i in range(geometry.n_balls):
            s_i = (
                c.constant
                + c.sine * math.sin(d.ball_angle[i])
                + c.cosine * math.cos(d.ball_angle[i])
            )
            rows.append(
                [
                    psi_deg,
                    i + 1,
                    f"{math.degrees(d.ball_angle[i]) % 360:.6f}",
                    f"{d.generalized_error[i] / UM:.6f}",
                    f"{s_i / UM:.6f}",
                    f"{c.slack[i] / UM:.6f}",
                    int(c.contact[i]),
                    f"{c.load_share[i]:.6f}",
                ]
            )
        print(
            f"psi = {psi_deg:4.0f} deg: a0 = {c.constant / UM:+.6f}  B = {c.sine / UM:+.6f}  "
            f"D = {c.cosine / UM:+.6f} um; contacts {[int(i) + 1 for i in np.flatnonzero(c.contact)]}"
            f"{' (degenerate, free play %.6f um)' % (d.free_play / UM) if c.degenerate else ''}"
        )
        print(
            f"              pose (dx, dy, dz) = ({d.x / UM:+.6f}, {d.y / UM:+.6f}, {d.z / UM:+.6f}) um; "
            f"refined ({r.x / UM:+.6f}, {r.y / UM:+.6f}, {r.z / UM:+.6f}) um in {int(r.passes)} passes"
        )
    written.append(
        write_csv(
            out / "example3_balls.csv",
            ["psi_deg", "ball", "theta_deg", "dk_um", "s_um", "slack_um", "contact", "load_share"],
            rows,
            [
                "spec 003 example 3: generalized errors and the enveloping sinusoid (first approximation)",
                "units: deg, um",
            ],
        )
    )

    # ---- rotation sequence: 3 revolutions x 360 steps (the spec's trajectory), all positions in one batch
    t = runout.rotation_sequence(geometry, errors, revolutions=3, steps_per_revolution=360)
    d = t.displacement
    written.append(
        write_csv(
            out / "example3_trajectory.csv",
            ["psi_deg", "dx_um", "dy_um", "dz_um", "contact_balls", "degenerate"],
            [
                [
                    f"{math.degrees(p):.1f}",
                    f"{x / UM:.6f}",
                    f"{y / UM:.6f}",
                    f"{z / UM:.6f}",
                    " ".join(str(i + 1) for i in np.flatnonzero(c)),
                    int(g),
                ]
                for p, x, y, z, c, g in zip(
                    t.rotation_angle, d.x, d.y, d.z, d.contact.contact, d.contact.degenerate
                )
            ],
            [
                "spec 003 example 3: inner-ring centre trajectory, 3 revolutions x 360 steps",
                "units: deg, um",
            ],
        )
    )
    written.append(
        write_csv(
            out / "example3_runout.csv",
            ["part", *[f"{m}_um" for m in runout.METRICS]],
            [
                [part, *[f"{getattr(m, name) / UM:.6f}" for name in runout.METRICS]]
                for part, m in (
                    ("whole", t.metrics),
                    ("synchronous", t.synchronous),
                    ("asynchronous", t.asynchronous),
                )
            ],
            ["spec 003 example 3: runout metrics (section 10)", "units: um"],
        )
    )
    m = t.metrics
    print(
        f"trajectory (3 rev x 360): radial ptp x {m.radial_ptp_x / UM:.6f}, y {m.radial_ptp_y / UM:.6f}, "
        f"max {m.radial_ptp_max / UM:.6f}; axial ptp {m.axial_ptp / UM:.6f}; mean dz {m.dz_mean / UM:.6f} um; "
        f"{100 * t.degenerate_fraction:.1f} % degenerate positions"
    )

    # ---- spectrum over a longer record (30 revolutions: resolution 1/30 of an order)
    long = runout.rotation_sequence(geometry, errors, revolutions=30, steps_per_revolution=180)
    ld = long.displacement
    spec = runout.runout_spectrum(ld.x, ld.y, ld.z, 180)
    lines = runout.spectrum_lines(spec, long.cage_ratio, threshold=0.05)
    written += plots.save_sequence(t, spec, lines, out)
    written.append(
        write_csv(
            out / "example3_spectrum_lines.csv",
            ["component", "order", "amplitude_um", "line", "source"],
            [
                [ln.component, f"{ln.order:.4f}", f"{ln.amplitude / UM:.6f}", ln.label, ln.source]
                for ln in lines
            ],
            [
                "spec 003 example 3: main spectral lines, 30 revolutions x 180 steps",
                "order in cycles per inner-ring revolution; κ = cage order, × = shaft order",
            ],
        )
    )
    top = sorted(lines, key=lambda ln: -ln.amplitude)[:4]
    print(
        "main spectral lines: "
        + ", ".join(f"{ln.component} {ln.label} ({ln.amplitude / UM:.3f} um)" for ln in top)
    )

    # ---- Monte Carlo: G5 balls, P4 rings, 200 bearings (spec: 180 steps x 2 revolutions)
    mc_geometry, _ = runout.load_error_file(HERE / "runout" / "monte_carlo_reference.toml")
    res = runout.monte_carlo(
        mc_geometry, "G5", "P4", 200, 2026, steps_per_revolution=180, revolutions=2
    )
    written += plots.save_monte_carlo(res, out)
    s = res.samples
    written.append(
        write_csv(
            out / "monte_carlo_G5_P4_samples.csv",
            ["sample", "first_ball_angle_deg", *[f"{n}_um" for n in runout.METRICS]],
            [
                [
                    int(i),
                    f"{math.degrees(a):.4f}",
                    *[f"{getattr(s, n)[k] / UM:.6f}" for n in runout.METRICS],
                ]
                for k, (i, a) in enumerate(zip(s.sample_index, s.first_ball_angle))
            ],
            [
                "spec 003 section 11 Monte Carlo: G5 / P4, seed 2026, 200 samples, 2 rev x 180 steps",
                "units: deg, um",
            ],
        )
    )
    written.append(
        write_csv(
            out / "monte_carlo_G5_P4_summary.csv",
            ["metric", "mean", "std", "median", "p95", "max"],
            [[n, *[f"{v / UM:.3f}" for v in res.summary[n]]] for n in runout.METRICS],
            ["spec 003 section 11 Monte Carlo summary: G5 / P4, 200 samples", "units: um"],
        )
    )
    print("Monte Carlo G5/P4, 200 samples (um):  mean / std / p95")
    for n in ("radial_ptp_x", "radial_ptp_max", "axial_ptp"):
        v = res.summary[n]
        print(f"  {n:15s} {v.mean / UM:6.3f} / {v.std / UM:5.3f} / {v.p95 / UM:6.3f}")
    print(f"wrote {len(written)} files under {out}/")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
