"""Every deterministic number the docs quote against what its script prints now.

The quotes are declared in tests/quoted_numbers.py. For each section of the scripts of
:data:`SCRIPTS` (``benchmarks/docs_numbers.py``, ``mdr_inplane_numbers.py``,
``inplane_numbers.py``) the test calls the section function and checks (a) that the
committed results file holds the same rows, to the digits it prints (rows of wall times
aside: they are machine-dependent and the results file says where and when they were
measured), and (b) that each page quoting the section quotes the same values, to the
digits it quotes. The scripts of :data:`PRINTED` are run whole and their output compared
with their results file the same way. A drift in the code, the results file or a page
fails and names the page or file, the quantity and both values.
"""

from __future__ import annotations

import importlib
import os
import re
import subprocess
import sys
from collections.abc import Callable
from functools import cache

import pytest

from quoted_numbers import QUOTES, ROOT, disagreements

sys.path.insert(0, str(ROOT / "benchmarks"))
from sections import WALL, read_sections, row_line  # noqa: E402

#: script -> (its section functions' registry, its results file)
SCRIPTS = {"docs_numbers": ("CLAIMS", "benchmarks/results/docs_numbers.md"),
           "mdr_inplane_numbers": ("SECTIONS", "benchmarks/results/mdr_inplane.md"),
           "inplane_numbers": ("CLAIMS", "benchmarks/results/inplane_numbers.md")}
#: sections that integrate the spring-row reference (seconds warm, a compilation cold)
SLOW = {"mdr_inplane_numbers.reference_flat_punch", "mdr_inplane_numbers.against_reference",
        "mdr_inplane_numbers.short_bar"}
#: scripts that print their results file whole (run with the arguments given): the output
#: against the committed file line by line (numbers that are both round-off agree, as in
#: :func:`_agree`), but for the lines matching the pattern (the date and commit, wall times)
#: and for a wall time in a table's column (the group 2 of the optional mask); a quote's key
#: is the beginning of its line, after the first line that begins with the text before a
#: "\n" in the key where there is one
_DATED = r"^# 20\d\d-\d\d-\d\d, commit \w+, |^\d+ s$"
PRINTED: dict[str, tuple[str, str, str | None, tuple[str, ...]]] = {
    "mdr_shape_numbers": ("benchmarks/results/mdr_shape.md", _DATED, None, ()),
    "mdr_critical_numbers": ("benchmarks/results/mdr_critical.md", _DATED,
                             # the FFT grid's table: ms a call
                             r"^(\| \([^|]*\) \| [\d.]+ \| \S+ \| \S+ \| )([\d.]+)( \|)$", ()),
    "inplane_drive_numbers": ("benchmarks/results/inplane_drive.md",
                              r"^20\d\d-\d\d-\d\d \d\d:\d\d UTC, commit \w+, ",
                              # the stated error, round-off (1e-13 to 1e-11) that moves from
                              # run to run: the solver's, not the page's, to check
                              r"^(\| [-+][\d.e-]+ \| [-+][\d.]+ \| )(\d\.\de-1\d)( \| True \|)$",
                              ("--print",)),
    "plane_vzero_numbers": ("benchmarks/results/plane_vzero.md",
                            # the date and commit, the number of repeats; the median times,
                            # and the slow points' periods before them (effort, whose last
                            # digits move with round-off from one processor to another)
                            r"^# 2-D solver at and near v0 = 0 \(|^Made by ",
                            r"^(\| .* \| )(\d+ \| \d[\d.]* m?s|\d[\d.]* m?s)( \|)$",
                            ("--print", "--repeats", "1")),
    "mdr_history_numbers": ("benchmarks/results/mdr_history.md", _DATED,
                            # the time table: ms a history, two columns
                            r"^(\| \([^|]*\) \| \d+ \| )(\d+ ms \| \d+ ms)( \|)$", ()),
    "mdr_convergence": ("benchmarks/results/mdr_convergence.md", _DATED, None, ()),
    "design_numbers": ("benchmarks/results/design.md", r"^Date: 20\d\d-",
                       r"^(\| .* \| )(\d+\.\d)( \|)$", ("--print",))}  # time (s) a design
#: sources that are tests computing quoted numbers themselves (they call quoted_numbers.check)
TEST_SOURCES = {"tests/solver/test_sensitivity.py"}


def _registry(script: str) -> dict[str, Callable[[], list[tuple[str, str]]]]:
    return getattr(importlib.import_module(script), SCRIPTS[script][0])


def _section_names() -> list[str]:
    # the names without importing the scripts at collection: their registries are literal
    out = []
    for script, (registry, _) in SCRIPTS.items():
        text = (ROOT / "benchmarks" / f"{script}.py").read_text()
        body = text[text.index(f"{registry}: dict"):]
        body = body[body.index("(") + 1:body.index(")}")]
        out += [f"{script}.{name}" for name in re.findall(r"\w+", body)]
    return out


SECTIONS = [pytest.param(s, marks=[pytest.mark.slow] if s in SLOW else [], id=s)
            for s in _section_names()]


@cache
def _rows(source: str) -> tuple[tuple[str, str], ...]:
    script, name = source.split(".")
    return tuple(_registry(script)[name]())


#: Below this magnitude a number is round-off (a difference of two agreeing solvers): its
#: digits depend on the order of the floating-point operations (the compiler, the CPU, a
#: kernel's restructuring), so a row agrees where both are below it
ROUND_OFF = 1e-12
_NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def _agree(written: str, computed: str) -> bool:
    """The same row text, but for numbers that are both round-off (:data:`ROUND_OFF`)."""
    if written == computed:
        return True
    a, b = _NUMBER.split(written), _NUMBER.split(computed)
    x, y = _NUMBER.findall(written), _NUMBER.findall(computed)
    return a == b and len(x) == len(y) and all(
        u == v or (abs(float(u)) < ROUND_OFF and abs(float(v)) < ROUND_OFF)
        for u, v in zip(x, y, strict=True))


@pytest.mark.parametrize("source", SECTIONS)
def test_results_file_and_pages_quote_what_the_section_computes(source):
    script, name = source.split(".")
    rows = _rows(source)
    results = SCRIPTS[script][1]
    written = read_sections(ROOT / results).get(name)
    assert written is not None, f"{results} has no section `{name}`: regenerate it"
    problems = []
    for quantity, value in rows:
        was = [line for line in written if line.startswith(f"| {quantity} | ")]
        if WALL in quantity or any(_agree(w, row_line(quantity, value)) for w in was):
            continue
        problems.append(f"{results}, `{name}`, {quantity!r}: the file has "
                        f"{was[0] if was else 'no such row'}, the script computes {value!r}")
    values = dict(rows)
    problems += [p for q in QUOTES if q.source == source for p in disagreements(q, values)]
    assert not problems, "\n".join(problems)


def _line_rows(lines: list[str], keys: set[str]) -> dict[str, str]:
    """``{key: the rest of its line}`` for the keys found once (see :data:`PRINTED`)."""
    out = {}
    for key in keys:
        after, _, start = key.rpartition("\n")
        first = next((i for i, line in enumerate(lines) if line.startswith(after)), None)
        if first is None:
            continue
        found = [line for line in lines[first:] if line.startswith(start)]
        if found and (after or len(found) == 1):
            out[key] = found[0][len(start):]
    return out


#: printed scripts that take more than 30 s of CPU (design_numbers: 20 designs, 70 s)
SLOW_PRINTED = {"design_numbers"}


@pytest.mark.parametrize("script", [
    pytest.param(s, marks=[pytest.mark.slow] if s in SLOW_PRINTED else [], id=s)
    for s in sorted(PRINTED)])
def test_printed_results_file_and_pages_quote_what_the_script_prints(script):
    results, volatile, mask, args = PRINTED[script]
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(
        [str(ROOT / "src"), *filter(None, [os.environ.get("PYTHONPATH")])]))
    out = subprocess.run([sys.executable, str(ROOT / "benchmarks" / f"{script}.py"), *args],
                         env=env,
                         check=True, capture_output=True, text=True, timeout=600).stdout
    printed, written = ([re.sub(mask, r"\1(wall time)\3", line) if mask else line
                         for line in text.splitlines() if not re.search(volatile, line)]
                        # a trailing empty line (print's newline after the file's) aside
                        for text in (out.rstrip("\n"), (ROOT / results).read_text()))
    problems = [f"{results}: the file has {w!r}, the script prints {p!r}"
                for w, p in zip(written, printed, strict=False) if not _agree(w, p)]
    if len(written) != len(printed):
        problems.append(f"{results}: {len(written)} lines, the script prints {len(printed)}")
    quotes = [q for q in QUOTES if q.source == script]
    rows = _line_rows(out.splitlines(), {q.key for q in quotes})
    problems += [p for q in quotes for p in disagreements(q, rows)]
    assert not problems, "\n".join(problems[:20])


def test_every_quote_has_a_source():
    names = {*_section_names(), *PRINTED}
    for q in QUOTES:
        if q.source in TEST_SOURCES:
            assert f'check("{q.source}"' in (ROOT / q.source).read_text(), q
        else:
            assert q.source in names, f"{q}: no section {q.source}"
