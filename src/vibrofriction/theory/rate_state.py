r"""Rate-and-state friction: steady sliding and its stability (docs/friction_laws.md).

Scaled units (docs/model.md) with ``mu_star = mu0``: forces in ``mu_star F_N0``, ``a``, ``b``
over ``mu_star``, ``d_c`` in units of the inertial length, ``v_ref`` and velocities in units
of the inertial velocity, the state ``theta`` in units of ``1/omega``.  The law,
regularised at zero slip rate::

    mu(v, theta) = a asinh( v/(2 v_ref) exp((1 + b ln(theta v_ref/d_c))/a) ),

with the aging law ``theta' = 1 - |v| theta/d_c`` or the slip law ``theta' = -(|v| theta/d_c)
ln(|v| theta/d_c)``; both hold ``theta = d_c/v`` in steady sliding.

**Stability of steady sliding** (no oscillation, ``n = 1``).  The body (mass 1) hangs on
the system spring ``alpha`` and dashpot ``gamma = 2 zeta sqrt(alpha)`` pulled at ``V``, and
drives the massless contact point ``w`` through the contact spring ``k = beta - alpha``.
Small perturbations ``~ e^{s tau}`` of steady sliding at ``V`` obey:

* friction: ``df = a_e dw'/V + b_e dtheta/theta`` with the law's local slopes
  ``a_e = d mu/d ln v = a tanh(mu_ss/a)`` and ``b_e = d mu/d ln theta = b tanh(mu_ss/a)``
  (``asinh' = 1/sqrt(1 + X^2)``, ``X/sqrt(1 + X^2) = tanh(asinh X)``);
* state, aging and slip law alike to first order: ``phi = dtheta/theta`` with
  ``(d_c s + V) phi = -s dw``;
* contact ``df = k (dx - dw)``, body ``(s^2 + gamma s + alpha) dx = -df``.

Eliminating ``dx``, ``dw``, ``phi`` leaves the characteristic polynomial
(:func:`sliding_polynomial`)::

    V k (d_c s + V) D(s) + s (a_e d_c s + (a_e - b_e) V) (D(s) + k) = 0,  D = s^2 + gamma s + alpha,

a quartic (a cubic for a rigid contact, ``k -> inf``: ``V (d_c s + V) D + s (a_e d_c s + (a_e
- b_e) V) = 0``).  Steady sliding is stable where every root has a negative real part
(the Hurwitz conditions, :func:`sliding_is_stable`).  Closed forms in two limits:

* rigid contact, undamped: the cubic's Hurwitz condition ``c2 c1 > c3 c0`` gives the
  classical (Rice & Ruina 1983) ``alpha_cr = (b_e - a_e)/d_c (1 + V^2/(a_e d_c))``;
* quasi-static (inertia negligible): the series stiffness ``alpha k/(alpha + k)`` against
  ``(b_e - a_e)/d_c``.

Steady sliding can only lose stability where it weakens with velocity, ``b_e > a_e``.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..validation import as_float_or_array
from .domains import FloatOrArray

__all__ = ["critical_stiffness", "critical_stiffness_rigid", "sliding_eigenvalues",
           "sliding_is_stable", "sliding_polynomial", "steady_mu_ratio", "steady_slopes"]


def steady_mu_ratio(v: ArrayLike, rs_a: ArrayLike, rs_b: ArrayLike, rs_d_c: ArrayLike,
                    rs_v_ref: ArrayLike) -> FloatOrArray:
    """``mu_ss(v)/mu_star``: the coefficient of steady sliding at the slip velocity ``v``.

    ``a asinh( |v|/(2 v_ref) exp((1 + b ln(v_ref/|v|))/a) )`` (``theta = d_c/|v|``), odd in
    ``v``; ``d_c`` drops out.  Computed without overflow (``asinh z = ln 2z + O(z^-2)`` for a
    large ``z``).  ``0`` at ``v = 0``.

    Examples
    --------
    >>> from vibrofriction import theory
    >>> round(theory.steady_mu_ratio(1.0, 0.01, 0.015, 1.0, 1.0), 12)  # at v_ref: mu_star
    1.0
    """
    v, a, b, _, vr = np.broadcast_arrays(*(np.asarray(x, dtype=float)
                                           for x in (v, rs_a, rs_b, rs_d_c, rs_v_ref)))
    speed = np.abs(v)
    with np.errstate(divide="ignore", invalid="ignore"):
        lnz = np.log(speed / (2.0 * vr)) + (1.0 + b * np.log(vr / speed)) / a
        big = lnz > 30.0
        mu = np.where(big, a * (lnz + math.log(2.0)),
                      a * np.arcsinh(np.exp(np.minimum(lnz, 30.0))))
    return as_float_or_array(np.where(speed == 0.0, 0.0, np.sign(v) * mu))


def steady_slopes(v: ArrayLike, rs_a: ArrayLike, rs_b: ArrayLike, rs_d_c: ArrayLike,
                  rs_v_ref: ArrayLike) -> tuple[FloatOrArray, FloatOrArray]:
    """``(a_e, b_e)``: the law's slopes ``d mu/d ln v`` and ``d mu/d ln theta`` in steady sliding.

    ``a tanh(mu_ss/a)`` and ``b tanh(mu_ss/a)``: ``a`` and ``b`` themselves wherever the
    regularisation does not matter (``mu_ss >> a``).
    """
    mu = np.asarray(steady_mu_ratio(v, rs_a, rs_b, rs_d_c, rs_v_ref))
    t = np.tanh(mu / np.asarray(rs_a, dtype=float))
    return (as_float_or_array(np.asarray(rs_a, dtype=float) * t),
            as_float_or_array(np.asarray(rs_b, dtype=float) * t))


def sliding_polynomial(alpha: float, beta: float, zeta: float, v: float, rs_a: float,
                       rs_b: float, rs_d_c: float, rs_v_ref: float) -> NDArray[np.float64]:
    """The coefficients (highest power first) of the characteristic polynomial of steady sliding.

    The quartic of the module's docstring (a cubic for a rigid contact, ``beta = inf``),
    at the velocity ``v > 0`` without oscillation.
    """
    gamma = 2.0 * zeta * math.sqrt(alpha)
    a_e, b_e = (float(x) for x in steady_slopes(v, rs_a, rs_b, rs_d_c, rs_v_ref))
    q1, q0 = a_e * rs_d_c, (a_e - b_e) * v
    if math.isinf(beta):  # V (d_c s + V) D + s Q
        return np.array([v * rs_d_c, v * v + v * rs_d_c * gamma + q1,
                         q0 + v * rs_d_c * alpha + v * v * gamma, v * v * alpha])
    k = beta - alpha
    return np.array([q1,
                     q1 * gamma + q0 + v * k * rs_d_c,
                     q1 * beta + q0 * gamma + v * k * (rs_d_c * gamma + v),
                     q0 * beta + v * k * (rs_d_c * alpha + v * gamma),
                     v * v * k * alpha])


def sliding_eigenvalues(alpha: float, beta: float, zeta: float, v: float, rs_a: float,
                        rs_b: float, rs_d_c: float, rs_v_ref: float) -> NDArray[np.complex128]:
    """The roots of :func:`sliding_polynomial`: the growth rates ``s`` of small perturbations.

    Per unit of the drive's time ``tau = omega t``; ``Im s`` is the angular frequency of
    the stick-slip that grows where ``Re s > 0``.
    """
    return np.roots(sliding_polynomial(alpha, beta, zeta, v, rs_a, rs_b, rs_d_c,
                                       rs_v_ref)).astype(complex)


def _hurwitz_margin(c: NDArray[np.float64]) -> float:
    """The last Hurwitz determinant over a scale: ``> 0`` where every root is stable.

    Cubic ``c3 s^3 + c2 s^2 + c1 s + c0``: ``c2 c1 - c3 c0``; quartic: ``c3 c2 c1 - c4 c1^2 -
    c3^2 c0``; ``-1`` where a coefficient is not positive.
    """
    if np.any(c <= 0.0):
        return -1.0
    if len(c) == 4:
        c3, c2, c1, c0 = c
        return float((c2 * c1 - c3 * c0) / (c2 * c1))
    c4, c3, c2, c1, c0 = c
    return float((c3 * c2 * c1 - c4 * c1 * c1 - c3 * c3 * c0) / (c3 * c2 * c1))


def sliding_is_stable(alpha: float, beta: float, zeta: float, v: float, rs_a: float,
                      rs_b: float, rs_d_c: float, rs_v_ref: float) -> bool:
    """Whether steady sliding at ``v`` without oscillation is linearly stable (Hurwitz)."""
    return _hurwitz_margin(sliding_polynomial(alpha, beta, zeta, v, rs_a, rs_b, rs_d_c,
                                              rs_v_ref)) > 0.0


def critical_stiffness(k_c: float, gamma: float, v: float, rs_a: float, rs_b: float,
                       rs_d_c: float, rs_v_ref: float) -> float:
    """The system stiffness ``alpha_cr`` below which steady sliding at ``v`` is unstable.

    At a fixed contact stiffness ``k_c = beta - alpha`` (``inf``: rigid) and a fixed pin
    dashpot ``gamma = 2 zeta sqrt(alpha)`` (so ``zeta = gamma/(2 sqrt(alpha_cr))`` at the
    onset): the root in ``alpha`` of the last Hurwitz determinant of
    :func:`sliding_polynomial`.  ``0`` where sliding is stable at every stiffness (velocity
    strengthening, ``b_e <= a_e``); ``inf`` where no pin stiffness stabilises it (a contact
    spring so soft that the series stiffness stays below the critical one).

    Raises
    ------
    ValueError
        A velocity ``v <= 0``.
    """
    if not v > 0.0:
        raise ValueError(f"v must be > 0 (steady sliding), got {v!r}")

    def margin(alpha: float) -> float:
        beta = math.inf if math.isinf(k_c) else alpha + k_c
        zeta = gamma / (2.0 * math.sqrt(alpha))
        return _hurwitz_margin(sliding_polynomial(alpha, beta, zeta, v, rs_a, rs_b, rs_d_c,
                                                  rs_v_ref))

    a_e, b_e = (float(x) for x in steady_slopes(v, rs_a, rs_b, rs_d_c, rs_v_ref))
    if b_e <= a_e:
        return 0.0
    hi = (b_e - a_e) / rs_d_c * (1.0 + v * v / (a_e * rs_d_c)) + 1.0
    lo = 1e-300
    while margin(hi) <= 0.0:  # the series spring: a softer contact needs a stiffer pin
        hi *= 4.0
        if hi > 1e300:
            return math.inf
    if margin(lo) > 0.0:
        return 0.0
    for _ in range(200):  # bisection in ln alpha: robust across decades
        mid = math.sqrt(lo * hi) if lo > 0.0 else 0.5 * hi
        if margin(mid) > 0.0:
            hi = mid
        else:
            lo = mid
        if hi - lo <= 1e-13 * hi:
            break
    return hi


def critical_stiffness_rigid(v: ArrayLike, rs_a: ArrayLike, rs_b: ArrayLike,
                             rs_d_c: ArrayLike, rs_v_ref: ArrayLike,
                             gamma: ArrayLike = 0.0) -> FloatOrArray:
    """The critical stiffness of a rigid contact in closed form, with the pin dashpot ``gamma``.

    The cubic's Hurwitz condition ``c2 c1 > c3 c0`` is linear in ``alpha``::

        alpha_cr = (V^2 + V d_c gamma + a_e d_c) (b_e - a_e - V gamma) / (d_c^2 (a_e + V gamma)),

    undamped the classical ``(b_e - a_e)/d_c (1 + V^2/(a_e d_c))`` of a block on a spring with
    rate-and-state friction, inertia included (Rice & Ruina 1983); ``0`` where sliding is
    stable at every stiffness (``gamma >= (b_e - a_e)/V``: the dashpot outweighs the negative
    damping of weakening friction).
    """
    a_e, b_e = (np.asarray(x) for x in steady_slopes(v, rs_a, rs_b, rs_d_c, rs_v_ref))
    d_c = np.asarray(rs_d_c, dtype=float)
    v = np.asarray(v, dtype=float)
    g = np.asarray(gamma, dtype=float)
    c2 = v * v + v * d_c * g + a_e * d_c
    return as_float_or_array(np.maximum(0.0, c2 * (b_e - a_e - v * g)
                                        / (d_c * d_c * (a_e + v * g))))
