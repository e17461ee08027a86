"""The design of a pin with a local friction law (docs/bench.md, "Fitting a friction law"): the law
is carried to every evaluation; a static coefficient equal to the kinetic one is Coulomb's design
bit for bit, a larger one changes the map where the contact sticks (checked at the optimum against
the independent reference); a rate-and-state design runs on its smaller map and its optimum is the
solver's value there."""

import dataclasses
import math

import numpy as np
import pytest

import vibrofriction as vf
from vibrofriction.bench.designing.choosing import RATE_STATE_MAP
from vibrofriction.bench.designing.space import BLOCKING_V
from vibrofriction_reference.friction_laws import static_kinetic_run

PIN = vf.from_bench(natural_frequency_hz=800.0, mass=0.01, quality_factor=50.0,
                    normal_load=20.0, k_zc=2e7, k_xc=1.5e7, drive_frequency_hz=1000.0,
                    du_z=0.5e-6, mu0=0.3)
LAW = vf.RateAndState(a=0.006, b=0.003, d_c=2e-6, v_ref=1e-2)
OMEGA = (2 * math.pi * 300, 2 * math.pi * 3000)
DU_Z = (0.1e-6, 0.9e-6)
SMALL = dict(n_omega=9, n_du_z=4, starts=2)


def _design(pin, **kwargs):
    return vf.design(pin, v0=0.005, omega=OMEGA, du_z=DU_Z, max_velocity_amplitude=0.01,
                     **{**SMALL, **kwargs})


@pytest.fixture(scope="module")
def coulomb():
    return _design(PIN)


def test_a_static_coefficient_equal_to_the_kinetic_one_is_coulombs_design(coulomb) -> None:
    same = _design(PIN.with_(mu_static=PIN.mu0))
    for name in ("cof", "mu_ratio", "trusted"):
        assert np.array_equal(same.map[name].values, coulomb.map[name].values, equal_nan=True)
    assert (same.system.omega, same.system.du_z, same.cof) == (
        coulomb.system.omega, coulomb.system.du_z, coulomb.cof)
    assert same.system.mu_static == PIN.mu0  # the law is carried into the chosen system


def test_a_larger_static_coefficient_changes_the_design_where_the_contact_sticks(coulomb) -> None:
    """Where the contact slides for the whole cycle (Coulomb's ``mu_ratio = 1``: the map's
    largest amplitudes fail to stick at the high frequencies) the static coefficient cannot
    act; elsewhere it raises the friction. The chosen optimum's value is the independent
    reference's at that oscillation (fixed-step, its own code)."""
    static = _design(PIN.with_(mu_static=1.3 * PIN.mu0))
    c, s = coulomb.map.cof.values, static.map.cof.values
    both = np.isfinite(c) & np.isfinite(s)
    assert np.any(s[both] > c[both] + 1e-3)  # stick-slip holds more force than mu0 n
    sliding = both & (coulomb.map.mu_ratio.values == 1.0)
    assert sliding.any() and np.array_equal(s[sliding], c[sliding])
    assert static.system.mu_static == pytest.approx(1.3 * PIN.mu0)
    d = static.system.to_dimensionless()
    ref = static_kinetic_run(d.alpha, d.beta, d.amplitude,
                             float(static.system.v0_to_inertial(static.v0)), d.static_ratio,
                             zeta=d.zeta, transient_periods=300, average_periods=60)
    assert static.cof == pytest.approx(PIN.mu0 * ref.mu_ratio,
                                       abs=PIN.mu0 * (3 * ref.error + 1e-4))
    labels = set(static.sensitivity["change"])
    assert {"mu_static -10 %", "mu_static +10 %", "mu0 +10 %"} <= labels


def test_a_rate_and_state_design_runs_and_its_optimum_is_the_solvers_value() -> None:
    pin = PIN.with_(friction=LAW)
    res = vf.design(pin, v0=0.005, omega=OMEGA, du_z=DU_Z, max_velocity_amplitude=0.01,
                    n_omega=5, n_du_z=3, starts=1)
    assert res.map.cof.shape[1] == 3 and RATE_STATE_MAP == (25, 9)
    assert res.system.friction == LAW
    r = vf.friction_coefficient(res.system.to_dimensionless(),
                                v_inertial=float(res.system.v0_to_inertial(res.v0)))
    assert r.method == "rate_state" and r.trusted
    assert res.cof == pytest.approx(pin.mu0 * r.mu_ratio, abs=pin.mu0 * 10 * max(r.error, 1e-9))
    # the law moves the answer: Coulomb friction at the same oscillation is another value
    coulomb = vf.friction_coefficient(res.system.with_(friction=None).to_dimensionless(),
                                      v_inertial=float(res.system.v0_to_inertial(res.v0)))
    assert abs(coulomb.mu_ratio - r.mu_ratio) > 1e-3
    assert {"a +10 %", "b -10 %", "d_c +10 %", "v_ref -10 %"} <= set(res.sensitivity["change"])


@pytest.mark.parametrize(("kwargs", "name"), [
    ({"du_x": (0.0, 1e-6)}, "du_x"), ({"du_y": (0.0, 1e-6)}, "du_y"),
    ({"du_x": (0.0, 1e-6), "goal": "drive"}, "du_x")])
def test_what_the_rate_and_state_design_does_not_take_is_refused_by_name(kwargs, name) -> None:
    pin = PIN.with_(friction=dataclasses.replace(LAW))
    with pytest.raises(ValueError, match=rf"rate-and-state friction .*normal oscillation only, "
                                         rf"not {name}"):
        vf.design(pin, v0=0.005, omega=OMEGA, du_z=DU_Z, **kwargs)


def test_the_in_plane_drive_of_a_static_pin_carries_the_law_to_its_characteristic() -> None:
    """``goal="drive"`` with a static coefficient: the chosen oscillation's value and its
    blocking force are the solver's with ``static_ratio`` (and not Coulomb's)."""
    pin = PIN.with_(mu_static=1.3 * PIN.mu0)
    res = vf.design(pin, v0=0.002, omega=(2 * math.pi * 200, 2 * math.pi * 5000),
                    du_z=(0.0, 0.9e-6), du_x=(0.0, 5e-6), goal="drive",
                    max_velocity_amplitude=0.03, n_omega=7, n_du_z=3, n_du_x=3, n_phase=4,
                    starts=2)
    s = res.system
    d = s.to_dimensionless()
    assert d.static_ratio == pytest.approx(1.3)
    r = vf.friction_coefficient(d, v_inertial=float(s.v0_to_inertial(res.v0)))
    assert res.cof == pytest.approx(pin.mu0 * r.mu_ratio, abs=1e-12)
    block = vf.friction_coefficient(d, v_inertial=BLOCKING_V)
    coulomb = vf.friction_coefficient(s.with_(mu_static=None).to_dimensionless(),
                                      v_inertial=BLOCKING_V)
    # the static law's answer, nan too where its motion settles on no orbit within the
    # budget (as at the oscillation chosen here), and not Coulomb's
    assert res.blocking[0] == pytest.approx(block.mu_ratio, abs=1e-12, nan_ok=True)
    assert math.isfinite(coulomb.mu_ratio)
    assert not abs(block.mu_ratio - coulomb.mu_ratio) <= 1e-6
