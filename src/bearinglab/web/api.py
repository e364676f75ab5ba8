"""The JSON API of the web calculator: each endpoint runs one command of the command line.

``GET /api/<endpoint>?name=value&...`` maps every query parameter to the command's option of the same
name (underscores become dashes: ``axial_load`` -> ``--axial-load``), runs the command in-process with
``--json`` (:func:`bearinglab.cli.run_json`) and answers with the document it prints. Only the options
that compute are reachable: no option that reads or writes a file, none that starts a cluster.

Endpoints
---------
ENDPOINTS     endpoint name -> the command's words (``friction`` -> ``friction torque``; ``film``, ``temperature``)
options       the options an endpoint takes, by query-parameter name
call          run an endpoint with query parameters -> ApiResult (status, document or error)
error_body    the JSON body of a failed call: ``{"detail", "parameter", "error"}``
parameter_of  the query parameter an error message names, if any
web_message   a command-line message as the web says it: query parameters, not options
"""

from __future__ import annotations

import re
from functools import cache
from typing import NamedTuple

import typer

from .. import cli

__all__ = [
    "ENDPOINTS",
    "ApiResult",
    "call",
    "error_body",
    "options",
    "parameter_of",
    "web_message",
]

#: Endpoint name -> the words of the command it runs.
ENDPOINTS = {
    "high-speed": ("high-speed",),
    "axial-angle": ("axial-angle",),
    "frequencies": ("frequencies",),
    "load-distribution": ("load-distribution",),
    "life": ("life",),
    "friction": ("friction", "torque"),
    "clearance": ("clearance",),
    "film": ("film",),
    "temperature": ("temperature",),
}

# not reachable from the web: files (read or written), clusters, output format, help
_HIDDEN = {
    "json",
    "help",
    "csv",
    "plot",
    "out",
    "catalog",
    "bearing-file",
    "executor",
    "workers",
    "chunk-size",
    "version",
}
_TRUE, _FALSE = {"true", "1", "yes", "on"}, {"false", "0", "no", "off", ""}


class ApiResult(NamedTuple):
    """The answer of :func:`call`."""

    status: int
    """HTTP status: 200, 404 (no such command in this version), 422 (bad input, no convergence)."""
    document: object
    """The command's JSON document (status 200) or the error body (:func:`error_body`)."""


@cache
def _command(words):
    """The click command for ``words``, or None when this version has no such command."""
    command = typer.main.get_command(cli.app)
    for word in words:
        command = getattr(command, "commands", {}).get(word)
        if command is None:
            return None
    return command


def _is_file(param):
    """Whether an option takes a file (click's path type; typer >= 0.20 keeps the annotation instead)."""
    click_type = getattr(getattr(param, "type", None), "name", "")
    annotation = getattr(getattr(param, "type_descriptor", None), "annotation", "")
    return click_type == "path" or "Path" in str(annotation)


def _reachable(endpoint):
    """The click parameters of ``endpoint`` reachable from the web, by query-parameter name."""
    command = _command(ENDPOINTS[endpoint])
    out = {}
    for param in getattr(command, "params", ()):
        longs = [o for o in getattr(param, "opts", ()) if o.startswith("--")]
        if not longs or longs[0][2:] in _HIDDEN or _is_file(param):
            continue
        out[longs[0][2:].replace("-", "_")] = param
    return out


@cache
def options(endpoint):
    """The options of ``endpoint`` reachable from the web: query-parameter name -> (option, is_flag).

    Parameters
    ----------
    endpoint : str
        A key of :data:`ENDPOINTS`.

    Returns
    -------
    dict
        ``{"axial_load": ("--axial-load", False), ...}``; empty when the command does not exist.
    """
    return {
        name: (
            next(o for o in param.opts if o.startswith("--")),
            bool(getattr(param, "is_flag", False)),
        )
        for name, param in _reachable(endpoint).items()
    }


@cache
def _spellings(endpoint):
    """Every way the command line spells a reachable option (``--axial-load``, ``-F``, ``--no-mask``)
    -> its query-parameter name, from the command's own option definitions."""
    return {
        spelling: name
        for name, param in _reachable(endpoint).items()
        for spelling in (*param.opts, *getattr(param, "secondary_opts", ()))
    }


_QUOTED_OPTIONS = re.compile(r"'-[^'\s]+'(?: / '-[^'\s]+')*")  # click: '--axial-load' / '-F'
_BARE_OPTION = re.compile(r"(?<![\w-])--[a-z][a-z0-9-]*(?![\w-])")  # a library message: --viscosity
_LEADING = re.compile(r"^([a-z][a-z0-9-]*)(?=:| must | needs )")  # axial-load: ..., axial-load must


def web_message(message, endpoint):
    """A command-line message as the web says it: each option of ``endpoint`` the message names
    becomes its query parameter.

    ``Missing option '--axial-load' / '-F'.`` -> ``Missing parameter 'axial_load'.``;
    ``give --viscosity, or --oil VG68 with --viscosity-100`` -> ``give viscosity, or oil VG68 with
    viscosity_100``; ``axial-load: '2 m' is a length`` -> ``axial_load: '2 m' is a length``. Options
    the web cannot reach (files, clusters) are left as the command line spells them.

    Parameters
    ----------
    message : str
        The one-line message of the command line (without its ``bearinglab: error:`` prefix).
    endpoint : str
        A key of :data:`ENDPOINTS`: the command whose options the message may name.

    Returns
    -------
    str
    """
    spellings = _spellings(endpoint)

    def quoted(match):
        names = {spellings.get(o) for o in re.findall(r"'(-[^'\s]+)'", match.group(0))}
        return f"'{names.pop()}'" if len(names) == 1 and None not in names else match.group(0)

    def leading(match):
        return spellings.get("--" + match.group(1), match.group(1))

    text = _QUOTED_OPTIONS.sub(quoted, message)
    text = _BARE_OPTION.sub(lambda m: spellings.get(m.group(0), m.group(0)), text)
    text = _LEADING.sub(leading, text, count=1)
    return text.replace("Missing option '", "Missing parameter '", 1)


def error_body(detail, parameter=None, error="input"):
    """The JSON body of a failed call.

    Parameters
    ----------
    detail : str
        The one-line message (as the command line prints it, without its prefix).
    parameter : str, optional
        The query parameter the message names.
    error : str
        ``input`` (bad input), ``convergence`` (the solve did not converge), ``not-found`` or
        ``failed``.

    Returns
    -------
    dict
        ``{"detail": ..., "parameter": ..., "error": ...}``.
    """
    return {"detail": detail, "parameter": parameter, "error": error}


_NAMED = (
    re.compile(r"'?--([a-z][a-z0-9-]*)"),
    re.compile(r"^([a-z][a-z0-9-]*)(?::| must | needs )"),
)


def parameter_of(message, known=()):
    """The query parameter a command-line error message names (``axial-load: ...`` -> ``axial_load``).

    Parameters
    ----------
    message : str
        The one-line error message.
    known : collection of str
        The endpoint's parameters; a name not among them is not returned (unless ``known`` is empty).

    Returns
    -------
    str or None
    """
    for pattern in _NAMED:
        match = pattern.search(message)
        if match:
            name = match.group(1).replace("-", "_")
            if not known or name in known:
                return name
    return None


def call(endpoint, query):
    """Run ``endpoint`` with the query parameters ``query`` as its command would run with ``--json``.

    Parameters
    ----------
    endpoint : str
        A key of :data:`ENDPOINTS`.
    query : mapping of str to str
        Query parameters (names with underscores), values as on the command line (``"20 kN"``).

    Returns
    -------
    ApiResult
        200 and the command's document; 422 and :func:`error_body` for bad input (unknown parameter,
        a value the command rejects) or a solve that did not converge; 404 when this version has no
        such command; 500 if the command failed otherwise.
    """
    known = options(endpoint)
    if not known:
        return ApiResult(
            404, error_body(f"{endpoint}: not available in this version", None, "not-found")
        )
    unknown = sorted(set(query) - set(known))
    if unknown:
        return ApiResult(
            422,
            error_body(
                f"{unknown[0]}: unknown parameter of /api/{endpoint}; valid: "
                f"{', '.join(sorted(known))}",
                unknown[0],
            ),
        )
    argv = list(ENDPOINTS[endpoint])
    for name, value in query.items():
        option, flag = known[name]
        if not flag:
            argv.append(
                f"{option}={value}"
            )  # '=' keeps a value such as '-5 kN' from reading as an option
        elif value.strip().lower() in _TRUE:
            argv.append(option)
        elif value.strip().lower() not in _FALSE:
            return ApiResult(
                422, error_body(f"{name}: expected true or false, got {value!r}", name)
            )
    try:
        run = cli.run_json(argv)
    except ValueError as exc:  # a library check the command does not turn into its one-line error
        run = cli.JsonRun(2, None, str(exc))
    except Exception as exc:  # noqa: BLE001 -- an answer names the failure, never shows a traceback
        run = cli.JsonRun(1, None, f"{type(exc).__name__}: {exc}")
    if run.exit_code == 0:
        return ApiResult(200, run.document)
    detail = web_message(run.error, endpoint)
    if run.exit_code not in (2, 3):
        return ApiResult(500, error_body(detail, None, "failed"))
    kind = "convergence" if run.exit_code == 3 else "input"
    return ApiResult(422, error_body(detail, parameter_of(run.error, known), kind))
