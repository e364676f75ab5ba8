"""
Runout from manufacturing errors
================================

Worked example 3 of the runout method (ball scatter, inner eccentricity and waviness, outer waviness;
see :doc:`/theory/runout`): the inner-ring centre over three revolutions, all 1080 positions solved in
one batch.
"""

from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

import bearinglab
from bearinglab import runout

here = Path(bearinglab.__file__).resolve().parents[2]
geometry, errors = runout.load_error_file(here / "examples" / "runout" / "example3_mixed.toml")
t = runout.rotation_sequence(geometry, errors, revolutions=3, steps_per_revolution=360)
um = 1e6
for name, value in t.metrics._asdict().items():
    print(f"{name:15s} {value * um:+.6f} um")
print(f"degenerate positions: {100 * t.degenerate_fraction:.1f} %")

# %%
fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9, 3.8), layout="constrained")
ax1.plot(t.displacement.x * um, t.displacement.y * um, lw=0.8)
ax1.set_aspect("equal")
ax1.set_xlabel("Δx [µm]")
ax1.set_ylabel("Δy [µm]")
ax1.set_title("centre trajectory")
ax2.plot(np.degrees(t.rotation_angle), t.displacement.z * um, lw=0.8)
ax2.set_xlabel("inner-ring rotation ψ [deg]")
ax2.set_ylabel("Δz [µm]")
ax2.set_title("axial displacement")
plt.show()
