"""bearinglab: ball-bearing mechanics, correct to the digit against the published methods.

Submodules
----------
units       SI constants, converters and parsing of quantities with units (boundary only)
errors      InputError, CatalogError, ConvergenceError, ValidityWarning
geometry    conformity, curvature sums, clearance and free contact angle
hertz       Hertz point contact: exact coefficients, semi-axes, pressure, approach, stiffness
bearing     Material, BallBearing: validated inputs of the models
catalog     built-in bearings and user TOML catalogs
designation designations as engineers write them: base size, seals, clearance, angle, tolerance
estimation  estimated ball set of a catalog bearing from its boundary dimensions
internal_clearance  ISO 5753-1 radial internal clearance classes of deep-groove ball bearings
static      static contact angle under thrust (zero speed): the public path of stand.static
stand       test-stand method (spec 000): stand load, C*, operating contact angle, iteration table;
            the static contact angle under thrust it builds on (stand.static)
parallel    chunked batch execution, serial or on dask
sweep       parameter sweeps of a model over a Cartesian grid (sweep files)
kinematics  cage and ball speeds, characteristic (defect) frequencies, spectral masks
runout      spindle-bearing manufacturing errors -> initial inner-ring displacement, runout (spec 003)
film        lubricant film: Hamrock-Dowson EHL film per contact and per ball, Lambda, regime
friction    friction torque: P0 max rule, one-term, two-term, Palmgren (spec 001 section 3)
lab         the friction-rig lab: rig loads, calibration, measurement files, the three fits (spec 001)
report      self-contained HTML reports of the friction lab, with PNG/SVG plots, CSV and JSON
quasistatic high-speed angular-contact bearing under thrust: centrifugal force, gyroscopic moment (spec 004)
tables      results -> engineering-unit columns; the CSV, Parquet and JSON writers
plots       all figures (matplotlib, loaded on first use); functions return Figures
cli         the command line (imported on its own: ``bearinglab.cli``, ``python -m bearinglab``)
ratings     load ratings and the life formulas: ISO 76, ISO 281, ISO/TS 16281
life        rating life of a bearing (ISO 281, ISO/TS 16281) and duty cycles
reactions   loads and stiffness of bearings at given ring displacements, batched (the entry point
            of system models)
thermal     steady bearing temperature: SKF friction power against the heat carried away
limits      plausibility limits: warnings for results beyond ISO 76, C0, Hertz, the shoulder, light load
mounting    mounted clearance: ISO 286 fits, ISO 492 tolerances, Lamé, temperature, speed (issue 23)
rollers     roller bearings: cylindrical, tapered (pairs), spherical; the ISO/TS 16281 slice model (issue 32)

The submodules are imported on first use (PEP 562): ``import bearinglab`` is instant, and
``bearinglab.hertz`` imports :mod:`bearinglab.hertz` the first time it is named, so that the command
line can start (``bearinglab --help``) without importing scipy or matplotlib.
"""

import importlib

__version__ = "0.2.0"
__all__ = [
    "__version__",
    "bearing",
    "catalog",
    "designation",
    "errors",
    "estimation",
    "film",
    "friction",
    "geometry",
    "hertz",
    "internal_clearance",
    "kinematics",
    "lab",
    "life",
    "limits",
    "mounting",
    "parallel",
    "plots",
    "quasistatic",
    "ratings",
    "reactions",
    "report",
    "rollers",
    "runout",
    "stand",
    "static",
    "sweep",
    "tables",
    "thermal",
    "units",
]


def __getattr__(name):
    """Import a submodule the first time it is named (PEP 562): ``bearinglab.hertz.point_contact``."""
    if name in __all__ and name != "__version__":
        return importlib.import_module(f".{name}", __name__)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | set(__all__))
