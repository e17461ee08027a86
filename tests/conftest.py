"""Shared fixtures and helpers for the test-suite."""

import numpy as np
import pytest

import vibrofriction as vf


@pytest.fixture(scope="session")
def general_system():
    return vf.Dimensionless(alpha=0.5, beta=2.0, amplitude=0.5)


@pytest.fixture(scope="session")
def rng():
    return np.random.default_rng(20170101)
