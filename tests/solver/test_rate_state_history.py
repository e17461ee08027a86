"""Time histories with rate-and-state friction (``simulate`` with ``rs_a > 0``).

Checks against what does not come from the history: the steady-state solver's
``mu_ratio`` (its Newton orbit and its stated error), the energy balance (the stored energy
from the sampled state against the work and the dissipations), the independent reference
integrator of :mod:`vibrofriction_reference.friction_laws` (scipy's implicit methods on
``e`` rather than ``f/n``), the closed form of steady sliding for ``theta`` in SI units,
and the mirror ``x -> -x``.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import vibrofriction as vf
from history_checks import period_balance, section_rows
from vibrofriction.schema import Status
from vibrofriction.solver import friction_gradient
from vibrofriction_reference.friction_laws import rate_state_history as reference_history

TWO_PI = 2.0 * math.pi
BASE = {"alpha": 0.5, "beta": 2.0, "amplitude": 0.5}
LAW = {"rs_a": 0.01, "rs_b": 0.005, "rs_d_c": 0.01, "rs_v_ref": 1.0}

#: Points of each regime: (system, V); the last periodic orbits of each are compared.
POINTS = {
    "strengthening, aging": ({}, 0.5),
    "jumping, damped": ({"amplitude": 1.5, "zeta": 0.1}, 0.5),
    "slip law": ({"rs_law": "slip"}, 0.5),
    "Linker-Dieterich": ({"rs_alpha_ld": 0.3, "rs_b": 0.008}, 0.5),
    "weakening, stiff pin": ({"alpha": 4.0, "beta": 12.0, "rs_b": 0.015}, 0.6),
    "in-plane on the substrate": ({"a_x": 0.4, "phase_x": 0.7}, 0.5),
    "backwards": ({"zeta": 0.05}, -0.5),
}


def _system(**kw: float | str) -> vf.Dimensionless:
    p: dict[str, float | str] = {**BASE, **LAW}
    p.update(kw)
    return vf.Dimensionless(**p)  # type: ignore[arg-type]


def _mean_normal(amplitude: float) -> float:
    """``<n>`` over a period: ``(th + A sin th)/pi`` with flight, else 1 (closed form)."""
    if amplitude < 1.0:
        return 1.0
    th = math.acos(-1.0 / amplitude)
    return (th + amplitude * math.sin(th)) / math.pi


@pytest.mark.parametrize("name", list(POINTS))
def test_the_last_period_s_mean_force_is_the_solver_s(name: str) -> None:
    """From the steady state, the mean of ``f`` over each period (its impulse) is
    ``mu_ratio <n>`` to the solver's stated error (the history integrates at the solver's
    coarse tolerance, which that error bounds), and every period repeats it.  Below
    ``1e-10`` the stated error is no bound: at the in-plane point the solver states 1.3e-11
    and differs by 2.8e-11 from the history, which is the same at rtol 1e-7 and 1e-10."""
    kw, V = POINTS[name]
    system = _system(**kw)
    r = vf.friction_coefficient(system, v_inertial=V)
    assert r.method == "rate_state" and r.status is Status.PERIODIC and r.trusted, r.message
    h = vf.simulate(system, v_inertial=V, periods=2, initial="steady")
    assert isinstance(h, vf.RateStateHistory) and h.is_rate_state
    rows = section_rows(h)
    means = np.diff(h.impulse[rows, 0]) / TWO_PI
    nbar = _mean_normal(system.amplitude)
    print(f"{name}: history {means}, solver {r.mu_ratio * nbar:.10f} +- {r.error * nbar:.2g}")
    assert np.all(np.abs(means - r.mu_ratio * nbar) <= max(r.error, 1e-10) * nbar)
    # the impulse is the integral of the sampled f (trapezoidal rule: to its own error)
    trap = np.sum(0.5 * (h.f[1:] + h.f[:-1]) * np.diff(h.tau))
    assert trap == pytest.approx(h.impulse[-1, 0], rel=1e-3)


@pytest.mark.parametrize("name", list(POINTS))
def test_the_energy_balance_holds_period_by_period(name: str) -> None:
    """The pulled end's work equals the friction's ``int f w'`` plus the dashpot's plus the
    change of the stored energy (computed from the sampled state), each period; from the
    sliding start (a transient): to the integrator's tolerance without an in-plane
    oscillation, to the trapezoidal rule's error over 400 samples a period with one."""
    kw, V = POINTS[name]
    h = vf.simulate(_system(**kw), v_inertial=V, periods=3)
    tol = 1e-4 if h.system.a_x > 0.0 else 1e-6
    assert period_balance(h) <= tol
    assert np.all(h.dissipated_contact == 0.0)
    assert np.all(np.diff(h.dissipated_friction) >= -1e-12)  # f w' >= 0: the law is odd


def test_samples_events_and_flights() -> None:
    """The contact slips always (by the sign of ``w'``), a flight has no force, no local
    coefficient and no slip velocity, the events are the lift-offs and touch-downs on both
    sides, ``f = n local_mu`` in contact, and ``theta`` ages as ``theta' = 1`` in flight."""
    h = vf.simulate(_system(amplitude=1.5, zeta=0.1), v_inertial=0.5, periods=2)
    fl = h.phase == "flight"
    assert fl.any() and set(np.unique(h.phase)) <= {"slip+", "slip-", "flight"}
    assert np.all(h.f[fl] == 0.0) and np.all(np.isnan(h.local_mu[fl]))
    assert np.all(np.isnan(h.slip_velocity[fl, 0])) and np.all(h.slip_velocity[:, 1] == 0.0)
    c = ~fl
    np.testing.assert_allclose(h.f[c], h.n[c] * h.local_mu[c], rtol=1e-14, atol=0.0)
    assert np.all((h.phase[c] == "slip+") == (h.slip_velocity[c, 0] >= 0.0))
    kinds = [e.kind for e in h.events]
    assert kinds == ["lift-off", "touchdown"] * 2
    for e in h.events:
        at = np.flatnonzero(h.tau == e.tau)
        assert at.size == 2 and h.phase[at[0]] == e.before and h.phase[at[1]] == e.after
        assert abs(1.0 + 1.5 * math.cos(e.tau)) <= 1e-8  # n = 0 there, to the cut's 1e-9
    # in flight the aging law gives theta' = 1: theta grows by the flight's duration
    off, on = h.events[0].tau, h.events[1].tau
    i0, i1 = np.flatnonzero(h.tau == off)[1], np.flatnonzero(h.tau == on)[0]
    assert h.theta[i1] - h.theta[i0] == pytest.approx(on - off, rel=1e-6)


def test_the_mirror_image() -> None:
    """``V < 0`` is ``-V`` mirrored: ``x``, ``f``, ``local_mu``, ``w'`` change sign, theta not."""
    fwd = vf.simulate(_system(zeta=0.05), v_inertial=0.5, periods=1)
    back = vf.simulate(_system(zeta=0.05), v_inertial=-0.5, periods=1)
    np.testing.assert_array_equal(back.f, -fwd.f)
    np.testing.assert_array_equal(back.x, -fwd.x)
    np.testing.assert_array_equal(back.local_mu, -fwd.local_mu)
    np.testing.assert_array_equal(back.theta, fwd.theta)
    np.testing.assert_array_equal(back.work_input, fwd.work_input)
    assert set(back.phase) == {"slip-"}


def _compared(system: vf.Dimensionless, V: float, rtol: float, periods: int
              ) -> tuple[np.ndarray, np.ndarray]:
    """``(tau, [x', f, theta])`` of this package's history on the reference's grid."""
    h = vf.simulate(system, v_inertial=V, periods=periods, samples_per_period=40,
                    settings=vf.SolverSettings(rtol=rtol))
    keep = np.concatenate([[True], np.diff(h.tau) > 0.0])  # the state after an event
    keep &= np.isclose(np.mod(h.tau * 40 / TWO_PI + 0.5, 1.0), 0.5, atol=1e-9)
    return h.tau[keep], np.stack([h.x_dot[keep], h.f[keep], h.theta[keep]])


@pytest.mark.parametrize("kw", [{}, {"amplitude": 0.8, "rs_law": "slip", "zeta": 0.1},
                                {"rs_alpha_ld": 0.3, "rs_b": 0.008}],
                         ids=["aging", "slip law, damped", "Linker-Dieterich"])
def test_agrees_with_the_independent_reference(kw: dict[str, float | str]) -> None:
    """The transient from steady sliding against the reference's scipy integration, at 40
    samples a period over 2 periods: within the two integrations' errors, each estimated by
    the largest change from a loose to a tight tolerance along the run (this package: rtol
    1e-7 to 1e-9; the reference: rtol 1e-7 to 1e-8), twice, relative to each sample's size."""
    system = _system(**kw)
    V = 0.5
    tau, ours = _compared(system, V, 1e-9, 2)
    _, ours_loose = _compared(system, V, 1e-7, 2)
    args = (system.alpha, system.beta, system.amplitude, V, system.rs_a, system.rs_b,
            system.rs_d_c, system.rs_v_ref)
    opts = {"alpha_ld": system.rs_alpha_ld, "law": system.rs_law, "zeta": system.zeta,
            "periods": 2, "points_per_period": 40}
    ref = reference_history(*args, **opts, rtol=1e-8, atol=1e-10)  # type: ignore[arg-type]
    ref_loose = reference_history(*args, **opts, rtol=1e-7, atol=1e-9)  # type: ignore[arg-type]
    np.testing.assert_allclose(ref.tau, tau, rtol=0.0, atol=1e-12)
    theirs = np.stack([ref.xdot, ref.f, ref.theta])
    theirs_loose = np.stack([ref_loose.xdot, ref_loose.f, ref_loose.theta])
    scale = 1.0 + np.abs(theirs)  # theta spans decades: each sample relative to its size

    def worst(a: np.ndarray, b: np.ndarray) -> np.ndarray:
        return np.max(np.abs(a - b) / scale, axis=1)

    # each quantity's bar: the errors along the run (they accumulate), not sample by sample
    bar = 2.0 * (worst(ours, ours_loose) + worst(theirs, theirs_loose)) + 1e-12
    gap = worst(ours, theirs)
    print(f"worst |difference| (relative) of x', f, theta: {gap}, bars {bar}")
    assert np.all(gap <= bar)


def test_a_physical_system_s_theta_starts_at_d_c_over_v0() -> None:
    """The start is steady sliding at ``v0``: ``theta = d_c/v0`` in seconds (``theta/omega``)
    and the local coefficient ``mu_ss(v0)/mu_star`` (the closed form of steady sliding)."""
    law = vf.RateAndState(a=0.01, b=0.015, d_c=1e-6, v_ref=1e-3)
    phys = vf.Physical(mass=0.01, k_x=2.5e5, k_xc=2e5, k_zc=2.5e5, u_z0=4e-6, du_z=2e-6,
                       omega=6283.0, mu0=0.6, friction=law)
    v0 = 2e-3
    h = vf.simulate(phys, v0=v0, periods=0.5)
    assert h.theta[0] / phys.omega == pytest.approx(law.d_c / v0, rel=1e-12)
    # n = 1 before the oscillation, then the local coefficient as n = 1 + A at tau = 0
    mu_ss = law.a * math.asinh(v0 / (2 * law.v_ref)
                               * math.exp((0.6 + law.b * math.log(law.v_ref / v0)) / law.a))
    assert h.local_mu[0] * h.n[0] == pytest.approx(mu_ss / 0.6, rel=1e-12)
    assert h.time(phys)[-1] == pytest.approx(0.5 * TWO_PI / phys.omega)


def test_starts_and_refusals() -> None:
    """A section state has no theta: refused by name, as a rest start; the rate-and-state
    solver's refusals apply; friction_gradient stays refused (no sensitivities)."""
    system = _system()
    state = vf.simulate(system, v_inertial=0.5, periods=1).final_state
    assert state is not None
    for initial in ("rest", state):
        with pytest.raises(ValueError, match="initial='sliding' or 'steady'") as err:
            vf.simulate(system, v_inertial=0.5, periods=1, initial=initial)
        assert getattr(err.value, "parameter", None) == "initial"
    with pytest.raises(ValueError, match="v_inertial = 0"):
        vf.simulate(system, v_inertial=0.0, periods=1)
    with pytest.raises(ValueError, match="rs_a"):
        vf.simulate(_system(a_y=0.3), v_inertial=0.5, periods=1)
    with pytest.raises(ValueError, match="friction_gradient .*rs_a"):
        friction_gradient(system, v_inertial=0.5)


def test_the_history_converts_to_tables() -> None:
    h = vf.simulate(_system(), v_inertial=0.5, periods=0.5, samples_per_period=20)
    ds = h.to_xarray()
    assert ds.theta.attrs["units"] == "1 / omega" and ds.local_mu.dims == ("sample",)
    df = h.to_dataframe()
    assert {"theta", "local_mu", "slip_velocity_x", "impulse_x"} <= set(df.columns)
    assert "RateStateHistory (the rate-and-state solver)" in repr(h)
