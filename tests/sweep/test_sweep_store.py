"""The resumable zarr store of sweeps: layout, resume, mismatches, damage, and a real
SIGKILL in the middle of a multi-process sweep."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import numpy as np
import pytest
import xarray as xr
import zarr

import vibrofriction.sweep as vsweep
from sweep_grid import GRID, assert_bitwise
from vibrofriction.solver import SolverSettings
from vibrofriction.sweep import compute_block, open_atlas, sweep


@pytest.fixture(scope="module")
def reference() -> xr.Dataset:
    return sweep(**GRID, workers=1, progress=False)


class Counter:
    """Wraps compute_block in the serial executor and counts the blocks it computes."""

    def __init__(self, monkeypatch, fail_after: int | None = None) -> None:
        self.blocks: list[int] = []
        self.fail_after = fail_after
        monkeypatch.setattr(vsweep._run, "compute_block", self)

    def __call__(self, plan, block):
        if self.fail_after is not None and len(self.blocks) >= self.fail_after:
            raise KeyboardInterrupt
        self.blocks.append(block)
        return compute_block(plan, block)


def test_store_layout_and_contents(tmp_path: Path, reference: xr.Dataset) -> None:
    path = tmp_path / "atlas.zarr"
    ds = sweep(**GRID, store=path, workers=1, chunk_size=20, progress=False)
    assert isinstance(ds.mu_ratio.data, object) and ds.attrs["blocks_done"] == 6
    assert_bitwise(reference, ds.load())
    # plain xarray reads it; the bookkeeping group stays out of the Dataset
    plain = xr.open_zarr(path, consolidated=False)
    assert "done" not in plain.variables and "_sweep" not in plain.variables
    assert plain.attrs["vibrofriction_version"] == vsweep.identity()[0]
    assert plain.mu_ratio.encoding["chunks"] == (1, 1, 13)  # one zarr chunk per block
    group = zarr.open_group(str(path), mode="r")
    assert np.all(group["_sweep"]["done"][:] == 1)
    assert not list(tmp_path.glob("*.partial*"))  # created atomically, nothing left over


def test_same_call_resumes_and_recomputes_nothing_when_complete(
        tmp_path: Path, monkeypatch) -> None:
    path = tmp_path / "atlas.zarr"
    sweep(**GRID, store=path, workers=1, chunk_size=20, progress=False)
    counter = Counter(monkeypatch)
    sweep(**GRID, store=path, workers=1, chunk_size=20, progress=False)
    assert counter.blocks == []


def test_interrupted_sweep_resumes_only_unfinished_blocks(
        tmp_path: Path, monkeypatch, reference: xr.Dataset) -> None:
    path = tmp_path / "atlas.zarr"
    Counter(monkeypatch, fail_after=2)  # Ctrl-C after two blocks
    with pytest.raises(KeyboardInterrupt):
        sweep(**GRID, store=path, workers=1, chunk_size=13, progress=False)
    partial = open_atlas(path)
    assert partial.attrs["blocks_done"] == 2 and partial.attrs["blocks_total"] == 6
    assert int((partial.status == -128).sum()) == 4 * 13  # not computed: fill values
    counter = Counter(monkeypatch)
    # another chunk_size in the resuming call: the store's own block shape is kept
    ds = sweep(**GRID, store=path, workers=1, chunk_size=1000, progress=False)
    assert sorted(counter.blocks) == [2, 3, 4, 5]
    assert_bitwise(reference, ds.load())


@pytest.mark.parametrize(("changes", "message"), [
    (dict(amplitude=0.6), r"params.amplitude: store has 0.5, this call 0.6"),
    (dict(alpha=[0.01, 0.1]), r"params.alpha: store has 3 values 0.01..0.3, this call 2 "
                              r"values 0.01..0.1"),
    (dict(vbar=np.linspace(0, 1.2, 14)), r"velocity.vbar"),
    (dict(settings=SolverSettings(max_periods=100)),
     r"settings.max_periods: store has each method's default, this call 100"),
    (dict(initial="rest"), r"initial: store has 'sliding', this call 'rest'"),
])
@pytest.mark.slow
def test_store_of_another_sweep_is_a_clear_error(tmp_path: Path, changes, message) -> None:
    path = tmp_path / "atlas.zarr"
    sweep(**GRID, store=path, workers=1, chunk_size=40, progress=False)
    with pytest.raises(ValueError, match=r"holds a different sweep \(" + message):
        sweep(**{**GRID, **changes}, store=path, workers=1, progress=False)


@pytest.mark.parametrize(("edit", "message"), [
    (lambda sig: sig["variables"].pop("trusted"),
     r"variables.trusted: store has absent, this call \['bool', False\]"),
    (lambda sig: sig["variables"].update(final_phase=["i1", -1]),
     r"variables.final_phase: store has \['i1', -1\], this call \['i1', -128\]"),
    (lambda sig: sig.pop("variables"), r"variables: the store was written with another set"),
])
def test_store_with_other_variables_is_an_error(tmp_path: Path, edit, message) -> None:
    """The variables (names, dtypes, fill values) are part of a store's signature."""
    path = tmp_path / "atlas.zarr"
    sweep(**GRID, store=path, workers=1, chunk_size=40, progress=False)
    meta = zarr.open_group(str(path), mode="r+")["_sweep"]
    signature = json.loads(meta.attrs["signature"])
    assert {"trusted", "multiplier", "settling_periods"} <= set(signature["variables"])
    edit(signature)
    meta.attrs["signature"] = json.dumps(signature, sort_keys=True)
    with pytest.raises(ValueError, match=r"holds a different sweep \(" + message):
        sweep(**GRID, store=path, workers=1, progress=False)


def test_store_of_another_version_or_solver_is_an_error(tmp_path: Path, monkeypatch) -> None:
    path = tmp_path / "atlas.zarr"
    sweep(**GRID, store=path, workers=1, chunk_size=40, progress=False)
    version, fingerprint = vsweep.identity()
    assert open_atlas(path).attrs["solver_fingerprint"] == fingerprint
    monkeypatch.setattr(vsweep, "identity", lambda: ("99.0", fingerprint))
    with pytest.raises(ValueError, match=r"version: store has '0\.1\.0', this call '99\.0'"):
        sweep(**GRID, store=path, workers=1, progress=False)
    # same version number, edited solver source: refused too
    monkeypatch.setattr(vsweep, "identity", lambda: (version, "0123456789abcdef"))
    with pytest.raises(ValueError, match=r"the solver's source code differs"):
        sweep(**GRID, store=path, workers=1, progress=False)


def test_a_store_that_cannot_be_made_is_refused_before_any_work(tmp_path: Path,
                                                               monkeypatch) -> None:
    """A new store is created while the first blocks are solved; a path under a file is
    refused before that."""
    blocks = Counter(monkeypatch)
    (tmp_path / "afile").write_text("not a folder")
    with pytest.raises(ValueError, match="is not a writable folder"):
        sweep(**GRID, store=tmp_path / "afile" / "atlas.zarr", workers=1, progress=False)
    assert blocks.blocks == []


def test_an_error_creating_the_store_is_raised(tmp_path: Path, monkeypatch) -> None:
    """The creation runs in the background: its error reaches the caller all the same,
    and no block is written."""
    def fail(path, plan):
        raise OSError("disk full")

    monkeypatch.setattr(vsweep._store, "_create", fail)
    with pytest.raises(OSError, match="disk full"):
        sweep(**GRID, store=tmp_path / "atlas.zarr", workers=1, progress=False)
    assert not (tmp_path / "atlas.zarr").exists()


def test_other_paths_are_refused_and_overwrite_replaces(tmp_path: Path,
                                                         reference: xr.Dataset) -> None:
    other = tmp_path / "photos"
    other.mkdir()
    (other / "cat.jpg").write_bytes(b"meow")
    with pytest.raises(ValueError, match="is not a vibrofriction sweep store"):
        sweep(**GRID, store=other, workers=1, progress=False)
    with pytest.raises(ValueError, match="is not a vibrofriction sweep store"):
        sweep(**GRID, store=other, workers=1, progress=False, overwrite=True)
    assert (other / "cat.jpg").exists()
    path = tmp_path / "atlas.zarr"
    sweep(**{**GRID, "amplitude": 0.6}, store=path, workers=1, progress=False)
    ds = sweep(**GRID, store=path, workers=1, progress=False, overwrite=True)
    assert_bitwise(reference, ds.load())


def _chunk_file(path: Path, var: str, block_index: tuple[int, ...]) -> Path:
    return path / var / "c" / Path(*map(str, block_index))


def test_damaged_blocks_are_found_and_recomputed(tmp_path: Path, monkeypatch,
                                                 reference: xr.Dataset) -> None:
    """What a power loss can leave: truncated or missing chunk files, stray temporaries."""
    path = tmp_path / "atlas.zarr"
    sweep(**GRID, store=path, workers=1, chunk_size=13, progress=False)  # blocks (3, 2, 1)
    truncated = _chunk_file(path, "mu_ratio", (0, 1, 0))
    truncated.write_bytes(truncated.read_bytes()[:10])
    _chunk_file(path, "final_f", (2, 0, 0)).unlink()
    zeroed = _chunk_file(path, "status", (1, 1, 0))
    zeroed.write_bytes(b"\0" * len(zeroed.read_bytes()))
    stray = path / "mu_ratio" / "c" / "0" / "0" / "0.1234abcd.partial"
    stray.write_bytes(b"half")
    counter = Counter(monkeypatch)
    ds = sweep(**GRID, store=path, workers=1, chunk_size=13, progress=False)
    assert sorted(counter.blocks) == [1, 3, 4]  # C order over the (3, 2, 1) block grid
    assert not stray.exists()
    assert_bitwise(reference, ds.load())


@pytest.mark.slow
def test_local_cores_into_store_equal_serial(tmp_path: Path, reference: xr.Dataset) -> None:
    ds = sweep(**GRID, store=tmp_path / "a.zarr", workers=2, chunk_size=7, progress=False)
    assert_bitwise(reference, ds.load())


# --------------------------------------------------------------------------- SIGKILL
KILL_GRID = dict(alpha=np.geomspace(0.01, 0.5, 8).tolist(), beta=[2.0, 5.0, 20.0],
                 amplitude=[0.5, 1.5], vbar=np.linspace(0.0, 1.2, 61).tolist())
KILL_CHUNK = 61

SCRIPT = """
import sys
from vibrofriction.sweep import sweep
if __name__ == "__main__":
    sweep(**{grid!r}, store=sys.argv[1], workers=2, chunk_size={chunk}, progress=False)
    print("finished")
"""


def _done_markers(path: Path) -> int:
    """The block markers written so far: not zarr's ``*.partial`` files, which a marker's
    write renames into place (counting one killed the sweep a marker early)."""
    try:
        names = os.listdir(path / "_sweep" / "done" / "c")
    except FileNotFoundError:
        return 0
    return sum(not name.endswith(".partial") for name in names)


@pytest.mark.slow
def test_sigkill_mid_sweep_then_resume_is_identical(tmp_path: Path, monkeypatch) -> None:
    """Kill -9 a two-process sweep (parent and workers) mid-run, resume, compare."""
    path = tmp_path / "atlas.zarr"
    script = tmp_path / "run.py"
    script.write_text(textwrap.dedent(SCRIPT.format(grid=KILL_GRID, chunk=KILL_CHUNK)))
    proc = subprocess.Popen([sys.executable, str(script), str(path)], start_new_session=True,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    n_blocks = 8 * 3 * 2
    try:
        deadline = time.monotonic() + 120
        while _done_markers(path) < 6 and time.monotonic() < deadline:
            assert proc.poll() is None, proc.communicate()
            time.sleep(0.002)
        os.killpg(proc.pid, signal.SIGKILL)  # the sweep and its worker processes
    finally:
        proc.wait(timeout=30)
        proc.stdout.close()  # a ResourceWarning (an error under filterwarnings) otherwise
        proc.stderr.close()
    assert proc.returncode == -signal.SIGKILL
    done_at_kill = open_atlas(path).attrs["blocks_done"]
    assert 6 <= done_at_kill < n_blocks, "the sweep was not interrupted mid-run"
    print(f"killed with {done_at_kill} of {n_blocks} blocks done")

    counter = Counter(monkeypatch)
    resumed = sweep(**KILL_GRID, store=path, workers=1, chunk_size=KILL_CHUNK,
                    progress=False).load()
    assert len(counter.blocks) == n_blocks - done_at_kill  # only the unfinished ones
    assert len(set(counter.blocks)) == len(counter.blocks)
    monkeypatch.undo()
    uninterrupted = sweep(**KILL_GRID, workers=1, chunk_size=KILL_CHUNK, progress=False)
    assert_bitwise(uninterrupted, resumed)
