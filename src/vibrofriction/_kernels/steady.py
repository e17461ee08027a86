r"""The steady state and the macroscopic coefficient of friction (paper eq. 25).

``mu_macro / mu0 = <f> / <n>`` over the steady state, with both integrals taken
from the closed forms, so a periodic orbit gives the ratio exactly.

The section states ``z_k = (y, x', f, phase)`` at ``tau = 2 pi k`` are compared
with ``z_{k-p}`` for ``p = 1..P``; when they agree to ``tol_state`` the orbit is
p-periodic and the average is taken over exactly those ``p`` periods.  The error
estimate is the section distance divided by ``1 - rho``, ``rho`` the observed
contraction per period.  Otherwise the running average is checked at doubling
checkpoints (means over ``(K/4, K/2]`` and ``(K/2, K]`` must agree within
``tol_mean``), and after ``max_periods`` the result is marked not converged.
"""

import math

import numpy as np

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
from .integrate import TWO_PI, initial_state, liftoff_phases, segment
from .jit import jit

MAX_PERIOD = 8  # longest periodic orbit looked for, in drive periods
N_ACC = 6  # accumulators: int_f, int_n, t_stick, t_slip, t_slip_neg, t_flight
MAX_DEGENERATE = 1000  # transitions decided within round-off before giving up (chatter)
FIRST_NEWTON = 1  # first attempt to solve the periodicity condition, in periods


@jit
def period_map(y, xd, f, ph, p, alpha, beta, a, V, th_off, th_on, max_events):
    """Integrate ``p`` drive periods from the section; returns the state and event count."""
    theta = 0.0
    k = 0
    events = 0
    ok_all = True
    while k < p:
        t, theta, y, xd, f, ph, ev, i_f, i_n, ok = segment(
            theta, y, xd, f, ph, alpha, beta, a, V, th_off, th_on)
        ok_all = ok_all and ok
        if ev != EV_SECTION:
            events += 1
            if events > max_events:
                return y, xd, f, ph, events, False
        if theta >= TWO_PI:
            theta = 0.0
            k += 1
    return y, xd, f, ph, events, ok_all


@jit
def _unpack(z, ph, alpha, a, V, rigid):
    """Section state from the free coordinates ``z`` of phase ``ph``."""
    if ph == STICK:
        if rigid:
            return z[0], 0.0, -alpha * z[0]
        return z[0], z[1], z[2]
    s = 1.0 if ph == SLIP_POS else -1.0
    return z[0], z[1], s * (1.0 + a)


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
def newton_orbit(y, xd, f, ph, p, alpha, beta, a, V, th_off, th_on, tol, max_events):
    """Solve ``P^p(z) = z`` on the section by Newton's method with a difference Jacobian.

    Only attracting orbits are accepted (spectral radius of ``DP^p`` below 1), so
    the answer is the attractor the iteration was approaching, not a nearby
    unstable orbit.  An iterate whose image is in another phase on the section
    (the orbit sticks at ``tau = 2 pi k`` where the guess slid, or vice versa)
    continues in that phase's coordinates.  Returns ``(ok, y, x', f, phase, events)``.
    """
    ph_in = ph
    rigid = math.isinf(beta)
    nd = 1 if (ph == STICK and rigid) else (3 if ph == STICK else 2)
    z = np.array([y, xd, f])
    events = 0
    jac = np.zeros((3, 3))
    have_jac = False
    res_prev = np.inf
    scale0 = 1.0 + alpha * abs(y) + abs(xd) + abs(f)
    for _ in range(12):
        # a Newton step that runs far from the start has diverged, not converged
        if alpha * abs(z[0] - y) + abs(z[1] - xd) + abs(z[2] - f) > 100.0 * scale0:
            return False, y, xd, f, ph_in, events
        y0, xd0, f0 = _unpack(z, ph, alpha, a, V, rigid)
        y1, xd1, f1, ph1, ev, ok = period_map(y0, xd0, f0, ph, p, alpha, beta, a, V,
                                              th_off, th_on, max_events)
        events += ev
        if not ok:
            return False, y, xd, f, ph_in, events
        if ph1 != ph:
            # change chart: continue from the image, in its phase's coordinates
            ph = ph1
            nd = 1 if (ph == STICK and rigid) else (3 if ph == STICK else 2)
            z[0], z[1], z[2] = y1, xd1, f1
            have_jac = False
            res_prev = np.inf
            continue
        r = np.array([y1 - y0, xd1 - xd0, f1 - f0])
        res = alpha * abs(r[0]) + abs(r[1]) + (abs(r[2]) if nd == 3 else 0.0)
        if res <= tol * scale0:
            if not have_jac:
                return False, y, xd, f, ph_in, events
            # accept only an attracting orbit: |eig(DP)| < 1 from the last Jacobian
            if nd >= 2:
                mat = (jac[:nd, :nd] + np.eye(nd)).astype(np.complex128)
                ev_mod = np.abs(np.linalg.eigvals(mat))
                if not np.max(ev_mod) < 1.0 - 1e-9:
                    return False, y, xd, f, ph_in, events
            elif not abs(jac[0, 0] + 1.0) < 1.0 - 1e-9:
                return False, y, xd, f, ph_in, events
            return True, y0, xd0, f0, ph, events
        if not have_jac or res > 0.25 * res_prev:
            # (re)build the difference Jacobian of z -> P(z) - z; otherwise chord steps
            for j in range(nd):
                h = 1e-7 * (1.0 + abs(z[j]))
                zp = z.copy()
                zp[j] += h
                y2, xd2, f2 = _unpack(zp, ph, alpha, a, V, rigid)
                y3, xd3, f3, ph3, ev, ok = period_map(y2, xd2, f2, ph, p, alpha, beta, a, V,
                                                      th_off, th_on, max_events)
                events += ev
                if ph3 != ph or not ok:
                    return False, y, xd, f, ph_in, events
                jac[0, j] = ((y3 - y2) - r[0]) / h
                jac[1, j] = ((xd3 - xd2) - r[1]) / h
                jac[2, j] = ((f3 - f2) - r[2]) / h
            have_jac = True
        res_prev = res
        dz, ok = _solve_small(jac[:nd, :nd], -r[:nd], nd)
        if not ok:
            return False, y, xd, f, ph_in, events
        for j in range(nd):
            z[j] += dz[j]
    return False, y, xd, f, ph_in, events


@jit
def sliding_certificate(y, xd, ph, alpha, beta, a, V):
    """Is continuous forward sliding proven from this section state (eqs. 7-12)?

    In slip+ the motion is the steady sliding solution plus a free oscillation at
    ``sqrt(alpha)`` (undamped: slip dissipates nothing it could store).  The
    contact point never stops if ``V - V*`` exceeds the free oscillation's velocity
    amplitude; then ``f = n`` for ever and ``mu/mu0 = 1`` exactly.
    """
    if ph != SLIP_POS or alpha == 1.0:
        return False
    if math.isinf(beta):
        vstar = a / abs(alpha - 1.0)
    else:
        vstar = a * abs(beta - 1.0) / ((beta - alpha) * abs(alpha - 1.0))
    yh = y + 1.0 / alpha + a / (alpha - 1.0)  # minus the particular solution at tau = 0
    yhd = xd - V  # the particular solution's velocity vanishes at tau = 0
    amp = math.sqrt(yhd * yhd + alpha * yh * yh)
    return V - vstar - amp > 1e-9 * (1.0 + V)


@jit
def _distance(alpha, z1, z2):
    return alpha * abs(z1[0] - z2[0]) + abs(z1[1] - z2[1]) + abs(z1[2] - z2[2])


@jit
def steady_state(alpha, beta, a, V, init_kind, y0, xd0, f0, ph0,
                 max_periods, min_periods, tol_state, tol_mean, max_events):
    """Long-time average from a given start.

    ``init_kind``: 0 steady sliding, 1 rest, 2 explicit state ``(y0, y0', f0, ph0)``
    at ``tau = 0``.  Returns ``(mu_ratio, status, period, error, periods, events,
    stick, slip, slip_neg, flight, y, x', f, phase, degenerate)`` where the four
    fractions are of time in the averaging window and the state is the final one
    on the section.
    """
    if init_kind == 2:
        y, xd, f, ph = y0, xd0, f0, ph0
    else:
        y, xd, f, ph = initial_state(init_kind, alpha, beta, a, V)
    th_off, th_on = liftoff_phases(a)
    theta = 0.0
    ring_z = np.zeros((MAX_PERIOD + 1, 4))
    ring_c = np.zeros((MAX_PERIOD + 1, N_ACC))
    dprev = np.full(MAX_PERIOD + 1, np.inf)
    ncheck = 64
    chk_k = np.zeros(ncheck, np.int64)
    chk_c = np.zeros((ncheck, N_ACC))
    acc = np.zeros(N_ACC)
    ring_z[0, 0], ring_z[0, 1], ring_z[0, 2], ring_z[0, 3] = y, xd, f, ph
    nchk = 0
    next_chk = min_periods
    next_newton = FIRST_NEWTON
    k = 0
    events = 0
    degenerate = 0
    zero_run = 0
    status = ST_NOT_CONVERGED
    period = 0
    mu = math.nan
    err = math.inf
    win = np.zeros(N_ACC)
    while True:
        t, theta, y, xd, f, ph1, ev, i_f, i_n, ok = segment(
            theta, y, xd, f, ph, alpha, beta, a, V, th_off, th_on)
        acc[0] += i_f
        acc[1] += i_n
        if ph == STICK:
            acc[2] += t
        elif ph == FLIGHT:
            acc[5] += t
        else:
            acc[3] += t
            if ph == SLIP_NEG:
                acc[4] += t
        if ev != EV_SECTION:
            events += 1
        if not ok:
            degenerate += 1
        zero_run = zero_run + 1 if t == 0.0 else 0
        ph = ph1
        if events > max_events or zero_run > 100 or degenerate > MAX_DEGENERATE:
            status = ST_FAILED
            break
        if theta < TWO_PI:
            continue
        # ---- Poincare section tau = 2 pi k ----
        theta = 0.0
        k += 1
        slot = k % (MAX_PERIOD + 1)
        ring_z[slot, 0], ring_z[slot, 1], ring_z[slot, 2], ring_z[slot, 3] = y, xd, f, ph
        ring_c[slot, :] = acc
        scale = 1.0 + alpha * abs(y) + abs(xd) + abs(f)
        found = False
        for p in range(1, MAX_PERIOD + 1):
            if p > k:
                break
            old = (k - p) % (MAX_PERIOD + 1)
            if ring_z[old, 3] != ph:
                dprev[p] = np.inf
                continue
            d = _distance(alpha, ring_z[slot], ring_z[old])
            if d <= tol_state * scale:
                rho = d / dprev[p] if dprev[p] > 0.0 and np.isfinite(dprev[p]) else 0.0
                rho = min(rho, 0.999)
                for j in range(N_ACC):
                    win[j] = acc[j] - ring_c[old, j]
                mu = win[0] / win[1]
                if win[2] == 0.0 and win[4] == 0.0 and win[5] == 0.0:
                    mu = 1.0  # pure forward slip: f = n identically, not just on average
                err = max(d / (1.0 - rho), 1e-15)
                status = ST_PERIODIC
                period = p
                found = True
                break
            dprev[p] = d
        if found:
            break
        if sliding_certificate(y, xd, ph, alpha, beta, a, V):
            mu = 1.0
            err = 0.0
            status = ST_SLIDING
            win[:] = 0.0
            win[3] = 1.0
            break
        if k == next_newton and k < max_periods:
            next_newton = k + max(1, k // 2)
            # try the period whose section distance is smallest, then p = 1
            pbest = 1
            for p in range(2, min(k, MAX_PERIOD) + 1):
                if dprev[p] < dprev[pbest]:
                    pbest = p
            for attempt in range(2):
                p = pbest if attempt == 0 else 1
                if attempt == 1 and pbest == 1:
                    break
                nok, ny, nxd, nf, nph, nev = newton_orbit(
                    y, xd, f, ph, p, alpha, beta, a, V, th_off, th_on, 0.1 * tol_state,
                    max_events)
                events += nev
                if nok:
                    y, xd, f, ph = ny, nxd, nf, nph
                    ring_z[slot, 0], ring_z[slot, 1], ring_z[slot, 2] = y, xd, f
                    ring_z[slot, 3] = ph
                    dprev[:] = np.inf
                    break
        if k == next_chk or k >= max_periods:
            if nchk < ncheck:
                chk_k[nchk] = k
                chk_c[nchk, :] = acc
                nchk += 1
            next_chk *= 2
            # checkpoints are min_periods * 2^j: (K/4, K/2] and (K/2, K]
            if nchk >= 3 or (k >= max_periods and nchk >= 2):
                i2, i1 = nchk - 1, nchk - 2
                i0 = max(nchk - 3, 0) if nchk >= 3 else -1
                for j in range(N_ACC):
                    win[j] = chk_c[i2, j] - chk_c[i1, j]
                m1 = win[0] / win[1]
                if i0 >= 0:
                    m0 = (chk_c[i1, 0] - chk_c[i0, 0]) / (chk_c[i1, 1] - chk_c[i0, 1])
                else:
                    m0 = chk_c[i1, 0] / chk_c[i1, 1]
                mu = m1
                err = abs(m1 - m0)
                # a window of pure forward slip averages to exactly 1 whatever the state;
                # without the sliding certificate it is a transient (e.g. a resonance
                # still building up), not evidence of convergence
                pure_slip = win[2] == 0.0 and win[4] == 0.0 and win[5] == 0.0
                if err <= tol_mean and not pure_slip:
                    status = ST_AVERAGED
                    break
            if k >= max_periods:
                status = ST_NOT_CONVERGED
                if nchk < 2:
                    for j in range(N_ACC):
                        win[j] = acc[j]
                    mu = acc[0] / acc[1]
                break
    total = win[2] + win[3] + win[5]
    if total <= 0.0 or status == ST_FAILED:
        total = math.nan
    return (mu, status, period, err, k, events,
            win[2] / total, win[3] / total, win[4] / total, win[5] / total,
            y, xd, f, ph, degenerate)


@jit
def steady_state_many(alpha, beta, a, V, init_kind, init, max_periods, min_periods,
                      tol_state, tol_mean, max_events, out_f, out_i):
    """:func:`steady_state` over arrays of points (one compiled loop, no Python calls).

    ``init`` has shape ``(n, 4)`` (used when ``init_kind == 2``); ``out_f`` gets
    columns ``mu, error, stick, slip, slip_neg, flight, y, x', f`` and ``out_i``
    ``status, period, periods, events, phase, degenerate``.
    """
    for i in range(V.shape[0]):
        r = steady_state(alpha[i], beta[i], a[i], V[i], init_kind, init[i, 0], init[i, 1],
                         init[i, 2], int(init[i, 3]), max_periods, min_periods, tol_state,
                         tol_mean, max_events)
        out_f[i, 0] = r[0]
        out_f[i, 1] = r[3]
        out_f[i, 2] = r[6]
        out_f[i, 3] = r[7]
        out_f[i, 4] = r[8]
        out_f[i, 5] = r[9]
        out_f[i, 6] = r[10]
        out_f[i, 7] = r[11]
        out_f[i, 8] = r[12]
        out_i[i, 0] = r[1]
        out_i[i, 1] = r[2]
        out_i[i, 2] = r[4]
        out_i[i, 3] = r[5]
        out_i[i, 4] = r[13]
        out_i[i, 5] = r[14]
