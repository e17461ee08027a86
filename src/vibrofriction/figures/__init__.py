"""The paper's figures, regenerated from the solver (and the maps beyond the paper).

One module per figure family; each exposes *recipes* (:class:`~.recipe.Recipe`):
the solver series a figure needs and how to draw, table and check them.

* :mod:`.history`: Fig. 2, forces over time in a stick-slip steady state, and any
  history's forces, local coefficient and rate-and-state state (:func:`plot_history`);
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
* :mod:`.friction_laws`: beyond the paper, local friction laws other than Coulomb's
  (Figs. 20-22: a static coefficient above the kinetic one and rate-and-state friction
  under a normal oscillation; a normal-load modulation as in Bureau et al. 2000; where the
  oscillation suppresses or creates stick-slip on a velocity-weakening contact);
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
    friction_laws,
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
    from ..solver import History

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
    "plot_history",
    "plot_profiles",
    "solve",
    "solve_recipes",
    "style",
]


def all_recipes(quick: bool = False) -> list[Recipe]:
    """Every figure of the reproduction, in the paper's order.

    Parameters
    ----------
    quick : bool, optional
        Reduced velocity grids and maps (for CI).

    Returns
    -------
    list of Recipe
        One recipe per figure (Figs. 3a and 3b are two).

    Examples
    --------
    >>> from vibrofriction.figures import all_recipes
    >>> recipes = all_recipes(quick=True)
    >>> len(recipes), recipes[0].name
    (22, 'fig02_history')
    """
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
        friction_laws.friction_laws(quick),
        friction_laws.load_modulation(quick),
        friction_laws.weakening_map(quick),
    ]


def plot_atlas(source: xr.Dataset | str | os.PathLike, **kwargs: Any):
    r"""Plot a variable of an atlas of :func:`vibrofriction.sweep.sweep` and return the figure.

    With ``y=None``, curves along ``x`` (default: the velocity), one per value of the
    single other swept dimension (continuation: up solid, down dashed); with ``y``
    given, a map over ``x`` and ``y``. Other swept dimensions must be fixed with
    ``sel={dim: value}`` (nearest value). Untrusted points (``trusted`` is False) are
    marked, not drawn as results: crosses on curves, hatched cells on maps. Log axes for
    geometric coordinates. xarray and the sweep are imported on first use.

    Parameters
    ----------
    source : xarray.Dataset or str or os.PathLike
        The atlas, or the path of its store.
    **kwargs
        ``x``, ``y`` (dimension names), ``var`` (default ``"mu_ratio"``), ``sel``,
        ``out`` (write the figure there: PNG, PDF, SVG by extension) and
        ``max_curves`` (default 24).

    Returns
    -------
    matplotlib.figure.Figure
        The figure.

    Examples
    --------
    >>> import vibrofriction as vf
    >>> from vibrofriction.figures import plot_atlas
    >>> atlas = vf.sweep(alpha=0.1, beta=2.0, amplitude=0.5, vbar=[0.25, 0.5, 1.0],
    ...                  workers=1, progress=False)
    >>> fig = plot_atlas(atlas)
    >>> print(fig.axes[0].get_xlabel())
    $\bar v = v_0/v_0^*$
    """
    from .atlas import plot_atlas as _plot

    return _plot(source, **kwargs)


def plot_history(h: History) -> Figure:
    """A time history of :func:`vibrofriction.simulate`: forces, local coefficient, theta.

    The normal and tangential forces with the contact's phases shaded and its events
    marked, the local coefficient ``f/n`` below with the law's levels and, for
    rate-and-state friction (a :class:`~vibrofriction.RateStateHistory`), the state
    ``theta`` on a log scale with its steady-sliding value ``d_c/|V|``.

    Parameters
    ----------
    h : vibrofriction.History
        What :func:`vibrofriction.simulate` returned.

    Returns
    -------
    matplotlib.figure.Figure
        The figure.

    Examples
    --------
    >>> import vibrofriction as vf
    >>> from vibrofriction.figures import plot_history
    >>> system = vf.Dimensionless(0.5, 2.0, 1.3, rs_a=0.03, rs_b=0.01, rs_d_c=0.02,
    ...                           rs_v_ref=0.2)
    >>> h = vf.simulate(system, v_inertial=0.5, periods=2, initial="steady")
    >>> len(plot_history(h).axes)
    3
    """
    return history.plot_history(h)


def plot_fit(result: FitResult) -> Figure:
    """A fit against its data and its residuals.

    Data with error bars, the fitted curves per (amplitude, frequency) and the
    residuals; the title gives the free parameters, the verdict and the reduced
    chi-square. The bench is imported on first use.

    Parameters
    ----------
    result : vibrofriction.bench.FitResult
        What :func:`vibrofriction.fit` returned.

    Returns
    -------
    matplotlib.figure.Figure
        The figure.

    Examples
    --------
    A fit solves hundreds of points (the gallery's ``fit_pin_on_disk`` example), so
    this one is not run with the API's doctests:

    >>> import vibrofriction as vf
    >>> from vibrofriction.figures import plot_fit
    >>> result = vf.fit(vf.read_measurements("data.csv"), guess,
    ...                 free=["mu0", "mass", "k_xc"])  # doctest: +SKIP
    >>> plot_fit(result).savefig("fit.png", dpi=150)  # doctest: +SKIP
    """
    from .bench import plot_fit as _plot

    return _plot(result)


def plot_profiles(result: FitResult, truth: dict[str, float] | None = None) -> Figure:
    """A fit's profile chi-square per free parameter, with its level and its interval.

    Every refit of the profiles (the parameter held, the others refitted), the level that
    bounds the 95 % interval, the interval, the fit and, where given, the ``truth`` (a
    mapping of parameter names to values). The bench is imported on first use.

    Parameters
    ----------
    result : vibrofriction.bench.FitResult
        What :func:`vibrofriction.fit` returned (a result loaded from JSON keeps no profiles).
    truth : dict, optional
        Values to mark, by parameter name.

    Returns
    -------
    matplotlib.figure.Figure
        The figure.

    Examples
    --------
    >>> from vibrofriction.figures import plot_profiles
    >>> plot_profiles(result).savefig("profiles.png", dpi=150)  # doctest: +SKIP
    """
    from .bench import plot_profiles as _plot

    return _plot(result, truth)


def plot_design(result: DesignResult) -> Figure:
    """A design's map with its optimum.

    The COF over the actuator's range (white: untrusted or beyond the velocity limit),
    the optimum and the pin's resonance. An in-plane design: the signed COF over
    ``(phase_x, du_x)`` at the chosen frequency and ``du_z``, and over ``(omega, du_z)``
    at the map's ``du_x`` and ``phase_x`` nearest the optimum. The bench is imported on
    first use.

    Parameters
    ----------
    result : vibrofriction.bench.DesignResult
        What :func:`vibrofriction.design` returned.

    Returns
    -------
    matplotlib.figure.Figure
        The figure.

    Examples
    --------
    A design solves a map of points (the gallery's ``design_oscillation`` example), so
    this one is not run with the API's doctests:

    >>> import vibrofriction as vf
    >>> from vibrofriction.figures import plot_design
    >>> pin = vf.from_bench(natural_frequency_hz=800, mass=0.01, quality_factor=50,
    ...                     normal_load=20, k_zc=2e7, k_xc=1.5e7,
    ...                     drive_frequency_hz=1000, du_z=0.5e-6, mu0=0.3)
    >>> best = vf.design(pin, v0=0.01, omega=(1e3, 3e4),
    ...                  du_z=(1e-7, 9e-7))  # doctest: +SKIP
    >>> plot_design(best).savefig("design.png", dpi=150)  # doctest: +SKIP
    """
    from .bench import plot_design as _plot

    return _plot(result)
