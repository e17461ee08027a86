"""One schema, one status vocabulary, one velocity conversion (issue 18, the house).

Each consumer of the result vocabulary is checked against :mod:`vibrofriction.schema`:
a field added there and not carried by a consumer fails here.
"""

from __future__ import annotations

import ast
import dataclasses
import json
import math
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given
from hypothesis import settings as hypothesis_settings
from hypothesis import strategies as st

import vibrofriction as vf
from vibrofriction import schema
from vibrofriction.params import inertial_velocity
from vibrofriction.schema import (
    FIELD,
    FLOAT_COLUMNS,
    INT_COLUMNS,
    MODELS,
    PARAMETER,
    PARAMETERS,
    RESULT_FIELDS,
    Status,
    parameter_names,
)

SRC = Path(vf.__file__).parent
POINT = vf.Dimensionless(0.5, 2.0, 0.5)


# --------------------------------------------------------------------------- the schema
def test_schema_is_standard_library_only() -> None:
    imported = set()
    for path in (SRC / "schema").glob("*.py"):
        tree = ast.parse(path.read_text())
        imported |= {alias.name.split(".")[0] for node in ast.walk(tree)
                     if isinstance(node, ast.Import) for alias in node.names}
        imported |= {node.module.split(".")[0] for node in ast.walk(tree)
                     if isinstance(node, ast.ImportFrom) and node.module and not node.level}
    assert imported <= {"__future__", "enum", "dataclasses"}, imported


def test_every_field_has_a_unit_a_long_name_and_a_known_kind() -> None:
    assert len({f.name for f in schema.FIELDS}) == len(schema.FIELDS)
    for f in schema.FIELDS:
        assert f.kind in ("float", "int", "bool", "str", "object"), f
        assert f.long_name and len(f.long_name) > 10, f
        assert f.role in ("result", "state", "kernel"), f
        assert f.kind in ("object", "str") or f.unit, f  # every number has a unit ("1": none)
    assert FIELD["mu_ratio"].equation == "(25)"


def test_kernel_indices_come_from_the_schema() -> None:
    """The kernels' output constants are the schema's columns, in the kernels' order."""
    import importlib
    import pkgutil

    import vibrofriction._kernels as kernels
    from vibrofriction._kernels import codes

    modules = [importlib.import_module(f"vibrofriction._kernels.{m.name}")
               for m in pkgutil.iter_modules(kernels.__path__)]

    names = {"O_MU": "mu_ratio", "O_ERR": "error", "O_STICK": "stick_fraction",
             "O_SLIP": "slip_fraction", "O_SLIP_NEG": "reverse_slip_fraction",
             "O_FLIGHT": "flight_fraction", "O_Y": "y", "O_XD": "x_dot", "O_F": "f",
             "O_MULT": "multiplier", "O_SETTLE": "settling_periods", "O_WMIN": "window_min",
             "O_WMAX": "window_max", "O_DRIFT": "drift_rate", "O_E": "e"}
    for const, name in names.items():
        assert getattr(codes, const) == FLOAT_COLUMNS.index(name), const
        for m in modules:  # no kernel module keeps a copy of its own
            assert getattr(m, const, getattr(codes, const)) == getattr(codes, const), m
    for const, name in {"I_STATUS": "status", "I_PERIOD": "period", "I_PERIODS": "periods",
                        "I_EVENTS": "events", "I_PHASE": "phase",
                        "I_DEGENERATE": "degenerate"}.items():
        assert getattr(codes, const) == INT_COLUMNS.index(name), const
        for m in modules:
            assert getattr(m, const, getattr(codes, const)) == getattr(codes, const), m
    assert vf.solver.FLOAT_COLUMNS is FLOAT_COLUMNS and vf.solver.INT_COLUMNS is INT_COLUMNS


def test_solve_points_returns_every_kernel_column() -> None:
    out = vf.solver.solve_points(0.5, 2.0, 0.5, [0.0, 0.3])
    assert set(out) == {*FLOAT_COLUMNS, *INT_COLUMNS, "trusted"}


# --------------------------------------------------------------------------- status
def test_every_status_carries_its_code_and_message() -> None:
    from vibrofriction._kernels import codes

    assert {s.code for s in Status} == set(schema.STATUS_BY_CODE)
    for s in Status:
        assert len(s.message) > 30 and s.value
        assert Status.from_code(s.code) is s and Status(s.value) is s
        assert vf.solver.STATUS_BY_CODE[s.code] is s
    assert set(schema.CONVERGED_CODES) == {s.code for s in Status if s.ok}
    assert {s for s in Status if not s.ok} == {Status.NOT_CONVERGED, Status.FAILED, Status.HELD}
    assert (codes.ST_PERIODIC, codes.ST_AVERAGED, codes.ST_NOT_CONVERGED, codes.ST_FAILED,
            codes.ST_SLIDING, codes.ST_STATIC) == tuple(
        s.code for s in (Status.PERIODIC, Status.AVERAGED, Status.NOT_CONVERGED,
                         Status.FAILED, Status.SLIDING, Status.STATIC))
    with pytest.raises(ValueError, match="unknown status code 7"):
        Status.from_code(7)
    assert vf.Status is Status


def test_converged_and_trusted_agree_for_codes_and_members() -> None:
    codes = np.array([s.code for s in Status])
    members = np.array(list(Status), dtype=object)
    expected = np.array([s.ok for s in Status])
    np.testing.assert_array_equal(vf.solver.converged(codes), expected)
    np.testing.assert_array_equal(vf.solver.converged(members), expected)
    settings = vf.SolverSettings(tol_trusted=1e-6)
    err = np.where(expected, 1e-7, 0.0)
    np.testing.assert_array_equal(settings.trusted(codes, err), expected)
    np.testing.assert_array_equal(settings.trusted(codes, np.full(codes.size, 1e-5)),
                                  np.zeros(codes.size, bool))


# --------------------------------------------------------------------------- consumers
def test_friction_result_fields_are_the_schema() -> None:
    names = tuple(f.name for f in RESULT_FIELDS)
    assert tuple(f.name for f in dataclasses.fields(vf.FrictionResult)) == names
    assert tuple(f.name for f in dataclasses.fields(vf.FrictionResults)) == names
    r = vf.friction_coefficient(POINT, vbar=0.5)
    assert r.trusted and set(r.as_dict()) == set(names)
    for f in RESULT_FIELDS:
        assert f.name in vf.FrictionResult.__doc__, f.name
    rs = vf.friction_coefficient(POINT, vbar=np.array([0.0, 0.5]))
    assert rs[1].mu_ratio == r.mu_ratio and rs[0].status is Status.STATIC


@pytest.mark.slow
def test_cli_json_prints_every_field() -> None:
    out = subprocess.run([sys.executable, "-m", "vibrofriction.cli", "mu", "--alpha", "0.5",
                          "--beta", "inf", "--amplitude", "0.5", "--vbar", "0,0.5", "--json"],
                         capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    static, moving = (json.loads(line) for line in out.stdout.splitlines())
    for row in (static, moving):
        assert {f.name for f in RESULT_FIELDS} <= set(row), set(row)
        assert {"vbar", "message"} <= set(row)
    r = vf.friction_coefficient(vf.Dimensionless(0.5, math.inf, 0.5), vbar=0.5)
    assert moving["mu_ratio"] == r.mu_ratio and moving["status"] == r.status.value
    assert moving["system"]["beta"] == "inf" and moving["final_state"]["phase"] in (
        "stick", "slip+", "slip-")
    for row in (static, moving):  # every parameter of the dimensionless model, by value,
        # then its choices
        assert list(row["system"]) == [*parameter_names("dimensionless"),
                                       *schema.choice_names("dimensionless")]
        assert row["system"]["inplane_on"] == "substrate"
        assert row["system"]["alpha"] == 0.5 and row["system"]["eta_c"] == 0.0
    assert static["final_state"] is None and static["status"] == "static limit"
    assert moving["window_min"] is None  # nan as null: not averaged


def test_sweep_variables_carry_every_schema_field_with_its_unit() -> None:
    from vibrofriction.sweep._variables import point_variables

    for velocity in ("vbar", "v_inertial"):
        variables = {v.name: v for v in point_variables(velocity)}
        for f in schema.FIELDS:
            if f.role == "kernel" or f.kind == "object" and f.name != "status":
                continue
            name = f"final_{f.name}" if f.role == "state" else f.name
            if name == "v_inertial" and velocity == "v_inertial":
                continue  # the coordinate
            var = variables.pop(name)
            assert var.dtype == f.dtype and var.attrs["long_name"].endswith(f.long_name)
            if f.name not in ("status", "trusted", "phase"):  # flags have no unit
                assert var.attrs["units"] == f.unit, name
        assert not variables, variables  # nothing the schema does not define


def test_sweep_dataset_has_every_field_with_its_unit() -> None:
    ds = vf.sweep(alpha=0.5, beta=2.0, amplitude=0.5, vbar=[0.0, 0.5], workers=1,
                  progress=False)
    for f in RESULT_FIELDS:
        if f.dtype and f.name != "status" and f.name != "trusted":
            assert ds[f.name].attrs["units"] == f.unit, f.name
    assert ds.status.attrs["flag_values"][1:] == sorted(schema.STATUS_BY_CODE)
    r = vf.friction_coefficient(POINT, vbar=0.5)
    assert float(ds.mu_ratio.sel(vbar=0.5)) == r.mu_ratio


def test_figure_curves_hold_every_solver_column() -> None:
    from vibrofriction.figures.series import CURVE_COLUMNS, Curve, series_at_vbar, solve

    assert set(CURVE_COLUMNS) == {*FLOAT_COLUMNS, *INT_COLUMNS, "trusted"}
    s = series_at_vbar("k", 0.5, 2.0, 0.5, [0.0, 0.5])
    c = solve([s])["k"]
    for name in CURVE_COLUMNS:
        assert getattr(c, name).shape == (2,), name
    assert c.mu_ratio[1] == vf.friction_coefficient(POINT, vbar=0.5).mu_ratio
    with pytest.raises(ValueError, match="lacks the columns"):
        Curve(s, {"mu_ratio": c.mu_ratio})
    with pytest.raises(ValueError, match="unknown curve columns"):
        Curve.of(s, mu=c.mu_ratio)


def test_explorer_curve_holds_every_result_field() -> None:
    from vibrofriction.explorer import compute
    from vibrofriction.explorer.state import State

    curve = compute.curve(State(alpha=0.5, beta=2.0, amplitude=0.5, axis="vbar", v_max=1.0,
                                points=3))
    for f in RESULT_FIELDS:
        if f.name not in ("final_state", "system"):
            assert len(curve[f.name]) == 3, f.name
    r = vf.friction_coefficient(POINT, vbar=0.5)
    assert curve["mu_ratio"][1] == r.mu_ratio and curve["status"][1] == r.status.value


# --------------------------------------------------------------------------- velocity
def test_velocity_conversion_round_trips() -> None:
    pin = vf.Physical(mass=0.01, k_x=2.5e5, k_xc=2e5, k_zc=2.5e5, u_z0=4e-6, du_z=2e-6,
                      omega=6283.0, mu0=0.3)
    dim = pin.to_dimensionless()
    vbar = np.array([0.0, 0.3, 1.7])
    V = inertial_velocity(pin, vbar)
    np.testing.assert_allclose(V, vbar * dim.critical_inertial_velocity(), rtol=1e-15)
    v0 = pin.inertial_to_v0(V)
    np.testing.assert_allclose(v0, vbar * pin.critical_velocity(), rtol=1e-12)
    np.testing.assert_allclose(inertial_velocity(pin, v0=v0), V, rtol=1e-14)
    np.testing.assert_allclose(inertial_velocity(dim, v_inertial=V), V, rtol=0)
    np.testing.assert_allclose(dim.inertial_to_vbar(inertial_velocity(pin, v0=v0)), vbar,
                               rtol=1e-12, atol=1e-300)
    assert inertial_velocity(dim, v_inertial=0.25) == 0.25
    assert pin.velocity_unit() * pin.mass * pin.omega == pytest.approx(pin.mu0 * pin.F_N0)
    np.testing.assert_allclose(pin.v0_to_inertial(0.01, np.array([pin.omega, 2 * pin.omega])),
                               [pin.v0_to_inertial(0.01), 2 * pin.v0_to_inertial(0.01)],
                               rtol=1e-15)


@pytest.mark.parametrize(("kwargs", "message"), [
    ({}, "give exactly one velocity.*got none"),
    ({"vbar": 0.5, "v_inertial": 0.3}, "give exactly one velocity.*got vbar and v_inertial"),
    ({"vbar": 0.5, "v0": 0.3}, "got vbar and v0"),
    ({"vbar": -0.5}, "vbar must be finite and >= 0, got -0.5"),
    ({"v_inertial": math.inf}, "v_inertial must be finite, got inf"),
    ({"v_inertial": [0.1, np.nan]}, "v_inertial must be finite, got nan"),
    ({"v0": 0.1}, "v0 \\(m/s\\) needs a Physical system"),
])
def test_velocity_conversion_refuses_none_two_and_bad_values(kwargs, message) -> None:
    with pytest.raises(ValueError, match=message):
        inertial_velocity(POINT, **kwargs)
    with pytest.raises(ValueError, match=message):
        vf.friction_coefficient(POINT, **kwargs)


def test_vbar_is_refused_where_it_does_not_exist() -> None:
    with pytest.raises(ValueError, match="vbar is undefined for alpha == 1"):
        inertial_velocity(vf.Dimensionless(1.0, 3.0, 0.5), vbar=0.5)
    with pytest.raises(TypeError, match="system must be a Dimensionless or Physical"):
        inertial_velocity("not a system", v_inertial=[0.5])


def test_one_name_for_the_critical_velocity() -> None:
    """``V_c`` is ``critical_inertial_velocity`` everywhere; the old aliases are gone, and
    no module outside params uses the private velocity unit."""
    from vibrofriction import params, theory

    assert not hasattr(theory, "inertial_per_vbar")
    assert not hasattr(vf.Dimensionless, "inertial_per_vbar")
    assert not hasattr(params, "vbar_factor")
    for path in SRC.rglob("*.py"):
        text = path.read_text()
        assert "_velocity_unit" not in text, path
        assert "inertial_per_vbar" not in text, path


def test_the_sweep_fingerprint_covers_the_solver_and_the_schema() -> None:
    """A store is resumed only by the same solver: every file that computes values counts."""
    from vibrofriction.sweep import _compute

    root = SRC
    hashed = {p.resolve() for pattern in _compute._VALUE_SOURCES for p in root.glob(pattern)}
    for module in [*(SRC / "solver").rglob("*.py"), *(SRC / "schema").glob("*.py"),
                   SRC / "capabilities.py"]:
        assert module.resolve() in hashed, module
    assert all(any(root.glob(pattern)) for pattern in _compute._VALUE_SOURCES)


# --------------------------------------------------------------------------- parameters
def test_every_parameter_is_described() -> None:
    assert len(PARAMETER) == len(PARAMETERS)
    for p in PARAMETERS:
        assert set(p.models) <= set(MODELS) and p.unit and p.symbol and p.equation, p
        assert len(p.long_name) > 10, p
        r = p.range
        # every one is bounded but a phase and the signed velocities: any finite real
        if p.name in ("phase_x", "phase_y", "v_inertial", "v0"):
            assert r == schema.FINITE, p
        else:
            assert r.minimum is not None or r.maximum is not None, p
        if r.above:  # checked after the parameter it must exceed
            assert parameter_names(p.model).index(r.above) < parameter_names(
                p.model).index(p.name), p
    assert PARAMETER["beta"].range.above == "alpha" and PARAMETER["beta"].range.allow_inf
    assert PARAMETER["k_xc"].range.allow_inf and PARAMETER["k_xc"].range.strict
    assert set(parameter_names("velocity")) == {"vbar", "v_inertial", "v0"}
    with pytest.raises(ValueError, match="model must be one of"):
        schema.parameters("geometry")


@pytest.mark.parametrize(("cls", "model"), [(vf.Dimensionless, "dimensionless"),
                                            (vf.Physical, "physical")])
def test_model_dataclasses_are_the_schema(cls, model) -> None:
    """Every field of Dimensionless and Physical is a schema parameter of its model, in
    the schema's order, with the schema's default (None: required), followed by the
    model's choices (``schema.CHOICES``: names, not numbers, e.g. ``inplane_on``) with
    theirs; Physical ends with its friction law (an object: ``RateAndState`` or None, whose own
    fields are the schema's ``rs_*`` once scaled)."""
    fields = [f for f in dataclasses.fields(cls) if f.name != "friction"]
    assert cls is not vf.Physical or dataclasses.fields(cls)[-1].name == "friction"
    choices = schema.choice_names(model)
    numeric = fields[:len(fields) - len(choices)]
    assert tuple(f.name for f in numeric) == parameter_names(model)
    assert tuple(f.name for f in fields[len(numeric):]) == choices
    for f in numeric:
        default = None if f.default is dataclasses.MISSING else f.default
        assert default == PARAMETER[f.name].default, f.name
    for name in choices:
        c = schema.CHOICES[name]
        assert cls.__dataclass_fields__[name].default == c.default in c.values
        with pytest.raises(ValueError, match=f"{name} must be one of"):
            dataclasses.replace(cls(**BASES[model]), **{name: "nowhere"})


def _bad_values(r: schema.Range, margin: float) -> list[float]:
    """Values outside the range ``r`` (``margin > 0`` away from a bound, or on it)."""
    bad = [math.nan]
    if not r.allow_inf:
        bad.append(math.inf)
    if r.minimum is not None:
        bad += [r.minimum - margin, -math.inf] + ([r.minimum] if r.strict else [])
    if r.maximum is not None:
        bad.append(r.maximum + margin)
    return bad


def _good_values(r: schema.Range, margin: float) -> list[float]:
    lo = r.minimum if r.minimum is not None else -1.0
    hi = r.maximum if r.maximum is not None else lo + 2.0 * margin + 1.0
    good = [min(lo + margin, hi)] + ([lo] if not r.strict else [])
    return good + ([math.inf] if r.allow_inf else [])


BASES = {"dimensionless": dict(alpha=0.5, beta=2.0, amplitude=0.5),
         "physical": dict(mass=0.01, k_x=2.5e5, k_xc=2e5, k_zc=2.5e5, u_z0=4e-6,
                          du_z=2e-6, omega=6283.0, mu0=0.3)}


@given(margin=st.floats(1e-9, 1e9, allow_nan=False, allow_infinity=False),
       index=st.integers(0, len(PARAMETERS) - 1))
@hypothesis_settings(max_examples=150, deadline=None)
def test_validator_refuses_every_out_of_range_value(margin: float, index: int) -> None:
    """For each schema parameter, values just outside its range (and nan, inf where not
    allowed) are refused by ``validated``, by its dataclass and by ``solve_points``, each
    with the sentence naming the parameter, the schema's range and the value; values
    inside pass."""
    from vibrofriction.validation import validated

    p = PARAMETERS[index]
    own = dataclasses.replace(p.range, above="")  # alone, without the one it must exceed
    for bad in _bad_values(own, margin):
        message = re.escape(f"{p.name} must be {own.text()}, got {bad!r}")
        with pytest.raises(ValueError, match=message):
            validated({p.name: bad})
        with pytest.raises(ValueError, match=message):  # inside an array
            validated({p.name: np.array([_good_values(own, margin)[0], bad])})
    for good in _good_values(own, margin):
        assert validated({p.name: good})[p.name] == good
    if p.range.above:  # beta: not above alpha
        low = 0.5
        for bad in (low, low - margin, math.nan, -math.inf):
            message = re.escape(f"{p.name} must be {p.range.text(low)}, got {bad!r}")
            with pytest.raises(ValueError, match=message):
                validated({p.range.above: low, p.name: bad})
            with pytest.raises(ValueError, match=message):
                vf.Dimensionless(**{**BASES["dimensionless"], p.range.above: low,
                                    p.name: bad})
        assert validated({p.range.above: low, p.name: low + margin})[p.name] == low + margin
        return
    if p.model in BASES:  # the dataclass refuses it with the same sentence
        cls = vf.Dimensionless if p.model == "dimensionless" else vf.Physical
        for bad in _bad_values(p.range, margin):
            with pytest.raises(ValueError, match=re.escape(f"{p.name} must be "
                                                           f"{p.range.text()}, got {bad!r}")):
                cls(**{**BASES[p.model], p.name: bad})
    if p.name in (*parameter_names("dimensionless"), "v_inertial"):
        point = dict(alpha=0.5, beta=2.0, amplitude=0.5, v_inertial=0.3)
        bad = _bad_values(p.range, margin)[-1]
        with pytest.raises(ValueError, match=re.escape(f"{p.name} must be")):
            vf.solver.solve_points(**{**point, p.name: np.array([point.get(p.name, 0.0),
                                                                 bad])})


@given(index=st.integers(0, len(PARAMETERS) - 1),
       value=st.one_of(st.floats(-1e3, 1e3), st.sampled_from([0.0, 1.0, -1.0, 0.5, 2.0, 5.0,
                                                              math.inf, -math.inf, math.nan]),
                       st.integers(-3, 3)),
       other=st.sampled_from([0.5, 2.0, math.inf, math.nan]))
@hypothesis_settings(max_examples=300, deadline=None)
def test_plain_numbers_are_checked_as_arrays_are(index: int, value: float,
                                                 other: float) -> None:
    """``validated`` takes one plain number (``float``, ``int``) by a shortcut; the answer
    is the array path's (``np.float64``, a 1-element array): the same value, or the same
    refusal, alone, above the parameter it must exceed, and with a friction-law partner."""
    from vibrofriction.validation import validated

    p = PARAMETERS[index]
    partners = [{}]
    if p.range.above:
        partners.append({p.range.above: other})
    partners += [{q: other} for q in ("rs_a", "rs_b", "amplitude") if q != p.name]

    def outcome(values: dict) -> tuple:
        try:
            return ("ok", {k: np.asarray(v).ravel().tolist()
                           for k, v in validated(values).items()})
        except ValueError as exc:
            return ("refused", str(exc))

    for partner in partners:
        plain = outcome({**partner, p.name: value})
        for wrapped in (np.float64(value), np.array([value], dtype=float)):
            assert outcome({**partner, p.name: wrapped}) == plain
        if plain[0] == "ok":
            assert validated({**partner, p.name: value})[p.name].shape == ()


def test_optional_parameters_default_to_their_twin() -> None:
    """``k_y``, ``c_y``, ``alpha_y``, ``zeta_y`` (``Parameter.twin``): None is the twin's
    value in the validator; the dataclasses keep the None, so that a copy with another
    ``k_x`` stays axisymmetric; a given value is checked like any other."""
    from vibrofriction.validation import validated

    twins = {p.name: p.twin for p in PARAMETERS if p.twin}
    assert twins == {"alpha_y": "alpha", "zeta_y": "zeta", "k_y": "k_x", "c_y": "c_x",
                     "mu_static": "mu0"}
    out = validated({"alpha": np.array([0.5, 2.0]), "alpha_y": None})
    np.testing.assert_array_equal(out["alpha_y"], [0.5, 2.0])
    with pytest.raises(ValueError, match="k_y = None means the value of k_x"):
        validated({"k_y": None})
    pin = vf.Physical(**BASES["physical"])
    assert (pin.k_y, pin.c_y) == (None, None) and pin.pin_y == (pin.k_x, pin.c_x)
    stiffer = pin.with_(k_x=2 * pin.k_x)
    assert stiffer.pin_y[0] == 2 * pin.k_x  # still axisymmetric
    d = stiffer.to_dimensionless()
    assert (d.alpha_y, d.zeta_y) == (None, None) and d.pin_y == (d.alpha, d.zeta)
    # k_y given: alpha_y = k_y/(m omega^2), zeta_y = c_y/(2 sqrt(k_y m)) with c_y = c_x
    aniso = vf.Physical(**BASES["physical"], c_x=3.0, k_y=1e5)
    d = aniso.to_dimensionless()
    m, w = BASES["physical"]["mass"], BASES["physical"]["omega"]
    assert d.alpha_y == pytest.approx(1e5 / (m * w**2), rel=1e-15)
    assert d.zeta_y == pytest.approx(3.0 / (2 * math.sqrt(1e5 * m)), rel=1e-15)
    assert d.zeta_y != d.zeta
    with pytest.raises(ValueError, match=re.escape("c_y must be finite and >= 0, got -1.0")):
        vf.Physical(**BASES["physical"], c_y=-1.0)
    bench = vf.from_bench(natural_frequency_hz=1000.0, normal_load=1.0,
                                   drive_frequency_hz=2000.0, mu0=0.3, mass=0.01, k_zc=1e7,
                                   k_xc=1e7, du_z=1e-7, k_y=2e5, damping_ratio_y=0.05)
    assert bench.k_y == 2e5 and bench.c_y == pytest.approx(2 * 0.05 * math.sqrt(2e5 * 0.01))


def test_validator_names_unknown_parameters_and_keeps_the_callers_order() -> None:
    from vibrofriction.validation import validated

    with pytest.raises(ValueError, match=r"unknown model parameter\(s\) \['gamma'\]"):
        validated({"alpha": 0.5, "gamma": 1.0})
    assert list(validated({"beta": 2.0, "alpha": 0.5})) == ["beta", "alpha"]
    # a closed form's own domain replaces the schema's range
    with pytest.raises(ValueError, match=r"amplitude must be finite and in \[0, 1\], got 1.5"):
        validated({"amplitude": 1.5}, ranges={"amplitude": schema.Range(0.0, maximum=1.0)})


@pytest.mark.slow
def test_sweep_parameters_and_coordinates_are_the_schema() -> None:
    """The sweep's parameter names and every coordinate's units and long name come from
    the schema, for a dimensionless and a physical grid."""
    from vibrofriction.sweep import _grid, make_plan
    from vibrofriction.sweep._dataset import template

    # the optional parameters (the pin across the sliding) are not swept, and a system
    # that gives one is refused, not swept as if axisymmetric
    assert _grid.DIMENSIONLESS == parameter_names("dimensionless", optional=False)
    assert _grid.PHYSICAL == parameter_names("physical", optional=False)
    # mu_static (the twin of mu0): an axis of its own where given (docs/sweeps.md)
    assert set(parameter_names("physical")) - set(_grid.PHYSICAL) == {"k_y", "c_y",
                                                                     _grid.MU_STATIC}
    with pytest.raises(ValueError, match="not axisymmetric yet"):
        make_plan(system=vf.Physical(**BASES["physical"], k_y=1e5), v0=[0.01])
    with pytest.raises(ValueError, match=r"not axisymmetric yet \(zeta_y given\)"):
        make_plan(system=vf.Dimensionless(0.5, 2.0, 0.5, zeta_y=0.1), v_inertial=[0.1])
    pin = vf.Physical(**BASES["physical"])
    for plan in (make_plan(alpha=[0.1, 0.2], beta=2.0, amplitude=0.5, vbar=[0.5]),
                 make_plan(alpha=0.1, beta=2.0, amplitude=[0.5], v_inertial=0.5),
                 make_plan(system=pin, v0=[0.001, 0.01], physical={"mass": [0.01, 0.02]})):
        ds = template(plan, None)
        names = (parameter_names(plan.kind, optional=False) + (plan.velocity.name,)
                 + (parameter_names("dimensionless", optional=False)
                    if plan.kind == "physical" else ()))
        assert set(names) <= set(ds.coords), (names, list(ds.coords))
        for name in names:
            p = PARAMETER[name]
            assert ds[name].attrs["units"] == p.unit, name
            assert ds[name].attrs["long_name"] == p.long_name, name
            assert ds[name].attrs["equation"] == p.equation, name
