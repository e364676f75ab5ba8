"""The friction-rig lab (spec 001 sections 4-7): from raw rig readings to fitted handbook coefficients.

Submodules
----------
rig           loads from the hung mass and the tilt, P0 and its branch, tare mass
calibration   speed and torque calibration tables, piecewise-linear conversion without extrapolation
fits          the three least-squares tasks: mu (task 1), f0 and T_F (task 2), f and T0 (task 3)
measurement   the measurement-session file: reading, validation, and the blank template
analysis      one session -> per-row values, Tables 4 and 5, fits, cross-checks, indicators, conclusions

This package sits at the boundary (it reads files with units), so it may import pint through
:mod:`bearinglab.units`; the physics it uses is in :mod:`bearinglab.friction`.
"""

from . import analysis, calibration, fits, measurement, rig

__all__ = ["analysis", "calibration", "fits", "measurement", "rig"]
