"""Input checks used at the public boundary of every model.

Each check converts to a float array, raises :class:`~bearinglab.errors.InputError` naming the
parameter, the rule with its unit and the first offending value, and returns the array.
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


def check_integer(name, value, minimum):
    arr = as_float(name, value)
    bad = ~((arr == np.round(arr)) & (arr >= minimum))
    if bad.any():
        _fail(name, f"an integer >= {minimum}", "-", arr, bad)
    return arr.astype(int)
