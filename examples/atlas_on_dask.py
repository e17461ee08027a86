"""An atlas on a Dask cluster
==========================

An atlas over (beta, vbar) on a Dask cluster, stored in zarr, plotted with the package.

A local cluster of two worker processes stands in for a real one: give
``Client("tcp://scheduler:8786")`` instead to use machines (docs/sweeps.md).
The store is resumable: run the script again and only unfinished blocks are
computed.

Run:  python examples/atlas_on_dask.py [output directory]
"""

# %%
# The grid
# --------
# An atlas is a grid over any of the parameters: here 12 values of :math:`\beta` (the
# contact's stiffness) by 24 sliding speeds :math:`\bar v`, at :math:`\alpha = 0.5` and
# :math:`a = 0.5`.

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
from dask.distributed import Client, LocalCluster

import vibrofriction as vf
from vibrofriction.figures import plot_atlas

OUT = Path(sys.argv[1] if len(sys.argv) > 1 else "example_output")
OUT.mkdir(parents=True, exist_ok=True)

grid = dict(alpha=0.5, beta=np.geomspace(0.6, 20.0, 12), amplitude=0.5,
            vbar=np.linspace(0.05, 1.2, 24))

# %%
# The sweep on the cluster
# ------------------------
# :func:`vibrofriction.sweep` cuts the grid into blocks of 48 points, sends them to the
# workers and writes each finished block into the zarr store. The workers are new
# processes that import this script, so the cluster is started only where the script
# runs as the main program (``if __name__ == "__main__"``, Python's rule for
# multiprocessing).

if __name__ == "__main__":
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster, Client(cluster) as client:
        ds = vf.sweep(**grid, client=client, store=OUT / "atlas.zarr", overwrite=True,
                      progress=False, chunk_size=48)
        ds = ds.load()
    print(ds)

# %%
# The result is an :class:`xarray.Dataset`: ``mu_ratio`` with its ``error``, ``status``
# and ``trusted`` on the grid's coordinates.

if __name__ == "__main__":
    trusted = int(ds["trusted"].sum())
    print(f"{trusted} of {ds['trusted'].size} points trusted")

# %%
# Two views
# ---------
# A map of :math:`\mu/\mu_0` over :math:`(\bar v, \beta)`, and the same data as one curve
# per :math:`\beta`.

if __name__ == "__main__":
    plot_atlas(ds, x="vbar", y="beta", out=OUT / "atlas_map.png")
    plot_atlas(ds, x="vbar", out=OUT / "atlas_curves.png", max_curves=12)
    print("wrote atlas_map.png and atlas_curves.png")
