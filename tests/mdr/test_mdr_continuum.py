"""The MDR row without springs (:mod:`vibrofriction._kernels.mdr_continuum`) against the
spring rows it is the limit of, and its own pieces."""

import json
import math
from pathlib import Path

import numpy as np
import pytest

from vibrofriction._kernels import mdr_continuum as mc
from vibrofriction.solver.mdr import mdr_friction, mdr_row
from vibrofriction.solver.mdr_continuum import (
    continuum_covers,
    continuum_friction,
    mdr_continuum,
    slides_continuously,
)


def test_hermite_is_exact_for_quintics():
    """The history's interpolant reproduces a quintic and its derivative from the values,
    first and second derivatives at the ends (it is the quintic Hermite basis)."""
    rng = np.random.default_rng(3)
    p = np.polynomial.Polynomial(rng.normal(size=6))
    dp, ddp = p.deriv(), p.deriv(2)
    HS = np.zeros((2, mc.N_HS))
    for i, t in enumerate((0.3, 0.9)):
        HS[i, mc.HT], HS[i, mc.HU], HS[i, mc.HD], HS[i, mc.HDD] = t, p(t), dp(t), ddp(t)
    for t in np.linspace(0.3, 0.9, 7):
        u, du = mc._hermite(HS, 0, t)
        assert u == pytest.approx(p(t), abs=1e-12)
        assert du == pytest.approx(dp(t), abs=1e-11)


def test_rotated_angles_match_the_library():
    """:func:`_cs`: ``cos t``, ``sin t`` rotated from a known angle by its Taylor series
    agree with the library's to a few units of round-off over every rotation it takes
    (``|t - t0| <= CS_NEAR``) and beyond it (the library's own), at times of many periods."""
    rng = np.random.default_rng(7)
    t0 = rng.uniform(0.0, 400.0, 2000)
    x = rng.uniform(-1.5 * mc.CS_NEAR, 1.5 * mc.CS_NEAR, t0.size)
    for a, b in zip(t0, x, strict=True):
        c, s = mc._cs(a + b, a, math.cos(a), math.sin(a))
        assert abs(c - math.cos(a + b)) <= 4e-16
        assert abs(s - math.sin(a + b)) <= 4e-16


@pytest.mark.parametrize("t", [0.4, 1.5])
def test_a_level_in_a_step_is_found_where_the_dense_output_reaches_it(t):
    """:func:`_level_in_step` (where a step rejected across a level is tried again to):
    the fraction of a real Dormand-Prince step at which a rising ``P`` (``t = 0.4``) or a
    falling ``N`` (``t = 1.5``) reaches a level between its values at the step's ends, at
    round-off there; 2 for a level beyond the end, and the earlier of two levels."""
    from vibrofriction.solver.mdr_continuum import HISTORY, _parameters

    prm = _parameters(0.5, 2.0, 0.5, 0.3, 2.0, 0.1, 0.0, 0.0)
    PC = np.zeros((mc.MAX_PIECES + 1, mc.N_PC))
    HS = np.empty((HISTORY, mc.N_HS))
    z = np.zeros(mc.N_Z)
    z[0] = -1.5 ** 1.5 / 0.5
    npc, nh = mc.start(prm, z[0], z[1], PC, HS)
    seg = np.array([0.0, 0.0, float(mc.EDGE_NONE), 0.0, math.nan])
    h = 0.3
    ct, st = math.cos(t), math.sin(t)
    k1, znew, K, cs = np.zeros(mc.N_Z), np.zeros(mc.N_Z), np.zeros((8, mc.N_Z)), np.zeros(2)
    mc.rhs(t, z, k1, prm, PC, npc, HS, nh, seg, ct, st)
    mc._step(t, z, k1, h, znew, K, prm, PC, npc, HS, nh, seg, ct, st, cs)
    kind = 2 if t < 1.0 else 3  # P (u - c delta) rises, or N (u + c delta) falls

    def edge(th):
        return mc._event_value(kind, 0.0, z, znew, K, h, t, th, prm, ct, st)

    def level_in(lev, other):
        lp, ln = (lev, other) if kind == 2 else (other, lev)
        return mc._level_in_step(z, znew, K, h, t, prm, lp, ln, ct, st)

    e0, e1 = edge(0.0), edge(1.0)
    sign = 1.0 if kind == 2 else -1.0
    assert sign * (e1 - e0) > 0.0
    never = -sign * math.inf  # (no level of the other edge)
    for frac in (0.1, 0.5, 0.93):
        lev = e0 + frac * (e1 - e0)
        th = level_in(lev, never)
        assert 0.0 < th < 1.0
        assert abs(edge(th) - lev) <= 1e-13 * (1.0 + abs(lev))
        # the other edge's level, not reached, leaves it
        assert level_in(lev, -sign * 1e9) == th
    assert level_in(e1 + sign * 1e-6, never) == 2.0
    assert level_in(sign * math.inf, never) == 2.0


def test_front_newton_converges_quadratically(monkeypatch):
    """A history piece's front (:func:`_hfront`): the root of ``u + c delta = target`` to
    round-off in a few Newton steps, also from a guess on the root itself (a converged
    step lands on the bracket's end: it must answer, not bisect the bracket away)."""
    calls = []
    hermite = mc._hermite.py_func

    def counted(HS, i, t):
        calls.append(t)
        return hermite(HS, i, t)

    monkeypatch.setattr(mc, "_hermite", counted)
    c, a = 0.5, 0.5
    ts = np.arange(0.0, 2.01, 0.1)
    HS = np.zeros((ts.size, mc.N_HS))  # u = 2 tau: its quintic interpolant is exact
    HS[:, mc.HT], HS[:, mc.HU], HS[:, mc.HD] = ts, 2.0 * ts, 2.0
    HS[:, mc.HN] = HS[:, mc.HU] + c * (1.0 + a * np.cos(ts))
    HS[:, mc.HC], HS[:, mc.HSN] = np.cos(ts), np.sin(ts)
    root = 1.2345
    target = 2.0 * root + c * (1.0 + a * math.cos(root))
    def level_at(t):
        return 2.0 * t + c * (1.0 + a * math.cos(t))

    slope = 2.0 - c * a * math.sin(root)
    last = root - 0.01  # a front found earlier, at a level 0.019 lower
    for guess, level, most in ((root + 0.04, math.nan, 5), (root, target, 2),
                               (math.nan, math.nan, 6), (last, level_at(last), 3)):
        calls.clear()
        # the last front at ``guess``, found at ``level`` with the slope there
        t, i, df = mc._hfront.py_func(HS, ts.size, 0.0, 2.0, target, 1.0, c, a, guess, 12,
                                      level, slope)
        assert t == pytest.approx(root, abs=1e-13)
        assert i == 12
        assert df == pytest.approx(slope, rel=1e-9)
        assert len(calls) <= most


def test_covers():
    assert continuum_covers(0.5, 0.3, 1.0)
    assert continuum_covers(1.2, 0.3, 1.0)  # jumping
    assert not continuum_covers(1.0, 0.3, 1.0)  # the contact closes to a point: the rows
    assert not continuum_covers(0.5, 0.0, 1.0)
    assert not continuum_covers(0.5, 0.3, 1.5)  # a static limit above the kinetic one


# (alpha, beta, a, V, n, zeta): stick-slip, undamped, a cone, soft pin, slow and lightly
# damped, n = 4, a stiff pin, fast with a = 0.9
POINTS = [(0.5, 2.0, 0.5, 0.3, 2.0, 0.1), (0.5, 2.0, 0.5, 0.3, 2.0, 0.0),
          (1.0, 3.0, 0.7, 0.5, 1.0, 0.1), (0.05, 0.1, 0.5, 0.3, 2.0, 0.5),
          (0.3, 3.0, 0.8, 0.05, 2.0, 0.02), (0.5, 2.0, 0.5, 0.3, 4.0, 0.1),
          (2.0, 2.5, 0.6, 0.2, 1.5, 0.05), (0.5, 1.0, 0.9, 1.0, 2.0, 0.3)]


@pytest.mark.parametrize("point", POINTS)
def test_continuum_is_the_rows_limit(point, rows_alone):
    """The continuum's ``mu_ratio`` lies within the refined rows' error (rows of up to
    thousands of springs, extrapolated, a different kernel: closed forms per spring), and
    states an error a hundred times smaller."""
    alpha, beta, a, V, n, zeta = point
    c = mdr_continuum(alpha, beta, a, V, n, zeta)
    r = mdr_friction(alpha, beta, a, V, n, zeta=zeta, tol=1e-6)
    assert r["rows"] != ()  # the rows answered
    assert c["status"] == "periodic" and r["status"] == "periodic"
    assert c["error"] < 3e-8
    assert abs(c["mu_ratio"] - r["mu_ratio"]) <= r["error"] + c["error"]
    # the time-averaged areas: the finest row's within its cells' share
    for key in ("stick_area_fraction", "slip_area_fraction", "open_area_fraction"):
        assert abs(c[key] - r[key]) < 2e-3
    assert c["stick_area_fraction"] + c["slip_area_fraction"] <= 1.0 + 1e-12


def test_rows_approach_the_continuum():
    """Single rows (no extrapolation) of 40 to 1280 springs approach the continuum: their
    distance falls from about 2e-5 to below 1e-7 (irregularly: the contact's edge moves
    across the springs, so not by a fixed factor a doubling)."""
    point = (0.5, 2.0, 0.5, 0.3, 2.0, 0.1)
    mu = mdr_continuum(*point[:5], zeta=point[5])["mu_ratio"]
    errs = [abs(mdr_row(*point[:5], N, zeta=point[5])["mu_ratio"] - mu) for N in (40, 1280)]
    assert errs[0] > 1e-6
    assert errs[1] < 1e-7


def test_drive_matches_the_rows(rows_alone):
    """A longitudinal drive of the substrate: the continuum within the rows' error."""
    from vibrofriction._kernels.phases import frame_offset, inplane_forcing

    alpha, beta, a, V, n, zeta, ax, ph = 0.5, 2.0, 0.5, 0.3, 2.0, 0.1, 0.4, 0.7
    hc, hs = inplane_forcing(alpha, 2 * zeta * math.sqrt(alpha), ax, ph, True)
    c = mdr_continuum(alpha, beta, a, V, n, zeta, hc, hs, frame_offset(ax, ph, True))
    r = mdr_friction(alpha, beta, a, V, n, zeta=zeta, tol=1e-6, a_x=ax, phase_x=ph)
    assert c["status"] == "periodic"
    assert abs(c["mu_ratio"] - r["mu_ratio"]) <= r["error"] + c["error"]


def test_the_continuum_answers_where_it_covers():
    """``mdr_friction`` answers a point the continuum covers with it (no rows) at every
    tolerance: ``1e-8``, the default ``1e-5``, a fit's ``1e-4`` and ``1e-3`` (each within it;
    the last three from maps at ``1e-7``, the loosest, alike); with ``n_springs`` or within
    ``rows_alone()`` the rows answer, and agree within the two errors."""
    import vibrofriction.solver.mdr as mdr
    from vibrofriction.bench.fitting import CURVED_TOL

    out = {}
    for tol in (1e-8, 1e-5, CURVED_TOL, 1e-3):
        r = mdr_friction(0.5, 2.0, 0.5, 0.3, 2.0, zeta=0.1, tol=tol)
        assert r["rows"] == () and r["status"] == "periodic" and r["error"] <= tol
        assert r["max_excess"] == 0.0
        out[tol] = r
    assert out[1e-3]["mu_ratio"] == out[CURVED_TOL]["mu_ratio"] == out[1e-5]["mu_ratio"]
    assert out[1e-5]["error"] <= 1e-6  # (about 1e-7: maps at 1e-7)
    for tol in (1e-5, 1e-3):
        assert abs(out[tol]["mu_ratio"] - out[1e-8]["mu_ratio"]) <= out[tol]["error"]
    rows = mdr_friction(0.5, 2.0, 0.5, 0.3, 2.0, zeta=0.1, tol=1e-3, n_springs=40)
    assert rows["rows"] == (40, 80)
    assert abs(rows["mu_ratio"] - out[1e-8]["mu_ratio"]) <= rows["error"] + out[1e-8]["error"]
    with mdr.rows_alone():
        assert mdr_friction(0.5, 2.0, 0.5, 0.3, 2.0, zeta=0.1, tol=1e-8)["rows"] != ()


def test_search_tolerance_follows_tol():
    """Not given, the search's tolerance is ``FACTOR tol`` within its bounds, as the maps'
    are: at ``1e-5`` looser than at ``1e-8`` (a larger stated error), in as many periods
    (measured: 10 and 10 here). A ``state_tol`` given is kept: ``1e-9`` at ``1e-5`` takes
    more periods (the maps' noise at their tolerance, ``1e-7``, slows the search down)."""
    point = (0.5, 2.0, 0.5, 0.3, 2.0, 0.0, 0.0, 0.0, (0.0, 0.0))
    loose = continuum_friction(*point, 1e-5)
    tight = continuum_friction(*point, 1e-8)
    given = continuum_friction(*point, 1e-5, state_tol=1e-9)
    assert 1e-8 < loose["error"] <= 1e-6 and tight["error"] <= 1e-8
    assert abs(loose["periods"] - tight["periods"]) <= 2
    assert given["periods"] > loose["periods"]
    for r in (loose, given):
        assert abs(r["mu_ratio"] - tight["mu_ratio"]) <= r["error"] + tight["error"]


FINE = json.loads((Path(__file__).parents[1] / "data" / "mdr_fine_reference.json")
                  .read_text())["points"]
COVERED = [p for p in FINE if continuum_covers(p["amplitude"], p["v_inertial"], 1.0)]


def test_the_fine_reference_covers_the_continuum():
    """Most of the independent reference's points are the continuum's, 20 or more with
    ``a < 1`` and as many jumping, with drives of the substrate and the holder among them."""
    assert sum(p["amplitude"] < 1.0 for p in COVERED) >= 20
    assert sum(p["amplitude"] > 1.0 for p in COVERED) >= 20
    assert {p["inplane_on"] for p in COVERED if p["a_x"] > 0} == {"substrate", "holder"}


@pytest.mark.parametrize("tol", [1e-5, 1e-7])
@pytest.mark.parametrize("p", COVERED, ids=lambda p: p["label"])
def test_continuum_agrees_with_the_independent_reference(p, tol):
    """Against the independent spring row refined to a bar of at most 2e-6
    (tests/data/make_mdr_fine_reference.py; shares no code with the continuum): within the
    bar plus the continuum's stated error, which is at most ``tol`` (asked for as the MDR
    solver asks, at the default ``tol_trusted`` and at ``1e-7``)."""
    from vibrofriction._kernels.phases import frame_offset, inplane_forcing

    alpha, zeta = p["alpha"], p["zeta"]
    on = p["inplane_on"] == "substrate"
    hc, hs = inplane_forcing(alpha, 2 * zeta * math.sqrt(alpha), p["a_x"], p["phase_x"], on)
    c = continuum_friction(alpha, p["beta"], p["amplitude"], p["v_inertial"],
                           p["profile_exponent"], zeta, hc, hs,
                           frame_offset(p["a_x"], p["phase_x"], on), tol)
    assert c["status"] == "periodic", c["reason"]
    assert c["error"] <= tol
    assert abs(c["mu_ratio"] - p["mu_ref"]) <= c["error"] + p["err_ref"], (
        c["mu_ratio"], p["mu_ref"], p["err_ref"])


def test_continuous_sliding_is_claimed_only_above_the_critical_velocity():
    """:func:`slides_continuously` (a coarse grid with the grid's error bound) against
    ``theory.profile_critical_velocity`` (2^15 points refined by Brent's method): never
    claimed below it, always claimed from 0.2 % above it, at random points."""
    from vibrofriction.theory import profile_critical_velocity

    rng = np.random.default_rng(5)
    for _ in range(60):
        al = 10 ** rng.uniform(-2, 1)
        be = al + 10 ** rng.uniform(-1.5, 2)
        a, n = rng.uniform(0.05, 0.95), float(rng.choice([0.7, 1, 1.5, 2, 3, 5]))
        ze = float(rng.choice([0, 0.01, 0.1, 0.5]))
        vc = float(profile_critical_velocity(al, be, a, n, ze))
        assert not slides_continuously(al, be, a, vc * (1 - 1e-9), n, ze)
        assert slides_continuously(al, be, a, vc * 1.002 + 1e-9, n, ze)


def test_continuous_sliding_is_never_claimed_at_an_undamped_harmonic_resonance():
    """Undamped, ``alpha = k^2`` makes the ``k``-th harmonic of the force resonate: the
    sliding orbit does not exist, whatever ``V``; just off it the check runs."""
    for k in (1, 2, 3):
        assert not slides_continuously(k * k, k * k + 10.0, 0.3, 1e6, 2.0, 0.0)
    assert slides_continuously(4.0 + 1e-6, 14.0, 0.3, 1e6, 2.0, 0.0)


def test_continuous_sliding_matches_the_rows():
    """Above the critical velocity the MDR solver (at a tolerance the continuum answers)
    returns ``mu_ratio = 1`` exactly with the status of continuous sliding, as the rows find
    (their orbit slips throughout)."""
    from vibrofriction.schema import Status
    from vibrofriction.solver import SolverSettings, solve_points

    tight = SolverSettings(tol_trusted=1e-9)
    out = solve_points(5.0, 50.0, 0.6, 0.5, profile_exponent=2.0, settings=tight)
    assert int(out["status"]) == Status.SLIDING.code and float(out["mu_ratio"]) == 1.0
    r = mdr_friction(5.0, 50.0, 0.6, 0.5, 2.0, n_springs=80)  # the rows alone
    assert r["mu_ratio"] == pytest.approx(1.0, abs=1e-10) and r["stick_area_fraction"] == 0
    assert float(out["slip_area_fraction"]) == pytest.approx(r["slip_area_fraction"],
                                                             abs=2e-3)
    assert float(out["error"]) == 0.0


def test_stated_error_holds_against_a_tighter_run_and_friction_stays_below_normal():
    """At random points the default run's ``mu_ratio`` lies within its stated error of a
    run with maps a hundred times tighter, and ``0 < mu_ratio <= 1`` within it (each point's
    force is clamped to its normal force, so the mean friction cannot exceed the mean
    normal force).
    """
    rng = np.random.default_rng(8)
    for _ in range(12):
        al = 10 ** rng.uniform(-1.5, 1)
        be = al + 10 ** rng.uniform(-1, 1.5)
        a, V = rng.uniform(0.1, 0.9), 10 ** rng.uniform(-1.5, 0.3)
        n, ze = float(rng.choice([1, 1.5, 2, 3])), float(rng.choice([0, 0.05, 0.3]))
        r = mdr_continuum(al, be, a, V, n, ze)
        fine = mdr_continuum(al, be, a, V, n, ze, rtol=1e-10)
        assert r["status"] == fine["status"] == "periodic"
        assert abs(r["mu_ratio"] - fine["mu_ratio"]) <= r["error"], (al, be, a, V, n, ze)
        assert 0.0 < r["mu_ratio"] <= 1.0 + r["error"]  # (the mean force integrated)


def test_tol_state_acts_on_the_continuum():
    """The MDR setting ``tol_state`` ends the continuum's search too (floored at 1e-9) and
    adds to its stated error: a loose one leaves ``tol`` to the rows."""
    tight = mdr_continuum(0.5, 2.0, 0.5, 0.3, 2.0, 0.1, state_tol=1e-9)
    loose = mdr_continuum(0.5, 2.0, 0.5, 0.3, 2.0, 0.1, state_tol=1e-5)
    assert loose["periods"] < tight["periods"] and loose["error"] > 1e-5
    assert abs(loose["mu_ratio"] - tight["mu_ratio"]) <= loose["error"]
    r = mdr_friction(0.5, 2.0, 0.5, 0.3, 2.0, zeta=0.1, tol=1e-7, state_tol=1e-5)
    assert r["rows"] != ()  # the continuum's error is above tol: the rows answer


# a jumping indenter (a > 1), (alpha, beta, a, V, n, zeta): undamped and damped spheres,
# n = 4, a stiff and fast cone, a contact that barely opens (a = 1.05)
JUMPING = [(0.5, 4.0, 1.5, 0.3, 2.0, 0.0), (0.5, 4.0, 1.5, 0.3, 2.0, 0.1),
           (0.3, 2.0, 1.2, 0.2, 4.0, 0.0), (2.0, 10.0, 2.5, 1.0, 1.0, 0.05),
           (0.5, 4.0, 1.05, 0.3, 2.0, 0.0)]


@pytest.mark.parametrize("point", JUMPING)
def test_jumping_is_the_rows_limit(point):
    """Where the contact opens every period, the continuum asked for ``1e-7`` lies within
    the rows' error at ``1e-7`` (rows of thousands of springs, extrapolated), and so do the
    time-averaged areas within the finest row's share of a cell."""
    import vibrofriction.solver.mdr as mdr

    alpha, beta, a, V, n, zeta = point
    c = continuum_friction(alpha, beta, a, V, n, zeta, 0.0, 0.0, (0.0, 0.0), 1e-7)
    with mdr.rows_alone():
        r = mdr_friction(alpha, beta, a, V, n, zeta=zeta, tol=1e-7)
    assert r["rows"] != () and r["status"] == "periodic"
    assert c["status"] == "periodic" and c["error"] <= 1e-7
    assert abs(c["mu_ratio"] - r["mu_ratio"]) <= r["error"] + c["error"]
    for key in ("stick_area_fraction", "slip_area_fraction", "open_area_fraction"):
        assert abs(c[key] - r[key]) < 1e-3
    assert c["open_area_fraction"] > 0.2  # (the flight: no contact at all)


def test_jumping_stated_error_holds_against_a_tighter_run():
    """Jumping, at random points: the default run's ``mu_ratio`` within its stated error of
    a run with maps a hundred times tighter, and ``0 < mu_ratio <= 1`` within it."""
    rng = np.random.default_rng(9)
    for _ in range(8):
        al = 10 ** rng.uniform(-1.5, 1)
        be = al + 10 ** rng.uniform(-1, 1.5)
        a, V = rng.uniform(1.05, 3.0), 10 ** rng.uniform(-1.5, 0.3)
        n, ze = float(rng.choice([1, 1.5, 2, 3, 5])), float(rng.choice([0, 0.05, 0.3]))
        r = mdr_continuum(al, be, a, V, n, ze)
        fine = mdr_continuum(al, be, a, V, n, ze, rtol=1e-10)
        assert r["status"] == fine["status"] == "periodic"
        assert abs(r["mu_ratio"] - fine["mu_ratio"]) <= r["error"], (al, be, a, V, n, ze)
        assert 0.0 < r["mu_ratio"] <= 1.0 + r["error"]


@pytest.mark.parametrize("n", [0.7, 1.5, 2.0, 4.0])
def test_touchdown_quadrature(n):
    """``W = int rho u' dtau`` from a touch-down, where ``rho = delta^(1/n)`` grows like
    ``(tau - tau_td)^(1/n)``: with that factor apart (Gauss-Jacobi) it agrees with SciPy's
    adaptive quadrature to 1e-14 on the first history interval and on a part of it, where
    three Gauss-Legendre nodes in ``tau`` err by 1e-6 or more."""
    from scipy.integrate import quad

    from vibrofriction.solver.mdr_continuum import _jacobi

    a, h = 1.5, 0.05
    ttd = 2.0 * math.pi - math.acos(-1.0 / a)
    p = np.polynomial.Polynomial([0.3, -1.2, 0.8, 2.0, -1.5, 0.7])  # u(tau - ttd), a quintic
    dp, ddp = p.deriv(), p.deriv(2)
    HS = np.zeros((2, mc.N_HS))
    for i, s in enumerate((0.0, h)):
        HS[i, mc.HT], HS[i, mc.HU], HS[i, mc.HD], HS[i, mc.HDD] = ttd + s, p(s), dp(s), ddp(s)
    prm = np.zeros(mc.N_PRM)
    prm[mc.P_GJX:] = _jacobi(n)

    def integrand(t):
        return max(0.0, 1.0 + a * math.cos(t)) ** (1.0 / n) * dp(t - ttd)

    for t0 in (ttd, ttd + h / 3.0):
        ref, _ = quad(integrand, t0, ttd + h, epsabs=1e-15, epsrel=1e-13, limit=200)
        assert mc._wint(HS, 0, t0, ttd + h, a, n, prm) == pytest.approx(ref, abs=1e-14)
    gl3 = sum(w * integrand(ttd + 0.5 * h * (1.0 + x))
              for x, w in zip(mc.GL_X, mc.GL_W, strict=True))
    ref, _ = quad(integrand, ttd, ttd + h, epsabs=1e-15, epsrel=1e-13, limit=200)
    assert abs(0.5 * h * gl3 - ref) > 1e-6 * abs(ref)


def test_a_step_misses_the_touchdown_integrand():
    """Why the touch-down's integral is taken apart: Dormand-Prince's own weights give
    0.655 for ``int_0^1 s^(1/2) ds = 2/3`` (docs/contact_geometry.md)."""
    from vibrofriction._kernels import dopri as d

    weights = (d._B1, 0.0, d._B3, d._B4, d._B5, d._B6)
    nodes = (0.0, d._C2, d._C3, d._C4, d._C5, 1.0)
    got = sum(b * c ** 0.5 for b, c in zip(weights, nodes, strict=True))
    assert got == pytest.approx(0.655, abs=5e-4)
    assert abs(got - 2.0 / 3.0) > 0.01


def test_jumping_routes_to_the_continuum():
    """``mdr_friction`` answers a jumping point with the continuum."""
    r = mdr_friction(0.5, 4.0, 1.5, 0.3, 2.0, zeta=0.1, tol=1e-8)
    assert r["rows"] == () and r["status"] == "periodic" and r["error"] <= 1e-8


def test_search_error_bounds_the_distance_to_the_orbit():
    """A jumping point's search-error term (Newton's step from the last map's start, by
    differences): from states off the orbit ``x*`` (found by 80 plain periods of a damped
    point), the last map's ``int F`` lies within the term of the orbit's, and the term is
    not ten times more (to first order it is twice that distance)."""
    from vibrofriction.solver.mdr_continuum import _flight_map, _parameters, _search_error

    prm = _parameters(0.5, 4.0, 1.5, 0.3, 2.0, 0.3, 0.0, 0.0)
    t, rtol = math.pi, 1e-10
    x = np.array([-0.8, 0.3])
    for _ in range(80):
        x = _flight_map(prm, t, x[0], x[1], rtol)[:2]
    w_orbit = _flight_map(prm, t, x[0], x[1], rtol)[2]
    for e in ([1e-5, 0.0], [0.0, 1e-5], [-1e-5, 2e-5]):
        start = x + np.array(e)
        m = _flight_map(prm, t, start[0], start[1], rtol)
        bound = _search_error(prm, t, start, m[:2], rtol)
        true = abs(m[2] - w_orbit)
        assert true > 1e-8  # (well above the maps' noise)
        assert true <= bound <= 10.0 * true


def test_a_creeping_soft_pin_is_extrapolated_and_agrees_with_the_reference():
    """A soft pin sliding slowly (``alpha = 0.05``, ``V = 0.01``): the body sticks to the
    substrate while the spring loads, about 200 periods of creep before it slips. The
    mixing cannot extrapolate that nearly neutral move (it ran out of 200 periods), the
    creep's doubling steps can: an orbit within far fewer periods, and within the stated
    error plus the bar of the independent spring row run 800 periods into its motion."""
    from vibrofriction_reference.mdr import mdr_reference

    c = continuum_friction(0.05, 20.0, 0.5, 0.01, 2.0, 0.0, 0.0, 0.0, (0.0, 0.0), 1e-7)
    assert c["status"] == "periodic", c["reason"]
    assert c["periods"] < 60 and c["error"] <= 1e-7
    ref = mdr_reference(0.05, 20.0, 0.5, 0.01, 2.0, transient_periods=800,
                        average_periods=50)
    assert ref.mu_error < 1e-4
    assert abs(c["mu_ratio"] - ref.mu_ratio) <= c["error"] + ref.mu_error


def test_mixed_work_is_int_f_at_the_fixed_point_of_an_affine_map():
    """The search's estimate of ``int F`` on the orbit (:func:`_mixed_work`): for an affine
    period map ``g(x) = x* + J (x - x*)`` and an ``int F`` affine in the start,
    ``W(x) = w* + c . (x - x*)``, the mixing's coefficients (type II Anderson, as in
    ``steady``) carry the history's ``int F`` to ``w*`` exactly (to round-off)."""
    rng = np.random.default_rng(7)
    for _ in range(20):
        nx = int(rng.integers(2, 5))
        xs = rng.normal(size=nx)
        J = 0.6 * rng.normal(size=(nx, nx)) / math.sqrt(nx)
        c, ws = rng.normal(size=nx), float(rng.normal())
        X = xs + rng.normal(size=(nx + 1, nx))  # nx + 1 starts: nx differences span
        G = xs + (X - xs) @ J.T
        W = ws + (X - xs) @ c
        dF = ((G[1:] - X[1:]) - (G[:-1] - X[:-1])).T
        gam = np.linalg.lstsq(dF, G[-1] - X[-1])[0]
        x_mixed = G[-1] - (G[1:] - G[:-1]).T @ gam
        np.testing.assert_allclose(x_mixed, xs, atol=1e-10)  # the map's fixed point
        assert mc._mixed_work(W, nx + 1, gam) == pytest.approx(ws, abs=1e-10)
