"""Filters for the Kaitai Struct target: model facts rendered as .ksy types, ids and docs.

Everything here reads the laid-out model and returns text or small lists; nothing computes
an offset (fields carry `.offset`, the frame `.payload_offset` and `.length_bias`).
"""

from __future__ import annotations

import re
from collections import Counter
from dataclasses import dataclass

import yaml

from generator.model import Command, Field, Frame, Payload, Spec, StatusWord, Variant

# Wire types as Kaitai spells them (the byte order comes from meta/endian).
KSY_TYPES = {"u8": "u1", "s8": "s1", "u16": "u2", "s16": "s2", "u32": "u4", "s32": "s4", "f32": "f4"}

# Kaitai identifiers: lower_snake_case starting with a letter.
_KSY_ID = re.compile(r"^[a-z][a-z0-9_]*$")

# meta/endian. The spec says `byte_order: little`, but the model does not carry it (no
# Spec.byte_order), so the target states it; every multi-byte value is low byte first (section 6).
ENDIAN = "le"

# Char fields are Latin-1 so that every byte survives (spec/README, payload decode).
CHAR_ENCODING = "ISO-8859-1"


def ksy_id(name: str) -> str:
    """A spec name used as a Kaitai identifier; refuses what the compiler would refuse."""
    if not _KSY_ID.match(name):
        raise ValueError(f"{name!r} is not a valid Kaitai identifier")
    return name


def ksy_type(field: Field) -> str:
    """The Kaitai type of a numeric field: `u2`, `s2`, `f4`, ..."""
    return KSY_TYPES[field.type.name]


_PLAIN_UNSAFE = re.compile(r"^[-?:,\[\]{}#&*!|>'\"%@`\s]|: | #|:$|\s$")


def scalar(text: object) -> str:
    """A one-line YAML scalar: plain where YAML reads it back unchanged, else single-quoted."""
    value = str(text)
    if not value or _PLAIN_UNSAFE.search(value) or yaml_special(value):
        return quote(value)
    return value


def yaml_special(value: str) -> bool:
    """Plain scalars YAML would read as something other than the text (numbers, booleans, null)."""
    loaded = yaml.safe_load(value)
    return not isinstance(loaded, str) or loaded != value


def quote(text: object) -> str:
    """A YAML single-quoted scalar (Kaitai expressions hold `:`, `?` and `#`)."""
    return "'" + str(text).replace("'", "''") + "'"


def error_kind(name: str, spec: Spec) -> str:
    """An error kind of the spec's `errors` list, refused if the spec has no such kind."""
    if name not in {e.name for e in spec.errors}:
        raise ValueError(f"the spec defines no error kind {name!r}")
    return name


def bytes_after(field: Field, frame: Frame) -> int:
    """How many bytes of the fixed frame part follow `field` (before the payload)."""
    return frame.payload_offset - field.end


def message_type_check(field: Field, frame: Frame) -> str:
    """`valid` expression of the message type: a known type, checked once the fixed part is there.

    spec/README checks a short input (truncated) before the message type, so the check passes
    while fewer bytes than the rest of the fixed part remain; reading them then fails.
    """
    known = " or ".join(f"_ == message_type::{ksy_id(t.name)}" for t in frame.message_types)
    return f"_io.size - _io.pos < {bytes_after(field, frame)} or {known}"


def flags_mask(sw: StatusWord, byte: str) -> int:
    """The flags of one status byte (`failure`, `warning`), without the mode bits it shares."""
    mask = 0
    for flag in sw.flags:
        if flag.byte == byte:
            mask |= flag.mask
    return mask


def checksum_modulus(frame: Frame) -> int:
    """The checksum is the byte sum modulo 2 ** (bits of the checksum field) (E28)."""
    return 1 << (8 * frame.checksum.size)


def engineering_id(field: Field) -> str:
    """The value instance holding a scaled field's engineering value, e.g. `heading_deg`."""
    suffix = field.unit.suffix if field.unit is not None else "value"
    return ksy_id(f"{field.name}_{suffix}")


def param_id(parameter: str) -> str:
    """A variant parameter (KG, KA) as a Kaitai parameter id (kg, ka)."""
    return ksy_id(parameter.lower())


def engineering_expr(field: Field, ref: str = "") -> str:
    """Raw x multiplier / divisor as a float-valued Kaitai expression.

    Kaitai divides integers as integers, so constant divisors are written as float literals
    and variant parameters are declared `f8`.
    """
    scale = field.scale
    assert scale is not None, field.name
    raw = f"{ref}{field.name}"
    term = raw if scale.multiplier == 1 else f"{raw} * {scale.multiplier}"
    if scale.divisor_parameter is not None:
        return f"{term} / {param_id(scale.divisor_parameter)}"
    assert scale.divisor is not None
    if scale.divisor == 1:
        return f"{raw} * {scale.multiplier}.0"
    return f"{term} / {scale.divisor}.0"


def engineering_doc(field: Field) -> str:
    unit = field.unit.doc if field.unit is not None else "engineering units"
    return f"{field.name} in {unit}: {scale_text(field)}."


def variant_value(parameter: str, variant: Variant) -> str:
    """A variant parameter as the `f8` argument of a scaled type: `100.0`."""
    return f"{float(variant.value(parameter))!r}"


def variant_values(spec: Spec, parameter: str) -> list[str]:
    """`g300_a2_tmga 100`, one per variant: the values a variant parameter takes."""
    return [f"{v.name} {v.value(parameter)}" for v in spec.variants]


def scale_text(field: Field) -> str:
    """`raw/100`, `raw*10`, `raw/KG` for docs."""
    scale = field.scale
    assert scale is not None, field.name
    text = "raw" if scale.multiplier == 1 else f"raw*{scale.multiplier}"
    divisor = scale.divisor_parameter or (None if scale.divisor == 1 else scale.divisor)
    return text if divisor is None else f"{text}/{divisor}"


def constant_scaled(payload: Payload) -> list[Field]:
    """Scaled fields whose engineering value needs no variant."""
    return [f for f in payload.scaled_fields if f.scale is not None and not f.scale.variant_dependent]


def variant_scaled(payload: Payload) -> list[Field]:
    """Scaled fields whose divisor is a variant parameter (KG, KA)."""
    return [f for f in payload.scaled_fields if f.scale is not None and f.scale.variant_dependent]


def variant_parameters(payload: Payload) -> list[str]:
    """The variant parameters a payload's scales use, in order of first use."""
    names: list[str] = []
    for f in variant_scaled(payload):
        assert f.scale is not None and f.scale.divisor_parameter is not None
        if f.scale.divisor_parameter not in names:
            names.append(f.scale.divisor_parameter)
    return names


def scaled_type_id(payload: Payload) -> str:
    """The parametric type holding a payload's variant-dependent engineering values."""
    return ksy_id(f"{payload.name}_scaled")


def byte_range(field: Field) -> str:
    """`bytes 4-5` (ICD style, inclusive)."""
    if field.size == 1:
        return f"byte {field.offset}"
    return f"bytes {field.offset}-{field.end - 1}"


def number(value: float) -> str:
    """A range bound as the spec writes it (integers without a decimal point)."""
    return str(int(value)) if float(value).is_integer() else repr(value)


def field_doc(field: Field, payload: Payload, spec: Spec) -> str:
    """The doc of a payload field: the spec's doc, then unit, scale, range, enum, encoding."""
    parts = [field.doc] if field.doc else []
    parts.append(f"Payload {byte_range(field)}.")
    if field.unit is not None:
        parts.append(f"Unit: {field.unit.doc}.")
    if field.scale is not None:
        where = (
            f"instance {engineering_id(field)}"
            if not field.scale.variant_dependent
            else f"instance {engineering_id(field)} of the type {scaled_type_id(payload)}"
        )
        parts.append(f"Engineering value = {scale_text(field)} ({where}).")
    if field.range is not None:
        parts.append(f"Builders accept raw {number(field.range[0])} to {number(field.range[1])}.")
    if field.default is not None:
        parts.append(f"Default {field.default}.")
    if field.enum is not None:
        enum = spec.enum(field.enum)
        parts.append(f"Enum {enum.name} ({enum.icd}).")
        if enum.external_above is not None:
            parts.append(
                f"Values above {enum.external_above:#04x} mean parameters loaded by other software "
                "and have no name in the enum."
            )
    if field.encoding is not None:
        parts.append(_encoding_doc(field.encoding, spec))
    if field.multiplexed_count is not None:
        quantities = "; ".join(field.multiplexed_quantities)
        parts.append(f"Multiplexed: {field.multiplexed_count} quantities in turn ({quantities}).")
    if field.kind == "char":
        parts.append(f"{CHAR_ENCODING}, trailing NULs removed.")
    if field.kind == "reserved":
        parts.append("Reserved: kept verbatim.")
    if field.erratum is not None:
        parts.append(f"See erratum {field.erratum}.")
    return " ".join(parts)


def _encoding_doc(name: str, spec: Spec) -> str:
    if name == "usw":
        return "Unit Status Word: see the type status_word."
    if name == "date" and spec.date is not None:
        return f"Encoding date: years {spec.date.year_min} to {spec.date.year_max}."
    if name == "declination" and spec.declination is not None:
        d = spec.declination
        return (
            f"Encoding declination: {number(d.min)} to {number(d.max)} deg, or above "
            f"{number(d.compute_above)} (builders write {number(d.compute_value)}) to have the AHRS compute it."
        )
    if name == "calibration_success" and spec.calibration_success is not None:
        return f"Encoding calibration_success: {spec.calibration_success.doc}"
    return f"Encoding {name}."


@dataclass(frozen=True)
class CommandCode:
    """One enum entry: a code and every command that has it, in spec order."""

    code: int
    commands: tuple[Command, ...]

    @property
    def id(self) -> str:
        """The first command's id names the code; the others are aliases (E14)."""
        return ksy_id(self.commands[0].id)

    @property
    def aliases(self) -> tuple[Command, ...]:
        return self.commands[1:]


def command_codes(spec: Spec) -> list[CommandCode]:
    """Commands grouped by code, ascending: a Kaitai enum holds each value once."""
    return [CommandCode(code, tuple(c for c in spec.commands if c.code == code)) for code in spec.codes]


def command_doc(command: Command) -> str:
    modes = ", ".join(command.valid_in)
    return f"{command.name} ({command.icd}): {command.purpose} Valid in {modes}."


def type_names(spec: Spec) -> list[str]:
    """Every user type the .ksy declares (besides the frame at the top)."""
    names = ["byte_sum", "command_payload", "status_word"]
    for p in spec.payloads:
        names.append(p.name)
        if variant_scaled(p):
            names.append(scaled_type_id(p))
    return names


def check_names(spec: Spec) -> None:
    """Types and enums become classes of one namespace in most targets: refuse clashes."""
    enums = ["message_type", "command", *[e.name for e in spec.enums]]
    names = [ksy_id(n) for n in [*type_names(spec), *enums]]
    clashes = sorted({n for n in names if names.count(n) > 1})
    if clashes:
        raise ValueError(f"kaitai: types and enums share the names {clashes}")


def length_decided(spec: Spec) -> list[tuple[Payload, int]]:
    """(table, message length) of the payload tables no other table shares a size with: a data frame
    of that length can only hold that table (sizes shared by several tables need the context, E7)."""
    sizes = Counter(p.size for p in spec.payloads)
    return [(p, p.size + spec.frame.length_bias) for p in spec.payloads if sizes[p.size] == 1]


FILTERS = {
    "ksy_id": ksy_id,
    "ksy_type": ksy_type,
    "quote": quote,
    "scalar": scalar,
    "error_kind": error_kind,
    "bytes_after": bytes_after,
    "checksum_modulus": checksum_modulus,
    "flags_mask": flags_mask,
    "message_type_check": message_type_check,
    "engineering_doc": engineering_doc,
    "engineering_id": engineering_id,
    "engineering_expr": engineering_expr,
    "scale_text": scale_text,
    "param_id": param_id,
    "constant_scaled": constant_scaled,
    "variant_scaled": variant_scaled,
    "variant_parameters": variant_parameters,
    "scaled_type_id": scaled_type_id,
    "field_doc": field_doc,
    "variant_value": variant_value,
    "command_doc": command_doc,
    "number": number,
}

GLOBALS = {
    "length_decided": length_decided,
    "command_codes": command_codes,
    "variant_values": variant_values,
    "CHAR_ENCODING": CHAR_ENCODING,
    "ENDIAN": ENDIAN,
}
