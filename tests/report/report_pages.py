"""Helpers of the report tests: the example sessions analysed, a report written and its page parsed.

Imported by the tests in this folder (pytest puts the folder on sys.path; a conftest.py here would clash
with the other conftest.py files under --doctest-modules).
"""

import functools
from html.parser import HTMLParser
from pathlib import Path

from bearinglab import report
from bearinglab.lab import analysis, measurement

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "friction"


class Page(HTMLParser):
    """Collects tables (rows of cell texts), images, links and external references."""

    def __init__(self):
        super().__init__()
        self.tables, self.images, self.refs, self.captions, self.tags = [], [], [], [], []
        self.headers = []
        self._row = self._cell = self._caption = None
        self._head = False

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        self.tags.append(tag)
        for key in ("src", "href", "action", "data"):
            if key in a:
                self.refs.append(a[key])
        if tag == "table":
            self.tables.append([])
        elif tag == "thead":
            self._head = True
        elif tag == "tr":
            self._row = []
        elif tag in ("td", "th"):
            self._cell = ""
        elif tag == "caption":
            self._caption = ""
        elif tag == "img":
            self.images.append(a)

    def handle_endtag(self, tag):
        if tag in ("td", "th") and self._cell is not None:
            self._row.append(self._cell.strip())
            self._cell = None
        elif tag == "tr" and self._row is not None:
            if not self._head:  # body rows only; header rows are checked through their texts
                self.tables[-1].append(self._row)
            else:
                self.headers.append(self._row)
            self._row = None
        elif tag == "thead":
            self._head = False
        elif tag == "caption":
            self.captions.append(self._caption.strip())
            self._caption = None

    def handle_data(self, data):
        if self._cell is not None:
            self._cell += data
        if self._caption is not None:
            self._caption += data


@functools.cache
def analysed(name):
    """The session ``examples/friction/NAME.toml`` analysed (S1: s1_readings, S0: s0_direct)."""
    return analysis.analyse(measurement.read_session(EXAMPLES / f"{name}.toml"))


def write_s1(directory):
    """The report of S1 written into ``directory``/s1 (ReportFiles) and its HTML page parsed (Page)."""
    files = report.write_report(
        analysed("s1_readings"), directory / "s1", generated="2024-01-01 00:00 UTC"
    )
    page = Page()
    page.feed(files.html.read_text(encoding="utf-8"))
    return files, page
