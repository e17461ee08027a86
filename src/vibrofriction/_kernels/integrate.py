r"""Event-driven integration: exact from event to event, cut at the Poincare section.

The state on entry to a segment is ``(theta, y, x', f, phase)``: the body
displacement without the drift, ``y = x - V tau``, but the body velocity ``x'``
itself (not ``y' = x' - V``), so that a body at rest is represented exactly.  A segment ends
at the first of: the phase's event (found by :func:`.roots.first_root`), lift-off
or touch-down (``cos tau = -1/a``, known in closed form) or the section
``tau = 2 pi k``.  Every segment is therefore shorter than one drive period.
At an event the state is projected exactly onto the event surface (``f = s n``
when stick ends, contact-point velocity 0 when slip ends) and the next phase is
the first of the candidates whose event functions start positive
(:func:`enter`); this decides grazing transitions by derivatives, not by a
tolerance that could flip back and forth.
"""

import math

from .basis import derivative, evaluate, integral
from .codes import (
    EV_LIFTOFF,
    EV_NONE,
    EV_REVERSAL,
    EV_SECTION,
    EV_SLIP_TO_STICK,
    EV_STICK_TO_SLIP,
    EV_TOUCHDOWN,
    FLIGHT,
    NO_PHASE,
    SLIP_NEG,
    SLIP_POS,
    STICK,
)
from .jit import jit
from .phases import (
    cone_margin,
    free_y,
    normal_force,
    normal_integral,
    rigid_stick_force,
    slip_velocity,
    stick_force,
)
from .roots import first_root, start_margin

TWO_PI = 2.0 * math.pi
ZENO_N = 1e-10  # relative normal force below which the approach to n = 0 is free motion


@jit
def slip_sign(phase):
    return 1.0 if phase == SLIP_POS else -1.0


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
def next_boundary(theta, a, th_off, th_on):
    if a > 1.0:
        if theta < th_off:
            return th_off, EV_LIFTOFF
        if theta < th_on:
            return th_on, EV_TOUCHDOWN
    elif a == 1.0 and theta < th_on:
        return th_on, EV_TOUCHDOWN  # grazing: a touch-down of zero flight time
    return TWO_PI, EV_SECTION


@jit
def stick_coefficients(alpha, beta, V, a, theta, y, xd, f):
    """Force coefficients and their frequency in stick (rigid contact when beta = inf)."""
    if math.isinf(beta):
        return rigid_stick_force(alpha, V, y), 1.0
    return stick_force(alpha, beta, beta - alpha, math.sqrt(beta), V, y, xd, f), math.sqrt(beta)


@jit
def enter(theta, y, xd, f, s_pref, alpha, beta, a, V, T, avoid):
    """Choose the phase that starts consistently at ``theta``.

    Candidates, in order: stick (both cone margins must start positive; for a rigid
    contact also zero body velocity), slip ``s_pref``, slip ``-s_pref``.  With a
    finite contact stiffness ``f`` is continuous, so slip ``s`` is a candidate only
    when ``f = s n``.  Returns ``(phase, f, ok)``; ``ok`` is False when no candidate
    starts consistently (a degenerate point, counted by the caller).  ``avoid``
    (a phase code, or ``NO_PHASE``) is skipped: the phase that has just ended at once, whose
    margin is lost in round-off (a near-tangency), must not be re-entered.
    """
    rigid = math.isinf(beta)
    k = beta - alpha
    n = normal_force(theta, a)
    if avoid != STICK and (not rigid or xd == 0.0):
        fc, wp = stick_coefficients(alpha, beta, V, a, theta, y, xd, f)
        ok1, _ = start_margin(cone_margin(fc, theta, 1.0, a), wp, T)
        if ok1:
            ok2, _ = start_margin(cone_margin(fc, theta, -1.0, a), wp, T)
            if ok2:
                return STICK, (evaluate(fc, wp, 0.0) if rigid else f), True
    w = math.sqrt(alpha)
    tol = 1e-12 * (1.0 + abs(n))
    for i in range(2):
        s = s_pref if i == 0 else -s_pref
        if (SLIP_POS if s > 0 else SLIP_NEG) == avoid:
            continue
        if rigid or abs(f - s * n) <= tol:
            vr = slip_velocity(free_y(alpha, w, theta, y, xd - V, s, a), w, theta, s, a, V, k)
            ok, _ = start_margin(vr, w, T)
            if ok:
                return (SLIP_POS if s > 0 else SLIP_NEG), s * n, True
    # degenerate: keep what continuity allows
    if rigid or abs(f - s_pref * n) <= tol:
        return (SLIP_POS if s_pref > 0 else SLIP_NEG), s_pref * n, False
    return STICK, f, False


@jit
def state_at(phase, theta, y, xd, f, t, alpha, beta, a, V):
    """``(y, x', f)`` a time ``t`` into a phase that started at ``theta`` in ``(y, x', f)``."""
    if phase == STICK:
        if math.isinf(beta):
            y1 = y - V * t
            return y1, 0.0, -alpha * y1
        fc, wp = stick_coefficients(alpha, beta, V, a, theta, y, xd, f)
        f1 = evaluate(fc, wp, t)
        k = beta - alpha
        return y + (f1 - f) / k - V * t, evaluate(derivative(fc, wp), wp, t) / k, f1
    w = math.sqrt(alpha)
    s = 0.0 if phase == FLIGHT else slip_sign(phase)
    yc = free_y(alpha, w, theta, y, xd - V, s, a)
    return (evaluate(yc, w, t), V + evaluate(derivative(yc, w), w, t),
            s * normal_force(theta + t, a))


@jit
def segment(theta, y, xd, f, phase, alpha, beta, a, V, th_off, th_on):
    """Advance one segment.

    Returns ``(t, theta_end, y, x', f, phase, event, int_f, int_n, ok)`` where
    ``event`` is the kind of what ended the segment (a transition or a boundary),
    ``int_f`` and ``int_n`` the integrals of ``f`` and ``n`` over it and ``ok`` False
    when a transition was degenerate.
    """
    rigid = math.isinf(beta)
    k = beta - alpha
    w = math.sqrt(alpha)
    tb, bkind = next_boundary(theta, a, th_off, th_on)
    T = tb - theta
    te = -1.0
    es = 0.0
    # Zeno guard: where the cone closes (n -> 0 at lift-off or grazing) stick and slip
    # can alternate infinitely often.  Once n < ZENO_N the force |f| <= n is negligible
    # (its integral over the rest of the approach is < 1e-14): move freely to the boundary.
    zeno = (phase != FLIGHT and bkind != EV_SECTION
            and normal_force(theta, a) <= ZENO_N * (1.0 + a))
    immediate = False  # the event fired at the start offset: a round-off tangency
    if phase == STICK and not zeno:
        fc, wp = stick_coefficients(alpha, beta, V, a, theta, y, xd, f)
        for i in range(2):
            s = 1.0 if i == 0 else -1.0
            g = cone_margin(fc, theta, s, a)
            ok, ts = start_margin(g, wp, T)
            tlim = T if te < 0.0 else te
            r = first_root(g, wp, ts, tlim) if ok else 0.0
            if r >= 0.0 and (te < 0.0 or r < te):
                te = r
                es = s
                immediate = r <= ts
    elif phase != FLIGHT and not zeno:
        s = slip_sign(phase)
        yc = free_y(alpha, w, theta, y, xd - V, s, a)
        vr = slip_velocity(yc, w, theta, s, a, V, k)
        ok, ts = start_margin(vr, w, T)
        te = first_root(vr, w, ts, T) if ok else 0.0
        immediate = te >= 0.0 and te <= ts
    hit = te >= 0.0
    avoid = phase if immediate else NO_PHASE
    t = te if hit else T
    # state and integrals at the end of the piece (the Zeno approach moves freely)
    y1, xd1, f1 = state_at(FLIGHT if zeno else phase, theta, y, xd, f, t, alpha, beta, a, V)
    if zeno or phase == FLIGHT:
        int_f = 0.0
        int_n = 0.0 if phase == FLIGHT else normal_integral(theta, t, a)
    elif phase == STICK:
        fc, wp = stick_coefficients(alpha, beta, V, a, theta, y, xd, f)
        int_f = integral(fc, wp, t)
        int_n = normal_integral(theta, t, a)
    else:
        int_n = normal_integral(theta, t, a)
        int_f = slip_sign(phase) * int_n
    theta1 = tb if t == T else theta + t
    ph1 = phase
    ok = True
    event = bkind
    Tn = tb - theta1 if tb > theta1 else TWO_PI
    if hit:
        if phase == STICK:
            # stick -> slip in direction es: project onto |f| = n
            f1 = es * normal_force(theta1, a)
            ph1, f1, ok = enter(theta1, y1, xd1, f1, es, alpha, beta, a, V, Tn, avoid)
            event = EV_STICK_TO_SLIP
        else:
            s = slip_sign(phase)
            # slip -> stick: project onto zero contact-point velocity
            xd1 = 0.0 if rigid else -s * a * math.sin(theta1) / k
            ph1, f1, ok = enter(theta1, y1, xd1, f1, -s, alpha, beta, a, V, Tn, avoid)
            event = EV_SLIP_TO_STICK if ph1 == STICK else EV_REVERSAL
    if t == T and not hit:
        if bkind == EV_LIFTOFF:
            ph1 = FLIGHT
            f1 = 0.0
        elif bkind == EV_TOUCHDOWN:
            f1 = 0.0
            sp = 1.0 if xd1 >= 0.0 else -1.0
            ph1, f1, ok = enter(theta1, y1, xd1, 0.0, sp, alpha, beta, a, V, TWO_PI - theta1,
                                  NO_PHASE)
    elif t == T and hit and bkind != EV_SECTION:
        # an event exactly at lift-off / touch-down: the boundary is handled by a
        # zero-length segment next (theta1 == tb keeps it as the next boundary)
        theta1 = math.nextafter(tb, -math.inf)
    return t, theta1, y1, xd1, f1, ph1, event, int_f, int_n, ok


@jit
def initial_state(kind, alpha, beta, a, V):
    """``kind`` 0: steady sliding before the oscillation starts; 1: rest."""
    if kind == 0:
        y, xd, f = -1.0 / alpha, V, 1.0
    else:
        y, xd, f = 0.0, 0.0, 0.0
    ph, f, _ = enter(0.0, y, xd, f, 1.0, alpha, beta, a, V, TWO_PI, NO_PHASE)
    return y, xd, f, ph


@jit
def run_periods(theta, y, xd, f, phase, alpha, beta, a, V, periods, max_segments, seg):
    """Integrate ``periods`` drive periods, recording every segment start in ``seg``.

    ``seg`` has shape ``(max_segments, 9)`` with columns ``tau, y, x', f, phase,
    event that ended the previous segment, int_f, int_n`` (cumulative) and the drive
    phase ``theta`` of the segment start.  Returns
    the number of rows written (``-1`` if ``max_segments`` was too small).
    """
    th_off, th_on = liftoff_phases(a)
    k = 0
    m = 0
    cf = 0.0
    cn = 0.0
    ev = EV_NONE
    while True:
        if m >= max_segments:
            return -1
        row = (TWO_PI * k + theta, y, xd, f, float(phase), float(ev), cf, cn, theta)
        for j in range(9):
            seg[m, j] = row[j]
        m += 1
        if k >= periods:
            return m
        t, theta, y, xd, f, phase, ev, i_f, i_n, ok = segment(
            theta, y, xd, f, phase, alpha, beta, a, V, th_off, th_on)
        cf += i_f
        cn += i_n
        if theta >= TWO_PI:
            theta = 0.0
            k += 1


@jit
def sample(seg, nseg, alpha, beta, a, V, taus, out):
    """Evaluate the closed forms at sorted times ``taus`` (columns y, x', f, n, phase)."""
    j = 0
    for i in range(taus.shape[0]):
        tau = taus[i]
        while j + 1 < nseg - 1 and seg[j + 1, 0] <= tau:
            j += 1
        theta = seg[j, 8]
        t = tau - seg[j, 0]
        phase = int(seg[j, 4])
        y1, xd1, f1 = state_at(phase, theta, seg[j, 1], seg[j, 2], seg[j, 3], t,
                               alpha, beta, a, V)
        out[i, 0] = y1
        out[i, 1] = xd1
        out[i, 2] = f1
        out[i, 3] = max(0.0, normal_force(theta + t, a))
        out[i, 4] = phase


