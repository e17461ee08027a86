"""The bench on the command line: mu --bench, fit, design (docs/bench.md)."""

import json
import subprocess
import sys

import numpy as np
import pandas as pd
import pytest
import xarray as xr

import vibrofriction as vf
from vibrofriction.bench import predict_cof

BENCH = {"natural_frequency_hz": 800, "mass": 0.01, "quality_factor": 50, "normal_load": 20,
         "contact": {"type": "sphere", "radius": 0.003, "pin": {"E": 210e9, "nu": 0.3},
                     "counterface": {"E": 210e9, "nu": 0.3}},
         "drive_frequency_hz": 1000, "dF_N": 10, "mu0": 0.3}


def _cli(*args: str, cwd=None) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "vibrofriction.cli", *args], cwd=cwd,
                          capture_output=True, text=True, timeout=600)


@pytest.fixture
def bench_file(tmp_path):
    path = tmp_path / "bench.json"
    path.write_text(json.dumps(BENCH))
    return path


@pytest.mark.slow
def test_mu_for_a_bench_file(bench_file):
    out = _cli("mu", "--bench", str(bench_file), "--v0", "0.01", "--json")
    assert out.returncode == 0, out.stderr
    row = json.loads(out.stdout)
    pin = vf.from_bench_file(bench_file)
    assert row["mu_ratio"] == pytest.approx(vf.friction_coefficient(pin, v0=0.01).mu_ratio,
                                            abs=1e-12)
    bad = _cli("mu", "--bench", str(bench_file) + ".missing", "--v0", "0.01")
    assert bad.returncode == 2 and "no bench file" in bad.stderr


@pytest.mark.slow
def test_fit_from_the_command_line(bench_file, tmp_path):
    pin = vf.from_bench_file(bench_file)
    v0 = np.geomspace(1e-3, 0.1, 12)
    cof = predict_cof(pin, v0, np.full(12, pin.du_z), np.full(12, pin.omega))
    csv = tmp_path / "m.csv"
    pd.DataFrame({"v0 [mm/s]": v0 * 1e3, "cof": cof, "du_z [um]": pin.du_z * 1e6,
                  "omega [Hz]": 1000.0, "sigma": 1e-4}).to_csv(csv, index=False)
    out = _cli("fit", str(csv), "--bench", str(bench_file), "--free", "mu0", "--fix",
               "mu0=0.4", "--out", str(tmp_path / "fit"), "--no-progress")
    assert out.returncode == 0, out.stderr
    saved = json.loads((tmp_path / "fit" / "fit.json").read_text())
    assert saved["params"]["mu0"]["value"] == pytest.approx(0.3, rel=1e-6)
    assert saved["quality"] == "good" and out.stdout.startswith("GOOD FIT")
    # what the data hold, in the report's second line, as in the API's report
    assert out.stdout.splitlines()[1] == "what the data hold: mu0 determined"
    assert saved["determination"] == {"mu0": "determined"}
    for figure in ("fit.png", "profiles.png"):
        assert (tmp_path / "fit" / figure).stat().st_size > 0
    bad = _cli("fit", str(csv), "--bench", str(bench_file), "--free", "mu0,oops")
    assert bad.returncode == 2 and "free must name" in bad.stderr


@pytest.mark.slow
def test_design_from_the_command_line(bench_file, tmp_path):
    out = _cli("design", "--bench", str(bench_file), "--v0", "0.01", "--frequency-hz",
               "300:3000", "--du-z", "0:5e-7", "--max-velocity-amplitude", "0.005",
               "--out", str(tmp_path / "design"))
    assert out.returncode == 0, out.stderr
    assert "optimum at v0 = 0.01" in out.stdout
    status = [line for line in out.stdout.splitlines() if line.startswith("status: ")]
    assert len(status) == 1 and "map points within the limits untrusted" in status[0]
    assert (tmp_path / "design" / "map.png").stat().st_size > 0
    saved = xr.open_zarr(tmp_path / "design" / "map.zarr", consolidated=False)
    assert saved.du_z.values[0] == 0.0  # the actuator's range from rest
    assert saved.attrs["n_untrusted"] == int((saved.feasible & ~saved.trusted).sum())
    assert saved.attrs["status"] in status[0]
    assert status[0].startswith("status: trusted") == (saved.attrs["n_untrusted"] == 0)
    bad = _cli("design", "--bench", str(bench_file), "--v0", "0.01", "--frequency-hz", "300",
               "--du-z", "1e-7:5e-7")
    assert bad.returncode == 2 and "low:high" in bad.stderr
    bad = _cli("design", "--bench", str(bench_file), "--v0", "0.01", "--frequency-hz",
               "300:3000", "--du-z", "0:5e-7", "--goal", "drive")
    assert bad.returncode == 2 and "needs an in-plane oscillation" in bad.stderr


@pytest.mark.slow
def test_inplane_drive_design_from_the_command_line(bench_file, tmp_path):
    out = _cli("design", "--bench", str(bench_file), "--v0", "0.002", "--frequency-hz",
               "300:3000", "--du-z", "0:5e-7", "--du-x", "0:4e-6", "--goal", "drive",
               "--max-velocity-amplitude", "0.03", "--out", str(tmp_path / "drive"))
    assert out.returncode == 0, out.stderr
    assert "largest drive force at v0 = 0.002" in out.stdout
    assert "blocking force" in out.stdout and "which direction" in out.stdout
    saved = xr.open_zarr(tmp_path / "drive" / "map.zarr", consolidated=False)
    assert saved.cof.dims == ("omega", "du_z", "du_x", "phase_x")
    assert saved.attrs["goal"] == "drive"


@pytest.mark.slow
def test_fit_from_the_command_line_refuses_a_parameter_a_constraint_holds(bench_file,
                                                                          tmp_path):
    csv = tmp_path / "m.csv"
    pd.DataFrame({"v0": [0.001, 0.01, 0.1], "cof": [0.2, 0.25, 0.28], "du_z": 5e-7,
                  "omega": 6283.0, "sigma": 0.003}).to_csv(csv, index=False)
    bad = _cli("fit", str(csv), "--bench", str(bench_file), "--free", "mu0,mass,k_x",
               "--no-progress")
    assert bad.returncode == 2
    assert "mass and k_x" in bad.stderr
    assert "--no-natural-frequency" in bad.stderr  # the flag that releases it, not the keyword
    assert "natural_frequency=False" not in bad.stderr


@pytest.mark.parametrize("contact, free", [
    ({"type": "sphere", "radius": 3e-3}, ["mu0", "mass", "radius"]),
    ({"type": "cone", "slope": 20.0}, ["mu0", "mass", "E_star"])])
def test_fit_command_passes_a_curved_contact_to_the_fit(tmp_path, monkeypatch, contact, free):
    """A bench file with a curved MDR contact: the fit gets that contact (its geometry is
    what is fitted, docs/bench.md) and, without --free, a free list it can fit."""
    import vibrofriction.bench as bench
    from vibrofriction.cli import run
    from vibrofriction.contact import Cone, Sphere

    steel = {"E": 210e9, "nu": 0.3}
    spec = dict(natural_frequency_hz=800, mass=0.02, normal_load=20, drive_frequency_hz=1000,
                du_z=6e-7, mu0=0.3, contact_model="mdr",
                contact={**contact, "pin": steel, "counterface": steel})
    path = tmp_path / "bench.json"
    path.write_text(json.dumps(spec))
    seen = {}

    class Stop(Exception):
        pass

    def fake_fit(data, guess, **kwargs):
        seen.update(kwargs, guess=guess)
        raise Stop

    monkeypatch.setattr(bench, "fit", fake_fit)
    with pytest.raises(Stop):
        run(["fit", "data.csv", "--bench", str(path)])
    assert seen["free"] == free and seen["guess"].curved
    kind = Sphere if contact["type"] == "sphere" else Cone
    assert isinstance(seen["contact"], kind)
    assert seen["guess"] == vf.from_bench(**{**spec, "contact": seen["contact"]})


FLAT = {"natural_frequency_hz": 800, "mass": 0.01, "quality_factor": 50, "normal_load": 20,
        "k_zc": 2e7, "k_xc": 1.5e7, "drive_frequency_hz": 1000, "du_z": 5e-7, "mu0": 0.3}


@pytest.mark.slow
def test_fit_of_a_friction_law_from_the_command_line(tmp_path):
    """The guess's law from the flags (``--friction-*``, ``--mu-static``), its parameters in
    ``--free``; on the steady rate-and-state table made by the reference
    (tests/data/make_friction_law_bench.py), ``a`` with ``b`` known; a law parameter without
    its law in the guess is refused by name."""
    from pathlib import Path

    bench = tmp_path / "flat.json"
    bench.write_text(json.dumps(FLAT))
    data = Path(__file__).resolve().parents[1] / "data" / "rate_state_steady.csv"
    law = ["--friction-a", "0.008", "--friction-b", "0.003", "--friction-d-c", "2e-6",
           "--friction-v-ref", "0.01"]
    out = _cli("fit", str(data), "--bench", str(bench), *law, "--free", "a", "--workers", "1",
               "--out", str(tmp_path / "fit"), "--no-progress")
    assert out.returncode == 0, out.stderr
    saved = json.loads((tmp_path / "fit" / "fit.json").read_text())
    lo, hi = saved["intervals"]["a"]
    assert lo <= 0.006 <= hi and hi - lo < 2e-3
    assert saved["system"]["friction"]["b"] == 0.003
    for free, message in (("mu0,mu_static", "free names mu_static, the static coefficient"),
                          ("a", "parameters of rate-and-state friction, but the guess has none")):
        bad = _cli("fit", str(data), "--bench", str(bench), "--free", free)
        assert bad.returncode == 2 and message in bad.stderr, bad.stderr
    bad = _cli("fit", str(data), "--bench", str(bench), "--mu-static", "0.2", "--free",
               "mu_static")
    assert bad.returncode == 2 and "mu_static must be >= mu0" in bad.stderr, bad.stderr


@pytest.mark.slow
def test_design_of_a_pin_with_a_friction_law_from_the_command_line(tmp_path):
    """``--mu-static`` reaches the design: its map is the library's for that pin, and the
    report names the law; a rate-and-state pin's in-plane design is refused by name."""
    bench = tmp_path / "flat.json"
    bench.write_text(json.dumps(FLAT))
    ranges = ("--v0", "0.01", "--frequency-hz", "300:3000", "--du-z", "0:5e-7")
    out = _cli("design", "--bench", str(bench), *ranges, "--mu-static", "0.4", "--out",
               str(tmp_path / "design"))
    assert out.returncode == 0, out.stderr
    assert "local friction: static above kinetic, mu_static = 0.4, mu0 = 0.3" in out.stdout
    table = out.stdout.split("sensitivity (COF):")[1].splitlines()
    assert any(line.strip().startswith("mu_static +") for line in table), out.stdout
    saved = xr.open_zarr(tmp_path / "design" / "map.zarr", consolidated=False)
    # the map is the static pin's: corners of it against the library's solver at that pin
    pin = vf.from_bench_file(bench).with_(mu_static=0.4)
    omega, du_z = saved.omega.values[[0, -1]], saved.du_z.values[[1, -1]]
    W, D = np.meshgrid(omega, du_z, indexing="ij")
    ref = vf.bench.predict_cof(pin, np.full(W.shape, 0.01), D, W) / pin.mu0
    got = saved.mu_ratio.sel(omega=omega, du_z=du_z).transpose("omega", "du_z").values
    np.testing.assert_allclose(got, ref, rtol=0, atol=1e-9)
    coulomb = vf.bench.predict_cof(vf.from_bench_file(bench), np.full(W.shape, 0.01), D, W)
    assert np.max(np.abs(ref * pin.mu0 - coulomb)) > 1e-3  # the law changed the map here
    bad = _cli("design", "--bench", str(bench), *ranges, "--du-x", "0:1e-6", "--friction-a",
               "0.008", "--friction-b", "0.003", "--friction-d-c", "2e-6", "--friction-v-ref",
               "0.01")
    assert bad.returncode == 2 and "rate-and-state friction" in bad.stderr, bad.stderr
