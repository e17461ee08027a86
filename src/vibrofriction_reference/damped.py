"""Peer B with damping: fixed-step dynamics with a pin dashpot and a Kelvin-Voigt contact.

Written from the model statement (``docs/damping.md``), independently of the
``vibrofriction`` package.  Scaled variables (``docs/model.md``), ``y = x - V tau``,
``v = y'``, ``gamma = 2 zeta sqrt(alpha)``, ``k = beta - alpha``, ``c = eta_c k``::

    y'' = -alpha y - gamma v - f            (x'' = alpha (V tau - x) + gamma (V - x') - f)
    f = k e + c (x' - x_c'),  e = x - x_c,  |f| <= n = max(0, 1 + a cos tau)
    stick: x_c' = 0 (e' = x') while |k e + c x'| <= n
    slip s: f = s n, c e' = s n - k e, s = sign(x_c') = sign(k e + c x' - s n)
    flight (n = 0): f = 0, c e' = -k e
    (eta_c = 0: the Jenkins element, e = f / k, e = 0 in flight)

For ``c > 0`` this is an ODE with a continuous right-hand side, ``f = clip(k e + c x',
-n, n)`` and ``c e' = f - k e``; for ``c = 0`` it is the rate-independent Jenkins element.

**Finite contact, one step ``dt``** (velocity Verlet, every velocity-dependent force
trapezoidal): a half kick with the force of the last step end (``v + dt/2 (-alpha y -
gamma v - f)``), a drift of ``y``, then the contact and the second half kick solved
together, implicitly in the end velocity (the linear step in closed form):

    x'_1 = A - B f,  A = V + (v_half - dt/2 alpha y_1) / (1 + dt gamma / 2),
                     B = (dt/2) / (1 + dt gamma / 2)

A return mapping of the Kelvin-Voigt element in series with the slider gives ``f``:

* stick predictor: the contact point held fixed, ``e_tr = e + dt x'_half`` (exactly the
  body's displacement over the step), and ``f_tr = k e_tr + c x'_1`` with the implicit
  end velocity, ``f_tr = (k e_tr + c A) / (1 + c B)``;
* if ``|f_tr| <= n(tau_1)``: stick, ``e = e_tr``, ``f = f_tr``;
* else slip ``s = sign(f_tr)``: ``f = s n(tau_1)`` and ``e`` relaxes exactly (an
  exponential integrator) towards ``s n(tau) / k`` with the rate ``k / c = 1 / eta_c``,
  ``n`` linear over the step; ``e = s n / k`` when ``c = 0``;
* with ``c > 0``, a switch inside the step (stick at the start and slip at the end, or
  the reverse) is placed where ``s F - n``, ``F = k e + c x'``, interpolated linearly
  between the step's ends, crosses 0: stick (``e`` follows the body) on one part, the
  exact slip relaxation on the other (without it ``e`` would relax over the whole step,
  an error growing like ``dt / eta_c``);
* flight: ``f = 0``, ``e`` decays exactly, ``e exp(-dt / eta_c)`` (0 when ``c = 0``);
  a lift-off inside the step at its closed-form time (slip relaxation towards
  ``s n(tau) / k`` until it, free decay after); a touch-down inside the step at its
  closed-form time: free decay until it, the contact from ``f = 0`` after.

The dashpots enter as trapezoidal (half explicit, half implicit) velocity forces, so the
pin dashpot and the contact dashpot are A-stable for any ``dt``, and the relaxation of
``e`` is exact in slip and flight: the scheme is stable for every ``gamma, eta_c >= 0``
and ``dt`` within the (undamped) Verlet limit ``dt sqrt(beta) < 2`` of the springs.
Second order in ``dt`` (each switch costs an ``O(dt^2)`` local error: with ``c > 0`` the
right-hand side is continuous, with ``c = 0`` the force is); measured in
``tests/reference/test_reference_damped.py``.

**Rigid contact** (``beta = inf``, ``eta_c`` irrelevant): Moreau's midpoint scheme with
the pin dashpot trapezoidal, the friction impulse in ``[-n dt, n dt]`` stopping the body
when it can (stick has the reaction ``f = -alpha y + gamma V``).  About first order, as
the undamped Moreau scheme at fine steps.

Averages by the trapezoid (finite) or midpoint (rigid) rule, as the undamped peer.

The step: ``steps_per_period`` steps per period of the fastest of the drive,
``sqrt(alpha)``, ``sqrt(beta)`` and the damping rates ``gamma`` and ``c`` (not for
stability, which needs none of them, but to resolve what a rate contributes to the
error constant), rounded up to a whole number per drive period.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from .model import contact_angle, normal

__all__ = ["HISTORY_ROWS", "damped_steps_per_drive_period", "fixed_step_damped"]

HISTORY_ROWS = ("tau", "x", "xdot", "f", "e")
"""Rows of the history array of :func:`fixed_step_damped`."""


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
def _relax(e, g0, g1, span, c, k):
    """``e`` after ``span`` of ``c e' = k (g(t) - e)``, ``g`` linear from ``g0`` to ``g1``.

    Exact (an exponential integrator): ``e1 = g1 + (e - g0) E - (g1 - g0)(1 - E)/r``
    with ``r = span k / c``, ``E = exp(-r)``; ``g1`` when ``c = 0``.
    """
    if c == 0.0:
        return g1
    r = span * k / c
    if r <= 0.0:
        return e
    return g1 + (e - g0) * math.exp(-r) + (g1 - g0) * (math.expm1(-r) / r)


@njit(cache=True)
def _contact(e, xd, span, n_a, n1, k, c, A, B, F_a, s_a):
    """Return mapping of the Kelvin-Voigt element and the slider over ``span``.

    ``e`` at the start, ``xd`` the body velocity over the step (the contact point is
    fixed in stick, so ``e`` grows by ``span xd``), ``n_a`` and ``n1`` the normal force
    at the start and the end of ``span``, the end velocity ``x'_1 = A - B f``;
    ``F_a = k e + c x'`` at the start and ``s_a`` the phase there (0 stick, +-1 slip).
    With ``c > 0`` a switch inside the step is placed where the linear interpolation of
    ``s F - n`` crosses 0 (stick then slip, or slip then stick).  Returns ``(e, f, s)``
    at the end (``s = 0`` in stick).
    """
    e_tr = e + span * xd
    f_tr = (k * e_tr + c * A) / (1.0 + c * B)
    if abs(f_tr) <= n1:
        if c > 0.0 and s_a != 0.0:  # the slip of the start ended inside the step
            g0 = s_a * F_a - n_a
            g1 = s_a * f_tr - n1
            phi = g0 / (g0 - g1) if g0 > 0.0 and g1 < 0.0 else 0.0
            n_phi = n_a + phi * (n1 - n_a)
            e_phi = _relax(e, s_a * n_a / k, s_a * n_phi / k, phi * span, c, k)
            e_sw = e_phi + (1.0 - phi) * span * xd
            f_sw = (k * e_sw + c * A) / (1.0 + c * B)
            if abs(f_sw) <= n1:
                return e_sw, f_sw, 0.0
        return e_tr, f_tr, 0.0
    s = 1.0 if f_tr > 0.0 else -1.0
    if c > 0.0 and s_a == 0.0:  # the stick of the start ended inside the step
        g0 = n_a - s * F_a
        g1 = n1 - s * f_tr
        phi = g0 / (g0 - g1) if g0 > 0.0 else 0.0
        n_phi = n_a + phi * (n1 - n_a)
        e = _relax(e + phi * span * xd, s * n_phi / k, s * n1 / k, (1.0 - phi) * span, c, k)
        return e, s * n1, s
    return _relax(e, s * n_a / k, s * n1 / k, span, c, k), s * n1, s


@njit(cache=True)
def _finite(alpha, beta, a, V, gamma, eta, N, n_total, avg_start, initial, record):
    k = beta - alpha
    c = eta * k
    dt = 2.0 * math.pi / N
    h = 0.5 * dt
    B = h / (1.0 + h * gamma)
    nn = normal(0.0, a)
    if initial == 0:  # steady sliding before the oscillation: x' = V, e = 1/k
        y, v, e = -1.0 / alpha, 0.0, 1.0 / k
        f = 1.0 + c * V  # the contact sticks if it can, else slips
        if f > nn:
            f = nn
    else:
        y, v, e, f = 0.0, -V, 0.0, 0.0
    nrec = n_total + 1 if record else 1
    hist = np.zeros((5, nrec))  # tau, x, x', f, e
    if record:
        hist[1, 0], hist[2, 0], hist[3, 0], hist[4, 0] = y, v + V, f, e
    sf = 0.0
    sn = 0.0
    pf = np.zeros((n_total - avg_start) // N)
    pn = np.zeros((n_total - avg_start) // N)
    if avg_start == 0:
        sf += 0.5 * f
        sn += 0.5 * nn
    theta = contact_angle(a) if a >= 1.0 else -1.0  # lift-off, touch-down at 2 pi - theta
    t_down = 2.0 * math.pi - theta
    sp = 0.0 if abs(f) < nn else (1.0 if f > 0.0 else -1.0)  # phase: 0 stick, +-1 slip
    for i in range(n_total):
        f_prev = f
        F_a = k * e + c * (v + V)
        vh = v + h * (-alpha * y - gamma * v - f)
        y += dt * vh
        m = i + 1
        n_prev = nn
        nn = normal((m % N) * dt, a)
        xd = vh + V
        A = (vh - h * alpha * y) / (1.0 + h * gamma) + V
        if nn > 0.0 and n_prev > 0.0:
            e, f, sp = _contact(e, xd, dt, n_prev, nn, k, c, A, B, F_a, sp)
        elif nn > 0.0:
            # touch-down inside this step, at its closed-form time: free decay of the
            # spring before, the contact from f = 0 after (slip along k e + c x')
            phi = min(1.0, max(0.0, (t_down - (i % N) * dt) / dt))
            e = _relax(e, 0.0, 0.0, phi * dt, c, k)
            F_a = k * e + c * xd
            s_a = 1.0 if F_a > 0.0 else (-1.0 if F_a < 0.0 else 0.0)
            e, f, sp = _contact(e, xd, (1.0 - phi) * dt, 0.0, nn, k, c, A, B, F_a, s_a)
        else:
            if n_prev > 0.0:
                # lift-off inside this step: the slider slips with n falling to 0
                phi = min(1.0, max(0.0, (theta - (i % N) * dt) / dt))
                s = 1.0 if k * e + c * xd >= 0.0 else -1.0
                e = _relax(e, s * n_prev / k, 0.0, phi * dt, c, k)
                e = _relax(e, 0.0, 0.0, (1.0 - phi) * dt, c, k)
            else:  # flight: no force, the spring relaxes
                e = _relax(e, 0.0, 0.0, dt, c, k)
            f = 0.0
        v = A - V - B * f
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
    """One damped run.

    The window's sums of ``f`` and ``n``, per-period sums, history (rows :data:`HISTORY_ROWS`:
    ``tau, x, x', f, e``; ``e = 0`` for a rigid contact).
    """
    gamma = 2.0 * zeta * math.sqrt(alpha)
    if math.isinf(beta):
        return _rigid(alpha, a, V, gamma, N, n_total, avg_start, initial, record)
    return _finite(alpha, beta, a, V, gamma, eta_c, N, n_total, avg_start, initial, record)
