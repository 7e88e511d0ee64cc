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

ROOT = Path(__file__).resolve().parents[2]
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
SESSION_SUITE = importlib.import_module("suites.sessions")  # importable once make_vectors put tools/ on the path


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
    for path in TOOLS.rglob("*.py"):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        imported = {alias.name.split(".")[0] for node in ast.walk(tree) if isinstance(node, ast.Import)
                    for alias in node.names}
        imported |= {(node.module or "").split(".")[0] for node in ast.walk(tree) if isinstance(node, ast.ImportFrom)}
        # Without yaml it cannot read the spec either: everything it knows is written from the ICD.
        # suites/levels.py alone reads the spec (errata, transitions' errata, commands' outputs) for
        # the levels and requirements of vectors, never for an expectation.
        spec_reader = {"yaml"} if path.name == "levels.py" else set()
        banned = {"generator", "ilahrs", "kaitaistruct", "construct", "yaml"} - spec_reader
        assert not imported & banned, path.name


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


# --- sessions: the device state machine -----------------------------------------------------------

DEVICE = _module("device_oracle")
assert SPEC.state_machine is not None
MACHINE = SPEC.state_machine

# Where the oracle (the ICD and the errata, transcribed again) and the spec's `state_machine` table
# give different answers, keyed by (state, input). Their vectors fail for every binding that follows
# the table until the spec is corrected. A new difference fails this test: find out which side the
# ICD supports and correct that side, or record it here with the reason.
# Pairs where the spec's table and the independent transcription of the ICD may differ, with the
# reason. Empty: every difference is a failure.
SPEC_DISAGREEMENTS: dict[tuple[str, str], str] = {}


def _spec_step(state: str, item: tuple[str, Any], legacy: bool) -> tuple[str, tuple[str, tuple[str, ...]] | None]:
    """The spec's table for one input: the event it names and (next state, sends) or None."""
    kind, value = item
    if kind == "command":
        command = SPEC.command_in_mode(value, MACHINE.state(state).mode)
        event = "unknown" if command is None else command.name
    elif kind == "data":
        expects = MACHINE.state(state).expects
        event = "parameter_block" if expects is not None and SPEC.payload(expects).size == value else "other_message"
    else:
        event = value
    row = MACHINE.lookup(state, event, legacy=legacy)
    return event, None if row is None else (state if row.to == "same" else row.to, tuple(row.send))


def test_oracle_states_are_the_specs() -> None:
    assert tuple(s.name for s in MACHINE.states) == DEVICE.STATES
    assert {s.name: s.mode for s in MACHINE.states} == DEVICE.MODES
    assert {s.name: s.expects for s in MACHINE.states if s.expects is not None} == DEVICE.EXPECTS
    assert MACHINE.initial == DEVICE.IDLE
    events = {e.name for e in MACHINE.events}
    # `unknown` is what a code outside Table C.1 is named (the oracle's command_event).
    assert set(DEVICE.EVENTS) | {DEVICE.PARAMETER_BLOCK, DEVICE.OTHER_MESSAGE, "unknown"} == events
    assert set(DEVICE.SOURCES) == set(DEVICE.STATES)


def test_oracle_state_machine_against_the_spec() -> None:
    """Every input in every state, on current and on legacy firmware: two transcriptions of section 6."""
    firmwares = [None, *sorted({t.firmware_before for t in MACHINE.transitions if t.firmware_before})]
    differences = {}
    for firmware in firmwares:
        # The current firmware, and a version just before each `firmware_before` (legacy).
        legacy = firmware is not None
        version = None if firmware is None else _just_before(firmware)
        for state in DEVICE.STATES:
            for item in DEVICE.inputs():
                ours_event = (DEVICE.command_event(item[1], state) if item[0] == "command" else
                              DEVICE.data_event(item[1], state) if item[0] == "data" else item[1])
                ours = (ours_event, DEVICE.react(state, ours_event, version))
                theirs = _spec_step(state, item, legacy)
                if ours != theirs:
                    differences[(state, SESSION_SUITE.input_label(item))] = (firmware, ours, theirs)
    unexplained = {k: v for k, v in differences.items() if k not in SPEC_DISAGREEMENTS}
    assert not unexplained, unexplained


def _just_before(version: str) -> str:
    """4.9.9.0 -> 4.9.8.0: a version older than the given one."""
    parts = [int(p) for p in version.split(".")]
    for i in reversed(range(len(parts))):
        if parts[i] > 0:
            parts[i] -= 1
            return ".".join(map(str, parts))
    raise ValueError(version)


def test_sessions_cover_every_input_in_every_state() -> None:
    """Each state of the spec, reached from power-up, then each command code of the spec, an unknown
    code, a data message of each parameter block's size and of another size, and each timer event."""
    vectors = {v["id"]: v for v in SUITES["sessions"]["vectors"]}
    codes = sorted({c.code for c in SPEC.commands})
    unknown = min(set(range(256)) - set(codes))
    sizes = {p.size for p in SPEC.parameter_blocks}
    timers = {e.name for e in MACHINE.events} - {"parameter_block", "other_message", "unknown"}
    for state in MACHINE.states:
        labels = {v["id"].rsplit("/", 1)[1]: v for k, v in vectors.items() if k.startswith(f"step/{state.name}/")}
        wanted = {f"0x{c:02X}" for c in [*codes, unknown]} | {f"data-{n}" for n in sizes} | timers
        assert wanted <= set(labels), (state.name, wanted - set(labels))
        assert any(label.startswith("data-") and int(label[5:]) not in sizes for label in labels), state.name
        for v in labels.values():
            steps = v["expect"]["steps"]
            assert (steps[-2]["state"] if len(steps) > 1 else MACHINE.initial) == state.name, v["id"]
            assert v["expect"]["state"] == steps[-1]["state"]


def test_sessions_cover_the_flows() -> None:
    ids = {v["id"] for v in SUITES["sessions"]["vectors"]}
    for c in SPEC.commands:
        if c.starts_mode == "continuous":
            assert f"flow/continuous/{c.name}" in ids
        if c.starts_mode == "on_request":
            assert f"flow/on-request/{c.name}" in ids
    for state in MACHINE.states:
        assert f"flow/0xFE/{state.name}" in ids
    firmwares = {v["input"].get("firmware") for v in SUITES["sessions"]["vectors"]}
    for before in {t.firmware_before for t in MACHINE.transitions if t.firmware_before}:
        assert before in firmwares and _just_before(before) in firmwares
    for prefix in ("flow/load-parameters/", "flow/calibration/Start3DClb/", "flow/calibration/Start2DClb/",
                   "flow/2d2t/", "flow/stopclb/", "flow/sleep/", "flow/unknown/"):
        assert sum(i.startswith(prefix) for i in ids) >= 3, prefix


def test_sessions_suite_size() -> None:
    assert (VECTORS / "sessions.json").stat().st_size < 500_000
