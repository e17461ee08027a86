"""The method protocol: declarations, the choice of method, refusals and every setting.

Each solver (``vibrofriction.solver.methods``) declares what it covers; these tests hold
the declarations to what the solvers do: a point, initial state or setting a method does
not cover is refused with a message naming it, and every setting a method declares has an
effect when set to an extreme value.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

import vibrofriction as vf
from vibrofriction.schema import FLOAT_COLUMNS, INT_COLUMNS, METHOD_NAMES, POINT_COLUMNS
from vibrofriction.solver import SectionState, SolverSettings, solve_points
from vibrofriction.solver.methods import METHODS, capability_table, choose, method_of
from vibrofriction.solver.points import point_table, table_of

SETTING_NAMES = tuple(f.name for f in dataclasses.fields(SolverSettings))
#: a point of each method that converges quickly with the defaults
POINTS = {
    "event": dict(alpha=0.5, beta=2.0, amplitude=0.5, v_inertial=0.3),
    "plane": dict(alpha=0.5, beta=2.0, amplitude=0.5, v_inertial=0.3, zeta=0.05, a_y=0.5,
                  phase_y=1.0),
    "mdr": dict(alpha=0.5, beta=2.0, amplitude=0.5, v_inertial=0.3, zeta=0.05,
                profile_exponent=2.0),
    "rate_state": dict(alpha=0.5, beta=2.0, amplitude=0.5, v_inertial=0.3, rs_a=0.01,
                       rs_b=0.005, rs_d_c=0.01, rs_v_ref=1.0),
}
#: where a point of POINTS does not show a setting: the averaging settings act only where
#: an average answers, on a motion neither locked to the drive nor near a periodic orbit
#: (a damped static coefficient's, averaged after 2048 periods by default), and
#: ``min_periods`` only where an average is then accepted
UNLOCKED_STATIC = dict(alpha=1.61131695894751, beta=5.201716269414939,
                       amplitude=0.667181213366733, v_inertial=0.34361794508618526,
                       zeta=0.028985213787314244, static_ratio=1.7004854100307911)
#: the rate-and-state solver averages only a motion not locked to the drive: self-excited
#: stick-slip of a weakening contact on a soft pin (0.7 times the critical stiffness)
UNLOCKED = dict(alpha=1.478, beta=11.478, amplitude=0.0, v_inertial=0.01, rs_a=0.01,
                rs_b=0.02, rs_d_c=0.01, rs_v_ref=1.0)
OVERRIDES = {("event", "tol_mean"): (UNLOCKED_STATIC, {}),
             ("event", "min_periods"): (UNLOCKED_STATIC, {"tol_mean": 0.5}),
             ("rate_state", "tol_mean"): (UNLOCKED, {"max_periods": 4000})}
#: settings at an extreme value each (a method that honours it must show an effect)
EXTREME = {"max_periods": 1, "min_periods": 1, "tol_state": 0.5, "tol_mean": 0.5,
           "max_events": 1, "max_events_per_period": 1, "rtol": 0.5}


def test_declarations_name_real_parameters_settings_and_columns() -> None:
    columns = set(FLOAT_COLUMNS) | set(INT_COLUMNS)
    assert tuple(METHODS) == METHOD_NAMES
    for name, method in METHODS.items():
        c = method.capabilities
        assert c.name == name
        assert set(c.parameters) <= set(POINT_COLUMNS), name
        assert set(c.settings) <= set(SETTING_NAMES) - {"tol_trusted"}, name
        assert set(c.outputs) <= columns, name
        assert {lim.parameter for lim in c.limits} <= set(POINT_COLUMNS), name
    table = capability_table()
    for method in METHODS.values():
        assert method.capabilities.title in table
    assert table.count("\n") == 12  # head, rule and ten rows


def test_choose_is_the_documented_rule() -> None:
    exponent = np.array([math.inf, math.inf, 2.0, 2.0, 1.0])
    a_y = np.array([0.0, 0.3, 0.0, 0.3, 0.0])
    assert [METHOD_NAMES[k] for k in choose(exponent, a_y)] == [
        "event", "plane", "mdr", "mdr", "mdr"]
    assert [method_of(n, y).capabilities.name for n, y in zip(exponent, a_y, strict=True)] \
        == ["event", "plane", "mdr", "mdr", "mdr"]
    # rate-and-state friction on the flat punch without a transverse oscillation
    rs_a = np.full(5, 0.01)
    assert [METHOD_NAMES[k] for k in choose(exponent, a_y, rs_a)] == [
        "rate_state", "plane", "mdr", "mdr", "mdr"]
    assert [method_of(n, y, 0.01).capabilities.name
            for n, y in zip(exponent, a_y, strict=True)] == [
        "rate_state", "plane", "mdr", "mdr", "mdr"]


def test_each_result_records_its_method() -> None:
    out = solve_points(0.5, 2.0, 0.5, [0.3, 0.3, 0.3, -0.3, 0.0],
                       zeta=0.05, a_y=[0.0, 0.5, 0.0, 0.5, 0.0],
                       profile_exponent=[math.inf, math.inf, 2.0, math.inf, 2.0])
    assert [METHOD_NAMES[k] for k in out["method"]] == ["event", "plane", "mdr", "plane",
                                                         "mdr"]
    r = vf.friction_coefficient(vf.Dimensionless(0.5, 2.0, 0.5), v_inertial=0.3)
    assert r.method == "event"
    rs = vf.friction_coefficient(vf.Dimensionless(0.5, 2.0, 0.5, zeta=0.05, a_y=0.5),
                                 v_inertial=np.array([0.3, 0.6]))
    assert list(rs.method) == ["plane", "plane"] and rs[1].method == "plane"


@pytest.mark.parametrize(("method", "change", "parameter"), [
    ("plane", dict(beta=math.inf), "beta"),
    ("plane", dict(amplitude=1.0), "amplitude"),
    ("mdr", dict(beta=math.inf), "beta"),
    ("mdr", dict(eta_c=0.1), "eta_c"),
    ("mdr", dict(a_x=0.5, v_inertial=0.0), "a_x"),
    ("rate_state", dict(v_inertial=0.0), "v_inertial"),
])
def test_a_point_a_method_does_not_cover_is_refused_by_name(method, change, parameter) -> None:
    point = {**POINTS[method], **change}
    if method == "plane" and parameter == "amplitude":
        point["zeta"] = 0.0
    title = METHODS[method].capabilities.title
    with pytest.raises(ValueError, match=f"{title} .* {parameter} = "):
        solve_points(**point)
    # refused before anything is solved, whatever the other points are
    with pytest.raises(ValueError, match=f"{parameter} = "):
        solve_points(**{k: [v, POINTS["event"].get(k, v)] for k, v in point.items()})


def test_a_curved_tip_starts_from_sliding_only() -> None:
    start = SectionState(y=-1.0, x_dot=0.0, f=0.5, phase="stick")
    for initial in ("rest", start):
        with pytest.raises(ValueError, match="initial = .*the MDR solver"):
            solve_points(**POINTS["mdr"], initial=initial)


@pytest.mark.parametrize("method", list(METHODS))
@pytest.mark.parametrize("setting", [s for s in SETTING_NAMES if s != "tol_trusted"])
def test_every_setting_is_honoured_or_refused_by_name(method, setting) -> None:
    """Set to an extreme value, a setting the method declares changes its result; one it
    does not declare is refused, naming the setting."""
    settings = SolverSettings(**{setting: EXTREME[setting]})
    if setting not in METHODS[method].capabilities.settings:
        with pytest.raises(ValueError, match=f"settings.{setting} = .* not honoured by "
                                             f"{METHODS[method].capabilities.title}"):
            solve_points(**POINTS[method], settings=settings)
        return
    point, before = OVERRIDES.get((method, setting), (POINTS[method], {}))
    base = solve_points(**point, settings=SolverSettings(**before))
    assert base["trusted"] or before, (method, base["status"])
    out = solve_points(**point, settings=SolverSettings(**before, **{setting: EXTREME[setting]}))
    changed = [k for k in ("mu_ratio", "error", "status", "periods", "work", "events")
               if not np.array_equal(out[k], base[k], equal_nan=True)]
    assert changed, (method, setting)


def test_the_extreme_budgets_make_points_fail_not_trusted() -> None:
    """The bounds that end a search end it: one period or one event is never a trusted
    result of a point that needs more (the flat punch and the curved tip alike)."""
    for method in ("event", "plane", "mdr", "rate_state"):
        out = solve_points(**POINTS[method], settings=SolverSettings(max_periods=1))
        assert not out["trusted"], method
    out = solve_points(**POINTS["event"], settings=SolverSettings(max_events=1))
    assert vf.Status.from_code(int(out["status"])) is vf.Status.FAILED
    out = solve_points(**POINTS["plane"], settings=SolverSettings(max_events_per_period=1))
    assert vf.Status.from_code(int(out["status"])) is vf.Status.FAILED


def test_settings_validate_each_field_by_name() -> None:
    for name in ("max_periods", "min_periods", "max_events", "max_events_per_period"):
        with pytest.raises(ValueError, match=f"settings.{name} must be an integer >= 1"):
            SolverSettings(**{name: 0})
    for name in ("tol_state", "tol_mean", "rtol", "tol_trusted"):
        with pytest.raises(ValueError, match=rf"settings.{name} must be a number in \(0, 1\)"):
            SolverSettings(**{name: 1.5})
    assert SolverSettings().chosen() == ()
    assert SolverSettings(rtol=1e-8, tol_trusted=1e-6).chosen() == ("rtol",)


def test_inplane_on_varies_per_point() -> None:
    V = np.array([0.3, 0.5, 0.3, 0.5])
    on = np.array(["substrate", "holder", "holder", "substrate"])
    both = solve_points(0.5, 2.0, 0.5, V, zeta=0.05, a_x=0.4, phase_x=0.7, inplane_on=on)
    for where in ("substrate", "holder"):
        alone = solve_points(0.5, 2.0, 0.5, V, zeta=0.05, a_x=0.4, phase_x=0.7,
                             inplane_on=where)
        rows = on == where
        for k in FLOAT_COLUMNS:
            np.testing.assert_array_equal(both[k][rows], alone[k][rows], err_msg=k)
    assert both["mu_ratio"][0] != both["mu_ratio"][2]  # same V: where it is imposed matters
    with pytest.raises(ValueError, match="inplane_on"):
        solve_points(0.5, 2.0, 0.5, V, inplane_on=["substrate", "holder", "side", "holder"])


def test_a_point_table_is_validated_once_by_name() -> None:
    t = point_table({"alpha": [0.5, 1.0], "beta": 2.0, "amplitude": 0.5, "v_inertial": 0.3})
    assert t.values.shape == (2, len(POINT_COLUMNS)) and t.shape == (2,)
    np.testing.assert_array_equal(t["alpha_y"], [0.5, 1.0])  # the twin's values
    assert t.choice("inplane_on", 1) == "substrate"
    assert t.system(1) == vf.Dimensionless(1.0, 2.0, 0.5, alpha_y=1.0, zeta_y=0.0)
    with pytest.raises(ValueError, match="beta"):
        point_table({"alpha": 3.0, "beta": 2.0, "amplitude": 0.5, "v_inertial": 0.3})
    with pytest.raises(TypeError, match="unknown parameter"):
        point_table({"alpha": 0.5, "beta": 2.0, "amplitude": 0.5, "v_inertial": 0.3,
                     "gamma": 1.0})
    # a number given as text is refused as everywhere else (it was read as 1.0)
    with pytest.raises(ValueError, match="alpha must be a real number .* not a str"):
        point_table({"alpha": "1.0", "beta": 2.0, "amplitude": 0.5, "v_inertial": 0.3})
    with pytest.raises(ValueError, match="amplitude must be a real number .* not a str"):
        solve_points(alpha=[0.5], beta=2.0, amplitude=["0.5"], v_inertial=0.3)


@pytest.mark.parametrize("system", [
    vf.Dimensionless(0.5, 2.0, 0.5, rs_a=0.01, rs_b=0.005, rs_law="slip"),
    vf.Dimensionless(0.7, math.inf, 1.3, a_y=0.3, alpha_y=0.9, zeta=0.1,
                     inplane_on="holder", profile_exponent=2.0),
])
@pytest.mark.parametrize("v", [0.5, [0.1, -0.2], np.ones((2, 3))])
def test_the_table_of_a_system_is_its_point_table(system, v) -> None:
    """A system's table (its fields checked when it was made, the velocities here) is the
    table of its values, row for row (twins and choices resolved the same way)."""
    fields = {n: getattr(system, n) for n in POINT_COLUMNS if n != "v_inertial"}
    mine, full = table_of(system, v), point_table({**fields, "v_inertial": v})
    assert mine.shape == full.shape
    np.testing.assert_array_equal(mine.values, full.values)
    with pytest.raises(ValueError, match="v_inertial"):
        table_of(system, [0.1, math.nan])


def test_no_points_is_no_work_and_keeps_the_shape() -> None:
    out = solve_points(0.5, 2.0, 0.5, np.zeros((0, 3)))
    assert out["mu_ratio"].shape == (0, 3) and out["method"].shape == (0, 3)
    assert vf.friction_coefficient(vf.Dimensionless(0.5, 2.0, 0.5), vbar=np.array([])).shape \
        == (0,)


def test_a_curved_tip_history_honours_or_refuses_the_settings() -> None:
    """simulate of a curved tip: the MDR solver's settings act on its steady start, the
    others are refused by name, as in solve_points."""
    sphere = vf.Dimensionless(0.5, 2.0, 0.5, zeta=0.05, profile_exponent=2.0)
    with pytest.raises(ValueError, match="settings.max_events = 1 is not honoured by the MDR"):
        vf.simulate(sphere, v_inertial=0.3, periods=0.1,
                    settings=SolverSettings(max_events=1))
    with pytest.raises(ValueError, match="did not converge"):
        vf.simulate(sphere, v_inertial=0.3, periods=0.1, initial="steady", springs=20,
                    settings=SolverSettings(max_periods=1))
    h = vf.simulate(sphere, v_inertial=0.3, periods=0.1, initial="steady", springs=20)
    assert np.all(np.isfinite(h.f))
    with pytest.raises(ValueError, match="settings.rtol = 0.5 is not honoured by the 1-D"):
        vf.simulate(vf.Dimensionless(0.5, 2.0, 0.5), v_inertial=0.3, periods=0.1,
                    settings=SolverSettings(rtol=0.5))
