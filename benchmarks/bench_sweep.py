"""Sweep benchmarks: throughput on 1 and 2 local cores and on a 2-worker Dask
LocalCluster, Dask overhead for 1000-point blocks, peak memory of a 10^6-point sweep
into a store.  Results are written (markdown) to benchmarks/results/sweep.md.

    .venv/bin/python benchmarks/bench_sweep.py throughput   # ~2 min
    .venv/bin/python benchmarks/bench_sweep.py memory       # ~1 min: 10^6 points
    .venv/bin/python benchmarks/bench_sweep.py memory --continuation up  # or both
    .venv/bin/python benchmarks/bench_sweep.py atlas --store /tmp/atlas.zarr  # 10^5 points
    .venv/bin/python benchmarks/bench_sweep.py all

The numbers are printed as markdown table rows; paste them into the results file.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import platform
import shutil
import signal
import subprocess
import sys
import tempfile
import textwrap
import time
from pathlib import Path

import numpy as np

from vibrofriction.parallel import process_pool
from vibrofriction.sweep import identity, make_plan, sweep, warm_up

#: the throughput grid: 20 000 points in 20 blocks of exactly 1000 points
GRID = dict(alpha=np.geomspace(0.01, 0.5, 20), beta=[2.0, 5.0, 20.0, 50.0, 200.0],
            amplitude=[0.5, 1.5], vbar=np.linspace(0.0, 1.2, 100))
CHUNK = 1000


def _busy_seconds() -> float:
    """CPU seconds the whole machine has been busy (all processes, /proc/stat)."""
    with open("/proc/stat") as f:
        user, nice, system, idle, iowait, irq, softirq, steal = map(int, f.readline().split()[1:9])
    return (user + nice + system + irq + softirq + steal) / os.sysconf("SC_CLK_TCK")


class CpuMeter:
    """CPU seconds of a process tree while it runs, and the load of everything else.

    A thread samples the tree (the root and all its descendants) every 0.1 s and keeps
    each process's latest user + system time, so processes that are not waited for
    (a forkserver, its workers) are counted too; only the last 0.1 s of a process that
    ends is missed.  ``foreign`` is the machine's busy time (/proc/stat) minus that,
    in cores: other users of the machine during the measurement.
    """

    def __init__(self, root: int | None = None) -> None:
        import psutil

        self._psutil = psutil
        self.root = root or os.getpid()
        self._first: dict[int, float] = {}
        self._last: dict[int, float] = {}
        self._stop = False

    def _sample(self, first: bool = False) -> None:
        psutil = self._psutil
        try:
            root = psutil.Process(self.root)
            procs = [root, *root.children(recursive=True)]
        except psutil.NoSuchProcess:
            return
        for p in procs:
            try:
                t = p.cpu_times()
            except psutil.NoSuchProcess:
                continue
            self._last[p.pid] = t.user + t.system
            if first:
                self._first[p.pid] = t.user + t.system

    def _run(self) -> None:
        while not self._stop:
            self._sample()
            time.sleep(0.1)

    def __enter__(self) -> CpuMeter:
        import threading

        self._busy = _busy_seconds()
        self._t = time.perf_counter()
        self._sample(first=True)
        self._thread = threading.Thread(target=self._run, daemon=True)
        self._thread.start()
        return self

    def __exit__(self, *exc) -> None:
        self._stop = True
        self._thread.join()
        self._sample()
        self.wall = time.perf_counter() - self._t
        self.own = sum(v - self._first.get(pid, 0.0) for pid, v in self._last.items())
        self.foreign = max(0.0, (_busy_seconds() - self._busy) - self.own) / self.wall


def _wait_idle(limit: float = 0.15, window: float = 3.0, patience: float = 1800.0) -> float:
    """Wait until other processes use less than `limit` cores; returns their load."""
    deadline = time.monotonic() + patience
    while True:
        with CpuMeter() as meter:
            time.sleep(window)
        if meter.foreign < limit or time.monotonic() > deadline:
            return meter.foreign


def _best(fn, repeat: int) -> tuple[float, float, float]:
    """Best of `repeat` runs, each started on an idle machine if one comes within the
    patience: (wall seconds, load of other processes in cores, CPU seconds used by this
    process tree).  The CPU seconds measure our own overhead even on a busy machine."""
    best = (math.inf, math.nan, math.nan)
    for _ in range(repeat):
        _wait_idle()
        with CpuMeter() as m:
            fn()
        best = min(best, (m.wall, m.foreign, m.own))
    return best


def _pool_startup(workers: int) -> float:
    """Wall time to start `workers` local processes and load the kernels in each."""
    t = time.perf_counter()
    with process_pool(workers, warm_up) as pool:
        list(pool.map(abs, range(workers)))
    return time.perf_counter() - t


RAW_SCRIPT = """
import sys, time
sys.path.insert(0, {bench!r})
from bench_sweep import GRID, CHUNK
from vibrofriction.sweep import compute_block, make_plan, warm_up
plan = make_plan(**GRID, chunk_size=CHUNK)
warm_up()
print("ready", flush=True)
sys.stdin.readline()
for block in range({start}, plan.n_blocks, {step}):
    compute_block(plan, block)
"""


def _raw(n_proc: int) -> float:
    """The machine's own ceiling: `n_proc` bare processes share the blocks (every
    n-th), started together once warm; no pool, no writes, no scheduler."""
    procs = [subprocess.Popen([sys.executable, "-c", RAW_SCRIPT.format(
        bench=str(Path(__file__).parent), start=i, step=n_proc)], stdin=subprocess.PIPE,
        stdout=subprocess.PIPE, text=True) for i in range(n_proc)]
    for p in procs:
        assert p.stdout.readline().strip() == "ready"
    t = time.perf_counter()
    for p in procs:
        p.stdin.write("go\n")
        p.stdin.flush()
    for p in procs:
        p.wait()
    return time.perf_counter() - t


def throughput(repeat: int) -> list[str]:
    """Rounds of (1 core, 2 bare processes, 2 local processes, 2 Dask workers), each run
    started on an idle machine; speed-ups are taken within a round (the machine's speed
    drifts by 10-30 % over minutes), then the median over rounds is reported."""
    from distributed import Client, LocalCluster

    plan = make_plan(**GRID, chunk_size=CHUNK)
    n = plan.size
    warm_up()
    names = ["1 core (in process)",
             "2 bare processes, no sweep machinery, start-up excluded (the ceiling)",
             "2 local processes", "Dask LocalCluster, 2 workers x 1 thread"]
    wall = {k: [] for k in names}
    cpu = {k: [] for k in names}
    other = {k: [] for k in names}
    startup = []
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                      dashboard_address=None) as cluster, Client(cluster) as client:
        client.wait_for_workers(2)
        sweep(alpha=0.1, beta=2.0, amplitude=0.5, vbar=[0.5], client=client, progress=False)
        runs = dict(zip(names, [
            lambda: sweep(**GRID, workers=1, chunk_size=CHUNK, progress=False),
            lambda: _raw(2),
            lambda: sweep(**GRID, workers=2, chunk_size=CHUNK, progress=False),
            lambda: sweep(**GRID, client=client, chunk_size=CHUNK, progress=False),
        ], strict=True))
        for _ in range(repeat):
            for name, fn in runs.items():
                _wait_idle()
                with CpuMeter() as m:
                    inner = fn()  # _raw returns its own wall time, start-up excluded
                wall[name].append(inner if isinstance(inner, float) else m.wall)
                cpu[name].append(m.own)
                other[name].append(m.foreign)
            _wait_idle()
            startup.append(_pool_startup(2))

    def med(x) -> float:
        return float(np.median(x))

    serial = np.array(wall[names[0]])
    speed = {k: med(serial / np.array(v)) for k, v in wall.items()}
    rows = [f"grid {dict(zip(plan.dims, plan.shape, strict=True))}: {n} points, "
            f"{plan.n_blocks} blocks of {int(np.prod(plan.chunks))} points; medians of "
            f"{repeat} interleaved rounds",
            "",
            "| executor | wall (s) | points/s | speed-up vs 1 core | CPU (s) | other load "
            "(cores) |",
            "|---|---:|---:|---:|---:|---:|"]
    for k in names:
        rows.append(f"| {k} | {med(wall[k]):.2f} | {n / med(wall[k]):,.0f} | "
                    f"{speed[k]:.2f} | {med(cpu[k]):.1f} | {max(other[k]):.2f} |")
    local = np.array(wall[names[2]]) - np.array(startup)
    rows.append(f"| 2 local processes, start-up ({med(startup):.1f} s) excluded | "
                f"{med(local):.2f} | {n / med(local):,.0f} | {med(serial / local):.2f} | | |")
    dask = np.array(wall[names[3]])
    rows += [
        "",
        f"Dask overhead, 1000-point blocks (median over rounds): wall "
        f"{100 * (med(dask / local) - 1):+.1f} % vs 2 local processes with start-up "
        f"excluded, {100 * (med(dask / np.array(wall[names[1]])) - 1):+.1f} % vs 2 bare "
        f"processes; CPU {100 * (med(cpu[names[3]]) / med(cpu[names[0]]) - 1):+.1f} % vs "
        f"1 core (local processes, start-up included: "
        f"{100 * (med(cpu[names[2]]) / med(cpu[names[0]]) - 1):+.1f} %).",
        "",
        "all walls (s): " + "; ".join(f"{k}: {', '.join(f'{x:.2f}' for x in v)}"
                                      for k, v in wall.items()),
    ]
    return rows


MEMORY_SCRIPT = """
import sys
import numpy as np
from vibrofriction.sweep import sweep
if __name__ == "__main__":
    # the package's default block size (auto_chunk_size)
    sweep(alpha=np.geomspace(0.01, 0.5, 100), beta=np.geomspace(2.0, 200.0, 100),
          amplitude=0.5, vbar=np.linspace(0.0, 1.2, 100), store=sys.argv[1], progress=False,
          continuation=sys.argv[2] or False)
"""


def _tree_memory(pid: int) -> tuple[float, float, float]:
    """(RSS of the process, RSS summed over it and its descendants, PSS summed), bytes.

    PSS shares each page among the processes mapping it, so the sum is what the tree
    really occupies; the RSS sum counts shared pages (libraries, copy-on-write) again
    for every process."""
    import psutil

    try:
        root = psutil.Process(pid)
        procs = [root, *root.children(recursive=True)]
    except psutil.NoSuchProcess:
        return 0.0, 0.0, 0.0
    own = rss = pss = 0.0
    for p in procs:
        try:
            info = p.memory_full_info()
        except psutil.NoSuchProcess:
            continue
        rss += info.rss
        pss += info.pss
        if p.pid == pid:
            own = info.rss
    return own, rss, pss


def memory(seconds: float | None, continuation: str = "") -> list[str]:
    """The 10^6-point sweep into a store (to the end, or killed after `seconds`),
    its resident memory sampled every second; ``continuation``: each velocity curve walked
    up (``"up"``, each point from its neighbour's final state) or up and down
    (``"both"``, 2 x 10^6 solves)."""
    tmp = Path(tempfile.mkdtemp(prefix="bench-sweep-"))
    store = tmp / "atlas.zarr"
    script = tmp / "run.py"
    script.write_text(textwrap.dedent(MEMORY_SCRIPT))
    marks = store / "_sweep" / "done" / "c"
    proc = subprocess.Popen([sys.executable, str(script), str(store), continuation],
                            start_new_session=True)
    samples = []
    t0 = time.perf_counter()
    try:
        while proc.poll() is None and (seconds is None or time.perf_counter() - t0 < seconds):
            own, rss, pss = _tree_memory(proc.pid)
            done = len(os.listdir(marks)) if marks.exists() else 0
            if own:
                samples.append((time.perf_counter() - t0, own, rss, pss, done))
            time.sleep(1.0)
    finally:
        finished = proc.poll() == 0
        os.killpg(proc.pid, signal.SIGKILL)
        proc.wait()
    wall = time.perf_counter() - t0
    done = len(os.listdir(marks)) if marks.exists() else 0
    size = sum(f.stat().st_size for f in store.rglob("*") if f.is_file())
    import zarr

    blocks = zarr.open_array(str(store / "_sweep" / "done"), mode="r").shape[0]
    solves = (2 if continuation == "both" else 1) * 10**6
    per_block = solves // blocks
    shutil.rmtree(tmp, ignore_errors=True)
    arr = np.array(samples)
    mib = 2.0**20

    def at(fraction: float) -> str:
        i = int(np.searchsorted(arr[:, 4], fraction * blocks))
        i = min(i, len(arr) - 1)
        return f"{arr[i, 2] / mib:.0f} / {arr[i, 3] / mib:.0f}"

    how = (f"ran to the end in {wall:.0f} s ({1e6 / wall:,.0f} points/s, start-up included)"
           if finished else f"killed after {wall:.0f} s with {done} of {blocks} blocks done")
    return [
        f"10^6-point grid (alpha 100 x beta 100 x vbar 100, the default blocks of {per_block} "
        f"points, 2 local processes, into a zarr store"
        + (f"; continuation {continuation!r}: {solves:.0e} solves, each velocity curve walked "
           f"from its first point" if continuation else "") + f"): {how}.",
        "",
        "| quantity | value |",
        "|---|---:|",
        f"| blocks done | {done} of {blocks} |",
        f"| peak RSS, sweep process | {arr[:, 1].max() / mib:.0f} MiB |",
        f"| peak RSS summed over sweep process + workers + helpers | "
        f"{arr[:, 2].max() / mib:.0f} MiB |",
        f"| peak PSS summed (shared pages counted once) | {arr[:, 3].max() / mib:.0f} MiB |",
        f"| tree RSS / PSS at 10 %, 50 %, 90 % of the blocks | {at(0.1)}, {at(0.5)}, "
        f"{at(0.9)} MiB |",
        f"| store size | {size / mib:.1f} MiB |",
    ]


ATLAS_ARGS = ["--alpha", "1e-2:0.5:41:log", "--beta", "2:400:20:log", "--amplitude", "0.5",
              "--vbar", "0:1.2:122"]  # 41 x 20 x 122 = 100 040 points


def atlas(store: str) -> list[str]:
    """The 10^5-point atlas through the command line, with its progress bar."""
    exe = Path(sys.executable).with_name("vibrofriction")
    cmd = [str(exe), "sweep", *ATLAS_ARGS, "--out", store]
    _wait_idle()
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    with CpuMeter(proc.pid) as m:
        stdout, stderr = proc.communicate()
    r = subprocess.CompletedProcess(cmd, proc.returncode, stdout, stderr)
    wall, own, foreign = m.wall, m.own, m.foreign
    if r.returncode not in (0, 3):  # 3: done, with points not trusted (counted below)
        raise RuntimeError(r.stderr)
    bar = [line for line in r.stderr.replace("\r", "\n").splitlines() if "pt/s" in line]
    return [
        "`" + " ".join(["vibrofriction", "sweep", *ATLAS_ARGS, "--out", "atlas.zarr"]) + "`",
        "",
        f"wall {wall:.0f} s, CPU {own:.0f} s, other processes' load {foreign:.2f} cores",
        "",
        "    " + r.stdout.strip(),
        "    progress bar, first and last updates:",
        *("    " + line.strip() for line in bar[1:3] + bar[-2:]),
    ]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("what", choices=["throughput", "memory", "atlas", "all"])
    parser.add_argument("--store", default="atlas.zarr", help="store of the atlas run")
    parser.add_argument("--repeat", type=int, default=2)
    parser.add_argument("--continuation", choices=["up", "both"], default="",
                        help="memory: the continuation sweep of the same grid")
    parser.add_argument("--seconds", type=float, default=None,
                        help="memory: kill the sweep after this long (default: run to the end)")
    args = parser.parse_args()
    header = {"python": platform.python_version(), "machine": platform.machine(),
              "cores": os.cpu_count(), "command": " ".join(sys.argv),
              "vibrofriction": identity()[0], "solver_fingerprint": identity()[1]}
    print(json.dumps(header), flush=True)
    if args.what in ("throughput", "all"):
        print("\n".join(throughput(args.repeat)), flush=True)
    if args.what in ("memory", "all"):
        print("\n".join(memory(args.seconds, args.continuation)), flush=True)
    if args.what in ("atlas", "all"):
        print("\n".join(atlas(args.store)))
    identity.cache_clear()
    if identity()[1] != header["solver_fingerprint"]:
        print("WARNING: the solver's source changed during the benchmark (kernels were "
              "recompiled): the numbers are not valid", flush=True)


if __name__ == "__main__":
    main()
