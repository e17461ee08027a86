"""Design the oscillation for a pin
================================

Design the oscillation for a pin: which frequency and amplitude lower friction most at
the operating speed, within the shaker's range and velocity limit, and how sensitive
the optimum is.

Run:  python examples/design_oscillation.py [output directory]
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import vibrofriction as vf
from vibrofriction.contact import Material, Sphere
from vibrofriction.figures import plot_design

STEEL = Material(E=210e9, nu=0.3)
PIN = vf.from_bench(natural_frequency_hz=800, mass=0.01, quality_factor=50,
                             normal_load=20.0, contact=Sphere(3e-3, STEEL, STEEL),
                             drive_frequency_hz=1000, dF_N=10.0, mu0=0.3)


def main(out_dir: str | Path = "example_output") -> dict[str, float]:
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    res = vf.design(PIN, v0=0.05, omega=(2 * math.pi * 200, 2 * math.pi * 5000),
                    du_z=(0.05e-6, 0.5e-6), max_velocity_amplitude=0.01)
    print(res.report())
    plot_design(res).savefig(out / "design_oscillation.png", dpi=150)
    return {"frequency_hz": res.system.omega / (2 * math.pi), "du_z": res.system.du_z,
            "cof": res.cof, "velocity_amplitude": res.system.omega * res.system.du_z}


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "example_output")
