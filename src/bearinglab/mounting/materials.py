"""Materials of the mounted-clearance chain: elastic constants, density and thermal expansion.

MountingMaterial    E, nu, density, linear thermal expansion, source
MATERIAL_NAMES      the names of ``data/mounting_materials.toml`` (steel, structural_steel, aluminium, ...)
material            a material by name (InputError listing the names)
of_bearing          the material of a :class:`bearinglab.bearing.Material` (its thermal expansion added)
"""

from __future__ import annotations

import functools
import tomllib
from importlib import resources
from typing import NamedTuple

from ..errors import InputError

__all__ = ["MATERIAL_NAMES", "MountingMaterial", "material", "of_bearing"]


class MountingMaterial(NamedTuple):
    """An isotropic, linear-elastic material with its thermal expansion."""

    name: str
    elastic_modulus: float
    """Young's modulus. [Pa]"""
    poisson_ratio: float
    """Poisson's ratio. [-]"""
    density: float
    """Mass density. [kg/m^3]"""
    thermal_expansion: float
    """Linear thermal expansion coefficient near room temperature. [1/K]"""
    source: str


@functools.cache
def _table():
    text = (resources.files("bearinglab") / "data" / "mounting_materials.toml").read_text(encoding="utf-8")
    return {name: MountingMaterial(name, float(v["elastic_modulus"]), float(v["poisson_ratio"]),
                                   float(v["density"]), float(v["thermal_expansion"]), v["source"])
            for name, v in tomllib.loads(text).items()}


MATERIAL_NAMES = ("steel", "silicon_nitride", "structural_steel", "aluminium")
_ALIASES = {"aluminum": "aluminium", "si3n4": "silicon_nitride", "bearing_steel": "steel", "52100": "steel",
            "100cr6": "steel"}


def material(name):
    """The material of that name from ``data/mounting_materials.toml``.

    Parameters
    ----------
    name : str
        One of :data:`MATERIAL_NAMES` (or ``aluminum``, ``si3n4``, ``100Cr6``).

    Returns
    -------
    MountingMaterial

    Examples
    --------
    >>> m = material("aluminium")
    >>> print(m.elastic_modulus / 1e9, "GPa", m.thermal_expansion * 1e6, "um/(m K)")
    70.0 GPa 23.0 um/(m K)
    """
    key = str(name).strip().lower().replace("-", "_").replace(" ", "_")
    key = _ALIASES.get(key, key)
    table = _table()
    if key not in table:
        raise InputError(f"material must be one of {list(MATERIAL_NAMES)}, got {name!r}")
    return table[key]


def of_bearing(bearing_material):
    """The mounting material of a ring or ball material of a :class:`~bearinglab.bearing.BallBearing`.

    Parameters
    ----------
    bearing_material : bearinglab.bearing.Material
        Its name (``"steel"``, ``"silicon nitride"``) selects the thermal expansion of the data file;
        its elastic constants and density are kept.

    Returns
    -------
    MountingMaterial

    Examples
    --------
    >>> from bearinglab.bearing import STEEL
    >>> print(of_bearing(STEEL).thermal_expansion)
    1.25e-05
    """
    base = material(bearing_material.name)
    return base._replace(elastic_modulus=float(bearing_material.elastic_modulus),
                         poisson_ratio=float(bearing_material.poisson_ratio),
                         density=float(bearing_material.density))
