r"""Closed-form solutions of the three phases (docs/model.md, docs/damping.md; eqs. 4, 5, 15).

Scaled variables: time ``tau = omega t``, forces in ``mu0 F_N0``, lengths in
``mu0 F_N0 / (m omega^2)``; ``y = x - V tau`` is the body displacement with the
drift removed, ``e = x - x_c`` the elongation of the contact spring, ``f`` the
tangential contact force, ``n = 1 + a cos tau`` the normal force, ``k = beta - alpha``
the contact stiffness (``inf`` = rigid), ``gamma = 2 zeta sqrt(alpha)`` the pin
dashpot and ``c = eta_c k`` the contact dashpot.  ``theta`` is the drive phase at
the segment start, ``t`` the time since then.

* body in slip ``s`` (``s = 0``: flight): ``y'' + gamma y' + alpha y = -s n``;
* contact in slip: ``f = s n``, ``eta_c e' + e = s n / k`` (``e = s n/k`` when
  ``eta_c = 0``); in flight ``f = 0`` and ``e`` relaxes, ``eta_c e' + e = 0``;
* stick (contact point fixed, ``e' = x'``):
  ``e'' + (gamma + c) e' + beta e = alpha (e_0 - y_0) + gamma V + alpha V t``,
  ``f = k e + c e'``, ``y = y_0 + (e - e_0) - V t``; rigid contact: ``x' = 0``,
  ``f = -alpha y + gamma V``.

The model tuple (:func:`make_model`) carries the parameters and the two modes
(free motions) of slip and stick.  Each function returns coefficient tuples over
:mod:`.basis`.
"""

import math

from .basis import RESONANT_BAND, add, derivative, initial_pair, make_mode, scale
from .jit import jit

# fields of the model tuple
M_ALPHA, M_BETA, M_A, M_V, M_GAMMA, M_ETA, M_K, M_C, M_R = 0, 1, 2, 3, 4, 5, 6, 7, 8
M_OFF, M_ON, M_SLIP, M_STICK = 9, 10, 11, 12
TWO_PI = 2.0 * math.pi
# Loss factors below this are treated as an elastic contact: the relaxation time
# eta_c/omega is then shorter than round-off can resolve in the contact-point velocity
# (its error ~ eps/(k eta_c)).  mu depends on eta_c linearly near 0 (measured
# |mu(eta_c) - mu(0)| <= 1.5 eta_c), so ETA_SLOPE * eta_c is added to the error.
ETA_ELASTIC = 1e-6
ETA_SLOPE = 10.0
ZERO9 = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)


@jit
def liftoff_phases(a):
    """Drive phases of lift-off and touch-down, ``cos theta = -1/a`` (a >= 1).

    At ``a = 1`` both are ``pi``: the grazing point, where ``n`` touches zero.
    """
    if a < 1.0:
        return TWO_PI, TWO_PI
    th = math.acos(-1.0 / a)
    return th, TWO_PI - th


@jit
def make_model(alpha, beta, a, V, zeta, eta):
    """The parameters of one point and the modes of slip and stick (see module doc)."""
    rigid = math.isinf(beta)
    k = math.inf if rigid else beta - alpha
    gamma = 2.0 * zeta * math.sqrt(alpha)
    viscous = eta >= ETA_ELASTIC and not rigid
    c = eta * k if viscous else 0.0
    r = 1.0 / eta if viscous else 0.0
    slip = make_mode(alpha, 0.5 * gamma, r)
    stick = slip if rigid else make_mode(beta, 0.5 * (gamma + c), 0.0)
    th_off, th_on = liftoff_phases(a)
    return (alpha, beta, a, V, gamma, eta if viscous else 0.0, k, c, r, th_off, th_on,
            slip, stick)


@jit
def body(M, theta, y0, yd0, s):
    """``y(t)`` in slip ``s`` (``s = 0``: flight) from ``(y0, y0')`` at phase ``theta``.

    Away from the resonance (``|P| > RESONANT_BAND``, ``P = alpha - 1 + i gamma``) the
    forced response is the periodic one, ``Re(-s a e^{i tau}/P)``, plus free motion;
    near it, the responses from rest ``C``, ``S`` (:mod:`.basis`), exact through it.
    """
    a = M[M_A]
    m = M[M_SLIP]
    p = -s / M[M_ALPHA]
    pr = m[7] - 1.0
    pi = 2.0 * m[1]
    p2 = pr * pr + pi * pi
    if s == 0.0 or a == 0.0 or p2 > RESONANT_BAND * RESONANT_BAND:
        # Z = -s a e^{i theta} / P; y_p = Re(Z e^{it}) = Zr cos t - Zi sin t
        wr = -s * a * math.cos(theta)
        wi = -s * a * math.sin(theta)
        zr = (wr * pr + wi * pi) / p2 if p2 > 0.0 else 0.0
        zi = (wi * pr - wr * pi) / p2 if p2 > 0.0 else 0.0
        D, E = initial_pair(m, y0 - p - zr, yd0 + zi)
        return (p, 0.0, zr, -zi, D, E, 0.0, 0.0, 0.0)
    D, E = initial_pair(m, y0 - p, yd0)
    return (p, 0.0, 0.0, 0.0, D, E, -s * a * math.cos(theta), s * a * math.sin(theta), 0.0)


@jit
def elongation(M, theta, e0, ed0, s):
    """``e(t)`` in slip ``s`` (``s = 0``: flight) from ``e0`` (zero for a rigid contact).

    ``ed0``, when finite, is the exact rate ``e'(0)`` (``x'`` when slip starts from
    stick): the relaxing part then follows from it, ``K = eta_c (e_p'(0) - ed0)``,
    without the cancellation of ``e0 - e_p(0)``, whose round-off ``eps/k`` becomes
    ``eps/(k eta_c)`` in the contact-point velocity.
    """
    if math.isinf(M[M_K]):
        return ZERO9
    eta, k = M[M_ETA], M[M_K]
    K = e0 if eta > 0.0 else 0.0
    if s == 0.0:
        return (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, K)
    g = s * M[M_A] / (k * (1.0 + eta * eta))
    ct = math.cos(theta)
    st = math.sin(theta)
    A = g * (ct + eta * st)
    B = g * (eta * ct - st)
    p = s / k
    if eta > 0.0:
        K = eta * (B - ed0) if math.isfinite(ed0) else e0 - (p + A)
    return (p, 0.0, A, B, 0.0, 0.0, 0.0, 0.0, K)


@jit
def slip_velocity(M, ycoef, ecoef, s):
    """Contact-point velocity times ``s``: ``s (V + y' - e')`` (eq. 10 generalised)."""
    m = M[M_SLIP]
    v = scale(add(derivative(ycoef, m), scale(derivative(ecoef, m), -1.0)), s)
    return (v[0] + s * M[M_V], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8])


@jit
def stick_elongation(M, y0, xd0, e0):
    """``e(t)`` in stick (finite contact), from the body velocity ``x' = xd0``.

    Takes ``x'`` itself, not ``y' = x' - V``: ``f' = k x'`` with ``k`` up to 1e6
    would amplify the cancellation in ``V + y'``.
    """
    alpha, beta, V = M[M_ALPHA], M[M_BETA], M[M_V]
    m = M[M_STICK]
    p1 = alpha * V / beta
    p0 = (alpha * (e0 - y0) + M[M_GAMMA] * V - 2.0 * m[1] * p1) / beta
    D, E = initial_pair(m, e0 - p0, xd0 - p1)
    return (p0, p1, 0.0, 0.0, D, E, 0.0, 0.0, 0.0)


@jit
def stick_force(M, ecoef):
    """``f = k e + c e'`` in stick (finite contact)."""
    return add(scale(ecoef, M[M_K]), scale(derivative(ecoef, M[M_STICK]), M[M_C]))


@jit
def rigid_stick_force(M, y0):
    """``f(t) = -alpha y + gamma V`` with ``y = y0 - V t`` (rigid contact, body at rest)."""
    alpha, V = M[M_ALPHA], M[M_V]
    return (-alpha * y0 + M[M_GAMMA] * V, alpha * V, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)


@jit
def cone_margin(fcoef, theta, s, a):
    """``n(tau) - s f(tau)``: positive inside the friction cone (eq. 15)."""
    ca = a * math.cos(theta)
    sa = a * math.sin(theta)
    return (1.0 - s * fcoef[0], -s * fcoef[1], ca - s * fcoef[2], -sa - s * fcoef[3],
            -s * fcoef[4], -s * fcoef[5], -s * fcoef[6], -s * fcoef[7], -s * fcoef[8])


@jit
def normal_force(theta, a):
    return 1.0 + a * math.cos(theta)


@jit
def normal_integral(theta, t, a):
    """Integral of ``1 + a cos tau`` over ``[theta, theta + t]``."""
    return t + a * (math.sin(theta + t) - math.sin(theta))
