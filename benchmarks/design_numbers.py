"""The design numbers that docs/bench.md quotes ("Design the oscillation"), regenerated.

1. The optimum against the operating velocity ``v0 = 0.001, 0.01, 0.1, 0.5 m/s`` for the
   pin of ``tests/bench/test_design.py`` (800 Hz, Q = 50, m = 0.01 kg, k_zc = 2e7 N/m,
   k_xc = 1.5e7 N/m, F_N0 = 20 N so u_z0 = 1 um, mu0 = 0.3) over 200-5000 Hz,
   0.1-0.9 um, ``omega du_z <= 0.01 m/s`` (the docs' call; default map and starts):
   frequency, amplitude, COF, the design's status and counts of untrusted points, the
   COF with the frequency off by -1 % and +1 % (the sensitivity table), and peer B of
   ``vibrofriction_reference`` (fixed-step, shares no code with the solver; 1600 steps
   per fastest period, 200 + 50 periods) at the optimum.
2. Why several starts: the same design at ``v0 = 0.01`` on coarser maps with one start
   and with eight, against the default (161 x 41, 8 starts).
3. The in-plane design (same pin, substrate, ``du_z`` 0-0.9 um, ``du_x`` 0-5 um, default
   4-D map 41 x 9 x 9 x 16, the combined velocity limit): ``goal="friction"`` at
   ``v0 = 0.001, 0.01, 0.1`` m/s with ``omega sqrt(du_z^2 + du_x^2) <= 0.01`` m/s, and
   ``goal="drive"`` at ``v0 = 0.001, 0.003`` m/s with the limit 0.01 and 0.03 m/s; the
   best normal-only and longitudinal-only choices; the drive's blocking force and idle
   velocity; the reference integrator (``vibrofriction_reference.inplane.inplane_mean``)
   at each optimum; the ``"each"`` rule beside ``"combined"``.
4. The optimum phase at fixed amplitudes against theory's adding phase
   (``inplane_cancellation().phase_x + pi``) for ``(alpha, beta, a) = (0.5, 2, 0.5)``,
   ``a_x = 0.5``, undamped and ``zeta = 0.05, eta_c = 0.1``.

Run: ``.venv/bin/python benchmarks/design_numbers.py`` (writes
benchmarks/results/design.md; with ``--print`` it prints the same text and writes nothing:
tests/docs/test_quoted_numbers.py compares it with the committed file).  One process, one
core.
"""

from __future__ import annotations

import math
import os
import platform
import sys
import time
from pathlib import Path

import numpy as np

import vibrofriction as vf
from vibrofriction import theory
from vibrofriction_reference import return_mapping_mu
from vibrofriction_reference.inplane import inplane_mean

HERE = Path(__file__).resolve().parent
PIN = vf.from_bench(natural_frequency_hz=800.0, mass=0.01, quality_factor=50.0,
                             normal_load=20.0, k_zc=2e7, k_xc=1.5e7, drive_frequency_hz=1000.0,
                             du_z=0.5e-6, mu0=0.3)
CALL = dict(omega=(2 * math.pi * 200, 2 * math.pi * 5000), du_z=(0.1e-6, 0.9e-6),
            max_velocity_amplitude=0.01)
VELOCITIES = (0.001, 0.01, 0.1, 0.5)
MAPS = ((161, 41, 8), (161, 41, 1), (41, 9, 8), (41, 9, 1), (21, 5, 8), (21, 5, 1))


def _reference_cof(system: vf.Physical, v0: float) -> float:
    al, be, a, ze, et = (float(x) for x in system.groups(system.du_z, system.omega))
    V = float(v0 / system.velocity_unit(system.omega))
    return system.mu0 * return_mapping_mu(al, be, a, V, steps_per_period=1600, zeta=ze,
                                          eta_c=et)


def _commit() -> str:
    import subprocess

    return subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                          text=True, cwd=HERE).stdout.strip()


def optimum_rows() -> list[str]:
    rows = ["| v0 (m/s) | f (Hz) | du_z (um) | omega du_z (m/s) | COF | mu/mu0 | status "
            "(untrusted map points) | COF at f -1 % / +1 % | peer B - COF | time (s) |",
            "|---|---|---|---|---|---|---|---|---|---|"]
    for v0 in VELOCITIES:
        t = time.perf_counter()
        res = vf.design(PIN, v0=v0, **CALL)
        elapsed = time.perf_counter() - t
        s = res.system
        table = res.sensitivity.set_index("change")["cof"]
        rows.append(f"| {v0:g} | {s.omega / (2 * math.pi):.1f} | {s.du_z * 1e6:.4f} | "
                    f"{s.omega * s.du_z:.4g} | {res.cof:.4f} | {res.mu_ratio:.4f} | "
                    f"{res.status} ({res.n_untrusted}) | {table['frequency -1 %']:.4f} / "
                    f"{table['frequency +1 %']:.4f} | "
                    f"{_reference_cof(s, v0) - res.cof:+.1e} | {elapsed:.1f} |")
    return rows


def starts_rows() -> list[str]:
    rows = ["| map | starts | f (Hz) | COF | COF - default's | time (s) |",
            "|---|---|---|---|---|---|"]
    best = None
    for n_omega, n_du_z, starts in MAPS:
        t = time.perf_counter()
        res = vf.design(PIN, v0=0.01, n_omega=n_omega, n_du_z=n_du_z, starts=starts, **CALL)
        elapsed = time.perf_counter() - t
        best = res.cof if best is None else best
        rows.append(f"| {n_omega} x {n_du_z} | {starts} | "
                    f"{res.system.omega / (2 * math.pi):.1f} | {res.cof:.5f} | "
                    f"{res.cof - best:.1e} | {elapsed:.1f} |")
    return rows


INPLANE = dict(omega=CALL["omega"], du_z=(0.0, 0.9e-6), du_x=(0.0, 5e-6))
INPLANE_CASES = (("friction", 0.001, 0.01), ("friction", 0.01, 0.01), ("friction", 0.1, 0.01),
                 ("drive", 0.001, 0.01), ("drive", 0.001, 0.03), ("drive", 0.003, 0.03))


def _reference_inplane(system: vf.Physical, v0: float) -> tuple[float, float]:
    d = system.to_dimensionless()
    ref = inplane_mean(d.alpha, d.beta, d.amplitude, float(system.v0_to_inertial(v0)),
                       zeta=d.zeta, eta_c=d.eta_c, a_x=d.a_x, phase_x=d.phase_x,
                       inplane_on=d.inplane_on)
    return ref.mu_ratio, ref.mu_error


def inplane_rows() -> list[str]:
    rows = ["| goal | v0 (m/s) | limit (m/s) | f (Hz) | du_z (um) | du_x (um) | phase_x | "
            "COF | normal only | longitudinal only | blocking mu(0+) / mu(0-) | idle (m/s) | "
            "reference - mu/mu0 (its error) | status | time (s) |",
            "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for goal, v0, vmax in INPLANE_CASES:
        t = time.perf_counter()
        res = vf.design(PIN, v0=v0, goal=goal, max_velocity_amplitude=vmax, **INPLANE)
        elapsed = time.perf_counter() - t
        s = res.system
        table = res.directions.set_index("direction")["cof"]
        block = ("-" if res.blocking is None else
                 f"{res.blocking[0]:+.4f} / {res.blocking[1]:+.4f}")
        idle = ("-" if res.idle_velocity is None else
                "none" if math.isnan(res.idle_velocity) else f"{res.idle_velocity:.4g}")
        ref, ref_err = _reference_inplane(s, v0)
        rows.append(f"| {goal} | {v0:g} | {vmax:g} | {s.omega / (2 * math.pi):.1f} | "
                    f"{s.du_z * 1e6:.4f} | {s.du_x * 1e6:.4f} | {s.phase_x:.4f} | "
                    f"{res.cof:+.5f} | {table['normal only']:.5f} | "
                    f"{table['longitudinal only']:.5f} | {block} | {idle} | "
                    f"{ref - res.mu_ratio:+.1e} ({ref_err:.0e}) | {res.status} "
                    f"({res.n_untrusted}) | {elapsed:.1f} |")
    return rows


def rule_rows() -> list[str]:
    rows = ["| rule | f (Hz) | du_z (um) | du_x (um) | omega du_z, omega du_x (m/s) | COF |",
            "|---|---|---|---|---|---|"]
    for rule in ("combined", "each"):
        res = vf.design(PIN, v0=0.01, max_velocity_amplitude=0.01, velocity_rule=rule,
                        **INPLANE)
        s = res.system
        rows.append(f"| {rule} | {s.omega / (2 * math.pi):.1f} | {s.du_z * 1e6:.4f} | "
                    f"{s.du_x * 1e6:.4f} | {s.omega * s.du_z:.4g}, {s.omega * s.du_x:.4g} | "
                    f"{res.cof:+.5f} |")
    return rows


def phase_rows() -> list[str]:
    m, w, u, kz, mu0 = 0.01, 2 * math.pi * 1000.0, 1e-6, 2e7, 0.3
    base = vf.Physical(mass=m, k_x=0.5 * m * w**2, k_xc=1.5 * m * w**2, k_zc=kz, u_z0=u,
                       du_z=0.5 * u, omega=w, mu0=mu0)
    dux = 0.5 * mu0 * kz * u / (m * w**2)
    rows = ["| zeta, eta_c | V | optimum phase_x | adding phase | difference | COF there | "
            "COF at the cancellation phase |", "|---|---|---|---|---|---|---|"]
    for zeta, eta in ((0.0, 0.0), (0.05, 0.1)):
        pin = base.with_damping(zeta=zeta, eta_c=eta)
        adding = (theory.inplane_cancellation(0.5, 2.0, 0.5, zeta, eta).phase_x
                  + math.pi) % (2 * math.pi)
        for V in (0.05, 0.2, 0.4):
            res = vf.design(pin, v0=V * pin.velocity_unit(), omega=(w, w), du_z=(0.5 * u,) * 2,
                            du_x=(dux, dux))
            pm = res.phase_map
            worst = float(pm.cof.sel(phase_x=adding - math.pi, method="nearest").item())
            diff = math.remainder(res.system.phase_x - adding, 2 * math.pi)
            rows.append(f"| {zeta}, {eta} | {V} | {res.system.phase_x:.5f} | {adding:.5f} | "
                        f"{diff:+.1e} | {res.cof:.5f} | {worst:.5f} |")
    return rows


def main() -> None:
    vf.design(PIN, v0=0.01, n_omega=3, n_du_z=2, **CALL)  # compile or load the kernels
    lines = [
        "# Design numbers (docs/bench.md, \"Design the oscillation\")",
        "",
        "Command: `.venv/bin/python benchmarks/design_numbers.py`  ",
        f"Machine: {platform.machine()}, {os.cpu_count()} cores, Python "
        f"{platform.python_version()}, numpy {np.__version__}; one process, one core.  ",
        f"Date: {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}, commit {_commit()}",
        "",
        "Pin: 800 Hz, Q = 50, m = 0.01 kg, k_zc = 2e7 N/m, k_xc = 1.5e7 N/m, F_N0 = 20 N "
        "(u_z0 = 1 um), mu0 = 0.3.  Range: 200-5000 Hz, 0.1-0.9 um, omega du_z <= 0.01 m/s.",
        "",
        "## The optimum against the operating velocity (default map 161 x 41, 8 starts)",
        "",
        "`peer B - COF`: peer B of vibrofriction_reference (1600 steps per fastest period, "
        "200 + 50 periods) at the optimum, minus the design's COF.",
        "",
        *optimum_rows(),
        "",
        "## Several starts: v0 = 0.01 m/s on coarser maps",
        "",
        *starts_rows(),
        "",
        "## In-plane design (substrate; du_z 0-0.9 um, du_x 0-5 um; default 4-D map "
        "41 x 9 x 9 x 16, 8 starts; the combined velocity limit)",
        "",
        "`normal only`, `longitudinal only`: the best COF of each alone within the same "
        "limits (the design's directions table). `blocking`: mu/mu0 at V = +-1e-5 of the "
        "chosen oscillation; `idle`: the root of mu(v) = 0 above v0. `reference`: "
        "vibrofriction_reference.inplane.inplane_mean at the optimum (rtol 1e-10, 100 + 40 "
        "periods) minus the design's mu/mu0, with the reference's own error.",
        "",
        *inplane_rows(),
        "",
        "## The velocity rule at v0 = 0.01 m/s, limit 0.01 m/s (friction)",
        "",
        *rule_rows(),
        "",
        "## The optimum phase against theory (fixed amplitudes a = 0.5, a_x = 0.5; "
        "(alpha, beta) = (0.5, 2) at 1 kHz)",
        "",
        "`adding phase`: theory.inplane_cancellation(...).phase_x + pi, where V_c is "
        "largest; `COF at the cancellation phase`: the design's phase map (73 phases) "
        "nearest it.",
        "",
        *phase_rows(),
        "",
    ]
    print("\n".join(lines))
    if "--print" not in sys.argv[1:]:
        out = HERE / "results" / "design.md"
        out.write_text("\n".join(lines))
        print(f"-> {out}")


if __name__ == "__main__":
    main()
