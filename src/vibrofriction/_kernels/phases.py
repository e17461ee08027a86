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
  ``e'' + (gamma + c) e' + beta e = alpha (e_0 - y_0) + gamma V + alpha V t + h``,
  ``f = k e + c e'``, ``y = y_0 + (e - e_0) - V t``; rigid contact: ``x' = 0``,
  ``f = -alpha y + gamma V + h``.

With a longitudinal in-plane oscillation ``X = a_x cos(tau + phase_x)`` (issue 20) the
body is described in the substrate's frame (``x`` relative to the substrate, where the
contact point is at rest in stick) and the same equations hold with one more force on
the body in every phase, ``h(tau) = hc cos tau + hs sin tau`` (:func:`inplane_forcing`):
``y'' + gamma y' + alpha y = -f + h``.  ``h = 0`` without in-plane oscillation.

With a static coefficient above the kinetic one (``s_r = mu_static/mu0 > 1``,
docs/friction_laws.md) a stuck contact holds while ``|f| <= s_r n`` (the stick margin
``s_r n - s f``, :func:`cone_margin`) and slips with the kinetic force ``f = s n``: every
phase keeps its closed form, only the stick margin and the events change.

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
# the in-plane forcing h = hc cos tau + hs sin tau
M_HC, M_HS = 13, 14
# the static coefficient over the kinetic one, s_r = mu_static/mu0 >= 1 (docs/friction_laws.md)
M_SR = 15
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
def inplane_forcing(alpha, gamma, a_x, phase_x, on_substrate):
    """``(hc, hs)``: the force ``h = hc cos tau + hs sin tau`` of a longitudinal in-plane
    oscillation ``X = a_x cos(tau + phase_x)`` on the body (docs/inplane.md, "The exact
    solver").

    On the substrate the body is described relative to it, ``x~ = x - X``: the frame's
    inertial force ``-X''`` and the spring and dashpot pulling on ``x = x~ + X`` give
    ``h = -alpha X - gamma X' - X'' = (1 - alpha) X - gamma X'``.  On the holder the
    pulled end moves by ``X``: ``h = alpha X + gamma X'``.
    """
    if a_x == 0.0:
        return 0.0, 0.0
    c = a_x * math.cos(phase_x)  # X = c cos tau - d sin tau, X' = -c sin tau - d cos tau
    d = a_x * math.sin(phase_x)
    if on_substrate:
        w = 1.0 - alpha
        return w * c + gamma * d, -w * d + gamma * c
    return alpha * c - gamma * d, -alpha * d - gamma * c


@jit
def make_model(alpha, beta, a, V, zeta, eta, a_x, phase_x, on_substrate, sr=1.0):
    """The parameters of one point and the modes of slip and stick (see module doc).

    ``sr``: the static coefficient over the kinetic one, ``mu_static/mu0 >= 1``.
    """
    rigid = math.isinf(beta)
    k = math.inf if rigid else beta - alpha
    gamma = 2.0 * zeta * math.sqrt(alpha)
    viscous = eta >= ETA_ELASTIC and not rigid
    c = eta * k if viscous else 0.0
    r = 1.0 / eta if viscous else 0.0
    slip = make_mode(alpha, 0.5 * gamma, r)
    stick = slip if rigid else make_mode(beta, 0.5 * (gamma + c), 0.0)
    th_off, th_on = liftoff_phases(a)
    hc, hs = inplane_forcing(alpha, gamma, a_x, phase_x, on_substrate)
    return (alpha, beta, a, V, gamma, eta if viscous else 0.0, k, c, r, th_off, th_on,
            slip, stick, hc, hs, sr)


@jit
def frame_offset(a_x, phase_x, on_substrate):
    """``(X, X')`` at ``tau = 2 pi k``: the offset of the kernels' frame (relative to an
    oscillating substrate) from the laboratory's; 0 when the holder oscillates.
    """
    if a_x == 0.0 or not on_substrate:
        return 0.0, 0.0
    return a_x * math.cos(phase_x), -a_x * math.sin(phase_x)


@jit
def forced(M):
    """Whether the point has an in-plane forcing ``h``."""
    return M[M_HC] != 0.0 or M[M_HS] != 0.0


@jit
def inplane_force(M, tau):
    """``(h, h')`` at drive phase ``tau``."""
    c = math.cos(tau)
    s = math.sin(tau)
    return M[M_HC] * c + M[M_HS] * s, M[M_HS] * c - M[M_HC] * s


@jit
def _periodic_response(m, wr, wi):
    """``Z = W / P`` of the harmonic force ``Re(W e^{it})``, ``W = wr + i wi``, on the
    oscillator of mode ``m`` (``P = w0^2 - 1 + 2 i sigma``): ``(Zr, Zi, near)``, ``near``
    where ``|P|`` is within ``RESONANT_BAND`` (use the responses ``C``, ``S`` instead).
    """
    pr = m[7] - 1.0
    pi = 2.0 * m[1]
    p2 = pr * pr + pi * pi
    if p2 <= RESONANT_BAND * RESONANT_BAND:
        return 0.0, 0.0, True
    return (wr * pr + wi * pi) / p2, (wi * pr - wr * pi) / p2, False


@jit
def body(M, theta, y0, yd0, s):
    """``y(t)`` in slip ``s`` (``s = 0``: flight) from ``(y0, y0')`` at phase ``theta``.

    The harmonic force is ``Re(W e^{i tau})``, ``W = -s a + H`` with the in-plane force
    ``h = Re(H e^{i tau})``, ``H = hc - i hs`` (0 without in-plane oscillation).  Away
    from the resonance (``|P| > RESONANT_BAND``, ``P = alpha - 1 + i gamma``) the forced
    response is the periodic one, ``Re(W e^{i tau}/P)``, plus free motion; near it, the
    responses from rest ``C``, ``S`` (:mod:`.basis`), exact through it.
    """
    a = M[M_A]
    m = M[M_SLIP]
    p = -s / M[M_ALPHA]
    ct = math.cos(theta)
    st = math.sin(theta)
    hc, hs = M[M_HC], M[M_HS]
    if not forced(M):
        wr = -s * a * ct
        wi = -s * a * st
        off = s == 0.0 or a == 0.0
    else:
        # W e^{i theta} = (-s a + hc - i hs)(cos theta + i sin theta)
        wc = -s * a + hc
        wr = wc * ct + hs * st
        wi = wc * st - hs * ct
        off = False
    # Z = W e^{i theta} / P; y_p = Re(Z e^{it}) = Zr cos t - Zi sin t
    zr, zi, near = (0.0, 0.0, False) if off else _periodic_response(m, wr, wi)
    if not near:
        D, E = initial_pair(m, y0 - p - zr, yd0 + zi)
        return (p, 0.0, zr, -zi, D, E, 0.0, 0.0, 0.0)
    D, E = initial_pair(m, y0 - p, yd0)
    return (p, 0.0, 0.0, 0.0, D, E, wr, -wi, 0.0)


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
def stick_elongation(M, theta, y0, xd0, e0):
    """``e(t)`` in stick (finite contact) from phase ``theta``, from the body velocity ``x' = xd0``.

    Takes ``x'`` itself, not ``y' = x' - V``: ``f' = k x'`` with ``k`` up to 1e6
    would amplify the cancellation in ``V + y'``.
    """
    alpha, beta, V = M[M_ALPHA], M[M_BETA], M[M_V]
    m = M[M_STICK]
    p1 = alpha * V / beta
    p0 = (alpha * (e0 - y0) + M[M_GAMMA] * V - 2.0 * m[1] * p1) / beta
    if not forced(M):
        D, E = initial_pair(m, e0 - p0, xd0 - p1)
        return (p0, p1, 0.0, 0.0, D, E, 0.0, 0.0, 0.0)
    # the in-plane force h(theta + t) = h0 cos t + h1 sin t drives the stick oscillator
    # (P_st = beta - 1 + i (gamma + c)): its periodic response, or near the resonance
    # beta = 1 the responses from rest C, S of the stick mode
    h0, h1 = inplane_force(M, theta)
    zr, zi, near = _periodic_response(m, h0, -h1)  # Z = (h0 - i h1) / P_st
    if not near:
        D, E = initial_pair(m, e0 - p0 - zr, xd0 - p1 + zi)
        return (p0, p1, zr, -zi, D, E, 0.0, 0.0, 0.0)
    D, E = initial_pair(m, e0 - p0, xd0 - p1)
    return (p0, p1, 0.0, 0.0, D, E, h0, h1, 0.0)


@jit
def stick_force(M, ecoef):
    """``f = k e + c e'`` in stick (finite contact)."""
    return add(scale(ecoef, M[M_K]), scale(derivative(ecoef, M[M_STICK]), M[M_C]))


@jit
def rigid_stick_force(M, theta, y0):
    """``f(t) = -alpha y + gamma V + h`` with ``y = y0 - V t`` (rigid contact, body at rest
    relative to the substrate).
    """
    alpha, V = M[M_ALPHA], M[M_V]
    h0, h1 = inplane_force(M, theta) if forced(M) else (0.0, 0.0)
    return (-alpha * y0 + M[M_GAMMA] * V, alpha * V, h0, h1, 0.0, 0.0, 0.0, 0.0, 0.0)


@jit
def cone_margin(fcoef, theta, s, a, sr):
    """``s_r n(tau) - s f(tau)``: positive inside the static friction cone (eq. 15; ``s_r = 1``:
    Coulomb's).
    """
    ca = sr * a * math.cos(theta)
    sa = sr * a * math.sin(theta)
    return (sr - s * fcoef[0], -s * fcoef[1], ca - s * fcoef[2], -sa - s * fcoef[3],
            -s * fcoef[4], -s * fcoef[5], -s * fcoef[6], -s * fcoef[7], -s * fcoef[8])


@jit
def normal_force(theta, a):
    return 1.0 + a * math.cos(theta)


@jit
def normal_integral(theta, t, a):
    """Integral of ``1 + a cos tau`` over ``[theta, theta + t]``."""
    return t + a * (math.sin(theta + t) - math.sin(theta))
