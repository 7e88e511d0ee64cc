"""An idle line ends every message (E41) and strict decoding refuses data frames whose reserved
byte is not the AHRS's (E42), in the Python binding: the stream decoder, the frame parser, the
whole-capture path and the device model, which answers a command behind a stale frame header once
the line has been idle."""

from __future__ import annotations

import math

import pytest

import ilahrs
from generator import build_spec
from ilahrs.bulk import decode_output, payload_offsets

STALE = bytes.fromhex("AA 55 01 00 3A 00")  # the start of a 58-byte data frame whose rest never came
SHORT_STALE = bytes.fromhex("AA 55 01 00 0F 00 FF FF FF FF FF F6")  # 12 bytes of a 17-byte frame
AHRSCONT1 = ilahrs.build_command("AHRScont1")
# A frame whose reserved byte went +0x3C and a payload byte -0x3C: the sum cannot see it (E42).
INTACT = bytes.fromhex("AA5501002800786906FF7D00DC0524FA3200000000001027D00724FA9411000000000000E02EFB009709")
ESCAPED = bytes.fromhex("AA55013C2800786906FF7D00DC0524FA3200000000001027940724FA9411000000000000E02EFB009709")


def test_the_constants_are_the_specs() -> None:
    spec = build_spec()
    assert spec.serial_line is not None and spec.frame.strict is not None
    assert spec.serial_line.idle_byte_times == ilahrs.IDLE_BYTE_TIMES
    assert spec.serial_line.idle_timeout_s == ilahrs.IDLE_TIMEOUT
    assert dict(ilahrs.spec.STRICT_RESERVED) == {spec.frame.strict.message_type_value: spec.frame.strict.reserved}


def test_idle_gives_up_a_stale_candidate_and_goes_on() -> None:
    decoder = ilahrs.StreamDecoder()
    assert decoder.feed(SHORT_STALE) == [] and decoder.pending == 12
    assert decoder.idle(ilahrs.IDLE_TIMEOUT / 2) == [] and decoder.pending == 12  # too short: nothing changes
    assert decoder.idle(math.nextafter(ilahrs.IDLE_TIMEOUT, 0)) == [] and decoder.pending == 12
    assert decoder.idle(ilahrs.IDLE_TIMEOUT) == [] and (decoder.pending, decoder.discarded) == (0, 12)
    assert [e.raw for e in decoder.feed(AHRSCONT1)] == [AHRSCONT1]
    # Without the idle call, the stale bytes and the command make a frame whose checksum is right.
    lenient = ilahrs.StreamDecoder()
    assert [e.raw for e in lenient.feed(SHORT_STALE + AHRSCONT1)] == [SHORT_STALE + AHRSCONT1[:5]]


def test_idle_emits_the_messages_behind_the_stale_bytes() -> None:
    decoder = ilahrs.StreamDecoder()
    read = ilahrs.build_command("ReadAHRSPar")
    assert decoder.feed(STALE + read) == [] and decoder.pending == len(STALE + read)
    assert [e.raw for e in decoder.idle()] == [read]  # None: the line is idle
    assert (decoder.pending, decoder.discarded) == (0, len(STALE))
    assert decoder.idle() == [] and decoder.idle(10.0) == []  # idle with nothing held


@pytest.mark.parametrize("quiet", [math.nan, -0.5, "0.2", b"", True, [1.0]])
def test_idle_refuses_what_is_no_quiet_time(quiet: object) -> None:
    decoder = ilahrs.StreamDecoder()
    decoder.feed(STALE)
    with pytest.raises(ilahrs.IlahrsError) as raised:
        decoder.idle(quiet)  # type: ignore[arg-type]
    assert raised.value.kind == ilahrs.ErrorKind.OUT_OF_RANGE and raised.value.field == "quiet"
    assert decoder.pending == len(STALE)
    assert decoder.idle(math.inf) == [] and decoder.pending == 0


def test_strict_refuses_what_the_checksum_lets_through() -> None:
    assert ilahrs.Frame.parse(ESCAPED).reserved == 0x3C  # E6: accepted by default
    with pytest.raises(ilahrs.IlahrsError) as raised:
        ilahrs.Frame.parse(ESCAPED, strict=True)
    error = raised.value
    assert (error.kind, error.offset, error.field) == (ilahrs.ErrorKind.BAD_RESERVED, 3, "reserved")
    assert ilahrs.Frame.parse(INTACT, strict=True).payload == ilahrs.Frame.parse(INTACT).payload
    command = ilahrs.Frame(ilahrs.MessageType.COMMAND, b"\x80", reserved=0x3C).build()
    assert ilahrs.Frame.parse(command, strict=True).reserved == 0x3C  # data frames only
    with pytest.raises(ilahrs.IlahrsError) as raised:
        ilahrs.Frame.parse(ESCAPED + b"\x00", strict=True)
    assert raised.value.kind == ilahrs.ErrorKind.TRAILING_DATA  # every other check first
    lenient, strict = ilahrs.StreamDecoder(), ilahrs.StreamDecoder(strict=True)
    assert [e.raw for e in lenient.feed(ESCAPED + INTACT)] == [ESCAPED, INTACT]
    assert [e.raw for e in strict.feed(ESCAPED + INTACT)] == [INTACT] and strict.discarded == len(ESCAPED)


def test_strict_is_a_flag() -> None:
    for bad in (1, "yes", None):
        with pytest.raises(ilahrs.IlahrsError) as raised:
            ilahrs.StreamDecoder(strict=bad)  # type: ignore[arg-type]
        assert raised.value.kind == ilahrs.ErrorKind.MALFORMED and raised.value.field == "strict"
        with pytest.raises(ilahrs.IlahrsError):
            ilahrs.Frame.parse(INTACT, bad)  # type: ignore[arg-type]
        with pytest.raises(ilahrs.IlahrsError):
            decode_output(INTACT, ilahrs.Quaternion, strict=bad)  # type: ignore[arg-type]


def test_the_capture_path_is_strict_when_asked() -> None:
    table = next(cls for cls in ilahrs.PAYLOADS.values() if len(ilahrs.Frame.parse(INTACT).payload) == cls.SIZE)
    capture = ESCAPED + INTACT
    assert list(payload_offsets(capture, table.SIZE)) == [6, len(ESCAPED) + 6]
    assert list(payload_offsets(capture, table.SIZE, strict=True)) == [len(ESCAPED) + 6]
    assert list(decode_output(capture, table, strict=True)) == [table.parse(ilahrs.Frame.parse(INTACT).payload)]


def test_the_device_answers_behind_a_stale_header_once_the_line_is_idle() -> None:
    """The repro of the stale header: the device held 15 bytes and answered nothing until 45 more
    bytes came; now it answers at the idle timeout, and not before."""
    device = ilahrs.Device()
    assert device.receive(STALE + ilahrs.build_command("ReadAHRSPar")) == b""
    assert device.next_event_in == pytest.approx(ilahrs.IDLE_TIMEOUT)
    assert device.advance(0.099) == b""
    answer = device.advance(0.001)
    frame = ilahrs.Frame.parse(answer)
    assert ilahrs.AhrsParametersRead.parse(frame.payload).update_rate > 0
    assert device.discarded == len(STALE) and device.next_event_in is None
    again = ilahrs.Device()
    again.receive(STALE + ilahrs.build_command("ReadAHRSPar"))
    assert again.advance(0.1) == answer
    # Bytes that keep coming keep the line busy: the idle timeout counts from the last one.
    busy = ilahrs.Device()
    busy.receive(STALE)
    busy.advance(0.09)
    busy.receive(ilahrs.build_command("ReadAHRSPar"))
    assert busy.advance(0.09) == b"" and busy.advance(0.01) == answer
    assert busy.idle() == b""


def test_the_device_idles_before_a_timer_due_later() -> None:
    device = ilahrs.Device()
    device.receive(ilahrs.build_command("AHRScont3"))  # acknowledged; output after the alignment
    device.receive(STALE + ilahrs.build_command("Stop"))
    out = device.advance(60.0)
    assert out == b"" and device.state == "idle"  # Stop came 0.1 s later, before the alignment ended
