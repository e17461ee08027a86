r"""The first zero of an event function on a segment, never missed.

An interval ``[t_a, t_b]`` on which ``g`` is positive at both ends is excluded
when a bound on ``|g''|`` over it (:func:`.basis.bound_parts`, which shrinks with
``t_a`` for decaying terms) proves that ``g`` cannot reach zero inside:

* ``min(g_a, g_b) > M_2 h^2 / 8`` (the linear interpolant's error bound), or the
  two tangent parabolas from the ends stay positive, or
* ``min(s_a, s_b) - M_{2,s} h^2/8 - R(t_a) > 0`` where ``s`` is ``g`` without its
  fast terms (a stiff contact's oscillation at ``sqrt(beta)`` up to 1e3, an
  over-damped contact's fast decay, a viscoelastic relaxation) whose envelope on
  the interval is ``R(t_a)``; this keeps fast terms from cutting the segment
  into tiny pieces.

Intervals that can be neither excluded nor shown to hold exactly one crossing are
bisected, leftmost first, so the earliest crossing is the one returned.  A
touching (double) zero is decided by the derivatives at the segment start
(:func:`start_margin`) or, inside a segment, by the interval shrinking below
``H_MIN`` without a sign change: a touch without crossing is not an event.
"""


import math

from .basis import (
    EXP,
    basis_values,
    bound_at,
    bound_parts,
    derivative,
    dot,
    fast_mask,
    has_cs,
    magnitude,
    sup_bound,
    value_at_zero,
)
from .jit import jit, jit_inline, stack_matrix

H_MIN = 1e-12  # intervals shorter than this without a sign change hold no crossing
REL_TOL = 1e-12  # round-off level of a value relative to its coefficients' sizes


@jit
def start_margin(c, m, T):
    """Does ``g`` stay positive just after ``t = 0``?

    Returns ``(ok, t_safe)``: ``ok`` is True when ``g > 0`` on ``(0, t_safe]``.  A
    zero value at the start is decided by the first non-vanishing derivative
    (up to the third), each compared with its own round-off level.
    """
    g0 = value_at_zero(c, m)
    tol = REL_TOL * magnitude(c)
    if g0 > tol:
        return True, 0.0
    if g0 < -tol:
        return False, 0.0
    c1 = derivative(c, m)
    c2 = derivative(c1, m)
    c3 = derivative(c2, m)
    g1 = value_at_zero(c1, m)
    tol = REL_TOL * magnitude(c1)
    if g1 > tol:
        b = sup_bound(c2, m, T)
        return True, min(T, g1 / b) if b > 0.0 else T
    if g1 < -tol:
        return False, 0.0
    g2 = value_at_zero(c2, m)
    tol = REL_TOL * magnitude(c2)
    if g2 > tol:
        b = sup_bound(c3, m, T)
        return True, min(T, 1.5 * g2 / b) if b > 0.0 else T
    if g2 < -tol:
        return False, 0.0
    g3 = value_at_zero(c3, m)
    tol = REL_TOL * magnitude(c3)
    if g3 > tol:
        b = sup_bound(derivative(c3, m), m, T)
        return True, min(T, 2.0 * g3 / b) if b > 0.0 else T
    return False, 0.0


@jit
def _refine(c, c1, m, a, b, ga, gb, m2):
    """Safeguarded Newton on a bracket with ``g(a) > 0 >= g(b)``, ``g`` monotone, ``m2`` a
    bound of ``|g''|`` on it.
    """
    cs = has_cs(c) or has_cs(c1)
    ce = c[8] != 0.0
    t = b if gb == 0.0 else a - ga * (b - a) / (gb - ga)
    probe = 0.0
    for _ in range(60):
        if not (a < t < b):
            t = 0.5 * (a + b)
        bv = basis_values(m, t, cs, ce)
        gt = dot(c, bv)
        if gt > 0.0:
            a = t
        else:
            b = t
            if gt == 0.0:
                return t
        if b - a <= 4e-16 * max(1.0, abs(b)):
            return b
        d = dot(c1, bv)
        if d == 0.0:
            t = 0.5 * (a + b)
            continue
        step = -gt / d
        t = t + step
        tol = 2e-16 * max(1.0, abs(t))
        if abs(step) <= tol or (m2 * step * step <= 0.05 * tol * abs(d) and a < t <= b):
            # converged to round-off: the step was, or the next one would be (Newton's
            # error after a step s is at most m2 s^2 / (2 |g'|))
            if a < t <= b:
                return t
            if t <= a:
                # converged onto the positive side, the step lost in rounding: the
                # crossing is within round-off of a, so probe just above it (1 ulp, then
                # 4, 16, ... while g stays positive in its noise) rather than halve the
                # bracket from its far end (tens of evaluations)
                probe = max(4.0 * probe, math.nextafter(a, math.inf) - a)
                t = a + probe
    return b


@jit
def _point(c, c1, m, t, cs, ce, f1, f2, fe):
    """``g``, its slow part (without the fast terms) and ``g'`` at ``t``."""
    bv = basis_values(m, t, cs, ce)
    g = dot(c, bv)
    fast = 0.0
    if f1:
        fast += c[4] * bv[4]
    if f2:
        fast += c[5] * bv[5]
    if fe:
        fast += c[8] * bv[8]
    return g, g - fast, dot(c1, bv)


@jit_inline
def _fast_terms(c, m):
    """Which terms of ``g`` are fast (:func:`.basis.fast_mask`) and present: ``(f1, f2,
    fe)`` for ``h1``, ``h2`` and the viscoelastic relaxation.
    """
    f1, f2, fe = fast_mask(m)
    if m[0] == EXP:  # two exponentials, each bounded by itself
        f1 = f1 and c[4] != 0.0
        f2 = f2 and c[5] != 0.0
    else:  # h1 and h2 share one envelope (bound_parts): both fast or both slow
        f1 = f2 = f1 and (c[4] != 0.0 or c[5] != 0.0)
    return f1, f2, fe and c[8] != 0.0


@jit_inline
def _split_bounds(c, c2, m, T, f1, f2, fe, pm2s, pr, ready, a, a_split, m2s, mr):
    """The bounds of the split test (``|g''|`` of the slow part, the envelope of the fast
    part): their parts ``pm2s``, ``pr`` on ``[t_a, T]``, made when first needed (``ready``
    False; many searches end by the other tests), and their values ``(m2s, mr)`` at ``a``,
    recomputed only when ``a`` is not ``a_split``.  Returns ``(pm2s, pr, True, a, m2s,
    mr)``.
    """
    if not ready:
        pm2s = bound_parts(c2, m, T, f1, f2, fe, 1)
        pr = bound_parts(c, m, T, f1, f2, fe, 2)
    if a != a_split:
        m2s = bound_at(pm2s, a)
        mr = bound_at(pr, a)
    return pm2s, pr, True, a, m2s, mr


@jit
def first_root(c, m, t0, T):
    """Earliest ``t`` in ``(t0, T]`` where ``g`` crosses from positive to ``<= 0``.

    ``g`` must be positive on ``(0, t0]`` (see :func:`start_margin`).  Returns -1.0
    when ``g`` stays positive, and ``t0`` when ``g(t0) <= 0`` already.
    """
    c1 = derivative(c, m)
    c2 = derivative(c1, m)
    cs = has_cs(c) or has_cs(c1)
    ce = c[8] != 0.0
    f1, f2, fe = _fast_terms(c, m)
    split = f1 or f2 or fe
    pm2 = bound_parts(c2, m, T, f1, f2, fe, 0)  # |g''| on [t_a, T]
    pm2s = pr = pm2  # the split test's, made when first needed
    ready = False
    a = t0
    ga, sa, da = _point(c, c1, m, a, cs, ce, f1, f2, fe)
    if ga <= 0.0:
        return a
    # right ends: t, g, slow part of g, g'; g = nan until evaluated (on the stack)
    stack = stack_matrix(96, 4)
    stack[0, 0] = T
    stack[0, 1] = math.nan
    top = 0
    # the bounds at a, recomputed only when a moves (bisection keeps it)
    a_m2 = a_split = math.nan
    m2 = m2s = mr = 0.0
    while top >= 0:
        b = stack[top, 0]
        h = b - a
        if a != a_m2:
            m2 = bound_at(pm2, a)
            a_m2 = a
        q = 0.125 * h * h
        hh = 0.5 * h
        last = h < H_MIN or top >= 95  # decided without bisection
        if stack[top, 1] != stack[top, 1]:
            # g(b) is needed only where [a, b] may be decided: each test below needs its
            # a-side half to hold (a lower bound through g(a) alone, or g monotone), so
            # where none does the interval is bisected whatever g(b) is, and g(b) waits
            # (most right ends of the descent towards a crossing are never needed)
            open_ = last or (da < 0.0 and -da > m2 * h) or ga > m2 * q \
                or ga + da * hh - 0.5 * m2 * hh * hh > 0.0
            if not open_ and split:
                pm2s, pr, ready, a_split, m2s, mr = _split_bounds(
                    c, c2, m, T, f1, f2, fe, pm2s, pr, ready, a, a_split, m2s, mr)
                open_ = sa - m2s * q - mr > 0.0
            if not open_:
                top += 1
                stack[top, 0] = 0.5 * (a + b)
                stack[top, 1] = math.nan
                continue
            stack[top, 1], stack[top, 2], stack[top, 3] = _point(c, c1, m, b, cs, ce, f1, f2, fe)
        gb = stack[top, 1]
        sb = stack[top, 2]
        db = stack[top, 3]
        if gb <= 0.0:
            # a crossing lies in (a, b]; accept when g is monotone there
            if da < 0.0 and -da > m2 * h or last:
                return _refine(c, c1, m, a, b, ga, gb, m2)
        else:
            # lower bounds: the linear interpolant, the two tangent parabolas meeting at
            # the midpoint, and the slow part minus the fast envelope
            excluded = (min(ga, gb) > m2 * q
                        or (ga + da * hh - 0.5 * m2 * hh * hh > 0.0
                            and gb - db * hh - 0.5 * m2 * hh * hh > 0.0))
            if not excluded and split:
                pm2s, pr, ready, a_split, m2s, mr = _split_bounds(
                    c, c2, m, T, f1, f2, fe, pm2s, pr, ready, a, a_split, m2s, mr)
                excluded = min(sa, sb) - m2s * q - mr > 0.0
            if excluded or last:
                a, ga, sa, da = b, gb, sb, db
                top -= 1
                continue
        top += 1
        stack[top, 0] = 0.5 * (a + b)
        stack[top, 1] = math.nan
    return -1.0
