"""The paper's experiment as a prediction
======================================

The paper's experiment (Section 7, Figs. 8-9) as a prediction, with stated assumptions.

Stated by the paper: a pin of about 800 Hz natural frequency driven at that resonance
(case IV), oscillation amplitudes 1.3, 5.4, 8.2 and 60 um. Assumed here (not stated):
modal mass 0.01 kg, mean normal force 1 N, mu0 = 0.3, mean indentation 10 um (so the
amplitudes are a = 0.13 ... 6), a quality factor Q = 50, a rigid tangential contact. The
prediction is the COF against the sliding velocity for each amplitude; with Q = 50 the
friction reduction ends at v0* = mu0 omega du_z k_zc / (omega c_x) (eq. 12 damped, rigid).

Run:  python examples/paper_experiment.py [output directory]
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

import vibrofriction as vf

AMPLITUDES_UM = (1.3, 5.4, 8.2, 60.0)
U_Z0 = 10e-6


def pin(du_z: float) -> vf.Physical:
    return vf.from_bench(natural_frequency_hz=800, mass=0.01, quality_factor=50,
                                  normal_load=1.0, k_zc=1.0 / U_Z0, k_xc=math.inf,
                                  drive_frequency_hz=800, du_z=du_z, mu0=0.3)


def main(out_dir: str | Path = "example_output") -> dict[str, float]:
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    v0 = np.geomspace(1e-4, 1.0, 60)
    fig = Figure(figsize=(5.2, 3.4), layout="constrained")
    ax = fig.add_subplot()
    result = {}
    for du in AMPLITUDES_UM:
        p = pin(du * 1e-6)
        r = vf.friction_coefficient(p, v0=v0)
        ok = r.trusted
        ax.plot(v0[ok], p.mu0 * r.mu_ratio[ok], lw=1.2, label=f"{du:g} um (a = {du / 10:g})")
        ax.plot(v0[~ok], p.mu0 * r.mu_ratio[~ok], "o", mfc="none", ms=3)
        result[f"v_star_{du:g}um"] = p.critical_velocity()
        result[f"cof_at_0.01_{du:g}um"] = float(p.mu0 * r.mu_ratio[np.argmin(abs(v0 - 0.01))])
    ax.set_xscale("log")
    ax.set_xlabel("sliding velocity v0 (m/s)")
    ax.set_ylabel("COF (mu0 = 0.3 assumed)")
    ax.set_title("prediction for the paper's experiment (800 Hz pin at resonance, Q = 50 "
                 "assumed)", fontsize=7)
    ax.legend(fontsize=7)
    fig.savefig(out / "paper_experiment.png", dpi=150)
    return result


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "example_output")
