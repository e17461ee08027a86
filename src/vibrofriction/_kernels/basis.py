r"""Event functions and phase solutions as coefficients over one basis per phase.

Every quantity of every phase (body displacement, contact elongation and force,
contact-point velocity, the margin :math:`n - s f` of the friction cone) is, with
``t`` the time since the start of the segment,

.. math::

    g(t) = p_0 + p_1 t + A\cos t + B\sin t + D h_1(t) + E h_2(t)
           + G\,C(t) + H\,S(t) + K e^{-rt}.

* :math:`h_1, h_2` span the free motion of the phase's oscillator
  :math:`u'' + 2\sigma u' + \omega_0^2 u = 0` (docs/damping.md), chosen by its
  *mode* (:func:`make_mode`): ``OSC`` (under-damped, undamped included)
  :math:`e^{-\sigma t}\cos\omega_d t,\ e^{-\sigma t}\sin(\omega_d t)/\omega_d`;
  ``NEAR`` (critical or nearly) the same with :math:`\cosh, \sinh`, which stay
  regular through :math:`\omega_d = 0`; ``EXP`` (over-damped, well separated)
  :math:`e^{\lambda_1 t},\ e^{\lambda_2 t}`, so that a fast decay and a slow one
  are bounded separately.  In ``OSC``/``NEAR``, :math:`h_2` is the impulse response.
* :math:`C, S` are the responses to :math:`\cos t` and :math:`\sin t` from rest
  (the drive of the slip phase).  Near resonance (:math:`|\omega_0^2 - 1 + 2i\sigma|`
  small) they are written as divided differences of exponentials, exact through
  the undamped resonance :math:`\omega_0 = 1` where :math:`C \to t\sin t/2`.
* :math:`e^{-rt}` is the relaxation of a viscoelastic contact in slip and flight
  (``r = 1/eta_c``).

The basis is closed under differentiation (:math:`S' = C`,
:math:`C' = -S + \text{impulse response}`), so derivatives are coefficient maps, and
bounds on any interval :math:`[t_a, t_b]` follow from coefficient sizes and the
decay rates (:func:`bound_parts`).  Coefficient tuples are
``(p0, p1, A, B, D, E, G, H, K)``; a mode is ``(kind, sigma, w2, q, lam1, lam2, r,
w0sq)`` with ``w2 = w0sq - sigma^2`` and ``q = sqrt(|w2|)``.
"""

import math

from .jit import jit, jit_inline

OSC = 0.0  # e^{-sig t} cos(q t), e^{-sig t} sin(q t)/q
NEAR = 1.0  # e^{-sig t} cosh(q t), e^{-sig t} sinh(q t)/q (q may be 0)
EXP = 2.0  # e^{lam1 t}, e^{lam2 t}
SEPARATED = 0.5  # over-damped modes with q >= SEPARATED sigma use EXP
RESONANT_BAND = 0.25  # |w0^2 - 1 + 2 i sig| below which C, S use divided differences
FAST = 4.0  # oscillations or decays faster than this are bounded by their envelope


@jit
def make_mode(w0sq, sig, r):
    """The free motions of ``u'' + 2 sig u' + w0sq u = 0`` and the relaxation rate ``r``."""
    w0 = math.sqrt(w0sq)
    w2 = (w0 - sig) * (w0 + sig)
    if w2 > 0.0:
        return (OSC, sig, w2, math.sqrt(w2), 0.0, 0.0, r, w0sq)
    q = math.sqrt(-w2)
    if q < SEPARATED * sig:
        return (NEAR, sig, w2, q, 0.0, 0.0, r, w0sq)
    lam2 = -(sig + q)
    return (EXP, sig, w2, q, w0sq / lam2, lam2, r, w0sq)  # lam1 lam2 = w0sq


@jit
def initial_pair(m, v0, d0):
    """``(D, E)`` of the free motion with value ``v0`` and derivative ``d0`` at ``t = 0``."""
    if m[0] == EXP:
        d = m[4] - m[5]
        return (d0 - m[5] * v0) / d, (m[4] * v0 - d0) / d
    return v0, d0 + m[1] * v0


@jit
def homogeneous(m, t):
    """``(h1(t), h2(t))``."""
    if m[0] == EXP:
        return math.exp(m[4] * t), math.exp(m[5] * t)
    sig, q = m[1], m[3]
    es = math.exp(-sig * t) if sig != 0.0 else 1.0
    if m[0] == OSC:
        return es * math.cos(q * t), es * math.sin(q * t) / q
    if q == 0.0:
        return es, es * t
    e1 = math.exp(-(sig - q) * t)
    em = math.expm1(-2.0 * q * t)
    return 0.5 * e1 * (2.0 + em), -0.5 * e1 * em / q


@jit
def _em1(z, t):
    """``(e^{z t} - 1)/z`` without cancellation (``Re z <= 0``); ``t`` at ``z = 0``."""
    x = z.real * t
    y = z.imag * t
    if x == 0.0 and y == 0.0:
        return complex(t, 0.0)
    ex = math.expm1(x)
    s = math.sin(0.5 * y)
    return complex(ex * math.cos(y) - 2.0 * s * s, (ex + 1.0) * math.sin(y)) / z


@jit
def resonant(m, t, ct, st, h1, h2):
    """``(C(t), S(t))``: responses to ``cos t``, ``sin t`` from rest, at every damping."""
    sig = m[1]
    pr = m[7] - 1.0
    pi = 2.0 * sig
    p2 = pr * pr + pi * pi
    if p2 > RESONANT_BAND * RESONANT_BAND:
        # (e^{it} + homogeneous part) / P, in real arithmetic
        if m[0] == EXP:
            l1, l2 = m[4], m[5]
            d = l1 - l2
            nr = ct + (l2 * h1 - l1 * h2) / d
            ni = st + (h2 - h1) / d
        else:
            nr = ct - h1 - sig * h2
            ni = st - h2
        if pi == 0.0:
            return nr / pr, ni / pr
        return (nr * pr + ni * pi) / p2, (ni * pr - nr * pi) / p2
    # near the resonance (then under-damped with q ~ 1): divided differences
    q = m[3]
    u = complex(ct, st) * (_em1(complex(-sig, q - 1.0), t) - _em1(complex(-sig, -q - 1.0), t))
    u = u / complex(0.0, 2.0 * q)
    return u.real, u.imag


@jit
def basis_values(m, t, with_cs, with_exp):
    """The nine basis functions at ``t`` (``C = S = 0`` unless ``with_cs``, the
    relaxation 0 unless ``with_exp``).  At ``t = 0`` (a search from the segment start)
    they are exact without a transcendental: ``C(0) = S(0) = 0``, ``h2(0) = 1`` in ``EXP``.
    """
    if t == 0.0:
        return (1.0, 0.0, 1.0, 0.0, 1.0, 1.0 if m[0] == EXP else 0.0, 0.0, 0.0,
                1.0 if with_exp else 0.0)
    ct = math.cos(t)
    st = math.sin(t)
    h1, h2 = homogeneous(m, t)
    cc = 0.0
    ss = 0.0
    if with_cs:
        cc, ss = resonant(m, t, ct, st, h1, h2)
    ex = math.exp(-m[6] * t) if with_exp else 0.0
    return (1.0, t, ct, st, h1, h2, cc, ss, ex)


@jit
def dot(c, b):
    return (c[0] * b[0] + c[1] * b[1] + c[2] * b[2] + c[3] * b[3] + c[4] * b[4]
            + c[5] * b[5] + c[6] * b[6] + c[7] * b[7] + c[8] * b[8])


@jit
def has_cs(c):
    return c[6] != 0.0 or c[7] != 0.0


@jit
def evaluate(c, m, t):
    """Value of the coefficient tuple ``c`` at local time ``t``."""
    return dot(c, basis_values(m, t, has_cs(c), c[8] != 0.0))


@jit
def value_at_zero(c, m):
    """``g(0)``: ``h1(0) = 1``; ``h2(0)`` is 1 in ``EXP``, else 0; ``C(0) = S(0) = 0``."""
    v = c[0] + c[2] + c[4] + c[8]
    return v + c[5] if m[0] == EXP else v


@jit
def derivative(c, m):
    """Coefficients of ``g'`` (the basis is closed under d/dt)."""
    if m[0] == EXP:
        d = m[4] - m[5]  # the impulse response is (h1 - h2)/d
        return (c[1], 0.0, c[3], -c[2], m[4] * c[4] + c[6] / d, m[5] * c[5] - c[6] / d,
                c[7], -c[6], -m[6] * c[8])
    sig, w2 = m[1], m[2]
    return (c[1], 0.0, c[3], -c[2], -sig * c[4] + c[5], -w2 * c[4] - sig * c[5] + c[6],
            c[7], -c[6], -m[6] * c[8])


@jit
def add(c, d):
    return (c[0] + d[0], c[1] + d[1], c[2] + d[2], c[3] + d[3], c[4] + d[4],
            c[5] + d[5], c[6] + d[6], c[7] + d[7], c[8] + d[8])


@jit
def scale(c, k):
    return (c[0] * k, c[1] * k, c[2] * k, c[3] * k, c[4] * k, c[5] * k, c[6] * k,
            c[7] * k, c[8] * k)


@jit
def _u_bound(m, t):
    """Upper bound of ``|C + i S|`` on ``[0, t]`` (impulse response ``|g(s)| <= s``)."""
    b = 0.5 * t * t
    p = math.hypot(m[7] - 1.0, 2.0 * m[1])
    if m[0] == OSC:
        q = m[3]
        b = min(b, t / q)
        if p > 0.0:  # |h1 + (sig + i) h2| <= max(1, sqrt(1 + sig^2)/q)
            b = min(b, (1.0 + max(1.0, math.sqrt(1.0 + m[1] * m[1]) / q)) / p)
    elif m[0] == EXP and p > 0.0:
        d = m[4] - m[5]
        b = min(b, (1.0 + (math.hypot(m[5], 1.0) + math.hypot(m[4], 1.0)) / d) / p)
    return b


@jit
def fast_mask(m):
    """Which of ``h1``, ``h2`` and the relaxation are fast (bounded by their envelope)."""
    fe = m[6] > FAST
    if m[0] == EXP:
        return -m[4] > FAST, -m[5] > FAST, fe
    fh = m[3] > FAST or m[1] > FAST if m[0] == OSC else m[1] - m[3] > FAST
    return fh, fh, fe


@jit
def bound_parts(c, m, T, f1, f2, fe, sel):
    """A bound of ``|g|`` on ``[t_a, T]`` as ``B0 + B1 e^{-d1 t_a} + B2 e^{-d2 t_a} +
    B3 e^{-d3 t_a}``: the tuple ``(B0, B1, d1, B2, d2, B3, d3)``.

    ``sel`` 0 bounds every term, 1 only the slow ones, 2 only the fast ones (the
    masks of :func:`fast_mask`; polynomial, drive and resonant terms are slow).
    """
    b0 = b1 = b2 = b3 = 0.0
    d1 = d2 = d3 = 0.0
    if sel != 2:
        b0 = max(abs(c[0]), abs(c[0] + c[1] * T)) + math.hypot(c[2], c[3])
        if c[6] != 0.0 or c[7] != 0.0:
            b0 += math.hypot(c[6], c[7]) * _u_bound(m, T)
    D, E = c[4], c[5]
    if m[0] == EXP:
        if sel == 0 or (sel == 1) != f1:
            b1, d1 = abs(D), -m[4]
        if sel == 0 or (sel == 1) != f2:
            b2, d2 = abs(E), -m[5]
    elif sel == 0 or (sel == 1) != f1:
        if m[0] == OSC:
            b1, d1 = min(math.hypot(D, E / m[3]), abs(D) + abs(E) * T), m[1]
        else:
            b1, d1 = abs(D) + abs(E) * T, m[1] - m[3]
    if c[8] != 0.0 and (sel == 0 or (sel == 1) != fe):
        b3, d3 = abs(c[8]), m[6]
    return (b0, b1, d1, b2, d2, b3, d3)


@jit
def bound_at(p, ta):
    """Evaluate the bound of :func:`bound_parts` at the interval start ``ta``."""
    b = p[0]
    if p[1] != 0.0:
        b += p[1] if p[2] == 0.0 or ta == 0.0 else p[1] * math.exp(-p[2] * ta)
    if p[3] != 0.0:
        b += p[3] if p[4] == 0.0 or ta == 0.0 else p[3] * math.exp(-p[4] * ta)
    if p[5] != 0.0:
        b += p[5] if p[6] == 0.0 or ta == 0.0 else p[5] * math.exp(-p[6] * ta)
    return b * (1.0 + 1e-12)


@jit
def sup_bound(c, m, T):
    """Upper bound of ``|g|`` on ``[0, T]``."""
    return bound_at(bound_parts(c, m, T, False, False, False, 0), 0.0)


@jit_inline
def homogeneous_integrals(m, t, h1, h2):
    """``(A, B, d)``: the integrals of ``h1``, ``h2`` over ``[0, t]`` are ``A/d``, ``B/d``
    (``h1``, ``h2`` their values at ``t``, used outside ``EXP``).
    """
    if m[0] == EXP:
        return math.expm1(m[4] * t) / m[4], math.expm1(m[5] * t) / m[5], 1.0
    sig = m[1]
    return sig * (1.0 - h1) + m[2] * h2, 1.0 - h1 - sig * h2, m[7]


@jit_inline
def _integral(c, m, t, ct, st, h1, h2, cc, ss):
    """:func:`integral` from the basis values at ``t`` (``h1``, ``h2`` needed outside ``EXP``
    where ``g`` has free-motion or resonant terms, ``cc``, ``ss`` where it has resonant ones).
    """
    v = c[0] * t + 0.5 * c[1] * t * t + c[2] * st + c[3] * (1.0 - ct)
    cs = c[6] != 0.0 or c[7] != 0.0
    if c[4] != 0.0 or c[5] != 0.0 or cs:
        A, B, d = homogeneous_integrals(m, t, h1, h2)
        v += (c[4] * A + c[5] * B) / d
        # the impulse response is (h1 - h2)/(lam1 - lam2) in EXP, else h2
        ii = (A - B) / (m[4] - m[5]) if m[0] == EXP else B / d
        if cs:
            v += c[6] * ss + c[7] * (ii - cc)
    if c[8] != 0.0:
        v -= c[8] * math.expm1(-m[6] * t) / m[6]
    return v


@jit
def integral(c, m, t):
    """Integral of ``g`` over ``[0, t]``.

    ``C, S`` integrate through their own equations: ``S' = C`` and ``S'' = -S + g_i``
    (``g_i`` the impulse response, ``S(0) = S'(0) = 0``), so ``int C = S`` and
    ``int S = int g_i - C``.
    """
    ct = math.cos(t)
    st = math.sin(t)
    cs = has_cs(c)
    h1 = h2 = cc = ss = 0.0
    if cs or (m[0] != EXP and (c[4] != 0.0 or c[5] != 0.0)):
        h1, h2 = homogeneous(m, t)
    if cs:
        cc, ss = resonant(m, t, ct, st, h1, h2)
    return _integral(c, m, t, ct, st, h1, h2, cc, ss)


@jit
def integral_basis(c, m, t, bv):
    """:func:`integral` with the basis values ``bv`` at ``t`` known (:func:`basis_values`,
    with ``C, S`` where ``c`` has resonant terms): no transcendental evaluated again.
    """
    return _integral(c, m, t, bv[2], bv[3], bv[4], bv[5], bv[6], bv[7])


@jit
def magnitude(c):
    """A scale for round-off tolerances: the sum of coefficient sizes."""
    return (abs(c[0]) + abs(c[2]) + abs(c[3]) + abs(c[4]) + abs(c[5])
            + abs(c[6]) + abs(c[7]) + abs(c[8]) + 1e-300)
