"""The figure layer: series, tables, style, single recipes, and the corrected eq. (27)."""

from __future__ import annotations

import math
from pathlib import Path

import matplotlib
import numpy as np
import pytest
from scipy.integrate import quad

import vibrofriction as vf
from vibrofriction import theory
from vibrofriction.figures import all_recipes, history, maps, style
from vibrofriction.figures.recipe import Table, curve_table, max_deviation, solve_recipes
from vibrofriction.figures.series import Series, series_at_vbar, solve
from vibrofriction.solver import solve_points

C0 = math.sqrt(4.0 * math.pi / 9.0)


# --------------------------------------------------------------------------- style
def test_style_is_headless_and_saves_png_and_pdf(tmp_path: Path) -> None:
    assert matplotlib.get_backend().lower() == "agg"
    fig = style.figure()
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
    c = theory.inertial_per_vbar(0.5, 2.0, 0.5)
    np.testing.assert_allclose(s.v_inertial, c * np.array([0.0, 0.5, 1.0]))
    with pytest.raises(ValueError, match="v_inertial must be"):
        Series("bad", 0.5, 2.0, 0.5, np.array([-1.0]), np.array([np.nan]))
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
    s = series_at_vbar("k", 0.01, 1.01, 1.0, [0.02, 0.5])  # near beta = 1: does not settle
    tight = vf.SolverSettings(max_periods=500)
    c = solve([s], settings=tight)["k"]
    direct = vf.friction_coefficient(vf.Dimensionless(0.01, 1.01, 1.0), vbar=[0.02, 0.5],
                                     settings=tight)
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
    assert len(set(names)) == len(names) == 10
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
    c = theory.inertial_per_vbar(0.01, 1.0e4, a)
    mu = solve_points(0.01, 1.0e4, a, c * vbar)["mu_ratio"]
    np.testing.assert_allclose(mu, theory.mu_ratio_soft_corrected(vbar, a), atol=0.006)


def test_importing_the_figures_leaves_the_matplotlib_backend_alone(tmp_path: Path) -> None:
    """A notebook's backend must survive ``import vibrofriction.figures`` (and a save)."""
    import subprocess
    import sys

    code = ("import matplotlib; matplotlib.use('svg'); "
            "import vibrofriction.figures as f; from vibrofriction.figures import style; "
            "fig = style.figure(); fig.add_subplot().plot([0, 1]); "
            f"style.save(fig, {str(tmp_path)!r}, 'x'); print(matplotlib.get_backend())")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=300)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "svg"
    assert (tmp_path / "x.png").stat().st_size > 1000
    pdf = (tmp_path / "x.pdf").read_bytes()
    assert b"CreationDate" not in pdf


def test_checks_report_a_violation_they_are_fed() -> None:
    """The physics checks are pure functions of curves: a decreasing curve is caught."""
    from vibrofriction.figures.checks import monotonicity, status_note
    from vibrofriction.figures.series import Curve

    s = series_at_vbar("k", 0.5, 2.0, 0.5, [0.1, 0.2, 0.3, 0.4])
    n = 4
    c = Curve(s, np.array([0.5, 0.6, 0.55, 0.7]), np.full(n, 1e-12), np.zeros(n, int),
              np.ones(n, int), np.zeros(n), np.zeros(n), np.ones(n, bool), np.full(n, np.nan),
              np.full(n, np.nan))
    worst, where = monotonicity({"k": c})
    assert worst == pytest.approx(0.05) and "vbar = 0.2..0.3" in where
    ok = Curve(s, np.array([0.5, 0.6, 0.65, 0.7]), *[getattr(c, f) for f in (
        "error", "status", "period", "stick_fraction", "flight_fraction", "trusted",
        "window_min", "window_max")])
    assert monotonicity({"k": ok})[0] == 0.0
    nc = Curve(s, np.array([0.5, np.nan, 0.65, 0.7]), np.array([0, np.inf, 0, 0]),
               np.array([0, 2, 0, 0]), np.ones(n, int), np.zeros(n), np.zeros(n),
               np.array([True, False, True, True]), np.full(n, 0.4), np.full(n, 0.6))
    assert "1 not converged" in status_note({"k": nc}) and "(0.5, 2): 1" in status_note({"k": nc})
