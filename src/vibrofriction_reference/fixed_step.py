"""Peer B: fixed-step explicit dynamics in numba.

Fixed-step explicit dynamics in numba (velocity Verlet with a return-mapping Jenkins element; Moreau
time-stepping for a rigid contact).

Without dashpots (``zeta = eta_c = 0``, or ``zeta = 0`` with a rigid contact) the
undamped schemes of this module run, unchanged; otherwise the damped scheme of
:mod:`.damped` (pin dashpot and Kelvin-Voigt contact, second order, stable for any
``zeta, eta_c >= 0``).  Histories carry the elongation ``e`` of the contact spring and the
energy bookkeeping (work of the pulled end, stored energy, the three dissipations).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit

from .damped import damped_steps_per_drive_period, fixed_step_damped
from .model import (
    INITIAL_SLIDING,
    check_count,
    check_damping,
    check_parameters,
    check_windows,
    contact_angle,
    initial_code,
    normal,
    steps_per_drive_period,
)

__all__ = ["PeriodMeans", "ReferenceHistory", "return_mapping_history", "return_mapping_mu",
           "return_mapping_periods"]


@njit(cache=True)
def _verlet_return_mapping(alpha, beta, a, V, N, n_total, avg_start, initial, record):
    """Velocity Verlet + Jenkins return mapping, finite contact stiffness.

    State at step m (tau_m = m dt): y = x - V tau, v = y', f. Returns the
    trapezoid sums of f and n over steps avg_start..n_total, the same sums over
    each drive period of that window, and, if ``record``, the history at every
    step (arrays of length n_total + 1, else length 1).
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
    nn = normal(0.0, a)
    if record:
        h_x[0] = y
        h_xd[0] = v + V
        h_f[0] = f
        h_n[0] = nn
    sf = 0.0
    sn = 0.0
    pf = np.zeros((n_total - avg_start) // N)
    pn = np.zeros((n_total - avg_start) // N)
    if avg_start == 0:
        sf += 0.5 * f
        sn += 0.5 * nn
    # touchdown phase 2 pi - theta (cos = -1/a) when the body jumps (a > 1)
    t_down = 2.0 * math.pi - contact_angle(a) if a > 1.0 else -1.0
    acc = -alpha * y - f
    for i in range(n_total):
        f_prev = f
        vh = v + 0.5 * dt * acc
        y += dt * vh
        m = i + 1
        n_prev = nn
        nn = normal((m % N) * dt, a)
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
            j = (i - avg_start) // N
            pf[j] += 0.5 * (f_prev + f)
            pn[j] += 0.5 * (n_prev + nn)
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
    return sf, sn, pf, pn, h_tau, h_x, h_xd, h_f, h_n


@njit(cache=True)
def _moreau_rigid(alpha, a, V, N, n_total, avg_start, initial, record):
    """Moreau midpoint time-stepping, rigid contact (beta = inf).

    Per step: half drift of y, friction impulse at the midpoint chosen in
    [-n dt, n dt] so that the body velocity u = x' becomes zero if possible
    (stick), else of full size opposing the free velocity (slip); half drift.
    Returns the midpoint sums of f and n over steps avg_start..n_total - 1, the
    same sums over each drive period of that window, and the optional history
    (f, n of the step ending at each tau).
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
        h_n[0] = normal(0.0, a)
    sf = 0.0
    sn = 0.0
    pf = np.zeros((n_total - avg_start) // N)
    pn = np.zeros((n_total - avg_start) // N)
    for i in range(n_total):
        ym = y + 0.5 * dt * (u - V)
        nm = normal(((i % N) + 0.5) * dt, a)
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
            j = (i - avg_start) // N
            pf[j] += f
            pn[j] += nm
        if record:
            m = i + 1
            tau = m * dt
            h_tau[m] = tau
            h_x[m] = y + V * tau
            h_xd[m] = u
            h_f[m] = f
            h_n[m] = nm
    return sf, sn, pf, pn, h_tau, h_x, h_xd, h_f, h_n


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
    zeta: float = 0.0,
    eta_c: float = 0.0,
) -> float:
    """``mu_macro / mu0 = <f> / <n>`` (paper eq. 25) by a fixed-step integrator (peer B).

    ``zeta`` (pin damping ratio, ``gamma = 2 zeta sqrt(alpha)``) and ``eta_c`` (contact
    loss factor, ``c = eta_c (beta - alpha)``), when a dashpot acts, select the damped
    scheme of :mod:`.damped` (``docs/damping.md``): Verlet with both dashpots trapezoidal
    and an exact relaxation of the Kelvin-Voigt contact in slip and flight, second order
    (fitted slopes 1.98-2.5 against the exact solver), stable for any ``zeta, eta_c``;
    its step also resolves the rates ``gamma`` and ``c``. Both must be finite and
    ``>= 0`` (ValueError naming the one that is not).

    Finite ``beta``: velocity Verlet for the body with a return-mapping Jenkins
    element for the contact; ``beta = math.inf``: Moreau midpoint time-stepping.
    The step is ``2 pi / N`` with ``N = steps_per_drive_period(alpha, beta,
    steps_per_period)`` so that a whole number of steps fits a drive period.
    The average runs over ``average_periods`` drive periods after
    ``transient_periods``, from ``initial`` (``"sliding"``/0 or ``"rest"``/1).
    Observed convergence (``tests/reference/test_reference.py``): about second order in
    ``dt`` (fitted slopes 1.7-2.3, irregular because the switches fall anywhere
    between two steps), with or without jumping -- a touchdown inside a step is
    placed at its closed-form time, without which the scheme is first order.
    The rigid (Moreau) scheme shows about second order down to errors of 1e-6
    and drifts towards first order below. The error is not a smooth function of
    ``dt``: it changes sign from one resolution to the next and can stay on a
    plateau (Moreau at ``alpha, a, V = 1.13, 0.98, 3.80``: 2.4e-5 from 6400 to 38400
    steps, then 1.1e-6), so estimate it from more than two resolutions
    (``tests/reference_points.py``). Relative cost: one numba step per
    ``dt``; about 2-3 ms per point at 400 steps and 250 periods when
    ``sqrt(beta) <= 1.5``, scaling with ``max(1, sqrt(beta))``.
    """
    sf, sn, _, _, _ = _averaging_sums(alpha, beta, amplitude, V, steps_per_period,
                                      transient_periods, average_periods, initial, zeta,
                                      eta_c)
    return sf / sn


def _undamped(beta, zeta, eta_c) -> bool:
    """No dashpot acts (``eta_c`` is irrelevant for a rigid contact)."""
    return not zeta and (not eta_c or math.isinf(beta))


def _steps(alpha, beta, zeta, eta_c, steps_per_period) -> int:
    if _undamped(beta, zeta, eta_c):
        return steps_per_drive_period(alpha, beta, steps_per_period)
    return damped_steps_per_drive_period(alpha, beta, zeta, eta_c, steps_per_period)


def _run(alpha, beta, amplitude, V, zeta, eta_c, N, n_total, avg_start, initial, record):
    """``(sf, sn, pf, pn, tau, x, x', f, n, e)``.

    The undamped scheme unchanged, or the damped one.
    """
    if _undamped(beta, zeta, eta_c):
        out = _fixed_step(alpha, beta, amplitude, V, N, n_total, avg_start, initial, record)
        # the Jenkins element: e = f / k at every step (0 for a rigid contact)
        e = np.zeros_like(out[4]) if math.isinf(beta) else out[7] / (beta - alpha)
        return (*out, e)
    sf, sn, pf, pn, hist = fixed_step_damped(alpha, beta, amplitude, V, zeta, eta_c, N,
                                             n_total, avg_start, initial, record)
    tau = hist[0]
    if record and math.isinf(beta):  # Moreau: n at the midpoint of the step ending there
        n = np.maximum(0.0, 1.0 + amplitude * np.cos(tau - math.pi / N))
        n[0] = normal(0.0, amplitude)
    else:
        n = np.maximum(0.0, 1.0 + amplitude * np.cos(tau))
    return sf, sn, pf, pn, tau, hist[1], hist[2], hist[3], n, hist[4]


def _energies(alpha, beta, V, zeta, eta_c, N, tau, x, xd, f, e):
    """Stored energy and the cumulative work and dissipations of a history.

    Finite contact (velocity Verlet): the trapezoid rule over each step, the mean force
    ``fm = (f_0 + f_1) / 2``, friction ``fm (dx - de)`` (the force times the motion of
    the contact point), contact dashpot ``de (fm - k e_mean)`` (``c e'^2 = e' (f - k e)``).
    Rigid contact (Moreau): the midpoint rule with the step's force and mean velocity.
    Each balances the stored energy to the scheme's order.
    """
    dt = 2.0 * math.pi / N
    gamma = 2.0 * zeta * math.sqrt(alpha)
    y = x - V * tau
    u = xd
    rigid = math.isinf(beta)
    k = 0.0 if rigid else beta - alpha
    stored = 0.5 * u**2 + 0.5 * alpha * y**2 + 0.5 * k * e**2

    def cumulative(per_step):
        return np.concatenate([[0.0], np.cumsum(per_step)])

    if rigid:
        um = 0.5 * (u[:-1] + u[1:])
        ym = y[:-1] + 0.5 * dt * (u[:-1] - V)
        work = cumulative(dt * V * (-alpha * ym + gamma * (V - um)))
        pin = cumulative(dt * gamma * (V - um) ** 2)
        contact = np.zeros_like(tau)
        friction = cumulative(dt * f[1:] * um)
    else:
        force_x = -alpha * y + gamma * (V - u)
        work = cumulative(0.5 * dt * V * (force_x[:-1] + force_x[1:]))
        pin = cumulative(0.5 * dt * gamma * ((V - u[:-1]) ** 2 + (V - u[1:]) ** 2))
        fm = 0.5 * (f[:-1] + f[1:])
        de = np.diff(e)
        if eta_c > 0.0:
            contact = cumulative(de * (fm - 0.5 * k * (e[:-1] + e[1:])))
        else:
            contact = np.zeros_like(tau)
        friction = cumulative(fm * (np.diff(x) - de))
    return stored, work, pin, contact, friction


def _averaging_sums(alpha, beta, amplitude, V, steps_per_period, transient_periods,
                    average_periods, initial, zeta=0.0, eta_c=0.0):
    """Checked arguments, one run: the window's sums of f and n, per-period sums, N."""
    alpha, beta, amplitude, V = check_parameters(alpha, beta, amplitude, V)
    zeta, eta_c = check_damping(zeta, eta_c)
    transient_periods, average_periods = check_windows(transient_periods, average_periods)
    N = _steps(alpha, beta, zeta, eta_c, steps_per_period)
    n_total = N * (transient_periods + average_periods)
    avg_start = N * transient_periods
    sf, sn, pf, pn, *_ = _run(alpha, beta, amplitude, V, zeta, eta_c, N, n_total, avg_start,
                              initial_code(initial), False)
    return sf, sn, pf, pn, N


@dataclass(frozen=True)
class PeriodMeans:
    """Means of ``f`` and ``n`` over each drive period of the averaging window.

    From :func:`return_mapping_periods`: ``f[j]`` and ``n[j]`` are the means over
    drive period ``transient_periods + j`` (same quadrature as
    :func:`return_mapping_mu`), so that the ratio over any run of whole periods
    can be formed afterwards, e.g. over each half of the window to see whether the
    run has settled.
    """

    f: np.ndarray
    n: np.ndarray
    steps_per_drive_period: int

    def mu_ratio(self, start: int = 0, stop: int | None = None) -> float:
        """``<f> / <n>`` (eq. 25) over the window's periods ``start..stop - 1``."""
        return float(np.sum(self.f[start:stop]) / np.sum(self.n[start:stop]))


def return_mapping_periods(
    alpha: float,
    beta: float,
    amplitude: float,
    V: float,
    steps_per_period: float = 400,
    transient_periods: int = 200,
    average_periods: int = 50,
    initial: int | str = INITIAL_SLIDING,
    zeta: float = 0.0,
    eta_c: float = 0.0,
) -> PeriodMeans:
    """The run of :func:`return_mapping_mu`, with the means of each averaged period."""
    _, _, pf, pn, N = _averaging_sums(alpha, beta, amplitude, V, steps_per_period,
                                      transient_periods, average_periods, initial, zeta,
                                      eta_c)
    return PeriodMeans(pf / N, pn / N, N)


@dataclass(frozen=True)
class ReferenceHistory:
    """Trajectory from :func:`return_mapping_history`.

    ``tau``, ``x``, ``xdot`` are on the step grid. With a finite contact ``f`` and
    ``n`` are the values at the same instants; with a rigid contact (Moreau)
    they are the mean force of the step ending at ``tau`` and ``n`` at that
    step's midpoint (entry 0 is the initial state).  ``e = x - x_c`` is the
    elongation of the contact spring (``f / k`` without a contact dashpot, zeros for a
    rigid contact).

    Energies, from ``tau = 0`` (quadratures of the history, to the scheme's order):
    ``stored_energy = x'^2/2 + alpha (V tau - x)^2/2 + k e^2/2`` at each step,
    ``work_input`` the work of the pulled end (``int F_x V``, ``F_x = alpha (V tau - x)
    + gamma (V - x')``), and the energies dissipated by the pin dashpot (``int gamma
    (V - x')^2``), the contact dashpot (``int c e'^2``) and friction (``int f x_c'``).
    ``work_input - stored_energy + stored_energy[0]`` equals the sum of the three
    dissipations to the order of the scheme (``tests/reference/test_reference_damped.py``).
    """

    tau: np.ndarray
    x: np.ndarray
    xdot: np.ndarray
    f: np.ndarray
    n: np.ndarray
    steps_per_drive_period: int
    e: np.ndarray
    stored_energy: np.ndarray
    work_input: np.ndarray
    dissipated_pin: np.ndarray
    dissipated_contact: np.ndarray
    dissipated_friction: np.ndarray


def return_mapping_history(
    alpha: float,
    beta: float,
    amplitude: float,
    V: float,
    periods: int = 10,
    steps_per_period: float = 400,
    initial: int | str = INITIAL_SLIDING,
    zeta: float = 0.0,
    eta_c: float = 0.0,
) -> ReferenceHistory:
    """The trajectory of :func:`return_mapping_mu` over ``periods`` drive periods from 0."""
    alpha, beta, amplitude, V = check_parameters(alpha, beta, amplitude, V)
    zeta, eta_c = check_damping(zeta, eta_c)
    periods = check_count("periods", periods, 1)
    N = _steps(alpha, beta, zeta, eta_c, steps_per_period)
    n_total = N * periods
    _, _, _, _, tau, x, xd, f, n, e = _run(alpha, beta, amplitude, V, zeta, eta_c, N, n_total,
                                           0, initial_code(initial), True)
    energies = _energies(alpha, beta, V, zeta, eta_c, N, tau, x, xd, f, e)
    return ReferenceHistory(tau, x, xd, f, n, N, e, *energies)


