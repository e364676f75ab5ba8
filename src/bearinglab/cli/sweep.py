"""Command line of parameter sweeps: ``bearinglab sweep FILE.toml`` (see :mod:`bearinglab.sweep`).

Commands
--------
COMMANDS   the ``sweep`` command, by name (the application adds it)
"""

from pathlib import Path
from typing import Annotated

import typer

from ._common import (
    ChunkSizeOpt,
    ExecutorOpt,
    JsonFlag,
    WorkersOpt,
    add_notes,
    check_output,
    console,
    emit_json,
    execution,
    inputs_echo,
    table,
)

__all__ = ["COMMANDS"]


def sweep(
    file: Annotated[Path, typer.Argument(help="Sweep file (TOML): model, bearing, parameters, output, execution.")],
    out: Annotated[Path | None, typer.Option("--out", "-o", help="Result table, .csv or .parquet (overrides the file).")] = None,
    executor: ExecutorOpt = None, workers: WorkersOpt = None, chunk_size: ChunkSizeOpt = None,
    memory_limit: Annotated[str | None, typer.Option("--memory-limit", help="Per local worker, a size with a unit, e.g. '4 GiB' or '2 GB' (at least 512 MiB).", rich_help_panel="Execution")] = None,
    allow_remote_executor: Annotated[bool, typer.Option("--allow-remote-executor", help="Run on the scheduler the file names when it is on another machine.", rich_help_panel="Execution")] = False,
    json_out: JsonFlag = False,
):
    """Evaluate any calculation over the Cartesian product of parameter values; write the cases as CSV or Parquet."""
    import numpy as np

    from .. import catalog as _catalog
    from .. import sweep as _sweep
    from .. import tables
    spec = _sweep.load_sweep(file)
    if spec.bearing is not None:  # an estimated catalog bearing says so (swept bearings: in each row)
        add_notes(_catalog.provenance_notes(spec.bearing))
    if executor is None:  # the file's scheduler: confirmed on the command line when it is another machine
        _sweep.check_file_executor(spec, allow_remote_executor=allow_remote_executor,
                                   option="--allow-remote-executor")
    target = out or spec.output
    if target is not None:  # checked before the sweep runs: the directory exists, the suffix is known
        check_output(target, "out" if out is not None else "output", (".csv", ".parquet"), inputs=(file,))
    with execution(f"sweep {spec.model.name}", executor or spec.executor, workers, chunk_size,
                   memory_limit=memory_limit) as ex:
        cols = _sweep.run_sweep(spec, execution=ex)
    n = len(cols["converged"])
    failed = int(n - np.count_nonzero(cols["converged"]))
    if target is not None:
        _sweep.write_table(cols, target)
    echo = {"sweep_file": str(file), "model": spec.model.name, "path": spec.path, "constants": spec.constants}
    summary = dict(inputs_echo(spec.bearing, **echo) if spec.bearing is not None else echo,
                   cases=n, failed=failed, executor=ex.executor, output=None if target is None else str(target))
    if json_out:
        emit_json(dict(summary, results=tables.rows(cols)))
        return
    reasons = {}
    for r in np.asarray(cols["failure"])[~np.asarray(cols["converged"], dtype=bool)]:
        reasons[r] = reasons.get(r, 0) + 1
    on = f" on {spec.bearing.designation}" if spec.bearing is not None else ""
    table(f"Sweep of {spec.model.name}{on}", ["quantity", "value"],
          [["cases", n], ["failed", failed]] + [[f"  {k}", v] for k, v in reasons.items()] +
          [["executor", ex.executor], ["output", summary["output"] or "(none: give --out or [output] file)"]])
    if target is not None:
        console.print(f"wrote {target}", highlight=False)


#: The ``sweep`` command, as the application adds it.
COMMANDS = {"sweep": sweep}
