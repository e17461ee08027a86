"""The one place where kernels are compiled (cf. hapsira's ``core/jit.py``).

Compiled code is cached on disk by numba (next to the sources, or in the user's cache
folder where the package is read-only), and looked up in a second place when numba's
cache has no entry: the **shipped cache**, ``_kernels/_shipped/``, which a wheel built by
``make dist`` carries (:func:`vibrofriction.warmup.build_shipped`). Its kernels are
compiled for the x86-64-v3 level of the x86-64 psABI (the AVX2/FMA machines of the last
decade; its code runs as fast as code compiled for the machine itself), so they load on any
such machine with the Python and numba versions they were compiled with; elsewhere the
kernels compile as usual. numba's own entries, compiled for the machine itself, come
first. An entry is used only if the kernel's source file and bytecode are those it was
compiled from (numba's checks), so a stale entry is never used.

``VIBROFRICTION_JIT_CACHE=0`` disables both caches, ``VIBROFRICTION_SHIPPED_CACHE=0`` the
shipped one only (the kernels then compile for the machine itself); ``NUMBA_DISABLE_JIT=1``
runs everything as plain Python (for coverage and debugging).
"""

import functools
import os
from collections.abc import Callable
from pathlib import Path
from typing import Any, TypeVar

import numba
import numpy as np
from numba.core import cgutils, types
from numba.core.caching import FunctionCache, IndexDataCacheFile
from numba.extending import intrinsic, overload

from . import notice

F = TypeVar("F", bound=Callable[..., Any])

_CACHE = os.environ.get("VIBROFRICTION_JIT_CACHE", "1") != "0"
_SHIPPED = os.environ.get("VIBROFRICTION_SHIPPED_CACHE", "1") != "0"
#: The shipped cache's folder (absent in a source checkout until ``make dist``).
SHIPPED = Path(__file__).resolve().parent / "_shipped"
#: The CPU target of the shipped cache's code (LLVM's name; its features implied by it).
SHIPPED_CPU = "x86-64-v3"
#: What x86-64-v3 requires of a machine (LLVM's feature names, v2's included).
_V3 = ("avx", "avx2", "bmi", "bmi2", "f16c", "fma", "lzcnt", "movbe", "xsave", "cx16",
       "popcnt", "sahf", "sse3", "sse4.1", "sse4.2", "ssse3")


def runs_shipped() -> bool:
    """Whether this machine runs the shipped cache's code (and it is not switched off)."""
    return _runs_shipped()


@functools.cache
def _runs_shipped() -> bool:
    """Whether this machine runs the shipped cache's code (x86-64 with every v3 feature)."""
    import platform

    from llvmlite import binding  # type: ignore[import-untyped]

    if not _SHIPPED or platform.machine().lower() not in ("x86_64", "amd64"):
        return False
    features = binding.get_host_cpu_features()
    return all(features.get(f, False) for f in _V3)


notice.install()


class _Cache(FunctionCache):
    """numba's on-disk cache, then the shipped one (a read-only folder)."""

    def __init__(self, py_func: Callable[..., Any]) -> None:
        super().__init__(py_func)
        self._shipped = IndexDataCacheFile(cache_path=str(SHIPPED),
                                           filename_base=self._impl.filename_base,
                                           source_stamp=self._cache_file._source_stamp)

    def _load_overload(self, sig: Any, target_context: Any) -> Any:
        data = super()._load_overload(sig, target_context)
        if data is None and self._enabled and SHIPPED.is_dir() and _runs_shipped():
            sig_, machine, code = self._index_key(sig, target_context.codegen())
            data = self._shipped.load((sig_, (machine[0], SHIPPED_CPU, ""), code))
            if data is not None:
                data = self._impl.rebuild(target_context, data)
        return data


def cached(kernel: Callable[..., Any]) -> bool:
    """Whether a disk cache (numba's, or the shipped one on a machine it serves) holds
    compiled code of ``kernel``, for any signature (an index look-up, nothing compiled).
    """
    cache = getattr(kernel, "_cache", None)
    if not isinstance(cache, _Cache):
        return False
    return bool(cache._cache_file._load_index()) or (
        SHIPPED.is_dir() and _runs_shipped() and bool(cache._shipped._load_index()))


def caching() -> bool:
    """Whether compiled kernels are cached on disk (``VIBROFRICTION_JIT_CACHE``)."""
    return _CACHE


def _compiled(func: F, **options: Any) -> F:
    dispatcher = numba.njit(cache=False, fastmath=False, error_model="numpy", **options)(func)
    if _CACHE and hasattr(dispatcher, "py_func"):  # not a plain function (NUMBA_DISABLE_JIT)
        dispatcher._cache = _Cache(dispatcher.py_func)
    return dispatcher  # type: ignore[no-any-return]


def jit(func: F) -> F:
    """Compile ``func`` in nopython mode with the project's settings.

    Typed as returning ``func`` itself: the dispatcher is called as the function it
    compiles, so that mypy checks each call against the kernel's signature.
    """
    return _compiled(func)


def jit_bare(func: F) -> F:
    """:func:`jit` without numba's reference counting (NRT) in the function's own body: for
    the step loops of a hot path, whose array arguments and views would otherwise each
    cost two atomic operations a use (measured: a third of the 2-D solver's time).  The
    function must not allocate (``np.empty`` and the like need the NRT): its scratch comes
    from its caller.
    """
    return _compiled(func, _nrt=False)


def jit_inline(func: F) -> F:
    """:func:`jit`, the body inlined into each caller at Numba IR level: for the helpers
    of a hot path, so that splitting a kernel by job costs no call.
    """
    return _compiled(func, inline="always")


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
