# Copied from generator/targets/python/runtime/cli_decode.py for spec/ilahrs.yaml,
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

Rows: `time` (seconds since the first chunk of the capture; empty in a raw dump), `direction`
(in: device to host, out: host to device), `kind` (a payload table's name, a command's name,
PAHR for a $PAHR sentence, frame for a frame whose table cannot be told), `offset` (of the
message's first byte in the bytes of its direction), then every field in engineering units (raw
values with `--raw`), the Unit Status Word as the names of its flags joined by '|'.
"""

from __future__ import annotations

import csv
import json
import sys
import time
from collections import Counter
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any, Final, TextIO

from .cli_capture import Chunk, Source
from .cli_common import SENTENCE_KIND, field_columns, fields_of, lookup, usw_text
from .codec import Payload, field_kind
from .columnar import (
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
from .commands import COMMAND_SET, COMMANDS, decode_command
from .encodings import Variant, calibration_accuracy_deg, calibration_succeeded
from .errors import IlahrsError
from .frame import PAYLOAD_OFFSET, MessageType
from .host import Acknowledged, DataBlock, Discarded, Host, HostEvent, Output, ProtocolError
from .nmea import PahrSentence
from .payloads import PAYLOADS
from .pcapng import Direction
from .statemachine import INITIAL, OUTPUT_FORMATS, command_event
from .stream import StreamDecoder, StreamEvent

__all__ = ["FORMATS", "UNDETERMINED", "CaptureDecoder", "ColumnarCsv", "Message", "RowWriter", "kinds", "output_table"]

UNDETERMINED: Final = "frame"
"""The kind of a frame whose table the context does not tell."""
FORMATS: Final = ("text", "csv", "jsonl")
BASE_COLUMNS: Final = ("time", "direction", "kind", "offset")
"""The first columns of every CSV row; the fields of the selected kinds follow."""
_DIRECTIONS: Final = {Direction.INBOUND: "in", Direction.OUTBOUND: "out"}
_PROGRESS_SIZE: Final = 8 << 20
_PROGRESS_PERIOD: Final = 0.5
_LISTED: Final = 10
"""Discarded runs and errors listed one by one in the summary."""


def kinds() -> list[str]:
    """Every message kind a row can have."""
    return [*PAYLOADS, SENTENCE_KIND, *COMMANDS, UNDETERMINED]


def output_table(command: str) -> str | None:
    """The payload table of the output `command` starts (None: $PAHR sentences); CliError for a
    command that starts no output."""
    starting = [name for name, info in COMMANDS.items() if info.starts_output is not None]
    name = lookup("output command", command, starting)
    return OUTPUT_FORMATS[COMMANDS[name].starts_output or ""]


def _by_size(direction: str) -> Mapping[int, list[str]]:
    sizes: dict[int, list[str]] = {}
    for name, table in PAYLOADS.items():
        if direction == table.DIRECTION:
            sizes.setdefault(table.SIZE, []).append(name)
    return sizes


_INBOUND_SIZES: Final = _by_size("device_to_host")
_OUTBOUND_SIZES: Final = _by_size("host_to_device")


@dataclass(frozen=True, slots=True)
class Message:
    """One decoded message: when (seconds since the capture's first chunk), which way, what, where
    (offset in its direction's bytes), its bytes and its decoded payload or sentence."""

    time: float | None
    direction: Direction
    kind: str
    offset: int
    raw: bytes
    data: Payload | PahrSentence | None = None


class _Splitter:
    """A StreamDecoder that also says where each message and each discarded run starts."""

    def __init__(self, strict: bool = False) -> None:
        self.decoder = StreamDecoder(strict=strict)
        self.buffer = bytearray()
        self.base = 0
        self.runs: list[tuple[int, int]] = []
        self.discarded = 0

    def feed(self, data: bytes, *, final: bool = False) -> list[tuple[int, StreamEvent]]:
        events = self.decoder.finish() if final else self.decoder.feed(data)
        self.buffer += data
        decided = len(self.buffer) - self.decoder.pending
        pos = 0
        located: list[tuple[int, StreamEvent]] = []
        for event in events:
            at = self.buffer.find(event.raw, pos)
            self._gap(pos, at)
            located.append((self.base + at, event))
            pos = at + len(event.raw)
        self._gap(pos, decided)
        del self.buffer[:decided]
        self.base += decided
        return located

    def _gap(self, start: int, end: int) -> None:
        if end <= start:
            return
        self.discarded += end - start
        offset = self.base + start
        if self.runs and sum(self.runs[-1]) == offset:
            self.runs[-1] = (self.runs[-1][0], self.runs[-1][1] + end - start)
        else:
            self.runs.append((offset, end - start))


class CaptureDecoder:
    """Chunks in, Messages out. `context`: follow the commands seen in the capture with a Host;
    `output`: the table of the output started before the capture began (None: unknown); `strict`:
    refuse data frames from the device whose reserved byte is not the AHRS's (E42)."""

    def __init__(
        self, *, context: bool, output: str | None = None, output_known: bool = False, strict: bool = False
    ) -> None:
        self._host = Host(strict=strict) if context else None
        self._output = output
        self._output_known = output_known
        self._in = _Splitter(strict)
        self._out = _Splitter()
        self._command: tuple[str, int] | None = None
        self._start: float | None = None
        self._last: float | None = None
        self.counts: Counter[str] = Counter()
        self.errors: list[str] = []

    def feed(self, chunk: Chunk) -> list[Message]:
        when = self._clock(chunk.time)
        if chunk.direction == Direction.OUTBOUND:
            return [m for at, event in self._out.feed(chunk.data) for m in self._outbound(when, at, event)]
        return [self._inbound(when, at, event) for at, event in self._in.feed(chunk.data)]

    def finish(self) -> list[Message]:
        when = None if self._last is None or self._start is None else self._last - self._start
        messages = [self._inbound(when, at, event) for at, event in self._in.feed(b"", final=True)]
        self._out.feed(b"", final=True)
        return messages

    @property
    def discarded(self) -> int:
        return self._in.discarded + self._out.discarded

    def runs(self) -> list[tuple[str, int, int]]:
        """Discarded runs: (direction, offset, length)."""
        return [("in", *r) for r in self._in.runs] + [("out", *r) for r in self._out.runs]

    def _clock(self, now: float | None) -> float | None:
        if now is None:
            return None
        if self._start is None:
            self._start = self._last = now
        assert self._last is not None
        if self._host is not None and now > self._last:
            for event in self._host.advance(now - self._last):
                self._error(now - self._start, event)
        self._last = max(self._last, now)
        return now - self._start

    def _error(self, when: float | None, event: HostEvent) -> None:
        if isinstance(event, ProtocolError):
            stamp = "" if when is None else f" at {when:.6f} s"
            self.errors.append(f"{event.problem}{stamp}: {event.detail}")

    def _message(
        self, when: float | None, direction: Direction, kind: str, at: int, event: StreamEvent, *, data: Any = None
    ) -> Message:
        if kind == UNDETERMINED:
            side = _DIRECTIONS[direction]
            self.errors.append(f"{side} offset {at}: a {len(event.raw)}-byte frame no table in context explains")
        self.counts[kind] += 1
        return Message(when, direction, kind, at, event.raw, data)

    # --- Device to host -------------------------------------------------------------------------

    def _inbound(self, when: float | None, at: int, event: StreamEvent) -> Message:
        if self._host is not None:
            found: HostEvent | None = None
            for result in self._host.receive(event.raw):
                if isinstance(result, Discarded):
                    continue
                if found is None and (not isinstance(result, ProtocolError) or result.raw == event.raw):
                    found = result
                else:
                    self._error(when, result)
            if isinstance(found, ProtocolError):
                self._error(when, found)
            elif isinstance(found, Acknowledged | DataBlock | Output):
                data = found.data if isinstance(found, Output) else _payload(found, event)
                return self._message(when, Direction.INBOUND, _kind(data), at, event, data=data)
        kind, guessed = self._guess(event, Direction.INBOUND)
        return self._message(when, Direction.INBOUND, kind, at, event, data=guessed)

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
        candidates = (_INBOUND_SIZES if inbound else _OUTBOUND_SIZES).get(size, [])
        if len(candidates) == 1:
            return candidates[0], PAYLOADS[candidates[0]].parse(frame.payload)
        return UNDETERMINED, None

    # --- Host to device -------------------------------------------------------------------------

    def _outbound(self, when: float | None, at: int, event: StreamEvent) -> list[Message]:
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
            return [self._message(when, Direction.OUTBOUND, name, at, event)]
        if frame is not None and self._command is not None:
            name = self._command[0]
            table = PAYLOADS[COMMANDS[name].parameter_block or ""]
            self._command = None
            if len(frame.payload) == table.SIZE:
                block = table.parse(frame.payload)
                self._send(name, block)
                return [self._message(when, Direction.OUTBOUND, table.NAME, at, event, data=block)]
            self._send(name, None)
        kind, data = self._guess(event, Direction.OUTBOUND)
        return [self._message(when, Direction.OUTBOUND, kind, at, event, data=data)]

    def _send(self, command: str, block: Payload | None) -> None:
        info = COMMANDS.get(command)
        if info is not None and info.starts_output is not None and not self._output_known:
            self._output = OUTPUT_FORMATS.get(info.starts_output)
        host = self._host
        if host is None or info is None:
            return
        for _attempt in range(2):
            try:
                host.send(command, block)
            except IlahrsError:
                if not host.owed:
                    return  # the device ignores it in this state (E33), as the host does
                host.resync(host.state)
            else:
                return


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
        self._columns = [*BASE_COLUMNS, *field_columns(selected)]
        self._csv = csv.DictWriter(out, self._columns, extrasaction="ignore", lineterminator="\n")
        if form == "csv":
            self._csv.writeheader()

    def write(self, message: Message) -> None:
        fields = {} if message.data is None else fields_of(message.data, self._variant, raw=self._raw)
        stamp = None if message.time is None else round(message.time, 6)
        direction = _DIRECTIONS[message.direction]
        if self._form == "csv":
            row: dict[str, object] = {"time": "" if stamp is None else f"{stamp:.6f}", "direction": direction}
            row.update({"kind": message.kind, "offset": message.offset, **fields})
            self._csv.writerow(row)
        elif self._form == "jsonl":
            entry: dict[str, object] = {"time": stamp, "direction": direction, "kind": message.kind}
            entry.update({"offset": message.offset, "raw": message.raw.hex(), "fields": fields})
            self._out.write(json.dumps(entry) + "\n")
        else:
            head = "-" if stamp is None else f"{stamp:.6f}"
            body = " ".join(f"{k}={_text(v)}" for k, v in fields.items())
            if message.data is None and message.kind == UNDETERMINED:
                body = message.raw.hex(" ")
            self._out.write(f"{head:>12} {direction:<3} {message.kind} {body}".rstrip() + "\n")


def _text(value: object) -> str:
    if isinstance(value, float):
        return f"{value:.6g}"
    if isinstance(value, str):
        return value if value and " " not in value else json.dumps(value)
    return str(value)


class ColumnarCsv:
    """The CSV rows of a raw dump (device-to-host bytes, no context) as RowWriter writes those of
    CaptureDecoder(context=False), and its summary (`counts`, `runs()`, `discarded`, `errors`),
    decoded a window at a time into columns. `feed` bytes, then `finish`."""

    def __init__(
        self, out: TextIO, selected: Iterable[str], variant: Variant, *, raw: bool, output: str | None = None
    ) -> None:
        self._numpy = numpy_for("auto")
        self._scanner = Scanner(self._numpy, output=output)
        self._variant = variant
        self._raw = raw
        self._wanted = set(selected)
        self._columns = [*BASE_COLUMNS, *field_columns(self._wanted)]
        self._csv = csv.writer(out, lineterminator="\n")
        self._csv.writerow(self._columns)
        self._blank = ("",) * (len(self._columns) - len(BASE_COLUMNS))
        self._pending: bytes = b""
        self._end = 0
        self._runs: list[tuple[int, int]] = []
        self.discarded = 0
        self.counts: Counter[str] = Counter()
        self.errors: list[str] = []
        self._usw: dict[Any, object] = {}
        self._calibration: dict[Any, object] = {}

    def feed(self, data: bytes) -> None:
        buffer = self._pending + data if self._pending else data
        for window in self._scanner.scan(buffer, final=False):
            self._window(window)
        self._pending = buffer[self._scanner.decided :]

    def finish(self) -> None:
        for window in self._scanner.scan(self._pending, final=True):
            self._window(window)
        total = self._scanner.base
        self._pending = b""
        if total > self._end:
            self._gap(self._end, total - self._end)
            self._end = total

    def runs(self) -> list[tuple[str, int, int]]:
        """Discarded runs: (direction, offset, length)."""
        return [("in", *run) for run in self._runs]

    def _gap(self, offset: int, length: int) -> None:
        self.discarded += length
        self._runs.append((offset, length))

    def _window(self, window: Window) -> None:
        starts = window.starts.tolist() if self._numpy is not None else window.starts
        lengths = window.lengths.tolist() if self._numpy is not None else window.lengths
        end = self._end
        for start, length in zip(starts, lengths, strict=True):
            if start > end:
                self._gap(end, start - end)
            end = start + length
        self._end = end
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
                    parts.append(
                        ([i for i, _ in chosen], [("", "in", name, starts[i], *self._blank) for i, name in chosen])
                    )
                continue
            name = KINDS[code]
            seen[name] = [places[0], len(places)]
            if name in self._wanted:
                parts.append((places, self._rows(window, code, name, [starts[i] for i in places])))
        for name, (_first, count) in sorted(seen.items(), key=lambda item: item[1][0]):
            self.counts[name] += count
        self.errors += [text for _, text in sorted(errors)]
        if len(parts) == 1:
            self._csv.writerows(parts[0][1])
        elif parts:
            ordered = sorted((i, row) for places, rows in parts for i, row in zip(places, rows, strict=True))
            self._csv.writerows(row for _, row in ordered)

    @staticmethod
    def _frame_kind(window: Window, start: int, length: int, code: int) -> str:
        if code == UNEXPLAINED:
            return UNDETERMINED
        at = start - window.base
        return _command_name(bytes(window.data[at : at + length]), INITIAL)

    def _rows(self, window: Window, code: int, name: str, starts: list[int]) -> Iterable[Sequence[Any]]:
        """The CSV rows of the messages of kind `code` starting at `starts`."""
        count = len(starts)
        if code == SENTENCE:
            made = [fields_of(window.sentences[at], self._variant, raw=self._raw) for at in starts]
            names = made[0] if made else {}
            values = {column: [row[column] for row in made] for column in names}
        else:
            values = self._table_values(window, PAYLOADS[name], starts)
        base = [[""] * count, ["in"] * count, [name] * count, starts]
        blank = [""] * count
        return zip(*base, *(values.get(c, blank) for c in self._columns[len(BASE_COLUMNS) :]), strict=True)

    def _table_values(self, window: Window, cls: type[Any], starts: list[int]) -> dict[str, list[Any]]:
        """Each field's CSV values, as fields_of gives them."""
        simple = all(info.type == "reserved" or field_kind(info) in ("integer", "float") for info in cls.FIELDS)
        if not simple or any(info.encoding not in (None, "usw", "calibration_success") for info in cls.FIELDS):
            here = [at - window.base + PAYLOAD_OFFSET for at in starts]
            blocks = [cls.parse(window.data[at : at + cls.SIZE]) for at in here]
            made = [fields_of(block, self._variant, raw=self._raw) for block in blocks]
            return {info.name: [row[info.name] for row in made] for info in cls.FIELDS if info.type != "reserved"}
        fields = scales(cls, None if self._raw else self._variant)
        if self._raw:
            fields = [(info, 1, None) for info, _, _ in fields]
        local = [at - window.base for at in starts]
        offsets = self._numpy.array(local, dtype=self._numpy.int64) if self._numpy is not None else local
        columns = table_columns(self._numpy, window.data, offsets, cls, fields)
        values: dict[str, list[Any]] = {}
        for info, _, _ in fields:
            column = columns[info.name].tolist()
            if not self._raw and info.encoding == "usw":
                column = _mapped(column, usw_text, self._usw)
            elif not self._raw and info.encoding == "calibration_success":
                column = _mapped(column, _calibration, self._calibration)
            values[info.name] = column
        return values


def _mapped(column: list[Any], function: Callable[[Any], object], known: dict[Any, object]) -> list[Any]:
    """`function` of each value, each distinct value computed once (`known` keeps them)."""
    known.update((value, function(value)) for value in set(column).difference(known))
    return list(map(known.__getitem__, column))


def _calibration(raw: int) -> object:
    accuracy = calibration_accuracy_deg(raw)
    return accuracy if calibration_succeeded(raw) and accuracy is not None else raw


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


def summary(decoder: CaptureDecoder | ColumnarCsv, prog: str) -> list[str]:
    """The lines of the summary: messages per kind, discarded bytes with their offsets, errors."""
    total = sum(decoder.counts.values())
    per_kind = ", ".join(f"{kind} {count}" for kind, count in decoder.counts.most_common())
    lines = [f"{prog}: {total} messages" + (f" ({per_kind})" if per_kind else "")]
    runs = decoder.runs()
    if runs:
        listed = ", ".join(f"{side} offset {at} ({length})" for side, at, length in runs[:_LISTED])
        more = f" and {len(runs) - _LISTED} more" if len(runs) > _LISTED else ""
        lines.append(f"{prog}: {decoder.discarded} bytes discarded in {len(runs)} runs: {listed}{more}")
    else:
        lines.append(f"{prog}: 0 bytes discarded")
    lines.append(f"{prog}: {len(decoder.errors)} decode errors")
    lines += [f"{prog}:   {error}" for error in decoder.errors[:_LISTED]]
    if len(decoder.errors) > _LISTED:
        lines.append(f"{prog}:   and {len(decoder.errors) - _LISTED} more")
    return lines
