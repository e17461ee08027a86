"""Cost of damping: damped against undamped points, the stiff-contact corner, and the peer.

1. The benchmark's regimes (``bench_solver.POINTS``) undamped and with a pin dashpot
   (``zeta = 0.005``), both dashpots (``zeta = 0.02, eta_c = 0.1``) and a viscoelastic
   contact alone (``eta_c = 0.1``): median time per point of the exact solver, and the
   ratio damped/undamped per regime.  Peer B (fixed-step return mapping, 400 steps per
   fastest period, 200 + 50 periods) is run side by side on the damped points when the
   reference package supports damping, with its deviation from our answer.
2. The stiff-contact corner: ``alpha = 0.01``, ``beta = 1e4 ... 1e6``, ``a = 0.5, 1,
   1.5``, ``vbar = 0.1, 0.5, 0.9`` with ``zeta = 0, 1e-3, 1e-2`` and ``eta_c = 0, 0.1``.

Run: ``.venv/bin/python benchmarks/bench_damped.py`` (writes benchmarks/results/damped.md
and damped.json).  Medians over repeats in one process, one core; read ratios.
"""

from __future__ import annotations

import inspect
import json
import os
import platform
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import numpy as np  # noqa: E402

import vibrofriction as vf  # noqa: E402
from bench_solver import POINTS, _median_time  # noqa: E402
from vibrofriction_reference import return_mapping_mu  # noqa: E402

HERE = Path(__file__).resolve().parent
QUICK = "--quick" in sys.argv
DAMPINGS = [(0.0, 0.0), (0.005, 0.0), (0.02, 0.1), (0.0, 0.1)]
PEER_DAMPED = "zeta" in inspect.signature(return_mapping_mu).parameters
CORNER_BETAS = (1e4, 1e5, 1e6)
CORNER_AMPLITUDES = (0.5, 1.0, 1.5)
CORNER_VBARS = (0.1, 0.5, 0.9)
CORNER_DAMPINGS = [(0.0, 0.0), (1e-3, 0.0), (1e-2, 0.0), (1e-3, 0.1)]


def _peer(alpha, beta, a, V, zeta, eta):
    kwargs = {"zeta": zeta, "eta_c": eta} if PEER_DAMPED else {}
    return return_mapping_mu(alpha, beta, a, V, 400, 200, 50, **kwargs)


def regimes() -> list[dict]:
    rows = []
    for label, alpha, beta, a, vbar, v_in in POINTS:
        V = float(vf.Dimensionless(alpha, beta, a).vbar_to_inertial(vbar)) if vbar else v_in
        for zeta, eta in DAMPINGS:
            s = vf.Dimensionless(alpha, beta, a, zeta, eta)
            t, r = _median_time(lambda s=s, V=V: vf.friction_coefficient(s, v_inertial=V),
                                5 if QUICK else 50, 5.0)
            row = {"point": label, "alpha": alpha, "beta": beta, "amplitude": a,
                   "v_inertial": V, "zeta": zeta, "eta_c": eta, "ours_s": t,
                   "mu_ratio": r.mu_ratio, "error": r.error, "status": r.status.value}
            if (zeta or eta) and PEER_DAMPED:
                tb, mu_b = _median_time(lambda p=(alpha, beta, a, V, zeta, eta): _peer(*p),
                                        1 if QUICK else 3, 20.0)
                row.update(peer_b_s=tb, peer_b_diff=abs(mu_b - r.mu_ratio))
            rows.append(row)
            print(f"{label:24s} zeta={zeta:<6g} eta_c={eta:<4g} {t * 1e3:7.3f} ms "
                  f"{r.status.value} mu={r.mu_ratio:.8f}"
                  + (f" | B {row['peer_b_s'] * 1e3:7.1f} ms diff {row['peer_b_diff']:.1e}"
                     if "peer_b_s" in row else ""), flush=True)
    return rows


def corner() -> list[dict]:
    rows = []
    for beta in CORNER_BETAS:
        for a in CORNER_AMPLITUDES:
            for vbar in (CORNER_VBARS[:1] if QUICK else CORNER_VBARS):
                V = float(vf.Dimensionless(0.01, beta, a).vbar_to_inertial(vbar))
                for zeta, eta in CORNER_DAMPINGS:
                    s = vf.Dimensionless(0.01, beta, a, zeta, eta)
                    t, r = _median_time(lambda s=s, V=V: vf.friction_coefficient(
                        s, v_inertial=V), 3 if QUICK else 5, 10.0)
                    rows.append({"beta": beta, "amplitude": a, "vbar": vbar, "zeta": zeta,
                                 "eta_c": eta, "ours_s": t, "status": r.status.value,
                                 "mu_ratio": r.mu_ratio, "events": r.events})
                print(f"beta={beta:.0e} a={a} vbar={vbar}: " + " | ".join(
                    f"{x['ours_s'] * 1e3:6.1f} ms" for x in rows[-len(CORNER_DAMPINGS):]),
                    flush=True)
    return rows


def write(reg: list[dict], cor: list[dict]) -> None:
    out = HERE / "results"
    out.mkdir(exist_ok=True)
    name = "damped_quick" if QUICK else "damped"
    (out / f"{name}.json").write_text(json.dumps({"regimes": reg, "corner": cor}, indent=1))
    base = {r["point"]: r["ours_s"] for r in reg if not (r["zeta"] or r["eta_c"])}
    lines = [
        "# Damped points: cost against undamped, the stiff corner, and the peer",
        "",
        f"Command: `.venv/bin/python benchmarks/bench_damped.py{' --quick' if QUICK else ''}`  ",
        f"Machine: {platform.machine()}, {os.cpu_count()} cores, Python "
        f"{platform.python_version()}, numpy {np.__version__}; one process, one core.  ",
        f"Date: {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}",
        "",
        "## The benchmark's regimes, undamped and damped",
        "",
        "Median wall time per steady-state point (ours: 50 repeats).  Peer B: fixed-step "
        "return mapping with both dashpots, 400 steps per fastest period, 200 transient + "
        "50 averaged periods (3 repeats); `B diff` is its deviation from our answer "
        "(its discretisation and finite-window error: tests/reference/test_reference_damped.py).",
        "",
        "| point | zeta | eta_c | ours (ms) | damped/undamped | status | mu/mu0 | error | "
        "B (ms) | B/ours | B diff |",
        "|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    ratios: dict[tuple[float, float], list[float]] = {}
    for r in reg:
        ratio = r["ours_s"] / base[r["point"]]
        if r["zeta"] or r["eta_c"]:
            ratios.setdefault((r["zeta"], r["eta_c"]), []).append(ratio)
        peer = (f"{r['peer_b_s'] * 1e3:.1f} | {r['peer_b_s'] / r['ours_s']:.0f}x | "
                f"{r['peer_b_diff']:.1e}") if "peer_b_s" in r else "| |"
        lines.append(f"| {r['point']} | {r['zeta']:g} | {r['eta_c']:g} | "
                     f"{r['ours_s'] * 1e3:.3f} | {ratio:.2f} | {r['status']} | "
                     f"{r['mu_ratio']:.8f} | {r['error']:.1e} | {peer} |")
    lines += ["", "Median ratio damped/undamped over the regimes: " + "; ".join(
        f"zeta = {z:g}, eta_c = {e:g}: **{statistics.median(v):.2f}**"
        for (z, e), v in ratios.items()) + ".", ""]
    speedups = [r["peer_b_s"] / r["ours_s"] for r in reg if "peer_b_s" in r]
    if speedups:
        lines += [f"Median speed-up over peer B on damped points: "
                  f"**{statistics.median(speedups):.0f}x** (min {min(speedups):.0f}x).", ""]
    lines += [
        "## The stiff-contact corner (alpha = 0.01)",
        "",
        "Median time per point (5 repeats), ms; status of every point in damped.json.",
        "",
        "| beta | a | vbar | " + " | ".join(f"zeta={z:g}, eta_c={e:g}"
                                            for z, e in CORNER_DAMPINGS) + " |",
        "|---|---|---|" + "---|" * len(CORNER_DAMPINGS),
    ]
    n = len(CORNER_DAMPINGS)
    for i in range(0, len(cor), n):
        grp = cor[i:i + n]
        lines.append(f"| {grp[0]['beta']:.0e} | {grp[0]['amplitude']:g} | {grp[0]['vbar']:g} | "
                     + " | ".join(f"{g['ours_s'] * 1e3:.1f}" for g in grp) + " |")
    for z, e in CORNER_DAMPINGS:
        ts = [r["ours_s"] * 1e3 for r in cor if r["zeta"] == z and r["eta_c"] == e]
        lines.append(f"\nzeta = {z:g}, eta_c = {e:g}: median {statistics.median(ts):.1f} ms, "
                     f"max {max(ts):.1f} ms, {sum(t < 10 for t in ts)}/{len(ts)} under 10 ms.")
    (out / f"{name}.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines[-6:]))


if __name__ == "__main__":
    vf.friction_coefficient(vf.Dimensionless(0.5, 2.0, 0.5, 0.01, 0.1), v_inertial=0.3)
    write(regimes(), corner())
