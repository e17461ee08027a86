r"""Event-driven integration: exact from event to event, cut at the Poincare section.

The state on entry to a segment is ``(theta, y, x', e, phase)``: the body
displacement without the drift, ``y = x - V tau``, the body velocity ``x'``
itself (not ``y' = x' - V``, so that a body at rest is represented exactly) and
the elongation ``e`` of the contact spring; the force ``f`` follows from them and
the phase (:func:`contact_force`).  A segment ends
at the first of: the phase's event (found by :func:`.roots.first_root`), lift-off
or touch-down (``cos tau = -1/a``, known in closed form) or the section
``tau = 2 pi k``.  Every segment is therefore shorter than one drive period.
At an event the state is projected exactly onto the event surface (``f = s n``
when stick ends, contact-point velocity 0 when slip ends; docs/damping.md for the
viscoelastic contact, whose phase is a function of the state) and the next phase is
the first of the candidates whose event functions start positive
(:func:`enter`); this decides grazing transitions by derivatives, not by a
tolerance that could flip back and forth.
"""

import math

from .basis import (
    basis_values,
    derivative,
    dot,
    evaluate,
    has_cs,
    integral,
    integral_basis,
    magnitude,
    value_at_zero,
)
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
    SEG_E,
    SEG_E_DOT,
    SEG_EVENT,
    SEG_F,
    SEG_INT_F,
    SEG_INT_N,
    SEG_PHASE,
    SEG_TAU,
    SEG_THETA,
    SEG_XD,
    SEG_Y,
    SLIP_NEG,
    SLIP_POS,
    SMP_E,
    SMP_F,
    SMP_N,
    SMP_PHASE,
    SMP_XD,
    SMP_Y,
    STICK,
)
from .jit import jit, jit_inline
from .phases import (
    M_A,
    M_ALPHA,
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
    ZERO9,
    body,
    cone_margin,
    elongation,
    forced,
    frame_offset,
    inplane_force,
    liftoff_phases,  # noqa: F401  (re-exported for theory)
    make_model,
    normal_force,
    normal_integral,
    rigid_stick_force,
    slip_velocity,
    stick_elongation,
    stick_force,
)
from .roots import REL_TOL, first_root, start_margin

TWO_PI = 2.0 * math.pi
ZENO_N = 1e-10  # relative normal force below which the approach to n = 0 is free motion


@jit
def slip_sign(phase):
    return 1.0 if phase == SLIP_POS else -1.0


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
def stick_coefficients(M, theta, y, xd, e):
    """Force and elongation coefficients in stick from phase ``theta`` and their mode
    (rigid when k = inf).
    """
    if math.isinf(M[M_K]):
        return rigid_stick_force(M, theta, y), M[M_SLIP], ZERO9
    ec = stick_elongation(M, theta, y, xd, e)
    return stick_force(M, ec), M[M_STICK], ec


@jit
def stick_margin(fc, m, theta, s, a, sr):
    """The cone margin ``s_r n - s f`` of stick (eq. 15), its round-off at the start removed.

    Its value at the start is the difference of ``s_r n`` and ``s f``, both about 1; the
    round-off of that difference, ``REL_TOL (s_r + |f_0|)``, is not seen by
    :func:`.roots.start_margin`, which scales it by the coefficients left after the
    cancellation (small where ``a cos theta`` and the free motion are, e.g. ``a = 0``).
    A value within it is zero, so that the derivatives decide.  Without this, a force
    projected onto the edge, ``k (1/k) = 1 - eps``, re-entered stick after every
    stick->slip event and left it ``eps/(k V)`` later: 2e7 events in one period.
    """
    g = cone_margin(fc, theta, s, a, sr)
    g0 = value_at_zero(g, m)
    tol = REL_TOL * magnitude(g)
    if tol < abs(g0) <= tol + REL_TOL * (sr + abs(fc[0])):
        g = (g[0] - g0, g[1], g[2], g[3], g[4], g[5], g[6], g[7], g[8])
    return g


@jit
def contact_force(M, phase, theta, y, xd, e):
    """``f`` of a state: ``k e + c x'`` (stick; ``-alpha y + gamma V + h`` rigid), ``s n``, 0."""
    if phase == STICK:
        if math.isinf(M[M_K]):
            f = -M[M_ALPHA] * y + M[M_GAMMA] * M[M_V]
            return f + inplane_force(M, theta)[0] if forced(M) else f
        return M[M_K] * e + M[M_C] * xd
    if phase == FLIGHT:
        return 0.0
    return slip_sign(phase) * normal_force(theta, M[M_A])


@jit
def enter(theta, y, xd, e, ed, f, s_pref, M, T, avoid):
    """Choose the phase that starts consistently at ``theta``.

    Candidates, in order: stick (both cone margins must start positive; for a rigid
    contact also zero body velocity), slip ``s_pref``, slip ``-s_pref``.  With a
    finite elastic contact ``f = k e`` is continuous, so slip ``s`` is a candidate
    only when ``f = s n``; a viscoelastic contact may change its force at once (the
    contact point is massless), and exactly one phase is consistent: stick while
    ``|k e + c x'| <= n``, else slip in the direction of that force.  ``ed`` is the
    exact rate ``e'`` where known (else nan, see :func:`.phases.elongation`).  Returns
    ``(phase, e, ed, f, ok)``; ``ok`` is False when no candidate starts consistently (a
    degenerate point, counted by the caller).  ``avoid`` (a phase code, or
    ``NO_PHASE``) is skipped: the phase that has just ended at once, whose margin is
    lost in round-off (a near-tangency), must not be re-entered.
    """
    a, V, k = M[M_A], M[M_V], M[M_K]
    rigid = math.isinf(k)
    free = rigid or M[M_C] > 0.0  # f need not be continuous into slip
    n = normal_force(theta, a)
    if avoid != STICK and (not rigid or xd == 0.0):
        fc, mst, _ = stick_coefficients(M, theta, y, xd, e)
        ok1, _ = start_margin(stick_margin(fc, mst, theta, 1.0, a, M[M_SR]), mst, T)
        if ok1:
            ok2, _ = start_margin(stick_margin(fc, mst, theta, -1.0, a, M[M_SR]), mst, T)
            if ok2:
                return STICK, e, xd, evaluate(fc, mst, 0.0), True
    tol = 1e-12 * (1.0 + abs(n))
    m = M[M_SLIP]
    for i in range(2):
        s = s_pref if i == 0 else -s_pref
        if (SLIP_POS if s > 0 else SLIP_NEG) == avoid:
            continue
        if free or abs(f - s * n) <= tol:
            e1 = e if free else s * n / k
            ec = elongation(M, theta, e1, ed, s)
            vr = slip_velocity(M, body(M, theta, y, xd - V, s), ec, s)
            ok, _ = start_margin(vr, m, T)
            if ok:
                return (SLIP_POS if s > 0 else SLIP_NEG), e1, ed, s * n, True
    # degenerate: keep what continuity allows
    if free or abs(f - s_pref * n) <= tol:
        return (SLIP_POS if s_pref > 0 else SLIP_NEG), (e if free else s_pref * n / k), ed, \
            s_pref * n, False
    return STICK, e, xd, f, False


@jit
def enter_slipping(theta, y, xd, e, ed, f, s, M, T):
    """Choose the phase of a contact that was slipping in direction ``s`` (``s_r > 1``).

    Where the static coefficient is above the kinetic one a state with ``n < |f| <= s_r n``
    may stick or slip: a slipping contact goes on slipping while its slip velocity stays
    positive, a stuck one holds.  So slip ``s`` comes first, where it is consistent
    (``f = s n`` for an elastic contact) and its slip velocity starts positive; else
    :func:`enter` (stick first).  Used after a stick->slip event (the force has dropped to
    ``s n``) and for the sliding start.  Returns as :func:`enter`.
    """
    k = M[M_K]
    free = math.isinf(k) or M[M_C] > 0.0
    n = normal_force(theta, M[M_A])
    if free or abs(f - s * n) <= 1e-12 * (1.0 + abs(n)):
        e1 = e if free else s * n / k
        vr = slip_velocity(M, body(M, theta, y, xd - M[M_V], s), elongation(M, theta, e1, ed, s),
                           s)
        ok, _ = start_margin(vr, M[M_SLIP], T)
        if ok:
            return (SLIP_POS if s > 0 else SLIP_NEG), e1, ed, s * n, True
    return enter(theta, y, xd, e, ed, f, s, M, T, NO_PHASE)


@jit
def _jump(M, theta1, y1, xd1, e1, es, Tn):
    """Stick -> slip where ``s_r > 1``: the force drops at once from ``s s_r n`` to ``s n``.

    An elastic contact's massless contact point jumps, ``e`` from ``s s_r n/k`` to
    ``s n/k``; a viscoelastic one's elongation is continuous (its dashpot takes the drop:
    the contact point starts with the velocity ``s (s_r - 1) n/c``, ``e' = x' - s (s_r - 1)
    n/c``); a rigid contact's body, at rest, starts to slip (``s x'' = (s_r - 1) n``).  The
    slip goes on where its velocity starts positive, else the contact sticks again at the
    kinetic force (an elastic contact whose normal force falls fast: the jump was the
    slip).  Returns ``(phase, e, e', f, ok)``.
    """
    n1 = normal_force(theta1, M[M_A])
    f1 = es * n1
    k, c = M[M_K], M[M_C]
    ed1 = xd1
    if math.isinf(k):
        e1 = 0.0
    elif c > 0.0:
        e1 = (es * M[M_SR] * n1 - c * xd1) / k  # projected onto |f| = s_r n: e is continuous
        ed1 = xd1 - es * (M[M_SR] - 1.0) * n1 / c
    else:
        e1 = f1 / k
    return enter_slipping(theta1, y1, xd1, e1, ed1, f1, es, M, Tn)


@jit
def state_at(M, phase, theta, y, xd, e, ed, t):
    """``(y, x', e, e', f)`` a time ``t`` into a phase that started at ``theta`` in
    ``(y, x', e)`` (``ed``: the exact ``e'`` at the start where known, else nan).
    """
    y1, xd1, e1, ed1, f1, _ = _state_basis(M, phase, theta, y, xd, e, ed, t)
    return y1, xd1, e1, ed1, f1


@jit
def _state_basis(M, phase, theta, y, xd, e, ed, t):
    """:func:`state_at` and the basis values at ``t`` it used (:func:`.basis.basis_values` of
    the phase's mode; zeros for a rigid stick), for the integrals over the piece.
    """
    V = M[M_V]
    if phase == STICK:
        if math.isinf(M[M_K]):
            y1 = y - V * t
            f1 = -M[M_ALPHA] * y1 + M[M_GAMMA] * V
            return y1, 0.0, 0.0, 0.0, (f1 + inplane_force(M, theta + t)[0] if forced(M)
                                       else f1), ZERO9
        m = M[M_STICK]
        ec = stick_elongation(M, theta, y, xd, e)
        bv = basis_values(m, t, has_cs(ec), False)
        e1 = dot(ec, bv)
        xd1 = dot(derivative(ec, m), bv)
        return y + (e1 - e) - V * t, xd1, e1, xd1, M[M_K] * e1 + M[M_C] * xd1, bv
    m = M[M_SLIP]
    s = 0.0 if phase == FLIGHT else slip_sign(phase)
    yc = body(M, theta, y, xd - V, s)
    ec = elongation(M, theta, e, ed, s)
    bv = basis_values(m, t, has_cs(yc), ec[8] != 0.0)  # one evaluation for all four
    return (dot(yc, bv), V + dot(derivative(yc, m), bv), dot(ec, bv),
            dot(derivative(ec, m), bv), s * normal_force(theta + t, M[M_A]), bv)


@jit_inline
def _stick_event(fc, mst, theta, a, sr, T):
    """The first stick->slip event within ``T``: ``(t or -1, direction s, immediate)``.

    Both cone margins ``n -+ f`` are searched; ``immediate`` when the event fires at the
    start offset (a round-off tangency).
    """
    te = -1.0
    es = 0.0
    immediate = False
    for i in range(2):
        s = 1.0 if i == 0 else -1.0
        g = stick_margin(fc, mst, theta, s, a, sr)
        ok, ts = start_margin(g, mst, T)
        tlim = T if te < 0.0 else te
        r = first_root(g, mst, ts, tlim) if ok else 0.0
        if r >= 0.0 and (te < 0.0 or r < te):
            te = r
            es = s
            immediate = r <= ts
    return te, es, immediate


@jit_inline
def _slip_event(vr, m, T):
    """The first zero of the contact point's slip velocity ``vr`` within ``T``:
    ``(t or -1, immediate)``.
    """
    ok, ts = start_margin(vr, m, T)
    te = first_root(vr, m, ts, T) if ok else 0.0
    return te, te >= 0.0 and te <= ts


@jit_inline
def _integrals(M, phase, zeno, theta, t, fc, mst, ec, e, e1, bv):
    """``(int_f, int_n)``: the integrals of ``f`` and ``n`` over a piece of length ``t``
    (``bv``: the basis values at ``t`` of :func:`_state_basis`).
    """
    a = M[M_A]
    if zeno or phase == FLIGHT:
        return 0.0, (0.0 if phase == FLIGHT else normal_integral(theta, t, a))
    int_n = normal_integral(theta, t, a)
    if phase != STICK:
        return slip_sign(phase) * int_n, int_n
    if math.isinf(M[M_K]):
        return integral(fc, mst, t), int_n
    return M[M_K] * integral_basis(ec, mst, t, bv) + M[M_C] * (e1 - e), int_n


@jit
def _transition(M, phase, theta1, y1, xd1, e1, ed1, f1, es, Tn, avoid):
    """The phase after the event that ended ``phase`` with the state ``(y1, xd1, e1, ed1,
    f1)`` (:func:`state_at`): the state is projected onto the event surface, then
    :func:`enter` decides.  Returns ``(phase, x', e, e', f, ok, event)``.
    """
    rigid = math.isinf(M[M_K])
    if phase == STICK and M[M_SR] > 1.0:
        ph1, e1, ed1, f1, ok = _jump(M, theta1, y1, xd1, e1, es, Tn)
        return ph1, xd1, e1, ed1, f1, ok, EV_STICK_TO_SLIP
    if phase == STICK:
        # stick -> slip in direction es: project onto |f| = n
        f1 = es * normal_force(theta1, M[M_A])
        if not rigid:
            e1 = (f1 - M[M_C] * xd1) / M[M_K]
        # the contact point starts from rest: e' = x' exactly
        ph1, e1, ed1, f1, ok = enter(theta1, y1, xd1, e1, xd1, f1, es, M, Tn, avoid)
        return ph1, xd1, e1, ed1, f1, ok, EV_STICK_TO_SLIP
    s = slip_sign(phase)
    # slip -> stick: project onto zero contact-point velocity, x' = e' (state_at's e')
    xd1 = 0.0 if rigid else ed1
    ph1, e1, ed1, f1, ok = enter(theta1, y1, xd1, e1, xd1, f1, -s, M, Tn, avoid)
    return ph1, xd1, e1, ed1, f1, ok, (EV_SLIP_TO_STICK if ph1 == STICK else EV_REVERSAL)


@jit
def _boundary(M, bkind, ph1, theta1, y1, xd1, e1, ed1, f1):
    """The phase after reaching lift-off, touch-down or the section without an event.
    Returns ``(phase, e, e', f, ok)``.
    """
    if bkind == EV_LIFTOFF:
        if M[M_C] == 0.0:
            return FLIGHT, 0.0, 0.0, 0.0, True
        return FLIGHT, e1, ed1, 0.0, True
    if bkind == EV_TOUCHDOWN:
        # f = 0 at n = 0; the contact point arrives with velocity x' + r e
        sp = 1.0 if xd1 + M[M_R] * e1 >= 0.0 else -1.0
        return enter(theta1, y1, xd1, e1, ed1, 0.0, sp, M, TWO_PI - theta1, NO_PHASE)
    return ph1, e1, ed1, f1, True


@jit
def free_approach(theta, phase, a, bkind):
    """Whether a segment starting at ``theta`` in ``phase`` moves freely to the boundary
    ``bkind`` (the Zeno guard of :func:`segment`).
    """
    return (phase != FLIGHT and bkind != EV_SECTION
            and normal_force(theta, a) <= ZENO_N * (1.0 + a))


@jit
def segment(theta, y, xd, e, ed, phase, M):
    """Advance one segment.

    Returns ``(t, theta_end, y, x', e, e', f, phase, event, int_f, int_n, ok)`` where
    ``event`` is the kind of what ended the segment (a transition or a boundary),
    ``int_f`` and ``int_n`` the integrals of ``f`` and ``n`` over it and ``ok`` False
    when a transition was degenerate.
    """
    a = M[M_A]
    m = M[M_SLIP]
    tb, bkind = next_boundary(theta, a, M[M_OFF], M[M_ON])
    T = tb - theta
    # Zeno guard: where the cone closes (n -> 0 at lift-off or grazing) stick and slip
    # can alternate infinitely often.  Once n < ZENO_N the force |f| <= n is negligible
    # (its integral over the rest of the approach is < 1e-14): move freely to the boundary.
    zeno = free_approach(theta, phase, a, bkind)
    te = -1.0
    es = 0.0
    immediate = False  # the event fired at the start offset: a round-off tangency
    fc, mst, ec = stick_coefficients(M, theta, y, xd, e) if phase == STICK else (ZERO9, m, ZERO9)
    if phase == STICK and not zeno:
        te, es, immediate = _stick_event(fc, mst, theta, a, M[M_SR], T)
    elif phase != FLIGHT and not zeno:
        s = slip_sign(phase)
        ec = elongation(M, theta, e, ed, s)
        te, immediate = _slip_event(slip_velocity(M, body(M, theta, y, xd - M[M_V], s), ec, s),
                                    m, T)
    hit = te >= 0.0
    t = te if hit else T
    # state and integrals at the end of the piece (the Zeno approach moves freely)
    y1, xd1, e1, ed1, f1, bv = _state_basis(M, FLIGHT if zeno else phase, theta, y, xd, e,
                                            ed, t)
    int_f, int_n = _integrals(M, phase, zeno, theta, t, fc, mst, ec, e, e1, bv)
    theta1 = tb if t == T else theta + t
    ph1, ok, event = phase, True, bkind
    if hit:
        ph1, xd1, e1, ed1, f1, ok, event = _transition(
            M, phase, theta1, y1, xd1, e1, ed1, f1, es, tb - theta1 if tb > theta1 else TWO_PI,
            phase if immediate else NO_PHASE)
    if t == T and not hit:
        ph1, e1, ed1, f1, ok = _boundary(M, bkind, ph1, theta1, y1, xd1, e1, ed1, f1)
    elif t == T and hit and bkind != EV_SECTION:
        # an event exactly at lift-off / touch-down: the boundary is handled by a
        # zero-length segment next (theta1 == tb keeps it as the next boundary)
        theta1 = math.nextafter(tb, -math.inf)
    return t, theta1, y1, xd1, e1, ed1, f1, ph1, event, int_f, int_n, ok


@jit
def to_kernel_frame(offset, y, xd):
    """A section state ``(y, x')`` of the laboratory frame in the kernels' frame: relative
    to an oscillating substrate, whose position and velocity at ``tau = 2 pi k`` are
    ``offset`` (:func:`.phases.frame_offset`; the identity where it is 0).
    """
    if offset[0] != 0.0 or offset[1] != 0.0:
        return y - offset[0], xd - offset[1]
    return y, xd


@jit
def to_lab_frame(offset, y, xd):
    """The inverse of :func:`to_kernel_frame`."""
    if offset[0] != 0.0 or offset[1] != 0.0:
        return y + offset[0], xd + offset[1]
    return y, xd


@jit
def initial_state(kind, M, offset=(0.0, 0.0)):
    """``kind`` 0: steady sliding before the oscillation starts; 1: rest.

    Both are states of the laboratory frame (body velocity ``V`` resp. 0); an oscillating
    substrate's frame is offset from it by ``offset`` (:func:`to_kernel_frame`).  Returns
    ``(y, x', e, phase, e')``.
    """
    if kind == 0:
        k = M[M_K]
        y, xd, e, f = -1.0 / M[M_ALPHA], M[M_V], (0.0 if math.isinf(k) else 1.0 / k), 1.0
        ed = 0.0  # steady sliding: the spring's elongation is constant
    else:
        y, xd, e, f, ed = 0.0, 0.0, 0.0, 0.0, 0.0
    y, xd = to_kernel_frame(offset, y, xd)
    if kind == 0 and M[M_SR] > 1.0:
        # a sliding contact goes on sliding where it can (f = n, slip velocity > 0); a
        # viscoelastic one's rate follows from f = n(0) = 1 + a
        if M[M_C] > 0.0:
            ed = (normal_force(0.0, M[M_A]) - f) / M[M_C]
        ph, e, ed, f, _ = enter_slipping(0.0, y, xd, e, ed, f, 1.0, M, TWO_PI)
        return y, xd, e, ph, ed
    ph, e, ed, f, _ = enter(0.0, y, xd, e, ed, f, 1.0, M, TWO_PI, NO_PHASE)
    return y, xd, e, ph, ed


@jit
def run_periods(theta, y, xd, e, ed, phase, alpha, beta, a, V, zeta, eta, a_x, phase_x,
                on_substrate, sr, periods, max_segments, seg):
    """Integrate ``periods`` drive periods, recording every segment start in ``seg``.

    The state is in the kernels' frame (relative to an oscillating substrate,
    :func:`to_kernel_frame`), and so are the recorded ``y`` and ``x'``.

    ``seg`` has shape ``(max_segments, N_SEG_COLUMNS)`` with columns (``codes.SEG_*``)
    ``tau, y, x', f, phase, event that ended the previous segment, int_f, int_n``
    (cumulative), the drive phase ``theta`` of the segment start, ``e`` and ``e'`` (nan
    where not known exactly, :func:`.phases.elongation`).  Returns the number of rows
    written (``-1`` if ``max_segments`` was too small).
    """
    M = make_model(alpha, beta, a, V, zeta, eta, a_x, phase_x, on_substrate, sr)
    k = 0
    m = 0
    cf = 0.0
    cn = 0.0
    ev = EV_NONE
    while True:
        if m >= max_segments:
            return -1
        seg[m, SEG_TAU] = TWO_PI * k + theta
        seg[m, SEG_Y] = y
        seg[m, SEG_XD] = xd
        seg[m, SEG_F] = contact_force(M, phase, theta, y, xd, e)
        seg[m, SEG_PHASE] = float(phase)
        seg[m, SEG_EVENT] = float(ev)
        seg[m, SEG_INT_F] = cf
        seg[m, SEG_INT_N] = cn
        seg[m, SEG_THETA] = theta
        seg[m, SEG_E] = e
        seg[m, SEG_E_DOT] = ed
        m += 1
        if k >= periods:
            return m
        t, theta, y, xd, e, ed, f, phase, ev, i_f, i_n, ok = segment(theta, y, xd, e, ed,
                                                                      phase, M)
        cf += i_f
        cn += i_n
        if theta >= TWO_PI:
            theta = 0.0
            k += 1


@jit
def sample(seg, nseg, alpha, beta, a, V, zeta, eta, a_x, phase_x, on_substrate, sr, taus, out):
    """Evaluate the closed forms at sorted times ``taus`` into ``out`` (shape ``(len(taus),
    N_SMP_COLUMNS)``, columns ``codes.SMP_*``: y, x', f, n, phase, e; ``y``, ``x'`` in the
    kernels' frame).
    """
    M = make_model(alpha, beta, a, V, zeta, eta, a_x, phase_x, on_substrate, sr)
    j = 0
    for i in range(taus.shape[0]):
        tau = taus[i]
        while j + 1 < nseg - 1 and seg[j + 1, SEG_TAU] <= tau:
            j += 1
        theta = seg[j, SEG_THETA]
        t = tau - seg[j, SEG_TAU]
        phase = int(seg[j, SEG_PHASE])
        y1, xd1, e1, _, f1 = state_at(M, phase, theta, seg[j, SEG_Y], seg[j, SEG_XD],
                                      seg[j, SEG_E], seg[j, SEG_E_DOT], t)
        out[i, SMP_Y] = y1
        out[i, SMP_XD] = xd1
        out[i, SMP_F] = f1
        out[i, SMP_N] = max(0.0, normal_force(theta + t, a))
        out[i, SMP_PHASE] = phase
        out[i, SMP_E] = e1


@jit
def initial_point(kind, alpha, beta, a, V, zeta, eta, a_x, phase_x, on_substrate, sr):
    """:func:`initial_state` from the parameters: ``(y, x', e, phase, e')`` (kernels' frame)."""
    return initial_state(kind, make_model(alpha, beta, a, V, zeta, eta, a_x, phase_x,
                                          on_substrate, sr),
                         frame_offset(a_x, phase_x, on_substrate))
