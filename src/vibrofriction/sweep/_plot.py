"""Quick look at an atlas: curves along one dimension, or a map over two.

matplotlib is imported here only (lazily, by :func:`vibrofriction.sweep.plot_atlas`),
and without pyplot, so it works headless.
"""

from __future__ import annotations

import os
from typing import Any

import numpy as np
import xarray as xr

from ..solver import STATUS_BY_CODE
from ._store import open_atlas
from ._variables import STATUS_PENDING

__all__ = ["plot_atlas"]

_TEX = {
    "alpha": r"$\alpha$", "beta": r"$\beta$", "amplitude": r"$a$", "vbar": r"$\bar v$",
    "v_inertial": r"$v_0 m\omega/(\mu_0 F_{N0})$", "v0": r"$v_0$ [m/s]",
    "mu_ratio": r"$\mu/\mu_0$", "mass": r"$m$ [kg]", "k_x": r"$k_x$ [N/m]",
    "k_xc": r"$k_{x,c}$ [N/m]", "k_zc": r"$k_{z,c}$ [N/m]", "u_z0": r"$u_{z0}$ [m]",
    "du_z": r"$\Delta u_z$ [m]", "omega": r"$\omega$ [rad/s]", "mu0": r"$\mu_0$",
    "critical_velocity": r"$v_0^*$",
}
_OK_CODES = [code for code, status in STATUS_BY_CODE.items() if status.ok]


def _label(ds: xr.Dataset, name: str) -> str:
    if name in _TEX:
        return _TEX[name]
    attrs = ds[name].attrs
    units = attrs.get("units", "")
    return name + (f" [{units}]" if units and units != "1" else "")


def _geometric(values: np.ndarray) -> bool:
    v = np.asarray(values, dtype=float)
    if v.size < 3 or not np.all(np.isfinite(v)) or np.any(v <= 0):
        return False
    steps = np.diff(np.log(v))
    return bool(np.allclose(steps, steps[0], rtol=1e-6) and abs(steps[0]) > 0)


def _edges(values: np.ndarray, name: str) -> np.ndarray:
    """Cell edges of a map axis: midpoints, geometric ones for a geometric axis."""
    v = np.asarray(values, dtype=float)
    if not np.all(np.isfinite(v)):
        raise ValueError(f"cannot draw a map over {name}, which holds non-finite values; "
                         "plot curves instead")
    if v.size == 1:
        return np.array([v[0] - 0.5, v[0] + 0.5]) if v[0] <= 0 else v[0] * np.array([0.9, 1.1])
    geo = _geometric(v)
    w = np.log(v) if geo else v
    mid = (w[1:] + w[:-1]) / 2
    edges = np.concatenate([[w[0] - (mid[0] - w[0])], mid, [w[-1] + (w[-1] - mid[-1])]])
    return np.exp(edges) if geo else edges


def _select(ds: xr.Dataset, sel: dict[str, Any] | None) -> xr.Dataset:
    for dim, value in (sel or {}).items():
        if dim not in ds.dims:
            raise ValueError(f"--sel {dim}: not a dimension of the atlas "
                             f"(dimensions: {', '.join(map(str, ds.dims))})")
        if dim == "direction":
            if value not in ("up", "down"):
                raise ValueError(f"direction must be 'up' or 'down', got {value!r}")
            ds = ds.sel(direction=value)
        else:
            ds = ds.sel({dim: float(value)}, method="nearest")
    return ds


def plot_atlas(
    source: xr.Dataset | str | os.PathLike,
    *,
    x: str | None = None,
    y: str | None = None,
    var: str = "mu_ratio",
    sel: dict[str, Any] | None = None,
    out: str | os.PathLike | None = None,
    max_curves: int = 24,
):
    """Plot ``var`` of an atlas (a Dataset or a store path) and return the figure.

    * ``y=None``: curves along ``x`` (default: the velocity), one per value of the
      single other swept dimension (continuation: up solid, down dashed);
    * ``y`` given: a map over ``x`` and ``y``.

    Other swept dimensions must be fixed with ``sel={dim: value}`` (nearest value).
    Points whose status is not usable (not converged, failed, not computed) are
    left out (curves: marked with crosses).  Log axes for geometric coordinates.
    ``out``: write the figure there (PNG, PDF, SVG by extension).
    """
    from matplotlib.figure import Figure

    ds = open_atlas(source) if not isinstance(source, xr.Dataset) else source
    if var not in ds.data_vars:
        raise ValueError(f"unknown variable {var!r}; choose from {', '.join(ds.data_vars)}")
    ds = _select(ds, sel)
    da = ds[var]
    dims = [d for d in da.dims if ds.sizes[d] > 1 or d in (x, y)]
    da = da.squeeze([d for d in da.dims if d not in dims])
    velocity = ds.attrs.get("velocity")
    if x is None:
        x = velocity if velocity in dims else (dims[-1] if dims else None)
    if x is None or x not in da.dims:
        raise ValueError(f"x must be a swept dimension of {var} "
                         f"(swept: {', '.join(dims) or 'none'}), got {x!r}")
    if y is not None and (y not in da.dims or y == x):
        raise ValueError(f"y must be another swept dimension of {var} "
                         f"(swept: {', '.join(dims)}), got {y!r}")
    status = ds["status"].squeeze([d for d in ds["status"].dims if d not in dims])
    usable = status.isin(_OK_CODES)
    pending = int((status == STATUS_PENDING).sum())

    fixed = {k: float(v) for k, v in ds.coords.items()
             if v.ndim == 0 and k != "direction" and np.issubdtype(v.dtype, np.number)}
    title = ", ".join(f"{k}={v:.4g}" for k, v in fixed.items())
    if "direction" in ds.coords and ds["direction"].ndim == 0:
        title += f", {ds['direction'].item()}"

    fig = Figure(figsize=(7.0, 4.8), layout="constrained")
    ax = fig.add_subplot()
    if y is None:
        others = [d for d in da.dims if d not in (x, "direction")]
        if len(others) > 1:
            raise ValueError(f"curves along {x} need at most one other swept dimension; "
                             f"fix some of {', '.join(others)} with sel (--sel dim=value)")
        group = others[0] if others else None
        n = ds.sizes[group] if group else 1
        pick = np.unique(np.linspace(0, n - 1, min(n, max_curves)).round().astype(int))
        import matplotlib as mpl

        cmap = mpl.colormaps["viridis"]
        directions = list(ds["direction"].values) if "direction" in da.dims else [None]
        for k, i in enumerate(pick):
            curve = da.isel({group: i}) if group else da
            ok = usable.isel({group: i}) if group else usable
            color = cmap(k / max(1, len(pick) - 1)) if len(pick) > 1 else "C0"
            for d in directions:
                c = curve.sel(direction=d) if d is not None else curve
                o = ok.sel(direction=d) if d is not None else ok
                xs = c[x].values
                vals = c.values.astype(float)
                label = None
                if d in (None, "up"):
                    label = f"{group}={float(ds[group][i]):.4g}" if group else None
                ax.plot(xs, np.where(o.values, vals, np.nan), color=color,
                        ls="--" if d == "down" else "-", label=label)
                bad = ~o.values & np.isfinite(vals)
                if np.any(bad):
                    ax.plot(xs[bad], vals[bad], "x", color=color, ms=4)
        if group and len(pick) <= 8:
            ax.legend(fontsize="small")
        elif group:  # many curves: a colour bar over the group's values instead
            values = np.asarray(ds[group].values, dtype=float)[pick]
            lines = mpl.colors.ListedColormap([cmap(k / (len(pick) - 1))
                                               for k in range(len(pick))])
            norm = mpl.colors.BoundaryNorm(_edges(values, group), lines.N)
            bar = fig.colorbar(mpl.cm.ScalarMappable(norm=norm, cmap=lines), ax=ax,
                               label=_label(ds, group))
            if _geometric(values):
                bar.ax.set_yscale("log")
        if directions != [None]:
            title += " (solid: up, dashed: down)"
        ax.set_xlabel(_label(ds, x))
        ax.set_ylabel(_label(ds, var))
        if _geometric(ds[x].values):
            ax.set_xscale("log")
        ax.grid(True, alpha=0.3)
    else:
        others = [d for d in da.dims if d not in (x, y)]
        if others:
            raise ValueError(f"a map over {x} and {y} needs the other swept dimensions "
                             f"fixed: {', '.join(others)} (--sel dim=value)")
        z = da.where(usable).transpose(y, x)
        mesh = ax.pcolormesh(_edges(ds[x].values, x), _edges(ds[y].values, y), z.values,
                             shading="flat", cmap="viridis")
        fig.colorbar(mesh, ax=ax, label=_label(ds, var))
        ax.set_xlabel(_label(ds, x))
        ax.set_ylabel(_label(ds, y))
        if _geometric(ds[x].values):
            ax.set_xscale("log")
        if _geometric(ds[y].values):
            ax.set_yscale("log")
    if pending:
        title += f" [{pending} points not computed yet]"
    ax.set_title(title, fontsize="medium")
    if out is not None:
        fig.savefig(out, dpi=150)
    return fig
