"""Shaft systems (issue 33): several bearings on an elastic shaft, with gears, housings and speed.

Modules
-------
model      the shaft, its supports and loads as checked dataclasses (Section, Shaft, BearingSupport, ...)
reading    the shaft-system file (TOML or JSON) -> the model and its load spectrum
elements   Timoshenko shaft elements (two bending planes, axial, torsion), rigid disks
mesh       nodes at every section change, support and load; assembled matrices; load vectors
supports   the bearings as the solver sees them (frames, preload offsets, housings), springs, constraints
statics    the solve: the shaft condensed to its bearing nodes, Newton over all load cases at once
outputs    internal loads along the shaft, stiffness at a point, each bearing's ball loads and lives
modes      natural frequencies and mode shapes at the operating point, gyroscopic; Campbell diagram
spectrum   load spectra on the executor, lives by Palmgren-Miner, the system life
rotor      the rotor exported to ROSS with bearinglab's speed-dependent bearing coefficients

The public names of the modules are reachable here: ``bearinglab.shaft.solve``,
``bearinglab.shaft.ShaftSystem``, ``bearinglab.shaft.load`` (a file).

Examples
--------
>>> from bearinglab import catalog, shaft
>>> b = catalog.get("6206")
>>> s = shaft.ShaftSystem(shaft.Shaft((shaft.Section(0.3, 0.03),)),
...                       (shaft.BearingSupport("A", 0.02, b, axial=True), shaft.BearingSupport("B", 0.28, b)),
...                       loads=(shaft.PointLoad(0.1, fx=3000.0),))
>>> r = shaft.solve(s)
>>> print([round(float(f)) for f in r.support_loads[0, :, 0]])  # the lever rule: 2076.9, 923.1
[2077, 923]
"""

from . import elements, mesh, model, modes, outputs, reading, rotor, spectrum, statics, supports
from .model import (
    BearingSetSupport,
    BearingSupport,
    Gear,
    Housing,
    LinearSupport,
    Mass,
    PointLoad,
    Pulley,
    RigidSupport,
    Section,
    Shaft,
    ShaftSystem,
    gear_loads,
)
from .modes import Campbell, Modes, campbell, natural_modes
from .outputs import (
    BearingState,
    InternalLoads,
    StiffnessAt,
    bearing_states,
    internal_loads,
    stiffness_at,
)
from .reading import ShaftDocument, from_dict, from_text, load
from .rotor import ross_elements, to_ross
from .spectrum import SpectrumLife, load_spectrum
from .statics import Assembly, Cases, SystemState, assemble, load_cases, solve

__all__ = [
    "Assembly",
    "BearingSetSupport",
    "BearingState",
    "BearingSupport",
    "Campbell",
    "Cases",
    "Gear",
    "Housing",
    "InternalLoads",
    "LinearSupport",
    "Mass",
    "Modes",
    "PointLoad",
    "Pulley",
    "RigidSupport",
    "Section",
    "Shaft",
    "ShaftDocument",
    "ShaftSystem",
    "SpectrumLife",
    "StiffnessAt",
    "SystemState",
    "assemble",
    "bearing_states",
    "campbell",
    "elements",
    "from_dict",
    "from_text",
    "gear_loads",
    "internal_loads",
    "load",
    "load_cases",
    "load_spectrum",
    "mesh",
    "model",
    "modes",
    "natural_modes",
    "outputs",
    "reading",
    "ross_elements",
    "rotor",
    "solve",
    "spectrum",
    "statics",
    "stiffness_at",
    "supports",
    "to_ross",
]
