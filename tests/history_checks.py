"""Shared checks of time histories (tests/inplane, tests/mdr): section rows, the energy
balance per period, a digest of a history's arrays, and a history against stored ones."""

from __future__ import annotations

import hashlib
import math
from pathlib import Path
from types import SimpleNamespace

import numpy as np

import vibrofriction as vf

TWO_PI = 2.0 * math.pi
#: The arrays of a history that :func:`history_digest` hashes (as
#: tests/data/make_static_ratio_baseline.py does).
HISTORY_FIELDS = ("tau", "x", "x_dot", "f", "n", "e", "work_input", "dissipated_pin",
                  "dissipated_contact", "dissipated_friction", "impulse")


def section_rows(h: vf.History) -> list[int]:
    """The last row at each ``tau = 2 pi k`` (the state after any event there)."""
    k = int(round(h.tau[-1] / TWO_PI))
    return [int(np.flatnonzero(np.isclose(h.tau, TWO_PI * j, rtol=0, atol=1e-12))[-1])
            for j in range(k + 1)]


def period_balance(h: vf.History) -> float:
    """The largest energy residual per period, relative to the work per period."""
    rows = section_rows(h)
    E = h.stored_energy()
    d = (h.dissipated_pin + h.dissipated_contact + h.dissipated_friction)
    res = np.diff(h.work_input[rows]) - np.diff(d[rows]) - np.diff(E[rows])
    return float(np.max(np.abs(res) / np.maximum(np.abs(np.diff(h.work_input[rows])), 1e-3)))


def history_digest(h: vf.History) -> str:
    """SHA-256 of a history's arrays (:data:`HISTORY_FIELDS`, as float64 bytes)."""
    d = hashlib.sha256()
    for name in HISTORY_FIELDS:
        d.update(np.ascontiguousarray(getattr(h, name), dtype=float).tobytes())
    return d.hexdigest()


#: Round-off of a history's arrays, relative to each array's largest value
ROUNDOFF = 1e-12


def assert_history_is_stored(h: vf.History, path: Path, digest: str) -> None:
    """``h`` against the arrays stored at ``path`` (:data:`HISTORY_FIELDS`): the same time
    grid (its event times, roots found to round-off, may move by an ulp when the arithmetic
    of a kernel is reordered), every array to :data:`ROUNDOFF`; the stored arrays must hash
    to ``digest`` (:func:`history_digest`: they are the baseline's own)."""
    with np.load(path) as stored:
        want = {name: stored[name] for name in HISTORY_FIELDS}
    assert history_digest(SimpleNamespace(**want)) == digest
    assert h.tau.shape == want["tau"].shape
    for name in HISTORY_FIELDS:
        have = np.asarray(getattr(h, name), dtype=float)
        np.testing.assert_allclose(have, want[name], rtol=0.0,
                                   atol=ROUNDOFF * (1.0 + np.max(np.abs(want[name]))),
                                   err_msg=name)
