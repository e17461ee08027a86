"""The time history of a curved tip (issue 21): the numbers of docs/contact_geometry.md,
"The history".

``simulate(..., profile_exponent=n)`` records the MDR row at the sample times
(vibrofriction.solver.mdr_history). Measured here, at the points of
tests/mdr/test_mdr_history.py:

* the energy balance ``work_input - dissipated_pin - dissipated_friction = stored -
  stored(0)`` at every sample of 20 periods from the sliding start, and per period on the
  periodic orbit (the drive's work against the dissipation);
* one period of the periodic orbit against ``solve_points`` (``mu_ratio`` and its error,
  the extrapolated MDR solver) and ``theory.profile_mean_normal_force``;
* ``max(|f_i| - n_i)`` over every spring and sample, also at 2 x 300 random points (with
  and without a longitudinal in-plane oscillation);
* every spring's force against the independent spring-row reference
  (``vibrofriction_reference.mdr.mdr_mean``, 40 springs, 300 periods) at 200, 800, 3200
  steps a period;
* the time of one history (median of 5).

    PYTHONPATH=src python benchmarks/mdr_history_numbers.py > benchmarks/results/mdr_history.md
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
from vibrofriction.solver import solve_points
from vibrofriction.solver.mdr import mdr_friction, rows_alone
from vibrofriction_reference.mdr import mdr_mean

#: (alpha, beta, a, V, n, zeta): sphere, jumping sphere (damped), cone, soft n = 3
POINTS = [(0.5, 2.0, 0.5, 0.3, 2.0, 0.0), (0.5, 2.0, 1.5, 0.3, 2.0, 0.1),
          (1.0, 3.0, 0.7, 0.5, 1.0, 0.1), (0.05, 0.1, 0.5, 2.0, 3.0, 0.5)]


#: with a longitudinal in-plane oscillation: (point, a_x, phase_x, inplane_on)
INPLANE = [((0.5, 2.0, 0.5, 0.3, 2.0, 0.1), 0.5, 1.0, "substrate"),
           ((0.5, 2.0, 0.5, -0.3, 2.0, 0.1), 0.5, 1.0, "holder"),
           ((1.0, 3.0, 1.3, 0.5, 1.0, 0.0), 0.8, 2.5, "substrate")]


def dim(alpha, beta, a, n, zeta, **inplane):
    return vf.Dimensionless(alpha, beta, a, zeta=zeta, profile_exponent=n, **inplane)


def balance(h) -> np.ndarray:
    E = h.stored_energy()
    return h.work_input - h.dissipated_pin - h.dissipated_friction - (E - E[0])


BALANCE_BOUND = 1e-10
"""The orbit's ``(W - D)/W`` is printed as this bound where below it: its digits below are
round-off that differ from one processor to another (-3.1e-12 and -5.0e-12 at the jumping
cone on two machines)."""


def _bound(x: float, bound: float) -> str:
    return f"{x:.1e}" if abs(x) >= bound else f"< {bound:.0e}"


def energy() -> None:
    print("\n## Energy balance\n")
    print("From the sliding start, 20 periods, 200 samples a period, 160 springs: the largest "
          "`|work_input - dissipated - (stored - stored(0))|` over the samples, and relative "
          "to the work input. On the periodic orbit (`initial=\"steady\"`, 160 springs), one "
          "period: the drive's work `W = V int f`, the pin's and friction's dissipation, "
          "`(W - D_pin - D_friction)/W` (below 1e-10: round-off, printed as that bound).\n")
    print("| point (alpha, beta, a, V, n, zeta) | residual, 20 periods | relative | W a period "
          "| D_pin | D_friction | (W - D)/W |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    cases = [(p, {}) for p in POINTS] + [
        (p, dict(a_x=ax, phase_x=px, inplane_on=on)) for p, ax, px, on in INPLANE]
    for p, ip in cases:
        alpha, beta, a, V, n, zeta = p
        h = vf.simulate(dim(alpha, beta, a, n, zeta, **ip), v_inertial=V, periods=20,
                        samples_per_period=200)
        r = float(np.max(np.abs(balance(h))))
        s = vf.simulate(dim(alpha, beta, a, n, zeta, **ip), v_inertial=V, periods=1,
                        samples_per_period=200, initial="steady")
        if ip:
            p = (*p, f"a_x {ip['a_x']}, phase_x {ip['phase_x']}, {ip['inplane_on']}")
        W, Dp, Df = s.work_input[-1], s.dissipated_pin[-1], s.dissipated_friction[-1]
        print(f"| {p} | {r:.1e} | {r / h.work_input[-1]:.1e} | {W:.6f} | {Dp:.6f} | "
              f"{Df:.6f} | {_bound((W - Dp - Df) / W, BALANCE_BOUND)} |")


def steady() -> None:
    print("\n## One period of the periodic orbit against the solver and the closed form\n")
    print("`springs` = the finer row of `mdr_friction`'s rows of springs at `tol = 1e-5` "
          "(the row without springs off), `rows +- error` their extrapolation; 400 samples. "
          "`mu` = `int f / int n` over the period (the exact impulses), `mu (samples)` the "
          "samples' means; `solve_points` the MDR solver (the row without springs) with its "
          "`error`; "
          "`<n>` the exact mean of `n` against `theory.profile_mean_normal_force`; the largest "
          "`|f_i| - n_i` relative to the largest `n_i`.\n")
    print("| point | springs | mu | mu (samples) | rows +- error | solve_points +- error "
          "| <n> - closed form | max(abs(f_i) - n_i) |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- |")
    for p in POINTS:
        alpha, beta, a, V, n, zeta = p
        with rows_alone():
            rows = mdr_friction(alpha, beta, a, V, n, zeta=zeta)
        M = rows["rows"][1]
        h = vf.simulate(dim(alpha, beta, a, n, zeta), v_inertial=V, periods=1,
                        samples_per_period=400, initial="steady", springs=M)
        mu = h.impulse[-1, 0] / h.normal_impulse[-1]
        mu_s = h.f[:-1].mean() / h.n[:-1].mean()
        pt = solve_points(alpha, beta, a, V, zeta, profile_exponent=n)
        dn = h.normal_impulse[-1] / (2 * math.pi) - float(theory.profile_mean_normal_force(a, n))
        nn = h.spring_normal()
        ex = float(np.max(np.abs(h.spring_f) - nn)) / float(np.max(nn))
        print(f"| {p} | {M} | {mu:.7f} | {mu_s:.7f} | {rows['mu_ratio']:.7f} +- "
              f"{rows['error']:.1e} | {float(pt['mu_ratio']):.7f} +- "
              f"{float(pt['error']):.1e} | {dn:+.1e} | {ex:.1e} |")


def reference() -> None:
    print("\n## Every spring's force against the spring-row reference\n")
    print("`mdr_mean` (its own code), 40 springs, 300 periods from its own start, "
          "the last period recorded; the history on the periodic orbit at the reference's "
          "step times: the largest `|f_i - f_i,ref|` over springs and samples, relative to "
          "the largest `n_i`.\n")
    steps = (200, 800, 3200)
    print("| point | " + " | ".join(f"{s} steps" for s in steps) + " |")
    print("| --- " * (1 + len(steps)) + "|")
    for p in POINTS[:3]:
        alpha, beta, a, V, n, zeta = p
        out = []
        for s in steps:
            ref = mdr_mean(alpha, beta, a, V, n, springs=40, steps_per_period=s,
                           transient_periods=300, average_periods=1, zeta=zeta,
                           record_last_period=True)
            h = vf.simulate(dim(alpha, beta, a, n, zeta), v_inertial=V, periods=1,
                            samples_per_period=ref.steps_per_drive_period, springs=40,
                            initial="steady")
            nn = h.spring_normal()
            out.append(float(np.max(np.abs(h.spring_f - ref.spring_f)) / np.max(nn)))
        print(f"| {p} | " + " | ".join(f"{d:.1e}" for d in out) + " |")


def random_points() -> None:
    print("\n## Random points\n")
    print("300 points each (40 springs, 2 periods from the sliding start, 100 samples a "
          "period): `alpha` in (0.05, 3), `beta - alpha` in (0.1, 5), `a` in (0, 2.5), "
          "`V` in (0, 2), `n` in {0.7, 1, 2, 4}, `zeta` in {0, 0.1}; with the in-plane "
          "oscillation also `a_x` in (0, 1.5), `phase_x` in (0, 6.3), both mounts, `|V|` in "
          "(0.05, 2) of either sign. The largest `|f_i| - n_i` over springs and samples "
          "relative to the largest `n_i`, and the largest energy-balance residual relative "
          "to `max(1, work_input)`.\n")
    print("| set | seed | max (abs(f_i) - n_i) | max balance residual |")
    print("| --- | --- | --- | --- |")
    for label, seed, inplane in (("no in-plane oscillation", 1, False),
                                 ("longitudinal in-plane oscillation", 2, True)):
        rng = np.random.default_rng(seed)
        worst_f = worst_b = 0.0
        for _ in range(300):
            alpha, k, a = rng.uniform(0.05, 3), rng.uniform(0.1, 5), rng.uniform(0, 2.5)
            n, zeta = rng.choice([0.7, 1.0, 2.0, 4.0]), rng.choice([0.0, 0.1])
            ip = {}
            if inplane:
                V = rng.uniform(0.05, 2) * (1 if rng.random() < 0.5 else -1)
                ip = dict(a_x=rng.uniform(0, 1.5), phase_x=rng.uniform(0, 6.3),
                          inplane_on=str(rng.choice(["substrate", "holder"])))
            else:
                V = rng.uniform(0, 2)
            h = vf.simulate(dim(alpha, alpha + k, a, float(n), float(zeta), **ip),
                            v_inertial=V, periods=2, samples_per_period=100, springs=40)
            nn = h.spring_normal()
            worst_f = max(worst_f, float(np.max(np.abs(h.spring_f) - nn) / np.max(nn)))
            worst_b = max(worst_b, float(np.max(np.abs(balance(h))))
                          / max(1.0, abs(h.work_input[-1])))
        print(f"| {label} | {seed} | {worst_f:.1e} | {worst_b:.1e} |")


def timing() -> None:
    print("\n## Time\n")
    print("`simulate(..., periods=1, samples_per_period=400, initial=\"steady\")` (the row's "
          "periodic orbit first), and 10 periods from the sliding start; median of 5, warm.\n")
    print("| point | springs | steady, 1 period | sliding, 10 periods |")
    print("| --- | --- | --- | --- |")
    for p in POINTS:
        alpha, beta, a, V, n, zeta = p
        for M in (160, 640):
            ts = []
            for kw in (dict(periods=1, initial="steady"), dict(periods=10)):
                vf.simulate(dim(alpha, beta, a, n, zeta), v_inertial=V, springs=M,
                            samples_per_period=400, **kw)
                t = []
                for _ in range(5):
                    t0 = time.perf_counter()
                    vf.simulate(dim(alpha, beta, a, n, zeta), v_inertial=V, springs=M,
                                samples_per_period=400, **kw)
                    t.append(time.perf_counter() - t0)
                ts.append(float(np.median(t)))
            print(f"| {p} | {M} | {1e3 * ts[0]:.0f} ms | {1e3 * ts[1]:.0f} ms |")


def main() -> None:
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True, check=False).stdout.strip()
    print("# The MDR time history: numbers\n")
    print("Regenerate: `PYTHONPATH=src python benchmarks/mdr_history_numbers.py > "
          "benchmarks/results/mdr_history.md`")
    print(f"\n# {time.strftime('%Y-%m-%d')}, commit {commit}, {platform.machine()} "
          f"{platform.python_version()}, the 2-core shared machine")
    t0 = time.perf_counter()
    energy()
    steady()
    reference()
    random_points()
    timing()
    print(f"\n{time.perf_counter() - t0:.0f} s", file=sys.stderr)


if __name__ == "__main__":
    main()
