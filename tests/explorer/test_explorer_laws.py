"""The explorer's friction-law selector: the State, the curve, the exports and the history.

Every expected value is the library's own, called here on a system built by hand (not through
the explorer), or a number written out (units, the law's limits).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import vibrofriction as vf
from vibrofriction import theory
from vibrofriction.explorer import compute, exports, texts
from vibrofriction.explorer.messages import LAW, law_refusal, law_taken, read_inputs
from vibrofriction.explorer.state import LAW_DISABLED, LAW_POINTS, State

RS = dict(rs_a=0.03, rs_b=0.01, rs_d_c=0.02, rs_v_ref=0.2, rs_alpha_ld=0.0)


def test_the_state_carries_each_law_and_applies_only_the_chosen_one():
    base = vf.Dimensionless(0.5, 2.0, 0.5)
    assert State(static_ratio=2.0, rs_a=0.5).system() == base  # Coulomb: kept, not applied
    assert State(friction="static", static_ratio=1.5).system() == \
        vf.Dimensionless(0.5, 2.0, 0.5, static_ratio=1.5)
    assert State(friction="rate_state", rs_law="slip", **RS).system() == \
        vf.Dimensionless(0.5, 2.0, 0.5, rs_law="slip", **RS)
    bench = State(mode="bench", friction="static", mu_static=0.45).system()
    assert isinstance(bench, vf.Physical) and bench.mu_static == 0.45 and bench.mu0 == 0.3
    rs = State(mode="bench", friction="rate_state", friction_a=0.01, friction_b=0.02,
               friction_d_c_um=2.0, friction_v_ref_mm_s=5.0, friction_alpha_ld=0.005,
               rs_law="slip").system()
    assert isinstance(rs, vf.Physical)  # d_c typed in um, v_ref in mm/s: SI by hand
    assert rs.friction == vf.RateAndState(a=0.01, b=0.02, d_c=2e-6, v_ref=5e-3,
                                          alpha_ld=0.005, law="slip")


@pytest.mark.parametrize("state", [
    State(friction="static", static_ratio=1.75),
    State(friction="rate_state", rs_law="slip", **RS),
    State(mode="bench", friction="rate_state", friction_d_c_um=0.25, axis="v0", v_min=1e-3,
          v_max=0.05),
])
def test_a_law_round_trips_through_the_url(state):
    back, problems = State.from_query(state.to_query())
    assert problems == {} and back == state


def test_the_url_refuses_an_unknown_law_by_name():
    state, problems = State.from_query({"friction": "viscous", "rs_law": "aged"})
    assert state.friction == "coulomb" and state.rs_law == "aging"
    assert "friction must be one of" in problems["friction"]
    state, problems = State.from_query({"rs_law": "aged"})
    assert "rs_law must be one of" in problems["rs_law"]


def test_rest_and_points_under_a_law():
    assert not State().rest_refused
    assert State(friction="static").rest_refused and State(friction="rate_state").rest_refused
    assert State(friction="rate_state").curve_points == LAW_POINTS == 40
    assert State(friction="static").curve_points == 200
    from vibrofriction.explorer.texts import status_text

    assert status_text(State(friction="rate_state")).startswith(
        "computing 40 points by the rate-and-state solver")


def test_static_above_kinetic_changes_the_curve_as_the_library_does():
    state = State(friction="static", static_ratio=1.5, points=15)
    c = compute.curve(state)
    vbar = np.linspace(0.0, 1.5, 15)[1:]  # V = 0 left out: no static limit at rest
    np.testing.assert_array_equal(c["x"], vbar)
    r = vf.friction_coefficient(vf.Dimensionless(0.5, 2.0, 0.5, static_ratio=1.5), vbar=vbar)
    np.testing.assert_array_equal(c["y"], r.mu_ratio)
    coulomb = vf.friction_coefficient(vf.Dimensionless(0.5, 2.0, 0.5), vbar=vbar)
    assert np.nanmax(np.abs(c["y"] - coulomb.mu_ratio)) > 1e-3  # the law changes the curve
    assert "static_ratio = 1.5" in c["rest_note"] and "v_inertial = 0" in c["rest_note"]
    assert math.isnan(c["static"]) and c["closed_forms"] == []  # eq. (2) is Coulomb's
    assert c["critical"] == 1.0  # continuous sliding sets in where Coulomb's does


def test_rate_and_state_curve_and_its_steady_sliding():
    state = State(friction="rate_state", axis="V", v_min=0.0, v_max=2.0, points=5, **RS)
    c = compute.curve(state)
    V = np.linspace(0.0, 2.0, 5)[1:]
    system = vf.Dimensionless(0.5, 2.0, 0.5, **RS)
    np.testing.assert_array_equal(c["x"], V)
    np.testing.assert_array_equal(c["y"], vf.friction_coefficient(system, v_inertial=V).mu_ratio)
    assert set(c["method"]) == {"rate_state"}
    assert compute.solver_text(c) == "rate-and-state solver"  # the plot's title
    (form,) = c["closed_forms"]
    np.testing.assert_allclose(form["y"], theory.steady_mu_ratio(V, 0.03, 0.01, 0.02, 0.2),
                               rtol=1e-14)
    # velocity strengthening (b < a): mu_ss(v) ~ 1 + (a - b) ln(v/v_ref) rises with v
    assert np.all(np.diff(form["y"]) > 0.0)
    assert form["y"][-1] == pytest.approx(1.0 + 0.02 * math.log(2.0 / 0.2), abs=1e-3)
    assert math.isnan(c["critical"])  # eq. (12) is Coulomb's
    # the contact creeps: the point's text gives no stick or slip fractions, and says so
    said = texts.point_text(c, 1)
    assert "stick and slip not separated" in said and "none" not in said


@pytest.mark.parametrize("state", [
    State(friction="static", static_ratio=1.4, points=12),
    State(friction="rate_state", rs_law="slip", points=6, **RS),
    State(mode="bench", friction="static", mu_static=0.42, points=10),
    State(mode="bench", friction="rate_state", axis="v0", v_min=1e-3, v_max=0.05, points=5),
])
def test_the_snippet_reproduces_the_curve_with_the_law(state):
    scope: dict = {}
    exec(exports.snippet(state), scope)  # noqa: S102 - the snippet shown to the user
    np.testing.assert_array_equal(np.asarray(scope["y"]), compute.curve(state)["y"])
    csv = exports.curve_csv(state, compute.curve(state))
    assert "friction: " + ("static above kinetic" if state.friction == "static"
                           else "rate-and-state") in csv.splitlines()[0]


@pytest.mark.parametrize("texts, base, field, words", [
    ({"static_ratio": "0.5"}, State(friction="static"), "static_ratio",
     "static_ratio must be finite and >= 1"),
    ({"rs_d_c": "0"}, State(friction="rate_state"), "rs_d_c", "rs_d_c must be finite and > 0"),
    ({"rs_alpha_ld": "0.1", "rs_b": "0"}, State(friction="rate_state"), "rs_alpha_ld",
     "needs rs_b > 0"),
    ({"amplitude": "1.5", "rs_alpha_ld": "0.1"}, State(friction="rate_state"), "rs_alpha_ld",
     "needs amplitude < 1"),
    ({"mu_static": "0.1"}, State(mode="bench", friction="static"), "mu_static",
     "mu_static must be >= mu0 (= 0.3"),
    ({"friction_a": "0"}, State(mode="bench", friction="rate_state"), "friction_a",
     "a must be finite and > 0"),
    ({"friction_d_c_um": "-1"}, State(mode="bench", friction="rate_state"), "friction_d_c_um",
     "d_c must be finite and > 0"),
])
def test_bad_law_input_gives_the_library_message_next_to_it(texts, base, field, words):
    state, problems = read_inputs(texts, base)
    assert state is None and list(problems) == [field]
    assert words in problems[field]


def test_a_rigid_contact_and_contact_damping_are_taken_with_rate_and_state():
    """The rate-and-state solver takes beta = inf and eta_c > 0: no message, the state."""
    state, problems = read_inputs({"beta": "inf", "eta_c": "0.1"},
                                  State(friction="rate_state", axis="V"))
    assert not problems and state is not None
    assert state.beta == math.inf and state.eta_c == 0.1


def test_the_pairs_of_laws_are_refused_under_the_selector():
    from vibrofriction.explorer.messages import field_of

    with pytest.raises(ValueError) as info:
        vf.Dimensionless(0.5, 2.0, 0.5, static_ratio=1.2, rs_a=0.01)
    assert field_of(str(info.value)) == LAW


def test_what_a_law_disables_is_what_its_solvers_refuse():
    """Each input a law disables is refused by the library under it; the others are taken."""
    assert LAW_DISABLED["coulomb"] == ()
    for law in ("static", "rate_state"):
        state = State(friction=law)
        for name in ("eta_c", "a_y", "a_x"):
            why = law_refusal(state, name, 0.5)
            assert (name in LAW_DISABLED[law]) == bool(why), (law, name, why)
    assert law_refusal(State(friction="rate_state"), "eta_c", 0.1) == ""  # taken
    assert "MDR solver" in law_taken(State(friction="rate_state", profile_exponent=2.0))
    assert law_taken(State(friction="rate_state")) == ""


def test_the_history_shows_the_local_coefficient():
    h = compute.history(State(friction="static", static_ratio=1.5), 0.3)
    f, n, mu = h["f"], h["n"], h["coefficient"]
    contact = n > 0.0
    np.testing.assert_array_equal(mu[contact], f[contact] / n[contact])
    assert np.all(np.isnan(mu[~contact]))
    assert h["static_ratio"] == 1.5
    assert np.nanmax(np.abs(mu)) <= 1.5 * (1 + 1e-9)  # a stuck contact holds up to 1.5
    assert np.nanmax(np.abs(mu)) > 1.0 + 1e-3  # above the kinetic coefficient
    slipping = np.isin(h["phase"], ["slip+", "slip-"]) & contact
    np.testing.assert_allclose(np.abs(mu[slipping]), 1.0, rtol=1e-9)  # slips at mu0 n


def test_a_rate_and_state_point_has_theta_and_the_local_coefficient():
    """The history of a rate-and-state point is the library's (its steady state): the state
    theta, the integrator's local coefficient, steady sliding's theta d_c/V and mu_ss/mu_star."""
    state = State(friction="rate_state", axis="V", **RS)
    h = compute.history(state, 0.5)
    system = vf.Dimensionless(0.5, 2.0, 0.5, **RS)
    lib = vf.simulate(system, v_inertial=0.5, periods=3.0, initial="steady")
    assert isinstance(lib, vf.RateStateHistory) and h["steady"]
    np.testing.assert_array_equal(h["theta"], lib.theta)
    np.testing.assert_array_equal(h["coefficient"], lib.local_mu)
    assert h["theta_sliding"] == RS["rs_d_c"] / 0.5
    assert h["sliding_mu_ratio"] == pytest.approx(
        float(theory.steady_mu_ratio(0.5, RS["rs_a"], RS["rs_b"], RS["rs_d_c"],
                                     RS["rs_v_ref"])), rel=1e-14)
    r = vf.friction_coefficient(system, v_inertial=0.5)
    assert h["mu_ratio"] == r.mu_ratio
    assert compute.history(State(), 0.5)["theta"] is None  # Coulomb: no state


def test_the_history_panel_shows_theta_or_the_local_coefficient():
    """The figure below the forces: the local coefficient (with steady sliding's level) or,
    chosen, theta on a log scale (with d_c/V); a Coulomb history keeps its coefficient."""
    pytest.importorskip("bokeh")
    from vibrofriction.explorer.views import HistoryView

    h = compute.history(State(friction="rate_state", axis="V", **RS), 0.5)
    view = HistoryView()
    view.show(h, "V = 0.5")
    assert view.coefficient_figure.visible and not view.theta_figure.visible
    np.testing.assert_array_equal(view.coefficient.data["mu"], h["coefficient"])
    mu_ss = abs(h["sliding_mu_ratio"])
    assert view.levels.data["y"] == [[mu_ss, mu_ss], [-mu_ss, -mu_ss]]
    view.choose("theta")
    assert view.theta_figure.visible and not view.coefficient_figure.visible
    np.testing.assert_array_equal(view.theta.data["theta"], h["theta"])
    assert view.theta_level.data["y"] == [0.04, 0.04]  # d_c/V = 0.02/0.5
    assert view.theta_figure.y_range.start <= np.min(h["theta"])
    assert view.theta_figure.y_range.end >= np.max(h["theta"])
    view.show(compute.history(State(), 0.5), "V = 0.5")  # Coulomb: theta has no meaning
    assert view.coefficient_figure.visible and not view.theta_figure.visible
    assert view.levels.data["level"][0] == "kinetic +-1"
    with pytest.raises(ValueError, match="quantity must be one of coefficient, theta"):
        view.choose("slip")


@pytest.mark.slow
def test_the_selector_shows_the_law_s_inputs_and_disables_what_its_solver_refuses(
        monkeypatch):
    pn = pytest.importorskip("panel")
    from vibrofriction.explorer import page

    monkeypatch.setattr(pn.state, "execute", lambda cb, *a, **k: None)
    ex = page.Explorer(State(eta_c=0.1))
    assert not ex.inputs["rs_a"].layout.visible and not ex.law_note.visible
    ex.law.value = "rate_state"
    # the rate-and-state solver takes contact damping: eta_c stays
    assert ex.state.friction == "rate_state" and ex.state.eta_c == 0.1
    assert ex.inputs["rs_a"].layout.visible and not ex.inputs["static_ratio"].layout.visible
    assert ex.rs_law.visible
    assert not ex.inputs["eta_c"].text.disabled and ex.inputs["a_y"].text.disabled
    assert "at most 40 points" in ex.law_note.object
    ex.inputs["rs_d_c"].text.value = "0"
    assert "rs_d_c must be finite and > 0" in ex.inputs["rs_d_c"].message.object
    assert ex.state.rs_d_c == State().rs_d_c  # the last good state stays
    ex.inputs["rs_d_c"].text.value = "0.05"
    assert ex.state.rs_d_c == 0.05 and not ex.inputs["rs_d_c"].message.visible
    ex.law.value = "static"
    assert not ex.inputs["eta_c"].text.disabled and ex.inputs["static_ratio"].layout.visible
    ex.profile.value = "sphere"  # the MDR solver takes the static coefficient (its declaration)
    assert ex.law.value == "static" and ex.state.friction == "static"
    ex.law.value = "rate_state"  # ... and not rate-and-state friction: back to Coulomb
    assert ex.law.value == "coulomb" and ex.state.friction == "coulomb"
    assert "rate-and-state reset to Coulomb: the MDR solver does not take it yet" in \
        ex.law_note.object
    ex.profile.value = "flat"
    ex.mode.value = "bench"
    ex.law.value = "rate_state"
    assert ex.inputs["friction_d_c_um"].layout.visible and not ex.inputs["rs_d_c"].layout.visible
    assert not ex.inputs["bench_eta_c"].text.disabled
    ex.inputs["friction_v_ref_mm_s"].text.value = "2"
    assert ex.state.system().friction.v_ref == 2e-3


@pytest.mark.slow
def test_the_page_offers_theta_for_a_rate_and_state_history(monkeypatch):
    pn = pytest.importorskip("panel")
    from vibrofriction.explorer import page

    monkeypatch.setattr(pn.state, "execute", lambda cb, *a, **k: None)
    state = State(friction="rate_state", axis="V", **RS)
    ex = page.Explorer(state)
    assert not ex.history_quantity.visible
    ex._show_history(state, compute.history(state, 0.5))
    assert ex.history_quantity.visible and ex.history_view.coefficient_figure.visible
    ex.history_quantity.value = "theta"
    assert ex.history_view.theta_figure.visible
    assert not ex.history_view.coefficient_figure.visible
    ex._show_history(State(), compute.history(State(), 0.5))  # Coulomb: no choice
    assert not ex.history_quantity.visible and not ex.history_view.theta_figure.visible
