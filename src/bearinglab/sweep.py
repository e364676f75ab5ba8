"""Parameter sweeps: a calculation evaluated over the Cartesian product of parameter values, in chunks.

A sweep file (TOML) names a model, a bearing, parameter lists or ranges, the output and the executor::

    model = "axial-angle"                 # any calculation of bearinglab.calculations.CALCULATIONS
    bearing = "4-1006095"                 # or a [bearing] table in the catalog format
    [parameters]                          # each: a value, a list, or "start:stop:step" with units
    axial_load = "0.5kgf:20kgf:0.5kgf"
    contact_angle = ["10 deg", "12 deg", "15 deg"]
    [constants]                           # optional: one value each, the same in every case
    [output]
    file = "sweep.parquet"                # .parquet or .csv, relative to the sweep file
    [execution]                           # all optional; the command line overrides them
    executor = "serial"                   # serial | local | tcp://host:8786
    workers = 2
    chunk_size = 10000

Two paths. The batch models of :data:`MODELS` (``axial-angle``, ``stand-load``, ``frequencies``,
``high-speed``) evaluate a whole chunk at once, vectorized, with their own columns and, for the test-stand
models, the geometry variants of :data:`GEOMETRY_PARAMETERS`; a file runs through them when each of its
parameters is theirs. Every other file, of any calculation, runs case by case
(:mod:`bearinglab._sweep_documents`): the parameters and constants are the calculation's fields, each
case is the document its command prints with ``--json``, and its row is that document flattened (nested
keys joined by a dot), with the inputs as columns too. ``path = "document"`` asks for this path for a
batch model's calculation too, ``path = "batch"`` insists on the batch model.

Functions
---------
MODELS          name -> SweepModel (parameters with their kinds, the chunk function, outputs)
load_sweep      read and check a sweep file -> SweepSpec
flatten_document  a calculation's document -> one row (the case-by-case path's rule)
case_grid       the Cartesian product of the parameter values, flattened to per-case arrays
run_sweep       evaluate a SweepSpec through :mod:`bearinglab.parallel`; inputs and outputs as columns
check_file_executor  refuse a scheduler on another machine named by a file, unless confirmed
write_table     write columns to CSV or Parquet, whole or not at all

Every chunk function is pure and flags failed cases (``converged`` False and a ``failure`` reason)
instead of raising, so one bad case does not stop a sweep. A file that cannot be read (an unknown
parameter, a value of the wrong kind, too many cases) is refused whole, before any case runs.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable
from pathlib import Path
from typing import NamedTuple

import numpy as np

from . import (
    _bounds,
    _document_paths,
    _sweep_documents,
    catalog,
    geometry,
    hertz,
    kinematics,
    parallel,
    stand,
    tables,
)
from ._sweep_documents import flatten_document
from .bearing import BallBearing
from .errors import CatalogError, ConvergenceError, InputError
from .stand import static
from .units import KGF, parse_quantity, parse_values

__all__ = [
    "GEOMETRY_PARAMETERS",
    "MODELS",
    "DocumentSweep",
    "SweepModel",
    "SweepSpec",
    "case_grid",
    "check_file_executor",
    "flatten_document",
    "load_sweep",
    "register_model",
    "run_sweep",
    "write_table",
]

#: Bearing fields a sweep may vary, with their kinds (geometry variants).
GEOMETRY_PARAMETERS = {
    "n_balls": "dimensionless",
    "ball_diameter": "length",
    "pitch_diameter": "length",
    "inner_conformity": "dimensionless",
    "outer_conformity": "dimensionless",
    "contact_angle": "angle",
}


class SweepModel(NamedTuple):
    """A model a sweep can evaluate."""

    name: str
    parameters: dict  # case parameter -> kind (besides the geometry parameters)
    evaluate: Callable  # pure chunk function(**per-case arrays, **constants) -> dict of arrays
    description: str
    optional: tuple = ()  # parameters that may be left out
    geometry: bool = True  # accepts GEOMETRY_PARAMETERS variants
    engine: bool = False  # its chunk function takes the engine of the stand solve (stand.engine_for)


class DocumentSweep(NamedTuple):
    """What a sweep of a calculation, case by case, needs besides the fields of :class:`SweepSpec`."""

    calculation: object  # bearinglab.calculations.Calculation
    columns: dict  # parameter -> (input column name, the value shown for each of its values)
    bearing_table: dict | None = None  # the file's [bearing] table, a bearing file of each document


class SweepSpec(NamedTuple):
    """A checked sweep file."""

    model: SweepModel
    bearing: BallBearing | None  # None: a calculation swept over bearings, or given none
    parameters: dict  # name -> SI array of values (batch); name -> list of the cases' values (document)
    output: Path | None
    executor: str
    workers: int | None
    chunk_size: int
    constants: dict  # batch: the model's options; document: field -> value, the same in every case
    document: DocumentSweep | None = None  # the case-by-case path (None: the batch model)

    @property
    def path(self):
        """``"batch"`` (a model of :data:`MODELS`) or ``"document"`` (any calculation, case by case)."""
        return "batch" if self.document is None else "document"


def _geometry_arrays(n, bearing, cases):
    out = {}
    for name in GEOMETRY_PARAMETERS:
        if name in cases:
            out[name] = np.asarray(cases[name], dtype=float)
        else:
            value = getattr(bearing, name) if bearing is not None else None
            out[name] = np.full(n, np.nan if value is None else float(value))
    return out


def _valid_geometry(g):
    """Per-case validity of the geometry, with the reason of the first failed rule."""
    rules = [
        ("n_balls must be an integer >= 1", (g["n_balls"] >= 1) & (g["n_balls"] == np.round(g["n_balls"]))),
        ("ball_diameter must be > 0", g["ball_diameter"] > 0),
        ("pitch_diameter must be > ball_diameter", g["pitch_diameter"] > g["ball_diameter"]),
        ("inner_conformity must be > 0.5", g["inner_conformity"] > 0.5),
        ("outer_conformity must be > 0.5", g["outer_conformity"] > 0.5),
        ("contact_angle must be in (0, 90) deg", (g["contact_angle"] > 0) & (g["contact_angle"] < np.pi / 2)),
    ]
    return rules


def _flags(n, rules):
    ok = np.ones(n, dtype=bool)
    reason = np.full(n, "", dtype=object)
    for text, good in rules:
        bad = ok & ~np.asarray(good, dtype=bool)
        reason[bad] = text
        ok &= ~bad
    return ok, reason


def _nan(n):
    return np.full(n, np.nan)


def _evaluate_axial_angle(axial_load, engine="numpy", **cases):
    """Chunk function of the ``axial-angle`` model (spec 000 with exact Hertz, C* at the operating angle
    and the elastic constant of the bearing's materials, as :func:`bearinglab.stand.stand_analysis`);
    ``engine`` of the angle solve, chosen once for the whole sweep (:func:`run_sweep`)."""
    fa = np.asarray(axial_load, dtype=float)
    n = fa.size
    bearing = cases.pop("bearing", None)
    g = _geometry_arrays(n, bearing, cases)
    ok, reason = _flags(n, [("axial_load must be > 0", fa > 0)] + _valid_geometry(g))
    angle, cstar, q, da = _nan(n), _nan(n), _nan(n), _nan(n)
    idx = np.flatnonzero(ok)
    if idx.size:
        s = {k: v[idx] for k, v in g.items()}
        ce = hertz.elastic_constant(bearing.reduced_modulus) if bearing is not None else None
        try:
            c, a = stand.constants_at_operating_angle(
                fa[idx], s["n_balls"].astype(int), s["ball_diameter"], s["pitch_diameter"], s["inner_conformity"],
                s["outer_conformity"], s["contact_angle"], elastic_constant=ce, engine=engine)
            cstar[idx] = c.force_characteristic
        except ConvergenceError:  # flag the chunk's cases rather than report an unsettled angle
            a = np.full(idx.size, np.nan)
            reason[idx] = "no convergence"
            ok[idx] = False
        bd = geometry.total_curvature(s["inner_conformity"], s["outer_conformity"]) * s["ball_diameter"]
        angle[idx] = a
        q[idx] = fa[idx] / (s["n_balls"] * np.sin(a))
        da[idx] = static.axial_displacement_ratio(a, s["contact_angle"]) * bd
    return {"operating_contact_angle_deg": np.degrees(angle), "load_deflection_constant_kgf": cstar / KGF,
            "load_deflection_constant_N": cstar,
            "axial_displacement_um": da * 1e6, "ball_load_N": q, "converged": ok, "failure": reason}


def _evaluate_stand_load(speed, **cases):
    """Chunk function of the ``stand-load`` model (spec 000 section 3)."""
    w = np.asarray(speed, dtype=float)
    n = w.size
    g = _geometry_arrays(n, cases.pop("bearing", None), cases)
    rules = [("speed must be >= 0", w >= 0)] + [r for r in _valid_geometry(g) if "conformity" not in r[0]]
    ok, reason = _flags(n, rules)
    lo = _nan(n)
    if ok.any():
        lo[ok] = stand.min_axial_load(w[ok], g["n_balls"][ok].astype(int), g["ball_diameter"][ok],
                                       g["pitch_diameter"][ok], g["contact_angle"][ok]).minimum
    return {"min_axial_load_N": lo, "max_axial_load_N": 1.2 * lo, "min_axial_load_kgf": lo / KGF,
            "max_axial_load_kgf": 1.2 * lo / KGF, "converged": ok, "failure": reason}


def _evaluate_frequencies(speed, axial_load=None, engine="numpy", **cases):
    """Chunk function of the ``frequencies`` model: orders and Hz at the nominal or the operating angle."""
    w = np.asarray(speed, dtype=float)
    n = w.size
    bearing = cases.pop("bearing", None)
    g = _geometry_arrays(n, bearing, cases)
    out = {}
    if axial_load is not None:  # operating angle; the axial-angle model checks the whole geometry
        res = _evaluate_axial_angle(axial_load, engine, bearing=bearing, **cases)
        angle = np.radians(res["operating_contact_angle_deg"])
        ok, reason = res["converged"], res["failure"]
        out["operating_contact_angle_deg"] = res["operating_contact_angle_deg"]
    else:  # nominal angle; kinematics needs neither the conformities nor a positive angle
        angle = g["contact_angle"]
        ok, reason = _flags(n, [r for r in _valid_geometry(g) if "conformity" not in r[0] and "(0, 90)" not in r[0]])
    ok = ok & (w >= 0)
    reason = np.where((w < 0) & (reason == ""), "speed must be >= 0", reason)
    freqs = {k: _nan(n) for k in ("shaft", "ftf", "bpfo", "bpfi", "bsf", "two_bsf")}
    if ok.any():
        f = kinematics.characteristic_frequencies(w[ok], g["ball_diameter"][ok], g["pitch_diameter"][ok],
                                                  g["n_balls"][ok].astype(int), angle[ok])
        for k, values in freqs.items():
            values[ok] = getattr(f, k)
    for k, v in freqs.items():
        out[f"{k}_hz"] = v / (2 * math.pi)
        if k != "shaft":
            with np.errstate(invalid="ignore", divide="ignore"):
                out[f"{k}_order"] = v / freqs["shaft"]
    out.update(converged=ok, failure=reason)
    return out


def _evaluate_high_speed(axial_load, speed, bearing, **options):
    """Chunk function of the ``high-speed`` model (spec 004; options as :func:`quasistatic.contact_angles`)."""
    import warnings

    from . import quasistatic
    from .errors import ValidityWarning

    fa, w = np.asarray(axial_load, dtype=float), np.asarray(speed, dtype=float)
    ok, reason = _flags(fa.size, [("axial_load must be > 0", fa > 0), ("speed must be >= 0", w >= 0)])
    # the same columns and dtypes in every chunk, even one without a valid case: floats, or objects
    # for the columns that have no unit factor (converged, iterations, status, method)
    cols = {c.name: _nan(fa.size) if c.factor is not None else np.full(fa.size, None, dtype=object)
            for c in tables.HIGH_SPEED if c.name not in ("axial_load_N", "speed_rpm")}
    idx = np.flatnonzero(ok)
    if idx.size:
        with warnings.catch_warnings():  # per-case validity is in the columns (friction_coefficient)
            warnings.simplefilter("ignore", ValidityWarning)
            state = quasistatic.high_speed_analysis(bearing, fa[idx], w[idx], on_failure="flag", **options)
        for name, col in tables.high_speed(state).items():
            if name in cols:
                cols[name][idx] = col
        failed = ~np.asarray(state.converged, dtype=bool).ravel()
        reason[idx[failed]] = np.asarray(state.status, dtype=object).ravel()[failed]
        ok[idx[failed]] = False
    cols.pop("converged", None)
    cols.update(converged=ok, failure=reason)
    return cols


MODELS: dict[str, SweepModel] = {}


def register_model(model: SweepModel):
    """Make a model available to sweep files (the capability modules register theirs).

    Parameters
    ----------
    model : SweepModel
        Name, case parameters with their kinds, the pure chunk function and a description.

    Returns
    -------
    SweepModel
        The model, now in :data:`MODELS`.
    """
    MODELS[model.name] = model
    return model


register_model(SweepModel("axial-angle", {"axial_load": "force"}, _evaluate_axial_angle,
                          "operating contact angle under axial load (the test-stand method)", engine=True))
register_model(SweepModel("stand-load", {"speed": "speed"}, _evaluate_stand_load,
                          "minimum axial load on a test stand (the test-stand method)"))
register_model(SweepModel("high-speed", {"axial_load": "force", "speed": "speed"}, _evaluate_high_speed,
                          "high-speed angular-contact bearing under thrust (the high-speed quasi-static model)", geometry=False))
register_model(SweepModel("frequencies", {"speed": "speed", "axial_load": "force"}, _evaluate_frequencies,
                          "characteristic frequencies at the nominal or operating angle", optional=("axial_load",),
                          engine=True))


def _fail(path, where, msg):
    raise CatalogError(f"{path}: {where}: {msg}")


def _values(path, name, value, kind):
    if isinstance(value, list):
        if not value:
            _fail(path, f"parameters.{name}", "empty list")
        parts = [_values(path, name, v, kind) for v in value]
        return np.concatenate(parts)
    try:
        if isinstance(value, (int, float)) and not isinstance(value, bool):  # finite, by the grammar's rules
            return np.array([parse_quantity(value, kind, name)])
        return np.atleast_1d(parse_values(str(value), kind, name))
    except InputError as exc:
        _fail(path, f"parameters.{name}", str(exc))


def load_sweep(path):
    """Read and check a sweep file.

    Parameters
    ----------
    path : str or Path
        The TOML sweep file (format in the module docstring).

    Returns
    -------
    SweepSpec

    Raises
    ------
    CatalogError
        Naming the file, the table and the field; a grid of more than
        :data:`bearinglab._bounds.MAX_SWEEP_CASES` cases is refused here, before it is built.
    """
    path = Path(path)
    doc = catalog.read_toml(path)
    name = doc.get("model")
    calculations = _calculations()
    if not isinstance(name, str) or name not in MODELS and name not in calculations:
        _fail(path, "model", f"must be one of {sorted(set(MODELS) | set(calculations))}, got {name!r}")
    way = doc.get("path")
    if way not in (None, "batch", "document"):
        _fail(path, "path", f"must be 'batch' or 'document', got {way!r}")
    if way == "batch" and name not in MODELS:
        _fail(path, "path", f"{name!r} has no batch model (batch models: {', '.join(sorted(MODELS))})")
    params = doc.get("parameters")
    if name not in MODELS or way == "document" or way is None and isinstance(params, dict) and not all(
            k in _batch_parameters(MODELS[name]) for k in params):
        return _load_document_sweep(path, doc, calculations[name])
    model = MODELS[name]
    if "bearing" not in doc:
        _fail(path, "bearing", "missing: give a catalog name or a [bearing] table")
    b = doc["bearing"]
    bearing = (catalog.bearing_from_table(b, name=str(b.get("designation", "sweep")), file=path)
               if isinstance(b, dict) else catalog.get(str(b)))
    params = doc.get("parameters")
    if not isinstance(params, dict) or not params:
        _fail(path, "parameters", "missing: give at least one parameter list or range")
    kinds = _batch_parameters(model)
    values = {}
    for key, value in params.items():
        if key not in kinds:
            _fail(path, f"parameters.{key}", f"unknown parameter of model {name!r} (known: {', '.join(sorted(kinds))})")
        values[key] = _values(path, key, value, kinds[key])
    required = [k for k in model.parameters if k not in values and k not in model.optional]
    if required:
        _fail(path, "parameters", f"model {name!r} needs {', '.join(required)}")
    try:  # the grid is built only when run: its size is checked now, from the lengths alone
        _check_grid(values)
    except InputError as exc:
        _fail(path, "parameters", str(exc))
    output, executor, workers, chunk = _output_and_execution(path, doc)
    return SweepSpec(model, bearing, values, output, executor, workers, chunk, dict(doc.get("constants", {})))


def _calculations():
    from .calculations import CALCULATIONS

    return CALCULATIONS


def _batch_parameters(model):
    """The parameters of a batch model with their kinds (the geometry variants too where it takes them)."""
    kinds = dict(model.parameters)
    if model.geometry:
        kinds.update(GEOMETRY_PARAMETERS)
    return kinds


def _output_and_execution(path, doc):
    """The [output] file and the [execution] table of a sweep file."""
    out = doc.get("output", {}).get("file")
    output = (path.parent / out) if out else None
    if output is not None and output.suffix not in (".csv", ".parquet"):
        _fail(path, "output.file", f"must end in .csv or .parquet, got {out!r}")
    ex = doc.get("execution", {})
    chunk = ex.get("chunk_size", parallel.DEFAULT_CHUNK_SIZE)
    return output, str(ex.get("executor", "serial")), ex.get("workers"), int(chunk)


def _load_document_sweep(path, doc, calc):
    """A sweep file of any calculation, case by case: its fields, checked and expanded before any case
    runs; the number of cases refused above :data:`bearinglab._bounds.MAX_DOCUMENT_SWEEP_CASES`."""
    fields = {f.name: f for f in calc.fields}
    limit = _bounds.MAX_DOCUMENT_SWEEP_CASES
    params = doc.get("parameters")
    if not isinstance(params, dict) or not params:
        _fail(path, "parameters", "missing: give at least one parameter list or range")
    constants = doc.get("constants", {})
    if not isinstance(constants, dict):
        _fail(path, "constants", "must be a table of field = value")
    # a document given as a file name (relative to the sweep file) is the file's text
    params = {k: _document_files(path, "parameters", k, v, fields) for k, v in params.items()}
    constants = {k: _document_files(path, "constants", k, v, fields) for k, v in constants.items()}
    # a name that is no field may address a value inside a document field (supports.front.position)
    fields = dict(fields, **_addresses(path, calc, params, constants))
    given, bearing, table = {}, None, None
    if "bearing" in doc:
        b = doc["bearing"]
        if "bearing" not in fields:
            _fail(path, "bearing", f"model {calc.name!r} takes no bearing")
        if "bearing" in params or "bearing" in constants:
            _fail(path, "bearing", "give the bearing once: at the top, in [parameters] or in [constants]")
        if isinstance(b, dict):
            _, files = _sweep_documents.document_function(calc.name)
            if not files:
                _fail(path, "bearing", f"model {calc.name!r} takes catalog names, not a [bearing] table")
            designation = str(b.get("designation", "sweep"))
            bearing = catalog.bearing_from_table(b, name=designation, file=path)
            table = dict(b, designation=designation)
        else:
            names = [s.strip() for s in str(b).split(",") if s.strip()] if fields["bearing"].many else [str(b)]
            bearings = [catalog.get(n) for n in names]  # an unknown name is refused here, not per case
            bearing = bearings[0] if len(bearings) == 1 else None
            given["bearing"] = names if fields["bearing"].many else str(b)
    counts = {}
    for key, value in params.items():  # counted from the entries alone, before any value is built
        if key not in fields:
            _fail(path, f"parameters.{key}", f"unknown parameter of model {calc.name!r} (known: "
                                             f"{', '.join(sorted(fields))})")
        try:
            counts[key] = _sweep_documents.parameter_count(fields[key], value, limit=limit)
        except InputError as exc:
            _fail(path, f"parameters.{key}", str(exc))
        try:
            _bounds.check_cases(math.prod(counts.values()), " x ".join(f"{n} {k}" for k, n in counts.items()),
                                limit=limit)
        except InputError as exc:
            _fail(path, "parameters", str(exc))
    values, columns = {}, {}
    for where, entries in (("parameters", params), ("constants", constants)):
        for key, value in entries.items():
            if key not in fields:  # (a constant: the parameters are checked above)
                _fail(path, f"{where}.{key}", f"unknown parameter of model {calc.name!r} (known: "
                                             f"{', '.join(sorted(fields))})")
            if where == "constants" and key in params:
                _fail(path, f"constants.{key}", "also in [parameters]: give it once")
            try:
                cases, shown = _sweep_documents.parameter_values(fields[key], value, limit=limit)
                if key == "bearing" or calc.name == "catalog" and key == "name":  # names: refused here, as
                    for name in dict.fromkeys(n for c in cases for n in (c if isinstance(c, list) else [c])):
                        catalog.get(name)  # the file's top-level bearing, not case by case
            except InputError as exc:
                _fail(path, f"{where}.{key}", str(exc))
            if where == "parameters":
                values[key] = cases
                columns[key] = (_sweep_documents.input_column(fields[key]), shown)
            elif len(cases) != 1:
                _fail(path, f"constants.{key}", f"one value, the same in every case, got {len(cases)} (a list "
                                                f"or a range belongs in [parameters])")
            else:
                given[key] = cases[0]
    required = [f.name for f in calc.fields if f.required and f.name not in values and f.name not in given]
    if required:
        _fail(path, "parameters", f"model {calc.name!r} needs {', '.join(required)}")
    output, executor, workers, chunk = _output_and_execution(path, doc)
    model = SweepModel(calc.name, {k: fields[k].kind for k in values}, _sweep_documents.evaluate, calc.title,
                       geometry=False)
    return SweepSpec(model, bearing, values, output, executor, workers, chunk, given,
                     DocumentSweep(calc, columns, table))


def _names_file(value):
    """Whether a document field's value names a file: one line, ending in .toml or .json, no ``=``."""
    return (isinstance(value, str) and "\n" not in value.strip() and "=" not in value
            and value.strip().lower().endswith((".toml", ".json")))


def _document_files(path, where, key, value, fields):
    """The value of a [parameters] or [constants] entry, a document field's file names read as their text
    (relative to the sweep file; recorded as inputs of the run, as every file a command reads)."""
    field = fields.get(key)
    if field is None or field.kind != "document":
        return value
    items = value if isinstance(value, list) else [value]
    texts = []
    for item in items:
        if not _names_file(item):
            texts.append(item)
            continue
        source = path.parent / item.strip()
        try:
            texts.append(_bounds.read_input_bytes(source).decode("utf-8-sig"))
        except FileNotFoundError:
            _fail(path, f"{where}.{key}", f"{item.strip()}: no such file (a path relative to the sweep file)")
        except (OSError, InputError, UnicodeDecodeError) as exc:
            _fail(path, f"{where}.{key}", f"{item.strip()}: cannot read it as a text file ({exc})")
    return texts if isinstance(value, list) else texts[0]


def _addresses(path, calc, params, constants):
    """The fields of the entries that address a value inside a document (:mod:`bearinglab._document_paths`),
    each checked against every document the file gives and read like the value it replaces."""
    names = {f.name for f in calc.fields}
    out = {}
    for where, entries in (("parameters", params), ("constants", constants)):
        for key, value in entries.items():
            if key in names:
                continue
            try:
                found = _document_paths.address(calc, key)
            except InputError as exc:
                _fail(path, f"{where}.{key}", str(exc))
            if found is None:  # an unknown parameter: said below, with the fields
                continue
            field, steps = found
            given = params.get(field, constants.get(field))
            if given is None:
                _fail(path, f"{where}.{key}", f"addresses the document {field!r}, which the file does not give; "
                                              f"give {field} in [constants] (its text, a table or a file name)")
            current = None
            for k, text in enumerate(given if isinstance(given, list) else [given]):
                try:
                    document = text if isinstance(text, dict) else _document_paths.parse_text(text, field)
                    table, last = _document_paths.locate(document, steps, key)
                except InputError as exc:
                    _fail(path, f"{where}.{key}", str(exc) + (f" (document {k})" if isinstance(given, list) else ""))
                current = table.get(last) if current is None else current
            out[key] = _document_paths.field_of(key, current, value)
    return out


def _check_grid(parameters):
    """The number of cases of the product, refused above :data:`bearinglab._bounds.MAX_SWEEP_CASES`
    before anything is allocated (a product of Python ints: no overflow)."""
    sizes = {k: int(np.size(v)) for k, v in parameters.items()}
    _bounds.check_cases(math.prod(sizes.values()), " x ".join(f"{n} {k}" for k, n in sizes.items()),
                        limit=_bounds.MAX_SWEEP_CASES)


def case_grid(parameters):
    """Flatten the Cartesian product of parameter values to per-case arrays (last parameter fastest).

    Parameters
    ----------
    parameters : dict
        name -> 1-D array of values.

    Returns
    -------
    dict
        name -> array of length prod(len(values)).

    Examples
    --------
    >>> g = case_grid({"a": np.array([1.0, 2.0]), "b": np.array([10.0, 20.0, 30.0])})
    >>> g["a"].tolist(), g["b"].tolist()
    ([1.0, 1.0, 1.0, 2.0, 2.0, 2.0], [10.0, 20.0, 30.0, 10.0, 20.0, 30.0])
    """
    names = list(parameters)
    _check_grid(parameters)
    mesh = np.meshgrid(*[np.asarray(parameters[k], dtype=float) for k in names], indexing="ij")
    return {k: m.ravel() for k, m in zip(names, mesh)}


def check_file_executor(spec, *, allow_remote_executor=False, option="allow_remote_executor=True"):
    """Refuse the scheduler a sweep file names when it is on another machine, unless confirmed.

    A sweep file can come from someone else; its ``[execution] executor`` would send the cases (and the
    file's constants) to that machine, and run there whatever it answers. The caller confirms it.

    Parameters
    ----------
    spec : SweepSpec
        From :func:`load_sweep`; its ``executor`` is the file's.
    allow_remote_executor : bool, optional
        The confirmation: a scheduler on another machine is accepted.
    option : str, optional
        How the caller confirms it, for the message (``--allow-remote-executor`` on the command line).

    Raises
    ------
    InputError
        The file names a scheduler that is not on this machine and ``allow_remote_executor`` is False.
    """
    if not allow_remote_executor and not parallel.is_local_address(spec.executor):
        raise InputError(f"executor: the sweep file names the scheduler {spec.executor!r}, not on this machine; "
                         f"confirm it with {option} (a file can come from someone else)")


def run_sweep(spec, *, execution=None, executor=None, workers=None, chunk_size=None, memory_limit=None,
              processes=None, progress=None, allow_remote_executor=False):
    """Evaluate a sweep; returns the input columns (engineering units) and the model's output columns.

    Parameters
    ----------
    spec : SweepSpec
        From :func:`load_sweep`.
    execution : bearinglab.parallel.Execution, optional
        Executor, workers, chunk size and progress as one value; it overrides the file's
        ``[execution]`` table, except for the workers and the chunk size when it leaves them ``None``.
        The keyword arguments below are the older spelling; give one or the other.
    executor : str, optional
        Overrides the file's executor.
    workers : int, optional
        Overrides the file's worker count. [-]
    chunk_size : int, optional
        Overrides the file's chunk size. [-]
    memory_limit : str or int, optional
        Memory limit per local worker, a size with a unit (``"2 GiB"``;
        :func:`bearinglab.parallel.parse_memory_limit`).
    processes : bool, optional
        Local workers as processes (default) or threads.
    progress : callable or "dask", optional
        See :func:`bearinglab.parallel.run_cases`.
    allow_remote_executor : bool, optional
        Run on the scheduler the file names when it is on another machine
        (:func:`check_file_executor`); not needed when ``execution`` or ``executor`` is given.

    Returns
    -------
    dict of str to ndarray
        Batch models: the inputs as :func:`bearinglab.tables.input_columns` (``axial_load_N``,
        ``speed_rpm``, ...), then the model's outputs, case by case. Any other calculation: the inputs
        (:func:`bearinglab._sweep_documents.input_column`: ``fx_N``, ``speed_rpm``, ``oil``), then each
        case's document flattened (:func:`flatten_document`; a key the document shares with an input
        column, such as high-speed's ``axial_load_N``, holds the document's value where the case ran),
        then ``converged`` and ``failure`` (the message the single command prints, '' where it ran).
    """
    if execution is None and executor is None:
        check_file_executor(spec, allow_remote_executor=allow_remote_executor)
    ex = parallel._execution(execution, executor=executor or (None if execution else spec.executor),
                             workers=workers, chunk_size=chunk_size, memory_limit=memory_limit,
                             processes=processes, progress=progress)
    if ex.workers is None and spec.workers is not None:
        ex = dataclasses.replace(ex, workers=spec.workers)
    ex = ex.with_default_chunk_size(spec.chunk_size)
    if spec.document is not None:
        return _run_documents(spec, ex)
    cases = case_grid(spec.parameters)
    constants = dict(spec.constants, bearing=spec.bearing)
    if spec.model.engine:  # one engine for the whole sweep, so that the chunk size does not choose it
        n = max((np.size(v) for v in cases.values()), default=0)
        constants["engine"] = stand.engine_for(n)
    out = parallel.run_cases(spec.model.evaluate, cases, constants=constants, execution=ex)
    columns = tables.input_columns(cases, dict(GEOMETRY_PARAMETERS, **spec.model.parameters))
    columns.update(out)
    return columns


def _run_documents(spec, ex):
    """A sweep of a calculation, case by case: the input columns, then the documents' columns."""
    # the cases as positions in each parameter's values (a grid of small integers), then the values
    index = {k: m.astype(np.intp) for k, m in case_grid({k: np.arange(len(v), dtype=float)
                                                         for k, v in spec.parameters.items()}).items()}
    cases, columns = {}, {}
    for key, values in spec.parameters.items():
        held = np.empty(len(values), dtype=object)  # one object per value (a list of bearing names too)
        held[:] = [v for v in values]
        cases[key] = held[index[key]]
        name, shown = spec.document.columns[key]
        columns[name] = _typed(shown)[index[key]]
    constants = {"calculation": spec.document.calculation.name, "given": dict(spec.constants),
                 "bearing_table": spec.document.bearing_table}
    chunks = parallel.run_chunks(_sweep_documents.evaluate, cases, constants=constants, execution=ex)
    outputs, computed = _sweep_documents.merge(chunks)
    for key, column in outputs.items():
        if key in columns:  # the document echoes an input: its value where the case ran, the input's elsewhere
            mixed = column.astype(object) if column.dtype != columns[key].dtype else column.copy()
            mixed[~computed] = columns[key][~computed]
            column = mixed
        columns[key] = column
    return columns


def _typed(values):
    """A list of one kind of value as an array: floats, ints (objects beyond int64), booleans or objects."""
    if all(isinstance(v, bool) for v in values):
        return np.array(values, dtype=bool)
    if all(isinstance(v, int) and not isinstance(v, bool) and -2**63 <= v < 2**63 for v in values):
        return np.array(values, dtype=np.int64)
    if all(isinstance(v, float) for v in values):
        return np.array(values, dtype=float)
    out = np.empty(len(values), dtype=object)
    out[:] = list(values)
    return out


def write_table(columns, path):
    """Write columns to ``path`` (.csv or .parquet), whole or not at all, creating its directory.

    Parameters
    ----------
    columns : dict of str to ndarray
        Equal-length columns.
    path : str or Path
        Target file; its suffix chooses the format (cells as :func:`bearinglab.tables.write_table`).
    """
    path = Path(path)
    if path.suffix not in (".csv", ".parquet"):
        raise InputError(f"output must end in .csv or .parquet, got {path.name!r}")
    path.parent.mkdir(parents=True, exist_ok=True)
    arrays = {k: np.asarray(v) for k, v in columns.items()}
    if path.suffix == ".parquet" and any(v.dtype == object and any(x is None for x in v.tolist())
                                         for v in arrays.values()):
        # a value a case does not have (a failed case's text) is null, not the text 'None' that
        # tables.write_table writes for it; every other cell as tables.write_table writes it
        import pyarrow as pa
        import pyarrow.parquet as pq

        from ._io import atomic_output

        table = pa.table({k: pa.array([None if x is None else str(x) for x in v.tolist()], type=pa.string())
                          if v.dtype == object else v for k, v in arrays.items()})
        with atomic_output(path, suffix=".parquet") as tmp:
            pq.write_table(table, tmp)
        return
    tables.write_table(columns, path)
