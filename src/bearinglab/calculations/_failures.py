"""A calculation's errors as :class:`~.fields.RunFailure`, naming its fields: the one mapping.

The input checks the calculations share with the command line (:mod:`._inputs`, :mod:`._mounting`,
the physics) raise :class:`bearinglab.errors.InputError` with the project's message convention: the
message opens with the name of the input at fault (the field's name with dashes, ``oil-flow: ...``,
``density must be ...``; a library parameter, ``n_balls``, where the user gave the field that sets it)
and names other inputs by their option (``--oil-flow``; click's usage errors quote them, ``'--speed' /
'-n'``). :func:`run_failure` turns such a message into a RunFailure whose template leaves those names
open (``{name}``, ``{field:oil_flow}``), so that each boundary names the fields its own way: the
command line as its options (:func:`bearinglab.cli._common.request_message`), the API as its
parameters, the page as its labels. A solve that does not converge is a RunFailure of kind
``convergence`` (or ``input`` where the input has no physical solution).

Functions
---------
run_failure   an InputError, ConvergenceError or message met while computing a request -> RunFailure
failures      context manager: the InputErrors and ConvergenceErrors of its block as such RunFailures
"""

from __future__ import annotations

import contextlib
import re

from ..errors import ConvergenceError, InputError
from .fields import RequestError, RunFailure

__all__ = ["failures", "run_failure"]

#: library parameter names -> the field that gives them, where the two differ
_FIELD_OF = {"n_balls": "balls", "kinematic_viscosity": "viscosity"}
# an option named in a message: '--axial-load' / '-A' / '-F' as click quotes it, or --axial-load
_OPTION = re.compile(r"'(--[a-z][a-z0-9-]*)'(?: / '-[^'\s]+')*|(?<![\w-])(--[a-z][a-z0-9-]*)")


def _head(message, fields, given):
    """The field the message opens with, and the rest of the message after its name; (None, message)
    where it opens with none. A name with underscores (a library parameter, ``pitch_diameter of 'X'``)
    counts only for a field the request gives (else it is a field of a bearing, not an input)."""
    names = {}
    for name in fields:
        names[name.replace("_", "-")] = name
        if given is None or name in given:
            names.setdefault(name, name)
    for library, name in _FIELD_OF.items():
        if name in fields and (given is None or name in given):
            names[library] = name
    for spelled in sorted(names, key=len, reverse=True):  # 'outer-speed' before 'speed'
        if message.startswith(spelled) and message[len(spelled):len(spelled) + 1] in (":", " ", ""):
            return names[spelled], message[len(spelled):]
    return None, message


def run_failure(error, calc, given=None, *, field=None, kind="input", options=True):
    """An error met while computing a request of ``calc``, as a RunFailure naming the field it is about.

    Parameters
    ----------
    error : InputError, ConvergenceError or str
        The error (a RequestError is returned as it is), or its one-line message.
    calc : Calculation
        The calculation whose fields the message may name.
    given : mapping, optional
        The fields the request gives (``Parsed.given``); a library parameter's name (with
        underscores) names a field only when the request gives it. None: any field.
    field : str, optional
        The field a message that opens with no field's name is about (default: the request).
    kind : {"input", "convergence"}
        For a message; a ConvergenceError is ``input`` where the input has no physical solution.
    options : bool
        Open the options the message names (``--oil-flow`` -> ``{field:oil_flow}``). False keeps them as
        written: the documents of frequencies, stand-load, axial-angle, high-speed and friction, whose
        messages every boundary shows in the command line's words (tests/calculations/
        test_native_friction.py holds that wording).

    Returns
    -------
    RunFailure
        ``parameter`` the field at fault (the one the message opens with, else ``field``, else the first
        option a usage error quotes, else None), ``template`` the message with ``{name}`` where it opens
        with the field and ``{field:...}`` for the fields it names as options.

    Examples
    --------
    >>> from bearinglab.calculations import CALCULATIONS
    >>> f = run_failure(InputError("oil-flow must be >= 0, got -1; or give --oil-inlet-temperature"),
    ...                 CALCULATIONS["temperature"])
    >>> f.parameter, f.template
    ('oil_flow', '{name} must be >= 0, got -1; or give {field:oil_inlet_temperature}')
    >>> f.worded(lambda name: "--" + name.replace("_", "-"))
    '--oil-flow must be >= 0, got -1; or give --oil-inlet-temperature'
    """
    if isinstance(error, RequestError):
        return error
    if isinstance(error, ConvergenceError):
        message, kind = error.summary, "input" if error.physical else "convergence"
    else:
        message = str(error)
    fields = {f.name: f for f in calc.fields}
    by_option = {f.cli_option: f.name for f in fields.values() if f.cli_option.startswith("--")}
    by_option.update({"--" + name.replace("_", "-"): name for name in fields})
    parameter, rest = _head(message, fields, given)
    if parameter is not None:
        template = "{name}" + rest
    elif field is not None:
        parameter, template = field, "{name}: " + message
    else:
        template = message
    quoted = []

    def named(match):
        option = match.group(1) or match.group(2)
        name = by_option.get(option)
        if name is None:
            return match.group(0)
        if match.group(1):
            quoted.append(name)
        return "{field:" + name + "}"

    if options:
        template = _OPTION.sub(named, template)
    if parameter is None and quoted:  # click's usage error: "Invalid value for '--speed': ..."
        parameter = quoted[0]
        template = template.replace("Missing option ", "Missing ")
    value = None if given is None or parameter is None else given.get(parameter)
    return RunFailure(parameter, value, template, kind)


@contextlib.contextmanager
def failures(request, field=None, *, options=True):
    """Inside: an InputError or ConvergenceError becomes a RunFailure (:func:`run_failure`) of the
    ``request`` (a Parsed request, or a Calculation); a RequestError, already naming its field, passes
    unchanged. ``field``: the field a message that names none is about; ``options``: as
    :func:`run_failure`."""
    calc = getattr(request, "calculation", request)
    given = getattr(request, "given", None)
    try:
        yield
    except RequestError:
        raise
    except (InputError, ConvergenceError) as exc:
        raise run_failure(exc, calc, given, field=field, options=options) from None
