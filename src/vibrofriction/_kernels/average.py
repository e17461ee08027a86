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
# a motion whose section state comes this close (relative) to its state p periods back,
# yet not within tol_state, is near a periodic orbit: no running average answers there
NEAR_ORBIT = 1e-3


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
def near_orbit(dprev, z, M):
    """Whether the section state ``z`` is within :data:`NEAR_ORBIT` (relative) of its state
    ``p`` periods back for some ``p`` (``dprev`` of :func:`detect_period`, which found none
    within ``tol_state``): the motion is near a periodic orbit without having reached it.
    """
    d = math.inf
    for p in range(1, MAX_PERIOD + 1):
        d = min(d, dprev[p])
    return d <= NEAR_ORBIT * section_scale(M[M_ALPHA], spring(M), z)


@jit
def window_means(num, den, ks, nchk, out_f):
    """The means of the last three doubling windows from the checkpoints' running sums
    ``num`` (of ``f``) and ``den`` (of ``n``) at periods ``ks``: the last window's mean into
    ``O_MU``, the range of the last three (two where there are only two) into ``O_ERR``
    (floored at round-off), ``O_WMIN`` and ``O_WMAX``, and their drift per period into
    ``O_DRIFT`` where they move one way (0 where they do not, nan with fewer than three).
    Returns whether there are three windows after the first checkpoint's (which holds the
    transient and never counts): only then is the range an error estimate.
    """
    i2, i1 = nchk - 1, nchk - 2
    m1 = (num[i2] - num[i1]) / (den[i2] - den[i1])
    m0 = (num[i1] - num[i1 - 1]) / (den[i1] - den[i1 - 1]) if nchk >= 3 else num[i1] / den[i1]
    lo, hi = min(m0, m1), max(m0, m1)
    out_f[O_DRIFT] = math.nan
    if nchk >= 4:
        i0, im = nchk - 3, nchk - 4
        mm = (num[i0] - num[im]) / (den[i0] - den[im])
        lo, hi = min(lo, mm), max(hi, mm)
        span = 0.5 * ((ks[i2] + ks[i1]) - (ks[i1] + ks[i0]))
        monotone = (m1 - m0) * (m0 - mm) > 0.0
        out_f[O_DRIFT] = (m1 - m0) / span if monotone else 0.0
    out_f[O_MU] = m1
    out_f[O_WMIN], out_f[O_WMAX] = lo, hi
    out_f[O_ERR] = max(hi - lo, ROUNDOFF_MU * (1.0 + abs(m1)))
    return nchk >= 4


@jit
def check_average(chk_k, chk_c, nchk, near, tol_mean, win, out_f):
    """Running-average test at the doubling checkpoints ``K/8, K/4, K/2, K``.

    The mean over ``(K/2, K]`` is the answer and the range of the means over the last
    three windows, ``(K/8, K/4]``, ``(K/4, K/2]`` and ``(K/2, K]``, the error
    (:func:`window_means`).  Returns True when converged: the range is within
    ``tol_mean``, the motion is not ``near`` a periodic orbit (:func:`near_orbit`: one it
    approaches answers as periodic; near one it leaves or circles, the window means are
    the orbit's, not those of the motion to come), and the last window is not pure
    forward slip (which averages to 1 whatever the state: without the certificate it is
    a transient, e.g. a resonance still building up).
    """
    if nchk < 2:
        return False
    for j in range(N_ACC):
        win[j] = chk_c[nchk - 1, j] - chk_c[nchk - 2, j]
    three = window_means(chk_c[:, A_F], chk_c[:, A_N], chk_k, nchk, out_f)
    if pure_forward_slip(win):
        # exactly 1 whatever the state: no evidence about the long-time average
        out_f[O_ERR] = math.inf
        return False
    return three and not near and out_f[O_ERR] <= tol_mean
