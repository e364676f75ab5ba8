"""The calculations of the test-stand method (spec 000): ``axial-angle`` (the operating contact angle
under an axial load, with the iteration table) and ``stand-load`` (the minimum axial load on a stand).

:func:`document` gives what ``bearinglab axial-angle ... --json`` and ``bearinglab stand-load ...
--json`` print (the commands print it), for the command line and the web alike.

Functions
---------
document   Parsed -> the JSON document of either calculation
"""

from __future__ import annotations

import math

from ..errors import InputError
from . import _reading as inp
from ._failures import failures
from ._finite import finite

__all__ = ["document"]


@finite(None)
def document(parsed, *, bearing_file=None, catalog=None):
    """The document of ``bearinglab axial-angle|stand-load ... --json`` for a request.

    Parameters
    ----------
    parsed : bearinglab.calculations.Parsed
        The request (fields of ``CALCULATIONS["axial-angle"]`` or ``CALCULATIONS["stand-load"]``).
    bearing_file, catalog : path, optional
        A bearing file or a user catalog (the command line's files; the web has none).

    Returns
    -------
    dict
        One case as one object; lists of loads or speeds as ``cases``; the inputs echoed and
        ``warnings``.
    """
    with failures(parsed, options=False):  # messages in the command line's words (_failures)
        b = inp.bearing_of(parsed, bearing_file=bearing_file, catalog=catalog)
        from ..bearing import check_model

        check_model(b, "axial-angle")
        out = (_axial_angle if parsed.calculation.name == "axial-angle" else _stand_load)(parsed, b)
    return inp.notes_in(out, b)


def _angle_row(row, legacy):
    from ..units import format_dms, to_dms
    d, m, s = to_dms(row.contact_angle, truncate=legacy)
    return f"{d}°{m:02d}'{s:02.0f}\"" if legacy else format_dms(row.contact_angle)


def _axial_angle(parsed, b):
    """Operating contact angle under axial load: C*, x0, Newton iterations, displacement."""
    import numpy as np

    from .. import limits, stand, tables
    from .._bounds import MAX_CASES, MAX_ROWS, check_count
    from ..units import KGF, format_dms, parse_values
    hertz = inp.value(parsed, "hertz", "exact")
    elastic_constant = inp.value(parsed, "elastic_constant", "materials")
    legacy, x0, rows = inp.value(parsed, "legacy", False), inp.value(parsed, "x0"), inp.value(parsed, "rows")
    if hertz not in ("exact", "table"):
        raise InputError(f"hertz must be one of ['exact', 'table'], got {hertz!r}")
    if elastic_constant not in ("materials", "paper"):
        raise InputError(f"elastic-constant must be one of ['materials', 'paper'], got {elastic_constant!r}")
    if rows is not None:
        check_count("rows", rows, MAX_ROWS)
    axial_load = inp.text(parsed, "axial_load")
    if axial_load is None:
        raise InputError("axial-load: missing; give the axial load, e.g. '2 kgf'")
    loads = parse_values(axial_load, "force", "axial-load", limit=MAX_CASES)
    if np.any(~(loads > 0)):
        bad = float(loads[~(loads > 0)][0])
        raise InputError(f"axial-load must be > 0 [N], got {bad:g} N ({bad / KGF:g} kgf)")
    scalar = loads.size == 1
    # the paper prints two rows; legacy mode reproduces exactly those unless --rows says otherwise
    max_rows = rows if rows is not None else (2 if legacy else None)
    r = stand.stand_analysis(b, loads[0] if scalar else loads, hertz=hertz, reproduce_print=legacy, x0=x0,
                             max_rows=max_rows, elastic_constant=elastic_constant)
    c = r.constants
    notes = limits.contact_warnings(b, r.axial_load, r.ball_load, r.ball_load, r.contact_angle, r.contact_angle)
    base = inp.inputs_echo(b, axial_load_N=list(map(float, np.atleast_1d(loads))) if not scalar else float(loads[0]),
                           hertz=hertz, elastic_constant=elastic_constant, legacy=legacy, x0_rad=x0, rows=rows)
    base.update({
        "elastic_constant_cm2_per_kgf_2_3": c.elastic_constant_paper,
        "contact_angle_initial_deg": math.degrees(r.free_angle),
        "gamma": c.gamma,
        "curvature_sum_inner_per_mm": c.curvature_sum_inner * 1e-3,
        "curvature_sum_outer_per_mm": c.curvature_sum_outer * 1e-3,
        "cos_tau_inner": c.curvature_difference_inner,
        "cos_tau_outer": c.curvature_difference_outer,
        "delta_star_inner": c.hertz_inner.delta_star,
        "delta_star_outer": c.hertz_outer.delta_star,
        "c_inner_cm2_per_kgf_2_3": c.approach_inner_paper,
        "c_outer_cm2_per_kgf_2_3": c.approach_outer_paper,
        "load_deflection_constant_kgf": c.force_characteristic_kgf,
        "load_deflection_constant_N": c.force_characteristic,
    })
    if not scalar:
        cases = [dict(row, converged=True) for row in tables.rows(tables.columns(r, tables.AXIAL_ANGLE))]
        return dict(base, cases=cases, warnings=notes)
    out = dict(base)
    out.update({
        "axial_load_N": float(r.axial_load), "axial_load_kgf": float(r.axial_load) / KGF,
        "series_coefficients": list(np.asarray(r.series).ravel()),
        "first_approximation_rad": float(r.first_approximation),
        "operating_contact_angle_deg": math.degrees(r.contact_angle),
        "operating_contact_angle_dms": format_dms(r.contact_angle),
        "contact_angle_increment_deg": math.degrees(r.contact_angle - r.free_angle),
        "axial_displacement_ratio": float(r.axial_displacement_ratio),
        "axial_displacement_um": float(r.axial_displacement) * 1e6,
        "ball_load_N": float(r.ball_load), "ball_load_kgf": float(r.ball_load) / KGF,
        "converged": True,
        "legacy": legacy,
        "warnings": notes,
        "iterations": [{"k": row.k, "x_rad": row.x, "contact_angle_deg": math.degrees(row.contact_angle),
                        "contact_angle_dms": _angle_row(row, legacy),
                        "axial_displacement_ratio": row.axial_displacement_ratio,
                        "axial_load_kgf": row.axial_load / KGF, "axial_load_N": row.axial_load,
                        "error_percent": row.error_percent} for row in r.iterations],
    })
    return out


def _stand_load(parsed, b):
    """Minimum axial load against gyroscopic slip on a test stand, and the +20 % maximum."""
    from .. import stand, tables
    z, d, dm, a = b.require("n_balls", "ball_diameter", "pitch_diameter", "contact_angle")
    speed = inp.text(parsed, "speed")
    if speed is None:
        raise InputError("speed: missing; give the inner-ring speed, e.g. '3000 rpm'")
    speeds = inp.parse_speeds(speed, pitch_diameter=dm)
    res = stand.min_axial_load(speeds, z, d, dm, a)
    rows = tables.rows(tables.stand_load(speeds, res))
    echo = inp.inputs_echo(b, contact_angle_deg=math.degrees(a))
    return dict(echo, **rows[0]) if len(rows) == 1 else dict(echo, cases=rows)
