r"""Detection of a periodic orbit on the section and the averages that answer (eq. 25).

A p-periodic orbit is averaged over exactly one of its periods with an error from
the change of successive window means and the leading Floquet multiplier
(:func:`periodic_result`); without one, the running average is checked at doubling
checkpoints (:func:`check_average`).  docs/solver.md, "What error means".
"""

import math

import numpy as np

from .codes import O_DRIFT, O_ERR, O_MU, O_MULT, O_SETTLE, O_WMAX, O_WMIN
from .jit import jit
from .newton import NEUTRAL, leading_multiplier
from .period import (
    A_F,
    A_N,
    A_SLIP_NEG,
    A_STICK,
    C_DEGENERATE,
    C_EVENTS,
    MAX_PERIOD,
    N_ACC,
    advance_counted,
    spring,
)
from .phases import M_ALPHA

RHO_MAX = 0.999  # cap of a contraction rate estimated from section distances
ROUNDOFF_MU = 1e-13  # floor of the error of an exact periodic average
ERROR_SAFETY = 2.0  # d_mu/(1 - lambda) assumes one real leading mode; others add to it
ATTRACTING = 1.0 - 1e-9  # a multiplier modulus below this is attracting
NEUTRAL_WINDOW = 512  # the motion near a neutral orbit is measured over periods (N, 2N]


@jit
def _distance(alpha, kk, z1, z2):
    return alpha * abs(z1[0] - z2[0]) + abs(z1[1] - z2[1]) + kk * abs(z1[2] - z2[2])


@jit
def pure_forward_slip(win):
    """A window without stick or reverse slip: ``f = n`` throughout (``0 = 0`` in flight)."""
    return win[A_STICK] == 0.0 and win[A_SLIP_NEG] == 0.0


@jit
def window_mu(win):
    return 1.0 if pure_forward_slip(win) else win[A_F] / win[A_N]


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
    kk = spring(M)
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
def last_window(acc, ring_c, k, p, win):
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
    Returns ``(deviation, events, work)`` (``work``: drive periods integrated).
    """
    z = z0.copy()
    acc = np.zeros(N_ACC)
    count = np.zeros(3, np.int64)
    work = 0.0
    for k in range(2 * NEUTRAL_WINDOW):
        if k == NEUTRAL_WINDOW:
            acc[:] = 0.0
        ok, w = advance_counted(z, acc, count, M, max_events)
        work += w
        if not ok:
            return math.inf, count[C_EVENTS], work
    return abs(acc[A_F] / acc[A_N] - mu), count[C_EVENTS], work


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
    Returns the events spent and the drive periods integrated.
    """
    mu = window_mu(win)
    z2 = z.copy()
    acc2 = np.zeros(N_ACC)
    count = np.zeros(3, np.int64)
    d_mu, work = 0.0, 0.0
    for _ in range(p):
        ok, w = advance_counted(z2, acc2, count, M, max_events)
        work += w
        if not ok:
            d_mu = math.inf
    d_mu = max(d_mu, abs(window_mu(acc2) - mu))
    lam, ev = math.nan, 0
    if math.isfinite(d_mu) and count[C_DEGENERATE] == 0:  # z2 is the exact image of z
        lam, ev, w = leading_multiplier(z, z2, p, M, max_events)
        work += w
    rate = lam if (math.isfinite(lam) and lam < ATTRACTING) else max(rho, RHO_MAX)
    err = max(ERROR_SAFETY * d_mu / (1.0 - rate), ROUNDOFF_MU * (1.0 + abs(mu)))
    settle = float(k)
    if first_jump >= 0 and not lam < NEUTRAL:
        # a neutral orbit (undamped slip) after a Newton jump: the motion from the start
        # need not approach it (no settling time; said in the message, docs/solver.md)
        settle = math.nan
        dev, ev2, w = transient_deviation(z0, mu, M, max_events)
        ev += ev2
        work += w
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
    return count[C_EVENTS] + ev, work


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
    if pure_forward_slip(win):
        # exactly 1 whatever the state: no evidence about the long-time average
        out_f[O_ERR] = math.inf
        return False
    return out_f[O_ERR] <= tol_mean
