"""The ``bearinglab`` command line as one click command, for sphinx-click (documentation only).

``command`` is the typer app turned into a click command by :func:`typer.main.get_command`; the CLI
reference page (``docs/cli.rst``) points sphinx-click at ``cli_reference:command``.

typer 0.20 and later vendor a trimmed copy of click (``typer._click``) whose classes are not
``click.Command`` subclasses, so sphinx-click's ``isinstance`` checks would reject them. For those
versions sphinx-click's module-level ``click`` name is pointed at a namespace holding the matching
typer classes; with an older typer (real click classes) nothing is patched.
"""

from __future__ import annotations

import types

import click
import typer
import typer.core
import typer.main

from bearinglab import cli

_register = getattr(cli, "_register_all", None)  # commands registered on first use (bearinglab <= 0.1)
if _register is not None:
    _register()

command = typer.main.get_command(cli.app)


class _Never:
    """A class no parameter or command is an instance of (click types typer's copy does not have)."""


def _patch_sphinx_click():
    import sphinx_click.ext
    from typer import _click as vendored

    group = typer.core.TyperGroup
    sphinx_click.ext.click = types.SimpleNamespace(
        Command=vendored.core.Command,
        BaseCommand=vendored.core.Command,
        Group=group,
        MultiCommand=group,
        CommandCollection=_Never,
        Context=vendored.core.Context,
        Option=typer.core.TyperOption,
        Argument=typer.core.TyperArgument,
        Choice=_Never,
        core=types.SimpleNamespace(Option=typer.core.TyperOption),
        formatting=vendored.formatting,
    )
    for cls in (typer.core.TyperOption, typer.core.TyperArgument):
        if not hasattr(cls, "type"):  # typer's copy keeps no click ParamType; sphinx-click reads it
            cls.type = None
    if not hasattr(typer.core.TyperArgument, "human_readable_name"):  # click's name for it
        typer.core.TyperArgument.human_readable_name = property(
            lambda self: self.metavar or self.name.upper()
        )


if not isinstance(command, click.Command):
    _patch_sphinx_click()
