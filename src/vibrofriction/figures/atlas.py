"""Quick look at an atlas (:func:`vibrofriction.sweep.sweep`).

Curves along one dimension, or a map over two.

Drawn with xarray's own plotting (``DataArray.plot.line``, ``.plot.pcolormesh``) on
a figure of the shared style (:mod:`.style`, no pyplot), so it works headless.  This
module, and with it xarray and the sweep, is imported only when an atlas is plotted
(:func:`vibrofriction.figures.plot_atlas`).  Points that are not trusted (the
Dataset's ``trusted`` variable: a converged status and ``error <= tol_trusted``) are
never drawn as results: crosses on curves, hatched cells on maps; points not computed
yet are left blank.
"""

from __future__ import annotations

import os
from typing import Any

import numpy as np
import xarray as xr

from ..sweep import STATUS_PENDING, open_atlas
from . import style
from .edges import cell_edges, is_geometric

__all__ = ["plot_atlas"]

_TEX = {
    "alpha": style.ALPHA, "beta": style.BETA, "amplitude": style.AMPLITUDE,
    "vbar": style.VBAR, "v_inertial": style.V_INERTIAL, "v0": r"$v_0$ [m/s]",
    "mu_ratio": style.MU, "mass": r"$m$ [kg]", "k_x": r"$k_x$ [N/m]",
    "k_xc": r"$k_{x,c}$ [N/m]", "k_zc": r"$k_{z,c}$ [N/m]", "u_z0": r"$u_{z0}$ [m]",
    "du_z": r"$\Delta u_z$ [m]", "omega": r"$\omega$ [rad/s]", "mu0": r"$\mu_0$",
    "critical_velocity": r"$v_0^*$",
}
_LEGEND_MAX = 8  # more curves than this: a colour bar instead of a legend


@style.styled
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
    Untrusted points (``trusted`` is False) are marked, not drawn as results: crosses
    on curves, hatched cells on maps.  Log axes for geometric coordinates.
    ``out``: write the figure there (PNG, PDF, SVG by extension).
    """
    ds = _select(open_atlas(source) if not isinstance(source, xr.Dataset) else source, sel)
    da, trusted, pending = _variable(ds, var, keep=(x, y))
    x = _x_axis(ds, da, x, var)
    fig = style.figure(style.PAGE, 4.8)
    ax = fig.add_subplot()
    if y is None:
        note = _draw_curves(fig, ax, ds, da, trusted, x, max_curves)
    else:
        note = _draw_map(fig, ax, ds, da, trusted, pending, x, _y_axis(da, x, y, var))
    ax.set_xlabel(_label(ds, x))
    ax.set_ylabel(_label(ds, var if y is None else y))
    ax.set_title(_title(ds, int(pending.sum())) + note, fontsize="medium")
    if out is not None:
        fig.savefig(out, dpi=150)
    return fig


# --------------------------------------------------------------------------- choosing
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
            try:
                number = float(value)
            except (TypeError, ValueError):
                raise ValueError(f"--sel {dim}={value!r}: the value must be a number") from None
            ds = ds.sel({dim: number}, method="nearest")
    return ds


def _variable(ds: xr.Dataset, var: str, keep: tuple[str | None, ...]
              ) -> tuple[xr.DataArray, xr.DataArray, xr.DataArray]:
    """``var``, ``trusted`` and "not computed yet" over the swept dims (size > 1 or kept)."""
    if var not in ds.data_vars:
        names = ", ".join(map(str, ds.data_vars))
        raise ValueError(f"unknown variable {var!r}; choose from {names}")
    if "trusted" not in ds.data_vars:
        raise ValueError("the atlas has no 'trusted' variable: it was written by an older "
                         "version; recompute it")
    drop = [d for d in ds[var].dims if ds.sizes[d] == 1 and d not in keep]
    da = ds[var].squeeze(drop).load()
    pending = ds["status"] == STATUS_PENDING
    pending = pending.any([d for d in pending.dims if d not in da.dims]).squeeze(drop)
    if set(ds["trusted"].dims) == set(ds[var].dims):
        trusted = ds["trusted"].squeeze(drop)
    else:  # a row variable (v0*, eq. 12): a closed form, no solver result to trust
        trusted = xr.ones_like(da, dtype=bool)
    return da, trusted.transpose(*da.dims).load(), pending.transpose(*da.dims).load()


def _x_axis(ds: xr.Dataset, da: xr.DataArray, x: str | None, var: str) -> str:
    velocity = ds.attrs.get("velocity")
    if x is None:
        x = velocity if velocity in da.dims else (str(da.dims[-1]) if da.dims else None)
    if x is None or x not in da.dims:
        raise ValueError(f"x must be a swept dimension of {var} "
                         f"(swept: {', '.join(map(str, da.dims)) or 'none'}), got {x!r}")
    return str(x)


def _y_axis(da: xr.DataArray, x: str, y: str, var: str) -> str:
    if y not in da.dims or y == x:
        raise ValueError(f"y must be another swept dimension of {var} "
                         f"(swept: {', '.join(map(str, da.dims))}), got {y!r}")
    return y


def _label(ds: xr.Dataset, name: str) -> str:
    if name in _TEX:
        return _TEX[name]
    units = ds[name].attrs.get("units", "")
    return name + (f" [{units}]" if units and units != "1" else "")


def _title(ds: xr.Dataset, pending: int) -> str:
    fixed = {k: float(v) for k, v in ds.coords.items()
             if v.ndim == 0 and k != "direction" and np.issubdtype(v.dtype, np.number)}
    title = ", ".join(f"{k}={v:.4g}" for k, v in fixed.items())
    if "direction" in ds.coords and ds["direction"].ndim == 0:
        title += f", {ds['direction'].item()}"
    if pending:
        title += f" [{pending} points not computed yet]"
    return title


# --------------------------------------------------------------------------- drawing
def _draw_curves(fig, ax, ds: xr.Dataset, da: xr.DataArray, trusted: xr.DataArray, x: str,
                 max_curves: int) -> str:
    """Trusted values as lines, untrusted ones as crosses; returns a note for the title."""
    import matplotlib as mpl

    others = [d for d in da.dims if d not in (x, "direction")]
    if len(others) > 1:
        raise ValueError(f"curves along {x} need at most one other swept dimension; "
                         f"fix some of {', '.join(map(str, others))} with sel "
                         "(--sel dim=value)")
    group = str(others[0]) if others else None
    if group is not None:
        n = ds.sizes[group]
        pick = np.unique(np.linspace(0, n - 1, min(n, max_curves)).round().astype(int))
        da, trusted = da.isel({group: pick}), trusted.isel({group: pick})
    count = da.sizes[group] if group is not None else 1
    cmap = mpl.colormaps["viridis"]
    # one curve: the default colour as RGBA (a prop cycle refuses the reference "C0")
    colors = ([cmap(k / (count - 1)) for k in range(count)] if count > 1
              else [mpl.colors.to_rgba("C0")])
    directions = list(da["direction"].values) if "direction" in da.dims else [None]
    for d in directions:
        values = da.sel(direction=d) if d is not None else da
        ok = trusted.sel(direction=d) if d is not None else trusted
        ax.set_prop_cycle(color=colors)
        lines = values.where(ok).plot.line(x=x, hue=group, ax=ax, add_legend=False,
                                           linestyle="--" if d == "down" else "-")
        ax.set_prop_cycle(color=colors)
        values.where(~ok & np.isfinite(values)).plot.line(
            x=x, hue=group, ax=ax, add_legend=False, linestyle="none", marker="x",
            markersize=4)
        if group is not None and d in (None, "up"):
            for line, v in zip(lines, da[group].values, strict=True):
                line.set_label(f"{group}={float(v):.4g}")
    if group is not None:
        _curve_key(fig, ax, ds, da[group].values, group, colors)
    if is_geometric(ds[x].values):
        ax.set_xscale("log")
    ax.grid(True, alpha=0.3)
    note = " (solid: up, dashed: down)" if directions != [None] else ""
    return note + (" (x: not trusted)" if not bool(trusted.all()) else "")


def _curve_key(fig, ax, ds: xr.Dataset, values: np.ndarray, group: str,
               colors: list) -> None:
    """A legend for a few curves, a colour bar over the group's values for many."""
    import matplotlib as mpl

    if len(values) <= _LEGEND_MAX:
        ax.legend(fontsize="small")
        return
    values = np.asarray(values, dtype=float)
    lines = mpl.colors.ListedColormap(colors)
    norm = mpl.colors.BoundaryNorm(cell_edges(values, name=group), lines.N)
    bar = fig.colorbar(mpl.cm.ScalarMappable(norm=norm, cmap=lines), ax=ax,
                       label=_label(ds, group))
    if is_geometric(values):
        bar.ax.set_yscale("log")


def _draw_map(fig, ax, ds: xr.Dataset, da: xr.DataArray, trusted: xr.DataArray,
              pending: xr.DataArray, x: str, y: str) -> str:
    """Trusted values as coloured cells, untrusted ones hatched, pending ones blank."""
    from matplotlib.collections import PatchCollection
    from matplotlib.patches import Rectangle

    others = [d for d in da.dims if d not in (x, y)]
    if others:
        raise ValueError(f"a map over {x} and {y} needs the other swept dimensions "
                         f"fixed: {', '.join(map(str, others))} (--sel dim=value)")
    edges = {}
    for d in (x, y):
        v = np.asarray(ds[d].values, dtype=float)
        if v.size < 2 or not np.all(np.isfinite(v)):
            raise ValueError(f"cannot draw a map over {d}: it needs two or more finite "
                             "values; plot curves instead")
        edges[d] = cell_edges(v, name=d)
    scale: dict[str, Any] = {d: "log" if is_geometric(ds[d].values) else "linear"
                             for d in (x, y)}
    da.where(trusted).plot.pcolormesh(x=x, y=y, ax=ax, cmap="viridis", xscale=scale[x],
                                      yscale=scale[y],
                                      cbar_kwargs={"label": _label(ds, str(da.name))})
    bad = (~trusted & ~pending).transpose(y, x).values
    if not bad.any():
        return ""
    ex, ey = edges[x], edges[y]
    cells = [Rectangle((ex[j], ey[i]), ex[j + 1] - ex[j], ey[i + 1] - ey[i])
             for i, j in zip(*np.nonzero(bad), strict=True)]
    ax.add_collection(PatchCollection(cells, facecolor="none", edgecolor="0.35",
                                      hatch="xxx", linewidth=0.0))
    return " (hatched: not trusted)"
