"""The ``high-speed`` calculation: the high-speed quasi-static model under thrust (spec 004), one case
or a grid of thrusts x speeds, at the operating clearance of the mounting inputs (issue 23).

:func:`document` gives what ``bearinglab high-speed ... --json`` prints (the command prints it), for
the command line and the web alike; :func:`figure` draws the map of a grid
(:func:`bearinglab.plots.high_speed.plot_map`) from the same solve.

Functions
---------
compute    Parsed -> HighSpeedResult (the document, the solved state, the bearing, the warnings)
document   Parsed -> the JSON document
figure     HighSpeedResult -> the map figure (and the notes of its sign-change solve)
"""

from __future__ import annotations

import contextlib
import dataclasses
import warnings
from typing import NamedTuple

from ..errors import ConvergenceError, InputError, ValidityWarning
from . import _mounting
from . import _reading as inp
from ._failures import failures
from ._finite import finite

__all__ = ["HighSpeedResult", "compute", "document", "figure"]

# A command runs in a fresh process, where loading the compiled kernel costs about 0.8 s (numba's import
# and its cache) against 2e-5 s a case saved: the numpy path (the same answers to 1e-12) is quicker below
# about 50 000 cases. The choice depends on the whole request only, never on the chunk size.
_COMPILED_MIN_CASES = 50_000
_PROGRESS_MIN_CASES = 5000  # serial sweeps at least this large are cut finer, so a progress bar moves
_CHUNK = 2500  # cases per batched call then


class HighSpeedResult(NamedTuple):
    """A solved high-speed request."""

    document: dict
    """The JSON document (``bearinglab high-speed --json``)."""
    state: object
    """The solved :class:`bearinglab.quasistatic.HighSpeedState` (thrusts x speeds)."""
    columns: dict
    """:func:`bearinglab.tables.high_speed` of the state (the CSV's columns)."""
    bearing: object
    """The bearing as solved (at its operating clearance under the mounting inputs)."""
    notes: list
    """The validity warnings of the solve (without the bearing's provenance notes)."""
    options: dict
    """The model options of :func:`bearinglab.quasistatic.high_speed_analysis`."""
    speeds: object
    """The speeds of the grid. [rad/s]"""


@finite('high-speed')
def compute(parsed, *, bearing_file=None, catalog=None, execution=None, check=None):
    """Solve a high-speed request.

    Parameters
    ----------
    parsed : bearinglab.calculations.Parsed
        The request (fields of ``CALCULATIONS["high-speed"]``).
    bearing_file, catalog : path, optional
        A bearing file or a user catalog (the command line's files; the web has none).
    execution : callable, optional
        ``execution(single)`` -> a context manager yielding the :class:`bearinglab.parallel.Execution`
        of the grid (the command line's executor and progress bar); serial by default.
    check : callable, optional
        ``check(loads, speeds)``, called with the checked inputs before anything is solved (the
        command line's output files).

    Returns
    -------
    HighSpeedResult
    """
    from .. import limits, parallel, tables
    from ..units import RPM
    from . import _preload
    from .load_distribution import clearance_source

    with failures(parsed, options=False):  # messages in the command line's words (_failures)
        b = inp.bearing_of(parsed, bearing_file=bearing_file, catalog=catalog)
        from ..bearing import check_model

        check_model(b, "high-speed")
        options = _model_options(inp.value(parsed, "solver", "newton"), inp.value(parsed, "raceway_control", "outer"),
                                 inp.value(parsed, "constants", "mass"),
                                 inp.value(parsed, "gyroscopic_sign", "physical"), inp.text(parsed, "reduced_modulus"))
        loads, speeds = _grid(inp.text(parsed, "axial_load"), inp.text(parsed, "speed"))
        limits.check_speed(speeds, b.require("pitch_diameter"))
        # issue 23: the operating clearance (at the highest speed)
        b, mounted = _mounting.operating_bearing(b, speeds.max(), {k: parsed.given.get(k) for k in _mounting.NAMES})
        if check is not None:
            check(loads, speeds)
        single = loads.size == 1 and speeds.size == 1
        context = execution(single) if execution is not None else contextlib.nullcontext(parallel.Execution())
        with context as ex:
            state, notes = _solve(b, loads, speeds, options, ex)
        preloaded, note = _preload.report(b, source=clearance_source(mounted, inp.text(parsed, "radial_clearance")))
        if note:  # issue 30: solved by the 5-DOF model with the rings held concentric (quasistatic.thrust)
            notes.insert(0, note)
        notes += limits.high_speed_warnings(b, state)
        cols = tables.high_speed(state)
        rows = tables.rows(cols)
        reduced = options["reduced_modulus"]
        echo = inp.inputs_echo(b, constants=options["constants"], raceway_control=options["raceway_control"],
                               gyroscopic_sign=inp.value(parsed, "gyroscopic_sign", "physical"),
                               solver=options["method"], reduced_modulus_GPa=None if reduced is None else reduced / 1e9)
        if single:  # the inputs as given, without the noise of the unit conversions
            echo.update(inp.inputs_echo(b, axial_load_N=float(loads[0]), speed_rpm=float(speeds[0]) / RPM))
            doc = dict(rows[0], **echo, **mounted, **preloaded, warnings=list(notes))
        else:
            doc = dict(echo, **inp.inputs_echo(b, axial_load_N=loads.tolist(), speed_rpm=(speeds / RPM).tolist()),
                       **mounted, **preloaded, cases=rows, warnings=list(notes))
    return HighSpeedResult(inp.notes_in(doc, b), state, cols, b, notes, options, speeds)


@finite('high-speed')
def document(parsed, *, bearing_file=None, catalog=None):
    """The document of ``bearinglab high-speed ... --json`` for a request (solved serially).

    Parameters
    ----------
    parsed : bearinglab.calculations.Parsed
        The request.
    bearing_file, catalog : path, optional
        A bearing file or a user catalog (the command line's files; the web has none).

    Returns
    -------
    dict
        One case as one object, a grid as ``cases``; the inputs echoed, the operating clearance with
        mounting inputs, and ``warnings``.
    """
    return compute(parsed, bearing_file=bearing_file, catalog=catalog).document


def figure(result):
    """The map of a grid of at least two thrusts (:func:`bearinglab.plots.high_speed.plot_map`).

    Parameters
    ----------
    result : HighSpeedResult
        From :func:`compute`.

    Returns
    -------
    tuple of (matplotlib.figure.Figure, list of str)
        The figure, and the notes of the sign-change solve (a delta_a sign change interpolated on the
        grid when the solve does not converge).

    Raises
    ------
    InputError
        Fewer than two thrusts.
    """
    import numpy as np

    from ..plots import high_speed as high_speed_plots

    state = result.state
    if np.ndim(state.axial_load) < 2 or np.shape(state.axial_load)[0] < 2:
        raise InputError("plot: needs a sweep over at least two thrusts (e.g. --axial-load 2.5kN:45kN:2.5kN)")
    notes = []
    fig = high_speed_plots.plot_map(
        state, title=f"Bearing {result.bearing.designation}: high-speed contact angles under thrust",
        sign_change=_sign_change(result.bearing, result.speeds, result.options, notes))
    return fig, notes


def _model_options(solver, raceway_control, constants, gyroscopic_sign, reduced_modulus):
    """The options of :func:`bearinglab.quasistatic.high_speed_analysis`, checked."""
    from .. import quasistatic
    from ..units import parse_quantity
    inp.choice("solver", solver, ("newton", "angle-iteration"))
    inp.choice("raceway-control", raceway_control, tuple(quasistatic.RACEWAY_CONTROLS))
    inp.choice("constants", constants, tuple(quasistatic.CONSTANTS))
    sign = {"physical": 1, "reversed": -1}.get(inp.choice("gyroscopic-sign", gyroscopic_sign,
                                                          ("physical", "reversed")))
    ep = None
    if reduced_modulus is not None:
        ep = parse_quantity(reduced_modulus, "pressure", "reduced-modulus")
        if not ep > 0:
            raise InputError(f"reduced-modulus must be > 0 [GPa], got {ep / 1e9:g} GPa")
    return {"method": solver, "raceway_control": raceway_control, "constants": constants, "gyroscopic_sign": sign,
            "reduced_modulus": ep}


def _grid(axial_load, speed):
    """The thrusts and speeds given (SI), checked."""
    import numpy as np

    from .._bounds import MAX_CASES, check_cases
    from ..units import parse_values
    if axial_load is None:
        raise InputError("axial-load: missing; give the thrust, e.g. '20 kN'")
    if speed is None:
        raise InputError("speed: missing; give the inner-ring speed, e.g. '10000 rpm'")
    loads = parse_values(axial_load, "force", "axial-load", limit=MAX_CASES)
    if np.any(~(loads > 0)):
        raise InputError(f"axial-load must be > 0 [N], got {float(loads[~(loads > 0)][0]):g} N")
    speeds = inp.parse_speeds(speed)
    check_cases(loads.size * speeds.size, f"{loads.size} thrusts x {speeds.size} speeds")  # before the map
    return loads, speeds


def _solve(bearing, loads, speeds, options, ex):
    """One case (:func:`quasistatic.high_speed_analysis`) or the grid (:func:`quasistatic.sweep`) in chunks on
    the chosen executor; returns the state and the validity warnings raised on the way."""
    from .. import quasistatic
    if loads.size * speeds.size < _COMPILED_MIN_CASES:
        options = {**options, "engine": "numpy"}
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", ValidityWarning)
        if loads.size == 1 and speeds.size == 1:
            state = quasistatic.high_speed_analysis(bearing, loads[0], speeds[0], **options)
        else:
            if ex.chunk_size is None and ex.executor == "serial" and loads.size * speeds.size >= _PROGRESS_MIN_CASES:
                ex = dataclasses.replace(ex, chunk_size=_CHUNK)  # small enough chunks for the bar to move
            state = quasistatic.sweep(bearing, loads, speeds, execution=ex, **options)
    return state, [str(c.message) for c in caught if issubclass(c.category, ValidityWarning)]


def _sign_change(bearing, speeds, options, notes):
    """The thrust at which delta_a changes sign per speed, from the library's solve (not the grid); None
    (the figure then interpolates on the grid) with a note if it does not converge."""
    from .. import quasistatic
    try:
        return quasistatic.sign_change_thrust(
            bearing, speeds, reduced_modulus=options["reduced_modulus"], constants=options["constants"],
            raceway_control=options["raceway_control"], gyroscopic_sign=options["gyroscopic_sign"])
    except (ConvergenceError, InputError) as exc:
        notes.append(f"plot: the delta_a sign change is interpolated on the grid ({exc})")
        return None
