r"""SKF's drag loss factor V_M of an oil bath, read from its published diagram.

Drag loss factor
----------------
drag_loss_factor       V_M at H/d_m for ball or roller bearings (the digitised diagram, interpolated)
drag_loss_table        the digitised points of one curve, with the source of every row
MAX_LEVEL_RATIO        the largest H/d_m of the diagram (1.4)

The SKF model's drag moment of an oil bath (:func:`bearinglab.friction.drag_moment` for ball bearings,
:func:`bearinglab.friction.roller_drag_moment` for roller bearings) takes V_M, "the variable as a function of
the oil level" that SKF gives only as a diagram, one curve for ball bearings and one for roller bearings. Both
friction models read it here, so that an oil bath needs its oil level H and no value read by hand.

References
----------
.. [1] SKF, *General Catalogue* 6000 EN (2005) and 6000/I RU (2006), section "Friction", "Drag losses in oil bath
   lubrication", p. 98-99 and diagram 2 (the drag loss factor V_M against H/d_m; red curve ball bearings, blue
   curve roller bearings), and the worked example of a 22208 E in an oil bath, p. 105 (V_M ~ 0.3e-4 at
   H/d_m = 0.041, roller bearings). The same diagram, with a detail chart of H/d_m <= 0.2, is in SKF's later
   catalogue PUB BU/P1 10000 EN; it was digitised for bearinglab from that diagram as published in the public
   repository github.com/JRaposo-m/SKF-Bearing-Selection-Tool (``data/skf_drag_loss_factor.csv`` says how, with
   its checks).
"""

from __future__ import annotations

import csv
from functools import cache
from importlib import resources

import numpy as np

from .._validate import check_nonnegative
from ..errors import InputError

__all__ = ["MAX_LEVEL_RATIO", "drag_loss_factor", "drag_loss_table"]

_KINDS = ("ball", "roller")


@cache
def _table(kind):
    ref = resources.files("bearinglab") / "data" / "skf_drag_loss_factor.csv"
    with ref.open(encoding="utf-8") as f:
        rows = [r for r in csv.DictReader(line for line in f if not line.startswith("#")) if r["bearing"] == kind]
    h = np.array([float(r["h_over_dm"]) for r in rows])
    v = np.array([float(r["drag_loss_factor"]) for r in rows])
    return h, v, tuple(r["source"] for r in rows)


def drag_loss_table(rolling_element="ball"):
    """The digitised points of SKF's V_M curve of ball or roller bearings.

    Parameters
    ----------
    rolling_element : {"ball", "roller"}
        Which curve.

    Returns
    -------
    tuple
        ``(h_over_dm, drag_loss_factor, sources)``: H/d_m [-] rising, V_M [-] and the source of every row.

    Examples
    --------
    >>> h, v, sources = drag_loss_table("roller")
    >>> print(f"{h[0]:g} {v[0]:g}, {len(h)} points up to H/d_m = {h[-1]:.2f}")
    0 0, 129 points up to H/d_m = 1.40
    """
    if rolling_element not in _KINDS:
        raise InputError(f"rolling_element must be one of {list(_KINDS)}, got {rolling_element!r}")
    return _table(rolling_element)


#: The largest H/d_m of SKF's diagram; V_M is flat from about 1.2 (the bearing under oil). [-]
MAX_LEVEL_RATIO = 1.4


def drag_loss_factor(oil_level, mean_diameter, rolling_element="ball"):
    r"""SKF's drag loss factor V_M of an oil bath at the oil level H.

    Parameters
    ----------
    oil_level : array_like
        H, from the lowest point of the outer ring raceway to the oil surface (SKF's fig. 2), >= 0. [m]
    mean_diameter : array_like
        d_m = (d + D)/2. [m]
    rolling_element : {"ball", "roller"}
        The curve: ball bearings (:func:`bearinglab.friction.drag_moment`) or roller bearings
        (:func:`bearinglab.friction.roller_drag_moment`).

    Returns
    -------
    ndarray or float
        V_M, interpolated linearly in the digitised diagram (``data/skf_drag_loss_factor.csv``). [-]

    Notes
    -----
    SKF's diagram gives V_M against H/d_m from 0 to 1.4; a higher level is refused (InputError), as the diagram
    holds no value there. The digitisation agrees with an independent one of the same diagram within 3.6 %, and
    gives 3.09e-5 where SKF's worked example reads about 0.3e-4 (module references). SKF notes that the curves
    hold for a large bath at speeds up to the reference speed; external agitation (gears, cams) is not included.

    Examples
    --------
    SKF's worked example, a 22208 E (d_m = 60 mm) with H = 2.5 mm, reads V_M ~ 0.3e-4:

    >>> print(f"{drag_loss_factor(2.5e-3, 60e-3, 'roller'):.3g}")
    3.09e-05
    >>> print(f"{drag_loss_factor(0.03, 0.06, 'ball'):.3g}")
    0.000568
    """
    h, v, _ = drag_loss_table(rolling_element)
    level = check_nonnegative("oil_level", oil_level, "m")
    dm = np.asarray(mean_diameter, dtype=float)
    if not np.all(dm > 0):
        raise InputError(f"mean_diameter must be > 0 [m], got {float(np.min(dm)):g} m")
    ratio = level / dm
    if np.any(ratio > MAX_LEVEL_RATIO):
        raise InputError(f"oil_level must be <= {MAX_LEVEL_RATIO:g} d_m (the end of SKF's drag loss diagram) [mm], got "
                         f"H/d_m = {float(np.max(ratio)):.3g}; give the drag loss factor V_M instead")
    return np.interp(ratio, h, v)[()]
