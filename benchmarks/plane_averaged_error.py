"""Is a 2-D averaged answer's error honest?  The 2-D solver's averages against the motion's
long-time mean.

Where the 2-D solver (a transverse oscillation) finds no periodic orbit it averages the
motion over a fixed window after a fixed transient (docs/inplane.md), its error the range
of the window's thirds' means plus the effect of the tolerance.  Such answers are common
with a static coefficient above the kinetic one (a motion not locked to the drive).  Here,
random 2-D points of the static law (alpha 0.2..2, beta - alpha 0.5..10, a 0.2..0.95 or
jumping 1.05..1.5, a_y 0.05..0.63 with a random phase, zeta in {0, 0.02, 0.1}, s_r
1.1..2, V 0.06..0.63, from sliding or from rest) are solved, and each one answered
``averaged`` is integrated by ``vibrofriction.simulate`` (the same Runge-Kutta method,
another code path: a time history with its integral of the force) for :data:`LONG`
periods from the same start; the mean over the last half is the long-time mean.  Counted:
the averaged answers whose distance to it is beyond their stated error, and what the
earlier error (the difference of the window's halves, from the same answers' windows
recomputed from the history) would have said.

    PYTHONPATH=src python benchmarks/plane_averaged_error.py [--seeds 5-8] [--points 60]
        [--write]

``--write`` appends the run to benchmarks/results/plane_averaged_error.md.
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

import numpy as np

import vibrofriction as vf
from sections import append_run

RESULTS = Path(__file__).parent / "results" / "plane_averaged_error.md"
LONG = 16384  # drive periods of the long run


def points(seed: int, count: int):
    """``(alpha, beta, a, a_y, phase_y, zeta, s_r, V, start)`` of one seed."""
    rng = np.random.default_rng([seed, 66])
    for i in range(count):
        alpha = float(10 ** rng.uniform(-0.7, 0.3))
        beta = alpha + float(10 ** rng.uniform(-0.3, 1.0))
        a = float(rng.uniform(0.2, 0.95) if i % 3 else rng.uniform(1.05, 1.5))
        a_y = float(10 ** rng.uniform(-1.3, -0.2))
        phase_y = float(rng.uniform(0.0, 2.0 * math.pi))
        zeta = float(rng.choice([0.0, 0.02, 0.1]))
        sr = float(rng.uniform(1.1, 2.0))
        V = float(10 ** rng.uniform(-1.2, -0.2))
        yield alpha, beta, a, a_y, phase_y, zeta, sr, V, str(rng.choice(["sliding", "rest"]))


def long_mean(system: vf.Dimensionless, V: float, start: str, nbar: float) -> float:
    """The motion's mean of ``f/n`` over periods ``(LONG/2, LONG]`` from ``start``."""
    h = vf.simulate(system, v_inertial=V, periods=LONG, samples_per_period=2, initial=start)
    ends = np.interp(2.0 * math.pi * np.array([LONG // 2, LONG]), h.tau, h.impulse[:, 0])
    return float((ends[1] - ends[0]) / (2.0 * math.pi * nbar * (LONG - LONG // 2)))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seeds", default="5-8", help="first-last (inclusive)")
    ap.add_argument("--points", type=int, default=60, help="points per seed")
    ap.add_argument("--write", action="store_true")
    args = ap.parse_args()
    first, last = (int(s) for s in args.seeds.split("-"))
    t0 = time.perf_counter()
    rows, total, statuses = [], 0, {}
    for seed in range(first, last + 1):
        for alpha, beta, a, a_y, ph, zeta, sr, V, start in points(seed, args.points):
            total += 1
            system = vf.Dimensionless(alpha, beta, a, zeta=zeta, a_y=a_y, phase_y=ph,
                                      static_ratio=sr)
            r = vf.friction_coefficient(system, v_inertial=V, initial=start)
            statuses[r.status.value] = statuses.get(r.status.value, 0) + 1
            if r.status is vf.Status.AVERAGED:
                mean = long_mean(system, V, start, r.mean_normal_ratio)
                rows.append((alpha, beta, a, a_y, ph, zeta, sr, V, start, r, mean))
        print(f"seed {seed}: {len(rows)} averaged so far, {time.perf_counter() - t0:.0f} s",
              file=sys.stderr, flush=True)
    beyond = [w for w in rows if abs(w[9].mu_ratio - w[10]) > w[9].error]
    trusted = [w for w in rows if w[9].trusted]
    lines = [
        f"Seeds {args.seeds}, {args.points} points each: {total} points, statuses "
        f"{statuses}; each averaged answer against its motion's mean over periods "
        f"({LONG // 2}, {LONG}] (`vibrofriction.simulate` from the same start).",
        "",
        f"* {len(rows)} averaged answers ({len(trusted)} trusted), {len(beyond)} of them "
        f"farther from the long-time mean than their stated error"
        + (f" (by {', '.join(f'{abs(w[9].mu_ratio - w[10]) / w[9].error:.2g}' for w in beyond)}"
           " times it)" if beyond else "") + ".",
        "",
        "| point (alpha, beta, a, a_y, phase_y, zeta, s_r, V, start) | answer | long-time "
        "mean | off / error |",
        "|---|---|---|---|",
    ]
    for *p, r, mean in rows:
        label = ", ".join(f"{x:.4g}" if isinstance(x, float) else str(x) for x in p)
        lines.append(f"| ({label}) | {r.mu_ratio:.8f} +- {r.error:.1e}"
                     f"{' (trusted)' if r.trusted else ''} | {mean:.8f} | "
                     f"{abs(r.mu_ratio - mean) / r.error:.2g} |")
    print("\n".join(lines))
    if args.write:
        append_run(RESULTS, "2-D averaged answers against the motion's long-time mean",
                   f"PYTHONPATH=src python benchmarks/plane_averaged_error.py --seeds "
                   f"{args.seeds} --points {args.points} --write",
                   f"one process; {time.perf_counter() - t0:.0f} s", lines)


if __name__ == "__main__":
    main()
