"""The friction-rig lab (spec 001 sections 4-7): from raw rig readings to fitted handbook coefficients.

Submodules
----------
rig           loads from the hung mass and the tilt, P0 and its branch, tare mass
calibration   speed and torque calibration tables, piecewise-linear conversion without extrapolation
fits          the three least-squares tasks: mu (task 1), f0 and T_F (task 2), f and T0 (task 3)
measurement   the measurement-session file: reading and validation (file, line and field in every error)
template      the blank, commented session file and its safe writer
analysis      one session -> per-row values, the three tasks, cross-checks and indicators I1-I7 (SI)
presentation  a result in engineering units: Tables 4 and 5, plot data, conclusions, the results dict

The report (HTML, figures, CSV, JSON) is written by :mod:`bearinglab.report`, the figures drawn by
:mod:`bearinglab.plots.friction`. This package sits at the boundary (it reads files with units), so
it may import pint through :mod:`bearinglab.units`; the physics it uses is in
:mod:`bearinglab.friction`.
"""

from . import analysis, calibration, fits, measurement, presentation, rig, template

__all__ = [
    "analysis",
    "calibration",
    "fits",
    "measurement",
    "presentation",
    "rig",
    "template",
]
