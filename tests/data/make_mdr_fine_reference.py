"""Make the fine MDR reference cache of tests/mdr/test_mdr_fine_reference.py.

The agreement tests of the MDR solver against its coarse caches (mdr_reference.json,
mdr_inplane_reference.json: rows (100, 200) and (200, 400), bars median 1.6e-5, up to
1.1e-4) allow ``error + bar``, so they cannot see a solver error at its own tolerance
(``tol_trusted = 1e-5``). Here the independent fixed-step spring row
``vibrofriction_reference.mdr.mdr_mean`` (no code shared with the solver) is refined until
its bar is at most :data:`TARGET`, a fifth of ``tol_trusted``, at two sets of points:

* ``random``: the 24 seeded points of tests/data/make_mdr_reference.py (seed 21: stiff,
  soft, near a resonance, general; jumping or not; damped or not; ``n`` 0.7 to 5), but
  its drifting point (undamped continuous sliding, whose reference mean depends on the
  transient, not on the resolution: tests/mdr/test_mdr_solver.py covers it);
* ``calibration``: the 24 seeded points (seed 5) of the calibration of the solver's error
  bar with a longitudinal in-plane oscillation (:func:`calibration_points`;
  docs/contact_geometry.md, benchmarks/mdr_inplane_numbers.py).

Each point from the sliding start, 300 transient and 20 averaged drive periods (more
where they do not settle, :data:`SLOW`), at the
resolutions ``(springs, steps per period)`` of :data:`LEVELS` in turn (each doubles both)
from the third on, until the bar is within :data:`TARGET`. The bar of the finest run,
``mu_ratio`` of ``runs[-1]``, with ``d1 = |mu[-1] - mu[-2]|`` and ``d0 = |mu[-2] -
mu[-3]|``, is ``max(d1, d0 / 4) + 4 |halves|``: ``d1`` is three times the finest run's
own error for a second-order scheme refined by 2 (the row converges at order 2 for
``n >= 1``, about 1.5 for ``n = 0.7``, where ``d1`` is still 1.8 times it), ``d0 / 4``
catches two runs that agree by chance (the difference the previous pair predicts at
order 2), and ``halves`` is the difference of the finest run's means over the two
halves of the window (0 for an orbit of one or two drive periods that has settled;
times 4 as in tests/reference_points.py). A point whose bar stays above ``TARGET`` at the
last level is kept with its bar (the test then names it). The solver is not run here.

Run (a few minutes on one core):  python tests/data/make_mdr_fine_reference.py
Writes tests/data/mdr_fine_reference.json.
"""

from __future__ import annotations

import math
import sys
import time
from pathlib import Path

import numpy as np

from vibrofriction_reference.mdr import mdr_mean

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from make_mdr_reference import DRIFTING, write_cache  # noqa: E402
from make_mdr_reference import points as random_points  # noqa: E402

TOL_TRUSTED = 1e-5  # the solver's default tol_trusted, which the bars must be well below
TARGET = TOL_TRUSTED / 5
LEVELS = ((200, 400), (400, 800), (800, 1600), (1600, 3200), (3200, 6400))
TRANSIENT, AVERAGE = 300, 20
AVERAGING_SAFETY = 4.0
CALIBRATION_SEED = 5
#: label -> (transient periods, averaged periods, why): where the window of 300 + 20 does
#: not settle
SLOW: dict[str, tuple[int, int, str]] = {
    "c01 holder n=2": (1300, 40, "undamped, jumping, near continuous sliding: after 300 "
                       "periods the period means still beat by 1e-5 (a free oscillation "
                       "that the rare micro-sticks damp slowly); the halves of 20 periods "
                       "differ by 7.5e-7 at every resolution, after 1300 periods the halves "
                       "of 40 by 1e-13"),
}
KEYS = ("label", "alpha", "beta", "amplitude", "v_inertial", "zeta", "profile_exponent",
        "a_x", "phase_x", "inplane_on")


def calibration_points(seed: int = CALIBRATION_SEED, count: int = 24) -> list[dict]:
    """The in-plane calibration points: ``n = 1, 2, 3`` in turn, substrate and holder in
    turn, ``alpha`` in (0.2, 2), ``beta - alpha`` in (0.5, 4), ``a`` in (0.2, 1.8), ``V``
    in (0.1, 1), ``zeta`` 0, 0.02 or 0.1, ``a_x`` in (0.2, 2), ``phase_x`` in (0, 2 pi),
    drawn by ``default_rng(seed)`` in this order."""
    rng = np.random.default_rng(seed)
    out = []
    for i in range(count):
        n = (1.0, 2.0, 3.0)[i % 3]
        al = float(rng.uniform(0.2, 2.0))
        be = al + float(rng.uniform(0.5, 4.0))
        a = float(rng.uniform(0.2, 1.8))
        V = float(rng.uniform(0.1, 1.0))
        z = float(rng.choice([0.0, 0.02, 0.1]))
        a_x = float(rng.uniform(0.2, 2.0))
        phase_x = float(rng.uniform(0.0, 2.0 * math.pi))
        on = ("substrate", "holder")[i % 2]
        label = f"c{i:02d} {on} n={n:g}"
        out.append(dict(zip(KEYS, (label, al, be, a, V, z, n, a_x, phase_x, on),
                            strict=True)))
    return out


def fine_points() -> list[dict]:
    """Every point of the cache, ``set`` naming its set (module docstring)."""
    random = [dict(p, a_x=0.0, phase_x=0.0, inplane_on="substrate", set="random")
              for p in random_points() if p["label"] not in DRIFTING]
    return random + [dict(p, set="calibration") for p in calibration_points()]


def refine(d: dict) -> dict:
    """The reference at ``d``, refined until its bar is within TARGET (module docstring)."""
    transient, average, why = SLOW.get(d["label"], (TRANSIENT, AVERAGE, ""))
    mus, runs, bar = [], [], math.inf
    for springs, steps in LEVELS:
        r = mdr_mean(d["alpha"], d["beta"], d["amplitude"], d["v_inertial"],
                     d["profile_exponent"], springs, steps, transient, average,
                     zeta=d["zeta"], a_x=d["a_x"], phase_x=d["phase_x"],
                     inplane_on=d["inplane_on"])
        mus.append(r.mu_ratio)
        runs.append(r)
        if len(mus) >= 3:
            halves = r.mu_ratio_over(0, average // 2) - r.mu_ratio_over(average // 2, average)
            bar = (max(abs(mus[-1] - mus[-2]), abs(mus[-2] - mus[-3]) / 4.0)
                   + AVERAGING_SAFETY * abs(halves))
            if bar <= TARGET:
                break
    return dict(({"slow": why} if why else {}), transient_periods=transient,
                average_periods=average, levels=[list(x) for x in LEVELS[:len(mus)]],
                mu_levels=mus,
                mu_ref=mus[-1], err_ref=bar, mean_normal_ref=runs[-1].mean_normal_ratio)


def main() -> None:
    rows = []
    for d in fine_points():
        t0 = time.perf_counter()
        d.update(refine(d), seconds=round(time.perf_counter() - t0, 2))
        print(f"{d['label']:36s} mu {d['mu_ref']:+.8f} +- {d['err_ref']:.1e}  "
              f"rows {d['levels'][-1]}  {d['seconds']} s", flush=True)
        rows.append(d)
    write_cache("mdr_fine_reference.json", "tests/data/make_mdr_fine_reference.py", rows,
                target=TARGET, transient_periods=TRANSIENT, average_periods=AVERAGE,
                initial="sliding", calibration_seed=CALIBRATION_SEED)


if __name__ == "__main__":
    main()
