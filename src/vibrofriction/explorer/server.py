"""Serve the explorer on a local Bokeh server (``vibrofriction explore``)."""

from __future__ import annotations

__all__ = ["serve"]


def serve(port: int = 5006, show: bool = True) -> None:
    """Serve the explorer at ``http://127.0.0.1:port/`` until interrupted."""
    import signal
    import sys

    import panel as pn

    from ..warmup import warm_up
    from . import pool
    from .page import app

    signal.signal(signal.SIGTERM, lambda *_: sys.exit(0))  # stop the workers too
    print("vibrofriction explorer: starting (loading the solver's kernels) ...", flush=True)
    # compiled once (with progress; on a cold start the curved tip's kernels beside the flat
    # punch's, no longer in wall time), then loaded by each worker
    warm_up(("flat", "curved", "histories"))
    pool.warm_up()
    pn.extension()
    print(f"vibrofriction explorer: http://127.0.0.1:{port}/  (Ctrl-C stops it)", flush=True)
    try:
        pn.serve(app, port=port, address="127.0.0.1", show=show, title="vibrofriction explorer",
                 websocket_origin=[f"127.0.0.1:{port}", f"localhost:{port}"],
                 threaded=False, print_url=False)
    finally:
        pool.shutdown()
