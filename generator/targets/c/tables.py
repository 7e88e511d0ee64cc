"""The C binding's descriptor tables, derived from the laid-out model.

The C library is table-driven where that keeps it small on a microcontroller: one generic
payload parser/builder walks a compact field table, one $PAHR codec walks a field table, and
names live in string pools. The names a firmware reports in errors (fields, frame parts, $PAHR
fields, error kinds, the date) have a pool per kind, so that a firmware image links only the
pools it uses; every other name (what the name accessors and by-name lookups return) shares one
pool, `name`, whose offsets form one table of sections, one per kind. Strings that are protocol
data rather than names (the text defaults of char fields, the variants' part numbers) have pools
of their own, which stay when the library is compiled without names. This module turns the
model into those tables (deduplicated, in first-use order, so the output is stable); the
templates only print them. Nothing here computes a wire
offset: offsets come from `field.offset` (generator/layout.py).
"""

from __future__ import annotations

import struct
from dataclasses import dataclass, field

from generator.model import FLOAT32_MAX, PRIMITIVES, Field, Payload, Spec

from . import machine

# The parts of a frame that are not fields but that errors name (spec/README.md, "Frame decode").
FRAME_HEADER_NAME = "header"
FRAME_PAYLOAD_NAME = "payload"

# Wire kinds, in the order of generator.model.PRIMITIVES (one C enum value each).
KINDS: tuple[str, ...] = tuple(dict.fromkeys(p.kind for p in PRIMITIVES.values()))

# Encodings a builder checks beyond a range.
ENCODINGS: tuple[str, ...] = ("none", "declination")

NO_PARAMETER = 0xFF
"""Scale table entry whose divisor is a constant, not a variant parameter."""


@dataclass
class StringPool:
    """Names of one kind, once each, as one NUL-separated string; tables hold offsets into it.

    Built twice (build_tables()): the first pass learns every name of the pool in first-use order
    (`known` None); the second lays them out with a name that ends another name stored as that
    name's tail ("gyro_x" inside "ugyro_x"), so `strings` holds only the names that carry others.
    """

    name: str
    known: list[str] | None = None
    strings: list[str] = field(default_factory=list)
    offsets: dict[str, int] = field(default_factory=dict)
    size: int = 0

    def __post_init__(self) -> None:
        if self.known is None:
            return
        for text in self.known:
            if "\0" in text:
                raise ValueError(f"name {text!r} cannot go into a C string pool")
        hosts = [t for t in self.known if not any(o != t and o.endswith(t) for o in self.known)]
        for text in hosts:
            self.offsets[text] = self.size
            self.strings.append(text)
            self.size += len(text.encode("latin-1")) + 1
        for text in self.known:
            if text not in self.offsets:
                host = next(h for h in hosts if h.endswith(text))
                self.offsets[text] = self.offsets[host] + len(host.encode("latin-1")) - len(text.encode("latin-1"))

    def add(self, text: str) -> int:
        if self.known is not None:
            return self.offsets[text]
        if text not in self.offsets:
            self.offsets[text] = len(self.strings)
            self.strings.append(text)
        return self.offsets[text]

    def __getitem__(self, text: str) -> int:
        return self.offsets[text]


@dataclass(frozen=True)
class Bounds:
    """Values a builder accepts, inclusive."""

    low: float
    high: float

    @property
    def low32(self) -> float:
        return float32(self.low)

    @property
    def high32(self) -> float:
        return float32(self.high)


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
    name: int  # offset in the field-name pool
    kind: int  # index into KINDS
    bounds: int  # index into the integer or float bounds table (by kind), 0 = no check
    scale: int  # index into the scale table, 0 = unscaled
    encoding: int  # index into ENCODINGS
    member: int  # offset of the field's member in its C struct (natural alignment, checked in C)


@dataclass(frozen=True)
class DefaultRow:
    """A field whose builder default is not the all-zero value."""

    field: int  # index into the flat field table
    number: float  # numeric default
    text: int  # text pool offset of a char default, or -1


@dataclass(frozen=True)
class NameSection:
    """The names of one kind in the shared pool, in the order of the kind's C enum (a USW bit
    without a flag has the empty name); `first` is the section's first entry in the offset table."""

    kind: str
    first: int
    names: tuple[str, ...]


@dataclass
class Tables:
    pools: dict[str, StringPool]
    name_sections: list[NameSection]
    int_bounds: list[Bounds]
    float_bounds: list[Bounds]
    scales: list[ScaleEntry]
    fields: list[FieldRow]
    first_field: dict[str, int]
    defaults: list[DefaultRow]
    encodings: tuple[str, ...] = ENCODINGS
    kinds: tuple[str, ...] = KINDS

    @property
    def name_count(self) -> int:
        """Entries of the name offset table."""
        return sum(len(s.names) for s in self.name_sections)


def float32(value: float) -> float:
    """The float32 nearest to `value` (round half to even, as C's double-to-float conversion)."""
    result: float = struct.unpack("<f", struct.pack("<f", value))[0]
    return result


def field_bounds(f: Field) -> Bounds | None:
    """What a builder checks for a numeric field, or None when the C type already holds the range."""
    if f.kind == "float":
        low, high = f.bounds if f.bounds is not None else (-FLOAT32_MAX, FLOAT32_MAX)
        return Bounds(float(low), float(high))
    if f.is_integer and f.range is not None:
        low, high = f.range
        if int(low) != low or int(high) != high or not -(2**31) <= low <= high <= 2**31 - 1:
            raise ValueError(f"field {f.name}: integer range {f.range} does not fit the C table (int32)")
        return Bounds(float(low), float(high))
    return None


def builder_default(f: Field) -> float | None:
    """The builders' default of a numeric field (generator/model/fields.py), or None for zero."""
    value = f.default_value
    if value is None or isinstance(value, str) or value == 0:
        return None
    return float(value)


def _index(table: list[Bounds], b: Bounds) -> int:
    if b not in table:
        table.append(b)
    return table.index(b)


def build_tables(spec: Spec) -> Tables:
    """The tables, with each string pool laid out once all its names are known."""
    names = _build_tables(spec, None).pools
    return _build_tables(spec, {kind: pool.strings for kind, pool in names.items()})


def _build_tables(spec: Spec, known: dict[str, list[str]] | None) -> Tables:
    kinds = ("error", "frame", "field", "sentence", "date", "text", "part", "name")
    pools = {name: StringPool(name, None if known is None else known[name]) for name in kinds}
    _error_pools(spec, pools)
    t = Tables(
        pools=pools,
        name_sections=_name_sections(spec, pools["name"]),
        int_bounds=[Bounds(0.0, 0.0)],  # row 0: no check
        float_bounds=[Bounds(0.0, 0.0)],
        scales=[ScaleEntry(1, 1, NO_PARAMETER)],  # row 0: unscaled
        fields=[],
        first_field={},
        defaults=[],
    )
    for p in spec.payloads:
        _add_payload(spec, t, p)
    return t


def _error_pools(spec: Spec, pools: dict[str, StringPool]) -> None:
    """The names errors report (a pool per kind) and the strings that are protocol data."""
    for e in spec.errors:
        pools["error"].add(e.name)
    for part in (FRAME_HEADER_NAME, FRAME_PAYLOAD_NAME, *(f.name for f in spec.frame.fields), spec.frame.checksum.name):
        pools["frame"].add(part)
    if spec.nmea is not None:
        for nf in spec.nmea.fields:
            pools["sentence"].add(nf.name)
    if spec.date is not None:
        pools["date"].add("date")
    for v in spec.variants:
        pools["part"].add(v.part_number)


def _name_sections(spec: Spec, pool: StringPool) -> list[NameSection]:
    """The sections of the shared name pool, one per kind, in the order of the kind's C enum."""
    sections: list[NameSection] = []

    def section(kind: str, entries: list[str]) -> None:
        first = sections[-1].first + len(sections[-1].names) if sections else 0
        sections.append(NameSection(kind, first, tuple(entries)))
        for name in entries:
            pool.add(name)

    # Events are the commands, then the state machine's own events: the event section follows the
    # command section, so that event names are the command names read further.
    m = machine.build_machine(spec)
    section("command", [c.name for c in spec.commands])
    if m is not None:
        section("event", m.extra_events)
    section("variant", [v.name for v in spec.variants])
    section("mode", [mode.name for mode in spec.modes])
    section("payload", [p.name for p in spec.payloads])
    if spec.status_word is not None:
        by_bit = [""] * (max(flag.bit for flag in spec.status_word.flags) + 1)
        for flag in spec.status_word.flags:
            if not flag.name:
                raise ValueError(f"USW bit {flag.bit}: the C name table needs a non-empty flag name")
            by_bit[flag.bit] = flag.name
        section("flag", by_bit)
    if m is not None:
        section("state", m.states)
        section("answer", [a.name for a in m.answers])
    return sections


def _scale_index(spec: Spec, t: Tables, f: Field) -> int:
    """The row of the field's engineering scale in t.scales (added if new), 0 for none."""
    if f.scale is None:
        return 0
    if f.scale.divisor_parameter is not None:
        parameters = [p.name for p in spec.variant_parameters]
        entry = ScaleEntry(f.scale.multiplier, 0, parameters.index(f.scale.divisor_parameter))
    else:
        entry = ScaleEntry(f.scale.multiplier, f.scale.divisor or 1, NO_PARAMETER)
    if entry not in t.scales:
        t.scales.append(entry)
    return t.scales.index(entry)


def _add_payload(spec: Spec, t: Tables, p: Payload) -> None:
    """The rows of one payload table's fields, and their builder defaults."""
    t.first_field[p.name] = len(t.fields)
    member = 0
    for f in p.fields:
        # The header declares the members in wire order, each aligned to its own size (arrays: 1).
        align = f.size if f.is_numeric else 1
        member = -(-member // align) * align
        b = field_bounds(f)
        number = builder_default(f) if f.is_numeric else None
        if isinstance(f.default, str) and f.default:
            t.defaults.append(DefaultRow(len(t.fields), 0.0, t.pools["text"].add(f.default)))
        elif number is not None:
            t.defaults.append(DefaultRow(len(t.fields), number, -1))
        t.fields.append(
            FieldRow(
                payload=p,
                field=f,
                index=len(t.fields),
                name=t.pools["field"].add(f.name),
                kind=KINDS.index(f.kind),
                bounds=0 if b is None else _index(t.float_bounds if f.kind == "float" else t.int_bounds, b),
                scale=_scale_index(spec, t, f),
                encoding=ENCODINGS.index("declination" if f.encoding == "declination" else "none"),
                member=member,
            )
        )
        member += f.size + (1 if f.kind == "char" else 0)  # a char array holds a terminating NUL (filters.c_member)


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
