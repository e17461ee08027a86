"""Old against new tree: ``friction_coefficient`` at random points of every regime.

``tests/reference_points.random_points(SEED, PER_REGIME, regime)`` over its 8 regimes
(seed 1919; the tests use 2017, bench_heldout 4919): 25 points each, 200 in all.  Each tree
(``--tree DIR``, its ``src`` first on ``PYTHONPATH``) solves them in its own process; the
results compared are ``mu`` (``mu_ratio``), the stated ``error``, ``status``, ``trusted``,
``work`` and ``events``.

Run:  ``.venv/bin/python benchmarks/compare_trees.py --tree OLD --tree NEW [--write]``;
``--write`` appends the summary to ``results/period.md``.
"""

from __future__ import annotations

import datetime
import json
import math
import os
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPORT = HERE / "results" / "period.md"
SEED = 1919
PER_REGIME = 25


def solve() -> list[dict]:
    """The points' results with the tree on ``sys.path``."""
    sys.path.insert(0, str(HERE.parent / "tests"))
    import vibrofriction as vf
    from reference_points import REGIMES, random_points

    rows = []
    for regime in REGIMES:
        for alpha, beta, a, V in random_points(SEED, PER_REGIME, regime):
            r = vf.friction_coefficient(vf.Dimensionless(alpha, beta, a), v_inertial=V)
            rows.append({"regime": regime, "point": [alpha, beta, a, V], "mu": float(r.mu_ratio),
                         "error": float(r.error), "status": r.status.value,
                         "trusted": bool(r.trusted), "work": float(r.work),
                         "events": int(r.events)})
    return rows


def _commit(tree: Path) -> str:
    out = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                         text=True, cwd=tree)
    return out.stdout.strip() if out.returncode == 0 else "not a git checkout"


def main() -> None:
    trees = [Path(sys.argv[i + 1]).resolve() for i, a in enumerate(sys.argv) if a == "--tree"]
    if len(trees) != 2:
        raise SystemExit("give --tree OLD --tree NEW")
    results = []
    for tree in trees:
        env = dict(os.environ, PYTHONPATH=str(tree / "src"))
        out = subprocess.run([sys.executable, __file__, "--solve"], capture_output=True,
                             text=True, env=env, check=True)
        results.append(json.loads(out.stdout))
    old, new = results
    dmu = [abs(a["mu"] - b["mu"]) for a, b in zip(old, new, strict=True)]
    rel_err = [abs(a["error"] - b["error"]) / max(abs(a["error"]), 1e-300)
               for a, b in zip(old, new, strict=True)
               if math.isfinite(a["error"]) and a["error"] > 0]
    worst = max(range(len(old)), key=lambda j: dmu[j])
    diffs = {k: sum(a[k] != b[k] for a, b in zip(old, new, strict=True))
             for k in ("status", "trusted", "work", "events")}
    lines = [f"\n## friction_coefficient, old against new tree: "
             f"{datetime.datetime.now(datetime.UTC):%Y-%m-%d %H:%M} UTC\n",
             f"Command: `{' '.join([Path(sys.executable).name, *sys.argv])}`  ",
             f"Trees: {trees[0].name} @ {_commit(trees[0])}, {trees[1].name} @ "
             f"{_commit(trees[1])}\n",
             f"{len(old)} points (`random_points({SEED}, {PER_REGIME}, regime)` over the 8 "
             f"regimes): max |d mu| **{max(dmu):.1e}** (at {old[worst]['regime']} "
             f"{old[worst]['point']}, stated error {old[worst]['error']:.1e}); "
             f"{sum(d == 0.0 for d in dmu)} identical; max relative change of the stated "
             f"error {max(rel_err, default=0.0):.1e}; points whose status differs: "
             f"{diffs['status']}, trusted: {diffs['trusted']}, work: {diffs['work']}, "
             f"events: {diffs['events']}."]
    for j, (a, b) in enumerate(zip(old, new, strict=True)):
        if any(a[k] != b[k] for k in diffs):
            lines.append(f"- {a['regime']} {a['point']}: " + ", ".join(
                f"{k} {a[k]} -> {b[k]}" for k in diffs if a[k] != b[k])
                + f" (d mu {dmu[j]:.1e})")
    text = "\n".join(lines) + "\n"
    print(text)
    if "--write" in sys.argv:
        with REPORT.open("a") as fh:
            fh.write(text)


if __name__ == "__main__":
    if "--solve" in sys.argv:
        json.dump(solve(), sys.stdout)
    else:
        main()
