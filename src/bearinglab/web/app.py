"""The FastAPI application of the web calculator: the page and the JSON API.

Routes
------
GET  /                 the calculator page; with the form's fields in the query it shows the results
GET  /api/{endpoint}   one command of the command line as JSON (:mod:`bearinglab.web.api`)
GET  /static/...       the style sheet

Functions
---------
create_app   the application
"""

from __future__ import annotations

from pathlib import Path

from fastapi import FastAPI, Request
from fastapi.responses import HTMLResponse, Response
from fastapi.staticfiles import StaticFiles
from fastapi.templating import Jinja2Templates

from .. import __version__, catalog, tables
from . import api, page

__all__ = ["create_app"]

_HERE = Path(__file__).parent


def _json(status, document):
    """The document as the command line prints it (:func:`bearinglab.tables.json_text`)."""
    return Response(tables.json_text(document), status_code=status, media_type="application/json")


def create_app():
    """The web calculator as a FastAPI application.

    Returns
    -------
    fastapi.FastAPI
        Serve it with ``uvicorn`` (``bearinglab serve``) or test it with ``fastapi.testclient``.
    """
    app = FastAPI(
        title="bearinglab", version=__version__, docs_url=None, redoc_url=None, openapi_url=None
    )
    app.mount("/static", StaticFiles(directory=_HERE / "static"), name="static")
    templates = Jinja2Templates(directory=_HERE / "templates")
    templates.env.filters["number"] = page.number
    templates.env.globals["quantity"] = page.quantity
    templates.env.globals["scales"] = page.scales
    templates.env.globals["column_scales"] = page.column_scales

    @app.get("/api/{endpoint}")
    def endpoint(endpoint: str, request: Request):
        if endpoint not in api.ENDPOINTS:
            return _json(
                404,
                api.error_body(
                    f"{endpoint}: no such endpoint; valid: {', '.join(api.ENDPOINTS)}",
                    None,
                    "not-found",
                ),
            )
        return _json(*api.call(endpoint, dict(request.query_params)))

    @app.get("/", response_class=HTMLResponse)
    def calculator(request: Request):
        values = {"bearing": request.query_params.get("bearing", "")}
        values.update(
            {
                f.name: request.query_params.get(f.name, "")
                for f in page.FIELDS.values()
                if not f.choices
            }
        )
        submitted = any(v.strip() for v in values.values()) or "bearing" in request.query_params
        values.update(
            {
                f.name: request.query_params.get(f.name, f.choices[0])
                for f in page.FIELDS.values()
                if f.choices
            }
        )
        results, field_errors = page.compute(values) if submitted else ([], {})
        return templates.TemplateResponse(
            request,
            "index.html",
            {
                "version": __version__,
                "names": catalog.names(),
                "values": values,
                "fields": page.FIELDS,
                "results": results,
                "errors": field_errors,
                "submitted": submitted,
                "geometry_open": not values["bearing"]
                or any(
                    values[f.name] or f.name in field_errors
                    for f in page.FIELDS.values()
                    if f.group == "geometry"
                ),
            },
        )

    return app
