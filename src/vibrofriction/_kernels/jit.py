"""The one place where kernels are compiled (cf. hapsira's ``core/jit.py``).

``VIBROFRICTION_JIT_CACHE=0`` disables the on-disk cache; ``NUMBA_DISABLE_JIT=1``
runs everything as plain Python (for coverage and debugging).
"""

import os
from collections.abc import Callable
from typing import Any, TypeVar

import numba
import numpy as np
from numba.core import cgutils, types
from numba.extending import intrinsic, overload

F = TypeVar("F", bound=Callable[..., Any])

_CACHE = os.environ.get("VIBROFRICTION_JIT_CACHE", "1") != "0"


def jit(func: F) -> F:
    """Compile ``func`` in nopython mode with the project's settings.

    Typed as returning ``func`` itself: the dispatcher is called as the function it
    compiles, so that mypy checks each call against the kernel's signature.
    """
    return numba.njit(cache=_CACHE, fastmath=False, error_model="numpy")(func)  # type: ignore[return-value]


def jit_inline(func: F) -> F:
    """:func:`jit`, the body inlined into each caller at Numba IR level: for the helpers
    of a hot path, so that splitting a kernel by job costs no call.
    """
    return numba.njit(cache=_CACHE, fastmath=False, error_model="numpy",  # type: ignore[return-value]
                      inline="always")(func)


def stack_matrix(rows: int, cols: int) -> np.ndarray:
    """An uninitialised float matrix ``(rows, cols)`` for scratch work that does not outlive
    the function that asks for it.

    Compiled, with literal ``rows`` and ``cols``, it lives on that function's stack (no heap
    allocation: ~40 ns saved per call of a hot kernel); it must not be returned or stored.
    As plain Python (``NUMBA_DISABLE_JIT=1``) it is ``np.empty``.
    """
    return np.empty((rows, cols))


@intrinsic
def _stack_f64(typingctx, size):  # type: ignore[no-untyped-def]
    """A pointer to ``size`` (a literal) float64 on the caller's stack."""
    if not isinstance(size, types.IntegerLiteral):
        return None
    n = size.literal_value

    def codegen(context, builder, signature, args):  # type: ignore[no-untyped-def]
        return cgutils.alloca_once(builder, context.get_value_type(types.float64), size=n)

    return types.CPointer(types.float64)(size), codegen


@overload(stack_matrix, inline="always")
def _stack_matrix(rows, cols):  # type: ignore[no-untyped-def]
    if not (isinstance(rows, types.IntegerLiteral) and isinstance(cols, types.IntegerLiteral)):
        return None
    shape = (rows.literal_value, cols.literal_value)
    size = shape[0] * shape[1]

    def impl(rows, cols):  # type: ignore[no-untyped-def]
        return numba.carray(_stack_f64(size), shape)  # type: ignore[call-arg]

    return impl
