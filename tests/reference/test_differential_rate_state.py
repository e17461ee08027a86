"""Rate-and-state friction: the rate-and-state solver against the independent reference.

The reference (:func:`vibrofriction_reference.friction_laws.rate_state_run`: scipy's
``solve_ivp``, LSODA with Radau as fallback, arc by arc; its own code) starts from the
same steady sliding, averages a fixed window after a transient and states the difference
of its runs at ``rtol`` and ``100 rtol`` as its error bar.  Compared at random points of
every regime (velocity weakening and strengthening, aging and slip law, the
Linker-Dieterich coupling on and off, pin damping, jumping) where the solver answers a
periodic orbit: the transient is what the solver's multiplier needs to come within 1e-9
(at most ``MAX_TRANSIENT`` periods), and the combined bar is the two stated errors plus the
spread of the reference's per-period means over its window (what its transient left).
A point the solver does not answer periodic is no agreement: they are counted, and most
points must be compared.  When written (2026-11-29, seed 34): 10 of 14 points periodic, all
within the combined bars.

A rigid contact (``beta = inf``) likewise, at its own random points (``a`` from 0.03 to
0.08, where the reference's rigid contact is well behaved): when written (seed 34) 14 of 14
periodic, all within the combined bars (the largest difference 0.19 of its bar); and its
time history from the start against the reference's at a tight tolerance.  Contact damping
(``eta_c`` from 0.02 to 0.4, seed 35): 12 of 12 periodic, all within the combined bars (the
largest difference 0.58 of its bar).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import vibrofriction as vf
from vibrofriction_reference.friction_laws import rate_state_run

MAX_TRANSIENT = 300
WINDOW = 10


def _points(n: int, seed: int, rigid: bool = False, damped: bool = False) -> list[dict]:
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(n):
        eta_c = float(10 ** rng.uniform(-1.7, -0.4)) if damped else 0.0
        alpha = 10 ** rng.uniform(-0.7, 0.5)
        beta = math.inf if rigid else alpha + 10 ** rng.uniform(0, 1)
        amplitude = rng.uniform(0.2, 1.5)
        V = 10 ** rng.uniform(-1, 0.3)
        zeta = float(rng.choice([0.0, 0.1]))
        a = 10 ** (rng.uniform(-1.5, -1.1) if rigid else rng.uniform(-2, -1.3))
        b = a * rng.uniform(0.3, 1.5)
        d_c = 10 ** rng.uniform(-2, -1)
        v_ref = 10 ** rng.uniform(-0.5, 0.3)
        law = str(rng.choice(["aging", "slip"]))
        ld = float(rng.choice([0.0, 0.3])) if amplitude < 1 else 0.0
        out.append(dict(alpha=float(alpha), beta=float(beta), amplitude=float(amplitude),
                        V=float(V), zeta=zeta, a=float(a), b=float(b), d_c=float(d_c),
                        v_ref=float(v_ref), law=law, alpha_ld=ld, eta_c=eta_c))
    return out


POINTS = _points(14, 34)
RIGID_POINTS = _points(14, 34, rigid=True)
DAMPED_POINTS = _points(12, 35, damped=True)


@pytest.mark.slow
@pytest.mark.parametrize("points", [POINTS, RIGID_POINTS, DAMPED_POINTS],
                         ids=["finite", "rigid", "damped"])
def test_rate_state_agrees_with_the_reference(points: list[dict]) -> None:
    compared, worst = 0, 0.0
    regimes = set()
    for p in points:
        s = vf.Dimensionless(alpha=p["alpha"], beta=p["beta"], amplitude=p["amplitude"],
                             zeta=p["zeta"], rs_a=p["a"], rs_b=p["b"], rs_d_c=p["d_c"],
                             rs_v_ref=p["v_ref"], rs_alpha_ld=p["alpha_ld"], rs_law=p["law"],
                             eta_c=p["eta_c"])
        r = vf.friction_coefficient(s, v_inertial=p["V"])
        if r.status is not vf.Status.PERIODIC:
            continue
        transient = MAX_TRANSIENT if r.multiplier <= 0.0 else min(
            MAX_TRANSIENT, math.ceil(math.log(1e-9) / math.log(r.multiplier)))
        ref = rate_state_run(p["alpha"], p["beta"], p["amplitude"], p["V"], p["a"], p["b"],
                             p["d_c"], p["v_ref"], alpha_ld=p["alpha_ld"], law=p["law"],
                             zeta=p["zeta"], eta_c=p["eta_c"], transient_periods=transient,
                             average_periods=WINDOW)
        means = ref.period_f / ref.period_n
        bar = r.error + ref.error + float(means.max() - means.min())
        diff = abs(r.mu_ratio - ref.mu_ratio)
        assert diff <= bar, (p, r.mu_ratio, r.error, ref.mu_ratio, ref.error, bar)
        worst = max(worst, diff / bar)
        compared += 1
        regimes.add((p["b"] > p["a"], p["law"], p["alpha_ld"] > 0.0, p["zeta"] > 0.0,
                     p["amplitude"] > 1.0))
    assert compared >= 9, compared
    # weakening and strengthening, both laws, the coupling, damping and jumping all compared
    assert {r[1] for r in regimes} == {"aging", "slip"}
    for i in (0, 2, 3, 4):
        assert {r[i] for r in regimes} == {True, False}, i


def test_rigid_history_agrees_with_the_reference() -> None:
    """A rigid contact's motion from the start (the same steady sliding, the body's velocity
    continuous at ``tau = 0``), jumping, damped, slip law: ``vf.simulate`` against the
    reference's dense output at a tight tolerance over three periods (the reference at
    rtol 1e-10 is within 5e-7 of the solver at its default tolerance; at 1e-8, 5e-5)."""
    from vibrofriction_reference.friction_laws import rate_state_history

    s = vf.Dimensionless(alpha=0.5, beta=math.inf, amplitude=1.3, zeta=0.1, rs_a=0.05,
                         rs_b=0.03, rs_d_c=0.05, rs_v_ref=1.0, rs_law="slip")
    h = vf.simulate(s, v_inertial=0.8, periods=3, samples_per_period=100)
    ref = rate_state_history(0.5, math.inf, 1.3, 0.8, 0.05, 0.03, 0.05, 1.0, law="slip",
                             zeta=0.1, periods=3, points_per_period=100, rtol=1e-10,
                             atol=1e-12)
    for t in (1.0, 2.0 * math.pi, 9.0, 6.0 * math.pi):  # contact, a section, flight, end
        i = int(np.argmin(np.abs(h.tau - t)))
        j = int(np.argmin(np.abs(ref.tau - t)))
        assert abs(h.tau[i] - ref.tau[j]) < 1e-9 and abs(h.tau[i] - t) < 0.05
        assert h.x[i] == pytest.approx(ref.y[j] + 0.8 * ref.tau[j], abs=1e-5)
        assert h.x_dot[i] == pytest.approx(ref.xdot[j], abs=1e-5)
        assert h.f[i] == pytest.approx(ref.f[j], abs=1e-5)
        assert h.theta[i] == pytest.approx(ref.theta[j], rel=1e-5)
