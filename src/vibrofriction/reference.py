"""Independent reference integrators for the in-plane model (Mao et al. 2017, Part II).

Two peers of the exact event-driven solver, written from the model statement
alone (``docs/model.md``) and sharing no code with it, so that tests can
use them to check it and benchmarks can time it against them.

Scaled variables (docs/model.md): time ``tau = omega t``, body position ``x``,
contact force ``f`` in units of ``mu0 F_N0``, pulling velocity ``V``::

    x'' = alpha (V tau - x) - f            n(tau) = max(0, 1 + a cos tau)
    |f| <= n;  finite contact stiffness k = beta - alpha: f = k (x - x_c),
    x_c' = 0 while |f| < n (stick), |f| = n with sign(x_c') = sign(f) (slip),
    f = 0 in flight (n = 0), touchdown in stick with f = 0;
    rigid contact (beta = inf): stick means x' = 0.

    mu_ratio = mu_macro / mu0 = <f> / <n>         (paper eq. 25)

Both peers work with the drift removed, ``y = x - V tau``, so that nothing grows
over long runs.

* **Peer B**, :func:`return_mapping_mu` -- fixed-step explicit dynamics in numba.
  Finite contact stiffness: velocity Verlet for the body, and the contact force
  from a return mapping (elastic predictor / plastic corrector) of the Jenkins
  element at every step. Rigid contact: Moreau's midpoint time-stepping (the
  friction impulse of each step is chosen in ``[-n dt, n dt]`` so that the
  body stops if it can). Averages by the trapezoid rule (Verlet) or the
  midpoint rule (Moreau), matching where each scheme evaluates the force.
* **Peer A**, :func:`solve_ivp_mu` -- what a Python user would write today:
  :func:`scipy.integrate.solve_ivp` phase by phase with terminal events for the
  stick/slip switches; lift-off and touchdown times are known in closed form
  and cut the time axis; quadrature state variables accumulate the integrals of
  ``f`` and ``n``.

Neither peer detects a periodic orbit: each averages over a fixed window after a
fixed transient, from a stated initial state. Compare them (and the main
solver) at the same transient/average windows when checking discretisation
error, or with windows long enough that the steady state is reached.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit
from scipy.integrate import solve_ivp

__all__ = [
    "INITIAL_REST",
    "INITIAL_SLIDING",
    "PeerRun",
    "ReferenceHistory",
    "return_mapping_history",
    "return_mapping_mu",
    "solve_ivp_mu",
    "solve_ivp_run",
    "steps_per_drive_period",
]

INITIAL_SLIDING = 0
"""Initial state ``tau = 0, x = -1/alpha, x' = V, f = 1`` (sliding before the oscillation)."""
INITIAL_REST = 1
"""Initial state ``tau = 0, x = 0, x' = 0, f = 0``."""

TWO_PI = 2.0 * math.pi


def _initial_code(initial) -> int:
    if isinstance(initial, str):
        codes = {"sliding": INITIAL_SLIDING, "rest": INITIAL_REST}
        if initial not in codes:
            raise ValueError(f"initial must be 'sliding' or 'rest', got {initial!r}")
        return codes[initial]
    code = int(initial)
    if code not in (INITIAL_SLIDING, INITIAL_REST):
        raise ValueError(f"initial must be 0 (sliding) or 1 (rest), got {initial!r}")
    return code


def _check_parameters(alpha, beta, amplitude, V) -> tuple[float, float, float, float]:
    alpha, beta, amplitude, V = float(alpha), float(beta), float(amplitude), float(V)
    if not (alpha > 0.0 and math.isfinite(alpha)):
        raise ValueError(f"alpha must be positive and finite, got {alpha}")
    if not beta > alpha:
        raise ValueError(f"beta must exceed alpha (or be math.inf), got beta={beta}")
    if not (amplitude >= 0.0 and math.isfinite(amplitude)):
        raise ValueError(f"amplitude must be >= 0 and finite, got {amplitude}")
    if not math.isfinite(V):
        raise ValueError(f"V must be finite, got {V}")
    return alpha, beta, amplitude, V


def steps_per_drive_period(alpha: float, beta: float, steps_per_period: float) -> int:
    """Number of fixed steps per drive period ``2 pi`` used by :func:`return_mapping_mu`.

    ``steps_per_period`` steps per period of the fastest of the drive (frequency 1),
    the slip oscillation (``sqrt(alpha)``) and, for a finite contact, the stick
    oscillation (``sqrt(beta)``), rounded up to a whole number per drive period.
    """
    w = max(1.0, math.sqrt(alpha))
    if math.isfinite(beta):
        w = max(w, math.sqrt(beta))
    return max(4, int(math.ceil(steps_per_period * w - 1e-9)))


# ---------------------------------------------------------------------------
# Peer B: fixed-step numba kernels
# ---------------------------------------------------------------------------


@njit(cache=True)
def _normal(tau, a):
    n = 1.0 + a * math.cos(tau)
    return n if n > 0.0 else 0.0


@njit(cache=True)
def _verlet_return_mapping(alpha, beta, a, V, N, n_total, avg_start, initial, record):
    """Velocity Verlet + Jenkins return mapping, finite contact stiffness.

    State at step m (tau_m = m dt): y = x - V tau, v = y', f. Returns the
    trapezoid sums of f and n over steps avg_start..n_total and, if ``record``,
    the history at every step (arrays of length n_total + 1, else length 1).
    """
    k = beta - alpha
    dt = 2.0 * math.pi / N
    if initial == 0:
        y = -1.0 / alpha
        v = 0.0
        f = 1.0
    else:
        y = 0.0
        v = -V
        f = 0.0
    nrec = n_total + 1 if record else 1
    h_tau = np.zeros(nrec)
    h_x = np.zeros(nrec)
    h_xd = np.zeros(nrec)
    h_f = np.zeros(nrec)
    h_n = np.zeros(nrec)
    nn = _normal(0.0, a)
    if record:
        h_x[0] = y
        h_xd[0] = v + V
        h_f[0] = f
        h_n[0] = nn
    sf = 0.0
    sn = 0.0
    if avg_start == 0:
        sf += 0.5 * f
        sn += 0.5 * nn
    # touchdown phase 2 pi - theta (cos = -1/a) when the body jumps (a > 1)
    t_down = 2.0 * math.pi - math.acos(-1.0 / a) if a > 1.0 else -1.0
    acc = -alpha * y - f
    for i in range(n_total):
        vh = v + 0.5 * dt * acc
        y += dt * vh
        m = i + 1
        n_prev = nn
        nn = _normal((m % N) * dt, a)
        # elastic predictor: contact point held fixed, f_tr = k (x_{m} - x_c)
        if n_prev > 0.0 or nn == 0.0:
            ftr = f + k * dt * (vh + V)
        else:
            # touchdown inside this step: the contact point follows the body up
            # to the touchdown time and is fixed from there (f = 0 at touchdown)
            phi = (t_down - (i % N) * dt) / dt
            phi = min(1.0, max(0.0, phi))
            ftr = k * (1.0 - phi) * dt * (vh + V)
        # plastic corrector: project onto the cone |f| <= n
        if ftr > nn:
            f = nn
        elif ftr < -nn:
            f = -nn
        else:
            f = ftr
        acc = -alpha * y - f
        v = vh + 0.5 * dt * acc
        if m > avg_start:
            w = 0.5 if m == n_total else 1.0
            sf += w * f
            sn += w * nn
        elif m == avg_start:
            sf += 0.5 * f
            sn += 0.5 * nn
        if record:
            tau = m * dt
            h_tau[m] = tau
            h_x[m] = y + V * tau
            h_xd[m] = v + V
            h_f[m] = f
            h_n[m] = nn
    return sf, sn, h_tau, h_x, h_xd, h_f, h_n


@njit(cache=True)
def _moreau_rigid(alpha, a, V, N, n_total, avg_start, initial, record):
    """Moreau midpoint time-stepping, rigid contact (beta = inf).

    Per step: half drift of y, friction impulse at the midpoint chosen in
    [-n dt, n dt] so that the body velocity u = x' becomes zero if possible
    (stick), else of full size opposing the free velocity (slip); half drift.
    Returns the midpoint sums of f and n over steps avg_start..n_total - 1 and
    the optional history (f, n of the step ending at each tau).
    """
    dt = 2.0 * math.pi / N
    if initial == 0:
        y = -1.0 / alpha
        u = V
    else:
        y = 0.0
        u = 0.0
    nrec = n_total + 1 if record else 1
    h_tau = np.zeros(nrec)
    h_x = np.zeros(nrec)
    h_xd = np.zeros(nrec)
    h_f = np.zeros(nrec)
    h_n = np.zeros(nrec)
    if record:
        h_x[0] = y
        h_xd[0] = u
        h_f[0] = 1.0 if initial == 0 else 0.0
        h_n[0] = _normal(0.0, a)
    sf = 0.0
    sn = 0.0
    for i in range(n_total):
        ym = y + 0.5 * dt * (u - V)
        nm = _normal(((i % N) + 0.5) * dt, a)
        ufree = u - dt * alpha * ym
        if abs(ufree) <= dt * nm:
            f = ufree / dt
            u = 0.0
        else:
            f = nm if ufree > 0.0 else -nm
            u = ufree - dt * f
        y = ym + 0.5 * dt * (u - V)
        if i >= avg_start:
            sf += f
            sn += nm
        if record:
            m = i + 1
            tau = m * dt
            h_tau[m] = tau
            h_x[m] = y + V * tau
            h_xd[m] = u
            h_f[m] = f
            h_n[m] = nm
    return sf, sn, h_tau, h_x, h_xd, h_f, h_n


@njit(cache=True)
def _fixed_step(alpha, beta, a, V, N, n_total, avg_start, initial, record):
    if math.isinf(beta):
        return _moreau_rigid(alpha, a, V, N, n_total, avg_start, initial, record)
    return _verlet_return_mapping(alpha, beta, a, V, N, n_total, avg_start, initial, record)


def return_mapping_mu(
    alpha: float,
    beta: float,
    amplitude: float,
    V: float,
    steps_per_period: float = 400,
    transient_periods: int = 200,
    average_periods: int = 50,
    initial: int | str = INITIAL_SLIDING,
) -> float:
    """``mu_macro / mu0 = <f> / <n>`` (paper eq. 25) by a fixed-step integrator (peer B).

    Finite ``beta``: velocity Verlet for the body with a return-mapping Jenkins
    element for the contact; ``beta = math.inf``: Moreau midpoint time-stepping.
    The step is ``2 pi / N`` with ``N = steps_per_drive_period(alpha, beta,
    steps_per_period)`` so that a whole number of steps fits a drive period.
    The average runs over ``average_periods`` drive periods after
    ``transient_periods``, from ``initial`` (``"sliding"``/0 or ``"rest"``/1).
    Observed convergence (``tests/test_reference.py``): about second order in
    ``dt`` (fitted slopes 1.7-2.3, irregular because the switches fall anywhere
    between two steps), with or without jumping -- a touchdown inside a step is
    placed at its closed-form time, without which the scheme is first order.
    The rigid (Moreau) scheme shows about second order down to errors of 1e-6
    and drifts towards first order below. Relative cost: one numba step per
    ``dt``; about 2-3 ms per point at 400 steps and 250 periods when
    ``sqrt(beta) <= 1.5``, scaling with ``max(1, sqrt(beta))``.
    """
    alpha, beta, amplitude, V = _check_parameters(alpha, beta, amplitude, V)
    if average_periods < 1 or transient_periods < 0:
        raise ValueError("need average_periods >= 1 and transient_periods >= 0")
    N = steps_per_drive_period(alpha, beta, steps_per_period)
    n_total = N * (int(transient_periods) + int(average_periods))
    avg_start = N * int(transient_periods)
    sf, sn, *_ = _fixed_step(
        alpha, beta, amplitude, V, N, n_total, avg_start, _initial_code(initial), False
    )
    return sf / sn


@dataclass(frozen=True)
class ReferenceHistory:
    """Trajectory from :func:`return_mapping_history`.

    ``tau``, ``x``, ``xdot`` are on the step grid. With a finite contact ``f`` and
    ``n`` are the values at the same instants; with a rigid contact (Moreau)
    they are the mean force of the step ending at ``tau`` and ``n`` at that
    step's midpoint (entry 0 is the initial state).
    """

    tau: np.ndarray
    x: np.ndarray
    xdot: np.ndarray
    f: np.ndarray
    n: np.ndarray
    steps_per_drive_period: int


def return_mapping_history(
    alpha: float,
    beta: float,
    amplitude: float,
    V: float,
    periods: int = 10,
    steps_per_period: float = 400,
    initial: int | str = INITIAL_SLIDING,
) -> ReferenceHistory:
    """The trajectory of :func:`return_mapping_mu` over ``periods`` drive periods from 0."""
    alpha, beta, amplitude, V = _check_parameters(alpha, beta, amplitude, V)
    N = steps_per_drive_period(alpha, beta, steps_per_period)
    n_total = N * int(periods)
    _, _, tau, x, xd, f, n = _fixed_step(
        alpha, beta, amplitude, V, N, n_total, 0, _initial_code(initial), True
    )
    return ReferenceHistory(tau, x, xd, f, n, N)


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
    alpha, beta, a, V = _check_parameters(alpha, beta, amplitude, V)
    if average_periods < 1 or transient_periods < 0:
        raise ValueError("need average_periods >= 1 and transient_periods >= 0")
    ode = _PhaseODE(alpha, beta, a, V)
    w = max(1.0, math.sqrt(alpha))
    if not ode.rigid:
        w = max(w, math.sqrt(beta))
    # a cap on the step (the minimum test below catches what it still misses)
    max_step = TWO_PI / (steps_per_fastest_period * w)
    first_step_scale = TWO_PI / w

    def _solve(fun, t_start, t_stop, z0, events, first_step):
        if first_step is not None:
            first_step = min(first_step, t_stop - t_start)
        try:
            sol = solve_ivp(
                fun,
                (t_start, t_stop),
                z0,
                method=method,
                rtol=rtol,
                atol=atol,
                events=events,
                max_step=max_step,
                first_step=first_step,
            )
        except ValueError as exc:  # brentq: dense output disagrees with the step ends
            raise RuntimeError(
                f"solve_ivp event location failed at tau={t_start:.9g} with method "
                f"{method!r}: {exc}. Use method='DOP853'."
            ) from exc
        if not sol.success:
            raise RuntimeError(f"solve_ivp failed at tau={t_start:.6g}: {sol.message}")
        return sol

    def _advance(phase, s, t_start, t_stop, z0, first_step):
        """Integrate one phase until its first terminal event or ``t_stop``."""
        g_funs, dg_funs = ode.events(phase, s)
        n_g = len(g_funs)
        crossings = [_event(g, -1.0) for g in g_funs]
        # minima of g, not terminal: a minimum below zero means the solver stepped
        # over a pair of close roots of g (a short stick or slip)
        minima = [_minimum_event(dg) for dg in dg_funs]
        fun = ode.rhs(phase, s)
        sol = _solve(fun, t_start, t_stop, z0, crossings + minima, first_step)
        t_missed = math.inf
        for i in range(n_g):
            for te, ye in zip(sol.t_events[n_g + i], sol.y_events[n_g + i], strict=True):
                if g_funs[i](te, ye) < -_GRAZE:
                    t_missed = min(t_missed, float(te))
        if math.isinf(t_missed):
            sol.t_events = sol.t_events[:n_g]
            sol.y_events = sol.y_events[:n_g]
            return [sol], 1
        # re-solve up to that minimum: g < 0 there, so a sign change between two
        # steps is now certain to be seen
        sol2 = _solve(fun, t_start, t_missed, z0, crossings, first_step)
        if sol2.status != 1:
            raise RuntimeError(f"lost a root of an event function near tau={t_missed:.9g}")
        return [sol, sol2], 2

    t_avg = TWO_PI * int(transient_periods)
    t_end = TWO_PI * (int(transient_periods) + int(average_periods))
    cuts = {0.0, t_avg, t_end}
    if a > 1.0:  # lift-off at 2 pi j + theta, touchdown at 2 pi (j + 1) - theta
        theta = math.acos(-1.0 / a)
        for j in range(int(transient_periods) + int(average_periods) + 1):
            for t in (TWO_PI * j + theta, TWO_PI * (j + 1) - theta):
                if 0.0 < t < t_end:
                    cuts.add(t)
    cuts = sorted(cuts)

    code = _initial_code(initial)
    if code == INITIAL_SLIDING:
        z = np.array([-1.0 / alpha, V, 1.0, 0.0, 0.0])
    else:
        z = np.array([0.0, 0.0, 0.0, 0.0, 0.0])
    phase, s, z = ode.entry_phase(0.0, z)

    n_events = n_calls = nfev = 0
    events_in_period: dict[int, int] = {}
    integrals_at_avg = (0.0, 0.0) if t_avg == 0.0 else None
    for t0, t1 in zip(cuts[:-1], cuts[1:], strict=True):
        in_contact = a <= 1.0 or 1.0 + a * math.cos(0.5 * (t0 + t1)) > 0.0
        if not in_contact:
            phase, s = _FLIGHT, 0.0
            z[2] = 0.0
        elif phase == _FLIGHT:  # touchdown: contact starts with f = 0
            z[2] = 0.0
            if ode.rigid:
                phase, s, z = ode.entry_phase(t0, z)
            else:
                # stick with f = 0 unless the body outruns the growing cone
                if ode.dn(t0) - ode.k * abs(z[1]) >= 0.0:
                    phase, s = _STICK, 0.0
                else:
                    s = 1.0 if z[1] > 0.0 else -1.0
                    phase = _SLIP
            if event_log is not None:
                event_log.append((t0, phase, s, z[:3].copy()))
        t = t0
        while True:
            # an event at the very start of a phase whose g starts at zero (entered
            # at the edge of the cone, or a rigid body from rest) means the first
            # step overshot a short phase: retry with a tiny first step
            for first_step in (None, 1e-7 * first_step_scale, 1e-10 * first_step_scale):
                sol, calls = _advance(phase, s, t, t1, z, first_step)
                n_calls += calls
                nfev += sum(x.nfev for x in sol)
                sol = sol[-1]
                if sol.status != 1:
                    break
                te = min(float(tt[0]) for tt in sol.t_events if len(tt))
                if te - t > 1e-10 * (1.0 + abs(t)):
                    break
            if sol.status != 1:
                z = sol.y[:, -1].copy()
                break
            # a terminal event: switch phase at the event time
            which = min(
                (i for i, te in enumerate(sol.t_events) if len(te)),
                key=lambda i: sol.t_events[i][0],
            )
            t = float(sol.t_events[which][0])
            z = sol.y_events[which][0].copy()
            n_events += 1
            period = int(t // TWO_PI)
            events_in_period[period] = events_in_period.get(period, 0) + 1
            if events_in_period[period] > max_events_per_period:
                raise RuntimeError(
                    f"chattering: more than {max_events_per_period} stick/slip events in "
                    f"drive period {period} (tau={t:.9g}); the phase logic is not "
                    "converging (grazing contact?). Raise max_events_per_period or "
                    "use return_mapping_mu."
                )
            n_here = ode.n(t)
            if phase == _STICK:
                s = 1.0 if which == 0 else -1.0
                phase = _SLIP
                z[2] = s * n_here
                if ode.rigid:
                    z[1] = 0.0
            elif ode.rigid:  # slip ended with the body at rest
                phase, s, z = ode.rigid_halt(t, z)
            else:  # contact point came to rest: stick at the edge of the cone
                phase = _STICK
                z[2] = s * n_here
                s = 0.0
            if event_log is not None:
                event_log.append((t, phase, s, z[:3].copy()))
            if t >= t1:
                break
        if t1 == t_avg:
            integrals_at_avg = (z[3], z[4])

    assert integrals_at_avg is not None
    span = t_end - t_avg
    mean_f = (z[3] - integrals_at_avg[0]) / span
    mean_n = (z[4] - integrals_at_avg[1]) / span
    final = (t_end, float(z[0]) + V * t_end, float(z[1]), float(z[2]))
    return PeerRun(mean_f / mean_n, mean_f, mean_n, n_events, n_calls, nfev, final)


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
