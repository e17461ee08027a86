"""The fit numbers that docs/bench.md quotes ("Fit the model to the measurements"), regenerated.

Public API only (``import vibrofriction as vf``).  Most fits use the held-out data set
made by the independent reference (tests/data/reference_bench.csv, .json: peer B of
``vibrofriction_reference``, which shares no code with the solver being fitted; 48
points, 3 amplitudes, noise 0.003; truth: an 800 Hz pin of 20 g, Q = 50, k_xc = 3e6 N/m,
k_zc = 2e7 N/m, 20 N, mu0 = 0.3, driven at 1 kHz).

1. The default call (``free = mu0, mass, k_xc, u_z0``; ``k_x`` follows ``mass`` at the
   measured natural frequency, ``k_zc`` follows ``u_z0`` at the applied load) from the
   guess of tests/bench/test_fit.py (off by factors 0.6-1.6, the measured f_n and Q): verdict,
   intervals (do they hold the truth?), their widths, correlations, time by stage.
2. The shape of the profile: ``k_xc`` held at 0.5, 1 and 2 % either side of a best fit,
   the others refitted (a local fit from the best fit): the rise of the chi-square on
   each side (a parabola would rise equally); on a synthetic data set of
   benchmarks/bench_fit.py and on the reference data about the fit of 1.
3. A constraint at a wrong value: the natural frequency released (five varied), the
   pin's quality factor held at the guess's -- the measured Q = 50, then a wrong Q = 76
   (a local fit from the truth's other values): verdict, intervals, correlations.
   ``--full`` adds the whole fit (global stage) at Q = 76 from a poor guess.
4. A constraint at a wrong value, and a poor fit: the natural frequency held at 680,
   880 and 960 Hz (truth 800; a local fit from the truth's other values): verdict, which
   profile intervals exclude the truth, and the report of the first poor fit (its
   intervals the search range, the profile intervals kept in ``extra``).
5. Coverage of the profile interval of ``mu0`` alone: the protocol of the slow test
   ``test_coverage_of_the_profile_intervals_is_consistent_with_95_percent`` (160
   synthetic data sets, seed 2027), the count and the binomial tail probabilities.

Run: ``python benchmarks/fit_numbers.py [--workers 2] [--full]`` (writes
benchmarks/results/fit_numbers.md; about 2.5 min with 2 workers on 2 cores, 6-7 with
``--full``).
"""

from __future__ import annotations

import argparse
import datetime
import json
import os
import platform
import time
from pathlib import Path

import numpy as np
from scipy.stats import binom

import vibrofriction as vf

HERE = Path(__file__).resolve().parent
DATA = HERE.parent / "tests" / "data"
REFERENCE = json.loads((DATA / "reference_bench.json").read_text())
TRUTH = vf.Physical(**REFERENCE["truth"])
#: the guess of tests/bench/test_fit.py's four-parameter reference test: the measured f_n and Q,
#: the modal mass, contact stiffnesses and mu0 off by factors 0.6-1.6
GUESS = vf.from_bench(natural_frequency_hz=800, mass=0.012, quality_factor=50,
                               normal_load=20, k_zc=2.8e7, k_xc=4.8e6,
                               drive_frequency_hz=1000, du_z=0.6e-6, mu0=0.39)
FIVE = ["mu0", "mass", "k_x", "k_xc", "u_z0"]
#: the pin of tests/bench/test_fit.py (coverage, section 5)
PIN = vf.from_bench(natural_frequency_hz=800.0, mass=0.01, quality_factor=50.0,
                             normal_load=20.0, k_zc=2e7, k_xc=1.5e7, drive_frequency_hz=1000.0,
                             du_z=0.5e-6, mu0=0.3)


def _data():
    return vf.read_measurements(DATA / "reference_bench.csv")


def _fit_rows(res, truth: vf.Physical) -> list[str]:
    """A table of the fit's parameters: value, interval, width, truth inside."""
    rows = ["| parameter | truth | fit | 95 % interval | width / value | holds the truth |",
            "|---|---|---|---|---|---|"]
    for n, (lo, hi) in res.intervals.items():
        value, true = res.params[n].value, getattr(truth, n)
        rows.append(f"| {n} | {true:.4g} | {value:.4g} | [{lo:.4g}, {hi:.4g}] | "
                    f"{100 * (hi - lo) / value:.2g} % | {'yes' if lo <= true <= hi else 'NO'} |")
    return rows


def _summary(res, elapsed: float) -> list[str]:
    pairs = [(a, b, res.params[a].correl[b]) for i, a in enumerate(res.free)
             for b in res.free[i + 1:] if res.params[a].correl and b in res.params[a].correl]
    stages = "; ".join(f"{r['stage']} {r['seconds']:.1f} s ({r['evaluations']})"
                       for r in res.extra["stages"])
    return [f"* verdict: `{res.report().splitlines()[0]}`",
            f"* quality {res.quality}, p = {res.p_value:.2g}, chi-square {res.chisqr:.4g}, "
            f"penalised rows {res.penalised}",
            "* correlations: " + (", ".join(f"{a}/{b} {r:+.3f}" for a, b, r in pairs) or "none"),
            "* warnings: " + ("; ".join(res.warnings) or "none"),
            f"* time {elapsed:.1f} s; stages (seconds, model evaluations): {stages}"]


def default_call(workers: int):
    """Section 1: the default free list on the reference data; the fit, for section 2."""
    t = time.perf_counter()
    res = vf.fit(_data(), GUESS, workers=workers, progress=False)
    elapsed = time.perf_counter() - t
    lines = ["## 1. The default call on the reference data", "",
             "`vf.fit(reference_bench.csv, guess, workers=...)`: free = "
             f"{', '.join(res.free)} (k_x follows mass, k_zc follows u_z0); guess: mass 0.012, "
             "k_zc 2.8e7, k_xc 4.8e6, mu0 0.39, f_n 800 Hz, Q 50.", "",
             *_fit_rows(res, TRUTH), "", *_summary(res, elapsed), ""]
    return lines, res


def _profile_rows(data, best) -> list[str]:
    """``k_xc`` held off the best fit by -+0.5, 1, 2 %, the others refitted locally."""
    k = best.system.k_xc
    others = [n for n in best.free if n != "k_xc"]
    rows = ["| k_xc / best | rise below | rise above |", "|---|---|---|"]
    for step in (0.005, 0.01, 0.02):
        rise = [vf.fit(data, best.system.with_(k_xc=k * f), free=others, global_stage=False,
                       progress=False).chisqr - best.chisqr for f in (1.0 - step, 1.0 + step)]
        rows.append(f"| 1 -+ {step:g} | {rise[0]:.3g} | {rise[1]:.3g} |")
    lo, hi = best.intervals["k_xc"]
    return [f"k_xc held at the best fit ({k:.5g}) times 1 -+ step, {', '.join(others)} "
            f"refitted (a local fit from the best fit); the rise of the chi-square from "
            f"{best.chisqr:.4g} ({best.quality} fit). The interval's level is a rise of "
            f"{4.0 * max(best.redchi, 1.0):.3g}; its ends lie at {100 * (lo / k - 1):+.2f} % "
            f"and {100 * (hi / k - 1):+.2f} % of the best fit.", "", *rows, ""]


def profile_shape(best) -> list[str]:
    """Section 2: the profile of ``k_xc`` on the synthetic data set of bench_fit.py
    (noise seed 11; ``mu0, k_xc`` free, a local fit from mu0 0.33, k_xc 1.8e7) and on the
    reference data about the fit of section 1."""
    synthetic = vf.synthetic_measurements(PIN, (0.3e-6, 0.6e-6, 0.9e-6),
                                          np.geomspace(1e-3, 0.2, 20), 0.003,
                                          np.random.default_rng(11))
    fit2 = vf.fit(synthetic, PIN.with_(mu0=0.33, k_xc=1.8e7), free=["mu0", "k_xc"],
                  global_stage=False, progress=False)
    return ["## 2. The shape of the profile of k_xc", "",
            "### Synthetic data of benchmarks/bench_fit.py (noise seed 11; the pin of "
            "tests/bench/test_fit.py, k_xc = 1.5e7; 3 amplitudes x 20 velocities), mu0 and k_xc "
            "free", "", *_profile_rows(synthetic, fit2),
            "### The reference data, about the fit of section 1", "",
            *_profile_rows(_data(), best)]


def held_quality_factor(workers: int, full: bool) -> list[str]:
    """Section 3: five varied, the pin's quality factor held at 50 (measured), then 76: a
    local fit from the truth's other values (mu0 0.33); with ``full``, also the whole fit
    (global stage) from the guess of section 1 with k_x 20 % high, Q = 76 (section 3b)."""
    lines = ["## 3. A constraint at a wrong value: the quality factor", "",
             f"free = {', '.join(FIVE)}, `natural_frequency=False`, the quality factor "
             "held at the guess's (the default `quality_factor=True`). Guess: the truth "
             "with mu0 0.33 and its damping set to Q; `global_stage=False` (a local fit "
             "from there).", ""]
    cases = [(f"Q held at {q:g} (truth 50)", TRUTH.with_(mu0=0.33).with_damping(
        quality_factor=q), False) for q in (50.0, 76.0)]
    if full:
        cases.append(("3b. Q held at 76, the whole fit (global stage) from the guess of "
                      "section 1 with k_x 20 % high (f_n 876 Hz)",
                      GUESS.with_(k_x=GUESS.k_x * 1.2).with_damping(quality_factor=76.0),
                      True))
    for title, guess, global_stage in cases:
        t = time.perf_counter()
        res = vf.fit(_data(), guess, free=FIVE, natural_frequency=False, workers=workers,
                     global_stage=global_stage, progress=False)
        elapsed = time.perf_counter() - t
        lines += [f"### {title}", "", *_fit_rows(res, TRUTH), "", *_summary(res, elapsed), ""]
    if not full:
        lines += ["(`--full` adds 3b: Q held at 76, the whole fit with its global stage from "
                  "the guess of section 1 with k_x 20 % high; about 4 min more.)", ""]
    return lines


def natural_frequency_held(workers: int) -> list[str]:
    """Section 4: the natural frequency held off the truth's 800 Hz."""
    rows = ["| f_n held (Hz) | verdict | p | chi-square | mass | k_xc | profile intervals "
            "that exclude the truth | time (s) |", "|---|---|---|---|---|---|---|---|"]
    first = []
    for ratio in (0.85, 1.1, 1.2):
        guess = TRUTH.with_(k_x=TRUTH.k_x * ratio ** 2, mu0=0.33).with_damping(zeta=TRUTH.zeta)
        t = time.perf_counter()
        res = vf.fit(_data(), guess, global_stage=False, workers=workers, progress=False)
        elapsed = time.perf_counter() - t
        profile = res.extra.get("profile_intervals") or res.intervals
        wrong = [n for n, (lo, hi) in profile.items() if not lo <= getattr(TRUTH, n) <= hi]
        rows.append(f"| {800 * ratio:.0f} | {res.quality} | {res.p_value:.2g} | "
                    f"{res.chisqr:.4g} | {res.system.mass:.4g} | {res.system.k_xc:.4g} | "
                    f"{', '.join(wrong) or 'none'} | {elapsed:.1f} |")
        if res.quality == "poor" and not first:
            first = [f"The report of the fit at {800 * ratio:.0f} Hz begins:", "", "```",
                     *res.report().splitlines()[:10], "```", "",
                     "and `res.extra['profile_intervals']` keeps the profile intervals: " +
                     "; ".join(f"{n} [{lo:.4g}, {hi:.4g}]" for n, (lo, hi) in profile.items()),
                     ""]
    return ["## 4. A constraint at a wrong value: the natural frequency", "",
            "The default call on the reference data, the guess's natural frequency (held by "
            "`natural_frequency=True`) off the truth's 800 Hz, mu0 0.33, Q 50, the other values "
            "the truth's; `global_stage=False` (a local fit from there).", "", *rows, "",
            *first]


def coverage(n: int = 160) -> list[str]:
    """Section 5: the protocol of the slow coverage test (mu0 alone)."""
    rng = np.random.default_rng(2027)
    hits, t = 0, time.perf_counter()
    for _ in range(n):
        true = PIN.with_(mu0=float(rng.uniform(0.2, 0.5)),
                         k_xc=float(rng.choice([5e6, 1.5e7, 6e7])))
        data = vf.synthetic_measurements(true, (0.3e-6, 0.9e-6), np.geomspace(1e-3, 0.2, 6),
                                         0.003, rng)
        res = vf.fit(data, true.with_(mu0=true.mu0 * 1.1), free=["mu0"], progress=False,
                     global_stage=False)
        lo, hi = res.intervals["mu0"]
        hits += lo <= true.mu0 <= hi
    return ["## 5. Coverage of the profile interval (mu0 alone)", "",
            f"{n} synthetic data sets (the pin of tests/bench/test_fit.py, mu0 uniform in 0.2-0.5, "
            "k_xc one of 5e6, 1.5e7, 6e7; 2 amplitudes x 6 velocities, noise 0.003; seed "
            f"2027): the truth lies in the 95.4 % interval in **{hits} of {n}** "
            f"({100 * hits / n:.1f} %). Binomial(p = 0.954) tails: P(X <= {hits}) = "
            f"{binom.cdf(hits, n, 0.954):.2g}, P(X >= {hits}) = "
            f"{binom.sf(hits - 1, n, 0.954):.2g} (the test refuses either below 1e-3). "
            f"{time.perf_counter() - t:.0f} s.", ""]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--full", action="store_true",
                    help="add section 3b (a whole five-parameter fit, about 4 min)")
    args = ap.parse_args()
    t0 = time.perf_counter()
    vf.fit(_data().head(6), TRUTH, free=["mu0"], global_stage=False, progress=False)  # warm up
    lines = [f"# Fit numbers ({datetime.date.today()}, "
             f"{platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
             f"workers={args.workers}{', --full' if args.full else ''}, load average "
             f"{os.getloadavg()[0]:.1f} at the start)", "",
             "`python benchmarks/fit_numbers.py`: the numbers of docs/bench.md's fit section. "
             f"Reference data: tests/data/reference_bench.csv ({REFERENCE['reference']}, "
             f"error bar {REFERENCE['reference_error_bar_cof']:.1e} in the COF, noise "
             f"{REFERENCE['sigma']}).", ""]
    section, best = default_call(args.workers)
    lines += section
    lines += profile_shape(best)
    lines += held_quality_factor(args.workers, args.full)
    lines += natural_frequency_held(args.workers)
    lines += coverage()
    lines += [f"Total {time.perf_counter() - t0:.0f} s.", ""]
    out = HERE / "results" / "fit_numbers.md"
    out.write_text("\n".join(lines))
    print(out.read_text())


if __name__ == "__main__":
    main()
