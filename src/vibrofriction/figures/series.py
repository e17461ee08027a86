"""Velocity series: what a figure asks the solver for, and what it gets back.

A :class:`Series` is one curve of a figure: a fixed system ``(alpha, beta, a)``
(eq. 20; with ``zeta``, ``eta_c`` for a damped one, docs/damping.md; with ``a_x``,
``phase_x``, ``inplane_on`` for a longitudinal in-plane oscillation, docs/inplane.md; with
``profile_exponent`` for a curved tip, docs/contact_geometry.md; with ``static_ratio`` or the
``rs_*`` parameters and ``rs_law`` for a local friction law other than Coulomb's,
docs/friction_laws.md) and
an array of inertial velocities ``V = v0 m omega/(mu0 F_N0)`` (signed: ``V < 0`` slides
backward).
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
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..params import Physical, vbar_to_inertial
from ..schema import FIELD, FLOAT_COLUMNS, INT_COLUMNS, STATUS_BY_CODE
from ..solver import SolverSettings, converged, solve_points
from ..validation import checked, checked_choice

__all__ = ["CHOICE_ARGS", "CURVE_COLUMNS", "POINT_ARGS", "Curve", "Runner", "Series",
           "point_columns",
           "series_at_vbar", "series_of_physical", "solve", "solve_points_on",
           "status_counts"]

#: The solver's numeric point arguments (the :class:`Series` fields and the keywords of
#: :func:`~vibrofriction.solver.solve_points` of the same names).
POINT_ARGS = ("alpha", "beta", "amplitude", "v_inertial", "zeta", "eta_c", "a_x", "phase_x",
              "a_y", "phase_y", "profile_exponent", "static_ratio", "rs_a", "rs_b", "rs_d_c",
              "rs_v_ref", "rs_alpha_ld")
#: The solver's choices per point (the :class:`Series` fields and the keywords of
#: :func:`~vibrofriction.solver.solve_points` of the same names): arrays of names.
CHOICE_ARGS = ("inplane_on", "rs_law")
#: The fields of the local friction law (of :class:`Series` and of
#: :class:`~vibrofriction.Dimensionless`).
_FRICTION_ARGS = ("static_ratio", "rs_a", "rs_b", "rs_d_c", "rs_v_ref", "rs_alpha_ld", "rs_law")
#: ``runner(*columns, settings=...) -> dict of arrays``: ``columns`` the :data:`POINT_ARGS`
#: arrays of the points followed by the :data:`CHOICE_ARGS` arrays of names, one entry per
#: point (:func:`point_columns`): :func:`solve_points_on` or one with its signature.
Runner = Callable[..., dict[str, NDArray]]


@dataclass(frozen=True)
class Series:
    """One curve: a system and the inertial velocities at which to solve it.

    Parameters
    ----------
    key : str
        Names the curve uniquely within a figure.
    alpha, beta, amplitude : float
        The system (eq. 20).
    v_inertial : array_like
        The inertial velocities ``V`` (1-D); signed (the solver's mirror solves
        ``V < 0``); ``V = 0`` with a transverse oscillation (``a_y > 0``) is refused, as
        by the solver.
    vbar : array_like
        ``v0/v0*`` (eq. 16) at each point, ``nan`` where it does not exist (cases III,
        IV); broadcast to the velocities.
    meta : mapping, optional
        Plotting information (labels, panel), written into the data tables.
    zeta, eta_c, a_x, phase_x, inplane_on, a_y, phase_y, profile_exponent : optional
        The rest of the system, as :class:`~vibrofriction.Dimensionless` names them.
    static_ratio, rs_a, rs_b, rs_d_c, rs_v_ref, rs_alpha_ld, rs_law : optional
        The local friction law, as :class:`~vibrofriction.Dimensionless` names them
        (default Coulomb friction: ``static_ratio = 1``, ``rs_a = 0``).

    Examples
    --------
    >>> import numpy as np
    >>> from vibrofriction.figures import Series, solve
    >>> series = Series("a", alpha=0.1, beta=2.0, amplitude=0.5, v_inertial=[0.3],
    ...                 vbar=np.nan)
    >>> series.size
    1
    >>> solve([series])["a"].mu_ratio  # above the critical velocity: mu0
    array([1.])
    """

    key: str
    alpha: float
    beta: float
    amplitude: float
    v_inertial: NDArray[np.float64]
    vbar: NDArray[np.float64]
    meta: Mapping[str, Any] = field(default_factory=dict)
    zeta: float = 0.0
    eta_c: float = 0.0
    a_x: float = 0.0
    phase_x: float = 0.0
    inplane_on: str = "substrate"
    a_y: float = 0.0
    phase_y: float = 0.0
    profile_exponent: float = math.inf
    static_ratio: float = 1.0
    rs_a: float = 0.0
    rs_b: float = 0.0
    rs_d_c: float = 1.0
    rs_v_ref: float = 1.0
    rs_alpha_ld: float = 0.0
    rs_law: str = "aging"

    def __post_init__(self) -> None:
        """Check the velocity grid and the system."""
        v = checked(f"series {self.key!r}: v_inertial", self.v_inertial)
        if v.ndim != 1:
            raise ValueError(f"series {self.key!r}: v_inertial must be a 1-d array, "
                             f"got shape {v.shape}")
        if self.a_y > 0 and np.any(v == 0.0):
            raise ValueError(f"series {self.key!r}: v_inertial = 0 with a transverse "
                             "oscillation (a_y > 0) is not computed (docs/inplane.md)")
        for name in CHOICE_ARGS:
            checked_choice(name, getattr(self, name))
        object.__setattr__(self, "v_inertial", v)
        vb = np.broadcast_to(np.asarray(self.vbar, dtype=float), v.shape).copy()
        object.__setattr__(self, "vbar", vb)

    @property
    def size(self) -> int:
        """The number of velocity points."""
        return int(self.v_inertial.size)


def series_at_vbar(key: str, alpha: float, beta: float, amplitude: float,
                   vbar: ArrayLike, **meta: object) -> Series:
    """A series on a grid of ``vbar = v0/v0*`` (eqs. 12, 16); needs ``alpha != 1 != beta``."""
    vb = np.asarray(vbar, dtype=float)
    try:
        V = vbar_to_inertial(alpha, beta, amplitude, vb)
    except ValueError as exc:
        raise ValueError(f"series {key!r}: {exc}") from None
    return Series(key, alpha, beta, amplitude, np.atleast_1d(V), vb, meta)


def series_of_physical(key: str, physical: Physical, v0: ArrayLike, **meta: object) -> Series:
    """A series of a :class:`Physical` system on a grid of ``v0`` (m/s).

    Its dimensionless groups (damping included), ``V`` and ``vbar`` (nan where ``v0*`` is 0 or
    infinite); ``v0`` is kept in ``meta``; a curved tip keeps its ``profile_exponent``, the
    friction law its ``static_ratio`` and ``rs_*`` (in the model's units at the pin's
    ``omega``).
    """
    v0 = np.asarray(v0, dtype=float)
    dim = physical.to_dimensionless()
    V = np.asarray(physical.v0_to_inertial(v0))
    try:
        vbar = np.asarray(physical.v0_to_vbar(v0))
    except ValueError:
        vbar = np.full(v0.size, np.nan)
    return Series(key, dim.alpha, dim.beta, dim.amplitude, V, vbar, {"v0": v0, **meta},
                  zeta=dim.zeta, eta_c=dim.eta_c, profile_exponent=dim.profile_exponent,
                  **{n: getattr(dim, n) for n in _FRICTION_ARGS})



#: The columns of a :class:`Curve`: those of :func:`solve_points` (the schema's kernel
#: columns and ``trusted``), by name.
CURVE_COLUMNS = (*FLOAT_COLUMNS, *INT_COLUMNS, "trusted")


@dataclass(frozen=True)
class Curve:
    """A solved :class:`Series`.

    Every column :func:`~vibrofriction.solver.solve_points` returns (named by
    :mod:`vibrofriction.schema`: ``mu_ratio`` (eq. 25), its ``error``, status codes,
    ``trusted`` (the solver's one definition:
    :meth:`~vibrofriction.SolverSettings.trusted`) ...) is an attribute of the same name.

    Parameters
    ----------
    series : Series
        What was solved.
    columns : mapping of str to numpy.ndarray
        Every column of ``CURVE_COLUMNS`` (those of ``solve_points``).

    Examples
    --------
    >>> from vibrofriction.figures import solve
    >>> from vibrofriction.figures.series import series_at_vbar
    >>> curve = solve([series_at_vbar("b", 0.1, 2.0, 0.5, [0.5])])["b"]
    >>> curve.mu_ratio, curve.trusted, curve.vbar
    (array([0.58754462]), array([ True]), array([0.5]))
    """

    series: Series
    columns: Mapping[str, NDArray]

    def __post_init__(self) -> None:
        """Check that the curve has every column of :data:`CURVE_COLUMNS`."""
        missing = [k for k in CURVE_COLUMNS if k not in self.columns]
        if missing:
            raise ValueError(f"curve {self.series.key!r} lacks the columns {missing}")

    @classmethod
    def of(cls, series: Series, **columns: ArrayLike) -> Curve:
        """A curve with the given columns.

        The others hold what no result holds (nan, -1, not trusted): for curves made by hand.
        """
        def filled(k: str) -> NDArray:
            if k in columns:
                return np.broadcast_to(np.asarray(columns[k]), (series.size,)).copy()
            # every field but trusted has its kernel column
            kind = "bool" if k == "trusted" else FIELD[k].column[0]  # type: ignore[index]
            return np.full(series.size, {"float": np.nan, "int": -1, "bool": False}[kind])

        unknown = set(columns) - set(CURVE_COLUMNS)
        if unknown:
            raise ValueError(f"unknown curve columns {sorted(unknown)}")
        return cls(series, {k: filled(k) for k in CURVE_COLUMNS})

    def __getattr__(self, name: str) -> NDArray:
        """A column by name, as an attribute."""
        columns = self.__dict__.get("columns", {})
        if name in columns:
            return columns[name]
        raise AttributeError(f"{type(self).__name__!r} object has no attribute {name!r}")

    @property
    def suspicious(self) -> NDArray[np.bool_]:
        """Points whose status claims convergence but whose error estimate is too large to trust.

        Drawn as open circles and listed in the report.
        """
        return converged(self.status) & ~self.trusted

    @property
    def trusted_mu(self) -> NDArray[np.float64]:
        """``mu_ratio`` with untrusted points replaced by nan, for lines."""
        return np.where(self.trusted, self.mu_ratio, np.nan)

    # shortcuts
    @property
    def v_inertial(self) -> NDArray[np.float64]:
        """The inertial velocities ``v0`` of the series (m/s)."""
        return self.series.v_inertial

    @property
    def vbar(self) -> NDArray[np.float64]:
        """The scaled velocities ``vbar`` of the series."""
        return self.series.vbar


def solve(series: Iterable[Series], *, runner: Runner | None = None,
          settings: SolverSettings | None = None) -> dict[str, Curve]:
    """Solve every point of every series in one batch.

    Parameters
    ----------
    series : iterable of Series
        The curves, with unique keys.
    runner : callable, optional
        Solves the points (a ``Runner``); default the exact solver in this process.
    settings : vibrofriction.SolverSettings, optional
        The solver's settings.

    Returns
    -------
    dict of str to Curve
        The solved curves by key.

    Raises
    ------
    ValueError
        If two series share a key.

    Examples
    --------
    See :class:`Series` and :class:`Curve`.
    """
    series = list(series)
    keys = [s.key for s in series]
    if len(set(keys)) != len(keys):
        raise ValueError("series keys must be unique")
    if not series:
        return {}
    run = runner or solve_points_on
    sizes = [s.size for s in series]
    out = run(*point_columns(series), settings=settings)
    curves: dict[str, Curve] = {}
    start = 0
    for s, n in zip(series, sizes, strict=True):
        sl = slice(start, start + n)
        curves[s.key] = Curve(s, {k: out[k][sl].copy() for k in CURVE_COLUMNS})
        start += n
    return curves


def point_columns(series: Sequence[Series]) -> list[NDArray]:
    """The arguments of a :data:`Runner` for every point of ``series``.

    The :data:`POINT_ARGS` arrays of every point of ``series`` (concatenated in order),
    then the :data:`CHOICE_ARGS` arrays of names (``dtype=object``).
    """
    if not series:
        return ([np.empty(0) for _ in POINT_ARGS]
                + [np.empty(0, dtype=object) for _ in CHOICE_ARGS])
    columns = [np.concatenate([s.v_inertial if n == "v_inertial" else
                               np.full(s.size, getattr(s, n)) for s in series])
               for n in POINT_ARGS]
    choices = [np.concatenate([np.full(s.size, getattr(s, n), dtype=object) for s in series])
               for n in CHOICE_ARGS]
    return columns + choices


def solve_points_on(*columns: NDArray, settings: SolverSettings | None = None
                    ) -> dict[str, NDArray]:
    """The default :data:`Runner`: the exact solver on every point.

    :func:`solve_points` on the :data:`POINT_ARGS` arrays followed by the
    :data:`CHOICE_ARGS` arrays (:func:`point_columns`), every one by its keyword; the
    solver takes a choice's value point by point.
    """
    n = len(POINT_ARGS)
    if len(columns) != n + len(CHOICE_ARGS):
        raise TypeError(f"a Runner takes {n + len(CHOICE_ARGS)} columns (POINT_ARGS, then "
                        f"CHOICE_ARGS), got {len(columns)}")
    numbers = dict(zip(POINT_ARGS, columns[:n], strict=True))
    choices = {k: np.asarray(v, dtype=object)
               for k, v in zip(CHOICE_ARGS, columns[n:], strict=True)}
    return solve_points(**numbers, **choices, settings=settings)


def status_counts(curves: Sequence[Curve] | Mapping[str, Curve]) -> dict[str, int]:
    """How many points of the curves ended in each status (by the status' name)."""
    items = curves.values() if isinstance(curves, Mapping) else curves
    counts: dict[str, int] = {}
    for c in items:
        for code in c.status:
            name = STATUS_BY_CODE[int(code)].value
            counts[name] = counts.get(name, 0) + 1
    return counts
