"""Sweeps (vibrofriction.sweep): grids, validation, the labelled Dataset, bitwise
reproducibility however the work is split, continuation, physical grids, CLI, plots."""

from __future__ import annotations

import json
import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

import vibrofriction
import vibrofriction.sweep as vsweep
from sweep_grid import GRID, VBAR, assert_bitwise
from vibrofriction import Dimensionless, Physical, friction_coefficient
from vibrofriction.figures import cell_edges, is_geometric, plot_atlas
from vibrofriction.solver import (
    FLOAT_COLUMNS,
    STATUS_BY_CODE,
    SectionState,
    SolverSettings,
    solve_points,
)
from vibrofriction.sweep import make_plan, parse_axis, sweep


@pytest.fixture(scope="module")
def serial() -> xr.Dataset:
    return sweep(**GRID, workers=1, progress=False)


# --------------------------------------------------------------------------- parsing
@pytest.mark.parametrize(("text", "expected"), [
    ("0:1.2:121", np.linspace(0, 1.2, 121)),
    ("1e-2:1e2:41:log", np.geomspace(1e-2, 1e2, 41)),
    ("0.25,0.5,1", np.array([0.25, 0.5, 1.0])),
    ("0.5,", np.array([0.5])),
    ("inf", math.inf),
    (" 0.5 ", 0.5),
])
def test_parse_axis(text, expected) -> None:
    got = parse_axis(text, "x")
    assert np.array_equal(got, expected)
    assert np.ndim(got) == np.ndim(expected)


@pytest.mark.parametrize(("text", "message"), [
    ("", "x: empty value"),
    ("a,b", "'a' is not a number"),
    ("0:1", "a range is start:stop:num"),
    ("0:1:5:lin", "a range is start:stop:num"),
    ("0:1:0", "empty grid"),
    ("0:1:2.5", "must be an integer"),
    ("0:1:5:log", "log range needs start, stop > 0"),
    ("0:inf:3", "range ends must be finite"),
])
def test_parse_axis_errors(text, message) -> None:
    with pytest.raises(ValueError, match=message):
        parse_axis(text, "x")


# --------------------------------------------------------------------------- validation
@pytest.mark.parametrize(("changes", "message"), [
    (dict(alpha=[]), r"alpha: empty grid"),
    (dict(vbar=np.array([])), r"vbar: empty grid"),
    (dict(alpha=[0.1, math.nan]), r"alpha must be finite and > 0, got nan"),
    (dict(beta=[2.0, math.nan]), r"beta must be > 0 \(math.inf allowed\), got nan"),
    (dict(amplitude=[0.5, math.inf]), r"amplitude must be finite and >= 0, got inf"),
    (dict(vbar=[0.1, -0.1]), r"vbar must be finite and >= 0, got -0.1"),
    (dict(alpha=[0.0, 0.1]), r"alpha must be finite and > 0, got 0.0"),
    (dict(alpha=[0.1, 3.0]), r"beta must be > alpha at every grid point: beta = 2.0 <= "
                             r"alpha = 3.0"),
    (dict(beta=[0.3, 2.0]), r"beta must be > alpha at every grid point"),
    (dict(alpha=[0.5, 1.0], beta=[2.0]), r"vbar does not exist where alpha == 1"),
    (dict(beta=[1.0, 2.0], alpha=0.5), r"vbar does not exist where beta == 1"),
    (dict(amplitude=[0.0, 0.5]), r"vbar does not exist where amplitude == 0"),
    (dict(alpha=[[0.1, 0.2]]), r"alpha must be a scalar \(held fixed\) or a 1-D array"),
    (dict(alpha="abc"), r"alpha must be a real number or an array of them \(finite and > 0\)"),
    (dict(phase_x="1.0"), r"phase_x must be a real number .* not a str: got '1.0'"),
    (dict(amplitude=[0.5, True]), r"amplitude must be a real number .* not a bool"),
])
def test_bad_grid_is_a_clear_error_before_any_work(changes, message, monkeypatch) -> None:
    def no_work(*args, **kwargs):
        raise AssertionError("work started")

    monkeypatch.setattr(vsweep._run, "run_blocks", no_work)
    monkeypatch.setattr(vsweep, "run_blocks", no_work)
    with pytest.raises(ValueError, match=message):
        sweep(**{**GRID, **changes}, workers=1, progress=False)


@pytest.mark.parametrize(("kwargs", "message"), [
    (dict(alpha=0.1, beta=2.0, amplitude=0.5), r"exactly one velocity axis"),
    (dict(alpha=0.1, beta=2.0, amplitude=0.5, vbar=0.1, v_inertial=0.1),
     r"exactly one velocity axis"),
    (dict(alpha=0.1, amplitude=0.5, vbar=0.1), r"missing parameter\(s\) \['beta'\]"),
    (dict(alpha=0.1, beta=2.0, amplitude=0.5, v0=0.1), r"v0 \(m/s\) needs a Physical"),
    (dict(alpha=0.1, beta=2.0, amplitude=0.5, vbar=0.1, mass=[1.0]), r"need a Physical"),
    (dict(alpha=0.1, beta=2.0, amplitude=0.5, vbar=0.1, continuation=True),
     r"continuation needs a swept velocity axis"),
    (dict(alpha=0.1, beta=2.0, amplitude=0.5, vbar=[0.2, 0.1], continuation=True),
     r"continuation needs vbar strictly increasing"),
    (dict(alpha=0.1, beta=2.0, amplitude=0.5, vbar=0.1, chunk_size=0), r"chunk_size"),
    (dict(alpha=0.1, beta=2.0, amplitude=0.5, vbar=0.1, initial="resting"), r"initial"),
    (dict(alpha=0.1, beta=2.0, amplitude=0.5, vbar=0.1, workers=0), r"workers"),
])
def test_bad_call(kwargs, message) -> None:
    with pytest.raises(ValueError, match=message):
        sweep(**kwargs, progress=False)


def test_v_inertial_axis_exists_where_vbar_does_not() -> None:
    # case III (beta = 1), case IV (alpha = 1) and a = 0 are fine with the inertial velocity
    ds = sweep(alpha=[0.5, 1.0], beta=4.0, amplitude=[0.0, 0.5], v_inertial=[0.0, 0.3],
               workers=1, progress=False)
    assert ds.mu_ratio.dims == ("alpha", "amplitude", "v_inertial")
    assert "v_inertial" not in ds.data_vars  # it is the coordinate
    assert math.isinf(float(ds.critical_velocity.sel(alpha=1.0, amplitude=0.5)))
    assert float(ds.critical_velocity.sel(alpha=0.5, amplitude=0.0)) == 0.0
    # no oscillation: mu = mu0 at every velocity
    assert np.all(ds.mu_ratio.sel(amplitude=0.0).values == 1.0)
    iii = sweep(alpha=0.5, beta=[1.0, 4.0], amplitude=0.5, v_inertial=[0.0, 0.3], workers=1,
                progress=False)
    assert float(iii.critical_velocity.sel(beta=1.0)) == 0.0
    # case III: mu = mu0 at every velocity (the contact resonance slides)
    assert float(iii.mu_ratio.sel(beta=1.0, v_inertial=0.3)) == pytest.approx(1.0, abs=1e-6)


# --------------------------------------------------------------------------- the Dataset
def test_dataset_is_labelled(serial: xr.Dataset) -> None:
    ds = serial
    assert ds.mu_ratio.dims == ("alpha", "beta", "vbar")
    assert ds.sizes == {"alpha": 3, "beta": 2, "vbar": 13}
    assert float(ds.amplitude) == 0.5 and ds.amplitude.ndim == 0  # fixed: scalar coord
    assert ds.critical_velocity.dims == ("alpha", "beta")
    for name in ("mu_ratio", "status", "error", "trusted", "periods", "period", "events",
                 "stick_fraction", "slip_fraction", "reverse_slip_fraction",
                 "flight_fraction", "multiplier", "settling_periods", "window_min",
                 "window_max", "v_inertial", "final_y", "final_x_dot", "final_f",
                 "final_phase", "critical_velocity"):
        assert name in ds.data_vars, name
        assert ds[name].attrs.get("long_name"), name
    # every float result of the solver is stored (the section state as final_*)
    assert set(FLOAT_COLUMNS) - {"y", "x_dot", "f", "e"} <= set(ds.data_vars)
    for name in ("multiplier", "settling_periods", "window_min", "window_max"):
        assert ds[name].attrs["units"] in ("1", "drive periods"), name
    assert ds.trusted.dtype == bool
    assert "error <= tol_trusted" in ds.trusted.attrs["long_name"]
    assert ds.attrs["solver_tol_trusted"] == SolverSettings().tol_trusted
    for name in ("mu_ratio", "critical_velocity", "alpha", "beta", "amplitude", "vbar"):
        assert "symbol" in ds[name].attrs and "units" in ds[name].attrs, name
    assert ds.mu_ratio.attrs["equation"] == "(25)"
    assert ds.critical_velocity.attrs["equation"] == "(12)"
    flags = ds.status.attrs
    meanings = flags["flag_meanings"].split()
    assert len(meanings) == len(flags["flag_values"])
    for code, word in zip(flags["flag_values"], meanings, strict=True):
        if code in STATUS_BY_CODE:
            assert word == STATUS_BY_CODE[code].value.replace(" ", "_")
    assert set(np.unique(ds.status.values)) <= set(STATUS_BY_CODE)
    assert ds.attrs["vibrofriction_version"] == vibrofriction.__version__
    assert ds.attrs["solver_max_periods"] == "default"  # each solver's own
    assert '"tol_mean": null' in ds.attrs["solver_settings"]
    methods = json.loads(ds.attrs["solver_methods"])
    assert methods["event"]["tol_mean"] == 1e-7 and methods["mdr"]["max_periods"] == 4000
    assert ds.attrs["velocity"] == "vbar"
    assert ds.attrs["fixed"] == ("a_x a_y amplitude eta_c phase_x phase_y profile_exponent rs_a "
                                 "rs_alpha_ld rs_b rs_d_c rs_v_ref static_ratio zeta")


def test_values_match_friction_coefficient_bitwise(serial: xr.Dataset) -> None:
    for al in (0.01, 0.3):
        system = Dimensionless(al, 5.0, 0.5)
        ref = friction_coefficient(system, vbar=VBAR)
        row = serial.sel(alpha=al, beta=5.0)
        assert row.mu_ratio.values.tobytes() == ref.mu_ratio.tobytes()
        assert row.v_inertial.values.tobytes() == np.asarray(
            system.vbar_to_inertial(VBAR)).tobytes()
        assert [STATUS_BY_CODE[int(c)] for c in row.status.values] == list(ref.status)
        assert np.array_equal(row.periods.values, ref.periods)
        assert float(serial.critical_velocity.sel(alpha=al, beta=5.0)) == \
            system.critical_inertial_velocity()


CONVERGED = [code for code, status in STATUS_BY_CODE.items() if status.ok]


def test_trusted_is_converged_status_and_error_within_tol_trusted() -> None:
    settings = SolverSettings(max_periods=20, min_periods=8, tol_trusted=1e-12)
    ds = sweep(**GRID, settings=settings, workers=1, progress=False)
    status, error = ds.status.values, ds.error.values
    expected = np.isin(status, CONVERGED) & (error <= 1e-12)
    assert np.array_equal(ds.trusted.values, expected)
    # both reasons occur here: a status that did not converge, an error above tolerance
    assert np.any(~np.isin(status, CONVERGED))
    assert np.any(np.isin(status, CONVERGED) & (error > 1e-12))
    assert ds.trusted.values.any()
    assert ds.attrs["solver_tol_trusted"] == 1e-12
    # the same notion as a single result's
    system = Dimensionless(0.1, 5.0, 0.5)
    ref = friction_coefficient(system, vbar=VBAR, settings=settings)
    assert np.array_equal(ds.trusted.sel(alpha=0.1, beta=5.0).values, ref.trusted)


def test_static_limit_and_continuous_sliding(serial: xr.Dataset) -> None:
    # eq. (2) at vbar = 0 and mu = mu0 exactly above vbar = 1 (away from resonances)
    assert np.all(serial.mu_ratio.sel(vbar=0.0).values == 0.5)
    assert np.all(serial.status.sel(vbar=0.0).values == -1)
    # (from the default start rare sticks of the undamped free oscillation may remain:
    # mu = mu0 within the stated error, docs/solver.md)
    above = serial.sel(vbar=1.2)
    assert np.all(above.trusted.values)
    assert np.all(np.abs(above.mu_ratio.values - 1.0) <= above.error.values)


@pytest.mark.parametrize("chunk_size", [1, 7, 13, 50, 10_000])
def test_bitwise_identical_for_any_chunking(serial: xr.Dataset, chunk_size: int) -> None:
    assert_bitwise(serial, sweep(**GRID, workers=1, chunk_size=chunk_size, progress=False))


@pytest.mark.slow
def test_bitwise_identical_on_local_cores(serial: xr.Dataset) -> None:
    assert_bitwise(serial, sweep(**GRID, workers=2, chunk_size=11, progress=False))


def test_module_is_callable(serial: xr.Dataset) -> None:
    assert_bitwise(serial, vibrofriction.sweep(**GRID, workers=1, progress=False))


def test_block_shapes_follow_chunk_size() -> None:
    plan = make_plan(alpha=np.geomspace(0.01, 0.5, 41), beta=np.linspace(2, 40, 41),
                     amplitude=0.5, vbar=np.linspace(0, 1.2, 121), chunk_size=1000)
    assert plan.chunks == (1, 7, 121)  # 6 blocks of 7 or 6 betas, not 5 of 8 and one of 1
    assert plan.n_blocks == 41 * 6
    assert sum(plan.block_size(b) for b in range(plan.n_blocks)) == plan.size
    plan = make_plan(alpha=0.1, beta=2.0, amplitude=0.5, vbar=np.linspace(0, 1, 2500),
                     chunk_size=1000)
    assert plan.chunks == (834,) and plan.n_blocks == 3
    cont = make_plan(alpha=[0.1, 0.2, 0.3], beta=2.0, amplitude=0.5,
                     vbar=np.linspace(0.1, 1, 30), continuation=True, chunk_size=10)
    assert cont.dims == ("alpha", "direction", "vbar")
    assert cont.chunks == (1, 2, 30)  # velocity curves are never split for continuation


def test_single_point_grid() -> None:
    ds = sweep(alpha=0.1, beta=2.0, amplitude=0.5, vbar=0.5, workers=1, progress=False)
    assert ds.mu_ratio.dims == ()
    ref = friction_coefficient(Dimensionless(0.1, 2.0, 0.5), vbar=0.5)
    assert float(ds.mu_ratio) == ref.mu_ratio


def test_dimensionless_base_system_with_overrides() -> None:
    a = sweep(Dimensionless(0.1, 2.0, 0.5), vbar=[0.2, 0.4], amplitude=[0.5, 1.5],
              workers=1, progress=False)
    b = sweep(alpha=0.1, beta=2.0, amplitude=[0.5, 1.5], vbar=[0.2, 0.4], workers=1,
              progress=False)
    assert_bitwise(a, b)
    assert a.flight_fraction.sel(amplitude=1.5).values.min() > 0  # jumping
    assert np.all(a.flight_fraction.sel(amplitude=0.5).values == 0)


# --------------------------------------------------------------------------- continuation
@pytest.mark.slow
def test_continuation_up_then_down_from_previous_states() -> None:
    vbar = np.linspace(0.05, 1.2, 8)
    ds = sweep(alpha=[0.01, 0.3], beta=2.0, amplitude=0.5, vbar=vbar, continuation=True,
               workers=1, progress=False)
    assert ds.mu_ratio.dims == ("alpha", "direction", "vbar")
    assert list(ds.direction.values) == ["up", "down"]
    # the first point of the up sweep starts like an independent point ...
    indep = sweep(alpha=[0.01, 0.3], beta=2.0, amplitude=0.5, vbar=vbar, workers=1,
                  progress=False)
    first = ds.isel(vbar=0).sel(direction="up")
    assert first.mu_ratio.values.tobytes() == indep.mu_ratio.isel(vbar=0).values.tobytes()
    # ... and every later one starts from its predecessor's final state, by hand:
    al = 0.3
    row = ds.sel(alpha=al)
    V = np.asarray(Dimensionless(al, 2.0, 0.5).vbar_to_inertial(vbar))
    prev = row.sel(direction="up").isel(vbar=2)
    state = vibrofriction.SectionState(float(prev.final_y), float(prev.final_x_dot),
                                       float(prev.final_f),
                                       ("stick", "slip+", "slip-")[int(prev.final_phase)])
    by_hand = solve_points(al, 2.0, 0.5, V[3], initial=state)
    # the same orbit (the continuation starts Newton from the neighbour's orbit at once,
    # by hand a period later): within the two stated errors
    here = row.sel(direction="up").isel(vbar=3)
    assert abs(float(by_hand["mu_ratio"]) - float(here.mu_ratio)) <= float(
        by_hand["error"]) + float(here.error)
    top = row.sel(direction="up").isel(vbar=-1)
    state = vibrofriction.SectionState(float(top.final_y), float(top.final_x_dot),
                                       float(top.final_f),
                                       ("stick", "slip+", "slip-")[int(top.final_phase)])
    by_hand = solve_points(al, 2.0, 0.5, V[-1], initial=state)
    here = row.sel(direction="down").isel(vbar=-1)
    assert abs(float(by_hand["mu_ratio"]) - float(here.mu_ratio)) <= float(
        by_hand["error"]) + float(here.error)
    # steady states here are unique: both directions agree to the solver's accuracy
    up, down = (row.sel(direction=d).mu_ratio.values for d in ("up", "down"))
    assert np.allclose(up, down, atol=1e-5)
    # splitting the rows differently changes nothing
    assert_bitwise(ds, sweep(alpha=[0.01, 0.3], beta=2.0, amplitude=0.5, vbar=vbar,
                             continuation=True, workers=2, chunk_size=1, progress=False))


def _state(point: xr.Dataset) -> SectionState | None:
    """The final section state stored for one point, or None where there is none."""
    phase = int(point.final_phase)
    if phase not in (0, 1, 2):
        return None
    return SectionState(float(point.final_y), float(point.final_x_dot), float(point.final_f),
                        ("stick", "slip+", "slip-")[phase], float(point.final_e))


def _walk_by_hand(alpha: float, beta: float, amplitude: float, V: np.ndarray,
                  row: xr.Dataset) -> tuple[list[float], list[float]]:
    """(mu, error) up then down in V, each point solved alone from the previous point's
    final state as stored in ``row`` (dims direction, velocity)."""
    up, down = [], []
    for direction, order, out in (("up", range(len(V)), up),
                                  ("down", range(len(V) - 1, -1, -1), down)):
        previous = None if direction == "up" else row.sel(direction="up").isel(
            {row.mu_ratio.dims[-1]: -1})
        for j in order:
            state = _state(previous) if previous is not None else None
            cols = solve_points(alpha, beta, amplitude, V[j],
                                initial=state if state is not None else "sliding")
            out.append((float(cols["mu_ratio"]), float(cols["error"])))
            previous = row.sel(direction=direction).isel({row.mu_ratio.dims[-1]: j})
    return up, down[::-1]


def _assert_walked(row: xr.Dataset, walked: tuple[list, list]) -> None:
    """The continuation's values are the walk by hand's within the two stated errors.

    The same orbits: the continuation starts Newton from the neighbour's orbit at once,
    the walk by hand a period later (and its bits differ).
    """
    for d, by_hand in zip(("up", "down"), walked, strict=True):
        mu, err = np.array(by_hand).T
        here = row.sel(direction=d)
        same = (np.abs(here.mu_ratio.values - mu) <= here.error.values + err) | (
            np.isnan(mu) & np.isnan(here.mu_ratio.values))
        assert np.all(same), (d, here.mu_ratio.values, mu)


def test_continuation_up_only_is_the_upward_half() -> None:
    """``continuation="up"``: one solve a point, the ``up`` branch of the full walk."""
    grid = dict(alpha=[0.01, 0.3], beta=2.0, amplitude=[0.5, 1.5],
                vbar=np.linspace(0.05, 1.2, 9), workers=1, progress=False)
    up = sweep(**grid, continuation="up")
    both = sweep(**grid, continuation="both")
    assert up.mu_ratio.dims == ("alpha", "amplitude", "direction", "vbar")
    assert list(up.direction.values) == ["up"] and up.attrs["continuation"] == "up"
    assert both.attrs["continuation"] == "both"
    assert_bitwise(up, both.sel(direction=["up"]).assign_attrs(up.attrs))


@pytest.mark.parametrize("bad", ["down", "yes", 1])
def test_continuation_names_its_values(bad) -> None:
    with pytest.raises(ValueError, match=r"continuation must be False, True, 'up' or 'both'"):
        sweep(alpha=0.1, beta=2.0, amplitude=0.5, vbar=[0.1, 0.2], continuation=bad,
              workers=1, progress=False)


@pytest.mark.slow
def test_continuation_over_v_inertial() -> None:
    V = np.array([0.0, 0.05, 0.1, 0.2, 0.4, 0.8])  # starts at the static limit (no state)
    ds = sweep(alpha=[0.01, 1.0], beta=4.0, amplitude=0.5, v_inertial=V, continuation=True,
               workers=1, progress=False)
    assert ds.mu_ratio.dims == ("alpha", "direction", "v_inertial")
    for al in (0.01, 1.0):  # alpha = 1: case IV, where vbar does not exist
        row = ds.sel(alpha=al)
        _assert_walked(row, _walk_by_hand(al, 4.0, 0.5, V, row))
        assert np.isnan(row.final_y.sel(direction="up").values[0])  # V = 0: no state
    assert_bitwise(ds, sweep(alpha=[0.01, 1.0], beta=4.0, amplitude=0.5, v_inertial=V,
                             continuation=True, workers=2, chunk_size=1, progress=False))


# --------------------------------------------------------------------------- physical
def pin(**changes) -> Physical:
    base = dict(mass=0.01, k_x=0.01 * (2 * math.pi * 800) ** 2, k_xc=2.0e5, k_zc=2.5e5,
                u_z0=4.0e-6, du_z=2.0e-6, omega=2 * math.pi * 1000, mu0=0.3)
    base.update(changes)
    return Physical(**base)


@pytest.mark.slow
def test_physical_sweep() -> None:
    system = pin()
    v0 = np.linspace(0.0, 2.0 * system.critical_velocity(), 6)
    ds = sweep(system, k_xc=[1.0e5, 2.0e5], du_z=[1.0e-6, 2.0e-6], v0=v0, workers=1,
               progress=False)
    assert ds.mu_ratio.dims == ("k_xc", "du_z", "v0")
    assert ds.v0.attrs["units"] == "m s-1" and ds.critical_velocity.attrs["units"] == "m s-1"
    assert float(ds.mass) == system.mass
    for k_xc in (1.0e5, 2.0e5):
        for du_z in (1.0e-6, 2.0e-6):
            s = system.with_(k_xc=k_xc, du_z=du_z)
            ref = friction_coefficient(s, v0=v0)
            point = ds.sel(k_xc=k_xc, du_z=du_z)
            assert point.mu_ratio.values.tobytes() == ref.mu_ratio.tobytes()
            d = s.to_dimensionless()
            assert (float(point.alpha), float(point.beta), float(point.amplitude)) == (
                d.alpha, d.beta, d.amplitude)
            assert float(point.critical_velocity) == s.critical_velocity()
    assert_bitwise(ds, sweep(system, k_xc=[1.0e5, 2.0e5], du_z=[1.0e-6, 2.0e-6], v0=v0,
                             workers=2, chunk_size=4, progress=False))


@pytest.mark.slow
def test_continuation_over_a_physical_grid() -> None:
    system = pin()
    v0 = np.linspace(0.2, 1.6, 5) * system.critical_velocity()
    ds = sweep(system, du_z=[1.0e-6, 2.0e-6], v0=v0, continuation=True, workers=1,
               progress=False)
    assert ds.mu_ratio.dims == ("du_z", "direction", "v0")
    for du_z in (1.0e-6, 2.0e-6):
        s = system.with_(du_z=du_z)
        d = s.to_dimensionless()
        row = ds.sel(du_z=du_z)
        walked = _walk_by_hand(d.alpha, d.beta, d.amplitude,
                               np.asarray(s.v0_to_inertial(v0)), row)
        _assert_walked(row, walked)
    assert_bitwise(ds, sweep(system, du_z=[1.0e-6, 2.0e-6], v0=v0, continuation=True,
                             workers=2, chunk_size=1, progress=False))


@pytest.mark.parametrize(("kwargs", "message"), [
    (dict(mass=[0.01, -1.0]), r"mass must be finite and > 0, got -1.0"),
    (dict(k_x=[]), r"k_x: empty grid"),
    (dict(mas=[1.0]), r"unknown physical parameter\(s\) \['mas'\]"),
    (dict(alpha=[0.1]),
     r"alpha, beta, amplitude, zeta, eta_c, a_x, vbar, v_inertial are not allowed"),
    (dict(k_xc=[1e-30]), r"invalid corner .*beta must be > alpha"),
])
def test_physical_grid_errors(kwargs, message) -> None:
    with pytest.raises(ValueError, match=message):
        sweep(pin(), v0=[0.0, 0.01], progress=False, **kwargs)


def test_physical_needs_v0() -> None:
    with pytest.raises(ValueError, match="give the sliding velocity v0"):
        sweep(pin(), k_x=[1.0, 2.0], progress=False)


# --------------------------------------------------------------------------- plots, CLI
def _cli(*args: str, cwd: Path) -> subprocess.CompletedProcess:
    exe = Path(sys.executable).with_name("vibrofriction")
    env = {**os.environ, "PYTHONWARNINGS": "ignore"}
    return subprocess.run([str(exe), *args], capture_output=True, text=True, cwd=cwd,
                          timeout=300, env=env)


@pytest.mark.slow
def test_cli_sweep_and_plot(tmp_path: Path) -> None:
    r = _cli("sweep", "--alpha", "0.01,0.1,0.3", "--beta", "2,5", "--amplitude", "0.5",
             "--vbar", "0:1.2:13", "--out", "atlas.zarr", "--workers", "1",
             "--chunk-size", "20", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert "78 points (alpha 3 x beta 2 x vbar 13)" in r.stdout
    assert "pt/s" in r.stderr  # the progress bar: points, rate
    stored = vsweep.open_atlas(tmp_path / "atlas.zarr")
    assert stored.attrs["blocks_done"] == stored.attrs["blocks_total"]
    ref = sweep(alpha=[0.01, 0.1, 0.3], beta=[2.0, 5.0], amplitude=0.5,
                vbar=np.linspace(0, 1.2, 13), workers=1, progress=False)
    assert ref.mu_ratio.values.tobytes() == stored.mu_ratio.values.tobytes()
    for extra in ([], ["--y", "alpha", "--sel", "beta=2"], ["--x", "alpha", "--sel",
                                                             "vbar=0.5"]):
        out = tmp_path / f"fig{len(extra)}.png"
        r = _cli("plot", "atlas.zarr", *extra, "--sel", "beta=5", "--out", str(out),
                 cwd=tmp_path) if not extra else _cli("plot", "atlas.zarr", *extra,
                                                      "--out", str(out), cwd=tmp_path)
        assert r.returncode == 0, r.stderr
        assert out.stat().st_size > 10_000
        assert out.read_bytes()[:4] == b"\x89PNG"


@pytest.mark.parametrize(("args", "message"), [
    (["sweep", "--alpha", "0.1", "--beta", "2", "--amplitude", "0.5", "--vbar", "0:1:0",
      "--out", "x.zarr"], "vbar: empty grid"),
    (["sweep", "--alpha", "0.1,3", "--beta", "2", "--amplitude", "0.5", "--vbar", "0.5",
      "--out", "x.zarr"], "beta must be > alpha"),
    (["sweep", "--alpha", "0.1", "--beta", "2", "--amplitude", "0.5", "--out", "x.zarr"],
     "exactly one of --vbar and --v-inertial"),
    (["sweep", "--mass", "1", "--v0", "0.1", "--out", "x.zarr"], "missing --k-x"),
    (["plot", "nothing.zarr", "--out", "x.png"], "not a vibrofriction sweep store"),
])
@pytest.mark.slow
def test_cli_bad_input_is_one_line_and_exit_2(tmp_path: Path, args, message) -> None:
    r = _cli(*args, cwd=tmp_path)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert message in r.stderr
    assert r.stderr.count("\n") == 1
    assert not (tmp_path / "x.zarr").exists()


def test_plot_function_curves_and_map(serial: xr.Dataset, tmp_path: Path) -> None:
    fig = plot_atlas(serial, sel={"beta": 2.0}, out=tmp_path / "c.png")
    ax = fig.axes[0]
    assert len(ax.lines) >= 3 and ax.get_xlabel() == r"$\bar v = v_0/v_0^*$"
    fig = plot_atlas(serial, x="vbar", y="alpha", sel={"beta": 5.0})
    assert len(fig.axes) == 2  # map and colour bar
    with pytest.raises(ValueError, match="fix some of alpha, beta"):
        plot_atlas(serial)
    with pytest.raises(ValueError, match="needs the other swept dimensions fixed: beta"):
        plot_atlas(serial, x="vbar", y="alpha")
    with pytest.raises(ValueError, match="unknown variable"):
        plot_atlas(serial, var="nope")


@pytest.mark.slow
def test_cli_sweep_exits_3_when_points_are_not_trusted(tmp_path: Path) -> None:
    r = _cli("sweep", "--alpha", "0.01,0.1,0.3", "--beta", "2,5", "--amplitude", "0.5",
             "--vbar", "0:1.2:13", "--out", "atlas.zarr", "--workers", "1",
             "--max-periods", "20", "--tol-trusted", "1e-12", "--no-progress", cwd=tmp_path)
    assert r.returncode == 3, (r.stdout, r.stderr)
    stored = vsweep.open_atlas(tmp_path / "atlas.zarr").load()
    assert stored.attrs["blocks_done"] == stored.attrs["blocks_total"]  # all written
    assert "78 points" in r.stdout
    trusted, status, error = (stored[k].values for k in ("trusted", "status", "error"))
    bad = ~trusted
    assert r.stderr.count("\n") == 1
    assert r.stderr.startswith(f"{int(bad.sum())} of 78 points are not trusted (")
    not_converged = int(np.sum(status == 2))
    assert not_converged and f"status not converged: {not_converged}" in r.stderr
    large = int(np.sum(np.isin(status, CONVERGED) & (error > 1e-12)))
    assert large and f"error > tol_trusted = 1e-12: {large}" in r.stderr


@pytest.fixture(scope="module")
def store(tmp_path_factory) -> Path:
    path = tmp_path_factory.mktemp("plot") / "atlas.zarr"
    sweep(**GRID, store=path, workers=1, progress=False)
    return path


@pytest.mark.parametrize(("sel", "message"), [
    ("beta", "--sel takes dim=value, got 'beta'"),
    ("=2", "--sel takes dim=value"),
    ("gamma=2", "--sel gamma: not a dimension of the atlas (dimensions: alpha, beta, vbar)"),
    ("beta=abc", "--sel beta='abc': the value must be a number"),
    ("direction=up", "--sel direction: not a dimension"),
])
@pytest.mark.slow
def test_cli_plot_bad_sel_is_one_line_and_exit_2(store: Path, tmp_path: Path, sel,
                                                message) -> None:
    r = _cli("plot", str(store), "--sel", sel, "--out", "x.png", cwd=tmp_path)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert r.stderr.count("\n") == 1 and message in r.stderr, r.stderr
    assert not (tmp_path / "x.png").exists()


def test_plot_marks_points_by_trusted_not_by_status(serial: xr.Dataset) -> None:
    from matplotlib.collections import PatchCollection

    ds = serial.copy(deep=True)
    assert ds.trusted.values.all()
    # two converged points declared untrusted: only `trusted` can tell the plot so
    picks = [dict(alpha=0.1, vbar=VBAR[5]), dict(alpha=0.3, vbar=VBAR[7])]
    for pick in picks:
        ds["trusted"].loc[dict(beta=2.0, **pick)] = False
    assert np.all(np.isin(ds.status.values, CONVERGED))
    fig = plot_atlas(ds, sel={"beta": 2.0})
    ax = fig.axes[0]
    crosses = [line for line in ax.lines if line.get_marker() == "x"]
    marked = sorted(float(y) for line in crosses for y in line.get_ydata() if np.isfinite(y))
    expected = sorted(float(ds.mu_ratio.sel(beta=2.0, **pick)) for pick in picks)
    assert marked == expected
    drawn = [y for line in ax.lines if line.get_marker() != "x" for y in line.get_ydata()]
    assert all(float(ds.mu_ratio.sel(beta=2.0, **pick)) not in drawn for pick in picks)
    fig = plot_atlas(ds, x="vbar", y="alpha", sel={"beta": 2.0})
    hatched = [c for c in fig.axes[0].collections if isinstance(c, PatchCollection)]
    assert len(hatched) == 1 and len(hatched[0].get_paths()) == 2
    assert hatched[0].get_hatch()
    mesh = fig.axes[0].collections[0].get_array()  # untrusted cells carry no colour
    assert int(np.ma.count_masked(mesh)) == 2


def test_cell_edges() -> None:
    # geometric: midpoints in log, outer edges mirrored: 10^-0.5, 10^0.5, 10^1.5, 10^2.5
    np.testing.assert_allclose(cell_edges([1.0, 10.0, 100.0]),
                               [10**-0.5, 10**0.5, 10**1.5, 10**2.5], rtol=1e-14)
    np.testing.assert_allclose(cell_edges([0.0, 1.0, 3.0]), [-0.5, 0.5, 2.0, 4.0])
    np.testing.assert_allclose(cell_edges([2.0, 4.0], log=True),
                               [2**0.5, 2 * 2**0.5, 4 * 2**0.5])
    np.testing.assert_allclose(cell_edges([5.0]), [4.5, 5.5])
    assert is_geometric(np.geomspace(0.01, 100, 9)) and not is_geometric([1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match="cannot draw cells along beta"):
        cell_edges([2.0, math.inf], name="beta")


def test_the_default_block_is_about_one_percent_of_the_grid_within_1000_and_10000():
    """A block's write costs the sweep process about the same whatever its size, so a big
    grid gets bigger blocks (benchmarks/results/sweep.md: 10^6 points 69 s -> 54 s), a
    small one keeps 1000-point blocks for balance and progress."""
    from vibrofriction.sweep import auto_chunk_size

    assert [auto_chunk_size(n) for n in (10, 20_000, 100_000, 500_000, 10**6, 10**8)] == [
        1000, 1000, 1000, 5000, 10_000, 10_000]
    big = make_plan(alpha=np.geomspace(0.01, 0.5, 100), beta=np.geomspace(2, 200, 100),
                    amplitude=0.5, vbar=np.linspace(0, 1.2, 100))
    assert big.n_blocks == 100 and int(np.prod(big.chunks)) == 10_000
    small = make_plan(alpha=np.geomspace(0.01, 0.5, 20), beta=np.geomspace(2, 200, 10),
                      amplitude=0.5, vbar=np.linspace(0, 1.2, 100))
    assert int(np.prod(small.chunks)) == 1000
    with pytest.raises(ValueError, match="chunk_size must be an integer >= 1 or None"):
        make_plan(alpha=0.5, beta=2.0, amplitude=0.5, vbar=[0.5], chunk_size=0)
