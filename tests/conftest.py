"""Shared fixtures and helpers for the test-suite.

Under pytest-xdist (``make test``, ``make fast``: ``-n auto --dist loadfile``) the tests
of one module run on one worker, so that a module-scoped fixture (a built wheel, a
reproduction, a sweep, a rendered figure, the site's server) is computed once, not once
per worker. (``--dist loadgroup`` with an ``xdist_group`` per module would balance
better, but pytest-xdist 3.8 on pytest 9.2 ignores the groups: pytest-xdist issue 1386.)
"""

import os

import numpy as np
import pytest

import vibrofriction as vf

# No compile notice on stderr (tests compare stderr; the notice has its own tests, which
# turn it on): set before any kernel compiles, inherited by the subprocesses tests start
os.environ.setdefault("VIBROFRICTION_COMPILE_NOTICE", "0")


@pytest.fixture(scope="session")
def general_system():
    return vf.Dimensionless(alpha=0.5, beta=2.0, amplitude=0.5)


@pytest.fixture(scope="session")
def rng():
    return np.random.default_rng(20170101)

