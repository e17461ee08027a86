"""The fit's result (:mod:`.procedure`).

:class:`FitResult` (the report, saving and loading), and the verdict on a fit's chi-square.
"""

from __future__ import annotations

import dataclasses
import json
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import lmfit
import numpy as np
import pandas as pd
from numpy.typing import NDArray

from ...params import Physical, RateAndState
from .problem import Problem, predict_cof

__all__ = ["DOUBTFUL_P", "POOR_P", "FitResult"]

#: A weighted fit whose chi-square has a probability below this (``points - free``
#: degrees of freedom) is poor: it runs a second global stage (with another seed) and,
#: if still poor, says so and reports the search range as its intervals.
POOR_P = 1e-3
#: Chi-square probability below which a weighted fit is doubtful (a finding, not a
#: footnote): a second global stage is run, and the report says what it may mean.
DOUBTFUL_P = 0.05


@dataclass
class FitResult:
    """The best fit, its uncertainties, its verdict and what the data cannot tell.

    ``params``: lmfit ``Parameters`` of the free fields (``.value``, ``.stderr``,
    ``.correl``; a field that follows a free one by a constraint, e.g. ``k_x`` with
    ``mass``, is listed with its mapped interval); ``intervals``: the 95.4 %
    profile-likelihood interval of each (``-inf``/``inf`` for a side the data do not
    close; the search range when the fit is poor; :mod:`.procedure`), ``stderr`` half its
    longer side; ``system``: the best-fit :class:`Physical`; ``quality``: ``"good"``,
    ``"doubtful"`` (``p_value`` below :data:`DOUBTFUL_P`: a second global stage found no
    lower minimum, the intervals are conditional on this one), ``"poor"`` (chi-square
    probability ``p_value`` below :data:`POOR_P`, a profile met a lower chi-square twice,
    or rows could not be evaluated) or ``"unjudged"`` (no ``sigma``);
    ``penalised``: rows the model could not evaluate at the best fit, by reason;
    ``determination``: what the data hold of each free parameter, ``"determined"``,
    ``"bounded below"``, ``"bounded above"`` or ``"not determined"``, and
    ``combinations`` the combination they hold of one not determined (e.g. ``k_x/mass``);
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
    determination: dict[str, str] = field(default_factory=dict)
    combinations: dict[str, str] = field(default_factory=dict)

    def predict(self, v0: NDArray, du_z: NDArray, omega: NDArray, *,
                du_x: NDArray | float = 0.0, phase_x: NDArray | float = 0.0,
                du_y: NDArray | float = 0.0, phase_y: NDArray | float = 0.0
                ) -> NDArray[np.float64]:
        """The fitted model's COF at other points (``nan`` where not trusted)."""
        return predict_cof(self.system, v0, du_z, omega, du_x=du_x, phase_x=phase_x,
                           du_y=du_y, phase_y=phase_y)

    def report(self) -> str:
        """The fit in words and numbers: the verdict first."""
        lines = [_verdict(self), *_held(self),
                 f"fit of {len(self.data)} points, {len(self.free)} free parameters "
                 f"({'weighted by sigma' if self.weighted else 'unweighted'}): "
                 f"chi-square {self.chisqr:.4g}, reduced {self.redchi:.4g}, "
                 f"{self.nfev} model evaluations, {self.seconds:.1f} s"]
        lines += _constraint_lines(self)
        if self.extra.get("stages"):
            lines.append("time: " + ", ".join(
                f"{r['stage']} {r['seconds']:.1f} s ({r['evaluations']} evaluations)"
                for r in self.extra["stages"]))
        what = {"poor": "search range (the fit is poor)",
                "doubtful": "95 % interval if this minimum is the right one"}.get(
                    self.quality, "95 % interval")
        for name in self.params:
            status = "poor" if self.quality == "poor" else self.determination.get(
                name, "determined")
            lines.append(_parameter_line(name, self.params[name],
                                         self.intervals.get(name), what, status))
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
        """Quantities that move with the fitted fields, at the fit and at the guess.

        ``f_n`` (Hz), ``zeta``, ``Q``, ``c_x`` (N s/m), ``eta_c`` (eq. of docs/damping.md)
        and ``F_N0`` (N, eq. 3).
        """
        def of(p: Physical) -> dict[str, float]:
            return {"f_n [Hz]": p.natural_frequency() / (2.0 * math.pi), "zeta": p.zeta,
                    "Q": p.quality_factor, "c_x [N s/m]": p.c_x, "eta_c": p.eta_c,
                    "F_N0 [N]": p.F_N0}
        guess = of(self.guess) if self.guess is not None else {}
        return {k: (v, guess.get(k)) for k, v in of(self.system).items()}

    def to_json(self, path: str | Path) -> Path:
        """Save (the data, the system, the parameters with errors and correlations, the verdict).

        An unbounded interval end is saved as ``null``.
        """
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
            "penalised": self.penalised, "determination": self.determination,
            "combinations": self.combinations,
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
        """A result saved by :meth:`to_json`."""
        doc = json.loads(Path(path).read_text())
        params = lmfit.Parameters()
        for n, p in doc["params"].items():
            params.add(n, value=p["value"])
            params[n].stderr = p["stderr"]
            params[n].correl = p["correl"]
        return cls(params=params, system=_physical(doc["system"]),
                   data=pd.DataFrame(doc["data"]), free=tuple(doc["free"]),
                   constraints=doc["constraints"], warnings=doc["warnings"],
                   chisqr=doc["chisqr"], redchi=doc["redchi"], nfev=doc["nfev"],
                   seconds=doc["seconds"], weighted=doc["weighted"],
                   guess=_physical(doc["guess"]) if doc["guess"] else None,
                   intervals=_intervals(doc.get("intervals", {})),
                   extra={"at_lowest_minimum": doc.get("at_lowest_minimum", True),
                          "profile_intervals": _intervals(doc.get("profile_intervals", {}))},
                   quality=doc.get("quality", "unjudged"),
                   p_value=math.nan if doc.get("p_value") is None else doc["p_value"],
                   penalised=doc.get("penalised", {}),
                   determination=doc.get("determination", {}),
                   combinations=doc.get("combinations", {}))


def _physical(saved: dict) -> Physical:
    """A :class:`Physical` as saved: its rate-and-state law (a dict in the JSON) rebuilt."""
    law = saved.get("friction")
    return Physical(**{**saved, "friction": None if law is None else RateAndState(**law)})


def _intervals(saved: dict) -> dict[str, tuple[float, float]]:
    """Intervals as saved: ``None`` is an unbounded end."""
    return {n: (-math.inf if lo is None else float(lo), math.inf if hi is None else float(hi))
            for n, (lo, hi) in saved.items()}


def _finite_or_none(x: float) -> float | None:
    """A number for JSON: ``None`` for an unbounded interval end (or an undefined value)."""
    return float(x) if math.isfinite(x) else None


def _verdict(res: FitResult) -> str:
    """The report's first line: what the chi-square says about the fit."""
    dof = len(res.data) - len(res.free)
    if dof <= 0:
        return (f"FIT NOT JUDGED: {len(res.free)} free parameters for {len(res.data)} points "
                "leave no degrees of freedom: the chi-square can say nothing about the fit, "
                "and the intervals hold only if the model is right")
    chi = f"chi-square {res.chisqr:.4g} for {dof} degrees of freedom (p = {res.p_value:.2g}"
    if res.quality == "good":
        return f"GOOD FIT: {chi})"
    if res.quality == "doubtful":
        return (f"DOUBTFUL FIT: {chi} < {DOUBTFUL_P:g}): the fit may sit in a wrong valley "
                f"({_searched(res)}), or a constraint, the model or sigma may be off; the "
                "intervals hold only if this minimum is the right one")
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


def _searched(res: FitResult) -> str:
    """What the global search did, as the stages that ran say."""
    rounds = [r for r in res.extra.get("stages", []) if r["stage"] == "global"]
    if not rounds:
        return "no global search ran: global_stage=False"
    if len(rounds) == 1:
        return "the global search found no lower one"
    return f"{len(rounds)} rounds of the global search found no lower one"


def _constraint_lines(res: FitResult) -> list[str]:
    """Every constraint in force, with what it holds and what follows."""
    g = res.guess or res.system
    free = set(res.free)
    text = {
        "natural_frequency": f"natural_frequency: k_x = mass (2 pi x "
                             f"{g.natural_frequency() / (2 * math.pi):.6g} Hz)^2",
        "normal_load": (f"normal_load: F(u_z0) = k_zc u_z0 n/(n + 1) = F_N0 = {g.F_N0:.6g} N "
                        f"(a curved contact, n = {g.profile_exponent:g})" if g.curved else
                        f"normal_load: k_zc u_z0 = F_N0 = {g.F_N0:.6g} N"),
        "quality_factor": f"quality_factor: c_x = 2 zeta sqrt(k_x mass), zeta = "
                          f"{g.zeta:.4g} (Q = {g.quality_factor:.4g})",
    }
    follows = {"natural_frequency": ("mass", "k_x"), "normal_load": ("k_zc", "u_z0")}
    lines = []
    for name, on in res.constraints.items():
        if not on:
            continue
        pair = follows.get(name)
        geometry = [n for n in ("radius", "E_star") if n in free]
        if pair is None:
            how = "c_x follows mass and k_x"
        elif name == "normal_load" and geometry:
            how = (f"k_zc, k_xc and u_z0 follow {geometry[0]}: the contact geometry at the "
                   f"load")
        else:
            moving = [n for n in pair if n in free]
            how = (f"{pair[1] if moving[0] == pair[0] else pair[0]} follows {moving[0]}"
                   if moving else f"{pair[0]} and {pair[1]} both held at the guess")
        lines.append(f"  {text[name]} ({how}; release with {name}=False)")
    return ["constraints in force:" if lines else "constraints in force: none", *lines]


def _held(res: FitResult) -> list[str]:
    """What the data hold of the free parameters, in one line (none without a verdict)."""
    if not res.determination:
        return []
    if res.quality == "poor":
        return ["what the data hold: nothing while the fit is poor (the intervals are the "
                "search range)"]
    groups: dict[str, list[str]] = {}
    for n in res.free:
        groups.setdefault(res.determination[n], []).append(n)
    parts = []
    for status in ("determined", "bounded below", "bounded above", "not determined"):
        names = groups.get(status, [])
        if not names:
            continue
        text = f"{', '.join(names)} {status}"
        combos = [res.combinations[n] for n in names if n in res.combinations]
        if status == "not determined" and combos:
            text += f" (the data hold {', '.join(dict.fromkeys(combos))})"
        elif status.startswith("bounded"):
            text += " only"
        parts.append(text)
    return ["what the data hold: " + "; ".join(parts)]


def _parameter_line(name: str, p, interval: tuple[float, float] | None, what: str,
                    status: str = "determined") -> str:
    """``name = value +- stderr, 95 % interval [lo, hi]``, an unbounded side in words."""
    err = (f"+- {p.stderr:.3g} ({100 * p.stderr / abs(p.value):.2g} %)"
           if p.stderr is not None and np.isfinite(p.stderr) else "(not bounded)")
    if status == "not determined":
        err, what = "not determined", "range explored"
    if interval is None or any(math.isnan(x) for x in interval):
        return f"  {name:6s} = {p.value:.6g} {err}"
    lo, hi = interval
    ends = [f"{lo:.4g}" if math.isfinite(lo) else "unbounded below",
            f"{hi:.4g}" if math.isfinite(hi) else "unbounded above"]
    return f"  {name:6s} = {p.value:.6g} {err}, {what} [{ends[0]}, {ends[1]}]"


def _json_default(x):
    if isinstance(x, float | np.floating):
        return None if not np.isfinite(x) else float(x)
    if isinstance(x, np.integer):
        return int(x)
    raise TypeError(f"not serialisable: {type(x).__name__}")


def judge(problem: Problem, chisqr: float, lower, penalised: int) -> tuple[str, float]:
    """``(quality, p_value)`` of a fit (:mod:`.procedure`; :class:`FitResult`)."""
    if len(problem.data) <= len(problem.free):  # no degrees of freedom: nothing to judge
        return "unjudged", math.nan
    p_value = chi_square_p(problem, chisqr) if problem.weighted else math.nan
    if lower is not None or penalised or (problem.weighted and p_value < POOR_P):
        return "poor", p_value
    if problem.weighted and p_value < DOUBTFUL_P:
        return "doubtful", p_value
    return ("good" if problem.weighted else "unjudged"), p_value


def chi_square_p(problem: Problem, chisqr: float) -> float:
    """The probability of a chi-square at least ``chisqr``.

    The probability of a chi-square at least ``chisqr`` with ``points - free`` degrees
    of freedom, if the model at the best fit were the truth and ``sigma`` right.
    """
    from scipy.stats import chi2

    dof = len(problem.data) - len(problem.free)
    return float(chi2.sf(chisqr, dof)) if dof > 0 else math.nan
