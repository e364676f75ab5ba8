"""Exceptions and warnings of bearinglab.

Errors
------
InputError        invalid input (a :class:`ValueError`): names the parameter, value and valid range
CatalogError      a malformed catalog or input file, or an unknown bearing (an :class:`InputError`)
ConvergenceError  an iterative solve that did not converge (a :class:`RuntimeError`)

Warnings
--------
ValidityWarning   an input outside the range a model or fit was derived on
"""

from __future__ import annotations

import numpy as np

__all__ = ["CatalogError", "ConvergenceError", "InputError", "ValidityWarning"]


class InputError(ValueError):
    """An input value that is physically impossible or outside a method's domain.

    The message names the parameter, the rule with its unit, and the offending value.
    """


class CatalogError(InputError):
    """A catalog or input file that cannot be used, or an unknown bearing name."""


class ConvergenceError(RuntimeError):
    """An iterative solve that did not converge.

    Attributes
    ----------
    iterations : int
        Iterations done before giving up.
    residual : ndarray or float
        Residual at the last iterate.
    estimate : ndarray or float
        The last iterate; never to be used as a result.
    """

    def __init__(self, where, *, iterations, residual, estimate, reason=""):
        self.where = where
        self.iterations = int(iterations)
        self.residual = residual
        self.estimate = estimate
        worst = np.nanmax(np.abs(np.atleast_1d(np.asarray(residual, dtype=float))))
        msg = f"{where}: no convergence after {self.iterations} iterations (|residual| = {worst:.3g})"
        if reason:
            msg += f": {reason}"
        super().__init__(msg)


class ValidityWarning(UserWarning):
    """An input outside the range on which a model or fit was derived; the result is extrapolated."""
