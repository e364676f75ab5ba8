"""Input checks used at the public boundary of every model.

Each check converts to a float array, raises :class:`~bearinglab.errors.InputError` naming the
parameter, the rule with its unit and the first offending value, and returns the array. A count that
sizes a loop or an array (:func:`check_integer`) is a whole number below 2^63, and below ``maximum``
where one is given: no ``OverflowError`` from numpy, no loop that does not end (issue 29).
"""

from __future__ import annotations

import numpy as np

from .errors import InputError

__all__: list[str] = []


def _fail(name, rule, unit, value, bad):
    first = value[bad].flat[0] if np.ndim(value) else value
    count = f" ({int(bad.sum())} of {value.size} values)" if np.ndim(value) and value.size > 1 else ""
    raise InputError(f"{name} must be {rule} [{unit}], got {float(first)!r}{count}")


def as_float(name, value):
    try:
        return np.asarray(value, dtype=float)
    except (TypeError, ValueError) as exc:
        raise InputError(f"{name} must be a number or an array of numbers, got {value!r}") from exc


def check_positive(name, value, unit):
    value = as_float(name, value)
    bad = ~(value > 0)  # NaN is bad too
    if bad.any():
        _fail(name, "> 0", unit, value, bad)
    return value


def check_nonnegative(name, value, unit):
    value = as_float(name, value)
    bad = ~(value >= 0)
    if bad.any():
        _fail(name, ">= 0", unit, value, bad)
    return value


def check_finite(name, value, unit):
    value = as_float(name, value)
    bad = ~np.isfinite(value)
    if bad.any():
        _fail(name, "finite", unit, value, bad)
    return value


def check_open_interval(name, value, low, high, unit, *, scale=1.0, shown_unit=None):
    """Require ``low < value < high``; ``scale`` converts value and bounds for the message."""
    value = as_float(name, value)
    bad = ~((value > low) & (value < high))
    if bad.any():
        rule = f"in ({low * scale:g}, {high * scale:g})"
        _fail(name, rule, shown_unit or unit, value * scale, bad)
    return value


def check_greater(name, value, other_name, other, unit):
    """Require ``value > other`` elementwise."""
    value = as_float(name, value)
    other = np.asarray(other, dtype=float)
    bad = ~(value > other)
    if bad.any():
        v, o = np.broadcast_arrays(value, other)
        raise InputError(
            f"{name} must be > {other_name} [{unit}], got {float(v[bad].flat[0])!r} "
            f"with {other_name} = {float(o[bad].flat[0])!r}"
        )
    return value


def check_positive_finite(name, value, unit):
    """Require ``0 < value < inf`` (a size, a load or a modulus that scales a result): the message of
    :func:`check_positive`, then of :func:`check_finite`."""
    return check_finite(name, check_positive(name, value, unit), unit)


_LARGEST_INTEGER = 2.0**63  # an int64 holds less; a count beyond it sizes no array and ends no loop


def check_integer(name, value, minimum, maximum=None):
    """Require a whole number ``>= minimum`` (and ``<= maximum`` where given, else below 2^63)."""
    if isinstance(value, (bool, np.bool_)):
        raise InputError(f"{name} must be an integer >= {minimum} [-], got {value!r}")
    arr = as_float(name, value)
    bad = ~((arr == np.round(arr)) & (arr >= minimum))
    if bad.any():
        _fail(name, f"an integer >= {minimum}", "-", arr, bad)
    top = _LARGEST_INTEGER if maximum is None else maximum
    big = ~(arr <= top) if maximum is not None else ~(arr < top)
    if big.any():
        _fail(name, f"an integer in [{minimum}, {maximum}]" if maximum is not None else "an integer below 2^63",
              "-", arr, big)
    return arr.astype(int)
