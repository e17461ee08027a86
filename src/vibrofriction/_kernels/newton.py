r"""Periodic orbits by Newton's method on the period map, Broyden's updates, Floquet.

``P^p(z) = z`` is solved on the section in the free coordinates of the phase there
(:func:`newton_orbit`); the Jacobian is a difference one, updated by Broyden's
rule between rebuilds; the leading Floquet multiplier (:func:`leading_multiplier`)
says how fast the motion approaches the orbit and whether it attracts at all.
"""

import math

import numpy as np

from .codes import SLIP_POS, STICK
from .jit import jit
from .period import MAX_PERIOD, period_map, spring
from .phases import M_A, M_ALPHA, M_C, M_K

NEWTON_ITERATIONS = 12  # Newton steps per attempt
NEWTON_DIVERGED = 100.0  # a Newton iterate this far (relative) from its start has diverged
NEUTRAL = 1.0 - 1e-6  # a multiplier modulus above this is neutral (to difference accuracy)


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

    ``r`` is the residual at ``z``.  Returns ``(ok, events, work)`` (``work``: drive
    periods integrated); not ok when a perturbed image leaves the chart or the
    integration fails.
    """
    nd = _free_dimension(ph, M)
    kk = spring(M)
    events, work = 0, 0.0
    for j in range(nd):
        if j == 2:  # e: the step of a force change 1e-7 (1 + |f|)
            h = 1e-7 * (abs(z[2]) + 1.0 / kk)
        else:
            h = 1e-7 * (1.0 + abs(z[j]))
        zp = z.copy()
        zp[j] += h
        y2, xd2, e2 = _unpack(zp, ph, M)
        y3, xd3, e3, ph3, ev, degenerate, w = period_map(y2, xd2, e2, ph, p, M, max_events)
        events += ev
        work += w
        if ph3 != ph or degenerate < 0:
            return False, events, work
        jac[0, j] = ((y3 - y2) - r[0]) / h
        jac[1, j] = ((xd3 - xd2) - r[1]) / h
        jac[2, j] = ((e3 - e2) - r[2]) / h
    return True, events, work


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
def _newton_step(z, r, ph, p, M, max_events, jac, nd, rebuild):
    """One Newton step ``z += dz`` with ``jac dz = -r``, the Jacobian rebuilt by differences
    first when ``rebuild`` (else Broyden's update of the old one, already applied).
    Returns ``(ok, dz, events, work)``."""
    events, work = 0, 0.0
    if rebuild:
        ok, events, work = residual_jacobian(z, r, ph, p, M, max_events, jac)
        if not ok:
            return False, r, events, work
    dz, ok = _solve_small(jac[:nd, :nd], -r[:nd], nd)
    if ok:
        for j in range(nd):
            z[j] += dz[j]
    return ok, dz, events, work


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
    Returns ``(ok, y, x', e, phase, events, work)`` (``work``: drive periods integrated).
    """
    ph_in = ph
    alpha = M[M_ALPHA]
    kk = spring(M)
    nd = _free_dimension(ph, M)
    z = np.array([y, xd, e])
    events, work = 0, 0.0
    jac = np.zeros((3, 3))
    have_jac = False
    res_prev = np.inf
    r_prev = np.zeros(3)
    dz = np.zeros(3)
    scale0 = 1.0 + alpha * abs(y) + abs(xd) + kk * abs(e)
    for _ in range(NEWTON_ITERATIONS):
        if (alpha * abs(z[0] - y) + abs(z[1] - xd) + kk * abs(z[2] - e)
                > NEWTON_DIVERGED * scale0):
            break
        y0, xd0, e0 = _unpack(z, ph, M)
        y1, xd1, e1, ph1, ev, degenerate, w = period_map(y0, xd0, e0, ph, p, M, max_events)
        events += ev
        work += w
        if degenerate < 0:
            break
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
                break
            return True, y0, xd0, e0, ph, events, work
        ok, dz, ev, w = _newton_step(z, r, ph, p, M, max_events, jac, nd,
                                     not have_jac or res > 0.5 * res_prev)
        events += ev
        work += w
        if not ok:
            break
        have_jac = True  # built, or updated by Broyden's rule
        res_prev = res
        r_prev = r
    return False, y, xd, e, ph_in, events, work


@jit
def leading_multiplier(z, z1, p, M, max_events):
    """Modulus of the leading Floquet multiplier of the p-periodic orbit through ``z``.

    ``z1`` is the image of the section state ``z`` after ``p`` periods (already
    integrated by the caller).  ``nan`` when the Jacobian cannot be formed in one
    chart (a perturbed orbit changes phase on the section).  Returns
    ``(multiplier, events, work)``.
    """
    ph = int(z[3])
    if int(z1[3]) != ph:
        return math.nan, 0, 0.0
    r = np.array([z1[0] - z[0], z1[1] - z[1], z1[2] - z[2]])
    jac = np.zeros((3, 3))
    ok, ev, work = residual_jacobian(z[:3].copy(), r, ph, p, M, max_events, jac)
    if not ok:
        return math.nan, ev, work
    return spectral_radius(jac, _free_dimension(ph, M)), ev, work


@jit
def try_newton(z, ring_z, dprev, k, M, tol_state, max_events):
    """Newton on the period whose section distance is smallest, then on ``p = 1``.

    On success ``z`` (and its ring slot) become the orbit's state.  Returns
    ``(p, events, work)`` with ``p = 0`` if no attracting orbit was found.
    """
    pbest = 1
    for p in range(2, min(k, MAX_PERIOD) + 1):
        if dprev[p] < dprev[pbest]:
            pbest = p
    events, work = 0, 0.0
    for attempt in range(2):
        p = pbest if attempt == 0 else 1
        if attempt == 1 and pbest == 1:
            break
        ok, y, xd, e, ph, ev, w = newton_orbit(z[0], z[1], z[2], int(z[3]), p, M,
                                               0.1 * tol_state, max_events)
        events += ev
        work += w
        if ok:
            z[0], z[1], z[2], z[3], z[4] = y, xd, e, ph, math.nan
            ring_z[k % (MAX_PERIOD + 1), :] = z
            dprev[:] = np.inf
            return p, events, work
    return 0, events, work
