"""Cell edges of a plotted grid axis: the package's one helper (atlas plots, figure maps)."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["cell_edges", "is_geometric"]


def is_geometric(values: ArrayLike) -> bool:
    """Whether ``values`` are evenly spaced in ``log``, as :func:`numpy.geomspace` makes them.

    Parameters
    ----------
    values : array_like
        A 1-D axis.

    Returns
    -------
    bool
        True for 3 or more finite values, all > 0, with equal ratios (to ``1e-6``).

    Examples
    --------
    >>> import numpy as np
    >>> from vibrofriction.figures import is_geometric
    >>> is_geometric(np.geomspace(1e-2, 1e2, 5)), is_geometric([0.0, 0.5, 1.0])
    (True, False)
    """
    v = np.asarray(values, dtype=float)
    if v.ndim != 1 or v.size < 3 or not np.all(np.isfinite(v)) or np.any(v <= 0):
        return False
    steps = np.diff(np.log(v))
    return bool(np.allclose(steps, steps[0], rtol=1e-6) and abs(steps[0]) > 0)


def cell_edges(values: ArrayLike, log: bool | None = None, name: str = "axis"
               ) -> NDArray[np.float64]:
    """The ``n + 1`` edges of ``n`` cells centred on ``values`` (for ``pcolormesh``).

    Inner edges are midpoints, outer ones mirror the nearest inner edge. A single value
    gets a cell of width 1 (``log``: a factor 1.1 either way).

    Parameters
    ----------
    values : array_like
        A 1-D axis of finite values.
    log : bool or None, optional
        Take the midpoints in ``log``, so that cells of a geometric axis look equal on a
        log scale; None (default): :func:`is_geometric` of ``values``.
    name : str, optional
        The axis' name, for the error messages.

    Returns
    -------
    numpy.ndarray
        The ``n + 1`` edges.

    Raises
    ------
    ValueError
        For an empty axis, non-finite values, or values ``<= 0`` on a log axis.

    Examples
    --------
    >>> from vibrofriction.figures import cell_edges
    >>> cell_edges([0.0, 0.5, 1.0])
    array([-0.25,  0.25,  0.75,  1.25])
    >>> cell_edges([0.01, 0.1, 1.0])  # a geometric axis: midpoints in log
    array([0.00316228, 0.03162278, 0.31622777, 3.16227766])
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
