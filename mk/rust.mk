# Rust: the ilahrs crate (generated/rust, no_std) and its conformance runner (generated/rust-conformance),
# the seeded property tests (tests/rust), the benchmark (bench/rust), the Cortex-M4 footprint and the fuzz
# targets (fuzz/rust).
#
# Cargo writes Cargo.lock beside the manifest it builds, and generated/ may hold only generated files: the
# generated crates are built from copies under build/rust/crates (mtimes kept, so builds stay incremental).

RUST_BUILD := $(BUILD)/rust
RUST_CRATES := $(RUST_BUILD)/crates
RUST_TARGET := $(ROOT)/$(RUST_BUILD)/target
CARGO := CARGO_TARGET_DIR=$(RUST_TARGET) cargo
RUST_LIB := $(RUST_CRATES)/rust/Cargo.toml
RUST_RUNNER_CRATE := $(RUST_CRATES)/rust-conformance/Cargo.toml
RUST_RUNNER := $(RUST_BUILD)/target/release/ilahrs-conformance
RUST_FOOTPRINT_TARGET := thumbv7em-none-eabihf

.PHONY: setup-rust rust-crates build-rust lint-rust test-rust bench-rust footprint-rust fuzz-rust

setup-rust:
	@command -v cargo >/dev/null || { echo "setup-rust: cargo not found (install Rust stable)" >&2; exit 1; }
	@cargo clippy --version >/dev/null 2>&1 || rustup component add clippy >/dev/null 2>&1 || true
	@cargo fmt --version >/dev/null 2>&1 || rustup component add rustfmt >/dev/null 2>&1 || true

rust-crates: setup-rust
	@for crate in rust rust-conformance; do \
	  mkdir -p $(RUST_CRATES)/$$crate; \
	  find $(RUST_CRATES)/$$crate -mindepth 1 -maxdepth 1 ! -name Cargo.lock -exec rm -rf {} +; \
	  cp -a generated/$$crate/. $(RUST_CRATES)/$$crate/; \
	done

build-rust: rust-crates
	$(CARGO) build --quiet --release --manifest-path $(RUST_RUNNER_CRATE)

lint-rust: rust-crates
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

test-rust: rust-crates
	$(CARGO) build --quiet --manifest-path $(RUST_LIB) --no-default-features
	$(CARGO) test --quiet --manifest-path $(RUST_LIB)
	$(CARGO) test --quiet --manifest-path $(RUST_LIB) --all-features
	$(CARGO) test --quiet --release --manifest-path tests/rust/Cargo.toml

SETUP_TARGETS += setup-rust
BUILD_TARGETS += build-rust
LINT_TARGETS += lint-rust
TEST_TARGETS += test-rust
