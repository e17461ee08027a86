"""The package's one pool of local worker processes.

Every local parallel computation runs here: sweeps (:func:`run_tasks`), ``vibrofriction
reproduce`` (:func:`run_tasks`), the fit's global search, local starts and profiles
(:func:`mapper`, also a ``workers=`` argument of scipy's optimisers) and the
explorer's long-lived workers (:func:`start_pool`).  The module imports nothing of the
package: it sits below every consumer (``pyproject.toml``, the layers contract).

Workers are started with multiprocessing's ``forkserver`` method (``spawn`` where
there is none), never ``fork``: the calling process may hold threads (zarr's event
loop, Dask, tqdm).  Each worker runs :func:`_init_worker` first: it ignores Ctrl-C
(the parent handles it and cancels the pool), ties its life to the process that
started the pool (below), and loads the compiled kernels.

**No orphans.** A parent killed with SIGKILL runs no clean-up, and a
``ProcessPoolExecutor`` worker blocked on its task queue never notices (it holds a
copy of the queue's write end itself).  So each worker

1. asks the kernel for SIGKILL when its parent dies (``prctl(PR_SET_PDEATHSIG)``,
   Linux).  Under ``forkserver`` that parent is the fork server, not the caller;
2. closes its copy of the fork server's "alive" pipe.  The fork server exits when
   every holder of that pipe has gone (its own protocol); once the workers have let
   go, the caller is the only holder left, so the fork server exits as soon as the
   caller dies, and its death kills the workers (1) at once, even in the middle of a
   compiled kernel that holds the GIL.  The resource tracker then reads end-of-file
   on its pipe (all writers gone) and exits too;
3. runs a watchdog thread that exits the worker when the caller's pid is gone or
   the worker was re-parented: the portable fallback (``spawn``, other systems; it
   runs between kernel calls, since the kernels hold the GIL).

``tests/sweep/test_pool.py`` SIGKILLs a running two-worker sweep, reproduction, map and
long-lived pool and checks that the fork server, the resource tracker and both workers
are gone within seconds.
"""

from __future__ import annotations

import multiprocessing
import os
import signal
import sys
import threading
import time
from collections.abc import Callable, Iterable, Iterator
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool
from contextlib import contextmanager
from typing import Any

import numpy as np

__all__ = ["Map", "Task", "available_cores", "check_workers", "mapper", "process_pool",
           "run_tasks", "start_method", "start_pool"]

#: ``(function, args, done)``: ``function(*args)`` runs in a worker (both must pickle:
#: a module-level function and plain data), ``done(result)`` in the calling process.
Task = tuple[Callable[..., Any], tuple[Any, ...], Callable[[Any], None]]
#: ``map_(function, items)``: the list ``[function(item) for item in items]``.
Map = Callable[[Callable[[Any], Any], Iterable[Any]], list[Any]]

_WATCH_SECONDS = 0.5  # period of the watchdog thread (fallback only)
_PR_SET_PDEATHSIG = 1  # <linux/prctl.h>


def available_cores() -> int:
    """The number of cores this process may run on.

    Returns
    -------
    int
        ``len(os.sched_getaffinity(0))`` (a container's or ``taskset``'s limit), else
        :func:`os.cpu_count`.

    Examples
    --------
    >>> from vibrofriction.parallel import available_cores
    >>> available_cores() >= 1
    True
    """
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # pragma: no cover - not Linux
        return os.cpu_count() or 1


def check_workers(workers: Any, name: str = "workers") -> int:
    """Check a number of worker processes.

    Parameters
    ----------
    workers : int
        The number of processes; 1 runs in this process.
    name : str, optional
        The argument's name, for the error message.

    Returns
    -------
    int
        ``workers`` as a Python int.

    Raises
    ------
    ValueError
        Unless ``workers`` is an integer (not a bool) ``>= 1``.

    Examples
    --------
    >>> from vibrofriction.parallel import check_workers
    >>> check_workers(2)
    2
    >>> check_workers(0)
    Traceback (most recent call last):
    ...
    ValueError: workers must be an integer >= 1 (worker processes; 1 = run in this process), got 0
    """
    if isinstance(workers, bool) or not isinstance(workers, int | np.integer) or workers < 1:
        raise ValueError(f"{name} must be an integer >= 1 (worker processes; 1 = run in "
                         f"this process), got {workers!r}")
    return int(workers)


def start_method() -> str:
    """The multiprocessing start method of the pool.

    Returns
    -------
    str
        ``"forkserver"`` where it exists, else ``"spawn"`` (never ``"fork"``: the calling
        process may hold threads).

    Examples
    --------
    >>> from vibrofriction.parallel import start_method
    >>> start_method() in ("forkserver", "spawn")
    True
    """
    return "forkserver" if "forkserver" in multiprocessing.get_all_start_methods() else "spawn"


# --------------------------------------------------------------------------- in the worker
def _die_with_parent() -> None:
    """Linux: SIGKILL this process when its parent dies (``prctl(PR_SET_PDEATHSIG)``)."""
    if not sys.platform.startswith("linux"):
        return
    import ctypes

    try:
        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(_PR_SET_PDEATHSIG, int(signal.SIGKILL), 0, 0, 0)
    except (OSError, AttributeError):  # pragma: no cover - no prctl: the watchdog remains
        pass


def _release_forkserver() -> None:
    """Close this worker's copy of the fork server's "alive" pipe (see the module doc)."""
    from multiprocessing import forkserver

    server = getattr(forkserver, "_forkserver", None)
    fd = getattr(server, "_forkserver_alive_fd", None)
    if server is not None and isinstance(fd, int):
        try:
            os.close(fd)
        except OSError:  # pragma: no cover
            pass
        server._forkserver_alive_fd = None  # this worker starts no processes itself


def _gone(pid: int) -> bool:
    """Whether process ``pid`` has exited (a zombie counts as exited)."""
    if sys.platform.startswith("linux"):
        try:
            with open(f"/proc/{pid}/stat", "rb") as fh:
                state = fh.read().rsplit(b")", 1)[1].split()[0]
        except (OSError, IndexError):
            return True
        return state in (b"Z", b"X")
    # mypy checks for this (Linux) platform, where the branch above always returns
    if os.name != "posix":  # type: ignore[unreachable]  # pragma: no cover - os.kill would terminate it on Windows
        return False
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return True
    except PermissionError:  # pragma: no cover
        return False
    return False


def _watchdog(caller: int, parent: int) -> None:
    while True:
        time.sleep(_WATCH_SECONDS)
        if os.getppid() != parent or _gone(caller):
            os._exit(1)


def _init_worker(caller: int, warm_up: Callable[[], None] | None) -> None:
    """Initializer of every worker: ignore Ctrl-C, die with the caller, load the kernels."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    parent = os.getppid()
    _die_with_parent()
    _release_forkserver()
    if _gone(caller):
        os._exit(1)
    threading.Thread(target=_watchdog, args=(caller, parent), daemon=True,
                     name="vibrofriction-watchdog").start()
    if warm_up is not None:
        warm_up()


# --------------------------------------------------------------------------- in the caller
def _worker_died() -> RuntimeError:
    """The error for a worker that died (or could not start)."""
    return RuntimeError(
        "a local worker process died. Workers are started with multiprocessing's "
        f"{start_method()!r} method, which imports the main script again: protect "
        "the call with `if __name__ == \"__main__\":`, or use 1 worker to run in "
        "this process")


def start_pool(workers: int, warm_up: Callable[[], None] | None = None
               ) -> ProcessPoolExecutor:
    """A long-lived pool of ``workers`` processes that die with this one.

    The caller owns it and stops it with ``shutdown()``. Workers start on demand (on
    the first tasks).

    Parameters
    ----------
    workers : int
        The number of processes, ``>= 1``.
    warm_up : callable, optional
        A module-level function run once in each worker, before any task, e.g. to load
        the compiled kernels from numba's cache. The caller should run it itself first,
        so that kernels are compiled once and only loaded by workers.

    Returns
    -------
    concurrent.futures.ProcessPoolExecutor
        The pool.

    Examples
    --------
    >>> from vibrofriction.parallel import start_pool
    >>> pool = start_pool(1)
    >>> pool.submit(divmod, 7, 2).result()
    (3, 1)
    >>> pool.shutdown()
    """
    workers = check_workers(workers)
    context = multiprocessing.get_context(start_method())
    return ProcessPoolExecutor(max_workers=workers, mp_context=context,
                               initializer=_init_worker, initargs=(os.getpid(), warm_up))


@contextmanager
def process_pool(workers: int, warm_up: Callable[[], None] | None = None
                 ) -> Iterator[ProcessPoolExecutor]:
    """A :func:`start_pool` for the duration of a ``with`` block.

    Leaving the block waits for the running tasks; leaving it by an exception (Ctrl-C
    included) cancels the tasks not yet started first.

    Parameters
    ----------
    workers : int
        The number of processes, ``>= 1``.
    warm_up : callable, optional
        Run once in each worker first (:func:`start_pool`).

    Yields
    ------
    concurrent.futures.ProcessPoolExecutor
        The pool, shut down when the block ends.

    Examples
    --------
    >>> from vibrofriction.parallel import process_pool
    >>> with process_pool(1) as pool:
    ...     pool.submit(pow, 2, 10).result()
    1024
    """
    pool = start_pool(workers, warm_up)
    try:
        yield pool
    except BaseException:
        pool.shutdown(wait=True, cancel_futures=True)
        raise
    pool.shutdown(wait=True)


@contextmanager
def mapper(workers: int, warm_up: Callable[[], None] | None = None) -> Iterator[Map]:
    """A :data:`Map` over ``workers`` processes.

    Each item is a task of its own (the model's cost varies 10x between items), the
    results come back in the order of the items; the function and the items must
    pickle. Usable as ``differential_evolution(..., workers=map_)``
    (:func:`scipy.optimize.differential_evolution`). A worker that dies raises
    RuntimeError; an exception in a task is raised here and cancels the items not
    started.

    Parameters
    ----------
    workers : int
        The number of processes; 1 maps in this process, without a pool.
    warm_up : callable, optional
        Run once in each worker first (:func:`start_pool`).

    Yields
    ------
    Map
        ``map_(function, items)``: the list ``[function(item) for item in items]``.

    Examples
    --------
    >>> from vibrofriction.parallel import mapper
    >>> with mapper(1) as map_:
    ...     map_(abs, [-1, 2, -3])
    [1, 2, 3]
    """
    if check_workers(workers) == 1:
        yield lambda func, items: [func(item) for item in items]
        return
    with process_pool(workers, warm_up) as pool:

        def map_(func: Callable[[Any], Any], items: Iterable[Any]) -> list[Any]:
            futures: list[Future] = []
            try:  # a worker may die while the items are still being submitted
                futures.extend(pool.submit(func, item) for item in items)
                return [f.result() for f in futures]
            except BrokenProcessPool as exc:
                raise _worker_died() from exc
            finally:
                for f in futures:
                    f.cancel()

        yield map_


def run_tasks(next_task: Callable[[], Task | None], *, workers: int,
              warm_up: Callable[[], None] | None = None, in_flight: int | None = None) -> None:
    """Run tasks on a :func:`process_pool` until ``next_task()`` returns None.

    At most ``in_flight`` tasks (default ``2 * workers``) are submitted at a time, so
    memory is bounded by the tasks, not their number; ``next_task`` is asked again each
    time one finishes (its answer may depend on the results delivered so far).  Each
    task's ``done(result)`` runs in this process, in the order tasks finish.  A worker
    that dies (or cannot start) raises RuntimeError; any exception cancels the rest.

    Parameters
    ----------
    next_task : callable
        Called without arguments: the next :data:`Task` ``(function, args, done)``, or
        None when there is none left.
    workers : int
        The number of processes, ``>= 1``.
    warm_up : callable, optional
        Run once in each worker first (:func:`start_pool`).
    in_flight : int, optional
        The most tasks submitted at a time (default ``2 * workers``).

    Examples
    --------
    >>> from vibrofriction.parallel import run_tasks
    >>> results = []
    >>> tasks = iter([(pow, (2, k), results.append) for k in range(4)])
    >>> run_tasks(lambda: next(tasks, None), workers=1)
    >>> sorted(results)
    [1, 2, 4, 8]
    """
    window = max(1, in_flight or 2 * workers)
    with process_pool(workers, warm_up) as pool:
        running: dict[Future, Callable[[Any], None]] = {}

        def submit() -> bool:
            task = next_task()
            if task is None:
                return False
            func, args, done = task
            running[pool.submit(func, *args)] = done
            return True

        try:
            while len(running) < window and submit():
                pass
            while running:
                finished, _ = wait(list(running), return_when=FIRST_COMPLETED)
                for fut in finished:
                    running.pop(fut)(fut.result())
                while len(running) < window and submit():
                    pass
        except BrokenProcessPool as exc:
            for fut in running:
                fut.cancel()
            raise _worker_died() from exc
        except BaseException:
            for fut in running:
                fut.cancel()
            raise
