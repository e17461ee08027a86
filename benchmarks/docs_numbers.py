"""Regenerate the numbers quoted in docs/solver.md, docs/damping.md and docs/figures.md
that neither `vibrofriction reproduce` nor another benchmark produces.

    PYTHONPATH=src python benchmarks/docs_numbers.py          # writes results/docs_numbers.md
    PYTHONPATH=src python benchmarks/docs_numbers.py --only settling

One function per claim (the section of the docs it backs is in its docstring); each
returns rows ``(quantity, value)`` (``benchmarks/sections.py``; a row whose quantity says
"wall time" is machine-dependent, the others are checked against the docs by
tests/docs/test_quoted_numbers.py).  One process, one core; about a minute warm.
"""

from __future__ import annotations

import argparse
import math
import platform
import subprocess
import time
from collections.abc import Callable
from datetime import UTC, datetime
from pathlib import Path

import numpy as np

import vibrofriction as vf
from sections import WALL, Rows, section
from vibrofriction import solver, theory
from vibrofriction.solver import SolverSettings

RESULTS = Path(__file__).parent / "results" / "docs_numbers.md"


def _g(x: float, digits: int = 3) -> str:
    return f"{x:.{digits}g}"


def settling() -> Rows:
    """docs/solver.md, "Settling time": the example with a slow leading multiplier."""
    r = vf.friction_coefficient(vf.Dimensionless(31.083, 33.976, 0.8507), vbar=0.23652)
    return [("status", r.status.name.lower()), ("mu/mu0", f"{r.mu_ratio:.6f}"),
            ("multiplier", f"{r.multiplier:.5f}"), ("error", _g(r.error, 2)),
            ("settling_periods", f"{r.settling_periods:.3g}")]


def unsettled() -> Rows:
    """docs/solver.md, last section: (0.01, 1.01, 1, vbar 0.02) with the default budget."""
    r = vf.friction_coefficient(vf.Dimensionless(0.01, 1.01, 1.0), vbar=0.02)
    return [("status", r.status.name.lower()), ("mu_ratio", f"{r.mu_ratio:.6g}"),
            ("window_min .. window_max", f"{r.window_min:.3f} .. {r.window_max:.3f}"),
            ("drift_rate (per period)", _g(r.drift_rate, 2))]


LONG_BUDGET = ((1.01, 0.016), (1.01, 0.02), (1.01, 0.04), (1.01, 0.064), (1.02, 0.05),
               (1.005, 0.02))


def long_budget() -> Rows:
    """docs/solver.md, table near beta = 1: alpha = 0.01, a = 1, max_periods = 400,000."""
    settings = SolverSettings(max_periods=400_000)
    rows = []
    for beta, vbar in LONG_BUDGET:
        r = vf.friction_coefficient(vf.Dimensionless(0.01, beta, 1.0), vbar=vbar,
                                    settings=settings)
        rows.append((f"beta {beta}, vbar {vbar}",
                     f"{r.status.name.lower()}, mu/mu0 {r.mu_ratio:.6g}, periods {r.periods:,}, "
                     f"multiplier {r.multiplier:.5f}, settling {r.settling_periods:,.0f}, "
                     f"trusted {r.trusted}"))
    return rows


def near_beta_one_default() -> Rows:
    """docs/solver.md, table near beta = 1 with the default budget (Newton with a limited
    step, since b903c48): alpha = 0.01, a = 1, and Fig. 5's last point vbar = 0.072; the
    least and most work at the points other than vbar 0.016 and 0.02 (beta 1.01), and the
    range of the settling times."""
    rows, others, settling = [], [], []
    for beta, vbar in (*LONG_BUDGET, (1.01, 0.072)):
        r = vf.friction_coefficient(vf.Dimensionless(0.01, beta, 1.0), vbar=vbar)
        rows.append((f"beta {beta}, vbar {vbar}",
                     f"{r.status.name.lower()}, mu/mu0 {r.mu_ratio:.6g}, work {r.work:,.0f}, "
                     f"multiplier {r.multiplier:.5f}, settling {r.settling_periods:,.0f}, "
                     f"trusted {r.trusted}"))
        settling.append(r.settling_periods)
        if (beta, vbar) not in ((1.01, 0.016), (1.01, 0.02)):
            others.append(r.work)
    return [*rows, ("work at the others: least-most", f"{min(others):.0f}-{max(others):.0f}"),
            ("settling: least, most", f"{min(settling):,.0f} to {max(settling):.3g}")]


def stiff_contacts() -> Rows:
    """docs/solver.md, "beta -> inf is a singular limit": cost and distance to the rigid
    contact at beta = 1e4 and 1e6 (a = 0.5, vbar 0.1 and 0.5; median of 3 runs)."""
    rows = []
    for alpha in (0.01, 0.1, 10.0, 1000.0):
        for beta in (1e4, 1e6):
            times, dmu = [], []
            for vbar in (0.1, 0.5):
                s = vf.Dimensionless(alpha, beta, 0.5)
                rigid = vf.Dimensionless(alpha, math.inf, 0.5)
                V = s.vbar_to_inertial(vbar)
                t = []
                for _ in range(3):
                    t0 = time.perf_counter()
                    r = vf.friction_coefficient(s, v_inertial=V)
                    t.append(time.perf_counter() - t0)
                times.append(float(np.median(t)))
                dmu.append(abs(r.mu_ratio - vf.friction_coefficient(rigid, v_inertial=V).mu_ratio))
            rows += [(f"alpha {alpha:g}, beta {beta:g}: |mu - mu(rigid)| <=", _g(max(dmu), 2)),
                     (f"alpha {alpha:g}, beta {beta:g}: {WALL} (ms)",
                      f"{1e3 * min(times):.2g}-{1e3 * max(times):.2g}")]
    t0 = time.perf_counter()
    r = vf.friction_coefficient(vf.Dimensionless(1e-4, 1e6, 0.5), vbar=0.1)
    corner = "corner alpha 1e-4, beta 1e6, a 0.5, vbar 0.1"
    rows += [(f"{corner}: {WALL} (s)", f"{time.perf_counter() - t0:.2g}"),
             (corner, f"{r.periods:,} periods, {r.events:.2g} events, {r.status.name.lower()}")]
    return rows


def near_alpha_one() -> Rows:
    """docs/solver.md, "Accuracy": alpha = 1 +- 1e-9 against alpha = 1 (beta 2, a 0.5)."""
    V = np.array([0.5, 1.0, 3.0])
    at = solver.solve_points(1.0, 2.0, 0.5, V)["mu_ratio"]
    dev = max(float(np.max(np.abs(solver.solve_points(1.0 + d, 2.0, 0.5, V)["mu_ratio"] - at)))
              for d in (1e-9, -1e-9))
    return [("max |mu(1 +- 1e-9) - mu(1)| at V = 0.5, 1, 3", _g(dev, 2))]


def case_iii_damped() -> Rows:
    """docs/damping.md, "Case III": (0.2, 1, 0.5) with eta_c = 0.2."""
    s = vf.Dimensionless(0.2, 1.0, 0.5, eta_c=0.2)
    vc = s.critical_inertial_velocity()
    below = vf.friction_coefficient(s, v_inertial=0.9 * vc)
    above = vf.friction_coefficient(s, v_inertial=1.02 * vc)
    return [("V_c", f"{vc:.4f}"), ("mu/mu0 at 0.9 V_c", f"{below.mu_ratio:.5f}"),
            ("mu/mu0 at 1.02 V_c", f"{above.mu_ratio:.12g} ({above.status.name.lower()})")]


def case_iv_rise() -> Rows:
    """docs/damping.md, "Case IV": largest |law - numerics|, rigid contact, 30 points
    evenly spaced in 0.3 <= V/V_c <= 0.97."""
    rows = []
    for a in (0.2, 0.5, 1.0, 1.5):
        cells = []
        for zeta in (0.005, 0.02, 0.05):
            vc = float(theory.resonant._drive_work(np.asarray(a))) / (2 * math.pi * zeta)
            V = vc * np.linspace(0.3, 0.97, 30)
            out = solver.solve_points(1.0, math.inf, a, V, zeta)
            assert np.all(out["trusted"])
            dev = np.max(np.abs(out["mu_ratio"] - theory.resonant_damped_mu_ratio(V, a, zeta)))
            cells.append(f"zeta {zeta}: {_g(float(dev), 2)}")
        rows.append((f"a = {a}", ", ".join(cells)))
    return rows


def stiff_exact_law() -> Rows:
    """docs/damping.md, "The stiff limit": eq. (26) against the exact law, and the solver
    against the exact law (a = 1, vbar 0.1 ... 0.9, 9 points)."""
    vb = np.linspace(0.0, 1.0, 100_001)
    rows = []
    for a in (0.2, 0.5, 1.0):
        d = np.abs(theory.mu_ratio_stiff(vb, a) - theory.mu_ratio_stiff_exact(vb, a))
        rows.append((f"max |eq. 26 - exact| / a, a = {a}",
                     f"{float(d.max()) / a:.4f} at vbar {vb[int(d.argmax())]:.3f}"))
    vb = np.linspace(0.1, 0.9, 9)
    for alpha in (1e-2, 1e-3, 1e-4):
        s = vf.Dimensionless(alpha, 2 * alpha, 1.0)
        out = solver.solve_points(alpha, 2 * alpha, 1.0, s.vbar_to_inertial(vb))
        d = np.max(np.abs(out["mu_ratio"] - theory.mu_ratio_stiff_exact(vb, 1.0)))
        rows.append((f"solver vs exact law, (alpha, beta) = ({alpha:g}, {2 * alpha:g})",
                     f"{_g(float(d), 2)} (trusted: {bool(np.all(out['trusted']))})"))
    return rows


def loss_factor_floor() -> Rows:
    """docs/solver.md and docs/damping.md: the effect of a loss factor just above the
    1e-6 floor, |mu(eta_c) - mu(0)| / eta_c, at six regimes and vbar 0.3, 0.7."""
    worst = 0.0
    for alpha, beta, a in ((0.5, 2.0, 0.5), (0.01, 0.02, 0.5), (0.01, 400.01, 0.5),
                           (0.5, 2.0, 1.5), (2.0, 5.0, 0.8), (0.2, 0.9, 0.7)):
        V = vf.Dimensionless(alpha, beta, a).vbar_to_inertial(np.array([0.3, 0.7]))
        ref = solver.solve_points(alpha, beta, a, V)["mu_ratio"]
        for eta in (1.5e-6, 1e-5):
            mu = solver.solve_points(alpha, beta, a, V, 0.0, eta)["mu_ratio"]
            worst = max(worst, float(np.max(np.abs(mu - ref))) / eta)
    return [("max |mu(eta_c) - mu(0)| / eta_c, eta_c = 1.5e-6, 1e-5", f"{worst:.2f}")]


def fig13_zeta_series() -> Rows:
    """docs/figures.md, Fig. 13: beta = 1.01, vbar = 0.08 (undamped v0*), alpha 0.01, a 1."""
    V = vf.Dimensionless(0.01, 1.01, 1.0).vbar_to_inertial(0.08)
    rows = []
    for zeta in (0.0, 1e-5, 1e-4, 3e-4, 1e-3, 3e-3, 0.01):
        r = vf.friction_coefficient(vf.Dimensionless(0.01, 1.01, 1.0, zeta), v_inertial=V)
        rows.append((f"zeta {zeta:g}", f"{r.mu_ratio:.3f} ({r.status.name.lower()}, "
                                       f"trusted {r.trusted})"))
    return rows


def damped_drift_settles() -> Rows:
    """docs/damping.md, "The slow drifts": (0.01, 1.01, 1, V = 0.02) with zeta = 0.02."""
    r = vf.friction_coefficient(vf.Dimensionless(0.01, 1.01, 1.0, 0.02), v_inertial=0.02)
    return [("periods, status", f"{r.periods}, {r.status.name.lower()}, trusted {r.trusted}")]


def soft_limit() -> Rows:
    """docs/theory.md, eq. (27) corrected deeper in the soft limit: (0.01, 1e4), a = 0.2 ... 1,
    vbar in [0, 1.2] (121 points): largest deviation and least-squares exponent; the slope
    (mu - (1 - a))/(a sqrt(vbar)) at beta = 1e6, vbar = 1e-3."""
    from scipy.optimize import minimize_scalar

    vb, amps = np.linspace(0.0, 1.2, 121), (0.2, 0.4, 0.6, 0.8, 1.0)
    s = {a: vf.Dimensionless(0.01, 1e4, a) for a in amps}
    mu = {a: solver.solve_points(0.01, 1e4, a, s[a].vbar_to_inertial(vb))["mu_ratio"]
          for a in amps}

    def dev(p: float) -> np.ndarray:
        return np.concatenate([mu[a] - theory.mu_ratio_soft_corrected(vb, a, p) for a in amps])

    p = float(minimize_scalar(lambda q: float(np.sum(dev(q) ** 2)), bounds=(0.5, 4.0),
                              method="bounded").x)
    rows = [("max |numerics - eq. 27 corrected| at (0.01, 1e4)", f"{np.max(np.abs(dev(1.2))):.4f}"),
            ("least-squares exponent at (0.01, 1e4)", f"{p:.3f}")]
    for a in (0.5, 1.0):
        V = vf.Dimensionless(0.01, 1e6, a).vbar_to_inertial(1e-3)
        r = vf.friction_coefficient(vf.Dimensionless(0.01, 1e6, a), v_inertial=V)
        rows.append((f"slope at (0.01, 1e6), a = {a}, vbar 1e-3 (sqrt(4 pi/9) = "
                     f"{math.sqrt(4 * math.pi / 9):.4f})",
                     f"{(r.mu_ratio - (1 - a)) / (a * math.sqrt(1e-3)):.4f}"))
    return rows


def critical_velocity_limits() -> Rows:
    """docs/theory.md, eqs. (13), (14): ratios of eq. (12) to its limits at Fig. 4's points."""
    soft = abs(400.01 - 1) / ((400.01 - 0.01) * abs(0.01 - 1))
    stiff = abs(0.02 - 1) / abs(0.01 - 1)
    return [("v0*/v0*_soft at (0.01, 400.01)", f"{soft:.4f}"),
            ("v0*/v0*_stiff at (0.01, 0.02)", f"{stiff:.3f}")]


def case_iii_jumping() -> Rows:
    """docs/theory.md, "Case III": beta = 1, a = 1.5; where mu/mu0 first reaches 1 on a grid
    of V step 0.01."""
    rows = []
    for alpha in (0.2, 0.01):
        V = np.array([0.05, 0.1])
        mu = solver.solve_points(alpha, 1.0, 1.5, V)["mu_ratio"]
        grid = np.round(np.arange(0.01, 0.5, 0.01), 2)
        out = solver.solve_points(alpha, 1.0, 1.5, grid)
        first = grid[np.argmax(out["mu_ratio"] >= 1.0 - 1e-9)]
        rows.append((f"(alpha, beta) = ({alpha}, 1)",
                     f"mu/mu0 {mu[0]:.2f} at V = 0.05, {mu[1]:.2f} at V = 0.1; "
                     f"= 1 from V = {first:.2f}"))
    return rows


def case_iv_plateau() -> Rows:
    """docs/theory.md, "Case IV": the exact plateau for large amplitudes, and the smallest V
    from which Fig. 6's curves (301 points, V up to 12) stay within 1e-3 of it."""
    rows = [("plateau (exact tau*) a = 1.5, 2, 5, 1e6",
             ", ".join(f"{float(theory.resonant_plateau_exact(a)):.3f}"
                       for a in (1.5, 2.0, 5.0, 1e6))),
            ("small-tau* approximation, a = 1e6", f"{float(theory.resonant_plateau(1e6)):.3f}")]
    V = np.linspace(0.0, 12.0, 301)
    cells = []
    for a in (0.2, 0.5, 0.8, 1.0, 1.5, 2.0):
        d = np.abs(solver.solve_points(1.0, math.inf, a, V)["mu_ratio"]
                   - float(theory.resonant_plateau_exact(a)))
        far = np.nonzero(d > 1e-3)[0]
        cells.append(f"a = {a}: V >= {V[far[-1] + 1]:.1f}")
    rows.append(("within 1e-3 of the plateau from", ", ".join(cells)))
    return rows


def contact_geometry_using_it() -> Rows:
    """docs/contact_geometry.md, "Using it": the python block of that page, run as written
    (the full sphere ``r`` and the linearised one ``r_lin``), and the bench's stiff contact
    (``mass=0.01``) by ``mdr_friction``: the row without springs, and the rows of springs
    alone."""
    import vibrofriction.solver.mdr as mdr

    text = (Path(__file__).resolve().parents[1] / "docs" / "contact_geometry.md").read_text()
    ns: dict = {}
    for block in (b.split("```", 1)[0] for b in text.split("```python\n")[1:]):
        exec(compile(block, "docs/contact_geometry.md", "exec"), ns)
    r, r_lin = ns["r"], ns["r_lin"]
    point = (0.64, 35.81106201466738, 0.5058099397428091, 0.314, 2.0)
    t0 = time.perf_counter()
    stiff = mdr.mdr_friction(*point)
    t_stiff = time.perf_counter() - t0
    with mdr.rows_alone():
        t0 = time.perf_counter()
        rows = mdr.mdr_friction(*point)
        t_rows = time.perf_counter() - t0
    return [("sphere (mdr): mu_ratio, error, status", f"{r.mu_ratio:.5f}, {r.error:.2g}, "
             f"{r.status.value}"),
            ("sphere (mdr): mean_normal_ratio", f"{r.mean_normal_ratio:.4f}"),
            ("sphere (mdr): stick, slip, open area", f"{r.stick_area_fraction:.3f}, "
             f"{r.slip_area_fraction:.3f}, {r.open_area_fraction:.3f}"),
            ("V (both)", f"{r.v_inertial:.3f}"),
            ("linearised: mu_ratio, error", f"{r_lin.mu_ratio:.5f}, {r_lin.error:.2g}"),
            ("stiff contact (mass 0.01): mu_ratio, error, rows, skipped",
             f"{stiff['mu_ratio']:.7f}, {stiff['error']:.2g}, {stiff['rows']}, "
             f"{stiff['skipped_rows']}"),
            (f"stiff contact: {WALL} (s)", f"{t_stiff:.3f}"),
            ("stiff contact, the rows alone: mu_ratio, error, rows, skipped",
             f"{rows['mu_ratio']:.7f}, {rows['error']:.2g}, {rows['rows']}, "
             f"{rows['skipped_rows']}"),
            (f"stiff contact, the rows alone: {WALL} (s)", f"{t_rows:.3f}")]


CLAIMS: dict[str, Callable[[], Rows]] = {
    f.__name__: f for f in (contact_geometry_using_it,
                            settling, unsettled, long_budget, near_beta_one_default,
                            stiff_contacts, near_alpha_one,
                            case_iii_damped, case_iv_rise, stiff_exact_law, loss_factor_floor,
                            fig13_zeta_series, damped_drift_settles, soft_limit,
                            critical_velocity_limits, case_iii_jumping, case_iv_plateau)}


def _header() -> str:
    try:
        commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                                text=True, check=True, cwd=Path(__file__).parent).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        commit = "unknown"
    return (f"# Numbers quoted in the docs\n\nCommand: `PYTHONPATH=src python "
            f"benchmarks/docs_numbers.py`  \nCommit: {commit}; "
            f"{datetime.now(UTC):%Y-%m-%d %H:%M} UTC; {platform.machine()}, "
            f"Python {platform.python_version()}, numpy {np.__version__}; one process.  \n"
            f"Times are wall times on a machine shared with other jobs.\n")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--only", nargs="*", choices=sorted(CLAIMS), help="claims to run")
    args = parser.parse_args()
    solver.friction_coefficient(vf.Dimensionless(0.5, 2.0, 0.5), vbar=0.5)  # load kernels
    parts, total = [_header()], time.perf_counter()
    for name in args.only or CLAIMS:
        t0 = time.perf_counter()
        rows = CLAIMS[name]()
        parts.append(section(name, CLAIMS[name].__doc__ or "", rows, time.perf_counter() - t0))
        print(parts[-1], flush=True)
    parts.append(f"Total {time.perf_counter() - total:.0f} s.\n")
    if not args.only:
        RESULTS.write_text("\n".join(parts))
        print(f"wrote {RESULTS}")


if __name__ == "__main__":
    main()
