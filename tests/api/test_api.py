"""The public API: shapes, units, validation and the command line."""

import dataclasses
import json
import math
import subprocess
import sys

import numpy as np
import pytest

import vibrofriction as vf


def test_scalar_in_result_out_array_in_arrays_out(general_system):
    r = vf.friction_coefficient(general_system, vbar=0.3)
    assert isinstance(r, vf.FrictionResult) and isinstance(r.mu_ratio, float)
    c = vf.friction_coefficient(general_system, vbar=np.linspace(0, 1.2, 7).reshape(7))
    assert isinstance(c, vf.FrictionResults) and c.mu_ratio.shape == (7,)
    grid = vf.friction_coefficient(general_system, vbar=np.full((2, 3), 0.4))
    assert grid.mu_ratio.shape == (2, 3)
    assert grid[1, 2].mu_ratio == vf.friction_coefficient(general_system, vbar=0.4).mu_ratio
    assert c[2].mu_ratio == c.mu_ratio[2]
    assert [x.mu_ratio for x in c] == list(c.mu_ratio)


def _fields(r):
    """Every field of a result with its type (floats by their bits)."""
    return {f.name: (type(v), v.hex() if isinstance(v, float) else v)
            for f in dataclasses.fields(r) for v in [getattr(r, f.name)]}


STARVED = vf.SolverSettings(max_events=3)  # FAILED, not trusted


@pytest.mark.parametrize(("system", "kw"), [
    (vf.Dimensionless(0.5, 2.0, 0.5), dict(vbar=0.3)),
    (vf.Dimensionless(0.5, 2.0, 0.5), dict(vbar=np.float64(1.5))),
    (vf.Dimensionless(0.5, 2.0, 0.5), dict(vbar=0.3, initial="rest")),
    (vf.Dimensionless(0.5, 2.0, 0.5), dict(vbar=0.3, settings=STARVED)),
    (vf.Dimensionless(0.5, math.inf, 1.5), dict(vbar=0.4)),
    (vf.Dimensionless(0.5, 2.0, 0.5, zeta=0.05, eta_c=0.1), dict(v_inertial=0.2)),
    (vf.Dimensionless(0.5, 1.0, 0.5), dict(v_inertial=0.3)),
])
def test_one_point_is_the_array_path_bit_for_bit(system, kw):
    """The scalar fast path (the kernel's scalar entry, results built without __init__)
    gives the object the array path and the dataclasses' checked constructors give."""
    one = vf.friction_coefficient(system, **kw)
    velocity = {k: [v] for k, v in kw.items() if k in ("vbar", "v_inertial")}
    many = vf.friction_coefficient(system, **{**kw, **velocity})
    assert _fields(one) == _fields(many[0])
    assert _fields(one) == _fields(dataclasses.replace(one))  # __init__ and its checks
    assert one.final_state == dataclasses.replace(one.final_state)
    assert one.trusted == bool(vf.solver.converged(many.status)[0] and one.error <= 1e-5)
    assert vars(one) == vars(dataclasses.replace(one))
    with pytest.raises(dataclasses.FrozenInstanceError):
        one.mu_ratio = 0.0


def test_one_point_from_a_section_state_is_the_array_path(general_system):
    start = vf.friction_coefficient(general_system, vbar=0.3).final_state
    one = vf.friction_coefficient(general_system, vbar=0.35, initial=start)
    many = vf.friction_coefficient(general_system, vbar=[0.35],
                                   initial=np.array([start], dtype=object))
    assert _fields(one) == _fields(many[0])


def test_scalar_velocities_convert_as_arrays_do(general_system):
    for vbar in (0.0, 0.3, 1.7, np.float64(0.3)):
        V = vf.params.inertial_velocity(general_system, vbar)
        assert type(V) is float
        assert V == general_system.vbar_to_inertial(np.array([vbar]))[0]
    with pytest.raises(ValueError, match="vbar must be finite and >= 0, got nan"):
        vf.params.inertial_velocity(general_system, math.nan)
    with pytest.raises(ValueError, match="vbar is undefined for beta == 1"):
        vf.friction_coefficient(vf.Dimensionless(0.5, 1.0, 0.5), vbar=0.3)
    # the value as a number, not a numpy repr (np.float64(1.0))
    with pytest.raises(ValueError, match=r"v0\* is infinite \(alpha = 1\); use"):
        vf.friction_coefficient(vf.Dimensionless(1.0, math.inf, 0.5), vbar=0.3)
    with pytest.raises(ValueError, match=r"a curved tip at alpha = 4: v0\* is infinite"):
        vf.friction_coefficient(vf.Dimensionless(4.0, 9.0, 0.5, profile_exponent=2.0),
                                vbar=0.3)


def test_trusted_one_is_trusted_for_every_status():
    settings = vf.SolverSettings(tol_trusted=1e-6)
    for status in vf.Status:
        for error in (0.0, 1e-7, 1e-6, 2e-6, math.inf, math.nan):
            assert settings.trusted_one(status, error) is bool(
                settings.trusted(status.code, error)), (status, error)


def test_results_state_their_status_and_accuracy(general_system):
    r = vf.friction_coefficient(general_system, vbar=0.3)
    assert r.status is vf.Status.PERIODIC and r.period == 1 and r.success
    assert "periodic" in r.message and r.error < 1e-9
    assert r.periods >= 1 and r.events > 0
    assert r.vbar == pytest.approx(0.3)
    assert r.final_state.phase in ("stick", "slip+", "slip-")


def test_physical_system_with_dimensional_velocity():
    omega0 = 2 * math.pi * 800.0
    p = vf.Physical(mass=0.01, k_x=0.01 * omega0**2, k_xc=4e5, k_zc=5e5, u_z0=1e-6,
                    du_z=0.5e-6, omega=2 * math.pi * 600.0, mu0=0.3)
    v0 = 0.5 * p.critical_velocity()
    a = vf.friction_coefficient(p, v0=v0)
    b = vf.friction_coefficient(p.to_dimensionless(), vbar=0.5)
    assert a.mu_ratio == pytest.approx(b.mu_ratio, abs=1e-12)


def test_velocity_arguments_are_checked(general_system):
    with pytest.raises(ValueError, match="exactly one"):
        vf.friction_coefficient(general_system)
    with pytest.raises(ValueError, match="exactly one"):
        vf.friction_coefficient(general_system, vbar=0.1, v_inertial=0.1)
    with pytest.raises(ValueError, match="vbar"):
        vf.friction_coefficient(general_system, vbar=-1.0)
    with pytest.raises(ValueError, match="v_inertial"):
        vf.friction_coefficient(general_system, v_inertial=math.nan)
    with pytest.raises(ValueError, match="Physical"):
        vf.friction_coefficient(general_system, v0=1.0)
    with pytest.raises(ValueError, match="v_inertial"):
        vf.friction_coefficient(vf.Dimensionless(1.0, math.inf, 0.5), vbar=0.5)
    with pytest.raises(ValueError, match="initial"):
        vf.friction_coefficient(general_system, vbar=0.5, initial="moving")
    with pytest.raises(TypeError):
        vf.friction_coefficient((0.5, 2.0, 0.5), vbar=0.5)


@pytest.mark.parametrize("kw,match", [({"max_periods": 0}, "max_periods"),
                                      ({"tol_state": 0.0}, "tol_state"),
                                      ({"tol_mean": 2.0}, "tol_mean"),
                                      ({"max_events": -1}, "max_events")])
def test_settings_are_validated(kw, match):
    with pytest.raises(ValueError, match=match):
        vf.SolverSettings(**kw)


def test_simulate_returns_a_sharp_time_history(general_system):
    h = vf.simulate(general_system, vbar=0.3, periods=5)
    assert h.tau[0] == 0 and h.tau[-1] == pytest.approx(10 * math.pi)
    assert np.all(np.diff(h.tau) >= 0)
    assert set(np.unique(h.phase)) <= {"stick", "slip+", "slip-", "flight"}
    assert {e.kind for e in h.events} == {"stick->slip", "slip->stick"}
    # in slip f = n exactly (Fig. 2: the two curves coincide)
    slip = h.phase == "slip+"
    np.testing.assert_allclose(h.f[slip], h.n[slip], rtol=1e-13)
    with pytest.raises(ValueError, match="periods"):
        vf.simulate(general_system, vbar=0.3, periods=0)


def _cli(*args):
    return subprocess.run([sys.executable, "-m", "vibrofriction.cli", *args],
                          capture_output=True, text=True, timeout=300)


@pytest.mark.slow
def test_cli_mu_json_lines():
    out = _cli("mu", "--alpha", "0.5", "--beta", "2", "--amplitude", "0.5",
               "--vbar", "0.3,1.2", "--json")
    assert out.returncode == 0, out.stderr
    rows = [json.loads(line) for line in out.stdout.splitlines()]
    assert len(rows) == 2
    assert rows[0]["status"] == "periodic" and 0.5 < rows[0]["mu_ratio"] < 1
    assert rows[1]["mu_ratio"] == 1.0 and rows[1]["error"] == 0.0
    case4 = _cli("mu", "--alpha", "1", "--beta", "inf", "--amplitude", "0.5",
                 "--v-inertial", "3", "--json")
    assert case4.returncode == 0
    assert json.loads(case4.stdout)["mu_ratio"] == pytest.approx(0.7427, abs=1e-3)


@pytest.mark.slow
def test_cli_mu_exits_3_with_a_count_when_a_point_is_not_trusted():
    # a slow jumping point (tests/solver/test_trust.py's SLOW): not converged within 256 periods
    out = _cli("mu", "--alpha", "0.5343889244565606", "--beta", "2.82801636121696",
               "--amplitude", "2.8253189143838906", "--v-inertial", "0.21615783285176932,5",
               "--max-periods", "256")
    assert out.returncode == 3, out.stderr
    assert "NOT TRUSTED" in out.stdout
    line, = out.stderr.strip().splitlines()
    assert "1 of 2 points are not trusted" in line


@pytest.mark.parametrize("args,needle", [
    (("--alpha", "0.5", "--beta", "0.2", "--amplitude", "0.5", "--vbar", "0.3"), "beta"),
    (("--alpha", "-1", "--beta", "2", "--amplitude", "0.5", "--vbar", "0.3"), "alpha"),
    (("--alpha", "1", "--beta", "inf", "--amplitude", "0.5", "--vbar", "0.3"), "v_inertial"),
    (("--alpha", "0.5", "--beta", "2", "--amplitude", "x", "--vbar", "0.3"), "amplitude"),
])
@pytest.mark.slow
def test_cli_bad_input_exits_2_with_one_line(args, needle):
    out = _cli("mu", *args)
    assert out.returncode == 2
    lines = out.stderr.strip().splitlines()
    assert len(lines) == 1 and needle in lines[0] and "Traceback" not in out.stderr


def test_sweep_is_reachable_from_the_package_without_eager_import():
    code = ("import sys, vibrofriction as vf; assert 'xarray' not in sys.modules; "
            "assert callable(vf.sweep); print('ok')")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=120)
    assert out.returncode == 0, out.stderr


def test_the_version_is_the_one_written_in_pyproject():
    import tomllib
    from pathlib import Path

    pyproject = Path(__file__).resolve().parents[2] / "pyproject.toml"
    assert vf.__version__ == tomllib.loads(pyproject.read_text())["project"]["version"]


def test_the_cli_and_citation_cff_give_that_version():
    import re
    import tomllib
    from pathlib import Path

    root = Path(__file__).resolve().parents[2]
    written = tomllib.loads((root / "pyproject.toml").read_text())["project"]["version"]
    out = _cli("--version")
    assert out.returncode == 0 and out.stdout.strip() == f"vibrofriction {written}", out
    cff = re.search(r"^version: *(\S+)$", (root / "CITATION.cff").read_text(), re.MULTILINE)
    assert cff is not None and cff.group(1) == written
