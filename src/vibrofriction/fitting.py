r"""Fitting measured friction curves with the model (docs/bench.md).

``fit(data, guess, free=[...])`` adjusts the named fields of a :class:`Physical` guess
so that ``mu0 * mu_ratio`` (eq. 25, exact solver) matches the measured ``cof`` at each
row's ``(v0, du_z, omega)``.  The other fields stay at the guess's values; the
experimenter's knowns can be imposed as constraints:

* ``natural_frequency``: ``k_x = m (2 pi f_n)^2`` with ``f_n`` of the guess (an impact
  test measures it), so ``mass`` and ``k_x`` move together;
* ``normal_load``: ``k_zc u_z0 = F_N0`` of the guess (the applied load);
* ``quality_factor``: the pin's damping ratio ``zeta`` of the guess is kept, so
  ``c_x = 2 zeta sqrt(k_x m)`` follows the pin.

The objective has kinks where the stick-slip pattern changes, so a local least-squares
fit from a poor start can stop in the wrong valley: a global stage (differential
evolution over ``ln`` of the free parameters, within a factor ``span`` of the guess,
on every other row of the table: half the cost per generation) comes first, then
Levenberg-Marquardt with lmfit on every row from its best point and from the next best
distinct members of its population (the lowest chi-square wins).  A weighted fit still
poor after the first starts (reduced chi-square above 2) runs a second global stage
with another seed.  Parameters are fitted as logarithms (all are positive and span
decades).

Uncertainties are profile-likelihood intervals, not the curvature at the minimum: the
kinks make the chi-square surface far from a parabola on the scale of the errors (the
Jacobian's errors covered the truth within two standard errors in only 87 % of seeded
synthetic fits).  For each free parameter and each side, the parameter is held and the
others refitted until the chi-square has risen by ``4 s^2`` (``s^2`` the reduced
chi-square, at least 1 when ``sigma`` is given, so that a poor fit widens its intervals):
the 95.4 % interval ``res.intervals[name]``, asymmetric in general; ``stderr`` is half
its longer side, so that ``value +- 2 stderr`` holds the whole interval (a symmetric
summary that claims no more than the interval).  Correlations come from
the covariance of the least-squares stage.  Another local minimum (from the other
starts) within the level widens the interval to reach it, and a profile that finds a
lower chi-square than the fit restarts the fit from there (and the profiles, if the
drop exceeds ``s^2/2``; a smaller one keeps the intervals, which then hold the true
ones: the new level set lies inside the old).
"""

from __future__ import annotations

import dataclasses
import json
import math
import multiprocessing
import os
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from functools import partial
from pathlib import Path
from typing import Any

import lmfit
import numpy as np
import pandas as pd
from numpy.typing import NDArray

from .measurements import read_measurements
from .params import Physical
from .solver import SolverSettings, solve_points

__all__ = ["FITTABLE", "FitResult", "fit", "predict_cof", "synthetic_measurements"]

#: The fields of :class:`Physical` that can be fitted.
FITTABLE = ("mu0", "mass", "k_x", "k_xc", "k_zc", "u_z0", "c_x", "c_xc")
#: Correlations beyond this in modulus are reported as a warning.
STRONG_CORRELATION = 0.98
#: Relative singular value below which a direction of the Jacobian counts as flat.
FLAT = 1e-4
#: The rise of the profile chi-square (in units of ``s^2``) that bounds the reported
#: intervals: 4, two standard errors of a Gaussian (95.4 %).
PROFILE_LEVEL = 4.0
#: Local least-squares starts: the global stage's best point and its next best.
STARTS = 4
#: Model evaluations per varied parameter (plus one) that a local least-squares run may
#: spend (measured: converging starts need 20-30; some crawl for thousands).
LOCAL_BUDGET = 60
#: The global stage compares the model with every other row of a table this long or
#: longer: an evaluation costs half, so it runs twice the generations for the same
#: time, and more generations find the narrow valleys more often (measured on the
#: 5-parameter data sets of benchmarks/bench_fit.py, 4 noise seeds x 2 seeds of the
#: global stage: 30 generations on every row ended in a wrong valley in 7 runs of 7,
#: 60 generations on every other row in 1 of 8).
COARSE_ROWS = 20
#: A profile that meets a chi-square lower than the fit's by more than this (in units of
#: ``s^2``) makes the fit start again from there and the profiles be run again; a
#: smaller drop keeps the intervals found, which hold the new level set (it lies within
#: the old one), re-centred on the new best fit.
RESTART_PROFILES = 0.5
#: A weighted fit with a reduced chi-square above this runs a second global stage (with
#: another seed) and, if still above, says it may sit in a local minimum.
POOR_FIT = 2.0


def predict_cof(system: Physical, v0: NDArray, du_z: NDArray, omega: NDArray,
                settings: SolverSettings | None = None) -> NDArray[np.float64]:
    """``mu0 * mu_ratio`` of ``system`` at each ``(v0, du_z, omega)`` (eq. 25).

    Where the solver has no trusted value the midpoint of its window means stands in
    (nan where it has none at all).
    """
    alpha, beta, a, zeta, eta = system.groups(du_z, omega)
    V = system.v0_to_inertial(v0, omega)
    out = solve_points(alpha, beta, a, V, zeta, eta, settings=settings)
    mu = np.where(np.isfinite(out["mu_ratio"]), out["mu_ratio"],
                  0.5 * (out["window_min"] + out["window_max"]))
    return system.mu0 * mu


def synthetic_measurements(system: Physical, du_z, v0, sigma: float,
                           rng: np.random.Generator) -> pd.DataFrame:
    """A measurement table made by the model, for a fit whose truth is known: at each
    amplitude of ``du_z`` (m) and each velocity of ``v0`` (m/s), at the system's
    ``omega``, :func:`predict_cof` plus Gaussian noise of standard deviation ``sigma``
    (drawn per amplitude, in order).  SI columns ``v0, cof, du_z, omega, sigma``, the
    format of :func:`~vibrofriction.measurements.read_measurements`."""
    v0 = np.asarray(v0, dtype=float)
    n = v0.size
    rows = []
    for du in np.atleast_1d(np.asarray(du_z, dtype=float)):
        cof = predict_cof(system, v0, np.full(n, du), np.full(n, system.omega))
        rows.append(pd.DataFrame({"v0": v0, "cof": cof + rng.normal(0.0, sigma, n),
                                  "du_z": du, "omega": system.omega, "sigma": sigma}))
    return pd.concat(rows, ignore_index=True)


@dataclass
class _Problem:
    """The free parameters in ``ln`` and how they map onto a :class:`Physical`."""

    guess: Physical
    free: tuple[str, ...]
    natural_frequency: bool
    normal_load: bool
    quality_factor: bool
    data: pd.DataFrame
    settings: SolverSettings | None = None

    def system(self, ln: NDArray[np.float64]) -> Physical:
        values = dataclasses.asdict(self.guess)
        values.update({n: math.exp(x) for n, x in zip(self.free, ln, strict=True)})
        g = self.guess
        if self.natural_frequency:
            wn2 = g.k_x / g.mass
            if "mass" in self.free:
                values["k_x"] = values["mass"] * wn2
            elif "k_x" in self.free:
                values["mass"] = values["k_x"] / wn2
        if self.normal_load:
            if "k_zc" in self.free:
                values["u_z0"] = g.F_N0 / values["k_zc"]
            elif "u_z0" in self.free:
                values["k_zc"] = g.F_N0 / values["u_z0"]
        if self.quality_factor and "c_x" not in self.free:
            values["c_x"] = 2.0 * g.zeta * math.sqrt(values["k_x"] * values["mass"])
        return Physical(**values)

    def residual(self, ln: NDArray[np.float64]) -> NDArray[np.float64]:
        d = self.data
        try:
            model = predict_cof(self.system(ln), d["v0"].to_numpy(), d["du_z"].to_numpy(),
                                d["omega"].to_numpy(), self.settings)
        except ValueError:  # outside the model's domain (e.g. beta <= alpha)
            return np.full(len(d), 1e3)
        r = model - d["cof"].to_numpy()
        sigma = d["sigma"].to_numpy()
        if np.all(np.isfinite(sigma)):
            r = r / sigma
        return np.nan_to_num(r, nan=1e3)

    def cost(self, ln: NDArray[np.float64]) -> float:
        r = self.residual(ln)
        return float(r @ r)

    def coarse(self) -> _Problem:
        """The same problem on every other row of a table of at least
        :data:`COARSE_ROWS` rows (the global stage's cheaper chi-square)."""
        if len(self.data) < COARSE_ROWS:
            return self
        return dataclasses.replace(self, data=self.data.iloc[::2].reset_index(drop=True))

    @property
    def weighted(self) -> bool:
        """Residuals divided by the measured ``sigma`` (given on every row)."""
        return bool(np.all(np.isfinite(self.data["sigma"].to_numpy())))


@dataclass
class FitResult:
    """The best fit, its uncertainties and what the data cannot tell.

    ``params``: lmfit ``Parameters`` of the free fields (``.value``, ``.stderr``,
    ``.correl``; a field tied to a free one by a constraint, e.g. ``k_x`` to ``mass``, is
    listed with the same relative error); ``intervals``: the 95.4 % profile-likelihood
    interval of each (``stderr`` is half its longer side; module docstring);
    ``system``: the best-fit :class:`Physical`;
    ``warnings``: one sentence per parameter the data do not identify; ``chisqr``,
    ``redchi``, ``nfev`` (model evaluations, global stage included) and ``seconds``.
    """

    params: lmfit.Parameters
    system: Physical
    data: pd.DataFrame
    free: tuple[str, ...]
    constraints: dict[str, bool]
    warnings: list[str]
    chisqr: float
    redchi: float
    nfev: int
    seconds: float
    weighted: bool
    guess: Physical | None = None
    intervals: dict[str, tuple[float, float]] = field(default_factory=dict)
    extra: dict[str, Any] = field(default_factory=dict)

    def predict(self, v0: NDArray, du_z: NDArray, omega: NDArray) -> NDArray[np.float64]:
        """The fitted model's COF at other points."""
        return predict_cof(self.system, v0, du_z, omega)

    def report(self) -> str:
        """The fit in words and numbers."""
        lines = [f"fit of {len(self.data)} points, {len(self.free)} free parameters "
                 f"({'weighted by sigma' if self.weighted else 'unweighted'}): "
                 f"chi-square {self.chisqr:.4g}, reduced {self.redchi:.4g}, "
                 f"{self.nfev} model evaluations, {self.seconds:.1f} s",
                 "constraints: " + (", ".join(k for k, v in self.constraints.items() if v)
                                    or "none")]
        if self.extra.get("stages"):
            lines.append("time: " + ", ".join(
                f"{r['stage']} {r['seconds']:.1f} s ({r['evaluations']} evaluations)"
                for r in self.extra["stages"]))
        for name in self.params:
            p = self.params[name]
            err = f"+- {p.stderr:.3g} ({100 * p.stderr / abs(p.value):.2g} %)" \
                if p.stderr is not None and np.isfinite(p.stderr) else "(not bounded)"
            lo, hi = self.intervals.get(name, (math.nan, math.nan))
            band = f", 95 % interval [{lo:.4g}, {hi:.4g}]" if not math.isnan(lo) else ""
            lines.append(f"  {name:6s} = {p.value:.6g} {err}{band}")
        pairs = [(a, b, self.params[a].correl[b]) for i, a in enumerate(self.free)
                 for b in self.free[i + 1:] if self.params[a].correl
                 and b in self.params[a].correl]
        if pairs:
            lines.append("correlations: " + ", ".join(f"{a}/{b} {r:+.3f}" for a, b, r in pairs))
        lines += ["warnings:" if self.warnings else "no warnings"] + [
            f"  - {w}" for w in self.warnings]
        lines.append(f"best-fit system: {self.system}")
        return "\n".join(lines)

    def to_json(self, path: str | Path) -> Path:
        """Save (the data, the system, the parameters with errors and correlations)."""
        path = Path(path)
        doc = {
            "system": dataclasses.asdict(self.system),
            "guess": dataclasses.asdict(self.guess) if self.guess else None,
            "free": list(self.free), "constraints": self.constraints,
            "params": {n: {"value": self.params[n].value, "stderr": self.params[n].stderr,
                           "correl": self.params[n].correl} for n in self.params},
            "warnings": self.warnings, "chisqr": self.chisqr, "redchi": self.redchi,
            "nfev": self.nfev, "seconds": self.seconds, "weighted": self.weighted,
            "intervals": {n: list(v) for n, v in self.intervals.items()},
            "data": self.data.to_dict(orient="list"),
        }
        path.write_text(json.dumps(doc, indent=1, default=_json_default))
        return path

    @classmethod
    def from_json(cls, path: str | Path) -> FitResult:
        doc = json.loads(Path(path).read_text())
        params = lmfit.Parameters()
        for n, p in doc["params"].items():
            params.add(n, value=p["value"])
            params[n].stderr = p["stderr"]
            params[n].correl = p["correl"]
        return cls(params=params, system=Physical(**doc["system"]),
                   data=pd.DataFrame(doc["data"]), free=tuple(doc["free"]),
                   constraints=doc["constraints"], warnings=doc["warnings"],
                   chisqr=doc["chisqr"], redchi=doc["redchi"], nfev=doc["nfev"],
                   seconds=doc["seconds"], weighted=doc["weighted"],
                   guess=Physical(**doc["guess"]) if doc["guess"] else None,
                   intervals={n: (_from_json_float(lo), _from_json_float(hi))
                              for n, (lo, hi) in doc.get("intervals", {}).items()})

    def plot(self):
        """Data with error bars and the fitted curves per (amplitude, frequency), and the
        residuals (a matplotlib Figure)."""
        from matplotlib.figure import Figure

        fig = Figure(figsize=(6.0, 5.0), layout="constrained")
        ax, axr = fig.subplots(2, 1, sharex=True, height_ratios=(3, 1))
        d = self.data
        groups = d.groupby(["du_z", "omega"], sort=True)
        for k, ((du, om), g) in enumerate(groups):
            color = f"C{k % 10}"
            v = np.geomspace(max(g["v0"].min(), 1e-9) / 1.5, g["v0"].max() * 1.5, 120)
            ax.plot(v, self.predict(v, np.full(v.size, du), np.full(v.size, om)), color=color,
                    lw=1.2, label=f"du_z = {du * 1e6:.3g} um, f = {om / (2 * math.pi):.4g} Hz")
            yerr = g["sigma"] if np.all(np.isfinite(g["sigma"])) else None
            ax.errorbar(g["v0"], g["cof"], yerr=yerr, fmt="o", ms=3, color=color, capsize=2)
            res = g["cof"] - self.predict(g["v0"].to_numpy(), g["du_z"].to_numpy(),
                                          g["omega"].to_numpy())
            axr.errorbar(g["v0"], res, yerr=yerr, fmt="o", ms=3, color=color, capsize=2)
        axr.axhline(0.0, color="0.5", lw=0.6)
        ax.set_xscale("log")
        ax.set_ylabel("COF")
        axr.set_ylabel("residual")
        axr.set_xlabel("sliding velocity v0 (m/s)")
        ax.legend(fontsize=7)
        ax.set_title(f"fit: {', '.join(self.free)} free; reduced chi-square {self.redchi:.3g}",
                     fontsize=8)
        return fig


def _tick(bar) -> bool:
    """Advance a progress bar; False, so that differential evolution goes on (a callback
    returning True stops it, and tqdm's ``update`` returns True when it redraws)."""
    bar.update(1)
    return False


def _from_json_float(x) -> float:
    """An interval end as saved: ``None`` stands for an unbounded side."""
    return math.inf if x is None else float(x)


def _json_default(x):
    if isinstance(x, float | np.floating):
        return None if not np.isfinite(x) else float(x)
    if isinstance(x, np.integer):
        return int(x)
    raise TypeError(f"not serialisable: {type(x).__name__}")


def _bounds(problem: _Problem, span: float) -> list[tuple[float, float]]:
    out = []
    for n in problem.free:
        x = math.log(getattr(problem.guess, n)) if getattr(problem.guess, n) > 0 else None
        if x is None:
            raise ValueError(f"{n} of the guess must be > 0 to be fitted, got "
                             f"{getattr(problem.guess, n)!r}")
        out.append((x - math.log(span), x + math.log(span)))
    return out


def fit(data: pd.DataFrame | str | Path, guess: Physical, free: list[str] | tuple[str, ...] = (
        "mu0", "mass", "k_x", "k_xc", "u_z0"), *, natural_frequency: bool = True,
        normal_load: bool = True, quality_factor: bool = True, span: float = 10.0,
        global_stage: bool = True, maxiter: int = 60, popsize: int = 12, seed: int = 0,
        workers: int = 1, progress: bool = True,
        settings: SolverSettings | None = None) -> FitResult:
    """Fit the fields ``free`` of ``guess`` to a measured table (module docstring).

    ``data``: a table of :func:`~vibrofriction.measurements.read_measurements` (or its
    path).  ``span``: each free parameter is searched within a factor ``span`` of the
    guess (``mu0`` as well).  ``maxiter``, ``popsize``, ``seed``: the global stage
    (:func:`scipy.optimize.differential_evolution`, on every other row of a table of
    20 rows or more).  ``workers``: processes for the global stage, the local starts
    and the profiles (``-1``: every core).  ``res.extra["stages"]`` says where the time
    went.
    """
    t0 = time.perf_counter()
    data = read_measurements(data)
    free, tied = _free_and_tied(tuple(free), natural_frequency, normal_load, len(data))
    problem = _Problem(guess, free, natural_frequency, normal_load, quality_factor, data,
                       settings)
    bounds = _bounds(problem, span)
    x0 = np.array([math.log(getattr(guess, n)) for n in free])
    workers = workers if workers >= 1 else os.cpu_count() or 1
    stages = _Stages()
    with _mapper(workers) as map_:
        if global_stage:
            out, minima = _search(problem, bounds, x0, map_ if workers != 1 else 1, map_,
                                  stages, maxiter, popsize, seed, progress, workers)
        else:
            with stages.timed("local") as row:
                out, minima, row["evaluations"] = _local_fit(problem, [x0], bounds, map_)
        out, minima, dists, lower = _uncertainties(problem, out, minima, bounds, map_,
                                                   stages, progress)
    ln = _ln(out, free)
    system = problem.system(ln)
    result_params, intervals = _physical_params(out, free, system, tied, dists)
    warnings = _identifiability(out, problem, ln, bounds, result_params)
    warnings += _profile_warnings(free, dists, tied, lower)
    return FitResult(params=result_params, system=system, data=data, free=free,
                     constraints={"natural_frequency": natural_frequency,
                                  "normal_load": normal_load, "quality_factor": quality_factor},
                     warnings=warnings, chisqr=float(out.chisqr), redchi=float(out.redchi),
                     nfev=stages.nfev, seconds=time.perf_counter() - t0,
                     weighted=problem.weighted, guess=guess, intervals=intervals,
                     extra={"local_minima": [float(m[0]) for m in minima],
                            "stages": stages.rows})


def _free_and_tied(free: tuple[str, ...], natural_frequency: bool, normal_load: bool,
                   points: int) -> tuple[tuple[str, ...], dict[str, tuple[str, float]]]:
    """The varied parameters, and those that follow one of them by a constraint (``name:
    (source, +-1)``, ``ln name = +-ln source + const``); ``free`` validated."""
    unknown = [n for n in free if n not in FITTABLE]
    if unknown or not free:
        raise ValueError(f"free must name fields of Physical among {list(FITTABLE)}, "
                         f"got {list(free)}")
    if len(set(free)) != len(free):
        raise ValueError(f"free names a parameter twice: {list(free)}")
    tied: dict[str, tuple[str, float]] = {}
    if natural_frequency and "mass" in free and "k_x" in free:
        free = tuple(n for n in free if n != "k_x")  # k_x follows the mass
        tied["k_x"] = ("mass", 1.0)
    if normal_load and "k_zc" in free and "u_z0" in free:
        free = tuple(n for n in free if n != "u_z0")  # u_z0 follows k_zc
        tied["u_z0"] = ("k_zc", -1.0)
    if len(free) > points:
        raise ValueError(f"{len(free)} free parameters but only {points} data points")
    return free, tied


@dataclass
class _Stages:
    """Where the fit spent its time: a row per stage (name, seconds, model evaluations)."""

    rows: list[dict[str, Any]] = field(default_factory=list)

    @contextmanager
    def timed(self, name: str) -> Iterator[dict[str, Any]]:
        row = {"stage": name, "seconds": 0.0, "evaluations": 0}
        self.rows.append(row)
        t = time.perf_counter()
        yield row
        row["seconds"] = time.perf_counter() - t

    @property
    def nfev(self) -> int:
        return sum(r["evaluations"] for r in self.rows)


def _search(problem: _Problem, bounds, x0: NDArray, de_workers, map_, stages: _Stages,
            maxiter: int, popsize: int, seed: int, progress: bool, first: int):
    """The global stage, then least squares from its best distinct points, ``first`` of
    them before the others.  A first global stage that ends poor (reduced chi-square
    above :data:`POOR_FIT`), or whose first starts do, is followed by a second one
    (another seed) before its remaining starts are tried: a wrong valley is left
    rather than explored.  The best fit and the local minima reached (chi-square,
    point)."""
    out, minima, deferred = None, [], []

    def polish(batch):
        nonlocal out, minima
        with stages.timed("local") as row:
            found, more, row["evaluations"] = _local_fit(problem, batch, bounds, map_)
        minima = sorted(minima + more, key=lambda r: r[0])
        if out is None or found.chisqr < out.chisqr:
            out = found

    coarse = problem.coarse()
    for attempt in range(2):
        last = attempt == 1
        with stages.timed("global") as row:
            de = _global_stage(coarse, bounds, x0, maxiter, popsize, seed + attempt,
                               de_workers, progress)
            row["evaluations"] = int(de.nfev)
        starts = _distinct_starts(de, x0, STARTS)
        if not last and _poor(coarse, float(de.fun)):
            deferred = starts
            continue
        polish(starts[:first])
        if not last and _poor(problem, out.chisqr):
            deferred = starts[first:]
            continue
        if starts[first:]:
            polish(starts[first:])
        if not _poor(problem, out.chisqr):
            return out, minima
    if deferred:
        polish(deferred)
    return out, minima


def _uncertainties(problem: _Problem, out, minima, bounds, map_, stages: _Stages,
                   progress: bool):
    """The profile intervals about ``out`` (module docstring); a lower chi-square met on
    the way is fitted from.  The fit, the minima, the distances of the interval ends and
    the lower point if the profiles met one again."""
    free = problem.free
    with stages.timed("profiles") as row:
        dists, lower, row["evaluations"] = _profiles(problem, out, minima, bounds, map_,
                                                     progress)
    if lower is None:
        return out, minima, dists, None
    old, old_best = out, _ln(out, free)
    with stages.timed("local") as row:
        out, more, row["evaluations"] = _local_fit(problem, [lower[1]], bounds, map_)
    minima = sorted(minima + more, key=lambda r: r[0])
    if old.chisqr - out.chisqr <= RESTART_PROFILES * _s2(problem, out):
        # the old level set holds the new one: its intervals, re-centred
        return out, minima, _recentre(dists, free, old_best, _ln(out, free)), None
    with stages.timed("profiles") as row:
        dists, lower, row["evaluations"] = _profiles(problem, out, minima, bounds, map_,
                                                     progress)
    return out, minima, dists, lower


def _global_stage(problem: _Problem, bounds, x0: NDArray, maxiter: int, popsize: int,
                  seed: int, workers, progress: bool):
    """Differential evolution over ``ln`` of the free parameters, from a Sobol sample
    that includes the guess."""
    from scipy.optimize import differential_evolution
    from tqdm.auto import tqdm

    with tqdm(total=maxiter, desc="fit: global stage", unit="gen",
              disable=not progress) as bar:
        return differential_evolution(
            problem.cost, bounds, maxiter=maxiter, popsize=popsize, seed=seed,
            polish=False, init="sobol", x0=x0, tol=0.0, workers=workers,
            updating="deferred" if workers != 1 else "immediate",
            callback=lambda *a, **k: _tick(bar))


def _poor(problem: _Problem, chisqr: float) -> bool:
    """A weighted fit whose reduced chi-square (``chisqr`` over the degrees of freedom)
    exceeds :data:`POOR_FIT`."""
    dof = max(len(problem.data) - len(problem.free), 1)
    return problem.weighted and chisqr / dof > POOR_FIT


@contextmanager
def _mapper(workers: int) -> Iterator[Callable]:
    """A map over ``workers`` processes (the built-in ``map`` for one)."""
    if workers == 1:
        yield map
        return
    with multiprocessing.Pool(workers) as pool:
        # one task at a time: model evaluations vary in cost by 10x (stiff contacts)
        yield partial(pool.map, chunksize=1)


def _distinct_starts(de, x0: NDArray, count: int) -> list[NDArray]:
    """The global stage's best point, then its next best distinct population members."""
    starts = [np.asarray(de.x, dtype=float)]
    for i in np.argsort(de.population_energies):
        x = np.asarray(de.population[i], dtype=float)
        if len(starts) == count:
            break
        if all(np.max(np.abs(x - y)) > 1e-3 for y in starts):
            starts.append(x)
    return starts


def _ln(out, free: tuple[str, ...]) -> NDArray[np.float64]:
    return np.array([out.params[n].value for n in free])


def _least_squares(problem: _Problem, x0: NDArray, bounds, hold: int | None = None):
    """Levenberg-Marquardt (lmfit) over ``ln`` of the free parameters from ``x0``;
    ``hold``: the index of a parameter kept at its value in ``x0`` (a profile)."""
    params = lmfit.Parameters()
    for i, (n, x, (lo, hi)) in enumerate(zip(problem.free, x0, bounds, strict=True)):
        params.add(n, value=float(np.clip(x, lo, hi)), min=lo, max=hi, vary=i != hold)

    def residual(p):
        return problem.residual(np.array([p[n].value for n in problem.free]))

    loose = {"ftol": 1e-6, "xtol": 1e-6} if hold is not None else {}  # chi^2 to ~1e-4
    nvary = len(problem.free) - (hold is not None)
    # a start that crawls along a kinked valley for thousands of evaluations does not win:
    # the budget is LOCAL_BUDGET evaluations per varied parameter
    return lmfit.minimize(residual, params, method="leastsq",
                          scale_covar=not problem.weighted, epsfcn=1e-8,
                          max_nfev=LOCAL_BUDGET * (nvary + 1), **loose)


@dataclass
class _Fit:
    """What the fit keeps of an lmfit run (picklable, so that a worker can send it)."""

    params: lmfit.Parameters
    chisqr: float
    redchi: float
    covar: NDArray | None
    nfev: int

    @classmethod
    def of(cls, out) -> _Fit:
        covar = getattr(out, "covar", None)
        return cls(out.params, float(out.chisqr), float(out.redchi),
                   None if covar is None else np.array(covar), int(out.nfev))


def _polish(task) -> _Fit:
    problem, x0, bounds = task
    return _Fit.of(_least_squares(problem, x0, bounds))


def _local_fit(problem: _Problem, starts: list[NDArray], bounds, map_):
    """Least squares from every start (in parallel): the lowest chi-square, the
    chi-squares and points reached from each start, and the count of model evaluations."""
    found = list(map_(_polish, [(problem, x, bounds) for x in starts]))
    minima = sorted(((r.chisqr, _ln(r, problem.free)) for r in found), key=lambda r: r[0])
    return min(found, key=lambda r: r.chisqr), minima, sum(r.nfev for r in found)


def _profiles(problem: _Problem, out, minima, bounds, map_, progress: bool):
    """The profile-likelihood distances ``(below, above)`` in ``ln`` of each free
    parameter from the best fit (module docstring), in parallel over parameters and
    sides, widened to reach the other local ``minima`` within the level; and the point
    of lowest chi-square a profile met, if lower than the fit's."""
    from tqdm.auto import tqdm

    best = _ln(out, problem.free)
    chi = float(out.chisqr)
    level = PROFILE_LEVEL * _s2(problem, out)
    covar = out.covar
    tasks = []
    for j, n in enumerate(problem.free):
        se = out.params[n].stderr
        step = 2.2 * se if se is not None and np.isfinite(se) and se > 0 else 0.05
        slope = _conditional_slope(covar, j, len(best))
        tasks += [(problem, best, bounds, j, side, step, slope, level, chi)
                  for side in (-1.0, 1.0)]
    with tqdm(total=len(tasks), desc="fit: profile intervals", disable=not progress) as bar:
        found = []
        for r in map_(_profile_side, tasks):
            found.append(r)
            bar.update(1)
    dists = {n: (found[2 * j][0], found[2 * j + 1][0]) for j, n in enumerate(problem.free)}
    for chi_k, x in minima:  # another valley within the level widens the interval to it
        if chi_k - chi <= level:
            dists = _reach(dists, problem.free, best, x)
    lower = min((r[1] for r in found if r[1] is not None), key=lambda r: r[0], default=None)
    return dists, lower, sum(r[2] for r in found)


def _recentre(dists, free: tuple[str, ...], old: NDArray, new: NDArray):
    """Distances from ``old`` as distances from ``new``: the same intervals."""
    return {n: (max(dists[n][0] + new[j] - old[j], 0.0), max(dists[n][1] + old[j] - new[j], 0.0))
            for j, n in enumerate(free)}


def _s2(problem: _Problem, out) -> float:
    """The scale ``s^2`` of the profile level: the reduced chi-square, at least 1 when
    the residuals are weighted by the measured ``sigma``."""
    return max(float(out.redchi), 1.0) if problem.weighted else float(out.redchi)


def _reach(dists, free: tuple[str, ...], best: NDArray, x: NDArray):
    """The distances ``dists`` from ``best`` widened so that each interval holds ``x``."""
    out = {}
    for j, n in enumerate(free):
        below, above = dists[n]
        out[n] = (max(below, best[j] - x[j]), max(above, x[j] - best[j]))
    return out


def _conditional_slope(covar, j: int, size: int) -> NDArray[np.float64]:
    """How the others move with parameter ``j`` along the valley, to first order: column
    ``j`` of the covariance over its diagonal entry (zeros without a covariance).  Only a
    starting point for the profile's refits."""
    if covar is None or np.shape(covar) != (size, size) or not covar[j, j] > 0:
        return np.zeros(size)
    slope = np.asarray(covar[:, j], dtype=float) / covar[j, j]
    return np.where(np.isfinite(slope), slope, 0.0)


def _profile_side(task) -> tuple[float, tuple[float, NDArray] | None, int]:
    """How far parameter ``j`` can move on ``side`` (in ``ln``) before the profile
    chi-square (the others refitted) has risen by ``target``: doubling steps to a
    bracket, then Brent's method; ``inf`` if it never does within the search range.
    Each refit starts from the previous one moved along ``slope`` (the valley's
    direction at the best fit); a distance already refitted is not refitted again."""
    from scipy.optimize import brentq

    problem, best, bounds, j, side, step, slope, target, chi_best = task
    limit = bounds[j][1] - best[j] if side > 0 else best[j] - bounds[j][0]
    state = {"x": best.copy(), "d": 0.0, "nfev": 0, "lower": None}
    rises = {0.0: 0.0}

    def rise(d: float) -> float:
        if d in rises:
            return rises[d]
        x = state["x"] + side * (d - state["d"]) * slope
        x[j] = best[j] + side * d
        lo, hi = np.array(bounds).T
        x = np.clip(x, lo, hi)
        if len(best) == 1:
            chi, state["nfev"] = problem.cost(x), state["nfev"] + 1
        else:
            out = _least_squares(problem, x, bounds, hold=j)
            x, chi = _ln(out, problem.free), float(out.chisqr)
            state["nfev"] += int(out.nfev)
        state["x"], state["d"] = x, d
        if chi < chi_best - 1e-6 * max(chi_best, 1.0) and (
                state["lower"] is None or chi < state["lower"][0]):
            state["lower"] = (chi, x)
        rises[d] = chi - chi_best
        return rises[d]

    def root(d: float) -> float:  # nearly linear in d where the profile is a parabola
        r = rise(d)
        return math.copysign(math.sqrt(abs(r)), r) - math.sqrt(target)

    inner, d = 0.0, min(step, limit)
    while root(d) <= 0.0:
        if d >= limit:
            return math.inf, state["lower"], state["nfev"]
        inner, d = d, min(2.0 * d, limit)
    d = brentq(root, inner, d, xtol=1e-5, rtol=0.03, disp=False)
    return float(d), state["lower"], state["nfev"]


def _physical_params(out, free: tuple[str, ...], system: Physical,
                     tied: dict[str, tuple[str, float]],
                     dists: dict[str, tuple[float, float]]):
    """The fitted parameters in physical units with their 95.4 % profile intervals and
    ``stderr`` half the interval's longer side; the correlations of the least-squares
    covariance.  A parameter tied to a free one by a constraint, ``ln x = +-ln y +
    const``, gets the mapped interval of its source."""
    params, intervals = lmfit.Parameters(), {}
    for n in [*free, *tied]:
        source, sign = tied.get(n, (n, 1.0))
        below, above = dists[source]
        if sign < 0:
            below, above = above, below
        value = getattr(system, n)
        lo, hi = value * math.exp(-below), value * math.exp(above) if np.isfinite(above) \
            else math.inf
        params.add(n, value=value, vary=False)
        params[n].stderr = max(value - lo, hi - value) / 2.0
        params[n].correl = dict(out.params[n].correl or {}) if n in free else {}
        intervals[n] = (lo, hi)
    return params, intervals


def _profile_warnings(free: tuple[str, ...], dists, tied, lower) -> list[str]:
    """One sentence per side of an interval the data do not close within the search
    range, and one if the fit's minimum is still not the lowest found."""
    out = []
    for n in free:
        for side, d in zip(("below", "above"), dists[n], strict=True):
            if not np.isfinite(d):
                also = [t for t, (src, _) in tied.items() if src == n]
                out.append(f"{n}{' (and ' + ', '.join(also) + ')' if also else ''} is not "
                           f"bounded {side} by these data within the search range: its "
                           f"profile chi-square never rises by {PROFILE_LEVEL:g} s^2")
    if lower is not None:
        out.append("a profile met a lower chi-square than the fit twice: the fit is not at "
                   "the global minimum; widen the global stage (maxiter, popsize)")
    return out


def _identifiability(out, problem: _Problem, ln: NDArray, bounds, params) -> list[str]:
    """One sentence per parameter the data do not identify: at a bound, in a flat direction
    of the Jacobian, strongly correlated with another, or without an uncertainty."""
    warnings = []
    free = problem.free
    for n, x, (lo, hi) in zip(free, ln, bounds, strict=True):
        if min(x - lo, hi - x) < 1e-3:
            warnings.append(f"{n} is at the bound of its search range ({math.exp(lo):.3g} .. "
                            f"{math.exp(hi):.3g}): the data push it out; widen span or fix it")
    jac = _jacobian(problem, ln)
    if jac is not None and len(free) > 1:
        u, sv, vt = np.linalg.svd(jac, full_matrices=False)
        if sv[0] > 0:
            for k in np.flatnonzero(sv / sv[0] < FLAT):
                names = [free[j] for j in np.argsort(-np.abs(vt[k]))[:2]]
                warnings.append(
                    f"{' and '.join(names)} are not identified by these data: changing them "
                    f"together along a flat direction leaves the fit unchanged (relative "
                    f"singular value {sv[k] / sv[0]:.1e}); fix one or add data")
    for i, a in enumerate(free):
        for b in free[i + 1:]:
            r = (params[a].correl or {}).get(b)
            if r is not None and abs(r) > STRONG_CORRELATION:
                warnings.append(f"{a} and {b} are strongly correlated (r = {r:+.3f}): the data "
                                f"constrain a combination of them, not each")
    for n in free:
        if params[n].stderr is None:
            warnings.append(f"{n}: no uncertainty could be estimated (singular covariance)")
    if _poor(problem, out.chisqr):
        warnings.append(f"reduced chi-square {out.redchi:.3g} with the stated sigma: the "
                        "fit may sit in a local minimum (widen the global stage: maxiter, "
                        "popsize) or the model does not describe these data; the intervals "
                        "are widened by its square root")
    return warnings


def _jacobian(problem: _Problem, ln: NDArray, step: float = 1e-4) -> NDArray | None:
    """Central differences of the residuals in ``ln`` (columns: free parameters)."""
    cols = []
    for j in range(len(ln)):
        e = np.zeros_like(ln)
        e[j] = step
        cols.append((problem.residual(ln + e) - problem.residual(ln - e)) / (2 * step))
    jac = np.array(cols).T
    return jac if np.all(np.isfinite(jac)) else None
