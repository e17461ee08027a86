"""Keep the arrays of the baseline's 2-D history from the sliding start (the first of
``histories`` in tests/data/static_ratio_baseline.json), which that file holds only as a
SHA-256.

``tests/inplane/test_static_kinetic_plane.py`` compared that history bit for bit until the
2-D solver's arithmetic changed at round-off (2026-11-29: one cosine and one sine a
Runge-Kutta stage, the drives' phases by the addition theorem); since then it compares to
round-off against these arrays. They are the baseline's own: this script refuses to write
unless their SHA-256 is the baseline's, so it runs on a checkout of the code before that
change (9b91f6f or earlier, its ``src`` first on the path):

    PYTHONPATH=<checkout>/src:tests python tests/data/make_static_ratio_history.py

Writes tests/data/static_ratio_history.npz.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

import vibrofriction as vf
from history_checks import HISTORY_FIELDS, history_digest
from vibrofriction.params import Dimensionless

HERE = Path(__file__).resolve().parent


def main() -> None:
    base = json.loads((HERE / "static_ratio_baseline.json").read_text())
    h = base["histories"][0]
    sim = vf.simulate(Dimensionless(**h["system"]), v_inertial=h["v_inertial"],
                      periods=h["periods"], initial=h["initial"])
    if history_digest(sim) != base["history_sha256"][0]:
        raise SystemExit("this code does not give the baseline's history bit for bit: run it "
                         "on a checkout of the code before the change (see the docstring)")
    np.savez_compressed(HERE / "static_ratio_history.npz",
                        **{name: np.asarray(getattr(sim, name), dtype=float)
                           for name in HISTORY_FIELDS})


if __name__ == "__main__":
    main()
