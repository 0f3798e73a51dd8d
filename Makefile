# rotarykiln: set-up, demo, tests and benchmarks. Every target creates .venv if needed.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
DEMO_OUT ?= demo-output

.PHONY: demo test bench lint format schema docs clean browser

$(BIN)/python:
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip

$(STAMP): pyproject.toml | $(BIN)/python
	$(BIN)/python -m pip install --quiet -e ".[test]"
	$(BIN)/python -m compileall -q src >/dev/null  # bytecode, as a wheel install has it (faster starts)
	touch $(STAMP)

demo: $(STAMP)
	$(BIN)/rotarykiln demo --out $(DEMO_OUT)
	@echo "demo results, plots and report written to $(DEMO_OUT)/ (open $(DEMO_OUT)/report.html)"

browser:  # Debian's Chromium and its driver for the browser tests (tests/app/); no browser download
	@command -v chromium >/dev/null && command -v chromedriver >/dev/null || { \
	  SUDO=$$([ "$$(id -u)" = 0 ] || echo sudo); \
	  $$SUDO apt-get update -q && $$SUDO apt-get install -y -q chromium chromium-driver; }

test: $(STAMP) browser
	$(BIN)/ruff check src tests benchmarks docs/scripts examples
	$(BIN)/ruff format --check src tests benchmarks docs/scripts examples
	MPLBACKEND=Agg $(BIN)/python -m pytest -q

bench: $(STAMP)
	MPLBACKEND=Agg $(BIN)/python -m pytest benchmarks --benchmark-enable --benchmark-only -q --benchmark-columns=median,iqr,rounds

lint: $(STAMP)
	$(BIN)/ruff check src tests benchmarks docs/scripts examples
	$(BIN)/ruff format --check src tests benchmarks docs/scripts examples

format: $(STAMP)
	$(BIN)/ruff check --fix src tests benchmarks docs/scripts examples
	$(BIN)/ruff format src tests benchmarks docs/scripts examples

schema: $(STAMP)  # after a change to the case models (tests/test_schema.py checks it)
	$(BIN)/rotarykiln schema --out src/rotarykiln/case.schema.json

DOCS_STAMP := $(VENV)/.installed-docs

$(DOCS_STAMP): pyproject.toml | $(BIN)/python
	$(BIN)/python -m pip install --quiet -e ".[docs]"
	touch $(DOCS_STAMP)

docs: $(DOCS_STAMP)  # the documentation site in site/ (open site/index.html); any warning fails it
	NO_MKDOCS_2_WARNING=1 $(BIN)/mkdocs build --strict -d site

clean:
	rm -rf $(VENV) $(DEMO_OUT) build dist src/*.egg-info
