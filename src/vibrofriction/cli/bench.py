"""``vibrofriction fit`` and ``vibrofriction design``: from the bench to the model and back
(docs/bench.md).  The pin is described by a bench file (JSON, ``vf.from_bench``)."""

from __future__ import annotations

import math
import re
from pathlib import Path
from typing import Annotated

import typer

from ..contact import FlatPunch, Sphere
from ..figures import plot_design, plot_fit
from ._app import app, friendly, parse_float


def _fixes(text: str | None) -> dict[str, float]:
    """``name=value,name=value``: fields of the guess to set before fitting."""
    if not text:
        return {}
    out = {}
    for item in text.split(","):
        name, sep, value = item.partition("=")
        if not sep:
            raise ValueError(f"--fix takes name=value pairs, got {item!r}")
        out[name.strip()] = parse_float(value, name.strip())
    return out


def _range(text: str, name: str, scale: float = 1.0) -> tuple[float, float]:
    lo, sep, hi = text.partition(":")
    if not sep:
        raise ValueError(f"{name} takes low:high, got {text!r}")
    return parse_float(lo, name) * scale, parse_float(hi, name) * scale


@app.command("fit")
@friendly
def fit_command(
    data: Annotated[str, typer.Argument(help="measurement table (CSV, docs/bench.md)")],
    bench: Annotated[str, typer.Option(help="bench file (JSON): the guess")],
    free: Annotated[str | None, typer.Option(
        help="fields to fit, comma-separated (default mu0,mass,k_xc,u_z0; with a curved "
             "MDR contact in the bench file mu0,mass,radius, or E_star for a cone or a "
             "power law)")] = None,
    fix: Annotated[str | None, typer.Option(
        help="fields of the guess to set first: name=value,...")] = None,
    natural_frequency: Annotated[bool, typer.Option(
        help="keep k_x/m (the measured natural frequency)")] = True,
    normal_load: Annotated[bool, typer.Option(help="keep k_zc u_z0 = F_N0")] = True,
    quality_factor: Annotated[bool, typer.Option(help="keep the pin's damping ratio")] = True,
    workers: Annotated[int, typer.Option(
        help="processes for the global stage, the local starts and the profiles "
             "(-1: every core)")] = -1,
    out: Annotated[str, typer.Option(help="folder for report.txt, fit.png, fit.json")] = "fit",
    progress: Annotated[bool, typer.Option(help="progress bars on stderr")] = True,
) -> None:
    """Fit the model to measured friction curves (report, figure, JSON)."""
    from ..bench import fit, from_bench_file, read_bench_file

    guess = from_bench_file(bench)
    # a curved (MDR) contact is fitted through its geometry (docs/bench.md, "Fit and design
    # with a curved contact"): the bench file's contact goes to the fit
    contact = read_bench_file(bench).get("contact") if guess.curved else None
    if free is None:
        free = ("mu0,mass,k_xc,u_z0" if contact is None
                else "mu0,mass," + ("radius" if isinstance(contact, Sphere | FlatPunch)
                                    else "E_star"))
    if fix:
        guess = guess.with_(**_fixes(fix))
    try:
        res = fit(data, guess, free=[f.strip() for f in free.split(",") if f.strip()],
                  natural_frequency=natural_frequency, normal_load=normal_load,
                  quality_factor=quality_factor, workers=workers, progress=progress,
                  **({} if contact is None else {"contact": contact}))
    except ValueError as err:  # name the command line's flag, not the Python keyword
        raise ValueError(re.sub(r"\b(natural_frequency|normal_load|quality_factor)=False",
                                lambda m: "--no-" + m.group(1).replace("_", "-"),
                                str(err))) from err
    folder = Path(out)
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "report.txt").write_text(res.report() + "\n")
    plot_fit(res).savefig(folder / "fit.png", dpi=150)
    res.to_json(folder / "fit.json")
    typer.echo(res.report())
    typer.echo(f"-> {folder}/report.txt, fit.png, fit.json")


@app.command("design")
@friendly
def design_command(
    bench: Annotated[str, typer.Option(help="bench file (JSON): the pin")],
    v0: Annotated[str, typer.Option(help="operating sliding velocity, m/s")],
    frequency_hz: Annotated[str, typer.Option(
        "--frequency-hz", help="drive frequency range low:high, Hz")],
    du_z: Annotated[str, typer.Option(
        "--du-z", help="amplitude range low:high, m (low may be 0: no oscillation)")],
    max_velocity_amplitude: Annotated[str | None, typer.Option(
        "--max-velocity-amplitude",
        help="limit of omega * du_z (with --du-x: of the velocity rule), m/s")] = None,
    du_x: Annotated[str | None, typer.Option(
        "--du-x", help="in-plane (longitudinal) amplitude range low:high, m")] = None,
    phase_x: Annotated[str | None, typer.Option(
        "--phase-x", help="fixed in-plane phase, rad (default: optimised)")] = None,
    du_y: Annotated[str | None, typer.Option(
        "--du-y", help="transverse amplitude range low:high, m (the 2-D solver; friction "
        "goal only)")] = None,
    phase_y: Annotated[str | None, typer.Option(
        "--phase-y", help="fixed transverse phase, rad (default: optimised)")] = None,
    inplane_on: Annotated[str | None, typer.Option(
        "--inplane-on", help="substrate or holder (default: the bench file's)")] = None,
    goal: Annotated[str, typer.Option(help="friction (smallest |COF|) or drive")] =
    "friction",
    velocity_rule: Annotated[str, typer.Option(
        "--velocity-rule", help="combined (omega sqrt(du_z^2 + du_x^2)) or each")] =
    "combined",
    out: Annotated[str, typer.Option(help="folder for report.txt, map.png, map.zarr")] =
    "design",
) -> None:
    """The oscillation that minimises friction at v0 within the actuator's limits, or
    with --goal drive maximises the drive force (needs --du-x); the report's status line
    counts the untrusted points of the map."""
    from ..bench import design, from_bench_file

    pin = from_bench_file(bench)
    res = design(pin, v0=parse_float(v0, "v0"),
                 omega=_range(frequency_hz, "frequency_hz", 2.0 * math.pi),
                 du_z=_range(du_z, "du_z"),
                 max_velocity_amplitude=None if max_velocity_amplitude is None else
                 parse_float(max_velocity_amplitude, "max_velocity_amplitude"),
                 du_x=None if du_x is None else _range(du_x, "du_x"),
                 phase_x=None if phase_x is None else parse_float(phase_x, "phase_x"),
                 inplane_on=inplane_on, goal=goal, velocity_rule=velocity_rule,
                 du_y=None if du_y is None else _range(du_y, "du_y"),
                 phase_y=None if phase_y is None else parse_float(phase_y, "phase_y"))
    folder = Path(out)
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "report.txt").write_text(res.report() + "\n")
    plot_design(res).savefig(folder / "map.png", dpi=150)
    res.map.to_zarr(folder / "map.zarr", mode="w", consolidated=False)
    typer.echo(res.report())
    typer.echo(f"-> {folder}/report.txt, map.png, map.zarr")
