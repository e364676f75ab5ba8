"""Command line of the local web calculator: ``serve`` (:mod:`bearinglab.web`).

The web framework (FastAPI, uvicorn) is the ``web`` extra and is imported only when the command runs,
so ``bearinglab --help`` and every other command stay light.

Commands
--------
COMMANDS   the ``serve`` command, by name (the application adds it)
"""

import errno
import socket
from typing import Annotated

import typer

from ..errors import InputError
from ._common import console

__all__ = ["COMMANDS"]


def _check_bindable(host, port):
    """Raise InputError naming ``host`` or ``port`` when the server could not listen there.

    Binds (and closes) a socket on every address ``host`` resolves to, as uvicorn's asyncio server
    does (``SO_REUSEADDR``, IPv6 sockets IPv6-only), so a taken port or an address this machine does
    not have is one line before the banner, not the banner and a server log.
    """
    try:
        infos = socket.getaddrinfo(
            host or None, port, type=socket.SOCK_STREAM, flags=socket.AI_PASSIVE
        )
    except (OSError, UnicodeError) as exc:  # socket.gaierror is an OSError
        reason = getattr(exc, "strerror", None) or exc
        raise InputError(f"host: cannot listen on {host!r} ({reason})") from None
    for family, kind, proto, _, address in dict.fromkeys(infos):
        with socket.socket(family, kind, proto) as sock:
            sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
            if family == socket.AF_INET6:
                sock.setsockopt(socket.IPPROTO_IPV6, socket.IPV6_V6ONLY, 1)
            try:
                sock.bind(address)
            except OSError as exc:
                if exc.errno == errno.EADDRINUSE:
                    raise InputError(f"port: {port} is already in use on {host}") from None
                if exc.errno == errno.EACCES:
                    raise InputError(
                        f"port: no permission to listen on {port} on {host} (ports below 1024 "
                        "need privileges)"
                    ) from None
                raise InputError(
                    f"host: cannot listen on {host!r} ({exc.strerror or exc})"
                ) from None


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
    _check_bindable(host, port)
    console.print(
        f"bearinglab calculator on http://{host}:{port}/ (Ctrl+C to stop)", highlight=False
    )
    try:
        uvicorn.run(create_app(), host=host, port=port, log_level="warning")
    except SystemExit as exc:  # uvicorn's startup failure is its exit code 3, which is ours for a solver
        if exc.code in (0, None):
            raise
        raise InputError(f"serve: the server could not start on {host}:{port}") from None


#: The ``serve`` command, as the application adds it.
COMMANDS = {"serve": serve}
