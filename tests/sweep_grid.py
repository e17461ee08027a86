"""The sweeps' shared grid and bitwise comparison (tests/sweep/: the local, Dask and store
tests compare their results with a serial sweep of the same grid)."""

from __future__ import annotations

import numpy as np
import xarray as xr

VBAR = np.linspace(0.0, 1.2, 13)
GRID = dict(alpha=[0.01, 0.1, 0.3], beta=[2.0, 5.0], amplitude=0.5, vbar=VBAR)


def assert_bitwise(a: xr.Dataset, b: xr.Dataset) -> None:
    """Same variables, same coordinates, and every numeric array equal byte for byte."""
    assert set(a.variables) == set(b.variables)
    for name in a.variables:
        x, y = a[name].values, b[name].values
        assert a[name].dims == b[name].dims, name
        if x.dtype.kind in "OUT" or y.dtype.kind in "OUT":
            assert [str(v) for v in x.ravel()] == [str(v) for v in y.ravel()], name
        else:
            assert x.dtype == y.dtype, name
            assert x.tobytes() == y.tobytes(), name
