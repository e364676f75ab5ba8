"""The ``runout`` and ``runout-monte-carlo`` documents (spec 003): manufacturing errors -> inner-ring runout.

``runout``: the inner-ring displacement at one rotation angle, or the trajectory, its runout metrics
and spectral lines over a rotation sequence, for one bearing's error set: an error file on the command
line, a posted JSON or TOML document on the web (which may not name files). ``runout-monte-carlo``: the
runout statistics over random bearings of an ISO 3290 ball grade and a ring class. The physics is
:mod:`bearinglab.runout`; the command line (``bearinglab runout``, ``runout monte-carlo``) and the web
compute both here.

Functions
---------
document              Parsed ``runout`` request -> the JSON document ``bearinglab runout --json`` prints
compute               the same, with the model's results (for the command line's figures and CSV)
monte_carlo_document  Parsed ``runout-monte-carlo`` request -> ``bearinglab runout monte-carlo --json``
compute_monte_carlo   the same, with the study (for the command line's CSV, worst files and figures)
check_sequence        the sizes of a rotation sequence and the cage ratio, in the model's words
check_study           the sizes of a Monte Carlo study, likewise
"""

from __future__ import annotations

import math
from typing import NamedTuple

from .. import _bounds
from .._bounds import check_count
from .._io import json_value
from ..errors import CatalogError, ConvergenceError, InputError
from ._failures import failures
from ._finite import finite
from .fields import RequestError

__all__ = ["check_sequence", "check_study", "compute", "compute_monte_carlo", "document",
           "monte_carlo_document"]

UM = 1e-6
MIN_STEPS_PER_REV = 4  # positions per revolution below which no line of the spectrum is resolved
#: what a posted error set is called in the document and in messages
POSTED = "(posted document)"


def _check_cage_ratio(cage_ratio):
    """kappa = cage speed / inner-ring speed lies in (0, 1): the cage turns with the shaft, slower."""
    if cage_ratio is not None and not 0.0 < cage_ratio < 1.0:
        raise InputError(f"cage-ratio must be in (0, 1) [-] (the cage turns slower than the inner ring; "
                         f"(1 - gamma)/2 is about 0.4), got {cage_ratio!r}")


def _geometry(geometry_file, bearing, catalog_file, first_ball_angle):
    """The geometry given by --geometry or --bearing (None when neither is given)."""
    from .. import catalog as _catalog
    from .. import runout
    from ..units import parse_quantity
    if geometry_file and bearing:
        raise InputError("geometry: give --geometry FILE or --bearing NAME, not both")
    theta1 = (
        None
        if first_ball_angle is None
        else parse_quantity(first_ball_angle, "angle", "first-ball-angle", default_unit="deg")
    )
    g = None
    if bearing:
        g = runout.geometry_from_bearing(_catalog.get(bearing, catalog=catalog_file))
    elif geometry_file:
        try:
            g = runout.files.load_geometry_file(geometry_file)
        except CatalogError as exc:
            if "no [geometry] table" not in str(exc):
                raise
            g = runout.geometry_from_bearing(_catalog.load_bearing_file(geometry_file))
    if g is not None and theta1 is not None:
        g = g._replace(first_ball_angle=theta1)
    return g, theta1


def _um(v):
    return float(v) / UM


def _metrics_dict(m):
    from .. import runout, tables
    return tables.runout_metrics(m, runout.METRICS)


def _geometry_dict(g):
    from .. import tables
    return tables.record(g, tables.RUNOUT_GEOMETRY)


def _single_dict(d, g):
    import numpy as np
    c = d.contact
    st = d.shifts
    balls = []
    for i in range(g.n_balls):
        s_i = float(
            c.constant + c.sine * np.sin(d.ball_angle[i]) + c.cosine * np.cos(d.ball_angle[i])
        )
        row = {
            "ball": i + 1,
            "theta_deg": math.degrees(d.ball_angle[i]) % 360.0,
            "dk_um": _um(d.generalized_error[i]),
            "s_um": _um(s_i),
            "slack_um": _um(c.slack[i]),
            "contact": bool(c.contact[i]),
            "load_share": float(c.load_share[i]),
        }
        if int(d.passes):
            row.update(
                {
                    "dtau1_rad": float(st.outer_angle_shift[i]),
                    "dtau2_rad": float(st.inner_angle_shift[i]),
                    "dtheta2_rad": float(st.inner_azimuth_shift[i]),
                }
            )
        balls.append(row)
    out = {
        "mode": "single",
        "psi_deg": math.degrees(d.rotation_angle),
        "a0_um": _um(c.constant),
        "B_um": _um(c.sine),
        "D_um": _um(c.cosine),
        "A_um": _um(c.amplitude),
        "phi_deg": math.degrees(c.phase),
        "dx_um": _um(d.x),
        "dy_um": _um(d.y),
        "dz_um": _um(d.z),
        "contact_balls": [int(i) + 1 for i in np.flatnonzero(c.contact)],
        "degenerate": bool(c.degenerate),
        "free_play_um": _um(d.free_play),
        "face_diameter_um": _um(c.face_diameter),
        "tilt_alpha_urad": float(d.tilt_x) / UM,
        "tilt_beta_urad": float(d.tilt_y) / UM,
        "refined": bool(int(d.passes) > 0),
        "passes": int(d.passes),
        "converged": bool(d.converged),
        "first_approximation": {
            "dx_um": _um(d.first_approximation.x),
            "dy_um": _um(d.first_approximation.y),
            "dz_um": _um(d.first_approximation.z),
        },
        "balls": balls,
    }
    return out


def _sequence_dict(t, lines):
    import numpy as np
    d = t.displacement
    out = {
        "mode": "sequence",
        "revolutions": t.revolutions,
        "steps_per_rev": t.steps_per_revolution,
        "positions": int(t.rotation_angle.size),
        "cage_ratio": t.cage_ratio,
    }
    out.update(_metrics_dict(t.metrics))
    out["synchronous"] = _metrics_dict(t.synchronous)
    out["asynchronous"] = _metrics_dict(t.asynchronous)
    out["degenerate_fraction"] = t.degenerate_fraction
    out["refined"] = bool(np.any(d.passes > 0))
    out["passes_max"] = int(np.max(d.passes))
    out["all_converged"] = bool(np.all(d.converged))
    out["spectrum_lines"] = [
        {
            "component": ln.component,
            "order": ln.order,
            "bin_order": ln.bin_order,
            "resolution": ln.resolution,
            "amplitude_um": _um(ln.amplitude),
            "label": ln.label,
            "source": ln.source,
            "cage_harmonic": ln.cage_harmonic,
            "shaft_harmonic": ln.shaft_harmonic,
        }
        for ln in lines
    ]
    out["trajectory"] = {
        "psi_deg": np.degrees(t.rotation_angle),
        "dx_um": d.x / UM,
        "dy_um": d.y / UM,
        "dz_um": d.z / UM,
        "contact_balls": [[int(i) + 1 for i in np.flatnonzero(row)] for row in d.contact.contact],
        "degenerate": d.contact.degenerate,
        "free_play_um": d.free_play / UM,
    }
    return out


class Runout(NamedTuple):
    """A runout computation: the document and the model's results."""

    document: dict
    geometry: object
    """The SpindleGeometry."""
    displacement: object
    """At one angle: the Displacement (None for a sequence)."""
    trajectory: object
    """Over a sequence: the Trajectory (None at one angle)."""
    spectrum: object
    lines: list


@finite('runout')
def document(parsed, **files):
    """The document of ``bearinglab runout ... --json`` for a checked request.

    Parameters
    ----------
    parsed : Parsed
        A request of the calculation ``runout``; its ``errors`` is the posted error set (JSON or TOML
        text, which may not name files).
    **files
        The command line's files (:func:`compute`); the web gives none.

    Returns
    -------
    dict
        ``mode`` "single" (the displacement at ``angle``) or "sequence" (the trajectory, its metrics
        and spectral lines), ``geometry``, ``warnings``.

    Raises
    ------
    RunFailure
        An input the model refuses (a bad error set names ``errors``), or a refinement that did not
        converge.
    """
    return json_value(compute(parsed, **files).document)


@finite('runout')
def compute(parsed, *, errors_file=None, geometry_file=None, catalog=None):
    """:func:`document` with the model's results, for the command line's figures and CSV.

    Parameters
    ----------
    parsed : Parsed
        A request of the calculation ``runout``.
    errors_file : Path, optional
        The command line's error file, read instead of the posted ``errors`` (its profile files are
        read next to it).
    geometry_file, catalog : Path, optional
        The command line's geometry file and user catalog.

    Returns
    -------
    Runout
    """
    with failures(parsed.calculation):
        return _compute(parsed, errors_file, geometry_file, catalog)


def _text(parsed, name, default=None):
    return str(parsed.given[name]).strip() if name in parsed.given else default


def _compute(parsed, errors_file, geometry_file, catalog):
    import numpy as np

    from .. import runout
    from ..units import parse_quantity

    v = parsed.values
    cage_ratio, refine = v.get("cage_ratio"), v.get("refine", False)
    _check_cage_ratio(cage_ratio)
    g, theta1 = _geometry(geometry_file, _text(parsed, "bearing"), catalog, _text(parsed, "first_ball_angle"))
    if errors_file is not None:
        g, e = runout.files.load_error_file(errors_file, g)
        source = str(errors_file)
    else:
        g, e = _posted_errors(parsed, g)
        source = POSTED
    if theta1 is not None:
        g = g._replace(first_ball_angle=theta1)
    revolutions, steps = v.get("revolutions"), v.get("steps_per_rev")
    angle = _text(parsed, "angle")
    if revolutions is None and steps is None:
        psi = 0.0 if angle is None else parse_quantity(angle, "angle", "angle", default_unit="deg")
        d, notes = _validity(runout.initial_displacement, psi, g, e, refine=refine, cage_ratio=cage_ratio)
        info = _single_dict(d, g)
        info.update(errors_file=source, refine=refine, cage_ratio=cage_ratio, geometry=_geometry_dict(g),
                    warnings=notes)
        return Runout(info, g, d, None, None, None)
    if angle is not None:
        raise InputError(
            "angle: give --angle for one position or --revolutions/--steps-per-rev for a sequence, not both"
        )
    revs = 3 if revolutions is None else revolutions
    steps = 360 if steps is None else steps
    check_sequence(revs, steps, cage_ratio)
    t, notes = _validity(
        runout.rotation_sequence,
        g,
        e,
        revolutions=revs,
        steps_per_revolution=steps,
        start_angle=parse_quantity(_text(parsed, "start_angle", "0 deg"), "angle", "start-angle",
                                   default_unit="deg"),
        cage_ratio=cage_ratio,
        refine=refine,
    )
    if not np.all(t.displacement.converged):
        bad = np.flatnonzero(~t.displacement.converged)
        raise ConvergenceError(
            "runout --refine",
            iterations=int(t.displacement.passes.max()),
            residual=t.displacement.last_change[bad],
            estimate=t.displacement.z[bad],
            reason=f"{bad.size} of {t.rotation_angle.size} positions did not converge",
        )
    d = t.displacement
    spec = runout.runout_spectrum(d.x, d.y, d.z, steps)
    lines = runout.spectrum_lines(spec, t.cage_ratio)
    info = _sequence_dict(t, lines)
    info.update(errors_file=source, start_angle_deg=math.degrees(t.rotation_angle.flat[0]), refine=refine,
                geometry=_geometry_dict(g), warnings=notes)
    return Runout(info, g, None, t, spec, lines)


def _posted_errors(parsed, geometry):
    """(geometry, errors) of the posted error set; nothing is read from the disk."""
    from .. import runout
    from ..errors import CatalogError
    from .documents import _document

    doc = _document("errors", str(parsed.values["errors"]))  # refuses a 'profile' (a file name)
    try:
        return runout.files.read_error_document(doc, geometry, source="the posted document")
    except CatalogError as exc:  # a bad entry of the error set: the field 'errors' is at fault
        raise RequestError("errors", "...", "a valid error set (examples/runout/README.md)",
                           "{name}: " + str(exc)) from None


def _validity(what, *args, **kwargs):
    """Run a runout model; its result and the messages of its ValidityWarnings (issue 20 item 8)."""
    import warnings

    from ..errors import ValidityWarning

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", ValidityWarning)
        result = what(*args, **kwargs)
    return result, list(dict.fromkeys(str(c.message) for c in caught if issubclass(c.category, ValidityWarning)))




@finite('runout-monte-carlo')
def monte_carlo_document(parsed, **options):
    """The document of ``bearinglab runout monte-carlo ... --json`` for a checked request.

    Parameters
    ----------
    parsed : Parsed
        A request of the calculation ``runout-monte-carlo``.
    **options
        The command line's files and execution (:func:`compute_monte_carlo`); the web gives none.

    Returns
    -------
    dict
        The inputs (grade, class, sizes, their sources), the geometry and, per runout metric, its
        statistics over the samples (mean, std, median, p95, max ...) in um.

    Raises
    ------
    RunFailure
        An input the study refuses, naming its field.
    """
    return json_value(compute_monte_carlo(parsed, **options)[0])


@finite('runout-monte-carlo')
def compute_monte_carlo(parsed, *, geometry_file=None, catalog=None, execution=None):
    """:func:`monte_carlo_document` with the study, for the command line's files.

    Parameters
    ----------
    parsed : Parsed
        A request of the calculation ``runout-monte-carlo``.
    geometry_file, catalog : Path, optional
        The command line's geometry file and user catalog.
    execution : bearinglab.parallel.Execution, optional
        Where the samples run (serial by default; the result depends on the seed only).

    Returns
    -------
    tuple
        ``(document, result, geometry, grade, rings)``: the study's MonteCarloResult, the
        SpindleGeometry, the BallGrade and the RingClass.
    """
    with failures(parsed.calculation):
        return _compute_monte_carlo(parsed, geometry_file, catalog, execution)


def _compute_monte_carlo(parsed, geometry_file, catalog, execution):
    from .. import runout

    v = parsed.values
    samples, seed = v.get("samples", 200), v.get("seed", 0)
    steps_per_rev, revolutions = v.get("steps_per_rev", 180), v.get("revolutions", 2)
    max_order, cage_ratio = v.get("max_order", 15), v.get("cage_ratio")
    if geometry_file is None and "bearing" not in parsed.given:  # the web's geometry is a bearing
        raise RequestError("bearing", None, "a catalog bearing",
                           "{name}: missing; a catalog bearing, e.g. 7218B (the geometry of the study)")
    g, _ = _geometry(geometry_file, _text(parsed, "bearing"), catalog, None)
    check_study(samples, steps_per_rev, revolutions, max_order, cage_ratio)
    grade = runout.ball_grade(v.get("ball_grade", "G5"))
    rings = runout.ring_class(v.get("ring_class", "P4"))
    r = runout.monte_carlo(g, grade, rings, samples, seed, steps_per_revolution=steps_per_rev,
                           revolutions=revolutions, max_order=max_order, cage_ratio=cage_ratio,
                           execution=execution)
    info = _monte_carlo_info(r, g, grade, rings, samples, seed, steps_per_rev, revolutions, max_order)
    return info, r, g, grade, rings


def _monte_carlo_info(r, g, grade, rings, samples, seed, steps_per_rev, revolutions, max_order):
    """The inputs and the summary statistics of a Monte Carlo study, in µm."""
    import numpy as np

    from .. import runout
    info = {
        "samples": samples,
        "seed": seed,
        "ball_grade": grade.name,
        "ring_class": rings.name,
        "steps_per_rev": steps_per_rev,
        "revolutions": revolutions,
        "max_order": max_order,
        "ball_grade_source": grade.source,
        "ring_class_source": rings.source,
        "ball_grade_um": {
            "V_DWS": grade.single_diameter_variation / UM,
            "V_DWL": grade.lot_diameter_variation / UM,
        },
        "ring_class_um": {
            "K_ia": rings.radial_runout / UM,
            "S_ia": rings.axial_runout / UM,
            "w_rms": rings.waviness_rms / UM,
        },
        "geometry": _geometry_dict(g),
    }
    for name in runout.METRICS:
        info[f"{name}_um"] = {k: v / UM for k, v in r.summary[name]._asdict().items()}
    info["degenerate_fraction_mean"] = float(np.mean(r.samples.degenerate_fraction))
    return info


def check_sequence(revolutions, steps_per_rev, cage_ratio=None):
    """Check the sizes of a rotation sequence and the cage ratio, in the words of the model's limits
    (the command line checks them before the fields' ranges, whose messages say less).

    Parameters
    ----------
    revolutions, steps_per_rev : int
        The sequence: at least one revolution of at least four positions, within bearinglab's limits.
    cage_ratio : float, optional
        Cage speed / inner-ring speed, in (0, 1). [-]

    Raises
    ------
    InputError
        Naming the input at fault.
    """
    _check_cage_ratio(cage_ratio)
    _check_positions(revolutions, steps_per_rev)
    if steps_per_rev < MIN_STEPS_PER_REV:
        raise InputError(f"steps-per-rev must be an integer >= {MIN_STEPS_PER_REV} [-] (the once-per-revolution "
                         f"line needs at least four positions per revolution), got {steps_per_rev}")


def check_study(samples, steps_per_rev, revolutions, max_order, cage_ratio=None):
    """Check the sizes of a runout Monte Carlo study and the cage ratio, as :func:`check_sequence`.

    Parameters
    ----------
    samples : int
        Random bearings, >= 2.
    steps_per_rev, revolutions : int
        Each sample's sequence.
    max_order : int
        Highest waviness order, >= 0.
    cage_ratio : float, optional
        Cage speed / inner-ring speed, in (0, 1). [-]

    Raises
    ------
    InputError
        Naming the input at fault.
    """
    if samples < 2:
        raise InputError(f"samples must be >= 2 [-], got {samples}")
    _check_positions(revolutions, steps_per_rev, _bounds.MAX_SAMPLE_POSITIONS)
    check_count("samples", samples, _bounds.MAX_SAMPLES, minimum=2)
    check_count("max-order", max_order, _bounds.MAX_ORDER, minimum=0)
    _check_cage_ratio(cage_ratio)
    if steps_per_rev < MIN_STEPS_PER_REV:
        raise InputError(f"steps-per-rev must be an integer >= {MIN_STEPS_PER_REV} [-], got {steps_per_rev}")


def _check_positions(revolutions, steps_per_rev, limit=_bounds.MAX_POSITIONS):
    """The size of a rotation sequence, checked before it is allocated (bearinglab._bounds)."""
    check_count("revolutions", revolutions, _bounds.MAX_REVOLUTIONS)
    check_count("steps-per-rev", steps_per_rev, _bounds.MAX_STEPS_PER_REV)
    if revolutions * steps_per_rev > limit:
        raise InputError(f"revolutions x steps-per-rev must be <= {limit} positions (bearinglab's size "
                         f"limit), got {revolutions} x {steps_per_rev}")
