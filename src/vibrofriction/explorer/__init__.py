"""The interactive browser explorer (``vibrofriction explore``; docs/explorer.md).

``app()`` is the page as a Panel object (a notebook: ``pn.extension()``, then
``vibrofriction.explorer.app()``); ``serve(port, show)`` runs it on a local server.
Panel is imported on first use, so ``import vibrofriction`` stays light.
"""

from __future__ import annotations

from typing import Any

__all__ = ["app", "serve"]


def app(state: Any = None) -> Any:
    """The explorer as a Panel object (``state``: a :class:`.state.State`, else the URL's)."""
    from .page import app as _app

    return _app(state)


def serve(port: int = 5006, show: bool = True) -> None:
    """Serve the explorer at ``http://127.0.0.1:port/`` until interrupted."""
    from .server import serve as _serve

    _serve(port, show)
