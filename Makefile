# ilahrs: the one entry point.
#
#   make              set up, regenerate, build every binding, run the conformance suite
#   make test         every test (on a fresh clone: sets up and builds first); one line per stage with
#                     its duration, each stage's output in build/logs/STAGE.log (shown on failure);
#                     VERBOSE=1 prints everything as it runs
#   make generate     regenerate generated/ from spec/ilahrs.yaml
#   make check        fail if generated/ differs from what the spec produces, or lint fails
#   make conformance  run every binding against conformance/vectors (VECTORS=dir BINDINGS=a,b)
#   make bench        benchmarks (timings live here, never in tests)
#   make footprint    code and RAM size on a Cortex-M4
#   make fuzz         every fuzz target until its coverage stops growing (fuzz/README.md)
#
# Each binding adds its own rules in mk/<name>.mk and appends to the lists below.

SHELL := /bin/bash
.SHELLFLAGS := -eu -o pipefail -c
.DEFAULT_GOAL := all

ROOT := $(CURDIR)
VENV := .venv
PY := $(VENV)/bin/python
PIP := $(VENV)/bin/pip
PYTHON ?= python3
BUILD := build

SETUP_TARGETS :=
GENERATE_TARGETS :=
CHECK_TARGETS :=
BUILD_TARGETS :=
LINT_TARGETS :=
TEST_TARGETS :=
# Runs after every other test: the repository's pytest suite, whose summary closes the log.
FINAL_TEST_TARGETS :=
BENCH_TARGETS :=
FOOTPRINT_TARGETS :=
FUZZ_TARGETS :=

.PHONY: all setup generate build check lint test conformance bench footprint fuzz clean

all: setup generate build conformance

# --- Python environment: pinned packages in .venv -----------------------------------
$(VENV)/.stamp: requirements.txt
	$(PYTHON) -m venv $(VENV)
	$(PIP) install --quiet --disable-pip-version-check -r requirements.txt
	touch $@

SETUP_TARGETS += $(VENV)/.stamp

include $(sort $(wildcard mk/*.mk))

setup: $(SETUP_TARGETS)

generate: setup
	$(PY) -m generator
	$(MAKE) --no-print-directory $(GENERATE_TARGETS)

build: setup $(BUILD_TARGETS)

lint: setup $(LINT_TARGETS) lint-commits

# Commit messages since CONTRIBUTING.md was written have its form (tools/check-commits).
.PHONY: lint-commits
lint-commits:
	@$(PY) tools/check-commits

check: setup
	$(PY) -m generator --check
	$(MAKE) --no-print-directory lint $(CHECK_TARGETS)

STAGE := tools/stage
VERBOSE ?= 0

ifeq ($(VERBOSE),1)
test: setup build check conformance $(TEST_TARGETS) $(FINAL_TEST_TARGETS)
else
test:
	@echo "make test: one line per stage, its output in $(BUILD)/logs/ (VERBOSE=1 prints all of it)"
	@for t in setup build check; do $(STAGE) $$t $(MAKE) --no-print-directory $$t || exit 1; done; \
	$(STAGE) conformance --show 4 $(MAKE) --no-print-directory conformance || exit 1; \
	for t in $(TEST_TARGETS); do $(STAGE) $$t $(MAKE) --no-print-directory $$t || exit 1; done; \
	for t in $(FINAL_TEST_TARGETS); do $(STAGE) $$t --show 1 $(MAKE) --no-print-directory $$t || exit 1; done
endif

bench: setup build $(BENCH_TARGETS)

footprint: setup $(FOOTPRINT_TARGETS)

fuzz: setup build $(FUZZ_TARGETS)

clean:
	rm -rf $(BUILD)
