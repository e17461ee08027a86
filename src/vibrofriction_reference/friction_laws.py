"""Reference integrators for two local friction laws beyond Coulomb's.

Written from the model statement alone (``docs/model.md`` and the equations below),
independently of the ``vibrofriction`` package (an import-linter contract forbids any
import from it), and by other methods than its solvers: a fixed-step scheme for law 1
(the package's is exact and event-driven), ``scipy.integrate.solve_ivp`` (Radau) for
law 2 (the package's is a Rosenbrock integrator in numba).

Scaled 1-D model (package units; ``y = x - V tau``, ``gamma = 2 zeta sqrt(alpha)``,
``k = beta - alpha``, ``n = max(0, 1 + A cos tau)``, ``w`` the massless contact point,
``f = k (x - w)``)::

    x'' = alpha (V tau - x) + gamma (V - x') - f,      mu_ratio = <f> / <n>

**Law 1, static above kinetic** (:func:`static_kinetic_run`): ``sigma = mu_static / mu0
>= 1``.  A stuck contact holds while ``|f| <= sigma n``; when ``|f|`` reaches ``sigma n``
it slips and ``f`` drops at once to ``s n`` (``s`` the sign of ``f``); in slip ``f = s n``
until the slip velocity ``w'`` would change sign, then it sticks (with the static
threshold again); in flight ``f = 0`` and the contact re-forms stuck with ``f = 0``.  A
rigid contact (``beta = inf``) sticks (``x' = 0``) while the force that keeps the body at
rest, ``alpha (V tau - x) + gamma V``, is within ``sigma n``, slips with ``f = s n``, ``s =
sign x'``, and when ``x'`` reaches 0 sticks if that force is within ``sigma n``, else
slips again along it.  ``sigma = 1`` is Coulomb's law (the peers
:func:`~vibrofriction_reference.return_mapping_mu` and
:func:`~vibrofriction_reference.solve_ivp_mu`).

*Method.*  Finite contact: velocity Verlet for the body (the pin dashpot trapezoidal,
solved implicitly in the end velocity) with a return mapping of the contact that keeps a
stuck/slipping flag: stuck, the trial force ``f + k dt x'`` (contact point held) sticks if
``|f_trial| <= sigma n``, else slips with ``f = s n``; slipping, the same trial force says
whether slip goes on (``s f_trial >= n``) or the slip velocity has reversed (then stick).
The drop of the force at the end of a stick falls inside a step: it is placed where the
linear interpolation of ``sigma n - s f`` crosses 0, and the step's impulse (the kick of
the body and the average of ``f``) is corrected for it, so that the scheme stays second
order.  A touch-down inside a step is placed at its closed-form time.  Rigid contact:
Moreau's midpoint time-stepping (the friction impulse of a step stops the body if it
can), with the stick-to-slip switch placed inside its step the same way.  Error bar:
the same run at ``N`` and ``2 N`` steps per drive period; ``error`` is their difference
(the finer run's error is about a third of it at second order).

**Law 2, rate-and-state friction** (:func:`rate_state_run`), regularised at zero slip
rate; ``a, b, alpha_ld`` fractions of ``mu_star`` (the force unit is ``mu_star F_N0``),
``d_c`` a length, ``v_ref`` a velocity, ``theta`` a time (package units)::

    mu(w', theta) = a asinh( w'/(2 v_ref) exp((1 + b ln(theta v_ref/d_c))/a) )
    f = n mu  <=>  w' = 2 v_ref sinh(f/(a n)) exp(-(1 + b ln(theta v_ref/d_c))/a)
    aging: theta' = 1 - |w'| theta/d_c;  slip: theta' = -(|w'| theta/d_c) ln(|w'| theta/d_c)
    Linker-Dieterich: theta' += -(alpha_ld/b) theta n'/n

*Method.*  :func:`scipy.integrate.solve_ivp` with an implicit method and an analytic
Jacobian (the slip rate is exponentially stiff, and its stiffness grows like ``1/n`` as
``n -> 0``): ``method="LSODA"`` by default (ODEPACK's switching Adams/BDF code), an arc it
fails on redone with ``"Radau"``; ``"Radau"`` or ``"BDF"`` on request.  The state is ``(y,
x', e = x - w, ln theta)`` (finite contact, ``f = k e``, ``e' = x' - w'(f, theta, n)``) or
``(y, f, ln theta)`` (rigid, ``w = x``, ``f = n mu(x', theta)``: the force is the state and
``x' = w'(f, theta, n)``, because the slope ``df/dx'`` at rest is ``exp(1/a)``; ``x'`` in
flight), with the integrals of ``f`` and ``n`` as quadrature variables, one drive period
at a time.  A contact dashpot ``c = eta_c k`` in parallel with the spring (``f = k e + c (x'
- w')``, ``eta_c > 0``, finite contact): the force at each evaluation is the root of the
scalar increasing ``f + c W(f) = k e + c x'`` (``W`` the slip rate the law gives the
force, ``brentq`` in its bracket ``[0, k e + c x']``), the Jacobian by implicit
differentiation; in flight ``k e + c e' = 0`` (``e`` decays as ``exp(-t/eta_c)``, closed
form) and the contact re-forms with the ``e`` it has (the root's force tiny at the cut's
load); its contact arcs are cut at ``n = 1e-9`` (the cut's error is of order ``n/eta_c``
there, and the rates stay bounded as ``n -> 0``).  With ``A >= 1`` a
contact arc is cut where ``n`` falls to ``1e-6`` short of the lift-off (touch-down) at
``cos tau = -1/A`` (the force there is below ``n``: its impulse is below ``1e-12``); in
flight (closed form) ``f = 0``, ``e = 0``, ``theta' = 1`` (aging) or 0 (slip law), and the
contact re-forms unloaded.  Error bar: the same run at ``rtol`` and ``100 rtol``.
Exponentials are evaluated in logarithms (``exp(1/a)`` overflows for ``a < 1.4e-3``).
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np
from numba import njit
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from .model import (
    INITIAL_SLIDING,
    TWO_PI,
    check_count,
    check_damping,
    check_parameters,
    check_windows,
    contact_angle,
    initial_code,
    normal,
    steps_per_drive_period,
)

__all__ = ["RateStateHistory", "RateStateRun", "StaticKineticHistory", "StaticKineticRun",
           "mu_steady_state", "rate_state_history", "rate_state_run", "static_kinetic_history",
           "static_kinetic_mu", "static_kinetic_run"]

# ---------------------------------------------------------------------------------------
# Law 1: static above kinetic, fixed steps
# ---------------------------------------------------------------------------------------

_STUCK = 0
_SLIPPING = 1
_FLYING = 2


@njit(cache=True)
def _law1_finite(alpha, k, sigma, a, V, gamma, N, n_total, avg_start, initial, record):
    """Velocity Verlet + return mapping with a stuck/slipping flag, finite contact.

    Returns the integrals of ``f`` and ``n`` over each drive period after ``avg_start``
    and, if ``record``, the history rows ``tau, x, x', f, n, state`` (state 0 stuck, +-1
    slipping in that direction, 2 flying).
    """
    dt = TWO_PI / N
    h = 0.5 * dt
    B = h / (1.0 + h * gamma)
    nn = normal(0.0, a)
    if initial == 0:  # steady sliding before the oscillation: slipping forward, f = 1
        y, v, f, state, s = -1.0 / alpha, 0.0, 1.0, _SLIPPING, 1.0
    else:
        y, v, f, state, s = 0.0, -V, 0.0, _STUCK, 0.0
    nrec = n_total + 1 if record else 1
    hist = np.zeros((6, nrec))
    if record:
        hist[1, 0], hist[2, 0], hist[3, 0], hist[4, 0] = y, v + V, f, nn
        hist[5, 0] = s if state == _SLIPPING else 0.0
    n_avg = n_total - avg_start
    pf = np.zeros(n_avg // N)
    pn = np.zeros(n_avg // N)
    t_down = TWO_PI - contact_angle(a) if a > 1.0 else -1.0
    for i in range(n_total):
        f0 = f
        n0 = nn
        vh = v + h * (-alpha * y - gamma * v - f)
        y += dt * vh
        nn = normal(((i + 1) % N) * dt, a)
        xd = vh + V
        A = (vh - h * alpha * y) / (1.0 + h * gamma) + V  # end velocity x'_1 = A - B f
        corr = 0.0
        if nn == 0.0:
            f, state, s = 0.0, _FLYING, 0.0
        else:
            check_stick = True
            if state == _FLYING or n0 == 0.0:
                # touch-down inside this step at its closed-form time: stuck from f = 0
                phi = min(1.0, max(0.0, (t_down - (i % N) * dt) / dt))
                f_tr = k * (1.0 - phi) * dt * xd
                from_stick = False
            else:
                f_tr = f + k * dt * xd  # contact point held
                from_stick = state == _STUCK
                if state == _SLIPPING and s * f_tr >= nn:
                    f = s * nn  # slip goes on
                    check_stick = False
            if check_stick:
                if abs(f_tr) <= sigma * nn:
                    f, state, s = f_tr, _STUCK, 0.0
                else:
                    s = 1.0 if f_tr > 0.0 else -1.0
                    f, state = s * nn, _SLIPPING
                    if from_stick:
                        # the static threshold was reached inside the step: the force
                        # drops from sigma n to n there; correct the step's impulse
                        g0 = sigma * n0 - s * f0
                        g1 = sigma * nn - s * f_tr
                        phi = g0 / (g0 - g1) if g0 > 0.0 else 0.0
                        n_sw = n0 + phi * (nn - n0)
                        impulse = (phi * h * (f0 + s * sigma * n_sw)
                                   + (1.0 - phi) * h * (s * n_sw + f))
                        corr = impulse - h * (f0 + f)
        v = A - V - B * f - corr / (1.0 + h * gamma)
        m = i + 1
        if i >= avg_start:
            j = (i - avg_start) // N
            if j < pf.shape[0]:
                pf[j] += h * (f0 + f) + corr
                pn[j] += h * (n0 + nn)
        if record:
            tau = m * dt
            hist[0, m], hist[1, m], hist[2, m], hist[3, m], hist[4, m] = (
                tau, y + V * tau, v + V, f, nn)
            hist[5, m] = s if state == _SLIPPING else (2.0 if state == _FLYING else 0.0)
    return pf, pn, hist


@njit(cache=True)
def _moreau_basic(y, u, span, t_mid, a, alpha, gamma, V, limit):
    """Moreau's midpoint step of length ``span``: the body stops if ``limit n span`` can stop it.

    Returns ``(y, u, impulse, stopped, s, ufree, scale, n)``: ``ufree`` the end velocity
    without friction, ``scale`` the velocity change per unit force over the step.
    """
    hs = 0.5 * span
    ym = y + hs * (u - V)
    nm = normal(t_mid, a)
    ufree = (u * (1.0 - hs * gamma) + span * (gamma * V - alpha * ym)) / (1.0 + hs * gamma)
    scale = span / (1.0 + hs * gamma)
    if nm > 0.0 and abs(ufree) <= scale * limit * nm:
        f = ufree / scale
        u_end = 0.0
        stopped = True
        s = 0.0
    else:
        s = 1.0 if ufree > 0.0 else -1.0
        f = s * nm
        u_end = ufree - scale * f
        stopped = False
    return ym + hs * (u_end - V), u_end, f * span, stopped, s, ufree, scale, nm


@njit(cache=True)
def _moreau_substep(y, u, span, t0, a, alpha, gamma, V, sigma, stuck):
    """One step of length ``span`` from ``(y, u)`` at ``t0``: ``(y, u, impulse, stuck, s)``.

    Stuck at the start: the body stays at rest if the force that keeps it there is within
    ``sigma n``.  Slipping (or flying): the friction impulse stops the body if ``n span``
    can; if it would reverse the body and ``sigma > 1``, the step is split where the body
    stops (the velocity linear over the step), and the rest of it starts stuck.
    """
    y1, u1, imp, stopped, s, ufree, scale, nm = _moreau_basic(
        y, u, span, t0 + 0.5 * span, a, alpha, gamma, V, sigma if stuck else 1.0)
    if stuck or stopped or sigma == 1.0 or u == 0.0 or s * u > 0.0 or nm == 0.0:
        return y1, u1, imp, stopped, s
    s0 = 1.0 if u > 0.0 else -1.0
    u_slip = ufree - scale * s0 * nm  # the end velocity of a slip along s0 (s0 u_slip < 0)
    t_stop = span * u / (u - u_slip)
    hs = 0.5 * t_stop
    y_stop = y + hs * (u - V) - hs * V
    imp_slip = s0 * normal(t0 + hs, a) * t_stop
    y1, u1, imp, stopped, s, _, _, _ = _moreau_basic(
        y_stop, 0.0, span - t_stop, t0 + 0.5 * (t_stop + span), a, alpha, gamma, V, sigma)
    return y1, u1, imp + imp_slip, stopped, s


@njit(cache=True)
def _law1_rigid(alpha, sigma, a, V, gamma, N, n_total, avg_start, initial, record):
    """Moreau midpoint time-stepping with the static threshold, rigid contact.

    A step that starts stuck and whose holding force leaves ``[-sigma n, sigma n]`` is
    split where the (linear) holding force ``-alpha y + gamma V`` reaches ``sigma n``: at
    rest before, a Moreau slip step after.  History ``f`` is the mean force of the step
    ending at ``tau``.
    """
    dt = TWO_PI / N
    if initial == 0:
        y, u, stuck = -1.0 / alpha, V, False
    else:
        y, u, stuck = 0.0, 0.0, True
    nrec = n_total + 1 if record else 1
    hist = np.zeros((6, nrec))
    if record:
        hist[1, 0], hist[2, 0], hist[4, 0] = y, u, normal(0.0, a)
        hist[3, 0] = 1.0 if initial == 0 else 0.0
        hist[5, 0] = 0.0 if stuck else 1.0
    n_avg = n_total - avg_start
    pf = np.zeros(n_avg // N)
    pn = np.zeros(n_avg // N)
    s = 0.0
    for i in range(n_total):
        t0 = (i % N) * dt
        nm = normal(t0 + 0.5 * dt, a)
        if stuck:
            # at rest the holding force -alpha y + gamma V grows linearly, by alpha V dt
            f_hold0 = -alpha * y + gamma * V
            f_hold1 = f_hold0 + alpha * V * dt
            s = 1.0 if f_hold1 > 0.0 else -1.0
            g1 = sigma * normal(t0 + dt, a) - s * f_hold1
            if g1 >= 0.0:  # stuck over the whole step (exact)
                y -= V * dt
                impulse = 0.5 * dt * (f_hold0 + f_hold1)
                stuck_new = True
            else:  # it reaches sigma n inside the step: at rest until then, slip after
                g0 = sigma * normal(t0, a) - s * f_hold0
                phi = min(1.0, max(0.0, g0 / (g0 - g1) if g0 > 0.0 else 0.0))
                t_sw = phi * dt
                impulse_stuck = t_sw * (f_hold0 + 0.5 * alpha * V * t_sw)
                y, u, impulse, stuck_new, s = _moreau_substep(
                    y - V * t_sw, 0.0, dt - t_sw, t0 + t_sw, a, alpha, gamma, V, 1.0, False)
                impulse += impulse_stuck
        else:
            y, u, impulse, stuck_new, s = _moreau_substep(y, u, dt, t0, a, alpha, gamma, V,
                                                          sigma, False)
        stuck = stuck_new
        if i >= avg_start:
            j = (i - avg_start) // N
            if j < pf.shape[0]:
                pf[j] += impulse
                pn[j] += nm * dt
        if record:
            m = i + 1
            tau = m * dt
            hist[0, m], hist[1, m], hist[2, m], hist[3, m], hist[4, m] = (
                tau, y + V * tau, u, impulse / dt, nm)
            hist[5, m] = 0.0 if stuck else (2.0 if nm == 0.0 else s)
    return pf, pn, hist


def _check_sigma(static_ratio) -> float:
    sigma = float(static_ratio)
    if not (sigma >= 1.0 and math.isfinite(sigma)):
        raise ValueError(f"static_ratio must be in [1, inf) (finite and >= 1), got {sigma}")
    return sigma


def _law1(alpha, beta, amplitude, V, sigma, zeta, N, periods, transient, initial, record):
    gamma = 2.0 * zeta * math.sqrt(alpha)
    n_total = N * periods
    avg_start = N * transient
    if math.isinf(beta):
        return _law1_rigid(alpha, sigma, amplitude, V, gamma, N, n_total, avg_start, initial,
                           record)
    return _law1_finite(alpha, beta - alpha, sigma, amplitude, V, gamma, N, n_total, avg_start,
                        initial, record)


def _law1_steps(alpha, beta, zeta, steps_per_period) -> int:
    """Steps per drive period: as the Coulomb peer, also resolving the dashpot's rate."""
    N = steps_per_drive_period(alpha, beta, steps_per_period)
    gamma = 2.0 * zeta * math.sqrt(alpha)
    return max(N, int(math.ceil(float(steps_per_period) * gamma - 1e-9)))


def _law1_window(alpha, beta, amplitude, V, static_ratio, zeta, steps_per_period,
                 transient_periods, average_periods, initial, refine):
    """Checked parameters, one run at ``refine`` times the steps: per-period integrals, ``N``."""
    alpha, beta, amplitude, V = check_parameters(alpha, beta, amplitude, V)
    sigma = _check_sigma(static_ratio)
    zeta, _ = check_damping(zeta, 0.0)
    transient, average = check_windows(transient_periods, average_periods)
    N = refine * _law1_steps(alpha, beta, zeta, steps_per_period)
    pf, pn, _ = _law1(alpha, beta, amplitude, V, sigma, zeta, N, transient + average,
                      transient, initial_code(initial), False)
    return pf, pn, N


@dataclass(frozen=True)
class StaticKineticRun:
    """Result of :func:`static_kinetic_run`.

    ``mu_ratio = <f>/<n>`` over the averaging window at ``steps_per_drive_period`` steps
    (the finer run), ``mu_ratio_coarse`` the same at half as many steps and ``error =
    |mu_ratio - mu_ratio_coarse|`` (a bound on the finer run's discretisation error when
    the scheme is in its second-order range, where that error is about ``error / 3``).
    ``period_f`` and ``period_n`` are the finer run's means of ``f`` and ``n`` over each
    averaged drive period (does the run settle, is it locked to the drive?).
    """

    mu_ratio: float
    mu_ratio_coarse: float
    error: float
    period_f: np.ndarray
    period_n: np.ndarray
    steps_per_drive_period: int


def static_kinetic_run(
    alpha: float,
    beta: float,
    amplitude: float,
    V: float,
    static_ratio: float = 1.0,
    *,
    zeta: float = 0.0,
    steps_per_period: float = 400,
    transient_periods: int = 200,
    average_periods: int = 50,
    initial: int | str = INITIAL_SLIDING,
) -> StaticKineticRun:
    """``<f>/<n>`` with static friction ``static_ratio`` times the kinetic (law 1), fixed steps.

    ``alpha, beta, amplitude, V`` as the Coulomb peers (``beta = math.inf``: rigid
    contact), ``static_ratio = sigma >= 1``, ``zeta`` the pin's damping ratio (no contact
    dashpot).  ``N = 2 steps_per_drive_period(alpha, beta, steps_per_period)`` steps per
    drive period (at least ``steps_per_period`` per period of the fastest of the drive,
    ``sqrt(alpha)``, ``sqrt(beta)`` and ``gamma``), and the same run at ``N/2`` for the
    error bar.  Averaged over ``average_periods`` drive periods after
    ``transient_periods``, from ``initial`` (``"sliding"``: ``x = -1/alpha, x' = V, f = 1``,
    slipping; ``"rest"``: ``x = x' = f = 0``, stuck), as the Coulomb peers.  See the module
    docstring for the method; measured order and cost in
    ``tests/reference/test_reference_friction_laws.py``.
    """
    pf, pn, N = _law1_window(alpha, beta, amplitude, V, static_ratio, zeta, steps_per_period,
                             transient_periods, average_periods, initial, 2)
    pf_c, pn_c, _ = _law1_window(alpha, beta, amplitude, V, static_ratio, zeta,
                                 steps_per_period, transient_periods, average_periods, initial,
                                 1)
    mu = float(pf.sum() / pn.sum())
    mu_c = float(pf_c.sum() / pn_c.sum())
    return StaticKineticRun(mu, mu_c, abs(mu - mu_c), pf / TWO_PI, pn / TWO_PI, N)


def static_kinetic_mu(
    alpha: float,
    beta: float,
    amplitude: float,
    V: float,
    static_ratio: float = 1.0,
    *,
    zeta: float = 0.0,
    steps_per_period: float = 400,
    transient_periods: int = 200,
    average_periods: int = 50,
    initial: int | str = INITIAL_SLIDING,
) -> float:
    """``<f>/<n>`` of law 1, one run at ``steps_per_period`` (see :func:`static_kinetic_run`).

    The step is ``2 pi / steps_per_drive_period(alpha, beta, steps_per_period)`` (that of
    the coarse run of :func:`static_kinetic_run` at the same ``steps_per_period``).
    """
    pf, pn, _ = _law1_window(alpha, beta, amplitude, V, static_ratio, zeta, steps_per_period,
                             transient_periods, average_periods, initial, 1)
    return float(pf.sum() / pn.sum())


@dataclass(frozen=True)
class StaticKineticHistory:
    """Trajectory of :func:`static_kinetic_history` on the step grid.

    ``tau, x, xdot, f, n``; ``state`` 0 stuck, ``+1``/``-1`` slipping in that direction, 2
    flying.  Finite contact: ``f`` and ``n`` at the instants ``tau``; rigid contact
    (Moreau): ``f`` the mean force of the step ending at ``tau``, ``n`` at that step's
    midpoint (entry 0 is the initial state).
    """

    tau: np.ndarray
    x: np.ndarray
    xdot: np.ndarray
    f: np.ndarray
    n: np.ndarray
    state: np.ndarray
    steps_per_drive_period: int


def static_kinetic_history(
    alpha: float,
    beta: float,
    amplitude: float,
    V: float,
    static_ratio: float = 1.0,
    *,
    zeta: float = 0.0,
    periods: int = 10,
    steps_per_period: float = 400,
    initial: int | str = INITIAL_SLIDING,
) -> StaticKineticHistory:
    """The trajectory of law 1 over ``periods`` drive periods from ``tau = 0``.

    At ``steps_per_drive_period(alpha, beta, steps_per_period)`` steps per drive period
    (the run of :func:`static_kinetic_mu`).
    """
    alpha, beta, amplitude, V = check_parameters(alpha, beta, amplitude, V)
    sigma = _check_sigma(static_ratio)
    zeta, _ = check_damping(zeta, 0.0)
    periods = check_count("periods", periods, 1)
    N = _law1_steps(alpha, beta, zeta, steps_per_period)
    _, _, hist = _law1(alpha, beta, amplitude, V, sigma, zeta, N, periods, 0,
                       initial_code(initial), True)
    return StaticKineticHistory(hist[0], hist[1], hist[2], hist[3], hist[4], hist[5], N)


# ---------------------------------------------------------------------------------------
# Law 2: rate-and-state friction, solve_ivp (Radau) arc by arc
# ---------------------------------------------------------------------------------------

_LAWS = ("aging", "slip")
_EXP_MAX = 300.0
"""Exponents are capped here: a slip rate of ``1e130`` is never reached by a solution, and
the cap keeps the right-hand side finite at the wild trial states of a diverging Newton
iteration (which the solver then rejects)."""
_N_FLOOR = 1e-14
"""Floor of ``n`` inside a contact arc (guards against rounding at its ends)."""
_N_CUT = 1e-6
"""The cut of a rigid contact (:func:`_arcs`)."""
_N_CUT_FINITE = 1e-8
"""The cut of a finite contact without its dashpot. The contact re-forms at the cut unloaded
(``e = 0``), so the elongation it would have gathered from ``n = 0`` to the cut is lost for
the whole arc: an error linear in the cut (measured at a jumping weakening point:
0.2119888433, ...9696, ...9822, ...9835 at cuts 1e-6, 1e-7, 1e-8, 1e-9, Radau at ``rtol =
1e-10``), about 1e-9 at this cut.  A lower cut costs time where the arc's ends are stiff
(25 periods at another jumping point: 0.6, 0.9, 2.4 and 7.2 s at cuts 1e-6 to 1e-9)."""
_N_CUT_DAMPED = 1e-9
"""The cut with a contact dashpot: the elongation's rate stays bounded as ``n -> 0`` (``de'/de
-> -1/eta_c``), and the cut's error there is of order ``n`` at the cut over ``eta_c``
(measured: 1.2e-7, 1.2e-8, 1.1e-9 at cuts 1e-6, 1e-7, 1e-8 with ``eta_c = 0.005``)."""
"""A contact arc ends (starts) where ``n`` falls to (rises from) this value."""


def _asinh_exp(X: float) -> float:
    """``asinh(exp(X))`` without overflow."""
    if X > 20.0:
        return X + math.log(2.0) + 0.25 * math.exp(-2.0 * X)
    return math.asinh(math.exp(X))


def mu_steady_state(v: float, a: float, b: float, v_ref: float) -> float:
    """``mu_ss(v) = a asinh(v/(2 v_ref) exp((1 + b ln(v_ref/v))/a))`` (in units of ``mu_star``).

    The steady-state friction coefficient of law 2 at the slip rate ``v > 0``
    (``theta = d_c / v``); about ``1 + (a - b) ln(v / v_ref)`` when ``v`` is not far below
    ``v_ref`` and ``a`` is small.
    """
    return a * _asinh_exp(math.log(v / (2.0 * v_ref)) + (1.0 + b * math.log(v_ref / v)) / a)


class _RateState:
    """Right-hand sides and Jacobians of law 2; state ``[y, x', (e,) ln theta, I_f, I_n]``."""

    def __init__(self, alpha, beta, A, V, gamma, a, b, d_c, v_ref, alpha_ld, law, eta_c=0.0):
        self.alpha, self.A, self.V, self.gamma = alpha, A, V, gamma
        self.a, self.b, self.d_c, self.v_ref, self.alpha_ld = a, b, d_c, v_ref, alpha_ld
        self.slip_law = law == "slip"
        self.rigid = math.isinf(beta)
        self.k = math.inf if self.rigid else beta - alpha
        # the contact dashpot c = eta_c k in parallel with the spring (a rigid contact
        # ignores it)
        self.eta_c = 0.0 if self.rigid else eta_c
        self.c = self.eta_c * self.k if self.eta_c > 0.0 else 0.0
        self.ln_vd = math.log(v_ref / d_c)
        self.ln_dc = math.log(d_c)
        self.i_lam = 2 if self.rigid else 3
        self.size = self.i_lam + 3
        self.theta0 = d_c / V

    def n(self, t):
        return max(1.0 + self.A * math.cos(t), _N_FLOOR)

    def phi_over_a(self, lam):
        """``(1 + b ln(theta v_ref / d_c)) / a``."""
        return (1.0 + self.b * (lam + self.ln_vd)) / self.a

    def slip_rate(self, f, n, lam):
        """``(w', ln|w'|, dw'/df)`` of a finite contact carrying ``f`` under ``n``."""
        q = f / (self.a * n)
        aq = abs(q)
        pa = self.phi_over_a(lam)
        # dw'/df = 2 v_ref cosh(q) exp(-Phi/a) / (a n), in logarithms
        ln_an = math.log(self.a * n)
        w_f = self.v_ref * (math.exp(min(aq - pa - ln_an, _EXP_MAX))
                            + math.exp(min(-aq - pa - ln_an, _EXP_MAX)))
        if aq == 0.0:
            return 0.0, -math.inf, w_f
        ln_w = math.log(self.v_ref) + min(aq - pa + math.log(-math.expm1(-2.0 * aq)), _EXP_MAX)
        w = math.copysign(math.exp(ln_w), q)
        return w, ln_w, w_f

    def mu(self, u, lam):
        """``(mu, dmu/du, dmu/dlam)`` at the slip rate ``u`` (rigid contact)."""
        if u == 0.0:
            c = 2.0 * self.v_ref * math.exp(max(-self.phi_over_a(lam), -_EXP_MAX))
            return 0.0, self.a / c, 0.0
        X = math.log(abs(u) / (2.0 * self.v_ref)) + self.phi_over_a(lam)
        mu = math.copysign(self.a * _asinh_exp(X), u)
        # hypot(c, u) = |u| sqrt(1 + exp(-2X)), c = 2 v_ref exp(-Phi/a)
        hyp = abs(u) * math.sqrt(1.0 + math.exp(min(-2.0 * X, _EXP_MAX)))
        return mu, self.a / hyp, self.b * u / hyp

    def lam_rate(self, w, ln_w, lam, t, n):
        """``(ln theta)'`` and its derivatives by ``w'`` and by ``ln theta`` (at fixed ``w'``)."""
        r = abs(w) / self.d_c
        sgn = 1.0 if w > 0.0 else (-1.0 if w < 0.0 else 0.0)
        if self.slip_law:
            L = (ln_w - self.ln_dc + lam) if r > 0.0 else math.log(1e-300)
            rate, d_w, d_lam = -r * L, -sgn * (L + 1.0) / self.d_c, -r
        else:
            inv = math.exp(min(-lam, _EXP_MAX))
            rate, d_w, d_lam = inv - r, -sgn / self.d_c, -inv
        if self.alpha_ld:
            rate += self.alpha_ld / self.b * self.A * math.sin(t) / n
        return rate, d_w, d_lam

    def _rigid(self, t, z):
        """A rigid contact in contact: state ``[y, f, ln theta, I_f, I_n]``.

        The body velocity is the slip rate, ``x' = W(f, theta, n)`` (the inverse of ``f = n
        mu(x', theta)``), and ``f`` follows from differentiating it: ``x'' = W_f f' + W_lam
        lam' + W_n n'`` with ``W_lam = -(b/a) W``, ``W_n = -W_f f/n``, so

            f' = (F - f + (b/a) W lam') / W_f + f n'/n,   F = -alpha y + gamma (V - W)

        (a stiff relaxation of ``f`` towards the holding force ``F`` where the contact
        sticks, ``W_f`` tiny, which implicit methods handle; its inverse, ``x'`` as the
        state with ``f = n mu(x')``, has a slope ``df/dx'`` of ``exp(1/a)`` at rest).
        Returns ``(W, lam', f', d f'/d[y, f, lam, ..], W_f, W_lam, d lam'/df, d lam'/dlam)``.
        """
        a, b, al, g = self.a, self.b, self.alpha, self.gamma
        n = self.n(t)
        f, lam = z[1], z[2]
        w, ln_w, w_f = self.slip_rate(f, n, lam)
        q = abs(f) / (a * n)
        # 1 / W_f = a n exp(Phi/a) / (2 v_ref cosh q), in logarithms
        inv_wf = math.exp(min(math.log(a * n) + self.phi_over_a(lam) - math.log(self.v_ref)
                              - q - math.log1p(math.exp(-2.0 * q)), _EXP_MAX))
        w_lam = -b / a * w
        rate, d_w, d_lam = self.lam_rate(w, ln_w, lam, t, n)
        rate_f, rate_lam = d_w * w_f, d_lam + d_w * w_lam
        dn_n = -self.A * math.sin(t) / n
        F = -al * z[0] + g * (self.V - w)
        N = F - f + b / a * w * rate
        f_rate = N * inv_wf + f * dn_n
        N_f = -g * w_f - 1.0 + b / a * (w_f * rate + w * rate_f)
        N_lam = -g * w_lam + b / a * (w_lam * rate + w * rate_lam)
        tanh_q = math.copysign(math.tanh(q), f)
        row_f = (-al * inv_wf, N_f * inv_wf - N * tanh_q / (a * n) * inv_wf + dn_n,
                 (N_lam + b / a * N) * inv_wf, 0.0, 0.0)
        return w, rate, f_rate, row_f, w_f, w_lam, rate_f, rate_lam

    def _finite(self, t, z):
        """A finite contact: ``(f, w', ln|w'|, df/d[x', e, lam], dw'/d[x', e, lam])``.

        Without the dashpot ``f = k e`` and ``w' = W(f)`` (:meth:`slip_rate`).  With it
        ``f = k e + c (x' - w')`` and ``f = n mu(w', theta)``: the force is the root of the
        increasing ``h(f) = f + c W(f) - (k e + c x')``, between 0 and ``k e + c x'``
        (``h`` has their signs there), found by bracketing (``brentq``); the derivatives
        by implicit differentiation, ``D = 1 + c W_f``: ``df = (c dx' + k de - c W_lam
        dlam)/D``, ``dw' = W_f df + W_lam dlam``.
        """
        n = self.n(t)
        lam = z[3]
        k, c = self.k, self.c
        if c == 0.0:
            f = k * z[2]
            w, ln_w, w_f = self.slip_rate(f, n, lam)
            w_lam = -self.b / self.a * w
            return f, w, ln_w, (0.0, k, 0.0), (0.0, w_f * k, w_lam)
        F0 = k * z[2] + c * z[1]
        f = 0.0
        if F0 != 0.0:
            f = brentq(lambda x: x + c * self.slip_rate(x, n, lam)[0] - F0, 0.0, F0,
                       xtol=1e-300, rtol=1e-15, maxiter=400)
        w, ln_w, w_f = self.slip_rate(f, n, lam)
        w_lam = -self.b / self.a * w
        D = 1.0 + c * w_f
        df = (c / D, k / D, -c * w_lam / D)
        return f, w, ln_w, df, (w_f * df[0], w_f * df[1], w_f * df[2] + w_lam)

    def contact(self, t, z):
        """Right-hand side in contact."""
        al, g, V = self.alpha, self.gamma, self.V
        n = self.n(t)
        lam = z[self.i_lam]
        if self.rigid:
            w, rate, f_rate = self._rigid(t, z)[:3]
            return np.array([w - V, f_rate, rate, z[1], n])
        f, w, ln_w, _, _ = self._finite(t, z)
        rate, _, _ = self.lam_rate(w, ln_w, lam, t, n)
        return np.array([z[1] - V, -al * z[0] + g * (V - z[1]) - f, z[1] - w, rate, f, n])

    def contact_jac(self, t, z):
        """Jacobian of :meth:`contact`."""
        al, g = self.alpha, self.gamma
        n = self.n(t)
        lam = z[self.i_lam]
        J = np.zeros((self.size, self.size))
        J[0, 1] = 1.0
        J[1, 0], J[1, 1] = -al, -g
        if self.rigid:
            _, _, _, row_f, w_f, w_lam, rate_f, rate_lam = self._rigid(t, z)
            J[0] = (0.0, w_f, w_lam, 0.0, 0.0)
            J[1] = row_f
            J[2, 1], J[2, 2] = rate_f, rate_lam
            J[3, 1] = 1.0
            return J
        _, w, ln_w, df, dw = self._finite(t, z)
        _, d_w, d_lam = self.lam_rate(w, ln_w, lam, t, n)
        for j, col in enumerate((1, 2, 3)):
            J[1, col] -= df[j]
            J[2, col] = (1.0 if col == 1 else 0.0) - dw[j]
            J[3, col] = d_w * dw[j] + (d_lam if col == 3 else 0.0)
            J[4, col] = df[j]
        return J

    def flight(self, t, z):
        """Right-hand side in flight: no force, aging ``theta' = 1``, slip law 0.

        ``e = 0``; with the dashpot ``k e + c e' = 0``: ``e' = -e/eta_c``.
        """
        out = np.zeros(self.size)
        out[0] = z[1] - self.V
        out[1] = -self.alpha * z[0] + self.gamma * (self.V - z[1])
        if self.c > 0.0:
            out[2] = -z[2] / self.eta_c
        if not self.slip_law:
            out[self.i_lam] = math.exp(min(-z[self.i_lam], _EXP_MAX))
        return out

    def flight_jac(self, t, z):
        """Jacobian of :meth:`flight`."""
        J = np.zeros((self.size, self.size))
        J[0, 1] = 1.0
        J[1, 0], J[1, 1] = -self.alpha, -self.gamma
        if self.c > 0.0:
            J[2, 2] = -1.0 / self.eta_c
        if not self.slip_law:
            J[self.i_lam, self.i_lam] = -math.exp(min(-z[self.i_lam], _EXP_MAX))
        return J

    def observables(self, t, z, in_contact):
        """``(f, w', n)`` of the state ``z`` at ``t``."""
        if not in_contact:
            return 0.0, z[1] if self.rigid else 0.0, 0.0
        n = self.n(t)
        lam = z[self.i_lam]
        if self.rigid:
            return z[1], self.slip_rate(z[1], n, lam)[0], n
        f, w = self._finite(t, z)[:2]
        return f, w, n

    def initial_state(self):
        """Steady sliding at ``V`` before the oscillation (``n = 1``), ``theta = theta0``."""
        f = mu_steady_state(self.V, self.a, self.b, self.v_ref)
        lam = math.log(self.theta0)
        if self.rigid:  # f = n mu(V, theta) at tau = 0, so that x' = V
            z = [-f / self.alpha, self.n(0.0) * self.mu(self.V, lam)[0]]
        else:
            z = [-f / self.alpha, self.V, f / self.k]
        return np.array(z + [lam, 0.0, 0.0])

    def velocity(self, t, z, in_contact):
        """The body velocity ``x'`` of the state ``z``."""
        if self.rigid and in_contact:
            return self.slip_rate(z[1], self.n(t), z[2])[0]
        return z[1]


def _arcs(A: float, j: int, cut: float = _N_CUT) -> list[tuple[float, float, bool]]:
    """The contact arcs and flights of drive period ``j``: ``(start, end, in_contact)``.

    With ``A >= 1`` a contact arc stops (and starts) where ``n`` has fallen to ``cut``
    (:data:`_N_CUT`, :data:`_N_CUT_FINITE`, :data:`_N_CUT_DAMPED`), short of the
    closed-form lift-off (touch-down), where the slip rate's stiffness ``1/n`` diverges:
    the force there is below ``n`` and its impulse below about ``cut**2 / sqrt(A**2 -
    1)``.
    """
    t0, t1 = TWO_PI * j, TWO_PI * (j + 1)
    if A < 1.0:
        return [(t0, t1, True)]
    th = contact_angle(A)
    # n = 1 + A cos(th - d) = A (cos th (cos d - 1) + sin th sin d): solve for n = cut
    d = min(th, cut / math.sqrt(A * A - 1.0)) if A > 1.0 else math.sqrt(2.0 * cut)
    for _ in range(50):  # Newton on 1 + A cos(th - d) = cut from below
        g = 1.0 + A * math.cos(th - d) - cut
        if abs(g) <= 1e-3 * cut:
            break
        d -= g / (A * math.sin(th - d))
    return [(t0, t0 + th - d, True), (t0 + th - d, t1 - th + d, False), (t1 - th + d, t1, True)]


def _flight(model: _RateState, z: np.ndarray, t0: float, t1: float,
            t_eval: np.ndarray | None, rows: list) -> np.ndarray:
    """The state after a flight from ``t0`` to ``t1``, in closed form (samples into ``rows``).

    ``y'' = -alpha y - gamma y'`` (its matrix exponential in closed form), ``e = 0``;
    aging ``theta' = 1``, slip law ``theta' = 0``; no force, so the quadratures stay.
    """
    al, hg = model.alpha, 0.5 * model.gamma
    K = np.array([[hg, 1.0], [-al, -hg]])  # M + gamma/2, M = [[0, 1], [-alpha, -gamma]]
    d = hg * hg - al  # K @ K = d I, so exp(M t) = exp(-gamma t/2) (C(t) I + S(t) K)
    yv0 = np.array([z[0], z[1] - model.V])
    theta0 = math.exp(z[model.i_lam])

    def at(t):
        out = z.copy()
        s = t - t0
        if d > 0.0:
            r = math.sqrt(d)
            c, sn = math.cosh(r * s), math.sinh(r * s) / r
        elif d < 0.0:
            r = math.sqrt(-d)
            c, sn = math.cos(r * s), math.sin(r * s) / r
        else:
            c, sn = 1.0, s
        yv = math.exp(-hg * s) * (c * yv0 + sn * (K @ yv0))
        out[0], out[1] = yv[0], yv[1] + model.V
        if not model.rigid:  # k e + c e' = 0
            out[2] = z[2] * math.exp(-s / model.eta_c) if model.c > 0.0 else 0.0
        if not model.slip_law:
            out[model.i_lam] = math.log(theta0 + (t - t0))
        return out

    if t_eval is not None:
        for t in t_eval:
            rows.append((float(t), at(float(t)), False))
    return at(t1)


_MAX_CALLS = 300_000
"""Right-hand-side evaluations allowed on one contact arc (a few thousand are usual)."""


class _TooLong(Exception):
    """An arc took more than :data:`_MAX_CALLS` evaluations."""


def _solve_arc(model: _RateState, t0: float, t1: float, z: np.ndarray, method: str,
               rtol: float, atol: float, dense: bool):
    """``solve_ivp`` over one contact arc; an arc that LSODA fails on is redone with Radau."""
    for meth in (method, "Radau") if method != "Radau" else (method,):
        calls = [0]

        def fun(t, y, calls=calls):
            calls[0] += 1
            if calls[0] > _MAX_CALLS:
                raise _TooLong(f"more than {_MAX_CALLS} evaluations")
            return model.contact(t, y)

        # a diverging Newton iteration (which the solver detects, and retries with a
        # shorter step) may overflow on the way; LSODA warns when it gives up
        with np.errstate(over="ignore", divide="ignore", invalid="ignore"), \
                warnings.catch_warnings():
            warnings.simplefilter("error", UserWarning)
            try:
                sol = solve_ivp(fun, (t0, t1), z, method=meth, jac=model.contact_jac,
                                rtol=rtol, atol=atol, dense_output=dense)
            except (UserWarning, _TooLong) as exc:
                message = f"{meth}: {exc}"
                continue
        if sol.success:
            return sol
        message = f"{meth}: {sol.message}"
    raise RuntimeError(f"solve_ivp failed on tau in [{t0:.9g}, {t1:.9g}]: {message}")


def _integrate(model: _RateState, periods: int, rtol: float, atol: float,
               points_per_period: int, method: str):
    """Run ``periods`` drive periods; per-period integrals of ``f`` and ``n``, history.

    The history (if ``points_per_period > 0``) is sampled at ``points_per_period`` points
    per period from ``solve_ivp``'s dense output (and the closed form in flight).
    """
    z = model.initial_state()
    i_f = model.size - 2
    pf, pn = np.zeros(periods), np.zeros(periods)
    rows: list[tuple] = []
    if points_per_period:
        rows.append((0.0, z.copy(), True))
    stats = {"nfev": 0, "njev": 0, "nlu": 0}
    for j in range(periods):
        z[i_f:] = 0.0
        for t0, t1, contact in _arcs(model.A, j, _N_CUT if model.rigid else _N_CUT_DAMPED
                                          if model.c > 0.0 else _N_CUT_FINITE):
            if not contact:  # lift-off: f = n mu is 0 there, up to n at the cut
                if model.rigid:
                    z[1] = model.velocity(t0, z, True)  # the state holds x' in flight
                elif model.c == 0.0:
                    z[2] = 0.0  # with the dashpot e stays (f = 0 there to the cut's load)
            t_eval = None
            if points_per_period:
                grid = TWO_PI * j + TWO_PI * np.arange(1, points_per_period + 1) / points_per_period
                t_eval = grid[(grid > t0) & (grid <= t1)]
            if not contact:
                z = _flight(model, z, t0, t1, t_eval, rows)
                continue
            if model.rigid and t0 > TWO_PI * j:  # touch-down: f = n mu(x', theta)
                z[1] = model.n(t0) * model.mu(z[1], z[2])[0]
            sol = _solve_arc(model, t0, t1, z, method, rtol, atol, t_eval is not None)
            stats["nfev"] += sol.nfev
            stats["njev"] += sol.njev
            stats["nlu"] += sol.nlu
            z = sol.y[:, -1].copy()
            if t_eval is not None and len(t_eval):
                rows.extend((float(t), zz, True)
                            for t, zz in zip(t_eval, sol.sol(t_eval).T, strict=True))
        pf[j], pn[j] = z[i_f], z[i_f + 1]
    return pf, pn, rows, stats


def _rate_state_model(alpha, beta, amplitude, V, a, b, d_c, v_ref, alpha_ld, law, zeta, theta0,
                      eta_c=0.0):
    """The checked parameters as a :class:`_RateState`, or ValueError naming the culprit."""
    alpha, beta, amplitude, V = check_parameters(alpha, beta, amplitude, V)
    zeta, eta_c = check_damping(zeta, eta_c)
    values = {}
    for name, value, lowest in (("a", a, "> 0"), ("b", b, ">= 0"), ("d_c", d_c, "> 0"),
                                ("v_ref", v_ref, "> 0"), ("alpha_ld", alpha_ld, ">= 0")):
        value = float(value)
        ok = value > 0.0 if lowest == "> 0" else value >= 0.0
        if not (ok and math.isfinite(value)):
            raise ValueError(f"{name} must be finite and {lowest}, got {value}")
        values[name] = value
    if not V > 0.0:
        raise ValueError(f"V must be > 0 (steady sliding at V is the start), got {V}")
    if law not in _LAWS:
        raise ValueError(f"law must be 'aging' or 'slip', got {law!r}")
    if values["alpha_ld"] > 0.0 and (values["b"] == 0.0 or amplitude >= 1.0):
        raise ValueError("alpha_ld > 0 needs b > 0 and amplitude < 1 (the coupling "
                         f"-(alpha_ld/b) theta n'/n), got b={values['b']}, "
                         f"amplitude={amplitude}")
    model = _RateState(alpha, beta, amplitude, V, 2.0 * zeta * math.sqrt(alpha), values["a"],
                       values["b"], values["d_c"], values["v_ref"], values["alpha_ld"], law,
                       eta_c)
    if theta0 is not None:
        theta0 = float(theta0)
        if not (theta0 > 0.0 and math.isfinite(theta0)):
            raise ValueError(f"theta0 must be finite and > 0, got {theta0}")
        model.theta0 = theta0
    return model


_METHODS = ("LSODA", "Radau", "BDF")


def _check_method(method: str) -> str:
    if method not in _METHODS:
        raise ValueError(f"method must be one of {_METHODS} (implicit), got {method!r}")
    return method


def _check_tolerances(rtol, atol) -> tuple[float, float]:
    rtol, atol = float(rtol), float(atol)
    if not (0.0 < rtol < 1.0 and 0.0 < atol < 1.0):
        raise ValueError(f"rtol and atol must be in (0, 1), got rtol={rtol}, atol={atol}")
    return rtol, atol


@dataclass(frozen=True)
class RateStateRun:
    """Result of :func:`rate_state_run`.

    ``mu_ratio = <f>/<n>`` over the averaging window at ``rtol, atol``; ``mu_ratio_loose``
    the same run at ``100 rtol, 100 atol`` and ``error = |mu_ratio - mu_ratio_loose|``
    (an error bar of the tight run).  ``period_f`` and ``period_n`` are the tight run's
    means of ``f`` and ``n`` over each averaged drive period (does the run settle, is it
    locked to the drive?).  ``nfev`` and ``njev`` count the tight run's right-hand-side
    and Jacobian evaluations.
    """

    mu_ratio: float
    mu_ratio_loose: float
    error: float
    period_f: np.ndarray
    period_n: np.ndarray
    transient_periods: int
    average_periods: int
    nfev: int
    njev: int


def rate_state_run(
    alpha: float,
    beta: float,
    amplitude: float,
    V: float,
    a: float,
    b: float,
    d_c: float,
    v_ref: float,
    *,
    alpha_ld: float = 0.0,
    law: str = "aging",
    zeta: float = 0.0,
    eta_c: float = 0.0,
    transient_periods: int = 50,
    average_periods: int = 20,
    rtol: float = 1e-8,
    atol: float = 1e-10,
    method: str = "LSODA",
    theta0: float | None = None,
) -> RateStateRun:
    """``<f>/<n>`` with rate-and-state friction (law 2), ``solve_ivp`` arc by arc.

    ``alpha, beta, amplitude, V`` as the Coulomb peers (``beta = math.inf``: rigid
    contact, ``w = x``), ``zeta`` the pin's damping ratio, ``eta_c`` the contact's loss
    factor (the dashpot ``c = eta_c k`` in parallel with the contact spring, ``f = k e + c
    (x' - w')``; a rigid contact ignores it); ``a > 0``, ``b >= 0`` (fractions
    of ``mu_star``), ``d_c > 0`` (length unit), ``v_ref > 0`` (velocity unit),
    ``alpha_ld >= 0`` (Linker-Dieterich, needs ``b > 0`` and ``amplitude < 1``), ``law``
    ``"aging"`` or ``"slip"``.  Starts in steady sliding at ``V`` without oscillation
    (``theta = d_c/V``, ``f = mu_steady_state(V)``, ``e = f/k``, ``x' = V``, ``y =
    -f/alpha``; the state continuous at ``tau = 0``, with the dashpot the force then jumps
    to the root of ``f = k e + c (x' - w') = n(0) mu(w')``), averages over
    ``average_periods`` drive periods after ``transient_periods``; ``theta0`` replaces
    the initial ``theta`` (a perturbed start).
    The error bar comes from a second run at ``100 rtol, 100 atol``; ``method``
    ``"LSODA"`` (an arc it fails on is redone with Radau), ``"Radau"`` or ``"BDF"``
    (the three agree to about 1e-8 at the default tolerances).  A rigid contact that
    sticks switches between stick and slip within ``a`` in ``f/n``, where ``x'`` changes by
    ``exp(1/a)``: measured fine at ``a = 0.05`` and at ``a = 0.02`` without jumping, but at
    ``a = 0.02`` with jumping or at ``a <= 0.01`` it can fail (RuntimeError: a step below
    the spacing of floats, or more than 300 000 evaluations on one contact arc); use a stiff
    finite contact there (its gap to the rigid one falls like ``1/k``), which is well
    behaved down to ``a = 1e-3``.  Raises RuntimeError where the integrator fails.
    """
    model = _rate_state_model(alpha, beta, amplitude, V, a, b, d_c, v_ref, alpha_ld, law, zeta,
                              theta0, eta_c)
    transient, average = check_windows(transient_periods, average_periods)
    rtol, atol = _check_tolerances(rtol, atol)
    results = []
    for scale in (1.0, 100.0):
        pf, pn, _, stats = _integrate(model, transient + average, min(scale * rtol, 0.1),
                                      scale * atol, 0, _check_method(method))
        results.append((pf[transient:], pn[transient:], stats))
    (pf, pn, stats), (pf_l, pn_l, _) = results
    mu = float(pf.sum() / pn.sum())
    mu_l = float(pf_l.sum() / pn_l.sum())
    return RateStateRun(mu, mu_l, abs(mu - mu_l), pf / TWO_PI, pn / TWO_PI, transient, average,
                        stats["nfev"], stats["njev"])


@dataclass(frozen=True)
class RateStateHistory:
    """Trajectory of :func:`rate_state_history`, sampled from the dense output.

    ``tau, y = x - V tau, xdot, e = x - w`` (0 for a rigid contact and in flight), ``f``,
    ``theta``, ``slip_rate = w'`` (``x'`` for a rigid contact, 0 in flight for a finite
    one) and ``n``.  Energy: ``x'^2/2 + alpha y^2/2 + k e^2/2`` changes by the work of the
    pulled end ``int (alpha (V tau - x) + gamma (V - x')) V`` less the friction
    dissipation ``int f w'`` and the pin dashpot's ``int gamma (V - x')^2``.
    """

    tau: np.ndarray
    y: np.ndarray
    xdot: np.ndarray
    e: np.ndarray
    f: np.ndarray
    theta: np.ndarray
    slip_rate: np.ndarray
    n: np.ndarray


def rate_state_history(
    alpha: float,
    beta: float,
    amplitude: float,
    V: float,
    a: float,
    b: float,
    d_c: float,
    v_ref: float,
    *,
    alpha_ld: float = 0.0,
    law: str = "aging",
    zeta: float = 0.0,
    eta_c: float = 0.0,
    periods: int = 10,
    points_per_period: int = 400,
    rtol: float = 1e-8,
    atol: float = 1e-10,
    method: str = "LSODA",
    theta0: float | None = None,
) -> RateStateHistory:
    """The trajectory of :func:`rate_state_run` over ``periods`` drive periods from 0.

    Sampled at ``points_per_period`` equally spaced points per drive period (and at
    ``tau = 0``), from the tight run (``rtol, atol``).
    """
    model = _rate_state_model(alpha, beta, amplitude, V, a, b, d_c, v_ref, alpha_ld, law, zeta,
                              theta0, eta_c)
    periods = check_count("periods", periods, 1)
    points = check_count("points_per_period", points_per_period, 1)
    rtol, atol = _check_tolerances(rtol, atol)
    _, _, rows, _ = _integrate(model, periods, rtol, atol, points, _check_method(method))
    cols = np.zeros((8, len(rows)))
    for i, (t, z, contact) in enumerate(rows):
        f, w, n = model.observables(t, z, contact)
        e = 0.0 if model.rigid else z[2]
        cols[:, i] = (t, z[0], model.velocity(t, z, contact), e, f, math.exp(z[model.i_lam]),
                      w, n)
    return RateStateHistory(*cols)
