r"""The test-stand method of spec 000, and the static contact angle under thrust it builds on.

Modules
-------
method       the method itself: minimum stand load, contact constants and C*, the operating contact angle,
             its iteration table and the whole analysis (every public name is re-exported here)
static       the static contact angle of a ball bearing under pure thrust at zero speed (eqs. (1) and (3),
             the axial displacement; also reachable as :mod:`bearinglab.static`)
_gap         Halley's step on the gap polynomial, shared by the numpy path and the compiled kernel
_compiled    the compiled fast path of the operating-angle solve (numba; imported only when it runs)

``bearinglab.stand.operating_contact_angle`` and the other names of :mod:`bearinglab.stand.method` are
reachable from here, as they were when the method was one module.
"""

from . import method, static
from .method import (
    MIN_LOAD_CONSTANT,
    PAPER_ELASTIC_CONSTANT,
    IterationRow,
    StandAnalysis,
    StandConstants,
    StandLoad,
    constants_at_operating_angle,
    engine_for,
    iteration_table,
    min_axial_load,
    min_axial_load_gyroscopic,
    operating_contact_angle,
    series_coefficients,
    stand_analysis,
    stand_constants,
)

__all__ = [
    "MIN_LOAD_CONSTANT",
    "PAPER_ELASTIC_CONSTANT",
    "IterationRow",
    "StandAnalysis",
    "StandConstants",
    "StandLoad",
    "constants_at_operating_angle",
    "engine_for",
    "iteration_table",
    "method",
    "min_axial_load",
    "min_axial_load_gyroscopic",
    "operating_contact_angle",
    "series_coefficients",
    "stand_analysis",
    "stand_constants",
    "static",
]
