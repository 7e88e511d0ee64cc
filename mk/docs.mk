# Docs: the state diagram, drawn by Graphviz from the generated .dot file.
# The SVG carries the sha256 of the .dot it was drawn from; `make check` verifies that hash
# (the SVG bytes depend on the machine's fonts, the hash does not).

DOT_FILE := generated/docs/state-machine.dot
SVG_FILE := generated/docs/state-machine.svg

.PHONY: docs check-docs setup-graphviz

setup-graphviz:
	@command -v dot >/dev/null || tools/need --tool dot graphviz

docs: setup-graphviz
	@hash=$$(sha256sum $(DOT_FILE) | cut -d' ' -f1); \
	if ! grep -q "drawn from state-machine.dot sha256 $$hash" $(SVG_FILE) 2>/dev/null; then \
		dot -Tsvg $(DOT_FILE) | sed "1a <!-- drawn from state-machine.dot sha256 $$hash -->" > $(SVG_FILE).tmp; \
		mv $(SVG_FILE).tmp $(SVG_FILE); echo "drew $(SVG_FILE)"; \
	fi

check-docs:
	@hash=$$(sha256sum $(DOT_FILE) | cut -d' ' -f1); \
	grep -q "drawn from state-machine.dot sha256 $$hash" $(SVG_FILE) || \
		{ echo "$(SVG_FILE) was not drawn from the current $(DOT_FILE): run make generate" >&2; exit 1; }

GENERATE_TARGETS += docs
CHECK_TARGETS += check-docs
