"""Seeded random points per regime and the reference value with its own error bar.

The harness of the differential tests (``tests/test_differential.py``): the exact
solver against the independent fixed-step integrator of :mod:`vibrofriction_reference`
(peer B), which shares no code with it. Every point is checked by
``vibrofriction.Dimensionless`` (the package's parameter validation; the reference
validates nothing physical).

``reference_mu`` returns ``(mu, err)`` where ``err`` bounds the reference's own error:

* discretisation: ``|mu(fine) - mu(coarse)|`` with steps in the ratio 4. For an error
  ``C dt^p`` the fine run's error is ``|mu(fine) - mu(coarse)| / (4^p - 1)``; taking the
  whole difference is a safety factor ``4^p - 1`` = 15 at the order ``p ~ 2`` measured
  in ``tests/test_reference.py`` (fitted slopes 1.7-2.3), 8 at its asserted floor
  1.6, and still 3 for first order (Moreau's scheme at very fine steps). The factor
  is that large because the order is irregular: switches fall anywhere between two
  steps, so the error of one resolution is not a smooth function of ``dt``;
* averaging and transient: the ratio ``<f>/<n>`` over each half of the averaging window
  (largest difference over both resolutions), times 2. The window is 120 drive
  periods, so a periodic orbit of period 1-6 drive periods is averaged exactly in
  either half; a difference of the halves is then a transient or a motion that is not
  periodic. For a transient decaying by a factor ``q = rho^(W/2)`` over half the window
  ``W``, the full mean is off by ``(1 + q) / (2 (1 - q))`` times the halves'
  difference, which is at most 2 while ``q <= 0.6`` (a decay time below ~120
  periods). A slower creep (near ``beta = 1`` with a small ``alpha``,
  ``docs/modulation.md``) is not bounded by this estimate.
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

# Steps per period of the fastest oscillation (coarse, fine): Verlet for a finite
# contact (second order); Moreau for a rigid one (drifts to first order), with more.
STEPS = {"finite": (400, 1600), "rigid": (1600, 6400)}
TRANSIENT_PERIODS = 300
AVERAGE_PERIODS = 120
AVERAGING_SAFETY = 2.0
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


def reference_mu(
    alpha: float,
    beta: float,
    a: float,
    V: float,
    initial: str = "sliding",
    transient_periods: int = TRANSIENT_PERIODS,
    average_periods: int = AVERAGE_PERIODS,
    steps: tuple[float, float] | None = None,
) -> tuple[float, float]:
    """``(mu, err)``: the fixed-step reference's ``mu_macro/mu0`` (eq. 25) and a bound
    on its own error (module docstring) after ``transient_periods`` from ``initial``.

    ``mu`` is the fine run's mean over ``average_periods`` drive periods (an even
    number); ``steps`` are the (coarse, fine) steps per fastest period
    (default ``STEPS``).
    """
    if average_periods % 2:
        raise ValueError(f"average_periods must be even (two halves), got {average_periods}")
    steps = steps or STEPS["rigid" if math.isinf(beta) else "finite"]
    half = average_periods // 2
    runs = [return_mapping_periods(alpha, beta, a, V, s, transient_periods, average_periods,
                                   initial) for s in steps]
    mu_coarse, mu = runs[0].mu_ratio(), runs[1].mu_ratio()
    halves = max(abs(r.mu_ratio(0, half) - r.mu_ratio(half)) for r in runs)
    err = abs(mu - mu_coarse) + AVERAGING_SAFETY * halves + ROUND_OFF
    return mu, err
