"""Accuracy and effort bounds of the steady-state search, and what counts as trusted."""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, fields
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..schema import CONVERGED_CODES, Status

__all__ = ["DEFAULT_SETTINGS", "SolverSettings", "converged"]


def converged(status: ArrayLike) -> NDArray[np.bool_]:
    """Which statuses are converged (:attr:`Status.ok`), elementwise.

    The package's one test of convergence.

    Parameters
    ----------
    status : array_like
        Integer codes (:attr:`Status.code`) or :class:`Status` members.

    Returns
    -------
    numpy.bool_ or ndarray of bool
        Of the shape of ``status``.

    Examples
    --------
    >>> import vibrofriction as vf
    >>> from vibrofriction.solver import converged
    >>> converged([vf.Status.PERIODIC.code, vf.Status.NOT_CONVERGED.code])
    array([ True, False])
    """
    st = np.asarray(status)
    if st.ndim == 0 and st.dtype != object:  # one point: no array machinery
        # a numpy bool, which broadcasts and indexes as a 0-d array would
        return np.bool_(int(st) in CONVERGED_CODES)  # type: ignore[return-value]
    if st.dtype == object:
        flat = [s.ok if isinstance(s, Status) else int(s) in CONVERGED_CODES for s in st.flat]
        return np.array(flat, dtype=bool).reshape(st.shape)
    return np.isin(st, CONVERGED_CODES)


#: The integer settings (the rest are tolerances in (0, 1)).
_COUNTS = ("max_periods", "min_periods", "max_events", "max_events_per_period")


@dataclass(frozen=True)
class SolverSettings:
    """Accuracy and effort bounds of the steady-state search, and what counts as trusted.

    One class for every method: each method declares the fields it honours and its own
    default for each (:data:`vibrofriction.solver.methods.METHODS`; the table "what each
    solver covers" in docs/solver.md).  A field left at None takes each method's default;
    a field given a value is honoured by every method that declares it, and a point whose
    method does not honour a field that was set is refused (``ValueError`` naming the
    setting), never silently run with another value.

    Parameters
    ----------
    max_periods : int or None
        Drive periods after which the search gives up (status ``NOT_CONVERGED``); the MDR
        solver: per row of springs.
    min_periods : int or None
        First checkpoint of the running average (doubling afterwards).
    tol_state : float or None
        Relative distance of section states that counts as periodic.
    tol_mean : float or None
        Agreement of successive averaging windows that counts as converged.
    max_events : int or None
        Event budget per point (status ``FAILED`` beyond).
    max_events_per_period : int or None
        Stick/slip switches per drive period beyond which a point fails (chatter).
    rtol : float or None
        Relative (and absolute) tolerance of the Runge-Kutta integration.
    tol_trusted : float
        A result is *trusted* when its status is a converged one and its ``error`` (an
        estimate of ``|mu_ratio - exact|``) is at most this; the one definition used by
        the figures, the report, the sweep and the command line.  Every method honours
        it; the MDR solver also refines its row of springs until its error is below it.

    Raises
    ------
    ValueError
        A count that is not an integer >= 1, or a tolerance outside ``(0, 1)``.

    Examples
    --------
    >>> import vibrofriction as vf
    >>> settings = vf.SolverSettings(max_periods=500, tol_trusted=1e-8)
    >>> settings.chosen()  # the fields set, tol_trusted aside
    ('max_periods',)
    >>> vf.SolverSettings(rtol=2.0)
    Traceback (most recent call last):
    ...
    ValueError: settings.rtol must be a number in (0, 1) or None, got 2.0
    """

    max_periods: int | None = None
    min_periods: int | None = None
    tol_state: float | None = None
    tol_mean: float | None = None
    max_events: int | None = None
    max_events_per_period: int | None = None
    rtol: float | None = None
    tol_trusted: float = 1e-5

    def __post_init__(self) -> None:
        """Check each field given: counts integers >= 1, tolerances in (0, 1)."""
        # what the methods derive from the settings, once (not a field: not compared,
        # hashed or stored; the fields are frozen, so it never goes stale)
        object.__setattr__(self, "_derived", {})
        for f in fields(self):
            v = getattr(self, f.name)
            if v is None and f.name != "tol_trusted":
                continue
            if f.name in _COUNTS:
                if not (isinstance(v, int | np.integer) and not isinstance(v, bool)
                        and v >= 1):
                    raise ValueError(f"settings.{f.name} must be an integer >= 1 or None "
                                     f"(each method's default), got {v}")
            elif not (isinstance(v, float | int | np.floating) and not isinstance(v, bool)
                      and math.isfinite(v) and 0.0 < v < 1.0):
                raise ValueError(f"settings.{f.name} must be a number in (0, 1)"
                                 f"{'' if f.name == 'tol_trusted' else ' or None'}, got {v}")

    def chosen(self) -> tuple[str, ...]:
        """The fields given a value (not None), ``tol_trusted`` aside.

        Every method honours ``tol_trusted``.
        """
        return tuple(f.name for f in fields(self)
                     if f.name != "tol_trusted" and getattr(self, f.name) is not None)

    def resolved(self, defaults: Mapping[str, float | int]) -> dict[str, float | int]:
        """The value of each field of ``defaults``: the one given here, else the default.

        ``defaults`` are a method's honoured settings and their defaults.
        """
        return {k: d if getattr(self, k) is None else getattr(self, k)
                for k, d in defaults.items()}

    def derived(self, key: str, make: Callable[[SolverSettings], Any]) -> Any:
        """``make(self)``, computed once per settings object and key.

        A method's kernel arguments: the one-point path pays a dictionary look-up.
        """
        try:
            return self._derived[key]  # type: ignore[attr-defined]
        except KeyError:
            value = self._derived[key] = make(self)  # type: ignore[attr-defined]
            return value

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


DEFAULT_SETTINGS = SolverSettings()
