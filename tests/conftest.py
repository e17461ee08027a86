"""Shared fixtures and helpers for the test-suite.

Under pytest-xdist (``make test``, ``make fast``: ``-n auto --dist loadgroup``) the tests
of a module that defines a module-scoped fixture (a built wheel, a reproduction, a
sweep, a rendered figure, the site's server) run on one worker, so that the fixture is
computed once, not once per worker: they get the ``xdist_group`` of their module.
"""

import numpy as np
import pytest

import vibrofriction as vf


@pytest.fixture(scope="session")
def general_system():
    return vf.Dimensionless(alpha=0.5, beta=2.0, amplitude=0.5)


@pytest.fixture(scope="session")
def rng():
    return np.random.default_rng(20170101)


def _module_fixture(item: pytest.Item) -> bool:
    """Whether ``item`` uses a module-scoped fixture of its own module."""
    info = getattr(item, "_fixtureinfo", None)
    if info is None:
        return False
    module = item.nodeid.split("::", 1)[0]
    return any(defs[-1].scope == "module" and defs[-1].baseid == module
               for defs in info.name2fixturedefs.values() if defs)


@pytest.hookimpl(tryfirst=True)  # before xdist's own hook reads the groups
def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    for item in items:
        if _module_fixture(item) and not item.get_closest_marker("xdist_group"):
            item.add_marker(pytest.mark.xdist_group(item.nodeid.split("::", 1)[0]))
