"""Size limits of one run, in one place, checked before anything is allocated (issue 20).

A count typed on a command line or read from a file (a number of harmonics, of positions, of cases) sets
the size of the arrays a run allocates. A typo or a hostile input (``--harmonics 1000000000``, a range
``1N:1e6N:1N`` times ``0rpm:9999rpm:1rpm``, ``/dev/zero`` as an input file) would ask for gigabytes before
any check of the physics. Every such size is checked here first, against a limit that no real study
meets; the command line turns the InputError into one line and exit 2. A study bigger than
:data:`MAX_CASES` runs through ``bearinglab sweep`` on dask, in chunks, up to :data:`MAX_SWEEP_CASES`.
The same constants bound a request of the web calculator.

Constants
---------
MAX_CASES           cases of one command (a product of lists and ranges included)
MAX_SWEEP_CASES     cases of one sweep of a batch model (evaluated in chunks)
MAX_DOCUMENT_SWEEP_CASES  cases of one sweep of any calculation, case by case (a document per case)
MAX_RANGE_VALUES    values of one list or range, whatever the command
MAX_ROWS            rows of the iteration table of ``axial-angle --rows``
MAX_HARMONICS       harmonics of the spectral mask (``frequencies --harmonics``)
MAX_SIDEBANDS       sideband orders of the spectral mask (``frequencies --sidebands``)
MAX_REVOLUTIONS     revolutions of a runout sequence (``--revolutions``)
MAX_STEPS_PER_REV   positions per revolution (``--steps-per-rev``)
MAX_POSITIONS       positions of one runout sequence (revolutions x steps per revolution)
MAX_SAMPLE_POSITIONS  positions per sample of a runout Monte Carlo study
MAX_ORDER           Fourier order of a waviness (``--max-order``, an error file's series)
MAX_BALLS           balls of one bearing (an error or geometry file, ``--balls``)
MAX_SAMPLES         random bearings of one Monte Carlo study (``--samples``)
MAX_INPUT_BYTES     size of one input file (TOML, CSV)
MAX_WORKERS         workers of a local dask cluster (processes started on this machine)
MAX_DUTY_CYCLE_STEPS  steps of one duty cycle (``life --duty-cycle``, the web's ``duty_cycle``)
MAX_DEPTH           nesting of a JSON or TOML document (a posted error set or duty cycle, a request body)

Functions
---------
check_count         a count option: an integer within [minimum, limit]
check_cases         the number of cases of a command (or a sweep), before the grid is built
range_count         the number of values of a range start:stop:step, computed without building it
read_input_bytes    the bytes of an input file: a regular file of at most MAX_INPUT_BYTES (noted as an input
                    of the run, which no output of the run may replace: ``bearinglab._io.run_files``)
check_steps         the steps of a duty cycle, counted before any step is read
parse_json          a JSON text: a repeated key, or nesting deeper than MAX_DEPTH, is an InputError
parse_document      a JSON (``{...}``) or TOML document, as parse_json
RepeatedKey         the InputError of a JSON object that gives one key twice (its ``key``)
"""

from __future__ import annotations

import math
import os
import stat
from pathlib import Path

from . import _io
from .errors import InputError

__all__ = [
    "MAX_BALLS",
    "MAX_CASES",
    "MAX_DEPTH",
    "MAX_DOCUMENT_SWEEP_CASES",
    "MAX_DUTY_CYCLE_STEPS",
    "MAX_HARMONICS",
    "MAX_INPUT_BYTES",
    "MAX_ORDER",
    "MAX_POSITIONS",
    "MAX_RANGE_VALUES",
    "MAX_REVOLUTIONS",
    "MAX_ROWS",
    "MAX_SAMPLES",
    "MAX_SAMPLE_POSITIONS",
    "MAX_SIDEBANDS",
    "MAX_STEPS_PER_REV",
    "MAX_SWEEP_CASES",
    "MAX_WORKERS",
    "RepeatedKey",
    "check_cases",
    "check_count",
    "check_steps",
    "parse_document",
    "parse_json",
    "range_count",
    "read_input_bytes",
]

# Why these values: a high-speed case holds about 8 kB while it is solved (measured on B218, 9000 cases:
# 75 MB), so 10^5 cases stay under 1 GB on a laptop; the largest published maps are a few thousand cases.
MAX_CASES = 100_000
MAX_SWEEP_CASES = 10_000_000  # a sweep keeps its inputs and outputs as columns: ~1 GB at 10^7 cases
MAX_RANGE_VALUES = MAX_SWEEP_CASES
# a sweep of any calculation computes one document per case, 1 to 50 ms each (life 16 ms, high-speed 25 ms,
# a bearing set 46 ms on this 2-core machine), and keeps a row of about 50 to 100 columns (~1 kB): 10^6
# cases are 5 to 14 hours of one core and ~1 GB of columns
MAX_DOCUMENT_SWEEP_CASES = 1_000_000
MAX_ROWS = 1000  # the Newton iteration of the test stand converges in under 10 rows
MAX_HARMONICS = 1000  # vibration analysis looks at the first 10 to 20 harmonics
MAX_SIDEBANDS = 100
MAX_REVOLUTIONS = 10_000
MAX_STEPS_PER_REV = 100_000  # 0.0036 deg per step
# a runout sequence holds ~2.3 kB per position (example1, 36 000 positions: 82 MB), so 10^6 positions
# ~ 2.3 GB; a real sequence is 1 to 100 revolutions of 360 to 3600 steps
MAX_POSITIONS = 1_000_000
# a Monte Carlo block of 256 samples holds ~0.7 kB per sample and position (B218, 100 samples x 10^4
# positions: 0.7 GB): 10^4 positions per sample stay under 2 GB; studies use 2-3 revolutions of 180-360
MAX_SAMPLE_POSITIONS = 10_000
MAX_ORDER = 10_000  # ISO 3290 and ring waviness are specified up to order ~ 500 (roundness ~ 150 UPR)
MAX_BALLS = 1000  # the largest slewing ball bearings have a few hundred balls per row
MAX_SAMPLES = 10_000_000
MAX_INPUT_BYTES = 16 * 2**20  # the largest bundled input (the catalog) is under 100 kB
MAX_WORKERS = 256  # one process per core: the largest single machines have a few hundred cores
# A duty cycle is a load spectrum of a few to a few hundred steps; a measured load-speed histogram binned
# for a life calculation has up to a few thousand (e.g. 50 load x 50 speed bins). Each step costs ~0.5 ms
# and ~8 kB (6208, measured: 2000 steps 1.6 s and 0.1 GB, 20 000 steps 9.8 s and 0.26 GB), so the limit
# keeps a duty cycle within seconds.
MAX_DUTY_CYCLE_STEPS = 10_000
# An error file is four levels deep ([rings.inner.roundness] and its arrays), a duty cycle two; a deeper
# document is no input of bearinglab, and 1000 levels would exhaust Python's recursion on reading it.
MAX_DEPTH = 32



def _bigger(limit):
    """What to do instead of a run bigger than ``limit``."""
    if limit < MAX_DOCUMENT_SWEEP_CASES:
        return "a bigger study runs through `bearinglab sweep` on dask, in chunks"
    return "split the study into several sweeps (by one parameter's range)"


def check_count(name, value, limit, *, minimum=1):
    """``value`` as an int, checked to be a whole number in ``[minimum, limit]``.

    Parameters
    ----------
    name : str
        The option or key, for the message (``"harmonics"``).
    value : int
        The count given.
    limit : int
        The largest count accepted (one of this module's constants).
    minimum : int, optional
        The smallest count accepted.

    Returns
    -------
    int
        ``value``.

    Raises
    ------
    InputError
        Not a whole number, below ``minimum`` or above ``limit``; the message names the limit.

    Examples
    --------
    >>> check_count("harmonics", 5, MAX_HARMONICS)
    5
    >>> check_count("harmonics", 10**9, MAX_HARMONICS)
    Traceback (most recent call last):
    ...
    bearinglab.errors.InputError: harmonics must be <= 1000 [-] (bearinglab's size limit), got 1000000000
    """
    if isinstance(value, bool) or not isinstance(value, int) and not (
            isinstance(value, float) and value.is_integer()):
        raise InputError(f"{name} must be a whole number [-], got {value!r}")
    value = int(value)
    if value < minimum:
        raise InputError(f"{name} must be an integer >= {minimum} [-], got {value}")
    if value > limit:
        raise InputError(f"{name} must be <= {limit} [-] (bearinglab's size limit), got {value}")
    return value


def check_cases(count, what, *, limit=MAX_CASES):
    """Refuse a run of more than ``limit`` cases before its grid is built.

    Parameters
    ----------
    count : int or float
        The number of cases (a product of the lengths of the lists; may be huge or inf).
    what : str
        What multiplies to ``count``, for the message (``"40 thrusts x 10000 speeds"``).
    limit : int, optional
        :data:`MAX_CASES` for a command, :data:`MAX_SWEEP_CASES` for a sweep.

    Returns
    -------
    int
        ``count``.

    Raises
    ------
    InputError
        More than ``limit`` cases; the message says that a bigger study runs through a sweep.
    """
    if not count <= limit:
        raise InputError(f"cases: {what} make {count:.4g} cases, more than the limit of {limit:.4g}; "
                         f"{_bigger(limit)}")
    return int(count)


def range_count(start, stop, step, name, text, *, limit=MAX_RANGE_VALUES):
    """The number of values of the range ``start:stop:step`` (end point kept when the steps land on it).

    Computed from the three numbers, without building the range, and refused when above ``limit`` or
    not finite (``1e-300 N:1e300 N:1e-300 N``).

    Examples
    --------
    >>> range_count(0.1, 0.3, 0.1, "x", "0.1:0.3:0.1")
    3
    """
    n = (stop - start) / step
    if not math.isfinite(n) or n >= limit:
        shown = f"{n + 1:.4g}" if math.isfinite(n) else "too many"
        raise InputError(f"{name}: range {text!r} has {shown} values, more than the limit of {limit:.4g}; "
                         f"{_bigger(limit)}")
    return math.floor(n * (1 + 1e-12) + 1e-9) + 1


def read_input_bytes(path, *, limit=MAX_INPUT_BYTES):
    """The bytes of an input file, read only when it is a regular file of at most ``limit`` bytes.

    A device (``/dev/zero``, ``/dev/urandom``), a FIFO or a huge file is refused before it is read; a
    file that grows while it is read is cut at ``limit`` + 1 bytes and refused too.

    Parameters
    ----------
    path : str or Path
        The file.
    limit : int, optional
        The largest size accepted. [bytes]

    Returns
    -------
    bytes
        The content.

    Raises
    ------
    FileNotFoundError, IsADirectoryError, PermissionError
        As ``open`` raises them (the callers word these).
    InputError
        Not a regular file, or larger than ``limit``; the message names the file.
    """
    path = Path(path)
    # O_NONBLOCK: opening a FIFO with no writer must not hang before fstat can refuse it
    fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    with os.fdopen(fd, "rb") as f:
        info = os.fstat(f.fileno())
        if stat.S_ISDIR(info.st_mode):
            raise IsADirectoryError(21, "Is a directory", str(path))
        if not stat.S_ISREG(info.st_mode):
            raise InputError(f"{path}: not a regular file (a device, a pipe or a socket); give a file")
        if info.st_size > limit:
            raise InputError(f"{path}: {info.st_size} bytes, more than the limit of {limit} bytes for an "
                             f"input file")
        _io.note_input(path, info)  # an input of the run: no output of the run may replace it
        data = f.read(limit + 1)
    if len(data) > limit:
        raise InputError(f"{path}: more than the limit of {limit} bytes for an input file")
    return data


def check_steps(count, what="duty-cycle", *, limit=None):
    """The number of steps of a duty cycle, checked before any step is read or computed.

    Parameters
    ----------
    count : int
        The steps (the length of the parsed ``[[step]]`` array, or of the loads given).
    what : str
        The option or parameter, named by the message.
    limit : int, optional
        The most steps accepted (default :data:`MAX_DUTY_CYCLE_STEPS`).

    Returns
    -------
    int
        ``count``.

    Raises
    ------
    InputError
        More than ``limit`` steps.

    Examples
    --------
    >>> check_steps(20000)
    Traceback (most recent call last):
    ...
    bearinglab.errors.InputError: duty-cycle: 20000 steps, more than the limit of 10000 steps of a duty cycle; \
bin the load spectrum into fewer steps (the life of a step depends on its load and speed only)
    """
    limit = MAX_DUTY_CYCLE_STEPS if limit is None else limit
    if count > limit:
        raise InputError(f"{what}: {count} steps, more than the limit of {limit} steps of a duty cycle; bin the "
                         f"load spectrum into fewer steps (the life of a step depends on its load and speed only)")
    return count


class RepeatedKey(InputError):
    """A JSON object that gives one key twice (:func:`parse_json`); ``key`` is the key."""

    def __init__(self, key, message):
        self.key = key
        super().__init__(message)


def _unique(pairs):
    """``object_pairs_hook`` of :func:`parse_json`: a key given twice is an error, never its last value."""
    out = {}
    for key, value in pairs:
        if key in out:
            raise RepeatedKey(key, f"key {key!r} given more than once; give it once")
        out[key] = value
    return out


def _check_depth(doc, what, limit):
    """Refuse a parsed document nested deeper than ``limit`` (walked without recursion)."""
    stack = [(doc, 1)]
    while stack:
        node, depth = stack.pop()
        children = node.values() if isinstance(node, dict) else node if isinstance(node, list) else ()
        for child in children:
            if isinstance(child, (dict, list)):
                if depth + 1 > limit:
                    raise InputError(f"{what}: nested more than {limit} levels deep; the inputs of bearinglab are a few levels deep")
                stack.append((child, depth + 1))
    return doc


def parse_json(text, what="the document", *, limit=MAX_DEPTH):
    """A JSON text, read strictly: a key given twice in one object, or nesting deeper than ``limit``, is an
    InputError (Python's reader keeps a repeated key's last value, and fails on deep nesting with a
    RecursionError).

    Parameters
    ----------
    text : str or bytes
        The JSON text.
    what : str
        What it is, named by the messages.
    limit : int, optional
        The deepest nesting accepted.

    Returns
    -------
    object

    Raises
    ------
    RepeatedKey
        A key given twice (its ``key``).
    InputError
        Too deeply nested.
    ValueError
        Not JSON (``json.JSONDecodeError``), as ``json.loads`` raises it.

    Examples
    --------
    >>> parse_json('{"a": 1, "a": 2}')
    Traceback (most recent call last):
    ...
    bearinglab._bounds.RepeatedKey: the document: key 'a' given more than once; give it once
    """
    import json

    try:
        doc = json.loads(text, object_pairs_hook=_unique)
    except RepeatedKey as exc:
        raise RepeatedKey(exc.key, f"{what}: {exc}") from None
    except RecursionError:
        raise InputError(f"{what}: nested more than {limit} levels deep; the inputs of bearinglab are a few levels deep") from None
    return _check_depth(doc, what, limit)


def parse_document(text, what="the document", *, limit=MAX_DEPTH):
    """A posted document: JSON when it opens with ``{``, else TOML, read as :func:`parse_json` reads JSON
    (TOML refuses a repeated key itself).

    Parameters
    ----------
    text : str
        The document.
    what : str
        What it is, named by the messages.
    limit : int, optional
        The deepest nesting accepted.

    Returns
    -------
    object
        The parsed document.

    Raises
    ------
    InputError
        A repeated key (JSON), nesting deeper than ``limit``.
    ValueError, tomllib.TOMLDecodeError
        Not JSON or not TOML, as the readers raise them.
    """
    import tomllib

    stripped = text.strip()
    if stripped.startswith("{"):
        return parse_json(stripped, what, limit=limit)
    try:
        doc = tomllib.loads(text)
    except RecursionError:
        raise InputError(f"{what}: nested more than {limit} levels deep; the inputs of bearinglab are a few levels deep") from None
    return _check_depth(doc, what, limit)
