"""The command line built from the calculations' fields: one command per registered calculation.

A calculation is declared once (:mod:`bearinglab.calculations.registry`); its command is generated
here, the way a schema-driven command line is: each :class:`~bearinglab.calculations.Field` becomes one
typer option (its spelling and short aliases, the type its kind reads as, default, required, help,
help panel from its group, one value or repeated), and typer builds the click command and its rich
help from them as from any hand-written signature. What belongs to the command line alone (the files
it reads and writes, ``--json``, the executor) is declared by hand, as the keyword parameters of the
command's ``run`` function, which receives the fields as typed. The values are not parsed here: typer
reads whole numbers and numbers, the rest stays text for the calculation to read by its own rules.

A ``document`` field (a shaft system, a duty cycle: text in the calculation, posted so on the web) is a
file on the command line (a positional ``FILE`` where its ``option`` is spelled without dashes): the
command reads it (:func:`bearinglab.cli._common.read_document`: a regular file of bounded size, UTF-8,
recorded as an input of the run, so that no output replaces it) and hands its text to the field, for
every command, the generic one included. A command whose ``run`` needs the file itself (runout reads
the profiles next to its error file) asks for the path (``command(..., documents="path")``).

Commands
--------
command       calculation name and its ``run(given, **options)`` -> the function typer registers
register      add a command for every registered calculation that has none yet (the generic one)
generic_run   the ``run`` of a calculation without a command module: its document, or a table of it
help_of       a field's help as the command line shows it (other fields as their options)
option_of     a field's parameter: (annotation, typer's OptionInfo with the default)
"""

from __future__ import annotations

import inspect
import re
from pathlib import Path

import typer

from ..calculations import CALCULATIONS
from ..calculations.registry import GROUPS
from ._common import JsonFlag

__all__: list[str] = []  # private to the command line

#: field kind -> the type typer reads the option as; every other kind is text, read by the calculation
_TYPES = {"int": int, "number": float, "flag": bool, "document": Path}
_NAMED = re.compile(r"`([a-z][a-z0-9_]*)`")  # another field, named in a help text
_BUILT: set = set()  # the calculations with a command (built by `command`)
_OPTIONS: dict = {}  # calculation name -> (calculation, {field name: its option}), for the help texts


def help_of(field, calc):
    """The help of ``field`` as the command line shows it: the other fields of ``calc`` it names (in
    backquotes: ``temperature`` between two backquotes) as their options (``--temperature``), a
    document as the file that holds it, the choices where the text does not list them, and every
    bracket escaped (rich would read ``[rad]`` as markup)."""
    known = _OPTIONS.get(calc.name)
    if known is None or known[0] is not calc:
        known = _OPTIONS[calc.name] = (calc, {f.name: f.cli_option for f in calc.fields if f.cli})
    options = known[1]
    text = _NAMED.sub(lambda m: options.get(m.group(1), m.group(0)), field.help)
    if field.kind == "document":
        text = "TOML file of " + text
    if field.choices and not all(c in text for c in field.choices):
        text = text.rstrip(".") + ": " + " | ".join(field.choices) + "."
    return text.replace("[", "\\[")


def _panel(field):
    group = field.group
    return GROUPS[group] if group in GROUPS else group[:1].upper() + group[1:]


def option_of(field, calc, required=True):
    """The parameter of ``field`` in ``calc``'s command: (annotation, typer's OptionInfo or ArgumentInfo
    holding the default).

    Whole numbers and numbers are typed (``int``, ``float``), a flag is a flag, a document a file; any
    other kind is text, read by the calculation. A field with a default has it as the option's; a
    required one has none (unless ``required`` is False: then it is optional, and the command says
    what is missing); a list of texts (``many``) is a repeated option; an ``option`` spelled without
    dashes (``NAME``) is a positional argument. (The default is typer's ``Option(default, ...)``, not
    ``Annotated``: building fifteen commands' ``Annotated`` types costs more than the rest of the help.)
    """
    kind = _TYPES.get(field.kind, str)
    if field.many and field.kind == "text":
        kind = list[str]
    if field.required and required:
        default = ...
    elif field.kind == "flag":
        kind, default = bool, bool(field.default)
    elif field.default is not None:
        default = field.default
    else:
        kind, default = kind | None, None
    help_text = help_of(field, calc)
    if not field.cli_option.startswith("-"):  # a positional argument, shown as its spelling (FILE)
        return kind, typer.Argument(default, help=help_text, metavar=field.cli_option)
    return kind, typer.Option(default, field.cli_option, *field.aliases, help=help_text,
                              rich_help_panel=_panel(field))


def _info(parameter):
    """The typer OptionInfo of a hand-written parameter (``Annotated[..., typer.Option(...)]``)."""
    return next((m for m in getattr(parameter.annotation, "__metadata__", ())
                 if isinstance(m, typer.models.ParameterInfo)), parameter.default)


def command(name, run, *, help=None, required=True, documents="text"):
    """The command of calculation ``name``: a function whose parameters typer reads as the options.

    Parameters
    ----------
    name : str
        A key of :data:`bearinglab.calculations.CALCULATIONS`.
    run : callable
        ``run(given, **options)``: ``given`` the calculation's fields as typed (field name -> value;
        an option not given is left out), ``options`` the command line's own options, declared as the
        keyword parameters of ``run`` (``json_out: JsonFlag = False``); a parameter annotated
        ``typer.Context`` receives the context. Each option joins its help panel after the fields
        shown there (the main panel's after its fields), or comes last.
    help : str, optional
        The command's help (default: ``run``'s docstring, else the calculation's summary).
    required : bool
        False: no option is required (the callback of a group, ``runout``, runs before its subcommand
        without them; ``run`` checks what it needs).
    documents : {"text", "path"}
        What ``run`` receives for a ``document`` field given on the command line: the text of the file
        (read by :func:`bearinglab.cli._common.read_document`, the message naming the field and the
        file), or the file's path, for a command that reads the file itself.

    Returns
    -------
    callable
        What ``app.command(word)`` (or a group's callback) registers.
    """
    calc = CALCULATIONS[name]
    fields = [f for f in calc.fields if f.cli]
    keyword = inspect.Parameter.KEYWORD_ONLY
    params = [inspect.Parameter(f.name, keyword, annotation=ann, default=info)
              for f in fields for ann, info in [option_of(f, calc, required)]]
    panels = [_panel(f) for f in fields]
    own = list(inspect.signature(run, eval_str=True).parameters.values())[1:]
    for p in own:
        if p.name in {f.name for f in fields}:
            raise ValueError(f"{name}: the option {p.name!r} of the command line is a field of the calculation")
        if p.annotation is typer.Context:
            params.insert(0, p.replace(kind=keyword))
            panels.insert(0, "")
            continue
        info = _info(p)
        panel = getattr(info, "rich_help_panel", None)
        at = max((i for i, q in enumerate(panels) if q == panel), default=len(params) - 1) + 1
        params.insert(at, p.replace(kind=keyword))
        panels.insert(at, panel)
    names = [f.name for f in fields]
    files = {f.name: _spelled(f) for f in fields if f.kind == "document"} if documents == "text" else {}

    def generated(**values):
        given = {k: values.pop(k) for k in names}
        given = {k: v for k, v in given.items() if v is not None}
        if files:  # a document is a file here: its text is the field's value
            from ._common import read_document

            given.update({k: read_document(v, files[k]) for k, v in given.items() if k in files})
        return run(given, **values)

    generated.__signature__ = inspect.Signature(params)
    generated.__doc__ = help or run.__doc__ or calc.summary
    generated.__name__ = generated.__qualname__ = run.__name__
    generated.__module__ = run.__module__
    generated.calculation = name
    generated.run = run
    _BUILT.add(name)
    return generated


def _spelled(field):
    """How a message names ``field``: its option without dashes (``duty-cycle``), or, for a positional
    argument (``FILE``), the field's name (``model``), as the web names it."""
    option = field.cli_option
    return option[2:] if option.startswith("--") else field.name


def generic_run(name):
    """The ``run`` of calculation ``name`` without a command module of its own: its document
    (:func:`bearinglab.calculations.run`, the inputs checked by the fields as the web checks them)
    with ``--json``, else its values as a table (:func:`bearinglab.cli._common.print_document`)."""
    def run(given, *, json_out: JsonFlag = False):
        from ..calculations import parse
        from ..calculations import run as compute
        from ._common import emit_json, print_document

        doc = compute(parse(name, given))
        if json_out:
            emit_json(doc)
            return
        print_document(CALCULATIONS[name].title, doc)

    run.__name__ = name.replace("-", "_")
    return run


def register(app, groups=None):
    """Add to ``app`` a command for every registered calculation that has none yet (no module of
    :mod:`bearinglab.cli` built it), with :func:`generic_run`: a calculation declared in the registry
    is on the command line. ``groups`` maps a first command word to its typer group (``friction``)."""
    groups = dict(groups or {})
    for calc in CALCULATIONS.values():
        if calc.name in _BUILT or not calc.command:
            continue
        function = command(calc.name, generic_run(calc.name))
        first, *rest = calc.command
        if not rest:
            app.command(first)(function)
            continue
        if first not in groups:
            groups[first] = typer.Typer(help=calc.title, no_args_is_help=True)
            app.add_typer(groups[first], name=first)
        groups[first].command(rest[0])(function)
