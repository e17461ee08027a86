"""The results files whose numbers the docs quote, one format for every script.

A script of ``benchmarks/`` made of sections (``docs_numbers.py``, ``mdr_inplane_numbers.py``)
writes, per section function, a markdown section headed by the function's name with a
table of rows ``(quantity, value)``. A row whose quantity contains :data:`WALL` is a wall
time (machine-dependent; the results file says where and when it was measured); every
other row is deterministic: ``tests/docs/test_quoted_numbers.py`` recomputes it by calling
the section function and checks it against the committed results file and the pages
that quote it.
"""

from __future__ import annotations

import datetime
import os
import platform
import re
import subprocess
from pathlib import Path

Rows = list[tuple[str, str]]
#: the mark of a machine-dependent row (its quantity contains it)
WALL = "wall time"
_HEADING = re.compile(r"^## `(\w+)`")


def section(name: str, doc: str, rows: Rows, seconds: float) -> str:
    """The markdown section of one section function: its name, run time, docstring and
    the table of its rows."""
    doc = " ".join(doc.split())
    table = "\n".join(row_line(q, v) for q, v in rows)
    return (f"## `{name}` ({seconds:.1f} s)\n\n{doc}\n\n| quantity | value |\n|---|---|\n"
            f"{table}\n")


def append_run(path: Path, title: str, command: str, how: str, lines: list[str]) -> None:
    """Append one run to the results file ``path`` (titled ``title`` when it is new): a
    section headed by the commit and the time, the ``command``, the machine and ``how``
    the numbers were taken, then ``lines``; the earlier runs stay above."""
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True, cwd=path.parent).stdout.strip()
    first = not path.exists()
    with path.open("a") as fh:
        if first:
            fh.write(f"# {title}\n")
        fh.write(f"\n## {commit}, {datetime.datetime.now(datetime.UTC):%Y-%m-%d %H:%M} UTC\n\n"
                 f"`{command}` on {platform.machine()}, {os.cpu_count()} cores; {how}\n\n"
                 + "\n".join(lines) + "\n")


def row_line(quantity: str, value: str) -> str:
    """A row as the results file writes it."""
    return f"| {quantity} | {value} |"


def read_sections(path: Path) -> dict[str, list[str]]:
    """The row lines of each section of a results file, by section name."""
    out: dict[str, list[str]] = {}
    rows: list[str] = []
    for line in path.read_text().splitlines():
        if line.startswith("#"):  # a section of rows, or another part
            m = _HEADING.match(line)
            rows = out.setdefault(m.group(1), []) if m else []
        elif line.startswith("| ") and line.endswith(" |"):
            rows.append(line)
    return out
