"""Former home of the runout figures, now :mod:`bearinglab.plots.runout` (kept for old imports).

Importing it imports matplotlib, as before.
"""

from .plots.runout import (
    figure_axial,
    figure_contact,
    figure_histograms,
    figure_spectrum,
    figure_trajectory,
    save,
    save_monte_carlo,
    save_sequence,
    save_single,
)

__all__ = [
    "figure_axial",
    "figure_contact",
    "figure_histograms",
    "figure_spectrum",
    "figure_trajectory",
    "save",
    "save_monte_carlo",
    "save_sequence",
    "save_single",
]
