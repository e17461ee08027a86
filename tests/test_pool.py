"""The package's one process pool (vibrofriction.sweep.pool): workers never outlive the
process that started them, even when it is killed with SIGKILL; a worker that dies is
an error, not a silent fallback."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from vibrofriction.sweep.pool import check_workers, run_tasks

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


def _alive(procs: list) -> list:
    alive = []
    for p in procs:
        try:
            if p.is_running() and p.status() != psutil.STATUS_ZOMBIE:
                alive.append(p)
        except psutil.NoSuchProcess:
            pass
    return alive


@pytest.mark.parametrize("args", [SWEEP, REPRODUCE], ids=["sweep", "reproduce"])
def test_sigkill_of_the_caller_leaves_no_process_behind(tmp_path: Path, args) -> None:
    """SIGKILL the command (only it, not its process group): its fork server, resource
    tracker and both workers must exit by themselves."""
    exe = Path(sys.executable).with_name("vibrofriction")
    proc = subprocess.Popen([str(exe), *args], cwd=tmp_path, start_new_session=True,
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
        print(f"{args[0]}: {len(tree)} descendants gone {time.monotonic() - t0:.2f} s "
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
