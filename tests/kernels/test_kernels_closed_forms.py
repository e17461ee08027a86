"""The closed forms of the kernels satisfy their (damped) ODEs; the basis is exact near
resonance, through critical damping and as the damping vanishes."""

import math

import numpy as np
import pytest

from vibrofriction._kernels import basis, phases, roots
from vibrofriction._kernels.roots import first_root, start_margin

TS = np.linspace(0.0, 2 * math.pi, 13)

# (w0^2, sigma): undamped, light, resonant, near-critical, critical, over-damped, stiff
MODES = [(0.01, 0.0), (0.3, 0.0), (1.0 - 1e-9, 0.0), (1.0, 0.0), (1.0 + 1e-7, 0.0),
         (1.0, 1e-6), (1.0, 0.05), (0.9, 0.2), (3.0, 0.0), (2.0, 1.0), (1.0, 1.0),
         (1.0, 1.0 + 1e-9), (1.0, 1.3), (0.5, 5.0), (1e6, 0.05), (1e6, 5e5)]


def _mode(w0sq, sig, r=0.0):
    return basis.make_mode(w0sq, sig, r)


def _d(c, m, k=1):
    for _ in range(k):
        c = basis.derivative(c, m)
    return c


def _unit(col):
    c = [0.0] * 9
    c[col] = 1.0
    return tuple(c)


@pytest.mark.parametrize("w0sq, sig", MODES)
def test_homogeneous_pair_solves_the_free_equation(w0sq, sig):
    """h'' + 2 sig h' + w0^2 h = 0, h1(0) = 1, h1'(0) = -sig (OSC/NEAR) and the
    initial pair reproduces given initial values in every kind of mode."""
    m = _mode(w0sq, sig)
    for col in (4, 5):
        c = _unit(col)
        for t in TS[1:]:
            h = basis.evaluate(c, m, t)
            res = (basis.evaluate(_d(c, m, 2), m, t) + 2 * sig * basis.evaluate(_d(c, m), m, t)
                   + w0sq * h)
            scale = 1 + w0sq + sig * sig
            assert abs(res) <= 1e-9 * scale * (1 + abs(h))
    D, E = basis.initial_pair(m, 0.7, -0.4)
    c = (0.0, 0.0, 0.0, 0.0, D, E, 0.0, 0.0, 0.0)
    assert basis.evaluate(c, m, 0.0) == pytest.approx(0.7, abs=1e-12)
    assert basis.evaluate(_d(c, m), m, 0.0) == pytest.approx(-0.4, abs=1e-9 * (1 + 2 * sig))


@pytest.mark.parametrize("w0sq, sig", [ms for ms in MODES if ms[0] < 100])
def test_resonant_pair_is_the_driven_response_from_rest(w0sq, sig):
    """C'' + 2 sig C' + w0^2 C = cos t, S'' + ... = sin t, all zero at t = 0."""
    m = _mode(w0sq, sig)
    for t in TS[1:]:
        for col, drive in ((6, math.cos(t)), (7, math.sin(t))):
            c = _unit(col)
            lhs = (basis.evaluate(_d(c, m, 2), m, t) + 2 * sig * basis.evaluate(_d(c, m), m, t)
                   + w0sq * basis.evaluate(c, m, t))
            assert lhs == pytest.approx(drive, abs=1e-11)
    for col in (6, 7):
        assert basis.evaluate(_unit(col), m, 0.0) == 0.0
        assert basis.evaluate(_d(_unit(col), m), m, 0.0) == pytest.approx(0.0, abs=1e-15)


def test_resonant_pair_is_continuous_as_damping_vanishes_and_at_resonance():
    """C -> t sin t / 2 at w0 = 1, sig = 0; sig = 1e-12 and w0^2 = 1 + 1e-9 stay close."""
    m0 = _mode(1.0, 0.0)
    for t in TS:
        c = basis.evaluate(_unit(6), m0, t)
        s = basis.evaluate(_unit(7), m0, t)
        assert c == pytest.approx(t * math.sin(t) / 2, abs=1e-15)
        assert s == pytest.approx((math.sin(t) - t * math.cos(t)) / 2, abs=1e-15)
        for m in (_mode(1.0, 1e-12), _mode(1.0 + 1e-9, 0.0), _mode(1.0 + 1e-9, 1e-12)):
            assert basis.evaluate(_unit(6), m, t) == pytest.approx(c, abs=1e-8)
            assert basis.evaluate(_unit(7), m, t) == pytest.approx(s, abs=1e-8)
    # far from resonance too: sig -> 0 is continuous (direct formula)
    for t in TS:
        for col in (6, 7):
            a0 = basis.evaluate(_unit(col), _mode(0.3, 0.0), t)
            assert basis.evaluate(_unit(col), _mode(0.3, 1e-12), t) == pytest.approx(a0,
                                                                                    abs=1e-10)


def test_over_damped_modes_are_continuous_through_critical_damping():
    """The NEAR (cosh/sinh) and EXP forms agree at the switch and with critical damping."""
    w0sq = 1.0
    sep = basis.SEPARATED
    sig_switch = 1.0 / math.sqrt(1 - sep**2)  # q = SEPARATED sig here
    for t in (0.1, 1.0, 3.0):
        vals = []
        for sig in (sig_switch * (1 - 1e-9), sig_switch * (1 + 1e-9)):
            m = _mode(w0sq, sig)
            D, E = basis.initial_pair(m, 1.0, 0.5)
            vals.append(basis.evaluate((0, 0, 0, 0, D, E, 0, 0, 0), m, t))
        assert vals[0] == pytest.approx(vals[1], rel=1e-7)
        crit = []
        for sig in (1.0 - 1e-10, 1.0, 1.0 + 1e-10):
            m = _mode(w0sq, sig)
            D, E = basis.initial_pair(m, 1.0, 0.5)
            crit.append(basis.evaluate((0, 0, 0, 0, D, E, 0, 0, 0), m, t))
        assert crit[0] == pytest.approx(crit[1], rel=1e-8)
        assert crit[2] == pytest.approx(crit[1], rel=1e-8)
        assert crit[1] == pytest.approx((1.0 + 1.5 * t) * math.exp(-t), rel=1e-12)


@pytest.mark.parametrize("w0sq, sig, r", [(0.2, 0.0, 0.0), (1.0, 0.0, 0.0), (3.0, 0.3, 2.0),
                                          (2.0, 3.0, 0.5), (1.0, 1.0, 7.0)])
def test_derivative_map_matches_finite_differences(w0sq, sig, r, rng):
    m = _mode(w0sq, sig, r)
    h = 1e-4
    for _ in range(5):
        c = tuple(rng.normal(size=9))
        for t in (0.3, 2.0, 5.5):
            f = [basis.evaluate(c, m, t + k * h) for k in (-1, 0, 1)]
            d1 = (f[2] - f[0]) / (2 * h)
            d2 = (f[2] - 2 * f[1] + f[0]) / h**2
            assert basis.evaluate(_d(c, m), m, t) == pytest.approx(d1, rel=1e-6, abs=1e-6)
            assert basis.evaluate(_d(c, m, 2), m, t) == pytest.approx(d2, rel=1e-4, abs=1e-4)


@pytest.mark.parametrize("w0sq, sig, r", [(0.3, 0.0, 0.0), (1.0, 0.0, 0.0), (2.5, 0.2, 3.0),
                                          (2.0, 2.0, 0.0), (1.0, 1.0, 0.0), (4.0, 10.0, 1.0)])
def test_integral_matches_quadrature(w0sq, sig, r, rng):
    from scipy.integrate import quad

    m = _mode(w0sq, sig, r)
    c = tuple(rng.normal(size=6)) + (0.0, 0.0, float(rng.normal()) if r else 0.0)
    val = basis.integral(c, m, 4.0)
    ref = quad(lambda t: basis.evaluate(c, m, t), 0.0, 4.0, epsabs=1e-13, limit=200)[0]
    assert val == pytest.approx(ref, abs=1e-11)


@pytest.mark.parametrize("alpha, zeta", [(1e-4, 0.0), (0.3, 0.0), (1.0 - 1e-9, 0.0), (1.0, 0.0),
                                         (1.0, 0.01), (4.0, 0.2), (1e3, 0.0), (0.5, 1.0),
                                         (2.0, 3.0)])
def test_slip_body_satisfies_its_damped_ode(alpha, zeta):
    """y'' + gamma y' + alpha y = -s (1 + a cos tau) with the stated initial values."""
    M = phases.make_model(alpha, alpha + 2.0, 0.7, 0.4, zeta, 0.0, 0.0, 0.0, True)
    m = M[phases.M_SLIP]
    gamma = 2 * zeta * math.sqrt(alpha)
    a, theta, y0, yd0 = 0.7, 0.9, 0.4, -0.3
    for s in (1.0, -1.0, 0.0):
        c = phases.body(M, theta, y0, yd0, s)
        assert basis.evaluate(c, m, 0.0) == pytest.approx(y0, abs=1e-12)
        assert basis.evaluate(_d(c, m), m, 0.0) == pytest.approx(yd0, abs=1e-12)
        for t in TS:
            y = basis.evaluate(c, m, t)
            lhs = basis.evaluate(_d(c, m, 2), m, t) + gamma * basis.evaluate(_d(c, m), m, t)
            rhs = -s * (1 + a * math.cos(theta + t)) if s else 0.0
            assert lhs + alpha * y == pytest.approx(rhs, abs=1e-10 * (1 + abs(y) * alpha))


@pytest.mark.parametrize("eta", [0.0, 1e-3, 0.3, 1.0, 5.0])
def test_slip_elongation_relaxes_towards_the_friction_force(eta):
    """eta e' + e = s n / k (e = s n / k when eta = 0), e(0) = e0 when eta > 0."""
    alpha, beta = 0.3, 4.0
    k = beta - alpha
    M = phases.make_model(alpha, beta, 0.8, 0.5, 0.1, eta, 0.0, 0.0, True)
    m = M[phases.M_SLIP]
    theta, e0 = 1.3, 0.05
    for s in (1.0, -1.0):
        c = phases.elongation(M, theta, e0, math.nan, s)
        if eta > 0:
            assert basis.evaluate(c, m, 0.0) == pytest.approx(e0, abs=1e-14)
            # given the exact rate instead, the same motion (no cancellation in K)
            rate = basis.evaluate(_d(c, m), m, 0.0)
            c2 = phases.elongation(M, theta, e0, rate, s)
            for t in TS:
                assert basis.evaluate(c2, m, t) == pytest.approx(basis.evaluate(c, m, t),
                                                                 abs=1e-13)
        for t in TS[1:]:
            n = 1 + 0.8 * math.cos(theta + t)
            lhs = eta * basis.evaluate(_d(c, m), m, t) + basis.evaluate(c, m, t)
            assert lhs == pytest.approx(s * n / k, abs=1e-13)
    flight = phases.elongation(M, theta, e0, math.nan, 0.0)
    for t in TS:
        expected = e0 * math.exp(-t / eta) if eta > 0 else 0.0
        assert basis.evaluate(flight, m, t) == pytest.approx(expected, abs=1e-15)


@pytest.mark.parametrize("beta, zeta, eta", [(0.02, 0.0, 0.0), (1.0, 0.0, 0.0), (2.0, 0.0, 0.0),
                                             (400.01, 0.0, 0.0), (1e6, 0.0, 0.0),
                                             (2.0, 0.3, 0.2), (400.01, 0.01, 1.0),
                                             (1e6, 1e-3, 0.0), (1e6, 1e-3, 1.0)])
def test_stick_solution_satisfies_its_ode(beta, zeta, eta):
    """x'' = alpha (V tau - x) + gamma (V - x') - f with f = k e + c e', e = x - x_c."""
    alpha, V, y0, xd0 = 0.01, 0.7, -80.0, 0.2
    k = beta - alpha
    e0 = 0.6 / k
    gamma = 2 * zeta * math.sqrt(alpha)
    M = phases.make_model(alpha, beta, 0.5, V, zeta, eta, 0.0, 0.0, True)
    m = M[phases.M_STICK]
    ec = phases.stick_elongation(M, 0.0, y0, xd0, e0)
    fc = phases.stick_force(M, ec)
    assert basis.evaluate(ec, m, 0.0) == pytest.approx(e0, rel=1e-12)
    assert basis.evaluate(_d(ec, m), m, 0.0) == pytest.approx(xd0, rel=1e-9)
    xc = y0 - e0  # contact point (x = y at tau = 0)
    for t in (1e-3, 0.1, 0.5, 2.0):
        e = basis.evaluate(ec, m, t)
        f = basis.evaluate(fc, m, t)
        x = xc + e
        xd = basis.evaluate(_d(ec, m), m, t)
        xdd = basis.evaluate(_d(ec, m, 2), m, t)
        assert f == pytest.approx(k * e + eta * k * xd, rel=1e-12, abs=1e-12)
        rhs = alpha * (V * t - x) + gamma * (V - xd) - f
        assert xdd == pytest.approx(rhs, abs=1e-8 * (1 + abs(f) + abs(xdd)))


def test_first_root_bounds_a_lone_fast_sine_with_its_envelope():
    """Regression (found by the friction-cone property test): g = cos t - sin(w t) with
    w = 17.8, no cos(w t) term.  The fast pair's envelope was dropped when only one of
    its coefficients was nonzero, and the dips below zero at t = 0.083 and 0.44 were
    excluded as if g stayed positive."""
    w = 17.78560558
    m = _mode(w * w, 0.0)
    c = (0.0, -5.62452404e-03, 1.0, 0.0, 0.0, -w, 0.0, 0.0, 0.0)  # -w h2 = -sin(w t)
    t = first_root(c, m, 0.0, math.pi)
    ts = np.linspace(0.0, t, 20001)
    assert np.all([basis.evaluate(c, m, s) > -1e-12 for s in ts])
    assert basis.evaluate(c, m, t) == pytest.approx(0.0, abs=1e-12)
    assert 0.07 < t < 0.09


def test_first_root_finds_the_earliest_of_close_roots():
    """g = cos(w t) - 0.999 has pairs of roots 0.09 apart: the first is returned."""
    w = 10.0
    m = _mode(w * w, 0.0)
    c = (-0.999, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0)
    t = first_root(c, m, 0.0, 2 * math.pi)
    assert t == pytest.approx(math.acos(0.999) / w, rel=1e-12)
    # a narrow dip that only just reaches zero: the shallow pair near t = pi/w
    c2 = (0.99999, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 0.0)
    t2 = first_root(c2, m, 1e-3, 2 * math.pi)
    assert t2 == pytest.approx((2 * math.pi - math.acos(0.99999)) / w, rel=1e-12)


@pytest.mark.parametrize("w0sq, sig, r", [(0.01, 0.0, 0.0), (0.49, 0.0, 0.0), (1.0, 0.0, 0.0),
                                          (9.0, 0.0, 0.0), (900.0, 0.0, 0.0), (1.0, 0.05, 0.0),
                                          (900.0, 0.3, 0.0), (1.0, 2.0, 0.0), (4.0, 50.0, 0.0),
                                          (1.0, 0.1, 30.0), (1e4, 1e3, 0.0)])
@pytest.mark.slow
def test_first_root_misses_nothing_against_dense_sampling(w0sq, sig, r, rng):
    m = _mode(w0sq, sig, r)
    T = 2 * math.pi
    ts = np.linspace(0, T, 40001)
    for _ in range(25):
        c = tuple(rng.normal(size=6)) + (0.0, 0.0, float(rng.normal()) if r else 0.0)
        c = (abs(c[0]) + 1.5,) + c[1:]
        # exact zeros occur (a phase starting at rest): drop each term with chance 1/3
        c = tuple(0.0 if i > 0 and rng.random() < 1 / 3 else x for i, x in enumerate(c))
        g = np.array([basis.evaluate(c, m, t) for t in ts])
        if g[0] <= 0.0:
            continue
        ok, t0 = start_margin(c, m, T)
        assert ok
        root = first_root(c, m, t0, T)
        neg = np.flatnonzero(g <= 0.0)
        if neg.size == 0:
            assert root == -1.0 or basis.evaluate(c, m, root) == pytest.approx(0.0, abs=1e-9)
        else:
            assert 0 <= root <= ts[neg[0]] + 1e-12
            assert basis.evaluate(c, m, root) == pytest.approx(0.0, abs=1e-9)


@pytest.mark.parametrize("w", [1.0, 10.0, 1000.0])
def test_refine_reaches_round_off_in_few_evaluations(w, monkeypatch):
    """Regression (issue 19): once Newton converged onto the positive end ``a`` of the
    bracket (its step lost in rounding), the bracket was halved from its far end down to
    round-off: tens of evaluations.  g = cos(w t) - c0 on [0, pi/w], root acos(c0)/w."""
    evaluations = [0]
    compiled = roots.basis_values

    def counting(*args):
        evaluations[0] += 1
        return compiled(*args)

    monkeypatch.setattr(roots, "basis_values", counting)  # seen by the Python _refine
    m = _mode(w * w, 0.0)
    most = 0
    for c0 in np.linspace(-0.999, 0.999, 201):
        c = (-float(c0), 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0)
        a, b = 0.0, math.pi / w
        evaluations[0] = 0
        t = roots._refine.py_func(c, basis.derivative(c, m), m, a, b, basis.evaluate(c, m, a),
                                  basis.evaluate(c, m, b), w * w)
        assert t == pytest.approx(math.acos(c0) / w, rel=1e-13)
        most = max(most, evaluations[0])
    assert most <= 12


def test_start_margin_decides_a_double_root_by_curvature():
    m = _mode(4.0, 0.0)
    # g = 1 - cos t: zero with zero slope at t = 0, positive curvature -> valid
    ok, t_safe = start_margin((1.0, 0.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0), m, 1.0)
    assert ok and t_safe > 0
    # g = cos t - 1: invalid
    ok, _ = start_margin((-1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0), m, 1.0)
    assert not ok
