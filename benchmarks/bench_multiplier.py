"""The Floquet multiplier in closed form against LAPACK, on the solver's own Jacobians.

For the periodic orbits of ``--n`` points of the 10^6-point flat atlas
(``atlas_work.sample``, seed 3), the exact Jacobian of the period map at the orbit's final
state (``tangent.period_map_tangent``, in the free coordinates of its phase), and its
spectral radius two ways: :func:`vibrofriction._kernels.newton.spectral_radius` (the
characteristic polynomial's roots, LAPACK where they cluster) and ``numpy.linalg.eigvals``.
Printed: how many Jacobians, their largest relative difference, and the time of one call
of each inside a compiled loop (median of 5 loops over all the Jacobians).

    PYTHONPATH=src python benchmarks/bench_multiplier.py [--n 20000] [--write]

``--write`` appends the run to benchmarks/results/multiplier.md.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

import numpy as np

from atlas_work import sample
from sections import append_run
from vibrofriction._kernels.jit import jit
from vibrofriction._kernels.newton import _free_dimension, spectral_radius
from vibrofriction._kernels.phases import make_model
from vibrofriction._kernels.tangent import period_map_tangent
from vibrofriction.schema import Status
from vibrofriction.solver import solve_points

RESULTS = Path(__file__).parent / "results" / "multiplier.md"


@jit
def _closed(Js, nds):
    s = 0.0
    for i in range(Js.shape[0]):
        s += spectral_radius(Js[i], nds[i])
    return s


@jit
def _lapack(Js, nds):
    s = 0.0
    for i in range(Js.shape[0]):
        n = nds[i]
        s += np.max(np.abs(np.linalg.eigvals(Js[i, :n, :n].astype(np.complex128))))
    return s


def jacobians(n: int) -> tuple[np.ndarray, np.ndarray]:
    pts = sample(n, seed=3)
    out = solve_points(**pts)
    Js, nds = [], []
    acc = np.zeros(6)
    for i in np.flatnonzero((out["status"] == Status.PERIODIC.code) & (out["period"] == 1)):
        M = make_model(pts["alpha"][i], pts["beta"][i], 0.5, pts["v_inertial"][i], 0.0, 0.0,
                       0.0, 0.0, True)
        J, G = np.zeros((3, 3)), np.zeros(3)
        ph = int(out["phase"][i])
        res = period_map_tangent(out["y"][i], out["x_dot"][i], out["e"][i], ph, 1, M,
                                 10**6, J, G, acc)
        if res[5] == 0 and res[7] and res[3] == ph:  # smooth, one chart
            Js.append(J)
            nds.append(_free_dimension(ph, M))
    return np.array(Js), np.array(nds, dtype=np.int64)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=20000)
    parser.add_argument("--write", action="store_true")
    args = parser.parse_args()
    Js, nds = jacobians(args.n)
    closed = np.array([spectral_radius(J, k) for J, k in zip(Js, nds, strict=True)])
    lapack = np.array([np.max(np.abs(np.linalg.eigvals(J[:k, :k])))
                       for J, k in zip(Js, nds, strict=True)])
    rel = np.abs(closed - lapack) / np.maximum(lapack, 1e-300)
    _closed(Js[:2], nds[:2])
    _lapack(Js[:2], nds[:2])
    times = {}
    for name, f in (("closed form", _closed), ("LAPACK", _lapack)):
        runs = []
        for _ in range(5):
            t = time.perf_counter()
            f(Js, nds)
            runs.append(time.perf_counter() - t)
        times[name] = statistics.median(runs) / len(Js) * 1e6
    lines = ["| quantity | value |", "|---|---:|",
             f"| Jacobians (orbits of one period, smooth) | {len(Js)} (2 x 2: "
             f"{int(np.sum(nds == 2))}, 3 x 3: {int(np.sum(nds == 3))}) |",
             f"| largest relative difference, closed form against LAPACK | {rel.max():.1e} |",
             f"| one call, closed form | {times['closed form']:.2f} us |",
             f"| one call, LAPACK (`numpy.linalg.eigvals` compiled) | {times['LAPACK']:.2f} us |"]
    print("\n".join(lines))
    if args.write:
        append_run(RESULTS, "The Floquet multiplier: closed form against LAPACK",
                   " ".join(["PYTHONPATH=src python benchmarks/bench_multiplier.py",
                             *sys.argv[1:]]),
                   "one process; the Jacobians of the sample's orbits, each call timed in a "
                   "compiled loop (median of 5 loops).", lines)


if __name__ == "__main__":
    main()
