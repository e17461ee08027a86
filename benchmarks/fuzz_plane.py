"""Random points of the 2-D (transverse) solver: statuses, trust and time per point.

150 points drawn with a fixed seed over alpha 1e-2..10, beta - alpha 0.03..100, a 0..2.5,
signed |V| 1e-3..3, zeta in {0, 0.01, 0.1, 0.5}, eta_c in {0, 0, 0.1, 1}, a_x in
{0, 0, 0.5, 2} and a_y 0.01..5 (random phases), each solved alone by ``solve_points``.
Prints the count of each status, the trusted count, the median, 90th percentile and
largest time, and the slowest point.  Run: ``python benchmarks/fuzz_plane.py [--write]``
(``--write``, also with ``--compare``: the run appended to
benchmarks/results/plane_fuzz.md with the commit, date and machine; the earlier runs stay
above).

``--compare OLD`` solves the same points with the source tree ``OLD`` (its ``src`` on the
path, in a subprocess: ``--values FILE`` saves them) and compares: equal statuses, the
largest difference of ``mu_ratio`` and ``lateral_ratio`` over the two stated errors, of the
multipliers, and the ratio of the stated errors.
"""

from __future__ import annotations

import subprocess
import sys
import time
from collections import Counter
from pathlib import Path

import numpy as np

from sections import append_run
from vibrofriction.solver import solve_points

RESULTS = Path(__file__).parent / "results" / "plane_fuzz.md"
TITLE = "150 random 2-D points"


def _commit(tree: str) -> str:
    """The short commit of the checkout ``tree``."""
    return subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                          text=True, cwd=tree).stdout.strip() or "not a git checkout"


def _points() -> tuple[np.ndarray, ...]:
    """The 150 points (seed 3): alpha, beta, a, V, zeta, eta_c, a_x, phase_x, a_y, phase_y."""
    rng = np.random.default_rng(3)
    n = 150
    al = 10 ** rng.uniform(-2, 1, n)
    be = al + 10 ** rng.uniform(-1.5, 2, n)
    a = rng.uniform(0, 2.5, n)
    V = rng.choice([-1, 1], n) * 10 ** rng.uniform(-3, 0.5, n)
    ze = rng.choice([0, 0.01, 0.1, 0.5], n)
    et = rng.choice([0, 0, 0.1, 1.0], n)
    ax = rng.choice([0, 0, 0.5, 2.0], n)
    px = rng.uniform(0, 6.3, n)
    ay = 10 ** rng.uniform(-2, 0.7, n)
    py = rng.uniform(0, 6.3, n)
    return al, be, a, V, ze, et, ax, px, ay, py


def _values(path: str) -> None:
    """The points' columns compared by ``--compare``, into the ``.npz`` file ``path``."""
    o = solve_points(*_points())
    np.savez(path, **{k: o[k] for k in ("mu_ratio", "lateral_ratio", "error", "status",
                                        "multiplier")})


def _compare(old_tree: str) -> list[str]:
    """This tree against ``old_tree`` on the same points (see the module doc)."""
    import os
    import tempfile

    with tempfile.TemporaryDirectory() as tmp:
        files = {}
        for name, tree in (("old", old_tree), ("new", str(Path(__file__).parents[1]))):
            files[name] = f"{tmp}/{name}.npz"
            env = {**os.environ, "PYTHONPATH": f"{tree}/src"}
            subprocess.run([sys.executable, __file__, "--values", files[name]], env=env,
                           check=True)
        o, n = (np.load(files[k]) for k in ("old", "new"))
        bar = o["error"] + n["error"]
        return [f"statuses equal: {bool(np.array_equal(o['status'], n['status']))}",
                "largest |difference| over the two stated errors: mu_ratio "
                f"{np.max(np.abs(o['mu_ratio'] - n['mu_ratio']) / bar):.1e}, lateral_ratio "
                f"{np.max(np.abs(o['lateral_ratio'] - n['lateral_ratio']) / bar):.1e}",
                "largest |difference| of the multipliers: "
                f"{np.nanmax(np.abs(o['multiplier'] - n['multiplier'])):.1e}",
                f"stated errors new/old: median {np.median(n['error'] / o['error']):.2f}, "
                f"largest {np.max(n['error'] / o['error']):.2f}"]


def main() -> None:
    if "--values" in sys.argv:
        _values(sys.argv[sys.argv.index("--values") + 1])
        return
    if "--compare" in sys.argv:
        old = sys.argv[sys.argv.index("--compare") + 1]
        lines = _compare(old)
        print("\n".join(lines))
        if "--write" in sys.argv:
            append_run(RESULTS, TITLE, f"python benchmarks/fuzz_plane.py --compare {old} --write",
                       f"this tree against the source tree `{old}` (commit {_commit(old)}), "
                       "each in its own process.", [f"* {x}" for x in lines])
        return
    al, be, a, V, ze, et, ax, px, ay, py = _points()
    n = len(al)
    solve_points(0.5, 2.0, 0.5, 0.3, 0.05, 0.0, 0.0, 0.0, 0.5, 1.0)  # compile or load
    times, status, trusted = [], [], 0
    for i in range(n):
        t = time.perf_counter()
        o = solve_points(al[i], be[i], a[i], V[i], ze[i], et[i], ax[i], px[i], ay[i], py[i])
        times.append(time.perf_counter() - t)
        status.append(int(o["status"]))
        trusted += bool(o["trusted"])
    t = np.array(times)
    i = int(np.argmax(t))
    lines = [f"statuses {dict(Counter(status))}, trusted {trusted} of {n}",
             f"time per point: median {np.median(t) * 1e3:.1f} ms, 90th percentile "
             f"{np.percentile(t, 90) * 1e3:.1f} ms, largest {t[i]:.2f} s at alpha "
             f"{al[i]:.4g}, beta {be[i]:.4g}, a {a[i]:.4g}, V {V[i]:.4g}, zeta {ze[i]:g}, "
             f"eta_c {et[i]:g}, a_x {ax[i]:g}, a_y {ay[i]:.4g} (status {status[i]})",
             f"points over 0.1 s: {int(np.sum(t > 0.1))}; total {t.sum():.2f} s"]
    print("\n".join(lines))
    if "--write" in sys.argv:
        append_run(RESULTS, TITLE, "python benchmarks/fuzz_plane.py --write",
                   "each point solved alone by `solve_points`. Status codes: 0 periodic, "
                   "1 averaged, 2 not converged, 3 failed.", [f"* {x}" for x in lines])


if __name__ == "__main__":
    main()
