"""How much the shape of the contact matters (issue 21, item 3): the numbers of
docs/contact_geometry.md, "How much the shape matters".

Flat punch, sphere and cone by the MDR solver (``solve_points(..., profile_exponent=n)``)
at equal normal-force amplitude ``A_F = (F_max - F_min)/(2 <F_N>)`` and equal velocity in
units of the mean normal force, ``x = v0 m omega/(mu0 <F_N>)``, in the stiff, soft and
resonant systems of Fig. 17 (``vibrofriction.figures.shape``); then the same at equal
indentation amplitude ``a`` for contrast; then the linearised sphere (one spring at the
load: ``a_lin = 3 a/2``, same ``alpha``, ``beta``, ``V``) against the full one over
``(a, V)`` in three systems (the bench of Fig. 18 among them).

    PYTHONPATH=src python benchmarks/mdr_shape_numbers.py > benchmarks/results/mdr_shape.md
"""

from __future__ import annotations

import math
import platform
import subprocess
import sys
import time

import numpy as np

from vibrofriction import theory
from vibrofriction.figures.shape import (
    PROFILES,
    SYSTEMS,
    equal_force_amplitude,
    force_amplitude,
)
from vibrofriction.solver import solve_points

X = {"stiff": (5.0, 15.0, 30.0), "soft": (0.05, 0.2, 0.4), "resonant": (0.2, 1.0, 3.0)}
X_JUMP = {"stiff": (15.0, 45.0, 90.0), "soft": (0.15, 0.6, 1.2), "resonant": (0.2, 1.0, 3.0)}
#: (name, alpha, beta) of the linearised-sphere comparison; "bench" is Fig. 18's
LIN_SYSTEMS = (("bench (Fig. 18)", 0.64, 2.398553100733369), ("stiff", 0.01, 0.02),
               ("soft", 0.01, 40.0))
LIN_A = (0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.9)
LIN_V = (0.05, 0.2, 0.5, 0.8, 0.95)   # fractions of the full sphere's onset of sliding


def mu(alpha: float, beta: float, a: float, V, n: float) -> tuple[np.ndarray, np.ndarray]:
    r = solve_points(alpha, beta, a, np.asarray(V, dtype=float), profile_exponent=n)
    return r["mu_ratio"], r["trusted"]


def fmt(m: float, ok: bool) -> str:
    return f"{m:.4f}" if ok else f"({m:.4f})"


def equal_force(x_of: dict, flat_a: float, equal: str) -> None:
    print(f"\n## flat punch a = {flat_a}: A_F = {force_amplitude(flat_a, math.inf):.4f}; "
          f"curved tips at equal {equal}")
    amps = {name: (equal_force_amplitude(flat_a, n) if equal == "A_F" else flat_a)
            for name, n, _ in PROFILES}
    print("a: " + ", ".join(f"{k} {v:.4f} (A_F {force_amplitude(v, n):.4f}, <F_N>/F_N0 "
                            f"{theory.profile_mean_normal_force(v, n):.4f}, static "
                            f"{theory.profile_static_mu_ratio(v, n):.4f})"
                            for (k, v), (_, n, _) in zip(amps.items(), PROFILES, strict=True)))
    print("\n| system | x = v0 m omega/(mu0 <F_N>) | flat | sphere | cone | "
          "max abs(curved - flat) |")
    print("| --- | --- | --- | --- | --- | --- |")
    for system, (alpha, beta) in SYSTEMS.items():
        x = np.asarray(x_of[system])
        cols = []
        for name, n, _ in PROFILES:
            a = amps[name]
            m, ok = mu(alpha, beta, a, x * float(theory.profile_mean_normal_force(a, n)), n)
            cols.append((m, ok))
        for i, xi in enumerate(x):
            d = max(abs(cols[k][0][i] - cols[0][0][i]) for k in (1, 2))
            print(f"| {system} ({alpha:g}, {beta:g}) | {xi:g} | "
                  + " | ".join(fmt(c[0][i], c[1][i]) for c in cols) + f" | {d:.4f} |")


def linearised() -> None:
    print("\n## linearised against full sphere: 100 (lin - MDR)/MDR in %, same (alpha, beta, V),"
          " a_lin = 3a/2")
    print("V in fractions of V_s, the smallest V at which the full sphere slides "
          "continuously (bisection on the solver, mu > 1 - 1e-9), at each a")
    for label, alpha, beta in LIN_SYSTEMS:
        print(f"\n### {label}: alpha = {alpha:g}, beta = {beta:.6g}")
        print("| a (MDR) | a_lin | static: lin, MDR, diff % | V_s | "
              + " | ".join(f"{f:g} V_s" for f in LIN_V) + " |")
        print("| --- " * (4 + len(LIN_V)) + "|")
        for a in LIN_A:
            lo, hi = 0.0, 1.0
            while mu(alpha, beta, a, hi, 2.0)[0] < 1 - 1e-9 and hi < 1e4:
                lo, hi = hi, 2 * hi
            for _ in range(12):
                mid = 0.5 * (lo + hi)
                lo, hi = (mid, hi) if mu(alpha, beta, a, mid, 2.0)[0] < 1 - 1e-9 else (lo, mid)
            vs = hi
            V = vs * np.asarray(LIN_V)
            m, ok = mu(alpha, beta, a, V, 2.0)
            ml, okl = mu(alpha, beta, 1.5 * a, V, math.inf)
            s_lin = float(theory.static_mu_ratio(1.5 * a))
            s_mdr = float(theory.profile_static_mu_ratio(a, 2.0))
            rel = [f"{100 * (b - c) / c:+.2f}" + ("" if o and p else " (untrusted)")
                   for b, c, o, p in zip(ml, m, okl, ok, strict=True)]
            print(f"| {a:g} | {1.5 * a:g} | {s_lin:.4f}, {s_mdr:.4f}, "
                  f"{100 * (s_lin - s_mdr) / s_mdr:+.1f} | {vs:.4g} | " + " | ".join(rel) + " |")


def main() -> None:
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip()
    print("# How much the shape matters: MDR numbers\n")
    print("Regenerate: `PYTHONPATH=src python benchmarks/mdr_shape_numbers.py > "
          "benchmarks/results/mdr_shape.md` (machine: 2 shared cores).")
    print(f"\n# {time.strftime('%Y-%m-%d')}, commit {commit}, {platform.machine()} "
          f"{platform.python_version()}")
    print("\nmu/mu0 by solve_points (the MDR solver, tol_trusted 1e-5; values in parentheses "
          "are not trusted). A_F = (F_max - F_min)/(2 <F_N>) of F/F_N0 = "
          "max(0, 1 + a cos tau)^(1 + 1/n).")
    t0 = time.perf_counter()
    equal_force(X, 0.5, "A_F")
    equal_force(X_JUMP, 1.5, "A_F")
    equal_force(X, 0.5, "indentation amplitude a")
    equal_force(X_JUMP, 1.5, "indentation amplitude a")
    linearised()
    print(f"\n{time.perf_counter() - t0:.0f} s", file=sys.stderr)


if __name__ == "__main__":
    main()
