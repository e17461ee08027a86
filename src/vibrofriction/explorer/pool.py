"""Worker processes.

The numba kernels hold the GIL, so every computation of the explorer runs in a process of its own,
off the server's event loop, and tabs do not wait for each other (a separate process serves the
fits, which take tens of seconds).

The processes are the package's one pool (:func:`vibrofriction.parallel.start_pool`): they
die with the server, even when it is killed with SIGKILL.
"""

from __future__ import annotations

import asyncio
import atexit
import os
from collections.abc import Callable
from concurrent.futures import ProcessPoolExecutor
from functools import partial
from typing import Any

from ..parallel import available_cores, start_pool

__all__ = ["run", "run_shared", "shutdown", "warm_up"]

_POOLS: dict[str, ProcessPoolExecutor] = {}
_SIZES = {"curve": max(2, min(4, available_cores())), "fit": 1}


def _pool(kind: str) -> ProcessPoolExecutor:
    if kind not in _POOLS:
        _POOLS[kind] = start_pool(_SIZES[kind])
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


def _ping_curved() -> int:
    from .compute import curve, history
    from .state import State

    sphere = State(points=2, profile_exponent=2.0, axis="V", v_max=0.3)
    curve(sphere)  # the MDR solver's kernels
    history(sphere, 0.3)  # and its history's
    return os.getpid()


def warm_up() -> None:
    """Start the workers and load the kernels in each (the first page then draws at once).

    The MDR solver's kernels (a curved tip) load after, while the page is served (from the disk
    cache the server's warm-up wrote, :func:`vibrofriction.explorer.serve`).
    """
    for kind, size in _SIZES.items():
        futures = [_pool(kind).submit(_ping) for _ in range(size)]
        for f in futures:
            f.result()
    for _ in range(_SIZES["curve"]):
        _pool("curve").submit(_ping_curved)


def shutdown() -> None:
    """Stop the worker processes."""
    for pool in _POOLS.values():
        pool.shutdown(wait=False, cancel_futures=True)
    _POOLS.clear()


atexit.register(shutdown)
