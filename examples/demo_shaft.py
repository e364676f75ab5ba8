"""Worked examples of shaft systems (issue 33): a gearbox shaft on two bearings and a spindle.

Usage: python examples/demo_shaft.py OUT

1. ``examples/shaft/gearbox.toml``: an intermediate shaft of a two-stage gearbox (a helical wheel, a spur
   pinion, two 6207, A locating) with a duty cycle of load cases: the support loads, each bearing's lives,
   the system life by ISO 281's rule and Palmgren-Miner over the cases, the rows along the shaft and the
   figure of the shaft with its deflection and bending moment.
2. ``examples/shaft/spindle.toml``: a DB pair of 7014 C at the nose and a floating 6012: the stiffness at
   the nose and the lowest natural frequencies with the gyroscopic terms at its speed.

Writes OUT/shaft/{gearbox,spindle}.json, gearbox_along_shaft.csv and gearbox.png, spindle.png; prints the
numbers the user guide quotes. Every document is the one ``bearinglab shaft FILE --json`` prints.
"""

from __future__ import annotations

import csv
import json
import sys
import warnings
from pathlib import Path

from bearinglab import calculations, plots
from bearinglab.errors import ValidityWarning
from bearinglab.plots import shaft as shaft_plots

HERE = Path(__file__).resolve().parent / "shaft"


def document(name, **options):
    """The ``shaft`` calculation of one example file (the command line's and the web's document)."""
    text = (HERE / f"{name}.toml").read_text(encoding="utf-8")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)  # estimated ball sets: the document's warnings say so
        return calculations.run(calculations.parse("shaft", {"model": text, **options}))


def write(out, name, doc):
    (out / f"{name}.json").write_text(json.dumps(doc, indent=2) + "\n", encoding="utf-8")
    plots.save(shaft_plots.overview(doc, title=f"examples/shaft/{name}.toml"), out / f"{name}.png")


def gearbox(out):
    doc = document("gearbox")
    write(out, "gearbox", doc)
    rows = doc["deflection"]
    with open(out / "gearbox_along_shaft.csv", "w", newline="", encoding="utf-8") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    for s in doc["supports"]:
        print(f"gearbox {s['name']}: F = ({s['force_x_N']:.0f}, {s['force_y_N']:.0f}, {s['force_z_N']:.0f}) N, "
              f"L10h = {s.get('basic_rating_life_h', float('nan')):.0f} h")
    print(f"gearbox system life L10h = {doc['system_life_h']:.0f} h ({len(rows)} rows along the shaft)")


def spindle(out):
    doc = document("spindle", stiffness_at="0 mm", modes="3")
    write(out, "spindle", doc)
    k = doc.get("stiffness_at") or {}
    print(f"spindle: stiffness at the nose {k.get('stiffness_x_N_per_um', float('nan')):.1f} N/um; "
          f"natural frequencies {', '.join(f'{f:.0f}' for f in doc.get('natural_frequencies_Hz', []))} Hz")


def main(argv):
    out = Path(argv[1] if len(argv) > 1 else "out") / "shaft"
    out.mkdir(parents=True, exist_ok=True)
    gearbox(out)
    spindle(out)
    print(f"wrote gearbox.json, gearbox_along_shaft.csv, gearbox.png, spindle.json, spindle.png in {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
