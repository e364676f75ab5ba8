"""Reports of the friction-rig lab: a self-contained HTML report, PNG and SVG plots, CSV tables, JSON.

Report
------
write_report      analysed session -> a report directory, written atomically (whole or not at all)
render_html       the HTML text of the report (figures embedded as SVG data URIs)
render_figure     one plot of :func:`bearinglab.lab.presentation.plots` -> (PNG bytes, SVG text)
ReportFiles       what :func:`write_report` wrote
MARKER            the marker file of a report directory

Submodules
----------
files             the report directory: every file, written in a temporary directory and swapped in
html              the HTML page: sections, tables and embedded figures

The HTML report opens offline (no external resource: styles inline, images embedded), prints well
(print style sheet, no page breaks inside tables and figures) and holds the test conditions and
bearing data, Tables 4 and 5, the fitted coefficients with their standard errors and handbook
comparisons, the plots (points and fitted lines from abscissa 0, spec 001 section 7.4) and the
generated conclusions (section 7.5). Next to it: every plot as PNG and SVG, every table as CSV and
every number in ``results.json``.

The numbers and texts come from :mod:`bearinglab.lab.presentation`, the figures from
:mod:`bearinglab.plots.friction`, which imports matplotlib on first use, so ``import bearinglab``
stays light and reports work on headless machines.
"""

from .files import MARKER, ReportFiles, render_figure, write_report
from .html import render_html

__all__ = ["MARKER", "ReportFiles", "render_figure", "render_html", "write_report"]
