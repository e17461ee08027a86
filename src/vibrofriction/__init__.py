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

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from . import sweep
    from .bench import (
        design,
        fit,
        from_bench,
        from_bench_file,
        read_bench_file,
        read_measurements,
        synthetic_measurements,
    )
    from .params import Case, Dimensionless, Physical, RateAndState, classify, pin_damping
    from .solver import (
        CurvedHistory,
        Event,
        FrictionResult,
        FrictionResults,
        History,
        PlaneHistory,
        RateStateHistory,
        SectionState,
        SolverSettings,
        Status,
        friction_coefficient,
        simulate,
    )

    __version__: str

# Every name -- and every submodule, ``vf.solver``, ``vf.theory`` -- is imported on first
# use (PEP 562), so that ``import vibrofriction`` -- and the command line's
# ``vibrofriction --help`` -- does not pay for numba, scipy and the kernels;
# ``vibrofriction.sweep`` (a callable module) pulls in xarray, zarr and Dask and the bench
# lmfit, pandas and xarray, likewise only when used.
_WHERE = {
    **dict.fromkeys(("Case", "Dimensionless", "Physical", "RateAndState", "classify",
                     "pin_damping"), ".params"),
    **dict.fromkeys(("CurvedHistory", "Event", "FrictionResult", "FrictionResults", "History",
                     "PlaneHistory", "RateStateHistory", "SectionState", "SolverSettings", "Status",
                     "friction_coefficient", "simulate"), ".solver"),
    **dict.fromkeys(("read_measurements", "fit", "design", "synthetic_measurements",
                     "from_bench", "from_bench_file", "read_bench_file"), ".bench"),
}


def _version() -> str:
    from importlib.metadata import PackageNotFoundError, version

    try:  # the one place the version is written is pyproject.toml
        return version("vibrofriction")
    except PackageNotFoundError:  # pragma: no cover - a source tree not installed
        return "0+unknown"


def __getattr__(name: str) -> Any:
    import importlib

    if name == "__version__":
        value: Any = _version()
    elif name in _WHERE:
        value = getattr(importlib.import_module(_WHERE[name], __name__), name)
    elif not name.startswith("__"):  # a subpackage or module: vf.solver, vf.theory, vf.sweep
        try:
            return importlib.import_module("." + name, __name__)
        except ModuleNotFoundError as err:
            if err.name != f"{__name__}.{name}":
                raise
            raise AttributeError(f"module {__name__!r} has no attribute {name!r}") from None
    else:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    globals()[name] = value  # once: the next look-up is a plain attribute
    return value


def __dir__() -> list[str]:
    return sorted({*globals(), *__all__})


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
    "RateAndState",
    "RateStateHistory",
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
