"""Time histories sampled from the closed forms (paper Fig. 2), with exact events."""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np
from numpy.typing import NDArray

from .._kernels import codes
from .._kernels.integrate import TWO_PI, initial_point, run_periods, sample, to_kernel_frame
from .._kernels.phases import frame_offset
from ..params import Dimensionless, Physical, System, dimensionless, inertial_velocity
from .energy import dissipation, inplane_motion, kernel_point
from .engine import _MIRROR_PHASE, friction_coefficient, initial_rows
from .results import SectionState, section_state
from .settings import SolverSettings

__all__ = ["Event", "History", "simulate"]


@dataclass(frozen=True)
class Event:
    """A transition at drive time ``tau``: ``kind`` and the phases before and after."""

    tau: float
    kind: str
    before: str
    after: str


@dataclass(frozen=True)
class History:
    """A time history sampled from the closed forms (Fig. 2).

    All quantities are scaled (docs/model.md): ``tau = omega t``; ``x`` body position and
    ``x_dot`` its velocity (units ``mu0 F_N0/(m omega^2)`` and ``mu0 F_N0/(m omega)``);
    ``f`` the tangential contact force and ``n`` the ``mu0``-scaled normal force, both
    in units of ``mu0 F_N0``; ``phase`` the phase name at each sample; ``events``
    every transition with its exact time.  Sample times include every event time
    (on both sides), so phase boundaries are sharp.  ``e`` is the elongation of the
    contact spring; ``work_input`` the work done by the pulled end since the start and
    ``dissipated_pin``, ``dissipated_contact``, ``dissipated_friction`` the energy
    dissipated by the pin dashpot, the contact dashpot and friction (unit
    ``(mu0 F_N0)^2/(m omega^2)``; Gauss-Legendre quadrature of the closed forms, relative
    accuracy ~1e-10), so that ``work_input - sum(dissipated) = stored_energy() -
    stored_energy()[0]`` (docs/damping.md).  With a longitudinal in-plane oscillation
    (docs/inplane.md) ``x``, ``x_dot`` are in the laboratory frame and ``work_input``
    includes the work of the oscillating substrate on the contact (or is that of the
    oscillating holder).
    """

    tau: NDArray[np.float64]
    x: NDArray[np.float64]
    x_dot: NDArray[np.float64]
    f: NDArray[np.float64]
    n: NDArray[np.float64]
    phase: NDArray[np.str_]
    events: tuple[Event, ...]
    system: Dimensionless
    v_inertial: float
    e: NDArray[np.float64]
    work_input: NDArray[np.float64]
    dissipated_pin: NDArray[np.float64]
    dissipated_contact: NDArray[np.float64]
    dissipated_friction: NDArray[np.float64]
    final_state: SectionState | None = field(default=None)

    def stored_energy(self) -> NDArray[np.float64]:
        """Kinetic and elastic energy ``x'^2/2 + alpha (V tau - x)^2/2 + k e^2/2`` (with an
        oscillating holder the pin's spring is stretched by ``V tau + X - x``)."""
        d = self.system
        y = self.x - self.v_inertial * self.tau
        if d.a_x > 0.0 and d.inplane_on == "holder":
            y = y - inplane_motion(d, self.tau)[0]
        out = 0.5 * self.x_dot**2 + 0.5 * d.alpha * y**2
        if not d.is_rigid:
            out = out + 0.5 * (d.beta - d.alpha) * self.e**2
        return out

    def time(self, physical: Physical) -> NDArray[np.float64]:
        """Sample times in seconds for a physical system (``t = tau/omega``)."""
        return self.tau / physical.omega


def _checked_run(periods: float, samples_per_period: int) -> None:
    if not (math.isfinite(periods) and periods > 0):
        raise ValueError(f"periods must be finite and > 0, got {periods!r}")
    if not (isinstance(samples_per_period, int) and samples_per_period >= 2):
        raise ValueError(f"samples_per_period must be an integer >= 2, got {samples_per_period!r}")


def _start(dim: Dimensionless, V: float, initial: str | SectionState,
           settings: SolverSettings | None) -> tuple[float, float, float, float, int]:
    """The start ``(y, x', e, e', phase)`` (the order of ``run_periods``); ``"steady"``
    is the trusted steady state's."""
    if isinstance(initial, str) and initial == "steady":
        steady = friction_coefficient(dim, v_inertial=V, settings=settings)
        if steady.final_state is None or not steady.trusted:
            raise ValueError(f"initial='steady': no trusted steady state at this point "
                             f"({steady.message})")
        initial = steady.final_state
    kind, init = initial_rows(initial, 1, lambda i: dim)
    if kind == 2:  # a laboratory state: into the kernels' frame (docs/inplane.md)
        y, xd = to_kernel_frame(frame_offset(*kernel_point(dim, V)[6:]), init[0, 0], init[0, 1])
        return y, xd, init[0, 2], math.nan, int(init[0, 3])
    if kind == 0 and V == 0.0 and dim.a_x > 0.0:
        kind = 1  # "sliding" has no direction at V = 0: the rest, as in solve_points
    if V < 0.0:  # the named starts of -V mirrored (x -> -x, phase_x + pi), as in solve_points
        mirror = replace(dim, phase_x=dim.phase_x + math.pi)
        y, xd, e, phase, e_dot = initial_point(kind, *kernel_point(mirror, -V))
        return -y, -xd, -e, -e_dot, _MIRROR_PHASE.get(phase, phase)
    y, xd, e, phase, e_dot = initial_point(kind, *kernel_point(dim, V))
    return y, xd, e, e_dot, phase


def _segments(dim: Dimensionless, V: float, start: tuple, whole: int) -> NDArray[np.float64]:
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
    initial: str | SectionState = "sliding",
    settings: SolverSettings | None = None,
) -> History:
    """Time history over ``periods`` drive periods, sampled from the closed forms (Fig. 2).

    ``initial``: ``"sliding"``, ``"rest"``, a :class:`SectionState`, or ``"steady"``:
    the final section state of :func:`friction_coefficient` at the same point, so the
    history shows the steady state rather than the transient (ValueError where that
    result has no section state or is not trusted).  ``final_state`` is the state on
    the last Poincare section within the history, ``tau = 2 pi floor(periods)``.
    ``V < 0`` is integrated as it stands, from the mirror image of the named start of
    ``-V`` (``"sliding"``: ``x' = V``, the spring stretched by ``-1``); at ``V = 0`` with
    an in-plane oscillation ``"sliding"`` is the rest (as in :func:`solve_points`).
    """
    dim = dimensionless(system)
    if dim.a_y > 0.0:
        raise ValueError(f"simulate does not take a transverse oscillation yet (a_y = "
                         f"{dim.a_y!r}): friction_coefficient computes its steady state")
    V = np.asarray(inertial_velocity(system, vbar, v_inertial=v_inertial, v0=v0), dtype=float)
    if V.ndim != 0:
        raise ValueError("simulate takes one velocity, got an array")
    V = float(V)
    _checked_run(periods, samples_per_period)
    seg = _segments(dim, V, _start(dim, V, initial, settings), int(math.ceil(periods)))
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
