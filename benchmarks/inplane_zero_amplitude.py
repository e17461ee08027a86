"""Zero in-plane amplitude reproduces the normal-only solver (issue 20, exact solver).

Solves a fixed set of points of every regime (random, seeded: soft, stiff, rigid, the
resonances ``alpha = 1`` and ``beta = 1``, jumping, damped, from the sliding start and
from rest) with whatever ``vibrofriction`` is on ``sys.path`` and either writes every
output column to ``OUT.npz`` or compares with a file written before::

    PYTHONPATH=<old>/src python benchmarks/inplane_zero_amplitude.py --write old.npz
    PYTHONPATH=<new>/src python benchmarks/inplane_zero_amplitude.py --compare old.npz

The comparison prints, per column, the number of points that differ bitwise and the
largest difference (relative to 1 + |value|), over the points both runs solved.
"""

from __future__ import annotations

import math
import sys

import numpy as np

from vibrofriction.solver import solve_points


def points(n: int = 240, seed: int = 20) -> dict[str, np.ndarray]:
    rng = np.random.default_rng(seed)
    alpha = 10.0 ** rng.uniform(-2.0, 1.3, n)
    k = 10.0 ** rng.uniform(-2.0, 3.0, n)
    alpha[:12] = 1.0  # system resonance
    alpha[12:24] = np.minimum(alpha[12:24], 0.6)
    beta = alpha + k
    beta[rng.random(n) < 0.15] = math.inf
    beta[12:24] = 1.0  # contact resonance
    a = rng.uniform(0.0, 2.0, n)
    a[rng.random(n) < 0.05] = 1.0
    zeta = np.where(rng.random(n) < 0.5, 10.0 ** rng.uniform(-3, -0.5, n), 0.0)
    zeta[:12] = np.maximum(zeta[:12], 0.01)  # alpha = 1 undamped takes 20000 periods
    eta = np.where(rng.random(n) < 0.4, 10.0 ** rng.uniform(-2, 0, n), 0.0)
    V = 10.0 ** rng.uniform(-2.0, 0.5, n)
    return {"alpha": alpha, "beta": beta, "amplitude": a, "v_inertial": V, "zeta": zeta,
            "eta_c": eta}


def solve(p: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
    out = {}
    for init in ("sliding", "rest"):
        cols = solve_points(**p, initial=init)
        out.update({f"{init}:{k}": np.asarray(v, dtype=float) for k, v in cols.items()})
    return out


def main() -> None:
    mode, path = sys.argv[1], sys.argv[2]
    res = solve(points())
    if mode == "--write":
        np.savez(path, **res)
        return
    old = np.load(path)
    worst = 0.0
    for key in sorted(res):
        if key not in old.files:  # a column the old solver did not have
            print(f"{key:32s} new column (range {np.nanmin(res[key]):.3g} .. "
                  f"{np.nanmax(res[key]):.3g})")
            continue
        a, b = old[key], res[key]
        same = (a == b) | (np.isnan(a) & np.isnan(b))
        with np.errstate(invalid="ignore"):
            d = np.abs(a - b) / (1.0 + np.abs(a))
        d = np.where(same, 0.0, d)
        dmax = float(np.nanmax(d)) if np.any(~same) else 0.0
        if not key.endswith(":work"):
            worst = max(worst, dmax)
        print(f"{key:32s} differ {int(np.sum(~same)):4d}/{a.size}  max rel {dmax:.2e}")
    print(f"largest relative difference (all columns but work): {worst:.2e}")


if __name__ == "__main__":
    main()
