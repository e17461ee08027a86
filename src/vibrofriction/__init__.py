"""vibrofriction: friction under normal oscillations.

Implements and extends X. Mao, V. L. Popov, J. Starcevic, M. Popov, "Reduction of
friction by normal oscillations. II. In-plane system dynamics", Friction (2017).
"""

from importlib.metadata import PackageNotFoundError, version

from .params import Case, Dimensionless, Physical, classify, pin_damping
from .solver import (
    CurvedHistory,
    Event,
    FrictionResult,
    FrictionResults,
    History,
    PlaneHistory,
    SectionState,
    SolverSettings,
    Status,
    friction_coefficient,
    simulate,
)

try:  # the one place the version is written is pyproject.toml
    __version__ = version("vibrofriction")
except PackageNotFoundError:  # pragma: no cover - running from a source tree not installed
    __version__ = "0+unknown"


_BENCH = ("read_measurements", "fit", "design", "synthetic_measurements", "from_bench",
          "from_bench_file", "read_bench_file")


def __getattr__(name: str):
    # ``vibrofriction.sweep`` (a callable module) is imported on first use: it pulls in
    # xarray, zarr and Dask, which a plain ``import vibrofriction`` should not pay for
    if name == "sweep":
        import importlib

        return importlib.import_module(".sweep", __name__)
    if name in _BENCH:  # lmfit, pandas and xarray, likewise on first use
        from . import bench

        return getattr(bench, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

__all__ = [
    "Case",
    "CurvedHistory",
    "Dimensionless",
    "Event",
    "FrictionResult",
    "FrictionResults",
    "History",
    "Physical",
    "PlaneHistory",
    "SectionState",
    "SolverSettings",
    "Status",
    "classify",
    "design",
    "fit",
    "friction_coefficient",
    "from_bench",
    "from_bench_file",
    "pin_damping",
    "read_bench_file",
    "read_measurements",
    "simulate",
    "sweep",
    "synthetic_measurements",
    "__version__",
]
