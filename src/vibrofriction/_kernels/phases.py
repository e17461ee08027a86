r"""Closed-form solutions of the three phases (docs/model.md, paper eqs. 4, 5, 15).

Scaled variables: time ``tau = omega t``, forces in ``mu0 F_N0``, lengths in
``mu0 F_N0 / (m omega^2)``; ``y = x - V tau`` is the body displacement with the
drift removed, ``f`` the tangential contact force, ``n = 1 + a cos tau`` the
normal force and ``k = beta - alpha`` the contact stiffness (``inf`` = rigid).
``theta`` is the drive phase at the segment start, ``t`` the time since then.

* slip ``s``:  ``y'' + alpha y = -s (1 + a cos tau)``, ``f = s n`` (natural
  frequency ``sqrt(alpha)``, driven at 1, resonant at ``alpha = 1``);
* flight:     ``y'' + alpha y = 0``, ``f = 0``;
* stick:      ``f'' + beta f = alpha (f_0 - k y_0) + alpha k V t`` with the
  contact point fixed, so ``y = y_0 + (f - f_0)/k - V t`` (natural frequency
  ``sqrt(beta)``); rigid contact: ``y' = -V``, ``f = -alpha y``.

Each function returns coefficient tuples over :mod:`.basis`.
"""

import math

from .basis import add, derivative, scale
from .jit import jit


@jit
def free_y(alpha, w, theta, y0, yd0, s, a):
    """``y(t)`` in slip ``s`` (``s = 0``: flight) from ``(y0, y0')`` at phase ``theta``."""
    return (-s / alpha, 0.0, 0.0, 0.0, y0 + s / alpha, yd0 / w,
            -s * a * math.cos(theta), s * a * math.sin(theta))


@jit
def slip_velocity(ycoef, w, theta, s, a, V, k):
    """Contact-point velocity times ``s``: ``s (V + y') + (a/k) sin tau`` (eq. 10)."""
    ak = a / k  # 0 for a rigid contact
    v = scale(derivative(ycoef, w), s)
    return add(v, (s * V, 0.0, ak * math.sin(theta), ak * math.cos(theta), 0.0, 0.0, 0.0, 0.0))


@jit
def stick_force(alpha, beta, k, W, V, y0, xd0, f0):
    """``f(t)`` in stick (finite contact stiffness), harmonic at ``W = sqrt(beta)``.

    Takes the body velocity ``xd0 = x'`` itself, not ``y' = x' - V``: ``f' = k x'``
    with ``k`` up to 1e6 would amplify the cancellation in ``V + y'``.
    """
    p0 = alpha * (f0 / beta - (k / beta) * y0)
    p1 = alpha * (k / beta) * V
    return (p0, p1, 0.0, 0.0, f0 - p0, (k * xd0 - p1) / W, 0.0, 0.0)


@jit
def rigid_stick_force(alpha, V, y0):
    """``f(t) = -alpha y`` with ``y = y0 - V t`` (rigid contact, body at rest)."""
    return (-alpha * y0, alpha * V, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)


@jit
def cone_margin(fcoef, theta, s, a):
    """``n(tau) - s f(tau)``: positive inside the friction cone (eq. 15)."""
    ca = a * math.cos(theta)
    sa = a * math.sin(theta)
    return (1.0 - s * fcoef[0], -s * fcoef[1], ca - s * fcoef[2], -sa - s * fcoef[3],
            -s * fcoef[4], -s * fcoef[5], -s * fcoef[6], -s * fcoef[7])


@jit
def normal_force(theta, a):
    return 1.0 + a * math.cos(theta)


@jit
def normal_force_rate(theta, a):
    return -a * math.sin(theta)


@jit
def normal_integral(theta, t, a):
    """Integral of ``1 + a cos tau`` over ``[theta, theta + t]``."""
    return t + a * (math.sin(theta + t) - math.sin(theta))
