"""The one parameter validator of the package.

Every public entry point (parameters, closed forms, solver, sweep grids, figures)
checks its inputs through :func:`checked` and :func:`checked_beta`, so that a bad
value is refused with the same sentence everywhere: the parameter's name, the
allowed range and the first offending value.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["as_float_or_array", "checked", "checked_beta", "range_text"]

FloatOrArray = float | NDArray[np.float64]


def range_text(minimum: float | None = None, strict: bool = False,
               maximum: float | None = None, allow_inf: bool = False) -> str:
    """The allowed range in words, e.g. ``"finite and > 0"``."""
    if minimum is not None and maximum is not None:
        text = f"in {'(' if strict else '['}{minimum:g}, {maximum:g}]"  # maximum inclusive
    elif minimum is not None:
        text = f"{'>' if strict else '>='} {minimum:g}"
    else:
        return "a number (not nan)" if allow_inf else "finite"
    return f"{text} (math.inf allowed)" if allow_inf else f"finite and {text}"


def checked(name: str, value: ArrayLike, *, minimum: float | None = None,
            strict: bool = False, maximum: float | None = None,
            allow_inf: bool = False) -> NDArray[np.float64]:
    """``value`` as a float array, or ValueError naming ``name``, the range and a bad value.

    ``minimum`` is exclusive when ``strict``; ``maximum`` is inclusive; ``allow_inf``
    admits ``+inf`` (a rigid contact, ``beta = inf``) but never ``nan``.
    """
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a number or an array of numbers, "
                         f"got {value!r}") from None
    bad = np.isnan(arr)
    if not allow_inf:
        bad |= np.isinf(arr)
    with np.errstate(invalid="ignore"):
        if minimum is not None:
            bad |= (arr <= minimum) if strict else (arr < minimum)
        if maximum is not None:
            bad |= arr > maximum
    if np.any(bad):
        first = float(np.atleast_1d(arr)[np.atleast_1d(bad)][0])
        raise ValueError(
            f"{name} must be {range_text(minimum, strict, maximum, allow_inf)}, got {first!r}")
    return arr


def checked_beta(alpha: ArrayLike, beta: ArrayLike) -> NDArray[np.float64]:
    """``beta`` as a float array, or ValueError unless ``beta > alpha`` (``inf`` allowed)."""
    a = np.asarray(alpha, dtype=float)
    b = checked("beta", beta, allow_inf=True) if np.ndim(beta) else np.asarray(beta, float)
    with np.errstate(invalid="ignore"):
        bad = ~(b > a)  # also nan
    if np.any(bad):
        a_b, b_b, bad_b = np.broadcast_arrays(a, b, bad)
        raise ValueError(f"beta must be > alpha (= {float(a_b[bad_b][0])!r}) or math.inf, "
                         f"got {float(b_b[bad_b][0])!r}")
    return b


def as_float_or_array(x: ArrayLike) -> FloatOrArray:
    """A Python float for a 0-d input, else a float array."""
    arr = np.asarray(x, dtype=float)
    return float(arr) if arr.ndim == 0 else arr
