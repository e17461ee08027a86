"""The explorer without a browser: state and URL, messages, snippet, exports, overlays."""

from __future__ import annotations

import math
from html import escape

import numpy as np
import pytest

import vibrofriction as vf
from vibrofriction.explorer import compute, exports
from vibrofriction.explorer.messages import GENERAL, field_of, read_inputs
from vibrofriction.explorer.state import State
from vibrofriction.explorer.views import CurveView, HistoryView
from vibrofriction.schema import ContactState


@pytest.mark.slow
def test_import_vibrofriction_does_not_import_panel():
    import subprocess
    import sys

    code = "import sys, vibrofriction, vibrofriction.cli; print('panel' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True)
    assert out.stdout.strip() == "False"


@pytest.mark.parametrize("state", [
    State(),
    State(alpha=0.01, beta=math.inf, amplitude=1.5, zeta=0.02, axis="V", v_max=30.0),
    State(mode="bench", du_z_um=0.123456789, k_xc=math.inf, axis="v0", v_min=1e-4,
          v_max=0.1, log_x=True, points=57),
    State(a_x=0.5, phase_x=1.25, inplane_on="holder", axis="V", v_min=-1.0, v_max=1.0),
    State(profile_exponent=2.0, axis="V"),
    State(profile_exponent=3.7, axis="V", v_max=0.8),
])
def test_state_round_trips_through_the_url(state):
    query = state.to_query()
    assert all(isinstance(v, str) for v in query.values())
    back, problems = State.from_query(query)
    assert problems == {}
    assert back == state


def test_url_reads_bytes_lists_and_reports_bad_values():
    state, problems = State.from_query({"alpha": [b"0.01"], "beta": [b"abc"],
                                        "axis": [b"sideways"], "unknown": [b"1"]})
    assert state.alpha == 0.01 and state.beta == State().beta and state.axis == "vbar"
    assert "beta must be a number" in problems["beta"]
    assert "axis must be one of" in problems["axis"]


@pytest.mark.parametrize("texts, field, words", [
    ({"beta": "0.3"}, "beta", "beta must be > alpha (= 0.5)"),
    ({"amplitude": "-0.1"}, "amplitude", "amplitude must be finite and >= 0"),
    ({"alpha": "abc"}, "alpha", "alpha must be a number"),
    ({"zeta": "nan"}, "zeta", "zeta must be"),
    ({"v_max": "-1"}, "v_max", "v_max must be"),
])
def test_bad_input_gives_the_library_message_next_to_its_input(texts, field, words):
    state, problems = read_inputs(texts, State())
    assert state is None
    assert list(problems) == [field]
    assert words in problems[field]


def test_bench_messages_and_axis_messages():
    _, problems = read_inputs({"du_z_um": "-2"}, State(mode="bench"))
    assert "du_z must be" in problems["du_z_um"]
    _, problems = read_inputs({"mass": "0"}, State(mode="bench"))
    assert "mass" in problems
    _, problems = read_inputs({"alpha": "1", "beta": "inf"}, State())
    assert "v0* is infinite" in problems["axis"]
    _, problems = read_inputs({}, State(axis="v0"))
    assert "needs a Physical system" in problems["axis"]
    state, problems = read_inputs({"alpha": "1", "beta": "inf"}, State(axis="V"))
    assert problems == {} and state.beta == math.inf
    assert field_of("give exactly one of mass (kg) and k_x (N/m)") == GENERAL
    assert field_of("something else") == GENERAL


def _run_snippet(state: State) -> np.ndarray:
    scope: dict = {}
    exec(exports.snippet(state), scope)  # noqa: S102 - the snippet shown to the user
    return np.asarray(scope["y"])


@pytest.mark.parametrize("state", [
    State(points=40),
    State(mode="bench", axis="v0", v_min=1e-4, v_max=0.05, log_x=True, points=30),
    State(alpha=1.0, beta=math.inf, amplitude=0.5, axis="V", v_max=8.0, points=30),
    State(a_x=0.5, phase_x=1.25, inplane_on="holder", axis="V", v_min=-1.0, v_max=1.0,
          points=21),
    State(profile_exponent=1.0, axis="V", v_max=1.2, points=12),
    State(profile_exponent=2.0, a_x=0.5, phase_x=1.0, inplane_on="holder", axis="V",
          v_min=-0.4, v_max=0.4, points=5),  # V = 0 left out
])
def test_snippet_reproduces_the_curve(state):
    c = compute.curve(state)
    np.testing.assert_array_equal(_run_snippet(state), c["y"])


def test_curve_marks_static_critical_case_and_trust():
    c = compute.curve(State(alpha=0.01, beta=0.02, amplitude=0.8, points=60))
    assert c["case"] == "II"
    assert c["static"] == pytest.approx(0.2)
    assert c["critical"] == 1.0
    assert [f["label"][:10] for f in c["closed_forms"]] == ["exact stif", "eq. (26), "]
    assert c["trusted"].dtype == bool and c["trusted"].all()
    soft = compute.curve(State(alpha=0.01, beta=400.01, amplitude=1.0, points=20))
    assert [f["label"] for f in soft["closed_forms"]] == ["eq. (27) corrected, soft law"]
    general = compute.curve(State(points=20))
    assert general["closed_forms"] == []  # no closed form outside its regime
    # the stiff laws are the normal oscillation's: none with an in-plane one
    shaken = compute.curve(State(alpha=0.01, beta=0.02, amplitude=0.8, a_x=0.3, axis="V",
                                 v_max=1.0, points=20))
    assert shaken["closed_forms"] == []
    iv = compute.curve(State(alpha=1.0, beta=math.inf, axis="V", v_max=10.0, points=20))
    assert iv["case"] == "IV" and math.isnan(iv["critical"])
    assert iv["closed_forms"][0]["label"].startswith("eq. (32)")
    np.testing.assert_allclose(iv["closed_forms"][0]["y"], _plateau_by_quadrature(0.5),
                               rtol=1e-9)


def _plateau_by_quadrature(a: float) -> float:
    """Case IV's plateau from its definition, by numerical quadrature (not the closed form
    of ``theory``): the body velocity ``dv cos tau`` with ``r = v0/dv`` such that friction
    feeds no mean power, ``<n cos tau sign(r - cos tau)> = 0`` (first eq. 32), then
    ``mu/mu0 = <n sign(r - cos tau)>/<n>`` (eq. 25), ``n = 1 + a cos tau`` (``a <= 1``)."""
    from scipy.integrate import quad
    from scipy.optimize import brentq

    def mean(g, r: float) -> float:
        t = math.acos(r)  # the sign changes at +-t: split the integral there
        parts = [(0.0, t), (t, 2 * math.pi - t), (2 * math.pi - t, 2 * math.pi)]
        return sum(quad(lambda x: g(x) * math.copysign(1.0, r - math.cos(x)), lo, hi,
                        epsabs=1e-13, epsrel=1e-12)[0] for lo, hi in parts) / (2 * math.pi)

    def n(x: float) -> float:
        return 1.0 + a * math.cos(x)

    r = brentq(lambda r: mean(lambda x: n(x) * math.cos(x), r), 0.0, 1.0 - 1e-12,
               xtol=1e-15)
    return mean(n, r)  # <n> = 1 for a <= 1


def test_bench_curve_is_the_cof():
    state = State(mode="bench", axis="v0", v_max=0.05, points=20)
    c = compute.curve(state)
    assert c["y_label"].startswith("COF")
    assert c["static"] == pytest.approx(0.3 * (1 - 0.5))  # mu0 (1 - a), a = du_z/u_z0 (eq. 2)
    # eq. (12) with the pin's dashpot by hand from the bench's numbers (State's defaults):
    # 800 Hz, 10 g, Q = 50, 20 N, k_zc = 2e7, k_xc = 1.5e7 N/m, 1000 Hz, 0.5 um, mu0 = 0.3
    m, w_n, w = 0.01, 2 * math.pi * 800, 2 * math.pi * 1000
    d = m * w_n**2 - m * w**2 + 1j * w * m * w_n / 50  # k_x - m w^2 + i w c_x
    v_star = 0.3 * w * 0.5e-6 * 2e7 * abs(1 + d / 1.5e7) / abs(d)
    assert c["critical"] == pytest.approx(v_star, rel=1e-12)
    # and the solver says it is the onset of continuous sliding: mu = mu0 just above it
    above = vf.friction_coefficient(state.system(), v0=1.001 * v_star)
    below = vf.friction_coefficient(state.system(), v0=0.99 * v_star)
    assert above.trusted and above.slip_fraction == 1.0
    assert above.mu_ratio == pytest.approx(1.0, abs=above.error)
    assert below.trusted and below.stick_fraction > 0.0 and below.mu_ratio < 0.99


def test_history_has_phases_and_events():
    h = compute.history(State(), 0.3)
    assert h["steady"] and h["trusted"]
    assert {s[2] for s in h["spans"]} >= {"stick", "slip+"}
    assert h["events"] and h["t"][-1] == pytest.approx(3.0)


def test_case_map_uses_classify():
    m = compute.case_map(20)
    assert m["cases"].shape == (20, 20)
    j, i = 19, 0  # beta = 1e4, alpha = 1e-3: case I
    assert m["cases"][j, i] == vf.classify(m["alpha"][i], m["beta"][j]).value == "I"
    assert m["cases"][0, 19] == ""  # beta < alpha


CSV = (b"# pin-on-disk\nv0 [mm/s],cof,du_z [um],omega [Hz],sigma\n"
       b"1.0,0.21,0.5,1000,0.005\n10.0,0.27,0.5,1000,0.004\n2.0,0.2,1.0,1000,0.005\n")


def test_csv_overlay_and_malformed_csv():
    data = compute.parse_measurements(CSV, "bench.csv")
    groups = compute.measurement_curves(State(mode="bench", axis="v0"), data)
    assert [len(g["x"]) for g in groups] == [2, 1]
    np.testing.assert_allclose(groups[0]["x"], [1e-3, 1e-2])
    with pytest.raises(ValueError, match="lacks the column"):
        compute.parse_measurements(b"v0,cof\n1,2\n")
    with pytest.raises(ValueError, match="column 'cof', line 2"):
        compute.parse_measurements(b"v0,cof,du_z,omega\n1,abc,1e-6,100\n")
    with pytest.raises(ValueError, match="'x.csv' holds no table"):
        compute.parse_measurements(b"", "x.csv")
    with pytest.raises(ValueError, match="choose the bench inputs"):
        compute.measurement_curves(State(), data)


def test_exports():
    state = State(points=12)
    c = compute.curve(state)
    csv = exports.curve_csv(state, c)
    lines = [ln for ln in csv.splitlines() if not ln.startswith("#")]
    assert lines[0] == "vbar,mu_ratio,status,error,trusted" and len(lines) == 13
    assert float(lines[1].split(",")[1]) == c["y"][0]
    assert exports.figure_bytes(c, "png")[:8] == b"\x89PNG\r\n\x1a\n"
    assert b"<svg" in exports.figure_bytes(c, "svg")[:500]
    with pytest.raises(ValueError, match="fmt"):
        exports.figure_bytes(c, "gif")


@pytest.mark.slow
def test_explorer_builds_and_refuses_bad_input_inline(monkeypatch):
    pn = pytest.importorskip("panel")
    from vibrofriction.explorer import page as app_module

    scheduled = []
    monkeypatch.setattr(pn.state, "execute", lambda cb, *a, **k: scheduled.append(cb))
    ex = app_module.Explorer(State())
    assert scheduled, "the first curve is requested"
    before = ex.state
    ex.inputs["beta"].text.value = "0.1"
    assert ex.inputs["beta"].message.visible
    assert "beta must be > alpha" in ex.inputs["beta"].message.object
    assert ex.state == before  # the last good state stays
    ex.inputs["beta"].text.value = "3"
    assert not ex.inputs["beta"].message.visible and ex.state.beta == 3.0
    ex.inputs["alpha"].slider.value = 0.0  # log10: alpha = 1
    assert ex.inputs["alpha"].text.value == "1"


def test_shares_of_the_curve_merge_into_the_whole():
    state = State(points=31)
    whole = compute.curve(state)
    merged = compute.merge([compute.curve(state, part=(i, 3)) for i in range(3)])
    for name in compute.POINT_COLUMNS:
        np.testing.assert_array_equal(merged[name], whole[name])
    assert merged["closed_forms"] == whole["closed_forms"] == []
    stiff = State(alpha=0.01, beta=0.02, points=9)
    merged = compute.merge([compute.curve(stiff, part=(i, 2)) for i in range(2)])
    np.testing.assert_array_equal(merged["closed_forms"][0]["y"],
                                  compute.curve(stiff)["closed_forms"][0]["y"])


@pytest.mark.slow
def test_explorer_computes_in_worker_processes_without_a_server(monkeypatch):
    """The notebook path: no Bokeh server, the computations awaited on an event loop."""
    import asyncio

    pn = pytest.importorskip("panel")
    from vibrofriction.explorer import page, pool

    scheduled = []
    monkeypatch.setattr(pn.state, "execute", lambda cb, *a, **k: scheduled.append(cb))

    async def run() -> page.Explorer:
        ex = page.Explorer(State(points=24))
        await ex._refresh()
        ex._pick(5)
        await ex._refresh_history()
        return ex

    try:
        ex = asyncio.run(run())
    finally:
        pool.shutdown()
    expected = compute.curve(State(points=24))
    np.testing.assert_array_equal(ex.curve["y"], expected["y"])
    assert "over the 24 trusted of 24 points" in ex.readout.object
    assert ex.history_text.object.startswith("history at vbar = ")


def test_a_bad_url_parameter_is_said_next_to_its_input(monkeypatch):
    pn = pytest.importorskip("panel")
    from vibrofriction.explorer import page

    monkeypatch.setattr(pn.state, "execute", lambda cb, *a, **k: None)
    monkeypatch.setattr(State, "from_query", classmethod(
        lambda cls, q: (State(), {"beta": "beta must be a number or an array of numbers, "
                                          "got 'x'"})))
    ex = page.Explorer()
    assert ex.inputs["beta"].message.visible
    assert "URL parameter beta" in ex.inputs["beta"].message.object


def test_readout_averages_only_trusted_points():
    pytest.importorskip("panel")
    from vibrofriction.explorer.page import readout_text

    curve = {"y": np.array([0.5, 0.7, 9.0, np.nan]), "y_label": "mu/mu0", "seconds": 0.25,
             "trusted": np.array([True, True, False, False])}
    text = readout_text(curve)
    assert text.startswith("mean mu/mu0 = 0.600000 over the 2 trusted of 4 points")
    none = readout_text({**curve, "trusted": np.zeros(4, bool)})
    assert none.startswith("no trusted point of 4: no mean")


def test_no_export_before_a_curve_and_the_export_is_the_curve_shown(monkeypatch):
    pn = pytest.importorskip("panel")
    from vibrofriction.explorer import page

    monkeypatch.setattr(pn.state, "execute", lambda cb, *a, **k: None)
    ex = page.Explorer(State(points=12))
    assert ex.curve is None and all(b.disabled for b in ex.downloads)
    with pytest.raises(RuntimeError, match="nothing to export"):
        ex._export("csv")
    shown = State(alpha=0.01, beta=0.02, points=12)
    ex._want = shown
    ex._show_curve(shown, compute.curve(shown))
    ex.state = State(alpha=0.2, points=12)  # inputs changed, their curve not yet computed
    assert not any(b.disabled for b in ex.downloads)
    csv = ex._export("csv").getvalue().decode()
    assert csv.startswith("# vibrofriction explorer: alpha = 0.01, beta = 0.02")
    assert len([ln for ln in csv.splitlines() if not ln.startswith("#")]) == 13


def test_inplane_mount_and_signed_velocity_axis():
    """The mount is an input (the curve changes with it where alpha != 1/2), V runs
    through 0 with an in-plane oscillation, vbar stays non-negative, a bad mount in the
    URL is said and replaced by the default, and the history works at V < 0."""
    state = State(alpha=0.3, a_x=0.5, phase_x=0.9, axis="V", v_min=-0.6, v_max=0.6,
                  points=13)
    sub, hold = compute.curve(state), compute.curve(state.with_(inplane_on="holder"))
    for c in (sub, hold):  # V = 0 is held (the mean force depends on the preload)
        assert c["x"][6] == 0.0 and not c["trusted"][6]
        assert np.delete(c["trusted"], 6).all()
    assert np.nanmax(np.abs(sub["y"] - hold["y"])) > 0.05
    assert np.all(np.sign(sub["y"][:5]) == -1) and np.all(np.sign(sub["y"][-5:]) == 1)
    _, problems = read_inputs({"v_min": "-1"}, State())  # the vbar axis starts at 0
    assert "v_min must be finite and >= 0" in problems["v_min"]
    back, problems = State.from_query({"inplane_on": "belt", "alpha": "0.3"})
    assert "inplane_on must be one of" in problems["inplane_on"]
    assert back.inplane_on == "substrate" and back.alpha == 0.3
    h = compute.history(state.with_(inplane_on="holder"), -0.3)
    assert h["mu_ratio"] < 0 and h["trusted"] and len(h["t"]) > 10


def test_history_shows_the_contact_point_with_an_inplane_oscillation():
    """Normal-only: no contact point (the view unchanged); 1-D in-plane: x_c(t); 2-D: the
    path (x_c, y_c) and f_y.  The contact point stands still on the substrate in stick
    and moves in slip."""
    assert compute.history(State(), 0.3)["xc"] is None
    one = compute.history(State(a_x=0.4, phase_x=0.9, eta_c=0.1, axis="V"), 0.3)
    two = compute.history(State(a_y=0.5, phase_y=0.3, eta_c=0.1, axis="V"), 0.3)
    assert one["yc"] is None and one["f_y"] is None and len(one["xc"]) == len(one["t"])
    assert two["yc"] is not None and len(two["yc"]) == len(two["t"])
    assert np.max(np.abs(two["f_y"])) > 0.1
    for h in (one, two):
        for lo, hi, phase in h["spans"]:
            inside = (h["t"] >= lo) & (h["t"] <= hi)
            moved = np.ptp(h["xc"][inside]) + (np.ptp(h["yc"][inside])
                                                if h["yc"] is not None else 0.0)
            if phase == "stick":
                assert moved < 1e-7, (lo, hi)
            elif hi - lo > 0.05:
                assert moved > 1e-3, (lo, hi, phase)
    view = HistoryView()
    view.show(two, "V = 0.3")
    assert view.path_figure.visible and view.path_figure.yaxis.axis_label == "y_c"
    view.show(compute.history(State(), 0.3), "vbar = 0.3")
    assert not view.path_figure.visible and len(view.path.data["x"]) == 0


def test_transverse_curve_through_zero_has_a_gap_there():
    """The 2-D solver does not compute V = 0: the curve has a gap (untrusted, nan) there
    and values elsewhere; no static value of eq. (2) and no band are claimed."""
    state = State(a_y=0.5, zeta=0.05, axis="V", v_min=-0.5, v_max=0.5, points=11)
    c = compute.curve(state)
    assert c["x"][5] == 0.0 and np.isnan(c["y"][5]) and not c["trusted"][5]
    assert "not computed" in c["status"][5]
    assert np.delete(c["trusted"], 5).all() and np.all(np.abs(np.delete(c["y"], 5)) < 1)
    assert math.isnan(c["static"]) and c["band"] is None


def _mean_force_by_quadrature(a: float, n: float) -> float:
    """``<F_N>/F_N0 = <max(0, 1 + a cos tau)^(1 + 1/n)>`` over a period, by quadrature (the
    MDR force law of docs/contact_geometry.md, not ``theory``)."""
    from scipy.integrate import quad

    p = 1.0 + 1.0 / n
    return quad(lambda t: max(0.0, 1.0 + a * math.cos(t)) ** p, 0.0, 2 * math.pi,
                epsabs=1e-13)[0] / (2 * math.pi)


def test_profile_selector_names_and_the_curved_refusals():
    from vibrofriction.explorer.state import PROFILES, profile_of

    assert [profile_of(PROFILES[k]) for k in PROFILES] == list(PROFILES)
    assert profile_of(3.5) == profile_of(0.5) == "power"
    assert State(profile_exponent=2.0).curved and not State().curved
    assert not State(mode="bench", profile_exponent=2.0).curved  # the bench: linearised
    assert State(profile_exponent=2.0).curve_points == 40 and State().curve_points == 200
    sphere = State(profile_exponent=2.0, axis="V")
    for texts, field, words in (
            ({"beta": "inf"}, "beta", "does not take a rigid contact (beta = inf)"),
            ({"eta_c": "0.1"}, "eta_c", "does not take contact damping (eta_c > 0)"),
            ({"a_y": "0.2"}, "a_y", "transverse in-plane oscillation (a_y > 0)"),
            ({"profile_exponent": "-1"}, "profile_exponent", "profile_exponent must be")):
        state, problems = read_inputs(texts, sphere)
        assert state is None and list(problems) == [field], problems
        assert words in problems[field]
    # vbar of a curved tip: V over the tip's critical velocity (tests/mdr/test_mdr_vbar.py)
    state, problems = read_inputs({}, sphere.with_(axis="vbar"))
    assert problems == {} and state.axis == "vbar"
    state, problems = read_inputs({"profile_exponent": "1.5"}, sphere)
    assert problems == {} and state.profile_exponent == 1.5
    # the longitudinal oscillation is taken (at V != 0: the curve leaves V = 0 out)
    state, problems = read_inputs({"a_x": "0.2", "phase_x": "1"}, sphere)
    assert problems == {} and state.a_x == 0.2 and state.rest_refused
    assert state.grid()[0] == 0.0 and np.all(state.velocities() > 0.0)
    assert state.velocities().size == state.curve_points - 1
    assert not sphere.rest_refused and not State(a_x=0.2).rest_refused  # flat: V = 0 kept


@pytest.mark.slow
def test_sphere_curve_is_the_mdr_solvers_with_its_static_value():
    """A sphere's curve: the library's MDR answer point for point (40 points at most), the
    static value and the mean normal force of its force law by quadrature, the stiff law
    of the curved tip drawn in case II only, the critical velocity of continuous sliding
    (not eq. 12, which the case text does not name)."""
    state = State(profile_exponent=2.0, axis="V", v_max=1.2)
    c = compute.curve(state)
    assert len(c["x"]) == 40 and c["profile"] == "sphere (n = 2)"
    r = vf.friction_coefficient(vf.Dimensionless(0.5, 2.0, 0.5, profile_exponent=2.0),
                                v_inertial=np.linspace(0.0, 1.2, 40))
    np.testing.assert_array_equal(c["y"], r.mu_ratio)
    mean = _mean_force_by_quadrature(0.5, 2.0)
    assert c["mean_normal"] == pytest.approx(mean, rel=1e-9)
    np.testing.assert_allclose(c["mean_normal_ratio"], mean, rtol=1e-9)
    assert c["static"] == pytest.approx(0.5 ** 1.5 / mean, rel=1e-9)  # (1 - a)^p/<F_N>
    assert c["closed_forms"] == [] and c["band"] is None
    assert c["critical"] == vf.theory.profile_critical_velocity(0.5, 2.0, 0.5, 2.0)
    assert c["critical"] == pytest.approx(0.98999, abs=1e-5)  # docs/contact_geometry.md
    assert c["critical_label"] == "critical velocity of continuous sliding (curved tip)"
    assert "eq. (12)" not in c["case_text"] and "v0*" not in c["case_text"]
    assert c["case_text"].startswith("General case: none of the limits I-IV applies")
    assert c["critical_note"] == c["rest_note"] == ""
    view = CurveView()
    view.show(c, False)  # drawn as the curved tip's line, not eq. (12)'s
    assert view.critical_curved.data["x0"] == [c["critical"]] and not view.critical.data["x0"]
    moving = c["x"] > 0
    for name in ("stick_area_fraction", "slip_area_fraction", "open_area_fraction"):
        assert np.all((c[name][moving] >= 0) & (c[name][moving] <= 1))
    total = (c["stick_area_fraction"] + c["slip_area_fraction"]
             + c["open_area_fraction"])[moving]
    np.testing.assert_allclose(total, 1.0, atol=1e-9)  # the disc is in one of the three
    # on the axis vbar: V over the sphere's critical velocity (0.98999), its line at 1
    on_vbar = compute.curve(state.with_(axis="vbar", v_max=1.5, points=4))
    np.testing.assert_array_equal(on_vbar["x"], [0.0, 0.5, 1.0, 1.5])
    r = vf.friction_coefficient(vf.Dimensionless(0.5, 2.0, 0.5, profile_exponent=2.0),
                                v_inertial=0.98999 * np.array([0.0, 0.5, 1.0, 1.5]))
    np.testing.assert_allclose(on_vbar["y"], r.mu_ratio, rtol=1e-4)
    assert on_vbar["critical"] == 1.0
    assert on_vbar["x_label"] == "vbar = v0/v0* (v0*: the curved tip's critical velocity)"
    stiff = compute.curve(State(alpha=0.01, beta=0.02, profile_exponent=2.0, axis="V",
                                v_max=80.0, points=6))
    assert [f["label"] for f in stiff["closed_forms"]] == [
        "stiff law of the curved tip (alpha, beta -> 0)"]
    # the stiff system is near its limit: the solver within 1 % of the law
    np.testing.assert_allclose(stiff["y"], stiff["closed_forms"][0]["y"], rtol=1e-2)


def test_sphere_with_a_longitudinal_oscillation_leaves_out_v_zero():
    """A sphere with a_x: the curve is the library's (``friction_coefficient`` and
    ``solve_points``, both mounts) at the signed velocities but V = 0, which is left out
    with the library's refusal as the note; no static value, band, closed form or critical
    velocity (those of a curved tip are without a_x), the library's reason instead."""
    from vibrofriction.explorer.page import curved_side_text
    from vibrofriction.solver import solve_points

    state = State(profile_exponent=2.0, axis="V", a_x=0.5, phase_x=1.0, v_min=-0.3,
                  v_max=0.3, points=3)
    c = compute.curve(state)
    np.testing.assert_array_equal(c["x"], [-0.3, 0.3])
    system = vf.Dimensionless(0.5, 2.0, 0.5, a_x=0.5, phase_x=1.0, profile_exponent=2.0)
    np.testing.assert_array_equal(c["y"], vf.friction_coefficient(
        system, v_inertial=[-0.3, 0.3]).mu_ratio)
    # docs/contact_geometry.md, "In-plane oscillation along the sliding"
    np.testing.assert_allclose(c["y"], [-0.27147156, 0.58492601], atol=2e-8)
    assert c["trusted"].all() and math.isnan(c["static"]) and math.isnan(c["critical"])
    assert c["band"] is None and c["closed_forms"] == []
    assert "derived without a_x" in c["critical_note"]
    assert c["rest_note"].startswith("V = 0 left out of the curve: the MDR solver")
    assert c["rest_note"].endswith("got a_x = 0.5")
    assert "oscillation at v_inertial = 0" in c["rest_note"]
    text = curved_side_text(c, state)
    assert "no static value" in text and "no critical velocity" in text
    assert "V = 0 left out" in text and "eq. (12)" not in text
    view = CurveView()
    view.show(c, False)  # the line breaks where V = 0 is left out; no critical line
    np.testing.assert_array_equal(view.trusted.data["x"], [-0.3, 0.0, 0.3])
    assert np.isnan(view.trusted.data["y"]).tolist() == [False, True, False]
    assert len(view.critical.data["x0"]) == len(view.critical_curved.data["x0"]) == 0
    assert len(view.static.data["x"]) == 0
    assert "V = 0 left out" in exports.curve_csv(state, c).splitlines()[2]
    assert exports.figure_bytes(c, "svg").startswith(b"<?xml")
    # the mount: alpha != 1/2 (at 1/2 the two are the same drive)
    holder = state.with_(alpha=0.3, inplane_on="holder", v_min=0.1, v_max=0.5, points=2)
    h = compute.curve(holder)
    p = solve_points(0.3, 2.0, 0.5, np.array([0.1, 0.5]), a_x=0.5, phase_x=1.0,
                     profile_exponent=2.0, inplane_on="holder")
    np.testing.assert_array_equal(h["y"], p["mu_ratio"])
    assert h["rest_note"] == ""  # V = 0 is not on this curve
    substrate = compute.curve(holder.with_(inplane_on="substrate"))
    assert np.max(np.abs(h["y"] - substrate["y"])) > 1e-3


def test_sphere_history_shows_the_contact_in_space_and_time():
    """The space-time view's data: one period, the springs along the profile up to the
    largest contact radius, out of contact exactly where the imposed indentation leaves
    them (xi^n > 1 + a cos tau: the MDR geometry), in contact elsewhere."""
    from vibrofriction.explorer.views import SpaceTimeView

    state = State(profile_exponent=2.0, axis="V")
    h = compute.history(state, 0.3)
    st = h["spacetime"]
    assert h["curved"] and h["steady"] and st is not None
    t, xi, codes = st["t"], st["xi"], np.asarray(st["state"])
    assert t[0] == pytest.approx(0.0) and t[-1] == pytest.approx(1.0)
    assert codes.shape == (t.size, xi.size) and xi[-1] + xi[0] == pytest.approx(1.5 ** 0.5)
    depth = 1.0 + 0.5 * np.cos(2 * math.pi * t)
    gap = xi[None, :] ** 2 - depth[:, None]
    clear = np.abs(gap) > 1e-9
    np.testing.assert_array_equal((codes == ContactState.FLIGHT)[clear], (gap > 0)[clear])
    # stick and slip both occur at this point
    assert {ContactState.STICK, ContactState.SLIP_POS} <= set(np.unique(codes))
    np.testing.assert_allclose(st["contact_radius"], np.sqrt(depth), rtol=1e-12)
    view = SpaceTimeView()
    view.show(h, "V = 0.3")
    assert view.figure.visible and view.note.text == ""
    assert view.image.data["image"][0].shape == (xi.size, t.size)
    view.show({"spacetime": None, "message": "needs the MDR history (test)"}, "V = 0.3")
    assert view.note.text == "needs the MDR history" and len(view.image.data["image"]) == 0


def test_choosing_a_curved_tip_resets_and_disables_what_it_refuses(monkeypatch):
    pn = pytest.importorskip("panel")
    from vibrofriction.explorer import page as app_module

    monkeypatch.setattr(pn.state, "execute", lambda cb, *a, **k: None)
    ex = app_module.Explorer(State(eta_c=0.1, a_x=0.3, a_y=0.2, inplane_on="holder"))
    # an in-plane drive has no vbar: the axis is V at once, said beside the axis
    assert ex.state.axis == "V" and "axis set from vbar to V" in ex.axis_message.object
    ex.profile.value = "sphere"
    assert ex.state.profile_exponent == 2.0 and ex.state.axis == "V"
    assert ex.state.eta_c == 0.0 and ex.state.a_y == 0.0
    for name, shown in (("eta_c", True), ("a_y", True), ("phase_y", False)):
        inp = ex.inputs[name]
        assert inp.text.disabled and inp.slider.disabled
        assert inp.message.visible == shown
    # the longitudinal oscillation is the MDR solver's now: kept and enabled
    assert ex.state.a_x == 0.3 and ex.state.inplane_on == "holder"
    for name in ("a_x", "phase_x"):
        inp = ex.inputs[name]
        assert not inp.text.disabled and not inp.slider.disabled
        assert not inp.message.visible
    assert not ex.inplane_on.disabled
    assert "eta_c reset from 0.1 to 0: the MDR solver" in ex.inputs["eta_c"].message.object
    assert "a_y reset from 0.2 to 0: the MDR solver" in ex.inputs["a_y"].message.object
    assert ex.profile_note.visible
    assert ex.inputs["profile_exponent"].text.disabled  # only the power law is typed
    ex.inputs["beta"].text.value = "inf"
    assert "rigid contact (beta = inf)" in ex.inputs["beta"].message.object
    assert ex.state.beta == 2.0
    ex.inputs["beta"].text.value = "2"
    ex.profile.value = "power"
    assert ex.state.profile_exponent == 3.0
    assert not ex.inputs["profile_exponent"].text.disabled
    ex.inputs["profile_exponent"].text.value = "1.5"
    assert ex.state.profile_exponent == 1.5
    ex.profile.value = "flat"
    assert ex.state.profile_exponent == math.inf
    assert not ex.inputs["eta_c"].text.disabled and not ex.inputs["eta_c"].message.visible
    assert not ex.profile_note.visible and not ex.axis_message.visible
    flat = app_module.Explorer(State())  # the axis vbar: a curved tip keeps it
    flat.profile.value = "cone"
    assert flat.state.profile_exponent == 1.0 and flat.state.axis == "vbar"
    assert not flat.axis_message.visible
    # its unit is the cone's critical velocity of continuous sliding, as the library's
    V_c = vf.Dimensionless(0.5, 2.0, 0.5, profile_exponent=1.0).vbar_to_inertial(1.0)
    assert V_c == vf.theory.profile_critical_velocity(0.5, 2.0, 0.5, 1.0)
    # an in-plane amplitude on the cone still switches it, for that reason (not the tip)
    flat.inputs["a_x"].text.value = "0.3"
    assert flat.state.axis == "V" and flat.state.a_x == 0.3
    assert "axis set from vbar to V: vbar is not defined with an in-plane oscillation" in \
        flat.axis_message.object
    assert "curved tip" not in flat.axis_message.object
    assert "not defined with an in-plane oscillation (a_x = 0.3" in flat.axis_message.object


def test_vbar_refusal_is_the_librarys():
    """The reasons left for refusing vbar: an in-plane amplitude (any tip), contact damping
    with a curved tip; a curved tip alone and a damped flat punch have vbar."""
    from vibrofriction.explorer.texts import vbar_refusal

    assert vbar_refusal(State()) == vbar_refusal(State(profile_exponent=2.0)) == ""
    assert vbar_refusal(State(eta_c=0.1)) == ""
    assert vbar_refusal(State(profile_exponent=2.0, eta_c=0.1)).startswith(
        "vbar of a curved tip is derived without contact damping")
    for tip in (math.inf, 2.0):
        assert "not defined with an in-plane oscillation (a_x = 0.2" in vbar_refusal(
            State(profile_exponent=tip, a_x=0.2))


@pytest.mark.parametrize("changes, same", [
    ({}, True),  # no in-plane oscillation: nothing for the mount to move
    ({"a_x": 0.5, "phase_x": 1.0, "eta_c": 0.1}, True),  # alpha = 1/2, zeta = 0
    ({"a_y": 0.4, "phase_y": 0.3, "eta_c": 0.1}, True),  # the 2-D solver alike
    ({"a_x": 0.5, "phase_x": 1.0, "zeta": 0.05}, False),  # pin damping
    ({"a_x": 0.5, "phase_x": 1.0, "alpha": 0.45}, False),
])
def test_the_mount_note_says_where_substrate_and_holder_are_the_same_drive(changes, same):
    """The note (texts.mount_note) against the library: where it says the two mounts are
    the same, friction_coefficient gives the same values on both at V != 0 (to round-off);
    where it says nothing, they differ."""
    from vibrofriction.explorer.texts import mount_note

    state = State(axis="V", **changes)
    note = mount_note(state)
    assert bool(note) == same
    V = np.array([-0.6, -0.2, 0.2, 0.4, 0.6])
    mu = [np.asarray(vf.friction_coefficient(state.with_(inplane_on=m).system(),
                                             v_inertial=V).mu_ratio) for m in
          ("substrate", "holder")]
    gap = float(np.max(np.abs(mu[0] - mu[1])))
    assert (gap < 1e-9) if same else (gap > 1e-3), gap
    assert mount_note(State(mode="bench")) == ""


def test_the_curve_view_fits_its_y_axis_and_marks_points_without_value():
    """The y axis follows each curve shown (a bench's COF after a mu/mu0 curve: not 1), takes
    in the measurements, and an untrusted point without a value (held at V = 0) is marked
    on the axis's bottom edge."""
    from bokeh.models import Range1d

    view = CurveView()
    view.show(compute.curve(State(points=20)), False)
    fig = view.figures["linear"]
    assert isinstance(fig.y_range, Range1d) and fig.y_range.end > 1.0
    bench = compute.curve(State(mode="bench", points=20))
    assert np.nanmax(bench["y"]) < 0.31
    view.show(bench, False)
    assert -0.05 < fig.y_range.start <= 0.0 and 0.3 < fig.y_range.end < 0.33
    assert fig.y_range.reset_end == fig.y_range.end  # the toolbar's reset comes back here
    view.show_measurements([{"x": [0.1], "cof": [0.45], "label": "m"}])
    assert fig.y_range.end > 0.45
    held = compute.curve(State(a_x=0.5, axis="V", v_min=-0.5, v_max=0.5, points=11))
    assert held["x"][5] == 0.0 and np.isnan(held["y"][5]) and not held["trusted"][5]
    view.show_measurements([])
    view.show(held, False)
    assert list(view.missing.data["x"]) == [0.0]
    assert fig.y_range.start < view.missing.data["y"][0] < np.nanmin(held["y"])
    assert len(view.untrusted.data["x"]) == 0  # no value, so not among the hollow circles
    import matplotlib

    with matplotlib.rc_context({"svg.fonttype": "none"}):  # the legend's text as text
        svg = exports.figure_bytes(held, "svg").decode()
    assert "not trusted, no value" in svg  # the export marks it too
    with matplotlib.rc_context({"svg.fonttype": "none"}):
        assert "no value" not in exports.figure_bytes(compute.curve(State(points=20)),
                                                      "svg").decode()


def test_notes_of_a_change_go_with_the_next_change(monkeypatch):
    """What the page did at a change (reset, switched) is said at that change only; a value
    never applied is not said to be reset; the disabled inputs keep their reason."""
    pn = pytest.importorskip("panel")
    from vibrofriction.explorer import page as app_module

    monkeypatch.setattr(pn.state, "execute", lambda cb, *a, **k: None)
    ex = app_module.Explorer(State())
    ex.inputs["beta"].text.value = "0.1"  # refused: the state stays the last good one
    ex.inputs["a_y"].text.value = "0.5"
    assert ex.state.a_y == 0.0
    ex.profile.value = "sphere"  # resets a_y, never applied
    message = ex.inputs["a_y"].message.object
    assert message.startswith("<span>a_y = 0.5 (never applied) cleared to 0: the MDR solver")
    assert "reset from" not in message
    ex.inputs["beta"].text.value = "2"
    ex.profile.value = "power"
    for name in ("a_y", "eta_c"):
        assert ex.inputs[name].message.object.startswith(
            "<span>disabled: the MDR solver does not take it yet")
    assert not ex.axis_message.visible  # the switch was news at the sphere's change only
    ex.profile.value = "flat"
    assert ex.state.profile_exponent == math.inf
    ex.inputs["a_x"].text.value = "0.4"  # the axis is V already: nothing to switch
    assert not ex.axis_message.visible and not ex.inputs["a_x"].message.visible
    assert ex.state.a_x == 0.4


def test_an_inplane_amplitude_on_vbar_switches_the_axis(monkeypatch):
    pn = pytest.importorskip("panel")
    from vibrofriction.explorer import page as app_module

    monkeypatch.setattr(pn.state, "execute", lambda cb, *a, **k: None)
    for name in ("a_x", "a_y"):
        ex = app_module.Explorer(State())
        ex.inputs[name].text.value = "0.5"
        assert ex.state.axis == "V" and getattr(ex.state, name) == 0.5
        assert ex.inputs[name].message.object.startswith(
            "<span>the velocity axis is now V: vbar is not defined with an in-plane oscillation")
        assert "axis set from vbar to V" in ex.axis_message.object
        assert escape("use the inertial velocity v_inertial") in ex.axis_message.object
        ex.inputs["alpha"].text.value = "0.3"
        assert not ex.axis_message.visible and not ex.inputs[name].message.visible
    ex = app_module.Explorer(State(mode="bench"))  # the bench has no in-plane input
    assert ex.state.axis == "vbar"


def test_side_texts_are_short_with_the_details_behind_more():
    from vibrofriction.explorer.texts import curved_side_text, flat_side_text, with_more

    assert with_more("a < b") == "a &lt; b"
    html = with_more("short", "<F_N>")
    assert html.startswith("<span>short</span><details") and "&lt;F_N&gt;" in html
    for state in (State(points=12), State(a_x=1.0, phase_x=3.1, axis="V", points=12),
                  State(a_y=0.5, axis="V", v_min=0.1, points=4),
                  State(profile_exponent=2.0, axis="V", points=4)):
        c = compute.curve(state)
        text = (flat_side_text if c["profile"] == "flat punch" else curved_side_text)(c, state)
        short, more = text.split("<details", 1)
        assert short.startswith(f"<span>case {c['case']}") and len(short) < 120, short
        assert c["case_text"].split(":")[0] in more
