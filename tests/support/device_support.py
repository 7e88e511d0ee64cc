"""Helpers for the device, host and simulator tests: a host wired to a device in memory (h11's
ConnectionPair), and a way to drive a device into any state of the table."""

from __future__ import annotations

import copy
import functools
from collections import deque
from collections.abc import Iterable

import ilahrs
from ilahrs import statemachine as sm
from ilahrs.session.device import Device, default_parameters
from ilahrs.session.host import Host, HostEvent
from ilahrs.stream import StreamDecoder, StreamEvent


def messages(data: bytes) -> list[StreamEvent]:
    """Every message in `data` (which must hold whole, valid messages only)."""
    decoder = StreamDecoder()
    events = decoder.feed(data) + decoder.finish()
    assert decoder.discarded == 0, f"{decoder.discarded} bytes are not messages"
    return events


def quick_parameters(alignment_time: int = 1, update_rate: int = 100) -> ilahrs.AhrsParametersRead:
    raw = default_parameters().raw()
    raw.update(alignment_time=alignment_time, update_rate=update_rate)
    return ilahrs.AhrsParametersRead.from_raw(raw)


class Pair:
    """A host and a device wired back to back; every byte either sends reaches the other."""

    def __init__(
        self,
        *,
        firmware: str | None = None,
        seed: int = 1,
        alignment_time: int = 1,
        update_rate: int = 100,
        **options: object,
    ) -> None:
        kwargs: dict[str, object] = {"seed": seed, "parameters": quick_parameters(alignment_time, update_rate)}
        if firmware is not None:
            kwargs["firmware"] = firmware
        kwargs.update(options)
        self.device = Device(**kwargs)  # type: ignore[arg-type]
        self.host = Host(firmware=firmware)
        self.wire: list[bytes] = []
        """Everything the device sent, in order."""

    def _deliver(self, data: bytes) -> list[HostEvent]:
        if data:
            self.wire.append(data)
        return self.host.receive(data)

    def send(self, command: str, block: ilahrs.Payload | None = None) -> list[HostEvent]:
        return self._deliver(self.device.receive(self.host.send(command, block)))

    def wait(self, seconds: float, step: float = 0.01) -> list[HostEvent]:
        """Let `seconds` pass on both clocks in steps."""
        events: list[HostEvent] = []
        for _ in range(round(seconds / step)):
            events += self._deliver(self.device.advance(step))
            events += self.host.advance(step)
        return events


# --- Reaching every state ------------------------------------------------------------------------


def apply(device: Device, event: str) -> bytes:
    """Make `event` happen to the device; return what it sends."""
    state = sm.STATES[device.state]
    if event in ilahrs.COMMANDS:
        return device.receive(ilahrs.build_command(event))
    if event == sm.PARAMETER_BLOCK:
        assert state.expects is not None
        block = ilahrs.PAYLOADS[state.expects]()
        return device.receive(ilahrs.Frame(ilahrs.MessageType.DATA, block.build()).build())
    if event == sm.UNKNOWN:
        code = next(c for c in range(256) if c not in ilahrs.CODES)
        return device.receive(ilahrs.Frame(ilahrs.MessageType.COMMAND, bytes((code,))).build())
    if event == sm.OTHER_MESSAGE:
        size = 3 if state.expects is None or ilahrs.PAYLOADS[state.expects].SIZE != 3 else 4
        return device.receive(ilahrs.Frame(ilahrs.MessageType.DATA, bytes(size)).build())
    wait = device.next_event_in
    assert wait is not None, f"no timer runs in {device.state} for {event}"
    return device.advance(wait)


@functools.cache
def reachable(seed: int = 1) -> dict[str, Device]:
    """A device in every state the table can reach from the initial one (breadth first). Shared:
    copy a device before using it."""
    start = Device(seed=seed, parameters=quick_parameters())
    found = {start.state: start}
    queue: deque[Device] = deque([start])
    while queue:
        device = queue.popleft()
        for (state, event), transition in sm.TRANSITIONS.items():
            if state != device.state or transition.to in found:
                continue
            if event in ilahrs.COMMANDS and sm.command_event(ilahrs.COMMANDS[event].code, state) != event:
                continue
            following = copy.deepcopy(device)
            apply(following, event)
            assert following.state == transition.to, (state, event, following.state)
            found[following.state] = following
            queue.append(following)
    return found


def kinds(items: Iterable[StreamEvent]) -> list[str]:
    """'sentence', or 'frame:TYPE:SIZE' for each message."""
    result = []
    for item in items:
        if item.sentence is not None:
            result.append("sentence")
        else:
            assert item.frame is not None
            result.append(f"frame:{item.frame.message_type}:{len(item.frame.payload)}")
    return result
