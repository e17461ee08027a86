"""``vibrofriction mu``: the coefficient of friction at one or several velocities."""

from __future__ import annotations

import json
from typing import Annotated

import numpy as np
import typer

from ..params import Dimensionless
from ..solver import SolverSettings, friction_coefficient
from ._app import app, exit_if_untrusted, friendly, json_number, parse_float, parse_list


@app.command("mu")
@friendly
def mu_command(
    alpha: Annotated[str, typer.Option(help="alpha = k_x/(m omega^2), eq. (20); > 0")],
    beta: Annotated[str, typer.Option(help="beta = (k_x + k_xc)/(m omega^2) > alpha; 'inf' = "
                                      "rigid contact")],
    amplitude: Annotated[str, typer.Option(help="a = du_z/u_z0 >= 0 (> 1: jumping)")],
    vbar: Annotated[str | None, typer.Option(help="v0/v0* (eq. 16); comma-separated list "
                                             "allowed")] = None,
    v_inertial: Annotated[str | None, typer.Option(
        "--v-inertial", help="v0 m omega/(mu0 F_N0) (Fig. 6; needed in cases III, IV); "
        "list allowed")] = None,
    initial: Annotated[str, typer.Option(help="initial state: sliding or rest")] = "sliding",
    max_periods: Annotated[int, typer.Option(help="give up after this many periods")] = 20000,
    tol_trusted: Annotated[float, typer.Option(
        help="largest error of a trusted point; exit code 3 if any point is not trusted")
    ] = SolverSettings.tol_trusted,
    as_json: Annotated[bool, typer.Option("--json", help="one JSON object per point")] = False,
) -> None:
    """Macroscopic coefficient of friction mu/mu0 in the steady state (eq. 25)."""
    system = Dimensionless(parse_float(alpha, "alpha"), parse_float(beta, "beta"),
                           parse_float(amplitude, "amplitude"))
    if (vbar is None) == (v_inertial is None):
        raise ValueError("give exactly one of --vbar and --v-inertial")
    settings = SolverSettings(max_periods=max_periods, tol_trusted=tol_trusted)
    if vbar is not None:
        speeds = np.array(parse_list(vbar, "vbar"))
        results = friction_coefficient(system, vbar=speeds, initial=initial, settings=settings)
    else:
        speeds = np.array(parse_list(v_inertial, "v_inertial"))
        results = friction_coefficient(system, v_inertial=speeds, initial=initial,
                                       settings=settings)
    if not as_json:
        typer.echo(f"alpha={system.alpha:g} beta={system.beta:g} amplitude={system.amplitude:g} "
                   f"case {system.case.value}")
        typer.echo(f"{'vbar':>10} {'v_inertial':>12} {'mu/mu0':>14} {'error':>9}  status")
    for r in results:
        if as_json:
            typer.echo(json.dumps({
                "alpha": json_number(system.alpha), "beta": json_number(system.beta),
                "amplitude": system.amplitude, "vbar": json_number(r.vbar),
                "v_inertial": r.v_inertial, "mu_ratio": json_number(r.mu_ratio),
                "status": r.status.value, "period": r.period, "error": json_number(r.error),
                "trusted": r.trusted, "multiplier": json_number(r.multiplier),
                "settling_periods": json_number(r.settling_periods),
                "periods": r.periods, "events": r.events,
                "stick_fraction": json_number(r.stick_fraction),
                "slip_fraction": json_number(r.slip_fraction),
                "flight_fraction": json_number(r.flight_fraction),
                "message": r.message}))
        else:
            typer.echo(f"{r.vbar:>10.4g} {r.v_inertial:>12.5g} {r.mu_ratio:>14.10f} "
                       f"{r.error:>9.1e}  {r.status.value}"
                       + (f" (period {r.period})" if r.period else "")
                       + ("" if r.trusted else "  NOT TRUSTED"))
    exit_if_untrusted([r.trusted for r in results], settings.tol_trusted)
