"""Output files written whole or not at all, and the one JSON and the one CSV convention of the package.

STYLE.md: no half-written result may be left behind. Every writer of the library (CSV tables, figures,
measurement templates, reports) goes through :func:`atomic_output`: the data go to a temporary file in
the target's directory, which replaces the target in one ``os.replace`` only once it is complete. A
failure leaves the old file, if any, as it was.

Functions
---------
atomic_output   temporary path that becomes the target on success (any writer)
write_text      a text file, whole or not at all
json_value      Python/numpy values -> JSON-ready values (NaN and inf -> None, numpy -> Python)
json_text       one JSON document (two-space indent, UTF-8 characters kept), ending in a newline
csv_cell        one value -> one CSV cell (floats as repr, NaN/inf/None empty, booleans true/false)
csv_text        CSV text: ``# comment`` lines, the header row, the rows (LF line endings)
write_columns   equal-length columns -> .csv or .parquet, whole or not at all

The public spelling of the JSON, CSV and column writers is :mod:`bearinglab.tables`.
"""

from __future__ import annotations

import contextlib
import contextvars
import csv
import io
import json
import math
import os
import signal
import tempfile
import threading
from pathlib import Path

import numpy as np

__all__ = ["atomic_output", "csv_cell", "csv_text", "json_text", "json_value", "write_columns", "write_text"]


# Temporary files of the atomic writes under way, removed by the SIGTERM/SIGHUP handler: a killed run
# (a batch system's time limit, a closed terminal) leaves no ".name.xxxx.tmp" behind.
_PENDING: set[str] = set()
_HANDLED: dict[int, object] = {}  # signal -> the handler it had before ours


def _remove_pending(signum, frame):
    """SIGTERM/SIGHUP: remove the temporary files, then die of the signal as before."""
    for tmp in list(_PENDING):
        with contextlib.suppress(OSError):
            os.unlink(tmp)
    _PENDING.clear()
    previous = _HANDLED.get(signum, signal.SIG_DFL)
    if callable(previous):
        previous(signum, frame)
        return
    signal.signal(signum, signal.SIG_DFL)
    os.kill(os.getpid(), signum)


def _handle_signals():
    """Install :func:`_remove_pending` for SIGTERM and SIGHUP, once, where the signal still has its default
    action (a program that set its own handler, a web server, keeps it). Only the main thread can."""
    if threading.current_thread() is not threading.main_thread():
        return
    for name in ("SIGTERM", "SIGHUP"):
        signum = getattr(signal, name, None)  # no SIGHUP on Windows
        if signum is None or signum in _HANDLED:
            continue
        try:
            if signal.getsignal(signum) is signal.SIG_DFL:
                _HANDLED[signum] = signal.signal(signum, _remove_pending)
        except (ValueError, OSError):  # not the main interpreter
            pass


@contextlib.contextmanager
def atomic_output(path, *, suffix=".tmp"):
    """Yield a temporary path next to ``path``; on a normal exit it becomes ``path``, on an error it is removed.

    ``suffix`` lets writers that choose their format from the file name (matplotlib) see the right one.
    SIGTERM and SIGHUP remove the temporary file too. An ``OSError`` without a file name (a full disk,
    ENOSPC, raised by ``write``) is raised again naming ``path``. A ``path`` that is a device, a pipe or
    a socket is refused (InputError): the rename would replace it.
    """
    path = Path(path)
    if path.exists() and not path.is_file() and not path.is_dir():
        # a device, a pipe or a socket: the rename would replace the node itself (/dev/null, /dev/zero
        # when run as root), not write into it
        from .errors import InputError

        raise InputError(f"{path}: not a regular file (a device, a pipe or a socket); an output is written "
                         f"to a file")
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=suffix, dir=path.parent)
    os.close(fd)
    _handle_signals()
    _PENDING.add(tmp)
    try:
        yield Path(tmp)
        os.chmod(tmp, 0o644)  # mkstemp creates 0600; an output is an ordinary file
        os.replace(tmp, path)
    except BaseException as exc:
        if os.path.exists(tmp):
            os.unlink(tmp)
        if isinstance(exc, OSError) and exc.filename in (None, tmp) and exc.errno is not None:
            raise OSError(exc.errno, exc.strerror or str(exc), str(path)) from exc  # name the user's file
        raise
    finally:
        _PENDING.discard(tmp)


def write_text(path, text):
    """Write ``text`` (UTF-8, line endings as given) to ``path`` whole or not at all; returns the path."""
    with atomic_output(path) as tmp:
        tmp.write_text(text, encoding="utf-8", newline="")
    return Path(path)


#: While set to a list, :func:`json_value` appends to it the path (``chain.least.operating_clearance``), the
#: value and the dict holding it of every non-finite number it writes as None: the calculations check that each such null is one their
#: document promises (an unbounded life, an unloaded contact), not an overflow (issue 29).
NULLED = contextvars.ContextVar("bearinglab_json_nulled", default=None)


def json_value(obj):
    """``obj`` with numpy arrays and scalars as Python lists and numbers, NaN and inf as ``None``.

    Dictionaries keep their order (keys become strings); tuples become lists.
    """
    nulled = NULLED.get()
    return _json_plain(obj) if nulled is None else _json_recorded(obj, "", nulled)


def _json_plain(obj):
    if isinstance(obj, dict):
        return {str(k): _json_plain(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_json_plain(v) for v in obj]
    if isinstance(obj, np.ndarray):
        return _json_plain(obj.tolist())
    if isinstance(obj, (np.bool_, bool)):
        return bool(obj)
    if isinstance(obj, np.integer):
        return int(obj)
    if isinstance(obj, (np.floating, float)):
        v = float(obj)
        return v if math.isfinite(v) else None
    return obj


def _json_recorded(obj, path, nulled, parent=None):
    """:func:`_json_plain`, noting ``(path, value, the dict that holds it)`` of each non-finite number in
    ``nulled``."""
    if isinstance(obj, dict):
        return {str(k): _json_recorded(v, f"{path}.{k}" if path else str(k), nulled, obj) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_json_recorded(v, f"{path}[{i}]", nulled, parent) for i, v in enumerate(obj)]
    if isinstance(obj, np.ndarray):
        return _json_recorded(obj.tolist(), path, nulled, parent)
    if isinstance(obj, (np.floating, float)) and not isinstance(obj, bool) and not math.isfinite(float(obj)):
        nulled.append((path, float(obj), parent))
        return None
    return _json_plain(obj)


def json_text(obj):
    """One JSON document of ``obj`` (see :func:`json_value`), indented by two spaces, with a final newline."""
    return json.dumps(json_value(obj), indent=2, ensure_ascii=False) + "\n"


def csv_cell(value):
    """One CSV cell: floats in full precision (``repr``), NaN, inf and None empty, booleans ``true``/``false``."""
    if value is None:
        return ""
    if isinstance(value, (np.bool_, bool)):
        return "true" if value else "false"
    if isinstance(value, (float, np.floating)):
        return repr(float(value)) if math.isfinite(value) else ""
    if isinstance(value, np.integer):
        return int(value)
    if isinstance(value, np.str_):
        return str(value)
    return value


def csv_text(header, rows, comments=()):
    """CSV text with ``# comment`` lines first, then the header row and the rows (LF line endings).

    Every cell goes through :func:`csv_cell`; cells already formatted as strings pass unchanged.
    """
    buf = io.StringIO()
    for line in comments:
        buf.write(f"# {line}\n")
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(header)
    w.writerows([csv_cell(v) for v in row] for row in rows)
    return buf.getvalue()


def write_columns(path, columns, *, comments=()):
    """Write equal-length columns (name -> 1-D array) to a .csv or .parquet file, whole or not at all.

    CSV cells follow :func:`csv_cell`; ``comments`` become ``#`` lines before the header (CSV only).
    Parquet keeps the column dtypes (object columns as strings). Returns the path.
    """
    path = Path(path)
    names = list(columns)
    if path.suffix == ".parquet":
        import pyarrow as pa
        import pyarrow.parquet as pq

        arrays = {k: np.asarray(columns[k]) for k in names}
        table = pa.table({k: (v.astype(str) if v.dtype == object else v) for k, v in arrays.items()})
        with atomic_output(path, suffix=".parquet") as tmp:
            pq.write_table(table, tmp)
        return path
    rows = zip(*(np.asarray(columns[k], dtype=object) for k in names))
    return write_text(path, csv_text(names, rows, comments))
