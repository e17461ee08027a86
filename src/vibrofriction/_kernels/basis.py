r"""Event functions and phase solutions as coefficients over one fixed basis.

Every quantity of every phase (body displacement, contact force, contact-point
velocity, the margin :math:`n - s f` of the friction cone) is, with ``t`` the time
since the start of the segment and ``w`` the phase's natural frequency,

.. math::

    g(t) = p_0 + p_1 t + A\cos t + B\sin t + D\cos wt + E\sin wt + G\,C(t) + H\,S(t),

where :math:`C` and :math:`S` are the responses of :math:`u'' + w^2 u` to
:math:`\cos t` and :math:`\sin t` from rest,

.. math::

    C = \frac{\cos t - \cos wt}{w^2 - 1}, \qquad
    S = \frac{\sin t - \sin(wt)/w}{w^2 - 1}.

Written through half-sum and half-difference angles they stay exact as
:math:`w \to 1` (the resonant drive, case IV), where
:math:`C \to t\sin t/2` and :math:`S \to (\sin t - t\cos t)/2`.  The basis is
closed under differentiation (:math:`S' = C`, :math:`C' = \sin t - w^2 S`), so
derivatives are coefficient maps and bounds follow from coefficient sizes.

Coefficient tuples are ``(p0, p1, A, B, D, E, G, H)``.
"""

import math

from .jit import jit


@jit
def cs_kernels(t, w):
    """Return ``(C(t), S(t))`` accurately for every ``w > 0`` including ``w = 1``."""
    q = 0.5 * (1.0 - w) * t
    if abs(q) < 1e-4:
        sinc = 1.0 - q * q / 6.0
    else:
        sinc = math.sin(q) / q
    two_sh = t * sinc  # = 2 sin(q) / (1 - w)
    p = 0.5 * (1.0 + w) * t
    c = math.sin(p) * two_sh / (1.0 + w)
    s = -math.cos(p) * two_sh / (1.0 + w) + math.sin(w * t) / (w * (1.0 + w))
    return c, s


RESONANT_BAND = 0.25  # |w^2 - 1| below which C and S need the half-angle forms


@jit
def basis_values(w, t, with_cs):
    """The eight basis functions at ``t`` (``C = S = 0`` unless ``with_cs``)."""
    ct = math.cos(t)
    st = math.sin(t)
    cw = math.cos(w * t)
    sw = math.sin(w * t)
    cc = 0.0
    ss = 0.0
    if with_cs:
        d = w * w - 1.0
        if abs(d) > RESONANT_BAND:
            cc = (ct - cw) / d
            ss = (st - sw / w) / d
        else:
            cc, ss = cs_kernels(t, w)
    return (1.0, t, ct, st, cw, sw, cc, ss)


@jit
def dot(c, b):
    return (c[0] * b[0] + c[1] * b[1] + c[2] * b[2] + c[3] * b[3]
            + c[4] * b[4] + c[5] * b[5] + c[6] * b[6] + c[7] * b[7])


@jit
def has_cs(c):
    return c[6] != 0.0 or c[7] != 0.0


@jit
def evaluate(c, w, t):
    """Value of the coefficient tuple ``c`` at local time ``t``."""
    return dot(c, basis_values(w, t, has_cs(c)))


@jit
def value_at_zero(c):
    """``g(0)``: the basis at ``t = 0`` is ``(1, 0, 1, 0, 1, 0, 0, 0)``."""
    return c[0] + c[2] + c[4]


@jit
def derivative(c, w):
    """Coefficients of ``g'`` (the basis is closed under d/dt)."""
    return (c[1], 0.0, c[3], c[6] - c[2], c[5] * w, -c[4] * w, c[7], -c[6] * w * w)


@jit
def add(c, d):
    return (c[0] + d[0], c[1] + d[1], c[2] + d[2], c[3] + d[3],
            c[4] + d[4], c[5] + d[5], c[6] + d[6], c[7] + d[7])


@jit
def scale(c, k):
    return (c[0] * k, c[1] * k, c[2] * k, c[3] * k, c[4] * k, c[5] * k, c[6] * k, c[7] * k)


@jit
def cs_bound(w, t):
    """Upper bound of ``|C|`` and ``|S|`` on ``[0, t]`` (Duhamel and closed form)."""
    b = min(0.5 * t * t, t / w)
    d = abs(w * w - 1.0)
    if d > 0.0:
        b = min(b, (1.0 + 1.0 / w) / d)
    return b


@jit
def sup_bound(c, w, t):
    """Upper bound of ``|g|`` on ``[0, t]``."""
    b = max(abs(c[0]), abs(c[0] + c[1] * t))
    b += math.hypot(c[2], c[3]) + math.hypot(c[4], c[5])
    if c[6] != 0.0 or c[7] != 0.0:
        b += (abs(c[6]) + abs(c[7])) * cs_bound(w, t)
    return b


@jit
def integral(c, w, t):
    """Integral of ``g`` over ``[0, t]`` (requires ``H = 0``; ``S' = C``)."""
    v = c[0] * t + 0.5 * c[1] * t * t + c[2] * math.sin(t) + c[3] * (1.0 - math.cos(t))
    v += c[4] * math.sin(w * t) / w + c[5] * (1.0 - math.cos(w * t)) / w
    if c[6] != 0.0:
        v += c[6] * cs_kernels(t, w)[1]
    return v


@jit
def magnitude(c):
    """A scale for round-off tolerances: the sum of coefficient sizes."""
    return (abs(c[0]) + abs(c[2]) + abs(c[3]) + abs(c[4]) + abs(c[5])
            + abs(c[6]) + abs(c[7]) + 1e-300)
