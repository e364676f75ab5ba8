"""The FastAPI application of the web calculator: the page, the JSON API and their limits.

Routes
------
GET  /                         the calculator page; with the form's fields in the query it shows results
GET  /api/<endpoint>           one calculation, query parameters (shareable links)
POST /api/<endpoint>           one calculation, a JSON body of the same parameters
GET  /csv/<endpoint>           the same calculation's document as CSV (the page's download link)
GET  /docs, /redoc, /openapi.json   every endpoint and field, with units, ranges and limits (offline)
GET  /static/...               the style sheet and the page's script

Swagger UI and ReDoc load their scripts from the package (fastapi-offline), with no network.

Limits: a request holds at most ``case_limit`` cases, runs at most ``time_budget`` seconds (then its
worker process is stopped and the answer is 503 naming the budget), and its body is at most
:data:`bearinglab.calculations.BODY_LIMIT` bytes. Calculations run in worker processes
(:mod:`bearinglab.web.workers`): a light pool for single cases and a heavy pool for lists, ranges,
runout, a clearance Monte Carlo and any request whose weight, estimated from its parsed size before it is
sent (:attr:`bearinglab.calculations.Parsed.weight`: cases, duty-cycle steps, samples, positions), is over
:data:`bearinglab.calculations.LIGHT_WEIGHT`, so that a light request never waits behind heavy ones; the
heavy workers run at a lower OS priority (``os.nice``), so that light requests keep a core; a client that
goes away stops its work.

Functions
---------
create_app   the application
"""

from __future__ import annotations

import asyncio
import contextlib
from pathlib import Path

from fastapi import Request
from fastapi.responses import HTMLResponse, Response, StreamingResponse
from fastapi.staticfiles import StaticFiles
from fastapi.templating import Jinja2Templates
from fastapi_offline import FastAPIOffline

from .. import __version__, calculations, tables
from ..calculations import BODY_LIMIT, CALCULATIONS, CASE_LIMIT, TIME_BUDGET, RequestError
from . import api, page, shaft
from .workers import HEAVY_NICENESS, MEMORY_BOUND_MB, Pool, Stopped

__all__ = ["create_app"]

_HERE = Path(__file__).parent
_IN_SERVER = ("catalog", "catalog-search")  # built here from the catalog: no worker needed


# the last line of defence of the request's checks, worded as the command line words it: 422, never a 500
_TOO_BIG = {
    OverflowError: "a number of the input is too large to compute with (overflow); check the values and units given",
    RecursionError: "the input is nested too deeply to read",
    MemoryError: "the request is too big for this server's memory; ask for fewer cases",
}


#: An answer above this size goes out in pieces of this size: the event loop sends a piece, then serves
#: the other requests while the socket drains, instead of copying a whole 20 MB map into its buffer at once
#: (a light request that met that copy waited 20-40 ms; bench/web_load.py) [bytes]
_PIECE = 1 << 18


async def _pieces(body):
    view = memoryview(body)
    for start in range(0, len(view), _PIECE):
        yield view[start:start + _PIECE]
        await asyncio.sleep(0)


def _json(status, document):
    """The document as the command line prints it (:func:`bearinglab.tables.json_text`); a text (or its
    UTF-8 bytes) is the document already written so by a worker."""
    text = document if isinstance(document, str | bytes) else tables.json_text(document)
    if isinstance(text, bytes) and len(text) > _PIECE:
        return StreamingResponse(_pieces(text), status_code=status, media_type="application/json",
                                 headers={"content-length": str(len(text))})
    return Response(text, status_code=status, media_type="application/json")


def _description(case_limit, time_budget):
    return (
        "The JSON API of bearinglab: every endpoint answers with the document `bearinglab <command> "
        "--json` prints. Each takes GET query parameters (shareable links) or a POST JSON body of the "
        "same parameters. Quantities are strings with their unit (`20 kN`, `10000 rpm`).\n\n"
        f"**Limits.** A request holds at most **{case_limit} cases** (the product of its lists and "
        f"ranges); it may compute for at most **{time_budget:g} s**, after which it is stopped and "
        f"answered 503 with `error` `limit`; its body is at most **{BODY_LIMIT} bytes** (413). "
        "Errors are `{\"detail\", \"parameter\", \"error\"}` with status 422 (bad input, unknown or "
        "repeated parameter, too many cases), 503 (time budget, busy) or 404."
    )


class _BoundedBody:
    """A request whose Content-Length is over :data:`BODY_LIMIT` is answered 413 before it is read.

    A plain ASGI middleware (not Starlette's BaseHTTPMiddleware, which hides a client's disconnect
    from the endpoint, so that its work would not be cancelled)."""

    def __init__(self, app):
        self.app = app

    async def __call__(self, scope, receive, send):
        if scope["type"] == "http":
            length = dict(scope.get("headers") or ()).get(b"content-length")
            if length is not None and (not length.isdigit() or int(length) > BODY_LIMIT):
                body = tables.json_text(api.error_body(
                    f"the request body is larger than {BODY_LIMIT} bytes", None, "limit")).encode()
                await send({"type": "http.response.start", "status": 413,
                            "headers": [(b"content-type", b"application/json"),
                                        (b"content-length", str(len(body)).encode())]})
                await send({"type": "http.response.body", "body": body})
                return
        await self.app(scope, receive, send)


class _Server:
    """The pools and limits of one application."""

    def __init__(self, light, heavy, case_limit, time_budget, memory_bound_mb):
        self.light = Pool(light, memory_bound_mb=memory_bound_mb)
        self.heavy = Pool(heavy, queue=16, memory_bound_mb=memory_bound_mb, niceness=HEAVY_NICENESS)
        self.case_limit, self.time_budget = case_limit, time_budget

    async def compute(self, name, given, request=None, *, what="document"):
        """(status, document or error body) of calculation ``name`` with ``given``."""
        try:
            parsed = calculations.parse(name, given, limit=self.case_limit)
            if name in _IN_SERVER and what in ("document", "json"):
                doc = await asyncio.to_thread(calculations.run, parsed)
                return 200, tables.json_text(doc) if what == "json" else doc
        except RequestError as exc:
            return api.web_error(exc)
        except (OverflowError, RecursionError, MemoryError) as exc:  # a size the request's checks let through
            return 422, api.error_body(_TOO_BIG[type(exc)], None, "input" if type(exc) is not MemoryError
                                       else "limit")
        # a Monte Carlo of the clearance (up to 10^5 samples) is heavy though it has no list
        study = parsed.values.get("monte_carlo") is not None
        pool = self.heavy if (parsed.heavy or study or what == "figure") else self.light
        gone = request.is_disconnected if request is not None else None
        try:
            kind, value = await pool.call((what, name, given, self.case_limit, parsed),
                                          budget=self.time_budget, gone=gone)
        except Stopped as exc:
            status = 499 if exc.reason == "gone" else 503
            return status, api.error_body(str(exc), None, "limit" if exc.reason == "budget" else exc.reason)
        if kind == "ok":
            return 200, value
        if kind == "error":
            return api.web_error(value)
        return 500, api.error_body(f"internal error: {value}", None, "failed")


#: The content security policy of /docs and /redoc: this server only (inline scripts and styles are the pages'
#: own; ReDoc's search runs in a worker made from a blob; images may be data: URIs).
_DOCS_CSP = ("default-src 'self'; script-src 'self' 'unsafe-inline'; style-src 'self' 'unsafe-inline'; "
             "img-src 'self' data:; font-src 'self' data:; worker-src 'self' blob:; connect-src 'self'")


_DOCS_STATIC = "/static-offline-docs"  # Swagger UI's and ReDoc's files, mounted from fastapi-offline


def _docs_pages(app):
    """/docs (Swagger UI) and /redoc (ReDoc) with their files from the fastapi-offline package, and a content
    security policy: ReDoc's side menu shows its maker's logo from a CDN (hard-coded in its script); the
    browser loads from this server only, so the logo is not fetched (ReDoc then leaves it out). Swagger UI's
    validator badge, which calls an outside server, is off."""
    from fastapi.openapi.docs import get_redoc_html, get_swagger_ui_html

    favicon = f"{_DOCS_STATIC}/favicon.png"

    @app.get("/docs", include_in_schema=False)
    async def swagger_ui():
        page = get_swagger_ui_html(openapi_url=app.openapi_url, title="bearinglab - Swagger UI",
                                   swagger_js_url=f"{_DOCS_STATIC}/swagger-ui-bundle.js",
                                   swagger_css_url=f"{_DOCS_STATIC}/swagger-ui.css", swagger_favicon_url=favicon,
                                   swagger_ui_parameters={"validatorUrl": None})
        page.headers["Content-Security-Policy"] = _DOCS_CSP
        return page

    @app.get("/redoc", include_in_schema=False)
    async def redoc():
        page = get_redoc_html(openapi_url=app.openapi_url, title="bearinglab - ReDoc",
                              redoc_js_url=f"{_DOCS_STATIC}/redoc.standalone.js", redoc_favicon_url=favicon,
                              with_google_fonts=False)
        page.headers["Content-Security-Policy"] = _DOCS_CSP
        return page


def create_app(*, light_workers=2, heavy_workers=2, case_limit=CASE_LIMIT, time_budget=TIME_BUDGET,
               memory_bound_mb=MEMORY_BOUND_MB):
    """The web calculator as a FastAPI application.

    Parameters
    ----------
    light_workers, heavy_workers : int
        Worker processes for single cases and for lists, ranges, runout and figures.
    case_limit : int
        The most cases one request may hold.
    time_budget : float
        Seconds a request may compute before it is stopped. [s]
    memory_bound_mb : float
        A worker whose peak memory passed this after a request is replaced. [MB]

    Returns
    -------
    fastapi.FastAPI
        Serve it with ``uvicorn`` (``bearinglab serve``) or test it with ``fastapi.testclient``.
    """
    server = _Server(light_workers, heavy_workers, case_limit, time_budget, memory_bound_mb)

    @contextlib.asynccontextmanager
    async def lifespan(app):
        server.light.start()
        server.heavy.start()
        yield
        server.light.close()
        server.heavy.close()

    # /docs and /redoc serve Swagger UI's and ReDoc's files from the fastapi-offline package (FastAPI's own
    # pages load them from a CDN, blank offline); Swagger UI's validator badge calls an outside server: off
    app = FastAPIOffline(title="bearinglab", version=__version__, description=_description(case_limit, time_budget),
                         lifespan=lifespan, docs_url=None, redoc_url=None, static_url=_DOCS_STATIC)
    _docs_pages(app)
    app.state.server = server
    app.mount("/static", StaticFiles(directory=_HERE / "static"), name="static")
    templates = Jinja2Templates(directory=_HERE / "templates")
    templates.env.filters["number"] = page.number
    templates.env.globals["quantity"] = page.quantity
    templates.env.globals["scales"] = page.scales
    templates.env.globals["column_scales"] = page.column_scales
    templates.env.globals["value_rows"] = page.value_rows
    templates.env.globals["case_rows"] = page.case_rows
    templates.env.globals["page_rows"] = page.PAGE_ROWS
    templates.env.globals["chain_rows"] = page.chain_rows
    templates.env.globals["chain_columns"] = page.CHAIN_COLUMNS
    templates.env.globals["percentile_rows"] = page.percentile_rows
    templates.env.globals["shaft"] = shaft  # the shaft section's editor and tables (templates/shaft_*.html)

    app.add_middleware(_BoundedBody)

    async def read_body(request):
        chunks, size = [], 0
        async for chunk in request.stream():
            size += len(chunk)
            if size > BODY_LIMIT:
                raise RequestError(None, None, f"at most {BODY_LIMIT} bytes",
                                   f"the request body is larger than {BODY_LIMIT} bytes")
            chunks.append(chunk)
        return b"".join(chunks)

    def add_routes(path, name):
        calc = CALCULATIONS[name]
        summary = f"{calc.title}: {calc.summary}"

        async def get(request: Request):
            try:
                values = api.query_values(path, request.query_params.multi_items())
            except RequestError as exc:
                return _json(*api.web_error(exc))
            return _json(*await server.compute(name, values, request, what="json"))

        async def post(request: Request):
            try:
                values = api.body_values(path, await read_body(request))
            except RequestError as exc:
                status, body = api.web_error(exc)
                return _json(413 if "larger than" in body["detail"] else status, body)
            return _json(*await server.compute(name, values, request, what="json"))

        schema = api.model(name).model_json_schema()
        app.add_api_route(f"/api/{path}", get, methods=["GET"], summary=summary, name=f"{name} (GET)",
                          operation_id=f"get_{name.replace('-', '_')}",
                          openapi_extra={"parameters": api.parameters(name)}, tags=[name])
        app.add_api_route(f"/api/{path}", post, methods=["POST"], summary=summary,
                          name=f"{name} (POST)", operation_id=f"post_{name.replace('-', '_')}",
                          openapi_extra={"requestBody": {"required": True, "content": {
                              "application/json": {"schema": schema}}}}, tags=[name])

    for path, name in sorted(api.ENDPOINTS.items(), key=lambda kv: kv[0].count("/"), reverse=True):
        add_routes(path, name)

    @app.api_route("/api/{rest:path}", methods=["GET", "POST"], include_in_schema=False)
    def unknown(rest: str):
        return _json(404, api.error_body(f"/api/{rest}: no such endpoint; valid: "
                                         f"{', '.join('/api/' + e for e in api.ENDPOINTS)}",
                                         None, "not-found"))

    @app.get("/csv/{path:path}", include_in_schema=False)
    async def csv(path: str, request: Request):
        name = api.ENDPOINTS.get(path)
        if name is None:
            return _json(404, api.error_body(f"/csv/{path}: no such calculation", None, "not-found"))
        try:
            values = api.query_values(path, request.query_params.multi_items())
        except RequestError as exc:
            return _json(*api.web_error(exc))
        status, doc = await server.compute(name, values, request)
        if status != 200:
            return _json(status, doc)
        return Response(page.to_csv(doc), media_type="text/csv", headers={
            "content-disposition": f'attachment; filename="bearinglab-{name}.csv"'})

    @app.get("/", response_class=HTMLResponse)
    async def calculator(request: Request):
        try:
            values = api.query_values("", request.query_params.multi_items())
        except RequestError:
            values = dict(request.query_params)
        context = await page.render_context(values, server)
        return templates.TemplateResponse(request, "index.html", dict(context, version=__version__))

    return app
