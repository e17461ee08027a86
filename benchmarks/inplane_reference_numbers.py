"""The numbers of docs/inplane_reference.md: accuracy and cost of the in-plane reference.

    PYTHONPATH=src python benchmarks/inplane_reference_numbers.py

(1) zero in-plane amplitude against the 1-D peer A (same windows, rtol 1e-10);
(2) tolerance convergence of mu at 2-D points (rtol 1e-6 ... 1e-12, 20 + 10 periods);
(3) distance to the kinematic laws against the stiffness S (alpha = S, k = S);
(4) cost: wall time of inplane_mean (100 + 40 periods, with the tolerance check) per point.
"""

import math
import platform
import subprocess
import time

from scipy.special import ellipk

from vibrofriction_reference import inplane_mean, inplane_run, solve_ivp_mu

POINTS_2D = {
    "combined x, pi/2": ((0.5, 2.0, 0.5, 0.3), {"a_x": 0.5, "phase_x": math.pi / 2}),
    "2-D, jumping, KV": ((0.3, 2.0, 1.5, 0.4), {"zeta": 0.02, "eta_c": 0.3, "a_x": 0.4,
                                                "phase_x": 1.0, "a_y": 0.3,
                                                "phase_y": 0.5}),
    "2-D holder": ((0.5, 2.0, 0.5, 0.3), {"zeta": 0.05, "a_x": 0.3, "phase_x": 0.7,
                                          "a_y": 0.4, "phase_y": 2.0,
                                          "inplane_on": "holder"}),
    "2-D Jenkins, jumping": ((0.5, 2.0, 1.5, 0.3), {"a_y": 0.4, "phase_y": 2.0}),
    "transverse, V = 0": ((0.5, 2.0, 0.5, 0.0), {"eta_c": 0.1, "a_y": 0.5}),
}


def main():
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip()
    print(f"# {time.strftime('%Y-%m-%d')}, commit {commit}, {platform.node()}, "
          f"{platform.processor() or platform.machine()}")
    print("\n(1) a_x = a_y = 0 against peer A (10 + 5 periods, rtol 1e-10)")
    for p, kw in [((0.5, 2.0, 0.5, 0.3), {}), ((0.5, 2.0, 1.5, 1.0), {}),
                  ((0.5, 2.0, 0.5, 0.3), {"zeta": 0.05, "eta_c": 0.5}),
                  ((0.3, 2.0, 1.5, 0.4), {"zeta": 0.02, "eta_c": 0.3}),
                  ((1.0, 5.3, 0.5, 1.0), {"zeta": 0.02, "eta_c": 0.1})]:
        d = inplane_run(*p, 10, 5, **kw).mu_ratio - solve_ivp_mu(*p, 10, 5, **kw)
        print(f"  {p} {kw}: {d:.2e}")
    print("\n(2) tolerance convergence, 20 + 10 periods: |mu(rtol) - mu(1e-13)|, atol = "
          "rtol/100; nfev at rtol 1e-10")
    for name, (p, kw) in POINTS_2D.items():
        ref = inplane_run(*p, 20, 10, 1e-13, 1e-15, **kw)
        row = []
        for rtol in (1e-6, 1e-8, 1e-10, 1e-12):
            r = inplane_run(*p, 20, 10, rtol, rtol / 100, **kw)
            row.append(f"{abs(r.mu_ratio - ref.mu_ratio):.1e}/"
                       f"{abs(r.lateral_ratio - ref.lateral_ratio):.1e}")
            if rtol == 1e-10:
                nfev = r.nfev
        print(f"  {name}: mu/lateral " + "  ".join(row) + f"  nfev {nfev}")
    print("\n(3) kinematic laws, a = 0, zeta = 0.7, amplitude 5, 8 + 4 periods: |mu - law|")
    law_x = (2 / math.pi) * math.asin(0.5)
    eps = 1.0
    law_y = (2 / math.pi) * ellipk(eps**2 / (1 + eps**2)) / math.sqrt(1 + eps**2)
    for S in (25.0, 100.0, 400.0, 1600.0):
        row = []
        for mode in ("substrate", "holder"):
            for eta in (0.0, 0.2):
                ex = inplane_run(S, 2 * S, 0.0, 2.5, 8, 4, zeta=0.7, eta_c=eta, a_x=5.0,
                                 inplane_on=mode).mu_ratio - law_x
                row.append(f"x {mode[0]} eta_c={eta}: {abs(ex):.1e}")
            ey = inplane_run(S, 2 * S, 0.0, 5.0, 8, 4, zeta=0.7, eta_c=0.2, a_y=5.0,
                             inplane_on=mode).mu_ratio - law_y
            row.append(f"y {mode[0]} eta_c=0.2: {abs(ey):.1e}")
        print(f"  S = {S:g}: " + ", ".join(row))
    print("\n(4) inplane_mean(100 + 40 periods, tolerance check): value, errors, wall time")
    for name, (p, kw) in POINTS_2D.items():
        t = time.perf_counter()
        m = inplane_mean(*p, 100, 40, **kw)
        dt = time.perf_counter() - t
        print(f"  {name}: mu {m.mu_ratio:.10f} +- {m.mu_error:.1e}, lateral "
              f"{m.lateral_ratio:.10f} +- {m.lateral_error:.1e}, stick/slip/flight "
              f"{m.stick_fraction:.3f}/{m.slip_fraction:.3f}/{m.flight_fraction:.3f}, "
              f"{dt:.1f} s")


if __name__ == "__main__":
    main()
