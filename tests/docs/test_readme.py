"""The README and docs/tour.md run: their Python examples as doctests (each output
checked, a number to the digits it shows), and the README's command lines against the
command line's own options."""

from __future__ import annotations

import doctest
import re
import shlex
from pathlib import Path

import pytest

from doctest_numbers import NumberChecker

ROOT = Path(__file__).resolve().parents[2]
README = ROOT / "README.md"
TOUR = ROOT / "docs" / "tour.md"
FENCE = re.compile(r"^```(\w*)\n(.*?)^```", re.M | re.S)


def blocks(language: str, page: Path = README) -> list[str]:
    return [body for lang, body in FENCE.findall(page.read_text()) if lang == language]


@pytest.mark.parametrize("page", [README, TOUR], ids=["README", "tour"])
def test_every_python_block_is_a_doctest(page):
    python = blocks("python", page)
    assert python, f"{page.name} shows no Python"
    for body in python:
        first = next(line for line in body.splitlines() if line.strip())
        assert first.startswith(">>> "), f"not a doctest, so not checked: {first!r}"


@pytest.mark.parametrize("page, least", [(README, 5), (TOUR, 20)], ids=["README", "tour"])
def test_python_runs_and_prints_what_it_shows(page, least):
    """All Python blocks of a page in order in one namespace (the tour's ``vf.design``
    takes about 13 s)."""
    parser = doctest.DocTestParser()
    runner = doctest.DocTestRunner(
        checker=NumberChecker(), verbose=False,
        optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    namespace: dict = {}
    examples = 0
    for k, body in enumerate(blocks("python", page)):
        test = parser.get_doctest(body, namespace, f"{page.name} python block {k}", str(page),
                                  0)
        examples += len(test.examples)
        runner.run(test, clear_globs=False)
    result = runner.summarize(verbose=False)
    assert examples > least
    assert result.failed == 0, f"{result.failed} of {result.attempted} examples failed"


# ------------------------------------------------------------------ command line
def command_lines() -> list[str]:
    """Each ``vibrofriction ...`` line of the README's shell blocks, continuation lines
    joined, comments dropped."""
    out = []
    for body in blocks("sh"):
        for line in body.replace("\\\n", " ").splitlines():
            line = line.partition("#")[0].strip()
            if line.startswith("vibrofriction "):
                out.append(line)
    return out


LINES = command_lines()


def test_the_readme_shows_every_subcommand():
    from vibrofriction.cli import COMMANDS

    shown = {shlex.split(line)[1] for line in LINES}
    assert shown >= {"mu", "fit", "design", "reproduce", "sweep", "explore"}
    assert shown <= {c.name for c in COMMANDS}


@pytest.mark.parametrize("line", LINES)
def test_readme_command_line_parses(line, capsys):
    """Each option exists on its subcommand and ``--help`` works; the cheap ``mu`` lines
    run (exit 0: every point computed and trusted)."""
    from vibrofriction.cli import COMMANDS, run

    args = shlex.split(line)[1:]
    command = next(c for c in COMMANDS if c.name == args[0])
    known = command.flags()
    used = {a.partition("=")[0] for a in args[1:] if a.startswith("--")} - {"--help"}
    assert used <= known, f"{line!r}: unknown options {sorted(used - known)}"
    assert run([args[0], "--help"]) == 0, capsys.readouterr()
    if args[0] == "mu":
        assert run(args) == 0, capsys.readouterr()
