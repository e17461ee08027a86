r"""The steady state and the macroscopic coefficient of friction (paper eq. 25).

``mu_macro / mu0 = <f> / <n>`` over the steady state, with both integrals taken
from the closed forms, so a periodic orbit gives the ratio exactly.

The run advances one drive period at a time (:func:`advance_period`).  At each
Poincare section ``tau = 2 pi k`` the state ``z_k = (y, x', e, phase)`` is
compared with ``z_{k-p}`` for ``p = 1..MAX_PERIOD`` (:func:`detect_period`);
Newton's method on the period map is tried on a schedule (:func:`newton_orbit`);
continuous sliding is proven where its certificate applies
(:func:`sliding_certificate`); otherwise the running average is checked at
doubling checkpoints (:func:`check_average`).  Every result states an estimate of
``|mu_ratio - exact|`` (docs/solver.md, "What error means"):

* periodic: the p-period means of two successive windows differ by ``d_mu``;
  the window means converge to the orbit's mean like ``lambda^k`` (``lambda``
  the leading Floquet multiplier, :func:`leading_multiplier`), so the error of
  the last window is about ``d_mu / (1 - |lambda|)``; twice that is stated (other
  modes add to it), floored at round-off;
* averaged: the disagreement of the last two averaging windows;
* not converged: no value (``nan``) and ``inf``; the last windows' means are
  reported as a range, never as the answer;
* continuous sliding: 0 (proven: eqs. 10-12 generalised to a contact that opens
  and to damping, docs/damping.md).

Output rows follow ``solver.FLOAT_COLUMNS`` / ``solver.INT_COLUMNS``.
"""

import math

import numpy as np

from .basis import derivative, evaluate, sup_bound
from .codes import (
    EV_SECTION,
    FLIGHT,
    SLIP_NEG,
    SLIP_POS,
    ST_AVERAGED,
    ST_FAILED,
    ST_NOT_CONVERGED,
    ST_PERIODIC,
    ST_SLIDING,
    STICK,
)
from .integrate import TWO_PI, contact_force, initial_state, segment
from .jit import jit
from .phases import (
    ETA_ELASTIC,
    ETA_SLOPE,
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
    make_model,
    slip_velocity,
)
from .roots import first_root, start_margin

MAX_PERIOD = 12  # longest periodic orbit looked for, in drive periods
MAX_DEGENERATE = 1000  # transitions decided within round-off before giving up (chatter)
MAX_ZERO_SEGMENTS = 100  # successive zero-length segments before giving up (stuck)
FIRST_NEWTON = 1  # first attempt to solve the periodicity condition, in periods
NEWTON_ITERATIONS = 12  # Newton steps per attempt
NEWTON_DIVERGED = 100.0  # a Newton iterate this far (relative) from its start has diverged
MAX_CHECKPOINTS = 64  # doubling checkpoints of the running average
RHO_MAX = 0.999  # cap of a contraction rate estimated from section distances
ROUNDOFF_MU = 1e-13  # floor of the error of an exact periodic average
ERROR_SAFETY = 2.0  # d_mu/(1 - lambda) assumes one real leading mode; others add to it
ATTRACTING = 1.0 - 1e-9  # a multiplier modulus below this is attracting
NEUTRAL_WINDOW = 512  # the motion near a neutral orbit is measured over periods (N, 2N]
NEUTRAL = 1.0 - 1e-6  # a multiplier modulus above this is neutral (to difference accuracy)

# accumulators: integrals of f and n, times in stick, slip, reverse slip, flight
A_F, A_N, A_STICK, A_SLIP, A_SLIP_NEG, A_FLIGHT = 0, 1, 2, 3, 4, 5
N_ACC = 6
# counters: events, degenerate transitions, successive zero-length segments
C_EVENTS, C_DEGENERATE, C_ZERO = 0, 1, 2
# output columns (solver.FLOAT_COLUMNS, solver.INT_COLUMNS)
O_MU, O_ERR, O_STICK, O_SLIP, O_SLIP_NEG, O_FLIGHT, O_Y, O_XD, O_F = 0, 1, 2, 3, 4, 5, 6, 7, 8
O_MULT, O_SETTLE, O_WMIN, O_WMAX, O_DRIFT, O_E = 9, 10, 11, 12, 13, 14
I_STATUS, I_PERIOD, I_PERIODS, I_EVENTS, I_PHASE, I_DEGENERATE = 0, 1, 2, 3, 4, 5


@jit
def advance_period(z, acc, count, M, max_events):
    """Integrate one drive period from the section state ``z = (y, x', e, phase, e')``
    (``e'``: the exact rate where known, else nan; :func:`.phases.elongation`).

    ``z`` is updated in place, ``acc`` accumulates the integrals and phase times,
    ``count`` the events, degenerate transitions and zero-length segments.
    Returns False when the integration must stop (event budget, chatter, stuck).
    """
    theta = 0.0
    y, xd, e, ph, ed = z[0], z[1], z[2], int(z[3]), z[4]
    while theta < TWO_PI:
        t, theta, y, xd, e, ed, f, ph1, ev, i_f, i_n, ok = segment(theta, y, xd, e, ed, ph, M)
        acc[A_F] += i_f
        acc[A_N] += i_n
        if ph == STICK:
            acc[A_STICK] += t
        elif ph == FLIGHT:
            acc[A_FLIGHT] += t
        else:
            acc[A_SLIP] += t
            if ph == SLIP_NEG:
                acc[A_SLIP_NEG] += t
        if ev != EV_SECTION:
            count[C_EVENTS] += 1
        if not ok:
            count[C_DEGENERATE] += 1
        count[C_ZERO] = count[C_ZERO] + 1 if t == 0.0 else 0
        ph = ph1
        if (count[C_EVENTS] > max_events or count[C_ZERO] > MAX_ZERO_SEGMENTS
                or count[C_DEGENERATE] > MAX_DEGENERATE):
            return False
    z[0], z[1], z[2], z[3], z[4] = y, xd, e, ph, ed
    return True


@jit
def period_map(y, xd, e, ph, p, M, max_events):
    """Integrate ``p`` drive periods from the section; returns the state, the event count
    and the number of degenerate transitions (-1: the integration did not finish).

    Transitions decided within round-off (degenerate, e.g. among the hundreds of
    micro-slips per period of a stiff contact) do not make the map unusable for Newton's
    iterations and Jacobians; the orbit is accepted only from a map without them.
    """
    z = np.array([y, xd, e, float(ph), math.nan])
    acc = np.zeros(N_ACC)
    count = np.zeros(3, np.int64)
    for _ in range(p):
        if not advance_period(z, acc, count, M, max_events):
            return z[0], z[1], z[2], int(z[3]), count[C_EVENTS], -1
    return z[0], z[1], z[2], int(z[3]), count[C_EVENTS], count[C_DEGENERATE]


@jit
def _spring(M):
    """The contact stiffness as a weight of ``e`` in distances (0 for a rigid contact)."""
    return 0.0 if math.isinf(M[M_K]) else M[M_K]


@jit
def _unpack(z, ph, M):
    """Section state ``(y, x', e)`` from the free coordinates ``z`` of phase ``ph``."""
    rigid = math.isinf(M[M_K])
    if ph == STICK:
        if rigid:
            return z[0], 0.0, 0.0
        return z[0], z[1], z[2]
    if rigid:
        return z[0], z[1], 0.0
    if M[M_C] > 0.0:
        return z[0], z[1], z[2]
    s = 1.0 if ph == SLIP_POS else -1.0
    return z[0], z[1], s * (1.0 + M[M_A]) / M[M_K]


@jit
def _free_dimension(ph, M):
    """Free coordinates on the section: ``y`` (rigid stick), ``y, x'`` (elastic slip),
    ``y, x', e`` (stick, viscoelastic slip)."""
    rigid = math.isinf(M[M_K])
    if ph == STICK:
        return 1 if rigid else 3
    return 3 if (M[M_C] > 0.0 and not rigid) else 2


@jit
def _solve_small(m, r, nd):
    """Solve ``m x = r`` for ``nd <= 3`` by Gaussian elimination with pivoting."""
    m = m.copy()
    r = r.copy()
    for c in range(nd):
        piv = c
        for i in range(c + 1, nd):
            if abs(m[i, c]) > abs(m[piv, c]):
                piv = i
        if m[piv, c] == 0.0:
            return r, False
        if piv != c:
            for j in range(nd):
                m[c, j], m[piv, j] = m[piv, j], m[c, j]
            r[c], r[piv] = r[piv], r[c]
        for i in range(c + 1, nd):
            q = m[i, c] / m[c, c]
            for j in range(c, nd):
                m[i, j] -= q * m[c, j]
            r[i] -= q * r[c]
    x = np.zeros(nd)
    for i in range(nd - 1, -1, -1):
        acc = r[i]
        for j in range(i + 1, nd):
            acc -= m[i, j] * x[j]
        x[i] = acc / m[i, i]
    return x, True


@jit
def residual_jacobian(z, r, ph, p, M, max_events, jac):
    """Difference Jacobian of ``z -> P^p(z) - z`` in the chart of phase ``ph`` (into ``jac``).

    ``r`` is the residual at ``z``.  Returns ``(ok, events)``; not ok when a
    perturbed image leaves the chart or the integration fails.
    """
    nd = _free_dimension(ph, M)
    kk = _spring(M)
    events = 0
    for j in range(nd):
        if j == 2:  # e: the step of a force change 1e-7 (1 + |f|)
            h = 1e-7 * (abs(z[2]) + 1.0 / kk)
        else:
            h = 1e-7 * (1.0 + abs(z[j]))
        zp = z.copy()
        zp[j] += h
        y2, xd2, e2 = _unpack(zp, ph, M)
        y3, xd3, e3, ph3, ev, degenerate = period_map(y2, xd2, e2, ph, p, M, max_events)
        events += ev
        if ph3 != ph or degenerate < 0:
            return False, events
        jac[0, j] = ((y3 - y2) - r[0]) / h
        jac[1, j] = ((xd3 - xd2) - r[1]) / h
        jac[2, j] = ((e3 - e2) - r[2]) / h
    return True, events


@jit
def spectral_radius(jac, nd):
    """Largest modulus of the eigenvalues of ``DP^p = jac + I`` (the Floquet multipliers)."""
    if nd == 1:
        return abs(jac[0, 0] + 1.0)
    mat = (jac[:nd, :nd] + np.eye(nd)).astype(np.complex128)
    return np.max(np.abs(np.linalg.eigvals(mat)))


@jit
def _broyden(jac, nd, dr, dz):
    """Broyden's ("good") rank-one update of ``jac`` after the step ``dz`` changed the
    residual by ``dr``: saves the ``nd`` period maps of a fresh difference Jacobian."""
    den = 0.0
    for j in range(nd):
        den += dz[j] * dz[j]
    if den == 0.0:
        return
    for i in range(nd):
        u = dr[i]
        for j in range(nd):
            u -= jac[i, j] * dz[j]
        for j in range(nd):
            jac[i, j] += u * dz[j] / den


@jit
def newton_orbit(y, xd, e, ph, p, M, tol, max_events):
    """Solve ``P^p(z) = z`` on the section by Newton's method with a difference Jacobian
    (updated by Broyden's rule between rebuilds).

    Only attracting orbits are accepted (spectral radius of ``DP^p`` below
    ``NEUTRAL``), so the answer is the attractor the iteration was approaching, not a
    nearby unstable orbit, nor a neutral one (the undamped free oscillation of pure
    slip) that the motion from the start need never approach.  An iterate whose
    image is in another phase on the section (the orbit sticks at ``tau = 2 pi k``
    where the guess slid, or vice versa) continues in that phase's coordinates.
    Returns ``(ok, y, x', e, phase, events)``.
    """
    ph_in = ph
    alpha = M[M_ALPHA]
    kk = _spring(M)
    nd = _free_dimension(ph, M)
    z = np.array([y, xd, e])
    events = 0
    jac = np.zeros((3, 3))
    have_jac = False
    res_prev = np.inf
    r_prev = np.zeros(3)
    dz = np.zeros(3)
    scale0 = 1.0 + alpha * abs(y) + abs(xd) + kk * abs(e)
    for _ in range(NEWTON_ITERATIONS):
        if (alpha * abs(z[0] - y) + abs(z[1] - xd) + kk * abs(z[2] - e)
                > NEWTON_DIVERGED * scale0):
            return False, y, xd, e, ph_in, events
        y0, xd0, e0 = _unpack(z, ph, M)
        y1, xd1, e1, ph1, ev, degenerate = period_map(y0, xd0, e0, ph, p, M, max_events)
        events += ev
        if degenerate < 0:
            return False, y, xd, e, ph_in, events
        if ph1 != ph:
            # change chart: continue from the image, in its phase's coordinates
            ph = ph1
            nd = _free_dimension(ph, M)
            z[0], z[1], z[2] = y1, xd1, e1
            have_jac = False
            res_prev = np.inf
            continue
        r = np.array([y1 - y0, xd1 - xd0, e1 - e0])
        res = alpha * abs(r[0]) + abs(r[1]) + (kk * abs(r[2]) if nd == 3 else 0.0)
        if have_jac and np.isfinite(res_prev):
            _broyden(jac, nd, r - r_prev, dz)
        if res <= tol * scale0:
            if degenerate > 0 or not have_jac or not spectral_radius(jac, nd) < NEUTRAL:
                return False, y, xd, e, ph_in, events
            return True, y0, xd0, e0, ph, events
        if not have_jac or res > 0.5 * res_prev:
            # (re)build the Jacobian; otherwise Broyden's updates of the old one
            have_jac, ev = residual_jacobian(z, r, ph, p, M, max_events, jac)
            events += ev
            if not have_jac:
                return False, y, xd, e, ph_in, events
        res_prev = res
        r_prev = r
        dz, ok = _solve_small(jac[:nd, :nd], -r[:nd], nd)
        if not ok:
            return False, y, xd, e, ph_in, events
        for j in range(nd):
            z[j] += dz[j]
    return False, y, xd, e, ph_in, events


@jit
def leading_multiplier(z, z1, p, M, max_events):
    """Modulus of the leading Floquet multiplier of the p-periodic orbit through ``z``.

    ``z1`` is the image of the section state ``z`` after ``p`` periods (already
    integrated by the caller).  ``nan`` when the Jacobian cannot be formed in one
    chart (a perturbed orbit changes phase on the section).  Returns
    ``(multiplier, events)``.
    """
    ph = int(z[3])
    if int(z1[3]) != ph:
        return math.nan, 0
    r = np.array([z1[0] - z[0], z1[1] - z[1], z1[2] - z[2]])
    jac = np.zeros((3, 3))
    ok, ev = residual_jacobian(z[:3].copy(), r, ph, p, M, max_events, jac)
    if not ok:
        return math.nan, ev
    return spectral_radius(jac, _free_dimension(ph, M)), ev


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
    relaxing on its own; the fixed point solves ``(I - R) z = b``.  Not ok where the
    undamped ``sqrt(alpha)`` is (nearly) an integer (a harmonic of ``n`` resonates
    and no bounded sliding solution exists) or ``a = 0``.
    """
    a = M[M_A]
    if a == 0.0:
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
def _distance(alpha, kk, z1, z2):
    return alpha * abs(z1[0] - z2[0]) + abs(z1[1] - z2[1]) + kk * abs(z1[2] - z2[2])


@jit
def _pure_forward_slip(win):
    """A window without stick or reverse slip: ``f = n`` throughout (``0 = 0`` in flight)."""
    return win[A_STICK] == 0.0 and win[A_SLIP_NEG] == 0.0


@jit
def _window_mu(win):
    return 1.0 if _pure_forward_slip(win) else win[A_F] / win[A_N]


@jit
def detect_period(ring_z, dprev, k, M, tol_state):
    """The shortest ``p`` with ``z_k`` within ``tol_state`` of ``z_{k-p}`` (same phase).

    Returns ``(p, d, rho)``: ``p = 0`` if none; ``d`` the section distance and
    ``rho`` the contraction observed since the previous period (``dprev`` keeps the
    last distance for every ``p`` and is updated).
    """
    nring = MAX_PERIOD + 1
    slot = k % nring
    z = ring_z[slot]
    alpha = M[M_ALPHA]
    kk = _spring(M)
    scale = 1.0 + alpha * abs(z[0]) + abs(z[1]) + kk * abs(z[2])
    for p in range(1, MAX_PERIOD + 1):
        if p > k:
            break
        old = (k - p) % nring
        if ring_z[old, 3] != z[3]:
            dprev[p] = np.inf
            continue
        d = _distance(alpha, kk, z, ring_z[old])
        if d <= tol_state * scale:
            rho = d / dprev[p] if dprev[p] > 0.0 and np.isfinite(dprev[p]) else 0.0
            return p, d, min(rho, RHO_MAX)
        dprev[p] = d
    return 0, math.inf, 0.0


@jit
def _window(acc, ring_c, k, p, win):
    """The accumulators over the last ``p`` periods (into ``win``)."""
    old = (k - p) % (MAX_PERIOD + 1)
    for j in range(N_ACC):
        win[j] = acc[j] - ring_c[old, j]


@jit
def transient_deviation(z0, mu, M, max_events):
    """``|mean over periods (N, 2N] - mu|`` of the motion from ``z0`` (``N = NEUTRAL_WINDOW``).

    Used where the orbit is neutral: the motion from the start need not approach it
    (an undamped free oscillation in slip survives and sticks now and then), so the
    distance of a long window of the real motion is what the error can honestly say.
    Returns ``(deviation, events)``.
    """
    z = z0.copy()
    acc = np.zeros(N_ACC)
    count = np.zeros(3, np.int64)
    for k in range(2 * NEUTRAL_WINDOW):
        if k == NEUTRAL_WINDOW:
            acc[:] = 0.0
        if not advance_period(z, acc, count, M, max_events):
            return math.inf, count[C_EVENTS]
    return abs(acc[A_F] / acc[A_N] - mu), count[C_EVENTS]


@jit
def periodic_result(z, z0, win, p, k, rho, first_jump, mu_first, M, max_events, out_f):
    """Average, error, multiplier and settling time of a p-periodic orbit.

    ``win`` holds the accumulators of the last ``p`` periods (one period of the
    orbit).  One more window is integrated to measure ``d_mu``, the change of the
    p-period mean; with the leading multiplier ``lam`` the window means converge
    geometrically, so the error is ``d_mu / (1 - lam)`` (``rho``, the contraction
    seen on the section, stands in where ``lam`` cannot be formed).  The settling
    time counts the periods the motion from the initial state needs until its
    p-period means stay within that error of the orbit's: ``k`` when the orbit was
    reached by plain iteration, else extrapolated from the first Newton jump
    (period ``first_jump``, window mean ``mu_first``) at the rate ``lam``.  A
    neutral orbit reached by a jump has no settling time, and its error includes
    :func:`transient_deviation` of the motion from the start ``z0``.
    Returns the events spent.
    """
    mu = _window_mu(win)
    z2 = z.copy()
    acc2 = np.zeros(N_ACC)
    count = np.zeros(3, np.int64)
    d_mu = 0.0
    for _ in range(p):
        if not advance_period(z2, acc2, count, M, max_events):
            d_mu = math.inf
    d_mu = max(d_mu, abs(_window_mu(acc2) - mu))
    lam, ev = math.nan, 0
    if math.isfinite(d_mu) and count[C_DEGENERATE] == 0:  # z2 is the exact image of z
        lam, ev = leading_multiplier(z, z2, p, M, max_events)
    rate = lam if (math.isfinite(lam) and lam < ATTRACTING) else max(rho, RHO_MAX)
    err = max(ERROR_SAFETY * d_mu / (1.0 - rate), ROUNDOFF_MU * (1.0 + abs(mu)))
    settle = float(k)
    if first_jump >= 0 and not lam < NEUTRAL:
        # a neutral orbit (undamped slip) after a Newton jump: the motion from the start
        # need not approach it (no settling time; said in the message, docs/solver.md)
        settle = math.nan
        dev, ev2 = transient_deviation(z0, mu, M, max_events)
        ev += ev2
        err = max(err, dev)
    elif first_jump >= 0:
        settle = float(first_jump)
        e0 = abs(mu_first - mu)
        if e0 > err and rate > 0.0:
            settle += math.log(err / e0) / math.log(rate)
    out_f[O_MU] = mu
    out_f[O_ERR] = err
    out_f[O_MULT] = lam
    out_f[O_SETTLE] = settle
    return count[C_EVENTS] + ev


@jit
def try_newton(z, ring_z, dprev, k, M, tol_state, max_events):
    """Newton on the period whose section distance is smallest, then on ``p = 1``.

    On success ``z`` (and its ring slot) become the orbit's state.  Returns
    ``(p, events)`` with ``p = 0`` if no attracting orbit was found.
    """
    pbest = 1
    for p in range(2, min(k, MAX_PERIOD) + 1):
        if dprev[p] < dprev[pbest]:
            pbest = p
    events = 0
    for attempt in range(2):
        p = pbest if attempt == 0 else 1
        if attempt == 1 and pbest == 1:
            break
        ok, y, xd, e, ph, ev = newton_orbit(z[0], z[1], z[2], int(z[3]), p, M,
                                            0.1 * tol_state, max_events)
        events += ev
        if ok:
            z[0], z[1], z[2], z[3], z[4] = y, xd, e, ph, math.nan
            ring_z[k % (MAX_PERIOD + 1), :] = z
            dprev[:] = np.inf
            return p, events
    return 0, events


@jit
def check_average(chk_k, chk_c, nchk, final, tol_mean, win, out_f):
    """Running-average test at the doubling checkpoints ``K/4, K/2, K``.

    The mean over ``(K/2, K]`` is the answer and its disagreement with the mean over
    ``(K/4, K/2]`` the error.  Returns True when converged: they agree within
    ``tol_mean`` and the last window is not pure forward slip (which averages to 1
    whatever the state: without the certificate it is a transient, e.g. a resonance
    still building up).  Where the means of the last three windows move one way,
    their drift per period (between the last two windows' centres) is recorded;
    0 where they do not, nan with fewer than three windows.
    """
    if not (nchk >= 3 or (final and nchk >= 2)):
        return False
    i2, i1 = nchk - 1, nchk - 2
    for j in range(N_ACC):
        win[j] = chk_c[i2, j] - chk_c[i1, j]
    m1 = win[A_F] / win[A_N]
    if nchk >= 3:
        i0 = nchk - 3
        m0 = (chk_c[i1, A_F] - chk_c[i0, A_F]) / (chk_c[i1, A_N] - chk_c[i0, A_N])
    else:
        m0 = chk_c[i1, A_F] / chk_c[i1, A_N]
    out_f[O_MU] = m1
    out_f[O_ERR] = max(abs(m1 - m0), ROUNDOFF_MU * (1.0 + abs(m1)))
    out_f[O_WMIN] = min(m0, m1)
    out_f[O_WMAX] = max(m0, m1)
    out_f[O_DRIFT] = math.nan
    if nchk >= 4:
        i0, im = nchk - 3, nchk - 4
        mm = (chk_c[i0, A_F] - chk_c[im, A_F]) / (chk_c[i0, A_N] - chk_c[im, A_N])
        out_f[O_WMIN] = min(out_f[O_WMIN], mm)
        out_f[O_WMAX] = max(out_f[O_WMAX], mm)
        span = 0.5 * ((chk_k[i2] + chk_k[i1]) - (chk_k[i1] + chk_k[i0]))
        monotone = (m1 - m0) * (m0 - mm) > 0.0
        out_f[O_DRIFT] = (m1 - m0) / span if monotone else 0.0
    if _pure_forward_slip(win):
        # exactly 1 whatever the state: no evidence about the long-time average
        out_f[O_ERR] = math.inf
        return False
    return out_f[O_ERR] <= tol_mean


@jit
def _fractions(win, status, out_f):
    total = win[A_STICK] + win[A_SLIP] + win[A_FLIGHT]
    if total <= 0.0 or status == ST_FAILED:
        total = math.nan
    out_f[O_STICK] = win[A_STICK] / total
    out_f[O_SLIP] = win[A_SLIP] / total
    out_f[O_SLIP_NEG] = win[A_SLIP_NEG] / total
    out_f[O_FLIGHT] = win[A_FLIGHT] / total


@jit
def steady_state(alpha, beta, a, V, zeta, eta, init_kind, y0, xd0, e0, ph0, max_periods,
                 min_periods, tol_state, tol_mean, max_events, out_f, out_i):
    """Long-time average from a given start, written into the rows ``out_f``, ``out_i``.

    ``init_kind``: 0 steady sliding, 1 rest, 2 explicit state ``(y0, x0', e0, ph0)``
    at ``tau = 0``.  The columns are ``solver.FLOAT_COLUMNS`` and
    ``solver.INT_COLUMNS``; the fractions are of time in the averaging window and
    the state is the final one on the section.
    """
    M = make_model(alpha, beta, a, V, zeta, eta)
    z = np.empty(5)  # y, x', e, phase, e' (exact rate where known, else nan)
    if init_kind == 2:
        z[0], z[1], z[2], z[3], z[4] = y0, xd0, e0, ph0, math.nan
    else:
        z[0], z[1], z[2], z[3], z[4] = initial_state(init_kind, M)
    z0 = z.copy()
    orbit_ok, ys, yds, es = sliding_orbit(M)
    nring = MAX_PERIOD + 1
    ring_z = np.zeros((nring, 5))
    ring_c = np.zeros((nring, N_ACC))
    dprev = np.full(nring, np.inf)
    chk_c = np.zeros((MAX_CHECKPOINTS, N_ACC))
    chk_k = np.zeros(MAX_CHECKPOINTS)
    acc = np.zeros(N_ACC)
    count = np.zeros(3, np.int64)
    win = np.zeros(N_ACC)
    ring_z[0, :] = z
    out_f[:] = math.nan
    nchk = 0
    next_chk = min_periods
    next_newton = FIRST_NEWTON
    first_jump = -1
    mu_first = math.nan
    k = 0
    period = 0
    while True:
        if not advance_period(z, acc, count, M, max_events):
            status = ST_FAILED
            break
        k += 1
        ring_z[k % nring, :] = z
        ring_c[k % nring, :] = acc
        p, d, rho = detect_period(ring_z, dprev, k, M, tol_state)
        if p > 0:
            _window(acc, ring_c, k, p, win)
            count[C_EVENTS] += periodic_result(z, z0, win, p, k, rho, first_jump, mu_first,
                                               M, max_events, out_f)
            status = ST_PERIODIC
            period = p
            break
        if sliding_certificate(z[0], z[1], z[2], int(z[3]), M, orbit_ok, ys, yds, es):
            out_f[O_MU], out_f[O_ERR], out_f[O_SETTLE] = 1.0, 0.0, k
            win[:] = 0.0
            win[A_SLIP] = 1.0
            status = ST_SLIDING
            break
        if k == next_newton and k < max_periods:
            next_newton = k + max(1, k // 2)
            pn, ev = try_newton(z, ring_z, dprev, k, M, tol_state, max_events)
            count[C_EVENTS] += ev
            if pn > 0 and first_jump < 0:
                _window(acc, ring_c, k, pn, win)
                first_jump, mu_first = k, _window_mu(win)
        if k == next_chk or k >= max_periods:
            if nchk < MAX_CHECKPOINTS:
                chk_c[nchk, :] = acc
                chk_k[nchk] = k
                nchk += 1
            next_chk *= 2
            if check_average(chk_k, chk_c, nchk, k >= max_periods, tol_mean, win, out_f):
                out_f[O_SETTLE] = k
                status = ST_AVERAGED
                break
            if k >= max_periods:
                # no answer: the window means (range in O_WMIN, O_WMAX) are not one
                status = ST_NOT_CONVERGED
                if nchk < 2:
                    win[:] = acc
                    out_f[O_WMIN] = out_f[O_WMAX] = acc[A_F] / acc[A_N]
                out_f[O_MU] = math.nan
                out_f[O_ERR] = math.inf
                break
    if status == ST_FAILED or not math.isfinite(out_f[O_ERR]):
        out_f[O_ERR] = math.inf  # no estimate: nothing is known about the value
    elif 0.0 < eta < ETA_ELASTIC and not math.isinf(beta):
        out_f[O_ERR] += ETA_SLOPE * eta  # solved as an elastic contact (phases.ETA_ELASTIC)
    _fractions(win, status, out_f)
    out_f[O_Y], out_f[O_XD], out_f[O_E] = z[0], z[1], z[2]
    out_f[O_F] = contact_force(M, int(z[3]), 0.0, z[0], z[1], z[2])
    out_i[I_STATUS] = status
    out_i[I_PERIOD] = period
    out_i[I_PERIODS] = k
    out_i[I_EVENTS] = count[C_EVENTS]
    out_i[I_PHASE] = int(z[3])
    out_i[I_DEGENERATE] = count[C_DEGENERATE]


@jit
def steady_state_many(alpha, beta, a, V, zeta, eta, init_kind, init, max_periods, min_periods,
                      tol_state, tol_mean, max_events, out_f, out_i):
    """:func:`steady_state` over arrays of points (one compiled loop, no Python calls).

    ``init`` has shape ``(n, 4)`` (used when ``init_kind == 2``); row ``i`` of
    ``out_f`` and ``out_i`` receives point ``i``.
    """
    for i in range(V.shape[0]):
        steady_state(alpha[i], beta[i], a[i], V[i], zeta[i], eta[i], init_kind, init[i, 0],
                     init[i, 1],
                     init[i, 2], int(init[i, 3]), max_periods, min_periods, tol_state,
                     tol_mean, max_events, out_f[i], out_i[i])
