# Two commands do all the set-up: `make demo` and `make test`.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
# The official SARIF 2.1.0 JSON schema, for the tests that validate `check --format sarif`.
# It ships in an npm package (the machine's npm reaches the registry); tests skip without it.
SARIF_SCHEMA := $(VENV)/sarif-2.1.0.json
SARIF_PACKAGE := @microsoft/jest-sarif@1.0.0-beta.0

.PHONY: demo test lint bench clean

$(BIN)/python:
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip

$(STAMP): $(BIN)/python pyproject.toml
	$(BIN)/python -m pip install --quiet -e '.[test]'
	touch $(STAMP)

$(SARIF_SCHEMA): | $(BIN)/python
	-cd $(VENV) && npm pack --silent $(SARIF_PACKAGE) >/dev/null 2>&1 && \
	  tar xzf microsoft-jest-sarif-*.tgz package/lib/schemas/sarif-2.1.0-rtm.5.json && \
	  mv package/lib/schemas/sarif-2.1.0-rtm.5.json sarif-2.1.0.json && \
	  rm -rf package microsoft-jest-sarif-*.tgz

demo: $(STAMP)
	$(BIN)/python -m tapegate.demo

test: $(STAMP) $(SARIF_SCHEMA)
	$(BIN)/python -m pytest -q
	$(BIN)/ruff check formats postproc dnc tapegate tests benchmarks
	$(BIN)/mypy

lint: $(STAMP)
	$(BIN)/ruff check formats postproc dnc tapegate tests benchmarks
	$(BIN)/mypy

bench: $(STAMP)
	$(BIN)/python benchmarks/run.py
	$(BIN)/python benchmarks/dnc.py
	$(BIN)/python benchmarks/gateway.py

clean:
	rm -rf $(VENV) build *.egg-info .pytest_cache .mypy_cache .ruff_cache
