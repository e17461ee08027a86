"""Time histories sampled from the closed forms (paper Fig. 2), with exact events."""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._kernels import codes
from .._kernels import plane as _plane
from .._kernels.integrate import TWO_PI, initial_point, run_periods, sample, to_kernel_frame
from .._kernels.phases import frame_offset
from ..params import Dimensionless, System, dimensionless, inertial_velocity
from ..schema import FLOAT_COLUMNS, INT_COLUMNS, Status, column_index
from .energy import dissipation, inplane_motion, kernel_point, transverse_motion
from .engine import _MIRROR_PHASE, friction_coefficient, initial_rows
from .history_types import CurvedHistory, Event, History, PlaneHistory, RateStateHistory
from .mdr_history import SPRINGS, mdr_history
from .methods.event import EVENT
from .methods.mdr import MDR
from .methods.plane import PLANE, plane_arguments, plane_held
from .points import table_of
from .rate_state_history import rate_state_history
from .results import SectionState, section_state
from .settings import DEFAULT_SETTINGS, SolverSettings

__all__ = ["CurvedHistory", "Event", "History", "PlaneHistory", "RateStateHistory", "simulate"]


def _checked_run(periods: float, samples_per_period: int) -> None:
    if not (math.isfinite(periods) and periods > 0):
        raise ValueError(f"periods must be finite and > 0, got {periods!r}")
    # the annotation says int, the caller may pass anything: the check stays
    if not (isinstance(samples_per_period, int)  # type: ignore[redundant-expr]
            and samples_per_period >= 2):
        raise ValueError(f"samples_per_period must be an integer >= 2, got {samples_per_period!r}")


def _start(dim: Dimensionless, V: float, initial: str | SectionState,
           settings: SolverSettings | None) -> tuple[float, float, float, float, int]:
    """The start ``(y, x', e, e', phase)`` (the order of ``run_periods``).

    ``"steady"`` is the trusted steady state's.
    """
    if isinstance(initial, str) and initial == "steady":
        steady = friction_coefficient(dim, v_inertial=V, settings=settings)
        if steady.final_state is None or not steady.trusted:
            raise ValueError(f"initial='steady': no trusted steady state at this point "
                             f"({steady.message})")
        initial = steady.final_state
    kind, init = initial_rows(initial, 1, lambda i: dim)
    if kind == 2:  # a laboratory state: into the kernels' frame (docs/inplane.md)
        y, xd = to_kernel_frame(frame_offset(*kernel_point(dim, V)[6:9]), init[0, 0], init[0, 1])
        return y, xd, init[0, 2], math.nan, int(init[0, 3])
    if kind == 0 and V == 0.0 and dim.a_x > 0.0:
        kind = 1  # "sliding" has no direction at V = 0: the rest, as in solve_points
    if V < 0.0:  # the named starts of -V mirrored (x -> -x, phase_x + pi), as in solve_points
        mirror = replace(dim, phase_x=dim.phase_x + math.pi)
        y, xd, e, phase, e_dot = initial_point(kind, *kernel_point(mirror, -V))
        return -y, -xd, -e, -e_dot, _MIRROR_PHASE.get(phase, phase)
    y, xd, e, phase, e_dot = initial_point(kind, *kernel_point(dim, V))
    return y, xd, e, e_dot, phase


def _segments(dim: Dimensionless, V: float, start: tuple[float, float, float, float, int],
              whole: int) -> NDArray[np.float64]:
    """The segment rows (:data:`codes.SEG_TAU` ...) of ``whole`` drive periods."""
    cap = 4096 * whole
    while True:
        seg = np.empty((cap, codes.N_SEG_COLUMNS))
        m = run_periods(0.0, *start, *kernel_point(dim, V), whole, cap, seg)
        if m > 0:
            return seg[:m]
        cap *= 4


def simulate(
    system: System,
    vbar: float | None = None,
    *,
    v_inertial: float | None = None,
    v0: float | None = None,
    periods: float = 5.0,
    samples_per_period: int = 400,
    initial: str | SectionState | NDArray[np.float64] = "sliding",
    settings: SolverSettings | None = None,
    springs: int = SPRINGS,
) -> History:
    """Time history over ``periods`` drive periods, sampled from the closed forms (Fig. 2).

    ``final_state`` is the state on the last Poincare section within the history,
    ``tau = 2 pi floor(periods)``.  ``V < 0`` is integrated as it stands, from the mirror
    image of the named start of ``-V`` (``"sliding"``: ``x' = V``, the spring stretched by
    ``-1``); at ``V = 0`` with an in-plane oscillation ``"sliding"`` is the rest (as in
    :func:`solve_points`).

    With a transverse oscillation (``a_y > 0``) the history is integrated by the 2-D
    solver's Runge-Kutta method (docs/inplane.md section 6): a :class:`PlaneHistory`, with
    the transverse fields; ``initial`` may also be a 2-D history's ``plane_state`` (6
    components), and a :class:`SectionState` starts with the transverse components 0.

    A curved tip (finite ``profile_exponent``) is the MDR row of ``springs`` springs
    (:func:`~vibrofriction.solver.mdr_history.mdr_history`), sampled on the uniform grid
    only (no event times): a :class:`CurvedHistory`, with the contact fields; ``initial``
    is ``"sliding"`` (the MDR solver's start) or ``"steady"`` (the row's periodic orbit);
    the refusals of the MDR solver apply (docs/contact_geometry.md).

    Rate-and-state friction (``rs_a > 0``) is the rate-and-state solver's Rosenbrock
    integration, its steps ending at each sample time (docs/friction_laws.md, "Time
    histories"): a :class:`RateStateHistory`, with the state ``theta``, the local
    coefficient ``local_mu`` and the slip velocity; ``initial`` is ``"sliding"`` (the
    solver's start) or ``"steady"`` (with the steady state's ``theta``); the refusals of the
    rate-and-state solver apply.

    Parameters
    ----------
    system : Dimensionless or Physical
        The system, as in :func:`friction_coefficient`.
    vbar, v_inertial, v0 : float
        The sliding velocity, exactly one of them, as in :func:`friction_coefficient`.
    periods : float, keyword-only
        The drive periods simulated (default 5).
    samples_per_period : int, keyword-only
        The uniform samples a period (default 400); the 1-D and 2-D histories add the
        event times.
    initial : str, SectionState or ndarray, keyword-only
        ``"sliding"`` (default), ``"rest"``, a :class:`SectionState`, or ``"steady"``: the
        final section state of :func:`friction_coefficient` at the same point, so the
        history shows the steady state rather than the transient; with a transverse
        oscillation also a 2-D history's ``plane_state``.
    settings : SolverSettings or None, keyword-only
        The settings of the steady state that ``initial="steady"`` solves (a curved tip:
        its row's orbit) and of the 2-D and rate-and-state integrations (``rtol``); None
        the defaults. A setting the
        point's solver does not honour is refused, as by :func:`solve_points`.
    springs : int, keyword-only
        The springs of a curved tip's MDR row (ignored otherwise).

    Returns
    -------
    History
        The 1-D solver's :class:`History`, a :class:`PlaneHistory` with a transverse
        oscillation, a :class:`CurvedHistory` for a curved tip, or a
        :class:`RateStateHistory` with rate-and-state friction.

    Raises
    ------
    ValueError
        ``initial="steady"`` where that result has no section state or is not trusted,
        an initial state the solver does not take, or the velocities as in
        :func:`friction_coefficient`.

    Examples
    --------
    >>> import vibrofriction as vf
    >>> system = vf.Dimensionless(alpha=0.5, beta=2.0, amplitude=0.5)
    >>> h = vf.simulate(system, vbar=0.3, periods=2)
    >>> h.tau.shape, [e.kind for e in h.events]
    ((809,), ['stick->slip', 'slip->stick', 'stick->slip', 'slip->stick'])
    """
    dim = dimensionless(system)
    v = np.asarray(inertial_velocity(system, vbar, v_inertial=v_inertial, v0=v0), dtype=float)
    if v.ndim != 0:
        raise ValueError("simulate takes one velocity, got an array")
    V = float(v)
    _checked_run(periods, samples_per_period)
    if dim.curved:
        settings = settings or DEFAULT_SETTINGS
        MDR.capabilities.check(table_of(dim, V), 0, settings)
        # the annotation is not enforced at run time: a bool, a float or 0 is refused here
        if isinstance(springs, bool) or not isinstance(  # type: ignore[redundant-expr]
                springs, (int, np.integer)) or springs < 1:
            raise ValueError(f"springs must be an integer >= 1, got {springs!r}")
        return mdr_history(dim, V, periods, samples_per_period, initial, springs, settings)
    if dim.a_y > 0.0:
        return _plane_history(dim, V, periods, samples_per_period, initial, settings)
    if dim.rs_a > 0.0:
        return rate_state_history(dim, V, periods, samples_per_period, initial, settings)
    # a plane_state array as initial is for the 2-D run; initial_rows refuses it here
    # refused as by solve_points (the limits and the settings), whatever the start
    EVENT.capabilities.check(table_of(dim, V), 0, settings or DEFAULT_SETTINGS)
    start = _start(dim, V, initial, settings)  # type: ignore[arg-type]
    seg = _segments(dim, V, start, int(math.ceil(periods)))
    m = seg.shape[0]
    tau_end = TWO_PI * periods
    grid = np.linspace(0.0, tau_end, int(round(samples_per_period * periods)) + 1)
    ev_rows = [j for j in range(1, m) if int(seg[j, codes.SEG_EVENT]) != codes.EV_SECTION
               and seg[j, codes.SEG_TAU] <= tau_end]
    ev_tau = seg[ev_rows, codes.SEG_TAU]
    # each event time twice: the end of one phase and the start of the next
    eps = 1e-12 * max(1.0, tau_end)
    taus = np.sort(np.concatenate([grid, ev_tau - eps, ev_tau]))
    taus = taus[(taus >= 0.0) & (taus <= tau_end)]
    out = np.empty((taus.size, codes.N_SMP_COLUMNS))
    sample(seg, m, *kernel_point(dim, V), taus, out)
    phases = np.asarray(codes.PHASE_NAMES, dtype=str)
    events = tuple(
        Event(float(seg[j, codes.SEG_TAU]), codes.EVENT_NAMES[int(seg[j, codes.SEG_EVENT])],
              codes.PHASE_NAMES[int(seg[j - 1, codes.SEG_PHASE])],
              codes.PHASE_NAMES[int(seg[j, codes.SEG_PHASE])])
        for j in ev_rows)
    whole_done = int(math.floor(periods + 1e-12))
    last = seg[np.flatnonzero(seg[:, codes.SEG_TAU] <= TWO_PI * whole_done * (1 + 1e-14))[-1]]
    x, x_dot = out[:, codes.SMP_Y] + V * taus, out[:, codes.SMP_XD]
    y_last, xd_last = last[codes.SEG_Y], last[codes.SEG_XD]
    if dim.a_x > 0.0 and dim.inplane_on == "substrate":  # back to the laboratory frame
        X, Xd = inplane_motion(dim, taus)
        x, x_dot = x + X, x_dot + Xd
        X0, Xd0 = inplane_motion(dim, last[codes.SEG_THETA])
        y_last, xd_last = y_last + X0, xd_last + Xd0
    return History(
        tau=taus, x=x, x_dot=x_dot,
        f=out[:, codes.SMP_F], n=out[:, codes.SMP_N],
        phase=phases[out[:, codes.SMP_PHASE].astype(int)], events=events, system=dim,
        v_inertial=V, e=out[:, codes.SMP_E], **dissipation(seg, m, dim, V, taus),
        final_state=section_state(y_last, xd_last, last[codes.SEG_F],
                                  int(last[codes.SEG_PHASE]), last[codes.SEG_E]))


def _plane_parameters(dim: Dimensionless, V: float) -> NDArray[np.float64]:
    return _plane.parameters(dim.alpha, dim.beta, dim.amplitude, V, dim.zeta, dim.eta_c,
                             dim.a_x, dim.phase_x, dim.a_y, dim.phase_y, *dim.pin_y,
                             dim.inplane_on == "substrate", dim.static_ratio)


def _plane_start(dim: Dimensionless, V: float, initial: object,
                 settings: SolverSettings | None) -> tuple[NDArray[np.float64], int]:
    """The 2-D start ``(y_x, y_y, v_x, v_y, e_x, e_y)`` at ``tau = 0`` and its phase.

    The phase is the steady orbit's at its section for ``"steady"``, slip for
    ``"sliding"`` (slipping where the state allows it, as the 2-D solver's start), else
    stick (a contact with no history starts stuck); it matters only where ``static_ratio
    > 1`` (:func:`vibrofriction._kernels.plane.entry_hint`).
    """
    s = np.zeros(_plane.N_S + 1)
    s[_plane.N_S] = codes.STICK
    if isinstance(initial, str) and initial == "steady":
        settings = settings or DEFAULT_SETTINGS
        mirror = V < 0.0  # as solve_points: the point (-V, phase_x + pi), mirrored back
        px = dim.phase_x + math.pi if mirror else dim.phase_x
        of = np.empty(len(FLOAT_COLUMNS))
        oi = np.empty(len(INT_COLUMNS), dtype=np.int64)
        _plane.plane_steady_section(
            dim.alpha, dim.beta, dim.amplitude, abs(V), dim.zeta, dim.eta_c, dim.a_x, px,
            dim.a_y, dim.phase_y, *dim.pin_y, dim.inplane_on == "substrate", 0, 0.0, 0.0, 0.0,
            *plane_arguments(settings), of, oi, s, dim.static_ratio)
        status, error = int(oi[column_index("status")]), float(of[column_index("error")])
        if V == 0.0 and plane_held(
                np.array([status]), np.array([of[column_index("stick_fraction")]]),
                table_of(dim, V), dim.inplane_on)[0]:
            status = Status.HELD.code  # as solve_points: a held body has no steady state
        if not settings.trusted(status, error):
            raise ValueError(f"initial='steady': no trusted steady state at this point "
                             f"(status {Status.from_code(status).value}, error {error:.3g})")
        if mirror:
            s[[0, 2, 4]] = -s[[0, 2, 4]]
        return s[:_plane.N_S], int(s[_plane.N_S])
    if isinstance(initial, str):
        kind = {"sliding": 0, "rest": 1}.get(initial)
        if kind is None:
            raise ValueError(f"initial must be 'sliding', 'rest', 'steady', a SectionState "
                             f"or a plane_state, got {initial!r}")
        _plane.start_state(_plane_parameters(dim, V), kind, 0.0, 0.0, 0.0, s)
        return s[:_plane.N_S], _plane.SLIP if kind == 0 else codes.STICK
    if isinstance(initial, SectionState):
        s[0], s[2], s[4] = initial.y, initial.x_dot, initial.elongation(dim)
        return s[:_plane.N_S], codes.STICK
    arr = np.asarray(initial, dtype=float)
    if arr.shape != (_plane.N_S,) or not np.all(np.isfinite(arr)):
        raise ValueError(f"a 2-D initial state is 6 finite numbers (y_x, y_y, v_x, v_y, "
                         f"e_x, e_y), got {initial!r}")
    return arr.copy(), codes.STICK


def _plane_history(dim: Dimensionless, V: float, periods: float, samples_per_period: int,
                   initial: object, settings: SolverSettings | None) -> PlaneHistory:
    """:func:`simulate` with a transverse oscillation: the 2-D kernel's history."""
    settings = settings or DEFAULT_SETTINGS
    PLANE.capabilities.check(table_of(dim, V), 1, settings)  # V = 0 is integrated
    start, hint = _plane_start(dim, V, initial, settings)
    P = _plane_parameters(dim, V)
    whole = int(math.ceil(periods))
    tau_end = TWO_PI * periods
    whole_done = int(math.floor(periods + 1e-12))
    sections = TWO_PI * np.arange(1, whole_done + 1)
    grid = np.unique(np.concatenate([
        np.linspace(0.0, tau_end, int(round(samples_per_period * periods)) + 1), sections]))
    grid = grid[grid <= tau_end]
    cap = grid.size + 64 * whole
    rtol, _, max_switches = plane_arguments(settings)
    while True:
        out = np.empty((cap, _plane.N_H))
        m = _plane.plane_history(P, start, whole, grid, rtol, max_switches, out, hint)
        if m < 0:
            raise RuntimeError("the 2-D history failed: a step could not be taken or the "
                               "contact chattered (more stick/slip switches per period than "
                               f"max_events_per_period = {max_switches})")
        if m <= cap:
            break
        cap = m
    out = out[:m]
    out = out[out[:, _plane.H_TAU] <= tau_end]
    tau = out[:, _plane.H_TAU]
    y, v, e = (out[:, j:j + 2] for j in (_plane.H_Y, _plane.H_V, _plane.H_E))
    f, n = out[:, _plane.H_F:_plane.H_F + 2], out[:, _plane.H_N]
    mode = out[:, _plane.H_PHASE].astype(int)
    ph = np.where(mode == _plane.SLIP, np.where(f[:, 0] >= 0.0, codes.SLIP_POS,
                                                codes.SLIP_NEG), mode)
    names = np.asarray(codes.PHASE_NAMES, dtype=str)
    ev = out[:, _plane.H_EVENT].astype(int)
    pairs = []  # every event is a pair of rows: before and after the switch
    j = 0
    while j < len(tau) - 1:
        if ev[j] >= 0:
            pairs.append(Event(float(tau[j]), codes.EVENT_NAMES[ev[j]], str(names[ph[j]]),
                               str(names[ph[j + 1]])))
            j += 1
        j += 1
    events = tuple(pairs)
    x, x_dot = y[:, 0] + V * tau, v[:, 0]
    slip = out[:, _plane.H_SLIP:_plane.H_SLIP + 2]
    energy = _plane_energy(dim, V, tau, x, y[:, 1], v, e, f, slip, ev)
    # the last section within the history (tau = 0, the start, for less than a period)
    r = np.flatnonzero((tau == TWO_PI * whole_done) & (ev < 0))[-1]
    plane_state = np.concatenate([y[r], v[r], e[r]])
    final = section_state(y[r, 0], v[r, 0], f[r, 0], int(ph[r]), e[r, 0])
    return PlaneHistory(
        tau=tau, x=x, x_dot=x_dot, f=f[:, 0].copy(), n=n.copy(), phase=names[ph],
        events=events, system=dim, v_inertial=V, e=e[:, 0].copy(), **energy,
        final_state=final, u_y=y[:, 1].copy(), u_y_dot=v[:, 1].copy(), f_y=f[:, 1].copy(),
        e_y=e[:, 1].copy(), slip_velocity=slip.copy(),
        impulse=out[:, _plane.H_INT:_plane.H_INT + 2].copy(), plane_state=plane_state)


def _cumulative(tau: NDArray[np.float64], p: NDArray[np.float64]) -> NDArray[np.float64]:
    """The trapezoidal rule's running integral of the samples ``p`` over ``tau``."""
    return np.concatenate([[0.0], np.cumsum(0.5 * (p[1:] + p[:-1]) * np.diff(tau))])


def _plane_energy(dim: Dimensionless, V: float, tau: NDArray[np.float64],
                  x: NDArray[np.float64], uy: NDArray[np.float64], v: NDArray[np.float64],
                  e: NDArray[np.float64], f: NDArray[np.float64],
                  slip: NDArray[np.float64], ev: NDArray[np.int64]) -> dict[str, Any]:
    """Work input and dissipation of a 2-D history, by the trapezoidal rule over the samples.

    The reference's definitions (vibrofriction_reference.inplane).  With ``static_ratio >
    1`` a Jenkins contact's elongation jumps at each stick->slip (``ev``: the rows' event
    codes) from the static circle to the kinetic one: the contact spring's energy lost
    there, ``k (|e_before|^2 - |e_after|^2)/2``, is friction's too.
    """
    X, Xd = inplane_motion(dim, tau)
    Y, Yd = transverse_motion(dim, tau)
    zero = np.zeros_like(tau)
    if dim.inplane_on == "holder":
        h = np.stack([V * tau + X, Y], axis=1)
        hd = np.stack([V + Xd, Yd], axis=1)
        vs = np.stack([zero, zero], axis=1)
    else:
        h = np.stack([V * tau, zero], axis=1)
        hd = np.stack([V + zero, zero], axis=1)
        vs = np.stack([Xd, Yd], axis=1)
    u = np.stack([x, uy], axis=1)
    alpha_y, zeta_y = dim.pin_y
    stiffness = np.array([dim.alpha, alpha_y])  # the pin along and across the sliding
    gamma = 2.0 * np.array([dim.zeta, zeta_y]) * np.sqrt(stiffness)
    c = dim.eta_c * (dim.beta - dim.alpha)
    f_pin = stiffness * (h - u) + gamma * (hd - v)
    e_dot = v - vs - slip
    p_in = np.sum(f_pin * hd, axis=1) - np.sum(f * vs, axis=1)
    return {
        "work_input": _cumulative(tau, p_in),
        "dissipated_pin": _cumulative(tau, np.sum(gamma * (hd - v) ** 2, axis=1)),
        "dissipated_contact": _cumulative(tau, c * np.sum(e_dot**2, axis=1)),
        "dissipated_friction": _cumulative(tau, np.sum(f * slip, axis=1))
        + _jump_dissipation(dim, tau, e, ev),
    }


def _jump_dissipation(dim: Dimensionless, tau: NDArray[np.float64], e: NDArray[np.float64],
                      ev: NDArray[np.int64]) -> NDArray[np.float64] | float:
    """The running sum of the contact spring's energy lost in the jumps of a 2-D history.

    Each stick->slip of a Jenkins contact (``eta_c = 0``) with ``static_ratio > 1``: the
    pair of rows at one time (before, after), ``k (|e_before|^2 - |e_after|^2)/2``.  0
    otherwise (a Kelvin-Voigt contact's elongation does not jump).
    """
    if dim.static_ratio == 1.0 or dim.eta_c > 0.0:
        return 0.0
    k = dim.beta - dim.alpha
    j = np.flatnonzero((ev[:-1] == codes.EV_STICK_TO_SLIP) & (ev[1:] == codes.EV_STICK_TO_SLIP)
                       & (tau[:-1] == tau[1:]))
    lost = np.zeros_like(tau)
    lost[j + 1] = 0.5 * k * (np.sum(e[j] ** 2, axis=1) - np.sum(e[j + 1] ** 2, axis=1))
    return np.cumsum(lost)
