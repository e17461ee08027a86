"""The paper's figures, regenerated from the solver (and the maps beyond the paper).

One module per figure family; each exposes *recipes* (:class:`~.recipe.Recipe`):
the solver series a figure needs and how to draw, table and check them.

* :mod:`.history`: Fig. 2, forces over time in a stick-slip steady state;
* :mod:`.velocity`: Figs. 3, 4, 5, 7, ``mu/mu0`` against ``vbar``;
* :mod:`.resonant`: Fig. 6 (case IV) and the prediction for Figs. 8-9;
* :mod:`.dimensional`: Fig. 10, COF against ``v0`` in m/s;
* :mod:`.maps`: maps over the ``(alpha, beta)`` plane;
* :mod:`.damped`: beyond the paper, the damped model (Figs. 11-13: case IV, Fig. 10
  and Fig. 5 with pin damping);
* :mod:`.inplane`: beyond the paper, the longitudinal in-plane oscillation (Figs. 14-16:
  the directions of oscillation, the combined drive over phase and velocity, the drive's
  blocking force and idle velocity);
* :mod:`.shape`: beyond the paper, the shape of the contact by MDR (Figs. 17-18: flat,
  sphere and cone at equal normal-force amplitude; the linearised against the full sphere);
* :mod:`.contact`: beyond the paper, stick, slip and lift-off across a sphere over one
  period (Fig. 19: the MDR time history's space-time picture);
* :mod:`.atlas`: quick looks at a sweep's atlas, curves or a map (:func:`plot_atlas`;
  imported on first use, with xarray and the sweep);
* :mod:`.bench`: the bench's figures, a fit against its data (:func:`plot_fit`) and a
  design's map (:func:`plot_design`; imported on first use, with the bench);
* :mod:`.edges`: cell edges of a plotted grid axis (maps, atlases);
* :mod:`.checks`: the physics checks of the curves (numerics against the closed forms),
  pure functions without drawing;
* :mod:`.style`: the shared matplotlib style.  Figures are ``matplotlib.figure.Figure``
  objects (no pyplot): importing this package never changes the matplotlib backend.
"""

from __future__ import annotations

import os
from typing import TYPE_CHECKING, Any

from . import (
    contact,
    damped,
    dimensional,
    history,
    inplane,
    maps,
    resonant,
    shape,
    style,
    velocity,
)
from .edges import cell_edges, is_geometric
from .recipe import Check, Recipe, Rendered, Table, solve_recipes
from .series import Curve, Series, solve

if TYPE_CHECKING:
    import xarray as xr
    from matplotlib.figure import Figure

    from ..bench import DesignResult, FitResult

__all__ = [
    "Check",
    "Curve",
    "Recipe",
    "Rendered",
    "Series",
    "Table",
    "all_recipes",
    "cell_edges",
    "is_geometric",
    "plot_atlas",
    "plot_design",
    "plot_fit",
    "solve",
    "solve_recipes",
    "style",
]


def all_recipes(quick: bool = False) -> list[Recipe]:
    """Every figure of the reproduction, in the paper's order (``quick``: reduced grids)."""
    return [
        history.fig2(),
        *velocity.fig3(quick),
        velocity.fig4(quick),
        velocity.fig5(quick),
        resonant.fig6(quick),
        velocity.fig7(quick),
        resonant.fig8_9(quick),
        dimensional.fig10(quick),
        maps.maps(quick),
        damped.damped_case_iv(quick),
        damped.damped_fig10(quick),
        damped.damped_fig5(quick),
        inplane.inplane_directions(quick),
        inplane.inplane_map(quick),
        inplane.inplane_drive(quick),
        shape.shape_dependence(quick),
        shape.sphere_linearised(quick),
        contact.fig19(),
    ]


def plot_atlas(source: xr.Dataset | str | os.PathLike, **kwargs: Any):
    """Plot an atlas of :func:`vibrofriction.sweep.sweep` (a Dataset or a store path).

    See :func:`vibrofriction.figures.atlas.plot_atlas` (xarray and the sweep are
    imported on first use).
    """
    from .atlas import plot_atlas as _plot

    return _plot(source, **kwargs)


def plot_fit(result: FitResult) -> Figure:
    """A fit against its data and its residuals.

    A fit against its data and its residuals (:func:`vibrofriction.figures.bench.plot_fit`;
    the bench is imported on first use).
    """
    from .bench import plot_fit as _plot

    return _plot(result)


def plot_design(result: DesignResult) -> Figure:
    """A design's map with its optimum.

    A design's map with its optimum (:func:`vibrofriction.figures.bench.plot_design`;
    the bench is imported on first use).
    """
    from .bench import plot_design as _plot

    return _plot(result)
