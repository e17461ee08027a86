"""Is an averaged answer's error honest?  The event solver's averages against the motion's
long-time mean.

An ``averaged`` answer (no periodic orbit: a motion not locked to the drive) states as its
error the range of its last three doubling windows' means, and no average answers while the
motion is near a periodic orbit (docs/solver.md, "What error means").  Here, over fresh
random points of every flat-punch regime (``tests/reference_points.random_points``, each
undamped and with a random pin dashpot and contact loss factor, as
``differential_campaign.py`` draws them) and of the static law (``static_kinetic_points``),
every point the solver answers ``averaged`` or ``not converged`` is integrated on for
``2**19`` drive periods by the solver's own period map from the same start; the mean over
the last half of that run is the long-time mean (its own uncertainty: the range of its last
three doubling windows' means).  Counted: the averaged answers whose distance to it is
beyond their stated error, and (from the same runs) what the earlier rule would have
answered: the difference of the last two windows' means as the error, and no test of a
nearby orbit.

    PYTHONPATH=src:tests python benchmarks/averaged_error.py [--seeds 7031-7070] [--write]

``--write`` appends the run to benchmarks/results/averaged_error.md.
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

import numpy as np

import vibrofriction as vf
from reference_points import REGIMES, random_points, static_kinetic_points
from sections import append_run
from vibrofriction._kernels.jit import jit
from vibrofriction._kernels.period import A_F, A_N, N_ACC, advance_counted
from vibrofriction._kernels.phases import frame_offset, make_model
from vibrofriction._kernels.steady import _start

RESULTS = Path(__file__).parent / "results" / "averaged_error.md"
LONG = 2**19  # drive periods of the long run
TOL_MEAN = 1e-7  # the event solver's default tol_mean
MIN_PERIODS, MAX_PERIODS = 64, 20_000  # ... and its checkpoints


@jit
def _long_run(M, z, n):
    """Running sums of ``f`` and ``n`` after each of ``n`` periods from ``z``."""
    acc = np.zeros(N_ACC)
    count = np.zeros(3, np.int64)
    F, N = np.empty(n), np.empty(n)
    for k in range(n):
        ok, _ = advance_counted(z, acc, count, M, 10**9)
        if not ok:
            return F[:k], N[:k]
        F[k], N[k] = acc[A_F], acc[A_N]
    return F, N


def points(seed: int, per: int, static: int):
    """``(alpha, beta, a, V, zeta, eta_c, s_r, initial)`` of the campaign's streams."""
    rng = np.random.default_rng([seed, 99])
    for regime in REGIMES:
        for alpha, beta, a, V in random_points(seed, per, regime):
            yield alpha, beta, a, V, 0.0, 0.0, 1.0, "sliding"
            zeta = float(10 ** rng.uniform(-2.3, 0.3)) if rng.uniform() < 0.8 else 0.0
            eta = float(rng.choice([0.0, 0.0, 0.05, 0.3, 1.0])) if math.isfinite(beta) else 0.0
            yield alpha, beta, a, V, zeta, eta, 1.0, "sliding"
    for alpha, beta, a, V, zeta, sr, initial in static_kinetic_points(static, [seed, 55]):
        yield alpha, beta, a, V, zeta, 0.0, sr, initial


def _checkpoints() -> list[int]:
    ks, k = [], MIN_PERIODS
    while k < MAX_PERIODS:
        ks.append(k)
        k *= 2
    return [*ks, MAX_PERIODS]


def _mean(F: np.ndarray, N: np.ndarray, k0: int, k1: int) -> float:
    """The mean of ``f/n`` over periods ``(k0, k1]``."""
    f0, n0 = (F[k0 - 1], N[k0 - 1]) if k0 > 0 else (0.0, 0.0)
    return float((F[k1 - 1] - f0) / (N[k1 - 1] - n0))


def earlier_rule(F: np.ndarray, N: np.ndarray) -> tuple[float, float] | None:
    """The answer of the earlier rule, ``(mu, error)``: the first checkpoint where the last
    two windows' means agree within ``TOL_MEAN`` (their difference the error), or None."""
    ks = _checkpoints()
    for i in range(2, len(ks)):
        m1, m0 = _mean(F, N, ks[i - 1], ks[i]), _mean(F, N, ks[i - 2], ks[i - 1])
        if abs(m1 - 1.0) < 1e-15:  # pure forward slip (mean 1 whatever the state): no answer
            continue
        err = max(abs(m1 - m0), 1e-13 * (1 + abs(m1)))
        if err <= TOL_MEAN:
            return m1, err
    return None


def survey(seed: int, per: int, static: int) -> list[dict]:
    """The points of ``seed`` answered averaged or not converged, with the long run's mean."""
    rows = []
    for alpha, beta, a, V, zeta, eta, sr, initial in points(seed, per, static):
        r = vf.friction_coefficient(vf.Dimensionless(alpha, beta, a, zeta=zeta, eta_c=eta,
                                                     static_ratio=sr),
                                    v_inertial=V, initial=initial)
        if r.status not in (vf.Status.AVERAGED, vf.Status.NOT_CONVERGED):
            continue
        M = make_model(alpha, beta, a, V, zeta, eta, 0.0, 0.0, True, sr)
        z = _start({"sliding": 0, "rest": 1}[initial], 0.0, 0.0, 0.0, 0.0, M,
                   frame_offset(0.0, 0.0, True))
        F, N = _long_run(M, z, LONG)
        if len(F) < LONG:
            continue
        windows = [_mean(F, N, LONG // 8, LONG // 4), _mean(F, N, LONG // 4, LONG // 2),
                   _mean(F, N, LONG // 2, LONG)]
        rows.append(dict(point=(alpha, beta, a, V, zeta, eta, sr, initial), result=r,
                         mean=windows[-1], spread=max(windows) - min(windows),
                         earlier=earlier_rule(F, N)))
    return rows


def _beyond(mu: float, err: float, row: dict) -> bool:
    return abs(mu - row["mean"]) > err


def report(rows: list[dict], seeds: str, per: int, static: int, total: int) -> list[str]:
    averaged = [w for w in rows if w["result"].status is vf.Status.AVERAGED]
    beyond = [w for w in averaged if _beyond(w["result"].mu_ratio, w["result"].error, w)]
    earlier = [w for w in rows if w["earlier"] is not None]
    e_beyond = [w for w in earlier if _beyond(*w["earlier"], w)]
    e_far = [w for w in e_beyond if abs(w["earlier"][0] - w["mean"]) > 1e-6]

    def off(w: dict, mu: float) -> str:
        return f"{abs(mu - w['mean']):.1e}"

    lines = [
        f"Seeds {seeds}: {total} points ({per} per regime, each undamped and damped, and "
        f"{static} of the static law per seed); {len(rows)} answered averaged or not "
        f"converged, each run on to {LONG} periods.",
        "",
        f"* The solver: {len(averaged)} averaged answers, {len(beyond)} of them farther from "
        f"the long run's mean than their stated error"
        + (f" (by {', '.join(off(w, w['result'].mu_ratio) for w in beyond)})" if beyond
           else "") + ".",
        f"* The earlier rule on the same motions: {len(earlier)} averaged answers, "
        f"{len(e_beyond)} beyond their error, {len(e_far)} of them by more than 1e-6 "
        f"(largest {max((abs(w['earlier'][0] - w['mean']) for w in e_beyond), default=0):.1e}).",
        "",
        "| point (alpha, beta, a, V, zeta, eta_c, s_r, start) | answer | long run "
        "(spread of its last 3 windows) | off / error |",
        "|---|---|---|---|",
    ]
    for w in beyond:
        r = w["result"]
        p = ", ".join(f"{x:.4g}" if isinstance(x, float) else str(x) for x in w["point"])
        lines.append(f"| ({p}) | {r.mu_ratio:.10f} +- {r.error:.1e} after {r.periods} "
                     f"periods | {w['mean']:.10f} ({w['spread']:.1e}) | "
                     f"{abs(r.mu_ratio - w['mean']) / r.error:.3g} |")
    return lines


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seeds", default="7031-7070", help="first-last (inclusive)")
    ap.add_argument("--per-regime", type=int, default=60)
    ap.add_argument("--static", type=int, default=480)
    ap.add_argument("--write", action="store_true")
    args = ap.parse_args()
    first, last = (int(s) for s in args.seeds.split("-"))
    rows: list[dict] = []
    total = 0
    t0 = time.perf_counter()
    for seed in range(first, last + 1):
        rows += survey(seed, args.per_regime, args.static)
        total += sum(1 for _ in points(seed, args.per_regime, args.static))
        print(f"seed {seed}: {len(rows)} rows so far, {time.perf_counter() - t0:.0f} s",
              file=sys.stderr, flush=True)
    lines = report(rows, args.seeds, args.per_regime, args.static, total)
    print("\n".join(lines))
    if args.write:
        append_run(RESULTS, "Averaged answers against the motion's long-time mean",
                   f"PYTHONPATH=src:tests python benchmarks/averaged_error.py --seeds "
                   f"{args.seeds} --per-regime {args.per_regime} --static {args.static} --write",
                   f"one process; {time.perf_counter() - t0:.0f} s", lines)


if __name__ == "__main__":
    main()
