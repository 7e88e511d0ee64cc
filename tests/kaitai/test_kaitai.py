"""Differential: the Kaitai parser compiled from generated/kaitai/ilahrs.ksy against the ilahrs binding.

Two engines that share only the spec decode the same frames and payloads and must agree on every
field, every engineering value and every refusal (kind, offset, field). The Kaitai parser comes
from the official compiler (`make build-kaitai`); a missing or stale build fails these tests.
"""

from __future__ import annotations

import importlib.util
import random
import struct
import subprocess
from pathlib import Path
from typing import Any

import kaitai_support as ks
import pytest
import yaml

import ilahrs
from generator import build_spec
from generator.model import Payload
from generator.naming import pascal
from generator.render import render

SEED = 20140311
SPEC = ks.spec()
PAYLOADS = {p.name: p for p in SPEC.payloads}


def ours_refusal(data: bytes, parse: Any) -> ks.Refusal:
    with pytest.raises(ilahrs.IlahrsError) as info:
        parse(data)
    error = info.value
    return ks.Refusal(str(error.kind.value), error.offset, error.field)


def kaitai_refusal(data: bytes, parse: Any) -> ks.Refusal:
    with pytest.raises(ks.KaitaiRefusedError) as info:
        parse(data)
    return info.value.refusal


def test_build_is_present_and_current() -> None:
    ks.kaitai_module()
    ks.construct_module()


def test_every_table_and_enum_is_a_kaitai_type() -> None:
    root = ks.kaitai_root()
    for p in SPEC.payloads:
        cls = ks.kaitai_type(p.name)
        obj = cls(ks.stream(bytes(p.size)))
        assert [a for a in vars(obj) if not a.startswith("_")] == [f.name for f in p.fields], p.name
    for e in SPEC.enums:
        members = {m.value: m.name for m in getattr(root, pascal(e.name))}
        assert members == {v.value: v.name for v in e.values}
    types = {m.value: m.name for m in root.MessageType}
    assert types == {t.value: t.name for t in SPEC.frame.message_types}


def test_command_enum_holds_every_code_once() -> None:
    members = {m.value: m.name for m in ks.kaitai_root().Command}
    assert sorted(members) == list(SPEC.codes)
    for code, name in members.items():
        # The first command of a shared code names it; decode_command lists them all.
        ids = [c.id for c in SPEC.commands if c.code == code]
        assert name == ids[0]
        frame = ilahrs.build_command(SPEC.commands_with_code(code)[0].name)
        kaitai_frame = ks.decode_frame(frame)
        command = ks.kaitai_type("command_payload")(ks.stream(kaitai_frame.payload))
        assert command.code.value == code
        assert ilahrs.decode_command(frame) == (code, tuple(c.name for c in SPEC.commands_with_code(code)))


def random_frames(rng: random.Random, count: int) -> list[bytes]:
    frames = []
    for table, payload in ks.random_frame_payloads(rng, count):
        message_type = rng.choice(SPEC.frame.message_types).value
        reserved = rng.choice([0, 0, rng.randrange(256)])
        frames.append(ilahrs.Frame(message_type, payload, reserved).build())
        del table
    for size in range(SPEC.frame.min_payload, SPEC.frame.max_payload + 1):
        frames.append(ilahrs.Frame(1, rng.randbytes(size)).build())
    frames.append(ilahrs.Frame(1, b"\xff" * SPEC.frame.max_payload, 0xFF).build())
    return frames


def test_frames_decode_identically() -> None:
    rng = random.Random(SEED)
    frames = random_frames(rng, 600)
    for data in frames:
        ours = ilahrs.Frame.parse(data)
        theirs = ks.decode_frame(data)
        assert int(theirs.message_type) == int(ours.message_type)
        assert theirs.reserved == ours.reserved
        assert theirs.payload == ours.payload
        assert theirs.message_length == len(data) - SPEC.frame.header_size
        assert theirs.checksum == theirs.checksum_computed == ilahrs.checksum(data[2:-2])
    assert len(frames) > 600


def corrupted_frames(rng: random.Random) -> list[bytes]:
    """Every way a frame can be refused, including every truncation and byte-level damage."""
    good = [ilahrs.Frame(1, rng.randbytes(p.size)).build() for p in SPEC.payloads]
    good.append(ilahrs.build_command(SPEC.commands[0].name))
    cases: list[bytes] = [b""]
    for frame in good:
        cases.extend(frame[:n] for n in range(len(frame)))  # truncated at every length
        cases.append(frame + b"\x00")  # trailing data
        cases.append(frame + frame)
        for index in range(len(frame)):  # every byte changed: header, type, length, payload, checksum
            damaged = bytearray(frame)
            damaged[index] ^= 1 << rng.randrange(8)
            cases.append(bytes(damaged))
    header = bytes(SPEC.frame.header)
    for length in (0, 1, SPEC.frame.min_length - 1, SPEC.frame.max_length + 1, 0x00FF, 0xFFFF):
        cases.append(header + b"\x01\x00" + struct.pack("<H", length) + bytes(64))
    for message_type in (2, 0x80, 0xFF):
        cases.append(header + bytes([message_type, 0]) + struct.pack("<H", 0xFFFF))
        cases.append(header + bytes([message_type]))  # short: truncated before the type is judged
        cases.append(header + bytes([message_type, 0, 7]))
    for _ in range(2000):
        cases.append(header + rng.randbytes(rng.randrange(12)))
    return cases


def test_frame_refusals_agree() -> None:
    rng = random.Random(SEED + 1)
    kinds = set()
    for data in corrupted_frames(rng):
        try:
            ours = ilahrs.Frame.parse(data)
        except ilahrs.IlahrsError as error:
            expected = ks.Refusal(str(error.kind.value), error.offset, error.field)
            assert kaitai_refusal(data, ks.decode_frame) == expected, data.hex()
            kinds.add(expected.kind)
        else:
            assert ks.decode_frame(data).payload == ours.payload
    assert kinds == {"truncated", "bad_header", "bad_message_type", "bad_length", "bad_checksum", "trailing_data"}


def edge_payloads(p: Payload, rng: random.Random) -> list[bytes]:
    """All zeros, all ones, NaN and infinity patterns in every float, and random bytes."""
    cases = [bytes(p.size), b"\xff" * p.size]
    for pattern in (b"\x00\x00\xc0\x7f", b"\x01\x00\x80\x7f", b"\x00\x00\x80\xff", b"\x00\x00\x80\x80"):
        data = bytearray(rng.randbytes(p.size))
        for f in p.fields:
            if f.is_float:
                data[f.offset : f.end] = pattern
        cases.append(bytes(data))
    cases.extend(rng.randbytes(p.size) for _ in range(150))
    return cases


@pytest.mark.parametrize("name", list(PAYLOADS))
def test_payloads_decode_identically(name: str) -> None:
    p = PAYLOADS[name]
    cls = ilahrs.PAYLOADS[name]
    rng = random.Random(f"{SEED}-{name}")
    for data in edge_payloads(p, rng):
        ours = cls.parse(data)
        theirs = ks.decode_payload(name, data)
        assert ks.same_raw(ks.kaitai_raw(p, theirs), ours.raw()), data.hex()
        assert ks.kaitai_values(p, theirs) == ours.values(), data.hex()
        for variant in SPEC.variants:
            assert ks.kaitai_values(p, theirs, variant) == ours.values(ilahrs.VARIANTS[variant.name])


@pytest.mark.parametrize("name", list(PAYLOADS))
def test_payload_refusals_agree(name: str) -> None:
    p = PAYLOADS[name]
    cls = ilahrs.PAYLOADS[name]
    data = random.Random(SEED).randbytes(p.size + 3)
    for size in [*range(p.size), p.size + 1, p.size + 3]:
        expected = ours_refusal(data[:size], cls.parse)
        assert kaitai_refusal(data[:size], lambda d: ks.decode_payload(name, d)) == expected


def test_status_word_flags_agree() -> None:
    usw_table = next(p for p in SPEC.payloads if any(f.encoding == "usw" for f in p.fields))
    field = next(f for f in usw_table.fields if f.encoding == "usw")
    sw = SPEC.status_word
    assert sw is not None
    for value in [0, 0xFFFF, sw.mode_mask, *(flag.mask for flag in sw.flags), *range(0, 0x10000, 0x0101)]:
        data = bytearray(usw_table.size)
        data[field.offset : field.end] = struct.pack("<H", value)
        theirs = ks.decode_payload(usw_table.name, bytes(data)).usw
        ours = ilahrs.UnitStatusWord(value)
        for flag in sw.flags:
            assert getattr(theirs, flag.name) == getattr(ours, flag.name) == bool(value & flag.mask), flag.name
        for mode in sw.modes:
            assert getattr(theirs, f"mode_{mode.name}") == (ours.mode.value == mode.name)
        assert theirs.any_failure == bool(ours.failures)
        assert theirs.any_warning == bool(ours.warnings)


def test_a_new_table_and_command_need_no_template_change(tmp_path: Path) -> None:
    """Add a payload table (with a constant and a variant scale) and a command to a copy of the
    spec, render only this target, compile it with ksc and parse the new table."""
    data = yaml.safe_load((ks.ROOT / "spec" / "ilahrs.yaml").read_text(encoding="utf-8"))
    unit = next(f for p in data["payloads"] for f in p["fields"] if f.get("scale", {}).get("divisor") == "KG")["unit"]
    data["payloads"].append(
        {
            "name": "extra_table",
            "icd": "Table X.1",
            "title": "Extra",
            "direction": "device_to_host",
            "size": 7,
            "doc": "A table added by the test.",
            "fields": [
                {"name": "angle", "type": "s16", "unit": "deg", "scale": {"divisor": 10}, "doc": "An angle."},
                {"name": "rate", "type": "s16", "unit": unit, "scale": {"divisor": "KG"}, "doc": "A rate."},
                {"name": "label", "type": "char", "length": 3, "doc": "Text."},
            ],
        }
    )
    code = next(c for c in range(0x100) if c not in SPEC.codes)
    data["commands"].append(
        {"name": "ExtraCmd", "id": "extra_cmd", "code": code, "icd": "X.1", "group": "control",
         "purpose": "A command added by the test.", "valid_in": ["idle"], "response": {"kind": "none"}}
    )
    data["state_machine"]["transitions"].append({"from": ["idle"], "when": ["ExtraCmd"], "to": "idle", "send": []})
    spec_path = tmp_path / "extra.yaml"
    spec_path.write_text(yaml.safe_dump(data, sort_keys=False), encoding="utf-8")
    extra = build_spec(spec_path)
    ksy_path = tmp_path / "extra.ksy"
    ksy_path.write_text(render(extra, ["kaitai"])[f"kaitai/{extra.name}.ksy"], encoding="utf-8")
    compiler = ks.ROOT / "tools" / "kaitai" / "compile.js"
    command = ["node", str(compiler), "python", str(ksy_path), str(tmp_path / "out")]
    done = subprocess.run(command, check=False, capture_output=True, text=True)
    assert done.returncode == 0, f"{done.stderr} (run `make setup-kaitai` first?)"
    module_spec = importlib.util.spec_from_file_location("ilahrs_extra", tmp_path / "out" / f"{extra.name}.py")
    assert module_spec is not None and module_spec.loader is not None
    module = importlib.util.module_from_spec(module_spec)
    module_spec.loader.exec_module(module)
    root = getattr(module, pascal(extra.name))
    obj = root.ExtraTable(ks.stream(struct.pack("<hh3s", -123, 250, b"ab\x00")))
    assert (obj.angle, obj.angle_deg, obj.rate, obj.label) == (-123, -12.3, 250, "ab")
    scaled = root.ExtraTableScaled(obj, 50.0, ks.stream(b""))
    assert scaled.rate_dps == 5.0
    assert root.Command(code).name == "extra_cmd"
