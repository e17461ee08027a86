"""Peer A: what a Python user would write today, ``scipy.integrate.solve_ivp`` phase by
phase with terminal events for the stick/slip switches."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

from .model import (
    INITIAL_SLIDING,
    TWO_PI,
    check_parameters,
    check_windows,
    contact_angle,
    initial_code,
)

__all__ = ["PeerRun", "solve_ivp_mu", "solve_ivp_run"]


# ---------------------------------------------------------------------------
# Peer A: scipy.integrate.solve_ivp, phase by phase
# ---------------------------------------------------------------------------

_STICK = 0
_SLIP = 1
_FLIGHT = 2


@dataclass(frozen=True)
class PeerRun:
    """Result of :func:`solve_ivp_run`.

    ``mu_ratio = mean_f / mean_n`` over the averaging window; ``n_events`` counts
    stick/slip switches (lift-off and touchdown excluded), ``n_solve_ivp`` the
    calls to :func:`scipy.integrate.solve_ivp` and ``nfev`` their right-hand-side
    evaluations. ``final_state`` is ``(tau, x, x', f)`` at the end of the run.
    """

    mu_ratio: float
    mean_f: float
    mean_n: float
    n_events: int
    n_solve_ivp: int
    nfev: int
    final_state: tuple[float, float, float, float]


_GRAZE = 1e-12
"""Depth below zero of a minimum of an event function that counts as a crossing."""


def _event(fun, direction):
    fun.terminal = True
    fun.direction = direction
    return fun


def _minimum_event(dfun):
    def event(t, z):
        return dfun(t, z)

    event.terminal = False
    event.direction = 1.0
    return event


class _PhaseODE:
    """Right-hand sides and event functions of every phase, state [y, u, f, I_f, I_n].

    ``y = x - V tau``, ``u = x'`` (the body velocity), ``f`` the contact force,
    ``I_f`` and ``I_n`` the running integrals of ``f`` and ``n``. Inside a
    contact segment ``n = 1 + a cos tau > 0`` is smooth.
    """

    def __init__(self, alpha, beta, a, V):
        self.alpha, self.beta, self.a, self.V = alpha, beta, a, V
        self.rigid = math.isinf(beta)
        self.k = math.inf if self.rigid else beta - alpha

    def n(self, t):
        return 1.0 + self.a * math.cos(t)

    def dn(self, t):
        return -self.a * math.sin(t)

    def rhs(self, phase, s):
        al, a, V, k = self.alpha, self.a, self.V, self.k
        if phase == _FLIGHT:

            def fun(t, z):
                return np.array([z[1] - V, -al * z[0], 0.0, 0.0, 0.0])
        elif phase == _SLIP:

            def fun(t, z):
                n = 1.0 + a * math.cos(t)
                return np.array([z[1] - V, -al * z[0] - s * n, -s * a * math.sin(t), s * n, n])
        elif self.rigid:  # stick, rigid contact: u = 0, f = -alpha y

            def fun(t, z):
                return np.array([-V, 0.0, al * V, -al * z[0], 1.0 + a * math.cos(t)])
        else:  # stick, finite contact: contact point fixed, f' = k x'

            def fun(t, z):
                return np.array(
                    [z[1] - V, -al * z[0] - z[2], k * z[1], z[2], 1.0 + a * math.cos(t)]
                )

        return fun

    def events(self, phase, s):
        """Event functions ``g`` that end the phase (``g`` falls through 0) and their
        derivatives ``g'`` (a minimum of ``g`` is where ``g'`` rises through 0).
        """
        a, k, al, V = self.a, self.k, self.alpha, self.V
        if phase == _FLIGHT:
            return [], []
        if phase == _STICK:
            # |f| reaches n from inside the friction cone: g = n - f, g = n + f
            if self.rigid:  # f = -alpha y, y' = -V

                def g_up(t, z):
                    return 1.0 + a * math.cos(t) + al * z[0]

                def g_down(t, z):
                    return 1.0 + a * math.cos(t) - al * z[0]

                def dg_up(t, z):
                    return -a * math.sin(t) - al * V

                def dg_down(t, z):
                    return -a * math.sin(t) + al * V
            else:  # f' = k u

                def g_up(t, z):
                    return 1.0 + a * math.cos(t) - z[2]

                def g_down(t, z):
                    return 1.0 + a * math.cos(t) + z[2]

                def dg_up(t, z):
                    return -a * math.sin(t) - k * z[1]

                def dg_down(t, z):
                    return -a * math.sin(t) + k * z[1]

            return [g_up, g_down], [dg_up, dg_down]
        # slip in direction s ends when the contact-point velocity reaches zero
        if self.rigid:  # g = s u, u' = -alpha y - s n

            def g_halt(t, z):
                return s * z[1]

            def dg_halt(t, z):
                return -s * al * z[0] - (1.0 + a * math.cos(t))
        else:  # g = s x_c' = s u - n'/k

            def g_halt(t, z):
                return s * z[1] + a * math.sin(t) / k

            def dg_halt(t, z):
                return -s * al * z[0] - (1.0 + a * math.cos(t)) + a * math.cos(t) / k

        return [g_halt], [dg_halt]

    def entry_phase(self, t, z):
        """Consistent phase for a contact state with no history (start, touchdown).

        Returns (phase, s, z) with ``f`` set consistently.
        """
        z = z.copy()
        n = self.n(t)
        if self.rigid:
            if z[1] != 0.0:
                s = 1.0 if z[1] > 0.0 else -1.0
                z[2] = s * n
                return _SLIP, s, z
            return self.rigid_halt(t, z)
        f = z[2]
        if abs(f) < n:
            return _STICK, 0.0, z
        s = 1.0 if f > 0.0 else (-1.0 if f < 0.0 else (1.0 if z[1] >= 0.0 else -1.0))
        # in stick d/dt (n - s f) = n' - s k u; stick is consistent if it is > 0
        if self.dn(t) - s * self.k * z[1] > 0.0:
            z[2] = s * n
            return _STICK, 0.0, z
        z[2] = s * n
        return _SLIP, s, z

    def rigid_halt(self, t, z):
        """Rigid contact, body at rest: stick if the required force fits the cone."""
        z = z.copy()
        n = self.n(t)
        z[1] = 0.0
        f_req = -self.alpha * z[0]
        if abs(f_req) <= n:
            z[2] = f_req
            return _STICK, 0.0, z
        s = 1.0 if f_req > 0.0 else -1.0
        z[2] = s * n
        return _SLIP, s, z


def _contact_cuts(a: float, t_avg: float, t_end: float, periods: int) -> list[float]:
    """Times that cut the run: start, start of the average, end, lift-offs, touch-downs."""
    cuts = {0.0, t_avg, t_end}
    if a > 1.0:  # lift-off at 2 pi j + theta, touchdown at 2 pi (j + 1) - theta
        theta = contact_angle(a)
        for j in range(periods + 1):
            for t in (TWO_PI * j + theta, TWO_PI * (j + 1) - theta):
                if 0.0 < t < t_end:
                    cuts.add(t)
    return sorted(cuts)


class _Run:
    """One run of peer A: the integration settings, the state and the counters."""

    def __init__(self, ode, method, rtol, atol, max_step, first_step_scale,
                 max_events_per_period, event_log):
        self.ode, self.method, self.rtol, self.atol = ode, method, rtol, atol
        self.max_step, self.first_step_scale = max_step, first_step_scale
        self.max_events_per_period, self.event_log = max_events_per_period, event_log
        self.n_events = self.n_calls = self.nfev = 0
        self.events_in_period: dict[int, int] = {}

    def solve(self, fun, t_start, t_stop, z0, events, first_step):
        """One call of ``solve_ivp``; failures become RuntimeError with the time."""
        if first_step is not None:
            first_step = min(first_step, t_stop - t_start)
        try:
            sol = solve_ivp(fun, (t_start, t_stop), z0, method=self.method, rtol=self.rtol,
                            atol=self.atol, events=events, max_step=self.max_step,
                            first_step=first_step)
        except ValueError as exc:  # brentq: dense output disagrees with the step ends
            raise RuntimeError(
                f"solve_ivp event location failed at tau={t_start:.9g} with method "
                f"{self.method!r}: {exc}. Use method='DOP853'.") from exc
        if not sol.success:
            raise RuntimeError(f"solve_ivp failed at tau={t_start:.6g}: {sol.message}")
        self.n_calls += 1
        self.nfev += sol.nfev
        return sol

    def advance(self, phase, s, t_start, t_stop, z0, first_step):
        """Integrate one phase until its first terminal event or ``t_stop``.

        Minima of the event functions are non-terminal events: a minimum below zero
        means the solver stepped over a pair of close roots (a short stick or slip),
        and the phase is solved again up to that minimum, where the sign change
        cannot be missed.
        """
        g_funs, dg_funs = self.ode.events(phase, s)
        n_g = len(g_funs)
        crossings = [_event(g, -1.0) for g in g_funs]
        minima = [_minimum_event(dg) for dg in dg_funs]
        fun = self.ode.rhs(phase, s)
        sol = self.solve(fun, t_start, t_stop, z0, crossings + minima, first_step)
        t_missed = math.inf
        for i in range(n_g):
            for te, ye in zip(sol.t_events[n_g + i], sol.y_events[n_g + i], strict=True):
                if g_funs[i](te, ye) < -_GRAZE:
                    t_missed = min(t_missed, float(te))
        if math.isinf(t_missed):
            sol.t_events = sol.t_events[:n_g]
            sol.y_events = sol.y_events[:n_g]
            return sol
        sol2 = self.solve(fun, t_start, t_missed, z0, crossings, first_step)
        if sol2.status != 1:
            raise RuntimeError(f"lost a root of an event function near tau={t_missed:.9g}")
        return sol2

    def advance_retrying(self, phase, s, t, t1, z):
        """:meth:`advance`, retried with tiny first steps when the event fires at once.

        An event at the very start of a phase whose event function starts at zero
        (entered at the edge of the cone, or a rigid body from rest) means the first
        step overshot a short phase.
        """
        for first_step in (None, 1e-7 * self.first_step_scale,
                           1e-10 * self.first_step_scale):
            sol = self.advance(phase, s, t, t1, z, first_step)
            if sol.status != 1:
                return sol
            te = min(float(tt[0]) for tt in sol.t_events if len(tt))
            if te - t > 1e-10 * (1.0 + abs(t)):
                return sol
        return sol

    def count_event(self, t):
        """Count a switch; RuntimeError on chatter (too many in one drive period)."""
        self.n_events += 1
        period = int(t // TWO_PI)
        self.events_in_period[period] = self.events_in_period.get(period, 0) + 1
        if self.events_in_period[period] > self.max_events_per_period:
            raise RuntimeError(
                f"chattering: more than {self.max_events_per_period} stick/slip events in "
                f"drive period {period} (tau={t:.9g}); the phase logic is not "
                "converging (grazing contact?). Raise max_events_per_period or "
                "use return_mapping_mu.")

    def log(self, t, phase, s, z):
        if self.event_log is not None:
            self.event_log.append((t, phase, s, z[:3].copy()))

    def touchdown(self, t0, z):
        """Contact starts with ``f = 0``: stick unless the body outruns the growing cone."""
        ode = self.ode
        z[2] = 0.0
        if ode.rigid:
            return ode.entry_phase(t0, z)
        if ode.dn(t0) - ode.k * abs(z[1]) >= 0.0:
            return _STICK, 0.0, z
        return _SLIP, (1.0 if z[1] > 0.0 else -1.0), z

    def switch(self, phase, s, which, t, z):
        """The phase after a terminal event ``which`` of ``phase`` at time ``t``."""
        ode = self.ode
        n_here = ode.n(t)
        if phase == _STICK:
            s = 1.0 if which == 0 else -1.0
            z[2] = s * n_here
            if ode.rigid:
                z[1] = 0.0
            return _SLIP, s, z
        if ode.rigid:  # slip ended with the body at rest
            return ode.rigid_halt(t, z)
        z[2] = s * n_here  # contact point came to rest: stick at the edge of the cone
        return _STICK, 0.0, z

    def enter_segment(self, phase, s, t0, t1, z):
        """The phase at the start of the segment ``t0..t1`` between two cuts.

        A segment whose middle has ``n <= 0`` is a flight (``f = 0``); the first
        contact segment after a flight starts with a touchdown; any other keeps
        the phase reached at ``t0``.
        """
        a = self.ode.a
        if a > 1.0 and 1.0 + a * math.cos(0.5 * (t0 + t1)) <= 0.0:
            z[2] = 0.0
            return _FLIGHT, 0.0, z
        if phase == _FLIGHT:
            phase, s, z = self.touchdown(t0, z)
            self.log(t0, phase, s, z)
        return phase, s, z

    def piece(self, phase, s, t0, t1, z):
        """Integrate from ``t0`` to ``t1`` (one contact arc or one flight), switching at events."""
        t = t0
        while True:
            sol = self.advance_retrying(phase, s, t, t1, z)
            if sol.status != 1:
                return phase, s, sol.y[:, -1].copy()
            which = min((i for i, te in enumerate(sol.t_events) if len(te)),
                        key=lambda i: sol.t_events[i][0])
            t = float(sol.t_events[which][0])
            z = sol.y_events[which][0].copy()
            self.count_event(t)
            phase, s, z = self.switch(phase, s, which, t, z)
            self.log(t, phase, s, z)
            if t >= t1:
                return phase, s, z


def solve_ivp_run(
    alpha: float,
    beta: float,
    amplitude: float,
    V: float,
    transient_periods: int = 200,
    average_periods: int = 20,
    rtol: float = 1e-10,
    atol: float = 1e-12,
    *,
    method: str = "DOP853",
    initial: int | str = INITIAL_SLIDING,
    max_events_per_period: int = 200,
    steps_per_fastest_period: float = 4.0,
    event_log: list | None = None,
) -> PeerRun:
    """Peer A with statistics; see :func:`solve_ivp_mu` for the method.

    Extra keywords: ``steps_per_fastest_period`` caps the step at that fraction
    of the fastest natural period (``2 pi / max(1, sqrt(alpha), sqrt(beta))``);
    ``event_log``, if a list, receives ``(tau, new_phase, s, [y, x', f])`` at
    every switch and touchdown (phase codes 0 stick, 1 slip, 2 flight).

    Pairs of close roots of an event function (a stick or slip shorter than a
    step) are caught by non-terminal events at the minima of the event
    function: a minimum below zero triggers a re-solve up to it. An event at
    the very start of a phase (a short phase overshot by the first step) is
    retried with a tiny first step.
    """
    alpha, beta, a, V = check_parameters(alpha, beta, amplitude, V)
    transient_periods, average_periods = check_windows(transient_periods, average_periods)
    if not (steps_per_fastest_period > 0.0 and math.isfinite(steps_per_fastest_period)):
        raise ValueError("steps_per_fastest_period must be in (0, inf) (finite and > 0), "
                         f"got {steps_per_fastest_period}")
    ode = _PhaseODE(alpha, beta, a, V)
    w = _fastest_frequency(ode)
    # a cap on the step (the minimum test catches what it still misses)
    run = _Run(ode, method, rtol, atol, TWO_PI / (steps_per_fastest_period * w), TWO_PI / w,
               max_events_per_period, event_log)
    periods = transient_periods + average_periods
    t_avg, t_end = TWO_PI * transient_periods, TWO_PI * periods
    phase, s, z = ode.entry_phase(0.0, _initial_state(initial, alpha, V))
    integrals_at_avg = (0.0, 0.0)
    cuts = _contact_cuts(a, t_avg, t_end, periods)
    for t0, t1 in zip(cuts[:-1], cuts[1:], strict=True):
        phase, s, z = run.enter_segment(phase, s, t0, t1, z)
        phase, s, z = run.piece(phase, s, t0, t1, z)
        if t1 == t_avg:
            integrals_at_avg = (z[3], z[4])
    mean_f, mean_n = _window_means(z, integrals_at_avg, t_end - t_avg)
    final = (t_end, float(z[0]) + V * t_end, float(z[1]), float(z[2]))
    return PeerRun(mean_f / mean_n, mean_f, mean_n, run.n_events, run.n_calls, run.nfev, final)


def _fastest_frequency(ode: _PhaseODE) -> float:
    """The fastest of the drive (1), slip (``sqrt(alpha)``) and stick (``sqrt(beta)``)."""
    w = max(1.0, math.sqrt(ode.alpha))
    return w if ode.rigid else max(w, math.sqrt(ode.beta))


def _initial_state(initial, alpha: float, V: float) -> np.ndarray:
    """``[y, x', f, I_f, I_n]`` at ``tau = 0`` (docs/model.md, initial states)."""
    if initial_code(initial) == INITIAL_SLIDING:
        return np.array([-1.0 / alpha, V, 1.0, 0.0, 0.0])
    return np.zeros(5)


def _window_means(z: np.ndarray, integrals_at_avg: tuple[float, float],
                  span: float) -> tuple[float, float]:
    """``<f>`` and ``<n>`` over the averaging window from the quadrature variables."""
    return (z[3] - integrals_at_avg[0]) / span, (z[4] - integrals_at_avg[1]) / span


def solve_ivp_mu(
    alpha: float,
    beta: float,
    amplitude: float,
    V: float,
    transient_periods: int = 200,
    average_periods: int = 20,
    rtol: float = 1e-10,
    atol: float = 1e-12,
    *,
    method: str = "DOP853",
    initial: int | str = INITIAL_SLIDING,
    max_events_per_period: int = 200,
) -> float:
    """``mu_macro / mu0 = <f> / <n>`` (paper eq. 25) by ``solve_ivp`` with events (peer A).

    The piecewise-smooth ODE is integrated phase by phase (stick, slip in
    direction ``s``, flight) with :func:`scipy.integrate.solve_ivp`
    (``method``, ``rtol``, ``atol``); terminal events end a phase: stick ->
    slip when ``|f|`` reaches ``n``, slip -> stick when the contact-point velocity
    (the body velocity for a rigid contact, ``beta = math.inf``) reaches zero.
    Lift-off and touchdown (``a > 1``) are at ``cos tau = -1/a`` and cut the
    time axis. A rigid contact whose body stops sticks if ``|alpha (V tau - x)|
    <= n``, else slips the other way. More than ``max_events_per_period``
    switches in one drive period raise :class:`RuntimeError` (chattering).

    Use ``method="DOP853"`` (the default): with ``"LSODA"`` scipy's event
    location can fail (its dense output need not match the step ends), which is
    reported as :class:`RuntimeError`. Accuracy about ``rtol`` in ``mu_ratio``
    (agrees with :func:`return_mapping_mu` at fine steps to 1e-8-1e-7).
    Cost: 5-50 ms per drive period in Python.
    """
    return solve_ivp_run(
        alpha,
        beta,
        amplitude,
        V,
        transient_periods,
        average_periods,
        rtol,
        atol,
        method=method,
        initial=initial,
        max_events_per_period=max_events_per_period,
    ).mu_ratio
