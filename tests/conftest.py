"""Shared fixtures and helpers for the test-suite.

Under pytest-xdist (``make test``, ``make fast``: ``-n auto --dist loadfile``) the tests
of one module run on one worker, so that a module-scoped fixture (a built wheel, a
reproduction, a sweep, a rendered figure, the site's server) is computed once, not once
per worker. (``--dist loadgroup`` with an ``xdist_group`` per module would balance
better, but pytest-xdist 3.8 on pytest 9.2 ignores the groups: pytest-xdist issue 1386.)

The modules are handed to the workers in the order of :data:`HEAVY_FIRST`, then the rest
by their number of tests (the Makefile passes ``--no-loadscope-reorder``: xdist's own order
is by number of tests alone, which sent the wheel's module, 4 tests and minutes of
set-up, last, with the other worker idle meanwhile). Longest first: the long modules
overlap the many short ones, and the run ends on short ones.
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
    "api/test_wheel.py", "bench/test_fit_transverse.py", "bench/test_fit_intervals.py",
    "bench/test_fit_friction_laws.py",
    "docs/test_quoted_numbers.py", "cli/test_cli_bench.py", "docs/test_examples.py",
    "bench/test_fit_mdr.py", "bench/test_fit.py", "explorer/test_explorer_browser.py",
    "docs/test_site.py", "reference/test_differential_damped.py", "kernels/test_tangent.py",
    "inplane/test_inplane_api.py", "figures/test_reproduce.py")


def pytest_collection_modifyitems(config, items):
    """The modules of :data:`HEAVY_FIRST` first, then the others by number of tests (the
    tests of a module keep their order)."""
    rank = {name: i for i, name in enumerate(HEAVY_FIRST)}
    counts: dict[str, int] = {}
    for item in items:
        module = item.nodeid.split("::")[0]
        counts[module] = counts.get(module, 0) + 1

    def key(module: str) -> tuple[int, int]:
        name = module.removeprefix("tests/")
        return (rank[name], 0) if name in rank else (len(rank), -counts[module])

    order = {m: i for i, m in enumerate(sorted(counts, key=key))}
    items.sort(key=lambda item: order[item.nodeid.split("::")[0]])


@pytest.fixture(scope="session")
def general_system():
    return vf.Dimensionless(alpha=0.5, beta=2.0, amplitude=0.5)


@pytest.fixture(scope="session")
def rng():
    return np.random.default_rng(20170101)

