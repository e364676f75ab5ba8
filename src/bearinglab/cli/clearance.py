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

from ..errors import InputError
from ._common import (
    BearingFile,
    BearingName,
    CatalogFile,
    ChunkSizeOpt,
    ExecutorOpt,
    JsonFlag,
    WorkersOpt,
    choice,
    emit_json,
    execution,
    inputs_echo,
    parse_speed,
    print_warnings,
    resolve_bearing,
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
    mounted_inputs,
)

__all__ = ["COMMANDS"]

_UM, _MPA = 1e-6, 1e6
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
    from ..mounting import chain
    from ..mounting import monte_carlo as mc

    b = resolve_bearing(bearing, bearing_file, catalog)
    choice("distribution", distribution, mc.DISTRIBUTIONS)
    if monte_carlo is not None and monte_carlo < 2:
        raise InputError(f"monte-carlo must be an integer >= 2 [-], got {monte_carlo}")
    w = 0.0 if speed is None else parse_speed(speed, "speed", bearing=b)
    inp = mounted_inputs(b, shaft_fit=shaft_fit, housing_fit=housing_fit, shaft_interference=shaft_interference,
                         housing_interference=housing_interference, shaft_bore=shaft_bore,
                         housing_outside_diameter=housing_outside_diameter, shaft_material=shaft_material,
                         housing_material=housing_material, shaft_roughness=shaft_roughness,
                         housing_roughness=housing_roughness, tolerance_class=tolerance_class,
                         clearance_class=clearance_class, radial_clearance=radial_clearance,
                         inner_ring_temperature=inner_ring_temperature,
                         outer_ring_temperature=outer_ring_temperature, ball_temperature=ball_temperature,
                         shaft_temperature=shaft_temperature, housing_temperature=housing_temperature, speed=w,
                         require=True)
    r = chain.operating_range(inp.unmounted, inp.inner, inp.outer, inp.mounting, inp.conditions)
    doc = _document(b, inp, r, speed)
    if monte_carlo is not None:
        with execution("Monte Carlo", executor, workers, chunk_size) as ex:
            study = mc.monte_carlo(monte_carlo, seed, inp.limits, inp.mounting, inp.conditions,
                                   distribution=distribution, execution=ex)
        doc["monte_carlo"] = {
            "samples": monte_carlo, "seed": seed, "distribution": distribution,
            "mean_um": study.mean / _UM, "std_um": study.std / _UM,
            "percentiles_um": {f"p{p:g}": v / _UM for p, v in study.percentiles.items()},
            "probability_negative_clearance": study.probability_preload,
        }
        if study.probability_preload > 0:
            doc["warnings"].append(f"{100 * study.probability_preload:.3g} % of the Monte Carlo samples run "
                                   "with a negative clearance (preloaded)")
    if json_out:
        emit_json(doc)
        return
    _print(b, inp, r, doc)


def _document(b, inp, r, speed_text):
    least, prob, largest = r.least, r.probable, r.largest
    um = lambda x: float(x) / _UM
    echo = dict(inp.echo)
    if speed_text is not None:
        echo["speed"] = speed_text
    doc = inputs_echo(b, **{k.replace("-", "_"): v for k, v in echo.items()})
    doc.update({
        "unmounted_clearance_source": inp.unmounted_source,
        "ring_diameters_mm": {"inner_raceway": inp.mounting.inner_raceway * 1e3,
                              "outer_raceway": inp.mounting.outer_raceway * 1e3,
                              "estimated": inp.mounting.estimated},
        "interference_inner_min_um": um(inp.inner[0]), "interference_inner_max_um": um(inp.inner[1]),
        "interference_outer_min_um": um(inp.outer[0]), "interference_outer_max_um": um(inp.outer[1]),
        "interference_inner_probable_um": [um(inp.probable[0].least), um(inp.probable[0].largest)],
        "interference_outer_probable_um": [um(inp.probable[1].least), um(inp.probable[1].largest)],
        "fit_reduction_min_um": um(largest.fit_reduction), "fit_reduction_max_um": um(least.fit_reduction),
        "thermal_reduction_um": um(prob.thermal_reduction),
        "centrifugal_reduction_um": um(prob.centrifugal_reduction),
        "unmounted_clearance_min_um": um(inp.unmounted[0]), "unmounted_clearance_max_um": um(inp.unmounted[1]),
        "operating_clearance_min_um": um(least.operating_clearance),
        "operating_clearance_max_um": um(largest.operating_clearance),
        "operating_clearance_probable_um": um(prob.operating_clearance),
        "fit_pressure_inner_MPa": float(least.inner_pressure) / _MPA,
        "fit_pressure_outer_MPa": float(least.outer_pressure) / _MPA,
        "chain": {name: {k: (um(getattr(c, k)) if k not in ("inner_pressure", "outer_pressure",
                                                                "inner_loosened_by_speed")
                             else (bool(getattr(c, k)) if k == "inner_loosened_by_speed"
                                   else float(getattr(c, k)) / _MPA))
                         for k in c._fields}
                  for name, c in (("least", least), ("probable", prob), ("largest", largest))},
        "warnings": list(r.warnings),
    })
    return doc


def _print(b, inp, r, doc):
    cols = ("least", "probable", "largest")
    cases = (r.least, r.probable, r.largest)
    f = lambda x: f"{float(x) / _UM:.2f}"
    rows = [
        ["unmounted clearance", *(f(c.unmounted_clearance) for c in cases)],
        ["inner interference", *(f(c.inner_interference) for c in cases)],
        ["outer interference", *(f(c.outer_interference) for c in cases)],
        ["- fit reduction", *(f(c.fit_reduction) for c in cases)],
        ["- thermal reduction", *(f(c.thermal_reduction) for c in cases)],
        ["- centrifugal reduction", *(f(c.centrifugal_reduction) for c in cases)],
        ["= operating clearance", *(f(c.operating_clearance) for c in cases)],
        ["inner fit pressure (MPa)", *(f"{float(c.inner_pressure) / _MPA:.2f}" for c in cases)],
        ["outer fit pressure (MPa)", *(f"{float(c.outer_pressure) / _MPA:.2f}" for c in cases)],
    ]
    table(f"Mounted clearance of {b.designation} (um)", ["stage", *cols], rows,
          caption=f"unmounted: {inp.unmounted_source}; tolerance class {inp.echo['tolerance_class']}")
    if "monte_carlo" in doc:
        m = doc["monte_carlo"]
        mrows = [[k, f"{v:.2f}"] for k, v in m["percentiles_um"].items()]
        mrows += [["mean", f"{m['mean_um']:.2f}"], ["std", f"{m['std_um']:.2f}"],
                  ["P(clearance < 0)", f"{m['probability_negative_clearance']:.4f}"]]
        table(f"Monte Carlo: {m['samples']} samples, {m['distribution']}, seed {m['seed']} (um)",
              ["operating clearance", "value"], mrows)
    print_warnings(doc["warnings"])


COMMANDS = {"clearance": clearance}
