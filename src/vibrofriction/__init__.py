"""vibrofriction: friction under normal oscillations.

Implements and extends X. Mao, V. L. Popov, J. Starcevic, M. Popov, "Reduction of
friction by normal oscillations. II. In-plane system dynamics", Friction (2017).

Examples
--------
The steady-state friction of a system at half its critical velocity (eq. 25):

>>> import vibrofriction as vf
>>> system = vf.Dimensionless(alpha=0.1, beta=2.0, amplitude=0.5)
>>> result = vf.friction_coefficient(system, vbar=0.5)
>>> result.mu_ratio, result.status, result.trusted
(0.587544617143..., <Status.PERIODIC: 'periodic'>, True)
"""

from importlib.metadata import PackageNotFoundError, version

from .params import Case, Dimensionless, Physical, classify, pin_damping
from .solver import (
    Event,
    FrictionResult,
    FrictionResults,
    History,
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


_BENCH = ("read_measurements", "fit", "design", "synthetic_measurements")


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
    "Dimensionless",
    "Event",
    "FrictionResult",
    "FrictionResults",
    "History",
    "Physical",
    "SectionState",
    "SolverSettings",
    "Status",
    "classify",
    "design",
    "fit",
    "friction_coefficient",
    "pin_damping",
    "read_measurements",
    "simulate",
    "sweep",
    "synthetic_measurements",
    "__version__",
]
