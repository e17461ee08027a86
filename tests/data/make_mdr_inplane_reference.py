"""Make the reference cache of tests/mdr/test_mdr_inplane.py: the MDR row with a longitudinal
in-plane oscillation (issue 21, "everything else as today"; docs/contact_geometry.md).

Hand-picked points (:data:`POINTS`): sphere, cone and ``n = 3``; the oscillation on the
substrate and on the holder at several phases; jumping (``a > 1``) and not; damped and
not; stiff, soft and general systems; a backward velocity (the reference integrates it as
it is, the package by the mirror); ``a_x`` above and below ``V`` (the slip reverses or not).
Each is integrated by the independent fixed-step spring row
``vibrofriction_reference.mdr.mdr_reference`` (no code shared with the solver) from the
sliding start, with its error bar ``|fine - coarse|``; points in :data:`FINER` use finer
rows where the default bar proved short (say why there).  The solver is not run here.

Run (about half a minute on one core):  python tests/data/make_mdr_inplane_reference.py
Writes tests/data/mdr_inplane_reference.json.
"""

from __future__ import annotations

import json
import math
import platform
import subprocess
import time
from pathlib import Path

from vibrofriction_reference.mdr import mdr_reference

HERE = Path(__file__).resolve().parent
TRANSIENT, AVERAGE = 300, 20
DEFAULT_RESOLUTIONS = ((100, 200), (200, 400))
KEYS = ("label", "alpha", "beta", "amplitude", "v_inertial", "zeta", "profile_exponent",
        "a_x", "phase_x", "inplane_on")
POINTS = [
    ("sphere substrate", 0.5, 2.0, 0.5, 0.3, 0.0, 2.0, 0.5, 1.0, "substrate"),
    ("sphere holder", 1.5, 4.0, 0.5, 0.3, 0.0, 2.0, 0.5, 1.0, "holder"),
    ("cone substrate damped", 1.0, 3.0, 0.7, 0.5, 0.1, 1.0, 0.8, 2.5, "substrate"),
    ("sphere holder jumping damped", 0.3, 3.0, 1.5, 0.4, 0.05, 2.0, 0.6, 0.0, "holder"),
    ("n=3 holder", 2.0, 6.0, 0.8, 0.5, 0.0, 3.0, 1.0, math.pi / 2, "holder"),
    ("n=3 substrate soft", 0.1, 0.5, 0.5, 0.1, 0.0, 3.0, 0.3, 4.0, "substrate"),
    ("cone substrate jumping damped", 1.5, 2.5, 2.0, 0.6, 0.02, 1.0, 1.5, 1.0, "substrate"),
    ("sphere holder jumping damped a_x > V", 0.5, 2.0, 1.2, 0.4, 0.2, 2.0, 2.0, -1.0,
     "holder"),
    ("sphere substrate backward", 0.5, 2.0, 0.5, -0.3, 0.0, 2.0, 0.5, 1.0, "substrate"),
    ("sphere substrate stiff damped", 0.05, 0.1, 0.5, 2.0, 0.5, 2.0, 3.0, 0.7, "substrate"),
    ("sphere substrate a_x > V damped", 0.8, 3.0, 0.3, 0.2, 0.05, 2.0, 1.0, 0.3,
     "substrate"),
    ("cone holder a_x > V", 0.3, 2.0, 0.4, 0.15, 0.0, 1.0, 0.5, 2.0, "holder"),
]
#: label -> resolutions where the default bar is short: the stiff point moves 1.1e-6 from
#: rows (100, 200) to (200, 400), then 1.9e-6 to (400, 800), 4.9e-7 to (800, 1600) and
#: 9.7e-7 to (1600, 3200); (400, 800) to (800, 1600) left it 9.8e-7 from the MDR solver's
#: rows at tol 1e-7 and its row without springs at 1e-9 (0.45724954, agreeing to 1e-9),
#: twice its bar; (1600, 3200) lies 3e-9 from them
FINER: dict[str, tuple[tuple[int, int], tuple[int, int]]] = {
    "sphere substrate stiff damped": ((800, 1600), (1600, 3200)),
}


def points() -> list[dict]:
    return [dict(zip(KEYS, p, strict=True)) for p in POINTS]


def main() -> None:
    rows = []
    for d in points():
        res = FINER.get(d["label"], DEFAULT_RESOLUTIONS)
        t0 = time.perf_counter()
        r = mdr_reference(d["alpha"], d["beta"], d["amplitude"], d["v_inertial"],
                          d["profile_exponent"], resolutions=res,
                          transient_periods=TRANSIENT, average_periods=AVERAGE,
                          zeta=d["zeta"], a_x=d["a_x"], phase_x=d["phase_x"],
                          inplane_on=d["inplane_on"])
        d.update(resolutions=[list(x) for x in res], mu_ref=r.mu_ratio, err_ref=r.mu_error,
                 seconds=round(time.perf_counter() - t0, 2))
        print(f"{d['label']:40s} mu {r.mu_ratio:+.8f} +- {r.mu_error:.1e}  {d['seconds']} s",
              flush=True)
        rows.append(d)
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True, cwd=HERE).stdout.strip()
    meta = {"script": "tests/data/make_mdr_inplane_reference.py", "commit": commit,
            "date": time.strftime("%Y-%m-%d"), "machine": platform.platform(),
            "transient_periods": TRANSIENT, "average_periods": AVERAGE,
            "initial": "sliding"}
    (HERE / "mdr_inplane_reference.json").write_text(
        json.dumps({"meta": meta, "points": rows}, indent=1) + "\n")


if __name__ == "__main__":
    main()
