"""The interactive browser explorer (``vibrofriction explore``; docs/explorer.md).

``app()`` is the page as a Panel object (a notebook: ``pn.extension()``, then
``vibrofriction.explorer.app()``); ``serve(port, show)`` runs it on a local server.
Panel is imported on first use, so ``import vibrofriction`` stays light.
"""

from __future__ import annotations

from typing import Any

__all__ = ["app", "serve"]


def app(state: Any = None) -> Any:
    """The explorer as a Panel object, to show in a notebook or serve.

    Parameters
    ----------
    state : vibrofriction.explorer.state.State, optional
        The inputs to start from; None
        (default): those of the page's URL, else the defaults.

    Returns
    -------
    panel.layout.Row
        The page: the inputs, the friction curve and the views of a point.

    Examples
    --------
    Building the page starts the explorer's worker processes and solves its first
    curve, so it is not run with the API's doctests:

    >>> from vibrofriction.explorer import app
    >>> from vibrofriction.explorer.state import State
    >>> page = app(State())  # doctest: +SKIP
    >>> type(page).__name__  # doctest: +SKIP
    'Row'
    """
    from .page import app as _app

    return _app(state)


def serve(port: int = 5006, show: bool = True) -> None:
    """Serve the explorer at ``http://127.0.0.1:port/`` until interrupted.

    The command ``vibrofriction explore`` calls it.

    Parameters
    ----------
    port : int, optional
        The local port.
    show : bool, optional
        Open the page in the default browser.

    Examples
    --------
    It runs until Ctrl-C, so it is not run with the API's doctests:

    >>> from vibrofriction.explorer import serve
    >>> serve(port=5006, show=False)  # doctest: +SKIP
    """
    from .server import serve as _serve

    _serve(port, show)
