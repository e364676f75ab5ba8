"""The report directory of a friction-lab session, written whole or not at all.

write_report      analysed session -> a report directory: report.html, results.json, every table as
                  CSV, every plot as PNG and SVG, and a marker file
render_figure     one plot of :func:`bearinglab.lab.presentation.plots` -> (PNG bytes, SVG text)
ReportFiles       what :func:`write_report` wrote
MARKER            the marker file's name: a directory holding it may be replaced by the next report

Everything is built in a temporary directory next to the target and renamed into place at the end.
The files are written by the library's one CSV, JSON and text writer (``bearinglab._io``), the
figures drawn by :mod:`bearinglab.plots.friction` and the page marked up by :mod:`.html`.
"""

from __future__ import annotations

import io
from pathlib import Path
from typing import NamedTuple

from .._io import atomic_directory, csv_text, json_text, write_text
from ..errors import InputError
from ..lab import presentation
from ..plots.friction import fitted_lines
from .html import render_html

__all__ = ["MARKER", "ReportFiles", "render_figure", "write_report"]

MARKER = ".bearinglab-report"  # marks a directory written by write_report (it may be replaced)


class ReportFiles(NamedTuple):
    """Files written by :func:`write_report` (all inside ``directory``)."""

    directory: Path
    """The report directory."""
    html: Path
    """``report.html``."""
    json: Path
    """``results.json``."""
    figures: list
    """PNG and SVG files of the plots."""
    tables: list
    """CSV files of the tables."""


# ----------------------------------------------------------------------------- figures
def render_figure(plot):
    """One plot as PNG and SVG: the figure of :func:`bearinglab.plots.friction.fitted_lines`.

    Parameters
    ----------
    plot : bearinglab.lab.presentation.PlotData
        Points and lines in engineering units.

    Returns
    -------
    tuple of (bytes, str)
        The PNG image and the SVG text, both free of time stamps and software versions, so that the
        same plot gives the same bytes.
    """
    import matplotlib

    fig = fitted_lines(plot)
    with matplotlib.rc_context({"svg.fonttype": "path", "svg.hashsalt": plot.name}):
        png = io.BytesIO()
        fig.savefig(png, format="png", metadata={"Software": None})
        svg = io.StringIO()
        fig.savefig(
            svg,
            format="svg",
            metadata={"Date": None, "Creator": None, "Format": None, "Type": None},
        )
    text = svg.getvalue()
    start = text.find("<metadata>")  # drop the RDF block: it only names external vocabularies
    if start >= 0:
        end = text.find("</metadata>", start)
        text = text[:start] + text[end + len("</metadata>") :]
    return png.getvalue(), text


# ----------------------------------------------------------------------------- writing
def _write_table(directory, name, columns, rows):
    """``name.csv`` in ``directory`` (None is an empty cell); returns the file name."""
    write_text(directory / f"{name}.csv", csv_text(columns, rows))
    return f"{name}.csv"


def _coefficient_tables(d):
    """(name, columns, rows) of task1.csv ... task4.csv from the results dict (tasks that were run)."""
    out = []
    for name in ("task1", "task2", "task3", "task4"):
        rows = d[name]
        if not rows:
            continue
        columns = [k for k in rows[0] if k != "lines"] + ["lines"]
        cells = [
            [r[k] if k != "lines" else " ".join(map(str, r[k])) for k in columns] for r in rows
        ]
        out.append((name, columns, cells))
    return out


def _is_replaceable(target):
    if not target.exists():
        return True
    if not target.is_dir():
        return False
    return not any(target.iterdir()) or (target / MARKER).is_file()


def _check_replaceable(target):
    if not _is_replaceable(target):
        raise InputError(
            f"out: {target} exists and is not a bearinglab report directory; give a new or empty "
            f"directory (a previous report is replaced)"
        )


def write_report(result, out_dir, *, generated=None):
    """Write the report of an analysed session into a directory, atomically.

    Parameters
    ----------
    result : bearinglab.lab.analysis.LabResult
        The analysed session.
    out_dir : str or Path
        The report directory. It is created (with its parents); an existing directory is replaced
        only if it is empty or a previous report (it holds the marker file ``.bearinglab-report``).
    generated : str, optional
        Time stamp shown in the report (default: now, UTC).

    Returns
    -------
    ReportFiles

    Raises
    ------
    InputError
        ``out_dir`` exists and is a file or a directory that is not a previous report; or, in a
        command's run, it is or holds one of the run's input files (the session, its measurements).

    Notes
    -----
    Everything is built in a temporary directory next to the target and renamed into place at the
    end; a failure at any point removes the temporary directory and leaves the target untouched.
    """
    target = Path(out_dir)
    # built in a temporary directory and put in place whole; inside a command's run (bearinglab._io) it
    # is refused when it is, or holds, an input the run read (the session, its measurements)
    with atomic_directory(target, option="out", replaceable=_check_replaceable) as tmp:
        figure_files, table_files = _write_files(tmp, result, generated)
    return ReportFiles(
        target,
        target / "report.html",
        target / "results.json",
        [target / f for f in figure_files],
        [target / f for f in table_files],
    )


def _write_files(directory, result, generated):
    """Every file of the report into ``directory``; returns the names of the figures and tables."""
    d = presentation.to_dict(result)
    figures, figure_files, table_files = [], [], []
    for plot in presentation.plots(result):
        png, svg = render_figure(plot)
        (directory / f"{plot.name}.png").write_bytes(png)
        write_text(directory / f"{plot.name}.svg", svg)
        figures.append((plot, svg))
        figure_files += [f"{plot.name}.png", f"{plot.name}.svg"]
    tables = [presentation.rows_table(result)]
    tables += presentation.table4(result) + presentation.table5(result)
    for t in tables:
        table_files.append(_write_table(directory, t.name, t.columns, t.rows))
    for name, columns, rows in _coefficient_tables(d):
        table_files.append(_write_table(directory, name, columns, rows))
    d["files"] = {
        "html": "report.html",
        "json": "results.json",
        "figures": figure_files,
        "tables": table_files,
    }
    write_text(directory / "results.json", json_text(d))
    write_text(directory / "report.html", render_html(result, figures, generated=generated))
    write_text(
        directory / MARKER,
        "bearinglab friction-lab report; this directory is replaced on the next run\n",
    )
    return figure_files, table_files
