"""The package's one process pool (vibrofriction.parallel): workers never outlive the
process that started them, even when it is killed with SIGKILL, by any of its entries (a
sweep and a reproduction through run_tasks, a fit's map, the explorer's long-lived pool);
a worker that dies is an error, not a silent fallback."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from vibrofriction.parallel import check_workers, mapper, run_tasks, start_pool

psutil = pytest.importorskip("psutil")  # installed with distributed

pytestmark = [pytest.mark.skipif(sys.platform != "linux", reason="SIGKILL and /proc: Linux"),
              pytest.mark.slow]  # real processes killed and waited for

#: about 40 s of work on one core (20 496 points); blocks of 2000 points take seconds
#: each, so the kill lands while both workers are inside a compiled kernel (GIL held)
SWEEP = ["sweep", "--alpha", "1e-2:0.5:56:log", "--beta", "2,5,20", "--amplitude", "0.5,1.5",
         "--vbar", "0:1.2:61", "--out", "atlas.zarr", "--workers", "2", "--chunk-size", "2000",
         "--no-progress"]
REPRODUCE = ["reproduce", "--out", "out", "--quick", "--workers", "2", "--no-progress"]
GONE_WITHIN = 10.0  # seconds
#: a map (the fit's) and a long-lived pool (the explorer's) on two workers, each busy in a
#: C loop that holds the GIL and never returns in time (as a compiled kernel would)
SCRIPT = """\
import sys
from vibrofriction.parallel import mapper, start_pool

if __name__ == "__main__":
    if sys.argv[1] == "map":
        with mapper(2) as map_:
            map_(sum, [range(10**13)] * 2)
    else:
        pool = start_pool(2)
        futures = [pool.submit(sum, range(10**13)) for _ in range(2)]
        futures[0].result()
"""


def _alive(procs: list) -> list:
    alive = []
    for p in procs:
        try:
            if p.is_running() and p.status() != psutil.STATUS_ZOMBIE:
                alive.append(p)
        except psutil.NoSuchProcess:
            pass
    return alive


@pytest.mark.parametrize("entry", ["sweep", "reproduce", "map", "start_pool"])
def test_sigkill_of_the_caller_leaves_no_process_behind(tmp_path: Path, entry) -> None:
    """SIGKILL the command (only it, not its process group): its fork server, resource
    tracker and both workers must exit by themselves."""
    if entry in ("sweep", "reproduce"):
        exe = Path(sys.executable).with_name("vibrofriction")
        command = [str(exe), *(SWEEP if entry == "sweep" else REPRODUCE)]
    else:
        (tmp_path / "busy.py").write_text(SCRIPT)
        command = [sys.executable, "busy.py", entry]
    proc = subprocess.Popen(command, cwd=tmp_path, start_new_session=True,
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                            env={**os.environ, "PYTHONWARNINGS": "ignore"})
    caller = psutil.Process(proc.pid)
    tree: list = []
    try:
        deadline = time.monotonic() + 120
        while time.monotonic() < deadline:
            assert proc.poll() is None, proc.communicate()
            tree = caller.children(recursive=True)
            workers = [p for p in tree if p.ppid() != proc.pid]  # children of the fork server
            if len(workers) >= 2:
                break
            time.sleep(0.05)
        assert len(workers) >= 2, [p.cmdline() for p in tree]
        time.sleep(1.5)  # both workers busy
        tree = caller.children(recursive=True)
        assert len(tree) >= 4  # resource tracker, fork server, two workers
        assert proc.poll() is None, "finished before it could be killed: use a larger grid"
        os.kill(proc.pid, signal.SIGKILL)
        proc.wait(timeout=10)
        t0 = time.monotonic()
        while _alive(tree) and time.monotonic() - t0 < GONE_WITHIN:
            time.sleep(0.02)
        left = _alive(tree)
        print(f"{entry}: {len(tree)} descendants gone {time.monotonic() - t0:.2f} s "
              "after SIGKILL")
        assert not left, [(p.pid, p.cmdline()) for p in left]
    finally:
        for p in _alive(tree):  # never leave anything behind on the machine
            p.kill()
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
        proc.stderr.close()


# --------------------------------------------------------------------------- errors
def _exit_worker(code: int) -> None:
    os._exit(code)


def _double(x: int) -> int:
    return 2 * x


def _pid(_: object) -> int:
    return os.getpid()


def _refuse(x: int) -> int:
    if x == 3:
        raise ValueError("three")
    return x


def test_a_dying_worker_is_an_error_not_a_fallback() -> None:
    queue = iter([(_exit_worker, (3,), lambda _: None)])
    with pytest.raises(RuntimeError, match="a local worker process died"):
        run_tasks(lambda: next(queue, None), workers=2)


def test_results_come_back_in_this_process_and_next_task_sees_them() -> None:
    got: list[int] = []
    todo = iter(range(7))

    def next_task():
        x = next(todo, None)
        return None if x is None else (_double, (x,), got.append)

    run_tasks(next_task, workers=2, in_flight=3)
    assert sorted(got) == [2 * x for x in range(7)]


@pytest.mark.parametrize("workers", [0, -1, 1.5, True, "2"])
def test_workers_must_be_an_integer_at_least_one(workers) -> None:
    with pytest.raises(ValueError, match=r"--workers must be an integer >= 1 .*got"):
        check_workers(workers, "--workers")


@pytest.mark.parametrize("workers", [1, 2])
def test_a_map_keeps_the_order_of_its_items(workers) -> None:
    with mapper(workers) as map_:
        assert map_(_double, range(7)) == [2 * x for x in range(7)]
        assert map_(_double, iter([])) == []
        pids = set(map_(_pid, range(6)))
    # two workers: the items ran in other processes (no silent fallback to this one)
    assert (pids == {os.getpid()}) if workers == 1 else (os.getpid() not in pids)


def test_a_map_raises_a_task_s_error_and_a_dead_worker() -> None:
    with mapper(2) as map_:
        with pytest.raises(ValueError, match="three"):
            map_(_refuse, range(6))
        with pytest.raises(RuntimeError, match="a local worker process died"):
            map_(_exit_worker, [3, 3])


def _slowly(items):
    """The items, the next one a second after the first was taken."""
    for i, item in enumerate(items):
        if i:
            time.sleep(1.0)
        yield item


def test_a_worker_dying_while_items_are_still_submitted_raises_the_same() -> None:
    """The pool is broken before the second item is submitted (submit itself raises)."""
    with mapper(2) as map_:
        with pytest.raises(RuntimeError, match="a local worker process died"):
            map_(_exit_worker, _slowly([3, 3]))


def test_a_map_drives_differential_evolution_as_its_workers() -> None:
    """The fit's global stage: scipy calls ``workers(func, population)``; the answer is
    the one of the serial run (same seed, deferred updating), found in the workers."""
    from scipy.optimize import differential_evolution, rosen

    kw = dict(bounds=[(-2.0, 2.0)] * 3, seed=1, maxiter=15, polish=False,
              updating="deferred")
    serial = differential_evolution(rosen, workers=lambda f, x: list(map(f, x)), **kw)
    with mapper(2) as map_:
        pooled = differential_evolution(rosen, workers=map_, **kw)
    assert pooled.nfev == serial.nfev and pooled.fun == serial.fun
    assert pooled.x.tolist() == serial.x.tolist()


def test_a_long_lived_pool_runs_elsewhere_and_stops_on_shutdown() -> None:
    pool = start_pool(2)
    try:
        pids = {pool.submit(_pid, k).result() for k in range(4)}
        assert os.getpid() not in pids
        procs = [psutil.Process(pid) for pid in pids]
    finally:
        pool.shutdown(wait=True)
    psutil.wait_procs(procs, timeout=GONE_WITHIN)
    assert not _alive(procs)
