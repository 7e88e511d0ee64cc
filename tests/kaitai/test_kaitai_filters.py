"""The Kaitai target's filters: small functions, each checked on the real spec model."""

from __future__ import annotations

import dataclasses

import pytest
import yaml

from generator import build_spec
from generator.targets.kaitai import filters

SPEC = build_spec()


@pytest.mark.parametrize(
    "text",
    ["Heading", "Date (Year, Month, Day)", "Bit 0: x", "a # b", "- dash", "yes", "null", "1.5", "0x10", "", "it's"],
)
def test_scalar_reads_back_as_the_same_text(text: str) -> None:
    assert yaml.safe_load(f"key: {filters.scalar(text)}") == {"key": text}


def test_scalar_is_plain_where_it_can_be() -> None:
    assert filters.scalar("Magnetic declination, Mdec") == "Magnetic declination, Mdec"
    assert filters.scalar("Bit 0: x") == "'Bit 0: x'"


def test_engineering_expressions_divide_as_floats() -> None:
    orientation = SPEC.payload("orientation_sensors")
    assert filters.engineering_expr(orientation.field("heading")) == "heading / 100.0"
    assert filters.engineering_expr(orientation.field("mag_x")) == "mag_x * 10.0"
    assert filters.engineering_expr(orientation.field("gyro_x"), "payload.") == "payload.gyro_x / kg"
    assert filters.engineering_id(orientation.field("gyro_x")) == "gyro_x_dps"
    assert filters.variant_parameters(orientation) == ["KG", "KA"]
    assert [f.name for f in filters.variant_scaled(orientation)][:1] == ["gyro_x"]


def test_message_type_is_checked_after_the_fixed_part() -> None:
    frame = SPEC.frame
    check = filters.message_type_check(frame.field("message_type"), frame)
    remaining = frame.payload_offset - frame.field("message_type").end
    assert check == f"_io.size - _io.pos < {remaining} or _ == message_type::command or _ == message_type::data"


def test_a_shared_code_is_one_enum_entry_with_aliases() -> None:
    entries = filters.command_codes(SPEC)
    assert [e.code for e in entries] == list(SPEC.codes)
    shared = [e for e in entries if e.aliases]
    assert shared and all(len(e.commands) > 1 for e in shared)
    for entry in shared:
        assert entry.id == entry.commands[0].id


def test_clashing_type_and_enum_names_are_refused() -> None:
    clash = dataclasses.replace(SPEC, enums=(dataclasses.replace(SPEC.enums[0], name="status_word"),))
    with pytest.raises(ValueError, match="status_word"):
        filters.check_names(clash)
    with pytest.raises(ValueError, match="not a valid Kaitai identifier"):
        filters.ksy_id("Heading")
    with pytest.raises(ValueError, match="no error kind"):
        filters.error_kind("bad_magic", SPEC)


def test_status_flags_leave_out_the_mode_bits() -> None:
    sw = SPEC.status_word
    assert sw is not None
    assert filters.flags_mask(sw, "failure") & sw.mode_mask == 0
    assert filters.flags_mask(sw, "warning") & sw.mode_mask == 0
    assert filters.flags_mask(sw, "failure") | filters.flags_mask(sw, "warning") == sum(f.mask for f in sw.flags)
