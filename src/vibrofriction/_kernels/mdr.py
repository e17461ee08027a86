r"""Event-driven kernel of the MDR spring row (issue 21, docs/contact_geometry.md).

The scaled row: springs at the midpoints ``xi_i`` of ``M`` cells on ``(0, xi_max]``,
``g_i = xi_i^n`` (0 for the flat punch), normal force ``n_i = w max(0, 1 + a cos tau - g_i)``
(``w = dxi (n + 1)/n``, flat ``dxi``), tangential stiffness ``k = (beta - alpha) dxi``; the
body, drift removed (``y = x - V tau``): ``y'' + gamma y' + alpha y = -sum f_i``.

With the indentation imposed every ``n_i(tau)`` is known, so between events the body ODE is
linear with constant coefficients: a stuck spring (contact point fixed, elongation
``e_i = e_i0 + (y - y0) + V t``) adds ``k`` to the stiffness, a slipping one (massless
contact point, sign ``s``) exerts ``s n_i(tau)``, one out of contact nothing::

    y'' + gamma y' + (alpha + K) y = -(E0 - K y0) - K V t - S_w (1 + a cos(theta + t)) + S_wg

(``K`` = k times the stuck springs, ``E0 = k sum e_i0`` over them, ``S_w = w sum s``,
``S_wg = w sum s g_i`` over the slipping ones). Its closed form is written over the
package's basis (:mod:`.basis`: free motion, periodic response or, near the resonance
``alpha + K = 1``, the responses from rest). Events:

* stick -> slip where the margin ``n_i - |k e_i|`` reaches 0 (slip sign ``sign e_i``);
  the margins of all stuck springs are one function of time minus each spring's constant
  ``w g_i +- k e_i``, so only the largest constant on each side is scanned, and the
  springs sharing it (a cluster that stuck together) slip together;
* slip -> stick where the slip velocity ``s (y' + V) - n_i'/k`` reaches 0: the same for
  every spring slipping in direction ``s`` (``n_i' = -w a sin tau``), so the group sticks
  at once;
* lift-off and touch-down at the known phases ``cos tau = (g_i - 1)/a``; a spring touching
  down starts unloaded, stuck if ``k |x'| <= n_i'`` there, else slipping with ``sign x'``.

These four group functions are scanned on sub-steps of the segment (at most
``2 pi/substeps`` and ``0.5/sqrt(alpha + K)``), a sign change is refined by the Illinois
method to round-off, and the earliest root ends the segment (a scan costs O(1), not
O(springs); switching groups as a whole, not spring by spring at round-off distances,
removed the stalls of the first version). A dip below
zero shorter than a sub-step is not seen (a grazing event); that is the method's only
approximation besides round-off.
"""

import math

import numpy as np

from .basis import basis_values, derivative, dot, initial_pair, integral, make_mode
from .jit import jit
from .phases import _periodic_response

TWO_PI = 2.0 * math.pi
OFF, STICK, SLIP_POS, SLIP_NEG = 0, 1, 2, 3


@jit
def row_geometry(a, n_exp, M):
    """``(g, w, dxi, tau_off, tau_on, area)``: the springs' gaps, the normal weight, the
    cell width, the lift-off and touch-down phases (``-1`` if the spring never leaves, or
    never touches) and each spring's share of the disc of the largest contact radius."""
    flat = math.isinf(n_exp)
    xi_max = 1.0 if flat else (1.0 + a) ** (1.0 / n_exp)
    dxi = xi_max / M
    w = dxi if flat else dxi * (n_exp + 1.0) / n_exp
    g = np.zeros(M)
    tau_off = np.full(M, -1.0)
    tau_on = np.full(M, -1.0)
    area = np.zeros(M)
    for i in range(M):
        xi = (i + 0.5) * dxi
        if not flat:
            g[i] = xi ** n_exp
        area[i] = 2.0 * xi * dxi / (xi_max * xi_max)
        if a > 0.0 and g[i] - 1.0 > -a:  # leaves the contact in the cycle
            th = math.acos(min(1.0, (g[i] - 1.0) / a))
            tau_off[i] = th
            tau_on[i] = TWO_PI - th
    return g, w, dxi, tau_off, tau_on, area


@jit
def normal_integral_row(a, g, w, tau_off):
    """``int_0^{2 pi} sum_i n_i dtau``."""
    s = 0.0
    for i in range(g.size):
        if tau_off[i] < 0.0:
            s += w * TWO_PI * (1.0 - g[i])
        else:
            th = tau_off[i]
            s += w * (2.0 * th * (1.0 - g[i]) + 2.0 * a * math.sin(th))
    return s


@jit
def _segment(alpha, gamma, K, E0, y0, yd0, Sw, Swg, V, a, theta):
    """Coefficients of ``y(t)`` on the segment from phase ``theta`` and its mode."""
    w0sq = alpha + K
    m = make_mode(w0sq, 0.5 * gamma, 0.0)
    c0 = -(E0 - K * y0) - Sw + Swg
    c1 = -K * V
    cc = -Sw * a
    p1 = c1 / w0sq
    p0 = (c0 - gamma * p1) / w0sq
    wr = cc * math.cos(theta)
    wi = cc * math.sin(theta)
    near = False
    zr = 0.0
    zi = 0.0
    if cc != 0.0:
        zr, zi, near = _periodic_response(m, wr, wi)
    if not near:
        D, E = initial_pair(m, y0 - p0 - zr, yd0 - p1 + zi)
        return (p0, p1, zr, -zi, D, E, 0.0, 0.0, 0.0), m
    D, E = initial_pair(m, y0 - p0, yd0 - p1)
    return (p0, p1, 0.0, 0.0, D, E, wr, -wi, 0.0), m


@jit
def _group_value(kind, cp, cm, w, k, a, V, y, yd, y0, t, tau):
    """The event function of a group: ``kind`` 0 the stuck springs' margin towards positive
    slip, ``w (1 + a cos tau) - k u - cp`` (``u = y - y0 + V t``, ``cp`` the largest
    ``w g_i + k e_i`` of the stuck springs), 1 towards negative slip (``cm`` the largest
    ``w g_i - k e_i``), 2 and 3 the slip velocity of the springs slipping forwards and
    backwards (the same for every spring of the group: ``n_i' = -w a sin tau``)."""
    if kind == 0:
        return w * (1.0 + a * math.cos(tau)) - k * (y - y0 + V * t) - cp
    if kind == 1:
        return w * (1.0 + a * math.cos(tau)) + k * (y - y0 + V * t) - cm
    if kind == 2:
        return (yd + V) + (w * a / k) * math.sin(tau)
    return -(yd + V) + (w * a / k) * math.sin(tau)


@jit
def _refine_group(c, dc, m, cs, kind, cp, cm, w, k, a, V, y0, theta, ta, tb, fa, fb):
    """Illinois iteration for the root of a group's event function on ``[ta, tb]``
    (``fa > 0 >= fb``); returns the right end of the final bracket."""
    side = 0
    for _ in range(200):
        if tb - ta <= 2e-16 * max(1.0, tb):
            break
        t = (ta * fb - tb * fa) / (fb - fa)
        if not (ta < t < tb):
            t = 0.5 * (ta + tb)
        b = basis_values(m, t, cs, False)
        f = _group_value(kind, cp, cm, w, k, a, V, dot(c, b), dot(dc, b), y0, t, theta + t)
        if f > 0.0:
            ta, fa = t, f
            if side == -1:
                fb *= 0.5
            side = -1
        else:
            tb, fb = t, f
            if side == 1:
                fa *= 0.5
            side = 1
    return tb


# the columns of a recorded sample (:func:`run_periods`' ``rec``): the body's ``y``, ``y'``,
# ``sum f_i``, ``sum n_i``, and the integrals since the start of ``sum f_i``, ``sum n_i``, the
# work input by the pulled end, the energy dissipated by the pin's dashpot and by friction
R_Y, R_YD, R_F, R_N, R_IF, R_IN, R_WIN, R_DPIN, R_DFRIC = range(9)
N_REC = 9
_GL_X, _GL_W = np.polynomial.legendre.leggauss(8)


@jit
def _record_state(rec, ri, acc, y, yd, tau, u, st, e, g, w, k, a):
    """Write sample ``ri`` of ``rec``: the body at ``(y, y')``, phase ``tau``, the stuck
    springs' elongations ``e_i + u``, the integrals ``acc``."""
    _, body, fs, sts = rec
    F = 0.0
    N = 0.0
    ca = 1.0 + a * math.cos(tau)
    for i in range(g.size):
        s = st[i]
        sts[ri, i] = s
        f = 0.0
        if s != OFF:
            n = max(w * (ca - g[i]), 0.0)
            N += n
            if s == STICK:
                f = k * (e[i] + u)
            elif s == SLIP_POS:
                f = n
            else:
                f = -n
        fs[ri, i] = f
        F += f
    body[ri, R_Y] = y
    body[ri, R_YD] = yd
    body[ri, R_F] = F
    body[ri, R_N] = N
    for j in range(acc.size):
        body[ri, R_IF + j] = acc[j]


@jit
def _accumulate(acc, c, dc, m, cs, theta, ta, tb, h, alpha, gamma, V, a, w, k, Wc, Wgc, Sw,
                Swg, Wa, Wga):
    """Add the integrals over ``[ta, tb]`` of a segment to ``acc``: ``sum f_i =
    -(y'' + gamma y' + alpha y)`` and ``sum n_i`` (the springs in contact: ``Wc = w`` times
    their number, ``Wgc`` their ``w g_i``) and the work input ``V (-alpha y - gamma y')``
    exactly; the pin's ``gamma y'^2`` and friction's ``sum f_i (x' - e_i')`` (slipping
    springs: ``(y' + V) sum s n_i + (w a sin tau/k) sum n_i``, ``Sw, Swg`` signed, ``Wa,
    Wga`` not) by 8-point Gauss-Legendre on pieces of at most ``h``."""
    if tb <= ta:
        return
    ba = basis_values(m, ta, cs, False)
    bb = basis_values(m, tb, cs, False)
    dy = dot(c, bb) - dot(c, ba)
    iy = integral(c, m, tb) - integral(c, m, ta)
    acc[0] += -((dot(dc, bb) - dot(dc, ba)) + gamma * dy + alpha * iy)
    acc[1] += (Wc - Wgc) * (tb - ta) + Wc * a * (math.sin(theta + tb) - math.sin(theta + ta))
    acc[2] += V * (-alpha * iy - gamma * dy)
    pieces = int(math.ceil((tb - ta) / h))
    half = 0.5 * (tb - ta) / pieces
    dp = 0.0
    df = 0.0
    for j in range(pieces):
        mid = ta + (2 * j + 1) * half
        for q in range(_GL_X.size):
            t = mid + half * _GL_X[q]
            ydt = dot(dc, basis_values(m, t, cs, False))
            tau = theta + t
            ca = 1.0 + a * math.cos(tau)
            dp += _GL_W[q] * gamma * ydt * ydt
            df += _GL_W[q] * ((ydt + V) * (Sw * ca - Swg)
                              + (w * a * math.sin(tau) / k) * (Wa * ca - Wga))
    acc[3] += half * dp
    acc[4] += half * df


@jit
def _record_segment(rec, ri, acc, c, dc, m, cs, t0, T, theta, alpha, gamma, K, V, a, g, w,
                    k, st, e, y0):
    """Record the samples of ``rec`` at times in ``[t0, t0 + T)`` of the segment that starts
    at time ``t0`` (phase ``theta``, body ``y0``, closed form ``c``) and add the segment's
    integrals to ``acc``; returns the next sample's index."""
    rtau = rec[0]
    Wc = 0.0
    Wgc = 0.0
    Sw = 0.0
    Swg = 0.0
    Wa = 0.0
    Wga = 0.0
    for i in range(g.size):
        s = st[i]
        if s != OFF:
            Wc += w
            Wgc += w * g[i]
        if s == SLIP_POS or s == SLIP_NEG:
            sg = 1.0 if s == SLIP_POS else -1.0
            Sw += sg * w
            Swg += sg * w * g[i]
            Wa += w
            Wga += w * g[i]
    h = min(0.25, 0.5 / math.sqrt(alpha + K))
    tq = 0.0
    while ri < rtau.size and rtau[ri] < t0 + T:
        ts = min(max(rtau[ri] - t0, 0.0), T)
        _accumulate(acc, c, dc, m, cs, theta, tq, ts, h, alpha, gamma, V, a, w, k, Wc, Wgc,
                    Sw, Swg, Wa, Wga)
        tq = ts
        b = basis_values(m, ts, cs, False)
        yv = dot(c, b)
        _record_state(rec, ri, acc, yv, dot(dc, b), theta + ts, yv - y0 + V * ts, st, e, g,
                      w, k, a)
        ri += 1
    _accumulate(acc, c, dc, m, cs, theta, tq, T, h, alpha, gamma, V, a, w, k, Wc, Wgc, Sw,
                Swg, Wa, Wga)
    return ri


@jit
def run_periods(alpha, beta, a, V, gamma, n_exp, M, substeps, min_periods, max_periods,
                state_tol, y, yd, st, e, rec=None):
    """Integrate the row period by period from the section state ``(y, y', st, e)``
    (modified in place) until the section state repeats within ``state_tol`` (relative to
    its size) after at least ``min_periods``, or ``max_periods``.

    The scanned events come in four groups, each decided by one function of time
    (:func:`_group_value`): every stuck spring's margin is a common function of time minus
    its own constant ``w g_i +- k e_i``, so the stuck spring with the largest constant
    slips first (and with it every stuck spring of the same constant: a cluster that
    stuck together), and every spring slipping the same way has the same slip velocity,
    so the group sticks at once. Switching groups as a whole, not spring by spring at
    round-off distances, is what keeps the event count per period bounded.

    Returns ``(periods, converged, pf, pn, frac, viol, events, y, yd)``: the per-period
    integrals of ``sum f_i`` (``pf``, exact: ``-(alpha int y + gamma [y] + [y'])``) and
    of ``sum n_i`` (``pn``), the time-averaged area fractions (stick, slip, out of
    contact) of the last period, the largest ``|f_i| - n_i`` seen at the scan points, the
    number of events of the last period (``-1``: no progress) and the final body state.

    ``rec = (tau, body, f, state)``, optional: record the samples at the sorted times
    ``tau`` (from the start, ``T`` of them): ``body`` (``T x N_REC``, columns ``R_*``),
    every spring's tangential force ``f`` and state ``state`` (``T x M``), from the closed
    forms (:func:`_record_segment`); pass ``min_periods = max_periods``.
    """
    g, w, dxi, tau_off, tau_on, area = row_geometry(a, n_exp, M)
    k = (beta - alpha) * dxi
    nint = normal_integral_row(a, g, w, tau_off)
    tol_c = 1e-11 * w * (2.0 + a)
    pf = np.zeros(max_periods)
    pn = np.full(max_periods, nint)
    frac = np.zeros(3)
    viol = -np.inf
    fresh = np.zeros(M, dtype=np.bool_)
    gprev = np.zeros(4)
    groot = np.zeros(4)
    gon = np.zeros(4, dtype=np.bool_)
    gfresh = np.zeros(4, dtype=np.bool_)
    stuck_loop = False
    e_old = np.zeros(M)
    st_old = np.zeros(M, dtype=np.int64)
    periods = 0
    converged = False
    events = 0
    ri = 0  # the next sample to record
    acc = np.zeros(N_REC - R_IF)  # the recorded integrals since the start
    for period in range(max_periods):
        y_old = y
        yd_old = yd
        e_old[:] = e
        st_old[:] = st
        theta = 0.0
        iy = 0.0
        fr0 = 0.0
        fr1 = 0.0
        fr2 = 0.0
        events = 0
        fresh[:] = False
        segments = 0
        while theta < TWO_PI:
            segments += 1
            if segments > 200 * M + 1000:  # no progress: report, do not hang
                stuck_loop = True
                break
            K = 0.0
            E0 = 0.0
            Sw = 0.0
            Swg = 0.0
            a_st = 0.0
            a_sl = 0.0
            cp = -np.inf
            cm = -np.inf
            gon[:] = False
            for i in range(M):
                s = st[i]
                if s == STICK:
                    K += k
                    E0 += k * e[i]
                    a_st += area[i]
                    gon[0] = True
                    gon[1] = True
                    cp = max(cp, w * g[i] + k * e[i])
                    cm = max(cm, w * g[i] - k * e[i])
                elif s == SLIP_POS:
                    Sw += w
                    Swg += w * g[i]
                    a_sl += area[i]
                    gon[2] = True
                elif s == SLIP_NEG:
                    Sw -= w
                    Swg -= w * g[i]
                    a_sl += area[i]
                    gon[3] = True
            # a group that has just switched (its event function at 0 by construction)
            gfresh[:] = False
            for i in range(M):
                if fresh[i]:
                    s = st[i]
                    if s == STICK:
                        if w * g[i] + k * e[i] >= cp - tol_c:
                            gfresh[0] = True
                        if w * g[i] - k * e[i] >= cm - tol_c:
                            gfresh[1] = True
                    elif s == SLIP_POS:
                        gfresh[2] = True
                    elif s == SLIP_NEG:
                        gfresh[3] = True
            c, m = _segment(alpha, gamma, K, E0, y, yd, Sw, Swg, V, a, theta)
            dc = derivative(c, m)
            cs = c[6] != 0.0 or c[7] != 0.0
            # the known contact events and the section bound the segment
            T = TWO_PI - theta
            for i in range(M):
                if tau_off[i] < 0.0:
                    continue
                tt = tau_on[i] if st[i] == OFF else tau_off[i]
                if tt > theta and tt - theta < T:
                    T = tt - theta
            # values at the start; a group at or past its event (not just switched)
            # switches now
            tol_s = 1e-12 * w * (1.0 + a + abs(g[M - 1]))
            tol_v = 1e-12 * (abs(yd) + abs(V) + w * a / k)
            immediate = False
            for j in range(4):
                groot[j] = np.inf
                if not gon[j]:
                    continue
                gprev[j] = _group_value(j, cp, cm, w, k, a, V, y, yd, y, 0.0, theta)
                tl = tol_s if j < 2 else tol_v
                if not gfresh[j] and gprev[j] < -tl:
                    groot[j] = 0.0
                    immediate = True
            t_ev = T
            scanned = immediate
            if scanned:
                t_ev = 0.0
            else:
                h = min(TWO_PI / substeps, 0.5 / math.sqrt(alpha + K))
                ta = 0.0
                while ta < T and not scanned:
                    tb = min(T, ta + h)
                    b = basis_values(m, tb, cs, False)
                    yb = dot(c, b)
                    ydb = dot(dc, b)
                    tau = theta + tb
                    best = T
                    for j in range(4):
                        if not gon[j]:
                            continue
                        f = _group_value(j, cp, cm, w, k, a, V, yb, ydb, y, tb, tau)
                        if j < 2 and f > 0.0 and -f > viol:
                            viol = -f
                        fa = gprev[j]
                        tq = ta
                        if f <= 0.0 and fa <= 0.0 and ta == 0.0 and gfresh[j]:
                            # a group that has just switched (its function at 0) can rise
                            # and fall back within the first sub-step (a spring touching
                            # down stuck, slipping again 0.002 later): a positive value
                            # nearer the start brackets that root
                            tl = tol_s if j < 2 else tol_v
                            tp = tb
                            for _ in range(12):
                                tp *= 0.5
                                bp = basis_values(m, tp, cs, False)
                                fp = _group_value(j, cp, cm, w, k, a, V, dot(c, bp),
                                                  dot(dc, bp), y, tp, theta + tp)
                                if fp > tl:
                                    fa = fp
                                    tq = tp
                                    break
                        if f <= 0.0 and fa <= 0.0 and ta == 0.0 and not gfresh[j]:
                            groot[j] = 0.0  # at its event within round-off, and leaving
                            best = 0.0
                            scanned = True
                        elif f <= 0.0 and fa > 0.0:
                            r = _refine_group(c, dc, m, cs, j, cp, cm, w, k, a, V, y, theta,
                                              tq, tb, fa, f)
                            groot[j] = r
                            if r < best:
                                best = r
                            scanned = True
                        gprev[j] = f
                    if scanned:
                        t_ev = best
                    ta = tb
            if rec is not None:
                ri = _record_segment(rec, ri, acc, c, dc, m, cs, TWO_PI * period + theta,
                                     t_ev, theta, alpha, gamma, K, V, a, g, w, k, st, e, y)
            # advance to t_ev
            b = basis_values(m, t_ev, cs, False)
            y1 = dot(c, b)
            yd1 = dot(dc, b)
            iy += integral(c, m, t_ev)
            fr0 += a_st * t_ev
            fr1 += a_sl * t_ev
            fr2 += (1.0 - a_st - a_sl) * t_ev
            tau = theta + t_ev
            u = y1 - y + V * t_ev
            fresh[:] = False
            if scanned:
                # the group(s) whose refined root is t_ev switch as a whole
                for i in range(M):
                    s = st[i]
                    if s == OFF:
                        continue
                    n = w * (1.0 + a * math.cos(tau) - g[i])
                    if s == STICK:
                        sw = 0
                        if groot[0] <= t_ev and w * g[i] + k * e[i] >= cp - tol_c:
                            sw = SLIP_POS
                        elif groot[1] <= t_ev and w * g[i] - k * e[i] >= cm - tol_c:
                            sw = SLIP_NEG
                        e[i] = e[i] + u
                        if sw != 0:
                            st[i] = sw
                            e[i] = 0.0
                            fresh[i] = True
                            events += 1
                    elif (s == SLIP_POS and groot[2] <= t_ev) or \
                            (s == SLIP_NEG and groot[3] <= t_ev):
                        sgn = 1.0 if s == SLIP_POS else -1.0
                        st[i] = STICK
                        e[i] = sgn * max(n, 0.0) / k
                        fresh[i] = True
                        events += 1
            else:
                for i in range(M):
                    if st[i] == STICK:
                        e[i] = e[i] + u
                if t_ev < TWO_PI - theta:
                    for i in range(M):
                        if tau_off[i] < 0.0:
                            continue
                        if st[i] == OFF:
                            if abs(tau_on[i] - tau) <= 1e-13 * TWO_PI:
                                rate = -w * a * math.sin(tau)
                                xd = yd1 + V
                                if k * abs(xd) <= rate:
                                    st[i] = STICK
                                else:
                                    st[i] = SLIP_POS if xd > 0.0 else SLIP_NEG
                                e[i] = 0.0
                                fresh[i] = True
                                events += 1
                        elif abs(tau_off[i] - tau) <= 1e-13 * TWO_PI:
                            st[i] = OFF
                            e[i] = 0.0
                            fresh[i] = True
                            events += 1
            theta = tau if t_ev < TWO_PI - theta else TWO_PI
            y = y1
            yd = yd1
        periods = period + 1
        if stuck_loop:
            break
        pf[period] = -(alpha * iy + gamma * (y - y_old) + (yd - yd_old))
        frac[0] = fr0 / TWO_PI
        frac[1] = fr1 / TWO_PI
        frac[2] = fr2 / TWO_PI
        # section-state change
        scale_s = abs(y) + abs(yd) + 1e-300
        d = abs(y - y_old) + abs(yd - yd_old)
        same = True
        for i in range(M):
            if st[i] != st_old[i]:
                same = False
            d += abs(e[i] - e_old[i])
            scale_s += abs(e[i])
        if same and d <= state_tol * scale_s and periods >= min_periods:
            converged = True
            break
    if stuck_loop:
        events = -1
    elif rec is not None:  # the samples at the end (the last section)
        while ri < rec[0].size:
            _record_state(rec, ri, acc, y, yd, rec[0][ri], 0.0, st, e, g, w, k, a)
            ri += 1
    return periods, converged, pf[:periods], pn[:periods], frac, viol, events, y, yd
