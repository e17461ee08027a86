"""The Typer application shared by the command modules, and its error handling."""

from __future__ import annotations

import functools
import math
import sys
from collections.abc import Callable
from typing import Any

import numpy as np
import typer

app = typer.Typer(
    name="vibrofriction",
    help="Friction under normal oscillations (Mao, Popov, Starcevic, Popov 2017).",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
)


def friendly(func: Callable[..., Any]) -> Callable[..., Any]:
    """Turn a ``ValueError``/``TypeError`` from the library into one line and exit 2."""

    @functools.wraps(func)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        try:
            return func(*args, **kwargs)
        except (ValueError, TypeError) as exc:
            print(f"error: {exc}", file=sys.stderr)
            raise typer.Exit(2) from None

    return wrapper


UNTRUSTED_EXIT = 3  # exit code when any computed point is not trusted


def exit_if_untrusted(trusted: Any, tol_trusted: float) -> None:
    """One line on stderr and exit 3 when any point is not trusted (``SolverSettings``)."""
    flags = np.asarray(trusted, dtype=bool)
    bad = int(flags.size - np.count_nonzero(flags))
    if bad:
        print(f"warning: {bad} of {flags.size} points are not trusted (status not converged "
              f"or error > tol_trusted = {tol_trusted:g}); exit code {UNTRUSTED_EXIT}",
              file=sys.stderr)
        raise typer.Exit(UNTRUSTED_EXIT)


def parse_float(text: str, name: str) -> float:
    """A float from the command line; ``inf`` is accepted."""
    try:
        return float(text)
    except ValueError:
        raise ValueError(f"{name} must be a number, got {text!r}") from None


def parse_list(text: str, name: str) -> list[float]:
    """A comma-separated list of floats (``0.1,0.2,0.5``)."""
    items = [t.strip() for t in text.split(",") if t.strip()]
    if not items:
        raise ValueError(f"{name} must be a number or a comma-separated list, got {text!r}")
    return [parse_float(t, name) for t in items]


def json_number(x: float | None) -> float | str | None:
    """JSON has no inf/nan: encode them as strings (inf) or null (nan, and None: an
    optional parameter left to its twin, ``alpha_y``)."""
    if x is None or math.isnan(x):
        return None
    if math.isinf(x):
        return "inf" if x > 0 else "-inf"
    return x


def _print_version(value: bool) -> None:
    if value:
        from .. import __version__

        print(f"vibrofriction {__version__}")
        raise typer.Exit()


@app.callback()
def _root(
    version: bool = typer.Option(False, "--version", callback=_print_version, is_eager=True,
                                 help="Print the version and exit."),
) -> None:
    """Friction under normal oscillations: exact steady states, the paper's figures, atlases."""
