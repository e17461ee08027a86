"""The MDR contact in the public API (issue 21, docs/contact_geometry.md "Using it"):
``profile_exponent`` in Dimensionless, Physical, solve_points, friction_coefficient, the
sweep and the CLI; ``vf.from_bench(..., contact_model="mdr")`` against hand-derived
Hertz and Sneddon formulas; the flat punch unchanged; the refusals name the parameter."""

import json
import math
import subprocess
import sys

import numpy as np
import pytest
from scipy.integrate import quad

import vibrofriction as vf
from vibrofriction import theory
from vibrofriction._kernels.steady import steady_state_many
from vibrofriction.contact import Cone, FlatPunch, Material, PowerLaw, Sphere
from vibrofriction.schema import (
    FLOAT_COLUMNS,
    INT_COLUMNS,
    PARAMETER,
    POINT_COLUMNS,
    column_index,
)
from vibrofriction.solver import solve_points
from vibrofriction.solver.mdr import mdr_friction

STEEL = Material(210e9, 0.3)
GLASS = Material(70e9, 0.22)
#: the kernels' own columns (the contact's four are filled by solve_points)
KERNEL_FLOATS = FLOAT_COLUMNS[:column_index("mean_normal_ratio")]


def _mean_force(a: float, p: float) -> float:
    """``<max(0, 1 + a cos tau)^p>`` by quadrature (independent of theory.py)."""
    return quad(lambda t: max(0.0, 1.0 + a * math.cos(t)) ** p, 0.0, math.pi,
                limit=200, points=[math.acos(-1.0 / a)] if a > 1 else None)[0] / math.pi


# --------------------------------------------------------------------------- flat punch
def test_the_flat_punch_is_the_kernels_output_unchanged():
    """The default (``profile_exponent = inf``) is the seed's model: solve_points returns
    the kernel's own columns bitwise, with and without the exponent given."""
    rng = np.random.default_rng(7)
    n = 24
    al = rng.uniform(0.1, 3.0, n)
    be = al + rng.uniform(0.1, 5.0, n)
    am = rng.uniform(0.0, 2.5, n)
    V = rng.uniform(0.05, 2.0, n)
    ze = np.where(rng.random(n) < 0.3, 0.05, 0.0)
    default = solve_points(al, be, am, V, ze)
    explicit = solve_points(al, be, am, V, ze, profile_exponent=math.inf)
    of = np.full((n, len(FLOAT_COLUMNS)), np.nan)
    oi = np.zeros((n, len(INT_COLUMNS)), dtype=np.int64)
    points = np.zeros((n, len(POINT_COLUMNS)))  # the kernel's packed rows, by hand
    for j, name in enumerate(POINT_COLUMNS):  # the schema's defaults (static_ratio = 1, ...)
        if name in PARAMETER and PARAMETER[name].default is not None:
            points[:, j] = PARAMETER[name].default
    for name, x in (("alpha", al), ("beta", be), ("amplitude", am), ("v_inertial", V),
                    ("zeta", ze), ("profile_exponent", math.inf)):
        points[:, POINT_COLUMNS.index(name)] = x
    steady_state_many(points, 0, np.zeros((n, 4)), np.zeros(n, np.int8), 20000, 64, 1e-10,
                      1e-7, 20_000_000, of, oi)
    for k in KERNEL_FLOATS:
        np.testing.assert_array_equal(default[k], of[:, column_index(k)], err_msg=k)
    for k in INT_COLUMNS:
        np.testing.assert_array_equal(default[k], oi[:, column_index(k)], err_msg=k)
    for k in default:
        np.testing.assert_array_equal(default[k], explicit[k], err_msg=k)
    # the contact's columns: the closed mean force and the time fractions of one spring
    for i in range(n):
        assert default["mean_normal_ratio"][i] == pytest.approx(_mean_force(am[i], 1.0),
                                                                abs=1e-10)
    np.testing.assert_array_equal(default["stick_area_fraction"], default["stick_fraction"])
    np.testing.assert_array_equal(default["slip_area_fraction"],
                                  default["slip_fraction"] + default["reverse_slip_fraction"])
    np.testing.assert_array_equal(default["open_area_fraction"], default["flight_fraction"])


def test_one_flat_point_is_the_batch_engines():
    for a in (0.4, 1.6):
        r = vf.friction_coefficient(vf.Dimensionless(0.5, 2.0, a), v_inertial=0.3)
        cols = solve_points(0.5, 2.0, a, 0.3)
        for k in (*(f for f in FLOAT_COLUMNS if hasattr(r, f)), "status"):
            got = getattr(r, k)
            got = got.code if k == "status" else got
            assert got == cols[k] or (math.isnan(got) and np.isnan(cols[k])), k
        assert r.mean_normal_ratio == (1.0 if a <= 1 else pytest.approx(_mean_force(a, 1.0)))


# --------------------------------------------------------------------------- curved tips
@pytest.mark.parametrize("alpha, beta, a, V, zeta, n", [
    (0.5, 2.0, 0.5, 0.3, 0.0, 2.0),   # sphere
    (1.0, 3.0, 1.4, 0.5, 0.05, 1.0),  # cone, jumping, damped
])
def test_a_curved_tip_is_the_mdr_solvers_value(alpha, beta, a, V, zeta, n):
    system = vf.Dimensionless(alpha, beta, a, zeta=zeta, profile_exponent=n)
    r = vf.friction_coefficient(system, v_inertial=V)
    ref = mdr_friction(alpha, beta, a, V, n, zeta=zeta)
    assert r.mu_ratio == ref["mu_ratio"] and r.error == ref["error"]
    assert ref["status"] == "periodic" and r.status is vf.Status.PERIODIC and r.period == 1
    assert r.trusted and r.error <= 1e-5
    assert r.stick_area_fraction == ref["stick_area_fraction"]
    assert r.slip_area_fraction == ref["slip_area_fraction"]
    assert r.open_area_fraction == ref["open_area_fraction"]
    assert r.stick_area_fraction + r.slip_area_fraction + r.open_area_fraction \
        == pytest.approx(1.0, abs=1e-12)
    assert r.open_area_fraction > 0.0  # the outer ring of the disc lifts off
    assert r.mean_normal_ratio == pytest.approx(_mean_force(a, 1.0 + 1.0 / n), rel=1e-9)
    assert r.final_state is None
    # vbar: V over the tip's critical velocity (tests/mdr/test_mdr_vbar.py)
    assert r.vbar == pytest.approx(V / float(theory.profile_critical_velocity(
        alpha, beta, a, n, zeta)), rel=1e-12)
    # the mirror x -> -x
    back = vf.friction_coefficient(system, v_inertial=-V)
    assert back.mu_ratio == -r.mu_ratio and back.status is r.status


def test_a_curved_tip_at_rest_is_its_static_limit():
    """``V = 0``: the smallest force of the cycle over the mean one (docs: eq. 2's
    analogue), here from a quadrature."""
    a, n = 0.5, 2.0
    r = vf.friction_coefficient(vf.Dimensionless(0.5, 2.0, a, profile_exponent=n),
                                v_inertial=0.0)
    p = 1.0 + 1.0 / n
    assert r.status is vf.Status.STATIC and r.error == 0.0
    assert r.mu_ratio == pytest.approx((1.0 - a) ** p / _mean_force(a, p), rel=1e-9)


def test_mixed_points_route_each_to_its_solver():
    cols = solve_points(0.5, 2.0, 0.5, [0.3, 0.3], profile_exponent=[math.inf, 2.0])
    flat = solve_points(0.5, 2.0, 0.5, 0.3)
    assert cols["mu_ratio"][0] == flat["mu_ratio"]
    assert cols["mu_ratio"][1] == mdr_friction(0.5, 2.0, 0.5, 0.3, 2.0)["mu_ratio"]


# --------------------------------------------------------------------------- from_bench
def _hertz(load, R, E1, nu1, E2, nu2):
    """Hand-derived Hertz-Mindlin: E*, G* (k_x = 8 G* a), d0, a0 at the load."""
    e_star = 1.0 / ((1 - nu1**2) / E1 + (1 - nu2**2) / E2)
    G1, G2 = E1 / (2 * (1 + nu1)), E2 / (2 * (1 + nu2))
    g_star = 1.0 / ((2 - nu1) / G1 + (2 - nu2) / G2)
    d0 = (3.0 * load / (4.0 * e_star * math.sqrt(R))) ** (2.0 / 3.0)  # F = 4/3 E* R^.5 d^1.5
    return e_star, g_star, d0, math.sqrt(R * d0)


BENCH = dict(natural_frequency_hz=800.0, mass=0.01, normal_load=20.0,
             drive_frequency_hz=1000.0, mu0=0.3)


def test_from_bench_sphere_mdr_is_hertz_scaled():
    R, du_z = 3e-3, 0.2e-6
    pin = vf.from_bench(**BENCH, contact=Sphere(R, STEEL, GLASS),
                                 contact_model="mdr", du_z=du_z)
    e_star, g_star, d0, a0 = _hertz(20.0, R, 210e9, 0.3, 70e9, 0.22)
    assert 4.0 / 3.0 * e_star * math.sqrt(R) * d0**1.5 == pytest.approx(20.0, rel=1e-12)
    m, w = 0.01, 2 * math.pi * 1000.0
    k_x = m * (2 * math.pi * 800.0) ** 2
    k_xc0 = 8.0 * g_star * a0  # = 2 G*_mdr a0
    dim = pin.to_dimensionless()
    assert dim.profile_exponent == 2.0 and pin.profile_exponent == 2.0
    assert pin.u_z0 == pytest.approx(d0, rel=1e-12)
    assert pin.k_zc == pytest.approx(2.0 * e_star * a0, rel=1e-12)
    assert pin.k_xc == pytest.approx(k_xc0, rel=1e-12)
    assert pin.F_N0 == pytest.approx(20.0, rel=1e-12)
    assert dim.alpha == pytest.approx(k_x / (m * w**2), rel=1e-12)
    assert dim.beta == pytest.approx((k_x + k_xc0) / (m * w**2), rel=1e-12)
    assert dim.amplitude == pytest.approx(du_z / d0, rel=1e-12)
    assert pin.velocity_unit() == pytest.approx(0.3 * 20.0 / (m * w), rel=1e-12)
    # the linearised sphere: the same tangent stiffnesses, but u_z0 = F/k_zc = 2 d0/3, so
    # the same du_z is 3/2 times the amplitude
    lin = vf.from_bench(**BENCH, contact=Sphere(R, STEEL, GLASS), du_z=du_z)
    assert lin.profile_exponent == math.inf
    assert lin.k_xc == pytest.approx(k_xc0, rel=1e-12)
    assert lin.to_dimensionless().amplitude == pytest.approx(1.5 * du_z / d0, rel=1e-12)
    assert lin == vf.from_bench(**BENCH, contact=Sphere(R, STEEL, GLASS),
                                         du_z=du_z, contact_model="linearised")


def test_from_bench_cone_and_power_law_mdr():
    theta = math.radians(70.0)
    cone = Cone.from_half_angle(theta, STEEL, STEEL)
    pin = vf.from_bench(**BENCH, contact=cone, contact_model="mdr", du_z=1e-7)
    e_star = 1.0 / (2 * (1 - 0.3**2) / 210e9)
    d0 = math.sqrt(20.0 * math.pi / (2.0 * e_star * math.tan(theta)))  # F = 2/pi E* tan d^2
    a0 = 2.0 * d0 * math.tan(theta) / math.pi  # d = pi/2 a cot(theta)
    assert pin.profile_exponent == 1.0
    assert pin.u_z0 == pytest.approx(d0, rel=1e-12)
    assert pin.k_zc == pytest.approx(2.0 * e_star * a0, rel=1e-12)
    assert pin.F_N0 == pytest.approx(20.0, rel=1e-12)
    # a power law with n = 2 and c = 1/(2R) is the sphere
    R = 3e-3
    law = vf.from_bench(**BENCH, contact=PowerLaw(0.5 / R, 2.0, STEEL, STEEL),
                                 contact_model="mdr", du_z=1e-7)
    sph = vf.from_bench(**BENCH, contact=Sphere(R, STEEL, STEEL),
                                 contact_model="mdr", du_z=1e-7)
    for k in ("k_xc", "k_zc", "u_z0", "profile_exponent"):
        assert getattr(law, k) == pytest.approx(getattr(sph, k), rel=1e-12), k


def test_from_bench_flat_punch_mdr_is_the_linearised_flat_punch():
    flat = FlatPunch(1e-3, STEEL, STEEL)
    mdr = vf.from_bench(**BENCH, contact=flat, contact_model="mdr", du_z=1e-7)
    lin = vf.from_bench(**BENCH, contact=flat, du_z=1e-7)
    assert mdr == lin


def test_from_bench_file_takes_a_cone_and_the_contact_model(tmp_path):
    spec = {**BENCH, "du_z": 1e-7, "contact_model": "mdr",
            "contact": {"type": "cone", "slope": 0.5, "pin": {"E": 210e9, "nu": 0.3},
                        "counterface": {"E": 210e9, "nu": 0.3}}}
    path = tmp_path / "bench.json"
    path.write_text(json.dumps(spec))
    pin = vf.from_bench_file(path)
    assert pin == vf.from_bench(**BENCH, du_z=1e-7, contact_model="mdr",
                                         contact=Cone(0.5, STEEL, STEEL))


# --------------------------------------------------------------------------- refusals
SPHERE = dict(alpha=0.5, beta=2.0, amplitude=0.5, profile_exponent=2.0)


@pytest.mark.parametrize("value", [0.0, -1.0, math.nan, "x"])
def test_a_bad_exponent_is_named(value):
    with pytest.raises(ValueError, match="profile_exponent"):
        vf.Dimensionless(0.5, 2.0, 0.5, profile_exponent=value)
    if isinstance(value, float):
        with pytest.raises(ValueError, match="profile_exponent"):
            solve_points(0.5, 2.0, 0.5, 0.3, profile_exponent=value)


@pytest.mark.parametrize("changes, needle", [
    (dict(eta_c=0.1), "eta_c"), (dict(a_y=0.5), "a_y"),
    (dict(beta=math.inf), "beta")])  # a_x: computed (V != 0), tests/mdr/test_mdr_inplane.py
def test_what_the_mdr_solver_does_not_cover_is_refused(changes, needle):
    system = vf.Dimensionless(**{**SPHERE, **changes})
    with pytest.raises(ValueError, match=f"MDR solver.*{needle} = "):
        vf.friction_coefficient(system, v_inertial=0.3)


def test_curved_refusals_elsewhere():
    system = vf.Dimensionless(**SPHERE)
    # vbar is taken (tests/mdr/test_mdr_vbar.py), but not with contact damping, without
    # which the tip's critical velocity is derived
    with pytest.raises(ValueError, match="vbar of a curved tip.*eta_c"):
        vf.friction_coefficient(vf.Dimensionless(**SPHERE, eta_c=0.1), vbar=0.3)
    with pytest.raises(ValueError, match="initial"):
        vf.friction_coefficient(system, v_inertial=0.3, initial="rest")
    assert vf.simulate(system, v_inertial=0.3, periods=1, samples_per_period=8,
                       springs=20).is_curved  # the MDR history (tests/mdr/test_mdr_history.py)
    with pytest.raises(ValueError, match="initial"):
        vf.simulate(system, v_inertial=0.3, initial="rest")
    pin = vf.from_bench(**BENCH, contact=Sphere(3e-3, STEEL, STEEL),
                                 contact_model="mdr", du_z=1e-7)
    # the fit and the design take it now: a = du_z/d0, V in units of mu0 F(d0)/(m omega)
    point = pin.point_arguments(0.01, 1e-7, pin.omega)
    assert point[2] == pytest.approx(1e-7 / pin.u_z0)
    assert point[3] == pytest.approx(0.01 * pin.mass * pin.omega / (pin.mu0 * pin.F_N0))
    with pytest.raises(ValueError, match="dF_N"):
        pin.dF_N  # noqa: B018


@pytest.mark.parametrize("kwargs, needle", [
    (dict(contact_model="hertz"), "contact_model"),
    (dict(normal_control="dead_weight", du_z=1e-5), "too large for the dead weight"),
    (dict(normal_control="load"), "normal_control"),
    (dict(contact=None, k_zc=1e7, k_xc=1e7), "contact_model='mdr' needs a contact"),
    (dict(du_z=None, dF_N=5.0), "dF_N"),
])
def test_from_bench_mdr_refusals_name_the_parameter(kwargs, needle):
    base = dict(BENCH, contact=Sphere(3e-3, STEEL, STEEL), contact_model="mdr", du_z=1e-7)
    with pytest.raises(ValueError, match=needle):
        vf.from_bench(**{**base, **kwargs})


# --------------------------------------------------------------------------- sweep, CLI
def test_sweep_axis_profile_exponent():
    ds = vf.sweep(alpha=0.5, beta=2.0, amplitude=0.5, profile_exponent=[math.inf, 2.0],
                  v_inertial=[0.3], workers=1, progress=False)
    mu = ds["mu_ratio"].sel(v_inertial=0.3)
    assert mu.sel(profile_exponent=math.inf) == solve_points(0.5, 2.0, 0.5, 0.3)["mu_ratio"]
    assert mu.sel(profile_exponent=2.0) == mdr_friction(0.5, 2.0, 0.5, 0.3, 2.0)["mu_ratio"]
    assert "mean_normal_ratio" in ds and "stick_area_fraction" in ds
    # the curved row's critical velocity is the derived one (theory), the flat row's eq. 12
    assert float(ds["critical_velocity"].sel(profile_exponent=2.0)) == \
        theory.profile_critical_velocity(0.5, 2.0, 0.5, 2.0)
    assert float(ds["critical_velocity"].sel(profile_exponent=math.inf)) == \
        pytest.approx(theory.critical_inertial_velocity(0.5, 2.0, 0.5), rel=1e-12)


def test_sweep_curved_store_resumes_without_recomputing(tmp_path, monkeypatch):
    """A finished store with curved rows verifies as done on resume: nothing is solved again
    (a nan critical velocity, where none is derived, must not mark its block unwritten)."""
    import vibrofriction.sweep._compute as compute

    kw = dict(alpha=0.5, beta=2.0, amplitude=0.5, profile_exponent=[2.0, 3.0],
              v_inertial=[0.3], workers=1, progress=False, store=tmp_path / "curved.zarr")
    first = vf.sweep(**kw)

    def no_solving(*args, **kwargs):
        raise AssertionError("a finished block was solved again")

    monkeypatch.setattr(compute, "solve_points", no_solving)
    again = vf.sweep(**kw)
    assert np.array_equal(again["mu_ratio"].values, first["mu_ratio"].values)


def _cli(*args):
    return subprocess.run([sys.executable, "-m", "vibrofriction.cli", *args],
                          capture_output=True, text=True, timeout=300)


@pytest.mark.slow
def test_cli_mu_profile_exponent():
    out = _cli("mu", "--alpha", "0.5", "--beta", "2", "--amplitude", "0.5",
               "--profile-exponent", "2", "--v-inertial", "0.3", "--json")
    assert out.returncode == 0, out.stderr
    row = json.loads(out.stdout)
    assert row["mu_ratio"] == mdr_friction(0.5, 2.0, 0.5, 0.3, 2.0)["mu_ratio"]
    assert row["system"]["profile_exponent"] == 2.0
    assert row["mean_normal_ratio"] == pytest.approx(_mean_force(0.5, 1.5), rel=1e-9)
    bad = _cli("mu", "--alpha", "0.5", "--beta", "2", "--amplitude", "0.5",
               "--profile-exponent", "0", "--v-inertial", "0.3")
    assert bad.returncode == 2 and "profile_exponent" in bad.stderr


def test_docs_contact_geometry_code_runs():
    """The python block of docs/contact_geometry.md runs as written; what it states."""
    from pathlib import Path

    text = (Path(__file__).resolve().parents[2] / "docs" / "contact_geometry.md").read_text()
    blocks = [b.split("```", 1)[0] for b in text.split("```python\n")[1:]]
    assert blocks
    ns: dict = {}
    for block in blocks:
        exec(compile(block, "docs/contact_geometry.md", "exec"), ns)
    r, r_lin, pin, lin = ns["r"], ns["r_lin"], ns["pin"], ns["lin"]
    assert r.trusted and r_lin.trusted and r.v_inertial == pytest.approx(r_lin.v_inertial)
    assert lin.to_dimensionless().amplitude == pytest.approx(
        1.5 * pin.to_dimensionless().amplitude, rel=1e-12)
    assert r.mean_normal_ratio > 1.0 and r_lin.mean_normal_ratio == 1.0
    assert ns["sphere"][0].status is vf.Status.STATIC and ns["sphere"][1].trusted
    # "In-plane oscillation along the sliding": the values it states
    assert ns["rx"].mu_ratio == pytest.approx([-0.27147156, 0.58492601], abs=1e-8)


@pytest.mark.parametrize(("kwargs", "message"), [
    (dict(tol=-1.0), r"^tol must be finite and > 0, got -1.0$"),
    (dict(tol=0.0), r"^tol must be finite and > 0, got 0.0$"),
    (dict(tol=math.nan), r"^tol must be finite and > 0, got nan$"),
    (dict(tol=math.inf), r"^tol must be finite and > 0, got inf$"),
    (dict(tol="1e-5"), r"^tol must be a real number or an array of them \(finite and > 0\)"),
    (dict(tol=True), r"^tol must be a real number .* not a bool"),
    (dict(n_springs=2.7), r"^n_springs must be a whole number >= 1 \(such as 3 or 3.0\), "
                          r"got 2.7$"),
    (dict(n_springs=0), r"^n_springs must be a whole number >= 1 .*got 0$"),
    (dict(n_springs=True), r"^n_springs must be a whole number >= 1 .*got True$"),
    (dict(n_springs="20"), r"^n_springs must be a whole number >= 1 .*got '20'$"),
    (dict(n_springs=math.nan), r"^n_springs must be a whole number"),
])
def test_the_mdr_entry_refuses_a_bad_tolerance_or_spring_count(kwargs, message):
    """``tol = -1`` or nan ended the doubling at once, ``n_springs = 2.7`` ran 2 springs."""
    from vibrofriction.solver.mdr import mdr_friction, mdr_row

    with pytest.raises(ValueError, match=message):
        mdr_friction(0.5, 2.0, 0.5, 0.3, 2.0, **kwargs)
    if "n_springs" in kwargs:
        with pytest.raises(ValueError, match=message):
            mdr_row(0.5, 2.0, 0.5, 0.3, 2.0, kwargs["n_springs"])


def test_the_mdr_entry_takes_an_integral_float_spring_count():
    from vibrofriction.solver.mdr import mdr_friction

    three = mdr_friction(0.5, 2.0, 0.5, 0.3, 2.0, n_springs=3.0)
    assert three["rows"] == (3, 6)
    same = mdr_friction(0.5, 2.0, 0.5, 0.3, 2.0, n_springs=3)
    assert (three["mu_ratio"], three["error"]) == (same["mu_ratio"], same["error"])
