"""Shared fixtures and helpers for the test-suite.

Under pytest-xdist (``make test``, ``make fast``: ``-n auto --dist loadfile``) the tests
of one module run on one worker, so that a module-scoped fixture (a built wheel, a
reproduction, a sweep, a rendered figure, the site's server) is computed once, not once
per worker. (``--dist loadgroup`` with an ``xdist_group`` per module would balance
better, but pytest-xdist 3.8 on pytest 9.2 ignores the groups: pytest-xdist issue 1386.)

The modules are handed to the workers in the order of :data:`HEAVY_FIRST`, then the rest
by their estimated time, :data:`SLOW_TEST_SECONDS` a ``slow`` test and
:data:`FAST_TEST_SECONDS` another (the Makefile passes ``--no-loadscope-reorder``: xdist's
own order is by number of tests alone, which sent the wheel's module, 4 tests and minutes
of set-up, last, with the other worker idle meanwhile; and by number of tests alone a
module of a few slow tests, 20 to 40 s, came among the last). Longest first: the long
modules overlap the many short ones, and the run ends on modules of fast tests only.
"""

import os

import numpy as np
import pytest

import vibrofriction as vf

# No compile notice on stderr (tests compare stderr; the notice has its own tests, which
# turn it on): set before any kernel compiles, inherited by the subprocesses tests start
os.environ.setdefault("VIBROFRICTION_COMPILE_NOTICE", "0")


#: The modules that take longest (benchmarks/results/test_loop.md), longest first: they
#: start first. A module not listed follows them; a listed one that is gone is ignored.
HEAVY_FIRST = (
    "bench/test_fit_transverse.py", "bench/test_fit_intervals.py",
    "bench/test_fit_friction_laws.py",
    "docs/test_quoted_numbers.py", "cli/test_cli_bench.py", "docs/test_examples.py",
    "bench/test_fit_mdr.py", "bench/test_fit.py", "explorer/test_explorer_browser.py",
    "docs/test_site.py", "reference/test_differential_damped.py", "kernels/test_tangent.py",
    "inplane/test_inplane_api.py", "figures/test_reproduce.py",
    # minutes where it compiles every kernel; about 30 s where make warmup built them
    "api/test_wheel.py")


#: The mean time of a test, slow and not (seconds of a worker), that orders the modules not
#: in HEAVY_FIRST: the fast lane took 165 s on 2 workers for 2210 tests (0.15 s a test),
#: the clean-clone run 890 s on 2 workers for 2660 tests, so about 4 s a slow test
#: (2026-11-29, benchmarks/results/test_loop.md and docs/packaging.md)
SLOW_TEST_SECONDS, FAST_TEST_SECONDS = 4.0, 0.15


def pytest_collection_modifyitems(config, items):
    """The modules of :data:`HEAVY_FIRST` first, then the others by their estimated time,
    longest first (the tests of a module keep their order)."""
    rank = {name: i for i, name in enumerate(HEAVY_FIRST)}
    cost: dict[str, float] = {}
    for item in items:
        module = item.nodeid.split("::")[0]
        slow = item.get_closest_marker("slow") is not None
        cost[module] = cost.get(module, 0.0) + (SLOW_TEST_SECONDS if slow
                                                else FAST_TEST_SECONDS)

    def key(module: str) -> tuple[int, float]:
        name = module.removeprefix("tests/")
        return (rank[name], 0.0) if name in rank else (len(rank), -cost[module])

    order = {m: i for i, m in enumerate(sorted(cost, key=key))}
    items.sort(key=lambda item: order[item.nodeid.split("::")[0]])


@pytest.fixture
def rows_alone():
    """The MDR solver's rows of springs alone for the test (``solver.mdr.rows_alone``)."""
    from vibrofriction.solver.mdr import rows_alone

    with rows_alone():
        yield


@pytest.fixture(scope="session")
def general_system():
    return vf.Dimensionless(alpha=0.5, beta=2.0, amplitude=0.5)


@pytest.fixture(scope="session")
def rng():
    return np.random.default_rng(20170101)

