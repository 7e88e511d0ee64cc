"""The device end of the virtual line without I/O: fault injection and its log, deterministically,
and the loopback-only address check."""

from __future__ import annotations

import io
import json

import pytest
from device_support import quick_parameters

import ilahrs
from ilahrs.edge.simulate import Faults, Line, loopback_address
from ilahrs.session.device import Device
from ilahrs.session.host import Discarded, Host, ProtocolError


def run_line(faults: Faults, seconds: float = 5.0) -> tuple[Line, list[dict[str, object]], bytes]:
    log = io.StringIO()
    line = Line(Device(seed=3, parameters=quick_parameters()), faults, log)
    written = bytearray(line.step(ilahrs.build_command("AHRScont1"), 0.0))
    t = 0.0
    while t < seconds:
        t += 0.013
        written += line.step(b"", t)
    entries = [json.loads(entry) for entry in log.getvalue().splitlines()]
    return line, entries, bytes(written)


def test_faults_are_seeded_and_logged() -> None:
    faults = Faults(corrupt_rate=0.01, drop_rate=0.01, garbage_rate=0.3, seed=9)
    line, entries, written = run_line(faults)
    assert run_line(faults)[2] == written  # the same seed damages the same bytes
    messages = [e for e in entries if e["kind"] != "garbage"]
    assert line.sent == len(messages) == 1 + 1 + 400  # ack, alignment block, 4 s at 100 Hz
    assert 0 < line.sent - line.intact < line.sent
    assert b"".join(bytes.fromhex(str(e["written"])) for e in entries) == written
    for entry in messages:
        assert (entry["message"] == entry["written"]) is entry["intact"]


def test_host_gets_every_intact_message_and_reports_the_rest() -> None:
    faults = Faults(corrupt_rate=0.005, drop_rate=0.005, garbage_rate=0.2, seed=4)
    _line, entries, written = run_line(faults)
    host = Host()
    host.send("AHRScont1")
    received: list[bytes] = []
    discarded = 0
    for i in range(0, len(written), 7):  # in small chunks
        for event in host.receive(written[i : i + 7]):
            if isinstance(event, Discarded):
                discarded += event.count
            elif isinstance(event, ProtocolError):
                assert event.problem == "missing"  # a damaged ack or alignment block
            else:
                received.append(event.raw)
        host.advance(0.001)
    intact = [bytes.fromhex(str(e["message"])) for e in entries if e.get("intact") is True]
    assert received == intact
    assert discarded + sum(len(m) for m in received) + host.pending == len(written)


def test_no_faults_writes_exactly_what_the_device_sends() -> None:
    line, entries, written = run_line(Faults(), seconds=1.0)
    assert line.sent == line.intact
    assert not [e for e in entries if e["kind"] == "garbage"]
    device = Device(seed=3, parameters=quick_parameters())
    # run_line takes 77 steps of 13 ms to pass 1 s; one advance over the same time sends the same.
    expected = device.receive(ilahrs.build_command("AHRScont1")) + device.advance(0.013 * 77)
    assert written == expected


@pytest.mark.parametrize(
    ("text", "expected"),
    [("127.0.0.1:0", ("127.0.0.1", 0)), ("localhost:5000", ("127.0.0.1", 5000)), ("[::1]:7", ("::1", 7)),
     ("127.5.6.7:65535", ("127.5.6.7", 65535))],
)
def test_loopback_addresses(text: str, expected: tuple[str, int]) -> None:
    assert loopback_address(text) == expected


@pytest.mark.parametrize("text", ["0.0.0.0:0", "10.0.0.1:80", "[::]:1", "host.example:1", "127.0.0.1", "1.2.3.4:x"])
def test_other_addresses_are_refused(text: str) -> None:
    with pytest.raises(ValueError, match=r"loopback|HOST:PORT|IP address"):
        loopback_address(text)
