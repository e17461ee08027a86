"""The stiff limit: the exact mean friction of a rigid contact without jumping."""

from __future__ import annotations

import math

from numpy.typing import ArrayLike

from ..validation import as_float_or_array
from .domains import ANY_VBAR, NO_JUMPING, FloatOrArray, elementwise, valid_array


# --------------------------------------------------------------------------- stiff limit
def _stiff_tau2(vbar: float) -> tuple[float, float]:
    """``(tau1, tau2)``, the start and the end of stick.

    Stick starts where ``n' = k V`` on the rising branch and ends where the stick line
    ``n(tau1) + a vbar (tau - tau1)`` meets ``n`` again.
    """
    tau1 = math.pi + math.asin(vbar)
    if vbar >= 1.0:
        return tau1, tau1
    if vbar == 0.0:
        return tau1, tau1 + 2.0 * math.pi
    from scipy.optimize import brentq

    def gap(t: float) -> float:  # (n - stick line)/a: positive while the contact sticks
        return math.cos(tau1 + t) - math.cos(tau1) - vbar * t

    # the gap grows while n' > k V, i.e. until t = pi - 2 asin(vbar), then falls to
    # -2 pi vbar at t = 2 pi: one crossing in between
    t_max = math.pi - 2.0 * math.asin(vbar)
    return tau1, tau1 + brentq(gap, t_max, 2.0 * math.pi, xtol=1e-15, rtol=1e-15)


def _stiff_exact(vbar: float, a: float) -> float:
    if vbar >= 1.0 or a == 0.0:
        return 1.0
    tau1, tau2 = _stiff_tau2(vbar)
    d = tau2 - tau1
    deficit = math.sin(tau2) - math.sin(tau1) - d * math.cos(tau1) - 0.5 * vbar * d * d
    return 1.0 - a * deficit / (2.0 * math.pi)


def mu_ratio_stiff_exact(vbar: ArrayLike, amplitude: ArrayLike) -> FloatOrArray:
    r"""The exact law of the stiff limit (Part I's flat contact), of which eq. (26) is a fit.

    For ``alpha, beta -> 0`` the body moves at the pulling velocity and only the contact
    spring sees it: stick ``f' = k V``, forward slip ``f = n`` while the contact point
    moves forward, ``n' < k V``, ``vbar = k V / a`` (eq. 14).  Slip ends at
    ``tau1 = pi + asin(vbar)`` where ``n'`` rises through ``k V``; the stick line
    ``f = n(tau1) + a vbar (tau - tau1)`` meets ``n`` again at ``tau2`` (one root of
    ``cos tau2 - cos tau1 = vbar (tau2 - tau1)``), so (docs/damping.md)

    .. math:: \frac{\mu}{\mu_0} = 1 - \frac{a}{2\pi}\Big[\sin\tau_2 - \sin\tau_1
              - (\tau_2 - \tau_1)\cos\tau_1 - \tfrac{\bar v}{2}(\tau_2 - \tau_1)^2\Big],

    ``1 - a`` at ``vbar = 0`` (eq. 2), 1 for ``vbar >= 1``.  For ``0 <= a <= 1``.
    """
    v = valid_array("vbar", vbar, ANY_VBAR)
    a = valid_array("amplitude", amplitude, NO_JUMPING)
    return as_float_or_array(elementwise(_stiff_exact, v, a))
