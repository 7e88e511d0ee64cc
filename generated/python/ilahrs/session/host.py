# Copied from generator/targets/python/runtime/session/host.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""The host session: the client side of the protocol, sans-I/O (h11 style).

The host builds commands and the parameter block that must follow them (E5, E13), and keeps track
of what the device owes it, from the same table the device model interprets
(`ilahrs.statemachine`): the answers to the last command (an acknowledgement carrying the
checksum of what was sent, E12; a data block of a known table; one output block), and what the
device sends as time passes in its state (the alignment block, output blocks, calibration
results). Every incoming frame is decoded by that context into the right payload class (a 50- or
52-byte block is only ever read as the table the context says, E7). An answer that is missing
(timed out on the host's own clock), wrong (an acknowledgement with another checksum) or
unexpected is reported as a ProtocolError; nothing is guessed.

>>> from ilahrs.session.device import Device
>>> host, device = Host(), Device(seed=1)
>>> answer = device.receive(host.send("ReadAHRSPar"))
>>> [type(event).__name__ for event in host.receive(answer)]
['DataBlock']

A capture or a line that is already streaming is decoded with a session that starts mid-stream:
`Host.mid_stream("AHRScont3")` believes the device is in the state where that command's output
flows and reads every block as its output format (`COMMANDS[command].starts_output`, whose payload
table is `OUTPUT_FORMATS[...]`, None for $PAHR sentences).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from typing import Final

from ..commands import COMMAND_SET, COMMANDS, build_command
from ..errors import ErrorKind, IlahrsError, brief, require_flag, require_seconds, suggest
from ..frame import Frame, MessageType
from ..machine import firmware_is_valid
from ..nmea import NMEA_MAX_RATE_HZ, PahrSentence
from ..payloads import PAYLOADS, Payload
from ..statemachine import (
    ACK,
    DEFAULT_ALIGNMENT_TIME_S,
    DEFAULT_UPDATE_RATE_HZ,
    INITIAL,
    OUTPUT,
    OUTPUT_FORMATS,
    OUTPUT_PREFIX,
    PARAMETER_BLOCK,
    STATES,
    TIMER_FIELDS,
    TIMER_IS_RATE,
    command_event,
    lookup,
    timer_transition,
)
from ..status import UnitStatusWord
from ..stream import IDLE_TIMEOUT_NS, StreamDecoder, StreamEvent

__all__ = [
    "DEFAULT_REPLY_TIMEOUT_S",
    "Acknowledged",
    "DataBlock",
    "Discarded",
    "Host",
    "HostEvent",
    "Output",
    "ProtocolError",
]

DEFAULT_REPLY_TIMEOUT_S: Final = 1.0
"""How long the host waits for an answer, and the margin it adds to timed events (covers the
0.5 s a calibration result may take, E38)."""
_NS: Final = 1_000_000_000
_USW_FIELDS: Final = {
    name: info.name for name, table in PAYLOADS.items() for info in table.FIELDS if info.encoding == "usw"
}
"""Payload table -> its USW field."""
_SENTENCE_USW: Final = next(name for name, kind, *_rest in PahrSentence._SPEC if kind == "hex")
"""The sentence's USW field."""


@dataclass(frozen=True, slots=True)
class Acknowledged:
    """The device acknowledged `message` (a command name, or the table of a parameter block) with
    the right checksum."""

    message: str
    checksum: int
    raw: bytes = b""
    at: float = field(default=0.0, compare=False)
    """Seconds on the receiver's clock when the event was reported (the Host's own clock;
    time.monotonic() in ilahrs.edge.serial)."""


@dataclass(frozen=True, slots=True)
class DataBlock:
    """A data block, decoded as the table the context says. `source`: the command or the event
    (alignment_done, accumulation_done ...) that made the device send it."""

    source: str
    payload: Payload
    raw: bytes = b""
    at: float = field(default=0.0, compare=False)
    """Seconds on the receiver's clock when the event was reported."""


@dataclass(frozen=True, slots=True)
class Output:
    """One block of the current output format: a payload object or a $PAHR sentence. `source`:
    the command or event that made the device send it; `late`: it arrived after the host left the
    state that sends it (it was in flight when the command went out)."""

    data: Payload | PahrSentence
    source: str = ""
    late: bool = False
    raw: bytes = b""
    at: float = field(default=0.0, compare=False)
    """Seconds on the receiver's clock when the event was reported."""

    @property
    def usw(self) -> UnitStatusWord:
        """The block's Unit Status Word."""
        if isinstance(self.data, PahrSentence):
            return UnitStatusWord(getattr(self.data, _SENTENCE_USW))
        return UnitStatusWord(getattr(self.data, _USW_FIELDS[self.data.NAME]))


@dataclass(frozen=True, slots=True)
class ProtocolError:
    """The device did not answer as the protocol says: `problem` is "missing" (nothing within the
    timeout), "wrong" (an acknowledgement with another checksum) or "unexpected" (a message
    nothing in the current state explains). `expected`: what the host was waiting for."""

    kind: ErrorKind
    problem: str
    detail: str
    expected: str | None = None
    raw: bytes | None = None
    source: str | None = None
    at: float = field(default=0.0, compare=False)
    """Seconds on the receiver's clock when the event was reported."""


@dataclass(frozen=True, slots=True)
class Discarded:
    """Received bytes that belong to no valid frame or sentence (noise, a broken message)."""

    count: int
    at: float = field(default=0.0, compare=False)
    """Seconds on the receiver's clock when the event was reported."""


HostEvent = Acknowledged | DataBlock | Output | ProtocolError | Discarded


@dataclass(slots=True)
class _Owed:
    item: str
    source: str
    checksum: int | None
    deadline: int


class Host:
    """The client side of one serial line.

    `send(command, block)` returns the bytes to write; `receive(data)` and `advance(seconds)`
    return HostEvents. `state` is the state the host believes the device is in (the table's
    names); `owed` lists what the device still owes for the last command. `firmware`: the
    device's firmware version, for the rows of the table that depend on it (E29). `state` and
    `output` (a command that starts output, or an output format) start the session mid-stream
    (see `mid_stream`). Every event carries `at`, the host's clock when it was reported.

    A message never spans an idle line (E41): when the host's clock passes IDLE_TIMEOUT after the
    last bytes received while the decoder holds some, `advance` gives them up (as `idle` does)
    and reports the messages found behind them as received then. `strict`: refuse data frames
    whose reserved byte is not the AHRS's (E42); they count as discarded bytes.
    """

    def __init__(
        self,
        *,
        firmware: str | None = None,
        reply_timeout: float = DEFAULT_REPLY_TIMEOUT_S,
        state: str = INITIAL,
        output: str | None = None,
        strict: bool = False,
    ) -> None:
        if firmware is not None and not firmware_is_valid(firmware):
            detail = f"{brief(firmware)} is not a firmware version such as 4.9.9.0"
            raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, "firmware", detail)
        self.firmware = firmware
        self.reply_timeout = require_seconds(reply_timeout, "reply_timeout")
        _check_state(state)
        self._decoder = StreamDecoder(strict=require_flag(strict, "strict"))
        self.strict = strict
        """Whether data frames with another reserved byte than the AHRS's are refused (E42)."""
        self._now = 0
        self._idle_at: int | None = None
        self._state = state
        self._owed: list[_Owed] = []
        self._target = state
        self._output: str | None = _output_format(output)
        self._timer_deadline: int | None = None
        self._timer_index = 0
        self._late_state: str | None = None
        self._late_until = 0
        self._settings: dict[str, float] = {}
        self._arm_timer()

    @classmethod
    def mid_stream(
        cls,
        command: str,
        *,
        firmware: str | None = None,
        reply_timeout: float = DEFAULT_REPLY_TIMEOUT_S,
        strict: bool = False,
    ) -> Host:
        """A session for a line that is already streaming the output `command` started (a capture
        that began mid-stream): in the state where that output flows, reading its format."""
        info = COMMANDS.get(command) if isinstance(command, str) else None
        if info is None or info.starts_output is None:
            detail = f"{brief(command)} is not a command that starts output{suggest(command, _STARTERS)}"
            raise IlahrsError(ErrorKind.UNKNOWN_COMMAND, None, None, detail)
        first = lookup(INITIAL, command, firmware)
        state = first.to if first is not None else INITIAL
        for _ in STATES:  # through the alignment to the state that sends output
            timed = timer_transition(state)
            if timed is None or timed[1].to == state:
                break
            state = timed[1].to
        return cls(firmware=firmware, reply_timeout=reply_timeout, state=state, output=command, strict=strict)

    @property
    def state(self) -> str:
        """The state the host believes the device is in."""
        return self._state

    @property
    def owed(self) -> tuple[str, ...]:
        """What the device still owes for the last command (ack, output, payload names)."""
        return tuple(o.item for o in self._owed)

    @property
    def pending(self) -> int:
        """Received bytes held while the decoder waits to decide on them."""
        return self._decoder.pending

    @property
    def output_format(self) -> str | None:
        """The output format the last start command chose."""
        return self._output

    @property
    def now(self) -> float:
        """Seconds on the host's clock."""
        return self._now / _NS

    def setting(self, timer: str) -> float:
        """What the host knows of a timer's parameter (alignment time, accumulation time in s;
        update rate in Hz): learned from blocks sent and parameter blocks read, else the default."""
        if not isinstance(timer, str) or timer not in TIMER_IS_RATE:
            detail = f"no timer {brief(timer)}{suggest(timer, TIMER_IS_RATE)}"
            raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, "timer", detail)
        default = DEFAULT_UPDATE_RATE_HZ if TIMER_IS_RATE.get(timer) else DEFAULT_ALIGNMENT_TIME_S
        return self._settings.get(timer, default)

    def resync(self, state: str = INITIAL) -> None:
        """Forget what is owed and believe the device is in `state` (after a Stop and a quiet line)."""
        _check_state(state, ErrorKind.UNEXPECTED_MESSAGE)
        self._owed = []
        self._late_state = None
        self._state = self._target = state
        self._arm_timer()

    def send(self, command: str, block: Payload | Mapping[str, object] | None = None) -> bytes:
        """The bytes of `command` (ICD name), followed by its parameter block if it takes one (a
        payload object or raw field values; a name its table does not have is refused, MALFORMED).
        Refused (IlahrsError UNEXPECTED_MESSAGE) while answers are owed, or if the device would
        ignore the command in its state (E33). Nothing is sent when an error is raised."""
        return self._send(command, block, None)

    def sent(self, command: str, block: Payload | Mapping[str, object] | None = None, *, frame: bytes) -> bytes:
        """`send` for a command someone else wrote (a capture being decoded), whose parameter block
        crossed the line as `frame`, whatever its message type (0 or 1, E5): the acknowledgement
        owed is checked against that frame's checksum (E12), not that of the type-1 frame `send`
        builds. Errors as `send`'s, and IlahrsError for a `frame` that is not a valid frame.
        Returns the bytes as they were sent.

        >>> from ilahrs.frame import Frame, MessageType
        >>> from ilahrs.payloads import CalibrationParameters
        >>> host, block = Host(), CalibrationParameters(accumulation_time=20)
        >>> data = host.sent("Start2DClb", block, frame=Frame(MessageType.COMMAND, block.build()).build())
        >>> host.owed, data[-2:] == Frame(MessageType.COMMAND, block.build()).build()[-2:]
        (('ack',), True)
        """
        return self._send(command, block, bytes(frame))

    def _send(self, command: str, block: Payload | Mapping[str, object] | None, sent: bytes | None) -> bytes:
        info = COMMANDS.get(command) if isinstance(command, str) else None
        if info is None:
            raise COMMAND_SET.unknown(command)
        if block is not None:
            block = COMMAND_SET.parameter_block(command, block)
        if self._owed:
            detail = f"still waiting for {', '.join(self.owed)}"
            raise IlahrsError(ErrorKind.UNEXPECTED_MESSAGE, None, None, detail)
        event = command_event(info.code, self._state) or command
        transition = lookup(self._state, event, self.firmware)
        if transition is None:
            detail = f"{command} is ignored in state {self._state} (E33)"
            raise IlahrsError(ErrorKind.UNEXPECTED_MESSAGE, None, None, detail)
        data = build_command(command)
        deadline = self._now + round(self.reply_timeout * _NS)
        owed = [_Owed(item, event, Frame.parse(data).checksum, deadline) for item in transition.send]
        target = transition.to
        expects = STATES[target].expects
        if expects is not None:
            if block is None or expects != block.NAME:
                got = "nothing" if block is None else block.NAME
                detail = f"{command} must be followed by a {expects} block, not {got} (E13)"
                raise IlahrsError(ErrorKind.UNEXPECTED_MESSAGE, None, None, detail)
            block_frame = Frame(MessageType.DATA, block.build()).build() if sent is None else sent
            after = lookup(target, PARAMETER_BLOCK, self.firmware)
            assert after is not None
            owed += [_Owed(item, block.NAME, Frame.parse(block_frame).checksum, deadline) for item in after.send]
            target = after.to
            data += block_frame
            self._learn(block)
        elif block is not None:
            raise IlahrsError(ErrorKind.UNEXPECTED_MESSAGE, None, None, f"{command} takes no parameter block")
        if info.starts_output is not None:
            self._output = info.starts_output
        self._owed = owed
        self._target = target
        if not owed:
            self._enter(target)
        return data

    def receive(self, data: bytes | bytearray | memoryview, *, within: float = 0.0) -> list[HostEvent]:
        """Bytes from the device -> events, in order (Discarded last, if any bytes were dropped).

        `within`: the bytes came at some moment of the next `within` seconds, as with a read that
        returns what arrived since the one before. They are matched first, so an answer among them
        counts before any deadline in that time; then the clock moves on by `within`, and the line
        counts as busy until then: the idle rule (E41) starts from the end, so bytes that came
        together are never given up for a quiet time that may have been before them."""
        seconds = require_seconds(within, "within")
        before = self._decoder.discarded
        events = self._messages(self._decoder.feed(data), before)
        if not len(data):
            return events + self.advance(seconds)
        if seconds:
            events += self._expire(self._now + round(seconds * _NS))
        self._idle_at = None if not self._decoder.pending or IDLE_TIMEOUT_NS is None else self._now + IDLE_TIMEOUT_NS
        return events

    def idle(self, quiet: float | None = None) -> list[HostEvent]:
        """The line has been quiet for `quiet` seconds since the last byte (None: it is idle). From
        IDLE_TIMEOUT on, the bytes held are given up (E41; StreamDecoder.idle) and the messages
        behind them reported, with a Discarded last; a shorter quiet time changes nothing."""
        before = self._decoder.discarded
        events = self._messages(self._decoder.idle(quiet), before)
        if not self._decoder.pending:
            self._idle_at = None
        return events

    def _messages(self, messages: list[StreamEvent], before: int) -> list[HostEvent]:
        events: list[HostEvent] = []
        for message in messages:
            events += self._message(message)
        dropped = self._decoder.discarded - before
        if dropped:
            events.append(Discarded(dropped))
        return self._stamped(events)

    def _stamped(self, events: list[HostEvent]) -> list[HostEvent]:
        now = self.now
        return [replace(event, at=now) for event in events] if now else events

    def advance(self, seconds: float) -> list[HostEvent]:
        """Let time pass on the host's clock; report answers that did not come in time, and what
        the line going idle releases (at the moment it went idle)."""
        target = self._now + round(require_seconds(seconds) * _NS)
        events: list[HostEvent] = []
        if self._idle_at is not None and self._idle_at <= target:
            events += self._expire(self._idle_at)
            events += self.idle()
        return events + self._expire(target)

    def _expire(self, now: int) -> list[HostEvent]:
        """Move the clock to `now`; report what was owed before it and did not come."""
        self._now = now
        events: list[HostEvent] = []
        if self._owed and self._owed[0].deadline < self._now:
            missing = ", ".join(self.owed)
            detail = f"no {missing} within {self.reply_timeout} s of {self._owed[0].source}"
            owed = self._owed[0]
            events.append(ProtocolError(ErrorKind.TIMEOUT, "missing", detail, owed.item, None, owed.source))
            self._owed = []
            self._enter(self._target)
        if self._overdue(self._now):
            timed = timer_transition(self._state)
            assert timed is not None
            event, transition = timed
            item = transition.send[self._timer_index] if transition.send else event
            detail = f"no {item} ({event}) in state {self._state}"
            events.append(ProtocolError(ErrorKind.TIMEOUT, "missing", detail, item, None, event))
            self._timer_done(transition.to)
        return self._stamped(events)

    def streaming(self) -> str | None:
        """The payload table of the output the device sends as time passes in the current state,
        when that is all the host waits for (nothing owed, the state's timer expects one output
        block at a time and stays in the state, no bytes held): then `streamed` stands for
        `advance` and `receive`. None otherwise (also for $PAHR output)."""
        timed = timer_transition(self._state)
        if self._owed or timed is None or self._output is None or self._decoder.pending or self._idle_at is not None:
            return None
        _event, transition = timed
        if tuple(transition.send) != (OUTPUT,) or transition.to != self._state or self._timer_index:
            return None
        return OUTPUT_FORMATS.get(self._output)

    def streamed(self, steps: list[int], outputs: list[int], *, apply: bool = True) -> int:
        """What `advance` and `receive` do while `streaming()` holds: at each step the clock moves
        on by steps[i] nanoseconds, then outputs[i] whole blocks of the output table arrive. The
        steps are applied up to the first at which a deadline would pass (where `advance` reports
        a missing output); returns how many were applied (all of them: nothing was reported).
        `apply` False: only count them, the session unchanged."""
        now, deadline = self._now, self._timer_deadline
        span = self._timer_span()
        watched = not self._owed  # `_overdue`, inline (nothing here changes what is owed): no call per step
        done = 0
        for step, count in zip(steps, outputs, strict=True):
            if step:
                if watched and deadline is not None and deadline < now + step:
                    break  # `advance` by this step would report the missing output
                now += step
            if count and span is not None:
                deadline = now + span  # as `receive` of an output re-arms the timer
            done += 1
        if apply:
            self._now, self._timer_deadline = now, deadline
        return done

    # --- Matching messages against what is owed --------------------------------------------------

    def _message(self, message: StreamEvent) -> list[HostEvent]:
        if self._owed:
            owed = self._owed[0]
            result = self._match(owed.item, owed.source, owed.checksum, message)
            if result is not None:
                self._owed.pop(0)
                if not self._owed:
                    self._enter(self._target)
                return [result]
        timed = timer_transition(self._state)
        if timed is not None and timed[1].send:
            event, transition = timed
            result = self._match(transition.send[self._timer_index], event, None, message)
            if result is not None:
                self._timer_index += 1
                if self._timer_index == len(transition.send):
                    self._timer_done(transition.to)
                return [result]
            following = timer_transition(transition.to) if transition.to != self._state else None
            if (
                following is not None
                and following[1].send
                and not self._owed
                and self._match(following[1].send[0], following[0], None, message) is not None
            ):
                missing = transition.send[self._timer_index]
                detail = f"{missing} never came: {following[0]} output arrived first"
                error = ProtocolError(ErrorKind.UNEXPECTED_MESSAGE, "missing", detail, missing, None, event)
                self._timer_done(transition.to)
                return [error, *self._message(message)]
        if self._late_state is not None and self._now <= self._late_until:
            late = timer_transition(self._late_state)
            if late is not None:
                for item in late[1].send:
                    result = self._match(item, late[0], None, message)
                    if isinstance(result, Output):
                        return [Output(result.data, result.source, True, result.raw)]
        expected = self._owed[0].item if self._owed else None
        detail = f"{_describe(message)} in state {self._state}"
        if expected is not None:
            detail += f" while waiting for {expected}"
        source = self._owed[0].source if self._owed else None
        return [ProtocolError(ErrorKind.UNEXPECTED_MESSAGE, "unexpected", detail, expected, message.raw, source)]

    def _match(self, item: str, source: str, checksum: int | None, message: StreamEvent) -> HostEvent | None:
        """The event if `message` is `item`; None if it is not."""
        frame = message.frame
        if item == OUTPUT or item.startswith(OUTPUT_PREFIX):
            mode = None if item == OUTPUT else item.removeprefix(OUTPUT_PREFIX)
            output = self._output_of(message)
            if output is None or (mode is not None and output.usw.mode != mode):
                return None
            return Output(output.data, source, False, message.raw)
        if frame is None or frame.message_type != MessageType.DATA:
            return None
        if item == ACK:
            cls = COMMAND_SET.acknowledgement
            if len(frame.payload) != cls.SIZE:
                return None
            ack = cls.parse(frame.payload)
            value = getattr(ack, cls.FIELDS[0].name)
            if checksum is not None and value != checksum:
                detail = f"acknowledgement of {source} carries {value:#06x}, sent {checksum:#06x} (E12)"
                return ProtocolError(ErrorKind.BAD_CHECKSUM, "wrong", detail, ACK, message.raw, source)
            return Acknowledged(source, value, message.raw)
        cls = PAYLOADS[item]
        if len(frame.payload) != cls.SIZE:
            return None
        payload = cls.parse(frame.payload)
        self._learn(payload)
        return DataBlock(source, payload, message.raw)

    def _output_of(self, message: StreamEvent) -> Output | None:
        if self._output is None:
            return None
        table = OUTPUT_FORMATS.get(self._output)
        if table is None:
            return Output(message.sentence) if message.sentence is not None else None
        frame = message.frame
        cls = PAYLOADS[table]
        if frame is None or frame.message_type != MessageType.DATA or len(frame.payload) != cls.SIZE:
            return None
        return Output(cls.parse(frame.payload))

    # --- State ---------------------------------------------------------------------------------

    def _enter(self, state: str) -> None:
        old = self._state
        if state != old:
            self._late_state, self._late_until = old, self._now + round(self.reply_timeout * _NS)
        self._state = state
        if not self._owed:  # a timed block that was in flight keeps the target of the command sent since
            self._target = state
        if state != old:
            self._arm_timer()

    def _timer_done(self, state: str) -> None:
        self._timer_index = 0
        if state == self._state:
            self._arm_timer()
        else:
            self._enter(state)

    def _overdue(self, now: int) -> bool:
        """The output-timer rule: whether, nothing being owed, the state's timer has expired by
        `now` (its item is then missing). `advance` and `streamed` both decide with it."""
        return not self._owed and self._timer_deadline is not None and self._timer_deadline < now

    def _arm_timer(self) -> None:
        self._timer_index = 0
        span = self._timer_span()
        self._timer_deadline = None if span is None else self._now + span

    def _timer_span(self) -> int | None:
        """How long (ns) the state's timer waits from its start or last item (None: no timer)."""
        timer = STATES[self._state].timer
        if timer is None:
            return None
        seconds = self.setting(timer)
        if TIMER_IS_RATE.get(timer):
            rate = seconds
            if self._output is not None and OUTPUT_FORMATS.get(self._output) is None:
                rate = min(rate, NMEA_MAX_RATE_HZ)
            seconds = 1.0 / rate
        return round((seconds + self.reply_timeout) * _NS)

    def _learn(self, block: Payload) -> None:
        """Remember the timer parameters a block carries (one the host sends or reads)."""
        raw = block.raw()
        for timer, (_table, name) in TIMER_FIELDS.items():
            value = raw.get(name)
            if isinstance(value, (int, float)) and value > 0:
                self._settings[timer] = float(value)


_STARTERS: Final = tuple(name for name, info in COMMANDS.items() if info.starts_output is not None)


def _check_state(state: object, kind: ErrorKind = ErrorKind.OUT_OF_RANGE) -> None:
    if not isinstance(state, str) or state not in STATES:
        detail = f"no state {brief(state)}{suggest(state, STATES)}"
        raise IlahrsError(kind, None, "state", detail)


def _output_format(output: object) -> str | None:
    """The output format of `output`: a command that starts output, or an output format name."""
    if output is None:
        return None
    if isinstance(output, str):
        info = COMMANDS.get(output)
        if info is not None and info.starts_output is not None:
            return info.starts_output
        if output in OUTPUT_FORMATS:
            return output
    detail = f"{brief(output)} is neither a command that starts output nor an output format"
    raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, "output", detail + suggest(output, [*_STARTERS, *OUTPUT_FORMATS]))


def _describe(message: StreamEvent) -> str:
    if message.sentence is not None:
        return "a $PAHR sentence"
    assert message.frame is not None
    kind = "command" if message.frame.message_type == MessageType.COMMAND else "data"
    return f"a {kind} frame with a {len(message.frame.payload)}-byte payload"
