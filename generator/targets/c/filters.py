"""Small filters for the C templates: C types, literals and comments from model values."""

from __future__ import annotations

import math
import struct
from collections.abc import Callable
from typing import Any

from generator import naming
from generator.model import Field, Nmea, NmeaField, Spec

_UNSIGNED = ((0xFF, "uint8_t"), (0xFFFF, "uint16_t"), (0xFFFFFFFF, "uint32_t"))
_SIGNED = ((0x7F, "int8_t"), (0x7FFF, "int16_t"), (0x7FFFFFFF, "int32_t"))


def c_int_type(low: float, high: float) -> str:
    """The smallest <stdint.h> type holding every integer in low..high."""
    if low >= 0:
        for top, name in _UNSIGNED:
            if high <= top:
                return name
    else:
        for top, name in _SIGNED:
            if -top - 1 <= low and high <= top:
                return name
    raise ValueError(f"no 32-bit C integer type holds {low}..{high}")


def c_index_type(count: int) -> str:
    """A type for indices 0..count (tables of names, fields, bounds)."""
    return c_int_type(0, count)


def c_scalar(f: Field) -> str:
    """The C type of a numeric field's struct member (same width and signedness as the wire)."""
    if f.kind == "float":
        if f.size != 4:
            raise ValueError(f"{f.name}: only 32-bit floats are supported")
        return "float"
    if f.kind in ("unsigned", "signed"):
        prefix = "uint" if f.kind == "unsigned" else "int"
        return f"{prefix}{8 * f.size}_t"
    raise ValueError(f"{f.name} is not numeric")


def c_member(f: Field) -> str:
    """The struct member declaring a payload field (char fields keep room for a NUL)."""
    if f.kind == "char":
        return f"char {f.name}[{f.size} + 1]"
    if f.kind == "reserved":
        return f"uint8_t {f.name}[{f.size}]"
    return f"{c_scalar(f)} {f.name}"


def c_nmea_type(f: NmeaField) -> str:
    return c_int_type(f.min, f.max)


def c_double(value: float) -> str:
    """An exact C double literal."""
    value = float(value)
    if not math.isfinite(value):
        raise ValueError("no literal for a non-finite value")
    text = repr(abs(value)) if value < 0 else repr(value)
    if "e" not in text and "." not in text and "inf" not in text:
        text += ".0"
    return f"(-{text})" if value < 0 else text


def c_float(value: float) -> str:
    text = c_double(value)
    return f"{text[:-1]}f)" if text.endswith(")") else text + "f"


def c_int(value: float) -> str:
    """A C integer literal: unsigned suffix for non-negative values, INT32_MIN-safe for negatives."""
    number = int(value)
    if number != value:
        raise ValueError(f"{value} is not an integer")
    if number >= 0:
        return f"{number}u" if number > 0x7FFF else str(number)
    if number == -0x80000000:
        return "(-2147483647 - 1)"
    return f"({number})"


def c_signed(value: int) -> str:
    """A C literal of a signed value (no unsigned suffix), for int32_t tables and macros."""
    if not -(2**31) <= value < 2**31:
        raise ValueError(f"{value} is not an int32")
    if value == -(2**31):
        return "(-2147483647 - 1)"
    return f"({value})" if value < 0 else str(value)


def c_string(text: str) -> str:
    out = []
    for ch in text:
        code = ord(ch)
        if ch in '"\\':
            out.append("\\" + ch)
        elif 0x20 <= code < 0x7F:
            out.append(ch)
        else:
            out.append(f"\\{code:03o}")
    return '"' + "".join(out) + '"'


def c_comment(text: str, indent: int = 0, width: int = 100, first: str = "/** ", cont: str = " *  ") -> str:
    """`text` as a block comment wrapped to `width` columns."""
    pad = " " * indent
    lines = naming.wrap(text, width - indent - len(first) - 3) or [""]
    if len(lines) == 1:
        return f"{pad}{first}{lines[0]} */"
    body = [f"{pad}{first}{lines[0]}"] + [f"{pad}{cont}{line}" for line in lines[1:]]
    return "\n".join(body) + " */"


def macro(*parts: str) -> str:
    """ILAHRS_ + the upper-cased parts joined by underscores."""
    return "_".join(["ILAHRS", *(naming.upper(p) for p in parts if p)])


def unit_suffix(f: Field) -> str:
    return f.unit.suffix if f.unit is not None else "value"


def nmea_suffix(spec: Spec, f: NmeaField) -> str:
    for unit in spec.units:
        if unit.key == f.unit:
            return unit.suffix
    return "value"


def banner(title: str) -> str:
    """A section banner of the header: the title between two rules, 92 columns wide."""
    rule = "/* " + "=" * 88 + " */"
    return f"{rule}\n/* {title:<88} */\n{rule}"


def macro_of(name: str, prefix: str) -> str:
    """macro(prefix, name), for map() over names."""
    return macro(prefix, name)


def format_with(value: str, pattern: str) -> str:
    """`pattern` % value, for map() over names."""
    return pattern % value


def mode_bit(mode: str) -> str:
    """A mode's bit in a mode set."""
    return f"ILAHRS_MODE_BIT({macro('mode', mode)})"


def payload_macro(name: str | None) -> str:
    """The ilahrs_payload_t constant of a payload table, ILAHRS_PAYLOAD_NONE for none."""
    return macro("payload", name) if name else "ILAHRS_PAYLOAD_NONE"


def payload_list(names: tuple[str, ...], length: int) -> str:
    """`length` payload constants: the tables named, then ILAHRS_PAYLOAD_NONE."""
    return ", ".join(payload_macro(names[i] if i < len(names) else None) for i in range(length))


def name_offset(name: str, t: Any) -> int:
    """The offset of a name in the shared name pool."""
    offset: int = t.pools["name"][name]
    return offset


def number_text(value: float) -> str:
    """A bound as a person reads it: an integer without a point, else float32's 9 digits."""
    return str(int(value)) if float(value).is_integer() else f"{value:.9g}"


FLOAT32_MAX = float(struct.unpack("<f", struct.pack("<I", 0x7F7FFFFF))[0])


def field_row_comment(r: Any, t: Any, spec: Spec) -> str:
    """What the bare numbers of a row of ilahrs_fields stand for (tables.FieldRow `r` of tables
    `t`): the field, its offset in the field-name pool, and for a number the row of its builder
    bounds (ilahrs_int_bounds or ilahrs_float_bounds, by kind; "finite" for every finite float)
    and of its engineering scale (ilahrs_scales: multiplier/divisor, a variant parameter's name
    as the divisor), with the unit; a row 0 (no check, unscaled) is left out."""
    f = r.field
    parts = [f"name@{r.name}"]
    unit = f" {f.unit.symbol}" if f.unit is not None and f.unit.symbol else ""
    if f.is_numeric and r.bounds:
        b = (t.float_bounds if f.is_float else t.int_bounds)[r.bounds]
        finite = f.is_float and b.low == -FLOAT32_MAX and b.high == FLOAT32_MAX
        parts.append(f"bounds[{r.bounds}]=" + ("finite" if finite else f"{number_text(b.low)}..{number_text(b.high)}"))
    if f.is_numeric and r.scale:
        s = t.scales[r.scale]
        divisor = spec.variant_parameters[s.parameter].name if s.divisor == 0 else str(s.divisor)
        parts.append(f"scale[{r.scale}]={s.multiplier}/{divisor}{unit}")
    elif f.is_numeric and unit:
        parts.append(f"in{unit}")
    text = f"{f.name}: {', '.join(parts)}"
    if "*/" in text:
        raise ValueError(f"{f.name}: a row comment cannot hold {text!r}")
    return text


def answer_macro(index: int, m: Any) -> str:
    """The ilahrs_answer_t constant of answer `index` of the machine."""
    return macro("answer", m.answers[index].name)


def event_macro(name: str, spec: Spec) -> str:
    """The ilahrs_event_t constant of an event: a command's (by its ICD name) or one of the others."""
    for c in spec.commands:
        if c.name == name:
            return macro("event", c.id)
    return macro("event", name)


def pahr_parameter(f: NmeaField) -> str:
    """A parameter of ilahrs_pahr_from_values(): a double for a decimal field, else its C type."""
    return f"double {f.name}" if f.format == "decimal" else f"{c_nmea_type(f)} {f.name}"


def field_doc(f: Field) -> str:
    """One comment for a payload struct member: what it is, its unit, scale, range and source."""
    parts = [f.doc.rstrip(".") + "." if f.doc else ""]
    facts = []
    if f.unit is not None and f.scale is None:
        facts.append(f.unit.doc)
    if f.scale is not None:
        div = f.scale.divisor_parameter or str(f.scale.divisor)
        mul = f" x {f.scale.multiplier}" if f.scale.multiplier != 1 else ""
        unit = f.unit.doc if f.unit is not None else "engineering units"
        facts.append(f"{unit} = raw{mul}" + (f" / {div}" if div != "1" else ""))
    if f.range is not None:
        low, high = f.range
        facts.append(f"builders accept {low:g}..{high:g}")
    if f.encoding is not None:
        facts.append(f"encoding {f.encoding}")
    if f.kind == "char":
        facts.append(f"{f.size} bytes, NUL-padded on the wire")
    if f.kind == "reserved":
        facts.append(f"{f.size} reserved bytes, kept verbatim")
    if f.multiplexed_count:
        facts.append(f"multiplexed: {f.multiplexed_count} quantities in successive frames")
    facts.append(f"ICD: {f.icd_name}")
    if f.erratum:
        facts.append(f"erratum {f.erratum}")
    return " ".join(p for p in parts if p) + " (" + "; ".join(facts) + ")"


_RESPONSE_DOCS = {
    "none": "Nothing.",
    "ack": "An acknowledgement: a data frame carrying the checksum of the received message (ilahrs_ack_build()).",
    "data": "A data block of a payload table (ilahrs_command_response_payload()).",
    "output": "One block of the current output format.",
}


def response_doc(kind: str) -> str:
    return _RESPONSE_DOCS.get(kind, f"Response kind `{kind}`.")


def float32(value: float) -> float:
    """The float32 nearest to `value` (as C's double-to-float conversion)."""
    result: float = struct.unpack("<f", struct.pack("<f", value))[0]
    return result


def float_key(value: float) -> int:
    """The integer that orders float32 values like the floats (ilahrs.c, float_key()): the bits of a
    non-negative float, minus the magnitude bits of a negative one; -0.0 and 0.0 are both 0."""
    bits: int = struct.unpack("<I", struct.pack("<f", value))[0]
    if bits != struct.unpack("<I", struct.pack("<f", float32(value)))[0] or not math.isfinite(value):
        raise ValueError(f"{value!r} is not a finite float32")
    magnitude = bits & 0x7FFFFFFF
    return -magnitude if bits & 0x80000000 else magnitude


def double_key(value: float) -> int:
    """The 64-bit float_key(): orders doubles like the values (ilahrs.c, double_key()), the bits of
    a non-negative double, minus the magnitude bits of a negative one; -0.0 and 0.0 are both 0."""
    value = float(value)
    if not math.isfinite(value):
        raise ValueError(f"{value!r} is not a finite double")
    bits: int = struct.unpack("<Q", struct.pack("<d", value))[0]
    magnitude = bits & 0x7FFF_FFFF_FFFF_FFFF
    return -magnitude if bits >> 63 else magnitude


def c_int64(value: int) -> str:
    """A C literal of an int64_t value (no unsigned suffix)."""
    if not -(2**63) < value < 2**63:
        raise ValueError(f"{value} is not an int64 literal")
    return f"(-{-value}ll)" if value < 0 else f"{value}ll"


def c_member_bits(value: float, f: Field) -> str:
    """The bits a numeric field's struct member holds for `value`, as a uint32_t literal: the bits
    of the float32 nearest it, or an integer's two's complement in the field's size (refused unless
    the member holds it exactly)."""
    if f.kind == "float" and f.size == 4:
        bits: int = struct.unpack("<I", struct.pack("<f", value))[0]
    elif f.kind in ("unsigned", "signed") and f.size in (1, 2, 4) and value == int(value):
        half = 2 ** (8 * f.size - 1)
        low, high = (0, 2 * half - 1) if f.kind == "unsigned" else (-half, half - 1)
        if not low <= int(value) <= high:
            raise ValueError(f"{f.name}: {value!r} does not fit its {f.size}-byte {f.kind} member")
        bits = int(value) % 2 ** (8 * f.size)
    else:
        raise ValueError(f"{f.name}: {value!r} is not a value of a numeric member")
    return f"0x{bits:08X}u"


# ilahrs.c multiplies a double's 53-bit significand by a $PAHR divisor in 64 bits (pahr_magnitude()).
PAHR_DIVISOR_LIMIT = 2**11


def pahr_max_divisor(nmea: Nmea) -> int:
    """The largest $PAHR divisor, refused unless 53-bit significands times it stay below 2^64."""
    divisor = max((f.divisor for f in nmea.fields if f.format == "decimal"), default=1)
    if divisor >= PAHR_DIVISOR_LIMIT:
        raise ValueError(f"$PAHR divisor {divisor}: the C code rounds exactly only below {PAHR_DIVISOR_LIMIT}")
    return divisor


FILTERS: dict[str, Callable[..., Any]] = {
    "c_index_type": c_index_type,
    "c_scalar": c_scalar,
    "c_member": c_member,
    "c_nmea_type": c_nmea_type,
    "c_double": c_double,
    "c_float": c_float,
    "c_int": c_int,
    "c_string": c_string,
    "c_comment": c_comment,
    "macro": macro,
    "unit_suffix": unit_suffix,
    "float32": float32,
    "float_key": float_key,
    "c_signed": c_signed,
    "double_key": double_key,
    "c_int64": c_int64,
    "c_member_bits": c_member_bits,
    "macro_of": macro_of,
    "format_with": format_with,
    "mode_bit": mode_bit,
    "payload_macro": payload_macro,
    "payload_list": payload_list,
    "name_offset": name_offset,
    "field_row_comment": field_row_comment,
    "answer_macro": answer_macro,
    "event_macro": event_macro,
    "pahr_parameter": pahr_parameter,
}
