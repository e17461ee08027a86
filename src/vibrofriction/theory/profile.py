"""The real contact geometry by the method of dimensionality reduction (MDR).

The mean force, the static ratio, the stiff law, the dead weight and the critical velocity of a
profile ``z = c r^n`` (docs/contact_geometry.md).
"""

from __future__ import annotations

import functools
import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..validation import as_float_or_array, checked, validated
from .domains import ANY_VBAR, FloatOrArray, elementwise, valid_array


# --------------------------------------------------------------- real contact geometry (MDR)
#: ``n = profile_exponent`` of ``z = c r^n``: ``0 < n <= inf`` (``inf``: the flat punch).
def _exponent(profile_exponent: ArrayLike) -> NDArray[np.float64]:
    return checked("profile_exponent", profile_exponent, minimum=0.0, strict=True,
                   allow_inf=True)


@functools.lru_cache(maxsize=4096)
def _profile_mean_force(a: float, n: float) -> float:
    """``<max(0, 1 + a cos tau)^p>``, ``p = 1 + 1/n``.

    Kept: a jumping indenter's quadrature takes some 50 us, and the MDR solver asks at
    every point of a curve.
    """
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
    a = valid_array("amplitude", amplitude)
    n = _exponent(profile_exponent)
    return as_float_or_array(elementwise(_profile_mean_force, a, n))


def profile_static_mu_ratio(amplitude: ArrayLike, profile_exponent: ArrayLike) -> FloatOrArray:
    r"""Static limit ``mu(v0 -> 0+)/mu0`` for the profile ``z = c r^n``: eq. (2)'s analogue.

    The pulling force creeps up until the whole contact slides at the smallest normal
    force of the cycle, ``F(d0 (1 - a)) = F_N0 (1 - a)^p`` (``p = 1 + 1/n``), and stays
    there, so ``mu/mu0 = (1 - a)^p / <(1 + a cos tau)^p>``
    (:func:`profile_mean_normal_force`) for ``a < 1`` and 0 for a jumping indenter
    (``a >= 1``). ``n = inf`` gives :func:`static_mu_ratio`, ``1 - a``.
    """
    a = valid_array("amplitude", amplitude)
    n = _exponent(profile_exponent)
    a, n = np.broadcast_arrays(a, n)
    p = 1.0 + 1.0 / n
    low = np.where(a < 1.0, np.maximum(1.0 - a, 0.0) ** p, 0.0)
    return as_float_or_array(low / np.asarray(profile_mean_normal_force(a, n)))


def _stiff_element(c: float, vbar: float) -> tuple[float, float]:
    """Stiff limit of one flat element with ``n = max(0, c + cos tau)``.

    Pulled at the rate ``f' = vbar`` while it sticks: ``(deficit, <n>)``, ``<f> = <n> - deficit/(2
    pi)``.

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
    r"""The stiff limit of a flat contact, jumping included.

    :func:`mu_ratio_stiff_exact` for ``a <= 1``, extended to ``a > 1``.

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
    v = valid_array("vbar", vbar, ANY_VBAR)
    a = valid_array("amplitude", amplitude)
    return as_float_or_array(elementwise(_stiff_flat, v, a))


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
    v = valid_array("vbar", vbar, ANY_VBAR)
    a = valid_array("amplitude", amplitude)
    n = _exponent(profile_exponent)
    return as_float_or_array(elementwise(_stiff_profile, v, a, n))


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
    return as_float_or_array(elementwise(_dead_weight_ratio, A, n))


#: Points of the period on which the continuous-sliding response is sampled (FFT).
_SLIDING_GRID = 1 << 15


def _force_harmonics(a: float, n: float, N: int = _SLIDING_GRID) -> NDArray[np.float64]:
    """The harmonics ``c_k`` of the total normal force ``m(tau) = max(0, 1 + a cos tau)^p``.

    ``m(tau) = c_0 + sum c_k cos(k tau)``, ``k = 0 .. N/2 - 1`` (``p = 1 + 1/n``): closed form
    for the flat punch, else by FFT of ``N`` samples (the aliasing error of the kink at a
    jumping contact's lift-off is ``O(N^-(p+1))``).
    """
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
    """``(tau, h on the grid, h)`` of continuous sliding under the total normal force.

    The force ``m = c_0 + sum c_k cos(k tau)`` (``c`` of :func:`_force_harmonics`; grid of ``2
    c.size`` points): ``h = -(y_p' + (p a/(beta - alpha)) sin tau)``, so that every spring's slip
    velocity is ``V - h``; ``None`` where the response is unbounded (undamped ``alpha = k^2`` with a
    ``k``-th harmonic in the force).
    """
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
    """``V_c`` of continuous sliding under the total normal force of harmonics ``c``.

    The largest ``h`` (:func:`_sliding_rate`) where ``1 + a cos tau > 0`` (the grid's, refined
    by Brent between its neighbours; the contact's ends for a jumping indenter), 0 if negative.
    """
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
