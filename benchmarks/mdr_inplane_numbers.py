"""The MDR row with a longitudinal in-plane oscillation (issue 21, "everything else as
today"): the numbers of docs/contact_geometry.md, "In-plane oscillation along the sliding".

1. The flat punch (one spring) of the MDR solver with ``a_x`` against the single-spring
   solver ``solve_points`` (the 1-D exact kernels) at the points of
   tests/mdr/test_mdr_inplane.py.
2. The spring-row reference's flat punch with ``a_x`` against the 1-D in-plane reference
   (``vibrofriction_reference.inplane``, DOP853 with events), two independent integrators.
3. The MDR solver (``solve_points(..., profile_exponent=n, a_x=...)``) against the
   reference at the cached points of tests/data/mdr_inplane_reference.json (the reference
   re-run here, side by side: its time and the solver's, median of 3).
4. The solver's error bar against the independent spring row refined until its bar is at
   most 2e-6, at 24 random points (seed 5; cached by tests/data/make_mdr_fine_reference.py)
   and at one point where a bar of one difference of rows is short.
5. With ``--baseline REV``: without the oscillation (``a_x = 0``) the MDR solver's results
   bit for bit against that revision's ``src`` (exported by ``git archive``, run in a
   fresh process): ``mdr_friction`` and a row of 20 springs at five points.

    PYTHONPATH=src python benchmarks/mdr_inplane_numbers.py --baseline 9cb60b9 \
        > benchmarks/results/mdr_inplane.md
"""

from __future__ import annotations

import argparse
import json
import math
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from itertools import pairwise
from pathlib import Path

from vibrofriction.solver import solve_points
from vibrofriction.solver.mdr import mdr_friction, mdr_row
from vibrofriction_reference.inplane import inplane_mean
from vibrofriction_reference.mdr import mdr_mean, mdr_reference

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "data"))
from make_mdr_fine_reference import refine  # noqa: E402

FLAT = [  # (alpha, beta, a, V, zeta, a_x, phase_x, inplane_on), as tests/mdr/test_mdr_inplane.py
    (0.5, 2.0, 0.5, 0.3, 0.0, 0.5, 1.0, "substrate"),
    (0.7, 2.0, 0.5, 0.3, 0.0, 0.5, 1.0, "holder"),
    (1.3, 4.0, 1.4, 0.8, 0.05, 1.2, 2.5, "substrate"),
    (0.2, 0.9, 0.5, 0.05, 0.0, 0.3, 0.0, "holder"),
    (2.5, 3.0, 2.0, 0.4, 0.02, 0.8, 4.0, "substrate"),
    (1.0, 3.0, 0.9, 1.0, 0.1, 2.0, -1.0, "holder"),
    (0.5, 2.0, 0.3, 0.2, 0.1, 0.5, math.pi / 2, "substrate")]
REFERENCE_FLAT = (FLAT[0], (1.3, 4.0, 1.4, 0.8, 0.05, 1.2, 2.5, "holder"))  # as the test


#: (alpha, beta, a, V, zeta, n) of the a_x = 0 comparison: sphere, jumping sphere, damped
#: cone, n = 3, jumping flat punch
BITWISE = [(0.5, 2.0, 0.5, 0.3, 0.0, 2.0), (0.5, 2.0, 1.5, 0.3, 0.0, 2.0),
           (1.0, 3.0, 0.7, 0.5, 0.1, 1.0), (0.1, 0.5, 0.5, 0.05, 0.0, 3.0),
           (1.3, 4.0, 1.4, 0.8, 0.0, math.inf)]


def _bits() -> list:
    """The a_x = 0 results of :data:`BITWISE` as hex strings (runs on any revision: no
    in-plane keyword is passed)."""
    out = []
    for al, be, a, V, z, n in BITWISE:
        r = mdr_friction(al, be, a, V, n, zeta=z)
        w = mdr_row(al, be, a, V, n, 20, z)
        out.append([float(r["mu_ratio"]).hex(), float(r["error"]).hex(), r["periods"],
                    float(w["mu_ratio"]).hex(), w["periods"],
                    float(w["final_state"][0]).hex(), float(w["final_state"][1]).hex()])
    return out


#: where the first pair of rows (20, 40) agrees by chance: the bar of one difference is short
SHORT = (1.0, 3.0, 0.6, 0.4, 0.02, 2.0, 0.5, 0.5, "holder")


def _calibration() -> None:
    """The solver's error bar against the independent reference, refined until its bar is
    at most 2e-6 (tests/data/make_mdr_fine_reference.py, its cache)."""
    cache = json.loads((ROOT / "tests" / "data" / "mdr_fine_reference.json").read_text())
    pts = [p for p in cache["points"] if p["set"] == "calibration"]
    bars = [p["err_ref"] for p in pts]
    print("\n## 4. The solver's error against the independent reference\n")
    print(f"{len(pts)} random points (seed 5): n = 1, 2, 3 in turn, substrate and holder in "
          "turn, alpha in (0.2, 2), beta - alpha in (0.5, 4), a in (0.2, 1.8), V in (0.1, 1), "
          "zeta 0, 0.02 or 0.1, a_x in (0.2, 2), phase_x in (0, 2 pi). Reference: the "
          "spring row of `vibrofriction_reference.mdr` (no code shared with the solver) "
          "refined until its bar is at most 2e-6 (tests/data/mdr_fine_reference.json, made "
          f"by tests/data/make_mdr_fine_reference.py): bars median "
          f"{statistics.median(bars):.1e}, largest {max(bars):.1e}. `short` where "
          "|mdr_friction - reference| > its error + the reference's bar.\n")
    short, alone, ratios, combined, first, errors = 0, 0, [], [], 0, []
    for p in pts:
        r = mdr_friction(p["alpha"], p["beta"], p["amplitude"], p["v_inertial"],
                         p["profile_exponent"], zeta=p["zeta"], a_x=p["a_x"],
                         phase_x=p["phase_x"], inplane_on=p["inplane_on"])
        d = abs(r["mu_ratio"] - p["mu_ref"])
        short += d > r["error"] + p["err_ref"]
        alone += d > r["error"]
        ratios.append(d / r["error"])
        combined.append(d / (r["error"] + p["err_ref"]))
        errors.append(r["error"])
        first += r["rows"] == (20, 40)
    print(f"short: {short} of {len(pts)} (beyond its error alone: {alone}); |diff|/error "
          f"median {statistics.median(ratios):.2g}, largest {max(ratios):.2g}; "
          f"|diff|/(error + bar) median {statistics.median(combined):.2g}, largest "
          f"{max(combined):.2g}; the solver's errors {min(errors):.1e} to "
          f"{max(errors):.1e}; {first} of {len(pts)} stopped at the first pair (20, 40)\n")
    al, be, a, V, z, n, ax, px, on = SHORT
    kw = dict(a_x=ax, phase_x=px, inplane_on=on)
    r = mdr_friction(al, be, a, V, n, zeta=z, **kw)
    ref = refine(dict(label="short", alpha=al, beta=be, amplitude=a, v_inertial=V, zeta=z,
                      profile_exponent=n, **kw))
    rows = {M: mdr_row(al, be, a, V, n, M, z, **kw)["mu_ratio"] for M in (20, 40, 80, 160)}
    print(f"A short bar of one difference: ({al:g}, {be:g}, {a:g}, {V:g}, zeta {z:g}, "
          f"n = {n:g}, a_x {ax:g}, phase_x {px:g}, {on}): the reference "
          f"{ref['mu_ref']:.8f} +- {ref['err_ref']:.1e} (rows {ref['levels'][-1]}); the "
          "solver's rows from cold starts: "
          + ", ".join(f"{M}: {v:.8f}" for M, v in rows.items())
          + f" (20 and 40 agree by chance, 80 moves: a bar of their difference, "
          f"{abs(rows[40] - rows[20]):.1e}, is {abs(rows[40] - ref['mu_ref']):.1e} short); "
          f"mdr_friction (two differences) {r['mu_ratio']:.8f} +- {r['error']:.1e} (rows "
          f"{r['rows']}), {abs(r['mu_ratio'] - ref['mu_ref']):.1e} off.")


def _bits_in(src: Path) -> list:
    env = dict(os.environ, PYTHONPATH=str(src))
    out = subprocess.run([sys.executable, __file__, "--bits-only"], env=env, check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out)


def _median_time(f, repeat: int = 3) -> tuple[float, object]:
    times, out = [], None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = f()
        times.append(time.perf_counter() - t0)
    return statistics.median(times), out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--baseline", metavar="REV",
                        help="compare the a_x = 0 results with this revision's, bit for bit")
    parser.add_argument("--bits-only", action="store_true", help=argparse.SUPPRESS)
    opts = parser.parse_args()
    if opts.bits_only:
        print(json.dumps(_bits()))
        return
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True, cwd=ROOT).stdout.strip()
    print("# MDR row with a longitudinal in-plane oscillation\n")
    flag = f" --baseline {opts.baseline}" if opts.baseline else ""
    print(f"`PYTHONPATH=src python benchmarks/mdr_inplane_numbers.py{flag}`, "
          f"{time.strftime('%Y-%m-%d')}, commit {commit}, {platform.platform()} "
          "(the 2-core shared machine).\n")
    mdr_friction(0.5, 2.0, 0.5, 0.3, 2.0, a_x=0.5)  # compile / load the caches
    print("## 1. Flat punch: MDR solver (one spring) against the 1-D solver\n")
    print("| alpha | beta | a | V | zeta | a_x | phase_x | on | MDR | 1-D | diff |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    worst = 0.0
    for al, be, a, V, z, ax, px, on in FLAT:
        r = mdr_friction(al, be, a, V, math.inf, zeta=z, a_x=ax, phase_x=px, inplane_on=on)
        s = float(solve_points(al, be, a, V, zeta=z, a_x=ax, phase_x=px,
                               inplane_on=on)["mu_ratio"])
        d = r["mu_ratio"] - s
        worst = max(worst, abs(d))
        print(f"| {al:g} | {be:g} | {a:g} | {V:g} | {z:g} | {ax:g} | {px:.4g} | {on} | "
              f"{r['mu_ratio']:.12f} | {s:.12f} | {d:.1e} |")
    print(f"\nlargest |diff| {worst:.1e}\n")
    print("## 2. Reference flat punch: spring row against the 1-D in-plane reference\n")
    print("| point | row (200 springs, 400 steps) +- bar | 1-D DOP853 +- bar | diff |")
    print("| --- | --- | --- | --- |")
    for al, be, a, V, z, ax, px, on in REFERENCE_FLAT:
        ip = dict(a_x=ax, phase_x=px, inplane_on=on)
        row = mdr_reference(al, be, a, V, math.inf, transient_periods=200,
                            average_periods=20, zeta=z, **ip)
        one = inplane_mean(al, be, a, V, 100, 20, zeta=z, tolerance_check=False, **ip)
        print(f"| ({al:g}, {be:g}, {a:g}, {V:g}, zeta {z:g}, a_x {ax:g}, {px:g}, {on}) | "
              f"{row.mu_ratio:.8f} +- {row.mu_error:.1e} | {one.mu_ratio:.8f} +- "
              f"{one.mu_error:.1e} | {row.mu_ratio - one.mu_ratio:.1e} |")
    print("\n## 3. MDR solver against the spring-row reference\n")
    print("Reference: `mdr_reference` at the rows of tests/data/mdr_inplane_reference.json "
          "(300 + 20 periods), re-run here; solver: `solve_points` at `tol_trusted` "
          "(1e-5). `ratio` = |diff|/(solver error + reference bar), <= 1 within the bars.\n")
    print("| point | n | on | solver +- error | reference +- bar | diff | ratio | "
          "solver s | reference s |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    pts = json.loads((ROOT / "tests" / "data" / "mdr_inplane_reference.json").read_text())
    ratios, t_sol, t_ref = [], [], []
    for p in pts["points"]:
        args = (p["alpha"], p["beta"], p["amplitude"], p["v_inertial"], p["zeta"])
        ts, s = _median_time(lambda args=args, p=p: solve_points(
            *args, a_x=p["a_x"], phase_x=p["phase_x"],
            profile_exponent=p["profile_exponent"], inplane_on=p["inplane_on"]))
        t0 = time.perf_counter()
        ref = mdr_reference(p["alpha"], p["beta"], p["amplitude"], p["v_inertial"],
                            p["profile_exponent"],
                            resolutions=tuple(tuple(x) for x in p["resolutions"]),
                            transient_periods=pts["meta"]["transient_periods"],
                            average_periods=pts["meta"]["average_periods"], zeta=p["zeta"],
                            a_x=p["a_x"], phase_x=p["phase_x"], inplane_on=p["inplane_on"])
        tr = time.perf_counter() - t0
        mu, err = float(s["mu_ratio"]), float(s["error"])
        d = mu - ref.mu_ratio
        ratio = abs(d) / (err + ref.mu_error)
        ratios.append(ratio)
        t_sol.append(ts)
        t_ref.append(tr)
        print(f"| {p['label']} | {p['profile_exponent']:g} | {p['inplane_on']} | "
              f"{mu:+.8f} +- {err:.1e} | {ref.mu_ratio:+.8f} +- {ref.mu_error:.1e} | "
              f"{d:.1e} | {ratio:.2f} | {ts:.3f} | {tr:.2f} |")
    stiff = next(p for p in pts["points"] if p["label"] == "sphere substrate stiff damped")
    moves = [mdr_mean(stiff["alpha"], stiff["beta"], stiff["amplitude"], stiff["v_inertial"],
                      stiff["profile_exponent"], M, steps, 300, 20, zeta=stiff["zeta"],
                      a_x=stiff["a_x"], phase_x=stiff["phase_x"],
                      inplane_on=stiff["inplane_on"]).mu_ratio
             for M, steps in ((100, 200), (200, 400), (400, 800), (800, 1600))]
    print("\nThe stiff point's reference rows (100, 200) ... (800, 1600): "
          + ", ".join(f"{m:.8f}" for m in moves) + " (steps "
          + ", ".join(f"{abs(b - a):.1e}" for a, b in pairwise(moves)) + ")\n")
    within = sum(r <= 1.0 for r in ratios)
    print(f"\nwithin the combined bars: {within} of {len(ratios)} (largest ratio "
          f"{max(ratios):.2f}); time per point median: solver {statistics.median(t_sol):.3f} s,"
          f" reference {statistics.median(t_ref):.2f} s (its two rows)")
    _calibration()
    if opts.baseline:
        base = subprocess.run(["git", "rev-parse", "--short", opts.baseline],
                              capture_output=True, text=True, cwd=ROOT,
                              check=True).stdout.strip()
        with tempfile.TemporaryDirectory() as tmp:
            archive = subprocess.run(["git", "archive", base, "src"], cwd=ROOT, check=True,
                                     capture_output=True).stdout
            subprocess.run(["tar", "-x", "-C", tmp], input=archive, check=True)
            old = _bits_in(Path(tmp) / "src")
        new = _bits_in(ROOT / "src")
        print(f"\n## 5. Without the oscillation: this tree against {base}, bit for bit\n")
        print("`mdr_friction` (mu_ratio, error, periods) and `mdr_row` of 20 springs "
              "(mu_ratio, periods, final y, y') at a_x = 0, each tree in a fresh process.\n")
        print("| alpha, beta, a, V, zeta, n | mdr_friction mu_ratio | equal |")
        print("| --- | --- | --- |")
        for p, o, n in zip(BITWISE, old, new, strict=True):
            print(f"| {', '.join(f'{x:g}' for x in p)} | {float.fromhex(n[0]):.15f} | "
                  f"{'all 7 bit for bit' if o == n else 'DIFFERENT: ' + str((o, n))} |")


if __name__ == "__main__":
    main()
