"""Make the MDR reference cache of tests/mdr/test_mdr_solver.py (issue 21, item 6).

Random points over the regimes of the scaled MDR model (docs/contact_geometry.md), drawn by
a seeded generator (:func:`points`): the profile exponent from cones to blunt tips
(``n`` in :data:`EXPONENTS`), the system stiff (small ``alpha``, ``beta = 1.5 ... 3 alpha``,
damped so that the slow transient dies within the reference's window), soft (small
``alpha``, ``beta`` 5 to 10), near a resonance (``alpha`` or ``beta`` within 10 % of 1,
lightly damped) or general; half of them jumping (``a > 1``), half of them damped.  Each
point is integrated by the independent fixed-step spring row
``vibrofriction_reference.mdr.mdr_reference`` (no code shared with the solver) from the
sliding start, with its error bar ``|fine - coarse|``; points in :data:`FINER` use finer
rows where the default bar proved short (say why there).  The solver is not run here.

Run (about a minute on one core):  python tests/data/make_mdr_reference.py
Writes tests/data/mdr_reference.json.
"""

from __future__ import annotations

import json
import platform
import subprocess
import time
from pathlib import Path

import numpy as np

from vibrofriction_reference.mdr import mdr_reference

HERE = Path(__file__).resolve().parent
SEED = 21
COUNT = 24
TRANSIENT, AVERAGE = 300, 20
EXPONENTS = (1.0, 2.0, 0.7, 1.5, 3.0, 5.0)
REGIMES = ("stiff", "soft", "resonant", "general")
DEFAULT_RESOLUTIONS = ((100, 200), (200, 400))
#: label -> resolutions where the default bar is short (none so far)
FINER: dict[str, tuple[tuple[int, int], tuple[int, int]]] = {}
#: label -> (transient periods, why): points whose long-time mean depends on the start
DRIFTING: dict[str, tuple[int, str]] = {
    "18 resonant n=1": (3000, "undamped continuous sliding: the pin's free oscillation "
                        "does not decay while every spring slips, only through sporadic "
                        "micro-sticks; the reference's mean is 1 - 2.8e-6, 1 - 2.3e-7, "
                        "1 - 1.8e-7 after 300, 1000, 3000 periods (its bar 4e-7, 2e-7, "
                        "1.2e-7 counts the resolution only), the solver's periodic orbit "
                        "slides continuously (mu = 1)"),
}
KEYS = ("label", "alpha", "beta", "amplitude", "v_inertial", "zeta", "profile_exponent")


def points(seed: int = SEED, count: int = COUNT) -> list[dict]:
    """``count`` points, the regimes in turn, the rest drawn by ``default_rng(seed)``."""
    rng = np.random.default_rng(seed)
    out = []
    for i in range(count):
        regime = REGIMES[i % len(REGIMES)]
        jumping = (i // len(REGIMES)) % 2 == 1
        damped = i % 3 != 0
        n = float(EXPONENTS[i % len(EXPONENTS)])
        if regime == "stiff":
            alpha = float(rng.uniform(0.02, 0.1))
            beta = alpha * float(rng.uniform(1.5, 3.0))
            zeta = float(rng.uniform(0.2, 1.0))   # always damped: the transient is slow
        elif regime == "soft":
            alpha = float(rng.uniform(0.02, 0.2))
            beta = float(rng.uniform(5.0, 10.0))
            zeta = float(rng.uniform(0.02, 0.3)) if damped else 0.0
        elif regime == "resonant":
            if rng.uniform() < 0.5:
                alpha = float(rng.uniform(0.9, 1.1))
                beta = alpha + float(rng.uniform(0.5, 3.0))
            else:
                alpha = float(rng.uniform(0.2, 0.6))
                beta = float(rng.uniform(0.9, 1.1))
            zeta = float(rng.uniform(0.02, 0.1)) if damped else 0.0
        else:
            alpha = float(rng.uniform(0.2, 2.0))
            beta = alpha + float(rng.uniform(0.5, 5.0))
            zeta = float(rng.uniform(0.02, 0.5)) if damped else 0.0
        a = float(rng.uniform(1.1, 2.5) if jumping else rng.uniform(0.2, 0.95))
        V = float(np.exp(rng.uniform(np.log(0.05), np.log(1.0))))
        if regime == "stiff":   # velocities of the stiff law: vbar = (beta - alpha) V n/((n + 1) a)
            V = float(rng.uniform(0.1, 0.8)) * (n + 1) * a / (n * (beta - alpha))
        tags = (" jumping" if jumping else "") + (" damped" if zeta else "")
        label = f"{i:02d} {regime}{tags} n={n:g}"
        out.append(dict(zip(KEYS, (label, alpha, beta, a, V, zeta, n), strict=True)))
    return out


def main() -> None:
    rows = []
    for d in points():
        res = FINER.get(d["label"], DEFAULT_RESOLUTIONS)
        transient, why = DRIFTING.get(d["label"], (TRANSIENT, ""))
        t0 = time.perf_counter()
        r = mdr_reference(d["alpha"], d["beta"], d["amplitude"], d["v_inertial"],
                          d["profile_exponent"], resolutions=res,
                          transient_periods=transient, average_periods=AVERAGE,
                          zeta=d["zeta"])
        if why:
            d.update(drifting=why)
        d.update(resolutions=[list(x) for x in res], transient_periods=transient,
                 mu_ref=r.mu_ratio, err_ref=r.mu_error,
                 mean_normal_ref=r.mean_normal_ratio, mean_normal_err=r.normal_error,
                 seconds=round(time.perf_counter() - t0, 2))
        print(f"{d['label']:36s} mu {r.mu_ratio:.8f} +- {r.mu_error:.1e}  {d['seconds']} s",
              flush=True)
        rows.append(d)
    write_cache("mdr_reference.json", "tests/data/make_mdr_reference.py", rows, seed=SEED,
                transient_periods=TRANSIENT, average_periods=AVERAGE, initial="sliding")


def write_cache(name: str, script: str, rows: list[dict], **meta) -> None:
    """Write ``{"meta": ..., "points": rows}`` to ``tests/data/name``, the meta naming the
    script, the commit, the date and the machine, then ``meta``."""
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True, cwd=HERE).stdout.strip()
    head = {"script": script, "commit": commit, "date": time.strftime("%Y-%m-%d"),
            "machine": platform.platform()}
    (HERE / name).write_text(json.dumps({"meta": {**head, **meta}, "points": rows},
                                        indent=1) + "\n")


if __name__ == "__main__":
    main()
