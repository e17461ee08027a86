"""Convergence of the MDR spring-row reference (src/vibrofriction_reference/mdr.py) in the
number of springs and in the time step, and its distance to the closed forms of
docs/contact_geometry.md. Prints the tables quoted there, the whole results file
(tests/docs/test_quoted_numbers.py compares its output with the committed file):

    PYTHONPATH=src python benchmarks/mdr_convergence.py > benchmarks/results/mdr_convergence.md
"""

from __future__ import annotations

import math
import platform
import subprocess
import time

from vibrofriction import theory
from vibrofriction_reference.mdr import mdr_mean, mdr_reference

POINTS = [  # (label, alpha, beta, amplitude, V, n, zeta)
    ("sphere, soft, a=0.5", 0.3, 3.0, 0.5, 0.4, 2.0, 0.0),
    ("sphere, resonant, jumping a=1.5", 1.0, 4.0, 1.5, 1.0, 2.0, 0.05),
    ("cone, stiff-ish, a=0.8", 0.2, 0.6, 0.8, 0.5, 1.0, 0.0),
]
WINDOWS = dict(transient_periods=150, average_periods=30)
REF = (1600, 1600)  # (springs, steps per period) of the "exact" run


def closed_forms() -> None:
    print("\n## closed forms (vibrofriction.theory): flat (n = inf), sphere (2), cone (1)")
    print("| a | <F_N>/F_N0 flat, sphere, cone | static mu/mu0 flat, sphere, cone |"
          " stiff law at vbar = 0.1, 0.3, 0.6: flat; sphere; cone |")
    print("| --- | --- | --- | --- |")
    for a in (0.2, 0.5, 0.8, 1.0, 1.5, 3.0):
        ns = (math.inf, 2.0, 1.0)
        mean = ", ".join(f"{theory.profile_mean_normal_force(a, n):.4f}" for n in ns)
        static = ", ".join(f"{theory.profile_static_mu_ratio(a, n):.4f}" for n in ns)
        stiff = "; ".join(", ".join(f"{theory.mu_ratio_stiff_profile(v, a, n):.4f}"
                                    for v in (0.1, 0.3, 0.6)) for n in ns)
        print(f"| {a} | {mean} | {static} | {stiff} |")


def main() -> None:
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip()
    print("# MDR spring-row reference: convergence and closed forms\n")
    print("Regenerate: `PYTHONPATH=src python benchmarks/mdr_convergence.py > "
          "benchmarks/results/mdr_convergence.md` (machine: 2 shared cores).")
    print("Errors are absolute errors of `mu_ratio` against the (1600 springs, 1600 "
          "steps/period) run.\n")
    print(f"# {time.strftime('%Y-%m-%d')}, commit {commit}, {platform.machine()} "
          f"{platform.python_version()}, windows {WINDOWS}")
    closed_forms()
    for label, alpha, beta, a, V, n, zeta in POINTS:
        ref = mdr_mean(alpha, beta, a, V, n, REF[0], REF[1], zeta=zeta, **WINDOWS).mu_ratio
        print(f"\n## {label}: alpha={alpha}, beta={beta}, a={a}, V={V}, n={n}, zeta={zeta}; "
              f"mu_ratio at {REF} = {ref:.8f}")
        print("| springs \\ steps/period | " + " | ".join(str(s) for s in (100, 200, 400, 800))
              + " |")
        print("| --- | --- | --- | --- | --- |")
        for springs in (50, 100, 200, 400, 800):
            row = [abs(mdr_mean(alpha, beta, a, V, n, springs, steps, zeta=zeta,
                                **WINDOWS).mu_ratio - ref) for steps in (100, 200, 400, 800)]
            print(f"| {springs} | " + " | ".join(f"{e:.1e}" for e in row) + " |")
        r = mdr_reference(alpha, beta, a, V, n, zeta=zeta, **WINDOWS)
        print(f"mdr_reference default ((100, 200), (200, 400)): {r.mu_ratio:.8f} "
              f"+- {r.mu_error:.1e}; true error {abs(r.mu_ratio - ref):.1e}; "
              f"<F_N>/F_N0 = {r.mean_normal_ratio:.8f} +- {r.normal_error:.1e}, closed form "
              f"{theory.profile_mean_normal_force(a, n):.8f}")
    print("\n## stiff system (alpha, beta = alpha0, 2 alpha0; zeta = 1), vbar = 0.3")
    print("| profile | a | law | alpha0 = 1e-3 | 1e-4 | 1e-5 |")
    print("| --- | --- | --- | --- | --- | --- |")
    for n in (2.0, 1.0):
        for a in (0.5, 1.5):
            law = theory.mu_ratio_stiff_profile(0.3, a, n)
            cells = []
            for alpha in (1e-3, 1e-4, 1e-5):
                V = 0.3 * (n + 1) * a / (n * alpha)
                r = mdr_reference(alpha, 2 * alpha, a, V, n, transient_periods=1000,
                                  average_periods=20, zeta=1.0)
                cells.append(f"{r.mu_ratio - law:+.1e} (+-{r.mu_error:.0e})")
            print(f"| n={n:g} | {a} | {law:.6f} | " + " | ".join(cells) + " |")
    print("\n## static limit (alpha, beta = 0.5, 2), mu_ratio - static value")
    print("| profile | a | static | V = 1e-2 | 3e-3 | 1e-3 |")
    print("| --- | --- | --- | --- | --- | --- |")
    for n in (2.0, 1.0):
        for a in (0.5, 1.5):
            st = theory.profile_static_mu_ratio(a, n)
            mus = [mdr_reference(0.5, 2.0, a, V, n, transient_periods=100,
                                 average_periods=20).mu_ratio for V in (1e-2, 3e-3, 1e-3)]
            cells = [f"{mu - st:+.2e}" for mu in mus]
            print(f"| n={n:g} | {a} | {st:.6f} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
