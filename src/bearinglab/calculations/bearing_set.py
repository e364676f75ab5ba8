"""A preloaded bearing set (issue 11) as a calculation: the document of ``bearinglab bearing-set --json``,
and its figure.

DB / DF / DT sets of like or unlike bearings on a rigid shaft under (F_x, F_y, F_z, M_x, M_y), preloaded
by a force or an axial interference, with the mounting inputs applied to the set's clearance and
interference (:func:`bearinglab.quasistatic.sets.set_analysis`, :func:`.._mounting.mounted_set`). The
command line (:mod:`bearinglab.cli.load`) and the web compute the same document with :func:`document`.

Functions
---------
document   Parsed -> the document (the shaft, each bearing's ball loads, the set's stiffness)
figure     a document -> the polar plot of the ball loads of its bearing 0
"""

from __future__ import annotations

import json
import types

from ..errors import InputError
from ._failures import failures
from ._finite import finite
from ._inputs import choice, five_loads, parse_length
from ._request import given_text, with_notes
from .load_distribution import inputs, plausibility, solve, takeup_um, with_takeup

__all__ = ["document", "figure"]

_LOADS = ("fx", "fy", "fz", "mx", "my", "radial_load", "axial_load")
_MOUNTING = ("shaft_fit", "housing_fit", "shaft_interference", "housing_interference", "shaft_bore",
             "housing_outside_diameter", "shaft_material", "housing_material", "tolerance_class",
             "inner_ring_temperature", "outer_ring_temperature", "ball_temperature", "shaft_temperature",
             "housing_temperature")


def _names(value):
    """The bearings of the request: a list (the command line's repeated option, the web's checked list)
    or one comma-separated text."""
    if isinstance(value, str):
        return [s.strip() for s in value.split(",") if s.strip()]
    return [str(s).strip() for s in value]


@finite('bearing-set')
def document(parsed, *, catalog=None):
    """The document of ``bearinglab bearing-set ... --json`` for a checked request.

    Parameters
    ----------
    parsed : Parsed
        A request of the calculation ``bearing-set`` (:func:`bearinglab.calculations.parse`).
    catalog : str or Path, optional
        The command line's user catalog (the web takes none).

    Returns
    -------
    dict
        The document: the shaft's displacement and stiffness, ``preload_offset_um``,
        ``operating_preload_N``, ``bearings`` (each one's loads and ball loads), ``inputs`` and
        ``warnings`` (the bearings' provenance notes last).

    Raises
    ------
    RunFailure
        An input the calculation refuses, naming its field.
    """
    import numpy as np

    from .. import catalog as _catalog
    from .. import tables
    from ..quasistatic import combined, sets
    from ..units import parse_quantity
    from . import _mounting, _rollers
    from .load_distribution import _speeds

    v = parsed.values

    def text(name):
        return given_text(parsed, name)

    with failures(parsed):
        names_given = _names(v["bearing"])
        bl = [_catalog.get(name, catalog=catalog) for name in names_given]
        if any(_rollers.is_roller(b) for b in bl):  # a pair of tapered roller bearings (issue 32)
            from . import _roller_pairs

            return json.loads(tables.json_text(_roller_pairs.document(parsed, bl)))
        for name in ("slices", "induced_axial_factor"):  # inputs of tapered pairs
            if name in parsed.given and (name, given_text(parsed, name)) != ("induced_axial_factor", "SKF"):
                raise InputError(f"{name.replace('_', '-')}: an input of a pair of tapered roller bearings; "
                                 f"{bl[0].designation!r} is a ball bearing")
        from ..bearing import check_model

        for b in bl:
            check_model(b, "bearing-set")
        notes = [n for b in bl for n in _catalog.provenance_notes(b)]
        arrangement = choice("arrangement", text("arrangement") or "DB", tuple(sets.ARRANGEMENTS))
        s = None if text("spacing") is None else parse_length(text("spacing"), "spacing", zero=True)
        if text("preload") is not None and text("preload_offset") is not None:
            raise InputError("preload: give --preload or --preload-offset, not both")
        fp = 0.0 if text("preload") is None else parse_quantity(text("preload"), "force", "preload")
        classes = {(b.preload_class, b.preload) for b in bl}
        if text("preload") is None and text("preload_offset") is None and len(classes) == 1:
            cls, value = classes.pop()
            if value is not None:  # issue 30: the preload class of the designation (GA, GB, GC), by SKF's table
                fp = value
                notes.append(f"preload: {fp:g} N of the class {cls} of {bl[0].designation} "
                             f"({bl[0].sources.get('preload', 'the maker table')})")
            elif cls is not None:
                notes.append(f"preload: the class {cls} of {bl[0].designation} has no preload in the catalog; give "
                             "--preload (the set is solved without)")
        if not fp >= 0:
            raise InputError(f"preload must be >= 0 [N] (an axial force at rest), got {fp:g} N")
        e = None if text("preload_offset") is None else parse_quantity(text("preload_offset"), "length",
                                                                        "preload-offset")
        loads = five_loads(*map(text, _LOADS))
        # the speed guard of the largest bearing of the set (the highest d_m n)
        w = float(_speeds(text("speed") or "0 rpm", False, max(b.require("pitch_diameter") for b in bl))[0])
        phi0 = parse_quantity(text("first_ball_angle") or "0 deg", "angle", "first-ball-angle")
        stiffness_at = choice("stiffness-at", text("stiffness_at") or "operating", combined.STIFFNESS_AT)
    one = bl if len(bl) > 1 else bl[0]
    st, caught = solve(sets.set_analysis, one, loads, w, arrangement_kind=arrangement, spacing=s, preload=fp,
                       preload_displacement=e, first_ball_angle=phi0, stiffness_at=stiffness_at)
    # issue 23: fits, temperatures and speed change each bearing's clearance, and so the set's interference
    # the thermal expansion over the spacing needs its value: the solver's own when it is the default
    gap = s if s is not None else (float(np.diff(st.positions)[0]) if len(st.positions) > 1 else 0.0)
    with failures(parsed):
        mounted = _mounting.mounted_set(bl, st.preload_displacement, arrangement, gap, w,
                                        {k: text(k) for k in _MOUNTING})
    if mounted is not None:
        bl = mounted.bearings
        st, caught = solve(sets.set_analysis, bl if len(bl) > 1 else bl[0], loads, w, arrangement_kind=arrangement,
                           spacing=s, preload_displacement=mounted.interference, first_ball_angle=phi0,
                           stiffness_at=stiffness_at)
        caught = [*mounted.warnings, *caught]
    idle, _ = solve(sets.set_analysis, bl if len(bl) > 1 else bl[0], [0.0] * 5, w, arrangement_kind=arrangement,
                    spacing=s, preload_displacement=st.preload_displacement, first_ball_angle=phi0,
                    stiffness_at=stiffness_at)
    operating_preload = float(abs(np.asarray(idle.bearing_loads)[0][2]))
    caught = list(dict.fromkeys([*st.warnings, *caught]))
    orient, pos = sets.arrangement(arrangement, np.diff(st.positions), len(st.bearings))
    gaps_mm = [float(g) * 1e3 for g in np.diff(st.positions)]
    spacing_mm = gaps_mm[0] if len(set(gaps_mm)) == 1 else gaps_mm  # one value, or one per gap
    names = [b.designation for b in bl] * (len(st.bearings) if len(bl) == 1 else 1)
    members = []
    for k, part in enumerate(st.bearings):
        bk = bl[k % len(bl)]
        ns = types.SimpleNamespace(**{"azimuth": combined.ball_azimuths(bk.n_balls, phi0), **part})
        carried = st.bearing_loads[k]
        if bool(np.all(st.converged)):
            caught += [f"bearing {k}: {m}" for m in plausibility(bk, carried, ns, [])]
        members.append({"bearing": names[k], "orientation": int(orient[k]),
                        "position_mm": float(pos[k] * 1e3) + 0.0,  # + 0.0: no -0
                        "loads": {"fx_N": carried[0], "fy_N": carried[1], "fz_N": carried[2],
                                  "mx_Nmm": carried[3] * 1e3, "my_Nmm": carried[4] * 1e3},
                        **with_takeup(tables.load_distribution(ns), takeup_um(bk))})
    doc = {**with_takeup(tables.load_distribution(_shaft(st)), _set_takeup_um(bl, orient)),
           "preload_offset_um": st.preload_displacement * 1e6,
           "operating_preload_N": operating_preload,
           **({} if mounted is None else {"operating_clearance_um": mounted.clearance * 1e6,
                                          "mounting": mounted.echo}),
           "bearings": members,
           "inputs": {**inputs(bl[0], loads, w, phi0, stiffness_at=stiffness_at), "bearings": names,
                      "arrangement": arrangement, "spacing_mm": spacing_mm, "spacing_default": st.default_spacing,
                      "preload_N": fp,
                      "preload_offset_um": None if e is None else e * 1e6},
           "warnings": caught}
    del doc["balls"], doc["max_ball_load_N"]
    if mounted is not None:  # issue 30: each bearing's radial preload where the fits took all its clearance
        from . import _preload

        preloaded, note = _preload.report(bl[0], source="each bearing's operating clearance from the fits and "
                                                        "temperatures")
        if note:
            doc = {**{k: v for k, v in doc.items() if k != "warnings"}, **preloaded,
                   "warnings": [note + " (besides the set's axial preload)", *doc["warnings"]]}
    return json.loads(tables.json_text(with_notes(tables.json_value(doc), notes)))


def figure(doc):
    """The polar plot of the ball loads of bearing 0 of a set's document (``bearing-set --plot``).

    Parameters
    ----------
    doc : dict
        A document of :func:`document`.

    Returns
    -------
    matplotlib.figure.Figure
    """
    from .load_distribution import figure as ball_loads

    first = doc["bearings"][0]
    if "iso281" in doc:  # a tapered pair (issue 32): bearing A's rollers and laminae
        if "rollers" not in first:
            raise InputError("plot: the slice model of this pair was not computed (see the warnings): there are no "
                             "roller loads to draw")
        return ball_loads(first, title=f"Pair {doc['inputs']['arrangement']}: bearing A ({first['bearing']}), "
                                       "roller loads and lamina pressures")
    return ball_loads(first, title=f"Set {doc['inputs']['arrangement']}: ball loads of bearing 0 "
                                   f"({first['bearing']})")


def _set_takeup_um(bearings, orient):
    """The axial play inside the shaft's delta_z [um]: none for opposed bearings (the shaft is counted from
    the assembled set, play taken up or preloaded), else that of the bearing whose balls touch first."""
    import numpy as np

    if not np.all(orient == orient[0]):
        return 0.0
    return min(takeup_um(b) for b in bearings)


def _shaft(st):
    """The shaft of a set as the fields :func:`bearinglab.tables.load_distribution` reads."""
    import numpy as np

    return types.SimpleNamespace(displacement=st.displacement, stiffness=st.stiffness, converged=st.converged,
                                 residual=st.residual, iterations=st.iterations, ball_load_inner=np.zeros(1),
                                 azimuth=np.zeros(0), ball_load_outer=np.zeros(0),
                                 contact_angle_inner=np.zeros(0), contact_angle_outer=np.zeros(0),
                                 max_pressure_inner=np.zeros(0), max_pressure_outer=np.zeros(0))
