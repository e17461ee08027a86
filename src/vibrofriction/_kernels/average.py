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
from .newton import orbit_multiplier
from .period import (
    A_F,
    A_N,
    MAX_PERIOD,
    N_ACC,
    pure_forward_slip,
    spring,
    window_mu,
)
from .phases import M_ALPHA

RHO_MAX = 0.999  # cap of a contraction rate estimated from section distances
ROUNDOFF_MU = 1e-13  # floor of the error of an exact periodic average
ERROR_SAFETY = 2.0  # d_mu/(1 - lambda) assumes one real leading mode; others add to it
ATTRACTING = 1.0 - 1e-9  # a multiplier modulus below this is attracting


@jit
def _distance(alpha, kk, z1, z2):
    return alpha * abs(z1[0] - z2[0]) + abs(z1[1] - z2[1]) + kk * abs(z1[2] - z2[2])


@jit
def section_scale(alpha, kk, z):
    """The size of a section state, against which its distances are measured."""
    return 1.0 + alpha * abs(z[0]) + abs(z[1]) + kk * abs(z[2])


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
    scale = section_scale(alpha, kk, z)
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
def _settling(k, mu_first, mu, err, rate):
    """Periods until the p-period means stay within ``err`` of the orbit's ``mu``: ``k``,
    the period of a Newton jump whose last window mean was ``mu_first``, plus the periods
    the motion from there needs at the contraction ``rate`` (none when it is within).
    """
    e0 = abs(mu_first - mu)
    if e0 > err and 0.0 < rate < 1.0:
        return k + math.log(err / e0) / math.log(rate)
    return float(k)


@jit
def periodic_result(z, win, p, k, rho, M, max_events, out_f):
    """Average, error, multiplier and settling time of a p-periodic orbit found by plain
    iteration (its state ``z`` repeats after ``p`` periods within ``tol_state``).

    ``win`` holds the accumulators of the last ``p`` periods (one period of the
    orbit).  One more window is integrated, with the exact Jacobian
    (:func:`.newton.orbit_multiplier`), to measure ``d_mu``, the change of the p-period
    mean, and the leading multiplier ``lam``; the window means converge geometrically,
    so the error is ``d_mu / (1 - lam)`` (``rho``, the contraction seen on the section,
    stands in where ``lam`` cannot be formed).  The settling time is ``k``.
    Returns the events spent and the drive periods integrated.
    """
    mu = window_mu(win)
    acc2 = np.zeros(N_ACC)
    lam, ok, ev, work = orbit_multiplier(z.copy(), p, M, max_events, acc2)
    d_mu = abs(window_mu(acc2) - mu) if ok else math.inf
    rate = lam if (math.isfinite(lam) and lam < ATTRACTING) else max(rho, RHO_MAX)
    err = max(ERROR_SAFETY * d_mu / (1.0 - rate), ROUNDOFF_MU * (1.0 + abs(mu)))
    out_f[O_MU] = mu
    out_f[O_ERR] = err
    out_f[O_MULT] = lam
    out_f[O_SETTLE] = float(k)
    return ev, work


@jit
def newton_result(mu, k, lam, shift, mu_first, out_f):
    """Average, error, multiplier and settling time of the orbit found by Newton's method
    (:func:`.newton.newton_orbit`) at period ``k``: ``mu`` its mean and ``shift`` a bound
    of its distance to the exact orbit's, from the exact gradient of ``int f`` and the
    next Newton step, so the error is ``ERROR_SAFETY * shift``, floored at round-off: no
    verification window is needed where the exact Jacobian proves the orbit attracting.
    The settling time counts from the motion's window that ends at period ``k`` (mean
    ``mu_first``) at the rate ``lam`` (a neutral orbit, ``lam`` within ``1 - NEUTRAL`` of
    1, is completed by the caller: :func:`.steady._neutral_result`).
    """
    err = max(ERROR_SAFETY * shift, ROUNDOFF_MU * (1.0 + abs(mu)))
    out_f[O_MU] = mu
    out_f[O_ERR] = err
    out_f[O_MULT] = lam
    out_f[O_SETTLE] = _settling(k, mu_first, mu, err, lam)


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
