"""Keep the arrays of two of the baseline's histories, which
tests/data/static_ratio_baseline.json holds only as SHA-256 digests: the 2-D one from the
sliding start (``histories[0]``) and the curved tip's (``histories[2]``).

``tests/inplane/test_static_kinetic_plane.py`` and ``tests/mdr/test_static_kinetic_mdr.py``
compared them bit for bit, which holds only where the arithmetic is the same to the last
digit: the 2-D solver's changed at round-off on 2026-11-29 (one cosine and one sine a
Runge-Kutta stage), and a processor may round differently. They compare to round-off
against these arrays instead, and check that the arrays are the baseline's own (their
digests). This script refuses to write a history whose digest is not the baseline's, so it
runs on a checkout of the code before that change (9b91f6f), its ``src`` first on the path:

    PYTHONPATH=<checkout>/src:tests python tests/data/make_static_ratio_history.py

Writes tests/data/static_ratio_history.npz (2-D) and
tests/data/static_ratio_curved_history.npz.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

import vibrofriction as vf
from history_checks import HISTORY_FIELDS, history_digest
from vibrofriction.params import Dimensionless

HERE = Path(__file__).resolve().parent
FILES = {0: "static_ratio_history.npz", 2: "static_ratio_curved_history.npz"}


def main() -> None:
    base = json.loads((HERE / "static_ratio_baseline.json").read_text())
    for j, name in FILES.items():
        h = base["histories"][j]
        sim = vf.simulate(Dimensionless(**h["system"]), v_inertial=h["v_inertial"],
                          periods=h["periods"], initial=h["initial"])
        if history_digest(sim) != base["history_sha256"][j]:
            raise SystemExit(f"history {j} is not the baseline's bit for bit here: run this "
                             "on a checkout of the code before the change (see the docstring)")
        np.savez_compressed(HERE / name, **{f: np.asarray(getattr(sim, f), dtype=float)
                                            for f in HISTORY_FIELDS})


if __name__ == "__main__":
    main()
