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
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import vibrofriction as vf
from vibrofriction_reference.friction_laws import rate_state_run

MAX_TRANSIENT = 300
WINDOW = 10


def _points(n: int, seed: int) -> list[dict]:
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(n):
        alpha = 10 ** rng.uniform(-0.7, 0.5)
        beta = alpha + 10 ** rng.uniform(0, 1)
        amplitude = rng.uniform(0.2, 1.5)
        V = 10 ** rng.uniform(-1, 0.3)
        zeta = float(rng.choice([0.0, 0.1]))
        a = 10 ** rng.uniform(-2, -1.3)
        b = a * rng.uniform(0.3, 1.5)
        d_c = 10 ** rng.uniform(-2, -1)
        v_ref = 10 ** rng.uniform(-0.5, 0.3)
        law = str(rng.choice(["aging", "slip"]))
        ld = float(rng.choice([0.0, 0.3])) if amplitude < 1 else 0.0
        out.append(dict(alpha=float(alpha), beta=float(beta), amplitude=float(amplitude),
                        V=float(V), zeta=zeta, a=float(a), b=float(b), d_c=float(d_c),
                        v_ref=float(v_ref), law=law, alpha_ld=ld))
    return out


POINTS = _points(14, 34)


@pytest.mark.slow
def test_rate_state_agrees_with_the_reference() -> None:
    compared, worst = 0, 0.0
    regimes = set()
    for p in POINTS:
        s = vf.Dimensionless(alpha=p["alpha"], beta=p["beta"], amplitude=p["amplitude"],
                             zeta=p["zeta"], rs_a=p["a"], rs_b=p["b"], rs_d_c=p["d_c"],
                             rs_v_ref=p["v_ref"], rs_alpha_ld=p["alpha_ld"], rs_law=p["law"])
        r = vf.friction_coefficient(s, v_inertial=p["V"])
        if r.status is not vf.Status.PERIODIC:
            continue
        transient = MAX_TRANSIENT if r.multiplier <= 0.0 else min(
            MAX_TRANSIENT, math.ceil(math.log(1e-9) / math.log(r.multiplier)))
        ref = rate_state_run(p["alpha"], p["beta"], p["amplitude"], p["V"], p["a"], p["b"],
                             p["d_c"], p["v_ref"], alpha_ld=p["alpha_ld"], law=p["law"],
                             zeta=p["zeta"], transient_periods=transient,
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
