"""Where finished blocks go: memory, or a resumable zarr store.

Store layout (zarr v3, readable with ``xarray.open_zarr``)::

    atlas.zarr/
      zarr.json            group attributes: package version, solver settings, ...
      alpha/ beta/ ...     one coordinate per swept parameter (fixed ones are 0-d)
      mu_ratio/ status/ .. data variables; one zarr chunk per block of work
      _sweep/zarr.json     the grid's signature and block shape (for resuming)
      _sweep/done/         one uint8 marker per block, in its own zarr chunk

A block is written by one writer (the process that called :func:`sweep`): all
its data chunks first, then its ``done`` marker.  zarr's local store writes each
chunk to a temporary file and renames it into place, so a killed process leaves
either the old file or the new one; a block without its marker is recomputed on
resume.  Resuming also re-reads every finished block and recomputes any that no
longer decode or still hold fill values (a power loss can drop recent writes
that were never flushed to disk), so no finished block is lost or corrupted.
The store is created in a temporary directory and renamed into place, so a
killed creation leaves no half-made store behind.
"""

from __future__ import annotations

import asyncio
import json
import os
import shutil
import threading
import uuid
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr

from ._dataset import template
from ._grid import Plan
from ._variables import STATUS_PENDING, point_variables, row_variables

__all__ = ["MemorySink", "ZarrSink", "open_sink"]

_FORMAT = "vibrofriction-sweep/1"


class MemorySink:
    """All results in memory (``store=None``)."""

    def __init__(self, plan: Plan) -> None:
        self.plan = plan
        self.points = {v.name: v.empty(plan.shape) for v in point_variables(plan.velocity.name)}
        self.rows = {v.name: v.empty(plan.row_shape) for v in row_variables(plan.kind)}
        self.done = np.zeros(plan.n_blocks, dtype=bool)

    def write(self, block: int, values: dict[str, np.ndarray]) -> None:
        sl, rsl = self.plan.block_slices(block), self.plan.row_slices(block)
        for name, arr in self.points.items():
            arr[sl] = values[name]
        for name, arr in self.rows.items():
            arr[rsl] = values[name]
        self.done[block] = True

    def dataset(self) -> xr.Dataset:
        return template(self.plan, {**self.points, **self.rows})

    def close(self) -> None:
        pass


class ZarrSink:
    """A zarr store on the local file system, written block by block."""

    def __init__(self, path: Path, plan: Plan, done: np.ndarray) -> None:
        import zarr.api.asynchronous as za

        self.path = path
        self.plan = plan
        self.done = done
        self._loop = asyncio.new_event_loop()
        self._point_names = [v.name for v in point_variables(plan.velocity.name)]
        self._row_names = [v.name for v in row_variables(plan.kind)]

        async def _open():
            group: Any = await za.open_group(str(path), mode="r+", zarr_format=3)
            # every chunk file is written, even all-fill ones: a missing file is damage
            arrays = {name: (await group.getitem(name)).with_config({"write_empty_chunks": True})
                      for name in self._point_names + self._row_names}
            marker = await (await group.getitem("_sweep")).getitem("done")
            return arrays, marker

        self._arrays, self._marker = self._loop.run_until_complete(_open())

    # ---- writing
    def write(self, block: int, values: dict[str, np.ndarray]) -> None:
        """Write one block's data, then (only then) its ``done`` marker."""
        sl, rsl = self.plan.block_slices(block), self.plan.row_slices(block)

        async def _write():
            await asyncio.gather(
                *(self._arrays[n].setitem(sl, values[n]) for n in self._point_names),
                *(self._arrays[n].setitem(rsl, values[n]) for n in self._row_names))
            await self._marker.setitem(block, np.uint8(1))

        self._loop.run_until_complete(_write())
        self.done[block] = True

    # ---- checking on resume
    def verify(self) -> list[int]:
        """Re-read every block marked done; unmark those that do not decode or are unfilled.

        Returns the block numbers found bad.
        """
        bad: list[int] = []
        for b in np.flatnonzero(self.done):
            block = int(b)
            sl, rsl = self.plan.block_slices(block), self.plan.row_slices(block)

            async def _read(sl=sl, rsl=rsl):
                return await asyncio.gather(
                    *(self._arrays[n].getitem(sl) for n in self._point_names),
                    *(self._arrays[n].getitem(rsl) for n in self._row_names))

            try:
                values = dict(zip(self._point_names + self._row_names,
                                  self._loop.run_until_complete(_read()), strict=True))
            except Exception:  # noqa: BLE001 - any decoding failure means: recompute
                ok = False
            else:
                # every chunk file present and every status set (critical_velocity is
                # nan where it is not derived, so its values prove nothing)
                ok = (self._files_exist(block)
                      and bool(np.all(values["status"] != STATUS_PENDING)))
            if not ok:
                bad.append(block)
                self.done[block] = False
                self._loop.run_until_complete(self._marker.setitem(block, np.uint8(0)))
        return bad

    def _files_exist(self, block: int) -> bool:
        grid = self.plan.block_grid
        coords = tuple(int(i) for i in np.unravel_index(block, grid)) if grid else ()
        nrow = len(self.plan.row_dims)
        for name in self._point_names + self._row_names:
            arr = self._arrays[name]
            c = coords if name in self._point_names else coords[:nrow]
            if not (self.path / name / arr.metadata.encode_chunk_key(c)).is_file():
                return False
        return True

    def dataset(self) -> xr.Dataset:
        return open_atlas(self.path)

    def close(self) -> None:
        if not self._loop.is_closed():
            self._loop.close()


class NewZarrSink:
    """A store being created in a background thread: a :class:`ZarrSink` once it exists.

    Creating a store (its 30-odd arrays, through xarray) takes most of a second; the
    workers start and solve the first blocks meanwhile. Writing a block, reading the
    dataset or closing waits for it; an error of the creation is raised there.
    """

    def __init__(self, path: Path, plan: Plan) -> None:
        self.plan = plan
        self.done = np.zeros(plan.n_blocks, dtype=bool)
        self._sink: ZarrSink | None = None
        self._error: BaseException | None = None
        self._thread = threading.Thread(target=self._create, args=(path,), daemon=True,
                                        name="vibrofriction-store")
        self._thread.start()

    def _create(self, path: Path) -> None:
        try:
            _create(path, self.plan)
            self._sink = ZarrSink(path, self.plan, self.done)
        except BaseException as exc:  # noqa: BLE001 - raised in the caller's thread
            self._error = exc

    def _ready(self) -> ZarrSink:
        self._thread.join()
        if self._error is not None:
            raise self._error
        assert self._sink is not None
        return self._sink

    def write(self, block: int, values: dict[str, np.ndarray]) -> None:
        self._ready().write(block, values)

    def dataset(self) -> xr.Dataset:
        return self._ready().dataset()

    def close(self) -> None:
        self._thread.join()
        if self._sink is not None:
            self._sink.close()


def _check_writable(path: Path) -> None:
    """Before any work: the store can be made at ``path``.

    Its nearest existing folder must be a writable folder.
    """
    parent = path.absolute().parent
    while not parent.exists():
        parent = parent.parent
    if not parent.is_dir() or not os.access(parent, os.W_OK | os.X_OK):
        raise ValueError(f"cannot create the store {str(path)!r}: {str(parent)!r} is not a "
                         "writable folder")


# --------------------------------------------------------------------------- create / open
def _signature_json(plan: Plan) -> str:
    return json.dumps(plan.signature(), sort_keys=True)


def _differences(stored: dict[str, Any], wanted: dict[str, Any]) -> list[str]:
    out = []
    for key in sorted(set(stored) | set(wanted)):
        a, b = stored.get(key), wanted.get(key)
        if a == b:
            continue
        if isinstance(a, dict) and isinstance(b, dict):
            out += [f"{key}.{d}" for d in _differences(a, b)]
        else:
            out.append(key)
    return out


def _describe(key: str, stored: dict[str, Any], wanted: dict[str, Any]) -> str:
    def get(d, path):
        for p in path.split("."):
            d = d.get(p) if isinstance(d, dict) else None
        return d

    hexed = key.startswith(("params.", "velocity."))  # grid values are stored as hex

    def show(v):
        if v is None:
            return "each method's default" if key.startswith("settings.") else "absent"
        if hexed and isinstance(v, list):
            vals = [float.fromhex(x) for x in v]
            return f"{len(vals)} values {vals[0]:g}..{vals[-1]:g}" if vals else "[]"
        if hexed and isinstance(v, str):
            return f"{float.fromhex(v):g}"
        return repr(v)

    if key == "fingerprint":
        return ("fingerprint: the solver's source code differs from the one that wrote the "
                "store")
    if key == "variables":
        return "variables: the store was written with another set of variables (layout)"
    return f"{key}: store has {show(get(stored, key))}, this call {show(get(wanted, key))}"


def _create(path: Path, plan: Plan) -> None:
    import zarr
    from zarr.codecs import ZstdCodec

    tmp = path.with_name(f"{path.name}.partial-{uuid.uuid4().hex[:8]}")
    try:
        ds = template(plan, None)
        encoding: dict[str, dict[str, Any]] = {}
        for v in point_variables(plan.velocity.name):
            encoding[v.name] = {"chunks": plan.chunks, "fill_value": v.fill}
        nrow = len(plan.row_dims)
        for v in row_variables(plan.kind):
            encoding[v.name] = {"chunks": plan.chunks[:nrow], "fill_value": v.fill}
        for enc in encoding.values():  # a checksum: a damaged chunk fails to decode
            enc["compressors"] = (ZstdCodec(level=0, checksum=True),)
        ds.to_zarr(tmp, mode="w-", compute=False, encoding=encoding, zarr_format=3,
                   consolidated=False)
        group = zarr.open_group(str(tmp), mode="r+", zarr_format=3)
        meta = group.create_group("_sweep")
        meta.create_array("done", shape=(plan.n_blocks,), chunks=(1,), dtype="u1",
                          fill_value=0)
        meta.attrs.update({"format": _FORMAT, "signature": _signature_json(plan),
                           "chunks": list(plan.chunks)})
        os.rename(tmp, path)  # atomic: the store appears complete or not at all
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise


def _clean_partials(path: Path) -> None:
    """Temporary files of chunk writes interrupted by a kill (zarr's ``*.partial``)."""
    for p in path.rglob("*.partial"):
        try:
            p.unlink()
        except OSError:
            pass


def open_sink(store: str | os.PathLike, plan: Plan, *, overwrite: bool = False,
              verify: bool = True) -> tuple[ZarrSink | NewZarrSink, list[int]]:
    """Create the store for ``plan``, or open an existing one to resume it.

    A new store is created in the background (:class:`NewZarrSink`).  Returns the sink
    and the blocks found bad by :meth:`ZarrSink.verify`.  The existing store's block
    shape wins over ``plan``'s (chunking does not change results).  Raises ``ValueError``
    if the store was made for another grid, other solver settings, another initial state
    or package version, or if it cannot be created there.
    """
    import zarr

    if int(zarr.__version__.split(".")[0]) < 3:
        raise RuntimeError(f"sweep stores need zarr >= 3 (installed: {zarr.__version__})")
    path = Path(store)
    if path.exists() and overwrite:
        _check_is_sweep_store(path)
        shutil.rmtree(path)
    if not path.exists():
        _check_writable(path)
        return NewZarrSink(path, plan), []

    meta = _check_is_sweep_store(path)
    stored = json.loads(meta.attrs["signature"])
    wanted = plan.signature()
    diffs = _differences(stored, wanted)
    if diffs:
        detail = "; ".join(_describe(k, stored, wanted) for k in diffs[:4])
        raise ValueError(f"store {str(path)!r} holds a different sweep ({detail}): resume "
                         "it with the same grid and settings, or choose another store")
    plan = plan.with_chunks(tuple(meta.attrs["chunks"]))
    _clean_partials(path)
    marker = meta["done"]
    try:
        done = np.asarray(marker[:], dtype=bool)
    except Exception:  # noqa: BLE001 - a marker that does not decode: read one by one
        done = np.zeros(plan.n_blocks, dtype=bool)
        for b in range(plan.n_blocks):
            try:
                done[b] = bool(marker[b])
            except Exception:  # noqa: BLE001
                done[b] = False
    if done.shape != (plan.n_blocks,):
        raise ValueError(f"store {str(path)!r} is damaged: {done.shape[0]} block markers "
                         f"for {plan.n_blocks} blocks")
    sink = ZarrSink(path, plan, done)
    bad = sink.verify() if verify else []
    return sink, bad


def _check_is_sweep_store(path: Path):
    import zarr

    try:
        group = zarr.open_group(str(path), mode="r", zarr_format=3)
        meta = group["_sweep"]
        if meta.attrs.get("format") != _FORMAT:
            raise KeyError("format")
    except Exception:  # noqa: BLE001
        raise ValueError(f"{str(path)!r} exists and is not a vibrofriction sweep store; "
                         "choose another path") from None
    return meta


def open_atlas(store: str | os.PathLike) -> xr.Dataset:
    """Open a sweep store lazily (dask arrays) as an :class:`xarray.Dataset`.

    Parameters
    ----------
    store : str or os.PathLike
        The path of a zarr store written by :func:`sweep`.

    Returns
    -------
    xarray.Dataset
        The atlas. The attributes ``blocks_done`` and ``blocks_total`` say how complete
        it is; points not computed yet read as fill values (``nan``, ``status`` = -128).

    Raises
    ------
    ValueError
        If ``store`` is not a sweep store.

    Examples
    --------
    >>> import tempfile
    >>> from pathlib import Path
    >>> import vibrofriction as vf
    >>> from vibrofriction.sweep import open_atlas
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     store = Path(tmp) / "atlas.zarr"
    ...     _ = vf.sweep(alpha=0.1, beta=2.0, amplitude=0.5, vbar=[0.25, 0.5],
    ...                  workers=1, progress=False, store=store)
    ...     atlas = open_atlas(store)
    ...     print(atlas.attrs["blocks_done"], atlas.attrs["blocks_total"])
    ...     print(atlas.mu_ratio.values)
    1 1
    [0.57195311 0.58754462]
    """
    path = Path(store)
    meta = _check_is_sweep_store(path)
    ds = xr.open_zarr(path, consolidated=False, zarr_format=3)
    done = np.asarray(meta["done"][:], dtype=bool)
    ds.attrs["blocks_done"] = int(done.sum())
    ds.attrs["blocks_total"] = int(done.size)
    return ds
