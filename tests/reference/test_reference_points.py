"""Tests of the differential-test harness (``tests/reference_points.py``) and of the
reference's per-period output it is built on."""

from __future__ import annotations

import math

import numpy as np
import pytest

import vibrofriction as vf
from reference_points import (
    REGIMES,
    random_points,
    rate_state_points,
    reference_mu,
    v_star,
)
from vibrofriction_reference import (
    return_mapping_mu,
    return_mapping_periods,
    solve_ivp_mu,
    solve_ivp_run,
)

# (alpha, beta, a, vbar) stated with 3 decimals and the mu stated with them (eq. 25)
KNOWN_JUMPING = [((10.467, 49.110, 1.302, 1.460), 0.98021),
                 ((15.730, 56.390, 2.761, 1.314), 0.99572)]


# --- random points ------------------------------------------------------------------


def test_random_points_are_seeded_and_differ_between_seeds_and_regimes():
    assert random_points(3, 5, "general") == random_points(3, 5, "general")
    assert random_points(3, 5, "general") != random_points(4, 5, "general")
    assert random_points(3, 5, "general") != random_points(3, 5, "stiff")
    assert len(random_points(0, 7, "rigid")) == 7


def test_unknown_regime_is_refused():
    with pytest.raises(ValueError, match="regime must be one of"):
        random_points(0, 1, "chaotic")


def test_v_star_is_eq_12_as_the_package_states_it():
    for alpha, beta, a in [(0.5, 2.0, 0.5), (3.0, 7.0, 1.5), (0.2, math.inf, 0.8)]:
        expected = float(vf.Dimensionless(alpha, beta, a).vbar_to_inertial(1.0))
        assert v_star(alpha, beta, a) == pytest.approx(expected, rel=1e-14)


@pytest.mark.parametrize("regime", REGIMES)
def test_random_points_lie_in_their_regime(regime):
    for alpha, beta, a, V in random_points(11, 40, regime):
        vf.Dimensionless(alpha, beta, a)  # valid
        assert V > 0.0 and 0.1 <= a <= 3.0
        if regime == "soft":
            assert alpha < 0.1 and beta > 10.0
        elif regime == "stiff":
            assert beta - alpha <= 0.1 * abs(alpha - 1.0)
        elif regime == "general":
            assert 0.05 <= alpha <= 5.0 and 1.1 * alpha <= beta <= 20.0 * alpha
            assert abs(alpha - 1.0) >= 0.05 and abs(beta - 1.0) >= 0.05
        elif regime == "alpha_gt_1":
            assert 1.2 <= alpha <= 40.0
        elif regime == "jumping_above_vstar":
            assert a > 1.0 and 1.05 <= V / v_star(alpha, beta, a) <= 2.0
            assert 1.05 * alpha <= beta <= 5.0 * alpha
        elif regime == "rigid":
            assert math.isinf(beta) and abs(alpha - 1.0) >= 0.05
        elif regime == "resonant_IV":
            assert alpha == 1.0 and math.isinf(beta) and 0.2 <= V <= 5.0
        elif regime == "contact_resonance_III":
            assert 0.02 <= abs(beta - 1.0) <= 0.2 and alpha < beta


def test_jumping_regime_covers_alpha_above_one():
    alphas = [p[0] for p in random_points(0, 60, "jumping_above_vstar")]
    assert min(alphas) < 0.5 and max(alphas) > 5.0


def test_rate_state_points_are_seeded_and_cover_every_regime():
    points = rate_state_points(96, [11, 91])
    assert points == rate_state_points(96, [11, 91])
    assert points != rate_state_points(96, [12, 91])
    for i, p in enumerate(points):
        rigid, jumping = math.isinf(p["beta"]), p["amplitude"] > 1.0
        assert rigid == (i % 4 == 3) and (p["eta_c"] > 0.0) == (i % 4 == 1)
        assert jumping == (i % 3 == 0)
        assert 1.05 <= p["amplitude"] <= 1.5 if jumping else 0.1 <= p["amplitude"] <= 0.95
        assert 0.2 <= p["alpha"] <= 3.2 and 0.1 <= p["V"] <= 2.0
        assert rigid or 1.0 <= p["beta"] - p["alpha"] <= 10.0
        # the rigid contact only where the reference is well behaved (rate_state_run)
        if rigid:
            assert (0.05 if jumping else 0.032) <= p["a"] <= 0.079
        else:
            assert 0.01 <= p["a"] <= 0.05
        assert 0.3 <= p["b"] / p["a"] <= 1.6 and not 0.95 < p["b"] / p["a"] < 1.05
        assert p["eta_c"] == 0.0 or 0.02 <= p["eta_c"] <= 0.4
        assert p["zeta"] == 0.0 or 0.02 <= p["zeta"] <= 0.3
        assert p["alpha_ld"] == 0.0 or (not jumping and 0.1 <= p["alpha_ld"] <= 0.3)
        assert 0.01 <= p["d_c"] <= 0.1 and 0.32 <= p["v_ref"] <= 2.0
    # weakening and strengthening, both laws, the coupling and the pin dashpot on and off
    assert {p["b"] > p["a"] for p in points} == {True, False}
    assert {p["law"] for p in points} == {"aging", "slip"}
    assert {p["alpha_ld"] > 0.0 for p in points} == {True, False}
    assert {p["zeta"] > 0.0 for p in points} == {True, False}
    # ... and each of them at rigid, damped and jumping points too
    for kind in (lambda p: math.isinf(p["beta"]), lambda p: p["eta_c"] > 0.0,
                 lambda p: p["amplitude"] > 1.0):
        some = [p for p in points if kind(p)]
        assert {p["b"] > p["a"] for p in some} == {True, False}
        assert {p["law"] for p in some} == {"aging", "slip"}
        assert {p["zeta"] > 0.0 for p in some} == {True, False}


# --- the reference's per-period means ------------------------------------------------


@pytest.mark.parametrize("params", [(0.5, 2.0, 0.5, 1 / 3), (0.5, 2.0, 1.5, 1.0),
                                    (1.0, math.inf, 0.5, 3.0)])
def test_period_means_add_up_to_the_window_mean(params):
    pm = return_mapping_periods(*params, 400, 30, 12)
    assert pm.f.shape == pm.n.shape == (12,)
    assert pm.mu_ratio() == pytest.approx(return_mapping_mu(*params, 400, 30, 12), abs=1e-13)
    # the first 4 averaged periods are the last 4 of a run with 4 more transient periods
    assert pm.mu_ratio(4, 8) == pytest.approx(return_mapping_mu(*params, 400, 34, 4),
                                              abs=1e-13)
    # <n> over one drive period is 1 (no jumping) or the mean of max(0, 1 + a cos)
    a = params[2]
    if a <= 1.0:
        np.testing.assert_allclose(pm.n, 1.0, atol=1e-12)


@pytest.mark.parametrize(
    ("kwargs", "name"),
    [({"steps_per_period": 0}, "steps_per_period"),
     ({"steps_per_period": math.inf}, "steps_per_period"),
     ({"transient_periods": -1}, "transient_periods"),
     ({"average_periods": 0}, "average_periods"),
     ({"average_periods": 2.5}, "average_periods")],
)
def test_fixed_step_refuses_what_it_cannot_run_naming_the_parameter(kwargs, name):
    with pytest.raises(ValueError, match=name):
        return_mapping_mu(0.5, 2.0, 0.5, 0.3, **kwargs)
    with pytest.raises(ValueError, match=name):
        return_mapping_periods(0.5, 2.0, 0.5, 0.3, **kwargs)


def test_event_peer_refuses_what_it_cannot_run_naming_the_parameter():
    with pytest.raises(ValueError, match="steps_per_fastest_period"):
        solve_ivp_run(0.5, 2.0, 0.5, 0.3, 2, 2, steps_per_fastest_period=0.0)
    with pytest.raises(ValueError, match="average_periods"):
        solve_ivp_mu(0.5, 2.0, 0.5, 0.3, 2, 0)
    with pytest.raises(ValueError, match=r"beta must be in \(alpha, inf\]"):
        solve_ivp_mu(0.5, 0.5, 0.5, 0.3)


# --- reference_mu's error bar ---------------------------------------------------------


def test_reference_mu_refuses_an_odd_window():
    with pytest.raises(ValueError, match="average_periods must be even"):
        reference_mu(0.5, 2.0, 0.5, 0.3, average_periods=41)


@pytest.mark.parametrize(
    "point",
    [random_points(5, 1, regime)[0] for regime in ("general", "stiff", "jumping_above_vstar")]
    + [(0.10315961089162809, 0.618467828993157, 2.3298697444586516, 2.2260654970135954)],
    ids=["general", "stiff", "jumping", "plateau-of-400-and-3200"],
)
@pytest.mark.slow
def test_reference_error_bar_covers_a_finer_later_run(point):
    # a run with 4 times finer steps, after a 5 times longer transient: its own error is
    # far below the bar, so |mu - finer| must be within err
    mu, err = reference_mu(*point)
    finer = return_mapping_mu(*point, 12800, 600, 240)
    print(f"mu {mu:.10f} err {err:.2e} finer {finer:.10f} |diff| {abs(mu - finer):.2e}")
    assert abs(mu - finer) <= err


@pytest.mark.slow
@pytest.mark.parametrize(("point", "stated"), KNOWN_JUMPING, ids=["alpha10.5", "alpha15.7"])
def test_reference_at_the_known_jumping_points(point, stated):
    alpha, beta, a, vbar = point
    V = vbar * v_star(alpha, beta, a)
    mu, err = reference_mu(alpha, beta, a, V)
    # converged at every resolution and window of the bar, and far from the mu = 1 that
    # the solver once claimed there: the differential test can see that claim
    assert err < 1e-6
    assert 1.0 - mu > 1000 * err
    # the stated values go with parameters rounded to 3 decimals; measured sensitivity
    # |dmu/da| = 0.15, |dmu/dvbar| = 0.09 at the first point, so +-5e-4 moves mu by 1.2e-4
    assert mu == pytest.approx(stated, abs=1.2e-4)
    # the event-driven peer (no step size) over the same window agrees within the bar
    assert solve_ivp_mu(alpha, beta, a, V, 120, 240) == pytest.approx(mu, abs=err)
