"""The conformance suites: reproducible from their script, documented, complete, and in the format.

The vectors are written by conformance/tools/make_vectors.py from its own oracle
(conformance/tools/oracle.py), never by the generator or a binding. These tests hold the
committed JSON to that script, every vector to a note, the suites to what they must cover, and
the oracle's independent table layouts to the spec's (two derivations of the ICD that must agree).
"""

from __future__ import annotations

import ast
import importlib.util
import json
import sys
from collections import Counter
from pathlib import Path
from types import ModuleType
from typing import Any

import jsonschema
import pytest

from generator import build_spec

ROOT = Path(__file__).resolve().parent.parent
CONFORMANCE = ROOT / "conformance"
VECTORS = CONFORMANCE / "vectors"
TOOLS = CONFORMANCE / "tools"
SPEC = build_spec()


def _module(name: str) -> ModuleType:
    """A script of conformance/tools (not a package), loaded under its own name, as it loads its sibling."""
    if name in sys.modules:
        return sys.modules[name]
    spec = importlib.util.spec_from_file_location(name, TOOLS / f"{name}.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


ORACLE = _module("oracle")
MAKE_VECTORS = _module("make_vectors")


def _suites() -> dict[str, dict[str, Any]]:
    return {p.stem: json.loads(p.read_text(encoding="utf-8")) for p in sorted(VECTORS.glob("*.json"))}


SUITES = _suites()


def _vectors(kind: str | None = None) -> list[dict[str, Any]]:
    return [v for s in SUITES.values() for v in s["vectors"] if kind is None or v["kind"] == kind]


def test_script_reproduces_the_committed_suites() -> None:
    written = MAKE_VECTORS.build_all()
    assert sorted(written) == sorted(p.name for p in VECTORS.glob("*.json")), "a suite file not written by the script"
    for name, text in written.items():
        assert (VECTORS / name).read_text(encoding="utf-8") == text, (
            f"conformance/vectors/{name} differs from what conformance/tools/make_vectors.py writes: "
            "edit the script and run `make vectors`, never the JSON")


def test_script_is_deterministic() -> None:
    assert MAKE_VECTORS.build_all() == MAKE_VECTORS.build_all()


def test_every_vector_says_where_its_bytes_come_from() -> None:
    missing = [v["id"] for v in _vectors() if not str(v.get("note", "")).strip()]
    assert not missing


@pytest.mark.parametrize("name", sorted(SUITES))
def test_suite_follows_the_schema(name: str) -> None:
    schema = json.loads((CONFORMANCE / "vectors.schema.json").read_text(encoding="utf-8"))
    jsonschema.Draft202012Validator.check_schema(schema)
    jsonschema.Draft202012Validator(schema).validate(SUITES[name])
    assert SUITES[name]["suite"] == name
    ids = [v["id"] for v in SUITES[name]["vectors"]]
    assert len(ids) == len(set(ids))


def test_oracle_is_independent_of_generator_and_bindings() -> None:
    for path in TOOLS.glob("*.py"):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        imported = {alias.name.split(".")[0] for node in ast.walk(tree) if isinstance(node, ast.Import)
                    for alias in node.names}
        imported |= {(node.module or "").split(".")[0] for node in ast.walk(tree) if isinstance(node, ast.ImportFrom)}
        # Without yaml it cannot read the spec either: everything it knows is written from the ICD.
        assert not imported & {"generator", "ilahrs", "yaml", "kaitaistruct", "construct"}, path.name


def test_error_kinds_are_the_specs() -> None:
    kinds = {e.name for e in SPEC.errors}
    used = {v["expect"]["error"] for v in _vectors() if isinstance(v["expect"], dict) and "error" in v["expect"]}
    assert used <= kinds


# --- what each suite must cover -----------------------------------------------------------------


def test_appendix_c_has_every_row_verbatim() -> None:
    vectors = SUITES["appendix-c"]["vectors"]
    encoded = {v["input"]["command"]: v["expect"] for v in vectors
               if v["kind"] == "command_encode" and isinstance(v["expect"], str)}
    assert set(encoded) == {c.name for c in SPEC.commands} and len(encoded) == 26
    for c in SPEC.commands:
        assert bytes.fromhex(encoded[c.name])[6] == c.code
    decoded = {v["id"]: v["expect"] for v in vectors if v["kind"] == "command_decode"}
    assert decoded["command_decode/Stop"]["names"] == decoded["command_decode/ExitClb"]["names"] == ["ExitClb", "Stop"]


def test_checksum_suite_carries_and_wraps() -> None:
    by_id = {v["id"]: v for v in SUITES["checksum"]["vectors"]}
    assert by_id["checksum/Stop-carries"]["expect"] > 0xFF
    wrapped = by_id["checksum/wraps-to-zero"]
    assert sum(bytes.fromhex(wrapped["input"])) > 0xFFFF and wrapped["expect"] == 0


def test_acks_cover_every_command_and_parameter_block() -> None:
    inputs = {bytes.fromhex(v["input"]) for v in SUITES["acks"]["vectors"] if isinstance(v["expect"], str)}
    for c in SPEC.commands:
        assert bytes.fromhex("AA5500000700") + bytes([c.code]) in {i[:7] for i in inputs}, c.name
    blocks = {p.name for c in SPEC.commands if c.parameter_block for p in SPEC.payloads if p.name == c.parameter_block}
    data_sizes = {len(i) - 8 for i in inputs if i[2] == 1}
    assert {p.size for p in SPEC.payloads if p.name in blocks} <= data_sizes


def test_payload_suite_covers_every_table_both_ways() -> None:
    counts: Counter[tuple[str, str, str]] = Counter()
    for v in SUITES["payloads"]["vectors"]:
        outcome = "error" if isinstance(v["expect"], dict) and "error" in v["expect"] else "ok"
        counts[(v["input"]["type"], v["kind"], outcome)] += 1
    for p in SPEC.payloads:
        assert counts[(p.name, "payload_decode", "ok")] >= 3, p.name
        assert counts[(p.name, "payload_encode", "ok")] >= 3, p.name
        assert counts[(p.name, "payload_encode", "error")] >= 1, p.name
        assert counts[(p.name, "payload_decode", "error")] >= 2, p.name


def test_payload_suite_checks_every_variant_scale() -> None:
    variants = {v["input"].get("variant") for v in SUITES["payloads"]["vectors"] if v["kind"] == "payload_decode"}
    assert {v.name for v in SPEC.variants} <= variants


def test_frames_suite_has_every_decode_error() -> None:
    errors = {(v["expect"]["error"], v["expect"].get("offset")) for v in SUITES["frames"]["vectors"]
              if v["kind"] == "frame_decode" and "error" in v["expect"]}
    for expected in [("truncated", 0), ("bad_header", 0), ("truncated", 1), ("bad_header", 1), ("bad_message_type", 2),
                     ("bad_length", 4), ("bad_checksum", 7), ("trailing_data", 9)]:
        assert expected in errors, expected


def test_stream_suite_size_and_soak() -> None:
    assert (VECTORS / "streams.json").stat().st_size < 1_000_000
    soak = next(v for v in SUITES["streams"]["vectors"] if v["id"] == "stream/soak-2500")
    frames = [e for e in soak["expect"]["events"] if "frame" in e]
    assert len(frames) >= 1000 and len(soak["input"]["chunks"]) >= 100
    sweep = [v for v in SUITES["streams"]["vectors"] if v["id"].startswith("stream/sweep-longest-frame-")]
    assert len(sweep) == SPEC.frame.max_length + 2


# --- the oracle against the spec: two derivations of the ICD tables -------------------------------

_ORACLE_TYPES = {"u8": "u8", "u16": "u16", "s16": "s16", "f32": "f32", "char": "char", "reserved": "reserved"}


@pytest.mark.parametrize("payload", SPEC.payloads, ids=lambda p: p.name)
def test_oracle_layout_matches_the_spec(payload: Any) -> None:
    _, size, fields = ORACLE.TABLES[payload.name]
    assert size == payload.size
    ours = [(f.name, f.type, f.size) for f in fields]
    theirs = [(f.name, f.type.name, f.size) for f in payload.fields]
    assert ours == theirs
    offset = 0
    for oracle_field, field in zip(fields, payload.fields, strict=True):
        assert offset == field.offset, field.name
        offset += oracle_field.size
        if field.range is not None and field.encoding != "date":
            assert (oracle_field.lo, oracle_field.hi) == field.range, field.name


def test_oracle_variants_match_the_spec() -> None:
    assert {v.name: dict(v.values) for v in SPEC.variants} == ORACLE.VARIANTS


def test_oracle_frame_bounds_match_the_spec() -> None:
    assert (SPEC.frame.min_length, SPEC.frame.max_length) == (ORACLE.MIN_LENGTH, ORACLE.MAX_LENGTH)
    assert SPEC.nmea is not None
    assert SPEC.nmea.max_length == ORACLE.MAX_SENTENCE
