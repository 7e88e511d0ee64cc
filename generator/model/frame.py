"""The model's frame and commands (part of generator.model).

The frame is the envelope every message travels in: header, the fields before the payload,
checksum, message types and the bounds of its length field. `payload_offset` is -1 until the
layout step fills it in.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..load import PathKey
from .fields import Field


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
class Strict:
    """What the AHRS writes in a data frame's header (E42): a strict decoder refuses other values."""

    message_type: str  # the message type name the rule covers
    message_type_value: int
    reserved: int
    erratum: str


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
    strict: Strict | None = None
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
