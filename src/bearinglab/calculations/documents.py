"""The documents of the calculations: what ``bearinglab <command> --json`` prints, for a Parsed request.

``catalog`` (:func:`catalog_document`, which ``catalog show`` prints too) and ``catalog-search``
(:func:`bearinglab.catalog.search`) are built here from :mod:`bearinglab.catalog` and
:mod:`bearinglab.tables`. Every other calculation (life, load-distribution, bearing-set, frequencies,
stand-load, axial-angle, high-speed, friction, clearance, film, temperature, runout, runout-monte-carlo,
shaft)
is computed by ``document(parsed)`` of its module of this package, the function its command calls too,
and its figure is drawn from that document: no request runs the command line, and no message of the
command line is read back (``tests/calculations/test_native*.py`` hold the documents equal to what
the commands print).

Functions
---------
run          Parsed -> the document
catalog_document  a bearing's ``catalog show --json`` document (the command prints it)
figure_svg   Parsed -> the command's figure as SVG text, or ''
argv         Parsed -> the command words and options
RunFailure   a run that failed: input (exit 2) or convergence (exit 3), with the field it names
"""

from __future__ import annotations

import importlib
import io
import json
import warnings

from ..errors import InputError
from ._failures import run_failure
from ._finite import check, finite
from .fields import RequestError, RunFailure
from .registry import CALCULATIONS

__all__ = ["RunFailure", "argv", "catalog_document", "figure_svg", "run"]



def argv(parsed, *, documents=None):
    """The command words and options for ``parsed`` (documents written to files named in ``documents``).

    Parameters
    ----------
    parsed : Parsed
        A checked request.
    documents : dict, optional
        Field name -> the path its posted document was written to.

    Returns
    -------
    list of str
    """
    calc = parsed.calculation
    words = list(calc.command)
    for f in calc.fields:
        if f.name not in parsed.given or not f.cli:  # an input of the page alone has no option
            continue
        value = parsed.values[f.name]
        if f.kind == "flag":
            if value:
                words.append(f.cli_option)
        elif f.kind == "document":
            words.append(f"{f.cli_option}={documents[f.name]}")
        elif f.cli_option == "NAME":
            words.append(str(parsed.given[f.name]).strip())
        elif f.many and f.kind == "text":
            words += [f"{f.cli_option}={v}" for v in value]
        else:  # '=' keeps a value such as '-5 kN' from reading as an option
            words.append(f"{f.cli_option}={str(parsed.given[f.name]).strip()}")
    return words


def _document(name, text):
    """A posted JSON or TOML document as a dict; one that refers to a file is refused."""
    import tomllib

    from .._bounds import MAX_DEPTH, parse_document

    try:  # a repeated JSON key, or nesting deeper than MAX_DEPTH, is refused (bearinglab._bounds)
        doc = parse_document(text, "the posted document")
    except InputError as exc:
        raise RequestError(name, "...", f"a JSON or TOML document, keys once, at most {MAX_DEPTH} levels deep",
                           f"{{name}}: {exc}") from None
    except (ValueError, tomllib.TOMLDecodeError) as exc:
        raise RequestError(name, "...", "a JSON or TOML document",
                           f"{{name}}: not a JSON or TOML document ({exc})") from None
    if not isinstance(doc, dict):
        raise RequestError(name, "...", "a JSON object", "{name}: expected a JSON object or TOML tables")

    def walk(node, where):
        if isinstance(node, dict):
            for key, value in node.items():
                if key == "profile":  # a file name: nothing is read from the server's disk
                    raise RequestError(name, "...", "inline angle/deviation arrays",
                                       f"{{name}}: [{where}] names a profile file; a request cannot "
                                       "refer to files: give the inline 'angle' and 'deviation' arrays")
                walk(value, f"{where}.{key}" if where else key)
        elif isinstance(node, list):
            for item in node:
                walk(item, where)

    walk(doc, "")
    return doc


def _clearance_range(b, choice, given):
    """The ISO 5753-1 range of a deep-groove bearing and the value the models use, for `catalog show`."""
    from .. import internal_clearance
    if b.type != "radial" or b.bore is None or b.clearance_class is None and "radial_clearance" not in b.sources:
        return None
    cls = b.clearance_class or "CN"
    try:
        r = internal_clearance.radial_clearance_range(b.bore, cls)
    except InputError:
        return None
    used = "given (--radial-clearance)" if given else (choice or "mean")
    return {"class": cls, "minimum_um": r.minimum * 1e6, "maximum_um": r.maximum * 1e6, "used": used}



@finite("catalog")
def catalog_document(name, *, catalog=None, clearance=None, radial_clearance=None):
    """The document of ``bearinglab catalog show NAME --json`` (the command prints this) and the bearing.

    Parameters
    ----------
    name : str
        Bearing name, alias or designation (``6208-2RS1/C3``).
    catalog : str or Path, optional
        A user catalog file (the command has checked it).
    clearance : {"mean", "min", "max"}, optional
        The value of the ISO 5753-1 range the models use.
    radial_clearance : str, optional
        A diametral clearance as written (``'9 um'``), instead of ``clearance``.

    Returns
    -------
    tuple of (dict, BallBearing)
        The document (its ``warnings`` without the bearing's provenance notes, which the command adds
        as it prints) and the bearing.
    """
    from .. import catalog as _catalog
    from .. import tables
    if clearance is not None and radial_clearance is not None:
        raise InputError("clearance: give --clearance or --radial-clearance, not both")
    if clearance is not None and clearance not in ("mean", "min", "max"):
        raise InputError(f"clearance must be one of ['mean', 'min', 'max'], got {clearance!r}")
    b = _catalog.get(name, catalog=catalog, clearance=clearance or "mean")
    if getattr(b, "type", None) in ("cylindrical", "tapered", "spherical"):  # a RollerBearing (issue 32)
        return _roller_document(b, name, catalog=catalog, clearance=clearance, radial_clearance=radial_clearance)
    if radial_clearance is not None:
        from ..units import parse_quantity
        value = parse_quantity(radial_clearance, "length", "radial-clearance")  # <= 0: a preload (issue 30)
        est = tuple(f for f in b.estimated_fields if f not in ("radial_clearance",))
        b = b.replace(radial_clearance=value, estimated_fields=est,
                      sources={**b.sources, "radial_clearance": "given (--radial-clearance)"})
    info = tables.bearing_summary(b)
    extra = _catalog.details(name) if not _catalog._is_builtin_entry(name) else None
    if extra:
        info.update({k: v for k, v in extra.items() if k != "row"})
    for key in ("seal", "seals", "tolerance_class"):
        info[key] = getattr(b, key)
    # issue 30: the maker's f0, the preload class of the designation and its preload, where there are
    for key, value in (("calculation_factor_f0", b.static_load_factor), ("preload_class", b.preload_class),
                       ("preload_N", b.preload)):
        if value is not None:
            info[key] = value
    info["iso5753_clearance"] = _clearance_range(b, clearance, radial_clearance)
    given = {k: getattr(b, k) for k in ("dynamic_load_rating", "static_load_rating", "fatigue_load_limit")}
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        if None not in given.values():  # the catalog's three ratings, as ratings.bearing_ratings gives them,
            # without its f0 (not shown), whose Hertz contact imports scipy: show answers within 0.5 s
            info.update({f"{k}_N": float(v) for k, v in given.items()})
            info["rating_source"] = dict.fromkeys(given, "catalog")
        else:
            from .. import (
                ratings,  # (its Hertz contact imports scipy: only when a rating is computed)
            )
            try:  # one set of ratings per bearing, whichever command asks (ratings.bearing_ratings)
                info.update(tables.ratings(ratings.bearing_ratings(b)))
            except InputError as exc:  # neither catalog ratings nor the ball set to compute them
                info.update({f"{k}_N": v for k, v in given.items()})
                info["rating_source"] = {k: "catalog" for k, v in given.items() if v is not None}
                caught.append(warnings.WarningMessage(f"ratings: not computed ({exc})", UserWarning, "", 0))
    if b.estimated_fields:  # a rating computed from the geometry is computed from an estimate
        info["rating_source"] = {k: (f"{v}, from the estimated geometry" if v != "catalog" else v)
                                 for k, v in (info.get("rating_source") or {}).items()}
    notes = list(dict.fromkeys(str(c.message) for c in caught))
    info.update(sources=dict(b.sources), estimated_fields=list(b.estimated_fields),
                inputs={"name": name, "catalog": None if catalog is None else str(catalog),
                        "clearance": clearance, "radial_clearance": radial_clearance}, warnings=notes)
    return info, b


def _roller_document(b, name, *, catalog, clearance, radial_clearance):
    """``catalog show`` of a roller bearing: its fields, the catalogue's data, and the roller set the models
    use, estimated where no source gives it (labelled in ``estimated_fields`` and ``sources``)."""
    from .. import catalog as _catalog
    from ..catalog import _rollers
    if clearance is not None:
        raise InputError(f"clearance: --clearance picks a value of a deep-groove ball bearing's ISO 5753-1 range; "
                         f"{b.designation!r} is a {b.type} roller bearing: give --radial-clearance")
    if radial_clearance is not None:
        from ..units import parse_quantity
        value = parse_quantity(radial_clearance, "length", "radial-clearance")
        b = b.replace(radial_clearance=value, sources={**b.sources, "radial_clearance": "given (--radial-clearance)"})
    notes = []
    shown = b
    if b.type != "spherical" and not b.has_internal_geometry:  # the set the models would use, labelled
        from ..rollers.estimation import with_estimated_geometry
        try:
            shown = with_estimated_geometry(b)
        except InputError as exc:
            notes.append(f"roller set: not estimated ({exc})")
    elif b.type == "spherical":
        notes.append(f"{b.designation}: a spherical roller bearing: ratings, life and friction only (its load "
                     "distribution is not modelled, so no roller set is estimated)")
    info = _rollers.summary(shown)
    extra = _catalog.details(name) if not _catalog._is_builtin_entry(name) else None
    if extra:
        info.update({k: (v or None) if isinstance(v, list) else v for k, v in extra.items() if k != "row"})
    given = {k: getattr(b, k) for k in ("dynamic_load_rating", "static_load_rating", "fatigue_load_limit")}
    if None not in given.values():
        info.update({f"{k}_N": float(v) for k, v in given.items()})
        info["rating_source"] = dict.fromkeys(given, "catalog")
    else:
        from .. import ratings, tables
        try:
            info.update(tables.ratings(ratings.bearing_ratings(shown)))
        except InputError as exc:
            info.update({f"{k}_N": v for k, v in given.items()})
            info["rating_source"] = {k: "catalog" for k, v in given.items() if v is not None}
            notes.append(f"ratings: not computed ({exc})")
    info.update(sources=dict(shown.sources), estimated_fields=list(shown.estimated_fields),
                inputs={"name": name, "catalog": None if catalog is None else str(catalog), "clearance": clearance,
                        "radial_clearance": radial_clearance}, warnings=notes)
    return info, shown


def _catalog_document(parsed):
    """``catalog show NAME --json`` for the built-in catalog, with the provenance notes the command adds."""
    from .. import catalog

    given = {k: (str(parsed.given[k]).strip() if k in parsed.given else None)
             for k in ("clearance", "radial_clearance")}
    with warnings.catch_warnings():
        info, b = catalog_document(parsed.values["name"], **given)
    notes = list(info["warnings"])  # the command adds the provenance notes as emit_json does
    info["warnings"] = notes + [n for n in dict.fromkeys(catalog.provenance_notes(b)) if n not in notes]
    return json.loads(json.dumps(info, default=float, allow_nan=True))


_SEARCH_TOLERANCE = 0.5e-3  # the page's search: a typed size matches within 0.5 mm [m]
_SEARCH_KEYS = ("bore", "outside_diameter", "width", "type", "series")


def _search_document(parsed):
    """The catalog search of the web.

    ``bearings``, ``inputs`` and ``warnings`` are what ``bearinglab catalog search --json`` prints for
    the same ``bore``, ``outside_diameter``, ``width``, ``type`` and ``series`` (the standard series of
    :func:`bearinglab.catalog.search`; ``bearings`` is empty when none of them is given). ``matches``
    serves the page's picker: the named catalog bearings whose designation or alias contains
    ``query``, then the standard-series bearings of ``catalog.search``, every size within 0.5 mm;
    ``count`` matches in all, at most ``limit`` listed (``truncated``).
    """
    from .. import catalog, tables
    from ..catalog import _series

    values = parsed.values
    size = {k: values.get(k) for k in _SEARCH_KEYS}
    echo = {k: (str(parsed.given[k]).strip() if k in parsed.given else None) for k in _SEARCH_KEYS}
    given = any(v is not None for v in size.values())
    bearings = catalog.search(**size) if given else []

    query = str(values.get("query", "")).strip().lower()
    aliases = catalog.aliases()

    def wanted(name):
        return not query or any(query in w.lower() for w in (name, *aliases.get(name, [])))

    def within(x_mm, key):
        return values.get(key) is None or (x_mm is not None and
                                           abs(x_mm * 1e-3 - values[key]) <= _SEARCH_TOLERANCE)

    matches = []
    if values.get("width") is None and values.get("series") is None:  # named rows carry neither
        from ..catalog import _rollers
        series_names = set(_series.records()) | set(_rollers.records())  # these come through catalog.search
        for name in catalog.names():
            if name in series_names or not wanted(name):
                continue
            row = dict(tables.catalog_entry(name, catalog.get(name)), aliases=aliases.get(name, []))
            kind = {"radial": "deep-groove"}.get(row["type"], row["type"])
            if (within(row.get("bore_mm"), "bore") and within(row.get("outside_diameter_mm"),
                                                                "outside_diameter")
                    and values.get("type") in (None, kind)):
                matches.append(row)
    for row in catalog.search(**size, tolerance=_SEARCH_TOLERANCE):  # every row when no size
        if wanted(row["name"]):
            matches.append(dict(row, aliases=aliases.get(row["name"], [])))
    limit = values.get("limit", 50)
    return {"bearings": bearings, "inputs": echo, "warnings": [], "query": values.get("query", ""),
            "count": len(matches), "truncated": len(matches) > limit, "matches": matches[:limit]}


def run(parsed):
    """The JSON document of a checked request: what ``bearinglab <command> ... --json`` prints.

    Parameters
    ----------
    parsed : Parsed
        From :func:`bearinglab.calculations.parse`.

    Returns
    -------
    dict or list
        The document.

    Raises
    ------
    RunFailure
        The calculation rejected its input (``kind`` "input") or did not converge ("convergence").
    """
    name = parsed.calculation.name
    if name == "catalog":
        try:
            return _catalog_document(parsed)
        except InputError as exc:
            message = str(exc)
            if not message.startswith("bearing: "):  # an option's message names its option
                raise run_failure(message, parsed.calculation, parsed.given) from None
            raise RunFailure("name", parsed.values["name"],
                             "{name}: " + message.removeprefix("bearing: ")) from None
    if name == "catalog-search":
        return check(_search_document(parsed), name)
    return _native(parsed)  # every other calculation has a document function of its own


#: the calculations computed by a function of their own (calculation name -> module of this package,
#: with ``document(parsed)``; the command line calls the same function): every registered one but the
#: catalog's two, by its ``Calculation.module``
_NATIVE = {c.name: c.document_module for c in CALCULATIONS.values() if c.name not in ("catalog", "catalog-search")}


def _module(calc):
    """The module whose ``document(parsed)`` computes ``calc``: one of this package (``life``), or any
    module by its full dotted name."""
    name = calc.document_module
    return importlib.import_module(name if "." in name else f".{name}", __package__)


def _native(parsed):
    """The document of a calculation of :data:`_NATIVE`; its errors as RunFailures."""
    from .._io import json_value
    from ..errors import ConvergenceError

    module = _module(parsed.calculation)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)  # every result is checked finite
            # NaN as null, numpy as plain numbers; every number finite or an error (a calculation whose
            # document function is not decorated is checked here all the same)
            return json_value(finite(parsed.calculation.name)(module.document)(parsed))
    except RequestError:
        raise
    except ConvergenceError as exc:  # no physical solution is the input's fault (2); else the solver's
        raise RunFailure(None, None, exc.summary, "input" if exc.physical else "convergence") from None
    except InputError as exc:  # the physics names no field
        raise RunFailure(None, None, str(exc)) from None


#: the calculations whose command draws a figure, and the option it takes
_PLOTS = {"high-speed": ".svg", "load-distribution": ".svg", "bearing-set": ".svg", "shaft": ".svg"}


def figure_svg(parsed):
    """The calculation's own figure (its command's ``--plot``) as SVG text, or '' when it has none.

    Parameters
    ----------
    parsed : Parsed
        A checked request (a high-speed figure needs at least two thrusts).

    Returns
    -------
    str
    """
    name = parsed.calculation.name
    if name == "high-speed":
        return _high_speed_svg(parsed)
    if name not in _PLOTS:
        return ""
    return _native_figure(parsed)  # drawn from the document by the calculation's own figure function


def _high_speed_svg(parsed):
    """The high-speed map drawn from the request's solve (:func:`.high_speed.figure`), as SVG text; ''
    for fewer than two thrusts or a request that fails."""
    from ..errors import ConvergenceError
    from . import high_speed

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)
            fig, _ = high_speed.figure(high_speed.compute(parsed))
    except (InputError, ConvergenceError):  # a RequestError too: the document says why
        return ""
    out = io.StringIO()
    fig.savefig(out, format="svg")
    svg = out.getvalue()
    start = svg.find("<svg")
    return svg[start:] if start >= 0 else ""


def _native_figure(parsed):
    """The SVG of a native calculation's figure, drawn from its document; '' where it has none."""
    module = _module(parsed.calculation)
    try:
        doc = _native(parsed)
    except RequestError:
        return ""
    if isinstance(doc, list):
        doc = doc[0]
    buffer = io.BytesIO()
    module.figure(doc).savefig(buffer, format="svg", dpi=120)
    svg = buffer.getvalue().decode("utf-8")
    start = svg.find("<svg")
    return svg[start:] if start >= 0 else ""
