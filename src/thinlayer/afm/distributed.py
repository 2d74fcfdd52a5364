"""Large batches on dask.distributed (issue 25 item 6): one function mapped over many items, in order.

:func:`map_batch` is the one batch API of thinlayer: the pixels of a force map (:func:`thinlayer.afm.maps.fit_map`),
a parameter sweep of :func:`thinlayer.solve` (:func:`solve_sweep`) or of the direct solvers, the cases of a
validation study.  The same call runs

* serially in this process (``scheduler=None``, the default: no dask needed);
* on dask's in-process threads (``scheduler="threads"``: a ``LocalCluster(processes=False)``; numpy and scipy
  release the GIL in their loops, Python code does not);
* on a local cluster of worker processes (``scheduler="local"``: ``LocalCluster(processes=True)``, one worker per
  core, one thread each, started as :func:`start_method` says), the embedded default for a large batch;
* on an existing cluster (``scheduler="tcp://host:8786"``, or a ``distributed.Client`` already connected);
* ``scheduler="auto"`` (the default of :func:`thinlayer.afm.maps.fit_map` and ``thinlayer fit-map``): ``"local"`` for
  a batch of :data:`AUTO_BATCH` items or more when dask.distributed is installed and there are 2 cores or more, else
  serially.

No pool of thinlayer's own: the items are grouped in chunks (one dask task per chunk, about :data:`TASKS_PER_WORKER`
per worker: a 4096-pixel map on 2 workers is 32 tasks of 128 curves, not 4096), sent to the workers by
``Client.scatter``, mapped by ``Client.map`` and collected by ``distributed.as_completed``; the results come back in
the items' order.  A chunk may travel packed (``pack=``: a force map's curves as 2 arrays per chunk), each worker may
make one warm-up call while the chunks travel (``warm=``), and ``timings=`` says where the time went.  A cluster
started here runs without dask's statistical profiler and with glibc's own ``malloc`` trimming
(:func:`_cluster_config`), and logs nothing below CRITICAL (its shutdown chatter); the tasks' errors reach the caller
through their futures.  Each item is computed by the same function on the same numbers on every path: the serial,
threaded and process results are equal bit for bit (``tests/afm/test_maps_distributed.py``).

dask is imported on first use (the extra ``thinlayer[afm]``); the serial path never imports it.
"""
from __future__ import annotations

import logging
import math
import sys
import time
from collections.abc import Callable, Iterable, Sequence
from typing import Any

from ..errors import InputError, InputTypeError

__all__ = ["AUTO_BATCH", "SCHEDULERS", "auto_scheduler", "chunked", "map_batch", "solve_sweep", "start_method"]

#: the named schedulers (besides a ``tcp://``/``tls://``/``inproc://`` address or a ``distributed.Client``)
SCHEDULERS = (None, "serial", "threads", "local", "auto")
#: ``scheduler="auto"``: a local cluster of processes from this many items on (with dask.distributed and 2+ cores),
#: else serially.  Starting 2 workers and closing them (forkserver, load 7-9): 0.6-1.1 s, the process's first
#: cluster 4-5 s (spawned: 7-9 s each time); a map curve 2.5-5 ms of CPU
AUTO_BATCH = 256
#: chunks per worker by default: the workers finish together within about one chunk (a worker that is done waits
#: for the others' last chunk; 128 map curves are 0.5 s, 512 were 2 s); a task costs dask about a millisecond
TASKS_PER_WORKER = 16
#: seconds to wait for a cluster to start or a scheduler to answer before giving up (one line, never a hang)
CONNECT_TIMEOUT = 60.0
#: what the server of a ``forkserver`` local cluster imports before it forks the workers (:func:`start_method`)
FORKSERVER_PRELOAD = ("distributed", "numpy", "scipy.optimize", "thinlayer.afm.maps", "thinlayer.afm.curve_fit",
                      "thinlayer.contact.models.any_thickness")


def chunked(items: Sequence[Any], size: int) -> list[list[Any]]:
    """``items`` cut into consecutive lists of at most ``size`` (order kept)."""
    return [list(items[i:i + size]) for i in range(0, len(items), size)]


def _run_chunk(func: Callable[[Any], Any], chunk: Iterable[Any]) -> tuple[list[Any], float]:
    """One dask task: ``func`` over a chunk of items (a list, or what ``pack`` made of one), in order, and the CPU
    seconds it took (:func:`map_batch`'s ``timings``).
    """
    t0 = time.process_time()
    out = [func(item) for item in chunk]
    return out, time.process_time() - t0


def _warm(func: Callable[[Any], Any], item: Any) -> None:
    """A worker's first call, its result dropped: the imports and caches ``func`` needs, paid while the items are
    still being sent.
    """
    func(item)


class Progress:
    """A progress bar over ``total`` items: tqdm when installed, else a plain counter on stderr; off when
    ``enabled`` is false.
    """

    def __init__(self, total: int, enabled: bool, label: str = "curves") -> None:
        self.total, self.done, self.enabled, self.label = total, 0, bool(enabled) and total > 0, label
        self._bar = None
        self._step = max(1, total // 20)
        if self.enabled:
            try:
                from tqdm import tqdm  # optional: nicer, not needed
            except ImportError:
                self._bar = None
            else:
                self._bar = tqdm(total=total, unit=f" {label}", file=sys.stderr)

    def update(self, n: int = 1) -> None:
        """``n`` more items done."""
        if not self.enabled:
            return
        self.done += n
        if self._bar is not None:
            self._bar.update(n)
        elif self.done == self.total or self.done // self._step != (self.done - n) // self._step:
            tty = sys.stderr.isatty()  # a terminal: one line rewritten; a log file: a line per 5 %
            print(f"{chr(13) if tty else ''}{self.done}/{self.total} {self.label}",
                  end="\n" if self.done >= self.total or not tty else "", file=sys.stderr, flush=True)

    def close(self) -> None:
        """End the bar (tqdm's line)."""
        if self._bar is not None:
            self._bar.close()


def _client(scheduler: Any, workers: int | None):
    """``(client, owned)``: a dask Client for ``scheduler`` and whether this call must close it (and its cluster)."""
    try:
        from distributed import Client, LocalCluster
    except ImportError:  # pragma: no cover - the extra is installed where dask is asked for
        raise InputError(f"scheduler={scheduler!r} needs dask.distributed: pip install 'thinlayer[afm]' (or "
                         "'dask[distributed]'); scheduler=None runs serially") from None
    if isinstance(scheduler, Client):
        return scheduler, False
    if scheduler in ("threads", "local"):
        import dask

        n = workers or (2 if scheduler == "threads" else _cores())
        config = _cluster_config()
        if scheduler == "local":
            _preload_forkserver(config)
        with dask.config.set(config):
            cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=scheduler == "local",  # ":0": any port
                                   dashboard_address=":0", silence_logs=logging.CRITICAL)
        return Client(cluster, timeout=CONNECT_TIMEOUT), True
    try:
        return Client(scheduler, timeout=CONNECT_TIMEOUT), True
    except OSError as exc:
        raise InputError(f"scheduler {scheduler!r}: no dask scheduler answered within {CONNECT_TIMEOUT:g} s "
                         f"({str(exc).splitlines()[0][:120]}); give a running scheduler's address, 'local' or None")\
            from None


def _cluster_config() -> dict[str, Any]:
    """Dask's settings for a cluster started here (:func:`map_batch`): the start method (:func:`start_method`), no
    statistical profiler (it samples every thread's stack each 10 ms: CPU taken from the tasks, for a dashboard
    nobody sees on a cluster that lives one call), and glibc's own ``malloc`` trimming instead of the nanny's
    ``MALLOC_TRIM_THRESHOLD_=65536`` (which returns every freed heap top above 64 KiB to the system: about 120 page
    faults and 0.5 ms of system CPU per map curve, benchmarks/bench_maps.py).  The BLAS/OpenMP threads stay at the
    nanny's 1 per worker (one worker per core).
    """
    return {"distributed.worker.multiprocessing-method": start_method(),
            "distributed.worker.profile.enabled": False,
            "distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_": None}


def auto_scheduler(n_items: int) -> str | None:
    """What ``scheduler="auto"`` runs ``n_items`` on: ``"local"`` or None (serially); see :data:`AUTO_BATCH`."""
    import importlib.util

    if n_items >= AUTO_BATCH and _cores() > 1 and importlib.util.find_spec("distributed") is not None:
        return "local"
    return None


def start_method() -> str:
    """How a local cluster started here starts its worker processes: ``THINLAYER_DASK_START`` (``fork``, ``spawn``,
    ``forkserver``) when set; else dask's configured method when it is not dask's default ``"spawn"``; else
    ``"forkserver"`` where the platform has it (Linux, macOS), else ``"spawn"``.

    ``forkserver``: one clean server process (no thread, no event loop: none of ``fork``'s hazards; a second forked
    cluster in the same process was seen to hang in ``Client.scatter``) imports :data:`FORKSERVER_PRELOAD` once and
    forks each worker from itself: the workers start with dask, numpy, scipy and thinlayer imported, and exit
    without tearing an interpreter down.  Against ``spawn`` (each worker imports everything again): the same first
    start, a second cluster in the same process 1.0 s instead of 6.0 s, closing 0.3 s instead of 3.0 s (load 10,
    benchmarks/bench_maps.py).
    """
    import os

    asked = os.environ.get("THINLAYER_DASK_START", "")
    if asked in ("fork", "spawn", "forkserver"):
        return asked
    import multiprocessing

    import dask

    configured = str(dask.config.get("distributed.worker.multiprocessing-method", "spawn"))
    if configured != "spawn":
        return configured
    return "forkserver" if "forkserver" in multiprocessing.get_all_start_methods() else "spawn"


def _preload_forkserver(config: dict[str, Any]) -> None:
    """With ``forkserver`` (:func:`start_method`): the server, when this call starts it, imports
    :data:`FORKSERVER_PRELOAD` (dask's own list, set on its first use, is replaced: it has pandas, not thinlayer).
    """
    if config.get("distributed.worker.multiprocessing-method") != "forkserver":
        return
    import dask
    from distributed.utils import get_mp_context

    with dask.config.set(config):
        context = get_mp_context()
    context.set_forkserver_preload(list(FORKSERVER_PRELOAD))


def _cores() -> int:
    import os

    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # pragma: no cover - not Linux
        return max(1, os.cpu_count() or 1)


def check_scheduler(scheduler: Any) -> Any:
    """``scheduler`` if it is one :func:`map_batch` takes, else one line naming the valid ones."""
    if scheduler in SCHEDULERS:
        return scheduler
    if isinstance(scheduler, str):
        if scheduler.startswith(("tcp://", "tls://", "inproc://", "ucx://", "ws://", "wss://")):
            return scheduler
        raise InputError(f"scheduler must be None (serial), 'threads', 'local' (a dask LocalCluster), 'auto' or a "
                         f"dask scheduler address such as 'tcp://host:8786', got {scheduler[:80]!r}")
    if type(scheduler).__name__ == "Client" and type(scheduler).__module__.startswith("distributed"):
        return scheduler
    raise InputTypeError(f"scheduler must be None, 'threads', 'local', 'auto', an address 'tcp://host:8786' or a "
                         f"distributed.Client, got {type(scheduler).__name__}")


def map_batch(func: Callable[[Any], Any], items: Iterable[Any], *, scheduler: Any = None, chunk: int | None = None,
              workers: int | None = None, progress: bool = False, label: str = "items",
              timeout: float | None = None, pack: Callable[[list[Any]], Iterable[Any]] | None = None,
              warm: bool = False, timings: dict[str, float] | None = None) -> list[Any]:
    """``[func(item) for item in items]``, serially or on dask.distributed, in the items' order.

    Parameters
    ----------
    func : callable
        One item to one result.  For a process cluster it must pickle (a module-level function or a
        ``functools.partial`` of one).  Exceptions are the caller's to catch inside ``func`` (a map records a failed
        pixel with its reason): an exception that escapes ``func`` stops the batch and is raised here.
    items : iterable
        The work, one item per call.
    scheduler : None, str or distributed.Client
        ``None`` or ``"serial"``: this process; ``"threads"``: a dask ``LocalCluster`` of threads in this process;
        ``"local"``: a ``LocalCluster`` of worker processes (one per core); ``"tcp://host:port"``: that cluster's
        scheduler; a ``Client``: used as it is (and left open).  A cluster started here is closed before return.
    chunk : int, optional
        Items per dask task (default: about :data:`TASKS_PER_WORKER` tasks per worker, at least 1 item).
    workers : int, optional
        Workers of a cluster started here (default: 2 threads, or one process per core).
    progress : bool
        A progress bar on stderr (tqdm when installed, else a counter).
    label : str
        What the items are, for the progress bar.
    timeout : float, optional
        Seconds to wait for the dask results; past it a :class:`TimeoutError` is raised (and a cluster started here
        closed) instead of waiting for ever.
    pack : callable, optional
        On dask: each chunk (a list of items) is sent as ``pack(chunk)``, an object that iterates over the same items
        in order and pickles in fewer, larger buffers (a force map's curves as one array per chunk: 0.8 s instead of
        5.2 s to send 4,096 curves of 2,000 points, benchmarks/bench_maps.py).  ``func`` sees what the iteration
        gives, on every path (the serial path iterates over the items themselves).
    warm : bool
        On dask: each worker computes ``func(first item)`` once, its result dropped, while the chunks are being sent
        (imports and caches paid then, not by the worker's first chunk).  ``func`` must have no side effect.
    timings : dict, optional
        Filled, on dask, with where the time went (benchmarks/bench_maps.py): wall seconds ``"start"`` (the cluster
        and its client), ``"send"`` (the chunks scattered), ``"compute"`` (until the last result), ``"close"``;
        ``"task_cpu"``, the CPU seconds of the tasks summed over the workers, and ``"worker_cpu"``, the workers'
        process CPU from the send to the last result (the warm-up, receiving the data and dask's own work included);
        ``"workers"``, ``"chunks"``.

    Returns
    -------
    list
        One result per item, in order.

    Examples
    --------
    >>> map_batch(abs, [-1, 2, -3])
    [1, 2, 3]
    """
    items = list(items)
    scheduler = check_scheduler(scheduler)
    if scheduler == "auto":
        scheduler = auto_scheduler(len(items))
    bar = Progress(len(items), progress, label)
    try:
        if scheduler in (None, "serial") or not items:
            out = []
            for item in items:
                out.append(func(item))
                bar.update()
            return out
        tick = {"start": time.perf_counter()}
        client, owned = _client(scheduler, workers)
        try:
            from distributed import as_completed

            tick["send"] = time.perf_counter()
            names = list(client.scheduler_info(n_workers=-1).get("workers", {}))
            if chunk is None:
                chunk = max(1, math.ceil(len(items) / (TASKS_PER_WORKER * max(1, len(names)))))
            parts = chunked(items, int(chunk))
            cpu0 = client.run(time.process_time) if timings is not None else {}
            warming = []
            if warm:  # runs on the workers while the chunks are sent (a worker thread: its event loop stays free)
                warming = [client.submit(_warm, func, items[0], workers=[w], allow_other_workers=False, pure=False)
                           for w in names]
            # the items sent to the workers once, not embedded in the task graph
            data = client.scatter([pack(p) for p in parts] if pack is not None else parts)
            tick["compute"] = time.perf_counter()
            futures = client.map(_run_chunk, [func] * len(parts), data, pure=False)
            order = {f.key: i for i, f in enumerate(futures)}
            results: list[Any] = [None] * len(parts)
            task_cpu = 0.0
            for fut in as_completed(futures, timeout=timeout):
                out, cpu = fut.result()
                results[order[fut.key]] = out
                task_cpu += cpu
                bar.update(len(parts[order[fut.key]]))
            tick["close"] = time.perf_counter()
            for w in warming:  # done long ago; an error there is the chunks' error too, already raised
                w.release()
            if timings is not None:
                cpu1 = client.run(time.process_time)
                timings.update(task_cpu=task_cpu, workers=len(names), chunks=len(parts),
                               worker_cpu=sum(cpu1[w] - cpu0[w] for w in cpu0 if w in cpu1))
            return [r for part in results for r in part]
        finally:
            if owned:
                cluster = getattr(client, "cluster", None)
                client.close()
                if cluster is not None:
                    cluster.close()
            if timings is not None and "close" in tick:
                end = time.perf_counter()
                marks = [tick["start"], tick["send"], tick["compute"], tick["close"], end]
                timings.update({k: b - a for k, a, b in zip(("start", "send", "compute", "close"), marks, marks[1:])})
    finally:
        bar.close()


def _solve_one(kwargs: dict[str, Any]) -> Any:
    from ..contact.solve import solve

    return solve(**kwargs)


def solve_sweep(cases: Iterable[dict[str, Any]], *, scheduler: Any = None, **options: Any) -> list[Any]:
    """:func:`thinlayer.solve` over a parameter sweep: one keyword dictionary per case, through :func:`map_batch`.

    Parameters
    ----------
    cases : iterable of dict
        The keyword arguments of each ``solve()`` call (``punch``, ``layer``, ``H``, ``delta``/``force``, ``model``
        such as ``"direct"``, ...).
    scheduler, **options
        As :func:`map_batch`.

    Returns
    -------
    list
        One ``solve()`` result per case, in order.
    """
    return map_batch(_solve_one, [dict(c) for c in cases], scheduler=scheduler, **options)
