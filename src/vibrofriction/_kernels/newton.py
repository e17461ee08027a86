r"""Periodic orbits by Newton's method on the period map, and their Floquet multipliers.

``P^p(z) = z`` is solved on the section in the free coordinates of the phase there
(:func:`newton_orbit`) with the exact Jacobian of the period map (:mod:`.tangent`);
its leading eigenvalue, the Floquet multiplier, says how fast the motion approaches
the orbit and whether it attracts at all.
"""

import math

import numpy as np

from .codes import SLIP_POS, STICK
from .jit import jit
from .period import A_N, MAX_PERIOD, spring, window_mu
from .phases import M_A, M_ALPHA, M_C, M_K
from .tangent import period_map_tangent

NEWTON_ITERATIONS = 12  # Newton steps per attempt
# p > 1 is tried where its section distance is this far below p = 1's (and below
# PERIOD_EVIDENCE itself where p = 1's is large or inf: a change of phase)
PERIOD_EVIDENCE = 0.1
# a Newton step moves the body by at most STEP_LIMIT times the state's size, or AMPLIFY
# times the residual where that is longer: a step that the linearisation scales up
# little from the residual is taken whole (a well-conditioned contraction), a long one
# of a nearly neutral map is cut
STEP_LIMIT = 0.1
AMPLIFY = 3.0
MAX_CHARTS = 2  # changes of chart per attempt: more is an iterate wandering between phases
NEWTON_DIVERGED = 100.0  # a Newton iterate this far (relative) from its start has diverged
NEUTRAL = 1.0 - 1e-6  # a multiplier modulus above this is neutral
UNSTABLE = 1.0 + 1e-6  # and above this, repelling
QUADRATIC = 0.01  # Newton steps shrinking at least this fast are in the quadratic regime
EARLY_ERROR = 1e-12  # a mean predicted one step early is taken only this accurate
# ... and only within this fraction of the residual's tolerance, where that is smaller: a
# tighter tol_state (below the default 1e-10, whose Newton tolerance is 1e-11) makes the
# early answer as much tighter, or takes the next map (without it, an early answer at
# 1e-12 passed every tolerance, and tol_state = 1e-13 returned the default's very bits)
EARLY_FRACTION = 0.1


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
    ``y, x', e`` (stick, viscoelastic slip).
    """
    rigid = math.isinf(M[M_K])
    if ph == STICK:
        return 1 if rigid else 3
    return 3 if (M[M_C] > 0.0 and not rigid) else 2


@jit
def _solve_small(m, r, nd):
    """Solve ``m x = r`` (``nd`` unknowns, ``m``, ``r`` kept) by Gaussian elimination with
    pivoting.
    """
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
def _step(z, dz, nd, limit, alpha):
    """``z += cut dz``, the Newton step ``dz`` cut so that it moves the body ``(y, x')`` by
    at most ``limit``, as the divergence guard watches it; ``e`` is not limited (at
    ``beta = 1e6`` a step of 300 ``n/k`` in ``e`` is normal and comes back).  Returns
    ``cut``.
    """
    body = alpha * abs(dz[0]) + (abs(dz[1]) if nd > 1 else 0.0)
    cut = min(1.0, limit / body) if body > 0.0 else 1.0
    for j in range(nd):
        z[j] += cut * dz[j]
    return cut


ROOT_ACCURACY = 1e-10
"""The closed form's eigenvalues are taken where the rounding of the characteristic
polynomial moves none of them by more than this (relative to the largest, or to 1); else
LAPACK answers (clustered eigenvalues of a non-normal matrix: the roots of the polynomial
lose accuracy as ``eps**(1/k)`` for ``k`` together)."""
EPS_POLY = 8.0 * 2.220446049250313e-16  # rounding of a coefficient, relative to its terms


@jit
def _quadratic_roots(b, c):
    """The roots of ``x^2 + b x + c`` (real coefficients): ``(re1, im1, re2, im2)``, the one
    of largest modulus first (a complex pair: ``im1 = -im2 > 0``).
    """
    disc = 0.25 * b * b - c
    if disc >= 0.0:
        s = math.sqrt(disc)
        big = -0.5 * b - math.copysign(s, b)  # no cancellation
        small = c / big if big != 0.0 else 0.0
        return big, 0.0, small, 0.0
    s = math.sqrt(-disc)
    return -0.5 * b, s, -0.5 * b, -s


@jit
def _cubic_real_root(a, b, c):
    """A real root of ``x^3 + a x^2 + b x + c`` (the largest where all three are real).

    Cardano's or the trigonometric form, polished by Newton's steps on the cubic; near a
    multiple root they converge slowly, and the caller checks the residual.
    """
    p = b - a * a / 3.0
    q = 2.0 * a * a * a / 27.0 - a * b / 3.0 + c
    d = 0.25 * q * q + p * p * p / 27.0
    if d > 0.0:
        s = math.sqrt(d)
        u = -0.5 * q + math.copysign(s, -q)  # the larger in modulus: no cancellation
        u = math.copysign(abs(u) ** (1.0 / 3.0), u)
        x = u - p / (3.0 * u) if u != 0.0 else 0.0
    elif p < 0.0:
        r = math.sqrt(-p / 3.0)
        x = 2.0 * r * math.cos(math.acos(max(-1.0, min(1.0, -0.5 * q / (r * r * r)))) / 3.0)
    else:
        x = 0.0  # p = q = 0: a triple root at -a/3
    x -= a / 3.0
    for _ in range(3):
        f = ((x + a) * x + b) * x + c
        df = (3.0 * x + 2.0 * a) * x + b
        if df == 0.0 or f == 0.0:
            break
        x -= f / df
    return x


@jit
def spectral_radius(J, nd):
    """Largest modulus of the eigenvalues of ``J[:nd, :nd]`` (the Floquet multipliers).

    In closed form from the characteristic polynomial (``nd <= 3``: a real root of the
    cubic, polished, and the quadratic left once it is divided out), an order of magnitude
    cheaper than LAPACK's QR iterations on these small matrices, where the rounding of the
    polynomial moves its roots by less than :data:`ROOT_ACCURACY`; elsewhere (clustered
    eigenvalues) LAPACK answers.  A property test holds it to LAPACK.
    """
    for i in range(nd):
        for j in range(nd):
            if not math.isfinite(J[i, j]):
                return math.inf
    if nd == 1:
        return abs(J[0, 0])
    if nd == 2:
        t = J[0, 0] + J[1, 1]
        mt = abs(J[0, 0]) + abs(J[1, 1])
        d = J[0, 0] * J[1, 1] - J[0, 1] * J[1, 0]
        md = abs(J[0, 0] * J[1, 1]) + abs(J[0, 1] * J[1, 0])
        r1, i1, r2, i2 = _quadratic_roots(-t, d)
        rad = math.hypot(r1, i1)
        noise = EPS_POLY * (rad * rad + rad * mt + md)  # the polynomial's rounding there
        if complex(r1, i1) != complex(r2, i2) and noise <= ROOT_ACCURACY * max(
                1.0, rad) * abs(complex(r1 - r2, i1 - i2)):
            return rad
        return np.max(np.abs(np.linalg.eigvals(J[:nd, :nd].astype(np.complex128))))
    t = J[0, 0] + J[1, 1] + J[2, 2]
    mt = abs(J[0, 0]) + abs(J[1, 1]) + abs(J[2, 2])
    m = (J[0, 0] * J[1, 1] - J[0, 1] * J[1, 0] + J[0, 0] * J[2, 2] - J[0, 2] * J[2, 0]
         + J[1, 1] * J[2, 2] - J[1, 2] * J[2, 1])
    mm = (abs(J[0, 0] * J[1, 1]) + abs(J[0, 1] * J[1, 0]) + abs(J[0, 0] * J[2, 2])
          + abs(J[0, 2] * J[2, 0]) + abs(J[1, 1] * J[2, 2]) + abs(J[1, 2] * J[2, 1]))
    d = (J[0, 0] * (J[1, 1] * J[2, 2] - J[1, 2] * J[2, 1])
         - J[0, 1] * (J[1, 0] * J[2, 2] - J[1, 2] * J[2, 0])
         + J[0, 2] * (J[1, 0] * J[2, 1] - J[1, 1] * J[2, 0]))
    md = (abs(J[0, 0]) * (abs(J[1, 1] * J[2, 2]) + abs(J[1, 2] * J[2, 1]))
          + abs(J[0, 1]) * (abs(J[1, 0] * J[2, 2]) + abs(J[1, 2] * J[2, 0]))
          + abs(J[0, 2]) * (abs(J[1, 0] * J[2, 1]) + abs(J[1, 1] * J[2, 0])))
    r = _cubic_real_root(-t, m, -d)  # lambda^3 - t lambda^2 + m lambda - d
    b = r - t  # the quadratic factor lambda^2 + b lambda + (r b + m)
    r1, i1, r2, i2 = _quadratic_roots(b, r * b + m)
    rad = max(abs(r), math.hypot(r1, i1))
    noise = EPS_POLY * (rad * rad * rad + rad * rad * mt + rad * mm + md)
    ok = abs(((r - t) * r + m) * r - d) <= noise  # r a root to rounding (not: a cluster)
    roots = (complex(r, 0.0), complex(r1, i1), complex(r2, i2))
    for k in range(3):  # each root moves by about noise / |p'(root)|, p' = prod(gaps)
        dp = 1.0
        for q in range(3):
            if q != k:
                dp *= abs(roots[k] - roots[q])
        ok = ok and noise <= ROOT_ACCURACY * max(1.0, rad) * dp
    if ok:
        return rad
    return np.max(np.abs(np.linalg.eigvals(J[:nd, :nd].astype(np.complex128))))


@jit
def dense_spectral_radius(D):
    """The largest eigenvalue modulus of a square matrix ``D`` by LAPACK (the 2-D and
    rate-and-state solvers' Jacobians, too large for :func:`spectral_radius`'s closed form).
    """
    r = 0.0
    for x in np.linalg.eigvals(D.astype(np.complex128)):
        r = max(r, abs(x))
    return r


@jit
def newton_orbit(y, xd, e, ph, p, M, tol, max_events, acc, jac_out):
    """Solve ``P^p(z) = z`` on the section by Newton's method with the exact Jacobian
    (:func:`.tangent.period_map_tangent`): quadratic convergence, no differences.

    Repelling orbits (spectral radius of ``DP^p`` above ``UNSTABLE``) are refused, so the
    answer is the attractor the iteration was approaching, or a neutral orbit (the
    undamped free oscillation of pure slip, radius 1), which the caller treats as such
    (:func:`.steady._run`).  An iterate whose image is in another phase on the section
    (the orbit sticks at ``tau = 2 pi k`` where the guess slid, or vice versa) continues
    in that phase's coordinates, twice at most (:data:`MAX_CHARTS`).  A step moves the
    body by at most :data:`STEP_LIMIT` of the state's size (a long one of a nearly
    neutral map leaves the piece of the map it was linearised on), or by up to
    :data:`AMPLIFY` times the residual, where that is longer (the step of a
    well-conditioned contraction, taken whole); the iterate that strays
    :data:`NEWTON_DIVERGED` times the state's size from the start has diverged.

    Returns ``(ok, y, x', e, phase, events, work, lam, shift, mu_first, mu)``: on success
    the orbit's section state, ``acc`` the accumulators of ``p`` periods from the accepted
    iterate, ``mu`` the orbit's mean ``<f>/<n>``, ``lam`` the modulus of the leading
    Floquet multiplier and ``shift`` a bound of ``mu``'s distance to the exact orbit's;
    ``work`` the drive periods integrated; ``mu_first`` the window mean of the first map,
    the motion's own ``p`` periods from the start (nan where it did not finish).

    With ``dz`` the next Newton step and ``G`` the exact gradient of ``int f``, the window
    mean moves by ``G . dz / int n`` to the exact orbit to first order.  An iterate whose
    residual is within ``tol`` is accepted with its own window mean and ``shift = sum_j
    |G_j dz_j| / int n``.  In the quadratic regime (the step shrank by ``QUADRATIC`` or
    more, ``rho = |dz| / |dz_prev|``) an iterate is accepted one map earlier, where the
    next residual, about ``rho^2 |dz|``, would be within ``tol`` and the bound below is
    within ``min(EARLY_ERROR, EARLY_FRACTION tol)``: the state is ``z + dz``, ``mu`` the
    window mean plus ``G . dz / int n``, and ``shift = |R| rho^2 + rho sum_j |G_j dz_j| /
    int n``, ``R`` the error of the previous iterate's first-order prediction of this
    window mean (the second-order remainder, which scales as ``|dz|^2``); the sum of
    moduli, not the modulus of the sum, as the terms of the next step need not cancel as
    this one's do.
    The phase-time fractions of ``acc`` are then those of the iterate, within about
    ``|dz|`` of the orbit's.  On success ``jac_out`` holds the Jacobian ``DP^p`` of the last
    iterate's map (in the free coordinates of the orbit's phase, :func:`_free_dimension`).
    """
    ph_in = ph
    alpha = M[M_ALPHA]
    kk = spring(M)
    nd = _free_dimension(ph, M)
    z = np.array([y, xd, e])
    events, work = 0, 0.0
    J = np.zeros((3, 3))
    G = np.zeros(3)
    scale0 = 1.0 + alpha * abs(y) + abs(xd) + kk * abs(e)
    mu_first = math.nan
    dzn_prev, predicted = math.inf, math.nan
    charts = 0
    for it in range(NEWTON_ITERATIONS):
        # the guard watches the body (y, x'): an iterate's contact force may leave the
        # cone for a step where the map is nearly neutral in y (beta = 1e6: k e by 300
        # times n), and Newton comes back from there
        if alpha * abs(z[0] - y) + abs(z[1] - xd) > NEWTON_DIVERGED * scale0:
            break
        y0, xd0, e0 = _unpack(z, ph, M)
        y1, xd1, e1, ph1, ev, degenerate, w, smooth = period_map_tangent(
            y0, xd0, e0, ph, p, M, max_events, J, G, acc)
        events += ev
        work += w
        if degenerate < 0:
            break
        if it == 0:
            mu_first = window_mu(acc)
        if ph1 != ph:
            # change chart: continue from the image, in its phase's coordinates
            charts += 1
            if charts > MAX_CHARTS:
                break
            ph = ph1
            nd = _free_dimension(ph, M)
            z[0], z[1], z[2] = y1, xd1, e1
            dzn_prev, predicted = math.inf, math.nan
            continue
        r = np.array([y1 - y0, xd1 - xd0, e1 - e0])
        res = alpha * abs(r[0]) + abs(r[1]) + (kk * abs(r[2]) if nd == 3 else 0.0)
        jac = J[:nd, :nd] - np.eye(nd)
        dz, ok = _solve_small(jac, -r[:nd], nd)
        if not ok:
            break
        mu = window_mu(acc)
        corr, shift = 0.0, 0.0  # the first-order change of the window mean to the orbit
        for j in range(nd):
            corr += G[j] * dz[j]
            shift += abs(G[j] * dz[j])
        corr /= acc[A_N]
        shift /= acc[A_N]
        dzn = alpha * abs(dz[0])  # the section's distance; dz has nd entries
        if nd > 1:
            dzn += abs(dz[1])
        if nd > 2:
            dzn += kk * abs(dz[2])
        rho = dzn / dzn_prev
        converged = res <= tol * scale0
        # one step early: in the quadratic regime the orbit is z + dz to ~rho^2 |dz|, and
        # its mean mu + corr to ~|R| rho^2 (R the remainder of the previous prediction)
        # plus the next step's first-order term, bounded by rho sum |G_j dz_j|
        bound = abs(mu - predicted) * rho * rho + shift * rho
        early = (not converged and rho <= QUADRATIC and dzn * rho * rho <= tol * scale0
                 and bound <= min(EARLY_ERROR, EARLY_FRACTION * tol))
        if converged or early:
            if degenerate > 0 or not smooth:
                break
            lam = spectral_radius(J, nd)
            if not lam < UNSTABLE:
                break
            jac_out[:, :] = J
            if converged:
                return True, y0, xd0, e0, ph, events, work, lam, shift, mu_first, mu
            for j in range(nd):
                z[j] += dz[j]
            y0, xd0, e0 = _unpack(z, ph, M)
            return True, y0, xd0, e0, ph, events, work, lam, bound, mu_first, mu + corr
        predicted = mu + corr
        dzn_prev = dzn
        if _step(z, dz, nd, max(STEP_LIMIT * scale0, AMPLIFY * res), alpha) < 1.0:
            dzn_prev, predicted = math.inf, math.nan
    return False, y, xd, e, ph_in, events, work, math.nan, math.nan, mu_first, math.nan


@jit
def orbit_multiplier(z, p, M, max_events, acc):
    """Modulus of the leading Floquet multiplier of the p-periodic orbit through ``z``,
    from the exact Jacobian of one integration of its ``p`` periods; the image into
    ``z1`` and the accumulators into ``acc``.  ``nan`` when the Jacobian cannot be
    formed in one chart (the image is in another phase, an event is tangential or a
    transition degenerate).  Returns ``(multiplier, ok, events, work)``, ``ok`` False when
    the integration did not finish.
    """
    ph = int(z[3])
    J = np.zeros((3, 3))
    G = np.zeros(3)
    y1, xd1, e1, ph1, ev, degenerate, work, smooth = period_map_tangent(
        z[0], z[1], z[2], ph, p, M, max_events, J, G, acc)
    if degenerate < 0:
        return math.nan, False, ev, work
    if ph1 != ph or degenerate > 0 or not smooth:
        return math.nan, True, ev, work
    return spectral_radius(J, _free_dimension(ph, M)), True, ev, work


@jit
def try_newton(z, dprev, k, M, tol_state, max_events, win, jac_out):
    """Newton on the period whose section distance is smallest where it stands out
    (:data:`PERIOD_EVIDENCE`), then on ``p = 1``.

    On success ``z`` becomes the orbit's state, ``win`` the accumulators of its ``p``
    periods from there and ``jac_out`` the Jacobian of its map.  Returns ``(p, events,
    work, lam, shift)`` (:func:`newton_orbit`)
    with ``p = 0`` if no attracting orbit was found.
    """
    pbest = 1
    for p in range(2, min(k, MAX_PERIOD) + 1):
        if dprev[p] < dprev[pbest]:
            pbest = p
    if dprev[pbest] > PERIOD_EVIDENCE * min(dprev[1], 1.0):
        # no period stands out: far from the orbit every distance is alike, and an
        # attempt on p periods costs p times one on a single period
        pbest = 1
    events, work = 0, 0.0
    for attempt in range(2):
        p = pbest if attempt == 0 else 1
        if attempt == 1 and pbest == 1:
            break
        ok, y, xd, e, ph, ev, w, lam, shift, mu_first, mu = newton_orbit(
            z[0], z[1], z[2], int(z[3]), p, M, 0.1 * tol_state, max_events, win, jac_out)
        events += ev
        work += w
        if ok:
            z[0], z[1], z[2], z[3], z[4] = y, xd, e, ph, math.nan
            return p, events, work, lam, shift, mu_first, mu
    return 0, events, work, math.nan, math.nan, math.nan, math.nan
