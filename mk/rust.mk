# Rust: the ilahrs crate (generated/rust, no_std) and its conformance runner (generated/rust-conformance),
# the seeded property and differential tests (tests/rust), the benchmark (bench/rust), the Cortex-M4
# footprint; the fuzz targets (fuzz/rust) are run by mk/fuzz.mk.
#
# The crates are hand-written runtime modules (generator/targets/rust/runtime/, copied) next to
# modules generated from the spec (generator/targets/rust/templates/); the runner's hand-written
# sources live with the other runners, in conformance/runners/rust/, and are copied the same way.
# rustfmt lays all of them out, so `cargo fmt --check` holds by construction and lint-rust checks
# the runtime and the runner sources through the crates.
#
# The generated crates build in place; build products go to build/rust/target, and the Cargo.lock
# cargo writes beside a generated manifest is ignored (by git and by the drift check).

RUST_BUILD := $(BUILD)/rust
RUST_TARGET := $(ROOT)/$(RUST_BUILD)/target
CARGO := CARGO_TARGET_DIR=$(RUST_TARGET) cargo
RUST_LIB := generated/rust/Cargo.toml
RUST_RUNNER_CRATE := generated/rust-conformance/Cargo.toml
RUST_RUNNER := $(RUST_BUILD)/target/release/ilahrs-conformance
RUST_FOOTPRINT_TARGET := thumbv7em-none-eabihf

# rustdoc warnings are errors, a link that resolves to nothing among them; lint-rust also refuses
# a link escaped into literal text (`\[` before a backquote), which rustdoc cannot see.
RUSTDOC_STRICT := -D warnings -D rustdoc::broken_intra_doc_links -D rustdoc::private_intra_doc_links

.PHONY: setup-rust build-rust lint-rust test-rust bench-rust footprint-rust format-rust-runtime

setup-rust:
	@command -v cargo >/dev/null || { echo "setup-rust: cargo not found (install Rust stable)" >&2; exit 1; }
	@cargo clippy --version >/dev/null 2>&1 || rustup component add clippy >/dev/null 2>&1 || true
	@cargo fmt --version >/dev/null 2>&1 || rustup component add rustfmt >/dev/null 2>&1 || true

# The hand-written runtime (generator/targets/rust/runtime/) must be laid out as rustfmt writes it:
# `make generate` refuses it otherwise. This rewrites it so, and the runner's sources in
# conformance/runners/rust/ too (inside crates rendered from the spec, since rustfmt follows
# `mod` declarations).
format-rust-runtime: setup
	$(PY) -c 'from generator.targets.rust.target import format_runtime; format_runtime()'

build-rust: setup-rust
	$(CARGO) build --quiet --release --manifest-path $(RUST_RUNNER_CRATE)

lint-rust: setup-rust
	cargo fmt --check --manifest-path $(RUST_LIB)
	cargo fmt --check --manifest-path $(RUST_RUNNER_CRATE)
	cargo fmt --check --manifest-path tests/rust/Cargo.toml
	cargo fmt --check --manifest-path bench/rust/Cargo.toml
	$(CARGO) clippy --quiet --manifest-path $(RUST_LIB) --all-targets -- -D warnings
	$(CARGO) clippy --quiet --manifest-path $(RUST_LIB) --all-targets --no-default-features -- -D warnings
	$(CARGO) clippy --quiet --manifest-path $(RUST_LIB) --all-targets --all-features -- -D warnings
	$(CARGO) clippy --quiet --manifest-path $(RUST_RUNNER_CRATE) -- -D warnings
	$(CARGO) clippy --quiet --manifest-path tests/rust/Cargo.toml --all-targets -- -D warnings
	$(CARGO) clippy --quiet --manifest-path bench/rust/Cargo.toml -- -D warnings
	RUSTDOCFLAGS="$(RUSTDOC_STRICT)" $(CARGO) doc --quiet --no-deps --manifest-path $(RUST_LIB)
	RUSTDOCFLAGS="$(RUSTDOC_STRICT)" $(CARGO) doc --quiet --no-deps --all-features --manifest-path $(RUST_LIB)
	@if grep -rn '\\\[`' generated/rust/src; then \
	  echo "lint-rust: an intra-doc link escaped into literal text (above); escape only spec prose" >&2; exit 1; fi

# The differential test runs the Rust and Python runners on the same seeded, mutated inputs
# (tests/rust/differential.py) and checks sessions against the spec model. A spec with one more
# command and payload table (tests/c/extend_spec.py) must give a crate that is laid out as
# rustfmt writes it, clippy-clean, and passes its unit tests, with no template change.
RUST_EXTENDED := $(RUST_BUILD)/extended

test-rust: build-rust
	$(PY) tests/c/extend_spec.py $(RUST_EXTENDED)/ilahrs.yaml
	$(PY) -m generator --spec $(RUST_EXTENDED)/ilahrs.yaml --out $(RUST_EXTENDED)/generated --target rust >/dev/null
	cargo fmt --check --manifest-path $(RUST_EXTENDED)/generated/rust/Cargo.toml
	$(CARGO) clippy --quiet --manifest-path $(RUST_EXTENDED)/generated/rust/Cargo.toml --all-targets -- -D warnings
	$(CARGO) test --quiet --manifest-path $(RUST_EXTENDED)/generated/rust/Cargo.toml
	$(CARGO) test --quiet --manifest-path $(RUST_LIB) --no-default-features
	$(CARGO) test --quiet --manifest-path $(RUST_LIB)
	$(CARGO) test --quiet --manifest-path $(RUST_LIB) --all-features
	$(CARGO) test --quiet --release --manifest-path tests/rust/Cargo.toml
	$(CARGO) test --quiet --release --manifest-path tests/rust/Cargo.toml --features ilahrs/small
	$(PY) tests/rust/differential.py

SETUP_TARGETS += setup-rust
BUILD_TARGETS += build-rust
LINT_TARGETS += lint-rust
TEST_TARGETS += test-rust

# --- bench: the Rust decoder next to C's and a byte-summing loop, on the same capture ----------
RUST_CAPTURE := $(BUILD)/bench/capture.bin
C_BENCH := $(BUILD)/c/bench_stream

bench-rust: setup-rust
	$(CARGO) build --quiet --release --manifest-path bench/rust/Cargo.toml
	@if [ -x $(C_BENCH) ]; then $(C_BENCH) | tee $(RUST_BUILD)/bench-c.txt; else echo "c: $(C_BENCH) not built (make build-c); no C numbers" | tee $(RUST_BUILD)/bench-c.txt; fi
	@$(RUST_BUILD)/target/release/ilahrs-bench $(RUST_CAPTURE) | tee $(RUST_BUILD)/bench-rust.txt
	@c=$$(sed -n 's/^c_stream_next: \([0-9.]*\) MiB\/s/\1/p' $(RUST_BUILD)/bench-c.txt); \
	 r=$$(sed -n 's/^rust_stream: \([0-9.]*\) MiB\/s/\1/p' $(RUST_BUILD)/bench-rust.txt); \
	 if [ -n "$$c" ] && [ -n "$$r" ]; then awk -v r="$$r" -v c="$$c" 'BEGIN { printf "rust_stream / c_stream_next: %.2f (target >= 0.90)\n", r / c }'; fi

# --- footprint: code and RAM on a Cortex-M4, when the target can be installed -------------------
footprint-rust: setup-rust
	@if ! rustup target list --installed 2>/dev/null | grep -q '^$(RUST_FOOTPRINT_TARGET)$$' \
	    && ! rustup target add $(RUST_FOOTPRINT_TARGET) >/dev/null 2>&1; then \
	  echo "footprint-rust: the $(RUST_FOOTPRINT_TARGET) target cannot be installed here; no numbers"; exit 0; fi; \
	CARGO_TARGET_DIR=$(RUST_TARGET) RUSTFLAGS="-C link-arg=-T$(ROOT)/bench/rust/footprint/link.x" \
	  cargo build --quiet --release --target $(RUST_FOOTPRINT_TARGET) --manifest-path bench/rust/footprint/Cargo.toml; \
	elf=$(RUST_TARGET)/$(RUST_FOOTPRINT_TARGET)/release/ilahrs-footprint; \
	size=$$(command -v arm-none-eabi-size || command -v size); \
	$$size -A $$elf | awk '/^\.(text|rodata|data|bss|vector_table) / { s[$$1] = $$2 } \
	  END { printf "rust_footprint_flash: %d bytes (.text %d, .rodata %d, .data %d)\nrust_footprint_static_ram: %d bytes (.data + .bss)\n", \
	  s[".text"] + s[".rodata"] + s[".data"] + s[".vector_table"], s[".text"], s[".rodata"], s[".data"], s[".data"] + s[".bss"] }'
	@$(CARGO) build --quiet --release --manifest-path bench/rust/Cargo.toml
	@$(RUST_BUILD)/target/release/ilahrs-bench --sizes

BENCH_TARGETS += bench-rust
FOOTPRINT_TARGETS += footprint-rust
