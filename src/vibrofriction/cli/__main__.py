"""``python -m vibrofriction.cli``."""

from . import main

main()
