"""The C binding's descriptor tables, derived from the laid-out model.

The C library is table-driven where that keeps it small on a microcontroller: one generic
payload parser/builder walks a compact field table, one $PAHR codec walks a field table,
and every name lives once in one string pool. This module turns the model into those tables
(deduplicated, in first-use order so the output is stable); the templates only print them.
Nothing here computes a wire offset: offsets come from `field.offset` (generator/layout.py).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from generator.model import FLOAT32_MAX, PRIMITIVES, Field, Payload, Spec

# The parts of a frame that are not fields but that errors name (spec/README.md, "Frame decode").
FRAME_HEADER_NAME = "header"
FRAME_PAYLOAD_NAME = "payload"

# Wire kinds, in the order of generator.model.PRIMITIVES (one C enum value each).
KINDS: tuple[str, ...] = tuple(dict.fromkeys(p.kind for p in PRIMITIVES.values()))

NO_PARAMETER = 0xFF
"""Scale table entry whose divisor is a constant, not a variant parameter."""


@dataclass
class StringPool:
    """Every name the C library can hand out, once, as one NUL-separated string."""

    strings: list[str] = field(default_factory=list)
    offsets: dict[str, int] = field(default_factory=dict)
    size: int = 0

    def add(self, text: str) -> int:
        if text not in self.offsets:
            if "\0" in text or '"' in text or "\\" in text:
                raise ValueError(f"name {text!r} cannot go into the C string pool")
            self.offsets[text] = self.size
            self.strings.append(text)
            self.size += len(text.encode("latin-1")) + 1
        return self.offsets[text]

    def __getitem__(self, text: str) -> int:
        return self.offsets[text]


@dataclass(frozen=True)
class Bounds:
    """Values a builder accepts, inclusive, compared as double."""

    low: float
    high: float


@dataclass(frozen=True)
class ScaleEntry:
    """Engineering = raw * multiplier / divisor; `parameter` names a variant parameter instead."""

    multiplier: int
    divisor: int
    parameter: int  # index into spec.variant_parameters, or NO_PARAMETER


@dataclass(frozen=True)
class FieldRow:
    payload: Payload
    field: Field
    index: int  # position in the flat field table
    name: int  # string pool offset
    kind: int  # index into KINDS
    bounds: int  # index into the bounds table, 0 = the C type is the range
    scale: int  # index into the scale table, 0 = unscaled
    encoding: str  # "none", "declination"


@dataclass(frozen=True)
class DefaultRow:
    """A field whose spec `default` is not the all-zero value."""

    field: int  # index into the flat field table
    number: float  # numeric default
    text: int  # string pool offset of a char default, or -1


@dataclass
class Tables:
    pool: StringPool
    bounds: list[Bounds]
    scales: list[ScaleEntry]
    fields: list[FieldRow]
    first_field: dict[str, int]
    defaults: list[DefaultRow]
    encodings: tuple[str, ...] = ("none", "declination")


def field_bounds(spec: Spec, f: Field) -> Bounds | None:
    """What a builder checks for a numeric field, or None when the C type already holds the range."""
    if f.kind == "float":
        if f.encoding == "date" and spec.date is not None:
            # A raw date float lies from year_min to the encoding of the last real date of
            # year_max, which is above year_max + 1 because Day/365 overlaps the next year
            # (E15). The model's derived range stops at year_max + 1 and so refuses 2199-12-31,
            # a real date (conformance vector payload_encode/*/date-2199-12-31).
            return Bounds(float(spec.date.year_min), last_date_value(spec))
        low, high = f.bounds if f.bounds is not None else (-FLOAT32_MAX, FLOAT32_MAX)
        return Bounds(float(low), float(high))
    if f.is_integer and f.range is not None:
        return Bounds(float(f.range[0]), float(f.range[1]))
    return None


def _days_in_month(year: int, month: int) -> int:
    """The Gregorian calendar."""
    if month == 2:
        return 29 if year % 4 == 0 and (year % 100 != 0 or year % 400 == 0) else 28
    return 30 if month in (4, 6, 9, 11) else 31


def date_value(spec: Spec, year: int, month: int, day: int) -> float:
    """The date float of a calendar date, summing the spec's terms in order (as the C code does)."""
    assert spec.date is not None
    parts = {"year": year, "month": month, "day": day}
    value = 0.0
    for term in spec.date.terms:
        value += (parts[term.part] + term.offset) / term.divisor
    return value


def last_date_value(spec: Spec) -> float:
    """The largest date float of a real date within year_range."""
    assert spec.date is not None
    year = spec.date.year_max
    return max(date_value(spec, year, m, d) for m in range(1, 13) for d in range(1, _days_in_month(year, m) + 1))


def builder_default(spec: Spec, f: Field) -> float | None:
    """What a builder starts from for a numeric field: the spec default, else 0 when the
    field's bounds allow it, else the lowest value they allow. None for zero."""
    if f.default is not None and not isinstance(f.default, str):
        return float(f.default) if f.default != 0 else None
    b = field_bounds(spec, f)
    if b is not None and not b.low <= 0 <= b.high:
        return b.low
    return None


def build_tables(spec: Spec) -> Tables:
    pool = StringPool()
    for e in spec.errors:
        pool.add(e.name)
    pool.add(FRAME_HEADER_NAME)
    pool.add(FRAME_PAYLOAD_NAME)
    for f in spec.frame.fields:
        pool.add(f.name)
    pool.add(spec.frame.checksum.name)
    for c in spec.commands:
        pool.add(c.name)
    for v in spec.variants:
        pool.add(v.name)
        pool.add(v.part_number)
    for m in spec.modes:
        pool.add(m.name)
    if spec.status_word is not None:
        for flag in spec.status_word.flags:
            pool.add(flag.name)
    if spec.nmea is not None:
        for nf in spec.nmea.fields:
            pool.add(nf.name)
    if spec.date is not None:
        pool.add("date")

    bounds: list[Bounds] = [Bounds(0.0, 0.0)]  # 0: no check
    scales: list[ScaleEntry] = [ScaleEntry(1, 1, NO_PARAMETER)]  # 0: unscaled
    rows: list[FieldRow] = []
    first: dict[str, int] = {}
    defaults: list[DefaultRow] = []
    parameters = [p.name for p in spec.variant_parameters]
    for p in spec.payloads:
        pool.add(p.name)
        first[p.name] = len(rows)
        for f in p.fields:
            b = field_bounds(spec, f)
            b_index = 0
            if b is not None:
                if b not in bounds:
                    bounds.append(b)
                b_index = bounds.index(b)
            s_index = 0
            if f.scale is not None:
                if f.scale.divisor_parameter is not None:
                    entry = ScaleEntry(f.scale.multiplier, 0, parameters.index(f.scale.divisor_parameter))
                else:
                    entry = ScaleEntry(f.scale.multiplier, f.scale.divisor or 1, NO_PARAMETER)
                if entry not in scales:
                    scales.append(entry)
                s_index = scales.index(entry)
            if isinstance(f.default, str) and f.default:
                defaults.append(DefaultRow(len(rows), 0.0, pool.add(f.default)))
            elif f.is_numeric and builder_default(spec, f) is not None:
                defaults.append(DefaultRow(len(rows), builder_default(spec, f) or 0.0, -1))
            encoding = "declination" if f.encoding == "declination" else "none"
            rows.append(
                FieldRow(
                    payload=p,
                    field=f,
                    index=len(rows),
                    name=pool.add(f.name),
                    kind=KINDS.index(f.kind),
                    bounds=b_index,
                    scale=s_index,
                    encoding=encoding,
                )
            )
    return Tables(pool=pool, bounds=bounds, scales=scales, fields=rows, first_field=first, defaults=defaults)


def member_type(spec: Spec) -> str:
    """A type for offsetof() values inside payload structs: uint8_t unless a struct may exceed 255 bytes."""
    worst = max(sum(f.size + 4 for f in p.fields) for p in spec.payloads)
    return "uint8_t" if worst <= 0xFF else "uint16_t"


def response_kinds(spec: Spec) -> list[str]:
    """The kinds of command response, "none" first (value 0), then in order of first use."""
    kinds = ["none"]
    for c in spec.commands:
        if c.response_kind not in kinds:
            kinds.append(c.response_kind)
    return kinds
