"""Step 3 of the pipeline: the validated spec as typed, immutable objects.

The model holds what the spec says, nothing computed about placement: offsets and sizes
derived from declaration order are the layout step's (generator/layout.py), which returns
the same objects with `offset` filled in. Templates read the laid-out model and never
change it.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from .load import LoadedSpec, PathKey


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
class ErrorKind:
    name: str
    doc: str


@dataclass(frozen=True)
class Mode:
    name: str
    doc: str
    icd: str = ""


@dataclass(frozen=True)
class Unit:
    key: str
    suffix: str
    doc: str


@dataclass(frozen=True)
class Variant:
    name: str
    part_number: str
    icd: str
    values: tuple[tuple[str, int], ...]
    erratum: str | None

    def value(self, parameter: str) -> int:
        value: int = dict(self.values)[parameter]
        return value


@dataclass(frozen=True)
class VariantParameter:
    name: str
    doc: str


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


@dataclass(frozen=True)
class FormerName:
    name: str
    until_firmware: str
    doc: str


@dataclass(frozen=True)
class Command:
    name: str  # ICD spelling, e.g. "AHRScont1"
    id: str  # lower_snake identifier, e.g. "ahrs_cont1"
    code: int
    icd: str
    group: str
    purpose: str
    valid_in: tuple[str, ...]
    response_kind: str  # ack, data, output, none
    response_payloads: tuple[str, ...]
    path: PathKey
    starts_mode: str | None = None
    starts_output: str | None = None
    parameter_block: str | None = None
    shares_code_with: str | None = None
    default_for_code: bool = False  # the meaning of a shared code in a mode where no name is valid
    begins_calibration: str | None = None  # the calibration_type value a start command begins
    former_names: tuple[FormerName, ...] = ()
    erratum: str | None = None


@dataclass(frozen=True)
class MessageType:
    name: str
    value: int
    doc: str


@dataclass(frozen=True)
class Frame:
    icd: str
    header: tuple[int, ...]
    fields: tuple[Field, ...]  # the fields between header and payload
    checksum: Field
    checksum_doc: str
    checksum_algorithm: str
    message_types: tuple[MessageType, ...]
    min_length: int  # bounds of the message_length field a decoder accepts
    max_length: int
    path: PathKey
    # Filled in by layout:
    payload_offset: int = -1

    def field(self, name: str) -> Field:
        for f in self.fields:
            if f.name == name:
                return f
        raise KeyError(name)

    def message_type(self, name: str) -> MessageType:
        for t in self.message_types:
            if t.name == name:
                return t
        raise KeyError(name)

    @property
    def header_size(self) -> int:
        return len(self.header)

    @property
    def overhead(self) -> int:
        """Bytes in a frame besides the payload."""
        return self.payload_offset + self.checksum.size

    @property
    def length_bias(self) -> int:
        """message_length minus payload size: the bytes after the header besides the payload."""
        return self.overhead - self.header_size

    @property
    def min_payload(self) -> int:
        return self.min_length - self.length_bias

    @property
    def max_payload(self) -> int:
        return self.max_length - self.length_bias

    @property
    def min_frame_size(self) -> int:
        return self.header_size + self.min_length

    @property
    def max_frame_size(self) -> int:
        return self.header_size + self.max_length


@dataclass(frozen=True)
class EnumValue:
    name: str
    value: int
    doc: str


@dataclass(frozen=True)
class Enum:
    name: str
    icd: str
    values: tuple[EnumValue, ...]
    external_above: int | None = None


@dataclass(frozen=True)
class DateTerm:
    part: str
    offset: int
    divisor: int


@dataclass(frozen=True)
class DateEncoding:
    doc: str
    icd: str
    terms: tuple[DateTerm, ...]
    year_min: int
    year_max: int
    decode: str
    erratum: str | None


@dataclass(frozen=True)
class DeclinationEncoding:
    doc: str
    icd: str
    min: float
    max: float
    compute_above: float
    compute_value: float


@dataclass(frozen=True)
class CalibrationSuccessEncoding:
    doc: str
    icd: str
    failed: int
    no_estimate: int
    accuracy_divisor: int


@dataclass(frozen=True)
class StatusFlag:
    bit: int
    name: str
    icd_name: str
    byte: str
    doc: str

    @property
    def mask(self) -> int:
        return 1 << self.bit


@dataclass(frozen=True)
class StatusMode:
    name: str
    bits: tuple[int, ...]  # one value per mode bit, in the order of StatusWord.mode_bits
    doc: str


@dataclass(frozen=True)
class StatusWord:
    icd: str
    flags: tuple[StatusFlag, ...]
    mode_bits: tuple[int, ...]
    modes: tuple[StatusMode, ...]
    other_mode: str
    failure_mask: int
    warning_mask: int

    @property
    def mode_mask(self) -> int:
        mask = 0
        for bit in self.mode_bits:
            mask |= 1 << bit
        return mask

    def mode_pattern(self, mode: StatusMode) -> int:
        """The USW bits (masked by mode_mask) that mean `mode`."""
        value = 0
        for bit, on in zip(self.mode_bits, mode.bits, strict=True):
            if on:
                value |= 1 << bit
        return value


@dataclass(frozen=True)
class NmeaField:
    name: str
    icd_name: str
    format: str  # decimal or hex
    width: int
    decimals: int
    unit: str
    min: int  # bounds of the scaled integer value
    max: int
    doc: str

    @property
    def divisor(self) -> int:
        return int(10**self.decimals)


@dataclass(frozen=True)
class Nmea:
    icd: str
    identifier: str
    template: str
    max_rate_hz: int
    max_length: int
    fields: tuple[NmeaField, ...]
    checksum_doc: str


@dataclass(frozen=True)
class SmState:
    """A state of the device: its operating mode, and what it waits for."""

    name: str
    mode: str
    doc: str
    expects: str | None = None  # the parameter block (payload name) this state waits for
    timer: str | None = None  # alignment, accumulation or output
    erratum: str | None = None


@dataclass(frozen=True)
class SmEvent:
    """An event besides the commands: a message that is not a command, or a timer."""

    name: str
    doc: str


@dataclass(frozen=True)
class Transition:
    """One cell of the table: in `state`, on `event`, go to `to` and send `send`."""

    state: str
    event: str  # a command name or an SmEvent name
    to: str
    send: tuple[str, ...]
    wildcard: bool = False  # from a `*` row
    firmware_before: str | None = None  # only on firmware older than this
    erratum: str | None = None
    effect: str | None = None  # store_parameters, save_calibration, clear_calibration


@dataclass(frozen=True)
class SmTimer:
    """A timer of the device and the parameter field that sets it (seconds, or Hz for output)."""

    name: str
    payload: str
    field: str


TIMER_EVENTS = {"alignment": "alignment_done", "accumulation": "accumulation_done", "output": "output_due"}

# The words a transition's `send` list is made of (spec/README.md): the acknowledgement, one block of
# the current output format, one output block whose USW reports a given mode (OUTPUT_MODE_PREFIX +
# the mode's name), or a payload table's name. Every target reads them from here.
ANSWER_ACK = "ack"
ANSWER_OUTPUT = "output"
OUTPUT_MODE_PREFIX = "output_"


@dataclass(frozen=True)
class Answer:
    """One kind of answer the state machine sends: `kind` is "ack", "output", "output_mode" (`mode`
    set) or "payload" (`payload` set)."""

    name: str
    kind: str
    doc: str
    payload: str | None = None
    mode: str | None = None


def answer_kind(name: str, payloads: set[str], usw_modes: set[str]) -> Answer | None:
    """What a `send` word means, or None if it is none of the words above."""
    if name in payloads:
        return Answer(name, "payload", f"One {name} data block.", payload=name)
    if name == ANSWER_ACK:
        return Answer(name, "ack", "The acknowledgement of the message just received.")
    if name == ANSWER_OUTPUT:
        return Answer(name, "output", "One block of the output format chosen by the start command.")
    mode = name.removeprefix(OUTPUT_MODE_PREFIX)
    if name.startswith(OUTPUT_MODE_PREFIX) and mode in usw_modes:
        return Answer(name, "output_mode", f"One output block whose USW reports mode {mode} (E35).", mode=mode)
    return None


@dataclass(frozen=True)
class StateMachine:
    icd: str
    initial: str
    states: tuple[SmState, ...]
    events: tuple[SmEvent, ...]
    transitions: tuple[Transition, ...]  # expanded: one per (state, event), explicit rows first
    parameter_block_timeout_s: float
    default_alignment_time_s: float
    default_update_rate_hz: float
    result_delay_s: float
    timers: tuple[SmTimer, ...] = ()
    min_successful_runs: int | None = None
    answers: tuple[Answer, ...] = ()  # every answer the table sends, in first-use order (`sends`)

    def timer(self, name: str) -> SmTimer:
        for t in self.timers:
            if t.name == name:
                return t
        raise KeyError(name)

    def state(self, name: str) -> SmState:
        for s in self.states:
            if s.name == name:
                return s
        raise KeyError(name)

    @property
    def sends(self) -> tuple[str, ...]:
        """Every kind of answer the table uses, in first-use order."""
        seen: list[str] = []
        for t in self.transitions:
            for item in t.send:
                if item not in seen:
                    seen.append(item)
        return tuple(seen)

    def lookup(self, state: str, event: str, legacy: bool = False) -> Transition | None:
        """The transition for `event` in `state`, or None (ignored). `legacy`: firmware older than
        a row's `firmware_before` (such rows take precedence there)."""
        if legacy:
            for t in self.transitions:
                if t.state == state and t.event == event and t.firmware_before is not None:
                    return t
        for t in self.transitions:
            if t.state == state and t.event == event and t.firmware_before is None:
                return t
        return None

    def rows(self, state: str) -> tuple[Transition, ...]:
        return tuple(t for t in self.transitions if t.state == state)


@dataclass(frozen=True)
class SerialLine:
    """The serial port settings (section 6)."""

    baud_rate: int
    data_bits: int
    parity: str
    stop_bits: int


@dataclass(frozen=True)
class Erratum:
    id: str
    where: str
    says: str
    chosen: str
    why: str


@dataclass(frozen=True)
class Spec:
    name: str
    version: str
    byte_order: str
    icd_title: str
    icd_revision: str
    icd_date: str
    file: str
    sha256: str
    errors: tuple[ErrorKind, ...]
    modes: tuple[Mode, ...]
    units: tuple[Unit, ...]
    variant_parameters: tuple[VariantParameter, ...]
    variants: tuple[Variant, ...]
    frame: Frame
    commands: tuple[Command, ...]
    ack_payload: str | None
    ack_doc: str
    payloads: tuple[Payload, ...]
    enums: tuple[Enum, ...]
    date: DateEncoding | None
    declination: DeclinationEncoding | None
    calibration_success: CalibrationSuccessEncoding | None
    status_word: StatusWord | None
    nmea: Nmea | None
    errata: tuple[Erratum, ...]
    state_machine: StateMachine | None = None
    serial_line: SerialLine | None = None

    def payload(self, name: str) -> Payload:
        for p in self.payloads:
            if p.name == name:
                return p
        raise KeyError(name)

    def command(self, name: str) -> Command:
        for c in self.commands:
            if c.name == name:
                return c
        raise KeyError(name)

    def enum(self, name: str) -> Enum:
        for e in self.enums:
            if e.name == name:
                return e
        raise KeyError(name)

    @property
    def codes(self) -> tuple[int, ...]:
        """Distinct command codes, ascending."""
        return tuple(sorted({c.code for c in self.commands}))

    def command_in_mode(self, code: int, mode: str) -> Command | None:
        """The command a code means in `mode`: of the names sharing the code, the one valid there (E14)."""
        named = self.commands_with_code(code)
        for c in named:
            if mode in c.valid_in:
                return c
        for c in named:
            if c.default_for_code or len(named) == 1:
                return c
        return None

    def commands_with_code(self, code: int) -> tuple[Command, ...]:
        """Commands sharing `code`, sorted by ICD name."""
        return tuple(sorted((c for c in self.commands if c.code == code), key=lambda c: c.name))

    @property
    def parameter_blocks(self) -> tuple[Payload, ...]:
        names: list[str] = []
        for c in self.commands:
            if c.parameter_block is not None and c.parameter_block not in names:
                names.append(c.parameter_block)
        return tuple(self.payload(n) for n in names)

    @property
    def max_message_size(self) -> int:
        """The longest message a stream decoder must hold: a frame or a sentence."""
        size = self.frame.max_frame_size
        if self.nmea is not None:
            size = max(size, self.nmea.max_length)
        return size

    @property
    def short_hash(self) -> str:
        return self.sha256[:16]


def _field(
    raw: dict[str, Any], path: PathKey, units: dict[str, Unit], date_bounds: tuple[float, float] | None = None
) -> Field:
    primitive = PRIMITIVES[raw["type"]]
    size = primitive.size if primitive.size is not None else int(raw["length"])
    scale = None
    if "scale" in raw:
        divisor = raw["scale"].get("divisor", 1)
        scale = Scale(
            multiplier=int(raw["scale"].get("multiplier", 1)),
            divisor=divisor if isinstance(divisor, int) else None,
            divisor_parameter=divisor if isinstance(divisor, str) else None,
        )
    value_range = None
    if "range" in raw:
        value_range = (raw["range"][0], raw["range"][1])
    elif raw.get("encoding") == "date" and date_bounds is not None:
        value_range = date_bounds
    multiplexed = raw.get("multiplexed")
    return Field(
        name=raw["name"],
        icd_name=raw.get("icd_name", raw["name"]),
        type=primitive,
        size=size,
        doc=" ".join(str(raw.get("doc", "")).split()),
        path=path,
        unit=units[raw["unit"]] if "unit" in raw else None,
        scale=scale,
        range=value_range,
        default=raw.get("default"),
        enum=raw.get("enum"),
        encoding=raw.get("encoding"),
        multiplexed_count=multiplexed["count"] if multiplexed else None,
        multiplexed_quantities=tuple(multiplexed.get("quantities", ())) if multiplexed else (),
        erratum=raw.get("erratum"),
        declared_offset=raw.get("offset"),
    )


def _float32_toward(value: float, upward: bool) -> float:
    """The nearest float32 value at or beyond `value` in the given direction."""
    import struct

    rounded: float = struct.unpack("<f", struct.pack("<f", value))[0]
    if (rounded < value and upward) or (rounded > value and not upward):
        bits = struct.unpack("<i", struct.pack("<f", rounded))[0]
        bits += 1 if (rounded >= 0) == upward else -1
        rounded = struct.unpack("<f", struct.pack("<i", bits))[0]
    return rounded


def _date_bounds(raw: dict[str, Any]) -> tuple[float, float]:
    """The floats a date field may hold: from the encoding of the first day of the first year to
    that of the last day of the last year (E15: Dec 31 encodes past the next year's start),
    widened to float32 values."""

    def encode(year: int, month: int, day: int) -> float:
        parts = {"year": year, "month": month, "day": day}
        return float(sum((parts[t["part"]] + t["offset"]) / t["divisor"] for t in raw["terms"]))

    low, high = raw["year_range"]
    return _float32_toward(encode(low, 1, 1), upward=False), _float32_toward(encode(high, 12, 31), upward=True)


def _doc(value: Any) -> str:
    return " ".join(str(value or "").split())


def build(loaded: LoadedSpec) -> Spec:
    """Turn validated data into the model. Call generator.validate.validate first."""
    d = loaded.data
    units = {key: Unit(key=key, suffix=u["suffix"], doc=_doc(u["doc"])) for key, u in d.get("units", {}).items()}
    fr = d["frame"]
    frame_fields = tuple(_field(f, ("frame", "fields", i), units) for i, f in enumerate(fr["fields"]))
    checksum = _field(
        {"name": "checksum", "icd_name": fr["checksum"].get("icd_name", "checksum"), "type": fr["checksum"]["type"]},
        ("frame", "checksum"),
        units,
    )
    frame = Frame(
        icd=fr.get("icd", ""),
        header=tuple(fr["header"]),
        fields=frame_fields,
        checksum=checksum,
        checksum_doc=_doc(fr["checksum"].get("doc")),
        checksum_algorithm=fr["checksum"]["algorithm"],
        message_types=tuple(MessageType(t["name"], t["value"], _doc(t.get("doc"))) for t in fr["message_types"]),
        min_length=fr["message_length"]["min"],
        max_length=fr["message_length"]["max"],
        path=("frame",),
    )
    commands = tuple(
        Command(
            name=c["name"],
            id=c["id"],
            code=c["code"],
            icd=str(c["icd"]),
            group=c["group"],
            purpose=_doc(c["purpose"]),
            valid_in=tuple(c["valid_in"]),
            response_kind=c["response"]["kind"],
            response_payloads=tuple(c["response"].get("payloads", ())),
            path=("commands", i),
            starts_mode=c["starts"]["mode"] if "starts" in c else None,
            starts_output=c["starts"]["output"] if "starts" in c else None,
            parameter_block=c.get("parameter_block"),
            shares_code_with=c.get("shares_code_with"),
            default_for_code=bool(c.get("default_for_code", False)),
            begins_calibration=c.get("begins_calibration"),
            former_names=tuple(
                FormerName(f["name"], f.get("until_firmware", ""), _doc(f["doc"])) for f in c.get("former_names", ())
            ),
            erratum=c.get("erratum"),
        )
        for i, c in enumerate(d["commands"])
    )
    date_raw = d.get("encodings", {}).get("date")
    date_bounds = _date_bounds(date_raw) if date_raw else None
    payloads = tuple(
        Payload(
            name=p["name"],
            icd=p["icd"],
            title=p["title"],
            direction=p["direction"],
            size=p["size"],
            doc=_doc(p.get("doc")),
            fields=tuple(
                _field(f, ("payloads", i, "fields", j), units, date_bounds) for j, f in enumerate(p["fields"])
            ),
            path=("payloads", i),
            erratum=p.get("erratum"),
        )
        for i, p in enumerate(d["payloads"])
    )
    variants_raw = d.get("variants", {"parameters": {}, "list": []})
    enc = d.get("encodings", {})
    date = None
    if "date" in enc:
        e = enc["date"]
        date = DateEncoding(
            doc=_doc(e["doc"]),
            icd=e.get("icd", ""),
            terms=tuple(DateTerm(t["part"], t["offset"], t["divisor"]) for t in e["terms"]),
            year_min=e["year_range"][0],
            year_max=e["year_range"][1],
            decode=e["decode"],
            erratum=e.get("erratum"),
        )
    declination = None
    if "declination" in enc:
        e = enc["declination"]
        declination = DeclinationEncoding(
            doc=_doc(e["doc"]),
            icd=e.get("icd", ""),
            min=e["range"][0],
            max=e["range"][1],
            compute_above=e["compute_above"],
            compute_value=e["compute_value"],
        )
    success = None
    if "calibration_success" in enc:
        e = enc["calibration_success"]
        success = CalibrationSuccessEncoding(
            doc=_doc(e["doc"]),
            icd=e.get("icd", ""),
            failed=e["failed"],
            no_estimate=e["no_estimate"],
            accuracy_divisor=e["accuracy_divisor"],
        )
    status_word = None
    if "status_word" in d:
        sw = d["status_word"]
        flags = tuple(
            StatusFlag(f["bit"], f["name"], f.get("icd_name", f["name"]), f["byte"], _doc(f.get("doc")))
            for f in sw["flags"]
        )
        byte_masks = {
            b["name"]: sum(1 << i for i in range(b["bits"][0], b["bits"][1] + 1)) for b in sw.get("bytes", [])
        }
        status_word = StatusWord(
            icd=sw.get("icd", ""),
            flags=flags,
            mode_bits=tuple(sw["mode"]["bits"]),
            modes=tuple(StatusMode(m["name"], tuple(m["bits"]), _doc(m.get("doc"))) for m in sw["mode"]["values"]),
            other_mode=sw["mode"]["other"],
            failure_mask=byte_masks.get("failure", 0),
            warning_mask=byte_masks.get("warning", 0),
        )
    nmea = None
    if "nmea" in d:
        n = d["nmea"]
        nmea = Nmea(
            icd=n.get("icd", ""),
            identifier=n["identifier"],
            template=n.get("template", ""),
            max_rate_hz=n["max_rate_hz"],
            max_length=n["max_length"],
            fields=tuple(
                NmeaField(
                    name=f["name"],
                    icd_name=f.get("icd_name", f["name"]),
                    format=f["format"],
                    width=f["width"],
                    decimals=f.get("decimals", 0),
                    unit=f.get("unit", ""),
                    min=int(f["range"][0]),
                    max=int(f["range"][1]),
                    doc=_doc(f.get("doc")),
                )
                for f in n["fields"]
            ),
            checksum_doc=_doc(n["checksum"].get("doc")),
        )
    ack = d.get("acknowledgement", {})
    return Spec(
        name=d["spec"]["name"],
        version=d["spec"]["version"],
        byte_order=d["byte_order"],
        icd_title=d["spec"]["icd"]["title"],
        icd_revision=str(d["spec"]["icd"]["revision"]),
        icd_date=str(d["spec"]["icd"]["date"]),
        file=loaded.file,
        sha256=loaded.sha256,
        errors=tuple(ErrorKind(e["name"], _doc(e["doc"])) for e in d["errors"]),
        modes=tuple(Mode(m["name"], _doc(m["doc"]), m.get("icd", "")) for m in d.get("modes", [])),
        units=tuple(units.values()),
        variant_parameters=tuple(VariantParameter(k, _doc(v["doc"])) for k, v in variants_raw["parameters"].items()),
        variants=tuple(
            Variant(
                name=v["name"],
                part_number=v["part_number"],
                icd=v.get("icd", ""),
                values=tuple(sorted(v["values"].items())),
                erratum=v.get("erratum"),
            )
            for v in variants_raw["list"]
        ),
        frame=frame,
        commands=commands,
        ack_payload=ack.get("payload"),
        ack_doc=_doc(ack.get("doc")),
        payloads=payloads,
        enums=tuple(
            Enum(
                name=k,
                icd=v.get("icd", ""),
                values=tuple(EnumValue(x["name"], x["value"], _doc(x.get("doc"))) for x in v["values"]),
                external_above=v.get("external_above"),
            )
            for k, v in d.get("enums", {}).items()
        ),
        date=date,
        declination=declination,
        calibration_success=success,
        status_word=status_word,
        nmea=nmea,
        errata=tuple(
            Erratum(e["id"], _doc(e["where"]), _doc(e["says"]), _doc(e["chosen"]), _doc(e["why"]))
            for e in d.get("errata", [])
        ),
        state_machine=_state_machine(
            d["state_machine"],
            [c["name"] for c in d["commands"]],
            {p["name"] for p in d["payloads"]},
            {m.name for m in status_word.modes} if status_word is not None else set(),
        )
        if "state_machine" in d
        else None,
        serial_line=SerialLine(
            d["serial_line"]["baud_rate"],
            d["serial_line"]["data_bits"],
            d["serial_line"]["parity"],
            d["serial_line"]["stop_bits"],
        )
        if "serial_line" in d
        else None,
    )


def _answers(transitions: list[Transition], payloads: set[str], usw_modes: set[str]) -> tuple[Answer, ...]:
    """Every answer the transitions send, in first-use order (validate has checked each word)."""
    seen: dict[str, Answer] = {}
    for t in transitions:
        for item in t.send:
            answer = answer_kind(item, payloads, usw_modes)
            if answer is None:
                raise ValueError(f"the state machine sends {item!r}: neither ack, output, output_MODE nor a payload")
            seen.setdefault(item, answer)
    return tuple(seen.values())


def _state_machine(
    raw: dict[str, Any], commands: list[str], payloads: set[str], usw_modes: set[str]
) -> StateMachine:
    """Expand the rows of the spec into one transition per (state, event)."""
    explicit: list[Transition] = []
    wildcards: list[tuple[str, dict[str, Any]]] = []
    for row in raw["transitions"]:
        for state in row["from"]:
            for event in row["when"]:
                if event == "*":
                    wildcards.append((state, row))
                    continue
                explicit.append(
                    Transition(
                        state=state,
                        event=event,
                        to=state if row["to"] == "same" else row["to"],
                        send=tuple(row["send"]),
                        firmware_before=row.get("firmware_before"),
                        erratum=row.get("erratum"),
                        effect=row.get("effect"),
                    )
                )
    covered = {(t.state, t.event) for t in explicit if t.firmware_before is None}
    expanded = list(explicit)
    for state, row in wildcards:
        for command in commands:
            if (state, command) not in covered:
                covered.add((state, command))
                expanded.append(
                    Transition(
                        state=state,
                        event=command,
                        to=state if row["to"] == "same" else row["to"],
                        send=tuple(row["send"]),
                        wildcard=True,
                        erratum=row.get("erratum"),
                    )
                )
    timing = raw["timing"]
    return StateMachine(
        icd=raw.get("icd", ""),
        initial=raw["initial"],
        states=tuple(
            SmState(
                name=st["name"],
                mode=st["mode"],
                doc=_doc(st["doc"]),
                expects=st.get("expects"),
                timer=st.get("timer"),
                erratum=st.get("erratum"),
            )
            for st in raw["states"]
        ),
        events=tuple(SmEvent(e["name"], _doc(e["doc"])) for e in raw["events"]),
        transitions=tuple(expanded),
        parameter_block_timeout_s=float(timing["parameter_block_timeout_s"]),
        default_alignment_time_s=float(timing["default_alignment_time_s"]),
        default_update_rate_hz=float(timing["default_update_rate_hz"]),
        result_delay_s=float(timing["result_delay_s"]),
        timers=tuple(SmTimer(t["name"], t["payload"], t["field"]) for t in raw.get("timers", ())),
        min_successful_runs=raw["calibration"]["min_successful_runs"] if "calibration" in raw else None,
        answers=_answers(expanded, payloads, usw_modes),
    )
