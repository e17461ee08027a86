"""Results and histories print like a table and convert to pandas and xarray.

The short reprs (a 121-point result in a few lines, its counts right), ``to_dataframe()``,
``to_xarray()`` and ``to_dict()``: their shape, columns, categoricals and round trips, and
the units and descriptions in their attributes against :mod:`vibrofriction.schema` (the
expected values come from the schema and the result's own arrays, not from the conversion).
"""

from __future__ import annotations

import dataclasses
import math
import re
from collections import Counter

import numpy as np
import pandas as pd
import pytest

import vibrofriction as vf
from vibrofriction.schema import (
    FIELD,
    HISTORY_FIELD,
    METHOD_NAMES,
    PARAMETER,
    RESULT_FIELDS,
    STATE_FIELDS,
    Status,
)

SYSTEM = vf.Dimensionless(alpha=0.5, beta=2.0, amplitude=0.5)
VBAR = np.linspace(0.0, 1.2, 121)
ARRAY_FIELDS = [f.name for f in RESULT_FIELDS if f.name not in ("final_state", "system",
                                                                  "v_inertial")]
FINAL = [f"final_{g.name}" for g in STATE_FIELDS]


@pytest.fixture(scope="module")
def curve() -> vf.FrictionResults:
    return vf.friction_coefficient(SYSTEM, vbar=VBAR)


@pytest.fixture(scope="module")
def grid() -> vf.FrictionResults:
    return vf.friction_coefficient(SYSTEM, vbar=np.array([[0.1, 0.5, 0.9], [1.1, 0.0, 0.3]]))


# --------------------------------------------------------------------------- the reprs
def test_repr_of_121_points_is_a_few_lines_with_the_counts_right(curve):
    text = repr(curve)
    lines = text.splitlines()
    assert 3 <= len(lines) <= 12, text
    assert all(len(line) <= 100 for line in lines), text
    counts = Counter(s.value for s in curve.status)  # independently, from the array
    assert len(counts) >= 3  # the curve has a static limit, periodic and sliding points
    status_line = next(line for line in lines if line.strip().startswith("status:"))
    shown = dict((name, int(n)) for name, n in
                 re.findall(r"([a-z][a-z ]*?) (\d+)(?:,|$)", status_line.split(":", 1)[1]))
    assert shown == dict(counts), status_line
    assert "121 points" in lines[0] and "(121,)" in lines[0]
    assert f"trusted {int(curve.trusted.sum())} of 121" in text
    mu = curve.mu_ratio[curve.trusted]
    assert f"from {mu.min():.6g} to {mu.max():.6g}" in text
    assert f"largest error {np.max(curve.error):.4g}" in text
    assert f"event {np.sum(curve.method == 'event')}" in text


def test_repr_of_results_that_are_not_trusted_says_so():
    r = vf.friction_coefficient(SYSTEM, vbar=np.array([0.3, 0.6]),
                                settings=vf.SolverSettings(tol_trusted=1e-14))
    assert not r.trusted.any()  # errors of ~1e-13 > 1e-14
    assert "trusted 0 of 2; mu_ratio of the trusted none" in repr(r)
    # a point without a value: nan, an unbounded error, not converged
    worse = dataclasses.replace(
        r, mu_ratio=np.array([r.mu_ratio[0], np.nan]), error=np.array([r.error[0], np.inf]),
        status=np.array([Status.PERIODIC, Status.NOT_CONVERGED], dtype=object))
    text = repr(worse)
    assert "status: periodic 1, not converged 1" in text
    assert "largest error inf (1 unbounded)" in text


def test_repr_of_one_result_is_short_and_names_its_value(curve):
    r = curve[30]
    text = repr(r)
    assert 2 <= len(text.splitlines()) <= 6, text
    assert f"mu_ratio = {r.mu_ratio:.10g}" in text
    assert r.status.value in text and r.method in text
    assert "SectionState(" not in text and "Dimensionless(" not in text  # summarised
    assert r.final_state is not None and r.final_state.phase in text
    static = repr(curve[0])
    assert curve[0].final_state is None and "none" in static


def test_history_reprs_are_short_and_name_periods_samples_and_arrays():
    flat = vf.simulate(SYSTEM, vbar=0.3, periods=2)
    plane = vf.simulate(vf.Dimensionless(0.5, 2.0, 0.5, a_y=0.3), v_inertial=0.3, periods=1)
    for h in (flat, plane):
        text = repr(h)
        lines = text.splitlines()
        assert len(lines) <= 8 and all(len(line) <= 100 for line in lines), text
        assert f"{h.tau.size} samples" in text and f"{len(h.events)} events" in text
        periods = (h.tau[-1] - h.tau[0]) / (2 * math.pi)
        assert f"({periods:.4g} drive period" in text
        assert type(h).__name__ in lines[0]
        assert "array([" not in text  # no numpy array dumped
    assert "u_y" in repr(plane) and "u_y" not in repr(flat)


# --------------------------------------------------------------------------- the tables
def test_dataframe_has_a_row_per_point_and_the_fields_as_columns(curve):
    df = curve.to_dataframe()
    assert df.shape[0] == 121 and df.index.name == "point"
    assert list(df.columns) == ["v_inertial", "vbar", *ARRAY_FIELDS, *FINAL]
    for name in ("status", "method", "final_phase"):
        assert isinstance(df[name].dtype, pd.CategoricalDtype), name
    assert list(df.status.cat.categories) == [s.value for s in Status]
    assert list(df.method.cat.categories) == list(METHOD_NAMES)
    assert list(df.status.astype(str)) == [s.value for s in curve.status]
    np.testing.assert_array_equal(df.mu_ratio.to_numpy(), curve.mu_ratio)
    np.testing.assert_allclose(df.vbar.to_numpy(), VBAR, rtol=1e-12, atol=1e-15)
    np.testing.assert_array_equal(df.trusted.to_numpy(), curve.trusted)
    states = curve.final_state
    assert df.final_phase.iloc[0] == "none" and states[0] is None
    assert [df.final_y.iloc[i] for i in (5, 50)] == [states[i].y for i in (5, 50)]
    assert df.attrs["units"]["v_inertial"] == FIELD["v_inertial"].unit
    assert df.attrs["units"]["final_x_dot"] == FIELD["x_dot"].unit


def test_one_result_to_dict_is_its_row_of_the_dataframe(curve):
    df = curve.to_dataframe()
    for i in (0, 7, 120):
        row = curve[i].to_dict()
        assert list(row) == list(df.columns)
        table = df.iloc[i].to_dict()
        for name, value in row.items():
            if isinstance(value, float) and math.isnan(value):
                assert math.isnan(table[name]), name
            else:
                assert table[name] == value, name
        assert row["status"] == curve.status[i].value


def test_xarray_labels_the_points_and_takes_its_units_from_the_schema(curve):
    ds = curve.to_xarray()
    assert dict(ds.sizes) == {"point": 121}
    assert set(ds.data_vars) == {*ARRAY_FIELDS, *FINAL}
    np.testing.assert_array_equal(ds.v_inertial.values, curve.v_inertial)
    np.testing.assert_allclose(ds.vbar.values, VBAR, rtol=1e-12, atol=1e-15)
    assert ds.v_inertial.dims == ("point",)
    for name in ARRAY_FIELDS:  # units and descriptions: the schema's
        f = FIELD[name]
        assert ds[name].attrs["units"] == f.unit and ds[name].attrs["long_name"] == f.long_name
    for g in STATE_FIELDS:
        assert ds[f"final_{g.name}"].attrs["units"] == g.unit
        assert ds[f"final_{g.name}"].attrs["long_name"].endswith(g.long_name)
    for name in ("alpha", "beta", "amplitude", "zeta"):  # the fixed system: scalar coords
        assert ds[name].ndim == 0 and float(ds[name]) == getattr(SYSTEM, name)
        assert ds[name].attrs["units"] == PARAMETER[name].unit
    assert ds.vbar.attrs["long_name"] == PARAMETER["vbar"].long_name
    assert list(ds.status.values) == [s.value for s in curve.status]  # names, not codes


def test_xarray_round_trips_through_a_dict(curve):
    import xarray as xr

    ds = curve.to_xarray()
    back = xr.Dataset.from_dict(ds.to_dict())
    xr.testing.assert_identical(back, ds)
    np.testing.assert_array_equal(ds.to_dataframe()["mu_ratio"].to_numpy(), curve.mu_ratio)


def test_several_axes_keep_their_shape_in_xarray_and_c_order_in_pandas(grid):
    ds = grid.to_xarray()
    assert ds.mu_ratio.dims == ("point_0", "point_1") and ds.mu_ratio.shape == (2, 3)
    np.testing.assert_array_equal(ds.mu_ratio.values, grid.mu_ratio)
    df = grid.to_dataframe()
    assert list(df.index.names) == ["point_0", "point_1"] and len(df) == 6
    np.testing.assert_array_equal(df.mu_ratio.to_numpy(), grid.mu_ratio.ravel())
    assert df.loc[(1, 1), "status"] == Status.STATIC.value == grid[1, 1].status.value
    assert "6 points, shape (2, 3)" in repr(grid)


def test_history_tables_carry_every_array_with_the_schema_units():
    h = vf.simulate(SYSTEM, vbar=0.3, periods=1)
    ds = h.to_xarray()
    assert ds.sizes["sample"] == h.tau.size and ds.sizes["event"] == len(h.events)
    np.testing.assert_array_equal(ds.tau.values, h.tau)
    np.testing.assert_array_equal(ds.f.values, h.f)
    for name in ("tau", "x", "x_dot", "f", "n", "e", "work_input", "dissipated_friction"):
        assert ds[name].attrs["units"] == HISTORY_FIELD[name].unit, name
    assert HISTORY_FIELD["x_dot"].unit == FIELD["x_dot"].unit  # the result's quantity
    assert list(ds.event_tau.values) == [e.tau for e in h.events]
    assert list(ds.event_after.values) == [e.after for e in h.events]
    assert float(ds.v_inertial) == h.v_inertial
    assert float(ds.final_y) == h.final_state.y
    df = h.to_dataframe()
    assert len(df) == h.tau.size and df.index.name == "sample"
    assert list(df.columns) == ["tau", "x", "x_dot", "f", "n", "phase", "e", "work_input",
                                "dissipated_pin", "dissipated_contact", "dissipated_friction"]
    assert isinstance(df.phase.dtype, pd.CategoricalDtype)
    assert list(df.phase.astype(str)) == list(h.phase)
    assert df.attrs["units"]["work_input"] == HISTORY_FIELD["work_input"].unit


def test_plane_history_splits_its_pairs_into_components():
    h = vf.simulate(vf.Dimensionless(0.5, 2.0, 0.5, a_y=0.3), v_inertial=0.3, periods=1)
    ds = h.to_xarray()
    assert ds.slip_velocity.dims == ("sample", "component")
    assert list(ds.component.values) == ["x", "y"]
    assert ds.plane_state.dims == ("plane_component",)
    df = h.to_dataframe()
    np.testing.assert_array_equal(df.impulse_y.to_numpy(), h.impulse[:, 1])
    np.testing.assert_array_equal(df.u_y.to_numpy(), h.u_y)
    assert df.attrs["units"]["slip_velocity_x"] == HISTORY_FIELD["slip_velocity"].unit


def test_curved_history_has_its_spring_row_as_names():
    h = vf.simulate(vf.Dimensionless(0.5, 2.0, 0.5, profile_exponent=2.0), v_inertial=0.3,
                    periods=1)
    ds = h.to_xarray()
    assert ds.spring_state.dims == ("sample", "spring") and ds.sizes["spring"] == h.xi.size
    np.testing.assert_array_equal(ds.xi.values, h.xi)
    names = np.asarray(["stick", "slip+", "slip-", "flight"])[h.spring_state]
    np.testing.assert_array_equal(ds.spring_state.values, names)
    assert ds.xi.attrs["units"] == HISTORY_FIELD["xi"].unit
    assert "event" not in ds.sizes  # a curved tip's states hold its transitions
    assert f"row of {h.xi.size} springs" in repr(h)
