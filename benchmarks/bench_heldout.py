"""The held-out 49-point check of issue 19: accuracy, calibration, work and time against peer B.

Points no test uses: ``tests/reference_points.random_points(4919, 6, regime)`` over its 8
``REGIMES`` (the tests use seed 2017), 48 points, and one damped point (the general
stick-slip point of ``bench_solver.POINTS`` with ``zeta = 0.01``, ``eta_c = 0.05``).
Per point:

* the independent reference ``reference_mu`` (``tests/reference_points.py``, its default
  resolutions and windows, the dashpots passed through): ``(mu_ref, err_ref)``, computed
  once with 2 processes and cached in ``results/heldout_reference.json`` (keyed by the
  point, recomputed only if the reference's settings change). ``err_ref = inf``: the
  reference cannot bound itself there, "reference unbounded", counted neither way;
* ours: ``vf.friction_coefficient(vf.Dimensionless(alpha, beta, a[, zeta, eta_c]),
  v_inertial=V)``, its status, ``trusted``, stated ``error``, ``work`` (drive periods
  integrated in all) and ``work / p`` (``p``: the orbit's period in drive periods, 1 for
  continuous sliding, ``bench_work.orbit_period``); time: median of 20 repeats;
* peer B (``peers.peer_b``, 400 steps per fastest period, 200 + 50 periods) in the same
  process: median of 3 repeats, and its ``|mu - mu_ref|``.

"agrees": trusted and ``|mu - mu_ref| <= max(error, 1e-9) + err_ref`` (the criterion of
tests/reference/test_differential.py); a calibration failure: ``|mu - mu_ref| > error + err_ref``.
The headline ratio is ``sum(B time) / sum(ours time)`` over the 49 points, with the
median of the per-point ratios beside it.

Run:  ``PYTHONPATH=src .venv/bin/python benchmarks/bench_heldout.py [--note TEXT]``
Each run appends a section (commit, date, machine, load average) to
``results/heldout.json`` and rewrites ``results/heldout.md`` from it: the summary over all
runs first, then one section per run.  ``--points N``: only the first N points, printed,
nothing written but the reference cache; ``--references-only``: fill the cache and stop;
``--wait-load X``: before timing, wait (30 min at most) until the 1-minute load average
is below X.  Run nothing heavy alongside (one core times; the load is recorded).
"""

from __future__ import annotations

import concurrent.futures
import json
import math
import os
import platform
import shlex
import statistics
import subprocess
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parent / "tests"))

import numba  # noqa: E402
import numpy as np  # noqa: E402

import reference_points  # noqa: E402
import vibrofriction as vf  # noqa: E402
from bench_solver import POINTS as BENCH_POINTS  # noqa: E402
from bench_solver import _median_time  # noqa: E402
from bench_work import orbit_period  # noqa: E402
from peers import peer_b, warm_up  # noqa: E402
from reference_points import REGIMES, random_points, reference_mu  # noqa: E402
from vibrofriction.solver import solve_points  # noqa: E402
from vibrofriction_reference import return_mapping_mu  # noqa: E402

SEED = 4919  # tests/reference/test_differential.py uses 2017
PER_REGIME = 6
DAMPING = (0.01, 0.05)  # (zeta, eta_c) of the one damped point
OURS_REPEATS, OURS_BUDGET = 20, 10.0  # repeats, seconds (fewer once the budget is spent)
PEER_REPEATS, PEER_BUDGET = 3, 60.0
REFERENCE_PROCESSES = 2
RESULTS = HERE / "results"
CACHE = RESULTS / "heldout_reference.json"
RUNS = RESULTS / "heldout.json"
REPORT = RESULTS / "heldout.md"
N_POINTS = int(sys.argv[sys.argv.index("--points") + 1]) if "--points" in sys.argv else None
NOTE = sys.argv[sys.argv.index("--note") + 1] if "--note" in sys.argv else ""
REFERENCES_ONLY = "--references-only" in sys.argv
WAIT_LOAD = float(sys.argv[sys.argv.index("--wait-load") + 1]) if "--wait-load" in sys.argv \
    else None
WAIT_LIMIT = 1800.0  # seconds at most waiting for the load to fall

# (regime, alpha, beta, a, V, zeta, eta_c)
Point = tuple[str, float, float, float, float, float, float]


def points() -> list[Point]:
    """The 48 seeded points (6 per regime) and the damped one."""
    out = [(regime, *p, 0.0, 0.0) for regime in REGIMES
           for p in random_points(SEED, PER_REGIME, regime)]
    _, alpha, beta, a, vbar, _ = BENCH_POINTS[0]  # general stick-slip, vbar 0.5
    V = float(vf.Dimensionless(alpha, beta, a).vbar_to_inertial(vbar))
    out.append(("general, damped", alpha, beta, a, V, *DAMPING))
    return out


def key(p: Point) -> str:
    """The cache key of a point: its parameters to 15 significant digits."""
    names = ("alpha", "beta", "a", "V", "zeta", "eta_c")
    return " ".join(f"{n}={x:.15g}" for n, x in zip(names, p[1:], strict=True))


def reference_settings() -> dict:
    """What the cached references depend on besides the point (a change recomputes)."""
    return {"steps": reference_points.STEPS,
            "transient_periods": reference_points.TRANSIENT_PERIODS,
            "average_periods": reference_points.AVERAGE_PERIODS,
            "later_windows": reference_points.LATER_WINDOWS,
            "safety": [reference_points.AVERAGING_SAFETY, reference_points.MOREAU_SAFETY,
                       reference_points.SLOWEST_DECAY, reference_points.ROUND_OFF]}


def _reference(p: Point) -> tuple[float, float, float]:
    """``(mu_ref, err_ref, seconds)`` at ``p`` (runs in a worker process)."""
    t0 = time.perf_counter()
    _, alpha, beta, a, V, zeta, eta_c = p
    mu, err = reference_mu(alpha, beta, a, V, zeta=zeta, eta_c=eta_c)
    return mu, err, time.perf_counter() - t0


def references(pts: list[Point]) -> dict[str, dict]:
    """The cached references, the missing ones computed (2 processes) and saved as they come."""
    settings = json.loads(json.dumps(reference_settings()))
    cache = json.loads(CACHE.read_text()) if CACHE.exists() else {}
    if cache.get("settings") != settings:
        if cache:
            print("reference settings changed: recomputing every reference", flush=True)
        cache = {"settings": settings, "points": {}}
    missing = [p for p in pts if key(p) not in cache["points"]]
    if missing:
        print(f"computing {len(missing)} references with {REFERENCE_PROCESSES} processes",
              flush=True)
        t0 = time.perf_counter()
        with concurrent.futures.ProcessPoolExecutor(REFERENCE_PROCESSES) as pool:
            futures = {pool.submit(_reference, p): p for p in missing}
            for done, future in enumerate(concurrent.futures.as_completed(futures), 1):
                p = futures[future]
                mu, err, seconds = future.result()
                cache["points"][key(p)] = {"regime": p[0], "mu_ref": mu, "err_ref": err,
                                           "seconds": seconds}
                CACHE.write_text(json.dumps(cache, indent=1) + "\n")
                print(f"[{done}/{len(missing)}] {p[0]:22s} {key(p)}: mu_ref {mu:.10f} "
                      f"+- {err:.1e} ({seconds:.1f} s, {time.perf_counter() - t0:.0f} s in "
                      "all)", flush=True)
    return cache["points"]


def measure(p: Point, ref: dict) -> dict:
    """One point: ours and peer B, timed in this process, against the reference."""
    regime, alpha, beta, a, V, zeta, eta_c = p
    s = vf.Dimensionless(alpha, beta, a, zeta, eta_c)
    t_ours, r = _median_time(lambda: vf.friction_coefficient(s, v_inertial=V),
                             OURS_REPEATS, OURS_BUDGET)
    t_b, mu_b = _median_time(lambda: peer_b(alpha, beta, a, V, zeta=zeta, eta_c=eta_c),
                             PEER_REPEATS, PEER_BUDGET)
    mu_ref, err_ref = ref["mu_ref"], ref["err_ref"]
    diff = abs(r.mu_ratio - mu_ref)
    checkable = math.isfinite(err_ref)
    p_orbit = orbit_period(r)
    return {
        "regime": regime, "alpha": alpha, "beta": beta, "a": a, "V": V, "zeta": zeta,
        "eta_c": eta_c, "mu_ref": mu_ref, "err_ref": err_ref, "checkable": checkable,
        "status": r.status.value, "trusted": bool(r.trusted), "mu": r.mu_ratio,
        "error": r.error, "diff": diff,
        "agrees": bool(checkable and r.trusted and diff <= max(r.error, 1e-9) + err_ref),
        "calibration_failure": bool(checkable and diff > r.error + err_ref),
        "period": r.period, "p": p_orbit, "work": r.work, "work_per_p": r.work / p_orbit,
        "ours_s": t_ours, "peer_b_s": t_b, "peer_b_mu": mu_b, "peer_b_diff": abs(mu_b - mu_ref),
    }


def _finite_median(values) -> float:
    values = [v for v in values if math.isfinite(v)]
    return statistics.median(values) if values else math.nan


def summarize(rows: list[dict]) -> dict:
    checkable = [r for r in rows if r["checkable"]]
    ours, b = sum(r["ours_s"] for r in rows), sum(r["peer_b_s"] for r in rows)
    return {
        "points": len(rows), "checkable": len(checkable),
        "unbounded": len(rows) - len(checkable), "agree": sum(r["agrees"] for r in rows),
        "not_trusted": sum(not r["trusted"] for r in rows),
        "calibration_failures": sum(r["calibration_failure"] for r in rows),
        "ours_total_s": ours, "peer_b_total_s": b, "ratio_of_sums": b / ours,
        "median_ratio": statistics.median(r["peer_b_s"] / r["ours_s"] for r in rows),
        "median_work": _finite_median(r["work"] for r in rows),
        "median_work_per_p": _finite_median(r["work_per_p"] for r in rows),
        "no_orbit_period": sum(not math.isfinite(r["p"]) for r in rows),
    }


def _git(*args: str) -> str:
    """git in the checkout of the package measured (PYTHONPATH may point at another)."""
    return subprocess.run(["git", *args], capture_output=True, text=True,
                          cwd=Path(vf.__file__).resolve().parent).stdout.strip()


def _cpu() -> str:
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"


def run_meta(load_before: float) -> dict:
    dirty = bool(_git("status", "--porcelain", "--", "src"))
    return {
        "commit": _git("rev-parse", "--short", "HEAD") + ("+dirty src" if dirty else ""),
        "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
        "machine": f"{platform.machine()}, {_cpu()}, {os.cpu_count()} cores",
        "software": f"Python {platform.python_version()}, numpy {np.__version__}, "
                    f"numba {numba.__version__}",
        "package": str(Path(vf.__file__).resolve().parent),
        "load_before": load_before, "load_after": os.getloadavg()[0],
        "note": NOTE,
        "command": shlex.join(["benchmarks/bench_heldout.py", *sys.argv[1:]]),
    }


def _e(x: float) -> str:
    return "0" if x == 0 else "inf" if math.isinf(x) else "nan" if math.isnan(x) else f"{x:.1e}"


def _g(x: float) -> str:
    return "" if math.isnan(x) else f"{x:.4g}"


def _row(r: dict) -> str:
    damped = f", zeta {r['zeta']:g}, eta_c {r['eta_c']:g}" if r["zeta"] or r["eta_c"] else ""
    params = f"{r['alpha']:.4g}, {r['beta']:.4g}, {r['a']:.4g}, {r['V']:.4g}{damped}"
    agrees = ("unbounded" if not r["checkable"] else "yes" if r["agrees"] else "**no**")
    calib = " (calibration)" if r["calibration_failure"] else ""
    return (f"| {r['regime']} | {params} | {r['status']}"
            f"{'' if r['trusted'] else ' (not trusted)'} | {r['mu']:.10f} | {_e(r['error'])} | "
            f"{_e(r['diff'])} | {_e(r['err_ref'])} | {agrees}{calib} | {r['work']:g} | "
            f"{_g(r['work_per_p'])} | {r['ours_s'] * 1e3:.3f} | {r['peer_b_s'] * 1e3:.2f} | "
            f"{_e(r['peer_b_diff'])} | {r['peer_b_s'] / r['ours_s']:.1f} |")


def _summary_row(run: dict) -> str:
    m, s = run["meta"], run["summary"]
    return (f"| {m['commit']} | {m['date']} | {m['load_before']:.2f} / {m['load_after']:.2f} | "
            f"{s['agree']} / {s['checkable']} | {s['unbounded']} | {s['not_trusted']} | "
            f"{s['calibration_failures']} | {s['ours_total_s'] * 1e3:.1f} | "
            f"{s['peer_b_total_s'] * 1e3:.0f} | **{s['ratio_of_sums']:.1f}x** | "
            f"{s['median_ratio']:.1f}x | {_g(s['median_work'])} | "
            f"{_g(s['median_work_per_p'])} |")


def section(run: dict) -> list[str]:
    m, s = run["meta"], run["summary"]
    return [
        f"## {m['commit']}, {m['date']}" + (f": {m['note']}" if m["note"] else ""),
        "",
        f"Command: `PYTHONPATH=src .venv/bin/python {m['command']}`  ",
        f"Machine: {m['machine']}; {m['software']}; load average {m['load_before']:.2f} "
        f"before the timings, {m['load_after']:.2f} after; package {m['package']}.",
        "",
        f"The solver is {s['ratio_of_sums']:.1f} times faster than the fixed-step peer B in "
        f"all (sum of B's times over the sum of ours over the {s['points']} points: "
        f"{s['peer_b_total_s'] * 1e3:.0f} ms against {s['ours_total_s'] * 1e3:.1f} ms); "
        f"median of the per-point ratios {s['median_ratio']:.1f}.  It agrees with the reference at "
        f"{s['agree']} of {s['checkable']} checkable points ({s['unbounded']} reference "
        f"unbounded); {s['not_trusted']} not trusted; {s['calibration_failures']} "
        f"calibration failures (`|mu - mu_ref| > error + err_ref`).  Median work "
        f"{_g(s['median_work'])} drive periods, median work/p {_g(s['median_work_per_p'])}"
        f" (left out of work/p: {s['no_orbit_period']} without an orbit period, averaged or "
        "not converged).",
        "",
        "| regime | alpha, beta, a, V | status | mu | stated error | \\|mu - mu_ref\\| | "
        "err_ref | agrees | work | work/p | ours (ms) | B (ms) | B \\|mu - mu_ref\\| | "
        "B/ours |",
        "|" + "---|" * 14,
        *(_row(r) for r in run["rows"]),
        "",
    ]


def report(runs: list[dict]) -> str:
    lines = [
        "# Held-out 49-point check (benchmarks/bench_heldout.py)",
        "",
        f"Issue 19's check on points no test uses: `random_points({SEED}, {PER_REGIME}, "
        "regime)` of tests/reference_points.py over its 8 regimes and one damped point "
        f"(general stick-slip, zeta {DAMPING[0]:g}, eta_c {DAMPING[1]:g}).  Reference: "
        "`reference_mu` (its default three resolutions; cached in heldout_reference.json), "
        "`err_ref = inf`: 'unbounded', counted neither way.  'agrees': trusted and "
        "`|mu - mu_ref| <= max(error, 1e-9) + err_ref` (tests/reference/test_differential.py); "
        "calibration failure: `|mu - mu_ref| > error + err_ref`.  Time: median of "
        f"{OURS_REPEATS} repeats (ours) and {PEER_REPEATS} (peer B: fixed step, 400 steps per "
        "fastest period, 200 + 50 periods), one process, side by side.  'B/ours total' is "
        "sum(B time) / sum(ours time) over the points, the headline ratio; 'median ratio' "
        "the median of the per-point ratios.  work: drive periods integrated in all; p: the "
        "orbit's period in drive periods (1 for continuous sliding).  Raw rows: heldout.json.",
        "",
        "## Summary over runs",
        "",
        "| commit | date | load before / after | agree / checkable | ref. unbounded | "
        "not trusted | calibration failures | ours total (ms) | B total (ms) | B/ours total | "
        "median ratio | median work | median work/p |",
        "|" + "---|" * 13,
        *(_summary_row(run) for run in runs),
        "",
    ]
    lines += _floor(runs[-1])
    for run in runs:
        lines += section(run)
    return "\n".join(lines)


def _floor(run: dict) -> list[str]:
    """What the ratio would be if every point cost only ``k`` periods of its orbit at its
    own measured cost per period (``ours / work``): issue 19's limit is "about 3 to 5"."""
    rows = [r for r in run["rows"] if r["work"] and r["work"] > 0]
    B = sum(r["peer_b_s"] for r in run["rows"])
    per = statistics.median(r["ours_s"] / r["work"] for r in rows)
    commit = run["meta"]["commit"]
    out = [f"## The ratio at the limit of a few periods per point (last run, {commit})",
           "", f"Median cost of one drive period integrated: {1e6 * per:.1f} us. If every point "
           "cost only `k` periods of its orbit (`k p` drive periods) at its own measured cost "
           "per period, the ratio to peer B would be:", "",
           "| k | ours total (ms) | B/ours total |", "|---|---|---|"]
    for k in (3, 4, 5):
        ours = sum(min(r["work"], k * (r["p"] or 1)) * r["ours_s"] / r["work"] for r in rows)
        out.append(f"| {k} | {1e3 * ours:.2f} | {B / ours:.0f}x |")
    batch = run["summary"].get("batch_s")
    if batch:
        out += ["", f"All {len(run['rows'])} points in one call (`solver.solve_points` over "
                f"arrays, the Python of a call paid once; median of whole calls): "
                f"{1e3 * batch:.2f} ms, **{B / batch:.0f}x** peer B."]
    return out + [""]


def batch_time(pts: list[Point]) -> float:
    """The 49 points in one call, ``vibrofriction.solver.solve_points`` over arrays (one
    compiled loop): the kernels' time with the Python of a call paid once, not per point; median of
    ``OURS_REPEATS``."""
    cols = np.array([p[1:] for p in pts], dtype=float).T
    t, _ = _median_time(lambda: solve_points(*cols), OURS_REPEATS, OURS_BUDGET)
    return t


def wait_for_load() -> None:
    """With ``--wait-load X``: sleep until the 1-minute load average is below X."""
    t0 = time.monotonic()
    while WAIT_LOAD is not None and os.getloadavg()[0] >= WAIT_LOAD:
        if time.monotonic() - t0 > WAIT_LIMIT:
            print(f"load still {os.getloadavg()[0]:.2f}: timing anyway", flush=True)
            return
        print(f"load average {os.getloadavg()[0]:.2f} >= {WAIT_LOAD:g}: waiting", flush=True)
        time.sleep(30)


def main() -> None:
    pts = points()[:N_POINTS]
    refs = references(pts)
    if REFERENCES_ONLY:
        return
    wait_for_load()
    load_before = os.getloadavg()[0]
    warm_up()
    return_mapping_mu(0.5, 2.0, 0.5, 0.3, 50, 1, 1, zeta=DAMPING[0], eta_c=DAMPING[1])
    vf.friction_coefficient(vf.Dimensionless(0.5, 2.0, 0.5), vbar=0.5)
    vf.friction_coefficient(vf.Dimensionless(0.5, 2.0, 0.5, *DAMPING), vbar=0.5)
    vf.friction_coefficient(vf.Dimensionless(0.5, math.inf, 0.5), vbar=0.5)
    rows = []
    for i, p in enumerate(pts, 1):
        row = measure(p, refs[key(p)])
        rows.append(row)
        print(f"[{i}/{len(pts)}] {_row(row)}", flush=True)
    run = {"meta": run_meta(load_before), "summary": summarize(rows), "rows": rows}
    run["summary"]["batch_s"] = batch_time(pts)
    print(_summary_row(run))
    if N_POINTS is not None:
        return
    runs = json.loads(RUNS.read_text()) if RUNS.exists() else []
    runs.append(run)
    RUNS.write_text(json.dumps(runs, indent=1) + "\n")
    REPORT.write_text(report(runs))
    print(f"wrote {REPORT.relative_to(HERE.parent)} ({len(runs)} runs)")


if __name__ == "__main__":
    main()
