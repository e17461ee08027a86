"""The exact Jacobian of the period map (``_kernels/tangent.py``) against the physics.

* ``J`` and the gradient ``G`` of the integral of ``f`` against central differences of
  the plain period map (an independent differentiation: the map's own event search, no
  variational equations), at seeded random points of every regime, every damping mode,
  over one and two periods;
* at each kind of event, a point whose period contains it, with a mutant of the
  variational equations at that kind shown to miss the differences by far;
* the Floquet multipliers of attracting orbits against the decay of perturbations in
  long runs of the plain map;
* Liouville's formula: over a period without events of the state (pure slip, slip and
  flight, pure stick) ``det J = exp(-trace * 2 pi p)``.
"""

import math
from collections import Counter

import numpy as np
import pytest

from reference_points import REGIMES, random_points
from vibrofriction._kernels.codes import (
    EV_LIFTOFF,
    EV_REVERSAL,
    EV_SECTION,
    EV_SLIP_TO_STICK,
    EV_STICK_TO_SLIP,
    EV_TOUCHDOWN,
    EVENT_NAMES,
    FLIGHT,
    N_SEG_COLUMNS,
    SEG_EVENT,
    SEG_PHASE,
    SEG_TAU,
    STICK,
)
from vibrofriction._kernels.integrate import (
    TWO_PI,
    free_approach,
    initial_state,
    next_boundary,
    run_periods,
    segment,
)
from vibrofriction._kernels.newton import _free_dimension
from vibrofriction._kernels.period import N_ACC, advance_period, period_map
from vibrofriction._kernels.phases import M_A, M_ALPHA, M_BETA, M_C, M_K, M_OFF, M_ON, make_model
from vibrofriction._kernels.tangent import period_map_tangent, saltation, segment_flow

MAX_EVENTS = 100_000
TRANSIENT = 4  # periods from steady sliding before the section state is taken
# zeta: undamped, under-damped, critically damped (zeta = 1), over-damped; eta_c: an
# elastic and a viscoelastic (relaxing) contact
DAMPING = [(zeta, eta) for zeta in (0.0, 0.02, 1.0, 3.0) for eta in (0.0, 0.1)]
# Differences: the fourth-order stencil (+-h, +-2h), h = STEP (|z_j| + s_j) / 4^i with s_j
# the natural scale of coordinate j (a force 1 + a over the stiffness of its motion: y
# alpha, e the contact's k, x' the fastest oscillation's velocity), the first step that
# the next one confirms.  No single step does for all regimes: the slope of the map
# changes on a fraction of s_j (how the event times move; near a grazing event much
# faster), so stiff contacts (alpha ~ 26, beta ~ 217, e ~ 5e-3) need h ~ 1e-7 (at
# 1e-5 the truncation error was 6e-4, going as h^4), while soft ones (y ~ -40, e ~ 0.02)
# lose 1e-6 to round-off (~ eps |z| / h) there and are exact to 1e-13 at h ~ 1e-3.
STEP = 1e-3
STEPS = 8  # down to STEP 4^-7 ~ 6e-8
TOL = 1e-6  # relative to 1 + max |J_fd| (resp. |G_fd|)
MIN_CHECKED = 0.8  # fraction of the cases of a regime that must be differentiable


def _args(pt, zeta, eta):
    """The kernels' point arguments of ``pt = (alpha, beta, a, V[, a_x, phase_x,
    on_substrate])`` (no in-plane oscillation when not given)."""
    inplane = tuple(pt[4:]) if len(pt) > 4 else (0.0, 0.0, True)
    return (*pt[:4], zeta, eta, *inplane)


def _section_state(M, periods=TRANSIENT, start=0):
    """``(y, x', e)`` and the phase on the section after ``periods`` from steady sliding
    (``start`` 0) or rest (1)."""
    z = np.array(list(initial_state(start, M)), dtype=float)
    acc = np.zeros(N_ACC)
    count = np.zeros(3, np.int64)
    for _ in range(periods):
        assert advance_period(z, acc, count, M, MAX_EVENTS)
    return z[:3].copy(), int(z[3])


def _plain(z3, ph, p, M):
    """The plain map over ``p`` periods: ``(state, phase, events, degenerate, int f)``, or
    None where the integration did not finish."""
    z = np.array([z3[0], z3[1], z3[2], float(ph), math.nan])
    acc = np.zeros(N_ACC)
    count = np.zeros(3, np.int64)
    for _ in range(p):
        if not advance_period(z, acc, count, M, MAX_EVENTS):
            return None
    return z[:3].copy(), int(z[3]), int(count[0]), int(count[1]), float(acc[0])


def _tangent(z3, ph, p, M):
    J = np.zeros((3, 3))
    G = np.zeros(3)
    acc = np.zeros(N_ACC)
    out = period_map_tangent(z3[0], z3[1], z3[2], ph, p, M, MAX_EVENTS, J, G, acc)
    return J, G, out, acc


def _column(pt, zeta, eta, z3, ph, p, events, j, h):
    """d(y, x', e, int f)/dz_j by the fourth-order stencil of step ``h``, or the reason the
    map is not differentiable there: it is smooth only where its sequence of events and
    phases is locally fixed, so every stencil point must have the sequence ``events`` and
    no segment of zero length (an event at the start of a phase: the state is outside
    that phase's chart and the event time is clamped)."""
    M = make_model(*_args(pt, zeta, eta))
    img = {}
    for k in (-2, -1, 1, 2):
        z = z3.copy()
        z[j] += k * h
        r = _plain(z, ph, p, M)
        if r is None:
            return "unfinished"
        if r[3]:
            return "degenerate"
        seq, clamped = _sequence(pt, zeta, eta, z, ph, p)
        if seq != events:
            return "events"
        if clamped:
            return "clamped"
        img[k] = np.append(r[0], r[4])
    return (8.0 * (img[1] - img[-1]) - (img[2] - img[-2])) / (12.0 * h)


def _differences(pt, zeta, eta, z3, ph, p, events):
    """``(J_fd, G_fd)`` over the free coordinates of ``ph``, or the reason there are none.

    Each column is taken at the steps ``h = STEP (|z_j| + s_j) / 4^i`` (see STEP), the
    first that the next one confirms within ``0.1 TOL``; steps whose stencil is not
    smooth (:func:`_column`) are passed over.
    """
    M = make_model(*_args(pt, zeta, eta))
    nd = _free_dimension(ph, M)
    Jfd = np.zeros((3, nd))
    Gfd = np.zeros(nd)
    for j in range(nd):
        h = STEP * (abs(z3[j]) + _scales(M)[j])
        prev = None
        for _ in range(STEPS):
            d = _column(pt, zeta, eta, z3, ph, p, events, j, h)
            h /= 4.0
            if isinstance(d, str):
                reason, prev = d, None
                continue
            if prev is not None and _rel(prev, d) <= 0.1 * TOL:
                break
            reason, prev = "not converged", d
        else:
            return reason
        Jfd[:, j] = d[:3]
        Gfd[j] = d[3]
    return Jfd, Gfd


def _scales(M):
    """Natural scales of ``(y, x', e)`` (see STEP)."""
    force = 1.0 + M[M_A]
    alpha, beta, k = M[M_ALPHA], M[M_BETA], M[M_K]
    if math.isinf(k):
        return force / alpha, force / math.sqrt(alpha), 0.0
    return force / alpha, force / math.sqrt(beta), force / k


def _rel(a, b):
    return float(np.abs(a - b).max() / (1.0 + np.abs(b).max()))


def _history(pt, zeta, eta, z3, ph, p):
    """The segments of ``p`` periods from the section state (``run_periods``)."""
    seg = np.zeros((50_000, N_SEG_COLUMNS))
    n = run_periods(0.0, z3[0], z3[1], z3[2], math.nan, ph, *_args(pt, zeta, eta), 1.0, p,
                    seg.shape[0], seg)
    assert n > 0
    return seg[:n]


def _sequence(pt, zeta, eta, z3, ph, p):
    """The events with the phases they enter, and whether a segment has zero length."""
    seg = _history(pt, zeta, eta, z3, ph, p)
    seq = tuple(zip(seg[1:, SEG_EVENT].astype(int), seg[1:, SEG_PHASE].astype(int),
                    strict=True))
    return seq, bool((np.diff(seg[:, SEG_TAU]) == 0.0).any())


def _event_kinds(pt, zeta, eta, z3, ph, p):
    """The events in ``p`` periods from the section state and the phases visited."""
    seg = _history(pt, zeta, eta, z3, ph, p)
    ev = seg[1:, SEG_EVENT].astype(int)
    return Counter(int(k) for k in ev if k != EV_SECTION), set(seg[:, SEG_PHASE].astype(int))


def _check_against_differences(pt, zeta, eta, p, z3=None, ph=None):
    """``(err_J, err_G, J, J_fd, G, G_fd)`` or the reason the case was skipped."""
    M = make_model(*_args(pt, zeta, eta))
    if z3 is None:
        z3, ph = _section_state(M)
    J, G, out, acc = _tangent(z3, ph, p, M)
    if out[5] < 0:
        return "unfinished"
    # the tangent map integrates the very same motion as the plain map
    assert out[:5] == period_map(z3[0], z3[1], z3[2], ph, p, M, MAX_EVENTS)[:5]
    if not out[7]:
        return "not smooth"
    if out[5] > 0:
        return "degenerate"
    events, clamped = _sequence(pt, zeta, eta, z3, ph, p)
    if clamped:
        return "clamped"
    r = _differences(pt, zeta, eta, z3, ph, p, events)
    if isinstance(r, str):
        return r
    plain = _plain(z3, ph, p, M)
    assert acc[0] == plain[4]
    Jfd, Gfd = r
    nd = Jfd.shape[1]
    return _rel(J[:, :nd], Jfd), _rel(G[:nd], Gfd), J[:, :nd], Jfd, G[:nd], Gfd


# ---------------------------------------------------------------------------------------
# 1. J and G against differences at random points of every regime and damping mode


def _sweep(regime, points):
    """Check every damping mode and p = 1, 2 at ``points``; print the counts."""
    rigid = regime in ("rigid", "resonant_IV")
    damping = [(z, e) for z, e in DAMPING if not (rigid and e)]  # eta_c: no rigid contact
    skipped = Counter()
    kinds = Counter()
    checked = 0
    worst = [0.0, 0.0]
    for pt in points:
        for zeta, eta in damping:
            for p in (1, 2):
                r = _check_against_differences(pt, zeta, eta, p)
                if isinstance(r, str):
                    skipped[r] += 1
                    continue
                err_j, err_g, J, Jfd, _, _ = r
                assert err_j <= TOL, (pt, zeta, eta, p, J, Jfd)
                assert err_g <= TOL, (pt, zeta, eta, p, err_g)
                checked += 1
                worst = [max(worst[0], err_j), max(worst[1], err_g)]
                M = make_model(*_args(pt, zeta, eta))
                z3, ph = _section_state(M)
                kinds.update(set(_event_kinds(pt, zeta, eta, z3, ph, p)[0]))
    total = checked + sum(skipped.values())
    print(f"\n{regime}: {checked}/{total} checked, skipped {dict(skipped)}, worst J "
          f"{worst[0]:.1e} G {worst[1]:.1e}, cases with "
          f"{ {EVENT_NAMES[k]: n for k, n in sorted(kinds.items())} }")
    assert checked >= MIN_CHECKED * total


@pytest.mark.parametrize("regime", REGIMES)
@pytest.mark.slow
def test_jacobian_and_gradient_match_differences(regime):
    _sweep(regime, random_points(2026, 8, regime))


def _with_inplane(points, seed):
    """``points`` with a longitudinal in-plane oscillation (issue 20): random amplitude and
    phase, on the substrate and on the holder in turn."""
    rng = np.random.default_rng(seed)
    return [(*pt, float(rng.uniform(0.2, 1.5)), float(rng.uniform(0.0, 2.0 * math.pi)),
             i % 2 == 0) for i, pt in enumerate(points)]


@pytest.mark.parametrize("regime", REGIMES)
@pytest.mark.slow
def test_jacobian_and_gradient_match_differences_inplane(regime):
    """The same with the in-plane force ``h`` (in the vector field before and after each
    event, and in a rigid stick's force and its event's time derivative)."""
    _sweep(regime, _with_inplane(random_points(2027, 6, regime), 20))


@pytest.mark.slow
@pytest.mark.parametrize("regime", REGIMES)
def test_jacobian_and_gradient_match_differences_wide(regime):
    """60 seeds x 5 points (4800 cases per regime, 2400 rigid): about 10 s per regime."""
    _sweep(regime, [pt for seed in range(60) for pt in random_points(seed, 5, regime)])


# ---------------------------------------------------------------------------------------
# 2. Each kind of event
#
# The variational equations are replayed here in Python from the kernel's own pieces (the
# replay is first checked to reproduce period_map_tangent bit for bit), with one mutation
# at the events of one kind; the mutant must miss the differences by far more than TOL,
# so that a wrong treatment of that kind would fail the check.
#
# Physics: a finite contact's force is continuous at each of its transitions (f = k e at
# the cone |f| = n; k e + c x' = s n where the contact point stops), so the vector field
# of (y, x', e) is too and the saltation matrix is the identity there; what such an event
# changes is the variational equation itself (stick's oscillator with beta, slip's with
# alpha) and the chart (e is slaved in elastic slip).  The mutant "hold" carries the
# perturbation across the segment after the event with the equation of the phase before
# it.  A rigid contact's force jumps where slip ends: at slip->stick (x'' = drag - s n
# to 0: the event time's shift changes int f, G) and at reversal (x'' jumps by 2 s n:
# S = diag(1, x''+/x''-) in (y, x'), J and G); the mutant "identity" drops the saltation.
# Lift-off and touch-down are at fixed drive phases (no time shift); a viscoelastic
# contact keeps relaxing in flight, the mutant "reset" unloads it as an elastic one.


def _replay(z3, ph, p, M, kind=-9, mutation=""):
    """:func:`.tangent.advance_period_tangent` over ``p`` periods, with ``mutation`` at
    the events of ``kind``; returns ``(J, G)`` (3 x 3, 3)."""
    y, xd, e = z3
    ed = math.nan
    J = np.eye(3)
    G = np.zeros(3)
    a = M[M_A]
    for _ in range(p):
        theta = 0.0
        hold = -1
        while theta < TWO_PI:
            _, bkind = next_boundary(theta, a, M[M_OFF], M[M_ON])
            free = free_approach(theta, ph, a, bkind)
            t, theta, y, xd, e, ed, _, ph1, ev, _, _, _ = segment(theta, y, xd, e, ed, ph, M)
            segment_flow(M, ph if hold < 0 else hold, free, t, J, G)
            hold = -1
            hit = ev == kind
            if hit and mutation == "hold":
                hold = ph
            if hit and mutation == "reset":
                J[2, :] = 0.0
            if not (hit and mutation in ("hold", "identity")):
                if ev in (EV_STICK_TO_SLIP, EV_SLIP_TO_STICK, EV_REVERSAL):
                    if not free:
                        saltation(M, ph, ph1, theta, y, xd, e, J, G)
                elif ev == EV_LIFTOFF and M[M_C] == 0.0:
                    J[2, :] = 0.0
            ph = ph1
    return J, G


# (id, (alpha, beta, a, V), zeta, eta_c, kind, mutation, phase entered at the event)
EVENT_CASES = [
    # elastic stick-slip: stick's oscillator (beta) hands over to slip's (alpha)
    ("stick->slip", (0.5, 2.0, 0.5, 0.3), 0.02, 0.0, EV_STICK_TO_SLIP, "hold", None),
    # viscoelastic contact: slip hands over to stick, e becomes a free coordinate of stick
    ("slip->stick", (0.5, 2.0, 0.5, 0.3), 0.02, 0.1, EV_SLIP_TO_STICK, "hold", STICK),
    # rigid contact (case IV): stick (1-D chart, x' = 0) hands over to slip (2-D)
    ("rigid stick->slip", (1.0, math.inf, 0.5, 3.0), 0.0, 0.0, EV_STICK_TO_SLIP, "hold", None),
    # rigid contact: the force jumps from s n to -alpha y + gamma V when the body stops
    ("rigid slip->stick", (1.0, math.inf, 0.5, 3.0), 0.0, 0.0, EV_SLIP_TO_STICK, "identity",
     STICK),
    # rigid contact: the body turns round in slip, the friction force flips
    ("reversal", (1.0, math.inf, 0.5, 3.0), 0.0, 0.0, EV_REVERSAL, "identity", None),
    # jumping, viscoelastic: e at lift-off relaxes through flight into the next contact
    ("lift-off", (0.5, 2.0, 1.5, 0.3), 0.0, 1.0, EV_LIFTOFF, "reset", FLIGHT),
    # jumping at a low speed: the body lands in stick (the flight's free oscillator hands
    # over to stick's)
    ("touch-down", (0.5, 5.0, 1.1, 0.02), 0.0, 0.0, EV_TOUCHDOWN, "hold", STICK),
]


@pytest.mark.parametrize("case", EVENT_CASES, ids=[c[0] for c in EVENT_CASES])
def test_jacobian_across_each_kind_of_event(case):
    _, pt, zeta, eta, kind, mutation, entered = case
    M = make_model(*_args(pt, zeta, eta))
    z3, ph = _section_state(M)
    kinds, _ = _event_kinds(pt, zeta, eta, z3, ph, 1)
    assert kinds[kind] >= 1, kinds  # the period contains the event
    if entered is not None:  # ... and enters the phase that makes it matter
        seg = _history(pt, zeta, eta, z3, ph, 1)
        after = {int(row[SEG_PHASE]) for row in seg[1:] if int(row[SEG_EVENT]) == kind}
        assert entered in after, after
    r = _check_against_differences(pt, zeta, eta, 1, z3, ph)
    assert not isinstance(r, str), r
    err_j, err_g, _, Jfd, _, Gfd = r
    assert err_j <= TOL and err_g <= TOL, (err_j, err_g)
    nd = Jfd.shape[1]
    J, G, _, _ = _tangent(z3, ph, 1, M)
    Jr, Gr = _replay(z3, ph, 1, M)
    assert np.array_equal(Jr, J) and np.array_equal(Gr, G)  # the replay is the kernel
    Jm, Gm = _replay(z3, ph, 1, M, kind, mutation)
    miss = max(_rel(Jm[:, :nd], Jfd), _rel(Gm[:nd], Gfd))
    assert miss > 1e3 * TOL, miss
    if math.isfinite(pt[1]) and kind in (EV_STICK_TO_SLIP, EV_SLIP_TO_STICK):
        # a finite contact's force is continuous: its saltation is the identity
        Ji, Gi = _replay(z3, ph, 1, M, kind, "identity")
        assert _rel(Ji, J) < 1e-12 and _rel(Gi, G) < 1e-12


# ---------------------------------------------------------------------------------------
# 3. Floquet multipliers against long runs of the plain map


def _orbit(M, p, periods=3000):
    """An attracting orbit of period ``p``: iterate the map until it repeats itself."""
    z3, ph = _section_state(M, 0)
    for _ in range(periods):
        r = _plain(z3, ph, p, M)
        if r[1] == ph and np.abs(r[0] - z3).max() <= 1e-14 * (1.0 + np.abs(z3).max()):
            return r[0], ph
        z3, ph = r[0], r[1]
    raise AssertionError("no periodic orbit")


def _run(z3, ph, p, M, m):
    """The section states ``z_0 .. z_m`` of ``m`` iterations of the map (``p`` periods)."""
    out = [z3]
    for _ in range(m):
        r = _plain(out[-1], ph, p, M)
        assert r[1] == ph
        out.append(r[0])
    return np.array(out)


# ((alpha, beta, a, V), zeta, eta_c, p): the leading multiplier of each, from J
FLOQUET_CASES = [
    ((0.5, 2.0, 0.5, 0.3), 1.0, 0.0, 1),  # stick-slip, critically damped: 0.138
    ((0.5, 2.0, 0.5, 0.3), 3.0, 0.1, 1),  # over-damped, viscoelastic (3-D slip chart): 0.491
    ((0.5, math.inf, 0.5, 0.3), 0.02, 0.0, 1),  # rigid, 1-D stick chart: -0.915
    ((1.0, math.inf, 0.5, 3.0), 0.02, 0.0, 1),  # rigid at the slip resonance: 0.556
    ((0.5, 2.0, 0.5, 0.3), 0.0, 0.0, 1),  # undamped stick-slip: 0.246 +- 0.634 i
    ((0.5, 2.0, 1.5, 0.3), 0.0, 0.1, 1),  # jumping, viscoelastic: 0.192 +- 0.766 i
    ((0.01, 0.02, 0.5, 0.4), 0.02, 0.0, 1),  # stiff system: 0.723 +- 0.537 i
    ((0.2, 0.9, 0.7, 0.3), 0.02, 0.0, 1),  # continuous sliding: -0.894 +- 0.308 i
    ((0.5, 2.0, 0.5, 0.3), 0.02, 0.0, 2),  # the same orbit over two periods: lambda^2
]


@pytest.mark.parametrize("pt, zeta, eta, p", FLOQUET_CASES)
def test_floquet_multiplier_is_the_decay_rate_of_long_runs(pt, zeta, eta, p):
    """A perturbation along the leading Floquet vector decays like ``lambda^m``: for a
    real multiplier the distance between the perturbed and the orbit's run shrinks by
    ``|lambda|`` each period; for a complex pair any component of the deviation obeys
    ``s_{m+2} = 2 Re(lambda) s_{m+1} - |lambda|^2 s_m``, whose coefficients are fitted
    to the run of the plain map (J is used only for the starting direction)."""
    M = make_model(*_args(pt, zeta, eta))
    z3, ph = _orbit(M, p)
    J, _, out, _ = _tangent(z3, ph, p, M)
    assert out[7] and out[3] == ph
    nd = _free_dimension(ph, M)
    lam, vec = np.linalg.eig(J[:nd, :nd])
    i = int(np.argmax(np.abs(lam)))
    lam1 = complex(lam[i])
    assert 0.05 < abs(lam1) < 0.99  # attracting, and slowly enough to measure
    m = math.ceil(math.log(1e-3) / math.log(abs(lam1)))  # three decades of decay
    d0 = np.zeros(3)
    d0[:nd] = np.real(vec[:, i])
    d0 *= 1e-6 * (1.0 + np.abs(z3).max()) / np.abs(d0).max()
    dev = (_run(z3 + d0, ph, p, M, m) - _run(z3, ph, p, M, m))[:, :nd]
    if abs(lam1.imag) < 1e-12 * abs(lam1):
        dist = np.linalg.norm(dev, axis=1)
        rate = math.log(dist[m] / dist[0]) / (m * math.log(abs(lam1)))
        assert rate == pytest.approx(1.0, abs=1e-3)
        assert np.sign(dev[m] @ dev[0]) == np.sign(lam1.real) ** m  # the sign flips if < 0
    else:
        k = int(np.argmax(np.abs(dev[0])))
        s = dev[:, k]
        A = np.column_stack([s[1:-1], -s[:-2]])
        (trace, det), *_ = np.linalg.lstsq(A, s[2:], rcond=None)
        fitted = np.roots([1.0, -trace, det])
        assert np.min(np.abs(fitted - lam1)) <= 1e-3 * abs(lam1), (fitted, lam1)
    if p == 2:  # the orbit of period 1 iterated twice: the multiplier squared
        J1, _, _, _ = _tangent(z3, ph, 1, M)
        lam_1 = np.linalg.eigvals(J1[:nd, :nd])
        assert np.min(np.abs(lam_1 ** 2 - lam1)) <= 1e-9


# ---------------------------------------------------------------------------------------
# 4. Liouville's formula where no state event interrupts the flow
#
# Between events the perturbation obeys a linear ODE, and det J = exp(int trace): in
# slip and flight, (y, x') moves as the free oscillator (trace -gamma) and a viscoelastic
# contact's e relaxes (trace -1/eta_c); in stick, x'' = ... - (gamma + c) x' with
# e' = x', y' = x' - V (trace -(gamma + c), c = eta_c k).  Lift-off and touch-down
# happen at fixed drive phases and move no event time.  In slip f = s n does not depend
# on the state: G = 0.

# (id, (alpha, beta, a, V), zeta, eta_c, phases of the period: slip only, slip and
# flight, stick only)
LIOUVILLE_CASES = [
    ("slip undamped", (0.5, 2.0, 0.5, 3.0), 0.0, 0.0, "slip"),
    ("slip under-damped", (0.5, 2.0, 0.5, 3.0), 0.02, 0.0, "slip"),
    ("slip critical", (0.5, 2.0, 0.5, 3.0), 1.0, 0.0, "slip"),
    ("slip over-damped", (0.05, 0.5, 0.5, 5.0), 3.0, 0.0, "slip"),
    ("slip viscoelastic", (0.5, 2.0, 0.5, 3.0), 0.02, 1.0, "slip"),
    ("slip viscoelastic fast", (0.5, 2.0, 0.5, 3.0), 0.02, 0.1, "slip"),
    ("slip rigid", (0.5, math.inf, 0.5, 3.0), 0.02, 0.0, "slip"),
    ("slip rigid undamped", (0.5, math.inf, 0.5, 3.0), 0.0, 0.0, "slip"),
    ("jumping undamped", (0.5, 2.0, 1.5, 10.0), 0.0, 0.0, "flight"),
    ("jumping", (4.0, 8.0, 1.3, 2.0), 0.02, 0.0, "flight"),
    ("jumping viscoelastic", (0.5, 2.0, 1.5, 10.0), 0.02, 1.0, "flight"),
    ("jumping rigid", (0.5, math.inf, 1.5, 5.0), 1.0, 0.0, "flight"),
    ("stick undamped", (0.5, 2.0, 0.1, 0.001), 0.0, 0.0, "stick"),
    ("stick under-damped", (0.5, 2.0, 0.1, 0.001), 0.02, 0.0, "stick"),
    ("stick viscoelastic", (0.5, 2.0, 0.1, 0.001), 0.0, 0.1, "stick"),
]


@pytest.mark.parametrize("p", [1, 2])
@pytest.mark.parametrize("case", LIOUVILLE_CASES, ids=[c[0] for c in LIOUVILLE_CASES])
def test_determinant_follows_liouville(case, p):
    _, pt, zeta, eta, kind = case
    M = make_model(*_args(pt, zeta, eta))
    # stick throughout: from rest, the drift V t loads the spring far below the cone
    z3, ph = _section_state(M, start=1 if kind == "stick" else 0)
    kinds, phases = _event_kinds(pt, zeta, eta, z3, ph, p)
    viscous = M[M_C] > 0.0
    gamma = 2.0 * zeta * math.sqrt(pt[0])
    if kind == "stick":
        assert phases == {STICK} and not kinds
        trace = gamma + M[M_C]
    else:
        assert STICK not in phases
        assert set(kinds) <= {EV_LIFTOFF, EV_TOUCHDOWN}
        assert (FLIGHT in phases) == (kind == "flight")
        trace = gamma + (1.0 / eta if viscous else 0.0)
    J, G, out, _ = _tangent(z3, ph, p, M)
    assert out[7] and out[3] == ph
    nd = _free_dimension(ph, M)
    assert nd == (3 if kind == "stick" or viscous else 2)
    expected = math.exp(-trace * TWO_PI * p)
    det = np.linalg.det(J[:nd, :nd])
    assert det == pytest.approx(expected, rel=1e-9)
    if kind != "stick":
        assert not G[:nd].any()
