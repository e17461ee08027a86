"""The ``vibrofriction`` command line: a thin shell over the library.

Each sub-command lives in its own module as a :class:`~._app.Command`: its options are
rows of one table made from the schema (:mod:`._options`), and it imports the heavy
modules (the solver, the figures, the sweep) only when it runs, so that
``vibrofriction --help`` starts fast.  Built on argparse: every error is one line on
stderr with exit code 2.
"""

from __future__ import annotations

import sys
from collections.abc import Sequence

from . import bench, explore, mu, reproduce, sweep, warmup
from ._app import (
    USAGE_EXIT,
    Command,
    Exit,
    Formatter,
    Parser,
    UsageError,
    add_options,
    checked,
    glue,
    one_line,
    value_flags,
)

#: Every sub-command, in the order of ``vibrofriction --help``.
COMMANDS: tuple[Command, ...] = (mu.COMMAND, sweep.COMMAND, sweep.PLOT, reproduce.COMMAND,
                                 bench.FIT, bench.DESIGN, explore.COMMAND, warmup.COMMAND)
DESCRIPTION = ("Friction under normal oscillations (Mao, Popov, Starcevic, Popov 2017): "
               "exact steady states, the paper's figures, atlases.")


def build_parser() -> Parser:
    """The argparse parser of every command (text values, checked by :func:`run`)."""
    parser = Parser(prog="vibrofriction", description=DESCRIPTION, allow_abbrev=False,
                    formatter_class=Formatter)
    parser.add_argument("--version", action="store_true", help="print the version and exit")
    subs = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=Parser)
    for command in COMMANDS:
        sub = subs.add_parser(command.name, help=command.help, description=command.description,
                              allow_abbrev=False, formatter_class=Formatter)
        add_options(sub, command.options)
    return parser


def run(argv: Sequence[str] | None = None) -> int:
    """Run the command line ``argv`` (default ``sys.argv[1:]``); the exit code."""
    argv = list(sys.argv[1:] if argv is None else argv)
    parser = build_parser()
    try:
        if argv and argv[0].startswith("-") and argv[0] not in ("-h", "--help", "--version"):
            raise UsageError(f"vibrofriction: unknown option {argv[0].partition('=')[0]} "
                             "(see vibrofriction --help)")
        ns, extras = parser.parse_known_args(glue(argv, value_flags(COMMANDS)))
        if extras:
            prog = "vibrofriction" + (f" {ns.command}" if ns.command else "")
            first = extras[0].partition("=")[0]
            what = "unknown option" if first.startswith("-") else "unexpected argument"
            raise UsageError(f"{prog}: {what} {first} (see {prog} --help)")
        if ns.version:
            from importlib.metadata import PackageNotFoundError, version

            try:
                print(f"vibrofriction {version('vibrofriction')}")
            except PackageNotFoundError:  # pragma: no cover - a source tree not installed
                print("vibrofriction 0+unknown")
            return 0
        if ns.command is None:
            parser.print_help()
            return 0
        command = next(c for c in COMMANDS if c.name == ns.command)
        command.run(checked(ns, command.options))
    except Exit as done:
        return done.code
    except UsageError as err:
        print(f"error: {one_line(str(err))}", file=sys.stderr)
        return USAGE_EXIT
    except (ValueError, TypeError) as err:  # bad input found by the library
        print(f"error: {one_line(str(err))}", file=sys.stderr)
        return USAGE_EXIT
    except SystemExit as done:  # --help
        return done.code if isinstance(done.code, int) else 0
    return 0


def main() -> None:
    """Console-script entry point."""
    sys.exit(run())


__all__ = ["COMMANDS", "build_parser", "main", "run"]
