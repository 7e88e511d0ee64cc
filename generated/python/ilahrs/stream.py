# Copied from generator/targets/python/runtime/stream.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""A sans-I/O stream decoder: bytes in, frames and sentences out, "leftmost valid message".

At each position a valid frame or a valid sentence is accepted and consumed; otherwise one byte
is discarded and scanning resumes at the next byte. So a false header, an absurd length or a
corrupted frame never costs a following good message, and the decoder never holds more than
MAX_MESSAGE_SIZE bytes. See spec/README.md for the exact rules every binding follows.

A message never spans an idle line (E41): `idle(quiet)` tells the decoder how long the line has
been quiet, and from IDLE_TIMEOUT on it decides on every byte it holds, as `finish` does, so the
start of a frame whose rest never came costs only its own bytes. `StreamDecoder(strict=True)`
refuses data frames whose reserved byte is not the AHRS's (E42).
"""

from __future__ import annotations

import math
from collections.abc import Generator
from dataclasses import dataclass
from typing import Final

from .errors import ErrorKind, IlahrsError, brief, require_bytes, require_flag
from .frame import (
    CHECKSUM_SIZE,
    HEADER,
    MESSAGE_TYPE_OFFSET,
    NEED_MORE,
    PAYLOAD_OFFSET,
    RESERVED_OFFSET,
    Frame,
    frame_at,
)
from .nmea import MAX_SENTENCE_LENGTH, PREFIX, PahrSentence
from .spec import IDLE_BYTE_TIMES, IDLE_TIMEOUT, MAX_MESSAGE_SIZE

__all__ = ["IDLE_BYTE_TIMES", "IDLE_TIMEOUT", "IDLE_TIMEOUT_NS", "MAX_MESSAGE_SIZE", "StreamDecoder", "StreamEvent"]

IDLE_TIMEOUT_NS: Final = None if math.isinf(IDLE_TIMEOUT) else round(IDLE_TIMEOUT * 1_000_000_000)
"""IDLE_TIMEOUT in nanoseconds, for clocks that count them (None: no quiet time is idle)."""

_NEED_MORE: Final = -1
_INVALID: Final = 0
_FRAME_START: Final = HEADER[0]
_SENTENCE_START: Final = PREFIX[0]
_CR: Final = 0x0D
_LF: Final = 0x0A
_CHUNK: Final = 1 << 16
"""feed_iter() adds its input in pieces of this size, so the decoder never holds much more."""


@dataclass(frozen=True, slots=True)
class StreamEvent:
    """An accepted message: its bytes as received, and the decoded frame or sentence."""

    raw: bytes
    frame: Frame | None = None
    sentence: PahrSentence | None = None


class StreamDecoder:
    """Feed bytes in chunks of any size; get accepted messages back in order.

    >>> decoder = StreamDecoder()
    >>> [e.frame.payload for e in decoder.feed(bytes.fromhex("00 AA 55 00 00 07 00 80 87 00"))]
    [b'\\x80']
    >>> decoder.discarded
    1

    The start of a frame whose rest never comes holds what follows, until the line is idle:

    >>> stale = bytes.fromhex("AA 55 01 00 3A 00")
    >>> decoder.feed(stale + bytes.fromhex("AA 55 00 00 07 00 41 48 00")), decoder.pending
    ([], 15)
    >>> [e.raw.hex(" ") for e in decoder.idle(IDLE_TIMEOUT)], decoder.discarded
    (['aa 55 00 00 07 00 41 48 00'], 7)

    `strict`: refuse data frames whose reserved byte is not the AHRS's (STRICT_RESERVED, E42).
    """

    __slots__ = ("_buffer", "_strict", "discarded")

    def __init__(self, strict: bool = False) -> None:
        self._buffer = bytearray()
        self._strict = require_flag(strict, "strict")
        self.discarded = 0
        """Input bytes that belong to no accepted message."""

    @property
    def pending(self) -> int:
        """Bytes held while waiting to decide on a possible message."""
        return len(self._buffer)

    def feed(self, data: bytes | bytearray | memoryview) -> list[StreamEvent]:
        """Add bytes; return the messages they complete, in order. IlahrsError(MALFORMED) for
        anything but a byte string (nothing is added)."""
        return list(self.feed_iter(data))

    def feed_iter(self, data: bytes | bytearray | memoryview) -> Generator[StreamEvent, None, None]:
        """`feed` as an iterator: the messages come as they are found, and memory stays flat for
        an input of any size (a whole capture at once). IlahrsError(MALFORMED) at once for
        anything but a byte string. Closed early, it keeps the bytes it has not scanned yet for
        the next `feed` or `finish` (messages already found and not taken are dropped)."""
        view = memoryview(require_bytes(data, "data"))
        return self._events(view)

    def _events(self, view: memoryview) -> Generator[StreamEvent, None, None]:
        start = 0
        try:
            while start < len(view):
                self._buffer += view[start : start + _CHUNK]
                start += _CHUNK
                yield from self._scan(final=False)
        finally:
            self._buffer += view[start:]

    def finish(self) -> list[StreamEvent]:
        """The input has ended: decide on every byte still held."""
        return self._scan(final=True)

    def idle(self, quiet: float | None = None) -> list[StreamEvent]:
        """The line has been quiet for `quiet` seconds since the last byte fed (None: it is idle).
        From IDLE_TIMEOUT on, decide on every byte held as `finish` does (a message never spans
        an idle line, E41) and return the messages found behind the ones given up; the decoder
        then goes on with the next bytes fed. A shorter quiet time changes nothing. NaN, a
        negative time or anything but a number: IlahrsError(OUT_OF_RANGE), nothing changes."""
        if quiet is not None:
            if isinstance(quiet, bool) or not isinstance(quiet, (int, float)) or not quiet >= 0:
                detail = f"{brief(quiet)} is not a quiet time in seconds (0 or more)"
                raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, "quiet", detail)
            if quiet < IDLE_TIMEOUT:
                return []
        return self._scan(final=True)

    def _scan(self, final: bool) -> list[StreamEvent]:
        buffer = self._buffer
        events: list[StreamEvent] = []
        size = len(buffer)
        pos = 0
        while pos < size:
            first = buffer[pos]
            if first == _FRAME_START:
                used, event = _frame_at(buffer, pos, size, self._strict)
            elif first == _SENTENCE_START:
                used, event = _sentence_at(buffer, pos, size)
            else:
                following = _next_start(buffer, pos + 1, size)
                self.discarded += following - pos
                pos = following
                continue
            if event is not None:
                events.append(event)
                pos += used
            elif used == _INVALID or final:
                self.discarded += 1
                pos += 1
            else:
                break
        del buffer[:pos]
        return events


def _next_start(buffer: bytearray, pos: int, size: int) -> int:
    """The next position that may start a message, or `size`."""
    frame = buffer.find(_FRAME_START, pos)
    sentence = buffer.find(_SENTENCE_START, pos)
    candidates = [p for p in (frame, sentence) if p >= 0]
    return min(candidates) if candidates else size


def _frame_at(buffer: bytearray, pos: int, size: int, strict: bool) -> tuple[int, StreamEvent | None]:
    total = frame_at(buffer, pos, size, strict=strict)
    if total < 0:
        return (_NEED_MORE if total == NEED_MORE else _INVALID), None
    raw = bytes(buffer[pos : pos + total])
    frame = Frame(raw[MESSAGE_TYPE_OFFSET], raw[PAYLOAD_OFFSET : total - CHECKSUM_SIZE], raw[RESERVED_OFFSET])
    return total, StreamEvent(raw, frame=frame)


def _sentence_at(buffer: bytearray, pos: int, size: int) -> tuple[int, StreamEvent | None]:
    limit = min(size, pos + MAX_SENTENCE_LENGTH)
    end = buffer.find(_LF, pos, limit)
    if end < 0:
        if size - pos >= MAX_SENTENCE_LENGTH:
            return _INVALID, None
        # Reject early what can never become a sentence: a wrong identifier or a byte that
        # is not printable (CR only directly before LF). Waiting would reach the same answer.
        head = bytes(buffer[pos : min(limit, pos + len(PREFIX))])
        if not PREFIX.startswith(head):
            return _INVALID, None
        for index in range(pos + 1, limit):
            byte = buffer[index]
            if not 0x20 <= byte <= 0x7E and not (byte == _CR and index == limit - 1):
                return _INVALID, None
        return _NEED_MORE, None
    raw = bytes(buffer[pos : end + 1])
    try:
        sentence = PahrSentence.parse(raw)
    except IlahrsError:
        return _INVALID, None
    return len(raw), StreamEvent(raw, sentence=sentence)
