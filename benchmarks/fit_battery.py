"""The fit's battery: held-out data sets made by the independent reference, and the score.

Each data set is a bench as an experimenter would measure it: a pin of random mass,
natural frequency, quality factor, contact stiffness, load and ``mu0``, driven at a
random frequency, its friction coefficient measured at three normal amplitudes and 16
sliding velocities, with Gaussian noise ``sigma``.  The friction coefficients come from
``vibrofriction_reference.return_mapping_mu`` (peer B, a fixed-step integrator sharing no
code with the solver being fitted), at two resolutions whose difference is the data's
error bar from the reference (written beside each set; far below ``sigma``).  The SI ->
dimensionless conversion (eq. 20, Fig. 6, docs/damping.md) is written out here, also
without the package.

Kinds (an equal share each): ``general``; ``jumping`` (the largest amplitude above 1: the
pin loses contact every period); ``damped`` (a quality factor 2-6 and a contact dashpot);
``resonant`` (driven near the pin's natural frequency, ``alpha`` 0.85-1.2); ``stiff`` (the
contact 50-300 times stiffer than the pin's inertia at the drive).  A set whose noise
makes a measured COF negative (a bench reports none) is drawn again.

Each set is fitted with five free fields (``mu0, mass, k_x, k_xc, u_z0``), the natural
frequency and load constraints released (``k_zc`` held at the truth's, the measured
quality factor kept), from a guess off by a factor drawn log-uniformly in 1/1.6..1.6 in
every free field.  The score of a fit:

* **valley**: its chi-square is at most the truth's plus 1 (the truth's chi-square: the
  package's model at the true parameters, the same residuals as the fit's);
* **intervals**: every 95 % interval of a free field holds the truth, required whenever
  the truth's chi-square is within 3.84 of the fit's (then the truth lies in every
  profile-likelihood interval of level 3.84 or more: a profile minimises over the others,
  and the truth is one such point).

Run:
  python benchmarks/fit_battery.py make [--sets 25] [--seed 32]   # the data (1-2 min)
  python benchmarks/fit_battery.py run [--only 0,3] [--workers 2] [--write NAME]
  python benchmarks/fit_battery.py profile [--set 3] [--out docs/img/fit_profiles.png]
``make`` writes benchmarks/data/fit_battery.json; ``run --write NAME`` writes
benchmarks/results/fit_battery_NAME.md (and .json with every number).
"""

from __future__ import annotations

import argparse
import datetime
import json
import math
import platform
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
# the SI -> dimensionless groups written out from the paper, without the package, and peer B's
# COF with its error bar: the held-out bench data's own (tests/data/make_reference_bench.py)
sys.path.insert(0, str(HERE.parent / "tests" / "data"))
from make_reference_bench import groups, reference_mu  # noqa: E402

sys.path.pop(0)
DATA = HERE / "data" / "fit_battery.json"
KINDS = ("general", "jumping", "damped", "resonant", "stiff")
FREE = ("mu0", "mass", "k_x", "k_xc", "u_z0")
#: The fit's options, as the refusal message of ``free`` says: both constraints released.
OPTIONS = {"natural_frequency": False, "normal_load": False, "quality_factor": True}
GUESS_FACTOR = 1.6
VELOCITIES = 16
#: The chi-square margins of the score.
VALLEY_MARGIN = 1.0
INTERVAL_LEVEL = 3.84


def _loguniform(rng: np.random.Generator, lo: float, hi: float) -> float:
    return float(math.exp(rng.uniform(math.log(lo), math.log(hi))))


def draw_truth(kind: str, rng: np.random.Generator) -> dict:
    """A random bench of ``kind`` in SI units, and its three normal amplitudes (m)."""
    f_drive = _loguniform(rng, 400.0, 3000.0)
    omega = 2.0 * math.pi * f_drive
    mass = _loguniform(rng, 0.005, 0.05)
    alpha = {"resonant": rng.uniform(0.85, 1.2)}.get(kind, _loguniform(rng, 0.25, 3.0))
    ratio = {"stiff": _loguniform(rng, 50.0, 300.0)}.get(kind, _loguniform(rng, 1.5, 20.0))
    q = {"damped": rng.uniform(2.0, 6.0), "resonant": rng.uniform(10.0, 30.0)}.get(
        kind, rng.uniform(15.0, 80.0))
    stiffness = mass * omega**2
    k_x, k_xc = alpha * stiffness, ratio * stiffness
    load = _loguniform(rng, 5.0, 50.0)
    u_z0 = _loguniform(rng, 0.5e-6, 3e-6)
    eta_c = rng.uniform(0.05, 0.3) if kind == "damped" else 0.0
    top = rng.uniform(1.15, 1.6) if kind == "jumping" else rng.uniform(0.7, 0.95)
    truth = {"mass": mass, "k_x": k_x, "k_xc": k_xc, "k_zc": load / u_z0, "u_z0": u_z0,
             "omega": omega, "mu0": rng.uniform(0.15, 0.6),
             "c_x": 2.0 * math.sqrt(k_x * mass) / (2.0 * q), "c_xc": eta_c * k_xc / omega}
    amplitudes = [u_z0 * top * s for s in (0.3, 0.6, 1.0)]
    return {"truth": truth, "amplitudes": amplitudes, "quality_factor": q}


def make_set(index: int, kind: str, rng: np.random.Generator) -> dict:
    """One data set of ``kind``: truth, guess, the measured rows and the reference's bar."""
    drawn = draw_truth(kind, rng)
    truth = drawn["truth"]
    sigma = float(rng.choice([0.002, 0.003, 0.005]))
    load = truth["k_zc"] * truth["u_z0"]
    # V from 0.02 to 3 (dimensionless), as v0 in m/s
    v_scale = truth["mu0"] * load / (truth["mass"] * truth["omega"])
    v0 = v_scale * np.geomspace(0.02, 3.0, VELOCITIES)
    rows, bar = [], 0.0
    for du in drawn["amplitudes"]:
        for v in v0:
            mu, e = reference_mu(truth, du, float(v), transients=(400, 800))
            bar = max(bar, e)
            rows.append([float(v), truth["mu0"] * mu + float(rng.normal(0.0, sigma)), du,
                         truth["omega"], sigma])
    factors = {n: _loguniform(rng, 1.0 / GUESS_FACTOR, GUESS_FACTOR) for n in FREE}
    guess = dict(truth)
    for n, f in factors.items():
        guess[n] = truth[n] * f
    q = drawn["quality_factor"]  # the measured quality factor, kept by the guess
    guess["c_x"] = 2.0 * math.sqrt(guess["k_x"] * guess["mass"]) / (2.0 * q)
    return {"index": index, "kind": kind, "truth": truth, "guess": guess,
            "guess_factors": factors, "sigma": sigma, "quality_factor": q,
            "amplitudes": drawn["amplitudes"],
            "dimensionless": dict(zip(("alpha", "beta", "a_max", "V_min", "zeta", "eta_c"),
                                      groups(truth, max(drawn["amplitudes"]), float(v0[0])),
                                      strict=True)),
            "reference_error_bar_cof": truth["mu0"] * bar,
            "columns": ["v0", "cof", "du_z", "omega", "sigma"], "rows": rows}


def make(sets: int, seed: int) -> None:
    t0 = time.perf_counter()
    rng = np.random.default_rng(seed)
    out = []
    for i in range(sets):
        s = make_set(i, KINDS[i % len(KINDS)], rng)
        while min(r[1] for r in s["rows"]) < 0.0:  # a bench reports no negative COF: redraw
            s = make_set(i, KINDS[i % len(KINDS)], rng)
        out.append(s)
    DATA.parent.mkdir(exist_ok=True)
    DATA.write_text(json.dumps({"seed": seed, "made_by": "benchmarks/fit_battery.py make",
                                "reference": "vibrofriction_reference.return_mapping_mu",
                                "sets": out}, indent=0) + "\n")
    worst = max(s["reference_error_bar_cof"] / s["sigma"] for s in out)
    print(f"{sets} sets in {time.perf_counter() - t0:.0f} s; the reference's error bar is at "
          f"most {worst:.1e} sigma; written to {DATA.relative_to(HERE.parent)}")


def load_sets(only: list[int] | None = None) -> list[dict]:
    """The battery's data sets (``only``: their indices)."""
    sets = json.loads(DATA.read_text())["sets"]
    return [s for s in sets if only is None or s["index"] in only]


def fit_call(s: dict):
    """The data table, the guess and the keyword arguments of the fit of set ``s``."""
    import pandas as pd

    import vibrofriction as vf
    from vibrofriction.bench import read_measurements

    data = read_measurements(pd.DataFrame(s["rows"], columns=s["columns"]))
    guess = vf.Physical(**s["guess"], du_z=max(s["amplitudes"]))
    return data, guess, {"free": FREE, **OPTIONS}


def truth_chisqr(s: dict) -> float:
    """The chi-square of the package's model at the true parameters (the fit's residuals)."""
    from vibrofriction.bench.fitting.problem import Problem

    data, guess, kw = fit_call(s)
    problem = Problem(guess, FREE, OPTIONS["natural_frequency"], OPTIONS["normal_load"],
                      OPTIONS["quality_factor"], data)
    return problem.cost(np.log([s["truth"][n] for n in FREE]))


def score(s: dict, res, chi_truth: float) -> dict:
    """The score of the fit ``res`` of set ``s`` (module docstring)."""
    excluded = [n for n in FREE
                if not res.intervals[n][0] <= s["truth"][n] <= res.intervals[n][1]]
    must_hold = chi_truth - res.chisqr <= INTERVAL_LEVEL
    # an interval with the fitted value at (or within 1e-4 of) one of its ends: a profile
    # that stopped at once, at a jump of the model or a refit gone astray
    pinched = [n for n in FREE if not min(res.params[n].value - res.intervals[n][0],
                                          res.intervals[n][1] - res.params[n].value)
               > 1e-4 * res.params[n].value]
    return {"index": s["index"], "kind": s["kind"], "chisqr": res.chisqr,
            "truth_chisqr": chi_truth, "valley": res.chisqr <= chi_truth + VALLEY_MARGIN,
            "must_hold": must_hold, "excluded": excluded,
            "intervals_hold": not (must_hold and excluded), "quality": res.quality,
            "pinched": pinched,
            "seconds": res.seconds, "nfev": res.nfev,
            "intervals": {n: list(res.intervals[n]) for n in FREE},
            "values": {n: res.params[n].value for n in FREE},
            "statuses": dict(getattr(res, "determination", {}) or {}),
            "combinations": dict(getattr(res, "combinations", {}) or {})}


def run(only: list[int] | None, workers: int, write: str | None, seed: int,
        options: dict | None = None) -> list[dict]:
    import vibrofriction as vf

    rows = []
    for s in load_sets(only):
        data, guess, kw = fit_call(s)
        chi_truth = truth_chisqr(s)
        res = vf.fit(data, guess, workers=workers, progress=False, seed=seed, **kw,
                     **(options or {}))
        r = score(s, res, chi_truth)
        rows.append(r)
        print(f"set {r['index']:2d} {r['kind']:8s} chi2 {r['chisqr']:8.2f} truth "
              f"{r['truth_chisqr']:8.2f} valley {'yes' if r['valley'] else 'NO '} "
              f"intervals {'hold' if r['intervals_hold'] else 'EXCLUDE ' + ','.join(r['excluded'])}"
              f" {r['quality']:9s} {r['seconds']:5.1f} s", flush=True)
    summary = summarise(rows)
    print(summary)
    if write:
        _write(rows, summary, write, workers, options or {})
    return rows


def summarise(rows: list[dict]) -> str:
    n = len(rows)
    valley = sum(r["valley"] for r in rows)
    hold = sum(r["intervals_hold"] for r in rows)
    good_wrong = sum(r["quality"] == "good" and not r["intervals_hold"] for r in rows)
    pinched = sum(bool(r.get("pinched")) for r in rows)
    times = [r["seconds"] for r in rows]
    return (f"valley found in {valley} of {n} sets; intervals hold the truth (where they "
            f"must) in {hold} of {n}; GOOD verdicts excluding the truth: {good_wrong}; "
            f"fits with a value at an end of its interval: {pinched}; "
            f"fit time median {statistics.median(times):.1f} s, max {max(times):.1f} s")


def _loose(r: dict) -> str:
    """The parameters a fit did not determine, with the combination the data hold."""
    out = [n + (f" ({r['combinations'][n]} held)" if n in r.get("combinations", {}) else "")
           for n, st in r.get("statuses", {}).items() if st != "determined"]
    return ", ".join(out) or "-"


def _write(rows: list[dict], summary: str, name: str, workers: int, options: dict) -> None:
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True, cwd=HERE).stdout.strip()
    dirty = subprocess.run(["git", "status", "--porcelain", "src"], capture_output=True,
                           text=True, cwd=HERE).stdout.strip()
    shown = "".join(f" --fit {k}={v}" for k, v in options.items())
    head = (f"# Fit battery: {name}\n\n`python benchmarks/fit_battery.py run --workers "
            f"{workers}{shown} --write {name}` at {commit}{' (src modified)' if dirty else ''}, "
            f"{datetime.date.today()}, {platform.machine()}, {len(rows)} sets of "
            f"benchmarks/data/fit_battery.json.\n\n**{summary}**\n\n")
    table = ["| set | kind | chi-square | truth's | valley | intervals | verdict | not determined"
             " | s |", "|---:|---|---:|---:|---|---|---|---|---:|"]
    table += [f"| {r['index']} | {r['kind']} | {r['chisqr']:.2f} | {r['truth_chisqr']:.2f} | "
              f"{'yes' if r['valley'] else 'no'} | "
              f"{'hold' if r['intervals_hold'] else 'exclude ' + ', '.join(r['excluded'])}"
              f"{'' if r['must_hold'] else ' (not required)'}"
              f"{' pinched ' + ', '.join(r['pinched']) if r.get('pinched') else ''} | "
              f"{r['quality']} | {_loose(r)} | {r['seconds']:.1f} |" for r in rows]
    out = HERE / "results" / f"fit_battery_{name}.md"
    out.write_text(head + "\n".join(table) + "\n")
    out.with_suffix(".json").write_text(json.dumps(rows, indent=1, default=float) + "\n")
    print(f"written to {out.relative_to(HERE.parent)}")


def profile_figure(index: int, out: Path, workers: int) -> None:
    """The fit of set ``index`` and its profiles (:func:`vibrofriction.figures.plot_profiles`)."""
    import vibrofriction as vf
    from vibrofriction.figures import plot_profiles

    s = load_sets([index])[0]
    data, guess, kw = fit_call(s)
    res = vf.fit(data, guess, workers=workers, progress=False, **kw)
    print(res.report())
    print(score(s, res, truth_chisqr(s)))
    fig = plot_profiles(res, truth={n: s["truth"][n] for n in FREE})
    fig.suptitle(f"battery set {index} ({s['kind']}): profiles of a 5-parameter fit to data "
                 "made by the independent reference", fontsize="small")
    fig.savefig(out, dpi=110)
    print(f"written to {out}")


def _keyword(text: str) -> tuple[str, object]:
    key, _, value = text.partition("=")
    for kind in (int, float):
        try:
            return key, kind(value)
        except ValueError:
            pass
    return key, {"True": True, "False": False}.get(value, value)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = ap.add_subparsers(dest="command", required=True)
    mk = sub.add_parser("make")
    mk.add_argument("--sets", type=int, default=25)
    mk.add_argument("--seed", type=int, default=32)
    rn = sub.add_parser("run")
    rn.add_argument("--only", type=lambda s: [int(x) for x in s.split(",")], default=None)
    rn.add_argument("--workers", type=int, default=2)
    rn.add_argument("--write", default=None)
    rn.add_argument("--seed", type=int, default=0, help="the fit's seed")
    rn.add_argument("--fit", action="append", default=[], metavar="KEY=VALUE",
                    help="a keyword of vf.fit (a number or a word), e.g. search=evolution")
    pf = sub.add_parser("profile")
    pf.add_argument("--set", type=int, default=3)
    pf.add_argument("--out", type=Path, default=HERE.parent / "docs" / "img" / "fit_profiles.png")
    pf.add_argument("--workers", type=int, default=2)
    args = ap.parse_args()
    if args.command == "profile":
        profile_figure(args.set, args.out, args.workers)
    elif args.command == "make":
        make(args.sets, args.seed)
    else:
        rows = run(args.only, args.workers, args.write, args.seed,
                   dict(_keyword(kv) for kv in args.fit))
        sys.exit(0 if rows else 1)


if __name__ == "__main__":
    main()
