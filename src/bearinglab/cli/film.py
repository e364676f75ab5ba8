"""Command line of the lubricant film (issue 24): ``film``.

The EHL film (Hamrock and Dowson) at every ball's inner and outer contact of a bearing under
(F_x, F_y, F_z, M_x, M_y) at a speed (:func:`bearinglab.film.film_analysis`): the ball loads and angles
of the load distribution (quasi-static at the speed, or at rest), the lubricant's viscosity (given, or of
an ISO VG oil at a temperature; ``--temperature auto`` takes the steady bearing temperature of
:mod:`bearinglab.thermal`), its pressure-viscosity coefficient and the surface roughness. The columns are
:func:`bearinglab.tables.film`.

Commands
--------
COMMANDS   the ``film`` command, by name (the application adds it)
"""

from ._common import (
    BearingFile,
    CatalogFile,
    JsonFlag,
    emit_json,
    print_warnings,
    table,
)
from ._options import command

__all__ = ["COMMANDS"]


def film(given, *, bearing_file: BearingFile = None, catalog: CatalogFile = None, json_out: JsonFlag = False):
    """EHL film (Hamrock-Dowson) at every ball's contacts, or the line-contact film of every roller: h_c, h_min,
    film parameter Lambda and regime."""
    from ..calculations import film as calculation
    from ..calculations import parse

    # typer has read the options; the calculation checks each value by the command line's own rules
    # (its messages), not by the fields' ranges the web checks first
    result = calculation.document(parse("film", given, check=False),
                                  bearing_file=bearing_file, catalog=catalog)
    if json_out:
        emit_json(result)
        return
    docs = result if isinstance(result, list) else [result]
    for doc in docs:
        _print(doc)
    print_warnings(docs[0]["warnings"])


def _f(x, spec):
    return "—" if x is None else format(x, spec)


def _print(doc):
    rpm = doc["inputs"]["speed_rpm"]
    if "rollers" in doc:  # a roller bearing (issue 32): one line contact per roller, both raceways
        table(f"Film of {doc['inputs']['bearing']} at {rpm:g} rpm",
              ["roller", "ψ [deg]", "Q [N]", "h_min,i [µm]", "h_min,o [µm]", "Λ"],
              [[str(j), _f(r["azimuth_deg"], ".2f"), _f(r["load_N"], ".1f"), _f(r["film_min_inner_um"], ".4f"),
                _f(r["film_min_outer_um"], ".4f"), _f(r["lambda"], ".2f")] for j, r in enumerate(doc["rollers"])],
              caption=f"{doc['inputs']['lubricant']}; --json for h_c and the velocity")
    else:
        table(f"Film of {doc['inputs']['bearing']} at {rpm:g} rpm",
              ["ball", "Q_i [N]", "Q_o [N]", "h_min,i [µm]", "h_min,o [µm]", "Λ_i", "Λ_o"],
              [[str(j), _f(r["load_inner_N"], ".1f"), _f(r["load_outer_N"], ".1f"), _f(r["film_min_inner_um"], ".4f"),
                _f(r["film_min_outer_um"], ".4f"), _f(r["lambda_inner"], ".2f"), _f(r["lambda_outer"], ".2f")]
               for j, r in enumerate(doc["balls"])],
              caption=f"{doc['inputs']['lubricant']}; --json for h_c, angles and velocities")
    table("Smallest film", ["quantity", "value"],
          [["h_min [µm]", _f(doc["film_min_um"], ".4f")], ["Λ_min", _f(doc["lambda_min"], ".3f")],
           ["regime", doc["regime"] or "—"]])


#: The ``film`` command, as the application adds it.
COMMANDS = {"film": command("film", film)}
