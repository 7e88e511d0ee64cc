"""The model's wire types, fields and payload tables (part of generator.model).

A field says what the spec says about it: type, size, unit, scale, range, default, enum or
encoding. Its `offset` is -1 until the layout step (generator/layout.py) places it.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..load import PathKey


@dataclass(frozen=True)
class Primitive:
    """A wire type a field may have."""

    name: str
    size: int | None  # None: the field's `length` gives it
    kind: str  # "unsigned", "signed", "float", "char", "reserved"
    min: int | None = None
    max: int | None = None


PRIMITIVES: dict[str, Primitive] = {
    "u8": Primitive("u8", 1, "unsigned", 0, 0xFF),
    "s8": Primitive("s8", 1, "signed", -0x80, 0x7F),
    "u16": Primitive("u16", 2, "unsigned", 0, 0xFFFF),
    "s16": Primitive("s16", 2, "signed", -0x8000, 0x7FFF),
    "u32": Primitive("u32", 4, "unsigned", 0, 0xFFFFFFFF),
    "s32": Primitive("s32", 4, "signed", -0x80000000, 0x7FFFFFFF),
    "f32": Primitive("f32", 4, "float"),
    "char": Primitive("char", None, "char"),
    "reserved": Primitive("reserved", None, "reserved"),
}

FLOAT32_MAX = 3.4028234663852886e38


@dataclass(frozen=True)
class Unit:
    key: str
    suffix: str
    doc: str
    symbol: str
    """What follows a value shown to a person ("" for a dimensionless number)."""


@dataclass(frozen=True)
class Scale:
    """Engineering value = raw * multiplier / divisor; the divisor may be a variant parameter."""

    multiplier: int
    divisor: int | None
    divisor_parameter: str | None

    @property
    def variant_dependent(self) -> bool:
        return self.divisor_parameter is not None


@dataclass(frozen=True)
class Field:
    name: str
    icd_name: str
    type: Primitive
    size: int
    doc: str
    path: PathKey
    unit: Unit | None = None
    scale: Scale | None = None
    range: tuple[float, float] | None = None
    default: float | str | None = None
    enum: str | None = None
    encoding: str | None = None
    multiplexed_count: int | None = None
    multiplexed_quantities: tuple[str, ...] = ()
    erratum: str | None = None
    declared_offset: int | None = None
    offset: int = -1  # filled in by layout

    @property
    def kind(self) -> str:
        return self.type.kind

    @property
    def is_integer(self) -> bool:
        return self.type.kind in ("unsigned", "signed")

    @property
    def is_float(self) -> bool:
        return self.type.kind == "float"

    @property
    def is_numeric(self) -> bool:
        return self.is_integer or self.is_float

    @property
    def is_bytes(self) -> bool:
        return self.type.kind in ("char", "reserved")

    @property
    def end(self) -> int:
        return self.offset + self.size

    @property
    def default_value(self) -> float | str | None:
        """What a builder uses when no value is given: the spec's default, else 0 (or zeros,
        or empty text) if that is allowed, else the lowest allowed value."""
        if self.default is not None:
            return self.default
        if not self.is_numeric:
            return None
        bounds = self.bounds
        if bounds is not None and not bounds[0] <= 0 <= bounds[1]:
            return bounds[0]
        return 0

    @property
    def bounds(self) -> tuple[float, float] | None:
        """The values a builder accepts: the declared range, or what the type holds."""
        if self.range is not None:
            return self.range
        if self.is_integer:
            assert self.type.min is not None and self.type.max is not None
            return (self.type.min, self.type.max)
        if self.is_float:
            return (-FLOAT32_MAX, FLOAT32_MAX)
        return None


@dataclass(frozen=True)
class Payload:
    name: str
    icd: str
    title: str
    direction: str
    size: int
    doc: str
    fields: tuple[Field, ...]
    path: PathKey
    erratum: str | None = None

    @property
    def variant_dependent(self) -> bool:
        return any(f.scale is not None and f.scale.variant_dependent for f in self.fields)

    @property
    def scaled_fields(self) -> tuple[Field, ...]:
        return tuple(f for f in self.fields if f.scale is not None)

    @property
    def value_fields(self) -> tuple[Field, ...]:
        """Fields that are not reserved: what a user sets and reads."""
        return tuple(f for f in self.fields if f.kind != "reserved")

    def field(self, name: str) -> Field:
        for f in self.fields:
            if f.name == name:
                return f
        raise KeyError(name)
