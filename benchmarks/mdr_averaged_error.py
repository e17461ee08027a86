"""Is a curved tip's averaged answer honest?  The MDR rows' averages against the long-time mean.

A row of springs (:func:`vibrofriction.solver.mdr.mdr_row`) that finds no periodic orbit
within its ``max_periods`` (4000 by default) answers ``averaged``: the mean over the last half
of its periods, its error the range of the means over the last three doubling windows
(:func:`~vibrofriction.solver.mdr.averaged_row`, the event solver's rule).  The earlier rule
took the mean over the last 100 periods and the difference of that window's halves as the
error.

Here, at random points of the MDR solver's domain (cone, sphere, ``n = 4``; Coulomb and a
static limit above the kinetic one; jumping a third of the time), each row of 20 or 40
springs is run from the row's own start for :data:`LONG` periods.  A row still not periodic
after :data:`ANSWER` periods is one that answers ``averaged``; both rules are applied to its
first :data:`ANSWER` periods (the motion is the same as in a run that stops there) and compared
with the long-time mean: the mean over the last half of the long run, its own uncertainty the
range of the means of its last three doubling windows (a motion on an orbit of ``p`` periods
biases a window's mean where ``p`` does not divide its length); where the row becomes periodic
later, that orbit's mean.  Counted: the answers farther from it than their stated error plus
that uncertainty and :data:`ROUNDOFF` (the sums of thousands of periods carry a few 1e-13),
and by how much.

    PYTHONPATH=src python benchmarks/mdr_averaged_error.py [--seed 11] [--count 160] [--write]

``--write`` appends the run to benchmarks/results/mdr_averaged_error.md.
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np

from sections import append_run
from vibrofriction.solver.mdr import averaged_row, mdr_row

RESULTS = Path(__file__).parent / "results" / "mdr_averaged_error.md"
ANSWER = 4000  # the MDR rows' default max_periods
LONG = 2**15  # periods of the long run
ROUNDOFF = 1e-12  # allowed beyond the bars: round-off of the long sums


def _points(seed: int, count: int) -> list[dict]:
    """Random points of the MDR domain, drawn with ``seed``."""
    rng = np.random.default_rng(seed)
    pts = []
    for _ in range(count):
        alpha = float(10 ** rng.uniform(-1.3, 0.5))
        jumping = rng.random() < 1 / 3
        pts.append(dict(
            alpha=alpha, beta=alpha + float(10 ** rng.uniform(-0.5, 1.5)),
            amplitude=float(rng.uniform(1.0, 1.6) if jumping else rng.uniform(0.0, 1.0)),
            V=float(10 ** rng.uniform(-1.7, 0.0)),
            profile_exponent=float(rng.choice([1.0, 2.0, 4.0])),
            zeta=float(rng.choice([0.0, 0.01, 0.1])),
            static_ratio=float(1.0 if rng.random() < 0.5 else rng.uniform(1.1, 2.2)),
            n_springs=int(rng.choice([20, 40]))))
    return pts


def _old_rule(pf: np.ndarray, pn: np.ndarray) -> tuple[float, float]:
    """The earlier answer: the mean over the last 100 periods, the difference of its halves."""
    mu = float(np.sum(pf[-100:]) / np.sum(pn[-100:]))
    m1 = np.sum(pf[-100:-50]) / np.sum(pn[-100:-50])
    m2 = np.sum(pf[-50:]) / np.sum(pn[-50:])
    return mu, float(abs(m1 - m2)) + 1e-12


def bench(seed: int, count: int) -> list[str]:
    rows = ["| point (alpha, beta, a, V, n, zeta, s_r; springs) | long run | long-time mean "
            "| new: mu, error, miss/bars | old: mu, error, miss/bars |",
            "|---|---|---|---|---|"]
    n_avg = new_out = old_out = 0
    worst_new = worst_old = 0.0
    t0 = time.perf_counter()
    for p in _points(seed, count):
        kw = {k: v for k, v in p.items() if k != "n_springs"}
        kw["accelerate"] = kw["static_ratio"] == 1.0  # as mdr_friction runs its rows
        r = mdr_row(n_springs=p["n_springs"], max_periods=LONG, **kw)
        pf, pn = r["period_integrals"]
        if pf.size <= ANSWER or not np.all(np.isfinite(pf)):
            continue  # periodic within the answer's periods (or a failed run): no average
        n_avg += 1
        if r["status"] == "periodic":
            truth, unc = float(pf[-1] / pn[-1]), 1e-12
            how = f"periodic after {r['periods']}"
        else:
            truth, unc = averaged_row(pf, pn)
            how = f"{r['status']}, {LONG}"
        mu, err = averaged_row(pf[:ANSWER], pn[:ANSWER])
        mo, eo = _old_rule(pf[:ANSWER], pn[:ANSWER])
        qn = abs(mu - truth) / (err + unc + ROUNDOFF)
        qo = abs(mo - truth) / (eo + unc + ROUNDOFF)
        new_out += qn > 1.0
        old_out += qo > 1.0
        worst_new = max(worst_new, abs(mu - truth) if qn > 1.0 else 0.0)
        worst_old = max(worst_old, abs(mo - truth) if qo > 1.0 else 0.0)
        line = (f"| ({p['alpha']:.3g}, {p['beta']:.3g}, {p['amplitude']:.3g}, {p['V']:.3g}, "
                f"{p['profile_exponent']:g}, {p['zeta']:g}, {p['static_ratio']:.3g}; "
                f"{p['n_springs']}) | {how} | {truth:.9f} +- {unc:.1e} "
                f"| {mu:.9f}, {err:.1e}, {qn:.2g} "
                f"| {mo:.9f}, {eo:.1e}, {qo:.2g} |")
        print(line, flush=True)
        rows.append(line)
    rows += ["", f"{count} points (seed {seed}), {time.perf_counter() - t0:.0f} s: {n_avg} rows "
             f"not periodic after {ANSWER} periods. Beyond their stated error plus the long "
             f"mean's uncertainty and {ROUNDOFF:g}: the three-window "
             f"rule {new_out} (the largest such miss {worst_new:.1e}), the earlier halves of "
             f"100 periods {old_out} (the largest {worst_old:.1e})."]
    print(rows[-1])
    return rows


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--seed", type=int, default=11)
    ap.add_argument("--count", type=int, default=160)
    ap.add_argument("--write", action="store_true", help=f"append to {RESULTS}")
    args = ap.parse_args()
    lines = bench(args.seed, args.count)
    if args.write:
        append_run(RESULTS, "The MDR rows' averaged answers against the long-time mean",
                   f"PYTHONPATH=src python benchmarks/mdr_averaged_error.py --seed {args.seed} "
                   f"--count {args.count} --write",
                   f"each row run for {LONG} periods from its own start; the answers from its "
                   f"first {ANSWER}.", lines)


if __name__ == "__main__":
    main()
