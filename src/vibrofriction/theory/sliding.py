"""Sliding and static friction without jumping.

Eq. (2), the critical velocity of eqs. (12)-(14), steady sliding of eqs. (7)-(10) and the laws of
eqs. (26), (27).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike

from ..schema import POSITIVE
from ..validation import as_float_or_array, checked, validated
from .domains import ANY_VBAR, NO_JUMPING, SOFT_LIMIT, FloatOrArray, ratio_or_inf, valid_array
from .inplane import checked_inplane_on, inplane_critical_velocity

#: Exponent of the soft-system law, eq. (27); printed "1,2" (decimal comma).
SOFT_EXPONENT: float = 1.2


#: ``sqrt(4 pi / 9)``, the linear coefficient of eq. (27).
_SOFT_SLOPE: float = math.sqrt(4.0 * math.pi / 9.0)


# --------------------------------------------------------------------------- eq. (2)
def static_mu_ratio(amplitude: ArrayLike) -> FloatOrArray:
    r"""Static limit ``mu(v0 -> 0) / mu0``, eq. (2).

    The body sticks until the pulling force reaches the *smallest* friction
    limit of the cycle, ``mu0 (F_N0 - dF_N)``: ``1 - a`` for ``a < 1``, ``0``
    for ``a >= 1`` (jumping: the normal force vanishes once per period).

    Parameters
    ----------
    amplitude : array_like
        ``a = du_z / u_z0 >= 0``.
    """
    a = valid_array("amplitude", amplitude)
    return as_float_or_array(np.where(a < 1.0, 1.0 - a, 0.0))


# --------------------------------------------------------------------------- eqs. (12)-(14)
def critical_velocity(mu0: ArrayLike, omega: ArrayLike, du_z: ArrayLike, k_zc: ArrayLike,
                      k_xc: ArrayLike, k_x: ArrayLike, mass: ArrayLike, c_x: ArrayLike = 0.0,
                      c_xc: ArrayLike = 0.0) -> FloatOrArray:
    r"""Critical ("insensitivity") velocity ``v0*`` in m/s, eq. (12), with damping.

    .. math:: v_0^* = \mu_0 \omega \Delta u_z k_{z,c}
              \frac{|1 + (d + i\omega c_x)/k_{x,c} + i\eta_c|}
                    {|d + i\omega c_x|\sqrt{1 + \eta_c^2}},
              \quad d = k_x - m\omega^2,\ \eta_c = \omega c_{x,c}/k_{x,c}

    (docs/damping.md; undamped it is eq. 12,
    ``mu0 omega du_z (k_zc/k_xc) |k_xc + k_x - m omega^2| / |k_x - m omega^2|``).
    Above ``v0*`` the contact point of the periodic sliding solution never stops and
    ``mu = mu0``.  ``k_xc = inf`` (rigid contact) gives
    ``mu0 omega du_z k_zc / |d + i omega c_x|``.  Returns ``inf`` at ``d = 0`` without
    pin damping (case IV), ``0`` at ``k_x + k_xc = m omega^2`` without damping (case
    III) and ``0`` when ``du_z = 0`` (no oscillation, no reduction of friction).
    """
    mu0, omega, du_z, k_zc, k_xc, k_x, mass, c_x, c_xc = validated(
        {"mu0": mu0, "omega": omega, "du_z": du_z, "k_zc": k_zc, "k_xc": k_xc, "k_x": k_x,
         "mass": mass, "c_x": c_x, "c_xc": c_xc}, ranges={"k_x": SOFT_LIMIT}).values()
    detuning = (k_x - mass * omega**2) + 1j * omega * c_x
    eta = np.where(np.isinf(k_xc), 0.0, omega * c_xc / k_xc)
    num = mu0 * omega * du_z * k_zc * np.abs(1.0 + detuning / k_xc + 1j * eta)
    return as_float_or_array(ratio_or_inf(num, np.abs(detuning) * np.sqrt(1.0 + eta**2)))


def critical_velocity_soft(mu0: ArrayLike, dF_N: ArrayLike, mass: ArrayLike,
                           omega: ArrayLike) -> FloatOrArray:
    r"""Critical velocity of a soft system on a stiff contact (case I), eq. (13).

    ``v0*_soft = mu0 dF_N / (m omega)``, the limit of eq. (12) for
    ``k_x << m omega^2 << k_xc``, with ``dF_N = k_zc du_z``. The paper writes
    ``|m omega^2|`` in the denominator; the modulus is redundant.
    """
    mu0, mass, omega = validated({"mu0": mu0, "mass": mass, "omega": omega}).values()
    dF_N = checked("dF_N", dF_N, minimum=0.0)
    return as_float_or_array(mu0 * dF_N / (mass * omega))


def critical_velocity_stiff(mu0: ArrayLike, omega: ArrayLike, du_z: ArrayLike,
                            k_zc: ArrayLike, k_xc: ArrayLike) -> FloatOrArray:
    r"""Critical velocity of a stiff system (case II), eq. (14).

    ``v0*_stiff = mu0 omega du_z k_zc / k_xc``, the limit of eq. (12) for
    ``k_xc << |k_x - m omega^2|`` (Part I of the series). Independent of the
    inertia; only the Mindlin ratio ``k_zc / k_xc`` enters.
    """
    mu0, omega, du_z, k_zc, k_xc = validated(
        {"mu0": mu0, "omega": omega, "du_z": du_z, "k_zc": k_zc, "k_xc": k_xc},
        ranges={"k_xc": POSITIVE}).values()  # a compliant contact: eq. (14) needs k_xc < inf
    return as_float_or_array(mu0 * omega * du_z * k_zc / k_xc)


def critical_inertial_velocity(alpha: ArrayLike, beta: ArrayLike, amplitude: ArrayLike,
                               zeta: ArrayLike = 0.0, eta_c: ArrayLike = 0.0,
                               a_x: ArrayLike = 0.0, phase_x: ArrayLike = 0.0,
                               inplane_on: str = "substrate") -> FloatOrArray:
    r"""Critical inertial velocity ``V_c`` (``V = V_c vbar``), eqs. (12), (16), (20) damped.

    Continuous forward sliding (``a <= 1``) is the periodic solution
    ``y = -1/alpha - a Re(e^{i tau}/P)``, ``P = alpha - 1 + i gamma``, of
    ``y'' + gamma y' + alpha y = -n``, with the contact spring following
    ``eta_c e' + e = n/k``; its contact point never stops iff (docs/damping.md)

    .. math:: V > V_c = \frac{a\,|(\beta - 1) + i(\gamma + \eta_c k)|}
              {|(\alpha - 1) + i\gamma|\; k\sqrt{1 + \eta_c^2}}
              = \frac{a\,|1 + (\alpha - 1 + i\gamma)/k + i\eta_c|}
              {|\alpha - 1 + i\gamma|\sqrt{1 + \eta_c^2}},

    ``gamma = 2 zeta sqrt(alpha)``, ``k = beta - alpha``.  Undamped it is eq. (12) over
    ``mu0 F_N0/(m omega)``, ``a|beta - 1|/((beta - alpha)|alpha - 1|)``; the second
    form gives the rigid contact ``beta = inf``: ``a/|alpha - 1 + i gamma|``.
    ``inf`` at ``alpha = 1`` without pin damping (case IV), ``0`` at ``beta = 1``
    without damping (case III) and ``0`` at ``a = 0``.  In the soft limit
    (``alpha -> 0``, ``beta -> inf``, undamped) ``V_c -> a``, i.e. eq. (13).

    With a longitudinal in-plane oscillation (``a_x > 0``, any element) it is
    :func:`inplane_critical_velocity` (docs/inplane.md), which reproduces the above at
    ``a_x = 0`` to round-off; without one, the above exactly.
    """
    if np.any(np.asarray(a_x, dtype=float) != 0.0):
        return inplane_critical_velocity(alpha, beta, amplitude, a_x, phase_x, zeta, eta_c,
                                         inplane_on)
    validated({"a_x": a_x, "phase_x": phase_x})
    checked_inplane_on(inplane_on)
    alpha, beta, a, zeta, eta = validated(
        {"alpha": alpha, "beta": beta, "amplitude": amplitude, "zeta": zeta, "eta_c": eta_c},
        ranges={"alpha": SOFT_LIMIT}).values()
    detuning = (alpha - 1.0) + 2j * zeta * np.sqrt(alpha)
    eta = np.where(np.isinf(beta), 0.0, eta)
    num = a * np.abs(1.0 + detuning / (beta - alpha) + 1j * eta)
    return as_float_or_array(ratio_or_inf(num, np.abs(detuning) * np.sqrt(1.0 + eta**2)))


# --------------------------------------------------------------------------- eqs. (7)-(10)
class SteadySliding(NamedTuple):
    """Periodic continuous-sliding solution, eqs. (7), (8), (10), scaled (see module doc)."""

    #: Body displacement minus the drift, ``y = x - V tau``.
    y: FloatOrArray
    #: Body velocity ``x'``.
    velocity: FloatOrArray
    #: Velocity of the contact point ``x_c'``; the solution is physical only if it is >= 0.
    contact_velocity: FloatOrArray


def steady_sliding(tau: ArrayLike, alpha: ArrayLike, beta: ArrayLike, amplitude: ArrayLike,
                   V: ArrayLike) -> SteadySliding:
    r"""Periodic solution of permanent forward slip, eqs. (7), (8), (10), scaled.

    In slip ``f = n(tau) = 1 + a cos tau`` and ``x'' + alpha x = alpha V tau - n``
    (eq. 6). Its particular solution is (eq. 7, whose last term
    ``mu0 k_zc du_z cos(omega t) / (m omega^2 - k_x)`` scales to ``a cos(tau)/(1 - alpha)``)

    .. math:: x = V\tau - \frac{1}{\alpha} + \frac{a\cos\tau}{1 - \alpha}, \qquad
              x' = V - \frac{a \sin\tau}{1 - \alpha}  \quad\text{(eq. 8)}.

    Since ``f = (beta - alpha)(x - x_c)``, the contact point moves at
    ``x_c' = x' - f'/(beta - alpha)`` (eq. 9), i.e. (eq. 10)

    .. math:: x_c' = V - a \sin\tau \frac{\beta - 1}{(1 - \alpha)(\beta - \alpha)},

    (``x_c' = x'`` for ``beta = inf``), whose minimum over a period is ``V - c``
    with ``c = critical_inertial_velocity(alpha, beta, a)``: the solution is a physical
    motion (no stick) exactly when ``vbar >= 1``, eqs. (11)-(12).

    Validity: ``alpha > 0``, ``alpha != 1`` (at resonance there is no periodic
    solution), ``0 <= a <= 1`` (no loss of contact). Arguments broadcast.
    """
    tau = checked("tau", tau)
    alpha = valid_array("alpha", alpha)
    if np.any(alpha == 1.0):
        raise ValueError(
            "alpha must differ from 1, got 1.0: at resonance (case IV) the sliding "
            "solution of eqs. (7)-(8) does not exist"
        )
    _, beta, a = validated({"alpha": alpha, "beta": beta, "amplitude": amplitude},
                           ranges={"amplitude": NO_JUMPING}).values()
    V = checked("V", V, minimum=0.0)
    body_amp = a / (1.0 - alpha)
    contact_gain = 1.0 + (alpha - 1.0) / (beta - alpha)  # (beta - 1)/(beta - alpha)
    y = -1.0 / alpha + body_amp * np.cos(tau)
    velocity = V - body_amp * np.sin(tau)
    contact_velocity = V - body_amp * contact_gain * np.sin(tau)
    y, velocity, contact_velocity = np.broadcast_arrays(y, velocity, contact_velocity)
    return SteadySliding(as_float_or_array(y), as_float_or_array(velocity),
                         as_float_or_array(contact_velocity))


# --------------------------------------------------------------------------- eqs. (26), (27)
def mu_ratio_stiff(vbar: ArrayLike, amplitude: ArrayLike) -> FloatOrArray:
    r"""Semi-empirical law of Part I for a stiff system (case II), eq. (26).

    .. math:: \frac{\mu}{\mu_0} = 1 - a\left[\tfrac34(\bar v - 1)^2
              + \tfrac14(\bar v - 1)^4\right], \quad \bar v < 1,

    and exactly ``1`` for ``vbar >= 1`` (the clamp is explicit: the polynomial
    itself turns down again above ``vbar = 1``). ``vbar`` uses ``v0*`` of
    eq. (14). Equals ``1 - a`` at ``vbar = 0`` (eq. 2), increases monotonically
    (derivative ``-a[3/2 (vbar-1) + (vbar-1)^3] >= 0``) and joins ``1`` with zero
    slope. Stated (Fig. 4) for ``0 <= a <= 1``; ``a > 1`` raises ValueError,
    since it would give ``1 - a < 0`` at ``vbar = 0``, contradicting eq. (2).
    """
    v = valid_array("vbar", vbar, ANY_VBAR)
    a = valid_array("amplitude", amplitude, NO_JUMPING)
    u = np.minimum(v, 1.0) - 1.0
    return as_float_or_array(np.where(v < 1.0, 1.0 - a * (0.75 * u**2 + 0.25 * u**4), 1.0))


def mu_ratio_soft(vbar: ArrayLike, amplitude: ArrayLike,
                  exponent: float = SOFT_EXPONENT) -> FloatOrArray:
    r"""Law of Teidelt et al. for a soft system on a stiff contact (case I), eq. (27).

    .. math:: \frac{\mu}{\mu_0} = (1 - a) + a\left[\sqrt{4\pi/9}\,\bar v
              + \left(1 - \sqrt{4\pi/9}\right)\bar v^{p}\right], \quad \bar v < 1,

    and exactly ``1`` for ``vbar >= 1``; ``vbar`` uses ``v0*`` of eq. (13) and
    ``a = dF_N / F_N0``. The transcription prints ``p`` as "1,2", read as 1.2
    (decimal comma); it is a parameter so that it can be checked against the
    numerics. Although ``1 - sqrt(4 pi/9) = -0.18 < 0``, the law is monotone on
    ``[0, 1]`` for any ``p < sqrt(4pi/9)/(sqrt(4pi/9) - 1) = 6.5`` (slope at
    ``vbar = 1`` is ``a[c + (1 - c) p] = 0.964 a`` for ``p = 1.2``: a kink, unlike
    eq. 26). Stated for ``0 <= a <= 1`` (Fig. 4); for ``a > 1`` the static part
    ``1 - a`` would be negative, contradicting eq. (2) (which gives 0), so
    ``a > 1`` raises ValueError.

    This is the formula *as transcribed*; it disagrees with the numerics by up to
    0.29 and with the small-velocity asymptotics.  See :func:`mu_ratio_soft_corrected`
    (``vbar`` under the square root), which agrees within 0.012 (docs/theory.md).
    """
    v = valid_array("vbar", vbar, ANY_VBAR)
    a = valid_array("amplitude", amplitude, NO_JUMPING)
    p = float(checked("exponent", exponent, minimum=0.0, strict=True))
    vc = np.minimum(v, 1.0)
    law = (1.0 - a) + a * (_SOFT_SLOPE * vc + (1.0 - _SOFT_SLOPE) * vc**p)
    return as_float_or_array(np.where(v < 1.0, law, 1.0))


def mu_ratio_soft_corrected(vbar: ArrayLike, amplitude: ArrayLike,
                            exponent: float = SOFT_EXPONENT) -> FloatOrArray:
    r"""Eq. (27) with ``vbar`` under the square root, as the small-velocity limit requires.

    .. math:: \frac{\mu}{\mu_0} = (1 - a) + a\left[\sqrt{\tfrac{4\pi}{9}\bar v}
              + \left(1 - \sqrt{4\pi/9}\right)\bar v^{p}\right], \quad \bar v < 1,

    and ``1`` for ``vbar >= 1``.  Derivation of the leading term (rigid body, soft
    system: constant pulling force ``f`` in units of ``mu0 F_N0``, ``a <= 1``): the
    body slips only while ``n = 1 + a cos tau < f``, near ``tau = pi``; with
    ``s = tau - pi``, ``n ~ 1 - a + a s^2/2``, slip starts at ``s = -sigma`` with
    ``a sigma^2/2 = f - (1 - a)`` and ``x'' = f - n = a(sigma^2 - s^2)/2``.  The
    velocity returns to zero at ``s = 2 sigma``, the distance slid per period is
    ``(9/8) a sigma^4``, so ``V = 9 a sigma^4/(16 pi)`` and, with ``vbar = V/a``
    (eq. 13), ``f - (1 - a) = a sqrt(4 pi vbar/9)``.  As ``<n> = 1``,
    ``mu/mu0 = f``.  The transcription's ``sqrt(4 pi/9) vbar`` has lost ``vbar``
    from under the root; the second term (exponent ``p``, printed "1,2") only
    makes the law reach 1 at ``vbar = 1``.  Stated for ``0 <= a <= 1``.
    """
    v = valid_array("vbar", vbar, ANY_VBAR)
    a = valid_array("amplitude", amplitude, NO_JUMPING)
    p = float(checked("exponent", exponent, minimum=0.0, strict=True))
    vc = np.minimum(v, 1.0)
    law = (1.0 - a) + a * (_SOFT_SLOPE * np.sqrt(vc) + (1.0 - _SOFT_SLOPE) * vc**p)
    return as_float_or_array(np.where(v < 1.0, law, 1.0))
