"""The exact solver with a longitudinal in-plane oscillation (issue 20), against physics
it does not contain.

* differential: the solver against the independent reference integrator
  ``vibrofriction_reference.inplane_mean`` (solve_ivp, no shared code) at the points of
  ``tests/data/inplane_reference.json`` (every regime: substrate and holder, several
  phases, stick-slip, jumping, grazing, damped, near both resonances, pure longitudinal,
  ``V < 0``), cached by ``tests/data/make_inplane_reference.py``;
* continuous sliding exactly above ``theory.inplane_critical_velocity`` (a closed form
  checked against its own integration in tests/theory/test_theory_inplane.py) and not below;
* the kinematic law of a rigid body, ``theory.kinematic_mu_longitudinal``, approached as
  the system stiffens;
* the mirror ``x -> -x`` of a backward velocity against the reference at ``V < 0``;
* ``|f| <= n`` along histories of random points;
* zero amplitude is the normal-only solver; the refusals.

The Jacobian with the in-plane force is checked in tests/kernels/test_tangent.py.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

import vibrofriction as vf
from vibrofriction import theory
from vibrofriction._kernels.codes import N_SEG_COLUMNS, N_SMP_COLUMNS, SMP_F, SMP_N
from vibrofriction._kernels.integrate import initial_point, run_periods, sample
from vibrofriction._kernels.phases import make_model
from vibrofriction._kernels.sliding import orbit_slides, sliding_orbit
from vibrofriction.schema import STATUS_BY_CODE, Status
from vibrofriction.solver import solve_points

DATA = json.loads((Path(__file__).parents[1] / "data" / "inplane_reference.json").read_text())
POINTS = DATA["points"]
#: Agreement is required within SAFETY times the combined error bar (solver's error plus
#: the reference's), plus the round-off of a mean of order 1.
SAFETY = 3.0
ROUNDOFF = 1e-12


def _solve(p: dict, **kw) -> dict:
    cols = solve_points(p["alpha"], p["beta"], p["amplitude"], p["v_inertial"], p["zeta"],
                        p["eta_c"], p["a_x"], p["phase_x"], inplane_on=p["inplane_on"], **kw)
    return {k: v[()] for k, v in cols.items()}


def _check_against_reference(points: list[dict]) -> float:
    """Assert agreement within the combined bars; returns the worst ``|diff| / bar``."""
    worst = 0.0
    for p in points:
        r = _solve(p)
        assert r["trusted"], (p["label"], STATUS_BY_CODE[int(r["status"])], r["error"])
        bar = float(r["error"]) + p["err_ref"]
        diff = abs(float(r["mu_ratio"]) - p["mu_ref"])
        assert diff <= SAFETY * bar + ROUNDOFF, (p["label"], r["mu_ratio"], p["mu_ref"], bar)
        worst = max(worst, diff / (bar + ROUNDOFF))
        print(f"{p['label']:32s} solver {float(r['mu_ratio']):+.12f} +- {float(r['error']):.1e}"
              f"  ref {p['mu_ref']:+.12f} +- {p['err_ref']:.1e}  |diff|/bar {diff / bar:.2f}")
    return worst


def test_reference_cache_covers_every_regime() -> None:
    """The cached points span what the brief asks for (the test is only as good)."""
    assert len(POINTS) >= 24
    on = {p["inplane_on"] for p in POINTS}
    assert on == {"substrate", "holder"}
    assert len({round(p["phase_x"], 6) for p in POINTS}) >= 6
    assert any(p["amplitude"] > 1.0 for p in POINTS)  # jumping
    assert any(p["amplitude"] == 0.0 for p in POINTS)  # pure longitudinal
    assert any(p["v_inertial"] < 0.0 for p in POINTS)
    assert any(p["zeta"] > 0.0 and p["eta_c"] > 0.0 for p in POINTS)
    assert any(abs(p["alpha"] - 1.0) < 0.1 for p in POINTS)  # near the system resonance
    assert any(abs(p["beta"] - 1.0) < 0.1 for p in POINTS)  # near the contact resonance
    assert any(p["stick_fraction"] > 0.3 for p in POINTS)  # stick-slip
    assert all(p["max_force_excess"] <= 1e-9 for p in POINTS)


def test_solver_agrees_with_the_independent_reference() -> None:
    worst = _check_against_reference(POINTS)
    print(f"\nworst |diff| / (err + err_ref) over {len(POINTS)} points: {worst:.3f}")


def test_backward_velocity_against_the_reference() -> None:
    """The engine's mirror at ``V < 0`` against the reference integrated at ``V < 0``."""
    backward = [p for p in POINTS if p["v_inertial"] < 0.0]
    assert len(backward) >= 4
    _check_against_reference(backward)
    for p in backward:  # a backward sliding body is pulled back: the mean force is negative
        assert _solve(p)["mu_ratio"] < 0.0


def test_backward_final_state_continues_the_orbit() -> None:
    """The final state of a ``V < 0`` result (laboratory frame, mirrored on the way out)
    fed back as the start (mirrored on the way in) is on the orbit: the same mean at once."""
    system = vf.Dimensionless(0.5, 2.0, 0.5, 0.05, 0.1, a_x=0.5, phase_x=1.0)
    first = vf.friction_coefficient(system, v_inertial=-0.3)
    assert first.trusted and first.mu_ratio < 0.0
    again = vf.friction_coefficient(system, v_inertial=-0.3, initial=first.final_state)
    assert again.trusted
    assert abs(again.mu_ratio - first.mu_ratio) <= first.error + again.error + 1e-12
    assert again.settling_periods <= 1


# --------------------------------------------------------------------------- continuous sliding
SLIDING_SYSTEMS = [  # (alpha, beta, a, zeta, eta_c, a_x)
    (0.5, 2.0, 0.5, 0.05, 0.1, 0.5),
    (0.3, 3.0, 0.8, 0.02, 0.0, 0.4),
    (3.0, math.inf, 0.5, 0.1, 0.0, 0.5),
    (2.0, 10.0, 0.0, 0.1, 0.05, 0.6),  # pure longitudinal
]
PHASES = (0.0, 1.0, 2.5, 4.0)


@pytest.mark.parametrize("on", ["substrate", "holder"])
@pytest.mark.parametrize("system", SLIDING_SYSTEMS, ids=lambda s: f"{s}")
def test_sliding_orbit_slides_exactly_above_the_critical_velocity(system, on) -> None:
    """The kernel's sliding orbit (slip velocity ``V`` plus the responses to ``n`` and
    ``h``) keeps its contact point moving iff ``V > V_c`` of the closed form: checked at
    ``V_c (1 +- 1e-6)``."""
    alpha, beta, a, zeta, eta, a_x = system
    for phase in PHASES:
        vc = float(theory.inplane_critical_velocity(alpha, beta, a, a_x, phase, zeta, eta, on))
        assert vc > 1e-3
        for factor, slides in ((1.0 + 1e-6, True), (1.0 - 1e-6, False)):
            M = make_model(alpha, beta, a, vc * factor, zeta, eta, a_x, phase, on == "substrate")
            assert orbit_slides(M, *sliding_orbit(M)) is slides, (phase, factor, vc)


@pytest.mark.parametrize("on", ["substrate", "holder"])
def test_mu_is_one_above_the_critical_velocity_and_below_one_under_it(on) -> None:
    alpha, beta, a, zeta, eta, a_x = SLIDING_SYSTEMS[0]
    for phase in PHASES:
        vc = float(theory.inplane_critical_velocity(alpha, beta, a, a_x, phase, zeta, eta, on))
        system = vf.Dimensionless(alpha, beta, a, zeta, eta, a_x, phase, inplane_on=on)
        above = vf.friction_coefficient(system, v_inertial=1.01 * vc)
        assert above.status == Status.SLIDING and above.mu_ratio == 1.0 and above.error == 0.0
        below = vf.friction_coefficient(system, v_inertial=0.95 * vc)
        assert below.trusted and below.status != Status.SLIDING
        assert below.mu_ratio < 1.0 - below.error
        # backward: the mirror needs |V| above V_c at phase_x + pi
        vb = float(theory.inplane_critical_velocity(alpha, beta, a, a_x, phase + math.pi, zeta,
                                                    eta, on))
        back = vf.friction_coefficient(system, v_inertial=-1.01 * vb)
        assert back.status == Status.SLIDING and back.mu_ratio == -1.0


# --------------------------------------------------------------------------- kinematic limit
@pytest.mark.parametrize("beta_over_alpha", [2.0, math.inf], ids=["elastic", "rigid"])
def test_kinematic_law_is_approached_as_the_system_stiffens(beta_over_alpha) -> None:
    """``a = 0``, substrate: a body held by a stiff, well-damped pin moves at ``V`` and the
    mean friction tends to ``(2/pi) arcsin(V/a_x)`` (docs/inplane.md, section 1)."""
    a_x = 5.0
    for V in (1.25, 2.5, 3.75):
        law = float(theory.kinematic_mu_longitudinal(V, a_x))
        dist = []
        for S in (100.0, 400.0, 1600.0):
            r = vf.friction_coefficient(vf.Dimensionless(S, S * beta_over_alpha, 0.0, 0.7, 0.0,
                                                         a_x, 0.3), v_inertial=V)
            assert r.trusted, (S, V, r.message)
            dist.append(abs(r.mu_ratio - law))
        print(f"V/a_x = {V / a_x}: |mu - law| = {dist}")
        # at least linear in 1/S (an elastic contact's reversals take up 2/k; a rigid
        # contact's at once, the pin's transients decaying within each half period)
        assert dist[1] <= 0.5 * dist[0] + 1e-12 and dist[2] <= 0.5 * dist[1] + 1e-12
        assert dist[2] < 1e-4


# --------------------------------------------------------------------------- |f| <= n
def test_contact_force_stays_in_the_cone_along_histories() -> None:
    rng = np.random.default_rng(2020)
    periods, per = 6, 300
    worst = -math.inf
    for _ in range(40):
        alpha = 10.0 ** rng.uniform(-1.5, 1.0)
        beta = math.inf if rng.random() < 0.2 else alpha + 10.0 ** rng.uniform(-1.0, 2.5)
        a = rng.uniform(0.0, 2.0)
        V = 10.0 ** rng.uniform(-2.0, 0.3)
        zeta = rng.choice([0.0, 0.05, 1.2])
        eta = rng.choice([0.0, 0.2])
        a_x = rng.uniform(0.0, 2.0)
        phase = rng.uniform(0.0, 2.0 * math.pi)
        on = bool(rng.random() < 0.5)
        args = (alpha, beta, a, V, zeta, eta, a_x, phase, on, 1.0)  # static_ratio 1
        y, xd, e, ph, ed = initial_point(0, *args)
        seg = np.zeros((200_000, N_SEG_COLUMNS))
        m = run_periods(0.0, y, xd, e, ed, ph, *args, periods, seg.shape[0], seg)
        assert m > 0
        taus = np.linspace(0.0, 2.0 * math.pi * periods, periods * per + 1)
        out = np.empty((taus.size, N_SMP_COLUMNS))
        sample(seg, m, *args, taus, out)
        excess = np.abs(out[:, SMP_F]) - out[:, SMP_N]
        worst = max(worst, float(excess.max()))
        assert np.all(excess <= 1e-9), (args, float(excess.max()))
    print(f"largest |f| - n over 40 histories: {worst:.1e}")


# --------------------------------------------------------------------------- energy
@pytest.mark.parametrize("on", ["substrate", "holder"])
@pytest.mark.parametrize("p, zeta, eta", [((0.5, 2.0, 0.5, 0.3), 0.05, 0.2),
                                          ((0.3, 2.0, 1.5, 0.4), 0.1, 0.0),
                                          ((2.0, math.inf, 0.5, 0.3), 0.2, 0.0),
                                          ((0.3, 1.05, 0.5, 0.1), 0.05, 0.0)])
def test_energy_balance_with_inplane_oscillation(p, zeta, eta, on):
    """Work of the pulled end and of the substrate = change of stored energy + pin,
    contact and friction dissipation at every sample, in the laboratory frame."""
    al, be, a, V = p
    s = vf.Dimensionless(al, be, a, zeta, eta, 0.6, 1.1, inplane_on=on)
    h = vf.simulate(s, v_inertial=V, periods=3.0, samples_per_period=200)
    lhs = h.work_input - h.dissipated_pin - h.dissipated_contact - h.dissipated_friction
    rhs = h.stored_energy() - h.stored_energy()[0]
    scale = np.max(np.abs(h.work_input)) + np.max(np.abs(h.stored_energy()))
    assert np.max(np.abs(lhs - rhs)) <= 1e-7 * scale
    assert h.dissipated_friction[-1] >= -1e-12 * scale
    # the solver's final state (laboratory frame) starts the history where it left off
    r = vf.friction_coefficient(s, v_inertial=V)
    h2 = vf.simulate(s, v_inertial=V, periods=1.0, samples_per_period=4000, initial="steady")
    assert abs(h2.x_dot[0] - r.final_state.x_dot) < 1e-12 * (1.0 + abs(h2.x_dot[0]))


# --------------------------------------------------------------------------- zero amplitude
def test_zero_amplitude_is_the_normal_only_solver() -> None:
    """With ``a_x = 0`` the phase and the mode change nothing, bit for bit; and ``V < 0``
    is the mirror of ``V > 0`` exactly (``h = 0``, ``n`` even)."""
    V = np.array([0.05, 0.3, 1.0])
    base = solve_points(0.5, 2.0, 0.8, V, 0.02, 0.1)
    for kw in ({"phase_x": 1.3}, {"phase_x": 2.0, "inplane_on": "holder"}):
        other = solve_points(0.5, 2.0, 0.8, V, 0.02, 0.1, **kw)
        for k in ("mu_ratio", "error", "y", "x_dot", "f", "e", "status", "periods"):
            np.testing.assert_array_equal(other[k], base[k])
    back = solve_points(0.5, 2.0, 0.8, -V, 0.02, 0.1)
    np.testing.assert_array_equal(back["mu_ratio"], -base["mu_ratio"])
    np.testing.assert_array_equal(back["x_dot"], -base["x_dot"])


# --------------------------------------------------------------------------- refusals
def test_zero_velocity_without_inplane_oscillation_is_the_static_limit() -> None:
    """``V = 0``, ``a_x = 0``: eq. (2) as before, also next to a point with ``a_x > 0``
    (integrated: tests/inplane/test_inplane_vzero.py)."""
    r = solve_points(0.5, 2.0, 0.5, 0.0)
    assert r["status"] == Status.STATIC.code and r["mu_ratio"] == 0.5
    r = solve_points(0.5, 2.0, 0.5, 0.0, a_x=[0.0, 0.5])
    assert r["status"][0] == Status.STATIC.code and r["mu_ratio"][0] == 0.5
    assert r["status"][1] != Status.STATIC.code


def test_inplane_on_is_a_checked_choice() -> None:
    for call in (lambda: vf.Dimensionless(0.5, 2.0, 0.5, inplane_on="pin"),
                 lambda: solve_points(0.5, 2.0, 0.5, 0.1, inplane_on="pin"),
                 lambda: theory.inplane_critical_velocity(0.5, 2.0, 0.5, 0.1, 0.0,
                                                          inplane_on="pin")):
        with pytest.raises(ValueError, match="inplane_on must be one of 'substrate', 'holder', "
                                             "got 'pin'"):
            call()
    with pytest.raises(ValueError, match="a_x must be finite and >= 0"):
        vf.Dimensionless(0.5, 2.0, 0.5, a_x=-0.1)
    with pytest.raises(ValueError, match="phase_x must be finite"):
        solve_points(0.5, 2.0, 0.5, 0.1, phase_x=math.inf)
