"""Sweeps on a real Dask cluster (LocalCluster, worker processes, loopback): the same
results as a local run, bitwise, and no lost or duplicated block when a worker dies."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

import vibrofriction.sweep as vsweep
from sweep_grid import GRID, assert_bitwise
from vibrofriction.sweep import open_atlas, sweep

pytestmark = pytest.mark.slow  # a Dask cluster per module; the fast lane skips it

distributed = pytest.importorskip("distributed")


@pytest.fixture(scope="module")
def cluster():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  host="127.0.0.1", dashboard_address=None) as cluster:
        yield cluster


@pytest.fixture(scope="module")
def client(cluster):
    with distributed.Client(cluster) as client:
        client.wait_for_workers(2, timeout=60)
        yield client


@pytest.fixture(scope="module")
def reference() -> xr.Dataset:
    return sweep(**GRID, workers=1, progress=False)


@pytest.mark.parametrize("chunk_size", [5, 26])
def test_dask_equals_local_bitwise(client, reference: xr.Dataset, chunk_size: int) -> None:
    assert_bitwise(reference, sweep(**GRID, client=client, chunk_size=chunk_size,
                                    progress=False))


def test_dask_into_store_and_resume_a_local_start(client, tmp_path: Path, monkeypatch,
                                                  reference: xr.Dataset) -> None:
    path = tmp_path / "atlas.zarr"
    calls = []

    def interrupt(plan, block):
        if len(calls) == 2:
            raise KeyboardInterrupt
        calls.append(block)
        return vsweep._compute.compute_block(plan, block)

    monkeypatch.setattr(vsweep._run, "compute_block", interrupt)
    with pytest.raises(KeyboardInterrupt):  # a local run, interrupted after two blocks
        sweep(**GRID, store=path, workers=1, chunk_size=13, progress=False)
    monkeypatch.undo()
    assert open_atlas(path).attrs["blocks_done"] == 2
    ds = sweep(**GRID, store=path, client=client, progress=False)  # finished on Dask
    assert ds.attrs["blocks_done"] == ds.attrs["blocks_total"] == 6
    assert_bitwise(reference, ds.load())


def test_dask_continuation_equals_local(client) -> None:
    kw = dict(alpha=[0.01, 0.3], beta=2.0, amplitude=0.5, vbar=np.linspace(0.05, 1.2, 6),
              continuation=True, progress=False)
    assert_bitwise(sweep(**kw, workers=1), sweep(**kw, client=client, chunk_size=1))


def test_workers_of_another_version_are_refused(client, monkeypatch) -> None:
    version, fingerprint = vsweep.identity()
    monkeypatch.setattr(vsweep, "identity", lambda: (version, "0123456789abcdef"))
    with pytest.raises(ValueError, match=r"the Dask workers run vibrofriction .*"
                                         + fingerprint + r".*install the same version"):
        sweep(**GRID, client=client, progress=False)


def test_client_and_workers_together_is_an_error(client) -> None:
    with pytest.raises(ValueError, match="either client"):
        sweep(**GRID, client=client, workers=2, progress=False)


KILL_GRID = dict(alpha=np.geomspace(0.01, 0.5, 8), beta=[2.0, 5.0, 20.0],
                 amplitude=[0.5, 1.5], vbar=np.linspace(0.0, 1.2, 61))


def test_worker_killed_mid_sweep_loses_and_duplicates_nothing(client, monkeypatch) -> None:
    reference = sweep(**KILL_GRID, workers=1, chunk_size=61, progress=False)
    pids = client.run(os.getpid)  # worker address -> pid
    written: list[int] = []
    killed: list[int] = []
    original = vsweep._store.MemorySink.write

    def write(self, block, values):
        original(self, block, values)
        written.append(block)
        if len(written) >= 3 and not killed:  # mid-sweep: kill a busy worker, hard
            busy = {w: keys for w, keys in client.processing().items() if keys}
            if busy:  # (between two submissions no worker may hold a task: try again)
                victim = sorted(busy)[0]
                os.kill(pids[victim], signal.SIGKILL)
                killed.append(len(busy[victim]))

    monkeypatch.setattr(vsweep._store.MemorySink, "write", write)
    ds = sweep(**KILL_GRID, client=client, chunk_size=61, progress=False)
    assert killed and killed[0] >= 1, "no busy worker was killed"  # its tasks were lost
    n_blocks = 8 * 3 * 2
    assert sorted(written) == list(range(n_blocks))  # each block exactly once
    assert_bitwise(reference, ds)
    # the nanny brought the worker back
    client.wait_for_workers(2, timeout=60)
    assert len(client.scheduler_info()["workers"]) == 2


def test_cli_scheduler(cluster, tmp_path: Path, reference: xr.Dataset) -> None:
    exe = Path(sys.executable).with_name("vibrofriction")
    r = subprocess.run([str(exe), "sweep", "--alpha", "0.01,0.1,0.3", "--beta", "2,5",
                        "--amplitude", "0.5", "--vbar", "0:1.2:13", "--out", "atlas.zarr",
                        "--scheduler", cluster.scheduler_address, "--chunk-size", "13",
                        "--no-progress"],
                       capture_output=True, text=True, cwd=tmp_path, timeout=300)
    assert r.returncode == 0, r.stderr
    assert_bitwise(reference, open_atlas(tmp_path / "atlas.zarr").load())

