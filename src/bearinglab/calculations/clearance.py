"""The ``clearance`` document: the mounted clearance of a bearing (issue 23).

The chain from the unmounted clearance (an ISO 5753-1 class, or ``radial_clearance``) through the fits
(ISO 286 fields and ISO 492 tolerances, or the interferences given), the temperatures and the speed to
the operating clearance, as least / probable / largest; ``monte_carlo`` samples add its distribution
over random tolerances. The physics is :mod:`bearinglab.mounting`. The command line
(``bearinglab clearance``) and the web compute it here alike.

Functions
---------
document   Parsed request -> the JSON document ``bearinglab clearance --json`` prints
"""

from __future__ import annotations

from .. import catalog as _catalog
from .._io import json_value
from ._failures import failures
from ._finite import finite
from ._inputs import inputs_echo, parse_speed, resolve_bearing
from ._mounting import mounted_inputs

__all__ = ["document"]

_UM, _MPA = 1e-6, 1e6
_MOUNTING = ("shaft_fit", "housing_fit", "shaft_interference", "housing_interference", "shaft_bore",
             "housing_outside_diameter", "shaft_material", "housing_material", "shaft_roughness",
             "housing_roughness", "tolerance_class", "clearance_class", "radial_clearance",
             "inner_ring_temperature", "outer_ring_temperature", "ball_temperature", "shaft_temperature",
             "housing_temperature")


@finite('clearance')
def document(parsed, *, bearing_file=None, catalog=None, execution=None):
    """The document of ``bearinglab clearance ... --json`` for a checked request.

    Parameters
    ----------
    parsed : Parsed
        A request of the calculation ``clearance``.
    bearing_file, catalog : Path, optional
        The command line's bearing file and user catalog (the web gives neither).
    execution : bearinglab.parallel.Execution, optional
        Where the Monte Carlo samples run (serial by default; the result does not depend on it).

    Returns
    -------
    dict
        The chain's least / probable / largest values, ``monte_carlo`` with ``monte_carlo`` samples,
        ``warnings`` (with the bearing's provenance notes).

    Raises
    ------
    RunFailure
        An input the chain refuses, naming its field.
    """
    with failures(parsed.calculation):
        return json_value(_document(parsed, bearing_file, catalog, execution))


def _text(parsed, name):
    return str(parsed.given[name]).strip() if name in parsed.given else None


def _document(parsed, bearing_file, catalog, execution):
    from ..mounting import chain
    from ..mounting import monte_carlo as mc

    values = parsed.values
    b = resolve_bearing(_text(parsed, "bearing"), bearing_file, catalog)
    speed = _text(parsed, "speed")
    w = 0.0 if speed is None else parse_speed(speed, "speed", bearing=b)
    inp = mounted_inputs(b, **{k: _text(parsed, k) for k in _MOUNTING}, speed=w, require=True)
    r = chain.operating_range(inp.unmounted, inp.inner, inp.outer, inp.mounting, inp.conditions)
    doc = _chain_document(b, inp, r, speed)
    samples = values.get("monte_carlo")
    if samples is not None:
        seed, distribution = values.get("seed", 0), values.get("distribution", "uniform")
        study = mc.monte_carlo(samples, seed, inp.limits, inp.mounting, inp.conditions,
                               distribution=distribution, execution=execution)
        doc["monte_carlo"] = {
            "samples": samples, "seed": seed, "distribution": distribution,
            "mean_um": study.mean / _UM, "std_um": study.std / _UM,
            "percentiles_um": {f"p{p:g}": v / _UM for p, v in study.percentiles.items()},
            "probability_negative_clearance": study.probability_preload,
        }
        if study.probability_preload > 0:
            doc["warnings"].append(f"{100 * study.probability_preload:.3g} % of the Monte Carlo samples "
                                   "run with a negative clearance (preloaded)")
    notes = doc["warnings"]  # the bearing's provenance notes after the chain's, as the command line adds them
    doc["warnings"] = notes + [n for n in dict.fromkeys(_catalog.provenance_notes(b)) if n not in notes]
    return doc


def _chain_document(b, inp, r, speed_text):
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
        "unmounted_clearance_min_um": um(inp.unmounted[0]),
        "unmounted_clearance_max_um": um(inp.unmounted[1]),
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
