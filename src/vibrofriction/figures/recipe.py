"""Recipes: what each figure needs from the solver and how it is drawn, tabled and checked.

A :class:`Recipe` couples the :class:`~vibrofriction.figures.series.Series` a
figure needs with a ``render`` function that turns the solved curves into a
:class:`Rendered`: the matplotlib figure, the data table behind it and the
comparisons of the numerics with the paper's closed forms (:class:`Check`).
The report runs every recipe; tests can run a single one.
"""

from __future__ import annotations

import csv
import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure
from numpy.typing import NDArray

from ..solver import STATUS_BY_CODE, SolverSettings
from .series import Curve, Runner, Series, solve

__all__ = ["Check", "Recipe", "Rendered", "Table", "curve_table", "solve_recipes",
           "max_deviation"]


@dataclass(frozen=True)
class Table:
    """Columns of equal length plus the parameter lines written as the CSV header.

    Parameters
    ----------
    name : str
        The table's name (the first comment line of its CSV).
    parameters : sequence of str
        Lines that state the parameters, written as ``#`` comments.
    columns : mapping of str to numpy.ndarray
        The columns by name, all of one length.

    Raises
    ------
    ValueError
        If the columns differ in length.

    Examples
    --------
    >>> import tempfile
    >>> from pathlib import Path
    >>> import numpy as np
    >>> from vibrofriction.figures import Table
    >>> table = Table("demo", ["alpha = 0.1"], {"vbar": np.array([0.5]),
    ...                                         "mu_ratio": np.array([0.5875])})
    >>> len(table)
    1
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     print(table.write_csv(Path(tmp) / "demo.csv").read_text())
    # demo
    # alpha = 0.1
    vbar,mu_ratio
    0.5,0.5875
    <BLANKLINE>
    """

    name: str
    parameters: Sequence[str]
    columns: Mapping[str, NDArray]

    def __post_init__(self) -> None:
        """Check that the columns have one length."""
        lengths = {len(np.asarray(v)) for v in self.columns.values()}
        if len(lengths) > 1:
            raise ValueError(f"table {self.name!r}: columns differ in length {sorted(lengths)}")

    def __len__(self) -> int:
        """The number of rows."""
        return len(next(iter(self.columns.values()))) if self.columns else 0

    def write_csv(self, path: Path) -> Path:
        """CSV with ``#`` comment lines stating the parameters, then a header row."""
        path = Path(path)
        path.parent.mkdir(parents=True, exist_ok=True)
        cols = {k: np.asarray(v) for k, v in self.columns.items()}
        with path.open("w", newline="") as fh:
            fh.write(f"# {self.name}\n")
            for line in self.parameters:
                fh.write(f"# {line}\n")
            writer = csv.writer(fh)
            writer.writerow(list(cols))
            for i in range(len(self)):
                writer.writerow([_cell(cols[k][i]) for k in cols])
        return path


def _cell(x: object) -> str:
    if isinstance(x, float | np.floating):
        return "nan" if math.isnan(x) else repr(float(x))
    if isinstance(x, np.integer):
        return str(int(x))
    return str(x)


@dataclass(frozen=True)
class Check:
    """One comparison of the numerics with a closed form.

    Parameters
    ----------
    formula : str
        The closed form, e.g. ``"eq. (2)"``.
    where : str
        The points compared, in words.
    deviation : float
        The largest ``|numerics - closed form|`` of ``mu/mu0`` (or of the quantity named
        in ``formula``) over those points.
    at : str
        Where it occurs.
    remark : str, optional
        The verdict in words.

    Examples
    --------
    >>> from vibrofriction.figures import Check
    >>> Check("eq. (2)", "a < 1", 1e-6, "vbar = 1e-4")
    Check(formula='eq. (2)', where='a < 1', deviation=1e-06, at='vbar = 1e-4', remark='')
    """

    formula: str
    where: str
    deviation: float
    at: str
    remark: str = ""


@dataclass(frozen=True)
class Rendered:
    """What a recipe produces: a figure (or ``None``), its data, its checks and notes.

    Parameters
    ----------
    figure : matplotlib.figure.Figure or None
        The figure; None for a recipe of checks only.
    tables : tuple of Table
        Its data, written as CSV.
    checks : tuple of Check, optional
        Its comparisons with the closed forms.
    notes : str, optional
        Markdown for the report.

    Examples
    --------
    See :class:`Recipe`.
    """

    figure: Figure | None
    tables: tuple[Table, ...]
    checks: tuple[Check, ...] = ()
    notes: str = ""


@dataclass(frozen=True)
class Recipe:
    """A figure of the reproduction: its series and how to render them.

    Parameters
    ----------
    name : str
        The file stem (``fig04``).
    title, caption : str
        Markdown for the report.
    series : tuple of Series
        The curves to solve.
    render : callable
        ``render(curves)``: a :class:`Rendered` from the solved curves by series key.
    parameters : tuple of str, optional
        Lines that state the parameters.
    settings : vibrofriction.SolverSettings, optional
        The solver's settings for this figure's points (state them in ``parameters``);
        None (default): the settings of the run (:func:`solve_recipes`), else the defaults.

    Examples
    --------
    A recipe of one point, solved and rendered as a table:

    >>> from vibrofriction.figures import Recipe, Rendered, Table, solve_recipes
    >>> from vibrofriction.figures.series import series_at_vbar
    >>> point = series_at_vbar("b", alpha=0.1, beta=2.0, amplitude=0.5, vbar=[0.5])
    >>> def render(curves):
    ...     return Rendered(None, (Table("mu", [], {"mu_ratio": curves["b"].mu_ratio}),))
    >>> recipe = Recipe("demo", "A demo", "One point.", (point,), render)
    >>> [curves] = solve_recipes([recipe])
    >>> recipe.render(curves).tables[0].columns
    {'mu_ratio': array([0.58754462])}
    """

    name: str
    title: str
    caption: str
    series: tuple[Series, ...]
    render: Callable[[Mapping[str, Curve]], Rendered]
    parameters: tuple[str, ...] = field(default_factory=tuple)
    settings: SolverSettings | None = None

    @property
    def points(self) -> int:
        """The number of velocity points of all series."""
        return sum(s.size for s in self.series)


def solve_recipes(recipes: Sequence[Recipe], *, runner: Runner | None = None,
                  settings: SolverSettings | None = None) -> list[dict[str, Curve]]:
    """Solve the series of all recipes in one batch per settings.

    Parameters
    ----------
    recipes : sequence of Recipe
        The recipes.
    runner : callable, optional
        Solves the points (a ``Runner`` of ``vibrofriction.figures.series``); default
        the exact solver in this process.
    settings : vibrofriction.SolverSettings, optional
        The solver's settings of every recipe that has none of its own
        (:attr:`Recipe.settings`).

    Returns
    -------
    list of dict of str to Curve
        Per recipe, its curves by series key.

    Examples
    --------
    See :class:`Recipe`.
    """
    groups: dict[SolverSettings | None, list[int]] = {}
    for i, r in enumerate(recipes):
        groups.setdefault(r.settings or settings, []).append(i)
    out: list[dict[str, Curve]] = [{} for _ in recipes]
    for chosen, members in groups.items():
        tagged = [replace(s, key=f"{i}\x1f{s.key}") for i in members
                  for s in recipes[i].series]
        for key, curve in solve(tagged, runner=runner, settings=chosen).items():
            index, own = key.split("\x1f", 1)
            s = curve.series
            out[int(index)][own] = replace(curve, series=replace(s, key=own))
    return out


def curve_table(name: str, curves: Mapping[str, Curve], parameters: Sequence[str],
                extra: Callable[[Curve], Mapping[str, NDArray]] | None = None,
                x: Callable[[Curve], Mapping[str, NDArray]] | None = None) -> Table:
    """Long-format table of curves: one row per point.

    Columns: ``series``, ``alpha``, ``beta``, ``amplitude``, ``vbar`` (nan where it
    does not exist), ``v_inertial``, any ``x`` columns (e.g. ``v0_m_per_s``),
    ``mu_ratio``, ``error``, ``status`` (the solver's status name) and any
    ``extra`` columns (closed forms at the same points).
    """
    cols: dict[str, list] = {}

    def add(k: str, v) -> None:
        cols.setdefault(k, []).append(np.asarray(v))

    for key, c in curves.items():
        s = c.series
        n = s.size
        add("series", np.full(n, key, dtype=object))
        add("alpha", np.full(n, s.alpha))
        add("beta", np.full(n, s.beta))
        add("amplitude", np.full(n, s.amplitude))
        add("vbar", s.vbar)
        add("v_inertial", s.v_inertial)
        for k, v in (x(c) if x else {}).items():
            add(k, v)
        add("mu_ratio", c.mu_ratio)
        add("error", c.error)
        add("status", np.array([STATUS_BY_CODE[int(t)].value for t in c.status],
                               dtype=object))
        for k, v in (extra(c) if extra else {}).items():
            add(k, v)
    return Table(name, tuple(parameters),
                 {k: np.concatenate(v) if v else np.empty(0) for k, v in cols.items()})


def max_deviation(values: NDArray, reference: NDArray, labels: Sequence[str]
                  ) -> tuple[float, str]:
    """Largest ``|values - reference|`` (ignoring nan) and the label of where it occurs."""
    d = np.abs(np.asarray(values, dtype=float) - np.asarray(reference, dtype=float))
    if d.size == 0 or np.all(np.isnan(d)):
        return math.nan, "no points"
    i = int(np.nanargmax(d))
    return float(d[i]), labels[i]
