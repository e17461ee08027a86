"""A static coefficient above the kinetic one in the 1-D solver (docs/friction_laws.md)."""

from __future__ import annotations

import json
import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import vibrofriction as vf
from vibrofriction import theory
from vibrofriction._kernels.integrate import initial_state
from vibrofriction._kernels.newton import _free_dimension
from vibrofriction._kernels.period import N_ACC, advance_period
from vibrofriction._kernels.phases import make_model
from vibrofriction._kernels.tangent import period_map_tangent
from vibrofriction.schema import FLOAT_COLUMNS, INT_COLUMNS
from vibrofriction.solver import solve_points

DATA = Path(__file__).parents[1] / "data"
BASE = json.loads((DATA / "static_ratio_base.json").read_text())


def _load_maker():
    import importlib.util

    spec = importlib.util.spec_from_file_location("make_static_ratio_base",
                                                  DATA / "make_static_ratio_base.py")
    mod = importlib.util.module_from_spec(spec)
    assert spec.loader is not None
    spec.loader.exec_module(mod)
    return mod


MAKER = _load_maker()


# --------------------------------------------------------------------------- s_r = 1
#: Output columns added after the baseline was stored (not today's results to compare).
NEW_COLUMNS = {"sliding_mu_ratio"}


def _without_new(x):
    """``x`` (nested dicts of a maker's run) without the columns of :data:`NEW_COLUMNS`."""
    if isinstance(x, dict):
        return {k: _without_new(v) for k, v in x.items() if k not in NEW_COLUMNS}
    return x


def test_the_new_columns_are_the_only_ones_added_since_the_baseline():
    stored = set(BASE["results"][0]["batch"])
    assert set(FLOAT_COLUMNS) - stored == NEW_COLUMNS


@pytest.mark.parametrize("i", range(len(BASE["points"])))
def test_static_ratio_one_is_the_coulomb_solver_bit_for_bit(i):
    """``static_ratio = 1`` reproduces the outputs of the solver before the law existed
    (stored by tests/data/make_static_ratio_base.py on that code), bit for bit.
    """
    p, want = BASE["points"][i], BASE["results"][i]
    # the stored point is unchanged by a fresh draw (the maker's list is the test's)
    assert MAKER.points()[i] == p
    got = _without_new(MAKER.run_point(p))
    _assert_base(got, want)
    # and 1.0 given explicitly is the default
    kw = {k: v for k, v in p.items() if k not in ("initial", "inplane_on")}
    cols = solve_points(**kw, static_ratio=1.0, inplane_on=p["inplane_on"],
                        initial=p["initial"])
    _assert_base({k: float(cols[k]).hex() for k in FLOAT_COLUMNS if k not in NEW_COLUMNS},
                 {k: want["batch"][k] for k in FLOAT_COLUMNS if k not in NEW_COLUMNS})
    assert {k: int(cols[k]) for k in INT_COLUMNS} == {k: want["batch"][k] for k in INT_COLUMNS}


#: Columns computed since the baseline in another way, equal to round-off: the Floquet
#: multiplier in closed form (LAPACK's QR iterations before), and the settling time
#: estimated from it.
ROUND_OFF = {"multiplier": 1e-12, "settling_periods": 1e-12}


def _assert_base(got, want, key=""):
    """``got == want`` (nested dicts of hexadecimal floats, integers and names), the
    columns of :data:`ROUND_OFF` to their relative tolerance."""
    if isinstance(want, dict):
        assert isinstance(got, dict) and got.keys() == want.keys(), key
        for k in want:
            _assert_base(got[k], want[k], k)
    elif key in ROUND_OFF and isinstance(want, str) and want != got:
        assert float.fromhex(got) == pytest.approx(float.fromhex(want), rel=ROUND_OFF[key]), key
    else:
        assert got == want, key


@pytest.mark.parametrize("i", range(len(BASE["histories"])))
def test_static_ratio_one_histories_are_unchanged(i):
    assert MAKER.history_digest(BASE["points"][i]) == BASE["histories"][i]


def test_the_base_covers_every_regime():
    pts = BASE["points"]
    assert any(math.isinf(p["beta"]) for p in pts)
    assert any(p["eta_c"] > 0 for p in pts)
    assert any(p["amplitude"] > 1 for p in pts)
    assert any(p["amplitude"] == 0 for p in pts)
    assert any(p["zeta"] > 0 for p in pts)
    assert any(p["a_x"] > 0 and p["inplane_on"] == "substrate" for p in pts)
    assert any(p["a_x"] > 0 and p["inplane_on"] == "holder" for p in pts)
    assert {p["initial"] for p in pts} == {"rest", "sliding"}
    status = {r["scalar"]["status"] for r in BASE["results"]}
    assert {"periodic", "continuous sliding"} <= status


# --------------------------------------------------------------------------- s_r > 1
def _random_points(n, seed):
    """The base's random points of every regime (finite elastic, viscoelastic and rigid
    contact, pin damping, jumping, no oscillation, an in-plane oscillation on the substrate
    or the holder, both starts), drawn afresh, each with a static ratio ``1 < s_r <= 2.5``."""
    rng = np.random.default_rng(seed)
    out = []
    for p in MAKER.points(seed)[:n]:
        dim = vf.Dimensionless(p["alpha"], p["beta"], p["amplitude"], zeta=p["zeta"],
                               eta_c=p["eta_c"], a_x=p["a_x"], phase_x=p["phase_x"],
                               inplane_on=p["inplane_on"],
                               static_ratio=float(rng.uniform(1.05, 2.5)))
        out.append((dim, p["v_inertial"], p["initial"]))
    return out


POINTS = _random_points(24, 7)


@pytest.mark.parametrize("dim, V, initial", POINTS)
def test_force_within_the_static_cone_and_energy_balanced(dim, V, initial):
    """Along a history ``|f| <= s_r n``; after every stick->slip event of a finite contact the
    force is the kinetic ``s n``; work = stored energy + dissipation, the elastic contact's
    jumps ``(k/2)(e_before^2 - e_after^2)`` counted in the friction's."""
    h = vf.simulate(dim, v_inertial=V, periods=4.0, samples_per_period=200, initial=initial)
    sr = dim.static_ratio
    assert np.all(np.abs(h.f) <= sr * h.n + 1e-9)
    slipping = np.isin(h.phase, ("slip+", "slip-"))
    s = np.where(h.phase == "slip+", 1.0, -1.0)
    np.testing.assert_allclose(h.f[slipping], s[slipping] * h.n[slipping], atol=1e-12)
    breaks = [e for e in h.events if e.kind == "stick->slip"]
    for ev in breaks:  # the force before the event is s_r n (the sample just before it)
        j = int(np.searchsorted(h.tau, ev.tau)) - 1
        assert abs(abs(h.f[j]) - sr * h.n[j]) <= 1e-8 * (1 + sr)
    lhs = h.work_input - h.dissipated_pin - h.dissipated_contact - h.dissipated_friction
    rhs = h.stored_energy() - h.stored_energy()[0]
    scale = np.max(np.abs(h.work_input)) + np.max(np.abs(h.stored_energy())) + 1.0
    assert np.max(np.abs(lhs - rhs)) <= 1e-7 * scale
    assert h.dissipated_friction[-1] >= -1e-12 * scale


def test_the_jump_is_in_the_energy_balance():
    """Without the jump's dissipation the balance of an elastic contact fails by it."""
    dim = vf.Dimensionless(0.5, 2.0, 0.5, static_ratio=1.6)
    h = vf.simulate(dim, v_inertial=0.3, periods=3.0, samples_per_period=200)
    k = dim.beta - dim.alpha
    jumps = [e for e in h.events if e.kind == "stick->slip"]
    assert jumps
    total = 0.0
    for ev in jumps:
        j = int(np.searchsorted(h.tau, ev.tau))  # the sample at the event: after the jump
        assert h.tau[j] == ev.tau
        e_after, e_before = h.e[j], h.e[j - 1]
        assert e_before == pytest.approx(dim.static_ratio * e_after, rel=1e-8)
        total += 0.5 * k * (e_before**2 - e_after**2)
    lhs = h.work_input - h.dissipated_pin - h.dissipated_contact - h.dissipated_friction
    rhs = h.stored_energy() - h.stored_energy()[0]
    assert abs(lhs[-1] - rhs[-1]) <= 1e-9 * (1 + total)
    # the jumps are no round-off: without them the balance would fail by far
    assert total >= 1e-3 * (abs(h.work_input[-1]) + np.max(np.abs(h.stored_energy())))


# --------------------------------------------------------------------------- the period map
def _plain_map(z3, ph, M, p=1):
    z = np.array([*z3, float(ph), math.nan])
    acc = np.zeros(N_ACC)
    count = np.zeros(3, np.int64)
    for _ in range(p):
        assert advance_period(z, acc, count, M, 10**6)
    return z[:3].copy(), int(z[3]), int(count[0]), float(acc[0])


def _check_tangent(z3, ph, M, p=1):
    """``J`` and ``G`` of ``p`` periods from ``(z3, ph)`` against fourth-order differences of
    the plain map; returns the number of its events."""
    J, G = np.zeros((3, 3)), np.zeros(3)
    out = period_map_tangent(*z3, ph, p, M, 10**6, J, G, np.zeros(N_ACC))
    assert out[-1]  # smooth
    base = _plain_map(z3, ph, M, p)
    checked = 0
    for j in range(_free_dimension(ph, M)):
        for h in (1e-4, 1e-5, 1e-6):
            step = h * (1.0 + abs(z3[j]))
            imgs = []
            for q in (-2, -1, 1, 2):
                zq = z3.copy()
                zq[j] += q * step
                r = _plain_map(zq, ph, M, p)
                if r[1:3] != base[1:3]:
                    break
                imgs.append(np.append(r[0], r[3]))
            else:
                d = (8 * (imgs[2] - imgs[1]) - (imgs[3] - imgs[0])) / (12 * step)
                got = np.append(J[:, j], G[j])
                assert np.max(np.abs(d - got)) <= 1e-7 * (1.0 + np.max(np.abs(d)))
                checked += 1
                break
    assert checked == _free_dimension(ph, M)
    return base[2]


# (alpha, beta, a, V, zeta, eta_c, s_r, start): elastic (the jump), viscoelastic, rigid,
# damped, jumping, a stiff system
TANGENT_POINTS = [(0.5, 2.0, 0.5, 0.3, 0.0, 0.0, 1.4, 0),
                  (0.5, 2.0, 0.5, 0.3, 0.05, 0.0, 1.4, 1),
                  (0.5, 2.0, 0.5, 0.3, 0.0, 0.2, 1.4, 0),
                  (0.3, math.inf, 0.5, 0.2, 0.0, 0.0, 1.4, 0),
                  (0.3, math.inf, 0.5, 0.2, 0.05, 0.0, 2.0, 0),
                  (0.3, 5.0, 1.3, 0.4, 0.02, 0.0, 1.4, 0),
                  (2.0, 10.0, 0.8, 0.6, 0.0, 0.0, 1.4, 0),
                  (2.0, 10.0, 0.8, 0.6, 0.0, 0.0, 2.2, 1)]


@pytest.mark.parametrize("pt", TANGENT_POINTS)
def test_period_map_tangent_with_the_jump_against_differences(pt):
    """The exact Jacobian of the period map and the gradient of ``int f`` (the jump's
    saltation for an elastic contact, the force's drop for the others) against fourth-order
    central differences of the plain map."""
    *par, sr, start = pt
    M = make_model(*par, 0.0, 0.0, True, sr)
    z = np.array(list(initial_state(start, M)), dtype=float)
    acc = np.zeros(N_ACC)
    count = np.zeros(3, np.int64)
    for _ in range(6):
        assert advance_period(z, acc, count, M, 10**6)
    assert _check_tangent(z[:3].copy(), int(z[3]), M) >= 1  # the period has an event


def test_a_break_that_sticks_again_at_once():
    """Where the normal force falls fast, an elastic contact's jump can be the whole slip: the
    contact sticks again at the kinetic force.  A 10-period orbit with one such break: the
    force is ``s n`` after it, the energy balance counts its jump, and the period map's
    Jacobian (the reset's saltation into stick, ``(R' - x') dt``) matches differences."""
    al, be, a, V, sr = 0.6361959374899742, 10.52813887612118, 1.015313892240192, \
        0.10297979045742119, 2.894033682901804
    dim = vf.Dimensionless(al, be, a, static_ratio=sr)
    r = vf.friction_coefficient(dim, v_inertial=V)
    assert r.status is vf.Status.PERIODIC and r.trusted and r.period == 10
    h = vf.simulate(dim, v_inertial=V, periods=10.0, samples_per_period=200,
                    initial=r.final_state)
    again = [e for e in h.events if e.kind == "stick->slip" and e.after == "stick"]
    assert len(again) == 1
    j = int(np.searchsorted(h.tau, again[0].tau))
    assert abs(h.f[j]) == pytest.approx(h.n[j], rel=1e-9)  # the kinetic force, stuck
    assert abs(h.f[j - 1]) == pytest.approx(sr * h.n[j - 1], rel=1e-6)
    lhs = h.work_input - h.dissipated_pin - h.dissipated_contact - h.dissipated_friction
    rhs = h.stored_energy() - h.stored_energy()[0]
    assert np.max(np.abs(lhs - rhs)) <= 1e-7 * (np.max(np.abs(h.work_input)) + 1.0)
    M = make_model(al, be, a, V, 0.0, 0.0, 0.0, 0.0, True, sr)
    s = r.final_state
    z3 = np.array([s.y, s.x_dot, s.elongation(dim)])
    assert _check_tangent(z3, 0, M, 10) == 40


@pytest.mark.parametrize("dim, V, initial", POINTS[:12])
def test_a_periodic_answer_is_an_orbit_of_the_history(dim, V, initial):
    """Newton's orbit (found with the jump's Jacobian) is a periodic motion: the history from
    its state returns to it after its period, and its mean is the answer."""
    r = vf.friction_coefficient(dim, v_inertial=V, initial=initial)
    assert r.status is not vf.Status.FAILED
    assert abs(r.mu_ratio) <= dim.static_ratio * (1 + 1e-12) or math.isnan(r.mu_ratio)
    if r.status is not vf.Status.PERIODIC or not r.trusted:
        return
    p = r.period
    h = vf.simulate(dim, v_inertial=V, periods=float(p), samples_per_period=2000,
                    initial=r.final_state)
    mean = np.trapezoid(h.f, h.tau) / np.trapezoid(h.n, h.tau)
    assert mean == pytest.approx(r.mu_ratio, abs=1e-5 + r.error)
    end = h.final_state
    assert end.phase == r.final_state.phase
    assert end.y == pytest.approx(r.final_state.y, abs=1e-6 * (1 + abs(end.y)))
    assert end.x_dot == pytest.approx(r.final_state.x_dot, abs=1e-6 * (1 + abs(end.x_dot)))


# --------------------------------------------------------------------------- V_c
VC_POINTS = [(0.5, 2.0, 0.5, 0.05, 0.0), (0.3, 4.0, 0.8, 0.02, 0.3), (2.0, 10.0, 0.6, 0.1, 0.1),
             (0.5, math.inf, 0.5, 0.05, 0.0), (0.2, math.inf, 0.7, 0.0, 0.0),
             (0.5, 2.0, 0.5, 0.0, 0.0)]


@pytest.mark.parametrize("p", VC_POINTS)
@pytest.mark.parametrize("sr", [1.2, 2.0])
def test_critical_velocity_is_coulombs(p, sr):
    """Continuous sliding carries the kinetic force: below Coulomb's ``V_c`` no start slides
    (the contact sticks or slips back in the answering window); far above it the motion from
    rest or steady sliding slides, proven where it is damped (undamped, a stick leaves a free
    oscillation that never dies, and the motion may go on sticking rarely: then its mean is
    near 1, or there is no answer)."""
    al, be, a, z, eta = p
    vc = theory.static_kinetic_critical_velocity(al, be, a, sr, z, eta)
    assert vc == theory.critical_inertial_velocity(al, be, a, z, eta)
    dim = vf.Dimensionless(al, be, a, zeta=z, eta_c=eta, static_ratio=sr)
    for initial in ("sliding", "rest"):
        r = vf.friction_coefficient(dim, v_inertial=0.9 * vc, initial=initial)
        assert r.trusted and r.status is not vf.Status.SLIDING
        assert r.stick_fraction + r.reverse_slip_fraction > 1e-3
        assert r.mu_ratio != 1.0
        r = vf.friction_coefficient(dim, v_inertial=4.0 * vc, initial=initial)
        if z > 0.0:
            assert r.status is vf.Status.SLIDING and r.mu_ratio == 1.0
        else:
            assert not r.trusted or abs(r.mu_ratio - 1.0) <= 1e-5


def test_sliding_and_stick_slip_coexist_above_the_critical_velocity():
    """Undamped, ``s_r = 1.5``, ``V = 1.2 V_c``: the sliding orbit slides for ever from its own
    state (Coulomb's orbit, proven), while the steady-sliding start and the rest are caught
    in a stick-slip orbit with ``mu > mu0``."""
    al, be, a = 0.5, 2.0, 0.5
    dim = vf.Dimensionless(al, be, a, static_ratio=1.5)
    V = 1.2 * theory.critical_inertial_velocity(al, be, a)
    orbit = theory.steady_sliding(0.0, al, be, a, V)
    on_orbit = vf.SectionState(y=orbit.y, x_dot=orbit.velocity, f=1.0 + a, phase="slip+")
    r = vf.friction_coefficient(dim, v_inertial=V, initial=on_orbit)
    assert r.status is vf.Status.SLIDING and r.mu_ratio == 1.0 and r.error == 0.0
    for initial in ("sliding", "rest"):
        r = vf.friction_coefficient(dim, v_inertial=V, initial=initial)
        assert r.status is vf.Status.PERIODIC and r.trusted
        assert r.stick_fraction > 0.05 and r.mu_ratio > 1.0 + 10 * r.error
    # with Coulomb friction the same starts slide
    r = vf.friction_coefficient(vf.Dimensionless(al, be, a), v_inertial=V)
    assert r.status is vf.Status.SLIDING


# A point of a fresh random campaign (differential_campaign.py --static, seed 1130) where
# Newton's iterate, early in the transient, converged to the sliding orbit, whose own state
# the certificate proves: the solver answered "continuous sliding, mu = 1, error 0", while
# the motion from the sliding start goes on to stick-slip with mu/mu0 about 1.12
FALSE_PROOF = (0.15875851859066223, 5.704098921487698, 0.2293556494950217,
               0.23131915240059525, 0.16649457906772397, 1.9790117995694856)


def test_an_orbit_the_motion_does_not_reach_is_no_answer():
    """Sliding and stick-slip coexist: Newton's orbit answers only once the motion itself
    comes to it.  Whatever the solver answers agrees with the mean of its own motion from
    the same start (periods 100 to 300 of the history); it is no proof of sliding."""
    al, be, a, V, z, sr = FALSE_PROOF
    dim = vf.Dimensionless(al, be, a, zeta=z, static_ratio=sr)
    h = vf.simulate(dim, v_inertial=V, periods=300, samples_per_period=100)
    late = h.tau >= 2 * math.pi * 100
    motion = np.trapezoid(h.f[late], h.tau[late]) / np.trapezoid(h.n[late], h.tau[late])
    assert motion > 1.1  # the motion sticks: its mean is above the kinetic force's
    r = vf.friction_coefficient(dim, v_inertial=V)
    assert r.status is not vf.Status.SLIDING
    assert not r.trusted or abs(r.mu_ratio - motion) <= 1e-2


def test_without_oscillation_the_sliding_start_slides_and_rest_sticks_and_slips():
    """``a = 0``: steady sliding goes on (kinetic force, slip velocity ``V``); from rest the
    classic stick-slip of a static coefficient, whose undamped rigid mean is exactly 1.
    Its cycle is not a multiple of the drive period, so windows of whole drive periods cut
    cycles: their means differ by about 1.5e-6 after 20,000 periods, which the default
    ``tol_mean`` (1e-7) does not accept (not converged) and ``1e-5`` does."""
    dim = vf.Dimensionless(0.5, math.inf, 0.0, static_ratio=1.4)
    r = vf.friction_coefficient(dim, v_inertial=0.3)
    assert r.mu_ratio == 1.0 and r.stick_fraction == 0.0
    r = vf.friction_coefficient(dim, v_inertial=0.3, initial="rest")
    assert r.status is vf.Status.NOT_CONVERGED and r.window_max - r.window_min > 1e-7
    r = vf.friction_coefficient(dim, v_inertial=0.3, initial="rest",
                                settings=vf.SolverSettings(tol_mean=1e-5))
    assert r.trusted and r.stick_fraction > 0.3
    assert r.mu_ratio == pytest.approx(1.0, abs=1e-9 + r.error)


# --------------------------------------------------------------------------- V -> 0
def _cycle_mean(dim, V, periods, samples=64):
    """``int f / int n`` over the last whole stick-slip cycle of a history from rest (between
    its last two stick->slip events) and the number of cycles seen."""
    h = vf.simulate(dim, v_inertial=V, periods=periods, samples_per_period=samples,
                    initial="rest")
    starts = [e.tau for e in h.events if e.kind == "stick->slip"]
    assert len(starts) >= 3
    i0 = int(np.searchsorted(h.tau, starts[-2]))
    i1 = int(np.searchsorted(h.tau, starts[-1]))
    sl = slice(i0, i1 + 1)
    return np.trapezoid(h.f[sl], h.tau[sl]) / np.trapezoid(h.n[sl], h.tau[sl]), len(starts)


@pytest.mark.parametrize("beta, zeta", [(math.inf, 0.0), (math.inf, 0.05), (math.inf, 0.3),
                                        (3.0, 0.05), (3.0, 0.3)])
def test_static_limit_without_oscillation(beta, zeta):
    """``a = 0``: the mean over a stick-slip cycle tends to the quasi-static cycle's as
    ``V -> 0``, linearly (the slip's time against the stick's)."""
    sr, al = 1.4, 0.5
    dim = vf.Dimensionless(al, beta, 0.0, zeta=zeta, static_ratio=sr)
    limit = theory.static_kinetic_static_limit(al, beta, 0.0, sr, zeta)
    if math.isinf(beta) and zeta == 0.0:
        assert limit == pytest.approx(1.0, abs=1e-12)  # the saw-tooth 2 - s_r ... s_r
    gaps = []
    for V in (1e-2, 1e-3):
        # the stuck force rises at alpha V k/beta: from 0 to s_r, then cycles of at most
        # 2 (s_r - 1) of it
        rate = al * V * (1.0 if math.isinf(beta) else (beta - al) / beta)
        mean, _ = _cycle_mean(dim, V, periods=(sr + 5.0 * (sr - 1.0)) / rate / (2 * math.pi)
                              + 5)
        gaps.append(abs(mean - limit))
    assert gaps[1] <= 2e-3
    assert gaps[1] <= 0.2 * gaps[0] + 1e-9


def test_static_limit_refuses_what_it_does_not_cover():
    with pytest.raises(ValueError, match="zeta"):
        theory.static_kinetic_static_limit(0.5, 3.0, 0.0, 1.4, 0.0)
    with pytest.raises(ValueError, match="amplitude"):
        theory.static_kinetic_static_limit(0.5, 3.0, 0.5, 1.4, 0.1)
    with pytest.raises(ValueError, match="amplitude"):
        theory.static_kinetic_static_limit(0.5, math.inf, 1.5, 1.4, 0.1)
    with pytest.raises(ValueError, match="static_ratio"):
        theory.static_kinetic_static_limit(0.5, math.inf, 0.5, 0.9, 0.1)
    # damped a = 0, rigid: 1 + (s_r - 1)(1 - q)/2 in closed form
    q = math.exp(-math.pi * 0.05 / math.sqrt(1 - 0.05**2))
    assert theory.static_kinetic_static_limit(0.5, math.inf, 0.0, 1.4, 0.05) == \
        pytest.approx(1 + 0.4 * (1 - q) / 2, abs=1e-9)
    # an over-damped pin: the first slip never ends, sliding
    assert theory.static_kinetic_static_limit(0.5, math.inf, 0.0, 1.4, 1.5) == 1.0


@pytest.mark.parametrize("alpha, a, sr, zeta", [(0.5, 0.5, 1.4, 0.05), (0.5, 0.5, 1.4, 0.0),
                                                (2.0, 0.3, 2.5, 0.1), (0.05, 0.7, 1.3, 0.02),
                                                (0.5, 0.5, 1.0, 0.05)])
def test_static_limit_slip_of_a_rigid_contact(alpha, a, sr, zeta):
    """The slip of the static limit against the solver: a rigid contact held at rest whose
    force reaches ``s_r (1 - a)`` at ``tau = pi`` (``V = 1e-9``) slips for the derived time
    and sticks again with the derived force."""
    slip = theory.static_kinetic_slip(alpha, a, sr, zeta)
    V = 1e-9
    gamma = 2.0 * zeta * math.sqrt(alpha)
    f_pi = slip.force_before
    y0 = (alpha * V * math.pi + gamma * V - f_pi) / alpha  # f = -alpha y + gamma V, y = y0 - V tau
    start = vf.SectionState(y=y0, x_dot=0.0, f=-alpha * y0 + gamma * V, phase="stick")
    dim = vf.Dimensionless(alpha, math.inf, a, zeta=zeta, static_ratio=sr)
    h = vf.simulate(dim, v_inertial=V, periods=2.0, samples_per_period=64, initial=start)
    ev = [e for e in h.events if e.tau < 2 * math.pi + 1.5]
    if sr == 1.0:
        assert slip.duration == 0.0 and slip.force_after == slip.force_before
        assert theory.static_kinetic_static_limit(alpha, math.inf, a, sr, zeta) == \
            pytest.approx(theory.static_mu_ratio(a), abs=1e-15)
        return
    assert ev[0].kind == "stick->slip" and ev[0].tau == pytest.approx(math.pi, abs=1e-4)
    assert ev[1].kind == "slip->stick" and ev[1].after == "stick"
    assert ev[1].tau - ev[0].tau == pytest.approx(slip.duration, abs=1e-6)
    j = int(np.searchsorted(h.tau, ev[1].tau))
    assert h.f[j] == pytest.approx(slip.force_after, abs=1e-6)


# --------------------------------------------------------------------------- properties
@settings(max_examples=30, deadline=None)
@given(alpha=st.floats(0.05, 3.0), k=st.floats(0.3, 20.0), rigid=st.booleans(),
       a=st.floats(0.0, 1.5), V=st.floats(0.02, 2.0), zeta=st.sampled_from([0.0, 0.02, 0.2]),
       eta=st.sampled_from([0.0, 0.1]), sr=st.floats(1.0, 3.0))
def test_properties_over_random_parameters(alpha, k, rigid, a, V, zeta, eta, sr):
    """Over random valid points: a result within the static cone, ``|mu| <= s_r``; never a
    failed integration; ``s_r`` barely above 1 is Coulomb's answer to first order."""
    beta = math.inf if rigid else alpha + k
    dim = vf.Dimensionless(alpha, beta, a, zeta=zeta, eta_c=eta, static_ratio=sr)
    r = vf.friction_coefficient(dim, v_inertial=V)
    assert r.status is not vf.Status.FAILED
    if math.isfinite(r.mu_ratio):
        assert abs(r.mu_ratio) <= sr * (1 + 1e-12)
    r1 = vf.friction_coefficient(replace(dim, static_ratio=1.0), v_inertial=V)
    near = vf.friction_coefficient(replace(dim, static_ratio=1.0 + 1e-9), v_inertial=V)
    if r1.trusted and near.trusted and r1.status is near.status:
        assert abs(near.mu_ratio - r1.mu_ratio) <= 1e-5 + 10 * (r1.error + near.error)


# --------------------------------------------------------------------------- declarations
def test_the_event_solver_declares_the_static_ratio_and_refuses_what_it_does_not_cover():
    from vibrofriction.capabilities import CAPABILITIES, refused_by
    from vibrofriction.solver import friction_gradient

    event = CAPABILITIES["event"]
    assert "static_ratio" in event.parameters
    assert event not in refused_by("static_ratio")  # only at V = 0, not every value
    dim = vf.Dimensionless(0.5, 2.0, 0.5, static_ratio=1.5)
    with pytest.raises(ValueError, match="static_ratio") as err:
        vf.friction_coefficient(dim, v_inertial=0.0)
    assert err.value.parameter == "static_ratio"
    assert math.isfinite(friction_gradient(dim, v_inertial=0.3)[1]["alpha"])
    # the physical system's mu_static is the dimensionless ratio
    p = vf.Physical(mass=0.01, k_x=2.5e5, k_xc=2e5, k_zc=2.5e5, u_z0=4e-6, du_z=2e-6,
                    omega=2 * math.pi * 1000, mu0=0.3, mu_static=0.45)
    r = vf.friction_coefficient(p, v0=0.001)
    d = vf.friction_coefficient(p.to_dimensionless(), v_inertial=r.v_inertial)
    assert p.to_dimensionless().static_ratio == pytest.approx(1.5, rel=1e-15)
    assert r.mu_ratio == d.mu_ratio and r.status is vf.Status.PERIODIC


@pytest.mark.parametrize("beta, zeta, eta, sr", [(2.0, 0.0, 0.0, 1.5), (2.0, 0.05, 0.2, 1.3),
                                                 (math.inf, 0.05, 0.0, 1.8),
                                                 (5.0, 0.02, 0.0, 2.2)])
def test_gradient_with_the_jump_against_differences_of_the_solver(beta, zeta, eta, sr):
    """``friction_gradient`` (the orbit's exact Jacobian with the break's saltation and the
    parameters' explicit differences) against central differences of the whole solver."""
    from vibrofriction.solver import friction_gradient

    base = {"alpha": 0.5, "beta": beta, "amplitude": 0.6, "zeta": zeta, "eta_c": eta,
            "static_ratio": sr}
    V = 0.3
    r, grad = friction_gradient(vf.Dimensionless(**base), v_inertial=V)
    assert r.status is vf.Status.PERIODIC and r.trusted
    names = ("alpha", "amplitude", "v_inertial") + (("zeta",) if zeta > 0 else ())
    checked = 0
    for name in names:
        h = 1e-5
        mus = []
        for sign in (-1.0, 1.0):
            kw, v = dict(base), V
            if name == "v_inertial":
                v = V + sign * h
            else:
                kw[name] = base[name] + sign * h
            q = vf.friction_coefficient(vf.Dimensionless(**kw), v_inertial=v)
            assert q.trusted and q.period == r.period
            mus.append(q.mu_ratio)
        fd = (mus[1] - mus[0]) / (2 * h)
        assert grad[name] == pytest.approx(fd, abs=2e-5 * (1 + abs(fd))), name
        checked += 1
    assert checked == len(names)
