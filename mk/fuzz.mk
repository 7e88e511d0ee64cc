# Fuzzing (fuzz/README.md): libFuzzer on the C library, cargo-fuzz on the Rust crate, atheris on the
# Python package, all from seeds and dictionaries made from the spec, and a three-way differential.
#
#   make fuzz           every target until its coverage stops growing (FUZZ_PLATEAU executions
#                       without a new edge; FUZZ_PLATEAU_PYTHON for the Python targets), FUZZ_CAP
#                       seconds at most each, FUZZ_JOBS targets at once; corpora in fuzz/corpus/TARGET/
#                       (minimised, committed); one line per target; exit 1 on a crash (its input kept
#                       in build/fuzz/TARGET/crashes/)
#   make fuzz-c / fuzz-rust / fuzz-python   the same for one language
#   make fuzz-seeds     build/fuzz/seeds/SHAPE/ and build/fuzz/dict/SHAPE.dict (fuzz/seeds.py)
#   make test-fuzz      (in make test) C, Rust and Python on the same seeded inputs, compared three
#                       ways (fuzz/differential.py)
#   make lint-fuzz      (in make check) ruff and mypy on fuzz/*.py
#   make fuzz-stateful  (in make fuzz) the stateful client test (tests/session/test_client_stateful.py) with
#                       STATEFUL_EXAMPLES examples of up to STATEFUL_STEPS steps, new ones each run;
#                       prints the (state, command, pause) combinations it explored
#
# make test-c also runs each C fuzzer FUZZ_RUNS times from these seeds and fails unless libFuzzer's
# coverage report shows the functions its source names on `fuzz-must-reach:` lines (fuzz/run.py check).
#
# cargo-fuzz is installed under build/fuzz/cargo-fuzz (cargo install --root) and its targets built on
# the stable toolchain with RUSTC_BOOTSTRAP=1 (cargo-fuzz passes nightly -Z flags). atheris (pinned in
# fuzz/requirements.txt) is installed under build/fuzz/python with pip --target, outside .venv.

FUZZ_OUT := $(BUILD)/fuzz
FUZZ_SEEDS := $(FUZZ_OUT)/seeds/.stamp
FUZZ_PLATEAU ?= 1000000
FUZZ_PLATEAU_PYTHON ?= 50000
FUZZ_CAP ?= 480
FUZZ_JOBS ?= 2
CARGO_FUZZ_VERSION := 0.13.1
CARGO_FUZZ := $(FUZZ_OUT)/cargo-fuzz/bin/cargo-fuzz
ATHERIS := $(FUZZ_OUT)/python/.stamp
FUZZ_C := c-fuzz_parsers c-fuzz_stream
FUZZ_RUST := rust-payloads rust-stream
FUZZ_PYTHON := python-stream python-payloads python-sentences python-device python-host
FUZZ_RUN = $(PY) fuzz/run.py fuzz --plateau $(FUZZ_PLATEAU) --plateau-python $(FUZZ_PLATEAU_PYTHON) --cap $(FUZZ_CAP) \
           --jobs $(FUZZ_JOBS)
FUZZ_PY_FILES := fuzz/seeds.py fuzz/run.py fuzz/differential.py fuzz/python/records.py fuzz/python/targets.py

.PHONY: fuzz-stateful fuzz-seeds fuzz-all fuzz-c fuzz-rust fuzz-python fuzz-rust-build test-fuzz lint-fuzz

$(FUZZ_SEEDS): fuzz/seeds.py fuzz/python/records.py $(wildcard generated/python/ilahrs/*.py) | setup
	$(PY) fuzz/seeds.py $(FUZZ_OUT)
	@touch $@

fuzz-seeds: $(FUZZ_SEEDS)

test-c: $(FUZZ_SEEDS)

$(CARGO_FUZZ):
	cargo install --quiet --locked --root $(FUZZ_OUT)/cargo-fuzz cargo-fuzz@$(CARGO_FUZZ_VERSION)

fuzz-rust-build: setup-rust $(CARGO_FUZZ)
	RUSTC_BOOTSTRAP=1 $(CARGO_FUZZ) build --debug-assertions --fuzz-dir fuzz/rust --target-dir $(RUST_TARGET)/fuzz

$(ATHERIS): fuzz/requirements.txt | setup
	rm -rf $(@D) && $(PIP) install --quiet --disable-pip-version-check --target $(@D) -r $<
	@touch $@

fuzz-c: setup-c $(C_FUZZERS) $(FUZZ_SEEDS)
	$(FUZZ_RUN) $(FUZZ_C)

fuzz-rust: fuzz-rust-build $(FUZZ_SEEDS)
	$(FUZZ_RUN) $(FUZZ_RUST)

fuzz-python: $(ATHERIS) $(FUZZ_SEEDS)
	$(FUZZ_RUN) $(FUZZ_PYTHON)

# make fuzz: every target in one run, so that its closing lines are one per target.
fuzz-all: setup-c $(C_FUZZERS) fuzz-rust-build $(ATHERIS) $(FUZZ_SEEDS)
	$(FUZZ_RUN) $(FUZZ_C) $(FUZZ_RUST) $(FUZZ_PYTHON)

# The three-way differential needs the three conformance runners (make build) and the capture tool.
test-fuzz: build-c build-rust $(C_OUT)/capture
	$(PY) fuzz/differential.py --capture $(C_OUT)/capture

lint-fuzz: setup
	$(VENV)/bin/ruff check $(FUZZ_PY_FILES)
	$(VENV)/bin/ruff format --check $(FUZZ_PY_FILES)
	$(VENV)/bin/mypy $(FUZZ_PY_FILES)

# The client against the device model on a pty, in real time (mostly sleeping: ~10 min, little CPU).
STATEFUL_EXAMPLES ?= 40
STATEFUL_STEPS ?= 40
fuzz-stateful: setup
	ILAHRS_STATEFUL_EXAMPLES=$(STATEFUL_EXAMPLES) ILAHRS_STATEFUL_STEPS=$(STATEFUL_STEPS) ILAHRS_STATEFUL_RANDOM=1 \
	  $(PY) -m pytest -q -s tests/session/test_client_stateful.py

FUZZ_TARGETS += fuzz-all fuzz-stateful
LINT_TARGETS += lint-fuzz
TEST_TARGETS += test-fuzz
