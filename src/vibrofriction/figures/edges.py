"""Cell edges of a plotted grid axis: the package's one helper (atlas plots, figure maps)."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["cell_edges", "is_geometric"]


def is_geometric(values: ArrayLike) -> bool:
    """Whether ``values`` (3 or more, all > 0) are evenly spaced in ``log``.

    As :func:`numpy.geomspace` makes them.
    """
    v = np.asarray(values, dtype=float)
    if v.ndim != 1 or v.size < 3 or not np.all(np.isfinite(v)) or np.any(v <= 0):
        return False
    steps = np.diff(np.log(v))
    return bool(np.allclose(steps, steps[0], rtol=1e-6) and abs(steps[0]) > 0)


def cell_edges(values: ArrayLike, log: bool | None = None, name: str = "axis"
               ) -> NDArray[np.float64]:
    """The ``n + 1`` edges of ``n`` cells centred on ``values`` (for ``pcolormesh``).

    Inner edges are midpoints, outer ones mirror the nearest inner edge; with ``log``
    (default: ``is_geometric(values)``) midpoints are taken in ``log``, so that cells
    of a geometric axis look equal on a log scale.  A single value gets a cell of
    width 1 (``log``: a factor 1.1 either way).  ValueError for non-finite values.
    """
    v = np.asarray(values, dtype=float)
    if v.ndim != 1 or v.size == 0 or not np.all(np.isfinite(v)):
        raise ValueError(f"cannot draw cells along {name}: it needs one or more finite "
                         f"values, got {values!r}")
    if log is None:
        log = is_geometric(v)
    if log and np.any(v <= 0):
        raise ValueError(f"cannot draw log-spaced cells along {name}: values must be > 0")
    if v.size == 1:
        return v[0] * np.array([1 / 1.1, 1.1]) if log else v[0] + np.array([-0.5, 0.5])
    w = np.log(v) if log else v
    mid = 0.5 * (w[1:] + w[:-1])
    edges = np.concatenate([[2 * w[0] - mid[0]], mid, [2 * w[-1] - mid[-1]]])
    return np.exp(edges) if log else edges
