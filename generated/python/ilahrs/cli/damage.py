# Copied from generator/targets/python/runtime/cli/damage.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""Damage in a stream of bytes: the damaged regions of bytes that are no message, with their
reasons (`damage_regions`), held and reported as they come (`Damage`), counted for the summary
(`Regions`), and `Splitter`, a stream decoder that says where each message and each damaged region
is."""

from __future__ import annotations

from bisect import bisect_right
from typing import Final

from ..frame import (
    BAD_CHECKSUM as FRAME_BAD_CHECKSUM,
)
from ..frame import (
    HEADER,
    HEADER_SIZE,
    MESSAGE_LENGTH_OFFSET,
    NEED_MORE,
    PAYLOAD_OFFSET,
    frame_at,
)
from ..nmea import MAX_SENTENCE_LENGTH, PREFIX
from ..stream import StreamDecoder, StreamEvent

__all__ = [
    "BAD_CHECKSUM",
    "BAD_RESERVED",
    "LISTED",
    "MISSING",
    "NO_FRAME_START",
    "REASONS",
    "TRUNCATED",
    "Damage",
    "Region",
    "Regions",
    "Splitter",
    "damage_regions",
]


BAD_CHECKSUM: Final = "bad_checksum"
BAD_RESERVED: Final = "bad_reserved"
TRUNCATED: Final = "truncated"
NO_FRAME_START: Final = "no_frame_start"
MISSING: Final = "missing"
_OPEN_LIMIT: Final = 1 << 16
"""Damaged bytes held before the regions already decided are reported."""
LISTED: Final = 10
"""Damaged regions and errors listed one by one in the summary."""


REASONS: Final = {
    BAD_CHECKSUM: "a frame or sentence whose checksum fails",
    BAD_RESERVED: "a frame whose reserved byte is not the AHRS's (E42)",
    TRUNCATED: "a frame or sentence cut short",
    NO_FRAME_START: "bytes that start no frame or sentence",
}


Region = tuple[int, int, str]
"""A damaged region: offset, length, reason."""


def _starts_frame(data: bytes | bytearray, pos: int) -> bool:
    """Whether a frame may start at `pos`: its header, a message type and a length that can be (as
    far as the bytes go)."""
    return frame_at(data, pos, min(len(data), pos + PAYLOAD_OFFSET)) == NEED_MORE


def _starts_sentence(data: bytes | bytearray, pos: int) -> bool:
    head = bytes(data[pos : pos + len(PREFIX)])
    return PREFIX.startswith(head)


_LENGTH_HIGH: Final = MESSAGE_LENGTH_OFFSET + 1
_STARTS: Final = ((HEADER[0], _starts_frame), (PREFIX[0], _starts_sentence))


def _next_start(data: bytes | bytearray, pos: int) -> int:
    """The first position from `pos` where a frame or a sentence may start, or len(data)."""
    best = len(data)
    for byte, test in _STARTS:
        at = data.find(byte, pos, best)
        while at >= 0 and not test(data, at):
            at = data.find(byte, at + 1, best)
        if at >= 0:
            best = at
    return best


def damage_regions(run: bytes | bytearray, *, closed: bool = True) -> list[Region]:
    """A run of bytes the stream decoder discarded (between two messages, or to the end), split
    into damaged regions with their reasons: a frame header whose frame fits in the run is a frame
    that failed its check (`bad_checksum`, or `bad_reserved` when the checksum holds: `--strict`),
    and so is a sentence whose end is in the run; a frame or sentence whose end the run does not
    reach was cut short (`truncated`, up to the next place a message may start); other bytes start
    no message (`no_frame_start`). `closed`: the run has ended; when not, the regions more bytes
    could change are left out (a run of noise at the end only once longer than half _OPEN_LIMIT).

    >>> frame = bytes.fromhex("AA 55 00 00 07 00 FE 05 01")
    >>> damage_regions(b"xy" + frame[:6] + bytes([0xFD]) + frame[7:] + bytes.fromhex("AA 55 01 00 3A 00"))
    [(0, 2, 'no_frame_start'), (2, 9, 'bad_checksum'), (11, 6, 'truncated')]
    """
    regions: list[Region] = []
    size = len(run)
    pos = 0
    while pos < size:
        found = _region_at(run, pos, closed)
        if found is None:
            break
        reason, end = found
        if not closed and end == size and reason == NO_FRAME_START and end - pos < _OPEN_LIMIT // 2:
            break  # more noise may follow
        regions.append((pos, end - pos, reason))
        pos = end
    return regions


def _region_at(run: bytes | bytearray, pos: int, closed: bool) -> tuple[str, int] | None:
    """The reason and end of the damaged region at `pos`; None if more bytes could change them."""
    size = len(run)
    if _starts_frame(run, pos):
        found = frame_at(run, pos, size)  # a whole frame here was refused when strict (E42)
        if found > 0:
            return BAD_RESERVED, pos + found
        if found == FRAME_BAD_CHECKSUM:
            return BAD_CHECKSUM, pos + HEADER_SIZE + (run[pos + MESSAGE_LENGTH_OFFSET] | run[pos + _LENGTH_HIGH] << 8)
        return (TRUNCATED, _next_start(run, pos + 1)) if closed else None
    if _starts_sentence(run, pos):
        lf = run.find(b"\n", pos, pos + MAX_SENTENCE_LENGTH)
        if lf >= 0:
            return BAD_CHECKSUM, lf + 1
        if closed or size - pos >= MAX_SENTENCE_LENGTH:
            return TRUNCATED, _next_start(run, pos + 1)
        return None
    return NO_FRAME_START, _next_start(run, pos + 1)


class Damage:
    """The discarded bytes of one direction, as they come (`add`), reported as damaged regions
    (`take`): a run is split when it ends (`close`), or when it grows past _OPEN_LIMIT (the regions
    more bytes cannot change), so memory stays bounded."""

    def __init__(self) -> None:
        self._start = 0
        self._data = bytearray()
        self._found: list[tuple[int, bytes, str]] = []

    def add(self, offset: int, data: bytes | bytearray | memoryview) -> None:
        if self._data and offset != self._start + len(self._data):
            self.close()
        if not self._data:
            self._start = offset
        self._data += data
        if len(self._data) > _OPEN_LIMIT:
            self._report(damage_regions(self._data, closed=False))

    @property
    def held(self) -> int:
        """Bytes of the run not yet reported."""
        return len(self._data)

    @property
    def start(self) -> int:
        """Offset of the first byte held."""
        return self._start

    def close(self) -> None:
        self._report(damage_regions(self._data))

    def take(self) -> list[tuple[int, bytes, str]]:
        """The regions decided since the last call: (offset, bytes, reason)."""
        found, self._found = self._found, []
        return found

    def _report(self, regions: list[Region]) -> None:
        for at, length, reason in regions:
            self._found.append((self._start + at, bytes(self._data[at : at + length]), reason))
        done = sum(regions[-1][:2]) if regions else 0
        del self._data[:done]
        self._start += done


class Splitter:
    """A StreamDecoder that also says where each message and each damaged region is, and which
    packet (time, number) holds a byte."""

    def __init__(self, strict: bool = False) -> None:
        self.decoder = StreamDecoder(strict=strict)
        self.buffer = bytearray()
        self.base = 0
        self.damage = Damage()
        self.discarded = 0
        self.fed = 0
        self.last: float | None = None
        """The time of the last chunk fed."""
        self._packets: list[tuple[int, float | None, int | None]] = []
        """(offset of its first byte, time, number) of each packet still referred to."""

    def feed(
        self, data: bytes, *, final: bool = False, when: float | None = None, packet: int | None = None
    ) -> list[tuple[int, StreamEvent | tuple[bytes, str]]]:
        """The messages and damaged regions `data` completes, in order, with their offsets.
        `final`: the input has ended, or the line has been idle (E41): decide on every byte held."""
        if data:
            self._packets.append((self.fed, when, packet))
            self.fed += len(data)
            self.last = when
        events = self.decoder.finish() if final else self.decoder.feed(data)
        self.buffer += data
        decided = len(self.buffer) - self.decoder.pending
        pos = 0
        located: list[tuple[int, StreamEvent | tuple[bytes, str]]] = []
        for event in events:
            at = self.buffer.find(event.raw, pos)
            self._gap(pos, at)
            if self.damage.held:
                self.damage.close()  # a message ends the run before it
            located += [(offset, (raw, reason)) for offset, raw, reason in self.damage.take()]
            located.append((self.base + at, event))
            pos = at + len(event.raw)
        self._gap(pos, decided)
        if final:
            self.damage.close()
        located += [(offset, (raw, reason)) for offset, raw, reason in self.damage.take()]
        del self.buffer[:decided]
        self.base += decided
        return located

    def note(self, before: int, size: int, when: float | None, packet: int | None) -> None:
        """`before` bytes, then a packet of `size` bytes, decoded elsewhere as whole messages."""
        self.fed += before
        self._packets.append((self.fed, when, packet))
        self.fed += size
        self.last = when

    def packet_of(self, offset: int) -> tuple[float | None, int | None]:
        """The time and number of the packet holding the byte at `offset`."""
        index = bisect_right(self._packets, offset, key=lambda entry: entry[0]) - 1
        if index < 0:
            return None, None
        _, when, number = self._packets[index]
        return when, number

    def forget(self, before: int) -> None:
        """Packets wholly before `before` are no longer looked up."""
        index = bisect_right(self._packets, before, key=lambda entry: entry[0]) - 1
        if index > 0:
            del self._packets[:index]

    def _gap(self, start: int, end: int) -> None:
        if end <= start:
            return
        self.discarded += end - start
        self.damage.add(self.base + start, self.buffer[start:end])


class Regions:
    """The damaged regions of bytes, for the summary: how many, how many bytes, the first few."""

    def __init__(self) -> None:
        self.count = 0
        self.listed: list[str] = []

    def add(self, direction: str, offset: int, length: int, reason: str) -> None:
        self.count += 1
        if len(self.listed) < LISTED:
            self.listed.append(f"{direction} offset {offset} ({length} {reason})")
