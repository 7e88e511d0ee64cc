# Conformance: every registered binding (conformance/bindings/*.json) against the vector suites.
#
#   make conformance                         every binding, conformance/vectors
#   make conformance VECTORS=dir             any directory of suites in the same format
#   make conformance BINDINGS=python,c       some bindings
#   make vectors                             rewrite conformance/vectors from conformance/tools/make_vectors.py
#                                            (conformance/tools/suites/: a module and a case file per suite)
#
#   make test-conformance-example           the example runner of a foreign implementation
#                                            (conformance/examples/javascript, Node 20) on its kinds,
#                                            with its declaration and expected-failure list
#   make conformance-report                  every registered binding and the JavaScript example side
#                                            by side: build/conformance-report.html (one self-contained
#                                            page, ilahrs.conformance.html) and .json; BINDINGS=... too
#
# The harness is the Python package's (ilahrs.conformance, also `ilahrs conformance` once installed;
# conformance/harness.py runs it with the repository's defaults); stdlib-only, it starts each runner
# once and prints a binding x suite table. tests/conformance/ run under the root pytest run
# (test-python), among them the installed package in a fresh virtual environment and the live mode.

VECTORS ?= conformance/vectors
BINDINGS ?=
CONFORMANCE_ARGS ?=

EXAMPLE_KINDS := checksum,frame_decode,frame_encode,ack

.PHONY: vectors check-vectors test-conformance-example conformance-report

conformance: setup build
	$(PY) conformance/harness.py --vectors $(VECTORS) $(if $(BINDINGS),--bindings $(BINDINGS)) $(CONFORMANCE_ARGS)

vectors: setup
	$(PY) conformance/tools/make_vectors.py

# The committed suites are exactly what the script writes (no hand edits), and their version has the
# bump each change since the last release tag needs (as spec-compat for the spec; no tag yet: skipped).
check-vectors: setup
	$(PY) conformance/tools/make_vectors.py --check

CHECK_TARGETS += check-vectors

# A runner in a second language joins with no registration: --kinds holds it to the kinds it does.
test-conformance-example: setup
	@command -v node >/dev/null || { echo "test-conformance-example: needs Node.js 20 (node)" >&2; exit 1; }
	mkdir -p $(BUILD)
	$(PY) conformance/harness.py --command "node conformance/examples/javascript/runner.mjs" \
		--name javascript --kinds $(EXAMPLE_KINDS) --options - --junit $(BUILD)/conformance-example.xml \
		--declaration conformance/examples/javascript/declaration.json \
		--expected-failures conformance/examples/javascript/expected-failures.json

TEST_TARGETS += test-conformance-example

# The report across implementations: the registered bindings, and the example runner as a --command
# beside them (held to its kinds as above). Written even when something fails (then make fails too).
conformance-report: setup build
	@command -v node >/dev/null || { echo "conformance-report: needs Node.js 20 (node)" >&2; exit 1; }
	mkdir -p $(BUILD)
	$(PY) conformance/harness.py --vectors $(VECTORS) --bindings $(or $(BINDINGS),all) \
		--command "node conformance/examples/javascript/runner.mjs" --name javascript \
		--kinds $(EXAMPLE_KINDS) --options - $(CONFORMANCE_ARGS) \
		--declaration conformance/examples/javascript/declaration.json \
		--expected-failures conformance/examples/javascript/expected-failures.json \
		--report $(BUILD)/conformance-report.html --json $(BUILD)/conformance-report.json
