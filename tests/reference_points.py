"""Seeded random points per regime and the reference value with its own error bar.

The harness of the differential tests (``tests/reference/test_differential.py``): the exact
solver against the independent fixed-step integrator of :mod:`vibrofriction_reference`
(peer B), which shares no code with it. Every point is checked by
``vibrofriction.Dimensionless`` (the package's parameter validation; the reference
validates nothing physical).

``reference_mu`` returns ``(mu, err)``, ``mu`` from the finest of three step sizes
(3200 steps per fastest period for a finite contact, 12800 for a rigid one) and ``err``
the sum of three bounds, each on one error of the reference, all measured:

* discretisation: the largest ``|mu(fine) - mu(coarse)|`` over two coarser runs, with
  8 and ``sqrt 8`` times fewer steps. For an error ``C dt^p`` the fine run's error is
  ``|mu(fine) - mu(coarse)| / (8^p - 1)``: the safety factor is 63 at the order
  ``p ~ 2`` of ``tests/reference/test_reference.py`` (fitted slopes 1.7-2.3) and 7 at first
  order (Moreau's scheme at fine steps). It has to be that large, and a second coarse
  run is needed, because the error is not a smooth function of ``dt``: the switches fall
  anywhere between two steps, the error changes sign from one resolution to the next,
  and in nearly neutral orbits it stays on plateaus (measured: at ``alpha, beta, a =
  0.103, 0.618, 2.33`` the runs at 400 and 3200 steps agree to 5e-10 but both are 5e-8
  off; a rigid point at ``alpha = 1.13`` sits at 2.4e-5 from 6400 to 38400 steps). On
  134 finite-contact points of all regimes the fine error over ``|fine - coarse|``
  was at most 0.4 at the ratio 8 and reached 2.4 at the ratio 4 (400 vs 1600 steps);
  on 48 rigid points, against the event-driven peer A, at most 0.35 (1600 vs 12800);
* averaging: the ratio ``<f>/<n>`` over each half of the averaging window (largest
  difference over the runs), times 4. With the defaults (transient 120 periods, window
  240) each half is 120 periods, so a periodic orbit of 1-6 drive periods is averaged
  exactly in both halves, and the halves' ages differ by the factor 2 that makes the
  check scale-free: a deficit decaying like ``k^-g`` leaves the full window off by
  ``(H1 + H2) / 2``, at most 1.9 (``g = 1``) and 3.8 (``g = 1/2``) times the halves'
  difference ``H1 - H2``; a geometric decay with ratio ``q`` per half gives
  ``(1 + q) / (2 (1 - q))``, at most 4 for ``q <= 0.78``;
* transient: the coarsest run goes on to two later windows of the same length (after
  600 and 1080 periods with the defaults). With ``d1, d2`` the changes of the window
  mean from one to the next and ``q = |d2 / d1|``, a geometric approach leaves the first
  window ``|d1| + |d2| / (1 - q)`` from the limit; if ``q > 0.5`` (or ``d1 = 0`` while
  ``d2`` is not within the averaging noise) the transient is too slow for these windows
  and ``err`` is ``inf``: the point cannot be checked. This catches what the halves
  miss: rare stick events that stop (just above ``V*`` the window means go 8e-8, 0,
  2e-9, 0 below 1), slow algebraic approaches (case IV at resonance: ``mu`` still
  rises by 1e-4 between periods 3000 and 6000) and orbits whose leading multiplier is
  close to 1 (``alpha, beta = 4.84, 4.92``: multiplier 0.99987, the window means creep
  by 3e-5 per 400 periods towards a value 3.3e-4 above the first window: ``inf``).

For a rigid contact the discretisation term is multiplied by 3: in a sweep of 480
points (seeds 0-9, 6 per regime) Moreau's fine error reached 2.1 times ``|fine -
coarse|`` (``alpha = 3.76``, ``a = 1.67``: the runs at 1600, 4525, 12800 steps are
5.5e-5, 2.6e-5, 4.9e-5 off), where the finite-contact runs stayed below 0.4. With
these bounds that sweep has no disagreement with the solver and 4 points that cannot be
checked (3 rigid, 1 stiff).

Not bounded: a drift slower than these windows see (near ``beta = 1`` with a small
``alpha``, ``docs/modulation.md``), and a coexisting attractor reached by the solver but
not by the reference (both start from the same state). Cost (2 shared cores, numba
warm): median 103 ms, mean 100 ms, at most 396 ms per point over those 480 points,
proportional to ``max(1, sqrt(alpha), sqrt(beta))``.
"""

from __future__ import annotations

import math

import numpy as np

import vibrofriction as vf
from vibrofriction_reference import return_mapping_periods

REGIMES = (
    "soft",
    "stiff",
    "general",
    "alpha_gt_1",
    "jumping_above_vstar",
    "rigid",
    "resonant_IV",
    "contact_resonance_III",
)

# Steps per period of the fastest oscillation (coarse, middle, fine): Verlet for a finite
# contact (second order), Moreau for a rigid one (drifts to first order), with more.
STEPS = {"finite": (400, 1131, 3200), "rigid": (1600, 4525, 12800)}
TRANSIENT_PERIODS = 120
AVERAGE_PERIODS = 240
LATER_WINDOWS = 2  # of the coarsest run: after 600 and 1080 periods with the defaults
AVERAGING_SAFETY = 4.0
MOREAU_SAFETY = 3.0
SLOWEST_DECAY = 0.5
ROUND_OFF = 1e-12


def v_star(alpha: float, beta: float, a: float) -> float:
    """Critical inertial velocity ``V* = a |beta - 1| / ((beta - alpha) |alpha - 1|)``
    (eq. 12 in the scaling of docs/model.md; ``a / |alpha - 1|`` for ``beta = inf``)."""
    contact = 1.0 if math.isinf(beta) else abs(beta - 1.0) / (beta - alpha)
    return a * contact / abs(alpha - 1.0)


def _log_uniform(rng: np.random.Generator, low: float, high: float) -> float:
    return float(math.exp(rng.uniform(math.log(low), math.log(high))))


def _away_from_one(draw, *, alpha_gap: float = 0.05, beta_gap: float = 0.05):
    """Redraw ``(alpha, beta)`` until ``|alpha - 1| >= alpha_gap``, ``|beta - 1| >= beta_gap``."""
    while True:
        alpha, beta = draw()
        if abs(alpha - 1.0) >= alpha_gap and abs(beta - 1.0) >= beta_gap:
            return alpha, beta


def _draw(rng: np.random.Generator, regime: str) -> tuple[float, float, float, float]:
    """One point ``(alpha, beta, a, V)`` of ``regime``."""
    a = float(rng.uniform(0.1, 2.5))
    vbar = float(rng.uniform(0.05, 1.2))
    if regime == "soft":
        alpha, beta = _log_uniform(rng, 0.02, 0.1), _log_uniform(rng, 10.0, 100.0)
    elif regime == "stiff":
        # a contact much softer than the distance from the slip resonance: beta - alpha
        # is 1-10 % of |alpha - 1| (so |beta - 1| >= 0.9 |alpha - 1| >= 0.045)
        alpha, _ = _away_from_one(lambda: (_log_uniform(rng, 0.05, 5.0), 2.0))
        beta = alpha + abs(alpha - 1.0) * _log_uniform(rng, 0.01, 0.1)
    elif regime == "general":
        def general():
            alpha = _log_uniform(rng, 0.05, 5.0)
            return alpha, alpha * _log_uniform(rng, 1.1, 20.0)

        alpha, beta = _away_from_one(general)
    elif regime == "alpha_gt_1":
        alpha = _log_uniform(rng, 1.2, 40.0)
        beta = alpha * _log_uniform(rng, 1.05, 10.0)
    elif regime == "jumping_above_vstar":
        def jumping():
            alpha = _log_uniform(rng, 0.05, 40.0)
            return alpha, alpha * _log_uniform(rng, 1.05, 5.0)

        alpha, beta = _away_from_one(jumping)
        a, vbar = float(rng.uniform(1.05, 3.0)), float(rng.uniform(1.05, 2.0))
    elif regime == "rigid":
        alpha, beta = _away_from_one(lambda: (_log_uniform(rng, 0.05, 5.0), 2.0))
        beta = math.inf
    elif regime == "resonant_IV":
        return 1.0, math.inf, a, _log_uniform(rng, 0.2, 5.0)
    elif regime == "contact_resonance_III":
        beta = 1.0 + float(rng.choice([-1.0, 1.0])) * float(rng.uniform(0.02, 0.2))
        alpha = _log_uniform(rng, 0.05, 0.6)
        vbar = float(rng.uniform(0.05, 1.5))
    else:
        raise ValueError(f"regime must be one of {REGIMES}, got {regime!r}")
    return alpha, beta, a, vbar * v_star(alpha, beta, a)


def random_points(seed: int, n: int, regime: str) -> list[tuple[float, float, float, float]]:
    """``n`` seeded random valid points ``(alpha, beta, a, V)`` of ``regime`` (see REGIMES).

    The generator is seeded by ``(seed, regime)``, so each regime has its own stream.
    Each point passes ``vibrofriction.Dimensionless`` (which raises otherwise).
    """
    if regime not in REGIMES:
        raise ValueError(f"regime must be one of {REGIMES}, got {regime!r}")
    rng = np.random.default_rng([seed, REGIMES.index(regime)])
    points = []
    for _ in range(n):
        alpha, beta, a, V = _draw(rng, regime)
        vf.Dimensionless(alpha, beta, a)
        points.append((alpha, beta, a, V))
    return points


def static_kinetic_points(n: int, seed) -> list[tuple]:
    """``n`` random points of every regime the static-above-kinetic reference covers: ``(alpha,
    beta, a, V, zeta, s_r, start)``, a finite elastic contact and a rigid one in turn,
    jumping every fourth, undamped every third, ``1.1 <= s_r <= 2.2``, from steady sliding
    and from rest in turn (``seed``: anything ``numpy.random.default_rng`` takes).
    """
    rng = np.random.default_rng(seed)
    out = []
    for i in range(n):
        alpha = float(rng.uniform(0.1, 2.0))
        beta = math.inf if i % 2 else alpha + float(rng.uniform(0.5, 8.0))
        a = float(rng.uniform(1.05, 1.5)) if i % 4 == 1 else float(rng.uniform(0.1, 0.95))
        zeta = float(rng.uniform(0.02, 0.2)) if i % 3 != 2 else 0.0
        out.append((alpha, beta, a, float(rng.uniform(0.05, 0.6)), zeta,
                    float(rng.uniform(1.1, 2.2)), ("sliding", "rest")[i % 2]))
    return out


def rate_state_points(n: int, seed) -> list[dict]:
    """``n`` random points of every regime the rate-and-state reference covers (``seed``:
    anything ``numpy.random.default_rng`` takes), as dicts of the arguments of
    ``rate_state_run`` (``alpha, beta, amplitude, V, a, b, d_c, v_ref, alpha_ld, law, zeta,
    eta_c``).

    By the index ``i``: a rigid contact (``beta = inf``) every fourth point (``i % 4 ==
    3``), a contact dashpot ``eta_c`` log-uniform 0.02..0.4 every fourth (``i % 4 == 1``,
    a finite contact), jumping (``amplitude`` 1.05..1.5, else 0.1..0.95) every third (``i %
    3 == 0``).  Drawn: velocity weakening (``b/a`` 1.05..1.6) or strengthening (0.3..0.95)
    and the aging or the slip law, each half of the points; the Linker-Dieterich coupling
    (``alpha_ld`` 0.1..0.3) at half of the points that do not jump (it needs ``amplitude <
    1``); a pin dashpot (``zeta`` log-uniform 0.02..0.3) at two thirds.  ``alpha``
    0.2..3.2, ``beta - alpha`` 1..10, ``V`` 0.1..2, ``d_c`` 0.01..0.1, ``v_ref`` 0.32..2, all
    log-uniform; ``a`` 0.01..0.05 (finite contact) and, rigid, 0.032..0.079 or with jumping
    0.05..0.079: where the reference's rigid contact is well behaved (it can fail at ``a =
    0.02`` with jumping and at ``a <= 0.01``, the ``rate_state_run`` docstring).  Each
    point passes ``vibrofriction.Dimensionless``.
    """
    rng = np.random.default_rng(seed)
    out = []
    for i in range(n):
        rigid, damped, jumping = i % 4 == 3, i % 4 == 1, i % 3 == 0
        alpha = _log_uniform(rng, 0.2, 3.2)
        beta = math.inf if rigid else alpha + _log_uniform(rng, 1.0, 10.0)
        amplitude = float(rng.uniform(1.05, 1.5) if jumping else rng.uniform(0.1, 0.95))
        V = _log_uniform(rng, 0.1, 2.0)
        zeta = _log_uniform(rng, 0.02, 0.3) if rng.uniform() < 2.0 / 3.0 else 0.0
        eta_c = _log_uniform(rng, 0.02, 0.4) if damped else 0.0
        if rigid:
            a = _log_uniform(rng, 0.05 if jumping else 0.032, 0.079)
        else:
            a = _log_uniform(rng, 0.01, 0.05)
        weakening = rng.uniform() < 0.5
        b = a * float(rng.uniform(1.05, 1.6) if weakening else rng.uniform(0.3, 0.95))
        law = str(rng.choice(["aging", "slip"]))
        alpha_ld = float(rng.uniform(0.1, 0.3)) \
            if not jumping and rng.uniform() < 0.5 else 0.0
        p = dict(alpha=alpha, beta=beta, amplitude=amplitude, V=V, a=a, b=b,
                 d_c=_log_uniform(rng, 0.01, 0.1), v_ref=_log_uniform(rng, 0.32, 2.0),
                 alpha_ld=alpha_ld, law=law, zeta=zeta, eta_c=eta_c)
        vf.Dimensionless(alpha=alpha, beta=beta, amplitude=amplitude, zeta=zeta, eta_c=eta_c,
                         rs_a=a, rs_b=b, rs_d_c=p["d_c"], rs_v_ref=p["v_ref"],
                         rs_alpha_ld=alpha_ld, rs_law=law)
        out.append(p)
    return out


def reference_mu(
    alpha: float,
    beta: float,
    a: float,
    V: float,
    initial: str = "sliding",
    transient_periods: int = TRANSIENT_PERIODS,
    average_periods: int = AVERAGE_PERIODS,
    steps: tuple[float, ...] | None = None,
    zeta: float = 0.0,
    eta_c: float = 0.0,
) -> tuple[float, float]:
    """``(mu, err)``: the fixed-step reference's ``mu_macro/mu0`` (eq. 25) from ``initial``
    and a bound on its own error (module docstring); ``zeta``, ``eta_c``: the dashpots
    (docs/damping.md).

    ``mu`` is the finest run's mean over ``average_periods`` drive periods (an even
    number) after ``transient_periods``; ``steps`` are the steps per fastest period,
    coarsest first and finest last (default ``STEPS``).
    """
    if average_periods % 2:
        raise ValueError(f"average_periods must be even (two halves), got {average_periods}")
    steps = steps or STEPS["rigid" if math.isinf(beta) else "finite"]
    if len(steps) < 2:
        raise ValueError(f"steps must name at least two resolutions, got {steps!r}")
    half = average_periods // 2
    # the coarsest run goes on for the later windows, each 2 windows after the last
    stride = 2 * average_periods
    damping = {"zeta": zeta, "eta_c": eta_c} if (zeta or eta_c) else {}
    runs = [return_mapping_periods(alpha, beta, a, V, s, transient_periods,
                                   average_periods + (stride * LATER_WINDOWS if i == 0 else 0),
                                   initial, **damping) for i, s in enumerate(steps)]
    mu = runs[-1].mu_ratio(0, average_periods)
    discretisation = max(abs(mu - r.mu_ratio(0, average_periods)) for r in runs[:-1])
    if math.isinf(beta):
        discretisation *= MOREAU_SAFETY
    halves = max(abs(r.mu_ratio(0, half) - r.mu_ratio(half, average_periods)) for r in runs)
    windows = [runs[0].mu_ratio(k * stride, k * stride + average_periods)
               for k in range(LATER_WINDOWS + 1)]
    averaging = AVERAGING_SAFETY * halves + ROUND_OFF
    err = discretisation + averaging + _transient_bound(windows, averaging)
    return mu, err


def _transient_bound(windows: list[float], noise: float) -> float:
    """How far the first window's mean can be from the limit, from the later windows.

    ``d1, d2`` are the changes between successive windows. Both within ``noise``:
    settled. Otherwise, for a geometric approach with ratio ``q = |d2 / d1|`` between
    windows, the first window is ``|d1| + |d2| / (1 - q)`` from the limit; a ratio above
    ``SLOWEST_DECAY`` means a transient too slow for these windows to bound: ``inf``.
    """
    d1, d2 = windows[1] - windows[0], windows[2] - windows[1]
    if abs(d2) <= noise:
        return abs(d1) + abs(d2)
    q = abs(d2) / abs(d1) if d1 != 0.0 else math.inf
    if q > SLOWEST_DECAY:
        return math.inf
    return abs(d1) + abs(d2) / (1.0 - q)
