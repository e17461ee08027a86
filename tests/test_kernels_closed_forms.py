"""The closed forms of the kernels satisfy their ODEs; the basis is exact near resonance."""

import math

import numpy as np
import pytest

from vibrofriction._kernels import basis, phases
from vibrofriction._kernels.roots import first_root, start_margin

TS = np.linspace(0.0, 2 * math.pi, 13)


def _fd(c, w, t, h=1e-4):
    """Second-order central differences of the first two derivatives."""
    f = [basis.evaluate(c, w, t + k * h) for k in (-2, -1, 0, 1, 2)]
    d1 = (f[3] - f[1]) / (2 * h)
    d2 = (f[3] - 2 * f[2] + f[1]) / h**2
    return d1, d2


@pytest.mark.parametrize("w", [0.01, 0.3, 1.0 - 1e-9, 1.0, 1.0 + 1e-7, 1.7, 31.6])
def test_cs_kernels_are_driven_responses_from_rest(w):
    """C'' + w^2 C = cos t, S'' + w^2 S = sin t, C(0) = S(0) = C'(0) = S'(0) = 0."""
    for t in TS[1:]:
        for col, drive in ((6, math.cos(t)), (7, math.sin(t))):
            c = [0.0] * 8
            c[col] = 1.0
            c = tuple(c)
            d2 = basis.evaluate(basis.derivative(basis.derivative(c, w), w), w, t)
            assert d2 + w * w * basis.evaluate(c, w, t) == pytest.approx(drive, abs=1e-12)
    c0, s0 = basis.cs_kernels(0.0, w)
    assert c0 == 0.0 and s0 == 0.0


def test_cs_kernels_tend_to_the_secular_terms_at_resonance():
    for t in TS:
        c, s = basis.cs_kernels(t, 1.0)
        assert c == pytest.approx(t * math.sin(t) / 2, abs=1e-15)
        assert s == pytest.approx((math.sin(t) - t * math.cos(t)) / 2, abs=1e-15)
        c9, s9 = basis.cs_kernels(t, 1.0 + 1e-9)
        assert c9 == pytest.approx(c, abs=1e-8) and s9 == pytest.approx(s, abs=1e-8)


@pytest.mark.parametrize("w", [0.2, 1.0, 3.0])
def test_derivative_map_matches_finite_differences(w, rng):
    for _ in range(5):
        c = tuple(rng.normal(size=8))
        for t in (0.3, 2.0, 5.5):
            d1, d2 = _fd(c, w, t)
            c1 = basis.derivative(c, w)
            assert basis.evaluate(c1, w, t) == pytest.approx(d1, rel=1e-6, abs=1e-6)
            assert basis.evaluate(basis.derivative(c1, w), w, t) == pytest.approx(
                d2, rel=1e-4, abs=1e-4)


def test_integral_matches_quadrature(rng):
    from scipy.integrate import quad

    for w in (0.3, 1.0, 2.5):
        c = tuple(rng.normal(size=7)) + (0.0,)
        val = basis.integral(c, w, 4.0)
        ref = quad(lambda t, c=c, w=w: basis.evaluate(c, w, t), 0.0, 4.0, epsabs=1e-13)[0]
        assert val == pytest.approx(ref, abs=1e-11)


@pytest.mark.parametrize("alpha", [1e-4, 0.3, 1.0 - 1e-9, 1.0, 4.0, 1e3])
def test_slip_solution_satisfies_its_ode(alpha):
    """y'' + alpha y = -s (1 + a cos tau) with the stated initial values."""
    w = math.sqrt(alpha)
    a, theta, y0, yd0 = 0.7, 0.9, 0.4, -0.3
    for s in (1.0, -1.0, 0.0):
        c = phases.free_y(alpha, w, theta, y0, yd0, s, a)
        assert basis.evaluate(c, w, 0.0) == pytest.approx(y0, abs=1e-12)
        assert basis.evaluate(basis.derivative(c, w), w, 0.0) == pytest.approx(yd0, abs=1e-12)
        for t in TS:
            ydd = basis.evaluate(basis.derivative(basis.derivative(c, w), w), w, t)
            rhs = -s * (1 + a * math.cos(theta + t)) if s else 0.0
            scale = 1 + abs(basis.evaluate(c, w, t)) * alpha
            assert ydd + alpha * basis.evaluate(c, w, t) == pytest.approx(rhs, abs=1e-10 * scale)


@pytest.mark.parametrize("beta", [0.02, 1.0, 2.0, 400.01, 1e6])
def test_stick_solution_satisfies_its_ode(beta):
    """x'' = alpha (V tau - x) - f with f = k (x - x_c), x_c fixed."""
    alpha, V, y0, xd0, f0 = 0.01, 0.7, -80.0, 0.2, 0.6
    k = beta - alpha
    W = math.sqrt(beta)
    c = phases.stick_force(alpha, beta, k, W, V, y0, xd0, f0)
    xc = y0 - f0 / k  # contact point (x = y at tau = 0)
    assert basis.evaluate(c, W, 0.0) == pytest.approx(f0)
    for t in TS[1:4]:
        f = basis.evaluate(c, W, t)
        x = xc + f / k
        xdd = basis.evaluate(basis.derivative(basis.derivative(c, W), W), W, t) / k
        assert xdd == pytest.approx(alpha * (V * t - x) - f, abs=1e-9 * (1 + abs(f)))


def test_first_root_finds_the_earliest_of_close_roots():
    """g = cos(w t) - 0.999 has pairs of roots 0.09 apart: the first is returned."""
    w = 10.0
    c = (-0.999, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0)
    t = first_root(c, w, 0.0, 2 * math.pi)
    assert t == pytest.approx(math.acos(0.999) / w, rel=1e-12)
    # a narrow dip that only just reaches zero: the shallow pair near t = pi/w
    c2 = (0.99999, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0)  # g = 0.99999 - cos(w t) > 0 nearly
    t2 = first_root(c2, w, 1e-3, 2 * math.pi)
    assert t2 == pytest.approx((2 * math.pi - math.acos(0.99999)) / w, rel=1e-12)


def test_first_root_misses_nothing_against_dense_sampling(rng):
    for _ in range(200):
        w = float(rng.choice([0.1, 0.7, 1.0, 3.0, 30.0]))
        c = tuple(rng.normal(size=6)) + (0.0, 0.0)
        c = (abs(c[0]) + 2.0,) + c[1:]
        T = 2 * math.pi
        ts = np.linspace(0, T, 200001)
        g = np.array([basis.evaluate(c, w, t) for t in ts[::50]])
        if g[0] <= 0.0:
            continue
        ok, t0 = start_margin(c, w, T)
        assert ok
        r = first_root(c, w, t0, T)
        neg = np.flatnonzero(g <= 0.0)
        if neg.size == 0:
            assert r == -1.0 or basis.evaluate(c, w, r) == pytest.approx(0.0, abs=1e-9)
        else:
            assert 0 <= r <= ts[::50][neg[0]] + 1e-12
            assert basis.evaluate(c, w, r) == pytest.approx(0.0, abs=1e-10)


def test_start_margin_decides_a_double_root_by_curvature():
    # g = 1 - cos t: zero with zero slope at t = 0, positive curvature -> valid
    ok, t_safe = start_margin((1.0, 0.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0), 1.0, 1.0)
    assert ok and t_safe > 0
    # g = cos t - 1: invalid
    ok, _ = start_margin((-1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0), 1.0, 1.0)
    assert not ok
