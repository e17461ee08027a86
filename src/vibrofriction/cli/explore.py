"""``vibrofriction explore``: the interactive explorer in the browser (docs/explorer.md)."""

from __future__ import annotations

from typing import Annotated

import typer

from ._app import app


@app.command("explore")
def explore_command(
    port: Annotated[int, typer.Option(help="port of the local server (127.0.0.1)")] = 5006,
    show: Annotated[bool, typer.Option(help="open the browser")] = True,
) -> None:
    """Explore friction curves, time histories and the cases in the browser."""
    from ..explorer import serve

    serve(port=port, show=show)
