"""A continuation in one compiled loop against the same continuation point by point.

:func:`vibrofriction.solver.engine.solve_chain` runs the flat punch's points (``V > 0``,
or static) as one kernel call, each started from its predecessor's final section state;
with Coulomb friction, where that state is an orbit of one period, Newton's method starts
from it at once, from the orbit extrapolated along ``V`` where the two points before are
both such orbits.  Anything else goes point by point.  Here every chain is compared with
the continuation written out with the public API: :func:`solve_points` of one point at a
time, started from :func:`section_state` of the row before (or the chain's own start
where that row has none).  Both reach the same orbits: the same statuses, values within
the two stated errors; where no Newton start is predicted (a static coefficient above the
kinetic one) bit for bit.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from vibrofriction.schema import Status
from vibrofriction.solver import SectionState, SolverSettings, section_state, solve_points
from vibrofriction.solver.engine import solve_chain
from vibrofriction.solver.points import point_table


def _by_hand(points: dict[str, np.ndarray], initial, settings=None,
             restart=()) -> dict[str, np.ndarray]:
    rows = []
    state = None
    for j in range(len(points["alpha"])):
        if j in restart:
            state = None
        one = solve_points(**{k: v[j:j + 1] for k, v in points.items()},
                           initial=state if state is not None else initial, settings=settings)
        rows.append(one)
        state = section_state(float(one["y"][0]), float(one["x_dot"][0]), float(one["f"][0]),
                              int(one["phase"][0]), float(one["e"][0]))
    return {k: np.concatenate([r[k] for r in rows]) for k in rows[0]}


def _assert_same(a: dict[str, np.ndarray], b: dict[str, np.ndarray]) -> None:
    assert a.keys() == b.keys()
    for k in a:
        np.testing.assert_array_equal(a[k], b[k], err_msg=k)


def _assert_same_orbits(chain: dict[str, np.ndarray], hand: dict[str, np.ndarray]) -> None:
    """The same statuses and trust, the values within the two stated errors."""
    np.testing.assert_array_equal(chain["status"], hand["status"])
    np.testing.assert_array_equal(chain["trusted"], hand["trusted"])
    np.testing.assert_array_equal(chain["period"], hand["period"])
    valued = np.isfinite(hand["mu_ratio"])
    np.testing.assert_array_equal(np.isfinite(chain["mu_ratio"]), valued)
    gap = np.abs(chain["mu_ratio"] - hand["mu_ratio"])[valued]
    assert np.all(gap <= (chain["error"] + hand["error"])[valued] + 1e-15), gap.max()


def _row(n: int, **fixed) -> dict[str, np.ndarray]:
    v = np.concatenate([np.linspace(0.02, 1.1, n), np.linspace(1.1, 0.02, n)])
    base = dict(alpha=0.3, beta=2.0, amplitude=0.6, zeta=0.0, eta_c=0.0, a_x=0.0,
                phase_x=0.0, a_y=0.0, static_ratio=1.0) | fixed
    return {"v_inertial": v, **{k: np.full(v.size, float(x)) for k, x in base.items()}}


@pytest.mark.parametrize("fixed", [
    {},  # stick-slip and sliding, up and down
    {"amplitude": 1.5, "beta": 20.0},  # jumping: sections in flight restart the chain
    {"zeta": 0.05, "eta_c": 0.2, "a_x": 0.4, "phase_x": 1.0},  # damped, in-plane drive
    {"beta": math.inf},  # rigid contact
    {"alpha": 0.05, "beta": 20.0},  # a long stick-slip branch
])
def test_compiled_chain_is_the_continuation(fixed):
    points = _row(12, **fixed)
    chain = solve_chain(point_table(points), "sliding", SolverSettings())
    _assert_same_orbits(chain, _by_hand(points, "sliding"))
    assert np.all(chain["status"] != Status.FAILED.code)


def test_static_above_kinetic_chains_the_states_as_they_are():
    """No predicted start there: the chain is the point-by-point walk bit for bit."""
    points = _row(12, static_ratio=1.4)
    chain = solve_chain(point_table(points), "sliding", SolverSettings())
    _assert_same(chain, _by_hand(points, "sliding"))


def test_chain_through_rows_it_cannot_compile():
    """``V = 0``, ``V < 0`` and a transverse point go point by point, the chain intact."""
    points = _row(5)
    points["v_inertial"][[0, 3, 8]] = [0.0, -0.4, 0.0]
    points["a_y"][6] = 0.3
    chain = solve_chain(point_table(points), "rest", SolverSettings())
    _assert_same_orbits(chain, _by_hand(points, "rest"))
    assert chain["status"][0] == chain["status"][8] == Status.STATIC.code


def test_chain_restarts_where_told():
    """Several curves in one table: each restarts from the chain's own start."""
    a, b = _row(6), _row(6, alpha=0.1, zeta=0.02)
    points = {k: np.concatenate([a[k], b[k]]) for k in a}
    restart = np.zeros(24, dtype=bool)
    restart[[0, 12]] = True
    chain = solve_chain(point_table(points), "sliding", SolverSettings(), restart)
    _assert_same_orbits(chain, _by_hand(points, "sliding", restart=(0, 12)))
    # and the second curve is the one solved alone, bit for bit
    alone = solve_chain(point_table(b), "sliding", SolverSettings())
    _assert_same({k: v[12:] for k, v in chain.items()}, alone)


def test_chain_from_a_state_and_with_settings():
    points = _row(6)
    start = SectionState(y=-1.0, x_dot=0.2, f=0.5, phase="stick")  # e from the system
    settings = SolverSettings(tol_state=1e-9, max_periods=3000)
    chain = solve_chain(point_table(points), start, settings)
    _assert_same_orbits(chain, _by_hand(points, start, settings))


@pytest.mark.parametrize(("fixed", "smooth"), [
    ({}, True),  # a smooth branch: the predicted start saves Newton's maps
    ({"alpha": 0.05, "beta": 20.0}, False),  # long stick phases
])
def test_chain_needs_fewer_periods_than_fresh_starts(fixed, smooth):
    """What the chain is for: each point starts near its orbit, and Newton at once."""
    points = _row(20, **fixed)
    chain = solve_chain(point_table(points), "sliding", SolverSettings())
    fresh = solve_points(**points)
    hand = _by_hand(points, "sliding")
    periodic = (chain["status"] == Status.PERIODIC.code) & (fresh["status"] == chain["status"])
    assert periodic.sum() > 15
    work = chain["work"][periodic]
    assert np.median(work) < 0.6 * np.median(fresh["work"][periodic])
    if smooth:  # and than the walk that integrates a period from each state first
        assert work.sum() < 0.9 * hand["work"][periodic].sum()
    same = np.abs(chain["mu_ratio"] - fresh["mu_ratio"]) <= chain["error"] + fresh["error"]
    assert same[periodic].all()  # one attractor at these points


def _transverse(n: int, **fixed) -> dict[str, np.ndarray]:
    return _row(n, **({"alpha": 0.5, "a_y": 0.5, "zeta": 0.02} | fixed))


@pytest.mark.parametrize("fixed", [
    {},  # stick-slip
    {"amplitude": 1.5, "beta": 4.0, "zeta": 0.1},  # jumping, damped
    {"a_x": 0.3, "phase_x": 1.0, "eta_c": 0.2},  # a longitudinal drive too, Kelvin-Voigt
])
def test_a_transverse_curve_chains_its_whole_orbits(fixed):
    """The 2-D solver's points start from the whole orbit before them (its transverse
    components and Jacobian too), Newton's method at once: the orbits of fresh starts, each
    multiplier from its own Jacobian, in about half the periods."""
    points = _transverse(10, **fixed)
    chain = solve_chain(point_table(points), "sliding", SolverSettings())
    fresh = solve_points(**points)
    _assert_same_orbits(chain, fresh)
    assert np.all(chain["status"] == Status.PERIODIC.code)
    assert np.all(chain["method"] == fresh["method"])
    gap = np.abs(chain["lateral_ratio"] - fresh["lateral_ratio"])
    assert np.all(gap <= chain["error"] + fresh["error"] + 1e-15), gap.max()
    np.testing.assert_allclose(chain["multiplier"], fresh["multiplier"], atol=1e-4)
    assert np.median(chain["work"][1:]) < 0.7 * np.median(fresh["work"][1:])
    # the first point has no neighbour: its own start, as a fresh one
    assert chain["work"][0] == fresh["work"][0]


def test_a_transverse_chain_restarts_where_told():
    a, b = _transverse(5), _transverse(5, alpha=0.3, zeta=0.05)
    points = {k: np.concatenate([a[k], b[k]]) for k in a}
    restart = np.zeros(20, dtype=bool)
    restart[[0, 10]] = True
    chain = solve_chain(point_table(points), "sliding", SolverSettings(), restart)
    _assert_same({k: v[10:] for k, v in chain.items()},
                 solve_chain(point_table(b), "sliding", SolverSettings()))
    _assert_same({k: v[:10] for k, v in chain.items()},
                 solve_chain(point_table(a), "sliding", SolverSettings()))


def test_a_chain_from_the_flat_punch_into_a_transverse_drive():
    """A row over ``a_y`` from 0: the first 2-D point starts from the 1-D orbit before it
    (its ``x`` components), the next ones from whole 2-D orbits."""
    points = _row(8)
    points["v_inertial"] = np.full(16, 0.3)
    points["a_y"] = np.linspace(0.0, 0.6, 16)
    chain = solve_chain(point_table(points), "sliding", SolverSettings())
    _assert_same_orbits(chain, _by_hand(points, "sliding"))
    assert chain["method"][0] != chain["method"][1]


def test_a_transverse_chain_with_static_above_kinetic_runs_its_transients():
    """No Newton start from the neighbour there (sliding and stick-slip coexist): each point
    runs the transient from the whole state before it, and reaches the orbits of fresh
    starts."""
    points = _transverse(6, static_ratio=1.3)
    chain = solve_chain(point_table(points), "sliding", SolverSettings())
    _assert_same_orbits(chain, solve_points(**points))
