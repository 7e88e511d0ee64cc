"""Outputs of the Rust target.

`generated/rust/` is the `ilahrs` crate (no_std, no dependencies): one module per concern and one
file per payload table. `generated/rust-conformance/` is the conformance runner, a std binary that
depends on the crate by path.
"""

from __future__ import annotations

from generator.model import Spec
from generator.render import Output

from . import filters

FILTERS = filters.FILTERS
GLOBALS = filters.GLOBALS

# (output path under generated/rust/, template): one template per file kind.
_CRATE_FILES = (
    ("Cargo.toml", "Cargo.toml.j2"),
    ("README.md", "README.md.j2"),
    ("src/lib.rs", "lib.rs.j2"),
    ("src/error.rs", "error.rs.j2"),
    ("src/wire.rs", "wire.rs.j2"),
    ("src/frame.rs", "frame.rs.j2"),
    ("src/command.rs", "command.rs.j2"),
    ("src/variant.rs", "variant.rs.j2"),
    ("src/status.rs", "status.rs.j2"),
    ("src/encoding.rs", "encoding.rs.j2"),
    ("src/payload/mod.rs", "payload_mod.rs.j2"),
    ("src/nmea.rs", "nmea.rs.j2"),
    ("src/stream.rs", "stream.rs.j2"),
    ("src/io.rs", "io.rs.j2"),
    ("src/tests.rs", "tests.rs.j2"),
)

_RUNNER_FILES = (
    ("Cargo.toml", "runner_Cargo.toml.j2"),
    ("src/main.rs", "runner_main.rs.j2"),
)


def outputs(spec: Spec) -> list[Output]:
    files = [Output(f"rust/{path}", template) for path, template in _CRATE_FILES]
    files += [
        Output(f"rust/src/payload/{payload.name}.rs", "payload.rs.j2", {"payload": payload})
        for payload in spec.payloads
    ]
    if spec.state_machine is not None:
        files.append(Output("rust/src/state_machine.rs", "state_machine.rs.j2"))
    files += [Output(f"rust-conformance/{path}", template) for path, template in _RUNNER_FILES]
    return files
