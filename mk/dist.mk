# Release artifacts and the spec's compatibility with the last release.
#
#   make dist          into dist/ (DIST=dir elsewhere), each named with the spec's version V:
#                        ilahrs-V-py3-none-any.whl, ilahrs-V.tar.gz   the Python package (twine check)
#                        ilahrs-V.crate                               the Rust crate (cargo package: built
#                                                                     from the packaged files alone)
#                        ilahrs-c-V.tar.gz                            the C library: sources, CMake package,
#                                                                     pkg-config file, licences
#                        ilahrs-V.ksy                                 the Kaitai Struct description
#                        ilahrs-wireshark-V.lua                       the Wireshark dissector plugin
#                        SHA256SUMS                                   `sha256sum -c SHA256SUMS` checks them
#                      built in $(BUILD)/dist-staging and moved into place whole: a failed build leaves
#                      the previous dist/ as it was.
#   make spec-compat   `python -m generator diff --check-version` against the last release tag (part of
#                      `make check`; says so and passes when the repository has no tag yet).

DIST ?= dist
DIST_STAGE := $(BUILD)/dist-staging
DIST_CARGO := $(BUILD)/dist-cargo

.PHONY: dist spec-compat

dist: setup
	@rm -rf $(DIST_STAGE) && mkdir -p $(DIST_STAGE)/out $(DIST_STAGE)/python
	@version=$$($(PY) -c 'import ilahrs; print(ilahrs.__version__)'); \
	out=$(DIST_STAGE)/out; \
	echo "dist: ilahrs $$version"; \
	cp -R generated/python/README.md generated/python/pyproject.toml generated/python/LICENSE-MIT \
	      generated/python/LICENSE-APACHE generated/python/ilahrs $(DIST_STAGE)/python/; \
	find $(DIST_STAGE)/python -name __pycache__ -prune -exec rm -rf {} +; \
	$(PY) -m build --no-isolation --sdist --wheel --outdir $$out $(DIST_STAGE)/python >$(DIST_STAGE)/python.log 2>&1 \
	    || { cat $(DIST_STAGE)/python.log >&2; exit 1; }; \
	$(VENV)/bin/twine check --strict $$out/ilahrs-$$version.tar.gz $$out/ilahrs-$$version-py3-none-any.whl; \
	cargo package --quiet --allow-dirty --manifest-path generated/rust/Cargo.toml --target-dir $(ROOT)/$(DIST_CARGO); \
	cp $(DIST_CARGO)/package/ilahrs-$$version.crate $$out/; \
	tar --sort=name --owner=0 --group=0 --numeric-owner --mtime=@0 \
	    --exclude=build --exclude='*.o' --transform "s,^generated/c,ilahrs-c-$$version," \
	    -cf - generated/c | gzip -n >$$out/ilahrs-c-$$version.tar.gz; \
	cp generated/kaitai/ilahrs.ksy $$out/ilahrs-$$version.ksy; \
	cp generated/wireshark/ilahrs.lua $$out/ilahrs-wireshark-$$version.lua; \
	(cd $$out && sha256sum -- * >SHA256SUMS)
	@rm -rf $(DIST).old && if [ -e $(DIST) ]; then mv $(DIST) $(DIST).old; fi
	@mv $(DIST_STAGE)/out $(DIST) && rm -rf $(DIST).old $(DIST_STAGE)
	@cd $(DIST) && ls -l --time-style=+ | awk 'NR > 1 { printf "%10d  %s\n", $$5, $$NF }'

# The last tag reachable from HEAD is the last release; its spec is what users have vendored.
spec-compat: setup
	@tag=$$(git describe --tags --abbrev=0 2>/dev/null || true); \
	if [ -z "$$tag" ]; then echo "spec-compat: no release tag yet, nothing to compare the spec with: skipped"; \
	else $(PY) -m generator diff --against "$$tag" --check-version --junit $(BUILD)/spec-compat.xml; fi

CHECK_TARGETS += spec-compat
