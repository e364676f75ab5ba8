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
run_seeded       Monte Carlo: ``func(n, rng, **constants)`` over blocks of samples with their own seeds
executor_client  context manager yielding a dask client for an executor (``None`` for serial)
probe_scheduler  check that a tcp:// address answers as a dask scheduler, before dask connects
is_local_address True for serial, local and a scheduler on this machine
Execution        the execution options (executor, workers, chunk size, progress, ...) as one value

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
import sys
from collections.abc import Callable, Mapping

import numpy as np

from . import _bounds
from .errors import InputError

__all__ = ["DEFAULT_BLOCK_SIZE", "DEFAULT_CHUNK_SIZE", "Execution", "chunk_bounds", "executor_client",
           "is_local_address", "probe_scheduler", "run_cases", "run_seeded"]

DEFAULT_CHUNK_SIZE = 10_000
DEFAULT_BLOCK_SIZE = 256
_CONNECT_TIMEOUT_S = 10.0


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
        Workers of a local cluster. [-]
    chunk_size : int, optional
        Cases per chunk (task); ``None`` takes the default of the entry point. [-]
    memory_limit : str or int, optional
        Memory limit per local worker.
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
        if self.workers is not None and self.workers > _bounds.MAX_WORKERS:  # processes of this machine
            raise InputError(f"workers must be <= {_bounds.MAX_WORKERS} [-] (bearinglab's size limit), got "
                             f"{self.workers}")

    def with_default_chunk_size(self, chunk_size):
        """This value, with ``chunk_size`` filled in where it was left ``None``."""
        return self if self.chunk_size is not None else dataclasses.replace(self, chunk_size=int(chunk_size))


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
        Workers of the local cluster (default: the number of cores). [-]
    memory_limit : str or int, optional
        Memory limit per local worker, e.g. ``"4GiB"``.
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
    import logging

    from distributed import Client, LocalCluster

    if executor == "local":
        n = workers or os.cpu_count() or 1
        if isinstance(n, bool) or int(n) != n or n < 1:
            raise InputError(f"workers must be an integer >= 1 [-], got {workers!r}")
        cluster = LocalCluster(n_workers=int(n), threads_per_worker=1, processes=processes,
                               memory_limit=memory_limit or "auto", dashboard_address=None,
                               silence_logs=logging.ERROR)
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
    arrays = {k: np.asarray(v) for k, v in cases.items()}
    if not arrays:
        raise InputError("cases must hold at least one input array")
    lengths = {len(v) for v in arrays.values()}
    if len(lengths) != 1:
        raise InputError(f"cases must all have the same length, got lengths {sorted(lengths)}")
    n = lengths.pop()
    ex = _execution(execution, chunk_size=chunk_size, executor=executor, workers=workers,
                    memory_limit=memory_limit, processes=processes, progress=progress,
                    timeout=timeout).with_default_chunk_size(DEFAULT_CHUNK_SIZE)
    bounds = chunk_bounds(n, ex.chunk_size)
    if not bounds:
        raise InputError("cases must hold at least one case")
    constants = dict(constants or {})
    tasks = [(_evaluate, (func, {k: v[a:b] for k, v in arrays.items()}, constants)) for a, b in bounds]
    results = _run(tasks, [b - a for a, b in bounds], ex)
    return _concatenate(results, n)


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
