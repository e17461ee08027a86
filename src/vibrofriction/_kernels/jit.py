"""The one place where kernels are compiled (cf. hapsira's ``core/jit.py``).

``VIBROFRICTION_JIT_CACHE=0`` disables the on-disk cache; ``NUMBA_DISABLE_JIT=1``
runs everything as plain Python (for coverage and debugging).
"""

import os

import numba

_CACHE = os.environ.get("VIBROFRICTION_JIT_CACHE", "1") != "0"


def jit(func):
    """Compile ``func`` in nopython mode with the project's settings."""
    return numba.njit(cache=_CACHE, fastmath=False, error_model="numpy")(func)


def jit_inline(func):
    """:func:`jit`, the body inlined into each caller at Numba IR level: for the helpers
    of a hot path, so that splitting a kernel by job costs no call."""
    return numba.njit(cache=_CACHE, fastmath=False, error_model="numpy", inline="always")(func)
