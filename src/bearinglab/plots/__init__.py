"""Figures (matplotlib; functions return Figures). Import a submodule to use it, e.g.
``from bearinglab.plots import runout``; matplotlib is imported only then, so ``import bearinglab``
stays light.

Submodules
----------
runout      figures of spec 003: contact, trajectory, axial motion, spectrum, Monte Carlo histograms
"""

__all__: list[str] = []
