# Python: the generator, the ilahrs package (generated/python) and the repository's pytest suite.

ILAHRS_STAMP := $(VENV)/.ilahrs-installed

# The package is installed editable, so regenerating it needs no reinstall.
$(ILAHRS_STAMP): $(VENV)/.stamp generated/python/pyproject.toml
	$(PIP) install --quiet --disable-pip-version-check --no-deps --no-build-isolation -e generated/python
	touch $@

SETUP_TARGETS += $(ILAHRS_STAMP)

PY_LINT_PATHS := generator generated/python tools/generator_stats.py $(wildcard tests/*.py conformance/*.py conformance/runners/*.py conformance/tools/*.py conformance/tools/*/*.py bench/python/*.py)
# Helper scripts of one binding live in tests/<binding>/; each folder is checked on its own, since
# their module names may repeat across folders.
PY_LINT_FOLDERS := $(sort $(dir $(wildcard tests/*/*.py)))

.PHONY: lint-python test-python

# The runtime modules of the package (generator/targets/python/runtime) are ruff-checked and
# format-checked where they are written; mypy checks them as the package's modules, in
# generated/python, where the generated tables they import sit beside them.
PY_RUNTIME := generator/targets/python/runtime

lint-python: setup
	$(VENV)/bin/ruff check $(PY_LINT_PATHS) $(PY_LINT_FOLDERS)
	$(VENV)/bin/ruff format --check $(PY_RUNTIME) generated/python
	$(VENV)/bin/mypy --exclude '^$(PY_RUNTIME)/' --exclude '^build/' --exclude '^\.venv/' $(PY_LINT_PATHS)
	for folder in $(PY_LINT_FOLDERS); do $(VENV)/bin/mypy $$folder; done

# tests/test_cli.py runs `ilahrs monitor` under tmux and reads captures with tshark as well: both
# are installed from Debian's packages when missing.
test-python: setup
	@command -v tmux >/dev/null && command -v tshark >/dev/null || { apt-get update -qq >/dev/null && \
		DEBIAN_FRONTEND=noninteractive apt-get install -y -qq tmux tshark >/dev/null; }
	$(PY) -m pytest tests

LINT_TARGETS += lint-python
FINAL_TEST_TARGETS += test-python
