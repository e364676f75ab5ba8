"""Former home of the runout contact solvers, now :mod:`bearinglab.runout._solver` (kept for old imports)."""

from .runout._solver import same_pattern, scale, solve_dual, solve_lp, solve_triples

__all__ = ["same_pattern", "scale", "solve_dual", "solve_lp", "solve_triples"]  # as before
