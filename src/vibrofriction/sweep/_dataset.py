"""The labelled ``xarray.Dataset`` of a sweep: coordinates, variables, attributes."""

from __future__ import annotations

import dataclasses
import json

import numpy as np
import xarray as xr

from ..capabilities import CAPABILITIES
from ._grid import DIMENSIONLESS, Plan
from ._variables import COORD_ATTRS, point_variables, row_variables

__all__ = ["template"]

REFERENCE = ("X. Mao, V. L. Popov, J. Starcevic, M. Popov, Reduction of friction by normal "
             "oscillations. II. In-plane system dynamics, Friction 5 (2017) 194-206")


def _attrs(plan: Plan) -> dict:
    s = dataclasses.asdict(plan.settings)
    attrs = {
        "title": "vibrofriction parameter atlas: steady-state friction under normal "
                 "and in-plane oscillations",
        "references": REFERENCE,
        "source": f"vibrofriction {plan.version}",
        "vibrofriction_version": plan.version,
        "solver_fingerprint": plan.fingerprint,
        "sweep_kind": plan.kind,
        "velocity": plan.velocity.name,
        "swept": " ".join(plan.row_dims + ((plan.velocity.name,) if plan.velocity.swept
                                           else ())),
        "fixed": " ".join(sorted(plan.fixed)),
        "initial": plan.initial,
        "inplane_on": plan.inplane_on,
        "rs_law": plan.rs_law,
        "continuation": plan.continuation or "none",
        "solver_settings": json.dumps(s, sort_keys=True),
        # what each solver ran with: the settings resolved with its own defaults
        "solver_methods": json.dumps({name: plan.settings.resolved(c.settings)
                                      for name, c in CAPABILITIES.items()}, sort_keys=True),
    }
    # a setting left at None is each solver's own default (solver_methods)
    attrs.update({f"solver_{k}": "default" if v is None else v for k, v in s.items()})
    return attrs


def template(plan: Plan, values: dict[str, np.ndarray] | None) -> xr.Dataset:
    """The sweep's Dataset; ``values=None`` gives lazy fill-valued arrays (store creation)."""
    coords: dict = {}
    for a in (*plan.params, plan.velocity):
        attrs = dict(COORD_ATTRS[a.name])
        if a.swept:
            coords[a.name] = (a.name, np.array(a.values), attrs)
        else:
            coords[a.name] = ((), float(a.values), attrs)
    if plan.continuation:
        coords["direction"] = ("direction", np.array(plan.directions, dtype=object),
                               COORD_ATTRS["direction"])

    def data(var, shape, chunks):
        if values is not None:
            return values[var.name]
        import dask.array as da

        return da.full(shape, var.fill, dtype=var.dtype, chunks=chunks)

    nrow = len(plan.row_dims)
    data_vars = {}
    for var in point_variables(plan.velocity.name):
        data_vars[var.name] = (plan.dims, data(var, plan.shape, plan.chunks), var.attrs)
    for var in row_variables(plan.kind):
        item = (plan.row_dims, data(var, plan.row_shape, plan.chunks[:nrow]), var.attrs)
        if var.name in DIMENSIONLESS:  # a physical sweep's derived groups: coordinates
            coords[var.name] = item
        else:
            data_vars[var.name] = item
    return xr.Dataset(data_vars, coords=coords, attrs=_attrs(plan))
