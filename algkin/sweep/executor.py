"""Where a sweep's chunks are evaluated: in this process, or on Dask distributed.

``serial`` runs each chunk here. ``dask`` starts a ``LocalCluster`` of worker processes (one
thread each) on this machine, or connects to the scheduler at an address (a cluster started
with ``dask scheduler`` and ``dask worker``, on other machines); either way each chunk is one
task, and its rows come back here, where they are written (``done``): the workers write no
file. The scheduler and the workers unpickle each chunk's job (the scene, the analyses), so
they need algkin too; each worker checks that its algkin is this process's version, and a
chunk that fails on the cluster (not a design: a design's failure is its row) stops the run
in one line. The cluster this module started is closed however the run ends (an error,
Ctrl-C as the command line's exception): its worker processes are stopped and joined. dask
and distributed (the ``sweep`` extra) are imported only here, only for a Dask run.
"""

from __future__ import annotations

import contextlib
import logging
import multiprocessing
import signal
import sys
import threading
import warnings
from collections.abc import Callable, Iterator, Sequence
from typing import Any

from ..errors import AlgkinError, ComputationError, UsageError
from ..runtime.cache import BoundedCache
from ..runtime.stopping import raise_if_stopped
from .design import Job, evaluate_chunk
from .family import Family

__all__ = ["EXECUTORS", "run_chunks", "on_worker", "dask_modules", "dask_setup"]

EXECUTORS = ("dask", "serial")
CONNECT_SECONDS = 10  # how long to wait for the scheduler at --scheduler ADDRESS
FAMILIES = 2  # jobs' families a process keeps at once
_TRACKER_WARNING = "ignore:resource_tracker:UserWarning"  # the tracker's warnings start with its name
# Ctrl-C and a terminal's hang-up reach the whole process group, the workers too.
GROUP_SIGNALS = frozenset({signal.SIGINT, signal.SIGHUP})
# Above every level: the scheduler logs at CRITICAL (with a traceback) each message it cannot send to
# workers a signal to the group has just ended, lines of its own beside the command's one.
_SILENT = logging.CRITICAL + 1


def run_chunks(job: Job, chunks: Sequence[tuple[int, list]], done: Callable[[int, list], None],
               executor: str = "dask", workers: int | None = None, scheduler: str | None = None,
               ready: Callable[[], None] = lambda: None) -> None:
    """Evaluate every ``(index, designs)`` chunk and hand each one's rows to ``done(index, rows)`` as it ends;
    ``ready()`` first, once the executor is (a scheduler that cannot be reached: nothing written).
    On Dask, each worker's algkin must be this process's version."""
    if executor == "serial":
        ready()
        families = _families()
        for index, designs in chunks:
            done(*evaluate_chunk(job, index, designs, families))
            raise_if_stopped()
        return
    version = _version()
    with _client(workers, scheduler) as (client, as_completed):
        ready()
        futures = {client.submit(on_worker, version, job, index, designs, pure=False): index
                   for index, designs in chunks}
        for future in as_completed(futures):
            try:
                rows = future.result()
            except AlgkinError:
                raise  # ours, said in one line (a worker's algkin of another version)
            except Exception as err:  # noqa: BLE001 - the cluster's failure, said in one line, not its traceback
                raise ComputationError(f"chunk {futures[future]} failed on the Dask cluster: "
                                       f"{type(err).__name__}: {' '.join(str(err).split())}") from None
            done(*rows)
            # a signal's exception raised in one of Dask's finalisers is printed and dropped there
            raise_if_stopped()


def on_worker(version: str, job: Job, index: int, designs: Sequence[tuple[int, Any]]) -> tuple[int, list]:
    """A chunk evaluated by a Dask worker (``evaluate_chunk``), once this process's algkin is found to be
    ``version`` (ComputationError if not) and allowed children.

    ``dask worker`` starts daemonic worker processes, which multiprocessing refuses children lest
    they outlive them; the child a design's budget runs in (and an interpolation's second prime)
    cannot: the kernel ends it with its parent (``algkin.runtime.child.bind_to_parent``), and the
    parent kills and joins it however the design ends."""
    found = _version()
    if found != version:
        from distributed import get_worker

        raise ComputationError(f"the Dask worker at {get_worker().address} has algkin {found}, this command "
                               f"{version}: every worker needs the same version")
    process = multiprocessing.current_process()
    if process.daemon:
        process.daemon = False
    from distributed import get_worker

    # the worker keeps, for the chunks it runs after this one, what the job's designs share
    worker = get_worker()
    families = getattr(worker, "algkin_families", None)
    if families is None:
        families = _families()
        setattr(worker, "algkin_families", families)  # noqa: B010 - an attribute of ours on dask's Worker
    return evaluate_chunk(job, index, designs, families)


def _families() -> BoundedCache[Family | None]:
    """Where a process keeps the families of the jobs it runs (a sweep runs one)."""
    return BoundedCache(FAMILIES, name="sweep families")


def _version() -> str:
    # the package's version from the facade, loaded before any of its subpackages (importing it
    # here would be an import of the facade's lazy names, the layers above, for the linter)
    return str(sys.modules["algkin"].__version__)


def dask_modules() -> tuple[Any, Any]:
    try:
        import dask
        import distributed
    except ImportError:
        raise UsageError("executor", "dask", "needs the sweep extra: pip install 'algkin[sweep]' "
                                               "(or the serial executor)") from None
    return dask, distributed


@contextlib.contextmanager
def _client(workers: int | None, scheduler: str | None) -> Iterator[tuple[Any, Any]]:
    """A Dask client on a LocalCluster of ``workers`` processes, or on the scheduler at ``scheduler``;
    everything it started closed when the block ends."""
    dask, distributed = dask_modules()
    # Each worker of our LocalCluster runs this module's dask_setup as it starts.
    settings = {"distributed.admin.tick.limit": "1h",
                "logging.distributed": "critical", "distributed.worker.preload": [__name__]}
    with dask.config.set(settings), _quiet_logs(), warnings.catch_warnings(), contextlib.ExitStack() as stack:
        warnings.simplefilter("ignore")  # dask's warnings are no line of ours on stderr either
        if scheduler is None:
            _start_resource_tracker()
            # no dashboard, and the scheduler's HTTP server (health checks) on a free local port:
            # its default, 8787, is taken by any other cluster on the machine
            with _held(GROUP_SIGNALS):
                cluster = stack.enter_context(distributed.LocalCluster(
                    n_workers=workers, threads_per_worker=1, processes=True, host="127.0.0.1", dashboard_address=None,
                    scheduler_kwargs={"dashboard": False, "dashboard_address": "127.0.0.1:0"},
                    silence_logs=_SILENT))
            client = stack.enter_context(distributed.Client(cluster))
        else:
            try:
                client = stack.enter_context(distributed.Client(scheduler, timeout=CONNECT_SECONDS))
            except (OSError, TimeoutError, ValueError, TypeError) as err:  # TypeError: tls:// without its context
                raise UsageError("scheduler", scheduler, f"cannot connect: {' '.join(str(err).split())}") from None
        yield client, distributed.as_completed


@contextlib.contextmanager
def _held(signals: frozenset[signal.Signals]) -> Iterator[None]:
    """``signals`` blocked in this thread while the block runs, then delivered here if they came.

    The threads started meanwhile (the cluster's event loop, which spawns its worker processes)
    keep them blocked, and so do those processes from their first instruction: a Ctrl-C to the
    process group while a worker still imports distributed (a second or more, before ``dask_setup``
    ignores it) waits for the worker to ignore it instead of printing its KeyboardInterrupt traceback.
    This thread answers it once the cluster is up, by closing it."""
    found = signal.pthread_sigmask(signal.SIG_BLOCK, signals)
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, found)


def _start_resource_tracker() -> None:
    """Start multiprocessing's resource tracker (once a process: the workers' queues register their
    semaphores with it) with SIGHUP ignored, as it ignores SIGINT and SIGTERM itself: a hang-up
    that reaches the process group would kill it, and the one started in its place print a
    ``KeyError`` traceback for each semaphore it never saw."""
    from multiprocessing import resource_tracker

    with _tracker_quiet():
        if threading.current_thread() is not threading.main_thread():
            resource_tracker.ensure_running()
            return
        found = signal.signal(signal.SIGHUP, signal.SIG_IGN)  # for the few milliseconds of a fork and exec
        try:
            resource_tracker.ensure_running()
        finally:
            signal.signal(signal.SIGHUP, found)


@contextlib.contextmanager
def _tracker_quiet() -> Iterator[None]:
    """The resource tracker started meanwhile has its ``resource_tracker: There appear to be N leaked
    semaphore objects to clean up`` warning silenced (passed on as a ``-W`` option): a SIGTERM to the
    group ends the workers before they let go of their semaphores, and the tracker, which removes them
    as it should, said so in two lines of its own after the command's one."""
    sys.warnoptions.append(_TRACKER_WARNING)
    try:
        yield
    finally:
        sys.warnoptions.remove(_TRACKER_WARNING)


def dask_setup(worker: Any) -> None:
    """Run by each worker of our LocalCluster as it starts (Dask's preload): SIGINT and SIGHUP
    ignored. Ctrl-C and a terminal's hang-up reach the whole process group; the command line
    stops (one line) and closes the cluster, which ends its workers (by SIGTERM), where each
    would otherwise print a ``KeyboardInterrupt`` traceback, or die leaving its semaphores to
    multiprocessing's resource tracker, which prints one traceback each."""
    for signum in GROUP_SIGNALS:
        signal.signal(signum, signal.SIG_IGN)


@contextlib.contextmanager
def _quiet_logs() -> Iterator[None]:
    """Dask's loggers quiet while the run lasts (its closing chatter is no line of ours on stderr)."""
    loggers = [logging.getLogger(n) for n in ("distributed", "dask", "tornado", "asyncio")]
    levels = [g.level for g in loggers]
    for g in loggers:
        g.setLevel(_SILENT)
    try:
        yield
    finally:
        for g, level in zip(loggers, levels):
            g.setLevel(level)
