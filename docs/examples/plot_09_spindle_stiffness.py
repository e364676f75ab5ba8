"""
A spindle's stiffness at the nose against its bearing span and preload
======================================================================

The spindle of ``examples/shaft/spindle.toml``: a hollow shaft (bore 30 mm) with a DB pair of 7014 C at
100 mm from the nose and a 6012 floating at the rear. The rear bearing moves along its 180 mm seat, so the
span between the middle of the front pair and the rear bearing runs from 130 to 290 mm, for three preloads
of the pair (200, 500, 1000 N). At each point the shaft system is solved at rest under the tool's load
(:func:`bearinglab.shaft.solve`) and the direct radial stiffness at the nose is the linearised system's
(:func:`bearinglab.shaft.stiffness_at`: the shaft's Timoshenko elements and every bearing's tangent
stiffness at its operating point).

Two things a spindle designer knows show up. Over this range the nose stiffens as the span grows: a
short span lets the nose tilt about the front pair (the rear deep-groove bearing, with its clearance, is
the softer support), and the gain levels off as the shaft's bending between the bearings takes over (the
stiffest span lies at or beyond the end of the seat). The preload stiffens the front pair, so the curves
rise with it, less than in proportion (the Hertz contact's stiffness grows as the cube root of its load).
The small kinks are real: a ball of the rear bearing enters or leaves contact as its load turns with the
span. The theory is :doc:`/theory/shaft_systems`; the
bearings' internal geometry is an estimate (the catalog says so).
"""

import warnings
from pathlib import Path

import numpy as np

import bearinglab
from bearinglab import shaft
from bearinglab.plots import shaft as shaft_plots
from bearinglab.units import UM

warnings.simplefilter("ignore")  # estimated internal geometry: said above

# the spindle file shipped in the repository's examples/shaft/ folder
here = Path(bearinglab.__file__).resolve().parents[2]
base = shaft.load(here / "examples" / "shaft" / "spindle.toml").system.replace(speed=0.0, gravity=None)
front = base.supports[0]
spans = np.arange(130.0, 291.0, 10.0)  # mm, from the middle of the front pair
series = {}
for preload in (200.0, 500.0, 1000.0):
    k = []
    for span in spans:
        rear = base.supports[1]
        supports = (shaft.BearingSetSupport(front.name, front.position, front.bearings, "DB", preload=preload),
                    shaft.BearingSupport(rear.name, front.position + span * 1e-3, rear.bearing))
        state = shaft.solve(base.replace(supports=supports))
        k.append(shaft.stiffness_at(state, 0.0).stiffness[0, 0] * UM)  # N/um along x
    series[f"preload {preload:.0f} N"] = np.array(k)
    best = spans[int(np.argmax(k))]
    print(f"preload {preload:6.0f} N: nose stiffness {min(k):.1f} to {max(k):.1f} N/um, stiffest at a span of "
          f"{best:.0f} mm")

fig = shaft_plots.study(spans, series, xlabel="span front pair to rear bearing [mm]",
                        ylabel="radial stiffness at the nose [N/um]",
                        title="Spindle: 7014 C DB pair + 6012, stiffness at the nose (at rest)")
fig  # noqa: B018 (sphinx-gallery shows the figure)
