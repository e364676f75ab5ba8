"""A request's inputs inside a calculation's document: the text as given, the provenance notes.

given_text   the value of a field as the user wrote it
with_notes   a document with the bearing's provenance notes after its warnings (as the command line adds
             them to every document it prints)

The errors of a document's computation become RunFailures naming their field through
:func:`._failures.failures`.
"""

from __future__ import annotations

__all__ = ["given_text", "with_notes"]


def given_text(parsed, name):
    """The value of field ``name`` as the user wrote it (stripped text), or None when not given."""
    value = parsed.given.get(name)
    return None if value is None else str(value).strip()


def with_notes(doc, notes):
    """``doc`` with the bearing's provenance notes after its own warnings, as the command line adds
    them to every document it prints (a list of documents: in each)."""
    if isinstance(doc, list):
        return [with_notes(d, notes) for d in doc]
    given = list(doc.get("warnings") or [])
    return {**doc, "warnings": given + [n for n in dict.fromkeys(notes) if n not in given]}
