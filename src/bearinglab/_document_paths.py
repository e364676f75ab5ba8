"""Numbers inside a document, addressed by a path: what a sweep varies inside a shaft-system file.

A calculation's ``document`` field (a shaft system, a runout error set, a duty cycle) holds tables. A
sweep parameter that is not a field but a dotted path addresses one value inside such a document
(:func:`address`): ``supports.front.position`` is the ``position`` of the support named ``front`` of the
``[[supports]]`` array, ``sections.1.diameter`` (or ``sections[1].diameter``) the diameter of the second
section, ``supports.front.bearing_set.preload`` a key of an inline table, ``model.speed`` a key at the
top of the document held by the field ``model``. A step into an array of tables is the ``name`` of one
of its tables, or its index from 0; the first step may name the document field, and must where the
calculation has more than one. Each case's document is the given one with the addressed values
replaced (:func:`with_values`), as JSON text, which every document field reads as it reads TOML.

The value an address takes is read like the value it replaces (:func:`field_of`): a quantity with a unit
(``"100 mm"``: its kind found by :mod:`bearinglab.units`, shown in that unit), a whole or plain number, a
flag, or a text (a bearing's designation); a key the document does not give yet is read like the values
the sweep gives it.

Functions
---------
address      a parameter name -> (the document field, the path in it), or None
parse_text   a document's text (TOML, or JSON opening with ``{``) -> its tables
locate       the table that holds an address's last step, checked against the document
field_of     the :class:`~bearinglab.calculations.Field` that reads an address's values
with_values  a request whose addressed values are written into its documents (JSON text)
"""

from __future__ import annotations

import copy
import json
import re

from .errors import InputError

__all__ = ["address", "field_of", "locate", "parse_text", "with_values"]

_INDEX = re.compile(r"\[\s*(\d+)\s*\]")  # sections[1].diameter -> sections.1.diameter
_QUANTITY = re.compile(r"^\s*[-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?\s*(.*?)\s*$")


def address(calc, key):
    """The document field and the path a parameter name addresses, or None where it addresses none.

    Parameters
    ----------
    calc : bearinglab.calculations.Calculation
    key : str
        The parameter's name as the sweep file writes it (``supports.front.position``).

    Returns
    -------
    tuple of (str, tuple of str) or None
        The document field's name and the steps of the path in its document; None for a field of the
        calculation, a name without a dot, or a calculation without a document field.

    Examples
    --------
    >>> from bearinglab.calculations import CALCULATIONS
    >>> address(CALCULATIONS["shaft"], "supports[0].position")
    ('model', ('supports', '0', 'position'))
    >>> address(CALCULATIONS["shaft"], "model.speed"), address(CALCULATIONS["shaft"], "speed")
    (('model', ('speed',)), None)
    """
    documents = [f.name for f in calc.fields if f.kind == "document"]
    if not documents or key in {f.name for f in calc.fields} or "." not in _INDEX.sub(r".\1", key):
        return None
    steps = tuple(s.strip() for s in _INDEX.sub(r".\1", key).split("."))
    if not all(steps):
        raise InputError(f"{key}: an empty step in the path; write e.g. supports.front.position")
    if steps[0] in documents:
        return steps[0], steps[1:]
    if len(documents) > 1:
        raise InputError(f"{key}: name the document first ({', '.join(documents)}), e.g. {documents[0]}.{key}")
    return documents[0], steps


def parse_text(text, name):
    """A document's text -> its tables: JSON where it opens with ``{``, else TOML.

    Parameters
    ----------
    text : str
    name : str
        The field, for the message.

    Returns
    -------
    dict
    """
    import tomllib

    from ._bounds import parse_document

    if not isinstance(text, str):
        raise InputError(f"{name}: expected the text of a document, got {type(text).__name__}")
    try:
        doc = parse_document(text, name)
    except (ValueError, tomllib.TOMLDecodeError) as exc:
        raise InputError(f"{name}: not a JSON or TOML document ({exc})") from None
    if not isinstance(doc, dict):
        raise InputError(f"{name}: expected tables, got {type(doc).__name__}")
    return doc


def _where(steps):
    return ".".join(steps) or "the document"


def _step(node, step, key, done):
    """One step of a path: a key of a table, or a table of an array by its name or index."""
    if isinstance(node, dict):
        if step not in node:
            raise InputError(f"{key}: {_where(done)} has no {step!r} (it has {', '.join(map(str, node)) or 'nothing'})")
        return node[step]
    if isinstance(node, list):
        named = [i for i, item in enumerate(node) if isinstance(item, dict) and item.get("name") == step]
        if len(named) == 1:
            return node[named[0]]
        if len(named) > 1:
            raise InputError(f"{key}: {_where(done)} has {len(named)} tables named {step!r}; give the index from 0")
        if step.isdigit() and int(step) < len(node):
            return node[int(step)]
        if not node:
            raise InputError(f"{key}: {_where(done)} is empty")
        names = [str(item["name"]) for item in node if isinstance(item, dict) and isinstance(item.get("name"), str)]
        index = f"an index from 0 to {len(node) - 1}"
        raise InputError(f"{key}: {_where(done)} has no table named {step!r} "
                         + (f"(names: {', '.join(names)}; or {index})" if names else f"(give {index})"))
    raise InputError(f"{key}: {_where(done)} is a value, not a table")


def locate(document, path, key):
    """The table that holds the last step of ``path``, and that step.

    Parameters
    ----------
    document : dict
        The document's tables.
    path : tuple of str
        From :func:`address`.
    key : str
        The parameter's name, for the messages.

    Returns
    -------
    tuple of (dict, str)
        The table and the key the value goes to (present or not yet).

    Raises
    ------
    InputError
        A step the document does not hold, or a path that ends at a table or an array.
    """
    node = document
    for depth, step in enumerate(path[:-1]):
        node = _step(node, step, key, path[:depth])
    if isinstance(node, list):  # the last step picks a table of an array: a table, not a value
        _step(node, path[-1], key, path[:-1])
        raise InputError(f"{key}: addresses a whole table; address one value in it, e.g. {key}.position")
    if not isinstance(node, dict):
        raise InputError(f"{key}: {_where(path[:-1])} is a value, not a table")
    current = node.get(path[-1])
    if isinstance(current, (dict, list)):
        raise InputError(f"{key}: addresses {'a table' if isinstance(current, dict) else 'an array'}; "
                         f"address one value in it")
    return node, path[-1]


def _kind(text):
    """The quantity kind of :data:`bearinglab.units.KINDS` that reads ``text`` (the first), or None."""
    from .units import KINDS, parse_quantity

    for kind in KINDS:
        if kind == "dimensionless":
            continue
        try:
            parse_quantity(text, kind, "value")
        except InputError:
            continue
        return kind
    return None


def _sample(value):
    """One value of what a sweep gives (the last item of a list, range or comma list), to read its kind."""
    item = value[-1] if isinstance(value, list) and value else value
    if isinstance(item, str):
        parts = [p for p in re.split(r"[:,;]", item) if p.strip()]
        return parts[-1] if parts else item
    return item


def field_of(key, current, value):
    """The field that reads the values of an address: like the ``current`` value of the document.

    Parameters
    ----------
    key : str
        The parameter's name (the field's name, and its input column with the unit).
    current : object
        The document's value at the address, or None where it gives none (then ``value`` decides).
    value : object
        What the sweep file gives (a value, a list or a range).

    Returns
    -------
    bearinglab.calculations.Field
        A quantity kind in the unit ``current`` is written in (``length`` in ``mm``); ``int``, ``number``
        or ``flag``; ``text`` otherwise (a designation; a temperature, with its unit, whose offset units
        scale no column).

    Examples
    --------
    >>> f = field_of("supports.front.position", "100 mm", "60 mm:120 mm:10 mm")
    >>> f.kind, f.unit
    ('length', 'mm')
    >>> field_of("material.poisson_ratio", 0.3, [0.28, 0.3]).kind
    'number'
    """
    from .calculations import Field

    sample = current if current is not None else _sample(value)
    if isinstance(sample, bool):
        return Field(key, "flag", key)
    if isinstance(sample, int):
        return Field(key, "int", key)
    if isinstance(sample, float):
        return Field(key, "number", key)
    if isinstance(sample, str):
        m = _QUANTITY.match(sample)
        unit = m.group(1) if m else ""
        kind = _kind(sample) if unit else None
        if kind == "temperature":
            return Field(key, "text", key, unit=unit)
        if kind is not None:
            return Field(key, kind, key, unit=unit)
    return Field(key, "text", key)


def with_values(calc, request, parsed=None):
    """``request`` with the values of its addresses written into its documents.

    Parameters
    ----------
    calc : bearinglab.calculations.Calculation
    request : dict
        Field name or address -> value as the command line types it; each document field holds its text.
    parsed : dict, optional
        A cache: a document's text -> its tables (parsed once for the cases of a chunk).

    Returns
    -------
    dict
        The request with only the calculation's fields; a document with addresses is its JSON text.
    """
    names = {f.name for f in calc.fields}
    edits = {k: v for k, v in request.items() if k not in names}
    if not edits:
        return request
    out = {k: v for k, v in request.items() if k in names}
    cache = {} if parsed is None else parsed
    documents = {}
    for key, value in edits.items():
        field, path = address(calc, key) or (None, None)
        if field is None:
            raise InputError(f"{key}: not an input of {calc.name} and no address in its document")
        if field not in documents:
            text = out.get(field)
            if text not in cache:
                cache[text] = parse_text(text, field)
            documents[field] = copy.deepcopy(cache[text])
        table, last = locate(documents[field], path, key)
        table[last] = value.item() if hasattr(value, "item") else value
    for field, doc in documents.items():
        out[field] = json.dumps(doc, default=str)
    return out
