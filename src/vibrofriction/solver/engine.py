r"""The batch engine: steady states at arbitrary points (paper eqs. 21-25).

:func:`solve_points` runs the exact event-driven kernels of :mod:`vibrofriction._kernels`
over arrays of points in one compiled loop and returns their named output columns
(:data:`vibrofriction.schema.FLOAT_COLUMNS`, ``INT_COLUMNS``); :func:`friction_coefficient`
wraps them as :class:`FrictionResult` objects for a system and its velocities.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import overload

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import theory
from .._kernels import codes
from .._kernels.codes import LINK_GIVEN, LINK_OWN, LINK_PREVIOUS
from .._kernels.steady import steady_state
from ..params import Dimensionless, System, dimensionless, inertial_velocity
from ..schema import FLOAT_COLUMNS, INT_COLUMNS, METHOD_NAMES, column_index
from .methods import METHODS, choose, method_of
from .methods.event import EVENT, event_arguments
from .methods.plane import PLANE
from .points import PointTable, point_table, table_of
from .results import (
    PHASE_CODE,
    FrictionResult,
    FrictionResults,
    SectionState,
    result_from_columns,
    result_from_rows,
    results_from_columns,
    section_state,
)
from .settings import DEFAULT_SETTINGS, SolverSettings

__all__ = ["friction_coefficient", "solve_chain", "solve_points", "solve_table"]

Initial = str | SectionState


def _elongation(state: SectionState, systems: Callable[[int], Dimensionless], i: int) -> float:
    """The state's ``e``: given, or the one its force implies for point ``i``'s system.

    The system is built only then: it is validated anew, the slowest part of a call.
    """
    return state.e if math.isfinite(state.e) else state.elongation(systems(i))


def initial_rows(initial: Initial | NDArray[np.object_], n: int,
                 systems: Callable[[int], Dimensionless]) -> tuple[int, NDArray[np.float64]]:
    """Kernel start ``(kind, rows (y, x', e, phase))``; ``systems(i)`` is point i's system.

    Parameters
    ----------
    initial : str, SectionState or ndarray of SectionState
        ``"sliding"``, ``"rest"``, one section state, or one per point.
    n : int
        The number of points.
    systems : callable
        ``systems(i)`` is point i's :class:`Dimensionless` system.

    Returns
    -------
    kind : int
        0 sliding, 1 rest, 2 explicit states.
    rows : ndarray, shape (n, 4)
        The explicit start ``(y, x', e, phase code)`` of each point (zeros otherwise).

    Raises
    ------
    ValueError
        An unknown initial state.
    """
    init = np.zeros((n, 4))
    if isinstance(initial, SectionState):
        init[:] = (initial.y, initial.x_dot, _elongation(initial, systems, 0),
                   PHASE_CODE[initial.phase])
        return 2, init
    if isinstance(initial, np.ndarray) and initial.dtype == object:
        for i, s in enumerate(initial.ravel()):
            init[i] = (s.y, s.x_dot, _elongation(s, systems, i), PHASE_CODE[s.phase])
        return 2, init
    if isinstance(initial, str) and initial in ("sliding", "rest"):
        return (0 if initial == "sliding" else 1), init
    hint = ""
    if isinstance(initial, np.ndarray | list | tuple):
        # e.g. a 2-D history's plane_state: a start of vf.simulate, not of the steady state
        hint = (" (an array of numbers is a start of a time history, vibrofriction."
                "simulate; the steady state starts from a SectionState, e.g. a result's "
                "final_state)")
    raise ValueError(f"initial must be 'sliding', 'rest' or a SectionState, got "
                     f"{initial!r}{hint}")


#: The final-state columns that change sign under the mirror ``x -> -x``.
_SIGNED = ("mu_ratio", "y", "x_dot", "f", "e", "drift_rate")
_MIRROR_PHASE = {codes.SLIP_POS: codes.SLIP_NEG, codes.SLIP_NEG: codes.SLIP_POS}


def _mirror_rows(init: NDArray[np.float64], rows: NDArray[np.bool_]) -> None:
    """Mirror explicit start rows ``(y, x', e, phase)`` in place (``x -> -x``)."""
    init[rows, :3] = -init[rows, :3]
    ph = init[rows, 3].copy()
    for a, b in _MIRROR_PHASE.items():
        ph[init[rows, 3] == a] = b
    init[rows, 3] = ph


def _mirror_outputs(out_f: NDArray[np.float64], out_i: NDArray[np.int64],
                    rows: NDArray[np.bool_]) -> None:
    """The results of the mirrored problem as those of the given one, in place.

    The signed columns negated, the window range negated and swapped, slip+ and slip-
    swapped in the final phase.  ``reverse_slip_fraction`` (slip against the sliding
    direction) is unchanged.
    """
    for k in _SIGNED:
        j = column_index(k)
        out_f[rows, j] = -out_f[rows, j]
    lo, hi = column_index("window_min"), column_index("window_max")
    out_f[rows, lo], out_f[rows, hi] = -out_f[rows, hi], -out_f[rows, lo]
    jp = column_index("phase")
    ph = out_i[rows, jp]
    out_i[rows, jp] = np.where(ph == codes.SLIP_POS, codes.SLIP_NEG,
                               np.where(ph == codes.SLIP_NEG, codes.SLIP_POS, ph))


def solve_points(
    alpha: ArrayLike,
    beta: ArrayLike,
    amplitude: ArrayLike,
    v_inertial: ArrayLike,
    zeta: ArrayLike = 0.0,
    eta_c: ArrayLike = 0.0,
    a_x: ArrayLike = 0.0,
    phase_x: ArrayLike = 0.0,
    a_y: ArrayLike = 0.0,
    phase_y: ArrayLike = 0.0,
    alpha_y: ArrayLike | None = None,
    zeta_y: ArrayLike | None = None,
    profile_exponent: ArrayLike = math.inf,
    static_ratio: ArrayLike = 1.0,
    rs_a: ArrayLike = 0.0,
    rs_b: ArrayLike = 0.0,
    rs_d_c: ArrayLike = 1.0,
    rs_v_ref: ArrayLike = 1.0,
    rs_alpha_ld: ArrayLike = 0.0,
    *,
    inplane_on: str | ArrayLike = "substrate",
    rs_law: str | ArrayLike = "aging",
    initial: Initial | NDArray[np.object_] = "sliding",
    settings: SolverSettings | None = None,
) -> dict[str, NDArray]:
    """Steady states at arbitrary points: the batch engine.

    The parameters (:data:`vibrofriction.schema.POINT_COLUMNS`) broadcast together and are
    validated once against their ranges in :data:`vibrofriction.schema.PARAMETERS`
    (:func:`~vibrofriction.solver.points.point_table`).  Each point goes to the method
    :func:`~vibrofriction.solver.methods.choose` picks (a curved tip the MDR solver, a
    transverse oscillation the 2-D solver, else the 1-D event-driven solver); what each
    covers is declared in :data:`~vibrofriction.solver.methods.METHODS` (docs/solver.md,
    "What each solver covers").  ``V < 0`` is solved by the mirror ``x -> -x``: the point
    ``(-V, phase_x + pi)`` with ``mu_ratio`` and the signed state negated (an explicit
    initial state is mirrored on the way in).

    Parameters
    ----------
    alpha, beta, amplitude : array_like
        The stiffness ratios and the relative normal amplitude of eq. (20).
    v_inertial : array_like
        The sliding velocity ``v0 m omega/(mu0 F_N0)`` (Fig. 6); negative is backwards.
    zeta, eta_c : array_like, optional
        The damping of the oscillator and of the contact (docs/damping.md).
    a_x, phase_x : array_like, optional
        The in-plane oscillation along the sliding direction and its phase.
    a_y, phase_y, alpha_y, zeta_y : array_like or None, optional
        The transverse oscillation, its phase, and the transverse stiffness and damping
        (None: those of the sliding direction).
    profile_exponent : array_like, optional
        The tip's power-law exponent (``inf``: the flat punch).
    static_ratio : array_like, optional
        ``mu_static / mu0 >= 1`` (1: Coulomb friction; docs/friction_laws.md).
    rs_a, rs_b, rs_d_c, rs_v_ref, rs_alpha_ld : array_like, optional
        Rate-and-state friction in the model's units (``rs_a = 0``: Coulomb friction;
        docs/friction_laws.md).
    inplane_on : str or array_like of str, keyword-only
        Where the in-plane oscillation acts: ``"substrate"`` (default) or the other body;
        one name or an array of names.
    rs_law : str or array_like of str, keyword-only
        The state's evolution law of rate-and-state friction: ``"aging"`` (default) or
        ``"slip"``.
    initial : str, SectionState or ndarray of SectionState, keyword-only
        ``"sliding"`` (default), ``"rest"``, one :class:`SectionState` or one per point.
    settings : SolverSettings or None, keyword-only
        Accuracy and effort bounds; None takes :data:`DEFAULT_SETTINGS`.

    Returns
    -------
    dict of str to ndarray
        Arrays of the inputs' broadcast shape named by
        :data:`~vibrofriction.schema.FLOAT_COLUMNS` and ``INT_COLUMNS`` (``status`` as
        :attr:`Status.code`, ``method`` the index of the method in
        :data:`~vibrofriction.schema.METHOD_NAMES`; ``y``, ``x_dot``, ``f``, ``e``,
        ``phase`` the final section state, in the laboratory frame) and ``trusted``.
        Results are bitwise reproducible: each point depends only on its own parameters.

    Raises
    ------
    ValueError
        A parameter out of its range, or a point, initial state or setting its method
        does not cover (named, before anything is solved).
    TypeError
        A required parameter missing.

    Examples
    --------
    >>> from vibrofriction.solver import solve_points
    >>> out = solve_points(alpha=0.5, beta=2.0, amplitude=0.5, v_inertial=0.1)
    >>> float(out["mu_ratio"]), int(out["status"]), bool(out["trusted"])
    (0.596291293623..., 0, True)
    """
    points = point_table({
        "alpha": alpha, "beta": beta, "amplitude": amplitude, "v_inertial": v_inertial,
        "zeta": zeta, "eta_c": eta_c, "a_x": a_x, "phase_x": phase_x, "a_y": a_y,
        "phase_y": phase_y, "alpha_y": alpha_y, "zeta_y": zeta_y,
        "profile_exponent": profile_exponent, "static_ratio": static_ratio, "rs_a": rs_a,
        "rs_b": rs_b, "rs_d_c": rs_d_c, "rs_v_ref": rs_v_ref, "rs_alpha_ld": rs_alpha_ld,
        "inplane_on": inplane_on, "rs_law": rs_law})
    return solve_table(points, initial, settings or DEFAULT_SETTINGS)


def solve_table(points: PointTable, initial: Initial | NDArray[np.object_],
                settings: SolverSettings) -> dict[str, NDArray]:
    """:func:`solve_points` of a validated :class:`~vibrofriction.solver.points.PointTable`.

    Parameters
    ----------
    points : PointTable
        The points, validated (:func:`~vibrofriction.solver.points.point_table`).
    initial : str, SectionState or ndarray of SectionState
        The initial state, as in :func:`solve_points`.
    settings : SolverSettings
        Accuracy and effort bounds.

    Returns
    -------
    dict of str to ndarray
        The named output columns, as in :func:`solve_points`.

    Raises
    ------
    ValueError
        An initial state or setting a point's method does not cover.
    """
    n = len(points)
    kind, init = initial_rows(initial, n, points.system)
    chosen = choose(points["profile_exponent"], points["a_y"], points["rs_a"])
    parts = [(METHODS[name], np.flatnonzero(chosen == k))
             for k, name in enumerate(METHOD_NAMES)]
    for method, idx in parts:  # every refusal before any work
        if idx.size:
            method.capabilities.check(points.take(idx), kind, settings)
    sliding = sliding_mu_ratio(points)  # of the given velocities, before the mirror
    backward = points["v_inertial"] < 0.0
    if np.any(backward):  # the mirror x -> -x
        points = points.with_column("v_inertial", np.abs(points["v_inertial"]))
        points = points.with_column("phase_x", np.where(backward, points["phase_x"] + math.pi,
                                                        points["phase_x"]))
        if kind == 2:
            _mirror_rows(init, backward)
    out_f = np.full((n, len(FLOAT_COLUMNS)), np.nan)
    out_i = np.zeros((n, len(INT_COLUMNS)), dtype=np.int64)
    for method, idx in parts:
        if not idx.size:
            continue
        if idx.size == n:  # one method for every point: its rows as they are
            out_f, out_i = method.solve(points, kind, init, settings)
        else:
            out_f[idx], out_i[idx] = method.solve(points.take(idx), kind,
                                                  np.ascontiguousarray(init[idx]), settings)
    if np.any(backward):
        _mirror_outputs(out_f, out_i, backward)
    return _columns(points, out_f, out_i, sliding, settings)


def _columns(points: PointTable, out_f: NDArray[np.float64], out_i: NDArray[np.int64],
             sliding: NDArray[np.float64], settings: SolverSettings) -> dict[str, NDArray]:
    """The named output columns of the rows ``out_f``, ``out_i``, shaped as ``points``.

    ``sliding`` is their ``sliding_mu_ratio``; ``trusted`` is added from ``settings``.
    """
    out_f[:, _O_SLIDING] = sliding
    out: dict[str, NDArray] = {k: out_f[:, j].reshape(points.shape)
                               for j, k in enumerate(FLOAT_COLUMNS)}
    out.update({k: out_i[:, j].reshape(points.shape) for j, k in enumerate(INT_COLUMNS)})
    out["trusted"] = settings.trusted(out["status"], out["error"])
    return out


def solve_chain(points: PointTable, initial: Initial, settings: SolverSettings,
                restart: NDArray[np.bool_] | None = None) -> dict[str, NDArray]:
    """A continuation: the points of a 1-D table solved in turn, each from the one before.

    Point ``i > 0`` starts from the final section state of point ``i - 1``
    (:func:`~.results.section_state`), or from ``initial`` where that has none (a static
    point, a failed one) or where ``restart[i]`` (a new curve): the columns of
    :func:`solve_table` of each point with that start.  The event-driven solver's points
    with ``V > 0`` (or static: ``V = 0`` without an in-plane oscillation) run in one
    compiled loop; the others are solved one by one in between.

    Parameters
    ----------
    points : PointTable
        The points, validated, one-dimensional, in the order of the continuation.
    initial : str or SectionState
        The start of the first point (and of any point whose predecessor has no state).
    settings : SolverSettings
        Accuracy and effort bounds.
    restart : ndarray of bool, optional
        The points that start from ``initial`` whatever precedes them (several curves in
        one table).

    Returns
    -------
    dict of str to ndarray
        The named output columns, as in :func:`solve_points`.
    """
    n = len(points)
    restart = np.zeros(n, dtype=bool) if restart is None else np.asarray(restart, dtype=bool)
    V = points["v_inertial"]
    method = choose(points["profile_exponent"], points["a_y"], points["rs_a"])
    fast = (method == _EVENT) & ((V > 0.0) | ((V == 0.0) & (points["a_x"] == 0.0)))
    plane = (method == _PLANE) & (V > 0.0)
    cols = {k: np.empty(n, dtype=np.float64) for k in FLOAT_COLUMNS} \
        | {k: np.empty(n, dtype=np.int64) for k in INT_COLUMNS} \
        | {"trusted": np.empty(n, dtype=bool)}
    state: SectionState | None = None  # the last point's final state
    j = 0
    one_by_one = False  # the next point's start needs its system (an elongation to derive)
    while j < n:
        if restart[j]:
            state = None
        if fast[j] and not one_by_one:
            stop = j + 1
            while stop < n and fast[stop]:
                stop += 1
            part, done = _chain_run(points.take(np.arange(j, stop)), initial, state,
                                    restart[j:stop], settings)
            one_by_one = done < stop - j
            if done == 0:
                continue
        elif plane[j]:
            stop = j + 1
            while stop < n and plane[stop]:
                stop += 1
            part = _plane_run(points.take(np.arange(j, stop)), initial, state,
                              restart[j:stop], settings)
            done, one_by_one = stop - j, False
        else:
            part, done = solve_table(points.take(np.array([j])),
                                     state if state is not None else initial, settings), 1
            one_by_one = False
        for k, v in part.items():
            cols[k][j:j + done] = v[:done]
        state = _final_state(part, done - 1)
        j += done
    return cols


def _chain_run(run: PointTable, initial: Initial, state: SectionState | None,
               restart: NDArray[np.bool_], settings: SolverSettings
               ) -> tuple[dict[str, NDArray], int]:
    """:func:`solve_chain` of ``run`` (the event solver's points) in one compiled loop.

    The first point starts from ``state`` (the final state before the run), or where
    there is none from ``initial``, as does any point whose predecessor has no state or
    that restarts.  Returns the columns and how many points were solved (fewer than all
    where a final state lacks its elongation: the caller derives it from the next
    point's system).
    """
    kind, init = initial_rows(initial, len(run), run.system)
    link = np.where(restart, LINK_OWN, LINK_PREVIOUS).astype(np.int8)
    if state is not None and not math.isfinite(state.e):
        return {}, 0  # its elongation from the first point's system: one by one
    if state is not None:
        init[0] = (state.y, state.x_dot, state.e, PHASE_CODE[state.phase])
        link[0] = LINK_GIVEN
    else:
        link[0] = LINK_OWN
    for start_kind in {kind, 2}:  # the own start, and a predecessor's state
        EVENT.capabilities.check(run, start_kind, settings)
    out_f, out_i, done = EVENT.solve_chain(run, kind, init, link, settings)
    return _columns(run, out_f, out_i, sliding_mu_ratio(run), settings), done


def _plane_run(run: PointTable, initial: Initial, state: SectionState | None,
               restart: NDArray[np.bool_], settings: SolverSettings) -> dict[str, NDArray]:
    """:func:`solve_chain` of ``run``, the 2-D solver's points (``V > 0``), in one loop.

    Each point starts from the whole final section state of the one before (its transverse
    components too) where that is a periodic orbit.  The first point starts from ``state``
    (the final state of another method's point before the run: its ``x`` components), or
    where there is none from ``initial``.
    """
    kind, init = initial_rows(initial, len(run), run.system)
    link = np.where(restart, LINK_OWN, LINK_PREVIOUS).astype(np.int8)
    link[0] = LINK_OWN
    if state is not None:
        init[0] = initial_rows(state, 1, run.system)[1][0]
        link[0] = LINK_GIVEN
    for start_kind in {kind, 2}:  # the own start, and a predecessor's state
        PLANE.capabilities.check(run, start_kind, settings)
    out_f, out_i = PLANE.solve_chain(run, kind, init, link, settings)
    return _columns(run, out_f, out_i, sliding_mu_ratio(run), settings)


def _final_state(cols: dict[str, NDArray], j: int) -> SectionState | None:
    """The final section state of row ``j`` of the columns ``cols`` (None: none)."""
    y, x_dot, f, e = (float(cols[k][j]) for k in ("y", "x_dot", "f", "e"))
    return section_state(y, x_dot, f, int(cols["phase"][j]), e)


_N_FLOAT, _N_INT = len(FLOAT_COLUMNS), len(INT_COLUMNS)
_O_STICK, _O_SLIP, _O_REVERSE, _O_FLIGHT = (column_index(k) for k in (
    "stick_fraction", "slip_fraction", "reverse_slip_fraction", "flight_fraction"))
_O_NORMAL, _O_STICK_AREA, _O_SLIP_AREA, _O_OPEN_AREA = (column_index(k) for k in (
    "mean_normal_ratio", "stick_area_fraction", "slip_area_fraction", "open_area_fraction"))
_I_METHOD = column_index("method")
_EVENT, _PLANE = METHOD_NAMES.index("event"), METHOD_NAMES.index("plane")
_O_SLIDING = column_index("sliding_mu_ratio")


def sliding_mu_ratio(points: PointTable) -> NDArray[np.float64]:
    """``mu_ss(V)/mu0`` of each point: steady sliding without oscillation at its velocity.

    Signed as ``mu_ratio`` (odd in ``V``): ``sign(V)`` for Coulomb friction (``rs_a = 0``; 1 at
    ``V = 0``); rate-and-state friction :func:`vibrofriction.theory.steady_mu_ratio` (nan at
    ``V = 0``, where there is no steady sliding).
    """
    out = np.where(points["v_inertial"] < 0.0, -1.0, 1.0)
    rs = np.flatnonzero(points["rs_a"] > 0.0)
    if rs.size:
        V = np.abs(points["v_inertial"][rs])
        with np.errstate(divide="ignore", invalid="ignore"):
            mu = theory.steady_mu_ratio(np.where(V > 0.0, V, 1.0), points["rs_a"][rs],
                                        points["rs_b"][rs], points["rs_d_c"][rs],
                                        points["rs_v_ref"][rs])
        out[rs] = np.where(V > 0.0, np.sign(points["v_inertial"][rs]) * mu, np.nan)
    return out

#: Kernel start of the named initial states: ``(kind, y, x', e, phase)``.
_NAMED_START = {"sliding": (0, 0.0, 0.0, 0.0, 0), "rest": (1, 0.0, 0.0, 0.0, 0)}


def _one_point(dim: Dimensionless, V: float, initial: Initial,
               settings: SolverSettings) -> FrictionResult:
    """One moving point by the scalar kernel directly (no array bookkeeping)."""
    start = _NAMED_START.get(initial) if initial.__class__ is str else None
    if start is None:
        kind, init = initial_rows(initial, 1, lambda i: dim)
        start = (kind, init[0, 0], init[0, 1], init[0, 2], int(init[0, 3]))
    of = np.empty(_N_FLOAT)
    oi = np.empty(_N_INT, dtype=np.int64)
    steady_state(dim.alpha, dim.beta, dim.amplitude, V, dim.zeta, dim.eta_c, dim.a_x,
                 dim.phase_x, dim.inplane_on == "substrate", dim.static_ratio, *start,
                 *event_arguments(settings), of, oi, False)  # warm: the signature in the cache
    f = of.tolist()  # the contact's columns (as contact_columns), on Python floats
    f[_O_NORMAL] = theory.mean_normal_force_of(dim.amplitude)
    f[_O_STICK_AREA] = f[_O_STICK]
    f[_O_SLIP_AREA] = f[_O_SLIP] + f[_O_REVERSE]
    f[_O_OPEN_AREA] = f[_O_FLIGHT]
    f[_O_SLIDING] = 1.0  # Coulomb friction, V > 0
    ints = oi.tolist()
    ints[_I_METHOD] = 0  # the event method
    return result_from_rows(f, ints, dim, V, settings)


@overload
def friction_coefficient(system: System, vbar: float, *, v_inertial: None = None,
                         v0: None = None, initial: Initial = "sliding",
                         settings: SolverSettings | None = None) -> FrictionResult: ...
@overload
def friction_coefficient(system: System, vbar: None = None, *, v_inertial: float,
                         v0: None = None, initial: Initial = "sliding",
                         settings: SolverSettings | None = None) -> FrictionResult: ...
@overload
def friction_coefficient(system: System, vbar: None = None, *, v_inertial: None = None,
                         v0: float, initial: Initial = "sliding",
                         settings: SolverSettings | None = None) -> FrictionResult: ...
@overload
def friction_coefficient(system: System, vbar: ArrayLike | None = None, *,
                         v_inertial: ArrayLike | None = None, v0: ArrayLike | None = None,
                         initial: Initial = "sliding", settings: SolverSettings | None = None
                         ) -> FrictionResult | FrictionResults: ...
def friction_coefficient(
    system: System,
    vbar: ArrayLike | None = None,
    *,
    v_inertial: ArrayLike | None = None,
    v0: ArrayLike | None = None,
    initial: Initial = "sliding",
    settings: SolverSettings | None = None,
) -> FrictionResult | FrictionResults:
    """Macroscopic coefficient of friction ``mu_macro/mu0`` in the steady state (eq. 25).

    Parameters
    ----------
    system : Dimensionless or Physical
        A :class:`Dimensionless` system ``(alpha, beta, amplitude)`` (eq. 20) or a
        :class:`Physical` system in SI units.
    vbar, v_inertial, v0 : float or array_like
        The sliding velocity, exactly one of: ``v0/v0*`` (eq. 16), ``v0 m omega/(mu0
        F_N0)`` (Fig. 6; required in cases III and IV), or m/s (Physical systems only);
        :func:`vibrofriction.params.inertial_velocity`.  Scalars give a
        :class:`FrictionResult`, arrays a :class:`FrictionResults` of the same shape.
    initial : str or SectionState, keyword-only
        ``"sliding"`` (default: steady sliding before the oscillation is switched on at
        ``tau = 0``, docs/model.md; at ``V = 0`` the rest), ``"rest"``, or a
        :class:`SectionState` (e.g. the ``final_state`` of another result, for
        continuation).  Coexisting attractors make the initial state part of the
        result's definition.
    settings : SolverSettings or None, keyword-only
        Accuracy and effort bounds (:class:`SolverSettings`); None the defaults.

    Returns
    -------
    FrictionResult or FrictionResults
        One result for a scalar velocity, results of the velocities' shape for an array.

    Raises
    ------
    ValueError
        Not exactly one velocity given, ``vbar`` where ``v0*`` does not exist (cases III
        and IV), ``v0`` of a dimensionless system, or a point, initial state or setting
        the solver does not cover.
    TypeError
        A system that is neither :class:`Dimensionless` nor :class:`Physical`.

    Examples
    --------
    >>> import vibrofriction as vf
    >>> system = vf.Dimensionless(alpha=0.5, beta=2.0, amplitude=0.5)
    >>> r = vf.friction_coefficient(system, vbar=0.3)
    >>> r.mu_ratio, r.status, r.trusted
    (0.597600554641..., <Status.PERIODIC: 'periodic'>, True)
    """
    dim = dimensionless(system)
    V = inertial_velocity(system, vbar, v_inertial=v_inertial, v0=v0)
    if V.__class__ is float and V > 0.0 and dim.rs_a == 0.0 \
            and method_of(dim.profile_exponent, dim.a_y, dim.rs_a) is EVENT:  # one moving point
        return _one_point(dim, V, initial, settings or DEFAULT_SETTINGS)
    V = np.asarray(V, dtype=float)
    cols = solve_table(table_of(dim, V), initial, settings or DEFAULT_SETTINGS)
    if V.ndim == 0:
        return result_from_columns({k: v[()].item() for k, v in cols.items()}, dim, float(V))
    return results_from_columns(cols, dim, V)
