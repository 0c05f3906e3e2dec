# Two commands do all the set-up: `make demo` and `make test`.
# Installing builds the Rust core (crates/) into formats._core through maturin.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
PY_SOURCES := formats postproc dnc tapegate tests benchmarks fuzz

.PHONY: demo test lint rust bench fuzz docs clean wheel wheel-check

$(BIN)/python:
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip

$(STAMP): $(BIN)/python pyproject.toml Cargo.toml crates/core/Cargo.toml crates/python/Cargo.toml
	rm -f formats/_core.cpython-*.so
	$(BIN)/python -m pip install --quiet -e '.[test]'
	touch $(STAMP) formats/.core-built

# The extension is rebuilt whenever a Rust source is newer than it.
# The extension is abi3 (`_core.abi3.so`); a version-specific one left by an older build
# (`_core.cpython-311-*.so`) would be imported before it, so it goes.
formats/.core-built: $(STAMP) $(shell find crates/core/src crates/python/src -name '*.rs')
	rm -f formats/_core.cpython-*.so
	$(BIN)/python -m pip install --quiet --no-deps -e .
	touch $@

demo: formats/.core-built
	$(BIN)/python -m tapegate.demo

test: formats/.core-built rust
	$(BIN)/python -m pytest -q
	$(BIN)/ruff check $(PY_SOURCES)
	$(BIN)/mypy

# The fuzz crate sits outside the workspace (cargo fuzz builds it): checked here so that a change
# of the core's API cannot leave `make fuzz` broken unseen.
rust:
	cargo test --quiet -p tapegate-core
	cargo clippy --quiet --workspace --all-targets -- -D warnings
	cargo check --quiet --manifest-path crates/fuzz/Cargo.toml --all-targets

lint: formats/.core-built
	$(BIN)/ruff check $(PY_SOURCES)
	$(BIN)/mypy
	cargo clippy --quiet --workspace --all-targets -- -D warnings

# Coverage-guided fuzzing, not part of `make test`; results in docs/robustness.md. First the
# core (cargo fuzz, libFuzzer), then the public Python API (atheris, fuzz/run.py): every target
# for FUZZ_SECONDS, seeded from ../shared/corpus. Both run; the exit status is the worse one.
FUZZ_SECONDS ?= 60

fuzz: formats/.core-built
	command -v cargo-fuzz >/dev/null || cargo install --quiet cargo-fuzz
	$(BIN)/python -c 'import atheris' 2>/dev/null || $(BIN)/python -m pip install --quiet -e '.[fuzz]'
	crates/fuzz/run.sh $(FUZZ_SECONDS); core=$$?; \
	$(BIN)/python fuzz/run.py $(FUZZ_SECONDS); py=$$?; \
	exit $$(( core > py ? core : py ))

# One wheel for CPython 3.11 and newer (abi3) in dist/, which installs without a Rust toolchain
# (README); maturin, the build backend, is installed into .venv on first use. `wheel-check`
# installs it into a fresh venv with no Rust on PATH and runs it beside .venv (CI runs both).
wheel: $(BIN)/python
	[ -x $(BIN)/maturin ] || $(BIN)/python -m pip install --quiet 'maturin>=1.5,<2'
	$(BIN)/maturin build --release --out dist

wheel-check: formats/.core-built wheel
	.ci/wheel-check

bench: formats/.core-built
	$(BIN)/python benchmarks/run.py
	$(BIN)/python benchmarks/dnc.py
	$(BIN)/python benchmarks/gateway.py

# The pictures in docs/: the gateway's status page (docs/gateway.md), taken in headless
# Chromium from an emulated gateway (apt-get install chromium).
docs: formats/.core-built
	$(BIN)/python docs/screenshot.py docs/status-page.png

clean:
	rm -rf $(VENV) build target dist *.egg-info .pytest_cache .mypy_cache .ruff_cache
	rm -f formats/_core*.so formats/.core-built
