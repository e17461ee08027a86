"""``vibrofriction sweep`` (an atlas into a zarr store) and ``vibrofriction plot STORE``.

The sweep machinery (xarray, zarr, Dask) is imported inside the commands, so that
the other commands start fast.
"""

from __future__ import annotations

import time
from typing import Any

from ..schema import parameter_names
from ._app import Args, Command, Exit, check_axis
from ._options import (
    FLOATS,
    FRICTION_SI,
    INITIAL,
    INT,
    MAX_PERIODS,
    TOL_TRUSTED,
    Opt,
    Range,
    by_name,
    flag,
    model_options,
    with_,
)

#: The schema's parameters the sweep does not take as axes (docs/inplane.md).
NOT_SWEPT = ("alpha_y", "zeta_y", "k_y", "c_y")
_AXES = model_options({}, skip=NOT_SWEPT)
_AXIS_OPTIONS = tuple(with_(o, kind="axis", metavar=FLOATS) if o.parameter is not None
                      else o for o in _AXES)

OPTIONS: tuple[Opt, ...] = (
    Opt("out", "zarr store to write (resumed if it exists)", kind="text", metavar="STORE",
        required=True),
    *_AXIS_OPTIONS,
    *(with_(o, kind="axis", metavar=FLOATS) for o in FRICTION_SI),
    Opt("scheduler", "Dask scheduler address (tcp://host:port): run on that cluster",
        kind="text", metavar="ADDRESS"),
    Opt("workers", "local worker processes (default: all cores)", kind="int", metavar=INT,
        range=Range(1.0)),
    Opt("chunk_size", "points per block of work (default: about 1% of the grid, 1000 to "
        "10000)", kind="int", metavar=INT, range=Range(1.0)),
    Opt("continuation", "walk each velocity curve up then down from the previous final "
        "state", kind="flag", default=False),
    Opt("up_only", "with --continuation: walk each velocity curve up only (one solve a "
        "point)", kind="flag", default=False, requires=("continuation",)),
    INITIAL, MAX_PERIODS, TOL_TRUSTED,
    Opt("overwrite", "replace the store, do not resume", kind="flag", default=False),
    Opt("progress", "progress bar on stderr", kind="flag", default=True),
)
_BY_NAME = by_name(OPTIONS)
_PHYSICAL = tuple(n for n in parameter_names("physical", optional=False)
                  if n not in parameter_names("dimensionless"))
#: The SI parameters a physical sweep needs, and those with a default.
REQUIRED_SI = tuple(n for n in _PHYSICAL if _BY_NAME[n].default is None)
OPTIONAL_SI = tuple(n for n in _PHYSICAL if _BY_NAME[n].default is not None)
#: The friction law of a physical sweep: the static coefficient (an axis; default mu0) and
#: the rate-and-state law's fixed values (SI).
FRICTION = tuple(o.name for o in FRICTION_SI)
LAW_SI = ("mu_static", *FRICTION)
#: The parameters of both kinds of sweep (a phase, the tip's profile), and the choice.
SHARED = ("phase_x", "phase_y", "profile_exponent")
SCALED = tuple(n for n in parameter_names("dimensionless", optional=False)
               if n not in SHARED) + ("vbar", "v_inertial")


def run(a: Args) -> None:
    """The sweep (heavy imports happen here)."""
    from ..parallel import check_workers
    from ..solver import SolverSettings

    if a.has("workers"):
        check_workers(a["workers"], "--workers")
    if a.has("scheduler") and a.has("workers"):
        raise ValueError("give either --scheduler or --workers")
    grid = _grid(a)
    if a.has("rs_law"):
        grid["rs_law"] = a["rs_law"]
    options = dict(store=a["out"], chunk_size=a["chunk_size"], inplane_on=a["inplane_on"],
                   settings=SolverSettings(max_periods=a["max_periods"],
                                           tol_trusted=a["tol_trusted"]),
                   initial=a["initial"],
                   continuation="up" if a["up_only"] and a["continuation"] else a["continuation"],
                   progress=a["progress"], overwrite=a["overwrite"])
    start = time.perf_counter()
    ds = _run(grid, options, scheduler=a["scheduler"], workers=a["workers"])
    print(_summary(a["out"], ds, time.perf_counter() - start))
    untrusted = _untrusted(ds)
    if untrusted:
        import sys

        print(untrusted, file=sys.stderr)
        raise Exit(3)


def _axis(a: Args, name: str) -> Any:
    from ..sweep import parse_axis

    values = parse_axis(a[name], name)
    check_axis(_BY_NAME[name], values)
    return values


def _grid(a: Args) -> dict:
    """The keyword arguments of :func:`vibrofriction.sweep.sweep` for the grid."""
    si = [flag(n) for n in (*REQUIRED_SI, *OPTIONAL_SI, *LAW_SI, "v0") if a.has(n)]
    if si:
        scaled = [flag(n) for n in SCALED if a.has(n)]
        if scaled:
            raise ValueError(f"give either the dimensionless parameters ({', '.join(scaled)}) "
                             f"or the physical ones ({', '.join(si)}); the friction law is "
                             "--static-ratio, --rs-a ... in the first, --mu-static, "
                             "--friction-a ... in the second")
        return _physical_grid(a)
    missing = [flag(n) for n in ("alpha", "beta", "amplitude") if not a.has(n)]
    if missing:
        raise ValueError("missing " + ", ".join(missing))
    if a.has("vbar") == a.has("v_inertial"):
        raise ValueError("give exactly one of --vbar and --v-inertial")
    return {n: _axis(a, n) for n in (*SCALED, *SHARED) if a.has(n)}


def _physical_grid(a: Args) -> dict:
    import numpy as np

    from ..params import Physical, RateAndState

    missing = [flag(n) for n in (*REQUIRED_SI, "v0") if not a.has(n)]
    if missing:
        raise ValueError("a physical sweep needs every SI parameter and v0; missing "
                         + ", ".join(missing))
    values = {n: _axis(a, n) for n in (*REQUIRED_SI, *OPTIONAL_SI, *SHARED, *LAW_SI)
              if a.has(n)}
    first: dict[str, Any] = {k: float(np.atleast_1d(v)[0]) for k, v in values.items()}
    law = {n.removeprefix("friction_"): first.pop(n) for n in FRICTION if n in first}
    friction = None
    if law:  # --friction-a is given (the others require it): the law of the first values
        missing = [flag(n) for n in ("friction_d_c", "friction_v_ref") if not a.has(n)]
        if missing:
            raise ValueError("rate-and-state friction (--friction-a) needs "
                             + ", ".join(missing))
        friction = RateAndState(**law, law=a["rs_law"])
    return dict(system=Physical(**first, friction=friction), v0=_axis(a, "v0"), **values)


def _run(grid: dict, options: dict, *, scheduler: str | None, workers: int | None):
    """The sweep, on the Dask cluster at ``scheduler`` or on local processes."""
    from ..sweep import sweep

    if scheduler is None:
        return sweep(**grid, workers=workers, **options)
    from distributed import Client

    with Client(scheduler) as client:
        return sweep(**grid, client=client, **options)


def _summary(out: str, ds, elapsed: float) -> str:
    """``OUT: N points (dims) in T s; status counts``."""
    import numpy as np

    from ..solver import STATUS_BY_CODE

    codes, counts = np.unique(ds["status"].values, return_counts=True)
    statuses = ", ".join(f"{STATUS_BY_CODE[int(c)].value} {n}" for c, n in
                         zip(codes, counts, strict=True) if int(c) in STATUS_BY_CODE)
    sizes = " x ".join(f"{d} {n}" for d, n in ds.sizes.items())
    return (f"{out}: {int(np.prod(list(ds.sizes.values())))} points ({sizes}) "
            f"in {elapsed:.1f} s; {statuses}")


def _untrusted(ds) -> str:
    """One line counting the points that are not trusted, by reason (empty if none)."""
    import numpy as np

    from ..solver import STATUS_BY_CODE, converged

    trusted = np.asarray(ds["trusted"].values, dtype=bool)
    if trusted.all():
        return ""
    status = np.asarray(ds["status"].values)
    bad = ~trusted
    ok = converged(status)
    parts = [f"status {STATUS_BY_CODE[int(c)].value}: {int(np.sum(bad & (status == c)))}"
             for c in np.unique(status[bad & ~ok]) if int(c) in STATUS_BY_CODE]
    pending = int(np.sum(bad & ~np.isin(status, list(STATUS_BY_CODE))))
    if pending:
        parts.append(f"not computed: {pending}")
    large = int(np.sum(bad & ok))
    if large:
        parts.append(f"error > tol_trusted = {ds.attrs.get('solver_tol_trusted', 'nan'):g}: "
                     f"{large}")
    return f"{int(bad.sum())} of {bad.size} points are not trusted ({', '.join(parts)})"


def run_plot(a: Args) -> None:
    """Quick look at an atlas (heavy imports happen here)."""
    from ..figures import plot_atlas
    from ..sweep import open_atlas

    chosen = {}
    for item in a["sel"] or []:
        dim, eq, value = item.partition("=")
        if not eq or not dim.strip() or not value.strip():
            raise ValueError(f"--sel takes dim=value, got '{item}'")
        chosen[dim.strip()] = value.strip()
    ds = open_atlas(a["store"])
    plot_atlas(ds, x=a["x"], y=a["y"], var=a["var"], sel=chosen, out=a["out"])
    print(a["out"])


COMMAND = Command(
    "sweep", "an atlas of mu/mu0 over a grid into a resumable zarr store",
    """Compute an atlas of mu/mu0 (eq. 25) over a grid into a resumable zarr store.

    Each parameter takes a value, a comma list (0.25,0.5,1; 0.5, for a one-value axis)
    or start:stop:num[:log] (0:1.2:121 is linspace, 1e-2:1e2:41:log geomspace). Give the
    dimensionless parameters with --vbar or --v-inertial, or the SI ones with --v0.
    The friction law: --static-ratio and --rs-a ... --rs-alpha-ld are axes of a
    dimensionless sweep, --mu-static and the rate-and-state law's --friction-a,
    --friction-b, --friction-d-c, --friction-v-ref, --friction-alpha-ld axes of a physical
    one; --rs-law is one for the grid.

    Exit status 0 if every point is trusted (converged status and error <= tol_trusted),
    3 if some are not (everything is still written), 2 for bad input.

    Example: vibrofriction sweep --alpha 1e-2:0.5:41:log --beta 2:400:20:log --amplitude
    0.5 --vbar 0:1.2:121 --out atlas.zarr""",
    OPTIONS, run)

PLOT = Command(
    "plot", "quick look at an atlas: curves or a map",
    "Quick look at an atlas: curves along one dimension or a map over two.",
    (Opt("store", "zarr store written by vibrofriction sweep", kind="text", metavar="STORE",
         positional=True),
     Opt("out", "image file to write (.png, .pdf, .svg)", kind="text", metavar="FILE",
         required=True),
     Opt("x", "dimension along the horizontal axis (default: the velocity)", kind="text",
         metavar="DIM"),
     Opt("y", "second dimension: draw a map", kind="text", metavar="DIM"),
     Opt("var", "variable to plot", kind="text", default="mu_ratio", metavar="NAME"),
     Opt("sel", "fix a dimension: dim=value (nearest; direction=up|down); repeatable",
         kind="text", metavar="DIM=VALUE", repeat=True)),
    run_plot)
