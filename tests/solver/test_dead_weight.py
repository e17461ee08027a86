"""A dead weight imposes the mean normal force over the cycle (docs/contact_geometry.md,
"Dead weight"): the mean indentation it sets, against quadratures of the force written here
and the solvers' mean normal force."""

import math

import numpy as np
import pytest
from scipy.integrate import quad

import vibrofriction as vf
from vibrofriction import theory
from vibrofriction.contact import Cone, FlatPunch, Material, Sphere
from vibrofriction.solver.mdr import mdr_friction

STEEL = Material(E=210e9, nu=0.3)
BENCH = dict(natural_frequency_hz=800.0, mass=0.2, normal_load=20.0,
             drive_frequency_hz=1000.0, mu0=0.3)


def _cycle_mean(force, d0: float, dd: float) -> float:
    """<force(d0 + dd cos tau)> over a period by quad, split where the contact opens."""
    cuts = [0.0, math.pi]
    if dd > d0:
        cuts.insert(1, math.acos(-d0 / dd))
    total = sum(quad(lambda t: force(d0 + dd * math.cos(t)), lo, hi, epsabs=0.0,
                     epsrel=1e-13, limit=200)[0] for lo, hi in zip(cuts[:-1], cuts[1:],
                                                                   strict=True))
    return total / math.pi


@pytest.mark.parametrize("n", [math.inf, 0.7, 1.0, 2.0, 4.0])
@pytest.mark.parametrize("A", [0.0, 0.3, 0.9, 1.4, 1.8])
def test_dead_weight_indentation_carries_the_load_on_average(A, n):
    p = 1.0 if math.isinf(n) else 1.0 + 1.0 / n
    r = theory.dead_weight_indentation(A, n)
    # F/F_s = (d/d_s)^p, d = d_s (r + A cos tau): its mean is the load
    mean = _cycle_mean(lambda d: max(0.0, d) ** p, r, A)
    assert mean == pytest.approx(1.0, rel=1e-11)
    if math.isinf(n) and A <= 1.0:
        assert r == 1.0  # a flat punch that does not jump: the static indentation
    elif A > 0.0:
        assert r < 1.0  # a convex F (or lift-off) raises the mean: the pin sits higher


def test_dead_weight_refuses_an_oscillation_no_indentation_carries():
    assert theory.dead_weight_indentation(3.1, math.inf) < 0.1
    with pytest.raises(ValueError, match="too large for the dead weight"):
        theory.dead_weight_indentation(3.2, math.inf)  # A >= pi: <max(0, A cos)> >= 1
    with pytest.raises(ValueError, match="too large for the dead weight"):
        theory.dead_weight_indentation(2.4, 2.0)


def _linear(k_zc):
    return lambda d: k_zc * max(0.0, d)


@pytest.mark.parametrize("contact, model, du_z", [
    (Sphere(3e-3, STEEL, STEEL), "mdr", 0.9e-6),         # a = 0.52
    (Sphere(3e-3, STEEL, STEEL), "mdr", 3.0e-6),         # jumping, a = 3.7
    (Cone(0.2, STEEL, STEEL), "mdr", 3.0e-6),
    (FlatPunch(1e-3, STEEL, STEEL), "mdr", 1.5e-7),      # jumping flat punch
    (FlatPunch(1e-3, STEEL, STEEL), "linearised", 1.5e-7),
    (Sphere(3e-3, STEEL, STEEL), "linearised", 3.0e-6),  # the linear spring jumps
])
def test_from_bench_dead_weight_mean_force_is_the_load(contact, model, du_z):
    static = vf.from_bench(**BENCH, contact=contact, contact_model=model, du_z=du_z)
    pin = vf.from_bench(**BENCH, contact=contact, contact_model=model, du_z=du_z,
                                 normal_control="dead_weight")
    assert pin.normal_control == "dead_weight" and static.normal_control == "indentation"
    assert pin.du_z == du_z and pin.u_z0 < static.u_z0
    force = contact.normal_force if model == "mdr" else _linear(pin.k_zc)
    if model == "mdr":
        assert force(pin.u_z0) == pytest.approx(pin.F_N0, rel=1e-12)
        assert pin.k_zc == pytest.approx(float(contact.normal_stiffness(pin.u_z0)), rel=1e-12)
    else:  # the linearised contact keeps its stiffnesses at the load
        assert (pin.k_zc, pin.k_xc) == (static.k_zc, static.k_xc)
    load = BENCH["normal_load"]
    assert _cycle_mean(lambda d: float(force(d)), pin.u_z0, du_z) == pytest.approx(load,
                                                                                  rel=1e-10)
    assert pin.mean_normal_force == pytest.approx(load, rel=1e-12)
    assert static.F_N0 == pytest.approx(load, rel=1e-12)
    assert _cycle_mean(lambda d: float(force(d)), static.u_z0, du_z) > load * (1 + 1e-3)
    # the solvers' mean normal force: the engine's column, and the MDR row's own
    r = vf.friction_coefficient(pin, v0=0.002)
    assert r.mean_normal_ratio * pin.F_N0 == pytest.approx(load, rel=1e-12)
    if pin.curved:
        d = pin.to_dimensionless()
        row = mdr_friction(d.alpha, d.beta, d.amplitude, float(r.v_inertial),
                           d.profile_exponent, n_springs=320)
        assert row["mean_normal_ratio"] * pin.F_N0 == pytest.approx(load, rel=2e-5)


@pytest.mark.parametrize("model", ["mdr", "linearised"])
def test_dead_weight_without_jumping_flat_is_the_indentation_mode(model):
    """A flat punch (and any linear spring) that does not jump has <F> = F(d0)."""
    kw = dict(BENCH, contact=FlatPunch(1e-3, STEEL, STEEL), contact_model=model, du_z=5e-8)
    a = vf.from_bench(**kw)
    b = vf.from_bench(**kw, normal_control="dead_weight")
    assert a == b and b.normal_control == "dead_weight"
    k = vf.from_bench(**BENCH, k_zc=2e8, k_xc=1.6e8, du_z=5e-8,
                               normal_control="dead_weight")
    assert k.u_z0 == 20.0 / 2e8 and k.mean_normal_force == pytest.approx(20.0, rel=1e-15)


def test_indentation_mode_is_unchanged():
    """The default: the load is the force at the mean indentation, as before."""
    sphere = Sphere(3e-3, STEEL, STEEL)
    pin = vf.from_bench(**BENCH, contact=sphere, contact_model="mdr", du_z=0.9e-6)
    assert pin == vf.from_bench(**BENCH, contact=sphere, contact_model="mdr",
                                         du_z=0.9e-6, normal_control="indentation")
    assert pin.u_z0 == float(sphere.indentation(20.0))
    assert pin.F_N0 == pytest.approx(20.0, rel=1e-12)
    assert pin.mean_normal_force == pytest.approx(
        20.0 * float(theory.profile_mean_normal_force(0.9e-6 / pin.u_z0, 2.0)), rel=1e-14)
    assert pin.with_(mu0=0.2).normal_control == "indentation"
    np.testing.assert_equal(pin.normal_control, "indentation")
