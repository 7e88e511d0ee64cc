# Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
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
SPEC_SHA256: Final = "509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d"
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
ERRATA_ALTERNATIVES: Final[Mapping[str, str]] = MappingProxyType(
    {
        "E3": "Byte 2 of Table 6.17 is the percent of used data points, as in Table 6.14.",
        "E4": "Utermo100 is an unsigned word as printed, 0 to 655.35 degC.",
        "E5": "Parameter blocks are sent with message type 0, like the command they follow.",
        "E6": (
            "The reserved byte must be 0: decoders refuse a frame that carries another value and builders write only 0."
        ),
        "E8": "Bytes 0-3 of Table 6.13 are a reserved field of 4 bytes, as the table prints them.",
        "E11": (
            "AHRS-G300-A2-TGA has no published KG and KA, so its scaled gyro and accelerometer values are not given."
        ),
        "E12": (
            "The acknowledgement of a parameter block carries the sum of the block's payload bytes only (\"the check "
            'sum of received parameters").'
        ),
        "E15": "Dates are decoded by floor arithmetic: the year, then the month, then the day from what remains.",
        "E16": (
            "Builders write numbers without zero padding (printf %.2f: 12.34 for a roll of 12.34 deg) and the USW "
            "without leading zeros."
        ),
        "E17": "Any message length a word holds is accepted, up to what the receiver can hold.",
        "E18": "A block with either undefined combination of bits 7 and 15 is refused.",
        "E23": "Raw heading 36000 (360.00 deg, the top of the ICD's range 0...360) is accepted.",
        "E27": "A plain word: 0 is a successful alignment, anything else an unsuccessful one, with no status bits.",
        "E30": "A time of 0 s is accepted, like any value a word holds.",
        "E31": "No bounds: any float32, NaN and infinities included, is accepted.",
        "E32": (
            "The reserved bytes are the float and word Table 6.15 and Table 6.16 print, read and written as numbers."
        ),
        "E33": (
            "A command with no transition in the current mode is still acknowledged (or acted on) as in the modes "
            "where it is valid."
        ),
        "E34": (
            "The AHRS waits for the block as long as it takes and takes the next data message as the block, whatever "
            "its size."
        ),
        "E35": "LowPowerOn is valid in every mode, and the AHRS sleeps at once without a last data block.",
        "E37": "FinishClb is ignored until two runs have succeeded.",
        "E39": "GetDataReq sent during the initial alignment is answered once the alignment is done.",
        "E41": (
            "A receiver never gives up a message it has started on an idle line: it waits for the bytes its length "
            "field promises."
        ),
        "E43": (
            "A ROS 2 view may take another value of g (9.81 m/s^2, or the local gravity of a known place) and "
            "covariances from Table 3.1's figures for a known part number; the AHRS's own bytes mean the same either "
            "way."
        ),
    }
)
"""Each erratum an implementation may take the other side of -> that other reading (the erratum's
`alternative`); the others are corrections with one reading. A conformance declaration chooses a side
of these only."""


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
