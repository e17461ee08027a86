"""``vibrofriction explore``: the interactive explorer in the browser (docs/explorer.md)."""

from __future__ import annotations

from ._app import Args, Command
from ._options import INT, Opt


def run(a: Args) -> None:
    """Serve the explorer (panel is imported here)."""
    from ..explorer import serve

    serve(port=a["port"], show=a["show"])


COMMAND = Command(
    "explore", "explore friction curves in the browser",
    "Explore friction curves, time histories and the cases in the browser.",
    (Opt("port", "port of the local server (127.0.0.1)", kind="int", default=5006,
         metavar=INT),
     Opt("show", "open the browser", kind="flag", default=True)),
    run)
