"""An atlas on a Dask cluster
==========================

An atlas over (beta, vbar) on a Dask cluster, stored in zarr, plotted with the package.

A local cluster of two worker processes stands in for a real one: give
``Client("tcp://scheduler:8786")`` instead to use machines (docs/sweeps.md).
The store is resumable: run the script again and only unfinished blocks are
computed.

Run:  python examples/atlas_on_dask.py [output directory]
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
from dask.distributed import Client, LocalCluster

import vibrofriction as vf
from vibrofriction.figures import plot_atlas


def main(out_dir: str | Path = "example_output") -> dict[str, float]:
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    grid = dict(alpha=0.5, beta=np.geomspace(0.6, 20.0, 12), amplitude=0.5,
                vbar=np.linspace(0.05, 1.2, 24))
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster, Client(cluster) as client:
        ds = vf.sweep(**grid, client=client, store=out / "atlas.zarr", overwrite=True,
                      progress=False, chunk_size=48)
        ds = ds.load()
    print(ds)
    trusted = int(ds["trusted"].sum())
    print(f"{trusted} of {ds['trusted'].size} points trusted")
    plot_atlas(ds, x="vbar", y="beta", out=out / "atlas_map.png")
    plot_atlas(ds, x="vbar", out=out / "atlas_curves.png", max_curves=12)
    print(f"wrote {out / 'atlas_map.png'} and {out / 'atlas_curves.png'}")
    return {"mu_sum": float(ds["mu_ratio"].sum())}


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "example_output")
