"""Continuous sliding of a curved contact and the dead weight (issue 21): the numbers of
docs/contact_geometry.md, "Continuous sliding" and "Dead weight".

1. ``theory.profile_critical_velocity`` over systems, amplitudes and exponents;
2. against the MDR solver: ``mdr_friction`` just above and below ``V_c``, and the onset of
   continuous sliding of fixed rows of springs found by bisection on ``mdr_row``
   (stick fraction 0 or not) against the same row's own ``V_c`` (the formula with the
   row's total normal force) and the continuum's;
3. the jumping flat punch (``a = 1.5``) on the panels of Fig. 7: the onset found by
   bisection on ``solve_points`` against ``profile_critical_velocity`` and eq. (12);
4. the dead weight: ``d0/d_s`` of ``theory.dead_weight_indentation``, and the bench's
   sphere (docs' example) under both normal controls.

    PYTHONPATH=src python benchmarks/mdr_critical_numbers.py > benchmarks/results/mdr_critical.md
"""

from __future__ import annotations

import math
import platform
import subprocess
import sys
import time

import numpy as np

import vibrofriction as vf
from vibrofriction import theory
from vibrofriction.contact import Material, Sphere
from vibrofriction.solver import solve_points
from vibrofriction.solver.mdr import mdr_friction, mdr_row, rows_alone
from vibrofriction.theory.profile import _SLIDING_GRID, _sliding_rate

SYSTEMS = (("stiff", 0.01, 0.02, 0.0), ("soft", 0.01, 40.0, 0.0),
           ("(0.5, 2)", 0.5, 2.0, 0.0), ("bench (Fig. 18)", 0.64, 2.398553100733369, 0.0),
           ("resonant, zeta 0.05", 1.0, 3.0, 0.05), ("above resonance", 5.0, 8.0, 0.0))
AMPLITUDES = (0.2, 0.5, 1.5)
EXPONENTS = (math.inf, 4.0, 2.0, 1.0)
NAMES = {math.inf: "flat", 4.0: "n = 4", 2.0: "sphere", 1.0: "cone"}
#: (alpha, beta, a, n, zeta) checked against the MDR solver
SOLVER_POINTS = ((0.5, 2.0, 0.5, 2.0, 0.0), (0.5, 2.0, 1.5, 2.0, 0.0),
                 (1.0, 3.0, 0.7, 1.0, 0.1), (0.01, 40.0, 0.5, 2.0, 0.0),
                 (0.05, 0.1, 0.5, 3.0, 0.5), (0.64, 2.398553100733369, 0.5058, 2.0, 0.0))
ROWS = (40, 160, 640)
#: the bisection's resolution on a row: within ~1e-6 of its onset the row meets orbits
#: that graze (periodic with stick, or none in 600 periods) on both sides
ROW_RTOL = 1e-6
MATRIX_ALPHAS = (0.01, 0.2, 5.0, 380.0)
MATRIX_BETAS = (0.02, 0.22, 5.3, 400.0)


def row_critical(alpha: float, beta: float, a: float, n: float, zeta: float, M: int) -> float:
    """``V_c`` of a row of ``M`` springs at the cells' midpoints: the formula with the row's
    total normal force ``sum_i w max(0, 1 + a cos tau - g_i)`` (harmonics by FFT), over the
    phases where its innermost spring is in contact (grid maximum, 2^15 points)."""
    N = _SLIDING_GRID
    dxi = (1.0 + a) ** (1.0 / n) / M
    g = ((np.arange(M) + 0.5) * dxi) ** n
    tau = 2.0 * math.pi * np.arange(N) / N
    m = np.zeros(N)
    for gi in g:
        m += np.maximum(0.0, 1.0 + a * np.cos(tau) - gi)
    m *= dxi * (n + 1.0) / n
    C = np.fft.rfft(m)[: N // 2].real / N
    c = np.concatenate(([C[0]], 2.0 * C[1:]))
    out = _sliding_rate(c, alpha, beta, a, 1.0 + 1.0 / n, zeta)
    if out is None:
        return math.inf
    _, h, _ = out
    return float(np.max(h[1.0 + a * np.cos(tau) > g[0]]))


def bisect(slides, lo: float, hi: float, rtol: float = 1e-7) -> float:
    """The smallest velocity in ``[lo, hi]`` at which ``slides(V)`` (monotone) holds."""
    assert not slides(lo) and slides(hi), (lo, hi)
    while hi - lo > rtol * hi:
        mid = 0.5 * (lo + hi)
        if slides(mid):
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)


def table_vc() -> None:
    print("\n## 1. `profile_critical_velocity` (inertial units, `mu0 F(d0)/(m omega)`)\n")
    print("`V_c`; in parentheses its ratio to the flat punch's eq. (12) "
          "(`theory.critical_inertial_velocity`, which holds for the flat punch at `a <= 1`).\n")
    print("| system (alpha, beta) | a | " + " | ".join(NAMES[n] for n in EXPONENTS) + " |")
    print("| --- | --- |" + " --- |" * len(EXPONENTS))
    for name, al, be, ze in SYSTEMS:
        for a in AMPLITUDES:
            eq12 = float(theory.critical_inertial_velocity(al, be, a, ze))
            cells = []
            for n in EXPONENTS:
                vc = float(theory.profile_critical_velocity(al, be, a, n, ze))
                cells.append(f"{vc:.5g} ({vc / eq12:.4f})")
            print(f"| {name} ({al:g}, {be:.4g}) | {a:g} | " + " | ".join(cells) + " |")


def grid_convergence() -> None:
    print("\nThe FFT grid (`theory._SLIDING_GRID = 2^15` points by default): `V_c` at "
          "`2^13, 2^15, 2^17` points, relative to the last; time of one "
          "`profile_critical_velocity` call (median of 11, default grid).\n")
    print("| (alpha, beta, a, n, zeta) | V_c (2^17) | 2^13 | 2^15 | ms a call |")
    print("| --- | --- | --- | --- | --- |")
    for al, be, a, n, ze in ((0.5, 2.0, 0.5, 2.0, 0.0), (0.5, 2.0, 1.5, 2.0, 0.0),
                             (0.5, 2.0, 1.5, 4.0, 0.0), (2.5, 6.0, 2.5, 0.7, 0.05),
                             (0.5, 2.0, 1.5, math.inf, 0.0)):
        v = [theory.profile._profile_critical(al, be, a, n, ze, N=1 << k) for k in (13, 15, 17)]
        times = []
        for _ in range(11):
            t0 = time.perf_counter()
            theory.profile_critical_velocity(al, be, a, n, ze)
            times.append(time.perf_counter() - t0)
        print(f"| ({al:g}, {be:g}, {a:g}, {n:g}, {ze:g}) | {v[2]:.15g} | "
              f"{v[0] / v[2] - 1:+.1e} | {v[1] / v[2] - 1:+.1e} | "
              f"{1e3 * float(np.median(times)):.1f} |")


def solver_check() -> None:
    print("\n## 2. Against the MDR solver\n")
    print("`mdr_friction` (default `tol` 1e-5) at `0.999 V_c` and `1.001 V_c`: `mu/mu0 "
          "+- error`, stick fraction of the disc. Then fixed rows of `M` springs "
          "(`mdr_row`): the onset of continuous sliding (stick fraction 0, periodic) "
          f"by bisection to {ROW_RTOL:g}, against the row's own `V_c` (the formula with "
          "the row's total normal force), relative to the continuum `V_c`.\n")
    print("| (alpha, beta, a, n, zeta) | V_c | 0.999 V_c: mu, stick | 1.001 V_c: mu, stick | "
          + " | ".join(f"M = {M}: onset/V_c - 1; row V_c/V_c - 1" for M in ROWS) + " |")
    print("| --- | --- | --- | --- |" + " --- |" * len(ROWS))
    for al, be, a, n, ze in SOLVER_POINTS:
        vc = float(theory.profile_critical_velocity(al, be, a, n, ze))
        cells = []
        for f in (0.999, 1.001):
            r = mdr_friction(al, be, a, f * vc, n, ze)
            cells.append(f"{r['mu_ratio']:.8f} +- {r['error']:.1e}, "
                         f"{r['stick_area_fraction']:.3g}")
        for M in ROWS:
            def slides(V, M=M, p=(al, be, a, n, ze)):  # no periodic orbit: no sliding
                r = mdr_row(*p[:3], V, p[3], M, p[4], max_periods=600)
                return r["status"] == "periodic" and r["stick_area_fraction"] == 0.0
            onset = bisect(slides, 0.98 * vc, 1.02 * vc, ROW_RTOL)
            own = row_critical(al, be, a, n, ze, M)
            cells.append(f"{onset / vc - 1:+.2e}; {own / vc - 1:+.2e}")
        print(f"| ({al:g}, {be:.4g}, {a:g}, {n:g}, {ze:g}) | {vc:.7g} | "
              + " | ".join(cells) + " |")


def flat_jumping() -> None:
    print("\n## 3. The jumping flat punch, `a = 1.5`, on the panels of Fig. 7\n")
    print("Onset of continuous sliding by bisection on `solve_points` (stick fraction 0), "
          "to 1e-7, against `profile_critical_velocity(..., inf)`; both also as "
          "`vbar = V/V_c(eq. 12)`.\n")
    print("| (alpha, beta) | eq. (12) V_c | V_c (lift-off) | vbar of V_c | solver onset/V_c - 1 |")
    print("| --- | --- | --- | --- | --- |")
    a = 1.5
    for be in MATRIX_BETAS:
        for al in MATRIX_ALPHAS:
            if not be > al:
                continue
            eq12 = float(theory.critical_inertial_velocity(al, be, a))
            vc = float(theory.profile_critical_velocity(al, be, a, math.inf))

            def slides(V, al=al, be=be):
                r = solve_points(al, be, a, V)
                return float(r["stick_fraction"]) == 0.0
            onset = bisect(slides, 0.98 * vc, 1.02 * vc)
            print(f"| ({al:g}, {be:g}) | {eq12:.6g} | {vc:.6g} | {vc / eq12:.4f} | "
                  f"{onset / vc - 1:+.1e} |")


def dead_weight() -> None:
    print("\n## 4. Dead weight\n")
    print("`d0/d_s` (`theory.dead_weight_indentation`) at `A = du_z/d_s`, `d_s` the "
          "indentation whose force is the load; the amplitude of the scaled model is then "
          "`a = A/(d0/d_s)`.\n")
    As = (0.25, 0.5, 1.0, 1.5, 1.8, 2.2, 3.0)
    print("| profile | " + " | ".join(f"A = {A:g}" for A in As) + " |")
    print("| --- |" + " --- |" * len(As))
    for n in EXPONENTS:
        cells = []
        for A in As:
            try:
                cells.append(f"{float(theory.dead_weight_indentation(A, n)):.5f}")
            except ValueError:
                cells.append("refused")
        print(f"| {NAMES[n]} | " + " | ".join(cells) + " |")
    steel = Material(E=210e9, nu=0.3)
    bench = dict(natural_frequency_hz=800, mass=0.2, normal_load=20, drive_frequency_hz=1000,
                 mu0=0.3, contact=Sphere(3e-3, steel, steel), contact_model="mdr")
    print("\nThe bench's sphere of docs/contact_geometry.md (`R = 3 mm`, steel, 20 N, "
          "`v0 = 1.5 mm/s`), both normal controls: `<F_N>` from the closed form "
          "(`Physical.mean_normal_force`) and from the MDR rows of springs (`mdr_friction`'s "
          "`mean_normal_ratio` times `F_N0`, the row without springs off, rows as in its "
          "result); `mu/mu0` by "
          "`friction_coefficient`.\n")
    print("| du_z (um) | control | d0 (um) | a | F_N0 (N) | <F_N> (N) | row <F_N> - <F_N> (N) | "
          "V_c (m/s) | mu/mu0 |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for du in (0.45e-6, 0.9e-6, 1.6e-6):
        for control in ("indentation", "dead_weight"):
            pin = vf.from_bench(**bench, du_z=du, normal_control=control)
            d = pin.to_dimensionless()
            r = vf.friction_coefficient(pin, v0=0.0015)
            with rows_alone():
                row = mdr_friction(d.alpha, d.beta, d.amplitude, float(r.v_inertial), 2.0)
            print(f"| {du * 1e6:g} | {control} | {pin.u_z0 * 1e6:.5f} | {d.amplitude:.4f} | "
                  f"{pin.F_N0:.4f} | {pin.mean_normal_force:.10g} | "
                  f"{row['mean_normal_ratio'] * pin.F_N0 - pin.mean_normal_force:+.1e} "
                  f"(rows {row['rows']}) | {pin.critical_velocity():.5g} | "
                  f"{float(r.mu_ratio):.5f} +- {float(r.error):.0e} |")


def main() -> None:
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip()
    print("# Continuous sliding of a curved contact; the dead weight\n")
    print("Regenerate: `PYTHONPATH=src python benchmarks/mdr_critical_numbers.py > "
          "benchmarks/results/mdr_critical.md` (machine: 2 shared cores).")
    print(f"\n# {time.strftime('%Y-%m-%d')}, commit {commit}, {platform.machine()} "
          f"{platform.python_version()}")
    t0 = time.perf_counter()
    table_vc()
    grid_convergence()
    solver_check()
    flat_jumping()
    dead_weight()
    print(f"\n{time.perf_counter() - t0:.0f} s", file=sys.stderr)


if __name__ == "__main__":
    main()
