"""The one place where kernels are compiled (cf. hapsira's ``core/jit.py``).

``VIBROFRICTION_JIT_CACHE=0`` disables the on-disk cache; ``NUMBA_DISABLE_JIT=1``
runs everything as plain Python (for coverage and debugging).
"""

import os
from collections.abc import Callable
from typing import Any, TypeVar

import numba

F = TypeVar("F", bound=Callable[..., Any])

_CACHE = os.environ.get("VIBROFRICTION_JIT_CACHE", "1") != "0"


def jit(func: F) -> F:
    """Compile ``func`` in nopython mode with the project's settings.

    Typed as returning ``func`` itself: the dispatcher is called as the function it
    compiles, so that mypy checks each call against the kernel's signature."""
    return numba.njit(cache=_CACHE, fastmath=False, error_model="numpy")(func)  # type: ignore[return-value]


def jit_inline(func: F) -> F:
    """:func:`jit`, the body inlined into each caller at Numba IR level: for the helpers
    of a hot path, so that splitting a kernel by job costs no call."""
    return numba.njit(cache=_CACHE, fastmath=False, error_model="numpy",  # type: ignore[return-value]
                      inline="always")(func)
