"""A native calculation's errors as :class:`~.fields.RunFailure`, naming the calculation's fields.

The input checks the calculations share with the command line (:mod:`._inputs`, :mod:`._mounting`,
the physics) raise :class:`bearinglab.errors.InputError` with the project's message convention: the
message opens with the name of the input at fault (the field's name with dashes, ``oil-flow: ...``,
``density must be ...``) and names other inputs by their option (``--oil-flow``). :func:`failures`
turns such a message into a RunFailure whose template leaves those names open (``{name}``,
``{field:oil_flow}``), so that each boundary names the fields its own way; a message that opens with no
field's name names no field. A solve that does not converge is a RunFailure of kind ``convergence``
(or ``input`` where the input has no physical solution).

Functions
---------
failures   context manager: InputError / ConvergenceError inside -> RunFailure for a calculation
"""

from __future__ import annotations

import contextlib

from ..errors import ConvergenceError, InputError
from .fields import RequestError, RunFailure


def _dashed(field):
    return field.name.replace("_", "-")


def as_failure(calc, message, kind="input"):
    """``message`` (the convention above) as a RunFailure naming ``calc``'s fields."""
    fields = sorted(calc.fields, key=lambda f: -len(f.name))  # --oil-flow before --oil
    parameter = None
    for f in fields:
        for head in (_dashed(f), f.name):  # the option's spelling, or the library parameter's
            if message.startswith(head) and message[len(head):len(head) + 1] in (":", " ", ""):
                parameter, message = f.name, "{name}" + message[len(head):]
                break
        if parameter is not None:
            break
    for f in fields:
        message = message.replace("--" + _dashed(f), "{field:" + f.name + "}")
    return RunFailure(parameter, None, message, kind)


@contextlib.contextmanager
def failures(calc):
    """Inside: an InputError or ConvergenceError becomes a RunFailure of ``calc`` (a RequestError,
    already naming its field, passes unchanged)."""
    try:
        yield
    except RequestError:
        raise
    except ConvergenceError as exc:
        raise as_failure(calc, exc.summary, "input" if exc.physical else "convergence") from None
    except InputError as exc:
        raise as_failure(calc, str(exc)) from None
