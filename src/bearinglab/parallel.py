"""Batch and distributed execution: the one execution layer every batch entry point uses.

Cases are split into numpy chunks of a tunable size and one pure function evaluates a chunk. The
chunks run in this process (``executor="serial"``, the default), on a ``dask.distributed.LocalCluster``
started and stopped for the job (``"local"``), or on a running dask scheduler (``"tcp://host:8786"``).
The same chunks are evaluated whatever the executor, so the results are bit-identical to the serial
path.

Functions
---------
chunk_bounds     (start, stop) of each chunk
run_cases        evaluate ``func(**chunk_of_cases, **constants)`` over all cases
run_chunks       the same, each chunk's output as the function returned it (a list, in case order)
run_seeded       Monte Carlo: ``func(n, rng, **constants)`` over blocks of samples with their own seeds
executor_client  context manager yielding a dask client for an executor (``None`` for serial)
probe_scheduler  check that a tcp:// address answers as a dask scheduler, before dask connects
is_local_address True for serial, local and a scheduler on this machine
machine_cores    the cores this process may run on (the cap of ``workers`` on this machine)
parse_memory_limit  a memory limit as written (``"512 MiB"``, ``"2 GB"``, bytes) -> bytes, checked
Execution        the execution options (executor, workers, chunk size, progress, ...) as one value

Checked before any cluster starts (:class:`Execution`): ``workers`` is at most the cores of this
machine unless the executor is a scheduler address (whose workers run elsewhere), and
``memory_limit`` is a size with a unit of at least :data:`MIN_MEMORY_LIMIT` (a dask worker holds
about 100 MB before its first task) and at most this machine's memory.

Every batch entry point of the models (``quasistatic.sweep``, ``runout.monte_carlo``, ``sweep.run_sweep``)
takes one ``execution=Execution(...)`` argument instead of five keyword arguments.

Seeds (``run_seeded``): samples are grouped in blocks of ``block_size``; block k draws from
``numpy.random.Generator(PCG64(SeedSequence(seed).spawn(n_blocks)[k]))``. A chunk is a run of whole blocks,
so a result depends on the seed and the block size only: not on the chunk size, the executor or the
number of workers.

dask is imported on first use of a distributed executor, so ``import bearinglab`` stays light.
"""

from __future__ import annotations

import contextlib
import dataclasses
import math
import os
import re
import sys
from collections.abc import Callable, Mapping

import numpy as np

from . import _bounds
from .errors import InputError

__all__ = ["DEFAULT_BLOCK_SIZE", "DEFAULT_CHUNK_SIZE", "MIN_MEMORY_LIMIT", "Execution", "chunk_bounds",
           "executor_client", "is_local_address", "machine_cores", "parse_memory_limit", "probe_scheduler",
           "run_cases", "run_chunks", "run_seeded"]

DEFAULT_CHUNK_SIZE = 10_000
DEFAULT_BLOCK_SIZE = 256
_CONNECT_TIMEOUT_S = 10.0
#: The smallest memory limit of a local dask worker [bytes]. A worker process holds about 100 MB before
#: its first task (measured: 68 MB idle, 95-101 MB after a test-stand sweep chunk or a life and a
#: high-speed document, distributed 2026.8, Python 3.11), and dask pauses it at 80 % of its limit and
#: restarts it at 95 %: below a few hundred MB a chunk of 10^4 high-speed cases (~80 MB) pauses the
#: worker forever (``--memory-limit 1MB`` hung) or the nanny fails to start it (``100MB``).
MIN_MEMORY_LIMIT = 512 * 2**20
# memory units as dask and the operating system write them: decimal (kB, MB, GB, TB) and binary (KiB,
# MiB, GiB, TiB), case-insensitive; a bare number is bytes
_MEMORY_UNITS = {"": 1, "b": 1, "bytes": 1, "kb": 10**3, "mb": 10**6, "gb": 10**9, "tb": 10**12,
                 "kib": 2**10, "mib": 2**20, "gib": 2**30, "tib": 2**40}
_MEMORY = re.compile(r"^\s*((?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?)\s*([A-Za-z]*)\s*$")


@dataclasses.dataclass(frozen=True)
class Execution:
    """How a batch runs: where, in which chunks, with what progress report. One value travels from the
    command line to :func:`run_cases` / :func:`run_seeded` instead of five keyword arguments.

    Parameters
    ----------
    executor : str, optional
        ``"serial"`` (default), ``"local"`` (a ``LocalCluster`` started for the job) or a scheduler
        address ``"tcp://host:8786"``.
    workers : int, optional
        Workers of a local cluster, at most :func:`machine_cores` when they are processes of this
        machine (not for a scheduler address, nor for threads). [-]
    chunk_size : int, optional
        Cases per chunk (task); ``None`` takes the default of the entry point. [-]
    memory_limit : str or int, optional
        Memory limit per local worker: a size with a unit (``"512 MiB"``, ``"2 GB"``) or bytes, from
        :data:`MIN_MEMORY_LIMIT` to this machine's memory (:func:`parse_memory_limit`); kept as bytes.
        ``None`` or ``"auto"``: dask's default, the machine's memory shared by the workers.
    processes : bool, optional
        Local workers as processes (default) or threads.
    progress : callable or "dask", optional
        ``progress(done_cases, total_cases)`` after each chunk, or ``"dask"`` for dask's progress bar.
    timeout : float, optional
        Seconds to wait for a remote scheduler (default 10). [s]

    Examples
    --------
    >>> Execution(chunk_size=500).with_default_chunk_size(10_000).chunk_size
    500
    >>> Execution().with_default_chunk_size(10_000).chunk_size
    10000
    >>> Execution(executor="local", workers=1, memory_limit="1 GiB").memory_limit
    1073741824
    >>> Execution(executor="local", memory_limit="100MB")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    bearinglab.errors.InputError: memory-limit must be 512 MiB ... per worker (a dask worker holds about 100 MB before its first task), got '100MB'
    """

    executor: str = "serial"
    workers: int | None = None
    chunk_size: int | None = None
    memory_limit: str | int | None = None
    processes: bool = True
    progress: Callable[[int, int], object] | str | None = None
    timeout: float | None = None

    def __post_init__(self):
        if self.executor is None:  # None and "serial" are the same request
            object.__setattr__(self, "executor", "serial")
        _validate_executor(self.executor)
        for name in ("workers", "chunk_size"):
            v = getattr(self, name)
            if v is not None and (not _whole(v) or v < 1):
                raise InputError(f"{name.replace('_', '-')} must be an integer >= 1 [-], got {v!r}")
        _check_workers(self.workers, self.executor, self.processes)
        # checked and kept in bytes before any cluster starts: a typo is one line, not a nanny's traceback
        object.__setattr__(self, "memory_limit", parse_memory_limit(self.memory_limit))

    def with_default_chunk_size(self, chunk_size):
        """This value, with ``chunk_size`` filled in where it was left ``None``."""
        return self if self.chunk_size is not None else dataclasses.replace(self, chunk_size=int(chunk_size))


def machine_cores():
    """The cores this process may run on: the cap of ``workers`` on this machine.

    The CPU affinity of the process where the system has one (a container or ``taskset`` limits it),
    else :func:`os.cpu_count`.

    Returns
    -------
    int
        At least 1. [-]
    """
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):  # no affinity on this system (macOS, Windows)
        return max(1, os.cpu_count() or 1)


def _machine_memory():
    """This machine's physical memory [bytes], or None where the system does not say."""
    try:
        return int(os.sysconf("SC_PAGE_SIZE")) * int(os.sysconf("SC_PHYS_PAGES"))
    except (AttributeError, ValueError, OSError):  # Windows has no sysconf
        return None


def _size_text(n):
    """Bytes as the largest binary unit that keeps them >= 1: ``512 MiB``, ``23.5 GiB``."""
    for unit, factor in (("TiB", 2**40), ("GiB", 2**30), ("MiB", 2**20), ("KiB", 2**10)):
        if n >= factor:
            return f"{n / factor:.3g} {unit}"
    return f"{n} B"


def _check_workers(workers, executor, processes=True):
    """``workers``: an integer >= 1, at most :data:`bearinglab._bounds.MAX_WORKERS`, and at most the cores
    of this machine when they are processes here: not for a scheduler address (its workers run wherever
    they were started, and this number is not used) nor for the threads of ``processes=False``."""
    if workers is None:
        return
    if isinstance(workers, bool) or int(workers) != workers or workers < 1:
        raise InputError(f"workers must be an integer >= 1 [-], got {workers!r}")
    if workers > _bounds.MAX_WORKERS:
        raise InputError(f"workers must be <= {_bounds.MAX_WORKERS} [-] (bearinglab's size limit), got {workers}")
    if processes and executor in ("serial", "local") and workers > machine_cores():
        # one process per worker: more than the cores only share them, each with its own memory
        raise InputError(f"workers must be 1 ... {machine_cores()} [-] (the cores of this machine; a scheduler "
                         f"given as --executor tcp://host:port is not capped), got {workers}")


def _memory_range():
    """The valid memory limits in words: ``512 MiB ... 23.5 GiB per worker``."""
    total = _machine_memory()
    return f"{_size_text(MIN_MEMORY_LIMIT)} ... {_size_text(total) if total else 'the machine memory'} per worker"


def parse_memory_limit(value):
    """A memory limit per local worker as written -> bytes, checked.

    Parameters
    ----------
    value : str, int or None
        One number and a unit: ``"512 MiB"``, ``"2 GB"``, ``"1.5GiB"`` (kB, MB, GB, TB decimal; KiB, MiB,
        GiB, TiB binary; any case), or bytes (``"536870912"``, an int). ``None`` or ``"auto"``: dask's
        default (the machine's memory shared by the workers).

    Returns
    -------
    int or None
        Bytes; None for the default.

    Raises
    ------
    InputError
        Not one number with a known unit, below :data:`MIN_MEMORY_LIMIT` or above this machine's
        memory; the message names ``memory-limit``, the value and the valid range.

    Examples
    --------
    >>> parse_memory_limit("2 GB"), parse_memory_limit("512 MiB")
    (2000000000, 536870912)
    >>> parse_memory_limit("abc")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    bearinglab.errors.InputError: memory-limit must be a size with a unit, 512 MiB ... per worker (e.g. '4 GiB' or '2 GB'; ...), got 'abc'
    """
    if value is None or (isinstance(value, str) and value.strip().lower() == "auto"):
        return None
    if isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(value, bool):
        size = float(value) if isinstance(value, (float, np.floating)) else int(value)  # bytes
    else:
        m = _MEMORY.match(value) if isinstance(value, str) else None
        if m is None or m.group(2).lower() not in _MEMORY_UNITS:
            raise InputError(f"memory-limit must be a size with a unit, {_memory_range()} (e.g. '4 GiB' or '2 GB'; "
                             f"kB, MB, GB, TB, KiB, MiB, GiB, TiB; a bare number is bytes), got {value!r}")
        size = float(m.group(1)) * _MEMORY_UNITS[m.group(2).lower()]  # '1e400 GB' is inf: above any machine
    total = _machine_memory()
    if not math.isfinite(size) or size > (total or 2**62):
        raise InputError(f"memory-limit must be {_memory_range()} (this machine's memory), got {value!r}")
    if size < MIN_MEMORY_LIMIT:
        raise InputError(f"memory-limit must be {_memory_range()} (a dask worker holds about 100 MB before its "
                         f"first task), got {value!r}")
    return math.floor(size)


def _execution(execution, **legacy):
    """One Execution from the new argument or the old keyword arguments (the old ones keep working)."""
    given = {k: v for k, v in legacy.items() if v is not None}
    if execution is None:
        return Execution(**given)
    if given:
        raise InputError(f"give execution=Execution(...) or {', '.join(sorted(given))}, not both")
    return execution


def _whole(value):
    """Whether ``value`` is a whole number (an int, or a float with no fraction; not a bool, NaN or inf)."""
    if isinstance(value, (bool, np.bool_)):
        return False
    if isinstance(value, (int, np.integer)):
        return True
    return isinstance(value, (float, np.floating)) and math.isfinite(value) and float(value).is_integer()


def chunk_bounds(n_cases, chunk_size):
    """Split ``n_cases`` into consecutive chunks of at most ``chunk_size``.

    Parameters
    ----------
    n_cases : int
        Number of cases. [-]
    chunk_size : int
        Cases per chunk, >= 1. [-]

    Returns
    -------
    list of tuple
        ``(start, stop)`` per chunk.

    Examples
    --------
    >>> chunk_bounds(10, 4)
    [(0, 4), (4, 8), (8, 10)]
    """
    if not _whole(chunk_size) or chunk_size < 1:
        raise InputError(f"chunk_size must be an integer >= 1 [-], got {chunk_size!r}")
    if not _whole(n_cases) or n_cases < 0:
        raise InputError(f"n_cases must be an integer >= 0 [-], got {n_cases!r}")
    if n_cases > _bounds.MAX_SWEEP_CASES:  # a list of chunks, and a loop over them, of bounded length
        raise InputError(f"n_cases must be <= {_bounds.MAX_SWEEP_CASES} [-] (bearinglab's size limit), got {n_cases}")
    n_cases, chunk_size = int(n_cases), int(chunk_size)
    return [(i, min(i + chunk_size, n_cases)) for i in range(0, n_cases, chunk_size)]


def _validate_executor(executor):
    if executor in ("serial", "local"):
        return executor
    if isinstance(executor, str) and "://" in executor:
        return executor
    raise InputError(f"executor must be 'serial', 'local' or a scheduler address such as 'tcp://host:8786', got {executor!r}")


@contextlib.contextmanager
def executor_client(executor="serial", *, workers=None, memory_limit=None, processes=True,
                    timeout=None):
    """A dask client for ``executor`` (``None`` for serial), closed (and the local cluster stopped) on exit.

    Parameters
    ----------
    executor : str
        ``"serial"``, ``"local"`` or a scheduler address ``"tcp://host:8786"``.
    workers : int, optional
        Workers of the local cluster, at most :func:`machine_cores` (the default). [-]
    memory_limit : str or int, optional
        Memory limit per local worker, e.g. ``"4 GiB"`` (:func:`parse_memory_limit`).
    processes : bool, optional
        Local workers as processes (default) or as threads of this process.
    timeout : float, optional
        Seconds to wait for a scheduler before giving up (default 10). [s]

    Yields
    ------
    distributed.Client or None
    """
    executor = _validate_executor(executor)
    timeout = _CONNECT_TIMEOUT_S if timeout is None else float(timeout)
    if executor == "serial":
        yield None
        return
    if executor == "local":  # before dask is imported or any process started
        _check_workers(workers, executor, processes)
        limit = parse_memory_limit(memory_limit)
    import logging

    from distributed import Client, LocalCluster

    if executor == "local":
        cluster = LocalCluster(n_workers=int(workers or machine_cores()), threads_per_worker=1,
                               processes=processes, memory_limit="auto" if limit is None else limit,
                               dashboard_address=None, silence_logs=logging.ERROR)
        try:
            with Client(cluster) as client:
                yield client
        finally:
            cluster.close()
        return
    probe_scheduler(executor, timeout=timeout)  # before dask reads a frame length from a stranger
    try:
        client = Client(executor, timeout=f"{timeout}s")
    except (OSError, TimeoutError, ValueError) as exc:
        raise InputError(f"executor: cannot reach a dask scheduler at {executor!r} within {timeout:g} s "
                         f"({type(exc).__name__}: {exc})") from None
    try:
        yield client
    finally:
        client.close()


# What a dask scheduler sends first on a TCP connection (distributed.comm.tcp): an 8-byte little-endian
# length of the message, then the frame count and the frame lengths (8 bytes each), then the frames:
# one msgpack map {"compression": ..., "python": ..., "pickle-protocol": ...}, its handshake (66 bytes
# with distributed 2026.8). Anything else is not a scheduler.
_HANDSHAKE_MAX_BYTES = 1 << 16
_HANDSHAKE_KEYS = (b"pickle-protocol", b"compression")


def _scheduler_host(address):
    """(host, port) of a ``tcp://host:port`` address (dask's default port 8786), or None for another
    protocol (tls, ucx, inproc: not probed)."""
    from urllib.parse import urlsplit

    parts = urlsplit(address)
    if parts.scheme != "tcp":
        return None
    try:
        port = parts.port or 8786
    except ValueError:
        raise InputError(f"executor: {address!r} has no valid port") from None
    if not parts.hostname:
        raise InputError(f"executor: {address!r} has no host")
    return parts.hostname, port


def is_local_address(executor):
    """True for ``"serial"``, ``"local"`` and a scheduler on this machine (localhost, 127.0.0.0/8, ::1).

    A sweep file that names any other scheduler sends the cases (and the file's constants) to another
    machine: the command line asks for ``--allow-remote-executor`` first.

    Parameters
    ----------
    executor : str or None
        ``"serial"``, ``"local"`` or a scheduler address such as ``"tcp://host:8786"``.

    Returns
    -------
    bool
        Whether the work stays on this machine.

    Examples
    --------
    >>> is_local_address("local"), is_local_address("tcp://127.0.0.1:8786"), is_local_address("tcp://lab:8786")
    (True, True, False)
    """
    import ipaddress
    from urllib.parse import urlsplit

    if executor in (None, "serial", "local"):
        return True
    host = urlsplit(str(executor)).hostname or ""
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:  # a host name other than localhost
        return False


def probe_scheduler(address, *, timeout=_CONNECT_TIMEOUT_S):
    """Check that a ``tcp://`` address answers as a dask scheduler before a dask client connects to it.

    dask reads the length of the first frame from the peer and allocates it: a server that answers
    something else (an HTTP server, an echo service) makes the client ask for exabytes or hang. This reads
    at most 64 kB, within ``timeout`` seconds, and checks the scheduler's handshake.

    Parameters
    ----------
    address : str
        ``"tcp://host:port"``; other protocols are left to dask.
    timeout : float, optional
        Seconds for the connection and the handshake together. [s]

    Raises
    ------
    InputError
        Nothing listens there ("cannot reach a dask scheduler"), or what answers is not one ("... is not a
        dask scheduler"), with the reason.
    """
    import socket
    import time

    target = _scheduler_host(address)
    if target is None:
        return
    deadline = time.monotonic() + float(timeout)
    try:
        sock = socket.create_connection(target, timeout=float(timeout))
    except OSError as exc:
        raise InputError(f"executor: cannot reach a dask scheduler at {address!r} within {timeout:g} s "
                         f"({type(exc).__name__}: {exc})") from None

    def receive(n):
        data = b""
        while len(data) < n:
            left = deadline - time.monotonic()
            if left <= 0:
                raise TimeoutError(f"no handshake within {timeout:g} s")
            sock.settimeout(left)
            try:
                chunk = sock.recv(min(n - len(data), _HANDSHAKE_MAX_BYTES))
            except TimeoutError:
                raise TimeoutError(f"no handshake within {timeout:g} s") from None
            if not chunk:
                raise ConnectionError("it closed the connection")
            data += chunk
        return data

    with sock:
        try:
            size = int.from_bytes(receive(8), "little")
            if not 16 <= size <= _HANDSHAKE_MAX_BYTES:
                raise ValueError(f"its first message announces {size} bytes")
            body = receive(size)
            frames = int.from_bytes(body[:8], "little")
            if not 1 <= frames <= 16 or 8 + 8 * frames > size:
                raise ValueError(f"its first message announces {frames} frames")
            if not any(key in body for key in _HANDSHAKE_KEYS):
                raise ValueError("its first message is not dask's handshake")
        except (OSError, ValueError) as exc:  # socket.timeout is an OSError (TimeoutError)
            raise InputError(f"executor: {address!r} answers but is not a dask scheduler ({exc})") from None


def _evaluate(func, chunk, constants):
    out = func(**chunk, **constants)
    return {k: np.asarray(v) for k, v in out.items()}


def _evaluate_blocks(func, sizes, seeds, constants):
    parts = [_evaluate(func, {"n": n, "rng": np.random.Generator(np.random.PCG64(s))}, constants)
             for n, s in zip(sizes, seeds)]
    return {k: np.concatenate([p[k] for p in parts]) for k in parts[0]}


def _concatenate(results, n_expected):
    keys = results[0].keys()
    out = {k: np.concatenate([r[k] for r in results]) for k in keys}
    for k, v in out.items():
        if len(v) != n_expected:
            raise RuntimeError(f"chunk function returned {len(v)} values of {k!r} for {n_expected} cases")
    return out


def _run(tasks, sizes, ex):
    """tasks: list of (callable, args) evaluated in order; returns their results in order."""
    total = int(sum(sizes))
    done = 0
    progress = ex.progress
    with executor_client(ex.executor, workers=ex.workers, memory_limit=ex.memory_limit,
                         processes=ex.processes, timeout=ex.timeout) as client:
        if client is None:
            results = []
            for (fn, args), size in zip(tasks, sizes):
                results.append(fn(*args))
                done += size
                if callable(progress):
                    progress(done, total)
            return results
        from distributed import as_completed

        # pure=False: each chunk is its own task; retries: a worker that dies is replaced and the chunk
        # re-run, its cases neither lost nor duplicated (results are collected by chunk index)
        futures = [client.submit(fn, *args, pure=False, retries=2) for fn, args in tasks]
        index = {f.key: i for i, f in enumerate(futures)}
        if progress == "dask":
            from distributed import progress as dask_progress

            # dask's text bar writes on stdout, which stays one table or one JSON document
            with contextlib.redirect_stdout(sys.stderr):
                dask_progress(futures)
        elif callable(progress):
            for fut in as_completed(futures):
                done += sizes[index[fut.key]]
                progress(done, total)
        return client.gather(futures)


def run_cases(func: Callable[..., Mapping[str, np.ndarray]], cases: Mapping[str, np.ndarray], *, constants=None,
              execution=None, chunk_size=None, executor=None, workers=None, memory_limit=None, processes=None,
              progress=None, timeout=None):
    """Evaluate a batched model over many cases, chunk by chunk.

    Parameters
    ----------
    func : callable
        Pure function ``func(**chunk, **constants)`` returning a mapping of per-case arrays (first axis =
        cases of the chunk). Per-case failures are flags in its output, not exceptions.
    cases : mapping of str to array_like
        Per-case inputs, all of the same length along the first axis.
    constants : mapping, optional
        Keyword arguments passed unchanged to every chunk.
    execution : Execution, optional
        Executor, workers, chunk size, progress and timeout as one value (default: serial, chunks of
        :data:`DEFAULT_CHUNK_SIZE`). The keyword arguments below are the older spelling of the same
        fields; give one or the other.
    chunk_size : int, optional
        Cases per chunk. [-]
    executor : str, optional
        ``"serial"`` (default), ``"local"`` or a scheduler address.
    workers : int, optional
        Workers of a local cluster. [-]
    memory_limit : str or int, optional
        Memory limit per local worker.
    processes : bool, optional
        Local workers as processes (default) or threads.
    progress : callable or "dask", optional
        ``progress(done_cases, total_cases)`` after each chunk, or ``"dask"`` for dask's progress bar.
    timeout : float, optional
        Seconds to wait for a remote scheduler (default 10). [s]

    Returns
    -------
    dict of str to ndarray
        The outputs of all chunks, concatenated in case order.

    Examples
    --------
    >>> out = run_cases(lambda x: {"y": 2 * x}, {"x": np.arange(5.0)}, chunk_size=2)
    >>> out["y"]
    array([0., 2., 4., 6., 8.])
    """
    ex = _execution(execution, chunk_size=chunk_size, executor=executor, workers=workers,
                    memory_limit=memory_limit, processes=processes, progress=progress, timeout=timeout)
    n, results = _run_chunks(_evaluate, func, cases, constants, ex)
    return _concatenate(results, n)


def _run_chunks(wrapper, func, cases, constants, ex):
    """(number of cases, [wrapper(func, chunk, constants) for each chunk]) on the executor of ``ex``."""
    arrays = {k: np.asarray(v) for k, v in cases.items()}
    if not arrays:
        raise InputError("cases must hold at least one input array")
    lengths = {len(v) for v in arrays.values()}
    if len(lengths) != 1:
        raise InputError(f"cases must all have the same length, got lengths {sorted(lengths)}")
    n = lengths.pop()
    bounds = chunk_bounds(n, ex.with_default_chunk_size(DEFAULT_CHUNK_SIZE).chunk_size)
    if not bounds:
        raise InputError("cases must hold at least one case")
    constants = dict(constants or {})
    tasks = [(wrapper, (func, {k: v[a:b] for k, v in arrays.items()}, constants)) for a, b in bounds]
    return n, _run(tasks, [b - a for a, b in bounds], ex)


def _call(func, chunk, constants):
    return func(**chunk, **constants)


def run_chunks(func: Callable[..., object], cases: Mapping[str, np.ndarray], *, constants=None, execution=None):
    """Evaluate a function over many cases, chunk by chunk, and return each chunk's output as it is.

    :func:`run_cases` concatenates outputs that are per-case arrays of the same names in every chunk;
    this leaves the outputs whole, for a function whose output is another shape (columns that differ
    between chunks, a summary per chunk). The chunks, the executors and the progress report are those
    of :func:`run_cases`.

    Parameters
    ----------
    func : callable
        Pure function ``func(**chunk, **constants)``; its output is returned unchanged (it travels back
        from a dask worker, so it must pickle).
    cases : mapping of str to array_like
        Per-case inputs, all of the same length along the first axis.
    constants : mapping, optional
        Keyword arguments passed unchanged to every chunk.
    execution : Execution, optional
        Executor, workers, chunk size, progress and timeout (default: serial, chunks of
        :data:`DEFAULT_CHUNK_SIZE`).

    Returns
    -------
    list
        The output of each chunk, in case order.

    Examples
    --------
    >>> run_chunks(lambda x: float(x.sum()), {"x": np.arange(5.0)}, execution=Execution(chunk_size=2))
    [1.0, 5.0, 4.0]
    """
    ex = _execution(execution)
    return _run_chunks(_call, func, cases, constants, ex)[1]


def run_seeded(func: Callable[..., Mapping[str, np.ndarray]], n_samples, seed, *, constants=None,
               block_size=DEFAULT_BLOCK_SIZE, execution=None, chunk_size=None, executor=None, workers=None,
               memory_limit=None, processes=None, progress=None, timeout=None):
    """Monte Carlo over ``n_samples``, reproducible from one seed whatever the chunking or executor.

    Parameters
    ----------
    func : callable
        Pure function ``func(n, rng, **constants)`` drawing ``n`` samples from ``rng`` and returning a
        mapping of per-sample arrays.
    n_samples : int
        Number of samples, >= 1. [-]
    seed : int or numpy.random.SeedSequence
        Root seed.
    constants : mapping, optional
        Keyword arguments passed unchanged to every block.
    block_size : int, optional
        Samples per seeded block; the result depends on it (and the seed) only. [-]
    execution : Execution, optional
        As in :func:`run_cases`; its chunk size is in samples per task, rounded up to whole blocks.
    chunk_size : int, optional
        Samples per task, rounded up to whole blocks. [-]
    executor : str, optional
        ``"serial"``, ``"local"`` or a scheduler address.
    workers : int, optional
        Workers of a local cluster. [-]
    memory_limit : str or int, optional
        Memory limit per local worker.
    processes : bool, optional
        Local workers as processes (default) or threads.
    progress : callable or "dask", optional
        As in :func:`run_cases`.
    timeout : float, optional
        Seconds to wait for a remote scheduler (default 10). [s]

    Returns
    -------
    dict of str to ndarray
        Per-sample outputs in sample order.

    Examples
    --------
    >>> draw = lambda n, rng: {"u": rng.random(n)}
    >>> a = run_seeded(draw, 1000, seed=7, chunk_size=256)["u"]
    >>> b = run_seeded(draw, 1000, seed=7, chunk_size=768)["u"]
    >>> bool(np.array_equal(a, b))
    True
    """
    if not _whole(n_samples) or n_samples < 1:
        raise InputError(f"n_samples must be an integer >= 1 [-], got {n_samples!r}")
    if n_samples > _bounds.MAX_SAMPLES:  # the seeds of the blocks are spawned before any work
        raise InputError(f"n_samples must be <= {_bounds.MAX_SAMPLES} [-] (bearinglab's size limit), got {n_samples}")
    if not isinstance(seed, np.random.SeedSequence) and (not _whole(seed) or seed < 0):
        raise InputError(f"seed must be an integer >= 0 [-] or a numpy.random.SeedSequence, got {seed!r}")
    if not isinstance(seed, np.random.SeedSequence):
        seed = int(seed)  # 7.0 is 7: SeedSequence takes ints only
    if not _whole(block_size) or block_size < 1:
        raise InputError(f"block_size must be an integer >= 1 [-], got {block_size!r}")
    n_samples, block_size = int(n_samples), int(block_size)
    ex = _execution(execution, chunk_size=chunk_size, executor=executor, workers=workers,
                    memory_limit=memory_limit, processes=processes, progress=progress,
                    timeout=timeout).with_default_chunk_size(DEFAULT_CHUNK_SIZE)
    root = seed if isinstance(seed, np.random.SeedSequence) else np.random.SeedSequence(seed)
    n_blocks = math.ceil(n_samples / block_size)
    seeds = root.spawn(n_blocks)
    sizes = [min(block_size, n_samples - k * block_size) for k in range(n_blocks)]
    blocks_per_chunk = max(1, math.ceil(chunk_bounds(n_samples, ex.chunk_size)[0][1] / block_size))
    constants = dict(constants or {})
    tasks, task_sizes = [], []
    for a in range(0, n_blocks, blocks_per_chunk):
        b = min(a + blocks_per_chunk, n_blocks)
        tasks.append((_evaluate_blocks, (func, sizes[a:b], seeds[a:b], constants)))
        task_sizes.append(sum(sizes[a:b]))
    results = _run(tasks, task_sizes, ex)
    return _concatenate(results, n_samples)
