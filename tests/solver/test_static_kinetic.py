"""A static coefficient above the kinetic one in the 1-D solver (docs/friction_laws.md)."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

import vibrofriction as vf
from vibrofriction.schema import FLOAT_COLUMNS, INT_COLUMNS
from vibrofriction.solver import solve_points

DATA = Path(__file__).parents[1] / "data"
BASE = json.loads((DATA / "static_ratio_base.json").read_text())


def _load_maker():
    import importlib.util

    spec = importlib.util.spec_from_file_location("make_static_ratio_base",
                                                  DATA / "make_static_ratio_base.py")
    mod = importlib.util.module_from_spec(spec)
    assert spec.loader is not None
    spec.loader.exec_module(mod)
    return mod


MAKER = _load_maker()


# --------------------------------------------------------------------------- s_r = 1
@pytest.mark.parametrize("i", range(len(BASE["points"])))
def test_static_ratio_one_is_the_coulomb_solver_bit_for_bit(i):
    """``static_ratio = 1`` reproduces the outputs of the solver before the law existed
    (stored by tests/data/make_static_ratio_base.py on that code), bit for bit.
    """
    p, want = BASE["points"][i], BASE["results"][i]
    # the stored point is unchanged by a fresh draw (the maker's list is the test's)
    assert MAKER.points()[i] == p
    got = MAKER.run_point(p)
    assert got == want
    # and 1.0 given explicitly is the default
    kw = {k: v for k, v in p.items() if k not in ("initial", "inplane_on")}
    cols = solve_points(**kw, static_ratio=1.0, inplane_on=p["inplane_on"],
                        initial=p["initial"])
    assert {k: float(cols[k]).hex() for k in FLOAT_COLUMNS} == \
        {k: want["batch"][k] for k in FLOAT_COLUMNS}
    assert {k: int(cols[k]) for k in INT_COLUMNS} == {k: want["batch"][k] for k in INT_COLUMNS}


@pytest.mark.parametrize("i", range(len(BASE["histories"])))
def test_static_ratio_one_histories_are_unchanged(i):
    assert MAKER.history_digest(BASE["points"][i]) == BASE["histories"][i]


def test_the_base_covers_every_regime():
    pts = BASE["points"]
    assert any(math.isinf(p["beta"]) for p in pts)
    assert any(p["eta_c"] > 0 for p in pts)
    assert any(p["amplitude"] > 1 for p in pts)
    assert any(p["amplitude"] == 0 for p in pts)
    assert any(p["zeta"] > 0 for p in pts)
    assert any(p["a_x"] > 0 and p["inplane_on"] == "substrate" for p in pts)
    assert any(p["a_x"] > 0 and p["inplane_on"] == "holder" for p in pts)
    assert {p["initial"] for p in pts} == {"rest", "sliding"}
    status = {r["scalar"]["status"] for r in BASE["results"]}
    assert {"periodic", "continuous sliding"} <= status
