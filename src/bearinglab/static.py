r"""Static contact angle of a ball bearing under pure thrust: the public path of :mod:`bearinglab.stand.static`.

The relations live in :mod:`bearinglab.stand.static` (with the test-stand method that builds on them);
this module keeps ``bearinglab.static.contact_angle_under_thrust`` and the other names working, and the
test-stand names it held before the method moved (``stand_analysis``, ``stand_constants``,
``min_axial_load``, ``PAPER_ELASTIC_CONSTANT``, ...) reachable, unchanged.

Load-angle relation
-------------------
thrust_from_angle            F_a = C* (cos a0 / cos a - 1)^1.5 sin a                        eq. (1)
first_approximation          x0 of eq. (3) (corrected prefactor sin 2 alpha0)
axial_displacement_ratio     xi_a = delta_a / (B D) = cos a0 (tan a - tan a0)
contact_angle_under_thrust   the static angle with the stiffness at the loaded angle
ThrustContact
"""

from . import stand
from .stand.static import (
    ThrustContact,
    axial_displacement_ratio,
    contact_angle_under_thrust,
    first_approximation,
    thrust_from_angle,
)

__all__ = [
    "ThrustContact",
    "axial_displacement_ratio",
    "contact_angle_under_thrust",
    "first_approximation",
    "thrust_from_angle",
]

#: Names of the test-stand method that this module held before the method moved to :mod:`bearinglab.stand`.
_STAND_NAMES = frozenset({
    "MIN_LOAD_CONSTANT", "PAPER_ELASTIC_CONSTANT", "IterationRow", "StandAnalysis", "StandConstants", "StandLoad",
    "iteration_table", "min_axial_load", "min_axial_load_gyroscopic", "operating_contact_angle",
    "series_coefficients", "stand_analysis", "stand_constants",
})


def __getattr__(name):
    """The test-stand names and the private helpers of :mod:`bearinglab.stand.static`, unchanged."""
    if name in _STAND_NAMES:
        return getattr(stand, name)
    if name.startswith("_") and not name.startswith("__") and hasattr(stand.static, name):
        return getattr(stand.static, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | _STAND_NAMES)
