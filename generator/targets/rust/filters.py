"""Small filters for the Rust templates: names, types and literals derived from the model.

Nothing here changes the model or computes an offset (offsets come from generator/layout.py
through `field.offset` and `field.size`), and nothing lays code out: rustfmt does (target.py).
"""

from __future__ import annotations

import struct
from collections.abc import Callable
from dataclasses import replace
from typing import Any

from generator import naming
from generator.model import FLOAT32_MAX, Field, NmeaField, Payload, Spec

from . import machine

# Rust integer type of each integer primitive.
_INT_TYPES = {"u8": "u8", "s8": "i8", "u16": "u16", "s16": "i16", "u32": "u32", "s32": "i32"}

# Words Rust reserves (strict and reserved keywords of edition 2021 and later); a spec name equal
# to one gets a trailing underscore.
_KEYWORD_TEXT = """
    as async await become box break const continue crate do dyn else enum extern false final fn for gen if impl in
    let loop macro match mod move mut override priv pub ref return self static struct super trait true try type
    typeof unsafe unsized use virtual where while yield abstract
"""
_KEYWORDS = frozenset(_KEYWORD_TEXT.split())


def ident(name: str) -> str:
    """A spec name as a Rust snake_case identifier."""
    text = naming.snake(name)
    return f"{text}_" if text in _KEYWORDS else text


def const(name: str) -> str:
    """A spec name as a Rust constant name: `tm_c_11` -> `TM_C_11`."""
    return naming.upper(name)


def type_name(name: str) -> str:
    """A spec name as a Rust type or variant name: `two_d_two_t` -> `TwoDTwoT`, `KG` -> `Kg`."""
    return naming.pascal(name.lower())


def rust_type(field: Field) -> str:
    """The Rust type holding a field's raw value."""
    if field.is_bytes:
        return f"[u8; {field.size}]"
    if field.is_float:
        return "f32"
    return _INT_TYPES[field.type.name]


def value_kind(field: Field) -> str:
    """The `FieldKind` variant of a field."""
    return type_name(field.kind)


def f64_literal(value: float) -> str:
    """A Rust f64 expression for a bound or default: `100.0`, `-0.5`, `F32_MAX`."""
    number = float(value)
    if abs(number) == FLOAT32_MAX:
        return ("-" if number < 0 else "") + "crate::payload::F32_MAX"
    text = repr(number)
    return text.replace("e+", "e") if ("e" in text or "." in text) else f"{text}.0"


def f32_literal(value: float) -> str:
    """The shortest Rust literal that reads back as the same float32 (clippy: no excess precision)."""
    number = struct.unpack("<f", struct.pack("<f", float(value)))[0]
    text = repr(number)
    for digits in range(1, 10):
        text = f"{number:.{digits}g}"
        if struct.unpack("<f", struct.pack("<f", float(text)))[0] == number:
            break
    return f64_literal(float(text))


def int_literal(value: float) -> str:
    """An integer bound or default as a Rust literal."""
    if float(value) != int(value):
        raise ValueError(f"{value!r} is not an integer")
    return str(int(value))


def byte_string(text: str) -> str:
    """A Latin-1 text as a Rust byte-string literal."""
    out = []
    for byte in text.encode("latin-1"):
        char = chr(byte)
        if char in '\\"':
            out.append("\\" + char)
        elif 0x20 <= byte < 0x7F:
            out.append(char)
        else:
            out.append(f"\\x{byte:02x}")
    return 'b"' + "".join(out) + '"'


def string(text: str) -> str:
    """A text as a Rust string literal."""
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def doc(text: str, indent: int = 0, width: int = 92) -> str:
    """Markdown as `///` lines of at most `width` characters (plus the indent). The text is
    rustdoc markup as it stands (a template's own intra-doc links stay links): pass prose from the
    spec through `escape_doc` first."""
    pad = " " * indent
    lines = naming.wrap(text, width - indent - 4) or [""]
    return "\n".join(f"{pad}/// {line}".rstrip() for line in lines)


def escape_doc(text: str) -> str:
    """Keep rustdoc from reading spec prose as markup: brackets and angle brackets. Only for text
    that comes from the spec; a template's own links must stay as they are."""
    return text.replace("<", "&lt;").replace(">", "&gt;").replace("[", "\\[").replace("]", "\\]")


def accessor(field: Field) -> str:
    """The name of a scaled field's engineering accessor: `heading_deg`, `gyro_x_dps`."""
    if field.unit is None:
        return f"{ident(field.name)}_value"
    return f"{ident(field.name)}_{field.unit.suffix.lower()}"


def unit_doc(field: Field) -> str:
    """`degrees` or `raw units` for doc lines."""
    return field.unit.doc if field.unit is not None else "raw units"


def nmea_type(field: NmeaField) -> str:
    """The Rust type of a $PAHR field's scaled integer."""
    if field.format == "hex" and field.min >= 0 and field.max <= 0xFFFF:
        return "u16"
    if field.format == "hex" and field.min >= 0 and field.max <= 0xFFFFFFFF:
        return "u32"
    if field.min >= -(2**31) and field.max < 2**31:
        return "i32"
    raise ValueError(f"$PAHR field {field.name} does not fit 32 bits")


def nmea_unit_suffix(spec: Spec, field: NmeaField) -> str:
    return next((unit.suffix.lower() for unit in spec.units if unit.key == field.unit), "value")


def nmea_unit_doc(spec: Spec, field: NmeaField) -> str:
    return next((unit.doc for unit in spec.units if unit.key == field.unit), "raw units")


def ack_field(spec: Spec) -> Field:
    """The one field of the acknowledgement payload: the acknowledged message's checksum."""
    if spec.ack_payload is None:
        raise ValueError("the spec names no acknowledgement payload")
    numeric = [f for f in spec.payload(spec.ack_payload).fields if f.kind != "reserved"]
    if len(numeric) != 1 or numeric[0].type.name != spec.frame.checksum.type.name:
        raise ValueError("the acknowledgement payload must hold exactly one field of the checksum's type")
    return numeric[0]


def encodings_used(spec: Spec) -> list[str]:
    """Every field encoding any payload uses, in first-use order."""
    seen: list[str] = []
    for payload in spec.payloads:
        seen += [f.encoding for f in payload.fields if f.encoding is not None and f.encoding not in seen]
    return seen


def max_fields(spec: Spec) -> int:
    return max(len(p.fields) for p in spec.payloads)


def power_of_ten(decimals: int) -> int:
    return int(10**decimals)


def big_endian(spec: Spec) -> str:
    """`true` or `false`: the spec's `byte_order`, as the runtime's `BIG_ENDIAN` reads it."""
    orders = {"little": "false", "big": "true"}
    if spec.byte_order not in orders:
        raise ValueError(f"unknown byte order {spec.byte_order!r}")
    return orders[spec.byte_order]


def header_const(spec: Spec) -> str:
    return "[" + ", ".join(naming.hex_byte(b) for b in spec.frame.header) + "]"


def first_with(items: list[Any] | tuple[Any, ...], attribute: str) -> Any:
    """The first item whose `attribute` is truthy (for examples in docs)."""
    for item in items:
        if getattr(item, attribute):
            return item
    raise ValueError(f"no item has {attribute}")


def _shared_type(spec: Spec, chosen: Callable[[Field], bool], what: str) -> str:
    types = {rust_type(f) for p in spec.payloads for f in p.fields if chosen(f)}
    if len(types) != 1:
        raise ValueError(f"{what} must share one type, found {sorted(types)}")
    return types.pop()


def encoding_type(spec: Spec, encoding: str) -> str:
    """The Rust type of the fields that use `encoding` (they must share one)."""
    return _shared_type(spec, lambda f: f.encoding == encoding, f"fields encoded as {encoding}")


def enum_type(spec: Spec, name: str) -> str:
    """The Rust type of the fields that hold enumeration `name` (they must share one)."""
    return _shared_type(spec, lambda f: f.enum == name, f"fields of enum {name}")


def usw_type(spec: Spec) -> str:
    """The Rust type of a Unit Status Word: that of the fields encoded as one."""
    return encoding_type(spec, "usw")


def _number(value: float | str | None) -> float:
    if isinstance(value, str):
        raise ValueError(f"a numeric field has the default {value!r}")
    return float(value or 0)


def default_literal(field: Field) -> str:
    """A Rust expression for the value a builder uses when a field is not given."""
    if field.kind == "char" and field.default_value:
        return "*" + byte_string(str(field.default_value).encode("latin-1").ljust(field.size, b"\0").decode("latin-1"))
    if field.is_bytes:
        return f"[0; {field.size}]"
    if field.is_float:
        return f32_literal(_number(field.default_value))
    return int_literal(_number(field.default_value))


def default_value(field: Field) -> str:
    """The default as a `Value<'static>` expression, or "" where `FieldInfo::new`'s (zero, or no
    bytes) is the one."""
    if field.kind == "reserved":
        return f"Value::Bytes(&[0; {field.size}])"
    if field.kind == "char":
        return f"Value::Bytes({byte_string(str(field.default_value))})" if field.default_value else ""
    if not _number(field.default_value):
        return ""
    if field.is_float:
        return f"Value::Float({f64_literal(_number(field.default_value))})"
    return f"Value::Int({int_literal(_number(field.default_value))})"


def derivable_default(payload: Payload) -> bool:
    """True when every default is zero and every array is small enough for `#[derive(Default)]`."""
    for field in payload.fields:
        if field.is_bytes and (field.size > 32 or field.default_value):
            return False
        if field.is_numeric and field.default_value:
            return False
    return True


# What a field's `_decoded` getter returns for each encoding: (doc after the ICD name, type, call).
_DECODED = {
    "usw": (" as a Unit Status Word (flags and mode).", "StatusWord", "StatusWord"),
    "date": (" as the nearest calendar date, or `None` (see [`Date::decode`]).", "Option<Date>", "Date::decode"),
    "declination": (": degrees, or a request that the AHRS compute it.", "Declination", "Declination::decode"),
    "calibration_success": (
        ": failed, succeeded with an accuracy estimate, or without one.",
        "CalibrationSuccess",
        "CalibrationSuccess::decode",
    ),
}

# The `set_..._decoded` setter of each encoding that has one: (doc, parameter, type, fallible).
_DECODED_SETTERS = {
    "date": (
        " from a calendar date. Error: `out_of_range` for a date that does not exist or lies outside the year range.",
        "date",
        "Date",
        True,
    ),
    "declination": (". Error: `out_of_range` for degrees outside the range.", "value", "Declination", True),
    "calibration_success": (".", "value", "CalibrationSuccess", False),
}


def decoded(field: Field) -> dict[str, str] | None:
    """The `_decoded` getter of a field with an encoding or an enumeration, or None."""
    if field.encoding in _DECODED:
        text, rust, call = _DECODED[field.encoding]
        return {"doc": text, "type": rust, "call": call}
    if field.enum is not None:
        name = type_name(field.enum)
        text = " as a named value, or `None` for a code the ICD does not name."
        return {"doc": text, "type": f"Option<{name}>", "call": f"{name}::from_raw"}
    return None


def decoded_setter(field: Field) -> dict[str, Any] | None:
    """The `set_..._decoded` setter of a field, or None."""
    if field.encoding not in _DECODED_SETTERS:
        return None
    text, parameter, rust, fallible = _DECODED_SETTERS[field.encoding]
    return {"doc": text, "parameter": parameter, "type": rust, "fallible": fallible}


def same_field(spec: Spec, field: Field) -> Payload | None:
    """The first table that holds the same field (name, position, type, range, scale, unit,
    encoding and text all equal), when that is not the field's own: its description is shared."""
    key = replace(field, path=(), erratum=None)
    for payload in spec.payloads:
        if any(replace(f, path=(), erratum=None) == key for f in payload.fields):
            return None if field in payload.fields else payload
    return None


def payload_uses(spec: Spec, payload: Payload) -> list[str]:
    """The `use` paths a table file needs."""
    fields = payload.fields
    own = [f for f in fields if same_field(spec, f) is None]  # the descriptions written out here
    names = {"check_size", "FieldInfo", "Value"} | ({"FieldKind"} if own else set())
    names |= {"Scale"} if any(f.scale for f in own) else set()
    names |= {"Unit"} if any(f.unit for f in own) else set()
    names |= {"Encoding"} if any(f.encoding for f in own) else set()
    codec = {"self", "Table"} | ({"Raw"} if any(not f.is_bytes for f in fields) else set())
    uses = [
        "crate::error::Result",
        "crate::wire",
        "crate::payload::codec::{" + ", ".join(sorted(codec, key=lambda name: (name != "self", name))) + "}",
        "crate::payload::{" + ", ".join(sorted(names, key=str.lower)) + "}",
    ]
    variant = {"Variant"} if any(f.scale is not None and f.scale.divisor_parameter for f in fields) else set()
    variant |= {"VariantParameter"} if any(f.scale is not None and f.scale.divisor_parameter for f in own) else set()
    if variant:
        uses.append("crate::variant::{" + ", ".join(sorted(variant)) + "}")
    for field in fields:
        found = decoded(field)
        if found is not None:
            path = "crate::status" if field.encoding == "usw" else "crate::encoding"
            uses.append(f"{path}::{found['call'].split('::')[0]}")
    return sorted(set(uses))


def check_supported(spec: Spec) -> None:
    """Refuse a spec whose rules the Rust runtime does not implement."""
    if spec.frame.checksum_algorithm != "sum16":
        raise ValueError(f"the Rust target implements the sum16 checksum, not {spec.frame.checksum_algorithm!r}")
    if spec.date is not None and spec.date.decode != "nearest_calendar_date":
        raise ValueError(f"the Rust target decodes dates to the nearest calendar date, not {spec.date.decode!r}")
    ack_field(spec)


FILTERS: dict[str, Callable[..., Any]] = {
    "ident": ident,
    "const": const,
    "type_name": type_name,
    "rust_type": rust_type,
    "value_kind": value_kind,
    "f64": f64_literal,
    "byte_string": byte_string,
    "string": string,
    "doc": doc,
    "escape_doc": escape_doc,
    "accessor": accessor,
    "unit_doc": unit_doc,
    "nmea_type": nmea_type,
    "power_of_ten": power_of_ten,
    "first_with": first_with,
    "default_literal": default_literal,
    "default_value": default_value,
    "derivable_default": derivable_default,
    "decoded": decoded,
    "decoded_setter": decoded_setter,
}

GLOBALS: dict[str, Any] = {
    "same_field": same_field,
    "payload_uses": payload_uses,
    "ack_field": ack_field,
    "encodings_used": encodings_used,
    "max_fields": max_fields,
    "header_const": header_const,
    "usw_type": usw_type,
    "encoding_type": encoding_type,
    "enum_type": enum_type,
    "big_endian": big_endian,
    "nmea_unit_suffix": nmea_unit_suffix,
    "nmea_unit_doc": nmea_unit_doc,
    **machine.GLOBALS,
}
