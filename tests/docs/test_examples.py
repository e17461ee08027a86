"""Every example runs as a user would run it, and pins a number it computes.

The examples are sphinx-gallery scripts (``# %%`` cells, no ``main()``): each is run
here as ``python examples/NAME.py OUTPUT_DIR`` would run it (:func:`runpy.run_path`
with that ``sys.argv``), and the test reads the variables it left behind.
"""

from __future__ import annotations

import math
import runpy
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import vibrofriction as vf
from vibrofriction import theory

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _run(name: str, out: Path, monkeypatch: pytest.MonkeyPatch,
         capsys: pytest.CaptureFixture[str]) -> dict:
    """Run ``examples/<name>.py out`` in this process; its globals. What it printed
    names no absolute path (the output directory is given, not printed)."""
    script = EXAMPLES / f"{name}.py"
    monkeypatch.setattr(sys, "argv", [str(script), str(out)])
    namespace = runpy.run_path(str(script), run_name="__main__")
    printed = capsys.readouterr().out
    assert str(out) not in printed and str(EXAMPLES) not in printed, printed
    return namespace


@pytest.mark.parametrize("name,pngs", [
    ("pin_si_units", ["pin_si_units.png"]),
    ("resonant_case_iv", ["resonant_case_iv.png"]),
    pytest.param("atlas_on_dask", ["atlas_map.png", "atlas_curves.png"],
                 marks=pytest.mark.slow),
    ("design_oscillation", ["design_oscillation.png"]),
    ("paper_experiment", ["paper_experiment.png"]),
    pytest.param("fit_pin_on_disk", ["fit_pin_on_disk.png"], marks=pytest.mark.slow),
    ("frictional_drive", ["frictional_drive.png"]),
    ("sphere_stick_slip", ["sphere_stick_slip.png"]),
])
@pytest.mark.slow
def test_example_runs_as_a_script(name, pngs, tmp_path):
    out = subprocess.run([sys.executable, str(EXAMPLES / f"{name}.py"), str(tmp_path)],
                         capture_output=True, text=True, timeout=300, cwd=tmp_path)
    assert out.returncode == 0, out.stderr
    assert str(tmp_path) not in out.stdout, out.stdout  # no absolute paths printed
    for png in pngs:
        assert (tmp_path / png).stat().st_size > 20_000, png  # a real figure, not a blank


def test_examples_are_gallery_scripts_with_text_between_steps():
    """sphinx-gallery's cell format: a titled docstring, then cells each opened by
    ``# %%`` and a comment explaining the step; no ``main()`` that hides the steps."""
    for script in sorted(EXAMPLES.glob("*.py")):
        text = script.read_text()
        assert text.startswith('"""') and "\n===" in text.split('"""')[1], script.name
        cells = text.split("\n# %%\n")[1:]
        assert len(cells) >= 3, (script.name, len(cells))
        for cell in cells:
            assert cell.startswith("# "), (script.name, cell[:60])
        assert "def main(" not in text, script.name


def test_pin_example_numbers(tmp_path, monkeypatch, capsys):
    ns = _run("pin_si_units", tmp_path, monkeypatch, capsys)
    p, cof = ns["PIN"], ns["cof"]
    # eq. (2): at rest the friction is mu0 (1 - a); eq. (12) written out here
    assert cof[0] == pytest.approx(p.mu0 * (1 - p.du_z / p.u_z0), rel=1e-12)
    mw2 = p.mass * p.omega**2
    v_star = p.mu0 * p.omega * p.du_z * p.k_zc / p.k_xc * abs(p.k_x + p.k_xc - mw2) \
        / abs(p.k_x - mw2)
    assert ns["v_star"] == pytest.approx(v_star, rel=1e-12)
    assert cof[0] < cof[1] < p.mu0


def test_resonant_example_reaches_the_energy_balance_plateau(tmp_path, monkeypatch, capsys):
    ns = _run("resonant_case_iv", tmp_path, monkeypatch, capsys)
    assert ns["mu_at_largest_V"][0.5] == pytest.approx(
        float(theory.resonant_plateau_exact(0.5)), abs=1e-3)


@pytest.mark.slow
def test_dask_example_equals_a_serial_sweep(tmp_path, monkeypatch, capsys):
    ns = _run("atlas_on_dask", tmp_path, monkeypatch, capsys)
    serial = vf.sweep(alpha=0.5, beta=np.geomspace(0.6, 20.0, 12), amplitude=0.5,
                      vbar=np.linspace(0.05, 1.2, 24), workers=1, progress=False)
    assert math.isclose(float(ns["ds"]["mu_ratio"].sum()), float(serial["mu_ratio"].sum()),
                        rel_tol=0, abs_tol=0)


@pytest.mark.slow
def test_fit_example_recovers_the_pin(tmp_path, monkeypatch, capsys):
    ns = _run("fit_pin_on_disk", tmp_path, monkeypatch, capsys)
    for name, (value, stderr) in ns["fitted"].items():
        assert abs(value - getattr(ns["TRUE"], name)) <= 3 * stderr, name


def test_design_example_respects_the_limits(tmp_path, monkeypatch, capsys):
    ns = _run("design_oscillation", tmp_path, monkeypatch, capsys)
    system = ns["res"].system
    assert 200 <= ns["frequency_hz"] <= 5000 and 0.05e-6 <= system.du_z <= 0.5e-6
    assert system.omega * system.du_z <= 0.01 * (1 + 1e-9)
    assert ns["res"].cof < 0.3


def test_paper_experiment_prediction_ends_at_the_damped_critical_velocity(
        tmp_path, monkeypatch, capsys):
    ns = _run("paper_experiment", tmp_path, monkeypatch, capsys)
    for du in ns["AMPLITUDES_UM"]:
        p = ns["pin"](du * 1e-6)
        # rigid contact, alpha = 1: V_c = a/(2 zeta) in units of mu0 F_N0/(m omega)
        v_c = (du * 1e-6 / ns["U_Z0"]) / (2 * p.zeta) * p.mu0 * p.F_N0 / (p.mass * p.omega)
        assert p.critical_velocity() == pytest.approx(v_c, rel=1e-12)
        assert ns["cof_at_1cm_s"][du] < p.mu0


def test_frictional_drive_example(tmp_path, monkeypatch, capsys):
    ns = _run("frictional_drive", tmp_path, monkeypatch, capsys)
    # the solver creeping at V = -+1e-4 settles at the closed form's band edges
    assert np.max(abs(ns["creep"] - np.column_stack([ns["closed"].lower,
                                                     ns["closed"].upper]))) < 5e-3
    # the mirror symmetry of the drive: mu(V, phase + pi) = -mu(-V, phase); V is symmetric
    V, curves = ns["V"], ns["curves"]
    assert np.allclose(V, -V[::-1])
    at_0, at_pi = curves[0.0], curves[math.pi]
    bound = at_0.error + at_pi.error[::-1] + 1e-9
    assert np.all(abs(at_pi.mu_ratio + at_0.mu_ratio[::-1]) <= bound)
    # at phase 0 the band lies above 0 (an actuator): a free slider drifts backwards, at
    # the idle velocity where the friction vanishes
    assert ns["closed"].lower[0] > 0 and ns["idle"] < 0
    at_idle = vf.friction_coefficient(ns["system"](0.0), v_inertial=ns["idle"])
    assert abs(at_idle.mu_ratio) < 1e-4 and at_idle.trusted
    # mu = mu0 above the combined critical velocity, below it less
    above, below = V > ns["v_c"] * 1.001, (V > 0) & (V < ns["v_c"] * 0.999)
    assert np.all(abs(at_0.mu_ratio[above] - 1) <= at_0.error[above] + 1e-9)
    assert np.all(at_0.mu_ratio[below] < 1)


def test_sphere_example(tmp_path, monkeypatch, capsys):
    ns = _run("sphere_stick_slip", tmp_path, monkeypatch, capsys)
    sphere, at, h = ns["sphere"], ns["at"], ns["h"]
    assert sphere.trusted.all()
    # one steady period of the 160-spring history against the converged solver
    assert ns["mu_history"] == pytest.approx(sphere.mu_ratio[at], abs=sphere.error[at] + 1e-5)
    # the map: stuck rings lie inside the stick radius, and no ring outside the contact
    # radius is in contact
    inside = h.xi[None, :] <= h.contact_radius[:, None] + (h.xi[1] - h.xi[0])
    assert np.all((h.spring_state == 3) | inside)
    stuck = h.spring_state == 0
    assert np.all(~stuck | (h.xi[None, :] <= h.stick_radius[:, None] + 1e-12))
    assert {0, 1, 2}.issubset(set(np.unique(h.spring_state)))  # stick and both slips
    # below the sphere's critical velocity friction is reduced, above it mu0
    v_c = ns["SPHERE"].critical_inertial_velocity()
    V = ns["V"]
    assert np.all(sphere.mu_ratio[V < 0.98 * v_c] < 1)
    assert np.all(abs(sphere.mu_ratio[V > 1.02 * v_c] - 1) <= sphere.error[V > 1.02 * v_c]
                  + 1e-6)
    # at low speed the sphere rubs less than the flat punch
    assert np.all(sphere.mu_ratio[V < 0.5] < ns["flat"].mu_ratio[V < 0.5])
