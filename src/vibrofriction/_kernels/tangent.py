r"""Exact derivatives of the period map: variational equations and saltation matrices.

Every phase is a linear ODE (:mod:`.phases`), so a perturbation ``dz = (dy, dx', de)``
of the state at a fixed time obeys the *homogeneous* equations of the phase: its flow
over a segment of length ``t`` is a closed form (:func:`segment_flow`), built from the
free motions of :mod:`.basis`:

* slip and flight: ``(dy, dy')`` moves as the free oscillator ``u'' + gamma u' +
  alpha u = 0``; ``de`` relaxes as ``e^{-t/eta_c}`` (viscoelastic contact) or is 0
  (elastic contact in slip, where ``e = s n/k`` does not depend on the state; flight);
* stick (finite contact): ``de`` moves as ``u'' + (gamma + c) u' + beta u =
  alpha (de_0 - dy_0)``, ``dx' = de'``, ``dy = dy_0 + de - de_0``; rigid contact:
  ``dy = dy_0``, ``dx' = de = 0``.

At an event ``g(z, tau) = 0`` that ends a phase, the event time moves by
``dt = -grad g . dz / g'`` and the perturbation jumps by the saltation matrix
``S = I + (F_+ - F_-) grad g^T / g'`` (``F_-``, ``F_+`` the time derivatives of the
state before and after, ``g' = grad g . F_- + dg/dtau``; every projection of
:mod:`.integrate` is the identity on its event surface).  Lift-off, touch-down and the
section are at fixed drive phases: no time shift; lift-off of an elastic contact resets
``e`` to 0.  The product over one period is the monodromy matrix, the exact Jacobian of
the period map (docs/solver.md, "Exact derivatives").

The integral of ``f`` over the period (eq. 25) has an exact gradient too: ``f`` depends
on the state only in stick (``k e + c x'``, rigid ``-alpha y + gamma V``), and jumps
at an event contribute ``(f_- - f_+) dt``; the integral of ``n`` does not depend on the
state (contact begins and ends at fixed phases).
"""

import math

import numpy as np

from .basis import EXP, homogeneous, homogeneous_integrals
from .codes import EV_LIFTOFF, EV_REVERSAL, EV_SLIP_TO_STICK, EV_STICK_TO_SLIP, FLIGHT, STICK
from .integrate import TWO_PI, contact_force, free_approach, next_boundary, segment, slip_sign
from .jit import jit
from .period import (
    C_DEGENERATE,
    C_EVENTS,
    accumulate,
    elapsed,
    stop_integration,
)
from .phases import (
    M_A,
    M_ALPHA,
    M_BETA,
    M_C,
    M_GAMMA,
    M_K,
    M_OFF,
    M_ON,
    M_R,
    M_SLIP,
    M_SR,
    M_STICK,
    M_V,
    forced,
    inplane_force,
)


@jit
def free_flow(m, h1, h2):
    """``(p11, p12, p21, p22)``: ``(u(t), u'(t))`` from ``(u(0), u'(0))`` for the free
    motion of mode ``m`` (:func:`.basis.make_mode`), from ``(h1, h2)`` at ``t``
    (:func:`.basis.homogeneous`).
    """
    if m[0] == EXP:
        l1, l2 = m[4], m[5]
        d = l1 - l2
        return (l1 * h2 - l2 * h1) / d, (h1 - h2) / d, l1 * l2 * (h2 - h1) / d, \
            (l1 * h1 - l2 * h2) / d
    sig = m[1]
    return h1 + sig * h2, h2, -m[7] * h2, h1 - sig * h2


@jit
def free_flow_integral(m, t, h1, h2):
    """``(q11, q12)``: the integrals over ``[0, t]`` of ``p11``, ``p12`` of :func:`free_flow`
    (``h1``, ``h2`` at ``t`` as there).
    """
    A, B, d = homogeneous_integrals(m, t, h1, h2)
    i1 = A / d
    i2 = B / d
    if m[0] == EXP:
        l1, l2 = m[4], m[5]
        d = l1 - l2
        return (l1 * i2 - l2 * i1) / d, (i1 - i2) / d
    return i1 + m[1] * i2, i2


@jit
def segment_flow(M, phase, free, t, J, G):
    """Carry the Jacobian ``J`` (3 x n) over a segment of length ``t`` in ``phase``
    (``free``: the Zeno approach, moving as in flight), and add to ``G`` (length n) the
    gradient of the integral of ``f`` over it.
    """
    n = J.shape[1]
    if phase == STICK and not free:
        if math.isinf(M[M_K]):
            t_alpha = -M[M_ALPHA] * t  # f = -alpha y + gamma V, y = y0 - V t
            for j in range(n):
                G[j] += t_alpha * J[0, j]
                J[1, j] = 0.0
                J[2, j] = 0.0
            return
        m = M[M_STICK]
        h1, h2 = homogeneous(m, t)
        p11, p12, p21, p22 = free_flow(m, h1, h2)
        q11, q12 = free_flow_integral(m, t, h1, h2)
        w = M[M_ALPHA] / M[M_BETA]
        k, c = M[M_K], M[M_C]
        for j in range(n):
            dy, dxd, de = J[0, j], J[1, j], J[2, j]
            dp = w * (de - dy)  # the constant part of the stick equation
            u = de - dp
            de1 = dp + p11 * u + p12 * dxd
            J[0, j] = dy + de1 - de
            J[1, j] = p21 * u + p22 * dxd
            J[2, j] = de1
            G[j] += k * (dp * t + q11 * u + q12 * dxd) + c * (de1 - de)
        return
    m = M[M_SLIP]
    h1, h2 = homogeneous(m, t)
    p11, p12, p21, p22 = free_flow(m, h1, h2)
    decay = math.exp(-M[M_R] * t) if M[M_C] > 0.0 else 0.0
    for j in range(n):
        dy, dxd = J[0, j], J[1, j]
        J[0, j] = p11 * dy + p12 * dxd
        J[1, j] = p21 * dy + p22 * dxd
        J[2, j] = decay * J[2, j]


@jit
def vector_field(M, phase, tau, y, xd, e):
    """``(y', x'', e')`` of the motion in ``phase`` at drive phase ``tau`` (``x''`` with the
    in-plane force ``h``).
    """
    V = M[M_V]
    drag = -M[M_ALPHA] * y - M[M_GAMMA] * (xd - V)
    if forced(M):
        drag += inplane_force(M, tau)[0]
    rigid = math.isinf(M[M_K])
    if phase == STICK:
        if rigid:
            return -V, 0.0, 0.0
        return xd - V, drag - (M[M_K] * e + M[M_C] * xd), xd
    if phase == FLIGHT:
        return xd - V, drag, (-M[M_R] * e if M[M_C] > 0.0 else 0.0)
    s = slip_sign(phase)
    a = M[M_A]
    n = 1.0 + a * math.cos(tau)
    if rigid:
        ed = 0.0
    elif M[M_C] > 0.0:
        ed = M[M_R] * (s * n / M[M_K] - e)
    else:
        ed = -s * a * math.sin(tau) / M[M_K]
    return xd - V, drag - s * n, ed


@jit
def event_gradient(M, phase, tau, y, xd, e):
    """``(grad g, dg/dtau)`` of the event that ends ``phase`` at ``(tau, y, x', e)``:
    the cone margin ``s_r n - s f`` of stick (``s`` the sign of ``f`` there) or the
    contact point's slip velocity ``s (x' - e')`` of slip.  A rigid stick's force
    ``-alpha y + gamma V + h`` depends on ``tau`` through the in-plane force ``h``.
    """
    a, k = M[M_A], M[M_K]
    rigid = math.isinf(k)
    if phase == STICK:
        f = contact_force(M, STICK, tau, y, xd, e)
        s = 1.0 if f >= 0.0 else -1.0
        g_t = -M[M_SR] * a * math.sin(tau)
        if rigid:
            if forced(M):
                g_t -= s * inplane_force(M, tau)[1]
            return s * M[M_ALPHA], 0.0, 0.0, g_t
        return 0.0, -s * M[M_C], -s * k, g_t
    s = slip_sign(phase)
    if rigid:
        return 0.0, s, 0.0, 0.0
    if M[M_C] > 0.0:
        return 0.0, s, s * M[M_R], M[M_R] * a * math.sin(tau) / k
    return 0.0, s, 0.0, a * math.cos(tau) / k


@jit
def saltation(M, ph0, ph1, tau, y, xd, e, J, G):
    """Apply the saltation matrix of the event ``ph0 -> ph1`` at ``(tau, y, x', e)`` to
    ``J``, and the force jump times the event's time shift to ``G``.  Returns False
    where the event is tangential (``g' = 0``: the map is not differentiable there).
    """
    g0, g1, g2, g_t = event_gradient(M, ph0, tau, y, xd, e)
    a0, a1, a2 = vector_field(M, ph0, tau, y, xd, e)
    b0, b1, b2 = vector_field(M, ph1, tau, y, xd, e)
    rate = g0 * a0 + g1 * a1 + g2 * a2 + g_t
    if rate == 0.0 or not math.isfinite(rate):
        return False
    jump = contact_force(M, ph0, tau, y, xd, e) - contact_force(M, ph1, tau, y, xd, e)
    for j in range(J.shape[1]):
        dt = -(g0 * J[0, j] + g1 * J[1, j] + g2 * J[2, j]) / rate
        J[0, j] -= (b0 - a0) * dt
        J[1, j] -= (b1 - a1) * dt
        J[2, j] -= (b2 - a2) * dt
        G[j] += jump * dt
    return True


@jit
def jump_saltation(M, ph1, tau, y, xd, e, J, G):
    """The saltation of stick -> slip of an elastic contact where ``s_r > 1`` (the jump).

    The event ``g = s_r n - s k e = 0`` resets the elongation, ``e_+ = R(tau) = s n(tau)/k``
    (the contact point jumps; ``e_- = s_r e_+``), so the perturbation after it, at a fixed
    time, is ``dz_+ = R_z dz_- + (R_z F_- + R_tau - F_+) dt`` with ``dt = -grad g . dz_-/g'``
    and ``R_z = diag(1, 1, 0)``: ``y`` and ``x'`` get ``(F_- - F_+) dt`` as at any event, ``e``
    forgets its perturbation and gets ``(R' - e'_+) dt`` (0 into slip, where ``e'_+ = R'``;
    into stick, the jump that ends at once, ``R' - x'``).  ``f`` drops from ``s s_r n`` to
    ``f_+``: ``G`` gets the jump times ``dt``.  ``(y, x', e)`` is the state after the jump.
    Returns False where the event is tangential.
    """
    sr = M[M_SR]
    eb = sr * e  # the elongation before the jump
    g0, g1, g2, g_t = event_gradient(M, STICK, tau, y, xd, eb)
    a0, a1, a2 = vector_field(M, STICK, tau, y, xd, eb)
    b0, b1, b2 = vector_field(M, ph1, tau, y, xd, e)
    rate = g0 * a0 + g1 * a1 + g2 * a2 + g_t
    if rate == 0.0 or not math.isfinite(rate):
        return False
    s = 1.0 if e >= 0.0 else -1.0
    r_t = -s * M[M_A] * math.sin(tau) / M[M_K]  # R'(tau)
    jump = M[M_K] * eb - contact_force(M, ph1, tau, y, xd, e)
    for j in range(J.shape[1]):
        dt = -(g0 * J[0, j] + g1 * J[1, j] + g2 * J[2, j]) / rate
        J[0, j] -= (b0 - a0) * dt
        J[1, j] -= (b1 - a1) * dt
        J[2, j] = (r_t - b2) * dt
        G[j] += jump * dt
    return True


@jit
def advance_period_tangent(z, acc, count, M, max_events, J, G):
    """:func:`.period.advance_period` carrying the Jacobian ``J`` of the state and the
    gradient ``G`` of the integral of ``f`` with respect to the start (multiplied onto
    what they hold).  Returns ``(ok, smooth)``: ``smooth`` False where an event was
    tangential, so that the derivatives do not exist.
    """
    theta = 0.0
    y, xd, e, ph, ed = z[0], z[1], z[2], int(z[3]), z[4]
    a = M[M_A]
    smooth = True
    while theta < TWO_PI:
        _, bkind = next_boundary(theta, a, M[M_OFF], M[M_ON])
        free = free_approach(theta, ph, a, bkind)
        t, theta, y, xd, e, ed, f, ph1, ev, i_f, i_n, ok = segment(theta, y, xd, e, ed, ph, M)
        segment_flow(M, ph, free, t, J, G)
        if ev == EV_STICK_TO_SLIP and M[M_SR] > 1.0 and M[M_C] == 0.0 \
                and not math.isinf(M[M_K]):
            if not free:
                smooth &= jump_saltation(M, ph1, theta, y, xd, e, J, G)
        elif ev == EV_STICK_TO_SLIP or ev == EV_SLIP_TO_STICK or ev == EV_REVERSAL:
            if not free:
                smooth &= saltation(M, ph, ph1, theta, y, xd, e, J, G)
        elif ev == EV_LIFTOFF and M[M_C] == 0.0:
            J[2, :] = 0.0  # an elastic contact unloads: e = 0 in flight
        accumulate(acc, count, ph, t, ev, ok, i_f, i_n)
        ph = ph1
        if stop_integration(count, max_events):
            return False, smooth
    z[0], z[1], z[2], z[3], z[4] = y, xd, e, ph, ed
    return True, smooth


@jit
def period_map_tangent(y, xd, e, ph, p, M, max_events, J, G, acc):
    """:func:`.period.period_map` with the exact Jacobian ``J`` (3 x 3) of the section
    state after ``p`` periods with respect to ``(y, x', e)``, the gradient ``G`` of the
    integral of ``f`` over them, and their accumulators in ``acc``.

    Returns ``(y, x', e, phase, events, degenerate, work, smooth)`` as
    :func:`.period.period_map` (``degenerate`` -1: the integration did not finish), and
    ``smooth`` False where the derivatives do not exist (a tangential event).
    """
    z = np.array([y, xd, e, float(ph), math.nan])
    acc[:] = 0.0
    count = np.zeros(3, np.int64)
    J[:, :] = 0.0
    for i in range(3):
        J[i, i] = 1.0
    G[:] = 0.0
    smooth = True
    for _ in range(p):
        ok, sm = advance_period_tangent(z, acc, count, M, max_events, J, G)
        smooth &= sm
        if not ok:
            return z[0], z[1], z[2], int(z[3]), count[C_EVENTS], -1, elapsed(acc), False
    return (z[0], z[1], z[2], int(z[3]), count[C_EVENTS], count[C_DEGENERATE], float(p),
            smooth)


__all__ = ["advance_period_tangent", "period_map_tangent", "segment_flow"]
