"""What the documents of frequencies, stand-load, axial-angle, high-speed and friction share: the
inputs of a request as given, the bearing.

text         a field's value as the user wrote it (a number from a JSON body with the field's unit)
value        a field's checked (or typed) value: whole numbers, numbers, flags, choices
notes_in     a document with the bearing's provenance notes after its own warnings (only where there are
             notes, as the command line's ``emit_json`` adds them)
bearing_of   the bearing of a request (the ``bearing`` field and the inline geometry)

The readers of the inputs themselves (``resolve_bearing``, ``inputs_echo``, ``parse_speeds`` ...) are
:mod:`._inputs`, re-exported here for the documents that import this module; their errors become
RunFailures naming the field through :func:`._failures.failures`.
"""

from __future__ import annotations

from ._inputs import (  # noqa: F401 -- the documents read their inputs through this module
    choice,
    inputs_echo,
    lubricant_viscosity,
    parse_length,
    parse_speed,
    parse_speeds,
    parse_viscosity,
    resolve_bearing,
    speed_size,
)

__all__: list[str] = []  # private to the calculations


def text(parsed, name, default=None):
    """The value of field ``name`` as the user wrote it (a number from a JSON body with the field's
    unit), or ``default`` when it was not given."""
    if name not in parsed.given:
        return default
    value = parsed.given[name]
    if isinstance(value, str):
        return value.strip()
    unit = parsed.calculation.field(name).unit
    return f"{value} {unit}" if unit and unit != "-" else str(value)


def value(parsed, name, default=None):
    """The checked value of a whole-number, number, flag or choice field, or ``default``."""
    return parsed.values.get(name, default)


def notes_in(doc, bearing):
    """The document with the bearing's provenance notes after its own warnings, as the command line's
    ``emit_json`` adds them."""
    from .. import catalog

    notes = list(dict.fromkeys(catalog.provenance_notes(bearing)))
    if not notes:  # emit_json adds no key of its own then
        return doc
    own = list(doc.get("warnings") or [])
    doc["warnings"] = own + [n for n in notes if n not in own]
    return doc


def bearing_of(parsed, *, bearing_file=None, catalog=None):
    """The bearing of a request: the ``bearing`` field, a bearing file or catalog file (command line
    only), and the inline geometry fields, by :func:`resolve_bearing`."""
    return resolve_bearing(
        text(parsed, "bearing"), bearing_file, catalog, value(parsed, "balls"),
        text(parsed, "ball_diameter"), text(parsed, "pitch_diameter"), text(parsed, "inner_groove_radius"),
        text(parsed, "outer_groove_radius"), value(parsed, "inner_conformity"),
        value(parsed, "outer_conformity"), text(parsed, "contact_angle"), text(parsed, "radial_clearance"),
        text(parsed, "ball_material"))


def request(name, options):
    """The command line's request for calculation ``name``: its options as typed (name -> value; None:
    not given; names that are no field, such as files and ``json_out``, are left out), not checked
    against the fields (as :func:`bearinglab.calculations.parse` with ``check=False``): the document
    checks them by the command line's own rules and limits (:mod:`bearinglab._bounds`)."""
    from . import CALCULATIONS, Parsed

    calc = CALCULATIONS[name]
    names = {f.name for f in calc.fields}
    given = {k: v for k, v in options.items() if v is not None and k in names}
    # as parse(check=False), but an empty text stays given: '--series ""' is an error, not 'no series'
    return Parsed(calc, given, dict(given), 1)
