# Python: the generator, the ilahrs package (generated/python) and the repository's pytest suite.

ILAHRS_STAMP := $(VENV)/.ilahrs-installed

# The package is installed editable, so regenerating it needs no reinstall.
$(ILAHRS_STAMP): $(VENV)/.stamp generated/python/pyproject.toml
	$(PIP) install --quiet --disable-pip-version-check --no-deps --no-build-isolation -e generated/python
	touch $@

SETUP_TARGETS += $(ILAHRS_STAMP)

PY_LINT_PATHS := generator generated/python tests $(wildcard conformance/*.py conformance/runners/*.py conformance/tools/*.py) $(wildcard bench/python/*.py)

.PHONY: lint-python test-python

lint-python: setup
	$(VENV)/bin/ruff check $(PY_LINT_PATHS)
	$(VENV)/bin/mypy $(PY_LINT_PATHS)

test-python: setup
	$(PY) -m pytest tests

LINT_TARGETS += lint-python
TEST_TARGETS += test-python
