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
One function per section, each returning rows ``(quantity, value)`` (``sections.py``;
tests/docs/test_quoted_numbers.py checks the quoted ones); the sections 1-4 take about
ten seconds warm.

5. With ``--baseline REV``: without the oscillation (``a_x = 0``) the MDR solver's results
   bit for bit against that revision's ``src`` (exported by ``git archive``, run in a
   fresh process): ``mdr_friction`` and a row of 20 springs at five points.

    PYTHONPATH=src python benchmarks/mdr_inplane_numbers.py --baseline 9cb60b9 \
        > benchmarks/results/mdr_inplane.md
"""

from __future__ import annotations

import argparse
import contextlib
import json
import math
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from itertools import pairwise
from pathlib import Path

import vibrofriction.solver.mdr as mdr_module
from sections import WALL, Rows, section
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


def _rows_alone() -> contextlib.AbstractContextManager:
    """``mdr_friction`` with the rows of springs alone (a revision without the row without
    springs has no switch and needs none)."""
    return getattr(mdr_module, "rows_alone", contextlib.nullcontext)()


def _bits() -> list:
    """The a_x = 0 results of :data:`BITWISE` as hex strings, the rows' (runs on any
    revision: no in-plane keyword is passed)."""
    out = []
    with _rows_alone():
        out = _bits_rows()
    return out


def _bits_rows() -> list:
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


def _point(al, be, a, V, z, ax, px, on) -> str:
    return f"({al:g}, {be:g}, {a:g}, {V:g}, zeta {z:g}, a_x {ax:g}, {px:.4g}, {on})"


def flat_punch() -> Rows:
    """1. Flat punch: the MDR solver (one spring) against the 1-D solver ``solve_points``
    at the points of tests/mdr/test_mdr_inplane.py (alpha, beta, a, V, zeta, a_x, phase_x,
    mount)."""
    rows, worst = [], 0.0
    for al, be, a, V, z, ax, px, on in FLAT:
        r = mdr_friction(al, be, a, V, math.inf, zeta=z, a_x=ax, phase_x=px, inplane_on=on)
        s = float(solve_points(al, be, a, V, zeta=z, a_x=ax, phase_x=px,
                               inplane_on=on)["mu_ratio"])
        d = r["mu_ratio"] - s
        worst = max(worst, abs(d))
        rows.append((_point(al, be, a, V, z, ax, px, on),
                     f"MDR {r['mu_ratio']:.12f}, 1-D {s:.12f}, diff {d:.1e}"))
    return [*rows, ("largest |diff|", f"{worst:.1e}")]


def _bar(error: float) -> str:
    """A reference's error bar as quoted: below ``1e-11`` as that bound (the spread of its
    window means at round-off, which differs in its digits from one processor to another)."""
    return f"+- {error:.1e}" if error >= 1e-11 else "+- < 1e-11"


def reference_flat_punch() -> Rows:
    """2. The reference's flat punch: the spring row (200 springs, 400 steps) against the
    1-D in-plane reference (``vibrofriction_reference.inplane``, DOP853 with events), two
    independent integrators."""
    rows = []
    for al, be, a, V, z, ax, px, on in REFERENCE_FLAT:
        ip = dict(a_x=ax, phase_x=px, inplane_on=on)
        row = mdr_reference(al, be, a, V, math.inf, transient_periods=200,
                            average_periods=20, zeta=z, **ip)
        one = inplane_mean(al, be, a, V, 100, 20, zeta=z, tolerance_check=False, **ip)
        rows.append((_point(al, be, a, V, z, ax, px, on),
                     f"row {row.mu_ratio:.8f} +- {row.mu_error:.1e}, 1-D {one.mu_ratio:.8f} "
                     f"{_bar(one.mu_error)}, diff {row.mu_ratio - one.mu_ratio:.1e}"))
    return rows


def _median_time(f, repeat: int = 3) -> tuple[float, object]:
    times, out = [], None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = f()
        times.append(time.perf_counter() - t0)
    return statistics.median(times), out


def against_reference() -> Rows:
    """3. The MDR solver (``solve_points`` at ``tol_trusted`` 1e-5) against the spring-row
    reference ``mdr_reference`` at the rows of tests/data/mdr_inplane_reference.json (300 +
    20 periods), re-run here side by side (the solver's time a median of 3). ``ratio`` =
    |diff|/(solver error + reference bar), <= 1 within the bars."""
    pts = json.loads((ROOT / "tests" / "data" / "mdr_inplane_reference.json").read_text())
    rows, ratios, diffs, errors, t_sol, t_ref = [], [], [], [], [], []
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
        t_ref.append(time.perf_counter() - t0)
        t_sol.append(ts)
        mu, err = float(s["mu_ratio"]), float(s["error"])
        d = mu - ref.mu_ratio
        ratios.append(abs(d) / (err + ref.mu_error))
        diffs.append(abs(d))
        errors.append(err)
        rows.append((f"{p['label']} (n {p['profile_exponent']:g}, {p['inplane_on']})",
                     f"solver {mu:+.8f} +- {err:.1e}, reference {ref.mu_ratio:+.8f} +- "
                     f"{ref.mu_error:.1e}, diff {d:.1e}, ratio {ratios[-1]:.2f}"))
    stiff = next(p for p in pts["points"] if p["label"] == "sphere substrate stiff damped")
    moves = [mdr_mean(stiff["alpha"], stiff["beta"], stiff["amplitude"], stiff["v_inertial"],
                      stiff["profile_exponent"], M, steps, 300, 20, zeta=stiff["zeta"],
                      a_x=stiff["a_x"], phase_x=stiff["phase_x"],
                      inplane_on=stiff["inplane_on"]).mu_ratio
             for M, steps in ((100, 200), (200, 400), (400, 800), (800, 1600),
                              (1600, 3200))]
    return [*rows,
            ("the stiff point's reference rows (100, 200) ... (1600, 3200)",
             ", ".join(f"{m:.8f}" for m in moves)),
            ("their steps", ", ".join(f"{abs(b - a):.1e}" for a, b in pairwise(moves))),
            ("within the combined bars", f"{sum(r <= 1.0 for r in ratios)} of {len(ratios)}"),
            ("largest ratio", f"{max(ratios):.2f}"),
            ("|diff|, smallest to largest", f"{min(diffs):.1e} to {max(diffs):.1e}"),
            ("the solver's errors, smallest to largest", f"{min(errors):.1e} to {max(errors):.1e}"),
            (f"median {WALL} per point (s): solver, reference (its two rows)",
             f"{statistics.median(t_sol):.3f}, {statistics.median(t_ref):.2f}")]


def calibration() -> Rows:
    """4. The error bars against the independent reference, the solver's (the row without
    springs) and the rows of springs' alone: 24 random points (seed
    5; n = 1, 2, 3 in turn, substrate and holder in turn, alpha in (0.2, 2), beta - alpha
    in (0.5, 4), a in (0.2, 1.8), V in (0.1, 1), zeta 0, 0.02 or 0.1, a_x in (0.2, 2),
    phase_x in (0, 2 pi)). Reference: the spring row of ``vibrofriction_reference.mdr`` (no
    code shared with the solver) refined until its bar is at most 2e-6
    (tests/data/mdr_fine_reference.json, made by tests/data/make_mdr_fine_reference.py).
    ``short`` where |mdr_friction - reference| > its error + the reference's bar."""
    cache = json.loads((ROOT / "tests" / "data" / "mdr_fine_reference.json").read_text())
    pts = [p for p in cache["points"] if p["set"] == "calibration"]
    bars = [p["err_ref"] for p in pts]

    def solve(p: dict) -> dict:
        return mdr_friction(p["alpha"], p["beta"], p["amplitude"], p["v_inertial"],
                            p["profile_exponent"], zeta=p["zeta"], a_x=p["a_x"],
                            phase_x=p["phase_x"], inplane_on=p["inplane_on"])

    solver = [solve(p) for p in pts]
    s_short = sum(abs(r["mu_ratio"] - p["mu_ref"]) > r["error"] + p["err_ref"]
                  for r, p in zip(solver, pts, strict=True))
    s_comb = [abs(r["mu_ratio"] - p["mu_ref"]) / (r["error"] + p["err_ref"])
              for r, p in zip(solver, pts, strict=True)]
    s_err = [r["error"] for r in solver]
    short, alone, ratios, combined, first, errors = 0, 0, [], [], 0, []
    for p in pts:
        with _rows_alone():
            r = solve(p)
        d = abs(r["mu_ratio"] - p["mu_ref"])
        short += d > r["error"] + p["err_ref"]
        alone += d > r["error"]
        ratios.append(d / r["error"])
        combined.append(d / (r["error"] + p["err_ref"]))
        errors.append(r["error"])
        first += r["rows"] == (20, 40)
    n = len(pts)
    return [("reference bars: median, largest", f"{statistics.median(bars):.1e}, {max(bars):.1e}"),
            ("the solver: answered without springs",
             f"{sum(r['rows'] == () for r in solver)} of {n}"),
            ("the solver: short", f"{s_short} of {n}"),
            ("the solver: |diff|/(error + bar): median, largest",
             f"{statistics.median(s_comb):.2g}, {max(s_comb):.2g}"),
            ("the solver's errors, smallest to largest", f"{min(s_err):.1e} to {max(s_err):.1e}"),
            ("the rows alone:", ""),
            ("short", f"{short} of {n}"), ("beyond its error alone", f"{alone} of {n}"),
            ("|diff|/error: median, largest", f"{statistics.median(ratios):.2g}, "
             f"{max(ratios):.2g}"),
            ("|diff|/(error + bar): median, largest", f"{statistics.median(combined):.2g}, "
             f"{max(combined):.2g}"),
            ("the rows' errors, smallest to largest", f"{min(errors):.1e} to {max(errors):.1e}"),
            ("stopped at the first pair (20, 40)", f"{first} of {n}")]


def short_bar() -> Rows:
    """4. A short bar of one difference, at :data:`SHORT` (alpha, beta, a, V, zeta, n, a_x,
    phase_x, mount), the rows alone: the solver's rows of 20 and 40 springs from cold starts
    agree by chance, 80 moves; the reference refined as in ``calibration``;
    ``mdr_friction`` counts two differences."""
    al, be, a, V, z, n, ax, px, on = SHORT
    kw = dict(a_x=ax, phase_x=px, inplane_on=on)
    with _rows_alone():
        r = mdr_friction(al, be, a, V, n, zeta=z, **kw)
    ref = refine(dict(label="short", alpha=al, beta=be, amplitude=a, v_inertial=V, zeta=z,
                      profile_exponent=n, **kw))
    rows = {M: mdr_row(al, be, a, V, n, M, z, **kw)["mu_ratio"] for M in (20, 40, 80, 160)}
    return [("reference", f"{ref['mu_ref']:.8f} +- {ref['err_ref']:.1e} (rows "
             f"{ref['levels'][-1]})"),
            *((f"the solver's row of {M}", f"{v:.8f}") for M, v in rows.items()),
            ("bar of the difference of the rows 20, 40", f"{abs(rows[40] - rows[20]):.1e}"),
            ("row 40 from the reference", f"{abs(rows[40] - ref['mu_ref']):.1e}"),
            ("mdr_friction (two differences)", f"{r['mu_ratio']:.8f} +- {r['error']:.1e} "
             f"(rows {r['rows']})"),
            ("mdr_friction from the reference", f"{abs(r['mu_ratio'] - ref['mu_ref']):.1e}")]


SECTIONS: dict[str, Callable[[], Rows]] = {
    f.__name__: f for f in (flat_punch, reference_flat_punch, against_reference, calibration,
                            short_bar)}


def _bits_in(src: Path) -> list:
    env = dict(os.environ, PYTHONPATH=str(src))
    out = subprocess.run([sys.executable, __file__, "--bits-only"], env=env, check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out)


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
          "(the 2-core shared machine; times are wall times).\n")
    mdr_friction(0.5, 2.0, 0.5, 0.3, 2.0, a_x=0.5)  # compile / load the caches
    for name, f in SECTIONS.items():
        t0 = time.perf_counter()
        rows = f()
        print(section(name, f.__doc__ or "", rows, time.perf_counter() - t0), flush=True)
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
        print(f"## 5. Without the oscillation: this tree against {base}, bit for bit\n")
        print("`mdr_friction` (mu_ratio, error, periods) and `mdr_row` of 20 springs "
              "(mu_ratio, periods, final y, y') at a_x = 0, each tree in a fresh process.\n")
        print("| alpha, beta, a, V, zeta, n | mdr_friction mu_ratio | equal |")
        print("| --- | --- | --- |")
        for p, o, n in zip(BITWISE, old, new, strict=True):
            print(f"| {', '.join(f'{x:g}' for x in p)} | {float.fromhex(n[0]):.15f} | "
                  f"{'all 7 bit for bit' if o == n else 'DIFFERENT: ' + str((o, n))} |")


if __name__ == "__main__":
    main()
