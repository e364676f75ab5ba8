"""Mounted clearance: fits and tolerances, thick cylinders, temperature and speed (issue 23).

Modules
-------
tables        ISO 286 fields of shafts and housings, ISO 492 bore and outside-diameter tolerances
fits          least and largest interference of the inner and outer fit; surface smoothing
materials     E, nu, density and thermal expansion of rings, balls, shafts and housings
lame          thick cylinders: fit pressure and the change of the raceway diameters
thermal       free expansion of rings and balls, and of the fits, from 20 degC
centrifugal   rotating-disc growth of the inner ring and the shaft; the inner fit's loss at speed
chain         the chain unmounted -> fit -> thermal -> centrifugal -> operating clearance
monte_carlo   the chain over random tolerances (uniform or normal fields), on bearinglab.parallel
preload       bearing sets: the operating axial interference of a set with rigid spacers
"""

from . import centrifugal, chain, fits, lame, materials, monte_carlo, preload, tables, thermal

__all__ = ["centrifugal", "chain", "fits", "lame", "materials", "monte_carlo", "preload", "tables", "thermal"]
