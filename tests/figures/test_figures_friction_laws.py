"""Figs. 20-22 (local friction laws): the series carry the law to the solver, the recipes
render with the tables their captions promise, and their checks hold in quick mode."""

from __future__ import annotations

import math

import numpy as np
import pytest

import vibrofriction as vf
from vibrofriction.figures import Recipe, all_recipes, friction_laws, style
from vibrofriction.figures.recipe import solve_recipes
from vibrofriction.figures.series import (
    CHOICE_ARGS,
    POINT_ARGS,
    Curve,
    Series,
    point_columns,
    series_of_physical,
    solve,
    solve_points_on,
)
from vibrofriction.solver import solve_points

NAMES = ("fig20_friction_laws", "fig21_load_modulation", "fig22_weakening_map")
MAKERS = (friction_laws.friction_laws, friction_laws.load_modulation,
          friction_laws.weakening_map)
#: The columns each table promises (its caption and parameter lines name them).
COLUMNS = {
    "fig20_friction_laws": {"series", "v_inertial", "amplitude", "mu_ratio", "error", "status",
                            "static_ratio", "rs_a", "rs_b", "rs_d_c", "rs_v_ref",
                            "rs_alpha_ld", "rs_law", "steady_mu_ratio", "reduction"},
    "fig21_load_modulation": {"series", "model", "sweep", "frequency_hz", "v0_m_per_s",
                              "amplitude", "alpha", "beta", "mu_ratio", "status", "rs_a",
                              "rs_d_c", "rs_v_ref", "rs_alpha_ld", "steady_mu_ratio"},
    "fig22_weakening_map": {"series", "v_inertial", "amplitude", "mu_ratio", "status",
                            "verdict", "stable_at_rest", "steady_mu_ratio", "rs_a", "rs_b"},
}
RS = {"rs_a": 0.03, "rs_b": 0.05, "rs_d_c": 1.0, "rs_v_ref": 1.0}


@pytest.fixture(scope="module")
def rendered(tmp_path_factory) -> dict:
    """The three recipes, quick grids, solved in one batch, rendered and saved:
    ``(recipe, curves, rendered, png)`` by name."""
    recipes = [make(True) for make in MAKERS]
    solved = solve_recipes(recipes)
    folder = tmp_path_factory.mktemp("friction_laws")
    out = {}
    for r, curves in zip(recipes, solved, strict=True):
        result = r.render(curves)
        png = style.save(result.figure, folder, r.name)[0]
        out[r.name] = (r, curves, result, png)
    return out


def _check(result, start: str):
    (check,) = [c for c in result.checks if c.formula.startswith(start)]
    return check


# --------------------------------------------------------------------------- the batch
def test_a_series_carries_the_friction_law_to_the_solver() -> None:
    """A Series' friction law reaches solve_points unchanged, mixed laws in one batch."""
    V = np.array([0.1, 0.6])
    series = [Series("coulomb", 0.2, 10.0, 0.3, V, np.nan),
              Series("static", 0.2, 10.0, 0.3, V, np.nan, static_ratio=1.3),
              Series("aging", 0.2, 10.0, 0.3, V[:1], np.nan, **RS),
              Series("slip", 0.2, 10.0, 0.3, V[:1], np.nan, rs_law="slip", **RS)]
    columns = point_columns(series)
    assert len(columns) == len(POINT_ARGS) + len(CHOICE_ARGS)
    by_name = dict(zip((*POINT_ARGS, *CHOICE_ARGS), columns, strict=True))
    np.testing.assert_array_equal(by_name["static_ratio"], [1, 1, 1.3, 1.3, 1, 1])
    np.testing.assert_array_equal(by_name["rs_a"], [0, 0, 0, 0, 0.03, 0.03])
    assert list(by_name["rs_law"]) == ["aging"] * 5 + ["slip"]
    curves = solve(series)
    for s in series:
        direct = solve_points(s.alpha, s.beta, s.amplitude, s.v_inertial,
                              static_ratio=s.static_ratio, rs_a=s.rs_a, rs_b=s.rs_b,
                              rs_d_c=s.rs_d_c, rs_v_ref=s.rs_v_ref, rs_law=s.rs_law)
        np.testing.assert_array_equal(curves[s.key].mu_ratio, direct["mu_ratio"])
    # the laws differ where they should: the static coefficient changes a stick-slip
    # point, the evolution law a rate-and-state point
    assert curves["static"].mu_ratio[0] != curves["coulomb"].mu_ratio[0]
    assert curves["slip"].mu_ratio[0] != curves["aging"].mu_ratio[0]


def test_the_runner_takes_the_columns_in_order_or_refuses() -> None:
    with pytest.raises(TypeError, match="Runner takes"):
        solve_points_on(*point_columns([Series("a", 0.5, 2.0, 0.5, [0.1], np.nan)])[:-1])
    with pytest.raises(ValueError, match="rs_law"):
        Series("bad", 0.5, 2.0, 0.5, [0.1], np.nan, rs_law="ageing")


def test_a_physical_series_keeps_its_law_in_the_models_units() -> None:
    """series_of_physical converts the law by hand's formulas: d_c over the inertial
    length mu F_N0/(m w^2), v_ref over the inertial velocity, a, b, alpha over mu."""
    for f in (0.3, 100.0, 300.0):
        pin = friction_laws.bureau_pin("rs_ld", f)
        s = series_of_physical("p", pin, [friction_laws.BUREAU_V0])
        length = pin.mu0 * pin.F_N0 / (pin.mass * pin.omega ** 2)
        assert s.rs_d_c == pytest.approx(0.5e-6 / length, rel=1e-12)
        assert s.rs_v_ref == pytest.approx(10e-6 / (length * pin.omega), rel=1e-12)
        assert (s.rs_a, s.rs_b) == pytest.approx((0.01 / 0.5, 0.014 / 0.5), rel=1e-12)
        assert s.rs_alpha_ld == pytest.approx(friction_laws.BUREAU_LD / 0.5, rel=1e-12)
        assert s.v_inertial[0] == pytest.approx(friction_laws.BUREAU_V0 / (length * pin.omega),
                                                rel=1e-12)
    coulomb = series_of_physical("c", friction_laws.bureau_pin("coulomb"), [1e-5])
    assert coulomb.rs_a == 0.0 and coulomb.static_ratio == 1.0
    static = series_of_physical("s", friction_laws.bureau_pin("coulomb").with_(
        mu_static=0.65), [1e-5])
    assert static.static_ratio == pytest.approx(1.3)


# --------------------------------------------------------------------------- recipes
def test_the_recipes_come_last_and_quick_is_small() -> None:
    quick, full = all_recipes(True), all_recipes(False)
    assert tuple(r.name for r in quick[-3:]) == NAMES
    assert tuple(r.name for r in full[-3:]) == NAMES
    assert quick[-4].name == "fig19_sphere_contact"
    for q, f in zip(quick[-3:], full[-3:], strict=True):
        assert q.points <= 40 and q.points <= f.points / 3


def test_the_steady_sliding_of_each_law() -> None:
    """Coulomb laws slide at mu0; rate-and-state at the law's own mu_ss (RateAndState)."""
    V = np.array([0.05, 1.0, 3.0])
    assert np.all(friction_laws.steady_mu(Series("c", 0.5, 2.0, 0.5, V, np.nan,
                                                 static_ratio=1.3), V) == 1.0)
    s = Series("r", 0.5, 2.0, 0.5, V, np.nan, **RS)
    law = vf.RateAndState(a=0.03, b=0.05, d_c=1.0, v_ref=1.0)
    np.testing.assert_allclose(friction_laws.steady_mu(s, V), [law.steady_mu(v) for v in V],
                               rtol=1e-13)
    # weakening: 1 + (a - b) ln(V/v_ref) where the regularisation does not matter
    np.testing.assert_allclose(friction_laws.steady_mu(s, V), 1 - 0.02 * np.log(V), atol=1e-12)


def test_the_onset_of_instability_and_the_coulomb_frequency() -> None:
    """Fig. 22's onset near Rice-Ruina's rigid closed form (the contact spring is 49 times
    stiffer than the pin); Fig. 21's Coulomb frequency puts v0* at v0."""
    (onset,) = friction_laws._onset_velocities()
    a, b, d_c = 0.03, 0.05, 1.0
    alpha = friction_laws.WEAKENING_PIN["alpha"]
    rigid = math.sqrt(a * d_c * (alpha * d_c / (b - a) - 1.0))  # alpha = alpha_cr(V)
    assert onset == pytest.approx(rigid, rel=0.01)
    fc = friction_laws._coulomb_frequency()
    pin = friction_laws.bureau_pin("coulomb", fc)
    assert pin.critical_velocity() == pytest.approx(friction_laws.BUREAU_V0, rel=1e-9)
    assert 0.3 < fc < 300.0  # inside Fig. 21's frequency axis


def test_the_map_verdicts_and_its_check_catch_a_contradiction() -> None:
    """Hand-made curves: the verdict of each status; a locked point where steady sliding
    is unstable is counted against the solver, a not-settled one is not."""
    V, amplitudes = friction_laws._map_grid(True)
    stable = friction_laws._stable_at_rest(V)
    assert stable[0] and not stable[-1]
    codes = {s: s.code for s in vf.Status}
    ss = friction_laws.steady_mu(Series("x", 0.2, 10.0, 0.0, V, np.nan, **RS), V)

    def curves(first_row_status: list[vf.Status]) -> dict[str, Curve]:
        out = {}
        for s in friction_laws._map_series(True):
            status = first_row_status if s.amplitude == 0 else [vf.Status.PERIODIC] * V.size
            ok = np.array([x == vf.Status.PERIODIC for x in status])
            out[s.key] = Curve.of(s, mu_ratio=np.where(ok, ss, np.nan), status=[
                codes[x] for x in status], trusted=ok)
        return out

    honest = [vf.Status.PERIODIC if x else vf.Status.NOT_CONVERGED for x in stable]
    c = curves(honest)
    verdicts = friction_laws._verdict(c["a=0"])
    assert list(verdicts) == [0 if x else 2 for x in stable]
    checks, notes = friction_laws._map_checks(c, True)
    assert checks[0].deviation == 0.0 and checks[0].at == "nowhere"
    assert checks[1].deviation == pytest.approx(0.0, abs=1e-15)
    assert f"{(amplitudes.size - 1) * V.size} locked, 0 self-excited" in notes
    lying = [vf.Status.PERIODIC] * V.size  # locked where steady sliding is unstable
    checks, _ = friction_laws._map_checks(curves(lying), True)
    assert checks[0].deviation == float(np.sum(~stable)) > 0
    assert f"V = {V[-1]:.3g} (locked)" in checks[0].at
    averaged = Curve.of(Series("y", 0.2, 10.0, 0.3, V[:2], np.nan, **RS),
                        status=[vf.Status.AVERAGED.code, vf.Status.FAILED.code])
    assert list(friction_laws._verdict(averaged)) == [1, 3]


@pytest.mark.parametrize("name", NAMES)
@pytest.mark.slow
def test_each_recipe_renders_its_figure_table_and_checks(rendered, name: str) -> None:
    r, curves, result, png = rendered[name]
    assert result.figure is not None and len(result.figure.axes) >= 2
    assert png.stat().st_size > 10_000 and png.read_bytes()[:4] == b"\x89PNG"
    panels = [ax for ax in result.figure.axes if ax.get_label() != "<colorbar>"]
    assert all(ax.get_xlabel() for ax in panels) and panels[0].get_ylabel()
    assert result.figure.legends  # the laws (or verdicts) are named
    (table,) = result.tables
    assert len(table) == r.points
    assert COLUMNS[name] <= set(table.columns)
    for key, c in curves.items():  # the table carries each series' law
        rows = table.columns["series"] == key
        np.testing.assert_array_equal(table.columns["rs_a"][rows], c.series.rs_a)
        np.testing.assert_array_equal(table.columns["static_ratio"][rows],
                                      c.series.static_ratio)
    assert result.checks
    assert all(math.isfinite(c.deviation) for c in result.checks)
    # the solver's work stays small in quick mode (CI runs reproduce --quick)
    assert sum(float(np.sum(c.work)) for c in curves.values()) < 30_000


@pytest.mark.slow
def test_fig20_each_law_reaches_its_steady_sliding_at_high_velocity(rendered) -> None:
    _, curves, result, _ = rendered["fig20_friction_laws"]
    for key, (label, _, _) in friction_laws.LAWS.items():
        check = _check(result, label)
        c = curves[key]
        assert np.all(c.trusted[c.v_inertial >= 1.0])
        if c.series.rs_a == 0:  # Coulomb laws: exact above the critical velocity
            assert check.deviation == 0.0
            vc = friction_laws._laws_vc()
            assert np.all(c.mu_ratio[c.v_inertial > vc] == 1.0)
        else:  # rate-and-state: the fluctuations about V shrink as V grows
            assert check.deviation < 2e-3
            ss = friction_laws.steady_mu(c.series, c.v_inertial)
            gap = np.abs(c.mu_ratio - ss)[c.v_inertial >= 1.0]
            assert gap[-1] < gap[0]
    # the reduction by the oscillation at the lowest velocity: every law well below its
    # steady sliding, Coulomb near its static value 1 - a (eq. 2)
    for c in curves.values():
        assert c.mu_ratio[0] / friction_laws.steady_mu(c.series, c.v_inertial[0]) < 0.6
    assert curves["coulomb"].mu_ratio[0] == pytest.approx(0.5, abs=0.02)


@pytest.mark.slow
def test_fig21_no_modulation_is_steady_sliding_and_coulomb_its_static_value(rendered) -> None:
    _, curves, result, _ = rendered["fig21_load_modulation"]
    assert _check(result, "no modulation").deviation < 1e-9
    assert _check(result, "Coulomb model: the static value").deviation < 5e-3
    assert all(np.all(c.trusted) for c in curves.values())
    # the Linker-Dieterich coupling changes the mean only where the load moves
    mu = {k: float(c.mu_ratio[0]) for k, c in curves.items()}
    assert mu["rs:a=0"] == pytest.approx(mu["rs_ld:a=0"], abs=1e-12)
    assert abs(mu["rs:a=0.3"] - mu["rs_ld:a=0.3"]) > 0.01
    # below the Coulomb frequency the Coulomb contact slides throughout
    fc = friction_laws._coulomb_frequency()
    for c in curves.values():
        m = c.series.meta
        if m["model"] == "coulomb" and m["sweep"] == "frequency" and m["frequency_hz"] < fc:
            assert c.mu_ratio[0] == 1.0


@pytest.mark.slow
def test_fig22_amplitude_zero_agrees_with_the_stability_of_steady_sliding(rendered) -> None:
    _, curves, result, _ = rendered["fig22_weakening_map"]
    check = _check(result, "amplitude 0: steady sliding")
    assert check.deviation == 0.0, check.at
    assert _check(result, "amplitude 0, stable steady sliding").deviation < 1e-9
    row = curves["a=0"]
    stable = friction_laws._stable_at_rest(row.v_inertial)
    assert stable.any() and (~stable).any()  # both sides of the onset are on the grid


def test_a_recipes_own_settings_reach_the_solver() -> None:
    """solve_recipes solves a recipe with its own settings, the others with the run's."""
    seen: list = []

    def runner(*columns, settings=None):
        seen.append((len(columns[0]), settings))
        return solve_points_on(*columns, settings=settings)

    point = (Series("p", 0.5, 2.0, 0.5, [0.1], np.nan),)
    strict = vf.SolverSettings(tol_trusted=1e-300)
    recipes = [Recipe("own", "", "", point, lambda c: None, settings=strict),
               Recipe("run", "", "", point, lambda c: None)]
    own, run = solve_recipes(recipes, runner=runner)
    assert sorted(seen, key=lambda x: x[1] is None) == [(1, strict), (1, None)]
    assert not own["p"].trusted[0] and run["p"].trusted[0]  # the same value, two verdicts
    assert own["p"].mu_ratio[0] == run["p"].mu_ratio[0]
    assert friction_laws.weakening_map(True).settings is friction_laws.WEAKENING_SETTINGS
