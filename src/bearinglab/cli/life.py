"""Command line of the rating life (issue 12): ``life``.

ISO 281 and ISO/TS 16281 lives of a bearing under (F_x, F_y, F_z, M_x, M_y) at a speed
(:func:`bearinglab.life.rating_life`; the ball loads of the reference life from the combined-load
model), or of a duty cycle (``--duty-cycle FILE``, :func:`bearinglab.life.duty_cycle_life`). The columns
are :func:`bearinglab.tables.rating_life`. Where ISO 281's P is not defined (under a moment) its fields
are null and a warning says why; the ISO/TS 16281 fields are still given. The document is
:func:`bearinglab.calculations.life.document`, the web's too; this module reads the options and prints.

Duty-cycle file (TOML; the time shares sum to 1)::

    [[step]]
    fx = "2 kN"          # any of fx, fy, fz, mx, my (radial_load = fx, axial_load = fz)
    fz = "500 N"
    speed = "3000 rpm"
    time = 0.6

Commands
--------
COMMANDS   the ``life`` command, by name (the application adds it)
"""

from ..calculations.life import _CONTAMINATION, _CONTAMINATION_CLASSES  # noqa: F401 -- startup test
from ._common import (
    BearingFile,
    CatalogFile,
    JsonFlag,
    cell_text,
    check_input,
    emit_json,
    print_document,
    print_warnings,
    run_calculation,
    table,
)
from ._options import command

__all__ = ["COMMANDS"]

_NEEDS_VISCOSITY = "needs viscosity"  # the table's cell of a result that needs the lubricant


def life(given, *, bearing_file: BearingFile = None, catalog: CatalogFile = None, json_out: JsonFlag = False):
    """Rating life (ISO 281, ISO/TS 16281): C, C0, Cu, P, L10, a_ISO, L_nm, L10r, L_nmr, s0; duty cycles.

    Without a lubricant (--viscosity, or --oil with --temperature) P, L10, L10r and s0 are given, and
    a_ISO, L_nm and L_nmr are null ("needs viscosity"). --temperature auto takes the oil's viscosity at
    the bearing's steady temperature (the thermal balance of `temperature`).
    """
    from ..calculations import life as calculation
    from ..errors import InputError

    source = calculation.POSTED
    duty_cycle = given.get("duty_cycle")
    if duty_cycle is not None:  # the command line's document is a file: its text is the field
        from .._bounds import read_input_bytes

        try:  # a regular file of bounded size
            given["duty_cycle"] = read_input_bytes(check_input(duty_cycle, "duty-cycle")).decode("utf-8")
        except UnicodeDecodeError:
            raise InputError(f"duty-cycle: {duty_cycle}: not a UTF-8 text file") from None
        source = str(duty_cycle)
    doc = run_calculation("life", given, calculation.document, catalog=catalog, bearing_file=bearing_file,
                          duty_cycle_source=source)
    if json_out:
        emit_json(doc)
        return
    if isinstance(doc, list):  # a speed list: one row per speed
        _print_speeds(doc)
        return
    lubricated = bool({"viscosity_cSt", "oil"} & set(doc["inputs"]))
    if duty_cycle is not None:
        _print(f"Duty cycle of {doc['inputs']['bearing']}: {len(doc['steps'])} steps, mean speed "
               f"{doc['mean_speed_rpm']:g} rpm", doc, lubricated)
        return
    _print(f"Rating life of {doc['inputs']['bearing']} at {doc['inputs']['speed_rpm']:g} rpm", doc, lubricated)


# The printed names of the JSON keys: the symbols of ISO 281 and ISO/TS 16281, with the unit.
_LABELS = {
    "dynamic_load_rating_N": "basic dynamic load rating C [N]",
    "static_load_rating_N": "basic static load rating C0 [N]",
    "fatigue_load_limit_N": "fatigue load limit Cu [N]",
    "equivalent_dynamic_load_N": "equivalent dynamic load P [N]",
    "basic_rating_life_Mrev": "basic rating life L10 [10^6 rev]",
    "basic_rating_life_h": "basic rating life L10h [h]",
    "reliability_factor": "reliability factor a1 [-]",
    "viscosity_mm2_s": "operating viscosity nu [mm^2/s]",
    "bearing_temperature_degC": "bearing temperature (balance) [degC]",
    "rated_viscosity_mm2_s": "rated viscosity nu1 [mm^2/s]",
    "rated_viscosity_diameter_mm": "diameter d_m of nu1 [mm]",
    "viscosity_ratio": "viscosity ratio κ [-]",
    "life_modification_factor": "life modification factor a_ISO [-]",
    "modified_rating_life_Mrev": "modified rating life L_nm [10^6 rev]",
    "modified_rating_life_h": "modified rating life L_nmh [h]",
    "reference_rating_life_Mrev": "reference rating life L10r [10^6 rev]",
    "modified_reference_rating_life_Mrev": "modified ref. life L_nmr [10^6 rev]",
    "static_safety_factor": "static safety factor s0 [-]",
    "mean_speed_rpm": "mean speed [rpm]",
    "contamination_factor": "contamination factor e_C [-]",
    "operating_clearance_um": "operating clearance, probable [um]",
    "operating_clearance_min_um": "operating clearance, least [um]",
    "operating_clearance_max_um": "operating clearance, largest [um]",
    "unmounted_clearance_um": "unmounted clearance, min, max [um]",
    "mounting": "mounting",
}


# the results that need the lubricant: shown as "needs viscosity" without one
_LUBRICATED = ("viscosity_mm2_s", "viscosity_ratio", "contamination_factor", "life_modification_factor",
               "modified_rating_life_Mrev",
               "modified_rating_life_h", "modified_reference_rating_life_Mrev")


def _print(title, doc, lubricated):
    """The document as one table: ISO 281's symbols (:data:`_LABELS`), each rating with its source."""
    src = doc["rating_source"]

    def cell(k, v):
        if v is None and k in _LUBRICATED and not lubricated:
            text = _NEEDS_VISCOSITY
        else:
            text = "— (see the warnings)" if v is None else cell_text(v)
        return text + (f"  ({src[k[:-2]]})" if k[:-2] in src else "")

    # the mounting's own notes join the warnings, after the table (never a Python list in a cell)
    doc = {**doc, "warnings": [*doc.get("mounting_warnings", []), *doc.get("warnings", [])]}
    if isinstance(doc.get("mounting"), dict):  # the mounting echo in one cell, in words ('shaft fit: j5; ...')
        doc["mounting"] = cell_text(doc["mounting"])
    print_document(title, doc, label=lambda k: _LABELS.get(k, k), cell=cell,
                   skip=("rating_source", "steps", "mounting_warnings"),
                   caption="--json for one JSON document (keys in the units shown)")


def _print_speeds(docs):
    """A speed list: the ratings and P once, the lives of each speed in a row (issue 30)."""
    first = docs[0]

    def f(d, key, spec=".4g"):
        v = d.get(key)
        return (_NEEDS_VISCOSITY if key in _LUBRICATED and "viscosity_mm2_s" not in d else "—") if v is None \
            else format(v, spec)

    rows = [[f(d["inputs"], "speed_rpm", "g"), f(d, "basic_rating_life_h", ".6g"), f(d, "viscosity_ratio"),
             f(d, "contamination_factor", ".3g"), f(d, "life_modification_factor"),
             f(d, "modified_rating_life_h", ".6g"), f(d, "reference_rating_life_Mrev", ".5g")] for d in docs]
    table(f"Rating life of {first['inputs']['bearing']}: C {first['dynamic_load_rating_N']:g} N, "
          f"C0 {first['static_load_rating_N']:g} N, Cu {first['fatigue_load_limit_N']:g} N, "
          f"P {cell_text(first['equivalent_dynamic_load_N'])} N",
          ["n [rpm]", "L10h [h]", "κ", "e_C", "a_ISO", "L_nmh [h]", "L10r [10^6 rev]"], rows,
          caption="--json for one JSON document per speed")
    print_warnings(list(dict.fromkeys(w for d in docs for w in [*d.get("mounting_warnings", []), *d["warnings"]])))


# the duty-cycle file is read by the command itself, which names it in the messages of its steps
#: The ``life`` command, as the application adds it.
COMMANDS = {"life": command("life", life, documents="path")}
