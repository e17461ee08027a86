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

* stick -> slip where the margin ``s_r n_i - |k e_i|`` reaches 0 (slip sign ``sign e_i``;
  ``s_r = static_ratio >= 1``, the static limit over the kinetic one, ``sr`` in the code);
  the margins of all stuck springs are one function of time minus each spring's constant
  ``s_r w g_i +- k e_i``, so only the largest constant on each side is scanned, and the
  springs sharing it (a cluster that stuck together) slip together; a slipping spring
  exerts the kinetic ``+-n_i``, so where ``s_r > 1`` its force drops at the switch (its
  energy goes to friction's dissipation) and, where the slip velocity is not positive
  there, it sticks again at once (:func:`_slip_jump`);
* slip -> stick where the slip velocity ``s (y' + V) - n_i'/k`` reaches 0: the same for
  every spring slipping in direction ``s`` (``n_i' = -w a sin tau``), so the group sticks
  at once;
* lift-off and touch-down at the known phases ``cos tau = (g_i - 1)/a``; a spring touching
  down starts unloaded, stuck if ``k |x'| <= s_r n_i'`` there, else slipping with ``sign x'``.

A longitudinal in-plane oscillation ``X = a_x cos(tau + phase_x)`` (issue 20,
docs/inplane.md) enters as in the single-spring kernels (:func:`.phases.inplane_forcing`):
the body is described in the substrate's frame (``y`` relative to the substrate, where a
stuck spring's contact point is at rest), and the body ODE gains the force
``h = hc cos tau + hs sin tau`` (substrate: ``(1 - alpha) X - gamma X'``, the frame's
inertial force and the pin's spring and dashpot pulling on ``x = y + X``; holder: ``alpha X
+ gamma X'``). In that frame a stuck spring's elongation is still ``e_i0 + (y - y0) + V t``
(the substrate carries its contact point), the slip velocity ``y' + V`` is relative to the
substrate, and the four group functions below are unchanged; ``h`` is at the drive
frequency, so it joins ``S_w a cos tau`` in the periodic response of the closed form, and
its integral over a period is 0 (the period's ``int sum f_i`` keeps its form).

These four group functions are scanned on sub-steps of the segment (``2 pi/substeps`` or
``0.5/sqrt(alpha + K)``, longer where each group's value over a bound of its derivative on
the segment shows it cannot reach 0 within the step), and no root is missed
(:func:`_first_crossing`, as the flat punch's :func:`.roots.first_root`): a sub-step whose
ends are positive is proven free of roots by a bound ``M`` of the function's second
derivative on the segment (:func:`_scan_bounds`; the linear interpolant's error
``M h^2/8``, or the tangent parabolas from both ends), else bisected, leftmost first, so a
dip below zero and back within a sub-step (a pair of close roots, a grazing event) is
found; the bisection stops where ``M h^2/8`` falls to the round-off tolerance (``1e-12`` of
the function's scale), so a dip shallower than that counts as a touch. The earliest sign
change is refined to round-off (Newton steps in the bracket, Illinois as fallback) and
ends the segment (a scan costs O(1), not O(springs); switching groups as a whole, not
spring by spring at round-off distances, removed the stalls of the first version). A group
that has just switched starts at its root, so a sign change in its first sub-step is
bracketed by a positive value nearer the start (where the start's slope guarantees one,
``f >= f'(0) t - M t^2/2``, then at halvings of the step: a spring touching down stuck may
slip again within the sub-step); a rise shorter than 1/65536 of the sub-step that the
start's slope does not guarantee is the one case still passed over (a group still below 0
at the next segment's start switches there).

Each spring's state is one of the package's contact states (:mod:`.codes`, from
``vibrofriction.schema.ContactState``): ``STICK``, ``SLIP_POS``, ``SLIP_NEG`` or ``FLIGHT``
(out of contact).

The bookkeeping between events is O(log M) an event (:func:`_switch`: each state's
members, running sums, max-trees of the stuck springs' constants relative to their common
displacement since the section, the contact events sorted by phase), rebuilt at each
section; :func:`steady_row` is the row's steady-state loop (Anderson mixing) compiled.

``run_periods(..., rec=(tau, body, f, state, ip))`` also records the row at the times ``tau``
(:func:`_record_segment`; the MDR time history, :mod:`vibrofriction.solver.mdr_history`).
"""

import math

import numpy as np

from .basis import (
    EXP,
    OSC,
    _u_bound,
    basis_values,
    derivative,
    dot,
    initial_pair,
    integral,
    integral_basis,
    make_mode,
)
from .codes import FLIGHT, SLIP_NEG, SLIP_POS, STICK
from .jit import jit, jit_bare
from .phases import _periodic_response

TWO_PI = 2.0 * math.pi


@jit
def row_geometry(a, n_exp, M):
    """``(g, w, dxi, tau_off, tau_on, area)``: the springs' gaps, the normal weight, the
    cell width, the lift-off and touch-down phases (``-1`` if the spring never leaves, or
    never touches) and each spring's share of the disc of the largest contact radius.
    """
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
def _segment(alpha, gamma, K, E0, y0, yd0, Sw, Swg, V, a, theta, hc, hs):
    """Coefficients of ``y(t)`` on the segment from phase ``theta`` and its mode; ``hc``,
    ``hs`` the in-plane force ``h = hc cos tau + hs sin tau`` on the body (0: none).
    """
    w0sq = alpha + K
    m = make_mode(w0sq, 0.5 * gamma, 0.0)
    c0 = -(E0 - K * y0) - Sw + Swg
    c1 = -K * V
    cc = -Sw * a
    p1 = c1 / w0sq
    p0 = (c0 - gamma * p1) / w0sq
    # the harmonic forces at the drive frequency, Re(W e^{it}), W = wr + i wi
    wr = cc * math.cos(theta)
    wi = cc * math.sin(theta)
    forced = hc != 0.0 or hs != 0.0
    if forced:  # h(theta + t) = (hc cos + hs sin) cos t - (hc sin - hs cos) sin t
        ct = math.cos(theta)
        sn = math.sin(theta)
        wr += hc * ct + hs * sn
        wi += hc * sn - hs * ct
    near = False
    zr = 0.0
    zi = 0.0
    if cc != 0.0 or forced:
        zr, zi, near = _periodic_response(m, wr, wi)
    if not near:
        D, E = initial_pair(m, y0 - p0 - zr, yd0 - p1 + zi)
        return (p0, p1, zr, -zi, D, E, 0.0, 0.0, 0.0), m
    D, E = initial_pair(m, y0 - p0, yd0 - p1)
    return (p0, p1, 0.0, 0.0, D, E, wr, -wi, 0.0), m


@jit
def _group_value(kind, cp, cm, w, sw, k, a, V, y, yd, y0, t, ctau, stau):
    """The event function of a group: ``kind`` 0 the stuck springs' margin towards positive
    slip, ``sw (1 + a cos tau) - k u - cp`` (``sw = static_ratio w``: a stuck spring holds
    while ``k |e_i| <= static_ratio n_i``; ``u = y - y0 + V t``, ``cp`` the largest
    ``sw g_i + k e_i`` of the stuck springs), 1 towards negative slip (``cm`` the largest
    ``sw g_i - k e_i``), 2 and 3 the slip velocity of the springs slipping forwards and
    backwards (the same for every spring of the group: ``n_i' = -w a sin tau``);
    ``ctau``, ``stau``: ``cos tau``, ``sin tau``.
    """
    if kind == 0:
        return sw * (1.0 + a * ctau) - k * (y - y0 + V * t) - cp
    if kind == 1:
        return sw * (1.0 + a * ctau) + k * (y - y0 + V * t) - cm
    if kind == 2:
        return (yd + V) + (w * a / k) * stau
    return -(yd + V) + (w * a / k) * stau


@jit
def _group_slope(kind, w, sw, k, a, V, yd, ydd, ctau, stau):
    """The derivative of :func:`_group_value` (``ydd`` = ``y''``)."""
    if kind == 0:
        return -sw * a * stau - k * (yd + V)
    if kind == 1:
        return -sw * a * stau + k * (yd + V)
    if kind == 2:
        return ydd + (w * a / k) * ctau
    return -ydd + (w * a / k) * ctau


@jit
def _refine_group(c, dc, m, cs, kind, cp, cm, w, sw, k, a, V, y0, cth, sth, ta, tb, fa, fb):
    """The root of a group's event function on ``[ta, tb]`` (``fa > 0 >= fb``; ``cth``,
    ``sth`` the cosine and sine of the segment's start phase) to round-off: Newton steps
    (the slope in closed form) kept inside the bracket (else regula falsi, Illinois), a
    converged step pushed just across the root to close the bracket; returns the right
    end of the final bracket (where the function is <= 0).
    """
    ddc = derivative(dc, m)
    side = 0
    t = (ta * fb - tb * fa) / (fb - fa)
    for _ in range(200):
        if tb - ta <= 2e-16 * max(1.0, tb):
            break
        if not (ta < t < tb):
            t = (ta * fb - tb * fa) / (fb - fa)
            if not (ta < t < tb):
                t = 0.5 * (ta + tb)
        b = basis_values(m, t, cs, False)
        ct = cth * b[2] - sth * b[3]
        st = sth * b[2] + cth * b[3]
        yd = dot(dc, b)
        f = _group_value(kind, cp, cm, w, sw, k, a, V, dot(c, b), yd, y0, t, ct, st)
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
            if f == 0.0:
                break
        d = _group_slope(kind, w, sw, k, a, V, yd, dot(ddc, b), ct, st)
        dt = -f / d if d != 0.0 else np.inf
        res = 1e-16 * max(1.0, t)
        if abs(dt) <= res:  # converged: step just across the root to close the bracket
            dt = 2.0 * res if f > 0.0 else -2.0 * res
        t = t + dt
    return tb


@jit
def _group_point(c, dc, ddc, m, cs, kind, cp, cm, w, sw, k, a, V, y0, cth, sth, t):
    """A group's event function and its derivative at ``t`` (:func:`_group_value`,
    :func:`_group_slope`).
    """
    b = basis_values(m, t, cs, False)
    ct = cth * b[2] - sth * b[3]
    st = sth * b[2] + cth * b[3]
    yd = dot(dc, b)
    return (_group_value(kind, cp, cm, w, sw, k, a, V, dot(c, b), yd, y0, t, ct, st),
            _group_slope(kind, w, sw, k, a, V, yd, dot(ddc, b), ct, st))


@jit
def _sup(c, m, T, u):
    """:func:`.basis.sup_bound` of ``c`` on ``[0, T]`` (no relaxation term), ``u`` the
    bound of the responses ``|C + i S|`` (:func:`.basis._u_bound`), square roots for
    ``hypot`` (the bound's own margin of 1e-12 covers their rounding).
    """
    b = max(abs(c[0]), abs(c[0] + c[1] * T)) + math.sqrt(c[2] * c[2] + c[3] * c[3])
    if u != 0.0:
        b += math.sqrt(c[6] * c[6] + c[7] * c[7]) * u
    D, E = c[4], c[5]
    if m[0] == EXP:
        b += abs(D) + abs(E)
    elif m[0] == OSC:
        q = m[3]
        b += min(math.sqrt(D * D + (E / q) * (E / q)), abs(D) + abs(E) * T)
    else:
        b += abs(D) + abs(E) * T
    return b * (1.0 + 1e-12)


@jit
def _scan_bounds(dc, ddc, m, T, w, sw, k, a, V):
    """``(L_m, L_v, M_m, M_v)``: bounds on ``[0, T]`` of the groups' first derivatives
    (margins: ``|f'| <= sw a + k (|y'| + |V|)``, ``sw = static_ratio w``; slip velocities:
    ``|y''| + w a/k``), for the scan's longer steps, and of their second derivatives
    (margins: ``|f''| <= sw a + k |y''|``; slip velocities: ``|y'''| + w a/k``), for
    :func:`_first_crossing`; ``dc``, ``ddc`` the coefficients of ``y'``, ``y''`` (the
    bounds of :func:`.basis.sup_bound`).
    """
    u = 0.0
    if dc[6] != 0.0 or dc[7] != 0.0 or ddc[6] != 0.0 or ddc[7] != 0.0:
        u = _u_bound(m, T)
    s2 = _sup(ddc, m, T, u)
    return (sw * a + k * (_sup(dc, m, T, u) + abs(V)), s2 + w * a / k, sw * a + k * s2,
            _sup(derivative(ddc, m), m, T, u) + w * a / k)


@jit
def _first_crossing(c, dc, ddc, m, cs, kind, cp, cm, w, sw, k, a, V, y0, cth, sth, ta, fa, da,
                    tb, fb, db, m2, tol, stk):
    """The earliest sign change of a group's event function ``f`` on ``[ta, tb]`` (values
    ``fa``, ``fb`` and slopes ``da``, ``db`` at the ends), never missed, as in
    :func:`.roots.first_root`: with ``m2`` a bound of ``|f''|`` on the interval, a piece
    whose ends are positive holds no root where ``min(fa, fb) > m2 h^2/8`` (the linear
    interpolant's error) or where the tangent parabolas from its ends stay positive up to
    its midpoint; a piece ending at or below 0 holds one root where ``f`` is monotone
    (``f' <= min(da + m2 (t - ta), db + m2 (tb - t)) < 0``: ``da + db + m2 h < 0``); other
    pieces are bisected, leftmost first, down to the width at
    which ``m2 h^2/8 <= tol``: a dip of at most ``tol`` (round-off) there is a touch, not
    an event. ``stk``: scratch of right ends ``(t, f, f')``.

    Returns ``(tl, fl, dl, tr, fr, dr)``: the earliest bracket, ``fl > 0 >= fr``, or, where the
    left end is not positive (a group at its root at the segment's start), the first right
    end at or below 0; ``tr = -1``: no root.
    """
    stk[0, 0] = tb
    stk[0, 1] = fb
    stk[0, 2] = db
    top = 0
    while top >= 0:
        b = stk[top, 0]
        fb = stk[top, 1]
        db = stk[top, 2]
        h = b - ta
        q = 0.125 * m2 * h * h
        last = q <= tol or top >= stk.shape[0] - 1
        if fb <= 0.0:
            if fa <= 0.0 or da + db + m2 * h < 0.0 or last:
                return ta, fa, da, b, fb, db
        else:
            hh = 0.5 * h
            dip = 0.5 * m2 * hh * hh
            if last or min(fa, fb) > q or (fa + da * hh - dip > 0.0
                                           and fb - db * hh - dip > 0.0):
                ta, fa, da = b, fb, db
                top -= 1
                continue
        t = 0.5 * (ta + b)
        f, d = _group_point(c, dc, ddc, m, cs, kind, cp, cm, w, sw, k, a, V, y0, cth, sth, t)
        top += 1
        stk[top, 0] = t
        stk[top, 1] = f
        stk[top, 2] = d
    return ta, fa, da, -1.0, 0.0, 0.0


# the columns of a recorded sample (:func:`run_periods`' ``rec``): the body's ``y``, ``y'``,
# ``sum f_i``, ``sum n_i``, and the integrals since the start of ``sum f_i``, ``sum n_i``, the
# work input by the pulled end, the energy dissipated by the pin's dashpot and by friction
R_Y, R_YD, R_F, R_N, R_IF, R_IN, R_WIN, R_DPIN, R_DFRIC = range(9)
N_REC = 9
_GL_X, _GL_W = np.polynomial.legendre.leggauss(8)


@jit
def _record_state(rec, ri, acc, y, yd, tau, u, st, e, g, w, k, a):
    """Write sample ``ri`` of ``rec``: the body at ``(y, y')``, phase ``tau``, the stuck
    springs' elongations ``e_i + u``, the integrals ``acc``.
    """
    body, fs, sts = rec[1], rec[2], rec[3]
    F = 0.0
    N = 0.0
    ca = 1.0 + a * math.cos(tau)
    for i in range(g.size):
        s = st[i]
        sts[ri, i] = s
        f = 0.0
        if s != FLIGHT:
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
                Swg, Wa, Wga, hc, hs, ip):
    """Add the integrals over ``[ta, tb]`` of a segment to ``acc``: ``sum f_i =
    -(y'' + gamma y' + alpha y) + h`` and ``sum n_i`` (the springs in contact: ``Wc = w``
    times their number, ``Wgc`` their ``w g_i``) exactly; the work input, the pin's
    dissipation and friction's ``sum f_i (x' - e_i')`` (slipping springs: ``(y' + V) sum s
    n_i + (w a sin tau/k) sum n_i``, ``Sw, Swg`` signed, ``Wa, Wga`` not) by 8-point
    Gauss-Legendre on pieces of at most ``h``. Without an in-plane oscillation the work
    input ``V (-alpha y - gamma y')`` is exact and the pin dissipates ``gamma y'^2``; with
    one, ``ip = (c, d, holder)`` (``X = c cos tau - d sin tau``), the laboratory's
    definitions of :mod:`vibrofriction.solver.energy` (substrate: ``V (-alpha (y + X) -
    gamma (y' + X')) - X' sum f_i`` and ``gamma (y' + X')^2``; holder: ``(V + X') (alpha
    (X - y) + gamma (X' - y'))`` and ``gamma (X' - y')^2``).
    """
    if tb <= ta:
        return
    ba = basis_values(m, ta, cs, False)
    bb = basis_values(m, tb, cs, False)
    dy = dot(c, bb) - dot(c, ba)
    iy = integral(c, m, tb) - integral(c, m, ta)
    ih = hc * (math.sin(theta + tb) - math.sin(theta + ta)) \
        - hs * (math.cos(theta + tb) - math.cos(theta + ta))
    acc[0] += -((dot(dc, bb) - dot(dc, ba)) + gamma * dy + alpha * iy) + ih
    acc[1] += (Wc - Wgc) * (tb - ta) + Wc * a * (math.sin(theta + tb) - math.sin(theta + ta))
    oscillating = ip[0] != 0.0 or ip[1] != 0.0
    holder = ip[2] != 0.0
    ddc = derivative(dc, m)
    if not oscillating:
        acc[2] += V * (-alpha * iy - gamma * dy)
    pieces = int(math.ceil((tb - ta) / h))
    half = 0.5 * (tb - ta) / pieces
    dw = 0.0
    dp = 0.0
    df = 0.0
    for j in range(pieces):
        mid = ta + (2 * j + 1) * half
        for q in range(_GL_X.size):
            t = mid + half * _GL_X[q]
            b = basis_values(m, t, cs, False)
            ydt = dot(dc, b)
            tau = theta + t
            ca = 1.0 + a * math.cos(tau)
            df += _GL_W[q] * ((ydt + V) * (Sw * ca - Swg)
                              + (w * a * math.sin(tau) / k) * (Wa * ca - Wga))
            if not oscillating:
                dp += _GL_W[q] * gamma * ydt * ydt
                continue
            X = ip[0] * math.cos(tau) - ip[1] * math.sin(tau)
            Xd = -ip[0] * math.sin(tau) - ip[1] * math.cos(tau)
            yt = dot(c, b)
            if holder:
                dw += _GL_W[q] * (V + Xd) * (alpha * (X - yt) + gamma * (Xd - ydt))
                dp += _GL_W[q] * gamma * (Xd - ydt) ** 2
            else:
                F = -(dot(ddc, b) + gamma * ydt + alpha * yt) \
                    + hc * math.cos(tau) + hs * math.sin(tau)
                dw += _GL_W[q] * (V * (-alpha * (yt + X) - gamma * (ydt + Xd)) - F * Xd)
                dp += _GL_W[q] * gamma * (ydt + Xd) ** 2
    acc[2] += half * dw
    acc[3] += half * dp
    acc[4] += half * df


@jit
def _record_segment(rec, ri, acc, c, dc, m, cs, t0, T, theta, alpha, gamma, K, V, a, g, w,
                    k, st, e, y0, hc, hs):
    """Record the samples of ``rec`` at times in ``[t0, t0 + T)`` of the segment that starts
    at time ``t0`` (phase ``theta``, body ``y0``, closed form ``c``) and add the segment's
    integrals to ``acc``; returns the next sample's index.
    """
    rtau = rec[0]
    ip = rec[4]
    Wc = 0.0
    Wgc = 0.0
    Sw = 0.0
    Swg = 0.0
    Wa = 0.0
    Wga = 0.0
    for i in range(g.size):
        s = st[i]
        if s != FLIGHT:
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
                    Sw, Swg, Wa, Wga, hc, hs, ip)
        tq = ts
        b = basis_values(m, ts, cs, False)
        yv = dot(c, b)
        _record_state(rec, ri, acc, yv, dot(dc, b), theta + ts, yv - y0 + V * ts, st, e, g,
                      w, k, a)
        ri += 1
    _accumulate(acc, c, dc, m, cs, theta, tq, T, h, alpha, gamma, V, a, w, k, Wc, Wgc, Sw,
                Swg, Wa, Wga, hc, hs, ip)
    return ri


# the running sums of the row's bookkeeping (:func:`_switch`): the stuck springs' elongations
# relative to the common displacement ``U`` (``e_i = eh_i + U``), the gaps of the springs
# slipping forwards and backwards, the stuck and the slipping springs' areas
S_EH, S_GP, S_GN, S_AST, S_ASL = range(5)


@jit
def _tree_set(tree, P, i, v):
    """Set leaf ``i`` of the max-tree ``tree`` (leaves at ``P + i``) to ``v``."""
    j = P + i
    tree[j] = v
    j >>= 1
    while j >= 1:
        lv = tree[2 * j]
        rv = tree[2 * j + 1]
        tree[j] = lv if lv > rv else rv
        j >>= 1


@jit
def _tree_collect(tree, P, thr, stack, out, n, skip):
    """Append to ``out`` (from ``n``) the leaves of ``tree`` at or above ``thr``, except
    where ``skip``; returns the new count. Visits only the branches whose maximum is at or
    above ``thr``: O(found log M).
    """
    if tree[1] < thr:
        return n
    top = 0
    stack[0] = 1
    while top >= 0:
        j = stack[top]
        top -= 1
        if j >= P:
            if not skip[j - P]:
                out[n] = j - P
                n += 1
            continue
        if tree[2 * j] >= thr:
            top += 1
            stack[top] = 2 * j
        if tree[2 * j + 1] >= thr:
            top += 1
            stack[top] = 2 * j + 1
    return n


@jit
def _switch(i, new, eh_new, st, eh, memb, cnt, pos, sums, tp, tm, P, g, sw, k, area):
    """Move spring ``i`` to the state ``new`` (a stuck one with ``eh_i = eh_new``), keeping
    the members of each state, the running sums and the stuck springs' max-trees of
    ``sw g_i +- k eh_i`` (``sw = static_ratio w``) up to date: O(log M).
    """
    old = st[i]
    if old == STICK:
        sums[S_EH] -= eh[i]
        sums[S_AST] -= area[i]
        _tree_set(tp, P, i, -np.inf)
        _tree_set(tm, P, i, -np.inf)
    elif old == SLIP_POS:
        sums[S_GP] -= g[i]
        sums[S_ASL] -= area[i]
    elif old == SLIP_NEG:
        sums[S_GN] -= g[i]
        sums[S_ASL] -= area[i]
    p = pos[i]
    last = memb[old, cnt[old] - 1]
    memb[old, p] = last
    pos[last] = p
    cnt[old] -= 1
    memb[new, cnt[new]] = i
    pos[i] = cnt[new]
    cnt[new] += 1
    st[i] = new
    eh[i] = 0.0
    if new == STICK:
        eh[i] = eh_new
        sums[S_EH] += eh_new
        sums[S_AST] += area[i]
        _tree_set(tp, P, i, sw * g[i] + k * eh_new)
        _tree_set(tm, P, i, sw * g[i] - k * eh_new)
    elif new == SLIP_POS:
        sums[S_GP] += g[i]
        sums[S_ASL] += area[i]
    elif new == SLIP_NEG:
        sums[S_GN] += g[i]
        sums[S_ASL] += area[i]


@jit
def _rebuild(st, e, eh, memb, cnt, pos, sums, tp, tm, P, g, sw, k, area):
    """The bookkeeping of :func:`_switch` from scratch (``U = 0``, ``eh = e``): at every
    section, so that the running sums carry no round-off from period to period.
    """
    cnt[:] = 0
    sums[:] = 0.0
    tp[:] = -np.inf
    tm[:] = -np.inf
    for i in range(g.size):
        s = st[i]
        memb[s, cnt[s]] = i
        pos[i] = cnt[s]
        cnt[s] += 1
        eh[i] = 0.0
        if s == STICK:
            eh[i] = e[i]
            sums[S_EH] += e[i]
            sums[S_AST] += area[i]
            tp[P + i] = sw * g[i] + k * e[i]
            tm[P + i] = sw * g[i] - k * e[i]
        elif s == SLIP_POS:
            sums[S_GP] += g[i]
            sums[S_ASL] += area[i]
        elif s == SLIP_NEG:
            sums[S_GN] += g[i]
            sums[S_ASL] += area[i]
    for j in range(P - 1, 0, -1):
        lv = tp[2 * j]
        rv = tp[2 * j + 1]
        tp[j] = lv if lv > rv else rv
        lv = tm[2 * j]
        rv = tm[2 * j + 1]
        tm[j] = lv if lv > rv else rv


@jit
def _row_setup(a, n_exp, M):
    """The row's fixed data: :func:`row_geometry`, ``int sum n_i`` over a period and the
    contact events sorted by phase (``ev_ph``, the spring ``ev_i``, touch-down ``ev_on``).
    """
    g, w, dxi, tau_off, tau_on, area = row_geometry(a, n_exp, M)
    nint = normal_integral_row(a, g, w, tau_off)
    nl = 0
    for i in range(M):
        if tau_off[i] >= 0.0:
            nl += 1
    ev_ph = np.zeros(2 * nl)
    ev_i = np.zeros(2 * nl, dtype=np.int64)
    ev_on = np.zeros(2 * nl, dtype=np.bool_)
    j = 0
    for i in range(M):
        if tau_off[i] >= 0.0:
            ev_ph[j] = tau_off[i]
            ev_i[j] = i
            ev_ph[j + 1] = tau_on[i]
            ev_i[j + 1] = i
            ev_on[j + 1] = True
            j += 2
    order = np.argsort(ev_ph, kind="mergesort")
    return g, w, dxi, tau_off, tau_on, area, nint, ev_ph[order], ev_i[order], ev_on[order]


@jit
def _scratch(M):
    """Work arrays of :func:`_period`: the max-trees (``P`` leaves, a stack for their
    search), each state's members, the running sums, ``eh``, the springs switched at the
    last event, buffers; the four groups' values, roots and flags, their slopes and the
    stack of :func:`_first_crossing`.
    """
    P = 1
    while P < M:
        P *= 2
    depth = 1
    while (1 << depth) < P:
        depth += 1
    return (P, np.zeros(2 * depth + 4, dtype=np.int64), np.full(2 * P, -np.inf),
            np.full(2 * P, -np.inf), np.zeros((4, M), dtype=np.int64),
            np.zeros(4, dtype=np.int64), np.zeros(M, dtype=np.int64), np.zeros(5),
            np.zeros(M), np.zeros(M, dtype=np.int64), np.zeros(M, dtype=np.int64),
            np.zeros(M, dtype=np.bool_), np.zeros(M), np.zeros(4), np.zeros(4),
            np.zeros(4, dtype=np.bool_), np.zeros(4, dtype=np.bool_), np.zeros(4),
            np.zeros((64, 3)))


@jit
def _slip_jump(i, forward, e_i, xd, ctau, stau, a, w, k, g, acc, st, eh, memb, cnt, pos, sums,
               tp, tm, P, sw, area, U):
    """Stick to slip of spring ``i`` where ``static_ratio > 1`` (``forward``: towards
    positive slip; ``e_i`` its elongation at the static limit, ``xd`` the body's velocity
    relative to the substrate, ``ctau``, ``stau``: ``cos tau``, ``sin tau``). Its force drops
    to the kinetic ``n_i`` (the massless contact point jumps): the spring's energy
    ``(k^2 e_i^2 - n_i^2)/(2 k)`` goes to the friction's dissipation ``acc[4]``. Where the
    slip velocity ``s x' - n_i'/k`` is not positive there the slip ends at once: the spring
    sticks again at the kinetic force, ``e_i = s n_i/k``.
    """
    n = max(w * (1.0 + a * ctau - g[i]), 0.0)
    acc[4] += 0.5 * (k * e_i * e_i - n * n / k)
    sgn = 1.0 if forward else -1.0
    if sgn * xd + (w * a / k) * stau > 0.0:  # :func:`_group_value` 2 or 3
        _switch(i, SLIP_POS if forward else SLIP_NEG, 0.0, st, eh, memb, cnt, pos, sums, tp,
                tm, P, g, sw, k, area)
    else:
        _switch(i, STICK, sgn * n / k - U, st, eh, memb, cnt, pos, sums, tp, tm, P, g, sw, k,
                area)


@jit_bare
def _period(alpha, beta, a, V, gamma, M, substeps, hc, hs, geo, scr, period, y, yd, st, e,
            frac, viol, rec, ri, acc, sr):
    """One period of the row from the section state ``(y, y', st, e)`` (``st``, ``e``
    modified in place; :func:`run_periods`). Returns ``(y, y', int y, events, no progress,
    ri, viol)``; ``frac`` gets the period's area fractions.
    """
    g, w, dxi, tau_off, tau_on, area, nint, ev_ph, ev_i, ev_on = geo
    (P, stack, tp, tm, memb, cnt, pos, sums, eh, fl, buf, taken, e_cur, gprev, groot, gon,
     gfresh, gslope, stk) = scr
    k = (beta - alpha) * dxi
    sw = sr * w  # the static limit's weight: a stuck spring holds while k |e_i| <= sr n_i
    tol_c = 1e-11 * w * (2.0 + a)
    tol_s = 1e-12 * w * (1.0 + a + abs(g[M - 1]))
    nev = ev_ph.size
    tol_ev = 1e-13 * TWO_PI
    stuck_loop = False
    _rebuild(st, e, eh, memb, cnt, pos, sums, tp, tm, P, g, sw, k, area)
    U = 0.0
    nf = 0
    ptr = 0
    theta = 0.0
    iy = 0.0
    fr0 = 0.0
    fr1 = 0.0
    fr2 = 0.0
    events = 0
    segments = 0
    while theta < TWO_PI:
        segments += 1
        if segments > 200 * M + 1000:  # no progress: report, do not hang
            stuck_loop = True
            break
        nst = cnt[STICK]
        K = k * nst
        E0 = k * (sums[S_EH] + nst * U)
        Sw = w * (cnt[SLIP_POS] - cnt[SLIP_NEG])
        Swg = w * (sums[S_GP] - sums[S_GN])
        a_st = sums[S_AST]
        a_sl = sums[S_ASL]
        gon[0] = nst > 0
        gon[1] = nst > 0
        gon[2] = cnt[SLIP_POS] > 0
        gon[3] = cnt[SLIP_NEG] > 0
        cph = tp[1]  # the largest constants, relative to U
        cmh = tm[1]
        cp = cph + k * U if nst > 0 else -np.inf
        cm = cmh - k * U if nst > 0 else -np.inf
        # a group that has just switched (its event function at 0 by construction)
        gfresh[:] = False
        for q in range(nf):
            i = fl[q]
            s = st[i]
            if s == STICK:
                if sw * g[i] + k * eh[i] >= cph - tol_c:
                    gfresh[0] = True
                if sw * g[i] - k * eh[i] >= cmh - tol_c:
                    gfresh[1] = True
            elif s == SLIP_POS:
                gfresh[2] = True
            elif s == SLIP_NEG:
                gfresh[3] = True
        c, m = _segment(alpha, gamma, K, E0, y, yd, Sw, Swg, V, a, theta, hc, hs)
        dc = derivative(c, m)
        cth = math.cos(theta)
        sth = math.sin(theta)
        cs = c[6] != 0.0 or c[7] != 0.0
        # the known contact events and the section bound the segment: the next
        # contact event after theta that applies (a touch-down of a spring out of
        # contact, a lift-off of one in contact; one that does not apply now never
        # will in this period)
        while ptr < nev:
            i = ev_i[ptr]
            if ev_ph[ptr] > theta and (st[i] == FLIGHT) == ev_on[ptr]:
                break
            ptr += 1
        T = TWO_PI - theta
        if ptr < nev and ev_ph[ptr] - theta < T:
            T = ev_ph[ptr] - theta
        # values at the start; a group at or past its event (not just switched)
        # switches now
        tol_v = 1e-12 * (abs(yd) + abs(V) + w * a / k)
        ddc = derivative(dc, m)
        b = basis_values(m, 0.0, cs, False)
        ydd = dot(ddc, b)
        immediate = False
        for j in range(4):
            groot[j] = np.inf
            if not gon[j]:
                continue
            gprev[j] = _group_value(j, cp, cm, w, sw, k, a, V, y, yd, y, 0.0, cth, sth)
            gslope[j] = _group_slope(j, w, sw, k, a, V, yd, ydd, cth, sth)
            tl = tol_s if j < 2 else tol_v
            if not gfresh[j] and gprev[j] < -tl:
                groot[j] = 0.0
                immediate = True
        t_ev = T
        t_b = -1.0  # the last scan point (its basis values b)
        scanned = immediate
        if scanned:
            t_ev = 0.0
        else:
            h = min(TWO_PI / substeps, 0.5 / math.sqrt(alpha + K))
            lb_m, lb_v, m2_m, m2_v = _scan_bounds(dc, ddc, m, T, w, sw, k, a, V)
            ta = 0.0
            while ta < T and not scanned:
                step = h
                if ta > 0.0:
                    # a longer step where no group can reach 0 within it: each group's
                    # value over the bound of its derivative; never shorter than the
                    # fixed sub-step h
                    hs_ = np.inf
                    for j in range(4):
                        if gon[j]:
                            hj = gprev[j] / (lb_m if j < 2 else lb_v)
                            if hj < hs_:
                                hs_ = hj
                    if hs_ > step:
                        step = hs_
                clear = step > h  # every group positive on [ta, tb) by that bound
                tb = min(T, ta + step)
                b = basis_values(m, tb, cs, False)
                yb = dot(c, b)
                ydb = dot(dc, b)
                yddb = dot(ddc, b)
                ctau = cth * b[2] - sth * b[3]
                stau = sth * b[2] + cth * b[3]
                best = T
                for j in range(4):
                    if not gon[j]:
                        continue
                    f = _group_value(j, cp, cm, w, sw, k, a, V, yb, ydb, y, tb, ctau, stau)
                    d = _group_slope(j, w, sw, k, a, V, ydb, yddb, ctau, stau)
                    if j < 2 and f > 0.0 and -f > viol:
                        viol = -f
                    fa = gprev[j]
                    if f <= 0.0 and fa <= 0.0 and ta == 0.0 and not gfresh[j]:
                        groot[j] = 0.0  # at its event within round-off, and leaving
                        best = 0.0
                        scanned = True
                    elif (fa > 0.0 or ta == 0.0) and not (clear and f > 0.0):
                        # the earliest root on [ta, tb], none missed (a dip below 0 and
                        # back within the sub-step included); the tests of
                        # _first_crossing on the whole sub-step first, inline
                        m2 = m2_m if j < 2 else m2_v
                        hh = 0.5 * (tb - ta)
                        dip = 0.5 * m2 * hh * hh
                        if f > 0.0 and fa > 0.0 and (min(fa, f) > dip or (
                                fa + gslope[j] * hh > dip and f - d * hh > dip)):
                            gprev[j] = f
                            gslope[j] = d
                            continue
                        tl = tol_s if j < 2 else tol_v
                        tq, fq, dq, tr, fr, dr = _first_crossing(
                            c, dc, ddc, m, cs, j, cp, cm, w, sw, k, a, V, y, cth, sth, ta, fa,
                            gslope[j], tb, f, d, m2, tl, stk)
                        if tr >= 0.0 and fq <= 0.0:
                            # a group at its root at the start (just switched) can rise
                            # and fall back within the first sub-step (a spring touching
                            # down stuck, slipping again 0.002 later): a positive value
                            # nearer the start brackets that root (first where the
                            # start's slope and m2 guarantee one, f >= f(0) + f'(0) t -
                            # m2 t^2/2, then halving); none: no event
                            t0_, f0_, d0_ = tr, fr, dr
                            tr = -1.0
                            for it in range(17):
                                if it == 0:
                                    tp_ = dq / m2 if dq > 0.0 else 0.0
                                    if not 0.0 < tp_ < t0_:
                                        continue
                                else:
                                    tp_ = t0_ * 0.5 ** it
                                fp, dp = _group_point(c, dc, ddc, m, cs, j, cp, cm, w, sw, k,
                                                      a, V, y, cth, sth, tp_)
                                if fp > tl:
                                    tq, fq, dq, tr, fr, dr = _first_crossing(
                                        c, dc, ddc, m, cs, j, cp, cm, w, sw, k, a, V, y, cth,
                                        sth, tp_, fp, dp, t0_, f0_, d0_, m2, tl, stk)
                                    break
                        if tr >= 0.0:
                            r = _refine_group(c, dc, m, cs, j, cp, cm, w, sw, k, a, V, y, cth,
                                              sth, tq, tr, fq, fr)
                            groot[j] = r
                            if r < best:
                                best = r
                            scanned = True
                    gprev[j] = f
                    gslope[j] = d
                if scanned:
                    t_ev = best
                t_b = tb
                ta = tb
        if rec is not None:
            for i in range(M):
                e_cur[i] = eh[i] + U if st[i] == STICK else 0.0
            ri = _record_segment(rec, ri, acc, c, dc, m, cs, TWO_PI * period + theta,
                                 t_ev, theta, alpha, gamma, K, V, a, g, w, k, st, e_cur,
                                 y, hc, hs)
        # advance to t_ev
        if t_ev != t_b:
            b = basis_values(m, t_ev, cs, False)
        y1 = dot(c, b)
        yd1 = dot(dc, b)
        iy += integral_basis(c, m, t_ev, b)
        fr0 += a_st * t_ev
        fr1 += a_sl * t_ev
        fr2 += (1.0 - a_st - a_sl) * t_ev
        tau = theta + t_ev
        U += y1 - y + V * t_ev  # the stuck springs' elongations follow
        nf = 0
        if scanned:
            # the group(s) whose refined root is t_ev switch as a whole: collect them
            # all first (the stuck cluster at the largest constant, towards positive
            # slip before negative; every spring slipping one way), then switch
            nb = 0
            if groot[0] <= t_ev:
                nb = _tree_collect(tp, P, cph - tol_c, stack, buf, nb, taken)
            n0 = nb
            for q in range(n0):
                taken[buf[q]] = True
            if groot[1] <= t_ev:
                nb = _tree_collect(tm, P, cmh - tol_c, stack, buf, nb, taken)
            for q in range(n0):
                taken[buf[q]] = False
            n1 = nb
            if groot[2] <= t_ev:
                for q in range(cnt[SLIP_POS]):
                    buf[nb] = memb[SLIP_POS, q]
                    nb += 1
            n2 = nb
            if groot[3] <= t_ev:
                for q in range(cnt[SLIP_NEG]):
                    buf[nb] = memb[SLIP_NEG, q]
                    nb += 1
            for q in range(nb):
                i = buf[q]
                if q < n1 and sr != 1.0:
                    _slip_jump(i, q < n0, eh[i] + U, yd1 + V, cth * b[2] - sth * b[3],
                               sth * b[2] + cth * b[3], a, w, k, g, acc, st, eh, memb, cnt,
                               pos, sums, tp, tm, P, sw, area, U)
                elif q < n0:
                    _switch(i, SLIP_POS, 0.0, st, eh, memb, cnt, pos, sums, tp, tm, P,
                            g, sw, k, area)
                elif q < n1:
                    _switch(i, SLIP_NEG, 0.0, st, eh, memb, cnt, pos, sums, tp, tm, P,
                            g, sw, k, area)
                else:
                    n = w * (1.0 + a * (cth * b[2] - sth * b[3]) - g[i])
                    sgn = 1.0 if q < n2 else -1.0
                    _switch(i, STICK, sgn * max(n, 0.0) / k - U, st, eh, memb, cnt,
                            pos, sums, tp, tm, P, g, sw, k, area)
                fl[nf] = i
                nf += 1
                events += 1
        elif t_ev < TWO_PI - theta:
            q = ptr
            while q < nev and ev_ph[q] <= tau + tol_ev:
                i = ev_i[q]
                if abs(ev_ph[q] - tau) <= tol_ev and (st[i] == FLIGHT) == ev_on[q]:
                    if ev_on[q]:
                        rate = -w * a * (sth * b[2] + cth * b[3])
                        xd = yd1 + V
                        if k * abs(xd) <= sr * rate:  # the static limit grows faster
                            _switch(i, STICK, -U, st, eh, memb, cnt, pos, sums, tp, tm,
                                    P, g, sw, k, area)
                        else:
                            _switch(i, SLIP_POS if xd > 0.0 else SLIP_NEG, 0.0, st, eh,
                                    memb, cnt, pos, sums, tp, tm, P, g, sw, k, area)
                    else:
                        _switch(i, FLIGHT, 0.0, st, eh, memb, cnt, pos, sums, tp, tm, P,
                                g, sw, k, area)
                    fl[nf] = i
                    nf += 1
                    events += 1
                q += 1
        theta = tau if t_ev < TWO_PI - theta else TWO_PI
        y = y1
        yd = yd1
    for i in range(M):  # the section's elongations
        e[i] = eh[i] + U if st[i] == STICK else 0.0
    frac[0] = fr0 / TWO_PI
    frac[1] = fr1 / TWO_PI
    frac[2] = fr2 / TWO_PI
    return y, yd, iy, events, stuck_loop, ri, viol


@jit
def run_periods(alpha, beta, a, V, gamma, n_exp, M, substeps, min_periods, max_periods,
                state_tol, y, yd, st, e, hc=0.0, hs=0.0, rec=None, sr=1.0):
    """Integrate the row period by period from the section state ``(y, y', st, e)``
    (modified in place) until the section state repeats within ``state_tol`` (relative to
    its size) after at least ``min_periods``, or ``max_periods``. ``hc``, ``hs``: the
    in-plane force on the body (module docstring; ``y`` then relative to the substrate).

    The scanned events come in four groups, each decided by one function of time
    (:func:`_group_value`): every stuck spring's margin is a common function of time minus
    its own constant ``w g_i +- k e_i``, so the stuck spring with the largest constant
    slips first (and with it every stuck spring of the same constant: a cluster that
    stuck together), and every spring slipping the same way has the same slip velocity,
    so the group sticks at once. Switching groups as a whole, not spring by spring at
    round-off distances, is what keeps the event count per period bounded.

    Returns ``(periods, converged, pf, pn, frac, viol, events, y, yd)``: the per-period
    integrals of ``sum f_i`` (``pf``, exact: ``-(alpha int y + gamma [y] + [y'])``, the
    in-plane force integrating to 0 over a period) and
    of ``sum n_i`` (``pn``), the time-averaged area fractions (stick, slip, out of
    contact) of the last period, the largest ``|f_i| - sr n_i`` of the stuck springs seen at
    the scan points, the
    number of events of the last period (``-1``: no progress) and the final body state.

    ``rec = (tau, body, f, state, ip)``, optional: record the samples at the sorted times
    ``tau`` (from the start, ``T`` of them): ``body`` (``T x N_REC``, columns ``R_*``),
    every spring's tangential force ``f`` and state ``state`` (``T x M``), from the closed
    forms (:func:`_record_segment`; ``ip = (c, d, holder)`` the in-plane oscillation
    ``X = c cos tau - d sin tau`` of the substrate or, ``holder != 0``, of the holder, for
    the energies: :func:`_accumulate`); pass ``min_periods = max_periods``.  ``sr``: the
    static ratio ``mu_static/mu0 >= 1`` (module docstring).
    """
    geo = _row_setup(a, n_exp, M)
    scr = _scratch(M)
    g, w, dxi = geo[0], geo[1], geo[2]
    k = (beta - alpha) * dxi
    pf = np.zeros(max_periods)
    pn = np.full(max_periods, geo[6])
    frac = np.zeros(3)
    viol = -np.inf
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
        y, yd, iy, events, stuck_loop, ri, viol = _period(
            alpha, beta, a, V, gamma, M, substeps, hc, hs, geo, scr, period, y, yd, st, e,
            frac, viol, rec, ri, acc, sr)
        periods = period + 1
        if stuck_loop:
            break
        pf[period] = -(alpha * iy + gamma * (y - y_old) + (yd - yd_old))
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


@jit
def _anderson_step(xs, gs, nh, out):
    """Anderson mixing (type II, no damping) from the ``nh`` iterates ``xs`` and their
    images ``gs`` (rows, oldest first): the combination of the images whose residuals'
    combination is smallest (least squares as ``numpy.linalg.lstsq``, ``rcond`` its
    default); written to ``out``.
    """
    n = xs.shape[1]
    dF = np.empty((n, nh - 1))
    for q in range(nh - 1):
        for i in range(n):
            dF[i, q] = (gs[q + 1, i] - xs[q + 1, i]) - (gs[q, i] - xs[q, i])
    fl = np.empty(n)
    for i in range(n):
        fl[i] = gs[nh - 1, i] - xs[nh - 1, i]
    coef = np.linalg.lstsq(dF, fl, rcond=np.finfo(np.float64).eps * max(n, nh - 1))[0]
    for i in range(n):
        v = gs[nh - 1, i]
        for q in range(nh - 1):
            v -= coef[q] * (gs[q + 1, i] - gs[q, i])
        out[i] = v


@jit
def steady_row(alpha, beta, a, V, gamma, n_exp, M, substeps, state_tol, max_periods,
               accelerate, anderson, accelerated_periods, y, yd, st, e, hc=0.0, hs=0.0,
               sr=1.0):
    """The row's steady state from the section state ``(y, y', st, e)`` (modified in
    place): the period map iterated until the section state repeats within ``state_tol``
    (relative), with ``accelerate`` first (for at most ``accelerated_periods``) with the
    continuous part of the state (``y``, ``y'``, the stuck springs' elongations) updated by
    Anderson mixing of the last ``anderson`` period maps once the springs' states at the
    section repeat (a change of them restarts the history), then plain iteration (at
    least 5 periods of it before convergence counts). The loop of
    :func:`vibrofriction.solver.mdr.mdr_row`, compiled; ``sr`` the static ratio.

    Returns ``(periods, converged, pf, nint, frac, viol, events, y, yd)``: the per-period
    ``int sum f_i``, ``int sum n_i`` over a period, the last period's area fractions, the
    largest ``|f_i| - sr n_i`` of the stuck springs at the scan points (``sr`` the static
    ratio), the last period's events (``-1``: no
    progress) and the final body state.
    """
    geo = _row_setup(a, n_exp, M)
    scr = _scratch(M)
    pf = np.zeros(max_periods)
    frac = np.zeros(3)
    viol = -np.inf
    acc = np.zeros(N_REC - R_IF)
    n = M + 2
    xs = np.zeros((anderson, n))
    gs = np.zeros((anderson, n))
    x = np.zeros(n)
    gx = np.zeros(n)
    xn = np.zeros(n)
    st_in = st.copy()
    st_hist = st.copy()
    e_old = np.zeros(M)
    nh = 0
    periods = 0
    conv = False
    events = 0
    plain = 0  # periods of plain iteration
    while periods < max_periods:
        acc_phase = accelerate and periods < accelerated_periods
        x[0] = y
        x[1] = yd
        x[2:] = e
        st_in[:] = st
        e_old[:] = e
        y_old = y
        yd_old = yd
        y, yd, iy, events, stuck_loop, _, viol = _period(
            alpha, beta, a, V, gamma, M, substeps, hc, hs, geo, scr, periods, y, yd, st, e,
            frac, viol, None, 0, acc, sr)
        periods += 1
        if stuck_loop:
            events = -1
            break
        pf[periods - 1] = -(alpha * iy + gamma * (y - y_old) + (yd - yd_old))
        gx[0] = y
        gx[1] = yd
        gx[2:] = e
        same = True
        for i in range(M):
            if st[i] != st_in[i]:
                same = False
        scale = 1e-300
        d = 0.0
        for i in range(n):
            scale += abs(gx[i])
            d += abs(gx[i] - x[i])
        if not acc_phase:
            plain += 1
            if same and d <= state_tol * scale and plain >= min(5, max_periods - periods
                                                                 + plain):
                conv = True
                break
            continue
        if same and d <= state_tol * scale and periods >= 2:
            conv = True
            break
        hist_same = True
        for i in range(M):
            if st[i] != st_hist[i]:
                hist_same = False
        if not (same and hist_same):
            nh = 0
            st_hist[:] = st
        if nh == anderson:
            for q in range(anderson - 1):
                xs[q] = xs[q + 1]
                gs[q] = gs[q + 1]
            nh -= 1
        xs[nh] = x
        gs[nh] = gx
        nh += 1
        if nh >= 2 and same:
            _anderson_step(xs, gs, nh, xn)
            y = xn[0]
            yd = xn[1]
            for i in range(M):
                e[i] = xn[2 + i] if st[i] == STICK else 0.0
    return periods, conv, pf[:periods], geo[6], frac, viol, events, y, yd
