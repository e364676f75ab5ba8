"""Worker processes for the web: each request's calculation runs in a process that can be stopped.

A :class:`Pool` holds a few worker processes (forked from a clean server process, so that no lock or
thread of the web server is copied into them). A request takes an idle worker, sends it the calculation's name and
values, and waits for the answer without blocking the event loop; it stops the worker (and starts a
new one) when the request runs over its time budget or its client goes away. A worker that computed
a large request, or whose memory grew past a bound, exits after answering, so that the memory goes
back to the system. The server keeps two pools, light and heavy, so that a light request never
waits behind heavy ones; the heavy workers run at a lower OS priority, so that the light ones keep a core.

Classes
-------
Pool           the worker processes of one kind; ``await pool.call(task, budget=..., gone=...)``
Stopped        a call stopped: over its time budget, client gone, pool busy, or worker lost
MEMORY_BOUND_MB  the peak memory of a worker after which it is replaced
HEAVY_NICENESS   the OS priority offset of the heavy pool's workers (os.nice): light requests keep a core
"""

from __future__ import annotations

import asyncio
import importlib
import multiprocessing
import os
import resource
import time

__all__ = ["HEAVY_NICENESS", "MEMORY_BOUND_MB", "Pool", "Stopped"]

#: Peak resident memory of a worker after which it is replaced, so that its memory goes back [MB].
MEMORY_BOUND_MB = 350
#: The niceness of the heavy pool's workers (``os.nice``): at 10 the Linux scheduler gives a process of
#: niceness 0 about 9 times its share of a busy core, so a light request computes at nearly full speed
#: beside heavy ones.
HEAVY_NICENESS = 10


class Stopped(Exception):
    """A call that did not finish: ``reason`` is ``budget``, ``gone``, ``busy`` or ``lost``."""

    def __init__(self, reason, message):
        self.reason = reason
        super().__init__(message)


def _calculation_modules():
    """The modules of the calculations' document functions (no command line: the web never runs it)."""
    from ..calculations import documents

    return tuple(sorted({f"bearinglab.calculations.{m}" for m in documents._NATIVE.values()}))


_CALCULATION_MODULES = _calculation_modules()


def _serve(conn, memory_bound_mb=MEMORY_BOUND_MB, niceness=0):
    """A worker's loop: receive (what, name, given, limit), answer ('ok', value) or ('error', ...).

    ``niceness`` is added to the worker's OS scheduling priority first (``os.nice``): the heavy pool's
    workers run below the server and the light workers, so that a light request keeps a core while
    heavy ones compute."""
    import warnings

    if niceness and hasattr(os, "nice"):
        try:
            os.nice(niceness)
        except OSError:  # not allowed here (a container's policy): the worker runs at the server's priority
            pass
        # Linux's idle class on top: a waking light worker or the server preempts a heavy worker at once
        # (niceness alone leaves the light request a scheduler slice of wake-up latency, the p99's tail);
        # the threads the worker starts later (numba, BLAS) inherit it
        if hasattr(os, "sched_setscheduler") and hasattr(os, "SCHED_IDLE"):
            try:
                os.sched_setscheduler(0, os.SCHED_IDLE, os.sched_param(0))
            except OSError:
                pass

    from .. import calculations, tables
    from ..errors import ConvergenceError, InputError
    from ..units import parse_quantity

    parse_quantity("1 N", "force", "warm-up")  # load the unit registry before the first request
    for module in _CALCULATION_MODULES:  # the calculations, imported before the first request
        importlib.import_module(module)

    warnings.simplefilter("ignore")
    while True:
        try:
            what, name, given, limit, *checked = conn.recv()
        except (EOFError, OSError):
            return
        try:
            # checked by the server already (sent along), or read here
            parsed = checked[0] if checked else calculations.parse(name, given, limit=limit)
            if what == "figure":
                value = calculations.figure_svg(parsed)
            elif what == "json":  # the bytes the server sends: no large document, no encoding in the server
                value = tables.json_text(calculations.run(parsed)).encode()
            else:
                value = calculations.run(parsed)
            answer = ("ok", value)
        except calculations.RequestError as exc:
            answer = ("error", {"parameter": exc.parameter, "template": exc.template,
                                "kind": getattr(exc, "kind", "input"), "valid": exc.valid})
        except (ConvergenceError, InputError) as exc:  # not turned into a message by the layer
            answer = ("error", {"parameter": None, "template": str(exc), "valid": "",
                                "kind": "convergence" if isinstance(exc, ConvergenceError) else "input"})
        except RecursionError:  # the last line of defence of the documents' depth bound (bearinglab._bounds)
            answer = ("error", {"parameter": None, "template": "the input is nested too deeply to read",
                                "valid": "", "kind": "input"})
        except Exception as exc:  # noqa: BLE001 -- a bug: the server answers 500 and names it
            answer = ("bug", f"{type(exc).__name__}: {exc}")
        peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
        leaving = peak > memory_bound_mb * 1024  # ru_maxrss is in kB on Linux
        conn.send((*answer, leaving))
        if leaving:
            return


def _context():
    """Workers fork from a clean server process that has imported the calculations once (so a new
    worker starts in milliseconds, and no thread or lock of the web server is copied into it)."""
    ctx = multiprocessing.get_context("forkserver")
    ctx.set_forkserver_preload(["bearinglab.calculations", *_CALCULATION_MODULES, "bearinglab.units",
                                "bearinglab.quasistatic", "bearinglab.plots.high_speed",
                                "bearinglab.plots.load_distribution", "matplotlib.figure",
                                "matplotlib.backends.backend_svg", "numpy", "scipy", "pint"])
    return ctx


class _Worker:
    def __init__(self, ctx, memory_bound_mb, niceness=0):
        self.conn, child = ctx.Pipe()
        self.process = ctx.Process(target=_serve, args=(child, memory_bound_mb, niceness), daemon=True)
        self.process.start()
        child.close()
        self.tasks = 0

    def alive(self):
        return self.process.is_alive()

    def stop(self):
        if self.process.is_alive():
            self.process.kill()
        self.process.join(5)
        self.conn.close()


class Pool:
    """Worker processes of one kind.

    Parameters
    ----------
    size : int
        Worker processes.
    recycle : bool
        Replace a worker after every call (for heavy requests: their memory goes back at once).
    queue : int
        Calls that may wait for a worker; one more is answered ``busy``.
    memory_bound_mb : float
        A worker whose peak resident memory passed this after a call is replaced. [MB]
    niceness : int
        Added to the workers' OS scheduling priority (``os.nice``; :data:`HEAVY_NICENESS` for the heavy
        pool): they yield the cores to the server and the light workers.
    """

    def __init__(self, size, *, recycle=False, queue=64, memory_bound_mb=MEMORY_BOUND_MB, niceness=0):
        self.size, self.recycle, self.queue = size, recycle, queue
        self.memory_bound_mb, self.niceness = memory_bound_mb, niceness
        self._ctx = _context()
        self._idle = None
        self._waiting = 0
        self._workers = []

    def start(self):
        """Start the workers (in the event loop that will use the pool)."""
        self._idle = asyncio.Queue()
        for _ in range(self.size):
            self._add()

    def _add(self):
        w = _Worker(self._ctx, self.memory_bound_mb, self.niceness)
        self._workers.append(w)
        self._idle.put_nowait(w)

    def _replace(self, worker):
        worker.stop()
        if worker in self._workers:
            self._workers.remove(worker)
        self._add()

    def close(self):
        """Stop every worker."""
        for w in self._workers:
            w.stop()
        self._workers = []

    def pids(self):
        """The process ids of the workers (for the benchmark's memory figure)."""
        return [w.process.pid for w in self._workers if w.alive()]

    async def call(self, task, *, budget, gone=None):
        """Run ``task`` = (what, name, given, limit) in a worker; its answer.

        Parameters
        ----------
        task : tuple
            ``("document" | "json" | "figure", calculation name, values as given, case limit[,
            Parsed])``: the document, its JSON text, or the figure.
        budget : float
            Seconds the call may take, waiting for a worker included. [s]
        gone : async callable, optional
            True when the client has gone away; checked while the call waits.

        Returns
        -------
        tuple
            The worker's answer: ``("ok", value)``, ``("error", {...})`` or ``("bug", text)``.

        Raises
        ------
        Stopped
            Over budget, client gone, too many calls waiting, or the worker died.
        """
        if self._idle is None:
            self.start()
        start = time.monotonic()
        if self._idle.empty() and self._waiting >= self.queue:
            raise Stopped("busy", f"the server is busy ({self._waiting} requests waiting); try again")
        self._waiting += 1
        try:
            worker = await self._take(start, budget, gone)
        finally:
            self._waiting -= 1
        try:
            worker.conn.send(task)
            await self._wait(worker, start, budget, gone)
            # read in a thread: a large answer (a map's JSON, tens of MB) comes through the pipe as fast as
            # its worker, niced below the server, writes it; the event loop keeps answering light requests
            *answer, leaving = await asyncio.to_thread(worker.conn.recv)
        except Stopped:
            await asyncio.to_thread(self._replace, worker)
            raise
        except (EOFError, OSError, BrokenPipeError):
            await asyncio.to_thread(self._replace, worker)
            raise Stopped("lost", "the calculation's worker process ended (out of memory?)") from None
        worker.tasks += 1
        if leaving or self.recycle or not worker.alive():
            await asyncio.to_thread(self._replace, worker)
        else:
            self._idle.put_nowait(worker)
        return tuple(answer)

    async def _take(self, start, budget, gone):
        while True:
            try:
                worker = await asyncio.wait_for(self._idle.get(), 0.25)
            except TimeoutError:
                _check(start, budget)
                if gone is not None and await gone():
                    raise Stopped("gone", "the client went away") from None
                continue
            if worker.alive():
                return worker
            await asyncio.to_thread(self._replace, worker)

    async def _wait(self, worker, start, budget, gone):
        loop = asyncio.get_running_loop()
        ready = loop.create_future()
        fd = worker.conn.fileno()
        loop.add_reader(fd, lambda: ready.done() or ready.set_result(True))
        try:
            while True:
                left = budget - (time.monotonic() - start)
                done, _ = await asyncio.wait({ready}, timeout=max(0.0, min(0.25, left)))
                if done:
                    return
                _check(start, budget)
                if gone is not None and await gone():
                    raise Stopped("gone", "the client went away")
        finally:
            loop.remove_reader(fd)


def _check(start, budget):
    if time.monotonic() - start > budget:
        raise Stopped("budget", f"the request ran over its time budget of {budget:g} s and was "
                                "stopped; ask for fewer cases")


def rss_kb(pid=None):
    """Resident memory of a process [kB] (Linux /proc), for the benchmark."""
    with open(f"/proc/{pid or os.getpid()}/status", encoding="ascii") as fh:
        for line in fh:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    return 0
