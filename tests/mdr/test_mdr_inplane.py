"""The MDR row with a longitudinal in-plane oscillation (issue 21, "everything else as
today"; docs/contact_geometry.md "In-plane oscillation"): the flat punch is the 1-D solver
with ``a_x``, the reference's flat punch is the 1-D in-plane reference, the solver agrees
with the reference (its own code) within the combined bars at the cached points, the
refusals that remain."""

import json
import math
import subprocess
import sys
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from vibrofriction import Dimensionless, friction_coefficient, theory
from vibrofriction.schema import Status
from vibrofriction.solver import solve_points
from vibrofriction.solver.mdr import mdr_friction
from vibrofriction_reference.inplane import inplane_mean
from vibrofriction_reference.mdr import mdr_reference

FLAT = [  # (alpha, beta, a, V, zeta, a_x, phase_x, inplane_on)
    (0.5, 2.0, 0.5, 0.3, 0.0, 0.5, 1.0, "substrate"),
    (0.7, 2.0, 0.5, 0.3, 0.0, 0.5, 1.0, "holder"),
    (1.3, 4.0, 1.4, 0.8, 0.05, 1.2, 2.5, "substrate"),
    (0.2, 0.9, 0.5, 0.05, 0.0, 0.3, 0.0, "holder"),
    (2.5, 3.0, 2.0, 0.4, 0.02, 0.8, 4.0, "substrate"),
    (1.0, 3.0, 0.9, 1.0, 0.1, 2.0, -1.0, "holder"),
    (0.5, 2.0, 0.3, 0.2, 0.1, 0.5, math.pi / 2, "substrate")]


@pytest.mark.parametrize("alpha, beta, a, V, zeta, a_x, phase_x, on", FLAT)
def test_flat_punch_is_the_single_spring_solver_with_a_x(alpha, beta, a, V, zeta, a_x,
                                                          phase_x, on):
    r = mdr_friction(alpha, beta, a, V, math.inf, zeta=zeta, a_x=a_x, phase_x=phase_x,
                     inplane_on=on)
    single = solve_points(alpha, beta, a, V, zeta=zeta, a_x=a_x, phase_x=phase_x,
                          inplane_on=on)
    assert r["status"] == "periodic" and int(single["status"]) == Status.PERIODIC.code
    assert abs(r["mu_ratio"] - float(single["mu_ratio"])) <= 1e-9


@pytest.mark.parametrize("alpha, beta, a, V, zeta, a_x, phase_x, on", [
    (0.5, 2.0, 0.5, 0.3, 0.0, 0.5, 1.0, "substrate"),
    (1.3, 4.0, 1.4, 0.8, 0.05, 1.2, 2.5, "holder")])
@pytest.mark.slow
def test_reference_flat_punch_is_the_1d_inplane_reference(alpha, beta, a, V, zeta, a_x,
                                                          phase_x, on):
    """The spring row (velocity Verlet, return mapping) against the 1-D in-plane reference
    (DOP853 with events), two independent integrators, within the row's bar."""
    ip = dict(a_x=a_x, phase_x=phase_x, inplane_on=on)
    row = mdr_reference(alpha, beta, a, V, math.inf, transient_periods=200,
                        average_periods=20, zeta=zeta, **ip)
    one = inplane_mean(alpha, beta, a, V, 100, 20, zeta=zeta, tolerance_check=False, **ip)
    assert abs(row.mu_ratio - one.mu_ratio) <= row.mu_error + one.mu_error
    assert row.mu_error < 5e-5


def test_reference_without_oscillation_is_unchanged():
    """a_x = 0 (the default) gives the cached values of tests/data/mdr_reference.json,
    made before the in-plane oscillation was added to the reference (to 1e-10, not bit
    for bit: another machine's libm may round differently; on the machine that made the
    cache they are equal)."""
    cached = json.loads((Path(__file__).parents[1] / "data" / "mdr_reference.json")
                        .read_text())["points"]
    for p in cached[1:3]:
        r = mdr_reference(p["alpha"], p["beta"], p["amplitude"], p["v_inertial"],
                          p["profile_exponent"],
                          resolutions=tuple(tuple(x) for x in p["resolutions"]),
                          transient_periods=p["transient_periods"], average_periods=20,
                          zeta=p["zeta"], a_x=0.0, phase_x=2.0)
        assert r.mu_ratio == pytest.approx(p["mu_ref"], abs=1e-10)
        assert r.mu_error == pytest.approx(p["err_ref"], abs=1e-10)


# 12 points with the reference cached by tests/data/make_mdr_inplane_reference.py (its own
# code, no solver run there)
CACHED = json.loads((Path(__file__).parents[1] / "data" / "mdr_inplane_reference.json")
                    .read_text())


def test_cached_points_cover_the_cases():
    pts = CACHED["points"]
    assert len(pts) >= 8
    assert {p["profile_exponent"] for p in pts} >= {1.0, 2.0, 3.0}
    assert {p["inplane_on"] for p in pts} == {"substrate", "holder"}
    assert any(p["amplitude"] > 1 for p in pts) and any(p["amplitude"] < 1 for p in pts)
    assert any(p["zeta"] > 0 for p in pts) and any(p["zeta"] == 0 for p in pts)
    assert len({p["phase_x"] for p in pts}) >= 2
    assert any(p["v_inertial"] < 0 for p in pts)
    assert any(p["a_x"] > abs(p["v_inertial"]) for p in pts)


@pytest.mark.parametrize("p", CACHED["points"], ids=lambda p: p["label"])
def test_agrees_with_the_cached_reference_within_the_error_bars(p):
    s = solve_points(p["alpha"], p["beta"], p["amplitude"], p["v_inertial"], p["zeta"],
                     a_x=p["a_x"], phase_x=p["phase_x"],
                     profile_exponent=p["profile_exponent"], inplane_on=p["inplane_on"])
    mu, err = float(s["mu_ratio"]), float(s["error"])
    assert int(s["status"]) == Status.PERIODIC.code and bool(s["trusted"])
    # bars up to 3.7e-5 here: at the solver's tolerance, tests/mdr/test_mdr_fine_reference.py
    assert abs(mu - p["mu_ref"]) <= err + p["err_ref"]
    assert float(s["mean_normal_ratio"]) == pytest.approx(
        theory.profile_mean_normal_force(p["amplitude"], p["profile_exponent"]), abs=1e-12)
    if p["v_inertial"] > 0:
        r = mdr_friction(p["alpha"], p["beta"], p["amplitude"], p["v_inertial"],
                         p["profile_exponent"], zeta=p["zeta"], a_x=p["a_x"],
                         phase_x=p["phase_x"], inplane_on=p["inplane_on"])
        assert r["mu_ratio"] == mu   # solve_points routes the point to mdr_friction
        assert r["max_excess"] <= 1e-12   # |f_i| <= n_i at every scan point
        assert r["stick_area_fraction"] + r["slip_area_fraction"] + r["open_area_fraction"] == \
            pytest.approx(1.0, abs=1e-12)


def test_backward_is_the_mirror():
    """V < 0 is solved as (-V, phase_x + pi) with mu negated (x -> -x)."""
    d = Dimensionless(0.5, 2.0, 0.5, a_x=0.5, phase_x=1.0, profile_exponent=2.0)
    back = friction_coefficient(d, v_inertial=-0.3)
    fwd = friction_coefficient(replace(d, phase_x=1.0 + math.pi), v_inertial=0.3)
    assert back.mu_ratio == -fwd.mu_ratio and back.status is Status.PERIODIC


def test_the_oscillation_reaches_the_solver():
    """Through the public API the oscillation is not dropped: a sphere with a_x = 1 > V on
    the substrate differs from the same pin without it by far more than both errors (here
    it rubs more: 0.8839 against 0.7381), and the holder's differs from the substrate's."""
    d = Dimensionless(0.8, 3.0, 0.3, zeta=0.05, profile_exponent=2.0)
    sub = friction_coefficient(replace(d, a_x=1.0, phase_x=0.3), v_inertial=0.2)
    hold = friction_coefficient(replace(d, a_x=1.0, phase_x=0.3, inplane_on="holder"),
                                v_inertial=0.2)
    without = friction_coefficient(d, v_inertial=0.2)
    assert abs(without.mu_ratio - sub.mu_ratio) > 1000 * (sub.error + without.error)
    assert abs(hold.mu_ratio - sub.mu_ratio) > 100 * (sub.error + hold.error)


@pytest.mark.parametrize("kw, name", [
    (dict(a_x=0.5, v_inertial=0.0), "a_x"),
    (dict(a_y=0.5, v_inertial=0.3), "a_y"),
    (dict(eta_c=0.1, v_inertial=0.3), "eta_c"),
    (dict(beta=np.inf, v_inertial=0.3), "beta")])
def test_what_is_still_refused_is_named(kw, name):
    args = dict(alpha=0.5, beta=2.0, amplitude=0.5, profile_exponent=2.0) | kw
    with pytest.raises(ValueError, match=name):
        solve_points(**args)
    with pytest.raises(ValueError, match="a_x"):
        mdr_friction(0.5, 2.0, 0.5, 0.0, 2.0, a_x=0.5)


@pytest.mark.slow
def test_cli_mu_curved_with_a_x():
    """`vibrofriction mu --profile-exponent 2 --a-x ...` gives the solver's values (it
    printed a critical velocity, not derived for a curved profile, and failed)."""
    args = [sys.executable, "-m", "vibrofriction.cli", "mu", "--alpha", "0.5", "--beta", "2",
            "--amplitude", "0.5", "--profile-exponent", "2", "--a-x", "0.5", "--phase-x",
            "1", "--inplane-on", "holder", "--v-inertial", "0.3"]
    js, out = (subprocess.run(args + extra, capture_output=True, text=True, timeout=300)
               for extra in (["--json"], []))
    assert js.returncode == 0 and out.returncode == 0, js.stderr + out.stderr
    row = json.loads(js.stdout)
    assert row["mu_ratio"] == mdr_friction(0.5, 2.0, 0.5, 0.3, 2.0, a_x=0.5, phase_x=1.0,
                                           inplane_on="holder")["mu_ratio"]
    assert "on the holder" in out.stdout and "critical velocity" not in out.stdout


def test_bench_and_sweep_carry_the_oscillation_to_a_curved_tip():
    """`vf.from_bench(..., contact_model="mdr", du_x=...)` and the sweep's a_x axis
    give the solver's values at the converted point."""
    import vibrofriction as vf
    from vibrofriction.contact import Material, Sphere

    steel = Material(E=210e9, nu=0.3)
    pin = vf.from_bench(natural_frequency_hz=800, mass=0.2, normal_load=20,
                                 drive_frequency_hz=1000, mu0=0.3, du_z=0.9e-6,
                                 contact=Sphere(3e-3, steel, steel), contact_model="mdr",
                                 du_x=2e-6, phase_x=1.0, inplane_on="holder")
    d = pin.to_dimensionless()
    assert d.a_x == pytest.approx(2e-6 * pin.mass * pin.omega**2 / (pin.mu0 * pin.F_N0),
                                  rel=1e-12)
    assert (d.phase_x, d.inplane_on, d.profile_exponent) == (1.0, "holder", 2.0)
    r = friction_coefficient(pin, v0=0.0015)
    s = solve_points(d.alpha, d.beta, d.amplitude, r.v_inertial, a_x=d.a_x, phase_x=1.0,
                     profile_exponent=2.0, inplane_on="holder")
    assert r.mu_ratio == float(s["mu_ratio"]) and r.trusted
    atlas = vf.sweep(Dimensionless(0.5, 2.0, 0.5, profile_exponent=1.0), a_x=[0.0, 0.5],
                     phase_x=[1.0], v_inertial=[-0.3, 0.3], progress=False)
    pts = solve_points(0.5, 2.0, 0.5, np.array([[-0.3, 0.3], [-0.3, 0.3]]),
                       a_x=np.array([[0.0], [0.5]]), phase_x=1.0, profile_exponent=1.0)
    np.testing.assert_array_equal(atlas["mu_ratio"].values[:, 0, :], pts["mu_ratio"])
