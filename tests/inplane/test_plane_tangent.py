"""The 2-D solver's Jacobian of the period map by the tangent carried along.

:func:`vibrofriction._kernels.plane.period_map_tangent` integrates ``Y' = Df Y`` with the
Runge-Kutta stages of the state (``rhs_jacobian`` in closed form), carries ``Y`` through each
stick-slip switch by its saltation and through lift-off and touch-down by their maps'
derivatives.  Checked here against what shares none of that: central differences of the
right-hand side, and forward/central differences of the period map itself, integrated at a
tolerance fine enough for them to resolve it.
"""

from __future__ import annotations

import numpy as np
import pytest

from plane_regimes import REGIMES
from vibrofriction._kernels import plane
from vibrofriction.schema import Status


def _orbit(p):
    """The parameter vector and the solver's periodic orbit ``(s, phase)`` at ``p``."""
    al, be, a, V, ze, eta, ax, ay, sub, sr = p
    out_f, out_i, s_out = np.zeros(40), np.zeros(20, np.int64), np.zeros(plane.N_S + 1)
    plane.plane_steady_section(al, be, a, V, ze, eta, ax, 0.3, ay, 0.7, al, ze, sub, 0, 0.0,
                               0.0, 0.0, 1e-10, 100_000, 1000, out_f, out_i, s_out, sr)
    assert out_i[0] == Status.PERIODIC.code
    return plane.parameters(al, be, a, V, ze, eta, ax, 0.3, ay, 0.7, al, ze, sub, sr), s_out


def _work(s_out):
    W = np.zeros((plane.N_W, plane.N_Z))
    W[plane.W_MODE, 0] = s_out[plane.N_S]
    return W, np.zeros(plane.N_C, np.int64), np.zeros(4)


def test_the_right_hand_side_jacobian_is_its_derivative():
    """``rhs_jacobian`` of every phase against central differences of ``rhs``, at random
    states, times and parameters (Jenkins and Kelvin-Voigt, substrate and holder)."""
    rng = np.random.default_rng(7)
    f1, f2 = np.empty(plane.N_Z), np.empty(plane.N_Z)
    checked = 0
    for _ in range(300):
        eta = float(rng.choice([0.0, 0.3]))
        P = plane.parameters(10 ** rng.uniform(-1, 0.5), 4.0, rng.uniform(0, 2),
                             rng.uniform(-1, 1), 0.05, eta, 0.4, 1.0, 0.6, 0.3, 0.7, 0.03,
                             bool(rng.integers(2)), 1.0)
        z, t = rng.normal(size=plane.N_Z), rng.uniform(0, 2 * np.pi)
        for mode in (plane.STICK, plane.SLIP, plane.FLIGHT):
            D, Dn = np.empty((6, 6)), np.empty((6, 6))
            plane.rhs_jacobian(mode, P, t, z, D)
            for j in range(6):
                d = 1e-6
                zp, zm = z.copy(), z.copy()
                zp[j] += d
                zm[j] -= d
                plane.rhs(mode, P, t, zp, f1)
                plane.rhs(mode, P, t, zm, f2)
                Dn[:, j] = (f1[:6] - f2[:6]) / (2 * d)
            scale = max(1.0, np.abs(Dn).max())
            assert np.abs(D - Dn).max() <= 1e-7 * scale, (mode, eta, D - Dn)
            checked += 1
    assert checked == 900


@pytest.mark.parametrize("p", REGIMES)
def test_the_tangent_is_the_period_maps_derivative(p):
    """At the orbit, the tangent's Jacobian against central differences of the period map at
    ``rtol = 1e-12`` (steps ``1e-5``: their error about ``1e-9``); the image is the period
    map's, bit for bit, and the multipliers agree."""
    P, s_out = _orbit(p)
    hmax = plane.max_step(P)
    s = s_out[:plane.N_S].copy()
    tol = 1e-12
    W, cnt, acc = _work(s_out)
    J, image = np.zeros((6, 6)), np.empty(6)
    ok, exact = plane.period_map_tangent(P, s, image, tol, tol, hmax, W, acc, cnt, 1000, J)
    assert ok and exact
    W, cnt, acc = _work(s_out)
    plain = np.empty(6)
    plane.period_map(P, s, plain, tol, tol, hmax, W, acc, cnt, 1000)
    np.testing.assert_array_equal(image, plain)
    Jc = np.empty((6, 6))
    for j in range(6):
        h = 1e-5 * (1.0 + abs(s[j]))
        cols = []
        for sign in (1.0, -1.0):
            sp = s.copy()
            sp[j] += sign * h
            W, cnt, acc = _work(s_out)
            out = np.empty(6)
            plane.period_map(P, sp, out, tol, tol, hmax, W, acc, cnt, 1000)
            cols.append(out)
        Jc[:, j] = (cols[0] - cols[1]) / (2 * h)
    # a Jenkins contact in slip at the section sits on its cone: radial differences leave the
    # entry rule's side (the map is not smooth across it), so only the directions along the
    # cone are compared there
    keep = np.arange(6)
    if P[plane.P_C] == 0.0 and int(s_out[plane.N_S]) == plane.SLIP:
        keep = np.arange(4)
    err = np.abs(J[:, keep] - Jc[:, keep]).max()
    assert err <= 1e-6 * max(1.0, np.abs(Jc).max()), err
    lam = np.abs(np.linalg.eigvals(J)).max()
    lam_c = np.abs(np.linalg.eigvals(Jc)).max()
    if keep.size == 6:
        assert abs(lam - lam_c) <= 1e-6


@pytest.mark.parametrize("p", REGIMES[:4])
def test_the_multiplier_at_the_solvers_tolerance_is_the_difference_jacobians(p):
    """At the solver's orbit and its ``rtol = 1e-10``, the multiplier from the tangent's
    Jacobian agrees with the spectral radius of the forward-difference Jacobian the solver
    used before (step ``1e-7``: its own error about ``1e-5``)."""
    P, s_out = _orbit(p)
    hmax = plane.max_step(P)
    W, cnt, acc = _work(s_out)
    ph = np.empty(6)
    s = s_out[:plane.N_S].copy()
    plane.period_map(P, s, ph, 1e-10, 1e-10, hmax, W, acc, cnt, 1000)
    assert plane._dist(ph, s, P[plane.P_K]) <= 1e-8
    Jd = np.zeros((6, 6))
    W, cnt, acc = _work(s_out)
    plane._difference_jacobian(P, s, ph, 1e-10, 1e-10, hmax, W, acc, cnt, 1000, Jd,
                               np.empty(6), np.empty(6), 0, plane.DIFF_STEP)
    J = np.zeros((6, 6))
    W, cnt, acc = _work(s_out)
    plane.period_map_tangent(P, s, np.empty(6), 1e-10, 1e-10, hmax, W, acc, cnt, 1000, J)
    assert abs(np.abs(np.linalg.eigvals(J)).max()
               - np.abs(np.linalg.eigvals(Jd)).max()) <= 1e-4


def test_the_tangent_keeps_the_event_budget():
    """A period with more switches than ``max_events`` fails with the tangent as without it
    (chatter is a failed period, whichever map integrates it)."""
    P, s_out = _orbit(REGIMES[0])
    hmax = plane.max_step(P)
    s = s_out[:plane.N_S]
    W, cnt, acc = _work(s_out)
    ok, _, _ = plane.period_map(P, s, np.empty(6), 1e-10, 1e-10, hmax, W, acc, cnt, 1000)
    assert ok and cnt[plane.C_EVENTS] >= 2  # a stick-slip orbit: two switches at least
    for tangent in (False, True):
        W, cnt, acc = _work(s_out)
        if tangent:
            ok, _ = plane.period_map_tangent(P, s, np.empty(6), 1e-10, 1e-10, hmax, W, acc,
                                             cnt, 1, np.zeros((6, 6)))
        else:
            ok, _, _ = plane.period_map(P, s, np.empty(6), 1e-10, 1e-10, hmax, W, acc, cnt, 1)
        assert not ok and cnt[plane.C_FAIL] > 0, tangent
