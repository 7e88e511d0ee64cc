"""The model's enums and value encodings: dates, declination, calibration success, the unit
status word (USW) and the $PAHR sentence (part of generator.model)."""

from __future__ import annotations

from dataclasses import dataclass


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
