# Generated from spec/ilahrs.yaml, spec hash 905562f909021aa2014695e63891380eb8bec4c960db652411cc7de9726e784b.
# Do not edit: change the spec or the generator and run `make generate`.
"""The single facts of spec/ilahrs.yaml (spec 1.0.0) that the runtime modules read: the error kinds,
the frame (Table 6.2, Table 6.3) and its message types, the serial line and the largest message."""

from __future__ import annotations

from collections.abc import Mapping
from enum import IntEnum
from types import MappingProxyType
from typing import Final

from .compat import StrEnum

SPEC_VERSION: Final = "1.0.0"
SPEC_SHA256: Final = "905562f909021aa2014695e63891380eb8bec4c960db652411cc7de9726e784b"
WIRE_FINGERPRINT: Final = 0x0D3AB4A6E6F066A7
"""What a device and a host must agree on (codes, payload layouts, frame, state-machine answers; not docs or
names), hashed to 64 bits: two builds with equal fingerprints speak the same bytes."""
ICD_DATE: Final = (2014, 3, 11)
"""The date of Inertial Labs AHRS Interface Control Document, rev 1.7: (year, month, day)."""
UNIT_SYMBOLS: Final[Mapping[str, str]] = MappingProxyType(
    {
        "deg": "deg",
        "deg_per_s": "deg/s",
        "g": "g",
        "nT": "nT",
        "V": "V",
        "degC": "degC",
        "one": "",
        "Hz": "Hz",
        "s": "s",
        "m": "m",
        "adc": "ADC",
        "percent": "%",
        "year": "year",
    }
)
"""Each unit of the spec (a field's `unit`) -> the symbol shown after its values: "" for a dimensionless number."""


class ErrorKind(StrEnum):
    """What went wrong. The values are the spec's names, shared by every binding."""

    TRUNCATED = "truncated"
    """The input ends before the frame, payload or sentence does."""
    BAD_HEADER = "bad_header"
    """The frame does not start with AA 55, or a sentence does not start with the $PAHR identifier."""
    BAD_MESSAGE_TYPE = "bad_message_type"
    """The message type byte is neither 0 (command) nor 1 (data) (Table 6.2)."""
    BAD_LENGTH = "bad_length"
    """The message length is outside the bounds the spec accepts, or a payload is not the size its table
    defines."""
    BAD_CHECKSUM = "bad_checksum"
    """The transmitted checksum does not match the one computed over the received bytes."""
    TRAILING_DATA = "trailing_data"
    """Bytes follow the end of a complete frame, payload or sentence where none are allowed."""
    UNKNOWN_COMMAND = "unknown_command"
    """A command code or command name that Table C.1 does not define."""
    OUT_OF_RANGE = "out_of_range"
    """A value outside the range the spec allows for its field (refused by builders, never wrapped or
    truncated)."""
    MALFORMED = "malformed"
    """Text that does not follow the sentence grammar (missing or extra fields, a bad number)."""
    BUFFER_TOO_SMALL = "buffer_too_small"
    """The caller's output buffer cannot hold the message being built."""
    UNEXPECTED_MESSAGE = "unexpected_message"
    """The peer sent a message that the protocol state does not allow (host session and device model)."""
    TIMEOUT = "timeout"
    """An answer the protocol requires did not arrive in time (host session)."""
    BAD_RESERVED = "bad_reserved"
    """Strict decoding only - a data frame's reserved byte is not the value the AHRS sends (E42)."""


class MessageType(IntEnum):
    """The message type byte (Table 6.2, Table 6.3)."""

    COMMAND = 0
    """A command from the host (one-byte payload holding the command code)."""
    DATA = 1
    """Data: every AHRS output, and the parameter blocks the host sends (E5)."""


HEADER: Final = bytes(
    (
        0xAA,
        0x55,
    )
)
"""The bytes every frame starts with."""
HEADER_SIZE: Final = 2
MESSAGE_TYPE_OFFSET: Final = 2
RESERVED_OFFSET: Final = 3
MESSAGE_LENGTH_OFFSET: Final = 4
FRAME_FIELDS: Final = ("message_type", "reserved", "message_length")
"""The fields between header and payload, in wire order."""
FRAME_FORMAT: Final = "<BBH"
"""Their `struct` format."""
PAYLOAD_OFFSET: Final = 6
CHECKSUM_SIZE: Final = 2
FRAME_OVERHEAD: Final = 8
"""Bytes in a frame besides the payload."""
LENGTH_BIAS: Final = 6
"""message_length = payload size + LENGTH_BIAS."""
MIN_MESSAGE_LENGTH: Final = 7
"""Smallest message length a decoder accepts (E17)."""
MAX_MESSAGE_LENGTH: Final = 58
"""Largest message length a decoder accepts (E17)."""
MIN_PAYLOAD_SIZE: Final = 1
MAX_PAYLOAD_SIZE: Final = 52
MIN_FRAME_SIZE: Final = 9
MAX_FRAME_SIZE: Final = 60
MAX_MESSAGE_SIZE: Final = 82
"""The longest frame or sentence: the most bytes a stream decoder ever holds."""

STRICT_RESERVED: Final[Mapping[int, int]] = MappingProxyType({1: 0})
"""Strict decoding (E42): message type -> the reserved byte the AHRS
writes in such frames. A decoder asked to be strict refuses a frame of such a type with another reserved
byte (BAD_RESERVED); without the option any value is accepted."""

UNITS: Final[Mapping[str, str]] = MappingProxyType(
    {
        "deg": "degrees",
        "deg_per_s": "degrees per second",
        "g": "standard gravity",
        "nT": "nanotesla",
        "V": "volts DC",
        "degC": "degrees Celsius",
        "one": "dimensionless",
        "Hz": "hertz",
        "s": "seconds",
        "m": "metres",
        "adc": "ADC codes (no physical scale given by the ICD)",
        "percent": "percent",
        "year": "fractional year, see encoding `date`",
    }
)
"""Unit name (a field's `unit`) -> what it measures, as the spec says."""

SERIAL_LINE: Final[Mapping[str, int | str]] = MappingProxyType(
    {"baud_rate": 115200, "data_bits": 8, "parity": "none", "stop_bits": 1}
)
"""The AHRS serial line."""
IDLE_BYTE_TIMES: Final = 1152
"""How long the line may be quiet inside a message, in byte times of 10 bits at 115200 baud."""
IDLE_TIMEOUT: Final = 0.1
"""IDLE_BYTE_TIMES in seconds: a stream decoder told that the line has been quiet this long gives up
the message it waits for (StreamDecoder.idle)."""
