"""The ``vibrofriction`` command line: a thin shell over the library.

Each sub-command lives in its own module and registers itself on :data:`app`.
"""

from . import bench as _bench  # noqa: F401  (registers fit, design)
from . import explore as _explore  # noqa: F401  (registers explore)
from . import mu  # noqa: F401  (registers the command)
from . import reproduce as _reproduce  # noqa: F401  (registers reproduce)
from . import sweep as _sweep  # noqa: F401  (registers sweep, plot)
from ._app import app


def main() -> None:
    """Console-script entry point."""
    app()


__all__ = ["app", "main"]
