# Copied from generator/targets/python/runtime/frame.py for spec/ilahrs.yaml,
# spec hash 7c7bff7a4eb096f2155fc3604f09bf92d9cb73a52d0059845310eba9f5ff0c74.
# Do not edit: change the runtime source and run `make generate`.
"""The binary frame and its checksum.

A frame is the header (HEADER), then the fields FRAME_FIELDS (message type, reserved byte and
message length), then the payload, then the checksum. The message length counts every byte after
the header; the checksum is the sum, modulo 2**16, of the bytes from the message type through the
payload. Every multi-byte value is little-endian. The layout is the spec's (`ilahrs.spec`).
"""

from __future__ import annotations

import struct
from dataclasses import dataclass
from typing import Final

from .errors import ErrorKind, IlahrsError, brief, require_bytes, require_flag
from .spec import (
    CHECKSUM_SIZE,
    FRAME_FIELDS,
    FRAME_FORMAT,
    FRAME_OVERHEAD,
    HEADER,
    HEADER_SIZE,
    LENGTH_BIAS,
    MAX_FRAME_SIZE,
    MAX_MESSAGE_LENGTH,
    MAX_PAYLOAD_SIZE,
    MESSAGE_LENGTH_OFFSET,
    MESSAGE_TYPE_OFFSET,
    MIN_FRAME_SIZE,
    MIN_MESSAGE_LENGTH,
    MIN_PAYLOAD_SIZE,
    PAYLOAD_OFFSET,
    RESERVED_OFFSET,
    STRICT_RESERVED,
    MessageType,
)

__all__ = [
    "CHECKSUM_SIZE",
    "FRAME_OVERHEAD",
    "HEADER",
    "HEADER_SIZE",
    "LENGTH_BIAS",
    "MAX_FRAME_SIZE",
    "MAX_MESSAGE_LENGTH",
    "MAX_PAYLOAD_SIZE",
    "MESSAGE_LENGTH_OFFSET",
    "MESSAGE_TYPE_OFFSET",
    "MIN_FRAME_SIZE",
    "MIN_MESSAGE_LENGTH",
    "MIN_PAYLOAD_SIZE",
    "PAYLOAD_OFFSET",
    "RESERVED_OFFSET",
    "STRICT_RESERVED",
    "Frame",
    "MessageType",
    "checksum",
]

_LENGTH: Final = struct.Struct("<H")
_PREFIX: Final = struct.Struct(FRAME_FORMAT)
"""The fields between header and payload, in FRAME_FIELDS order."""
_MESSAGE_TYPES: Final = frozenset(int(t) for t in MessageType)


def checksum(data: bytes | bytearray | memoryview) -> int:
    """The frame checksum of `data`: the sum of its bytes modulo 2**16 (E28)."""
    return sum(require_bytes(data, "data")) & 0xFFFF


@dataclass(frozen=True, slots=True)
class Frame:
    """One frame: message type, payload and the reserved byte (E6: any value is accepted, unless
    decoding is strict, E42).

    `build()` fills the length and the checksum; `Frame.parse()` checks them.
    """

    message_type: int
    payload: bytes
    reserved: int = 0

    @classmethod
    def parse(cls, data: bytes | bytearray | memoryview, strict: bool = False) -> Frame:
        """Decode exactly one frame; raise IlahrsError (see spec/README.md for the order of checks).
        `data` must be a byte string (MALFORMED otherwise: hex text is not decoded for you).
        `strict`: after every other check, refuse a frame whose reserved byte is not the one the
        AHRS writes in frames of its message type (BAD_RESERVED at RESERVED_OFFSET; STRICT_RESERVED).

        >>> Frame.parse(bytes.fromhex("AA 55 01 3C 09 00 01 02 03 4C 00")).reserved
        60
        >>> Frame.parse(bytes.fromhex("AA 55 01 3C 09 00 01 02 03 4C 00"), strict=True)
        Traceback (most recent call last):
        ...
        ilahrs.errors.IlahrsError: bad_reserved in reserved at offset 3: reserved byte 0x3c, the AHRS sends 0x00
        """
        data = require_bytes(data, "data")
        require_flag(strict, "strict")
        size = len(data)
        for index, expected in enumerate(HEADER):
            if size <= index:
                raise IlahrsError(ErrorKind.TRUNCATED, size, None, "input ends inside the header")
            if data[index] != expected:
                detail = f"byte {data[index]:#04x}, expected {expected:#04x}"
                raise IlahrsError(ErrorKind.BAD_HEADER, index, "header", detail)
        if size < PAYLOAD_OFFSET:
            raise IlahrsError(ErrorKind.TRUNCATED, size, None, "input ends before the message length")
        message_type = data[MESSAGE_TYPE_OFFSET]
        if message_type not in _MESSAGE_TYPES:
            detail = f"message type {message_type}"
            raise IlahrsError(ErrorKind.BAD_MESSAGE_TYPE, MESSAGE_TYPE_OFFSET, "message_type", detail)
        (length,) = _LENGTH.unpack_from(data, MESSAGE_LENGTH_OFFSET)
        if not MIN_MESSAGE_LENGTH <= length <= MAX_MESSAGE_LENGTH:
            raise IlahrsError(
                ErrorKind.BAD_LENGTH,
                MESSAGE_LENGTH_OFFSET,
                "message_length",
                f"message length {length} outside {MIN_MESSAGE_LENGTH}..{MAX_MESSAGE_LENGTH}",
            )
        end = HEADER_SIZE + length
        if size < end:
            raise IlahrsError(ErrorKind.TRUNCATED, size, None, f"the frame needs {end} bytes")
        at = end - CHECKSUM_SIZE
        (sent,) = _LENGTH.unpack_from(data, at)
        computed = sum(data[HEADER_SIZE:at]) & 0xFFFF
        if sent != computed:
            raise IlahrsError(ErrorKind.BAD_CHECKSUM, at, "checksum", f"sent {sent:#06x}, computed {computed:#06x}")
        if size > end:
            raise IlahrsError(ErrorKind.TRAILING_DATA, end, None, f"{size - end} bytes after the frame")
        reserved = data[RESERVED_OFFSET]
        if strict and STRICT_RESERVED.get(message_type, reserved) != reserved:
            detail = f"reserved byte {reserved:#04x}, the AHRS sends {STRICT_RESERVED[message_type]:#04x}"
            raise IlahrsError(ErrorKind.BAD_RESERVED, RESERVED_OFFSET, "reserved", detail)
        return cls(message_type, data[PAYLOAD_OFFSET:at], reserved)

    def build(self) -> bytes:
        """Encode the frame, filling in message length and checksum."""
        if _is_int(self.message_type) and self.message_type not in _MESSAGE_TYPES:
            # spec/README.md, frame encode: the message type is checked before the reserved byte
            raise IlahrsError(ErrorKind.BAD_MESSAGE_TYPE, None, "message_type", f"message type {self.message_type}")
        self._check_types()
        if not MIN_PAYLOAD_SIZE <= len(self.payload) <= MAX_PAYLOAD_SIZE:
            raise IlahrsError(
                ErrorKind.BAD_LENGTH,
                None,
                "payload",
                f"payload of {len(self.payload)} bytes outside {MIN_PAYLOAD_SIZE}..{MAX_PAYLOAD_SIZE}",
            )
        body = self._body()
        return HEADER + body + _LENGTH.pack(sum(body) & 0xFFFF)

    def _check_types(self) -> None:
        """IlahrsError unless the fields are of the types the wire needs (integers, a byte string)."""
        for name in ("message_type", "reserved"):
            value = getattr(self, name)
            if not _is_int(value) or not 0 <= value <= 0xFF:
                kind = ErrorKind.BAD_MESSAGE_TYPE if name == "message_type" else ErrorKind.OUT_OF_RANGE
                raise IlahrsError(kind, None, name, f"{name.replace('_', ' ')} {brief(value)} is not a byte")
        if not isinstance(self.payload, (bytes, bytearray, memoryview)):
            raise IlahrsError(ErrorKind.MALFORMED, None, "payload", f"{brief(self.payload)} is not a byte string")

    def _body(self) -> bytes:
        """The checksummed bytes: the fields between header and payload, then the payload."""
        values = {
            "message_type": self.message_type,
            "reserved": self.reserved,
            "message_length": len(self.payload) + LENGTH_BIAS,
        }
        return _PREFIX.pack(*(values[name] for name in FRAME_FIELDS)) + bytes(self.payload)

    @property
    def checksum(self) -> int:
        """The checksum this frame carries on the wire."""
        self._check_types()
        return sum(self._body()) & 0xFFFF


def _is_int(value: object) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)
