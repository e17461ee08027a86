"""The MDR spring-row reference (vibrofriction_reference.mdr): the flat-punch identity with
peer B, the stiff-system law and the static value of a curved profile (vibrofriction.theory),
the mean normal force, |f_i| <= mu0 N_i at every spring, convergence (docs/contact_geometry.md)."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from vibrofriction import theory
from vibrofriction_reference import return_mapping_mu
from vibrofriction_reference.mdr import mdr_mean, mdr_reference

W = dict(transient_periods=100, average_periods=20)


@pytest.mark.parametrize("alpha, beta, a, V, zeta", [
    (0.5, 2.0, 0.6, 0.3, 0.0), (1.3, 4.0, 1.4, 0.8, 0.0), (0.2, 0.9, 0.5, 0.05, 0.0),
    (1.0, 3.0, 0.9, 1.0, 0.1), (2.5, 3.0, 2.0, 0.4, 0.02)])
def test_flat_punch_is_the_single_spring(alpha, beta, a, V, zeta):
    """Every spring of a flat punch carries the same share: the row is peer B's spring."""
    r = mdr_reference(alpha, beta, a, V, math.inf, **W, zeta=zeta)
    single = return_mapping_mu(alpha, beta, a, V, steps_per_period=400, zeta=zeta, **W)
    assert abs(r.mu_ratio - single) <= max(r.mu_error, 1e-9)
    # the trapezoid mean of n over the step grid: 4e-6 off with the kink of a jumping body
    assert r.mean_normal_ratio == pytest.approx(theory.mean_normal_force(a), abs=1e-5)
    assert mdr_mean(alpha, beta, a, V, math.inf, 1, 400, zeta=zeta, **W).mu_ratio == \
        pytest.approx(r.mu_ratio, abs=1e-11)


@pytest.mark.parametrize("n, a", [(2.0, 0.5), (2.0, 1.5), (1.0, 0.5), (1.0, 1.5)])
def test_stiff_system_approaches_the_profile_law(n, a):
    """alpha, beta = alpha0, 2 alpha0 (zeta = 1 damps the slow transient): the distance to
    the law falls with alpha0 and is within the error bar + 1.5e-5 at alpha0 = 1e-5."""
    vbar = 0.3
    law = theory.mu_ratio_stiff_profile(vbar, a, n)
    dist = []
    for alpha in (1e-3, 1e-5):
        V = vbar * (n + 1) * a / (n * alpha)
        r = mdr_reference(alpha, 2 * alpha, a, V, n, transient_periods=1000,
                          average_periods=20, zeta=1.0)
        dist.append(abs(r.mu_ratio - law))
    assert dist[1] <= r.mu_error + 1.5e-5
    assert dist[0] > 10 * dist[1]
    assert r.mean_normal_ratio == pytest.approx(theory.profile_mean_normal_force(a, n),
                                                abs=r.normal_error + 1e-6)


@pytest.mark.parametrize("n, a", [(2.0, 0.5), (1.0, 0.5), (2.0, 1.5), (3.0, 0.8)])
def test_static_limit_is_the_smallest_normal_force_over_the_mean(n, a):
    static = theory.profile_static_mu_ratio(a, n)
    excess = [mdr_reference(0.5, 2.0, a, V, n, **W).mu_ratio - static for V in (1e-2, 1e-3)]
    # mu falls to the static value linearly in V (3.3 V and 0.3 V at a = 0.5 and 1.5)
    assert 0 < excess[1] < 0.15 * excess[0] and excess[1] < 4e-3


@settings(max_examples=12, deadline=None)
@given(alpha=st.floats(0.05, 3.0), k=st.floats(0.1, 5.0), a=st.floats(0.0, 2.5),
       V=st.floats(0.0, 2.0), n=st.sampled_from([0.7, 1.0, 2.0, 4.0, math.inf]),
       zeta=st.sampled_from([0.0, 0.1]))
def test_every_spring_stays_within_its_friction_cone(alpha, k, a, V, n, zeta):
    r = mdr_mean(alpha, alpha + k, a, V, n, springs=40, steps_per_period=100,
                 transient_periods=5, average_periods=1, zeta=zeta, record_last_period=True)
    f, nn = r.spring_f, r.spring_n
    assert np.all(nn >= 0.0) and np.all(np.abs(f) <= nn * (1 + 1e-12))
    assert np.all(f[nn == 0.0] == 0.0)


def test_a_jumping_sphere_has_stick_slip_and_lift_off_rings():
    r = mdr_mean(1.0, 4.0, 1.5, 1.0, 2.0, springs=100, steps_per_period=200,
                 transient_periods=20, average_periods=1, record_last_period=True)
    f, nn = r.spring_f, r.spring_n
    out = nn == 0.0
    slip = ~out & (np.abs(f) >= nn * (1 - 1e-12))
    stick = ~out & ~slip
    assert out.any() and slip.any() and stick.any()
    # the centre leaves the contact for less of the cycle than the edge
    assert out[:, 0].mean() < out[:, -1].mean()


def test_convergence_in_springs_and_time_step():
    """Second order in time at fixed springs, and the spring error falls with their number
    (benchmarks/results/mdr_convergence.md)."""
    p = (0.3, 3.0, 0.5, 0.4, 2.0)
    ref = mdr_mean(*p, 800, 800, **W).mu_ratio
    e_t = [abs(mdr_mean(*p, 800, s, **W).mu_ratio - ref) for s in (100, 200)]
    assert e_t[1] < 0.5 * e_t[0]
    e_m = [abs(mdr_mean(*p, m, 800, **W).mu_ratio - ref) for m in (12, 50, 200)]
    assert e_m[1] < 0.25 * e_m[0] and e_m[2] < 0.25 * e_m[1]


@pytest.mark.parametrize("kwargs, message", [
    (dict(beta=0.4), "beta must be > 0.5"), (dict(beta=math.inf), "beta must be a finite"),
    (dict(amplitude=-0.1), "amplitude must be in"), (dict(profile_exponent=0.0),
                                                     "profile_exponent must be > 0"),
    (dict(springs=0), "springs must be an integer >= 1"), (dict(zeta=-1.0), "zeta must be"),
])
def test_errors_name_the_parameter(kwargs, message):
    args = dict(alpha=0.5, beta=2.0, amplitude=0.5, V=0.1) | kwargs
    with pytest.raises(ValueError, match=message):
        mdr_mean(**args)
