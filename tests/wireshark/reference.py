"""What the Python binding makes of a capture, message by message, and how tshark must show it.

The host-to-device bytes are cut into frames by the binding's StreamDecoder and replayed into a
fresh `ilahrs.Host` (each command named by the host's state, E14, with the parameter block that
follows it); the device-to-host bytes go to `Host.receive`, which decodes them by context. Time
passes on the host's clock as the capture's timestamps say. Each message becomes an `Expected`:
its kind, table, command or source, late flag, and every field's raw and engineering value as
tshark prints them (`-T json`).
"""

from __future__ import annotations

import struct
from dataclasses import dataclass, field
from typing import Any

import ilahrs
from ilahrs import statemachine
from ilahrs.pcapng import Capture, Direction
from ilahrs.session.host import Acknowledged, DataBlock, Discarded, Output, ProtocolError

PROTO = "ilahrs"
ACK_TABLE = "acknowledgement"
SENTENCE = f"{PROTO}.{ilahrs.nmea.IDENTIFIER.lower()}"


@dataclass
class Value:
    """One value tshark must show: an integer, a double (15 significant digits), a float (6, and
    its 4 bytes exactly), text or bytes."""

    kind: str
    value: Any
    wire: bytes | None = None


@dataclass
class Expected:
    direction: str  # host or device
    kind: str
    table: str | None = None
    command: str | None = None
    source: str | None = None
    late: bool = False
    wrong: bool = False
    missing: str | None = None
    values: dict[str, Value] = field(default_factory=dict)
    answered: bool = False
    frame: int = 0
    """The packet the message completes in."""
    request: int | None = None
    """A device message: the packet of the host message it answers."""


@dataclass
class PacketExpected:
    messages: list[Expected] = field(default_factory=list)
    discarded: int = 0


def payload_values(payload: ilahrs.Payload, variant: ilahrs.Variant) -> dict[str, Value]:
    """tshark's fields for a payload: `ilahrs.<table>.<field>` (engineering value where a scale
    applies, with `.raw`; a date as YYYY-MM-DD with the float as `.raw`; the calibration success
    byte with `.outcome` and `.accuracy`), the USW flags."""
    raw = payload.raw()
    engineering = payload.values(variant)
    out: dict[str, Value] = {}
    for info in payload.FIELDS:
        name = f"{PROTO}.{payload.NAME}.{info.name}"
        value = raw[info.name]
        if info.encoding == "date":
            assert isinstance(value, float)
            try:
                year, month, day = ilahrs.decode_date(value)
            except ilahrs.IlahrsError:
                pass  # no calendar date: the float only
            else:
                out[name] = Value("text", f"{year:04d}-{month:02d}-{day:02d}")
            out[name + ".raw"] = Value("double", value)
        elif info.type == "reserved":
            assert isinstance(value, bytes)
            out[name] = Value("bytes", value)
        elif info.type == "char":
            out[name] = Value("text", value)
        elif info.name in engineering:
            out[name] = Value("double", engineering[info.name])
            out[name + ".raw"] = Value("float" if info.type == "f32" else "int", value)
        elif info.type == "f32":
            assert isinstance(value, float)
            out[name] = Value("float", value, struct.pack("<f", value))
        else:
            out[name] = Value("int", value)
        if info.encoding == "calibration_success":
            assert isinstance(value, int)
            out[name + ".outcome"] = Value("text", "succeeded" if ilahrs.calibration_succeeded(value) else "failed")
            accuracy = ilahrs.calibration_accuracy_deg(value)
            if accuracy is not None:
                out[name + ".accuracy"] = Value("double", accuracy)
    return out


def sentence_values(sentence: ilahrs.PahrSentence) -> dict[str, Value]:
    engineering = sentence.values()
    out: dict[str, Value] = {}
    for name, kind, *_rest in sentence._SPEC:
        value = getattr(sentence, name)
        if kind == "hex":
            out[f"{SENTENCE}.{name}"] = Value("int", value)
        else:
            out[f"{SENTENCE}.{name}"] = Value("double", engineering[name])
            out[f"{SENTENCE}.{name}.raw"] = Value("int", value)
    return out


def _frame_payload(raw: bytes) -> bytes:
    return ilahrs.Frame.parse(raw).payload


class Reference:
    """Replays a capture through the Python binding."""

    def __init__(self, variant: ilahrs.Variant, firmware: str | None = None) -> None:
        self.variant = variant
        self.host = ilahrs.Host(firmware=firmware)
        self.outbound = ilahrs.StreamDecoder()
        self.pending: tuple[str, bytes, str, Expected] | None = None
        self.requests: dict[str, Expected] = {}
        self.timeouts = 0

    def decode(self, capture: Capture) -> list[PacketExpected]:
        result = []
        start = capture.packets[0].timestamp_us if capture.packets else 0
        now = start
        for number, packet in enumerate(capture.packets, start=1):
            self._advance((packet.timestamp_us - now) / 1_000_000)
            now = packet.timestamp_us
            expected = PacketExpected()
            if packet.direction == Direction.OUTBOUND:
                before = self.outbound.discarded
                for event in self.outbound.feed(packet.data):
                    expected.messages.append(self._host_message(event.raw))
                    expected.messages[-1].frame = number
                expected.discarded = self.outbound.discarded - before
            else:
                self._device(self.host.receive(packet.data), expected)
            result.append(expected)
        return result

    def _advance(self, seconds: float) -> None:
        for event in self.host.advance(seconds):
            assert isinstance(event, ProtocolError) and event.problem == "missing"
            self.timeouts += 1
            if event.source in self.requests:
                self.requests[event.source].missing = event.expected

    def _host_message(self, raw: bytes) -> Expected:
        frame = ilahrs.Frame.parse(raw)
        if self.pending is not None:
            command, command_raw, table, _ = self.pending
            block = ilahrs.PAYLOADS[table].parse(frame.payload)
            sent = self.host.send(command, block)
            assert sent == command_raw + raw, "the host would not have sent these bytes"
            self.pending = None
            message = Expected("host", "parameter_block", table=table, values=payload_values(block, self.variant))
            self.requests[table] = message
            return message
        assert frame.message_type == ilahrs.MessageType.COMMAND and len(frame.payload) == 1
        name = statemachine.command_event(frame.payload[0], self.host.state)
        assert name is not None
        message = Expected("host", "command", command=name)
        self.requests[name] = message
        transition = statemachine.lookup(self.host.state, name, self.host.firmware)
        assert transition is not None, f"{name} is ignored in {self.host.state}"
        expects = statemachine.STATES[transition.to].expects
        if expects is not None:
            self.pending = (name, raw, expects, message)
        else:
            assert self.host.send(name) == raw
        return message

    def _device(self, events: list[Any], expected: PacketExpected) -> None:
        missing: str | None = None
        for event in events:
            message: Expected | None = None
            if isinstance(event, Discarded):
                expected.discarded += event.count
            elif isinstance(event, Acknowledged):
                ack = ilahrs.PAYLOADS[ACK_TABLE].parse(_frame_payload(event.raw))
                message = Expected(
                    "device", "ack", table=ack.NAME, source=event.message, values=payload_values(ack, self.variant)
                )
            elif isinstance(event, DataBlock):
                message = Expected(
                    "device",
                    "data",
                    table=event.payload.NAME,
                    source=event.source,
                    values=payload_values(event.payload, self.variant),
                )
            elif isinstance(event, Output):
                message = self._output(event)
            elif isinstance(event, ProtocolError) and event.raw is None:
                missing = event.expected
            elif isinstance(event, ProtocolError) and event.problem == "wrong":
                ack = ilahrs.PAYLOADS[ACK_TABLE].parse(_frame_payload(event.raw or b""))
                message = Expected(
                    "device",
                    "ack",
                    table=ack.NAME,
                    source=event.source,
                    wrong=True,
                    values=payload_values(ack, self.variant),
                )
            elif isinstance(event, ProtocolError):
                message = Expected("device", "unexpected")
                if event.raw is not None and event.raw.startswith(b"$"):
                    message.values = sentence_values(ilahrs.PahrSentence.parse(event.raw))
            if message is not None:
                message.missing, missing = missing, None
                request = self.requests.get(message.source or "") if message.kind != "unexpected" else None
                message.request = request.frame if request is not None else None
                expected.messages.append(message)

    def _output(self, event: Output) -> Expected:
        if isinstance(event.data, ilahrs.PahrSentence):
            return Expected(
                "device", "output", source=event.source, late=event.late, values=sentence_values(event.data)
            )
        return Expected(
            "device",
            "output",
            table=event.data.NAME,
            source=event.source,
            late=event.late,
            values=payload_values(event.data, self.variant),
        )
