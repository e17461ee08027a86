r"""Proofs of continuous forward sliding: ``mu/mu0 = 1`` exactly (eqs. 7-12).

:func:`sliding_orbit` is the periodic solution of forward slip (and flight);
:func:`sliding_certificate` proves from a section state that the contact point
never stops again; :func:`orbit_slides` proves the long-time average from any start
where the sliding orbit's own contact point never stops, :func:`unmodulated_sliding`
for ``a = 0``.
"""

import math

from .basis import derivative, evaluate, sup_bound
from .codes import SLIP_POS
from .integrate import TWO_PI
from .jit import jit
from .phases import (
    M_A,
    M_ALPHA,
    M_C,
    M_K,
    M_OFF,
    M_ON,
    M_R,
    M_SLIP,
    M_V,
    body,
    elongation,
    forced,
    slip_velocity,
)
from .roots import first_root, start_margin


@jit
def _slip_arcs(a, th_off, th_on):
    """The arcs of one period in contact: ``[0, 2 pi]``, or both sides of the flight."""
    if a > 1.0:
        return 2, 0.0, th_off, th_on, TWO_PI
    return 1, 0.0, TWO_PI, TWO_PI, TWO_PI


@jit
def _free_arc(M, theta, T, y, yd, e, s):
    """``(y, y', e)`` after ``T`` of forward slip (``s = 1``) or flight (``s = 0``)."""
    m = M[M_SLIP]
    c = body(M, theta, y, yd, s)
    ce = elongation(M, theta, e, math.nan, s)
    return evaluate(c, m, T), evaluate(derivative(c, m), m, T), evaluate(ce, m, T)


@jit
def _slip_flight_period(M, y, yd, e):
    """``(y, y', e)`` after one period of forward slip in contact and flight out of it.

    ``y'' + gamma y' + alpha y = -n(tau)``, ``n = max(0, 1 + a cos tau)``: the motion
    of a body whose contact point never stops (``f = n``), closed form arc by arc.
    """
    narcs, t0, t1, t2, t3 = _slip_arcs(M[M_A], M[M_OFF], M[M_ON])
    y, yd, e = _free_arc(M, t0, t1 - t0, y, yd, e, 1.0)
    if narcs == 2:
        y, yd, e = _free_arc(M, t1, t2 - t1, y, yd, e, 0.0)
        y, yd, e = _free_arc(M, t2, t3 - t2, y, yd, e, 1.0)
    return y, yd, e


@jit
def sliding_orbit(M):
    """The periodic solution of forward slip (and flight): ``(ok, y*, y*', e*)`` at ``tau = 0``.

    Forward slip is linear, so its period map is affine, ``z -> R z + b`` with ``R``
    the free motion at ``sqrt(alpha)`` (decaying with the pin's damping) and ``e``
    relaxing on its own; the fixed point solves ``(I - R) z = b``.  The in-plane force
    ``h`` (:func:`.phases.inplane_forcing`) is part of the forcing of both slip and
    flight, so the orbit carries its periodic response.  Not ok where the undamped
    ``sqrt(alpha)`` is (nearly) an integer (a harmonic of ``n`` resonates and no bounded
    sliding solution exists) or without any oscillation (``a = 0``, ``h = 0``).
    """
    a = M[M_A]
    if a == 0.0 and not forced(M):
        return False, 0.0, 0.0, 0.0
    b0, b1, be = _slip_flight_period(M, 0.0, 0.0, 0.0)
    r00, r10, _ = _slip_flight_period(M, 1.0, 0.0, 0.0)
    r01, r11, _ = _slip_flight_period(M, 0.0, 1.0, 0.0)
    m00, m01 = 1.0 - (r00 - b0), -(r01 - b0)
    m10, m11 = -(r10 - b1), 1.0 - (r11 - b1)
    det = m00 * m11 - m01 * m10  # = 2 - 2 cos(2 pi sqrt(alpha)) undamped
    if not abs(det) > 1e-6:
        return False, 0.0, 0.0, 0.0
    es = 0.0
    if M[M_C] > 0.0:
        es = be / -math.expm1(-TWO_PI * M[M_R])  # e -> e^{-2 pi r} e + be
    return True, (m11 * b0 - m01 * b1) / det, (m00 * b1 - m10 * b0) / det, es


@jit
def sliding_certificate(y, xd, e, ph, M, orbit_ok, ys, yds, es):
    """Is continuous forward sliding proven from this section state (eqs. 7-12)?

    Without stick the motion is the sliding orbit ``(ys, yds, es)`` of
    :func:`sliding_orbit` plus a free motion of the body, whose energy
    ``(z'^2 + alpha z^2)/2`` slip and flight never increase, and a relaxation of
    ``e`` that only decays.  The contact point keeps sliding forward, and at every
    touch-down starts sliding again rather than sticking, as long as its velocity on
    the orbit, ``V + y*' - e*'``, exceeds the bound ``A + r |e - e*|`` of those on
    every arc in contact.  That is checked with the event root finder (which never
    misses a zero); then ``f = n`` for ever and ``mu/mu0 = 1`` exactly.  For
    ``a <= 1`` the minimum of the orbit's contact velocity is ``V - V_c``
    (eq. 12 generalised, docs/damping.md), the classic condition.
    """
    if ph != SLIP_POS or not orbit_ok:
        return False
    alpha, V = M[M_ALPHA], M[M_V]
    m = M[M_SLIP]
    amp = math.sqrt((xd - V - yds) ** 2 + alpha * (y - ys) ** 2) + M[M_R] * abs(e - es)
    margin = amp * (1.0 + 1e-9) + 1e-9 * (1.0 + V)
    narcs, t0, t1, t2, t3 = _slip_arcs(M[M_A], M[M_OFF], M[M_ON])
    y0, yd0, e0 = ys, yds, es
    for i in range(narcs):
        theta, T = (t0, t1 - t0) if i == 0 else (t2, t3 - t2)
        if i == 1:  # through the flight
            y0, yd0, e0 = _free_arc(M, t1, t2 - t1, y0, yd0, e0, 0.0)
        c = body(M, theta, y0, yd0, 1.0)
        ce = elongation(M, theta, e0, math.nan, 1.0)
        g = slip_velocity(M, c, ce, 1.0)
        if margin >= sup_bound(g, m, T):
            return False  # cannot hold: skip the root search
        g = (g[0] - margin, g[1], g[2], g[3], g[4], g[5], g[6], g[7], g[8])
        ok, ts = start_margin(g, m, T)
        if not ok or first_root(g, m, ts, T) >= 0.0:
            return False
        y0, yd0, e0 = evaluate(c, m, T), evaluate(derivative(c, m), m, T), evaluate(ce, m, T)
    return True


@jit
def unmodulated_sliding(y, xd, e, M):
    r"""Without oscillation (``a = 0``) the long-time average is ``mu/mu0 = 1`` from any start.

    With ``n = 1`` the energy about steady sliding,
    ``E = (y'^2 + alpha (y + 1/alpha)^2 + k (e - 1/k)^2)/2`` (no ``e`` term for a rigid
    contact), obeys ``E' = -gamma y'^2 - c e'^2 - (1 - f)(V - v_c)`` with ``v_c`` the
    contact-point velocity: ``v_c = 0`` and ``f <= 1`` in stick, ``f = 1`` in forward
    slip, ``f = -1`` and ``v_c < 0`` in reverse slip.  So ``E`` never increases (the
    motion is bounded) and ``V * integral(1 - f) <= E(0)``: the mean of ``f`` over the
    first ``tau`` is within ``E(0)/(V tau)`` of 1, and ``<f>/<n> = 1`` exactly (eq. 25).

    Returns ``E(0)`` and the steady sliding state ``(y, x', e)`` the motion approaches
    (around which an undamped one keeps its free oscillation).
    """
    alpha, V, k = M[M_ALPHA], M[M_V], M[M_K]
    es = 0.0 if math.isinf(k) else 1.0 / k
    energy = 0.5 * ((xd - V) ** 2 + alpha * (y + 1.0 / alpha) ** 2)
    if not math.isinf(k):
        energy += 0.5 * k * (e - es) ** 2
    return energy, -1.0 / alpha, V, es


@jit
def orbit_slides(M, orbit_ok, ys, yds, es):
    r"""Where the sliding orbit's contact point never stops, ``mu/mu0 = 1`` from any start.

    Let ``delta = x - x_o`` be the motion's distance from the sliding orbit ``x_o``
    (:func:`sliding_orbit`, ``f_o = n``) and ``delta_e = e - e_o``.  Both obey the body
    equation, so ``E = (delta'^2 + alpha delta^2 + k delta_e^2)/2`` (no ``e`` term for a
    rigid contact) has ``E' = -gamma delta'^2 - c delta_e'^2 - (n - f)(v_o - v_c)`` with
    ``v_c``, ``v_o`` the contact-point velocities of the motion and of the orbit
    (``f - n = k delta_e + c delta_e'`` in contact; in flight ``f = n = 0``, and an elastic
    contact's ``e`` is reset to 0 at lift-off in both).  ``n - f >= 0`` always, and
    ``v_c = 0`` in stick, ``f = n`` in forward slip, ``f = -n`` and ``v_c < 0`` in reverse
    slip: every term is ``<= 0``, and ``(n - f)(v_o - v_c) >= (n - f) v_min`` with
    ``v_min > 0`` the smallest contact-point velocity of the orbit in contact.  Hence
    ``v_min * integral(n - f) <= E(0)``: the mean of ``f`` over the first ``tau`` is within
    ``E(0) / (v_min tau)`` of the mean of ``n``, and ``<f>/<n> = 1`` exactly (eq. 25),
    whatever the stability of the orbit and however the motion sticks on its way.
    The in-plane force ``h`` (issue 20) acts alike on the motion and on the orbit (both
    are described in the substrate's frame, where ``f``, ``n``, ``e`` and the
    contact-point velocities are those above): it cancels in ``delta`` and the proof
    holds unchanged.

    ``v_min > 0`` is checked as in :func:`sliding_certificate` with no free motion (the
    orbit's contact velocity stays above ``1e-9 (1 + V)`` on every arc in contact).
    """
    if not orbit_ok:
        return False
    return sliding_certificate(ys, M[M_V] + yds, es, SLIP_POS, M, orbit_ok, ys, yds, es)
