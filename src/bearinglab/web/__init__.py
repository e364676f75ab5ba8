"""The local web calculator and its JSON API (``bearinglab serve``; needs the ``web`` extra).

A page (``GET /``) with a form (a catalog bearing or an inline geometry, the loads, speed and
lubricant) and the results of the command line's models on it, with the library's own figures; and a
JSON API, ``GET /api/<endpoint>``, that answers with exactly what ``bearinglab <command> --json``
prints. This package imports FastAPI; ``import bearinglab`` does not import it.

Modules
-------
api    endpoint -> command; query parameters -> the command's options; errors as JSON
page   the form fields, the sections of results, the figures
shaft  the shaft-system section: its editor's tables, request and results
app    the FastAPI application

Functions
---------
create_app   the FastAPI application (serve it with uvicorn, test it with its TestClient)
"""

from __future__ import annotations

from .app import create_app

__all__ = ["create_app"]
