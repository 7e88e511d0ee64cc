"""`ilahrs decode` on two-direction pcapng captures made by hand: a host and the device model
(ilahrs.Device) talking, written with ilahrs.pcapng.PcapngWriter, then damaged on purpose. Each
test names the situation: a retry after a damaged answer, a parameter block sent with message type
0, a truncated frame, a capture begun mid-stream, adjacent damage, a lost answer, and pcapng files
that are not ours to read."""

from __future__ import annotations

import csv
import io
import json
import struct
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

import ilahrs
from ilahrs.pcapng import Direction, PcapngWriter
from ilahrs.statemachine import DEFAULT_ALIGNMENT_TIME_S

START_US = 1_700_000_000_000_000
"""The capture's first timestamp (microseconds since the epoch)."""
ANSWER_US = 4_500
"""How long after a command its answer is recorded (a 115200-baud answer and some latency)."""


def ilahrs_cli(*args: str) -> subprocess.CompletedProcess[str]:
    command = [sys.executable, "-m", "ilahrs", *args]
    return subprocess.run(command, capture_output=True, text=True, timeout=120, check=False)


class Line:
    """A serial line recorded as pcapng: the host writes, the device model answers, time passes."""

    def __init__(self) -> None:
        self.device = ilahrs.Device(seed=1)
        self.file = io.BytesIO()
        self.writer = PcapngWriter(self.file, port="/dev/ttyUSB0", baud=115200)
        self.now_us = START_US
        self.device_us = 0

    def _catch_up(self) -> bytes:
        """What the device sends until now."""
        elapsed = self.now_us - START_US - self.device_us
        self.device_us += elapsed
        return self.device.advance(elapsed / 1e6) if elapsed > 0 else b""

    def wait(self, seconds: float) -> bytes:
        """Let time pass; the bytes the device sent meanwhile (not recorded: see `inbound`)."""
        self.now_us += round(seconds * 1e6)
        return self._catch_up()

    def send(self, data: bytes) -> bytes:
        """The host writes `data` (recorded); the device's immediate answer (not recorded)."""
        self.writer.write(data, self.now_us, Direction.OUTBOUND)
        return self.device.receive(data)

    def inbound(self, data: bytes, after: float = ANSWER_US / 1e6) -> None:
        """Record bytes from the device, `after` seconds from now."""
        self.now_us += round(after * 1e6)
        self._catch_up()
        if data:
            self.writer.write(data, self.now_us, Direction.INBOUND)

    def save(self, path: Path) -> Path:
        path.write_bytes(self.file.getvalue())
        return path


def flipped(frame: bytes, at: int = 10) -> bytes:
    """`frame` with one payload bit changed: its checksum no longer holds."""
    return frame[:at] + bytes([frame[at] ^ 0x10]) + frame[at + 1 :]


def on_request(line: Line) -> None:
    """Stop, then AHRSreq1 and the alignment: the device answers GetDataReq from then on."""
    line.inbound(line.send(ilahrs.build_command("Stop")))
    line.inbound(line.send(ilahrs.build_command("AHRSreq1")))
    line.inbound(line.wait(DEFAULT_ALIGNMENT_TIME_S + 0.1), after=0)


def rows(path: Path, *options: str) -> tuple[list[dict[str, Any]], list[str]]:
    result = ilahrs_cli("decode", str(path), "--to", "jsonl", *options)
    assert result.returncode == 0, result.stderr
    return [json.loads(line) for line in result.stdout.splitlines()], result.stderr.splitlines()


def damaged(found: list[dict[str, Any]]) -> list[tuple[str, str, int, int]]:
    return [(r["direction"], r["reason"], r["offset"], r["length"]) for r in found if r["kind"] == "damaged"]


def test_a_retry_after_a_damaged_answer(tmp_path: Path) -> None:
    line = Line()
    on_request(line)
    answer = line.send(ilahrs.build_command("GetDataReq"))
    line.inbound(flipped(answer))
    line.wait(1.0 - ANSWER_US / 1e6)
    retry = line.send(ilahrs.build_command("GetDataReq"))
    line.inbound(retry)
    found, summary = rows(line.save(tmp_path / "retry.pcapng"))
    kinds = [r["kind"] for r in found]
    assert kinds[-4:] == ["damaged", "damaged", "GetDataReq", "full_output"]
    bad, missing = found[-4:-2]
    assert (bad["reason"], bad["length"], bad["raw"]) == ("bad_checksum", len(answer), flipped(answer).hex())
    assert bad["packet"] == 6 and bad["time"] > 30.0  # Stop, AHRSreq1, its ack, the alignment, GetDataReq
    assert (missing["reason"], missing["length"], missing["packet"]) == ("missing", 0, None)
    assert "GetDataReq" in missing["detail"]
    assert found[-1]["raw"] == retry.hex()
    assert "ilahrs decode: 2 damaged (bad_checksum 1, missing 1)" in summary


def test_a_parameter_block_sent_with_message_type_0(tmp_path: Path) -> None:
    line = Line()
    line.inbound(line.send(ilahrs.build_command("Stop")))
    block = ilahrs.CalibrationParameters(accumulation_time=20, latitude=45.0, date=ilahrs.encode_date(2014, 3, 11))
    typed0 = ilahrs.Frame(ilahrs.MessageType.COMMAND, block.build()).build()  # E5: the device takes it
    answer = line.send(ilahrs.build_command("Start2DClb") + typed0)
    assert (
        ilahrs.Acknowledgement.parse(ilahrs.Frame.parse(answer).payload).checksum == ilahrs.Frame.parse(typed0).checksum
    )
    line.inbound(answer)
    found, summary = rows(line.save(tmp_path / "type0.pcapng"))
    assert [r["kind"] for r in found][-3:] == ["Start2DClb", "calibration_parameters", "acknowledgement"]
    assert found[-2]["fields"]["date"] == "2014-03-11"
    assert summary[-2:] == ["ilahrs decode: 0 damaged", "ilahrs decode: 0 decode errors"]
    raw, _ = rows(tmp_path / "type0.pcapng", "--raw")
    assert raw[-2]["fields"]["date"] == ilahrs.CalibrationParameters.parse(block.build()).date


def test_a_truncated_frame_and_adjacent_damage(tmp_path: Path) -> None:
    line = Line()  # the output flows already: decoded as started by --output-format
    blocks = [ilahrs.FullOutput(heading=100 * i) for i in range(4)]
    frames = [ilahrs.Frame(ilahrs.MessageType.DATA, block.build()).build() for block in blocks]
    cut = frames[1][:20]
    line.inbound(frames[0] + flipped(frames[1]) + cut + frames[2] + b"\x01\x02\x03" + frames[3])
    found, summary = rows(line.save(tmp_path / "damage.pcapng"), "--output-format", "AHRScont1")
    first = len(frames[0])
    assert damaged(found) == [
        ("in", "bad_checksum", first, len(frames[1])),
        ("in", "truncated", first + len(frames[1]), 20),
        ("in", "no_frame_start", first + len(frames[1]) + 20 + len(frames[2]), 3),
    ]
    assert [r["kind"] for r in found].count("full_output") == 3
    assert "ilahrs decode: 3 damaged (bad_checksum 1, truncated 1, no_frame_start 1)" in summary
    path = tmp_path / "damage.pcapng"
    table = ilahrs_cli("decode", str(path), "--to", "csv", "--types", "damaged", "--output-format", "AHRScont1")
    cells = list(csv.DictReader(io.StringIO(table.stdout)))
    assert [(c["reason"], c["length"], c["packet"]) for c in cells] == [
        ("bad_checksum", str(len(frames[1])), "1"),
        ("truncated", "20", "1"),
        ("no_frame_start", "3", "1"),
    ]


def test_a_capture_begun_mid_stream(tmp_path: Path) -> None:
    line = Line()
    line.device.receive(ilahrs.build_command("AHRScont3"))
    line.wait(DEFAULT_ALIGNMENT_TIME_S + 0.5)
    line.inbound(line.wait(0.05), after=0)
    line.inbound(line.send(ilahrs.build_command("Stop")))
    found, summary = rows(line.save(tmp_path / "mid.pcapng"), "--output-format", "AHRScont3")
    assert [r["kind"] for r in found].count("orientation_sensors") == 5
    assert summary[-2:] == ["ilahrs decode: 0 damaged", "ilahrs decode: 0 decode errors"]


def test_a_lost_answer_is_a_row_and_counted(tmp_path: Path) -> None:
    line = Line()
    line.inbound(line.send(ilahrs.build_command("Stop")))
    line.send(ilahrs.build_command("GetBIT"))  # its answer is lost
    line.wait(1.0)
    line.inbound(line.send(ilahrs.build_command("GetBIT")))
    found, summary = rows(line.save(tmp_path / "lost.pcapng"))
    assert damaged(found) == [("in", "missing", 0, 0)]
    assert [r["kind"] for r in found][-3:] == ["damaged", "GetBIT", "bit_result"]
    assert summary[-3:-1] == ["ilahrs decode: 1 damaged (missing 1)", "ilahrs decode: 1 decode errors"]


def test_calibration_outcome_and_accuracy_are_two_columns(tmp_path: Path) -> None:
    results = [ilahrs.CalibrationRunResult(success=value) for value in (0, 12, 255)]
    dump = tmp_path / "results.bin"  # a raw dump: the 30-byte block is this table's alone
    dump.write_bytes(b"".join(ilahrs.Frame(ilahrs.MessageType.DATA, block.build()).build() for block in results))
    expected = [("failed", None), ("succeeded", 1.2), ("succeeded", None)]
    found, _ = rows(dump)
    assert [(r["fields"]["success"], r["fields"]["accuracy"]) for r in found] == expected
    raw, _ = rows(dump, "--raw")
    assert [(r["fields"]["success"], r["fields"]["accuracy"]) for r in raw] == [(0, None), (12, None), (255, None)]
    for options in ((), ("--strict",)):  # columns, then message by message
        table = ilahrs_cli("decode", str(dump), "--to", "csv", *options)
        cells = [(c["success"], c["accuracy"]) for c in csv.DictReader(io.StringIO(table.stdout))]
        assert cells == [("failed", ""), ("succeeded", "1.2"), ("succeeded", "")]


def pcapng_header(linktype: int) -> bytes:
    out = io.BytesIO()
    PcapngWriter(out, port="eth0", baud=115200, linktype=linktype)
    return out.getvalue()


def test_a_capture_of_another_link_type_is_refused(tmp_path: Path) -> None:
    out = io.BytesIO()
    writer = PcapngWriter(out, port="eth0", baud=115200, linktype=1)
    writer.write(ilahrs.build_command("Stop"), START_US, Direction.OUTBOUND)
    path = tmp_path / "ethernet.pcapng"
    path.write_bytes(out.getvalue())
    result = ilahrs_cli("decode", str(path))
    assert result.returncode == 2 and result.stdout == ""
    assert result.stderr.splitlines() == [
        f"ilahrs decode: {path}: packet 1 has link type 1 (ETHERNET), not 147 (LINKTYPE_USER0, an AHRS serial line)"
    ]


@pytest.mark.skipif(not Path("/proc/self/status").exists(), reason="reads VmHWM from /proc")
def test_a_huge_block_length_is_refused_before_it_is_read(tmp_path: Path) -> None:
    path = tmp_path / "huge.pcapng"
    with path.open("wb") as out:
        out.write(pcapng_header(147) + struct.pack("<II", 6, 0xFFFFFFF0))
        out.write(bytes(64 << 20))  # a long stream behind the length field
    result = subprocess.run(
        [sys.executable, "-c", WATCH_MEMORY, str(path)], capture_output=True, text=True, timeout=120, check=False
    )
    stderr, peak = result.stderr.rsplit("\n", 2)[0], int(result.stderr.rsplit("\n", 2)[1])
    assert result.returncode == 2
    at = len(pcapng_header(147))
    assert stderr.endswith(f"block at offset {at} claims 4294967280 bytes, more than the 16 MiB allowed"), stderr
    assert peak < 48 << 10, f"peak RSS {peak} KiB"  # well under the 64 MiB behind the field


WATCH_MEMORY = """
import sys
from ilahrs.__main__ import main
try:
    code = main(["decode", sys.argv[1]])
except SystemExit as exc:
    code = exc.code
# This process's own peak (VmHWM, KiB): getrusage's ru_maxrss keeps the peak of the process it was
# forked from across exec, so under a large pytest process it reports that one's size.
with open("/proc/self/status") as status:
    print(next(line.split()[1] for line in status if line.startswith("VmHWM:")), file=sys.stderr)
sys.exit(code)
"""


def test_a_damaged_pcapng_prints_its_error_alone(tmp_path: Path) -> None:
    path = tmp_path / "cut.pcapng"
    line = Line()
    line.inbound(line.send(ilahrs.build_command("Stop")))
    line.send(ilahrs.build_command("GetBIT"))
    path.write_bytes(line.file.getvalue()[:-7])
    result = ilahrs_cli("decode", str(path))
    assert result.returncode == 2
    assert len(result.stderr.splitlines()) == 1 and "file ends inside the block" in result.stderr
