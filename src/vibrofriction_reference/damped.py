"""Peer B with damping: fixed-step dynamics with a pin dashpot and a Kelvin-Voigt contact.

Written from the model statement (``docs/damping.md``), independently of the
``vibrofriction`` package.  Scaled variables (``docs/model.md``), ``y = x - V tau``,
``v = y'``, ``gamma = 2 zeta sqrt(alpha)``, ``k = beta - alpha``, ``c = eta_c k``::

    y'' = -alpha y - gamma v - f
    f = k e + c (x' - x_c'),  e = x - x_c,  |f| <= n = max(0, 1 + a cos tau)
    stick: x_c' = 0 while |k e + c x'| <= n;  slip: f = s n, s = sign(k e + c x')
    flight (n = 0): f = 0, the spring relaxes (c e' = -k e)

Finite contact, one step ``dt``: a half kick with the last force, a drift, then the
contact over the step with the body velocity of the drift held fixed (a return
mapping for the Kelvin-Voigt element in series with the slider): the stick trial
``e + dt x'``, ``f = k e + c x'``; outside the cone, slip with ``f = s n`` and ``e``
relaxing exactly towards ``s n / k`` with rate ``k / c`` (``e = s n / k`` when
``c = 0``); a touch-down inside the step at its closed-form time.  The second half
kick treats the pin dashpot implicitly (trapezoidal).  Rigid contact (``beta =
inf``): Moreau's midpoint scheme with the pin dashpot trapezoidal, the friction
impulse in ``[-n dt, n dt]`` stopping the body when it can.  Averages by the
trapezoid (finite) or midpoint (rigid) rule, as the undamped peer.

The step: ``steps_per_period`` steps per period of the fastest of the drive,
``sqrt(alpha)``, ``sqrt(beta)`` and the damping rates ``gamma`` and ``c`` (explicit
in the kicks), rounded up to a whole number per drive period.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from .model import contact_angle, normal

__all__ = ["damped_steps_per_drive_period", "fixed_step_damped"]


def damped_steps_per_drive_period(alpha: float, beta: float, zeta: float, eta_c: float,
                                  steps_per_period: float) -> int:
    """Steps per drive period ``2 pi``: see the module docstring."""
    steps_per_period = float(steps_per_period)
    if not (steps_per_period > 0.0 and math.isfinite(steps_per_period)):
        raise ValueError(
            f"steps_per_period must be in (0, inf) (finite and > 0), got {steps_per_period}")
    w = max(1.0, math.sqrt(alpha), 2.0 * zeta * math.sqrt(alpha))
    if math.isfinite(beta):
        w = max(w, math.sqrt(beta), eta_c * (beta - alpha))
    return max(4, int(math.ceil(steps_per_period * w - 1e-9)))


@njit(cache=True)
def _contact(e, xd, n, dt, k, c):
    """Return mapping of the Kelvin-Voigt element and slider over one step: ``(e, f)``."""
    e_tr = e + dt * xd
    f_tr = k * e_tr + c * xd
    if abs(f_tr) <= n:
        return e_tr, f_tr
    s = 1.0 if f_tr > 0.0 else -1.0
    target = s * n / k
    if c == 0.0:
        return target, s * n
    return target + (e - target) * math.exp(-dt * k / c), s * n


@njit(cache=True)
def _finite(alpha, beta, a, V, gamma, eta, N, n_total, avg_start, initial, record):
    k = beta - alpha
    c = eta * k
    dt = 2.0 * math.pi / N
    if initial == 0:  # steady sliding before the oscillation: e' = 0, f = 1
        y, v, e, f = -1.0 / alpha, 0.0, 1.0 / k, 1.0
    else:
        y, v, e, f = 0.0, -V, 0.0, 0.0
    nrec = n_total + 1 if record else 1
    hist = np.zeros((5, nrec))  # tau, x, x', f, e
    nn = normal(0.0, a)
    if record:
        hist[1, 0], hist[2, 0], hist[3, 0], hist[4, 0] = y, v + V, f, e
    sf = 0.0
    sn = 0.0
    pf = np.zeros((n_total - avg_start) // N)
    pn = np.zeros((n_total - avg_start) // N)
    if avg_start == 0:
        sf += 0.5 * f
        sn += 0.5 * nn
    t_down = 2.0 * math.pi - contact_angle(a) if a > 1.0 else -1.0
    h = 0.5 * dt
    for i in range(n_total):
        f_prev = f
        vh = v + h * (-alpha * y - gamma * v - f)
        y += dt * vh
        m = i + 1
        n_prev = nn
        nn = normal((m % N) * dt, a)
        xd = vh + V
        if nn == 0.0:  # flight (or lift-off inside the step): no force, the spring relaxes
            e = 0.0 if c == 0.0 else e * math.exp(-dt * k / c)
            f = 0.0
        elif n_prev > 0.0:
            e, f = _contact(e, xd, nn, dt, k, c)
        else:
            # touch-down inside this step, at its closed-form time: free before, then
            # the contact from f = 0
            phi = min(1.0, max(0.0, (t_down - (i % N) * dt) / dt))
            if c == 0.0:
                e = 0.0
            else:
                e *= math.exp(-phi * dt * k / c)
            e, f = _contact(e, xd, nn, (1.0 - phi) * dt, k, c)
        v = (vh + h * (-alpha * y - f)) / (1.0 + h * gamma)
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
            hist[0, m], hist[1, m], hist[2, m], hist[3, m], hist[4, m] = (
                tau, y + V * tau, v + V, f, e)
    return sf, sn, pf, pn, hist


@njit(cache=True)
def _rigid(alpha, a, V, gamma, N, n_total, avg_start, initial, record):
    dt = 2.0 * math.pi / N
    h = 0.5 * dt
    if initial == 0:
        y, u = -1.0 / alpha, V
    else:
        y, u = 0.0, 0.0
    nrec = n_total + 1 if record else 1
    hist = np.zeros((5, nrec))
    if record:
        hist[1, 0], hist[2, 0], hist[3, 0] = y, u, (1.0 if initial == 0 else 0.0)
    sf = 0.0
    sn = 0.0
    pf = np.zeros((n_total - avg_start) // N)
    pn = np.zeros((n_total - avg_start) // N)
    for i in range(n_total):
        ym = y + h * (u - V)
        nm = normal(((i % N) + 0.5) * dt, a)
        # u' = -alpha y + gamma (V - u) - f, the dashpot trapezoidal
        ufree = (u * (1.0 - h * gamma) + dt * (gamma * V - alpha * ym)) / (1.0 + h * gamma)
        scale = dt / (1.0 + h * gamma)  # velocity change per unit force over the step
        if abs(ufree) <= scale * nm:
            f = ufree / scale
            u = 0.0
        else:
            f = nm if ufree > 0.0 else -nm
            u = ufree - scale * f
        y = ym + h * (u - V)
        if i >= avg_start:
            sf += f
            sn += nm
            j = (i - avg_start) // N
            pf[j] += f
            pn[j] += nm
        if record:
            m = i + 1
            tau = m * dt
            hist[0, m], hist[1, m], hist[2, m], hist[3, m] = tau, y + V * tau, u, f
    return sf, sn, pf, pn, hist


def fixed_step_damped(alpha, beta, a, V, zeta, eta_c, N, n_total, avg_start, initial,
                      record):
    """One damped run: the window's sums of ``f`` and ``n``, per-period sums, history
    (rows ``tau, x, x', f, e``; ``e = 0`` for a rigid contact)."""
    gamma = 2.0 * zeta * math.sqrt(alpha)
    if math.isinf(beta):
        return _rigid(alpha, a, V, gamma, N, n_total, avg_start, initial, record)
    return _finite(alpha, beta, a, V, gamma, eta_c, N, n_total, avg_start, initial, record)
