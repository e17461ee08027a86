"""Is the rate-and-state solver's stated error honest? 40 random points of every regime.

Each point (both evolution laws, weakening and strengthening, the Linker-Dieterich coupling
on and off, damping, jumping; seed 7) is solved at the default ``rtol`` and at
``rtol = 1e-11``; where both are periodic, ``|mu - mu_tight|`` is compared with the
default's stated error. Writes benchmarks/results/rate_state_error.md.

    PYTHONPATH=src python benchmarks/rate_state_error_numbers.py
"""

from __future__ import annotations

import datetime
from collections import Counter
from pathlib import Path

import numpy as np

import vibrofriction as vf


def main() -> None:
    rng = np.random.default_rng(7)
    statuses: Counter[str] = Counter()
    ratios, others = [], []
    for _ in range(40):
        al = 10 ** rng.uniform(-1, 0.5)
        be = al + 10 ** rng.uniform(-0.3, 1)
        am = rng.uniform(0, 1.6)
        V = 10 ** rng.uniform(-1.5, 0.5)
        ze = float(rng.choice([0.0, 0.1]))
        a = 10 ** rng.uniform(-2.3, -1.3)
        b = a * rng.uniform(0, 1.6)
        dc = 10 ** rng.uniform(-2.5, -0.5)
        vr = 10 ** rng.uniform(-1, 0.5)
        law = str(rng.choice(["aging", "slip"]))
        ld = float(rng.choice([0.0, 0.3])) if (b > 0 and am < 1) else 0.0
        s = vf.Dimensionless(alpha=al, beta=be, amplitude=am, zeta=ze, rs_a=a, rs_b=b,
                             rs_d_c=dc, rs_v_ref=vr, rs_alpha_ld=ld, rs_law=law)
        r = vf.friction_coefficient(s, v_inertial=V)
        statuses[r.status.value] += 1
        if r.status is not vf.Status.PERIODIC:
            others.append(f"| {al:.3g} | {be:.3g} | {am:.3g} | {V:.3g} | {a:.3g} | {b / a:.2f} "
                          f"| {law} | {ld} | {ze} | {r.status.value} |")
            continue
        tight = vf.friction_coefficient(s, v_inertial=V, settings=vf.SolverSettings(rtol=1e-11))
        ratios.append(abs(r.mu_ratio - tight.mu_ratio) / r.error)
    text = "\n".join([
        "# Rate-and-state solver: the stated error against rtol = 1e-11",
        "",
        f"`PYTHONPATH=src python benchmarks/rate_state_error_numbers.py`, "
        f"{datetime.date.today()}. 40 random points (seed 7).",
        "",
        f"Statuses at the default rtol: {dict(statuses)}.",
        "",
        f"Periodic points: {len(ratios)}; `|mu - mu(rtol = 1e-11)| / error`: largest "
        f"**{max(ratios):.2f}**, median {float(np.median(ratios)):.3f}; above 1 at "
        f"{sum(q > 1 for q in ratios)} points.",
        "",
        "The points not answered periodic:",
        "",
        "| alpha | beta | amplitude | V | a | b/a | law | alpha_ld | zeta | status |",
        "|---|---|---|---|---|---|---|---|---|---|",
        *others,
        "",
    ])
    (Path(__file__).parent / "results" / "rate_state_error.md").write_text(text)
    print(text)


if __name__ == "__main__":
    main()
