r"""The steady state and the macroscopic coefficient of friction (paper eq. 25).

``mu_macro / mu0 = <f> / <n>`` over the steady state, with both integrals taken
from the closed forms, so a periodic orbit gives the ratio exactly.

The section states ``z_k = (y, y', f, phase)`` at ``tau = 2 pi k`` are compared
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
    ST_AVERAGED,
    ST_FAILED,
    ST_NOT_CONVERGED,
    ST_PERIODIC,
    STICK,
)
from .integrate import TWO_PI, initial_state, liftoff_phases, segment
from .jit import jit

MAX_PERIOD = 8  # longest periodic orbit looked for, in drive periods
N_ACC = 6  # accumulators: int_f, int_n, t_stick, t_slip, t_slip_neg, t_flight


@jit
def _distance(alpha, z1, z2):
    return alpha * abs(z1[0] - z2[0]) + abs(z1[1] - z2[1]) + abs(z1[2] - z2[2])


@jit
def steady_state(alpha, beta, a, V, init_kind, y0, yd0, f0, ph0,
                 max_periods, min_periods, tol_state, tol_mean, max_events):
    """Long-time average from a given start.

    ``init_kind``: 0 steady sliding, 1 rest, 2 explicit state ``(y0, y0', f0, ph0)``
    at ``tau = 0``.  Returns ``(mu_ratio, status, period, error, periods, events,
    stick, slip, slip_neg, flight, y, y', f, phase, degenerate)`` where the four
    fractions are of time in the averaging window and the state is the final one
    on the section.
    """
    if init_kind == 2:
        y, yd, f, ph = y0, yd0, f0, ph0
    else:
        y, yd, f, ph = initial_state(init_kind, alpha, beta, a, V)
    th_off, th_on = liftoff_phases(a)
    theta = 0.0
    ring_z = np.zeros((MAX_PERIOD + 1, 4))
    ring_c = np.zeros((MAX_PERIOD + 1, N_ACC))
    dprev = np.full(MAX_PERIOD + 1, np.inf)
    ncheck = 64
    chk_k = np.zeros(ncheck, np.int64)
    chk_c = np.zeros((ncheck, N_ACC))
    acc = np.zeros(N_ACC)
    ring_z[0, 0], ring_z[0, 1], ring_z[0, 2], ring_z[0, 3] = y, yd, f, ph
    nchk = 0
    next_chk = min_periods
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
        t, theta, y, yd, f, ph1, ev, i_f, i_n, ok = segment(
            theta, y, yd, f, ph, alpha, beta, a, V, th_off, th_on)
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
        if events > max_events or zero_run > 100:
            status = ST_FAILED
            break
        if theta < TWO_PI:
            continue
        # ---- Poincare section tau = 2 pi k ----
        theta = 0.0
        k += 1
        slot = k % (MAX_PERIOD + 1)
        ring_z[slot, 0], ring_z[slot, 1], ring_z[slot, 2], ring_z[slot, 3] = y, yd, f, ph
        ring_c[slot, :] = acc
        scale = 1.0 + alpha * abs(y) + abs(yd) + abs(f)
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
                err = max(d / (1.0 - rho), 1e-15)
                status = ST_PERIODIC
                period = p
                found = True
                break
            dprev[p] = d
        if found:
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
                if err <= tol_mean:
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
            y, yd, f, ph, degenerate)


@jit
def steady_state_many(alpha, beta, a, V, init_kind, init, max_periods, min_periods,
                      tol_state, tol_mean, max_events, out_f, out_i):
    """:func:`steady_state` over arrays of points (one compiled loop, no Python calls).

    ``init`` has shape ``(n, 4)`` (used when ``init_kind == 2``); ``out_f`` gets
    columns ``mu, error, stick, slip, slip_neg, flight, y, y', f`` and ``out_i``
    ``status, period, periods, events, phase, degenerate``.
    """
    for i in range(V.shape[0]):
        r = steady_state(alpha[i], beta[i], a[i], V[i], init_kind, init[i, 0], init[i, 1],
                         init[i, 2], int(init[i, 3]), max_periods, min_periods, tol_state,
                         tol_mean, max_events)
        out_f[i, 0] = r[0]
        out_f[i, 1] = r[3]
        for j in range(4):
            out_f[i, 2 + j] = r[6 + j]
        out_f[i, 6] = r[10]
        out_f[i, 7] = r[11]
        out_f[i, 8] = r[12]
        out_i[i, 0] = r[1]
        out_i[i, 1] = r[2]
        out_i[i, 2] = r[4]
        out_i[i, 3] = r[5]
        out_i[i, 4] = r[13]
        out_i[i, 5] = r[14]
