"""Running the blocks of a plan: in this process, on local cores, or on a Dask cluster.

Whatever runs the blocks, this process is the only writer: it receives each
finished block, writes it to the sink (memory or store) and ticks the progress
bar.  At most a few blocks per worker are in flight, so memory stays bounded
by the block size, not the grid size.
"""

from __future__ import annotations

import multiprocessing
import os
import signal
import time
from collections.abc import Callable, Iterable
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool
from typing import Any

import numpy as np

from ._compute import compute_block, identity, warm_up
from ._grid import Plan

__all__ = ["available_cores", "check_executor", "run_blocks"]

Deliver = Callable[[int, dict[str, np.ndarray]], None]


def available_cores() -> int:
    """Cores this process may run on (``sched_getaffinity``, else ``os.cpu_count``)."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # pragma: no cover - not Linux
        return os.cpu_count() or 1


def _context():
    methods = multiprocessing.get_all_start_methods()
    return multiprocessing.get_context("forkserver" if "forkserver" in methods else "spawn")


def _worker_init() -> None:
    # Ctrl-C is handled by the parent, which cancels the pool; workers just stop.
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    warm_up()


def _serial(plan: Plan, todo: Iterable[int], deliver: Deliver) -> None:
    for block in todo:
        deliver(*compute_block(plan, block))


def _local(plan: Plan, todo: list[int], workers: int, deliver: Deliver) -> None:
    window = 2 * workers
    queue = iter(todo)
    context = _context()
    with ProcessPoolExecutor(max_workers=workers, mp_context=context,
                             initializer=_worker_init) as pool:
        pending: set[Future] = set()
        try:
            for block in queue:
                pending.add(pool.submit(compute_block, plan, block))
                if len(pending) >= window:
                    break
            while pending:
                finished, pending = wait(pending, return_when=FIRST_COMPLETED)
                for fut in finished:
                    deliver(*fut.result())
                    nxt = next(queue, None)
                    if nxt is not None:
                        pending.add(pool.submit(compute_block, plan, nxt))
        except BrokenProcessPool as exc:
            for fut in pending:
                fut.cancel()
            raise RuntimeError(
                "a local worker process died. Workers are started with multiprocessing's "
                f"{context.get_start_method()!r} method, which imports the main "
                "script again: protect the call with `if __name__ == \"__main__\":`, or "
                "pass workers=1 to run in this process") from exc
        except BaseException:
            for fut in pending:
                fut.cancel()
            raise


def _dask(plan: Plan, todo: list[int], client: Any, deliver: Deliver) -> None:
    from distributed import as_completed

    mine = (plan.version, plan.fingerprint)
    theirs = {tuple(v) for v in client.run(identity).values()}
    if theirs - {mine}:
        raise ValueError(
            f"the Dask workers run vibrofriction {sorted(theirs)} (version, solver "
            f"fingerprint), this process {mine}: install the same version everywhere")
    client.run(warm_up)  # load (or compile) the kernels on every worker first
    nthreads = sum(client.nthreads().values()) or 1
    window = max(4, 3 * nthreads)
    token = plan.token()
    queue = iter(todo)

    def submit(block: int):
        # pure, deterministic key: a resubmitted block (retry, second client) is one task
        return client.submit(compute_block, plan, block, key=f"vibrofriction-{token}-{block}",
                             pure=True, retries=2)

    first = [submit(b) for _, b in zip(range(window), queue, strict=False)]
    stream = as_completed(first)
    try:
        for fut in stream:
            result = fut.result()
            fut.release()
            deliver(*result)
            nxt = next(queue, None)
            if nxt is not None:
                stream.add(submit(nxt))
    except BaseException:
        client.cancel(list(stream.futures))
        raise


def check_executor(client: Any, workers: int | None) -> None:
    """``client`` and ``workers`` are exclusive; ``workers`` is an integer >= 1."""
    if client is not None and workers is not None:
        raise ValueError("give either client (a Dask cluster) or workers (local cores)")
    if workers is not None and (isinstance(workers, bool)
                                or not isinstance(workers, int | np.integer) or workers < 1):
        raise ValueError(f"workers must be an integer >= 1, got {workers!r}")


def run_blocks(plan: Plan, todo: list[int], write: Deliver, *, client: Any = None,
               workers: int | None = None, progress: bool = True,
               initial_points: int = 0) -> float:
    """Compute ``todo`` blocks with the chosen executor; returns the wall time in seconds."""
    from tqdm.auto import tqdm

    check_executor(client, workers)
    seen: set[int] = set()
    bar = tqdm(total=plan.size, initial=initial_points, unit="pt", unit_scale=plan.size >= 10**4,
               desc="sweep", disable=not progress, smoothing=0.1, dynamic_ncols=True)

    def deliver(block: int, values: dict[str, np.ndarray]) -> None:
        if block in seen:  # never write or count a block twice
            return
        write(block, values)
        seen.add(block)
        bar.update(plan.block_size(block))

    start = time.perf_counter()
    try:
        if not todo:
            pass
        elif client is not None:
            _dask(plan, todo, client, deliver)
        else:
            n = min(workers or available_cores(), len(todo))
            if n <= 1:
                warm_up()
                _serial(plan, todo, deliver)
            else:
                warm_up()  # compile (or load) once here, so workers load from disk cache
                _local(plan, todo, n, deliver)
    finally:
        bar.close()
    return time.perf_counter() - start
