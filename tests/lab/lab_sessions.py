"""Session files for the friction-lab tests: the example S1 as text, written with its rows to a directory.

Imported by the tests in this folder (pytest puts the folder on sys.path; a conftest.py here would clash
with the other conftest.py files under --doctest-modules).
"""

from pathlib import Path

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "friction"
S1_TEXT = (EXAMPLES / "s1_readings.toml").read_text()
S1_ROWS = (EXAMPLES / "s1_readings.csv").read_text()


def write_session(directory, toml=S1_TEXT, rows=S1_ROWS):
    """Write ``toml`` as s.toml and ``rows`` as s1_readings.csv (the file S1 names) into ``directory``."""
    (directory / "s.toml").write_text(toml)
    (directory / "s1_readings.csv").write_text(rows)
    return directory / "s.toml"


def line_of(text, needle):
    """Number (from 1) of the first line of ``text`` that contains ``needle``."""
    return next(i for i, line in enumerate(text.splitlines(), 1) if needle in line)
