"""``vibrofriction mu``: the coefficient of friction at one or several velocities."""

from __future__ import annotations

import json
from typing import TYPE_CHECKING, Any, cast

from ..schema import choice_names, parameter_names, parameters
from ._app import Args, Command, exit_if_untrusted, json_number
from ._options import (
    FLOAT,
    FRICTION_SI,
    GROUPS,
    INITIAL,
    MAX_PERIODS,
    TOL_TRUSTED,
    Opt,
    Range,
    flag,
    model_options,
)

if TYPE_CHECKING:
    from ..params import Dimensionless, Physical, RateAndState
    from ..solver import FrictionResult, FrictionResults

#: The SI set-up's parameters every physical set-up needs (no default, no twin).
REQUIRED_SI = tuple(p.name for p in parameters("physical")
                    if p.default is None and not p.twin and "dimensionless" not in p.models)
_MDR = ("the MDR solver (docs/contact_geometry.md): slow; with --v-inertial or --v0; takes "
        "--a-x, --phase-x, --inplane-on at a velocity != 0, not --eta-c or --a-y")

OPTIONS: tuple[Opt, ...] = (
    *model_options({"vbar": "list", "v_inertial": "list", "v0": "list"},
                   {"profile_exponent": _MDR,
                    "v_inertial": "needed in cases III, IV undamped and with an in-plane "
                                  "oscillation",
                    "v0": "a physical set-up's velocity"}),
    Opt("quality_factor", "the pin's quality factor Q from an impact test (a physical "
        "set-up, instead of --c-x)", metavar=FLOAT, range=Range(0.0, strict=True),
        group=GROUPS["physical"]),
    Opt("bench", "physical set-up from a bench file (JSON, docs/bench.md), with --v0",
        kind="text", metavar="FILE", group=GROUPS["physical"]),
    *FRICTION_SI, INITIAL, MAX_PERIODS, TOL_TRUSTED,
    Opt("as_json", "one JSON object per point: every field of the result (and, for a "
        "physical set-up, v0 in m/s, mu and the SI parameters)", kind="flag",
        flags=("--json",), negatable=False),
)

#: The options only a dimensionless system takes, and those only a physical set-up takes.
SCALED_ONLY = (*[p.name for p in parameters("dimensionless") if "physical" not in p.models],
               "vbar", "v_inertial")
_SCALED_INPLANE = ("a_x", "a_y", "alpha_y", "zeta_y")
_SI_INPLANE = ("du_x", "du_y", "k_y", "c_y")
SI_ONLY = (*[n for n in parameter_names("physical") if n not in parameter_names(
    "dimensionless")], "v0", "quality_factor", "bench", *(o.name for o in FRICTION_SI))


def run(a: Args) -> None:
    """Compute and print (the command's body; heavy imports happen here)."""
    import numpy as np

    from ..solver import SolverSettings, friction_coefficient

    settings = SolverSettings(max_periods=a["max_periods"], tol_trusted=a["tol_trusted"])
    physical = None
    v0: list[float] = []
    if any(a.has(n) for n in SI_ONLY):
        physical = _physical(a)
        v0 = a["v0"]
        results = friction_coefficient(physical, v0=np.array(v0), initial=a["initial"],
                                       settings=settings)
    else:
        system = _dimensionless(a)
        speeds = {n: None if a[n] is None else np.array(a[n]) for n in ("vbar", "v_inertial")}
        results = friction_coefficient(system, **speeds, initial=a["initial"],
                                       settings=settings)
    rows = list(cast("FrictionResults", results))  # the velocities are 1-d arrays
    _print(rows, physical, v0, a["as_json"])
    exit_if_untrusted([r.trusted for r in rows], settings.tol_trusted)


def _given(a: Args, names: tuple[str, ...] | list[str]) -> list[str]:
    return [flag(n) for n in names if a.has(n)]


def _physical(a: Args) -> Physical:
    """The SI set-up of the flags or of ``--bench`` (ValueError naming what is wrong)."""
    from ..params import Physical

    scaled, si = _given(a, SCALED_ONLY), _given(a, SI_ONLY)
    if scaled and all(n in _SI_INPLANE for n in a.given if n in SI_ONLY):
        raise ValueError("--du-x, --du-y (m) need a physical set-up, as do --k-y, --c-y: "
                         "the dimensionless system takes --a-x, --a-y, --alpha-y, --zeta-y")
    if scaled and all(n in _SCALED_INPLANE for n in a.given if n in SCALED_ONLY):
        raise ValueError("--a-x, --a-y are the dimensionless amplitudes (and --alpha-y, "
                         "--zeta-y dimensionless): a physical set-up takes --du-x, --du-y "
                         "(m), --k-y, --c-y")
    if scaled:
        raise ValueError(f"give either the dimensionless system ({', '.join(scaled)}) or "
                         f"the physical set-up ({', '.join(si)})")
    if not a.has("v0"):
        raise ValueError("a physical set-up needs the velocity --v0 (m/s)")
    inplane = {n: a[n] for n in ("du_x", "du_y", "phase_x", "phase_y", "inplane_on")}
    pin_y = {n: a[n] for n in ("k_y", "c_y") if a.has(n)}
    if a.has("bench"):
        own = _given(a, [*REQUIRED_SI, "c_x", "c_xc", "quality_factor"])
        if own:
            raise ValueError(f"give either --bench or the SI flags ({', '.join(own)})")
        from ..bench import from_bench_file

        physical = from_bench_file(a["bench"])
        if a.has("du_x") or a.has("du_y"):
            physical = physical.with_(**inplane)
        if pin_y:
            physical = physical.with_(**pin_y)
        if a.has("mu_static") or a.has("friction_a"):
            physical = physical.with_(mu_static=a["mu_static"], friction=_friction(a))
        if a.has("profile_exponent") and a["profile_exponent"] != physical.profile_exponent:
            raise ValueError("--profile-exponent: a bench file's contact geometry and "
                             "contact_model give the profile (docs/bench.md)")
        return physical
    missing = [flag(n) for n in REQUIRED_SI if not a.has(n)]
    if missing:
        raise ValueError("a physical set-up needs " + ", ".join(missing))
    if a.has("quality_factor") and a.has("c_x"):
        raise ValueError("give either --c-x or --quality-factor")
    system = Physical(**{n: a[n] for n in REQUIRED_SI}, c_x=a["c_x"], c_xc=a["c_xc"],
                      **inplane, **pin_y, profile_exponent=a["profile_exponent"],
                      mu_static=a["mu_static"], friction=_friction(a))
    if a.has("quality_factor"):
        system = system.with_damping(quality_factor=a["quality_factor"])
    return system


def _friction(a: Args) -> RateAndState | None:
    """The rate-and-state law of a physical set-up's flags (None: Coulomb friction)."""
    from ..params import RateAndState

    if not a.has("friction_a"):
        return None
    missing = [flag(n) for n in ("friction_d_c", "friction_v_ref") if not a.has(n)]
    if missing:
        raise ValueError("rate-and-state friction (--friction-a) needs " + ", ".join(missing))
    return RateAndState(a=a["friction_a"], b=a["friction_b"] or 0.0, d_c=a["friction_d_c"],
                        v_ref=a["friction_v_ref"], alpha_ld=a["friction_alpha_ld"] or 0.0,
                        law=a["rs_law"])


def _dimensionless(a: Args) -> Dimensionless:
    from ..params import Dimensionless

    missing = [flag(n) for n in ("alpha", "beta", "amplitude") if not a.has(n)]
    if missing:
        raise ValueError("missing " + ", ".join(missing) + " (or give a physical set-up)")
    return Dimensionless(**{n: a[n] for n in parameter_names("dimensionless")},
                         **{n: a[n] for n in choice_names("dimensionless")})


def _json_value(v: Any) -> Any:
    if isinstance(v, float):
        return json_number(v)
    if isinstance(v, dict):
        return {k: _json_value(x) for k, x in v.items()}
    return v


def json_row(r: FrictionResult, physical: Physical | None = None,
             v0: float | None = None) -> dict:
    """Every field of a result, JSON-safe, with its ``vbar`` and its message.

    Every field of a result (:data:`vibrofriction.schema.RESULT_FIELDS`, JSON-safe:
    nan as null, inf as "inf"; ``system`` as every parameter of the schema's
    dimensionless model), its ``vbar`` and its message; for a physical set-up also
    ``v0`` (m/s), ``mu`` (mu0 * mu_ratio) and ``physical``, every SI parameter.
    """
    row = {k: _json_value(v) for k, v in r.as_dict().items()}
    row["system"] = {n: json_number(getattr(r.system, n))
                     for n in parameter_names("dimensionless")}
    row["system"].update({n: getattr(r.system, n) for n in choice_names("dimensionless")})
    row["vbar"] = json_number(r.vbar)
    row["message"] = r.message
    if physical is not None:
        row["v0"] = json_number(v0)
        row["mu"] = json_number(physical.mu0 * r.mu_ratio)
        row["physical"] = {n: json_number(getattr(physical, n))
                           for n in parameter_names("physical")}
        row["physical"].update({n: getattr(physical, n) for n in choice_names("physical")})
    return row


def _header(system: Dimensionless) -> str:
    damping = (f" zeta={system.zeta:g} eta_c={system.eta_c:g}" if system.damped else "")
    inplane = "".join(f" a_{c}={getattr(system, 'a_' + c):g} phase_{c}="
                      f"{getattr(system, 'phase_' + c):g}" for c in "xy"
                      if getattr(system, "a_" + c) > 0)
    if system.a_y > 0 and (system.alpha_y, system.zeta_y) != (None, None):
        inplane += " alpha_y={:g} zeta_y={:g}".format(*system.pin_y)
    if inplane:  # the critical velocity of a curved profile is not derived
        inplane += f" on the {system.inplane_on}" + ("" if system.curved else (
            f" (critical velocity {system.critical_inertial_velocity():.5g})"))
    profile = f" profile_exponent={system.profile_exponent:g}" if system.curved else ""
    return (f"alpha={system.alpha:g} beta={system.beta:g} amplitude={system.amplitude:g}"
            f"{damping}{inplane}{profile} case {system.case.value}")


def _si_header(p: Physical) -> str:
    """The SI set-up in one line: every parameter that is set, with its unit."""
    from ._options import unit_words

    parts = []
    for q in parameters("physical"):
        v = getattr(p, q.name)
        if v is None or (q.default is not None and v == q.default):
            continue
        unit = unit_words(q.unit)
        parts.append(f"{q.name}={v:g}" + (f" {unit}" if unit else ""))
    return "physical set-up: " + ", ".join(parts)


def _cell(x: float, width: int, spec: str) -> str:
    """A number, or ``-`` where it is not defined (``vbar`` where ``v0*`` is not)."""
    return f"{'-' if x != x else format(x, spec):>{width}}"


def _print(rows: list[FrictionResult], physical: Physical | None, v0: list[float],
           as_json: bool) -> None:
    if as_json:
        for i, r in enumerate(rows):
            print(json.dumps(json_row(r, physical, v0[i] if physical is not None else None)))
        return
    system = rows[0].system
    if physical is not None:
        print(_si_header(physical))
    print(_header(system))
    lateral = system.a_y > 0  # the 2-D solver: the mean force across the sliding too
    with_vbar = any(r.vbar == r.vbar for r in rows)  # not nan: v0* is defined
    cols = ([("v0 [m/s]", 12)] if physical is not None else []) \
        + ([("vbar", 10)] if with_vbar else []) + [("v_inertial", 12)] \
        + ([("mu", 14)] if physical is not None else []) + [("mu/mu0", 14)] \
        + ([("lateral", 14)] if lateral else []) + [("error", 9)]
    print(" ".join(f"{name:>{width}}" for name, width in cols) + "  status")
    for i, r in enumerate(rows):
        cells = ([f"{v0[i]:>12.5g}"] if physical is not None else []) \
            + ([_cell(r.vbar, 10, ".4g")] if with_vbar else []) \
            + [f"{r.v_inertial:>12.5g}"] \
            + ([f"{physical.mu0 * r.mu_ratio:>14.10f}"] if physical is not None else []) \
            + [f"{r.mu_ratio:>14.10f}"] \
            + ([f"{r.lateral_ratio:>14.10f}"] if lateral else []) + [f"{r.error:>9.1e}"]
        print(" ".join(cells) + f"  {r.status.value}"
              + (f" (period {r.period})" if r.period else "")
              + ("" if r.trusted else "  NOT TRUSTED"))


COMMAND = Command(
    "mu", "the coefficient of friction at one or several velocities",
    """Macroscopic coefficient of friction mu/mu0 in the steady state (eq. 25).

    Give the dimensionless system (--alpha --beta --amplitude, optionally --zeta --eta-c
    --a-x --phase-x --a-y --phase-y --alpha-y --zeta-y --inplane-on --profile-exponent) with
    --vbar or --v-inertial, or a physical set-up in SI units (--mass --k-x --k-xc --k-zc
    --u-z0 --du-z --omega --mu0, optionally --c-x or --quality-factor, --c-xc, --du-x
    --phase-x --du-y --phase-y --k-y --c-y --inplane-on --profile-exponent; or --bench) with
    --v0: it prints v0 in m/s and the coefficient of friction mu = mu0 * mu/mu0 too.

    Exit status 0 if every point is trusted, 3 if some are not, 2 for bad input.""",
    OPTIONS, run)
