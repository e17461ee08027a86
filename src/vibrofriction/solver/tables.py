"""Results and histories as tables: the one conversion to xarray and pandas, and short reprs.

:class:`~vibrofriction.FrictionResults` and the histories (:mod:`.history_types`) describe
their arrays as :class:`Column` s (name, dimensions, values, the schema's attributes); the
functions here turn those into an :class:`xarray.Dataset` (:func:`dataset`) or a
:class:`pandas.DataFrame` (:func:`dataframe`), with names, not codes, as categoricals. The
attributes come from :mod:`vibrofriction.schema` (:meth:`~vibrofriction.schema.Field.attrs`,
:meth:`~vibrofriction.schema.Parameter.attrs`), as a sweep's atlas's. xarray and pandas are
imported only when a table is asked for.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from ..params import Dimensionless
from ..schema import CHOICES, PARAMETER, PARAMETERS, parameter_names

if TYPE_CHECKING:
    import pandas as pd
    import xarray as xr

__all__ = ["Column", "dataframe", "dataset", "number", "system_coords", "system_text",
           "table_attrs", "vbar_of"]


@dataclass(frozen=True)
class Column:
    """One labelled array of a table.

    Parameters
    ----------
    name : str
        The variable's (or column's) name.
    dims : tuple of str
        The names of its dimensions (``()``: a scalar).
    values : numpy.ndarray
        Its values, of the shape the dimensions say.
    attrs : mapping of str to object
        Its CF-style attributes (``units``, ``long_name``, ...), from the schema.
    categories : tuple of str, optional
        The names a categorical (string) column may take, in order (empty: not categorical).
    coord : bool, optional
        Whether it labels the points (a coordinate), rather than being a result.
    """

    name: str
    dims: tuple[str, ...]
    values: np.ndarray
    attrs: Mapping[str, Any]
    categories: tuple[str, ...] = ()
    coord: bool = False


def number(x: float) -> str:
    """A float in a few significant digits (``"0.5"``, ``"1.2e-08"``, ``"inf"``)."""
    return f"{x:.4g}"


def system_text(system: Dimensionless) -> str:
    """The parameters of ``system`` that are required or not at their defaults, on one line.

    ``"alpha=0.5, beta=2, amplitude=0.5"``; the choices (``inplane_on``) where an in-plane
    amplitude makes them matter.
    """
    parts = []
    for name in parameter_names("dimensionless"):
        p, value = PARAMETER[name], getattr(system, name)
        if value is None or (p.default is not None and value == p.default):
            continue
        parts.append(f"{name}={number(value)}")
    if system.a_x > 0.0 or system.a_y > 0.0:
        parts += [f"{c}={getattr(system, c)}" for c in CHOICES]
    return ", ".join(parts)


def vbar_of(system: Dimensionless, v_inertial: np.ndarray) -> np.ndarray:
    """``vbar = v0/v0*`` of the inertial velocities, nan where ``v0*`` is zero or infinite."""
    try:
        return np.asarray(system.inertial_to_vbar(v_inertial), dtype=float)
    except ValueError:
        return np.full(np.shape(v_inertial), math.nan)


def table_attrs(title: str, system: Dimensionless) -> dict[str, Any]:
    """The attributes of a table: its title and ``inplane_on``."""
    return {"title": f"vibrofriction {title}", "inplane_on": system.inplane_on}


def system_coords(system: Dimensionless) -> list[Column]:
    """The parameters of ``system`` as scalar coordinates, with the schema's attributes."""
    return [Column(p.name, (), np.asarray(getattr(system, p.name), dtype=float), p.attrs(),
                   coord=True)
            for p in PARAMETERS if "dimensionless" in p.models
            and getattr(system, p.name) is not None]


def dataset(columns: Iterable[Column], attrs: Mapping[str, Any]) -> xr.Dataset:
    """The :class:`xarray.Dataset` of ``columns`` (coordinates and data variables).

    Categorical columns are stored as strings (their names); the dataset's ``attrs`` are
    ``attrs``.
    """
    import xarray as xr

    coords: dict[str, Any] = {}
    data: dict[str, Any] = {}
    for c in columns:
        values = c.values.astype(str) if c.categories else c.values
        (coords if c.coord else data)[c.name] = (c.dims, values, dict(c.attrs))
    return xr.Dataset(data, coords=coords, attrs=dict(attrs))


def dataframe(columns: Sequence[Column], index: Sequence[str],
              attrs: Mapping[str, Any]) -> pd.DataFrame:
    """A :class:`pandas.DataFrame` of the ``columns`` whose dimensions are ``index``.

    One row per element of those dimensions (in C order; a :class:`pandas.MultiIndex` over
    several), one column per column of ``columns`` with exactly those dimensions (the others,
    scalar coordinates or arrays over other dimensions, are left out); categorical columns
    as :class:`pandas.Categorical` of their names. ``DataFrame.attrs`` holds ``attrs`` and,
    under ``"units"``, each column's unit.
    """
    import pandas as pd

    index = tuple(index)
    kept = [c for c in columns if c.dims == index]
    shape = kept[0].values.shape if kept else (0,)
    if len(index) == 1:
        rows: pd.Index = pd.RangeIndex(shape[0], name=index[0])
    else:
        rows = pd.MultiIndex.from_product([range(n) for n in shape], names=index)
    table = {}
    for c in kept:
        flat = c.values.reshape(-1)
        table[c.name] = pd.Categorical(flat.astype(str), categories=c.categories) \
            if c.categories else flat
    out = pd.DataFrame(table, index=rows)
    out.attrs = {**attrs, "units": {c.name: c.attrs.get("units", "") for c in kept}}
    return out
