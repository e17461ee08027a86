"""Every example runs as a user would run it, and pins a number it computes."""

from __future__ import annotations

import importlib.util
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import vibrofriction as vf
from vibrofriction import theory

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _load(name: str):
    spec = importlib.util.spec_from_file_location(name, EXAMPLES / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.mark.parametrize("name,pngs", [
    ("pin_si_units", ["pin_si_units.png"]),
    ("resonant_case_iv", ["resonant_case_iv.png"]),
    pytest.param("atlas_on_dask", ["atlas_map.png", "atlas_curves.png"],
                 marks=pytest.mark.slow),
    ("design_oscillation", ["design_oscillation.png"]),
    ("paper_experiment", ["paper_experiment.png"]),
    pytest.param("fit_pin_on_disk", ["fit_pin_on_disk.png"], marks=pytest.mark.slow),
])
@pytest.mark.slow
def test_example_runs_as_a_script(name, pngs, tmp_path):
    out = subprocess.run([sys.executable, str(EXAMPLES / f"{name}.py"), str(tmp_path)],
                         capture_output=True, text=True, timeout=300, cwd=tmp_path)
    assert out.returncode == 0, out.stderr
    for png in pngs:
        assert (tmp_path / png).stat().st_size > 20_000, png  # a real figure, not a blank


def test_pin_example_numbers(tmp_path):
    ex = _load("pin_si_units")
    got = ex.main(tmp_path)
    p = ex.PIN
    # eq. (2): at rest the friction is mu0 (1 - a); eq. (12) written out here
    assert got["cof_at_rest"] == pytest.approx(p.mu0 * (1 - p.du_z / p.u_z0), rel=1e-12)
    mw2 = p.mass * p.omega**2
    v_star = p.mu0 * p.omega * p.du_z * p.k_zc / p.k_xc * abs(p.k_x + p.k_xc - mw2) \
        / abs(p.k_x - mw2)
    assert got["v_star"] == pytest.approx(v_star, rel=1e-12)
    assert got["cof_at_rest"] < got["cof_slowest"] < p.mu0


def test_resonant_example_reaches_the_energy_balance_plateau(tmp_path):
    got = _load("resonant_case_iv").main(tmp_path)
    assert got["mu_at_largest_V_a0.5"] == pytest.approx(
        float(theory.resonant_plateau_exact(0.5)), abs=1e-3)


@pytest.mark.slow
def test_dask_example_equals_a_serial_sweep(tmp_path):
    got = _load("atlas_on_dask").main(tmp_path)
    serial = vf.sweep(alpha=0.5, beta=np.geomspace(0.6, 20.0, 12), amplitude=0.5,
                      vbar=np.linspace(0.05, 1.2, 24), workers=1, progress=False)
    assert math.isclose(got["mu_sum"], float(serial["mu_ratio"].sum()), rel_tol=0,
                        abs_tol=0)


@pytest.mark.slow
def test_fit_example_recovers_the_pin(tmp_path):
    ex = _load("fit_pin_on_disk")
    got = ex.main(tmp_path)
    for name, (value, stderr) in got.items():
        assert abs(value - getattr(ex.TRUE, name)) <= 3 * stderr, name


def test_design_example_respects_the_limits(tmp_path):
    got = _load("design_oscillation").main(tmp_path)
    assert 200 <= got["frequency_hz"] <= 5000 and 0.05e-6 <= got["du_z"] <= 0.5e-6
    assert got["velocity_amplitude"] <= 0.01 * (1 + 1e-9)
    assert got["cof"] < 0.3


def test_paper_experiment_prediction_ends_at_the_damped_critical_velocity(tmp_path):
    ex = _load("paper_experiment")
    got = ex.main(tmp_path)
    for du in ex.AMPLITUDES_UM:
        p = ex.pin(du * 1e-6)
        # rigid contact, alpha = 1: V_c = a/(2 zeta) in units of mu0 F_N0/(m omega)
        v_c = (du * 1e-6 / ex.U_Z0) / (2 * p.zeta) * p.mu0 * p.F_N0 / (p.mass * p.omega)
        assert got[f"v_star_{du:g}um"] == pytest.approx(v_c, rel=1e-12)
        assert got[f"cof_at_0.01_{du:g}um"] < p.mu0
