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
    """The builders' default of a numeric field (generator/model.py), or None for zero."""
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
    for e in spec.errors:
        pools["error"].add(e.name)
    pools["frame"].add(FRAME_HEADER_NAME)
    pools["frame"].add(FRAME_PAYLOAD_NAME)
    for f in spec.frame.fields:
        pools["frame"].add(f.name)
    pools["frame"].add(spec.frame.checksum.name)
    names = pools["field"]
    if spec.nmea is not None:
        for nf in spec.nmea.fields:
            pools["sentence"].add(nf.name)
    if spec.date is not None:
        pools["date"].add("date")
    for v in spec.variants:
        pools["part"].add(v.part_number)
    sections: list[NameSection] = []

    def section(kind: str, entries: list[str]) -> None:
        first = sections[-1].first + len(sections[-1].names) if sections else 0
        sections.append(NameSection(kind, first, tuple(entries)))
        for name in entries:
            pools["name"].add(name)

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

    int_bounds: list[Bounds] = [Bounds(0.0, 0.0)]  # row 0: no check
    float_bounds: list[Bounds] = [Bounds(0.0, 0.0)]
    scales: list[ScaleEntry] = [ScaleEntry(1, 1, NO_PARAMETER)]  # row 0: unscaled
    rows: list[FieldRow] = []
    first: dict[str, int] = {}
    defaults: list[DefaultRow] = []
    parameters = [p.name for p in spec.variant_parameters]
    for p in spec.payloads:
        first[p.name] = len(rows)
        member = 0
        for f in p.fields:
            # The header declares the members in wire order, each aligned to its own size (arrays: 1).
            align = f.size if f.is_numeric else 1
            member = -(-member // align) * align
            b = field_bounds(f)
            b_index = 0 if b is None else _index(float_bounds if f.kind == "float" else int_bounds, b)
            s_index = 0
            if f.scale is not None:
                if f.scale.divisor_parameter is not None:
                    entry = ScaleEntry(f.scale.multiplier, 0, parameters.index(f.scale.divisor_parameter))
                else:
                    entry = ScaleEntry(f.scale.multiplier, f.scale.divisor or 1, NO_PARAMETER)
                if entry not in scales:
                    scales.append(entry)
                s_index = scales.index(entry)
            number = builder_default(f) if f.is_numeric else None
            if isinstance(f.default, str) and f.default:
                defaults.append(DefaultRow(len(rows), 0.0, pools["text"].add(f.default)))
            elif number is not None:
                defaults.append(DefaultRow(len(rows), number, -1))
            rows.append(
                FieldRow(
                    payload=p,
                    field=f,
                    index=len(rows),
                    name=names.add(f.name),
                    kind=KINDS.index(f.kind),
                    bounds=b_index,
                    scale=s_index,
                    encoding=ENCODINGS.index("declination" if f.encoding == "declination" else "none"),
                    member=member,
                )
            )
            member += f.size + (1 if f.kind == "char" else 0)  # a char array holds a terminating NUL (filters.c_member)
    return Tables(
        pools=pools,
        name_sections=sections,
        int_bounds=int_bounds,
        float_bounds=float_bounds,
        scales=scales,
        fields=rows,
        first_field=first,
        defaults=defaults,
    )


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


@dataclass(frozen=True)
class CanonicalField:
    """Where a $PAHR field sits in a sentence a builder writes (E16: fixed template widths)."""

    index: int
    position: int  # character position of its first character
    length: int  # characters, sign included
    width: int  # integer-part (decimal) or digit (hex) characters, sign included
    decimals: int
    hex: bool


@dataclass(frozen=True)
class CanonicalLayout:
    fields: tuple[CanonicalField, ...]
    star: int  # position of "*"
    length: int  # whole sentence, "$" through CR LF


def canonical_layout(spec: Spec) -> CanonicalLayout | None:
    """The text layout of sentences written by the builders, when every value in range fits its
    template width (then every built sentence has the same length and field positions)."""
    if spec.nmea is None:
        return None
    position = len(spec.nmea.identifier) + 2  # "$", identifier, ","
    fields = []
    for k, f in enumerate(spec.nmea.fields):
        hex_field = f.format == "hex"
        if hex_field:
            fits = f.min >= 0 and f.max < 16**f.width
            length = f.width
        else:
            positive = len(str(max(f.max, 0) // f.divisor)) <= f.width
            negative = f.min >= 0 or len(str(-f.min // f.divisor)) + 1 <= f.width
            fits = positive and negative
            length = f.width + (1 + f.decimals if f.decimals else 0)
        digits = f.width + f.decimals
        if not fits or digits > 9:  # the fast path adds digits in 32 bits
            return None
        fields.append(CanonicalField(k, position, length, f.width, f.decimals, hex_field))
        position += length + 1
    star = position - 1
    return CanonicalLayout(tuple(fields), star, star + 5)
