r"""Ring temperatures from the lumped bearing temperature: the coupling to the mounted clearance.

Ring temperatures
-----------------
ring_temperatures              inner and outer ring from the lumped bearing temperature and a split
clearance_conditions           the same as :class:`bearinglab.mounting.chain.Conditions`
RingTemperatures               their result
RING_TEMPERATURE_DIFFERENCE    the default split (inner ring warmer by 10 K)

References are those of :mod:`bearinglab.thermal`.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from .._validate import check_nonnegative, check_positive
from ..errors import InputError

__all__ = ["RING_TEMPERATURE_DIFFERENCE", "RingTemperatures", "clearance_conditions", "ring_temperatures"]

#: Inner ring warmer than the outer by this much by default [K]: the upper end of the ring temperature
#: difference that Normal clearance is made for (KRW catalogue, p. 95 [6]: more than 10 K calls for a
#: larger clearance group). A design value, not a prediction; give the machine's own where known.
RING_TEMPERATURE_DIFFERENCE = 10.0


class RingTemperatures(NamedTuple):
    """Inner and outer ring temperatures from a lumped bearing temperature [K]."""

    inner: np.ndarray
    outer: np.ndarray


def ring_temperatures(bearing_temperature, *, difference=RING_TEMPERATURE_DIFFERENCE):
    r"""Inner and outer ring temperatures from the lumped temperature of the thermal balance.

    Parameters
    ----------
    bearing_temperature : array_like
        T of :func:`thermal_balance` (or any lumped bearing temperature). [K]
    difference : array_like, optional
        T_inner - T_outer; by default :data:`RING_TEMPERATURE_DIFFERENCE` (10 K). [K]

    Returns
    -------
    RingTemperatures
        T_outer = T and T_inner = T + difference. [K]

    Notes
    -----
    The balance has one temperature; the clearance needs two. The lumped temperature is read as the
    outer ring's, because that is where ISO 15312 and SKF measure the bearing temperature ("on the
    bearing stationary outer ring" [5]), and the inner ring, which sheds its heat only through the
    balls and the shaft, is warmer - "which is usually the case" [6]. The default split of 10 K is the
    upper end of what Normal clearance is made for [6]: a design value, not a prediction. A measured
    or estimated difference of the machine should be given; 0 gives one temperature throughout.

    Examples
    --------
    >>> r = ring_temperatures(343.15)
    >>> print(f"inner {r.inner - 273.15:.1f} degC, outer {r.outer - 273.15:.1f} degC")
    inner 80.0 degC, outer 70.0 degC
    """
    t = check_positive("bearing_temperature", bearing_temperature, "K")
    dt = np.asarray(difference, dtype=float)
    if not np.all(np.isfinite(dt)) or np.any(np.abs(dt) > 100.0):
        raise InputError(f"difference must be in [-100, 100] [K] (inner minus outer ring), got "
                         f"{float(np.max(np.abs(dt)))!r}")
    return RingTemperatures((t + dt)[()], (t + 0 * dt)[()])


def clearance_conditions(bearing_temperature, *, difference=RING_TEMPERATURE_DIFFERENCE, speed=0.0):
    r"""The mounted-clearance chain's operating conditions from a bearing temperature.

    Parameters
    ----------
    bearing_temperature : float
        Lumped T of :func:`thermal_balance`. [K]
    difference : float, optional
        T_inner - T_outer (:func:`ring_temperatures`). [K]
    speed : float, optional
        Inner-ring speed for the chain's centrifugal stage. [rad/s]

    Returns
    -------
    bearinglab.mounting.chain.Conditions
        Inner and outer ring temperatures of :func:`ring_temperatures`; the balls at their mean, the
        shaft at the inner ring's and the housing at the outer ring's (the chain's defaults).

    Examples
    --------
    >>> from bearinglab.mounting.chain import Mounting, operating_clearance
    >>> m = Mounting(0.025, 0.052, 0.03110, 0.04698, 0.00794)
    >>> r = operating_clearance(20e-6, 0.0, 0.0, m, clearance_conditions(343.15, difference=10.0))
    >>> print(f"{r.thermal_reduction * 1e6:.2f} um")
    4.88 um
    """
    from ..mounting.chain import Conditions

    r = ring_temperatures(bearing_temperature, difference=difference)
    w = check_nonnegative("speed", speed, "rad/s")
    return Conditions(inner_temperature=float(r.inner), outer_temperature=float(r.outer), speed=float(w))
