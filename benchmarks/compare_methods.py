"""Old against new tree: ``solve_points`` at 1,000 random points of every kind of point.

Six families, each drawn from its own seed: ``flat`` (the undamped flat punch, rigid and
elastic contacts), ``damped`` (pin and contact damping), ``jumping`` (amplitude > 1),
``inplane`` (a longitudinal in-plane oscillation of the substrate or the holder, signed
velocities), ``transverse`` (the 2-D solver) and ``curved`` (sphere, cone and power-law
tips, the MDR solver).  Each tree (``--tree DIR``: its ``src`` first on ``PYTHONPATH``)
solves them in its own process with the public ``solve_points`` and its default
settings; every float and integer output column the two trees share is compared, and the
largest difference of each column is named.

Run:  ``.venv/bin/python benchmarks/compare_methods.py --tree OLD --tree NEW [--n 1000]
[--write]``; ``--write`` writes the summary to ``results/methods.md``.
"""

from __future__ import annotations

import argparse
import datetime
import json
import math
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
REPORT = HERE / "results" / "methods.md"
FAMILIES = ("flat", "damped", "jumping", "inplane", "transverse", "curved")


def points(family: str, n: int) -> dict[str, np.ndarray]:
    """``n`` random points of ``family`` (keyword arguments of ``solve_points``)."""
    rng = np.random.default_rng(FAMILIES.index(family) + 3100)
    alpha = rng.uniform(0.1, 3.0, n)
    beta = np.where(rng.random(n) < 0.2, math.inf, alpha + rng.uniform(0.1, 5.0, n))
    p = {"alpha": alpha, "beta": beta, "amplitude": rng.uniform(0.0, 0.95, n),
         "v_inertial": rng.uniform(0.01, 3.0, n)}
    if family == "damped":
        p["zeta"] = rng.uniform(0.0, 0.3, n)
        p["eta_c"] = np.where(rng.random(n) < 0.5, rng.uniform(0.0, 0.5, n), 0.0)
    elif family == "jumping":
        p["amplitude"] = rng.uniform(1.0, 3.0, n)
        p["zeta"] = np.where(rng.random(n) < 0.5, rng.uniform(0.0, 0.2, n), 0.0)
    elif family == "inplane":
        p["zeta"] = rng.uniform(0.0, 0.2, n)
        p["a_x"] = rng.uniform(0.0, 2.0, n)
        p["phase_x"] = rng.uniform(0.0, 2 * math.pi, n)
        p["v_inertial"] = rng.uniform(-2.0, 2.0, n)
        p["inplane_on"] = np.where(rng.random(n) < 0.5, "substrate", "holder")
    elif family == "transverse":
        p["beta"] = alpha + rng.uniform(0.5, 5.0, n)
        p["zeta"] = rng.uniform(0.02, 0.2, n)
        p["a_y"] = rng.uniform(0.1, 2.0, n)
        p["phase_y"] = rng.uniform(0.0, 2 * math.pi, n)
        p["a_x"] = np.where(rng.random(n) < 0.3, rng.uniform(0.0, 1.0, n), 0.0)
        p["alpha_y"] = np.where(rng.random(n) < 0.3, rng.uniform(0.1, 3.0, n), alpha)
        p["v_inertial"] = rng.uniform(0.05, 2.0, n)
    elif family == "curved":
        p["beta"] = alpha + rng.uniform(0.5, 5.0, n)
        p["zeta"] = rng.uniform(0.02, 0.3, n)
        p["profile_exponent"] = rng.choice([1.0, 2.0, 1.5, 3.0], n)
        p["amplitude"] = rng.uniform(0.0, 0.8, n)
        p["v_inertial"] = rng.uniform(0.1, 2.0, n)
    return p


def solve(n: int, out: Path) -> None:
    """Every family's columns with the tree on ``sys.path``, into ``out`` (npz)."""
    from vibrofriction.solver import solve_points

    arrays, seconds = {}, {}
    for family in FAMILIES:
        p = points(family, n)
        on = p.pop("inplane_on", None)
        t = time.perf_counter()
        if on is None:  # the old tree takes one inplane_on for all points
            cols = solve_points(**p)
        else:
            cols = {}
            for where in ("substrate", "holder"):
                rows = on == where
                part = solve_points(**{k: v[rows] for k, v in p.items()}, inplane_on=where)
                for k, v in part.items():
                    cols.setdefault(k, np.zeros(n, dtype=v.dtype))[rows] = v
        seconds[family] = time.perf_counter() - t
        arrays.update({f"{family}/{k}": np.asarray(v) for k, v in cols.items()})
    np.savez(out, **arrays)
    out.with_suffix(".json").write_text(json.dumps(seconds))


def _run(tree: Path, n: int, out: Path) -> dict[str, float]:
    env = {**os.environ, "PYTHONPATH": str(tree / "src")}
    subprocess.run([sys.executable, __file__, "--solve", str(out), "--n", str(n)], env=env,
                   check=True)
    return json.loads(out.with_suffix(".json").read_text())


def _commit(tree: Path) -> str:
    out = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                         text=True, cwd=tree)
    return out.stdout.strip() if out.returncode == 0 else "not a git checkout"


def compare(old: dict, new: dict) -> list[dict]:
    """Per family: points, identical columns, the largest difference and its column."""
    rows = []
    for family in FAMILIES:
        keys = sorted(k for k in old if k.startswith(family + "/") and k in new)
        worst, where, differ = 0.0, "", []
        for k in keys:
            a, b = old[k], new[k]
            if np.array_equal(a, b, equal_nan=True):
                continue
            differ.append(k.split("/")[1])
            both = np.isfinite(a) & np.isfinite(b) if a.dtype.kind == "f" else slice(None)
            d = float(np.max(np.abs(a[both] - b[both]), initial=0.0)) if a.dtype.kind == "f" \
                else float(np.sum(a != b))
            if a.dtype.kind == "f" and not np.array_equal(np.isfinite(a), np.isfinite(b)):
                d = math.inf
            if d >= worst:
                worst, where = d, k.split("/")[1]
        trusted = int(np.sum(new[f"{family}/trusted"]))
        rows.append({"family": family, "points": int(old[f"{family}/mu_ratio"].size),
                     "trusted": trusted, "columns": len(keys), "differ": differ,
                     "largest": worst, "column": where})
    return rows


def against_errors(old: dict, new: dict) -> list[str]:
    """For each family whose ``mu_ratio`` differs: the differences against the stated errors.

    The statuses equal or not, the largest ``|difference|`` of ``mu_ratio`` and
    ``lateral_ratio`` over the sum of the two stated errors, of the multipliers, the ratio
    of the stated errors and the median periods integrated, old and new.
    """
    out = []
    for family in FAMILIES:
        o = {k.split("/")[1]: v for k, v in old.items() if k.startswith(family + "/")}
        n = {k.split("/")[1]: v for k, v in new.items() if k.startswith(family + "/")}
        if np.array_equal(o["mu_ratio"], n["mu_ratio"], equal_nan=True):
            continue
        bar = o["error"] + n["error"]
        ratio = {c: float(np.nanmax(np.abs(o[c] - n[c]) / bar)) for c in
                 ("mu_ratio", "lateral_ratio")}
        out.append(
            f"{family}: statuses equal {bool(np.array_equal(o['status'], n['status']))}; "
            f"largest |difference| over the two stated errors: mu_ratio "
            f"{ratio['mu_ratio']:.2g}, lateral_ratio {ratio['lateral_ratio']:.2g}; "
            f"multipliers within {np.nanmax(np.abs(o['multiplier'] - n['multiplier'])):.2g}; "
            f"stated errors new/old at most {np.nanmax(n['error'] / o['error']):.3g}; median "
            f"periods integrated {np.median(o['periods']):g} (old), "
            f"{np.median(n['periods']):g} (new)")
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--tree", action="append", type=Path, default=[])
    ap.add_argument("--n", type=int, default=1000)
    ap.add_argument("--write", action="store_true")
    ap.add_argument("--solve", type=Path, help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.solve:
        solve(args.n, args.solve)
        return
    old_tree, new_tree = args.tree
    with tempfile.TemporaryDirectory() as tmp:
        t_old = _run(old_tree, args.n, Path(tmp) / "old.npz")
        t_new = _run(new_tree, args.n, Path(tmp) / "new.npz")
        old, new = np.load(Path(tmp) / "old.npz"), np.load(Path(tmp) / "new.npz")
        rows = compare(dict(old), dict(new))
        notes = against_errors(dict(old), dict(new))
    lines = [f"| {r['family']} | {r['points']} | {r['trusted']} | {r['columns']} | "
             f"{', '.join(r['differ']) or 'none'} | "
             f"{r['largest']:.3g} ({r['column'] or '-'}) | {t_old[r['family']]:.2f} | "
             f"{t_new[r['family']]:.2f} |" for r in rows]
    text = (f"\n## {datetime.date.today()}: {_commit(old_tree)} (old) against "
            f"{_commit(new_tree)} (new)\n\n"
            f"`python benchmarks/compare_methods.py --tree {old_tree} --tree {new_tree} "
            f"--n {args.n}`\n\n"
            "| family | points | trusted (new) | columns compared | columns that differ | "
            "largest difference (column) | old s | new s |\n"
            "|---|---|---|---|---|---|---|---|\n" + "\n".join(lines) + "\n"
            + "".join(f"\n{x}\n" for x in notes))
    print(text)
    if args.write:
        head = "" if REPORT.exists() else (
            "# The method protocol: old against new columns\n\n"
            "`benchmarks/compare_methods.py`: 1,000 random points of each family solved by "
            "the tree before the solver's methods were split into modules and by the tree "
            "after; every output column the two share, compared bitwise (a float column's "
            "largest absolute difference where both are finite; inf where one is finite "
            "and the other not). The seconds are each tree's wall time in its own process "
            "(numba caches warm), on a machine shared with other work.\n")
        with REPORT.open("a") as f:
            f.write(head + text)


if __name__ == "__main__":
    main()
