"""Static above kinetic friction with every switch an event: the peer and the exact solver.

:func:`vibrofriction_reference.static_kinetic_events_run` integrates each smooth phase with
scipy's DOP853 and restarts at each switch (its own code, written from the model
statement). It agrees with the exact solver to about 1e-11 where the fixed-step peer's
error is smooth, and it decides the points where that error is not: rigid contacts that
touch down, and switches that graze. The three points below, from fresh random points
(``tests/reference_points.static_kinetic_points``), are ones where the fixed-step peer
disagreed with the solver beyond its bar at 800 and 1600 steps a period (by 2.6e-5,
6.6e-6 and 9.3e-3): the events give the solver's value to about 3e-12.
"""

from __future__ import annotations

import math

import pytest

import vibrofriction as vf
from reference_points import static_kinetic_points
from vibrofriction_reference import static_kinetic_events_run

# (seed, index) of static_kinetic_points(480, [seed, 55]): a period-3 orbit whose switch
# grazes (elastic, damped), and two rigid jumping contacts touching down
HARD = [(2001, "(1.134, 4.653, 0.7769, 0.0592, 0.0497, 1.75, sliding)"),
        (2003, "(1.705, inf, 1.197, 0.4969, 0, 1.14, rest)"),
        (2005, "(1.759, inf, 1.474, 0.5021, 0, 1.66, rest)")]


def _point(seed: int, label: str) -> tuple:
    for p in static_kinetic_points(480, [seed, 55]):
        if f"({p[0]:.4g}, {p[1]:.4g}, {p[2]:.4g}, {p[3]:.4g}, {p[4]:.3g}, {p[5]:.3g}, " \
                f"{p[6]})" == label:
            return p
    raise LookupError(label)


def _compare(alpha, beta, a, V, zeta, sr, initial, transient):
    r = vf.friction_coefficient(vf.Dimensionless(alpha, beta, a, zeta=zeta, static_ratio=sr),
                                v_inertial=V, initial=initial)
    assert r.trusted and r.status is vf.Status.PERIODIC
    period = max(1, r.period)
    ev = static_kinetic_events_run(alpha, beta, a, V, sr, zeta=zeta, initial=initial,
                                   transient_periods=transient,
                                   average_periods=period * math.ceil(24 / period))
    assert ev.error < 1e-9
    assert abs(r.mu_ratio - ev.mu_ratio) <= r.error + ev.error + 1e-11


@pytest.mark.parametrize("point", [
    (0.5, 2.0, 0.5, 0.33, 0.0, 1.0, "sliding"),  # Coulomb's law
    (0.5, 2.0, 0.5, 0.33, 0.0, 1.3, "sliding"),
    (0.3, math.inf, 0.8, 0.5, 0.05, 1.5, "rest"),  # rigid, pin damping
])
def test_events_agree_with_the_solver(point):
    _compare(*point, transient=80)


@pytest.mark.slow
@pytest.mark.parametrize("seed, label", HARD)
def test_events_decide_where_the_fixed_steps_do_not(seed, label):
    _compare(*_point(seed, label), transient=300)


def test_the_fixed_steps_miss_where_the_events_do_not():
    """The rigid touch-down of the 2005 point: the fixed-step peer is off by 9e-3."""
    from vibrofriction_reference import static_kinetic_run

    alpha, beta, a, V, zeta, sr, initial = _point(*HARD[2])
    kw = dict(zeta=zeta, initial=initial, transient_periods=60, average_periods=8)
    fixed = static_kinetic_run(alpha, beta, a, V, sr, steps_per_period=800, **kw)
    ev = static_kinetic_events_run(alpha, beta, a, V, sr, **kw)
    assert abs(fixed.mu_ratio - ev.mu_ratio) > 100 * (fixed.error + ev.error)


@pytest.mark.parametrize("kw, name", [
    (dict(static_ratio=0.9), "static_ratio"),
    (dict(rtol=1e-3), "rtol"),
    (dict(average_periods=0), "average_periods"),
    (dict(zeta=-1.0), "zeta"),
])
def test_refusals_name_the_parameter(kw, name):
    with pytest.raises(ValueError, match=name):
        static_kinetic_events_run(0.5, 2.0, 0.5, 0.33, **kw)
