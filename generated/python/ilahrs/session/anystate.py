# Copied from generator/targets/python/runtime/session/anystate.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""A command sent to a device whose state the host does not know (a new client on a device that
may be streaming, calibrating or asleep), sans-I/O.

The answer the device owes depends on its state, so it cannot be predicted: `AnyStateRequest`
makes one host session (`ilahrs.session.host.Host`) per state in which the command has a transition in
`ilahrs.statemachine` (and per output format, in states that send output), has each of them
send the command, and feeds every byte the device sends, and the time that passes, to all of
them. The device was in the state whose owed answers all arrived without a protocol error; when
several fit, the first in the table's order (idle first) is taken. Output formats whose blocks
have the same size cannot be told apart (E7): unless the caller names the format (`output`),
`Reply.formats` lists every one that fits. A command with no answer in
some state (LowPowerOff in sleep) cannot be told from a command the device ignored: after the
reply timeout, `Reply.state` is the first such state that what came fits.

>>> from ilahrs.session.device import Device
>>> device = Device(seed=1)
>>> request = AnyStateRequest("GetBIT")
>>> request.receive(device.receive(request.data))
>>> reply = request.reply()
>>> reply.state, [type(answer).__name__ for answer in reply.answers]
('idle', ['DataBlock'])
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Final

from ..commands import COMMAND_SET, COMMANDS
from ..errors import ErrorKind, IlahrsError, require_seconds
from ..payloads import Payload
from ..statemachine import INITIAL, OUTPUT, OUTPUT_FORMATS, OUTPUT_PREFIX, STATES, TRANSITIONS, command_event, lookup
from .host import DEFAULT_REPLY_TIMEOUT_S, Acknowledged, Host, HostEvent, Output, ProtocolError

__all__ = ["AnyStateRequest", "Reply", "states_hearing"]

_STREAMING: Final = frozenset(
    state
    for (state, _event), transition in TRANSITIONS.items()
    if any(item == OUTPUT or item.startswith(OUTPUT_PREFIX) for item in transition.send)
)
"""States in which the device sends blocks of the current output format."""


@dataclass(frozen=True, slots=True)
class Reply:
    """What a command sent in an unknown state brought back.

    `state`: the state the device was in, as its answers show; for a command that owes no answer
    there, the first such state that fits what came; None when no state that hears the command
    fits (the device ignored it, or did not answer at all). `answers`: the acknowledgements, data
    blocks and output blocks the command brought, in order. `silent`: every state that fits in
    which the command owes no answer (set only when nothing answered). `formats`: when the
    answers hold output blocks, every output format they fit (more than one: the blocks were
    decoded as the first, and only naming the format decides, E7). `received`: the bytes that
    came. `host`: the session of the fitting state after the command (the device's state now, its
    output format), None when no state fits."""

    command: str
    state: str | None
    answers: tuple[HostEvent, ...] = ()
    silent: tuple[str, ...] = ()
    formats: tuple[str, ...] = ()
    received: int = 0
    host: Host | None = field(default=None, compare=False, repr=False)


def states_hearing(command: str, firmware: str | None = None) -> tuple[str, ...]:
    """The states in which the device acts on `command` (a transition of its own, not the
    catch-all of a state waiting for a parameter block), idle first, then in the table's order."""
    info = COMMANDS.get(command) if isinstance(command, str) else None
    if info is None:
        raise COMMAND_SET.unknown(command)
    order = [INITIAL, *(state for state in STATES if state != INITIAL)]
    heard = []
    for state in order:
        transition = lookup(state, command_event(info.code, state) or command, firmware)
        if transition is not None and not transition.wildcard:
            heard.append(state)
    return tuple(heard)


@dataclass(slots=True)
class _Hypothesis:
    state: str
    host: Host
    owes: bool
    events: list[HostEvent] = field(default_factory=list)
    failed: bool = False

    @property
    def complete(self) -> bool:
        return not self.failed and not self.host.owed


class AnyStateRequest:
    """`command` (and its parameter block: a payload object or raw field values, for the states
    whose transition waits for one) to a device in an unknown state; `output`: the output format
    the device uses, or the command that started it (None: any). Write `data`, then give
    `receive` every byte the device sends and `advance` the time that passes (before the bytes it
    precedes), until `done`; `reply()` says what the device answered.

    IlahrsError: UNKNOWN_COMMAND for a name the table does not have; UNEXPECTED_MESSAGE when no
    state hears the command with (or without) a parameter block as given."""

    def __init__(
        self,
        command: str,
        block: Payload | Mapping[str, object] | None = None,
        *,
        firmware: str | None = None,
        reply_timeout: float = DEFAULT_REPLY_TIMEOUT_S,
        output: str | None = None,
    ) -> None:
        chosen = None if output is None else Host(output=output).output_format
        heard = states_hearing(command, firmware)
        info = COMMANDS[command]
        payload = None if block is None else COMMAND_SET.parameter_block(command, block)
        self.command = command
        self.reply_timeout = require_seconds(reply_timeout, "reply_timeout")
        self._sources = {command, *(name for name, other in COMMANDS.items() if other.code == info.code)}
        if payload is not None:
            self._sources.add(payload.NAME)
        self._hypotheses: list[_Hypothesis] = []
        data: bytes | None = None
        for state in heard:
            transition = lookup(state, command_event(info.code, state) or command, firmware)
            assert transition is not None
            if (STATES[transition.to].expects is None) != (payload is None):
                continue
            formats: list[str | None] = [None]
            if state in _STREAMING:
                formats = list(OUTPUT_FORMATS) if chosen is None else [chosen]
            for fmt in formats:
                host = Host(firmware=firmware, reply_timeout=reply_timeout, state=state, output=fmt)
                sent = host.send(command, payload)
                assert data is None or sent == data, "every state is sent the same bytes"
                data = sent
                self._hypotheses.append(_Hypothesis(state, host, bool(host.owed)))
        if data is None:
            takes = "with" if payload is None else "without"
            detail = f"{command} is heard {takes} a parameter block ({info.parameter_block}) in {', '.join(heard)}"
            if not heard:
                detail = f"no state of the device hears {command}"
            raise IlahrsError(ErrorKind.UNEXPECTED_MESSAGE, None, None, detail)
        self.data: Final[bytes] = data
        """The bytes to write: the command and its parameter block."""
        self.states: Final = tuple(dict.fromkeys(h.state for h in self._hypotheses))
        """The states considered, in the order of preference."""
        self._elapsed = 0.0
        self._received = 0

    def receive(self, data: bytes | bytearray | memoryview, *, within: float = 0.0) -> None:
        """Bytes from the device, as they arrived (`within`: as `Host.receive` takes it, the
        seconds in which they came, which pass on the clock)."""
        self._elapsed += require_seconds(within, "within")
        self._received += len(data)
        for hypothesis in self._hypotheses:
            if not hypothesis.failed:
                self._take(hypothesis, hypothesis.host.receive(data, within=within))

    def advance(self, seconds: float) -> None:
        """Let time pass (the quiet before the next bytes, or after the last)."""
        self._elapsed += require_seconds(seconds)
        for hypothesis in self._hypotheses:
            if not hypothesis.failed:
                self._take(hypothesis, hypothesis.host.advance(seconds))

    def _take(self, hypothesis: _Hypothesis, events: list[HostEvent]) -> None:
        hypothesis.events += events
        if any(isinstance(event, ProtocolError) for event in events):
            hypothesis.failed = True

    def _answered(self) -> _Hypothesis | None:
        return next((h for h in self._hypotheses if h.owes and h.complete), None)

    @property
    def done(self) -> bool:
        """True once the answers of one state came, or no state that owes answers can still get
        them and the reply timeout has passed (or every state has failed)."""
        if self._answered() is not None:
            return True
        if any(h.owes and not h.failed for h in self._hypotheses):
            return False
        return self._elapsed >= self.reply_timeout or all(h.failed for h in self._hypotheses)

    def reply(self) -> Reply:
        """What the device answered, as far as it has come (see `done`)."""
        answered = self._answered()
        if answered is not None:
            answers = self._answers(answered)
            formats: tuple[str, ...] = ()
            if any(isinstance(answer, Output) for answer in answers):
                fits = [h for h in self._hypotheses if h.owes and h.complete and h.state == answered.state]
                formats = tuple(dict.fromkeys(h.host.output_format or "" for h in fits))
            return Reply(self.command, answered.state, answers, (), formats, self._received, answered.host)
        silent = [h for h in self._hypotheses if not h.owes and not h.failed]
        if not silent:
            return Reply(self.command, None, (), (), (), self._received, None)
        states = tuple(dict.fromkeys(h.state for h in silent))
        return Reply(self.command, silent[0].state, (), states, (), self._received, silent[0].host)

    def _answers(self, hypothesis: _Hypothesis) -> tuple[HostEvent, ...]:
        def source(event: HostEvent) -> str | None:
            return event.message if isinstance(event, Acknowledged) else getattr(event, "source", None)

        return tuple(e for e in hypothesis.events if source(e) in self._sources)
