"""Roller bearings on the calculator page (issue 32): which sections a roller bearing leaves out, and the
tables of its documents (per roller, per bearing of a tapered pair, ISO 281's method of the pair).

roller_of   the roller bearing of the form (its catalog designation or the inline roller set), or None
left_out    why a section does not apply to a roller bearing (one line), or ''
query       a section's query for a roller bearing (the frequencies without the stand load)
tables      the tables of a roller document the page shows apart, and the keys it leaves out of the generic ones

:mod:`bearinglab.web.page` calls these; the template shows the tables (``templates/_rollers.html``).
"""

from __future__ import annotations

__all__ = ["left_out", "query", "roller_of", "tables"]


def _given(values, name):
    return bool(str(values.get(name) or "").strip())


def roller_of(values):
    """The roller bearing of the form (its catalog designation, or the inline roller set), or None."""
    name = str(values.get("bearing") or "").strip()
    if not name:
        return "inline" if any(_given(values, k) for k in ("rollers", "roller_diameter", "roller_length")) else None
    return _bearing(name)


def _bearing(name):
    """The catalog's roller bearing of this name, or None (a ball bearing, or no such bearing: its sections
    say so)."""
    from .. import catalog

    try:
        b = catalog.get(name)
    except Exception:  # noqa: BLE001 -- an unknown name: the sections name the error at its field
        return None
    return b if hasattr(b, "roller_diameter") else None


#: the sections of ball bearings' models, which a roller bearing leaves out
_BALL_SECTIONS = ("high-speed", "axial-angle", "stand-load", "runout")
#: the sections that need a load distribution, which a spherical roller bearing has not
_DISTRIBUTION_SECTIONS = ("load-distribution", "film", "frequencies", "clearance", "bearing-set")


def left_out(section, values, roller):
    """Why a section does not apply to a roller bearing (one line), or ''."""
    from ..calculations._rollers import BALL_MODELS

    label = "the inline roller bearing" if roller == "inline" else f"{roller.designation} is a {roller.type} " \
        "roller bearing;"
    kind = None if roller == "inline" else roller.type
    if section.key in _BALL_SECTIONS:
        return f"Left out: {label} {BALL_MODELS[section.calculation]}, a model of ball bearings."
    if kind == "spherical" and section.key in _DISTRIBUTION_SECTIONS:
        return (f"Left out: {label} its load distribution is not modelled: spherical roller bearings have "
                "ratings, life and friction only.")
    if section.key == "friction" and (values.get("model") or "one-term") != "skf":
        return f"Left out: {label} choose the skf friction model (the handbook models are ball bearings')."
    if section.key == "bearing-set" and values.get("arrangement"):
        if kind != "tapered":
            return f"Left out: {label} a set of roller bearings is a pair of tapered roller bearings."
        if values.get("arrangement") == "DT":
            return f"Left out: {label} a tapered pair is DB (back to back) or DF (face to face)."
        if not _given(values, "spacing"):
            return (f"Left out: {label} a tapered pair needs the spacing of its pressure centres (the "
                    "effective spread).")
    if section.key == "clearance" and kind == "tapered":
        return (f"Left out: {label} its play is set by adjusting it against the other bearing of its pair (the "
                "bearing set).")
    return ""


def query(section, values, query):
    """A section's query for a roller bearing: the frequencies of its rollers are at its nominal angle (the
    operating angle under a stand load is the test-stand method of ball bearings), so without the axial load."""
    if section.key == "frequencies" and "axial_load" in query and roller_of(values) is not None:
        query = {k: v for k, v in query.items() if k != "axial_load"}
    return query


def tables(document, number):
    """The tables of a roller bearing's document the page shows apart: per roller (load, pressure, film) and
    per bearing of a tapered pair (ISO 281's method); and the document's keys the generic tables leave out.

    Parameters
    ----------
    document : dict or list or None
        A section's document.
    number : callable
        The page's formatter of a value (:func:`bearinglab.web.page.number`).

    Returns
    -------
    tuple
        ``(tables, skip)``: each table a dict of ``title``, ``columns`` and ``rows`` (cells as text), and the
        keys of ``document`` not to show as rows of their own.
    """
    if not isinstance(document, dict):
        return [], ()
    tables = []
    if isinstance(document.get("rollers"), list):
        tables.append(_rollers_table("Rollers", document, number))
    if isinstance(document.get("iso281"), dict):
        for k, m in enumerate(document.get("bearings") or ()):
            if isinstance(m.get("rollers"), list):
                tables.append(_rollers_table(f"Bearing {'AB'[k]} ({m['bearing']}): rollers, F_r = "
                                             f"{number(m['radial_load_N'])} N, F_a = {number(m['axial_load_N'])} N", m, number))
        iso = document["iso281"]
        tables.append({"title": f"ISO 281's method, induced axial load {number(iso['induced_axial_factor'])} F_r/Y "
                                f"({iso['source']})",
                       "columns": ["bearing", "F_r [N]", "f F_r/Y [N]", "F_a [N]", "P [N]", "L10 [10⁶ rev]", "L10h [h]"],
                       "rows": [[f"{'AB'[k]} {m['bearing']}", *(number(m[key]) for key in (
                           "radial_load_N", "induced_axial_load_N", "axial_load_N", "equivalent_dynamic_load_N",
                           "basic_rating_life_Mrev", "basic_rating_life_h"))]
                                for k, m in enumerate(iso["bearings"])]})
        return tables, ("rollers", "bearings")
    return tables, ("rollers",) if tables else ()


def _rollers_table(title, doc, number):
    """One table of rollers: a load distribution's (load, highest lamina pressure and where) or a film's."""
    rows = doc["rollers"]
    if rows and "lambda" in rows[0]:  # the film of every roller
        return {"title": f"{title} ({len(rows)})", "columns": ["roller", "ψ [°]", "Q [N]", "h_min,i [µm]",
                                                                "h_min,o [µm]", "Λ"],
                "rows": [[str(j), number(r["azimuth_deg"]), number(r["load_N"]), number(r["film_min_inner_um"]),
                          number(r["film_min_outer_um"]), number(r["lambda"])] for j, r in enumerate(rows)]}
    positions = doc.get("slice_positions_mm") or []

    def peak(r):
        p = [x if x is not None else -1.0 for x in r.get("slice_pressures_MPa") or ()]
        if not p or not r["load_N"]:
            return "—"
        return number(positions[max(range(len(p)), key=p.__getitem__)])

    return {"title": f"{title} ({len(rows)}, {doc.get('slices')} slices each; p_max at s from the roller's middle)",
            "columns": ["roller", "ψ [°]", "Q [N]", "p_max [MPa]", "at s [mm]"],
            "rows": [[str(j), number(r["azimuth_deg"]), number(r["load_N"]), number(r["max_pressure_MPa"]), peak(r)]
                     for j, r in enumerate(rows)]}
