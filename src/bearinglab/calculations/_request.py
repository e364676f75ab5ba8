"""A request's inputs inside a calculation's document: the text as given, failures naming the field.

given_text   the value of a field as the user wrote it
failure      an InputError (worded by :mod:`._inputs`, :mod:`._mounting`) -> a RunFailure naming its field
reading      context manager: the InputErrors of its block as such RunFailures
with_notes   a document with the bearing's provenance notes after its warnings (as the command line adds
             them to every document it prints)
"""

from __future__ import annotations

from ..errors import InputError

__all__ = ["failure", "given_text", "reading", "with_notes"]

#: library parameter names -> the field that gives them, where the two differ (as the command line's)
_FIELD_OF = {"n_balls": "balls", "kinematic_viscosity": "viscosity"}


def given_text(parsed, name):
    """The value of field ``name`` as the user wrote it (stripped text), or None when not given."""
    value = parsed.given.get(name)
    return None if value is None else str(value).strip()


def failure(exc, parsed, field=None):
    """An InputError met while computing ``parsed``, as a RunFailure naming the field it is about.

    The messages of :mod:`._inputs` and :mod:`._mounting` open with the input's name (``radial-load:
    ...``, ``speed must be ...``) and name the other inputs with their dashes (``give --fx or
    --radial-load``): those become ``{name}`` and ``{field:...}``, which each boundary words its own
    way. A message that names no field of the calculation is about ``field`` where given, else about
    the request as a whole.
    """
    from .fields import RequestError, RunFailure

    if isinstance(exc, RequestError):
        return exc
    message = str(exc)
    fields = {f.name: f for f in parsed.calculation.fields}
    head = message.split(":", 1)[0].split(" ", 1)[0]
    key = head.replace("-", "_")
    if key in _FIELD_OF and _FIELD_OF[key] in parsed.given:
        key = _FIELD_OF[key]
    if key in fields and ("_" not in head or key in parsed.given):  # pitch_diameter of 'X' is not known:
        parameter, template = key, "{name}" + message[len(head):]  # a bearing's field, not the input
    elif field is not None:
        parameter, template = field, "{name}: " + message
    else:
        return RunFailure(None, None, message)
    for f in sorted(fields.values(), key=lambda f: -len(f.cli_option)):  # --viscosity-index first
        if f.cli_option.startswith("--"):
            template = template.replace(f.cli_option, "{field:" + f.name + "}")
    return RunFailure(parameter, parsed.given.get(parameter), template)


class reading:
    """Turn the InputErrors raised in its block into RunFailures naming their field (:func:`failure`)."""

    def __init__(self, parsed, field=None):
        self.parsed, self.field = parsed, field

    def __enter__(self):
        return self

    def __exit__(self, kind, exc, tb):
        if exc is not None and isinstance(exc, InputError):
            raise failure(exc, self.parsed, self.field) from None
        return False


def with_notes(doc, notes):
    """``doc`` with the bearing's provenance notes after its own warnings, as the command line adds
    them to every document it prints (a list of documents: in each)."""
    if isinstance(doc, list):
        return [with_notes(d, notes) for d in doc]
    given = list(doc.get("warnings") or [])
    return {**doc, "warnings": given + [n for n in dict.fromkeys(notes) if n not in given]}
