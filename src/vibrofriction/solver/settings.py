"""Accuracy and effort bounds of the steady-state search, and what counts as trusted."""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..schema import CONVERGED_CODES, Status

__all__ = ["DEFAULT_SETTINGS", "SolverSettings", "converged"]


def converged(status: ArrayLike) -> NDArray[np.bool_]:
    """Which statuses are converged (:attr:`Status.ok`), elementwise: integer codes or
    :class:`Status` members.  The package's one test of convergence."""
    st = np.asarray(status)
    if st.ndim == 0 and st.dtype != object:  # one point: no array machinery
        # a numpy bool, which broadcasts and indexes as a 0-d array would
        return np.bool_(int(st) in CONVERGED_CODES)  # type: ignore[return-value]
    if st.dtype == object:
        flat = [s.ok if isinstance(s, Status) else int(s) in CONVERGED_CODES for s in st.flat]
        return np.array(flat, dtype=bool).reshape(st.shape)
    return np.isin(st, CONVERGED_CODES)


@dataclass(frozen=True)
class SolverSettings:
    """Accuracy and effort bounds of the steady-state search.

    Parameters
    ----------
    max_periods : give up (status ``NOT_CONVERGED``) after this many drive periods.
    min_periods : first checkpoint of the running average (doubling afterwards).
    tol_state : relative distance of section states that counts as periodic.
    tol_mean : agreement of successive averaging windows that counts as converged.
    max_events : event budget per point (status ``FAILED`` beyond).
    tol_trusted : a result is *trusted* when its status is a converged one and its
        ``error`` (an estimate of ``|mu_ratio - exact|``) is at most this; the one
        definition used by the figures, the report, the sweep and the command line.
    """

    max_periods: int = 20000
    min_periods: int = 64
    tol_state: float = 1e-10
    tol_mean: float = 1e-7
    max_events: int = 20_000_000
    tol_trusted: float = 1e-5

    def __post_init__(self) -> None:
        for name in ("max_periods", "min_periods", "max_events"):
            v = getattr(self, name)
            if not (isinstance(v, int | np.integer) and v >= 1):
                raise ValueError(f"{name} must be an integer >= 1, got {v!r}")
        for name in ("tol_state", "tol_mean", "tol_trusted"):
            v = getattr(self, name)
            if not (math.isfinite(v) and 0.0 < v < 1.0):
                raise ValueError(f"{name} must be in (0, 1), got {v!r}")

    def trusted(self, status: ArrayLike, error: ArrayLike) -> NDArray[np.bool_]:
        """Which results to trust: a converged status and ``error <= tol_trusted``.

        ``status`` holds integer codes (:attr:`Status.code`) or :class:`Status`
        members.  This is the package's one notion of a trusted result.
        """
        if np.ndim(error) == 0:  # one point (nan is never <= tol)
            return converged(status) & np.bool_(float(np.asarray(error, dtype=float))
                                                <= self.tol_trusted)
        err = np.nan_to_num(np.asarray(error, dtype=float), nan=np.inf)
        return converged(status) & (err <= self.tol_trusted)

    def trusted_one(self, status: Status, error: float) -> bool:
        """:meth:`trusted` of one point, a :class:`Status` and its ``error``, as a bool."""
        return status.ok and error <= self.tol_trusted

    def kernel_arguments(self) -> tuple[int, int, float, float, int]:
        """``(max_periods, min_periods, tol_state, tol_mean, max_events)`` for the kernels."""
        return self._kernel_arguments

    @functools.cached_property
    def _kernel_arguments(self) -> tuple[int, int, float, float, int]:
        """:meth:`kernel_arguments`, converted once (the fields are frozen)."""
        return (int(self.max_periods), int(self.min_periods), float(self.tol_state),
                float(self.tol_mean), int(self.max_events))


DEFAULT_SETTINGS = SolverSettings()
