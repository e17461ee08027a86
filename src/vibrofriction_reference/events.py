"""Peer A: ``solve_ivp`` phase by phase, with events for the switches.

What a Python user would write today, ``scipy.integrate.solve_ivp`` phase by phase with terminal
events for the stick/slip switches.

Damping (``docs/damping.md``): the pin dashpot ``gamma = 2 zeta sqrt(alpha)`` adds
``gamma (V - x')`` to the body's equation in every phase (a rigid stick then needs the
reaction ``f = -alpha y + gamma V``).  Without a contact dashpot the state is
``[y, x', f, I_f, I_n]`` as undamped.  With ``eta_c > 0`` (finite contact) the state is
``[y, x', e, I_f, I_n]``, ``e = x - x_c`` the elongation of the contact spring and
``F = k e + c x'`` (``c = eta_c k``): stick ``e' = x'``, ``f = F``; slip ``s``: ``f = s n``,
``c e' = s n - k e``; flight ``f = 0``, ``c e' = -k e``.  Stick ends when ``|F|`` reaches
``n``, slip when the contact point's velocity ``x_c' = (F - s n) / c`` falls to 0 (then
stick); at touch-down ``f`` starts at 0 and the contact slips along ``F`` (sticks if
``F = 0``).  Lift-off and touch-down stay closed-form cuts of the time axis.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

from .model import (
    INITIAL_SLIDING,
    TWO_PI,
    check_damping,
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

    # solve_ivp reads these attributes of an event function
    event.terminal = False  # type: ignore[attr-defined]
    event.direction = 1.0  # type: ignore[attr-defined]
    return event


class _PhaseODE:
    """Right-hand sides and event functions of every phase, state [y, u, f, I_f, I_n].

    ``y = x - V tau``, ``u = x'`` (the body velocity), ``f`` the contact force,
    ``I_f`` and ``I_n`` the running integrals of ``f`` and ``n``. Inside a
    contact segment ``n = 1 + a cos tau > 0`` is smooth. The contact is the Jenkins
    element (no contact dashpot), the pin dashpot ``gamma`` acts on the body:
    ``u' = -alpha y - gamma (u - V) - f``.
    """

    def __init__(self, alpha, beta, a, V, gamma=0.0):
        self.alpha, self.beta, self.a, self.V = alpha, beta, a, V
        self.gamma = gamma
        self.rigid = math.isinf(beta)
        self.k = math.inf if self.rigid else beta - alpha

    def n(self, t):
        return 1.0 + self.a * math.cos(t)

    def dn(self, t):
        return -self.a * math.sin(t)

    def rhs(self, phase, s):
        al, a, V, k, g = self.alpha, self.a, self.V, self.k, self.gamma
        if phase == _FLIGHT:

            def fun(t, z):
                return np.array([z[1] - V, -al * z[0] - g * (z[1] - V), 0.0, 0.0, 0.0])
        elif phase == _SLIP:

            def fun(t, z):
                n = 1.0 + a * math.cos(t)
                return np.array([z[1] - V, -al * z[0] - s * n - g * (z[1] - V),
                                 -s * a * math.sin(t), s * n, n])
        elif self.rigid:  # stick, rigid contact: u = 0, f = -alpha y + gamma V

            def fun(t, z):
                return np.array([-V, 0.0, al * V, -al * z[0] + g * V, 1.0 + a * math.cos(t)])
        else:  # stick, finite contact: contact point fixed, f' = k x'

            def fun(t, z):
                return np.array(
                    [z[1] - V, -al * z[0] - z[2] - g * (z[1] - V), k * z[1], z[2],
                     1.0 + a * math.cos(t)]
                )

        return fun

    def events(self, phase, s):
        """The events that end a phase.

        Event functions ``g`` that end the phase (``g`` falls through 0) and their
        derivatives ``g'`` (a minimum of ``g`` is where ``g'`` rises through 0).
        """
        a, k, al, V, gm = self.a, self.k, self.alpha, self.V, self.gamma
        if phase == _FLIGHT:
            return [], []
        if phase == _STICK:
            # |f| reaches n from inside the friction cone: g = n - f, g = n + f
            if self.rigid:  # f = -alpha y + gamma V, y' = -V

                def g_up(t, z):
                    return 1.0 + a * math.cos(t) + al * z[0] - gm * V

                def g_down(t, z):
                    return 1.0 + a * math.cos(t) - al * z[0] + gm * V

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
        if self.rigid:  # g = s u, u' = -alpha y - gamma (u - V) - s n

            def g_halt(t, z):
                return s * z[1]

            def dg_halt(t, z):
                return s * (-al * z[0] - gm * (z[1] - V)) - (1.0 + a * math.cos(t))
        else:  # g = s x_c' = s u - n'/k

            def g_halt(t, z):
                return s * z[1] + a * math.sin(t) / k

            def dg_halt(t, z):
                return (s * (-al * z[0] - gm * (z[1] - V)) - (1.0 + a * math.cos(t))
                        + a * math.cos(t) / k)

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
        f_req = -self.alpha * z[0] + self.gamma * self.V
        if abs(f_req) <= n:
            z[2] = f_req
            return _STICK, 0.0, z
        s = 1.0 if f_req > 0.0 else -1.0
        z[2] = s * n
        return _SLIP, s, z

    def enter_flight(self, z):
        """The state at lift-off: no force."""
        z[2] = 0.0
        return z

    def touchdown(self, t0, z):
        """Contact starts with ``f = 0``: stick unless the body outruns the growing cone."""
        z[2] = 0.0
        if self.rigid:
            return self.entry_phase(t0, z)
        if self.dn(t0) - self.k * abs(z[1]) >= 0.0:
            return _STICK, 0.0, z
        return _SLIP, (1.0 if z[1] > 0.0 else -1.0), z

    def switch(self, phase, s, which, t, z):
        """The phase after a terminal event ``which`` of ``phase`` at time ``t``."""
        n_here = self.n(t)
        if phase == _STICK:
            s = 1.0 if which == 0 else -1.0
            z[2] = s * n_here
            if self.rigid:
                z[1] = 0.0
            return _SLIP, s, z
        if self.rigid:  # slip ended with the body at rest
            return self.rigid_halt(t, z)
        z[2] = s * n_here  # contact point came to rest: stick at the edge of the cone
        return _STICK, 0.0, z

    def force(self, phase, s, t, z):
        """The contact force ``f`` of the state ``z`` in ``phase``."""
        return float(z[2])


class _ViscousPhaseODE:
    """The phases of a finite Kelvin-Voigt contact.

    The phases of a finite Kelvin-Voigt contact (``c = eta_c k > 0``), state
    ``[y, u, e, I_f, I_n]`` with ``e = x - x_c`` the elongation of the contact spring.

    ``f = k e + c (u - x_c')``. Stick (``x_c' = 0``): ``e' = u``, ``f = k e + c u``;
    slip ``s``: ``f = s n``, ``c e' = s n - k e``; flight: ``f = 0``, ``c e' = -k e``.
    With ``F = k e + c u`` the phase is a function of the state: stick while ``|F| <=
    n``, slip in the direction of ``F`` (the contact point's velocity is ``x_c' = (F -
    s n) / c``), so stick ends when ``|F|`` reaches ``n`` and slip ends when ``x_c'``,
    that is ``s F - n``, falls to 0. The right-hand side is continuous across both.
    """

    rigid = False

    def __init__(self, alpha, beta, a, V, gamma, eta_c):
        self.alpha, self.beta, self.a, self.V = alpha, beta, a, V
        self.gamma = gamma
        self.k = beta - alpha
        self.c = eta_c * self.k

    def n(self, t):
        return 1.0 + self.a * math.cos(t)

    def dn(self, t):
        return -self.a * math.sin(t)

    def rhs(self, phase, s):
        al, a, V, k, c, g = self.alpha, self.a, self.V, self.k, self.c, self.gamma
        if phase == _FLIGHT:

            def fun(t, z):
                return np.array([z[1] - V, -al * z[0] - g * (z[1] - V), -k * z[2] / c,
                                 0.0, 0.0])
        elif phase == _SLIP:

            def fun(t, z):
                n = 1.0 + a * math.cos(t)
                return np.array([z[1] - V, -al * z[0] - g * (z[1] - V) - s * n,
                                 (s * n - k * z[2]) / c, s * n, n])
        else:

            def fun(t, z):
                F = k * z[2] + c * z[1]
                return np.array([z[1] - V, -al * z[0] - g * (z[1] - V) - F, z[1], F,
                                 1.0 + a * math.cos(t)])

        return fun

    def stick_force_rate(self, t, z):
        """``F' = k u + c u'`` in stick."""
        k, c = self.k, self.c
        F = k * z[2] + c * z[1]
        du = -self.alpha * z[0] - self.gamma * (z[1] - self.V) - F
        return k * z[1] + c * du

    def events(self, phase, s):
        """As :meth:`_PhaseODE.events`: stick ends at ``|F| = n``, slip at ``s F = n``."""
        a, k, c, al, V, gm = self.a, self.k, self.c, self.alpha, self.V, self.gamma
        if phase == _FLIGHT:
            return [], []
        if phase == _STICK:

            def g_up(t, z):
                return 1.0 + a * math.cos(t) - (k * z[2] + c * z[1])

            def g_down(t, z):
                return 1.0 + a * math.cos(t) + (k * z[2] + c * z[1])

            def dg_up(t, z):
                return -a * math.sin(t) - self.stick_force_rate(t, z)

            def dg_down(t, z):
                return -a * math.sin(t) + self.stick_force_rate(t, z)

            return [g_up, g_down], [dg_up, dg_down]

        def g_halt(t, z):  # c s x_c' = s F - n
            return s * (k * z[2] + c * z[1]) - (1.0 + a * math.cos(t))

        def dg_halt(t, z):
            n = 1.0 + a * math.cos(t)
            de = (s * n - k * z[2]) / c
            du = -al * z[0] - gm * (z[1] - V) - s * n
            return s * (k * de + c * du) + a * math.sin(t)

        return [g_halt], [dg_halt]

    def entry_phase(self, t, z):
        """The phase of a contact state at ``t`` (start).

        Stick if ``|F| < n``, else slip along ``F``; on the edge ``|F| = n``, stick if ``|F|`` falls
        below ``n`` in stick.
        """
        z = z.copy()
        n = self.n(t)
        F = self.k * z[2] + self.c * z[1]
        if abs(F) < n:
            return _STICK, 0.0, z
        s = 1.0 if F > 0.0 else (-1.0 if F < 0.0 else (1.0 if z[1] >= 0.0 else -1.0))
        if abs(F) == n and self.dn(t) - s * self.stick_force_rate(t, z) > 0.0:
            return _STICK, 0.0, z
        return _SLIP, s, z

    def enter_flight(self, z):
        """At lift-off ``f = n = 0`` already; the spring keeps its elongation."""
        return z

    def touchdown(self, t0, z):
        """``n = 0``, so ``f`` starts at 0.

        Stick only if ``F = k e + c u`` is 0, else slip in the direction of the contact point's
        velocity ``F / c``.
        """
        F = self.k * z[2] + self.c * z[1]
        if F == 0.0:
            return _STICK, 0.0, z
        return _SLIP, (1.0 if F > 0.0 else -1.0), z

    def switch(self, phase, s, which, t, z):
        """Stick ends in slip along the edge it reached; slip ends in stick."""
        if phase == _STICK:
            return _SLIP, (1.0 if which == 0 else -1.0), z
        return _STICK, 0.0, z

    def force(self, phase, s, t, z):
        """The contact force ``f`` of the state ``z`` in ``phase``."""
        if phase == _FLIGHT:
            return 0.0
        if phase == _SLIP:
            return s * self.n(t)
        return float(self.k * z[2] + self.c * z[1])


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

    def enter_segment(self, phase, s, t0, t1, z):
        """The phase at the start of the segment ``t0..t1`` between two cuts.

        A segment whose middle has ``n <= 0`` is a flight (``f = 0``); the first
        contact segment after a flight starts with a touchdown; any other keeps
        the phase reached at ``t0``.
        """
        a = self.ode.a
        if a > 1.0 and 1.0 + a * math.cos(0.5 * (t0 + t1)) <= 0.0:
            return _FLIGHT, 0.0, self.ode.enter_flight(z)
        if phase == _FLIGHT:
            phase, s, z = self.ode.touchdown(t0, z)
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
            phase, s, z = self.ode.switch(phase, s, which, t, z)
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
    zeta: float = 0.0,
    eta_c: float = 0.0,
) -> PeerRun:
    """Peer A with statistics; see :func:`solve_ivp_mu` for the method.

    Extra keywords: ``steps_per_fastest_period`` caps the step at that fraction
    of the fastest natural period (``2 pi / max(1, sqrt(alpha), sqrt(beta))``);
    ``event_log``, if a list, receives ``(tau, new_phase, s, [y, x', f])`` at
    every switch and touchdown (phase codes 0 stick, 1 slip, 2 flight; ``[y, x', e]``
    with a contact dashpot). ``zeta`` and ``eta_c``: see :func:`solve_ivp_mu`.

    Pairs of close roots of an event function (a stick or slip shorter than a
    step) are caught by non-terminal events at the minima of the event
    function: a minimum below zero triggers a re-solve up to it. An event at
    the very start of a phase (a short phase overshot by the first step) is
    retried with a tiny first step.
    """
    alpha, beta, a, V = check_parameters(alpha, beta, amplitude, V)
    zeta, eta_c = check_damping(zeta, eta_c)
    transient_periods, average_periods = check_windows(transient_periods, average_periods)
    if not (steps_per_fastest_period > 0.0 and math.isfinite(steps_per_fastest_period)):
        raise ValueError("steps_per_fastest_period must be in (0, inf) (finite and > 0), "
                         f"got {steps_per_fastest_period}")
    gamma = 2.0 * zeta * math.sqrt(alpha)
    viscous = eta_c > 0.0 and math.isfinite(beta)
    ode = (_ViscousPhaseODE(alpha, beta, a, V, gamma, eta_c) if viscous
           else _PhaseODE(alpha, beta, a, V, gamma))
    w = _fastest_frequency(ode)
    # a cap on the step (the minimum test catches what it still misses)
    run = _Run(ode, method, rtol, atol, TWO_PI / (steps_per_fastest_period * w), TWO_PI / w,
               max_events_per_period, event_log)
    periods = transient_periods + average_periods
    t_avg, t_end = TWO_PI * transient_periods, TWO_PI * periods
    phase, s, z = ode.entry_phase(0.0, _initial_state(initial, alpha, beta, V, viscous))
    integrals_at_avg = (0.0, 0.0)
    cuts = _contact_cuts(a, t_avg, t_end, periods)
    for t0, t1 in zip(cuts[:-1], cuts[1:], strict=True):
        phase, s, z = run.enter_segment(phase, s, t0, t1, z)
        phase, s, z = run.piece(phase, s, t0, t1, z)
        if t1 == t_avg:
            integrals_at_avg = (z[3], z[4])
    mean_f, mean_n = _window_means(z, integrals_at_avg, t_end - t_avg)
    final = (t_end, float(z[0]) + V * t_end, float(z[1]), ode.force(phase, s, t_end, z))
    return PeerRun(mean_f / mean_n, mean_f, mean_n, run.n_events, run.n_calls, run.nfev, final)


def _fastest_frequency(ode: _PhaseODE | _ViscousPhaseODE) -> float:
    """The fastest of the drive (1), slip (``sqrt(alpha)``) and stick (``sqrt(beta)``)."""
    w = max(1.0, math.sqrt(ode.alpha))
    return w if ode.rigid else max(w, math.sqrt(ode.beta))


def _initial_state(initial, alpha: float, beta: float, V: float,
                   viscous: bool = False) -> np.ndarray:
    """The initial state at ``tau = 0``.

    ``[y, x', f, I_f, I_n]`` at ``tau = 0`` (docs/model.md, initial states), or
    ``[y, x', e, I_f, I_n]`` for a viscous contact (``e = 1/k`` when sliding).
    """
    if initial_code(initial) == INITIAL_SLIDING:
        return np.array([-1.0 / alpha, V, 1.0 / (beta - alpha) if viscous else 1.0, 0.0, 0.0])
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
    zeta: float = 0.0,
    eta_c: float = 0.0,
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

    ``zeta`` (pin damping ratio) and ``eta_c`` (contact loss factor, ignored for a rigid
    contact) add the dashpots of ``docs/damping.md`` (see the module docstring); both
    must be finite and ``>= 0``. With both 0 the undamped equations run unchanged.
    Damped, the agreement with the exact solver is 1e-11 (finite contact) to 3e-9
    (rigid) at the default tolerances; a small ``eta_c`` makes slip stiff (rate
    ``1 / eta_c``) and DOP853 slow (``eta_c = 0.01``: about 20 ms per period).

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
        zeta=zeta,
        eta_c=eta_c,
    ).mu_ratio
