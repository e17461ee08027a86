"""Figs. 14-16 (the longitudinal in-plane oscillation): the recipes render, their checks hold
the physics, the closed forms of docs/inplane.md are met and the mirror symmetry holds."""

from __future__ import annotations

import math

import numpy as np
import pytest

from vibrofriction import theory
from vibrofriction.figures import all_recipes, inplane, style
from vibrofriction.figures.recipe import solve_recipes
from vibrofriction.figures.series import Curve, Series, solve
from vibrofriction.solver import solve_points

NAMES = ("fig14_inplane_directions", "fig15_inplane_map", "fig16_inplane_drive")
RECIPES = {"fig14_inplane_directions": inplane.inplane_directions,
           "fig15_inplane_map": inplane.inplane_map,
           "fig16_inplane_drive": inplane.inplane_drive}


@pytest.fixture(scope="module", params=NAMES)
def rendered(request, tmp_path_factory):
    """One quick recipe, solved, rendered and saved: ``(recipe, curves, rendered, png)``."""
    recipe = RECIPES[request.param](True)
    curves = solve_recipes([recipe])[0]
    result = recipe.render(curves)
    png = style.save(result.figure, tmp_path_factory.mktemp("inplane"), recipe.name)[0]
    return recipe, curves, result, png


def _check(result, start: str):
    found = [c for c in result.checks if c.formula.startswith(start)]
    assert found, start
    return found


def test_inplane_recipes_are_registered_in_order_with_smaller_quick_grids() -> None:
    quick, full = all_recipes(True), all_recipes(False)
    k = [r.name for r in quick].index(NAMES[0])
    assert tuple(r.name for r in quick[k:k + 3]) == NAMES
    assert tuple(r.name for r in full[k:k + 3]) == NAMES
    for q, f in zip(quick[k:k + 3], full[k:k + 3], strict=True):
        assert q.points < f.points / 4


@pytest.mark.slow
def test_each_recipe_renders_a_figure_one_table_and_passing_checks(rendered) -> None:
    recipe, curves, result, png = rendered
    assert png.stat().st_size > 20_000
    assert len(result.tables) == 1                   # data/<name>.csv, as the report expects
    table = result.tables[0]
    assert len(table) == recipe.points
    assert {"a_x", "phase_x", "inplane_on", "mu_ratio", "status"} <= set(table.columns)
    for key, c in curves.items():
        if key == "transverse":  # undamped 2-D: only the points nearest V = 0 averaged
            bad = c.series.v_inertial[~c.trusted]
            assert bad.size <= 4 and np.all(np.abs(bad) < 0.01), bad
        else:
            assert np.all(c.trusted), key
    for c in _check(result, "continuous sliding"):   # mu = sign(V) beyond theory's V_c
        assert c.deviation < 1e-9, c
    for c in _check(result, "mirror symmetry"):
        assert c.deviation < 1e-12, c


def test_below_the_critical_velocity_the_contact_does_not_slide() -> None:
    recipe = inplane.inplane_directions(True)
    result = recipe.render(solve_recipes([recipe])[0])
    for c in _check(result, "no continuous sliding below"):
        assert 0 < c.deviation < 0.1, c


def test_the_map_reaches_full_friction_within_one_step_of_v_c() -> None:
    recipe = inplane.inplane_map(True)
    result = recipe.render(solve_recipes([recipe])[0])
    for c in _check(result, "|mu/mu0| reaches 1"):
        dv = float(c.where.split("dV = ")[1])
        assert c.deviation < dv, c
    # a_x = 1 drives (hatched cells) near phase pi; a_x = 0.5 nowhere
    assert "a_x = 0.5: 0 of" in result.notes
    assert "a_x = 1: 0 of" not in result.notes


def test_blocking_force_meets_the_static_band_and_idle_velocity_is_a_root() -> None:
    recipe = inplane.inplane_drive(True)
    curves = solve_recipes([recipe])[0]
    result = recipe.render(curves)
    for c in _check(result, "blocking force"):
        assert c.deviation < 1e-3, c                  # creep at V = 1e-5 (~5 V to 30 V)
    for c in _check(result, "convergence in V"):
        assert c.deviation < 5e-3, c
    for c in _check(result, "an idle velocity exists iff"):
        assert c.deviation == 0, c
    for c in _check(result, "|mu/mu0| at the idle"):
        assert c.deviation < 1e-5, c
    # the numbers at phase_x = pi/2 (benchmarks/results/inplane_drive.md): blocking
    # forces +-0.375047 undamped, against the band +-0.375 of theory
    phases = np.linspace(0, 2 * math.pi, 13)
    j = int(np.argmin(np.abs(phases - math.pi / 2)))
    c = curves[f"a_x=0.5,zeta=0,phase={j}"]
    up, down = inplane.blocking_forces(c)
    band = theory.inplane_static_mu_ratio(*inplane.SYSTEM, 0.5, phases[j])
    assert abs(up - float(band.upper)) < 1e-4 and abs(down - float(band.lower)) < 1e-4
    assert inplane.idle_velocities(c) == []
    # a_x = 1 at phase pi: both limits negative, the body is driven forward up to V_idle
    k = int(np.argmin(np.abs(phases - math.pi)))
    d = curves[f"a_x=1,zeta=0,phase={k}"]
    up, down = inplane.blocking_forces(d)
    assert up < 0 and down < 0
    (v_idle,) = inplane.idle_velocities(d)
    assert 0 < v_idle < theory.inplane_critical_velocity(*inplane.SYSTEM, 1.0, phases[k])
    mu = solve_points(*inplane.SYSTEM, [0.9 * v_idle, 1.1 * v_idle], 0.0, 0.0, 1.0,
                      phases[k])["mu_ratio"]
    assert mu[0] < 0 < mu[1]


@pytest.mark.parametrize("zeta, eta_c, on", [(0.0, 0.0, "substrate"), (0.05, 0.1, "substrate"),
                                             (0.05, 0.1, "holder")])
def test_mirror_symmetry_of_independent_solves(zeta: float, eta_c: float, on: str) -> None:
    """mu(V; phase) = -mu(-V; phase + pi), each side solved through the figures' series
    (the holder too: a batch mixing both modes is split by solve_points_on)."""
    rng = np.random.default_rng(20)
    phases = rng.uniform(0, 2 * math.pi, 4)
    V = np.array([0.02, 0.3, 0.7, 1.4])
    fwd = [Series(f"f{i}", 0.5, 2.0, 0.5, V, np.full(4, np.nan), zeta=zeta, eta_c=eta_c,
                  a_x=0.8, phase_x=float(p), inplane_on=on) for i, p in enumerate(phases)]
    bwd = [Series(f"b{i}", 0.5, 2.0, 0.5, -V, np.full(4, np.nan), zeta=zeta, eta_c=eta_c,
                  a_x=0.8, phase_x=float(p + math.pi), inplane_on=on)
           for i, p in enumerate(phases)]
    other = Series("other", 0.5, 2.0, 0.5, V, np.full(4, np.nan), a_x=0.8,
                   inplane_on="substrate" if on == "holder" else "holder")
    curves: dict[str, Curve] = solve([*fwd, *bwd, other])
    for i in range(4):
        f, b = curves[f"f{i}"], curves[f"b{i}"]
        assert np.all(f.trusted) and np.all(b.trusted)
        np.testing.assert_allclose(f.mu_ratio, -b.mu_ratio, rtol=0, atol=1e-12)
        direct = solve_points(0.5, 2.0, 0.5, V, zeta, eta_c, 0.8, phases[i], inplane_on=on)
        np.testing.assert_array_equal(f.mu_ratio, direct["mu_ratio"])
