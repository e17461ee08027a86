"""The in-plane oscillation through the public API: Physical (SI), the sweep, the CLI.

The solver's in-plane physics is tested in tests/inplane/test_inplane_solver.py against the
independent reference; here the SI conversion, the critical velocity of the combined
drive in m/s, the mirror symmetry through the sweep, validation and the command line.
"""

from __future__ import annotations

import json
import math
import subprocess
import sys

import numpy as np
import pytest

import vibrofriction as vf
from vibrofriction import Dimensionless, Physical, friction_coefficient, sweep
from vibrofriction.bench import from_bench

#: a pin like tests/bench/test_fit.py's, at 1 kHz, with a 1 um longitudinal oscillation
PIN = dict(mass=0.01, k_x=2.5e5, k_xc=1.5e7, k_zc=2e7, u_z0=1e-6, du_z=5e-7,
           omega=2 * math.pi * 1000.0, mu0=0.3)


def test_physical_inplane_amplitude_is_the_vibration_velocity_in_inertial_units() -> None:
    """``a_x = du_x m omega^2/(mu0 F_N0)`` is also ``omega du_x`` over the velocity unit:
    two routes through different methods give the same number."""
    p = Physical(**PIN, du_x=1e-6, phase_x=1.0, inplane_on="holder")
    d = p.to_dimensionless()
    assert d.a_x == pytest.approx(p.omega * p.du_x / p.velocity_unit(), rel=1e-14)
    assert d.a_x == pytest.approx(p.v0_to_inertial(p.omega * p.du_x), rel=1e-14)
    assert (d.phase_x, d.inplane_on) == (1.0, "holder")
    # no in-plane oscillation: the same dimensionless system as before the fields existed
    assert Physical(**PIN).to_dimensionless() == Dimensionless(
        *Physical(**PIN).groups(PIN["du_z"], PIN["omega"]))


def test_physical_critical_velocity_of_the_combined_drive() -> None:
    """Above ``critical_velocity()`` (m/s) the contact slides continuously (mu = mu0),
    below it it does not; backward, the same at ``phase_x + pi`` (docs/inplane.md)."""
    for on in ("substrate", "holder"):
        p = Physical(**PIN, du_x=2e-6, phase_x=0.7, inplane_on=on)
        vc = p.critical_velocity()
        assert vc > 0.0 and vc != Physical(**PIN).critical_velocity()
        above = friction_coefficient(p, v0=1.02 * vc)
        below = friction_coefficient(p, v0=0.9 * vc)
        assert above.trusted and above.mu_ratio == pytest.approx(1.0, abs=1e-9)
        assert below.trusted and below.mu_ratio < 1.0 - 1e-3
        back = p.with_(phase_x=0.7 + math.pi).critical_velocity()
        assert friction_coefficient(p, v0=-1.02 * back).mu_ratio == pytest.approx(-1.0,
                                                                                abs=1e-9)
        assert friction_coefficient(p, v0=-0.9 * back).mu_ratio > -1.0 + 1e-3


@pytest.mark.parametrize(("changes", "message"), [
    ({"du_x": -1e-6}, r"du_x must be finite and >= 0, got -1e-06"),
    ({"du_x": math.inf}, r"du_x must be finite and >= 0, got inf"),
    ({"phase_x": math.nan}, r"phase_x must be finite, got nan"),
    ({"inplane_on": "disk"}, r"inplane_on must be one of 'substrate', 'holder', got 'disk'"),
])
def test_physical_inplane_validation(changes, message) -> None:
    with pytest.raises(ValueError, match=message):
        Physical(**{**PIN, **changes})


def test_vbar_is_refused_with_an_inplane_oscillation() -> None:
    p = Physical(**PIN, du_x=1e-6)
    for call in (lambda: p.v0_to_vbar(0.01), lambda: p.vbar_to_v0(0.5),
                 lambda: friction_coefficient(p.to_dimensionless(), vbar=0.5),
                 lambda: sweep(Dimensionless(0.5, 2.0, 0.5, a_x=0.2), vbar=[0.5],
                               workers=1, progress=False)):
        with pytest.raises(ValueError, match=r"vbar .* not defined with an in-plane"):
            call()


def test_from_bench_takes_the_inplane_oscillation() -> None:
    p = from_bench(natural_frequency_hz=800.0, normal_load=20.0,
                            drive_frequency_hz=1000.0, mu0=0.3, mass=0.01, k_zc=2e7,
                            k_xc=1.5e7, du_z=5e-7, du_x=1e-6, phase_x=0.5, du_y=2e-6,
                            phase_y=0.25, inplane_on="holder")
    assert (p.du_x, p.phase_x, p.du_y, p.phase_y, p.inplane_on) == (1e-6, 0.5, 2e-6, 0.25,
                                                                    "holder")
    d = p.to_dimensionless()
    assert d.a_y == pytest.approx(2 * d.a_x, rel=1e-14) and d.phase_y == 0.25


def test_sweep_mirror_symmetry_and_mount() -> None:
    """``mu(V; phase_x) = -mu(-V; phase_x + pi)`` over a sweep of signed velocities and
    phases, on the substrate and on the holder; the two mounts differ (alpha != 1/2)."""
    phases = np.array([0.0, 0.9, math.pi, 0.9 + math.pi])
    V = np.array([-0.6, -0.05, 0.05, 0.6])
    out = {}
    for on in ("substrate", "holder"):
        ds = sweep(Dimensionless(0.3, 2.0, 0.5, zeta=0.05), a_x=0.5, phase_x=phases,
                   v_inertial=V, inplane_on=on, workers=1, progress=False)
        assert ds.attrs["inplane_on"] == on and bool(ds.trusted.all())
        mu = ds.mu_ratio.values
        err = ds.error.values
        for i, j in ((0, 2), (1, 3)):  # phase and phase + pi
            np.testing.assert_array_less(np.abs(mu[i] + mu[j][::-1]),
                                         err[i] + err[j][::-1] + 1e-9)
        out[on] = mu
        point = friction_coefficient(Dimensionless(0.3, 2.0, 0.5, zeta=0.05, a_x=0.5,
                                                   phase_x=0.9, inplane_on=on),
                                     v_inertial=-0.05)
        assert point.mu_ratio == mu[1, 1]
    assert np.max(np.abs(out["substrate"] - out["holder"])) > 0.05


@pytest.mark.slow
def test_physical_sweep_over_the_inplane_amplitude() -> None:
    p = Physical(**PIN, phase_x=1.0, inplane_on="holder")
    ds = sweep(p, du_x=[0.0, 1e-6], v0=[-0.01, 0.01], workers=1, progress=False)
    assert ds.mu_ratio.dims == ("du_x", "v0") and float(ds.phase_x) == 1.0
    assert ds.a_x.values[0] == 0.0
    assert ds.a_x.values[1] == pytest.approx(p.with_(du_x=1e-6).to_dimensionless().a_x)
    # without an in-plane oscillation the curve is odd in v0; with one it is not
    mu = ds.mu_ratio.values
    assert mu[0, 0] == pytest.approx(-mu[0, 1], abs=1e-9)
    assert abs(mu[1, 0] + mu[1, 1]) > 1e-3
    assert float(ds.critical_velocity[1]) == pytest.approx(
        p.with_(du_x=1e-6).critical_velocity())


def test_store_remembers_the_mount(tmp_path) -> None:
    kwargs = dict(a_x=0.3, v_inertial=[0.1, 0.2], workers=1, progress=False,
                  store=tmp_path / "a.zarr")
    sweep(Dimensionless(0.5, 2.0, 0.5), **kwargs)
    with pytest.raises(ValueError, match="inplane_on"):
        sweep(Dimensionless(0.5, 2.0, 0.5), inplane_on="holder", **kwargs)


def _cli(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "vibrofriction.cli", *args],
                          capture_output=True, text=True, timeout=300)


@pytest.mark.slow
def test_cli_mu_inplane_signed_velocity() -> None:
    out = _cli("mu", "--alpha", "0.5", "--beta", "2", "--amplitude", "0.5", "--a-x", "0.5",
               "--phase-x", "0.9", "--inplane-on", "holder", "--v-inertial", "-0.05,0.05",
               "--json")
    assert out.returncode == 0, out.stderr
    rows = [json.loads(line) for line in out.stdout.splitlines()]
    d = Dimensionless(0.5, 2.0, 0.5, a_x=0.5, phase_x=0.9, inplane_on="holder")
    assert [r["mu_ratio"] for r in rows] == [
        friction_coefficient(d, v_inertial=v).mu_ratio for v in (-0.05, 0.05)]
    assert rows[0]["system"]["inplane_on"] == "holder" and rows[0]["v_inertial"] == -0.05
    text = _cli("mu", "--alpha", "0.5", "--beta", "2", "--amplitude", "0.5", "--a-x", "0.5",
                "--v-inertial", "1")
    assert "a_x=0.5 phase_x=0 on the substrate (critical velocity" in text.stdout
    bad = _cli("mu", "--alpha", "0.5", "--beta", "2", "--amplitude", "0.5", "--du-x", "1e-6",
               "--v-inertial", "1")
    assert bad.returncode == 2 and "--du-x, --du-y (m) need a physical set-up" in bad.stderr


@pytest.mark.slow
def test_cli_mu_physical_inplane() -> None:
    si = [f"--{k.replace('_', '-')}={v!r}" for k, v in PIN.items()]
    out = _cli("mu", *si, "--du-x", "1e-6", "--phase-x", "1", "--v0", "-0.01", "--json")
    assert out.returncode == 0, out.stderr
    row = json.loads(out.stdout)
    expect = friction_coefficient(Physical(**PIN, du_x=1e-6, phase_x=1.0), v0=-0.01)
    assert row["mu_ratio"] == expect.mu_ratio and row["system"]["a_x"] > 0


@pytest.mark.slow
def test_cli_sweep_inplane(tmp_path) -> None:
    out = _cli("sweep", "--alpha", "0.5", "--beta", "2", "--amplitude", "0.5", "--a-x", "0.5",
               "--phase-x", "0,1.5", "--v-inertial", "-0.5,0.5", "--inplane-on", "holder",
               "--workers", "1", "--no-progress", "--out", str(tmp_path / "s.zarr"))
    assert out.returncode == 0, out.stderr
    ds = vf.sweep(Dimensionless(0.5, 2.0, 0.5), a_x=0.5, phase_x=[0.0, 1.5],
                  v_inertial=[-0.5, 0.5], inplane_on="holder", workers=1, progress=False,
                  store=tmp_path / "s.zarr")  # resumed: the same grid and mount
    assert ds.attrs["inplane_on"] == "holder" and bool(ds.trusted.all())


@pytest.mark.slow
def test_docs_inplane_code_runs() -> None:
    """The python blocks of docs/inplane.md run as written."""
    from pathlib import Path

    text = (Path(__file__).resolve().parents[2] / "docs" / "inplane.md").read_text()
    blocks = [b.split("```", 1)[0] for b in text.split("```python\n")[1:]]
    assert blocks
    namespace: dict = {}
    for block in blocks:
        exec(compile(block, "docs/inplane.md", "exec"), namespace)
    assert namespace["r"].mu_ratio < 0 and namespace["atlas"].mu_ratio.shape == (3, 3, 4)


def test_design_refuses_an_inplane_oscillation_rather_than_ignore_it() -> None:
    from vibrofriction.bench import design

    pin = Physical(**PIN, du_x=1e-6)
    # the design chooses the in-plane oscillation when given its range (du_x=); without
    # it a pin's in-plane oscillation is refused, not silently dropped
    with pytest.raises(ValueError, match=r"the pin has an in-plane oscillation .* du_x=\(low"):
        design(pin, v0=0.01, omega=(1e3, 1e4), du_z=(0.0, 1e-6))


# --- the bench: measurements with an in-plane oscillation, fitted -------------------------
def _inplane_bench():
    from pathlib import Path

    here = Path(__file__).resolve().parents[1] / "data"
    meta = json.loads((here / "inplane_bench.json").read_text())
    return vf.read_measurements(here / "inplane_bench.csv"), meta, Physical(**meta["truth"])


def test_inplane_measurements_are_read_and_predicted() -> None:
    """tests/data/inplane_bench.csv (made by the independent reference with
    tests/data/make_inplane_bench.py: signed v0 and COF, du_x and phase_x columns): read
    in SI, and the package's COF at the truth scatters about it as the stated sigma."""
    from scipy.stats import chi2 as chi2_dist

    from vibrofriction.bench import predict_cof

    data, meta, truth = _inplane_bench()
    assert list(data.columns) == ["v0", "cof", "du_z", "omega", "sigma", "du_x", "phase_x",
                                  "du_y", "phase_y"]
    assert (data.v0 < 0).sum() == 10 and (data.cof < 0).any() and set(data.du_x) == {4e-6}
    model = predict_cof(truth, data.v0, data.du_z, data.omega, du_x=data.du_x,
                        phase_x=data.phase_x)
    chi2 = float(np.sum(((model - data.cof) / data.sigma) ** 2))
    assert 1e-3 < chi2_dist.sf(chi2, len(data)) < 1 - 1e-3, chi2
    assert meta["reference_error_bar_cof"] < 0.01 * meta["sigma"]
    # without the du_x (and du_y) column the same signs are refused: they need an in-plane
    # oscillation
    with pytest.raises(ValueError, match=r"column 'v0', row 0: -0.08 is not a finite number "
                                         r">= 0"):
        vf.read_measurements(data.drop(columns=["du_x", "du_y"]))


@pytest.mark.slow
def test_fit_to_inplane_reference_data_holds_the_truth() -> None:
    """mu0 and k_xc fitted to the held-out in-plane data from a guess off by 1.3 and 1.6:
    the 95 % intervals hold the truth, and the mount is the guess's."""
    data, _, truth = _inplane_bench()
    guess = truth.with_(mu0=0.39, k_xc=4.8e6, du_x=0.0)  # du_x, phase_x: from the rows
    res = vf.fit(data, guess, free=["mu0", "k_xc"], progress=False, workers=1)
    assert res.quality == "good", res.report()
    for n in ("mu0", "k_xc"):
        lo, hi = res.intervals[n]
        assert lo <= getattr(truth, n) <= hi, (n, lo, hi, res.report())
    holder = vf.fit(data, guess.with_(inplane_on="holder"), free=["mu0", "k_xc"],
                    progress=False, workers=1)
    assert holder.chisqr > 4 * res.chisqr  # the wrong mount does not describe the data


def test_regimes_of_the_combined_drive_agree_with_the_solver() -> None:
    """theory.inplane_regime (from the closed-form static band) against the solver's
    blocking forces mu(V = +-1e-5): actuator where both have one sign, ratchet or
    reduction where they straddle 0, reduction where they are opposite equals. Random
    damped systems, both mounts; points within 0.02 of a band edge at 0 are skipped."""
    from vibrofriction import theory

    rng = np.random.default_rng(7)
    seen = set()
    for _ in range(40):
        alpha = float(rng.uniform(0.1, 0.9))
        d = dict(alpha=alpha, beta=alpha + float(rng.uniform(1.0, 5.0)),
                 amplitude=float(rng.uniform(0.0, 0.8)), zeta=float(rng.uniform(0.02, 0.2)),
                 eta_c=float(rng.uniform(0.0, 0.3)), a_x=float(rng.uniform(0.1, 1.5)),
                 phase_x=float(rng.uniform(0, 2 * math.pi)),
                 inplane_on=str(rng.choice(["substrate", "holder"])))
        upper, lower = theory.inplane_static_mu_ratio(**d)
        regime = int(theory.inplane_regime(**d))
        if regime < 0 or min(abs(upper), abs(lower)) < 0.02:
            continue
        plus, minus = (friction_coefficient(Dimensionless(**d), v_inertial=v)
                       for v in (1e-5, -1e-5))
        assert plus.trusted and minus.trusted, d
        if regime == 2:
            assert np.sign(plus.mu_ratio) == np.sign(minus.mu_ratio), d
        else:
            assert plus.mu_ratio > 0 > minus.mu_ratio, d
        seen.add(regime)
    assert seen >= {1, 2}
    # the undamped issue system at phase pi/2 is symmetric: friction reduction
    assert int(theory.inplane_regime(0.5, 2.0, 0.5, 0.5, math.pi / 2)) == 0


def test_transverse_oscillation_is_refused_where_not_asked_for() -> None:
    """A pin with a transverse oscillation whose design does not give du_y is refused
    rather than designed without it (the fit takes du_y from the rows:
    tests/bench/test_fit_transverse.py); simulate computes it (the 2-D history)."""
    from vibrofriction.bench import design

    pin = Physical(**PIN, du_y=1e-6)
    with pytest.raises(ValueError, match=r"the pin has a transverse oscillation"):
        design(pin, v0=0.01, omega=(1e3, 1e4), du_z=(0.0, 1e-6))
    h = vf.simulate(pin.to_dimensionless(), v_inertial=0.3, periods=1)
    assert h.is_plane and np.any(h.f_y != 0.0)


@pytest.mark.slow
def test_cli_transverse() -> None:
    """``--a-y``/``--phase-y`` (and ``--du-y`` in SI) reach the 2-D solver: the table gains
    the lateral column, --json carries lateral_ratio, and the values are the library's."""
    out = _cli("mu", "--alpha", "0.5", "--beta", "2", "--amplitude", "0.5", "--zeta", "0.05",
               "--a-y", "0.5", "--phase-y", "1", "--v-inertial", "0.3", "--json")
    assert out.returncode == 0, out.stderr
    row = json.loads(out.stdout)
    r = friction_coefficient(Dimensionless(0.5, 2.0, 0.5, zeta=0.05, a_y=0.5, phase_y=1.0),
                             v_inertial=0.3)
    assert (row["mu_ratio"], row["lateral_ratio"]) == (r.mu_ratio, r.lateral_ratio)
    assert row["system"]["a_y"] == 0.5 and r.lateral_ratio != 0.0
    text = _cli("mu", "--alpha", "0.5", "--beta", "2", "--amplitude", "0.5", "--zeta", "0.05",
                "--a-y", "0.5", "--v-inertial", "0.3")
    assert "lateral" in text.stdout.splitlines()[1] and "critical velocity inf" in text.stdout
    si = [f"--{k.replace('_', '-')}={v!r}" for k, v in PIN.items()]
    phys = _cli("mu", *si, "--du-y", "1e-6", "--v0", "0.01", "--json")
    assert phys.returncode == 0, phys.stderr
    expect = friction_coefficient(Physical(**PIN, du_y=1e-6), v0=0.01)
    assert json.loads(phys.stdout)["lateral_ratio"] == expect.lateral_ratio
