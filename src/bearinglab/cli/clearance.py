"""Command line of the mounted clearance (issue 23): ``clearance``.

The chain from the unmounted clearance (an ISO 5753-1 class, or ``--radial-clearance``) through the fits
(ISO 286 fields and ISO 492 tolerances, or the interferences given), the temperatures and the speed to the
operating clearance, as least / probable / largest; ``--monte-carlo N`` adds its distribution over random
tolerances on the executor of :mod:`bearinglab.parallel`. The physics is :mod:`bearinglab.mounting`; the
mounting options are the fields ``MOUNTING`` of :mod:`bearinglab.calculations.registry`, shared with the
other commands.

Commands
--------
COMMANDS   the ``clearance`` command, by name (the application adds it)
"""

from __future__ import annotations

from ._common import (
    BearingFile,
    CatalogFile,
    ChunkSizeOpt,
    ExecutorOpt,
    JsonFlag,
    WorkersOpt,
    emit_json,
    execution,
    print_warnings,
    table,
)
from ._options import command

__all__ = ["COMMANDS"]


def clearance(
    given, *, bearing_file: BearingFile = None, catalog: CatalogFile = None,
    executor: ExecutorOpt = None, workers: WorkersOpt = None, chunk_size: ChunkSizeOpt = None,
    json_out: JsonFlag = False,
):
    """Mounted clearance: unmounted -> fit -> temperature -> speed -> operating (least/probable/largest)."""
    from .. import _bounds
    from ..calculations import clearance as calculation
    from ..calculations import parse

    parsed = parse("clearance", given, limit=_bounds.MAX_SAMPLES)
    if given.get("monte_carlo") is None:
        doc = calculation.document(parsed, bearing_file=bearing_file, catalog=catalog)
    else:
        with execution("Monte Carlo", executor, workers, chunk_size) as ex:
            doc = calculation.document(parsed, bearing_file=bearing_file, catalog=catalog, execution=ex)
    if json_out:
        emit_json(doc)
        return
    _print(doc)


def _print(doc):
    cols = ("least", "probable", "largest")
    cases = [doc["chain"][c] for c in cols]
    rows = [[label, *(f"{c[key]:.2f}" for c in cases)] for label, key in (
        ("unmounted clearance", "unmounted_clearance"), ("inner interference", "inner_interference"),
        ("outer interference", "outer_interference"), ("- fit reduction", "fit_reduction"),
        ("- thermal reduction", "thermal_reduction"), ("- centrifugal reduction", "centrifugal_reduction"),
        ("= operating clearance", "operating_clearance"), ("inner fit pressure (MPa)", "inner_pressure"),
        ("outer fit pressure (MPa)", "outer_pressure"))]
    table(f"Mounted clearance of {doc['bearing']} (um)", ["stage", *cols], rows,
          caption=f"unmounted: {doc['unmounted_clearance_source']}; tolerance class "
                  f"{doc['tolerance_class']}")
    if "monte_carlo" in doc:
        m = doc["monte_carlo"]
        mrows = [[k, f"{v:.2f}"] for k, v in m["percentiles_um"].items()]
        mrows += [["mean", f"{m['mean_um']:.2f}"], ["std", f"{m['std_um']:.2f}"],
                  ["P(clearance < 0)", f"{m['probability_negative_clearance']:.4f}"]]
        table(f"Monte Carlo: {m['samples']} samples, {m['distribution']}, seed {m['seed']} (um)",
              ["operating clearance", "value"], mrows)
    print_warnings(doc["warnings"])


COMMANDS = {"clearance": command("clearance", clearance)}
