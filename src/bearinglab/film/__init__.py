"""Lubricant film in ball bearings: the EHL film of each contact and of every ball of a bearing.

Modules
-------
ehl        one elliptical contact: Hamrock-Dowson film, inlet heating, pressure-viscosity estimate,
           film parameter Lambda and lubrication regime
analysis   every ball of a bearing under combined load, at rest or at speed: loads, angles and
           entrainment velocities from the load distribution, films, Lambda, regime, warnings

The package re-exports the public names of both modules.
"""

from . import analysis, ehl
from .analysis import FilmAnalysis, distribution_films, entrainment_velocities, film_analysis
from .ehl import (
    REGIME_THRESHOLDS,
    REGIMES,
    ContactRadii,
    DimensionlessGroups,
    FilmThickness,
    contact_radii,
    dimensionless_groups,
    ellipticity,
    film_parameter,
    hamrock_dowson,
    lubrication_regime,
    pressure_viscosity_coefficient,
    thermal_reduction_factor,
)

__all__ = [
    "REGIMES",
    "REGIME_THRESHOLDS",
    "ContactRadii",
    "DimensionlessGroups",
    "FilmAnalysis",
    "FilmThickness",
    "analysis",
    "contact_radii",
    "dimensionless_groups",
    "distribution_films",
    "ehl",
    "ellipticity",
    "entrainment_velocities",
    "film_analysis",
    "film_parameter",
    "hamrock_dowson",
    "lubrication_regime",
    "pressure_viscosity_coefficient",
    "thermal_reduction_factor",
]
