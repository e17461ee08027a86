"""The design numbers that docs/bench.md quotes ("Design the oscillation"), regenerated.

1. The optimum against the operating velocity ``v0 = 0.001, 0.01, 0.1, 0.5 m/s`` for the
   pin of ``tests/test_design.py`` (800 Hz, Q = 50, m = 0.01 kg, k_zc = 2e7 N/m,
   k_xc = 1.5e7 N/m, F_N0 = 20 N so u_z0 = 1 um, mu0 = 0.3) over 200-5000 Hz,
   0.1-0.9 um, ``omega du_z <= 0.01 m/s`` (the docs' call; default map and starts):
   frequency, amplitude, COF, the design's status and counts of untrusted points, the
   COF with the frequency off by -1 % and +1 % (the sensitivity table), and peer B of
   ``vibrofriction_reference`` (fixed-step, shares no code with the solver; 1600 steps
   per fastest period, 200 + 50 periods) at the optimum.
2. Why several starts: the same design at ``v0 = 0.01`` on coarser maps with one start
   and with eight, against the default (161 x 41, 8 starts).

Run: ``.venv/bin/python benchmarks/design_numbers.py`` (writes
benchmarks/results/design.md).  One process, one core.
"""

from __future__ import annotations

import math
import os
import platform
import time
from pathlib import Path

import numpy as np

import vibrofriction as vf
from vibrofriction_reference import return_mapping_mu

HERE = Path(__file__).resolve().parent
PIN = vf.Physical.from_bench(natural_frequency_hz=800.0, mass=0.01, quality_factor=50.0,
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


def main() -> None:
    vf.design(PIN, v0=0.01, n_omega=3, n_du_z=2, **CALL)  # compile or load the kernels
    lines = [
        "# Design numbers (docs/bench.md, \"Design the oscillation\")",
        "",
        "Command: `.venv/bin/python benchmarks/design_numbers.py`  ",
        f"Machine: {platform.machine()}, {os.cpu_count()} cores, Python "
        f"{platform.python_version()}, numpy {np.__version__}; one process, one core.  ",
        f"Date: {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}",
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
    ]
    out = HERE / "results" / "design.md"
    out.write_text("\n".join(lines))
    print("\n".join(lines))
    print(f"-> {out}")


if __name__ == "__main__":
    main()
