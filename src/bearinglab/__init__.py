"""bearinglab: ball-bearing mechanics, correct to the digit against the published methods.

Submodules
----------
units       SI constants, converters and parsing of quantities with units (boundary only)
errors      InputError, CatalogError, ConvergenceError, ValidityWarning
kinematics  cage and ball speeds, characteristic (defect) frequencies, spectral masks
"""

from . import errors, kinematics, units

__version__ = "0.1.0"
__all__ = ["errors", "kinematics", "units", "__version__"]
