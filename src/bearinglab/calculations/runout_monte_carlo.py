"""The ``runout-monte-carlo`` document: runout statistics over random bearings (spec 003).

Random bearings of an ISO 3290 ball grade and a ring class (``bearinglab runout monte-carlo``); the
computation is :func:`bearinglab.calculations.runout.compute_monte_carlo`, which the command line uses.

Functions
---------
document   Parsed request -> the JSON document ``bearinglab runout monte-carlo --json`` prints
"""

from __future__ import annotations

from .runout import monte_carlo_document as document

__all__ = ["document"]
