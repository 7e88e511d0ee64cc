# Copied from generator/targets/python/runtime/frame.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
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
    "BAD_CHECKSUM",
    "BAD_HEADER",
    "BAD_LENGTH",
    "BAD_MESSAGE_TYPE",
    "BAD_RESERVED",
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
    "NEED_MORE",
    "PAYLOAD_OFFSET",
    "REFUSALS",
    "RESERVED_OFFSET",
    "STRICT_RESERVED",
    "Frame",
    "MessageType",
    "checksum",
    "frame_at",
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
        found = frame_at(data, 0, size, strict=strict)
        if found < 0:
            if found != BAD_RESERVED or size <= _frame_size(data):
                raise _refusal(data, found)
            found = _frame_size(data)
        if size > found:
            raise IlahrsError(ErrorKind.TRAILING_DATA, found, None, f"{size - found} bytes after the frame")
        at = found - CHECKSUM_SIZE
        message_type, reserved = data[MESSAGE_TYPE_OFFSET], data[RESERVED_OFFSET]
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


NEED_MORE: Final = -1
"""`frame_at`: the bytes so far may begin a frame; more are needed to tell."""
BAD_HEADER: Final = -2
"""`frame_at`: not a frame, its header is not HEADER."""
BAD_MESSAGE_TYPE: Final = -3
"""`frame_at`: not a frame, its message type is not one."""
BAD_LENGTH: Final = -4
"""`frame_at`: not a frame, its message length is outside MIN_MESSAGE_LENGTH..MAX_MESSAGE_LENGTH."""
BAD_CHECKSUM: Final = -5
"""`frame_at`: not a frame, its checksum fails."""
BAD_RESERVED: Final = -6
"""`frame_at`: not a frame when decoding is strict, its reserved byte is not the AHRS's (E42)."""
REFUSALS: Final = {
    BAD_HEADER: ErrorKind.BAD_HEADER,
    BAD_MESSAGE_TYPE: ErrorKind.BAD_MESSAGE_TYPE,
    BAD_LENGTH: ErrorKind.BAD_LENGTH,
    BAD_CHECKSUM: ErrorKind.BAD_CHECKSUM,
    BAD_RESERVED: ErrorKind.BAD_RESERVED,
    NEED_MORE: ErrorKind.TRUNCATED,
}
"""The error kind of each answer of `frame_at` that is not a frame."""


def frame_at(
    data: bytes | bytearray | memoryview, pos: int = 0, end: int | None = None, *, strict: bool = False
) -> int:
    """The frame rule, in the order spec/README.md gives its checks: the size of the valid frame
    that starts at `pos` in data[:end] (end: len(data)), a positive number; NEED_MORE if the bytes
    up to `end` may begin one and more are needed to tell; else why there is none (BAD_HEADER,
    BAD_MESSAGE_TYPE, BAD_LENGTH, BAD_CHECKSUM, BAD_RESERVED: negative, REFUSALS gives their error
    kinds). `strict`: a frame whose reserved byte is not the one the AHRS writes in frames of its
    message type is none (STRICT_RESERVED, E42). Every decoder of this package decides with it.

    >>> frame_at(bytes.fromhex("00 AA 55 01 3C 09 00 01 02 03 4C 00"), 1)
    11
    >>> frame_at(bytes.fromhex("AA 55 01 3C 09 00 01 02 03 4C 00"), strict=True) == BAD_RESERVED
    True
    >>> frame_at(bytes.fromhex("AA 55 01 3C 09 00 01"), 0) == NEED_MORE
    True
    """
    available = (len(data) if end is None else end) - pos
    if available < PAYLOAD_OFFSET or data[pos : pos + HEADER_SIZE] != HEADER:
        for index, expected in enumerate(HEADER):
            if available <= index:
                return NEED_MORE
            if data[pos + index] != expected:
                return BAD_HEADER
        if available < PAYLOAD_OFFSET:
            return NEED_MORE
    message_type = data[pos + MESSAGE_TYPE_OFFSET]
    if message_type not in _MESSAGE_TYPES:
        return BAD_MESSAGE_TYPE
    length = data[pos + MESSAGE_LENGTH_OFFSET] | data[pos + MESSAGE_LENGTH_OFFSET + 1] << 8
    if not MIN_MESSAGE_LENGTH <= length <= MAX_MESSAGE_LENGTH:
        return BAD_LENGTH
    total = HEADER_SIZE + length
    if available < total:
        return NEED_MORE
    at = pos + total - CHECKSUM_SIZE
    if sum(data[pos + HEADER_SIZE : at]) & 0xFFFF != data[at] | data[at + 1] << 8:
        return BAD_CHECKSUM
    if strict:
        reserved = data[pos + RESERVED_OFFSET]
        if STRICT_RESERVED.get(message_type, reserved) != reserved:
            return BAD_RESERVED
    return total


def _frame_size(data: bytes | bytearray | memoryview) -> int:
    """The size the message length of the frame at the start of `data` gives it."""
    (length,) = _LENGTH.unpack_from(data, MESSAGE_LENGTH_OFFSET)
    return HEADER_SIZE + int(length)


def _refusal(data: bytes | bytearray | memoryview, found: int) -> IlahrsError:
    """The error Frame.parse raises for `data`, which frame_at answered `found` (not a frame)."""
    size = len(data)
    kind = REFUSALS[found]
    if found == BAD_HEADER or (found == NEED_MORE and size < HEADER_SIZE):
        index = next(i for i, byte in enumerate(HEADER) if i >= size or data[i] != byte)
        if index >= size:
            return IlahrsError(kind, size, None, "input ends inside the header")
        return IlahrsError(kind, index, "header", f"byte {data[index]:#04x}, expected {HEADER[index]:#04x}")
    if found == NEED_MORE and size < PAYLOAD_OFFSET:
        return IlahrsError(kind, size, None, "input ends before the message length")
    if found == NEED_MORE:
        return IlahrsError(kind, size, None, f"the frame needs {_frame_size(data)} bytes")
    if found == BAD_MESSAGE_TYPE:
        return IlahrsError(kind, MESSAGE_TYPE_OFFSET, "message_type", f"message type {data[MESSAGE_TYPE_OFFSET]}")
    if found == BAD_LENGTH:
        length = _frame_size(data) - HEADER_SIZE
        detail = f"message length {length} outside {MIN_MESSAGE_LENGTH}..{MAX_MESSAGE_LENGTH}"
        return IlahrsError(kind, MESSAGE_LENGTH_OFFSET, "message_length", detail)
    at = _frame_size(data) - CHECKSUM_SIZE
    if found == BAD_CHECKSUM:
        (sent,) = _LENGTH.unpack_from(data, at)
        computed = sum(data[HEADER_SIZE:at]) & 0xFFFF
        return IlahrsError(kind, at, "checksum", f"sent {sent:#06x}, computed {computed:#06x}")
    reserved, message_type = data[RESERVED_OFFSET], data[MESSAGE_TYPE_OFFSET]
    detail = f"reserved byte {reserved:#04x}, the AHRS sends {STRICT_RESERVED[message_type]:#04x}"
    return IlahrsError(kind, RESERVED_OFFSET, "reserved", detail)


def _is_int(value: object) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)
