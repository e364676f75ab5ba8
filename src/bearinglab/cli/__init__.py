"""The ``bearinglab`` command line. It calls public functions only; every number it prints can be had
from Python.

Commands
--------
catalog list | show | search  the bearings known (built-in and user catalogs)        cli/catalog.py
axial-angle                    operating contact angle under axial load (spec 000)    cli/stand.py
stand-load                     minimum axial load on a test stand (spec 000 section 3) cli/stand.py
frequencies                    characteristic frequencies and the spectral mask       cli/frequencies.py
sweep FILE                     a model over a grid of parameters (sweep files)        cli/sweep.py
high-speed                     high-speed quasi-static model under thrust (spec 004)  cli/high_speed.py
friction torque | lab | template   friction torque models and the friction-rig lab   cli/friction.py
load-distribution              5-DOF load distribution, stiffness, ROSS file (issue 11) cli/load.py
bearing-set                    preloaded DB/DF/DT sets on one shaft (issue 11)     cli/load.py
life                           ISO 281 / ISO/TS 16281 lives, duty cycles (issue 12)  cli/life.py
film                           EHL film, Lambda and regime per ball (issue 24)        cli/film.py
temperature                    steady bearing temperature, heat balance (issue 24)    cli/temperature.py
runout | runout monte-carlo    manufacturing errors -> inner-ring runout (spec 003)   cli/runout.py
clearance                      mounted clearance: fits, temperatures, speed (issue 23) cli/clearance.py
shaft FILE                     bearings on an elastic shaft: loads, lives, stiffness   cli/shaft.py

Each command module defines ``COMMANDS`` (command name -> function, or a Typer group). A calculation's
command is generated from its declaration in :mod:`bearinglab.calculations.registry` (``cli/_options.py``:
one option per field); the module adds the options of the command line alone (files, ``--json``, the
executor) and prints the document as tables. A registered calculation without a module gets the generic
command. The output helpers and the command line's own options are in ``cli/_common.py``, so no command
module imports this package. Importing this package builds the whole application: :data:`app` lists every
command, for the console script, ``python -m bearinglab``, test runners and documentation tools alike.

Building the application imports typer and rich only: each command imports the physics it needs when
it runs, so ``bearinglab --help`` starts in about 0.2 s (``bench/cli_help.py``) without numpy, scipy,
pint or matplotlib (``tests/cli/test_cli_startup.py``), and typer's rich help loads without the
markdown parser it imports for a markup mode this application does not use
(:func:`_rich_help_without_markdown`). Flags show no type in the help.

Errors in the input print one line on stderr, naming the option the user typed (a library parameter
such as ``n_balls`` is named by its option, ``balls``), and exit with code 2, as do inputs for which the model
has no physical solution (a ball leaving its raceway); a solver that does not converge prints one line
and exits with code 3. No traceback reaches the user, and numpy's floating-point warnings are not shown.

Functions
---------
main       run the command line with a list of arguments; returns the exit code
run        the console-script entry point (``bearinglab``): ``sys.exit(main())``
run_json   run one command with ``--json`` in-process; its exit code, document and error line (the
           web API's adapter, :mod:`bearinglab.web`)
"""

from __future__ import annotations

import contextlib
import copy
import io
import json
import os
import re
import sys
import threading
import types
import warnings
from pathlib import Path
from typing import NamedTuple

import typer
import typer.main

from .. import __version__
from .._io import run_files
from ..calculations.fields import RequestError
from ..errors import ConvergenceError, InputError
from . import (
    catalog,
    clearance,
    film,
    frequencies,
    friction,
    high_speed,
    life,
    load,
    runout,
    serve,
    shaft,
    stand,
    sweep,
    temperature,
)
from ._common import request_message
from ._console import ascii_spelling, needs_spelling, output_width, setup_streams
from ._options import register

__all__ = ["JsonRun", "app", "main", "run", "run_json"]

# typer >= 0.20 vendors click and raises its own exception classes, older typer raises click's: the
# usage error is the base class named so of typer's BadParameter either way (click is not a dependency).
_USAGE_ERRORS = tuple(c for c in typer.BadParameter.__mro__ if c.__name__ == "UsageError")


def _version(value: bool):
    if value:
        print(f"bearinglab {__version__}")
        raise typer.Exit()


_HELP_NAMES = ["-h", "--help"]

app = typer.Typer(
    name="bearinglab",
    help="Ball-bearing mechanics: combined loads and bearing sets, rating life, friction torque, high speed, test stand, runout, frequencies.",
    no_args_is_help=True,
    pretty_exceptions_enable=False,
    add_completion=False,
    context_settings={"help_option_names": _HELP_NAMES},
)


@app.callback()
def _main_options(
    version: bool = typer.Option(False, "--version", help="Print the version and exit.", is_eager=True,
                                 callback=_version),
):
    """Ball-bearing mechanics: combined loads and bearing sets, rating life, friction torque, high speed, test stand, runout, frequencies."""
    setup_streams()  # also when the app runs without main() (typer's test runner)


_GROUPS = {}
for _module in (catalog, stand, frequencies, sweep, high_speed, load, life, film, temperature, friction, runout,
                clearance, shaft, serve):
    for _name, _command in _module.COMMANDS.items():
        if isinstance(_command, typer.Typer):
            app.add_typer(_command, name=_name)
            _GROUPS[_name] = _command
        else:
            app.command(_name)(_command)
# a calculation of the registry without a command module gets the generic command (its document, or a table)
register(app, _GROUPS)


_CLICK = {}


def _click_command(name=None):
    """The click command of :data:`app`, built once: typer builds it anew on every call, which costs more
    than most commands (about 60 % of a run). Commands are registered on import, before any run. On a
    stdout that cannot hold the project's characters (cp1252, ASCII), the help texts are spelled the
    ASCII way before rich lays them out (:func:`ascii_spelling`), so that its boxes close.

    With the ``name`` of one command or group, the application is built with that command alone under
    the same root: a run needs no other (its help, usage and errors read the same), and building all
    fifteen costs 25-70 ms of every command's start (issue 21: ``catalog show`` within 0.5 s)."""
    encoding = getattr(sys.stdout, "encoding", None) or "utf-8"
    key = (encoding if needs_spelling(encoding) else "utf-8", name)
    if key not in _CLICK:
        source = app
        if name is not None:
            source = copy.copy(app)  # the root's callback and settings, one command: app is not changed
            source.registered_commands = [c for c in app.registered_commands if c.name == name]
            source.registered_groups = [g for g in app.registered_groups if g.name == name]
        _CLICK[key] = _tidy(typer.main.get_command(source), None if key[0] == "utf-8" else key[0])
    return _CLICK[key]


def _command_named(argv):
    """The command or group a command line opens with (``life`` of ``life -b 6208``), or None: the root's
    own options (``--help``, ``--version``) and a word that names no command need the whole application."""
    first = next(iter(argv), None)
    names = {c.name for c in app.registered_commands} | {g.name for g in app.registered_groups}
    return first if first in names else None


def _tidy(root, encoding=None):
    """Flags show no type in the help (typer prints ``<bool>`` after ``--json``, ``--help``); the help
    option is False unless given, so that a group passing its arguments on to a command (``bearinglab
    high-speed --help``) does not run typer's value coercion (which, in typer 0.29, imports pydantic). With an
    ``encoding`` that cannot hold them, the help texts are spelled the ASCII way."""
    stack = [root]
    while stack:
        command = stack.pop()
        if encoding is not None:
            _spell_help(command, encoding)
        ctx = command.context_class(command, info_name=command.name, help_option_names=_HELP_NAMES)
        help_option = command.get_help_option(ctx)
        if help_option is not None:
            help_option.default = False
        for param in [*command.params, help_option]:
            if getattr(param, "is_flag", False):
                param.metavar = ""
            _strict_number(param)
        stack.extend(getattr(command, "commands", {}).values())
    return root


# a whole number or a number option as click reads it, but only plain ASCII digits (issue 29): Python's int()
# and float() read '٥' as 5, '1_000' as 1000 and float() 'nan', 'inf' and '1e-400' (as 0.0)
_STRICT_TEXT = {"IntParamType": re.compile(r"^\s*[-+]?[0-9]+\s*$", re.ASCII),
                "FloatParamType": re.compile(r"^\s*[-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?\s*$",
                                             re.ASCII)}
_STRICT_TYPES = {}


def _strict_number(param):
    """Give an integer or float option a type that reads plain ASCII digits only (and no overflow or
    underflow), refusing the rest as click refuses a word: one line, exit 2."""
    base = type(getattr(param, "type", None))
    kind = next((k.__name__ for k in base.__mro__ if k.__name__ in _STRICT_TEXT), None)
    if kind is None or getattr(base, "_strict", False):
        return
    if base not in _STRICT_TYPES:
        pattern = _STRICT_TEXT[kind]

        def convert(self, value, param, ctx):
            if isinstance(value, str):
                if len(value) > 40 or not pattern.match(value):
                    what = "a whole number" if kind == "IntParamType" else "a number"
                    self.fail(f"{value!r} is not {what} (plain digits 0-9)", param, ctx)
                if kind == "FloatParamType":
                    import math

                    x = float(value)
                    if not math.isfinite(x) or (x == 0.0 and re.search(r"[1-9]", re.split("[eE]", value)[0])):
                        self.fail(f"{value!r} overflows or underflows a number", param, ctx)
            return base.convert(self, value, param, ctx)

        _STRICT_TYPES[base] = type(base.__name__, (base,), {"convert": convert, "_strict": True})
    strict = _STRICT_TYPES[base].__new__(_STRICT_TYPES[base])
    strict.__dict__.update(param.type.__dict__)
    param.type = strict


def _spell_help(command, encoding):
    """The help texts of one command and its options, spelled for ``encoding``."""
    def spell(obj, name):
        value = getattr(obj, name, None)
        if isinstance(value, str):
            setattr(obj, name, ascii_spelling(value, encoding))

    for name in ("help", "short_help", "epilog", "rich_help_panel"):
        spell(command, name)
    for param in command.params:
        for name in ("help", "rich_help_panel", "metavar"):
            spell(param, name)
        if isinstance(getattr(param, "default", None), str):
            spell(param, "default")


# the temporary file of an atomic write (bearinglab._io.atomic_output): ".NAME.RANDOM.SUFFIX" -> NAME
_TEMPORARY = re.compile(r"^\.(?P<name>.+)\.[A-Za-z0-9_]{8}\.[A-Za-z0-9]+$")


def _target_name(filename):
    """The file the user named, not the temporary file an atomic write was using when it failed."""
    if not filename:
        return ""
    path = Path(str(filename))
    m = _TEMPORARY.match(path.name)
    return str(path.with_name(m.group("name"))) if m else str(path)


# library parameter names -> the option that gives them, where the two differ
_OPTION_OF = {"n-balls": "balls", "kinematic-viscosity": "viscosity"}
_LEADING_NAME = re.compile(r"^([A-Za-z][A-Za-z0-9_-]*)(?=:| must | needs | is | has )")


def _typed_options(argv):
    """The long names of the options typed in ``argv`` (``-F 2kN`` and ``--axial-load=2kN`` ->
    ``--axial-load``), looked up in the command the words name."""
    command, typed = _click_command(), set()
    for word in map(str, argv):
        sub = getattr(command, "commands", {}).get(word)
        if sub is not None:
            command = sub
            continue
        if not word.startswith("-") or word == "-":
            continue
        key = word.split("=", 1)[0] if word.startswith("--") else word[:2]
        for param in getattr(command, "params", ()):
            if key in (*param.opts, *param.secondary_opts):
                typed.add(next((o for o in param.opts if o.startswith("--")), key))
    return typed


def _name_option(message, argv):
    """The message of an InputError, naming the option the user typed: a message that opens with a
    library parameter's name (``n_balls must be <= 15``, ``kinematic_viscosity must be > 0``) opens with
    the option's (``balls must ...``, ``viscosity must ...``: the long option without its dashes, as
    every message of the command line and the web API's parameter names) when the user gave that
    option. A name the user did not type (a field of a catalog or input file) is left as it is."""
    m = _LEADING_NAME.match(message)
    if not m:
        return message
    name = m.group(1).replace("_", "-")
    option = _OPTION_OF.get(name, name)
    try:
        typed = _typed_options(argv)
    except Exception:  # noqa: BLE001 -- naming the option is a courtesy: never lose the message itself
        return message
    return option + message[m.end():] if "--" + option in typed else message


_EXTRA = re.compile(r"^Got unexpected extra argument(?:s|\(s\))? \((?P<words>.*)\)$")


def _with_bearing_hint(message):
    """A click usage message, with a hint where an extra word is a catalog bearing: the commands take the
    bearing as an option (``life 6205-2RS`` -> ``give it as --bearing 6205-2RS``)."""
    m = _EXTRA.match(message)
    if not m:
        return message
    word = next((w for w in m.group("words").split() if _is_bearing(w)), None)
    return f"{message}: give the bearing as an option, --bearing {word}" if word else message


def _is_bearing(word):
    from .. import catalog

    try:
        catalog.get(word)
    except (InputError, OSError):  # not a bearing, or an unreadable user catalog: no hint
        return False
    return True


def _rich_help_without_markdown():
    """Load typer's rich help without ``rich.markdown``: typer imports it (and markdown-it with it, about
    a fifth of the start of ``--help``) for its markdown markup mode, which this application does not
    use (its help is rich markup). While ``typer.rich_utils`` loads, a stand-in takes the module's place
    whose ``Markdown`` loads the real class when first used; the real module is imported as usual
    afterwards. Help reads the same either way (``tests/cli/test_cli_startup.py``)."""
    if "typer.rich_utils" in sys.modules or "rich.markdown" in sys.modules:
        return
    stand_in = types.ModuleType("rich.markdown")

    class Markdown:
        def __new__(cls, *args, **kwargs):
            from rich.markdown import Markdown as markdown

            return markdown(*args, **kwargs)

    stand_in.Markdown = Markdown
    sys.modules["rich.markdown"] = stand_in
    try:
        import typer.rich_utils  # noqa: F401 -- loaded here, without the markdown parser
    finally:
        if sys.modules.get("rich.markdown") is stand_in:
            del sys.modules["rich.markdown"]


def main(argv=None) -> int:
    """Run the command line; return the exit code instead of raising (tests call this).

    Parameters
    ----------
    argv : list of str, optional
        The arguments after the program name; ``None`` reads ``sys.argv``.

    Returns
    -------
    int
        0 on success, 2 for invalid or physically impossible input (one line on stderr; a run too big for
        memory, an overflow and a too deeply nested input too), 3 for a solve that did not converge.
    """
    from ._common import flush_notes, reset_notes

    reset_notes()  # the provenance notes of the previous command's bearings
    setup_streams()  # no UnicodeEncodeError on a cp1252 or ASCII stream: the ASCII spelling
    try:
        # one run: the files it reads are its inputs, and its outputs, checked against every one of them,
        # are put in place together when it ends (bearinglab._io.run_files: inputs are never replaced)
        with warnings.catch_warnings(), run_files():
            # numpy's floating-point warnings are no message for a user: every result is checked finite
            warnings.simplefilter("ignore", RuntimeWarning)
            words = sys.argv[1:] if argv is None else list(argv)
            for word in words:  # no file name or value holds one; os.stat would raise a bare ValueError
                if "\x00" in str(word):
                    raise InputError(f"argument {word!r}: a NUL character (\\x00) is no part of an option, "
                                     "a value or a file name")
            if not words or {"-h", "--help"} & set(words):
                _rich_help_without_markdown()
            rv = _click_command(_command_named(words)).main(args=words, prog_name="bearinglab",
                                                             standalone_mode=False)
        flush_notes()
    except _USAGE_ERRORS as exc:
        if exc.format_message():  # empty after no_args_is_help has printed the help
            print(f"bearinglab: error: {_with_bearing_hint(exc.format_message())}", file=sys.stderr)
        return 2
    except typer.Exit as exc:
        return exc.exit_code
    except typer.Abort:
        print("bearinglab: aborted", file=sys.stderr)
        return 1
    except ConvergenceError as exc:  # no physical solution: the input is impossible (2); else the solver (3)
        print(f"bearinglab: error: {exc.summary}", file=sys.stderr)
        return 2 if exc.physical else 3
    except RequestError as exc:  # a calculation's input (bearinglab.calculations): named as its option
        print(f"bearinglab: error: {_name_option(request_message(exc), sys.argv[1:] if argv is None else argv)}",
              file=sys.stderr)
        return 3 if getattr(exc, "kind", "input") == "convergence" else 2  # a RunFailure that did not converge
    except InputError as exc:
        print(f"bearinglab: error: {_name_option(str(exc), sys.argv[1:] if argv is None else argv)}",
              file=sys.stderr)
        return 2
    except OSError as exc:
        print(f"bearinglab: error: {_target_name(exc.filename)}: {exc.strerror or exc}", file=sys.stderr)
        return 2
    except (MemoryError, OverflowError, RecursionError) as exc:  # a size the input checks let through
        print(f"bearinglab: error: {_TOO_BIG[type(exc)]}", file=sys.stderr)
        return 2
    return rv if isinstance(rv, int) else 0


# the last line of defence of the size limits (bearinglab._bounds): one line, never a traceback
_TOO_BIG = {
    MemoryError: "out of memory: the run is too big for this machine; a bigger study runs through "
                 "`bearinglab sweep` on dask, in chunks",
    OverflowError: "a number of the input is too large to compute with (overflow); check the values and "
                   "units given",
    RecursionError: "the input is nested too deeply to read",
}


class JsonRun(NamedTuple):
    """What :func:`run_json` gives back."""

    exit_code: int
    """0 on success, 2 for invalid input, 3 for a solve that did not converge."""
    document: object
    """The JSON document the command printed (parsed), or None when it failed."""
    error: str
    """The one-line message on failure, without the ``bearinglab: error:`` prefix; '' on success."""


_CAPTURE = threading.Lock()  # redirecting stdout and stderr is process-wide: one command at a time
_ERROR = "bearinglab: error: "


def run_json(argv) -> JsonRun:
    """Run one command with ``--json`` in this process and capture what it prints.

    The web API (:mod:`bearinglab.web`) answers with exactly what ``bearinglab ... --json`` prints, by
    running the command through this function.

    Parameters
    ----------
    argv : list of str
        The command words and options, without ``--json`` (e.g. ``["high-speed", "--bearing=B218",
        "--axial-load=20 kN", "--speed=10000 rpm"]``).

    Returns
    -------
    JsonRun
        The exit code, the parsed document (None on failure) and the one-line error message.
    """
    out, err = io.StringIO(), io.StringIO()
    with _CAPTURE, contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main([*argv, "--json"])
    lines = [line for line in err.getvalue().splitlines() if line.startswith(_ERROR)]
    if code != 0:
        last = (err.getvalue().strip().splitlines() or ["failed"])[-1]
        return JsonRun(code, None, lines[-1][len(_ERROR) :] if lines else last)
    return JsonRun(0, json.loads(out.getvalue()) if out.getvalue().strip() else None, "")


def run():
    """Console-script entry point. Output to a pipe or a file is as wide as ``$COLUMNS``, else 80 columns,
    the help included (typer's console reads ``$COLUMNS``), whatever terminal the command started from."""
    if not _isatty(sys.stdout):
        os.environ.setdefault("COLUMNS", str(output_width()))
    sys.exit(main())


def _isatty(stream):
    try:
        return stream.isatty()
    except (AttributeError, ValueError, OSError):
        return False
