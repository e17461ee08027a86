"""The domains of the closed forms and the helpers every part of the theory shares."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..schema import Range
from ..validation import validated

#: Domains of closed forms wider or narrower than the model's (the schema's ranges):
#: the soft limit ``k_x = 0`` (``alpha = 0``) is a point of the formulas, the laws of
#: eqs. (26), (27) hold without jumping (``a <= 1``) and at every ``vbar`` up to ``inf``.
SOFT_LIMIT = Range(0.0)


NO_JUMPING = Range(0.0, maximum=1.0)


ANY_VBAR = Range(0.0, allow_inf=True)


def valid_array(name: str, value: ArrayLike, domain: Range | None = None) -> NDArray[np.float64]:
    """One model parameter checked by the one validator (in ``domain`` if given)."""
    return validated({name: value}, ranges=None if domain is None else {name: domain})[name]


FloatOrArray = float | NDArray[np.float64]


def elementwise(f: Callable[..., float], *args: ArrayLike) -> NDArray[np.float64]:
    """The scalar closed form ``f`` over the broadcast ``args``: a float array of their shape.

    :func:`numpy.vectorize` without its fixed cost (some 30 us a call, more than most of
    these forms take), which the solvers pay at every point.
    """
    b = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in args))
    if b[0].ndim == 0:
        return np.array(f(*(float(x) for x in b)), dtype=float)
    out = np.empty(b[0].shape)
    for i in np.ndindex(out.shape):
        out[i] = f(*(float(x[i]) for x in b))
    return out


# --------------------------------------------------------------------------- helpers
def ratio_or_inf(num: NDArray[np.float64], den: NDArray[np.float64]) -> NDArray[np.float64]:
    """``num / den`` with ``0`` where ``num == 0`` and ``inf`` where only ``den == 0``."""
    num, den = np.broadcast_arrays(num, den)
    out = np.full(num.shape, np.inf)
    np.divide(num, den, out=out, where=den != 0)
    out[num == 0] = 0.0
    return out
