"""The test suite's own layout (docs/packaging.md, "Test lanes"): one folder per layer,
no test module imported by another (shared code lives in the helper modules of tests/ and
in conftest.py), and no two test modules with the same name (the folders are not
packages: pytest imports each module by its basename)."""

from __future__ import annotations

import re
from collections import Counter
from pathlib import Path

TESTS = Path(__file__).resolve().parents[1]
IMPORT = re.compile(r"^\s*(?:from|import)\s+(test_\w+)", re.M)


def _modules() -> list[Path]:
    return sorted(p for p in TESTS.rglob("test_*.py") if "__pycache__" not in p.parts)


def test_no_test_module_imports_another():
    found = [f"{p.relative_to(TESTS)} imports {name}"
             for p in _modules() for name in IMPORT.findall(p.read_text())]
    assert not found, "\n".join(found)


def test_test_modules_have_unique_names_and_sit_in_a_layer_folder():
    modules = _modules()
    assert len(modules) > 50, f"found only {len(modules)} test modules under {TESTS}"
    twice = [name for name, n in Counter(p.name for p in modules).items() if n > 1]
    assert not twice, twice
    assert all(p.parent.parent == TESTS for p in modules), \
        [str(p.relative_to(TESTS)) for p in modules if p.parent.parent != TESTS]


def test_the_longest_modules_are_named_as_they_are_and_collected_first(request):
    """Every module of conftest's HEAVY_FIRST exists (a renamed one would lose its place
    silently), and in this session's collection the listed modules come first, in their
    order (the order xdist hands out with --no-loadscope-reorder)."""
    from conftest import HEAVY_FIRST

    missing = [name for name in HEAVY_FIRST if not (TESTS / name).is_file()]
    assert not missing, missing
    assert len(set(HEAVY_FIRST)) == len(HEAVY_FIRST)
    seen = list(dict.fromkeys(Path(item.path).relative_to(TESTS).as_posix()
                              for item in request.session.items))
    rank = [HEAVY_FIRST.index(m) if m in HEAVY_FIRST else len(HEAVY_FIRST) for m in seen]
    assert rank == sorted(rank), seen
