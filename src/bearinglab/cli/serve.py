"""Command line of the local web calculator: ``serve`` (:mod:`bearinglab.web`).

The web framework (FastAPI, uvicorn) is the ``web`` extra and is imported only when the command runs,
so ``bearinglab --help`` and every other command stay light.

Commands
--------
COMMANDS   the ``serve`` command, by name (the application adds it)
"""

from typing import Annotated

import typer

from ..errors import InputError
from ._common import console

__all__ = ["COMMANDS"]


def serve(
    host: Annotated[
        str, typer.Option("--host", help="Address to listen on (default: this machine only).")
    ] = "127.0.0.1",
    port: Annotated[int, typer.Option("--port", "-p", help="TCP port.")] = 8000,
):
    """The local web calculator and its JSON API (/api/high-speed, /api/axial-angle, ...)."""
    if not 0 <= port <= 65535:
        raise InputError(f"port must be in [0, 65535], got {port}")
    try:
        import uvicorn

        from ..web import create_app
    except ImportError as exc:  # the extra is missing: one line, no traceback
        raise InputError(
            f"serve: needs the web extra (pip install 'bearinglab[web]'): {exc}"
        ) from None
    console.print(
        f"bearinglab calculator on http://{host}:{port}/ (Ctrl+C to stop)", highlight=False
    )
    uvicorn.run(create_app(), host=host, port=port, log_level="warning")


#: The ``serve`` command, as the application adds it.
COMMANDS = {"serve": serve}
