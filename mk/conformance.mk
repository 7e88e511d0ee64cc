# Conformance: every registered binding (conformance/bindings/*.json) against the vector suites.
#
#   make conformance                         every binding, conformance/vectors
#   make conformance VECTORS=dir             any directory of suites in the same format
#   make conformance BINDINGS=python,c       some bindings
#   make vectors                             rewrite conformance/vectors from conformance/tools/make_vectors.py
#                                            (conformance/tools/suites/: a module and a case file per suite)
#
# The harness is stdlib-only Python; it starts each runner once and prints a binding x suite table.
# tests/test_conformance*.py run under the root pytest run (test-python).

VECTORS ?= conformance/vectors
BINDINGS ?=
CONFORMANCE_ARGS ?=

.PHONY: vectors check-vectors

conformance: setup build
	$(PY) conformance/harness.py --vectors $(VECTORS) $(if $(BINDINGS),--bindings $(BINDINGS)) $(CONFORMANCE_ARGS)

vectors: setup
	$(PY) conformance/tools/make_vectors.py

# The committed suites are exactly what the script writes (no hand edits).
check-vectors: setup
	$(PY) conformance/tools/make_vectors.py --check

CHECK_TARGETS += check-vectors
