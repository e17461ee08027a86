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
evolution over ``ln`` of the free parameters, within a factor ``span`` of the guess)
comes first, then Levenberg-Marquardt with lmfit from its best point.  Parameters are
fitted as logarithms (all are positive and span decades); values, standard errors
(first-order propagation, ``stderr = value * stderr(ln)``) and correlations are reported
in the physical parameters.  With ``sigma`` in the data the residuals are weighted and
the covariance is not rescaled; without it, lmfit scales it by the reduced chi-square.
"""

from __future__ import annotations

import dataclasses
import json
import math
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import lmfit
import numpy as np
import pandas as pd
from numpy.typing import NDArray

from .measurements import read_measurements
from .params import Physical
from .solver import SolverSettings, solve_points

__all__ = ["FITTABLE", "FitResult", "fit", "predict_cof"]

#: The fields of :class:`Physical` that can be fitted.
FITTABLE = ("mu0", "mass", "k_x", "k_xc", "k_zc", "u_z0", "c_x", "c_xc")
#: Correlations beyond this in modulus are reported as a warning.
STRONG_CORRELATION = 0.98
#: Relative singular value below which a direction of the Jacobian counts as flat.
FLAT = 1e-4


def predict_cof(system: Physical, v0: NDArray, du_z: NDArray, omega: NDArray,
                settings: SolverSettings | None = None) -> NDArray[np.float64]:
    """``mu0 * mu_ratio`` of ``system`` at each ``(v0, du_z, omega)`` (eq. 25).

    Where the solver has no trusted value the midpoint of its window means stands in
    (nan where it has none at all).
    """
    alpha, beta, a, zeta, eta = system.groups(du_z, omega)
    V = np.asarray(v0, dtype=float) / system._velocity_unit(omega)
    out = solve_points(alpha, beta, a, V, zeta, eta, settings=settings)
    mu = np.where(np.isfinite(out["mu_ratio"]), out["mu_ratio"],
                  0.5 * (out["window_min"] + out["window_max"]))
    return system.mu0 * mu


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


@dataclass
class FitResult:
    """The best fit, its uncertainties and what the data cannot tell.

    ``params``: lmfit ``Parameters`` of the free fields (``.value``, ``.stderr``,
    ``.correl``; a field tied to a free one by a constraint, e.g. ``k_x`` to ``mass``, is
    listed with the same relative error); ``system``: the best-fit :class:`Physical`;
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
        for name in self.params:
            p = self.params[name]
            err = f"+- {p.stderr:.3g} ({100 * p.stderr / abs(p.value):.2g} %)" \
                if p.stderr is not None and np.isfinite(p.stderr) else "(no uncertainty)"
            lines.append(f"  {name:6s} = {p.value:.6g} {err}")
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
                   guess=Physical(**doc["guess"]) if doc["guess"] else None)

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
        global_stage: bool = True, maxiter: int = 30, popsize: int = 12, seed: int = 0,
        workers: int = 1, progress: bool = True,
        settings: SolverSettings | None = None) -> FitResult:
    """Fit the fields ``free`` of ``guess`` to a measured table (module docstring).

    ``data``: a table of :func:`~vibrofriction.measurements.read_measurements` (or its
    path).  ``span``: each free parameter is searched within a factor ``span`` of the
    guess (``mu0`` as well).  ``maxiter``, ``popsize``, ``seed``, ``workers``: the global
    stage (:func:`scipy.optimize.differential_evolution`).
    """
    from scipy.optimize import differential_evolution
    from tqdm.auto import tqdm

    t0 = time.perf_counter()
    data = read_measurements(data)
    free = tuple(free)
    unknown = [n for n in free if n not in FITTABLE]
    if unknown or not free:
        raise ValueError(f"free must name fields of Physical among {list(FITTABLE)}, "
                         f"got {list(free)}")
    if len(set(free)) != len(free):
        raise ValueError(f"free names a parameter twice: {list(free)}")
    tied: dict[str, tuple[str, float]] = {}  # reported too, following a free one
    if natural_frequency and "mass" in free and "k_x" in free:
        free = tuple(n for n in free if n != "k_x")  # k_x follows the mass
        tied["k_x"] = ("mass", 1.0)
    if normal_load and "k_zc" in free and "u_z0" in free:
        free = tuple(n for n in free if n != "u_z0")  # u_z0 follows k_zc
        tied["u_z0"] = ("k_zc", -1.0)
    if len(free) > len(data):
        raise ValueError(f"{len(free)} free parameters but only {len(data)} data points")
    problem = _Problem(guess, free, natural_frequency, normal_load, quality_factor, data,
                       settings)
    bounds = _bounds(problem, span)
    x0 = np.array([math.log(getattr(guess, n)) for n in free])
    nfev = 0
    if global_stage:
        bar = tqdm(total=maxiter, desc="fit: global stage", unit="gen", disable=not progress)
        de = differential_evolution(problem.cost, bounds, maxiter=maxiter, popsize=popsize,
                                    seed=seed, polish=False, init="sobol", x0=x0, tol=0.0,
                                    workers=workers, updating="deferred" if workers != 1
                                    else "immediate", callback=lambda *a, **k: _tick(bar))
        bar.close()
        nfev += int(de.nfev)
        x0 = de.x if de.fun <= problem.cost(x0) else x0
    params = lmfit.Parameters()
    for n, x, (lo, hi) in zip(free, x0, bounds, strict=True):
        params.add(n, value=float(x), min=lo, max=hi)
    bar = tqdm(desc="fit: least squares", unit="eval", disable=not progress)

    def residual(p):
        bar.update(1)
        return problem.residual(np.array([p[n].value for n in free]))

    weighted = bool(np.all(np.isfinite(data["sigma"].to_numpy())))
    out = lmfit.minimize(residual, params, method="leastsq", scale_covar=not weighted,
                         epsfcn=1e-8)
    bar.close()
    nfev += int(out.nfev)
    ln = np.array([out.params[n].value for n in free])
    system = problem.system(ln)
    result_params = _physical_params(out, free, system, tied)
    warnings = _identifiability(out, problem, ln, bounds, result_params)
    return FitResult(params=result_params, system=system, data=data, free=free,
                     constraints={"natural_frequency": natural_frequency,
                                  "normal_load": normal_load, "quality_factor": quality_factor},
                     warnings=warnings, chisqr=float(out.chisqr), redchi=float(out.redchi),
                     nfev=nfev, seconds=time.perf_counter() - t0, weighted=weighted,
                     guess=guess)


def _physical_params(out, free: tuple[str, ...], system: Physical,
                     tied: dict[str, tuple[str, float]]) -> lmfit.Parameters:
    """The fitted ``ln`` parameters as physical ones: value, ``stderr = value * stderr(ln)``,
    the same correlations; and the parameters tied to them by a constraint, ``ln x =
    +-ln y + const`` (same relative error)."""
    params = lmfit.Parameters()
    for n in free:
        value = getattr(system, n)
        params.add(n, value=value, vary=False)
        s = out.params[n].stderr
        params[n].stderr = value * s if s is not None and np.isfinite(s) else None
        params[n].correl = dict(out.params[n].correl or {})
    for n, (source, _) in tied.items():
        value = getattr(system, n)
        params.add(n, value=value, vary=False)
        s = out.params[source].stderr
        params[n].stderr = value * s if s is not None and np.isfinite(s) else None
    return params


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
    sigma = problem.data["sigma"].to_numpy()
    dof = len(problem.data) - len(free)
    if np.all(np.isfinite(sigma)) and dof > 0 and out.chisqr / dof > 2.0:
        warnings.append(f"reduced chi-square {out.chisqr / dof:.3g} with the stated sigma: the "
                        "fit may sit in a local minimum (widen the global stage: maxiter, "
                        "popsize) or the model does not describe these data; the standard "
                        "errors then understate the uncertainty")
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
