"""The Wireshark dissector on hand-made captures, checked with tshark: a retry after a damaged
answer, a truncated frame, a capture begun mid-stream (the output-format preference), $PAHR status
flags, dates and calibration outcomes, labels.

Each capture is built here, both directions with timestamps (ilahrs.pcapng.PcapngWriter), from
frames the package builds (build_command, Frame, payload classes) and answers of the device model
(ilahrs.Device). tshark is installed by `make setup-wireshark` (tools/need); without it these
tests are skipped.
"""

from __future__ import annotations

import io
import shutil
import sys
from collections.abc import Iterable
from pathlib import Path
from typing import Any

import pytest

import ilahrs
from ilahrs.pcapng import Direction, PcapngWriter

sys.path.insert(0, str(Path(__file__).resolve().parent))
import tshark  # tests/wireshark/tshark.py

ROOT = Path(__file__).resolve().parents[2]
LUA = ROOT / "generated" / "wireshark" / "ilahrs.lua"
P = tshark.PROTO
EPOCH_US = 1_700_000_000_000_000
OUT, IN = Direction.OUTBOUND, Direction.INBOUND

pytestmark = pytest.mark.skipif(shutil.which("tshark") is None, reason="tshark is not installed (make setup-wireshark)")

Packet = tuple[float, Direction, bytes]


def capture(path: Path, packets: Iterable[Packet]) -> Path:
    """A pcapng capture of `packets`: (seconds after the first, direction, bytes)."""
    out = io.BytesIO()
    writer = PcapngWriter(out, port="/dev/ttyUSB0", baud=115200)
    for seconds, direction, data in packets:
        writer.write(data, EPOCH_US + round(seconds * 1_000_000), direction)
    path.write_bytes(out.getvalue())
    return path


def shown(path: Path, *options: str) -> list[Any]:
    """The packets as tshark shows them (tshark.Shown)."""
    packets: list[Any] = tshark.parse(tshark.run(LUA, path, *options))
    return packets


def messages(packets: list[Any]) -> list[tuple[int, str | None, str | None]]:
    """(packet number, kind, table) of every message the dissector shows, in order."""
    return [
        (number, t.get(f"{P}.kind"), t.get(f"{P}.table"))
        for number, packet in enumerate(packets, 1)
        for t in packet.trees
        if t.has(f"{P}.kind")
    ]


def command(name: str) -> bytes:
    return ilahrs.build_command(name)


def data_frame(payload: ilahrs.Payload) -> bytes:
    return ilahrs.Frame(ilahrs.MessageType.DATA, payload.build()).build()


def damaged(frame: bytes) -> bytes:
    """The frame with one payload byte changed: its checksum no longer matches."""
    spoiled = bytearray(frame)
    spoiled[ilahrs.frame.PAYLOAD_OFFSET] ^= 0x01
    return bytes(spoiled)


def output_frames(count: int) -> list[bytes]:
    """`count` AHRScont3 output frames of the device model, after its alignment."""
    device = ilahrs.Device()
    device.receive(command("AHRScont3"))
    frames: list[bytes] = []
    decoder = ilahrs.StreamDecoder()
    while len(frames) < count + 2:
        step = device.next_event_in
        assert step is not None
        frames += [event.raw for event in decoder.feed(device.advance(step))]
    return frames[2:]  # after the acknowledgement and the alignment block


# --- A retry after a damaged answer, a truncated frame, a capture begun mid-stream -------------


def session() -> list[Packet]:
    """Begins mid-stream in AHRScont3 output (one frame cut short by the next), then Stop, AHRSreq3,
    and GetDataReq whose answer arrives damaged: the host retries after its 1 s timeout and the
    retry's answer comes 4.5 ms later; then one more GetDataReq answered at once."""
    out = output_frames(5)
    packets: list[Packet] = [
        (0.000, IN, out[0]),
        (0.010, IN, out[1]),
        (0.020, IN, out[2][:20]),  # cut short: the next frame starts where its 21st byte should be
        (0.030, IN, out[3]),
        (0.040, IN, out[4]),
    ]
    device = ilahrs.Device()
    device.receive(command("AHRScont3"))
    device.advance(device.next_event_in or 0.0)
    assert device.receive(command("Stop")) == b""  # Stop has no answer (Table C.1)
    packets.append((0.500, OUT, command("Stop")))
    packets += [(1.000, OUT, command("AHRSreq3")), (1.0045, IN, device.receive(command("AHRSreq3")))]
    alignment = device.advance(device.next_event_in or 0.0)
    packets.append((31.000, IN, alignment))
    answers = [device.receive(command("GetDataReq")) for _ in range(3)]
    packets += [
        (40.500, OUT, command("GetDataReq")),
        (40.5045, IN, damaged(answers[0])),
        (41.500, OUT, command("GetDataReq")),  # the retry, when the host's 1 s timeout ends
        (41.5045, IN, answers[1]),
        (42.000, OUT, command("GetDataReq")),
        (42.0045, IN, answers[2]),
    ]
    return packets


@pytest.fixture(scope="module")
def session_capture(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return capture(tmp_path_factory.mktemp("dissector") / "session.pcapng", session())


def test_the_answer_to_a_retry_is_decoded_after_a_damaged_answer(session_capture: Path) -> None:
    packets = shown(session_capture)
    # 10: GetDataReq; 11: its answer, damaged; 12: the retry, when the first one's timeout ends.
    assert packets[9].trees[0].has(f"{P}.expert.missing")
    assert [t.get(f"{P}.damaged") for t in packets[10].trees if t.has(f"{P}.damaged")] == ["bad checksum"]
    (answer,) = packets[12].trees
    assert (answer.get(f"{P}.kind"), answer.get(f"{P}.table")) == ("output", "orientation_sensors")
    assert answer.get(f"{P}.request_in") == "12"
    assert not answer.has(f"{P}.expert.unexpected")
    assert not packets[11].trees[0].has(f"{P}.expert.missing")
    assert packets[11].trees[0].get(f"{P}.response_in") == "13"
    (last,) = packets[14].trees
    assert (last.get(f"{P}.kind"), last.get(f"{P}.request_in")) == ("output", "14")


def test_a_truncated_frame_ends_where_the_next_frame_starts(session_capture: Path) -> None:
    frames = output_frames(5)
    packets = shown(session_capture, f"{P}.output_format:AHRScont3")
    damaged_trees = [t for t in packets[3].trees if t.has(f"{P}.damaged")]
    (cut,) = damaged_trees
    assert cut.get(f"{P}.damaged") == "truncated"
    assert cut.has(f"{P}.expert.damaged")
    assert not cut.has(f"{P}.checksum")
    payload = bytes.fromhex(cut.get(f"{P}.payload").replace(":", ""))
    assert payload == frames[2][ilahrs.frame.PAYLOAD_OFFSET : 20]
    (intact,) = [t for t in packets[3].trees if t.has(f"{P}.kind")]
    assert intact.get(f"{P}.kind") == "output" and intact.raw == frames[3]
    # 20 bytes given up, as the stream decoder gives them up.
    decoder = ilahrs.StreamDecoder()
    assert [e.raw for e in decoder.feed(frames[2][:20] + frames[3])] == [frames[3]]
    assert decoder.discarded == 20
    (run,) = [t for t in packets[3].trees if t.has(f"{P}.discarded")]
    assert len(run.get(f"{P}.discarded").split(":")) == 20


def test_a_capture_begun_mid_stream_is_read_with_the_output_format_preference(session_capture: Path) -> None:
    without = shown(session_capture)
    first = without[0].trees[0]
    assert first.get(f"{P}.kind") == "unexpected"
    assert first.has(f"{P}.expert.no_start")
    text = tshark.run(LUA, session_capture, fmt=("-V",))
    assert f"{P}.output_format" in text
    packets = shown(session_capture, f"{P}.output_format:AHRScont3")
    found = messages(packets)
    assert [m for m in found if m[0] <= 5] == [(n, "output", "orientation_sensors") for n in (1, 2, 4, 5)]
    assert not any(t.has(f"{P}.expert.no_start") for packet in packets for t in packet.trees)
    # The values of Host.mid_stream, field by field.
    host = ilahrs.Host.mid_stream("AHRScont3")
    frames = output_frames(5)
    decoded = [e.data for e in host.receive(b"".join(frames[:2] + frames[3:])) if isinstance(e, ilahrs.Output)]
    trees = [t for number in (1, 2, 4, 5) for t in packets[number - 1].trees if t.has(f"{P}.kind")]
    assert len(decoded) == len(trees) == 4
    for tree, payload in zip(trees, decoded, strict=True):
        assert isinstance(payload, ilahrs.OrientationSensors)
        for name, value in payload.values(ilahrs.VARIANTS["g300_a2_tmga"]).items():
            assert float(tree.get(f"{P}.orientation_sensors.{name}")) == pytest.approx(value, rel=1e-12)
    # Stop takes the device from the state where that output flows.
    stop = packets[5].trees[0]
    assert (stop.get(f"{P}.command"), stop.get(f"{P}.state")) == ("Stop", ilahrs.statemachine.INITIAL)


# --- $PAHR status flags, dates, calibration outcomes, labels -------------------------------


def values_session() -> tuple[list[Packet], list[ilahrs.PahrSentence], list[ilahrs.CalibrationStatus], Any]:
    device = ilahrs.Device()
    packets: list[Packet] = [(0.0, OUT, command("NMEAcont")), (0.0045, IN, device.receive(command("NMEAcont")))]
    packets.append((30.0, IN, device.advance(device.next_event_in or 0.0)))
    sentences = [
        ilahrs.PahrSentence(150, -25, 12345, 251, 512, 0),
        ilahrs.PahrSentence(150, -25, 12345, 251, 512, int(ilahrs.UswFlag.LARGE_MAGNETIC_FIELD)),
    ]
    packets += [(30.1 + i / 10, IN, s.build().encode()) for i, s in enumerate(sentences)]
    assert device.receive(command("Stop")) == b""
    packets.append((31.0, OUT, command("Stop")))
    read = device.receive(command("ReadAHRSPar"))
    packets += [(32.0, OUT, command("ReadAHRSPar")), (32.0045, IN, read)]
    results = [ilahrs.CalibrationStatus(calibration_type=1, runs_used=1, success=s) for s in (12, 0, 255)]
    for i, result in enumerate(results):
        packets += [(33.0 + i, OUT, command("GetClbRes")), (33.0045 + i, IN, data_frame(result))]
    parameters = ilahrs.AhrsParametersRead.parse(ilahrs.Frame.parse(read).payload)
    return packets, sentences, results, parameters


@pytest.fixture(scope="module")
def values_capture(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return capture(tmp_path_factory.mktemp("dissector") / "values.pcapng", values_session()[0])


def test_pahr_status_flags_come_from_the_parsed_word(values_capture: Path) -> None:
    packets = shown(values_capture)
    clear, magnetic = packets[3].trees[0], packets[4].trees[0]
    flags = [f"{P}.usw.{name.lower()}" for name in ilahrs.UswFlag.__members__]
    assert clear.get(f"{P}.pahr.usw") == "0x0000"
    assert [clear.get(name) for name in flags] == ["0"] * len(flags)
    assert [name for name in flags if magnetic.get(name) == "1"] == [f"{P}.usw.large_magnetic_field"]
    matched = tshark.run(
        LUA, values_capture, fmt=("-Y", f"{P}.usw.large_magnetic_field == 1", "-T", "fields", "-e", "frame.number")
    )
    assert matched.split() == ["5"]


def test_dates_and_calibration_outcomes_as_decode_gives_them(values_capture: Path) -> None:
    _packets, _sentences, results, parameters = values_session()
    packets = shown(values_capture)
    (read,) = [t for t in packets[7].trees if t.get(f"{P}.table") == "ahrs_parameters_read"]
    year, month, day = ilahrs.decode_date(parameters.date)
    assert read.get(f"{P}.ahrs_parameters_read.date") == f"{year:04d}-{month:02d}-{day:02d}"
    assert float(read.get(f"{P}.ahrs_parameters_read.date.raw")) == parameters.date
    for number, result in zip((9, 11, 13), results, strict=True):
        (tree,) = packets[number].trees
        base = f"{P}.calibration_status.success"
        assert int(tree.get(base)) == result.success
        outcome = "succeeded" if ilahrs.calibration_succeeded(result.success) else "failed"
        assert tree.get(f"{base}.outcome") == outcome
        accuracy = ilahrs.calibration_accuracy_deg(result.success)
        assert (None if accuracy is None else float(tree.get(f"{base}.accuracy"))) == accuracy
        assert tree.has(f"{base}.accuracy") == (accuracy is not None)


def test_labels_are_the_spec_titles_and_an_ack_checksum_is_hex(values_capture: Path, tmp_path: Path) -> None:
    text = tshark.run(LUA, values_capture, fmt=("-V",))
    assert "Device ID: VIRT0001" in text
    assert "Date (Year, Month, Day): " in text
    assert "Calibration success: 12 (succeeded, 1.2 deg)" in text
    assert "Calibration outcome: succeeded" in text
    assert "Predicted heading accuracy: 1.2 deg" in text
    assert "USW: 0x2000" in text
    fields = {row[2]: row[1] for row in tshark.fields(LUA)}
    assert fields[f"{P}.orientation_sensors.gyro_x"] == "GyroX"
    assert fields[f"{P}.full_output.ugyro_y"] == "Ugyro Y"
    assert fields[f"{P}.orientation_sensors.heading"] == "Heading"
    assert fields[f"{P}.pahr.roll"] == "Roll"
    # An acknowledgement's checksum in hex, as the checksum of the frame it acknowledges.
    ack = ilahrs.Device().receive(command("NMEAcont"))
    acked = capture(tmp_path / "ack.pcapng", [(0.0, OUT, command("NMEAcont")), (0.0045, IN, ack)])
    (tree,) = shown(acked)[1].trees
    sent = ilahrs.Frame.parse(command("NMEAcont")).checksum
    assert tree.get(f"{P}.acknowledgement.checksum") == f"0x{sent:04x}"
    assert tree.get(f"{P}.acknowledgement.checksum") == shown(acked)[0].trees[0].get(f"{P}.checksum")
