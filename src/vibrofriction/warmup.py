"""Compile the solver's kernels before they are needed: ``vibrofriction warmup``.

numba compiles each kernel on its first call and caches the machine code on disk; the
first call of a fresh install therefore waits for the compiler (about a minute for every
kernel on one core) unless the kernels come precompiled (a wheel built by ``make dist``
ships them, :mod:`vibrofriction._kernels.jit`). :func:`warm_up` compiles (or loads) the
kernels of the parts named, with a progress bar, on several cores at once: for images, CI
and the commands that must not wait in the middle of their work (``reproduce``,
``explore``). :func:`build_shipped` makes the shipped cache; :func:`refresh_shipped` makes
it only where it is missing or older than the kernels' sources (``make warmup``: built once,
then loaded by the warm-up, the tests and the wheel's test).

The parts (:data:`PARTS`): ``flat`` (the flat punch's event-driven solver, every regime,
damping and a longitudinal in-plane drive), ``plane`` (the 2-D solver of a transverse
drive), ``curved`` (the MDR solver of a curved tip), ``rate_state`` (the rate-and-state
solver), ``histories`` (the time histories of the event-driven, 2-D, MDR and
rate-and-state solvers) and ``gradients`` (the parameter sensitivities the bench's fit uses).
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path

__all__ = ["PARTS", "WarmUp", "build_shipped", "in_cache", "refresh_shipped", "shipped_is_fresh",
           "warm_up"]


def _flat() -> None:
    from .solver.engine import solve_points

    solve_points(0.5, 2.0, 0.5, 0.3)
    solve_points(1.0, float("inf"), 1.5, 0.3)  # case IV, jumping
    solve_points(0.5, 2.0, 0.5, -0.3, 0.05, 0.1, 0.5, 1.0)  # damped, in-plane, V < 0


def _plane() -> None:
    from .params import Dimensionless
    from .solver.engine import solve_chain, solve_points
    from .solver.points import table_of
    from .solver.settings import DEFAULT_SETTINGS

    solve_points(0.5, 2.0, 0.5, 0.3, 0.05, 0.0, 0.0, 0.0, 0.5, 1.0)
    # a continuation's compiled loop (its points from whole 2-D orbits)
    solve_chain(table_of(Dimensionless(0.5, 2.0, 0.5, a_y=0.5), [0.3, 0.35]), "sliding",
                DEFAULT_SETTINGS)


def _curved() -> None:
    from .solver.engine import solve_points
    from .solver.mdr import mdr_row

    solve_points(0.5, 2.0, 0.5, 0.3, profile_exponent=2.0)  # the row without springs
    mdr_row(0.5, 2.0, 0.5, 0.3, 2.0, 20)  # a row of springs (histories, n_springs)


def _rate_state() -> None:
    from .solver.engine import solve_points

    solve_points(0.5, 2.0, 0.5, 0.3, rs_a=0.05, rs_b=0.03)


def _histories() -> None:
    from .params import Dimensionless
    from .solver.history import simulate

    simulate(Dimensionless(0.5, 2.0, 0.5), v_inertial=0.3, periods=1, samples_per_period=8)
    simulate(Dimensionless(0.5, 2.0, 0.5, a_y=0.5), v_inertial=0.3, periods=1,
             samples_per_period=8)
    simulate(Dimensionless(0.5, 2.0, 0.5, profile_exponent=2.0), v_inertial=0.3, periods=1,
             samples_per_period=8, springs=64)
    simulate(Dimensionless(0.5, 2.0, 1.5, rs_a=0.05, rs_b=0.03), v_inertial=0.3, periods=1,
             samples_per_period=8)


def _gradients() -> None:
    from .solver.sensitivity import solve_gradients

    solve_gradients(0.5, 2.0, 0.5, 0.3)


#: The parts a warm-up can compile, by name, in the order :func:`warm_up` runs them.
PARTS: dict[str, Callable[[], None]] = {
    "flat": _flat, "plane": _plane, "curved": _curved, "rate_state": _rate_state,
    "histories": _histories, "gradients": _gradients}
#: A kernel of each part (module of ``_kernels``, name): found in a disk cache, the part is
#: taken to be there (loaded here, no pool started)
_MARKS = {"flat": ("steady", "steady_state_many"), "plane": ("plane", "plane_steady_state_many"),
          "curved": ("mdr", "steady_row"), "rate_state": ("rate_state", "rs_steady_state_many"),
          "histories": ("integrate", "run_periods"),
          "gradients": ("sensitivity", "orbit_sensitivity_many")}


def in_cache(parts: Sequence[str] | None = None) -> bool:
    """Whether a disk cache holds every part of ``parts`` (default all).

    A process that needs them then loads them: nothing is compiled.

    Examples
    --------
    >>> from vibrofriction._kernels.jit import caching
    >>> from vibrofriction.warmup import in_cache, warm_up
    >>> _ = warm_up(["flat"], workers=1, progress=False)
    >>> in_cache(["flat"]) == caching()  # once compiled, cached wherever caching is on
    True
    """
    return all(_cached(name) for name in _checked(parts))


def _cached(name: str) -> bool:
    import importlib

    from ._kernels.jit import cached

    module, kernel = _MARKS[name]
    return cached(getattr(importlib.import_module(f"._kernels.{module}", __package__), kernel))


@dataclass(frozen=True)
class WarmUp:
    """What :func:`warm_up` did.

    Attributes
    ----------
    parts : tuple of str
        The parts, in :data:`PARTS`'s order.
    compiled : int
        Functions numba compiled (0: every kernel came from a cache).
    seconds : float
        Wall time.
    workers : int
        Processes that compiled (1 where every part was in a disk cache already).
    """

    parts: tuple[str, ...]
    compiled: int
    seconds: float
    workers: int


@contextmanager
def _counting() -> Iterator[list[int]]:
    """``[n]``: the functions numba compiles inside the block (a load from a cache is none)."""
    from numba.core import event

    count = [0]

    class Count(event.Listener):  # type: ignore[misc]
        def on_start(self, ev: event.Event) -> None:
            pass

        def on_end(self, ev: event.Event) -> None:
            count[0] += 1

    listener = Count()
    event.register("numba:compile", listener)
    try:
        yield count
    finally:
        event.unregister("numba:compile", listener)


def _run_part(name: str) -> int:
    """Compile one part in this process; the functions compiled."""
    from ._kernels import notice

    with _counting() as count, notice.quiet():
        PARTS[name]()
    return count[0]


def _checked(parts: Sequence[str] | None) -> tuple[str, ...]:
    if parts is None:
        return tuple(PARTS)
    if isinstance(parts, str):
        parts = [parts]
    unknown = [p for p in parts if p not in PARTS]
    if unknown or not parts:
        raise ValueError(f"parts must be among {', '.join(PARTS)}, "
                         f"got {', '.join(parts) or 'none'}")
    return tuple(p for p in PARTS if p in parts)


def warm_up(parts: Sequence[str] | None = None, *, workers: int | None = None,
            progress: bool = True) -> WarmUp:
    """Compile (or load from the disk caches) the kernels of ``parts`` in this process.

    Parameters
    ----------
    parts : sequence of str, optional
        Names from :data:`PARTS`; default all.
    workers : int, optional
        Processes that compile parts side by side first (the package's pool,
        :mod:`vibrofriction.parallel`), each writing numba's disk cache, which this process
        then loads; default ``min(2, available cores)``; ``1`` compiles here. Where a disk
        cache already holds every part, or without one (``VIBROFRICTION_JIT_CACHE=0``),
        everything happens here, in this process.
    progress : bool, optional
        A progress bar on stderr (a part a step).

    Returns
    -------
    WarmUp
        The parts, the functions compiled, the time taken.

    Examples
    --------
    >>> from vibrofriction.warmup import warm_up
    >>> done = warm_up(["flat"], workers=1, progress=False)
    >>> done.parts
    ('flat',)
    """
    from tqdm.auto import tqdm

    from ._kernels.jit import caching
    from .parallel import available_cores, check_workers, run_tasks

    t0 = time.perf_counter()
    names = _checked(parts)
    workers = min(2, available_cores()) if workers is None else check_workers(workers)
    workers = min(workers, len(names)) if caching() else 1
    if workers > 1 and in_cache(names):
        workers = 1  # a load: a pool would only cost its start
    compiled = 0

    def done(n: int) -> None:
        nonlocal compiled
        compiled += n
        bar.update(1)
        bar.set_postfix_str(f"{compiled} functions compiled")

    with tqdm(total=len(names), desc="the solver's kernels (compiled once, then loaded from "
              "disk)", unit=" part", disable=not progress, file=sys.stderr,
              bar_format="{desc}: {n}/{total} parts [{elapsed}]{postfix}") as bar:
        if workers > 1:
            tasks = iter([(_run_part, (name,), done) for name in names])
            run_tasks(lambda: next(tasks, None), workers=workers)
        else:
            for name in names:
                done(_run_part(name))
    if workers > 1:  # load here what the workers wrote (or compile what they could not)
        for name in names:
            compiled += _run_part(name)
    return WarmUp(names, compiled, time.perf_counter() - t0, workers)


def build_shipped(dest: Path | str | None = None, *, workers: int | None = None) -> int:
    """Compile every part for the shipped cache's CPU target into ``dest``.

    The compilation runs in fresh processes with ``NUMBA_CPU_NAME`` set to
    :data:`~vibrofriction._kernels.jit.SHIPPED_CPU` (no other feature) and an empty
    ``NUMBA_CACHE_DIR``; the cache files are then gathered into ``dest`` (emptied first;
    default the package's ``_kernels/_shipped``, where :mod:`vibrofriction._kernels.jit`
    looks). ``make dist`` runs it before building the wheel. Returns the number of files.
    """
    from ._kernels.jit import SHIPPED, SHIPPED_CPU

    cpu = SHIPPED_CPU
    dest = SHIPPED if dest is None else Path(dest)
    if dest.exists():  # not loaded from while it is made
        shutil.rmtree(dest)
    with tempfile.TemporaryDirectory() as tmp:
        env = {**os.environ, "NUMBA_CPU_NAME": cpu, "NUMBA_CPU_FEATURES": "",
               "NUMBA_CACHE_DIR": tmp, "VIBROFRICTION_JIT_CACHE": "1"}
        code = ("from vibrofriction.warmup import warm_up; "
                f"warm_up(workers={workers!r}, progress=True)")
        subprocess.run([sys.executable, "-c", code], env=env, check=True)
        dest.mkdir(parents=True)
        n = 0
        for path in Path(tmp).rglob("*.nb[ic]"):
            shutil.copy2(path, dest / path.name)
            n += 1
    (dest / _COMPLETE).write_text(f"{n} files\n")
    return n


#: The file :func:`build_shipped` writes last: the cache is whole, and as old as this file.
_COMPLETE = ".complete"


def shipped_is_fresh(dest: Path | str | None = None) -> bool:
    """Whether the shipped cache in ``dest`` (default the package's) is whole and fresh.

    Fresh: newer than every source file the compiled code comes from, the kernels'
    (``_kernels``) and the schema's, whose column indices they read as constants (numba
    itself checks only each kernel's own file).
    """
    from ._kernels.jit import SHIPPED

    stamp = (SHIPPED if dest is None else Path(dest)) / _COMPLETE
    if not stamp.is_file():
        return False
    package = Path(__file__).resolve().parent
    newest = max(p.stat().st_mtime for folder in _COMPILED_FROM
                 for p in (package / folder).rglob("*.py"))
    return stamp.stat().st_mtime >= newest


#: The package's folders the compiled kernels are made from (their imports: ``_kernels``
#: imports nothing of the package but the schema)
_COMPILED_FROM = ("_kernels", "schema")


def refresh_shipped(*, workers: int | None = None) -> bool:
    """:func:`build_shipped` into the package's folder, unless it is fresh there.

    Only on a machine that runs its code; where it is fresh (:func:`shipped_is_fresh`),
    nothing. Returns whether the shipped cache serves this machine.
    """
    from ._kernels.jit import runs_shipped

    if not runs_shipped():
        return False
    if not shipped_is_fresh():
        build_shipped(workers=workers)
    return True
