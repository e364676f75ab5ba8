"""Sweeps of any calculation, case by case: each case is the calculation's JSON document, as one row.

:mod:`bearinglab.sweep` runs a sweep file through this module when its ``model`` names a calculation of
:data:`bearinglab.calculations.CALCULATIONS` that has no batch model of its own, when its parameters are
fields the batch model does not take, or when the file says ``path = "document"``. Each case is the
request the command line makes for the same options (field name -> value as typed: the text of a
quantity, an int, a float, a flag), and its row is the document ``bearinglab <command> ... --json``
prints (:func:`bearinglab.calculations.run`), flattened by :func:`flatten_document`.

Rows (:func:`flatten_document`)
-------------------------------
- The keys of a nested mapping are joined by a dot: ``inputs.geometry.balls``,
  ``chain.probable.operating_clearance``.
- A list of numbers, or a list of equal lists of numbers, of at most :data:`MAX_LIST_NUMBERS` numbers
  gives one column per number, named by its indices from 0: ``stiffness_matrix.2.2``,
  ``interference_inner_probable_um.1``.
- A list of text (``warnings``) is one text cell, its items joined by ``" | "``.
- A list of tables that :data:`NAMED_LISTS` gives for the calculation (the supports of a shaft, the
  bearings of a support) spreads each table's scalars under its ``name``, or its index from 0 where the
  tables have no distinct names: ``supports.front.force_x_N``, ``supports.front.bearings.1.static_safety_factor``.
- Other lists are left out: tables (the balls, the iteration table, the bearings of a set) and longer
  series (a trajectory). The single command with the case's inputs prints them.
- An empty list is left out (no warnings: no cell).

Columns: a column holds numbers (float64; int64 when every case gave an integer), booleans, or objects
(text, and the rare key whose values mix kinds; its numbers are floats). A value the case does not have
(a failed case, a key its document lacks) is NaN in a column of numbers and None (null) otherwise. The
type of a column depends on the values of all cases, never on the chunks.

Values of a parameter (:func:`parameter_values`)
------------------------------------------------
A value, a TOML list, or a range ``start:stop:step``. Quantities follow :mod:`bearinglab.units` (one
value, a list ``a, b, c UNIT``); a range is computed in its own unit, ``start + k * step`` rounded to 12
significant digits (``0.1:0.5:0.1 kN`` gives ``0.3 kN``, not ``0.30000000000000004 kN``), and its three
numbers take one unit. Whole numbers and plain numbers take ranges and comma lists too; a text with a
unit (a temperature) takes a range; choices, flags and other texts take TOML lists; a document (a runout
error set, a duty cycle) is a TOML table or its text. A parameter that is no field but a dotted path
addresses a value inside a document field (:mod:`bearinglab._document_paths`: ``supports.front.position``
of a shaft system); each case's document is the given one with that value replaced.

Functions
---------
flatten_document   a document -> one row: column name -> scalar
parameter_values   one [parameters] or [constants] entry -> the requests' values and the input column
parameter_count    how many values an entry holds, counted before they are built
input_column       the name of a parameter's input column
evaluate           the chunk function: each case's document, as columns
merge              the chunks' columns -> one table, with ``converged`` and ``failure``
document_function  the function that computes a calculation's document, and whether it reads files
"""

from __future__ import annotations

import contextlib
import importlib
import inspect
import json
import math
import re
import tempfile
import threading
import warnings
from pathlib import Path

import numpy as np

from .errors import ConvergenceError, InputError

__all__ = ["MAX_LIST_NUMBERS", "NAMED_LISTS", "TEXT_SEPARATOR", "document_function", "evaluate", "flatten_document",
           "input_column", "merge", "parameter_count", "parameter_values"]

#: The longest list of numbers a row spreads into columns (a 5 x 5 stiffness matrix is 25).
MAX_LIST_NUMBERS = 100
#: How the items of a list of text (``warnings``) are joined into one cell.
TEXT_SEPARATOR = " | "
#: The lists of tables of a calculation's document that a row spreads by the tables' names (or their
#: index where they have no distinct names; at most MAX_LIST_NUMBERS tables), by their path (``*``: any
#: one step): ``supports.front.force_x_N``. Their tables are few, and named by the user; other lists of
#: tables (balls, rows along a shaft) are left out.
NAMED_LISTS = {"shaft": ("supports", "supports.*.bearings", "spectrum.bearings")}

# The calculations whose documents read checked (SI) values: the web's catalog search, which has no
# command of its own. Every other document is computed from the values as the command line types them.
_CHECKED = ("catalog-search",)
_NUMBER = r"[-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?"
_NUMBER_UNIT = re.compile(rf"^\s*({_NUMBER})\s*(.*?)\s*$")
_PLAIN = re.compile(rf"^\s*{_NUMBER}\s*$")
_INTEGER = re.compile(r"^\s*[-+]?[0-9]+\s*$")
_TRUE, _FALSE = ("true", "yes", "on", "1"), ("false", "no", "off", "0")
# the documents run one at a time in a process: a local cluster of threads shares the warnings filters
# and the caches of the models, which a document reads (its warnings list is what it records)
_LOCK = threading.Lock()


def flatten_document(doc, named=()):
    """One document as one row: its scalars, keyed by their path (the rules in the module docstring).

    Parameters
    ----------
    doc : dict
        A JSON document (:func:`bearinglab.calculations.run`).
    named : tuple of str, optional
        The paths of the lists of tables spread by their names (:data:`NAMED_LISTS`).

    Returns
    -------
    dict
        Column name -> str, int, float, bool or None.

    Examples
    --------
    >>> flatten_document({"a_N": 1.5, "chain": {"least": {"x": 2}}, "k": [[1.0, 2.0], [3.0, 4.0]],
    ...                   "balls": [{"load_N": 3.0}], "warnings": ["w1", "w2"], "notes": []})
    {'a_N': 1.5, 'chain.least.x': 2, 'k.0.0': 1.0, 'k.0.1': 2.0, 'k.1.0': 3.0, 'k.1.1': 4.0, 'warnings': 'w1 | w2'}
    """
    row = {}

    def walk(node, key):
        if isinstance(node, dict):
            for k, v in node.items():
                walk(v, f"{key}.{k}" if key else str(k))
        elif isinstance(node, (list, tuple)):
            if not node:
                return
            if _spread(key, named) and len(node) <= MAX_LIST_NUMBERS and all(isinstance(x, dict) for x in node):
                names = [x.get("name") for x in node]
                if not all(isinstance(n, str) and n for n in names) or len(set(names)) != len(names):
                    names = [str(i) for i in range(len(node))]
                for name, table in zip(names, node):
                    walk({k: v for k, v in table.items() if k != "name"}, f"{key}.{name}")
            elif all(isinstance(x, str) for x in node):
                row[key] = TEXT_SEPARATOR.join(node)
            elif _numbers(node) is not None:
                for index, x in _numbers(node):
                    row[f"{key}.{index}"] = x
        else:
            row[key] = node

    walk(doc, "")
    return row


def _spread(key, named):
    """Whether the list at ``key`` is one of the ``named`` paths (``*`` standing for any one step)."""
    steps = key.split(".")
    return any(len(p) == len(steps) and all(a in ("*", b) for a, b in zip(p, steps))
               for p in (n.split(".") for n in named))


def _is_number(x):
    return x is None or (isinstance(x, (int, float)) and not isinstance(x, bool))


def _numbers(node):
    """[(index text, number)] of a vector or a matrix of at most MAX_LIST_NUMBERS numbers, else None."""
    if all(_is_number(x) for x in node):
        items = [(str(i), x) for i, x in enumerate(node)]
    elif all(isinstance(r, (list, tuple)) and len(r) == len(node[0]) and all(_is_number(x) for x in r)
             for r in node):
        items = [(f"{i}.{j}", x) for i, r in enumerate(node) for j, x in enumerate(r)]
    else:
        return None
    return items if len(items) <= MAX_LIST_NUMBERS else None


# ----------------------------------------------------------------------------- the values of a parameter
def input_column(field):
    """The input column of a parameter: the field's name, with its display unit for a quantity
    (``axial_load_N``, ``speed_rpm``, ``mx_Nmm``, ``density_kg_m3``, ``reliability_percent``) and
    ``_item`` for a document (the position of the document in the list, from 0)."""
    from .units import KINDS

    if field.kind == "document":
        return f"{field.name}_item"
    if field.kind not in KINDS and field.kind != "number" or not field.unit or field.unit == "-":
        return field.name
    suffix = {"N*mm": "Nmm", "%": "percent"}.get(field.unit)
    if suffix is None:  # as the documents write units in keys: kg/m^3 -> kg_m3, J/(kg*K) -> J_kg_K
        suffix = re.sub(r"[()^]", "", field.unit.replace("/", "_").replace("*", "_"))
    return f"{field.name}_{suffix}"


def parameter_values(field, value, *, limit):
    """One entry of a sweep file's [parameters] or [constants] -> the values of its cases.

    Parameters
    ----------
    field : bearinglab.calculations.Field
        The field the entry names.
    value : str, int, float, bool, dict or list
        As the TOML file holds it: a value, a list, or a range ``"start:stop:step"``.
    limit : int
        The most values one entry may hold (a range is counted before it is built).

    Returns
    -------
    tuple of (list, list)
        The value of each case as the command line types it (the text of a quantity, an int, a float, a
        flag, the names of a list of bearings), and the value shown in its input column (a quantity in
        the field's display unit, rounded to 12 significant digits; a document's position).

    Raises
    ------
    InputError
        A value that does not parse, is of the wrong kind or is not one of the choices, an empty list, or
        more than ``limit`` values.
    """
    given, shown = [], []
    items = value if isinstance(value, list) else [value]
    if not items:
        raise InputError(f"{field.name}: empty list")
    for item in items:
        if isinstance(item, list):
            raise InputError(f"{field.name}: a list inside a list, got {item!r}")
        g, s = _values(field, item, limit)
        given += g
        shown += s
        if len(given) > limit:
            raise InputError(f"{field.name}: {len(given)} values, more than the limit of {limit}")
    if field.kind == "document":
        shown = list(range(len(given)))
    return given, shown


def parameter_count(field, value, *, limit):
    """How many values an entry of [parameters] holds, counted without building them (a range from its
    three numbers), so that the grid is bounded before anything is allocated; the values themselves are
    checked by :func:`parameter_values`.

    Examples
    --------
    >>> from bearinglab.calculations import CALCULATIONS
    >>> fx = CALCULATIONS["life"].field("fx")
    >>> parameter_count(fx, ["1 kN", "0:10:2 kN", "1, 2, 3 kN"], limit=100)
    10
    """
    from .units import KINDS

    count = 0
    for item in value if isinstance(value, list) else [value]:
        if not isinstance(item, str):
            count += 1
        elif ":" in item and (field.kind in KINDS or field.kind in ("int", "number") or field.unit):
            count += _range(field.name, item, limit)[2]
        elif field.kind in KINDS or field.kind in ("int", "number"):  # a list a, b, c (the units' separators)
            count += len([s for s in item.split(";" if ";" in item else ",") if s.strip()])
        else:
            count += 1
    return count


def _values(field, item, limit):
    from .units import KINDS

    name, kind = field.name, field.kind
    if kind in KINDS:
        return _quantities(field, item, limit)
    if kind in ("int", "number"):
        return _numbers_of(field, item, limit)
    if kind == "flag":
        if isinstance(item, str) and item.strip().lower() in _TRUE + _FALSE:
            item = item.strip().lower() in _TRUE
        if not isinstance(item, bool):
            raise InputError(f"{name}: expected true or false, got {item!r}")
        return [item], [item]
    if kind == "choice":
        if not isinstance(item, str) or item.strip() not in field.choices:
            raise InputError(f"{name} must be one of {', '.join(field.choices)}, got {item!r}")
        return [item.strip()], [item.strip()]
    if kind == "document":
        if isinstance(item, dict):
            return [json.dumps(item)], [None]
        if not isinstance(item, str):
            raise InputError(f"{name}: expected a table or the text of a JSON or TOML document, got {item!r}")
        return [item], [None]
    # text: one value (a pair '5 um, 20 um' stays one); a range where the field has a unit (temperatures)
    if isinstance(item, bool) or not isinstance(item, (str, int, float)):
        raise InputError(f"{name}: expected text, got {item!r}")
    text = str(item)
    if field.unit and ":" in text:
        numbers, unit = _range_numbers(name, text, limit)
        texts = [f"{_text(x)} {unit}".strip() for x in _without_noise(numbers)]
    else:
        texts = [text.strip()]
    if field.many:  # a list of names for one case (the bearings of a set), as the repeated option gives
        return [[s.strip() for s in t.split(",") if s.strip()] for t in texts], texts
    return texts, texts


def _without_noise(numbers):
    """The numbers of a range without their binary noise: 12 significant digits (0.1 + 2 * 0.1 is 0.3)."""
    from .tables import significant

    return significant(np.asarray(numbers, dtype=float)).tolist() if numbers else []


def _text(x):
    """A number's shortest text: ``250`` for 250.0, ``0.3``, ``1e-05``."""
    return repr(int(x)) if float(x).is_integer() and abs(x) < 1e15 else repr(float(x))


def _range_numbers(name, text, limit):
    """The numbers of ``start:stop:step`` in its own unit (one unit: the last one written applies to the
    numbers written without one) and that unit; counted before they are built."""
    start, step, count, unit = _range(name, text, limit)
    return [start + step * k for k in range(count)], unit


def _range(name, text, limit):
    """``start:stop:step`` -> (start, step, number of values, unit), the numbers in the range's unit."""
    from ._bounds import range_count

    parts = [p.strip() for p in text.split(":")]
    if len(parts) != 3:
        raise InputError(f"{name}: a range is start:stop:step, got {text!r}")
    split = [_NUMBER_UNIT.match(p) for p in parts]
    if not all(split):
        raise InputError(f"{name}: a range is three numbers with one unit, e.g. '0:15000:250 rpm', got {text!r}")
    units = {m.group(2) for m in split if m.group(2)}
    if len(units) > 1:
        raise InputError(f"{name}: the start, stop and step of a range take one unit (e.g. '0 rpm:15000 rpm:250 "
                         f"rpm' or '0:15000:250 rpm'), got {text!r}")
    unit = units.pop() if units else ""
    start, stop, step = (float(m.group(1)) for m in split)
    if not all(map(math.isfinite, (start, stop, step))):
        raise InputError(f"{name}: range {text!r} holds a number that is not finite")
    if not step > 0 or stop < start:
        raise InputError(f"{name}: range {text!r} needs step > 0 and stop >= start")
    return start, step, range_count(start, stop, step, name, text, limit=limit), unit


def _quantities(field, item, limit):
    """A quantity, a list ``a, b, c UNIT`` or a range: the texts of the cases and their shown values."""
    from .tables import significant
    from .units import parse_quantity, parse_values

    name, kind = field.name, field.kind
    scale = parse_quantity(f"1 {field.unit}", kind, name) if field.unit else 1.0  # SI per display unit
    if not isinstance(item, str):  # a bare number has no unit
        parse_quantity(item, kind, name)  # (raises, naming the unit to write)
        raise InputError(f"{name}: expected a quantity with its unit, got {item!r}")
    if ":" in item:
        numbers, unit = _range_numbers(name, item, limit)
        per_unit = parse_quantity(f"1 {unit}", kind, name)  # the unit's grammar and kind [SI per unit]
        numbers = _without_noise(numbers)
        texts = [f"{_text(x)} {unit}" for x in numbers]
        for text in (texts[0], texts[-1]):  # each end by the units' grammar (a sign, an overflow)
            parse_quantity(text, kind, name)
        if per_unit == scale:  # written in the display unit: the numbers are the column
            return texts, numbers
        si = np.asarray(numbers) * per_unit
    else:
        si = parse_values(item, kind, name, limit=limit)  # the units' grammar, lists and all
        sep = ";" if ";" in item else ","
        parts = [s.strip() for s in item.split(sep) if s.strip()]
        last = _NUMBER_UNIT.match(parts[-1])
        last_unit = last.group(2) if last else ""
        texts = [f"{p} {last_unit}" if last_unit and _PLAIN.match(p) else p for p in parts]
    shown = significant(si / scale).tolist()
    return texts, shown


def _numbers_of(field, item, limit):
    """Whole or plain numbers: a TOML number, a text, a comma list or a range."""
    name, whole = field.name, field.kind == "int"
    what = "a whole number" if whole else "a plain number"
    if isinstance(item, bool):
        raise InputError(f"{name}: expected {what}, got {item!r}")
    if isinstance(item, (int, float)):
        if whole and not isinstance(item, int) or not math.isfinite(item):
            raise InputError(f"{name}: expected {what}, got {item!r}")
        values = [item if whole else float(item)]
    elif not isinstance(item, str):
        raise InputError(f"{name}: expected {what}, got {item!r}")
    elif ":" in item:
        numbers, unit = _range_numbers(name, item, limit)
        if unit or whole and not all(float(x).is_integer() for x in numbers):
            raise InputError(f"{name}: a range of {what}s, e.g. '1:5:1', got {item!r}")
        values = [int(x) for x in numbers] if whole else _without_noise(numbers)
    else:
        parts = [s.strip() for s in item.split(",")]
        pattern = _INTEGER if whole else _PLAIN
        if not all(pattern.match(p) for p in parts):
            raise InputError(f"{name}: expected {what} or a list of them, got {item!r}")
        values = [int(p) if whole else float(p) for p in parts]
        if not whole and not all(map(math.isfinite, values)):
            raise InputError(f"{name}: {item!r} is not finite")
    if len(values) > limit:
        raise InputError(f"{name}: {len(values)} values, more than the limit of {limit}")
    return values, list(values)


# ----------------------------------------------------------------------------- the cases
def document_function(calculation):
    """The function that computes a calculation's document, and whether it reads a bearing file.

    Parameters
    ----------
    calculation : str
        A key of :data:`bearinglab.calculations.CALCULATIONS`.

    Returns
    -------
    tuple of (callable or None, bool)
        ``document(parsed, ...)`` of the calculation's module (None for the catalog and its search,
        which :func:`bearinglab.calculations.run` computes itself) and whether it takes ``bearing_file``.
    """
    from .calculations import documents

    module = documents._NATIVE.get(calculation)
    if module is None:
        return None, False
    function = importlib.import_module(f"bearinglab.calculations.{module}").document
    return function, "bearing_file" in inspect.signature(function).parameters


@contextlib.contextmanager
def _command_line_warnings():
    """The warnings filters of ``bearinglab`` in a shell (Python's defaults, and numpy's floating-point
    warnings ignored, as :func:`bearinglab.cli.main`): a document records the same warnings in every
    process, whatever filters a test runner or a dask worker has set. What escapes a document is not
    shown: its JSON does not hold it."""
    with warnings.catch_warnings(record=True):
        warnings.resetwarnings()
        warnings.filterwarnings("ignore", category=RuntimeWarning)
        warnings.filterwarnings("default", category=DeprecationWarning, module="__main__", append=True)
        for category in (DeprecationWarning, PendingDeprecationWarning, ImportWarning, ResourceWarning):
            warnings.filterwarnings("ignore", category=category, append=True)
        yield


@contextlib.contextmanager
def _bearing_file(table):
    """A bearing file holding ``table`` for the documents of one chunk, written where the chunk runs (a
    dask worker on another machine has no access to the sweep file); None when there is no table."""
    if table is None:
        yield None
        return
    with tempfile.TemporaryDirectory(prefix="bearinglab-sweep-") as folder:
        path = Path(folder) / "bearing.toml"
        path.write_text(_toml(table), encoding="utf-8")
        yield path


def _toml(table, prefix=""):
    """A table of a TOML file, written back (strings, numbers, booleans, arrays and sub-tables)."""
    lines, tables = [], []
    for key, value in table.items():
        name = json.dumps(str(key))
        if isinstance(value, dict):
            tables.append((f"{prefix}.{name}" if prefix else name, value))
        else:
            lines.append(f"{name} = {json.dumps(value, default=str)}")  # JSON's strings are TOML's
    text = "\n".join(lines) + "\n"
    for name, sub in tables:
        text += f"[{name}]\n" + _toml(sub, name)
    return text


def _message(exc):
    """A failed case's reason: the message the command line prints for it (fields by their names)."""
    if isinstance(exc, ConvergenceError):
        return exc.summary
    if isinstance(exc, OverflowError):
        return "a number of the input is too large to compute with (overflow)"
    return str(exc)


def _document(calculation, request, bearing_file):
    """The document of one request, as :func:`bearinglab.calculations.run` computes it."""
    from . import calculations
    from ._io import json_value

    parsed = calculations.parse(calculation, request, check=calculation in _CHECKED)
    with _command_line_warnings():
        if bearing_file is None:
            doc = calculations.run(parsed)
        else:  # the module's own function with the file, as run() calls it without one
            function, _ = document_function(calculation)
            doc = json_value(function(parsed, bearing_file=bearing_file))
    if isinstance(doc, list) and len(doc) == 1:  # a request of one case given as a list
        doc = doc[0]
    if not isinstance(doc, dict):
        raise TypeError(f"{calculation}: a document of one case is a mapping, got {type(doc).__name__}")
    return doc


def evaluate(calculation, given, bearing_table=None, **cases):
    """The chunk function of a sweep of a calculation: each case's document as columns.

    Parameters
    ----------
    calculation : str
        A key of :data:`bearinglab.calculations.CALCULATIONS`.
    given : dict
        The values every case shares (the file's bearing and [constants]), as the command line types them.
    bearing_table : dict, optional
        The sweep file's [bearing] table (a bearing file of each document).
    **cases : ndarray of object
        Field name -> the value of each case of the chunk.

    Returns
    -------
    dict
        ``n`` (cases), ``columns`` (name -> (kinds of values, some value missing, array)), ``computed``,
        ``converged`` and ``failure`` (per case); :func:`merge` joins the chunks.
    """
    from . import _document_paths
    from .calculations import CALCULATIONS

    n = len(next(iter(cases.values())))
    rows, computed = [], np.zeros(n, dtype=bool)
    converged, failure = np.zeros(n, dtype=bool), np.full(n, "", dtype=object)
    named, parsed = NAMED_LISTS.get(calculation, ()), {}
    with _LOCK, _bearing_file(bearing_table) as path:
        for i in range(n):
            request = dict(given, **{k: v[i] for k, v in cases.items()})
            try:  # the values addressed inside a document, written into it
                request = _document_paths.with_values(CALCULATIONS[calculation], request, parsed)
                row = flatten_document(_document(calculation, request, path), named)
            except (InputError, ConvergenceError, OverflowError) as exc:  # the case's, not the sweep's
                rows.append(None)
                failure[i] = _message(exc)
                continue
            rows.append(row)
            computed[i] = True
            converged[i] = row.get("converged", True) is not False
            if not converged[i]:
                status = row.get("status")
                failure[i] = f"not converged ({status})" if isinstance(status, str) else "not converged"
    return {"n": n, "columns": _columns(rows), "computed": computed, "converged": converged,
            "failure": failure}


def _kind(value):
    if value is None:
        return None
    if isinstance(value, bool):
        return "bool"
    if isinstance(value, int):
        return "int" if -2**63 <= value < 2**63 else "object"
    if isinstance(value, float):
        return "float"
    return "object"


def _class(kinds, missing):
    """The type of a column from the kinds of its values and whether one is missing."""
    if not kinds:
        return "none"
    if kinds == {"int"} and not missing:
        return "int"
    if kinds <= {"int", "float"}:
        return "float"
    if kinds == {"bool"} and not missing:
        return "bool"
    return "object"


def _array(values, cls):
    if cls == "int":
        return np.array(values, dtype=np.int64)
    if cls == "float":
        return np.array([math.nan if v is None else float(v) for v in values], dtype=float)
    if cls == "bool":
        return np.array(values, dtype=bool)
    if cls == "none":
        return None
    out = np.empty(len(values), dtype=object)
    out[:] = [float(v) if _kind(v) == "int" else v for v in values]  # numbers of a mixed column: floats
    return out


def _columns(rows):
    """The rows of a chunk as typed columns: name -> (kinds, missing, array)."""
    keys = {}
    for row in rows:
        if row is not None:
            keys.update(dict.fromkeys(row))
    out = {}
    for key in keys:
        values = [None if row is None else row.get(key) for row in rows]
        kinds = {k for k in map(_kind, values) if k is not None}
        missing = any(v is None for v in values)
        out[key] = (kinds, missing, _array(values, _class(kinds, missing)))
    return out


def _converted(array, n, cls):
    """A chunk's column (or None: all missing) as the column type ``cls`` of the whole sweep."""
    if cls in ("float", "none"):  # a key that is null in every case: a column of NaN
        return np.full(n, math.nan) if array is None else array.astype(float)
    if cls in ("int", "bool"):
        return array
    out = np.empty(n, dtype=object)  # object: NaN was a missing value; numbers are floats
    if array is not None:
        out[:] = [None if isinstance(v, float) and math.isnan(v) else
                  float(v) if _kind(v) == "int" and array.dtype != object else v for v in array.tolist()]
    return out


def merge(chunks):
    """The columns of all chunks, in case order: the documents' columns, ``converged`` and ``failure``.

    Parameters
    ----------
    chunks : list of dict
        The outputs of :func:`evaluate`, in case order.

    Returns
    -------
    tuple of (dict, ndarray)
        Column name -> array (the documents' keys in the order first met, then ``converged`` and
        ``failure``), and per case whether its document was computed.
    """
    keys = {}
    for chunk in chunks:
        keys.update(dict.fromkeys(chunk["columns"]))
    columns = {}
    for key in keys:
        parts = [chunk["columns"].get(key) for chunk in chunks]
        kinds = set().union(*(p[0] for p in parts if p is not None))
        missing = any(p is None or p[1] for p in parts)
        cls = _class(kinds, missing)
        columns[key] = np.concatenate([_converted(None if p is None else p[2], c["n"], cls)
                                       for p, c in zip(parts, chunks)])
    columns["converged"] = np.concatenate([c["converged"] for c in chunks])
    columns["failure"] = np.concatenate([c["failure"] for c in chunks])
    return columns, np.concatenate([c["computed"] for c in chunks])
