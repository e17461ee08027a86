"""Time histories with a transverse oscillation (``simulate`` with ``a_y > 0``, issue 20
item 4), against what they must obey and against the independent reference:

* a steady history's mean ``<f_x>/<n>`` and ``<f_y>/<n>`` over its periods is the 2-D
  solver's ``mu_ratio`` and ``lateral_ratio`` within their error;
* ``|f| <= n`` at every sample; in slip ``f`` is parallel to the contact point's velocity
  relative to the substrate (and points along it), in stick that velocity is 0;
* a short history from the sliding start agrees with ``vibrofriction_reference.inplane_run``
  (DOP853 of scipy, no shared code): the per-period means of ``f_x``, ``f_y`` and the state
  at the end, and its work and dissipation per period (the reference's definitions);
* the energy balance per period, to the trapezoidal rule's second order in the spacing;
* ``a_y -> 0`` is the exact 1-D history (closed forms) at the common sample times.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import vibrofriction as vf
from history_checks import period_balance, section_rows
from vibrofriction.params import Dimensionless
from vibrofriction_reference import inplane_run

TWO_PI = 2.0 * math.pi

# (label, system, V): Kelvin-Voigt and Jenkins contacts, substrate and holder, jumping,
# damping, combined drives, V < 0
POINTS = [
    ("KV transverse substrate", Dimensionless(0.5, 2.0, 0.5, eta_c=0.1, a_y=0.5,
                                              phase_y=0.3), 0.3),
    ("Jenkins jumping holder", Dimensionless(0.5, 2.0, 1.5, zeta=0.05, a_y=0.4, a_x=0.3,
                                             phase_x=1.0, inplane_on="holder"), 0.6),
    ("KV combined V < 0", Dimensionless(0.5, 2.0, 0.5, zeta=0.05, eta_c=0.2, a_x=0.5,
                                        phase_x=math.pi / 2, a_y=0.3, phase_y=-0.7), -0.2),
    ("KV anisotropic pin holder", Dimensionless(0.5, 2.0, 0.5, zeta=0.05, eta_c=0.1, a_y=0.5,
                                                phase_y=1.0, alpha_y=1.5, zeta_y=0.2,
                                                inplane_on="holder"), 0.3),
]
IDS = [p[0] for p in POINTS]


def _mean_n(a: float) -> float:
    """``<max(0, 1 + a cos tau)>`` over a period (the contact opens at ``cos = -1/a``)."""
    if a <= 1.0:
        return 1.0
    th = math.acos(-1.0 / a)
    return (th + a * math.sin(th)) / math.pi


@pytest.fixture(scope="module", params=POINTS, ids=IDS)
def steady(request):
    label, d, V = request.param
    return d, V, vf.simulate(d, v_inertial=V, periods=2, initial="steady",
                             samples_per_period=300)


def test_steady_means_are_the_solvers(steady) -> None:
    d, V, h = steady
    r = vf.friction_coefficient(d, v_inertial=V)
    assert r.trusted
    rows = section_rows(h)
    span = TWO_PI * (len(rows) - 1)
    mean_n = _mean_n(d.amplitude) * span
    mu = (h.impulse[rows[-1], 0] - h.impulse[rows[0], 0]) / mean_n
    lat = (h.impulse[rows[-1], 1] - h.impulse[rows[0], 1]) / mean_n
    print(f"mu {mu:.10f} vs {r.mu_ratio:.10f}, lateral {lat:.10f} vs {r.lateral_ratio:.10f}"
          f" (error {r.error:.1e})")
    assert abs(mu - r.mu_ratio) <= 3.0 * r.error + 1e-10
    assert abs(lat - r.lateral_ratio) <= 3.0 * r.error + 1e-10
    # one period of the orbit after another: the section state repeats
    first = np.r_[h.x[rows[0]] - V * h.tau[rows[0]], h.u_y[rows[0]], h.x_dot[rows[0]],
                  h.u_y_dot[rows[0]]]
    np.testing.assert_allclose(h.plane_state[:4], first, atol=1e-6)
    # and the sampled trapezoidal mean of f_x agrees to the rule's accuracy
    trap = np.sum(0.5 * (h.f[1:] + h.f[:-1]) * np.diff(h.tau)) / mean_n
    assert abs(trap - r.mu_ratio) < 1e-3


def test_force_in_the_cone_and_along_the_slip(steady) -> None:
    d, V, h = steady
    fmag = np.hypot(h.f, h.f_y)
    assert np.all(fmag <= h.n * (1.0 + 1e-9) + 1e-12)
    slip = np.char.startswith(h.phase, "slip")
    stick = h.phase == "stick"
    assert slip.any() and stick.any()
    s = h.slip_velocity
    smag = np.hypot(s[:, 0], s[:, 1])
    assert np.all(smag[stick] <= 1e-9)
    moving = slip & (smag > 1e-6)
    assert moving.sum() > 20
    # in slip |f| = n, and f is along the slip velocity (friction on the substrate's
    # side: the force on the body, -f, opposes the contact point's slip)
    np.testing.assert_allclose(fmag[moving], h.n[moving], rtol=1e-9, atol=1e-12)
    cos = (h.f * s[:, 0] + h.f_y * s[:, 1])[moving] / (fmag * smag)[moving]
    np.testing.assert_allclose(cos, 1.0, atol=1e-8)
    # slip+ / slip- follow the sign of f_x
    assert np.all(h.f[h.phase == "slip+"] >= 0.0)
    assert np.all(h.f[h.phase == "slip-"] < 0.0)


def test_events_sit_between_their_phases(steady) -> None:
    d, V, h = steady
    assert h.events
    for ev in h.events:
        at = np.flatnonzero(h.tau == ev.tau)
        assert len(at) >= 2
        assert h.phase[at[0]] == ev.before and h.phase[at[1]] == ev.after
        if ev.kind == "stick->slip":
            assert ev.before == "stick" and ev.after.startswith("slip")
        if ev.kind in ("lift-off", "touchdown"):
            assert "flight" in (ev.before, ev.after)
    # between events the phase does not change
    change = np.flatnonzero(h.phase[1:] != h.phase[:-1])
    ev_tau = {ev.tau for ev in h.events}
    assert all(h.tau[j] in ev_tau for j in change)


@pytest.mark.parametrize("label,d,V", POINTS, ids=IDS)
def test_agrees_with_the_reference(label: str, d: Dimensionless, V: float) -> None:
    n_per = 3
    h = vf.simulate(d, v_inertial=V, periods=n_per, samples_per_period=400)
    ref = inplane_run(d.alpha, d.beta, d.amplitude, V, 0, n_per, zeta=d.zeta,
                      eta_c=d.eta_c, a_x=d.a_x, phase_x=d.phase_x, a_y=d.a_y,
                      phase_y=d.phase_y, alpha_y=d.alpha_y, zeta_y=d.zeta_y,
                      inplane_on=d.inplane_on)
    rows = section_rows(h)
    per_fx = np.diff(h.impulse[rows, 0]) / TWO_PI
    per_fy = np.diff(h.impulse[rows, 1]) / TWO_PI
    print(label, np.max(np.abs(per_fx - ref.period_fx)), np.max(np.abs(per_fy - ref.period_fy)))
    np.testing.assert_allclose(per_fx, ref.period_fx, atol=1e-7)
    np.testing.assert_allclose(per_fy, ref.period_fy, atol=1e-7)
    # the state at the end: (tau, u_x, u_y, v_x, v_y, f_x, f_y)
    r = rows[-1]
    mine = (h.tau[r], h.x[r], h.u_y[r], h.x_dot[r], h.u_y_dot[r], h.f[r], h.f_y[r])
    np.testing.assert_allclose(mine, ref.final_state, atol=1e-6)
    # work and dissipation per period, the reference's definitions (its integrals are
    # state variables; ours the trapezoidal rule over 400 samples a period)
    work = np.diff(h.work_input[rows])
    diss = np.diff((h.dissipated_pin + h.dissipated_contact + h.dissipated_friction)[rows])
    scale = np.maximum(np.abs(ref.period_work), 1e-3)
    assert np.all(np.abs(work - ref.period_work) / scale < 1e-3)
    assert np.all(np.abs(diss - ref.period_dissipation) / scale < 1e-3)


@pytest.mark.parametrize("label,d,V", POINTS, ids=IDS)
def test_energy_balance_per_period(label: str, d: Dimensionless, V: float) -> None:
    coarse = period_balance(vf.simulate(d, v_inertial=V, periods=2, samples_per_period=200))
    fine = period_balance(vf.simulate(d, v_inertial=V, periods=2, samples_per_period=800))
    print(label, coarse, fine)
    assert fine < 1e-4
    assert fine < coarse / 6.0  # second order: 16 times smaller, up to the events' kinks
    for k in ("dissipated_pin", "dissipated_contact", "dissipated_friction"):
        assert np.all(np.diff(getattr(vf.simulate(d, v_inertial=V, periods=1), k)) >= -1e-12)


def test_vanishing_transverse_amplitude_is_the_exact_1d_history() -> None:
    base = dict(alpha=0.5, beta=2.0, amplitude=0.5, eta_c=0.1, a_x=0.4, phase_x=0.8)
    h1 = vf.simulate(Dimensionless(**base), v_inertial=0.3, periods=2)
    h2 = vf.simulate(Dimensionless(**base, a_y=1e-10), v_inertial=0.3, periods=2)
    assert type(h1) is vf.History and isinstance(h2, vf.PlaneHistory)
    grid = np.linspace(0.0, 2 * TWO_PI, 801)
    i1 = np.searchsorted(h1.tau, grid)
    i2 = np.searchsorted(h2.tau, grid)
    assert np.array_equal(h1.tau[i1], grid) and np.array_equal(h2.tau[i2], grid)
    for k in ("x", "x_dot", "f", "n", "e"):
        np.testing.assert_allclose(getattr(h2, k)[i2], getattr(h1, k)[i1], atol=1e-7,
                                   err_msg=k)
    assert np.max(np.abs(h2.f_y)) < 1e-8
    assert [e.kind for e in h1.events] == [e.kind for e in h2.events]
    np.testing.assert_allclose([e.tau for e in h2.events], [e.tau for e in h1.events],
                               atol=1e-7)
    # the contact point: 1-D x_c and the 2-D one agree
    np.testing.assert_allclose(h2.contact_point()[0][i2], h1.contact_point()[0][i1],
                               atol=1e-7)


def test_plane_state_continues_a_history() -> None:
    d, V = POINTS[0][1], POINTS[0][2]
    whole = vf.simulate(d, v_inertial=V, periods=2)
    first = vf.simulate(d, v_inertial=V, periods=1)
    second = vf.simulate(d, v_inertial=V, periods=1, initial=first.plane_state)
    r = section_rows(whole)[-1]
    np.testing.assert_allclose(second.f_y[-1], whole.f_y[r], atol=1e-8)
    np.testing.assert_allclose(second.x[-1] + V * TWO_PI, whole.x[r], atol=1e-8)


def test_every_period_count_ends_on_its_section() -> None:
    """A history of any whole number of periods ends on its last section: the kernel's
    period ends are the grid's section times, to the last bit (1 + ... + 1 periods summed
    in floating point missed the section at 730 and 1140 periods of this static-law point,
    and the history had no final state)."""
    d = Dimensionless(1.025744332849627, 1.575480500380936, 0.5555301555141661,
                      a_y=0.2148720847692363, phase_y=0.09928158932083511,
                      static_ratio=1.9224187633970171)
    for periods in (730, 1140):
        h = vf.simulate(d, v_inertial=0.10115672805167288, periods=periods,
                        samples_per_period=2, initial="rest")
        assert h.tau[-1] == 2.0 * math.pi * periods
        assert np.all(np.isfinite(h.plane_state))


def test_refusals() -> None:
    with pytest.raises(ValueError, match="finite beta"):
        vf.simulate(Dimensionless(0.5, math.inf, 0.5, a_y=0.3), v_inertial=0.3)
    with pytest.raises(ValueError, match="6 finite numbers"):
        vf.simulate(Dimensionless(0.5, 2.0, 0.5, a_y=0.3), v_inertial=0.3, initial=[1.0, 2.0])
    # V = 0 is computed, but a held body has no steady state to start from
    with pytest.raises(ValueError, match="status held"):
        vf.simulate(Dimensionless(0.5, 2.0, 0.5, a_y=0.3), v_inertial=0.0, initial="steady")
