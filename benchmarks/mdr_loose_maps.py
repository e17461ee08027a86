"""Why the row without springs' maps are not looser than ``1e-7``: the orbits just below V_c.

Just below the critical velocity of continuous sliding the springs stick briefly, and
whether a stick begins at all turns on a small dip of the band's edge velocity ``P'``
below zero: the period map jumps there. At two points at ``0.999 V_c`` (the first from
a scan of random points at 0.95-0.999 V_c, the second from another seed of that scan),
the row without springs (:func:`~vibrofriction.solver.mdr_continuum.mdr_continuum`) is run
with its maps at each tolerance from ``1e-5`` to ``1e-8`` (the search's state tolerance
``1e-9``), and :func:`~vibrofriction.solver.mdr.mdr_friction` at its default
``tol = 1e-5``; the reference is the rows of 640 and 1280 springs (an independent solver,
stated error below 1e-10). Each row gives ``mu``, the stated error, the difference from the
reference over the two errors (above 1: the error does not hold) and the stick area
fraction.

    PYTHONPATH=src python benchmarks/mdr_loose_maps.py [--write]

``--write`` appends the run to benchmarks/results/mdr_loose_maps.md.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from sections import append_run
from vibrofriction import theory
from vibrofriction.solver import mdr_continuum as smc
from vibrofriction.solver.mdr import mdr_friction
from vibrofriction.solver.mdr_continuum import mdr_continuum

RESULTS = Path(__file__).parent / "results" / "mdr_loose_maps.md"
# (alpha, beta, a, n, zeta), each at 0.999 V_c
POINTS = [(0.021, 12.0, 0.64, 5.0, 0.05),
          (0.1798988937195852, 4.428067920160702, 0.8383816231766487, 2.0, 0.05)]
FRACTION = 0.999
RTOLS = (1e-5, 3e-6, 1e-6, 3e-7, 1e-7, 3e-8, 1e-8)


def _row(label: str, r: dict, ref: dict) -> str:
    if r["status"] != "periodic":
        return f"| {label} | {r['status']} | | | |"
    ratio = abs(r["mu_ratio"] - ref["mu_ratio"]) / (r["error"] + ref["error"])
    return (f"| {label} | {r['mu_ratio']:.10f} | {r['error']:.1e} | {ratio:.2f} | "
            f"{r['stick_area_fraction']:.4f} |")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--write", action="store_true")
    opts = ap.parse_args()
    lines: list[str] = []
    for alpha, beta, a, n, zeta in POINTS:
        V = FRACTION * theory.profile_critical_velocity(alpha, beta, a, n, zeta)
        ref = mdr_friction(alpha, beta, a, V, n, zeta, n_springs=640)
        lines += ["", f"alpha {alpha:.4g}, beta {beta:.4g}, a {a:.4g}, n {n:g}, zeta {zeta:g}, "
                  f"V = {FRACTION} V_c = {V:.6g}; the rows of 640 and 1280 springs: "
                  f"{ref['mu_ratio']:.10f} +- {ref['error']:.1e}, stick "
                  f"{ref['stick_area_fraction']:.4f}", "",
                  "| maps | mu | stated error | \\|difference\\| / errors | stick area |",
                  "|---|---|---|---|---|"]
        for rtol in RTOLS:
            r = mdr_continuum(alpha, beta, a, V, n, zeta, rtol=rtol, state_tol=1e-9)
            lines.append(_row(f"`{rtol:g}`", r, ref))
        lines.append(_row("default (`tol = 1e-5`)", mdr_friction(alpha, beta, a, V, n, zeta),
                          ref))
        print("\n".join(lines[-len(RTOLS) - 6:]), flush=True)
    if opts.write:
        append_run(RESULTS, "The row without springs' maps just below the critical velocity",
                   "PYTHONPATH=src python benchmarks/mdr_loose_maps.py --write",
                   f"the maps' tolerance as given (the fine orbit's {smc.FINE:g} times it), "
                   "the search's state tolerance 1e-9.", lines)


if __name__ == "__main__":
    main()
