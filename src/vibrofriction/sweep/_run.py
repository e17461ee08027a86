"""Running the blocks of a plan: in this process, on local cores, or on a Dask cluster.

Whatever runs the blocks, this process is the only writer: it receives each
finished block, writes it to the sink (memory or store) and ticks the progress
bar.  At most a few blocks per worker are in flight, so memory stays bounded
by the block size, not the grid size.  Local cores use the package's one
process pool (:mod:`vibrofriction.parallel`).
"""

from __future__ import annotations

import time
from collections.abc import Callable, Iterable
from typing import Any

import numpy as np

from ..parallel import available_cores, check_workers, run_tasks
from ..warmup import in_cache
from ._compute import compute_block, identity, warm_up
from ._grid import Plan

__all__ = ["available_cores", "check_executor", "run_blocks"]

Deliver = Callable[[int, dict[str, np.ndarray]], None]


def _serial(plan: Plan, todo: Iterable[int], deliver: Deliver) -> None:
    for block in todo:
        deliver(*compute_block(plan, block))


def _local(plan: Plan, todo: list[int], workers: int, deliver: Deliver) -> None:
    queue = iter(todo)

    def next_task():
        block = next(queue, None)
        if block is None:
            return None
        return compute_block, (plan, block), lambda result: deliver(*result)

    run_tasks(next_task, workers=workers, warm_up=warm_up, in_flight=2 * workers)


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
    if workers is not None:
        check_workers(workers)


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
            if n <= 1 or not in_cache(["flat"]):
                warm_up()  # compile once here (or load to solve here): workers load them
            if n <= 1:
                _serial(plan, todo, deliver)
            else:
                _local(plan, todo, n, deliver)
    finally:
        bar.close()
    return time.perf_counter() - start
