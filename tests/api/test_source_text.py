"""The package's source text: no control characters where a backslash was meant.

A ``"\\tau"`` in a docstring that is not a raw string is a tab and ``au``; ``"\\frac"`` a
form feed (theory.py's exact stiff law held both, and ``"\\b"`` of ``\\bar``).
"""

from __future__ import annotations

import re
from pathlib import Path

import vibrofriction as vf

SRC = Path(__file__).resolve().parents[2] / "src"
# every C0 control character and DEL, except the tab and the newline; and a tab before a
# letter, which is where "\tau", "\theta", "\tfrac" lost their backslash
CONTROL = re.compile(r"[\x00-\x08\x0b-\x1f\x7f]|\t(?=[A-Za-z])")


def test_no_source_file_under_src_holds_control_characters():
    files = sorted(p for p in SRC.rglob("*.py") if "__pycache__" not in p.parts)
    assert len(files) > 40, f"found only {len(files)} source files under {SRC}"
    found = []
    for path in files:
        for number, line in enumerate(path.read_text(encoding="utf-8").split("\n"), 1):
            for match in CONTROL.finditer(line):
                found.append(f"{path.relative_to(SRC)}:{number}: {match.group()!r} in "
                             f"{line.strip()[:60]!r}")
    assert not found, "\n".join(found)


def test_the_exact_stiff_law_states_its_formula_in_latex():
    doc = vf.theory.mu_ratio_stiff_exact.__doc__
    for command in (r"\frac{\mu}{\mu_0}", r"\sin\tau_2", r"\tfrac{\bar v}{2}"):
        assert command in doc
