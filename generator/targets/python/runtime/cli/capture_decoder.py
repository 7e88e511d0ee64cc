"""`CaptureDecoder`: the chunks of a capture in, the Messages of `ilahrs decode` out, told apart
by context as the host session does (a `Host` follows the commands of a two-direction capture),
with every damaged region and every protocol error as a damaged row; `Run`, chunks from the device
held to be decoded elsewhere as whole output frames (`CaptureDecoder.streamed`)."""

from __future__ import annotations

from collections import Counter
from collections.abc import Callable, Iterable
from typing import Any, Final

from ..bulk import tables_by_size
from ..codec import Payload
from ..commands import COMMAND_SET, COMMANDS
from ..errors import ErrorKind, IlahrsError
from ..frame import MessageType
from ..nmea import PahrSentence
from ..payloads import PAYLOADS
from ..pcapng import Direction
from ..session.host import Acknowledged, DataBlock, Discarded, Host, HostEvent, Output, ProtocolError
from ..statemachine import INITIAL, OUTPUT_FORMATS
from ..stream import IDLE_TIMEOUT, StreamEvent
from .capture import Chunk
from .common import SENTENCE_KIND
from .damage import MISSING, REASONS, Regions, Splitter
from .rows import DAMAGED, DIRECTIONS, UNDETERMINED, Message, command_name

__all__ = ["CaptureDecoder", "Run"]


_INBOUND_SIZES: Final = tables_by_size("device_to_host")
_OUTBOUND_SIZES: Final = tables_by_size("host_to_device")


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
        self._in = Splitter(strict)
        self._out = Splitter()
        self._command: tuple[str, int] | None = None
        self._start: float | None = None
        self._last: float | None = None
        self._rows: list[Message] = []
        self.counts: Counter[str] = Counter()
        self.damage: Counter[str] = Counter()
        """Damaged rows by reason."""
        self.regions = Regions()
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

    def writing(
        self, write: Callable[[Message], None], kinds: Iterable[str]
    ) -> tuple[Callable[[Chunk], None], Callable[[], None]]:
        """`feed` and `finish` that hand every Message of one of `kinds` to `write`, in order."""
        wanted = set(kinds)

        def feed(chunk: Chunk) -> None:
            for message in self.feed(chunk):
                if message.kind in wanted:
                    write(message)

        def finish() -> None:
            for message in self.finish():
                if message.kind in wanted:
                    write(message)

        return feed, finish

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

    def streamed(self, chunks: Run, table: str, count: int, size: int) -> None:
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
        sizes = chunks.sizes
        last = len(sizes) - 1
        while not sizes[last]:  # the last chunk with bytes
            last -= 1
        when = chunks.times[last]
        side.note(size - sizes[last], sizes[last], when - start, chunks.packets[last])
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

    def _region(self, side: Splitter, direction: Direction, at: int, raw: bytes, reason: str) -> None:
        when, packet = side.packet_of(at + len(raw) - 1)
        self.regions.add(DIRECTIONS[direction], at, len(raw), reason)
        detail = f"{len(raw)} bytes: {REASONS[reason]}"
        self._damaged(direction, at, raw, when=when, reason=reason, detail=detail, packet=packet)

    def _message(self, direction: Direction, kind: str, at: int, event: StreamEvent, *, data: Any = None) -> None:
        side = self._in if direction == Direction.INBOUND else self._out
        when, packet = side.packet_of(at + len(event.raw) - 1)
        if kind == UNDETERMINED:
            name = DIRECTIONS[direction]
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
            return command_name(event.raw, INITIAL), None
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
            name = command_name(event.raw, state)
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


def _payload(found: Acknowledged | DataBlock, event: StreamEvent) -> Payload:
    if isinstance(found, DataBlock):
        return found.payload
    assert event.frame is not None
    return COMMAND_SET.acknowledgement.parse(event.frame.payload)


def _kind(data: Payload | PahrSentence) -> str:
    return SENTENCE_KIND if isinstance(data, PahrSentence) else data.NAME


class Run:
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

    def first(self, count: int) -> Run:
        """The first `count` chunks."""
        return self._part(0, count)

    def after(self, count: int) -> Run:
        """The chunks after the first `count`."""
        return self._part(count, len(self.sizes))

    def _part(self, low: int, high: int) -> Run:
        run = Run()
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
