"""``vibrofriction sweep`` and the local friction laws: the law's parameters as axes
(``--static-ratio``, ``--rs-a`` ...; ``--mu-static`` of a physical sweep), ``--rs-law`` one
for the grid, a physical set-up's rate-and-state law held (``--friction-a`` ...); nothing
given is ignored."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import vibrofriction as vf
import vibrofriction.cli.sweep as cli_sweep
from vibrofriction.cli import run

PHYS = ("--mass", "0.01", "--k-x", "2.5e5", "--k-xc", "2e5", "--k-zc", "2.5e5", "--u-z0",
        "4e-6", "--du-z", "2e-6", "--omega", "6283", "--mu0", "0.3")
SYSTEM = ("--alpha", "0.1", "--beta", "2", "--amplitude", "0.5")
LAW_SI = ("--friction-a", "0.006", "--friction-b", "0.009", "--friction-d-c", "2e-7",
          "--friction-v-ref", "1e-3")


def _run(capsys, *args: str) -> tuple[int, str, str]:
    code = run(["sweep", *args, "--out", "x.zarr", "--workers", "1", "--no-progress"])
    out = capsys.readouterr()
    return code, out.out, out.err


def _refused(capsys, *args: str) -> str:
    code, out, err = _run(capsys, *args)
    assert code == 2, (out, err)
    lines = err.strip().splitlines()
    assert len(lines) == 1 and err.startswith("error: "), err
    return lines[0]


@pytest.fixture
def grid(monkeypatch, tmp_path: Path) -> dict:
    """What the command would sweep (the sweep itself is not run)."""
    monkeypatch.chdir(tmp_path)
    seen: dict = {}

    def capture(grid, options, *, scheduler, workers):
        seen.update(grid=grid, options=options)
        raise cli_sweep.Exit(0)

    monkeypatch.setattr(cli_sweep, "_run", capture)
    return seen


def test_the_laws_axes_and_rs_law_reach_the_sweep(capsys, grid) -> None:
    code, _, err = _run(capsys, *SYSTEM, "--rs-a", "0.02,0.04", "--rs-b", "0:0.03:4",
                        "--rs-d-c", "0.05", "--rs-v-ref", "0.2", "--rs-alpha-ld", "1e-3",
                        "--rs-law", "slip", "--v-inertial", "0.2")
    assert code == 0, err
    g = grid["grid"]
    assert np.array_equal(g["rs_a"], [0.02, 0.04])
    assert np.array_equal(g["rs_b"], np.linspace(0.0, 0.03, 4))
    assert (g["rs_d_c"], g["rs_v_ref"], g["rs_alpha_ld"], g["rs_law"]) == (0.05, 0.2, 1e-3,
                                                                          "slip")
    code, _, err = _run(capsys, *SYSTEM, "--static-ratio", "1,1.5,2", "--v-inertial", "0.2")
    assert code == 0, err
    assert np.array_equal(grid["grid"]["static_ratio"], [1.0, 1.5, 2.0])
    assert "rs_law" not in grid["grid"]  # not given: the sweep's default


def test_a_physical_sweep_takes_mu_static_and_holds_the_rate_and_state_law(capsys,
                                                                           grid) -> None:
    code, _, err = _run(capsys, *PHYS, *LAW_SI, "--friction-alpha-ld", "1e-4", "--rs-law",
                        "slip", "--du-z", "1e-6,2e-6", "--v0", "0.01")
    assert code == 0, err
    system = grid["grid"]["system"]
    assert system.friction == vf.RateAndState(a=0.006, b=0.009, d_c=2e-7, v_ref=1e-3,
                                              alpha_ld=1e-4, law="slip")
    assert np.array_equal(grid["grid"]["du_z"], [1e-6, 2e-6])
    g = dict(grid["grid"])  # the plan carries the law
    plan = vf.sweep.make_plan(system=g.pop("system"), v0=g.pop("v0"),
                              rs_law=g.pop("rs_law", None), physical=g)
    assert plan.friction == system.friction and plan.rs_law == "slip"
    # the law's own SI parameters as axes: the system's law has the first values
    code, _, err = _run(capsys, *PHYS, "--friction-a", "0.006", "--friction-b", "0.009",
                        "--friction-d-c", "1e-7:4e-7:3", "--friction-v-ref", "1e-3,2e-3",
                        "--v0", "0.01")
    assert code == 0, err
    g = grid["grid"]
    assert np.array_equal(g["friction_d_c"], np.linspace(1e-7, 4e-7, 3))
    assert np.array_equal(g["friction_v_ref"], [1e-3, 2e-3])
    assert g["system"].friction == vf.RateAndState(a=0.006, b=0.009, d_c=1e-7, v_ref=1e-3)
    code, _, err = _run(capsys, *PHYS, "--mu-static", "0.3,0.45", "--v0", "0.01")
    assert code == 0, err
    assert np.array_equal(grid["grid"]["mu_static"], [0.3, 0.45])
    assert grid["grid"]["system"].mu_static == 0.3 and grid["grid"]["system"].friction is None


@pytest.mark.parametrize(("args", "words"), [
    ((*SYSTEM, "--v-inertial", "0.2", "--rs-law", "slip"), "--rs-law needs --rs-a or "
                                                           "--friction-a"),
    ((*SYSTEM, "--v-inertial", "0.2", "--rs-b", "0.01"), "--rs-b needs --rs-a"),
    ((*SYSTEM, "--v-inertial", "0.2", "--rs-a", "0,0.02", "--rs-b", "0.01"),
     "rs_b > 0 needs rs_a > 0 (rs_a = 0 is Coulomb friction): got rs_b = 0.01 with rs_a = 0"),
    ((*SYSTEM, "--v-inertial", "0.2", "--static-ratio", "1,1.5", "--rs-a", "0,0.02"),
     "static_ratio > 1 is a law of Coulomb friction"),
    ((*SYSTEM, "--v-inertial", "0.2", "--static-ratio", "0.5"),
     "--static-ratio (static_ratio) must be finite and >= 1, got 0.5"),
    ((*SYSTEM, "--vbar", "0.5", "--rs-a", "0.02"), "vbar (v0/v0* of eq. 16) is not defined "
                                                   "for rate-and-state friction"),
    ((*SYSTEM, "--v-inertial", "0.2", "--mu-static", "0.4"),
     "give either the dimensionless parameters (--alpha, --beta, --amplitude, --v-inertial) "
     "or the physical ones (--mu-static)"),
    ((*SYSTEM, "--v-inertial", "0.2", "--friction-a", "0.01"), "or the physical ones "
                                                                "(--friction-a)"),
    ((*PHYS, "--v0", "0.01", "--static-ratio", "1.5"), "give either the dimensionless "
                                                       "parameters (--static-ratio)"),
    ((*PHYS, "--v0", "0.01", "--rs-law", "slip"), "--rs-law needs --rs-a or --friction-a"),
    ((*PHYS, "--v0", "0.01", "--friction-b", "0.01"), "--friction-b needs --friction-a"),
    ((*PHYS, "--v0", "0.01", "--friction-a", "0.01"),
     "rate-and-state friction (--friction-a) needs --friction-d-c, --friction-v-ref"),
    ((*PHYS, "--v0", "0.01", "--mu-static", "0.2,0.4"), "mu_static must be >= mu0 (= 0.3"),
    ((*PHYS, "--v0", "0.01", *LAW_SI[2:], "--friction-a", "0.01,0"),
     "--friction-a (friction_a) must be finite and > 0, got 0"),
    ((*PHYS, "--v0", "0.01", *LAW_SI, "--friction-alpha-ld", "1e-3", "--friction-b", "0,1e-2"),
     "alpha_ld = 0.001 > 0 needs b > 0"),
    ((*PHYS, "--v0", "0.01", *LAW_SI, "--mu-static", "0.4"),
     "mu_static is a law of Coulomb friction"),
    ((*PHYS, "--v0", "0.01", *LAW_SI, "--profile-exponent", "2"),
     "does not take rate-and-state friction (rs_a > 0): got rs_a = 0.02 in the grid"),
])
def test_friction_options_are_refused_rather_than_ignored(capsys, tmp_path, monkeypatch,
                                                          args, words) -> None:
    monkeypatch.chdir(tmp_path)
    line = _refused(capsys, *args)
    assert words in line, line
    assert not (tmp_path / "x.zarr").exists()


def test_a_static_ratio_atlas_from_the_command_line(capsys, tmp_path, monkeypatch) -> None:
    monkeypatch.chdir(tmp_path)
    code, out, err = _run(capsys, *SYSTEM, "--static-ratio", "1,1.5", "--v-inertial",
                          "0.15,0.3")
    assert code in (0, 3), err
    assert "4 points (static_ratio 2 x v_inertial 2)" in out
    stored = vf.sweep.open_atlas(tmp_path / "x.zarr")
    ref = vf.sweep(alpha=0.1, beta=2.0, amplitude=0.5, static_ratio=[1.0, 1.5],
                   v_inertial=[0.15, 0.3], workers=1, progress=False)
    assert stored.mu_ratio.values.tobytes() == ref.mu_ratio.values.tobytes()
    assert stored.attrs["rs_law"] == "aging"
    # below V_c = 0.29 (above it, undamped, stick-slip and sliding coexist: not converged)
    one = vf.friction_coefficient(vf.Dimensionless(0.1, 2.0, 0.5, static_ratio=1.5),
                                  v_inertial=0.15)
    assert math.isfinite(one.mu_ratio)
    assert float(stored.mu_ratio.sel(static_ratio=1.5, v_inertial=0.15)) == one.mu_ratio
    assert not math.isnan(one.mu_ratio)
