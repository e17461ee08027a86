"""Worker processes: the numba kernels hold the GIL, so every computation of the explorer
runs in a process of its own, off the server's event loop, and tabs do not wait for each
other (a separate process serves the fits, which take tens of seconds)."""

from __future__ import annotations

import asyncio
import atexit
import multiprocessing
import os
from collections.abc import Callable
from concurrent.futures import ProcessPoolExecutor
from functools import partial
from typing import Any

__all__ = ["run", "run_shared", "shutdown", "warm_up"]

_POOLS: dict[str, ProcessPoolExecutor] = {}
_SIZES = {"curve": max(2, min(4, os.cpu_count() or 2)), "fit": 1}


def _watch_parent(parent: int) -> None:
    """In a worker: exit when the server is gone (killed without shutting its pool)."""
    import threading
    import time

    def watch() -> None:
        while os.getppid() == parent:
            time.sleep(1.0)
        os._exit(0)

    threading.Thread(target=watch, daemon=True).start()


def _pool(kind: str) -> ProcessPoolExecutor:
    if kind not in _POOLS:
        _POOLS[kind] = ProcessPoolExecutor(_SIZES[kind],
                                           mp_context=multiprocessing.get_context("spawn"),
                                           initializer=_watch_parent, initargs=(os.getpid(),))
    return _POOLS[kind]


async def run(func: Callable[..., Any], *args: Any, kind: str = "curve") -> Any:
    """``func(*args)`` in a worker process, awaited without blocking the event loop."""
    loop = asyncio.get_running_loop()
    return await loop.run_in_executor(_pool(kind), func, *args)


async def run_shared(func: Callable[..., Any], merge: Callable[[list], Any],
                     *args: Any) -> Any:
    """``func(*args, part=(i, n))`` for the ``n`` curve workers at once, merged."""
    n = _SIZES["curve"]
    loop = asyncio.get_running_loop()
    parts = [loop.run_in_executor(_pool("curve"), partial(func, *args, part=(i, n)))
             for i in range(n)]
    return merge(list(await asyncio.gather(*parts)))


def _ping() -> int:
    from .compute import curve
    from .state import State

    curve(State(points=8))  # loads the compiled kernels
    return os.getpid()


def warm_up() -> None:
    """Start the workers and load the kernels in each (the first page then draws at once)."""
    for kind, size in _SIZES.items():
        futures = [_pool(kind).submit(_ping) for _ in range(size)]
        for f in futures:
            f.result()


def shutdown() -> None:
    """Stop the worker processes."""
    for pool in _POOLS.values():
        pool.shutdown(wait=False, cancel_futures=True)
    _POOLS.clear()


atexit.register(shutdown)
