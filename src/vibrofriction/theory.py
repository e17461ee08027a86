r"""Closed-form results of Mao, Popov, Starcevic & Popov, *Friction* (2017), Part II.

Every analytic formula of the paper lives here, once, vectorised over numpy
arrays (scalars in give floats out). Equation numbers refer to the paper; the
transcription numbers all equations of the resonant case IV "(32)", and they
are told apart below by what they compute.

Scaled variables (see ``docs/model.md``): time ``tau = omega t``; force unit
``mu0 F_N0``; length unit ``mu0 F_N0 / (m omega^2)``; velocity unit
``mu0 F_N0 / (m omega)``, in which the pulling velocity is the *inertial
velocity* ``V = v0 m omega / (mu0 F_N0)`` (the axis of Fig. 6). The paper's
groups are ``alpha = k_x/(m omega^2)``, ``beta = (k_x + k_xc)/(m omega^2)``
(eq. 20), ``a = du_z/u_z0`` and ``vbar = v0/v0*`` (eq. 16).

Defects of the paper corrected or made explicit here:

* eq. (27): the exponent printed ``1,2`` is read as 1.2 (decimal comma);
* eqs. (26), (27) are stated for ``a <= 1`` only (Fig. 4); for ``a > 1`` they
  would give a negative static friction, contradicting eq. (2), so they refuse;
* eqs. (21), (23) print the scaled contact force as
  ``(u_z0/du_z + cos tau)(alpha - 1)/(beta - 1)``; with ``xi = u_x omega/v0*``
  and ``v0*`` of eq. (12) (which has absolute values) the factor is
  ``|alpha - 1|/|beta - 1|``. As printed it is negative for ``alpha < 1 < beta``
  (e.g. the soft case I), i.e. friction would push the slider forward;
* case IV with jumping (``a > 1``): the paper's ``1 - a/2`` neglects loss of
  contact (and is negative for ``a > 2``); ``resonant_plateau`` and
  ``resonant_plateau_exact`` use ``n = max(0, 1 + a cos tau)`` and the mean
  normal force ``<n>`` instead.
"""

from __future__ import annotations

import math
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ._kernels.integrate import liftoff_phases as _kernel_liftoff_phases
from .schema import CHOICES, POSITIVE, Range
from .validation import as_float_or_array, checked, checked_choice, validated

__all__ = [
    "INPLANE_ON",
    "SOFT_EXPONENT",
    "Cancellation",
    "InplaneStatic",
    "Liftoff",
    "SteadySliding",
    "critical_inertial_velocity",
    "critical_velocity",
    "critical_velocity_soft",
    "critical_velocity_stiff",
    "inplane_cancellation",
    "inplane_critical_velocity",
    "inplane_regime",
    "inplane_static_mu_ratio",
    "PlaneStatic",
    "plane_static_region",
    "kinematic_mu_longitudinal",
    "kinematic_mu_transverse",
    "liftoff_phases",
    "dead_weight_indentation",
    "mean_normal_force",
    "profile_critical_velocity",
    "profile_mean_normal_force",
    "profile_static_mu_ratio",
    "mu_ratio_soft",
    "mu_ratio_soft_corrected",
    "mu_ratio_stiff",
    "mu_ratio_stiff_exact",
    "mu_ratio_stiff_flat",
    "mu_ratio_stiff_profile",
    "resonant_damped_mu_ratio",
    "resonant_plateau",
    "resonant_plateau_exact",
    "resonant_tau_star",
    "resonant_velocity_ratio",
    "resonant_velocity_ratio_exact",
    "static_mu_ratio",
    "steady_sliding",
]

#: Domains of closed forms wider or narrower than the model's (the schema's ranges):
#: the soft limit ``k_x = 0`` (``alpha = 0``) is a point of the formulas, the laws of
#: eqs. (26), (27) hold without jumping (``a <= 1``) and at every ``vbar`` up to ``inf``.
_SOFT_LIMIT = Range(0.0)
_NO_JUMPING = Range(0.0, maximum=1.0)
_ANY_VBAR = Range(0.0, allow_inf=True)


def _valid(name: str, value: ArrayLike, domain: Range | None = None) -> NDArray[np.float64]:
    """One model parameter checked by the one validator (in ``domain`` if given)."""
    return validated({name: value}, ranges=None if domain is None else {name: domain})[name]


FloatOrArray = float | NDArray[np.float64]

#: Exponent of the soft-system law, eq. (27); printed "1,2" (decimal comma).
SOFT_EXPONENT: float = 1.2

#: ``sqrt(4 pi / 9)``, the linear coefficient of eq. (27).
_SOFT_SLOPE: float = math.sqrt(4.0 * math.pi / 9.0)


# --------------------------------------------------------------------------- helpers
def _ratio_or_inf(num: NDArray[np.float64], den: NDArray[np.float64]) -> NDArray[np.float64]:
    """``num / den`` with ``0`` where ``num == 0`` and ``inf`` where only ``den == 0``."""
    num, den = np.broadcast_arrays(num, den)
    out = np.full(num.shape, np.inf)
    np.divide(num, den, out=out, where=den != 0)
    out[num == 0] = 0.0
    return out


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
    a = _valid("amplitude", amplitude)
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
         "mass": mass, "c_x": c_x, "c_xc": c_xc}, ranges={"k_x": _SOFT_LIMIT}).values()
    detuning = (k_x - mass * omega**2) + 1j * omega * c_x
    eta = np.where(np.isinf(k_xc), 0.0, omega * c_xc / k_xc)
    num = mu0 * omega * du_z * k_zc * np.abs(1.0 + detuning / k_xc + 1j * eta)
    return as_float_or_array(_ratio_or_inf(num, np.abs(detuning) * np.sqrt(1.0 + eta**2)))


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
    _inplane_on(inplane_on)
    alpha, beta, a, zeta, eta = validated(
        {"alpha": alpha, "beta": beta, "amplitude": amplitude, "zeta": zeta, "eta_c": eta_c},
        ranges={"alpha": _SOFT_LIMIT}).values()
    detuning = (alpha - 1.0) + 2j * zeta * np.sqrt(alpha)
    eta = np.where(np.isinf(beta), 0.0, eta)
    num = a * np.abs(1.0 + detuning / (beta - alpha) + 1j * eta)
    return as_float_or_array(_ratio_or_inf(num, np.abs(detuning) * np.sqrt(1.0 + eta**2)))


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
    alpha = _valid("alpha", alpha)
    if np.any(alpha == 1.0):
        raise ValueError(
            "alpha must differ from 1, got 1.0: at resonance (case IV) the sliding "
            "solution of eqs. (7)-(8) does not exist"
        )
    _, beta, a = validated({"alpha": alpha, "beta": beta, "amplitude": amplitude},
                           ranges={"amplitude": _NO_JUMPING}).values()
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
    v = _valid("vbar", vbar, _ANY_VBAR)
    a = _valid("amplitude", amplitude, _NO_JUMPING)
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
    v = _valid("vbar", vbar, _ANY_VBAR)
    a = _valid("amplitude", amplitude, _NO_JUMPING)
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
    v = _valid("vbar", vbar, _ANY_VBAR)
    a = _valid("amplitude", amplitude, _NO_JUMPING)
    p = float(checked("exponent", exponent, minimum=0.0, strict=True))
    vc = np.minimum(v, 1.0)
    law = (1.0 - a) + a * (_SOFT_SLOPE * np.sqrt(vc) + (1.0 - _SOFT_SLOPE) * vc**p)
    return as_float_or_array(np.where(v < 1.0, law, 1.0))


# --------------------------------------------------------------------------- jumping
class Liftoff(NamedTuple):
    """Phases ``tau`` in ``[0, 2 pi)`` where contact is lost and regained."""

    tau_off: FloatOrArray
    tau_on: FloatOrArray


#: The kernels' lift-off angle (the one place it is computed), over arrays.
_liftoff_angles = np.vectorize(_kernel_liftoff_phases, otypes=[float, float])


def _contact_half_angle(a: NDArray[np.float64]) -> NDArray[np.float64]:
    """``theta = arccos(-1/a)`` for ``a > 1``, ``pi`` otherwise: contact while ``|tau| < theta``."""
    return np.where(a > 1.0, _liftoff_angles(a)[0], np.pi)


def mean_normal_force(amplitude: ArrayLike) -> FloatOrArray:
    r"""Mean scaled normal force ``<n> = <max(0, 1 + a cos tau)> = <F_N>/F_N0``.

    For ``a <= 1`` the contact never opens and ``<n> = 1``. For ``a > 1`` it is
    closed for ``|tau| < theta = arccos(-1/a)``, so

    .. math:: \langle n\rangle = \frac{1}{2\pi}\int_{-\theta}^{\theta}(1 + a\cos\tau)\,d\tau
              = \frac{\theta + a\sin\theta}{\pi}, \quad \sin\theta = \sqrt{1 - a^{-2}},

    which is the denominator of eq. (25) for a jumping body.
    """
    a = _valid("amplitude", amplitude)
    theta = _contact_half_angle(a)
    return as_float_or_array(np.where(a > 1.0, (theta + a * np.sin(theta)) / np.pi, 1.0))


def mean_normal_force_of(a: float) -> float:
    """:func:`mean_normal_force` of one valid amplitude, in plain floats (the one-point
    fast path of the solver, where numpy's overhead would be most of the call)."""
    if a <= 1.0:
        return 1.0
    theta = math.acos(-1.0 / a)
    return (theta + a * math.sin(theta)) / math.pi


def liftoff_phases(amplitude: ArrayLike) -> Liftoff:
    r"""Phases of loss of contact and touchdown, where ``1 + a cos tau = 0``.

    ``tau_off = arccos(-1/a)`` (in ``(pi/2, pi]``) and ``tau_on = 2 pi - tau_off``
    for ``a >= 1``; ``a = 1`` gives the grazing point ``(pi, pi)``; ``nan`` for
    ``a < 1`` (no loss of contact).
    """
    a = _valid("amplitude", amplitude)
    off = np.where(a >= 1.0, _liftoff_angles(a)[0], np.nan)
    return Liftoff(as_float_or_array(off), as_float_or_array(2.0 * np.pi - off))


# ------------------------------------------------------------------ case IV, eqs. (27)-(32)
def _drive_work(a: NDArray[np.float64]) -> NDArray[np.float64]:
    r"""``E(a) = 2 pi <n cos tau>``: ``pi a`` for ``a <= 1``, ``a theta + sin theta`` above."""
    theta = _contact_half_angle(a)
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
    a = _valid("amplitude", amplitude)
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
    return np.vectorize(_resonant_tau_star_exact, otypes=[float])(a)


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
    a = _valid("amplitude", amplitude)
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
    a = _valid("amplitude", amplitude)
    theta = _contact_half_angle(a)
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
    a = _valid("amplitude", amplitude)
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
    V = _valid("v_inertial", v_inertial)
    a = _valid("amplitude", amplitude)
    zeta = _valid("zeta", zeta)
    V, a, zeta = np.broadcast_arrays(V, a, zeta)
    x = np.pi * 2.0 * zeta * V
    tau = np.vectorize(_damped_tau_star, otypes=[float])(x, a)
    n_mean = np.asarray(mean_normal_force(a))
    return as_float_or_array(1.0 - (2.0 / np.pi) * (tau + a * np.sin(tau)) / n_mean)


# --------------------------------------------------------------------------- stiff limit
def _stiff_tau2(vbar: float) -> tuple[float, float]:
    """``(tau1, tau2)``: stick starts where ``n' = k V`` on the rising branch and ends
    where the stick line ``n(tau1) + a vbar (tau - tau1)`` meets ``n`` again."""
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
    v = _valid("vbar", vbar, _ANY_VBAR)
    a = _valid("amplitude", amplitude, _NO_JUMPING)
    return as_float_or_array(np.vectorize(_stiff_exact, otypes=[float])(v, a))


# --------------------------------------------------------------------------- in-plane
#: Where the in-plane oscillation is imposed (docs/inplane.md).
INPLANE_ON = CHOICES["inplane_on"].values


def _inplane_on(inplane_on: str) -> str:
    return checked_choice("inplane_on", inplane_on)


def kinematic_mu_longitudinal(v: ArrayLike, a_x: ArrayLike) -> FloatOrArray:
    r"""Kinematic law of a rigid body, oscillation along the sliding direction (docs/inplane.md).

    The body moves at the constant velocity ``v`` against a substrate whose velocity
    is ``-a_x sin(theta)``; friction ``-sign(v + a_x sin theta)`` averages to

    .. math:: \frac{\mu}{\mu_0} = \frac{2}{\pi}\arcsin\frac{v}{a_x}, \quad |v| < a_x,

    and ``sign(v)`` for ``|v| >= a_x``.  Any unit, as long as ``v`` and ``a_x`` (the
    vibration-velocity amplitude ``omega du_x``) share it; ``v`` is signed.
    """
    v = checked("v", v)
    a_x = checked("a_x", a_x, minimum=0.0)
    v, a_x = np.broadcast_arrays(v, a_x)
    r = np.array(np.sign(v), dtype=float)
    np.divide(v, a_x, out=r, where=np.abs(v) < a_x)
    return as_float_or_array(2.0 / np.pi * np.arcsin(np.clip(r, -1.0, 1.0)))


def kinematic_mu_transverse(v: ArrayLike, a_y: ArrayLike) -> FloatOrArray:
    r"""Kinematic law of a rigid body, oscillation across the sliding direction.

    The slip velocity is ``(v, a_y sin theta)``; isotropic friction opposes it, so its
    component along the sliding is ``v/sqrt(v^2 + a_y^2 sin^2 theta)``, whose mean is

    .. math:: \frac{\mu}{\mu_0} = \frac{2}{\pi}\frac{K(m)}{\sqrt{1 + \epsilon^2}}, \quad
              \epsilon = \frac{a_y}{v}, \quad m = \frac{\epsilon^2}{1 + \epsilon^2},

    ``K(m) = int_0^{pi/2} (1 - m sin^2)^{-1/2}`` with the parameter ``m``
    (``scipy.special.ellipk``).  No critical velocity: ``mu < mu0`` at every ``v``;
    ``-> 1 - eps^2/4`` for large ``v``, ``(2/pi)(|v|/a_y) ln(4 a_y/|v|)`` for small.
    """
    from scipy.special import ellipk

    v = checked("v", v)
    a_y = checked("a_y", a_y, minimum=0.0)
    v, a_y = np.broadcast_arrays(v, a_y)
    av = np.abs(v)
    # m = a_y^2/(v^2 + a_y^2), 1/sqrt(1 + eps^2) = |v|/sqrt(v^2 + a_y^2), with 0/0 -> 0
    norm = np.hypot(av, a_y)
    m = np.zeros(v.shape)
    np.divide(a_y**2, norm**2, out=m, where=norm > 0)
    scale = np.zeros(v.shape)
    np.divide(av, norm, out=scale, where=norm > 0)
    with np.errstate(invalid="ignore"):
        law = 2.0 / np.pi * ellipk(np.minimum(m, 1.0)) * scale
    law = np.where(av == 0.0, 0.0, law)  # K(1) = inf times 0
    return as_float_or_array(np.sign(v) * law)


def _inplane_factors(alpha: NDArray[np.float64], beta: NDArray[np.float64],
                     zeta: NDArray[np.float64], eta: NDArray[np.float64], on: str):
    """``P``, the contact's slip compliance ``1/(k(1 + i eta_c))``, the contact
    impedance ``k + i c`` (0 for rigid: then unused) and the in-plane forcing ``G``
    times ``P`` (substrate: ``-P``; holder: ``alpha + i gamma``)."""
    gamma = 2.0 * zeta * np.sqrt(alpha)
    p = (alpha - 1.0) + 1j * gamma
    rigid = np.isinf(beta)
    k = np.where(rigid, 1.0, beta - alpha)
    eta = np.where(rigid, 0.0, eta)
    slip_compliance = np.where(rigid, 0.0, 1.0 / (k * (1.0 + 1j * eta)))
    impedance = k * (1.0 + 1j * eta)
    gp = -p if on == "substrate" else alpha + 1j * gamma
    return p, slip_compliance, impedance, gp, rigid


def _inplane_inputs(alpha, beta, amplitude, a_x, phase_x, zeta, eta_c, inplane_on
                    ) -> tuple[Any, ...]:
    """The validated inputs of the in-plane closed forms (the schema's ranges; ``alpha``
    as in the soft limit): ``(on_substrate, alpha, beta, a, zeta, eta_c, a_x, phase_x)``."""
    on = _inplane_on(inplane_on)
    values = validated({"alpha": alpha, "beta": beta, "amplitude": amplitude, "zeta": zeta,
                        "eta_c": eta_c, "a_x": a_x, "phase_x": phase_x},
                       ranges={"alpha": _SOFT_LIMIT})
    return (on, *values.values())


def inplane_critical_velocity(alpha: ArrayLike, beta: ArrayLike, amplitude: ArrayLike,
                              a_x: ArrayLike, phase_x: ArrayLike, zeta: ArrayLike = 0.0,
                              eta_c: ArrayLike = 0.0,
                              inplane_on: str = "substrate") -> FloatOrArray:
    r"""Critical inertial velocity of continuous sliding, normal + longitudinal oscillation.

    In permanent forward slip (``f = n = 1 + a cos tau``, ``a <= 1``) the contact
    point's slip velocity relative to the substrate is ``V`` plus a harmonic
    (docs/inplane.md),

    .. math:: w = V - \mathrm{Re}\big(i e^{i\tau}\,[a B - a_x G e^{i\phi_x}]\big),\quad
              B = \frac1P + \frac{1}{k(1 + i\eta_c)},\quad P = \alpha - 1 + i\gamma,

    ``G = -1`` (substrate) or ``(alpha + i gamma)/P`` (holder), ``gamma = 2 zeta
    sqrt(alpha)``, ``k = beta - alpha``.  It never reaches 0 iff ``V >= V_c`` with

    .. math:: V_c = |a B - a_x G e^{i\phi_x}|.

    ``a_x = 0`` gives :func:`critical_inertial_velocity`.  For ``V < 0`` (backward
    sliding) the condition is ``|V| >= V_c(phase_x + pi)``.  ``inf`` at an undamped
    resonance ``alpha = 1`` unless the holder's forcing cancels the normal one there.
    """
    on, alpha, beta, a, zeta, eta, a_x, phase = _inplane_inputs(
        alpha, beta, amplitude, a_x, phase_x, zeta, eta_c, inplane_on)
    # the names keep their ArrayLike annotations; _inplane_inputs made them float arrays
    p, slip_compliance, _, gp, _ = _inplane_factors(alpha, beta, zeta, eta, on)  # type: ignore[arg-type]
    # a B - a_x G e^{i phi} = N / P + a / (k (1 + i eta_c)), N = a - a_x (G P) e^{i phi}
    num = a - a_x * gp * np.exp(1j * phase)
    num, p, rest = np.broadcast_arrays(num, p, a * slip_compliance)
    resonant = np.zeros(num.shape, dtype=complex)
    np.divide(num, p, out=resonant, where=p != 0)
    total = np.abs(resonant + rest)
    total = np.where((p == 0) & (num != 0), np.inf, total)
    return as_float_or_array(total)


class Cancellation(NamedTuple):
    """Where the normal and longitudinal oscillations cancel in the sliding velocity."""

    #: ``phase_x`` in ``[0, 2 pi)`` at which ``V_c`` is smallest, ``| a|B| - a_x|G| |``;
    #: they add (``V_c = a|B| + a_x|G|``) at ``phase_x + pi``.
    phase_x: FloatOrArray
    #: The ``a_x = a|B|/|G|`` at which ``V_c = 0`` there (``mu = mu0`` at every ``V > 0``).
    a_x: FloatOrArray


def inplane_cancellation(alpha: ArrayLike, beta: ArrayLike, amplitude: ArrayLike,
                         zeta: ArrayLike = 0.0, eta_c: ArrayLike = 0.0,
                         inplane_on: str = "substrate") -> Cancellation:
    r"""Phase and amplitude at which the longitudinal oscillation cancels the normal one.

    ``V_c^2 = a^2|B|^2 + a_x^2|G|^2 - 2 a a_x |B||G| cos(phase_x - arg B + arg G)``
    (:func:`inplane_critical_velocity`), so the phase of cancellation is
    ``arg B - arg G`` (mod ``2 pi``) and ``V_c`` vanishes there for ``a_x = a|B|/|G|``.
    Undamped, ``B`` and ``G`` are real: the phase is 0 or ``pi``.  At an undamped
    resonance (``P = 0``) ``B`` and ``G`` are both infinite and their ratio ``1/(alpha +
    i gamma)`` (holder) sets the phase; the substrate cannot cancel it (``a_x = inf``).
    """
    on = _inplane_on(inplane_on)
    alpha, beta, a, zeta, eta = validated(
        {"alpha": alpha, "beta": beta, "amplitude": amplitude, "zeta": zeta, "eta_c": eta_c},
        ranges={"alpha": _SOFT_LIMIT}).values()
    # the names keep their ArrayLike annotations; _inplane_inputs made them float arrays
    p, slip_compliance, _, gp, _ = _inplane_factors(alpha, beta, zeta, eta, on)  # type: ignore[arg-type]
    # B/G = (1 + P/(k(1 + i eta_c))) / (G P): finite also at P = 0
    bp = 1.0 + p * slip_compliance
    ratio = np.full(np.broadcast(bp, gp).shape, np.inf, dtype=complex)
    np.divide(bp, gp, out=ratio, where=gp != 0)
    phase = np.mod(np.angle(ratio), 2.0 * np.pi)
    amp = a * np.abs(ratio)
    amp = np.where(np.isinf(np.abs(ratio)) & (a == 0), 0.0, amp)
    return Cancellation(as_float_or_array(phase), as_float_or_array(amp))


class InplaneStatic(NamedTuple):
    """Range of mean forces a stuck contact can hold (``mu/mu0``, ``V -> 0+`` and ``0-``)."""

    #: ``mu(V -> 0+)/mu0 = 1 - |a + Q|``: the largest mean force of a permanent stick.
    upper: FloatOrArray
    #: ``mu(V -> 0-)/mu0 = -(1 - |a - Q|)``: the most negative one.
    lower: FloatOrArray


def inplane_static_mu_ratio(alpha: ArrayLike, beta: ArrayLike, amplitude: ArrayLike,
                            a_x: ArrayLike, phase_x: ArrayLike, zeta: ArrayLike = 0.0,
                            eta_c: ArrayLike = 0.0,
                            inplane_on: str = "substrate") -> InplaneStatic:
    r"""Static friction under normal + longitudinal oscillation, compliant contact.

    With the contact stuck through the whole cycle the system is linear: the contact
    force is ``F + Re(F^ e^{i tau})``, ``F`` the mean (the measured friction force),
    ``F^ = -Q``, ``Q = a_x T e^{i phase_x}`` with (docs/inplane.md)

    .. math:: T = \frac{(k + i c)\,P}{P + k + i c}\ \text{(substrate)},\qquad
              T = -\frac{(k + i c)(\alpha + i\gamma)}{P + k + i c}\ \text{(holder)},

    ``c = eta_c k``, ``P = alpha - 1 + i gamma``; rigid contact: ``T = P`` or
    ``-(alpha + i gamma)``.  ``|f| <= n`` through the cycle iff
    ``-1 + |a - Q| <= F <= 1 - |a + Q|``; the body creeping at ``V -> 0+`` raises ``F``
    to the upper bound, so ``mu(0+)/mu0 = 1 - |a + Q|`` and ``mu(0-)/mu0 =
    -(1 - |a - Q|)``.  Quasi-statically (``alpha, beta -> 0``: a heavy body) ``T = k``
    and a pure in-plane oscillation gives ``1 - k a_x`` (the intrinsic length
    ``1/k``, i.e. ``mu0 F_N0/k_xc``).  ``nan`` where no permanent stick exists
    (``|a + Q| + |a - Q| > 2``, or ``a > 1``): the contact slips in every cycle.
    Valid where the stuck orbit is the attractor (damping; the solver is the judge).
    """
    on, alpha, beta, a, zeta, eta, a_x, phase = _inplane_inputs(
        alpha, beta, amplitude, a_x, phase_x, zeta, eta_c, inplane_on)
    # the names keep their ArrayLike annotations; _inplane_inputs made them float arrays
    p, _, impedance, gp, rigid = _inplane_factors(alpha, beta, zeta, eta, on)  # type: ignore[arg-type]
    # T = -(k + i c) G P / (P + k + i c); rigid: -G P
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.where(rigid, -gp, -impedance * gp / (p + impedance))
    with np.errstate(invalid="ignore"):  # T = inf at an undamped beta = 1
        q = np.where(a_x == 0.0, 0.0, a_x * t * np.exp(1j * phase))
        plus, minus = np.abs(a + q), np.abs(a - q)
    ok = (plus + minus <= 2.0) & (a <= 1.0)
    upper = np.where(ok, 1.0 - plus, np.nan)
    lower = np.where(ok, minus - 1.0, np.nan)
    return InplaneStatic(as_float_or_array(upper), as_float_or_array(lower))


class PlaneStatic(NamedTuple):
    """The region of mean forces ``(F_x, F_y)/(mu0 F_N0)`` a contact stuck through whole
    cycles can hold under normal + in-plane oscillation in both directions
    (:func:`plane_static_region`), given by its extent; ``nan`` where it is empty."""

    #: The largest and the smallest ``F_x`` of the region (held ``mu_ratio`` values).
    x_upper: FloatOrArray
    x_lower: FloatOrArray
    #: The largest and the smallest ``F_y`` (held ``lateral_ratio`` values).
    y_upper: FloatOrArray
    y_lower: FloatOrArray


#: Samples of the drive period on which :func:`plane_static_region` imposes the cone.
PLANE_STATIC_SAMPLES = 4096


def _axis_range(qa: NDArray[np.float64], qb: NDArray[np.float64],
                n: NDArray[np.float64]) -> tuple[float, float]:
    """The extent along ``a`` of ``{F: |F - (qa_j, qb_j)| <= n_j for all j}`` (a convex
    set): at fixed ``F_a`` the feasible ``F_b`` is an intersection of intervals, of
    concave width ``h(F_a) = min hi_j - max lo_j``; its maximum by golden section, the
    ends where ``h = 0`` by bisection.  ``(nan, nan)`` where the set is empty."""
    lo_dom, hi_dom = float(np.max(qa - n)), float(np.min(qa + n))
    if lo_dom > hi_dom:
        return math.nan, math.nan

    def width(x: float) -> float:
        r = np.sqrt(np.maximum(n * n - (x - qa) ** 2, 0.0))
        return float(np.min(qb + r) - np.max(qb - r))

    g = (math.sqrt(5.0) - 1.0) / 2.0
    a, b = lo_dom, hi_dom
    c, d = b - g * (b - a), a + g * (b - a)
    wc, wd = width(c), width(d)
    for _ in range(100):
        if b - a <= 1e-15 * (1.0 + abs(a) + abs(b)):
            break
        if wc >= wd:
            b, d, wd = d, c, wc
            c = b - g * (b - a)
            wc = width(c)
        else:
            a, c, wc = c, d, wd
            d = a + g * (b - a)
            wd = width(d)
    top = 0.5 * (a + b)
    if width(top) < 0.0:
        return math.nan, math.nan

    def edge(inside: float, outside: float) -> float:
        for _ in range(100):
            mid = 0.5 * (inside + outside)
            if mid in (inside, outside):
                break
            if width(mid) >= 0.0:
                inside = mid
            else:
                outside = mid
        return inside

    return edge(top, lo_dom) if width(lo_dom) < 0.0 else lo_dom, \
        edge(top, hi_dom) if width(hi_dom) < 0.0 else hi_dom


def plane_static_region(alpha: ArrayLike, beta: ArrayLike, amplitude: ArrayLike,
                        a_x: ArrayLike, phase_x: ArrayLike, a_y: ArrayLike,
                        phase_y: ArrayLike, zeta: ArrayLike = 0.0, eta_c: ArrayLike = 0.0,
                        inplane_on: str = "substrate", alpha_y: ArrayLike | None = None,
                        zeta_y: ArrayLike | None = None) -> PlaneStatic:
    r"""Static friction under normal + in-plane oscillation in both directions: the
    region of mean forces a contact stuck through the whole cycle can hold.

    In stick the contact point moves with the substrate and the two directions decouple
    (the pin's springs act along their axes, the contact spring is isotropic): each
    component of the contact force is that of :func:`inplane_static_mu_ratio`, ``F_x -
    Re(Q_x e^{i tau})`` and ``F_y - Re(Q_y e^{i tau})`` with ``Q_x = a_x T e^{i
    phase_x}`` and ``Q_y = a_y T_y e^{i phase_y}`` (``T_y`` of the pin across,
    ``alpha_y``, ``zeta_y``; None: ``alpha``, ``zeta``).  The stick holds through the
    cycle iff ``|F - q(tau)| <= n(tau) = 1 + a cos tau`` for every ``tau``: ``F`` in the
    intersection of the disks of radius ``n`` about the ellipse ``q``, a convex set.  Its
    extent is computed on :data:`PLANE_STATIC_SAMPLES` equally spaced phases (an outer
    approximation, to about ``1e-6``).  With ``a_y = 0`` the ``x`` extent is the band of
    :func:`inplane_static_mu_ratio`.  ``nan`` where the region is empty (or ``a > 1``):
    the contact slips in every cycle.
    """
    on, al, be, am, ze, et, ax, px = _inplane_inputs(alpha, beta, amplitude, a_x, phase_x,
                                                     zeta, eta_c, inplane_on)
    aly = al if alpha_y is None else np.asarray(alpha_y, dtype=float)
    zey = ze if zeta_y is None else np.asarray(zeta_y, dtype=float)
    al, be, am, ze, et, ax, px, ay, py, aly, zey = np.broadcast_arrays(
        al, be, am, ze, et, ax, px, np.asarray(a_y, dtype=float),
        np.asarray(phase_y, dtype=float), aly, zey)
    tau = np.linspace(0.0, 2.0 * np.pi, PLANE_STATIC_SAMPLES, endpoint=False)
    e = np.exp(1j * tau)
    out = np.full((4,) + al.shape, np.nan)
    for i in np.ndindex(al.shape):
        if am[i] > 1.0:
            continue
        q = []
        # the contact (k = beta - alpha, c = eta_c k) is shared: across, beta_y = k + alpha_y
        for amp, ph, a_, b_, z_ in ((ax[i], px[i], al[i], be[i], ze[i]),
                                    (ay[i], py[i], aly[i], be[i] - al[i] + aly[i], zey[i])):
            p, _, impedance, gp, rigid = _inplane_factors(
                np.asarray(a_), np.asarray(b_), np.asarray(z_), np.asarray(et[i]), on)
            with np.errstate(divide="ignore", invalid="ignore"):
                t = complex(-gp if rigid else -impedance * gp / (p + impedance))
            q.append(np.zeros_like(tau) if amp == 0.0 else np.real(amp * t * np.exp(1j * ph) * e))
        n = 1.0 + am[i] * np.cos(tau)
        out[(1, *i)], out[(0, *i)] = _axis_range(q[0], q[1], n)
        out[(3, *i)], out[(2, *i)] = _axis_range(q[1], q[0], n)
    return PlaneStatic(*(as_float_or_array(x) for x in out))


#: The regimes of :func:`inplane_regime`, in the order of their codes 0, 1, 2 (-1: the
#: contact slips in every cycle, no closed form).
INPLANE_REGIMES = ("reduction", "ratchet", "actuator")


def inplane_regime(alpha: ArrayLike, beta: ArrayLike, amplitude: ArrayLike,
                   a_x: ArrayLike, phase_x: ArrayLike, zeta: ArrayLike = 0.0,
                   eta_c: ArrayLike = 0.0, inplane_on: str = "substrate",
                   rtol: float = 1e-9) -> NDArray[np.int8]:
    r"""The regime of the combined drive near ``V = 0``, from the static band of
    :func:`inplane_static_mu_ratio` (``upper = mu(0+)/mu0``, ``lower = mu(0-)/mu0``):

    * ``0`` **friction reduction**: ``lower < 0 < upper`` and ``upper = -lower`` (within
      ``rtol``): the oscillation lowers static friction equally both ways;
    * ``1`` **ratchet**: ``lower < 0 < upper``, ``upper != -lower``: a preferred
      direction, but a held body needs no force (0 is in the band);
    * ``2`` **actuator**: the band excludes 0 (``upper < 0`` or ``lower > 0``): the
      oscillation pushes; a held body carries a force, and the free body moves (at its
      idle velocity, where ``mu(V) = 0``);
    * ``-1``: no permanent stick (the contact slips in every cycle); the solver's
      ``mu(V -> 0+-)`` decide (docs/inplane.md, section 3).
    """
    upper, lower = (np.asarray(x, dtype=float) for x in inplane_static_mu_ratio(
        alpha, beta, amplitude, a_x, phase_x, zeta, eta_c, inplane_on))
    out = np.full(upper.shape, -1, dtype=np.int8)
    held = np.isfinite(upper)
    out[held & ((upper < 0.0) | (lower > 0.0))] = 2
    inside = held & (upper >= 0.0) & (lower <= 0.0)
    symmetric = np.abs(upper + lower) <= rtol * np.maximum(np.abs(upper), np.abs(lower))
    out[inside & symmetric] = 0
    out[inside & ~symmetric] = 1
    return out


# --------------------------------------------------------------- real contact geometry (MDR)
#: ``n = profile_exponent`` of ``z = c r^n``: ``0 < n <= inf`` (``inf``: the flat punch).
def _exponent(profile_exponent: ArrayLike) -> NDArray[np.float64]:
    return checked("profile_exponent", profile_exponent, minimum=0.0, strict=True,
                   allow_inf=True)


def _profile_mean_force(a: float, n: float) -> float:
    """``<max(0, 1 + a cos tau)^p>``, ``p = 1 + 1/n``."""
    if math.isinf(n) or a == 0.0:
        return 1.0 if a <= 1.0 else (math.acos(-1.0 / a) + math.sqrt(a * a - 1.0)) / math.pi
    p = 1.0 + 1.0 / n
    if a <= 1.0:
        from scipy.special import hyp2f1

        return float(hyp2f1(-0.5 * p, 0.5 * (1.0 - p), 1.0, a * a))
    from scipy.integrate import quad

    theta = math.acos(-1.0 / a)
    return quad(lambda t: (1.0 + a * math.cos(t)) ** p, 0.0, theta, epsabs=0.0,
                epsrel=1e-13, limit=200)[0] / math.pi


def profile_mean_normal_force(amplitude: ArrayLike, profile_exponent: ArrayLike) -> FloatOrArray:
    r"""``<F_N>/F_N0`` for the indentation ``d = d0 (1 + a cos tau)`` imposed on ``z = c r^n``.

    The MDR force is ``F(d) = F_N0 (d/d0)^p``, ``p = 1 + 1/n`` (0 for ``d <= 0``), so

    .. math:: \frac{\langle F_N\rangle}{F_{N0}} = \langle \max(0, 1 + a\cos\tau)^p\rangle
              = {}_2F_1\!\left(-\tfrac p2, \tfrac{1 - p}{2}; 1; a^2\right) \quad (a \le 1),

    (the binomial series averaged term by term, ``<cos^{2k}> = (2k)!/(4^k k!^2)``) and
    ``(1/pi) int_0^theta (1 + a cos tau)^p dtau``, ``cos theta = -1/a``, for a jumping
    indenter (``a > 1``). A sphere (``p = 3/2``) gains ``3 a^2/16`` to leading order; the
    flat punch (``n = inf``, ``p = 1``) is :func:`mean_normal_force`.
    """
    a = _valid("amplitude", amplitude)
    n = _exponent(profile_exponent)
    return as_float_or_array(np.vectorize(_profile_mean_force, otypes=[float])(a, n))


def profile_static_mu_ratio(amplitude: ArrayLike, profile_exponent: ArrayLike) -> FloatOrArray:
    r"""Static limit ``mu(v0 -> 0+)/mu0`` for the profile ``z = c r^n``: eq. (2)'s analogue.

    The pulling force creeps up until the whole contact slides at the smallest normal
    force of the cycle, ``F(d0 (1 - a)) = F_N0 (1 - a)^p`` (``p = 1 + 1/n``), and stays
    there, so ``mu/mu0 = (1 - a)^p / <(1 + a cos tau)^p>``
    (:func:`profile_mean_normal_force`) for ``a < 1`` and 0 for a jumping indenter
    (``a >= 1``). ``n = inf`` gives :func:`static_mu_ratio`, ``1 - a``.
    """
    a = _valid("amplitude", amplitude)
    n = _exponent(profile_exponent)
    a, n = np.broadcast_arrays(a, n)
    p = 1.0 + 1.0 / n
    low = np.where(a < 1.0, np.maximum(1.0 - a, 0.0) ** p, 0.0)
    return as_float_or_array(low / np.asarray(profile_mean_normal_force(a, n)))


def _stiff_element(c: float, vbar: float) -> tuple[float, float]:
    """Stiff limit of one flat element with ``n = max(0, c + cos tau)``, pulled at the
    rate ``f' = vbar`` while it sticks: ``(deficit, <n>)``, ``<f> = <n> - deficit/(2 pi)``.

    Stick starts where ``n' = -sin tau`` rises through ``vbar`` (``tau1 = pi + asin vbar``)
    or, if the element is out of contact then, at touch-down ``2 pi - theta``
    (``cos theta = -c``) with ``f = 0`` provided ``n' = sin theta > vbar`` there (else the
    element never sticks); it ends where the stick line meets ``n`` again.
    """
    if c <= -1.0:
        return 0.0, 0.0
    if c >= 1.0:
        theta, n_mean = math.pi, c
    else:
        theta = math.acos(-c)
        n_mean = (c * theta + math.sin(theta)) / math.pi
    if vbar >= 1.0:
        return 0.0, n_mean
    if vbar == 0.0:  # f stays at the smallest normal force of the cycle
        return 2.0 * math.pi * (n_mean - max(0.0, c - 1.0)), n_mean
    s = math.sqrt(1.0 - vbar * vbar)
    if c >= s:
        tau_s = math.pi + math.asin(vbar)
    elif c > -s:
        tau_s = 2.0 * math.pi - theta
    else:
        return 0.0, n_mean
    from scipy.optimize import brentq

    def gap(t: float) -> float:  # n - stick line: > 0 while the element sticks
        return math.cos(tau_s + t) - math.cos(tau_s) - vbar * t

    t_max = 2.0 * math.pi - math.asin(vbar) - tau_s  # n' falls through vbar: gap largest
    t_min = t_max + math.pi + 2.0 * math.asin(vbar)  # n' rises through it: gap smallest
    t2 = brentq(gap, t_max, t_min, xtol=1e-15, rtol=1e-15)
    deficit = (math.sin(tau_s + t2) - math.sin(tau_s) - t2 * math.cos(tau_s)
               - 0.5 * vbar * t2 * t2)
    return deficit, n_mean


def _stiff_flat(vbar: float, a: float) -> float:
    if a == 0.0:
        return 1.0
    deficit, n_mean = _stiff_element(1.0 / a, vbar)
    return 1.0 - deficit / (2.0 * math.pi * n_mean)


def mu_ratio_stiff_flat(vbar: ArrayLike, amplitude: ArrayLike) -> FloatOrArray:
    r"""The stiff limit of a flat contact, jumping included: :func:`mu_ratio_stiff_exact`
    for ``a <= 1``, extended to ``a > 1``.

    In units of ``dF_N``, ``n = max(0, c + cos tau)`` with ``c = 1/a`` and ``f' = vbar`` in
    stick. A jumping contact (``c < 1``) lands at ``tau_on = 2 pi - theta``,
    ``cos theta = -c``, with ``f = 0``: if ``tau_on`` comes after ``tau1 = pi + asin vbar``
    (i.e. ``c < sqrt(1 - vbar^2)``) stick starts there, ``tau_s = tau_on``, else at
    ``tau_s = tau1`` as without jumping. With ``tau2`` the next meeting of the stick line
    ``f = n(tau_s) + vbar (tau - tau_s)`` with ``n``, ``d = tau2 - tau_s``:

    .. math:: \frac{\mu}{\mu_0} = 1 - \frac{\sin\tau_2 - \sin\tau_s - d\cos\tau_s
              - \bar v d^2/2}{2\pi \langle n\rangle},\quad
              \langle n\rangle = (c\,\theta + \sin\theta)/\pi,

    0 at ``vbar = 0`` for ``a >= 1`` (eq. 2), 1 for ``vbar >= 1``.
    """
    v = _valid("vbar", vbar, _ANY_VBAR)
    a = _valid("amplitude", amplitude)
    return as_float_or_array(np.vectorize(_stiff_flat, otypes=[float])(v, a))


def _stiff_profile(vbar: float, a: float, n: float) -> float:
    if math.isinf(n):
        return _stiff_flat(vbar, a)
    if a == 0.0 or vbar >= 1.0:
        return 1.0
    from scipy.integrate import quad

    # elements x/a0 = xi in (0, (1 + a)^(1/n)]: c(xi) = (1 - xi^n)/a in units of dd;
    # sum of their <n>: int (1 + a cos tau - xi^n)_+ dxi / a = n M(a) / ((n + 1) a)
    total_n = n * _profile_mean_force(a, n) / ((n + 1.0) * a)
    if vbar == 0.0:
        return (max(0.0, 1.0 - a) ** (1.0 + 1.0 / n)) / _profile_mean_force(a, n)
    s = math.sqrt(1.0 - vbar * vbar)
    xi_s = max(0.0, 1.0 - a * s) ** (1.0 / n)  # inside: stick starts at tau1 (c >= s)
    xi_m = (1.0 + a * s) ** (1.0 / n)  # outside: the element never sticks (c <= -s)
    core = _stiff_element(max(s, 1.0), vbar)[0] * xi_s  # same deficit for every c >= s

    def deficit(xi: float) -> float:
        return _stiff_element((1.0 - xi**n) / a, vbar)[0]

    ring = quad(deficit, xi_s, xi_m, epsabs=1e-13, epsrel=1e-11, limit=200)[0]
    return 1.0 - (core + ring) / (2.0 * math.pi * total_n)


def mu_ratio_stiff_profile(vbar: ArrayLike, amplitude: ArrayLike,
                           profile_exponent: ArrayLike) -> FloatOrArray:
    r"""The stiff-system law of Part I for the curved profile ``z = c r^n`` (MDR).

    In a stiff system the body moves at the pulling velocity and every MDR spring at
    ``x`` is an independent flat element (:func:`mu_ratio_stiff_flat`) with its own
    amplitude ``dd/(d0 - g(x))`` and the same dimensionless velocity
    ``vbar = v0 G*_mdr/(mu0 E* omega dd)`` (scaled: ``(beta - alpha) V n/((n + 1) a)``;
    the flat punch's ``k V/a``). With ``xi = x/a0`` and ``c(xi) = (1 - xi^n)/a`` the
    element's mean force in units of ``E* dd dx`` is ``<n>(c) - D(c, vbar)/(2 pi)``, so

    .. math:: \frac{\mu}{\mu_0} = 1 - \frac{(n + 1) a}{2\pi n M(a)}
              \int_0^{(1 + a)^{1/n}} D\big(c(\xi), \bar v\big)\,d\xi,

    ``M(a)`` of :func:`profile_mean_normal_force`. ``D`` is the same for every element
    with ``c >= sqrt(1 - vbar^2)`` (the core), 0 for ``c <= -sqrt(1 - vbar^2)`` (the outer
    ring that slides whenever it touches); between them the ring of jumping elements is
    integrated by quadrature. It is :func:`profile_static_mu_ratio` at ``vbar = 0``, 1 for
    ``vbar >= 1`` (continuous sliding: the same ``vbar = 1`` for every profile), and
    :func:`mu_ratio_stiff_flat` for ``n = inf``.
    """
    v = _valid("vbar", vbar, _ANY_VBAR)
    a = _valid("amplitude", amplitude)
    n = _exponent(profile_exponent)
    return as_float_or_array(np.vectorize(_stiff_profile, otypes=[float])(v, a, n))


def _dead_weight_ratio(A: float, n: float) -> float:
    """``d0/d_s`` with ``(d0/d_s)^p M(A d_s/d0, n) = 1`` (:func:`dead_weight_indentation`)."""
    if A == 0.0:
        return 1.0
    p = 1.0 if math.isinf(n) else 1.0 + 1.0 / n
    # at d0 -> 0+ the mean force tends to A^p <max(0, cos tau)^p> (units of the load)
    floor = A**p * math.exp(math.lgamma(0.5 * p + 0.5) - math.lgamma(0.5 * p + 1.0)) \
        / (2.0 * math.sqrt(math.pi))
    if floor >= 1.0 - 1e-12:  # (at the limit itself d0 = 0)
        limit = floor ** (-1.0 / p) * A
        raise ValueError(f"the oscillation is too large for the dead weight: the mean force "
                         f"at zero mean indentation is already {floor:.6g} times the load "
                         f"(du_z/d_static = {A!r} must be below {limit:.6g}): the mean "
                         "indentation would be <= 0, which the scaled model (a = du_z/d0) "
                         "does not cover")
    if math.isinf(n) and A <= 1.0:  # M = 1 at d0 = d_s: the flat punch does not jump
        return 1.0
    from scipy.optimize import brentq

    def excess(r: float) -> float:  # mean force at d0 = r d_s over the load, minus 1
        return r**p * _profile_mean_force(A / r, n) - 1.0

    lo = 0.5
    for _ in range(60):  # down to d0 ~ 1e-18 d_s
        if excess(lo) <= 0.0:
            return brentq(excess, lo, 1.0, xtol=1e-16, rtol=1e-15, maxiter=200)
        lo *= 0.5
    raise ValueError(f"the oscillation is too large for the dead weight: du_z/d_static = "
                     f"{A!r} is at its limit, where the mean indentation tends to 0")


def dead_weight_indentation(static_amplitude: ArrayLike,
                            profile_exponent: ArrayLike) -> FloatOrArray:
    r"""The mean indentation ``d0`` under a dead weight, in units of the static one.

    A dead weight imposes the *mean* normal force over the cycle: with the indentation
    ``d0 + dd cos tau`` and the force ``F(d) = F_s (d/d_s)^p`` of the tip ``z = c r^n``
    (``p = 1 + 1/n``; ``F(d_s) = F_s``, the load; a linear spring or a flat punch
    ``p = 1``), ``<F> = F_s (d0/d_s)^p M(dd/d0, n)`` with ``M`` of
    :func:`profile_mean_normal_force`, so ``r = d0/d_s`` solves

    .. math:: r^p\, M\!\left(\frac{A}{r}, n\right) = 1, \qquad A = \frac{\Delta d}{d_s}
              \quad (\texttt{static\_amplitude}),

    by Brent's method (``<F>`` grows with ``d0``; ``M >= 1``, so ``r <= 1``). A flat punch
    that does not jump has ``M = 1`` and ``r = 1`` (the static and the dead-weight
    indentation agree); a curved tip, or a jumping flat punch, sits higher (``r < 1``).
    ValueError where no ``d0 > 0`` exists: ``A^p <max(0, cos tau)^p> >= 1`` (``A >= pi``
    for the flat punch, ``A >= 2.347`` for a sphere): even at ``d0 = 0`` the mean force
    exceeds the load.
    """
    A = checked("static_amplitude", static_amplitude, minimum=0.0)
    n = _exponent(profile_exponent)
    return as_float_or_array(np.vectorize(_dead_weight_ratio, otypes=[float])(A, n))


#: Points of the period on which the continuous-sliding response is sampled (FFT).
_SLIDING_GRID = 1 << 15


def _force_harmonics(a: float, n: float, N: int = _SLIDING_GRID) -> NDArray[np.float64]:
    """``c_k``, ``k = 0 .. N/2 - 1``, of ``m(tau) = max(0, 1 + a cos tau)^p = c_0 + sum c_k
    cos(k tau)`` (``p = 1 + 1/n``): closed form for the flat punch, else by FFT of ``N``
    samples (the aliasing error of the kink at a jumping contact's lift-off is
    ``O(N^-(p+1))``)."""
    K = N // 2
    c = np.zeros(K)
    if math.isinf(n):
        if a <= 1.0:
            c[0], c[1] = 1.0, a
            return c
        th = math.acos(-1.0 / a)
        k = np.arange(K, dtype=float)

        def S(j: NDArray[np.float64]) -> NDArray[np.float64]:  # int_0^th cos(j t) dt
            jj = np.where(j == 0.0, 1.0, j)
            return np.where(j == 0.0, th, np.sin(j * th) / jj)

        c[:] = 2.0 / math.pi * (S(k) + 0.5 * a * (S(np.abs(k - 1.0)) + S(k + 1.0)))
        c[0] = (th + a * math.sin(th)) / math.pi
        return c
    tau = 2.0 * math.pi * np.arange(N) / N
    m = np.maximum(0.0, 1.0 + a * np.cos(tau)) ** (1.0 + 1.0 / n)
    C = np.fft.rfft(m)[:K].real / N
    c[0] = C[0]
    c[1:] = 2.0 * C[1:]
    return c


def _sliding_rate(c: NDArray[np.float64], alpha: float, beta: float, a: float, p: float,
                  zeta: float):
    """``(tau, h on the grid, h)`` of continuous sliding driven by the total normal force
    ``m = c_0 + sum c_k cos(k tau)`` (``c`` of :func:`_force_harmonics`; grid of
    ``2 c.size`` points): ``h = -(y_p' + (p a/(beta - alpha)) sin tau)``, so that every
    spring's slip velocity is ``V - h``; ``None`` where the response is unbounded (undamped
    ``alpha = k^2`` with a ``k``-th harmonic in the force)."""
    K = c.size
    N = 2 * K
    k = np.arange(K, dtype=float)
    gamma = 2.0 * zeta * math.sqrt(alpha)
    D = alpha - k * k + 1j * gamma * k
    Q = np.zeros(K, dtype=complex)
    live = k >= 1.0
    if gamma == 0.0:
        root = round(math.sqrt(alpha))
        if 1 <= root < K and root * root == alpha:
            if abs(c[root]) > 1e-12 * abs(c[0]):
                return None
            live &= k != root  # a harmonic the force does not have
    Q[live] = c[live] * 1j * k[live] / D[live]  # y_p' = -sum Re(Q_k e^{i k tau})
    drag = 0.0 if math.isinf(beta) else p * a / (beta - alpha)
    tau = 2.0 * math.pi * np.arange(N) / N
    X = np.zeros(K + 1, dtype=complex)
    X[:K] = 0.5 * N * Q
    h_grid = np.fft.irfft(X, N) - drag * np.sin(tau)

    def h(t: float) -> float:
        return float(np.real(np.sum(Q * np.exp(1j * k * t)))) - drag * math.sin(t)

    return tau, h_grid, h


def _critical_of(c: NDArray[np.float64], alpha: float, beta: float, a: float, p: float,
                 zeta: float) -> float:
    """``V_c`` of continuous sliding under the total normal force of harmonics ``c``: the
    largest ``h`` (:func:`_sliding_rate`) where ``1 + a cos tau > 0`` (the grid's, refined
    by Brent between its neighbours; the contact's ends for a jumping indenter), 0 if
    negative."""
    if a == 0.0:
        return 0.0
    out = _sliding_rate(c, alpha, beta, a, p, zeta)
    if out is None:
        return math.inf
    tau, h_grid, h = out
    th = math.acos(-1.0 / a) if a > 1.0 else math.pi  # contact while |tau| < th
    t = np.where(tau > math.pi, tau - 2.0 * math.pi, tau)
    inside = np.abs(t) < th
    j = int(np.argmax(np.where(inside, h_grid, -np.inf)))
    from scipy.optimize import minimize_scalar

    step = 2.0 * math.pi / tau.size
    lo, hi = max(t[j] - step, -th), min(t[j] + step, th)
    best = minimize_scalar(lambda s: -h(s), bounds=(lo, hi), method="bounded",
                           options={"xatol": 1e-12})
    values = [h_grid[j], -best.fun]
    if a > 1.0:
        values += [h(th), h(-th)]
    return max(0.0, max(values))


def _profile_critical(alpha: float, beta: float, a: float, n: float, zeta: float,
                      N: int = _SLIDING_GRID) -> float:
    p = 1.0 if math.isinf(n) else 1.0 + 1.0 / n
    return _critical_of(_force_harmonics(a, n, N), alpha, beta, a, p, zeta)


def profile_critical_velocity(alpha: ArrayLike, beta: ArrayLike, amplitude: ArrayLike,
                              profile_exponent: ArrayLike, zeta: ArrayLike = 0.0
                              ) -> FloatOrArray:
    r"""Critical inertial velocity of continuous sliding for the tip ``z = c r^n`` (MDR).

    Under continuous forward sliding every spring in contact slips forward, ``f_i = n_i``,
    so the body ``y = x - V tau`` is driven by the total normal force
    ``m(tau) = max(0, 1 + a cos tau)^p`` (``p = 1 + 1/n``; units of ``mu0 F_N0``; not
    harmonic for a curved tip, nor for a jumping flat punch):
    ``y'' + gamma y' + alpha y = -m``, ``gamma = 2 zeta sqrt(alpha)``, whose periodic
    solution ``y_p`` is a Fourier series, ``m = sum c_k cos(k tau)``,
    ``y_p' = -sum c_k Re(i k e^{i k tau}/(alpha - k^2 + i gamma k))``. Every spring has the
    same slip velocity ``V + y_p' + (p a/(beta - alpha)) sin tau`` (in slip
    ``x_ci = x - n_i/k_i`` with ``n_i' = -p a sin(tau) dxi``, ``k_i = (beta - alpha) dxi``
    for every spring in contact), and so does a spring touching
    down unloaded (it slips from touch-down iff that velocity is positive, else it
    sticks). Continuous sliding holds iff it is ``>= 0`` wherever some spring is in
    contact, ``1 + a cos tau > 0``:

    .. math:: V_c = \max_{1 + a\cos\tau > 0}\Big[-y_p'(\tau)
              - \frac{p\,a}{\beta - \alpha}\sin\tau\Big]

    (0 if negative). The rings that lift off in every cycle change only ``m``; the
    condition is the innermost spring's. A flat punch without jumping (``n = inf``,
    ``a <= 1``) gives eq. (12) with pin damping (:func:`critical_inertial_velocity`); a
    jumping flat punch the true onset, which eq. (12) is not. ``inf`` undamped at
    ``alpha = k^2`` for every harmonic ``k`` the force has (for a curved tip all of them).
    ``beta = inf`` drops the last term. Above ``V_c`` ``mu/mu0 = <m>/<m> = 1``.
    """
    alpha, beta, a, zeta = validated(
        {"alpha": alpha, "beta": beta, "amplitude": amplitude, "zeta": zeta}).values()
    n = _exponent(profile_exponent)
    return as_float_or_array(np.vectorize(_profile_critical, otypes=[float])(
        alpha, beta, a, n, zeta))
