"""Issue 10 item 5: nothing in the repository points outside it (a user who clones it has nothing else).

Every text file of the repository (the working tree, without generated or environment folders) is
searched for references to the development workspace: its shared specification and seed folders and
absolute paths into it. The theory lives in docs/theory, in the project's own words.
"""

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SKIP = {".git", ".venv", "out", "build", "_build", "auto_examples", "test-artifacts", "mutants", "__pycache__",
        ".hypothesis", ".pytest_cache", ".ruff_cache"}
SUFFIXES = {".py", ".md", ".rst", ".toml", ".csv", ".txt", ".cfg", ".ini", ".yml", ".yaml", ".json", ".html",
            ".css", ".js", ""}
# written in pieces so that this file does not match itself
OUTSIDE = re.compile("|".join([r"\.\./" + "shared", "shared/" + "(?:spec|seeds)", "/" + "work/"]))


def _files():
    for path in ROOT.rglob("*"):
        rel = path.relative_to(ROOT)
        if any(part in SKIP or part.endswith(".egg-info") for part in rel.parts) or not path.is_file():
            continue
        if path.suffix in SUFFIXES:
            yield path


def test_no_file_points_outside_the_repository():
    hits = []
    for path in _files():
        try:
            text = path.read_text(encoding="utf-8")
        except (UnicodeDecodeError, OSError):
            continue  # binary files (test bytes, images) are not references
        for n, line in enumerate(text.splitlines(), 1):
            if OUTSIDE.search(line):
                hits.append(f"{path.relative_to(ROOT)}:{n}: {line.strip()[:100]}")
    assert not hits, "references outside the repository:\n" + "\n".join(hits)


def test_the_pattern_finds_what_it_must():
    assert OUTSIDE.search("see ../" + "shared" + "/spec/000.md") and OUTSIDE.search("/" + "work/" + "shared/x")
    assert not OUTSIDE.search("docs/theory/runout.md, section 2")
