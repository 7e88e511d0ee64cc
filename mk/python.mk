# Python: the generator, the ilahrs package (generated/python) and the repository's pytest suite.

ILAHRS_STAMP := $(VENV)/.ilahrs-installed

# The package is installed editable, so regenerating it needs no reinstall.
$(ILAHRS_STAMP): $(VENV)/.stamp generated/python/pyproject.toml
	$(PIP) install --quiet --disable-pip-version-check --no-deps --no-build-isolation -e generated/python
	touch $@

SETUP_TARGETS += $(ILAHRS_STAMP)

PY_LINT_PATHS := generator generated/python tools/generator_stats.py tools/checksum_escapes.py tools/check-commits $(wildcard tests/*.py conformance/*.py conformance/runners/python/*.py conformance/runners/kaitai/*.py conformance/tools/*.py conformance/tools/*/*.py bench/python/*.py)
# Helper scripts of one binding live in tests/<binding>/; each folder is checked on its own, since
# their module names may repeat across folders.
PY_LINT_FOLDERS := $(sort $(dir $(wildcard tests/*/*.py)))

.PHONY: lint-python test-python test-python-versions bench-dataset

# The runtime modules of the package (generator/targets/python/runtime) are ruff-checked and
# format-checked where they are written; mypy checks them as the package's modules, in
# generated/python, where the generated tables they import sit beside them. lint-imports holds the
# package's layers (.importlinter): nothing imports from a layer above its own.
PY_RUNTIME := generator/targets/python/runtime

lint-python: setup
	$(VENV)/bin/ruff check $(PY_LINT_PATHS) $(PY_LINT_FOLDERS)
	$(VENV)/bin/ruff format --check $(PY_RUNTIME) generated/python
	$(VENV)/bin/mypy --exclude '^$(PY_RUNTIME)/' --exclude '(^|/)build/' --exclude '^\.venv/' $(PY_LINT_PATHS)
	$(VENV)/bin/mypy --python-version 3.10 --cache-dir $(BUILD)/mypy-py310 -p ilahrs
	for folder in $(PY_LINT_FOLDERS); do $(VENV)/bin/mypy $$folder; done
	$(VENV)/bin/lint-imports --config .importlinter

# The suite runs in PYTEST_JOBS worker processes (pytest-xdist), a test file to a worker (loadfile:
# a module's fixtures, such as a simulator shared by its tests, are set up once); PYTEST_JOBS=
# runs it in one process.
PYTEST_JOBS ?= -n 2 --dist loadfile

# tests/cli/test_cli.py runs `ilahrs monitor` under tmux and reads captures with tshark as well, and
# tests/conformance/test_html_report.py opens the conformance report in headless Chromium: all three
# are installed from Debian's packages when missing.
test-python: setup
	@command -v tmux >/dev/null || tools/need tmux
	@command -v tshark >/dev/null || tools/need tshark
	@command -v chromium >/dev/null || tools/need --no-recommends chromium fonts-liberation
	$(PY) -m pytest $(PYTEST_JOBS) tests

# The package on every Python from 3.10 that the machine has (tools/test-python-versions: a venv per
# version under build/python-versions/ with the pinned pytest and pyserial only, the package
# installed with pip; the version of the repository's venv is left out: the whole suite runs on it
# there). The tests are the folders whose tests use the package and nothing else
# of the repository (tests/session: the device and host sessions; tests/edge: the serial client, the
# simulator, pcapng), less the three long runs the main run covers (the pty flows, the stateful
# client, hundreds of motion sessions); then the conformance harness runs the Python runner on every
# vector. The other folders import the generator, whose pinned dependencies (rpds-py) do not install
# on 3.10.
PY_PACKAGE_TESTS := tests/session tests/edge
PY_VERSION_TESTS := $(PY_PACKAGE_TESTS) -k "not full_flow and not whatever_the_user_does and not ratchet"

test-python-versions: setup
	ILAHRS_COVERED_PYTHON=$$($(PY) -c 'import sys; print("%d.%d" % sys.version_info[:2])') \
	    tools/test-python-versions $(BUILD)/python-versions $(PY_VERSION_TESTS)

# How often damage passes the ICD's checksum, with and without strict decoding (E42): the device
# model's output through the simulator's byte corruption (1 %, seeded), 5,000,000 frames, ~2 minutes
# (the figures of erratum E42). FRAMES=N and ESCAPES_ARGS (tools/checksum_escapes.py --help) change it.
FRAMES ?= 5000000
ESCAPES_ARGS ?=

.PHONY: checksum-escapes
checksum-escapes: setup
	$(PY) tools/checksum_escapes.py --frames $(FRAMES) $(ESCAPES_ARGS)

LINT_TARGETS += lint-python
TEST_TARGETS += test-python-versions
FINAL_TEST_TARGETS += test-python

# Many captures into one Parquet dataset: captures/s and messages/s for 1, 2 and N jobs.
bench-dataset: setup
	$(PY) bench/python/bench_dataset.py

BENCH_TARGETS += bench-dataset
