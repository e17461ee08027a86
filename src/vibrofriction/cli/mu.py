"""``vibrofriction mu``: the coefficient of friction at one or several velocities."""

from __future__ import annotations

import json
from typing import Annotated, Any, cast

import numpy as np
import typer

from ..params import Dimensionless, Physical
from ..schema import choice_names, parameter_names
from ..solver import FrictionResult, FrictionResults, SolverSettings, friction_coefficient
from ._app import app, exit_if_untrusted, friendly, json_number, parse_float, parse_list


@app.command("mu")
@friendly
def mu_command(
    alpha: Annotated[str | None, typer.Option(help="alpha = k_x/(m omega^2), eq. (20); > 0")]
    = None,
    beta: Annotated[str | None, typer.Option(
        help="beta = (k_x + k_xc)/(m omega^2) > alpha; 'inf' = rigid contact")] = None,
    amplitude: Annotated[str | None, typer.Option(help="a = du_z/u_z0 >= 0 (> 1: jumping)")]
    = None,
    zeta: Annotated[str, typer.Option(
        help="damping ratio of the pin c_x/(2 sqrt(k_x m)) = 1/(2Q) >= 0")] = "0",
    eta_c: Annotated[str, typer.Option(
        "--eta-c", help="loss factor of the contact omega c_xc/k_xc >= 0")] = "0",
    a_x: Annotated[str, typer.Option(
        "--a-x", help="in-plane oscillation along the sliding, du_x m omega^2/(mu0 F_N0) "
        ">= 0 (docs/inplane.md)")] = "0",
    phase_x: Annotated[str, typer.Option(
        "--phase-x", help="its phase relative to the normal oscillation, rad")] = "0",
    a_y: Annotated[str, typer.Option(
        "--a-y", help="in-plane oscillation across the sliding, du_y m omega^2/(mu0 F_N0) "
        ">= 0 (the 2-D solver)")] = "0",
    phase_y: Annotated[str, typer.Option(
        "--phase-y", help="its phase relative to the normal oscillation, rad")] = "0",
    alpha_y: Annotated[str | None, typer.Option(
        "--alpha-y", help="the pin across the sliding: k_y/(m omega^2) > 0 (default alpha; "
        "the 2-D solver)")] = None,
    zeta_y: Annotated[str | None, typer.Option(
        "--zeta-y", help="its damping ratio c_y/(2 sqrt(k_y m)) >= 0 (default zeta)")] = None,
    inplane_on: Annotated[str, typer.Option(
        "--inplane-on", help="where the in-plane oscillation is imposed: substrate or "
        "holder")] = "substrate",
    profile_exponent: Annotated[str, typer.Option(
        "--profile-exponent", help="exponent n of the pin's tip z = c r^n: 'inf' the flat "
        "punch (default), 2 a sphere, 1 a cone (the MDR solver, docs/contact_geometry.md: "
        "slow, with --v-inertial or --v0; takes --a-x, --phase-x, --inplane-on at a "
        "velocity != 0, not --eta-c or --a-y)")] = "inf",
    vbar: Annotated[str | None, typer.Option(help="v0/v0* (eq. 16); comma-separated list "
                                             "allowed")] = None,
    v_inertial: Annotated[str | None, typer.Option(
        "--v-inertial", help="v0 m omega/(mu0 F_N0) (Fig. 6; needed in cases III, IV "
        "undamped and with an in-plane oscillation; signed); list allowed")] = None,
    mass: Annotated[str | None, typer.Option(help="physical set-up: mass m, kg")] = None,
    k_x: Annotated[str | None, typer.Option("--k-x", help="system spring k_x, N/m")] = None,
    k_xc: Annotated[str | None, typer.Option(
        "--k-xc", help="tangential contact stiffness, N/m ('inf' = rigid)")] = None,
    k_zc: Annotated[str | None, typer.Option("--k-zc", help="normal contact stiffness, N/m")]
    = None,
    u_z0: Annotated[str | None, typer.Option("--u-z0", help="mean indentation, m")] = None,
    du_z: Annotated[str | None, typer.Option("--du-z", help="oscillation amplitude, m")] = None,
    omega: Annotated[str | None, typer.Option(help="angular frequency, rad/s")] = None,
    mu0: Annotated[str | None, typer.Option(help="local coefficient of friction")] = None,
    c_x: Annotated[str, typer.Option("--c-x", help="pin dashpot, N s/m")] = "0",
    c_xc: Annotated[str, typer.Option("--c-xc", help="contact dashpot, N s/m")] = "0",
    du_x: Annotated[str, typer.Option(
        "--du-x", help="in-plane oscillation amplitude along the sliding, m (with "
        "--phase-x, --inplane-on)")] = "0",
    du_y: Annotated[str, typer.Option(
        "--du-y", help="in-plane oscillation amplitude across the sliding, m (with "
        "--phase-y)")] = "0",
    k_y: Annotated[str | None, typer.Option(
        "--k-y", help="the pin's stiffness across the sliding, N/m (default k_x; with "
        "--du-y)")] = None,
    c_y: Annotated[str | None, typer.Option(
        "--c-y", help="the pin's dashpot across the sliding, N s/m (default c_x)")] = None,
    quality_factor: Annotated[str | None, typer.Option(
        "--quality-factor", help="the pin's Q from an impact test (instead of --c-x)")] = None,
    v0: Annotated[str | None, typer.Option(help="physical set-up: velocity v0, m/s "
                                           "(signed); list allowed")] = None,
    bench: Annotated[str | None, typer.Option(
        help="physical set-up from a bench file (JSON, docs/bench.md), with --v0")] = None,
    initial: Annotated[str, typer.Option(help="initial state: sliding or rest")] = "sliding",
    max_periods: Annotated[int, typer.Option(help="give up after this many periods")] = 20000,
    tol_trusted: Annotated[float, typer.Option(
        help="largest error of a trusted point; exit code 3 if any point is not trusted")
    ] = SolverSettings.tol_trusted,
    as_json: Annotated[bool, typer.Option(
        "--json", help="one JSON object per point: every field of the result")] = False,
) -> None:
    """Macroscopic coefficient of friction mu/mu0 in the steady state (eq. 25).

    Give the dimensionless system (--alpha --beta --amplitude [--zeta --eta-c --a-x
    --phase-x --a-y --phase-y --alpha-y --zeta-y --inplane-on --profile-exponent]) with
    --vbar or --v-inertial, or a physical set-up in SI units (--mass --k-x --k-xc --k-zc
    --u-z0 --du-z --omega --mu0 [--c-x or --quality-factor, --c-xc, --du-x --phase-x --du-y
    --phase-y --k-y --c-y --inplane-on --profile-exponent]) with --v0.
    """
    inplane: dict[str, Any] = {"phase_x": parse_float(phase_x, "phase_x"),
               "phase_y": parse_float(phase_y, "phase_y"), "inplane_on": inplane_on}
    si_inplane: dict[str, Any] = {"du_x": parse_float(du_x, "du_x"),
                                  "du_y": parse_float(du_y, "du_y")}
    exponent = parse_float(profile_exponent, "profile_exponent")
    scaled_inplane: dict[str, Any] = {"a_x": parse_float(a_x, "a_x"),
                                      "a_y": parse_float(a_y, "a_y")}
    si_pin_y = {k: parse_float(v, k) for k, v in (("k_y", k_y), ("c_y", c_y)) if v is not None}
    scaled_pin_y: dict[str, Any] = {
        k: parse_float(v, k) for k, v in (("alpha_y", alpha_y), ("zeta_y", zeta_y))
        if v is not None}
    phys = {"mass": mass, "k_x": k_x, "k_xc": k_xc, "k_zc": k_zc, "u_z0": u_z0,
            "du_z": du_z, "omega": omega, "mu0": mu0}
    settings = SolverSettings(max_periods=max_periods, tol_trusted=tol_trusted)
    if bench is not None or any(v is not None for v in phys.values()) or v0 is not None:
        if bench is not None:
            if any(v is not None for v in phys.values()):
                raise ValueError("give either --bench or the SI flags")
            from ..bench import from_bench_file

            physical = from_bench_file(bench)
            if any(v > 0.0 for v in si_inplane.values()):
                physical = physical.with_(**si_inplane, **inplane)
            if si_pin_y:
                physical = physical.with_(**si_pin_y)
            if exponent != physical.profile_exponent:
                raise ValueError("--profile-exponent: a bench file's contact geometry and "
                                 "contact_model give the profile (docs/bench.md)")
        else:
            physical = _physical(phys, c_x, c_xc, quality_factor,
                                 (alpha, beta, amplitude, vbar, v_inertial),
                                 **si_inplane, **inplane, **si_pin_y,
                                 profile_exponent=exponent)
        if any(v != 0.0 for v in scaled_inplane.values()) or scaled_pin_y:
            raise ValueError("--a-x, --a-y are the dimensionless amplitudes (and --alpha-y, "
                             "--zeta-y dimensionless): a physical set-up takes --du-x, --du-y "
                             "(m), --k-y, --c-y")
        if v0 is None:
            raise ValueError("a physical set-up needs the velocity --v0 (m/s)")
        system = physical.to_dimensionless()
        results = cast(FrictionResults,  # v0 is a 1-d array
                       friction_coefficient(physical, v0=np.array(parse_list(v0, "v0")),
                                            initial=initial, settings=settings))
    else:
        missing = [f"--{n}" for n, v in (("alpha", alpha), ("beta", beta),
                                         ("amplitude", amplitude)) if v is None]
        if missing:
            raise ValueError("missing " + ", ".join(missing) + " (or give a physical set-up)")
        assert alpha is not None and beta is not None and amplitude is not None  # none missing
        system = Dimensionless(parse_float(alpha, "alpha"), parse_float(beta, "beta"),
                               parse_float(amplitude, "amplitude"), parse_float(zeta, "zeta"),
                               parse_float(eta_c, "eta_c"), **scaled_inplane, **inplane,
                               **scaled_pin_y, profile_exponent=exponent)
        if any(v != 0.0 for v in si_inplane.values()) or si_pin_y:
            raise ValueError("--du-x, --du-y (m) need a physical set-up, as do --k-y, --c-y: "
                             "the dimensionless system takes --a-x, --a-y, --alpha-y, "
                             "--zeta-y")
        results = _dimensionless(system, vbar, v_inertial, initial, settings)
    _print(system, results, as_json)
    exit_if_untrusted([r.trusted for r in results], settings.tol_trusted)


def _physical(phys: dict, c_x: str, c_xc: str, quality_factor: str | None,
              dimensionless: tuple, **inplane) -> Physical:
    if any(v is not None for v in dimensionless):
        raise ValueError("give either the dimensionless system or the physical set-up")
    missing = ["--" + k.replace("_", "-") for k, v in phys.items() if v is None]
    if missing:
        raise ValueError("a physical set-up needs " + ", ".join(missing))
    values: dict[str, Any] = {k: parse_float(v, k) for k, v in phys.items()}
    system = Physical(**values, c_x=parse_float(c_x, "c_x"), c_xc=parse_float(c_xc, "c_xc"),
                      **inplane)
    if quality_factor is not None:
        if system.c_x != 0.0:
            raise ValueError("give either --c-x or --quality-factor")
        system = system.with_damping(
            quality_factor=parse_float(quality_factor, "quality_factor"))
    return system


def _dimensionless(system: Dimensionless, vbar: str | None, v_inertial: str | None,
                   initial: str, settings: SolverSettings) -> FrictionResults:
    speeds = {name: None if text is None else np.array(parse_list(text, name))
              for name, text in (("vbar", vbar), ("v_inertial", v_inertial))}
    # the velocities are 1-d arrays: the results are FrictionResults
    return cast(FrictionResults, friction_coefficient(system, **speeds, initial=initial,
                                                      settings=settings))


def _json_value(v):
    if isinstance(v, float):
        return json_number(v)
    if isinstance(v, dict):
        return {k: _json_value(x) for k, x in v.items()}
    return v


def json_row(r: FrictionResult) -> dict:
    """Every field of a result (:data:`vibrofriction.schema.RESULT_FIELDS`, JSON-safe:
    nan as null, inf as "inf"; ``system`` as every parameter of the schema's
    dimensionless model), its ``vbar`` and its message."""
    row = {k: _json_value(v) for k, v in r.as_dict().items()}
    row["system"] = {n: json_number(getattr(r.system, n))
                     for n in parameter_names("dimensionless")}
    row["system"].update({n: getattr(r.system, n) for n in choice_names("dimensionless")})
    row["vbar"] = json_number(r.vbar)
    row["message"] = r.message
    return row


def _print(system: Dimensionless, results, as_json: bool) -> None:
    if not as_json:
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
        typer.echo(f"alpha={system.alpha:g} beta={system.beta:g} amplitude={system.amplitude:g}"
                   f"{damping}{inplane}{profile} case {system.case.value}")
        lateral = system.a_y > 0  # the 2-D solver: the mean force across the sliding too
        typer.echo(f"{'vbar':>10} {'v_inertial':>12} {'mu/mu0':>14} "
                   + (f"{'lateral':>14} " if lateral else "") + f"{'error':>9}  status")
    for r in results:
        if as_json:
            typer.echo(json.dumps(json_row(r)))
        else:
            typer.echo(f"{r.vbar:>10.4g} {r.v_inertial:>12.5g} {r.mu_ratio:>14.10f} "
                       + (f"{r.lateral_ratio:>14.10f} " if lateral else "")
                       + f"{r.error:>9.1e}  {r.status.value}"
                       + (f" (period {r.period})" if r.period else "")
                       + ("" if r.trusted else "  NOT TRUSTED"))
