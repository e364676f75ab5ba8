"""What every command of the command line shares: its own options, the bearing, and the output.

Options          the options of the command line alone (the calculations' fields are options built by
                 :mod:`bearinglab.cli._options`): FileOption (a file read or written), BearingFile,
                 CatalogFile, JsonFlag, ExecutorOpt, WorkersOpt, ChunkSizeOpt
Bearing          resolve_bearing (with the provenance notes: add_notes, reset_notes, flush_notes)
Execution        execution (one parallel.Execution with the command's progress bar), progress_bar
Output           console, emit_json (one JSON document on stdout), table (a rich table), print_document
                 (a document as tables: labels and units from its keys), emit_csv, print_warnings,
                 plain_zero (no '-0' in printed numbers)
Inputs echoed    inputs_echo (the bearing as used, the overrides, the quantities given)
Input checks     choice, check_directory, check_output (directory and suffix of an output file, and
                 check_not_input: not an input file of the command),
                 check_output_directory (its parent exists),
                 check_input (an input file exists), read_document (a document field's file -> its
                 text, recorded as an input of the run), parse_speeds (one rule for every speed option),
                 parse_speed (one speed), speed_size (the d_m of the speed guard), parse_length (a
                 length > 0, the message in mm or um), parse_viscosity, parse_temperature,
                 lubricant_viscosity (the oil options -> the operating viscosity and how it was obtained)
Calculations     request_message (a calculation's RequestError in the command line's words: the field as
                 its option), run_calculation (a calculation's document from the options as typed)

The input readers (the bearing's resolution, inputs_echo, the speeds, loads, lengths and the lubricant)
are :mod:`bearinglab.calculations._inputs`, shared with the calculations' documents, and imported
here. The command modules import these; none of them imports the package ``bearinglab.cli`` itself,
so the application is built on import without a cycle. The physics (numpy, scipy, pint, matplotlib) is
imported inside the functions that compute, never at the top of a command module: ``bearinglab --help``
builds every command without it (``tests/cli/test_cli_startup.py``).
"""

from __future__ import annotations

import contextlib
import dataclasses
import re
import sys
import textwrap
from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer
from rich.cells import cell_len
from rich.markup import escape
from rich.table import Table

from ..calculations import _inputs
from ..calculations._inputs import (  # noqa: F401 -- the commands import them from here
    LubricantViscosity,
    choice,
    five_loads,
    inputs_echo,
    lubricant_viscosity,
    parse_length,
    parse_speed,
    parse_speeds,
    parse_temperature,
    parse_viscosity,
    speed_size,
)
from ..errors import InputError
from ._console import Console, needs_spelling

if TYPE_CHECKING:
    from ..bearing import BallBearing

__all__: list[str] = []  # private to the command line

console = Console()

# ----------------------------------------------------------------------------- the command line's own options
# The options of the calculations are their fields (cli/_options.py); these belong to the command line
# alone: the files it reads and writes, the output format, the executor.
def FileOption(option, help, panel=None, *aliases):
    """An option naming a file (or directory) the command reads or writes: ``Path | None`` (named as
    a type, as the other options here)."""
    return Annotated[Path | None, typer.Option(option, *aliases, help=help, rich_help_panel=panel)]


BearingFile = FileOption("--bearing-file", "TOML file with one bearing table.", "Bearing")
CatalogFile = FileOption("--catalog", "User catalog TOML (also $BEARINGLAB_CATALOG).", "Bearing")
JsonFlag = Annotated[bool, typer.Option("--json", help="Print one JSON document on stdout.")]
# Batch execution (bearinglab.parallel): every batch command takes these three.
ExecutorOpt = Annotated[str | None, typer.Option("--executor", help="serial | local | tcp://host:8786 (a running dask scheduler).", rich_help_panel="Execution")]
WorkersOpt = Annotated[int | None, typer.Option("--workers", help="Workers of the local dask cluster (at most the cores of this machine).", rich_help_panel="Execution")]
ChunkSizeOpt = Annotated[int | None, typer.Option("--chunk-size", help="Cases per chunk (task).", rich_help_panel="Execution")]


def resolve_bearing(*args, **kwargs) -> BallBearing:
    """The bearing named, read from a file, or given inline (:func:`bearinglab.calculations._inputs.
    resolve_bearing`); its provenance notes go with the command's output (:func:`add_notes`)."""
    from .. import catalog as _catalog

    b = _inputs.resolve_bearing(*args, **kwargs)
    add_notes(_catalog.provenance_notes(b))
    return b


_NOTES: list[str] = []  # provenance notes of the bearings resolved by the command that runs


def add_notes(notes):
    """Remember the provenance notes of a resolved bearing (estimated fields, a user entry overriding a
    built-in): :func:`emit_json` adds them to a document's ``warnings`` and :func:`print_warnings` prints them."""
    _NOTES.extend(n for n in notes if n not in _NOTES)


def reset_notes():
    """Forget the notes of the previous command (the command line calls this before each command)."""
    _NOTES.clear()
    _SHOWN[0] = False


def flush_notes():
    """Print the provenance notes a command did not print with its warnings (the command line calls this
    after a command that succeeded)."""
    if _NOTES and not _SHOWN[0]:
        print_warnings([])


_SHOWN = [False]  # whether the notes went out with the command's output


def _stderr_console():
    """Progress goes to stderr, so that stdout stays one JSON document or one table."""
    return Console(stderr=True)


@contextlib.contextmanager
def progress_bar(description, executor="serial"):
    """The ``progress`` argument of :mod:`bearinglab.parallel` for a command: a rich bar (serial) or dask's
    progress bar (distributed) on an interactive terminal, nothing otherwise (pipes, tests, CI)."""
    err = _stderr_console()
    if not err.is_terminal:
        yield None
        return
    if executor not in (None, "serial"):
        yield "dask"
        return
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TimeRemainingColumn

    with Progress("[progress.description]{task.description}", BarColumn(), MofNCompleteColumn(),
                  TimeRemainingColumn(), console=err, transient=True) as bar:
        task = bar.add_task(description, total=None)
        yield lambda done, total: bar.update(task, completed=done, total=total)


def emit_json(obj):
    """Print one JSON document on stdout (NaN and inf become null; :func:`bearinglab.tables.json_text`).
    On a stream that cannot hold the project's characters (cp1252, ASCII) the characters outside ASCII
    are JSON escapes (``"\\u00b0"``), not an ASCII spelling: the document's data stay exact."""
    from .. import tables

    if _NOTES:
        _SHOWN[0] = True
        obj = _with_notes(obj)
    text = tables.json_text(obj)
    if needs_spelling(getattr(sys.stdout, "encoding", None) or "utf-8"):
        text = _NON_ASCII.sub(_json_escape, text)
    sys.stdout.write(text)


_NON_ASCII = re.compile(r"[^\x00-\x7f]")


def _json_escape(m):
    """A character outside ASCII as its JSON escape (two for one beyond the BMP, a surrogate pair)."""
    code = ord(m.group())
    if code < 0x10000:
        return f"\\u{code:04x}"
    code -= 0x10000
    return f"\\u{0xD800 + (code >> 10):04x}\\u{0xDC00 + (code & 0x3FF):04x}"


def _with_notes(obj):
    """A JSON document with the provenance notes in its ``warnings`` (a list of documents: in each)."""
    if isinstance(obj, list):
        return [_with_notes(o) for o in obj]
    if not isinstance(obj, dict):
        return obj
    given = obj.get("warnings")
    given = list(given) if isinstance(given, list) else []
    return {**obj, "warnings": given + [n for n in _NOTES if n not in given]}


# a cell that is a number (with its sign, exponent, unit marks or a D°M'S" angle): never shortened
_NUMBER_CELL = re.compile(r"^[-+−]?[\d.,]+(?:[eE][-+]?\d+)?(?:[°'\"′″]\d*[.\d]*)*[\"″]?(?:\s*[%×]?\s*[-+]?[\d.eE]*)*$|^[—-]?$")


def _rich_table(title, columns, cells, caption, numeric):
    t = Table(title=escape(title), caption=caption and escape(caption), header_style="bold")
    for i, col in enumerate(columns):
        t.add_column(escape(col), justify="left" if i == 0 else "right", no_wrap=numeric[i],
                     overflow="fold")
    for row in cells:
        t.add_row(*row)
    return t


# a zero printed with a minus sign ("-0", "-0.0000", "-0e+00"): a rounding artefact, shown as 0. Only a
# whole number: "-0°30'" (minus half a degree) and "-0.5" keep their sign
_NEGATIVE_ZERO = re.compile(r"(?<![\w.])[-−](?=0(?:\.0*)?(?:[eE][-+]?\d+)?(?:$|[\s,;)\]%/]))")


def plain_zero(text):
    """``text`` with every negative zero ('-0', '-0.0000') written without its sign ('0', '0.0000')."""
    return _NEGATIVE_ZERO.sub("", text)


def _header_lines(header, width, level):
    """A number column's header on several lines: the unit on a line of its own (level 1: 'ball load'
    over '[N]'), then also the name on lines no wider than the column's cells where its words allow
    (level 2: 'ball', 'load', '[N]')."""
    name, bracket, unit = header.rpartition(" [")
    name, unit = (name, bracket.strip() + unit) if bracket else (header, "")
    if level >= 2:
        name = "\n".join(textwrap.wrap(name, width=max(width, *map(len, name.split() or [""])),
                                       break_long_words=False, break_on_hyphens=False))
    return "\n".join(part for part in (name, unit) if part)


def cell_text(value):
    """A table cell as text: a list in words ('6, 20'), a mapping as 'name: value' pairs, a float with six
    significant digits; never a Python list or dict (issue 30). Text and formatted numbers are kept."""
    if isinstance(value, dict):
        return "; ".join(f"{str(k).replace('_', ' ')}: {cell_text(v)}" for k, v in value.items())
    if isinstance(value, (list, tuple)):
        return ", ".join(cell_text(v) for v in value)
    if isinstance(value, float):
        return f"{value:.6g}"
    return "—" if value is None else str(value)


def table(title, columns, rows, *, caption=None):
    """Print a rich table; ``columns`` are header strings, ``rows`` lists of already formatted cells.

    A number is never shortened ('0.34…') and a zero never signed ('-0'; :func:`plain_zero`): number
    columns do not wrap, text columns wrap. The table is never wider than the console (a terminal's
    width; on a pipe or in a file ``$COLUMNS``, else 80: ``cli/_console.py``). Where it does not fit,
    the headers of its number columns go on several lines, the widest first, until it fits; one that
    does not fit even so is stacked, one small quantity/value table per row. A command chooses
    tables that fit 80 columns, so that stacking is for narrower terminals only.
    """
    title, caption = plain_zero(title), caption and plain_zero(caption)
    plain = [[plain_zero(cell_text(c)) for c in row] for row in rows]
    cells = [[escape(c) for c in row] for row in plain]
    numeric = [all(_NUMBER_CELL.match(row[i].strip()) for row in cells if i < len(row))
               for i in range(len(columns))]
    shown = getattr(console, "spelled", str)  # the text as the console writes it (ASCII spelling)

    def width(text, whole):
        """Columns ``text`` needs: whole (a number), or down to its longest word (a text, that wraps)."""
        lines = shown(text).split("\n") if whole else shown(text).split()
        return max(map(cell_len, lines), default=0)

    body = [max((width(row[i], numeric[i]) for row in plain if i < len(row)), default=0)
            for i in range(len(columns))]
    heads, level = [shown(h) for h in columns], [0] * len(columns)

    def need():
        """The narrowest the table can be: rich's heavy box with one space of padding, 3 per column + 1."""
        return sum(max(b, width(h, numeric[i])) for i, (b, h) in enumerate(zip(body, heads))) + 3 * len(heads) + 1

    while need() > console.width:
        # the number column whose header, on more lines, saves the most
        shorter = {(i, k): _header_lines(shown(columns[i]), body[i], k)
                   for i in range(len(heads)) if numeric[i] for k in range(level[i] + 1, 3)}
        saving = {(i, k): max(body[i], width(heads[i], True)) - max(body[i], width(h, True))
                  for (i, k), h in shorter.items()}
        if not saving or max(saving.values()) <= 0:
            break
        # the largest saving, at the lowest level that gives it
        best = max(saving, key=lambda ik: (saving[ik], -ik[1]))
        heads[best[0]], level[best[0]] = shorter[best], best[1]
    if need() <= console.width:
        console.print(_rich_table(title, heads, cells, caption, numeric))
        return
    for k, row in enumerate(cells, 1):
        label = f"{title} ({k} of {len(cells)})" if len(cells) > 1 else title
        console.print(_rich_table(label, ["quantity", "value"], list(zip(map(escape, columns), row)),
                                  caption if k == len(cells) else None, [False, True]))


def _shown(value):
    """Whether a table shows ``value`` in a cell: a scalar, or a list of numbers (a range)."""
    if isinstance(value, list):
        return all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in value)
    return not isinstance(value, dict)


def _cell(value):
    """A value of a document as a table shows it: 6 significant digits, a list of numbers joined."""
    if value is None:
        return "—"
    if isinstance(value, bool):
        return str(value).lower()
    if isinstance(value, float):
        return f"{value:.6g}"
    if isinstance(value, list):
        return ", ".join(_cell(v) for v in value)
    return str(value)


def _label(key):
    from ..tables import quantity

    name, unit = quantity(key)
    return f"{name} [{unit}]" if unit else name


def print_document(title, doc, *, label=None, cell=None, skip=(), caption=None):
    """Print a calculation's document as tables, then its warnings: one quantity/value table of its
    scalars (a key's unit suffix gives the unit, ``basic_rating_life_h`` -> ``basic rating life [h]``;
    a list of numbers on one line; a mapping of scalars as rows ``key name``), and one table of each
    list of records (cases, balls: one column per key). A list of documents is one table, a row each.

    ``label(key)`` and ``cell(key, value)`` replace the default label and cell of a scalar; the keys of
    ``skip`` (and ``inputs``, ``warnings``) are not shown.
    """
    label, cell = label or _label, cell or (lambda key, value: _cell(value))
    skip = {"inputs", "warnings", *skip}
    if isinstance(doc, list):
        print_document(title, {"cases": doc}, label=label, cell=cell, skip=skip, caption=caption)
        print_warnings(doc[0].get("warnings", []) if doc and isinstance(doc[0], dict) else [])
        return
    rows, records = [], []
    for key, value in doc.items():
        if key in skip:
            continue
        if isinstance(value, list) and value and all(isinstance(v, dict) for v in value):
            records.append((key, value))
        elif isinstance(value, dict):
            rows += [[f"{label(key)} {_label(k)}", _cell(v)] for k, v in value.items() if _shown(v)]
        elif _shown(value):
            rows.append([label(key), cell(key, value)])
    if rows:
        table(title, ["quantity", "value"], rows, caption=caption if not records else None)
    for key, value in records:
        keys = [k for k in value[0] if k not in skip and _shown(value[0][k])]
        table(f"{title}: {key.replace('_', ' ')}" if rows else title, [_label(k) for k in keys],
              [[_cell(r.get(k)) for k in keys] for r in value], caption=caption if key == records[-1][0] else None)
    print_warnings(doc.get("warnings", []))


def print_warnings(notes):
    """Print the plausibility and validity warnings of a result (yellow), after its tables, and the
    provenance notes of the bearing (estimated fields)."""
    notes = list(notes) + [n for n in _NOTES if n not in notes]
    _SHOWN[0] = True
    for note in notes:
        console.print(f"[yellow]warning:[/yellow] {escape(note)}", highlight=False)


def emit_csv(path, columns, what="csv"):
    """Write ``columns`` as CSV to ``path`` (whole or not at all); the directory must exist."""
    from .. import tables

    path = Path(path)
    check_directory(path, what)
    tables.write_table(columns, path)


def check_directory(path: Path, what: str) -> None:
    """An output file's directory must exist (a typo must not create a tree of directories)."""
    if not Path(path).parent.is_dir():
        raise InputError(f"{what}: directory {str(Path(path).parent)!r} does not exist")


#: Figure formats the ``--plot FILE`` options accept (matplotlib's writers without extra packages).
FIGURE_SUFFIXES = (".png", ".pdf", ".svg", ".eps", ".ps", ".jpg", ".jpeg", ".tif", ".tiff")


def check_output(path, what, suffixes=None, *, inputs=()):
    """An output file, checked before anything is computed: its directory exists, it is not a
    directory itself, its suffix is one of ``suffixes`` (if given), and it is none of the command's
    ``inputs`` (:func:`check_not_input`)."""
    path = Path(path)
    check_directory(path, what)
    if path.is_dir():
        raise InputError(f"{what}: {str(path)!r} is a directory; give a file name")
    if path.exists() and not path.is_file():  # /dev/null: the atomic rename would replace the device
        raise InputError(f"{what}: {str(path)!r} is not a regular file (a device, a pipe or a socket); "
                         f"give a file name")
    if suffixes is not None and path.suffix.lower() not in suffixes:
        ends = suffixes[0] if len(suffixes) == 1 else f"one of {', '.join(suffixes)}"
        raise InputError(f"{what}: {str(path)!r} must end in {ends}, got {path.suffix or 'no suffix'!r}")
    check_not_input(path, what, inputs)
    return path


def check_not_input(path, what, inputs=()):
    """An output must not be an input file of the same command: writing it would replace the input.

    ``inputs`` are the command's input paths (None skipped); the user catalog of ``$BEARINGLAB_CATALOG``
    is always one. The same file under another name (a link, ``./a/../a``) counts as the same.
    """
    import os

    from .._io import name_output

    path = Path(path)
    name_output(path, what)  # the run's last check of its outputs (bearinglab._io) names the option too
    env = os.environ.get("BEARINGLAB_CATALOG")
    for source in [*inputs, env or None]:
        if source is None or str(source) == "":
            continue
        source = Path(source)
        try:
            same = os.path.samefile(path, source)
        except (OSError, ValueError):  # one of them does not exist (yet): compare the resolved names
            try:
                same = path.resolve() == source.resolve()
            except (OSError, RuntimeError):  # a symlink loop: not the input
                same = False
        if same:
            raise InputError(f"{what}: {str(path)!r} is an input file of this command ({source}); "
                             f"write the output to another file")


def check_output_directory(path, what):
    """An output directory, checked before anything is computed: the command creates it (or replaces what
    it wrote there before), but its parent must exist, as the directory of an output file must."""
    from .._io import name_output

    path = Path(path)
    check_directory(path, what)
    if path.exists() and not path.is_dir():
        raise InputError(f"{what}: {str(path)!r} is a file; give a directory")
    name_output(path, what)  # every file written into it is checked against the run's inputs, named so
    return path


def check_input(path, what):
    """An input file, checked before anything is read: it exists, is a regular file (not a device such
    as /dev/zero, nor a pipe) and is at most :data:`bearinglab._bounds.MAX_INPUT_BYTES` long (the message
    names the option, ``what``)."""
    from .._bounds import MAX_INPUT_BYTES

    path = Path(path)
    if not path.exists():
        raise InputError(f"{what}: {path}: no such file")
    if path.is_dir():
        raise InputError(f"{what}: {str(path)!r} is a directory; give a file name")
    if not path.is_file():
        raise InputError(f"{what}: {str(path)!r} is not a regular file (a device, a pipe or a socket); "
                         f"give a file")
    size = path.stat().st_size
    if size > MAX_INPUT_BYTES:
        raise InputError(f"{what}: {str(path)!r} has {size} bytes, more than the limit of {MAX_INPUT_BYTES} "
                         f"bytes for an input file")
    return path


def read_document(path, what):
    """The text of the file that holds a ``document`` field (a shaft system, a duty cycle): checked by
    :func:`check_input`, read by :func:`bearinglab._bounds.read_input_bytes` (so that the run records it
    as an input, which no output may replace), and decoded as UTF-8 (a byte-order mark is dropped).

    Parameters
    ----------
    path : str or Path
        The file the command line names.
    what : str
        The field as the messages name it (``model``, ``duty-cycle``).

    Returns
    -------
    str

    Raises
    ------
    InputError
        One line naming ``what`` and the file: missing, not a regular file, too large, unreadable, or
        not UTF-8 text.
    """
    from .._bounds import read_input_bytes

    path = check_input(path, what)
    try:
        data = read_input_bytes(path)
    except InputError as exc:
        raise InputError(f"{what}: {exc}") from None
    except OSError as exc:
        raise InputError(f"{what}: {path}: {exc.strerror or exc}") from None
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise InputError(f"{what}: {path}: not a UTF-8 text file") from None


@contextlib.contextmanager
def execution(description, executor=None, workers=None, chunk_size=None, *, memory_limit=None,
              progress=True):
    """The execution options of a batch command as one :class:`bearinglab.parallel.Execution`.

    Checks the options (executor, workers >= 1, chunk size >= 1), then yields the Execution with the
    command's progress report: a rich bar (serial) or dask's bar (distributed) on a terminal, none
    otherwise or with ``progress=False``.
    """
    from .. import parallel

    ex = parallel.Execution(executor=executor or "serial", workers=workers, chunk_size=chunk_size,
                            memory_limit=memory_limit)
    bar = progress_bar(description, ex.executor) if progress else contextlib.nullcontext(None)
    with bar as report:
        yield dataclasses.replace(ex, progress=report)


# ----------------------------------------------------------------------------- calculations (issue 22)
def request_message(exc):
    """A :class:`bearinglab.calculations.RequestError` in the command line's words: the field at fault
    opens the message as its option without dashes (``speed must be ...``, as every message of the
    command line), and the options it names elsewhere carry their dashes (``give --fx or --radial-load``)."""
    def option(name):
        return "--" + name.replace("_", "-")

    template, parameter = exc.template, exc.parameter or "request"
    if template.startswith("{name}"):
        template = parameter.replace("_", "-") + template[len("{name}"):]
    text = template.replace("{name}", option(parameter))
    return re.sub(r"\{field:([a-z0-9_]+)\}", lambda m: option(m.group(1)), text)


def run_calculation(name, given, document, **options):
    """Compute calculation ``name`` from the options as typed (field name -> value; None: not given)
    with its ``document`` function, the one the web runs (:mod:`bearinglab.calculations`); a refused
    input is an InputError in the command line's words (:func:`request_message`), a solve that did not
    converge stays a RunFailure of kind ``convergence`` (exit 3)."""
    from ..calculations import parse
    from ..calculations._finite import finite
    from ..calculations.fields import RequestError

    given = {k: v for k, v in given.items() if v is not None}
    try:  # typer has read the options; the calculation checks them by the command line's own rules
        # every number finite or an error, whether or not the document function is decorated itself
        return finite(name)(document)(parse(name, given, check=False), **options)
    except RequestError as exc:
        if getattr(exc, "kind", "input") == "convergence":
            raise  # a solve that did not converge: the command line words it and exits with 3
        raise InputError(request_message(exc)) from None
