"""The resonant case IV: eqs. (27)-(32), exact and approximate, and its damped law."""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..validation import as_float_or_array, checked
from .domains import FloatOrArray, elementwise, valid_array
from .jumping import contact_half_angle, mean_normal_force


# ------------------------------------------------------------------ case IV, eqs. (27)-(32)
def _drive_work(a: NDArray[np.float64]) -> NDArray[np.float64]:
    r"""``E(a) = 2 pi <n cos tau>``: ``pi a`` for ``a <= 1``, ``a theta + sin theta`` above."""
    theta = contact_half_angle(a)
    return np.where(a > 1.0, a * theta + np.sin(theta), np.pi * a)


def resonant_velocity_ratio(amplitude: ArrayLike) -> FloatOrArray:
    r"""Paper's approximate ``v0/dv`` of the resonant oscillation (case IV, the eq. after (32)).

    .. math:: \frac{v_0}{\Delta v} = 1 - \frac12\left(\frac{\pi\,\Delta F}
              {4(F_{N,0} + \Delta F)}\right)^2, \quad \Delta F / F_{N,0} = a,

    from the energy balance of ``resonant_velocity_ratio_exact`` with
    ``sin tau* ~ tau*``, ``cos tau* ~ 1``: ``4(1 + a) tau* = pi a``, and
    ``tau* ~ sqrt(2(1 - v0/dv))``. For ``a > 1`` the right-hand side ``pi a``
    becomes ``a theta + sin theta`` (loss of contact, ``theta = arccos(-1/a)``).
    """
    a = valid_array("amplitude", amplitude)
    tau_star = _drive_work(a) / (4.0 * (1.0 + a))
    return as_float_or_array(1.0 - 0.5 * tau_star**2)


def resonant_tau_star(v_ratio: ArrayLike, *, approximate: bool = False) -> FloatOrArray:
    r"""Half-width ``tau*`` of the reverse-slip window of case IV (eqs. numbered (32)).

    ``x' = dv cos tau`` exceeds the substrate velocity ``v0`` for
    ``|tau| < tau* = arccos(v0/dv)``; with ``approximate=True`` the paper's
    ``tau* ~ sqrt(2(1 - v0/dv))``, accurate for ``v0/dv -> 1``.
    ``v_ratio = v0/dv`` must lie in ``[-1, 1]`` (``<= 1`` if approximate).
    """
    if approximate:
        r = checked("v_ratio", v_ratio, maximum=1.0)
        return as_float_or_array(np.sqrt(2.0 * (1.0 - r)))
    r = checked("v_ratio", v_ratio, minimum=-1.0, maximum=1.0)
    return as_float_or_array(np.arccos(r))


def _resonant_tau_star_exact(a: float) -> float:
    if a == 0.0:
        return 0.0
    from scipy.optimize import brentq

    work = float(_drive_work(np.asarray(a)))

    def balance(t: float) -> float:
        return 4.0 * math.sin(t) + 2.0 * a * (t + math.sin(t) * math.cos(t)) - work

    return float(brentq(balance, 0.0, 0.5 * math.pi, xtol=1e-300, rtol=1e-15))


def _tau_star_exact(a: NDArray[np.float64]) -> NDArray[np.float64]:
    return elementwise(_resonant_tau_star_exact, a)


def resonant_velocity_ratio_exact(amplitude: ArrayLike) -> FloatOrArray:
    r"""Exact root ``r = v0/dv`` of the paper's energy balance for case IV (first eq. (32)).

    With ``x' = dv cos tau`` (eq. 30) the mean power of friction vanishes:
    ``<n(tau) cos tau sign(r - cos tau)> = 0``. The sign is ``-1`` on
    ``|tau| < tau* = arccos r`` and ``+1`` elsewhere, so (for ``a <= 1``)

    .. math:: \int_0^{2\pi}(\cos\tau + a\cos^2\tau)\,d\tau
              - 2\int_{-\tau^*}^{\tau^*}(\cos\tau + a\cos^2\tau)\,d\tau
              = \pi a - 4\sin\tau^* - 2a(\tau^* + \sin\tau^*\cos\tau^*) = 0.

    For ``a > 1`` (jumping) ``n = max(0, 1 + a cos tau)`` and the first
    integral is ``a theta + sin theta`` with ``theta = arccos(-1/a) > pi/2 > tau*``
    (contact is lost only where the sign is ``+1``). The left side is increasing
    in ``tau*`` on ``[0, pi/2]``, negative at 0 and ``>= 3`` at ``pi/2``: one root,
    found with ``scipy.optimize.brentq``. (The phase of ``x'`` relative to ``n``
    assumed in eq. (30) is consistent: the quadrature component of the
    fundamental of the friction force vanishes only for phase 0 or pi.)
    """
    a = valid_array("amplitude", amplitude)
    return as_float_or_array(np.cos(_tau_star_exact(a)))


def resonant_plateau(amplitude: ArrayLike) -> FloatOrArray:
    r"""Paper's plateau of ``mu/mu0`` at large velocity in case IV, last eq. (32).

    ``mu/mu0 = 1 - (2/pi)(tau* + a sin tau*) / <n>`` (see
    ``resonant_plateau_exact``) with ``tau* + a sin tau* ~ (1 + a) tau*`` and
    ``(1 + a) tau* ~ E/4`` gives ``mu/mu0 ~ 1 - <n cos tau>/<n>``, i.e.

    * ``1 - a/2`` for ``a <= 1`` (the paper's result; ``dF/F_N0 = a``);
    * ``1 - (a theta + sin theta) / (2 (theta + a sin theta))`` for ``a > 1``,
      ``theta = arccos(-1/a)``: the same approximation with loss of contact and
      the mean normal force of eq. (25). The paper gives no formula here; its
      ``1 - a/2`` would neglect loss of contact (negative for ``a > 2``). This one
      tends to ``1 - pi/4`` as ``a -> inf``.
    """
    a = valid_array("amplitude", amplitude)
    theta = contact_half_angle(a)
    jumping = 1.0 - (a * theta + np.sin(theta)) / (2.0 * (theta + a * np.sin(theta)))
    return as_float_or_array(np.where(a > 1.0, jumping, 1.0 - 0.5 * a))


def resonant_plateau_exact(amplitude: ArrayLike) -> FloatOrArray:
    r"""Plateau of ``mu/mu0`` in case IV without the small-``tau*`` approximations.

    The friction force on the body is ``mu0 F_N sign(v0 - x')``, so with
    ``x' = dv cos tau`` and ``tau* = arccos(v0/dv)`` from
    ``resonant_velocity_ratio_exact`` (eq. 25, ``mu = <F_x>/<F_N>``)

    .. math:: \frac{\mu}{\mu_0}
              = \frac{\langle n\,\mathrm{sign}(r - \cos\tau)\rangle}{\langle n\rangle}
              = \frac{1}{\langle n\rangle}\left[\langle n\rangle
              - \frac{2}{2\pi}\int_{-\tau^*}^{\tau^*}(1 + a\cos\tau)\,d\tau\right]
              = 1 - \frac{2}{\pi}\,\frac{\tau^* + a\sin\tau^*}{\langle n\rangle},

    with ``<n> = 1`` for ``a <= 1`` (the paper's second eq. (32)) and
    ``mean_normal_force(a)`` for ``a > 1``. Valid within the paper's ansatz
    (harmonic body velocity, rigid contact ``beta = inf``, ``alpha = 1``,
    large ``v0``); the solver is the judge of the ansatz.
    """
    a = valid_array("amplitude", amplitude)
    tau = _tau_star_exact(a)
    n_mean = np.asarray(mean_normal_force(a))
    return as_float_or_array(1.0 - (2.0 / np.pi) * (tau + a * np.sin(tau)) / n_mean)


# --------------------------------------------------------------------------- case IV, damped
def _damped_tau_star(x: float, a: float) -> float:
    """Root ``tau*`` of ``G(tau*) cos tau* = x`` on ``[0, tau*_0]`` (``x = pi gamma V``)."""
    work = float(_drive_work(np.asarray(a)))
    if x >= work:
        return 0.0
    from scipy.optimize import brentq

    def balance(t: float) -> float:
        g = work - 4.0 * math.sin(t) - 2.0 * a * (t + math.sin(t) * math.cos(t))
        return g * math.cos(t) - x

    hi = _resonant_tau_star_exact(a)  # the undamped root, where G = 0
    if balance(hi) >= 0.0:  # x = 0 (no damping) or below G's round-off there
        return hi
    return float(brentq(balance, 0.0, hi, xtol=1e-300, rtol=1e-15))


def resonant_damped_mu_ratio(v_inertial: ArrayLike, amplitude: ArrayLike,
                             zeta: ArrayLike) -> FloatOrArray:
    r"""The rise of ``mu/mu0`` to 1 in case IV with a damped pin (docs/damping.md).

    The paper's energy balance of case IV (first eq. 32) with the pin dashpot
    ``gamma = 2 zeta`` (``alpha = 1``, rigid contact, harmonic body velocity
    ``x' = V - dv cos tau``): the mean power friction feeds into the oscillation now
    equals what the dashpot dissipates, ``gamma dv^2/2``, instead of 0,

    .. math:: \pi\gamma\,dv = G(\tau^*) = E(a) - 4\sin\tau^*
              - 2a(\tau^* + \sin\tau^*\cos\tau^*), \qquad V = dv\cos\tau^*,

    (``E(a) = pi a`` for ``a <= 1``, ``a theta + sin theta`` with loss of contact), so
    ``tau*`` solves ``G(tau*) cos tau* = pi gamma V`` and, as for the plateau,

    .. math:: \mu/\mu_0 = 1 - \frac{2}{\pi}\frac{\tau^* + a\sin\tau^*}{\langle n\rangle}.

    At ``gamma = 0`` it is :func:`resonant_plateau_exact`; ``tau*`` closes (``mu = mu0``)
    at ``V = E(a)/(pi gamma)``, which is the critical velocity ``a/(2 zeta)`` for
    ``a <= 1``.  Within the ansatz (large ``V``, harmonic motion); the solver is the judge.
    """
    V = valid_array("v_inertial", v_inertial)
    a = valid_array("amplitude", amplitude)
    zeta = valid_array("zeta", zeta)
    V, a, zeta = np.broadcast_arrays(V, a, zeta)
    x = np.pi * 2.0 * zeta * V
    tau = elementwise(_damped_tau_star, x, a)
    n_mean = np.asarray(mean_normal_force(a))
    return as_float_or_array(1.0 - (2.0 / np.pi) * (tau + a * np.sin(tau)) / n_mean)
