"""Command line of the mounted clearance (issue 23): ``clearance``.

The chain from the unmounted clearance (an ISO 5753-1 class, or ``--radial-clearance``) through the fits
(ISO 286 fields and ISO 492 tolerances, or the interferences given), the temperatures and the speed to the
operating clearance, as least / probable / largest; ``--monte-carlo N`` adds its distribution over random
tolerances on the executor of :mod:`bearinglab.parallel`. The physics is :mod:`bearinglab.mounting`; the
mounting options are :mod:`bearinglab.cli._mounting`, shared with the other commands.

Commands
--------
COMMANDS   the ``clearance`` command, by name (the application adds it)
"""

from __future__ import annotations

from typing import Annotated

import typer

from ._common import (
    BearingFile,
    BearingName,
    CatalogFile,
    ChunkSizeOpt,
    ExecutorOpt,
    JsonFlag,
    WorkersOpt,
    emit_json,
    execution,
    fields_given,
    print_warnings,
    table,
)
from ._mounting import (
    BallTempOpt,
    ClearanceClassOpt,
    HousingFitOpt,
    HousingInterferenceOpt,
    HousingMaterialOpt,
    HousingOutsideDiameterOpt,
    HousingRoughnessOpt,
    HousingTempOpt,
    InnerTempOpt,
    OuterTempOpt,
    ShaftBoreOpt,
    ShaftFitOpt,
    ShaftInterferenceOpt,
    ShaftMaterialOpt,
    ShaftRoughnessOpt,
    ShaftTempOpt,
    ToleranceClassOpt,
)

__all__ = ["COMMANDS"]

_MC = "Monte Carlo"


def clearance(
    bearing: BearingName = None,
    bearing_file: BearingFile = None,
    catalog: CatalogFile = None,
    shaft_fit: ShaftFitOpt = None,
    housing_fit: HousingFitOpt = None,
    shaft_interference: ShaftInterferenceOpt = None,
    housing_interference: HousingInterferenceOpt = None,
    shaft_bore: ShaftBoreOpt = None,
    housing_outside_diameter: HousingOutsideDiameterOpt = None,
    shaft_material: ShaftMaterialOpt = None,
    housing_material: HousingMaterialOpt = None,
    shaft_roughness: ShaftRoughnessOpt = None,
    housing_roughness: HousingRoughnessOpt = None,
    tolerance_class: ToleranceClassOpt = None,
    clearance_class: ClearanceClassOpt = None,
    radial_clearance: Annotated[str | None, typer.Option("--radial-clearance", help="Unmounted diametral clearance instead of the class: one value or 'min, max', e.g. '6 um, 20 um'.")] = None,
    inner_ring_temperature: InnerTempOpt = None,
    outer_ring_temperature: OuterTempOpt = None,
    ball_temperature: BallTempOpt = None,
    shaft_temperature: ShaftTempOpt = None,
    housing_temperature: HousingTempOpt = None,
    speed: Annotated[str | None, typer.Option("--speed", "-n", help="Inner-ring (shaft) speed, e.g. '6000 rpm'.")] = None,
    monte_carlo: Annotated[int | None, typer.Option("--monte-carlo", help="Samples of random tolerances through the chain.", rich_help_panel=_MC)] = None,
    seed: Annotated[int, typer.Option("--seed", help="Root seed (results do not depend on chunking).", rich_help_panel=_MC)] = 0,
    distribution: Annotated[str, typer.Option("--distribution", help="uniform | normal (limits at +-3 sigma).", rich_help_panel=_MC)] = "uniform",
    executor: ExecutorOpt = None,
    workers: WorkersOpt = None,
    chunk_size: ChunkSizeOpt = None,
    json_out: JsonFlag = False,
):
    """Mounted clearance: unmounted -> fit -> temperature -> speed -> operating (least/probable/largest)."""
    from .. import _bounds
    from ..calculations import clearance as calculation
    from ..calculations import parse

    parsed = parse("clearance", fields_given("clearance", locals()), limit=_bounds.MAX_SAMPLES)
    if monte_carlo is None:
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


COMMANDS = {"clearance": clearance}
