"""Regenerate the numbers quoted in docs/inplane.md.

    PYTHONPATH=src python benchmarks/inplane_numbers.py      # writes results/inplane_numbers.md

The closed forms come from ``vibrofriction.theory``; where the dynamics are compared with
them, this script integrates the rigid-contact model itself with a first-order Moreau
time-stepping (its own code, not the package's kernels, which have no in-plane physics
yet): body velocity ``u`` (2-D), free step ``u* = u + dt (alpha (h - x) + gamma (h' - u))``,
then the frictional impulse projected on the cone ``|P| <= dt n``: stick (the body moves
with the substrate) if ``|u* - s'| <= dt n``, else ``u = u* - dt n (u* - s')/|u* - s'|``.
Its error is first order in ``dt``; each number is given with the difference to a run at
half the step.  About 10 s on one core.  tests/docs/test_quoted_numbers.py calls each
section function of :data:`CLAIMS` and checks its rows against the results file and the page.
"""

from __future__ import annotations

import math
import platform
import subprocess
import time
from collections.abc import Callable
from datetime import UTC, datetime
from pathlib import Path

import numba
import numpy as np

from vibrofriction import theory

RESULTS = Path(__file__).parent / "results" / "inplane_numbers.md"
Rows = list[tuple[str, str]]


@numba.njit(cache=True)
def _moreau(alpha, zeta, a, V, a_x, phase_x, a_y, phase_y, holder, steps, settle, periods):
    """Mean ``<f_x>/<n>`` and ``<f_y>/<n>`` of the rigid-contact model over ``periods``
    after ``settle`` periods; start: steady sliding (spring stretched by 1, ``x' = V``)."""
    dt = 2.0 * math.pi / steps
    gamma = 2.0 * zeta * math.sqrt(alpha)
    x = -1.0 / alpha if alpha > 0 else 0.0
    y = 0.0
    u = V
    w = 0.0
    sfx = sfy = sn = 0.0
    for i in range((settle + periods) * steps):
        t0 = i * dt
        t1 = t0 + dt
        hx = V * t0
        hxd = V
        hy = hyd = 0.0
        sxd = syd = 0.0
        if holder:
            hx += a_x * math.cos(t0 + phase_x)
            hxd -= a_x * math.sin(t0 + phase_x)
            hy += a_y * math.cos(t0 + phase_y)
            hyd -= a_y * math.sin(t0 + phase_y)
        else:
            sxd = -a_x * math.sin(t1 + phase_x)
            syd = -a_y * math.sin(t1 + phase_y)
        ux = u + dt * (alpha * (hx - x) + gamma * (hxd - u))
        uy = w + dt * (alpha * (hy - y) + gamma * (hyd - w))
        n = max(0.0, 1.0 + a * math.cos(t1))
        rx = ux - sxd
        ry = uy - syd
        r = math.hypot(rx, ry)
        if r <= dt * n:
            u, w = sxd, syd
        else:
            u = ux - dt * n * rx / r
            w = uy - dt * n * ry / r
        x += dt * u
        y += dt * w
        if i >= settle * steps:
            sfx += (ux - u) / dt  # the contact force f (the body receives -f)
            sfy += (uy - w) / dt
            sn += n
    return sfx / sn, sfy / sn


def _mu(alpha, zeta, a, V, a_x=0.0, phase_x=0.0, a_y=0.0, phase_y=0.0, holder=False,
        steps=2000, settle=150, periods=50):
    fine = _moreau(alpha, zeta, a, V, a_x, phase_x, a_y, phase_y, holder, 2 * steps, settle,
                   periods)
    coarse = _moreau(alpha, zeta, a, V, a_x, phase_x, a_y, phase_y, holder, steps, settle,
                     periods)
    return fine[0], abs(fine[0] - coarse[0])


def kinematic() -> Rows:
    """Kinematic laws against the rigid-contact dynamics (zeta = 0.05, a = 0): the largest
    |mu_dynamics - law| over V/a_vib = 0.25, 0.5, 0.75 (longitudinal: a_x; transverse: a_y);
    "holder, effective": the law with the body's amplitude |H| a_vib, H = (alpha + i gamma)/P."""
    rows = []
    for on in ("substrate", "holder", "holder, effective"):
        for alpha, amp in ((0.01, 10.0), (0.1, 3.0), (0.1, 10.0), (10.0, 1.0), (10.0, 3.0),
                           (100.0, 1.0)):
            dev_x = dev_y = err = 0.0
            gamma = 0.1 * math.sqrt(alpha)
            gain = abs((alpha + 1j * gamma) / (alpha - 1 + 1j * gamma)) if "eff" in on else 1.0
            holder = on != "substrate"
            for r in (0.25, 0.5, 0.75):
                mu, e = _mu(alpha, 0.05, 0.0, r * amp, a_x=amp, holder=holder)
                dev_x = max(dev_x, abs(mu - theory.kinematic_mu_longitudinal(r, gain)))
                muy, ey = _mu(alpha, 0.05, 0.0, r * amp, a_y=amp, holder=holder)
                dev_y = max(dev_y, abs(muy - theory.kinematic_mu_transverse(r, gain)))
                err = max(err, e, ey)
            rows.append((f"{on}, alpha {alpha}, amplitude {amp}",
                         f"longitudinal {dev_x:.3g}, transverse {dev_y:.3g} "
                         f"(step effect {err:.1g})"))
    return rows


def combined_critical() -> Rows:
    """The issue's system (0.5, 2, 0.5), a_x = 0.5 at phase pi/2, and its cancellation;
    then rigid contact, zeta = 0.1, a = 0.5, a_x = 0.5: the dynamics at 0.9 and 1.02 V_c."""
    rows = []
    for on in ("substrate", "holder"):
        for zeta, eta in ((0.0, 0.0), (0.05, 0.1)):
            vc = theory.inplane_critical_velocity(0.5, 2.0, 0.5, 0.5, math.pi / 2, zeta, eta,
                                                  on)
            vc0 = theory.critical_inertial_velocity(0.5, 2.0, 0.5, zeta, eta)
            c = theory.inplane_cancellation(0.5, 2.0, 0.5, zeta, eta, on)
            st = theory.inplane_static_mu_ratio(0.5, 2.0, 0.5, 0.5, math.pi / 2, zeta, eta, on)
            rows.append((f"(0.5, 2, 0.5), {on}, zeta {zeta}, eta_c {eta}",
                         f"V_c(a_x=0) {vc0:.4f}; V_c(0.5, pi/2) {vc:.4f}; cancels at phase "
                         f"{c.phase_x:.4f}, a_x {c.a_x:.4f}; static mu(0+) {st.upper:.4f}, "
                         f"mu(0-) {st.lower:.4f}"))
    for on in ("substrate", "holder"):
        for phase in (0.0, math.pi / 2, math.pi, 4.0):
            vc = theory.inplane_critical_velocity(3.0, math.inf, 0.5, 0.5, phase, 0.1,
                                                  inplane_on=on)
            lo, _ = _mu(3.0, 0.1, 0.5, 0.9 * vc, a_x=0.5, phase_x=phase, holder=on == "holder")
            hi, _ = _mu(3.0, 0.1, 0.5, 1.02 * vc, a_x=0.5, phase_x=phase,
                        holder=on == "holder")
            rows.append((f"(3, inf, 0.5), zeta 0.1, a_x 0.5, {on}, phase {phase:.3g}",
                         f"V_c {vc:.4f}; mu/mu0 {lo:.5f} at 0.9 V_c, {hi:.8f} at 1.02 V_c"))
    return rows


#: the section functions (tests/docs/test_quoted_numbers.py calls each and checks the rows)
CLAIMS: dict[str, Callable[[], Rows]] = {
    f.__name__: f for f in (kinematic, combined_critical)}


def _header() -> str:
    try:
        commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                                text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        commit = "unknown"
    return (f"# Numbers of docs/inplane.md\n\n`python benchmarks/inplane_numbers.py`, commit "
            f"{commit}, {datetime.now(UTC):%Y-%m-%d %H:%M} UTC; {platform.machine()}, Python "
            f"{platform.python_version()}, numpy {np.__version__}; one process.\n")


def main() -> None:
    parts, total = [_header()], time.perf_counter()
    for name, claim in CLAIMS.items():
        t0 = time.perf_counter()
        rows = claim()
        doc = (claim.__doc__ or "").strip().replace("\n    ", " ")
        table = "\n".join(f"| {q} | {v} |" for q, v in rows)
        parts.append(f"## `{name}` ({time.perf_counter() - t0:.1f} s)\n\n{doc}\n\n"
                     f"| quantity | value |\n|---|---|\n{table}\n")
        print(parts[-1], flush=True)
    parts.append(f"Total {time.perf_counter() - total:.0f} s.\n")
    RESULTS.write_text("\n".join(parts))
    print(f"wrote {RESULTS}")


if __name__ == "__main__":
    main()
