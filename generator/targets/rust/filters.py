"""Small filters for the Rust templates: names, types and literals derived from the model.

Nothing here changes the model or computes an offset: offsets come from generator/layout.py
through `field.offset` and `field.size`.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from generator import naming
from generator.model import FLOAT32_MAX, TIMER_EVENTS, Field, NmeaField, Payload, Spec, StateMachine, Transition

# Rust integer type of each integer primitive.
_INT_TYPES = {"u8": "u8", "s8": "i8", "u16": "u16", "s16": "i16", "u32": "u32", "s32": "i32"}

# Words Rust reserves; a spec name equal to one gets a trailing underscore.
_KEYWORDS = frozenset(
    [
        "as",
        "break",
        "const",
        "continue",
        "crate",
        "else",
        "enum",
        "extern",
        "false",
        "fn",
        "for",
        "if",
        "impl",
        "in",
        "let",
        "loop",
        "match",
        "mod",
        "move",
        "mut",
        "pub",
        "ref",
        "return",
        "self",
        "static",
        "struct",
        "super",
        "trait",
        "true",
        "type",
        "unsafe",
        "use",
        "where",
        "while",
        "async",
        "await",
        "dyn",
        "abstract",
        "become",
        "box",
        "do",
        "final",
        "macro",
        "override",
        "priv",
        "typeof",
        "unsized",
        "virtual",
        "yield",
        "try",
        "gen",
    ]
)


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


def f64_literal(value: float | int) -> str:
    """A Rust f64 expression for a bound or default: `100.0`, `-0.5`, `F32_MAX`."""
    number = float(value)
    if number == FLOAT32_MAX:
        return "crate::payload::F32_MAX"
    if number == -FLOAT32_MAX:
        return "-crate::payload::F32_MAX"
    text = repr(number)
    if "e" in text or "." in text:
        return text.replace("e+", "e")
    return f"{text}.0"


def f32_literal(value: float | int) -> str:
    """The shortest Rust literal that reads back as the same float32 (clippy: no excess precision)."""
    import struct

    number = struct.unpack("<f", struct.pack("<f", float(value)))[0]
    for digits in range(1, 10):
        text = f"{number:.{digits}g}"
        if struct.unpack("<f", struct.pack("<f", float(text)))[0] == number:
            break
    text = repr(float(text))
    return text.replace("e+", "e") if ("e" in text or "." in text) else f"{text}.0"


def int_literal(value: float | int) -> str:
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
    """Prose as `///` lines of at most `width` characters (plus the indent)."""
    pad = " " * indent
    lines = naming.wrap(escape_doc(text), width - indent - 4) or [""]
    return "\n".join(f"{pad}/// {line}".rstrip() for line in lines)


def escape_doc(text: str) -> str:
    """Keep rustdoc from reading spec prose as markup: brackets and angle brackets."""
    return text.replace("<", "&lt;").replace(">", "&gt;").replace("[", "\\[").replace("]", "\\]")


def accessor(field: Field) -> str:
    """The name of a scaled field's engineering accessor: `heading_deg`, `gyro_x_dps`."""
    if field.unit is None:
        return f"{ident(field.name)}_value"
    return f"{ident(field.name)}_{field.unit.suffix.lower()}"


def unit_doc(field: Field) -> str:
    """`degrees` or `raw units` for doc lines."""
    return field.unit.doc if field.unit is not None else "raw units"


def checked_range(field: Field) -> bool:
    """True when a builder must check an integer field against a range narrower than its type."""
    if not field.is_integer or field.range is None:
        return False
    return (field.range[0], field.range[1]) != (field.type.min, field.type.max)


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
    for unit in spec.units:
        if unit.key == field.unit:
            return unit.suffix.lower()
    return "value"


def nmea_unit_doc(spec: Spec, field: NmeaField) -> str:
    for unit in spec.units:
        if unit.key == field.unit:
            return unit.doc
    return "raw units"


def ack_field(spec: Spec) -> Field:
    """The one u16 field of the acknowledgement payload: the acknowledged message's checksum."""
    if spec.ack_payload is None:
        raise ValueError("the spec names no acknowledgement payload")
    payload = spec.payload(spec.ack_payload)
    numeric = [f for f in payload.fields if f.kind != "reserved"]
    if len(numeric) != 1 or numeric[0].type.name != spec.frame.checksum.type.name:
        raise ValueError("the acknowledgement payload must hold exactly one field of the checksum's type")
    return numeric[0]


def variant_payloads(spec: Spec) -> list[Payload]:
    return [p for p in spec.payloads if p.variant_dependent]


def encodings_used(spec: Spec) -> list[str]:
    """Every field encoding any payload uses, in first-use order."""
    seen: list[str] = []
    for payload in spec.payloads:
        for field in payload.fields:
            if field.encoding is not None and field.encoding not in seen:
                seen.append(field.encoding)
    return seen


def max_fields(spec: Spec) -> int:
    return max(len(p.fields) for p in spec.payloads)


def power_of_ten(decimals: int) -> int:
    return int(10**decimals)


def byte_order(spec: Spec) -> str:
    """`le` or `be`: the spec's `byte_order` as Rust's `from_le_bytes` / `from_be_bytes` spell it."""
    orders = {"little": "le", "big": "be"}
    if spec.byte_order not in orders:
        raise ValueError(f"unknown byte order {spec.byte_order!r}")
    return orders[spec.byte_order]


def checksum_algorithm(spec: Spec) -> str:
    """The frame checksum algorithm, refused unless the crate implements it (`sum16`: the byte sum
    modulo 2^16, what `frame::checksum` computes)."""
    if spec.frame.checksum_algorithm != "sum16":
        raise ValueError(f"the Rust target implements the sum16 checksum, not {spec.frame.checksum_algorithm!r}")
    return spec.frame.checksum_algorithm


def date_decode(spec: Spec) -> str:
    """The date decode rule, refused unless `encoding::Date::decode` implements it."""
    if spec.date is None or spec.date.decode != "nearest_calendar_date":
        raise ValueError(f"the Rust target decodes dates to the nearest calendar date, not {spec.date!r}")
    return spec.date.decode


def wire_types(spec: Spec) -> list[str]:
    """The Rust integer and float types the wire helpers must read and write, in a fixed order."""
    used = {_INT_TYPES.get(f.type.name, f.type.name) for p in spec.payloads for f in p.fields if f.is_numeric}
    used |= {_INT_TYPES[f.type.name] for f in (*spec.frame.fields, spec.frame.checksum)}
    if "f32" in used:
        used.add("u32")
    return [t for t in ("u8", "i8", "u16", "i16", "u32", "i32", "f32") if t in used]


def encoding_type(spec: Spec, encoding: str) -> str:
    """The Rust type of the fields that use `encoding` (they must share one)."""
    types = {rust_type(f) for p in spec.payloads for f in p.fields if f.encoding == encoding}
    if len(types) != 1:
        raise ValueError(f"fields encoded as {encoding} must share one type, found {sorted(types)}")
    return types.pop()


def enum_type(spec: Spec, name: str) -> str:
    """The Rust type of the fields that hold enumeration `name` (they must share one)."""
    types = {rust_type(f) for p in spec.payloads for f in p.fields if f.enum == name}
    if len(types) != 1:
        raise ValueError(f"fields of enum {name} must share one type, found {sorted(types)}")
    return types.pop()


def usw_type(spec: Spec) -> str:
    """The Rust type of a Unit Status Word: that of the fields encoded as one."""
    return encoding_type(spec, "usw")


def scale_expr(field: Field, raw: str) -> str:
    """The engineering value of `raw` (a Rust f64 expression) in the order raw x multiplier / divisor."""
    if field.scale is None:
        raise ValueError(f"field {field.name} has no scale")
    text = raw
    if field.scale.multiplier != 1:
        text += f" * {f64_literal(field.scale.multiplier)}"
    if field.scale.divisor_parameter is not None:
        text += f" / f64::from(variant.{ident(field.scale.divisor_parameter)}())"
    elif field.scale.divisor not in (None, 1):
        text += f" / {f64_literal(field.scale.divisor)}"
    return text


def _number(value: float | str | None) -> float:
    if isinstance(value, str):
        raise ValueError(f"a numeric field has the default {value!r}")
    return float(value or 0)


def default_literal(field: Field) -> str:
    """A Rust expression for the value a builder uses when a field is not given."""
    if field.kind == "reserved":
        return f"[0; {field.size}]"
    if field.kind == "char":
        text = str(field.default_value or "")
        if not text:
            return f"[0; {field.size}]"
        padded = text.encode("latin-1").ljust(field.size, b"\0")
        return "*" + byte_string(padded.decode("latin-1"))
    if field.is_float:
        return f32_literal(_number(field.default_value))
    return int_literal(_number(field.default_value))


def default_value(field: Field) -> str:
    """The default as a `Value<'static>` expression."""
    if field.is_bytes:
        return (
            f"Value::Bytes(&{default_literal(field)})"
            if field.kind == "reserved"
            else ("Value::Bytes(" + byte_string(str(field.default_value or "")) + ")")
        )
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


def header_const(spec: Spec) -> str:
    return "[" + ", ".join(naming.hex_byte(b) for b in spec.frame.header) + "]"


def first_with(items: list[Any] | tuple[Any, ...], attribute: str) -> Any:
    """The first item whose `attribute` is truthy (for examples in docs)."""
    for item in items:
        if getattr(item, attribute):
            return item
    raise ValueError(f"no item has {attribute}")


def format_pair(name: str) -> str:
    """`name={}`: one `KEY=VALUE` of an answer line, as a Rust format string piece."""
    return f"{name}={{}}"


# The device state machine. Events are the commands (by their `id`) and the spec's other events;
# answers come from the model (`spec.state_machine.answers`).
UNKNOWN_EVENT = "unknown"


def _machine(spec: Spec) -> StateMachine:
    if spec.state_machine is None:
        raise ValueError("the spec has no state_machine")
    return spec.state_machine


def _unique(names: list[str], what: str) -> list[str]:
    clashes = sorted({n for n in names if names.count(n) > 1})
    if clashes:
        raise ValueError(f"{what} names clash in Rust: {clashes}")
    return names


def sm_events(spec: Spec) -> list[dict[str, Any]]:
    """Every event of the table, commands first (spec order), then the other events: the Rust
    variant, the name the table uses, the command (or None) and a doc line."""
    events: list[dict[str, Any]] = [
        {
            "variant": type_name(c.id),
            "name": c.name,
            "command": c,
            "doc": f"The command `{c.name}` ({naming.hex_byte(c.code)}, {c.icd}).",
        }
        for c in spec.commands
    ]
    events += [
        {"variant": type_name(e.name), "name": e.name, "command": None, "doc": e.doc} for e in _machine(spec).events
    ]
    _unique([e["variant"] for e in events], "event")
    return events


def sm_event(spec: Spec, name: str) -> str:
    """The Rust variant of the table's event `name` (a command's ICD name or another event)."""
    for event in sm_events(spec):
        if event["name"] == name:
            return str(event["variant"])
    raise ValueError(f"the state machine has no event {name!r}")


def sm_timer_event(spec: Spec, timer: str) -> str:
    """The Rust variant of the event a state's `timer` fires."""
    return sm_event(spec, TIMER_EVENTS[timer])


def sm_answers(spec: Spec) -> list[dict[str, Any]]:
    """Every answer the table sends, in first-use order: the Rust variant, the spec name, the payload
    table (or None), the USW mode (or None) and a doc line."""
    answers: list[dict[str, Any]] = []
    for a in _machine(spec).answers:
        payload = next((p for p in spec.payloads if p.name == a.payload), None)
        doc = f"One {payload.name} block ({payload.icd}, {payload.title})." if payload is not None else a.doc
        answers.append({"variant": type_name(a.name), "name": a.name, "payload": payload, "mode": a.mode, "doc": doc})
    _unique([a["variant"] for a in answers], "answer")
    return answers


def firmware_parts(version: str) -> list[int]:
    """A firmware version as its numeric parts: "4.9.9.0" -> [4, 9, 9, 0]."""
    parts = version.strip().split(".")
    if not all(part.isdigit() for part in parts):
        raise ValueError(f"firmware version {version!r} is not numeric")
    return [int(part) for part in parts]


def sm_rows(spec: Spec) -> list[Transition]:
    """The table's rows sorted by state, then event (declaration order), the rows for older firmware
    before the current row of the same pair."""
    machine = _machine(spec)
    states = [s.name for s in machine.states]
    events = [e["name"] for e in sm_events(spec)]

    def key(t: Transition) -> tuple[int, int, bool, list[int]]:
        return (
            states.index(t.state),
            events.index(t.event),
            t.firmware_before is None,
            firmware_parts(t.firmware_before or "0"),
        )

    rows = sorted(machine.transitions, key=key)
    current = [(t.state, t.event) for t in rows if t.firmware_before is None]
    if len(set(current)) != len(current):
        raise ValueError("the state machine has two current rows for one (state, event)")
    return rows


def sm_max_firmware_parts(spec: Spec) -> int:
    """The most parts a firmware version of the table has."""
    versions = [t.firmware_before for t in _machine(spec).transitions if t.firmware_before]
    return max([len(firmware_parts(v)) for v in versions] or [1])


def sm_code_events(spec: Spec, code: int) -> list[tuple[list[str], str]]:
    """What a command code means in each mode, as (modes, event variant) groups in mode order: the
    command valid in the mode, else the spec's `unknown` event."""
    groups: dict[str, list[str]] = {}
    for mode in spec.modes:
        command = spec.command_in_mode(code, mode.name)
        variant = sm_event(spec, UNKNOWN_EVENT) if command is None else type_name(command.id)
        groups.setdefault(variant, []).append(mode.name)
    return [(modes, variant) for variant, modes in groups.items()]


# Layout: the generated code must be what rustfmt (default configuration, edition 2021) would
# write, without running rustfmt. Data-dependent lines pick rustfmt's one-line or vertical form
# by the same widths rustfmt uses.
MAX_WIDTH = 100
SHORT_WIDTH = 60  # fn_call_width, array_width, chain_width
STRUCT_LIT_WIDTH = 18


def fits(text: str, indent: int = 0) -> bool:
    """True if `text`, indented by `indent` spaces, fits rustfmt's line width."""
    return indent + len(text) <= MAX_WIDTH


def _lines(items: list[str], indent: int) -> str:
    return "".join(f"{' ' * (indent + 4)}{item},\n" for item in items)


def arm(pattern: str, body: str, indent: int) -> str:
    """A match arm: `pattern => body,` or, when too long, its body in a block."""
    one = f"{pattern} => {body},"
    if fits(one, indent):
        return one
    pad = " " * indent
    return f"{pattern} => {{\n{pad}    {body}\n{pad}}}"


def seq(items: list[str], indent: int, head: str = "", tail: str = "", brackets: str = "[]") -> str:
    """`head[a, b]tail` on one line when it fits, else one item per line (rustfmt's vertical list)."""
    inner = ", ".join(items)
    one = f"{head}{brackets[0]}{inner}{brackets[1]}{tail}"
    if fits(one, indent) and len(inner) <= SHORT_WIDTH:
        return one
    return f"{head}{brackets[0]}\n{_lines(items, indent)}{' ' * indent}{brackets[1]}{tail}"


def assign_seq(items: list[str], indent: int, head: str, tail: str = ";") -> str:
    """`head = [a, b]tail`: on one line when it fits; else the array alone on the next line when it
    fits there (rustfmt prefers a one-line right-hand side); else one item per line."""
    inner = ", ".join(items)
    array = f"[{inner}]"
    if fits(f"{head} = {array}{tail}", indent) and len(inner) <= SHORT_WIDTH:
        return f"{head} = {array}{tail}"
    if len(array) <= SHORT_WIDTH and fits(f"{array}{tail}", indent + 4):
        return f"{head} =\n{' ' * (indent + 4)}{array}{tail}"
    return f"{head} = [\n{_lines(items, indent)}{' ' * indent}]{tail}"


def signature(head: str, params: list[str], tail: str, indent: int) -> str:
    """`head(params) tail {` on one line when it fits, else one parameter per line."""
    one = f"{head}({', '.join(params)}){tail} {{"
    if fits(one, indent):
        return one
    return f"{head}(\n{_lines(params, indent)}{' ' * indent}){tail} {{"


def struct_lit(name: str, fields: list[str], indent: int, tail: str = "") -> str:
    """A struct literal: on one line only when its fields are short (rustfmt's struct_lit_width)."""
    inner = ", ".join(fields)
    one = f"{name} {{ {inner} }}{tail}"
    if len(inner) <= STRUCT_LIT_WIDTH and fits(one, indent):
        return one
    return f"{name} {{\n{_lines(fields, indent)}{' ' * indent}}}{tail}"


def init(name: str, value: str, indent: int) -> str:
    """A struct field initialiser, `name: value,`, moving a long value to the next line."""
    one = f"{name}: {value},"
    if fits(one, indent):
        return one
    return f"{name}:\n{' ' * (indent + 4)}{value},"


def _use_key(path: str) -> list[tuple[int, str]]:
    key = []
    for segment in path.replace("{", "").split("::"):
        if segment in ("self", "super", "crate"):
            rank = 0
        elif segment[:1].islower():
            rank = 1
        elif segment.isupper():
            rank = 3
        else:
            rank = 2
        key.append((rank, segment))
    return key


def sort_uses(paths: list[str]) -> list[str]:
    """`use` paths in rustfmt's order (lower-case segments before types)."""
    return sorted(set(paths), key=_use_key)


def prefix(text: str, head: str) -> str:
    """`head` + `text` (to map a list of names to paths)."""
    return head + text


FILTERS: dict[str, Callable[..., Any]] = {
    "prefix": prefix,
    "sort_uses": sort_uses,
    "format_pair": format_pair,
    "ident": ident,
    "const": const,
    "type_name": type_name,
    "rust_type": rust_type,
    "value_kind": value_kind,
    "f64": f64_literal,
    "int_lit": int_literal,
    "byte_string": byte_string,
    "string": string,
    "doc": doc,
    "escape_doc": escape_doc,
    "accessor": accessor,
    "unit_doc": unit_doc,
    "checked_range": checked_range,
    "nmea_type": nmea_type,
    "power_of_ten": power_of_ten,
    "first_with": first_with,
    "scale_expr": scale_expr,
    "default_literal": default_literal,
    "default_value": default_value,
    "derivable_default": derivable_default,
}

GLOBALS: dict[str, Any] = {
    "fits": fits,
    "assign_seq": assign_seq,
    "arm": arm,
    "seq": seq,
    "signature": signature,
    "struct_lit": struct_lit,
    "init": init,
    "ack_field": ack_field,
    "variant_payloads": variant_payloads,
    "encodings_used": encodings_used,
    "max_fields": max_fields,
    "header_const": header_const,
    "usw_type": usw_type,
    "encoding_type": encoding_type,
    "enum_type": enum_type,
    "wire_types": wire_types,
    "byte_order": byte_order,
    "checksum_algorithm": checksum_algorithm,
    "date_decode": date_decode,
    "nmea_unit_suffix": nmea_unit_suffix,
    "nmea_unit_doc": nmea_unit_doc,
    "sm_events": sm_events,
    "sm_event": sm_event,
    "sm_timer_event": sm_timer_event,
    "sm_answers": sm_answers,
    "sm_rows": sm_rows,
    "sm_code_events": sm_code_events,
    "sm_max_firmware_parts": sm_max_firmware_parts,
    "firmware_parts": firmware_parts,
}
