"""The rate-and-state solver (docs/friction_laws.md, "Rate-and-state friction").

Checks against what does not come from the solver: the event-driven solver in the Coulomb
limit, the closed form of steady sliding, the linear stability of steady sliding
(:mod:`vibrofriction.theory.rate_state`: the quartic's roots and the critical stiffness),
the energy balance of the orbit, and the solver itself at a much tighter tolerance for the
honesty of its stated error.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import vibrofriction as vf
from vibrofriction import theory
from vibrofriction._kernels import rate_state as rs
from vibrofriction.capabilities import RATE_STATE
from vibrofriction.schema import FLOAT_COLUMNS, INT_COLUMNS, Status, column_index
from vibrofriction.solver import friction_gradient, solve_points
from vibrofriction.theory import rate_state as trs

BASE = {"alpha": 0.5, "beta": 2.0, "amplitude": 0.5}
LAW = {"rs_a": 0.01, "rs_b": 0.005, "rs_d_c": 0.01, "rs_v_ref": 1.0}


def _system(**kw: float | str) -> vf.Dimensionless:
    p: dict[str, float | str] = {**BASE, **LAW}
    p.update(kw)
    return vf.Dimensionless(**p)  # type: ignore[arg-type]


def test_routed_to_the_rate_state_solver() -> None:
    r = vf.friction_coefficient(_system(), v_inertial=0.5)
    assert r.method == "rate_state"
    assert r.status is Status.PERIODIC and r.trusted
    assert r.period == 1 and 0.0 < r.multiplier < 1.0
    # the one-point path and the batch agree (the one-point path is not the event kernel)
    out = solve_points(v_inertial=[0.5, 0.5], **BASE, **LAW)
    assert list(out["method"]) == [3, 3]
    assert out["mu_ratio"][0] == r.mu_ratio


def test_mirror_and_sliding_value() -> None:
    fwd = vf.friction_coefficient(_system(), v_inertial=0.5)
    back = vf.friction_coefficient(_system(), v_inertial=-0.5)
    assert back.mu_ratio == -fwd.mu_ratio
    mu_ss = float(theory.steady_mu_ratio(0.5, 0.01, 0.005, 0.01, 1.0))
    assert fwd.sliding_mu_ratio == pytest.approx(mu_ss, rel=1e-14)
    assert back.sliding_mu_ratio == pytest.approx(-mu_ss, rel=1e-14)
    coulomb = vf.friction_coefficient(vf.Dimensionless(**BASE), v_inertial=0.5)
    assert coulomb.sliding_mu_ratio == 1.0
    assert solve_points(v_inertial=-0.5, **BASE)["sliding_mu_ratio"] == -1.0


def test_rigid_and_damped_contacts_are_taken() -> None:
    """A rigid contact and contact damping are the solver's (no refusal): periodic here.

    A rigid contact that sticks at a small ``a`` (here 0.01) fails honestly (``nan``, error
    ``inf``): the force drops to the holding force within a time ``~ x'/x''`` where the
    body's velocity reaches ``exp(-(mu_ss - m)/a)`` (1e-14 here), below the integrator's
    smallest step; measured periodic from ``a = 0.03`` (0.04 jumping) at this point.
    """
    for kw in ({"beta": math.inf, "rs_a": 0.05, "rs_b": 0.025}, {"eta_c": 0.1}):
        r = vf.friction_coefficient(_system(**kw), v_inertial=0.5)
        assert r.method == "rate_state" and r.status is Status.PERIODIC
    r = vf.friction_coefficient(_system(beta=math.inf), v_inertial=0.5)
    assert r.status is Status.FAILED and math.isnan(r.mu_ratio) and r.error == math.inf


def test_refuses_zero_velocity_and_other_starts() -> None:
    with pytest.raises(ValueError, match="v_inertial"):
        vf.friction_coefficient(_system(), v_inertial=0.0)
    with pytest.raises(ValueError, match="initial"):
        vf.friction_coefficient(_system(), v_inertial=0.5, initial="rest")
    with pytest.raises(ValueError, match="max_events"):
        vf.friction_coefficient(_system(), v_inertial=0.5,
                                settings=vf.SolverSettings(max_events=10))


def test_coulomb_limit() -> None:
    """``a, b -> 0`` (``b = a/2``, ``v_ref = V``): the event solver's value, the difference
    falling about linearly in ``a`` (the law's deviation from Coulomb, ``a ln(...)``)."""
    exact = vf.friction_coefficient(vf.Dimensionless(**BASE), v_inertial=0.5).mu_ratio
    diffs = []
    for a in (0.01, 0.005, 0.0025):
        r = vf.friction_coefficient(_system(rs_a=a, rs_b=a / 2, rs_v_ref=0.5), v_inertial=0.5)
        assert r.trusted
        diffs.append(abs(r.mu_ratio - exact))
    rates = [math.log2(diffs[i] / diffs[i + 1]) for i in range(2)]
    assert diffs[-1] < 0.006
    assert all(0.7 < q < 1.2 for q in rates), (diffs, rates)


@pytest.mark.parametrize("law", ["aging", "slip"])
@pytest.mark.parametrize("V", [0.05, 0.5, 3.0])
def test_zero_amplitude_stable_sliding(law: str, V: float) -> None:
    """Velocity strengthening, no oscillation: ``mu_ratio = mu_ss(V)`` to the stated error."""
    r = vf.friction_coefficient(_system(amplitude=0.0, rs_law=law), v_inertial=V)
    mu_ss = float(theory.steady_mu_ratio(V, 0.01, 0.005, 0.01, 1.0))
    assert r.status is Status.PERIODIC and r.trusted
    assert abs(r.mu_ratio - mu_ss) <= r.error
    assert r.sliding_mu_ratio == pytest.approx(mu_ss, rel=1e-14)


@pytest.mark.parametrize("factor", [1.3, 1.1, 0.9, 0.7])
def test_critical_stiffness(factor: float) -> None:
    """The onset of self-excited stick-slip at ``A = 0`` is the theory's critical stiffness:
    above it steady sliding is an attracting orbit whose multiplier is the theory's
    ``exp(2 pi max Re s)``; below it the motion leaves steady sliding (averaged, its window
    means apart from ``mu_ss``), never periodic."""
    k_c, V, a, b, dc, vref = 10.0, 0.01, 0.01, 0.02, 0.01, 1.0
    acr = trs.critical_stiffness(k_c, 0.0, V, a, b, dc, vref)
    alpha = factor * acr
    s = vf.Dimensionless(alpha=alpha, beta=alpha + k_c, amplitude=0.0, rs_a=a, rs_b=b,
                         rs_d_c=dc, rs_v_ref=vref)
    r = vf.friction_coefficient(s, v_inertial=V, settings=vf.SolverSettings(tol_mean=1e-3))
    growth = math.exp(2.0 * math.pi * max(trs.sliding_eigenvalues(
        alpha, alpha + k_c, 0.0, V, a, b, dc, vref).real))
    if factor > 1.0:
        assert r.status is Status.PERIODIC
        assert r.multiplier == pytest.approx(growth, abs=1e-5)  # the exact monodromy
        assert abs(r.mu_ratio - r.sliding_mu_ratio) <= r.error
    else:
        assert growth > 1.0
        assert r.status is not Status.PERIODIC
        assert r.status is Status.AVERAGED
        assert r.window_min < r.sliding_mu_ratio - 1e-6


def _orbit(P: np.ndarray) -> tuple[np.ndarray, int]:
    """The periodic orbit's section state (kernels' variables) and the status code."""
    z = rs.sliding_start(P, (0.0, 0.0))
    of = np.empty(len(FLOAT_COLUMNS))
    oi = np.empty(len(INT_COLUMNS), np.int64)
    rs.rs_steady_state(P, z, 1e-9, 2000, 1e-8, (0.0, 0.0), of, oi)
    return z, int(oi[column_index("status")])


@pytest.mark.parametrize("law", [0.0, 1.0])
@pytest.mark.parametrize("zeta", [0.0, 0.2])
def test_energy_balance(law: float, zeta: float) -> None:
    """Over the periodic orbit the puller's work ``V int f`` is the friction's dissipation
    ``int f w'`` plus the dashpot's ``int gamma y'^2`` (three quadratures, one integration)."""
    V = 0.5
    P = rs.make_parameters(0.5, 2.0, 0.5, V, zeta, 0.0, 0.0, True, 0.01, 0.005, 0.01, 1.0,
                           0.0, law)
    z, status = _orbit(P)
    assert status == Status.PERIODIC.code
    work = rs._workspace()
    count = np.zeros(3, np.int64)
    assert rs.rs_period(P, z, 1e-10, np.array([1e-3]), work, count)
    drive, friction, dashpot = V * z[rs.Z_F], z[rs.Z_D], z[rs.Z_G]
    assert friction > 0.0 and (dashpot > 0.0) == (zeta > 0.0)
    assert abs(drive - friction - dashpot) <= 1e-6 * drive


def test_local_force_bounded() -> None:
    """``|f| <= n |mu|`` with ``|mu|`` bounded by the law at the largest slip rate the body
    reaches: along the orbit the local coefficient stays within a few ``a`` of ``mu_ss``."""
    P = rs.make_parameters(0.5, 2.0, 0.9, 0.5, 0.0, 0.0, 0.0, True, 0.01, 0.005, 0.01, 1.0,
                           0.0, 0.0)
    z, status = _orbit(P)
    assert status == Status.PERIODIC.code
    work = rs._workspace()
    count = np.zeros(3, np.int64)
    hb = np.array([1e-3])
    ms = []
    for tau_end in np.linspace(0.0, 2 * math.pi, 17)[1:]:
        # integrate the period in pieces, watching the local coefficient m = f/n
        assert rs._segment(P, z, tau_end - 2 * math.pi / 16, tau_end, rs.CONTACT, 1e-9, hb,
                           rs._scales(P), work, count, np.empty(1), np.zeros(2, np.int64))
        ms.append(z[rs.Z_M])
    assert max(abs(m) for m in ms) < 1.2


_RNG_POINTS = [
    # alpha, beta, amplitude, V, zeta, a, b, d_c, v_ref, alpha_ld, law, a_x
    (0.5, 2.0, 0.5, 0.5, 0.0, 0.01, 0.005, 0.01, 1.0, 0.0, "aging", 0.0),
    (0.5, 2.0, 0.7, 0.3, 0.1, 0.02, 0.03, 0.05, 0.5, 0.0, "slip", 0.0),
    (0.2, 3.0, 0.6, 1.0, 0.1, 0.01, 0.008, 0.01, 1.0, 0.3, "aging", 0.0),
    (2.0, 5.0, 0.4, 0.4, 0.05, 0.03, 0.01, 0.1, 0.2, 0.2, "slip", 0.0),
    (0.5, 2.0, 1.5, 0.5, 0.0, 0.01, 0.005, 0.01, 1.0, 0.0, "aging", 0.0),
    (0.5, 2.0, 1.3, 0.8, 0.1, 0.02, 0.01, 0.02, 1.0, 0.0, "slip", 0.0),
    (0.5, 2.0, 0.3, 0.5, 0.0, 0.01, 0.005, 0.01, 1.0, 0.0, "aging", 0.2),
]


@pytest.mark.parametrize("point", _RNG_POINTS)
def test_error_is_honest(point: tuple) -> None:
    """The stated error bounds the distance to the same point at ``rtol = 1e-11`` (both
    laws, coupling on and off, damping, jumping, an in-plane drive)."""
    al, be, am, V, ze, a, b, dc, vr, ld, law, ax = point
    s = vf.Dimensionless(alpha=al, beta=be, amplitude=am, zeta=ze, a_x=ax, rs_a=a, rs_b=b,
                         rs_d_c=dc, rs_v_ref=vr, rs_alpha_ld=ld, rs_law=law)
    r = vf.friction_coefficient(s, v_inertial=V)
    tight = vf.friction_coefficient(s, v_inertial=V, settings=vf.SolverSettings(rtol=1e-11))
    assert r.status is Status.PERIODIC and r.trusted
    assert tight.status is Status.PERIODIC
    assert abs(r.mu_ratio - tight.mu_ratio) <= r.error + tight.error
    assert abs(r.mu_ratio - tight.mu_ratio) <= r.error


def test_laws_and_coupling_matter() -> None:
    """The slip law, the Linker-Dieterich coupling and the pin's damping each change the
    answer by more than the errors (they are read)."""
    ref = vf.friction_coefficient(_system(rs_b=0.01), v_inertial=0.5)
    for kw in ({"rs_law": "slip"}, {"rs_alpha_ld": 0.3}, {"zeta": 0.2}):
        r = vf.friction_coefficient(_system(rs_b=0.01, **kw), v_inertial=0.5)  # type: ignore[arg-type]
        assert abs(r.mu_ratio - ref.mu_ratio) > 10.0 * (r.error + ref.error), kw


def test_unlocked_response_is_averaged_with_an_honest_error() -> None:
    """With the Linker-Dieterich coupling near a neutral mode the response is not locked to
    the drive: averaged (never periodic), and the answers at two tolerances agree within
    their stated errors (the range of the last three windows' means; it is 1.2e-4 to
    1.4e-4 here, hence ``tol_mean = 2e-4``)."""
    s = _system(alpha=0.2, beta=3.0, amplitude=0.6, rs_b=0.008, rs_d_c=0.02, rs_alpha_ld=0.3)
    rs_ = [vf.friction_coefficient(s, v_inertial=1.0,
                                   settings=vf.SolverSettings(rtol=rtol, tol_mean=2e-4))
           for rtol in (1e-7, 1e-9)]
    for r in rs_:
        assert r.status is Status.AVERAGED and r.period == 0
        assert r.window_min <= r.mu_ratio <= r.window_max
    assert abs(rs_[0].mu_ratio - rs_[1].mu_ratio) <= rs_[0].error + rs_[1].error


def test_gradients_are_refused_not_coulomb() -> None:
    """The rate-and-state solver declares histories (tests/solver/test_rate_state_history.py)
    and no sensitivities: friction_gradient refuses such a point by name instead of running
    the Coulomb kernels."""
    assert RATE_STATE.histories
    assert not RATE_STATE.sensitivities
    assert isinstance(vf.simulate(_system(), v_inertial=0.5, periods=1), vf.RateStateHistory)
    with pytest.raises(ValueError, match="friction_gradient .*rs_a"):
        friction_gradient(_system(), v_inertial=0.5)


def test_unstable_steady_sliding_without_oscillation_is_never_periodic() -> None:
    """Without oscillation, a periodic answer is steady sliding: only where theory's Hurwitz
    conditions make it stable (a slow growth the finite-difference multiplier missed,
    0.968 against exp(2 pi Re s) = 1.033 at V = 0.79, is not converged, not periodic)."""
    V = np.array([0.3, 0.45, 0.6, 0.7924465962305569])
    out = solve_points(0.2, 10.0, 0.0, V, rs_a=0.03, rs_b=0.05, rs_d_c=1.0, rs_v_ref=1.0)
    stable = [theory.sliding_is_stable(0.2, 10.0, 0.0, v, 0.03, 0.05, 1.0, 1.0) for v in V]
    assert stable[0] and not stable[-1]
    for v, s, status in zip(V, stable, out["status"], strict=True):
        assert (status == Status.PERIODIC.code) <= s, v


@pytest.mark.parametrize("law", [0.0, 1.0])
@pytest.mark.parametrize("ald", [0.0, 0.3])
def test_the_finite_contacts_written_out_law_is_the_state_rate(law: float, ald: float) -> None:
    """The finite contact's right-hand side writes the state's law out (for speed); the
    rigid and damped contacts call :func:`_state_rate`.  At random states both give the
    same ``L'`` and the same derivatives in the Jacobian."""
    rng = np.random.default_rng(11)
    for _ in range(20):
        a = 10 ** rng.uniform(-2.3, -1.3)
        P = rs.make_parameters(0.5, 2.0, rng.uniform(0, 0.9), 0.5, 0.0, 0.0, 0.0, True, a,
                               a * rng.uniform(0.2, 1.6), 10 ** rng.uniform(-2.5, -0.5),
                               10 ** rng.uniform(-1, 0.5), ald, law)
        tau = rng.uniform(0, 2 * math.pi)
        z = np.zeros(rs.NZ)
        z[rs.Z_Y], z[rs.Z_V] = rng.normal(), rng.uniform(-1, 2)
        z[rs.Z_M], z[rs.Z_L] = rng.uniform(-1.2, 1.2), rng.uniform(-6, 2)
        dz, J, ft = np.empty(rs.NZ), np.empty((rs.NZ, rs.NM)), np.empty(rs.NZ)
        rs._evaluate(P, tau, z, rs.CONTACT, dz, J, ft, True)
        n = 1.0 + P[rs.P_A] * math.cos(tau)
        nd = -P[rs.P_A] * math.sin(tau)
        w, wm, wL = rs._slip_rate(P, z[rs.Z_M], z[rs.Z_L])
        rate, dw, dL = rs._state_rate(P, w, z[rs.Z_L], n, nd)
        assert dz[rs.Z_L] == pytest.approx(rate, rel=1e-13, abs=1e-13)
        assert J[rs.Z_L, rs.Z_M] == pytest.approx(dw * wm, rel=1e-13, abs=1e-13)
        assert J[rs.Z_L, rs.Z_L] == pytest.approx(dL + dw * wL, rel=1e-13, abs=1e-13)
        assert ft[rs.Z_L] == pytest.approx(rs._coupling_rate(P, tau), rel=1e-13, abs=1e-13)


def test_a_weakening_contact_that_diverges_fails_and_says_why() -> None:
    """A rigid weakening contact where the slip rate diverges in the first periods (seed
    2017's point 31 of the differential campaign; the independent reference's implicit
    integrator stops there too): ``failed``, not trusted, no value, and the message names the
    finite-time divergence; a strengthening contact's failure would not (the caveat needs
    ``rs_b > rs_a``)."""
    s = vf.Dimensionless(alpha=0.8702709685073428, beta=math.inf,
                         amplitude=0.9058626119117343, zeta=0.02084081229542702,
                         rs_a=0.033276543420103936, rs_b=0.043131759368929434,
                         rs_d_c=0.013961291944808456, rs_v_ref=1.1230613123333857,
                         rs_law="aging")
    r = vf.friction_coefficient(s, v_inertial=1.8767116584434378)
    assert r.status is Status.FAILED and not r.trusted and math.isnan(r.mu_ratio)
    assert "slip rate diverging in finite time" in r.message
    ok = vf.friction_coefficient(_system(), v_inertial=0.3)
    assert "diverging" not in ok.message
