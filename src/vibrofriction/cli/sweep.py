"""``vibrofriction sweep`` (an atlas into a zarr store) and ``vibrofriction plot STORE``.

The sweep machinery (xarray, zarr, Dask) is imported inside the commands, so that
the other commands start fast.
"""

from __future__ import annotations

import time
from typing import Annotated, Any

import numpy as np
import typer

from ..params import Physical
from ..solver import STATUS_BY_CODE, SolverSettings, converged
from ._app import app, friendly

_AXIS = "a value, a comma list, or start:stop:num[:log]"


def _opt(help_: str):
    return typer.Option(help=f"{help_}; {_AXIS}")


@app.command("sweep")
@friendly
def sweep_command(
    out: Annotated[str, typer.Option(help="zarr store to write (resumed if it exists)")],
    alpha: Annotated[str | None, _opt("alpha = k_x/(m omega^2), eq. (20)")] = None,
    beta: Annotated[str | None, _opt("beta = (k_x + k_xc)/(m omega^2) > alpha; inf = rigid")]
    = None,
    amplitude: Annotated[str | None, _opt("a = du_z/u_z0 >= 0")] = None,
    zeta: Annotated[str | None, _opt("damping ratio of the pin (default 0)")] = None,
    eta_c: Annotated[str | None, typer.Option(
        "--eta-c", help=f"loss factor of the contact (default 0); {_AXIS}")] = None,
    a_x: Annotated[str | None, typer.Option(
        "--a-x", help=f"in-plane oscillation along the sliding, du_x m omega^2/(mu0 F_N0) "
        f"(default 0; docs/inplane.md); {_AXIS}")] = None,
    phase_x: Annotated[str | None, typer.Option(
        "--phase-x", help=f"its phase relative to the normal oscillation, rad (default 0; "
        f"physical sweeps too); {_AXIS}")] = None,
    a_y: Annotated[str | None, typer.Option(
        "--a-y", help=f"in-plane oscillation across the sliding (the 2-D solver; default "
        f"0); {_AXIS}")] = None,
    phase_y: Annotated[str | None, typer.Option(
        "--phase-y", help=f"its phase, rad (default 0; physical sweeps too); {_AXIS}")] = None,
    profile_exponent: Annotated[str | None, typer.Option(
        "--profile-exponent", help=f"exponent n of the tip z = c r^n (default inf: the flat "
        f"punch; 2 a sphere, 1 a cone: the MDR solver, slow; with --a-x at velocities "
        f"!= 0, not with --eta-c or --a-y; physical sweeps too; docs/contact_geometry.md); "
        f"{_AXIS}")] = None,
    inplane_on: Annotated[str, typer.Option(
        "--inplane-on", help="where the in-plane oscillation is imposed: substrate or "
        "holder")] = "substrate",
    vbar: Annotated[str | None, _opt("velocity v0/v0* (eq. 16)")] = None,
    v_inertial: Annotated[str | None, typer.Option(
        "--v-inertial", help=f"velocity v0 m omega/(mu0 F_N0) (Fig. 6; signed); {_AXIS}")]
    = None,
    mass: Annotated[str | None, _opt("physical sweep: mass m, kg")] = None,
    k_x: Annotated[str | None, typer.Option("--k-x", help=f"k_x, N/m; {_AXIS}")] = None,
    k_xc: Annotated[str | None, typer.Option("--k-xc", help=f"k_xc, N/m; {_AXIS}")] = None,
    k_zc: Annotated[str | None, typer.Option("--k-zc", help=f"k_zc, N/m; {_AXIS}")] = None,
    u_z0: Annotated[str | None, typer.Option("--u-z0", help=f"u_z0, m; {_AXIS}")] = None,
    du_z: Annotated[str | None, typer.Option("--du-z", help=f"du_z, m; {_AXIS}")] = None,
    omega: Annotated[str | None, _opt("omega, rad/s")] = None,
    mu0: Annotated[str | None, _opt("local coefficient of friction mu0")] = None,
    c_x: Annotated[str | None, typer.Option(
        "--c-x", help=f"physical sweep: pin dashpot, N s/m (default 0); {_AXIS}")] = None,
    c_xc: Annotated[str | None, typer.Option(
        "--c-xc", help=f"physical sweep: contact dashpot, N s/m (default 0); {_AXIS}")] = None,
    du_x: Annotated[str | None, typer.Option(
        "--du-x", help=f"physical sweep: in-plane amplitude along the sliding, m (default "
        f"0); {_AXIS}")] = None,
    du_y: Annotated[str | None, typer.Option(
        "--du-y", help=f"physical sweep: in-plane amplitude across the sliding, m (default "
        f"0); {_AXIS}")] = None,
    v0: Annotated[str | None, _opt("physical sweep: velocity v0, m/s (signed)")] = None,
    scheduler: Annotated[str | None, typer.Option(
        help="Dask scheduler address (tcp://host:port): run on that cluster")] = None,
    workers: Annotated[int | None, typer.Option(
        help="local worker processes (default: all cores)")] = None,
    chunk_size: Annotated[int | None, typer.Option(
        help="points per block of work [default: about 1% of the grid, 1000 to 10000]")] = None,
    continuation: Annotated[bool, typer.Option(
        help="walk each velocity curve up then down from the previous final state")] = False,
    initial: Annotated[str, typer.Option(help="initial state: sliding or rest")] = "sliding",
    max_periods: Annotated[int | None, typer.Option(
        help="give up after this many periods (default: each solver's own)")] = None,
    tol_trusted: Annotated[float, typer.Option(
        help="largest error estimate of a trusted point")] = SolverSettings.tol_trusted,
    overwrite: Annotated[bool, typer.Option(help="replace the store, do not resume")] = False,
    progress: Annotated[bool, typer.Option(help="progress bar on stderr")] = True,
) -> None:
    """Compute an atlas of mu/mu0 (eq. 25) over a grid into a resumable zarr store.

    Exit status 0 if every point is trusted (converged status and error <= tol_trusted),
    3 if some are not (everything is still written), 2 for bad input.

    Example: vibrofriction sweep --alpha 1e-2:0.5:41:log --beta 2:400:20:log
    --amplitude 0.5 --vbar 0:1.2:121 --out atlas.zarr
    """
    from ..parallel import check_workers

    if workers is not None:
        check_workers(workers, "--workers")
    if scheduler is not None and workers is not None:
        raise ValueError("give either --scheduler or --workers")
    phys = {"mass": mass, "k_x": k_x, "k_xc": k_xc, "k_zc": k_zc, "u_z0": u_z0,
            "du_z": du_z, "omega": omega, "mu0": mu0}
    optional = {"c_x": c_x, "c_xc": c_xc, "du_x": du_x, "du_y": du_y}
    grid = _grid(dict(alpha=alpha, beta=beta, amplitude=amplitude, zeta=zeta, eta_c=eta_c,
                      a_x=a_x, a_y=a_y, vbar=vbar, v_inertial=v_inertial), phys, optional,
                 v0, {"phase_x": phase_x, "phase_y": phase_y,
                      "profile_exponent": profile_exponent})
    options = dict(store=out, chunk_size=chunk_size, inplane_on=inplane_on,
                   settings=SolverSettings(max_periods=max_periods, tol_trusted=tol_trusted),
                   initial=initial,
                   continuation=continuation, progress=progress, overwrite=overwrite)
    start = time.perf_counter()
    ds = _run(grid, options, scheduler=scheduler, workers=workers)
    typer.echo(_summary(out, ds, time.perf_counter() - start))
    untrusted = _untrusted(ds)
    if untrusted:
        typer.echo(untrusted, err=True)
        raise typer.Exit(3)


def _flag(name: str) -> str:
    return "--" + name.replace("_", "-")


def _grid(dimensionless: dict[str, str | None], phys: dict[str, str | None],
          optional: dict[str, str | None], v0: str | None,
          phases: dict[str, str | None]) -> dict:
    """The keyword arguments of :func:`vibrofriction.sweep.sweep` for the grid
    (``optional``: the SI parameters with a default; the ``phases`` belong to both kinds)."""
    if any(v is not None for v in (*phys.values(), *optional.values())) or v0 is not None:
        if any(v is not None for v in dimensionless.values()):
            raise ValueError("give either the dimensionless parameters or the physical ones")
        return _physical_grid(phys, {**optional, **phases}, v0)
    return _dimensionless_grid(**dimensionless, **phases)


def _physical_grid(phys: dict[str, str | None], optional: dict[str, str | None],
                   v0: str | None) -> dict:
    from ..sweep import parse_axis

    missing = [k for k, v in phys.items() if v is None] + (["v0"] if v0 is None else [])
    if missing:
        raise ValueError("a physical sweep needs every SI parameter and v0; missing "
                         + ", ".join(_flag(m) for m in missing))
    values = {k: parse_axis(v, k) for k, v in phys.items() if v is not None}
    values.update({k: parse_axis(v, k) for k, v in optional.items() if v is not None})
    first: dict[str, Any] = {k: float(np.atleast_1d(v)[0]) for k, v in values.items()}
    assert v0 is not None  # not missing
    return dict(system=Physical(**first), v0=parse_axis(v0, "v0"), **values)


def _dimensionless_grid(alpha: str | None, beta: str | None, amplitude: str | None,
                        zeta: str | None, eta_c: str | None, a_x: str | None,
                        a_y: str | None, vbar: str | None, v_inertial: str | None,
                        phase_x: str | None, phase_y: str | None,
                        profile_exponent: str | None) -> dict:
    from ..sweep import parse_axis

    given = {"alpha": alpha, "beta": beta, "amplitude": amplitude}
    missing = [n for n, v in given.items() if v is None]
    if missing:
        raise ValueError("missing " + ", ".join(_flag(m) for m in missing))
    if (vbar is None) == (v_inertial is None):
        raise ValueError("give exactly one of --vbar and --v-inertial")
    grid = {n: parse_axis(v, n) for n, v in given.items() if v is not None}
    for n, v in (("zeta", zeta), ("eta_c", eta_c), ("a_x", a_x), ("phase_x", phase_x),
                 ("a_y", a_y), ("phase_y", phase_y), ("profile_exponent", profile_exponent)):
        if v is not None:
            grid[n] = parse_axis(v, n)
    if vbar is not None:
        grid["vbar"] = parse_axis(vbar, "vbar")
    elif v_inertial is not None:  # exactly one of them is given
        grid["v_inertial"] = parse_axis(v_inertial, "v_inertial")
    return grid


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
    codes, counts = np.unique(ds["status"].values, return_counts=True)
    statuses = ", ".join(f"{STATUS_BY_CODE[int(c)].value} {n}" for c, n in
                         zip(codes, counts, strict=True) if int(c) in STATUS_BY_CODE)
    sizes = " x ".join(f"{d} {n}" for d, n in ds.sizes.items())
    return (f"{out}: {int(np.prod(list(ds.sizes.values())))} points ({sizes}) "
            f"in {elapsed:.1f} s; {statuses}")


def _untrusted(ds) -> str:
    """One line counting the points that are not trusted, by reason (empty if none)."""
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


@app.command("plot")
@friendly
def plot_command(
    store: Annotated[str, typer.Argument(help="zarr store written by `vibrofriction sweep`")],
    out: Annotated[str, typer.Option(help="image file to write (.png, .pdf, .svg)")],
    x: Annotated[str | None, typer.Option(help="dimension along the horizontal axis "
                                          "(default: the velocity)")] = None,
    y: Annotated[str | None, typer.Option(help="second dimension: draw a map")] = None,
    var: Annotated[str, typer.Option(help="variable to plot")] = "mu_ratio",
    sel: Annotated[list[str] | None, typer.Option(
        help="fix a dimension: dim=value (nearest; direction=up|down); repeatable")] = None,
) -> None:
    """Quick look at an atlas: curves along one dimension or a map over two."""
    from ..figures import plot_atlas
    from ..sweep import open_atlas

    chosen = {}
    for item in sel or []:
        dim, eq, value = item.partition("=")
        if not eq or not dim.strip() or not value.strip():
            raise ValueError(f"--sel takes dim=value, got {item!r}")
        chosen[dim.strip()] = value.strip()
    ds = open_atlas(store)
    plot_atlas(ds, x=x, y=y, var=var, sel=chosen, out=out)
    typer.echo(out)
