"""The Rust target: the `ilahrs` crate (no_std) and its conformance runner."""
