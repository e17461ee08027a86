"""Velocity series: what a figure asks the solver for, and what it gets back.

A :class:`Series` is one curve of a figure: a fixed system ``(alpha, beta, a)``
(eq. 20) and an array of inertial velocities ``V = v0 m omega/(mu0 F_N0)``.
:func:`solve` flattens any number of series into one batch for
:func:`vibrofriction.solver.solve_points` and cuts the answer back into
:class:`Curve` objects.  The batch can be run by any *runner* with the signature
of ``solve_points`` (the report passes one that spreads the points over
processes); since every point depends only on its own parameters, the result
does not depend on how the batch is split.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import theory
from ..solver import STATUS_BY_CODE, SolverSettings, solve_points

__all__ = ["TRUSTED_ERROR", "Curve", "Runner", "Series", "solve", "series_at_vbar",
           "status_counts"]

#: Largest error estimate (absolute, in ``mu/mu0``) of a point that is drawn as trusted.
TRUSTED_ERROR: float = 1e-5

#: ``runner(alpha, beta, amplitude, v_inertial, settings=...) -> dict of arrays``.
Runner = Callable[..., dict[str, NDArray]]


@dataclass(frozen=True)
class Series:
    """One curve: a system and the inertial velocities at which to solve it.

    ``key`` names the curve uniquely within a figure; ``vbar`` holds ``v0/v0*``
    (eq. 16) at each point, ``nan`` where it does not exist (cases III, IV);
    ``meta`` carries plotting information (labels, panel) and is written into
    the data tables.
    """

    key: str
    alpha: float
    beta: float
    amplitude: float
    v_inertial: NDArray[np.float64]
    vbar: NDArray[np.float64]
    meta: Mapping[str, object] = field(default_factory=dict)

    def __post_init__(self) -> None:
        v = np.asarray(self.v_inertial, dtype=float)
        if v.ndim != 1 or not np.all(np.isfinite(v) & (v >= 0.0)):
            raise ValueError(f"series {self.key!r}: v_inertial must be a 1-d array of "
                             "finite velocities >= 0")
        object.__setattr__(self, "v_inertial", v)
        vb = np.broadcast_to(np.asarray(self.vbar, dtype=float), v.shape).copy()
        object.__setattr__(self, "vbar", vb)

    @property
    def size(self) -> int:
        return int(self.v_inertial.size)


def series_at_vbar(key: str, alpha: float, beta: float, amplitude: float,
                   vbar: ArrayLike, **meta: object) -> Series:
    """A series on a grid of ``vbar = v0/v0*`` (eqs. 12, 16); needs ``alpha != 1 != beta``."""
    vb = np.asarray(vbar, dtype=float)
    c = float(theory.inertial_per_vbar(alpha, beta, amplitude))
    if c == 0.0 or math.isinf(c):
        raise ValueError(f"series {key!r}: vbar does not exist at alpha={alpha}, beta={beta} "
                         f"(v0* is {c}); use the inertial velocity")
    return Series(key, alpha, beta, amplitude, c * vb, vb, meta)


@dataclass(frozen=True)
class Curve:
    """A solved :class:`Series`: ``mu_ratio`` (eq. 25), its ``error`` and status codes."""

    series: Series
    mu_ratio: NDArray[np.float64]
    error: NDArray[np.float64]
    status: NDArray[np.int64]
    period: NDArray[np.int64]
    stick_fraction: NDArray[np.float64]
    flight_fraction: NDArray[np.float64]

    @property
    def ok(self) -> NDArray[np.bool_]:
        """Points to trust: a converged status and an error estimate below :data:`TRUSTED_ERROR`.

        The second condition catches a result whose status claims convergence although
        its own error estimate says otherwise (seen for a periodic orbit accepted from a
        diverged Newton step); such points are drawn as open circles and listed in the
        report instead of being joined into the curve.
        """
        status_ok = np.array([STATUS_BY_CODE[int(s)].ok for s in self.status], dtype=bool)
        return status_ok & (np.nan_to_num(self.error, nan=np.inf) <= TRUSTED_ERROR)

    @property
    def suspicious(self) -> NDArray[np.bool_]:
        """Points whose status claims convergence but whose error estimate is large."""
        status_ok = np.array([STATUS_BY_CODE[int(s)].ok for s in self.status], dtype=bool)
        return status_ok & ~self.ok

    @property
    def trusted_mu(self) -> NDArray[np.float64]:
        """``mu_ratio`` with untrusted points (see :attr:`ok`) replaced by nan, for lines."""
        return np.where(self.ok, self.mu_ratio, np.nan)

    # shortcuts
    @property
    def v_inertial(self) -> NDArray[np.float64]:
        return self.series.v_inertial

    @property
    def vbar(self) -> NDArray[np.float64]:
        return self.series.vbar


def solve(series: Iterable[Series], *, runner: Runner | None = None,
          settings: SolverSettings | None = None) -> dict[str, Curve]:
    """Solve every point of every series in one batch; return curves by key."""
    series = list(series)
    keys = [s.key for s in series]
    if len(set(keys)) != len(keys):
        raise ValueError("series keys must be unique")
    if not series:
        return {}
    run = runner or solve_points
    sizes = [s.size for s in series]
    al = np.concatenate([np.full(s.size, s.alpha) for s in series])
    be = np.concatenate([np.full(s.size, s.beta) for s in series])
    am = np.concatenate([np.full(s.size, s.amplitude) for s in series])
    V = np.concatenate([s.v_inertial for s in series])
    out = run(al, be, am, V, settings=settings)
    curves: dict[str, Curve] = {}
    start = 0
    for s, n in zip(series, sizes, strict=True):
        sl = slice(start, start + n)
        curves[s.key] = Curve(s, out["mu_ratio"][sl].copy(), out["error"][sl].copy(),
                              out["status"][sl].copy(), out["period"][sl].copy(),
                              out["stick_fraction"][sl].copy(),
                              out["flight_fraction"][sl].copy())
        start += n
    return curves


def status_counts(curves: Sequence[Curve] | Mapping[str, Curve]) -> dict[str, int]:
    """How many points of the curves ended in each status (by the status' name)."""
    items = curves.values() if isinstance(curves, Mapping) else curves
    counts: dict[str, int] = {}
    for c in items:
        for code in c.status:
            name = STATUS_BY_CODE[int(code)].value
            counts[name] = counts.get(name, 0) + 1
    return counts
