"""The inputs of a calculation, declared once: what each field is, how it is read and checked.

A :class:`Field` says what a boundary needs to show, read and check one input: its name, the quantity
kind and the unit it is shown in, the valid range, the default, the help text, its label on the page,
and whether it may be a list or a range. :func:`parse_field` reads a value as a user wrote it with
:mod:`bearinglab.units` and checks it once; a bad value raises :class:`RequestError`, which holds the
field, the value and the valid range so that each boundary words it its own way (``--axial-load`` on
the command line, *Axial load* on the page, ``axial_load`` in the API).

Fields
------
Field           one input of a calculation
RequestError    a bad input: field, value, valid range, and the message with the name left open
RunFailure      a run that failed on its input (exit 2) or did not converge (exit 3), naming its field
parse_field     one value as written -> its checked value (SI floats, an int, a choice, a flag, text)
count_values    how many values a list or range holds, without building it
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from ..errors import InputError

__all__ = ["Field", "RequestError", "RunFailure", "count_values", "parse_field"]

#: kinds that are not quantities of :data:`bearinglab.units.KINDS`
_PLAIN = ("int", "number", "choice", "flag", "text", "document")
_TRUE, _FALSE = {"true", "1", "yes", "on"}, {"false", "0", "no", "off"}
# SI value -> shown value, per display unit (the unit a field is shown and bounded in)
_SCALE = {
    "N": 1.0, "kN": 1e3, "mm": 1e-3, "um": 1e-6, "deg": math.pi / 180.0, "rpm": 2.0 * math.pi / 60.0,
    "N*mm": 1e-3, "cSt": 1e-6, "GPa": 1e9, "degC": 1.0, "%": 1.0, "-": 1.0, "": 1.0, "mrad": 1e-3,
    "l/min": 1e-3 / 60.0,
}


@dataclass(frozen=True)
class Field:
    """One input of a calculation.

    ``minimum`` and ``maximum`` are in the display ``unit`` (``mm``, ``kN``); ``exclusive`` makes
    the minimum strict (> rather than >=). ``many`` allows a list or a range (``2kN:20kN:2kN``),
    whose values multiply into cases. ``group`` is the heading the field is shown under (the help
    panel of the command line, :data:`bearinglab.calculations.registry.GROUPS`).

    The command line's option is built from the field (:mod:`bearinglab.cli._options`): ``option`` is
    its spelling where it is not ``--`` and the name with dashes (a spelling without dashes, ``NAME``,
    is a positional argument), ``aliases`` its short spellings (``-n``); ``cli=False`` leaves the
    field off the command line (an input of the page alone, such as its picker's query). The help
    names another field of the same calculation between backquotes (as Markdown code: the API's
    descriptions are CommonMark): the command line writes it as that field's option
    (``--temperature``), the API and the page as it stands. ``example`` is a small valid value of a
    ``document`` field (its text), which the registry-driven fuzz test and the API's schema show.
    """

    name: str
    kind: str
    help: str
    label: str = ""
    unit: str = ""
    default: object = None
    required: bool = False
    minimum: float | None = None
    maximum: float | None = None
    exclusive: bool = False
    choices: tuple = ()
    many: bool = False
    group: str = ""
    option: str = ""
    aliases: tuple = ()
    cli: bool = True
    example: str = ""

    @property
    def cli_option(self):
        """The command line's option: ``--axial-load``."""
        return self.option or "--" + self.name.replace("_", "-")

    @property
    def title(self):
        """The label on the page (the name in words when none is given)."""
        return self.label or self.name.replace("_", " ").capitalize()

    def valid(self):
        """The valid values in words: ``> 0 kN``, ``1 ... 50``, ``one of newton, angle-iteration``."""
        if self.choices:
            return "one of " + ", ".join(self.choices)
        unit = f" {self.unit}" if self.unit and self.unit != "-" else ""
        low, high = self.minimum, self.maximum
        if low is not None and high is not None:
            return f"{'>' if self.exclusive else ''}{low:g} ... {high:g}{unit}"
        if low is not None:
            return f"{'>' if self.exclusive else '>='} {low:g}{unit}"
        if high is not None:
            return f"<= {high:g}{unit}"
        if self.kind == "flag":
            return "true or false"
        return {"text": "text", "document": "a JSON or TOML document"}.get(self.kind, f"a {self.kind}")


class RequestError(InputError):
    """A bad input of a calculation, named as each boundary names it.

    Attributes
    ----------
    parameter : str or None
        The field's name (``axial_load``); None when the request as a whole is at fault.
    value : object
        The value given.
    valid : str
        The valid values in words (``>= 1 ... 50``), or '' where no range applies.
    template : str
        The message with ``{name}`` where the field's name goes.
    """

    def __init__(self, parameter, value, valid, template):
        self.parameter, self.value, self.valid, self.template = parameter, value, valid, template
        super().__init__(self.worded(lambda name: name))

    def worded(self, name_of):
        """The message with each field named by ``name_of(field name)`` (an option, a label ...):
        ``{name}`` is the field at fault, ``{field:NAME}`` another field the message names."""
        text = self.template.replace("{name}", name_of(self.parameter) if self.parameter else "request")
        return _OTHER.sub(lambda m: name_of(m.group(1)), text)


class RunFailure(RequestError):
    """A calculation that failed on its input (``kind="input"``) or did not converge
    (``kind="convergence"``); the message names fields as ``{name}`` placeholders."""

    def __init__(self, parameter, value, template, kind="input"):
        self.kind = kind
        super().__init__(parameter, value, "", template)


_OTHER = re.compile(r"\{field:([a-z0-9_]+)\}")
_MALFORMED = re.compile(r"[0-9]*\.[0-9]*\.[0-9]")
_RANGE = re.compile(r"^([^:]+):([^:]+):([^:]+)$")
# a number as a field of kind "number" or "int" takes it: ASCII digits, one sign, no grouping, no words
# (Python's float() and int() read '٥', '1_000', 'nan' and 'infinity')
_NUMBER = re.compile(r"^\s*[-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?\s*$", re.ASCII)
_INTEGER = re.compile(r"^\s*[-+]?[0-9]+\s*$", re.ASCII)
_LONGEST_NUMBER = 40  # characters of a number field's text: more is no number a user typed


def count_values(field, text):
    """How many values ``text`` holds for ``field`` (a range is counted, not built).

    Parameters
    ----------
    field : Field
        A field with ``many``.
    text : str
        One value, a list ``a, b, c UNIT`` or a range ``start:stop:step``.

    Returns
    -------
    int

    Raises
    ------
    RequestError
        A range whose ends do not read, whose step is not > 0, or whose count is not finite
        (``0 kN:1e300 kN:1e-300 kN``: computed without overflow, never as ``floor(inf)``).
    """
    from ..units import _NUMBER_TEXT, parse_values

    text = str(text).strip()
    m = _RANGE.match(text)
    if not m:
        sep = ";" if ";" in text else ","
        return len([s for s in text.split(sep) if s.strip()])
    unit = re.sub(rf"^\s*{_NUMBER_TEXT}", "", m.group(3), flags=re.ASCII).strip()
    ends = []
    for part in m.groups():
        part = part.strip()
        if unit and re.fullmatch(_NUMBER_TEXT, part, flags=re.ASCII):
            part = f"{part} {unit}"
        try:
            ends.append(float(parse_values(part, field.kind, field.name)[0]))
        except RequestError:
            raise
        except InputError as exc:
            raise _named(field, text, str(exc)) from None
    start, stop, step = ends
    if not (step > 0 and stop >= start):
        raise RequestError(field.name, text, "start:stop:step with step > 0 and stop >= start",
                           f"{{name}}: range {text!r} needs step > 0 and stop >= start")
    n = (stop - start) / step
    if not math.isfinite(n):  # 1e303 / 1e-297: the count overflows a float
        raise RequestError(field.name, text, "a range of finitely many values",
                           f"{{name}}: range {text!r} holds too many values to count (its span over its "
                           f"step overflows); give a larger step or a shorter range")
    return math.floor(n * (1 + 1e-12) + 1e-9) + 1


def _named(field, value, message):
    """An InputError's message (which opens with the field's name) as a RequestError of ``field``."""
    if message.startswith(field.name):
        message = "{name}" + message[len(field.name):]
    return RequestError(field.name, value, field.valid(), message)


def _bounded(field, shown, text):
    """Check the value ``shown`` (in the field's display unit) against the field's range."""
    low, high = field.minimum, field.maximum
    bad = not math.isfinite(shown)
    if low is not None:
        bad |= shown <= low if field.exclusive else shown < low
    if high is not None:
        bad |= shown > high
    if bad:
        unit = f" {field.unit}" if field.unit and field.unit != "-" else ""
        raise RequestError(field.name, text, field.valid(),
                           f"{{name}} must be {field.valid()}, got {shown:g}{unit}")


def parse_field(field, value, *, limit=None):
    """Read and check one value of ``field`` as a user wrote it.

    Parameters
    ----------
    field : Field
        The field.
    value : str, int, float or bool
        The value as given (text from a form or a query, a number or a flag from a JSON body).
    limit : int, optional
        The most values a list or range may hold.

    Returns
    -------
    object
        A quantity in SI (a float; a numpy array for a field with ``many``), an int, a float, a
        choice, a bool, or the text.

    Raises
    ------
    RequestError
        The value does not parse, has the wrong dimension, lies outside the range, or a list or range
        holds more than ``limit`` values.
    """
    from ..units import parse_quantity, parse_values

    kind = field.kind
    if kind == "flag":
        if isinstance(value, bool):
            return value
        text = str(value).strip().lower()
        if text in _TRUE or text in _FALSE:
            return text in _TRUE
        raise RequestError(field.name, value, "true or false",
                           f"{{name}}: expected true or false, got {value!r}")
    if kind in ("text", "document"):
        if not isinstance(value, str):
            raise RequestError(field.name, value, field.valid(), f"{{name}}: expected text, got {value!r}")
        return value
    if kind == "choice":
        text = str(value).strip()
        if text not in field.choices:
            raise RequestError(field.name, value, field.valid(),
                               f"{{name}} must be {field.valid()}, got {value!r}")
        return text
    if kind in ("int", "number"):
        number = _number(field, value)
        shown = float(number) if abs(number) < 1e300 else math.copysign(math.inf, number)
        _bounded(field, shown, value)
        return number
    # a quantity
    text = value if isinstance(value, str) else (f"{value} {field.unit}" if field.unit else str(value))
    if _MALFORMED.search(text):  # '1.2.3 kN' is no number (pint would read 1.2 * 0.3 kN)
        raise RequestError(field.name, value, field.valid(),
                           f"{{name}}: {text!r} holds a malformed number (two decimal points)")
    scale = _SCALE.get(field.unit, 1.0)
    try:
        if field.many:
            count = count_values(field, text)
            if limit is not None and count > limit:
                raise RequestError(field.name, text, f"at most {limit} values",
                                   f"{{name}}: {text!r} holds {count} values, more than the limit of {limit}")
            values = parse_values(text, kind, field.name)
            for v in values.flat:
                _bounded(field, float(v) / scale if field.unit != "degC" else float(v) - 273.15, text)
            return values
        si = parse_quantity(text, kind, field.name)
    except RequestError:
        raise
    except InputError as exc:  # the units' message opens with the field's name: leave it open
        raise _named(field, value, str(exc)) from None
    _bounded(field, si / scale if field.unit != "degC" else si - 273.15, text)
    return si


def _number(field, value):
    """The int or float of a field of kind ``int`` or ``number``: a JSON number, or text of plain ASCII
    digits (an optional sign; for a number a decimal point and an exponent), finite, not read as 0 where
    it is not 0 (an underflow)."""
    what = "a whole number" if field.kind == "int" else "a plain number"

    def refuse():
        return RequestError(field.name, value, field.valid(), f"{{name}}: expected {what}, got {value!r}")

    if isinstance(value, bool):
        raise RequestError(field.name, value, field.valid(), f"{{name}}: expected a number, got {value!r}")
    if isinstance(value, int) or isinstance(value, float) and field.kind == "number":
        number = value
    else:
        text = str(value)
        pattern = _INTEGER if field.kind == "int" else _NUMBER
        if len(text) > _LONGEST_NUMBER or not pattern.match(text):
            raise refuse()
        number = int(text) if field.kind == "int" else float(text)
    if field.kind == "number" and not isinstance(number, float):  # a JSON integer: a float, as the text
        number = float(number) if abs(number) < 1e308 else math.copysign(math.inf, number)
    if isinstance(number, float):
        if not math.isfinite(number):
            raise RequestError(field.name, value, field.valid(),
                               f"{{name}} must be {field.valid()}, got {value!r} (not a finite number)")
        if number == 0.0 and isinstance(value, str) and re.search(r"[1-9]", re.split("[eE]", value)[0]):
            raise RequestError(field.name, value, field.valid(),  # '1e-400': not 0, but read as 0
                               f"{{name}}: {value!r} underflows (below 5e-324); write 0 or a larger value")
    return number
