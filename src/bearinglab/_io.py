"""Output files written whole or not at all (STYLE.md: no half-written result may be left behind).

Every writer of the library (CSV tables, figures, measurement templates) goes through
:func:`atomic_output`: the data go to a temporary file in the target's directory, which replaces the
target in one ``os.replace`` only once it is complete. A failure leaves the old file, if any, as it was.

atomic_output     a temporary path that becomes the target on success
write_text        text to a file, whole or not at all
csv_text          the library's one CSV dialect: ``#`` comments, header, rows, LF line endings
json_text         the library's one JSON dialect: indent 2, UTF-8 text, NaN/inf -> null, numpy -> Python
"""

from __future__ import annotations

import contextlib
import csv
import io
import json
import math
import os
import tempfile
from pathlib import Path

import numpy as np

__all__ = ["atomic_output", "csv_text", "json_text", "write_text"]


@contextlib.contextmanager
def atomic_output(path, *, suffix=".tmp"):
    """Yield a temporary path next to ``path``; on a normal exit it becomes ``path``, on an error it is removed.

    ``suffix`` lets writers that choose their format from the file name (matplotlib) see the right one.
    """
    path = Path(path)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=suffix, dir=path.parent)
    os.close(fd)
    try:
        yield Path(tmp)
        os.chmod(tmp, 0o644)  # mkstemp creates 0600; an output is an ordinary file
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def write_text(path, text):
    """Write ``text`` (UTF-8, line endings as given) to ``path`` whole or not at all; returns the path."""
    with atomic_output(path) as tmp:
        tmp.write_text(text, encoding="utf-8", newline="")
    return Path(path)


def csv_text(header, rows, comments=()):
    """CSV text with ``# comment`` lines first, then the header row and the rows (LF line endings)."""
    buf = io.StringIO()
    for line in comments:
        buf.write(f"# {line}\n")
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(header)
    w.writerows(rows)
    return buf.getvalue()


def json_text(obj):
    """JSON text of ``obj`` (indent 2, non-ASCII kept, one final newline).

    NaN and infinities become null (JSON has no such numbers); numpy scalars and arrays become Python
    numbers and lists, tuples become lists and dict keys strings.
    """
    return json.dumps(_jsonable(obj), indent=2, ensure_ascii=False, allow_nan=False) + "\n"


def _jsonable(obj):
    if isinstance(obj, dict):
        return {str(k): _jsonable(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_jsonable(v) for v in obj]
    if isinstance(obj, np.ndarray):
        return _jsonable(obj.tolist())
    if isinstance(obj, (bool, np.bool_)):
        return bool(obj)
    if isinstance(obj, np.integer):
        return int(obj)
    if isinstance(obj, (float, np.floating)):
        v = float(obj)
        return v if math.isfinite(v) else None
    return obj
