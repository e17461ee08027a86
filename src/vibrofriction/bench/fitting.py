r"""Fitting measured friction curves with the model (docs/bench.md).

``fit(data, guess, free=[...])`` adjusts the named fields of a :class:`Physical` guess
so that ``mu0 * mu_ratio`` (eq. 25, exact solver, trusted values only) matches the
measured ``cof`` at each row's ``(v0, du_z, omega)``.  The other fields stay at the
guess's values; the experimenter's knowns can be imposed as constraints (each on by
default, each stated in the report):

* ``natural_frequency``: ``k_x = m (2 pi f_n)^2`` with ``f_n`` of the guess (an impact
  test measures it): with ``mass`` free, ``k_x`` follows it (and the other way round);
* ``normal_load``: ``k_zc u_z0 = F_N0`` of the guess (the applied load): with ``k_zc``
  free, ``u_z0`` follows it (and the other way round);
* ``quality_factor``: the pin's damping ratio ``zeta`` of the guess is kept, so
  ``c_x = 2 zeta sqrt(k_x m)`` follows the pin.

A parameter named in ``free`` is fitted: naming both members of a constraint's pair
(``mass`` and ``k_x``; ``k_zc`` and ``u_z0``; ``c_x`` under ``quality_factor``) is refused
with the keyword that releases it.

The objective has kinks where the stick-slip pattern changes, so a local least-squares
fit from a poor start can stop in the wrong valley: a global stage (differential
evolution over ``ln`` of the free parameters, within a factor ``span`` of the guess,
on every other row of the table: half the cost per generation) comes first, then
Levenberg-Marquardt with lmfit on every row from its best point and from the next best
distinct members of its population (the lowest chi-square wins).  A weighted fit still
poor after the first starts (chi-square probability below :data:`POOR_P`) runs a second
global stage with another seed.  Parameters are fitted as logarithms (all are positive
and span decades).  A row the model cannot evaluate (no trusted value of the solver)
costs more than any honest misfit of that row could (:meth:`_Problem.penalty`).

Uncertainties are profile-likelihood intervals, not the curvature at the minimum: the
kinks make the chi-square surface far from a parabola on the scale of the errors.  For
each free parameter and each side, the parameter is held and the others refitted until
the chi-square has risen by ``4 s^2`` (``s^2`` the reduced chi-square, at least 1 when
``sigma`` is given): the 95.4 % interval ``res.intervals[name]``, asymmetric in general;
``stderr`` is half its longer side, so that ``value +- 2 stderr`` holds the whole
interval.  A side the profile never closes within the search range is unbounded
(``-inf`` or ``inf``).  Correlations come from the covariance of the least-squares
stage.  Another local minimum (from the other starts) within the level widens the
interval to reach it, and a profile that finds a lower chi-square than the fit restarts
the fit from there (and the profiles, if the drop exceeds ``s^2/2``; a smaller one keeps
the intervals, which then hold the true ones: the new level set lies inside the old).

A weighted fit is judged by the probability of its chi-square (``res.p_value``, with
``points - free`` degrees of freedom): below :data:`POOR_P`, or when a profile met a lower
chi-square twice, the fit is not a description of the data within ``sigma`` (a wrong
valley, a wrong model, a wrong constraint or an understated ``sigma``: the fit cannot
tell which), ``res.quality`` says so, the report says so first, and the intervals are
the whole search range (the profile intervals, scaled by ``s^2``, are kept in
``res.extra["profile_intervals"]``).  An unweighted fit cannot be judged.
"""

from __future__ import annotations

import dataclasses
import json
import math
import time
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import lmfit
import numpy as np
import pandas as pd
from numpy.typing import NDArray

from ..parallel import available_cores, mapper
from ..params import Physical
from ..solver import SolverSettings, solve_points
from .measurements import read_measurements

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
#: spend: a start that crawls along a kinked valley does not win.
LOCAL_BUDGET = 60
#: The global stage compares the model with every other row of a table this long or
#: longer: an evaluation costs half, so it runs twice the generations for the same
#: time, and more generations find the narrow valleys more often.
COARSE_ROWS = 20
#: A profile that meets a chi-square lower than the fit's by more than this (in units of
#: ``s^2``) makes the fit start again from there and the profiles be run again; a
#: smaller drop keeps the intervals found, which hold the new level set (it lies within
#: the old one), re-centred on the new best fit.
RESTART_PROFILES = 0.5
#: A weighted fit whose chi-square has a probability below this (``points - free``
#: degrees of freedom) is poor: it runs a second global stage (with another seed) and,
#: if still poor, says so and reports the search range as its intervals.
POOR_P = 1e-3


def predict_cof(system: Physical, v0: NDArray, du_z: NDArray, omega: NDArray,
                settings: SolverSettings | None = None) -> NDArray[np.float64]:
    """``mu0 * mu_ratio`` of ``system`` at each ``(v0, du_z, omega)`` (eq. 25), ``nan``
    where the solver's value is not trusted (:meth:`SolverSettings.trusted`): the count
    of untrusted points is ``np.isnan(...).sum()``."""
    alpha, beta, a, zeta, eta = system.groups(du_z, omega)
    V = system.v0_to_inertial(v0, omega)
    out = solve_points(alpha, beta, a, V, zeta, eta, settings=settings)
    return system.mu0 * np.where(out["trusted"], out["mu_ratio"], np.nan)


def synthetic_measurements(system: Physical, du_z, v0, sigma: float,
                           rng: np.random.Generator, *,
                           settings: SolverSettings | None = None) -> pd.DataFrame:
    """A measurement table made by the model, for a fit whose truth is known: at each
    amplitude of ``du_z`` (m) and each velocity of ``v0`` (m/s), at the system's
    ``omega``, :func:`predict_cof` plus Gaussian noise of standard deviation ``sigma``
    (drawn per amplitude, in order).  SI columns ``v0, cof, du_z, omega, sigma``, the
    format of :func:`~vibrofriction.bench.read_measurements`.  A truth the solver
    does not trust at some point is refused (ValueError naming the points)."""
    v0 = np.asarray(v0, dtype=float)
    n = v0.size
    rows = []
    for du in np.atleast_1d(np.asarray(du_z, dtype=float)):
        cof = predict_cof(system, v0, np.full(n, du), np.full(n, system.omega), settings)
        if np.any(np.isnan(cof)):
            bad = v0[np.isnan(cof)]
            shown = ", ".join(f"{v:.4g}" for v in bad[:5]) + (", ..." if bad.size > 5 else "")
            raise ValueError(f"the solver has no trusted value of the truth at {bad.size} of "
                             f"{n} points at du_z = {du:g} m (v0 = {shown} m/s): no "
                             "synthetic measurement is made from an untrusted value")
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
    #: the largest ``mu0`` of the search (the bound of an honest misfit, :meth:`penalty`)
    mu0_max: float | None = None

    def values(self, ln: NDArray[np.float64]) -> dict[str, float]:
        """The fields of the system at ``ln`` of the free parameters, constraints applied."""
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
        if self.quality_factor:
            values["c_x"] = 2.0 * g.zeta * math.sqrt(values["k_x"] * values["mass"])
        return values

    def system(self, ln: NDArray[np.float64]) -> Physical:
        return Physical(**self.values(ln))

    def penalty(self) -> NDArray[np.float64]:
        """The residual of a row the model cannot evaluate: twice the largest honest one,
        ``(mu0_max + |cof|) / sigma`` (``|mu_ratio| <= 1``, eq. 25), so that a failed
        row always costs more than any misfit of it."""
        mu0_max = self.guess.mu0 if self.mu0_max is None else self.mu0_max
        return 2.0 * (mu0_max + np.abs(self.data["cof"].to_numpy())) / self._scale()

    def _scale(self) -> NDArray[np.float64] | float:
        return self.data["sigma"].to_numpy() if self.weighted else 1.0

    def evaluate(self, ln: NDArray[np.float64]) -> tuple[NDArray[np.float64], int, int]:
        """The residuals, and the counts of rows penalised (:meth:`penalty`) because the
        parameters leave the model's domain (every row) or the solver's value is not
        trusted."""
        d = self.data
        values = self.values(ln)
        if not _in_domain(values):  # e.g. exp overflow, or k_x + k_xc == k_x in floats
            return self.penalty(), len(d), 0
        model = predict_cof(Physical(**values), d["v0"].to_numpy(), d["du_z"].to_numpy(),
                            d["omega"].to_numpy(), self.settings)
        r = (model - d["cof"].to_numpy()) / self._scale()
        bad = np.isnan(r)
        return np.where(bad, self.penalty(), r), 0, int(bad.sum())

    def residual(self, ln: NDArray[np.float64]) -> NDArray[np.float64]:
        return self.evaluate(ln)[0]

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


def _in_domain(values: dict[str, float]) -> bool:
    """Whether ``values`` make a valid :class:`Physical` whose every point has
    ``beta > alpha`` (checked here, so that no error of the model is swallowed)."""
    positive = ("mass", "k_x", "k_zc", "u_z0", "omega", "mu0")
    if not all(math.isfinite(values[n]) and values[n] > 0.0 for n in positive):
        return False
    if not values["k_xc"] > 0.0:  # math.inf: a rigid contact
        return False
    if not all(math.isfinite(values[n]) and values[n] >= 0.0 for n in ("c_x", "c_xc", "du_z")):
        return False
    return values["k_x"] + values["k_xc"] > values["k_x"]


@dataclass
class FitResult:
    """The best fit, its uncertainties, its verdict and what the data cannot tell.

    ``params``: lmfit ``Parameters`` of the free fields (``.value``, ``.stderr``,
    ``.correl``; a field that follows a free one by a constraint, e.g. ``k_x`` with
    ``mass``, is listed with its mapped interval); ``intervals``: the 95.4 %
    profile-likelihood interval of each (``-inf``/``inf`` for a side the data do not
    close; the search range when the fit is poor; module docstring), ``stderr`` half its
    longer side; ``system``: the best-fit :class:`Physical`; ``quality``: ``"good"``,
    ``"poor"`` (chi-square probability ``p_value`` below :data:`POOR_P`, a profile met a
    lower chi-square twice, or rows could not be evaluated) or ``"unjudged"`` (no
    ``sigma``);
    ``penalised``: rows the model could not evaluate at the best fit, by reason;
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
    quality: str = "unjudged"
    p_value: float = math.nan
    penalised: dict[str, int] = field(default_factory=dict)

    def predict(self, v0: NDArray, du_z: NDArray, omega: NDArray) -> NDArray[np.float64]:
        """The fitted model's COF at other points (``nan`` where not trusted)."""
        return predict_cof(self.system, v0, du_z, omega)

    def report(self) -> str:
        """The fit in words and numbers: the verdict first."""
        lines = [_verdict(self),
                 f"fit of {len(self.data)} points, {len(self.free)} free parameters "
                 f"({'weighted by sigma' if self.weighted else 'unweighted'}): "
                 f"chi-square {self.chisqr:.4g}, reduced {self.redchi:.4g}, "
                 f"{self.nfev} model evaluations, {self.seconds:.1f} s"]
        lines += _constraint_lines(self)
        if self.extra.get("stages"):
            lines.append("time: " + ", ".join(
                f"{r['stage']} {r['seconds']:.1f} s ({r['evaluations']} evaluations)"
                for r in self.extra["stages"]))
        judged = self.quality != "poor"
        for name in self.params:
            lines.append(_parameter_line(name, self.params[name],
                                         self.intervals.get(name), judged))
        pairs = [(a, b, self.params[a].correl[b]) for i, a in enumerate(self.free)
                 for b in self.free[i + 1:] if self.params[a].correl
                 and b in self.params[a].correl]
        if pairs:
            lines.append("correlations: " + ", ".join(f"{a}/{b} {r:+.3f}" for a, b, r in pairs))
        lines.append("derived: " + ", ".join(
            f"{k} {v:.4g}" + (f" (guess {g:.4g})" if g is not None else "")
            for k, (v, g) in self.derived().items()))
        lines += ["warnings:" if self.warnings else "no warnings"] + [
            f"  - {w}" for w in self.warnings]
        lines.append(f"best-fit system: {self.system}")
        return "\n".join(lines)

    def derived(self) -> dict[str, tuple[float, float | None]]:
        """Quantities that move with the fitted fields, at the fit and at the guess:
        ``f_n`` (Hz), ``zeta``, ``Q``, ``c_x`` (N s/m), ``eta_c`` (eq. of docs/damping.md)
        and ``F_N0`` (N, eq. 3)."""
        def of(p: Physical) -> dict[str, float]:
            return {"f_n [Hz]": p.natural_frequency() / (2.0 * math.pi), "zeta": p.zeta,
                    "Q": p.quality_factor, "c_x [N s/m]": p.c_x, "eta_c": p.eta_c,
                    "F_N0 [N]": p.F_N0}
        guess = of(self.guess) if self.guess is not None else {}
        return {k: (v, guess.get(k)) for k, v in of(self.system).items()}

    def to_json(self, path: str | Path) -> Path:
        """Save (the data, the system, the parameters with errors and correlations, the
        verdict); an unbounded interval end is saved as ``null``."""
        path = Path(path)
        doc = {
            "system": dataclasses.asdict(self.system),
            "guess": dataclasses.asdict(self.guess) if self.guess else None,
            "free": list(self.free), "constraints": self.constraints,
            "params": {n: {"value": self.params[n].value, "stderr": self.params[n].stderr,
                           "correl": self.params[n].correl} for n in self.params},
            "warnings": self.warnings, "chisqr": self.chisqr, "redchi": self.redchi,
            "nfev": self.nfev, "seconds": self.seconds, "weighted": self.weighted,
            "quality": self.quality, "p_value": _finite_or_none(self.p_value),
            "penalised": self.penalised,
            "intervals": {n: [_finite_or_none(lo), _finite_or_none(hi)]
                          for n, (lo, hi) in self.intervals.items()},
            "derived": {k: v for k, (v, _) in self.derived().items()},
            "at_lowest_minimum": self.extra.get("at_lowest_minimum", True),
            "profile_intervals": {n: [_finite_or_none(lo), _finite_or_none(hi)] for n, (lo, hi)
                                  in self.extra.get("profile_intervals", {}).items()},
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
                   intervals=_intervals(doc.get("intervals", {})),
                   extra={"at_lowest_minimum": doc.get("at_lowest_minimum", True),
                          "profile_intervals": _intervals(doc.get("profile_intervals", {}))},
                   quality=doc.get("quality", "unjudged"),
                   p_value=math.nan if doc.get("p_value") is None else doc["p_value"],
                   penalised=doc.get("penalised", {}))


def _tick(bar) -> bool:
    """Advance a progress bar; False, so that differential evolution goes on (a callback
    returning True stops it, and tqdm's ``update`` returns True when it redraws)."""
    bar.update(1)
    return False


def _intervals(saved: dict) -> dict[str, tuple[float, float]]:
    """Intervals as saved: ``None`` is an unbounded end."""
    return {n: (-math.inf if lo is None else float(lo), math.inf if hi is None else float(hi))
            for n, (lo, hi) in saved.items()}


def _finite_or_none(x: float) -> float | None:
    """A number for JSON: ``None`` for an unbounded interval end (or an undefined value)."""
    return float(x) if math.isfinite(x) else None


def _verdict(res: FitResult) -> str:
    """The report's first line: what the chi-square says about the fit."""
    dof = max(len(res.data) - len(res.free), 1)
    chi = f"chi-square {res.chisqr:.4g} for {dof} degrees of freedom (p = {res.p_value:.2g}"
    if res.quality == "good":
        return f"GOOD FIT: {chi})"
    rows = sum(res.penalised.values())
    why = [f"{chi} < {POOR_P:g})"] if res.weighted and res.p_value < POOR_P else []
    if not res.extra.get("at_lowest_minimum", True):
        why.append("a profile met a lower chi-square than the fit twice")
    if rows:
        why.append(f"{rows} rows could not be evaluated at the best fit (" + ", ".join(
            f"{v} {k}" for k, v in res.penalised.items() if v) + ")")
    if res.quality == "unjudged":
        return ("FIT NOT JUDGED: no sigma, so the chi-square cannot say whether the model "
                "describes the data; the intervals assume it does")
    return (f"POOR FIT: {'; '.join(why)}: these parameters do not describe the data within "
            "the stated sigma (a wrong valley, a wrong constraint, a wrong model or an "
            "understated sigma); the intervals are the whole search range")


def _constraint_lines(res: FitResult) -> list[str]:
    """Every constraint in force, with what it holds and what follows."""
    g = res.guess or res.system
    free = set(res.free)
    text = {
        "natural_frequency": f"natural_frequency: k_x = mass (2 pi x "
                             f"{g.natural_frequency() / (2 * math.pi):.6g} Hz)^2",
        "normal_load": f"normal_load: k_zc u_z0 = F_N0 = {g.F_N0:.6g} N",
        "quality_factor": f"quality_factor: c_x = 2 zeta sqrt(k_x mass), zeta = "
                          f"{g.zeta:.4g} (Q = {g.quality_factor:.4g})",
    }
    follows = {"natural_frequency": ("mass", "k_x"), "normal_load": ("k_zc", "u_z0")}
    lines = []
    for name, on in res.constraints.items():
        if not on:
            continue
        pair = follows.get(name)
        if pair is None:
            how = "c_x follows mass and k_x"
        else:
            moving = [n for n in pair if n in free]
            how = (f"{pair[1] if moving[0] == pair[0] else pair[0]} follows {moving[0]}"
                   if moving else f"{pair[0]} and {pair[1]} both held at the guess")
        lines.append(f"  {text[name]} ({how}; release with {name}=False)")
    return ["constraints in force:" if lines else "constraints in force: none", *lines]


def _parameter_line(name: str, p, interval: tuple[float, float] | None, judged: bool) -> str:
    """``name = value +- stderr, 95 % interval [lo, hi]``, an unbounded side in words."""
    err = (f"+- {p.stderr:.3g} ({100 * p.stderr / abs(p.value):.2g} %)"
           if p.stderr is not None and np.isfinite(p.stderr) else "(not bounded)")
    if interval is None or any(math.isnan(x) for x in interval):
        return f"  {name:6s} = {p.value:.6g} {err}"
    lo, hi = interval
    what = "95 % interval" if judged else "search range (the fit is poor)"
    ends = [f"{lo:.4g}" if math.isfinite(lo) else "unbounded below",
            f"{hi:.4g}" if math.isfinite(hi) else "unbounded above"]
    return f"  {name:6s} = {p.value:.6g} {err}, {what} [{ends[0]}, {ends[1]}]"


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
        "mu0", "mass", "k_xc", "u_z0"), *, natural_frequency: bool = True,
        normal_load: bool = True, quality_factor: bool = True, span: float = 10.0,
        global_stage: bool = True, maxiter: int = 60, popsize: int = 12, seed: int = 0,
        workers: int = 1, progress: bool = True,
        settings: SolverSettings | None = None) -> FitResult:
    """Fit the fields ``free`` of ``guess`` to a measured table (module docstring).

    ``data``: a table of :func:`~vibrofriction.bench.read_measurements` (or its
    path).  ``natural_frequency``, ``normal_load``, ``quality_factor``: the constraints
    (module docstring); a parameter in ``free`` that one of them would hold is refused,
    naming the keyword that releases it.  ``span``: each free parameter is searched
    within a factor ``span`` of the guess (``mu0`` as well).  ``maxiter``, ``popsize``,
    ``seed``: the global stage (:func:`scipy.optimize.differential_evolution`, on every
    other row of a table of 20 rows or more).  ``workers``: processes for the global
    stage, the local starts and the profiles (``-1``: every core), from the package's one
    pool (:mod:`vibrofriction.parallel`, forkserver workers that die with their parent):
    a script that fits with ``workers != 1`` runs the fit under
    ``if __name__ == "__main__":``.
    ``res.extra["stages"]`` says where the time went; ``res.quality`` whether the fit
    describes the data.
    """
    t0 = time.perf_counter()
    data = read_measurements(data)
    free, tied = _free_and_tied(tuple(free), natural_frequency, normal_load, quality_factor,
                                len(data))
    problem = _Problem(guess, free, natural_frequency, normal_load, quality_factor, data,
                       settings)
    bounds = _bounds(problem, span)
    if "mu0" in free:
        problem.mu0_max = math.exp(bounds[free.index("mu0")][1])
    x0 = np.array([math.log(getattr(guess, n)) for n in free])
    workers = workers if workers >= 1 else available_cores()
    stages = _Stages()
    with mapper(workers) as map_:
        if global_stage:
            out, minima = _search(problem, bounds, x0, map_ if workers != 1 else 1, map_,
                                  stages, maxiter, popsize, seed, progress, workers)
        else:
            with stages.timed("local") as row:
                out, minima, row["evaluations"] = _local_fit(problem, [x0], bounds, map_)
        out, minima, dists, lower = _uncertainties(problem, out, minima, bounds, map_,
                                                   stages, progress)
    res = _result(problem, out, bounds, tied, dists, lower)
    res.nfev, res.seconds = stages.nfev, time.perf_counter() - t0
    res.extra.update(local_minima=[float(m[0]) for m in minima], stages=stages.rows)
    return res


def _result(problem: _Problem, out, bounds, tied, dists, lower) -> FitResult:
    """The :class:`FitResult` of the best fit ``out``: its verdict (a poor one widens the
    intervals to the search range), parameters, intervals and warnings."""
    free = problem.free
    ln = _ln(out, free)
    _, outside, untrusted = problem.evaluate(ln)
    penalised = {"untrusted": untrusted, "outside the model's domain": outside}
    quality, p_value = _judge(problem, float(out.chisqr), lower, outside + untrusted)
    extra: dict[str, Any] = {}
    system = problem.system(ln)
    result_params, intervals = _physical_params(out, free, system, tied, dists)
    extra["at_lowest_minimum"] = lower is None
    if quality == "poor":
        extra["profile_intervals"] = intervals
        search = {n: (ln[j] - bounds[j][0], bounds[j][1] - ln[j]) for j, n in enumerate(free)}
        result_params, intervals = _physical_params(out, free, system, tied, search)
    warnings = _identifiability(out, problem, ln, bounds)
    warnings += _profile_warnings(free, dists, tied, lower)
    return FitResult(params=result_params, system=system, data=problem.data, free=free,
                     constraints={"natural_frequency": problem.natural_frequency,
                                  "normal_load": problem.normal_load,
                                  "quality_factor": problem.quality_factor},
                     warnings=warnings, chisqr=float(out.chisqr), redchi=float(out.redchi),
                     nfev=0, seconds=0.0, weighted=problem.weighted, guess=problem.guess,
                     intervals=intervals, extra=extra, quality=quality, p_value=p_value,
                     penalised=penalised)


def _judge(problem: _Problem, chisqr: float, lower, penalised: int) -> tuple[str, float]:
    """``(quality, p_value)`` of a fit (module docstring; :class:`FitResult`)."""
    p_value = _p_value(problem, chisqr) if problem.weighted else math.nan
    if lower is not None or penalised or (problem.weighted and p_value < POOR_P):
        return "poor", p_value
    return ("good" if problem.weighted else "unjudged"), p_value


def _p_value(problem: _Problem, chisqr: float) -> float:
    """The probability of a chi-square at least ``chisqr`` with ``points - free`` degrees
    of freedom, if the model at the best fit were the truth and ``sigma`` right."""
    from scipy.stats import chi2

    return float(chi2.sf(chisqr, max(len(problem.data) - len(problem.free), 1)))


#: The pairs a constraint ties together (the first follows the second when that is free,
#: and the other way round), and the single field it sets.
_CONSTRAINED = {"natural_frequency": ("mass", "k_x", "k_x = mass (2 pi f_n)^2"),
                "normal_load": ("k_zc", "u_z0", "k_zc u_z0 = F_N0")}


def _free_and_tied(free: tuple[str, ...], natural_frequency: bool, normal_load: bool,
                   quality_factor: bool, points: int
                   ) -> tuple[tuple[str, ...], dict[str, tuple[str, float]]]:
    """``free`` validated (a field a constraint holds is refused, naming the keyword that
    releases it), and the fields that follow a free one by a constraint (``name:
    (source, +-1)``, ``ln name = +-ln source + const``)."""
    unknown = [n for n in free if n not in FITTABLE]
    if unknown or not free:
        raise ValueError(f"free must name fields of Physical among {list(FITTABLE)}, "
                         f"got {list(free)}")
    if len(set(free)) != len(free):
        raise ValueError(f"free names a parameter twice: {list(free)}")
    on = {"natural_frequency": natural_frequency, "normal_load": normal_load}
    tied: dict[str, tuple[str, float]] = {}
    for key, (a, b, law) in _CONSTRAINED.items():
        if not on[key]:
            continue
        if a in free and b in free:
            raise ValueError(f"free names both {a} and {b}, but the constraint {key} "
                             f"({law}, of the guess) holds {b} to {a}: pass {key}=False to "
                             f"fit both, or leave one out of free")
        sign = 1.0 if key == "natural_frequency" else -1.0
        if a in free:
            tied[b] = (a, sign)
        elif b in free:
            tied[a] = (b, sign)
    if quality_factor and "c_x" in free:
        raise ValueError("free names c_x, but the constraint quality_factor (c_x = 2 zeta "
                         "sqrt(k_x mass), zeta of the guess) holds it: pass "
                         "quality_factor=False to fit c_x")
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
    them before the others.  A first global stage that ends poor (:func:`_poor`), or
    whose first starts do, is followed by a second one (another seed) before its
    remaining starts are tried: a wrong valley is left rather than explored.  The best
    fit and the local minima reached (chi-square, point)."""
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
    """A weighted fit whose chi-square has a probability below :data:`POOR_P`."""
    return problem.weighted and _p_value(problem, chisqr) < POOR_P


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
        lo = value * math.exp(-below) if math.isfinite(below) else -math.inf
        hi = value * math.exp(above) if math.isfinite(above) else math.inf
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


def _identifiability(out, problem: _Problem, ln: NDArray, bounds) -> list[str]:
    """One sentence per parameter the data do not identify: at a bound, in a flat direction
    of the Jacobian, strongly correlated with another; and one if the least-squares
    covariance is singular (no correlations)."""
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
            r = (out.params[a].correl or {}).get(b)
            if r is not None and abs(r) > STRONG_CORRELATION:
                warnings.append(f"{a} and {b} are strongly correlated (r = {r:+.3f}): the data "
                                f"constrain a combination of them, not each")
    if out.covar is None:
        warnings.append(f"the least-squares covariance of {', '.join(free)} is singular: "
                        "no correlations (the intervals come from the profiles)")
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
