"""The 2-D solver's Newton bookkeeping: what it keeps of its last iterate is that iterate's.

Newton's full steps carry the tangent until a Jacobian is near the orbit, so the Jacobian it
returns is the tangent's at the iterate a step accepted, and the rough orbit's record (its
state, the end of its period map, that map's means and the Jacobian) is reused by the
error's solve at ``100 rtol`` instead of integrating that map again.  Each kept item is
checked here against the same quantity integrated afresh at the returned state: equal to
the last bit, since the integration is deterministic.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from plane_regimes import REGIMES
from vibrofriction._kernels import plane

COULOMB = [r for r in REGIMES if r[-1] == 1.0]  # the record is kept at s = 1 only


def _transient_end(regime, periods=plane.TRANSIENT_EARLY):
    """``(P, s, W, cnt, hmax)``: the point's state after the solver's early transient (or
    ``periods`` of it)."""
    al, be, a, V, ze, et, ax, ay, sub, sr = regime
    P = plane.parameters(al, be, a, V, ze, et, ax, 0.0, ay, 1.0, al, ze, sub, sr)
    s = np.empty(plane.N_S)
    plane.start_state(P, 0, 0.0, 0.0, 0.0, s)
    W = np.zeros((plane.N_W, plane.N_Z))
    W[plane.W_MODE, 0] = plane.SLIP
    cnt = np.zeros(plane.N_C, np.int64)
    hmax = plane.max_step(P)
    plane._transient(P, s, 1e-10, hmax, W, cnt, 1000, periods)
    return P, s, W, cnt, hmax


def _fresh(P, s, hmax, rtol):
    """The period map from ``s`` integrated afresh: its end, means and tangent Jacobian."""
    W = np.zeros((plane.N_W, plane.N_Z))
    cnt = np.zeros(plane.N_C, np.int64)
    means = np.zeros(7)
    plane.orbit_mean(P, s, rtol, rtol, hmax, W, cnt, 1000, means)
    end = W[13, :plane.N_S].copy()
    J = np.empty((plane.N_S, plane.N_S))
    ok, exact = plane.period_map_tangent(P, s, np.empty(plane.N_S), rtol, rtol, hmax, W,
                                         np.zeros(4), cnt, 1000, J)
    assert ok and exact
    return end, means, J


@pytest.mark.parametrize("regime", COULOMB)
def test_the_rough_orbits_record_is_its_own_map(regime):
    P, s, W, cnt, hmax = _transient_end(regime)
    scale = 1.0 + plane._dist(s, np.zeros(plane.N_S), P[plane.P_K])
    J = np.zeros((plane.N_S, plane.N_S))
    info = np.zeros(4)
    R = np.zeros(plane.N_R)
    found = plane._rough_orbit(P, s, 1e-10, hmax, W, cnt, 1000, scale, J, info, R, False, 12,
                               False, s, np.zeros(7), 0)
    assert found == plane.ROUGH_FOUND
    assert R[plane.R_OK] == 1.0  # Newton's last step carried the tangent
    assert np.array_equal(R[plane.R_S:plane.R_S + plane.N_S], s)
    end, means, Jf = _fresh(P, s, hmax, plane.ROUGH_RTOL)
    assert np.array_equal(R[plane.R_PH:plane.R_PH + plane.N_S], end)
    assert np.array_equal(R[plane.R_MEANS:plane.R_MEANS + 7], means)
    assert np.array_equal(R[plane.R_J:].reshape(plane.N_S, plane.N_S), Jf)
    assert np.array_equal(J, Jf)
    # and it is the orbit at that tolerance: the section residual within Newton's tolerance
    assert plane._dist(end, s, P[plane.P_K]) <= 100 * plane.ROUGH_RTOL * scale


@pytest.mark.parametrize("regime", REGIMES[:4])
def test_newton_returns_the_tangent_of_the_iterate_it_was_taken_at(regime):
    """From the transient's end, Newton at the solve's tolerance: the Jacobian it returns was
    taken at the residual ``info[3]``; where that is the final residual it is the tangent at
    the returned state, else at an earlier iterate (a chord step followed)."""
    P, s, W, cnt, hmax = _transient_end(regime)
    scale = 1.0 + plane._dist(s, np.zeros(plane.N_S), P[plane.P_K])
    J = np.zeros((plane.N_S, plane.N_S))
    info = np.zeros(4)
    ok = plane.newton(P, s, np.empty(plane.N_S), False, 1e-10, 1e-10, hmax, W, cnt, 1000,
                      1e-12 * scale, 1e-8 * scale, 12, J, info, False, plane.DIFF_STEP, 0.0,
                      np.zeros(7), plane._near(scale))
    assert ok and math.isfinite(info[3])
    _, _, Jf = _fresh(P, s, hmax, 1e-10)
    if info[3] == info[1]:
        assert np.array_equal(J, Jf)
    else:  # taken near the orbit (the chord rule), so near the tangent at it
        assert info[3] <= plane._near(scale)
        assert np.max(np.abs(J - Jf)) <= 1e-3 * (1.0 + np.max(np.abs(Jf)))


@pytest.mark.parametrize("regime", COULOMB)
def test_newton_steps_first_on_a_given_maps_tangent(regime):
    """Given a period map and its tangent at ``s`` (the transient's last period, at its own
    tolerance), Newton does not integrate that map again: its first step is
    ``s - (J - I)^-1 (Phi(s) - s)`` on that tangent, and where that step is taken whole its
    one trial map is the only period counted."""
    P, s, W, cnt, hmax = _transient_end(regime)
    rt = plane.TRANSIENT_RTOL
    ph, J = np.empty(plane.N_S), np.empty((plane.N_S, plane.N_S))
    ok, exact = plane.period_map_tangent(P, s, ph, rt, rt, hmax, W, np.zeros(4), cnt, 1000, J)
    assert ok and exact
    W[plane.W_MODE, 1] = W[plane.W_MODE, 0]
    step = np.linalg.solve(J - np.eye(plane.N_S), -(ph - s))
    scale = 1.0 + plane._dist(ph, np.zeros(plane.N_S), P[plane.P_K])
    x, info = s.copy(), np.zeros(4)
    J0 = J.copy()
    plane.newton(P, x, ph.copy(), True, plane.ROUGH_RTOL, plane.ROUGH_RTOL, hmax, W, cnt, 1000,
                 0.0, 0.0, 1, J, info, False, plane.DIFF_STEP, 0.0, np.zeros(7),
                 plane._near(scale), 50)
    if info[2] == 1:  # the whole step was taken: one map, the trial's
        np.testing.assert_allclose(x, s + step, rtol=0, atol=1e-14 * scale)
        assert not np.array_equal(J, J0)  # and J is the tangent carried by that trial
    else:  # halved: the step's direction is the given tangent's all the same
        d = x - s
        np.testing.assert_allclose(d / np.max(np.abs(d)), step / np.max(np.abs(step)),
                                   rtol=0, atol=1e-12)


@pytest.mark.parametrize("regime", COULOMB)
def test_the_early_attempt_finds_the_rough_orbit_the_plain_start_finds(regime):
    """The early attempt (the transient's 8th period with the tangent, then Newton from its
    start on it) and the rough orbit from that period's end with a fresh tangent reach the
    same orbit at :data:`plane.ROUGH_RTOL`, within the tolerance Newton stops at, and the
    attempt's record is its orbit's own map."""
    P, s, W, cnt, hmax = _transient_end(regime)  # 8 periods
    scale = 1.0 + plane._dist(s, np.zeros(plane.N_S), P[plane.P_K])
    J, info, R = np.zeros((plane.N_S, plane.N_S)), np.zeros(4), np.zeros(plane.N_R)
    assert plane._rough_orbit(P, s, 1e-10, hmax, W, cnt, 1000, scale, J, info, R, False, 12,
                              False, s, np.zeros(7), 0) == plane.ROUGH_FOUND
    # the attempt, from the 7th period's end
    _, x, W2, cnt2, _ = _transient_end(regime, plane.TRANSIENT_EARLY - 1)
    J2, R2 = np.zeros((plane.N_S, plane.N_S)), np.zeros(plane.N_R)
    periods, found, stop = plane._attempt(P, x, 1e-10, hmax, W2, cnt2, 1000, J2, np.zeros(4),
                                          R2, 0)
    assert found and stop and R2[plane.R_OK] == 1.0
    mult = max(abs(np.linalg.eigvals(J)))
    tol = 100 * plane.ROUGH_RTOL * scale / (1.0 - min(mult, 0.999))
    assert plane._dist(x, s, P[plane.P_K]) <= 2 * tol
    end, means, Jf = _fresh(P, x, hmax, plane.ROUGH_RTOL)
    assert np.array_equal(R2[plane.R_PH:plane.R_PH + plane.N_S], end)
    assert np.array_equal(R2[plane.R_MEANS:plane.R_MEANS + 7], means)
