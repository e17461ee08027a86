"""``vibrofriction reproduce``: every figure of the paper, its data and a checked report.

:func:`reproduce` solves the series of every recipe of :mod:`vibrofriction.figures`
(spread over worker processes), renders each figure as PNG and PDF as soon as its
data are complete, writes the data behind each figure as CSV (a ``#`` header states
the parameters) and finally ``report.md``: the figures with captions, notes on
convergence, and the table *numerics vs closed form* (largest deviation, where
measured), also written as ``deviations.csv``.

Every point depends only on its own parameters (``solve_points`` is bitwise
reproducible), so the results do not depend on how the points are split among
processes.
"""

from __future__ import annotations

import functools
import math
import os
import platform
import time
from collections import deque
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
from tqdm.auto import tqdm

from . import __version__, theory
from .figures import all_recipes, style
from .figures.recipe import Check, Recipe, Rendered, Table, curve_table, max_deviation
from .figures.series import (
    Curve,
    Series,
    point_columns,
    series_at_vbar,
    solve,
    solve_points_on,
)
from .solver import STATUS_BY_CODE, SolverSettings
from .warmup import warm_up

if TYPE_CHECKING:
    from .parallel import Task

__all__ = ["Reproduction", "check_recipe", "reproduce", "recipes"]

_CHUNK = 160  # points per task: small enough to balance two cores and move the bar


# --------------------------------------------------------------------------- extra checks
_STATIC_SYSTEMS = ((0.01, 0.02), (0.2, 0.22), (0.01, 5.3), (0.01, 400.0), (5.0, 400.0),
                   (380.0, 400.0), (5.0, 5.3), (1.0, 5.3), (1.0, 400.0), (1.0, math.inf),
                   (0.01, 1.0), (0.2, 1.0))
_STATIC_AMPLITUDES = (0.5, 1.0, 1.5)
_STATIC_VBAR = (1e-4, 1e-3)


def check_recipe(quick: bool = False) -> Recipe:
    """The checks that belong to no single figure: the static limit, eq. (2), as v0 -> 0.

    Each system of the Fig. 3 matrix (and case IV on a rigid contact) is solved at
    ``vbar = 1e-4`` and ``1e-3`` (the same values of ``V`` on the resonance lines,
    where ``vbar`` does not exist).

    Parameters
    ----------
    quick : bool, optional
        Unused: a handful of points either way (the signature of every recipe maker).

    Returns
    -------
    Recipe
        The recipe ``checks_static_limit``.

    Examples
    --------
    >>> from vibrofriction.report import check_recipe
    >>> recipe = check_recipe()
    >>> recipe.name, recipe.points
    ('checks_static_limit', 70)
    """
    del quick  # a handful of points either way
    series = []
    v = np.array(_STATIC_VBAR)
    for alpha, beta in _STATIC_SYSTEMS:
        for a in _STATIC_AMPLITUDES:
            key = f"alpha={alpha:g},beta={beta:g},a={a:g}"
            if beta == 1.0:
                # case III: mu = 1 at every V > 0.  V = 1e-4 at a = 1 is left out: there the
                # solver exhausts its event budget (about 5400 events per period, status
                # "failed", 12 s), see docs/figures.md.
                vv = v[1:] if a == 1.0 else v
                series.append(Series(key, alpha, beta, a, vv, np.full(vv.size, np.nan),
                                     {"resonant": True}))
            elif alpha == 1.0:
                series.append(Series(key, alpha, beta, a, v, np.full(v.size, np.nan),
                                     {"resonant": True}))
            else:
                series.append(series_at_vbar(key, alpha, beta, a, v, resonant=False))

    def render(curves: Mapping[str, Curve]) -> Rendered:
        table = curve_table("Static limit: mu/mu0 at vbar = 1e-4, 1e-3 (V on resonance lines)",
                            curves, ("static_eq2 = 1 - a (a < 1), 0 (a >= 1)",),
                            extra=lambda c: {"static_eq2": np.full(
                                c.series.size, float(theory.static_mu_ratio(c.series.amplitude)))})
        checks = []
        for label, pick in (
                ("eq. (2): static value as v0 -> 0 (non-jumping)",
                 lambda s: s.amplitude < 1.0 and s.beta != 1.0),
                ("eq. (2): static value as v0 -> 0 (a >= 1)",
                 lambda s: s.amplitude >= 1.0 and s.beta != 1.0),
                ("eq. (2) in case III (beta = 1): the limit v0 -> 0+ is 1, not 1 - a",
                 lambda s: s.beta == 1.0 and s.amplitude <= 1.0)):
            cs = [c for c in curves.values() if pick(c.series)]
            ref = np.array([float(theory.static_mu_ratio(c.series.amplitude)) for c in cs])
            labels = [f"({c.series.alpha:g}, {c.series.beta:g}), a={c.series.amplitude:g}"
                      for c in cs]
            d0, at0 = max_deviation(np.array([c.mu_ratio[0] for c in cs]), ref, labels)
            d1, at1 = max_deviation(np.array([c.mu_ratio[-1] for c in cs]), ref, labels)
            checks.append(Check(
                label, f"{len(cs)} systems of the Fig. 3 matrix and case IV, vbar = "
                f"{_STATIC_VBAR[0]:g} (V where vbar does not exist)", d0, at0,
                (f"at vbar = {_STATIC_VBAR[1]:g}: {d1:.3g} ({at1}); the deviation "
                 "vanishes as v0 -> 0") if "III" not in label else
                "mu = mu0 at every v0 > 0: eq. (2) holds only at v0 = 0 itself"))
        return Rendered(None, (table,), tuple(checks), "")

    return Recipe(name="checks_static_limit", title="Static limit (eq. 2)", caption="",
                  series=tuple(series), render=render)


def recipes(quick: bool = False) -> list[Recipe]:
    """All figure recipes plus the extra checks, in report order.

    The argument ``quick`` is that of :func:`vibrofriction.figures.all_recipes`.

    Returns
    -------
    list of Recipe
        :func:`vibrofriction.figures.all_recipes` and :func:`check_recipe`.

    Examples
    --------
    >>> from vibrofriction.report import recipes
    >>> names = [r.name for r in recipes(quick=True)]
    >>> names[:3], names[-1]
    (['fig02_history', 'fig03a_matrix', 'fig03b_matrix'], 'checks_static_limit')
    """
    return [*all_recipes(quick), check_recipe(quick)]


# --------------------------------------------------------------------------- tasks
# The functions below run in the worker processes of the package's one pool
# (vibrofriction.parallel), or in this process with workers=1.  They get everything
# as arguments: the recipes, which hold closures, are rebuilt in the worker from
# ``quick`` and looked up by name.
@functools.cache
def _recipes_by_name(quick: bool) -> dict[str, Recipe]:
    return {r.name: r for r in recipes(quick)}


def _solve_chunk(settings: SolverSettings | None, *columns: np.ndarray
                 ) -> tuple[int, dict[str, np.ndarray]]:
    """``(pid, solve_points_on(*columns, settings=settings))``: the pid says who worked.

    ``settings`` are the recipe's (None: the defaults).
    """
    return os.getpid(), solve_points_on(*columns, settings=settings)


@dataclass(frozen=True)
class _Done:
    """What rendering one recipe produced (picklable: no matplotlib objects)."""

    index: int
    files: tuple[str, ...]
    checks: tuple[Check, ...]
    notes: str
    suspicious: tuple[str, ...]
    untrusted: int
    points: int
    seconds: float
    pid: int


def _render(index: int, quick: bool, name: str, out: Path,
            curves: Mapping[str, Curve]) -> _Done:
    t0 = time.perf_counter()
    r = _recipes_by_name(quick)[name]
    rendered: Rendered = r.render(curves)
    files: list[str] = []
    if rendered.figure is not None:
        files += [p.name for p in style.save(rendered.figure, out, r.name)]
    data = out / "data"
    for k, table in enumerate(rendered.tables):
        stem = r.name if len(rendered.tables) == 1 else f"{r.name}_{k}"
        files.append("data/" + table.write_csv(data / f"{stem}.csv").name)
    suspicious = []
    untrusted = 0
    for c in curves.values():
        untrusted += int(np.sum(~c.trusted))
        for i in np.flatnonzero(c.suspicious):
            s = c.series
            suspicious.append(
                f"alpha={s.alpha!r}, beta={s.beta!r}, amplitude={s.amplitude!r}, "
                + (f"zeta={s.zeta!r}, eta_c={s.eta_c!r}, " if s.zeta or s.eta_c else "")
                + (f"a_x={s.a_x!r}, phase_x={s.phase_x!r} ({s.inplane_on}), " if s.a_x
                   else "")
                + (f"a_y={s.a_y!r}, phase_y={s.phase_y!r}, " if s.a_y else "")
                + (f"profile_exponent={s.profile_exponent!r}, "
                   if s.profile_exponent != math.inf else "")
                + (f"static_ratio={s.static_ratio!r}, " if s.static_ratio != 1.0 else "")
                + (f"rs_a={s.rs_a!r}, rs_b={s.rs_b!r}, rs_d_c={s.rs_d_c!r}, "
                   f"rs_v_ref={s.rs_v_ref!r}, rs_alpha_ld={s.rs_alpha_ld!r}, "
                   f"rs_law={s.rs_law!r}, " if s.rs_a else "")
                + f"v_inertial={float(s.v_inertial[i])!r}: mu_ratio={float(c.mu_ratio[i]):.6g}, "
                f"status {STATUS_BY_CODE[int(c.status[i])].value}, error "
                f"{float(c.error[i]):.3g}")
    return _Done(index, tuple(files), rendered.checks, rendered.notes, tuple(suspicious),
                 untrusted, sum(s.size for s in r.series), time.perf_counter() - t0,
                 os.getpid())


# --------------------------------------------------------------------------- scheduler
@dataclass
class _Batch:
    """The points of one recipe, split into strided chunks (expensive regions spread out)."""

    index: int
    columns: list[np.ndarray]  # the POINT_ARGS, then the CHOICE_ARGS arrays (point_columns)
    chunks: list[np.ndarray]
    results: dict[str, np.ndarray] = field(default_factory=dict)
    remaining: int = 0
    settings: SolverSettings | None = None  # the recipe's

    @classmethod
    def of(cls, index: int, recipe: Recipe, chunk: int) -> _Batch:
        columns = point_columns(recipe.series)
        n = columns[0].size
        k = max(1, math.ceil(n / chunk)) if n else 0
        chunks = [np.arange(j, n, k) for j in range(k)]
        return cls(index, columns, chunks, {}, len(chunks), recipe.settings)

    @property
    def size(self) -> int:
        return int(self.columns[0].size)

    def store(self, idx: np.ndarray, part: Mapping[str, np.ndarray]) -> None:
        for key, val in part.items():
            if key not in self.results:
                self.results[key] = np.empty(self.size, dtype=val.dtype)
            self.results[key][idx] = val
        self.remaining -= 1

    def runner(self, *_args, **_kwargs) -> dict[str, np.ndarray]:
        """A ``Runner`` that returns the stored results (for :func:`figures.series.solve`)."""
        return self.results


def _curves(recipe: Recipe, batch: _Batch) -> dict[str, Curve]:
    if not recipe.series:
        return {}
    return solve(recipe.series, runner=batch.runner)


class _Schedule:
    """The next task: rendering a recipe whose data are complete, else a chunk of points.

    Called by :func:`vibrofriction.parallel.run_tasks` (or :func:`_run_here`) each
    time a slot is free; the largest recipes' chunks go first.
    """

    def __init__(self, todo: Sequence[Recipe], batches: list[_Batch], quick: bool, out: Path,
                 pbar, fbar) -> None:
        self.todo, self.batches, self.quick, self.out = todo, batches, quick, out
        self.pbar, self.fbar = pbar, fbar
        self.compute: deque[tuple[_Batch, np.ndarray]] = deque(
            (b, idx) for b in sorted(batches, key=lambda b: -b.size)
            for idx in b.chunks)
        self.renders: deque[int] = deque(b.index for b in batches if b.remaining == 0)
        self.done: list[_Done] = []
        self.pids: set[int] = set()

    def __call__(self) -> Task | None:
        if self.renders:
            i = self.renders.popleft()
            args = (i, self.quick, self.todo[i].name, self.out,
                    _curves(self.todo[i], self.batches[i]))
            return _render, args, self._rendered
        if self.compute:
            b, idx = self.compute.popleft()
            args = (b.settings, *(c[idx] for c in b.columns))
            return _solve_chunk, args, functools.partial(self._solved, b, idx)
        return None

    def _solved(self, batch: _Batch, idx: np.ndarray,
                result: tuple[int, dict[str, np.ndarray]]) -> None:
        pid, cols = result
        self.pids.add(pid)
        batch.store(idx, cols)
        self.pbar.update(idx.size)
        if batch.remaining == 0:
            self.renders.append(batch.index)

    def _rendered(self, done: _Done) -> None:
        self.pids.add(done.pid)
        self.done.append(done)
        self.fbar.update(1)


def _run_here(schedule: _Schedule) -> None:
    """Run every task of ``schedule`` in this process (``workers=1``)."""
    while (task := schedule()) is not None:
        func, args, done = task
        done(func(*args))


@dataclass(frozen=True)
class Reproduction:
    """What :func:`reproduce` wrote and measured.

    Parameters
    ----------
    out : pathlib.Path
        The output folder.
    report : pathlib.Path
        Its ``report.md``.
    files : tuple of pathlib.Path
        Every file written (figures as PNG and PDF, their data as CSV, the report).
    checks : tuple of Check
        The comparisons of the numerics with the closed forms.
    points : int
        The number of solver points.
    seconds : float
        The wall time.
    workers : int
        The size of the process pool (1: everything ran in the calling process).
    untrusted : int
        The number of points whose result the solver does not trust.
    suspicious : tuple of str
        The recipes with suspicious points, in words.
    processes : tuple of int, optional
        The pids of the processes that solved or rendered.

    Examples
    --------
    See :func:`reproduce`.
    """

    out: Path
    report: Path
    files: tuple[Path, ...]
    checks: tuple[Check, ...]
    points: int
    seconds: float
    workers: int
    untrusted: int
    suspicious: tuple[str, ...]
    processes: tuple[int, ...] = ()


#: The kernels the solving and rendering use (:data:`vibrofriction.warmup.PARTS`).
_PARTS = ("flat", "plane", "curved", "rate_state", "histories")


def _load() -> None:
    """Each worker loads them (from the disk cache the parent's warm-up wrote) first."""
    warm_up(_PARTS, workers=1, progress=False)


def _select(todo: list[Recipe], only: Sequence[str] | None) -> list[Recipe]:
    if only is None:
        return todo
    wanted = tuple(only)
    chosen = [r for r in todo if r.name.startswith(wanted)]
    if not chosen:
        names = ", ".join(r.name for r in todo)
        raise ValueError(f"only={list(wanted)!r} matches no figure; names: {names}")
    return chosen


def reproduce(out: Path | str, *, quick: bool = False, workers: int | None = None,
              progress: bool = True, only: Sequence[str] | None = None) -> Reproduction:
    """Compute every figure, write PNG + PDF + CSV per figure and ``report.md`` into ``out``.

    Parameters
    ----------
    out : str or pathlib.Path
        The output folder (created).
    quick : bool, optional
        Reduced velocity grids and maps (for CI); the figures keep their layout.
    workers : int, optional
        Processes for solving and rendering (the package's one process pool,
        :mod:`vibrofriction.parallel`); default ``min(2, available cores)``; ``1`` runs
        everything in this process. Results do not depend on it.
    progress : bool, optional
        Show tqdm progress bars (on stderr).
    only : sequence of str, optional
        Names (or name prefixes, e.g. ``fig04``) of the recipes to run; default all.

    Returns
    -------
    Reproduction
        What was written and measured.

    Examples
    --------
    One figure, the sphere of Fig. 18 (30 points; the first call also loads the solver's
    kernels, so it is not run with the API's doctests):

    >>> import tempfile
    >>> from vibrofriction.report import reproduce
    >>> with tempfile.TemporaryDirectory() as tmp:  # doctest: +SKIP
    ...     result = reproduce(tmp, quick=True, workers=1, progress=False, only=["fig18"])
    ...     print(result.points, result.untrusted)
    ...     print(sorted(path.name for path in result.files))
    30 0
    ['deviations.csv', 'fig18_sphere_linearised.csv', 'fig18_sphere_linearised.pdf',
     'fig18_sphere_linearised.png', 'report.md']
    """
    from .parallel import available_cores, check_workers, run_tasks

    t0 = time.perf_counter()
    workers = min(2, available_cores()) if workers is None else check_workers(workers)
    todo = _select(recipes(quick), only)
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    (out / "data").mkdir(exist_ok=True)
    batches = [_Batch.of(i, r, _CHUNK) for i, r in enumerate(todo)]
    n_points = sum(b.size for b in batches)
    bar_kw = {"disable": not progress, "dynamic_ncols": True, "leave": True}
    warm_up(_PARTS, workers=workers, progress=progress)  # compiles once, on every core
    with tqdm(total=n_points, desc="solving", unit="pt", smoothing=0.1, **bar_kw) as pbar, \
            tqdm(total=len(todo), desc="figures", unit="fig", **bar_kw) as fbar:
        schedule = _Schedule(todo, batches, quick, out, pbar, fbar)
        if workers == 1:
            _run_here(schedule)
        else:  # one extra task in flight keeps every core busy
            run_tasks(schedule, workers=workers, warm_up=_load, in_flight=workers + 1)
    done = sorted(schedule.done, key=lambda d: d.index)
    seconds = time.perf_counter() - t0
    checks = tuple(c for d in done for c in d.checks)
    _write_deviations(out / "deviations.csv", checks)
    report = _write_report(out, todo, done, checks, quick=quick, seconds=seconds,
                           workers=workers, points=n_points)
    files = tuple(sorted({out / f for d in done for f in d.files}
                         | {report, out / "deviations.csv"}))
    return Reproduction(out, report, files, checks, n_points, seconds, workers,
                        sum(d.untrusted for d in done),
                        tuple(s for d in done for s in d.suspicious),
                        tuple(sorted(schedule.pids)))


# --------------------------------------------------------------------------- writing
def _write_deviations(path: Path, checks: Sequence[Check]) -> None:
    Table("Numerics vs closed forms: largest deviation of mu/mu0 (or of the named quantity)",
          ("deviation = max |numerics - closed form| over the points described in 'where'",),
          {"formula": np.array([c.formula for c in checks], dtype=object),
           "where": np.array([c.where for c in checks], dtype=object),
           "deviation": np.array([c.deviation for c in checks], dtype=float),
           "at": np.array([c.at for c in checks], dtype=object),
           "remark": np.array([c.remark for c in checks], dtype=object)}).write_csv(path)


def _md(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


def _fmt_dev(x: float) -> str:
    if math.isnan(x):
        return "n/a"
    if x == 0.0:
        return "0"
    return f"{x:.2e}" if x < 1e-3 else f"{x:.4f}"


def _write_report(out: Path, todo: Sequence[Recipe], done: Sequence[_Done],
                  checks: Sequence[Check], *, quick: bool, seconds: float, workers: int,
                  points: int) -> Path:
    lines = (_report_header(quick=quick, seconds=seconds, workers=workers, points=points)
             + _checks_section(checks) + _suspicious_section(done)
             + _figures_section(todo, done))
    path = out / "report.md"
    path.write_text("\n".join(lines) + "\n")
    return path


def _report_header(*, quick: bool, seconds: float, workers: int, points: int) -> list[str]:
    """The report's title and how it was made."""
    return [
        "# Reproduction of Mao, Popov, Starcevic & Popov, *Friction* (2017), Part II",
        "",
        f"Generated by `vibrofriction reproduce` (version {__version__}) "
        f"{'with reduced grids (--quick)' if quick else 'with full grids'}: "
        f"{points} steady states, {seconds:.1f} s wall time on {workers} worker "
        f"process(es), {os.cpu_count()} CPU(s), Python {platform.python_version()}.",
        "",
        "Every curve is computed by the solver that covers its points (the exact "
        "event-driven solver; the MDR, 2-D and rate-and-state solvers where a figure needs "
        "them: docs/solver.md) from the initial state 'steady sliding before the oscillation "
        "is switched on' (docs/model.md). Data behind "
        "each figure are in `data/` (CSV, parameters in the `#` header). Points whose "
        "steady state did not converge (or whose error estimate exceeds 1e-5) are drawn as "
        "open circles and are not joined into the curves. Corrections to the paper are "
        "derived in `docs/theory.md`; `docs/figures.md` discusses each figure.",
        "",
    ]


def _checks_section(checks: Sequence[Check]) -> list[str]:
    """The table of numerics against the closed forms."""
    lines = [
        "## Numerics vs closed forms",
        "",
        "Largest |numerics - closed form| of mu/mu0 (or of the named quantity) over the "
        "points described; also in `deviations.csv`.",
        "",
        "| closed form / claim | where measured | max deviation | at | remark |",
        "|---|---|---|---|---|",
    ]
    for c in checks:
        lines.append(f"| {_md(c.formula)} | {_md(c.where)} | {_fmt_dev(c.deviation)} | "
                     f"{_md(c.at)} | {_md(c.remark)} |")
    return lines


def _suspicious_section(done: Sequence[_Done]) -> list[str]:
    """Converged points whose error estimate is too large to trust."""
    tol = SolverSettings().tol_trusted
    suspicious = [s for d in done for s in d.suspicious]
    lines = ["", "## Converged results whose error estimate is too large to trust", ""]
    if not suspicious:
        return lines + ["None: every point with a converged status has an error estimate "
                        f"within tol_trusted = {tol:g}."]
    return lines + ["These points report a converged status but an error estimate above "
                    f"tol_trusted = {tol:g} (not trusted); they are excluded from the curves:",
                    ""] + [f"* {s}" for s in suspicious]


def _figures_section(todo: Sequence[Recipe], done: Sequence[_Done]) -> list[str]:
    """Each figure with its caption, notes and files."""
    lines = ["", "## Figures", ""]
    for d in done:
        r = todo[d.index]
        if not any(f.endswith(".png") for f in d.files):
            continue
        lines += [f"### {r.title}", "", f"![{r.title}]({r.name}.png)", "",
                  r.caption, ""]
        if d.notes:
            lines += [f"*Notes:* {d.notes}", ""]
        lines += ["Files: " + ", ".join(f"[{f}]({f})" for f in d.files)
                  + f" ({d.points} points; rendered in {d.seconds:.1f} s).", ""]
    if any(todo[d.index].name.startswith("fig08") for d in done):
        lines += ["### Figs. 8 and 9: the experiment", "",
                  "The measured friction coefficients of Fig. 9 (and the photographs of Fig. 8) "
                  "are not contained in the paper's text, so they cannot be reproduced here. "
                  "The figure `fig08_09_prediction` above shows the model's prediction for "
                  "the four amplitudes of Fig. 9 under the stated assumptions, clearly "
                  "labelled as a prediction.", ""]
    return lines
