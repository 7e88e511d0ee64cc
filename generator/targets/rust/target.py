"""Outputs of the Rust target.

`generated/rust/` is the `ilahrs` crate (no_std, no dependencies): hand-written runtime modules
from `runtime/crate/` (the stream decoder, byte access, errors, frame and sentence codecs, what
every payload table shares, the state machine's lookup) next to modules generated from the spec
(tables, enums, constants, one file per payload table, written out as plain impl blocks).
`generated/rust-conformance/` is the conformance runner, a std binary that depends on the crate by
path: its hand-written sources live with the other runners, in `conformance/runners/rust/`, and
are copied in as the runtime is. Everything is laid out by `rustfmt`.
"""

from __future__ import annotations

import re
from pathlib import Path

from generator import DEFAULT_SPEC, ROOT, build_spec, render
from generator.formatting import FormatterError, run_formatter, tool
from generator.model import Spec
from generator.render import Output, Runtime

from . import filters

FILTERS = filters.FILTERS
GLOBALS = filters.GLOBALS

# Generated from templates: (output path under generated/, template).
_TEMPLATES = (
    ("rust/Cargo.toml", "Cargo.toml.j2"),
    ("rust/README.md", "README.md.j2"),
    ("rust/src/lib.rs", "lib.rs.j2"),
    ("rust/src/error/kind.rs", "error_kind.rs.j2"),
    ("rust/src/frame/layout.rs", "frame_layout.rs.j2"),
    ("rust/src/command.rs", "command.rs.j2"),
    ("rust/src/variant.rs", "variant.rs.j2"),
    ("rust/src/status.rs", "status.rs.j2"),
    ("rust/src/encoding.rs", "encoding.rs.j2"),
    ("rust/src/payload/mod.rs", "payload_mod.rs.j2"),
    ("rust/src/nmea/fields.rs", "nmea_fields.rs.j2"),
    ("rust-conformance/Cargo.toml", "runner_Cargo.toml.j2"),
    ("rust-conformance/src/nmea.rs", "runner_nmea.rs.j2"),
)

# Copied from runtime/: (output path under generated/, source under runtime/).
_RUNTIME = (
    ("rust/src/error.rs", "crate/error.rs"),
    ("rust/src/wire.rs", "crate/wire.rs"),
    ("rust/src/frame.rs", "crate/frame.rs"),
    ("rust/src/command/frames.rs", "crate/command/frames.rs"),
    ("rust/src/status/word.rs", "crate/status/word.rs"),
    ("rust/src/payload/codec.rs", "crate/payload/codec.rs"),
    ("rust/src/nmea.rs", "crate/nmea.rs"),
    ("rust/src/stream.rs", "crate/stream.rs"),
    ("rust/src/io.rs", "crate/io.rs"),
    ("rust/src/tests.rs", "crate/tests.rs"),
)

# The conformance runner's hand-written sources, where a reader looks for a runner.
RUNNER = ROOT / "conformance" / "runners" / "rust"


# Folders that carry the licence texts (render.LICENCE_FILES).
LICENSED = ("rust",)


def outputs(spec: Spec) -> list[Output | Runtime]:
    filters.check_supported(spec)
    files: list[Output | Runtime] = [Output(path, template) for path, template in _TEMPLATES]
    files += [Runtime(path, source) for path, source in _RUNTIME]
    files.append(runner_source("main.rs"))
    files += [
        Output(f"rust/src/payload/{payload.name}.rs", "payload.rs.j2", {"payload": payload})
        for payload in spec.payloads
    ]
    # Encodings the spec defines get their runtime half; the generated half holds their constants.
    for part in ("date", "declination", "calibration_success"):
        if getattr(spec, part) is not None:
            files.append(Runtime(f"rust/src/encoding/{part}.rs", f"crate/encoding/{part}.rs"))
    if spec.state_machine is not None:
        files.append(Output("rust/src/state_machine.rs", "state_machine.rs.j2"))
        files.append(Runtime("rust/src/state_machine/device.rs", "crate/state_machine/device.rs"))
        files.append(runner_source("session.rs"))
    else:
        files.append(runner_source("no_session.rs", "session.rs"))
    return files


def runner_source(source: str, name: str | None = None) -> Output:
    """The runner source `conformance/runners/rust/<source>`, copied to
    `rust-conformance/src/<name>` behind a notice that says where it comes from."""
    text = (RUNNER / source).read_text(encoding="utf-8")
    return Output(f"rust-conformance/src/{name or source}", "runner_source.rs.j2", {"source": source, "text": text})


# How a copied runtime file starts (render.runtime_notice, in Rust comment syntax), and how a
# copied runner source does (runner_source.rs.j2).
_COPIED = ("// Copied from generator/targets/rust/runtime/", "// Copied from conformance/runners/rust/")

# The crate roots rustfmt starts from; it follows their `mod` declarations to every module.
_ROOTS = ("rust/src/lib.rs", "rust-conformance/src/main.rs")


# False only while `format_runtime` lays the runtime sources out.
_STRICT = [True]


def format(files: dict[str, str]) -> dict[str, str]:
    """Every Rust file as rustfmt lays it out (the edition from the crate's Cargo.toml; the runner
    shares it). A copied runtime file must come out unchanged: the runtime is kept formatted as
    it is written (`make format-rust-runtime` formats it)."""
    edition = _edition(files.get("rust/Cargo.toml", ""))
    roots = [root for root in _ROOTS if root in files]
    formatted = run_formatter(
        files,
        (".rs",),
        lambda paths: [tool("rustfmt"), "--edition", edition, *(str(p) for p in paths if _is_root(p, roots))],
    )
    for path, text in files.items():
        if _STRICT[0] and path.endswith(".rs") and _is_copied(text) and formatted[path] != text:
            raise FormatterError(f"rustfmt changes the runtime file behind {path}: run `make format-rust-runtime`")
    return formatted


def format_runtime() -> None:
    """Rewrite the runtime sources as rustfmt lays them out inside the crate rendered from the
    spec (rustfmt needs the crate around a module to follow its `mod` declarations)."""
    spec = build_spec(DEFAULT_SPEC)
    _STRICT[0] = False
    try:
        files = render.render(spec, ["rust"])
    finally:
        _STRICT[0] = True
    for out in outputs(spec):
        if isinstance(out, Runtime):
            body = files[out.path].split("\n", len(render.runtime_notice(spec, "rust", out.source)))[-1]
            source = render.TARGETS_DIR / "rust" / "runtime" / out.source
        elif out.template == "runner_source.rs.j2":
            body = files[out.path].split("\n", _RUNNER_NOTICE_LINES)[-1]
            source = RUNNER / out.context["source"]
        else:
            continue
        if source.read_text(encoding="utf-8") != body:
            source.write_text(body, encoding="utf-8")
            print(f"formatted {source.relative_to(ROOT)}")


def _is_root(path: Path, roots: list[str]) -> bool:
    return any(path.as_posix().endswith("/" + root) for root in roots)


def _is_copied(text: str) -> bool:
    return text.startswith(_COPIED)


# The notice lines in front of a copied runner source (runner_source.rs.j2).
_RUNNER_NOTICE_LINES = 3


def _edition(cargo_toml: str) -> str:
    found = re.search(r'^edition\s*=\s*"(\d+)"', cargo_toml, re.MULTILINE)
    return found.group(1) if found else "2021"
