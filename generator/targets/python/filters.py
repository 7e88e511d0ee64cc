"""Filters of the Python target: small functions from model values to Python text."""

from __future__ import annotations

import textwrap
from collections.abc import Callable
from typing import Any

from generator.model import FLOAT32_MAX, Field, Payload, StatusWord
from generator.targets import naming

_STRUCT_CODES = {"u8": "B", "s8": "b", "u16": "H", "s16": "h", "u32": "I", "s32": "i", "f32": "f"}


def struct_code(field: Field) -> str:
    """The `struct` format code of a field: `H`, `h`, `f`, `50s` ..."""
    if field.is_bytes:
        return f"{field.size}s"
    return _STRUCT_CODES[field.type.name]


def struct_format(fields: tuple[Field, ...]) -> str:
    """A little-endian `struct` format for consecutive fields."""
    return "<" + "".join(struct_code(f) for f in fields)


def py_type(field: Field) -> str:
    if field.is_integer:
        return "int"
    if field.is_float:
        return "float"
    if field.kind == "char":
        return "str"
    return "bytes"


def py_default(field: Field) -> str:
    """The default value of a field as Python source."""
    if field.kind == "reserved":
        return f'b"\\x00" * {field.size}'
    if field.kind == "char":
        return repr(field.default if isinstance(field.default, str) else "")
    value = field.default_value
    assert isinstance(value, (int, float))
    return repr(float(value)) if field.is_float else repr(int(value))


def py_number(value: float, is_float: bool) -> str:
    return repr(float(value)) if is_float else repr(int(value))


def flag_mask(status: StatusWord, byte: str) -> str:
    """The mask of the flags that live in one byte of the status word (mode bits excluded)."""
    mask = 0
    for flag in status.flags:
        if flag.byte == byte:
            mask |= flag.mask
    return naming.hex_word(mask)


def scale_expr(field: Field, value: str, variant: str = "variant") -> str:
    """Python expression converting the raw `value` to engineering units."""
    assert field.scale is not None
    expr = value
    if field.scale.multiplier != 1:
        expr = f"{expr} * {field.scale.multiplier}"
    if field.scale.divisor_parameter is not None:
        expr = f"{expr} / {variant}.{field.scale.divisor_parameter.lower()}"
    elif field.scale.divisor not in (None, 1):
        expr = f"{expr} / {field.scale.divisor}"
    else:
        expr = f"float({expr})"
    return expr


def accessor(field: Field) -> str:
    """The name of a field's engineering accessor: `heading_deg`, `gyro_x_dps`."""
    assert field.unit is not None
    return f"{field.name}_{field.unit.suffix}"


def docstring(text: str, indent: int = 4, width: int = 112) -> str:
    """Wrap prose for a docstring body at the given indent, leaving room for the quotes."""
    pad = " " * indent
    body = text.replace('"""', "'''").replace("\\", "\\\\")
    return ("\n" + pad).join(naming.wrap(body, width - indent - 6))


def field_summary(field: Field) -> str:
    """One line describing a field's wire form."""
    parts = [f"{field.type.name if not field.is_bytes else field.kind + '[' + str(field.size) + ']'}"]
    parts.append(f"at offset {field.offset}")
    if field.scale is not None and field.unit is not None:
        s = field.scale
        div = s.divisor_parameter or (str(s.divisor) if s.divisor not in (None, 1) else "")
        mul = str(s.multiplier) if s.multiplier != 1 else ""
        unit = "value" if field.unit.key == "one" else field.unit.key
        scale = unit + (f" x {div}" if div else "") + (f" / {mul}" if mul else "")
        parts.append(f"raw = {scale}")
    elif field.unit is not None:
        parts.append(f"unit {field.unit.key}")
    if field.range is not None:
        parts.append(f"range {field.range[0]}..{field.range[1]}")
    parts.append(f"ICD: {field.icd_name}")
    return ", ".join(parts)


def field_doc(field: Field) -> str:
    """A field's docstring: its doc, then its wire form, erratum and multiplexing."""
    text = f"{field.doc} " if field.doc else ""
    text += f"({field_summary(field)}"
    text += f"; erratum {field.erratum})" if field.erratum else ")"
    if field.multiplexed_count:
        text += f" Multiplexed: {field.multiplexed_count} quantities in successive frames."
    return text


def _bound(value: float, is_float: bool) -> str:
    if is_float and abs(value) == FLOAT32_MAX:
        return "-FLOAT32_MAX" if value < 0 else "FLOAT32_MAX"
    return py_number(value, is_float)


def field_info(field: Field) -> str:
    """A field's row of its class's FIELDS table: `FieldInfo("heading", "Heading", 0, 2, ...)`."""
    scale = field.scale
    divisor: int | str = 1
    if scale is not None:
        divisor = scale.divisor_parameter.lower() if scale.divisor_parameter else (scale.divisor or 1)
    args = [
        repr(field.name),
        repr(field.icd_name),
        str(field.offset),
        str(field.size),
        repr(field.type.name),
        repr(field.unit.key if field.unit is not None else None),
        str(scale.multiplier if scale is not None else 1),
        repr(divisor),
    ]
    if field.bounds is not None:
        args += [_bound(field.bounds[0], field.is_float), _bound(field.bounds[1], field.is_float)]
    if field.encoding is not None:
        args.append(f"encoding={field.encoding!r}")
    if field.multiplexed_count:
        args.append(f"multiplexed={field.multiplexed_count}")
    return f"FieldInfo({', '.join(args)})"


def class_name(payload: Payload) -> str:
    return naming.pascal(payload.name)


def literal(value: Any) -> str:
    return repr(value)


def long_literal(text: str, indent: int = 8, width: int = 120) -> str:
    """A string literal that fits the line width after `indent` spaces and a dict key: as it is when it
    is short, else pieces of at most `width` columns in parentheses (implicit concatenation)."""
    if indent + 8 + len(repr(text)) <= width:  # the key and ": " take 7 or 8 columns
        return repr(text)
    pad = " " * (indent + 4)
    pieces = textwrap.wrap(text, width - len(pad) - 3, drop_whitespace=False, break_on_hyphens=False)
    return "(\n" + "\n".join(pad + repr(piece) for piece in pieces) + "\n" + " " * indent + ")"


FILTERS: dict[str, Callable[..., Any]] = {
    "struct_code": struct_code,
    "struct_format": struct_format,
    "py_type": py_type,
    "py_default": py_default,
    "py_number": py_number,
    "flag_mask": flag_mask,
    "scale_expr": scale_expr,
    "accessor": accessor,
    "docstring": docstring,
    "field_summary": field_summary,
    "class_name": class_name,
    "field_doc": field_doc,
    "literal": literal,
    "long_literal": long_literal,
    "field_info": field_info,
}


def tuple_literal(items: list[Any]) -> str:
    """A Python tuple literal: `()`, `("a",)`, `("a", "b")`."""
    if not items:
        return "()"
    if len(items) == 1:
        return f"({items[0]!r},)"
    return "(" + ", ".join(repr(i) for i in items) + ")"


FILTERS["tuple_literal"] = tuple_literal


def _natural(text: str) -> list[Any]:
    import re

    return [int(part) if part.isdigit() else part for part in re.split(r"(\d+)", text)]


def all_sorted(names: list[str]) -> list[str]:
    """Order `__all__` as ruff's RUF022 wants: CONSTANTS, then Classes, then functions."""

    def key(name: str) -> tuple[int, list[Any]]:
        group = 0 if name.isupper() else 1 if name[:1].isupper() else 2
        return group, _natural(name)

    return sorted(names, key=key)


FILTERS["all_sorted"] = all_sorted


# The property a field of each value encoding gets: (name suffix, type, doc, function of its raw value).
ENCODING_PROPERTIES = {
    "usw": ("status", "UnitStatusWord", "FIELD decoded: flags and mode.", "UnitStatusWord"),
    "date": ("ymd", "tuple[int, int, int]", "FIELD as (year, month, day) (E15).", "decode_date"),
    "declination": (
        "computed",
        "bool",
        "True if the AHRS computes the declination itself (value above the threshold).",
        "declination_is_computed",
    ),
    "calibration_success": (
        "accuracy_deg",
        "float | None",
        "Predicted 3-sigma heading error in degrees, or None (failed, or no estimate).",
        "calibration_accuracy_deg",
    ),
}
