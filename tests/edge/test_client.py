"""The serial client as a user drives it, against `ilahrs simulate` on a pty: answers it returns,
errors it raises, times it stamps, history it keeps while streaming, the calibrations it runs, and
the bad input it refuses before anything is written to the line."""

from __future__ import annotations

import math
import sys
import time
from collections.abc import Iterator
from pathlib import Path

import pytest
from simulators import Simulator, simulator

import ilahrs
from ilahrs.edge.serial import LINE, AhrsClient, ClientError
from ilahrs.session.host import Acknowledged, DataBlock, Output

pytest.importorskip("serial")
pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="ptys are POSIX")


@pytest.fixture(scope="module")
def sim(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Simulator]:
    folder = tmp_path_factory.mktemp("client")
    with simulator(folder, "--seed", "2", "--alignment-time", "1", "--update-rate", "100") as running:
        yield running


@pytest.fixture
def client(sim: Simulator) -> Iterator[AhrsClient]:
    with AhrsClient(sim.first_line) as opened:
        opened.stop()
        yield opened


def test_request_returns_the_acknowledgements(client: AhrsClient) -> None:
    for command in ("ClearClb", "GetBIT"):
        answers = client.request(command)
        assert answers, command
    acknowledged = client.request("ClearClb")
    assert [type(e) for e in acknowledged] == [Acknowledged]
    assert isinstance(acknowledged[0], Acknowledged) and acknowledged[0].message == "ClearClb"


def test_a_timeout_is_reported_as_timeout_with_a_rounded_time(client: AhrsClient) -> None:
    with pytest.raises(ClientError) as info:
        client.wait_for(lambda event: False, 0.3)
    assert info.value.kind == ilahrs.ErrorKind.TIMEOUT
    assert info.value.detail == "nothing came within 0.3 s"


def test_events_carry_their_monotonic_receive_time(client: AhrsClient) -> None:
    before = time.monotonic()
    client.start("AHRScont3")
    events = client.poll(0.3)
    after = time.monotonic()
    stamps = [event.at for event in client.events]
    assert events and all(before <= t <= after for t in stamps)
    assert stamps == sorted(stamps)


def test_the_baud_rate_is_a_parameter(sim: Simulator) -> None:
    with AhrsClient(sim.first_line) as default:
        assert default.baud == LINE["baudrate"] == ilahrs.spec.SERIAL_LINE["baud_rate"]
    with AhrsClient(sim.first_line, baud=57600) as other:
        assert other.baud == 57600 and other._port.baudrate == 57600
    with pytest.raises(ilahrs.IlahrsError):
        AhrsClient(sim.first_line, baud=-1)


def test_streaming_keeps_bounded_history(sim: Simulator) -> None:
    with AhrsClient(sim.first_line, history=40) as client:
        client.stop()
        client.start("AHRScont3")
        for count, block in enumerate(client.output(), 1):
            assert isinstance(block, ilahrs.OrientationSensors)
            assert len(client.events) <= 40 and len(client.received) <= 40
            if count == 250:
                break
        client.poll(0.5)  # blocks nobody takes wait in a bounded queue
        assert len(client.events) == len(client.received) == 40
        assert isinstance(client.events[-1], Output)
        client.stop()


def test_single_run_calibrations(client: AhrsClient) -> None:
    parameters = {"accumulation_time": 2, "latitude": 38.9}
    result = client.calibrate_2d(parameters)
    assert isinstance(result, ilahrs.CalibrationResult)
    assert result.calibration_type == ilahrs.CalibrationType.TWO_D
    assert client.host.state == ilahrs.statemachine.INITIAL
    assert client.get_calibration_results().raw()["calibration_type"] == ilahrs.CalibrationType.TWO_D
    result = client.calibrate_3d(parameters, accept=False)
    assert isinstance(result, ilahrs.CalibrationResult)
    assert result.calibration_type == ilahrs.CalibrationType.THREE_D
    assert client.get_calibration_results().raw()["calibration_type"] == ilahrs.CalibrationType.TWO_D
    assert client.errors == []


def test_a_misspelt_parameter_is_refused_before_anything_is_sent(client: AhrsClient) -> None:
    before = client.read_parameters()
    written = client._port.out_waiting
    for bad in ({"bogus": 1}, {"update_rat": 50}):
        with pytest.raises(ilahrs.IlahrsError) as info:
            client.load_parameters(bad)
        assert info.value.kind == ilahrs.ErrorKind.MALFORMED
    assert "did you mean 'update_rate'" in str(info.value)
    assert client._port.out_waiting == written and client.host.owed == ()
    assert client.read_parameters() == before
    client.load_parameters(before.raw())  # a read block's own fields (device id) are still fine


def test_bad_arguments_raise_ilahrs_errors_at_once(client: AhrsClient) -> None:
    with pytest.raises(ilahrs.IlahrsError) as info:
        client.start("bogus")
    assert info.value.kind == ilahrs.ErrorKind.UNKNOWN_COMMAND
    with pytest.raises(ilahrs.IlahrsError, match="did you mean 'AHRScont3'"):
        client.request("AHRSCont3")
    start = time.monotonic()
    for call in (
        lambda: client.poll(math.nan),
        lambda: client.wait_for(lambda e: True, math.nan),
        lambda: client.frames(3, math.nan),
        lambda: client.poll(-1),
    ):
        with pytest.raises(ilahrs.IlahrsError):
            call()
    assert time.monotonic() - start < 1.0


def test_mid_stream_session_reads_a_running_stream(sim: Simulator, tmp_path: Path) -> None:
    del tmp_path
    with AhrsClient(sim.first_line) as client:
        client.stop()
        client.start("AHRScont2")
        client.poll(0.2)
        client.host = ilahrs.Host.mid_stream("AHRScont2")  # as if the client had just connected
        blocks = client.frames(20)
        assert all(isinstance(b, ilahrs.Quaternion) for b in blocks)
        assert not [e for e in client.poll(0.2) if isinstance(e, ilahrs.ProtocolError)]
        client.stop()
        assert not any(isinstance(e, DataBlock) for e in client.poll(0.1))


STALE = bytes.fromhex("AA 55 01 00 3A 00")  # the start of a 58-byte frame whose rest never came


def test_the_device_recovers_from_a_stale_header_a_crashed_host_left(tmp_path: Path) -> None:
    """E41 on the simulator's pty: a host cut off mid-write leaves a frame header; the next client's
    Stop and ReadAHRSPar are answered once the line has been idle, without a retry."""
    with simulator(tmp_path, "--seed", "3") as running:
        with AhrsClient(running.first_line) as crashed:
            crashed._write(STALE)
        with AhrsClient(running.first_line, retries=0) as client:
            client.stop()
            assert isinstance(client.read_parameters(), ilahrs.AhrsParametersRead)
            assert client.errors == []


def test_the_client_gives_up_held_bytes_once_reads_return_nothing() -> None:
    """E41 on the client's side: the start of a frame the device never finished is given up after
    IDLE_TIMEOUT of empty reads (pyserial's loop:// reads back what is written)."""
    with AhrsClient("loop://") as client:
        client._write(STALE)
        client.poll(ilahrs.IDLE_TIMEOUT / 4)
        assert client.host.pending == len(STALE)
        client.poll(2 * ilahrs.IDLE_TIMEOUT)
        assert client.host.pending == 0 and client.discarded == len(STALE)


PAUSES = (0.0, 0.05, 0.099, 0.101, 0.15, 0.3, 0.6, 2.0)
"""Around the idle timeout (100 ms) and well past it."""


def test_a_command_after_a_pause_is_answered_without_a_retry(sim: Simulator) -> None:
    """E41 counts the quiet before bytes arrive: an answer that begins after the caller's pause is
    read whole, so each command goes out once (no retry), in idle and in on-request mode, where
    GetDataReq has no retry to hide a lost answer."""
    sent: list[bytes] = []
    with AhrsClient(sim.first_line, retries=0, tap=lambda data, out: sent.append(data) if out else None) as client:
        client.stop()
        for pause in PAUSES:
            time.sleep(pause)
            assert isinstance(client.read_parameters(), ilahrs.AhrsParametersRead), pause
        assert sent.count(ilahrs.build_command("ReadAHRSPar")) == len(PAUSES)
        client.stop()
        client.start("AHRSreq2")
        for pause in PAUSES:
            time.sleep(pause)
            assert isinstance(client.get_data(), ilahrs.Quaternion), pause
        assert sent.count(ilahrs.build_command("GetDataReq")) == len(PAUSES)
        assert client.errors == [] and client.discarded == 0
        client.stop()


def test_output_read_after_pauses_loses_nothing(sim: Simulator) -> None:
    """Continuous output that piles up while the caller pauses is read whole: every frame the
    device sent is an output block, none discarded, no protocol error."""
    with AhrsClient(sim.first_line, history=100_000) as client:
        client.stop()
        client.start("AHRScont3")
        for pause in PAUSES:
            time.sleep(pause)
            client.frames(5)
        client.stop()
        assert client.errors == [] and client.discarded == 0
        outputs = [e for e in client.events if isinstance(e, Output)]
        assert len(outputs) == len(client.received) - 2  # all but the acknowledgement and the alignment block


def test_the_tap_sees_each_chunk_once_as_it_crossed_the_line(sim: Simulator) -> None:
    """One call per write and one per read: a message is never split into a first byte and the
    rest (a capture of the session shows what the line carried)."""
    chunks: list[tuple[bytes, bool]] = []
    with AhrsClient(sim.first_line, tap=lambda data, out: chunks.append((data, out))) as client:
        client.stop()
        chunks.clear()
        time.sleep(0.2)
        client.read_parameters()
    (command, written), (answer, read) = chunks
    assert (command, written) == (ilahrs.build_command("ReadAHRSPar"), True)
    assert read is False and len(ilahrs.Frame.parse(answer).payload) == ilahrs.AhrsParametersRead.SIZE
