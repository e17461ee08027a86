r"""The MDR row without springs: the continuum limit of :mod:`.mdr` (docs/contact_geometry.md).

Scaled as in :mod:`.mdr`: the points of the row are labelled by ``xi >= 0``, their gap is
``g = xi^n``, the indentation ``delta = 1 + a cos tau``, the normal force per unit ``xi``
``w (delta - g)^+`` (``w = (n + 1)/n``), the tangential stiffness per unit ``xi``
``k = beta - alpha``; ``c = w/k``.  The body (drift removed, in the substrate's frame):
``y'' + gamma y' + alpha y = -F + h(tau)``, ``u = y + V tau`` its displacement relative to the
substrate, ``F = k int e dxi`` the row's force.

**Each point is a play operator.**  A point's contact spot ``q`` (so ``e = u - q``) stays
put while ``|k e| <= w (delta - g)``; in terms of ``P = u - c delta`` and ``N = u + c delta``
that is ``P + c g <= q <= N - c g``: the band's edges push ``q`` and never pull it.  A point
touches down (``delta`` rising through ``g``) with ``q = u`` and forgets on leaving.  So,
where neither ``P`` nor ``N`` changes direction over a stretch of time, the profile at its
end is exactly ``q = clamp(q_0, P + c g, N - c g)`` of the profile at its start; such a
stretch (a segment) ends where ``P' = u' - c delta'`` or ``N' = u' + c delta'`` changes sign
(a slipping zone sticks as a whole: the group events of the spring row).

**The profile is a few pieces.**  A pushed point lies on ``q = P_j + c g`` (pushed from below,
``P_j`` the lower edge's level at the end of the segment that pushed it; kind ``AFP``) or
``q = N_j - c g`` (``AFN``): pieces affine in ``g``, so their fronts (where a segment's edge
reaches them) are closed forms.  A
point stuck since it touched down keeps ``q = u(tau_on)`` (kind ``HIS``): ``P(tau_on) = u -
c g`` decreases and ``N`` increases along such a piece (it touched down with the band growing
faster than ``u`` moved), so each edge reaches it in one front, found by a root on the stored
history of ``u`` (quintic Hermite interpolation of ``u, u', u''`` at the step ends).  The
row's force is exact per piece: ``int (A + B g) dxi`` in closed form, and over a stuck
``HIS`` range ``u (xi_b - xi_a) - (Q(tau_b) - Q(tau_a))`` with ``Q = int u rho' dtau``
(``rho = delta^(1/n)`` the contact radius) integrated with the body.  The points touching
down within a segment enter stuck (``HIS``, through ``Q``) or on the band (``P' > 0`` or ``N' < 0``
at the edge), by closed forms.

**Segments and kinks.**  A segment runs until ``P'`` or ``N'`` changes sign (or the
indentation turns, at ``tau = m pi``); within it the clamp of its starting profile is exact,
so the profile is updated at its end only (:func:`period`).  Within a segment the force's
slope jumps where a monotone edge reaches a whole affine piece and its curvature where a
front crosses a piece's end or the contact's edge passes one: levels of ``P`` or ``N`` and
times known at the segment's start (:func:`_levels`), each passed once, located on the
dense output and made step ends (the step cut there, its end read from the dense output;
a step rejected across a level is tried again to just past it, where its error, which
falls only like the step across a kink, would take several rejections).  Between them the
body's equation has a smooth right-hand side and Dormand-Prince 5(4) integrates it at its
order.

It covers Coulomb friction (``static_ratio = 1``) and ``V > 0``, with ``a < 1`` (the core of
the contact never opens) or ``a > 1`` (a jumping indenter: the lift-off and the touch-down
are step ends, the flight has no contact; where the contact opens ``W = int rho u'`` is
carried instead of ``Q``, recomputed after a touch-down with the singular factor apart,
:func:`_wint`, and the indentation near the boundary is taken from its time, :func:`_delta`).
"""

import math

import numpy as np

from .dopri import (
    _A21,
    _A31,
    _A32,
    _A41,
    _A42,
    _A43,
    _A51,
    _A52,
    _A53,
    _A54,
    _A61,
    _A62,
    _A63,
    _A64,
    _A65,
    _B1,
    _B3,
    _B4,
    _B5,
    _B6,
    _C2,
    _C3,
    _C4,
    _C5,
    _D1,
    _D3,
    _D4,
    _D5,
    _D6,
    _D7,
    _E1,
    _E3,
    _E4,
    _E5,
    _E6,
    _E7,
)
from .jit import jit, jit_bare, jit_inline

TWO_PI = 2.0 * math.pi
# two sign changes of an edge's velocity this close are taken for one (a safeguard: an
# event found again just after a segment's end was seen 1e-10..1e-5 apart before the next
# segment took the other direction and the restart took a change back, _unchange)
SAME_CHANGE = 1e-6
AFP, AFN, HIS = 0, 1, 2  # piece kinds: q = P_j + c g, q = N_j - c g, q = u(tau_on)
# piece table columns: xi range, kind, P_j / N_j (affine) or Q(tau_a) (history), the
# history's tau range, xi_a^(n+1), xi_b^(n+1); a history piece's u(tau_a), u(tau_b) (set at
# the segment's start) and its last front, that front's history interval, the level it
# was found at and the slope there (a cache: the next front's first guess)
X0, X1, KIND, VAL, TA, TB, X0P, X1P, UA, UB, TF, IF, TL, TD = range(14)
N_PC = 14
# history table columns: tau, u, u', u'', Q = int u rho' dtau, P = u - c delta, N, and
# cos tau, sin tau (the angles within an interval are rotations from its start: _cs)
HT, HU, HD, HDD, HQ, HP, HN, HC, HSN = range(9)
N_HS = 9
# parameter vector
P_ALPHA, P_GAMMA, P_K, P_C, P_N, P_A, P_V, P_HC, P_HS = range(9)
# ... then Gauss-Jacobi's nodes on [0, 1] and weights for the weight s^(1/n)
# (:func:`_touchdown_integral`), GJ_N each
GJ_N = 8
P_GJX = 9
P_GJW = P_GJX + GJ_N
N_PRM = P_GJW + GJ_N
# edge modes of a step: new points enter stuck, pushed from below, from above; none enter
EDGE_STUCK, EDGE_POS, EDGE_NEG, EDGE_NONE = 0, 1, 2, 3
N_Z = 7  # y, y', Q = int u rho' (jumping: W = int rho u', Q = u rho - W), int F, int stick
# area, int slip area,
# int y
N_ERR = 2  # the components the step's error control sees (the body)
MAX_PIECES = 64
SLIVER = 1e-12  # a piece narrower than this times its end is dropped
# Gauss-Legendre, 3 nodes (exact to degree 5; over a history interval of the steps'
# length its error is far below the steps' own)
GL_X = np.array([-math.sqrt(0.6), 0.0, math.sqrt(0.6)])
GL_W = np.array([5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0])
# a jumping contact's force is C^1 only at the touch-down and the lift-off: steps there at
# most EDGE_RAMP times the time from (to) it, and at least EDGE_STEP
EDGE_STEP, EDGE_RAMP = 1e-2, 0.5
DELTA_NEAR = 0.5  # within this of a contact boundary rhs takes delta from it (_delta)
SINGULAR_NEAR = 8.0  # within this many intervals of a touch-down rho u' is integrated
# with its singular factor apart (:func:`_wint`)
FAIL_PIECES, FAIL_HISTORY, FAIL_STEPS = -1, -2, -3
FRONT_STEP = 1e-7  # a front's Newton step this small (relative): the next one is round-off
MAX_STEPS_HALF = 20000  # steps in a half period before giving up
LEVEL_PAST = 1e-6  # a step rejected across a level is tried again to this much past it
CS_NEAR = 0.6  # _cs rotates by at most this (its series is exact to round-off there)


@jit
def _root(x, n):
    """``x^(1/n)`` (``x >= 0``): the gap's inverse, a square root for the sphere."""
    if n == 2.0:
        return math.sqrt(x)
    if n == 1.0:
        return x
    if n == 4.0:
        return math.sqrt(math.sqrt(x))  # (a third of the cost of the power)
    return x ** (1.0 / n)


@jit
def _cs(t, t0, c0, s0):
    """``(cos t, sin t)`` from ``c0 = cos t0``, ``s0 = sin t0``: the rotation by
    ``x = t - t0``, whose cosine and sine are Taylor series exact to round-off for
    ``|x| <= CS_NEAR`` (the library's functions beyond).  A step's stages, its dense
    output and a history interval's points all lie within a step of a known angle, and
    the series cost about a third of the library's pair.
    """
    x = t - t0
    if abs(x) > CS_NEAR:
        return math.cos(t), math.sin(t)
    x2 = x * x
    cx = 1.0 + x2 * (-1.0 / 2.0 + x2 * (1.0 / 24.0 + x2 * (-1.0 / 720.0 + x2 * (
        1.0 / 40320.0 + x2 * (-1.0 / 3628800.0 + x2 * (1.0 / 479001600.0 + x2 * (
            -1.0 / 87178291200.0 + x2 / 20922789888000.0)))))))
    sx = x * (1.0 + x2 * (-1.0 / 6.0 + x2 * (1.0 / 120.0 + x2 * (-1.0 / 5040.0 + x2 * (
        1.0 / 362880.0 + x2 * (-1.0 / 39916800.0 + x2 * (1.0 / 6227020800.0 + x2 * (
            -1.0 / 1307674368000.0 + x2 / 355687428096000.0))))))))
    return c0 * cx - s0 * sx, s0 * cx + c0 * sx


@jit
def _hcs(HS, i, t):
    """``(cos t, sin t)`` at ``t`` on history interval ``i`` (:func:`_cs` from its start)."""
    return _cs(t, HS[i, HT], HS[i, HC], HS[i, HSN])


@jit
def _hindex(HS, nh, t):
    """The history interval ``i`` with ``HS[i, HT] <= t <= HS[i + 1, HT]``."""
    lo = 0
    hi = nh - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if HS[mid, HT] <= t:
            lo = mid
        else:
            hi = mid
    return lo


@jit
def _hermite(HS, i, t):
    """``u`` and ``u'`` at ``t`` on history interval ``i`` (quintic Hermite)."""
    t0 = HS[i, HT]
    h = HS[i + 1, HT] - t0
    s = (t - t0) / h
    s2 = s * s
    s3 = s2 * s
    s4 = s3 * s
    s5 = s4 * s
    u0, d0, dd0 = HS[i, HU], HS[i, HD] * h, HS[i, HDD] * h * h
    u1, d1, dd1 = HS[i + 1, HU], HS[i + 1, HD] * h, HS[i + 1, HDD] * h * h
    u = (u0 * (1.0 - 10.0 * s3 + 15.0 * s4 - 6.0 * s5)
         + d0 * (s - 6.0 * s3 + 8.0 * s4 - 3.0 * s5)
         + dd0 * 0.5 * (s2 - 3.0 * s3 + 3.0 * s4 - s5)
         + dd1 * 0.5 * (s3 - 2.0 * s4 + s5)
         + d1 * (-4.0 * s3 + 7.0 * s4 - 3.0 * s5)
         + u1 * (10.0 * s3 - 15.0 * s4 + 6.0 * s5))
    du = (u0 * (-30.0 * s2 + 60.0 * s3 - 30.0 * s4)
          + d0 * (1.0 - 18.0 * s2 + 32.0 * s3 - 15.0 * s4)
          + dd0 * 0.5 * (2.0 * s - 9.0 * s2 + 12.0 * s3 - 5.0 * s4)
          + dd1 * 0.5 * (3.0 * s2 - 8.0 * s3 + 5.0 * s4)
          + d1 * (-12.0 * s2 + 28.0 * s3 - 15.0 * s4)
          + u1 * (30.0 * s2 - 60.0 * s3 + 30.0 * s4))
    return u, du / h


@jit
def _touchdown(a, t):
    """The last touch-down at or before ``t`` of a jumping indenter (``a > 1``) in the
    contact that holds ``t`` (``t`` past the lift-off: the next one, after ``t``).
    """
    return TWO_PI * math.ceil(t / TWO_PI) - math.acos(-1.0 / a)


@jit
def _liftoff(a, t):
    """The lift-off of a jumping indenter after the maximum at or before ``t``."""
    return TWO_PI * math.floor(t / TWO_PI) + math.acos(-1.0 / a)


@jit_inline
def _indentation(a, ct):
    """The indentation ``delta = 1 + a cos tau`` from ``ct = cos tau``, ``0`` out of contact."""
    return max(0.0, 1.0 + a * ct)


@jit
def _delta(a, t, tc):
    """The indentation ``delta = 1 + a cos tau``, ``0`` out of contact; given a jumping
    indenter's touch-down or lift-off ``tc`` (``nan``: none), as
    ``-2 a sin((t + tc)/2) sin((t - tc)/2)``, which is 0 at ``tc`` exactly and free of
    cancellation near it: ``rho = delta^(1/n)`` there would take the rounding of
    ``1 + a cos tau`` (about 1e-14 at ``tau ~ 50``) to its ``1/n``-th power (2e-3 at ``n = 5``).
    """
    if math.isnan(tc):
        return _indentation(a, math.cos(t))
    return max(0.0, -2.0 * a * math.sin(0.5 * (t + tc)) * math.sin(0.5 * (t - tc)))


@jit
def _rho(a, n, t):
    """The contact radius ``rho = delta^(1/n)``, ``delta = 1 + a cos tau`` (0 out of contact)."""
    return _root(_delta(a, t, math.nan), n)


@jit
def _rho_rate(a, n, ct, st):
    """``rho'(tau)``, ``rho = (1 + a cos tau)^(1/n)`` (``a < 1``: never 0), from
    ``ct = cos tau``, ``st = sin tau``.
    """
    d = 1.0 + a * ct
    return _root(d, n) / (d * n) * (-a * st)


@jit
def _gauss(HS, i, t0, t1, a, n, rho_du):
    """Gauss-Legendre (3 nodes) over ``[t0, t1]`` within history interval ``i``:
    ``int rho u' dtau`` (``rho_du``) or ``int u rho' dtau`` (the contact never opens).
    """
    hw = 0.5 * (t1 - t0)
    tm = t0 + hw
    s = 0.0
    for j in range(GL_X.size):
        tj = tm + hw * GL_X[j]
        uj, duj = _hermite(HS, i, tj)
        cj, sj = _hcs(HS, i, tj)
        if rho_du:
            s += GL_W[j] * duj * _root(_indentation(a, cj), n)
        else:
            s += GL_W[j] * uj * _rho_rate(a, n, cj, sj)
    return hw * s


@jit
def _touchdown_integral(HS, i, ttd, L, a, n, prm):
    """``int_0^L rho u' ds`` from the touch-down ``ttd`` (``s = tau - ttd``), ``u'`` the
    quintic of history interval ``i`` (continued beyond it where ``L`` ends before it:
    differences of these integrals are exact for it).

    ``rho = delta^(1/n) = s^(1/n) phi(s)`` with ``phi = (delta/s)^(1/n)`` smooth, and
    ``delta = 1 + a cos(ttd + s) = -2 a sin(ttd + s/2) sin(s/2)`` (no cancellation near
    ``s = 0``): Gauss-Jacobi for the weight ``s^(1/n)`` (``prm``'s nodes), exact where
    ``phi u'`` is a polynomial of degree ``2 GJ_N - 1``.
    """
    if L <= 0.0:
        return 0.0
    s = 0.0
    for j in range(GJ_N):
        sj = L * prm[P_GJX + j]
        ratio = -2.0 * a * math.sin(ttd + 0.5 * sj) * math.sin(0.5 * sj) / sj
        _, duj = _hermite(HS, i, ttd + sj)
        s += prm[P_GJW + j] * _root(max(0.0, ratio), n) * duj
    return L * _root(L, n) * s


@jit
def _wint(HS, i, t0, t1, a, n, prm):
    """``int rho u' dtau`` over ``[t0, t1]`` within history interval ``i``.

    Gauss-Legendre in ``tau``; in the contact of a jumping indenter (``a > 1``) within
    ``SINGULAR_NEAR`` interval lengths of the touch-down ``tau_td``, where
    ``rho ~ (tau - tau_td)^(1/n)`` (in ``tau`` the quadrature errs by ``O(h^(1 + 1/n))``
    there), as the difference of two :func:`_touchdown_integral`.
    """
    if a > 1.0:
        ttd = _touchdown(a, t0)
        if ttd <= t0 + 1e-12 and t0 - ttd < SINGULAR_NEAR * (t1 - t0):
            return (_touchdown_integral(HS, i, ttd, t1 - ttd, a, n, prm)
                    - _touchdown_integral(HS, i, ttd, t0 - ttd, a, n, prm))
    return _gauss(HS, i, t0, t1, a, n, True)


@jit
def _hq_jumping(HS, i, t, a, n, prm):
    """:func:`_hq` of a jumping indenter: ``Q_i + [u rho] - int rho u'``, whose integrand
    stays bounded after a touch-down (:func:`_wint`).
    """
    t0 = HS[i, HT]
    if t <= t0:
        return HS[i, HQ]
    u, _ = _hermite(HS, i, t)
    ttd = _touchdown(a, t0)
    return (HS[i, HQ] + u * _root(_delta(a, t, ttd), n)
            - HS[i, HU] * _root(_delta(a, t0, ttd), n) - _wint(HS, i, t0, t, a, n, prm))


@jit
def _hq(HS, i, t, a, n):
    """``Q(t) = int u rho' dtau`` on history interval ``i`` by Gauss-Legendre, where the
    contact never opens (``a <= 1``; else :func:`_hq_jumping`).
    """
    t0 = HS[i, HT]
    if t <= t0:
        return HS[i, HQ]
    return HS[i, HQ] + _gauss(HS, i, t0, t, a, n, False)


@jit
def _hfront(HS, nh, ta, tb, target, sgn, c, a, tg, ig, tl, td):
    """``(t, i, slope)``: ``t`` in ``[ta, tb]`` where ``u(t) + sgn c delta(t) = target``
    (``sgn = -1``: ``P``, decreasing on a history piece; ``+1``: ``N``, increasing; the
    caller has checked that it lies there), its history interval and the function's slope
    there; ``tg``, ``ig`` the last front, found at level ``tl`` with slope ``td``: the
    first guess is Newton's step from it to ``target`` (no evaluation), whose error is
    second order in the level's change.
    """
    if td * sgn > 0.0 and math.isfinite(tl):  # (the last front was this edge's)
        tg = tg + (target - tl) / td
    col = HP if sgn < 0.0 else HN
    i = -1
    if 0 <= ig < nh - 1 and HS[ig + 1, HT] > ta and HS[ig, HT] < tb:
        # the guess's interval, if it holds the root (beyond [ta, tb] the sides are known)
        f0 = HS[ig, col] - target if HS[ig, HT] > ta else -sgn
        f1 = HS[ig + 1, col] - target if HS[ig + 1, HT] < tb else sgn
        if (f0 > 0.0) == (sgn < 0.0) and (f1 > 0.0) != (sgn < 0.0):
            i = ig
    if i < 0:  # bracket on the stored step ends
        lo = _hindex(HS, nh, ta)
        hi = _hindex(HS, nh, tb) + 1
        while hi - lo > 1:
            mid = (lo + hi) // 2
            if (HS[mid, col] > target) == (sgn < 0.0):  # before the front
                lo = mid
            else:
                hi = mid
        i = lo
    x0 = max(ta, HS[i, HT])
    x1 = min(tb, HS[i + 1, HT])
    # safeguarded Newton in [x0, x1], from the guess where it lies there; a step that
    # stays in the closed bracket is taken (a converged step lands on the end just
    # moved: bisecting there would throw the root away and halve the bracket to the end)
    t = tg if x0 < tg < x1 else 0.5 * (x0 + x1)
    df = math.nan
    for _ in range(60):
        u, du = _hermite(HS, i, t)
        ct, st = _hcs(HS, i, t)
        f = u + sgn * c * (1.0 + a * ct) - target
        df = du - sgn * c * a * st
        if f == 0.0:
            return t, i, df
        if (f > 0.0) == (sgn < 0.0):
            x0 = t
        else:
            x1 = t
        tn = t - f / df if df != 0.0 else 0.5 * (x0 + x1)
        newton = x0 <= tn <= x1
        if not newton:
            tn = 0.5 * (x0 + x1)
        # a Newton step of FRONT_STEP leaves an error of about its square (times the
        # curvature over the slope): round-off.  (And the force is smooth across the
        # front: its error is second order in the front's.)
        if (newton and abs(tn - t) <= FRONT_STEP * (1.0 + abs(t))) \
                or x1 - x0 <= 1e-12 * (1.0 + abs(t)):
            return tn, i, df
        t = tn
    return t, i, df


@jit
def _add(out, m, x0, x1, kind, val, ta, tb, x0p, x1p):
    """Append a piece to ``out`` (``m`` pieces so far), merged with the last where it
    continues it; returns the new count (``MAX_PIECES + 1`` on overflow).
    """
    if x1 - x0 <= SLIVER * x1:  # (the contact's edge a rounding away from a piece's end)
        return m
    if m > 0:
        if kind != HIS and out[m - 1, KIND] == kind and out[m - 1, VAL] == val:
            out[m - 1, X1] = x1
            out[m - 1, X1P] = x1p
            return m
        if kind == HIS and out[m - 1, KIND] == HIS and out[m - 1, TB] == ta:
            out[m - 1, X1] = x1
            out[m - 1, X1P] = x1p
            out[m - 1, TB] = tb
            return m
    if m >= MAX_PIECES:
        return MAX_PIECES + 1
    out[m, X0] = x0
    out[m, X1] = x1
    out[m, KIND] = kind
    out[m, VAL] = val
    out[m, TA] = ta
    out[m, TB] = tb
    out[m, X0P] = x0p
    out[m, X1P] = x1p
    return m + 1


@jit
def _on_edge(xa, xb, xap, xbp, sgn, c, d, n1):
    """A range ``[xa, xb]`` of the profile on the band's lower (``sgn = 1``) or upper
    (``-1``) edge, ``e = sgn c (d - g)``: ``(int e dxi, its area)``.
    """
    return sgn * c * (d * (xb - xa) - (xbp - xap) / n1), xb * xb - xa * xa


@jit
def _add_edge(out, m, xa, xb, xap, xbp, sgn, P, N):
    """:func:`_add` of a range on the lower (``sgn = 1``, level ``P``) or upper edge."""
    if sgn > 0.0:
        return _add(out, m, xa, xb, AFP, P, 0.0, 0.0, xap, xbp)
    return _add(out, m, xa, xb, AFN, N, 0.0, 0.0, xap, xbp)


@jit_inline
def _sweep(u, prm, PC, npc, HS, nh, out, write, rho, d):
    """The old points at ``u`` and ``delta = d`` (``rho = d^(1/n)``), clamped to the band of
    the segment's monotone edges: ``(int e dxi, stick area, slip area, m)`` (areas as
    ``int 2 xi dxi``); where ``write``, the clamped profile is written to ``out`` (``m``
    pieces).
    """
    c, n, a = prm[P_C], prm[P_N], prm[P_A]
    n1 = n + 1.0
    P = u - c * d
    N = u + c * d
    E = 0.0
    ast = 0.0
    asl = 0.0
    m = 0
    for j in range(npc):
        xa = PC[j, X0]
        if xa >= rho:
            break
        xb = PC[j, X1]
        xap = PC[j, X0P]
        xbp = PC[j, X1P]
        cut = xb > rho
        if cut:
            xb = rho
            xbp = rho * d  # rho^(n+1)
        kind = int(PC[j, KIND])
        v = PC[j, VAL]
        # the sub-ranges: stuck [xa, xs], pushed from below / above [xs, xb] (affine: one
        # of the two), or all pushed
        if kind == AFP:
            if v <= P:  # the lower edge reaches the whole piece
                dE, da = _on_edge(xa, xb, xap, xbp, 1.0, c, d, n1)
                E += dE
                asl += da
                if write:
                    m = _add_edge(out, m, xa, xb, xap, xbp, 1.0, P, N)
                continue
            gs = 0.5 * (N - v) / c  # beyond: above the upper edge
            sgn = -1.0
        elif kind == AFN:
            if v >= N:  # the upper edge reaches the whole piece
                dE, da = _on_edge(xa, xb, xap, xbp, -1.0, c, d, n1)
                E += dE
                asl += da
                if write:
                    m = _add_edge(out, m, xa, xb, xap, xbp, -1.0, P, N)
                continue
            gs = 0.5 * (v - P) / c  # beyond: below the lower edge
            sgn = 1.0
        else:
            ta = PC[j, TA]
            tb = PC[j, TB]
            gb = PC[j, X1P] / PC[j, X1] if not cut else d
            if cut:  # the newest points have left: the loading time of delta = d
                ml = math.ceil(ta / TWO_PI)
                tb = min(tb, TWO_PI * ml - math.acos(min(1.0, max(-1.0, (d - 1.0) / a))))
                ub, _ = _hermite(HS, _hindex(HS, nh, tb), tb)
            else:
                ub = PC[j, UB]
            ga = PC[j, X0P] / xa if xa > 0.0 else 0.0
            sgn = 0.0
            ts = tb
            its = -1
            sl = tl = math.nan
            if ub - c * gb < P:  # the newest points below the lower edge
                sgn = 1.0
                if PC[j, UA] - c * ga <= P:
                    ts = ta
                else:
                    ts, its, sl = _hfront(HS, nh, ta, tb, P, -1.0, c, a, PC[j, TF],
                                          int(PC[j, IF]), PC[j, TL], PC[j, TD])
                    tl = P
            elif ub + c * gb > N:
                sgn = -1.0
                if PC[j, UA] + c * ga >= N:
                    ts = ta
                else:
                    ts, its, sl = _hfront(HS, nh, ta, tb, N, 1.0, c, a, PC[j, TF],
                                          int(PC[j, IF]), PC[j, TL], PC[j, TD])
                    tl = N
            if its >= 0:
                PC[j, TF] = ts
                PC[j, IF] = its
                PC[j, TL] = tl
                PC[j, TD] = sl
            else:
                its = _hindex(HS, nh, ts)
            if ts > PC[j, TA]:
                if a > 1.0:
                    ds = _delta(a, ts, _touchdown(a, ts))
                else:
                    ds = _indentation(a, _hcs(HS, its, ts)[0])
                xs = _root(ds, n) if ts < tb else xb
                xsp = xs * ds if ts < tb else xbp
                Qs = _hq_jumping(HS, its, ts, a, n, prm) if a > 1.0 else _hq(HS, its, ts, a, n)
                E += u * (xs - xa) - (Qs - v)
                ast += xs * xs - xa * xa
                if write:
                    m = _add(out, m, xa, xs, HIS, v, PC[j, TA], ts, xap, xsp)
            else:
                xs = xa
                xsp = xap
            if sgn != 0.0 and xs < xb:
                dE, da = _on_edge(xs, xb, xsp, xbp, sgn, c, d, n1)
                E += dE
                asl += da
                if write:
                    m = _add_edge(out, m, xs, xb, xsp, xbp, sgn, P, N)
            continue
        # affine piece, not wholly pushed: e = u - v -+ c g up to the front gs
        if gs <= 0.0:
            xs = xa
            xsp = xap
        else:
            xs = _root(gs, n)
            xsp = xs * gs
            if xs > xb:
                xs = xb
                xsp = xbp
            elif xs < xa:
                xs = xa
                xsp = xap
        kc = c if kind == AFP else -c  # q = v + kc g
        if xs > xa:
            E += (u - v) * (xs - xa) - kc * (xsp - xap) / n1
            ast += xs * xs - xa * xa
            if write:
                m = _add(out, m, xa, xs, kind, v, 0.0, 0.0, xap, xsp)
        if xs < xb:
            dE, da = _on_edge(xs, xb, xsp, xbp, sgn, c, d, n1)
            E += dE
            asl += da
            if write:
                m = _add_edge(out, m, xs, xb, xsp, xbp, sgn, P, N)
    return E, ast, asl, m


@jit
def rhs(t, z, dz, prm, PC, npc, HS, nh, seg, ct, st):
    """The body's equation, ``Q``'s rate and the integrands of the period's means, with
    the profile of the segment's start clamped (:func:`_sweep`) and the points touched
    down since (``seg = (rho, Q, edge mode, rho^n)`` at the segment's start); ``ct``,
    ``st`` are ``cos t``, ``sin t``.
    """
    y, v = z[0], z[1]
    V = prm[P_V]
    u = y + V * t
    a, n, c = prm[P_A], prm[P_N], prm[P_C]
    d = _indentation(a, ct)
    if abs(t - seg[4]) < DELTA_NEAR:  # (nan: no boundary)
        d = _delta(a, t, seg[4])
    rho = _root(d, n)
    E, ast, asl, _ = _sweep(u, prm, PC, npc, HS, nh, PC, False, rho, d)
    rho0 = seg[0]
    edge = int(seg[2])
    if edge != EDGE_NONE and rho > rho0:
        if edge == EDGE_STUCK:
            Q = z[2] if not a > 1.0 else u * rho - z[2]  # (jumping: z[2] is W, Q = u rho - W)
            E += u * (rho - rho0) - (Q - seg[1])
            ast += rho * rho - rho0 * rho0
        else:  # the new points on the edge they entered at
            dE, da = _on_edge(rho0, rho, rho0 * seg[3], rho * d,
                              1.0 if edge == EDGE_POS else -1.0, c, d, n + 1.0)
            E += dE
            asl += da
    F = prm[P_K] * E
    dz[0] = v
    dz[1] = -prm[P_ALPHA] * y - prm[P_GAMMA] * v - F + prm[P_HC] * ct + prm[P_HS] * st
    if not a > 1.0:
        dz[2] = u * rho / d / n * (-a * st)  # Q' = u rho' (smooth: the contact never opens)
    else:
        dz[2] = rho * (v + V)  # W' = rho u' (bounded where rho' is not, at a touch-down)
    dz[3] = F
    dz[4] = ast
    dz[5] = asl
    dz[6] = y


@jit_bare
def _step(t, z, k1, h, znew, K, prm, PC, npc, HS, nh, seg, ct, st, cs):
    """One Dormand-Prince step (``K[6]`` = the stage at the end, ``K[0]`` = ``k1``,
    ``K[7]`` scratch) from ``t`` (``ct``, ``st``: its cosine and sine); the cosine and sine
    of ``t + h`` into ``cs``.
    """
    tmp = K[7]
    for i in range(N_Z):
        K[0, i] = k1[i]
        tmp[i] = z[i] + h * _A21 * k1[i]
    tt = t + _C2 * h
    c_, s_ = _cs(tt, t, ct, st)
    rhs(tt, tmp, K[1], prm, PC, npc, HS, nh, seg, c_, s_)
    for i in range(N_Z):
        tmp[i] = z[i] + h * (_A31 * k1[i] + _A32 * K[1, i])
    tt = t + _C3 * h
    c_, s_ = _cs(tt, t, ct, st)
    rhs(tt, tmp, K[2], prm, PC, npc, HS, nh, seg, c_, s_)
    for i in range(N_Z):
        tmp[i] = z[i] + h * (_A41 * k1[i] + _A42 * K[1, i] + _A43 * K[2, i])
    tt = t + _C4 * h
    c_, s_ = _cs(tt, t, ct, st)
    rhs(tt, tmp, K[3], prm, PC, npc, HS, nh, seg, c_, s_)
    for i in range(N_Z):
        tmp[i] = z[i] + h * (_A51 * k1[i] + _A52 * K[1, i] + _A53 * K[2, i] + _A54 * K[3, i])
    tt = t + _C5 * h
    c_, s_ = _cs(tt, t, ct, st)
    rhs(tt, tmp, K[4], prm, PC, npc, HS, nh, seg, c_, s_)
    for i in range(N_Z):
        tmp[i] = z[i] + h * (_A61 * k1[i] + _A62 * K[1, i] + _A63 * K[2, i]
                             + _A64 * K[3, i] + _A65 * K[4, i])
    tt = t + h
    c_, s_ = _cs(tt, t, ct, st)
    rhs(tt, tmp, K[5], prm, PC, npc, HS, nh, seg, c_, s_)
    for i in range(N_Z):
        znew[i] = z[i] + h * (_B1 * k1[i] + _B3 * K[2, i] + _B4 * K[3, i]
                              + _B5 * K[4, i] + _B6 * K[5, i])
    rhs(tt, znew, K[6], prm, PC, npc, HS, nh, seg, c_, s_)
    cs[0] = c_
    cs[1] = s_


@jit_bare
def _err(z, znew, K, h, rtol, atol):
    s = 0.0
    for i in range(N_ERR):
        e = h * (_E1 * K[0, i] + _E3 * K[2, i] + _E4 * K[3, i] + _E5 * K[4, i]
                 + _E6 * K[5, i] + _E7 * K[6, i])
        sc = atol + rtol * max(abs(z[i]), abs(znew[i]))
        s += (e / sc) ** 2
    return math.sqrt(s / N_ERR)


@jit
def _contd5(z, znew, K, h, i):
    """The coefficients ``(ydiff, bspl, r4, r5)`` of component ``i``'s dense output (Hairer's
    CONTD5): ``z + th (ydiff + (1 - th) (bspl + th (r4 + (1 - th) r5)))``.
    """
    ydiff = znew[i] - z[i]
    bspl = h * K[0, i] - ydiff
    r4 = ydiff - h * K[6, i] - bspl
    r5 = h * (_D1 * K[0, i] + _D3 * K[2, i] + _D4 * K[3, i] + _D5 * K[4, i]
              + _D6 * K[5, i] + _D7 * K[6, i])
    return ydiff, bspl, r4, r5


@jit
def _dense(z, znew, K, h, i, th):
    """Component ``i`` at ``t + th h`` (Hairer's CONTD5)."""
    ydiff, bspl, r4, r5 = _contd5(z, znew, K, h, i)
    th1 = 1.0 - th
    return z[i] + th * (ydiff + th1 * (bspl + th * (r4 + th1 * r5)))


@jit
def _dense_slope(z, znew, K, h, i, th):
    """The rate of component ``i`` at ``t + th h`` (:func:`_dense` differentiated in ``t``)."""
    ydiff, bspl, r4, r5 = _contd5(z, znew, K, h, i)
    th1 = 1.0 - th
    g = bspl + th * (r4 + th1 * r5)
    dg = r4 + (th1 - th) * r5
    return (ydiff + th1 * g + th * (th1 * dg - g)) / h


@jit
def _edge_slope(kind, z, znew, K, h, t, th, prm, ct, st):
    """The rate of ``P'`` (``kind`` 0) or ``N'`` (1) at ``t + th h`` on the dense output."""
    c, a = prm[P_C], prm[P_A]
    c_, _ = _cs(t + th * h, t, ct, st)
    udd = _dense_slope(z, znew, K, h, 1, th)
    return udd + c * a * c_ if kind == 0 else udd - c * a * c_


@jit
def _turn(kind, z, znew, K, h, t, prm, th0, f0, d0, th1, d1, sg, ct, st, gz):
    """Where ``P'`` (``kind`` 0) or ``N'`` (1), of sign ``sg`` at both ends of ``[th0, th1]``
    (``f0`` at ``th0``; ``d0``, ``d1`` its slopes at the ends), turns back towards 0 within
    it and crosses: the crossing (the first root, as a fraction of the step), else 2.  An
    edge that turns within a sample interval (a brief stick near the critical velocity) is
    then not passed over however long the step: its extremum is found by bisection on the
    slope.  The extremum's distance from 0 lowers ``gz[0]`` (the period's graze depth).
    """
    if not (d0 * sg < 0.0 < d1 * sg):
        return 2.0  # no turn towards 0 and back inside
    a0, a1 = th0, th1
    for _ in range(60):  # bisection on the slope: the extremum
        m = 0.5 * (a0 + a1)
        if _edge_slope(kind, z, znew, K, h, t, m, prm, ct, st) * sg < 0.0:
            a0 = m
        else:
            a1 = m
        if a1 - a0 <= 1e-12:
            break
    m = 0.5 * (a0 + a1)
    fm = _event_value(kind, 0.0, z, znew, K, h, t, m, prm, ct, st)
    gz[0] = min(gz[0], abs(fm))
    if not _crossed(fm, sg):
        return 2.0
    return _event_root(kind, 0.0, z, znew, K, h, t, prm, th0, f0, m, fm, ct, st)


@jit
def _event_value(kind, lev, z, znew, K, h, t, th, prm, ct, st):
    """The event functions on the dense output: 0 ``P' = u' - c delta'``, 1 ``N'``,
    2 ``P - lev``, 3 ``N - lev`` (``ct``, ``st``: the cosine and sine of ``t``).
    """
    tt = t + th * h
    c, a, V = prm[P_C], prm[P_A], prm[P_V]
    c_, s_ = _cs(tt, t, ct, st)
    if kind <= 1:
        ud = _dense(z, znew, K, h, 1, th) + V
        dd = -a * s_
        return ud - c * dd if kind == 0 else ud + c * dd
    u = _dense(z, znew, K, h, 0, th) + V * tt
    d = 1.0 + a * c_
    return (u - c * d - lev) if kind == 2 else (u + c * d - lev)


@jit
def _event_root(kind, lev, z, znew, K, h, t, prm, th0, f0, th1, f1, ct, st):
    """The root of event ``kind`` in ``[th0, th1]`` (values of opposite signs), Illinois."""
    side = 0
    for _ in range(80):
        th = (th0 * f1 - th1 * f0) / (f1 - f0)
        if not (th0 < th < th1):
            th = 0.5 * (th0 + th1)
        f = _event_value(kind, lev, z, znew, K, h, t, th, prm, ct, st)
        if (f > 0.0) == (f0 > 0.0):
            th0, f0 = th, f
            if side == 1:
                f1 *= 0.5
            side = 1
        else:
            th1, f1 = th, f
            if side == -1:
                f0 *= 0.5
            side = -1
        if th1 - th0 <= 1e-14:
            break
    return th1


@jit
def _levels(prm, PC, npc, t0, P0, N0, up, down, unloading, LP, LN, LT):
    """The levels of a segment from ``t0`` where the force bends: the values of a rising
    ``P`` (``up``) at which its front reaches a whole affine piece (``AFP``: the force's
    slope jumps) or a piece's end (its curvature jumps), ascending in ``LP``; those of a
    falling ``N`` (``down``), descending in ``LN``; and, ``unloading``, the times at which
    the contact's edge passes a piece's end, ascending in ``LT``.  Returns the counts.
    (The profile does not change within a segment, so each level is passed once.)
    """
    c, a = prm[P_C], prm[P_A]
    tiny = 1e-10 * (1.0 + abs(P0) + abs(N0))  # a level just passed (an event step)
    mp = 0
    mn = 0
    mt = 0
    base = TWO_PI * math.floor(t0 / TWO_PI + 1e-12)
    for j in range(npc):
        kind = int(PC[j, KIND])
        v = PC[j, VAL]
        ga = PC[j, X0P] / PC[j, X0] if PC[j, X0] > 0.0 else 0.0
        last = j == npc - 1  # its far end is the contact's edge: the band has no width
        gb = PC[j, X1P] / PC[j, X1]
        for q in range(3):
            lv = math.nan
            if kind == AFP:
                if q == 0:
                    lv = v
                elif not (up and v <= P0 + tiny):  # (a piece pushed from below meets
                    lv = v + 2.0 * c * (ga if q == 1 else gb)  # the upper edge at the edge)
            elif kind == AFN:
                if q == 0:
                    lv = v
                elif not (down and v >= N0 - tiny):
                    lv = v - 2.0 * c * (ga if q == 1 else gb)
            elif q > 0:
                uq = PC[j, UA] if q == 1 else PC[j, UB]
                gq = ga if q == 1 else gb
                lv = uq - c * gq  # P(tau_on): the lower edge's level; N's is 2 c g above
            if math.isnan(lv) or (q == 2 and last):
                continue
            if kind == AFP:
                lp = lv if q == 0 else math.nan
                ln = lv if q > 0 else math.nan
            elif kind == AFN:
                ln = lv if q == 0 else math.nan
                lp = lv if q > 0 else math.nan
            else:
                lp = lv
                ln = lv + 2.0 * c * (ga if q == 1 else gb)
            if up and lp > P0 + tiny and mp < LP.size:
                LP[mp] = lp
                mp += 1
            if down and ln < N0 - tiny and mn < LN.size:
                LN[mn] = ln
                mn += 1
        if unloading and not last and a > 0.0:
            x = (gb - 1.0) / a
            if -1.0 < x < 1.0:
                te = base + math.acos(x)
                if te > t0 + 1e-12 and mt < LT.size:
                    LT[mt] = te
                    mt += 1
    _sort(LP, mp)
    _sort(LN, mn)
    for i in range(mn // 2):  # descending
        LN[i], LN[mn - 1 - i] = LN[mn - 1 - i], LN[i]
    _sort(LT, mt)
    return mp, mn, mt


@jit_inline
def _sort(x, m):
    """``x[:m]`` in ascending order, in place (insertion: a segment has a few levels, and
    numba's sort needs the reference counting :func:`_period` runs without).
    """
    for i in range(1, m):
        v = x[i]
        j = i - 1
        while j >= 0 and x[j] > v:
            x[j + 1] = x[j]
            j -= 1
        x[j + 1] = v


@jit
def _direction(g, gd, tol):
    """The sign of an event function just after the step's start: its slope's where it is
    within ``tol`` of 0 (the step after an event).
    """
    if g > tol:
        return 1.0
    if g < -tol:
        return -1.0
    return 1.0 if gd >= 0.0 else -1.0


@jit
def _crossed(f, sg):
    """Whether ``f`` has left the sign ``sg`` it had at the step's start."""
    return f != 0.0 and (f > 0.0) != (sg > 0.0)


@jit
def _level_in_step(z, znew, K, hh, t, prm, lp, ln, ct, st):
    """Where in a step ``P`` reaches the level ``lp`` or ``N`` reaches ``ln``, as a fraction
    of it (on its dense output; 2 if neither does by its end).

    Within a segment ``P`` only rises towards ``lp`` and ``N`` only falls towards ``ln``
    (:func:`_levels`), so a level is reached in a step if its end is past it.
    """
    th = 2.0
    for kind in (2, 3):
        lev = lp if kind == 2 else ln
        if math.isinf(lev):
            continue
        f0 = _event_value(kind, lev, z, znew, K, hh, t, 0.0, prm, ct, st)
        f1 = _event_value(kind, lev, z, znew, K, hh, t, 1.0, prm, ct, st)
        if (f0 < 0.0 < f1) if kind == 2 else (f1 < 0.0 < f0):
            th = min(th, _event_root(kind, lev, z, znew, K, hh, t, prm, 0.0, f0, 1.0, f1,
                                     ct, st))
    return th


@jit_bare
def _first_event(z, znew, K, hh, t, prm, dirp, dirn, lp, ln, ct, st, gz):
    """The earliest event of the step on its dense output, as a fraction of it (2 if
    none): ``P'`` or ``N'`` changing sign, ``P`` reaching ``lp`` or ``N`` reaching ``ln``;
    and its kind.  Each is sampled at four points of the step; ``P'`` and ``N'`` also
    where they turn back towards 0 between two samples (:func:`_turn`), so that a sign
    change and back within a quarter step is not passed over (``gz``: :func:`_turn`).
    """
    c, a, V = prm[P_C], prm[P_A], prm[P_V]
    p0 = dirp * 1e-300
    p1 = dirn * 1e-300
    p2 = -1e-300
    p3 = 1e-300
    thp = 0.0
    dp0 = K[0, 1] + c * a * ct  # the slopes of P' and N' at the step's start
    dn0 = K[0, 1] - c * a * ct
    for q in range(1, 5):
        th = 0.25 * q
        tt = t + th * hh
        ud = _dense(z, znew, K, hh, 1, th) + V
        u = _dense(z, znew, K, hh, 0, th) + V * tt
        c_, s_ = _cs(tt, t, ct, st)
        cd = c * (1.0 + a * c_)
        cdd = -c * a * s_
        f0 = ud - cdd
        f1 = ud + cdd
        udd = _dense_slope(z, znew, K, hh, 1, th)
        dp1 = udd + c * a * c_
        dn1 = udd - c * a * c_
        f2 = u - cd - lp
        f3 = u + cd - ln
        th_ev = 2.0
        k_ev = -1
        if _crossed(f0, dirp):
            th_ev = _event_root(0, 0.0, z, znew, K, hh, t, prm, thp, p0, th, f0, ct, st)
            k_ev = 0
        else:
            th_ev = _turn(0, z, znew, K, hh, t, prm, thp, p0, dp0, th, dp1, dirp, ct, st,
                          gz)
            k_ev = 0 if th_ev < 2.0 else -1
        if _crossed(f1, dirn):
            r = _event_root(1, 0.0, z, znew, K, hh, t, prm, thp, p1, th, f1, ct, st)
        else:
            r = _turn(1, z, znew, K, hh, t, prm, thp, p1, dn0, th, dn1, dirn, ct, st, gz)
        if r < th_ev:
            th_ev = r
            k_ev = 1
        if lp != math.inf and _crossed(f2, -1.0):
            r = _event_root(2, lp, z, znew, K, hh, t, prm, thp, p2, th, f2, ct, st)
            if r < th_ev:
                th_ev = r
                k_ev = 2
        if ln != -math.inf and _crossed(f3, 1.0):
            r = _event_root(3, ln, z, znew, K, hh, t, prm, thp, p3, th, f3, ct, st)
            if r < th_ev:
                th_ev = r
                k_ev = 3
        if k_ev >= 0:
            return th_ev, k_ev
        p0, p1, p2, p3 = f0, f1, f2, f3
        dp0, dn0 = dp1, dn1
        thp = th
    return 2.0, -1


@jit
def period(prm, t0, z, PC, npc, HS, nh, rtol, atol, hmax, h, K, out, cnt, gz, halves=2):
    """``halves`` half periods from ``t0 = m pi`` (``z[0:3]`` the body and ``Q``;
    ``PC[:npc]`` the profile, ``HS[:nh]`` the history, its last entry at ``t0``):
    ``(npc, nh, h)`` at the end (``npc`` < 0: failed), ``z[3:6]`` the integrals over the
    run; ``cnt`` counts steps, rejections, events and segments.  ``gz`` measures how
    closely the run grazes a change of the edges' directions: ``gz[0]`` the smallest
    ``|P'|`` or ``|N'|`` where one turns back from 0 (:func:`_turn`), ``gz[1]`` the
    shortest time between two sign changes of the same one in contact (a brief stick or
    slip: :func:`_sign_change`); ``gz[2:4]``, ``gz[4:6]`` the last and the one before
    sign changes' times of ``P'`` and ``N'`` (nan: none), carried from the run before
    (the caller sets them to nan at first; the last stretch, not yet confirmed, is
    counted by :func:`_shortest_stretch`).

    A segment runs until ``P'`` or ``N'`` changes sign or the half ends; within it the
    profile of its start, clamped, is exact, so it is updated at the segment's end only
    (and the points touched down in it appended).  Steps also end at the segment's levels
    (:func:`_levels`).
    """
    return _period(prm, t0, z, PC, npc, HS, nh, rtol, atol, hmax, h, K, out, cnt, gz, halves,
                   np.empty(N_Z), np.empty(N_Z), np.empty(5), np.empty(4 * MAX_PIECES),
                   np.empty(4 * MAX_PIECES), np.empty(2 * MAX_PIECES), np.empty(2))


@jit_bare
def _period(prm, t0, z, PC, npc, HS, nh, rtol, atol, hmax, h, K, out, cnt, gz, halves, znew,
            k1, seg, LP, LN, LT, cs):
    """:func:`period` with its scratch (the step's end and first stage, the segment's
    record, the levels, the cosine and sine at a step's end), without reference counting
    (its step loop is hot).
    """
    c, a, n, V = prm[P_C], prm[P_A], prm[P_N], prm[P_V]
    jump = a > 1.0
    z[3] = 0.0
    z[4] = 0.0
    z[5] = 0.0
    z[6] = 0.0
    gz[0] = gz[1] = math.inf
    t = t0
    seg[0] = 0.0
    seg[1] = 0.0
    seg[2] = EDGE_NONE
    seg[3] = 0.0
    seg[4] = math.nan
    ct = math.cos(t)
    st = math.sin(t)
    rhs(t, z, k1, prm, PC, npc, HS, nh, seg, ct, st)
    HS[nh - 1, HDD] = k1[1]
    HS[nh - 1, HQ] = z[2] if not jump else HS[nh - 1, HU] * _rho(a, n, t) - z[2]
    HS[nh - 1, HP] = HS[nh - 1, HU] - c * (1.0 + a * ct)
    HS[nh - 1, HN] = HS[nh - 1, HU] + c * (1.0 + a * ct)
    HS[nh - 1, HC] = ct
    HS[nh - 1, HSN] = st
    for half in range(halves):
        t_end = t0 + (half + 1) * math.pi
        unloading = math.sin(t0 + (half + 0.5) * math.pi) > 0.0
        # a jumping indenter's flight [t_fl0, t_fl1] in this half: after the lift-off
        # (unloading) or before the touch-down (loading); none: both at the half's end
        t_fl0 = t_fl1 = t_end
        if jump and unloading:
            t_fl0 = _liftoff(a, t_end - 0.5 * math.pi)
        elif jump:
            t_fl0, t_fl1 = t_end - math.pi, _touchdown(a, t_end - 0.5 * math.pi)
        # the contact's boundary in this half (delta's zero: _delta)
        tc = math.nan if not jump else (t_fl0 if unloading else t_fl1)
        steps = 0
        # an edge velocity found to change sign at a step's very start (within 1e-12 of it,
        # too close to step to) has the wrong direction for its segment: the segment ends
        # there and the next one takes the other direction, once at a time t (t_forced)
        force_p = force_n = 0.0
        t_forced = math.nan
        while t < t_end - 1e-14 * (1.0 + t_end):  # segments
            cnt[3] += 1
            eps = 1e-12 * (1.0 + abs(t))
            flight = t_fl0 - eps <= t < t_fl1 - eps  # (no contact: F = 0, no profile)
            if flight:
                t_seg = t_fl1
                for i in range(2, 6):  # (a new contact: no stretch runs across a flight)
                    gz[i] = math.nan
                npc = 0  # every point has left (also where an event ended the contact a
                # rounding before the lift-off)
            elif t < t_fl0 - eps:
                t_seg = t_fl0  # the contact up to the lift-off
            else:
                t_seg = t_end
            d0 = _delta(a, t, tc)
            u0 = z[0] + V * t
            P0 = u0 - c * d0
            N0 = u0 + c * d0
            ud = z[1] + V
            ct = math.cos(t)
            st = math.sin(t)
            dd = -a * st
            ddd = -a * ct
            tol = 1e-9 * (abs(ud) + c * a)
            dirp = _direction(ud - c * dd, k1[1] - c * ddd, tol)
            dirn = _direction(ud + c * dd, k1[1] + c * ddd, tol)
            if force_p != 0.0:
                dirp = force_p
            if force_n != 0.0:
                dirn = force_n
            force_p = force_n = 0.0
            if unloading or flight:
                edge = EDGE_NONE
            elif dirp > 0.0:
                edge = EDGE_POS
            elif dirn < 0.0:
                edge = EDGE_NEG
            else:
                edge = EDGE_STUCK
            rho_s = _root(d0, n)
            seg[0] = rho_s
            seg[1] = z[2] if not jump else u0 * rho_s - z[2]  # Q at the segment's start
            seg[2] = edge
            seg[3] = d0  # rho_s^n
            seg[4] = tc
            t_s = t
            ih_s = nh - 1
            mp = mn = mt = 0
            if not flight:
                mp, mn, mt = _levels(prm, PC, npc, t, P0, N0, dirp > 0.0, dirn < 0.0,
                                     unloading, LP, LN, LT)
            ip = 0
            jn = 0
            it = 0
            first = True
            restart = False
            while True:  # steps of the segment
                steps += 1
                if steps > MAX_STEPS_HALF:
                    return FAIL_STEPS, nh, h
                if not first:  # (the library's at each step's start: no drift)
                    ct = math.cos(t)
                    st = math.sin(t)
                first = False
                while it < mt and LT[it] <= t + 1e-12:
                    it += 1
                t_stop = LT[it] if it < mt and LT[it] < t_seg else t_seg
                lp = LP[ip] if ip < mp else math.inf
                ln = LN[jn] if jn < mn else -math.inf
                hinted = False
                h_back = h
                while True:  # attempts
                    hh = min(h, t_stop - t, hmax)
                    if jump and not flight:  # (the force is C^1 only at both: steps shrink)
                        edge_dist = t - t_fl1 if not unloading else t_fl0 - t
                        hh = min(hh, max(EDGE_STEP, EDGE_RAMP * edge_dist))
                    _step(t, z, k1, hh, znew, K, prm, PC, npc, HS, nh, seg, ct, st, cs)
                    en = _err(z, znew, K, hh, rtol, atol)
                    if en > 1.0 or not math.isfinite(en):
                        cnt[1] += 1
                        if not (hinted or flight) and math.isfinite(en):
                            # a level inside the step: the force bends there, so the
                            # step's error falls only like h, not h^5, as it shrinks (seen:
                            # six rejections in a row); the next try ends just past it (the
                            # level then found on its dense output, below), and the step
                            # after it resumes this one's size
                            th_l = _level_in_step(z, znew, K, hh, t, prm, lp, ln, ct, st)
                            if th_l < 1.0:
                                hinted = True
                                h_back = hh
                                h = th_l * hh * (1.0 + LEVEL_PAST)
                                continue
                        h = hh * max(0.1, 0.9 * en ** -0.2) if math.isfinite(en) else 0.1 * hh
                        if h < 1e-13:
                            return FAIL_STEPS, nh, h
                        continue
                    th_ev, k_ev = 2.0, -1
                    if not flight:
                        th_ev, k_ev = _first_event(z, znew, K, hh, t, prm, dirp, dirn, lp, ln,
                                                   ct, st, gz)
                    if th_ev < 1.0 and th_ev * hh > 1e-12:
                        cnt[2] += 1  # the step cut at the event: its end from the dense
                        for i in range(N_Z):  # output (no step taken again), K[6] there
                            K[7, i] = _dense(z, znew, K, hh, i, th_ev)
                        hh = th_ev * hh
                        for i in range(N_Z):
                            znew[i] = K[7, i]
                        cs[0], cs[1] = _cs(t + hh, t, ct, st)
                        rhs(t + hh, znew, K[6], prm, PC, npc, HS, nh, seg, cs[0], cs[1])
                    elif th_ev < 1.0 and k_ev <= 1 and t != t_forced:
                        restart = True  # P' or N' has the other sign already: no step
                        t_forced = t
                        if k_ev == 0:
                            force_p = -dirp
                        else:
                            force_n = -dirn
                        _unchange(gz, k_ev, t)
                    else:
                        k_ev = -1
                        h = hh * min(5.0, max(0.2, 0.9 * en ** -0.2)) if en > 0.0 else 5.0 * hh
                    break
                if hinted:
                    h = h_back
                if restart:
                    break
                cnt[0] += 1
                t1 = t + hh
                if t_stop - t1 < 1e-12 * (1.0 + t_stop):
                    t1 = t_stop
                if nh >= HS.shape[0]:  # full: what the profile and the segment no longer need
                    n0 = nh
                    nh = compact(HS, nh, PC, npc, t_s)
                    ih_s -= n0 - nh
                    for j in range(npc):
                        PC[j, IF] = -1.0  # (the cached intervals moved)
                    if nh >= HS.shape[0]:
                        return FAIL_HISTORY, nh, h
                HS[nh, HT] = t1
                HS[nh, HU] = znew[0] + V * t1
                HS[nh, HD] = znew[1] + V
                HS[nh, HDD] = K[6, 1]
                HS[nh, HQ] = (znew[2] if not jump
                              else HS[nh, HU] * _root(_delta(a, t1, tc), n) - znew[2])
                if t1 != t + hh:  # (snapped to the stop)
                    cs[0], cs[1] = _cs(t1, t, ct, st)
                d1 = 1.0 + a * cs[0]
                HS[nh, HP] = HS[nh, HU] - c * d1
                HS[nh, HN] = HS[nh, HU] + c * d1
                HS[nh, HC] = cs[0]
                HS[nh, HSN] = cs[1]
                nh += 1
                w0 = z[2]
                for i in range(N_Z):
                    z[i] = znew[i]
                    k1[i] = K[6, i]
                t = t1
                if jump and not (unloading or flight):
                    # W after a touch-down: the steps' quadrature of rho u' errs by
                    # O(h^(1 + 1/n)) there; the stored history's, weighted, does not
                    z[2] = w0 + _wint(HS, nh - 2, HS[nh - 2, HT], t1, a, n, prm)
                    rhs(t, z, k1, prm, PC, npc, HS, nh, seg, cs[0], cs[1])
                    HS[nh - 1, HDD] = k1[1]
                    HS[nh - 1, HQ] = HS[nh - 1, HU] * _root(_delta(a, t1, tc), n) - z[2]
                u1 = z[0] + V * t
                while ip < mp and u1 - c * (1.0 + a * cs[0]) >= LP[ip] - 1e-12:
                    ip += 1
                while jn < mn and u1 + c * (1.0 + a * cs[0]) <= LN[jn] + 1e-12:
                    jn += 1
                if k_ev == 0 or k_ev == 1:
                    # the edge's velocity has changed sign: the next segment takes the other
                    # direction (the step redone to the event can end a rounding short of
                    # it, where a direction judged from the value would find the same
                    # change again just after: a segment of 1e-9..1e-5, seen)
                    if k_ev == 0:
                        force_p = -dirp
                    else:
                        force_n = -dirn
                    _sign_change(gz, k_ev, t)
                    break
                if t >= t_seg:
                    break
            if flight:
                continue
            # the segment's end: the old points clamped, the new ones appended (at a
            # lift-off none is left)
            u1 = z[0] + V * t
            d1 = _delta(a, t, tc)
            rho1 = _root(d1, n)
            _, _, _, m = _sweep(u1, prm, PC, npc, HS, nh, out, True, rho1, d1)
            if m > MAX_PIECES:
                return FAIL_PIECES, nh, h
            if edge != EDGE_NONE and rho1 > rho_s:
                r0p = rho_s * d0
                if edge == EDGE_STUCK:
                    m = _add(out, m, rho_s, rho1, HIS, HS[ih_s, HQ], t_s, t, r0p, rho1 * d1)
                else:
                    m = _add_edge(out, m, rho_s, rho1, r0p, rho1 * d1,
                                  1.0 if edge == EDGE_POS else -1.0, u1 - c * d1, u1 + c * d1)
                if m > MAX_PIECES:
                    return FAIL_PIECES, nh, h
            for j in range(m):
                for q in range(X1P + 1):
                    PC[j, q] = out[j, q]
                if PC[j, KIND] == HIS:  # the ends' u for the next segment's stages
                    PC[j, UA], _ = _hermite(HS, _hindex(HS, nh, PC[j, TA]), PC[j, TA])
                    PC[j, UB], _ = _hermite(HS, _hindex(HS, nh, PC[j, TB]), PC[j, TB])
                    PC[j, TF] = math.nan
                    PC[j, IF] = -1.0
            npc = m
    return npc, nh, h


@jit
def _sign_change(gz, kind, t):
    """``P'`` (``kind`` 0) or ``N'`` (1) changes sign at ``t``: the change before it is
    confirmed (no restart at its time undid it, :func:`_unchange`), so the stretch from the
    one before that to it lowers ``gz[1]`` (:func:`period`), unless shorter than
    :data:`SAME_CHANGE`.
    """
    _confirm(gz, kind)
    gz[4 + kind] = gz[2 + kind]
    gz[2 + kind] = t


@jit
def _confirm(gz, kind):
    """The stretch between the last two sign changes of ``kind`` lowers ``gz[1]``."""
    d = gz[2 + kind] - gz[4 + kind]  # (nan where either is none)
    if d > SAME_CHANGE:
        gz[1] = min(gz[1], d)


@jit
def _unchange(gz, kind, t):
    """A segment from ``t`` finds ``kind``'s velocity of the other sign at once: a change
    recorded at ``t`` (its event, located on a step's dense output, a rounding early) had
    not happened yet, and is taken back; else it is a change at ``t``.
    """
    if gz[2 + kind] == t:
        gz[2 + kind] = gz[4 + kind]
        gz[4 + kind] = math.nan
    else:
        _sign_change(gz, kind, t)


@jit
def _shortest_stretch(gz):
    """:func:`period`'s ``gz[1]`` with the last stretches of ``P'`` and ``N'`` counted."""
    _confirm(gz, 0)
    _confirm(gz, 1)
    return gz[1]


@jit
def compact(HS, nh, PC, npc, t_keep=math.inf):
    """Drop the history before the oldest history piece and ``t_keep`` (keeping their
    intervals); returns the new count.  The last entry is always kept.
    """
    t_keep = min(t_keep, HS[nh - 1, HT])
    for j in range(npc):
        if int(PC[j, KIND]) == HIS and PC[j, TA] < t_keep:
            t_keep = PC[j, TA]
    i0 = _hindex(HS, nh, t_keep)
    if i0 == 0:
        return nh
    m = nh - i0
    for i in range(m):
        for q in range(N_HS):
            HS[i, q] = HS[i0 + i, q]
    return m


@jit
def start(prm, y0, v0, PC, HS):
    """Steady sliding at ``tau = 0``: every point on the lower edge (slipping forwards);
    returns ``(npc, nh)``.
    """
    c, a, n, V = prm[P_C], prm[P_A], prm[P_N], prm[P_V]
    d = 1.0 + a
    rho = _root(d, n)
    PC[0, X0] = 0.0
    PC[0, X1] = rho
    PC[0, KIND] = AFP
    PC[0, VAL] = y0 - c * d
    PC[0, TA] = 0.0
    PC[0, TB] = 0.0
    PC[0, X0P] = 0.0
    PC[0, X1P] = rho * d
    HS[0, HT] = 0.0
    HS[0, HU] = y0
    HS[0, HD] = v0 + V
    HS[0, HDD] = 0.0  # (set by the first period)
    HS[0, HQ] = 0.0
    HS[0, HP] = y0 - c * d
    HS[0, HN] = y0 + c * d
    HS[0, HC] = 1.0
    HS[0, HSN] = 0.0
    return 1, 1


@jit
def _section(z, PC, npc, u, x):
    """The section state ``(y, y', the pieces' ends, their levels relative to u)`` into
    ``x``; returns its length.
    """
    x[0] = z[0]
    x[1] = z[1]
    for j in range(npc):
        x[2 + 2 * j] = PC[j, X1]
        x[3 + 2 * j] = PC[j, VAL] - u
    return 2 + 2 * npc


@jit
def _set_section(x, z, PC, npc, HS, nh, t, prm):
    """The inverse of :func:`_section` at time ``t`` (the ends kept in order, the last, the
    contact's edge, fixed), the history's last ``u``, ``u'`` with it.
    """
    V, n = prm[P_V], prm[P_N]
    u = x[0] + V * t
    z[0] = x[0]
    z[1] = x[1]
    HS[nh - 1, HU] = u
    HS[nh - 1, HD] = x[1] + V
    lo = 0.0
    for j in range(npc):
        e = PC[j, X1] if j == npc - 1 else min(max(x[2 + 2 * j], lo), PC[npc - 1, X1])
        PC[j, X0] = lo
        PC[j, X0P] = PC[j - 1, X1P] if j > 0 else 0.0
        PC[j, X1] = e
        PC[j, X1P] = e ** (n + 1.0)
        PC[j, VAL] = x[3 + 2 * j] + u
        lo = e


SECTION_OK, SECTION_NO_ORBIT = 0, 1
LEAP = 1e3  # a mixed step further than this times the residual from the map's is refused
# the transient's maps: at VROUGH until the state's relative change per period is below
# VROUGH_UNTIL (far from the orbit a map's error is swamped by its move, and the loose
# tolerance takes about a sixth fewer steps), then at ROUGH until it is below ROUGH_UNTIL
VROUGH, VROUGH_UNTIL = 1e-4, 1e-2
ROUGH, ROUGH_UNTIL = 1e-6, 1e-4
# a period whose map moves u = y + V tau by less than this fraction of the substrate's
# 2 pi V is a creep: the body mostly stuck to the substrate while the pin's spring loads
# (the slow transient of a soft pin or a slow sliding), extrapolated by steps doubling
DRIFT = 0.3
# a contact that never opens (a < 1), its coarse maps not grazing (:func:`steady`): each
# stage of the search ends once the map and the mixing's step both move the state by less
# than this many times state_tol and the mixing's estimate of int F on the orbit
# (:func:`_mixed_work`) moves by less than that times the sliding orbit's, the answer
# taken at that estimate, not at the last map's start: the correction is first-order in
# that distance, so its error is second-order (stopping at state_tol itself cost about a
# map a stage more, the maps often stalling at their noise); where the maps graze they are
# not smooth enough for it (just below V_c the stated error fell short by up to 3 times)
EXTRAPOLATED = 10.0
BALANCED = 6  # the first periods whose end is balanced (:func:`_balance`) where the pieces change


@jit
def _balance(prm, z, PC, npc, HS, nh):
    """Shift the section state (the body and the profile with it) by the mismatch of the
    last period's mean force balance.

    On the orbit ``alpha <y> + <F> = 0`` (the damping and the drive average out), so a
    body whose mean ``<y>`` misses ``-<F>/alpha`` is in the slow swing of its spring (the
    soft pin's transient), which plain periods damp only slowly.
    """
    _shift(-z[3] / (TWO_PI * prm[P_ALPHA]) - z[6] / TWO_PI, z, PC, npc, HS, nh)


@jit
def _shift(dy, z, PC, npc, HS, nh):
    """Move the body by ``dy`` with its profile (every level relative to ``u`` kept)."""
    z[0] += dy
    HS[nh - 1, HU] += dy
    for j in range(npc):
        PC[j, VAL] += dy


@jit
def _copy_state(PC, z, npc, PC_to, z_to):
    """The profile's first ``npc`` pieces and the body's state ``z`` copied to ``PC_to``,
    ``z_to``.
    """
    for j in range(npc):
        for q in range(N_PC):
            PC_to[j, q] = PC[j, q]
    for i in range(N_Z):
        z_to[i] = z[i]


@jit
def _change(new, old, i):
    """How far a section state's component ``i`` moved from ``old`` to ``new``.

    ``y`` (``i = 0``) absolutely (it sits near ``-(1 + a)^(1 + 1/n)/alpha``, far from 0
    where ``alpha`` is small), the rest relative to ``1 + |old|``.
    """
    return abs(new - old) / (1.0 + (abs(old) if i > 0 else 0.0))


@jit
def _mixed_work(W, nhist, gam):
    """``int F`` at the mixing's estimate of the orbit: the last map's, less the
    coefficients ``gam`` times the history's differences, as for the state (``int F`` is
    smooth in the map's start, so the same combination of starts carries it there).
    """
    w = W[nhist - 1]
    for q in range(nhist - 1):
        w -= (W[q + 1] - W[q]) * gam[q]
    return w


@jit
def steady(prm, z, PC, npc, HS, nh, rtol, fine, fine_graze, graze_depth, graze_time, depth,
           state_tol, growth, y_sliding, max_periods, cnt, res):
    """The periodic orbit from the state at ``tau = 0`` (:func:`start`): half a period,
    then periods from ``tau = pi`` mixed by Anderson on the section state (``depth`` maps,
    restarted where the pieces' kinds change; a mixed step after which the map's residual
    grows by ``growth`` is undone, back to the plain map's end it left; a map over which
    the body creeps with the substrate, :data:`DRIFT`, is not mixed but its move taken
    ``2^k - 1`` more times, ``k`` such maps in a row, down to ``y_sliding`` at most, the
    sliding body's mean ``y``; the maps at ``VROUGH`` until the state's relative change
    is below ``VROUGH_UNTIL``, at ``ROUGH`` until it is below ``ROUGH_UNTIL``, then at
    ``rtol``, the first of these from where the last rough one started and the history
    shifted as for the fine maps below) until it is below ``state_tol`` and so is the
    mixing's step (:func:`_change`; :data:`EXTRAPOLATED` times that where the contact
    never opens and the map does not graze, see below, where the mixing's estimate of
    ``int F`` on the orbit, :func:`_mixed_work`, has settled as far, and is taken); then
    with maps at ``fine * rtol`` (``fine_graze * rtol`` where that
    last coarse map grazes: an edge's velocity turning back within ``graze_depth`` times
    ``V + c a`` of 0, or changing sign twice within ``graze_time``, :func:`period`'s
    ``gz``; and always for a jumping indenter) to that map's orbit (the orbit
    of a map moves with its error, by more where the orbit attracts slowly, so the fine
    orbit is sought anew, not one fine period taken from the coarse orbit): the first
    fine map from where the last coarse one started, and the mixing's history shifted by
    the difference of their ends there (the two maps differ by their errors, nearly
    constant over the history's span, so its differences keep holding, and the offset is
    not taken for the state's own move).  Writes ``res = (int F over the
    coarse orbit's period, -, over the fine orbit's, its stick area, its slip area, the
    last map's start y, y', the last coarse map's graze depth over V + c a and its graze
    time)``.
    Returns ``(code, periods, events of the last period)``: ``code`` 0,
    :data:`SECTION_NO_ORBIT` or a kernel failure (< 0).
    """
    V = prm[P_V]
    K = np.zeros((8, N_Z))
    out = np.zeros_like(PC)
    gz = np.full(6, math.nan)
    nmax = 2 + 2 * MAX_PIECES
    X = np.zeros((depth, nmax))
    G = np.zeros((depth, nmax))
    W = np.zeros(depth)  # the maps' int F, with their starts X and ends G
    w_orbit = math.nan  # the mixing's estimate of int F on the orbit
    w_before = math.nan  # ... the one before (moved to the new maps where they change)
    w_scale = -TWO_PI * prm[P_ALPHA] * y_sliding  # int F of the sliding orbit
    grazes = False
    x = np.zeros(nmax)
    g = np.zeros(nmax)
    dg = np.zeros(nmax)
    kinds = np.zeros(MAX_PIECES + 1)
    z2 = np.zeros(N_Z)
    # the plain map's end where a mixed step left it (undone if that step made things worse)
    bz = np.zeros(N_Z)
    bpc = np.zeros_like(PC)
    bg = np.zeros(nmax)
    bnpc = 0
    mixed = False
    shift = False  # the history to be shifted to the fine map's
    creeps = prm[P_A] < 1.0  # (a jumping indenter's flight frees the body every period)
    ncreep = 0  # the creeping maps in a row
    stage = 0  # the maps at 0: max(rtol, VROUGH), then max(rtol, ROUGH) (the transient),
    tol_m = max(rtol, VROUGH)  # 1: rtol, 2: fine * rtol
    npc, nh, h = period(prm, 0.0, z, PC, npc, HS, nh, tol_m, 0.01 * tol_m, 0.5, 0.1, K, out,
                        cnt, gz, 1)
    if npc < 0:
        return npc, 0, 0
    nh = compact(HS, nh, PC, npc)
    t = math.pi
    nhist = 0
    last = math.inf
    w_prev = math.nan
    w_last = math.nan
    periods = 0
    found = False
    w_coarse = math.nan
    g_depth = g_time = math.nan
    ev = 0
    y_start = v_start = math.nan
    for m in range(max_periods):
        periods = m + 1
        nx = _section(z, PC, npc, z[0] + V * t, x)
        y_start = x[0]
        v_start = x[1]
        for j in range(npc):
            kinds[j] = PC[j, KIND]
        npc0 = npc
        for i in range(N_Z):
            z2[i] = z[i]
        ev0 = cnt[2]
        npc, nh, h = period(prm, t, z2, PC, npc, HS, nh, tol_m, 0.01 * tol_m, 0.5, h, K,
                            out, cnt, gz, 2)
        if npc < 0:
            return npc, periods, 0
        ev = cnt[2] - ev0
        nh = compact(HS, nh, PC, npc)
        t += 2.0 * math.pi
        for i in range(N_Z):
            z[i] = z2[i]
        w_prev = w_last
        w_last = z2[3]
        # a creep (the body mostly stuck to the substrate, u nearly unchanged) moves the
        # state along a nearly neutral direction the mixing cannot extrapolate (its map is
        # close to a translation: seen sending the state back by whole swings): the map's
        # move is taken 2^k - 1 more times instead, k the creeping maps in a row, never
        # beyond the sliding body's mean position y_sliding (every orbit's <y> is above it)
        dy = z[0] - x[0]
        if creeps and stage == 0 and abs(1.0 + dy / (TWO_PI * V)) < DRIFT:
            ncreep += 1
            nhist = 0
            mixed = False
            last = math.inf
            dy *= 2.0 ** min(ncreep - 1, 30) - 1.0
            dy = max(dy, min(0.0, y_sliding - z[0]))
            if dy != 0.0:
                _shift(dy, z, PC, npc, HS, nh)
            continue
        ncreep = 0
        same = npc == npc0
        if same:
            for j in range(npc):
                if PC[j, KIND] != kinds[j]:
                    same = False
        if not same:  # the pieces' kinds changed: a new start
            nhist = 0
            shift = False
            last = math.inf
            if m < BALANCED:
                _balance(prm, z, PC, npc, HS, nh)
            continue
        _section(z, PC, npc, z[0] + V * t, g)
        r = 0.0
        for i in range(nx):
            r = max(r, _change(g[i], x[i], i))
        if shift:  # the first map at a new tolerance, from where the last one started
            shift = False
            for i in range(nx):
                dg[i] = g[i] - G[nhist - 1, i]
            dw = w_last - W[nhist - 1]
            w_orbit += dw  # (the estimate before, at the new tolerance)
            nhist -= 1  # (this map's pair replaces it)
            for q in range(nhist):
                W[q] += dw
                for i in range(nx):
                    G[q, i] += dg[i]
        if mixed and r > growth * last:
            # the mixed step took the state where the map moves it farther: undone, back
            # to the plain map's end it left (the profile's structure of that time, its
            # levels relative to u now), and the mixing starts again from there
            npc = bnpc
            _copy_state(bpc, bz, npc, PC, z)
            _set_section(bg, z, PC, npc, HS, nh, t, prm)
            nhist = 0
            last = math.inf
            mixed = False
            continue
        mixed = False
        if stage == 0 and r < VROUGH_UNTIL:
            tol_m = max(rtol, ROUGH)
        coarse = stage == 0 and r < ROUGH_UNTIL
        if coarse:
            stage = 1  # near the orbit: the coarse maps, the first from where this one
            tol_m = rtol  # started and the history shifted to them (as the fine ones below)
        if r > growth * last:  # the mixing went astray: start again from here
            nhist = 0
        last = r
        keep = min(depth, nx + 1)
        if nhist == keep:  # drop the oldest
            for q in range(keep - 1):
                X[q, :nx] = X[q + 1, :nx]
                G[q, :nx] = G[q + 1, :nx]
                W[q] = W[q + 1]
            nhist -= 1
        X[nhist, :nx] = x[:nx]
        G[nhist, :nx] = g[:nx]
        W[nhist] = w_last
        nhist += 1
        w_before = w_orbit
        w_orbit = w_last
        ok = False
        jump = 0.0
        if nhist >= 2:
            dF = np.empty((nx, nhist - 1))
            for q in range(nhist - 1):
                for i in range(nx):
                    dF[i, q] = (G[q + 1, i] - X[q + 1, i]) - (G[q, i] - X[q, i])
            f = g[:nx] - x[:nx]
            gam = np.linalg.lstsq(dF, f)[0]
            ok = True
            w_orbit = _mixed_work(W, nhist, gam)
            for i in range(nx):
                s = g[i]
                for q in range(nhist - 1):
                    s -= (G[q + 1, i] - G[q, i]) * gam[q]
                jump = max(jump, _change(s, g[i], i))
                x[i] = s
                if not math.isfinite(s):
                    ok = False
            if not ok or jump > LEAP * r:  # an ill-conditioned mix: the plain map instead
                nhist = 0
                ok = False
                jump = 0.0
                w_orbit = w_last
        # converged where the map moved the state by less than stop and the mixing would
        # move it by less (it estimates the orbit: where that attracts slowly, the map's
        # own move understates the distance); never on the last map at the rough tolerance
        anew = coarse  # a new tolerance from the next map on
        # (a jumping indenter's int F stays the last map's, _search_error measuring its
        # distance; where a map grazes, it is not smooth enough in the state)
        if stage < 2:
            g_depth = gz[0] / (V + prm[P_C] * prm[P_A])
            g_time = _shortest_stretch(gz)
            # (a jumping indenter's brief stick just below V_c is not measured: its
            # stretches end at the flight; maps ten times finer fell short there, so its
            # fine maps are always the hundredfold ones)
            grazes = prm[P_A] > 1.0 or g_depth < graze_depth or g_time < graze_time
        stop = state_tol if grazes else EXTRAPOLATED * state_tol
        # (and the estimate of int F on the orbit settled as far: from a history that
        # still holds the rough maps' noise it can miss by far more than the state)
        settled = grazes or abs(w_orbit - w_before) < stop * w_scale
        if stage >= 1 and not coarse and r < stop and jump < stop and settled:
            if grazes:
                w_orbit = w_last
            if stage == 2:
                found = True
                break
            stage = 2  # on to the fine map's orbit
            w_coarse = w_orbit
            tol_m = (fine_graze if grazes else fine) * rtol
            anew = True
        if anew:
            # the first map at the new tolerance from where this one started: the
            # difference of their ends there shifts the history to the new maps' (they
            # differ by their errors, smooth in the state, so the history's differences
            # still hold, and the offset is not taken for the state's own move)
            last = math.inf
            shift = True
            ok = False
            for i in range(nx):
                x[i] = X[nhist - 1, i]
            _set_section(x, z, PC, npc, HS, nh, t, prm)
        if ok:
            bnpc = npc
            _copy_state(PC, z, npc, bpc, bz)
            for i in range(nx):
                bg[i] = g[i]
            mixed = True
            _set_section(x, z, PC, npc, HS, nh, t, prm)
    if not found:
        return SECTION_NO_ORBIT, periods, 0
    res[0] = w_coarse
    res[1] = w_prev
    res[2] = w_orbit
    res[3] = z[4]
    res[4] = z[5]
    res[5] = y_start
    res[6] = v_start
    res[7] = g_depth
    res[8] = g_time
    return 0, periods, ev
