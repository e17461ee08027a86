"""``vibrofriction reproduce``: every figure of the paper, its data and a checked report."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from ..report import recipes, reproduce
from ._app import app, friendly


@app.command("reproduce")
@friendly
def reproduce_command(
    out: Annotated[Path, typer.Option("--out", help="output folder (created)")] = Path(
        "reproduction"),
    quick: Annotated[bool, typer.Option("--quick", help="reduced grids (CI)")] = False,
    workers: Annotated[int | None, typer.Option(
        help="processes for solving and rendering, >= 1 (default: min(2, cores); 1 = this "
        "process only); results do not depend on it")] = None,
    progress: Annotated[bool, typer.Option(help="show progress bars")] = True,
    only: Annotated[list[str] | None, typer.Option(
        help="run only the figures whose names start with this (repeatable), e.g. fig04")
    ] = None,
) -> None:
    """Regenerate every figure of the paper (PNG + PDF), its data (CSV) and report.md."""
    from ..parallel import check_workers

    if workers is not None:
        check_workers(workers, "--workers")
    if only:
        _check_only(only, quick)
    result = reproduce(out, quick=quick, workers=workers, progress=progress,
                       only=only or None)
    figures = sum(1 for f in result.files if f.suffix == ".png")
    typer.echo(f"{figures} figures, {len(result.files)} files, {result.points} steady states "
               f"in {result.seconds:.1f} s -> {result.report}")
    if result.untrusted:
        typer.echo(f"note: {result.untrusted} points are not trusted (drawn as open circles, "
                   "or as bars over the window means where the motion did not settle; "
                   "see report.md)")
    if result.suspicious:
        typer.echo(f"note: {len(result.suspicious)} of them have a converged status but an "
                   "error estimate above tol_trusted (listed in report.md)")


def _check_only(only: list[str], quick: bool) -> None:
    """ValueError naming ``--only`` and the figure names if a prefix matches nothing."""
    names = [r.name for r in recipes(quick)]
    unknown = [o for o in only if not any(n.startswith(o) for n in names)]
    if unknown:
        raise ValueError(f"--only {', '.join(map(repr, unknown))} matches no figure; "
                         f"names: {', '.join(names)}")
