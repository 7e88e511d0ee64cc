"""The host session: decoding by context (E7), acknowledgement checks (E12), missing, wrong and
unexpected answers, refusals, and what it tolerates (late output, a lost alignment block)."""

from __future__ import annotations

import random

import pytest
from device_support import Pair

import ilahrs
from ilahrs.session.host import Acknowledged, DataBlock, Discarded, Host, Output, ProtocolError

SEED = 20140311


def data_frame(payload: bytes) -> bytes:
    return ilahrs.Frame(ilahrs.MessageType.DATA, payload).build()


def test_acknowledgement_is_checked_against_what_was_sent() -> None:
    host = Host()
    sent = host.send("ClearClb")
    (good,) = host.receive(ilahrs.ack_for(sent))
    assert good == Acknowledged("ClearClb", ilahrs.Frame.parse(sent).checksum, ilahrs.ack_for(sent))
    host.send("ClearClb")
    (wrong,) = host.receive(data_frame(ilahrs.Acknowledgement(checksum=0x1234).build()))
    assert isinstance(wrong, ProtocolError)
    assert (wrong.kind, wrong.problem, wrong.expected, wrong.source) == (ilahrs.ErrorKind.BAD_CHECKSUM, "wrong", "ack",
                                                                          "ClearClb")
    assert host.owed == () and host.state == "idle"


def test_parameter_block_acknowledgement_carries_the_block_checksum() -> None:
    """E12, E13: LoadAHRSPar gets no answer; its block gets an ack with the block's checksum."""
    host = Host()
    block = ilahrs.AhrsParametersLoad(update_rate=10)
    sent = host.send("LoadAHRSPar", block)
    command, block_frame = sent[:9], sent[9:]
    assert command == ilahrs.build_command("LoadAHRSPar")
    assert ilahrs.Frame.parse(block_frame).payload == block.build()
    (wrong,) = host.receive(ilahrs.ack_for(command))
    assert isinstance(wrong, ProtocolError) and wrong.problem == "wrong"
    host.send("LoadAHRSPar", block)
    (ack,) = host.receive(ilahrs.ack_for(block_frame))
    assert isinstance(ack, Acknowledged) and ack.message == "ahrs_parameters_load"
    assert host.setting("output") == 10.0


def test_missing_answer_is_reported_after_the_timeout() -> None:
    host = Host(reply_timeout=0.5)
    host.send("ReadAHRSPar")
    assert host.advance(0.5) == []
    (missing,) = host.advance(0.01)
    assert isinstance(missing, ProtocolError)
    assert (missing.problem, missing.expected, missing.source) == ("missing", "ahrs_parameters_read", "ReadAHRSPar")
    assert missing.kind == ilahrs.ErrorKind.TIMEOUT
    assert host.owed == ()
    assert host.advance(10.0) == []


def test_same_size_blocks_decode_by_context() -> None:
    """E7: a 50-byte block is parameters, a firmware string or an alignment block as the context says."""
    pair = Pair(seed=SEED)
    (read,) = pair.send("ReadAHRSPar")
    (firmware,) = pair.send("GetVerFirmware")
    assert isinstance(read, DataBlock) and isinstance(read.payload, ilahrs.AhrsParametersRead)
    assert isinstance(firmware, DataBlock) and isinstance(firmware.payload, ilahrs.FirmwareVersion)
    assert firmware.payload.version.startswith("ilahrs virtual AHRS")
    assert len(read.payload.build()) == len(firmware.payload.build()) == 50
    # The frame says nothing about its table: the same bytes are what the context owes, and
    # nothing at all when nothing is owed.
    host = Host()
    host.send("GetVerFirmware")
    (as_firmware,) = host.receive(read.raw)
    assert isinstance(as_firmware, DataBlock) and isinstance(as_firmware.payload, ilahrs.FirmwareVersion)
    (error,) = host.receive(read.raw)
    assert isinstance(error, ProtocolError) and error.problem == "unexpected" and error.expected is None
    # 52 bytes: GetClbRes answers Table 6.17; the same bytes after FinishClb would be Table 6.14.
    (status,) = pair.send("GetClbRes")
    assert isinstance(status, DataBlock) and isinstance(status.payload, ilahrs.CalibrationStatus)


def test_unexpected_messages_and_garbage() -> None:
    host = Host()
    (error,) = host.receive(ilahrs.ack_for(ilahrs.build_command("Stop")))
    assert isinstance(error, ProtocolError) and error.problem == "unexpected" and error.expected is None
    events = host.receive(b"\x00\x01\xaa\x55\x99" + ilahrs.build_command("AHRScont1"))
    assert isinstance(events[0], ProtocolError) and "command frame" in events[0].detail
    assert events[-1] == Discarded(5)
    rng = random.Random(SEED)
    for _ in range(200):
        for event in host.receive(bytes(rng.randrange(256) for _ in range(rng.randrange(100)))):
            assert isinstance(event, ProtocolError | Discarded)


def test_send_refuses_what_the_device_would_not_take() -> None:
    host = Host()
    with pytest.raises(ilahrs.IlahrsError) as info:
        host.send("GetDataReq")  # E33: ignored in idle
    assert info.value.kind == ilahrs.ErrorKind.UNEXPECTED_MESSAGE
    with pytest.raises(ilahrs.IlahrsError):
        host.send("LoadAHRSPar")  # E13: the block must follow
    with pytest.raises(ilahrs.IlahrsError):
        host.send("LoadAHRSPar", ilahrs.CalibrationParameters())
    with pytest.raises(ilahrs.IlahrsError):
        host.send("ReadAHRSPar", ilahrs.AhrsParametersLoad())
    with pytest.raises(ilahrs.IlahrsError) as info:
        host.send("NoSuchCommand")
    assert info.value.kind == ilahrs.ErrorKind.UNKNOWN_COMMAND
    host.send("ReadAHRSPar")
    with pytest.raises(ilahrs.IlahrsError):
        host.send("GetBIT")  # still owed: the parameter block
    assert host.state == "idle" and host.owed == ("ahrs_parameters_read",)


def test_stop_in_calibration_is_exitclb() -> None:
    """E14: the host resolves 0xFE by mode as the device does."""
    pair = Pair(seed=SEED)
    pair.send("Start2D2TClb", ilahrs.CalibrationParameters(accumulation_time=2))
    (ack,) = pair.send("Stop")
    assert isinstance(ack, Acknowledged) and ack.message == "ExitClb"
    assert pair.host.state == pair.device.state == "idle"


def test_late_output_after_stop() -> None:
    """Output in flight when Stop went out is accepted as late, for one reply timeout."""
    pair = Pair(seed=SEED)
    pair.send("AHRScont3")
    pair.wait(1.5)
    in_flight = pair.device.advance(0.05)
    assert pair.send("Stop") == []
    events = pair.host.receive(in_flight)
    assert len(events) == 5 and all(isinstance(e, Output) and e.late for e in events)
    pair.host.advance(1.5)
    (late,) = pair.host.receive(in_flight[: len(in_flight) // 5])
    assert isinstance(late, ProtocolError) and late.problem == "unexpected"


def test_lost_alignment_block_is_reported_and_output_accepted() -> None:
    pair = Pair(seed=SEED)
    pair.send("AHRScont2")
    sent = pair.device.advance(1.0)  # the alignment block
    assert len(sent) == ilahrs.InitialAlignment.SIZE + 8
    events = pair.host.receive(pair.device.advance(0.02))  # the alignment block never arrives
    missing, output, *_ = events
    assert isinstance(missing, ProtocolError) and missing.expected == "initial_alignment"
    assert isinstance(output, Output) and isinstance(output.data, ilahrs.Quaternion)
    assert pair.host.state == "continuous"


def test_output_that_stops_is_reported() -> None:
    pair = Pair(seed=SEED)
    pair.send("AHRScont3")
    pair.wait(1.2)
    pair.device.receive(ilahrs.build_command("Stop"))  # behind the host's back
    events = pair.wait(1.1)
    assert [e.problem for e in events if isinstance(e, ProtocolError)] == ["missing"]


def test_resync_and_settings() -> None:
    host = Host()
    assert host.setting("alignment") == ilahrs.statemachine.DEFAULT_ALIGNMENT_TIME_S
    host.send("Start2D2TClb", ilahrs.CalibrationParameters(accumulation_time=7))
    assert host.setting("accumulation") == 7.0
    host.resync("runs_ready")
    assert host.state == "runs_ready" and host.owed == ()
    with pytest.raises(ilahrs.IlahrsError):
        host.resync("nowhere")


def test_the_host_gives_up_a_stale_header_when_the_line_goes_idle() -> None:
    """E41: the start of a frame whose rest never came holds the answer behind it until the line
    has been idle for IDLE_TIMEOUT; then the answer is reported, stamped at that moment."""
    host, device = Host(), ilahrs.Device()
    answer = device.receive(host.send("GetBIT"))
    stale = bytes.fromhex("AA 55 01 00 3A 00")
    assert host.receive(stale + answer) == [] and host.pending == len(stale + answer)
    assert host.advance(0.099) == [] and host.owed == ("bit_result",)
    block, dropped = host.advance(0.5)
    assert isinstance(block, DataBlock) and block.raw == answer and block.at == pytest.approx(ilahrs.IDLE_TIMEOUT)
    assert dropped == Discarded(len(stale)) and host.pending == 0 and not host.owed
    assert host.advance(2.0) == []  # the answer came in time: no timeout reported


def test_the_host_reports_a_timeout_before_what_idle_releases_later() -> None:
    host = Host(reply_timeout=0.05)
    answer = ilahrs.Device().receive(host.send("GetBIT"))
    host.receive(bytes.fromhex("AA 55 01 00 3A 00") + answer)
    missing, late, dropped = host.advance(1.0)
    assert isinstance(missing, ProtocolError) and missing.problem == "missing"
    assert isinstance(late, ProtocolError) and late.problem == "unexpected" and late.raw == answer
    assert missing.at == late.at == pytest.approx(ilahrs.IDLE_TIMEOUT) and isinstance(dropped, Discarded)


def test_the_host_idle_call_and_strict_option() -> None:
    host = Host.mid_stream("AHRScont2", strict=True)
    assert host.strict
    block = ilahrs.Quaternion(heading=9000).build()
    good = ilahrs.Frame(ilahrs.MessageType.DATA, block).build()
    bad = ilahrs.Frame(ilahrs.MessageType.DATA, block, reserved=1).build()
    events = host.receive(bad + good)
    assert [type(e) for e in events] == [Output, Discarded] and isinstance(events[0], Output)
    assert events[0].raw == good
    assert [type(e) for e in Host.mid_stream("AHRScont2").receive(bad + good)] == [Output, Output]
    host.receive(good[:5])
    assert host.idle(0.01) == [] and host.pending == 5
    assert host.idle() == [Discarded(5)] and host.pending == 0
    with pytest.raises(ilahrs.IlahrsError):
        Host(strict="yes")  # type: ignore[arg-type]


def test_bytes_read_together_after_a_quiet_time_are_never_given_up() -> None:
    """E41 counts the quiet before bytes arrive, never past them: a read that returns the first
    bytes of an answer after a long pause (the caller's) keeps them, and the rest completes it."""
    host, device = Host(), ilahrs.Device()
    answer = device.receive(host.send("GetBIT"))
    assert host.advance(0.3) == []  # the line was quiet: nothing is held, nothing is given up
    assert host.receive(answer[:1], within=0.3) == [] and host.pending == 1  # came some time in 0.3 s
    assert host.advance(0.05) == [] and host.pending == 1
    (block,) = host.receive(answer[1:], within=0.001)
    assert isinstance(block, DataBlock) and block.raw == answer and not host.owed


def test_an_answer_read_after_its_deadline_counts_when_it_came() -> None:
    """`within`: the bytes of a read came some time since the one before; an answer among them is
    matched before a deadline that passed in that time, and a later deadline still fires."""
    host = Host(reply_timeout=0.5)
    answer = ilahrs.Device().receive(host.send("GetBIT"))
    (block,) = host.receive(answer, within=2.0)
    assert isinstance(block, DataBlock) and host.now == pytest.approx(2.0) and not host.owed
    host.send("GetBIT")
    (missing,) = host.receive(b"", within=0.6)  # no bytes: time passes as with advance
    assert isinstance(missing, ProtocolError) and missing.problem == "missing"
    with pytest.raises(ilahrs.IlahrsError):
        host.receive(b"", within=-1.0)


@pytest.mark.parametrize(("start", "leave"), [("Start2DClb", "ExitClb"), ("AHRScont3", "Stop"), ("AHRSreq3", "Stop")])
def test_a_timer_block_in_flight_when_a_command_goes_out_keeps_the_command_s_state(start: str, leave: str) -> None:
    """The alignment block the device sent while the host was not reading arrives with the answer
    to the command the host sent meanwhile: the host follows the block's transition, then the
    command's (found by the stateful client test: the host was left in calibration_deciding,
    the device idle)."""
    pair = Pair(seed=SEED)
    table = ilahrs.COMMANDS[start].parameter_block
    pair.send(start, None if table is None else ilahrs.CalibrationParameters(accumulation_time=2))
    in_flight = pair.device.advance(1.2)  # the alignment block: not read yet
    assert in_flight
    answer = pair.device.receive(pair.host.send(leave))
    pair.host.receive(in_flight + answer)
    pair.host.advance(3.0)
    assert pair.host.state == pair.device.state == "idle"
