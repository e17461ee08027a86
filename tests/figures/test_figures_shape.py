"""Figs. 17-18 (the shape of the contact by MDR, issue 21): the recipes render, the stiff
panels meet the stiff law, equal normal-force amplitude holds by brute force, and the
linearised sphere's amplitude is 3/2 of the full sphere's."""

from __future__ import annotations

import math

import numpy as np
import pytest

from vibrofriction.figures import all_recipes, contact, shape, style
from vibrofriction.figures.recipe import solve_recipes
from vibrofriction.schema import ContactState

NAMES = ("fig17_shape", "fig18_sphere_linearised")
RECIPES = {"fig17_shape": shape.shape_dependence, "fig18_sphere_linearised":
           shape.sphere_linearised}


@pytest.fixture(scope="module", params=NAMES)
def rendered(request, tmp_path_factory):
    """One quick recipe, solved, rendered and saved: ``(recipe, curves, rendered, png)``."""
    recipe = RECIPES[request.param](True)
    curves = solve_recipes([recipe])[0]
    result = recipe.render(curves)
    png = style.save(result.figure, tmp_path_factory.mktemp("shape"), recipe.name)[0]
    return recipe, curves, result, png


def test_shape_recipes_follow_inplane_with_smaller_quick_grids() -> None:
    quick, full = all_recipes(True), all_recipes(False)
    at = [r.name for r in quick].index(NAMES[0])
    names = (*NAMES, "fig19_sphere_contact")
    assert tuple(r.name for r in quick[at:at + 3]) == names
    assert tuple(r.name for r in full[at:at + 3]) == names
    assert quick[at - 1].name == "fig16_inplane_drive"
    for q, f in zip(quick[at:at + 2], full[at:at + 2], strict=True):
        assert q.points <= f.points / 3
    assert quick[at + 2].points == full[at + 2].points == 0  # Fig. 19 simulates histories


def test_fig19_sphere_contact_renders_with_its_checks(tmp_path) -> None:
    """Fig. 19 (figures/contact.py): one period of the sphere's MDR history at a = 0.5 and
    1.5; its checks against the solver, the mean normal force and the energy balance, the
    table's columns, and the jumping sphere's centre out of contact 1 - arccos(-1/a)/pi
    of the period."""
    recipe = contact.fig19()
    assert recipe.name == "fig19_sphere_contact" and recipe.series == ()
    out = recipe.render({})
    assert style.save(out.figure, tmp_path, recipe.name)[0].stat().st_size > 50_000
    (table,) = out.tables
    assert {"amplitude", "tau", "f", "n", "stick_radius", "contact_radius",
            "stick_area_fraction", "slip_area_fraction", "open_area_fraction"} \
        <= set(table.columns)
    cols = table.columns
    assert np.all(cols["stick_radius"] < cols["contact_radius"] + 1e-12)
    assert len(out.checks) == 8
    for c in out.checks:
        if c.formula.startswith("the rows of"):
            assert c.deviation <= float(c.at.split()[-1]), c  # within the bars
        elif c.formula.startswith("mean normal"):
            assert c.deviation < 1e-6, c
        else:
            assert c.deviation < 1e-12, c
    hs = contact.sphere_histories()
    jumping = hs[1.5]
    centre_open = np.mean(jumping.spring_state[:-1, 0] == ContactState.FLIGHT)
    assert centre_open == pytest.approx(1 - math.acos(-1 / 1.5) / math.pi, abs=2 / 720)
    assert "27 %" in recipe.caption and f"{100 * centre_open:.1f} %" in out.notes


@pytest.mark.slow
def test_each_recipe_renders_a_figure_and_one_table(rendered) -> None:
    recipe, curves, result, png = rendered
    assert png.stat().st_size > 20_000
    (table,) = result.tables
    assert len(table) == recipe.points
    assert {"profile_exponent", "mu_ratio", "error", "status"} <= set(table.columns)
    trusted = np.concatenate([c.trusted for c in curves.values()])
    assert trusted.mean() >= 0.9
    assert any(math.isfinite(c.series.profile_exponent) for c in curves.values())


@pytest.mark.slow
def test_stiff_panels_meet_the_stiff_law(rendered) -> None:
    recipe, curves, result, _ = rendered
    if recipe.name != "fig17_shape":
        pytest.skip("Fig. 17 only")
    (c,) = [c for c in result.checks if c.formula.startswith("stiff system")]
    assert c.deviation < 1e-2, c       # alpha = 0.01: the distance falls like alpha


def test_at_equal_force_amplitude_only_the_jumping_panel_separates_the_shapes(rendered):
    """Docs' answer (docs/contact_geometry.md, "How much the shape matters"): without
    jumping the three tips nearly coincide; where the flat punch jumps the curved tips,
    which do not, rub more."""
    recipe, curves, _, _ = rendered
    if recipe.name != "fig17_shape":
        pytest.skip("Fig. 17 only")
    for system in shape.SYSTEMS:
        flat, sph, cone = (curves[shape._key(system, 0.5, name)].trusted_mu
                           for name, _, _ in shape.PROFILES)
        assert np.nanmax(np.abs(sph - flat)) < 0.05 and np.nanmax(np.abs(cone - flat)) < 0.05
        flat, sph, cone = (curves[shape._key(system, 1.5, name)].trusted_mu
                           for name, _, _ in shape.PROFILES)
        below = flat < 1 - 1e-9
        assert np.all(sph[below] > flat[below]) and np.all(cone[below] > flat[below])


@pytest.mark.parametrize("flat_a", shape.FLAT_AMPLITUDES)
@pytest.mark.parametrize("n", [2.0, 1.0, 3.0])
def test_equal_force_amplitude_by_brute_force(flat_a: float, n: float) -> None:
    """Half the peak-to-peak force over the mean force, sampled over one period (no
    closed form used): the curved tip at equal_force_amplitude matches the flat punch."""
    tau = np.linspace(0.0, 2 * math.pi, 400_001)[:-1]

    def a_f(a: float, p: float) -> float:
        f = np.maximum(0.0, 1.0 + a * np.cos(tau)) ** p
        return (f.max() - f.min()) / (2.0 * f.mean())

    a = shape.equal_force_amplitude(flat_a, n)
    assert a_f(a, 1.0 + 1.0 / n) == pytest.approx(a_f(flat_a, 1.0), rel=1e-7)
    assert a < flat_a                   # a curved tip's force is peakier


def test_linearised_sphere_amplitude_is_three_halves_of_the_full_one() -> None:
    """Hertz: F ~ d^(3/2), so the tangent spring at the load has u_z0 = F/k_zc = 2 d0/3."""
    for du in shape.BENCH_DU_Z:
        lin = shape.bench_physical(du, "linearised").to_dimensionless()
        mdr = shape.bench_physical(du, "mdr").to_dimensionless()
        assert lin.amplitude == pytest.approx(1.5 * mdr.amplitude, rel=1e-9)
        assert mdr.profile_exponent == 2.0 and lin.profile_exponent == math.inf
        assert lin.alpha == pytest.approx(mdr.alpha, rel=1e-12)
