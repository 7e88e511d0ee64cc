# Copied from generator/targets/python/runtime/cli/decode.py for spec/ilahrs.yaml,
# spec hash 7c7bff7a4eb096f2155fc3604f09bf92d9cb73a52d0059845310eba9f5ff0c74.
# Do not edit: change the runtime source and run `make generate`.
"""`ilahrs decode`: a capture as one row per message, in text, CSV or JSON lines.

Messages are told apart by context, as the host session does. With both directions recorded
(pcapng), the commands in the capture drive a `Host`, so the 50- and 52-byte blocks and the three
34-byte output layouts are decoded as the table the device was asked for. With device-to-host
bytes only (a raw dump), `--output-format` names the command that started the output; other
frames are decoded when their size fits one table only, and are of kind "frame" otherwise.

A raw dump written as CSV goes the columnar way (`ColumnarCsv`, `ilahrs.columnar`): a window of
the capture at a time, its frames found and decoded into columns (numpy when installed, else the
standard library's array), then written row by row, the same rows as message by message.

Rows: `time` (seconds since the first chunk of the capture, when the row's last byte was
recorded; empty in a raw dump), `direction` (in: device to host, out: host to device), `kind` (a
payload table's name, a command's name, PAHR for a $PAHR sentence, frame for a frame whose table
cannot be told, damaged for damage), `offset` (of the row's first byte in the bytes of its
direction), `packet` (the pcapng packet holding its last byte, from 1; empty in a raw dump),
`length` (bytes), `reason` and `detail` (damaged rows only), then every field in engineering units
(raw values with `--raw`): the Unit Status Word as the names of its flags joined by '|' (OK when
none is set), dates as YYYY-MM-DD, a calibration's `success` as succeeded or failed with its
predicted `accuracy` in degrees beside it (empty when the device gives none).

Every stretch of bytes that is no message is a row of kind damaged, one per region: a frame whose
checksum fails (`bad_checksum`; `bad_reserved` with `--strict`), a frame or sentence cut short
(`truncated`), bytes that start no frame (`no_frame_start`; a run longer than 64 KiB is reported
in pieces). With both directions, what the host session finds is a row too: a message nothing in
its state explains (`unexpected`), an acknowledgement with another checksum (`wrong`), an answer
owed and never received (`missing`, length 0, at the offset where it was due).
"""

from __future__ import annotations

import argparse
import csv
import json
import sys
import time
from bisect import bisect_right
from collections import Counter
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from typing import Any, Final, TextIO

from ..bulk import tables_by_size
from ..codec import Payload, date_text, field_kind
from ..columnar import (
    COMMAND,
    KINDS,
    SENTENCE,
    UNEXPLAINED,
    Scanner,
    Window,
    numpy_for,
    scales,
    table_columns,
)
from ..commands import COMMAND_SET, COMMANDS, decode_command
from ..encodings import Variant, calibration_accuracy_deg, calibration_succeeded
from ..errors import ErrorKind, IlahrsError
from ..frame import (
    BAD_CHECKSUM as FRAME_BAD_CHECKSUM,
)
from ..frame import (
    HEADER,
    HEADER_SIZE,
    MESSAGE_LENGTH_OFFSET,
    NEED_MORE,
    PAYLOAD_OFFSET,
    MessageType,
    frame_at,
)
from ..nmea import MAX_SENTENCE_LENGTH, PREFIX, PahrSentence
from ..payloads import PAYLOADS
from ..pcapng import Direction, Packets
from ..session.host import Acknowledged, DataBlock, Discarded, Host, HostEvent, Output, ProtocolError
from ..statemachine import INITIAL, OUTPUT_FORMATS, command_event
from ..stream import IDLE_TIMEOUT, StreamDecoder, StreamEvent
from .arguments import OneLineParser, strict_argument, variant_argument, words
from .capture import Chunk, Source, open_source
from .common import SENTENCE_KIND, CliError, field_columns, fields_of, lookup, usw_text, variant_named

__all__ = [
    "DAMAGED",
    "FORMATS",
    "UNDETERMINED",
    "CaptureDecoder",
    "ColumnarCapture",
    "ColumnarCsv",
    "Message",
    "RowWriter",
    "damage_regions",
    "decode_columns",
    "kinds",
    "output_table",
    "row_fields",
]

UNDETERMINED: Final = "frame"
"""The kind of a frame whose table the context does not tell."""
DAMAGED: Final = "damaged"
"""The kind of a row that reports damage: bytes that are no message, or an answer that never came."""
BAD_CHECKSUM: Final = "bad_checksum"
BAD_RESERVED: Final = "bad_reserved"
TRUNCATED: Final = "truncated"
NO_FRAME_START: Final = "no_frame_start"
MISSING: Final = "missing"
FORMATS: Final = ("text", "csv", "jsonl")
BASE_COLUMNS: Final = ("time", "direction", "kind", "offset", "packet", "length", "reason", "detail")
"""The first columns of every CSV row; the fields of the selected kinds follow (`decode_columns`)."""
ACCURACY: Final = "accuracy"
"""The column beside a calibration's success: its predicted accuracy in degrees (3 sigma)."""
SUCCEEDED: Final = "succeeded"
FAILED: Final = "failed"
_OPEN_LIMIT: Final = 1 << 16
"""Damaged bytes held before the regions already decided are reported."""
_DIRECTIONS: Final = {Direction.INBOUND: "in", Direction.OUTBOUND: "out"}
_PROGRESS_SIZE: Final = 8 << 20
_PROGRESS_PERIOD: Final = 0.5
_LISTED: Final = 10
"""Damaged regions and errors listed one by one in the summary."""


def kinds() -> list[str]:
    """Every message kind a row can have."""
    return [*PAYLOADS, SENTENCE_KIND, *COMMANDS, UNDETERMINED, DAMAGED]


def decode_columns(kinds: Iterable[str]) -> list[str]:
    """The field columns of `decode` rows of these kinds: `field_columns`, with `accuracy` after
    each calibration success."""
    result: list[str] = []
    for name in field_columns(kinds):
        result.append(name)
        if name in _CALIBRATION_FIELDS:
            result.append(ACCURACY)
    return result


_CALIBRATION_FIELDS: Final = frozenset(
    info.name for table in PAYLOADS.values() for info in table.FIELDS if info.encoding == "calibration_success"
)


def _usw(raw: int) -> str:
    return usw_text(raw)


def _outcome(raw: int) -> str:
    return SUCCEEDED if calibration_succeeded(raw) else FAILED


def _accuracy(raw: int) -> float | None:
    return calibration_accuracy_deg(raw) if calibration_succeeded(raw) else None


def _date(value: float) -> object:
    text = date_text(value)
    return value if text is None else text  # not a date the encoding can give: the number as sent


def row_fields(data: Payload | PahrSentence, variant: Variant, *, raw: bool = False) -> dict[str, object]:
    """The fields of a `decode` row: `fields_of`, where in engineering units the Unit Status Word
    with no flag reads OK, a date reads YYYY-MM-DD (the nearest calendar date, E15) and a
    calibration's success reads succeeded or failed, its accuracy in degrees in `accuracy` (None
    when there is none). `raw`: every field as sent (`accuracy` None)."""
    fields = fields_of(data, variant, raw=raw)
    if isinstance(data, PahrSentence):
        if not raw:
            fields["usw"] = _usw(data.usw)
        return fields
    result: dict[str, object] = {}
    for info in data.FIELDS:
        if info.type == "reserved":
            continue
        value = fields[info.name]
        sent = getattr(data, info.name)
        if info.encoding == "calibration_success":
            result[info.name] = value if raw else _outcome(sent)
            result[ACCURACY] = None if raw else _accuracy(sent)
            continue
        if not raw and info.encoding == "usw":
            value = _usw(sent)
        elif not raw and info.encoding == "date":
            value = _date(sent)
        result[info.name] = value
    return result


def output_table(command: str) -> str | None:
    """The payload table of the output `command` starts (None: $PAHR sentences); CliError for a
    command that starts no output."""
    starting = [name for name, info in COMMANDS.items() if info.starts_output is not None]
    name = lookup("output command", command, starting)
    return OUTPUT_FORMATS[COMMANDS[name].starts_output or ""]


_INBOUND_SIZES: Final = tables_by_size("device_to_host")
_OUTBOUND_SIZES: Final = tables_by_size("host_to_device")


@dataclass(frozen=True, slots=True)
class Message:
    """One row: when (seconds since the capture's first chunk, its last byte), which way, what,
    where (offset in its direction's bytes; the pcapng packet of its last byte), its bytes and its
    decoded payload or sentence. A damaged row has kind DAMAGED, a `reason` and a `detail`."""

    time: float | None
    direction: Direction
    kind: str
    offset: int
    raw: bytes
    data: Payload | PahrSentence | None = None
    packet: int | None = None
    reason: str | None = None
    detail: str | None = None


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


class _Damage:
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


class _Splitter:
    """A StreamDecoder that also says where each message and each damaged region is, and which
    packet (time, number) holds a byte."""

    def __init__(self, strict: bool = False) -> None:
        self.decoder = StreamDecoder(strict=strict)
        self.buffer = bytearray()
        self.base = 0
        self.damage = _Damage()
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


class CaptureDecoder:
    """Chunks in, Messages out. `context`: follow the commands seen in the capture with a Host;
    `output`: the table of the output started before the capture began (None: unknown), `start`
    the command that started it (a capture whose first bytes are the device's is then decoded by
    `Host.mid_stream`); `strict`: refuse data frames from the device whose reserved byte is not the
    AHRS's (E42)."""

    def __init__(
        self,
        *,
        context: bool,
        output: str | None = None,
        output_known: bool = False,
        strict: bool = False,
        start: str | None = None,
    ) -> None:
        self._context = context
        self._host: Host | None = None
        self._start_command = start
        self._strict = strict
        self._output = output
        self._output_known = output_known
        self._in = _Splitter(strict)
        self._out = _Splitter()
        self._command: tuple[str, int] | None = None
        self._start: float | None = None
        self._last: float | None = None
        self._rows: list[Message] = []
        self.counts: Counter[str] = Counter()
        self.damage: Counter[str] = Counter()
        """Damaged rows by reason."""
        self.regions = _Regions()
        self.errors: list[str] = []

    def feed(self, chunk: Chunk) -> list[Message]:
        if self._context and self._host is None:
            mid = chunk.direction == Direction.INBOUND and self._start_command is not None
            command = self._start_command or ""
            self._host = Host.mid_stream(command, strict=self._strict) if mid else Host(strict=self._strict)
        when = self._clock(chunk.time)
        for side, handle in ((self._in, self._inbound), (self._out, self._outbound)):
            if when is not None and side.last is not None and when - side.last >= IDLE_TIMEOUT:
                side.last = None  # the line was idle: no message spans it (E41), nor any damage
                for at, event in side.feed(b"", final=True):
                    handle(at, event)
        if chunk.direction == Direction.OUTBOUND:
            for at, event in self._out.feed(chunk.data, when=when, packet=chunk.packet):
                self._outbound(at, event)
        else:
            for at, event in self._in.feed(chunk.data, when=when, packet=chunk.packet):
                self._inbound(at, event)
        return self._take()

    def finish(self) -> list[Message]:
        for at, event in self._in.feed(b"", final=True):
            self._inbound(at, event)
        for at, event in self._out.feed(b"", final=True):
            self._outbound(at, event)
        return self._take()

    # --- Output decoded as columns (ColumnarCapture) ---------------------------------------------

    @property
    def start(self) -> float | None:
        """The time of the capture's first chunk (None before it)."""
        return self._start

    @property
    def inbound_bytes(self) -> int:
        """Bytes from the device fed so far."""
        return self._in.fed

    def in_idle(self, now: float | None) -> bool:
        """Whether the device's line has been idle (E41) before a chunk at `now`."""
        side = self._in
        if now is None or self._start is None or side.last is None:
            return False
        return now - self._start - side.last >= IDLE_TIMEOUT

    def streaming(self) -> str | None:
        """The table of the output the host waits for and nothing else (`Host.streaming`), while
        no bytes of either direction are held undecided; None otherwise."""
        host = self._host
        if host is None or self._start is None or self._command is not None:
            return None
        for side in (self._in, self._out):
            if side.buffer or side.decoder.pending or side.damage.held:
                return None
        return host.streaming()

    def steps(self, times: list[float], numpy: Any) -> list[int]:
        """The steps of the host's clock (nanoseconds) to chunks from the device at `times`, as
        `feed` takes them (a time before the latest one is no step)."""
        assert self._last is not None
        now = numpy.array(times, dtype=numpy.float64)
        before = numpy.maximum.accumulate(numpy.concatenate(([self._last], now)))[:-1]
        steps: list[int] = (
            numpy.where(now > before, numpy.rint((now - before) * 1_000_000_000), 0).astype(numpy.int64).tolist()
        )
        return steps

    def stream(self, steps: list[int], outputs: list[int], *, apply: bool) -> int:
        """The host's clock through chunks from the device (`steps`: `steps` of their times),
        outputs[i] output frames completed by chunk i (`Host.streamed`): how many chunks pass with
        no deadline passing. `apply`: move the clocks (the caller then gives the same chunks to
        `streamed`, which moves the decoder's clock)."""
        host = self._host
        assert host is not None
        return host.streamed(steps, outputs[: len(steps)], apply=apply)

    def streamed(self, chunks: _Run, table: str, count: int, size: int) -> None:
        """The `chunks` from the device were `count` whole output frames of `table` (`size`
        bytes), decoded elsewhere: count them and move on as `feed` would have."""
        start = self._start
        assert start is not None
        side, out = self._in, self._out
        latest = max(chunks.times)
        assert self._last is not None
        self._last = max(self._last, latest)
        if out.last is not None and latest - start - out.last >= IDLE_TIMEOUT:
            out.last = None  # nothing held: the idle line releases nothing
        last = max(i for i, n in enumerate(chunks.sizes) if n)
        when = chunks.times[last]
        side.note(size - chunks.sizes[last], chunks.sizes[last], when - start, chunks.packets[last])
        assert side.fed == side.base + size
        side.base += size
        side.forget(side.base)
        self.counts[table] += count

    def _take(self) -> list[Message]:
        rows, self._rows = self._rows, []
        for side in (self._in, self._out):
            side.forget(min(side.base, side.damage.start) if side.damage.held else side.base)
        return rows

    @property
    def discarded(self) -> int:
        return self._in.discarded + self._out.discarded

    def _clock(self, now: float | None) -> float | None:
        if now is None:
            return None
        if self._start is None:
            self._start = self._last = now
        assert self._last is not None
        if self._host is not None and now > self._last:
            for event in self._host.advance(now - self._last):
                self._error(event)
        self._last = max(self._last, now)
        return now - self._start

    def _error(self, event: HostEvent, at: int | None = None, raw: bytes = b"") -> None:
        """A ProtocolError: an error line and a damaged row (at `at` in the inbound bytes, or, for
        an answer that never came, where the inbound bytes had reached)."""
        if not isinstance(event, ProtocolError):
            return
        when = event.at if self._start is not None else None
        stamp = "" if when is None else f" at {when:.6f} s"
        self.errors.append(f"{event.problem}{stamp}: {event.detail}")
        if at is None:
            self._damaged(
                Direction.INBOUND, self._in.fed, b"", when=when, reason=event.problem, detail=event.detail, packet=None
            )
        else:
            when, packet = self._in.packet_of(at + max(len(raw), 1) - 1)
            self._damaged(
                Direction.INBOUND, at, raw, when=when, reason=event.problem, detail=event.detail, packet=packet
            )

    def _damaged(
        self,
        direction: Direction,
        at: int,
        raw: bytes,
        *,
        when: float | None,
        reason: str,
        detail: str,
        packet: int | None,
    ) -> None:
        self.damage[reason] += 1
        self._rows.append(Message(when, direction, DAMAGED, at, raw, None, packet, reason, detail))

    def _region(self, side: _Splitter, direction: Direction, at: int, raw: bytes, reason: str) -> None:
        when, packet = side.packet_of(at + len(raw) - 1)
        self.regions.add(_DIRECTIONS[direction], at, len(raw), reason)
        detail = f"{len(raw)} bytes: {_REASONS[reason]}"
        self._damaged(direction, at, raw, when=when, reason=reason, detail=detail, packet=packet)

    def _message(self, direction: Direction, kind: str, at: int, event: StreamEvent, *, data: Any = None) -> None:
        side = self._in if direction == Direction.INBOUND else self._out
        when, packet = side.packet_of(at + len(event.raw) - 1)
        if kind == UNDETERMINED:
            name = _DIRECTIONS[direction]
            self.errors.append(f"{name} offset {at}: a {len(event.raw)}-byte frame no table in context explains")
        self.counts[kind] += 1
        self._rows.append(Message(when, direction, kind, at, event.raw, data, packet))

    # --- Device to host -------------------------------------------------------------------------

    def _inbound(self, at: int, event: StreamEvent | tuple[bytes, str]) -> None:
        if not isinstance(event, StreamEvent):
            self._region(self._in, Direction.INBOUND, at, *event)
            return
        if self._host is not None:
            found: HostEvent | None = None
            for result in self._host.receive(event.raw):
                if isinstance(result, Discarded):
                    continue
                if found is None and (not isinstance(result, ProtocolError) or result.raw == event.raw):
                    found = result
                else:
                    self._error(result)
            if isinstance(found, ProtocolError):
                self._error(found, at, event.raw)
            elif isinstance(found, Acknowledged | DataBlock | Output):
                data = found.data if isinstance(found, Output) else _payload(found, event)
                self._message(Direction.INBOUND, _kind(data), at, event, data=data)
                return
        kind, guessed = self._guess(event, Direction.INBOUND)
        self._message(Direction.INBOUND, kind, at, event, data=guessed)

    def _guess(self, event: StreamEvent, direction: Direction) -> tuple[str, Payload | PahrSentence | None]:
        """A message no context explains: its kind from its size and the output format given."""
        if event.sentence is not None:
            return SENTENCE_KIND, event.sentence
        frame = event.frame
        assert frame is not None
        if frame.message_type == MessageType.COMMAND:
            return _command_name(event.raw, INITIAL), None
        size = len(frame.payload)
        inbound = direction == Direction.INBOUND
        if inbound and self._output is not None and size == PAYLOADS[self._output].SIZE:
            return self._output, PAYLOADS[self._output].parse(frame.payload)
        candidates = (_INBOUND_SIZES if inbound else _OUTBOUND_SIZES).get(size, ())
        if len(candidates) == 1:
            return candidates[0], PAYLOADS[candidates[0]].parse(frame.payload)
        return UNDETERMINED, None

    # --- Host to device -------------------------------------------------------------------------

    def _outbound(self, at: int, event: StreamEvent | tuple[bytes, str]) -> None:
        if not isinstance(event, StreamEvent):
            self._region(self._out, Direction.OUTBOUND, at, *event)
            return
        frame = event.frame
        state = self._host.state if self._host is not None else INITIAL
        if frame is not None and frame.message_type == MessageType.COMMAND and len(frame.payload) == 1:
            if self._command is not None:  # a command that should have had a block
                self._send(self._command[0], None)
            name = _command_name(event.raw, state)
            if name in COMMANDS and COMMANDS[name].parameter_block is not None:
                self._command = (name, at)
            else:
                self._command = None
                self._send(name, None)
            self._message(Direction.OUTBOUND, name, at, event)
            return
        if frame is not None and self._command is not None:
            name = self._command[0]
            table = PAYLOADS[COMMANDS[name].parameter_block or ""]
            self._command = None
            if len(frame.payload) == table.SIZE:
                block = table.parse(frame.payload)
                self._send(name, block, event.raw)  # as sent: message type 0 or 1 (E5)
                self._message(Direction.OUTBOUND, table.NAME, at, event, data=block)
                return
            self._send(name, None)
        kind, data = self._guess(event, Direction.OUTBOUND)
        self._message(Direction.OUTBOUND, kind, at, event, data=data)

    def _send(self, command: str, block: Payload | None, frame: bytes | None = None) -> None:
        info = COMMANDS.get(command)
        if info is not None and info.starts_output is not None and not self._output_known:
            self._output = OUTPUT_FORMATS.get(info.starts_output)
        host = self._host
        if host is None or info is None:
            return
        for _attempt in range(2):
            try:
                if block is not None and frame is not None:
                    host.sent(command, block, frame=frame)
                else:
                    host.send(command, block)
            except IlahrsError:
                if not host.owed:
                    return  # the device ignores it in this state (E33), as the host does
                detail = f"no {', '.join(host.owed)} before the next command ({command})"
                self._error(ProtocolError(ErrorKind.TIMEOUT, MISSING, detail, host.owed[0], at=host.now))
                host.resync(host.state)
            else:
                return


_REASONS: Final = {
    BAD_CHECKSUM: "a frame or sentence whose checksum fails",
    BAD_RESERVED: "a frame whose reserved byte is not the AHRS's (E42)",
    TRUNCATED: "a frame or sentence cut short",
    NO_FRAME_START: "bytes that start no frame or sentence",
}


def _payload(found: Acknowledged | DataBlock, event: StreamEvent) -> Payload:
    if isinstance(found, DataBlock):
        return found.payload
    assert event.frame is not None
    return COMMAND_SET.acknowledgement.parse(event.frame.payload)


def _command_name(raw: bytes, state: str) -> str:
    try:
        code, names = decode_command(raw)
    except IlahrsError:
        return UNDETERMINED
    return command_event(code, state) or names[0]


def _kind(data: Payload | PahrSentence) -> str:
    return SENTENCE_KIND if isinstance(data, PahrSentence) else data.NAME


class RowWriter:
    """Writes Messages as text, CSV or JSON lines."""

    def __init__(self, out: TextIO, form: str, selected: Iterable[str], variant: Variant, *, raw: bool) -> None:
        self._out = out
        self._form = form
        self._variant = variant
        self._raw = raw
        self._columns = [*BASE_COLUMNS, *decode_columns(selected)]
        self._csv = csv.DictWriter(out, self._columns, extrasaction="ignore", lineterminator="\n")
        if form == "csv":
            self._csv.writeheader()

    def write(self, message: Message) -> None:
        fields = {} if message.data is None else row_fields(message.data, self._variant, raw=self._raw)
        stamp = None if message.time is None else round(message.time, 6)
        direction = _DIRECTIONS[message.direction]
        base: dict[str, object] = {"direction": direction, "kind": message.kind, "offset": message.offset}
        base.update(packet=message.packet, length=len(message.raw), reason=message.reason, detail=message.detail)
        if self._form == "csv":
            row: dict[str, object] = {"time": "" if stamp is None else f"{stamp:.6f}", **base, **fields}
            self._csv.writerow(row)
        elif self._form == "jsonl":
            entry: dict[str, object] = {"time": stamp, **base, "raw": message.raw.hex(), "fields": fields}
            self._out.write(json.dumps(entry) + "\n")
        else:
            head = "-" if stamp is None else f"{stamp:.6f}"
            body = " ".join(f"{k}={_text(v)}" for k, v in fields.items())
            if message.kind == DAMAGED:
                where = f"offset={message.offset} length={len(message.raw)}"
                where += "" if message.packet is None else f" packet={message.packet}"
                body = f"{message.reason} {where}: {message.detail}"
            elif message.data is None and message.kind == UNDETERMINED:
                body = message.raw.hex(" ")
            self._out.write(f"{head:>12} {direction:<3} {message.kind} {body}".rstrip() + "\n")


def _text(value: object) -> str:
    if value is None:
        return "-"
    if isinstance(value, float):
        return f"{value:.6g}"
    if isinstance(value, str):
        return value if value and " " not in value else json.dumps(value)
    return str(value)


class ColumnarCsv:
    """The CSV rows of a raw dump (device-to-host bytes, no context) as RowWriter writes those of
    CaptureDecoder(context=False), and its summary (`counts`, `damage`, `regions`, `discarded`,
    `errors`), decoded a window at a time into columns. `feed` bytes, then `finish`."""

    def __init__(
        self, out: TextIO, selected: Iterable[str], variant: Variant, *, raw: bool, output: str | None = None
    ) -> None:
        self._numpy = numpy_for("auto")
        self._scanner = Scanner(self._numpy, output=output)
        self._variant = variant
        self._raw = raw
        self._wanted = set(selected)
        self._columns = [*BASE_COLUMNS, *decode_columns(self._wanted)]
        self._csv = csv.writer(out, lineterminator="\n")
        self._csv.writerow(self._columns)
        self._blank = ("",) * (len(self._columns) - len(BASE_COLUMNS))
        self._pending: bytes = b""
        self._end = 0
        self._damage = _Damage()
        self.discarded = 0
        self.counts: Counter[str] = Counter()
        self.damage: Counter[str] = Counter()
        """Damaged rows by reason."""
        self.regions = _Regions()
        self.errors: list[str] = []
        self._values = _Values(self._numpy, variant, raw)

    def feed(self, data: bytes) -> None:
        buffer = self._pending + data if self._pending else data
        base = self._scanner.base
        for window in self._scanner.scan(buffer, final=False):
            self._window(window)
        self._discard(buffer, base)
        self._csv.writerows(row for _, row in self._damaged())
        self._pending = buffer[self._scanner.decided :]

    def finish(self) -> None:
        base = self._scanner.base
        for window in self._scanner.scan(self._pending, final=True):
            self._window(window)
        self._discard(self._pending, base)
        self._damage.close()
        self._csv.writerows(row for _, row in self._damaged())
        self._pending = b""

    def _discard(self, buffer: bytes, base: int) -> None:
        """The bytes decided after the last message (`buffer` starts at `base`) are damage."""
        total = self._scanner.base
        if total > self._end:
            self._gap(buffer, base, self._end, total)
            self._end = total

    def _gap(self, data: bytes | bytearray, base: int, start: int, end: int) -> None:
        self.discarded += end - start
        self._damage.add(start, memoryview(data)[start - base : end - base])

    def _damaged(self) -> list[tuple[int, Sequence[Any]]]:
        """The damaged rows decided so far, by offset."""
        rows: list[tuple[int, Sequence[Any]]] = []
        for at, raw, reason in self._damage.take():
            self.damage[reason] += 1
            self.regions.add("in", at, len(raw), reason)
            if DAMAGED in self._wanted:
                detail = f"{len(raw)} bytes: {_REASONS[reason]}"
                rows.append((at, ("", "in", DAMAGED, at, "", len(raw), reason, detail, *self._blank)))
        return rows

    def _window(self, window: Window) -> None:
        starts = window.starts.tolist() if self._numpy is not None else window.starts
        lengths = window.lengths.tolist() if self._numpy is not None else window.lengths
        self._gaps(window, starts, lengths)
        parts: list[tuple[list[int], Iterable[Sequence[Any]]]] = []
        seen: dict[str, list[int]] = {}
        errors: list[tuple[int, str]] = []
        for code, positions in window.groups().items():
            places = positions.tolist() if self._numpy is not None else positions
            if code in (COMMAND, UNEXPLAINED):
                names = [self._frame_kind(window, starts[i], lengths[i], code) for i in places]
                chosen: list[tuple[int, str]] = []
                for i, name in zip(places, names, strict=True):
                    seen.setdefault(name, [i, 0])[1] += 1
                    if name == UNDETERMINED:
                        errors.append(
                            (i, f"in offset {starts[i]}: a {lengths[i]}-byte frame no table in context explains")
                        )
                    if name in self._wanted:
                        chosen.append((i, name))
                if chosen:
                    made = [("", "in", name, starts[i], "", lengths[i], "", "", *self._blank) for i, name in chosen]
                    parts.append(([starts[i] for i, _ in chosen], made))
                continue
            name = KINDS[code]
            seen[name] = [places[0], len(places)]
            if name in self._wanted:
                at = [starts[i] for i in places]
                parts.append((at, self._rows(window, code, name, at, [lengths[i] for i in places])))
        for name, (_first, count) in sorted(seen.items(), key=lambda item: item[1][0]):
            self.counts[name] += count
        self.errors += [text for _, text in sorted(errors)]
        damaged = self._damaged()
        if len(parts) == 1 and not damaged:
            self._csv.writerows(parts[0][1])
        elif parts or damaged:
            ordered = [(at, row) for places, rows in parts for at, row in zip(places, rows, strict=True)]
            ordered.sort(key=lambda item: item[0])
            self._csv.writerows(row for _, row in sorted([*ordered, *damaged], key=lambda item: item[0]))

    def _gaps(self, window: Window, starts: list[int], lengths: list[int]) -> None:
        """The bytes between the messages of `window` are damage: each run ends at a message."""
        end = self._end
        damage = self._damage
        for start, length in zip(starts, lengths, strict=True):
            if start > end:
                self._gap(window.data, window.base, end, start)
            if damage.held:
                damage.close()
            end = start + length
        self._end = end

    @staticmethod
    def _frame_kind(window: Window, start: int, length: int, code: int) -> str:
        if code == UNEXPLAINED:
            return UNDETERMINED
        at = start - window.base
        return _command_name(bytes(window.data[at : at + length]), INITIAL)

    def _rows(
        self, window: Window, code: int, name: str, starts: list[int], lengths: list[int]
    ) -> Iterable[Sequence[Any]]:
        """The CSV rows of the messages of kind `code` starting at `starts`."""
        count = len(starts)
        if code == SENTENCE:
            made = [row_fields(window.sentences[at], self._variant, raw=self._raw) for at in starts]
            names = made[0] if made else {}
            values = {column: [row[column] for row in made] for column in names}
        else:
            values = self._table_values(window, PAYLOADS[name], starts)
        blank = [""] * count
        base = [blank, ["in"] * count, [name] * count, starts, blank, lengths, blank, blank]
        return zip(*base, *(values.get(c, blank) for c in self._columns[len(BASE_COLUMNS) :]), strict=True)

    def _table_values(self, window: Window, cls: type[Any], starts: list[int]) -> dict[str, list[Any]]:
        return self._values.of(window.data, window.base, cls, starts)


class _Values:
    """The CSV values of the fields of frames of one table, decoded as columns, as row_fields
    gives them (each distinct USW or calibration byte turned into text once)."""

    def __init__(self, numpy: Any, variant: Variant, raw: bool) -> None:
        self._numpy = numpy
        self._variant = variant
        self._raw = raw
        self._known: dict[Callable[[Any], object], dict[Any, object]] = {}

    def of(self, data: bytes | bytearray, base: int, cls: type[Any], starts: list[int]) -> dict[str, list[Any]]:
        """Each column's values for the frames of table `cls` at `starts` (`data` starts at `base`)."""
        if not _simple(cls):
            here = [at - base + PAYLOAD_OFFSET for at in starts]
            blocks = [cls.parse(data[at : at + cls.SIZE]) for at in here]
            made = [row_fields(block, self._variant, raw=self._raw) for block in blocks]
            return {column: [row[column] for row in made] for column in made[0]} if made else {}
        fields = scales(cls, None if self._raw else self._variant)
        if self._raw:
            fields = [(info, 1, None) for info, _, _ in fields]
        local = [at - base for at in starts]
        offsets = self._numpy.array(local, dtype=self._numpy.int64) if self._numpy is not None else local
        columns = table_columns(self._numpy, data, offsets, cls, fields)
        values: dict[str, list[Any]] = {}
        for info, _, _ in fields:
            column = columns[info.name].tolist()
            if info.encoding == "calibration_success":
                raw = self._raw
                values[ACCURACY] = [None] * len(column) if raw else self._mapped(column, _accuracy)
                column = column if raw else self._mapped(column, _outcome)
            elif not self._raw and info.encoding == "usw":
                column = self._mapped(column, _usw)
            values[info.name] = column
        return values

    def texts(self, data: bytes | bytearray, cls: type[Any], starts: list[int]) -> dict[str, list[Any]]:
        """`of` (`data` from 0) as csv.writer writes the values (`_csv_text`), each distinct
        value of a column written once (numpy; else as `of`)."""
        numpy = self._numpy
        if numpy is None or not _simple(cls):
            return {name: list(map(_csv_text, column)) for name, column in self.of(data, 0, cls, starts).items()}
        fields = scales(cls, None if self._raw else self._variant)
        if self._raw:
            fields = [(info, 1, None) for info, _, _ in fields]
        columns = table_columns(numpy, data, numpy.array(starts, dtype=numpy.int64), cls, fields)
        values: dict[str, list[Any]] = {}
        for info, _, _ in fields:
            distinct, where = numpy.unique(columns[info.name], return_inverse=True)
            known = distinct.tolist()
            if info.encoding == "calibration_success" and not self._raw:
                values[ACCURACY] = _spread(numpy, [_csv_text(_accuracy(v)) for v in known], where)
                values[info.name] = _spread(numpy, [_csv_text(_outcome(v)) for v in known], where)
                continue
            if info.encoding == "calibration_success":
                values[ACCURACY] = [""] * len(starts)
            if info.encoding == "usw" and not self._raw:
                values[info.name] = _spread(numpy, [_csv_text(_usw(v)) for v in known], where)
            else:
                values[info.name] = _spread(numpy, [str(v) for v in known], where)
        return values

    def _mapped(self, column: list[Any], function: Callable[[Any], object]) -> list[Any]:
        """`function` of each value, each distinct value computed once."""
        known = self._known.setdefault(function, {})
        known.update((value, function(value)) for value in set(column).difference(known))
        return list(map(known.__getitem__, column))


def _simple(cls: type[Any]) -> bool:
    """Whether the fields of `cls` are numbers with no encoding but the USW's and a calibration's."""
    simple = all(info.type == "reserved" or field_kind(info) in ("integer", "float") for info in cls.FIELDS)
    return simple and all(info.encoding in (None, "usw", "calibration_success") for info in cls.FIELDS)


def _spread(numpy: Any, texts: list[str], where: Any) -> list[str]:
    """texts[i] for each i in `where`."""
    result: list[str] = numpy.array(texts, dtype=object)[where].tolist()
    return result


class ColumnarCapture:
    """The CSV rows of a pcapng capture (both directions) as RowWriter writes those of
    CaptureDecoder(context=True), and its summary, with the device's continuous output decoded as
    columns. The CaptureDecoder follows the commands and every other message; while its host
    waits for nothing but the output its state streams (`Host.streaming`), the device's chunks
    are held (up to _STRETCH bytes, until a chunk from the host or an idle line) and decoded at
    once: the longest run of them whose bytes are whole output frames, back to back, ending with a
    chunk, and in which no deadline passes (`Host.streamed`). Whatever else the run holds (damage,
    another message, a frame across its end, a late output) goes message by message: the rows are
    those of CaptureDecoder either way. Needs numpy (else every chunk goes message by message)."""

    def __init__(
        self,
        out: TextIO,
        selected: Iterable[str],
        variant: Variant,
        *,
        raw: bool,
        output: str | None = None,
        output_known: bool = False,
        strict: bool = False,
        start: str | None = None,
    ) -> None:
        self.decoder = CaptureDecoder(
            context=True, output=output, output_known=output_known, strict=strict, start=start
        )
        self._numpy = numpy_for("auto")
        self._strict = strict
        self._wanted = set(selected)
        self._writer = RowWriter(out, "csv", self._wanted, variant, raw=raw)
        self._columns = [*BASE_COLUMNS, *decode_columns(self._wanted)]
        self._out = out
        self._values = _Values(self._numpy, variant, raw)
        self._held = _Run()
        self._last_in: float | None = None
        self._misses = 0

    @property
    def counts(self) -> Counter[str]:
        return self.decoder.counts

    @property
    def damage(self) -> Counter[str]:
        return self.decoder.damage

    @property
    def regions(self) -> _Regions:
        return self.decoder.regions

    @property
    def errors(self) -> list[str]:
        return self.decoder.errors

    @property
    def discarded(self) -> int:
        return self.decoder.discarded

    def feed(self, chunk: Chunk) -> None:
        inbound = chunk.direction == Direction.INBOUND and chunk.time is not None
        self._packet(chunk.time, inbound, chunk.data, chunk)

    def feed_packets(self, found: Packets) -> None:
        """`feed` of each of the packets `found` (directions INBOUND or OUTBOUND, numbered from
        found.first, as `Source.packets` gives them), with no object made for the packets the
        columns decode."""
        data, ends, stamps, directions = found.data, found.ends, found.stamps, found.directions
        number = found.first
        start = index = 0
        count = len(ends)
        inbound = Direction.INBOUND
        while index < count:
            end = ends[index]
            when = stamps[index] / 1_000_000
            held = self._held
            if held.sizes and directions[index] == inbound:
                # `_packet` of each packet while held ones are: the same rule, without calls.
                origin = self.decoder.start
                assert origin is not None
                last = self._last_in
                pieces, sizes, times, numbers = held.pieces, held.sizes, held.times, held.packets
                total = held.total
                while total < _STRETCH:
                    if last is None:
                        if self.decoder.in_idle(when):
                            break
                    elif (when - origin) - (last - origin) >= IDLE_TIMEOUT:
                        break
                    pieces.append(data[start:end])
                    sizes.append(end - start)
                    times.append(when)
                    numbers.append(number + index)
                    total += end - start
                    if end > start:
                        last = when
                    start = end
                    index += 1
                    if index == count or directions[index] != inbound:
                        break
                    end = ends[index]
                    when = stamps[index] / 1_000_000
                held.total = total
                self._last_in = last
                if index == count:
                    break
                end = ends[index]
                when = stamps[index] / 1_000_000
            self._packet(when, directions[index] == inbound, data[start:end], None, number + index)
            start = end
            index += 1

    def _packet(
        self, when: float | None, inbound: bool, data: bytes, chunk: Chunk | None, number: int | None = None
    ) -> None:
        held = self._held
        if held.sizes:
            if inbound and held.total < _STRETCH and not self._idle(when):
                self._hold(when, data, chunk.packet if chunk is not None else number)
                return
            self._flush()
        if inbound and self._numpy is not None and self._streaming() is not None and not self._idle(when):
            self._hold(when, data, chunk.packet if chunk is not None else number)
            return
        if chunk is None:
            chunk = Chunk(when, Direction.INBOUND if inbound else Direction.OUTBOUND, data, number)
        self._write(self.decoder.feed(chunk))

    def finish(self) -> None:
        self._flush()
        self._write(self.decoder.finish())

    def _hold(self, when: float | None, data: bytes, packet: int | None) -> None:
        assert when is not None
        self._held.add(when, data, packet)
        if data:
            self._last_in = when

    def _idle(self, when: float | None) -> bool:
        """Whether the device's line was idle before a chunk at `when` (E41): a message cannot span it."""
        decoder = self.decoder
        last = self._last_in if self._held.sizes else None
        if last is None or decoder.start is None:
            return decoder.in_idle(when)
        assert when is not None
        return (when - decoder.start) - (last - decoder.start) >= IDLE_TIMEOUT

    def _write(self, messages: list[Message]) -> None:
        wanted = self._wanted
        for message in messages:
            if message.kind in wanted:
                self._writer.write(message)

    def _streaming(self) -> str | None:
        return self.decoder.streaming()

    def _flush(self) -> None:
        held, self._held, self._last_in = self._held, _Run(), None
        while held.sizes:
            done = self._columnar(held)
            if done:
                self._misses = 0
                held = held.after(done)
                continue
            self._misses += 1
            slow = min(len(held.sizes), 1 << min(self._misses, 12))  # damage: fewer rescans of the same bytes
            for chunk in held.chunks(slow):
                self._write(self.decoder.feed(chunk))
            held = held.after(slow)

    def _columnar(self, held: _Run) -> int:
        """Decode the leading chunks of `held` as columns, if they are whole output frames that
        arrive in time; how many chunks were decoded (0: none)."""
        decoder = self.decoder
        numpy = self._numpy
        table = decoder.streaming()
        if table is None or numpy is None:
            return 0
        cls = PAYLOADS[table]
        data = held.joined()
        scanner = Scanner(numpy, sentences=False, output=table, strict=self._strict)
        windows = scanner.scan(data, final=True)
        if not windows:
            return 0
        starts = numpy.concatenate([w.starts for w in windows])
        lengths = numpy.concatenate([w.lengths for w in windows])
        types = numpy.concatenate([w.types for w in windows])
        ends = starts + lengths
        kinds = numpy.concatenate([w.kinds for w in windows])
        good = (types == int(MessageType.DATA)) & (kinds == KINDS.index(table))
        good[1:] &= starts[1:] == ends[:-1]
        if len(starts):
            good[0] &= int(starts[0]) == 0
        bad = numpy.flatnonzero(~good)
        count = int(bad[0]) if len(bad) else len(starts)
        if not count:
            return 0
        chunk_ends = numpy.cumsum(numpy.array(held.sizes, dtype=numpy.int64))
        aligned = numpy.flatnonzero(numpy.isin(chunk_ends, ends[:count]) & (chunk_ends > 0))
        if not len(aligned):
            return 0
        used = int(aligned[-1]) + 1
        arrived = numpy.searchsorted(chunk_ends, ends[:count] - 1, side="right")
        per_chunk = numpy.bincount(arrived, minlength=used)[:used].tolist()
        steps = decoder.steps(held.times[:used], numpy)
        used = decoder.stream(steps, per_chunk, apply=False)
        aligned = aligned[aligned < used]
        if not len(aligned):
            return 0
        used = int(aligned[-1]) + 1
        total = int(chunk_ends[used - 1])
        count = int(numpy.searchsorted(ends[:count], total, side="right"))
        base = decoder.inbound_bytes
        taken = held.first(used)
        decoder.stream(steps[:used], per_chunk[:used], apply=True)
        decoder.streamed(taken, table, count, total)
        if table in self._wanted:
            found = {"starts": starts[:count], "lengths": lengths[:count], "arrived": arrived[:count]}
            self._rows(data, taken, **found, cls=cls, base=base)
        return used

    def _rows(
        self, data: bytes, taken: _Run, *, starts: Any, lengths: Any, arrived: Any, cls: type[Any], base: int
    ) -> None:
        """The CSV rows of the output frames at `starts` in `data` (the bytes of `taken`, from
        `base` in the device's bytes), each in the chunk `arrived` says."""
        start = self.decoder.start
        assert start is not None
        at = arrived.tolist()
        times, packets = taken.times, taken.packets
        stamps = {i: f"{round(times[i] - start, 6):.6f}" for i in set(at)}
        local = starts.tolist()
        values = self._values.texts(data, cls, local)
        columns: list[list[str]] = [
            [stamps[i] for i in at],
            list(map(str, [base + offset for offset in local])),
            [str(packets[i]) for i in at] if None not in packets else [_csv_text(packets[i]) for i in at],
            list(map(str, lengths.tolist())),
        ]
        # A row is its values and constant fields joined by commas; each run of constant fields is
        # one item (repeated), so each row joins few items.
        layout: list[Any] = [columns[0], "in", _csv_text(cls.NAME), *columns[1:], "", ""]
        for name in self._columns[len(BASE_COLUMNS) :]:
            layout.append(values.get(name, ""))
        items: list[Any] = []
        for item in layout:
            if isinstance(item, str) and items and isinstance(items[-1], str):
                items[-1] += "," + item
            else:
                items.append(item)
        count = len(at)
        rows = zip(*([item] * count if isinstance(item, str) else item for item in items), strict=True)
        self._out.write("".join([",".join(row) + "\n" for row in rows]))


class _Run:
    """Chunks from the device held to be decoded as columns: their bytes, sizes, times and
    packet numbers."""

    __slots__ = ("packets", "pieces", "sizes", "times", "total")

    def __init__(self) -> None:
        self.pieces: list[bytes] = []
        self.sizes: list[int] = []
        self.times: list[float] = []
        self.packets: list[int | None] = []
        self.total = 0

    def add(self, when: float, data: bytes, packet: int | None) -> None:
        self.pieces.append(data)
        self.sizes.append(len(data))
        self.times.append(when)
        self.packets.append(packet)
        self.total += len(data)

    def joined(self) -> bytes:
        """The bytes of every chunk, back to back."""
        if len(self.pieces) != 1:
            self.pieces = [b"".join(self.pieces)]
        return self.pieces[0]

    def first(self, count: int) -> _Run:
        """The first `count` chunks."""
        return self._part(0, count)

    def after(self, count: int) -> _Run:
        """The chunks after the first `count`."""
        return self._part(count, len(self.sizes))

    def _part(self, low: int, high: int) -> _Run:
        run = _Run()
        start = sum(self.sizes[:low])
        run.sizes, run.times, run.packets = self.sizes[low:high], self.times[low:high], self.packets[low:high]
        run.total = sum(run.sizes)
        run.pieces = [self.joined()[start : start + run.total]]
        return run

    def chunks(self, count: int) -> list[Chunk]:
        """The first `count` chunks as Chunks."""
        data = self.joined()
        result: list[Chunk] = []
        start = 0
        for size, when, packet in zip(self.sizes[:count], self.times, self.packets, strict=False):
            result.append(Chunk(when, Direction.INBOUND, data[start : start + size], packet))
            start += size
        return result


def _csv_text(value: object) -> str:
    """One field as csv.writer (QUOTE_MINIMAL, lineterminator \\n) writes it."""
    if value is None:
        return ""
    text = str(value)
    if any(c in text for c in ',"\n\r'):
        return '"' + text.replace('"', '""') + '"'
    return text


_STRETCH: Final = 1 << 20
"""Bytes of the device's output held before they are decoded as columns."""


class _Regions:
    """The damaged regions of bytes, for the summary: how many, how many bytes, the first few."""

    def __init__(self) -> None:
        self.count = 0
        self.listed: list[str] = []

    def add(self, direction: str, offset: int, length: int, reason: str) -> None:
        self.count += 1
        if len(self.listed) < _LISTED:
            self.listed.append(f"{direction} offset {offset} ({length} {reason})")


class Progress:
    """A progress line on stderr for a large file, when stderr is a terminal."""

    def __init__(self, source: Source, stream: TextIO = sys.stderr, clock: Callable[[], float] = time.monotonic):
        size = source.size
        self._on = size is not None and size >= _PROGRESS_SIZE and stream.isatty()
        self._source = source
        self._stream = stream
        self._clock = clock
        self._next = clock()

    def update(self) -> None:
        if not self._on or self._clock() < self._next:
            return
        self._next = self._clock() + _PROGRESS_PERIOD
        size = self._source.size or 1
        done = self._source.position
        self._stream.write(f"\rdecoding {self._source.name}: {100 * done // size}% of {size >> 20} MiB")
        self._stream.flush()

    def done(self) -> None:
        if self._on:
            self._stream.write("\r\033[K")
            self._stream.flush()


def summary(decoder: CaptureDecoder | ColumnarCsv | ColumnarCapture, prog: str) -> list[str]:
    """The lines of the summary: messages per kind, discarded bytes in damaged regions (the first
    with their offsets and reasons), damaged rows per reason, errors."""
    total = sum(decoder.counts.values())
    per_kind = ", ".join(f"{kind} {count}" for kind, count in decoder.counts.most_common())
    lines = [f"{prog}: {total} messages" + (f" ({per_kind})" if per_kind else "")]
    regions = decoder.regions
    if regions.count:
        listed = ", ".join(regions.listed)
        more = f" and {regions.count - len(regions.listed)} more" if regions.count > len(regions.listed) else ""
        lines.append(f"{prog}: {decoder.discarded} bytes discarded in {regions.count} regions: {listed}{more}")
    else:
        lines.append(f"{prog}: {decoder.discarded} bytes discarded")
    damaged = sum(decoder.damage.values())
    per_reason = ", ".join(f"{reason} {count}" for reason, count in decoder.damage.most_common())
    lines.append(f"{prog}: {damaged} damaged" + (f" ({per_reason})" if per_reason else ""))
    lines.append(f"{prog}: {len(decoder.errors)} decode errors")
    lines += [f"{prog}:   {error}" for error in decoder.errors[:_LISTED]]
    if len(decoder.errors) > _LISTED:
        lines.append(f"{prog}:   and {len(decoder.errors) - _LISTED} more")
    return lines


# --- the subcommand -------------------------------------------------------------------------------


def add_parser(commands: argparse._SubParsersAction[OneLineParser]) -> OneLineParser:
    dec = commands.add_parser("decode", help="decode a capture (pcapng or raw bytes) to text, CSV or JSON lines")
    dec.add_argument("file", metavar="FILE", help="pcapng file or raw byte dump; - for standard input")
    dec.add_argument("--to", choices=FORMATS, default="text", help="output format (default text)")
    dec.add_argument("--types", metavar="KIND,...", help=f"only these kinds of rows (default all): {words(kinds())}")
    variant_argument(dec)
    dec.add_argument("--raw", action="store_true", help="raw field values instead of engineering units")
    dec.add_argument("--follow", action="store_true", help="keep reading a growing file (Ctrl-C ends)")
    strict_argument(dec)
    starting = ", ".join(n for n, i in COMMANDS.items() if i.starts_output is not None)
    dec.add_argument(
        "--output-format",
        metavar="COMMAND",
        help=f"the command that started the output ({starting}); a capture that begins with the device's"
        " output is decoded as if that command had been sent before it",
    )
    return dec


def run(args: argparse.Namespace) -> int:
    """`ilahrs decode`."""
    valid = kinds()
    selected = [lookup("message kind", k.strip(), valid) for k in args.types.split(",")] if args.types else valid
    variant_named(args.variant)  # a wrong name is refused before the capture is opened
    table = output_table(args.output_format) if args.output_format else None
    source = open_source(args.file)
    if args.to == "csv" and source.kind == "raw" and not args.follow and not args.strict:
        return _decode_columns(args, source, selected, table)
    if args.to == "csv" and source.kind == "pcapng" and not args.follow:
        return _decode_capture_columns(args, source, selected, table)
    return _decode_messages(args, source, selected, table)


def _decode_messages(args: argparse.Namespace, source: Source, selected: list[str], table: str | None) -> int:
    """`_decode` message by message, following the commands in a pcapng capture."""
    variant = variant_named(args.variant)
    known = args.output_format is not None
    context = source.kind == "pcapng"
    start = args.output_format if known else None
    decoder = CaptureDecoder(context=context, output=table, output_known=known, strict=args.strict, start=start)
    writer = RowWriter(sys.stdout, args.to, selected, variant, raw=args.raw)
    wanted = set(selected)

    def feed(chunk: Chunk) -> None:
        for message in decoder.feed(chunk):
            if message.kind in wanted:
                writer.write(message)

    def finish() -> None:
        for message in decoder.finish():
            if message.kind in wanted:
                writer.write(message)

    failure = _drive(source, feed, finish, follow=args.follow)
    if failure is not None:
        raise failure  # alone: a summary of a capture cut short would read as the whole
    for line in summary(decoder, "ilahrs decode"):
        print(line, file=sys.stderr)
    return 0


def _decode_columns(args: argparse.Namespace, source: Source, selected: list[str], table: str | None) -> int:
    """`_decode` of a raw dump to CSV, a window at a time through ilahrs.columnar (lenient decoding
    only: `--strict` goes message by message)."""
    decoder = ColumnarCsv(sys.stdout, selected, variant_named(args.variant), raw=args.raw, output=table)
    failure = _drive(source, lambda chunk: decoder.feed(chunk.data), decoder.finish, follow=False)
    if failure is not None:
        raise failure
    for line in summary(decoder, "ilahrs decode"):
        print(line, file=sys.stderr)
    return 0


def _decode_capture_columns(args: argparse.Namespace, source: Source, selected: list[str], table: str | None) -> int:
    """`_decode` of a pcapng capture to CSV: the commands and every other message one by one, the
    device's continuous output a stretch at a time through ilahrs.columnar (ColumnarCapture)."""
    known = args.output_format is not None
    decoder = ColumnarCapture(
        sys.stdout,
        selected,
        variant_named(args.variant),
        raw=args.raw,
        output=table,
        output_known=known,
        strict=args.strict,
        start=args.output_format if known else None,
    )
    failure = _drive(source, decoder.feed_packets, decoder.finish, follow=False, packets=True)
    if failure is not None:
        raise failure
    for line in summary(decoder, "ilahrs decode"):
        print(line, file=sys.stderr)
    return 0


def _drive(
    source: Source, feed: Callable[[Any], None], finish: Callable[[], None], *, follow: bool, packets: bool = False
) -> CliError | None:
    """Every chunk of `source` to `feed` with progress shown, then `finish`; Ctrl-C ends the input; a
    closed pipe (BrokenPipeError) goes on to `ilahrs.__main__.main`, as in every subcommand. Returns
    the error that cut the capture short, if any (the messages before it are written).
    `packets`: feed the packets of a pcapng file as arrays (`Source.packets`), not as Chunks."""
    progress = Progress(source)
    failure: CliError | None = None
    try:
        try:
            for chunk in source.packets() if packets else source.chunks(follow=follow):
                feed(chunk)
                progress.update()
                if follow:
                    sys.stdout.flush()
        except KeyboardInterrupt:
            pass
        except CliError as exc:
            failure = exc
        finish()
        sys.stdout.flush()
    finally:
        progress.done()
        source.close()
    return failure
