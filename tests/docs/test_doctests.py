"""The ``Examples`` of the API reference run and print what they show.

Every public name (the top level's ``__all__`` and that of each public module the API
pages list, ``docs/api_pages.py``) is collected with its methods, and the ``>>>`` lines
of its docstring run as a doctest (``ELLIPSIS | NORMALIZE_WHITESPACE``), each docstring
in a fresh namespace. The examples stay cheap: at most one solver point each.
"""

from __future__ import annotations

import doctest
import importlib
import sys
from pathlib import Path

import pytest

from doctest_numbers import NumberChecker

DOCS = Path(__file__).resolve().parents[2] / "docs"
sys.path.insert(0, str(DOCS))
import api_pages  # noqa: E402

FLAGS = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE


def _modules() -> list[str]:
    return [api_pages.TOP] + [module for module, _ in api_pages.MODULES]


def _tests() -> list[doctest.DocTest]:
    """Each public object's doctests (classes with their methods), each once."""
    finder = doctest.DocTestFinder(recurse=True, exclude_empty=True)
    seen: dict[str, doctest.DocTest] = {}
    for module in _modules():
        mod = importlib.import_module(module)
        for test in finder.find(mod, module, globs={}):  # the module's own docstring
            if test.name == module and test.examples:
                seen.setdefault(test.name, test)
        for name in api_pages.public_names(module):
            if name == "__version__":
                continue
            obj = getattr(mod, name)
            home = api_pages.home(name, module)
            if not (callable(obj) or isinstance(obj, type)) or home != module:
                continue  # constants, and names documented under another module
            for test in finder.find(obj, f"{module}.{name}", globs={}):
                if test.examples:
                    seen.setdefault(test.name, test)
    return sorted(seen.values(), key=lambda t: t.name)


TESTS = _tests()


def test_the_public_api_has_examples():
    """The collection finds examples in every public module that has functions."""
    for module in ("vibrofriction.contact", "vibrofriction.schema",
                   "vibrofriction.validation", "vibrofriction.parallel",
                   "vibrofriction.sweep", "vibrofriction.figures", "vibrofriction.report"):
        assert any(t.name.startswith(f"{module}.") for t in TESTS), module


@pytest.mark.parametrize("test", TESTS, ids=[t.name for t in TESTS])
def test_docstring_example(test: doctest.DocTest):
    runner = doctest.DocTestRunner(checker=NumberChecker(), optionflags=FLAGS)
    runner.run(test)
    assert runner.failures == 0, f"{test.name}: see the doctest report above"
