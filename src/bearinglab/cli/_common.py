"""What every command of the command line shares: the bearing and execution options, and the output.

Bearing options  BearingName, BearingFile, CatalogFile and the inline geometry; resolve_bearing
Execution        ExecutorOpt, WorkersOpt, ChunkSizeOpt; execution (one parallel.Execution with the
                 command's progress bar)
Output           console, emit_json (one JSON document on stdout), table (a rich table), emit_csv,
                 print_warnings, plain_zero (no '-0' in printed numbers)
Inputs echoed    inputs_echo (the bearing as used, the overrides, the quantities given)
Input checks     choice, check_directory, check_output (directory and suffix of an output file, and
                 check_not_input: not an input file of the command),
                 check_output_directory (its parent exists),
                 check_input (an input file exists), parse_speeds (one rule for every speed option),
                 parse_speed (one speed), speed_size (the d_m of the speed guard), parse_length (a
                 length > 0, the message in mm or um), parse_viscosity
Lubricant        ViscosityOpt, OilOpt, TemperatureOpt, ViscosityIndexOpt, Viscosity100Opt (the oil options
                 every command that needs a viscosity shares); parse_temperature; lubricant_viscosity (those
                 options -> the operating viscosity and how it was obtained)

The input readers (the bearing's resolution, inputs_echo, the speeds, loads, lengths and the lubricant)
are :mod:`bearinglab.calculations._inputs`, shared with the calculations' documents, and imported
here; request_message words a calculation's RequestError for the command line, fields_given collects
a command's options as the request of its calculation, run_calculation computes a calculation's document
from them. The command modules import these; none of them imports the package ``bearinglab.cli`` itself,
so the application is built on import without a cycle. The physics (numpy, scipy, pint, matplotlib) is imported
inside the functions that compute, never at the top of a command module: ``bearinglab --help`` builds
every command without it (``tests/cli/test_cli_startup.py``).
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

# ----------------------------------------------------------------------------- shared options
# Bearing given by name, by file, or inline. Commands that need a bearing take these parameters and
# call resolve_bearing(...) with them.
BearingName = Annotated[str | None, typer.Option("--bearing", "-b", help="Catalog name, e.g. B218, 4-1006095, 6205-2RS.", rich_help_panel="Bearing")]
BearingFile = Annotated[Path | None, typer.Option("--bearing-file", help="TOML file with one bearing table.", rich_help_panel="Bearing")]
CatalogFile = Annotated[Path | None, typer.Option("--catalog", help="User catalog TOML (also $BEARINGLAB_CATALOG).", rich_help_panel="Bearing")]
Balls = Annotated[int | None, typer.Option("--balls", help="Number of balls.", rich_help_panel="Inline geometry")]
BallDiameter = Annotated[str | None, typer.Option("--ball-diameter", help="e.g. '2 mm'.", rich_help_panel="Inline geometry")]
PitchDiameter = Annotated[str | None, typer.Option("--pitch-diameter", help="e.g. '8.7355 mm'.", rich_help_panel="Inline geometry")]
InnerRadius = Annotated[str | None, typer.Option("--inner-groove-radius", help="e.g. '1.05 mm'.", rich_help_panel="Inline geometry")]
OuterRadius = Annotated[str | None, typer.Option("--outer-groove-radius", help="e.g. '1.16 mm'.", rich_help_panel="Inline geometry")]
InnerConformity = Annotated[float | None, typer.Option("--inner-conformity", help="f_i = r_i / D.", rich_help_panel="Inline geometry")]
OuterConformity = Annotated[float | None, typer.Option("--outer-conformity", help="f_o = r_o / D.", rich_help_panel="Inline geometry")]
ContactAngle = Annotated[str | None, typer.Option("--contact-angle", help="Nominal (free) angle, e.g. '12 deg'.", rich_help_panel="Inline geometry")]
Clearance = Annotated[str | None, typer.Option("--radial-clearance", help="Diametral clearance, e.g. '9 um'.", rich_help_panel="Inline geometry")]
BallMaterial = Annotated[str | None, typer.Option("--ball-material", help="steel | silicon_nitride.", rich_help_panel="Inline geometry")]
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


def fields_given(name, values, **renamed):
    """The values of a command's options that are fields of calculation ``name``, as typed (an option
    not given, None, is left out): the ``given`` of :func:`bearinglab.calculations.parse`.
    ``renamed`` maps a field to the command's parameter where the two differ (``density="density_text"``)."""
    from ..calculations import CALCULATIONS

    out = {}
    for f in CALCULATIONS[name].fields:
        value = values.get(renamed.get(f.name, f.name))
        if value is not None:
            out[f.name] = value
    return out


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


# ----------------------------------------------------------------------------- five loads (issues 11, 12)
# The loads on the inner ring, (F_x, F_y, F_z, M_x, M_y); --radial-load and --axial-load are F_x and F_z.
_LOADS = "Loads on the inner ring"
FxOpt = Annotated[str | None, typer.Option("--fx", help="Radial force along x, e.g. '1 kN'.", rich_help_panel=_LOADS)]
FyOpt = Annotated[str | None, typer.Option("--fy", help="Radial force along y, e.g. '200 N'.", rich_help_panel=_LOADS)]
FzOpt = Annotated[str | None, typer.Option("--fz", help="Axial force (along the bearing axis), e.g. '500 N'.", rich_help_panel=_LOADS)]
MxOpt = Annotated[str | None, typer.Option("--mx", help="Tilting moment about x, e.g. '1000 N*mm'.", rich_help_panel=_LOADS)]
MyOpt = Annotated[str | None, typer.Option("--my", help="Tilting moment about y, e.g. '2 N*m'.", rich_help_panel=_LOADS)]
RadialLoadOpt = Annotated[str | None, typer.Option("--radial-load", "-R", help="Same as --fx.", rich_help_panel=_LOADS)]
AxialLoadOpt = Annotated[str | None, typer.Option("--axial-load", "-A", help="Same as --fz.", rich_help_panel=_LOADS)]


# ----------------------------------------------------------------------------- lubricant (issue 20)
# The oil options shared by every command that needs the operating viscosity (life; film, friction, ...):
# --viscosity alone, or --oil with --temperature (and --viscosity-index or --viscosity-100).
_LUBRICANT = "Lubricant"
ViscosityOpt = Annotated[str | None, typer.Option("--viscosity", help="Operating kinematic viscosity, e.g. '20 cSt'.", rich_help_panel=_LUBRICANT)]
OilOpt = Annotated[str | None, typer.Option("--oil", help="ISO VG grade, e.g. VG68 (with --temperature).", rich_help_panel=_LUBRICANT)]
TemperatureOpt = Annotated[str | None, typer.Option("--temperature", help="Operating temperature of the oil, e.g. '70 degC'.", rich_help_panel=_LUBRICANT)]
ViscosityIndexOpt = Annotated[float | None, typer.Option("--viscosity-index", help="The oil's viscosity index (default 95, a mineral oil).", rich_help_panel=_LUBRICANT)]
Viscosity100Opt = Annotated[str | None, typer.Option("--viscosity-100", help="The oil's viscosity at 100 degC, e.g. '8.7 cSt' (instead of --viscosity-index).", rich_help_panel=_LUBRICANT)]


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
    input is an InputError in the command line's words (:func:`request_message`)."""
    from ..calculations import parse
    from ..calculations.fields import RequestError

    given = {k: v for k, v in given.items() if v is not None}
    try:  # typer has read the options; the calculation checks them by the command line's own rules
        return document(parse(name, given, check=False), **options)
    except RequestError as exc:
        raise InputError(request_message(exc)) from None
