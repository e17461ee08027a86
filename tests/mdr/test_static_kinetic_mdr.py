"""A static coefficient above the kinetic one in the MDR row of a curved tip (``static_ratio
= s > 1``, spring by spring; docs/contact_geometry.md, "A static coefficient above the
kinetic one").

* ``s = 1`` is the row before the law: 20 random rows of 20 springs, three points of the
  solver and a curved history (tests/data/static_ratio_baseline.json, made on the code
  before by tests/data/make_static_ratio_baseline.py; the history's arrays in
  tests/data/static_ratio_curved_history.npz), the counts exactly and the values to
  round-off (bit for bit on the processor the baseline was taken on);
* the law spring by spring on histories: a stuck spring's ``|f_i| <= s n_i`` (reached: the
  largest stuck ``|f_i|/n_i`` comes near ``s``), a slipping one's ``f_i = +-n_i``, one out of
  contact 0;
* the energy balances at every sample to round-off, the jumps' dissipation included;
* the flat punch (one spring) is the 2-D solver at a vanishing transverse amplitude with a
  Jenkins contact (Runge-Kutta with located switches: a different method, no shared
  code) and the 1-D solver with its own law, and a flat row of several springs is the
  single spring;
* a nearly flat profile approaches the flat punch as the exponent grows (first order in
  ``1/n``), at ``s = 1`` and above;
* ``V = 0`` is refused by name where ``s > 1``;
* property: over random valid rows every spring stays within its static limit at the
  scan points, and ``mu_ratio <= s``.
"""

from __future__ import annotations

import json
import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import vibrofriction as vf
from history_checks import ROUNDOFF, assert_history_is_stored
from vibrofriction import theory
from vibrofriction.capabilities import Refusal
from vibrofriction.schema import ContactState, Status
from vibrofriction.solver import solve_points
from vibrofriction.solver.mdr import mdr_friction, mdr_row
from vibrofriction.solver.mdr_history import mdr_history, spring_row

DATA = Path(__file__).resolve().parents[1] / "data"
BASELINE = json.loads((DATA / "static_ratio_baseline.json").read_text())
OPEN, STICK, SLIP_POS, SLIP_NEG = (ContactState.FLIGHT, ContactState.STICK,
                                   ContactState.SLIP_POS, ContactState.SLIP_NEG)
# (alpha, beta, a, V, n, zeta, in-plane): sphere, jumping sphere, cone, soft n = 3,
# longitudinal in-plane oscillation on the holder, V < 0
POINTS = [(0.5, 2.0, 0.5, 0.3, 2.0, 0.0, {}), (0.5, 2.0, 1.5, 0.3, 2.0, 0.1, {}),
          (1.0, 3.0, 0.7, 0.5, 1.0, 0.1, {}), (0.05, 0.1, 0.5, 2.0, 3.0, 0.5, {}),
          (1.3, 4.0, 1.4, 0.8, 2.0, 0.05, dict(a_x=1.2, phase_x=0.3, inplane_on="holder")),
          (0.5, 2.0, 1.2, -0.3, 2.0, 0.1, dict(a_x=0.5, phase_x=4.0))]


def _dim(alpha, beta, a, n, zeta, s=1.0, **inplane):
    return vf.Dimensionless(alpha, beta, a, zeta=zeta, profile_exponent=n, static_ratio=s,
                            **inplane)


# --------------------------------------------------------------------------- s = 1
def test_static_ratio_one_is_the_row_before():
    for p, expected in zip(BASELINE["mdr_points"], BASELINE["mdr_outputs"], strict=True):
        r = mdr_row(p["alpha"], p["beta"], p["amplitude"], p["V"], p["profile_exponent"], 20,
                    p["zeta"], a_x=p["a_x"], phase_x=p["phase_x"],
                    inplane_on=p["inplane_on"], static_ratio=1.0)
        y, yd, st_, e = r["final_state"]
        got = dict(mu_ratio=r["mu_ratio"], error=r["error"], status=r["status"],
                   periods=r["periods"], events=r["events_per_period"],
                   max_excess=r["max_excess"],
                   fractions=[r["stick_area_fraction"], r["slip_area_fraction"],
                              r["open_area_fraction"]],
                   y=y, yd=yd, st=[int(s) for s in st_], e=[float(x) for x in e])
        _assert_same(json.loads(json.dumps(got)), expected)


def _assert_same(got: dict, expected: dict) -> None:
    """Every value of ``expected``: an integer or a name (status, counts, spring states)
    exactly, a float to :data:`ROUNDOFF` relative (the baseline was taken on another
    processor, which rounds a few last digits differently: 4e-14 apart on an AMD EPYC,
    2026-11-29)."""
    assert got.keys() >= expected.keys()
    for k, v in expected.items():
        have, want = np.asarray(got[k]), np.asarray(v)
        if want.dtype.kind in "iubUO":  # integers, flags and names: exactly
            assert np.array_equal(have, want), k
        else:
            assert np.allclose(have, want, rtol=ROUNDOFF, atol=ROUNDOFF, equal_nan=True), k


def test_static_ratio_one_is_the_solver_and_history_before(rows_alone):
    # (the baseline is the rows'; solve_points of one point runs in this process)
    for p, expected in zip(BASELINE["mdr_solver_points"], BASELINE["mdr_solver_outputs"],
                           strict=True):
        got = {k: np.asarray(v).item() for k, v in solve_points(**p, static_ratio=1.0).items()}
        _assert_same(got, expected)
    h = BASELINE["histories"][2]
    sim = vf.simulate(vf.Dimensionless(**h["system"], static_ratio=1.0),
                      v_inertial=h["v_inertial"], periods=h["periods"], initial=h["initial"])
    assert_history_is_stored(sim, DATA / "static_ratio_curved_history.npz",
                             BASELINE["history_sha256"][2])


# --------------------------------------------------------------------------- the law
def _spring_normal(h):
    """Every spring's normal force ``w max(0, 1 + a cos tau - g_i)`` at the samples."""
    d = h.system
    _, g, w, _ = spring_row(d.amplitude, d.profile_exponent, h.xi.size)
    return w * np.maximum(0.0, 1.0 + d.amplitude * np.cos(h.tau)[:, None] - g[None, :])


@pytest.mark.parametrize("s", [1.3, 2.0])
@pytest.mark.parametrize("alpha, beta, a, V, n, zeta, inplane", POINTS)
def test_the_law_spring_by_spring_along_a_history(alpha, beta, a, V, n, zeta, inplane, s):
    d = _dim(alpha, beta, a, n, zeta, s, **inplane)
    h = vf.simulate(d, v_inertial=V, periods=3, samples_per_period=600, springs=40)
    ni = _spring_normal(h)
    f, state = h.spring_f, h.spring_state
    tol = 1e-12 * float(np.max(ni))
    stuck = state == STICK
    assert stuck.any() and np.isin(state, (SLIP_POS, SLIP_NEG)).any()
    assert np.all(np.abs(f[stuck]) <= s * ni[stuck] + tol)
    np.testing.assert_allclose(f[state == SLIP_POS], ni[state == SLIP_POS], atol=tol)
    np.testing.assert_allclose(f[state == SLIP_NEG], -ni[state == SLIP_NEG], atol=tol)
    assert np.all(f[state == OPEN] == 0.0)
    # the static limit is reached: near its stick->slip a spring carries almost s n_i
    loaded = stuck & (ni > 0.05 * np.max(ni))
    ratio = np.max(np.abs(f[loaded]) / ni[loaded])
    print(f"largest stuck |f_i|/n_i: {ratio:.4f} (s = {s})")
    assert 1.0 + 0.8 * (s - 1.0) < ratio <= s * (1 + 1e-12)


def _balance(h):
    """Work input minus dissipation minus the change of the stored energy, at each sample."""
    E = h.stored_energy()
    return h.work_input - h.dissipated_pin - h.dissipated_friction - (E - E[0])


@pytest.mark.parametrize("alpha, beta, a, V, n, zeta, inplane", POINTS)
def test_energy_balance_with_the_jumps(alpha, beta, a, V, n, zeta, inplane):
    """At every sample from the sliding start, to round-off: each stick->slip puts the
    spring's energy ``(k^2 e_i^2 - n_i^2)/(2 k)`` into the friction's dissipation (without it
    the balance is off by that much at the first jump)."""
    d = _dim(alpha, beta, a, n, zeta, 1.5, **inplane)
    h = vf.simulate(d, v_inertial=V, periods=3, samples_per_period=50, springs=30)
    st_ = h.spring_state
    assert np.any((st_[:-1] == STICK) & np.isin(st_[1:], (SLIP_POS, SLIP_NEG)))  # jumps
    bal = _balance(h)
    print(f"{np.max(np.abs(bal)):.2e} of work {h.work_input[-1]:.3f}")
    assert np.max(np.abs(bal)) <= 1e-10 * max(1.0, abs(h.work_input[-1]))
    assert np.all(np.diff(h.dissipated_friction) >= -1e-13)


# --------------------------------------------------------------------------- other methods
# (alpha, beta, a, V, zeta, a_x, phase_x): where the flat punch has one attractor from both
# starts (an undamped pin with s > 1 can have several: the two solvers' sliding starts
# differ, the row's slipping at n(0), the 2-D one's stuck at the force 1)
FLAT = [(0.5, 2.0, 0.5, 0.3, 0.05, 0.0, 0.0), (1.3, 4.0, 1.4, 0.8, 0.0, 0.0, 0.0),
        (1.0, 3.0, 0.9, 1.0, 0.1, 0.0, 0.0), (2.5, 3.0, 2.0, 0.4, 0.02, 0.0, 0.0),
        (0.5, 2.0, 0.6, 0.3, 0.1, 0.5, 1.0), (0.3, 3.0, 0.0, 0.1, 0.05, 0.0, 0.0)]


@pytest.mark.parametrize("s", [1.3, 2.0])
@pytest.mark.parametrize("alpha, beta, a, V, zeta, a_x, phase_x", FLAT)
def test_flat_punch_is_the_2d_solver_at_a_vanishing_transverse_amplitude(
        alpha, beta, a, V, zeta, a_x, phase_x, s):
    """The row's one spring (closed forms, events to round-off) against the 2-D kernel
    (Dormand-Prince, switches located by the Illinois method) with a Jenkins contact at
    ``a_y = 1e-7``: within the 2-D solver's error plus ``1e-8`` (a jumping Jenkins
    contact's arcs are shortened by ``1e-7``, which moves its mean by about ``1e-8``: the
    same difference at ``s = 1``)."""
    row = mdr_friction(alpha, beta, a, V, math.inf, zeta=zeta, a_x=a_x, phase_x=phase_x,
                       static_ratio=s)
    two = solve_points(alpha, beta, a, V, zeta=zeta, a_x=a_x, phase_x=phase_x, a_y=1e-7,
                       static_ratio=s)
    diff = abs(row["mu_ratio"] - float(two["mu_ratio"]))
    print(f"{row['mu_ratio']:.10f} {float(two['mu_ratio']):.10f} {diff:.1e}")
    assert int(two["status"]) in (Status.PERIODIC.code, Status.AVERAGED.code)
    assert diff <= row["error"] + float(two["error"]) + 1e-8


@pytest.mark.parametrize("s", [1.3, 2.0])
@pytest.mark.parametrize("alpha, beta, a, V, zeta, a_x, phase_x", FLAT)
def test_flat_punch_is_the_1d_solver_with_the_same_law(alpha, beta, a, V, zeta, a_x, phase_x,
                                                       s):
    """The row's one spring against the 1-D event-driven solver's own static-above-kinetic
    law (closed forms both, separate kernels): within 1e-10, as at ``s = 1``
    (tests/mdr/test_mdr_solver.py)."""
    row = mdr_friction(alpha, beta, a, V, math.inf, zeta=zeta, a_x=a_x, phase_x=phase_x,
                       static_ratio=s)
    one = solve_points(alpha, beta, a, V, zeta=zeta, a_x=a_x, phase_x=phase_x, static_ratio=s)
    diff = abs(row["mu_ratio"] - float(one["mu_ratio"]))
    print(f"{row['mu_ratio']:.12f} {float(one['mu_ratio']):.12f} {diff:.1e}")
    # (0.5, 2, 0.6, 0.3, a_x 0.5) at s = 2 has an orbit of period 10: the row averages it
    assert row["status"] in ("periodic", "averaged")
    assert diff <= 1e-10


@pytest.mark.parametrize("alpha, beta, a, V, zeta", [(0.5, 2.0, 0.5, 0.3, 0.05),
                                                     (0.5, 2.0, 1.5, 0.3, 0.1)])
def test_flat_row_of_springs_is_the_single_spring(alpha, beta, a, V, zeta):
    """Springs of one gap stick, reach their static limit and slip together: a flat row of 6
    is the single spring, sample by sample."""
    d = _dim(alpha, beta, a, math.inf, zeta, 1.6)
    one = mdr_history(d, V, 3, 100, "sliding", 1)
    six = mdr_history(d, V, 3, 100, "sliding", 6)
    for name in ("x", "x_dot", "f", "n", "work_input", "dissipated_friction"):
        np.testing.assert_allclose(getattr(six, name), getattr(one, name), atol=1e-12,
                                   err_msg=name)
    assert np.any(one.phase == "stick") and np.any(one.phase == "slip+")


@pytest.mark.parametrize("s", [1.0, 1.3])
def test_a_nearly_flat_profile_approaches_the_flat_punch(s):
    """``g_i = xi_i^n`` -> 0 inside the unit radius as ``n`` grows: the row's ``mu_ratio``
    approaches the flat punch's at first order in ``1/n`` (measured: ``-0.033, -0.0085,
    -0.0021`` at ``n = 10, 40, 160``, ``s = 1``)."""
    args = (0.5, 2.0, 0.5, 0.3)
    flat = mdr_friction(*args, math.inf, zeta=0.1, static_ratio=s)["mu_ratio"]
    d = [mdr_friction(*args, n, zeta=0.1, static_ratio=s, tol=1e-4)["mu_ratio"] - flat
         for n in (10.0, 40.0, 160.0)]
    print(d)
    assert abs(d[2]) < 3e-3
    assert 3.0 < d[0] / d[1] < 5.0 and 3.0 < d[1] / d[2] < 5.0


# --------------------------------------------------------------------------- limits, API
@pytest.mark.parametrize("n", [1.0, 2.0, 4.0])
def test_zero_velocity_is_refused_above_one_and_static_at_one(n):
    """The limit ``V -> 0+`` depends on the slips' dynamics where ``s > 1`` (as for the 1-D
    solver, docs/friction_laws.md): refused by name; ``s = 1`` is the tip's static value."""
    with pytest.raises(Refusal, match="static_ratio = 1.4"):
        solve_points(0.5, 2.0, 0.5, 0.0, profile_exponent=n, static_ratio=1.4)
    for a in (0.0, 0.5, 1.5):
        r = solve_points(0.5, 2.0, a, 0.0, profile_exponent=n, static_ratio=1.0)
        assert int(r["status"]) == Status.STATIC.code
        assert float(r["mu_ratio"]) == theory.profile_static_mu_ratio(a, n)


def test_the_law_changes_the_answer_and_the_history_carries_it():
    d = _dim(0.5, 2.0, 0.5, 2.0, 0.1)
    mus = [vf.friction_coefficient(replace(d, static_ratio=s), v_inertial=0.3).mu_ratio
           for s in (1.0, 1.3, 2.0)]
    print(mus)
    assert mus[0] < mus[1] < mus[2]
    h = vf.simulate(replace(d, static_ratio=1.3), v_inertial=0.3, periods=1)
    assert h.system.static_ratio == 1.3


# --------------------------------------------------------------------------- properties
@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(al=st.floats(0.1, 3.0), dk=st.floats(0.3, 8.0), a=st.floats(0.0, 1.8),
       V=st.floats(0.05, 1.5), n=st.sampled_from([0.7, 1.0, 2.0, 3.5, math.inf]),
       zeta=st.floats(0.0, 0.5), s=st.floats(1.0, 3.0))
def test_random_rows_keep_every_spring_within_its_static_limit(al, dk, a, V, n, zeta, s):
    r = mdr_row(al, al + dk, a, V, n, 20, zeta, static_ratio=s, max_periods=1000)
    assert r["events_per_period"] >= 0  # it progressed
    # the largest k |e_i| - s n_i of the stuck springs seen at the scan points
    assert r["max_excess"] <= 1e-10
    if r["status"] != "not converged":
        assert abs(r["mu_ratio"]) <= s + r["error"]


# A point of a random self-consistency check (a cone, undamped, s = 1.87): Anderson's step
# landed on the sliding orbit, and the rows answered "periodic, 1.000000 +- 2e-12", while
# the row's own motion from the sliding start sticks, its mean about 1.06
ACCELERATED = (0.20632261832867776, 0.7830788798614823, 0.20540461732229198,
               0.5567409796149243, 1.865082630754237, 3.0)


def test_the_rows_follow_the_motion_above_the_kinetic_limit():
    """Sliding and stick-slip coexist: the rows follow the motion, not Anderson's step, and
    the answer is within its error of the mean of the row's history (periods 150 to 300)."""
    al, be, a, V, sr, n = ACCELERATED
    d = vf.Dimensionless(al, be, a, static_ratio=sr, profile_exponent=n)
    h = vf.simulate(d, v_inertial=V, periods=300, samples_per_period=200)
    late = h.tau >= 2 * math.pi * 150
    motion = np.trapezoid(h.f[late], h.tau[late]) / np.trapezoid(h.n[late], h.tau[late])
    assert motion > 1.05
    r = vf.friction_coefficient(d, v_inertial=V)
    assert math.isnan(r.mu_ratio) or abs(r.mu_ratio - motion) <= r.error + 2e-3
