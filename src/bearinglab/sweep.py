"""Parameter sweeps: a model evaluated over the Cartesian product of parameter values, in chunks.

A sweep file (TOML) names a model, a bearing, parameter lists or ranges, the output and the executor::

    model = "axial-angle"                 # see MODELS
    bearing = "4-1006095"                 # or a [bearing] table in the catalog format
    [parameters]                          # each: a value, a list, or "start:stop:step" with units
    axial_load = "0.5kgf:20kgf:0.5kgf"
    contact_angle = ["10 deg", "12 deg", "15 deg"]
    [output]
    file = "sweep.parquet"                # .parquet or .csv, relative to the sweep file
    [execution]                           # all optional; the command line overrides them
    executor = "serial"                   # serial | local | tcp://host:8786
    workers = 2
    chunk_size = 10000

Functions
---------
MODELS          name -> SweepModel (parameters with their kinds, the chunk function, outputs)
load_sweep      read and check a sweep file -> SweepSpec
case_grid       the Cartesian product of the parameter values, flattened to per-case arrays
run_sweep       evaluate a SweepSpec through :mod:`bearinglab.parallel`; inputs and outputs as columns
check_file_executor  refuse a scheduler on another machine named by a file, unless confirmed
write_table     write columns to CSV or Parquet, whole or not at all

Every chunk function is pure and flags failed cases (``converged`` False and a ``failure`` reason)
instead of raising, so one bad case does not stop a sweep.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable
from pathlib import Path
from typing import NamedTuple

import numpy as np

from . import _bounds, catalog, geometry, hertz, kinematics, parallel, stand, tables
from .bearing import BallBearing
from .errors import CatalogError, ConvergenceError, InputError
from .stand import static
from .units import KGF, parse_quantity, parse_values

__all__ = [
    "GEOMETRY_PARAMETERS",
    "MODELS",
    "SweepModel",
    "SweepSpec",
    "case_grid",
    "check_file_executor",
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


class SweepSpec(NamedTuple):
    """A checked sweep file."""

    model: SweepModel
    bearing: BallBearing
    parameters: dict  # name -> SI array of values
    output: Path | None
    executor: str
    workers: int | None
    chunk_size: int
    constants: dict


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
    if name not in MODELS:
        _fail(path, "model", f"must be one of {sorted(MODELS)}, got {name!r}")
    model = MODELS[name]
    if "bearing" not in doc:
        _fail(path, "bearing", "missing: give a catalog name or a [bearing] table")
    b = doc["bearing"]
    bearing = (catalog.bearing_from_table(b, name=str(b.get("designation", "sweep")), file=path)
               if isinstance(b, dict) else catalog.get(str(b)))
    params = doc.get("parameters")
    if not isinstance(params, dict) or not params:
        _fail(path, "parameters", "missing: give at least one parameter list or range")
    kinds = dict(model.parameters)
    if model.geometry:
        kinds.update(GEOMETRY_PARAMETERS)
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
    out = doc.get("output", {}).get("file")
    output = (path.parent / out) if out else None
    if output is not None and output.suffix not in (".csv", ".parquet"):
        _fail(path, "output.file", f"must end in .csv or .parquet, got {out!r}")
    ex = doc.get("execution", {})
    chunk = ex.get("chunk_size", parallel.DEFAULT_CHUNK_SIZE)
    return SweepSpec(model, bearing, values, output, str(ex.get("executor", "serial")), ex.get("workers"),
                     int(chunk), dict(doc.get("constants", {})))


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
    memory_limit : str, optional
        Memory limit per local worker.
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
        The inputs as :func:`bearinglab.tables.input_columns` (``axial_load_N``, ``speed_rpm``, ...),
        then the model's outputs, case by case.
    """
    if execution is None and executor is None:
        check_file_executor(spec, allow_remote_executor=allow_remote_executor)
    ex = parallel._execution(execution, executor=executor or (None if execution else spec.executor),
                             workers=workers, chunk_size=chunk_size, memory_limit=memory_limit,
                             processes=processes, progress=progress)
    if ex.workers is None and spec.workers is not None:
        ex = dataclasses.replace(ex, workers=spec.workers)
    ex = ex.with_default_chunk_size(spec.chunk_size)
    cases = case_grid(spec.parameters)
    constants = dict(spec.constants, bearing=spec.bearing)
    if spec.model.engine:  # one engine for the whole sweep, so that the chunk size does not choose it
        n = max((np.size(v) for v in cases.values()), default=0)
        constants["engine"] = stand.engine_for(n)
    out = parallel.run_cases(spec.model.evaluate, cases, constants=constants, execution=ex)
    columns = tables.input_columns(cases, dict(GEOMETRY_PARAMETERS, **spec.model.parameters))
    columns.update(out)
    return columns


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
    tables.write_table(columns, path)
