# Kaitai Struct: compile generated/kaitai/ilahrs.ksy with the official compiler (npm
# kaitai-struct-compiler 0.11, driven by tools/kaitai/compile.js) into a Kaitai Python parser and
# a `construct` definition, the independent decoder and builder that tests/kaitai/test_kaitai*.py and
# tests/kaitai/test_construct.py hold the Python binding against. The root pytest run (test-python)
# collects those tests; `make test-kaitai` runs only them.

KAITAI_TOOLS := tools/kaitai
KAITAI_NODE := $(KAITAI_TOOLS)/node_modules/.ilahrs-stamp
KAITAI_KSY := generated/kaitai/ilahrs.ksy
KAITAI_OUT := $(BUILD)/kaitai
KAITAI_PARSERS := $(KAITAI_OUT)/python/ilahrs.py $(KAITAI_OUT)/construct/ilahrs.py

.PHONY: setup-kaitai build-kaitai test-kaitai bench-python

# npm ci again whenever the lock file changes (a stale or missing node_modules).
$(KAITAI_NODE): $(KAITAI_TOOLS)/package.json $(KAITAI_TOOLS)/package-lock.json
	command -v node >/dev/null || { echo "kaitai: node (20+) is needed to run the Kaitai Struct compiler" >&2; exit 1; }
	cd $(KAITAI_TOOLS) && npm ci --no-audit --no-fund --loglevel=error >/dev/null
	touch $@

setup-kaitai: $(KAITAI_NODE)

$(KAITAI_OUT)/%/ilahrs.py: $(KAITAI_KSY) $(KAITAI_TOOLS)/compile.js $(KAITAI_NODE)
	@rm -rf $(@D)
	node $(KAITAI_TOOLS)/compile.js $* $(KAITAI_KSY) $(@D)

build-kaitai: $(KAITAI_PARSERS)

test-kaitai: setup build-kaitai
	$(PY) -m pytest tests/kaitai

bench-python: setup build-kaitai
	$(PY) bench/python/bench_decode.py

SETUP_TARGETS += setup-kaitai
BUILD_TARGETS += build-kaitai
BENCH_TARGETS += bench-python
