"""The command line's machinery.

Argparse parsers built from the option table, values checked against the schema, one-line errors and
the exit codes.

Exit codes: 0 success, 2 bad input (one line on stderr), 3 some computed point is not
trusted (one line counting them on stderr).  Standard library only (and the schema,
through :mod:`._options`): ``vibrofriction --help`` imports nothing heavy.
"""

from __future__ import annotations

import argparse
import math
import re
import sys
import textwrap
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from typing import Any, NoReturn

from ._options import Opt, check_value, flag, plain

UNTRUSTED_EXIT = 3  # exit code when any computed point is not trusted
USAGE_EXIT = 2  # exit code for bad input


class Exit(Exception):  # noqa: N818  (not an error: the way out with a code)
    """Leave the command with ``code`` (after the command printed its message)."""

    def __init__(self, code: int) -> None:
        super().__init__(code)
        self.code = code


class UsageError(Exception):
    """Bad input: printed as one line, exit 2."""


@dataclass(frozen=True)
class Command:
    """A sub-command: its name, help, description, options and the function that runs it.

    The help is one line; heavy imports happen inside the function.
    """

    name: str
    help: str
    description: str
    options: tuple[Opt, ...]
    run: Callable[[Args], None]

    def flags(self) -> set[str]:
        """Every option string of the command (``--progress`` and ``--no-progress``)."""
        out: set[str] = set()
        for o in self.options:
            if not o.positional:
                out.update(o.flags or (o.flag,))
                if o.kind == "flag" and o.negatable:
                    out.add("--no-" + o.flag[2:])
        return out


class Args:
    """The checked values of a command line.

    ``args["alpha"]`` is the value given or the option's default; ``args.given`` only what was
    given.
    """

    def __init__(self, given: dict[str, Any], options: Sequence[Opt]) -> None:
        self.given = given
        self.defaults = {o.name: o.default for o in options}

    def __getitem__(self, name: str) -> Any:
        return self.given[name] if name in self.given else self.defaults[name]

    def has(self, name: str) -> bool:
        return name in self.given


# --------------------------------------------------------------------------- messages
_REPRS = ((re.compile(r"np\.(?:float|int)\d*\(([^()]*)\)"), r"\1"),
          (re.compile(r"\bmath\.inf\b"), "inf"),
          (re.compile(r"\bmath\.nan\b"), "nan"))


def one_line(message: str) -> str:
    """A message from the library as one plain line: no Python reprs of numbers."""
    for pattern, repl in _REPRS:
        message = pattern.sub(repl, message)
    return " ".join(message.split())


def exit_if_untrusted(trusted: Any, tol_trusted: float) -> None:
    """One line on stderr and exit 3 when any point is not trusted (``SolverSettings``)."""
    flags = [bool(t) for t in trusted]
    bad = flags.count(False)
    if bad:
        print(f"warning: {bad} of {len(flags)} points are not trusted (status not converged "
              f"or error > tol_trusted = {tol_trusted:g}); exit code {UNTRUSTED_EXIT}",
              file=sys.stderr)
        raise Exit(UNTRUSTED_EXIT)


def json_number(x: float | None) -> float | str | None:
    """JSON has no inf/nan.

    Encode them as strings (inf) or null (nan, and None: an optional parameter left to its twin,
    ``alpha_y``).
    """
    if x is None or math.isnan(x):
        return None
    if math.isinf(x):
        return "inf" if x > 0 else "-inf"
    return float(x)


# --------------------------------------------------------------------------- values
def parse_float(text: str, name: str) -> float:
    """A float from the command line; ``inf`` is accepted."""
    try:
        return float(text)
    except ValueError:
        raise ValueError(f"{name} must be a number, got {text.strip() or 'nothing'}") from None


def parse_list(text: str, name: str) -> list[float]:
    """A comma-separated list of floats (``0.1,0.2,0.5``); an empty item is refused."""
    items = [t.strip() for t in text.split(",")]
    if any(not t for t in items):
        raise ValueError(f"{name} takes a number or a comma-separated list of numbers "
                         f"without empty items, got {text.strip() or 'nothing'}")
    return [parse_float(t, name) for t in items]


def _convert(opt: Opt, text: Any, given: dict[str, Any]) -> Any:
    name = opt.flag
    if opt.kind == "float":
        value: Any = parse_float(text, name)
        values = [value]
    elif opt.kind == "list":
        value = values = parse_list(text, name)
    elif opt.kind == "int":
        try:
            value = int(text)
        except ValueError:
            raise ValueError(f"{name} must be an integer, got {text}") from None
        values = [float(value)]
    elif opt.kind == "choice":
        if text not in opt.choices:
            raise ValueError(f"{name} must be one of {', '.join(opt.choices)}, got {text}")
        return text
    elif opt.kind == "axis":
        if re.search(r"(^|,)\s*,", text):  # 0.3,,0.4 (a trailing comma is an axis)
            raise ValueError(f"{name} has an empty item in its list: {text}")
        return text  # the sweep parses it; check_axis checks its values
    else:
        return text
    rng = opt.allowed
    if rng is not None:
        above = None
        if rng.above and isinstance(given.get(rng.above), float):
            above = (flag(rng.above), given[rng.above])
        for v in values:
            check_value(name, rng, v, above, opt.name)
    return value


def check_axis(opt: Opt, values: Any) -> None:
    """Each value of a parsed sweep axis within the option's range (ValueError)."""
    if opt.allowed is not None:
        for v in [values] if isinstance(values, float | int) else list(values):
            check_value(opt.flag, opt.allowed, float(v), name=opt.name)


def _nonzero(value: Any) -> bool:
    if isinstance(value, list):
        return any(v != 0.0 for v in value)
    if isinstance(value, float | int):
        return value != 0
    return value is not None  # an axis or text: given is enough


def checked(namespace: argparse.Namespace, options: Sequence[Opt]) -> Args:
    """The given values converted and checked (range, choices, dependencies)."""
    given: dict[str, Any] = {}
    for opt in options:  # the schema's order: alpha comes before beta > alpha
        text = getattr(namespace, opt.name, None)
        if text is None:
            continue
        if opt.kind == "flag":
            given[opt.name] = bool(text)
        elif opt.repeat:
            given[opt.name] = [_convert(opt, t, given) for t in text]
        else:
            given[opt.name] = _convert(opt, text, given)
    missing = [o.metavar if o.positional else o.flag for o in options
               if (o.required or o.positional) and o.name not in given]
    if missing:
        raise UsageError("missing " + ", ".join(missing))
    known = {o.name for o in options}
    for opt in options:
        if opt.name in given and opt.requires:
            if not any(_nonzero(given.get(r)) for r in opt.requires if r in known):
                need = " or ".join(flag(r) for r in opt.requires if r in known)
                raise ValueError(f"{opt.flag} needs {need} (nonzero); "
                                 "without it it would be ignored")
    return Args(given, options)


# --------------------------------------------------------------------------- parsers
class Formatter(argparse.HelpFormatter):
    """Whole words wrapped at the terminal's width; paragraphs of a description kept."""

    def __init__(self, prog: str) -> None:
        super().__init__(prog, max_help_position=32)

    def _fill_text(self, text: str, width: int, indent: str) -> str:
        paragraphs = [" ".join(p.split()) for p in text.strip().split("\n\n")]
        return "\n\n".join(textwrap.fill(p, width, initial_indent=indent,
                                         subsequent_indent=indent,
                                         break_long_words=False, break_on_hyphens=False)
                           for p in paragraphs)

    def _split_lines(self, text: str, width: int) -> list[str]:
        return textwrap.wrap(" ".join(text.split()), width, break_long_words=False,
                             break_on_hyphens=False)


class Parser(argparse.ArgumentParser):
    """An ArgumentParser whose errors are one line (raised, printed by :func:`run`)."""

    def error(self, message: str) -> NoReturn:
        message = message.replace("'", "")
        command = re.match(r"argument COMMAND: invalid choice: (\S+) \(choose from (.*)\)",
                           message)
        if command:
            message = f"unknown command {command.group(1)} (one of {command.group(2)})"
        raise UsageError(f"{self.prog}: {message} (see {self.prog} --help)")


class _OnOff(argparse.Action):
    """``--progress`` / ``--no-progress`` for one boolean."""

    def __init__(self, option_strings: list[str], dest: str, **kwargs: Any) -> None:
        super().__init__(option_strings, dest, nargs=0, **kwargs)

    def __call__(self, parser: argparse.ArgumentParser, namespace: argparse.Namespace,
                 values: Any, option_string: str | None = None) -> None:
        setattr(namespace, self.dest, not (option_string or "").startswith("--no-"))


def add_options(parser: argparse.ArgumentParser, options: Sequence[Opt]) -> None:
    """The table's rows as argparse arguments (every value is text until checked)."""
    groups: dict[str, Any] = {"": parser}
    for opt in options:
        if opt.group not in groups:
            groups[opt.group] = parser.add_argument_group(opt.group)
    for opt in options:
        parser = groups[opt.group]
        opt = replace(opt, help=opt.help.replace("%", "%%"))  # argparse formats with %
        if opt.positional:
            parser.add_argument(opt.name, metavar=opt.metavar or opt.name.upper(),
                                nargs="?", help=opt.help)  # checked() says if missing
        elif opt.kind == "flag":
            strings = [opt.flag] + (["--no-" + opt.flag[2:]] if opt.negatable else [])
            on = " (on by default)" if opt.default else ""
            parser.add_argument(*strings, dest=opt.name, action=_OnOff if opt.negatable
                                else "store_const", const=True, default=None,
                                help=opt.help + on)
        else:
            parser.add_argument(opt.flag, *opt.flags[1:], dest=opt.name, default=None,
                                metavar=opt.metavar or "TEXT",
                                action="append" if opt.repeat else "store",
                                help=opt.full_help())  # checked() says if missing


def value_flags(commands: Sequence[Command]) -> set[str]:
    """Every flag that takes a value (its value may start with ``-``: ``--v0 -1e-3``)."""
    return {o.flag for c in commands for o in c.options if o.takes_value}


def glue(argv: Sequence[str], flags: set[str]) -> list[str]:
    """``--v0 -1e-3`` as ``--v0=-1e-3``.

    So that argparse does not read a negative number as an option.
    """
    out: list[str] = []
    i = 0
    while i < len(argv):
        tok = argv[i]
        if tok in flags and i + 1 < len(argv) and argv[i + 1].startswith("-") \
                and re.match(r"-[\d.]|-inf", argv[i + 1]):
            out.append(f"{tok}={argv[i + 1]}")
            i += 2
            continue
        out.append(tok)
        i += 1
    return out


__all__ = ["UNTRUSTED_EXIT", "USAGE_EXIT", "Args", "Command", "Exit", "Formatter", "Parser",
           "UsageError", "add_options", "check_axis", "checked", "exit_if_untrusted", "glue",
           "json_number", "one_line", "parse_float", "parse_list", "plain", "value_flags"]
