"""Rate-and-state friction's closed forms (theory.rate_state): steady sliding and its stability.

The characteristic polynomial is checked against the eigenvalues of the Jacobian of the
nonlinear equations of motion, differentiated numerically here (no code shared with the
derivation), and the critical stiffness against the classical closed form and the roots.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import settings as hypothesis_settings
from hypothesis import strategies as st

from vibrofriction import theory


def _rhs(z: np.ndarray, alpha: float, k: float, gamma: float, V: float, a: float, b: float,
         d_c: float, v_ref: float, law: str) -> np.ndarray:
    """The equations of motion at n = 1: state (y, x', e, ln theta), written from the law."""
    y, xd, e, lt = z
    theta = math.exp(lt)
    f = k * e
    w = 2 * v_ref * math.sinh(f / a) * math.exp(-(1 + b * math.log(theta * v_ref / d_c)) / a)
    if law == "aging":
        dlt = 1 / theta - abs(w) / d_c
    else:
        r = abs(w) * theta / d_c
        dlt = -(abs(w) / d_c) * math.log(r)
    return np.array([xd - V, -alpha * y - gamma * (xd - V) - f, xd - w, dlt])


def _jacobian_eigenvalues(alpha, beta, zeta, V, a, b, d_c, v_ref, law="aging"):
    k = beta - alpha
    gamma = 2 * zeta * math.sqrt(alpha)
    mu = float(theory.steady_mu_ratio(V, a, b, d_c, v_ref))
    z0 = np.array([-mu / alpha, V, mu / k, math.log(d_c / V)])
    assert np.max(np.abs(_rhs(z0, alpha, k, gamma, V, a, b, d_c, v_ref, law))) < 1e-9 * V
    J = np.empty((4, 4))
    for j in range(4):
        h = 1e-8 * max(1.0, abs(z0[j]))
        dz = np.zeros(4)
        dz[j] = h
        J[:, j] = (_rhs(z0 + dz, alpha, k, gamma, V, a, b, d_c, v_ref, law)
                   - _rhs(z0 - dz, alpha, k, gamma, V, a, b, d_c, v_ref, law)) / (2 * h)
    return np.sort_complex(np.linalg.eigvals(J))


def test_steady_coefficient_is_the_law_at_the_steady_state() -> None:
    """mu_ss(v) = a asinh(v/(2 v_ref) e^((1 + b ln(v_ref/v))/a)) computed directly where it does
    not overflow, the log-linear law 1 + (a - b) ln(v/v_ref) where mu >> a, odd in v, 0 at 0."""
    a, b, v_ref = 0.2, 0.3, 0.7
    for v in (1e-3, 0.1, 0.7, 5.0):
        direct = a * math.asinh(v / (2 * v_ref) * math.exp((1 + b * math.log(v_ref / v)) / a))
        assert theory.steady_mu_ratio(v, a, b, 1.0, v_ref) == pytest.approx(direct, rel=1e-14)
        assert theory.steady_mu_ratio(-v, a, b, 1.0, v_ref) == -theory.steady_mu_ratio(
            v, a, b, 1.0, v_ref)
    a, b = 0.01, 0.015  # asinh z = ln 2z + O(z^-2): exp(-2/a) ~ 1e-87 away
    for v in (1e-4, 1.0, 1e3):
        assert theory.steady_mu_ratio(v, a, b, 1.0, 1.0) == pytest.approx(
            1 + (a - b) * math.log(v), rel=1e-13)
    assert theory.steady_mu_ratio(0.0, a, b, 1.0, 1.0) == 0.0


@pytest.mark.parametrize("law", ["aging", "slip"])
@pytest.mark.parametrize(("alpha", "beta", "zeta", "V", "a", "b", "d_c", "v_ref"), [
    (2.0, 50.0, 0.0, 0.5, 0.01, 0.02, 0.05, 1.0),  # weakening, finite contact
    (0.3, 1.3, 0.05, 2.0, 0.05, 0.02, 0.5, 0.1),  # strengthening, damped
    (5.0, 7.0, 0.2, 0.1, 0.2, 0.4, 0.01, 3.0),  # a soft contact, regularisation felt
])
def test_characteristic_polynomial_is_the_linearised_motion(law, alpha, beta, zeta, V, a, b,
                                                              d_c, v_ref) -> None:
    """The roots of the quartic are the eigenvalues of the Jacobian of the full equations of
    motion at steady sliding, for the aging and the slip law alike (same linearisation)."""
    roots = np.sort_complex(theory.sliding_eigenvalues(alpha, beta, zeta, V, a, b, d_c, v_ref))
    eig = _jacobian_eigenvalues(alpha, beta, zeta, V, a, b, d_c, v_ref, law)
    scale = np.max(np.abs(eig))
    np.testing.assert_allclose(roots, eig, atol=1e-6 * scale)


def test_rigid_undamped_critical_stiffness_is_the_classical_one() -> None:
    """The bisection on the Hurwitz determinant reproduces (b - a)/d_c (1 + V^2/(a d_c)), a
    finite but very stiff contact approaches it, and at alpha_cr a pair of roots crosses the
    imaginary axis."""
    a, b, d_c = 0.01, 0.02, 0.05
    for V in (0.1, 1.0, 3.0):
        closed = float(theory.critical_stiffness_rigid(V, a, b, d_c, 1.0))
        assert closed == pytest.approx((b - a) / d_c * (1 + V * V / (a * d_c)), rel=1e-12)
        assert theory.critical_stiffness(math.inf, 0.0, V, a, b, d_c, 1.0) == pytest.approx(
            closed, rel=1e-10)
        assert theory.critical_stiffness(1e7, 0.0, V, a, b, d_c, 1.0) == pytest.approx(
            closed, rel=1e-5)
        for factor, unstable in ((0.99, True), (1.01, False)):
            s = theory.sliding_eigenvalues(factor * closed, math.inf, 0.0, V, a, b, d_c, 1.0)
            assert (np.max(s.real) > 0) == unstable
        for gamma in (1e-3, 0.5 * (b - a) / V):  # damped: the closed form with gamma
            damped = float(theory.critical_stiffness_rigid(V, a, b, d_c, 1.0, gamma))
            assert 0.0 < damped < closed
            assert theory.critical_stiffness(math.inf, gamma, V, a, b, d_c, 1.0) == \
                pytest.approx(damped, rel=1e-10)
        assert theory.critical_stiffness_rigid(V, a, b, d_c, 1.0, 1.01 * (b - a) / V) == 0.0


def test_critical_stiffness_separates_stable_from_unstable_roots() -> None:
    """Finite contacts, damped and not: just below alpha_cr a root has Re s > 0, just above
    none; a dashpot stronger than the weakening's negative damping (b - a)/V stabilises at
    every stiffness; strengthening is stable everywhere."""
    rng = np.random.default_rng(7)
    checked = 0
    for _ in range(40):
        a = 10 ** rng.uniform(-2.5, -1)
        b = a * rng.uniform(1.2, 3.0)
        d_c, V = 10 ** rng.uniform(-2, 0), 10 ** rng.uniform(-1.5, 0.5)
        k_c = 10 ** rng.uniform(0, 4)
        gamma = rng.choice([0.0, 10 ** rng.uniform(-4, -2)])
        alpha_cr = theory.critical_stiffness(k_c, gamma, V, a, b, d_c, 1.0)
        if not 0.0 < alpha_cr < math.inf:
            continue
        checked += 1
        for factor, unstable in ((0.97, True), (1.03, False)):
            al = factor * alpha_cr
            s = theory.sliding_eigenvalues(al, al + k_c, gamma / (2 * math.sqrt(al)), V, a, b,
                                           d_c, 1.0)
            assert (np.max(s.real) > 0) == unstable, (a, b, d_c, V, k_c, gamma, factor)
    assert checked >= 20
    a, b, V = 0.01, 0.02, 0.1  # negative damping (b - a)/V = 0.1 < gamma = 0.3
    assert theory.critical_stiffness(math.inf, 0.3, V, a, b, 0.05, 1.0) == 0.0
    assert theory.critical_stiffness(10.0, 0.0, 1.0, 0.02, 0.01, 0.05, 1.0) == 0.0


@hypothesis_settings(max_examples=60, deadline=None)
@given(st.floats(0.05, 50), st.floats(0.05, 1e3), st.floats(0, 0.3), st.floats(0.01, 10),
       st.floats(0.002, 0.2), st.floats(0.0, 3.0), st.floats(0.005, 1.0))
def test_hurwitz_verdict_is_the_roots_verdict(alpha, k, zeta, V, a, b_over_a, d_c) -> None:
    """sliding_is_stable agrees with the signs of the roots wherever they are not on the
    boundary."""
    args = (alpha, alpha + k, zeta, V, a, a * b_over_a, d_c, 1.0)
    s = theory.sliding_eigenvalues(*args)
    margin = np.max(s.real) / np.max(np.abs(s))
    if abs(margin) > 1e-8:
        assert theory.sliding_is_stable(*args) == (margin < 0)
