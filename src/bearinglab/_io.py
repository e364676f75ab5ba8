"""Output files written whole or not at all, inputs never replaced, and the one JSON and the one CSV
convention of the package.

STYLE.md: no half-written result may be left behind. Every writer of the library (CSV tables, figures,
measurement templates, reports) goes through :func:`atomic_output` (a file) or :func:`atomic_directory`
(a directory of files, the friction-lab report): the data go to a temporary file or directory next to
the target, which replaces the target in one rename only once it is complete. A failure leaves the old
file, if any, as it was.

Input files are never modified (issue 29). A command runs inside :func:`run_files`: every input file
the run reads (``bearinglab._bounds.read_input_bytes`` notes it: a session, its measurements, an error
file, its profiles, a geometry, a catalog) is one of the run's inputs, by its resolved name and by its
device and inode (so a symbolic link, a hard link, a relative path or ``a/../a`` name the same file).
Every output of the run, a file written inside an output directory included, is checked against them
when it is opened and, against every input the run read, when the run ends: only then are the outputs
put in place, all together. An output that would replace an input (or a report directory that would
delete one) is refused with one line naming the option and the file, and nothing is written.

Functions
---------
atomic_output   temporary path that becomes the target on success (any writer)
atomic_directory  temporary directory that becomes the target directory on success (a report)
write_text      a text file, whole or not at all
run_files       the scope of one run (a command): its inputs, and its outputs put in place at its end
note_input      a file the run reads (called by ``_bounds.read_input_bytes``)
name_output     the option that names an output file or directory, for the messages
check_output    refuse an output file that is one of the run's inputs
check_output_directory  refuse an output directory that is, or holds, one of the run's inputs
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
import shutil
import signal
import tempfile
import threading
from pathlib import Path

from .errors import InputError

# numpy is imported where it is used: the command line opens a run (run_files) before it knows whether
# the command needs numpy, and `bearinglab --help` must not import it (tests/cli/test_cli_startup.py)

__all__ = ["RunFiles", "atomic_directory", "atomic_output", "check_output", "check_output_directory", "csv_cell",
           "csv_text", "json_text", "json_value", "name_output", "note_input", "run_files", "write_columns",
           "write_text"]


# Temporary files (and report directories) of the atomic writes under way, removed by the SIGTERM/SIGHUP
# handler: a killed run (a batch system's time limit, a closed terminal) leaves no ".name.xxxx.tmp" behind.
_PENDING: set[str] = set()
_PENDING_DIRS: set[str] = set()
_HANDLED: dict[int, object] = {}  # signal -> the handler it had before ours


def _remove_pending(signum, frame):
    """SIGTERM/SIGHUP: remove the temporary files, then die of the signal as before."""
    for tmp in list(_PENDING):
        with contextlib.suppress(OSError):
            os.unlink(tmp)
    _PENDING.clear()
    for tmp in list(_PENDING_DIRS):
        shutil.rmtree(tmp, ignore_errors=True)
    _PENDING_DIRS.clear()
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


# ----------------------------------------------------------------------------- the files of one run
def _input_error(message):
    return InputError(message)


def _absolute(path):
    """``path`` made absolute without following links (``a/../b`` -> ``b``), and its resolved form."""
    lexical = Path(os.path.abspath(path))
    try:
        resolved = Path(path).resolve()
    except (OSError, RuntimeError):  # a symbolic-link loop: its name only
        resolved = lexical
    return lexical, resolved


class RunFiles:
    """The files of one run (one command): the inputs it read, the options naming its outputs, and the
    outputs waiting to be put in place at its end (:func:`run_files`).

    Attributes
    ----------
    inputs : dict
        Resolved path of each input file read (str) -> the path as the run named it.
    """

    def __init__(self):
        self._lock = threading.Lock()
        self.inputs = {}
        self._lexical = {}  # the absolute path as named (links not followed) -> the path as named
        self._ids = {}  # (st_dev, st_ino) -> the path as named: hard links, another spelling
        self._options = []  # (lexical, resolved, option): the option that gave an output file or directory
        self._staged = []  # (tmp, target, option, swap): put in place at the end of the run, in order
        self._private = set()  # the temporary directories of atomic_directory: written at once, put in place whole

    # ------------------------------------------------------------------ inputs
    def note_input(self, path, info=None):
        """Note ``path`` as an input file of the run (``info``: its ``os.stat`` result, if at hand)."""
        lexical, resolved = _absolute(path)
        if info is None:
            try:
                info = os.stat(path)
            except OSError:
                info = None
        with self._lock:
            self.inputs.setdefault(str(resolved), Path(path))
            self._lexical.setdefault(str(lexical), Path(path))
            if info is not None:
                self._ids.setdefault((info.st_dev, info.st_ino), Path(path))

    def input_named(self, path):
        """The input file ``path`` names (the same file under any name), or None."""
        lexical, resolved = _absolute(path)
        with self._lock:
            found = self.inputs.get(str(resolved)) or self._lexical.get(str(lexical))
            if found is None and self._ids:
                try:
                    info = os.stat(path)
                except OSError:
                    info = None
                if info is not None:
                    found = self._ids.get((info.st_dev, info.st_ino))
        return found

    def input_within(self, directory):
        """An input file inside ``directory`` (at any depth, by its name or by where its links lead), or
        None: replacing the directory would delete it."""
        lexical, resolved = _absolute(directory)
        with self._lock:
            named = [*self.inputs.items(), *self._lexical.items()]
        for where, given in named:
            where = Path(where)
            if where.is_relative_to(resolved) or where.is_relative_to(lexical):
                return given
        return None

    # ------------------------------------------------------------------ outputs
    def name_output(self, path, option):
        """``option`` gave the output file or directory ``path``: the messages about it name the option."""
        lexical, resolved = _absolute(path)
        with self._lock:
            self._options.append((lexical, resolved, option))

    def option_of(self, path):
        """The option that gave ``path`` (or the directory it is in; the innermost wins), or ``output``."""
        lexical, resolved = _absolute(path)
        best, depth = "output", -1
        with self._lock:
            options = list(self._options)
        for out_lexical, out_resolved, option in options:
            for here, there in ((lexical, out_lexical), (resolved, out_resolved)):
                if here.is_relative_to(there) and len(there.parts) > depth:
                    best, depth = option, len(there.parts)
        return best

    def check_output(self, path, option=None):
        """Refuse (InputError) an output file that is one of the run's inputs."""
        source = self.input_named(path)
        if source is not None:
            raise _input_error(f"{option or self.option_of(path)}: {str(path)!r} is an input file of this "
                               f"command ({source}); write the output to another file")

    def check_directory(self, path, option=None):
        """Refuse (InputError) an output directory that is an input or holds one: it is replaced whole."""
        source = self.input_named(path) or self.input_within(path)
        if source is not None:
            raise _input_error(f"{option or self.option_of(path)}: {str(path)!r} holds an input file of this "
                               f"command ({source}), which replacing the directory would delete; write the "
                               f"output to another directory")

    def _private_dir(self, directory):
        _, resolved = _absolute(directory)
        return str(resolved) in self._private

    def finish(self):
        """Put the staged outputs in place: each is checked against every input first (InputError, and
        nothing is written), then renamed, in the order they were written."""
        staged, self._staged = self._staged, []
        try:
            for _tmp, target, option, swap in staged:
                if swap is None:
                    self.check_output(target, option)
                else:
                    self.check_directory(target, option)
        except BaseException:
            _discard(staged)
            raise
        for k, (tmp, target, _option, swap) in enumerate(staged):
            try:
                if swap is None:
                    _put_file(tmp, target)
                else:
                    swap(tmp, target)
                    self._private.discard(str(_absolute(tmp)[1]))
                    _PENDING_DIRS.discard(str(tmp))
            except BaseException:
                _discard(staged[k:])
                raise

    def discard(self):
        """Remove the staged outputs' temporary files: the run failed, nothing is written."""
        staged, self._staged = self._staged, []
        _discard(staged)


def _discard(staged):
    for tmp, _target, _option, swap in staged:
        if swap is None:
            with contextlib.suppress(OSError):
                os.unlink(tmp)
            _PENDING.discard(str(tmp))
        else:
            shutil.rmtree(tmp, ignore_errors=True)
            _PENDING_DIRS.discard(str(tmp))


def _put_file(tmp, target):
    """Rename the complete temporary file onto its target; an OSError names the target."""
    try:
        os.replace(tmp, target)
    except BaseException as exc:
        if os.path.exists(tmp):
            os.unlink(tmp)
        if isinstance(exc, OSError) and exc.filename in (None, str(tmp)) and exc.errno is not None:
            raise OSError(exc.errno, exc.strerror or str(exc), str(target)) from exc  # name the user's file
        raise
    finally:
        _PENDING.discard(str(tmp))


_RUN: contextvars.ContextVar[RunFiles | None] = contextvars.ContextVar("bearinglab_run_files", default=None)


@contextlib.contextmanager
def run_files():
    """The scope of one run: its input files are noted, its outputs checked against them and put in place
    together at its end (on a normal exit; on an error they are removed and nothing is written).

    The command line runs every command inside one (``bearinglab.cli.main``). Outside a run, a write is
    put in place at once, as before.

    Yields
    ------
    RunFiles
    """
    run = RunFiles()
    token = _RUN.set(run)
    try:
        yield run
    except BaseException:
        run.discard()
        raise
    finally:
        _RUN.reset(token)
    run.finish()


def note_input(path, info=None):
    """Note ``path`` as an input file of the run under way (none: nothing to do).

    Parameters
    ----------
    path : str or Path
        The file read.
    info : os.stat_result, optional
        Its status, if the reader has it (``os.fstat`` of the open file).
    """
    run = _RUN.get()
    if run is not None:
        run.note_input(path, info)


def name_output(path, option):
    """Name the option that gave the output file or directory ``path`` (its messages name the option).

    Parameters
    ----------
    path : str or Path
        An output file, or the directory the outputs are written into.
    option : str
        The option, as messages name it (``plot``, ``out``).
    """
    run = _RUN.get()
    if run is not None:
        run.name_output(path, option)


def check_output(path, option=None):
    """Refuse an output file that is one of the inputs the run has read so far.

    Parameters
    ----------
    path : str or Path
        The output file.
    option : str, optional
        The option that gave it (default: the one :func:`name_output` named, else ``output``).

    Raises
    ------
    InputError
        ``path`` is an input file of the run, under any name.
    """
    run = _RUN.get()
    if run is not None:
        run.check_output(path, option)


def check_output_directory(path, option=None):
    """Refuse an output directory that is replaced whole (a report) while it is, or holds, an input.

    Parameters
    ----------
    path : str or Path
        The output directory.
    option : str, optional
        The option that gave it.

    Raises
    ------
    InputError
        ``path`` holds an input file of the run.
    """
    run = _RUN.get()
    if run is not None:
        run.check_directory(path, option)


@contextlib.contextmanager
def atomic_output(path, *, suffix=".tmp"):
    """Yield a temporary path next to ``path``; on a normal exit it becomes ``path``, on an error it is removed.

    ``suffix`` lets writers that choose their format from the file name (matplotlib) see the right one.
    SIGTERM and SIGHUP remove the temporary file too. An ``OSError`` without a file name (a full disk,
    ENOSPC, raised by ``write``) is raised again naming ``path``. A ``path`` that is a device, a pipe or
    a socket is refused (InputError): the rename would replace it.

    Inside a run (:func:`run_files`), ``path`` is refused (InputError) when it is one of the run's input
    files, and the complete file is put in place when the run ends, after a last check against every
    input the run read.
    """
    path = Path(path)
    if path.exists() and not path.is_file() and not path.is_dir():
        # a device, a pipe or a socket: the rename would replace the node itself (/dev/null, /dev/zero
        # when run as root), not write into it
        raise _input_error(f"{path}: not a regular file (a device, a pipe or a socket); an output is written "
                           f"to a file")
    run = _RUN.get()
    private = run is not None and run._private_dir(path.parent)  # inside a report being built: no input there
    if run is not None and not private:
        run.check_output(path)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=suffix, dir=path.parent)
    os.close(fd)
    _handle_signals()
    _PENDING.add(tmp)
    staged = False
    try:
        yield Path(tmp)
        os.chmod(tmp, 0o644)  # mkstemp creates 0600; an output is an ordinary file
        if run is not None and not private:
            run._staged.append((tmp, path, None, None))  # put in place when the run ends
            staged = True
        else:
            _put_file(tmp, path)
    except BaseException as exc:
        if os.path.exists(tmp):
            os.unlink(tmp)
        if isinstance(exc, OSError) and exc.filename in (None, tmp) and exc.errno is not None:
            raise OSError(exc.errno, exc.strerror or str(exc), str(path)) from exc  # name the user's file
        raise
    finally:
        if not staged:
            _PENDING.discard(tmp)


def _swap_directory(tmp, target):
    """Put the complete directory ``tmp`` in place of ``target`` (absent, empty, or replaced whole: the
    old one is renamed aside, then removed; a failure puts it back)."""
    if not target.exists():
        os.rename(tmp, target)
        return
    if not any(target.iterdir()):
        target.rmdir()
        os.rename(tmp, target)
        return
    old = Path(tempfile.mkdtemp(prefix=f".{target.name}.old-", dir=tmp.parent))
    old.rmdir()
    os.rename(target, old)
    try:
        os.rename(tmp, target)
    except BaseException:
        os.rename(old, target)  # put the previous directory back
        raise
    shutil.rmtree(old, ignore_errors=True)


@contextlib.contextmanager
def atomic_directory(path, *, option=None, replaceable=None):
    """Yield a new empty directory next to ``path``; on a normal exit it replaces ``path`` whole, on an
    error it is removed (with what was written into it).

    Parameters
    ----------
    path : str or Path
        The output directory. Its parent is created.
    option : str, optional
        The option that gave it, named by the messages.
    replaceable : callable, optional
        ``replaceable(path)`` raises when ``path`` may not be replaced (a directory of other files); it is
        called before the directory is built and again just before it is put in place.

    Notes
    -----
    Inside a run (:func:`run_files`), ``path`` is refused (InputError) when it is, or holds, one of the
    run's input files (replacing it would delete them), and it is put in place when the run ends. The
    files written into the temporary directory are written at once: the directory is the unit.
    """
    target = Path(path)
    run = _RUN.get()
    if run is not None:
        if option is not None:
            run.name_output(target, option)
        run.check_directory(target, option)
    if replaceable is not None:
        replaceable(target)
    parent = target.parent if str(target.parent) else Path(".")
    parent.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(prefix=f".{target.name}.tmp-", dir=parent))
    _handle_signals()
    _PENDING_DIRS.add(str(tmp))
    if run is not None:
        run._private.add(str(_absolute(tmp)[1]))

    def swap(tmp, target):
        if replaceable is not None:
            replaceable(target)  # checked again: something may have appeared meanwhile
        _swap_directory(tmp, target)

    staged = False
    try:
        umask = os.umask(0o022)
        os.umask(umask)
        os.chmod(tmp, 0o777 & ~umask)  # mkdtemp makes it private; an output directory is an ordinary one
        yield tmp
        if run is not None:
            run._staged.append((tmp, target, option, swap))  # put in place when the run ends
            staged = True
        else:
            swap(tmp, target)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        if run is not None:
            run._private.discard(str(_absolute(tmp)[1]))
        raise
    finally:
        if not staged:
            _PENDING_DIRS.discard(str(tmp))


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
    import numpy as np  # here, not at import: the command line's --help loads no numpy

    nulled = NULLED.get()
    return _json_plain(obj, np) if nulled is None else _json_recorded(obj, "", nulled, np)


def _json_plain(obj, np):
    if isinstance(obj, dict):
        return {str(k): _json_plain(v, np) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_json_plain(v, np) for v in obj]
    if isinstance(obj, np.ndarray):
        return _json_plain(obj.tolist(), np)
    if isinstance(obj, (np.bool_, bool)):
        return bool(obj)
    if isinstance(obj, np.integer):
        return int(obj)
    if isinstance(obj, (np.floating, float)):
        v = float(obj)
        return v if math.isfinite(v) else None
    return obj


def _json_recorded(obj, path, nulled, np, parent=None):
    """:func:`_json_plain`, noting ``(path, value, the dict that holds it)`` of each non-finite number in
    ``nulled``."""
    if isinstance(obj, dict):
        return {str(k): _json_recorded(v, f"{path}.{k}" if path else str(k), nulled, np, obj)
                for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_json_recorded(v, f"{path}[{i}]", nulled, np, parent) for i, v in enumerate(obj)]
    if isinstance(obj, np.ndarray):
        return _json_recorded(obj.tolist(), path, nulled, np, parent)
    if isinstance(obj, (np.floating, float)) and not isinstance(obj, bool) and not math.isfinite(float(obj)):
        nulled.append((path, float(obj), parent))
        return None
    return _json_plain(obj, np)


def json_text(obj):
    """One JSON document of ``obj`` (see :func:`json_value`), indented by two spaces, with a final newline."""
    return json.dumps(json_value(obj), indent=2, ensure_ascii=False) + "\n"


def csv_cell(value):
    """One CSV cell: floats in full precision (``repr``), NaN, inf and None empty, booleans ``true``/``false``."""
    import numpy as np

    return _csv_cell(value, np)


def _csv_cell(value, np):
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
    import numpy as np

    buf = io.StringIO()
    for line in comments:
        buf.write(f"# {line}\n")
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(header)
    w.writerows([_csv_cell(v, np) for v in row] for row in rows)
    return buf.getvalue()


def write_columns(path, columns, *, comments=()):
    """Write equal-length columns (name -> 1-D array) to a .csv or .parquet file, whole or not at all.

    CSV cells follow :func:`csv_cell`; ``comments`` become ``#`` lines before the header (CSV only).
    Parquet keeps the column dtypes (object columns as strings). Returns the path.
    """
    import numpy as np

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
