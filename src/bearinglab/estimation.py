r"""Estimated internal geometry of a catalog bearing from its boundary dimensions.

Makers publish the envelope d x D x B and the ratings, rarely the ball set. Where no public source gives
the ball set, the catalog estimates it by the rules below, and labels every field so obtained as
"estimated" (docs/user_guide/catalog.md, "Estimated internal geometry", has the rules' measured error).

Functions
---------
estimate_ball_set    Z, D_w and d_m of a deep-groove or angular-contact bearing from d, D and B
snap_ball_diameter   the nearest standard ball size (ISO 3290 nominal sizes, ``data/ball_sizes.csv``)
ball_sizes           the standard ball diameters as stored [m]

Constants
---------
RULES                the calibrated coefficients of each family
GROOVE_CONFORMITY    the conformities assumed, f_i = 0.52 and f_o = 0.53 (ISO 76 / ISO 281)

Rules (lengths in the same unit)
--------------------------------
- pitch diameter: :math:`d_m = (d + D) / 2`;
- ball diameter: :math:`D_w = \mathrm{snap}(\min(k (D - d), k_B B))`, the nearest standard ball;
  :math:`k = 0.29` (bores below 10 mm, the miniatures: 0.27 deep-groove, 0.255 angular-contact),
  :math:`k_B = 0.75` (deep-groove) or 0.80;
- ball count, deep-groove (Conrad assembly: the balls fill a sector of the eccentric rings):
  :math:`Z = \lfloor \phi / (2 \arcsin(D_w / d_m)) \rfloor + 1` with a filling angle :math:`\phi = 198°`;
- ball count, angular-contact (the rings are assembled over a counterbore, so the balls are spaced only
  by the cage's webs): :math:`Z = \lfloor \pi d_m / (D_w + s) \rfloor` with a web
  :math:`s = 0.6\ \mathrm{mm} + 0.02\, d_m`;
- groove conformities 0.52 (inner) and 0.53 (outer): the values ISO 76 table 2 and ISO 281 clause 6
  assume for their factors f0 and fc; Harris & Kotzalas give 0.515-0.53 as the usual range.

Calibration: on the published ball sets of ``data/ball_sets.csv`` (116 of its 117 rows: the data
sets' bearings, the textbook examples and GMN's catalogue of deep-groove and spindle bearings, which
prints d_m, D_w and Z of every size; the instrument bearing 4-1006095 is outside the rules' range), per
family: deep-groove D_w within 9.5 %, Z within one ball (20 of 23 exact); angular-contact D_w within
10.3 %, Z within two balls; miniatures (d < 10 mm) D_w within 10.3 % (deep-groove) and 16.7 %
(angular-contact). The table and the ratings check are in docs/user_guide/catalog.md.

References
----------
.. [1] T. A. Harris, M. N. Kotzalas, *Rolling Bearing Analysis*, 5th ed., CRC Press, 2007: Conrad
   assembly and its filling angle; groove curvatures 0.515-0.53.
.. [2] ISO 76:2006 table 2 and ISO 281:2007 clause 6.1: ratings for groove radii <= 0.52 D_w (inner)
   and <= 0.53 D_w (outer).
.. [3] GMN Paul Müller Industrie, *High precision ball bearings*, catalogue 4000 0813 EN: bearing
   data of the spindle bearings (pp. 22-43) and deep-groove bearings (pp. 52-55) with d_m, D_w and Z.
"""

from __future__ import annotations

import csv
import functools
import math
from importlib import resources
from typing import NamedTuple

import numpy as np

from ._validate import check_positive
from .errors import InputError

__all__ = ["GROOVE_CONFORMITY", "RULES", "EstimatedBallSet", "ball_sizes", "estimate_ball_set",
           "snap_ball_diameter"]

#: Calibrated coefficients: ``k`` (D_w / (D - d)), ``k_small`` (bores below ``small_bore``), ``k_width``
#: (D_w / B at most), and the filling angle [deg] (deep-groove) or the cage web between two balls,
#: ``web`` [m] + ``web_per_pitch`` d_m (angular-contact).
RULES = {
    "deep-groove": {"k": 0.29, "k_small": 0.27, "small_bore": 10e-3, "k_width": 0.75, "filling_angle": 198.0},
    "angular": {"k": 0.29, "k_small": 0.255, "small_bore": 10e-3, "k_width": 0.80, "web": 0.6e-3,
                "web_per_pitch": 0.02},
}
GROOVE_CONFORMITY = {"inner": 0.52, "outer": 0.53}
_FAMILIES = {"deep-groove": "deep-groove", "radial": "deep-groove", "angular": "angular"}


class EstimatedBallSet(NamedTuple):
    """An estimated ball set."""

    n_balls: int | np.ndarray
    """Number of balls Z. [-]"""
    ball_diameter: float | np.ndarray
    """Ball diameter D_w, a standard size. [m]"""
    pitch_diameter: float | np.ndarray
    """Pitch diameter d_m. [m]"""


@functools.cache
def ball_sizes():
    """The standard ball diameters of ``data/ball_sizes.csv``, ascending. [m]

    Examples
    --------
    >>> float(ball_sizes()[0]), round(float(ball_sizes()[-1]) * 1e3, 1)
    (0.0003, 114.3)
    """
    text = (resources.files("bearinglab") / "data" / "ball_sizes.csv").read_text(encoding="utf-8")
    rows = csv.DictReader(line for line in text.splitlines() if not line.startswith("#"))
    return np.array(sorted(float(r["ball_diameter_mm"]) * 1e-3 for r in rows))


def snap_ball_diameter(ball_diameter):
    """The nearest standard ball size (a tie goes to the smaller one).

    Parameters
    ----------
    ball_diameter : array_like
        A ball diameter. [m]

    Returns
    -------
    ndarray or float
        The nearest diameter of :func:`ball_sizes`. [m]

    Examples
    --------
    >>> round(float(snap_ball_diameter(8.1e-3)) * 1e3, 4)   # 8 mm, not 5/16 in = 7.9375 mm
    8.0
    """
    x = check_positive("ball_diameter", ball_diameter, "m")
    sizes = ball_sizes()
    i = np.clip(np.searchsorted(sizes, x), 1, sizes.size - 1)
    lo, hi = sizes[i - 1], sizes[i]
    return np.where(x - lo <= hi - x, lo, hi)[()]


def estimate_ball_set(bore, outside_diameter, width, *, family="deep-groove"):
    r"""Estimate Z, D_w and d_m of a single-row ball bearing from its boundary dimensions.

    Parameters
    ----------
    bore, outside_diameter, width : array_like
        Boundary dimensions d, D and B. [m]
    family : {"deep-groove", "angular"}
        Deep-groove (Conrad) or angular-contact ball bearing (``"radial"`` is taken for deep-groove).

    Returns
    -------
    EstimatedBallSet
        ``n_balls`` [-], ``ball_diameter`` and ``pitch_diameter`` [m].

    Notes
    -----
    The rules and their coefficients are in the module docstring and :data:`RULES`; their error on the
    published ball sets is tabulated in docs/user_guide/catalog.md. An estimate, never a measurement.

    Examples
    --------
    >>> s = estimate_ball_set(0.025, 0.052, 0.015)   # 6205: published 9 balls of 7.94 mm on 39.04 mm
    >>> int(s.n_balls), round(float(s.ball_diameter) * 1e3, 3), round(float(s.pitch_diameter) * 1e3, 2)
    (9, 7.938, 38.5)
    >>> s = estimate_ball_set(0.025, 0.047, 0.012, family="angular")  # GMN S 6005 C: 15 of 6.35 mm
    >>> int(s.n_balls), round(float(s.ball_diameter) * 1e3, 3)
    (14, 6.35)
    """
    key = _FAMILIES.get(str(family))
    if key is None:
        raise InputError(f"family must be one of ['deep-groove', 'angular'], got {family!r}")
    rule = RULES[key]
    d = check_positive("bore", bore, "m")
    big = check_positive("outside_diameter", outside_diameter, "m")
    b = check_positive("width", width, "m")
    if np.any(big <= d):
        raise InputError("outside_diameter must be > bore [m]")
    d, big, b = np.broadcast_arrays(d, big, b)
    dm = (d + big) / 2.0
    k = np.where(d < rule["small_bore"], rule["k_small"], rule["k"])
    dw = snap_ball_diameter(np.minimum(k * (big - d), rule["k_width"] * b))
    half = np.arcsin(dw / dm)  # half the angle a ball takes on the pitch circle
    if key == "deep-groove":
        z = np.floor(math.radians(rule["filling_angle"]) / (2.0 * half)) + 1
    else:
        # Each ball takes its diameter plus a cage web on the pitch circle; the web's fixed part is why
        # thin sections (618) carry fewer balls than a filled fraction of the circle would give them.
        z = np.floor(math.pi * dm / (dw + rule["web"] + rule["web_per_pitch"] * dm))
    return EstimatedBallSet(z.astype(int)[()], np.asarray(dw)[()], dm[()])
