"""Shaft systems: several bearings on an elastic shaft (issue 33)."""

from . import elements, mesh, model, solve, supports

__all__ = ["elements", "mesh", "model", "solve", "supports"]
