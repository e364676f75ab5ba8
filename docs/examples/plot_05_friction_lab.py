"""
Friction-rig lab: from readings to coefficients
===============================================

Data set S1 of the friction-rig method (bearing 18, readings and calibration tables, see
:doc:`/theory/friction_lab`): the three least-squares fits, and the task-1 plot of torque against the
static equivalent load with the lines drawn from zero.
"""

from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

import bearinglab
from bearinglab.lab import analysis, measurement

# the session file shipped in the repository's examples/friction/ folder
here = Path(bearinglab.__file__).resolve().parents[2]
session = measurement.read_session(here / "examples" / "friction" / "s1_readings.toml")
result = analysis.analyse(session)
t1, t2, t3 = result.task1, result.task2, result.task3
print("task 1  mu :", np.array2string(t1.friction_coefficient, precision=6))
print("task 2  f0 :", np.array2string(t2.speed_term_factor, precision=6))
print("task 3  f  :", np.array2string(t3.load_term_factor, precision=6))

# %%
# Task 1: T = mu P0 d/2 through the origin, one line per speed column.
rows = result.rows
d = session.bearing.bore
fig, ax = plt.subplots(figsize=(6, 3.5), layout="constrained")
for k, idx in enumerate(t1.rows):
    p0 = rows.equivalent_load[idx]
    torque = rows.torque[idx] * 1e3  # N*mm
    line, = ax.plot(p0, torque, "o", label=f"{t1.shaft_speed[k] * 60 / (2 * np.pi):.0f} rpm")
    x = np.array([0.0, 1.1 * p0.max()])
    ax.plot(x, t1.friction_coefficient[k] * x * d / 2 * 1e3, color=line.get_color())
ax.set_xlabel("static equivalent load P0 [N]")
ax.set_ylabel("friction torque [N·mm]")
ax.set_xlim(left=0)
ax.set_ylim(bottom=0)
ax.legend()
plt.show()
