"""The damped model (docs/damping.md): parameters, limits, energy balance, critical velocity."""

import json
import math
import subprocess
import sys

import numpy as np
import pytest

import vibrofriction as vf
from vibrofriction import solver, theory

# regimes of the undamped solver: stick-slip, stiff, soft, grazing, jumping, alpha > 1,
# rigid, case IV rigid and elastic, near beta = 1
REGIMES = [(0.5, 2.0, 0.5, 0.3), (0.01, 0.02, 0.5, 0.3), (0.01, 400.01, 1.0, 0.5),
           (0.5, 2.0, 1.0, 0.2), (0.3, 2.0, 1.5, 0.4), (2.0, 10.0, 0.8, 1.0),
           (0.01, math.inf, 0.5, 0.3), (1.0, math.inf, 0.5, 3.0), (1.0, 5.3, 1.5, 2.0),
           (0.2, 0.9, 0.7, 0.2)]


# --------------------------------------------------------------------------- parameters
@pytest.mark.parametrize("field, value", [("zeta", -0.1), ("zeta", math.nan),
                                          ("eta_c", -1e-3), ("eta_c", math.inf)])
def test_bad_damping_is_a_clear_error(field, value):
    with pytest.raises(ValueError, match=field):
        vf.Dimensionless(0.5, 2.0, 0.5, **{field: value})


def test_physical_damping_maps_to_zeta_and_eta_c():
    p = vf.Physical(mass=0.01, k_x=2.5e5, k_xc=2e5, k_zc=2.5e5, u_z0=4e-6, du_z=2e-6,
                    omega=2 * math.pi * 1000, mu0=0.3)
    q = p.with_damping(quality_factor=50.0, eta_c=0.2)
    d = q.to_dimensionless()
    assert d.zeta == pytest.approx(0.01, rel=1e-14)
    assert q.quality_factor == pytest.approx(50.0, rel=1e-14)
    assert q.c_x == pytest.approx(2 * 0.01 * math.sqrt(2.5e5 * 0.01), rel=1e-14)
    assert d.eta_c == pytest.approx(0.2, rel=1e-14)
    assert q.c_xc == pytest.approx(0.2 * 2e5 / p.omega, rel=1e-14)
    assert p.with_damping(zeta=0.01).c_x == pytest.approx(q.c_x, rel=1e-14)
    assert vf.pin_damping(2.5e5, 0.01, quality_factor=math.inf) == 0.0
    with pytest.raises(ValueError, match="exactly one"):
        vf.pin_damping(2.5e5, 0.01, zeta=0.1, quality_factor=5.0)
    with pytest.raises(ValueError, match="c_x"):
        p.with_(c_x=-1.0)
    with pytest.raises(ValueError, match="quality_factor"):
        p.with_damping(quality_factor=0.0)
    # SI critical velocity = inertial one times the velocity unit
    unit = p.mu0 * p.F_N0 / (p.mass * p.omega)
    assert q.critical_velocity() == pytest.approx(d.critical_inertial_velocity() * unit,
                                                  rel=1e-12)


# --------------------------------------------------------------------------- limits
@pytest.mark.parametrize("p", REGIMES)
def test_vanishing_damping_gives_the_undamped_result(p):
    al, be, a, V = p
    r0 = vf.friction_coefficient(vf.Dimensionless(al, be, a), v_inertial=V)
    if not r0.trusted:
        pytest.skip("no trusted undamped reference")
    for zeta, eta in ((1e-10, 0.0), (0.0, 1e-8), (1e-10, 1e-8)):
        r = vf.friction_coefficient(vf.Dimensionless(al, be, a, zeta, eta), v_inertial=V)
        assert r.trusted
        assert abs(r.mu_ratio - r0.mu_ratio) <= r.error + r0.error + 1e-8


@pytest.mark.parametrize("p", REGIMES[:7])
def test_small_damping_changes_mu_smoothly(p):
    """|mu(zeta) - mu(0)| shrinks with zeta (linearly, away from thresholds)."""
    al, be, a, V = p
    mus = [vf.friction_coefficient(vf.Dimensionless(al, be, a, z, 0.0), v_inertial=V)
           for z in (0.0, 1e-6, 1e-5, 1e-4)]
    if not all(r.trusted for r in mus):
        pytest.skip("not every point is trusted")
    d = [abs(r.mu_ratio - mus[0].mu_ratio) for r in mus[1:]]
    assert d[0] <= d[1] + 1e-9 <= d[2] + 2e-9
    assert d[2] < 0.05


# --------------------------------------------------------------------------- energy
@pytest.mark.parametrize("p, zeta, eta", [((0.5, 2.0, 0.5, 0.3), 0.05, 0.2),
                                          ((0.3, 2.0, 1.5, 0.4), 0.1, 0.5),
                                          ((0.01, math.inf, 0.5, 0.3), 0.2, 0.0),
                                          ((1.0, 5.3, 1.5, 2.0), 0.02, 1.0),
                                          ((0.01, 0.02, 0.5, 0.3), 1.5, 0.05),
                                          ((0.01, 1e4, 0.5, 0.05), 0.01, 0.1)])
def test_energy_balance_with_both_dashpots(p, zeta, eta):
    """Work of the pulled end = change of stored energy + pin, contact and friction
    dissipation, at every sample (docs/damping.md)."""
    al, be, a, V = p
    h = vf.simulate(vf.Dimensionless(al, be, a, zeta, eta), v_inertial=V, periods=3.0,
                    samples_per_period=200)
    lhs = h.work_input - h.dissipated_pin - h.dissipated_contact - h.dissipated_friction
    rhs = h.stored_energy() - h.stored_energy()[0]
    scale = np.max(np.abs(h.work_input)) + np.max(np.abs(h.stored_energy())) + 1e-300
    assert np.max(np.abs(lhs - rhs)) <= 1e-7 * scale
    assert h.dissipated_pin[-1] >= 0.0 and h.dissipated_contact[-1] >= 0.0
    assert h.dissipated_friction[-1] >= -1e-12 * scale
    if zeta > 0:
        assert h.dissipated_pin[-1] > 0.0


def test_mean_tangential_force_is_mean_friction_in_a_damped_steady_state():
    """<F_x> = <-alpha y - gamma y'> = <f> over whole periods of the orbit (eq. 25)."""
    s = vf.Dimensionless(0.5, 2.0, 0.8, 0.1, 0.3)
    h = vf.simulate(s, v_inertial=0.3, periods=2.0, samples_per_period=4000,
                    initial="steady")
    gamma = 2 * s.zeta * math.sqrt(s.alpha)
    y = h.x - h.v_inertial * h.tau
    fx = -s.alpha * y - gamma * (h.x_dot - h.v_inertial)
    mean_fx = np.trapezoid(fx, h.tau) / np.trapezoid(h.n, h.tau)
    mean_f = np.trapezoid(h.f, h.tau) / np.trapezoid(h.n, h.tau)
    r = vf.friction_coefficient(s, v_inertial=0.3)
    assert mean_fx == pytest.approx(r.mu_ratio, abs=1e-5)
    assert mean_f == pytest.approx(r.mu_ratio, abs=1e-5)


# --------------------------------------------------------------------------- V_c
def test_damped_critical_velocity_reduces_to_eq12():
    rng = np.random.default_rng(7)
    al = rng.uniform(0.05, 5.0, 50)
    be = al * rng.uniform(1.1, 30.0, 50)
    a = rng.uniform(0.1, 1.0, 50)
    np.testing.assert_allclose(theory.critical_inertial_velocity(al, be, a),
                               a * np.abs(be - 1) / ((be - al) * np.abs(al - 1)), rtol=1e-12)
    # rigid contact, case IV: a / gamma
    assert theory.critical_inertial_velocity(1.0, math.inf, 0.5, 0.02) == pytest.approx(
        0.5 / 0.04, rel=1e-14)
    # case III becomes finite and positive with damping
    assert theory.critical_inertial_velocity(0.2, 1.0, 0.5) == 0.0
    assert theory.critical_inertial_velocity(0.2, 1.0, 0.5, 0.0, 0.1) > 0.0


# (alpha, beta, a, zeta, eta_c), off the resonances sqrt(alpha) = 1, 2, ...
CRITICAL_POINTS = [(0.5, 2.0, 0.5, 0.05, 0.0), (0.3, 4.0, 0.8, 0.02, 0.3),
                   (2.0, 10.0, 0.6, 0.1, 0.1), (0.01, 400.01, 1.0, 0.01, 0.05),
                   (0.2, 1.0, 0.5, 0.0, 0.2), (1.0, math.inf, 0.5, 0.05, 0.0),
                   (1.0, 5.3, 0.5, 0.02, 0.5), (0.7, math.inf, 0.9, 1.2, 0.0)]


@pytest.mark.parametrize("p", CRITICAL_POINTS)
def test_mu_is_mu0_just_above_the_damped_critical_velocity_and_less_below(p):
    s = vf.Dimensionless(*p)
    vc = s.critical_inertial_velocity()
    assert 0.0 < vc < math.inf
    above = vf.friction_coefficient(s, v_inertial=1.02 * vc)
    assert above.trusted and above.mu_ratio == pytest.approx(1.0, abs=1e-9)
    below = vf.friction_coefficient(s, v_inertial=0.9 * vc)
    assert below.trusted and below.mu_ratio < 1.0 - 1e-6
    assert below.stick_fraction + below.reverse_slip_fraction > 0.0
    assert s.inertial_to_vbar(1.02 * vc) == pytest.approx(1.02, rel=1e-12)


# --------------------------------------------------------------------------- cases III, IV
def test_case_iv_plateau_ends_at_the_damped_critical_velocity():
    """Undamped case IV never reaches mu0; with zeta > 0 it does, at V_c = a/(2 zeta)."""
    a = 0.5
    far = vf.friction_coefficient(vf.Dimensionless(1.0, math.inf, a), v_inertial=200.0)
    assert far.trusted and far.mu_ratio < 0.8
    for zeta in (0.005, 0.02, 0.05):
        s = vf.Dimensionless(1.0, math.inf, a, zeta)
        vc = s.critical_inertial_velocity()
        assert vc == pytest.approx(a / (2 * zeta), rel=1e-14)
        mus = solver.solve_points(1.0, math.inf, a, vc * np.array([0.25, 0.5, 0.75, 0.95, 1.05]),
                                  zeta)
        assert np.all(mus["trusted"])
        assert np.all(np.diff(mus["mu_ratio"]) >= -1e-9)  # a rise to mu0
        assert mus["mu_ratio"][-1] == 1.0 and mus["mu_ratio"][-2] < 1.0


def test_modulated_points_near_beta_1_settle_with_small_damping():
    """The slow drifts near beta = 1 (docs/modulation.md) become ordinary orbits."""
    s0 = vf.Dimensionless(0.01, 1.01, 1.0)
    V = 0.02
    undamped = vf.friction_coefficient(s0, v_inertial=V)
    damped = vf.friction_coefficient(vf.Dimensionless(0.01, 1.01, 1.0, 0.02), v_inertial=V)
    assert damped.trusted and damped.periods < 2000
    assert undamped.periods >= damped.periods


# --------------------------------------------------------------------------- command line
def _cli(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "vibrofriction.cli", *args], capture_output=True,
                          text=True, timeout=300)


@pytest.mark.slow
def test_cli_mu_with_damping_and_for_a_physical_set_up():
    out = _cli("mu", "--alpha", "1", "--beta", "inf", "--amplitude", "0.5", "--zeta", "0.02",
               "--vbar", "0.5,1.01", "--json")
    assert out.returncode == 0, out.stderr
    rows = [json.loads(line) for line in out.stdout.splitlines()]
    assert rows[0]["system"]["zeta"] == 0.02 and rows[0]["v_inertial"] == pytest.approx(0.5 * 12.5)
    assert rows[0]["mu_ratio"] < 1.0 and rows[1]["mu_ratio"] == pytest.approx(1.0, abs=1e-9)
    phys = ("--mass", "0.01", "--k-x", "2.5e5", "--k-xc", "2e5", "--k-zc", "2.5e5", "--u-z0",
            "4e-6", "--du-z", "2e-6", "--omega", "6283", "--mu0", "0.3")
    out = _cli("mu", *phys, "--quality-factor", "50", "--v0", "0.001", "--json")
    assert out.returncode == 0, out.stderr
    row = json.loads(out.stdout)
    p = vf.Physical(0.01, 2.5e5, 2e5, 2.5e5, 4e-6, 2e-6, 6283.0, 0.3).with_damping(
        quality_factor=50.0)
    assert row["system"]["zeta"] == pytest.approx(0.01) and row["mu_ratio"] == pytest.approx(
        vf.friction_coefficient(p, v0=0.001).mu_ratio, abs=1e-12)
    bad = _cli("mu", "--alpha", "0.5", "--beta", "2", "--amplitude", "0.5", "--eta-c", "-1",
               "--vbar", "0.5")
    assert bad.returncode == 2 and "eta_c" in bad.stderr and "Traceback" not in bad.stderr
    bad = _cli("mu", *phys, "--c-x", "1", "--quality-factor", "50", "--v0", "0.001")
    assert bad.returncode == 2 and "--quality-factor" in bad.stderr


@pytest.mark.slow
def test_sweep_over_damping_axes(tmp_path):
    ds = vf.sweep(alpha=0.5, beta=2.0, amplitude=0.5, zeta=[0.0, 0.05], eta_c=[0.0, 0.2],
                  vbar=[0.5, 1.2], workers=1, progress=False)
    assert ds.mu_ratio.dims == ("zeta", "eta_c", "vbar")
    direct = solver.solve_points(0.5, 2.0, 0.5, ds.v_inertial.values,
                                 ds.zeta.values[:, None, None], ds.eta_c.values[None, :, None])
    np.testing.assert_array_equal(ds.mu_ratio.values, direct["mu_ratio"])
    vc = theory.critical_inertial_velocity(0.5, 2.0, 0.5, ds.zeta.values[:, None],
                                           ds.eta_c.values[None, :])
    np.testing.assert_allclose(ds.critical_velocity.values, vc, rtol=1e-14)
    # physical sweeps take the dashpots in N s/m
    p = vf.Physical(0.01, 2.5e5, 2e5, 2.5e5, 4e-6, 2e-6, 6283.0, 0.3)
    ds = vf.sweep(p, c_x=[0.0, 1.0], v0=[1e-3, 1e-2], workers=1, progress=False)
    assert ds.mu_ratio.dims == ("c_x", "v0")
    assert ds.zeta.values[1] == pytest.approx(p.with_(c_x=1.0).zeta)
