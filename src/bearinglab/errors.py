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
    reason : str
        The physical reason, where one is known.
    physical : bool
        True when the equations have no physical solution for these inputs (a ball leaving a raceway,
        an angle leaving its range): the input is impossible, not the solver weak.
    summary : str
        The message without the name of the internal function (for the command line). With ``physical``
        it is the physical reason ("no physical solution: ..."), without the solver's iteration count,
        which only the full message (``str(exc)``) keeps.
    """

    def __init__(self, where, *, iterations, residual, estimate, reason="", physical=False):
        self.where = where
        self.iterations = int(iterations)
        self.residual = residual
        self.estimate = estimate
        self.reason = reason
        self.physical = bool(physical)
        import numpy as np  # here, not at the top: the command line imports this module before numpy

        res = np.abs(np.atleast_1d(np.asarray(residual, dtype=float)))
        res = res[np.isfinite(res)]
        solver = f"no convergence after {self.iterations} iterations"
        if res.size:
            solver += f" (|residual| = {res.max():.3g})"
        if self.physical:  # the input is impossible: the reason is the message, the solver's state is not
            self.summary = f"no physical solution: {reason}" if reason else "no physical solution for these inputs"
        elif reason.startswith("no convergence"):  # the reason says it already: once is enough
            self.summary = f"{reason} ({solver.removeprefix('no convergence ')})"
        else:
            self.summary = f"{solver}: {reason}" if reason else solver
        super().__init__(f"{where}: {self.summary}" + (f" ({solver})" if self.physical else ""))


class ValidityWarning(UserWarning):
    """An input outside the range on which a model or fit was derived; the result is extrapolated."""
