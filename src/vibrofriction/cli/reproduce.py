"""``vibrofriction reproduce``: every figure of the paper, its data and a checked report."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from ..report import reproduce
from ._app import app, friendly


@app.command("reproduce")
@friendly
def reproduce_command(
    out: Annotated[Path, typer.Option("--out", help="output folder (created)")] = Path(
        "reproduction"),
    quick: Annotated[bool, typer.Option("--quick", help="reduced grids (CI)")] = False,
    workers: Annotated[int | None, typer.Option(
        help="processes for solving and rendering (default: min(2, CPUs)); results do not "
        "depend on it")] = None,
    progress: Annotated[bool, typer.Option(help="show progress bars")] = True,
    only: Annotated[list[str] | None, typer.Option(
        help="run only the figures whose names start with this (repeatable), e.g. fig04")
    ] = None,
) -> None:
    """Regenerate every figure of the paper (PNG + PDF), its data (CSV) and report.md."""
    if workers is not None and workers < 1:
        raise ValueError(f"workers must be >= 1, got {workers}")
    result = reproduce(out, quick=quick, workers=workers, progress=progress,
                       only=only or None)
    figures = sum(1 for f in result.files if f.suffix == ".png")
    typer.echo(f"{figures} figures, {len(result.files)} files, {result.points} steady states "
               f"in {result.seconds:.1f} s -> {result.report}")
    if result.untrusted:
        typer.echo(f"note: {result.untrusted} points did not converge or are untrusted "
                   "(open circles; see report.md)")
    if result.suspicious:
        typer.echo(f"warning: {len(result.suspicious)} solver results look wrong "
                   "(listed in report.md)")
