"""Lubricant film in ball bearings: the EHL film of each contact and of every ball of a bearing.

Modules
-------
ehl        one elliptical contact: Hamrock-Dowson film, inlet heating, pressure-viscosity estimate,
           film parameter Lambda and lubrication regime
analysis   every ball of a bearing under combined load, at rest or at speed: loads, angles and
           entrainment velocities from the load distribution, films, Lambda, regime, warnings
line_contact  line (roller) contacts: Pan-Hamrock and Dowson-Higginson films, every roller's film and Lambda

The package re-exports the public names of both modules.
"""

from . import analysis, ehl, line_contact
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
from .line_contact import (
    LINE_MODELS,
    RollerFilms,
    line_film,
    roller_entrainment_velocity,
    roller_films,
)

__all__ = [
    "LINE_MODELS",
    "REGIMES",
    "REGIME_THRESHOLDS",
    "ContactRadii",
    "DimensionlessGroups",
    "FilmAnalysis",
    "FilmThickness",
    "RollerFilms",
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
    "line_contact",
    "line_film",
    "lubrication_regime",
    "pressure_viscosity_coefficient",
    "roller_entrainment_velocity",
    "roller_films",
    "thermal_reduction_factor",
]
