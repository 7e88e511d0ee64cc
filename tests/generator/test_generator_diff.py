"""`python -m generator diff`: each rule on a spec mutated to trigger it, the version check, JUnit
output, and the wire fingerprint (a doc-only edit keeps it, a wire edit changes it)."""

from __future__ import annotations

import copy
import dataclasses
import subprocess
import sys
import xml.etree.ElementTree as ET
from collections.abc import Callable
from functools import cache
from pathlib import Path
from typing import Any

import pytest
import yaml

from generator import DEFAULT_SPEC, ROOT, build_spec
from generator.diff import ADDITIVE, API, DOCS, RULES, WIRE, compare, required_bump, wire_fingerprint
from generator.load import SpecError
from generator.model import Spec

Data = dict[str, Any]


@cache
def _base() -> Data:
    data: Data = yaml.safe_load(DEFAULT_SPEC.read_text(encoding="utf-8"))
    return data


@cache
def _base_spec() -> Spec:
    return build_spec(DEFAULT_SPEC)


def _command(d: Data, name: str) -> Data:
    return next(c for c in d["commands"] if c["name"] == name)


def _payload(d: Data, name: str) -> Data:
    return next(p for p in d["payloads"] if p["name"] == name)


def _field(d: Data, payload: str, name: str) -> Data:
    return next(f for f in _payload(d, payload)["fields"] if f["name"] == name)


def _drop_command(d: Data, name: str) -> None:
    d["commands"] = [c for c in d["commands"] if c["name"] != name]
    for t in d["state_machine"]["transitions"]:
        t["when"] = [w for w in t["when"] if w != name]
    d["state_machine"]["transitions"] = [t for t in d["state_machine"]["transitions"] if t["when"]]


def _rename_command(d: Data, old: str, new: str, new_id: str) -> None:
    c = _command(d, old)
    c["name"], c["id"] = new, new_id
    for t in d["state_machine"]["transitions"]:
        t["when"] = [new if w == old else w for w in t["when"]]


def m_code_removed(d: Data) -> None:
    _drop_command(d, "GetVerFirmware")


def m_code_reused(d: Data) -> None:
    _drop_command(d, "GetVerFirmware")
    c = copy.deepcopy(_command(d, "GetBIT"))
    c.update(name="GetVersionNow", id="get_version_now", code=0x1F, valid_in=["idle"])
    d["commands"].append(c)
    d["state_machine"]["transitions"].append(
        {"from": ["idle"], "when": ["GetVersionNow"], "to": "idle", "send": ["bit_result"]}
    )


def m_code_changed(d: Data) -> None:
    _command(d, "GetVerFirmware")["code"] = 0x1E


def m_response(d: Data) -> None:
    _command(d, "ClearClb")["response"] = {"kind": "none"}


def m_behaviour(d: Data) -> None:
    _command(d, "AHRScont2")["starts"]["output"] = "full_output"


def m_field_offset(d: Data) -> None:
    fields = _payload(d, "bit_result")["fields"]
    fields[0], fields[1] = fields[1], fields[0]


def m_field_signedness(d: Data) -> None:
    _field(d, "full_output", "ugyro_x")["type"] = "u16"


def m_field_scale(d: Data) -> None:
    _field(d, "full_output", "heading")["scale"] = {"divisor": 10}


def m_payload_size(d: Data) -> None:
    p = _payload(d, "calibration_run_parameters")
    p["size"] = 8
    p["fields"][0]["length"] = 8


def m_enum_value(d: Data) -> None:
    d["enums"]["calibration_type"]["values"][2]["value"] = 4


def m_frame(d: Data) -> None:
    d["frame"]["header"] = [0xAA, 0x56]


def m_serial_line(d: Data) -> None:
    d["serial_line"]["baud_rate"] = 57600


def m_answer(d: Data) -> None:
    for t in d["state_machine"]["transitions"]:
        if t["when"] == ["ReadAHRSPar"]:
            t["send"] = ["ack"]


def m_variant_value(d: Data) -> None:
    d["variants"]["list"][0]["values"]["KG"] += 1


def m_field_renamed(d: Data) -> None:
    _field(d, "full_output", "ugyro_x")["name"] = "raw_gyro_x"


def m_command_renamed(d: Data) -> None:
    _rename_command(d, "GetBIT", "GetSelfTest", "get_self_test")


def m_enum_value_removed(d: Data) -> None:
    values = d["enums"]["calibration_status_type"]["values"]
    values[:] = [v for v in values if v["name"] != "three_d"]


def m_field_range(d: Data) -> None:
    _field(d, "full_output", "pitch")["range"] = [-4500, 4500]


def m_field_unit(d: Data) -> None:
    _field(d, "full_output", "ugyro_x")["unit"] = next(k for k in d["units"] if k != "adc")


def m_command_added(d: Data) -> None:
    c = copy.deepcopy(_command(d, "GetBIT"))
    c.update(name="GetBIT2", id="get_bit2", code=0x1B, valid_in=["idle"])
    d["commands"].append(c)
    d["state_machine"]["transitions"].append(
        {"from": ["idle"], "when": ["GetBIT2"], "to": "idle", "send": ["bit_result"]}
    )


def m_field_in_reserved(d: Data) -> None:
    fields = _payload(d, "full_output")["fields"]
    i = next(i for i, f in enumerate(fields) if f["type"] == "reserved")
    fields[i : i + 1] = [
        {"name": "board_temperature", "type": "s16", "doc": "Board temperature."},
        {"name": "reserved", "type": "reserved", "length": 2},
    ]


def m_enum_value_added(d: Data) -> None:
    d["enums"]["calibration_type"]["values"].append({"name": "four_d", "value": 4, "doc": "4D calibration"})


def m_payload_added(d: Data) -> None:
    p = copy.deepcopy(_payload(d, "bit_result"))
    p["name"] = "bit_result_extended"
    d["payloads"].append(p)


def m_doc(d: Data) -> None:
    _command(d, "GetBIT")["purpose"] = "Run the built-in test and send its result (reworded)."
    _field(d, "full_output", "heading")["doc"] = "Heading angle, reworded."


def m_payload_direction(d: Data) -> None:
    _payload(d, "firmware_version")["direction"] = "host_to_device"


def m_field_size(d: Data) -> None:
    # device_id grows into the reserved bytes after it: no other offset and no size moves.
    fields = _payload(d, "ahrs_parameters_read")["fields"]
    assert [f["name"] for f in fields[-2:]] == ["device_id", "reserved"]
    fields[-2]["length"] += 2
    fields[-1]["length"] -= 2


def m_field_encoding(d: Data) -> None:
    vdd = _field(d, "full_output", "vdd")
    vdd["multiplexed"] = {"count": 3, "quantities": [*vdd["multiplexed"]["quantities"], "backup battery voltage"]}


def m_field_removed_from_layout(d: Data) -> None:
    p = _payload(d, "bit_result")
    p["fields"] = [f for f in p["fields"] if f["name"] != "usw"]
    p["size"] = 2


def m_field_added_to_layout(d: Data) -> None:
    p = _payload(d, "bit_result")
    p["fields"].append({"name": "error_count", "type": "u16", "doc": "Errors counted since power-up."})
    p["size"] = 6


def m_byte_order(d: Data) -> None:
    d["byte_order"] = "big"


def m_encoding(d: Data) -> None:
    d["encodings"]["declination"]["compute_value"] = 998


def m_state_machine(d: Data) -> None:
    d["state_machine"]["timing"]["result_delay_s"] = 0.5


def m_field_default(d: Data) -> None:
    _field(d, "calibration_parameters", "reference_azimuth")["default"] = 90


def m_unit_suffix(d: Data) -> None:
    d["units"]["adc"]["suffix"] = "raw"


def m_enum_external(d: Data) -> None:
    d["enums"]["calibration_status_type"]["external_above"] = 0x90


def m_variant_added(d: Data) -> None:
    v = copy.deepcopy(d["variants"]["list"][0])
    v.update(name="g300_a8_tmga", part_number="AHRS-G300-A8-TMGA-C1-V1.1")
    d["variants"]["list"].append(v)


def m_multiplexed_quantities_reworded(d: Data) -> None:
    _field(d, "full_output", "vdd")["multiplexed"]["quantities"] = ["input voltage", "sensor supply voltage"]


def m_error_kind_added(d: Data) -> None:
    d["errors"].append({"name": "busy", "doc": "The AHRS is busy."})


# mutation -> (the rule that must be reported, its class)
CASES: dict[str, tuple[Callable[[Data], None], str, str]] = {
    "code removed": (m_code_removed, "COMMAND_CODE_REMOVED", WIRE),
    "code reused": (m_code_reused, "COMMAND_CODE_REUSED", WIRE),
    "code changed": (m_code_changed, "COMMAND_CODE_CHANGED", WIRE),
    "response changed": (m_response, "COMMAND_RESPONSE_CHANGED", WIRE),
    "behaviour changed": (m_behaviour, "COMMAND_BEHAVIOUR_CHANGED", WIRE),
    "field offset": (m_field_offset, "FIELD_OFFSET_CHANGED", WIRE),
    "field signedness": (m_field_signedness, "FIELD_SIGNEDNESS_CHANGED", WIRE),
    "field scale": (m_field_scale, "FIELD_SCALE_CHANGED", WIRE),
    "payload size": (m_payload_size, "PAYLOAD_SIZE_CHANGED", WIRE),
    "enum value number": (m_enum_value, "ENUM_VALUE_CHANGED", WIRE),
    "frame header": (m_frame, "FRAME_CHANGED", WIRE),
    "serial line": (m_serial_line, "SERIAL_LINE_CHANGED", WIRE),
    "state-machine answer": (m_answer, "STATE_MACHINE_ANSWER_CHANGED", WIRE),
    "variant value": (m_variant_value, "VARIANT_VALUE_CHANGED", WIRE),
    "payload direction": (m_payload_direction, "PAYLOAD_DIRECTION_CHANGED", WIRE),
    "field size": (m_field_size, "FIELD_SIZE_CHANGED", WIRE),
    "field multiplexing": (m_field_encoding, "FIELD_ENCODING_CHANGED", WIRE),
    "field removed from layout": (m_field_removed_from_layout, "FIELD_REMOVED_FROM_LAYOUT", WIRE),
    "field added to layout": (m_field_added_to_layout, "FIELD_ADDED_TO_LAYOUT", WIRE),
    "value encoding": (m_encoding, "ENCODING_CHANGED", WIRE),
    "state-machine timing": (m_state_machine, "STATE_MACHINE_CHANGED", WIRE),
    "field renamed": (m_field_renamed, "NAME_RENAMED", API),
    "command renamed": (m_command_renamed, "NAME_RENAMED", API),
    "enum value removed": (m_enum_value_removed, "NAME_REMOVED", API),
    "field range": (m_field_range, "FIELD_TYPE_CHANGED", API),
    "field unit": (m_field_unit, "FIELD_TYPE_CHANGED", API),
    "field default": (m_field_default, "FIELD_DEFAULT_CHANGED", API),
    "unit suffix": (m_unit_suffix, "UNIT_CHANGED", API),
    "enum external range": (m_enum_external, "ENUM_CHANGED", WIRE),
    "command added": (m_command_added, "COMMAND_ADDED", ADDITIVE),
    "field in reserved": (m_field_in_reserved, "FIELD_ADDED_IN_RESERVED", ADDITIVE),
    "enum value added": (m_enum_value_added, "ENUM_VALUE_ADDED", ADDITIVE),
    "payload added": (m_payload_added, "PAYLOAD_ADDED", ADDITIVE),
    "variant added": (m_variant_added, "VARIANT_ADDED", ADDITIVE),
    "error kind added": (m_error_kind_added, "NAME_ADDED", ADDITIVE),
    "doc only": (m_doc, "DOC_CHANGED", DOCS),
    "multiplexed quantities reworded": (m_multiplexed_quantities_reworded, "DOC_CHANGED", DOCS),
}

# Rules that no valid spec edit triggers: the edit that would, which the spec's schema refuses.
# They are checked on a laid-out model changed by hand instead.
UNREACHABLE: dict[str, tuple[Callable[[Data], None], Callable[[Spec], Spec]]] = {
    "BYTE_ORDER_CHANGED": (m_byte_order, lambda s: dataclasses.replace(s, byte_order="big")),
}


def _mutated(tmp_path: Path, mutate: Callable[[Data], None], version: str | None = None) -> Path:
    data = copy.deepcopy(_base())
    mutate(data)
    if version is not None:
        data["spec"]["version"] = version
    path = tmp_path / "mutated.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False, allow_unicode=True), encoding="utf-8")
    return path


@pytest.mark.parametrize("case", CASES)
def test_each_rule_classifies_its_mutation(tmp_path: Path, case: str) -> None:
    mutate, rule, cls = CASES[case]
    assert RULES[rule][0] == cls
    new = build_spec(_mutated(tmp_path, mutate))
    changes = compare(_base_spec(), new)
    assert changes, f"{case}: no change reported"
    assert rule in {c.rule for c in changes}, [c.line() for c in changes]
    # The most severe class reported is the case's class: nothing is over- or under-classified.
    order = [WIRE, API, ADDITIVE, DOCS]
    assert min(order.index(c.cls) for c in changes) == order.index(cls), [c.line() for c in changes]
    # The fingerprint moves exactly when a wire rule fires (a variant's scale is wire; a new
    # command, table, enum value or variant adds to what the wire carries; names, units' suffixes
    # and builders' defaults are no wire fact).
    same = wire_fingerprint(_base_spec()) == wire_fingerprint(new)
    if cls == WIRE or (cls == ADDITIVE and rule not in ("FIELD_ADDED_IN_RESERVED", "NAME_ADDED")):
        assert not same, case
    elif cls == DOCS or rule in ("NAME_RENAMED", "NAME_ADDED", "UNIT_CHANGED", "FIELD_DEFAULT_CHANGED"):
        assert same, case


def test_every_rule_has_a_mutated_spec() -> None:
    cased = {rule for _, rule, _ in CASES.values()}
    assert not cased & set(UNREACHABLE), "a rule with a mutated spec is not unreachable"
    missing = [rule for rule in RULES if rule not in cased and rule not in UNREACHABLE]
    assert not missing, f"rules without a mutated-spec case in CASES: {missing}"
    assert cased | set(UNREACHABLE) <= set(RULES)


@pytest.mark.parametrize("rule", UNREACHABLE)
def test_a_rule_no_valid_spec_triggers(tmp_path: Path, rule: str) -> None:
    mutate, change_model = UNREACHABLE[rule]
    # The spec edit is refused; once it is accepted, the rule belongs in CASES.
    with pytest.raises(SpecError):
        build_spec(_mutated(tmp_path, mutate))
    changes = compare(_base_spec(), change_model(_base_spec()))
    assert [c.rule for c in changes] == [rule], [c.line() for c in changes]


def test_the_same_spec_has_no_change() -> None:
    assert compare(_base_spec(), build_spec(DEFAULT_SPEC)) == []
    assert required_bump([], "1.0.0") is None


def test_required_bump_by_class(tmp_path: Path) -> None:
    base = _base_spec()
    for mutate, bump in (
        (m_field_scale, "major"),
        (m_field_renamed, "major"),
        (m_command_added, "minor"),
        (m_doc, "patch"),
    ):
        changes = compare(base, build_spec(_mutated(tmp_path, mutate)))
        assert required_bump(changes, base.version) == bump, mutate.__name__
        assert required_bump(changes, "0.3.0") == {"major": "minor", "minor": "patch", "patch": "patch"}[bump]


def _diff(*args: str | Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "generator", "diff", *map(str, args)],
        capture_output=True,
        text=True,
        cwd=ROOT,
        timeout=120,
        check=False,
    )


def test_check_version_fails_when_the_version_does_not_bump_enough(tmp_path: Path) -> None:
    old = _mutated(tmp_path, lambda d: None)
    (tmp_path / "old.yaml").write_text(old.read_text(encoding="utf-8"), encoding="utf-8")
    base = tmp_path / "old.yaml"
    new = tmp_path / "new"
    new.mkdir()
    too_small = _mutated(new, m_field_scale, version="1.1.0")
    run = _diff("--against", base, "--spec", too_small, "--check-version", "--junit", tmp_path / "junit.xml")
    assert run.returncode == 1, run.stderr
    assert "FIELD_SCALE_CHANGED" in run.stdout and "wire-breaking" in run.stdout
    assert run.stderr.strip().splitlines() == ["error: spec version 1.1.0 must be at least a major bump over 1.0.0"]
    suite = ET.parse(tmp_path / "junit.xml").getroot()
    assert suite.tag == "testsuite" and int(suite.get("failures", "0")) >= 2
    assert any(c.get("name", "").startswith("FIELD_SCALE_CHANGED") for c in suite.iter("testcase"))

    enough = _mutated(new, m_field_scale, version="2.0.0")
    run = _diff("--against", base, "--spec", enough, "--check-version", "--junit", tmp_path / "junit.xml")
    assert run.returncode == 0, run.stderr
    assert "required bump: major; version 1.0.0 -> 2.0.0 (major)" in run.stdout
    assert ET.parse(tmp_path / "junit.xml").getroot().get("failures") == "0"


def test_against_a_git_revision_and_a_bad_one() -> None:
    run = _diff("--against", "HEAD")
    assert run.returncode == 0, run.stderr
    run = _diff("--against", "no-such-revision-anywhere")
    assert run.returncode == 2
    lines = run.stderr.strip().splitlines()
    assert len(lines) == 1 and "no-such-revision-anywhere" in lines[0] and "Traceback" not in run.stderr


def test_rules_are_listed_and_an_unwritable_report_is_one_line(tmp_path: Path) -> None:
    run = _diff("--rules")
    assert run.returncode == 0 and [line.split()[1] for line in run.stdout.splitlines()] == list(RULES)
    (tmp_path / "blocker").write_text("", encoding="utf-8")
    run = _diff("--against", DEFAULT_SPEC, "--junit", tmp_path / "blocker" / "x.xml")
    assert run.returncode == 2 and run.stderr.startswith("error: cannot write") and len(run.stderr.splitlines()) == 1


def test_fingerprint_ignores_docs_and_names_but_not_bytes(tmp_path: Path) -> None:
    base = wire_fingerprint(_base_spec())
    assert 0 < base < 1 << 64

    def docs_and_names(d: Data) -> None:
        m_doc(d)
        m_field_renamed(d)
        d["errata"][0]["why"] = "Reworded."

    assert wire_fingerprint(build_spec(_mutated(tmp_path, docs_and_names))) == base
    assert wire_fingerprint(build_spec(_mutated(tmp_path, m_field_scale))) != base
    assert wire_fingerprint(build_spec(_mutated(tmp_path, m_answer))) != base


def test_every_binding_exports_the_fingerprint() -> None:
    value = wire_fingerprint(_base_spec())
    hex16 = f"{value:016x}"
    c = (ROOT / "generated/c/ilahrs.h").read_text(encoding="utf-8")
    assert f"#define ILAHRS_WIRE_FINGERPRINT UINT64_C(0x{hex16})" in c
    rust = (ROOT / "generated/rust/src/lib.rs").read_text(encoding="utf-8")
    assert f"pub const WIRE_FINGERPRINT: u64 = 0x{hex16};" in rust
    from ilahrs import spec as py_spec

    assert value == py_spec.WIRE_FINGERPRINT
    run = subprocess.run(
        [sys.executable, "-m", "ilahrs", "--version"], capture_output=True, text=True, timeout=60, check=True
    )
    assert f"wire fingerprint {hex16}" in run.stdout
