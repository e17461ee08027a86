"""Every example runs as a user would run it, and pins a number it computes.

The examples are sphinx-gallery scripts (``# %%`` cells, no ``main()``): each is run
once, as ``python -W error examples/NAME.py OUTPUT_DIR`` (a warning is an error, as in
every test), and the tests read what it wrote and the variables it left behind: a
``sitecustomize`` on the script's path (:data:`_KEEP_GLOBALS`) writes the script's globals
(those that pickle) to a file at its exit. One run serves the test that it runs as a
script and the test that pins its numbers (each example used to run twice). Where the
script tests are not selected (``make fast``: they are ``slow``), the numbers' tests run
the example in the test process instead (:func:`runpy.run_path` with that ``sys.argv``).
"""

from __future__ import annotations

import contextlib
import io
import math
import os
import runpy
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

import cloudpickle
import numpy as np
import pytest

import vibrofriction as vf
from vibrofriction import theory

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

#: The ``sitecustomize`` of an example's run: at exit, the globals of ``__main__`` that
#: pickle (cloudpickle: functions of the script by value) into the file the environment
#: names, in the script's own process only (not in a process it starts, which imports this
#: too). Nothing else changes: the script runs as ``python examples/NAME.py`` runs it.
_KEEP_GLOBALS = """
import atexit
import os
import sys


def _keep_globals():
    import cloudpickle

    script, path = os.environ["VIBROFRICTION_EXAMPLE_GLOBALS"].split(os.pathsep)
    if os.path.realpath(sys.argv[0]) != script:  # a process the script started
        return
    kept = {}
    for name, value in vars(sys.modules["__main__"]).items():
        if name.startswith("__"):
            continue
        try:
            kept[name] = cloudpickle.dumps(value)
        except Exception:
            pass
    with open(path, "wb") as f:
        f.write(cloudpickle.dumps(kept))


atexit.register(_keep_globals)
"""


@dataclass
class Run:
    """One example run: the process, its output folder, and its globals."""

    out: subprocess.CompletedProcess
    folder: Path
    globals_file: Path

    def namespace(self) -> dict:
        """The script's globals (those that pickled), for the tests that pin its numbers."""
        assert self.out.returncode == 0, self.out.stderr
        for path in (self.folder, EXAMPLES):  # no absolute paths printed
            assert str(path) not in self.out.stdout, self.out.stdout
        kept = cloudpickle.loads(self.globals_file.read_bytes())
        return {name: cloudpickle.loads(value) for name, value in kept.items()}


class Examples:
    """The runs of the examples, each made once, on first use (the module's fixture)."""

    def __init__(self, tmp_path_factory: pytest.TempPathFactory, scripted: set[str]) -> None:
        self.tmp = tmp_path_factory
        self.scripted = scripted  # the examples whose script test runs in this session
        self.hook = tmp_path_factory.mktemp("keep_globals")
        (self.hook / "sitecustomize.py").write_text(_KEEP_GLOBALS)
        self.runs: dict[str, Run] = {}

    def script(self, name: str) -> Run:
        """``python -W error examples/<name>.py OUT``, its globals kept."""
        if name not in self.runs:
            folder = self.tmp.mktemp(name)
            kept = self.hook / f"{name}.pickle"
            script = (EXAMPLES / f"{name}.py").resolve()
            env = dict(os.environ, VIBROFRICTION_EXAMPLE_GLOBALS=f"{script}{os.pathsep}{kept}",
                       PYTHONPATH=os.pathsep.join(
                           [str(self.hook), *filter(None, [os.environ.get("PYTHONPATH")])]))
            out = subprocess.run([sys.executable, "-W", "error", str(script), str(folder)],
                                 capture_output=True, text=True, timeout=300, cwd=folder,
                                 env=env)
            self.runs[name] = Run(out, folder, kept)
        return self.runs[name]

    def namespace(self, name: str) -> dict:
        """The globals of the example: from its script run where this session runs its
        script test (``make test``), else from a run in this process (``make fast``, where
        the script tests are deselected as slow: no process to start), as
        ``python examples/NAME.py OUT`` would run it (:func:`runpy.run_path`, that
        ``sys.argv``); either way it printed no absolute path."""
        if name in self.scripted:
            return self.script(name).namespace()
        folder = self.tmp.mktemp(name)
        script = EXAMPLES / f"{name}.py"
        argv, sys.argv = sys.argv, [str(script), str(folder)]
        printed = io.StringIO()
        try:
            with contextlib.redirect_stdout(printed):
                namespace = runpy.run_path(str(script), run_name="__main__")
        finally:
            sys.argv = argv
        for path in (folder, EXAMPLES):
            assert str(path) not in printed.getvalue(), printed.getvalue()
        return namespace


@pytest.fixture(scope="module")
def example(request, tmp_path_factory) -> Examples:
    scripted = {item.callspec.params["name"] for item in request.session.items
                if getattr(item, "originalname", "") == "test_example_runs_as_a_script"}
    return Examples(tmp_path_factory, scripted)


def _run(name: str, example: Examples) -> dict:
    """The globals of ``examples/<name>.py``'s run."""
    return example.namespace(name)


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
def test_example_runs_as_a_script(name, pngs, example):
    run = example.script(name)
    run.namespace()  # it ran, printed no absolute path, and left its globals
    for png in pngs:
        assert (run.folder / png).stat().st_size > 20_000, png  # a real figure, not a blank


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


def test_pin_example_numbers(example):
    ns = _run("pin_si_units", example)
    p, cof = ns["PIN"], ns["cof"]
    # eq. (2): at rest the friction is mu0 (1 - a); eq. (12) written out here
    assert cof[0] == pytest.approx(p.mu0 * (1 - p.du_z / p.u_z0), rel=1e-12)
    mw2 = p.mass * p.omega**2
    v_star = p.mu0 * p.omega * p.du_z * p.k_zc / p.k_xc * abs(p.k_x + p.k_xc - mw2) \
        / abs(p.k_x - mw2)
    assert ns["v_star"] == pytest.approx(v_star, rel=1e-12)
    assert cof[0] < cof[1] < p.mu0


def test_resonant_example_reaches_the_energy_balance_plateau(example):
    ns = _run("resonant_case_iv", example)
    assert ns["mu_at_largest_V"][0.5] == pytest.approx(
        float(theory.resonant_plateau_exact(0.5)), abs=1e-3)


@pytest.mark.slow
def test_dask_example_equals_a_serial_sweep(example):
    ns = _run("atlas_on_dask", example)
    serial = vf.sweep(alpha=0.5, beta=np.geomspace(0.6, 20.0, 12), amplitude=0.5,
                      vbar=np.linspace(0.05, 1.2, 24), workers=1, progress=False)
    assert math.isclose(float(ns["ds"]["mu_ratio"].sum()), float(serial["mu_ratio"].sum()),
                        rel_tol=0, abs_tol=0)


@pytest.mark.slow
def test_fit_example_recovers_the_pin(example):
    ns = _run("fit_pin_on_disk", example)
    for name, (value, stderr) in ns["fitted"].items():
        assert abs(value - getattr(ns["TRUE"], name)) <= 3 * stderr, name


def test_design_example_respects_the_limits(example):
    ns = _run("design_oscillation", example)
    system = ns["res"].system
    assert 200 <= ns["frequency_hz"] <= 5000 and 0.05e-6 <= system.du_z <= 0.5e-6
    assert system.omega * system.du_z <= 0.01 * (1 + 1e-9)
    assert ns["res"].cof < 0.3


def test_paper_experiment_prediction_ends_at_the_damped_critical_velocity(example):
    ns = _run("paper_experiment", example)
    for du in ns["AMPLITUDES_UM"]:
        p = ns["pin"](du * 1e-6)
        # rigid contact, alpha = 1: V_c = a/(2 zeta) in units of mu0 F_N0/(m omega)
        v_c = (du * 1e-6 / ns["U_Z0"]) / (2 * p.zeta) * p.mu0 * p.F_N0 / (p.mass * p.omega)
        assert p.critical_velocity() == pytest.approx(v_c, rel=1e-12)
        assert ns["cof_at_1cm_s"][du] < p.mu0


def test_frictional_drive_example(example):
    ns = _run("frictional_drive", example)
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


def test_sphere_example(example):
    ns = _run("sphere_stick_slip", example)
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
