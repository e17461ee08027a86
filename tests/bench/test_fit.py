"""Fitting measured friction curves (vibrofriction.bench.fitting): recovery, on data made by the
model and by the independent reference; honest uncertainties and an honest verdict;
constraints that never override ``free``; rows the model cannot evaluate; save and load."""

import json
import math
from pathlib import Path

import numpy as np
import pytest
from scipy.stats import binom

import vibrofriction as vf
from vibrofriction.bench.fitting import FitResult, predict_cof, synthetic_measurements
from vibrofriction.bench.fitting.problem import Problem
from vibrofriction.figures import plot_fit
from vibrofriction.solver import SolverSettings, solve_points

DATA = Path(__file__).resolve().parents[1] / "data"
TRUE = vf.from_bench(natural_frequency_hz=800.0, mass=0.01, quality_factor=50.0,
                              normal_load=20.0, k_zc=2e7, k_xc=1.5e7, drive_frequency_hz=1000.0,
                              du_z=0.5e-6, mu0=0.3)
#: a solver given too few periods to converge anywhere: nothing it returns is trusted
STARVED = SolverSettings(max_periods=1, min_periods=1)  # no Newton attempt


def synthetic(true: vf.Physical, amplitudes, rng, sigma=0.003, n=20, v=(1e-3, 0.2)):
    return synthetic_measurements(true, amplitudes, np.geomspace(*v, n), sigma, rng)


def _columns(data):
    return data.v0.to_numpy(), data.du_z.to_numpy(), data.omega.to_numpy()


# --- point 1: only trusted values -----------------------------------------------------

def test_predict_cof_is_nan_where_the_solver_does_not_trust_its_value():
    """A starved solver trusts its values at the fast points only (steady sliding is
    certified at once); the slow ones keep finite window means, which used to stand in.
    ``predict_cof`` is nan exactly there, and agrees with the unstarved solver elsewhere."""
    v0 = np.geomspace(1e-3, 0.2, 8)
    du, om = np.full(8, 0.6e-6), np.full(8, TRUE.omega)
    starved = predict_cof(TRUE, v0, du, om, STARVED)
    alpha, beta, a, zeta, eta = TRUE.groups(du, om)
    V = v0 * TRUE.mass * TRUE.omega / (TRUE.mu0 * TRUE.F_N0)  # Fig. 6
    raw = solve_points(alpha, beta, a, V, zeta, eta, settings=STARVED)
    untrusted = ~raw["trusted"]
    assert 0 < untrusted.sum() < 8
    assert np.all(np.isfinite(raw["window_min"] + raw["window_max"])[untrusted])
    assert np.array_equal(np.isnan(starved), untrusted)
    good = predict_cof(TRUE, v0, du, om)
    assert np.all(np.isfinite(good)) and np.all((0 < good) & (good <= TRUE.mu0))
    assert starved[~untrusted] == pytest.approx(good[~untrusted], abs=1e-5)


def test_synthetic_measurements_refuse_an_untrusted_truth():
    with pytest.raises(ValueError, match="no trusted value of the truth at 4 of 4 points"):
        synthetic_measurements(TRUE, (0.5e-6,), np.geomspace(1e-3, 5e-3, 4), 0.003,
                               np.random.default_rng(0), settings=STARVED)


# --- point 3: rows the model cannot evaluate -------------------------------------------

def _problem(data, settings=None, free=("mu0",)):
    return Problem(TRUE, free, True, True, True, data, settings, mu0_max=TRUE.mu0 * 10)


def test_an_unevaluable_row_costs_more_than_any_honest_misfit_even_with_a_small_sigma():
    """With sigma = 1e-5 an honest misfit of 0.1 in the COF is a residual of 1e4 (the old
    flat penalty was 1e3): every row the solver cannot evaluate must still cost more than
    the worst honest residual of that row over the whole search range of mu0."""
    data = synthetic(TRUE, (0.3e-6, 0.9e-6), np.random.default_rng(1), sigma=1e-5, n=6,
                     v=(1e-3, 5e-3))
    honest = _problem(data)
    worst = np.zeros(len(data))
    for mu0 in np.geomspace(TRUE.mu0 / 10, TRUE.mu0 * 10, 9):
        r, outside, untrusted = honest.evaluate(np.array([math.log(mu0)]))
        assert outside == untrusted == 0
        worst = np.maximum(worst, np.abs(r))
    assert worst.max() > 1e3  # the old penalty would have rewarded failing here
    r, outside, untrusted = _problem(data, STARVED).evaluate(np.array([math.log(TRUE.mu0)]))
    bad = np.isnan(predict_cof(TRUE, *_columns(data), STARVED))
    assert outside == 0 and untrusted == bad.sum() > 0
    assert np.all(np.abs(r[bad]) > worst[bad])


def test_a_model_error_is_not_turned_into_a_chi_square(monkeypatch):
    data = synthetic(TRUE, (0.5e-6,), np.random.default_rng(2), n=4)

    def broken(*args, **kwargs):
        raise ValueError("a programming error")

    monkeypatch.setattr("vibrofriction.bench.fitting.problem.solve_points", broken)
    with pytest.raises(ValueError, match="a programming error"):
        _problem(data).residual(np.array([math.log(0.3)]))
    with pytest.raises(ValueError, match="a programming error"):  # the global stage's call
        _problem(data).costs(np.full((1, 3), math.log(0.3)), map_=_serial, chunks=2)


def _serial(func, items):
    return [func(item) for item in items]


def test_a_generation_costs_what_its_members_cost_one_by_one():
    """The global stage's vectorised call (a generation's rows solved together, split
    into interleaved tasks) gives each member the chi-square of its own evaluation, a
    member outside the model's domain included."""
    data = synthetic(TRUE, (0.3e-6, 0.9e-6), np.random.default_rng(3), n=5)
    problem = _problem(data)
    members = np.array([[math.log(0.3), math.log(0.2), math.log(0.45), -1e4]])  # exp: 0
    costs = problem.costs(members, map_=_serial, chunks=3)
    one_by_one = [problem.cost(x) for x in members.T]
    assert np.array_equal(costs, one_by_one)
    assert costs[0] < costs[1] and costs[0] < costs[2]


def test_penalised_rows_are_counted_and_make_the_fit_poor(monkeypatch):
    """A model whose solver never trusts the slowest velocity of the table: the two rows
    there are penalised wherever the fit goes, counted at the best fit and in the verdict."""
    data = synthetic(TRUE, (0.3e-6, 0.9e-6), np.random.default_rng(3), n=4)
    real = solve_points

    def untrusted_at_the_slowest(alpha, beta, a, v_inertial, *args, **kwargs):
        out = real(alpha, beta, a, v_inertial, *args, **kwargs)
        out["trusted"] = out["trusted"] & (v_inertial != np.min(v_inertial))
        return out

    monkeypatch.setattr("vibrofriction.bench.fitting.problem.solve_points",
                        untrusted_at_the_slowest)
    res = vf.fit(data, TRUE.with_(mu0=0.35), free=["mu0"], progress=False,
                 global_stage=False)
    assert res.penalised == {"untrusted": 2, "outside the model's domain": 0}
    assert res.params["mu0"].value == pytest.approx(TRUE.mu0, rel=0.02)  # the rest fits
    assert res.quality == "poor"
    first = res.report().splitlines()[0]
    assert first.startswith("POOR FIT") and "2 rows could not be evaluated" in first


# --- point 2: free means fitted; every constraint stated; an honest verdict -------------

@pytest.mark.parametrize("kwargs, message", [
    (dict(free=["mu0", "nope"]), "free must name"),
    (dict(free=[]), "free must name"),
    (dict(free=["mu0", "mu0"]), "twice"),
    (dict(free=["mu0", "mass", "k_x", "k_xc", "u_z0"]),
     r"both mass and k_x.*natural_frequency.*pass natural_frequency=False"),
    (dict(free=["k_zc", "u_z0"], natural_frequency=False),
     r"both k_zc and u_z0.*normal_load.*pass normal_load=False"),
    (dict(free=["c_x"]), r"c_x.*quality_factor.*pass quality_factor=False"),
])
def test_fit_errors(kwargs, message):
    data = synthetic(TRUE, (0.5e-6,), np.random.default_rng(5), n=5)
    with pytest.raises(ValueError, match=message):
        vf.fit(data, TRUE, progress=False, **kwargs)


def test_the_report_states_every_constraint_in_force_and_what_moves():
    data = synthetic(TRUE, (0.3e-6, 0.9e-6), np.random.default_rng(4), n=6)
    res = vf.fit(data, TRUE.with_(mu0=0.35), free=["mu0"], progress=False,
                 global_stage=False)
    text = res.report()
    for line in ("natural_frequency: k_x = mass (2 pi x 800 Hz)^2",
                 "normal_load: k_zc u_z0 = F_N0 = 20 N",
                 "quality_factor: c_x = 2 zeta sqrt(k_x mass), zeta = 0.01 (Q = 50)"):
        assert line in text
    assert text.count("release with") == 3
    off = vf.fit(data, TRUE.with_(mu0=0.35), free=["mu0"], progress=False,
                 global_stage=False, natural_frequency=False, normal_load=False,
                 quality_factor=False)
    assert "constraints in force: none" in off.report()


def test_every_named_parameter_is_varied_and_derived_quantities_are_reported():
    """``mass`` and ``k_x`` both free (natural frequency released) move apart from the
    guess's ratio; with ``quality_factor`` the damping ratio is kept and ``c_x`` moves,
    and the report's ``derived`` line says so."""
    data = synthetic(TRUE, (0.3e-6, 0.9e-6), np.random.default_rng(9), n=10)
    guess = TRUE.with_(mass=0.0105, k_x=TRUE.k_x * 0.97).with_damping(zeta=TRUE.zeta)
    res = vf.fit(data, guess, free=["mass", "k_x"], natural_frequency=False,
                 progress=False, global_stage=False)
    assert res.quality == "good"
    for n in ("mass", "k_x"):
        lo, hi = res.intervals[n]
        assert lo <= getattr(TRUE, n) <= hi
        assert getattr(res.system, n) != getattr(guess, n)
    assert res.system.k_x / res.system.mass != pytest.approx(guess.k_x / guess.mass, rel=1e-3)
    assert res.system.zeta == pytest.approx(guess.zeta, rel=1e-12)
    (c_x, c_x_guess) = res.derived()["c_x [N s/m]"]
    assert c_x == pytest.approx(res.system.c_x) and c_x != pytest.approx(c_x_guess, rel=1e-3)
    assert "derived: f_n [Hz]" in res.report() and "c_x [N s/m]" in res.report()


@pytest.mark.slow
def test_a_wrong_constraint_gives_a_poor_verdict_and_intervals_that_hold_the_truth(tmp_path):
    """The guess's natural frequency is 14 % high and ``natural_frequency`` holds it: the
    fit cannot reach the truth.  Its profile intervals (conditional on the fit being right)
    exclude the truth; the verdict says the fit is poor, first, and the reported intervals
    (the search range) hold the truth."""
    data = synthetic(TRUE, (0.3e-6, 0.9e-6), np.random.default_rng(10), n=10)
    guess = TRUE.with_(k_x=TRUE.k_x * 1.3, mu0=0.35)
    res = vf.fit(data, guess, free=["mu0", "mass"], progress=False, global_stage=False)
    assert res.quality == "poor" and res.p_value < 1e-3
    assert res.report().startswith("POOR FIT: chi-square")
    profile = res.extra["profile_intervals"]
    assert any(not lo <= getattr(TRUE, n) <= hi for n, (lo, hi) in profile.items())
    for n in ("mu0", "mass"):
        lo, hi = res.intervals[n]
        assert lo <= getattr(TRUE, n) <= hi
        assert (lo, hi) == pytest.approx((getattr(guess, n) / 10, getattr(guess, n) * 10))
    assert "search range (the fit is poor)" in res.report()
    assert res.report().splitlines()[1].startswith("what the data hold: nothing while the fit "
                                                   "is poor")
    assert set(res.determination.values()) == {"not determined"}
    back = FitResult.from_json(res.to_json(tmp_path / "fit.json"))
    assert back.intervals == res.intervals and back.report().splitlines()[0] == \
        res.report().splitlines()[0]
    for n, interval in profile.items():
        assert back.extra["profile_intervals"][n] == pytest.approx(interval)


def test_an_understated_sigma_gives_a_poor_verdict_and_profiles_scaled_by_it():
    """The noise 4x the stated sigma: chi-square probability far below 1e-3, so the fit is
    poor; its profile intervals widen by the square root of the reduced chi-square."""
    rng = np.random.default_rng(7)
    data = synthetic(TRUE, (0.3e-6, 0.9e-6), rng, n=12)
    noisy = data.assign(cof=data.cof + rng.normal(0.0, 4 * 0.003, len(data)))
    fair = vf.fit(data, TRUE, free=["mu0"], progress=False, global_stage=False)
    poor = vf.fit(noisy, TRUE, free=["mu0"], progress=False, global_stage=False)
    assert fair.quality == "good" and fair.p_value > 1e-3
    assert poor.quality == "poor" and poor.p_value < 1e-3
    assert fair.report().startswith("GOOD FIT") and poor.report().startswith("POOR FIT")
    (lo, hi), (plo, phi) = fair.intervals["mu0"], poor.extra["profile_intervals"]["mu0"]
    ratio = (phi - plo) / (hi - lo)
    assert ratio == pytest.approx(math.sqrt(poor.redchi / max(fair.redchi, 1.0)), rel=0.05)
    assert poor.intervals["mu0"] == pytest.approx((TRUE.mu0 / 10, TRUE.mu0 * 10))


def test_a_chi_square_probability_between_1e_3_and_5_percent_makes_the_fit_doubtful():
    """Weighted least squares is unchanged by a common factor on sigma, which scales the
    chi-square by its inverse square: chosen so that p = 0.01, the verdict is doubtful,
    the report says so first, and the global search ran a second stage looking for a
    lower valley (at p = 0.5 it does not)."""
    from scipy.stats import chi2

    rng = np.random.default_rng(7)
    data = synthetic(TRUE, (0.3e-6, 0.9e-6), rng, n=12)
    fair = vf.fit(data, TRUE, free=["mu0"], progress=False, global_stage=False)
    dof = len(data) - 1
    for p, quality, stages in ((0.01, "doubtful", 2), (0.5, "good", 1)):
        scale = math.sqrt(fair.chisqr / chi2.isf(p, dof))
        res = vf.fit(data.assign(sigma=data.sigma * scale), TRUE, free=["mu0"],
                     progress=False, starts=2, screen=8)
        assert res.p_value == pytest.approx(p, rel=1e-3)
        assert res.quality == quality
        assert res.report().startswith("DOUBTFUL FIT" if quality == "doubtful" else "GOOD")
        conditional = "95 % interval if this minimum is the right one" in res.report()
        assert conditional == (quality == "doubtful")
        assert [r["stage"] for r in res.extra["stages"]].count("global") == stages
        assert res.intervals["mu0"][0] < res.params["mu0"].value < res.intervals["mu0"][1]


def test_an_unweighted_fit_is_not_judged():
    data = synthetic(TRUE, (0.3e-6, 0.9e-6), np.random.default_rng(11), n=6)
    res = vf.fit(data.drop(columns="sigma"), TRUE.with_(mu0=0.35), free=["mu0"],
                 progress=False, global_stage=False)
    assert res.quality == "unjudged" and math.isnan(res.p_value)
    assert res.report().startswith("FIT NOT JUDGED")


# --- point 7: tests that can fail -----------------------------------------------------

@pytest.mark.slow
def test_coverage_of_the_profile_intervals_is_consistent_with_95_percent():
    """160 seeded data sets, mu0 fitted alone (its profile is the chi-square itself): the
    count of intervals that hold the truth is a binomial draw of probability 0.954 (a bit
    more: ``s^2 >= 1`` widens some).  Refused if either tail has probability below 1e-3:
    too few (overconfident) or all of them (intervals too wide to mean anything)."""
    rng = np.random.default_rng(2027)
    n, hits = 160, 0
    for _ in range(n):
        true = TRUE.with_(mu0=float(rng.uniform(0.2, 0.5)),
                          k_xc=float(rng.choice([5e6, 1.5e7, 6e7])))
        data = synthetic(true, (0.3e-6, 0.9e-6), rng, n=6)
        res = vf.fit(data, true.with_(mu0=true.mu0 * 1.1), free=["mu0"], progress=False,
                     global_stage=False)
        lo, hi = res.intervals["mu0"]
        hits += lo <= true.mu0 <= hi
    print(f"coverage {hits}/{n}")
    assert binom.cdf(hits, n, 0.954) > 1e-3, hits  # not overconfident
    assert binom.sf(hits - 1, n, 0.954) > 1e-3, hits  # not vacuous (refuses hits == n)


def test_a_quasi_static_curve_does_not_bound_the_mass_and_the_fit_says_so():
    """Stiff springs (alpha, beta ~ 0.0025, 0.0076): inertia is negligible, so the curve
    barely depends on the mass (checked directly: the chi-square moves by less than the
    profile level between mass / 10 and x 10).  A fit of the mass must then report it
    unbounded on both sides, and the pair (mass, k_x) as not identified, while ``mu0``
    from the same data is bounded and holds the truth."""
    stiff = vf.Physical(mass=1.0, k_x=1e3, k_xc=2e3, k_zc=2.5e3, u_z0=4e-3, du_z=2e-3,
                        omega=2 * math.pi * 100, mu0=0.3)
    data = synthetic(stiff, (2e-3,), np.random.default_rng(3), v=(1e-3, 0.5), n=15)

    def chi2(p):
        return float(np.sum(((predict_cof(p, *_columns(data)) - data.cof) / data.sigma) ** 2))

    flat = [chi2(stiff.with_(mass=m)) for m in (0.1, 1.0, 10.0)]
    assert max(flat) - min(flat) < 4.0
    pair = vf.fit(data, stiff.with_(mass=1.5, k_x=2e3), free=["mass", "k_x"],
                  natural_frequency=False, progress=False, starts=2, screen=8)
    assert any(("mass and k_x" in w or "k_x and mass" in w) and "not identified" in w
               for w in pair.warnings), pair.warnings
    # the report's second line: neither is determined (the curve barely moves with the mass,
    # and not at all with k_x: no combination of the two is held either)
    assert pair.determination == {"mass": "not determined", "k_x": "not determined"}
    assert pair.report().splitlines()[1] == "what the data hold: mass, k_x not determined"
    assert pair.params["mass"].stderr is None and pair.params["k_x"].stderr is None
    mass = vf.fit(data, stiff.with_(mass=1.5), free=["mass"], natural_frequency=False,
                  progress=False, global_stage=False)
    assert mass.intervals["mass"] == (-math.inf, math.inf)
    assert "[unbounded below, unbounded above]" in mass.report()
    mu0 = vf.fit(data, stiff.with_(mu0=0.35), free=["mu0"], natural_frequency=False,
                 progress=False, global_stage=False)
    lo, hi = mu0.intervals["mu0"]
    assert lo <= stiff.mu0 <= hi and hi / lo < 1.1


REFERENCE = json.loads((DATA / "reference_bench.json").read_text())
REFERENCE_TRUTH = vf.Physical(**REFERENCE["truth"])


def test_the_reference_data_set_is_what_its_json_says():
    """tests/data/reference_bench.csv (made by vibrofriction_reference, peer B, with
    tests/data/make_reference_bench.py): its scatter about the solver's curve at the truth
    is the stated sigma (chi-square probability not extreme), and the reference's error
    bar is far below it."""
    data = vf.read_measurements(DATA / "reference_bench.csv")
    assert len(data) == 48 and np.all(data.sigma == REFERENCE["sigma"])
    assert REFERENCE["reference_error_bar_cof"] < 0.01 * REFERENCE["sigma"]
    model = predict_cof(REFERENCE_TRUTH, *_columns(data))
    chi2 = float(np.sum(((model - data.cof) / data.sigma) ** 2))
    from scipy.stats import chi2 as chi2_dist
    assert 1e-3 < chi2_dist.sf(chi2, len(data)) < 1 - 1e-3, chi2


@pytest.mark.slow
def test_fit_to_reference_data_holds_the_truth():
    """Held-out data made by the independent reference, mu0 and k_xc off by 1.3 and 1.6:
    the 95 % intervals hold the truth, or the verdict says the fit is poor (and then the
    intervals, the search range, hold it anyway).  About 15 s."""
    data = vf.read_measurements(DATA / "reference_bench.csv")
    guess = REFERENCE_TRUTH.with_(mu0=0.39, k_xc=4.8e6)
    res = vf.fit(data, guess, free=["mu0", "k_xc"], progress=False, workers=1)
    assert res.quality in ("good", "doubtful", "poor")
    for n in ("mu0", "k_xc"):
        lo, hi = res.intervals[n]
        assert lo <= getattr(REFERENCE_TRUTH, n) <= hi, (n, lo, hi, res.report())


@pytest.mark.slow
def test_fit_of_four_parameters_to_reference_data_holds_the_truth_or_says_it_is_poor():
    """The issue's case: held-out reference data, four free parameters (k_x follows the
    mass at the measured natural frequency, k_zc follows u_z0 at the applied load), the
    guess off by factors 0.6-1.6 within the search span."""
    data = vf.read_measurements(DATA / "reference_bench.csv")
    guess = vf.from_bench(natural_frequency_hz=800, mass=0.012, quality_factor=50,
                                   normal_load=20, k_zc=2.8e7, k_xc=4.8e6,
                                   drive_frequency_hz=1000, du_z=0.6e-6, mu0=0.39)
    res = vf.fit(data, guess, free=["mu0", "mass", "k_xc", "u_z0"], progress=False,
                 workers=1)
    print(res.report())
    for n in ("mu0", "mass", "k_x", "k_xc", "u_z0", "k_zc"):
        lo, hi = res.intervals[n]
        assert lo <= getattr(REFERENCE_TRUTH, n) <= hi, (n, lo, hi, res.quality)


@pytest.mark.slow
def test_noise_free_data_give_back_the_parameters():
    data = synthetic(TRUE, (0.3e-6, 0.6e-6, 0.9e-6), np.random.default_rng(0), sigma=1e-6)
    # the experimenter's guess: the measured f_n and Q, a wrong modal mass, k_xc and mu0
    guess = vf.from_bench(natural_frequency_hz=800.0, mass=0.015, quality_factor=50.0,
                                   normal_load=20.0, k_zc=2e7, k_xc=3e7,
                                   drive_frequency_hz=1000.0, du_z=0.5e-6, mu0=0.4)
    res = vf.fit(data, guess, free=["mu0", "mass", "k_xc"], progress=False)
    for n in ("mu0", "mass", "k_x", "k_xc"):
        assert res.params[n].value == pytest.approx(getattr(TRUE, n), rel=1e-3)
    assert res.system.k_x / res.system.mass == pytest.approx(TRUE.k_x / TRUE.mass, rel=1e-12)
    assert res.system.quality_factor == pytest.approx(50.0, rel=1e-12)


# --- point 8: unbounded intervals, singular covariance; save and load --------------------

def test_an_interval_unbounded_below_is_reported_and_saved_as_unbounded(tmp_path):
    """Data of an undamped contact, ``c_xc`` fitted: a small dashpot changes nothing, so
    the profile never rises below (not "bounded at 0"), while a large one is excluded."""
    data = synthetic(TRUE, (0.3e-6, 0.9e-6), np.random.default_rng(1), n=10)
    res = vf.fit(data, TRUE.with_damping(eta_c=0.05), free=["c_xc"], progress=False,
                 global_stage=False)
    lo, hi = res.intervals["c_xc"]
    assert lo == -math.inf and math.isfinite(hi)
    assert "unbounded below" in res.report()
    saved = json.loads(res.to_json(tmp_path / "fit.json").read_text())
    assert saved["intervals"]["c_xc"][0] is None
    back = FitResult.from_json(tmp_path / "fit.json")
    assert back.intervals == res.intervals
    assert "unbounded below" in back.report()


def test_a_singular_covariance_is_warned_about():
    """A rigid contact ignores ``c_xc``: the Jacobian's column is zero, the least-squares
    covariance singular, and the interval unbounded on both sides."""
    rigid = TRUE.with_(k_xc=math.inf)
    data = synthetic(rigid, (0.3e-6, 0.9e-6), np.random.default_rng(1), n=6)
    res = vf.fit(data, rigid.with_(c_xc=1.0), free=["c_xc"], progress=False,
                 global_stage=False)
    assert any("covariance of c_xc is singular" in w for w in res.warnings)
    assert res.intervals["c_xc"] == (-math.inf, math.inf)
    regular = vf.fit(data, rigid.with_(mu0=0.35), free=["mu0"], progress=False,
                     global_stage=False)
    assert not any("singular" in w for w in regular.warnings)


def test_save_and_load(tmp_path):
    data = synthetic(TRUE, (0.3e-6, 0.9e-6), np.random.default_rng(4), n=10)
    res = vf.fit(data, TRUE.with_(mu0=0.35), free=["mu0"], progress=False, global_stage=False)
    back = FitResult.from_json(res.to_json(tmp_path / "fit.json"))
    assert back.params["mu0"].value == res.params["mu0"].value
    assert back.params["mu0"].stderr == res.params["mu0"].stderr
    assert back.system == res.system and back.free == res.free
    assert back.intervals == res.intervals
    assert (back.quality, back.p_value, back.penalised) == (res.quality, res.p_value,
                                                            res.penalised)
    assert back.extra["at_lowest_minimum"] is True
    assert back.report().splitlines()[0] == res.report().splitlines()[0]
    assert "mu0" in back.report() and "95 % interval" in back.report()
    fig = plot_fit(res)
    assert len(fig.axes) == 2


@pytest.mark.slow
def test_profile_interval_is_where_chi_square_rises_by_four():
    """One free parameter: its profile is chi-square itself.  Scanned on a fine grid of
    ``mu0`` with :func:`predict_cof` (``mu0`` also sets the velocity scale, so the curve
    is not a parabola), the rise by ``4 s^2`` (``s^2`` the reduced chi-square, at least 1)
    is met where the fit's interval ends."""
    data = synthetic(TRUE, (0.3e-6, 0.9e-6), np.random.default_rng(6), n=12)
    res = vf.fit(data, TRUE.with_(mu0=0.4), free=["mu0"], progress=False, global_stage=False)
    cols = _columns(data)

    def chi2(mu0):
        r = (predict_cof(TRUE.with_(mu0=mu0), *cols) - data.cof) / data.sigma
        return float(np.sum(r * r))

    best, lo, hi = res.params["mu0"].value, *res.intervals["mu0"]
    assert lo < best < hi
    level = 4.0 * max(res.redchi, 1.0)
    for end in (lo, hi):
        grid = np.linspace(best, best + 1.5 * (end - best), 301)
        rise = np.array([chi2(m) for m in grid]) - chi2(best)
        k = int(np.argmax(rise > level))
        crossing = np.interp(level, rise[k - 1:k + 1], grid[k - 1:k + 1])
        assert end == pytest.approx(crossing, abs=0.03 * abs(crossing - best))
    assert res.params["mu0"].stderr == pytest.approx(max(best - lo, hi - best) / 2)


@pytest.mark.slow
def test_two_parameter_profile_ends_where_the_minimum_over_the_other_rises_by_four():
    """Two free parameters (``mu0``, ``k_xc``): at each end of the ``k_xc`` interval the
    chi-square minimised over ``mu0`` alone (bounded scalar search, independent of the
    fit's refits) has risen by ``4 s^2`` from the best fit, to the bisection's 3 %."""
    from scipy.optimize import minimize_scalar

    data = synthetic(TRUE, (0.3e-6, 0.9e-6), np.random.default_rng(8), n=12)
    guess = TRUE.with_(mu0=0.35, k_xc=2e7)
    # from this guess the least squares alone stop in a wrong valley (k_xc 2.3e7 against
    # 1.5e7, chi-square 69.9 for 22 degrees of freedom); without the global search the
    # verdict says so, or the profiles met the right valley and the fit restarted there
    local = vf.fit(data, guess, free=["mu0", "k_xc"], progress=False, global_stage=False)
    res = vf.fit(data, guess, free=["mu0", "k_xc"], progress=False, workers=1)
    assert (local.quality == "poor" and local.p_value < 1e-3) or (
        local.chisqr == pytest.approx(res.chisqr, abs=0.1)), local.report()
    assert res.quality == "good", res.report()
    cols = _columns(data)

    def profile(k_xc):
        def chi2(mu0):
            r = (predict_cof(TRUE.with_(mu0=mu0, k_xc=k_xc), *cols) - data.cof) / data.sigma
            return float(np.sum(r * r))
        mu0 = res.params["mu0"].value
        return minimize_scalar(chi2, bounds=(0.8 * mu0, 1.2 * mu0), method="bounded",
                               options={"xatol": 1e-7}).fun

    best, (lo, hi) = res.params["k_xc"].value, res.intervals["k_xc"]
    level = 4.0 * max(res.redchi, 1.0)
    for end in (lo, hi):
        d = math.log(end / best)
        inside, outside = (profile(best * math.exp(f * d)) - res.chisqr for f in (0.97, 1.03))
        assert inside < level < outside, (end, inside, outside, level)
