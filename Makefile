PYTHON ?= python3
VENV   ?= .venv
BIN     = $(VENV)/bin
OUT    ?= reproduction

.PHONY: demo test fast lint typecheck dist bench clean clean-cache browser docs

$(BIN)/vibrofriction: pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/pip install --quiet --upgrade pip
	$(BIN)/pip install --quiet -e . --group dev  # PEP 735 group: pip >= 25.1
	touch $@

demo: $(BIN)/vibrofriction  ## reproduce every figure of the paper into $(OUT)/
	$(BIN)/vibrofriction reproduce --out $(OUT)

browser:  ## the distribution's headless Chromium for the explorer's browser tests
	command -v chromium >/dev/null || (apt-get update && apt-get install -y --no-install-recommends chromium)

$(VENV)/.docs: $(BIN)/vibrofriction pyproject.toml
	$(BIN)/pip install --quiet --group docs  # PEP 735 group, as dev
	touch $@

docs: $(VENV)/.docs  ## the site into docs/_build/html, offline, warnings as errors (examples run)
	$(BIN)/python -m sphinx -b html -W --keep-going -q -d docs/_build/doctrees docs docs/_build/html
	@echo "site: docs/_build/html/index.html"

test: $(BIN)/vibrofriction browser docs  ## the whole test suite, site, slow and browser tests included
	$(BIN)/ruff check src tests benchmarks examples
	$(BIN)/lint-imports
	$(BIN)/mypy
	VIBROFRICTION_BROWSER_TESTS=required $(BIN)/python -m pytest -q

fast:  ## the development loop, installs nothing: lint, contracts, tests not slow or browser
	@test -x $(BIN)/vibrofriction || (echo "make fast installs nothing: run 'make test' once first" >&2; exit 2)
	$(BIN)/ruff check src tests benchmarks examples
	$(BIN)/lint-imports
	$(BIN)/mypy
	$(BIN)/python -m pytest -q -x -m "not slow and not browser"

lint: $(BIN)/vibrofriction
	$(BIN)/ruff check src tests benchmarks examples

typecheck: $(BIN)/vibrofriction  ## mypy on src/ (configured in pyproject.toml)
	$(BIN)/mypy

dist: $(BIN)/vibrofriction  ## the wheel and the sdist into dist/ (docs/packaging.md)
	$(BIN)/python -m build

bench: $(BIN)/vibrofriction  ## peer benchmarks, results written to benchmarks/results/
	$(BIN)/python benchmarks/bench_solver.py

clean:
	rm -rf $(VENV) $(OUT) docs/_build docs/api docs/gallery docs/_generated

clean-cache:  ## numba checks only a kernel's own file: clear the cache after editing _kernels/
	find src -name '*.nbi' -delete; find src -name '*.nbc' -delete
