"""Sweeps of the local friction laws: a static coefficient above the kinetic one
(``static_ratio``, SI ``mu_static``) and rate-and-state friction (``rs_*``, ``rs_law``; SI
``Physical(friction=RateAndState(...))``): plans, signatures, refusals before any work, the
store, and atlases equal to :func:`~vibrofriction.friction_coefficient` bit for bit."""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest

import vibrofriction.sweep as vsweep
from vibrofriction import Dimensionless, Physical, RateAndState, friction_coefficient
from vibrofriction.capabilities import CAPABILITIES, Refusal, refused_by
from vibrofriction.sweep import compute_block, make_plan, sweep
from vibrofriction.sweep._compute import _physical_rows

BASE = dict(alpha=0.1, beta=2.0, amplitude=0.5)
V = np.array([0.15, 0.2, 0.3])  # inertial velocities, all > 0
LAW = dict(rs_a=0.02, rs_b=0.03, rs_d_c=0.05, rs_v_ref=0.2)  # velocity weakening, b > a


def pin(**changes) -> Physical:
    base = dict(mass=0.01, k_x=0.01 * (2 * math.pi * 800) ** 2, k_xc=2.0e5, k_zc=2.5e5,
                u_z0=4.0e-6, du_z=2.0e-6, omega=2 * math.pi * 1000, mu0=0.3)
    base.update(changes)
    return Physical(**base)


def rate_state(**changes) -> RateAndState:
    law = dict(a=0.006, b=0.009, d_c=2.0e-7, v_ref=1.0e-3)
    law.update(changes)
    return RateAndState(**law)


@pytest.fixture
def no_work(monkeypatch):
    """Make any block of work fail the test: the refusals come before it."""
    def work(*args, **kwargs):
        raise AssertionError("work started")

    monkeypatch.setattr(vsweep._run, "run_blocks", work)
    monkeypatch.setattr(vsweep, "run_blocks", work)


# --------------------------------------------------------------------------- plans
def test_the_laws_parameters_are_axes_in_the_schemas_order() -> None:
    plan = make_plan(**BASE, rs_b=[0.01, 0.03], rs_a=[0.02, 0.04], rs_alpha_ld=0.001,
                     v_inertial=V)
    assert plan.dims == ("rs_a", "rs_b", "v_inertial")
    assert plan.shape == (2, 2, 3)
    # held: given, or the schema's defaults (Coulomb: static_ratio 1, rs_d_c, rs_v_ref 1)
    assert plan.fixed["rs_alpha_ld"] == 0.001
    assert (plan.fixed["static_ratio"], plan.fixed["rs_d_c"], plan.fixed["rs_v_ref"]) == (
        1.0, 1.0, 1.0)
    assert plan.rs_law == "aging" and plan.friction is None
    static = make_plan(**BASE, static_ratio=[1.0, 1.5, 2.0], v_inertial=V)
    assert static.dims == ("static_ratio", "v_inertial")
    assert static.fixed["rs_a"] == 0.0


def test_held_values_and_the_law_come_from_the_system() -> None:
    system = Dimensionless(**BASE, rs_law="slip", **LAW)
    plan = make_plan(system=system, rs_b=[0.01, 0.03], v_inertial=V)
    assert plan.dims == ("rs_b", "v_inertial")
    assert (plan.fixed["rs_a"], plan.fixed["rs_d_c"], plan.fixed["rs_v_ref"]) == (
        0.02, 0.05, 0.2)
    assert plan.rs_law == "slip"
    assert make_plan(system=system, rs_law="aging", v_inertial=V).rs_law == "aging"
    static = make_plan(system=Dimensionless(**BASE, static_ratio=1.25), v_inertial=V)
    assert static.fixed["static_ratio"] == 1.25


def test_rs_law_is_part_of_the_signature() -> None:
    aging = make_plan(**BASE, **LAW, v_inertial=V)
    slip = make_plan(**BASE, **LAW, rs_law="slip", v_inertial=V)
    assert aging.signature()["rs_law"] == "aging" and slip.signature()["rs_law"] == "slip"
    assert aging.signature()["friction"] is None
    assert aging.token() != slip.token()
    changed = {k for k in aging.signature() if aging.signature()[k] != slip.signature()[k]}
    assert changed == {"rs_law"}


def test_a_physical_plan_carries_the_law_and_mu_static() -> None:
    law = rate_state(alpha_ld=1.0e-4)
    plan = make_plan(system=pin(friction=law), physical=dict(du_z=[1.0e-6, 2.0e-6]),
                     v0=[0.01, 0.02])
    assert plan.friction == law and plan.rs_law == "aging"
    # the law's SI parameters: axes held at the law's values
    assert {n: plan.fixed[f"friction_{n}"] for n in ("a", "b", "d_c", "v_ref", "alpha_ld")} == {
        "a": 0.006, "b": 0.009, "d_c": 2.0e-7, "v_ref": 1.0e-3, "alpha_ld": 1.0e-4}
    assert plan.signature()["params"]["friction_d_c"] == (2.0e-7).hex()
    assert plan.signature()["friction"] == "rate-and-state"
    slip = make_plan(system=pin(friction=law), physical=dict(du_z=[1.0e-6, 2.0e-6]),
                     v0=[0.01, 0.02], rs_law="slip")
    assert slip.friction == dataclasses.replace(law, law="slip") and slip.rs_law == "slip"
    assert slip.token() != plan.token()
    other = make_plan(system=pin(friction=rate_state(d_c=3.0e-7)),
                      physical=dict(du_z=[1.0e-6, 2.0e-6]), v0=[0.01, 0.02])
    assert other.signature()["params"]["friction_d_c"] == (3.0e-7).hex()
    assert other.token() != plan.token()
    swept = make_plan(system=pin(friction=law), physical=dict(friction_d_c=[1e-7, 4e-7],
                                                              friction_b=[0.005, 0.01]), v0=0.01)
    assert swept.dims == ("friction_b", "friction_d_c")
    coulomb = make_plan(system=pin(), v0=0.01)
    assert coulomb.signature()["friction"] is None
    assert not any(a.name.startswith("friction_") for a in coulomb.params)
    # mu_static: an SI axis where given (None: mu0, no axis)
    assert "mu_static" not in [a.name for a in make_plan(system=pin(), v0=0.01).params]
    static = make_plan(system=pin(), physical=dict(mu_static=[0.3, 0.45]), v0=0.01)
    assert static.dims == ("mu_static",)
    held = make_plan(system=pin(mu_static=0.4), v0=0.01)
    assert held.fixed["mu_static"] == 0.4


def test_a_physical_grid_scales_its_law_as_the_system_does() -> None:
    """The rows of a physical block: Physical(..., friction=law).to_dimensionless()."""
    law = rate_state(alpha_ld=1.0e-4, law="slip")
    system = pin(friction=law)
    omegas, masses = [2 * math.pi * 900, 2 * math.pi * 1000], [0.01, 0.02]
    plan = make_plan(system=system, physical=dict(omega=omegas, mass=masses), v0=[0.01])
    point, rows, _ = _physical_rows(plan, 0, np.array([0.01]))
    for i, mass in enumerate(masses):
        for j, omega in enumerate(omegas):
            s = system.with_(mass=mass, omega=omega)
            fields = s.friction_fields()
            assert fields["rs_law"] == "slip"
            for name in ("static_ratio", "rs_a", "rs_b", "rs_d_c", "rs_v_ref", "rs_alpha_ld"):
                assert point[name][i, j] == fields[name], name
                assert rows[name][i, j] == fields[name], name
            assert math.isnan(rows["critical_velocity"][i, j])  # rate-and-state: no eq. 12
    # the law's own SI parameters swept: each row's law is the system's with them
    plan = make_plan(system=system, physical=dict(friction_d_c=[1.0e-7, 4.0e-7],
                                                  friction_b=[0.004, 0.009]), v0=[0.01])
    point, rows, _ = _physical_rows(plan, 0, np.array([0.01]))
    for i, b in enumerate((0.004, 0.009)):
        for j, d_c in enumerate((1.0e-7, 4.0e-7)):
            fields = system.with_(friction=rate_state(b=b, d_c=d_c, alpha_ld=1.0e-4,
                                                      law="slip")).friction_fields()
            for name in ("rs_a", "rs_b", "rs_d_c", "rs_v_ref", "rs_alpha_ld"):
                assert point[name][i, j] == fields[name], name
    static = make_plan(system=pin(mu_static=0.45), physical=dict(mu0=[0.3, 0.36]), v0=[0.01])
    point, rows, _ = _physical_rows(static, 0, np.array([0.01]))
    assert point["static_ratio"].tolist() == [0.45 / 0.3, 0.45 / 0.36]
    assert rows["critical_velocity"].tolist() == [
        pin(mu0=mu0, mu_static=0.45).critical_velocity() for mu0 in (0.3, 0.36)]


# --------------------------------------------------------------------------- refusals
@pytest.mark.parametrize(("changes", "message"), [
    (dict(rs_a=[0.0, 0.02], rs_b=0.01), r"rs_b > 0 needs rs_a > 0 .*got rs_b = 0.01 with "
                                         r"rs_a = 0"),
    (dict(rs_a=0.02, rs_b=[0.0, 0.01], rs_alpha_ld=0.001),
     r"rs_alpha_ld > 0 needs rs_b > 0 .*got rs_alpha_ld = 0.001 with rs_b = 0"),
    (dict(rs_a=[0.0, 0.02], rs_alpha_ld=[0.0, 0.001], rs_b=0.0), r"rs_alpha_ld > 0 needs"),
    (dict(LAW, rs_alpha_ld=0.001, amplitude=[0.5, 1.0]),
     r"rs_alpha_ld > 0 needs amplitude < 1 .*got rs_alpha_ld = 0.001 with amplitude = 1"),
    (dict(static_ratio=[1.0, 1.5], rs_a=[0.0, 0.02]),
     r"static_ratio > 1 is a law of Coulomb friction: it needs rs_a = 0: got static_ratio "
     r"= 1.5 with rs_a = 0.02"),
    (dict(static_ratio=[0.9, 1.5]), r"static_ratio must be finite and >= 1, got 0.9"),
    (dict(rs_a=[-0.01]), r"rs_a must be finite and >= 0, got -0.01"),
    (dict(LAW, rs_d_c=[0.0, 1.0]), r"rs_d_c must be finite and > 0"),
    (dict(LAW, rs_law="creep"), r"rs_law must be one of .*aging.*slip.*got 'creep'"),
    (dict(LAW, vbar=[0.5, 1.0]), r"vbar \(v0/v0\* of eq. 16\) is not defined for "
                                 r"rate-and-state friction"),
    (dict(LAW, v_inertial=[0.1, 0.2], continuation=True),
     r"continuation is not available for rate-and-state friction"),
])
def test_bad_friction_grids_are_refused_by_name_before_any_work(changes, message,
                                                                 no_work) -> None:
    kwargs = {**BASE, "v_inertial": V, **changes}
    if "vbar" in changes:
        kwargs.pop("v_inertial")
    with pytest.raises(ValueError, match=message):
        make_plan(**{k: v for k, v in kwargs.items() if k not in ("workers", "progress")})
    with pytest.raises(ValueError, match=message):
        sweep(**kwargs, workers=1, progress=False)


@pytest.mark.parametrize(("changes", "message"), [
    (dict(rs_law="slip"), r"rs_law = 'slip' needs rate-and-state friction: a Physical "
                          r"system takes it as friction=RateAndState"),
    (dict(rs_a=[0.01]), r"rs_a: a Physical system's friction law is its mu_static"),
    (dict(static_ratio=1.5), r"static_ratio: a Physical system's friction law"),
    (dict(friction_a=[0.01, 0.02]), r"friction_a needs rate-and-state friction: a Physical "
                                    r"system takes it as friction=RateAndState"),
    (dict(d_c=[1e-6]), r"d_c: a physical sweep takes the parameters of its rate-and-state "
                       r"law as friction_d_c"),
    (dict(mu_static=[0.2, 0.4]), r"mu_static must be >= mu0 \(= 0.3"),
    (dict(mu0=[0.3, 0.5], mu_static=0.4), r"invalid corner .*'mu0': 0.5.*mu_static must "
                                          r"be >= mu0"),
])
def test_bad_physical_friction_is_refused_by_name(changes, message, no_work) -> None:
    with pytest.raises(ValueError, match=message):
        sweep(pin(), v0=[0.01, 0.02], workers=1, progress=False, **changes)


def test_a_physical_law_with_alpha_ld_and_jumping_is_refused_at_a_corner(no_work) -> None:
    system = pin(friction=rate_state(alpha_ld=1.0e-4))
    with pytest.raises(ValueError, match=r"invalid corner .*'du_z': 4e-06.*rs_alpha_ld > 0 "
                                         r"needs amplitude < 1"):
        sweep(system, du_z=[1.0e-6, 4.0e-6], v0=0.01, workers=1, progress=False)


@pytest.mark.parametrize(("changes", "message"), [
    (dict(friction_a=[0.0, 0.01]), r"friction_a = 0: a must be finite and > 0, got 0.0"),
    (dict(friction_d_c=[-1e-7]), r"friction_d_c = -1e-07: d_c must be finite and > 0"),
    (dict(friction_b=[0.0, 0.01], friction_alpha_ld=1e-3),
     r"invalid corner .*'friction_b': 0.0.*alpha_ld = 0.001 > 0 needs b > 0"),
    (dict(friction_b=[0.0, 0.01], friction_alpha_ld=[0.0, 1e-3]),
     r"invalid corner .*'friction_b': 0.0.*'friction_alpha_ld': 0.001.*needs b > 0"),
])
def test_bad_values_of_a_physical_law_are_refused_by_name(changes, message, no_work) -> None:
    with pytest.raises(ValueError, match=message):
        sweep(pin(friction=rate_state()), v0=0.01, workers=1, progress=False, **changes)


def test_mu_static_with_a_rate_and_state_law_is_refused(no_work) -> None:
    with pytest.raises(ValueError, match=r"mu_static is a law of Coulomb friction"):
        sweep(pin(friction=rate_state()), mu_static=[0.3, 0.4], v0=0.01, workers=1,
              progress=False)


#: (profile_exponent, a_y) choosing each solver.
SOLVERS = {"event": (math.inf, 0.0), "plane": (math.inf, 0.2), "mdr": (2.0, 0.0)}


@pytest.mark.parametrize("solver", sorted(SOLVERS))
@pytest.mark.parametrize(("law", "value"), [("static_ratio", 1.5), ("rs_a", 0.02)])
def test_a_law_a_solver_of_the_grid_never_takes_is_refused_before_any_work(
        solver, law, value, no_work) -> None:
    """As each solver declares it (capabilities): refused before any work, or planned."""
    profile_exponent, a_y = SOLVERS[solver]
    kwargs = dict(BASE, profile_exponent=profile_exponent, a_y=a_y, v_inertial=V,
                  **{law: [0.0 if law == "rs_a" else 1.0, value]})
    if solver not in {c.name for c in refused_by(law)}:  # it takes the law: work starts
        with pytest.raises(AssertionError, match="work started"):
            sweep(**kwargs, workers=1, progress=False)
        return
    with pytest.raises(Refusal, match=rf"{CAPABILITIES[solver].title} .*does not take "
                                      rf".*got {law} = {value:g} in the grid") as info:
        sweep(**kwargs, workers=1, progress=False)
    assert info.value.parameter == law
    make_plan(**kwargs)  # the plan is only the grid: made all the same


def test_a_physical_law_no_solver_takes_is_refused_before_any_work(no_work) -> None:
    refusers = {c.name for c in refused_by("static_ratio")}
    if "mdr" in refusers and "event" not in refusers:
        with pytest.raises(Refusal, match=r"MDR solver .*got static_ratio = 1.5"):
            sweep(pin(mu_static=0.45), profile_exponent=[2.0, math.inf], v0=0.01, workers=1,
                  progress=False)
    if "event" in {c.name for c in refused_by("rs_a")}:
        with pytest.raises(Refusal, match=r"does not take rate-and-state friction"):
            sweep(pin(friction=rate_state()), v0=0.01, workers=1, progress=False)


# --------------------------------------------------------------------------- atlases
def test_an_atlas_over_static_ratio_equals_friction_coefficient_bitwise() -> None:
    ratios = [1.0, 1.3, 2.0]
    ds = sweep(**BASE, static_ratio=ratios, v_inertial=V, workers=1, progress=False)
    assert ds.mu_ratio.dims == ("static_ratio", "v_inertial")
    assert ds.attrs["rs_law"] == "aging"
    coulomb = Dimensionless(**BASE).critical_inertial_velocity()
    for s in ratios:
        ref = friction_coefficient(Dimensionless(**BASE, static_ratio=s), v_inertial=V)
        row = ds.sel(static_ratio=s)
        assert row.mu_ratio.values.tobytes() == ref.mu_ratio.tobytes()
        assert row.error.values.tobytes() == ref.error.tobytes()
        assert np.array_equal(row.periods.values, ref.periods)
        # a sliding contact carries the kinetic force: the Coulomb critical velocity
        assert float(row.critical_velocity) == coulomb
    # the static coefficient changes the result (else this test could not fail)
    assert not np.array_equal(ds.mu_ratio.sel(static_ratio=2.0).values,
                              ds.mu_ratio.sel(static_ratio=1.0).values)
    assert "nan for rate-and-state" in ds.critical_velocity.attrs["comment"]


def test_a_physical_sweep_over_mu_static_equals_friction_coefficient_bitwise() -> None:
    system = pin()
    v0 = np.array([0.6, 0.8, 1.2]) * system.critical_velocity()
    ds = sweep(system, mu_static=[0.3, 0.39, 0.6], v0=v0, workers=1, progress=False)
    assert ds.mu_ratio.dims == ("mu_static", "v0")
    assert ds.mu_static.attrs["units"] == "1"
    for mu_static in (0.3, 0.39, 0.6):
        s = system.with_(mu_static=mu_static)
        ref = friction_coefficient(s, v0=v0)
        row = ds.sel(mu_static=mu_static)
        assert row.mu_ratio.values.tobytes() == ref.mu_ratio.tobytes()
        assert float(row.static_ratio) == mu_static / 0.3
        assert float(row.critical_velocity) == system.critical_velocity()


def test_a_resumed_store_with_another_rs_law_is_refused(tmp_path: Path) -> None:
    path = tmp_path / "atlas.zarr"
    grid = dict(BASE, v_inertial=V, workers=1, progress=False)
    ds = sweep(**grid, rs_law="slip", store=path)
    assert ds.attrs["rs_law"] == "slip"
    assert vsweep.open_atlas(path).attrs["rs_law"] == "slip"
    sweep(**grid, rs_law="slip", store=path)  # the same law resumes
    with pytest.raises(ValueError, match=r"holds a different sweep \(rs_law: store has "
                                         r"'slip', this call 'aging'\)"):
        sweep(**grid, store=path)


def test_an_atlas_over_rs_a_equals_friction_coefficient_bitwise() -> None:
    values = [0.01, 0.02, 0.04]
    for law in ("aging", "slip"):
        ds = sweep(**BASE, rs_a=values, rs_b=0.03, rs_d_c=0.05, rs_v_ref=0.2, rs_law=law,
                   v_inertial=V, workers=1, progress=False)
        assert ds.attrs["rs_law"] == law
        for a in values:
            system = Dimensionless(**BASE, rs_a=a, rs_b=0.03, rs_d_c=0.05, rs_v_ref=0.2,
                                   rs_law=law)
            ref = friction_coefficient(system, v_inertial=V)
            row = ds.sel(rs_a=a)
            assert row.mu_ratio.values.tobytes() == ref.mu_ratio.tobytes()
            assert np.all(np.isnan(row.critical_velocity.values))


def test_a_physical_sweep_keeps_its_rate_and_state_law() -> None:
    system = pin(friction=rate_state(law="slip"))
    v0 = np.array([0.6, 1.2]) * pin().critical_velocity()
    ds = sweep(system, du_z=[1.0e-6, 2.0e-6], friction_d_c=[1.0e-7, 2.0e-7], v0=v0,
               workers=1, progress=False)
    assert ds.attrs["rs_law"] == "slip"
    assert ds.mu_ratio.dims == ("du_z", "friction_d_c", "v0")
    assert (float(ds.friction_a), ds.friction_d_c.attrs["units"]) == (0.006, "m")
    for du_z, d_c in ((1.0e-6, 1.0e-7), (2.0e-6, 2.0e-7), (2.0e-6, 1.0e-7)):
        s = system.with_(du_z=du_z, friction=rate_state(d_c=d_c, law="slip"))
        row = ds.sel(du_z=du_z, friction_d_c=d_c)
        for name, value in s.friction_fields().items():
            if name != "rs_law":
                assert float(row[name]) == value, name
        assert row.mu_ratio.values.tobytes() == friction_coefficient(s, v0=v0).mu_ratio.tobytes()


def test_a_rate_and_state_block_is_solved_with_the_plans_law() -> None:
    plan = make_plan(**BASE, **LAW, rs_law="slip", v_inertial=V)
    _, values = compute_block(plan, 0)
    ref = friction_coefficient(Dimensionless(**BASE, **LAW, rs_law="slip"), v_inertial=V)
    assert values["mu_ratio"].tobytes() == ref.mu_ratio.tobytes()


def test_continuation_carries_the_static_coefficient() -> None:
    ds = sweep(**BASE, static_ratio=[1.0, 1.5], v_inertial=V, continuation=True, workers=1,
               progress=False)
    assert ds.mu_ratio.dims == ("static_ratio", "direction", "v_inertial")
    for s in (1.0, 1.5):  # each upward walk starts from steady sliding, as a single point
        first = friction_coefficient(Dimensionless(**BASE, static_ratio=s), v_inertial=V[:1])
        got = ds.mu_ratio.sel(static_ratio=s, direction="up").values[:1]
        assert got.tobytes() == first.mu_ratio.tobytes()
    assert not np.array_equal(ds.mu_ratio.sel(static_ratio=1.5).values,
                              ds.mu_ratio.sel(static_ratio=1.0).values)
