"""The domains of the closed forms and the helpers every part of the theory shares."""

from __future__ import annotations

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


# --------------------------------------------------------------------------- helpers
def ratio_or_inf(num: NDArray[np.float64], den: NDArray[np.float64]) -> NDArray[np.float64]:
    """``num / den`` with ``0`` where ``num == 0`` and ``inf`` where only ``den == 0``."""
    num, den = np.broadcast_arrays(num, den)
    out = np.full(num.shape, np.inf)
    np.divide(num, den, out=out, where=den != 0)
    out[num == 0] = 0.0
    return out
