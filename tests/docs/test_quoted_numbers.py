"""Every deterministic number the docs quote against what its script prints now.

The quotes are declared in tests/quoted_numbers.py. For each section of
``benchmarks/docs_numbers.py`` and ``benchmarks/mdr_inplane_numbers.py`` the test calls the
section function and checks (a) that the committed results file holds the same rows, to
the digits it prints (rows of wall times aside: they are machine-dependent and the
results file says where and when they were measured), and (b) that each page quoting
the section quotes the same values, to the digits it quotes. A drift in the code, the
results file or a page fails and names the page or file, the quantity and both values.
"""

from __future__ import annotations

import importlib
import re
import sys
from collections.abc import Callable
from functools import cache

import pytest

from quoted_numbers import QUOTES, ROOT, disagreements

sys.path.insert(0, str(ROOT / "benchmarks"))
from sections import WALL, read_sections, row_line  # noqa: E402

#: script -> (its section functions' registry, its results file)
SCRIPTS = {"docs_numbers": ("CLAIMS", "benchmarks/results/docs_numbers.md"),
           "mdr_inplane_numbers": ("SECTIONS", "benchmarks/results/mdr_inplane.md")}
#: sections that integrate the spring-row reference (seconds warm, a compilation cold)
SLOW = {"mdr_inplane_numbers.reference_flat_punch", "mdr_inplane_numbers.against_reference",
        "mdr_inplane_numbers.short_bar"}
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


@pytest.mark.parametrize("source", SECTIONS)
def test_results_file_and_pages_quote_what_the_section_computes(source):
    script, name = source.split(".")
    rows = _rows(source)
    results = SCRIPTS[script][1]
    written = read_sections(ROOT / results).get(name)
    assert written is not None, f"{results} has no section `{name}`: regenerate it"
    problems = []
    for quantity, value in rows:
        if WALL in quantity or row_line(quantity, value) in written:
            continue
        was = [line for line in written if line.startswith(f"| {quantity} | ")]
        problems.append(f"{results}, `{name}`, {quantity!r}: the file has "
                        f"{was[0] if was else 'no such row'}, the script computes {value!r}")
    values = dict(rows)
    problems += [p for q in QUOTES if q.source == source for p in disagreements(q, values)]
    assert not problems, "\n".join(problems)


def test_every_quote_has_a_source():
    names = set(_section_names())
    for q in QUOTES:
        if q.source in TEST_SOURCES:
            assert f'check("{q.source}"' in (ROOT / q.source).read_text(), q
        else:
            assert q.source in names, f"{q}: no section {q.source}"
