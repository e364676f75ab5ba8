"""The figures of bearinglab: all matplotlib lives here, and every function returns a Figure.

Submodules
----------
friction    figures of the friction-rig lab (spec 001 section 7.4)

Matplotlib is imported by the plotting functions on first use (with the Agg canvas attached
explicitly: no pyplot, no global backend state), so ``import bearinglab`` stays light.
"""

__all__: list[str] = []
