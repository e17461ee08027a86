"""Closed forms for a real contact geometry (docs/contact_geometry.md): the mean normal
force and the static value for a power-law profile, the stiff-system law of a flat
contact with jumping and of a curved profile, each against a brute force written here."""

import math

import numpy as np
import pytest

from vibrofriction import theory


def _cycle_mean(values: np.ndarray) -> float:
    return float(np.mean(values))  # uniform periodic grid: the trapezoid rule, spectral


@pytest.mark.parametrize("n", [0.7, 1.0, 2.0, 3.5])
@pytest.mark.parametrize("a", [0.0, 0.3, 1.0, 1.7])
def test_profile_mean_normal_force_is_the_cycle_mean_of_F(n, a):
    tau = np.linspace(0, 2 * np.pi, 200_000, endpoint=False)
    brute = _cycle_mean(np.maximum(0.0, 1.0 + a * np.cos(tau)) ** (1 + 1 / n))
    assert theory.profile_mean_normal_force(a, n) == pytest.approx(brute, rel=1e-9)


def test_profile_mean_normal_force_broadcasts_like_each_point_alone():
    a = np.array([[0.0], [0.3], [1.7]])
    n = np.array([0.7, 2.0, math.inf, 3.5])
    out = theory.profile_mean_normal_force(a, n)
    assert isinstance(out, np.ndarray) and out.shape == (3, 4) and out.dtype == float
    for i in range(3):
        for j in range(4):
            assert out[i, j] == theory.profile_mean_normal_force(float(a[i, 0]), float(n[j]))
    assert isinstance(theory.profile_mean_normal_force(0.3, 2.0), float)


def test_profile_mean_normal_force_limits():
    a = np.array([0.0, 0.4, 1.0, 2.5])
    np.testing.assert_allclose(theory.profile_mean_normal_force(a, math.inf),
                               theory.mean_normal_force(a), rtol=1e-14)
    # a sphere, p = 3/2: <(1 + a cos)^p> = 1 + p (p - 1) a^2 / 4 + O(a^4) = 1 + 3 a^2/16
    assert theory.profile_mean_normal_force(1e-3, 2.0) - 1 == pytest.approx(3e-6 / 16,
                                                                            rel=1e-5)
    with pytest.raises(ValueError, match="profile_exponent must be"):
        theory.profile_mean_normal_force(0.5, 0.0)


def test_profile_static_value():
    a = np.array([0.0, 0.2, 0.7, 1.0, 1.4])
    np.testing.assert_allclose(theory.profile_static_mu_ratio(a, math.inf),
                               theory.static_mu_ratio(a), atol=1e-15)
    tau = np.linspace(0, 2 * np.pi, 100_000, endpoint=False)
    for n in (1.0, 2.0):
        for aa in (0.2, 0.7):
            F = (1 + aa * np.cos(tau)) ** (1 + 1 / n)
            assert theory.profile_static_mu_ratio(aa, n) == pytest.approx(
                F.min() / F.mean(), rel=1e-9)
    assert theory.profile_static_mu_ratio(1.4, 2.0) == 0.0
    # a curved profile's static friction falls below the flat one's: the small forces
    # of the cycle are smaller still (F ~ d^p, p > 1)
    assert theory.profile_static_mu_ratio(0.5, 2.0) < 0.5


def _quasi_static_row(vbar: float, c: np.ndarray, steps: int = 20_000) -> tuple[float, float]:
    """Brute force of the stiff limit for independent flat elements n_i = max(0, c_i + cos):
    f_i grows at the rate vbar while it sticks, is capped at n_i (forward slip), vanishes
    out of contact and restarts from 0; sums of <f_i> and <n_i> over period 3."""
    dt = 2 * math.pi / steps
    f = np.maximum(0.0, c - 1.0)
    sf = sn = 0.0
    for i in range(3 * steps):
        n = np.maximum(0.0, c + math.cos((i + 1) * dt))
        f = np.where(n > 0.0, np.minimum(f + vbar * dt, n), 0.0)
        if i >= 2 * steps:
            sf += f.sum()
            sn += n.sum()
    return sf / steps, sn / steps


@pytest.mark.parametrize("vbar, a", [(0.1, 1.3), (0.4, 1.3), (0.2, 2.5), (0.7, 4.0),
                                     (0.3, 0.8)])
@pytest.mark.slow
def test_flat_stiff_law_with_jumping_against_a_brute_force(vbar, a):
    sf, sn = _quasi_static_row(vbar, np.array([1.0 / a]))
    assert theory.mu_ratio_stiff_flat(vbar, a) == pytest.approx(sf / sn, abs=3e-4)


def test_flat_stiff_law_extends_the_exact_law():
    vb = np.linspace(0.0, 1.2, 61)
    for a in (0.2, 0.6, 1.0):
        np.testing.assert_allclose(theory.mu_ratio_stiff_flat(vb, a),
                                   theory.mu_ratio_stiff_exact(vb, a), atol=1e-13)
    for a in (1.2, 3.0):
        mu = theory.mu_ratio_stiff_flat(vb, a)
        assert mu[0] == 0.0 and mu[-1] == 1.0 and np.all(np.diff(mu) >= -1e-12)


@pytest.mark.parametrize("n", [1.0, 2.0])
@pytest.mark.parametrize("vbar, a", [(0.15, 0.5), (0.5, 0.5), (0.3, 1.5)])
@pytest.mark.slow
def test_profile_stiff_law_against_a_brute_force_row(n, vbar, a):
    m = 400
    xi_max = (1 + a) ** (1 / n)
    xi = (np.arange(m) + 0.5) * xi_max / m
    sf, sn = _quasi_static_row(vbar, (1 - xi**n) / a)
    assert theory.mu_ratio_stiff_profile(vbar, a, n) == pytest.approx(sf / sn, abs=5e-4)


def test_profile_stiff_law_limits():
    for n in (1.0, 2.0, 4.0):
        for a in (0.4, 1.6):
            assert theory.mu_ratio_stiff_profile(0.0, a, n) == pytest.approx(
                theory.profile_static_mu_ratio(a, n), abs=1e-14)
            assert theory.mu_ratio_stiff_profile(1e-7, a, n) == pytest.approx(
                theory.profile_static_mu_ratio(a, n), abs=1e-5)
            assert theory.mu_ratio_stiff_profile(1.0, a, n) == 1.0
    vb = np.array([0.05, 0.3, 0.8])
    np.testing.assert_allclose(theory.mu_ratio_stiff_profile(vb, 0.6, math.inf),
                               theory.mu_ratio_stiff_flat(vb, 0.6), atol=0)
    # n -> inf tends to the flat law like 1/n
    d1 = np.abs(theory.mu_ratio_stiff_profile(vb, 0.6, 1e3) - theory.mu_ratio_stiff_flat(vb, 0.6))
    d2 = np.abs(theory.mu_ratio_stiff_profile(vb, 0.6, 1e4) - theory.mu_ratio_stiff_flat(vb, 0.6))
    assert np.all(d1 < 1e-3) and np.all(d2 < 0.2 * d1)
