"""The explorer's screenshots in docs/img/, taken in the distribution's headless Chromium.

Starts ``vibrofriction explore`` on a free port (as bench_explorer.py does) and saves
``explorer_default.png`` (the default view), ``explorer_inplane.png`` (a combined
normal + longitudinal drive over signed velocities), ``explorer_history.png`` (a point's time
history after a click on the curve), ``explorer_map.png`` (the case map, soft contact),
``explorer_error.png`` (the inline message for a typed ``beta`` below ``alpha``),
``explorer_fit.png`` (a measured CSV at two amplitudes overlaid and fitted) and
``explorer_path.png`` (a transverse drive: the history with ``f_y`` and the contact point's
path in the plane, cropped to the history) and ``explorer_mdr.png`` (a sphere: eta_c
reset with the MDR solver's refusal beside it, its curve on the axis vbar and its critical
velocity of continuous sliding, a point's history and its contact in space and time) and
``explorer_axis.png`` (a_x typed on the axis vbar: the axis switched to V, said beside a_x and
the axis; the mount's note under its toggle) and the friction laws: ``explorer_static.png``
(static above kinetic, a point's history with the local coefficient f/n) and
``explorer_rate_state.png`` (rate-and-state friction with contact damping eta_c = 0.1, the
curve with steady sliding without oscillation, a point's history with the state theta
chosen under the forces).

Run:  python benchmarks/explorer_screenshots.py [default inplane history map error fit path
      mdr axis static rate_state]
"""

from __future__ import annotations

import re
import shutil
import signal
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
from playwright.sync_api import Page, sync_playwright

from bench_explorer import READOUT, free_port, start_server
from vibrofriction.bench import synthetic_measurements
from vibrofriction.explorer.state import State

IMG = Path(__file__).resolve().parent.parent / "docs" / "img"
WIDTH, HEIGHT = 1500, 1000
HISTORY = re.compile("history at")


def measurements(folder: Path) -> Path:
    """A synthetic bench CSV: two amplitudes, 10 velocities each, noise 0.004."""
    truth = State(mode="bench", mu0=0.32, k_xc=1.0e7).system()
    table = synthetic_measurements(truth, (0.4e-6, 0.8e-6), np.geomspace(1e-3, 0.2, 10), 0.004,
                                   np.random.default_rng(3))
    path = folder / "bench_measurements.csv"
    table.to_csv(path, index=False)
    return path


def opened(browser, url: str) -> Page:
    """A page at ``url`` once its curve and its first history are drawn."""
    page = browser.new_page(viewport={"width": WIDTH, "height": HEIGHT})
    page.set_default_timeout(180_000)
    page.goto(url)
    page.get_by_text(READOUT).wait_for()
    page.get_by_text(HISTORY).wait_for()
    time.sleep(1.0)  # let the canvases settle
    return page


def shoot(page: Page, name: str, height: int | None = None) -> None:
    path = IMG / f"explorer_{name}.png"
    if height is None:
        page.screenshot(path=path, full_page=True)
    else:
        page.screenshot(path=path, clip={"x": 0, "y": 0, "width": WIDTH, "height": height})
    page.close()
    print(path)


def main(which: list[str]) -> None:
    IMG.mkdir(exist_ok=True)
    port = free_port()
    server = start_server(port)
    url = f"http://127.0.0.1:{port}/"
    try:
        with sync_playwright() as p, tempfile.TemporaryDirectory() as tmp:
            browser = p.chromium.launch(executable_path=shutil.which("chromium"),
                                        headless=True)
            if "default" in which:
                shoot(opened(browser, url), "default")
            if "history" in which:
                page = opened(browser, url + "?alpha=0.2&beta=5.3&amplitude=1.5&v_max=1.2")
                shown = page.get_by_text(HISTORY).inner_text()
                box = page.locator("canvas").first.bounding_box()
                page.mouse.click(box["x"] + 0.45 * box["width"], box["y"] + 0.5 * box["height"])
                while page.get_by_text(HISTORY).inner_text() == shown:
                    time.sleep(0.1)
                time.sleep(1.0)
                shoot(page, "history", 760)
            if "inplane" in which:
                shoot(opened(browser, url + "?a_x=1&phase_x=3.1&zeta=0.05&eta_c=0.1&axis=V"
                             "&v_min=-1.5&v_max=1.5"), "inplane")
            if "path" in which:
                page = opened(browser, url + "?a_y=0.5&phase_y=0.3&eta_c=0.1&axis=V"
                              "&v_min=0.05&v_max=1.2&points=40")
                time.sleep(1.0)
                shoot(page, "path")
            if "mdr" in which:
                page = opened(browser, url + "?eta_c=0.1&v_max=1.2")
                shown = page.get_by_text(READOUT).inner_text()
                page.get_by_role("button", name="sphere", exact=True).click()
                while page.get_by_text(READOUT).inner_text() == shown:
                    time.sleep(0.1)
                page.get_by_text(re.compile("point at vbar = ")).wait_for()
                time.sleep(1.5)
                shoot(page, "mdr")
            if "axis" in which:
                page = opened(browser, url)
                shown = page.get_by_text(READOUT).inner_text()
                box = page.locator(".vf-text-a_x input")
                box.fill("0.5")
                box.press("Enter")
                while page.get_by_text(READOUT).inner_text() == shown:
                    time.sleep(0.1)
                page.get_by_text(re.compile("history at V = ")).wait_for()
                time.sleep(1.5)
                shoot(page, "axis", 1000)
            if "static" in which:
                shoot(opened(browser, url + "?friction=static&static_ratio=1.6"), "static")
            if "rate_state" in which:
                page = browser.new_page(viewport={"width": WIDTH, "height": HEIGHT})
                page.set_default_timeout(180_000)
                page.goto(url + "?friction=rate_state&eta_c=0.1")
                page.get_by_text(READOUT).wait_for()
                page.get_by_text(re.compile("history at vbar = ")).wait_for()
                page.get_by_role("button", name="state theta").click()
                time.sleep(1.5)
                shoot(page, "rate_state")
            if "map" in which:
                shoot(opened(browser, url + "?alpha=0.01&beta=400.01&amplitude=1"), "map", 760)
            if "error" in which:
                page = opened(browser, url)
                beta = page.locator("input.bk-input[type=text]").nth(1)
                beta.fill("0.3")
                beta.press("Enter")
                page.get_by_text("beta must be > alpha").wait_for()
                time.sleep(0.5)
                shoot(page, "error", 520)
            if "fit" in which:
                page = opened(browser, url + "?mode=bench&axis=v0&v_min=0.001&v_max=0.2&log_x=1")
                page.locator("input[type=file][accept='.csv']").set_input_files(
                    str(measurements(Path(tmp))))
                page.get_by_text(re.compile("overlaid 20 measured")).wait_for()
                page.get_by_role("button", name="fit").click()
                page.get_by_text(re.compile(r"fit of \d+ points|fit failed")).wait_for()
                time.sleep(1.0)
                shoot(page, "fit")
    finally:
        server.send_signal(signal.SIGINT)
        server.wait(20)


if __name__ == "__main__":
    main(sys.argv[1:] or ["default", "inplane", "history", "map", "error", "fit",
                             "path", "mdr", "axis", "static", "rate_state"])
