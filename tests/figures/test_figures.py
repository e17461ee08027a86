"""The figure layer: series, tables, style, single recipes, and the corrected eq. (27)."""

from __future__ import annotations

import math
from pathlib import Path

import matplotlib
import matplotlib.figure
import numpy as np
import pytest
from scipy.integrate import quad

import vibrofriction as vf
from vibrofriction import theory
from vibrofriction.figures import all_recipes, history, maps, style
from vibrofriction.figures.recipe import Table, curve_table, max_deviation, solve_recipes
from vibrofriction.figures.series import Curve, Series, series_at_vbar, solve
from vibrofriction.solver import STATUS_BY_CODE, solve_points

C0 = math.sqrt(4.0 * math.pi / 9.0)


# --------------------------------------------------------------------------- style
def test_style_is_headless_and_saves_png_and_pdf(tmp_path: Path) -> None:
    fig = style.figure()
    # a plain Figure, not registered with pyplot: nothing to close, no notebook state
    assert isinstance(fig, matplotlib.figure.Figure) and fig.canvas.manager is None
    assert fig.get_size_inches()[0] == pytest.approx(style.COLUMN)
    ax = fig.add_subplot()
    ax.plot([0, 1], [0, 1])
    ax.set_xlabel(style.VBAR)
    ax.set_ylabel(style.MU)
    paths = style.save(fig, tmp_path, "demo")
    assert [p.suffix for p in paths] == [".png", ".pdf"]
    assert all(p.stat().st_size > 500 for p in paths)
    assert len(style.sequence_colors(4)) == 4


# --------------------------------------------------------------------------- series
def test_series_validates_and_converts() -> None:
    s = series_at_vbar("k", 0.5, 2.0, 0.5, [0.0, 0.5, 1.0])
    c = theory.critical_inertial_velocity(0.5, 2.0, 0.5)
    np.testing.assert_allclose(s.v_inertial, c * np.array([0.0, 0.5, 1.0]))
    with pytest.raises(ValueError, match="v_inertial must be"):
        Series("bad", 0.5, 2.0, 0.5, np.array([np.nan]), np.array([np.nan]))
    Series("signed", 0.5, 2.0, 0.5, np.array([-1.0]), np.array([np.nan]))  # V < 0: backward
    with pytest.raises(ValueError, match="v_inertial = 0 with a transverse"):
        Series("held", 0.5, 2.0, 0.5, np.array([0.0]), np.array([np.nan]), a_y=0.5)
    # V = 0 with a longitudinal oscillation is computed (held or driven, docs/inplane.md)
    assert Series("held", 0.5, 2.0, 0.5, np.array([0.0]), np.array([np.nan]), a_x=0.5).size
    with pytest.raises(ValueError, match="inplane_on"):
        Series("k", 0.5, 2.0, 0.5, np.array([1.0]), np.array([np.nan]), inplane_on="disk")
    for alpha, beta in ((0.5, 1.0), (1.0, 3.0)):  # cases III and IV: no vbar
        with pytest.raises(ValueError, match="vbar is undefined"):
            series_at_vbar("k", alpha, beta, 0.5, [0.1])


def test_solve_cuts_the_batch_back_into_curves() -> None:
    a = series_at_vbar("a", 0.01, 0.02, 0.5, np.linspace(0, 1.2, 7))
    b = Series("b", 1.0, math.inf, 1.0, np.array([0.0, 1.0, 5.0]), np.full(3, np.nan))
    curves = solve([a, b])
    for s in (a, b):
        direct = solve_points(s.alpha, s.beta, s.amplitude, s.v_inertial)
        np.testing.assert_array_equal(curves[s.key].mu_ratio, direct["mu_ratio"])
        np.testing.assert_array_equal(curves[s.key].status, direct["status"])
    with pytest.raises(ValueError, match="unique"):
        solve([a, a])


def test_curves_carry_the_solvers_trusted_flags() -> None:
    """The figures hide exactly what the solver does not trust (one definition)."""
    # a slow jumping point (tests/solver/test_trust.py's SLOW): not converged within 256 periods
    slow = (0.5343889244565606, 2.82801636121696, 2.8253189143838906)
    vbars = [0.04469609687392416, 0.5]
    s = series_at_vbar("k", *slow, vbars)
    tight = vf.SolverSettings(max_periods=256)
    c = solve([s], settings=tight)["k"]
    direct = vf.friction_coefficient(vf.Dimensionless(*slow), vbar=vbars, settings=tight)
    np.testing.assert_array_equal(c.trusted, direct.trusted)
    assert not c.trusted.all()
    np.testing.assert_array_equal(np.isnan(c.trusted_mu), ~c.trusted)
    # a converged status with an error above tol_trusted is 'suspicious', not trusted
    strict = solve([series_at_vbar("g", 0.5, 2.0, 0.5, [0.3])],
                   settings=vf.SolverSettings(tol_trusted=1e-15))["g"]
    assert strict.suspicious.all() and not strict.trusted.any()


# --------------------------------------------------------------------------- tables
def test_table_csv_states_parameters(tmp_path: Path) -> None:
    t = Table("demo", ("alpha = 0.5",), {"x": np.array([1.0, np.nan]),
                                         "s": np.array(["a", "b"], dtype=object)})
    text = t.write_csv(tmp_path / "t.csv").read_text().splitlines()
    assert text[:3] == ["# demo", "# alpha = 0.5", "x,s"]
    assert text[3] == "1.0,a" and text[4] == "nan,b"
    with pytest.raises(ValueError, match="differ in length"):
        Table("bad", (), {"x": np.zeros(2), "y": np.zeros(3)})


def test_curve_table_and_max_deviation() -> None:
    curves = solve([series_at_vbar("k", 0.01, 0.02, 0.5, [0.0, 0.5, 1.5])])
    t = curve_table("t", curves, ("p",), extra=lambda c: {"eq26": theory.mu_ratio_stiff(
        c.vbar, 0.5)})
    assert list(t.columns)[:6] == ["series", "alpha", "beta", "amplitude", "vbar", "v_inertial"]
    assert list(t.columns["status"]) == ["static limit", "periodic", "continuous sliding"]
    d, at = max_deviation(t.columns["mu_ratio"], t.columns["eq26"], ["p0", "p1", "p2"])
    assert 0 < d < 0.01 and at == "p1"


# --------------------------------------------------------------------------- recipes
def test_recipe_names_are_unique_and_quick_grids_smaller() -> None:
    quick, full = all_recipes(True), all_recipes(False)
    names = [r.name for r in quick]
    assert len(set(names)) == len(names) == 22
    assert [r.name for r in full] == names
    assert sum(r.points for r in quick) < sum(r.points for r in full) / 3


def test_fig2_history_shows_stick_and_slip(tmp_path: Path) -> None:
    recipe = history.fig2()
    out = recipe.render({})
    cols = out.tables[0].columns
    assert {"stick", "slip+"} <= set(cols["phase"])
    assert np.all(np.abs(cols["f"]) <= cols["n"] + 1e-9)          # |f| <= mu0 F_N
    slip = cols["phase"] == "slip+"
    np.testing.assert_allclose(cols["f"][slip], cols["n"][slip], atol=1e-9)
    assert style.save(out.figure, tmp_path, recipe.name)[0].stat().st_size > 10_000


def test_fig4_recipe_renders_with_its_checks(tmp_path: Path) -> None:
    recipe = next(r for r in all_recipes(True) if r.name == "fig04_limits")
    curves = solve_recipes([recipe])[0]
    out = recipe.render(curves)
    by = {c.formula: c.deviation for c in out.checks}
    assert by["eq. (26), stiff law"] < 0.015
    assert by["eq. (27) corrected: sqrt(4 pi vbar/9), p = 1.2"] < 0.013
    assert by["eq. (27) as printed: sqrt(4 pi/9) vbar, p = 1.2"] > 0.2
    assert out.figure is not None


def test_map_grid_avoids_the_resonance_lines() -> None:
    alpha, beta = maps.grid(48, 60)
    assert not np.any(np.isclose(alpha, 1.0, rtol=1e-3))
    assert not np.any(np.isclose(beta, 1.0, rtol=1e-3))
    with pytest.raises(ValueError, match="avoid"):
        maps.grid(41, 60)  # log grid with alpha = 1 on it


# ------------------------------------------------ theory addition: corrected eq. (27)
def test_soft_law_corrected_limits() -> None:
    for a in (0.2, 0.5, 1.0):
        assert theory.mu_ratio_soft_corrected(0.0, a) == pytest.approx(1 - a)
        assert theory.mu_ratio_soft_corrected(1.0, a) == 1.0
        assert theory.mu_ratio_soft_corrected(1.0 - 1e-12, a) == pytest.approx(1.0, abs=1e-9)
        v = np.linspace(0, 1, 2001)
        assert np.all(np.diff(theory.mu_ratio_soft_corrected(v, a)) > 0)  # monotone
        for small in (1e-8, 1e-6):  # leading term a sqrt(4 pi vbar/9)
            rise = theory.mu_ratio_soft_corrected(small, a) - (1 - a)
            assert rise / (a * math.sqrt(small)) == pytest.approx(C0, rel=1e-3)
    with pytest.raises(ValueError, match="amplitude"):
        theory.mu_ratio_soft_corrected(0.5, 1.5)


def test_soft_law_leading_term_from_the_rigid_body_slip_window() -> None:
    """Derivation in the docstring: slip window [-sigma, 2 sigma], V = 9 a sigma^4/(16 pi)."""
    a, sigma = 0.7, 0.05
    f = 1 - a + a * sigma**2 / 2          # pulling force that opens the window

    def velocity(s: float) -> float:      # x' from the start of slip, n ~ 1 - a + a s^2/2
        return quad(lambda u: f - (1 - a * math.cos(u)), -sigma, s)[0]

    assert velocity(2 * sigma) == pytest.approx(0.0, abs=1e-2 * a * sigma**3)
    distance = quad(velocity, -sigma, 2 * sigma)[0]
    V = distance / (2 * math.pi)
    assert V == pytest.approx(9 * a * sigma**4 / (16 * math.pi), rel=1e-2)
    vbar = V / a                           # soft limit: v0* = mu0 dF_N/(m omega), eq. (13)
    assert f - (1 - a) == pytest.approx(a * math.sqrt(4 * math.pi * vbar / 9), rel=1e-2)


def test_soft_law_corrected_against_the_solver_near_the_soft_limit() -> None:
    vbar = np.array([0.05, 0.2, 0.5, 0.8])
    a = 0.6
    c = theory.critical_inertial_velocity(0.01, 1.0e4, a)
    mu = solve_points(0.01, 1.0e4, a, c * vbar)["mu_ratio"]
    np.testing.assert_allclose(mu, theory.mu_ratio_soft_corrected(vbar, a), atol=0.006)


@pytest.mark.parametrize("how", ["use", "env"])
@pytest.mark.slow
def test_importing_the_figures_leaves_the_matplotlib_backend_alone(tmp_path: Path,
                                                                    how: str) -> None:
    """A notebook's backend must survive ``import vibrofriction.figures``, the rendering of
    a recipe and a save; no pyplot is imported on the way."""
    import os
    import subprocess
    import sys

    env = {k: v for k, v in os.environ.items() if k != "MPLBACKEND"}
    if how == "env":
        env["MPLBACKEND"] = "pdf"
        chosen, first = "pdf", "import matplotlib; before = matplotlib.get_backend(); "
    else:
        chosen, first = "svg", ("import matplotlib; matplotlib.use('svg'); "
                                "before = matplotlib.get_backend(); ")
    code = (first + "import sys; import vibrofriction.figures as f; "
            "from vibrofriction.figures import history, style; "
            "out = history.fig2().render({}); "
            f"style.save(out.figure, {str(tmp_path)!r}, 'x'); "
            "print(before, matplotlib.get_backend(), 'matplotlib.pyplot' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=300, env=env)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == [chosen, chosen, "False"]
    assert (tmp_path / "x.png").stat().st_size > 10_000
    pdf = (tmp_path / "x.pdf").read_bytes()
    assert b"CreationDate" not in pdf


def test_the_figures_need_no_sweep_machinery() -> None:
    """The maps' cell edges are the figures' own: importing the figures loads neither the
    sweep nor xarray, zarr or Dask (an atlas plot loads them when it is drawn)."""
    import subprocess
    import sys

    heavy = ("vibrofriction.sweep", "xarray", "zarr", "dask")
    code = ("import sys; import vibrofriction.figures; "
            f"print([m for m in {heavy!r} if m in sys.modules])")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=300)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["[]"]


def test_the_phases_have_one_palette() -> None:
    """The explorer shades the phases in the figures' colours (one definition)."""
    pytest.importorskip("bokeh")
    from vibrofriction.explorer import views
    from vibrofriction.figures import style

    assert views.PHASE_COLORS is style.PHASE_COLORS
    assert set(style.PHASE_COLORS) == {"stick", "slip+", "slip-", "flight"}


def test_checks_report_a_violation_they_are_fed() -> None:
    """The physics checks are pure functions of curves: a decreasing curve is caught."""
    from vibrofriction.figures.checks import monotonicity, status_note
    from vibrofriction.figures.series import Curve

    s = series_at_vbar("k", 0.5, 2.0, 0.5, [0.1, 0.2, 0.3, 0.4])
    c = Curve.of(s, mu_ratio=[0.5, 0.6, 0.55, 0.7], error=1e-12, status=0, period=1,
                 stick_fraction=0.0, flight_fraction=0.0, trusted=True)
    worst, where = monotonicity({"k": c})
    assert worst == pytest.approx(0.05) and "vbar = 0.2..0.3" in where
    ok = Curve(s, {**c.columns, "mu_ratio": np.array([0.5, 0.6, 0.65, 0.7])})
    assert monotonicity({"k": ok})[0] == 0.0
    nc = Curve.of(s, mu_ratio=[0.5, np.nan, 0.65, 0.7], error=[0, np.inf, 0, 0],
                  status=[0, 2, 0, 0], period=1, stick_fraction=0.0, flight_fraction=0.0,
                  trusted=[True, False, True, True], window_min=0.4, window_max=0.6)
    assert "1 not converged" in status_note({"k": nc}) and "(0.5, 2): 1" in status_note({"k": nc})


# ------------------------------------------------ the checks module, on hand-made curves
_CODE = {status: code for code, status in STATUS_BY_CODE.items()}


def _curve(s: Series, mu, *, trusted=None, status: vf.Status = vf.Status.PERIODIC) -> Curve:
    """A solved-looking curve with the given values (error 0 where trusted, inf elsewhere)."""
    n = s.size
    mu = np.asarray(mu, dtype=float)
    ok = np.ones(n, bool) if trusted is None else np.asarray(trusted, bool)
    return Curve.of(s, mu_ratio=mu, error=np.where(ok, 0.0, np.inf), status=_CODE[status],
                    period=1, stick_fraction=0.0, flight_fraction=0.0, trusted=ok)


def test_matrix_checks_report_eq12_case_iii_and_plateau_violations() -> None:
    from vibrofriction.figures.checks import matrix_checks

    vb = np.array([0.0, 0.5, 1.0, 1.2])
    gen = series_at_vbar("g", 0.5, 2.0, 0.5, vb, axis="vbar")
    V = np.array([0.0, 1.0, 2.0])
    iii = Series("iii", 0.2, 1.0, 0.5, V, np.full(3, np.nan), {"axis": "v_inertial"})
    iv = Series("iv", 1.0, 5.3, 0.5, V, np.full(3, np.nan), {"axis": "v_inertial"})
    far = Series("plateau:iv", 1.0, 5.3, 0.5, np.array([100.0, 1000.0]), np.full(2, np.nan),
                 {"axis": "plateau"})
    exact = float(theory.resonant_plateau_exact(0.5))
    curves = {"g": _curve(gen, [0.5, 0.8, 0.97, 1.0]),          # 0.03 below 1 at vbar = 1
              "iii": _curve(iii, [0.5, 1.0, 0.996]),             # case III off by 0.004
              "iv": _curve(iv, [0.5, 0.7, 0.74]),
              "plateau:iv": _curve(far, [0.70, exact + 0.002])}
    by = {c.formula: c for c in matrix_checks(curves, 0.5, "figX", 2.0)}
    eq12 = by["eq. (12): mu = mu0 exactly for vbar >= 1"]
    assert eq12.deviation == pytest.approx(0.03) and "vbar=1" in eq12.at
    case3 = by["case III: mu = mu0 for all v0 > 0"]
    assert case3.deviation == pytest.approx(0.004) and "V=2" in case3.at
    assert "stated accuracy" in case3.remark           # not "holds exactly"
    plateau = by["case IV plateau (exact, rigid contact) at finite beta"]
    assert plateau.deviation == pytest.approx(0.002)
    mono = by["Fig. 3 caption: mu/mu0 increases monotonically with vbar"]
    assert mono.deviation == pytest.approx(0.004) and "(0.2, 1), V = 1..2" in mono.at
    # the same curves without the defects pass
    curves["g"] = _curve(gen, [0.5, 0.8, 1.0, 1.0])
    curves["iii"] = _curve(iii, [0.5, 1.0, 1.0])
    by = {c.formula: c for c in matrix_checks(curves, 0.5, "figX", 2.0)}
    assert by["eq. (12): mu = mu0 exactly for vbar >= 1"].deviation == 0.0
    assert by["case III: mu = mu0 for all v0 > 0"].remark.startswith("holds exactly")


def test_fig4_checks_measure_the_closed_forms_and_fit_the_exponent() -> None:
    from vibrofriction.figures.checks import fig4_checks, fit_soft_exponent

    vb = np.linspace(0.0, 1.2, 25)
    systems = {"stiff": (0.01, 0.02), "soft": (0.01, 400.01)}
    curves = {}
    for a in (0.4, 1.0):
        st = series_at_vbar(f"stiff,a={a:g}", 0.01, 0.02, a, vb, system="stiff")
        so = series_at_vbar(f"soft,a={a:g}", 0.01, 400.01, a, vb, system="soft")
        stiff_mu = np.array(theory.mu_ratio_stiff(vb, a))
        stiff_mu[6] += 0.01                             # one defect on the stiff law
        curves[st.key] = _curve(st, stiff_mu)
        curves[so.key] = _curve(so, theory.mu_ratio_soft_corrected(vb, a, 1.5))  # p = 1.5
    p, dev = fit_soft_exponent(curves)
    assert p == pytest.approx(1.5, abs=1e-3) and dev < 1e-4
    by = {c.formula: c for c in fig4_checks(curves, systems)}
    stiff = by["eq. (26), stiff law"]
    assert stiff.deviation == pytest.approx(0.01) and stiff.at == f"a=0.4, vbar={vb[6]:.3g}"
    gap = max(float(np.max(np.abs(theory.mu_ratio_soft_corrected(vb, a, 1.5)
                                  - theory.mu_ratio_soft_corrected(vb, a)))) for a in (0.4, 1))
    assert by["eq. (27) corrected: sqrt(4 pi vbar/9), p = 1.2"].deviation == pytest.approx(gap)
    assert "best p = 1.500" in by["eq. (27) corrected, exponent p fitted to the numerics"].at


def test_fig5_envelope_counts_only_trusted_points() -> None:
    from vibrofriction.figures.checks import fig5_checks

    vb = np.linspace(0.0, 1.2, 13)
    below, above = (0.5,), (1.01, 1.1, 10.0)
    curves = {}
    for b in below + above:
        s = series_at_vbar(f"beta={b:g}", 0.01, b, 1.0, vb)
        mu = np.array(theory.mu_ratio_soft_corrected(vb, 1.0)) - 0.05 * (vb < 1)
        trusted = np.ones(vb.size, bool)
        if b == 10.0:
            mu[3] += 0.08                              # 0.03 above the soft law
            mu[8] += 0.5                               # far above, but not trusted
            trusted[8] = False
        if b == 1.1:
            mu[6] = mu[5] - 0.02                       # a decrease of 0.02
        curves[s.key] = _curve(s, mu, trusted=trusted)
    checks, plateau = fig5_checks(curves, below, above)
    env = checks[0]
    assert env.where.startswith("fig05: alpha = 0.01, beta = 10")
    assert env.deviation == pytest.approx(0.03) and env.at == f"vbar={vb[3]:.3g}"
    mono = [c for c in checks if "beta > 1" in c.where][0]
    assert mono.deviation == pytest.approx(0.02) and "(0.01, 1.1), vbar = 0.5..0.6" in mono.at
    assert [c for c in checks if "beta < 1" in c.where][0].deviation == 0.0
    assert len(plateau) == 3 and all(p.startswith("beta = ") for p in plateau)


def test_fig6_checks_measure_the_plateau_against_eq32() -> None:
    from vibrofriction.figures.checks import fig6_checks, fig6_note

    amps = (0.5, 1.5)
    curves = {}
    for a, offset in zip(amps, (0.004, -0.001), strict=True):
        V = np.array([0.0, 12.0])
        curves[f"a={a:g}"] = _curve(Series(f"a={a:g}", 1.0, math.inf, a, V, np.full(2, np.nan),
                                           {"role": "curve"}), [1 - a, 1 - a / 2 + offset])
        far = Series(f"plateau,a={a:g}", 1.0, math.inf, a, np.array([50.0, 200.0]),
                     np.full(2, np.nan), {"role": "plateau"})
        curves[far.key] = _curve(far, [0.0, 1 - a / 2 + offset])
    by = {c.formula: c for c in fig6_checks(curves, amps, 200.0, 12.0,
                                            velocity_amplitudes=(0.5,))}
    paper = by["1 - a/2 (last eq. 32)"]
    assert paper.deviation == pytest.approx(0.004) and paper.at == "a=0.5"
    assert by["1 - a/2 (last eq. 32) for jumping"].deviation == pytest.approx(0.001)
    exact15 = float(theory.resonant_plateau_exact(1.5))
    assert by["Fig. 6: curves approach the plateau"].deviation >= abs(0.249 - exact15)
    # v0/dv from a simulation of the true case IV: the exact energy balance holds
    assert by["v0/dv, exact root of the energy balance (eq. 32)"].deviation < 1e-3
    assert "a = 0.5: numerics 0.7540" in fig6_note(curves, amps, 200.0)


def test_fig10_check_catches_cof_below_mu0_above_the_critical_velocity() -> None:
    from vibrofriction.figures.checks import fig10_checks
    from vibrofriction.figures.dimensional import SYSTEMS, physical_system

    systems = {n: (SYSTEMS[n][0], physical_system(n)) for n in ("soft (I)", "stiff (II)")}
    curves = {}
    for name, (_, phys) in systems.items():
        vstar = phys.critical_velocity()
        v0 = np.array([0.0, 0.5 * vstar, vstar, 2 * vstar, 4 * vstar])
        s = Series(name, 0.5, 2.0, 0.5, np.zeros(5), np.full(5, np.nan), {"v0": v0})
        mu = np.array([0.5, 0.9, 1.0, 1.0, 1.0])
        trusted = np.ones(5, bool)
        if name == "soft (I)":
            mu[3] = 0.98                               # below mu0 above v0*: a violation
            mu[4], trusted[4] = 0.5, False             # untrusted: not counted
        curves[name] = _curve(s, mu, trusted=trusted)
    checks, note = fig10_checks(curves, systems, soft="soft (I)", stiff="stiff (II)")
    dev = {c.where.split(",")[0]: c.deviation for c in checks}
    assert dev["fig10: soft (I)"] == pytest.approx(0.02) and dev["fig10: stiff (II)"] == 0.0
    assert "soft eq. (13)" in note and "stiff eq. (14)" in note


def test_map_note_and_jumping_note_from_hand_made_curves() -> None:
    from vibrofriction.figures.checks import jumping_note, map_field, map_note

    alpha, beta = np.array([0.1, 2.0]), np.array([0.5, 3.0])   # beta > alpha: 3 cells
    curves = {}
    values = {(0, 0): 0.6, (1, 0): 0.7, (1, 1): 0.9}
    for kind in ("vbar", "V"):
        for (i, j), mu in values.items():
            s = Series(f"{kind}:{i}:{j}", float(alpha[j]), float(beta[i]), 0.5, np.array([1.0]),
                       np.array([0.5]), {"map": kind, "row": i, "alpha": float(alpha[j])})
            curves[s.key] = _curve(s, [mu], trusted=[not (kind == "V" and (i, j) == (1, 1))])
    mu, ok = map_field(curves, "V", alpha, beta)
    assert np.isnan(mu[0, 1]) and not ok[0, 1] and not ok[1, 1] and ok[1, 0]
    note = map_note(curves, alpha, beta)
    assert note.startswith("3 points per map; untrusted: 0 at fixed vbar, 1 at fixed V")
    assert "between 0.600 and 0.900" in note

    vb = np.array([0.0, 0.5, 1.0, 1.5])
    reach = series_at_vbar("r", 0.5, 2.0, 1.5, vb, axis="vbar")
    never = series_at_vbar("n", 0.2, 0.22, 1.5, vb, axis="vbar")
    text = jumping_note({"r": _curve(reach, [0, 0.8, 1.0, 1.0]),
                         "n": _curve(never, [0, 0.5, 0.9, 0.99])}, 1.6)
    assert "(0.5, 2): 1;" in text and "(0.2, 0.22): > 1.6" in text


def test_history_summary_from_a_hand_made_history() -> None:
    from vibrofriction.figures.checks import history_mu_ratio, history_note, history_transitions
    from vibrofriction.solver import Event, History

    tau = np.linspace(0.0, 4 * math.pi, 401)
    n = 1.0 + 0.5 * np.cos(tau)
    phase = np.where(np.sin(tau) > 0, "stick", "slip+")
    events = (Event(1.0, "slip->stick", "slip+", "stick"), Event(4.0, "stick->slip", "stick",
                                                                  "slip+"),
              Event(8.0, "slip->stick", "slip+", "stick"), Event(5.0, "lift-off", "slip+",
                                                                 "flight"))
    zero = np.zeros_like(tau)
    h = History(tau, zero, zero, 0.25 * n, n, phase, events, vf.Dimensionless(0.3, 3.0, 0.5),
                0.1, e=zero, work_input=zero, dissipated_pin=zero, dissipated_contact=zero,
                dissipated_friction=zero)
    assert history_mu_ratio(h) == pytest.approx(0.25, rel=1e-12)
    window = (0.1, 1.0)                                 # periods: tau in (0.63, 6.28)
    assert [e.tau for e in history_transitions(h, window)] == [1.0, 4.0]
    assert "2 stick/slip transitions" in history_note(h, (0.3, 3.0, 0.5, 0.5), window)
