"""Figs. 11-13 (the damped model): the recipes render and their checks hold the physics."""

from __future__ import annotations

import math

import numpy as np
import pytest

import vibrofriction as vf
from vibrofriction import theory
from vibrofriction.figures import Rendered, all_recipes, damped, style
from vibrofriction.figures.damped_checks import (
    damped_beta_series_checks,
    damped_case_iv_checks,
    damped_onset,
)
from vibrofriction.figures.recipe import solve_recipes
from vibrofriction.figures.series import Curve, Series
from vibrofriction.solver import STATUS_BY_CODE

NAMES = ("fig11_damped_case_iv", "fig12_damped_law", "fig13_damped_beta_series")


@pytest.fixture(scope="module")
def rendered(tmp_path_factory) -> dict:
    """The three damped recipes, quick grids, solved in one batch and rendered (and saved):
    ``(recipe, curves, rendered)`` by name, and the folder of the PNGs as ``"folder"``."""
    recipes = [damped.damped_case_iv(True), damped.damped_fig10(True), damped.damped_fig5(True)]
    solved = solve_recipes(recipes)
    folder = tmp_path_factory.mktemp("damped")
    out = {}
    for r, curves in zip(recipes, solved, strict=True):
        result = r.render(curves)
        style.save(result.figure, folder, r.name)
        out[r.name] = (r, curves, result)
    out["folder"] = folder
    return out


def _by_formula(result: Rendered, start: str) -> list:
    return [c for c in result.checks if c.formula.startswith(start)]


# --------------------------------------------------------------------------- recipes
def test_damped_recipes_follow_the_paper_and_quick_is_smaller() -> None:
    quick, full = all_recipes(True), all_recipes(False)
    names = [r.name for r in quick]
    at = names.index(NAMES[0])
    assert tuple(names[at:at + 3]) == NAMES and names[at - 1] == "maps_alpha_beta"
    assert [r.name for r in full] == names
    for q, f in zip(quick[at:at + 3], full[at:at + 3], strict=True):
        assert q.points < f.points
    # Fig. 13 shares one axis: the damped series are at the undamped curve's velocities
    s = {x.key: x for x in damped.damped_fig5(True).series}
    u, d = s["beta=1.01"], s[f"beta=1.01,zeta={damped.FIG13_ZETA:g}"]
    assert u.zeta == 0.0 and d.zeta == damped.FIG13_ZETA
    np.testing.assert_array_equal(u.v_inertial, d.v_inertial)


@pytest.mark.parametrize("name", NAMES)
@pytest.mark.slow
def test_each_recipe_renders_figure_table_and_checks(rendered, name: str) -> None:
    r, curves, result = rendered[name]
    assert result.figure is not None and result.figure.axes
    png = rendered["folder"] / f"{name}.png"
    assert png.stat().st_size > 10_000 and png.read_bytes()[:4] == b"\x89PNG"
    (table,) = result.tables
    assert len(table) == r.points
    cols = table.columns
    assert {"zeta", "eta_c", "mu_ratio", "status"} <= set(cols)
    for key, c in curves.items():   # the table carries each series' damping
        rows = cols["series"] == key
        np.testing.assert_array_equal(cols["zeta"][rows], c.series.zeta)
    assert result.checks and result.notes
    assert all(math.isfinite(c.deviation) for c in result.checks)


def test_fig11_damped_case_iv_reaches_mu0_at_vc(rendered) -> None:
    _, curves, result = rendered["fig11_damped_case_iv"]
    above = _by_formula(result, "damped case IV: mu = mu0 above")
    below = _by_formula(result, "damped case IV: max mu/mu0 below")
    assert len(above) == len(below) == 3
    assert all(c.deviation <= 1e-9 for c in above)
    assert all(0.9 < c.deviation < 1.0 for c in below)
    (plateau,) = _by_formula(result, "undamped case IV: plateau")
    assert plateau.deviation < 1e-6
    for z in damped.CASE_IV_ZETAS[1:]:   # V_c = a/(2 zeta) on a rigid contact
        assert curves[f"zeta={z:g}"].series.meta["v_c"] == pytest.approx(
            damped.CASE_IV_AMPLITUDE / (2 * z))
    assert "V_c = 50" in result.notes


def test_fig12_damped_law_only_the_resonant_system_changes(rendered) -> None:
    _, curves, result = rendered["fig12_damped_law"]
    above = _by_formula(result, "damped eq. (12) in m/s")
    assert len(above) == 4 and all(c.deviation <= 1e-9 for c in above)
    (away,) = _by_formula(result, "damping away from resonance")
    assert away.deviation < 0.01
    (iv,) = _by_formula(result, "undamped resonant system")
    assert iv.deviation < 1e-3
    vstar = damped.damped_system("resonant (IV)").critical_velocity()
    assert 2.5 < vstar < 3.5 and f"{vstar:.4g} m/s" in iv.remark
    # the undamped resonant curve never reaches mu0; the damped one does, above v0*
    u, d = curves["undamped:resonant (IV)"], curves["resonant (IV)"]
    assert np.nanmax(u.mu_ratio) < 0.76
    v0 = d.series.meta["v0"]
    np.testing.assert_array_equal(d.mu_ratio[v0 >= 1.02 * vstar], 1.0)


def test_fig13_damping_leaves_no_more_untrusted_points(rendered) -> None:
    _, curves, result = rendered["fig13_damped_beta_series"]
    (plain,) = _by_formula(result, "untrusted points, undamped")
    (damp,) = _by_formula(result, "untrusted points, damped")
    assert damp.deviation <= plain.deviation
    n_damped = sum(int(np.sum(~c.trusted)) for c in curves.values() if c.series.zeta > 0)
    assert damp.deviation == n_damped
    effect = {c.where: c.deviation for c in _by_formula(result, "effect of small damping")}
    assert effect["fig13: |beta - 1| > 0.15, points trusted in both"] < 0.01
    assert max(effect.values()) >= effect["fig13: |beta - 1| > 0.15, points trusted in both"]


# ------------------------------------------------ the checks, on hand-made curves
_CODE = {status: code for code, status in STATUS_BY_CODE.items()}


def _curve(s: Series, mu, trusted=None) -> Curve:
    n = s.size
    ok = np.ones(n, bool) if trusted is None else np.asarray(trusted, bool)
    mu = np.asarray(mu, dtype=float)
    status = np.where(np.isfinite(mu), _CODE[vf.Status.PERIODIC], _CODE[vf.Status.NOT_CONVERGED])
    return Curve.of(s, mu_ratio=mu, error=np.where(ok, 0.0, np.inf), status=status, period=1,
                    stick_fraction=0.0, flight_fraction=0.0, trusted=ok, window_min=0.4,
                    window_max=0.6)


def test_damped_onset_and_case_iv_checks_report_violations() -> None:
    z = 0.05                                       # V_c = 0.5/(2 * 0.05) = 5
    V = np.array([0.0, 1.0, 4.75, 5.1, 10.0])
    s = Series("d", 1.0, math.inf, 0.5, V, np.full(5, np.nan), zeta=z)
    bad = _curve(s, [0.5, 0.8, 1.0, 1.0, 0.97])    # reaches 1 too early, drops above V_c
    vc, dev, top = damped_onset(bad)
    assert vc == pytest.approx(5.0) and dev == pytest.approx(0.03) and top == 1.0
    plateau = float(theory.resonant_plateau_exact(0.5))
    u = _curve(Series("u", 1.0, math.inf, 0.5, V, np.full(5, np.nan)),
               [0.5, 0.7, 0.74, 0.745, plateau + 0.01])
    checks, note = damped_case_iv_checks({"d": bad, "u": u})
    dev = {c.formula.split(":")[1].strip()[:10]: c.deviation for c in checks}
    assert dev["mu = mu0 a"] == pytest.approx(0.03)
    assert dev["max mu/mu0"] == 1.0 and "NOT below 1" in checks[1].remark
    assert dev["plateau, e"] == pytest.approx(0.01)
    assert "V_c = 5" in note and "departs" in note


def test_beta_series_checks_count_untrusted_and_compare_trusted_only() -> None:
    vb = np.array([0.0, 0.5, 1.0])
    curves = {}
    for beta in (0.5, 2.0):
        s = Series(f"b{beta}", 0.01, beta, 1.0, np.array([0.0, 0.1, 0.2]), vb)
        curves[f"u{beta}"] = _curve(s, [0.0, np.nan, 1.0], trusted=[True, False, True])
        d = Series(f"d{beta}", 0.01, beta, 1.0, s.v_inertial, vb, zeta=0.01)
        curves[f"d{beta}"] = _curve(d, [0.0, 0.3, 0.99])
    checks, note = damped_beta_series_checks(curves)
    by = {c.formula: c for c in checks}
    assert by["untrusted points, undamped: count"].deviation == 2.0
    assert by["untrusted points, damped, zeta = 0.01: count"].deviation == 0.0
    effect = [c for c in checks if c.formula.startswith("effect")]
    # the untrusted middle point (0.3 vs nan) is not compared: the difference is 0.01
    assert all(c.deviation == pytest.approx(0.01) for c in effect)
    assert "undamped 2 (2 not converged), damped 0" in note


def test_damped_system_is_fig10s_system_with_q50() -> None:
    from vibrofriction.figures.dimensional import physical_system

    p = damped.damped_system("stiff (II)")
    assert p.quality_factor == pytest.approx(damped.QUALITY_FACTOR)
    assert p.with_(c_x=0.0) == physical_system("stiff (II)")
