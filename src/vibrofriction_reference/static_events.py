"""Static friction above kinetic (law 1) phase by phase with ``solve_ivp``, every switch an event.

The fixed-step peer (:func:`.friction_laws.static_kinetic_run`) places a switch inside its
step. Where a switch grazes (a slip that almost ends, a stuck force that almost reaches
the static limit) or a rigid contact touches down, the error this leaves does not fall
smoothly with the step: at jumping rigid points it scatters by some 1e-5 between step
counts one apart, and the difference of two resolutions is no bound. This peer integrates
each smooth phase with DOP853 and restarts at each switch, found by a terminal event;
lift-off and touch-down at their closed-form times. It needs no step count, only a
tolerance: the error bar is the difference of the runs at ``rtol`` and ``100 rtol``.

Scaled model (docs/model.md, docs/damping.md, docs/friction_laws.md), ``y = x - V tau``,
``gamma = 2 zeta sqrt(alpha)``, ``n = max(0, 1 + a cos tau)``::

    y' = x' - V,   x'' = -alpha y + gamma (V - x') - f

Finite contact, ``k = beta - alpha``, ``f = k e``:

* stick: ``e' = x'``, holds while ``|k e| <= s_r n``; at ``|k e| = s_r n`` the force drops
  to ``s n`` (``s`` the sign of ``e``) and the contact slips if ``s x' - n'/k > 0``, else it
  sticks again at once at that force;
* slip ``s``: ``f = s n``, ``e = s n/k``, until the slip velocity ``s x' - n'/k`` reaches 0,
  then stick;
* flight: ``f = 0``; touch-down sticks where ``k |x'| <= s_r n'`` there, else slips along
  ``x'``.

Rigid contact: stick ``x' = 0`` with ``f = -alpha y + gamma V`` while ``|f| <= s_r n``,
then slip along ``f``; slip ``s`` until ``x' = 0``, then stick if ``|f| <= s_r n`` there,
else slip along ``f``; touch-down slips along ``x'``.

Starts: ``"sliding"`` (``y = -1/alpha``, ``x' = V``, ``f = 1``: stuck where the contact is
elastic, as ``1 < s_r n(0)``; slipping forward where rigid) or ``"rest"`` (``y = x' = f = 0``,
stuck). Tested against the solver and the fixed-step peer in
``tests/reference/test_reference_static_events.py``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

from .model import INITIAL_SLIDING, TWO_PI, check_count, check_damping, initial_code

STICK, SLIP, FLIGHT = 0, 1, 2
MAX_SEGMENTS = 10000  # smooth pieces in one drive period: more is a chattering failure


@dataclass(frozen=True)
class StaticEventsRun:
    """Result of :func:`static_kinetic_events_run`.

    ``mu_ratio = <f>/<n>`` over the averaging window at ``rtol``, ``error`` its difference
    from the run at ``100 rtol``,
    ``period_f`` and ``period_n`` the integrals of ``f`` and ``n`` over each averaged drive
    period, ``section`` the final state ``(y, x', e, phase, s)`` at ``tau = 2 pi k``.
    """

    mu_ratio: float
    error: float
    period_f: np.ndarray
    period_n: np.ndarray
    section: tuple


class _Law1:
    """One system: its smooth phases, their events and the switches between them."""

    def __init__(self, alpha, beta, a, V, zeta, sr, rtol):
        self.alpha, self.a, self.V, self.sr = alpha, a, V, sr
        self.gamma = 2.0 * zeta * math.sqrt(alpha)
        self.rigid = math.isinf(beta)
        self.k = math.inf if self.rigid else beta - alpha
        self.rtol, self.atol = rtol, rtol * 1e-2
        self.flight = None
        if a > 1.0:
            lift = math.acos(-1.0 / a)
            self.flight = (lift, TWO_PI - lift)

    def n(self, t):
        return max(0.0, 1.0 + self.a * math.cos(t))

    def dn(self, t):
        return -self.a * math.sin(t)

    def stuck_force(self, y, e):
        return -self.alpha * y + self.gamma * self.V if self.rigid else self.k * e

    def rhs(self, phase, s):
        """The phase's field on ``(y, x', e, int f, int n)``."""
        al, g, V, k, a = self.alpha, self.gamma, self.V, self.k, self.a

        def field(t, z):
            y, v, e = z[0], z[1], z[2]
            n = max(0.0, 1.0 + a * math.cos(t))
            if phase == FLIGHT:
                return [v - V, -al * y + g * (V - v), 0.0, 0.0, 0.0]
            if phase == SLIP:
                de = 0.0 if self.rigid else s * (-a * math.sin(t)) / k
                return [v - V, -al * y + g * (V - v) - s * n, de, s * n, n]
            if self.rigid:
                return [-V, 0.0, 0.0, -al * y + g * V, n]
            return [v - V, -al * y + g * (V - v) - k * e, v, k * e, n]
        return field

    def events(self, phase, s):
        """Terminal events of the phase, each with the slip direction that follows it."""
        sr, a = self.sr, self.a
        if phase == STICK:
            def up(t, z):
                return sr * (1.0 + a * math.cos(t)) - self.stuck_force(z[0], z[2])

            def down(t, z):
                return sr * (1.0 + a * math.cos(t)) + self.stuck_force(z[0], z[2])
            out = [(up, 1), (down, -1)]
        elif phase == SLIP:
            def end(t, z):
                return s * z[1] if self.rigid else s * z[1] + a * math.sin(t) / self.k
            out = [(end, 0)]
        else:
            out = []
        for fn, _ in out:
            fn.terminal = True  # type: ignore[attr-defined]  # read by solve_ivp
            fn.direction = -1  # type: ignore[attr-defined]
        return out

    def after_stick(self, t, y, v, s):
        """The static limit reached in direction ``s``: ``(phase, s, e)``."""
        if self.rigid:
            return SLIP, s, 0.0
        e = s * self.n(t) / self.k
        if s * v - self.dn(t) / self.k > 0.0:
            return SLIP, s, e
        return STICK, 0, e  # stuck again at once at the kinetic force

    def after_slip(self, t, y, s):
        """The slip in direction ``s`` ended: ``(phase, s, e)``."""
        if not self.rigid:
            return STICK, 0, s * self.n(t) / self.k
        f = self.stuck_force(y, 0.0)
        if abs(f) <= self.sr * self.n(t):
            return STICK, 0, 0.0
        return SLIP, (1 if f > 0 else -1), 0.0

    def touch_down(self, t, v):
        if self.rigid:
            return (STICK, 0, 0.0) if v == 0.0 else (SLIP, 1 if v > 0 else -1, 0.0)
        if self.k * abs(v) <= self.sr * self.dn(t):
            return STICK, 0, 0.0
        return SLIP, (1 if v > 0 else -1), 0.0

    def start(self, initial):
        if initial_code(initial) == INITIAL_SLIDING:
            if self.rigid:
                return [-1.0 / self.alpha, self.V, 0.0, SLIP, 1]
            return [-1.0 / self.alpha, self.V, 1.0 / self.k, STICK, 0]
        return [0.0, 0.0, 0.0, STICK, 0]

    def period(self, state):
        """One drive period from the section state ``[y, x', e, phase, s]`` (in place).

        Returns the integrals of ``f`` and ``n`` over it.
        """
        y, v, e, phase, s = state
        t, int_f, int_n = 0.0, 0.0, 0.0
        cuts = [TWO_PI] if self.flight is None else [*self.flight, TWO_PI]
        for _ in range(MAX_SEGMENTS):
            if t >= TWO_PI:
                break
            t_end = next(c for c in cuts if c > t + 1e-15)
            events = self.events(phase, s)
            sol = solve_ivp(self.rhs(phase, s), (t, t_end), [y, v, e, 0.0, 0.0],
                            method="DOP853", rtol=self.rtol, atol=self.atol,
                            events=[fn for fn, _ in events] or None)
            if sol.status == -1:
                raise RuntimeError(sol.message)
            hit = None
            for i, (_, direction) in enumerate(events):
                if sol.status == 1 and sol.t_events[i].size:
                    hit = direction
                    t1, z1 = sol.t_events[i][0], sol.y_events[i][0]
                    break
            if hit is None:
                t1, z1 = t_end, sol.y[:, -1]
            y, v, e = z1[0], z1[1], z1[2]
            int_f += z1[3]
            int_n += z1[4]
            if hit is not None and phase == STICK:
                if self.rigid:
                    v = 0.0
                phase, s, e = self.after_stick(t1, y, v, hit)
            elif hit is not None:
                if self.rigid:
                    v = 0.0
                phase, s, e = self.after_slip(t1, y, s)
            elif self.flight is not None and t1 == self.flight[0]:
                phase, s, e = FLIGHT, 0, 0.0
            elif self.flight is not None and t1 == self.flight[1]:
                phase, s, e = self.touch_down(t1, v)
            t = t1
        else:
            raise RuntimeError("more than MAX_SEGMENTS smooth pieces in one drive period")
        state[:] = [y, v, e, phase, s]
        return int_f, int_n


def _window(alpha, beta, a, V, zeta, sr, initial, transient, average, rtol):
    law = _Law1(alpha, beta, a, V, zeta, sr, rtol)
    state = law.start(initial)
    pf, pn = np.empty(average), np.empty(average)
    for j in range(transient + average):
        int_f, int_n = law.period(state)
        if j >= transient:
            pf[j - transient], pn[j - transient] = int_f, int_n
    return pf, pn, tuple(state)


def static_kinetic_events_run(
    alpha: float,
    beta: float,
    amplitude: float,
    V: float,
    static_ratio: float = 1.0,
    *,
    zeta: float = 0.0,
    transient_periods: int = 200,
    average_periods: int = 50,
    initial: int | str = INITIAL_SLIDING,
    rtol: float = 1e-11,
) -> StaticEventsRun:
    """``<f>/<n>`` of law 1, phase by phase at ``rtol``, every switch an event.

    Averaged over ``average_periods`` drive periods after ``transient_periods``, from
    ``initial`` (the module docstring); the error bar is the difference from the same run
    at ``100 rtol``.  Each run costs some 5 ms a drive period.
    """
    zeta, _ = check_damping(zeta, 0.0)
    transient = check_count("transient_periods", transient_periods, 0)
    average = check_count("average_periods", average_periods, 1)
    if not (static_ratio >= 1.0 and math.isfinite(static_ratio)):
        raise ValueError(f"static_ratio must be finite and >= 1, got {static_ratio!r}")
    if not 1e-13 <= rtol <= 1e-6:
        raise ValueError(f"rtol must be in [1e-13, 1e-6], got {rtol!r}")
    args = (alpha, beta, amplitude, V, zeta, static_ratio, initial, transient, average)
    pf, pn, section = _window(*args, rtol)
    pf_loose, pn_loose, _ = _window(*args, 100.0 * rtol)
    mu = float(pf.sum() / pn.sum())
    return StaticEventsRun(mu, abs(mu - float(pf_loose.sum() / pn_loose.sum())), pf, pn,
                           section)
