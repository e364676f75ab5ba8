"""The JSON API of the web calculator: one endpoint per calculation of :mod:`bearinglab.calculations`.

``GET /api/<endpoint>?name=value&...`` (shareable links) and ``POST /api/<endpoint>`` with a JSON body
take the calculation's fields by name; both answer with the document ``bearinglab <command> --json``
prints. The request is read and checked here, in the server (cheap), and computed in a worker
process (:mod:`bearinglab.web.workers`). Errors are one JSON object, ``{"detail", "parameter",
"error"}``, worded with the API's parameter names.

Endpoints
---------
ENDPOINTS     URL path -> calculation name (``/api/friction`` -> ``friction``)
query_values  the query parameters of a GET as the calculation's values (a repeated one is an error)
body_values   the JSON body of a POST as the calculation's values (a repeated key is an error, as in a query)
error_body    the JSON body of a failed call: ``{"detail", "parameter", "error"}``
web_error     a RequestError worded for the web: ``(status, body)``
model         the pydantic model of a calculation's fields (the OpenAPI schema of its body)
parameters    the OpenAPI query parameters of a calculation

Deprecated (removed in the next release): ApiResult, call, options, parameter_of, web_message.
"""

from __future__ import annotations

import re
import warnings
from functools import cache
from typing import NamedTuple

from .. import calculations
from ..calculations import CALCULATIONS, RequestError

__all__ = [
    "ENDPOINTS",
    "ApiResult",
    "body_values",
    "call",
    "error_body",
    "model",
    "options",
    "parameter_of",
    "parameters",
    "query_values",
    "web_error",
    "web_message",
]

#: URL path under /api -> calculation name.
ENDPOINTS = {
    "life": "life",
    "load-distribution": "load-distribution",
    "bearing-set": "bearing-set",
    "friction": "friction",
    "high-speed": "high-speed",
    "frequencies": "frequencies",
    "axial-angle": "axial-angle",
    "stand-load": "stand-load",
    "catalog": "catalog",
    "catalog/search": "catalog-search",
    "clearance": "clearance",
    "film": "film",
    "temperature": "temperature",
    "runout": "runout",
    "runout-monte-carlo": "runout-monte-carlo",
}
# a calculation registered later (e.g. by another model's work) gets its endpoint at its own name
ENDPOINTS.update({name: name for name in CALCULATIONS if name not in ENDPOINTS.values()})


def error_body(detail, parameter=None, error="input"):
    """The JSON body of a failed call.

    Parameters
    ----------
    detail : str
        One line, naming API parameters.
    parameter : str, optional
        The parameter at fault.
    error : str
        ``input``, ``convergence``, ``not-found``, ``limit`` (a size or time limit), ``busy`` or
        ``failed`` (a bug).

    Returns
    -------
    dict
        ``{"detail": ..., "parameter": ..., "error": ...}``.
    """
    return {"detail": detail, "parameter": parameter, "error": error}


def web_error(exc):
    """A RequestError (or a worker's error record) as the web says it: the status and the body.

    Parameters
    ----------
    exc : RequestError or dict
        The error, or the worker's record ``{"parameter", "template", "kind"}``.

    Returns
    -------
    tuple
        ``(422, error_body(...))``.
    """
    if isinstance(exc, dict):
        exc = calculations.RunFailure(exc["parameter"], None, exc["template"], exc.get("kind", "input"))
    detail = exc.worded(lambda name: name)
    kind = getattr(exc, "kind", "input")
    if "limit of" in exc.template or "at most" in (exc.valid or ""):
        kind = "limit"
    return 422, error_body(detail, exc.parameter, kind)


def query_values(endpoint, items):
    """The query parameters of a GET as the calculation's values.

    Parameters
    ----------
    endpoint : str
        A key of :data:`ENDPOINTS`.
    items : list of (str, str)
        The query's pairs, in order (a parameter given twice is an error, never its last value).

    Returns
    -------
    dict
    """
    values = {}
    for name, value in items:
        if name in values:
            raise RequestError(name, value, "one value",
                               "{name}: given more than once; give it once (a list is one value: "
                               "'1 kN, 2 kN')")
        values[name] = value
    return values


def body_values(endpoint, raw):
    """The JSON body of a POST as the calculation's values.

    Parameters
    ----------
    endpoint : str
        A key of :data:`ENDPOINTS`.
    raw : bytes
        The body.

    Returns
    -------
    dict
    """
    from .._bounds import RepeatedKey, parse_json
    from ..errors import InputError

    try:  # strictly: a key given twice is refused, as in a query; so is a deeply nested body
        values = parse_json(raw or b"{}", "the body")
    except RepeatedKey as exc:
        raise RequestError(exc.key, None, "one value",
                           "{name}: given more than once; give it once (a list is one value: '1 kN, 2 kN')") from None
    except InputError as exc:
        raise RequestError(None, None, "a JSON object of parameters", str(exc)) from None
    except (ValueError, UnicodeDecodeError) as exc:
        raise RequestError(None, None, "a JSON object", f"the body is not JSON ({exc})") from None
    if not isinstance(values, dict):
        raise RequestError(None, None, "a JSON object", "the body must be a JSON object of parameters")
    for name, value in values.items():
        if value is not None and not isinstance(value, (str, int, float, bool)):
            raise RequestError(name, value, "a string, number or true/false",
                               "{name}: expected a string, a number or true/false")
    return values


def _describe(field):
    unit = f" [{field.unit}]" if field.unit and field.unit != "-" else ""
    parts = [field.help + unit]
    if field.valid() and not field.valid().startswith("a ") and field.kind != "flag":
        parts.append(f"Valid: {field.valid()}.")
    if field.many:
        parts.append("A list ('1 kN, 2 kN') or a range ('1kN:5kN:1kN') is allowed.")
    if field.default is not None:
        parts.append(f"Default: {field.default}.")
    return " ".join(parts)


def _schema(field):
    if field.kind == "flag":
        out = {"type": "boolean"}
    elif field.kind == "int":
        out = {"type": "integer"}
    elif field.kind == "number":
        out = {"type": "number"}
    elif field.kind == "choice":
        out = {"type": "string", "enum": list(field.choices)}
    else:
        out = {"type": "string"}
    for key, value in (("minimum", field.minimum), ("maximum", field.maximum)):
        if value is not None and field.kind in ("int", "number"):
            if key == "minimum" and field.exclusive:
                out["exclusiveMinimum"] = value
            else:
                out[key] = value
    out["description"] = _describe(field)
    out["title"] = field.title
    extra = {"x-unit": field.unit or None, "x-kind": field.kind, "x-many": field.many}
    if field.minimum is not None or field.maximum is not None:
        extra["x-range"] = field.valid()
    out.update({k: v for k, v in extra.items() if v not in (None, "")})
    if field.default is not None:
        out["default"] = field.default
    return out


@cache
def model(name):
    """The pydantic model of calculation ``name``'s fields: the schema of its POST body.

    Parameters
    ----------
    name : str
        A key of :data:`bearinglab.calculations.CALCULATIONS`.

    Returns
    -------
    type
        A pydantic model; every field optional unless required, with its unit and range.
    """
    import pydantic

    types = {"flag": bool, "int": int | str, "number": float | str, "choice": str}
    fields = {}
    for f in CALCULATIONS[name].fields:
        annotation = types.get(f.kind, str)
        extra = {k: v for k, v in _schema(f).items() if k.startswith("x-")}
        info = pydantic.Field(
            ... if f.required else None, description=_describe(f), title=f.title,
            json_schema_extra=extra)
        fields[f.name] = (annotation if f.required else annotation | None, info)
    title = "".join(w.capitalize() for w in name.replace("-", " ").split()) + "Request"
    return pydantic.create_model(title, __config__=pydantic.ConfigDict(extra="forbid"), **fields)


def parameters(name):
    """The OpenAPI query parameters of calculation ``name``.

    Parameters
    ----------
    name : str
        A key of :data:`bearinglab.calculations.CALCULATIONS`.

    Returns
    -------
    list of dict
    """
    return [{"name": f.name, "in": "query", "required": f.required, "description": _describe(f),
             "schema": _schema(f)} for f in CALCULATIONS[name].fields]


# ----------------------------------------------------------------------------- deprecated (0.2)
# The names of the command-line shim this module was; they warn and are removed in the next release.
class ApiResult(NamedTuple):
    """The answer of :func:`call` (deprecated)."""

    status: int
    """HTTP status."""
    document: object
    """The document, or the error body."""


def _deprecated(name, instead):
    warnings.warn(f"bearinglab.web.api.{name} is deprecated; use {instead}", DeprecationWarning,
                  stacklevel=3)


def options(endpoint):
    """Deprecated: the parameters of ``endpoint`` -> (command-line option, is a flag).

    Parameters
    ----------
    endpoint : str
        A key of :data:`ENDPOINTS`.

    Returns
    -------
    dict
    """
    _deprecated("options", "bearinglab.calculations.CALCULATIONS[name].fields")
    name = ENDPOINTS.get(endpoint)
    fields = CALCULATIONS[name].fields if name else ()
    return {f.name: (f.cli_option, f.kind == "flag") for f in fields}


def call(endpoint, query):
    """Deprecated: run ``endpoint`` in this process (the server runs it in a worker process).

    Parameters
    ----------
    endpoint : str
        A key of :data:`ENDPOINTS`.
    query : mapping of str to str
        The parameters.

    Returns
    -------
    ApiResult
    """
    _deprecated("call", "bearinglab.calculations.parse and run, or the HTTP API")
    name = ENDPOINTS.get(endpoint)
    if name is None:
        return ApiResult(404, error_body(f"{endpoint}: no such endpoint", None, "not-found"))
    try:
        return ApiResult(200, calculations.run(calculations.parse(name, dict(query))))
    except RequestError as exc:
        return ApiResult(*web_error(exc))


def web_message(message, endpoint):
    """Deprecated: a command-line message with the options of ``endpoint`` as API parameters.

    Parameters
    ----------
    message : str
        The one-line message.
    endpoint : str
        A key of :data:`ENDPOINTS`.

    Returns
    -------
    str
    """
    _deprecated("web_message", "RequestError.worded")
    from ..calculations._failures import run_failure

    return web_error(run_failure(message, CALCULATIONS[ENDPOINTS[endpoint]]))[1]["detail"]


def parameter_of(message, known=()):
    """Deprecated: the parameter a command-line message names (``axial-load: ...`` -> ``axial_load``).

    Parameters
    ----------
    message : str
        The one-line message.
    known : collection of str
        The endpoint's parameters; a name not among them is not returned (unless empty).

    Returns
    -------
    str or None
    """
    _deprecated("parameter_of", "RequestError.parameter")
    for pattern in (re.compile(r"'?--([a-z][a-z0-9-]*)"), re.compile(r"^([a-z][a-z0-9-]*)(?::| must | needs )")):
        match = pattern.search(message)
        if match:
            name = match.group(1).replace("-", "_")
            if not known or name in known:
                return name
    return None
