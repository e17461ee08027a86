"""``python -m vibrofriction``: the command line (``vibrofriction.cli``)."""

from .cli import main

main()
