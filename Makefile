PYTHON ?= python3
VENV   ?= .venv
BIN     = $(VENV)/bin
OUT    ?= reproduction
# pytest-xdist: one test process per core (-n auto; PYTEST_WORKERS=0 for one process); the
# tests of a module run on one worker (--dist loadfile), so that a module-scoped fixture (a
# wheel, a reproduction, a sweep, the site) is computed once; the modules go out in the
# order of tests/conftest.py (the longest first), not by their number of tests as xdist's
# default would (--no-loadscope-reorder). The 25 slowest tests are listed at the end.
# Bytecode is written even where PYTHONDONTWRITEBYTECODE is set: pytest caches its
# rewritten test modules there (about 20 s of collection per worker otherwise)
PYTEST_WORKERS ?= auto
PYTEST = PYTHONDONTWRITEBYTECODE= $(BIN)/python -m pytest -q -n $(PYTEST_WORKERS) \
         --dist loadfile --no-loadscope-reorder --durations=25

.PHONY: demo warmup test fast checks lint typecheck dist bench clean clean-cache browser docs

# The package and what it needs to run (make demo); the tools of the tests on top (make test)
$(BIN)/vibrofriction: pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/pip install --quiet --upgrade pip
	$(BIN)/pip install --quiet -e .
	touch $@

$(VENV)/.dev: $(BIN)/vibrofriction pyproject.toml
	$(BIN)/pip install --quiet --group dev  # PEP 735 group: pip >= 25.1
	touch $@

demo: $(BIN)/vibrofriction  ## reproduce every figure of the paper into $(OUT)/
	$(BIN)/vibrofriction reproduce --out $(OUT)
	@echo "the command line: .venv/bin/vibrofriction --help (or 'source .venv/bin/activate' first)"

# numba's cache filled on both cores before the site's examples and the tests run (else the
# site compiles on one core, and both test workers compile the kernels they start with)
warmup: $(BIN)/vibrofriction  ## the shipped kernels built (once, where they run), then loaded or compiled
	$(BIN)/python -c "from vibrofriction.warmup import refresh_shipped; refresh_shipped()"
	$(BIN)/vibrofriction warmup --no-progress

browser:  ## the distribution's headless Chromium for the explorer's browser tests
	command -v chromium >/dev/null || (apt-get update && apt-get install -y --no-install-recommends chromium)

$(VENV)/.docs: $(VENV)/.dev pyproject.toml
	$(BIN)/pip install --quiet --group docs  # PEP 735 group, as dev
	touch $@

docs: $(VENV)/.docs  ## the site into docs/_build/html, offline, warnings as errors (examples run)
	$(BIN)/python -m sphinx -b html -W --keep-going -q -d docs/_build/doctrees docs docs/_build/html
	@echo "site: docs/_build/html/index.html"

# The test lanes (docs/packaging.md, "Test lanes"):
# * make test: every test (fast, slow and browser), the site built first; CI runs it. The
#   site's build runs on one core: the checks (mypy, about 40 s of one core from a clean
#   clone) run beside it, on the other (make -j2), and pytest starts when both are done
# * make fast: the tests not marked slow or browser, stopping at the first failure
test: $(VENV)/.dev browser warmup  ## the whole test suite, site, slow and browser tests included
	$(MAKE) --no-print-directory -j2 docs checks
	VIBROFRICTION_BROWSER_TESTS=required $(PYTEST)

checks: $(VENV)/.dev  ## ruff, the import contracts and mypy (make test runs them beside the site)
	$(BIN)/ruff check src tests benchmarks examples
	$(BIN)/lint-imports
	$(BIN)/mypy

fast:  ## the development loop, installs nothing: lint, contracts, tests not slow or browser
	@test -x $(BIN)/vibrofriction || (echo "make fast installs nothing: run 'make test' once first" >&2; exit 2)
	@$(BIN)/python -c "import xdist" 2>/dev/null || (echo "make fast installs nothing: pytest-xdist is missing, run 'make test' once (it installs the dev group)" >&2; exit 2)
	$(BIN)/ruff check src tests benchmarks examples
	$(BIN)/lint-imports
	$(BIN)/mypy
	$(PYTEST) -x -m "not slow and not browser"

lint: $(VENV)/.dev
	$(BIN)/ruff check src tests benchmarks examples

typecheck: $(VENV)/.dev  ## mypy on src/ (configured in pyproject.toml)
	$(BIN)/mypy

dist: $(VENV)/.dev  ## the wheel and the sdist into dist/, kernels precompiled (docs/packaging.md)
	$(BIN)/python -c "from vibrofriction.warmup import build_shipped; build_shipped()"
	$(BIN)/python -m build --sdist  # source only (MANIFEST.in excludes compiled files)
	$(BIN)/python -m build --wheel  # from the tree: the kernels of _kernels/_shipped with it

bench: $(VENV)/.dev  ## peer benchmarks, results written to benchmarks/results/
	$(BIN)/python benchmarks/bench_solver.py

clean:
	rm -rf $(VENV) $(OUT) docs/_build docs/api docs/gallery docs/_generated

clean-cache:  ## numba checks only a kernel's own file: clear the cache after editing _kernels/
	find src -name '*.nbi' -delete; find src -name '*.nbc' -delete
	rm -rf src/vibrofriction/_kernels/_shipped
