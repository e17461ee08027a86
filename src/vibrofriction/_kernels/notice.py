"""A line on stderr while numba compiles the kernels: a first call is never silent.

numba compiles a kernel on its first call in a process unless its disk cache (or the shipped
one, :mod:`.jit`) holds it; a cold start compiles for tens of seconds. This module listens to
numba's compile events (``numba:compile``, emitted only for real compilations, never for
loads from a cache) and, once a compilation has lasted :data:`AFTER` seconds, writes a
line on stderr: the functions compiled so far and the time, until the outermost
compilation ends. Loading from a cache shows nothing. (Standard library only, as every
kernel module: no tqdm here.)

``VIBROFRICTION_COMPILE_NOTICE=0`` turns it off (the test suite does, except where it tests
the notice); :func:`quiet` turns it off inside a block that shows its own progress
(:func:`vibrofriction.warmup.warm_up`).
"""

from __future__ import annotations

import os
import sys
import time
from collections.abc import Iterator
from contextlib import contextmanager

from numba.core import event

#: Seconds of compiling before the bar appears (a load from the cache takes less).
AFTER = 1.0
TEXT = "compiling the solver's kernels, once (later runs load them from disk)"


class _Notice(event.Listener):  # type: ignore[misc]
    """Counts nested compilations; shows a line once the outermost one is slow.

    On a terminal the line is rewritten in place (at most twice a second); elsewhere (a log)
    it is written when it appears and when the compilation ends.
    """

    def __init__(self) -> None:
        self.depth = 0
        self.count = 0
        self.t0 = 0.0
        self.muted = 0
        self.shown = -1.0  # when the line was last written (-1: not yet)

    def on_start(self, ev: event.Event) -> None:
        if self.depth == 0:
            self.t0 = time.perf_counter()
            self.count = 0
            self.shown = -1.0
        self.depth += 1
        self._show(final=False)

    def on_end(self, ev: event.Event) -> None:
        self.depth -= 1
        self.count += 1
        self._show(final=self.depth == 0)

    def _show(self, final: bool) -> None:
        now = time.perf_counter()
        if self.shown < 0.0 and (self.muted or now - self.t0 < AFTER or os.environ.get(
                "VIBROFRICTION_COMPILE_NOTICE", "1") == "0"):
            return
        tty = sys.stderr.isatty()
        if not final and self.shown >= 0.0 and (not tty or now - self.shown < 0.5):
            return
        line = f"{TEXT}: {self.count} functions, {now - self.t0:.0f} s"
        sys.stderr.write(("\r" + line + ("\n" if final else "")) if tty else line + "\n")
        sys.stderr.flush()
        self.shown = now


_NOTICE = _Notice()
_installed = False


def install() -> None:
    """Listen to numba's compilations (once a process; :mod:`.jit` calls it)."""
    global _installed
    if not _installed:
        event.register("numba:compile", _NOTICE)
        _installed = True


@contextmanager
def quiet() -> Iterator[None]:
    """No notice inside the block (it shows its own progress)."""
    _NOTICE.muted += 1
    try:
        yield
    finally:
        _NOTICE.muted -= 1
