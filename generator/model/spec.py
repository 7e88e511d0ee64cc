"""The model's root, `Spec`, and the small sections it holds directly: error kinds, modes,
variants, errata and the serial line (part of generator.model)."""

from __future__ import annotations

from dataclasses import dataclass

from .encodings import (
    CalibrationSuccessEncoding,
    DateEncoding,
    DeclinationEncoding,
    Enum,
    Nmea,
    StatusWord,
)
from .fields import Payload, Unit
from .frame import Command, Frame
from .machine import StateMachine


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
class SerialLine:
    """The serial port settings (section 6)."""

    baud_rate: int
    data_bits: int
    parity: str
    stop_bits: int
    idle_byte_times: int | None = None  # E41: None when the spec gives no idle threshold

    @property
    def bits_per_byte(self) -> int:
        """Start bit, data bits, parity bit (if any), stop bits."""
        return 1 + self.data_bits + (self.parity != "none") + self.stop_bits

    @property
    def idle_timeout_us(self) -> int | None:
        """The idle threshold in whole microseconds (rounded up), or None."""
        if self.idle_byte_times is None:
            return None
        return -(-self.idle_byte_times * self.bits_per_byte * 1_000_000 // self.baud_rate)

    @property
    def idle_timeout_s(self) -> float | None:
        """The idle threshold in seconds, or None."""
        us = self.idle_timeout_us
        return None if us is None else us / 1_000_000


@dataclass(frozen=True)
class Erratum:
    id: str
    where: str
    says: str
    chosen: str
    why: str
    alternative: str | None = None
    """The other reading an implementation may take instead of `chosen`; None: only one reading
    (a correction), so no vector rests on this erratum's side."""


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
    # 64 bits of the hash of the wire-relevant part (generator/diff/fingerprint.py, wire_facts): equal
    # for two specs a device and a host agree on, whatever their docs and names. Filled in by layout.
    wire_fingerprint: int = 0

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
