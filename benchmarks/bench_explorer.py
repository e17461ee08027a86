"""Responsiveness and load of the explorer, measured in the distribution's headless Chromium.

* redraw: the time from a key press on the alpha slider to the redrawn curve's readout
  (median and spread over ``--moves`` moves);
* load: the server's resident memory (its process and its worker processes) over
  ``--updates`` updates (at the start, every 100, at the end);
* two tabs: the redraw time in one tab while another runs a fit (in its worker process).

Run:  python benchmarks/bench_explorer.py [--moves 30] [--updates 1000]
Writes benchmarks/results/explorer.md.

``--curves``: instead, the redraw of the curves of the slower solvers (a transverse
oscillation, the 2-D solver; a curved tip, the MDR solver), 40 points each, ``--moves`` moves
on the alpha slider each; appended to benchmarks/results/explorer.md.
"""

from __future__ import annotations

import argparse
import contextlib
import datetime
import math
import platform
import re
import shutil
import signal
import socket
import statistics
import subprocess
import sys
import tempfile
import time
import urllib.request
from pathlib import Path

import psutil
from playwright.sync_api import sync_playwright

READOUT = re.compile(r"mean (mu/mu0|COF = mu) = ")
HERE = Path(__file__).resolve().parent


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def start_server(port: int) -> subprocess.Popen:
    proc = subprocess.Popen([sys.executable, "-m", "vibrofriction.cli", "explore", "--port",
                             str(port), "--no-show"], start_new_session=True,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline:
        try:
            with urllib.request.urlopen(f"http://127.0.0.1:{port}/", timeout=5):
                return proc
        except OSError:
            time.sleep(0.3)
    proc.kill()
    raise RuntimeError("the explorer did not start")


@contextlib.contextmanager
def served():
    """``(server, url, browser)``: the explorer served on a free port, a headless Chromium;
    both stopped on the way out."""
    port = free_port()
    server = start_server(port)
    try:
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path=shutil.which("chromium"), headless=True)
            yield server, f"http://127.0.0.1:{port}/", browser
            browser.close()
    finally:
        server.send_signal(signal.SIGINT)
        try:
            server.wait(timeout=15)
        except subprocess.TimeoutExpired:
            server.kill()


def rss_mb(proc: subprocess.Popen) -> tuple[float, float]:
    """Resident memory of the server process and of its worker processes, MB."""
    p = psutil.Process(proc.pid)
    workers = sum(c.memory_info().rss for c in p.children(recursive=True))
    return p.memory_info().rss / 2**20, workers / 2**20


def open_page(browser, url: str):
    page = browser.new_page(viewport={"width": 1500, "height": 1100})
    page.set_default_timeout(120_000)
    page.goto(url)
    page.get_by_text(READOUT).wait_for()
    return page


def move(page, key: str) -> float:
    """Press ``key`` on alpha's slider; seconds until the curve's readout changed."""
    readout = page.get_by_text(READOUT)
    before = readout.inner_text()
    handle = page.locator(".noUi-handle").first
    handle.focus()
    t0 = time.perf_counter()
    handle.press(key)
    while readout.inner_text() == before:
        if time.perf_counter() - t0 > 60:
            raise RuntimeError(f"no redraw within 60 s after {key} (readout {before!r})")
        time.sleep(0.005)
    return time.perf_counter() - t0


def moves(page, n: int) -> list[float]:
    # five steps right, five back: alpha stays below 1 (alpha = 1 exactly, a
    # grid point of the slider, has no vbar axis: the page says so and keeps the view)
    return [move(page, "ArrowRight" if (i // 5) % 2 == 0 else "ArrowLeft") for i in range(n)]


def _ms(x: float) -> str:
    return "-" if math.isnan(x) else f"{x:.0f}"


def summary(times: list[float]) -> str:
    ms = sorted(1e3 * t for t in times)
    q = statistics.quantiles(ms, n=10) if len(ms) >= 10 else [ms[0]] * 9
    return (f"median {statistics.median(ms):.0f} ms, 10-90 % {q[0]:.0f}-{q[-1]:.0f} ms, "
            f"min {ms[0]:.0f} ms, max {ms[-1]:.0f} ms (n = {len(ms)})")


CSV = """v0 [mm/s],cof,du_z [um],omega [Hz],sigma
0.5,0.160,0.5,1000,0.005
1,0.175,0.5,1000,0.005
2,0.190,0.5,1000,0.005
5,0.215,0.5,1000,0.005
10,0.240,0.5,1000,0.005
20,0.265,0.5,1000,0.005
50,0.290,0.5,1000,0.005
100,0.300,0.5,1000,0.005
"""


#: the curves of the slower solvers (URL query of the page), 40 points each, and the flat
#: punch's (the 1-D solver) as the peer in the same run: the page's redraw without them
CURVES = {
    "flat punch (the peer), `vbar` in [0, 1.5]": "points=40",
    "transverse, `a_y = 0.5`, `V` in [0, 1.5]": "a_y=0.5&axis=V&points=40",
    "transverse, jumping: `a = 1.5`, `a_y = 0.5`": "a_y=0.5&amplitude=1.5&axis=V&points=40",
    "transverse and longitudinal, `a_x = 0.3`, `a_y = 0.5`":
        "a_x=0.3&a_y=0.5&axis=V&points=40",
    "sphere (`n = 2`), `vbar` in [0, 1.5]": "profile_exponent=2&points=40",
    "cone (`n = 1`), jumping: `a = 1.5`": "profile_exponent=1&amplitude=1.5&points=40",
    "sphere, stiff contact: `beta = 20`": "profile_exponent=2&beta=20&points=40",
}


def curves(n_moves: int) -> None:
    """The redraw of the curves of :data:`CURVES`, appended to the results."""
    rows = []
    with served() as (_, url, browser):
        for label, query in CURVES.items():
            page = open_page(browser, url + "?" + query)
            moves(page, 5)  # warm
            times = moves(page, n_moves)
            print(f"{label}: {summary(times)}", flush=True)
            rows.append((label, query, times))
            page.close()
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True, cwd=HERE.parent).stdout.strip()
    cpu = platform.processor() or platform.machine()
    lines = [
        "",
        "## The curves of the 2-D and MDR solvers (40 points)",
        "",
        f"Measured {datetime.datetime.now(datetime.UTC):%Y-%m-%d %H:%M} UTC at commit {commit} "
        f"on {cpu}, {psutil.cpu_count()} cores, by `python benchmarks/bench_explorer.py "
        f"--curves --moves {n_moves}`. A move is a key press on the alpha slider, timed "
        "until the redrawn curve's readout changed in the page (the solver's time, the round "
        "trip and the browser's drawing); the page opened with the query given.",
        "",
        "| curve | query | median redraw (ms) | 10-90 % (ms) | max (ms) |",
        "| --- | --- | ---: | ---: | ---: |",
    ]
    for label, query, times in rows:
        ms = sorted(1e3 * t for t in times)
        q = statistics.quantiles(ms, n=10) if len(ms) >= 10 else [ms[0]] * 9
        lines.append(f"| {label} | `{query}` | {statistics.median(ms):.0f} | "
                     f"{q[0]:.0f}-{q[-1]:.0f} | {ms[-1]:.0f} |")
    out = HERE / "results" / "explorer.md"
    with out.open("a") as fh:
        fh.write("\n".join(lines) + "\n")
    print(f"-> {out}")


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--moves", type=int, default=30)
    ap.add_argument("--updates", type=int, default=1000)
    ap.add_argument("--curves", action="store_true",
                    help="measure the curves of the 2-D and MDR solvers instead")
    args = ap.parse_args()
    if args.curves:
        curves(args.moves)
        return
    lines = []
    with served() as (server, url, browser):
        page = open_page(browser, url)
        moves(page, 5)  # warm
        redraw = moves(page, args.moves)
        print("redraw:", summary(redraw), flush=True)

        memory = [(0, *rss_mb(server), math.nan, math.nan)]
        done = 0
        while done < args.updates:
            step = min(100, args.updates - done)
            t0 = time.perf_counter()
            block = moves(page, step)
            done += step
            memory.append((done, *rss_mb(server), 1e3 * statistics.median(block),
                           (time.perf_counter() - t0) / step * 1e3))
            print(f"  {done} updates: server {memory[-1][1]:.0f} MB, "
                  f"workers {memory[-1][2]:.0f} MB, median redraw {memory[-1][3]:.0f} ms, "
                  f"{memory[-1][4]:.0f} ms per update", flush=True)

        # two tabs: a fit in the first while the second redraws
        fit_page = open_page(browser, url + "?mode=bench&axis=v0&v_min=0.0001&v_max=0.2"
                                            "&log_x=1")
        with tempfile.TemporaryDirectory() as tmp:
            csv = Path(tmp) / "bench.csv"
            csv.write_text(CSV)
            fit_page.locator("input[type=file][accept='.csv']").set_input_files(str(csv))
            fit_page.get_by_text(re.compile("overlaid 8 measured points")).wait_for()
        fit_page.get_by_role("button", name="fit").click()
        fit_page.get_by_text(re.compile("fitting")).wait_for()
        t_fit = time.perf_counter()
        during = []
        while not fit_page.get_by_text(re.compile(r"fit of \d+ points|fit failed")).count():
            during.append(move(page, "ArrowRight" if len(during) % 10 < 5
                               else "ArrowLeft"))
        fit_seconds = time.perf_counter() - t_fit
        print("during the fit:", summary(during), f"(fit {fit_seconds:.0f} s)", flush=True)

    cpu = platform.processor() or platform.machine()
    lines += [
        "# The explorer: responsiveness and load",
        "",
        f"Measured {datetime.datetime.now(datetime.UTC):%Y-%m-%d %H:%M} UTC on {cpu}, "
        f"{psutil.cpu_count()} cores, {psutil.virtual_memory().total / 2**30:.0f} GB, "
        f"Python {platform.python_version()}, headless Chromium (Debian package), "
        "by `python benchmarks/bench_explorer.py"
        f" --moves {args.moves} --updates {args.updates}`.",
        "",
        "A move is a key press on the alpha slider (one step, the default general system "
        "`(0.5, 2, 0.5)`, 200 points of `vbar` in [0, 1.5]); its time runs until the "
        "redrawn curve's readout changed in the page (the curve and the case map are redrawn "
        "together; the point's history follows only once the inputs rest for 0.4 s, so not "
        "during these moves). The solver's own time for the 200 points is 0.1-0.5 s here "
        "(it grows as alpha nears 1); the rest is the round trip and the browser's drawing, "
        "all on the same two cores.",
        "",
        f"* **redraw**: {summary(redraw)}",
        f"* **two tabs**: while one tab runs a fit ({fit_seconds:.0f} s, 8 points, "
        f"mu0, mass, k_xc free) the other redraws in {summary(during)}: nothing waits "
        "for the fit (its own worker process, the server's event loop free); the slower "
        "redraw is the fit taking one of the two cores.",
        "",
        "## Server memory over the updates",
        "",
        "| updates | server process RSS (MB) | worker processes RSS (MB) | median redraw of "
        "the last 100 (ms) | wall time per update (ms) |",
        "| ---: | ---: | ---: | ---: | ---: |",
        *(f"| {n} | {s:.0f} | {w:.0f} | {_ms(m)} | {_ms(u)} |" for n, s, w, m, u in memory),
        "",
    ]
    out = HERE / "results" / "explorer.md"
    out.write_text("\n".join(lines))
    print(f"-> {out}")


if __name__ == "__main__":
    main()
